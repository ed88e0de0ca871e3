/*
 * test_sim_v206.c - the simulated GCU as V2.0.6 describes a GCU, on the wire
 * (xf_sim_process: host packets in, replies out): commands read in its own
 * version; desired angles that hold while the control quantities are
 * invalid, in every angle mode; relative angles that do not follow the
 * carrier data of one packet; the failure state 0x02 of the orders only
 * camera 2 takes; rates divided by the main screen's zoom; the strict
 * reading of what V2.0.6 leaves open, told to on_note; a simulator that
 * answers one version only.
 */
#include "client_test.h"
#include "sim_fx.h"

/* What on_note was told. */
typedef struct notes {
    size_t n;
    xf_sim_note last;
} notes;

static void on_note(void *user, const xf_sim_note *note)
{
    notes *k = (notes *)user;
    k->n++;
    k->last = *note;
}

static sim_fx *fx_version(uint8_t version, notes *k)
{
    xf_sim_config cfg;
    xf_sim_config_init(&cfg);
    cfg.version = version;
    cfg.on_note = on_note;
    cfg.user = k;
    return fx_new(&cfg);
}

/* One raw host packet: @p order with @p len parameter bytes @p params, in @p version; the reply in @p r. */
static void send_raw(sim_fx *f, uint8_t version, uint8_t order, const uint8_t *params, uint8_t len, xf_gcu_packet *r)
{
    xf_host_packet p;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t n = 0;
    xf_host_packet_init(&p, version);
    p.order = order;
    memcpy(p.params, params, len);
    p.params_len = len;
    assert_xf(xf_host_pack(&p, buf, sizeof(buf), &n), XF_OK);
    send_bytes(f, buf, n, r);
}

/* ---- the simulator's own version ------------------------------------------------------- */

/* A V0.2 simulator reads a command in V0.2 whatever version byte the host sends (pip mode 3 is
 * V0.2's, palette 50 is beyond V0.2's 0..10), and a V0.1 one in V0.1. */
static void test_commands_in_own_version(void **state)
{
    notes k;
    sim_fx *f;
    xf_gcu_packet r;
    uint8_t pip3 = 3, palette50[2] = {XF_CAM2, 50};
    (void)state;
    memset(&k, 0, sizeof(k));
    f = fx_version(2, &k);
    send_raw(f, 1, XF_ORDER_PIP, &pip3, 1, &r);
    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    assert_int_equal(f->s.camera_status & XF_CAMERA_PIP_MASK, 3);
    send_raw(f, 1, XF_ORDER_PALETTE, palette50, 2, &r);
    assert_int_equal(r.params[0], XF_CAM2); /* failed: out of V0.2's range, failure 0x02 */
    assert_int_equal(k.n, 1);
    assert_int_equal(k.last.question, XF_SIM_Q_RANGE);
    assert_int_equal(k.last.order, XF_ORDER_PALETTE);
    free(f);
    memset(&k, 0, sizeof(k));
    f = fx_version(1, &k);
    send_raw(f, 2, XF_ORDER_PALETTE, palette50, 2, &r); /* a V0.2 host, a V0.1 GCU: 0..100 */
    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
    send_raw(f, 2, XF_ORDER_PIP, &pip3, 1, &r); /* V0.1's pip takes 0 only */
    assert_int_equal(r.params[0], XF_STATE_FAILURE);
    assert_int_equal(k.last.question, XF_SIM_Q_RANGE);
    assert_int_equal(f->s.stats.strict, 1);
    free(f);
}

/* ---- desired angles hold while the control quantities are invalid ----------------------- */

/* ArduPilot's frames: an angle frame (INS and control valid: the carrier's attitude, the desired
 * angles) and, between two, a camera command frame with no carrier data at all (bytes 5-68 zero:
 * status 0, no sub frame request). @p cmd NULL: the angle frame. */
static void ap_frame(sim_fx *f, uint8_t version, const xf_command *cmd, const int16_t want[3], xf_gcu_packet *r)
{
    xf_host_packet p;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t n = 0;
    xf_host_packet_init(&p, version);
    if (cmd != NULL) {
        memset(&p.main, 0, sizeof(p.main)); /* sub_request too */
        assert_xf(xf_host_set_command(&p, cmd, NULL), XF_OK);
    } else {
        p.main.status = XF_STATUS_INS_VALID | XF_STATUS_CTRL_VALID;
        p.main.carrier_roll = 1050;
        p.main.carrier_pitch = -525;
        p.main.carrier_yaw = 25000;
        p.main.roll_ctrl = want[0];
        p.main.pitch_ctrl = want[1];
        p.main.yaw_ctrl = want[2];
    }
    assert_xf(xf_host_pack(&p, buf, sizeof(buf), &n), XF_OK);
    f->now += 20;
    send_bytes(f, buf, n, r);
}

