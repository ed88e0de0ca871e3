/*
 * test_client_callbacks.c - what a callback may call (xf_client.h, at the
 * callback types), against the simulator over an in-memory link on a fake
 * clock (client_test.h): submit and cancel from on_result, a nested step
 * refused, sweeps that nest, state read and inputs set from every callback.
 */
#include "client_test.h"

/* ---- what a callback may call (xf_client.h, at the callback types) ---------------------------- */

/* A status as a bit of cb_probe.resubmit_on. */
#define CB_ST(status) (1u << (unsigned)(status))

/* Where a probe callback ran. */
enum { CB_RESULT, CB_TELEMETRY, CB_LINK, CB_BYTES_HOST, CB_BYTES_GCU, CB_KINDS };

/* What the probe's callbacks do, and what they saw. One test at a time uses it. */
typedef struct cb_probe {
    ct_rig *r;
    /* actions */
    int try_step;            /* try a nested xf_client_step() from every callback */
    uint32_t submit_after;   /* on this command's final result, submit submit_order (once) */
    uint8_t submit_order;    /* ... */
    uint32_t cancel_after;   /* on this command's final result, call xf_client_cancel_all() */
    unsigned resubmit_on;    /* resubmit every command that ends with a status in this mask (CB_ST) ... */
    uint32_t resubmit_max;   /* ... at most this many times (a sweep that never ends fails, not hangs) */
    uint32_t resubmit_below; /* ... only commands with an id below this (0: any) */
    int read_state;          /* check what the state readers give in every callback */
    int set_inputs;          /* on the first telemetry: set rates and start the external-track stream */
    /* observations */
    size_t calls[CB_KINDS];
    size_t step_tries, step_not_busy, step_changed;
    uint32_t submitted;             /* the id submit_after's command got */
    xf_err submit_err;              /* ... and what xf_client_submit returned */
    xf_cmd_status submitted_status; /* ... and its status, asked from inside the callback */
    size_t pending_after_submit;
    size_t pending_after_cancel;
    uint32_t resubmitted[16];
    size_t n_resubmitted;
    size_t pending_at_down; /* xf_client_pending() in on_link(DOWN) */
    size_t bad;             /* state readers that disagreed with the callback */
    const char *first_bad;
    size_t host_packets, gcu_packets;
} cb_probe;

static cb_probe g_probe;

static void probe_bad(cb_probe *p, int ok, const char *what)
{
    if (!ok) {
        if (p->bad++ == 0u) {
            p->first_bad = what;
        }
    }
}

/* A nested step must be refused and leave the client exactly as it was. */
static void probe_try_step(cb_probe *p)
{
    static xf_client before; /* static: the client is large for a callback's stack */
    memcpy(&before, &p->r->c, sizeof(before));
    p->step_tries++;
    p->step_not_busy += (xf_client_step(&p->r->c, p->r->now + 500u) != XF_ERR_BUSY);
    p->step_changed += (memcmp(&before, &p->r->c, sizeof(before)) != 0);
}

/* Every state reader works from inside a callback. */
static void probe_read_common(cb_probe *p)
{
    const xf_client *c = &p->r->c;
    xf_telemetry_units u;
    probe_bad(p, xf_client_telemetry(c) == &c->tele, "telemetry");
    probe_bad(p, xf_client_health(c) == &c->health, "health");
    probe_bad(p, xf_client_parser_stats(c) != NULL, "parser stats");
    probe_bad(p, xf_client_pending(c) <= XF_CLIENT_QUEUE, "pending");
    probe_bad(p, xf_client_link(c) == xf_client_health(c)->link, "link");
    probe_bad(p, xf_telemetry_convert(xf_client_telemetry(c), &u) == XF_OK, "convert");
    (void)xf_client_next_deadline(c);
}

