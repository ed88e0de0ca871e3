/*
 * test_cli_live.c - scriptable and live (issue 15, item 4), against `xfgcu sim`: point and rate
 * --json (their keys and values), monitor --json (the times on every line, link events when the
 * simulator stops), monitor --wait for a simulator started late (UDP, TCP, a pty link path),
 * the default wait at a terminal (a pseudo-terminal), the age of every figure in the plain
 * lines, and sim --json. Each step waits for what a program has shown, not for a time, and the
 * figures are checked against the program's own times: none depends on the machine's load.
 */
#define _POSIX_C_SOURCE 200809L
#define _XOPEN_SOURCE   600 /* posix_openpt, grantpt, unlockpt, ptsname */

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <setjmp.h>
#include <signal.h>
#include <spawn.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>
#include <jansson.h>

#include "bg_proc.h"
#include "run_tool.h"
#include "sim_proc.h"

extern char **environ;

/* ---- helpers ---------------------------------------------------------------------------- */

/* A port nobody uses now (bound, read, released), for a program started before its peer. */
static void free_port(int type, char *buf, size_t cap) { close(hold_port(type, buf, cap)); }

/* The JSON object on line @p i (0-based) of @p text; NULL past the end. */
static json_t *line_at(const char *text, size_t i)
{
    while (i > 0 && *text != '\0') {
        text += strcspn(text, "\n");
        text += (*text == '\n');
        i--;
    }
    return (*text != '\0') ? parse_line(text) : NULL;
}

static double real_key(const json_t *o, const char *key)
{
    json_t *v = json_object_get(o, key);
    if (!json_is_number(v)) {
        print_error("no number under \"%s\"\n", key);
        fail();
    }
    return json_number_value(v);
}

/* Both times of every --json line: time_mono a number, time_utc "2026-11-26T10:00:00.123Z". */
static void assert_times(const json_t *o)
{
    const char *utc = str_key(o, "time_utc");
    assert_true(real_key(o, "time_mono") > 0.0);
    assert_int_equal(strlen(utc), 24);
    assert_true(utc[4] == '-' && utc[10] == 'T' && utc[19] == '.' && utc[23] == 'Z');
}

/* ---- point and rate --json ------------------------------------------------------------------ */

/* The mode's line: {"step": "mode", "status": STATUS, "order_name": ORDER, ...}. */
static void assert_mode_line(const json_t *o, const char *status, const char *order)
{
    static const char *const keys[] = {"order", "state", "failed_cameras", "packets", "elapsed_ms"};
    size_t i;
    assert_times(o);
    assert_string_equal(str_key(o, "step"), "mode");
    assert_string_equal(str_key(o, "status"), status);
    assert_string_equal(str_key(o, "order_name"), order);
    assert_non_null(strstr(str_key(o, "link"), "127.0.0.1:"));
    for (i = 0; i < sizeof(keys) / sizeof(keys[0]); i++) {
        (void)int_key(o, keys[i]);
    }
}

/* An angle printed as the GCU's hundredths of a degree, with no float tail (12.340000152587891). */
static void assert_hundredths(double deg) { assert_true(fabs(deg * 100.0 - round(deg * 100.0)) < 1e-9); }

static void test_point_json(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    /* -30.3 and 45.3 are no float's value: a float round trip would show in the angles printed */
    tool_result r = sim_run_on(s, "point", "--pitch", "-30.3", "--yaw", "45.3", "--json", NULL);
    json_t *o;
    assert_int_equal(r.status, 0);
    assert_int_equal(r.err_len, 0);
    assert_int_equal(count_lines(r.out), 2);
    o = line_at(r.out, 0);
    assert_mode_line(o, "ok", "euler");
    json_decref(o);
    o = line_at(r.out, 1);
    assert_times(o);
    assert_string_equal(str_key(o, "step"), "point");
    assert_string_equal(str_key(o, "status"), "reached");
    assert_true(json_is_null(json_object_get(o, "target_roll")));
    assert_true(real_key(o, "target_pitch") == -30.3 && real_key(o, "target_yaw") == 45.3);
    assert_true(fabs(real_key(o, "pitch") + 30.3) <= 0.5 && fabs(real_key(o, "yaw") - 45.3) <= 0.5);
    assert_true(fabs(real_key(o, "roll")) <= 0.5);
    assert_hundredths(real_key(o, "pitch"));
    assert_hundredths(real_key(o, "yaw"));
    assert_true(real_key(o, "tolerance_deg") == 0.5);
    assert_true(int_key(o, "elapsed_ms") >= 0 && int_key(o, "elapsed_ms") < 10000);
    assert_true(int_key(o, "attitude_age_ms") >= 0 && int_key(o, "attitude_age_ms") < 1000);
    json_decref(o);
    tool_result_free(&r);
    /* not there in time: both lines, the motion's says where it is; then the one stderr line */
    r = sim_run_on(s, "point", "--pitch", "120", "--yaw", "0", "--wait", "0.3", "--json", NULL);
    assert_int_equal(r.status, 3);
    assert_int_equal(count_lines(r.out), 2);
    assert_int_equal(count_lines(r.err), 1);
    assert_non_null(strstr(r.err, "xfgcu: point: not there in time"));
    o = line_at(r.out, 1);
    assert_string_equal(str_key(o, "status"), "not_there");
    assert_true(real_key(o, "pitch") < 119.0);
    json_decref(o);
    tool_result_free(&r);
}

