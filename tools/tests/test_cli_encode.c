/*
 * test_cli_encode.c - `xfgcu encode`: every named command against bytes
 * written out from the spec's tables, range and usage errors, encode
 * --json, and decode -> encode round trips over many packets of both
 * directions and versions (by argument, by JSON Lines and through a noisy
 * stream).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "run_tool.h"
#include "xfgcu/xfgcu.h"

/* The host packet of a named command: no carrier data, sub_request 0x01. */
static void expected_packet(uint8_t version, uint8_t order, const uint8_t *params, size_t n, char *line)
{
    uint8_t pkt[XF_PACKET_MAX_LEN];
    memset(pkt, 0, sizeof(pkt));
    pkt[0] = 0xA8;
    pkt[1] = 0xE5;
    pkt[4] = version;
    pkt[30] = 0x01; /* sub_request */
    pkt[69] = order;
    memcpy(pkt + 70, params, n);
    seal_packet(pkt, 72u + n);
    hex_line(pkt, 72u + n, line);
}

/* "encode", then @p args up to the first NULL (at most 10), into @p argv; returns how many. */
static int encode_argv(const char *const *args, const char **argv)
{
    int argc = 1;
    argv[0] = "encode";
    while (argc <= 10 && args[argc - 1] != NULL) {
        argv[argc] = args[argc - 1];
        argc++;
    }
    return argc;
}

/* ---- named commands ------------------------------------------------------------------- */

typedef struct named_case {
    const char *args[10]; /* after "encode", NULL-terminated */
    uint8_t version, order, n;
    uint8_t params[12];
} named_case;

static const named_case cases[] = {
    {{"null"}, 1, 0x00, 0, {0}},
    {{"calibration"}, 1, 0x01, 0, {0}},
    {{"neutral"}, 1, 0x03, 0, {0}},
    {{"angle-control"}, 1, 0x10, 0, {0}},
    {{"head-lock"}, 1, 0x11, 0, {0}},
    {{"head-follow"}, 1, 0x12, 0, {0}},
    {{"orthoview"}, 1, 0x13, 0, {0}},
    {{"euler"}, 1, 0x14, 0, {0}},
    {{"gaze-lock"}, 1, 0x16, 0, {0}},
    {{"fpv", "--protocol", "2"}, 2, 0x1C, 0, {0}},
    {{"zoom-to", "--factor", "5.5", "--cameras", "all"}, 1, 0x25, 3, {0xFF, 0xC9, 0xFF}},
    {{"zoom-to", "--rate", "5.5", "--cameras", "all"}, 1, 0x25, 3, {0xFF, 0xC9, 0xFF}}, /* its old spelling */
    {{"zoom-to", "--fraction", "10000", "--cameras", "2"}, 1, 0x25, 3, {0x02, 0x10, 0x27}},
    {{"zoom-to", "--rate=1"}, 1, 0x25, 3, {0x01, 0xF6, 0xFF}},
    {{"gaze-geo", "--lat", "22.5", "--lon", "113.25", "--alt", "100.5"},
     1,
     0x15,
     12,
     {0x20, 0x94, 0x80, 0x43, 0x40, 0x3A, 0x69, 0x0D, 0x94, 0x88, 0x01, 0x00}},
    {{"gaze-geo", "--lon", "-122.5", "--lat", "-33.75", "--alt", "-5"},
     1,
     0x15,
     12,
     {0xC0, 0xFB, 0xFB, 0xB6, 0xA0, 0x28, 0xE2, 0xEB, 0x78, 0xEC, 0xFF, 0xFF}},
    {{"track", "--start", "--box", "1000,2000,3000,4000"},
     1,
     0x17,
     10,
     {0x01, 0x01, 0xE8, 0x03, 0xD0, 0x07, 0xB8, 0x0B, 0xA0, 0x0F}},
    {{"track", "--stop"}, 1, 0x17, 10, {0x01, 0x00}},
    {{"click-to-aim", "--at", "5000,5000"}, 1, 0x1A, 5, {0x01, 0x88, 0x13, 0x88, 0x13}},
    {{"external-track", "--start", "--offset", "-100,200"}, 1, 0x1B, 6, {0x01, 0x9C, 0xFF, 0xC8, 0x00, 0x02}},
    {{"external-track", "--stop"}, 1, 0x1B, 6, {0x01}},
    {{"shutter"}, 1, 0x20, 1, {0x01}},
    {{"record", "--cameras", "1,2"}, 1, 0x21, 1, {0x03}},
    {{"zoom-in", "--cameras", "0x03"}, 1, 0x22, 1, {0x03}},
    {{"zoom-in", "--cameras", "3"}, 1, 0x22, 1, {0x04}}, /* a decimal number is a camera, not a mask */
    {{"zoom-in", "--cameras", "2,3"}, 1, 0x22, 1, {0x06}},
    {{"zoom-out"}, 1, 0x23, 1, {0x01}},
    {{"zoom-stop", "--cameras=2"}, 1, 0x24, 1, {0x02}},
    {{"focus"}, 1, 0x26, 1, {0x01}},
    {{"palette", "--mode", "3"}, 1, 0x2A, 2, {0x02, 0x03}},
    {{"palette", "--mode", "0", "--cameras", "1"}, 1, 0x2A, 2, {0x01, 0x00}},
    {{"night-vision", "--mode", "auto"}, 1, 0x2B, 2, {0x01, 0x02}},
    {{"night-vision", "--mode", "off"}, 1, 0x2B, 2, {0x01, 0x00}},
    {{"osd", "--hide"}, 1, 0x73, 1, {0x01}},
    {{"osd", "--show"}, 1, 0x73, 1, {0x00}},
    /* V0.2 inverted the meaning: 1 = on (docs/protocol.md §11.4) */
    {{"--protocol", "2", "osd", "--hide"}, 2, 0x73, 1, {0x00}},
    {{"osd", "--show", "--protocol", "2"}, 2, 0x73, 1, {0x01}},
    {{"pip", "--mode", "0"}, 1, 0x74, 1, {0x00}},
    {{"pip", "--mode", "3", "--protocol", "2"}, 2, 0x74, 1, {0x03}},
    {{"lighting", "--level", "128"}, 1, 0x80, 1, {0x80}},
    {{"ranging", "--on"}, 1, 0x81, 1, {0x02}},
    {{"ranging", "--off"}, 1, 0x81, 1, {0x00}},
    {{"--protocol", "2", "osd-coordinate", "--target"}, 2, 0x06, 1, {0x01}},
    {{"auto-flip", "--off", "--protocol", "2"}, 2, 0x07, 1, {0x01}},
    {{"auto-flip", "--on", "--protocol", "2"}, 2, 0x07, 1, {0x00}},
    {{"time-zone", "--hours", "-2", "--protocol", "2"}, 2, 0x08, 1, {0xFE}},
    {{"area-temp", "--on", "--box", "100,200,300,400", "--protocol", "2"},
     2,
     0x30,
     10,
     {0x02, 0x01, 0x64, 0x00, 0xC8, 0x00, 0x2C, 0x01, 0x90, 0x01}},
    {{"temp-alarm", "--on", "--high", "50.5", "--low", "-10", "--protocol", "2"},
     2,
     0x31,
     6,
     {0x02, 0x01, 0xF9, 0x01, 0x9C, 0xFF}},
    {{"isotherm", "--off", "--protocol", "2"}, 2, 0x32, 6, {0x02, 0x00}},
    {{"spot-temp", "--on", "--at", "100,200", "--protocol", "2"}, 2, 0x33, 6, {0x02, 0x01, 0x64, 0x00, 0xC8, 0x00}},
    {{"target-detection", "--on", "--protocol", "2"}, 2, 0x75, 1, {0x01}},
    {{"digital-zoom", "--off", "--protocol", "2"}, 2, 0x76, 1, {0x00}},
};

