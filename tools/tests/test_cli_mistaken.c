/*
 * test_cli_mistaken.c - nothing mistaken, every bad input one line: the red team's cases against
 * the program (issue 15). A simulator whose replies come 1.5 s late, one whose packets overtake
 * one another and arrive twice; --rate and --timeout that cannot work; contradicting link
 * options; link options after COMMAND; help; send --json and --trace.
 */
#define _POSIX_C_SOURCE 200809L

#include <poll.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>
#include <jansson.h>

#include "run_tool.h"
#include "sim_proc.h"

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec / 1e9;
}

/* A UDP port for the client to bind, the same for every process of a test (as the default 2338
 * is), so that one process's late replies reach the next one. */
static const char *fixed_port(char *buf, size_t cap)
{
    snprintf(buf, cap, "%d", 20000 + (int)(getpid() % 20000));
    return buf;
}

/* `xfgcu --udp 127.0.0.1 --gcu-port P --local-port L [--timeout T] [extra...] send shutter --json` */
static tool_result send_shutter(const sim_proc *s, const char *local, const char *timeout, const char *extra)
{
    const char *args[16];
    int n = 0;
    args[n++] = "--udp";
    args[n++] = "127.0.0.1";
    args[n++] = "--gcu-port";
    args[n++] = s->port;
    args[n++] = "--local-port";
    args[n++] = local;
    args[n++] = "--timeout";
    args[n++] = timeout;
    if (extra != NULL) {
        args[n++] = "--reorder";
        args[n++] = extra;
    }
    args[n++] = "send";
    args[n++] = "shutter";
    args[n++] = "--json";
    return run_tool_argv(n, args, NULL);
}

static unsigned count_in(const char *log, const char *what)
{
    unsigned n = 0;
    const char *at = log;
    while ((at = strstr(at, what)) != NULL) {
        n++;
        at++;
    }
    return n;
}

/* Has the simulator's log *@p want "executed shutter" lines? */
static int shutters_enough(const char *log, const void *want)
{
    return count_in(log, "executed shutter") >= *(const unsigned *)want;
}

/* Every reply 1.5 s late, one `send shutter` after another on the same local port: an earlier
 * process's late "ok" must never be taken (the red team saw ok after 0.5 s and 0.1 s): an ok is
 * never sooner than its own reply can come; with the default 1 s timeout a send fails (exit 3, one
 * line) unless a stall of the machine kept it from looking at the clock until its own reply was
 * in (the client reads before it checks the time: that ok is a true one); with a 4 s timeout each
 * is ok. */
static void test_late_replies(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    char port[16];
    int i;
    sim_start(s, SIM_UDP, "--delay", "1500", NULL);
    fixed_port(port, sizeof(port));
    for (i = 0; i < 5; i++) {
        int long_timeout = i >= 3;
        double t0 = now_s(), took;
        tool_result r = send_shutter(s, port, long_timeout ? "4000" : "1000", NULL);
        took = now_s() - t0;
        if (strstr(r.out, "\"ok\"") != NULL) {
            json_t *o = parse_line(r.out);
            assert_true(int_key(o, "elapsed_ms") >= 1500); /* its own reply, not a late one */
            assert_true(took >= 1.5);
            json_decref(o);
        } else {
            assert_false(long_timeout);
            assert_int_equal(r.status, 3);
            assert_int_equal(count_lines(r.err), 1); /* one line: no answer, or no state in time */
        }
        tool_result_free(&r);
    }
}

/* Packets overtake one another (0..60 ms each way) and 30 % arrive twice: with --reorder 100, 12
 * shutters in a row, each ok, and the GCU ran exactly 12 (no false ok: a taken "ok" that was
 * another's would leave a shutter unrun or run twice). */