static void test_rate_json(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r = sim_run_on(s, "rate", "--pitch", "-10", "--yaw", "30", "--duration", "0.5", "--json", NULL);
    json_t *o;
    double moved, secs;
    assert_int_equal(r.status, 0);
    assert_int_equal(r.err_len, 0);
    assert_int_equal(count_lines(r.out), 2);
    o = line_at(r.out, 0);
    assert_mode_line(o, "ok", "head_lock");
    json_decref(o);
    o = line_at(r.out, 1);
    assert_times(o);
    assert_string_equal(str_key(o, "step"), "rate");
    assert_string_equal(str_key(o, "status"), "done");
    assert_true(real_key(o, "pitch_dps") == -10.0 && real_key(o, "yaw_dps") == 30.0);
    assert_true(real_key(o, "duration_s") == 0.5);
    secs = (double)int_key(o, "elapsed_ms") / 1000.0; /* how long the rates were sent */
    assert_true(secs >= 0.5 && secs < 3.0);
    /* 30 deg/s and -10 deg/s for that long; the simulator's time with each rate is that, give or take
     * how late its first and last packets came (more on a loaded machine): a third of it */
    moved = fmod(real_key(o, "yaw") - real_key(o, "start_yaw") + 360.0, 360.0);
    assert_true(fabs(moved - 30.0 * secs) <= 10.0 * secs + 1.0);
    assert_true(fabs(real_key(o, "pitch") - real_key(o, "start_pitch") + 10.0 * secs) <= 3.4 * secs + 0.5);
    (void)real_key(o, "start_roll");
    (void)real_key(o, "roll");
    assert_hundredths(real_key(o, "start_yaw"));
    assert_hundredths(real_key(o, "yaw"));
    assert_true(fabs(real_key(o, "rate_x")) < 1.0 && fabs(real_key(o, "rate_y")) < 1.0 &&
                fabs(real_key(o, "rate_z")) < 1.0); /* holding still: the final rates */
    json_decref(o);
    tool_result_free(&r);
}

/* A mode the GCU refuses: its JSON line says so, then the one stderr line, exit 1. */
static void test_mode_refused_json(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    json_t *o;
    sim_start(s, SIM_TCP, "--fail", "head-lock=1", NULL);
    r = sim_run_on(s, "rate", "--pitch", "0", "--yaw", "10", "--duration", "0.2", "--json", NULL);
    assert_int_equal(r.status, 1);
    assert_int_equal(count_lines(r.out), 1);
    assert_int_equal(count_lines(r.err), 1);
    assert_non_null(strstr(r.err, "xfgcu: rate: head_lock: the GCU answered failed"));
    o = line_at(r.out, 0);
    assert_mode_line(o, "failed", "head_lock");
    assert_int_equal(int_key(o, "state"), 1);
    json_decref(o);
    tool_result_free(&r);
}

/* ---- monitor --json --------------------------------------------------------------------------- */

/* The link event on line @p o: its state, checked ("stale", "down" or "up"). */
static const char *event_state(const json_t *o)
{
    const char *st = str_key(o, "state");
    assert_string_equal(str_key(o, "event"), "link");
    assert_non_null(strstr(str_key(o, "link"), "udp 127.0.0.1:"));
    assert_true(int_key(o, "reply_age_ms") >= 0);
    if (strcmp(st, "down") == 0) {
        assert_true(int_key(o, "reply_age_ms") >= 1000);
        return "down";
    }
    return strcmp(st, "stale") == 0 ? "stale" : strcmp(st, "up") == 0 ? "up" : "?";
}