static void test_named_commands(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        const char *argv[12];
        char want[3 * XF_PACKET_MAX_LEN + 1];
        int argc = encode_argv(cases[i].args, argv);
        tool_result r;
        expected_packet(cases[i].version, cases[i].order, cases[i].params, cases[i].n, want);
        r = run_tool_argv(argc, argv, NULL);
        if (r.status != 0 || strcmp(r.out, want) != 0) {
            print_error("encode %s ...: status %d\n got: %s want: %s stderr: %s\n", argv[1], r.status, r.out, want,
                        r.err);
            fail();
        }
        tool_result_free(&r);
    }
}

/* The acceptance example, spelled out byte by byte. */
static void test_zoom_to_bytes(void **state)
{
    tool_result r = run_tool(NULL, "encode", "zoom-to", "--rate", "5.5", "--cameras", "all", NULL);
    (void)state;
    assert_int_equal(r.status, 0);
    assert_int_equal(r.out_len, 3u * 75u);
    assert_true(strncmp(r.out, "A8 E5 4B 00 01 00 00", 20) == 0);
    assert_true(strncmp(r.out + 3 * 30, "01 ", 3) == 0);
    assert_true(strncmp(r.out + 3 * 69, "25 FF C9 FF ", 12) == 0);
    tool_result_free(&r);
}

/* Every order of the codec's table has a command with its own help and summary. */
static void test_every_order_has_a_command(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        const xf_order_info *info = xf_order_at(i);
        char name[32], want[48];
        size_t k;
        tool_result r;
        for (k = 0; xf_order_name(info->order)[k] != '\0'; k++) {
            name[k] = xf_order_name(info->order)[k] == '_' ? '-' : xf_order_name(info->order)[k];
        }
        name[k] = '\0';
        snprintf(want, sizeof(want), "order 0x%02X %s", info->order, xf_order_name(info->order));
        r = run_tool(NULL, "encode", name, "--help", NULL);
        /* its summary (the command line's own row for the order) ends the line before */
        if (r.status != 0 || strstr(r.out, want) == NULL || strstr(r.out, name) == NULL ||
            strstr(r.out, ".\norder 0x") == NULL) {
            print_error("encode %s --help: status %d\n%s%s", name, r.status, r.out, r.err);
            fail();
        }
        tool_result_free(&r);
    }
}

