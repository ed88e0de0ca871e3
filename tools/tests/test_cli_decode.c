/*
 * test_cli_decode.c - `xfgcu decode`: the vendor's worked example, both
 * directions and versions, every argument layout, faults of hex and of
 * packets, noisy streams on stdin, and the byte order of pod_status.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include <jansson.h>

#include "run_tool.h"
#include "xfgcu/xfgcu.h"

/* ---- helpers ------------------------------------------------------------------ */

static void hex_plain(const uint8_t *b, size_t n, char *buf)
{
    size_t i;
    for (i = 0; i < n; i++) {
        sprintf(buf + 2u * i, "%02x", b[i]);
    }
    buf[2u * n] = '\0';
}

static size_t gcu_packet(uint8_t version, uint8_t order, const uint8_t *fb, uint8_t fb_len, uint8_t *out)
{
    xf_gcu_packet p;
    size_t len = 0;
    memset(&p, 0, sizeof(p));
    p.version = version;
    p.order = order;
    p.params_len = fb_len;
    if (fb_len > 0u) {
        memcpy(p.params, fb, fb_len);
    }
    p.main.gimbal_mode = XF_MODE_HEAD_LOCK;
    p.main.pod_status = XF_POD_RANGING_ON | XF_POD_TARGET_VALID;
    p.main.cam_pitch = -4500;
    p.main.cam_yaw = 35999;
    p.main.rate_x = -123;
    p.sub.sub_header = XF_SUB_HEADER;
    p.sub.gimbal_code = 30;
    p.sub.target_distance = 12345;
    p.sub.zoom_cam1 = 55;
    p.sub.thermal_status = 0x81;
    p.sub.camera_status = 0x2012;
    p.sub.time_zone = -5;
    assert_int_equal(xf_gcu_pack(&p, out, XF_PACKET_MAX_LEN, &len), XF_OK);
    return len;
}

/* ---- the vendor's worked example ---------------------------------------------------- */

/* The appendix's packet in engineering units (the default): each value the wire integer times its
 * step, written with the digits of the step, under the same names. */
static void test_appendix1_engineering(void **state)
{
    tool_result r = run_tool(NULL, "decode", "--json", APPENDIX1_HEX, NULL);
    json_t *o;
    (void)state;
    assert_int_equal(r.status, 0);
    assert_int_equal(r.err_len, 0);
    o = parse_line(r.out);
    assert_int_equal(int_key(o, "roll_ctrl"), 0); /* the mode says its unit: the wire integer */
    assert_int_equal(int_key(o, "pitch_ctrl"), 100);
    assert_int_equal(int_key(o, "status"), 5);
    assert_true(num_key(o, "carrier_roll") == -11.32);
    assert_true(num_key(o, "carrier_pitch") == 1.01);
    assert_true(num_key(o, "carrier_yaw") == 240.0);
    assert_true(num_key(o, "accel_east") == -1.12);
    assert_true(num_key(o, "vel_north") == -327.04);
    assert_true(num_key(o, "longitude") == 170.9175332);
    assert_true(num_key(o, "latitude") == 38.0300822);
    assert_true(num_key(o, "altitude") == 41.123);
    assert_true(num_key(o, "relative_height") == 12.12);
    assert_int_equal(int_key(o, "gnss_ms"), 352718000); /* its name says its unit */
    assert_int_equal(int_key(o, "satellites"), 19);
    /* the digits of each step, nothing more */
    assert_non_null(strstr(r.out, "\"carrier_roll\":-11.32,"));
    assert_non_null(strstr(r.out, "\"carrier_yaw\":240.0,"));
    assert_non_null(strstr(r.out, "\"latitude\":38.0300822,"));
    json_decref(o);
    tool_result_free(&r);
}

