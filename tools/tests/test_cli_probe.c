/*
 * test_cli_probe.c - `xfgcu probe` against `xfgcu sim` configured as several models (codes
 * 58, 0, 2 in V0.1, 49 and 58 in V0.2): the model, versions and protocol reported; the orders
 * the model lacks (by V2.0.6's list, typed here per model) answered "failed" and the others
 * "ok"; --json valid with its documented keys; no motion order without --move (the orders the
 * simulator says it executed, --verbose, are exactly the ones the probe reports, none of them
 * moves), and nothing the GCU reports changed by the probe; --move moving and coming back;
 * a failure with a camera mask flagged as a disagreement; the round trip measured under a
 * delay; no GCU (exit 3, one line); usage errors (exit 2).
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <poll.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>
#include <cmocka.h>
#include <jansson.h>

#include "run_tool.h"
#include "sim_proc.h"
#include "xfgcu/xfgcu.h"

/* The orders of the safe set, V0.1 and V0.2 (docs/cli.md, probe). */
static const char *const safe_v1[] = {"zoom_stop", "zoom_to", "focus",          "ranging",
                                      "lighting",  "track",   "external_track", NULL};
static const char *const safe_v2[] = {"osd",          "osd_coordinate",   "auto_flip", "time_zone",
                                      "digital_zoom", "target_detection", "area_temp", "temp_alarm",
                                      "isotherm",     "spot_temp",        NULL};
/* Orders that move the gimbal or change its mode or settings: never sent without --move. */
static const char *const moving[] = {"calibration", "neutral",      "angle_control", "head_lock", "head_follow",
                                     "orthoview",   "euler",        "gaze_geo",      "gaze_lock", "click_to_aim",
                                     "fpv",         "shutter",      "record",        "zoom_in",   "zoom_out",
                                     "palette",     "night_vision", "pip",           NULL};

/* ---- helpers ---------------------------------------------------------------------------- */

static int in_list(const char *const *list, const char *name)
{
    for (; *list != NULL; list++) {
        if (strcmp(*list, name) == 0) {
            return 1;
        }
    }
    return 0;
}

/* The orders of the "executed NAME (0xCODE)" lines in @p buf. */
static void parse_executed(const char *buf, int seen[256])
{
    const char *line;
    memset(seen, 0, 256 * sizeof(int));
    for (line = strstr(buf, "executed "); line != NULL; line = strstr(line + 1, "executed ")) {
        unsigned code;
        const char *paren = strstr(line, "(0x");
        if (paren != NULL && sscanf(paren, "(0x%x)", &code) == 1) {
            seen[code & 0xFFu] = 1;
        }
    }
}

/* Does the simulator's log hold every order of @p want (256 flags; NULL: none)? */
static int all_executed(const char *log, const void *want)
{
    int seen[256];
    size_t i;
    parse_executed(log, seen);
    for (i = 0; want != NULL && i < 256u; i++) {
        if (((const int *)want)[i] && !seen[i]) {
            return 0;
        }
    }
    return 1;
}

/* The orders the simulator says it executed since the last call: every one of @p want, and any
 * other (sim_read_log()). */
static void executed(sim_proc *s, int seen[256], const int *want)
{
    char log[16384];
    size_t n = 0;
    sim_read_log(s, log, sizeof(log), &n, all_executed, want);
    parse_executed(log, seen);
}

/* Every probe here waits for an answer up to this long, not the default second: on a loaded
 * machine a reply can be late, and these tests are about the answers, not about the timeout. */
#define PATIENCE_MS "3000"

/* The probe's report as JSON: exit 0, nothing on stderr, one line. */
static json_t *probe_json(const sim_proc *s, const char *protocol, const char *extra)
{
    tool_result r = (extra != NULL) ? sim_run_on(s, "--timeout", PATIENCE_MS, "--protocol", protocol, "probe", "--json",
                                                 "--window", "0.3", extra, NULL)
                                    : sim_run_on(s, "--timeout", PATIENCE_MS, "--protocol", protocol, "probe", "--json",
                                                 "--window", "0.3", NULL);
    json_t *obj;
    if (r.status != 0 || r.err_len != 0 || count_lines(r.out) != 1) {
        print_error("status %d\nstdout: %s\nstderr: %s\n", r.status, r.out, r.err);
        fail();
    }
    obj = parse_line(r.out);
    tool_result_free(&r);
    return obj;
}

