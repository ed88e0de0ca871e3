/*
 * test_client_logic.c - the client's contract against the simulator over an
 * in-memory link on a fake clock: deterministic, no sleeping.
 *
 * Commands (sent until a reply carries their state, then a null; the
 * once-rule; the stale-reply guard; feedback late, once, failing; timeouts;
 * calibration's operating phase; the queue), carrier and GNSS freshness,
 * control (rates, zoom scaling, watchdog, angles per mode), telemetry and
 * its timestamps, link health and its callbacks, protocol V2, external
 * track streaming, the 32-bit clock wrap.
 */
#include "client_test.h"
#include "tap.h" /* tools/xfgcu: the program's tap, a HAL that reports what it moves */

/* ---- helpers -------------------------------------------------------------------- */

/* Maximal runs of consecutive host packets of @p order. */
static size_t runs_of(const ct_log *log, uint8_t order)
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
static size_t sent_count(const ct_log *log, uint8_t order, size_t from)
{
    size_t i, n = 0;
    for (i = from; i < log->n_sent; i++) {
        n += (log->sent_order[i] == order);
    }
    return n;
}

/* Every run of @p order is followed by a null packet (when anything follows it). */
static void assert_null_after_runs(const ct_log *log, uint8_t order)
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

static ct_rig *rig_up(const xf_client_config *cc, const xf_sim_config *sc)
{
    ct_rig *r = ct_rig_new(cc, sc);
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    return r;
}

/* ---- init ---------------------------------------------------------------------- */

static void test_init_rates_and_args(void **state)
{
    static const uint16_t warn[] = {5, 20, 29, 51, 60, 200};
    static const uint16_t ok[] = {30, 40, 50};
    static const uint16_t bad[] = {0, 201, 300};
    xf_client c;
    xf_client_config cfg;
    xf_hal hal, incomplete;
    ct_rig *r = ct_rig_new(NULL, NULL);
    size_t i;
    (void)state;
    hal = r->host_hal;
    for (i = 0; i < sizeof(warn) / sizeof(warn[0]); i++) {
        xf_client_config_init(&cfg);
        cfg.rate_hz = warn[i];
        assert_xf(xf_client_init(&c, &hal, &cfg), XF_WARN_RATE);
    }
    for (i = 0; i < sizeof(ok) / sizeof(ok[0]); i++) {
        xf_client_config_init(&cfg);
        cfg.rate_hz = ok[i];
        assert_xf(xf_client_init(&c, &hal, &cfg), XF_OK);
    }
    for (i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
        xf_client_config_init(&cfg);
        cfg.rate_hz = bad[i];
        assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    }
    xf_client_config_init(&cfg);
    cfg.protocol_version = 0;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    /* times that cannot work: a link never up, commands timing out unsent */
    xf_client_config_init(&cfg);
    cfg.stale_ms = 0;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    xf_client_config_init(&cfg);
    cfg.down_ms = cfg.stale_ms;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    cfg.down_ms = (uint16_t)(cfg.stale_ms + 1u);
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_OK);
    xf_client_config_init(&cfg);
    cfg.command_timeout_ms = 0;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    xf_client_config_init(&cfg);
    cfg.operating_timeout_ms = 0;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    /* a link that reads stale between two packets: 1 Hz with the default 250 ms (the red team's
     * --rate 1, after which every command ended "link lost" against a healthy GCU) */
    xf_client_config_init(&cfg);
    cfg.rate_hz = 1;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    assert_non_null(strstr(xf_client_config_problem(&cfg), "stale_ms"));
    cfg.stale_ms = 1001; /* above the period: stale only after a reply is missing */
    cfg.down_ms = 3000;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE); /* 1000 ms timeout < a 2000 ms round trip */
    assert_non_null(strstr(xf_client_config_problem(&cfg), "command_timeout_ms"));
    cfg.command_timeout_ms = 2000;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_WARN_RATE);
    assert_null(xf_client_config_problem(&cfg));
    assert_null(xf_client_config_problem(NULL));
    {
        /* the times behind those limits, which the program phrases in terms of its options */
        xf_client_timing t = {7u, 7u, 7u};
        xf_client_config_init(&cfg);
        cfg.rate_hz = 30;
        cfg.reorder_ms = 40;
        assert_xf(xf_client_config_timing(&cfg, &t), XF_OK);
        assert_int_equal(t.period_ms, 33); /* 1000 / 30, rounded */
        assert_int_equal(t.gap_ms, 33 + 80);
        assert_int_equal(t.round_trip_ms, 66 + 80);
        cfg.rate_hz = 0;
        assert_xf(xf_client_config_timing(&cfg, &t), XF_ERR_ARG);
        assert_int_equal(t.period_ms, 33); /* left alone */
        cfg.rate_hz = 201;
        assert_xf(xf_client_config_timing(&cfg, &t), XF_ERR_ARG);
        assert_xf(xf_client_config_timing(NULL, &t), XF_ERR_ARG);
        cfg.rate_hz = 50;
        assert_xf(xf_client_config_timing(&cfg, NULL), XF_ERR_ARG);
    }
    /* reorder_ms counts twice against both: silence before and after a command */
    xf_client_config_init(&cfg);
    cfg.reorder_ms = 115; /* 20 + 230 = 250: not above stale_ms */
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    cfg.reorder_ms = 114;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_OK);
    cfg.stale_ms = 5000;
    cfg.down_ms = 6000;
    cfg.reorder_ms = 1001;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    cfg.reorder_ms = 1000;
    cfg.command_timeout_ms = 2039; /* 2 x 20 + 2 x 1000 - 1 */
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    cfg.command_timeout_ms = 2040;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_OK);
    xf_client_config_init(&cfg); /* the limits of the 16-bit times are accepted */
    cfg.stale_ms = 65534;
    cfg.down_ms = 65535;
    cfg.carrier_max_age_ms = 65535;
    cfg.gnss_max_age_ms = 65535;
    cfg.rate_watchdog_ms = 65535;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_OK);
    assert_xf(xf_client_init(&c, &hal, NULL), XF_OK); /* defaults */
    assert_int_equal(c.cfg.rate_hz, 50);
    assert_int_equal(c.cfg.protocol_version, 1);
    assert_xf(xf_client_init(NULL, &hal, NULL), XF_ERR_ARG);
    assert_xf(xf_client_init(&c, NULL, NULL), XF_ERR_ARG);
    incomplete = hal;
    incomplete.read = NULL;
    assert_xf(xf_client_init(&c, &incomplete, NULL), XF_ERR_ARG);
    incomplete = hal;
    incomplete.write = NULL;
    assert_xf(xf_client_init(&c, &incomplete, NULL), XF_ERR_ARG);
    incomplete = hal;
    incomplete.fd = NULL; /* write and read are all a link needs: no clock */
    assert_xf(xf_client_init(&c, &incomplete, NULL), XF_OK);
    assert_xf(xf_client_step(NULL, 0), XF_ERR_ARG);
    ct_rig_free(r);
}

/* A 20 Hz client (XF_WARN_RATE, still accepted) sends 20 packets a second. */
static void test_rate_20hz_paces_packets(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    (void)state;
    xf_client_config_init(&cc);
    cc.rate_hz = 20;
    r = ct_rig_new(&cc, NULL);
    ct_run(r, 1000);
    assert_int_equal(r->c.health.packets_sent, 20);
    assert_int_equal(xf_client_next_deadline(&r->c), 1000u + 1u + 1000u);
    ct_rig_free(r);
}

/* ---- commands ------------------------------------------------------------------- */

/* Null packets by default, 72 bytes each, one reply each. */
static void test_null_packets_by_default(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    size_t i;
    (void)state;
    ct_run(r, 1000);
    assert_int_equal(r->log.n_sent, 50);
    for (i = 0; i < r->log.n_sent; i++) {
        assert_int_equal(r->log.sent_order[i], XF_ORDER_NULL);
    }
    assert_int_equal(r->s.stats.packets_in, 50);
    assert_int_equal(r->c.health.replies, 50);
    for (i = 0; i < r->log.n_replies; i++) {
        assert_int_equal(r->log.reply_len[i], 72);
    }
    for (i = 0; i < 256; i++) {
        assert_int_equal(r->s.stats.executed[i], 0);
    }
    ct_rig_free(r);
}

/* The issue's first case: two shutters in a row run twice, a null between. */
static void test_two_shutters_null_between(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    xf_cmd_result ra, rb;
    uint32_t a, b;
    (void)state;
    a = ct_submit(r, XF_ORDER_SHUTTER);
    b = ct_submit(r, XF_ORDER_SHUTTER);
    assert_true(b != a);
    assert_int_equal(xf_client_pending(&r->c), 2);
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_QUEUED);
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_QUEUED);
    ct_run(r, 20);
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_OK);
    assert_status(ct_run_cmd(r, b, 1000, &rb), XF_CMD_OK);
    assert_status(xf_client_command_status(&r->c, a, &ra), XF_CMD_OK);
    assert_int_equal(r->s.stats.executed[XF_ORDER_SHUTTER], 2);
    assert_int_equal(r->s.stats.photos, 2);
    assert_int_equal(runs_of(&r->log, XF_ORDER_SHUTTER), 2);
    assert_null_after_runs(&r->log, XF_ORDER_SHUTTER);
    /* the results: by polling and by callback, in order */
    assert_int_equal(ra.id, a);
    assert_int_equal(ra.order, XF_ORDER_SHUTTER);
    assert_int_equal(ra.state, XF_STATE_SUCCESS);
    assert_int_equal(ra.packets, 1); /* answered within one period */
    assert_int_equal(rb.packets, 1);
    assert_int_equal(r->log.n_results, 2);
    assert_int_equal(r->log.results[0].id, a);
    assert_int_equal(r->log.results[1].id, b);
    assert_int_equal(xf_client_pending(&r->c), 0);
    ct_rig_free(r);
}

/* Replies that arrive in small pieces (a slow UART) are put together. */
static void test_replies_in_pieces(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    uint32_t a, b;
    (void)state;
    r->host.chunk = 5; /* 16 reads of 5 bytes a step: a reply spans up to 15 reads */
    assert_true(ct_run_link(r, XF_LINK_UP, 100));
    a = ct_submit(r, XF_ORDER_SHUTTER);
    b = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, b, 1000, NULL), XF_CMD_OK);
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_OK);
    ct_run(r, 500);
    assert_int_equal(r->c.health.replies, r->s.stats.replies);
    assert_int_equal(xf_client_parser_stats(&r->c)->crc_errors, 0);
    assert_int_equal(r->s.stats.photos, 2);
    ct_rig_free(r);
}

/* A command is repeated in every packet until a reply carries its state;
 * the GCU runs it once. Here the state comes 3 replies late. */
static void test_feedback_in_later_reply(void **state)
{
    xf_sim_config sc;
    ct_rig *r;
    xf_cmd_result res;
    uint32_t id;
    size_t i, first = 0, state_at = 0;
    (void)state;
    xf_sim_config_init(&sc);
    sc.feedback_after = 3;
    r = rig_up(NULL, &sc);
    id = ct_submit(r, XF_ORDER_RECORD);
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_OK);
    assert_int_equal(res.packets, 4);
    assert_true(res.elapsed_ms >= 60u && res.elapsed_ms <= 62u);
    assert_int_equal(r->s.stats.executed[XF_ORDER_RECORD], 1);
    assert_int_equal(r->s.stats.recordings, 1);
    /* replies: three of order record without state (72 bytes), then the state */
    for (i = 0; i < r->log.n_replies && r->log.reply_order[i] != XF_ORDER_RECORD; i++) {
    }
    first = i;
    for (; i < r->log.n_replies && r->log.reply_len[i] == 72u; i++) {
    }
    state_at = i;
    assert_int_equal(state_at - first, 3);
    assert_int_equal(r->log.reply_order[state_at], XF_ORDER_RECORD);
    assert_int_equal(r->log.reply_len[state_at], 73);
    assert_int_equal(runs_of(&r->log, XF_ORDER_RECORD), 1);
    assert_null_after_runs(&r->log, XF_ORDER_RECORD);
    ct_rig_free(r);
}

/* Failures come back with their state and, where the order says so, the mask. */
static void test_failing_camera_mask(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    xf_command cmd;
    xf_cmd_result res;
    uint32_t id;
    (void)state;
    xf_sim_set_failure(&r->s, XF_ORDER_ZOOM_IN, XF_CAM2);
    xf_command_init(&cmd, XF_ORDER_ZOOM_IN);
    cmd.cameras = XF_CAM1 | XF_CAM2;
    id = ct_submit_cmd(r, &cmd);
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_FAILED);
    assert_int_equal(res.failed_cameras, XF_CAM2);
    assert_int_equal(res.state, XF_CAM2);
    assert_int_equal(ct_result_of(&r->log, id)->failed_cameras, XF_CAM2);
    /* shutter reports plain failure: state 1, no mask */
    xf_sim_set_failure(&r->s, XF_ORDER_SHUTTER, XF_STATE_FAILURE);
    id = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_FAILED);
    assert_int_equal(res.state, XF_STATE_FAILURE);
    assert_int_equal(res.failed_cameras, 0);
    /* restored */
    xf_sim_set_failure(&r->s, XF_ORDER_SHUTTER, 0);
    id = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_OK);
    ct_rig_free(r);
}

/* Dropped replies: the command is repeated (retries), runs once, then times out. */
static void test_dropped_replies_retry_then_timeout(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    xf_cmd_result res;
    uint32_t id, t0;
    (void)state;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 300;
    r = rig_up(&cc, NULL);
    r->s.fault.drop_next = 1000;
    id = ct_submit(r, XF_ORDER_SHUTTER);
    t0 = r->now;
    assert_status(ct_run_cmd(r, id, 2000, &res), XF_CMD_TIMEOUT);
    assert_true(xf_ms_since(r->now, t0) >= 300u && xf_ms_since(r->now, t0) <= 321u);
    assert_true(res.packets >= 14u && res.packets <= 16u);
    assert_true(res.elapsed_ms >= 300u);
    assert_int_equal(r->s.stats.executed[XF_ORDER_SHUTTER], 1); /* repeated, run once */
    assert_int_equal(r->s.stats.photos, 1);
    assert_true(r->s.stats.dropped >= 14u);
    assert_int_equal(xf_client_link(&r->c), XF_LINK_STALE); /* not yet down */
    /* the drops end: the link is back, and a new shutter runs */
    r->s.fault.drop_next = 0;
    assert_true(ct_run_link(r, XF_LINK_UP, 100));
    id = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_OK);
    assert_int_equal(r->s.stats.photos, 2);
    ct_rig_free(r);
}