static void test_appendix1_json(void **state)
{
    static const char *const host_keys[] = {
        "roll_ctrl",   "pitch_ctrl",  "yaw_ctrl",   "status",         "carrier_roll", "carrier_pitch",
        "carrier_yaw", "accel_north", "accel_east", "accel_up",       "vel_north",    "vel_east",
        "vel_up",      "sub_request", "sub_header", "longitude",      "latitude",     "altitude",
        "satellites",  "gnss_ms",     "gnss_week",  "relative_height"};
    tool_result r = run_tool(NULL, "decode", "--json", "--raw", APPENDIX1_HEX, NULL);
    json_t *o;
    size_t i;
    (void)state;
    assert_int_equal(r.status, 0);
    assert_int_equal(r.err_len, 0);
    assert_int_equal(count_lines(r.out), 1);
    /* compact, keys in order, required keys first */
    assert_true(strncmp(r.out, "{\"direction\":\"host\",\"version\":1,\"length\":72,\"order\":0,", 54) == 0);
    o = parse_line(r.out);
    assert_string_equal(str_key(o, "params"), "");
    for (i = 0; i < sizeof(host_keys) / sizeof(host_keys[0]); i++) {
        (void)int_key(o, host_keys[i]);
    }
    assert_int_equal(int_key(o, "roll_ctrl"), 0);
    assert_int_equal(int_key(o, "pitch_ctrl"), 100);
    assert_int_equal(int_key(o, "yaw_ctrl"), -100);
    assert_int_equal(int_key(o, "status"), 5);
    assert_int_equal(int_key(o, "carrier_roll"), -1132);
    assert_int_equal(int_key(o, "carrier_pitch"), 101);
    assert_int_equal(int_key(o, "carrier_yaw"), 24000);
    assert_int_equal(int_key(o, "accel_north"), 112);
    assert_int_equal(int_key(o, "accel_east"), -112);
    assert_int_equal(int_key(o, "accel_up"), 112);
    assert_int_equal(int_key(o, "vel_north"), -32704);
    assert_int_equal(int_key(o, "vel_east"), -2112);
    assert_int_equal(int_key(o, "vel_up"), -32704);
    assert_int_equal(int_key(o, "sub_request"), 1);
    assert_int_equal(int_key(o, "sub_header"), 1);
    assert_int_equal(int_key(o, "longitude"), 1709175332);
    assert_int_equal(int_key(o, "latitude"), 380300822);
    assert_int_equal(int_key(o, "altitude"), 41123);
    assert_int_equal(int_key(o, "satellites"), 19);
    assert_int_equal(int_key(o, "gnss_ms"), 352718000);
    assert_int_equal(int_key(o, "gnss_week"), 2278);
    assert_int_equal(int_key(o, "relative_height"), 12120);
    assert_null(json_object_get(o, "reserved_main")); /* all zero: not printed */
    assert_null(json_object_get(o, "reserved_sub"));
    assert_null(json_object_get(o, "thermal_status"));
    json_decref(o);
    tool_result_free(&r);
}

static void test_appendix1_layouts(void **state)
{
    char lower[2 * 72 + 1], colons[3 * 72], prefixed[5 * 72 + 1];
    const char *singles[72 + 2];
    char bytes[72][3];
    tool_result ref = run_tool(NULL, "decode", "--json", APPENDIX1_HEX, NULL);
    tool_result r;
    size_t i;
    (void)state;
    hex_plain(appendix1, 72, lower);
    for (i = 0; i < 72; i++) {
        sprintf(colons + 3u * i, i < 71u ? "%02X:" : "%02X", appendix1[i]);
        sprintf(prefixed + 5u * i, i < 71u ? "0x%02X," : "0x%02X", appendix1[i]);
        sprintf(bytes[i], "%02x", appendix1[i]);
        singles[i + 2] = bytes[i];
    }
    r = run_tool(NULL, "decode", "--json", lower, NULL);
    assert_string_equal(r.out, ref.out);
    tool_result_free(&r);
    r = run_tool(NULL, "decode", "--json", colons, NULL);
    assert_string_equal(r.out, ref.out);
    tool_result_free(&r);
    r = run_tool(NULL, "decode", "--json", prefixed, NULL);
    assert_string_equal(r.out, ref.out);
    tool_result_free(&r);
    /* unquoted on a shell: one byte per argument */
    singles[0] = "decode";
    singles[1] = "--json";
    r = run_tool_argv(74, singles, NULL);
    assert_int_equal(r.status, 0);
    assert_string_equal(r.out, ref.out);
    tool_result_free(&r);
    tool_result_free(&ref);
}