static void test_protocol_placement(void **state)
{
    tool_result r = run_tool(NULL, "--protocol", "2", "encode", "shutter", NULL);
    (void)state;
    assert_true(strncmp(r.out, "A8 E5 49 00 02", 14) == 0);
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "--protocol=2", "shutter", NULL);
    assert_true(strncmp(r.out, "A8 E5 49 00 02", 14) == 0);
    tool_result_free(&r);
    r = run_tool(NULL, "--protocol", "2", "encode", "shutter", "--protocol", "1", NULL); /* the last one wins */
    assert_true(strncmp(r.out, "A8 E5 49 00 01", 14) == 0);
    tool_result_free(&r);
    /* a V0.2 order with version 1 is built, with a note */
    r = run_tool(NULL, "encode", "fpv", NULL);
    assert_int_equal(r.status, 0);
    assert_true(strncmp(r.out, "A8 E5 48 00 01", 14) == 0);
    assert_non_null(strstr(r.err, "note: fpv is an order of protocol 2"));
    tool_result_free(&r);
    /* external_track, dropped by V0.2: built, with a note for version 2 only */
    r = run_tool(NULL, "encode", "external-track", "--start", "--offset", "10,-10", "--protocol", "2", NULL);
    assert_int_equal(r.status, 0);
    assert_true(strncmp(r.out, "A8 E5 4E 00 02", 14) == 0);
    assert_non_null(strstr(r.err, "note: external-track is an order of protocol 1 (V0.1) that V0.2 no longer lists"));
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "external-track", "--start", "--offset", "10,-10", NULL);
    assert_int_equal(r.status, 0);
    assert_null(strstr(r.err, "no longer lists"));
    tool_result_free(&r);
}

/* ---- range and usage errors ----------------------------------------------------------- */

typedef struct error_case {
    const char *args[10];
    const char *needles[3];
} error_case;

static const error_case errors[] = {
    {{"zoom-to", "--rate", "0.5"}, {"encode zoom-to: --rate 0.5 is out of range", "1.0..3276.8"}},
    {{"zoom-to", "--rate", "5x"}, {"--rate 5x", "expected a number"}},
    {{"zoom-to", "--fraction", "0"}, {"--fraction 0 is out of range", "1 (min)..10000 (max)"}},
    {{"zoom-to", "--fraction", "10001"}, {"--fraction 10001 is out of range"}},
    {{"zoom-to", "--rate", "2", "--fraction", "3"}, {"--rate and --fraction exclude each other"}},
    {{"zoom-to", "--factor", "2", "--fraction", "3"}, {"--factor and --fraction exclude each other"}},
    {{"zoom-to", "--factor", "2", "--rate", "3"}, {"--rate given twice"}}, /* the old spelling of --factor */
    {{"zoom-to", "--factor", "0.5"}, {"encode zoom-to: --factor 0.5 is out of range", "1.0..3276.8"}},
    {{"zoom-to"}, {"give --factor X or --fraction N"}},
    {{"lighting", "--level", "256"}, {"--level 256 is out of range", "0..255"}},
    {{"lighting"}, {"missing --level N"}},
    {{"time-zone", "--hours", "15", "--protocol", "2"}, {"--hours 15 is out of range", "-12..14"}},
    {{"palette", "--mode", "11", "--protocol", "2"}, {"--mode 11 is out of range for protocol 2", "0..10"}},
    {{"palette", "--mode", "101"}, {"--mode 101 is out of range for protocol 1", "0..100"}},
    {{"pip", "--mode", "1"}, {"--mode 1 is out of range for protocol 1"}},
    {{"pip", "--mode", "5", "--protocol", "2"}, {"--mode 5 is out of range for protocol 2", "0..4"}},
    {{"night-vision", "--mode", "dim"}, {"--mode dim", "off|on|auto"}},
    {{"gaze-geo", "--lat", "91", "--lon", "0", "--alt", "0"}, {"--lat 91 is out of range", "-90..90"}},
    {{"gaze-geo", "--lat", "1", "--lon", "180.5", "--alt", "0"}, {"--lon 180.5 is out of range", "-180..180"}},
    {{"gaze-geo", "--lat", "1", "--lon", "2"}, {"missing --alt M"}},
    {{"gaze-geo", "--lat", "nan", "--lon", "2", "--alt", "3"}, {"--lat nan", "expected a number"}},
    {{"track", "--start", "--box", "0,0,10001,5"}, {"--box 0,0,10001,5 is out of range", "0..10000"}},
    {{"track", "--start", "--box", "500,500,100,100"}, {"--box 500,500,100,100 is out of range", "X0 <= X1"}},
    {{"track", "--start", "--box", "1,2,3"}, {"--box 1,2,3", "expected X0,Y0,X1,Y1"}},
    {{"track", "--start"}, {"--start needs --box X0,Y0,X1,Y1"}},
    {{"track", "--stop", "--box", "1,2,3,4"}, {"--box goes only with --start"}},
    {{"track", "--start", "--stop", "--box", "1,2,3,4"}, {"--start and --stop exclude each other"}},
    {{"track"}, {"give --start --box X0,Y0,X1,Y1 or --stop"}},
    {{"click-to-aim", "--at", "10001,0"}, {"--at 10001,0 is out of range", "0..10000"}},
    {{"external-track", "--start", "--offset", "2000,0"}, {"--offset 2000,0 is out of range", "-1024..1024"}},
    {{"temp-alarm", "--on", "--high", "10", "--low", "20", "--protocol", "2"},
     {"--low 20 is out of range", "not above --high"}},
    {{"temp-alarm", "--on", "--high", "5000", "--low", "0", "--protocol", "2"}, {"--high 5000 is out of range"}},
    {{"shutter", "--cameras", "0"}, {"--cameras 0", "camera numbers 1..8"}},
    {{"shutter", "--cameras", "0x00"}, {"--cameras 0x00", "0x01..0xFF"}},
    {{"shutter", "--cameras", "0x100"}, {"--cameras 0x100", "0x01..0xFF"}},
    {{"shutter", "--cameras", "3,"}, {"--cameras 3,", "camera numbers 1..8"}},
    {{"shutter", "--cameras", ",3"}, {"--cameras ,3"}},
    {{"shutter", "--cameras", "1,,2"}, {"--cameras 1,,2"}},
    {{"shutter", "--cameras", "1,1"}, {"camera 1 given twice"}},
    {{"shutter", "--cameras", "9"}, {"--cameras 9"}},
    {{"shutter", "--cameras", "1,9"}, {"--cameras 1,9", "1..8"}},
    {{"shutter", "--cameras", "lots"}, {"--cameras lots"}},
    {{"shutter", "--cameras"}, {"--cameras needs a value"}},
    {{"shutter", "--cameras", "1", "--cameras", "2"}, {"--cameras given twice"}},
    {{"shutter", "--frobnicate"}, {"encode shutter: unknown option '--frobnicate'"}},
    {{"null", "--cameras", "1"}, {"encode null: unknown option '--cameras'"}},
    {{"shutter", "extra"}, {"unexpected argument 'extra'"}},
    {{"osd", "--hide=1"}, {"--hide takes no value"}},
    {{"osd", "--hide", "--hide"}, {"--hide given twice"}},
    {{"frobnicate"}, {"encode: unknown command 'frobnicate'"}},
    {{NULL}, {"give --json OBJECT or a COMMAND"}},
};

