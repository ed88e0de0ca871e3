/*
 * test_sim.c - the simulated GCU on its own, offline (xf_sim_process): it
 * answers only correct packets, one reply each (72 bytes for the null
 * order, 73 with a state); keeps the once-rule (external track excepted);
 * gives every order its feedback, with configured failures, late or
 * single feedback and calibration's operating phase; V2 fields and units;
 * faults.
 */
#include "client_test.h"
#include "sim_fx.h"

static void test_init(void **state)
{
    xf_sim_config cfg;
    xf_sim s;
    (void)state;
    xf_sim_config_init(&cfg);
    assert_int_equal(cfg.version, 1);
    assert_int_equal(cfg.gimbal_code, 58);
    cfg.version = 3;
    assert_xf(xf_sim_init(&s, &cfg), XF_ERR_RANGE);
    cfg.version = 0;
    assert_xf(xf_sim_init(&s, &cfg), XF_ERR_RANGE);
    assert_xf(xf_sim_init(NULL, NULL), XF_ERR_ARG);
    assert_xf(xf_sim_init(&s, NULL), XF_OK);
    assert_xf(xf_sim_attach(&s, NULL), XF_OK);
    assert_xf(xf_sim_attach(NULL, NULL), XF_ERR_ARG);
    assert_xf(xf_sim_step(NULL, 0), XF_ERR_ARG);
    assert_xf(xf_sim_step(&s, 0), XF_OK); /* detached: nothing to read */
    assert_xf(xf_sim_process(NULL, NULL, 0, 0, NULL, 0, NULL), XF_ERR_ARG);
    assert_xf(xf_sim_process(&s, NULL, 5, 0, NULL, 0, NULL), XF_ERR_ARG);
}

/* Replies: 72 bytes for the null order, 73 (order + state) otherwise; GCU header, version, CRC. */
static void test_reply_lengths(void **state)
{
    sim_fx *f = fx_new(NULL);
    xf_gcu_packet r;
    (void)state;
    send_order(f, 1, XF_ORDER_NULL, &r);
    assert_int_equal(f->out_len, 72);
    assert_int_equal(f->out[0], XF_GCU_HEADER0);
    assert_int_equal(f->out[1], XF_GCU_HEADER1);
    assert_int_equal(f->out[2], 72);
    assert_int_equal(f->out[3], 0);
    assert_int_equal(f->out[4], 1);
    assert_int_equal(f->out[XF_OFF_ORDER], 0);
    assert_xf(xf_packet_check(f->out, f->out_len, XF_DIR_GCU), XF_OK);
    assert_int_equal(r.params_len, 0);
    send_order(f, 1, XF_ORDER_SHUTTER, &r);
    assert_int_equal(f->out_len, 73);
    assert_int_equal(f->out[2], 73);
    assert_int_equal(r.order, XF_ORDER_SHUTTER);
    assert_int_equal(r.params_len, 1);
    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    assert_xf(xf_packet_check(f->out, f->out_len, XF_DIR_GCU), XF_OK);
    assert_int_equal(f->s.stats.packets_in, 2);
    assert_int_equal(f->s.stats.replies, 2);
    free(f);
}

