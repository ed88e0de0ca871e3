/*
 * test_cli_hosts.c - what the vendor's text does not allow, and the hosts in the field (issue 29
 * items 4 and 5, issue 31 item 5):
 *
 * - decode warns (a JSON "warnings" list, a "warning:" line each in the table) and never refuses:
 *   a heading of -180..180 deg in the U16 yaw, INS valid with a zero attitude, record 0x00, a
 *   parameter of the wrong length, a GCU angle out of range, a null's reply with a state; a
 *   warned packet still goes back to its bytes through encode;
 * - monitor warns about a GCU that sends what the text does not allow (a fake GCU in this test);
 * - decode and replay end with a summary that counts the frames the parsers gave up;
 * - a small driver in this test talks to `xfgcu sim --protocol 2` the way ArduPilot's driver and
 *   the public wrappers do: version 2 throughout, angle frames 0x10 with the heading as a signed
 *   value, camera-command frames with zero carrier data between them, record stopped with 0x00,
 *   and 72- and 73-byte replies (sim --state-once); what the simulator answers, what it writes in
 *   its log, and that the attitude does not move when a command frame comes.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <poll.h>
#include <setjmp.h>
#include <signal.h>
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
#include "xfgcu/xfgcu.h"

/* ---- packets --------------------------------------------------------------------------------- */

/* A host packet as ArduPilot's driver sends it: version 2, its carrier data; order and one
 * parameter byte (none when @p n is 0). */
static size_t host_packet(xf_host_packet *p, uint8_t order, const uint8_t *params, uint8_t n, uint8_t *buf)
{
    size_t len = 0;
    p->order = order;
    p->params_len = n;
    if (n > 0u) {
        memcpy(p->params, params, n);
    }
    assert_int_equal(xf_host_pack(p, buf, XF_PACKET_MAX_LEN, &len), XF_OK);
    return len;
}

/* ArduPilot's angle frame: 0x10, control and INS valid, pitch -30 deg (earth frame), yaw 45 deg
 * (body frame); carrier roll 10.5, pitch -5.25, heading 250 deg written as wrap_PI's -110 deg
 * into the U16 field (54536). */
static size_t ap_angle_frame(uint8_t *buf)
{
    xf_host_packet p;
    xf_host_packet_init(&p, XF_PROTOCOL_V2);
    p.main.status = XF_STATUS_CTRL_VALID | XF_STATUS_INS_VALID;
    p.main.pitch_ctrl = -3000;
    p.main.yaw_ctrl = 4500;
    p.main.carrier_roll = 1050;
    p.main.carrier_pitch = -525;
    p.main.carrier_yaw = (uint16_t)(65536 - 11000);
    return host_packet(&p, XF_ORDER_ANGLE_CONTROL, NULL, 0u, buf);
}

/* ArduPilot's camera-command frame: bytes 5-68 all zero (status 0, no sub frame), one parameter. */
static size_t ap_command_frame(uint8_t order, uint8_t param, uint8_t *buf)
{
    xf_host_packet p;
    xf_host_packet_init(&p, XF_PROTOCOL_V2);
    p.main.sub_request = 0u;
    return host_packet(&p, order, &param, 1u, buf);
}

static char *hex_of(const uint8_t *bytes, size_t n)
{
    static char text[3 * XF_PACKET_MAX_LEN + 2];
    hex_line(bytes, n, text);
    text[strcspn(text, "\n")] = '\0';
    return text;
}

/* decode --json of one packet: its object. */
static json_t *decoded(const uint8_t *bytes, size_t n)
{
    tool_result r = run_tool(NULL, "decode", "--json", hex_of(bytes, n), NULL);
    json_t *o;
    assert_int_equal(r.status, 0);
    assert_int_equal(count_lines(r.out), 1);
    o = parse_line(r.out);
    tool_result_free(&r);
    return o;
}

/* Does the object's "warnings" list have a line holding every needle (NULL-terminated)? */
static int warned(const json_t *o, ...)
{
    json_t *list = json_object_get(o, "warnings"), *w;
    size_t i;
    json_array_foreach(list, i, w)
    {
        va_list ap;
        const char *needle, *text = json_string_value(w);
        int all = 1;
        va_start(ap, o);
        while ((needle = va_arg(ap, const char *)) != NULL) {
            all &= strstr(text, needle) != NULL;
        }
        va_end(ap);
        if (all) {
            return 1;
        }
    }
    return 0;
}

