/*
 * test_client_control.c - control quantities, against the simulator over an
 * in-memory link on a fake clock (client_test.h): rates scaled by the main
 * screen's zoom, angles per mode (head lock, Euler, orthoview, FPV), which
 * quantities go out in each reported mode and during which orders
 * (xf_ctrl_status), setpoints dropped when the mode changes.
 */
#include "client_test.h"

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

/* Camera 2 on the main screen, at 4x, camera 1 at 1x: the client and the GCU both divide by the
 * main screen's zoom, so the gimbal turns as asked; a client that scales by the other camera's
 * zoom turns it four times too fast. */
static void test_rates_main_screen_end_to_end(void **state)
{
    xf_sim_config sc;
    ct_rig *r;
    const xf_telemetry *t;
    xf_command cmd;
    uint32_t i;
    (void)state;
    xf_sim_config_init(&sc);
    sc.main_camera = 2;
    r = rig_up(NULL, &sc);
    t = xf_client_telemetry(&r->c);
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.cameras = XF_CAM2;
    cmd.zoom = xf_zoom_to_rate_raw(4.0f);
    assert_status(ct_run_cmd(r, ct_submit_cmd(r, &cmd), 1000, NULL), XF_CMD_OK);
    for (i = 0; i < 5000u && t->zoom_cam2 != 40u; i++) {
        ct_tick(r);
    }
    assert_int_equal(t->zoom_cam2, 40);
    assert_int_equal(t->zoom_cam1, 10);
    xf_client_set_main_camera(&r->c, 2);
    xf_client_set_rates(&r->c, 0.0f, 0.0f, 5.0f, r->now);
    ct_run(r, 60);
    assert_int_equal(r->s.host.main.yaw_ctrl, 200); /* 5 deg/s at 4x */
    assert_near(r->s.rate[2], 5.0, 0.01);
    xf_client_set_main_camera(&r->c, 1); /* the client says camera 1: wrong for this GCU */
    xf_client_set_rates(&r->c, 0.0f, 0.0f, 5.0f, r->now);
    ct_run(r, 60);
    assert_int_equal(r->s.host.main.yaw_ctrl, 50);
    assert_near(r->s.rate[2], 1.25, 0.01);
    ct_rig_free(r);
}

/* The client sends no control quantities after a mode change until the application sets them
 * again (its setpoint is dropped); the GCU holds meanwhile (V2.0.6: desired angles keep their
 * value), in every angle mode it is switched to, so the gimbal does not swing away. */
static void test_mode_change_holds(void **state)
{
    static const uint8_t to[] = {XF_ORDER_ANGLE_CONTROL, XF_ORDER_FPV, XF_ORDER_EULER, XF_ORDER_ANGLE_CONTROL};
    xf_client_config cc;
    xf_sim_config sc;
    ct_rig *r;
    const xf_telemetry *t;
    xf_carrier car;
    size_t k;
    int i;
    (void)state;
    xf_client_config_init(&cc);
    cc.protocol_version = 2;
    xf_sim_config_init(&sc);
    sc.version = 2;
    r = rig_up(&cc, &sc);
    t = xf_client_telemetry(&r->c);
    memset(&car, 0, sizeof(car));
    car.pitch_deg = 4.0f;
    car.yaw_deg = 45.0f;
    xf_client_set_carrier(&r->c, &car, r->now);
    assert_status(ct_run_cmd(r, ct_submit(r, XF_ORDER_EULER), 1000, NULL), XF_CMD_OK);
    ct_run(r, 60);
    assert_int_equal(xf_client_set_angles(&r->c, 0.0f, -30.0f, 90.0f, r->now), XF_CTRL_SENT);
    for (i = 0; i < 30; i++) {
        xf_client_set_carrier(&r->c, &car, r->now);
        ct_run(r, 50);
    }
    assert_near(xf_cdeg(t->cam_pitch), -30.0, 0.011);
    for (k = 0; k < sizeof(to); k++) {
        assert_status(ct_run_cmd(r, ct_submit(r, to[k]), 1000, NULL), XF_CMD_OK);
        for (i = 0; i < 20; i++) {
            xf_client_set_carrier(&r->c, &car, r->now);
            ct_run(r, 50);
        }
        assert_int_equal(r->s.host.main.status & XF_STATUS_CTRL_VALID, 0);
        assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_DROPPED);
        assert_near(xf_cdeg(t->cam_pitch), -30.0, 0.011);
        assert_angle_near(xf_cdeg(t->cam_yaw), 90.0, 0.011);
        assert_near(xf_cdeg(t->rel_angle_z), 45.0, 0.011);
    }
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
    assert_angle_near(r->s.yaw, y0 - 20.0f, 1.0);
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
    xf_client_config cc;
    ct_rig *r;
    xf_host_packet last;
    xf_command cmd;
    xf_ctrl_status st = XF_CTRL_NOT_SET;
    int holds = order == XF_ORDER_NEUTRAL || order == XF_ORDER_TRACK || order == XF_ORDER_CLICK_TO_AIM ||
                order == XF_ORDER_GAZE_GEO;
    int sets_mode = (xf_order_lookup(order)->flags & XF_ORDER_SETS_MODE) != 0u; /* the new mode reads them */
    int want = kind != '-' && !holds && !sets_mode && cr_reads(mode) == kind;
    /* with no reply yet, no reply to a null either: the command waits, nulls go out */
    uint8_t sent = (mode == CR_NO_REPLY) ? (uint8_t)XF_ORDER_NULL : order;
    size_t n;
    xf_client_config_init(&cc);
    cc.reorder_fixed = 1; /* the test answers before the first packet: no link to judge, no bound of the client's */
    r = ct_rig_new(&cc, NULL);
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
    } else if (sets_mode && kind != '-' && sent == order) {
        assert_int_equal(xf_client_control_status(&r->c), XF_CTRL_COMMAND); /* not yet on the wire: kept */
    }
    ct_rig_free(r);
}

/* Every reported mode x every setpoint kind x every order, on the packets actually sent. */
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_control_rule_every_case),      cmocka_unit_test(test_control_mode_changes),
        cmocka_unit_test(test_rates_main_camera_zoom),       cmocka_unit_test(test_rates_scaled_by_zoom),
        cmocka_unit_test(test_rates_main_screen_end_to_end), cmocka_unit_test(test_mode_change_holds),
        cmocka_unit_test(test_head_lock_rates_integrate),    cmocka_unit_test(test_euler_reaches_target),
        cmocka_unit_test(test_orthoview_points_down),        cmocka_unit_test(test_fpv_follows_carrier),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