static void test_appendix1_table(void **state)
{
    tool_result r = run_tool(NULL, "decode", APPENDIX1_HEX, NULL);
    static const char *const needles[] = {
        "host packet",          "72 bytes",        "version 1",  "0xE9D4",       "vel_north", "-32704", "-327.04 m/s",
        "ins_valid ctrl_valid", "170.9175332 deg", "240.00 deg", "352718.000 s", "41.123 m",  "null"};
    size_t i;
    (void)state;
    assert_int_equal(r.status, 0);
    for (i = 0; i < sizeof(needles) / sizeof(needles[0]); i++) {
        if (strstr(r.out, needles[i]) == NULL) {
            print_error("table lacks \"%s\":\n%s", needles[i], r.out);
            fail();
        }
    }
    tool_result_free(&r);
    /* --raw: the wire integers and the names of flags, no engineering value */
    r = run_tool(NULL, "decode", "--raw", APPENDIX1_HEX, NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "-32704"));
    assert_non_null(strstr(r.out, "ins_valid ctrl_valid"));
    assert_null(strstr(r.out, " deg"));
    assert_null(strstr(r.out, "327.04"));
    tool_result_free(&r);
}

/* ---- GCU packets, versions, extras --------------------------------------------------- */

static void test_gcu_versions(void **state)
{
    uint8_t pkt[XF_PACKET_MAX_LEN];
    char hex[2 * XF_PACKET_MAX_LEN + 1];
    static const uint8_t failed3 = 0x03;
    size_t len = gcu_packet(2, XF_ORDER_ZOOM_IN, &failed3, 1, pkt);
    tool_result r;
    json_t *o, *fb;
    (void)state;
    hex_plain(pkt, len, hex);
    r = run_tool(NULL, "decode", "--json", "--raw", hex, NULL);
    assert_int_equal(r.status, 0);
    o = parse_line(r.out);
    assert_string_equal(str_key(o, "direction"), "gcu");
    assert_int_equal(int_key(o, "version"), 2);
    assert_int_equal(int_key(o, "length"), 73);
    assert_int_equal(int_key(o, "order"), 0x22);
    assert_string_equal(str_key(o, "order_name"), "zoom_in");
    assert_string_equal(str_key(o, "params"), "03");
    assert_int_equal(int_key(o, "gimbal_mode"), 0x11);
    assert_string_equal(str_key(o, "mode_name"), "head_lock");
    assert_int_equal(int_key(o, "pod_status"), 0x180);
    assert_int_equal(int_key(o, "cam_pitch"), -4500);
    assert_int_equal(int_key(o, "cam_yaw"), 35999);
    assert_int_equal(int_key(o, "rate_x"), -123);
    assert_int_equal(int_key(o, "gimbal_code"), 30);
    assert_string_equal(str_key(o, "gimbal_model"), "Z-9A");
    assert_int_equal(int_key(o, "target_distance"), 12345);
    assert_int_equal(int_key(o, "zoom_cam1"), 55);
    assert_int_equal(int_key(o, "thermal_status"), 0x81);
    assert_int_equal(int_key(o, "camera_status"), 0x2012);
    assert_int_equal(int_key(o, "time_zone"), -5);
    fb = json_object_get(o, "feedback");
    assert_string_equal(str_key(fb, "result"), "failed");
    assert_int_equal(int_key(fb, "failed_cameras"), 3);
    json_decref(o);
    tool_result_free(&r);

    /* the same in engineering units: V0.2's rates in 0.1 deg/s, versions in tenths */
    r = run_tool(NULL, "decode", "--json", hex, NULL);
    assert_int_equal(r.status, 0);
    o = parse_line(r.out);
    assert_true(num_key(o, "cam_pitch") == -45.0);
    assert_true(num_key(o, "cam_yaw") == 359.99);
    assert_true(num_key(o, "rate_x") == -12.3);
    assert_true(num_key(o, "target_distance") == 1234.5);
    assert_true(num_key(o, "zoom_cam1") == 5.5);
    assert_int_equal(int_key(o, "pod_status"), 0x180); /* flags and codes: integers in both views */
    assert_int_equal(int_key(o, "gimbal_code"), 30);
    assert_int_equal(int_key(o, "time_zone"), -5);
    json_decref(o);
    tool_result_free(&r);

    /* V0.1: bytes 63-66 are reserved, shown as reserved_sub when not zero */
    len = gcu_packet(1, XF_ORDER_NULL, NULL, 0, pkt);
    hex_plain(pkt, len, hex);
    r = run_tool(NULL, "decode", "--json", hex, NULL);
    o = parse_line(r.out);
    assert_null(json_object_get(o, "thermal_status"));
    assert_null(json_object_get(o, "camera_status"));
    assert_null(json_object_get(o, "time_zone"));
    assert_null(json_object_get(o, "feedback")); /* the null order's reply has no state */
    assert_string_equal(str_key(o, "reserved_sub"), "811220FB0000");
    json_decref(o);
    tool_result_free(&r);

    /* the table shows the V0.2 rate unit */
    len = gcu_packet(2, XF_ORDER_NULL, NULL, 0, pkt);
    hex_plain(pkt, len, hex);
    r = run_tool(NULL, "decode", hex, NULL);
    assert_non_null(strstr(r.out, "-12.3 deg/s"));
    assert_non_null(strstr(r.out, "UTC-5"));
    assert_non_null(strstr(r.out, "1234.5 m"));
    assert_non_null(strstr(r.out, "osd_on"));
    tool_result_free(&r);
}