/* ---- decode's warnings -------------------------------------------------------------------------- */

static void test_decode_warnings(void **state)
{
    uint8_t buf[XF_PACKET_MAX_LEN], two[2] = {0x01u, 0x01u};
    xf_host_packet h;
    xf_gcu_packet g;
    size_t n;
    json_t *o;
    tool_result r;
    (void)state;
    /* ArduPilot's heading: 545.36 deg read as U16, which a GCU takes for 185.36 */
    n = ap_angle_frame(buf);
    o = decoded(buf, n);
    assert_true(warned(o, "carrier_yaw 54536 (545.36 deg) is outside the vendor's range [0, 360) deg",
                       "as a signed value it is -110.00 deg", "takes for 185.36 deg", NULL));
    assert_true(json_is_number(json_object_get(o, "carrier_yaw"))); /* decoded all the same */
    json_decref(o);
    /* the table: one line each, after the rows; exit 0 */
    r = run_tool(NULL, "decode", hex_of(buf, n), NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "\nwarning: carrier_yaw 54536 (545.36 deg) is outside"));
    tool_result_free(&r);
    /* a wrapper's INS valid with a zero attitude */
    xf_host_packet_init(&h, XF_PROTOCOL_V2);
    h.main.status = XF_STATUS_INS_VALID | XF_STATUS_CTRL_VALID;
    n = host_packet(&h, XF_ORDER_NULL, NULL, 0u, buf);
    o = decoded(buf, n);
    assert_true(warned(o, "ins_valid is set with carrier_roll, carrier_pitch and carrier_yaw all 0", NULL));
    json_decref(o);
    /* record stopped with 0x00: command_error as before, and a warning that says why it matters */
    n = ap_command_frame(XF_ORDER_RECORD, 0x00u, buf);
    o = decoded(buf, n);
    assert_string_equal(str_key(o, "command_error"), "cameras out of range");
    assert_true(warned(o, "record with parameter 0x00", "toggle with the fixed parameter 0x01", NULL));
    json_decref(o);
    /* a wrapper's two-byte shutter */
    xf_host_packet_init(&h, XF_PROTOCOL_V1);
    n = host_packet(&h, XF_ORDER_SHUTTER, two, 2u, buf);
    o = decoded(buf, n);
    assert_true(warned(o, "parameters the order does not take: shutter takes 1 parameter bytes, not 2", NULL));
    json_decref(o);
    /* a GCU's yaw out of range, and a null's reply with a state */
    memset(&g, 0, sizeof(g));
    g.version = XF_PROTOCOL_V2;
    g.main.cam_yaw = 36500;
    g.order = XF_ORDER_NULL;
    g.params_len = 1;
    assert_int_equal(xf_gcu_pack(&g, buf, sizeof(buf), &n), XF_OK);
    o = decoded(buf, n);
    assert_true(warned(o, "cam_yaw 36500 (365.00 deg) is outside the vendor's range [0, 360) deg", NULL));
    assert_true(warned(o, "a reply to the null order with an execution state (0x00)", NULL));
    json_decref(o);
    /* a clean packet has no "warnings" at all */
    n = ap_command_frame(XF_ORDER_SHUTTER, 0x01u, buf);
    o = decoded(buf, n);
    assert_null(json_object_get(o, "warnings"));
    json_decref(o);
}

/* decode --json | encode --json - gives back a warned packet's very bytes. */
static void test_warned_round_trip(void **state)
{
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t n = ap_angle_frame(buf);
    char line[3 * XF_PACKET_MAX_LEN + 2];
    tool_result d, e;
    (void)state;
    hex_line(buf, n, line);
    d = run_tool(line, "decode", "--json", NULL); /* a stream: the summary comes too, and encode skips it */
    assert_int_equal(d.status, 0);
    assert_non_null(strstr(d.out, "\"warnings\":["));
    e = run_tool(d.out, "encode", "--json", "-", NULL);
    assert_int_equal(e.status, 0);
    assert_string_equal(e.out, line);
    tool_result_free(&d);
    tool_result_free(&e);
}