static void test_errors(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(errors) / sizeof(errors[0]); i++) {
        const char *argv[12];
        int argc = encode_argv(errors[i].args, argv);
        tool_result r;
        r = run_tool_argv(argc, argv, NULL);
        assert_failure(&r, 2, errors[i].needles[0], errors[i].needles[1], errors[i].needles[2], NULL);
        tool_result_free(&r);
    }
}

/* ---- encode --json -------------------------------------------------------------------- */

/* encode --json OBJECT [--raw] gives @p want_line. */
static void expect_json_in(const char *object, int raw, const char *want_line)
{
    tool_result r = raw ? run_tool(NULL, "encode", "--raw", "--json", object, NULL)
                        : run_tool(NULL, "encode", "--json", object, NULL);
    if (r.status != 0 || strcmp(r.out, want_line) != 0) {
        print_error("encode --json %s: status %d\n got: %s want: %s stderr: %s", object, r.status, r.out, want_line,
                    r.err);
        fail();
    }
    tool_result_free(&r);
}

static void expect_json(const char *object, const char *want_line) { expect_json_in(object, 0, want_line); }

static void expect_json_error_in(const char *object, int raw, const char *needle)
{
    tool_result r = raw ? run_tool(NULL, "--raw", "encode", "--json", object, NULL)
                        : run_tool(NULL, "encode", "--json", object, NULL);
    assert_failure(&r, 2, "encode --json", needle, NULL);
    tool_result_free(&r);
}

static void expect_json_error(const char *object, const char *needle) { expect_json_error_in(object, 0, needle); }

