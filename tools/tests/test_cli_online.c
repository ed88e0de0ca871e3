/*
 * test_cli_online.c - the commands that talk to a GCU, against `xfgcu sim`
 * running in the background on each link (TCP, UDP, a pseudo-terminal):
 * send (ok, failed with a camera mask, calibration's "operating"), no GCU
 * at all, monitor --json and plain, point and rate moving the simulated
 * gimbal, capture then replay, and the link named every way (--link, XFGCU_LINK, --udp HOST:PORT).
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <glob.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>
#include <cmocka.h>
#include <jansson.h>

#include "run_tool.h"
#include "sim_proc.h"

/* ---- helpers ---------------------------------------------------------------------- */

static void expect(const tool_result *r, int status, const char *out)
{
    if (r->status != status || strcmp(r->out, out) != 0) {
        print_error("status %d (want %d)\nstdout: \"%s\" (want \"%s\")\nstderr: %s\n", r->status, status, r->out, out,
                    r->err);
        fail();
    }
}

/* Every line of @p text is a GCU packet object with the decode --json keys, or an event (monitor's
 * health, when the GCU comes up); returns how many packets. */
static size_t check_gcu_lines(const char *text, uint8_t version)
{
    static const char *const keys[] = {"version",    "length",     "order",           "gimbal_mode",
                                       "pod_status", "cam_roll",   "cam_pitch",       "cam_yaw",
                                       "rate_x",     "sub_header", "gimbal_code",     "target_distance",
                                       "zoom_cam1",  "zoom_cam2",  "target_latitude", "rel_angle_z"};
    size_t n = 0, k;
    const char *p = text;
    while (*p != '\0') {
        size_t len = strcspn(p, "\n");
        json_t *obj = parse_line(p);
        if (json_object_get(obj, "event") != NULL) {
            json_decref(obj);
            p += len + (p[len] == '\n');
            continue;
        }
        assert_string_equal(json_string_value(json_object_get(obj, "direction")), "gcu");
        assert_non_null(json_object_get(obj, "params"));
        for (k = 0; k < sizeof(keys) / sizeof(keys[0]); k++) {
            (void)num_key(obj, keys[k]); /* engineering units: numbers, not all integers */
        }
        assert_int_equal(int_key(obj, "version"), version);
        if (version >= 2u) {
            (void)int_key(obj, "thermal_status");
            (void)int_key(obj, "camera_status");
            (void)int_key(obj, "time_zone");
        }
        json_decref(obj);
        n++;
        p += len + (p[len] == '\n');
    }
    return n;
}

/* The attitude the simulator reports now (raw 0.01 deg), through monitor --json --raw --count 1: its
 * one packet (the first line; the client's health event follows it). */
static void attitude(const sim_proc *s, long *pitch, long *yaw)
{
    tool_result r = sim_run_on(s, "monitor", "--json", "--raw", "--count", "1", NULL);
    json_t *obj;
    assert_int_equal(r.status, 0);
    assert_int_equal(count_packet_lines(r.out), 1);
    obj = parse_line(r.out);
    *pitch = (long)int_key(obj, "cam_pitch");
    *yaw = (long)int_key(obj, "cam_yaw");
    json_decref(obj);
    tool_result_free(&r);
}

/* ---- send --------------------------------------------------------------------------- */

static void test_send_ok(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r = sim_run_on(s, "send", "shutter", NULL);
    expect(&r, 0, "ok\n");
    assert_int_equal(r.err_len, 0);
    tool_result_free(&r);
    r = sim_run_on(s, "send", "zoom-to", "--rate", "5.5", NULL);
    expect(&r, 0, "ok\n");
    tool_result_free(&r);
    r = sim_run_on(s, "send", "shutter", "--cameras", "all", NULL);
    expect(&r, 0, "ok\n");
    tool_result_free(&r);
}