/* monitor --json on UDP; the simulator stops once 20 packets are shown and starts again once the
 * link is down: every line has both times, in order; packets, then the link events stale (250 ms
 * without a reply) and down (1 s), no packet while down (none before the simulator is back), then
 * up and packets again. Each step waits for what the monitor has shown, not for a time. On a
 * loaded machine a stall may show as a stale then up before the simulator stops: those pairs are
 * allowed, the down and its stale and up must be there in that order. */
static void test_monitor_json_events(void **state)
{
    char port[8];
    int packets_before = 0, packets_down = 0, downs = 0, up_after_down = 0;
    const char *prev = "up", *st;
    double last = 0.0, restarted;
    size_t i;
    bg m, sim;
    tool_result r;
    json_t *o;
    (void)state;
    free_port(SOCK_DGRAM, port, sizeof(port));
    bg_start(&sim, "events-sim", "sim", "--udp", port, "--duration", "40", NULL);
    bg_start(&m, "events", "--udp", "127.0.0.1", "--gcu-port", port, "--local-port", "0", "monitor", "--json", "--wait",
             "10", NULL);
    assert_true(bg_wait_output(&m, "\"direction\":\"gcu\"", 20, 20.0));
    bg_stop(&sim);
    assert_true(bg_wait_output(&m, "\"state\":\"down\"", 1, 20.0));
    restarted = now_s();
    bg_start(&sim, "events-sim", "sim", "--udp", port, "--duration", "40", NULL);
    assert_true(bg_wait_output(&m, "\"state\":\"up\"", 1, 20.0));
    kill(m.pid, SIGTERM);
    r = bg_finish(&m, 10000);
    bg_stop(&sim);
    assert_int_equal(r.status, 0);
    for (i = 0; (o = line_at(r.out, i)) != NULL; i++) {
        assert_times(o);
        assert_true(real_key(o, "time_mono") >= last);
        last = real_key(o, "time_mono");
        if (json_object_get(o, "event") != NULL && strcmp(str_key(o, "event"), "health") == 0) {
            (void)int_key(o, "out_of_turn"); /* the client's judgement: when it came up, and on changes */
        } else if (json_object_get(o, "event") != NULL) {
            st = event_state(o);
            /* a change each time (none for the first "up": the stream starts with it); down only
             * after stale, then only up */
            assert_true(strcmp(st, prev) != 0 && (strcmp(st, "down") != 0 || strcmp(prev, "stale") == 0));
            assert_true(strcmp(prev, "down") != 0 || strcmp(st, "up") == 0);
            downs += strcmp(st, "down") == 0;
            up_after_down |= strcmp(prev, "down") == 0;
            prev = st;
        } else {
            assert_string_equal(str_key(o, "direction"), "gcu");
            (void)num_key(o, "cam_yaw");
            if (strcmp(prev, "down") == 0) {
                /* the packets that bring the link up come before the event (the client reads them
                 * first): from the restarted simulator */
                assert_true(real_key(o, "time_mono") >= restarted);
                packets_down++;
            } else if (downs == 0) {
                packets_before++;
            }
        }
        json_decref(o);
    }
    assert_int_equal(downs, 1);
    assert_true(up_after_down);
    assert_true(packets_before >= 20 && packets_down >= 1);
    assert_non_null(strstr(r.err, "xfgcu: note: link down on udp 127.0.0.1:"));
    tool_result_free(&r);
}

/* ---- monitor --wait -------------------------------------------------------------------------- */

/* monitor started first with --wait 5 (and --timeout 300), the simulator 1 s later: it waits,
 * then shows packets; exit 0. @p link: the monitor's link options, 2 or 6 of them. */