static void test_host_command_extra(void **state)
{
    uint8_t pkt[XF_PACKET_MAX_LEN];
    char hex[2 * XF_PACKET_MAX_LEN + 1];
    xf_host_packet h;
    size_t len = 0;
    tool_result r;
    json_t *o, *c;
    (void)state;
    xf_host_packet_init(&h, 1);
    h.order = XF_ORDER_ZOOM_TO;
    h.params_len = 3;
    h.params[0] = 0xFF;
    h.params[1] = 0xC9;
    h.params[2] = 0xFF;
    h.main.reserved_main[5] = 0x42;
    assert_int_equal(xf_host_pack(&h, pkt, sizeof(pkt), &len), XF_OK);
    hex_plain(pkt, len, hex);
    r = run_tool(NULL, "decode", "--json", hex, NULL);
    o = parse_line(r.out);
    c = json_object_get(o, "command");
    assert_int_equal(int_key(c, "cameras"), 255);
    assert_int_equal(int_key(c, "zoom"), -55);
    assert_string_equal(str_key(o, "reserved_main"), "000000000042");
    json_decref(o);
    tool_result_free(&r);

    /* wrong parameter length for the order: the raw params, and why they do not decode */
    h.params_len = 2;
    assert_int_equal(xf_host_pack(&h, pkt, sizeof(pkt), &len), XF_OK);
    hex_plain(pkt, len, hex);
    r = run_tool(NULL, "decode", "--json", hex, NULL);
    o = parse_line(r.out);
    assert_null(json_object_get(o, "command"));
    assert_non_null(strstr(str_key(o, "command_error"), "3 parameter bytes"));
    assert_string_equal(str_key(o, "params"), "FFC9");
    json_decref(o);
    tool_result_free(&r);
}

/* ---- the byte order of pod_status (docs/protocol.md §11.7) ------------------------------ */

/* V2.0.6's decoded GCU reply (docs/protocol.md §2.4): bytes 6-7 are 01 80 in head follow. */
#define V206_REPLY_HEX                                                                                                 \
    "8A 5E 49 00 02 12 01 80 0C FE F4 01 DD FC 20 00 4A 18 FF FF A5 03 47 18 FF FF 01 00 FE FF 00 00 00 00 00 00 00 "  \
    "01 1F 32 29 00 00 06 17 00 00 24 F2 DF 65 16 EE AA 16 A3 A0 00 00 2B 01 14 00 00 00 00 08 00 00 20 00 EC 85"