static json_t *key(const json_t *obj, const char *name)
{
    json_t *v = json_object_get(obj, name);
    if (v == NULL) {
        print_error("no key \"%s\"\n", name);
        fail();
    }
    return v;
}

/* The documented keys, with their types. */
static void check_keys(const json_t *p)
{
    static const char *const top_int[] = {"probe", "first_reply_ms", NULL};
    static const char *const gimbal_int[] = {"gimbal_code", "protocol", "pod_status", "gimbal_mode", NULL};
    static const char *const gimbal_real[] = {"hw_version", "fw_version", "zoom_cam1", "zoom_cam2", NULL}; /* units */
    const json_t *g = key(p, "gimbal"), *w = key(p, "reply_rate"), *rt = key(p, "round_trip_ms"), *l = key(p, "link");
    size_t i;
    for (i = 0; top_int[i] != NULL; i++) {
        assert_true(json_is_integer(key(p, top_int[i])));
    }
    for (i = 0; gimbal_int[i] != NULL; i++) {
        assert_true(json_is_integer(key(g, gimbal_int[i])));
    }
    for (i = 0; gimbal_real[i] != NULL; i++) {
        assert_true(json_is_real(key(g, gimbal_real[i])));
    }
    assert_true(json_is_string(key(p, "time_utc")) && strlen(str_key(p, "time_utc")) == 24u);
    assert_true(str_key(p, "time_utc")[10] == 'T' && str_key(p, "time_utc")[23] == 'Z');
    assert_true(json_is_real(key(p, "time_mono")) && json_real_value(key(p, "time_mono")) > 0.0);
    assert_string_equal(str_key(p, "program"), "xfgcu");
    assert_true(json_is_string(key(p, "version")));
    assert_true(json_is_string(key(l, "option")) && json_is_string(key(l, "where")));
    assert_true(json_is_integer(key(l, "protocol_sent")) && json_is_integer(key(l, "rate_hz")));
    assert_true(json_is_boolean(key(p, "move")) && json_is_true(key(p, "complete")));
    assert_true(json_is_null(key(p, "stopped")) && json_is_real(key(p, "duration_s")));
    assert_true(json_is_string(key(g, "gimbal_model")) && json_is_string(key(g, "pod_status_order")));
    assert_true(json_is_string(key(g, "mode_name")) && json_is_true(key(g, "have_sub")));
    assert_true(json_is_real(key(w, "hz")) && json_is_real(key(w, "window_s")));
    assert_true(json_is_integer(key(w, "packets_sent")) && json_is_integer(key(w, "replies")));
    assert_true(json_is_integer(key(rt, "commands")) && json_is_integer(key(rt, "min")));
    assert_true(json_is_number(key(rt, "median")) && json_is_integer(key(rt, "max")));
    assert_true(json_is_array(key(p, "orders")) && json_is_array(key(p, "disagreements")));
    assert_true(json_is_array(key(p, "orders_on_wire")) && json_is_array(key(p, "moves")));
}

/* One sent order's object: its keys, and its result is the one expected. */
static void check_sent(const json_t *o, const char *want)
{
    static const char *const ints[] = {"order", "state", "failed_cameras", "packets", "elapsed_ms", NULL};
    size_t i;
    for (i = 0; ints[i] != NULL; i++) {
        assert_true(json_is_integer(key(o, ints[i])));
    }
    assert_true(json_is_string(key(o, "params")) && json_is_string(key(o, "why")));
    assert_true(json_is_string(key(o, "support")));
    if (strcmp(str_key(o, "result"), want) != 0) {
        print_error("%s: result %s, want %s\n", str_key(o, "order_name"), str_key(o, "result"), want);
        fail();
    }
}

/*
 * The orders sent are exactly @p safe (and the V0.2 ones when @p v2), each "failed" when it is
 * in @p lacks, else "ok"; none disagrees with the list; the simulator executed exactly those.
 */
