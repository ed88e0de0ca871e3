/*
 * test_cli_live.c - scriptable and live (issue 15, item 4), against `xfgcu sim`: point and rate
 * --json (their keys and values), monitor --json (the times on every line, link events when the
 * simulator stops), monitor --wait for a simulator started late (UDP, TCP, a pty link path),
 * the default wait at a terminal (a pseudo-terminal), the age of every figure in the plain
 * lines, and sim --json.
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
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>
#include <jansson.h>

#include "run_tool.h"
#include "sim_proc.h"

extern char **environ;

/* ---- helpers ---------------------------------------------------------------------------- */

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec / 1e9;
}

static void sleep_ms(long ms)
{
    struct timespec t;
    t.tv_sec = ms / 1000;
    t.tv_nsec = (ms % 1000) * 1000000L;
    nanosleep(&t, NULL);
}

/* A port nobody uses now (bound, read, released), for a program started before its peer. */
static void free_port(int type, char *buf, size_t cap)
{
    struct sockaddr_in a;
    socklen_t len = sizeof(a);
    int fd = socket(AF_INET, type, 0);
    assert_true(fd >= 0);
    memset(&a, 0, sizeof(a));
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    assert_int_equal(bind(fd, (struct sockaddr *)&a, sizeof(a)), 0);
    assert_int_equal(getsockname(fd, (struct sockaddr *)&a, &len), 0);
    snprintf(buf, cap, "%u", (unsigned)ntohs(a.sin_port));
    close(fd);
}

/* A program in the background, its stdout and stderr to files. */
typedef struct bg {
    pid_t pid;
    char out[96], err[96];
} bg;