static void probe_on_result(void *user, const xf_cmd_result *res)
{
    cb_probe *p = &g_probe;
    xf_client *c = &p->r->c;
    ct_on_result(user, res);
    p->calls[CB_RESULT]++;
    if (p->read_state) {
        xf_cmd_result got;
        xf_cmd_status st = xf_client_command_status(c, res->id, &got);
        probe_read_common(p);
        probe_bad(p, st == res->status, "command status in on_result");
        probe_bad(p, res->status == XF_CMD_OPERATING || got.id == res->id, "kept result in on_result");
        probe_bad(p, res->status != XF_CMD_LINK_LOST || xf_client_link(c) == XF_LINK_DOWN,
                  "link in a link-lost result");
    }
    if (p->try_step) {
        probe_try_step(p);
    }
    if (res->status != XF_CMD_OPERATING && res->id == p->submit_after && p->submitted == 0u) {
        xf_command cmd;
        xf_command_init(&cmd, p->submit_order);
        p->submit_err = xf_client_submit(c, &cmd, &p->submitted, NULL);
        p->submitted_status = xf_client_command_status(c, p->submitted, NULL);
        p->pending_after_submit = xf_client_pending(c);
    }
    if ((p->resubmit_on & CB_ST(res->status)) != 0u && p->n_resubmitted < p->resubmit_max &&
        p->n_resubmitted < sizeof(p->resubmitted) / sizeof(p->resubmitted[0]) &&
        (p->resubmit_below == 0u || res->id < p->resubmit_below)) {
        xf_command cmd;
        uint32_t id = 0;
        xf_command_init(&cmd, res->order);
        if (xf_client_submit(c, &cmd, &id, NULL) == XF_OK) {
            p->resubmitted[p->n_resubmitted++] = id;
        }
    }
    if (res->status != XF_CMD_OPERATING && res->id == p->cancel_after) {
        xf_client_cancel_all(c);
        p->pending_after_cancel = xf_client_pending(c);
    }
}

static void probe_on_telemetry(void *user, const xf_telemetry *t)
{
    cb_probe *p = &g_probe;
    xf_client *c = &p->r->c;
    ct_on_telemetry(user, t);
    p->calls[CB_TELEMETRY]++;
    if (p->read_state) {
        probe_read_common(p);
        probe_bad(p, t == xf_client_telemetry(c) && t->have_main, "telemetry in on_telemetry");
        probe_bad(p, xf_client_health(c)->replies == p->gcu_packets, "replies in on_telemetry");
        probe_bad(p, xf_client_health(c)->last_rx_ms == p->r->now, "last_rx_ms in on_telemetry");
        probe_bad(p, xf_client_link(c) != XF_LINK_DOWN, "link in on_telemetry");
    }
    if (p->try_step) {
        probe_try_step(p);
    }
    if (p->set_inputs && p->calls[CB_TELEMETRY] == 1u) {
        (void)xf_client_set_rates(c, 0.0f, -20.0f, 30.0f, p->r->now); /* the simulator is in head lock */
        probe_bad(p, xf_client_external_track(c, XF_CAM1, 100, -100) == XF_OK, "external track in on_telemetry");
    }
}

static void probe_on_link(void *user, xf_link_state s)
{
    cb_probe *p = &g_probe;
    xf_client *c = &p->r->c;
    ct_on_link(user, s);
    p->calls[CB_LINK]++;
    if (p->read_state) {
        probe_read_common(p);
        probe_bad(p, xf_client_link(c) == s && xf_client_health(c)->link == s, "link in on_link");
    }
    if (s == XF_LINK_DOWN) {
        p->pending_at_down = xf_client_pending(c);
    }
    if (p->try_step) {
        probe_try_step(p);
    }
}

