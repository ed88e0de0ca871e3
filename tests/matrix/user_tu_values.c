/*
 * user_tu_values.c - the second file of the matrix's user program (see
 * user_tu.c): it includes xfgcu/xfgcu.h WITHOUT defining XF_IMPLEMENTATION,
 * as every other file of a header-only user does, so it sees the codec's
 * declarations only and is linked with the definitions user_tu.c compiles.
 * It must build as cleanly as user_tu.c in every combination of the matrix.
 *
 * Its checks are the calls whose arguments are values and tables rather than
 * the caller's buffers: error names, the byte helpers (static inline, so the
 * optimiser still sees their buffers here), the gimbal table, the order
 * table, field names, command members and their checks, units, the wire-field
 * table.
 */
#include <stdint.h>
#include <string.h>
#include "xfgcu/xfgcu.h"
#include "user_tu.h"

/* Always 0, read at run time (a NaN from 0 / 0 that the compiler cannot fold). */
static volatile double opaque_dzero;

static int near_f(float a, float b, float eps)
{
    float d = a - b;
    return d <= eps && d >= -eps;
}

static int near_d(double a, double b, double eps)
{
    double d = a - b;
    return d <= eps && d >= -eps;
}

static int same_str(const char *a, const char *b) { return a != NULL && b != NULL && strcmp(a, b) == 0; }

/* ---- xf_error.h ---------------------------------------------------------- */

void test_strerror(void)
{
    static const xf_err codes[] = {
        XF_OK,         XF_WARN_RATE,  XF_ERR_ARG,     XF_ERR_NO_SPACE, XF_ERR_RANGE,     XF_ERR_UNSUPPORTED,
        XF_ERR_CONFIG, XF_ERR_HEADER, XF_ERR_LENGTH,  XF_ERR_CRC,      XF_ERR_TRUNCATED, XF_ERR_PARAMS,
        XF_ERR_FORMAT, XF_ERR_IO,     XF_ERR_TIMEOUT, XF_ERR_CLOSED,   XF_ERR_NOT_FOUND, XF_ERR_PERMISSION,
        XF_ERR_BUSY,   XF_ERR_AGAIN,  XF_ERR_EOF};
    size_t i, j;
    for (i = 0; i < sizeof(codes) / sizeof(codes[0]); i++) {
        const char *s = xf_strerror(codes[i]);
        const char *name = xf_err_name(codes[i]);
        CHECK(s != NULL && s[0] != '\0' && !same_str(s, "unknown error"));
        CHECK(name != NULL && name[0] == 'X' && !same_str(name, "unknown"));
        for (j = 0; j < i; j++) {
            CHECK(!same_str(s, xf_strerror(codes[j])));
            CHECK(!same_str(name, xf_err_name(codes[j])));
        }
    }
    CHECK(same_str(xf_strerror(XF_OK), "ok"));
    CHECK(same_str(xf_strerror(-1), "unknown error"));
    CHECK(same_str(xf_strerror(12345), "unknown error"));
    CHECK(same_str(xf_strerror(XF_ERR_NO_SPACE), "output buffer too small"));
    CHECK(same_str(xf_err_name(XF_ERR_CRC), "XF_ERR_CRC") && same_str(xf_err_name(XF_OK), "XF_OK"));
    CHECK(same_str(xf_err_name((xf_err)-1), "unknown") && same_str(xf_err_name((xf_err)1), "unknown"));
}

/* ---- xf_bytes.h, xf_mem.h -------------------------------------------------- */