static void test_json_input(void **state)
{
    static const uint8_t zoom[3] = {0xFF, 0xC9, 0xFF}, failed3 = 0x03;
    uint8_t pkt[XF_PACKET_MAX_LEN];
    char want[3 * XF_PACKET_MAX_LEN + 1];
    (void)state;
    /* the appendix-1 packet from its fields, as wire integers (--raw) and in engineering units; the
     * extras decode prints are accepted */
    hex_line(appendix1, 72, want);
    expect_json_in(
        "{\"direction\":\"host\",\"version\":1,\"length\":72,\"order\":0,\"order_name\":\"null\","
        "\"params\":\"\","
        "\"pitch_ctrl\":100,\"yaw_ctrl\":-100,\"status\":5,\"carrier_roll\":-1132,\"carrier_pitch\":101,"
        "\"carrier_yaw\":24000,\"accel_north\":112,\"accel_east\":-112,\"accel_up\":112,\"vel_north\":-32704,"
        "\"vel_east\":-2112,\"vel_up\":-32704,\"sub_request\":1,\"sub_header\":1,\"longitude\":1709175332,"
        "\"latitude\":380300822,\"altitude\":41123,\"satellites\":19,\"gnss_ms\":352718000,"
        "\"gnss_week\":2278,\"relative_height\":12120}",
        1, want);
    expect_json("{\"pitch_ctrl\":100,\"yaw_ctrl\":-100,\"status\":5,\"carrier_roll\":-11.32,\"carrier_pitch\":1.01,"
                "\"carrier_yaw\":240,\"accel_north\":1.12,\"accel_east\":-1.12,\"accel_up\":1.12,\"vel_north\":-327.04,"
                "\"vel_east\":-21.12,\"vel_up\":-327.04,\"sub_request\":1,\"sub_header\":1,\"longitude\":170.9175332,"
                "\"latitude\":38.0300822,\"altitude\":41.123,\"satellites\":19,\"gnss_ms\":352718000,"
                "\"gnss_week\":2278,\"relative_height\":12.12}",
                want);
    /* a value computed by a script, a double's error off its step, is that step */
    expect_json("{\"pitch_ctrl\":100,\"yaw_ctrl\":-100,\"status\":5,\"carrier_roll\":-11.319999999999999,"
                "\"carrier_pitch\":1.0100000000000002,\"carrier_yaw\":240,\"accel_north\":1.12,\"accel_east\":-1.12,"
                "\"accel_up\":1.12,\"vel_north\":-327.04,\"vel_east\":-21.12,\"vel_up\":-327.04,\"sub_request\":1,"
                "\"sub_header\":1,\"longitude\":170.9175332,\"latitude\":38.0300822,\"altitude\":41.123,"
                "\"satellites\":19,\"gnss_ms\":352718000,\"gnss_week\":2278,\"relative_height\":12.12}",
                want);

    /* missing fields are 0 (sub_request too); params in either case; order by name; command instead of params */
    memset(pkt, 0, sizeof(pkt));
    pkt[0] = 0xA8;
    pkt[1] = 0xE5;
    pkt[4] = 1;
    pkt[69] = 0x25;
    memcpy(pkt + 70, zoom, 3);
    seal_packet(pkt, 75);
    hex_line(pkt, 75, want);
    expect_json("{\"order\":37,\"params\":\"ffc9ff\"}", want);
    expect_json("{\"order\":\"zoom-to\",\"params\":\"FF C9 FF\"}", want);
    expect_json("{\"order\":37,\"command\":{\"cameras\":255,\"zoom\":-55}}", want); /* ZZ: an integer in both */
    expect_json_in("{\"order\":37,\"command\":{\"cameras\":255,\"zoom\":-55}}", 1, want);
    expect_json("{\"order\":37,\"params\":\"FFC9FF\",\"command\":{\"cameras\":255,\"zoom\":-55}}", want);

    /* a GCU reply from its feedback */
    memset(pkt, 0, sizeof(pkt));
    pkt[0] = 0x8A;
    pkt[1] = 0x5E;
    pkt[4] = 2;
    pkt[69] = 0x22;
    pkt[70] = failed3;
    seal_packet(pkt, 73);
    hex_line(pkt, 73, want);
    expect_json("{\"direction\":\"gcu\",\"version\":2,\"order\":\"zoom_in\","
                "\"feedback\":{\"result\":\"failed\",\"failed_cameras\":3}}",
                want);

    /* the version defaults to --protocol */
    {
        tool_result r = run_tool(NULL, "encode", "--protocol", "2", "--json", "{}", NULL);
        assert_true(strncmp(r.out, "A8 E5 48 00 02 00", 17) == 0);
        tool_result_free(&r);
    }
}