static void probe_on_bytes(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    cb_probe *p = &g_probe;
    xf_client *c = &p->r->c;
    ct_on_bytes(user, dir, data, len, now_ms);
    if (dir == XF_DIR_HOST) {
        p->calls[CB_BYTES_HOST]++;
        p->host_packets++;
    } else {
        p->calls[CB_BYTES_GCU]++;
        p->gcu_packets++;
    }
    if (p->read_state) {
        probe_read_common(p);
        probe_bad(p, now_ms == p->r->now, "time in on_bytes");
        if (dir == XF_DIR_HOST) {
            probe_bad(p, xf_client_health(c)->packets_sent == p->host_packets, "packets_sent in on_bytes");
        } else { /* before the client processes the reply: not counted yet */
            probe_bad(p, xf_client_health(c)->replies + 1u == p->gcu_packets, "replies in on_bytes");
        }
    }
    if (p->try_step) {
        probe_try_step(p);
    }
}

/* A rig (not yet stepped) whose callbacks are the probe's, which also log as the rig's do. */
static ct_rig *probe_rig(const xf_client_config *cc)
{
    ct_rig *r = ct_rig_new(cc, NULL);
    memset(&g_probe, 0, sizeof(g_probe));
    g_probe.r = r;
    r->c.cfg.on_result = probe_on_result;
    r->c.cfg.on_telemetry = probe_on_telemetry;
    r->c.cfg.on_link = probe_on_link;
    r->c.cfg.on_bytes = probe_on_bytes;
    return r;
}

static void assert_probe_clean(const cb_probe *p)
{
    if (p->bad != 0u) {
        print_error("%u state reads disagreed in callbacks, the first: %s\n", (unsigned)p->bad, p->first_bad);
        fail();
    }
    assert_int_equal(p->step_not_busy, 0);
    assert_int_equal(p->step_changed, 0);
}

/* A command submitted from on_result is queued at once and runs next, after the null. */
static void test_cb_submit_from_on_result(void **state)
{
    ct_rig *r = probe_rig(NULL);
    uint32_t a;
    (void)state;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    a = ct_submit(r, XF_ORDER_SHUTTER);
    g_probe.submit_after = a;
    g_probe.submit_order = XF_ORDER_RECORD;
    assert_status(ct_run_cmd(r, a, 1000, NULL), XF_CMD_OK);
    assert_xf(g_probe.submit_err, XF_OK);
    assert_true(g_probe.submitted != 0u && g_probe.submitted != a);
    assert_status(g_probe.submitted_status, XF_CMD_QUEUED);
    assert_int_equal(g_probe.pending_after_submit, 1); /* the finished one is gone, the new one in */
    assert_status(ct_run_cmd(r, g_probe.submitted, 1000, NULL), XF_CMD_OK);
    assert_int_equal(r->s.stats.executed[XF_ORDER_RECORD], 1);
    assert_int_equal(runs_of(&r->log, XF_ORDER_SHUTTER), 1);
    assert_int_equal(runs_of(&r->log, XF_ORDER_RECORD), 1);
    assert_null_after_runs(&r->log, XF_ORDER_SHUTTER);
    assert_int_equal(r->log.n_results, 2);
    assert_int_equal(r->log.results[1].id, g_probe.submitted);
    ct_rig_free(r);
}

/* xf_client_cancel_all() from on_result cancels what is queued behind; its results nest in the callback. */
static void test_cb_cancel_all_from_on_result(void **state)
{
    ct_rig *r = probe_rig(NULL);
    uint32_t a, b, c;
    (void)state;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    a = ct_submit(r, XF_ORDER_SHUTTER);
    b = ct_submit(r, XF_ORDER_RECORD);
    c = ct_submit(r, XF_ORDER_FOCUS);
    g_probe.cancel_after = a;
    g_probe.try_step = 1; /* also from the nested on_result of the cancel */
    assert_status(ct_run_cmd(r, a, 1000, NULL), XF_CMD_OK);
    assert_int_equal(g_probe.pending_after_cancel, 0);
    assert_int_equal(xf_client_pending(&r->c), 0);
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_CANCELLED);
    assert_status(xf_client_command_status(&r->c, c, NULL), XF_CMD_CANCELLED);
    assert_int_equal(r->log.n_results, 3);
    assert_int_equal(r->log.results[0].id, a);
    assert_int_equal(r->log.results[1].id, b);
    assert_int_equal(r->log.results[2].id, c);
    ct_run(r, 200);
    assert_int_equal(runs_of(&r->log, XF_ORDER_RECORD), 0); /* never sent */
    assert_int_equal(runs_of(&r->log, XF_ORDER_FOCUS), 0);
    assert_int_equal(r->log.sent_order[r->log.n_sent - 1u], XF_ORDER_NULL);
    assert_true(g_probe.step_tries >= 3u);
    assert_probe_clean(&g_probe);
    ct_rig_free(r);
}