/* ---- given up ------------------------------------------------------------------------------------ */

/* A real reply, false GCU headers that each announce 255 bytes (more of them than a parser has
 * slots), then two real replies. */
static size_t hostile_stream(uint8_t *buf)
{
    xf_gcu_packet g;
    size_t n = 0, len = 0, i;
    memset(&g, 0, sizeof(g));
    g.version = XF_PROTOCOL_V1;
    assert_int_equal(xf_gcu_pack(&g, buf, XF_PACKET_MAX_LEN, &len), XF_OK);
    n = len;
    for (i = 0; i < 3u * XF_PARSER_SLOTS; i++) {
        buf[n++] = XF_GCU_HEADER0;
        buf[n++] = XF_GCU_HEADER1;
        buf[n++] = 0xFFu;
        buf[n++] = 0x00u;
    }
    for (i = 0; i < 2u; i++) {
        assert_int_equal(xf_gcu_pack(&g, buf + n, XF_PACKET_MAX_LEN, &len), XF_OK);
        n += len;
    }
    return n;
}

/* What a GCU parser makes of @p bytes fed @p chunk bytes at a time, then flushed: its frames and
 * its count of given up (the figure decode and replay must print). */
static void reference(const uint8_t *bytes, size_t n, size_t chunk, size_t *frames, uint32_t *given_up)
{
    xf_parser p;
    xf_frame f;
    size_t at = 0;
    assert_int_equal(xf_parser_init(&p, XF_DIR_GCU), XF_OK);
    *frames = 0;
    while (at < n) {
        size_t k = (n - at < chunk) ? n - at : chunk, taken = 0, used = 0;
        while (xf_parser_feed(&p, bytes + at + taken, k - taken, &used, &f) == XF_PARSE_FRAME) {
            taken += used;
            (*frames)++;
        }
        at += k;
    }
    while (xf_parser_flush(&p, &f) == XF_PARSE_FRAME) {
        (*frames)++;
    }
    *given_up = p.stats.given_up;
}

static void test_given_up(void **state)
{
    uint8_t bytes[4u * 3u * XF_PARSER_SLOTS + 3u * XF_PACKET_MAX_LEN];
    size_t n = hostile_stream(bytes), frames = 0;
    uint32_t given_up = 0;
    char text[3u * sizeof(bytes) + 2u], file[64], want[64];
    tool_result r;
    json_t *sum;
    FILE *f;
    (void)state;
    hex_line(bytes, n, text);
    reference(bytes, n, 64u, &frames, &given_up); /* decode feeds its parsers 64 bytes at a time */
    assert_true(given_up > 0u);                   /* the stream is hostile enough to show the figure */
    r = run_tool(text, "decode", "--json", NULL);
    assert_int_equal(r.status, 0);
    sum = cut_summary(&r);
    assert_int_equal(int_key(sum, "gcu_packets"), (json_int_t)frames);
    assert_int_equal(int_key(sum, "given_up"), (json_int_t)given_up);
    json_decref(sum);
    tool_result_free(&r);
    r = run_tool(text, "decode", NULL);
    assert_int_equal(r.status, 0);
    snprintf(want, sizeof(want), " CRC errors, %u frames given up\n", (unsigned)given_up);
    assert_non_null(strstr(r.out, want));
    tool_result_free(&r);
    /* replay: the same bytes as one chunk from the GCU */
    reference(bytes, n, n, &frames, &given_up);
    snprintf(file, sizeof(file), "/tmp/xfgcu-hosts-%ld.cap", (long)getpid());
    f = fopen(file, "w");
    assert_non_null(f);
    fprintf(f, "# xfgcu capture 1\n0.000 < %s", text);
    fclose(f);
    r = run_tool(NULL, "replay", file, "--json", NULL);
    assert_int_equal(r.status, 0);
    sum = cut_summary(&r);
    assert_int_equal(int_key(sum, "given_up"), (json_int_t)given_up);
    json_decref(sum);
    assert_int_equal(count_packet_lines(r.out), frames);
    tool_result_free(&r);
    r = run_tool(NULL, "replay", file, "--brief", NULL);
    assert_int_equal(r.status, 0);
    snprintf(want, sizeof(want), " CRC errors, %u frames given up\n", (unsigned)given_up);
    assert_non_null(strstr(r.out, want));
    tool_result_free(&r);
    unlink(file);
}