static void bg_start(bg *b, const char *tag, ...)
{
    char *argv[40];
    int argc = 0;
    posix_spawn_file_actions_t fa;
    va_list ap;
    const char *a;
    snprintf(b->out, sizeof(b->out), "/tmp/xfgcu-live-%ld-%s.out", (long)getpid(), tag);
    snprintf(b->err, sizeof(b->err), "/tmp/xfgcu-live-%ld-%s.err", (long)getpid(), tag);
    argv[argc++] = (char *)XFGCU_EXE;
    va_start(ap, tag);
    while ((a = va_arg(ap, const char *)) != NULL && argc < 38) {
        argv[argc++] = (char *)a;
    }
    va_end(ap);
    argv[argc] = NULL;
    assert_int_equal(posix_spawn_file_actions_init(&fa), 0);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 1, b->out, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_addopen(&fa, 2, b->err, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    assert_int_equal(posix_spawn(&b->pid, XFGCU_EXE, &fa, NULL, argv, environ), 0);
    posix_spawn_file_actions_destroy(&fa);
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text = calloc(1, 1 << 20);
    size_t n;
    assert_non_null(f);
    assert_non_null(text);
    n = fread(text, 1, (1 << 20) - 1, f);
    text[n] = '\0';
    fclose(f);
    return text;
}

/* Wait for it (SIGKILL after @p limit_ms), read what it wrote, remove the files. */
static tool_result bg_finish(bg *b, long limit_ms)
{
    tool_result r;
    int wstatus = 0;
    double end = now_s() + (double)limit_ms / 1000.0;
    pid_t got;
    while ((got = waitpid(b->pid, &wstatus, WNOHANG)) == 0 && now_s() < end) {
        sleep_ms(10);
    }
    if (got == 0) {
        kill(b->pid, SIGKILL);
        waitpid(b->pid, &wstatus, 0);
        print_error("%s did not end in %ld ms\n", b->out, limit_ms);
    }
    r.status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
    r.out = slurp(b->out);
    r.err = slurp(b->err);
    r.out_len = strlen(r.out);
    r.err_len = strlen(r.err);
    unlink(b->out);
    unlink(b->err);
    b->pid = 0;
    assert_int_not_equal(got, 0);
    return r;
}

static void bg_stop(bg *b)
{
    tool_result r;
    kill(b->pid, SIGTERM);
    r = bg_finish(b, 5000);
    tool_result_free(&r);
}

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
    double moved;
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
    assert_true(int_key(o, "elapsed_ms") >= 500 && int_key(o, "elapsed_ms") < 1500);
    moved = fmod(real_key(o, "yaw") - real_key(o, "start_yaw") + 360.0, 360.0);
    assert_true(fabs(moved - 15.0) <= 4.0);                                            /* 30 deg/s for 0.5 s */
    assert_true(fabs(real_key(o, "pitch") - real_key(o, "start_pitch") + 5.0) <= 1.5); /* -10 deg/s */
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

/* monitor --json on UDP for 3 s; the simulator stops after 0.8 s and starts again at 2.1 s: every line
 * has both times, in order; packets, then the link events stale (250 ms without a reply) and
 * down (1 s), no packet while down, then up and packets again. */
static void test_monitor_json_events(void **state)
{
    const char *states[4] = {NULL, NULL, NULL, NULL};
    char port[8];
    int events = 0, packets[4] = {0, 0, 0, 0};
    double last = 0.0;
    size_t i;
    bg m, sim;
    tool_result r;
    json_t *o;
    (void)state;
    free_port(SOCK_DGRAM, port, sizeof(port));
    bg_start(&sim, "events-sim", "sim", "--udp", port, "--duration", "20", NULL);
    bg_start(&m, "events", "--udp", "127.0.0.1", "--gcu-port", port, "--local-port", "0", "monitor", "--json",
             "--duration", "3", "--wait", "3", NULL);
    sleep_ms(800);
    bg_stop(&sim);
    sleep_ms(1300);
    bg_start(&sim, "events-sim", "sim", "--udp", port, "--duration", "20", NULL);
    r = bg_finish(&m, 8000);
    bg_stop(&sim);
    assert_int_equal(r.status, 0);
    for (i = 0; (o = line_at(r.out, i)) != NULL; i++) {
        assert_times(o);
        assert_true(real_key(o, "time_mono") >= last);
        last = real_key(o, "time_mono");
        if (json_object_get(o, "event") != NULL && strcmp(str_key(o, "event"), "health") == 0) {
            (void)int_key(o, "out_of_turn"); /* the client's judgement: when it came up, and on changes */
        } else if (json_object_get(o, "event") != NULL) {
            assert_true(events < 3);
            states[events++] = event_state(o);
        } else {
            assert_string_equal(str_key(o, "direction"), "gcu");
            (void)num_key(o, "cam_yaw");
            packets[events]++;
        }
        json_decref(o);
    }
    assert_int_equal(events, 3); /* none for the first "up": the stream starts with it */
    assert_string_equal(states[0], "stale");
    assert_string_equal(states[1], "down");
    assert_string_equal(states[2], "up");
    /* the packet that brings the link up comes before the event: the client reads it first */
    assert_true(packets[0] >= 20 && packets[1] == 0 && packets[2] == 1 && packets[3] >= 1);
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

/* No GCU: --wait S ends after S s with the one line; --wait 0 and no terminal: after --timeout. */
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
    assert_true(now_s() - t0 >= 0.75 && now_s() - t0 < 3.0);
    tool_result_free(&r);
    t0 = now_s();
    r = run_tool(NULL, "--udp", "127.0.0.1", "--gcu-port", port, "--local-port", "0", "--timeout", "200", "monitor",
                 NULL);
    assert_failure(&r, 3, "no answer from the GCU on udp 127.0.0.1:", "within 200 ms", NULL);
    assert_true(now_s() - t0 < 0.75);
    tool_result_free(&r);
    r = run_tool(NULL, "--udp", "127.0.0.1", "monitor", "--wait", "-1", NULL);
    assert_failure(&r, 2, "monitor: --wait -1", NULL);
    tool_result_free(&r);
}

/* ---- a person at a terminal ----------------------------------------------------------------- */

/* Read what the pseudo-terminal @p master has for @p ms into @p buf (appending). */
static void pty_read(int master, char *buf, size_t cap, long ms)
{
    double end = now_s() + (double)ms / 1000.0;
    size_t n = strlen(buf);
    while (now_s() < end && n + 1u < cap) {
        struct pollfd p = {master, POLLIN, 0};
        ssize_t got;
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
    const char *argv[] = {XFGCU_EXE, "--udp",     "127.0.0.1", "--gcu-port", NULL, "--local-port",
                          "0",       "--timeout", "200",       "monitor",    NULL};
    pid_t pid;
    bg sim;
    (void)state;
    free_port(SOCK_DGRAM, port, sizeof(port));
    argv[4] = port;
    assert_true(master >= 0 && grantpt(master) == 0 && unlockpt(master) == 0);
    slave = open(ptsname(master), O_RDWR | O_NOCTTY);
    assert_true(slave >= 0);
    assert_int_equal(posix_spawn_file_actions_init(&fa), 0);
    posix_spawn_file_actions_adddup2(&fa, slave, 0);
    posix_spawn_file_actions_adddup2(&fa, slave, 1);
    posix_spawn_file_actions_adddup2(&fa, slave, 2);
    assert_int_equal(posix_spawn(&pid, XFGCU_EXE, &fa, NULL, (char *const *)argv, environ), 0);
    posix_spawn_file_actions_destroy(&fa);
    close(slave);
    seen[0] = '\0';
    pty_read(master, seen, sizeof(seen), 900);
    assert_int_equal(waitpid(pid, &wstatus, WNOHANG), 0); /* still waiting, past --timeout */
    assert_non_null(strstr(seen, "xfgcu: note: waiting for the GCU on udp 127.0.0.1:"));
    assert_non_null(strstr(seen, "Ctrl-C to stop"));
    bg_start(&sim, "tty-sim", "sim", "--udp", port, "--duration", "20", NULL);
    pty_read(master, seen, sizeof(seen), 1000);
    assert_non_null(strstr(seen, "\033[H\033[2J")); /* the screen */
    assert_non_null(strstr(seen, "attitude"));
    assert_non_null(strstr(seen, " age\r\n"));
    assert_non_null(strstr(seen, "link        up"));
    bg_stop(&sim);
    pty_read(master, seen, sizeof(seen), 2000); /* the link goes down (1 s): the screen says so */
    assert_non_null(strstr(seen, "NO CURRENT DATA"));
    assert_non_null(strstr(seen, "link        down"));
    kill(pid, SIGINT);
    pty_read(master, seen, sizeof(seen), 300);
    assert_int_equal(waitpid(pid, &wstatus, 0), pid);
    assert_true(WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0);
    close(master);
}

/* ---- monitor, plain lines ------------------------------------------------------------------- */

/* Each plain line gives the age of its figures; after the simulator stops, the link reads down
 * and the last attitude is shown with an age of more than a second. */
static void test_monitor_plain_ages(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    const char *args[8];
    const char *down;
    double age = 0.0;
    bg m;
    tool_result r;
    sim_start(s, SIM_TCP, NULL);
    assert_int_equal(sim_link_args(s, args), 2);
    bg_start(&m, "plain", args[0], args[1], "monitor", "--duration", "2.6", NULL);
    sleep_ms(600);
    assert_int_equal(sim_stop(s), 0);
    r = bg_finish(&m, 8000);
    assert_int_equal(r.status, 0);
    assert_int_equal(count_lines(r.out), 3); /* at 0, 1 and 2 s */
    assert_true(strncmp(r.out, "    0.0 s  link up, ", 20) == 0);
    assert_non_null(strstr(r.out, " deg (age 0.0"));
    assert_non_null(strstr(r.out, "  no target (age 0.0"));
    down = strchr(strchr(r.out, '\n') + 1, '\n') + 1; /* the third line, at about 2 s */
    assert_non_null(strstr(down, " s  link down, "));
    down = strstr(down, " deg (age ");
    assert_non_null(down);
    assert_int_equal(sscanf(down, " deg (age %lf s)", &age), 1);
    assert_true(age >= 1.0 && age < 2.5);
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