/* xf_client_step() from inside any callback returns XF_ERR_BUSY and changes nothing. */
static void test_cb_step_is_busy(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    uint32_t a, b;
    size_t k;
    (void)state;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 5000;
    r = probe_rig(&cc);
    g_probe.try_step = 1;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000)); /* on_link(UP), on_bytes both ways, on_telemetry */
    a = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, a, 1000, NULL), XF_CMD_OK); /* on_result inside the step */
    r->s.fault.silent = 1;
    a = ct_submit(r, XF_ORDER_RECORD);
    ct_run(r, 30);
    xf_client_cancel_all(&r->c); /* on_result inside xf_client_cancel_all(), outside any step */
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_CANCELLED);
    b = ct_submit(r, XF_ORDER_FOCUS);
    assert_true(ct_run_link(r, XF_LINK_DOWN, 2000)); /* on_result(LINK_LOST), on_link(STALE, DOWN) */
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_LINK_LOST);
    for (k = 0; k < CB_KINDS; k++) {
        assert_true(g_probe.calls[k] >= 1u);
    }
    assert_int_equal(g_probe.step_tries, g_probe.calls[CB_RESULT] + g_probe.calls[CB_TELEMETRY] +
                                             g_probe.calls[CB_LINK] + g_probe.calls[CB_BYTES_HOST] +
                                             g_probe.calls[CB_BYTES_GCU]);
    assert_probe_clean(&g_probe);
    /* outside the callbacks the client steps as before */
    g_probe.try_step = 0;
    r->s.fault.silent = 0;
    assert_true(ct_run_link(r, XF_LINK_UP, 200));
    assert_xf(xf_client_step(&r->c, r->now + 1u), XF_OK);
    ct_rig_free(r);
}

/* On_result resubmitting every command the link-lost sweep finishes: the sweep ends, the new commands survive it. */
static void test_cb_resubmit_during_link_lost_sweep(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    uint32_t old[3];
    size_t i;
    (void)state;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 5000; /* the link goes down first */
    r = probe_rig(&cc);
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    r->s.fault.silent = 1;
    old[0] = ct_submit(r, XF_ORDER_SHUTTER);
    old[1] = ct_submit(r, XF_ORDER_RECORD);
    old[2] = ct_submit(r, XF_ORDER_FOCUS);
    g_probe.resubmit_on = CB_ST(XF_CMD_LINK_LOST);
    g_probe.resubmit_max = 12; /* a sweep that took its own resubmissions would reach this */
    assert_true(ct_run_link(r, XF_LINK_DOWN, 2000));
    assert_int_equal(g_probe.n_resubmitted, 3);
    assert_int_equal(g_probe.pending_at_down, 3); /* on_link(DOWN) comes after the sweep */
    assert_int_equal(xf_client_pending(&r->c), 3);
    for (i = 0; i < 3u; i++) {
        xf_cmd_status st = xf_client_command_status(&r->c, g_probe.resubmitted[i], NULL);
        assert_status(xf_client_command_status(&r->c, old[i], NULL), XF_CMD_LINK_LOST);
        assert_true(st == XF_CMD_QUEUED || st == XF_CMD_SENDING);
    }
    assert_int_equal(r->log.n_results, 3);
    /* the survivors run once the GCU answers again; the lost shutter's packets never had a reply,
     * so the guard holds (one of its replies could still come, on a link that stalled) until it
     * gives up, command_timeout_ms after the loss */
    g_probe.resubmit_on = 0;
    r->s.fault.silent = 0;
    for (i = 0; i < 3u; i++) {
        assert_status(ct_run_cmd(r, g_probe.resubmitted[i], 8000, NULL), XF_CMD_OK);
    }
    assert_int_equal(r->s.stats.executed[XF_ORDER_RECORD], 1);
    assert_int_equal(r->s.stats.executed[XF_ORDER_FOCUS], 1);
    ct_rig_free(r);
}