/*
 * The stale-reply guard: replies are 200 ms late, so when command A of an
 * order has its state, ten more replies to A's packets, all carrying A's
 * state, are still on their way. Command B of the same order must not be
 * resolved by them: the GCU fails B, and B must come back failed.
 */
static void test_stale_reply_guard(void **state)
{
    xf_sim_config sc;
    xf_client_config cc;
    ct_rig *r;
    xf_cmd_result ra, rb;
    uint32_t a, b;
    (void)state;
    xf_sim_config_init(&sc);
    sc.feedback_after = 3;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 3000;
    r = ct_rig_new(&cc, &sc);
    r->s.fault.delay_ms = 200;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    a = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, a, 2000, &ra), XF_CMD_OK);
    assert_true(ra.packets > 10u); /* many of A's replies are still in flight */
    xf_sim_set_failure(&r->s, XF_ORDER_SHUTTER, XF_STATE_FAILURE);
    b = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, b, 3000, &rb), XF_CMD_FAILED);
    assert_int_equal(rb.state, XF_STATE_FAILURE);
    assert_int_equal(r->s.stats.executed[XF_ORDER_SHUTTER], 2);
    assert_int_equal(r->s.stats.photos, 1);
    assert_null_after_runs(&r->log, XF_ORDER_SHUTTER);
    ct_rig_free(r);
}

/* The same with both commands queued together. */
static void test_stale_reply_guard_queued(void **state)
{
    xf_sim_config sc;
    xf_client_config cc;
    ct_rig *r;
    xf_cmd_result res;
    uint32_t id[3];
    size_t i;
    (void)state;
    xf_sim_config_init(&sc);
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 3000;
    r = ct_rig_new(&cc, &sc);
    r->s.fault.delay_ms = 150;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    for (i = 0; i < 3; i++) {
        id[i] = ct_submit(r, XF_ORDER_SHUTTER);
    }
    assert_status(ct_run_cmd(r, id[2], 5000, &res), XF_CMD_OK);
    for (i = 0; i < 3; i++) {
        assert_status(xf_client_command_status(&r->c, id[i], &res), XF_CMD_OK);
    }
    assert_int_equal(r->s.stats.executed[XF_ORDER_SHUTTER], 3);
    assert_int_equal(runs_of(&r->log, XF_ORDER_SHUTTER), 3);
    /* each result came at least one round trip (150 ms) after its first packet:
     * none was taken from a reply to an earlier command */
    for (i = 0; i < 3; i++) {
        assert_true(ct_result_of(&r->log, id[i])->elapsed_ms >= 150u);
    }
    ct_rig_free(r);
}

/* state_once: only one reply carries the state; the client takes it. */
static void test_state_once(void **state)
{
    xf_sim_config sc;
    xf_client_config cc;
    ct_rig *r;
    xf_cmd_result res;
    uint32_t id;
    (void)state;
    xf_sim_config_init(&sc);
    sc.state_once = 1;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 300;
    r = ct_rig_new(&cc, &sc);
    r->s.fault.delay_ms = 100; /* so the command is repeated while the state is on its way */
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    id = ct_submit(r, XF_ORDER_FOCUS);
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_OK);
    assert_true(res.packets >= 5u);
    ct_run(r, 300);
    assert_int_equal(ct_state_replies(&r->log, XF_ORDER_FOCUS), 1);
    assert_true(sent_count(&r->log, XF_ORDER_FOCUS, 0) >= 5u);
    assert_int_equal(r->s.stats.executed[XF_ORDER_FOCUS], 1);
    /* the one reply with the state lost: nothing else will say it, so a timeout */
    r->s.fault.delay_ms = 0;
    ct_run(r, 300);
    id = ct_submit(r, XF_ORDER_FOCUS);
    r->s.fault.drop_next = 1; /* the next reply is the command's first */
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_TIMEOUT);
    assert_int_equal(r->s.stats.executed[XF_ORDER_FOCUS], 2);
    ct_rig_free(r);
}

/* Calibration: "operating" (reported once), kept going, then ok. */
static void test_calibration_operating_then_ok(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    xf_cmd_result res;
    uint32_t id;
    size_t i, n = 0;
    (void)state;
    id = ct_submit(r, XF_ORDER_CALIBRATION);
    ct_run(r, 100);
    assert_status(xf_client_command_status(&r->c, id, &res), XF_CMD_OPERATING);
    assert_int_equal(r->log.n_results, 1);
    assert_int_equal(r->log.results[0].status, XF_CMD_OPERATING);
    assert_int_equal(r->log.results[0].state, XF_STATE_OPERATING);
    assert_int_equal(r->log.results[0].id, id);
    assert_int_equal(xf_client_pending(&r->c), 1);
    assert_status(ct_run_cmd(r, id, 3000, &res), XF_CMD_OK);
    assert_true(res.elapsed_ms >= 1500u && res.elapsed_ms <= 1530u);
    assert_true(res.packets >= 75u);
    assert_int_equal(r->s.stats.executed[XF_ORDER_CALIBRATION], 1);
    for (i = 0; i < r->log.n_results; i++) {
        n += (r->log.results[i].id == id);
    }
    assert_int_equal(n, 2); /* operating once, then ok */
    assert_int_equal(runs_of(&r->log, XF_ORDER_CALIBRATION), 1);
    ct_rig_free(r);
}

/* "operating", then a failure as the final state. */
static void test_calibration_operating_then_failed(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    xf_cmd_result res;
    uint32_t id;
    (void)state;
    id = ct_submit(r, XF_ORDER_CALIBRATION);
    ct_run(r, 100);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_OPERATING);
    xf_sim_set_failure(&r->s, XF_ORDER_CALIBRATION, XF_STATE_FAILURE); /* the gimbal was moved */
    assert_status(ct_run_cmd(r, id, 3000, &res), XF_CMD_FAILED);
    assert_int_equal(res.state, XF_STATE_FAILURE);
    assert_true(res.elapsed_ms >= 1500u);
    ct_rig_free(r);
}

/* ... and a final state that never comes: the operating timeout. */
static void test_calibration_operating_timeout(void **state)
{
    xf_client_config cc;
    xf_sim_config sc;
    ct_rig *r;
    xf_cmd_result res;
    uint32_t id;
    (void)state;
    xf_client_config_init(&cc);
    cc.operating_timeout_ms = 500;
    cc.command_timeout_ms = 200;
    xf_sim_config_init(&sc);
    sc.calibration_ms = 5000;
    r = rig_up(&cc, &sc);
    id = ct_submit(r, XF_ORDER_CALIBRATION);
    ct_run(r, 300); /* past the command timeout: operating keeps it alive */
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_OPERATING);
    assert_status(ct_run_cmd(r, id, 2000, &res), XF_CMD_TIMEOUT);
    assert_true(res.elapsed_ms >= 500u && res.elapsed_ms <= 525u);
    assert_int_equal(xf_client_link(&r->c), XF_LINK_UP);
    ct_rig_free(r);
}

/* Eight commands fill the queue; the ninth is XF_ERR_BUSY. All eight run. */
static void test_queue_full_busy(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    xf_command cmd;
    xf_cmd_result res;
    uint32_t id[XF_CLIENT_QUEUE], extra = 0;
    size_t i;
    (void)state;
    for (i = 0; i < XF_CLIENT_QUEUE; i++) {
        id[i] = ct_submit(r, XF_ORDER_SHUTTER);
    }
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    assert_xf(xf_client_submit(&r->c, &cmd, &extra, NULL), XF_ERR_BUSY);
    assert_int_equal(extra, 0);
    assert_int_equal(xf_client_pending(&r->c), XF_CLIENT_QUEUE);
    assert_status(ct_run_cmd(r, id[XF_CLIENT_QUEUE - 1], 3000, &res), XF_CMD_OK);
    for (i = 0; i < XF_CLIENT_QUEUE; i++) {
        assert_status(xf_client_command_status(&r->c, id[i], NULL), XF_CMD_OK);
    }
    assert_int_equal(r->s.stats.photos, XF_CLIENT_QUEUE);
    assert_int_equal(runs_of(&r->log, XF_ORDER_SHUTTER), XF_CLIENT_QUEUE);
    /* space again */
    assert_xf(xf_client_submit(&r->c, &cmd, &extra, NULL), XF_OK);
    ct_rig_free(r);
}

/* Ids are never 0, also when the counter wraps. */
static void test_ids_skip_zero(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    xf_cmd_result res;
    uint32_t z, a, b;
    (void)state;
    r->c.next_id = 0xFFFFFFFEu;
    z = ct_submit(r, XF_ORDER_SHUTTER);
    a = ct_submit(r, XF_ORDER_FOCUS);
    b = ct_submit(r, XF_ORDER_RECORD);
    assert_int_equal(z, 0xFFFFFFFEu);
    assert_int_equal(a, 0xFFFFFFFFu);
    assert_int_equal(b, 1);
    /* queued across the wrap: each id still names its own command */
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_QUEUED);
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_QUEUED);
    assert_status(xf_client_command_status(&r->c, 0, NULL), XF_CMD_UNKNOWN);
    assert_status(xf_client_command_status(&r->c, 2, NULL), XF_CMD_UNKNOWN);
    assert_status(ct_run_cmd(r, b, 1000, NULL), XF_CMD_OK);
    assert_status(xf_client_command_status(&r->c, z, &res), XF_CMD_OK);
    assert_int_equal(res.id, z);
    assert_int_equal(res.order, XF_ORDER_SHUTTER);
    assert_status(xf_client_command_status(&r->c, a, &res), XF_CMD_OK);
    assert_int_equal(res.id, a);
    assert_int_equal(res.order, XF_ORDER_FOCUS);
    assert_status(xf_client_command_status(&r->c, b, &res), XF_CMD_OK);
    assert_int_equal(res.id, b);
    assert_int_equal(res.order, XF_ORDER_RECORD);
    assert_status(xf_client_command_status(&r->c, 0, NULL), XF_CMD_UNKNOWN);
    ct_rig_free(r);
}

/* Finished results are kept for polling, the oldest forgotten. */
static void test_results_ring(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    uint32_t id[XF_CLIENT_RESULTS + 2];
    size_t i;
    (void)state;
    assert_status(xf_client_command_status(&r->c, 0, NULL), XF_CMD_UNKNOWN);
    assert_status(xf_client_command_status(&r->c, 12345, NULL), XF_CMD_UNKNOWN);
    assert_status(xf_client_command_status(NULL, 1, NULL), XF_CMD_UNKNOWN);
    for (i = 0; i < XF_CLIENT_RESULTS + 2u; i++) {
        id[i] = ct_submit(r, XF_ORDER_FOCUS);
        assert_status(ct_run_cmd(r, id[i], 1000, NULL), XF_CMD_OK);
    }
    assert_status(xf_client_command_status(&r->c, id[0], NULL), XF_CMD_UNKNOWN);
    assert_status(xf_client_command_status(&r->c, id[1], NULL), XF_CMD_UNKNOWN);
    for (i = 2; i < XF_CLIENT_RESULTS + 2u; i++) {
        assert_status(xf_client_command_status(&r->c, id[i], NULL), XF_CMD_OK);
    }
    ct_rig_free(r);
}

static void test_cancel_all(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    uint32_t a, b, c;
    xf_cmd_result res;
    (void)state;
    r->s.fault.silent = 1; /* nothing finishes on its own */
    a = ct_submit(r, XF_ORDER_SHUTTER);
    b = ct_submit(r, XF_ORDER_RECORD);
    c = ct_submit(r, XF_ORDER_FOCUS);
    ct_run(r, 25);
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_SENDING);
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_QUEUED);
    xf_client_cancel_all(&r->c);
    assert_int_equal(xf_client_pending(&r->c), 0);
    assert_status(xf_client_command_status(&r->c, a, &res), XF_CMD_CANCELLED);
    assert_true(res.packets >= 1u);
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_CANCELLED);
    assert_status(xf_client_command_status(&r->c, c, NULL), XF_CMD_CANCELLED);
    assert_int_equal(r->log.n_results, 3);
    /* back to nulls */
    ct_run(r, 100);
    assert_int_equal(r->log.sent_order[r->log.n_sent - 1u], XF_ORDER_NULL);
    xf_client_cancel_all(NULL);
    ct_rig_free(r);
}

/* Range errors on submit name the field; nothing is queued. */
static void test_submit_range_errors(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    xf_command cmd;
    xf_field bad = XF_F_NONE;
    uint32_t id = 0;
    (void)state;
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.zoom = 0;
    assert_xf(xf_client_submit(&r->c, &cmd, &id, &bad), XF_ERR_RANGE);
    assert_int_equal(bad, XF_F_ZOOM);
    cmd.zoom = 10001;
    assert_xf(xf_client_submit(&r->c, &cmd, &id, &bad), XF_ERR_RANGE);
    assert_int_equal(bad, XF_F_ZOOM);
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    cmd.cameras = 0;
    bad = XF_F_NONE;
    assert_xf(xf_client_submit(&r->c, &cmd, &id, &bad), XF_ERR_RANGE);
    assert_int_equal(bad, XF_F_CAMERAS);
    xf_command_init(&cmd, XF_ORDER_TRACK);
    cmd.value = 1;
    cmd.x0 = 5000;
    cmd.y0 = 100;
    cmd.x1 = 4000;
    cmd.y1 = 200;
    assert_xf(xf_client_submit(&r->c, &cmd, &id, &bad), XF_ERR_RANGE);
    assert_int_equal(bad, XF_F_X1);
    xf_command_init(&cmd, XF_ORDER_EXTERNAL_TRACK);
    cmd.value = 2;
    cmd.dx = 2000;
    assert_xf(xf_client_submit(&r->c, &cmd, &id, &bad), XF_ERR_RANGE);
    assert_int_equal(bad, XF_F_DX);
    xf_command_init(&cmd, XF_ORDER_RANGING);
    cmd.value = 1;
    assert_xf(xf_client_submit(&r->c, &cmd, &id, &bad), XF_ERR_RANGE);
    assert_int_equal(bad, XF_F_VALUE);
    assert_xf(xf_client_submit(&r->c, &cmd, &id, NULL), XF_ERR_RANGE); /* bad_field may be NULL */
    xf_command_init(&cmd, 0x99);
    assert_xf(xf_client_submit(&r->c, &cmd, &id, &bad), XF_ERR_NOT_FOUND);
    assert_int_equal(bad, XF_F_NONE); /* no member at fault */
    bad = XF_F_ZOOM;
    assert_xf(xf_client_submit(&r->c, NULL, &id, &bad), XF_ERR_ARG);
    assert_int_equal(bad, XF_F_NONE);
    bad = XF_F_ZOOM;
    assert_xf(xf_client_submit(NULL, &cmd, &id, &bad), XF_ERR_ARG);
    assert_int_equal(bad, XF_F_NONE);
    assert_xf(xf_client_external_track(&r->c, XF_CAM1, 0, -1100), XF_ERR_RANGE);
    assert_xf(xf_client_external_track(&r->c, 0, 0, 0), XF_ERR_RANGE);
    assert_int_equal(id, 0);
    assert_int_equal(xf_client_pending(&r->c), 0);
    ct_run(r, 200);
    assert_int_equal(sent_count(&r->log, XF_ORDER_NULL, 0), r->log.n_sent); /* nothing went out */
    ct_rig_free(r);
}