static void test_send_failed_mask(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    sim_start(s, SIM_TCP, "--fail", "zoom-in=0x02", "--fail", "shutter=1", NULL);
    r = sim_run_on(s, "send", "zoom-in", NULL);
    expect(&r, 1, "failed cameras 0x02\n");
    assert_int_equal(count_lines(r.err), 1);
    assert_non_null(strstr(r.err, "xfgcu: send zoom-in: the GCU answered failed cameras 0x02"));
    tool_result_free(&r);
    r = sim_run_on(s, "send", "shutter", NULL);
    expect(&r, 1, "failed\n");
    assert_int_equal(count_lines(r.err), 1);
    tool_result_free(&r);
    r = sim_run_on(s, "send", "focus", NULL); /* the others still work */
    expect(&r, 0, "ok\n");
    tool_result_free(&r);
}

static void test_send_calibration(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    sim_start(s, SIM_UDP, "--calibration-ms", "300", NULL);
    r = sim_run_on(s, "send", "calibration", NULL);
    expect(&r, 0, "operating\nok\n");
    tool_result_free(&r);
}

static void test_send_v2(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    sim_start(s, SIM_TCP, "--protocol", "2", NULL);
    r = sim_run_on(s, "--protocol", "2", "send", "digital-zoom", "--on", NULL);
    expect(&r, 0, "ok\n");
    tool_result_free(&r);
    r = sim_run_on(s, "monitor", "--json", "--count", "3", NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(check_gcu_lines(r.out, 2), 3);
    tool_result_free(&r);
}

/* An order the GCU's model lacks (V2.0.6's support list) is not sent without --force; with it,
 * the GCU (a simulated Z-6A, code 0: focus, no palette) answers failed, with state 0x02: palette is
 * an order only camera 2 takes (V2.0.6). */
static void test_send_model_support(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r;
    sim_start(s, SIM_TCP, "--model", "0", "--verbose", NULL);
    r = sim_run_on(s, "send", "palette", "--mode", "1", NULL);
    assert_failure(&r, 1, "send palette: the GCU's model Z-6A (code 0) does not support it", "--force", NULL);
    tool_result_free(&r);
    r = sim_run_on(s, "send", "palette", "--mode", "1", "--force", NULL);
    expect(&r, 1, "failed cameras 0x02\n");
    tool_result_free(&r);
    r = sim_run_on(s, "send", "--force", "focus", NULL);
    expect(&r, 0, "ok\n");
    tool_result_free(&r);
}

/* send osd --show / --hide mean what they say on a V0.2 GCU, whose OSD values are inverted
 * (the program sends the value of the version the GCU speaks). */
static void test_send_osd_follows_gcu(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    static const char *const sw[] = {"--hide", "--show"};
    int i;
    sim_start(s, SIM_TCP, "--protocol", "2", NULL);
    for (i = 0; i < 2; i++) {
        tool_result r = sim_run_on(s, "send", "osd", sw[i], NULL);
        json_t *obj;
        expect(&r, 0, "ok\n");
        tool_result_free(&r);
        r = sim_run_on(s, "monitor", "--json", "--count", "1", NULL);
        assert_int_equal(r.status, 0);
        obj = parse_line(r.out);
        assert_int_equal((int_key(obj, "camera_status") & 0x2000) != 0, i); /* XF_CAMERA_OSD_ON */
        json_decref(obj);
        tool_result_free(&r);
    }
}

/* ---- no GCU -------------------------------------------------------------------------- */

/* The simulator answers to a fixed address and port (the vendor's GCU: the LAN broadcast address,
 * port 2338), not to the sender: a host listening there gets the replies, one listening elsewhere
 * does not. */
static void test_sim_reply_to(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    char local[8], to[32];
    int fd = hold_port(SOCK_DGRAM, local, sizeof(local));
    tool_result r;
    close(fd); /* a free port, for the host to listen on */
    snprintf(to, sizeof(to), "127.0.0.1:%s", local);
    sim_start(s, SIM_UDP, "--reply-to", to, NULL);
    r = run_tool(NULL, "--udp", "127.0.0.1", "--gcu-port", s->port, "--local-port", local, "send", "shutter", NULL);
    expect(&r, 0, "ok\n");
    tool_result_free(&r);
    r = run_tool(NULL, "--udp", "127.0.0.1", "--gcu-port", s->port, "--local-port", "0", "--timeout", "400", "send",
                 "shutter", NULL);
    assert_failure(&r, 3, "no answer from the GCU", NULL);
    tool_result_free(&r);
}

static void test_no_gcu(void **state)
{
    char port[8], tcp[32];
    int fd = hold_port(SOCK_STREAM, port, sizeof(port));
    tool_result r;
    (void)state;
    snprintf(tcp, sizeof(tcp), "127.0.0.1:%s", port);
    r = run_tool(NULL, "--tcp", tcp, "--timeout", "300", "send", "shutter", NULL);
    assert_failure(&r, 3, "--tcp 127.0.0.1:", "connect to 127.0.0.1:", NULL);
    tool_result_free(&r);
    close(fd);
    fd = hold_port(SOCK_DGRAM, port, sizeof(port));
    r = run_tool(NULL, "--udp", "127.0.0.1", "--gcu-port", port, "--local-port", "0", "--timeout", "300", "monitor",
                 NULL);
    assert_failure(&r, 3, "no answer from the GCU on udp 127.0.0.1:", "within 300 ms", NULL);
    tool_result_free(&r);
    close(fd);
    r = run_tool(NULL, "--serial", "/dev/xfgcu-no-such-device", "send", "shutter", NULL);
    assert_failure(&r, 3, "--serial /dev/xfgcu-no-such-device", "No such file or directory", NULL);
    tool_result_free(&r);
}

static void test_sim_port_taken(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r = run_tool(NULL, "sim", "--tcp", s->port, "--duration", "5", NULL);
    assert_failure(&r, 3, "sim --tcp", s->port, NULL);
    tool_result_free(&r);
}

/* ---- the link, however it is named --------------------------------------------------------- */

/* send shutter on @p s with the link named by @p a and @p b (NULL: none), XFGCU_LINK=@p env (NULL: unset). */
static void expect_send_ok(const sim_proc *s, const char *a, const char *b, const char *env)
{
    const char *args[6];
    int n = 0;
    tool_result r;
    (void)s;
    if (env != NULL) {
        assert_int_equal(setenv("XFGCU_LINK", env, 1), 0);
    }
    if (a != NULL) {
        args[n++] = a;
        args[n++] = b;
    }
    args[n++] = "send";
    args[n++] = "shutter";
    r = run_tool_argv(n, args, NULL);
    if (r.status != 0 || strcmp(r.out, "ok\n") != 0) {
        print_error("%s %s (XFGCU_LINK %s): status %d\nstdout: %s\nstderr: %s\n", a ? a : "", b ? b : "",
                    env ? env : "unset", r.status, r.out, r.err);
        fail();
    }
    tool_result_free(&r);
    assert_int_equal(unsetenv("XFGCU_LINK"), 0);
}

/* The library's link strings, as --link SPEC and XFGCU_LINK, and --udp HOST:PORT like --tcp
 * HOST:PORT: each reaches the simulator on its link. */
static void test_link_forms(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    char spec[192], host_port[64];
    sim_start(s, SIM_TCP, NULL);
    snprintf(spec, sizeof(spec), "tcp:127.0.0.1:%s", s->port);
    snprintf(host_port, sizeof(host_port), "127.0.0.1:%s", s->port);
    expect_send_ok(s, "--link", spec, NULL);
    expect_send_ok(s, NULL, NULL, spec);
    expect_send_ok(s, "--tcp", host_port,
                   "tcp:127.0.0.1:9"); /* an option names the link: the environment's is not used */
    (void)sim_stop(s);

    sim_start(s, SIM_UDP, NULL);
    snprintf(spec, sizeof(spec), "udp:127.0.0.1:%s,local=0", s->port);
    snprintf(host_port, sizeof(host_port), "127.0.0.1:%s", s->port);
    expect_send_ok(s, "--link", spec, NULL);
    expect_send_ok(s, NULL, NULL, spec);
    {
        tool_result r = run_tool(NULL, "--udp", host_port, "--local-port", "0", "send", "shutter", NULL);
        expect(&r, 0, "ok\n");
        tool_result_free(&r);
    }
    (void)sim_stop(s);

    sim_start(s, SIM_PTY, NULL);
    snprintf(spec, sizeof(spec), "serial:%s", s->path);
    expect_send_ok(s, "--link", spec, NULL);
    snprintf(spec, sizeof(spec), "serial:%s,baud=115200", s->path);
    expect_send_ok(s, NULL, NULL, spec);
    {
        tool_result r = run_tool(NULL, "--link", spec, "monitor", "--json", "--count", "2", NULL);
        assert_int_equal(r.status, 0);
        assert_int_equal(check_gcu_lines(r.out, 1), 2);
        tool_result_free(&r);
    }
}

/* ---- monitor ------------------------------------------------------------------------- */

static void test_monitor_json(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r = sim_run_on(s, "monitor", "--json", "--count", "5", NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(r.err_len, 0);
    assert_int_equal(check_gcu_lines(r.out, 1), 5);
    tool_result_free(&r);
}

static void test_monitor_plain(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r = sim_run_on(s, "monitor", "--duration", "1.5", NULL); /* not a terminal: one line per second */
    assert_int_equal(r.status, 0);
    assert_true(count_lines(r.out) >= 1 && count_lines(r.out) <= 3);
    assert_non_null(strstr(r.out, "link up"));
    assert_non_null(strstr(r.out, "mode head_lock"));
    assert_null(strstr(r.out, "\033[")); /* no terminal codes into a pipe */
    tool_result_free(&r);
    r = sim_run_on(s, "monitor", "--duration", "0.5", "--raw", NULL); /* the wire integers */
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "cam_pitch "));
    assert_non_null(strstr(r.out, "zoom_cam1 10 "));
    assert_null(strstr(r.out, " deg"));
    tool_result_free(&r);
}