static void test_json_errors(void **state)
{
    (void)state;
    expect_json_error("{\"direction\":\"host\",\"bogus\":1}", "unknown key 'bogus' for a host packet");
    expect_json_error("{\"gimbal_mode\":1}", "unknown key 'gimbal_mode' for a host packet");
    expect_json_error("{\"direction\":\"gcu\",\"roll_ctrl\":1}", "unknown key 'roll_ctrl' for a gcu packet");
    expect_json_error("{\"direction\":\"gcu\",\"command\":{}}", "unknown key 'command'");
    expect_json_error("{\"direction\":\"gcu\",\"version\":1,\"thermal_status\":1}",
                      "'thermal_status' needs version >= 2");
    expect_json_error("{\"direction\":\"sideways\"}", "direction must be");
    expect_json_error_in("{\"vel_north\":40000}", 1, "vel_north 40000 is out of range -32768..32767");
    expect_json_error_in("{\"vel_north\":1.5}", 1, "vel_north must be an integer");
    expect_json_error_in("{\"vel_north\":\"5\"}", 1, "vel_north must be an integer");
    expect_json_error("{\"gnss_ms\":-1}", "gnss_ms -1 is out of range 0..4294967295");
    /* engineering units: out of range, between two steps (never rounded), not a number */
    expect_json_error("{\"vel_north\":400}", "vel_north 400 is out of range -327.68..327.67 m/s");
    expect_json_error("{\"vel_north\":1.234}", "vel_north 1.234 is not a whole number of steps of 0.01 m/s");
    expect_json_error("{\"latitude\":22.12345678}",
                      "latitude 22.12345678 is not a whole number of steps of 0.0000001 deg");
    expect_json_error("{\"vel_north\":\"5\"}", "vel_north must be a number (m/s), -327.68..327.67");
    expect_json_error("{\"satellites\":1.5}", "satellites must be an integer");
    expect_json_error("{\"direction\":\"gcu\",\"hw_version\":3.14}",
                      "hw_version 3.14 is not a whole number of steps of 0.1");
    expect_json_error("{\"order\":\"gaze_geo\",\"command\":{\"altitude\":1.0001}}", "command.altitude 1.0001 is not");
    expect_json_error("{\"version\":256}", "version 256 is out of range");
    expect_json_error("{\"order\":300}", "order must be an integer 0..255 or the name");
    expect_json_error("{\"order\":\"warp\"}", "order must be");
    expect_json_error("{\"params\":\"FG\"}", "params, position 2: 'G' is not a hex digit");
    expect_json_error("{\"params\":\"F\"}", "params, position 1: odd number");
    expect_json_error("{\"params\":7}", "params must be a string");
    expect_json_error("{\"order\":37,\"params\":\"FFC9FF\",\"length\":72}", "length 72 disagrees");
    expect_json_error("{\"reserved_main\":\"01\"}", "reserved_main must hold 6 bytes");
    expect_json_error("{\"direction\":\"gcu\",\"version\":2,\"reserved_sub\":\"000000000000\"}",
                      "reserved_sub must hold 2 bytes");
    expect_json_error("{\"order\":37,\"params\":\"FFC9FF\",\"command\":{\"cameras\":1,\"zoom\":-55}}",
                      "command and params disagree");
    expect_json_error("{\"order\":37,\"command\":{\"zoom\":0}}", "command.zoom is out of range");
    expect_json_error("{\"order\":37,\"command\":{\"speed\":1}}", "command.speed is not a parameter of zoom_to");
    expect_json_error("{\"order\":240,\"command\":{}}", "command needs a known order");
    expect_json_error("{\"direction\":\"gcu\",\"feedback\":{\"result\":\"meh\"}}", "feedback.result");
    expect_json_error("{\"a\":", "invalid JSON");
    expect_json_error("{\"order\":1,\"order\":2}", "invalid JSON");
    expect_json_error("[1]", "expected a JSON object");
    {
        tool_result r = run_tool(NULL, "encode", "--json", "{}", "shutter", NULL);
        assert_failure(&r, 2, "--json takes one OBJECT", NULL);
        tool_result_free(&r);
        r = run_tool("{}\n{\"order\":32}\n", "encode", "--json", NULL); /* no OBJECT: JSON Lines on stdin */
        assert_int_equal(r.status, 0);
        assert_int_equal(count_lines(r.out), 2);
        tool_result_free(&r);
        r = run_tool(NULL, "encode", "--json", "{}", "--json", "{}", NULL);
        assert_failure(&r, 2, "--json given twice", NULL);
        tool_result_free(&r);
        r = run_tool("{}\n{\"bogus\":1}\n", "encode", "--json", "-", NULL);
        assert_int_equal(r.status, 2);
        assert_int_equal(count_lines(r.out), 1);
        assert_non_null(strstr(r.err, "stdin line 2: unknown key 'bogus'"));
        tool_result_free(&r);
    }
}

/* JSON Lines on stdin, and a capture on stdin: a NUL byte, a truncated object or anything after
 * it is an error (exit 2, one line) that names the line; what came before it is printed. */
typedef struct line_fault {
    const char *input;
    size_t len; /* with the NUL bytes */
    const char *args[4];
    size_t good_lines; /* packets printed before the bad line */
    const char *needles[3];
} line_fault;

#define TEXT(s) s, sizeof(s) - 1u