void test_bytes(void)
{
    uint8_t b1[1];
    uint8_t b2[2];
    uint8_t b4[4];
    uint8_t b16[16];
    size_t i;

    xf_put_u16le(b2, 0xBEEFu);
    CHECK(b2[0] == 0xEFu && b2[1] == 0xBEu);
    CHECK(xf_get_u16le(b2) == 0xBEEFu);
    xf_put_s16le(b2, (int16_t)-32768);
    CHECK(xf_get_s16le(b2) == -32768);
    CHECK(xf_get_u16le(b2) == 0x8000u);
    xf_put_s16le(b2, -2);
    CHECK(b2[0] == 0xFEu && b2[1] == 0xFFu && xf_get_s16le(b2) == -2);

    xf_put_u32le(b4, 0x12345678u);
    CHECK(b4[0] == 0x78u && b4[1] == 0x56u && b4[2] == 0x34u && b4[3] == 0x12u);
    CHECK(xf_get_u32le(b4) == 0x12345678u);
    xf_put_s32le(b4, INT32_MIN);
    CHECK(xf_get_s32le(b4) == INT32_MIN);
    xf_put_s32le(b4, -380300822);
    CHECK(xf_get_s32le(b4) == -380300822);

    /* at odd offsets of a larger buffer */
    XF_MEMSET(b16, 0, sizeof(b16));
    xf_put_u32le(b16 + 11, 0xA1B2C3D4u);
    xf_put_s16le(b16 + 1, 1234);
    CHECK(xf_get_u32le(b16 + 11) == 0xA1B2C3D4u && xf_get_s16le(b16 + 1) == 1234);
    CHECK(b16[0] == 0u && b16[15] == 0u);

    for (i = 0; i < 256u; i++) {
        b1[0] = (uint8_t)i;
        CHECK(xf_u8_to_s8(b1[0]) == (int)((i < 128u) ? (int)i : (int)i - 256));
    }

    /* the byte-block macros of xf_mem.h */
    XF_MEMCPY(b4, vendor_packet, sizeof(b4));
    CHECK(b4[0] == 0xA8u && b4[3] == 0x00u);
    CHECK(XF_MEMCHR(vendor_packet, 0xE9, sizeof(vendor_packet)) == (const void *)(vendor_packet + 70));
    b1[0] = 0x5A;
    CHECK(XF_MEMCHR(b1, 0x5A, sizeof(b1)) == (const void *)b1);
    CHECK(XF_MEMCHR(b4, 0x5A, sizeof(b4)) == NULL);
    XF_MEMMOVE(b4, b4 + 1, 3); /* overlapping, down (how the parser moves bytes) then up */
    CHECK(b4[0] == 0xE5u && b4[2] == 0x00u && b4[3] == 0x00u);
    XF_MEMMOVE(b4 + 1, b4, 3);
    CHECK(b4[0] == 0xE5u && b4[1] == 0xE5u && b4[3] == 0x00u);
}

/* ---- xf_protocol.h ------------------------------------------------------ */

void test_protocol(void)
{
    CHECK(same_str(xf_gimbal_model(40), "D-80AI"));
    CHECK(same_str(xf_gimbal_model(0), "Z-6A"));
    CHECK(same_str(xf_gimbal_model(62), "D-90Pro(V)"));
    CHECK(xf_gimbal_model(1) == NULL);
    CHECK(xf_gimbal_model(255) == NULL);
    CHECK(xf_gimbal_supports(0, XF_ORDER_PALETTE) == XF_SUPPORT_NO); /* Z-6A has no palette */
    CHECK(xf_gimbal_supports(58, XF_ORDER_PALETTE) == XF_SUPPORT_YES);
    CHECK(xf_osd_value(1, XF_PROTOCOL_V2) == 1u && xf_osd_value(1, XF_PROTOCOL_V1) == 0u);
    CHECK(xf_pod_status_order(0x8001u) == XF_POD_ORDER_BE); /* V2.0.6's example, bytes 01 80 */
    CHECK(xf_pod_status_order(0x1001u) == XF_POD_ORDER_LE);
    CHECK(xf_pod_status_order(0x0001u) == XF_POD_ORDER_UNDECIDED);
    CHECK(xf_pod_flags(0x8001u, XF_POD_ORDER_BE) == (XF_POD_RANGING_ON | XF_POD_TARGET_VALID));
    CHECK(xf_pod_flags(0x8001u, XF_POD_ORDER_LE) == 0x8001u);
}

/* ---- xf_command.h ------------------------------------------------------- */

