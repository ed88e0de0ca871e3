/*
 * test_cli_versions.c - the version a GCU answers, and what the user sees of the client's health
 * (issue 29 item 2, issue 30 item 4, issue 31 item 5), against `xfgcu sim` in the background:
 *
 * - --protocol auto (the default) finds a GCU that answers version 1 only or version 2 only
 *   (sim --answer-only), and says which one answered (send --json, --verbose, monitor);
 * - ranges and meanings follow the version the GCU answered in: pip --mode 3 against a V0.2 GCU
 *   with default settings, refused against a V0.1 one; an argument that fits no version is refused
 *   before any link is opened;
 * - a GCU that never answers gets one line that says what was tried and what to check;
 * - --reorder fixes the client's reorder bound (reorder_fixed), 0 included;
 * - the simulator's new options are checked and shown in its --json ready line.
 */
#define _POSIX_C_SOURCE 200809L

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
#include "sim_proc.h"

static void expect_out(const tool_result *r, int status, const char *out)
{
    if (r->status != status || strcmp(r->out, out) != 0) {
        print_error("status %d (want %d)\nstdout: \"%s\" (want \"%s\")\nstderr: %s\n", r->status, status, r->out, out,
                    r->err);
        fail();
    }
}

static json_t *object_key(const json_t *obj, const char *key)
{
    json_t *v = json_object_get(obj, key);
    if (!json_is_object(v)) {
        print_error("no object under \"%s\"\n", key);
        fail();
    }
    return v;
}

/* The "health" object of send --json's line in @p r (its status checked); *top is the line's
 * object, for the caller to free. */
static json_t *health_of(const tool_result *r, json_t **top)
{
    assert_int_equal(r->status, 0);
    *top = parse_line(r->out);
    return object_key(*top, "health");
}

/* send --json shutter on @p s: the version answered, at the top and in the health object. */
static void expect_answered(const sim_proc *s, int version)
{
    tool_result r = sim_run_on(s, "send", "--json", "shutter", NULL);
    json_t *o, *h = health_of(&r, &o);
    assert_string_equal(str_key(o, "status"), "ok");
    assert_int_equal(int_key(o, "version_answered"), version);
    assert_string_equal(str_key(h, "version_setting"), "auto");
    assert_int_equal(int_key(h, "version_answered"), version);
    assert_int_equal(int_key(h, "version_sent"), version);
    assert_int_equal(int_key(h, "gcu_version"), version); /* sim --answer-only N speaks N */
    json_decref(o);
    tool_result_free(&r);
}

/* A default `send shutter` works unchanged against a GCU that answers version 1 only and one that
 * answers version 2 only; with the other version fixed, the silence says what to try. */
static void test_auto_finds_the_version(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    static const char *const only[2] = {"1", "2"};
    static const char *const other[2] = {"2", "1"};
    int k;
    for (k = 0; k < 2; k++) {
        tool_result r;
        sim_start(s, SIM_TCP, "--answer-only", only[k], NULL);
        r = sim_run_on(s, "send", "shutter", NULL);
        expect_out(&r, 0, "ok\n");
        assert_int_equal(r.err_len, 0);
        tool_result_free(&r);
        expect_answered(s, k + 1);
        r = sim_run_on(s, "--protocol", other[k], "--timeout", "400", "send", "shutter", NULL);
        assert_failure(&r, 3, "no answer from the GCU on tcp 127.0.0.1:", "one protocol version sent",
                       "--protocol auto tries both", "xfgcu probe", NULL);
        tool_result_free(&r);
        assert_int_equal(sim_stop(s), 0);
    }
}

/* pip --mode 3 is V0.2's: with default settings it goes to a V0.2 GCU, and a V0.1 GCU's answer
 * refuses it (exit 2, nothing sent); palette 50 the other way round. */
static void test_ranges_follow_the_gcu(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    sim_start(s, SIM_TCP, "--protocol", "2", "--verbose", NULL);
    r = sim_run_on(s, "send", "pip", "--mode", "3", NULL);
    expect_out(&r, 0, "ok\n");
    tool_result_free(&r);
    r = sim_run_on(s, "send", "palette", "--mode", "50", NULL);
    assert_failure(&r, 2, "send palette: --mode 50 is out of range for protocol 2", "the GCU answers in protocol 2",
                   NULL);
    tool_result_free(&r);
    assert_int_equal(sim_stop(s), 0);

    sim_start(s, SIM_TCP, NULL); /* V0.1 */
    r = sim_run_on(s, "send", "pip", "--mode", "3", NULL);
    assert_failure(&r, 2, "send pip: --mode 3 is out of range for protocol 1", "the GCU answers in protocol 1", NULL);
    tool_result_free(&r);
    r = sim_run_on(s, "send", "palette", "--mode", "50", NULL);
    expect_out(&r, 0, "ok\n");
    tool_result_free(&r);
    assert_int_equal(sim_stop(s), 0);
}