static void check_orders(sim_proc *s, const json_t *p, int v2, const char *const *lacks)
{
    const json_t *orders = key(p, "orders");
    int seen[256], sent[256];
    size_t i, n = 0;
    memset(sent, 0, sizeof(sent));
    for (i = 0; i < json_array_size(orders); i++) {
        const json_t *o = json_array_get(orders, i);
        sent[int_key(o, "order") & 0xFF] = strcmp(str_key(o, "result"), "not sent") != 0;
    }
    executed(s, seen, sent);
    for (i = 0; i < json_array_size(orders); i++) {
        const json_t *o = json_array_get(orders, i);
        const char *name = str_key(o, "order_name");
        int safe = in_list(safe_v1, name) || (v2 && in_list(safe_v2, name));
        if (strcmp(str_key(o, "result"), "not sent") == 0) {
            assert_false(safe);
            continue;
        }
        if (!safe) {
            print_error("%s sent: not in the safe set\n", name);
            fail();
        }
        check_sent(o, in_list(lacks, name) ? "failed" : "ok");
        assert_true(json_is_true(key(o, "agrees")) || strcmp(name, "external_track") == 0);
        n++;
    }
    assert_int_equal(n, 7u + (v2 ? 10u : 0u));
    /* every order of the codec's table but null reported once, sent or not: an order added to the table
     * fails here until probe plans it or says in plan_never() why it never sends it */
    assert_int_equal(json_array_size(orders), XF_ORDER_COUNT - 1u); /* the null order: every packet */
    for (i = 0; i < XF_ORDER_COUNT; i++) {
        size_t j, times = 0;
        for (j = 0; j < json_array_size(orders); j++) {
            times += int_key(json_array_get(orders, j), "order") == xf_order_at(i)->order;
        }
        assert_int_equal(times, xf_order_at(i)->order != XF_ORDER_NULL);
    }
    for (i = 0; moving[i] != NULL; i++) { /* said twice, as the contract */
        uint8_t code = 0;
        assert_int_equal(xf_order_from_name(moving[i], &code), XF_OK);
        assert_false(seen[code]);
    }
    assert_int_equal(json_array_size(key(p, "disagreements")), 0);
    for (i = 1; i < 256u; i++) {
        if (seen[i] != sent[i]) {
            print_error("order 0x%02zX: executed by the simulator %d, reported sent %d\n", i, seen[i], sent[i]);
            fail();
        }
    }
}

static void check_gimbal(const json_t *p, int code, const char *model, int protocol)
{
    const json_t *g = key(p, "gimbal");
    assert_int_equal(int_key(g, "gimbal_code"), code);
    assert_string_equal(str_key(g, "gimbal_model"), model);
    assert_true(num_key(g, "hw_version") == 3.1); /* the simulator's 31 and 50: versions in tenths */
    assert_true(num_key(g, "fw_version") == 5.0);
    assert_int_equal(int_key(g, "protocol"), protocol);
    assert_int_equal(int_key(key(p, "link"), "protocol_sent"), protocol);
    assert_string_equal(str_key(g, "mode_name"), "head_lock");
    assert_string_equal(str_key(g, "pod_status_order"), "undecided"); /* 0: reads the same both ways */
}

/* ---- models -------------------------------------------------------------------------------- */

typedef struct model_case {
    const char *code;
    const char *name;
    const char *protocol;
    const char *const *lacks; /* V2.0.6's list, appendix 8, for the safe set */
} model_case;

static const char *const lacks_none[] = {NULL};
static const char *const lacks_z6a[] = {"zoom_to", "ranging", "lighting", NULL};
static const char *const lacks_z6c[] = {"track", "zoom_to", "ranging", "lighting", NULL};
static const char *const lacks_z1pro[] = {
    "focus", "ranging", "lighting", "digital_zoom", "area_temp", "temp_alarm", "isotherm", "spot_temp", NULL};