static void wait_then(sim_proc *s, const char *const *link, int n, const char *tag, const char *sim_kind,
                      const char *sim_where)
{
    bg m, sim;
    tool_result r;
    json_t *o;
    double t0 = now_s();
    assert_true(n == 2 || n == 6);
    if (n == 2) {
        bg_start(&m, tag, "--timeout", "300", link[0], link[1], "monitor", "--wait", "5", "--json", "--count", "3",
                 NULL);
    } else {
        bg_start(&m, tag, "--timeout", "300", link[0], link[1], link[2], link[3], link[4], link[5], "monitor", "--wait",
                 "5", "--json", "--count", "3", NULL);
    }
    sleep_ms(1000);
    if (strcmp(sim_kind, "--pty") == 0) {
        sim_start(s, SIM_PTY, "--link", sim_where, NULL);
    } else {
        bg_start(&sim, "late-sim", "sim", sim_kind, sim_where, "--duration", "20", NULL);
    }
    r = bg_finish(&m, 8000);
    if (strcmp(sim_kind, "--pty") != 0) {
        bg_stop(&sim);
    }
    if (r.status != 0) {
        print_error("status %d\nstdout: %s\nstderr: %s\n", r.status, r.out, r.err);
        fail();
    }
    assert_int_equal(r.err_len, 0);                 /* no terminal: no note */
    assert_int_equal(count_packet_lines(r.out), 3); /* three packets (and the health event) */
    o = line_at(r.out, 0);
    assert_times(o);
    assert_string_equal(str_key(o, "direction"), "gcu");
    json_decref(o);
    assert_true(now_s() - t0 >= 1.0);
    tool_result_free(&r);
}

static void test_monitor_wait_udp(void **state)
{
    char port[8];
    const char *link[6] = {"--udp", "127.0.0.1", "--gcu-port", NULL, "--local-port", "0"};
    free_port(SOCK_DGRAM, port, sizeof(port));
    link[3] = port;
    wait_then((sim_proc *)*state, link, 6, "wait-udp", "--udp", port);
}

static void test_monitor_wait_tcp(void **state)
{
    char port[8], where[32];
    const char *link[2] = {"--tcp", where};
    free_port(SOCK_STREAM, port, sizeof(port));
    snprintf(where, sizeof(where), "127.0.0.1:%s", port);
    wait_then((sim_proc *)*state, link, 2, "wait-tcp", "--tcp", port);
}

static void test_monitor_wait_pty(void **state)
{
    char path[96];
    const char *link[2] = {"--serial", path};
    snprintf(path, sizeof(path), "/tmp/xfgcu-live-%ld-gcu", (long)getpid());
    unlink(path);
    wait_then((sim_proc *)*state, link, 2, "wait-pty", "--pty", path);
}

/* No GCU: --wait S ends after S s with the one line; --wait 0 and no terminal: after --timeout.
 * The times the messages give are the program's; the ones measured here include starting it, on
 * whatever load: at least what was asked, at most a bound no wait for the other one would keep. */
static void test_monitor_wait_in_vain(void **state)
{
    char port[8];
    double t0;
    tool_result r;
    (void)state;
    free_port(SOCK_DGRAM, port, sizeof(port));
    t0 = now_s();
    r = run_tool(NULL, "--udp", "127.0.0.1", "--gcu-port", port, "--local-port", "0", "--timeout", "200", "monitor",
                 "--wait", "0.8", NULL);
    assert_failure(&r, 3, "no answer from the GCU on udp 127.0.0.1:", "within 0.8 s", NULL);
    assert_true(now_s() - t0 >= 0.75 && now_s() - t0 < 5.0);
    tool_result_free(&r);
    t0 = now_s();
    r = run_tool(NULL, "--udp", "127.0.0.1", "--gcu-port", port, "--local-port", "0", "--timeout", "200", "monitor",
                 NULL);
    assert_failure(&r, 3, "no answer from the GCU on udp 127.0.0.1:", "within 200 ms", NULL);
    assert_true(now_s() - t0 >= 0.2 && now_s() - t0 < 5.0); /* not the wait of a terminal: until Ctrl-C */
    tool_result_free(&r);
    r = run_tool(NULL, "--udp", "127.0.0.1", "monitor", "--wait", "-1", NULL);
    assert_failure(&r, 2, "monitor: --wait -1", NULL);
    tool_result_free(&r);
}

/* ---- a person at a terminal ----------------------------------------------------------------- */

/* Read what the pseudo-terminal @p master has into @p buf (appending) until it holds every needle
 * (NULL-terminated; none: until it ends), for at most @p ms. */