/* A GCU packet whose bytes 6 and 7 are @p b6 @p b7, as hex. */
static void pod_packet_hex(uint8_t b6, uint8_t b7, char *hex)
{
    uint8_t pkt[XF_PACKET_MAX_LEN];
    size_t len = gcu_packet(2, XF_ORDER_NULL, NULL, 0, pkt);
    pkt[XF_OFF_GCU_POD_STATUS] = b6;
    pkt[XF_OFF_GCU_POD_STATUS + 1u] = b7;
    seal_packet(pkt, len);
    hex_plain(pkt, len, hex);
}

/* The pod keys of decode --json for @p hex with @p option ("--pod-order=..." or NULL), checked
 * whole, in order, right after pod_status: raw word, order, flags. */
static void expect_pod(const char *hex, const char *option, const char *want)
{
    tool_result r = (option != NULL) ? run_tool(NULL, "decode", "--json", option, hex, NULL)
                                     : run_tool(NULL, "decode", "--json", hex, NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(r.err_len, 0);
    if (strstr(r.out, want) == NULL) {
        print_error("expected %s\nin %s", want, r.out);
        fail();
    }
    json_decref(parse_line(r.out)); /* and the line is JSON */
    tool_result_free(&r);
}

static void test_pod_order_json(void **state)
{
    char hex[2 * XF_PACKET_MAX_LEN + 1];
    tool_result r;
    json_t *o, *flags;
    (void)state;
    /* the vendor's example: only the big-endian reading leaves the reserved bits clear */
    r = run_tool(NULL, "decode", "--json", V206_REPLY_HEX, NULL);
    assert_int_equal(r.status, 0);
    o = parse_line(r.out);
    assert_int_equal(int_key(o, "pod_status"), 0x8001); /* the raw little-endian wire integer */
    assert_string_equal(str_key(o, "pod_status_order"), "be");
    flags = json_object_get(o, "pod_flags");
    assert_true(json_is_array(flags));
    assert_int_equal(json_array_size(flags), 2);
    assert_string_equal(json_string_value(json_array_get(flags, 0)), "target_valid");
    assert_string_equal(json_string_value(json_array_get(flags, 1)), "ranging_on");
    json_decref(o);
    tool_result_free(&r);
    expect_pod(V206_REPLY_HEX, NULL,
               "\"pod_status\":32769,\"pod_status_order\":\"be\",\"pod_flags\":[\"target_valid\",\"ranging_on\"],");

    /* only the little-endian reading fits: 01 10, tracking and mounted upside down */
    pod_packet_hex(0x01, 0x10, hex);
    expect_pod(hex, NULL,
               "\"pod_status\":4097,\"pod_status_order\":\"le\",\"pod_flags\":[\"tracking_ok\",\"upward_mount\"],");
    /* 80 01: the same two flags as the vendor's example, sent little-endian */
    pod_packet_hex(0x80, 0x01, hex);
    expect_pod(hex, NULL,
               "\"pod_status\":384,\"pod_status_order\":\"le\",\"pod_flags\":[\"target_valid\",\"ranging_on\"],");
    /* every flag, big-endian: 17 81 */
    pod_packet_hex(0x17, 0x81, hex);
    expect_pod(hex, NULL,
               "\"pod_status\":33047,\"pod_status_order\":\"be\",\"pod_flags\":[\"tracking_ok\",\"target_valid\","
               "\"ranging_on\",\"night_vision_on\",\"lighting_on\",\"upward_mount\"],");
    /* undecided, both readings fit (01 00: tracking, or ranging): the documented order */
    pod_packet_hex(0x01, 0x00, hex);
    expect_pod(hex, NULL, "\"pod_status\":1,\"pod_status_order\":\"le\",\"pod_flags\":[\"tracking_ok\"],");
    pod_packet_hex(0x00, 0x01, hex);
    expect_pod(hex, NULL, "\"pod_status\":256,\"pod_status_order\":\"le\",\"pod_flags\":[\"ranging_on\"],");
    pod_packet_hex(0x00, 0x00, hex);
    expect_pod(hex, NULL, "\"pod_status\":0,\"pod_status_order\":\"le\",\"pod_flags\":[],");
    /* undecided, neither fits (02 08: bits 1 and 11, or 3 and 9): the documented order, named bits only */
    pod_packet_hex(0x02, 0x08, hex);
    expect_pod(hex, NULL, "\"pod_status\":2050,\"pod_status_order\":\"le\",\"pod_flags\":[],");

    /* host packets have no pod status */
    r = run_tool(NULL, "decode", "--json", APPENDIX1_HEX, NULL);
    assert_null(strstr(r.out, "pod_"));
    tool_result_free(&r);
}

static void test_pod_order_option(void **state)
{
    char hex[2 * XF_PACKET_MAX_LEN + 1], *input;
    tool_result r;
    (void)state;
    /* forced, either way, whatever the data says; pod_status itself never changes */
    expect_pod(V206_REPLY_HEX, "--pod-order=le",
               "\"pod_status\":32769,\"pod_status_order\":\"le\",\"pod_flags\":[\"tracking_ok\"],");
    expect_pod(V206_REPLY_HEX, "--pod-order=be",
               "\"pod_status\":32769,\"pod_status_order\":\"be\",\"pod_flags\":[\"target_valid\",\"ranging_on\"],");
    expect_pod(V206_REPLY_HEX, "--pod-order=auto",
               "\"pod_status\":32769,\"pod_status_order\":\"be\",\"pod_flags\":[\"target_valid\",\"ranging_on\"],");
    pod_packet_hex(0x01, 0x00, hex);
    expect_pod(hex, "--pod-order=be", "\"pod_status\":1,\"pod_status_order\":\"be\",\"pod_flags\":[\"ranging_on\"],");
    pod_packet_hex(0x01, 0x10, hex); /* big-endian 0x0110: ranging, and reserved bit 4 (not named) */
    expect_pod(hex, "--pod-order=be",
               "\"pod_status\":4097,\"pod_status_order\":\"be\",\"pod_flags\":[\"ranging_on\"],");

    /* the value as the next argument, and on stdin */
    r = run_tool(V206_REPLY_HEX, "decode", "--pod-order", "le", "--json", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "\"pod_status_order\":\"le\",\"pod_flags\":[\"tracking_ok\"]"));
    tool_result_free(&r);

    /* the table reads the flags the same way, and says when it reads them big-endian */
    r = run_tool(NULL, "decode", V206_REPLY_HEX, NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "0x8001       target_valid ranging_on (read big-endian"));
    tool_result_free(&r);
    r = run_tool(NULL, "decode", "--pod-order", "le", V206_REPLY_HEX, NULL);
    assert_non_null(strstr(r.out, "0x8001       tracking_ok reserved bits 0x8000 (read little-endian: --pod-order)"));
    tool_result_free(&r);
    pod_packet_hex(0x01, 0x10, hex);
    r = run_tool(NULL, "decode", hex, NULL);
    assert_non_null(strstr(r.out, "0x1001       tracking_ok upward_mount\n"));
    tool_result_free(&r);
    /* and when the data leaves the order open */
    pod_packet_hex(0x01, 0x00, hex);
    r = run_tool(NULL, "decode", hex, NULL);
    assert_non_null(strstr(r.out, "0x0001       tracking_ok (read little-endian: big-endian would fit too)\n"));
    tool_result_free(&r);
    pod_packet_hex(0x02, 0x08, hex);
    r = run_tool(NULL, "decode", hex, NULL);
    assert_non_null(
        strstr(r.out, "0x0802       reserved bits 0x802 (read little-endian: both orders set reserved bits)\n"));
    tool_result_free(&r);

    /* decode --json | encode --json gives back the bytes: the new keys are accepted */
    r = run_tool(NULL, "decode", "--json", V206_REPLY_HEX, NULL);
    input = strdup(r.out);
    tool_result_free(&r);
    r = run_tool(input, "encode", "--json", "-", NULL);
    assert_int_equal(r.status, 0);
    assert_string_equal(r.out, V206_REPLY_HEX "\n");
    tool_result_free(&r);
    free(input);

    /* bad values */
    r = run_tool(NULL, "decode", "--pod-order", "little", V206_REPLY_HEX, NULL);
    assert_failure(&r, 2, "decode: --pod-order little: must be le, be or auto", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "decode", V206_REPLY_HEX, "--pod-order", NULL);
    assert_failure(&r, 2, "decode: --pod-order needs a value", NULL);
    tool_result_free(&r);
}