/* The same for xf_client_cancel_all(): it cancels what was queued when it was called, and no more. */
static void test_cb_resubmit_during_cancel_all(void **state)
{
    ct_rig *r = probe_rig(NULL);
    uint32_t old[3];
    size_t i;
    (void)state;
    assert_true(ct_run_ready(r, 1000));
    r->s.fault.silent = 1; /* nothing finishes on its own */
    old[0] = ct_submit(r, XF_ORDER_SHUTTER);
    old[1] = ct_submit(r, XF_ORDER_RECORD);
    old[2] = ct_submit(r, XF_ORDER_FOCUS);
    ct_run(r, 25);
    assert_status(xf_client_command_status(&r->c, old[0], NULL), XF_CMD_SENDING);
    g_probe.resubmit_on = CB_ST(XF_CMD_CANCELLED);
    g_probe.resubmit_max = 12;
    xf_client_cancel_all(&r->c);
    assert_int_equal(g_probe.n_resubmitted, 3);
    assert_int_equal(xf_client_pending(&r->c), 3);
    for (i = 0; i < 3u; i++) {
        assert_status(xf_client_command_status(&r->c, old[i], NULL), XF_CMD_CANCELLED);
        assert_status(xf_client_command_status(&r->c, g_probe.resubmitted[i], NULL), XF_CMD_QUEUED);
    }
    g_probe.resubmit_on = 0;
    r->s.fault.silent = 0;
    for (i = 0; i < 3u; i++) {
        assert_status(ct_run_cmd(r, g_probe.resubmitted[i], 3000, NULL), XF_CMD_OK);
    }
    ct_rig_free(r);
}

/*
 * Sweeps nest. The link is lost with a, b, c queued; on_result resubmits
 * each of them, and on a's result also cancels everything. a is lost and
 * resubmitted (x); the cancel then finishes b, c and x (queued before it
 * began) while b and c are resubmitted (y, z); y and z survive the cancel
 * and the link-lost sweep around it, and run once the GCU answers again.
 */
static void test_cb_nested_sweeps(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    uint32_t a, b, c;
    const uint32_t *again = g_probe.resubmitted;
    (void)state;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 5000;
    r = probe_rig(&cc);
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    r->s.fault.silent = 1;
    a = ct_submit(r, XF_ORDER_SHUTTER);
    b = ct_submit(r, XF_ORDER_RECORD);
    c = ct_submit(r, XF_ORDER_FOCUS);
    g_probe.resubmit_on = CB_ST(XF_CMD_LINK_LOST) | CB_ST(XF_CMD_CANCELLED);
    g_probe.resubmit_max = 12;
    g_probe.resubmit_below = c + 1u; /* a, b and c only */
    g_probe.cancel_after = a;
    assert_true(ct_run_link(r, XF_LINK_DOWN, 2000));
    assert_int_equal(g_probe.n_resubmitted, 3); /* x, y, z */
    assert_int_equal(g_probe.pending_after_cancel, 2);
    assert_int_equal(g_probe.pending_at_down, 2);
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_LINK_LOST);
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_CANCELLED);
    assert_status(xf_client_command_status(&r->c, c, NULL), XF_CMD_CANCELLED);
    assert_status(xf_client_command_status(&r->c, again[0], NULL), XF_CMD_CANCELLED);
    assert_int_equal(r->log.n_results, 4);
    assert_int_equal(r->log.results[3].id, again[0]);
    assert_int_equal(r->log.results[3].order, XF_ORDER_SHUTTER);
    assert_int_equal(xf_client_pending(&r->c), 2);
    g_probe.resubmit_on = 0;
    r->s.fault.silent = 0;
    assert_status(ct_run_cmd(r, again[1], 3000, NULL), XF_CMD_OK);
    assert_status(ct_run_cmd(r, again[2], 3000, NULL), XF_CMD_OK);
    assert_int_equal(r->s.stats.executed[XF_ORDER_RECORD], 1);
    assert_int_equal(r->s.stats.executed[XF_ORDER_FOCUS], 1);
    ct_rig_free(r);
}