/* ---- link health ---------------------------------------------------------------- */

/* DOWN (no callback) -> UP at the first reply -> STALE -> DOWN -> UP. */
static void test_link_transitions(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    uint32_t last_rx;
    (void)state;
    assert_int_equal(xf_client_link(&r->c), XF_LINK_DOWN);
    assert_int_equal(xf_client_link(NULL), XF_LINK_DOWN);
    assert_true(ct_run_link(r, XF_LINK_UP, 100));
    assert_int_equal(r->log.n_links, 1);
    assert_int_equal(r->log.links[0], XF_LINK_UP);
    assert_int_equal(r->log.link_ms[0], r->c.health.last_rx_ms);
    ct_run(r, 100);
    r->s.fault.silent = 1;
    last_rx = r->c.health.last_rx_ms;
    assert_true(ct_run_link(r, XF_LINK_STALE, 2000));
    assert_int_equal(r->now - last_rx, 250); /* stale_ms */
    assert_true(ct_run_link(r, XF_LINK_DOWN, 2000));
    assert_int_equal(r->now - last_rx, 1000); /* down_ms: a dead link is reported at its timeout */
    r->s.fault.silent = 0;
    assert_true(ct_run_link(r, XF_LINK_UP, 100));
    assert_int_equal(r->log.n_links, 4);
    assert_int_equal(r->log.links[1], XF_LINK_STALE);
    assert_int_equal(r->log.links[2], XF_LINK_DOWN);
    assert_int_equal(r->log.links[3], XF_LINK_UP);
    assert_int_equal(r->log.link_ms[1], last_rx + 250u);
    assert_int_equal(r->log.link_ms[2], last_rx + 1000u);
    assert_string_equal(xf_link_state_name(XF_LINK_UP), "up");
    assert_string_equal(xf_link_state_name(XF_LINK_STALE), "stale");
    assert_string_equal(xf_link_state_name(XF_LINK_DOWN), "down");
    assert_string_equal(xf_cmd_status_name(XF_CMD_LINK_LOST), "link lost");
    assert_string_equal(xf_cmd_status_name(XF_CMD_OK), "ok");
    assert_string_equal(xf_cmd_status_name((xf_cmd_status)99), "unknown");
    ct_rig_free(r);
}

/* Commands fail with LINK_LOST when the link dies: silent GCU, closed transport,
 * and a command sent while there is no GCU at all. */
static void test_link_lost_fails_commands(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    xf_cmd_result res;
    uint32_t a, b, c, last_rx;
    (void)state;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 5000;
    r = rig_up(&cc, NULL);
    r->s.fault.silent = 1;
    last_rx = r->c.health.last_rx_ms;
    a = ct_submit(r, XF_ORDER_SHUTTER);
    b = ct_submit(r, XF_ORDER_RECORD);
    c = ct_submit(r, XF_ORDER_ZOOM_IN);
    assert_status(ct_run_cmd(r, c, 3000, &res), XF_CMD_LINK_LOST);
    assert_int_equal(r->now - last_rx, 1000);
    assert_status(xf_client_command_status(&r->c, a, &res), XF_CMD_LINK_LOST);
    assert_true(res.packets >= 45u);
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_LINK_LOST);
    assert_int_equal(xf_client_pending(&r->c), 0);
    /* the transport closes: down at once, the running command lost at once */
    r->s.fault.silent = 0;
    assert_true(ct_run_link(r, XF_LINK_UP, 100));
    a = ct_submit(r, XF_ORDER_RECORD);
    r->s.fault.silent = 1;
    ct_run(r, 30);
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_SENDING);
    r->host.closed = 1;
    ct_tick(r);
    assert_int_equal(xf_client_link(&r->c), XF_LINK_DOWN);
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_LINK_LOST);
    ct_run(r, 30);
    assert_int_equal(xf_client_step(&r->c, r->now + 1u), XF_ERR_CLOSED);
    assert_true(r->c.health.send_errors >= 1u);
    assert_int_equal(xf_client_link(&r->c), XF_LINK_DOWN);
    ct_rig_free(r);
    /* never a GCU: a command never starts (no reply to a null), and ends as LINK_LOST after
     * twice the timeout */
    cc.command_timeout_ms = 300;
    r = ct_rig_new(&cc, NULL);
    r->s.fault.silent = 1;
    a = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, a, 1000, &res), XF_CMD_LINK_LOST);
    assert_true(res.elapsed_ms >= 600u && res.elapsed_ms <= 621u);
    assert_int_equal(res.packets, 0);
    ct_rig_free(r);
}

/*
 * Once the transport has been closed, the link stays DOWN until a valid
 * reply comes over the reopened transport; a reconnection alone (TCP
 * connected to a listener that then refuses, a reopened port) is not a
 * GCU answering, and must not flap the link to UP/STALE.
 */
static void test_reopened_transport_down_until_reply(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    size_t links;
    (void)state;
    ct_run(r, 50);
    r->host.closed = 1;
    ct_tick(r);
    assert_int_equal(xf_client_link(&r->c), XF_LINK_DOWN);
    links = r->log.n_links;
    /* reopened, but the GCU is not answering yet */
    r->host.closed = 0;
    r->sim_on = 0;
    ct_run(r, 100);
    assert_int_equal(xf_client_link(&r->c), XF_LINK_DOWN);
    assert_int_equal(r->log.n_links, links); /* no flapping */
    (void)ct_drain_host(r, NULL);
    r->sim_on = 1;
    assert_true(ct_run_link(r, XF_LINK_UP, 100));
    assert_int_equal(r->log.n_links, links + 1u);
    assert_true(r->log.link_replies[links] > 0u);
    ct_rig_free(r);
}

/* Health figures: packets, replies, the reply rate, what is missing, parser errors. */
/* replies_missing is exact under question and answer: 0 on a perfect link
 * from the first window on (the reply in flight at a window's edge is not
 * missing), and exactly the replies lost in a window. */
static void test_replies_missing_exact(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    const xf_health *h = xf_client_health(&r->c);
    (void)state;
    ct_run(r, 1001);
    assert_int_equal(h->replies_missing, 0);
    ct_run(r, 1000);
    assert_int_equal(h->replies_missing, 0);
    r->s.fault.drop_next = 7;
    ct_run(r, 1000);
    assert_int_equal(r->s.stats.dropped, 7);
    assert_int_equal(h->replies_missing, 7);
    ct_run(r, 1000);
    assert_int_equal(h->replies_missing, 0);
    ct_rig_free(r);
}

/* transport_closed follows the transport: set when it says closed, cleared
 * when a GCU answers over it again. */
static void test_transport_closed_flag(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    const xf_health *h = xf_client_health(&r->c);
    (void)state;
    ct_run(r, 200);
    assert_int_equal(h->transport_closed, 0);
    r->host.closed = 1;
    ct_run(r, 100);
    assert_int_equal(h->transport_closed, 1);
    assert_int_equal(h->link, XF_LINK_DOWN);
    r->host.closed = 0;
    ct_run(r, 200);
    assert_int_equal(h->transport_closed, 0);
    assert_int_equal(h->link, XF_LINK_UP);
    ct_rig_free(r);
}

static void test_health_figures(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    const xf_health *h;
    uint32_t replies;
    (void)state;
    ct_run(r, 2001); /* the figures of the second full second */
    h = xf_client_health(&r->c);
    assert_int_equal(h->packets_sent, 101);
    assert_int_equal(h->replies, 100); /* the last one's reply is a millisecond away */
    assert_true(h->reply_rate_hz >= 49u && h->reply_rate_hz <= 51u);
    assert_int_equal(h->replies_missing, 0);
    assert_int_equal(h->link, XF_LINK_UP);
    assert_int_equal(xf_client_parser_stats(&r->c)->frames, 100);
    /* half the replies dropped */
    r->s.fault.drop_permille = 500;
    ct_run(r, 2000);
    assert_true(h->replies_missing >= 10u && h->replies_missing <= 40u);
    r->s.fault.drop_permille = 0;
    /* corrupted replies are not replies */
    ct_run(r, 1000);
    replies = h->replies;
    r->s.fault.corrupt_next = 5;
    ct_run(r, 1000);
    assert_int_equal(r->s.stats.corrupted, 5);
    assert_int_equal(h->replies - replies, 45);
    assert_true(xf_client_parser_stats(&r->c)->crc_errors >= 5u);
    assert_null(xf_client_health(NULL));
    assert_null(xf_client_parser_stats(NULL));
    ct_rig_free(r);
}

/* ---- telemetry ----------------------------------------------------------------------- */

static void test_telemetry_and_ages(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    const xf_telemetry *t = xf_client_telemetry(&r->c);
    const xf_health *h = xf_client_health(&r->c);
    xf_gcu_packet p;
    uint32_t seen, sub_seen;
    (void)state;
    assert_int_equal(t->have_main, 0);
    assert_int_equal(t->have_sub, 0);
    ct_run(r, 500);
    assert_int_equal(t->have_main, 1);
    assert_int_equal(t->have_sub, 1);
    assert_int_equal(t->sub_ms, h->last_rx_ms); /* the main frame's time is the reply's */
    assert_true(r->now - h->last_rx_ms <= 20u);
    assert_int_equal(t->version, 1);
    assert_int_equal(t->gimbal_mode, XF_MODE_HEAD_LOCK);
    assert_int_equal(t->gimbal_code, 58);
    assert_string_equal(xf_gimbal_model(t->gimbal_code), "Z-9B_V4(T)");
    assert_int_equal(t->hw_version, 31); /* 3.1, in tenths */
    assert_int_equal(t->fw_version, 50);
    assert_int_equal(t->zoom_cam1, 10); /* 1.0x in 0.1 x */
    assert_int_equal(t->zoom_cam2, 10);
    assert_true(t->target_distance <= 0);   /* no valid measurement */
    assert_int_equal(t->thermal_status, 0); /* V1 */
    assert_int_equal(r->log.n_telemetry, r->c.health.replies);
    /* a silent GCU: the timestamps stay, the age grows */
    r->s.fault.silent = 1;
    seen = h->last_rx_ms;
    ct_run(r, 600);
    assert_int_equal(h->last_rx_ms, seen);
    assert_true(r->now - h->last_rx_ms >= 600u);
    assert_int_equal(t->have_main, 1);
    r->s.fault.silent = 0;
    ct_run(r, 40);
    assert_true(r->now - h->last_rx_ms <= 20u);
    /* main and sub frames age separately: a reply without the sub frame */
    r->sim_on = 0;
    sub_seen = t->sub_ms;
    ct_run(r, 100);
    memset(&p, 0, sizeof(p));
    p.version = 1;
    p.main.gimbal_mode = XF_MODE_EULER;
    p.main.cam_roll = -1234;
    p.main.cam_pitch = -4500;
    p.main.cam_yaw = 35999;
    p.main.rel_angle_x = 1;
    p.main.rel_angle_y = -2;
    p.main.rel_angle_z = 18000;
    p.main.rate_x = -150;
    p.main.rate_y = 7;
    p.main.rate_z = 2000;
    p.main.target_offset_x = -1000;
    p.main.target_offset_y = 999;
    p.main.pod_status = XF_POD_TRACKING_OK | XF_POD_UPWARD_MOUNT;
    ct_gcu_reply(r, &p);
    ct_tick(r);
    assert_int_equal(h->last_rx_ms, r->now);
    assert_int_equal(t->gimbal_mode, XF_MODE_EULER);
    assert_int_equal(t->cam_roll, -1234); /* every main field, as received */
    assert_int_equal(t->cam_pitch, -4500);
    assert_int_equal(t->cam_yaw, 35999);
    assert_int_equal(t->rel_angle_x, 1);
    assert_int_equal(t->rel_angle_y, -2);
    assert_int_equal(t->rel_angle_z, 18000);
    assert_int_equal(t->rate_x, -150);
    assert_int_equal(t->rate_y, 7);
    assert_int_equal(t->rate_z, 2000);
    assert_int_equal(t->target_offset_x, -1000);
    assert_int_equal(t->target_offset_y, 999);
    assert_int_equal(t->pod_status, XF_POD_TRACKING_OK | XF_POD_UPWARD_MOUNT);
    assert_int_equal(t->sub_ms, sub_seen);
    assert_int_equal(t->gimbal_code, 58); /* sub values kept from the last sub frame */
    /* a ranging sub frame: every sub field, V2 ones too */
    p.version = 2;
    p.sub.sub_header = XF_SUB_HEADER;
    p.sub.hw_version = 7;
    p.sub.fw_version = 9;
    p.sub.gimbal_code = 200; /* unknown model */
    p.sub.error_code = XF_ERROR_GNSS_NOT_FIXED;
    p.sub.target_distance = 1234;
    p.sub.target_longitude = -1224194200;
    p.sub.target_latitude = 377749300;
    p.sub.target_altitude = -12345;
    p.sub.zoom_cam1 = 55;
    p.sub.zoom_cam2 = 20;
    p.sub.thermal_status = XF_THERMAL_SPOT_ON;
    p.sub.time_zone = -5;
    p.sub.camera_status = XF_CAMERA_RECORDING;
    ct_gcu_reply(r, &p);
    ct_tick(r);
    assert_int_equal(t->sub_ms, r->now);
    assert_null(xf_gimbal_model(t->gimbal_code));
    assert_int_equal(t->hw_version, 7);
    assert_int_equal(t->fw_version, 9);
    assert_int_equal(t->gimbal_code, 200);
    assert_int_equal(t->error_code, XF_ERROR_GNSS_NOT_FIXED);
    assert_int_equal(t->target_distance, 1234);
    assert_int_equal(t->target_longitude, -1224194200);
    assert_int_equal(t->target_latitude, 377749300);
    assert_int_equal(t->target_altitude, -12345);
    assert_int_equal(t->zoom_cam1, 55);
    assert_int_equal(t->zoom_cam2, 20);
    assert_int_equal(t->thermal_status, XF_THERMAL_SPOT_ON);
    assert_int_equal(t->time_zone, -5);
    assert_int_equal(t->camera_status, XF_CAMERA_RECORDING);
    assert_int_equal(t->version, 2);
    assert_null(xf_client_telemetry(NULL));
    ct_rig_free(r);
}