/* ---- point and rate ------------------------------------------------------------------ */

static void test_point(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r = sim_run_on(s, "point", "--pitch", "-30", "--yaw", "45", NULL);
    double roll_deg = 99, pitch_deg = 99, yaw_deg = 99;
    long pitch, yaw;
    assert_int_equal(r.status, 0);
    assert_int_equal(sscanf(r.out, "reached roll %lf pitch %lf yaw %lf deg in ", &roll_deg, &pitch_deg, &yaw_deg), 3);
    assert_true(fabs(roll_deg) <= 0.5 && fabs(pitch_deg + 30.0) <= 0.5 && fabs(yaw_deg - 45.0) <= 0.5);
    tool_result_free(&r);
    attitude(s, &pitch, &yaw);
    assert_true(labs(pitch + 3000) <= 50 && labs(yaw - 4500) <= 50);
    r = sim_run_on(s, "point", "--pitch", "10", "--yaw", "-90", NULL); /* -90 is 270 */
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    attitude(s, &pitch, &yaw);
    assert_true(labs(pitch - 1000) <= 50 && labs(yaw - 27000) <= 50);
    /* --json: the attitude in degrees, or with --raw in the GCU's 0.01 deg */
    r = sim_run_on(s, "point", "--pitch", "-20", "--yaw", "30", "--json", NULL);
    assert_int_equal(r.status, 0);
    {
        json_t *o = parse_line(strchr(r.out, '\n') + 1);
        assert_true(json_is_real(json_object_get(o, "pitch")) && fabs(num_key(o, "pitch") + 20.0) <= 0.5);
        json_decref(o);
    }
    tool_result_free(&r);
    r = sim_run_on(s, "point", "--pitch", "-20", "--yaw", "30", "--json", "--raw", NULL);
    assert_int_equal(r.status, 0);
    {
        json_t *o = parse_line(strchr(r.out, '\n') + 1);
        assert_true(labs((long)int_key(o, "pitch") + 2000) <= 50 && labs((long)int_key(o, "yaw") - 3000) <= 50);
        json_decref(o);
    }
    tool_result_free(&r);
}