/* The attitude a reply reports: camera roll, pitch, yaw, relative x, y, z, raw. */
static void attitude(const xf_gcu_packet *r, int32_t a[6])
{
    a[0] = r->main.cam_roll;
    a[1] = r->main.cam_pitch;
    a[2] = r->main.cam_yaw;
    a[3] = r->main.rel_angle_x;
    a[4] = r->main.rel_angle_y;
    a[5] = r->main.rel_angle_z;
}

static void assert_attitude(const xf_gcu_packet *r, const int32_t want[6], const char *what)
{
    int32_t a[6];
    int i;
    attitude(r, a);
    for (i = 0; i < 6; i++) {
        if (a[i] != want[i]) {
            print_error("%s: attitude member %d is %d, was %d\n", what, i, (int)a[i], (int)want[i]);
            fail();
        }
    }
}

/*
 * The interop trial's case: in every angle mode, angle frames with camera command frames between
 * them (status 0, zero carrier data) leave the attitude where it is, relative angles included, and
 * a second of frames with the control quantities invalid does not move the gimbal. Then one valid
 * frame sets a new target and invalid frames follow: the desired angles keep that value, and the
 * gimbal gets there.
 */
static void test_angles_hold_while_invalid(void **state)
{
    static const struct {
        uint8_t version, order;
        float pitch; /* where pitch -30 ends: V0.1's angle control and FPV add the carrier's -5.25 */
    } modes[] = {{1, XF_ORDER_ANGLE_CONTROL, -35.25f},
                 {2, XF_ORDER_ANGLE_CONTROL, -30.0f},
                 {2, XF_ORDER_FPV, -35.25f},
                 {1, XF_ORDER_EULER, -30.0f},
                 {2, XF_ORDER_EULER, -30.0f}};
    static const int16_t target[3] = {0, -3000, 4500}, level[3] = {0, 0, 4500};
    size_t m;
    int i;
    (void)state;
    for (m = 0; m < sizeof(modes) / sizeof(modes[0]); m++) {
        notes k;
        sim_fx *f;
        xf_gcu_packet r;
        xf_command mode, shutter;
        int32_t held[6];
        memset(&k, 0, sizeof(k));
        f = fx_version(modes[m].version, &k);
        xf_command_init(&mode, modes[m].order);
        xf_command_init(&shutter, XF_ORDER_SHUTTER);
        ap_frame(f, modes[m].version, &mode, NULL, &r);
        assert_int_equal(r.params[0], XF_STATE_SUCCESS);
        for (i = 0; i < 150; i++) { /* 3 s: there */
            ap_frame(f, modes[m].version, NULL, target, &r);
        }
        assert_near(xf_cdeg(r.main.cam_pitch), modes[m].pitch, 0.011);
        attitude(&r, held);
        for (i = 0; i < 20; i++) { /* a command between angle frames, as ArduPilot sends them */
            ap_frame(f, modes[m].version, (i % 4 == 0) ? &shutter : &mode, NULL, &r);
            assert_attitude(&r, held, "a command frame");
            ap_frame(f, modes[m].version, NULL, target, &r);
            assert_attitude(&r, held, "the angle frame after it");
        }
        for (i = 0; i < 50; i++) { /* a second of command frames only */
            ap_frame(f, modes[m].version, &shutter, NULL, &r);
        }
        assert_attitude(&r, held, "a second without valid control quantities");
        ap_frame(f, modes[m].version, NULL, level, &r); /* one valid frame: pitch 0 */
        for (i = 0; i < 100; i++) {
            ap_frame(f, modes[m].version, &shutter, NULL, &r);
        }
        assert_near(xf_cdeg(r.main.cam_pitch), modes[m].pitch + 30.0f, 0.011); /* held at its new value */
        assert_int_equal(k.n, 0);
        free(f);
    }
}

/* Relative angles come from the motors' encoders (V2.0.6), not from the carrier data of the
 * packet: in head lock, a packet without INS data changes neither them nor the absolute angles. */
