/*
 * test_cli_args.c - the program's shape: help, version, link options,
 * unknown commands and options, and the arguments of the online commands
 * (checked before any link is opened).
 * Every failure is exit 2 with one "xfgcu: ..." line naming the culprit.
 */
#define _POSIX_C_SOURCE 200809L /* setenv */
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

static void assert_ok_containing(tool_result *r, const char *needle)
{
    if (r->status != 0 || strstr(r->out, needle) == NULL || r->err_len != 0u) {
        print_error("status %d\nstdout: %s\nstderr: %s\n", r->status, r->out, r->err);
        fail();
    }
}

/* Arguments (NULL-terminated) and a piece of the one-line error they must give, with exit 2. */
typedef struct failure_case {
    const char *args[10];
    const char *needle;
} failure_case;

static void expect_failures(const failure_case *cases, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        int argc = 0;
        tool_result r;
        while (cases[i].args[argc] != NULL) {
            argc++;
        }
        r = run_tool_argv(argc, cases[i].args, NULL);
        assert_failure(&r, 2, cases[i].needle, NULL);
        tool_result_free(&r);
    }
}

static void test_version(void **state)
{
    tool_result r = run_tool(NULL, "--version", NULL);
    (void)state;
    assert_int_equal(r.status, 0);
    assert_string_equal(r.out, "xfgcu " XF_VERSION_STRING "\n");
    tool_result_free(&r);
}

static void test_help(void **state)
{
    static const char *const names[] = {"decode", "encode",  "send",   "point",      "rate",   "monitor", "sim",
                                        "demo",   "capture", "replay", "--protocol", "--baud", "--link",  "--raw"};
    tool_result r = run_tool(NULL, "--help", NULL);
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
        assert_ok_containing(&r, names[i]);
    }
    tool_result_free(&r);
}

static void test_command_help(void **state)
{
    tool_result r = run_tool(NULL, "decode", "--help", NULL);
    (void)state;
    assert_ok_containing(&r, "usage: xfgcu decode");
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "--help", NULL);
    assert_ok_containing(&r, "zoom-to");
    assert_ok_containing(&r, "--factor X");
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "zoom-to", "--help", NULL);
    assert_ok_containing(&r, "usage: xfgcu encode [--protocol 1|2] zoom-to (--factor X | --fraction N)");
    tool_result_free(&r);
}

/* getopt_long() with the program's own rules: whole option names only, "--opt=VALUE", no value
 * for a switch, no clusters, "--" ends the options; --help among a command's arguments. */
static void test_option_forms(void **state)
{
    static const failure_case bad[] = {
        {{"--bau", "115200", "encode", "null", NULL}, "unknown option '--bau' (try 'xfgcu --help')"},
        {{"-hx", NULL}, "unknown option '-hx'"},
        {{"--help=1", NULL}, "--help takes no value"},
        {{"decode", "--json=1", APPENDIX1_HEX, NULL}, "decode: --json takes no value"},
        {{"decode", "--js", APPENDIX1_HEX, NULL}, "decode: unknown option '--js'"},
        {{"encode", "zoom-to", "--rat", "5", NULL}, "encode zoom-to: unknown option '--rat'"},
        {{"encode", "zoom-to", "--rate", NULL}, "encode zoom-to: --rate needs a value: X"},
        {{"encode", "zoom-to", "--factor", NULL}, "encode zoom-to: --factor needs a value: X"},
        {{"encode", "zoom-to", "--help", "--protocol", "3", NULL}, "--protocol 3: must be 1 or 2"},
        {{"encode", "shutter", "--", "extra", NULL}, "encode shutter: unexpected argument 'extra'"},
        {{"--tcp", "127.0.0.1:9", "capture", "f.cap", "shutter", "--help", NULL},
         "capture shutter: unknown option '--help' (see 'xfgcu send shutter --help')"},
    };
    tool_result r = run_tool(NULL, "-h", NULL);
    (void)state;
    assert_ok_containing(&r, "usage: xfgcu");
    tool_result_free(&r);
    r = run_tool(NULL, "--", "encode", "null", NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "zoom-to", "--rate", "0.5", "--help", NULL); /* --help wins over the values */
    assert_ok_containing(&r, "usage: xfgcu encode [--protocol 1|2] zoom-to");
    tool_result_free(&r);
    r = run_tool(NULL, "--timeout=500", "encode", "--protocol=2", "zoom-to", "--rate=5.5", "--cameras=all", NULL);
    assert_ok_containing(&r, "A8 E5 4B 00 02");
    tool_result_free(&r);
    expect_failures(bad, sizeof(bad) / sizeof(bad[0]));
}

