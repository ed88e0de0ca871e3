/*
 * test_client_version.c - the GCU's protocol version and model, against the
 * simulator over an in-memory link on a fake clock (client_test.h): V0.2
 * units and orders, meaning that follows the version the GCU speaks, orders
 * its model does not support.
 */
#include "client_test.h"

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

/* ---- the version the GCU answers (version_auto) ---------------------------------------- */

/* A client with version_auto against a simulator that answers only @p gcu (and replies in it),
 * trying @p first first. */
static ct_rig *auto_rig(uint8_t first, uint8_t gcu)
{
    xf_client_config cc;
    xf_sim_config sc;
    xf_client_config_init(&cc);
    cc.protocol_version = first;
    cc.version_auto = 1;
    xf_sim_config_init(&sc);
    sc.version = gcu;
    sc.answer_only = gcu;
    return ct_rig_new(&cc, &sc);
}

/* A GCU that answers only version 1 and one that answers only version 2: the client finds either,
 * from either first guess, within stale_ms of trying the wrong one, says which answered, sends it
 * from then on, and follows the GCU's version (pip mode 3 is V0.2's, palette 50 V0.1's). */
static void test_auto_version_finds_it(void **state)
{
    static const uint8_t cases[][2] = {{1, 1}, {1, 2}, {2, 1}, {2, 2}}; /* first tried, the GCU's */
    size_t k;
    (void)state;
    for (k = 0; k < 4u; k++) {
        ct_rig *r = auto_rig(cases[k][0], cases[k][1]);
        const xf_health *h = xf_client_health(&r->c);
        uint8_t gcu = cases[k][1];
        uint32_t t0 = r->now, id = 0;
        xf_command cmd;
        assert_int_equal(xf_client_answered_version(&r->c), 0);
        assert_int_equal(h->version_sent, cases[k][0]);
        assert_true(ct_run_link(r, XF_LINK_UP, 1000));
        /* the right guess answers within a packet; a wrong one costs stale_ms (250) and a packet */
        assert_true(r->now - t0 <= (cases[k][0] == gcu ? 2u : 250u + 2u * 20u + 2u));
        ct_run(r, 20);
        assert_int_equal(xf_client_answered_version(&r->c), gcu);
        assert_int_equal(h->version_answered, gcu);
        assert_int_equal(h->version_sent, gcu);
        assert_int_equal(xf_client_gcu_version(&r->c), gcu);
        assert_int_equal(r->s.stats.ignored, cases[k][0] == gcu ? 0u : 13u); /* the wrong guess's packets */
        xf_command_init(&cmd, gcu == 2u ? XF_ORDER_PIP : XF_ORDER_PALETTE);
        cmd.value = gcu == 2u ? 3u : 50u;
        assert_xf(xf_client_submit(&r->c, &cmd, &id, NULL), XF_OK);
        assert_status(ct_run_cmd(r, id, 1000, NULL), XF_CMD_OK);
        ct_run(r, 200);
        assert_int_equal(r->s.host.version, gcu);
        assert_int_equal(r->s.stats.ignored, cases[k][0] == gcu ? 0u : 13u); /* none since */
        ct_rig_free(r);
    }
}

/* It keeps the version that was answered while the link is up, also through a silence that makes
 * the link stale; once the link has gone down it looks again, from that version, and finds it. */
static void test_auto_version_sticks(void **state)
{
    ct_rig *r = auto_rig(1, 2);
    const xf_health *h = xf_client_health(&r->c);
    uint32_t ignored;
    (void)state;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    r->s.fault.silent = 1;
    assert_true(ct_run_link(r, XF_LINK_STALE, 1000));
    ct_run(r, 500); /* stale, not down */
    assert_int_equal(xf_client_link(&r->c), XF_LINK_STALE);
    assert_int_equal(h->version_sent, 2);
    assert_int_equal(h->version_answered, 2);
    assert_true(ct_run_link(r, XF_LINK_DOWN, 1000));
    assert_int_equal(h->version_answered, 0); /* looking again */
    ct_run(r, 240);
    assert_int_equal(h->version_sent, 2); /* from the version that was answered */
    ct_run(r, 40);
    assert_int_equal(h->version_sent, 1); /* then the other */
    ignored = r->s.stats.ignored;
    r->s.fault.silent = 0;
    assert_true(ct_run_link(r, XF_LINK_UP, 1000));
    assert_int_equal(xf_client_answered_version(&r->c), 2);
    assert_true(r->s.stats.ignored > ignored);
    ct_rig_free(r);
}

/* Without version_auto a client that sends version 1 gets no answer from a GCU that answers only
 * version 2, and says nothing was answered; and version_auto takes 0 or 1. */