void test_order_table(void)
{
    size_t i;
    uint8_t params[XF_PARAMS_KNOWN_MAX];
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        const xf_order_info *info = xf_order_at(i);
        const char *name;
        uint8_t order = 0xFF;
        xf_command c, d;
        xf_field bad = XF_F_NONE;
        size_t n = 99, plen;
        CHECK(info != NULL);
        if (info == NULL) {
            continue;
        }
        CHECK(xf_order_lookup(info->order) == info);
        name = xf_order_name(info->order);
        CHECK(name != NULL);
        CHECK(xf_order_from_name(name, &order) == XF_OK && order == info->order);
        plen = xf_order_params_len(info->order);
        CHECK(plen <= XF_PARAMS_KNOWN_MAX);
        CHECK(info->since == 1u || info->since == 2u);
        if (i > 0u) {
            CHECK(xf_order_at(i - 1u)->order < info->order);
        }

        xf_command_init(&c, info->order);
        CHECK(c.order == info->order && c.cameras == info->default_cameras);
        if (info->order == XF_ORDER_ZOOM_TO) {
            /* zoom 0 is neither a rate nor a fraction */
            CHECK(xf_command_check(&c, XF_PROTOCOL_V2, &bad) == XF_ERR_RANGE && bad == XF_F_ZOOM);
            c.zoom = 5000;
        }
        CHECK(xf_command_check(&c, XF_PROTOCOL_V1, NULL) == XF_OK);
        CHECK(xf_command_encode(&c, XF_PROTOCOL_V2, params, sizeof(params), &n, &bad) == XF_OK && n == plen);
        XF_MEMSET(&d, 0x5A, sizeof(d));
        CHECK(xf_command_decode(info->order, params, n, XF_PROTOCOL_V2, &d, &bad) == XF_OK);
        CHECK(memcmp(&c, &d, sizeof(c)) == 0);
    }
    CHECK(xf_order_at(XF_ORDER_COUNT) == NULL);
    CHECK(xf_order_at(hide(XF_ORDER_COUNT)) == NULL);
    CHECK(xf_order_lookup(0xFF) == NULL && xf_order_lookup(0x02) == NULL);
    CHECK(xf_order_name(0xFF) == NULL);
    CHECK(same_str(xf_order_name(XF_ORDER_ZOOM_TO), "zoom_to"));
    CHECK(xf_order_params_len(0xFF) == 0u);
    CHECK(xf_order_params_len(XF_ORDER_TRACK) == 10u && xf_order_params_len(XF_ORDER_GAZE_GEO) == 12u);
    {
        uint8_t order = 0;
        CHECK(xf_order_from_name("zoom-to", &order) == XF_OK && order == XF_ORDER_ZOOM_TO);
        CHECK(xf_order_from_name("external_track", &order) == XF_OK && order == XF_ORDER_EXTERNAL_TRACK);
        order = 0x42;
        CHECK(xf_order_from_name("zoom", &order) == XF_ERR_NOT_FOUND && order == 0x42u);
        CHECK(xf_order_from_name("zoom_to_", &order) == XF_ERR_NOT_FOUND);
        CHECK(xf_order_from_name("", &order) == XF_ERR_NOT_FOUND);
        CHECK(xf_order_from_name("Zoom_to", &order) == XF_ERR_NOT_FOUND);
        CHECK(xf_order_from_name(NULL, &order) == XF_ERR_ARG);
        CHECK(xf_order_from_name("null", NULL) == XF_ERR_ARG);
    }
}

void test_names(void)
{
    static const uint8_t modes[] = {XF_MODE_ANGLE_CONTROL, XF_MODE_HEAD_LOCK, XF_MODE_HEAD_FOLLOW, XF_MODE_ORTHOVIEW,
                                    XF_MODE_EULER,         XF_MODE_GAZE,      XF_MODE_TRACK,       XF_MODE_FPV};
    size_t i;
    int f;
    for (i = 0; i < sizeof(modes); i++) {
        CHECK(xf_mode_name(modes[i]) != NULL);
    }
    CHECK(same_str(xf_mode_name(XF_MODE_HEAD_LOCK), "head_lock"));
    CHECK(xf_mode_name(0) == NULL && xf_mode_name(0x15) == NULL);

    for (f = XF_F_CAMERAS; f <= XF_F_ALTITUDE; f++) {
        const char *s = xf_field_name((xf_field)f);
        size_t sz = xf_field_size((xf_field)f);
        CHECK(s != NULL && s[0] != '\0' && !same_str(s, "?"));
        CHECK(sz == 1u || sz == 2u || sz == 4u);
    }
    CHECK(same_str(xf_field_name(XF_F_CAMERAS), "cameras"));
    CHECK(same_str(xf_field_name(XF_F_TEMP_LOW), "temp_low"));
    CHECK(same_str(xf_field_name(XF_F_ALTITUDE), "altitude"));
    CHECK(xf_field_size(XF_F_HOURS) == 1u && xf_field_size(XF_F_ZOOM) == 2u && xf_field_size(XF_F_LATITUDE) == 4u);
    /* 15 is no member, but inside the enumeration's range (C++ too) */
    CHECK(same_str(xf_field_name((xf_field)15), "?"));
    CHECK(xf_field_size((xf_field)15) == 2u);
}

