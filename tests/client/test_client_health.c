/*
 * test_client_health.c - link health and the rate watchdog, against the
 * simulator over an in-memory link on a fake clock (client_test.h): link
 * states and their callbacks, commands lost with the link, a reopened
 * transport, the health figures, zero rates when the application stalls.
 */
#include "client_test.h"

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
    ct_rig_free(r);
}

/* Every link state's and command status's name, each by its enumerator: the names are packed
 * texts in the enum's order, so one out of place or missing shows here. */
static void test_state_names(void **state)
{
    static const struct {
        xf_cmd_status s;
        const char *name;
    } cmd[] = {{XF_CMD_UNKNOWN, "unknown"},
               {XF_CMD_QUEUED, "queued"},
               {XF_CMD_SENDING, "sending"},
               {XF_CMD_OPERATING, "operating"},
               {XF_CMD_OK, "ok"},
               {XF_CMD_FAILED, "failed"},
               {XF_CMD_TIMEOUT, "timeout"},
               {XF_CMD_LINK_LOST, "link lost"},
               {XF_CMD_CANCELLED, "cancelled"},
               {XF_CMD_REFUSED, "refused"}};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(cmd) / sizeof(cmd[0]); i++) {
        assert_string_equal(xf_cmd_status_name(cmd[i].s), cmd[i].name);
    }
    assert_string_equal(xf_cmd_status_name((xf_cmd_status)(XF_CMD_REFUSED + 1)), "unknown");
    assert_string_equal(xf_link_state_name(XF_LINK_DOWN), "down");
    assert_string_equal(xf_link_state_name(XF_LINK_STALE), "stale");
    assert_string_equal(xf_link_state_name(XF_LINK_UP), "up");
    assert_string_equal(xf_link_state_name((xf_link_state)(XF_LINK_UP + 1)), "down");
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

/* A read that says it copied more than it was asked for is the link's error, to the client and
 * to the simulator, and none of it is read: past the buffer there is nothing to read. The
 * client's packet due still goes; the next step reads again. */
static void test_overlong_read(void **state)
{
    ct_rig *r = ct_rig_new(NULL, NULL);
    (void)state;
    assert_true(ct_run_link(r, XF_LINK_UP, 100));
    r->host.overread = 1;
    {
        uint32_t bytes = xf_client_parser_stats(&r->c)->bytes_in, sent = r->c.health.packets_sent;
        uint32_t replies = r->c.health.replies;
        r->now += 20u;
        assert_xf(xf_client_step(&r->c, r->now), XF_ERR_IO);
        assert_int_equal(xf_client_parser_stats(&r->c)->bytes_in, bytes);
        assert_int_equal(r->c.health.packets_sent, sent + 1u);
        r->host.overread = 0;
        ct_run(r, 100); /* reading again, and nothing of the broken read taken for a reply */
        assert_true(r->c.health.replies > replies);
        assert_int_equal(xf_client_parser_stats(&r->c)->crc_errors, 0);
        assert_int_equal(xf_client_parser_stats(&r->c)->bytes_skipped, 0);
    }
    r->gcu.overread = 1; /* the simulator's link alike */
    {
        uint32_t bytes = r->s.parser.stats.bytes_in, packets = r->s.stats.packets_in;
        assert_xf(xf_sim_step(&r->s, r->now), XF_ERR_IO);
        assert_int_equal(r->s.parser.stats.bytes_in, bytes);
        r->gcu.overread = 0;
        ct_run(r, 100);
        assert_true(r->s.stats.packets_in > packets);
        assert_int_equal(r->s.parser.stats.crc_errors, 0);
    }
    ct_rig_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_link_transitions),
        cmocka_unit_test(test_state_names),
        cmocka_unit_test(test_link_lost_fails_commands),
        cmocka_unit_test(test_reopened_transport_down_until_reply),
        cmocka_unit_test(test_health_figures),
        cmocka_unit_test(test_replies_missing_exact),
        cmocka_unit_test(test_transport_closed_flag),
        cmocka_unit_test(test_watchdog_zeroes_rates),
        cmocka_unit_test(test_watchdog_off),
        cmocka_unit_test(test_overlong_read),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