/* Only correct host packets are answered. */
static void test_answers_only_correct_packets(void **state)
{
    sim_fx *f = fx_new(NULL);
    uint8_t good[XF_PACKET_MAX_LEN], bad[XF_PACKET_MAX_LEN], stream[1024];
    uint8_t garbage[300];
    xf_command cmd;
    xf_gcu_packet g;
    size_t len, i, n;
    (void)state;
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    len = host_bytes(good, 1, &cmd, 0);
    /* garbage */
    for (i = 0; i < sizeof(garbage); i++) {
        garbage[i] = (uint8_t)((i * 37u + 11u) & 0xFFu);
    }
    feed(f, garbage, sizeof(garbage));
    assert_int_equal(f->out_len, 0);
    /* CRC broken, in each place */
    for (i = 5; i < len; i += 7) {
        memcpy(bad, good, len);
        bad[i] ^= 0x10u;
        feed(f, bad, len);
        assert_int_equal(f->out_len, 0);
    }
    memcpy(bad, good, len);
    bad[len - 1u] ^= 0x01u;
    feed(f, bad, len);
    assert_int_equal(f->out_len, 0);
    /* a GCU packet (wrong direction) */
    memset(&g, 0, sizeof(g));
    g.version = 1;
    assert_xf(xf_gcu_pack(&g, bad, sizeof(bad), &n), XF_OK);
    feed(f, bad, n);
    assert_int_equal(f->out_len, 0);
    assert_int_equal(f->s.stats.packets_in, 0);
    assert_int_equal(f->s.stats.executed[XF_ORDER_SHUTTER], 0);
    assert_int_equal(f->s.stats.photos, 0);
    /* split across calls: one reply, after the last byte */
    feed(f, good, 40);
    assert_int_equal(f->out_len, 0);
    feed(f, good + 40, len - 40u);
    assert_int_equal(f->out_len, 73);
    assert_int_equal(f->s.stats.packets_in, 1);
    /* noise, a broken packet, a good one, noise: exactly one reply */
    n = 0;
    memcpy(stream + n, garbage, 50);
    n += 50;
    memcpy(stream + n, good, len);
    stream[n + 30] ^= 0xFFu;
    n += len;
    n += host_bytes(stream + n, 1, NULL, 0);
    memcpy(stream + n, garbage + 100, 60);
    n += 60;
    feed(f, stream, n);
    assert_int_equal(f->out_len, 72);
    assert_int_equal(f->s.stats.packets_in, 2);
    /* two good packets in one read: two replies back to back */
    n = host_bytes(stream, 1, &cmd, 0);
    n += host_bytes(stream + n, 1, NULL, 0);
    feed(f, stream, n);
    assert_int_equal(f->out_len, 73 + 72);
    assert_xf(xf_packet_check(f->out, 73, XF_DIR_GCU), XF_OK);
    assert_xf(xf_packet_check(f->out + 73, 72, XF_DIR_GCU), XF_OK);
    free(f);
}

/* The once-rule: an order runs once while it repeats; a null (or any other order) re-arms it. */
static void test_once_rule(void **state)
{
    sim_fx *f = fx_new(NULL);
    xf_gcu_packet r;
    xf_command cmd;
    int i;
    (void)state;
    for (i = 0; i < 3; i++) {
        send_order(f, 1, XF_ORDER_SHUTTER, &r);
        assert_int_equal(f->out_len, 73); /* every repeat carries the state */
        assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    }
    assert_int_equal(f->s.stats.executed[XF_ORDER_SHUTTER], 1);
    assert_int_equal(f->s.stats.photos, 1);
    send_order(f, 1, XF_ORDER_NULL, NULL);
    send_order(f, 1, XF_ORDER_SHUTTER, NULL);
    assert_int_equal(f->s.stats.photos, 2);
    send_order(f, 1, XF_ORDER_RECORD, NULL);
    send_order(f, 1, XF_ORDER_SHUTTER, NULL);
    assert_int_equal(f->s.stats.photos, 3);
    /* even with other parameters, the same order runs once */
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.zoom = -20;
    send_cmd(f, 1, &cmd, NULL);
    cmd.zoom = -50;
    send_cmd(f, 1, &cmd, NULL);
    assert_int_equal(f->s.stats.executed[XF_ORDER_ZOOM_TO], 1);
    assert_near(f->s.zoom_target, 2.0, 1e-6);
    /* external track is streamed: every packet runs */
    xf_command_init(&cmd, XF_ORDER_EXTERNAL_TRACK);
    cmd.value = 2;
    for (i = 0; i < 5; i++) {
        cmd.dx = (int16_t)(i * 100);
        send_cmd(f, 1, &cmd, &r);
        assert_int_equal(r.params_len, 1);
    }
    assert_int_equal(f->s.stats.executed[XF_ORDER_EXTERNAL_TRACK], 5);
    assert_int_equal(f->s.track_x, 400 * 1000 / 1024);
    free(f);
}