static void test_relative_angles_from_encoders(void **state)
{
    sim_fx *f = fx_new(NULL);
    xf_gcu_packet r;
    int32_t held[6];
    int i;
    (void)state;
    for (i = 0; i < 10; i++) {
        f->now += 20;
        send_carrier(f, NULL, 25000, 0, &r); /* the carrier heads 250 deg */
    }
    assert_near(xf_cdeg(r.main.rel_angle_z), 110.0, 0.011); /* the camera heads 0: 110 deg from the carrier */
    attitude(&r, held);
    f->now += 20;
    send_order(f, 1, XF_ORDER_NULL, &r); /* no INS data */
    assert_attitude(&r, held, "a packet without carrier data");
    f->now += 20;
    send_order(f, 1, XF_ORDER_SHUTTER, &r);
    assert_attitude(&r, held, "a command without carrier data");
    f->now += 20;
    send_carrier(f, NULL, 26000, 0, &r); /* the carrier turns 10 deg: the camera holds, the motor turns */
    assert_near(xf_cdeg(r.main.rel_angle_z), 100.0, 0.011);
    assert_near(xf_cdeg(r.main.cam_yaw), 0.0, 0.011);
    free(f);
}

/* ---- failures of the orders only camera 2 takes -------------------------------------------- */

/* Palette and the four thermometry orders fail with 0x02 (V2.0.6), whether the model lacks them
 * or the mask asks for another camera than 2; an NN order fails with the cameras asked. */
static void test_camera2_orders_fail_0x02(void **state)
{
    static const uint8_t camera2[] = {XF_ORDER_PALETTE, XF_ORDER_AREA_TEMP, XF_ORDER_TEMP_ALARM, XF_ORDER_ISOTHERM,
                                      XF_ORDER_SPOT_TEMP};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(camera2); i++) {
        notes k;
        xf_sim_config cfg;
        sim_fx *f;
        xf_command cmd;
        xf_gcu_packet r;
        memset(&k, 0, sizeof(k));
        xf_sim_config_init(&cfg);
        cfg.version = 2;
        cfg.gimbal_code = 59; /* Z-9B_V4(V): palette, no thermometry */
        cfg.on_note = on_note;
        cfg.user = &k;
        f = fx_new(&cfg);
        ct_valid_command(&cmd, camera2[i]);
        send_cmd(f, 2, &cmd, &r);
        assert_int_equal(r.params[0], camera2[i] == XF_ORDER_PALETTE ? XF_STATE_SUCCESS : XF_CAM2);
        send_order(f, 2, XF_ORDER_NULL, NULL);
        cmd.cameras = XF_CAM1; /* camera 1, which takes none of them */
        send_cmd(f, 2, &cmd, &r);
        assert_int_equal(r.params[0], XF_CAM2);
        assert_int_equal(k.n, 1);
        assert_int_equal(k.last.question, XF_SIM_Q_CAMERA);
        assert_int_equal(k.last.state, XF_CAM2);
        assert_int_equal(k.last.param0, XF_CAM1);
        free(f);
    }
    {
        xf_sim_config cfg;
        sim_fx *f;
        xf_command cmd;
        xf_gcu_packet r;
        xf_sim_config_init(&cfg);
        cfg.gimbal_code = 0; /* Z-6A: no zoom_to */
        f = fx_new(&cfg);
        xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
        cmd.cameras = XF_CAM1 | XF_CAM2;
        cmd.zoom = 5000;
        send_cmd(f, 1, &cmd, &r);
        assert_int_equal(r.params[0], XF_CAM1 | XF_CAM2); /* NN: both cameras asked failed */
        xf_command_init(&cmd, XF_ORDER_PALETTE);
        send_cmd(f, 1, &cmd, &r);
        assert_int_equal(r.params[0], XF_CAM2);
        free(f);
    }
}

/* ---- rates divided by the main screen's zoom --------------------------------------------------- */

/* Camera 1 at 1x, camera 2 at 4x: a yaw rate of 100 raw is 10 deg/s with camera 1 on the main
 * screen and 2.5 deg/s with camera 2 (V2.0.6: 0.1 deg/s divided by the main screen's zoom). */