void test_command_get_set(void)
{
    xf_command c;
    int f;
    xf_command_init(&c, XF_ORDER_TRACK);
    CHECK(c.order == XF_ORDER_TRACK && c.cameras == XF_CAM1);
    xf_command_init(NULL, XF_ORDER_TRACK); /* does nothing */
    xf_command_init(&c, 0xFF);
    CHECK(c.order == 0xFFu && c.cameras == 0u);

    for (f = XF_F_CAMERAS; f <= XF_F_ALTITUDE; f++) {
        xf_command_set(&c, (xf_field)f, 100 + f);
        CHECK(xf_command_get(&c, (xf_field)f) == 100 + f);
    }
    xf_command_set(&c, XF_F_VALUE, 300);
    CHECK(c.value == 255u);
    xf_command_set(&c, XF_F_X0, -5);
    CHECK(c.x0 == 0u);
    xf_command_set(&c, XF_F_HOURS, -1000);
    CHECK(c.hours == -128);
    xf_command_set(&c, XF_F_DX, 40000);
    CHECK(c.dx == 32767);
    xf_command_set(&c, XF_F_LONGITUDE, INT32_MIN);
    CHECK(xf_command_get(&c, XF_F_LONGITUDE) == INT32_MIN);
    xf_command_set(&c, (xf_field)15, 1); /* ignored */
    CHECK(xf_command_get(&c, (xf_field)15) == 0);
    CHECK(xf_command_get(NULL, XF_F_VALUE) == 0);
    xf_command_set(NULL, XF_F_VALUE, 1); /* does nothing */
}

void test_command_check(void)
{
    xf_command c;
    xf_field bad = XF_F_NONE;

    CHECK(xf_command_check(NULL, XF_PROTOCOL_V1, &bad) == XF_ERR_ARG);
    xf_command_init(&c, 0x02); /* not an order */
    CHECK(xf_command_check(&c, XF_PROTOCOL_V1, &bad) == XF_ERR_NOT_FOUND);

    xf_command_init(&c, XF_ORDER_TRACK);
    c.value = 1;
    c.x0 = 500;
    c.x1 = 400; /* right edge left of the left one */
    c.y1 = 10;
    CHECK(xf_command_check(&c, XF_PROTOCOL_V1, &bad) == XF_ERR_RANGE && bad == XF_F_X1);
    c.x1 = 600;
    bad = XF_F_NONE;
    CHECK(xf_command_check(&c, XF_PROTOCOL_V1, &bad) == XF_OK && bad == XF_F_NONE);
    c.cameras = 0;
    CHECK(xf_command_check(&c, XF_PROTOCOL_V1, &bad) == XF_ERR_RANGE && bad == XF_F_CAMERAS);
    CHECK(xf_command_check(&c, XF_PROTOCOL_V1, NULL) == XF_ERR_RANGE);

    xf_command_init(&c, XF_ORDER_TIME_ZONE);
    c.hours = 15;
    CHECK(xf_command_check(&c, XF_PROTOCOL_V2, &bad) == XF_ERR_RANGE && bad == XF_F_HOURS);
    c.hours = -12;
    CHECK(xf_command_check(&c, XF_PROTOCOL_V2, &bad) == XF_OK);

    xf_command_init(&c, XF_ORDER_EXTERNAL_TRACK);
    c.dx = 1025;
    CHECK(xf_command_check(&c, XF_PROTOCOL_V1, &bad) == XF_ERR_RANGE && bad == XF_F_DX);
    c.dx = XF_EXT_TRACK_LOST;
    c.dy = XF_EXT_TRACK_LOST; /* the "lost" marker */
    CHECK(xf_command_check(&c, XF_PROTOCOL_V1, &bad) == XF_OK);

    xf_command_init(&c, XF_ORDER_RANGING);
    c.value = 1; /* 0 or 2 only */
    CHECK(xf_command_check(&c, XF_PROTOCOL_V1, &bad) == XF_ERR_RANGE && bad == XF_F_VALUE);

    xf_command_init(&c, XF_ORDER_TEMP_ALARM);
    c.value = 1;
    c.temp_high = 100;
    c.temp_low = 200;
    CHECK(xf_command_check(&c, XF_PROTOCOL_V2, &bad) == XF_ERR_RANGE && bad == XF_F_TEMP_LOW);
}

/* ---- xf_units.h --------------------------------------------------------- */