/* ---- faults in arguments -------------------------------------------------------------- */

static void test_argument_faults(void **state)
{
    uint8_t pkt[72];
    char hex[2 * 80 + 1], odd[2 * 72 + 2];
    tool_result r;
    (void)state;

    memcpy(pkt, appendix1, 72);
    pkt[71] ^= 1u;
    hex_plain(pkt, 72, hex);
    r = run_tool(NULL, "decode", hex, NULL);
    assert_failure(&r, 2, "argument 1", "bad CRC", "E9 D5", "E9 D4", NULL);
    tool_result_free(&r);

    r = run_tool(NULL, "decode", "--json", APPENDIX1_HEX, hex, NULL); /* nothing printed for the good one */
    assert_failure(&r, 2, "argument 2", "bad CRC", NULL);
    tool_result_free(&r);

    hex_plain(appendix1, 50, hex);
    r = run_tool(NULL, "decode", hex, NULL);
    assert_failure(&r, 2, "truncated", "50 bytes", NULL);
    tool_result_free(&r);

    memcpy(pkt, appendix1, 72);
    pkt[0] = 0x12;
    hex_plain(pkt, 72, hex);
    r = run_tool(NULL, "decode", hex, NULL);
    assert_failure(&r, 2, "bad header", "12 E5", NULL);
    tool_result_free(&r);

    memcpy(pkt, appendix1, 72);
    pkt[2] = 0x20; /* length 32 */
    hex_plain(pkt, 72, hex);
    r = run_tool(NULL, "decode", hex, NULL);
    assert_failure(&r, 2, "bad length", "32", NULL);
    tool_result_free(&r);

    hex_plain(appendix1, 72, hex);
    strcat(hex, "00");
    r = run_tool(NULL, "decode", hex, NULL);
    assert_failure(&r, 2, "bad length", "73 bytes", NULL);
    tool_result_free(&r);

    hex_plain(appendix1, 72, odd);
    odd[5] = 'g';
    r = run_tool(NULL, "decode", odd, NULL);
    assert_failure(&r, 2, "argument 1, position 6", "'g' is not a hex digit", NULL);
    tool_result_free(&r);

    r = run_tool(NULL, "decode", APPENDIX1_HEX, "A8 E5 4", NULL);
    assert_failure(&r, 2, "argument 2, position 7", "odd number of hex digits", NULL);
    tool_result_free(&r);

    r = run_tool(NULL, "decode", "", NULL);
    assert_failure(&r, 2, "argument 1", "no hex digits", NULL);
    tool_result_free(&r);
}

