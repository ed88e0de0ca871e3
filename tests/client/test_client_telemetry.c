/*
 * test_client_telemetry.c - what the client reads and what it sends besides
 * commands, against the simulator over an in-memory link on a fake clock
 * (client_test.h): telemetry and its timestamps, its units, packets and
 * telemetry checked against the codec, carrier and GNSS data only while
 * fresh, the pod status word's byte order.
 */
#include "client_test.h"

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
        /* what the replies say */
        cmocka_unit_test(test_telemetry_and_ages),
        cmocka_unit_test(test_telemetry_convert),
        cmocka_unit_test(test_wire_agrees_with_the_codec),
        cmocka_unit_test(test_pod_order_per_gcu),
        /* what goes out besides commands */
        cmocka_unit_test(test_carrier_only_while_fresh),
        cmocka_unit_test(test_gnss_only_while_fresh),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