/* Every order gets its feedback: the order in byte 69, a state in byte 70. */
static void test_every_order_gets_feedback(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        const xf_order_info *info = xf_order_at(i);
        xf_sim_config cfg;
        sim_fx *f;
        xf_command cmd;
        xf_gcu_packet r;
        uint8_t st;
        assert_non_null(info);
        xf_sim_config_init(&cfg);
        cfg.version = 2;
        f = fx_new(&cfg);
        if (info->order == XF_ORDER_NULL) {
            send_order(f, 2, XF_ORDER_NULL, &r);
            assert_int_equal(f->out_len, 72);
            free(f);
            continue;
        }
        ct_valid_command(&cmd, info->order);
        assert_xf(xf_command_check(&cmd, 2, NULL), XF_OK);
        send_cmd(f, 2, &cmd, &r);
        if (f->out_len != 73u) {
            print_error("order %s: reply of %u bytes\n", xf_order_name(info->order), (unsigned)f->out_len);
        }
        assert_int_equal(f->out_len, 73);
        assert_int_equal(r.order, info->order);
        assert_int_equal(r.params_len, 1);
        st = r.params[0];
        assert_int_equal(f->s.stats.executed[info->order], 1);
        if (info->order == XF_ORDER_CALIBRATION) {
            assert_int_equal(st, XF_STATE_OPERATING);
        } else if (info->order == XF_ORDER_GAZE_GEO || info->order == XF_ORDER_GAZE_LOCK) {
            assert_int_equal(st, XF_STATE_FAILURE); /* no valid carrier INS data */
        } else if (st != XF_STATE_SUCCESS) {
            print_error("order %s: state 0x%02X\n", xf_order_name(info->order), st);
            fail();
        }
        free(f);
    }
    {
        /* an order the protocol does not know: still answered, with failure */
        sim_fx *f = fx_new(NULL);
        xf_host_packet p;
        xf_gcu_packet r;
        uint8_t buf[XF_PACKET_MAX_LEN];
        size_t len = 0;
        xf_host_packet_init(&p, 1);
        p.order = 0x99;
        assert_xf(xf_host_pack(&p, buf, sizeof(buf), &len), XF_OK);
        send_bytes(f, buf, len, &r);
        assert_int_equal(f->out_len, 73);
        assert_int_equal(r.order, 0x99);
        assert_int_equal(r.params[0], XF_STATE_FAILURE);
        free(f);
    }
}

/* Configured failures: 0x01, or a failed-camera mask; 0 restores success. */
static void test_configured_failures(void **state)
{
    sim_fx *f = fx_new(NULL);
    xf_gcu_packet r;
    (void)state;
    xf_sim_set_failure(&f->s, XF_ORDER_ZOOM_IN, XF_CAM1 | XF_CAM2);
    send_order(f, 1, XF_ORDER_ZOOM_IN, &r);
    assert_int_equal(r.params[0], XF_CAM1 | XF_CAM2);
    xf_sim_set_failure(&f->s, XF_ORDER_SHUTTER, XF_STATE_FAILURE);
    send_order(f, 1, XF_ORDER_SHUTTER, &r);
    assert_int_equal(r.params[0], XF_STATE_FAILURE);
    assert_int_equal(f->s.stats.photos, 0); /* a failed shutter takes no photo */
    xf_sim_set_failure(&f->s, XF_ORDER_SHUTTER, 0);
    send_order(f, 1, XF_ORDER_NULL, NULL);
    send_order(f, 1, XF_ORDER_SHUTTER, &r);
    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    assert_int_equal(f->s.stats.photos, 1);
    xf_sim_set_failure(NULL, 1, 1);
    free(f);
}

/* feedback_after: the state comes in the Nth reply after the execution. */
static void test_feedback_after(void **state)
{
    xf_sim_config cfg;
    sim_fx *f;
    xf_gcu_packet r;
    static const size_t want[] = {72, 72, 72, 73, 73};
    size_t i;
    (void)state;
    xf_sim_config_init(&cfg);
    cfg.feedback_after = 3;
    f = fx_new(&cfg);
    for (i = 0; i < 5; i++) {
        send_order(f, 1, XF_ORDER_FOCUS, &r);
        assert_int_equal(f->out_len, want[i]);
        assert_int_equal(r.order, XF_ORDER_FOCUS);
    }
    assert_int_equal(f->s.stats.executed[XF_ORDER_FOCUS], 1);
    free(f);
}