static void test_point_unreachable(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    tool_result r =
        sim_run_on(s, "point", "--pitch", "120", "--yaw", "0", "--wait", "0.5", NULL); /* the sim stops at 90 */
    assert_failure(&r, 3, "point: not there in time", NULL);
    tool_result_free(&r);
}

static void test_rate(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    long pitch0, yaw0, pitch1, yaw1, moved;
    tool_result r;
    double secs = 0.0;
    attitude(s, &pitch0, &yaw0);
    r = sim_run_on(s, "rate", "--pitch", "-10", "--yaw", "30", "--duration", "1", NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(sscanf(r.out, "turned %lf s", &secs), 1); /* how long the rates were sent */
    assert_true(secs >= 1.0 && secs < 3.0);
    tool_result_free(&r);
    attitude(s, &pitch1, &yaw1);
    /* 30 deg/s and -10 deg/s (in 0.01 deg) for that long, give or take how late the simulator got
     * its first and last packets (more on a loaded machine): a third of it */
    moved = ((yaw1 - yaw0) % 36000 + 36000) % 36000;
    assert_true(fabs((double)moved - 3000.0 * secs) <= 1000.0 * secs + 100.0);
    assert_true(fabs((double)(pitch1 - pitch0) + 1000.0 * secs) <= 340.0 * secs + 50.0);
    attitude(s, &pitch0, &yaw0); /* and it holds still after */
    assert_true(labs(yaw0 - yaw1) <= 20);
}

/* ---- capture and replay ---------------------------------------------------------------- */

static void temp_name(char *buf, size_t cap, const char *what)
{
    snprintf(buf, cap, "/tmp/xfgcu-test-%ld-%s.cap", (long)getpid(), what);
}

static void count_directions(const char *jsonl, size_t *host, size_t *gcu, int *shutter)
{
    const char *p = jsonl;
    *host = *gcu = 0;
    *shutter = 0;
    while (*p != '\0') {
        size_t len = strcspn(p, "\n");
        json_t *obj = parse_line(p);
        const char *dir = json_string_value(json_object_get(obj, "direction"));
        if (json_object_get(obj, "summary") != NULL && p[len] == '\n' && p[len + 1u] == '\0') {
            json_decref(obj); /* the last line: replay's summary */
            break;
        }
        assert_true(json_is_number(json_object_get(obj, "t")));
        assert_non_null(dir);
        if (strcmp(dir, "host") == 0) {
            (*host)++;
        } else {
            (*gcu)++;
            *shutter |=
                (int_key(obj, "order") == 0x20 && strcmp(json_string_value(json_object_get(obj, "params")), "00") == 0);
        }
        json_decref(obj);
        p += len + (p[len] == '\n');
    }
}

static void test_capture_replay(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    char file[128];
    size_t host, gcu;
    unsigned sent = 0, received = 0;
    double secs = 0.0;
    int shutter;
    tool_result r;
    temp_name(file, sizeof(file), "duration");
    r = sim_run_on(s, "capture", file, "--duration", "1", NULL);
    assert_int_equal(r.status, 0);
    assert_int_equal(sscanf(r.out, "captured %lf s on %*s %*s %*u chunks, %*u bytes (%u packets sent, %u received)",
                            &secs, &sent, &received),
                     3);
    assert_true(secs >= 1.0 && secs < 3.0);
    tool_result_free(&r);
    r = run_tool(NULL, "replay", file, "--json", NULL);
    assert_int_equal(r.status, 0);
    count_directions(r.out, &host, &gcu, &shutter);
    /* what the summary counted is in the file, each answered; 50 packets per second: never more,
     * and not a fifth of it fewer even on a loaded machine */
    assert_true(host == sent && gcu == received && host - gcu <= 2);
    assert_true((double)host <= 50.0 * secs + 2.0 && host >= 10);
    tool_result_free(&r);
    r = run_tool(NULL, "replay", file, "--brief", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, " > host "));
    assert_non_null(strstr(r.out, " < gcu "));
    assert_non_null(strstr(r.out, " packets: "));
    tool_result_free(&r);
    r = run_tool(NULL, "replay", file, NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "gcu packet (t 0."));
    tool_result_free(&r);
    unlink(file);
}