static void test_rates_by_main_screen_zoom(void **state)
{
    xf_sim_config cfg;
    sim_fx *f;
    xf_command cmd;
    xf_gcu_packet r;
    float yaw;
    int i, cam;
    (void)state;
    xf_sim_config_init(&cfg);
    cfg.main_camera = 2;
    f = fx_new(&cfg);
    assert_int_equal(f->s.main_camera, 2);
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.cameras = XF_CAM2;
    cmd.zoom = -40; /* 4x */
    send_cmd(f, 1, &cmd, NULL);
    for (i = 0; i < 40; i++) {
        f->now += 100;
        send_order(f, 1, XF_ORDER_NULL, NULL);
    }
    assert_near(f->s.zoom2, 4.0, 1e-4);
    assert_near(f->s.zoom1, 1.0, 1e-4);
    for (cam = 2; cam >= 1; cam--) {
        xf_sim_set_main_camera(&f->s, (uint8_t)cam);
        f->now += 20;
        send_carrier(f, NULL, 0, 100, &r);
        yaw = f->s.yaw;
        for (i = 0; i < 10; i++) {
            f->now += 100;
            send_carrier(f, NULL, 0, 100, &r);
        }
        assert_near(ct_angle_diff((double)f->s.yaw, (double)yaw), cam == 2 ? 2.5 : 10.0, 0.01);
        assert_near(xf_gcu_rate_dps(r.main.rate_z, r.version), cam == 2 ? 2.5 : 10.0, 0.02);
    }
    xf_sim_set_main_camera(&f->s, 7); /* no such camera: camera 1 */
    assert_int_equal(f->s.main_camera, 1);
    xf_sim_set_main_camera(NULL, 2);
    free(f);
}

/* Every order V0.2 added, with valid parameters, on the wire: a V0.1 simulator does not know it and
 * answers as to an unknown order (failure, told to on_note, nothing done: the time zone and the
 * mode stay); a V0.2 simulator runs it. */
static void test_v01_refuses_v02_orders(void **state)
{
    size_t i, newer = 0;
    (void)state;
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        const xf_order_info *info = xf_order_at(i);
        uint8_t version;
        if (info->since < XF_PROTOCOL_V2) {
            continue;
        }
        newer++;
        for (version = 1; version <= 2u; version++) {
            notes k;
            sim_fx *f;
            xf_gcu_packet r;
            xf_command cmd;
            uint8_t mode;
            memset(&k, 0, sizeof(k));
            f = fx_version(version, &k);
            mode = (uint8_t)f->s.mode;
            ct_valid_command(&cmd, info->order);
            if (info->order == XF_ORDER_TIME_ZONE) {
                cmd.hours = 5;
            }
            send_cmd(f, version, &cmd, &r);
            assert_int_equal(r.order, info->order);
            assert_int_equal(r.params_len, 1);
            if (version == 1u) {
                assert_int_equal(r.params[0], (info->flags & XF_ORDER_MASK_FAILURE) ? XF_CAM2 : XF_STATE_FAILURE);
                assert_int_equal(k.n, 1);
                assert_int_equal(k.last.question, XF_SIM_Q_NEWER);
                assert_int_equal(k.last.order, info->order);
                assert_string_equal(k.last.text, xf_sim_question_text(XF_SIM_Q_NEWER));
                assert_int_equal(f->s.stats.strict, 1);
                assert_int_equal(f->s.mode, mode);
                assert_int_equal(f->s.time_zone, 0);
            } else {
                assert_int_equal(k.n, 0);
                assert_int_equal(f->s.stats.strict, 0);
                if (info->order == XF_ORDER_TIME_ZONE) {
                    assert_int_equal(f->s.time_zone, 5);
                    assert_int_equal(r.params[0], XF_STATE_SUCCESS);
                }
                if (info->order == XF_ORDER_FPV) {
                    assert_int_equal(f->s.mode, XF_MODE_FPV);
                }
            }
            free(f);
        }
    }
    assert_int_equal(newer, 10); /* V0.2's ten new orders (docs/protocol.md §10.2) */
}

/* ---- what V2.0.6 leaves open: the strict reading, said -------------------------------------- */

/* Parameters of the wrong length (a 2-byte shutter, a 9-byte click-to-aim and track, as public
 * wrappers send them), record with 0x00 (ArduPilot's stop) or 0x02, an order no document defines:
 * each fails, executes nothing, and is told to on_note once, with its text. */