/* state_once: only one reply carries the state. */
static void test_state_once(void **state)
{
    xf_sim_config cfg;
    sim_fx *f;
    static const size_t want[] = {73, 72, 72};
    size_t i;
    (void)state;
    xf_sim_config_init(&cfg);
    cfg.state_once = 1;
    f = fx_new(&cfg);
    for (i = 0; i < 3; i++) {
        send_order(f, 1, XF_ORDER_FOCUS, NULL);
        assert_int_equal(f->out_len, want[i]);
    }
    send_order(f, 1, XF_ORDER_NULL, NULL);
    send_order(f, 1, XF_ORDER_FOCUS, NULL);
    assert_int_equal(f->out_len, 73); /* re-armed by the next execution */
    free(f);
}

/* Calibration: operating until calibration_ms has passed, then the final state. */
static void test_calibration_phase(void **state)
{
    xf_sim_config cfg;
    sim_fx *f;
    xf_gcu_packet r;
    (void)state;
    xf_sim_config_init(&cfg);
    cfg.calibration_ms = 1000;
    f = fx_new(&cfg);
    send_order(f, 1, XF_ORDER_CALIBRATION, &r);
    assert_int_equal(r.params[0], XF_STATE_OPERATING);
    f->now += 500;
    send_order(f, 1, XF_ORDER_CALIBRATION, &r);
    assert_int_equal(r.params[0], XF_STATE_OPERATING);
    f->now += 499;
    send_order(f, 1, XF_ORDER_CALIBRATION, &r);
    assert_int_equal(r.params[0], XF_STATE_OPERATING);
    f->now += 1;
    send_order(f, 1, XF_ORDER_CALIBRATION, &r);
    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    f->now += 20;
    send_order(f, 1, XF_ORDER_CALIBRATION, &r);
    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    assert_int_equal(f->s.stats.executed[XF_ORDER_CALIBRATION], 1);
    free(f);
}

/* Version 2 replies: bytes 63-66 carry thermal_status, camera_status, time_zone; rates in 0.1 deg/s. */
static void test_v2_fields_and_units(void **state)
{
    static const uint8_t versions[] = {1, 2};
    size_t k;
    (void)state;
    for (k = 0; k < 2; k++) {
        xf_sim_config cfg;
        sim_fx *f;
        xf_command cmd;
        xf_host_packet p;
        xf_gcu_packet r;
        uint8_t buf[XF_PACKET_MAX_LEN];
        size_t len = 0;
        xf_sim_config_init(&cfg);
        cfg.version = versions[k];
        f = fx_new(&cfg);
        xf_command_init(&cmd, XF_ORDER_TIME_ZONE);
        cmd.hours = -3;
        send_cmd(f, 2, &cmd, &r);
        assert_int_equal(r.version, versions[k]);
        assert_int_equal(f->out[4], versions[k]);
        if (versions[k] == 2u) {
            assert_int_equal(f->out[63], XF_THERMAL_MEASURE_AVAILABLE);
            assert_int_equal(f->out[64] | (f->out[65] << 8), XF_CAMERA_OSD_ON);
            assert_int_equal(f->out[66], 0xFD);
        } else {
            assert_int_equal(f->out[63], 0);
            assert_int_equal(f->out[64], 0);
            assert_int_equal(f->out[65], 0);
            assert_int_equal(f->out[66], 0);
        }
        /* head lock, yaw 20 deg/s for 100 ms */
        xf_host_packet_init(&p, 1);
        p.main.status = XF_STATUS_CTRL_VALID;
        p.main.yaw_ctrl = 200;
        assert_xf(xf_host_pack(&p, buf, sizeof(buf), &len), XF_OK);
        feed(f, buf, len);
        f->now += 100;
        feed(f, buf, len);
        assert_xf(xf_gcu_unpack(f->out, f->out_len, &r), XF_OK);
        assert_int_equal(r.main.rate_z, versions[k] == 2u ? 200 : 2000);
        assert_near(xf_gcu_rate_dps(r.main.rate_z, r.version), 20.0, 1e-3);
        assert_near(xf_cdeg(r.main.cam_yaw), 2.0, 0.011);
        free(f);
    }
}

