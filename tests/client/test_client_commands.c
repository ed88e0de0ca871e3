/*
 * test_client_commands.c - how the client runs commands, against the
 * simulator over an in-memory link on a fake clock (client_test.h): the
 * configuration it accepts, null packets by default, a command sent until a
 * reply carries its state and then a null, feedback late, once or failing,
 * timeouts, calibration's operating phase, the queue, ids and results, the
 * 32-bit clock wrap.
 */
#include "client_test.h"

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
        assert_string_equal(xf_client_config_problem(&cfg), "rate_hz: 1..200"); /* the first line, whole */
    }
    xf_client_config_init(&cfg);
    cfg.protocol_version = 0;
    assert_xf(xf_client_init(&c, &hal, &cfg), XF_ERR_RANGE);
    assert_true(strncmp(xf_client_config_problem(&cfg), "protocol_version, ", 18) == 0);
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

/* The first case: two shutters in a row run twice, a null between. */
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
        cmocka_unit_test(test_clock_wrap),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