static const line_fault line_faults[] = {
    {TEXT("{\"order\":32}\0{\"garbage\n"), {"encode", "--json", "-"}, 0, {"stdin line 1", "NUL byte at column 13"}},
    {TEXT("{\"order\":32}\n{\"order\":3"), {"encode", "--json", "-"}, 1, {"stdin line 2", "invalid JSON"}},
    {TEXT("{\"order\":32} x\n"), {"encode", "--json", "-"}, 0, {"stdin line 1", "invalid JSON at column 14"}},
    {TEXT("{\"order\":32}{\"order\":1}\n"), {"encode", "--json", "-"}, 0, {"stdin line 1", "invalid JSON"}},
    {TEXT("\n \n{\"order\":}\n"), {"encode", "--json", "-"}, 0, {"stdin line 3", "invalid JSON"}},
    {TEXT("{\"order\":32}\n\0\n"), {"encode", "--json", "-"}, 1, {"stdin line 2", "NUL byte at column 1"}},
    {TEXT("# xfgcu capture 1\n0.000 > A8\0E5\n"), {"replay", "-"}, 0, {"-:2: ", "NUL byte"}},
    {TEXT("A8 E5\0 48\n"), {"decode"}, 0, {"stdin, line 1 column 6", "byte 0x00 is not a hex digit"}},
    {TEXT("# xfgcu capture 1\n0.000 > A8 E5\n0.001 < 8A 5E 4\n"), {"replay", "-", "--json"}, 0, {"-:3: "}},
};

static void test_json_line_faults(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(line_faults) / sizeof(line_faults[0]); i++) {
        const line_fault *c = &line_faults[i];
        int argc = 0;
        tool_result r;
        while (argc < 4 && c->args[argc] != NULL) {
            argc++;
        }
        r = run_tool_bytes(argc, c->args, c->input, c->len);
        if (r.status != 2 || count_lines(r.out) != c->good_lines || count_lines(r.err) != 1 ||
            strncmp(r.err, "xfgcu: ", 7) != 0 || strstr(r.err, c->needles[0]) == NULL ||
            (c->needles[1] != NULL && strstr(r.err, c->needles[1]) == NULL)) {
            print_error("case %zu: status %d\nstdout: %s\nstderr: %s\n", i, r.status, r.out, r.err);
            fail();
        }
        tool_result_free(&r);
    }
    /* the same rule for one object given as an argument */
    expect_json_error("{\"order\":32} x", "invalid JSON at column 14");
    expect_json_error("{\"order\":32", "invalid JSON");
}

/* ---- round trips ------------------------------------------------------------------------ */