/* An unknown sub frame request: bytes 37-68 all zero. */
static void test_unknown_sub_request(void **state)
{
    sim_fx *f = fx_new(NULL);
    xf_host_packet p;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0, i;
    (void)state;
    xf_host_packet_init(&p, 1);
    p.main.sub_request = 0x05;
    assert_xf(xf_host_pack(&p, buf, sizeof(buf), &len), XF_OK);
    feed(f, buf, len);
    assert_int_equal(f->out_len, 72);
    for (i = XF_OFF_SUB; i < XF_OFF_ORDER; i++) {
        assert_int_equal(f->out[i], 0);
    }
    send_order(f, 1, XF_ORDER_NULL, NULL);
    assert_int_equal(f->out[XF_OFF_SUB], XF_SUB_HEADER);
    assert_int_equal(f->out[XF_OFF_SUB + 3], 58); /* the default model code */
    free(f);
}

/* Faults in offline use: drop, corrupt, silent; ins_valid counted. */
static void test_faults_offline(void **state)
{
    sim_fx *f = fx_new(NULL);
    uint8_t buf[XF_PACKET_MAX_LEN], small[10];
    size_t len, n = 99;
    (void)state;
    len = host_bytes(buf, 1, NULL, XF_STATUS_INS_VALID);
    f->s.fault.drop_next = 2;
    feed(f, buf, len);
    assert_int_equal(f->out_len, 0);
    feed(f, buf, len);
    assert_int_equal(f->out_len, 0);
    feed(f, buf, len);
    assert_int_equal(f->out_len, 72);
    assert_int_equal(f->s.stats.dropped, 2);
    f->s.fault.corrupt_next = 1;
    feed(f, buf, len);
    assert_int_equal(f->out_len, 72);
    assert_true(xf_packet_check(f->out, f->out_len, XF_DIR_GCU) != XF_OK);
    assert_int_equal(f->out[0], XF_GCU_HEADER0); /* header and length intact */
    assert_int_equal(f->out[2], 72);
    assert_int_equal(f->s.stats.corrupted, 1);
    feed(f, buf, len);
    assert_xf(xf_packet_check(f->out, f->out_len, XF_DIR_GCU), XF_OK);
    f->s.fault.silent = 1;
    feed(f, buf, len);
    assert_int_equal(f->out_len, 0);
    f->s.fault.silent = 0;
    assert_int_equal(f->s.stats.packets_in, 6);
    assert_int_equal(f->s.stats.ins_valid_packets, 6);
    /* no room for the reply */
    assert_xf(xf_sim_process(&f->s, buf, len, f->now, small, sizeof(small), &n), XF_ERR_NO_SPACE);
    assert_int_equal(n, 0);
    free(f);
}

/* Gaze needs valid INS data; neutral does nothing in Euler mode. */
static void test_mode_preconditions(void **state)
{
    sim_fx *f = fx_new(NULL);
    xf_command cmd;
    xf_gcu_packet r;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len;
    (void)state;
    xf_command_init(&cmd, XF_ORDER_GAZE_GEO);
    cmd.latitude = 473977419;
    cmd.longitude = 85455938;
    send_cmd(f, 1, &cmd, &r);
    assert_int_equal(r.params[0], XF_STATE_FAILURE);
    send_order(f, 1, XF_ORDER_NULL, NULL);
    len = host_bytes(buf, 1, &cmd, XF_STATUS_INS_VALID);
    feed(f, buf, len);
    assert_xf(xf_gcu_unpack(f->out, f->out_len, &r), XF_OK);
    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    assert_int_equal(r.main.gimbal_mode, XF_MODE_GAZE);
    send_order(f, 1, XF_ORDER_EULER, &r);
    assert_int_equal(r.main.gimbal_mode, XF_MODE_EULER);
    send_order(f, 1, XF_ORDER_NEUTRAL, &r);
    assert_int_equal(r.params[0], XF_STATE_FAILURE);
    send_order(f, 1, XF_ORDER_HEAD_LOCK, &r);
    send_order(f, 1, XF_ORDER_NEUTRAL, &r);
    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    free(f);
}