/* The client writes its packets and reads telemetry at its own offsets (no
 * packet structs): with every input in use and a V0.2 GCU, each packet sent
 * is what xf_host_pack makes of it and each telemetry update holds what
 * xf_gcu_unpack reads (ct_rig_free checks the same in every test). */
static void test_wire_agrees_with_the_codec(void **state)
{
    static const uint8_t versions[] = {1, 2};
    size_t v;
    (void)state;
    for (v = 0; v < 2; v++) {
        xf_client_config cc;
        xf_sim_config sc;
        xf_carrier k;
        xf_gnss g;
        xf_command cmd;
        ct_rig *r;
        xf_client_config_init(&cc);
        cc.protocol_version = versions[v];
        xf_sim_config_init(&sc);
        sc.version = versions[v];
        r = rig_up(&cc, &sc);
        memset(&k, 0, sizeof(k));
        k.roll_deg = -179.5f;
        k.pitch_deg = 45.25f;
        k.yaw_deg = 359.0f;
        k.accel_north = -0.5f;
        k.accel_east = 1.25f;
        k.accel_up = -327.0f;
        k.vel_north = 300.0f;
        k.vel_east = -0.01f;
        k.vel_up = 2.0f;
        xf_client_set_carrier(&r->c, &k, r->now);
        memset(&g, 0, sizeof(g));
        g.latitude_e7 = -338688000;
        g.longitude_e7 = 1512093000;
        g.altitude_mm = -4200;
        g.satellites = 21;
        g.week = 2345;
        g.ms_of_week = 604799999u;
        g.relative_height_mm = -12;
        xf_client_set_gnss(&r->c, &g, r->now);
        xf_client_set_angles(&r->c, 200.0f, -30.0f, -190.0f, r->now);
        xf_command_init(&cmd, XF_ORDER_GAZE_GEO); /* the longest parameters: 12 bytes */
        cmd.longitude = -1224194200;
        cmd.latitude = 377749300;
        cmd.altitude = -100000;
        assert_status(ct_run_cmd(r, ct_submit_cmd(r, &cmd), 1000, NULL), XF_CMD_OK);
        xf_client_set_rates(&r->c, -3.5f, 2.0f, 7.25f, r->now);
        assert_xf(xf_client_external_track(&r->c, XF_CAM1, -1000, 1000), XF_OK); /* 6 streamed bytes */
        ct_run(r, 200);
        assert_xf(xf_client_external_track_stop(&r->c, NULL), XF_OK);
        ct_run(r, 200);
        xf_client_set_carrier(&r->c, &k, r->now); /* fresh again: both flags in the last packets */
        xf_client_set_rates(&r->c, -3.5f, 2.0f, 7.25f, r->now);
        ct_run(r, 40);
        assert_true(r->log.n_host_checked >= 20u);
        assert_true(r->log.n_tele_checked >= 20u);
        assert_int_equal(r->log.n_host_mismatch, 0);
        assert_int_equal(r->log.n_tele_mismatch, 0);
        assert_int_equal(r->s.host.main.status, XF_STATUS_INS_VALID | XF_STATUS_CTRL_VALID);
        assert_int_equal(r->s.host.main.carrier_roll, -17950); /* and the values at their places */
        assert_int_equal(r->s.host.main.carrier_pitch, 4525);
        assert_int_equal(r->s.host.main.carrier_yaw, 35900);
        assert_int_equal(r->s.host.main.accel_north, -50);
        assert_int_equal(r->s.host.main.accel_east, 125);
        assert_int_equal(r->s.host.main.accel_up, -32700);
        assert_int_equal(r->s.host.main.vel_north, 30000);
        assert_int_equal(r->s.host.main.vel_east, -1);
        assert_int_equal(r->s.host.main.vel_up, 200);
        assert_int_equal(r->s.host.main.roll_ctrl, -35); /* 0.1 deg/s at zoom 1x */
        assert_int_equal(r->s.host.main.pitch_ctrl, 20);
        assert_int_equal(r->s.host.main.yaw_ctrl, 73);
        assert_int_equal(r->s.host.main.sub_request, XF_SUB_HEADER);
        assert_int_equal(r->s.host.sub.sub_header, XF_SUB_HEADER);
        assert_int_equal(r->s.host.sub.latitude, -338688000);
        assert_int_equal(r->s.host.sub.longitude, 1512093000);
        assert_int_equal(r->s.host.sub.altitude, -4200);
        assert_int_equal(r->s.host.sub.satellites, 21);
        assert_int_equal(r->s.host.sub.gnss_week, 2345);
        assert_int_equal(r->s.host.sub.gnss_ms, 604799999u);
        assert_int_equal(r->s.host.sub.relative_height, -12);
        assert_int_equal(r->c.tele.version, versions[v]);
        ct_rig_free(r);
    }
}

/* The wire's integers in physical units, on read. */
static void test_telemetry_convert(void **state)
{
    xf_telemetry t;
    xf_telemetry_units u;
    (void)state;
    memset(&t, 0, sizeof(t));
    t.version = 1;
    t.cam_roll = -1234;
    t.cam_pitch = -9000;
    t.cam_yaw = 35999;
    t.rel_angle_x = 1;
    t.rel_angle_y = -2;
    t.rel_angle_z = 18000;
    t.rate_x = -150;
    t.rate_y = 7;
    t.rate_z = 2000;
    t.zoom_cam1 = 55;
    t.zoom_cam2 = 300;
    t.target_distance = 1234;
    memset(&u, 0xA5, sizeof(u)); /* every member written */
    assert_xf(xf_telemetry_convert(&t, &u), XF_OK);
    assert_near(u.cam_roll_deg, -12.34, 1e-4);
    assert_near(u.cam_pitch_deg, -90.0, 1e-4);
    assert_near(u.cam_yaw_deg, 359.99, 1e-3);
    assert_near(u.rel_x_deg, 0.01, 1e-6);
    assert_near(u.rel_y_deg, -0.02, 1e-6);
    assert_near(u.rel_z_deg, 180.0, 1e-4);
    assert_near(u.rate_x_dps, -1.5, 1e-5); /* V0.1: 0.01 deg/s */
    assert_near(u.rate_y_dps, 0.07, 1e-6);
    assert_near(u.rate_z_dps, 20.0, 1e-4);
    assert_near(u.zoom_cam1, 5.5, 1e-6);
    assert_near(u.zoom_cam2, 30.0, 1e-5);
    assert_true(u.distance_valid);
    assert_near(u.target_distance_m, 123.4, 1e-3);
    /* V0.2: rates in 0.1 deg/s */
    t.version = 2;
    assert_xf(xf_telemetry_convert(&t, &u), XF_OK);
    assert_near(u.rate_x_dps, -15.0, 1e-4);
    assert_near(u.rate_z_dps, 200.0, 1e-3);
    /* no valid distance (0 and the -1 m sentinel): 0 m, flagged */
    t.target_distance = XF_DISTANCE_INVALID_RAW;
    assert_xf(xf_telemetry_convert(&t, &u), XF_OK);
    assert_false(u.distance_valid);
    assert_near(u.target_distance_m, 0.0, 0.0);
    t.target_distance = 0;
    u.distance_valid = true;
    assert_xf(xf_telemetry_convert(&t, &u), XF_OK);
    assert_false(u.distance_valid);
    assert_xf(xf_telemetry_convert(NULL, &u), XF_ERR_ARG);
    assert_xf(xf_telemetry_convert(&t, NULL), XF_ERR_ARG);
}

/* V2 replies: rates in 0.1 deg/s on the wire, deg/s in the telemetry; the V2 fields. */
static void test_protocol_v2_rates(void **state)
{
    static const uint8_t versions[] = {1, 2};
    size_t k;
    (void)state;
    for (k = 0; k < 2; k++) {
        xf_sim_config sc;
        ct_rig *r;
        const xf_telemetry *t;
        int i;
        xf_sim_config_init(&sc);
        sc.version = versions[k];
        r = rig_up(NULL, &sc);
        t = xf_client_telemetry(&r->c);
        for (i = 0; i < 6; i++) {
            xf_client_set_rates(&r->c, 0.0f, 0.0f, 20.0f, r->now);
            ct_run(r, 50);
        }
        assert_int_equal(t->version, versions[k]);
        assert_int_equal(t->rate_z, versions[k] == 2u ? 200 : 2000); /* 20 deg/s in the version's unit */
        assert_near(xf_gcu_rate_dps(t->rate_z, t->version), 20.0, 0.15);
        assert_near(xf_gcu_rate_dps(t->rate_x, t->version), 0.0, 0.15);
        if (versions[k] == 2u) {
            assert_int_equal(t->thermal_status, XF_THERMAL_MEASURE_AVAILABLE);
            assert_true((t->camera_status & XF_CAMERA_OSD_ON) != 0u);
        } else {
            assert_int_equal(t->thermal_status, 0);
            assert_int_equal(t->camera_status, 0);
        }
        ct_rig_free(r);
    }
}

/* A V2 client with a V2 GCU: V2 orders, V2 fields change. */
static void test_protocol_v2_orders(void **state)
{
    xf_client_config cc;
    xf_sim_config sc;
    ct_rig *r;
    xf_command cmd;
    uint32_t id;
    const xf_telemetry *t;
    xf_host_packet last;
    (void)state;
    xf_client_config_init(&cc);
    cc.protocol_version = 2;
    xf_sim_config_init(&sc);
    sc.version = 2;
    r = rig_up(&cc, &sc);
    t = xf_client_telemetry(&r->c);
    xf_command_init(&cmd, XF_ORDER_TIME_ZONE);
    cmd.hours = -2;
    id = ct_submit_cmd(r, &cmd);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 40);
    assert_int_equal(t->time_zone, -2);
    id = ct_submit(r, XF_ORDER_RECORD);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 40);
    assert_true((t->camera_status & XF_CAMERA_RECORDING) != 0u);
    assert_int_equal(r->s.host.version, 2); /* the client speaks V2 */
    r->sim_on = 0;
    ct_run(r, 40);
    assert_true(ct_drain_host(r, &last) >= 1u);
    assert_int_equal(last.version, 2);
    ct_rig_free(r);
}

/* ---- inputs: carrier and GNSS ------------------------------------------------------- */

static void test_carrier_only_while_fresh(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_carrier k;
    const xf_host_main *m = &r->s.host.main;
    uint32_t n;
    (void)state;
    ct_run(r, 200);
    assert_int_equal(r->s.stats.ins_valid_packets, 0); /* never set: never sent */
    assert_int_equal(m->status & XF_STATUS_INS_VALID, 0);
    memset(&k, 0, sizeof(k));
    k.roll_deg = 10.5f;
    k.pitch_deg = -5.25f;
    k.yaw_deg = 270.0f;
    k.accel_north = 0.1f;
    k.accel_east = -0.2f;
    k.accel_up = 0.5f;
    k.vel_north = 21.12f;
    k.vel_east = -3.5f;
    k.vel_up = 1.0f;
    xf_client_set_carrier(&r->c, &k, r->now);
    ct_run(r, 100);
    assert_true(r->s.stats.ins_valid_packets >= 4u);
    assert_int_equal(m->status & XF_STATUS_INS_VALID, XF_STATUS_INS_VALID);
    assert_int_equal(m->carrier_roll, 1050);
    assert_int_equal(m->carrier_pitch, -525);
    assert_int_equal(m->carrier_yaw, 27000);
    assert_int_equal(m->accel_north, 10);
    assert_int_equal(m->accel_east, -20);
    assert_int_equal(m->accel_up, 50);
    assert_int_equal(m->vel_north, 2112);
    assert_int_equal(m->vel_east, -350);
    assert_int_equal(m->vel_up, 100);
    ct_run(r, 100); /* 200 ms: the last fresh packet */
    n = r->s.stats.ins_valid_packets;
    assert_true(n >= 10u && n <= 11u);
    ct_run(r, 500); /* stale: zeros with ins_valid clear, never invented */
    assert_int_equal(r->s.stats.ins_valid_packets, n);
    assert_int_equal(m->status & XF_STATUS_INS_VALID, 0);
    assert_int_equal(m->carrier_roll, 0);
    assert_int_equal(m->carrier_pitch, 0);
    assert_int_equal(m->carrier_yaw, 0);
    assert_int_equal(m->accel_up, 0);
    assert_int_equal(m->vel_north, 0);
    /* fresh again */
    xf_client_set_carrier(&r->c, &k, r->now);
    ct_run(r, 30);
    assert_true(r->s.stats.ins_valid_packets > n);
    xf_client_set_carrier(NULL, &k, r->now);
    xf_client_set_carrier(&r->c, NULL, r->now);
    ct_rig_free(r);
}