static uint32_t next_random(uint32_t *s)
{
    /* xorshift32: deterministic, so a failure can be replayed */
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* Any valid packet: random frames (reserved bytes included, or zeroed), both
 * directions, versions 0..3, known orders with their parameter length or
 * any order with any length up to the limit. */
static size_t random_packet(uint32_t *seed, uint8_t *out)
{
    static const uint8_t versions[] = {1, 2, 1, 2, 0, 3};
    uint32_t pick = next_random(seed);
    int gcu = (int)(pick & 1u);
    size_t i, n;
    uint8_t order;
    if ((pick & 6u) != 0u) {
        const xf_order_info *info = xf_order_at(next_random(seed) % XF_ORDER_COUNT);
        order = info->order;
        n = gcu ? ((pick & 8u) ? 1u : 0u) : xf_order_params_len(order);
    } else {
        order = (uint8_t)next_random(seed);
        n = (pick & 8u) ? next_random(seed) % (XF_PACKET_MAX_LEN - 71u) : next_random(seed) % 13u;
    }
    for (i = 0; i < 72u + n; i++) {
        out[i] = (uint8_t)next_random(seed);
    }
    if ((pick & 16u) != 0u) {
        memset(out + 30, 0, 7); /* reserved main bytes (and host sub_request) zero */
        memset(out + 61, 0, 8); /* reserved sub bytes zero */
    }
    out[0] = gcu ? 0x8A : 0xA8;
    out[1] = gcu ? 0x5E : 0xE5;
    out[4] = versions[(pick >> 8) % sizeof(versions)];
    out[69] = order;
    seal_packet(out, 72u + n);
    return 72u + n;
}

#define ROUND_TRIP_PACKETS 300

typedef struct corpus {
    char *hex[ROUND_TRIP_PACKETS]; /* each packet as compact hex, for arguments */
    char *want;                    /* every packet as encode prints it, one per line */
    char *stream;                  /* all packets in hex text, with noise between */
} corpus;

static void make_corpus(corpus *c)
{
    uint32_t seed = 0x5EEDu;
    size_t i, k, want_len = 0, stream_len = 0;
    c->want = calloc(ROUND_TRIP_PACKETS, 3u * XF_PACKET_MAX_LEN + 1u);
    c->stream = calloc(ROUND_TRIP_PACKETS, 3u * XF_PACKET_MAX_LEN + 32u);
    assert_non_null(c->want);
    assert_non_null(c->stream);
    for (i = 0; i < ROUND_TRIP_PACKETS; i++) {
        uint8_t pkt[XF_PACKET_MAX_LEN];
        size_t len = random_packet(&seed, pkt);
        c->hex[i] = malloc(2u * len + 1u);
        assert_non_null(c->hex[i]);
        for (k = 0; k < len; k++) {
            sprintf(c->hex[i] + 2u * k, (i & 1u) ? "%02X" : "%02x", pkt[k]);
        }
        hex_line(pkt, len, c->want + want_len);
        want_len += strlen(c->want + want_len);
        /* noise that is never a header byte, in a different layout */
        stream_len +=
            (size_t)sprintf(c->stream + stream_len, "%02X:%02X\n", next_random(&seed) & 0x7Fu, (unsigned)(i & 0x7Fu));
        strcpy(c->stream + stream_len, c->hex[i]);
        stream_len += strlen(c->hex[i]);
        c->stream[stream_len++] = (i % 3u == 0u) ? '\n' : ' ';
    }
}

static void free_corpus(corpus *c)
{
    size_t i;
    for (i = 0; i < ROUND_TRIP_PACKETS; i++) {
        free(c->hex[i]);
    }
    free(c->want);
    free(c->stream);
}

/* decode --json [--raw] of every packet of the corpus, as arguments. */
static tool_result decode_corpus(const corpus *c, int raw)
{
    const char *argv[ROUND_TRIP_PACKETS + 3];
    int n = 0;
    size_t i;
    argv[n++] = "decode";
    argv[n++] = "--json";
    if (raw) {
        argv[n++] = "--raw";
    }
    for (i = 0; i < ROUND_TRIP_PACKETS; i++) {
        argv[n++] = c->hex[i];
    }
    return run_tool_argv(n, argv, NULL);
}

/* encode --json [--raw] - of @p jsonl gives every packet of the corpus back. */
static void expect_encoded(const corpus *c, const char *jsonl, int raw)
{
    tool_result encoded =
        raw ? run_tool(jsonl, "encode", "--json", "--raw", "-", NULL) : run_tool(jsonl, "encode", "--json", "-", NULL);
    if (encoded.status != 0 || strcmp(encoded.out, c->want) != 0) {
        print_error("round trip%s differs (status %d): %s", raw ? " (--raw)" : "", encoded.status, encoded.err);
        fail();
    }
    tool_result_free(&encoded);
}

static void test_round_trip(void **state)
{
    corpus c;
    tool_result decoded, raw, streamed;
    size_t i;
    (void)state;
    make_corpus(&c);
    decoded = decode_corpus(&c, 0);
    assert_int_equal(decoded.status, 0);
    assert_int_equal(count_lines(decoded.out), ROUND_TRIP_PACKETS);
    expect_encoded(&c, decoded.out, 0); /* JSON Lines back to bytes */

    /* the same with the wire integers: decode --json --raw, encode --json --raw */
    raw = decode_corpus(&c, 1);
    assert_int_equal(raw.status, 0);
    assert_string_not_equal(raw.out, decoded.out); /* another view of the fields */
    expect_encoded(&c, raw.out, 1);
    tool_result_free(&raw);

    /* the same packets found in a noisy stream, in the same order */
    streamed = run_tool(c.stream, "decode", "--json", NULL);
    assert_int_equal(streamed.status, 0);
    json_decref(cut_summary(&streamed));
    assert_string_equal(streamed.out, decoded.out);

    /* and one object at a time, as an argument */
    for (i = 0; i < 12; i++) {
        const char *line = decoded.out, *want = c.want;
        size_t k;
        char object[4096], want_line[3 * XF_PACKET_MAX_LEN + 2];
        tool_result one;
        for (k = 0; k < i * 25u; k++) {
            line = strchr(line, '\n') + 1;
            want = strchr(want, '\n') + 1;
        }
        memcpy(object, line, strcspn(line, "\n"));
        object[strcspn(line, "\n")] = '\0';
        memcpy(want_line, want, strcspn(want, "\n") + 1u);
        want_line[strcspn(want, "\n") + 1u] = '\0';
        one = run_tool(NULL, "encode", "--json", object, NULL);
        assert_int_equal(one.status, 0);
        assert_string_equal(one.out, want_line);
        tool_result_free(&one);
    }
    tool_result_free(&decoded);
    tool_result_free(&streamed);
    free_corpus(&c);
}

/* Named commands decode to their own command object and back. */
static void test_named_round_trip(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        const char *argv[12];
        int argc = encode_argv(cases[i].args, argv);
        tool_result hex, json, back;
        hex = run_tool_argv(argc, argv, NULL);
        json = run_tool(NULL, "decode", "--json", hex.out, NULL);
        assert_int_equal(json.status, 0);
        assert_true(cases[i].n == 0 || strstr(json.out, "\"command\":{") != NULL);
        back = run_tool(json.out, "encode", "--json", "-", NULL);
        assert_string_equal(back.out, hex.out);
        tool_result_free(&hex);
        tool_result_free(&json);
        tool_result_free(&back);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_named_commands),
        cmocka_unit_test(test_zoom_to_bytes),
        cmocka_unit_test(test_every_order_has_a_command),
        cmocka_unit_test(test_protocol_placement),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_json_input),
        cmocka_unit_test(test_json_errors),
        cmocka_unit_test(test_json_line_faults),
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_named_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