static void probe_model(const model_case *m)
{
    sim_proc s;
    json_t *p;
    sim_start(&s, SIM_TCP, "--model", m->code, "--protocol", m->protocol, "--verbose", NULL);
    p = probe_json(&s, m->protocol, NULL);
    check_keys(p);
    check_gimbal(p, atoi(m->code), m->name, atoi(m->protocol));
    assert_true(json_is_false(key(p, "move")));
    assert_int_equal(json_array_size(key(p, "moves")), 0);
    check_orders(&s, p, strcmp(m->protocol, "2") == 0, m->lacks);
    json_decref(p);
    assert_int_equal(sim_stop(&s), 0);
}

static void test_probe_models_v1(void **state)
{
    static const model_case cases[] = {
        {"58", "Z-9B_V4(T)", "1", lacks_none}, {"0", "Z-6A", "1", lacks_z6a}, {"2", "Z-6C", "1", lacks_z6c}};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        probe_model(&cases[i]);
    }
}

static void test_probe_models_v2(void **state)
{
    static const model_case cases[] = {{"49", "Z-1Pro", "2", lacks_z1pro}, {"58", "Z-9B_V4(T)", "2", lacks_none}};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        probe_model(&cases[i]);
    }
}

/* ---- nothing changed -------------------------------------------------------------------------- */

/* What the GCU reports that a probe must leave as it is, through monitor --json --count 1. */
static void snapshot(const sim_proc *s, char *buf, size_t cap)
{
    static const char *const keys[] = {"gimbal_mode", "pod_status",     "cam_pitch",     "cam_yaw",   "zoom_cam1",
                                       "zoom_cam2",   "thermal_status", "camera_status", "time_zone", NULL};
    tool_result r = sim_run_on(s, "--protocol", "2", "monitor", "--json", "--raw", "--count", "1", NULL);
    json_t *obj;
    size_t i, n = 0;
    assert_int_equal(r.status, 0);
    obj = parse_line(r.out);
    for (i = 0; keys[i] != NULL; i++) {
        n += (size_t)snprintf(buf + n, cap - n, "%s=%lld ", keys[i], (long long)int_key(obj, keys[i]));
    }
    json_decref(obj);
    tool_result_free(&r);
}

/* A snapshot once the simulator shows @p needle (the zoom takes a while to get there). */
static void snapshot_with(const sim_proc *s, const char *needle, char *buf, size_t cap)
{
    int i;
    for (i = 0; i < 50; i++) {
        snapshot(s, buf, cap);
        if (strstr(buf, needle) != NULL) {
            return;
        }
    }
    fail_msg("the simulator never shows %s: %s", needle, buf);
}