static void test_gnss_only_while_fresh(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_gnss g;
    const xf_host_sub *s = &r->s.host.sub;
    (void)state;
    ct_run(r, 100);
    assert_int_equal(s->sub_header, 0); /* no sub frame data: all zero */
    assert_int_equal(s->latitude, 0);
    memset(&g, 0, sizeof(g));
    g.latitude_e7 = xf_deg7_raw(47.3977419);
    g.longitude_e7 = xf_deg7_raw(8.5455938);
    g.altitude_mm = xf_mm_raw(488.2);
    g.satellites = 14;
    g.week = 2300;
    g.ms_of_week = 352718000u;
    g.relative_height_mm = xf_mm_raw(35.5);
    xf_client_set_gnss(&r->c, &g, r->now);
    ct_run(r, 1000);
    assert_int_equal(s->sub_header, XF_SUB_HEADER);
    assert_int_equal(s->latitude, 473977419);
    assert_int_equal(s->longitude, 85455938);
    assert_int_equal(s->altitude, 488200);
    assert_int_equal(s->satellites, 14);
    assert_int_equal(s->gnss_week, 2300);
    assert_int_equal(s->gnss_ms, 352718000u);
    assert_int_equal(s->relative_height, 35500);
    assert_int_equal(r->s.host.main.sub_request, XF_SUB_HEADER);
    ct_run(r, 1000); /* 2000 ms: still fresh at the limit */
    assert_int_equal(s->sub_header, XF_SUB_HEADER);
    ct_run(r, 30);
    assert_int_equal(s->sub_header, 0);
    assert_int_equal(s->latitude, 0);
    assert_int_equal(s->longitude, 0);
    assert_int_equal(s->altitude, 0);
    assert_int_equal(s->satellites, 0);
    assert_int_equal(s->gnss_ms, 0);
    assert_int_equal(s->gnss_week, 0);
    assert_int_equal(s->relative_height, 0);
    ct_rig_free(r);
}

/* ---- control ---------------------------------------------------------------------------- */

/* The watchdog: rates not refreshed are replaced by zero rates (still valid). */
static void test_watchdog_zeroes_rates(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    const xf_host_main *m = &r->s.host.main;
    const xf_health *h = xf_client_health(&r->c);
    float pitch;
    (void)state;
    xf_client_set_rates(&r->c, 0.0f, 10.0f, 20.0f, r->now);
    ct_run(r, 100);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, XF_STATUS_CTRL_VALID);
    assert_int_equal(m->pitch_ctrl, 100);
    assert_int_equal(m->yaw_ctrl, 200);
    assert_near(r->s.rate[1], 10.0, 0.01);
    assert_int_equal(h->watchdog_active, 0);
    ct_run(r, 400); /* 500 ms */
    assert_int_equal(m->yaw_ctrl, 200);
    ct_run(r, 30);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, XF_STATUS_CTRL_VALID);
    assert_int_equal(m->roll_ctrl, 0);
    assert_int_equal(m->pitch_ctrl, 0);
    assert_int_equal(m->yaw_ctrl, 0);
    assert_int_equal(h->watchdog_active, 1);
    assert_int_equal(h->watchdog_trips, 1);
    assert_near(r->s.rate[1], 0.0, 1e-6); /* the gimbal holds still */
    pitch = r->s.pitch;
    ct_run(r, 500);
    assert_near(r->s.pitch, pitch, 1e-6);
    assert_int_equal(h->watchdog_trips, 1); /* one trip, however long */
    /* refreshed: moving again, then a second trip */
    xf_client_set_rates(&r->c, 0.0f, -10.0f, 0.0f, r->now);
    assert_int_equal(h->watchdog_active, 0);
    ct_run(r, 40);
    assert_int_equal(m->pitch_ctrl, -100);
    ct_run(r, 500);
    assert_int_equal(m->pitch_ctrl, 0);
    assert_int_equal(h->watchdog_trips, 2);
    /* clear_control: ctrl_valid clear */
    xf_client_clear_control(&r->c);
    ct_run(r, 40);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, 0);
    assert_int_equal(h->watchdog_active, 0);
    ct_rig_free(r);
}

static void test_watchdog_off(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    (void)state;
    xf_client_config_init(&cc);
    cc.rate_watchdog_ms = 0;
    r = rig_up(&cc, NULL);
    xf_client_set_rates(&r->c, 0.0f, 0.0f, 5.0f, r->now);
    ct_run(r, 2000);
    assert_int_equal(r->s.host.main.yaw_ctrl, 50);
    assert_int_equal(r->c.health.watchdog_trips, 0);
    ct_rig_free(r);
}

/* Rates are sent divided by 0.1 deg/s / zoom: the gimbal turns as asked at any zoom. */
static void test_rates_scaled_by_zoom(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    const xf_telemetry *t = xf_client_telemetry(&r->c);
    xf_command cmd;
    uint32_t id, i;
    (void)state;
    xf_client_set_rates(&r->c, 0.0f, 0.0f, 5.0f, r->now);
    ct_run(r, 40);
    assert_int_equal(r->s.host.main.yaw_ctrl, 50);
    assert_near(r->s.rate[2], 5.0, 0.01);
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.zoom = xf_zoom_to_rate_raw(10.0f);
    id = ct_submit_cmd(r, &cmd);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    for (i = 0; i < 3000u && t->zoom_cam1 != 100u; i++) { /* 10.0x in 0.1 x */
        ct_tick(r);
    }
    assert_int_equal(t->zoom_cam1, 100);
    xf_client_set_rates(&r->c, 0.0f, 0.0f, 5.0f, r->now);
    ct_run(r, 40);
    assert_int_equal(r->s.host.main.yaw_ctrl, 500);
    assert_near(r->s.rate[2], 5.0, 0.01);
    xf_client_set_rates(&r->c, 0.0f, -2.5f, 0.0f, r->now);
    ct_run(r, 40);
    assert_int_equal(r->s.host.main.pitch_ctrl, -250);
    assert_near(r->s.rate[1], -2.5, 0.01);
    /* the wire's limit, 1500, is 15 deg/s at 10x */
    xf_client_set_rates(&r->c, 0.0f, 0.0f, 20.0f, r->now);
    ct_run(r, 40);
    assert_int_equal(r->s.host.main.yaw_ctrl, 1500);
    ct_rig_free(r);
}

/* Head lock: rates integrate; at zero the angles hold. */
static void test_head_lock_rates_integrate(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    const xf_telemetry *t = xf_client_telemetry(&r->c);
    float p0, y0;
    int i;
    (void)state;
    assert_int_equal(t->gimbal_mode, XF_MODE_HEAD_LOCK);
    p0 = r->s.pitch;
    y0 = r->s.yaw;
    for (i = 0; i < 10; i++) {
        xf_client_set_rates(&r->c, 0.0f, 10.0f, -20.0f, r->now);
        ct_run(r, 100);
    }
    xf_client_set_rates(&r->c, 0.0f, 0.0f, 0.0f, r->now);
    ct_run(r, 40);
    assert_near(r->s.pitch - p0, 10.0, 0.5);
    assert_angle_near(r->s.yaw, y0 - 20.0, 1.0);
    ct_run(r, 400);
    assert_near(xf_cdeg(t->cam_pitch), r->s.pitch, 0.011);
    assert_angle_near(xf_cdeg(t->cam_yaw), r->s.yaw, 0.011);
    p0 = r->s.pitch;
    ct_run(r, 400);
    assert_near(r->s.pitch, p0, 1e-6);
    ct_rig_free(r);
}

/* Euler mode: the gimbal slews to the angles asked (not subject to the watchdog). */
static void test_euler_reaches_target(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    const xf_telemetry *t = xf_client_telemetry(&r->c);
    uint32_t id;
    (void)state;
    id = ct_submit(r, XF_ORDER_EULER);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    xf_client_set_angles(&r->c, 0.0f, -30.0f, 90.0f, r->now);
    ct_run(r, 300);
    assert_true(xf_cdeg(t->cam_yaw) > 10.0f && xf_cdeg(t->cam_yaw) < 85.0f); /* slewing, not jumping */
    ct_run(r, 1700);
    assert_int_equal(t->gimbal_mode, XF_MODE_EULER);
    assert_near(xf_cdeg(t->cam_pitch), -30.0, 0.02);
    assert_angle_near(xf_cdeg(t->cam_yaw), 90.0, 0.02);
    assert_near(xf_cdeg(t->cam_roll), 0.0, 0.02);
    assert_int_equal(r->s.host.main.pitch_ctrl, -3000); /* angles stay: no watchdog */
    assert_int_equal(r->s.host.main.yaw_ctrl, 9000);
    assert_int_equal(r->c.health.watchdog_trips, 0);
    ct_rig_free(r);
}

static void test_orthoview_points_down(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    const xf_telemetry *t = xf_client_telemetry(&r->c);
    uint32_t id;
    (void)state;
    id = ct_submit(r, XF_ORDER_ORTHOVIEW);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 1500);
    assert_int_equal(t->gimbal_mode, XF_MODE_ORTHOVIEW);
    assert_near(xf_cdeg(t->cam_pitch), -90.0, 0.02);
    ct_rig_free(r);
}

/* FPV follows the carrier: V1's angle control ("FPV" in V2.0.4), V2's fpv. */
static void test_fpv_follows_carrier(void **state)
{
    size_t k;
    (void)state;
    for (k = 0; k < 2; k++) {
        xf_client_config cc;
        xf_sim_config sc;
        ct_rig *r;
        const xf_telemetry *t;
        xf_carrier car;
        uint32_t id;
        int i;
        xf_client_config_init(&cc);
        xf_sim_config_init(&sc);
        cc.protocol_version = (uint8_t)(k + 1u);
        sc.version = (uint8_t)(k + 1u);
        r = rig_up(&cc, &sc);
        t = xf_client_telemetry(&r->c);
        memset(&car, 0, sizeof(car));
        car.roll_deg = 5.0f;
        car.pitch_deg = 10.0f;
        car.yaw_deg = 45.0f;
        xf_client_set_carrier(&r->c, &car, r->now);
        id = ct_submit(r, k == 0u ? XF_ORDER_ANGLE_CONTROL : XF_ORDER_FPV);
        assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
        xf_client_set_angles(&r->c, 0.0f, 0.0f, 0.0f, r->now);
        for (i = 0; i < 20; i++) {
            xf_client_set_carrier(&r->c, &car, r->now);
            ct_run(r, 50);
        }
        assert_int_equal(t->gimbal_mode, k == 0u ? XF_MODE_ANGLE_CONTROL : XF_MODE_FPV);
        assert_near(xf_cdeg(t->cam_roll), 5.0, 0.02);
        assert_near(xf_cdeg(t->cam_pitch), 10.0, 0.02);
        assert_angle_near(xf_cdeg(t->cam_yaw), 45.0, 0.02);
        assert_near(xf_cdeg(t->rel_angle_z), 0.0, 0.02);
        /* the carrier turns; the camera follows, offset by the angles asked */
        car.yaw_deg = 200.0f;
        xf_client_set_angles(&r->c, 0.0f, -10.0f, 15.0f, r->now);
        for (i = 0; i < 40; i++) {
            xf_client_set_carrier(&r->c, &car, r->now);
            ct_run(r, 50);
        }
        assert_angle_near(xf_cdeg(t->cam_yaw), 215.0, 0.02);
        assert_near(xf_cdeg(t->cam_pitch), 0.0, 0.02);
        assert_near(xf_cdeg(t->rel_angle_z), 15.0, 0.02);
        ct_rig_free(r);
    }
}

/* ---- external track ----------------------------------------------------------------------- */

static void test_external_track_stream_and_stop(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    const xf_telemetry *t = xf_client_telemetry(&r->c);
    uint32_t before, id, stop;
    size_t mark;
    xf_cmd_result res;
    (void)state;
    assert_xf(xf_client_external_track(&r->c, XF_CAM1, 512, -256), XF_OK);
    before = r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK];
    ct_run(r, 500);
    /* every packet runs: exempt from the once-rule */
    assert_int_equal(r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK] - before, 25);
    assert_int_equal(r->s.mode, XF_MODE_TRACK);
    assert_int_equal(t->gimbal_mode, XF_MODE_TRACK);
    assert_true((t->pod_status & XF_POD_TRACKING_OK) != 0u);
    assert_true(t->target_offset_x > 0 && t->target_offset_y < 0);
    /* new offsets go out at once */
    assert_xf(xf_client_external_track(&r->c, XF_CAM1, -100, 100), XF_OK);
    ct_run(r, 40);
    assert_true(t->target_offset_x < 0 && t->target_offset_y > 0);
    /* a command in the middle: the stream pauses for it and a null */
    mark = r->log.n_sent;
    id = ct_submit(r, XF_ORDER_SHUTTER);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 100);
    assert_int_equal(r->s.stats.photos, 1);
    assert_int_equal(sent_count(&r->log, XF_ORDER_SHUTTER, mark), 1);
    assert_true(sent_count(&r->log, XF_ORDER_EXTERNAL_TRACK, mark) >= 3u);
    /* stop: exit sent as a command, then no more streaming */
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_OK);
    assert_status(ct_run_cmd(r, stop, 1000, &res), XF_CMD_OK);
    assert_int_equal(r->s.mode, XF_MODE_HEAD_LOCK);
    ct_run(r, 40);
    assert_int_equal(t->pod_status & XF_POD_TRACKING_OK, 0);
    before = r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK];
    mark = r->log.n_sent;
    ct_run(r, 500);
    assert_int_equal(r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK], before);
    assert_int_equal(sent_count(&r->log, XF_ORDER_NULL, mark), r->log.n_sent - mark);
    assert_xf(xf_client_external_track(NULL, 1, 0, 0), XF_ERR_ARG);
    assert_xf(xf_client_external_track_stop(NULL, NULL), XF_ERR_ARG);
    ct_rig_free(r);
}

/*
 * The stop's result is its own: with replies 200 ms late, the stream's
 * replies (order 0x1B, success) are still in flight when the stop starts.
 * The GCU fails the stop; the client must say so.
 */
static void test_external_track_stop_not_resolved_by_stream(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    uint32_t stop;
    xf_cmd_result res;
    (void)state;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = 3000;
    r = ct_rig_new(&cc, NULL);
    r->s.fault.delay_ms = 200;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    assert_xf(xf_client_external_track(&r->c, XF_CAM1, 10, 10), XF_OK);
    ct_run(r, 500);
    xf_sim_set_failure(&r->s, XF_ORDER_EXTERNAL_TRACK, XF_CAM1);
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_OK);
    assert_status(ct_run_cmd(r, stop, 3000, &res), XF_CMD_FAILED);
    assert_int_equal(res.failed_cameras, XF_CAM1);
    ct_rig_free(r);
}