static void test_fixed_version_unanswered(void **state)
{
    xf_client_config cc;
    xf_sim_config sc;
    ct_rig *r;
    xf_client c;
    (void)state;
    xf_sim_config_init(&sc);
    sc.version = 2;
    sc.answer_only = 2;
    r = ct_rig_new(NULL, &sc);
    assert_false(ct_run_link(r, XF_LINK_UP, 2000));
    assert_int_equal(xf_client_answered_version(&r->c), 0);
    assert_int_equal(xf_client_health(&r->c)->version_sent, 1);
    assert_int_equal(r->s.stats.ignored, 100);
    xf_client_config_init(&cc);
    assert_int_equal(cc.version_auto, 0);
    cc.version_auto = 2;
    assert_xf(xf_client_init(&c, &r->host_hal, &cc), XF_ERR_RANGE);
    assert_non_null(strstr(xf_client_config_problem(&cc), "version_auto"));
    assert_int_equal(xf_client_answered_version(NULL), 0);
    ct_rig_free(r);
}

/* A command submitted before the GCU has answered is checked for the version guessed then; when it
 * would start, the GCU has answered, and one whose parameters are out of range or mean something
 * else in the GCU's version ends as refused, never sent; the OSD helper's value is set for the
 * GCU's version; the others run. @p first: the version guessed (with version_auto, and without:
 * the configured one), @p gcu: the GCU's. */
static void run_queued_early(uint8_t first, uint8_t gcu, int version_auto)
{
    xf_client_config cc;
    xf_sim_config sc;
    ct_rig *r;
    xf_command cmd;
    uint32_t bad_value, osd_raw, osd_hide, shutter, both;
    size_t i;
    xf_client_config_init(&cc);
    cc.protocol_version = first;
    cc.version_auto = (uint8_t)version_auto;
    xf_sim_config_init(&sc);
    sc.version = gcu;
    sc.answer_only = version_auto ? gcu : 0u;
    r = ct_rig_new(&cc, &sc);
    /* before the first step: checked for the first guess */
    xf_command_init(&cmd, (first == 1u) ? XF_ORDER_PALETTE : XF_ORDER_PIP);
    cmd.value = (first == 1u) ? 50u : 3u; /* palette 50: V0.1 only; pip 3: V0.2 only */
    bad_value = ct_submit_cmd(r, &cmd);
    xf_command_init(&cmd, XF_ORDER_OSD);
    cmd.value = xf_osd_value(1, first); /* "show" in the first guess: "hide" in the other version */
    osd_raw = ct_submit_cmd(r, &cmd);
    assert_xf(xf_client_osd(&r->c, 0, &osd_hide), XF_OK);
    shutter = ct_submit(r, XF_ORDER_SHUTTER);
    xf_command_init(&cmd, XF_ORDER_PALETTE);
    cmd.value = 5; /* valid in both, the same meaning */
    both = ct_submit_cmd(r, &cmd);
    assert_status(ct_run_cmd(r, both, 3000, NULL), XF_CMD_OK);
    assert_int_equal(xf_client_gcu_version(&r->c), gcu);
    assert_status(xf_client_command_status(&r->c, bad_value, NULL), XF_CMD_REFUSED);
    assert_status(xf_client_command_status(&r->c, osd_raw, NULL), XF_CMD_REFUSED);
    assert_status(xf_client_command_status(&r->c, osd_hide, NULL), XF_CMD_OK);
    assert_status(xf_client_command_status(&r->c, shutter, NULL), XF_CMD_OK);
    assert_non_null(ct_result_of(&r->log, bad_value));
    assert_int_equal(ct_result_of(&r->log, bad_value)->status, XF_CMD_REFUSED);
    assert_int_equal(ct_result_of(&r->log, bad_value)->packets, 0);
    /* on the wire: the refused ones never, the OSD once, as "hide" in the GCU's version */
    assert_int_equal(r->s.stats.executed[XF_ORDER_OSD], 1);
    assert_int_equal(r->s.camera_status & XF_CAMERA_OSD_ON, 0);
    assert_int_equal(r->s.stats.executed[XF_ORDER_PIP], 0);
    print_message("case %u %u %d: palette %u\n", first, gcu, version_auto,
                  (unsigned)r->s.stats.executed[XF_ORDER_PALETTE]);
    for (i = 0; i < r->log.n_sent; i++)
        print_message(" %02x", r->log.sent_order[i]);
    print_message("\n");
    assert_int_equal(r->s.stats.executed[XF_ORDER_PALETTE], 1);
    assert_int_equal(r->s.stats.photos, 1);
    for (i = 0; i < r->log.n_sent; i++) {
        assert_true(r->log.sent_order[i] != XF_ORDER_PIP);
    }
    assert_string_equal(xf_cmd_status_name(XF_CMD_REFUSED), "refused");
    ct_rig_free(r);
}

static void test_queued_before_version_known(void **state)
{
    (void)state;
    run_queued_early(1, 2, 1); /* version_auto, a wrong first guess either way */
    run_queued_early(2, 1, 1);
    run_queued_early(1, 2, 0); /* configured for V0.1, the GCU speaks V0.2 */
    run_queued_early(2, 1, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_protocol_v2_rates),        cmocka_unit_test(test_protocol_v2_orders),
        cmocka_unit_test(test_submit_model_support),     cmocka_unit_test(test_gcu_version_decides),
        cmocka_unit_test(test_auto_version_finds_it),    cmocka_unit_test(test_auto_version_sticks),
        cmocka_unit_test(test_fixed_version_unanswered), cmocka_unit_test(test_queued_before_version_known),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