static void test_no_command(void **state)
{
    tool_result r = run_tool(NULL, NULL);
    (void)state;
    assert_failure(&r, 2, "no command", NULL);
    tool_result_free(&r);
}

static void test_unknown_command_and_option(void **state)
{
    tool_result r = run_tool(NULL, "frobnicate", NULL);
    (void)state;
    assert_failure(&r, 2, "unknown command 'frobnicate'", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--bogus", "decode", NULL);
    assert_failure(&r, 2, "unknown option '--bogus'", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "zoom-to", NULL);
    assert_failure(&r, 2, "'zoom-to'", "xfgcu encode zoom-to", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "decode", "--bogus", NULL);
    assert_failure(&r, 2, "decode: unknown option '--bogus'", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "--bogus", NULL);
    assert_failure(&r, 2, "encode: unknown option '--bogus'", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "frobnicate", NULL);
    assert_failure(&r, 2, "unknown command 'frobnicate'", NULL);
    tool_result_free(&r);
}

static void test_baud(void **state)
{
    static const char *const good[] = {"115200", "250000", "500000", "1000000"};
    static const char *const bad[] = {"9600", "0", "-115200", "fast", "115200x", "2000000"};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(good) / sizeof(good[0]); i++) {
        tool_result r = run_tool(NULL, "--baud", good[i], "decode", APPENDIX1_HEX, NULL);
        assert_int_equal(r.status, 0);
        tool_result_free(&r);
    }
    for (i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
        tool_result r = run_tool(NULL, "--baud", bad[i], "decode", APPENDIX1_HEX, NULL);
        assert_failure(&r, 2, "--baud", bad[i], "115200, 250000, 500000 or 1000000", NULL);
        tool_result_free(&r);
    }
    {
        tool_result r = run_tool(NULL, "--baud=250000", "decode", APPENDIX1_HEX, NULL);
        assert_int_equal(r.status, 0);
        tool_result_free(&r);
        r = run_tool(NULL, "--baud", NULL);
        assert_failure(&r, 2, "--baud needs a value", NULL);
        tool_result_free(&r);
    }
}

static void test_protocol_option(void **state)
{
    tool_result r = run_tool(NULL, "--protocol", "3", "encode", "null", NULL);
    (void)state;
    assert_failure(&r, 2, "--protocol 3", "1 or 2", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "--protocol", "0", "null", NULL);
    assert_failure(&r, 2, "--protocol 0", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "null", "--protocol", "x", NULL);
    assert_failure(&r, 2, "--protocol x", NULL);
    tool_result_free(&r);
}