/* ---- stdin ------------------------------------------------------------------------------------ */

static char *spaced(const uint8_t *b, size_t n)
{
    char *s = malloc(3u * n + 2u);
    assert_non_null(s);
    hex_line(b, n, s);
    return s;
}

static void test_stdin_noisy(void **state)
{
    uint8_t gcu[XF_PACKET_MAX_LEN];
    static const uint8_t ok = 0;
    size_t glen = gcu_packet(2, XF_ORDER_SHUTTER, &ok, 1, gcu);
    char *a = spaced(appendix1, 72), *g = spaced(gcu, glen);
    char input[4096];
    tool_result r;
    json_t *o;
    const char *line;
    (void)state;
    /* noise, a false candidate (its CRC fails), the example, a false header, the GCU reply, noise; any layout */
    snprintf(input, sizeof(input), "12 34 8A\n0xA8,0xE5 48 00 01 02 03\r\n%s\n99 88 a8e5 ff00\n%s  \t77 66:55\n%.*s", a,
             g, 99, a);
    r = run_tool(input, "decode", "--json", NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(r.err_len, 0);
    o = cut_summary(&r); /* the stream's last word: two packets, no frame given up */
    assert_int_equal(int_key(o, "host_packets"), 1);
    assert_int_equal(int_key(o, "gcu_packets"), 1);
    assert_int_equal(int_key(o, "given_up"), 0);
    json_decref(o);
    assert_int_equal(count_lines(r.out), 2);
    o = parse_line(r.out);
    assert_true(num_key(o, "vel_east") == -21.12);
    json_decref(o);
    line = strchr(r.out, '\n') + 1;
    o = parse_line(line);
    assert_string_equal(str_key(o, "direction"), "gcu");
    assert_string_equal(str_key(json_object_get(o, "feedback"), "result"), "ok");
    json_decref(o);
    tool_result_free(&r);

    /* the table says where each packet starts */
    r = run_tool(input, "decode", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "host packet (stdin offset"));
    assert_non_null(strstr(r.out, "gcu packet (stdin offset"));
    tool_result_free(&r);
    free(a);
    free(g);
}