void test_units(void)
{
    double nan_d = opaque_dzero / opaque_dzero;
    float nan_f = (float)nan_d;
    float r = 0, p = 0, y = 0, ax = 0, ay = 0, az = 0, m = -1.0f;
    int64_t unix_ms = 0;
    int16_t week = 0;
    uint32_t ms = 0;

    CHECK(xf_units_round(2.5, -10, 10) == 3 && xf_units_round(-2.5, -10, 10) == -3);
    CHECK(xf_units_round(100.0, -10, 10) == 10 && xf_units_round(nan_d, -10, 10) == 0);
    CHECK(xf_units_round(nan_d, 5, 10) == 5);
    CHECK(xf_units_roundf(2.5f, -10, 10) == 3 && xf_units_roundf(-100.0f, -10, 10) == -10);
    CHECK(xf_units_roundf(nan_f, -10, 10) == 0);
    CHECK(near_d(xf_units_wrap360(370.0, 0.0), 10.0, 1e-9));
    CHECK(near_d(xf_units_wrap360(-190.0, -180.0), 170.0, 1e-9));
    CHECK(xf_units_wrap360(nan_d, -180.0) == 0.0 && xf_units_wrap360(1e13, 10.0) == 10.0);
    CHECK(near_f(xf_units_wrap360f(725.0f, 0.0f), 5.0f, 1e-4f));
    CHECK(near_f(xf_units_wrap360f(180.0f, -180.0f), -180.0f, 1e-4f));
    CHECK(xf_units_wrap360f(nan_f, 0.0f) == 0.0f);

    CHECK(xf_carrier_roll_raw(-11.32f) == -1132);
    CHECK(xf_carrier_roll_raw(179.999f) == -18000);
    CHECK(xf_carrier_roll_raw(190.0f) == -17000);
    CHECK(xf_carrier_pitch_raw(1.01f) == 101 && xf_carrier_pitch_raw(95.0f) == 9000);
    CHECK(xf_carrier_yaw_raw(240.0f) == 24000 && xf_carrier_yaw_raw(-90.0f) == 27000);
    CHECK(xf_carrier_yaw_raw(359.999f) == 0);
    CHECK(xf_accel_raw(1.12f) == 112 && xf_accel_raw(1e6f) == 32767);
    CHECK(xf_velocity_raw(-0.5f) == -50 && xf_velocity_raw(-1e6f) == -32768);
    CHECK(xf_ctrl_angle_raw(-200.0f) == -18000 && xf_ctrl_angle_raw(1.0f) == 100);
    CHECK(xf_ctrl_rate_raw(1.0f, 2.0f) == 20 && xf_ctrl_rate_raw(1.0f, 0.5f) == 10);
    CHECK(xf_ctrl_rate_raw(10.0f, 20.0f) == 1500 && xf_ctrl_rate_raw(1.0f, nan_f) == 10);

    CHECK(xf_deg7_raw(170.9175332) == 1709175332 && xf_deg7_raw(200.0) == 1800000000);
    CHECK(xf_mm_raw(41.123) == 41123 && xf_mm_raw(1e12) == INT32_MAX && xf_mm_raw(-1e12) == INT32_MIN);
    CHECK(near_d(xf_deg7(1709175332), 170.9175332, 1e-9));

    CHECK(near_f(xf_cdeg(-1132), -11.32f, 1e-4f));
    CHECK(near_f(xf_gcu_rate_dps(100, XF_PROTOCOL_V1), 1.0f, 1e-6f));
    CHECK(near_f(xf_gcu_rate_dps(100, XF_PROTOCOL_V2), 10.0f, 1e-6f));
    CHECK(xf_gcu_rate_raw(1.0f, XF_PROTOCOL_V1) == 100 && xf_gcu_rate_raw(1.0f, XF_PROTOCOL_V2) == 10);
    CHECK(near_f(xf_zoom_x(55), 5.5f, 1e-6f));
    CHECK(xf_zoom_raw(5.5f) == 55 && xf_zoom_raw(-1.0f) == 0 && xf_zoom_raw(1e9f) == 65535);
    CHECK(xf_zoom_to_rate_raw(5.5f) == -55 && xf_zoom_to_rate_raw(0.5f) == -10);
    CHECK(!xf_distance_m(XF_DISTANCE_INVALID_RAW, &m) && m == -1.0f);
    CHECK(!xf_distance_m(0, &m));
    CHECK(xf_distance_m(1234, &m) && near_f(m, 123.4f, 1e-3f));
    CHECK(xf_distance_m(1234, NULL));

    CHECK(xf_gnss_to_unix_ms(2278, 352718000u, XF_LEAP_SECONDS_2017, &unix_ms) == XF_OK);
    CHECK(unix_ms == (XF_GPS_EPOCH_UNIX - XF_LEAP_SECONDS_2017) * 1000 + 2278LL * (int64_t)XF_WEEK_MS + 352718000LL);
    CHECK(xf_unix_ms_to_gnss(unix_ms, XF_LEAP_SECONDS_2017, &week, &ms) == XF_OK);
    CHECK(week == 2278 && ms == 352718000u);
    CHECK(xf_gnss_to_unix_ms(-1, 0, XF_LEAP_SECONDS_2017, &unix_ms) == XF_ERR_RANGE);
    CHECK(xf_gnss_to_unix_ms(0, (uint32_t)XF_WEEK_MS, XF_LEAP_SECONDS_2017, &unix_ms) == XF_ERR_RANGE);
    CHECK(xf_gnss_to_unix_ms(0, 0, XF_LEAP_SECONDS_2017, NULL) == XF_ERR_ARG);
    week = 5;
    CHECK(xf_unix_ms_to_gnss(0, XF_LEAP_SECONDS_2017, &week, &ms) == XF_ERR_RANGE && week == 5);
    CHECK(xf_unix_ms_to_gnss(INT64_MAX, 0, &week, &ms) == XF_ERR_RANGE);
    CHECK(xf_unix_ms_to_gnss(unix_ms, 0, NULL, &ms) == XF_ERR_ARG);
    CHECK(xf_unix_ms_to_gnss(unix_ms, 0, &week, NULL) == XF_ERR_ARG);

    xf_axes_to_euler(10.0f, 20.0f, 30.0f, &r, &p, &y);
    CHECK(near_f(r, 20.0f, 1e-4f) && near_f(p, -10.0f, 1e-4f) && near_f(y, 120.0f, 1e-4f));
    xf_euler_to_axes(r, p, y, &ax, &ay, &az);
    CHECK(near_f(ax, 10.0f, 1e-4f) && near_f(ay, 20.0f, 1e-4f) && near_f(az, 30.0f, 1e-4f));
    xf_axes_to_euler(0.0f, 0.0f, 300.0f, NULL, NULL, &y);
    CHECK(near_f(y, 30.0f, 1e-4f));
    xf_euler_to_axes(0.0f, 0.0f, 0.0f, NULL, NULL, &az);
    CHECK(near_f(az, -90.0f, 1e-4f));
    xf_axes_to_euler(1.0f, 2.0f, 3.0f, NULL, NULL, NULL);
    xf_euler_to_axes(1.0f, 2.0f, 3.0f, NULL, NULL, NULL);
}

