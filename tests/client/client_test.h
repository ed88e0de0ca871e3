/*
 * client_test.h - helpers shared by the tests of the client and the
 * simulator (tests/client).
 *
 * The fast layer runs a client and a simulator over an in-memory link (two
 * byte queues) on a FAKE clock the test advances itself: no sleeping, no
 * OS, every run the same. The rig records what crossed the link (the order
 * of every host packet, order and length of every reply), every result and
 * every link-state callback, so tests can check the protocol's sequence as
 * well as the outcome.
 *
 * Include after the feature-test macros: it pulls in cmocka (which needs
 * setjmp.h, stdarg.h and stddef.h first).
 */
#ifndef XFGCU_CLIENT_TEST_H
#define XFGCU_CLIENT_TEST_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "xfgcu/xf_client.h"
#include "xfgcu/xf_sim.h"
#include "xfgcu/xfgcu.h"
#include "../xf_test_assert.h"

/* A command status compared with its expected value, printed by name. */
#define assert_status(expr, want)                                                                                      \
    do {                                                                                                               \
        int got_ = (int)(expr), want_ = (int)(want);                                                                   \
        if (got_ != want_) {                                                                                           \
            print_error("%s is %d (%s), expected %d (%s)\n", #expr, got_, xf_cmd_status_name((xf_cmd_status)got_),     \
                        want_, xf_cmd_status_name((xf_cmd_status)want_));                                              \
            fail();                                                                                                    \
        }                                                                                                              \
    } while (0)