/* Arguments that fit no version, or not the version given, are refused before any link. */
static void test_ranges_offline(void **state)
{
    tool_result r;
    (void)state;
    r = run_tool(NULL, "--tcp", "127.0.0.1:1", "send", "pip", "--mode", "9", NULL);
    assert_failure(&r, 2, "send pip: --mode 9 is out of range", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", "127.0.0.1:1", "--protocol", "1", "send", "pip", "--mode", "3", NULL);
    assert_failure(&r, 2, "send pip: --mode 3 is out of range for protocol 1", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", "127.0.0.1:1", "send", "pip", "--mode", "3", "--protocol", "1", NULL);
    assert_failure(&r, 2, "send pip: --mode 3 is out of range for protocol 1", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--protocol", "3", "send", "shutter", NULL);
    assert_failure(&r, 2, "--protocol 3: must be auto, 1 or 2", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--protocol", "auto", "encode", "shutter", NULL); /* a packet needs a byte: the first tried */
    assert_int_equal(r.status, 0);
    assert_true(strncmp(r.out, "A8 E5 49 00 01 ", 15) == 0);
    tool_result_free(&r);
    r = run_tool(NULL, "encode", "--protocol", "auto", "shutter", NULL);
    assert_failure(&r, 2, "--protocol auto: must be 1 or 2", NULL);
    tool_result_free(&r);
}

/* A GCU that never answers (every reply dropped): one line, both versions tried, what to check. */
static void test_silence_says_what_to_try(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    sim_start(s, SIM_TCP, "--drop", "1000", NULL);
    r = sim_run_on(s, "--timeout", "1000", "send", "shutter", NULL);
    assert_failure(&r, 3, "no answer from the GCU on tcp 127.0.0.1:", "within 1000 ms",
                   "(protocol versions 1 and 2 tried)", "check the address and TCP port", "the GCU's power and wiring",
                   "then try 'xfgcu probe' on this link", NULL);
    tool_result_free(&r);
    r = sim_run_on(s, "--timeout", "1000", "monitor", "--json", NULL);
    assert_failure(&r, 3, "no answer from the GCU", "power and wiring", NULL);
    tool_result_free(&r);
    assert_int_equal(sim_stop(s), 0);
    sim_start(s, SIM_UDP, "--drop", "1000", NULL);
    r = sim_run_on(s, "--timeout", "1000", "send", "shutter", NULL);
    assert_failure(&r, 3, "no answer from the GCU on udp 127.0.0.1:", "the GCU's UDP port",
                   "the local port it answers to (--local-port)", NULL);
    tool_result_free(&r);
}

/* The client's judgement of the link in send --json and --verbose; --reorder fixes the bound, 0
 * included (the client then uses no bound of its own), and so does a TCP link, which keeps order. */
static void test_send_health(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    static const struct {
        const char *value;
        int reorder_ms;
    } fixed[] = {{"50", 50}, {"0", 0}};
    size_t i;
    tool_result r;
    json_t *o, *h;
    r = sim_run_on(s, "send", "--json", "shutter", NULL);
    h = health_of(&r, &o);
    assert_true(json_is_boolean(json_object_get(h, "in_order")));
    assert_true(int_key(h, "out_of_turn") >= 0);
    assert_true(int_key(h, "reorder_ms") >= 0);
    assert_true(json_is_true(json_object_get(h, "reorder_fixed"))); /* TCP keeps order */
    assert_int_equal(int_key(h, "reorder_ms"), 0);
    assert_int_equal(int_key(h, "given_up"), 0);
    assert_true(int_key(h, "replies") >= 1);
    json_decref(o);
    tool_result_free(&r);
    for (i = 0; i < sizeof(fixed) / sizeof(fixed[0]); i++) {
        r = sim_run_on(s, "send", "--json", "shutter", "--reorder", fixed[i].value, NULL);
        h = health_of(&r, &o);
        assert_true(json_is_true(json_object_get(h, "reorder_fixed")));
        assert_int_equal(int_key(h, "reorder_ms"), fixed[i].reorder_ms);
        json_decref(o);
        tool_result_free(&r);
    }
    r = sim_run_on(s, "--protocol", "2", "send", "--json", "shutter", NULL); /* sent 2; the GCU speaks 1 */
    h = health_of(&r, &o);
    assert_int_equal(int_key(h, "version_setting"), 2);
    assert_int_equal(int_key(h, "version_answered"), 2);
    assert_int_equal(int_key(h, "gcu_version"), 1);
    json_decref(o);
    tool_result_free(&r);
    r = sim_run_on(s, "send", "shutter", "--verbose", NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(count_lines(r.out), 2);
    assert_true(strncmp(r.out, "ok\nlink: protocol version 1 answered (auto), link ", 50) == 0);
    assert_non_null(strstr(r.out, " ms, "));
    assert_non_null(strstr(r.out, " replies out of turn, 0 frames given up\n"));
    tool_result_free(&r);
}

/* monitor: a health event in the JSON, the health at the end of each plain line. */
static void test_monitor_health(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r = sim_run_on(s, "monitor", "--json", "--count", "3", NULL);
    const char *p;
    int health = 0;
    assert_int_equal(r.status, 0);
    assert_int_equal(count_packet_lines(r.out), 3);
    for (p = r.out; *p != '\0'; p += strcspn(p, "\n") + 1u) {
        json_t *o = parse_line(p);
        if (json_object_get(o, "event") != NULL) {
            assert_string_equal(str_key(o, "event"), "health");
            assert_int_equal(int_key(o, "version_answered"), 1);
            assert_string_equal(str_key(o, "version_setting"), "auto");
            (void)int_key(o, "out_of_turn");
            (void)int_key(o, "reorder_ms");
            assert_int_equal(int_key(o, "given_up"), 0);
            assert_non_null(strstr(str_key(o, "link"), "tcp 127.0.0.1:"));
            health++;
        }
        json_decref(o);
    }
    assert_true(health >= 1);
    tool_result_free(&r);
    r = sim_run_on(s, "monitor", "--json", "--count", "1", NULL); /* the packet, then the health */
    assert_int_equal(r.status, 0);
    assert_int_equal(count_lines(r.out), 2);
    assert_int_equal(count_packet_lines(r.out), 1);
    assert_non_null(strstr(r.out, "\"event\":\"health\""));
    tool_result_free(&r);
    r = sim_run_on(s, "monitor", "--duration", "0.5", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "  health: protocol version 1 answered (auto), link "));
    assert_non_null(strstr(r.out, " frames given up\n"));
    tool_result_free(&r);
}

/* The simulator's options: checked, and said in its --json ready line. */
static void test_sim_options(void **state)
{
    tool_result r;
    json_t *o;
    (void)state;
    r = run_tool(NULL, "sim", "--answer-only", "3", NULL);
    assert_failure(&r, 2, "sim: --answer-only 3: must be a version byte, 1 or 2", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "sim", "--main-camera", "0", NULL);
    assert_failure(&r, 2, "sim: --main-camera 0: must be a camera, 1 or 2", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "sim", "--state-once=1", NULL);
    assert_failure(&r, 2, "--state-once", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "sim", "--tcp", "0", "--json", "--state-once", "--answer-only", "2", "--main-camera", "2",
                 "--duration", "0.2", NULL);
    assert_int_equal(r.status, 0);
    o = parse_line(r.out);
    assert_string_equal(str_key(o, "event"), "listening");
    assert_int_equal(int_key(o, "protocol"), 2); /* a GCU that answers version 2 only speaks 2 */
    assert_true(json_is_true(json_object_get(o, "state_once")));
    assert_int_equal(int_key(o, "answer_only"), 2);
    assert_int_equal(int_key(o, "main_camera"), 2);
    json_decref(o);
    tool_result_free(&r);
    r = run_tool(NULL, "sim", "--tcp", "0", "--json", "--answer-only", "2", "--protocol", "1", "--duration", "0.2",
                 NULL);
    assert_int_equal(r.status, 0);
    o = parse_line(r.out);
    assert_int_equal(int_key(o, "protocol"), 1); /* unless --protocol says otherwise */
    assert_false(json_is_true(json_object_get(o, "state_once")));
    json_decref(o);
    tool_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_auto_finds_the_version, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_ranges_follow_the_gcu, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_ranges_offline),
        cmocka_unit_test_setup_teardown(test_silence_says_what_to_try, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_send_health, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_monitor_health, sim_setup_tcp, sim_teardown),
        cmocka_unit_test(test_sim_options),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