/* ---- a driver that talks as the hosts in the field do ----------------------------------------- */

typedef struct driver {
    int fd;
    xf_parser parser;
    uint8_t buf[512];
    size_t have, at; /* bytes read, and how many of them the parser took */
} driver;

static void drive_open(driver *d, const sim_proc *s)
{
    struct sockaddr_in a;
    memset(d, 0, sizeof(*d));
    memset(&a, 0, sizeof(a));
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)atoi(s->port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    d->fd = socket(AF_INET, SOCK_STREAM, 0);
    assert_true(d->fd >= 0);
    assert_int_equal(connect(d->fd, (struct sockaddr *)&a, sizeof(a)), 0);
    assert_int_equal(xf_parser_init(&d->parser, XF_DIR_GCU), XF_OK);
}

/* Send one packet and read its reply (within 2 s: a loaded machine) into @p g; its length. */
static size_t drive(driver *d, const uint8_t *pkt, size_t len, xf_gcu_packet *g)
{
    xf_frame f;
    size_t used = 0;
    assert_int_equal(send(d->fd, pkt, len, 0), (ssize_t)len);
    for (;;) {
        struct pollfd p;
        ssize_t got;
        while (d->at < d->have) {
            xf_parse_status st = xf_parser_feed(&d->parser, d->buf + d->at, d->have - d->at, &used, &f);
            d->at += used;
            if (st == XF_PARSE_FRAME) {
                assert_int_equal(xf_frame_gcu(&f, g), XF_OK);
                return f.len;
            }
        }
        p.fd = d->fd;
        p.events = POLLIN;
        assert_int_equal(poll(&p, 1, 2000), 1);
        got = recv(d->fd, d->buf, sizeof(d->buf), 0);
        assert_true(got > 0);
        d->have = (size_t)got;
        d->at = 0;
    }
}

static void pause_ms(long ms)
{
    struct timespec t;
    t.tv_sec = ms / 1000;
    t.tv_nsec = (ms % 1000) * 1000000L;
    nanosleep(&t, NULL);
}

/* Angle frames at 50 Hz until the gimbal is there (5 s at most: 0.4 s of slewing): the last reply. */
static void drive_to_target(driver *d, xf_gcu_packet *g)
{
    uint8_t angle[XF_PACKET_MAX_LEN];
    size_t n = ap_angle_frame(angle);
    int i;
    for (i = 0; i < 250; i++) {
        (void)drive(d, angle, n, g);
        if (abs(g->main.cam_pitch + 3000) <= 5 && abs(g->main.rel_angle_z - 4500) <= 5) {
            return;
        }
        pause_ms(20);
    }
    fail_msg("the simulated gimbal did not reach pitch -30, relative yaw 45 (at %d, %d)", g->main.cam_pitch,
             g->main.rel_angle_z);
}

/* The attitude of @p b is that of @p a (to within a hundredth of a degree). */
static void same_attitude(const xf_gcu_packet *a, const xf_gcu_packet *b)
{
    assert_true(abs(a->main.cam_pitch - b->main.cam_pitch) <= 1);
    assert_true(abs(a->main.cam_roll - b->main.cam_roll) <= 1);
    assert_true(abs(a->main.rel_angle_z - b->main.rel_angle_z) <= 1);
    assert_true(abs(a->main.rel_angle_x - b->main.rel_angle_x) <= 1);
}

/* ArduPilot against a V0.2 simulator: the angle target is reached (yaw relative to the carrier,
 * whose heading the GCU reads as the U16 185.36 deg: the absolute yaw shows the 64.64 deg error);
 * a camera-command frame between angle frames runs the command and moves nothing; record stopped
 * with 0x00 fails by the strict reading, recording stays on, and the simulator's log says so. */