/* A false header with a long length holds the host parser back: a host
 * packet inside it is found after a GCU packet that starts later. The
 * output is still in stream order, and a false header just before the end
 * of the input does not hide the packets after it. */
static void test_stdin_stream_order(void **state)
{
    uint8_t gcu[XF_PACKET_MAX_LEN];
    size_t glen = gcu_packet(1, XF_ORDER_NULL, NULL, 0, gcu);
    char *a = spaced(appendix1, 72), *g = spaced(gcu, glen);
    char input[4096];
    tool_result r;
    (void)state;
    snprintf(input, sizeof(input), "A8 E5 F0 00\n%s%s", a, g);
    r = run_tool(input, "decode", "--json", NULL);
    assert_int_equal(r.status, 0);
    json_decref(cut_summary(&r));
    assert_int_equal(count_lines(r.out), 2);
    assert_non_null(strstr(r.out, "{\"direction\":\"host\""));
    assert_true(strstr(r.out, "\"direction\":\"host\"") < strstr(r.out, "\"direction\":\"gcu\""));
    tool_result_free(&r);

    snprintf(input, sizeof(input), "%s A8 E5 F0 00 %s", g, a);
    r = run_tool(input, "decode", "--json", NULL);
    json_decref(cut_summary(&r));
    assert_int_equal(count_lines(r.out), 2);
    assert_true(strstr(r.out, "\"direction\":\"gcu\"") < strstr(r.out, "\"direction\":\"host\""));
    tool_result_free(&r);
    free(a);
    free(g);
}

static void test_stdin_faults(void **state)
{
    char input[1024];
    char *a = spaced(appendix1, 72);
    tool_result r;
    (void)state;
    r = run_tool("A8 E5 48\n00 garbage 01\n", "decode", NULL);
    assert_failure(&r, 2, "stdin", "line 2 column 4", "offset 12", "'g' is not a hex digit", NULL);
    tool_result_free(&r);

    r = run_tool("A8 E5 4\n", "decode", NULL);
    assert_failure(&r, 2, "stdin", "line 1 column 7", "odd number", NULL);
    tool_result_free(&r);

    r = run_tool("12 34 56\n", "decode", NULL);
    assert_failure(&r, 2, "no valid packet", "3 bytes", NULL);
    tool_result_free(&r);

    r = run_tool(NULL, "decode", NULL);
    assert_failure(&r, 2, "no valid packet", NULL);
    tool_result_free(&r);

    /* the packets before a hex fault are printed, then the fault fails the command */
    snprintf(input, sizeof(input), "%s zz\n", a);
    r = run_tool(input, "decode", "--json", NULL);
    assert_int_equal(r.status, 2);
    assert_int_equal(count_lines(r.out), 1);
    assert_non_null(strstr(r.err, "'z' is not a hex digit"));
    tool_result_free(&r);
    free(a);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_appendix1_json),     cmocka_unit_test(test_appendix1_engineering),
        cmocka_unit_test(test_appendix1_layouts),  cmocka_unit_test(test_appendix1_table),
        cmocka_unit_test(test_gcu_versions),       cmocka_unit_test(test_host_command_extra),
        cmocka_unit_test(test_argument_faults),    cmocka_unit_test(test_stdin_noisy),
        cmocka_unit_test(test_stdin_stream_order), cmocka_unit_test(test_stdin_faults),
        cmocka_unit_test(test_pod_order_json),     cmocka_unit_test(test_pod_order_option),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