/* Every callback reads the client's state, and sees it as the contract says. */
static void test_cb_read_state(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    uint32_t a, b, cal;
    size_t k;
    (void)state;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 5000;
    r = probe_rig(&cc);
    g_probe.read_state = 1;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    a = ct_submit(r, XF_ORDER_SHUTTER);
    cal = ct_submit(r, XF_ORDER_CALIBRATION); /* operating, then ok */
    assert_status(ct_run_cmd(r, cal, 4000, NULL), XF_CMD_OK);
    r->s.fault.silent = 1;
    (void)ct_submit(r, XF_ORDER_RECORD);
    (void)ct_submit(r, XF_ORDER_FOCUS);
    ct_run(r, 30);
    xf_client_cancel_all(&r->c); /* cancelled */
    b = ct_submit(r, XF_ORDER_RECORD);
    assert_true(ct_run_link(r, XF_LINK_DOWN, 2000)); /* stale, down, link lost */
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_OK);
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_LINK_LOST);
    for (k = 0; k < CB_KINDS; k++) {
        assert_true(g_probe.calls[k] >= 1u);
    }
    assert_int_equal(g_probe.calls[CB_LINK], 3);
    assert_probe_clean(&g_probe);
    ct_rig_free(r);
}

/* The inputs set from a callback go out from the next packet: the rates in head lock, until the
 * external track the callback started puts the gimbal in track mode, which reads none (they are
 * dropped then, docs/protocol.md §11.2). */
static void test_cb_set_inputs(void **state)
{
    ct_rig *r = probe_rig(NULL);
    (void)state;
    g_probe.set_inputs = 1;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000)); /* the first telemetry sets them */
    assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_SENT);
    ct_run(r, 20); /* the next packet */
    assert_int_equal(r->s.host.main.status & XF_STATUS_CTRL_VALID, XF_STATUS_CTRL_VALID);
    assert_int_equal(r->s.host.main.pitch_ctrl, -200);
    assert_int_equal(r->s.host.main.yaw_ctrl, 300);
    ct_run(r, 100);
    assert_int_equal(xf_client_telemetry(&r->c)->gimbal_mode, XF_MODE_TRACK);
    assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_DROPPED);
    assert_int_equal(r->s.host.main.status & XF_STATUS_CTRL_VALID, 0);
    assert_true(sent_count(&r->log, XF_ORDER_EXTERNAL_TRACK, 0) >= 4u);
    assert_probe_clean(&g_probe);
    ct_rig_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cb_submit_from_on_result),
        cmocka_unit_test(test_cb_cancel_all_from_on_result),
        cmocka_unit_test(test_cb_step_is_busy),
        cmocka_unit_test(test_cb_resubmit_during_link_lost_sweep),
        cmocka_unit_test(test_cb_resubmit_during_cancel_all),
        cmocka_unit_test(test_cb_nested_sweeps),
        cmocka_unit_test(test_cb_read_state),
        cmocka_unit_test(test_cb_set_inputs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