static void test_other_link_options(void **state)
{
    tool_result r = run_tool(NULL, "--serial", "/dev/null", "--udp", "10.0.0.1", "decode", APPENDIX1_HEX, NULL);
    (void)state;
    assert_failure(&r, 2, "only one of --serial, --udp, --tcp", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--gcu-port", "0", "decode", APPENDIX1_HEX, NULL);
    assert_failure(&r, 2, "--gcu-port 0", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--local-port", "65536", "decode", APPENDIX1_HEX, NULL);
    assert_failure(&r, 2, "--local-port 65536", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--local-port", "0", "decode", APPENDIX1_HEX, NULL); /* any free port */
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    r = run_tool(NULL, "--rate", "201", "decode", APPENDIX1_HEX, NULL);
    assert_failure(&r, 2, "--rate 201", "1..200", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", "gimbal:99999", "decode", APPENDIX1_HEX, NULL);
    assert_failure(&r, 2, "--tcp", "99999", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--rate", "0", "decode", APPENDIX1_HEX, NULL);
    assert_failure(&r, 2, "--rate 0", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--timeout", "soon", "decode", APPENDIX1_HEX, NULL);
    assert_failure(&r, 2, "--timeout soon", NULL);
    tool_result_free(&r);
    /* valid link options are accepted (and ignored) by the offline commands */
    r = run_tool(NULL, "--udp", "192.168.144.108", "--rate", "30", "--timeout", "500", "--gcu-port", "2337",
                 "--local-port", "2338", "--reorder", "50", "--trace", "decode", APPENDIX1_HEX, NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    /* ...but not options that contradict each other (issue 15: conflicting options are usage errors) */
    r = run_tool(NULL, "--tcp", "192.168.144.108:2332", "--gcu-port", "2337", "decode", APPENDIX1_HEX, NULL);
    assert_failure(&r, 2, "--gcu-port and the port of --tcp", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--serial", "/dev/ttyUSB0", "--baud", "1000000", "encode", "null", NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
}

static void test_online_commands_help(void **state)
{
    static const char *const names[] = {"send", "point", "rate", "monitor", "sim", "demo", "capture", "replay"};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
        char want[64];
        tool_result r = run_tool(NULL, names[i], "--help", NULL);
        snprintf(want, sizeof(want), "usage: xfgcu ");
        assert_ok_containing(&r, want);
        assert_ok_containing(&r, names[i]);
        tool_result_free(&r);
    }
    {
        tool_result r = run_tool(NULL, "send", "zoom-to", "--help", NULL);
        assert_ok_containing(&r, "usage: xfgcu send [--protocol 1|2] zoom-to (--factor X | --fraction N)");
        tool_result_free(&r);
        r = run_tool(NULL, "record", "--help", NULL); /* the old name of capture */
        assert_ok_containing(&r, "usage: xfgcu [LINK OPTIONS] capture");
        tool_result_free(&r);
        r = run_tool(NULL, "--tcp", "127.0.0.1", "point", "--pitch", "1", "--help", NULL);
        assert_ok_containing(&r, "usage: xfgcu [LINK OPTIONS] point");
        tool_result_free(&r);
    }
}

static void test_online_commands_need_a_link(void **state)
{
    static const char *const names[] = {"send", "point", "rate", "monitor", "capture"};
    static const char *const args[][7] = {{"shutter"},
                                          {"--pitch", "0", "--yaw", "0"},
                                          {"--pitch", "0", "--yaw", "0", "--duration", "1"},
                                          {"--json"},
                                          {"/tmp/xfgcu-never-written.cap"}};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
        const char *argv[8];
        int n = 0;
        char want[128];
        tool_result r;
        argv[n++] = names[i];
        while (n < 8 && args[i][n - 1] != NULL) {
            argv[n] = args[i][n - 1];
            n++;
        }
        r = run_tool_argv(n, argv, NULL);
        snprintf(want, sizeof(want),
                 "%s needs a link: give --link SPEC, --serial PATH, --udp HOST or --tcp HOST[:PORT]", names[i]);
        assert_failure(&r, 2, want, NULL);
        tool_result_free(&r);
    }
}

/* Bad arguments of each online command: exit 2 and one line naming the argument, before any link is opened
 * (the links named here do not exist). */
static void test_online_bad_arguments(void **state)
{
    static const failure_case cases[] = {
        {{"--tcp", "127.0.0.1:9", "send", NULL}, "send: which command?"},
        {{"--tcp", "127.0.0.1:9", "send", "frobnicate", NULL}, "send: unknown command 'frobnicate'"},
        {{"--tcp", "127.0.0.1:9", "send", "--bogus", NULL}, "send: unknown option '--bogus'"},
        {{"--tcp", "127.0.0.1:9", "send", "zoom-to", "--rate", "0.5", NULL},
         "send zoom-to: --rate 0.5 is out of range"},
        {{"--tcp", "127.0.0.1:9", "send", "track", "--start", NULL}, "send track: --start needs --box"},
        {{"--tcp", "127.0.0.1:9", "send", "shutter", "--protocol", "3", NULL}, "--protocol 3"},
        {{"--tcp", "127.0.0.1:9", "point", "--pitch", "10", NULL}, "point: missing --yaw DEG"},
        {{"--tcp", "127.0.0.1:9", "point", "--pitch", "200", "--yaw", "0", NULL},
         "point: --pitch 200: must be degrees"},
        {{"--tcp", "127.0.0.1:9", "point", "--pitch", "1", "--pitch", "2", "--yaw", "0", NULL}, "--pitch given twice"},
        {{"--tcp", "127.0.0.1:9", "point", "--pitch", "x", "--yaw", "0", NULL}, "point: --pitch x"},
        {{"--tcp", "127.0.0.1:9", "point", "--pitch", "0", "--yaw", "0", "--wait", "0", NULL}, "point: --wait 0"},
        {{"--tcp", "127.0.0.1:9", "rate", "--pitch", "0", "--yaw", "10", NULL}, "rate: missing --duration S"},
        {{"--tcp", "127.0.0.1:9", "rate", "--pitch", "0", "--yaw", "151", "--duration", "1", NULL},
         "rate: --yaw 151: must be deg/s, -150..150"},
        {{"--tcp", "127.0.0.1:9", "rate", "--pitch", "0", "--yaw", "1", "--duration", "0", NULL}, "rate: --duration 0"},
        {{"--tcp", "127.0.0.1:9", "rate", "--spin", NULL}, "rate: unknown option '--spin'"},
        {{"--tcp", "127.0.0.1:9", "monitor", "--count", "0", NULL}, "monitor: --count 0"},
        {{"--tcp", "127.0.0.1:9", "monitor", "--duration", NULL}, "monitor: --duration needs a value"},
        {{"--tcp", "127.0.0.1:9", "monitor", "extra", NULL}, "monitor: unexpected argument 'extra'"},
        {{"--tcp", "127.0.0.1:9", "capture", NULL}, "capture: missing FILE"},
        {{"--tcp", "127.0.0.1:9", "capture", "f.cap", "--count", "x", NULL}, "capture: --count x"},
        {{"--tcp", "127.0.0.1:9", "capture", "f.cap", "frobnicate", NULL}, "capture: unknown command 'frobnicate'"},
        {{"--tcp", "127.0.0.1:9", "capture", "f.cap", "zoom-to", NULL},
         "capture zoom-to: give --factor X or --fraction N"},
        {{"replay", NULL}, "replay: missing FILE"},
        {{"replay", "a.cap", "b.cap", NULL}, "replay: unexpected argument 'b.cap'"},
        {{"replay", "--json", "--brief", "a.cap", NULL}, "--json and --brief exclude each other"},
        {{"replay", "/tmp/xfgcu-no-such-capture", NULL}, "replay: cannot open /tmp/xfgcu-no-such-capture"},
        {{"sim", "--tcp", "70000", NULL}, "sim: --tcp 70000: must be a port"},
        {{"sim", "--tcp=70000", NULL}, "sim: --tcp 70000: must be a port"},
        {{"sim", "--pty=x", NULL}, "sim: --pty takes no value"},
        {{"sim", "--udp", "--tcp", NULL}, "sim: give only one of"},
        {{"sim", "--fail", "zoom-in", NULL}, "sim: --fail zoom-in: expected ORDER=STATE"},
        {{"sim", "--fail", "frobnicate=1", NULL}, "'frobnicate' is not an order"},
        {{"sim", "--fail", "shutter=256", NULL}, "STATE must be 0..255"},
        {{"sim", "--drop", "1001", NULL}, "sim: --drop 1001"},
        {{"sim", "--delay", "-1", NULL}, "sim: --delay -1"},
        {{"sim", "--link", "/tmp/gcu", NULL}, "sim: --link /tmp/gcu goes only with --pty"},
        {{"sim", "--serial", NULL}, "sim: --serial needs a value"},
        {{"sim", "--protocol", "3", NULL}, "--protocol 3"},
        {{"sim", "--bogus", NULL}, "sim: unknown option '--bogus'"},
        {{"demo", "now", NULL}, "demo: unexpected argument 'now'"},
        {{"--rate", "500", "send", "shutter", NULL}, "--rate 500"},
    };
    (void)state;
    expect_failures(cases, sizeof(cases) / sizeof(cases[0]));
}

/* --link SPEC, XFGCU_LINK and --udp HOST:PORT are read by the library's parser: bad specs, two
 * links and options the spec already says are usage errors, before any link is opened. */
static void test_link_specs(void **state)
{
    static const failure_case cases[] = {
        {{"--link", "bogus:1", "send", "shutter", NULL}, "--link bogus:1: unknown link kind 'bogus'"},
        {{"--link", "tcp:h:99999", "send", "shutter", NULL}, "--link tcp:h:99999: port 99999 is out of range"},
        {{"--link", "serial:/dev/x,baud=9600", "send", "shutter", NULL}, "baud must be"},
        {{"--link", "tcp:127.0.0.1:9", "--tcp", "127.0.0.1:9", "send", "shutter", NULL},
         "give only one of --serial, --udp, --tcp, --link"},
        {{"--link", "udp:127.0.0.1:9", "--local-port", "0", "send", "shutter", NULL},
         "--local-port is for --udp or --tcp; with --link, the spec says it"},
        {{"--link", "serial:/dev/ttyUSB0", "--baud", "500000", "send", "shutter", NULL},
         "--baud is for --serial; with --link, the spec says it"},
        {{"--link", "tcp:127.0.0.1:9", "--link", "tcp:127.0.0.1:9", "send", "shutter", NULL}, "--link given twice"},
        {{"--udp", "127.0.0.1:9", "--gcu-port", "9", "send", "shutter", NULL}, "--gcu-port and the port of --udp"},
        {{"--udp", "127.0.0.1:99999", "send", "shutter", NULL}, "--udp 127.0.0.1:99999: port 99999 is out of range"},
        {{"--udp", "127.0.0.1:9,local=0", "send", "shutter", NULL}, "options have no place here: give --link"},
        {{"send", "shutter", "--link", "tcp:127.0.0.1:9", "--serial", "/dev/x", NULL}, "give only one of"},
    };
    tool_result r;
    (void)state;
    expect_failures(cases, sizeof(cases) / sizeof(cases[0]));
    /* XFGCU_LINK: read when a command needs a link, checked then; an option names another link */
    assert_int_equal(setenv("XFGCU_LINK", "bogus:x", 1), 0);
    r = run_tool(NULL, "send", "shutter", NULL);
    assert_failure(&r, 2, "XFGCU_LINK: bogus:x: unknown link kind 'bogus'", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "decode", APPENDIX1_HEX, NULL); /* an offline command does not read it */
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    assert_int_equal(setenv("XFGCU_LINK", "serial:/dev/ttyUSB0", 1), 0);
    r = run_tool(NULL, "--baud", "500000", "send", "shutter", NULL);
    assert_failure(&r, 2, "--baud is for --serial; with XFGCU_LINK, the spec says it", NULL);
    tool_result_free(&r);
    assert_int_equal(unsetenv("XFGCU_LINK"), 0);
}

/* The capture command's old name still runs it, with a note; the camera order keeps its name. */
static void test_record_alias(void **state)
{
    tool_result r = run_tool(NULL, "--tcp", "127.0.0.1:9", "record", NULL);
    (void)state;
    assert_int_equal(r.status, 2);
    assert_int_equal(count_lines(r.err), 2);
    assert_non_null(strstr(r.err, "xfgcu: note: 'xfgcu record FILE' is the old name of 'xfgcu capture FILE'"));
    assert_non_null(strstr(r.err, "xfgcu: capture: missing FILE"));
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "record", NULL); /* the order */
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, " 21 01 "));
    tool_result_free(&r);
}

/* An error that echoes the user's input stays one line: control characters are escaped. */
static void test_errors_escape_control_characters(void **state)
{
    static const char *const levels[] = {"1\nxfgcu: fake", "1\x01\x7f\t", "1\r2"};
    static const char *const shown[] = {"--level 1\\nxfgcu: fake:", "--level 1\\x01\\x7F\\t:", "--level 1\\r2:"};
    size_t i;
    (void)state;
    for (i = 0; i < 3u; i++) {
        tool_result r = run_tool(NULL, "encode", "lighting", "--level", levels[i], NULL);
        assert_int_equal(r.status, 2);
        assert_int_equal(strlen(r.out), 0);
        assert_non_null(strstr(r.err, shown[i]));
        assert_int_equal(strchr(r.err, '\n') - r.err, (long)strlen(r.err) - 1); /* one line */
        assert_null(strchr(r.err, '\r'));
        tool_result_free(&r);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version),
        cmocka_unit_test(test_help),
        cmocka_unit_test(test_command_help),
        cmocka_unit_test(test_option_forms),
        cmocka_unit_test(test_no_command),
        cmocka_unit_test(test_unknown_command_and_option),
        cmocka_unit_test(test_baud),
        cmocka_unit_test(test_protocol_option),
        cmocka_unit_test(test_other_link_options),
        cmocka_unit_test(test_online_commands_help),
        cmocka_unit_test(test_online_commands_need_a_link),
        cmocka_unit_test(test_online_bad_arguments),
        cmocka_unit_test(test_errors_escape_control_characters),
        cmocka_unit_test(test_link_specs),
        cmocka_unit_test(test_record_alias),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