static void test_capture_command(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    char file[128];
    size_t host, gcu;
    int shutter;
    tool_result r;
    temp_name(file, sizeof(file), "shutter");
    r = sim_run_on(s, "capture", file, "shutter", NULL);
    assert_int_equal(r.status, 0);
    assert_true(strncmp(r.out, "ok\ncaptured ", 12) == 0);
    tool_result_free(&r);
    r = run_tool(NULL, "replay", file, "--json", NULL);
    assert_int_equal(r.status, 0);
    count_directions(r.out, &host, &gcu, &shutter);
    if (!(host >= 3 && gcu + 1 >= host && gcu <= host && shutter)) { /* the last reply may be late under load */
        print_error("%zu host packets, %zu GCU packets, shutter feedback %d\n", host, gcu, shutter);
        fail();
    }
    tool_result_free(&r);
    unlink(file);
}

static void test_replay_malformed(void **state)
{
    char file[128];
    FILE *f;
    tool_result r;
    (void)state;
    temp_name(file, sizeof(file), "bad");
    f = fopen(file, "w");
    assert_non_null(f);
    fputs("# xfgcu capture 1\n0.000 > A8 E5\n0.001 < 8A 5E 4\n", f);
    fclose(f);
    r = run_tool(NULL, "replay", file, "--json", NULL);
    assert_failure(&r, 2, ":3: ", file, NULL);
    tool_result_free(&r);
    f = fopen(file, "w");
    assert_non_null(f);
    fputs("not a capture\n", f);
    fclose(f);
    r = run_tool(NULL, "replay", file, NULL);
    assert_failure(&r, 2, ":1: ", "not an xfgcu capture", NULL);
    tool_result_free(&r);
    f = fopen(file, "w"); /* empty: not a capture either */
    assert_non_null(f);
    fclose(f);
    r = run_tool(NULL, "replay", file, NULL);
    assert_failure(&r, 2, ":1: ", "not an xfgcu capture", NULL);
    tool_result_free(&r);
    unlink(file);
    r = run_tool(NULL, "replay", file, NULL);
    assert_failure(&r, 2, "cannot open", NULL);
    tool_result_free(&r);
    /* a directory opens, but cannot be read: a read error, not the end of the capture */
    r = run_tool(NULL, "replay", "/", NULL);
    assert_failure(&r, 2, "cannot read", "/:1: ", NULL);
    tool_result_free(&r);
}