/* |a - b| <= tol for floats. */
#define assert_near(a, b, tol)                                                                                         \
    do {                                                                                                               \
        double a_ = (double)(a), b_ = (double)(b), t_ = (double)(tol);                                                 \
        if (!(fabs(a_ - b_) <= t_)) {                                                                                  \
            print_error("%s = %g, expected %g +- %g\n", #a, a_, b_, t_);                                               \
            fail();                                                                                                    \
        }                                                                                                              \
    } while (0)

/* Angles: the shortest way round. */
static inline double ct_angle_diff(double a, double b)
{
    double d = fmod(a - b, 360.0);
    if (d > 180.0) {
        d -= 360.0;
    } else if (d < -180.0) {
        d += 360.0;
    }
    return fabs(d);
}

#define assert_angle_near(a, b, tol)                                                                                   \
    do {                                                                                                               \
        double a_ = (double)(a), b_ = (double)(b);                                                                     \
        if (!(ct_angle_diff(a_, b_) <= (double)(tol))) {                                                               \
            print_error("%s = %g deg, expected %g +- %g\n", #a, a_, b_, (double)(tol));                                \
            fail();                                                                                                    \
        }                                                                                                              \
    } while (0)

/* ---- what crossed a link ------------------------------------------------------- */

#define CT_LOG     8192
#define CT_RESULTS 128
#define CT_LINKS   64

/* Observations made through the client's callbacks. */
typedef struct ct_log {
    uint8_t sent_order[CT_LOG]; /* order byte of every host packet */
    uint32_t sent_ms[CT_LOG];
    size_t n_sent;
    uint8_t reply_order[CT_LOG]; /* order byte and length of every valid reply */
    uint8_t reply_len[CT_LOG];
    size_t n_replies;
    xf_cmd_result results[CT_RESULTS];
    size_t n_results;
    uint8_t links[CT_LINKS];
    uint32_t link_ms[CT_LINKS];
    uint32_t link_replies[CT_LINKS]; /* health.replies when the callback ran */
    size_t n_links;
    size_t n_telemetry;
    uint32_t (*clock)(void *ctx); /* for timestamps in callbacks that carry none */
    void *clock_ctx;
    const xf_client *client;
    /* The client writes packets and reads telemetry at its own offsets:
     * every packet and every telemetry update is checked against the codec. */
    size_t n_host_checked, n_host_mismatch; /* host packets that are not what xf_host_pack makes of them */
    size_t n_tele_checked, n_tele_mismatch; /* telemetry not what xf_gcu_unpack reads in the reply */
    uint8_t last_reply[XF_PACKET_LIMIT];
    size_t last_reply_len;
} ct_log;

static inline void ct_on_result(void *user, const xf_cmd_result *r)
{
    ct_log *l = (ct_log *)user;
    if (l->n_results < CT_RESULTS) {
        l->results[l->n_results++] = *r;
    }
}

static inline void ct_on_link(void *user, xf_link_state s)
{
    ct_log *l = (ct_log *)user;
    if (l->n_links < CT_LINKS) {
        l->links[l->n_links] = (uint8_t)s;
        l->link_ms[l->n_links] = (l->clock != NULL) ? l->clock(l->clock_ctx) : 0u;
        l->link_replies[l->n_links] = (l->client != NULL) ? l->client->health.replies : 0u;
        l->n_links++;
    }
}

/* Does @p t hold the fields of reply @p g (the sub frame's when it has one)? */
static inline int ct_tele_matches(const xf_telemetry *t, const xf_gcu_packet *g)
{
    const xf_gcu_main *m = &g->main;
    const xf_gcu_sub *s = &g->sub;
    int ok = t->have_main == 1 && t->version == g->version && t->gimbal_mode == m->gimbal_mode &&
             t->pod_status == m->pod_status && t->target_offset_x == m->target_offset_x &&
             t->target_offset_y == m->target_offset_y && t->rel_angle_x == m->rel_angle_x &&
             t->rel_angle_y == m->rel_angle_y && t->rel_angle_z == m->rel_angle_z && t->cam_roll == m->cam_roll &&
             t->cam_pitch == m->cam_pitch && t->cam_yaw == m->cam_yaw && t->rate_x == m->rate_x &&
             t->rate_y == m->rate_y && t->rate_z == m->rate_z;
    if (s->sub_header == XF_SUB_HEADER) {
        ok = ok && t->have_sub == 1 && t->hw_version == s->hw_version && t->fw_version == s->fw_version &&
             t->gimbal_code == s->gimbal_code && t->error_code == s->error_code &&
             t->target_distance == s->target_distance && t->target_longitude == s->target_longitude &&
             t->target_latitude == s->target_latitude && t->target_altitude == s->target_altitude &&
             t->zoom_cam1 == s->zoom_cam1 && t->zoom_cam2 == s->zoom_cam2 && t->thermal_status == s->thermal_status &&
             t->camera_status == s->camera_status && t->time_zone == s->time_zone;
    }
    return ok;
}

static inline void ct_on_telemetry(void *user, const xf_telemetry *t)
{
    ct_log *l = (ct_log *)user;
    xf_gcu_packet g;
    l->n_telemetry++;
    if (l->last_reply_len > 0u) { /* on_bytes showed the reply first */
        l->n_tele_checked++;
        if (xf_gcu_unpack(l->last_reply, l->last_reply_len, &g) != XF_OK || !ct_tele_matches(t, &g)) {
            l->n_tele_mismatch++;
        }
    }
}

/* Is @p data what xf_host_pack makes of its own unpacking (same bytes, reserved ones zero)? */
static inline int ct_host_canonical(const uint8_t *data, size_t len)
{
    xf_host_packet p;
    uint8_t again[XF_PACKET_LIMIT];
    size_t n = 0;
    return xf_host_unpack(data, len, &p) == XF_OK && xf_host_pack(&p, again, sizeof(again), &n) == XF_OK && n == len &&
           memcmp(again, data, len) == 0;
}

static inline void ct_on_bytes(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    ct_log *l = (ct_log *)user;
    if (len < XF_PACKET_MIN_LEN) {
        return;
    }
    if (dir == XF_DIR_HOST) {
        l->n_host_checked++;
        l->n_host_mismatch += !ct_host_canonical(data, len);
    } else if (len <= sizeof(l->last_reply)) {
        memcpy(l->last_reply, data, len);
        l->last_reply_len = len;
    }
    if (dir == XF_DIR_HOST && l->n_sent < CT_LOG) {
        l->sent_order[l->n_sent] = data[XF_OFF_ORDER];
        l->sent_ms[l->n_sent] = now_ms;
        l->n_sent++;
    } else if (dir == XF_DIR_GCU && l->n_replies < CT_LOG) {
        l->reply_order[l->n_replies] = data[XF_OFF_ORDER];
        l->reply_len[l->n_replies] = (uint8_t)len;
        l->n_replies++;
    }
}

/* Point a client configuration's callbacks at @p log. */
static inline void ct_log_hook(ct_log *log, xf_client_config *cfg)
{
    cfg->on_result = ct_on_result;
    cfg->on_link = ct_on_link;
    cfg->on_telemetry = ct_on_telemetry;
    cfg->on_bytes = ct_on_bytes;
    cfg->user = log;
}

/* The last result of command @p id seen by the callback, or NULL. */
static inline const xf_cmd_result *ct_result_of(const ct_log *log, uint32_t id)
{
    size_t i = log->n_results;
    while (i-- > 0u) {
        if (log->results[i].id == id) {
            return &log->results[i];
        }
    }
    return NULL;
}

/* Times the link callback reported @p s. */
static inline size_t ct_link_count(const ct_log *log, xf_link_state s)
{
    size_t i, n = 0;
    for (i = 0; i < log->n_links; i++) {
        n += (log->links[i] == (uint8_t)s);
    }
    return n;
}

/* Replies of @p order that carried an execution state (73 bytes). */
static inline size_t ct_state_replies(const ct_log *log, uint8_t order)
{
    size_t i, n = 0;
    for (i = 0; i < log->n_replies; i++) {
        n += (log->reply_order[i] == order && log->reply_len[i] > XF_PACKET_MIN_LEN);
    }
    return n;
}

/* ---- an in-memory link ---------------------------------------------------------- */

#define CT_FIFO 16384

typedef struct ct_fifo {
    uint8_t buf[CT_FIFO];
    size_t len;
    uint32_t overflow;
} ct_fifo;

static inline void ct_fifo_put(ct_fifo *f, const uint8_t *data, size_t len)
{
    if (f->len + len > sizeof(f->buf)) {
        f->overflow++;
        return;
    }
    memcpy(f->buf + f->len, data, len);
    f->len += len;
}

static inline size_t ct_fifo_get(ct_fifo *f, uint8_t *buf, size_t cap)
{
    size_t n = (f->len < cap) ? f->len : cap;
    memcpy(buf, f->buf, n);
    memmove(f->buf, f->buf + n, f->len - n);
    f->len -= n;
    return n;
}

struct ct_rig;

/* One end of the in-memory link. */
typedef struct ct_end {
    ct_fifo *in, *out;
    struct ct_rig *rig;
    int closed;     /* read and write return XF_ERR_CLOSED */
    int cut;        /* writes vanish (a cable cut that the transport cannot see) */
    uint32_t chunk; /* deliver reads at most this many bytes (0: all) */
    int overread;   /* a broken backend: a read fills its buffer and says it copied one more */
} ct_end;

/* A client and a simulator on an in-memory link with a fake clock. */
typedef struct ct_rig {
    uint32_t now;
    ct_fifo h2g, g2h;
    ct_end host, gcu;
    xf_hal host_hal, gcu_hal;
    xf_client c;
    xf_sim s;
    int sim_on; /* 0: the test plays the GCU itself (ct_gcu_reply) */
    ct_log log;
} ct_rig;

static inline xf_err ct_end_write(void *ctx, const uint8_t *data, size_t len)
{
    ct_end *e = (ct_end *)ctx;
    if (e->closed) {
        return XF_ERR_CLOSED;
    }
    if (!e->cut) {
        ct_fifo_put(e->out, data, len);
    }
    return XF_OK;
}

static inline xf_err ct_end_read(void *ctx, uint8_t *buf, size_t cap, size_t *n)
{
    ct_end *e = (ct_end *)ctx;
    *n = 0;
    if (e->closed) {
        return XF_ERR_CLOSED;
    }
    if (e->overread) {
        memset(buf, XF_GCU_HEADER0, cap); /* bytes the parser would count */
        *n = cap + 1u;
        return XF_OK;
    }
    if (e->chunk != 0u && cap > e->chunk) {
        cap = e->chunk;
    }
    *n = ct_fifo_get(e->in, buf, cap);
    return XF_OK;
}

static inline uint32_t ct_rig_clock(void *ctx) { return ((ct_rig *)ctx)->now; }

/*
 * A rig on the heap (the client keeps pointers into it). @p cc / @p sc NULL
 * mean defaults; the rig's callbacks replace any in @p cc. The clock starts
 * at @p t0. The client is initialised (its return value in *init_err if
 * not NULL), the simulator attached.
 */
static inline ct_rig *ct_rig_new_at(const xf_client_config *cc, const xf_sim_config *sc, uint32_t t0)
{
    ct_rig *r = (ct_rig *)calloc(1, sizeof(*r));
    xf_client_config ccfg;
    xf_err err;
    assert_non_null(r);
    r->now = t0;
    r->host.in = &r->g2h;
    r->host.out = &r->h2g;
    r->host.rig = r;
    r->gcu.in = &r->h2g;
    r->gcu.out = &r->g2h;
    r->gcu.rig = r;
    r->host_hal.ctx = &r->host;
    r->host_hal.read = ct_end_read;
    r->host_hal.write = ct_end_write;
    r->host_hal.fd = NULL;
    r->gcu_hal = r->host_hal;
    r->gcu_hal.ctx = &r->gcu;
    if (cc != NULL) {
        ccfg = *cc;
    } else {
        xf_client_config_init(&ccfg);
    }
    ct_log_hook(&r->log, &ccfg);
    r->log.clock = ct_rig_clock;
    r->log.clock_ctx = r;
    r->log.client = &r->c;
    err = xf_client_init(&r->c, &r->host_hal, &ccfg);
    if (err != XF_OK && err != XF_WARN_RATE) {
        print_error("xf_client_init: %s\n", xf_strerror(err));
        free(r);
        fail();
    }
    assert_xf(xf_sim_init(&r->s, sc), XF_OK);
    assert_xf(xf_sim_attach(&r->s, &r->gcu_hal), XF_OK);
    r->sim_on = 1;
    return r;
}

static inline ct_rig *ct_rig_new(const xf_client_config *cc, const xf_sim_config *sc)
{
    return ct_rig_new_at(cc, sc, 1000u);
}

/* One millisecond: the clock moves on, then the simulator and the client step. */
static inline void ct_tick(ct_rig *r)
{
    r->now++;
    if (r->sim_on) {
        (void)xf_sim_step(&r->s, r->now);
    }
    (void)xf_client_step(&r->c, r->now);
}

static inline void ct_run(ct_rig *r, uint32_t ms)
{
    uint32_t i;
    for (i = 0; i < ms; i++) {
        ct_tick(r);
    }
}

/* Run until command @p id has a final status, at most @p max_ms; returns the status. */
static inline xf_cmd_status ct_run_cmd(ct_rig *r, uint32_t id, uint32_t max_ms, xf_cmd_result *res)
{
    uint32_t i;
    xf_cmd_status st = xf_client_command_status(&r->c, id, res);
    for (i = 0; i < max_ms && (st == XF_CMD_QUEUED || st == XF_CMD_SENDING || st == XF_CMD_OPERATING); i++) {
        ct_tick(r);
        st = xf_client_command_status(&r->c, id, res);
    }
    return st;
}

/* Run until the link is @p want, at most @p max_ms; 1 if it got there. */
static inline int ct_run_link(ct_rig *r, xf_link_state want, uint32_t max_ms)
{
    uint32_t i;
    for (i = 0; i < max_ms && xf_client_link(&r->c) != want; i++) {
        ct_tick(r);
    }
    return xf_client_link(&r->c) == want;
}

/* A command for every order, valid for protocol V2. */
static inline void ct_valid_command(xf_command *cmd, uint8_t order)
{
    xf_command_init(cmd, order);
    switch (order) {
    case XF_ORDER_ZOOM_TO: cmd->zoom = 5000; break;
    case XF_ORDER_TRACK:
    case XF_ORDER_AREA_TEMP:
        cmd->value = 1;
        cmd->x0 = 1000;
        cmd->y0 = 1000;
        cmd->x1 = 2000;
        cmd->y1 = 2000;
        break;
    case XF_ORDER_EXTERNAL_TRACK: cmd->value = 2; break;
    case XF_ORDER_RANGING: cmd->value = 2; break;
    case XF_ORDER_TEMP_ALARM:
    case XF_ORDER_ISOTHERM:
        cmd->value = 1;
        cmd->temp_high = 500;
        cmd->temp_low = 100;
        break;
    default: break;
    }
}

/* Submit a command with default parameters for @p order; returns its id. */
static inline uint32_t ct_submit(ct_rig *r, uint8_t order)
{
    xf_command cmd;
    uint32_t id = 0;
    xf_command_init(&cmd, order);
    assert_xf(xf_client_submit(&r->c, &cmd, &id, NULL), XF_OK);
    assert_true(id != 0u);
    return id;
}

static inline uint32_t ct_submit_cmd(ct_rig *r, const xf_command *cmd)
{
    uint32_t id = 0;
    assert_xf(xf_client_submit(&r->c, cmd, &id, NULL), XF_OK);
    return id;
}

/* The test plays the GCU: put one reply on the link to the host. */
static inline void ct_gcu_reply(ct_rig *r, const xf_gcu_packet *p)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    assert_xf(xf_gcu_pack(p, buf, sizeof(buf), &len), XF_OK);
    ct_fifo_put(&r->g2h, buf, len);
}

/* Take every host packet the client has written; returns how many; the last in *last. */
static inline size_t ct_drain_host(ct_rig *r, xf_host_packet *last)
{
    size_t n = 0;
    xf_parser p;
    uint8_t buf[CT_FIFO];
    size_t len = ct_fifo_get(&r->h2g, buf, sizeof(buf)), off = 0;
    xf_parser_init(&p, XF_DIR_HOST);
    while (off < len) { /* a frame comes from the call that feeds its last byte */
        size_t used = 0;
        xf_frame f;
        xf_parse_status rc = xf_parser_feed(&p, buf + off, len - off, &used, &f);
        off += used;
        if (rc != XF_PARSE_FRAME) {
            break;
        }
        if (last != NULL) {
            assert_xf(xf_host_unpack(f.data, f.len, last), XF_OK);
        }
        n++;
    }
    return n;
}

/* Free the rig, after checking that every packet it saw agreed with the codec. */
static inline void ct_rig_free(ct_rig *r)
{
    size_t host_bad = r->log.n_host_mismatch, tele_bad = r->log.n_tele_mismatch;
    free(r);
    assert_int_equal(host_bad, 0);
    assert_int_equal(tele_bad, 0);
}

/* ---- what the packets show ----------------------------------------------------- */

/* Maximal runs of consecutive host packets of @p order. */
static inline size_t runs_of(const ct_log *log, uint8_t order)
{
    size_t i, n = 0;
    for (i = 0; i < log->n_sent; i++) {
        if (log->sent_order[i] == order && (i == 0u || log->sent_order[i - 1u] != order)) {
            n++;
        }
    }
    return n;
}

/* Host packets of @p order from index @p from on. */
static inline size_t sent_count(const ct_log *log, uint8_t order, size_t from)
{
    size_t i, n = 0;
    for (i = from; i < log->n_sent; i++) {
        n += (log->sent_order[i] == order);
    }
    return n;
}

/* Every run of @p order is followed by a null packet (when anything follows it). */
static inline void assert_null_after_runs(const ct_log *log, uint8_t order)
{
    size_t i;
    for (i = 0; i + 1u < log->n_sent; i++) {
        if (log->sent_order[i] == order && log->sent_order[i + 1u] != order) {
            if (log->sent_order[i + 1u] != XF_ORDER_NULL) {
                print_error("packet %u after a run of 0x%02X is 0x%02X, not null\n", (unsigned)(i + 1u), order,
                            log->sent_order[i + 1u]);
                fail();
            }
        }
    }
}

/* Whether the link is up, shown to keep order, and every packet answered. */
static inline int ct_ready(const ct_rig *r)
{
    const xf_health *h = xf_client_health(&r->c);
    return h->link == XF_LINK_UP && h->in_order && h->replies == h->packets_sent;
}

/* Run until the link is up and shown to keep order (xf_health.in_order: six packets answered
 * alike on a clean link), and the last packet answered, at most @p max_ms; 1 if it got there.
 * A new client runs its first command from then on without a bound of its own
 * (docs/protocol.md §7.4). */
static inline int ct_run_ready(ct_rig *r, uint32_t max_ms)
{
    uint32_t i;
    for (i = 0; i < max_ms && !ct_ready(r); i++) {
        ct_tick(r);
    }
    return ct_ready(r);
}

/* A rig whose link is up and judged: ready to run commands at once. */
static inline ct_rig *rig_up(const xf_client_config *cc, const xf_sim_config *sc)
{
    ct_rig *r = ct_rig_new(cc, sc);
    assert_true(ct_run_ready(r, 1000));
    return r;
}

#endif /* XFGCU_CLIENT_TEST_H */