/*
 * Run until command @p id has a final status, at most @p max_ms, watching
 * what the simulator receives: *exits counts the external-track exits
 * (value 0), *cameras ORs their camera masks, *streamed counts the stream's
 * packets (value 2). Returns the status.
 */
static xf_cmd_status run_watch_exits(ct_rig *r, uint32_t id, uint32_t max_ms, size_t *exits, uint8_t *cameras,
                                     size_t *streamed)
{
    uint32_t i, seen = r->s.stats.packets_in;
    xf_cmd_status st = xf_client_command_status(&r->c, id, NULL);
    for (i = 0; i < max_ms && (st == XF_CMD_QUEUED || st == XF_CMD_SENDING || st == XF_CMD_OPERATING); i++) {
        ct_tick(r);
        /* The simulator keeps only the last host packet: look at each as it comes. */
        if (r->s.stats.packets_in != seen && r->s.host.order == XF_ORDER_EXTERNAL_TRACK) {
            xf_command got;
            assert_xf(xf_command_decode(r->s.host.order, r->s.host.params, r->s.host.params_len, r->s.host.version,
                                        &got, NULL),
                      XF_OK);
            if (got.value == 0u) {
                (*exits)++;
                *cameras |= got.cameras;
            } else {
                (*streamed)++;
            }
        }
        seen = r->s.stats.packets_in;
        st = xf_client_command_status(&r->c, id, NULL);
    }
    return st;
}

/*
 * A stop refused with XF_ERR_BUSY (queue full) changes nothing: the stream
 * stays on, nothing is queued, the client is byte for byte as before. The
 * application's retry, once a command has finished, then sends the exit to
 * the stream's camera (2 here), not to camera 1, the camera of a stop with
 * no stream on.
 */
static void test_external_track_stop_busy_changes_nothing(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    xf_client *before = (xf_client *)malloc(sizeof(xf_client));
    uint32_t id[XF_CLIENT_QUEUE], stop = 0;
    size_t i, exits = 0, streamed = 0;
    uint8_t cameras = 0;
    (void)state;
    assert_non_null(before);
    assert_xf(xf_client_external_track(&r->c, XF_CAM2, 300, -200), XF_OK);
    ct_run(r, 100);
    assert_int_equal(r->s.mode, XF_MODE_TRACK);
    for (i = 0; i < XF_CLIENT_QUEUE; i++) {
        id[i] = ct_submit(r, XF_ORDER_SHUTTER);
    }
    memcpy(before, &r->c, sizeof(xf_client));
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_ERR_BUSY);
    assert_int_equal(stop, 0); /* no id given */
    assert_int_equal(r->c.stream_on, 1);
    assert_int_equal(r->c.stream[0], XF_CAM2);
    assert_int_equal(xf_client_pending(&r->c), XF_CLIENT_QUEUE);
    assert_int_equal(r->c.guard_order, before->guard_order);
    assert_int_equal(r->c.guard_open, before->guard_open);
    assert_memory_equal(&r->c, before, sizeof(xf_client));
    free(before);
    /* the first command done, there is room: the retry queues the stream's exit */
    assert_status(ct_run_cmd(r, id[0], 1000, NULL), XF_CMD_OK);
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_OK);
    assert_true(stop != 0u);
    assert_int_equal(r->c.stream_on, 0);
    assert_status(run_watch_exits(r, stop, 5000, &exits, &cameras, &streamed), XF_CMD_OK);
    assert_int_equal(r->s.stats.photos, XF_CLIENT_QUEUE); /* the commands ahead of it all ran */
    assert_true(exits >= 1u);
    assert_int_equal(cameras, XF_CAM2); /* every exit went to camera 2, none to camera 1 */
    assert_int_equal(streamed, 0);      /* the stream stopped with the accepted stop */
    assert_int_equal(r->s.mode, XF_MODE_HEAD_LOCK);
    ct_rig_free(r);
}

/* A stop accepted at once: the stream ends, the exit goes to the stream's
 * camera, waits behind the stream's replies, and its result is its own. */
static void test_external_track_stop_success(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    uint32_t stop = 0, before;
    size_t mark, exits = 0, streamed = 0;
    uint8_t cameras = 0;
    xf_cmd_result res;
    (void)state;
    assert_xf(xf_client_external_track(&r->c, XF_CAM2, -300, 200), XF_OK);
    ct_run(r, 100);
    assert_int_equal(r->s.mode, XF_MODE_TRACK);
    assert_xf(xf_client_external_track_stop(&r->c, &stop), XF_OK);
    assert_true(stop != 0u);
    assert_int_equal(r->c.stream_on, 0);
    assert_int_equal(xf_client_pending(&r->c), 1);
    /* the stream's late replies may still come: the exit waits for another order's */
    assert_int_equal(r->c.guard_order, XF_ORDER_EXTERNAL_TRACK);
    assert_int_equal(r->c.guard_open, 1);
    assert_status(run_watch_exits(r, stop, 1000, &exits, &cameras, &streamed), XF_CMD_OK);
    assert_status(xf_client_command_status(&r->c, stop, &res), XF_CMD_OK);
    assert_int_equal(res.order, XF_ORDER_EXTERNAL_TRACK);
    assert_true(exits >= 1u);
    assert_int_equal(cameras, XF_CAM2);
    assert_int_equal(streamed, 0);
    assert_int_equal(r->s.mode, XF_MODE_HEAD_LOCK);
    /* and no more streaming */
    before = r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK];
    mark = r->log.n_sent;
    ct_run(r, 300);
    assert_int_equal(r->s.stats.executed[XF_ORDER_EXTERNAL_TRACK], before);
    assert_int_equal(sent_count(&r->log, XF_ORDER_EXTERNAL_TRACK, mark), 0);
    ct_rig_free(r);
}

/* ---- the clock wraps at 2^32 ---------------------------------------------------------------- */

static void test_clock_wrap(void **state)
{
    xf_client_config cc;
    xf_sim_config sc;
    ct_rig *r;
    uint32_t a, b, cal;
    int i;
    (void)state;
    xf_client_config_init(&cc);
    xf_sim_config_init(&sc);
    sc.calibration_ms = 600;
    r = ct_rig_new_at(&cc, &sc, 0xFFFFFC00u);
    assert_true(ct_run_link(r, XF_LINK_UP, 100));
    ct_run(r, 700);
    a = ct_submit(r, XF_ORDER_SHUTTER);
    b = ct_submit(r, XF_ORDER_SHUTTER);
    cal = ct_submit(r, XF_ORDER_CALIBRATION);
    for (i = 0; i < 20; i++) { /* rates refreshed across the wrap: no watchdog trip */
        xf_client_set_rates(&r->c, 0.0f, 0.0f, 1.0f, r->now);
        ct_run(r, 100);
    }
    assert_true(r->now < 0x10000000u); /* wrapped */
    assert_status(xf_client_command_status(&r->c, a, NULL), XF_CMD_OK);
    assert_status(xf_client_command_status(&r->c, b, NULL), XF_CMD_OK);
    assert_status(xf_client_command_status(&r->c, cal, NULL), XF_CMD_OK);
    assert_int_equal(r->s.stats.photos, 2);
    assert_int_equal(r->log.n_links, 1); /* up all along */
    assert_int_equal(r->c.health.watchdog_trips, 0);
    assert_true(r->now - r->c.health.last_rx_ms <= 20u);
    ct_rig_free(r);
}

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
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
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

/* ---- a tap stamps with its own clock (xf_tap.h) ------------------------------------------------ */

typedef struct tap_seen {
    ct_rig *r;
    size_t host, gcu, clock_calls, wrong_time;
} tap_seen;

static uint32_t tap_clock(void *user)
{
    tap_seen *s = (tap_seen *)user;
    s->clock_calls++;
    return s->r->now + 7u; /* not the client's time: the stamps must come from here */
}

static void tap_chunk(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    tap_seen *s = (tap_seen *)user;
    (void)data;
    assert_true(len > 0u);
    if (dir == XF_DIR_HOST) {
        s->host++;
    } else {
        s->gcu++;
    }
    s->wrong_time += (now_ms != s->r->now + 7u);
}

static void test_tap_own_clock(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_client_config cc = r->c.cfg;
    xf_tap tap;
    xf_hal tapped;
    tap_seen seen;
    (void)state;
    memset(&seen, 0, sizeof(seen));
    seen.r = r;
    xf_tap_init(&tap, &r->host_hal, tap_chunk, tap_clock, &seen, &tapped);
    assert_xf(xf_hal_check(&tapped), XF_OK);
    assert_int_equal(xf_hal_fd(&tapped), -1);
    assert_xf(xf_client_init(&r->c, &tapped, &cc), XF_OK);
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    ct_run(r, 100);
    assert_true(seen.host >= 5u && seen.gcu >= 5u);
    assert_int_equal(seen.clock_calls, seen.host + seen.gcu);
    assert_int_equal(seen.wrong_time, 0);
    assert_int_equal(seen.host, r->c.health.packets_sent);
    ct_rig_free(r);
}

/* The GCU's model decides what goes: an order its model does not have (V2.0.6's support list)
 * is refused, nothing queued, unless the application insists; before the first sub frame the
 * model is unknown and nothing is refused. The simulated Z-6A (code 0) has focus, not palette. */
static void test_submit_model_support(void **state)
{
    xf_sim_config sc;
    ct_rig *r;
    xf_command palette, focus;
    xf_cmd_result res;
    uint32_t id = 0;
    (void)state;
    xf_sim_config_init(&sc);
    sc.gimbal_code = 0;
    r = ct_rig_new(NULL, &sc);
    xf_command_init(&palette, XF_ORDER_PALETTE);
    palette.value = 1;
    xf_command_init(&focus, XF_ORDER_FOCUS);
    assert_int_equal(xf_client_supports(&r->c, XF_ORDER_PALETTE), XF_SUPPORT_UNKNOWN);
    assert_xf(xf_client_submit(&r->c, &palette, &id, NULL), XF_OK); /* no sub frame yet: it goes */
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_FAILED);    /* and the model fails it */
    assert_int_equal(r->s.stats.executed[XF_ORDER_PALETTE], 1);
    assert_int_equal(xf_client_telemetry(&r->c)->have_sub, 1);
    assert_int_equal(xf_client_supports(&r->c, XF_ORDER_PALETTE), XF_SUPPORT_NO);
    assert_int_equal(xf_client_supports(&r->c, XF_ORDER_FOCUS), XF_SUPPORT_YES);
    assert_int_equal(xf_client_supports(&r->c, XF_ORDER_EXTERNAL_TRACK), XF_SUPPORT_UNKNOWN);
    assert_int_equal(xf_client_supports(NULL, XF_ORDER_FOCUS), XF_SUPPORT_UNKNOWN);
    /* refused: id untouched, nothing queued, nothing sent */
    id = 77;
    assert_xf(xf_client_submit(&r->c, &palette, &id, NULL), XF_ERR_UNSUPPORTED);
    assert_int_equal(id, 77);
    assert_int_equal(r->c.q_count, 0);
    ct_run(r, 200);
    assert_int_equal(r->s.stats.executed[XF_ORDER_PALETTE], 1);
    /* insisting sends it; the GCU answers as its model does */
    assert_xf(xf_client_submit_opt(&r->c, &palette, XF_SUBMIT_ANY_MODEL, &id, NULL), XF_OK);
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_FAILED);
    assert_int_equal(r->s.stats.executed[XF_ORDER_PALETTE], 2);
    /* a supported order goes as always, with or without the flag */
    assert_xf(xf_client_submit_opt(&r->c, &focus, 0u, &id, NULL), XF_OK);
    assert_status(ct_run_cmd(r, id, 1000, &res), XF_CMD_OK);
    ct_rig_free(r);
}

/* The GCU's version decides meaning: commands are checked for the version it speaks once it has
 * answered (palette 0..100 in V0.1, 0..10 in V0.2), and the OSD helper sends the value that
 * means show or hide in it (inverted in V0.2). The version byte sent stays the configured one. */
static void test_gcu_version_decides(void **state)
{
    static const uint8_t versions[] = {1, 2};
    size_t v;
    (void)state;
    for (v = 0; v < 2u; v++) {
        xf_sim_config sc;
        ct_rig *r;
        xf_command palette;
        xf_field bad = XF_F_NONE;
        uint32_t id = 0;
        xf_sim_config_init(&sc);
        sc.version = versions[v];
        r = ct_rig_new(NULL, &sc); /* the client's configured version is 1 */
        assert_int_equal(xf_client_gcu_version(&r->c), 1);
        assert_true(ct_run_link(r, XF_LINK_UP, 1000));
        assert_int_equal(xf_client_gcu_version(&r->c), versions[v]);
        xf_command_init(&palette, XF_ORDER_PALETTE);
        palette.value = 50;
        assert_xf(xf_client_submit(&r->c, &palette, &id, &bad), versions[v] == 2 ? XF_ERR_RANGE : XF_OK);
        assert_int_equal(bad, versions[v] == 2 ? XF_F_VALUE : XF_F_NONE);
        if (versions[v] == 1) {
            assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
        }
        assert_xf(xf_client_osd(&r->c, 0, &id), XF_OK);
        assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
        assert_int_equal(r->s.camera_status & XF_CAMERA_OSD_ON, 0); /* hidden, whatever the version */
        assert_int_equal(r->s.host.version, 1);
        assert_xf(xf_client_osd(&r->c, 1, &id), XF_OK);
        assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
        assert_int_equal(r->s.camera_status & XF_CAMERA_OSD_ON, XF_CAMERA_OSD_ON);
        ct_rig_free(r);
    }
    assert_int_equal(xf_client_gcu_version(NULL), 0);
    assert_xf(xf_client_osd(NULL, 1, NULL), XF_ERR_ARG);
}

/* ---- which control quantities go out (xf_ctrl_status) ---------------------------------- */

#define CR_NO_REPLY 0x00u /* a "mode" for no reply at all */