static void test_ardupilot_session(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    uint8_t pkt[XF_PACKET_MAX_LEN], angle[XF_PACKET_MAX_LEN];
    size_t an = ap_angle_frame(angle), n;
    xf_gcu_packet before, g;
    char line[512];
    driver d;
    sim_start(s, SIM_TCP, "--protocol", "2", NULL);
    drive_open(&d, s);
    drive_to_target(&d, &before);
    assert_int_equal(before.version, XF_PROTOCOL_V2);
    assert_int_equal(before.main.gimbal_mode, XF_MODE_ANGLE_CONTROL);
    assert_true(abs((int)before.main.cam_yaw - 23036) <= 5); /* 185.36 + 45: the heading read as a U16 */
    /* a photo between angle frames: executed, and the attitude does not move */
    n = ap_command_frame(XF_ORDER_SHUTTER, 0x01u, pkt);
    assert_int_equal(drive(&d, pkt, n, &g), 73);
    assert_int_equal(g.order, XF_ORDER_SHUTTER);
    assert_int_equal(g.params[0], XF_STATE_SUCCESS);
    same_attitude(&before, &g);
    assert_int_equal(drive(&d, angle, an, &g), 73); /* 0x10 runs again after the photo: its state */
    same_attitude(&before, &g);
    /* record start, an angle frame, record stop with 0x00 */
    n = ap_command_frame(XF_ORDER_RECORD, 0x01u, pkt);
    (void)drive(&d, pkt, n, &g);
    assert_int_equal(g.params[0], XF_STATE_SUCCESS);
    assert_int_equal(g.sub.sub_header, 0u); /* a command frame asks for no sub frame (byte 36 is 0) */
    (void)drive(&d, angle, an, &g);         /* an angle frame asks for it */
    assert_true((g.sub.camera_status & XF_CAMERA_RECORDING) != 0u);
    n = ap_command_frame(XF_ORDER_RECORD, 0x00u, pkt);
    (void)drive(&d, pkt, n, &g);
    assert_int_equal(g.order, XF_ORDER_RECORD);
    assert_int_equal(g.params[0], 0x01u); /* failed: the strict reading */
    same_attitude(&before, &g);
    (void)drive(&d, angle, an, &g);
    assert_true((g.sub.camera_status & XF_CAMERA_RECORDING) != 0u); /* still recording */
    assert_int_equal(sim_log_line(s, "note: open question 3: record (0x21)", 3000, line, sizeof(line)), 0);
    assert_non_null(strstr(line, "1 parameter bytes, first 0x00, answered state 0x01"));
    assert_non_null(strstr(line, "recording unchanged"));
    close(d.fd);
    assert_int_equal(sim_stop(s), 0);
}

/* A wrapper's two-byte shutter: failed by the strict reading; the log says so in JSON too. */
static void test_wrapper_lengths(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    static const uint8_t two[2] = {0x01u, 0x01u};
    uint8_t pkt[XF_PACKET_MAX_LEN];
    xf_host_packet h;
    xf_gcu_packet g;
    char line[512];
    json_t *o;
    json_error_t e;
    driver d;
    sim_start(s, SIM_TCP, "--json", NULL);
    drive_open(&d, s);
    xf_host_packet_init(&h, XF_PROTOCOL_V1);
    (void)drive(&d, pkt, host_packet(&h, XF_ORDER_SHUTTER, two, 2u, pkt), &g);
    assert_int_equal(g.params[0], 0x01u);
    assert_int_equal(sim_log_line(s, "\"event\":\"note\"", 3000, line, sizeof(line)), 0);
    o = json_loads(line, 0, &e);
    assert_non_null(o);
    assert_int_equal(int_key(o, "question"), 1);
    assert_string_equal(str_key(o, "order_name"), "shutter");
    assert_int_equal(int_key(o, "params_len"), 2);
    assert_int_equal(int_key(o, "state"), 1);
    assert_non_null(strstr(str_key(o, "text"), "parameter bytes not the order's length"));
    (void)str_key(o, "time_utc");
    json_decref(o);
    close(d.fd);
}

/* Replies to a repeated order: 73 bytes each by default; with --state-once 73 then 72, whose main
 * frame (the attitude) decode reads all the same; and a default send works against either. */
