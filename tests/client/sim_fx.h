/*
 * sim_fx.h - a simulator on its own, offline (xf_sim_process): host packets
 * in, the replies out, at a clock the test sets. Shared by the simulator's
 * tests (test_sim.c, test_sim_v206.c). Include after client_test.h.
 */
#ifndef XFGCU_SIM_FX_H
#define XFGCU_SIM_FX_H

#define OUT_CAP 4096

typedef struct sim_fx {
    xf_sim s;
    uint8_t out[OUT_CAP];
    size_t out_len;
    uint32_t now;
} sim_fx;

static inline sim_fx *fx_new(const xf_sim_config *cfg)
{
    sim_fx *f = (sim_fx *)calloc(1, sizeof(*f));
    assert_non_null(f);
    assert_xf(xf_sim_init(&f->s, cfg), XF_OK);
    f->now = 1000;
    return f;
}

/* A host packet of @p version carrying @p cmd (NULL: the null order). */
static inline size_t host_bytes(uint8_t *buf, uint8_t version, const xf_command *cmd, uint8_t status)
{
    xf_host_packet p;
    size_t len = 0;
    xf_host_packet_init(&p, version);
    p.main.status = status;
    if (cmd != NULL) {
        assert_xf(xf_host_set_command(&p, cmd, NULL), XF_OK);
    }
    assert_xf(xf_host_pack(&p, buf, XF_PACKET_MAX_LEN, &len), XF_OK);
    return len;
}

/* Feed raw bytes at the fixture's clock; the replies are in f->out. */
static inline void feed(sim_fx *f, const uint8_t *data, size_t len)
{
    f->out_len = 0;
    assert_xf(xf_sim_process(&f->s, data, len, f->now, f->out, sizeof(f->out), &f->out_len), XF_OK);
}

/* Feed one host packet; decode the one reply into @p reply (if not NULL). */
static inline void send_bytes(sim_fx *f, const uint8_t *buf, size_t len, xf_gcu_packet *reply)
{
    if (reply != NULL) {
        memset(reply, 0, sizeof(*reply)); /* a failed unpack below leaves it as it was */
    }
    feed(f, buf, len);
    assert_true(f->out_len >= XF_PACKET_MIN_LEN);
    if (reply != NULL) {
        assert_xf(xf_gcu_unpack(f->out, f->out_len, reply), XF_OK);
    }
}

/* Send one packet of @p order (default parameters, V@p version); decode the one reply. */
static inline void send_order(sim_fx *f, uint8_t version, uint8_t order, xf_gcu_packet *reply)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    xf_command cmd;
    size_t len;
    xf_command_init(&cmd, order);
    len = host_bytes(buf, version, order == XF_ORDER_NULL ? NULL : &cmd, 0);
    send_bytes(f, buf, len, reply);
}

static inline void send_cmd(sim_fx *f, uint8_t version, const xf_command *cmd, xf_gcu_packet *reply)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = host_bytes(buf, version, cmd, 0);
    send_bytes(f, buf, len, reply);
}

/* A host packet of V1 with @p order (0: null), carrier INS valid at @p carrier_yaw (0.01 deg), and
 * a valid yaw rate @p yaw_ctrl when non-zero; fed at the fixture's clock. */
static inline void send_carrier(sim_fx *f, const xf_command *cmd, uint16_t carrier_yaw, int16_t yaw_ctrl,
                                xf_gcu_packet *r)
{
    xf_host_packet p;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    xf_host_packet_init(&p, 1);
    p.main.status = XF_STATUS_INS_VALID | (yaw_ctrl != 0 ? XF_STATUS_CTRL_VALID : 0u);
    p.main.carrier_yaw = carrier_yaw;
    p.main.yaw_ctrl = yaw_ctrl;
    if (cmd != NULL) {
        assert_xf(xf_host_set_command(&p, cmd, NULL), XF_OK);
    }
    assert_xf(xf_host_pack(&p, buf, sizeof(buf), &len), XF_OK);
    send_bytes(f, buf, len, r);
}

#endif /* XFGCU_SIM_FX_H */