static void test_replay_split_chunks(void **state)
{
    /* a packet split over two chunks, noise, and a false header at the end (flushed) */
    char file[128], line[400];
    uint8_t pkt[72];
    size_t i;
    FILE *f;
    tool_result r;
    (void)state;
    memcpy(pkt, appendix1, sizeof(pkt));
    temp_name(file, sizeof(file), "split");
    f = fopen(file, "w");
    assert_non_null(f);
    fputs("# xfgcu capture 1\n# link test\n0.000 > 00 11", f);
    for (i = 0; i < 30; i++) {
        fprintf(f, " %02X", pkt[i]);
    }
    fputs("\n0.005 <\n0.010 >", f);
    for (i = 30; i < 72; i++) {
        fprintf(f, " %02X", pkt[i]);
    }
    fputs(" A8 E5 48\n", f);
    fclose(f);
    r = run_tool(NULL, "replay", file, "--json", NULL);
    assert_int_equal(r.status, 0);
    json_decref(cut_summary(&r));
    assert_int_equal(count_lines(r.out), 1);
    snprintf(line, sizeof(line), "{\"t\":0.01,\"direction\":\"host\",\"version\":1,\"length\":72,");
    assert_true(strncmp(r.out, line, strlen(line)) == 0);
    tool_result_free(&r);
    unlink(file);
}

/* ---- nothing lost: files the program did not create in this run are left alone ------------ */

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

static int has_text(const char *path, const char *text)
{
    char buf[256];
    size_t n;
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        return 0;
    }
    n = fread(buf, 1, sizeof(buf) - 1u, f);
    fclose(f);
    buf[n] = '\0';
    return strcmp(buf, text) == 0;
}

/* No "FILE.part*" left beside FILE. */
static int no_part_files(const char *file)
{
    char pattern[160];
    glob_t g;
    int rc;
    snprintf(pattern, sizeof(pattern), "%s.part*", file);
    rc = glob(pattern, 0, NULL, &g);
    if (rc == 0) {
        globfree(&g);
    }
    return rc == GLOB_NOMATCH;
}

/* capture: an existing FILE is refused without --force, kept when the link fails even with
 * --force, and replaced only by a complete capture; a new FILE is not left behind empty. */