/* What a mode reads, typed from the rule's table (docs/protocol.md §11.1): 'a' angles, 'r' rates,
 * '-' none. */
static char cr_reads(uint8_t mode)
{
    switch (mode) {
    case 0x10:
    case 0x14:
    case 0x1C: return 'a';
    case 0x11:
    case 0x12:
    case 0x13:
    case 0x16: return 'r';
    default: return '-';
    }
}

/* One case: the GCU reports @p mode, the application sets @p kind ('-', 'r', 'a'), then submits
 * @p order; the packet that carries the order must carry the setpoint exactly when the rule says. */
static void cr_case(uint8_t mode, char kind, uint8_t order)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_host_packet last;
    xf_command cmd;
    xf_ctrl_status st = XF_CTRL_NOT_SET;
    int holds = order == XF_ORDER_NEUTRAL || order == XF_ORDER_TRACK || order == XF_ORDER_CLICK_TO_AIM ||
                order == XF_ORDER_GAZE_GEO;
    int want = kind != '-' && !holds && cr_reads(mode) == kind;
    /* with no reply yet, no reply to a null either: the command waits, nulls go out */
    uint8_t sent = (mode == CR_NO_REPLY) ? (uint8_t)XF_ORDER_NULL : order;
    size_t n;
    r->sim_on = 0; /* the test is the GCU */
    if (mode != CR_NO_REPLY) {
        xf_gcu_packet g;
        memset(&g, 0, sizeof(g));
        g.version = 2;
        g.main.gimbal_mode = mode;
        ct_gcu_reply(r, &g);
    }
    ct_run(r, 5);
    if (kind == 'r') {
        st = xf_client_set_rates(&r->c, 1.0f, 10.0f, -20.0f, r->now);
    } else if (kind == 'a') {
        st = xf_client_set_angles(&r->c, 5.0f, -45.0f, 30.0f, r->now);
    }
    assert_int_equal(st == XF_CTRL_SENT, kind != '-' && cr_reads(mode) == kind);
    (void)ct_drain_host(r, NULL);
    if (order != XF_ORDER_NULL) {
        ct_valid_command(&cmd, order);
        assert_xf(xf_client_submit(&r->c, &cmd, NULL, NULL), XF_OK);
    }
    ct_run(r, 25); /* one packet */
    n = ct_drain_host(r, &last);
    if (n != 1u || last.order != sent || ((last.main.status & XF_STATUS_CTRL_VALID) != 0u) != want) {
        print_error("mode 0x%02X, setpoint '%c', order %s: %u packets, order 0x%02X, ctrl_valid %d (want %d)\n", mode,
                    kind, xf_order_name(order), (unsigned)n, last.order,
                    (last.main.status & XF_STATUS_CTRL_VALID) != 0u, want);
        fail();
    }
    if (!want) {
        assert_int_equal(last.main.roll_ctrl | last.main.pitch_ctrl | last.main.yaw_ctrl, 0);
        assert_true(xf_client_control_status(&r->c) != XF_CTRL_SENT);
    } else {
        assert_int_equal(last.main.pitch_ctrl, kind == 'a' ? -4500 : 100);
        assert_int_equal(last.main.yaw_ctrl, kind == 'a' ? 3000 : -200);
        assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_SENT);
    }
    if (holds && kind != '-' && sent == order) {
        assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_DROPPED); /* set before it: gone */
    }
    ct_rig_free(r);
}

/* Every reported mode x every setpoint kind x every order, on the packets actually sent. */
/* ---- nothing mistaken: the start-up rule and links that reorder (docs/protocol.md §7.4) ---- */

/* A reply with the state of @p order, as a GCU sends it for an earlier command. */
static void nm_reply(ct_rig *r, uint8_t order, int with_state)
{
    xf_gcu_packet g;
    memset(&g, 0, sizeof(g));
    g.version = 1;
    g.order = order;
    if (with_state) {
        g.params[0] = XF_STATE_SUCCESS;
        g.params_len = 1;
    }
    ct_gcu_reply(r, &g);
}

/* A new client takes no reply for its command before a reply to one of its nulls: a late
 * "shutter ok" meant for a process that ran before it is not its own. */
static void test_start_waits_for_null_reply(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_host_packet last;
    uint32_t id;
    size_t i;
    (void)state;
    r->sim_on = 0; /* the test is the GCU */
    id = ct_submit(r, XF_ORDER_SHUTTER);
    nm_reply(r, XF_ORDER_SHUTTER, 1); /* late, for someone else */
    ct_run(r, 100);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_QUEUED);
    assert_int_equal(xf_client_link(&r->c), XF_LINK_UP); /* a GCU answers: only the rule holds it */
    for (i = 0; i < r->log.n_sent; i++) {
        assert_int_equal(r->log.sent_order[i], XF_ORDER_NULL);
    }
    nm_reply(r, XF_ORDER_SHUTTER, 1); /* still not a null's reply */
    ct_run(r, 40);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_QUEUED);
    nm_reply(r, XF_ORDER_NULL, 0);
    (void)ct_drain_host(r, NULL);
    ct_run(r, 20); /* one packet period */
    assert_int_equal(ct_drain_host(r, &last), 1);
    assert_int_equal(last.order, XF_ORDER_SHUTTER); /* the next packet carries it */
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_SENDING);
    nm_reply(r, XF_ORDER_SHUTTER, 1);
    ct_run(r, 5);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_OK);
    ct_rig_free(r);
}

/* A command that never gets to start ends after twice command_timeout_ms. */
static void test_unsynced_command_times_out(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    uint32_t id;
    (void)state;
    r->sim_on = 0;
    id = ct_submit(r, XF_ORDER_SHUTTER);
    ct_run(r, 1990);
    assert_status(xf_client_command_status(&r->c, id, NULL), XF_CMD_QUEUED);
    assert_status(ct_run_cmd(r, id, 100, &res), XF_CMD_LINK_LOST); /* nobody ever answered */
    assert_int_equal(res.packets, 0);
    assert_true(res.elapsed_ms >= 2000u && res.elapsed_ms <= 2002u);
    ct_rig_free(r);
}

/*
 * The red team's case: 60 shutters in a row over a link with 0..60 ms of jitter each way and
 * 30 % of packets duplicated. Returns the false "ok"s (an ok before the simulator had run that
 * many shutters) and, in *extra, the executions beyond one per command.
 */
static unsigned nm_shutters(uint16_t reorder_ms, unsigned *extra)
{
    xf_client_config cc;
    ct_rig *r;
    unsigned k, ok = 0, false_ok = 0;
    xf_client_config_init(&cc);
    cc.reorder_ms = reorder_ms;
    r = ct_rig_new(&cc, NULL);
    r->s.fault.jitter_ms = 60;
    r->s.fault.dup_permille = 300;
    ct_run(r, 200);
    for (k = 0; k < 60u; k++) {
        xf_cmd_result res;
        uint32_t id = ct_submit(r, XF_ORDER_SHUTTER);
        xf_cmd_status st = ct_run_cmd(r, id, 5000, &res);
        assert_status(st, XF_CMD_OK);
        ok++;
        if (r->s.stats.photos < ok) {
            false_ok++; /* the reply it took was an earlier command's */
        }
    }
    ct_run(r, 500);
    *extra = (r->s.stats.photos > ok) ? r->s.stats.photos - ok : 0u; /* (fewer when oks were false) */
    ct_rig_free(r);
    return false_ok;
}

/*
 * The red team's other case: every reply 1.5 s late, and one client after another on the same
 * link, as `xfgcu send shutter` run again and again. Each client settles before it goes
 * (xf_client_settled(): its command's replies are in) when @p settle; returns the "ok"s taken
 * sooner than the command's own reply could have come (an earlier client's late reply).
 */
static unsigned nm_sequence_at(uint32_t delay_ms, int settle, uint32_t timeout_ms, unsigned *oks);

static unsigned nm_sequence(int settle, uint32_t timeout_ms, unsigned *oks)
{
    return nm_sequence_at(1500, settle, timeout_ms, oks);
}

static unsigned nm_sequence_at(uint32_t delay_ms, int settle, uint32_t timeout_ms, unsigned *oks)
{
    xf_client_config cc;
    ct_rig *r;
    unsigned k, false_ok = 0;
    xf_client_config_init(&cc);
    cc.command_timeout_ms = timeout_ms;
    r = ct_rig_new(&cc, NULL);
    *oks = 0;
    r->s.fault.delay_ms = delay_ms;
    for (k = 0; k < 4u; k++) {
        xf_client_config keep = r->c.cfg;
        xf_cmd_result res;
        uint32_t id, i;
        assert_xf(xf_client_init(&r->c, &r->host_hal, &keep), XF_OK); /* a new process, same link */
        id = ct_submit(r, XF_ORDER_SHUTTER);
        if (ct_run_cmd(r, id, 10000, &res) == XF_CMD_OK) {
            (*oks)++;
            false_ok += (res.elapsed_ms < delay_ms) ? 1u : 0u; /* before its own reply could have come */
        }
        for (i = 0; settle && i < 3u * delay_ms + 2000u && !xf_client_settled(&r->c); i++) {
            ct_tick(r);
        }
        assert_true(!settle || xf_client_settled(&r->c));
    }
    ct_rig_free(r);
    return false_ok;
}

static void test_late_replies_not_taken(void **state)
{
    unsigned oks = 0, false_ok;
    (void)state;
    false_ok = nm_sequence(1, 1000, &oks); /* the red team's: the timeout is shorter than the delay */
    print_message("settled clients, 1 s timeout: %u ok of 4, %u false\n", oks, false_ok);
    assert_int_equal(false_ok, 0);
    false_ok = nm_sequence(1, 4000, &oks); /* a timeout long enough: every one genuinely ok */
    print_message("settled clients, 4 s timeout: %u ok of 4, %u false\n", oks, false_ok);
    assert_int_equal(false_ok, 0);
    assert_int_equal(oks, 4);
    /* without settling, the next client can take the last one's late "ok": the check can fail */
    false_ok = nm_sequence(0, 1000, &oks);
    print_message("unsettled clients, 1 s timeout: %u ok of 4, %u false\n", oks, false_ok);
    assert_true(false_ok > 0u);
}

/* The simulator's delay queue full of late replies never costs a host packet: the GCU still runs
 * what it receives (replies 3 s late at 50 Hz: more than the queue holds). And what is held when
 * the host goes away is not delivered to the next one. */
static void test_sim_delay_queue_keeps_commands(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    (void)state;
    r->s.fault.delay_ms = 3000;
    ct_run(r, 2900); /* the queue fills with replies */
    assert_int_equal(r->s.n_delayed, XF_SIM_DELAY_QUEUE);
    r->sim_on = 0;
    {
        xf_host_packet p;
        uint8_t buf[XF_PACKET_MAX_LEN];
        size_t len = 0;
        xf_host_packet_init(&p, 1);
        p.order = XF_ORDER_SHUTTER;
        assert_xf(xf_host_pack(&p, buf, sizeof(buf), &len), XF_OK);
        ct_fifo_put(&r->h2g, buf, len);
    }
    (void)xf_sim_step(&r->s, r->now + 1u);
    assert_int_equal(r->s.stats.executed[XF_ORDER_SHUTTER], 1); /* run at once, not dropped behind the replies */
    r->gcu.closed = 1;                                          /* the host goes away */
    (void)xf_sim_step(&r->s, r->now + 2u);
    assert_int_equal(r->s.n_delayed, 0);
    ct_rig_free(r);
}

/* The review's cases (2026-11-26): each ended with a false "ok" or a command that never ran. */

/* Two commands of different orders time out with their replies still on the way (1.5 s late):
 * the second's guard must not drop the first's, or a third of the first's order takes its late ok. */
static void test_guard_two_orders(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    (void)state;
    r->s.fault.delay_ms = 1500;
    ct_run(r, 3000);
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 5000, &res), XF_CMD_TIMEOUT);
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_RECORD), 5000, &res), XF_CMD_TIMEOUT);
    if (ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 5000, &res) == XF_CMD_OK) {
        assert_true(res.elapsed_ms >= 1500u); /* its own reply, never the first shutter's */
    }
    ct_rig_free(r);
}

/* A guard that gave up waiting no longer holds commands back, but the client is not settled:
 * nothing says the late replies have come (replies 2.5 s late, 1 s timeout). */
static void test_settled_needs_evidence(void **state)
{
    unsigned oks = 0;
    (void)state;
    assert_int_equal(nm_sequence_at(2500, 1, 1000, &oks), 0);
}

/* With the external-track stream on, a command that waits (for the start-up rule or a guard)
 * gets null packets, not the stream: else no null's reply ever comes and it never runs. */
static void test_stream_and_waiting_commands(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    uint32_t id;
    (void)state;
    assert_xf(xf_client_external_track(&r->c, 1, 10, 10), XF_OK); /* before the first step */
    ct_run(r, 500);
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_ZOOM_STOP), 3000, &res), XF_CMD_OK);
    ct_run(r, 500);
    assert_xf(xf_client_external_track_stop(&r->c, &id), XF_OK);
    assert_xf(xf_client_external_track(&r->c, 1, 20, 20), XF_OK); /* a new target at once */
    assert_status(ct_run_cmd(r, id, 3000, &res), XF_CMD_OK);
    ct_rig_free(r);
}

/* 0x1B submitted as a command while the stream runs: the stream's replies carry that order's
 * state, so the command waits for them to pass (replies 100 ms late). */
static void test_track_command_while_streaming(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    xf_command cmd;
    (void)state;
    ct_run(r, 500);
    r->s.fault.delay_ms = 100;
    assert_xf(xf_client_external_track(&r->c, 1, 10, 10), XF_OK);
    ct_run(r, 500);
    xf_command_init(&cmd, XF_ORDER_EXTERNAL_TRACK);
    assert_status(ct_run_cmd(r, ct_submit_cmd(r, &cmd), 5000, &res), XF_CMD_OK);
    assert_true(res.elapsed_ms >= 100u); /* its own reply */
    ct_rig_free(r);
}

/* A link that stalls 1.3 s and then delivers what it held: the lost command's late "ok" is not
 * the retry's, even though the link went down in between. */