static void pty_read_until(int master, char *buf, size_t cap, long ms, ...)
{
    double end = now_s() + (double)ms / 1000.0;
    size_t n = strlen(buf);
    while (now_s() < end && n + 1u < cap) {
        struct pollfd p = {master, POLLIN, 0};
        const char *needle;
        int all = 1;
        ssize_t got;
        va_list ap;
        va_start(ap, ms);
        while ((needle = va_arg(ap, const char *)) != NULL) {
            all &= strstr(buf, needle) != NULL;
        }
        va_end(ap);
        va_start(ap, ms);
        needle = va_arg(ap, const char *);
        va_end(ap);
        if (all && needle != NULL) {
            return;
        }
        if (poll(&p, 1, 20) <= 0) {
            continue;
        }
        got = read(master, buf + n, cap - n - 1u);
        if (got <= 0) {
            break; /* EIO: the program has closed its end */
        }
        n += (size_t)got;
        buf[n] = '\0';
    }
}

/* monitor on a terminal with no --wait: it waits past --timeout, saying so in one line, then
 * shows the screen with the age of the figures; Ctrl-C ends it with exit 0. */
static void test_monitor_terminal(void **state)
{
    static char seen[1 << 18];
    char port[8];
    int master = posix_openpt(O_RDWR | O_NOCTTY), slave, wstatus = 0;
    posix_spawn_file_actions_t fa;
    const char *args[] = {"--udp", "127.0.0.1", "--gcu-port", NULL, "--local-port", "0", "--timeout", "200", "monitor"};
    char **argv;
    pid_t pid;
    bg sim;
    (void)state;
    free_port(SOCK_DGRAM, port, sizeof(port));
    args[3] = port;
    argv = spawn_argv((int)(sizeof(args) / sizeof(args[0])), args);
    assert_true(master >= 0 && grantpt(master) == 0 && unlockpt(master) == 0);
    slave = open(ptsname(master), O_RDWR | O_NOCTTY);
    assert_true(slave >= 0);
    assert_int_equal(posix_spawn_file_actions_init(&fa), 0);
    posix_spawn_file_actions_adddup2(&fa, slave, 0);
    posix_spawn_file_actions_adddup2(&fa, slave, 1);
    posix_spawn_file_actions_adddup2(&fa, slave, 2);
    assert_int_equal(posix_spawn(&pid, XFGCU_EXE, &fa, NULL, argv, environ), 0);
    posix_spawn_file_actions_destroy(&fa);
    free(argv);
    close(slave);
    seen[0] = '\0';
    pty_read_until(master, seen, sizeof(seen), 20000, "Ctrl-C to stop", NULL); /* past --timeout */
    assert_int_equal(waitpid(pid, &wstatus, WNOHANG), 0);                      /* still waiting */
    assert_non_null(strstr(seen, "xfgcu: note: waiting for the GCU on udp 127.0.0.1:"));
    assert_non_null(strstr(seen, "Ctrl-C to stop"));
    bg_start(&sim, "tty-sim", "sim", "--udp", port, "--duration", "40", NULL);
    pty_read_until(master, seen, sizeof(seen), 20000, "\033[H\033[2J", "attitude", " age\r\n", "link        up", NULL);
    assert_non_null(strstr(seen, "\033[H\033[2J")); /* the screen */
    assert_non_null(strstr(seen, "attitude"));
    assert_non_null(strstr(seen, " age\r\n"));
    assert_non_null(strstr(seen, "link        up"));
    bg_stop(&sim);
    seen[0] = '\0'; /* what comes from now on: the link goes down (1 s), the screen says so */
    pty_read_until(master, seen, sizeof(seen), 20000, "NO CURRENT DATA", "link        down", NULL);
    assert_non_null(strstr(seen, "NO CURRENT DATA"));
    assert_non_null(strstr(seen, "link        down"));
    kill(pid, SIGINT);
    pty_read_until(master, seen, sizeof(seen), 5000, NULL); /* to its end */
    assert_int_equal(waitpid(pid, &wstatus, 0), pid);
    assert_true(WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0);
    close(master);
}

/* ---- monitor, plain lines ------------------------------------------------------------------- */

/* Each plain line (one a second) gives the age of its figures; once the simulator stops, the
 * link reads down (at once on TCP: the connection closes) and the last attitude is shown with an
 * age that grows with the time (no newer one came), never more than the monitor has run. Each
 * step waits for what the monitor has shown. */