static void test_72_and_73_byte_replies(void **state)
{
    sim_proc *s = (sim_proc *)*state;
    static const char *const once[2] = {NULL, "--state-once"};
    uint8_t angle[XF_PACKET_MAX_LEN];
    size_t an = ap_angle_frame(angle);
    int k, i;
    for (k = 0; k < 2; k++) {
        uint8_t reply[XF_PACKET_MAX_LEN];
        size_t lens[4], n = 0;
        xf_gcu_packet g;
        tool_result r;
        driver d;
        json_t *o;
        sim_start(s, SIM_TCP, "--protocol", "2", once[k], NULL);
        drive_open(&d, s);
        for (i = 0; i < 4; i++) {
            lens[i] = drive(&d, angle, an, &g);
        }
        assert_int_equal(lens[0], 73);
        for (i = 1; i < 4; i++) {
            assert_int_equal(lens[i], k == 0 ? 73 : 72);
        }
        assert_int_equal(g.order, XF_ORDER_ANGLE_CONTROL);
        assert_int_equal(xf_gcu_pack(&g, reply, sizeof(reply), &n), XF_OK);
        o = decoded(reply, n);
        assert_int_equal(int_key(o, "length"), (json_int_t)lens[3]);
        assert_true(fabs(num_key(o, "cam_pitch") - (double)g.main.cam_pitch / 100.0) < 1e-9);
        json_decref(o);
        close(d.fd);
        r = sim_run_on(s, "send", "shutter", NULL);
        assert_int_equal(r.status, 0);
        assert_string_equal(r.out, "ok\n");
        tool_result_free(&r);
        assert_int_equal(sim_stop(s), 0);
    }
}

/* ---- monitor, against a GCU that sends what the text does not allow ---------------------------- */

/* A fake GCU on TCP for @p seconds: each host packet gets a 73-byte null reply (a state where
 * V2.0.6 has none) with a yaw of 365 deg. Returns its pid; *port is its port. */
static pid_t fake_gcu(int *port, int seconds)
{
    char text[8];
    int lfd = hold_port(SOCK_STREAM, text, sizeof(text));
    pid_t pid;
    assert_int_equal(listen(lfd, 4), 0);
    *port = atoi(text);
    pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        xf_gcu_packet g;
        uint8_t reply[XF_PACKET_MAX_LEN], in[512];
        size_t n = 0;
        int c;
        alarm((unsigned)seconds);
        memset(&g, 0, sizeof(g));
        g.version = XF_PROTOCOL_V1;
        g.main.cam_yaw = 36500;
        g.params_len = 1;
        (void)xf_gcu_pack(&g, reply, sizeof(reply), &n);
        while ((c = accept(lfd, NULL, NULL)) >= 0) {
            ssize_t got;
            while ((got = recv(c, in, sizeof(in), 0)) > 0) {
                (void)send(c, reply, n, MSG_NOSIGNAL); /* one reply per chunk: a packet at 50 Hz */
            }
            close(c);
        }
        _exit(0);
    }
    close(lfd);
    return pid;
}

static void test_monitor_warns(void **state)
{
    char where[32];
    int port = 0;
    pid_t pid = fake_gcu(&port, 20);
    tool_result r;
    json_t *o;
    (void)state;
    snprintf(where, sizeof(where), "127.0.0.1:%d", port);
    r = run_tool(NULL, "--tcp", where, "monitor", "--json", "--count", "2", NULL);
    assert_int_equal(r.status, 0);
    o = parse_line(r.out);
    assert_string_equal(str_key(o, "direction"), "gcu");
    assert_true(warned(o, "cam_yaw 36500 (365.00 deg) is outside", NULL));
    assert_true(warned(o, "a reply to the null order with an execution state", NULL));
    json_decref(o);
    tool_result_free(&r);
    r = run_tool(NULL, "--tcp", where, "monitor", "--duration", "0.5", NULL);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "\nwarning: a reply to the null order with an execution state (0x00)"));
    assert_non_null(strstr(r.out, " packets with warnings)\n"));
    tool_result_free(&r);
    kill(pid, SIGKILL);
    waitpid(pid, NULL, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_decode_warnings),
        cmocka_unit_test(test_warned_round_trip),
        cmocka_unit_test(test_given_up),
        cmocka_unit_test_setup_teardown(test_ardupilot_session, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_wrapper_lengths, sim_setup_none, sim_teardown),
        cmocka_unit_test_setup_teardown(test_72_and_73_byte_replies, sim_setup_none, sim_teardown),
        cmocka_unit_test(test_monitor_warns),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