static void test_strict_readings_told(void **state)
{
    static const struct {
        uint8_t order, len, params[10];
        xf_sim_question q;
        uint8_t state;
    } cases[] = {
        {XF_ORDER_SHUTTER, 2, {0x01, 0x01}, XF_SIM_Q_LENGTH, XF_STATE_FAILURE},
        {XF_ORDER_CLICK_TO_AIM, 9, {0x01, 0x10, 0x27}, XF_SIM_Q_LENGTH, XF_CAM1},
        {XF_ORDER_TRACK, 9, {0x01, 0x10, 0x27}, XF_SIM_Q_LENGTH, XF_CAM1},
        {XF_ORDER_RECORD, 1, {0x00}, XF_SIM_Q_RECORD, XF_STATE_FAILURE},
        {XF_ORDER_RECORD, 1, {0x02}, XF_SIM_Q_RECORD, XF_STATE_FAILURE},
        {0x99, 0, {0}, XF_SIM_Q_ORDER, XF_STATE_FAILURE},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        notes k;
        sim_fx *f;
        xf_gcu_packet r;
        memset(&k, 0, sizeof(k));
        f = fx_version(2, &k);
        send_raw(f, 2, cases[i].order, cases[i].params, cases[i].len, &r);
        assert_int_equal(r.order, cases[i].order);
        assert_int_equal(r.params[0], cases[i].state);
        assert_int_equal(k.n, 1);
        assert_int_equal(k.last.question, cases[i].q);
        assert_int_equal(k.last.order, cases[i].order);
        assert_int_equal(k.last.state, cases[i].state);
        assert_int_equal(k.last.params_len, cases[i].len);
        assert_string_equal(k.last.text, xf_sim_question_text(cases[i].q));
        assert_true(strlen(k.last.text) > 20u);
        assert_int_equal(f->s.stats.strict, 1);
        assert_int_equal(f->s.stats.photos + f->s.stats.recordings, 0);
        assert_int_equal(f->s.camera_status & XF_CAMERA_RECORDING, 0);
        send_order(f, 2, XF_ORDER_NULL, NULL);
        send_order(f, 2, XF_ORDER_RECORD, &r); /* the vendor's record: 0x01, no question */
        assert_int_equal(r.params[0], XF_STATE_SUCCESS);
        assert_int_equal(k.n, 1);
        free(f);
    }
    assert_string_equal(xf_sim_question_text((xf_sim_question)0), "");
    {
        sim_fx *f = fx_new(NULL); /* no on_note: counted all the same */
        uint8_t two[2] = {1, 1};
        xf_gcu_packet r;
        send_raw(f, 1, XF_ORDER_FOCUS, two, 2, &r);
        assert_int_equal(r.params[0], XF_STATE_FAILURE);
        assert_int_equal(f->s.stats.strict, 1);
        free(f);
    }
}

/* ---- a GCU that answers one version only ------------------------------------------------------ */

/* answer_only: packets of the other version are ignored as if they had not come (no reply, no
 * execution, nothing read from them), and counted. */
static void test_answer_only(void **state)
{
    static const uint8_t versions[] = {1, 2};
    size_t v;
    (void)state;
    for (v = 0; v < 2u; v++) {
        xf_sim_config cfg;
        sim_fx *f;
        xf_command shutter;
        uint8_t other = (uint8_t)(3u - versions[v]), buf[XF_PACKET_MAX_LEN];
        size_t len;
        xf_sim_config_init(&cfg);
        cfg.version = versions[v];
        cfg.answer_only = versions[v];
        f = fx_new(&cfg);
        xf_command_init(&shutter, XF_ORDER_SHUTTER);
        len = host_bytes(buf, other, NULL, XF_STATUS_INS_VALID);
        feed(f, buf, len);
        assert_int_equal(f->out_len, 0);
        len = host_bytes(buf, other, &shutter, 0);
        feed(f, buf, len);
        assert_int_equal(f->out_len, 0);
        assert_int_equal(f->s.stats.photos, 0);
        assert_int_equal(f->s.stats.ignored, 2);
        assert_int_equal(f->s.stats.packets_in, 0);
        assert_int_equal(f->s.stats.ins_valid_packets, 0);
        send_order(f, versions[v], XF_ORDER_SHUTTER, NULL);
        assert_int_equal(f->out_len, 73);
        assert_int_equal(f->s.stats.photos, 1);
        assert_int_equal(f->s.stats.packets_in, 1);
        free(f);
    }
    {
        xf_sim_config cfg;
        xf_sim s;
        xf_sim_config_init(&cfg);
        assert_int_equal(cfg.answer_only, 0);
        cfg.answer_only = 3;
        assert_xf(xf_sim_init(&s, &cfg), XF_ERR_RANGE);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_commands_in_own_version),       cmocka_unit_test(test_angles_hold_while_invalid),
        cmocka_unit_test(test_relative_angles_from_encoders), cmocka_unit_test(test_camera2_orders_fail_0x02),
        cmocka_unit_test(test_rates_by_main_screen_zoom),     cmocka_unit_test(test_strict_readings_told),
        cmocka_unit_test(test_v01_refuses_v02_orders),        cmocka_unit_test(test_answer_only),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