static void test_monitor_plain_ages(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    const char *args[8];
    const char *line;
    double age[2] = {0.0, 0.0}, at[2] = {0.0, 0.0}, t = 0.0, prev = -1.0;
    int downs = 0;
    bg m;
    tool_result r;
    sim_start(s, SIM_TCP, NULL);
    assert_int_equal(sim_link_args(s, args), 2);
    bg_start(&m, "plain", args[0], args[1], "monitor", NULL);
    assert_true(bg_wait_output(&m, " s  link up, ", 1, 20.0));
    assert_int_equal(sim_stop(s), 0);
    assert_true(bg_wait_output(&m, " s  link down, ", 2, 20.0));
    kill(m.pid, SIGTERM);
    r = bg_finish(&m, 10000);
    assert_int_equal(r.status, 0);
    assert_true(strncmp(r.out, "    0.0 s  link up, ", 20) == 0);
    assert_non_null(strstr(r.out, " deg (age 0.0"));
    assert_non_null(strstr(r.out, "  no target (age 0.0"));
    for (line = r.out; *line != '\0'; line += strcspn(line, "\n"), line += (*line == '\n')) {
        const char *deg = strstr(line, " deg (age ");
        assert_int_equal(sscanf(line, "%lf s ", &t), 1);
        assert_true(t >= prev + 0.9); /* one line a second */
        prev = t;
        assert_non_null(strstr(line, " s  "));
        assert_non_null(deg);
        if (strncmp(strstr(line, " s  ") + 4, "link down, ", 11) == 0 && downs < 2) {
            assert_int_equal(sscanf(deg, " deg (age %lf s)", &age[downs]), 1);
            at[downs++] = t;
        }
    }
    assert_int_equal(downs, 2);
    assert_true(age[0] >= 0.0 && age[0] <= at[0] + 0.1);
    assert_true(fabs((age[1] - age[0]) - (at[1] - at[0])) <= 0.15); /* the same attitude, older */
    assert_true(age[1] >= 0.9);
    tool_result_free(&r);
}

/* ---- sim --json ------------------------------------------------------------------------------- */

static void test_sim_json(void **state)
{
    bg sim;
    tool_result r;
    json_t *o;
    char *text = NULL, tcp[32];
    double end = now_s() + 5.0;
    (void)state;
    bg_start(&sim, "sim-json", "sim", "--tcp", "0", "--json", "--verbose", "--fail", "zoom-in=2", "--duration", "20",
             NULL);
    do { /* its first line: the link it listens on */
        sleep_ms(20);
        free(text);
        text = slurp(sim.out);
    } while (strchr(text, '\n') == NULL && now_s() < end);
    o = parse_line(text);
    free(text);
    assert_times(o);
    assert_string_equal(str_key(o, "event"), "listening");
    assert_string_equal(str_key(o, "link"), "tcp");
    assert_string_equal(str_key(o, "host"), "127.0.0.1");
    assert_true(int_key(o, "port") > 0 && int_key(o, "port") < 65536);
    assert_int_equal(int_key(o, "protocol"), 1);
    snprintf(tcp, sizeof(tcp), "127.0.0.1:%d", (int)int_key(o, "port"));
    json_decref(o);
    r = run_tool(NULL, "--tcp", tcp, "send", "shutter", NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", tcp, "send", "zoom-in", NULL);
    assert_int_equal(r.status, 1);
    tool_result_free(&r);
    kill(sim.pid, SIGTERM);
    r = bg_finish(&sim, 5000);
    assert_int_equal(r.status, 0);
    assert_int_equal(count_lines(r.out), 3);
    o = line_at(r.out, 1);
    assert_times(o);
    assert_string_equal(str_key(o, "event"), "executed");
    assert_string_equal(str_key(o, "order_name"), "shutter");
    assert_int_equal(int_key(o, "order"), 0x20);
    assert_int_equal(int_key(o, "state"), 0);
    assert_true(real_key(o, "t") > 0.0);
    json_decref(o);
    o = line_at(r.out, 2);
    assert_string_equal(str_key(o, "order_name"), "zoom_in");
    assert_int_equal(int_key(o, "state"), 2);
    json_decref(o);
    tool_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_point_json, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_rate_json, sim_setup_udp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_mode_refused_json, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_monitor_json_events),
        cmocka_unit_test_setup_teardown(test_monitor_wait_udp, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_monitor_wait_tcp, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_monitor_wait_pty, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_monitor_wait_in_vain),
        cmocka_unit_test(test_monitor_terminal),
        cmocka_unit_test_setup_teardown(test_monitor_plain_ages, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_sim_json),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