static void test_capture_keeps_files(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    char file[128], port[8], dead[32];
    int fd = hold_port(SOCK_STREAM, port, sizeof(port));
    tool_result r;
    snprintf(dead, sizeof(dead), "127.0.0.1:%s", port);
    temp_name(file, sizeof(file), "keep");
    write_text(file, "precious\n");
    r = run_tool(NULL, "--tcp", dead, "--timeout", "200", "capture", file, NULL);
    assert_failure(&r, 2, "exists; not replaced", "--force", NULL);
    tool_result_free(&r);
    assert_true(has_text(file, "precious\n"));
    r = run_tool(NULL, "--tcp", dead, "--timeout", "200", "capture", file, "--force", NULL);
    assert_int_equal(r.status, 3);
    tool_result_free(&r);
    assert_true(has_text(file, "precious\n")); /* not truncated, not deleted */
    assert_true(no_part_files(file));
    unlink(file);
    r = run_tool(NULL, "--tcp", dead, "--timeout", "200", "capture", file, NULL);
    assert_int_equal(r.status, 3);
    tool_result_free(&r);
    assert_int_equal(access(file, F_OK), -1); /* nothing left: no byte moved */
    assert_true(no_part_files(file));
    close(fd);
    /* a complete capture replaces FILE with --force */
    write_text(file, "precious\n");
    sim_start(s, SIM_TCP, NULL);
    r = sim_run_on(s, "capture", file, "--count", "3", "--force", NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    assert_false(has_text(file, "precious\n"));
    r = run_tool(NULL, "replay", file, NULL);
    assert_int_equal(r.status, 0);
    tool_result_free(&r);
    assert_true(no_part_files(file));
    unlink(file);
}

/* sim --pty --link PATH: an existing file at PATH is refused and kept; a second simulator given
 * the first one's link path is refused, and the first keeps its link; each removes only its own. */
static void test_sim_link_keeps_paths(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    char path[128], target[128], first[128];
    ssize_t n;
    tool_result r;
    temp_name(path, sizeof(path), "link");
    write_text(path, "precious\n");
    r = run_tool(NULL, "sim", "--pty", "--link", path, "--duration", "0.2", NULL);
    assert_failure(&r, 3, path, "exists; not replaced", NULL);
    tool_result_free(&r);
    assert_true(has_text(path, "precious\n"));
    unlink(path);
    sim_start(s, SIM_PTY, "--link", path, NULL);
    n = readlink(path, first, sizeof(first) - 1u);
    assert_true(n > 0);
    first[n] = '\0';
    r = run_tool(NULL, "sim", "--pty", "--link", path, "--duration", "0.2", NULL);
    assert_failure(&r, 3, "exists; not replaced", NULL);
    tool_result_free(&r);
    n = readlink(path, target, sizeof(target) - 1u);
    assert_true(n > 0);
    target[n] = '\0';
    assert_string_equal(target, first); /* still the first simulator's */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_send_ok, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_send_ok, sim_setup_udp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_send_ok, sim_setup_pty, sim_teardown),
        cmocka_unit_test_setup_teardown(test_send_failed_mask, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_send_calibration, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_send_v2, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_send_model_support, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_send_osd_follows_gcu, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_sim_reply_to, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_link_forms, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_no_gcu),
        cmocka_unit_test_setup_teardown(test_sim_port_taken, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_monitor_json, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_monitor_json, sim_setup_udp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_monitor_json, sim_setup_pty, sim_teardown),
        cmocka_unit_test_setup_teardown(test_monitor_plain, sim_setup_udp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_point, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_point, sim_setup_pty, sim_teardown),
        cmocka_unit_test_setup_teardown(test_point_unreachable, sim_setup_udp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_rate, sim_setup_udp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_capture_replay, sim_setup_tcp, sim_teardown),
        cmocka_unit_test_setup_teardown(test_capture_command, sim_setup_pty, sim_teardown),
        cmocka_unit_test_setup_teardown(test_capture_keeps_files, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_sim_link_keeps_paths, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_replay_malformed),
        cmocka_unit_test(test_replay_split_chunks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