/* The field table: the vendor packet's fields read through it, written back, and the units. */
void test_wire_fields(void)
{
    size_t n = 0;
    int64_t lo = 0, hi = 0, raw = 0;
    uint8_t copy[72];
    const xf_wire_field *rows = xf_wire_fields(xf_wire_frames(XF_DIR_HOST), &n);
    const xf_wire_field *yaw = xf_wire_field_find(XF_WIRE_HOST, "carrier_yaw");
    const xf_wire_field *rate = xf_wire_field_find(XF_WIRE_GCU, "rate_x");
    CHECK(rows != NULL && n > 20u && yaw != NULL && rate != NULL);
    CHECK(xf_wire_field_get(yaw, vendor_packet) == 24000);
    CHECK(near_d(xf_wire_field_value(yaw, 24000, XF_PROTOCOL_V1), 240.0, 1e-9));
    CHECK(xf_wire_field_raw(yaw, 240.0, XF_PROTOCOL_V1, &raw) == XF_OK && raw == 24000);
    CHECK(xf_wire_field_raw(yaw, 240.005, XF_PROTOCOL_V1, &raw) == XF_ERR_ARG);
    XF_MEMCPY(copy, vendor_packet, sizeof(copy));
    xf_wire_field_put(yaw, copy, 12345);
    CHECK(xf_wire_field_get(yaw, copy) == 12345);
    xf_wire_field_range(yaw, &lo, &hi);
    CHECK(lo == 0 && hi == 65535);
    CHECK(xf_wire_field_decimals(rate, XF_PROTOCOL_V1) == 2u && xf_wire_field_decimals(rate, XF_PROTOCOL_V2) == 1u);
    CHECK(xf_wire_field_present(xf_wire_field_find(XF_WIRE_GCU, "time_zone"), XF_PROTOCOL_V2));
    CHECK(xf_wire_param(XF_F_ZOOM) != NULL && same_str(xf_wire_param(XF_F_ZOOM)->name, "zoom"));
}