static void send_ok(const sim_proc *s, ...)
{
    const char *args[16];
    int n = sim_link_args(s, args);
    va_list ap;
    const char *a;
    tool_result r;
    args[n++] = "--protocol";
    args[n++] = "2";
    args[n++] = "send";
    va_start(ap, s);
    while ((a = va_arg(ap, const char *)) != NULL) {
        args[n++] = a;
    }
    va_end(ap);
    r = run_tool_argv(n, args, NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
}

/* States away from the simulator's defaults, then a probe: every state the GCU reports is as
 * it was, the orders that set a state sent the one reported, and the ones that are on (spot
 * temperature) or unknown are not sent. */
static void test_probe_changes_nothing(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    char before[512], after[512];
    const json_t *orders;
    json_t *p;
    size_t i;
    sim_start(s, SIM_TCP, "--protocol", "2", NULL);
    send_ok(s, "zoom-to", "--rate", "2", NULL); /* it takes the simulator 0.17 s to get there */
    send_ok(s, "ranging", "--on", NULL);
    send_ok(s, "osd", "--hide", NULL);
    send_ok(s, "auto-flip", "--off", NULL);
    send_ok(s, "time-zone", "--hours", "5", NULL);
    send_ok(s, "digital-zoom", "--on", NULL);
    send_ok(s, "spot-temp", "--on", "--at", "5000,5000", NULL);
    snapshot_with(s, "zoom_cam1=20 ", before, sizeof(before));
    p = probe_json(s, "2", NULL);
    snapshot(s, after, sizeof(after));
    assert_string_equal(before, after);
    assert_string_equal(str_key(key(p, "gimbal"), "pod_status_order"), "le"); /* ranging: 0x0180 */
    orders = key(p, "orders");
    for (i = 0; i < json_array_size(orders); i++) {
        const json_t *o = json_array_get(orders, i);
        const char *name = str_key(o, "order_name"), *want = NULL;
        want = strcmp(name, "ranging") == 0        ? "02"
               : strcmp(name, "osd") == 0          ? "00"
               : strcmp(name, "auto_flip") == 0    ? "01"
               : strcmp(name, "time_zone") == 0    ? "05"
               : strcmp(name, "digital_zoom") == 0 ? "01"
               : strcmp(name, "zoom_to") == 0      ? "01ECFF" /* -20: 2x */
                                                   : NULL;
        if (want != NULL) {
            assert_string_equal(str_key(o, "result"), "ok");
            assert_string_equal(str_key(o, "params"), want);
        }
        if (strcmp(name, "spot_temp") == 0) {
            assert_string_equal(str_key(o, "result"), "not sent");
        }
    }
    json_decref(p);
}

/* ---- text, failures, timing --------------------------------------------------------------------- */

static void test_probe_text(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    sim_start(s, SIM_UDP, "--model", "0", NULL);
    r = sim_run_on(s, "--timeout", PATIENCE_MS, "probe", "--window", "0.3", NULL);
    if (r.status != 0 || r.err_len != 0) {
        print_error("status %d\nstdout: %s\nstderr: %s\n", r.status, r.out, r.err);
        fail();
    }
    assert_non_null(strstr(r.out, "xfgcu probe: udp 127.0.0.1:"));
    assert_non_null(strstr(r.out, "\ngimbal       Z-6A (code 0), hardware 3.1, firmware 5.0\n"));
    assert_non_null(strstr(r.out, "\nprotocol     the GCU answers in V0.1 (version byte 1); sent 1\n"));
    assert_non_null(strstr(r.out, "\npod status   byte order undecided"));
    assert_non_null(strstr(r.out, "\n  zoom_to           failed "));
    assert_non_null(strstr(r.out, "\n  focus             ok "));
    assert_non_null(strstr(r.out, "\n  shutter           takes a picture"));
    assert_non_null(strstr(r.out, "\ndisagreements with V2.0.6's support list: 0\n"));
    assert_null(strstr(r.out, "\033["));
    tool_result_free(&r);
}

/* A failure with a camera mask where the list says the order is supported: flagged; and a
 * delay on every reply shows in the round trip; the reply rate is the window's replies over its
 * length, never more than the packets sent in it (a loaded machine sends fewer: only the counts
 * are checked, and that none is made up). */
static void test_probe_disagreement_rtt(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    const json_t *o, *rt, *w;
    json_t *p;
    double hz;
    json_int_t replies;
    sim_start(s, SIM_TCP, "--fail", "zoom-stop=0x02", "--delay", "40", NULL);
    p = probe_json(s, "1", NULL);
    o = json_array_get(key(p, "orders"), 0);
    assert_string_equal(str_key(o, "order_name"), "zoom_stop");
    assert_string_equal(str_key(o, "result"), "failed");
    assert_int_equal(int_key(o, "failed_cameras"), 2);
    assert_true(json_is_false(key(o, "agrees")));
    assert_int_equal(json_array_size(key(p, "disagreements")), 1);
    assert_string_equal(json_string_value(json_array_get(key(p, "disagreements"), 0)), "zoom_stop");
    rt = key(p, "round_trip_ms");
    assert_int_equal(int_key(rt, "commands"), 7);
    assert_true(int_key(rt, "min") >= 40); /* every reply 40 ms late */
    assert_true((double)int_key(rt, "min") <= num_key(rt, "median") &&
                num_key(rt, "median") <= (double)int_key(rt, "max"));
    assert_true(int_key(rt, "max") < atoi(PATIENCE_MS)); /* each answered within --timeout */
    w = key(p, "reply_rate");
    hz = num_key(w, "hz");
    replies = int_key(w, "replies");
    assert_true(replies >= 1 && replies <= int_key(w, "packets_sent")); /* 40 ms late: some still on the way */
    assert_true(fabs(hz * num_key(w, "window_s") - (double)replies) < 0.5);
    assert_true((double)int_key(w, "packets_sent") <= 50.0 * num_key(w, "window_s") + 1.0); /* --rate's 50 a second */
    json_decref(p);
}

/* ---- --move ---------------------------------------------------------------------------------- */

static void attitude(const sim_proc *s, long *pitch, long *yaw, long *mode)
{
    tool_result r = sim_run_on(s, "monitor", "--json", "--raw", "--count", "1", NULL);
    json_t *obj;
    assert_int_equal(r.status, 0);
    obj = parse_line(r.out);
    *pitch = (long)int_key(obj, "cam_pitch");
    *yaw = (long)int_key(obj, "cam_yaw");
    *mode = (long)int_key(obj, "gimbal_mode");
    json_decref(obj);
    tool_result_free(&r);
}

static void test_probe_move(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    long pitch, yaw, mode;
    int seen[256], want[256];
    const json_t *moves;
    json_t *p;
    size_t i;
    tool_result r;
    sim_start(s, SIM_TCP, "--verbose", NULL);
    r = sim_run_on(s, "point", "--pitch", "-30", "--yaw", "45", NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    r = sim_run_on(s, "send", "head-lock", NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    memset(want, 0, sizeof(want));
    want[0x14] = want[0x11] = 1; /* euler (point's), head_lock */
    executed(s, seen, want);     /* forget those */
    p = probe_json(s, "1", "--move");
    want[0x03] = 1; /* and neutral */
    executed(s, seen, want);
    assert_true(seen[0x11] && seen[0x03] && seen[0x14]); /* head_lock, neutral, euler */
    assert_true(json_is_true(key(p, "move")));
    moves = key(p, "moves");
    assert_int_equal(json_array_size(moves), 4);
    for (i = 0; i < 4u; i++) {
        assert_true(json_is_true(key(json_array_get(moves, i), "reached")));
    }
    assert_true(fabs(json_real_value(key(json_array_get(moves, 0), "end_pitch"))) < 1.0); /* neutral: centre */
    attitude(s, &pitch, &yaw, &mode);
    assert_true(labs(pitch + 3000) <= 60 && labs(yaw - 4500) <= 60); /* back where it was */
    assert_int_equal(mode, 0x11);                                    /* in the mode it was in */
    json_decref(p);
}

/* ---- no GCU, usage ----------------------------------------------------------------------------- */

static void test_probe_no_gcu(void **state)
{
    char port[8];
    int fd = hold_port(SOCK_DGRAM, port, sizeof(port)); /* a port that swallows datagrams */
    tool_result r;
    (void)state;
    r = run_tool(NULL, "--udp", "127.0.0.1", "--gcu-port", port, "--local-port", "0", "--timeout", "300", "probe",
                 "--json", NULL);
    assert_failure(&r, 3, "no answer from the GCU on udp 127.0.0.1:", "within 300 ms", NULL);
    tool_result_free(&r);
    close(fd);
}

static void test_probe_usage(void **state)
{
    tool_result r;
    (void)state;
    r = run_tool(NULL, "probe", NULL);
    assert_failure(&r, 2, "probe needs a link", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", "127.0.0.1:1", "probe", "--bogus", NULL);
    assert_failure(&r, 2, "--bogus", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", "127.0.0.1:1", "probe", "extra", NULL);
    assert_failure(&r, 2, "extra", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", "127.0.0.1:1", "probe", "--window", "0.1", NULL);
    assert_failure(&r, 2, "--window", "0.2..60", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "probe", "--help", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "usage: xfgcu [LINK OPTIONS] probe [--move] [--json]"));
    tool_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_probe_models_v1),
        cmocka_unit_test(test_probe_models_v2),
        cmocka_unit_test_setup_teardown(test_probe_changes_nothing, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_probe_text, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_probe_disagreement_rtt, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_probe_move, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_probe_no_gcu),
        cmocka_unit_test(test_probe_usage),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