static void test_reordering_link(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    char port[16], log[16384];
    size_t len = 0;
    unsigned k, oks = 0;
    sim_start(s, SIM_UDP, "--jitter", "60", "--dup", "300", "--verbose", NULL);
    fixed_port(port, sizeof(port));
    for (k = 0; k < 12u; k++) {
        tool_result r = send_shutter(s, port, "2000", "100");
        if (r.status != 0) {
            print_error("send %u: status %d\nstdout %s\nstderr %s\n", k, r.status, r.out, r.err);
        }
        assert_int_equal(r.status, 0);
        oks += strstr(r.out, "\"status\":\"ok\"") != NULL;
        tool_result_free(&r);
    }
    assert_int_equal(oks, 12);
    sim_read_log(s, log, sizeof(log), &len, shutters_enough, &oks); /* all 12 of them, and no 13th */
    assert_int_equal(count_in(log, "executed shutter"), 12);
}

/* Run `XFGCU_EXE ARGS` through the shell with stdin redirected as @p redirect; returns the exit
 * status, the output (stdout and stderr) in @p out. */
static int shell_run(const char *args, const char *redirect, char *out, size_t cap)
{
    char cmd[512];
    FILE *p;
    size_t n;
    int st;
    snprintf(cmd, sizeof(cmd), "'%s' %s %s 2>&1", XFGCU_EXE, args, redirect);
    p = popen(cmd, "r");
    assert_non_null(p);
    n = fread(out, 1, cap - 1u, p);
    out[n] = '\0';
    st = pclose(p);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* Count the lines of a --trace that start with "trace " and hold @p what. */
static unsigned trace_lines(const char *out, const char *what)
{
    unsigned n = 0;
    const char *at = out;
    char line[512];
    while (*at != '\0') {
        size_t len = strcspn(at, "\n");
        snprintf(line, sizeof(line), "%.*s", (int)len, at);
        at += len + (at[len] == '\n');
        n += (strncmp(line, "trace ", 6) == 0 && strstr(line, what) != NULL);
    }
    return n;
}

/* The state of a send's trace, line by line (check_trace_line()). */
typedef struct send_trace {
    unsigned cmd_sent, null_replies;
    int result;      /* the reply with the command's state has come */
    int just_result; /* ... on the line before */
    json_t *json;    /* send --json's line */
} send_trace;

static void check_trace_line(send_trace *t, const char *line, const char *all)
{
    int was_result = t->just_result;
    t->just_result = 0;
    if (line[0] == '{') {
        if (!was_result || t->json != NULL) {
            fail_msg("the result printed other than at once after the reply with its state:\n%s", all);
        }
        t->json = parse_line(line);
    } else if (strncmp(line, "xfgcu: note: ", 13) == 0) {
        return; /* settling that takes long on a loaded machine says so */
    } else if (strncmp(line, "trace ", 6) != 0) {
        fail_msg("a line that is neither the trace nor the result: %s\n%s", line, all);
    } else if (strstr(line, " > shutter ") != NULL) {
        if (t->null_replies == 0 || t->result) {
            fail_msg("the command sent before a null was answered, or after its result:\n%s", all);
        }
        t->cmd_sent++;
    } else if (strstr(line, " > null ") != NULL && t->cmd_sent > 0 && !t->result) {
        fail_msg("a null between the command's packets, before its result:\n%s", all);
    } else if (strstr(line, " < shutter (0x20)") != NULL && strstr(line, ", state 0x00") != NULL) {
        t->just_result = !t->result;
        t->result = 1;
    } else if (strstr(line, " < null (0x00)") != NULL) {
        t->null_replies++;
    }
}

/*
 * `xfgcu LINK send shutter --json --trace [--raw]` (the link options after COMMAND), stdout and
 * stderr in one stream, checked in the protocol's order whatever the machine's load (a slow reply
 * only adds packets): nulls until one is answered, then the command in every packet until a reply
 * carries its state, the result printed at once after that reply (nothing sent in between), then
 * no command again. Returns the output; *json the result's object, its packets the trace's.
 */
static char *send_traced(const sim_proc *s, int raw, json_t **json)
{
    static char out[1 << 16];
    char args[256];
    send_trace t;
    const char *at = out;
    char line[512];
    snprintf(args, sizeof(args), "send shutter --json --tcp 127.0.0.1:%s --trace%s", s->port, raw ? " --raw" : "");
    assert_int_equal(shell_run(args, "</dev/null", out, sizeof(out)), 0);
    memset(&t, 0, sizeof(t));
    while (*at != '\0') {
        size_t len = strcspn(at, "\n");
        snprintf(line, sizeof(line), "%.*s", (int)len, at);
        at += len + (at[len] == '\n');
        check_trace_line(&t, line, out);
    }
    assert_true(t.result && t.json != NULL);
    assert_int_equal(int_key(t.json, "packets"), t.cmd_sent);
    *json = t.json;
    return out;
}

/* send --json: one object with the documented keys and both times; --trace: every packet sent
 * and received on one stderr line each, in the protocol's order (send_traced()), the packets
 * counted in the JSON the ones the trace shows; a reply's attitude in degrees, or with --raw in
 * the wire's integers (the unit rule). */
static void test_send_json_and_trace(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    const char *keys[] = {"time_mono",      "time_utc", "status",     "order",   "order_name", "state",
                          "failed_cameras", "packets",  "elapsed_ms", "command", "link"};
    tool_result r;
    json_t *o;
    const char *out;
    size_t i;
    sim_start(s, SIM_TCP, NULL);
    r = sim_run_on(s, "point", "--pitch", "-30", "--yaw", "45", NULL); /* angles that show their unit */
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    out = send_traced(s, 0, &o);
    for (i = 0; i < sizeof(keys) / sizeof(keys[0]); i++) {
        assert_non_null(json_object_get(o, keys[i]));
    }
    assert_string_equal(str_key(o, "status"), "ok");
    assert_string_equal(str_key(o, "order_name"), "shutter");
    assert_int_equal(strlen(str_key(o, "time_utc")), 24); /* 2026-11-26T10:00:00.123Z */
    json_decref(o);
    assert_true(strncmp(out, "trace 0.0", 9) == 0);
    assert_non_null(strstr(out, " > null (0x00), 72 bytes\n"));
    assert_non_null(strstr(out, " > shutter (0x20), 73 bytes\n"));
    assert_non_null(strstr(out, " < shutter (0x20), 73 bytes, mode 0x14, roll 0.00 pitch -30.00 yaw 45.00 deg, "));
    assert_int_equal(trace_lines(out, "cam_pitch"), 0);
    out = send_traced(s, 1, &o);
    json_decref(o);
    assert_non_null(strstr(out, " < shutter (0x20), 73 bytes, mode 0x14, cam_roll 0 cam_pitch -3000 cam_yaw 4500, "));
    assert_int_equal(trace_lines(out, " deg"), 0);
}

/* A usage error: exit 2, nothing on stdout, one line on stderr holding every needle. */
typedef struct usage_case {
    const char *args[10];   /* NULL-terminated: room for one after the longest case */
    const char *needles[4]; /* NULL-terminated */
} usage_case;

static const usage_case usage_cases[] = {
    {{"--udp", "127.0.0.1", "--rate", "1", "send", "shutter"}, {"--rate 1", "stale after 250 ms", "--rate 5 or more"}},
    {{"--udp", "127.0.0.1", "--timeout", "30", "send", "shutter"},
     {"--timeout 30", "round trip", "--timeout 40 or more"}},
    {{"--udp", "127.0.0.1", "--reorder", "100", "--timeout", "200", "send", "shutter"},
     {"--timeout 200", "twice --reorder", "--timeout 240 or more"}},
    {{"--udp", "127.0.0.1", "--reorder", "1001", "send", "shutter"}, {"--reorder 1001"}},
    {{"--udp", "127.0.0.1", "--baud", "115200", "send", "shutter"}, {"--baud is for --serial"}},
    {{"--serial", "/dev/null", "--gcu-port", "2337", "send", "shutter"}, {"--gcu-port is for --udp or --tcp"}},
    {{"--tcp", "127.0.0.1", "--local-port", "5", "send", "shutter"}, {"--local-port is for --udp"}},
    {{"--tcp", "127.0.0.1:2332", "--gcu-port", "2332", "send", "shutter"}, {"give the port once"}},
    /* after COMMAND as well */
    {{"send", "shutter", "--udp", "127.0.0.1", "--tcp", "127.0.0.1"}, {"give only one of --serial, --udp, --tcp"}},
    {{"send", "shutter", "--rate", "1", "--udp", "127.0.0.1"}, {"--rate 1"}},
    {{"send", "shutter", "--reorder", "x"}, {"--reorder x", "0..1000"}},
    {{"--udp", "127.0.0.1", "--udp", "127.0.0.2", "send", "shutter"}, {"--udp given twice"}},
    {{"--timeout", "200", "send", "shutter", "--timeout", "300"}, {"--timeout given twice"}},
    {{"send", "shutter", "--version"}, {"unknown option '--version'"}},
};

/* Settings that cannot work, and options that contradict each other, are one-line usage errors. */
static void test_impossible_settings(void **state)
{
    size_t i, k;
    tool_result r;
    (void)state;
    for (i = 0; i < sizeof(usage_cases) / sizeof(usage_cases[0]); i++) {
        const usage_case *c = &usage_cases[i];
        int n = 0;
        while (c->args[n] != NULL) {
            n++;
        }
        r = run_tool_argv(n, c->args, NULL);
        for (k = 0; c->needles[k] != NULL; k++) {
            if (r.status != 2 || r.out[0] != '\0' || count_lines(r.err) != 1u || strstr(r.err, c->needles[k]) == NULL) {
                print_error("case %zu: status %d, stdout \"%s\", stderr \"%s\" (want \"%s\")\n", i, r.status, r.out,
                            r.err, c->needles[k]);
                fail();
            }
        }
        tool_result_free(&r);
    }
    /* a command's own option of the same name wins: zoom-to's --rate is the zoom */
    r = run_tool(NULL, "encode", "zoom-to", "--rate", "5.5", NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
}

/* Read errors on stdin are errors, not an empty input (encode --json - exited 0, silent). */
static void test_stdin_read_errors(void **state)
{
    char out[1024];
    (void)state;
    assert_int_equal(shell_run("encode --json -", "< /", out, sizeof(out)), 2);
    assert_non_null(strstr(out, "xfgcu: encode: cannot read stdin: Is a directory\n"));
    assert_int_equal(shell_run("encode --json -", "<&-", out, sizeof(out)), 2);
    assert_non_null(strstr(out, "xfgcu: encode: cannot read stdin: Bad file descriptor\n"));
    assert_int_equal(shell_run("decode", "< /", out, sizeof(out)), 2);
    assert_non_null(strstr(out, "xfgcu: decode: cannot read stdin: Is a directory\n")); /* the reason, not "Success" */
    assert_int_equal(shell_run("decode", "<&-", out, sizeof(out)), 2);
    assert_non_null(strstr(out, "xfgcu: decode: cannot read stdin: Bad file descriptor\n"));
    assert_int_equal(shell_run("encode --json -", "< /dev/null", out, sizeof(out)), 0); /* empty: fine */
    assert_string_equal(out, "");
}

/* What monitor --json and replay --json print, with their times, encode reads back. */
static void test_encode_takes_timed_lines(void **state)
{
    tool_result plain, timed;
    (void)state;
    plain = run_tool(NULL, "encode", "--json", "{\"direction\":\"gcu\",\"order\":\"shutter\"}", NULL);
    timed = run_tool(NULL, "encode", "--json",
                     "{\"time_mono\":12.5,\"time_utc\":\"2026-11-26T10:00:00.123Z\",\"t\":0.02,"
                     "\"time\":\"2026-11-26T10:00:00.143Z\",\"direction\":\"gcu\",\"order\":\"shutter\"}",
                     NULL);
    assert_int_equal(plain.status, 0);
    assert_int_equal(timed.status, 0);
    assert_string_equal(timed.out, plain.out);
    tool_result_free(&plain);
    tool_result_free(&timed);
}

/* The second review's cases: record --force keeps FILE when the link fails (its capture stays
 * under the temporary name, named in a note after the failure's line); --protocol after record's COMMAND is the one the
 * command is checked for; settings that
 * cannot work are refused before any link is opened, for every command. */
static void test_review_cases(void **state)
{
    char dir[] = "/tmp/xfgcu-mistaken-XXXXXX", file[128], other[128], text[64] = "";
    tool_result r;
    FILE *f;
    (void)state;
    assert_non_null(mkdtemp(dir));
    snprintf(file, sizeof(file), "%s/ex.cap", dir);
    snprintf(other, sizeof(other), "%s/new.cap", dir); /* never made: the links below fail */
    f = fopen(file, "w");
    assert_non_null(f);
    fputs("keep\n", f);
    fclose(f);
    r = run_tool(NULL, "--udp", "127.0.0.1", "--gcu-port", "9", "--local-port", "0", "--timeout", "300", "record",
                 "--force", file, "--duration", "1", NULL);
    assert_int_equal(r.status, 3);
    assert_non_null(strstr(r.err, "xfgcu: note: capture: what was captured ("));
    assert_non_null(strstr(r.err, "ex.cap is as it was\n"));
    tool_result_free(&r);
    f = fopen(file, "r");
    assert_non_null(f);
    assert_non_null(fgets(text, sizeof(text), f));
    fclose(f);
    assert_string_equal(text, "keep\n"); /* FILE as it was */
    /* --protocol after record's COMMAND: the command is checked for it (fpv is a V0.2 order, so
     * version 1 brings a note and 2 none); then the link fails, and no FILE is left */
    r = run_tool(NULL, "--tcp", "127.0.0.1:9", "record", other, "fpv", NULL);
    assert_int_equal(r.status, 3);
    assert_non_null(strstr(r.err, "add --protocol 2"));
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", "127.0.0.1:9", "record", other, "fpv", "--protocol", "2", NULL);
    assert_int_equal(r.status, 3);
    assert_null(strstr(r.err, "add --protocol 2"));
    assert_non_null(strstr(r.err, "127.0.0.1:9"));
    tool_result_free(&r);
    assert_int_equal(access(other, F_OK), -1);
    r = run_tool(NULL, "--tcp", "127.0.0.1:1", "--rate", "1", "send", "shutter", NULL);
    assert_failure(&r, 2, "--rate 1", NULL); /* a usage error, not "connection refused" */
    tool_result_free(&r);
    r = run_tool(NULL, "--rate", "1", "encode", "shutter", NULL);
    assert_failure(&r, 2, "--rate 1", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", "[::1]:2332", "--gcu-port", "1", "send", "shutter", NULL);
    assert_failure(&r, 2, "give the port once", NULL);
    tool_result_free(&r);
    {
        char cmd[300];
        snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir); /* ours: made above */
        assert_int_equal(system(cmd), 0);
    }
}

/* xfgcu help [COMMAND], -h anywhere a command's help is asked for. */
static void test_help_forms(void **state)
{
    tool_result r;
    (void)state;
    r = run_tool(NULL, "help", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "usage: xfgcu"));
    assert_non_null(strstr(r.out, "--reorder MS"));
    assert_non_null(strstr(r.out, "--trace"));
    tool_result_free(&r);
    r = run_tool(NULL, "help", "send", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "usage: xfgcu [LINK OPTIONS] send"));
    tool_result_free(&r);
    r = run_tool(NULL, "send", "shutter", "-h", NULL); /* -h wherever --help is taken */
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "shutter"));
    tool_result_free(&r);
    r = run_tool(NULL, "send", "-h", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "usage: xfgcu [LINK OPTIONS] send"));
    tool_result_free(&r);
    r = run_tool(NULL, "-h", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "usage: xfgcu"));
    tool_result_free(&r);
    r = run_tool(NULL, "help", "nothing", NULL);
    assert_failure(&r, 2, "unknown command 'nothing'", NULL);
    tool_result_free(&r);
    r = run_tool(NULL, "help", "send", "more", NULL);
    assert_failure(&r, 2, "help: unexpected argument 'more'", NULL);
    tool_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_late_replies, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_reordering_link, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_send_json_and_trace, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_impossible_settings),
        cmocka_unit_test(test_help_forms),
        cmocka_unit_test(test_stdin_read_errors),
        cmocka_unit_test(test_encode_takes_timed_lines),
        cmocka_unit_test(test_review_cases),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