static void test_retry_after_stall(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_cmd_result res;
    (void)state;
    ct_run(r, 500);
    r->s.fault.delay_ms = 1300;
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 5000, &res), XF_CMD_LINK_LOST);
    r->s.fault.delay_ms = 0;
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_SHUTTER), 5000, &res), XF_CMD_OK);
    assert_int_equal(r->s.stats.photos, 2); /* the retry ran before its ok */
    ct_rig_free(r);
}

/* A command submitted after the application has not stepped for a while waits from the next
 * step, not from the old step's time. */
static void test_submit_after_a_pause(void **state)
{
    xf_client_config cc;
    ct_rig *r;
    uint32_t id, i;
    (void)state;
    xf_client_config_init(&cc);
    cc.down_ms = 5000; /* the pause is not a lost link */
    r = ct_rig_new(&cc, NULL);
    ct_run(r, 500);
    for (i = 0; i < 2100u; i++) { /* the simulator runs on; the client is not stepped */
        r->now++;
        (void)xf_sim_step(&r->s, r->now);
    }
    id = ct_submit(r, XF_ORDER_SHUTTER);
    (void)xf_client_step(&r->c, r->now);
    assert_true(xf_client_command_status(&r->c, id, NULL) != XF_CMD_TIMEOUT);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_rig_free(r);
}

static void test_reorder_no_false_ok(void **state)
{
    unsigned extra = 0, false_ok;
    (void)state;
    false_ok = nm_shutters(100, &extra); /* the bound covers the 60 ms of jitter */
    assert_int_equal(false_ok, 0);
    assert_int_equal(extra, 0); /* and the GCU ran each command once */
    /* the same link without the bound: the check above can fail */
    false_ok = nm_shutters(0, &extra);
    print_message("reorder_ms 0 on a reordering link: %u false ok, %u extra executions of 60\n", false_ok, extra);
    assert_true(false_ok > 0u || extra > 0u);
}

static void test_control_rule_every_case(void **state)
{
    static const uint8_t modes[] = {0x10, 0x11, 0x12, 0x13, 0x14, 0x16, 0x17, 0x1C, 0x42, CR_NO_REPLY};
    static const char kinds[] = {'-', 'r', 'a'};
    size_t m, k, i;
    (void)state;
    for (m = 0; m < sizeof(modes); m++) {
        for (k = 0; k < sizeof(kinds); k++) {
            for (i = 0; i < XF_ORDER_COUNT; i++) {
                cr_case(modes[m], kinds[k], xf_order_at(i)->order);
            }
        }
    }
}

/* The audit's case: Euler with angles (0, -45, 0), then click-to-aim. Its packets carry no
 * angles, and when the gimbal ends in head lock the angles are dropped, not read as rates; so are
 * rates set in head lock when a command switches to Euler. Angles set in head lock wait, and go
 * out once Euler is reported. */
static void test_control_mode_changes(void **state)
{
    ct_rig *r = rig_up(NULL, NULL);
    const xf_host_main *m = &r->s.host.main;
    xf_command aim;
    uint32_t id;
    (void)state;
    id = ct_submit(r, XF_ORDER_EULER);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 60);
    assert_int_equal(xf_client_set_angles(&r->c, 0.0f, -45.0f, 0.0f, r->now), XF_CTRL_SENT);
    ct_run(r, 40);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, XF_STATUS_CTRL_VALID);
    assert_int_equal(m->pitch_ctrl, -4500);
    ct_valid_command(&aim, XF_ORDER_CLICK_TO_AIM);
    assert_xf(xf_client_submit(&r->c, &aim, &id, NULL), XF_OK);
    ct_run(r, 21);
    assert_int_equal(r->s.host.order, XF_ORDER_CLICK_TO_AIM);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, 0);
    assert_int_equal(m->pitch_ctrl, 0);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 200);
    assert_int_equal(xf_client_telemetry(&r->c)->gimbal_mode, XF_MODE_HEAD_LOCK);
    assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_DROPPED);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, 0);
    /* rates in head lock, then a switch to Euler: dropped when the mode changes */
    assert_int_equal(xf_client_set_rates(&r->c, 0.0f, 10.0f, 0.0f, r->now), XF_CTRL_SENT);
    ct_run(r, 40);
    assert_int_equal(m->pitch_ctrl, 100);
    id = ct_submit(r, XF_ORDER_EULER);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 60);
    assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_DROPPED);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, 0);
    /* angles set in head lock wait for Euler */
    id = ct_submit(r, XF_ORDER_HEAD_LOCK);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 60);
    assert_int_equal(xf_client_set_angles(&r->c, 0.0f, -30.0f, 0.0f, r->now), XF_CTRL_WRONG_KIND);
    ct_run(r, 40);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, 0);
    id = ct_submit(r, XF_ORDER_EULER);
    assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
    ct_run(r, 60);
    assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_SENT);
    assert_int_equal(m->status & XF_STATUS_CTRL_VALID, XF_STATUS_CTRL_VALID);
    assert_int_equal(m->pitch_ctrl, -3000);
    xf_client_clear_control(&r->c);
    assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_NOT_SET);
    assert_int_equal(xf_client_control_status(NULL), XF_CTRL_NOT_SET);
    assert_int_equal(xf_client_set_rates(NULL, 0.0f, 0.0f, 0.0f, 0u), XF_CTRL_NOT_SET);
    ct_rig_free(r);
}

/* Rates are 0.1 deg/s divided by the main screen's zoom: camera 1's until the application says
 * camera 2 is on the main screen. */
static void test_rates_main_camera_zoom(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_gcu_packet g;
    xf_host_packet last;
    (void)state;
    r->sim_on = 0; /* the test is the GCU: head lock, camera 1 at 2x, camera 2 at 4x */
    memset(&g, 0, sizeof(g));
    g.version = 1;
    g.main.gimbal_mode = XF_MODE_HEAD_LOCK;
    g.sub.sub_header = XF_SUB_HEADER;
    g.sub.zoom_cam1 = 20;
    g.sub.zoom_cam2 = 40;
    ct_gcu_reply(r, &g);
    ct_run(r, 5);
    assert_int_equal(xf_client_set_rates(&r->c, 0.0f, 10.0f, -20.0f, r->now), XF_CTRL_SENT);
    (void)ct_drain_host(r, NULL);
    ct_run(r, 25);
    assert_int_equal(ct_drain_host(r, &last), 1);
    assert_int_equal(last.main.pitch_ctrl, 200); /* 10 deg/s: 100 raw at 1x, 200 at 2x (a unit is 0.05 deg/s) */
    assert_int_equal(last.main.yaw_ctrl, -400);
    xf_client_set_main_camera(&r->c, 2);
    ct_run(r, 20);
    assert_int_equal(ct_drain_host(r, &last), 1);
    assert_int_equal(last.main.pitch_ctrl, 400);
    assert_int_equal(last.main.yaw_ctrl, -800);
    xf_client_set_main_camera(&r->c, 7); /* not a camera: camera 1 */
    ct_run(r, 20);
    assert_int_equal(ct_drain_host(r, &last), 1);
    assert_int_equal(last.main.pitch_ctrl, 200);
    xf_client_set_main_camera(NULL, 2);
    ct_rig_free(r);
}

/* The pod status word's byte order, decided per GCU from the data, kept, and forced on demand. */
static void test_pod_order_per_gcu(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    xf_gcu_packet g;
    (void)state;
    r->sim_on = 0; /* the test is the GCU */
    memset(&g, 0, sizeof(g));
    g.version = 2;
    g.main.gimbal_mode = XF_MODE_HEAD_FOLLOW;
    g.main.pod_status = 0x0001u; /* bytes 01 00: tracking (LE) or ranging (BE): it does not tell */
    ct_gcu_reply(r, &g);
    ct_run(r, 5);
    assert_int_equal(xf_client_pod_order(&r->c), XF_POD_ORDER_UNDECIDED);
    assert_int_equal(xf_client_pod_flags(&r->c), XF_POD_TRACKING_OK); /* read as documented meanwhile */
    g.main.pod_status = 0x8001u; /* bytes 01 80, V2.0.6's example: only big-endian has no reserved bit */
    ct_gcu_reply(r, &g);
    ct_run(r, 5);
    assert_int_equal(r->c.tele.pod_status, 0x8001u); /* the raw word stays */
    assert_int_equal(xf_client_pod_order(&r->c), XF_POD_ORDER_BE);
    assert_int_equal(xf_client_pod_flags(&r->c), XF_POD_RANGING_ON | XF_POD_TARGET_VALID);
    g.main.pod_status = 0x0001u; /* again undecided: the order stays big-endian for this GCU */
    ct_gcu_reply(r, &g);
    ct_run(r, 5);
    assert_int_equal(xf_client_pod_order(&r->c), XF_POD_ORDER_BE);
    assert_int_equal(xf_client_pod_flags(&r->c), XF_POD_RANGING_ON);
    g.main.pod_status = 0x1001u; /* bytes 01 10 would decide little-endian, but the order is kept */
    ct_gcu_reply(r, &g);
    ct_run(r, 5);
    assert_int_equal(xf_client_pod_order(&r->c), XF_POD_ORDER_BE);
    xf_client_set_pod_order(&r->c, XF_POD_ORDER_LE); /* forced */
    assert_int_equal(xf_client_pod_order(&r->c), XF_POD_ORDER_LE);
    assert_int_equal(xf_client_pod_flags(&r->c), XF_POD_TRACKING_OK | XF_POD_UPWARD_MOUNT);
    g.main.pod_status = 0x8001u;
    ct_gcu_reply(r, &g);
    ct_run(r, 5);
    assert_int_equal(xf_client_pod_order(&r->c), XF_POD_ORDER_LE); /* forced stays */
    xf_client_set_pod_order(&r->c, XF_POD_ORDER_UNDECIDED);        /* automatic again: the last word decides */
    assert_int_equal(xf_client_pod_order(&r->c), XF_POD_ORDER_BE);
    assert_int_equal(xf_client_pod_flags(NULL), 0);
    assert_int_equal(xf_client_pod_order(NULL), XF_POD_ORDER_UNDECIDED);
    xf_client_set_pod_order(NULL, XF_POD_ORDER_LE);
    ct_rig_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_init_rates_and_args),
        cmocka_unit_test(test_rate_20hz_paces_packets),
        cmocka_unit_test(test_null_packets_by_default),
        cmocka_unit_test(test_two_shutters_null_between),
        cmocka_unit_test(test_replies_in_pieces),
        cmocka_unit_test(test_feedback_in_later_reply),
        cmocka_unit_test(test_failing_camera_mask),
        cmocka_unit_test(test_dropped_replies_retry_then_timeout),
        cmocka_unit_test(test_stale_reply_guard),
        cmocka_unit_test(test_stale_reply_guard_queued),
        cmocka_unit_test(test_state_once),
        cmocka_unit_test(test_calibration_operating_then_ok),
        cmocka_unit_test(test_calibration_operating_then_failed),
        cmocka_unit_test(test_calibration_operating_timeout),
        cmocka_unit_test(test_queue_full_busy),
        cmocka_unit_test(test_ids_skip_zero),
        cmocka_unit_test(test_results_ring),
        cmocka_unit_test(test_cancel_all),
        cmocka_unit_test(test_submit_range_errors),
        cmocka_unit_test(test_link_transitions),
        cmocka_unit_test(test_link_lost_fails_commands),
        cmocka_unit_test(test_reopened_transport_down_until_reply),
        cmocka_unit_test(test_health_figures),
        cmocka_unit_test(test_replies_missing_exact),
        cmocka_unit_test(test_transport_closed_flag),
        cmocka_unit_test(test_telemetry_and_ages),
        cmocka_unit_test(test_telemetry_convert),
        cmocka_unit_test(test_wire_agrees_with_the_codec),
        cmocka_unit_test(test_protocol_v2_rates),
        cmocka_unit_test(test_protocol_v2_orders),
        cmocka_unit_test(test_submit_model_support),
        cmocka_unit_test(test_gcu_version_decides),
        cmocka_unit_test(test_control_rule_every_case),
        cmocka_unit_test(test_start_waits_for_null_reply),
        cmocka_unit_test(test_unsynced_command_times_out),
        cmocka_unit_test(test_reorder_no_false_ok),
        cmocka_unit_test(test_late_replies_not_taken),
        cmocka_unit_test(test_guard_two_orders),
        cmocka_unit_test(test_sim_delay_queue_keeps_commands),
        cmocka_unit_test(test_settled_needs_evidence),
        cmocka_unit_test(test_stream_and_waiting_commands),
        cmocka_unit_test(test_track_command_while_streaming),
        cmocka_unit_test(test_retry_after_stall),
        cmocka_unit_test(test_submit_after_a_pause),
        cmocka_unit_test(test_control_mode_changes),
        cmocka_unit_test(test_rates_main_camera_zoom),
        cmocka_unit_test(test_pod_order_per_gcu),
        cmocka_unit_test(test_carrier_only_while_fresh),
        cmocka_unit_test(test_gnss_only_while_fresh),
        cmocka_unit_test(test_watchdog_zeroes_rates),
        cmocka_unit_test(test_watchdog_off),
        cmocka_unit_test(test_rates_scaled_by_zoom),
        cmocka_unit_test(test_head_lock_rates_integrate),
        cmocka_unit_test(test_euler_reaches_target),
        cmocka_unit_test(test_orthoview_points_down),
        cmocka_unit_test(test_fpv_follows_carrier),
        cmocka_unit_test(test_external_track_stream_and_stop),
        cmocka_unit_test(test_external_track_stop_not_resolved_by_stream),
        cmocka_unit_test(test_external_track_stop_busy_changes_nothing),
        cmocka_unit_test(test_external_track_stop_success),
        cmocka_unit_test(test_clock_wrap),
        cmocka_unit_test(test_cb_submit_from_on_result),
        cmocka_unit_test(test_cb_cancel_all_from_on_result),
        cmocka_unit_test(test_cb_step_is_busy),
        cmocka_unit_test(test_cb_resubmit_during_link_lost_sweep),
        cmocka_unit_test(test_cb_resubmit_during_cancel_all),
        cmocka_unit_test(test_cb_nested_sweeps),
        cmocka_unit_test(test_cb_read_state),
        cmocka_unit_test(test_cb_set_inputs),
        cmocka_unit_test(test_tap_own_clock),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