/* Orthoview slews pitch to -90 at slew_dps; the snapshot says so. */
static void test_orthoview_slew(void **state)
{
    sim_fx *f = fx_new(NULL);
    xf_gcu_packet snap;
    (void)state;
    send_order(f, 1, XF_ORDER_ORTHOVIEW, NULL);
    f->now += 100;
    send_order(f, 1, XF_ORDER_NULL, NULL);
    xf_sim_snapshot(&f->s, &snap);
    assert_near(xf_cdeg(snap.main.cam_pitch), -12.0, 0.02); /* 120 deg/s for 100 ms */
    f->now += 200;
    send_order(f, 1, XF_ORDER_NULL, NULL);
    f->now += 200;
    send_order(f, 1, XF_ORDER_NULL, NULL);
    f->now += 200;
    send_order(f, 1, XF_ORDER_NULL, NULL);
    xf_sim_snapshot(&f->s, &snap);
    assert_near(xf_cdeg(snap.main.cam_pitch), -84.0, 0.02);
    f->now += 200;
    send_order(f, 1, XF_ORDER_NULL, NULL);
    xf_sim_snapshot(&f->s, &snap);
    assert_near(xf_cdeg(snap.main.cam_pitch), -90.0, 0.001);
    assert_int_equal(snap.main.gimbal_mode, XF_MODE_ORTHOVIEW);
    xf_sim_snapshot(NULL, &snap);
    xf_sim_snapshot(&f->s, NULL);
    free(f);
}

/* What V2.0.6 says a GCU does: neutral does not respond in track; zoom_to 5000 of a 30x camera is
 * 15x; zoom in/out/stop act on the cameras of the mask only; a valid non-zero quantity turns
 * gaze-geo into gaze lock; in orthoview after head follow yaw follows the carrier; versions in
 * tenths. */
static void test_v206_behaviours(void **state)
{
    sim_fx *f = fx_new(NULL);
    xf_command cmd;
    xf_gcu_packet r;
    int i;
    (void)state;
    assert_int_equal(f->s.cfg.hw_version, 31);
    assert_int_equal(f->s.cfg.fw_version, 50);
    /* neutral in track: no response */
    ct_valid_command(&cmd, XF_ORDER_TRACK);
    send_cmd(f, 1, &cmd, &r);
    assert_int_equal(r.main.gimbal_mode, XF_MODE_TRACK);
    send_order(f, 1, XF_ORDER_NEUTRAL, &r);
    assert_int_equal(r.params[0], XF_STATE_FAILURE);
    assert_int_equal(r.main.gimbal_mode, XF_MODE_TRACK);
    /* zoom_to 5000: half of 30x */
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.zoom = 5000;
    send_cmd(f, 1, &cmd, NULL);
    for (i = 0; i < 40; i++) { /* 4 s at 6x per second */
        f->now += 100;
        send_order(f, 1, XF_ORDER_NULL, NULL);
    }
    assert_near(f->s.zoom1, 15.0, 0.001);
    assert_near(f->s.zoom2, 1.0, 0.001); /* camera 2 was not in the mask */
    /* zoom in on camera 2 only */
    xf_command_init(&cmd, XF_ORDER_ZOOM_IN);
    cmd.cameras = XF_CAM2;
    send_cmd(f, 1, &cmd, NULL);
    for (i = 0; i < 5; i++) {
        f->now += 100;
        send_order(f, 1, XF_ORDER_NULL, NULL);
    }
    assert_near(f->s.zoom1, 15.0, 0.001);
    assert_true(f->s.zoom2 > 1.5f);
    /* gaze-geo, then a valid non-zero rate: gaze lock */
    xf_command_init(&cmd, XF_ORDER_GAZE_GEO);
    cmd.latitude = 473977419;
    cmd.longitude = 85455938;
    send_carrier(f, &cmd, 0, 0, &r);
    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    assert_true(f->s.gaze_lat != 0.0f);
    f->now += 100;
    send_carrier(f, NULL, 0, 0, NULL); /* 0 or invalid: it keeps the point */
    assert_true(f->s.gaze_lat != 0.0f);
    for (i = 0; i < 2; i++) { /* the rate acts from the step after the packet that carries it */
        f->now += 100;
        send_carrier(f, NULL, 0, 100, NULL);
    }
    assert_true(f->s.gaze_lat == 0.0f && f->s.gaze_lon == 0.0f);
    /* orthoview after head follow: yaw follows the carrier */
    xf_command_init(&cmd, XF_ORDER_HEAD_FOLLOW);
    send_carrier(f, &cmd, 0, 0, NULL);
    xf_command_init(&cmd, XF_ORDER_ORTHOVIEW);
    send_carrier(f, &cmd, 0, 0, &r);
    assert_int_equal(r.main.gimbal_mode, XF_MODE_ORTHOVIEW);
    assert_int_equal(f->s.ortho_follow, 1);
    for (i = 0; i < 10; i++) {
        f->now += 200;
        send_carrier(f, NULL, 9000, 0, NULL); /* the carrier turns to 90 deg */
    }
    assert_near(ct_angle_diff((double)f->s.yaw, 90.0 + (double)f->s.hold_yaw_offset), 0.0, 0.01);
    /* orthoview straight from head lock: yaw stays */
    xf_command_init(&cmd, XF_ORDER_HEAD_LOCK);
    send_carrier(f, &cmd, 9000, 0, NULL);
    xf_command_init(&cmd, XF_ORDER_ORTHOVIEW);
    send_carrier(f, &cmd, 9000, 0, NULL);
    assert_int_equal(f->s.ortho_follow, 0);
    {
        float yaw = f->s.yaw;
        for (i = 0; i < 5; i++) {
            f->now += 200;
            send_carrier(f, NULL, 18000, 0, NULL);
        }
        assert_near(f->s.yaw, yaw, 0.001);
    }
    free(f);
}

/* The model code picks the orders: one its model lacks (V2.0.6's support list) fails, the
 * same order on a model that has it succeeds. */
static void test_model_orders(void **state)
{
    static const struct {
        uint8_t code, order, state;
    } cases[] = {
        {0, XF_ORDER_PALETTE, XF_CAM2},           /* Z-6A: no palette; V2.0.6's failure state 0x02 */
        {41, XF_ORDER_PALETTE, XF_STATE_SUCCESS}, /* D-90AI: palette */
        {0, XF_ORDER_FOCUS, XF_STATE_SUCCESS},    /* Z-6A: focus */
        {49, XF_ORDER_FOCUS, XF_STATE_FAILURE},   /* Z-1Pro: no focus */
        {3, XF_ORDER_FOCUS, XF_STATE_SUCCESS},    /* a V2.0.4 model: the list does not know it */
        {58, XF_ORDER_SPOT_TEMP, XF_STATE_SUCCESS},
        {59, XF_ORDER_SPOT_TEMP, XF_CAM2}, /* Z-9B_V4(V): no thermometry, 0x02 */
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        xf_sim_config cfg;
        sim_fx *f;
        xf_command cmd;
        xf_gcu_packet r;
        xf_sim_config_init(&cfg);
        cfg.version = 2;
        cfg.gimbal_code = cases[i].code;
        f = fx_new(&cfg);
        ct_valid_command(&cmd, cases[i].order);
        send_cmd(f, 2, &cmd, &r);
        assert_int_equal(f->out_len, 73);
        if (r.params[0] != cases[i].state) {
            print_error("model %u, %s: state %u\n", cases[i].code, xf_order_name(cases[i].order), r.params[0]);
            fail();
        }
        free(f);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_init),
        cmocka_unit_test(test_reply_lengths),
        cmocka_unit_test(test_answers_only_correct_packets),
        cmocka_unit_test(test_once_rule),
        cmocka_unit_test(test_v206_behaviours),
        cmocka_unit_test(test_model_orders),
        cmocka_unit_test(test_every_order_gets_feedback),
        cmocka_unit_test(test_configured_failures),
        cmocka_unit_test(test_feedback_after),
        cmocka_unit_test(test_state_once),
        cmocka_unit_test(test_calibration_phase),
        cmocka_unit_test(test_v2_fields_and_units),
        cmocka_unit_test(test_unknown_sub_request),
        cmocka_unit_test(test_faults_offline),
        cmocka_unit_test(test_mode_preconditions),
        cmocka_unit_test(test_orthoview_slew),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
