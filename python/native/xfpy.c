/*
 * xfpy.c - the flat C API of the Python package (xfpy.h): the program's
 * JSON and command parsing, the client and the simulator behind opaque
 * handles.
 */
#define _POSIX_C_SOURCE 200809L /* poll, nanosleep, clock_gettime */

#include "xfpy.h"

#include <jansson.h>
#include <math.h>
#include <poll.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "cmdargs.h"
#include "encode.h"
#include "jsonpkt.h"
#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/xf_client.h"
#include "xfgcu/xf_sim.h"

/* ---- messages: the program's cli_report(), into buffers instead of stderr ------------ */

static char error_text[2048];
static char notes_text[4096];

int cli_report(int code, const char *where, const char *fmt, ...)
{
    char text[1536];
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(text, sizeof(text), fmt, ap);
    va_end(ap);
    if (n < 0) {
        snprintf(text, sizeof(text), "%s", fmt);
    }
    if (code == XFGCU_EXIT_OK) { /* a note: kept, one per line */
        size_t used = strlen(notes_text);
        snprintf(notes_text + used, sizeof(notes_text) - used, "%s\n", text);
    } else if (where != NULL) {
        snprintf(error_text, sizeof(error_text), "%s: %s", where, text);
    } else {
        snprintf(error_text, sizeof(error_text), "%s", text);
    }
    return code;
}

const char *xfpy_error(void) { return error_text; }
const char *xfpy_notes(void) { return notes_text; }
const char *xfpy_version(void) { return XF_VERSION_STRING; }

void xfpy_clear(void)
{
    error_text[0] = '\0';
    notes_text[0] = '\0';
}

/* A JSON value into @p out as compact text: 0, or the size needed (text and NUL). */
static int dump_json(json_t *obj, char *out, size_t cap)
{
    size_t need = json_dumpb(obj, NULL, 0, JSON_COMPACT | JSON_PRESERVE_ORDER);
    if (need == 0u) {
        return -1; /* jansson could not write it: an error, not a size to retry with */
    }
    if (need + 1u > cap) {
        return (int)need + 1;
    }
    (void)json_dumpb(obj, out, cap, JSON_COMPACT | JSON_PRESERVE_ORDER);
    out[need] = '\0';
    return 0;
}

/* ---- codec ----------------------------------------------------------------------------- */

int xfpy_decode(const uint8_t *buf, size_t len, int pod, char *out, size_t cap)
{
    xf_direction dir = XF_DIR_HOST;
    xf_err err = xf_packet_direction(buf, len, &dir);
    json_t *obj;
    int rc;
    if (err == XF_OK) {
        err = xf_packet_check(buf, len, dir);
    }
    if (err != XF_OK) {
        return (int)err;
    }
    obj = jsonpkt_from_wire(buf, len, dir, (pod_reading)pod);
    if (obj == NULL) {
        return (int)XF_ERR_IO;
    }
    rc = dump_json(obj, out, cap);
    json_decref(obj);
    return rc;
}

int xfpy_encode(const char *json, int version, uint8_t *out, size_t cap, size_t *len)
{
    json_error_t error;
    int rc;
    json_t *obj = json_loads(json, JSON_REJECT_DUPLICATES, &error);
    if (obj == NULL) {
        return cli_fail("encode: invalid JSON at column %d: %s", error.column, error.text);
    }
    rc = jsonpkt_to_wire(obj, (uint8_t)version, "encode", out, cap, len);
    json_decref(obj);
    return rc;
}

/* The command @p argv names, parsed as `encode` parses it; its spec into *spec. */
static int parse_command(int argc, char **argv, uint8_t version, const cmd_spec **spec, xf_command *cmd)
{
    if (argc < 1 || argv[0] == NULL || (*spec = cmdargs_find(argv[0])) == NULL) {
        return cli_fail("encode: unknown command '%s' (see 'xfgcu encode --help')", argc > 0 ? argv[0] : "");
    }
    return cmdargs_parse_command(*spec, "encode", argc, argv, &version, cmd);
}

int xfpy_command(int argc, char **argv, int version, uint8_t *out, size_t cap, size_t *len)
{
    const cmd_spec *spec = NULL;
    xf_command cmd;
    int rc = parse_command(argc, argv, (uint8_t)version, &spec, &cmd);
    return (rc == XFGCU_EXIT_OK) ? encode_command(spec, &cmd, (uint8_t)version, out, cap, len) : rc;
}

const char *xfpy_model_name(int code)
{
    const char *name = xf_gimbal_model((uint8_t)code);
    return (name != NULL) ? name : "";
}

const char *xfpy_command_names(void)
{
    static char names[4096];
    size_t i, used = 0;
    const xf_order_info *info;
    names[0] = '\0';
    for (i = 0; (info = xf_order_at(i)) != NULL; i++) {
        const cmd_spec *spec = cmdargs_find(xf_order_name(info->order));
        if (spec != NULL && used < sizeof(names)) {
            used += (size_t)snprintf(names + used, sizeof(names) - used, "%s\n", cmdargs_name(spec));
        }
    }
    return names;
}

/* ---- stream parser ------------------------------------------------------------------- */

typedef struct xfpy_parser {
    xf_parser p[2]; /* host, GCU */
    uint32_t pos;   /* bytes fed so far */
} xfpy_parser;

void *xfpy_parser_new(void)
{
    xfpy_parser *p = (xfpy_parser *)calloc(1, sizeof(*p));
    if (p != NULL &&
        (xf_parser_init(&p->p[0], XF_DIR_HOST) != XF_OK || xf_parser_init(&p->p[1], XF_DIR_GCU) != XF_OK)) {
        free(p);
        p = NULL;
    }
    return p;
}

void xfpy_parser_free(void *p) { free(p); }

/* The frames of one direction into @p out; @return the bytes written, or -1 when out is full. */
static long feed_one(xf_parser *parser, uint8_t dir, uint32_t pos, const uint8_t *data, size_t len, uint8_t *out,
                     size_t cap)
{
    size_t done = 0, n = 0, used = 0;
    xf_frame f;
    while (done < len && xf_parser_feed(parser, data + done, len - done, &n, &f) == XF_PARSE_FRAME) {
        uint32_t end;
        done += n;
        end = pos + (uint32_t)done;
        if (used + 6u + f.len > cap) {
            return -1;
        }
        out[used++] = (uint8_t)(end & 0xFFu);
        out[used++] = (uint8_t)((end >> 8) & 0xFFu);
        out[used++] = (uint8_t)((end >> 16) & 0xFFu);
        out[used++] = (uint8_t)(end >> 24);
        out[used++] = dir;
        out[used++] = (uint8_t)f.len;
        memcpy(out + used, f.data, f.len);
        used += f.len;
    }
    return (long)used;
}

long xfpy_parser_feed(void *h, const uint8_t *data, size_t len, uint8_t *out, size_t cap)
{
    xfpy_parser *p = (xfpy_parser *)h;
    long a = feed_one(&p->p[0], 0u, p->pos, data, len, out, cap);
    long b = (a >= 0) ? feed_one(&p->p[1], 1u, p->pos, data, len, out + a, cap - (size_t)a) : -1;
    p->pos += (uint32_t)len;
    return (b >= 0) ? a + b : -1;
}

void xfpy_wait(int fd, int ms)
{
    if (fd >= 0) {
        struct pollfd pfd;
        pfd.fd = fd;
        pfd.events = POLLIN;
        pfd.revents = 0;
        (void)poll(&pfd, 1, ms);
    } else {
        struct timespec ts;
        ts.tv_sec = ms / 1000;
        ts.tv_nsec = (long)(ms % 1000) * 1000000L;
        (void)nanosleep(&ts, NULL);
    }
}

/* ---- client ------------------------------------------------------------------------------ */

#define RING 64u /* replies kept for the telemetry stream */

typedef struct reply {
    uint8_t bytes[XF_PACKET_MAX_LEN];
    uint8_t len;
    xf_telemetry tele;
    struct timespec mono, wall; /* when it came: monitor --json's time_mono and time_utc */
} reply;

typedef struct xfpy_client {
    xf_client_config cfg;
    xf_link link;
    xf_hal hal;
    xf_client client;
    uint8_t last[XF_PACKET_MAX_LEN]; /* the last GCU packet (on_bytes), until its telemetry comes */
    size_t last_len;
    reply ring[RING];
    uint32_t replies;
    int opened;
    char desc[320];
} xfpy_client;

static void on_bytes(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    xfpy_client *h = (xfpy_client *)user;
    (void)now_ms;
    if (dir == XF_DIR_GCU && len <= sizeof(h->last)) {
        memcpy(h->last, data, len);
        h->last_len = len;
    }
}

static void on_telemetry(void *user, const xf_telemetry *t)
{
    xfpy_client *h = (xfpy_client *)user;
    reply *r = &h->ring[h->replies % RING];
    memcpy(r->bytes, h->last, h->last_len);
    r->len = (uint8_t)h->last_len;
    r->tele = *t;
    clock_gettime(CLOCK_MONOTONIC, &r->mono);
    clock_gettime(CLOCK_REALTIME, &r->wall);
    h->replies++;
}

void *xfpy_client_new(void)
{
    xfpy_client *h = (xfpy_client *)calloc(1, sizeof(*h));
    if (h != NULL) {
        xf_client_config_init(&h->cfg);
    }
    return h;
}

int xfpy_client_config(void *p, const char *name, long v)
{
    xf_client_config *c = &((xfpy_client *)p)->cfg;
    if (v < 0) {
        return -1;
    }
    /* each member's own limit: a value cut to its type would be another value */
#define XFPY_SET(member, type, max)                                                                                    \
    if (strcmp(name, #member) == 0) {                                                                                  \
        if (v > (long)(max)) {                                                                                         \
            return -1;                                                                                                 \
        }                                                                                                              \
        c->member = (type)v;                                                                                           \
        return 0;                                                                                                      \
    }
    XFPY_SET(command_timeout_ms, uint32_t, 3600000L)
    XFPY_SET(operating_timeout_ms, uint32_t, 3600000L)
    XFPY_SET(rate_hz, uint16_t, 200)
    XFPY_SET(carrier_max_age_ms, uint16_t, UINT16_MAX)
    XFPY_SET(gnss_max_age_ms, uint16_t, UINT16_MAX)
    XFPY_SET(stale_ms, uint16_t, UINT16_MAX)
    XFPY_SET(down_ms, uint16_t, UINT16_MAX)
    XFPY_SET(rate_watchdog_ms, uint16_t, UINT16_MAX)
    XFPY_SET(protocol_version, uint8_t, 2)
    XFPY_SET(reorder_ms, uint16_t, 1000)
#undef XFPY_SET
    return -1;
}

const char *xfpy_client_config_problem(void *p) { return xf_client_config_problem(&((xfpy_client *)p)->cfg); }

int xfpy_client_open(void *p, const char *spec)
{
    xfpy_client *h = (xfpy_client *)p;
    xf_err err = xf_link_open(&h->link, spec);
    if (err != XF_OK) {
        (void)cli_fail("%s", h->link.error.text[0] != '\0' ? h->link.error.text : xf_strerror(err));
        return (int)err;
    }
    h->opened = 1;
    (void)xf_link_describe(&h->link, h->desc, sizeof(h->desc));
    err = xf_link_hal(&h->link, &h->hal);
    h->cfg.on_bytes = on_bytes;
    h->cfg.on_telemetry = on_telemetry;
    h->cfg.user = h;
    if (err == XF_OK) {
        err = xf_client_init(&h->client, &h->hal, &h->cfg);
    }
    if (err != XF_OK) {
        (void)cli_fail("%s: %s", h->desc, xf_strerror(err));
        return (int)err;
    }
    return 0;
}

int xfpy_client_step(void *p, int *fd)
{
    xfpy_client *h = (xfpy_client *)p;
    uint32_t now = xf_posix_now_ms();
    int32_t wait;
    (void)xf_client_step(&h->client, now);
    wait = (int32_t)(xf_client_next_deadline(&h->client) - now); /* a deadline passed: negative */
    *fd = xf_hal_fd(&h->hal);
    return (wait < 0) ? 0 : (wait > 20) ? 20 : (int)wait;
}

uint32_t xfpy_client_replies(void *p) { return ((xfpy_client *)p)->replies; }

int xfpy_client_settled(void *p)
{
    const xf_client *c = &((xfpy_client *)p)->client;
    return xf_client_settled(c) || xf_client_link(c) == XF_LINK_DOWN;
}

/* Round to 1e-6 so that a float of the library prints as its decimal value. */
static json_t *real6(double v) { return json_real(floor(v * 1e6 + 0.5) / 1e6); }

static json_t *units_json(const xf_telemetry *t)
{
    json_t *u = json_object();
    float dist = 0.0f;
    int valid = xf_distance_m(t->target_distance, &dist);
    json_object_set_new(u, "cam_roll_deg", real6(t->cam_roll / 100.0));
    json_object_set_new(u, "cam_pitch_deg", real6(t->cam_pitch / 100.0));
    json_object_set_new(u, "cam_yaw_deg", real6(t->cam_yaw / 100.0));
    json_object_set_new(u, "rel_x_deg", real6(t->rel_angle_x / 100.0));
    json_object_set_new(u, "rel_y_deg", real6(t->rel_angle_y / 100.0));
    json_object_set_new(u, "rel_z_deg", real6(t->rel_angle_z / 100.0));
    json_object_set_new(u, "rate_x_dps", real6(xf_gcu_rate_dps(t->rate_x, t->version)));
    json_object_set_new(u, "rate_y_dps", real6(xf_gcu_rate_dps(t->rate_y, t->version)));
    json_object_set_new(u, "rate_z_dps", real6(xf_gcu_rate_dps(t->rate_z, t->version)));
    json_object_set_new(u, "zoom_cam1", real6(t->zoom_cam1 / 10.0));
    json_object_set_new(u, "zoom_cam2", real6(t->zoom_cam2 / 10.0));
    json_object_set_new(u, "target_distance_m", valid ? real6(t->target_distance / 10.0) : json_null());
    json_object_set_new(u, "target_latitude_deg", real6(xf_deg7(t->target_latitude)));
    json_object_set_new(u, "target_longitude_deg", real6(xf_deg7(t->target_longitude)));
    json_object_set_new(u, "target_altitude_m", real6(t->target_altitude / 1000.0));
    json_object_set_new(u, "mode",
                        json_string(xf_mode_name(t->gimbal_mode) ? xf_mode_name(t->gimbal_mode) : "unknown"));
    return u;
}

int xfpy_client_telemetry(void *p, uint32_t seq, char *out, size_t cap)
{
    xfpy_client *h = (xfpy_client *)p;
    const reply *r;
    json_t *obj, *pkt;
    int rc;
    if (seq == 0u) {
        seq = h->replies;
    }
    if (seq == 0u || seq > h->replies || h->replies - seq >= RING) {
        return -1;
    }
    r = &h->ring[(seq - 1u) % RING];
    pkt = jsonpkt_from_wire(r->bytes, r->len, XF_DIR_GCU, POD_READ_AUTO);
    obj = json_object();
    if (pkt == NULL || obj == NULL) {
        json_decref(pkt);
        json_decref(obj);
        return -1;
    }
    (void)jsonpkt_times(obj, &r->mono, &r->wall); /* first, as monitor --json has them */
    json_object_update(obj, pkt);
    json_decref(pkt);
    json_object_set_new(obj, "units", units_json(&r->tele));
    rc = dump_json(obj, out, cap);
    json_decref(obj);
    return rc;
}

/* xf_ctrl_status, as health's "control" says it */
static const char *const ctrl_names[] = {"sent", "not_set", "no_mode", "wrong_kind", "not_read", "command", "dropped"};

int xfpy_client_health(void *p, char *out, size_t cap)
{
    xfpy_client *h = (xfpy_client *)p;
    const xf_health *he = xf_client_health(&h->client);
    const xf_parser_stats *ps = xf_client_parser_stats(&h->client);
    int rc;
    json_t *o = json_pack("{s:s,s:b,s:b,s:i,s:I,s:I,s:I,s:I,s:I,s:I,s:I,s:I,s:I,s:i,s:s}", "link",
                          xf_link_state_name(he->link), "watchdog_active", he->watchdog_active != 0u,
                          "transport_closed", he->transport_closed != 0u, "reply_rate_hz", (int)he->reply_rate_hz,
                          "last_rx_ms", (json_int_t)he->last_rx_ms, "packets_sent", (json_int_t)he->packets_sent,
                          "replies", (json_int_t)he->replies, "replies_missing", (json_int_t)he->replies_missing,
                          "send_errors", (json_int_t)he->send_errors, "watchdog_trips", (json_int_t)he->watchdog_trips,
                          "crc_errors", (json_int_t)ps->crc_errors, "length_errors", (json_int_t)ps->length_errors,
                          "bytes_skipped", (json_int_t)ps->bytes_skipped, "pending", (int)xf_client_pending(&h->client),
                          "control", ctrl_names[(unsigned)xf_client_control_status(&h->client) % 7u]);
    if (o == NULL) {
        return -1;
    }
    rc = dump_json(o, out, cap);
    json_decref(o);
    return rc;
}

int xfpy_client_submit(void *p, int argc, char **argv, int force, uint32_t *id)
{
    xfpy_client *h = (xfpy_client *)p;
    uint8_t version = xf_client_gcu_version(&h->client);
    const cmd_spec *spec = NULL;
    xf_field bad = XF_F_NONE;
    xf_command cmd;
    xf_err err;
    int rc = parse_command(argc, argv, version, &spec, &cmd);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    cmdargs_for_version(&cmd, version); /* as send does: the GCU's meaning */
    err = xf_client_submit_opt(&h->client, &cmd, force ? XF_SUBMIT_ANY_MODEL : 0u, id, &bad);
    if (err == XF_ERR_UNSUPPORTED) {
        const char *model = xf_gimbal_model(xf_client_telemetry(&h->client)->gimbal_code);
        return cli_report(XFGCU_EXIT_FAILED, NULL,
                          "send %s: the GCU's model %s (code %u) does not support it, by V2.0.6's support list; "
                          "send it with force=True all the same",
                          cmdargs_name(spec), model != NULL ? model : "?",
                          (unsigned)xf_client_telemetry(&h->client)->gimbal_code);
    }
    if (err != XF_OK) {
        return cli_fail("send %s: %s%s%s", cmdargs_name(spec), xf_strerror(err), bad != XF_F_NONE ? ": " : "",
                        bad != XF_F_NONE ? xf_field_name(bad) : "");
    }
    return XFGCU_EXIT_OK;
}

int xfpy_client_result(void *p, uint32_t id, int *failed_cameras, int *packets, long *elapsed_ms, int *state)
{
    xf_cmd_result r;
    xf_cmd_status s;
    memset(&r, 0, sizeof(r));
    s = xf_client_command_status(&((xfpy_client *)p)->client, id, &r);
    *failed_cameras = r.failed_cameras;
    *packets = r.packets;
    *elapsed_ms = (long)r.elapsed_ms;
    *state = r.state;
    return (int)s;
}

void xfpy_client_cancel_all(void *p) { xf_client_cancel_all(&((xfpy_client *)p)->client); }

int xfpy_client_set_rates(void *p, double roll, double pitch, double yaw)
{
    return (int)xf_client_set_rates(&((xfpy_client *)p)->client, (float)roll, (float)pitch, (float)yaw,
                                    xf_posix_now_ms());
}

int xfpy_client_set_angles(void *p, double roll, double pitch, double yaw)
{
    return (int)xf_client_set_angles(&((xfpy_client *)p)->client, (float)roll, (float)pitch, (float)yaw,
                                     xf_posix_now_ms());
}

void xfpy_client_clear_control(void *p) { xf_client_clear_control(&((xfpy_client *)p)->client); }

void xfpy_client_set_carrier(void *p, const double *v)
{
    xf_carrier c;
    c.roll_deg = (float)v[0];
    c.pitch_deg = (float)v[1];
    c.yaw_deg = (float)v[2];
    c.accel_north = (float)v[3];
    c.accel_east = (float)v[4];
    c.accel_up = (float)v[5];
    c.vel_north = (float)v[6];
    c.vel_east = (float)v[7];
    c.vel_up = (float)v[8];
    xf_client_set_carrier(&((xfpy_client *)p)->client, &c, xf_posix_now_ms());
}

void xfpy_client_set_gnss(void *p, double lat, double lon, double alt_m, int satellites, int week, long ms_of_week,
                          double relative_height_m)
{
    xf_gnss g;
    memset(&g, 0, sizeof(g));
    g.latitude_e7 = xf_deg7_raw(lat);
    g.longitude_e7 = xf_deg7_raw(lon);
    g.altitude_mm = xf_mm_raw(alt_m);
    g.satellites = (uint8_t)(satellites < 0 ? 0 : satellites > 255 ? 255 : satellites);
    g.relative_height_mm = xf_mm_raw(relative_height_m);
    if (week < 0) {
        struct timespec ts;
        (void)clock_gettime(CLOCK_REALTIME, &ts);
        /* 18: the GPS-UTC leap seconds since 2017 */
        (void)xf_unix_ms_to_gnss((int64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000L, 18, &g.week, &g.ms_of_week);
    } else {
        g.week = (int16_t)week;
        g.ms_of_week = (uint32_t)ms_of_week;
    }
    xf_client_set_gnss(&((xfpy_client *)p)->client, &g, xf_posix_now_ms());
}

const char *xfpy_client_describe(void *p) { return ((xfpy_client *)p)->desc; }

void xfpy_client_free(void *p)
{
    xfpy_client *h = (xfpy_client *)p;
    if (h != NULL && h->opened) {
        xf_link_close(&h->link);
    }
    free(h);
}

/* ---- simulator ------------------------------------------------------------------------------ */

typedef struct xfpy_sim {
    xf_sim_config cfg;
    xf_simlink link;
    xf_sim sim;
    uint8_t fail[256];
    int opened;
    char spec[XF_LINK_SPEC_MAX + 1u];
} xfpy_sim;

void *xfpy_sim_new(void)
{
    xfpy_sim *h = (xfpy_sim *)calloc(1, sizeof(*h));
    if (h != NULL) {
        xf_sim_config_init(&h->cfg);
    }
    return h;
}

int xfpy_sim_config(void *p, const char *name, long v)
{
    xf_sim_config *c = &((xfpy_sim *)p)->cfg;
    if (v < 0) {
        return -1;
    }
#define XFPY_SET(key, member, type, max)                                                                               \
    if (strcmp(name, key) == 0 && v <= (long)(max)) {                                                                  \
        c->member = (type)v;                                                                                           \
        return 0;                                                                                                      \
    }
    XFPY_SET("version", version, uint8_t, 2)
    XFPY_SET("model", gimbal_code, uint8_t, 255)
    XFPY_SET("hw_version", hw_version, uint8_t, 255)
    XFPY_SET("fw_version", fw_version, uint8_t, 255)
    XFPY_SET("calibration_ms", calibration_ms, uint32_t, 600000)
    XFPY_SET("feedback_after", feedback_after, uint16_t, 65535)
    XFPY_SET("state_once", state_once, uint8_t, 1)
    XFPY_SET("seed", seed, uint32_t, 0x7FFFFFFF)
#undef XFPY_SET
    return -1;
}

int xfpy_sim_fault(void *p, const char *name, long v)
{
    xf_sim_faults *f = &((xfpy_sim *)p)->sim.fault;
    if (v < 0) {
        return -1;
    }
#define XFPY_SET(member, type, max)                                                                                    \
    if (strcmp(name, #member) == 0 && v <= (long)(max)) {                                                              \
        f->member = (type)v;                                                                                           \
        return 0;                                                                                                      \
    }
    XFPY_SET(drop_next, uint16_t, 65535)
    XFPY_SET(drop_permille, uint16_t, 1000)
    XFPY_SET(corrupt_next, uint16_t, 65535)
    XFPY_SET(corrupt_permille, uint16_t, 1000)
    XFPY_SET(delay_ms, uint32_t, 10000)
    XFPY_SET(jitter_ms, uint16_t, 10000)
    XFPY_SET(dup_permille, uint16_t, 1000)
    XFPY_SET(silent, uint8_t, 1)
#undef XFPY_SET
    return -1;
}

void xfpy_sim_fail(void *p, int order, int state)
{
    xfpy_sim *h = (xfpy_sim *)p;
    h->fail[order & 0xFF] = (uint8_t)state;
    if (h->opened) {
        xf_sim_set_failure(&h->sim, (uint8_t)order, (uint8_t)state);
    }
}

static xf_err open_simlink(xfpy_sim *h, const char *kind, const char *where, int port)
{
    if (strcmp(kind, "pty") == 0) {
        return xf_simlink_open_pty(&h->link, (where != NULL && where[0] != '\0') ? where : NULL);
    }
    if (strcmp(kind, "udp") == 0) {
        return xf_simlink_open_udp(&h->link, where, (uint16_t)port);
    }
    if (strcmp(kind, "tcp") == 0) {
        return xf_simlink_open_tcp(&h->link, where, (uint16_t)port);
    }
    return XF_ERR_ARG;
}

int xfpy_sim_open(void *p, const char *kind, const char *where, int port)
{
    xfpy_sim *h = (xfpy_sim *)p;
    xf_hal hal;
    int i;
    xf_err err = open_simlink(h, kind, where, port);
    if (err != XF_OK) {
        (void)cli_fail("sim %s: %s", kind, h->link.error.text[0] != '\0' ? h->link.error.text : xf_strerror(err));
        return (int)err;
    }
    h->opened = 1;
    err = xf_sim_init(&h->sim, &h->cfg);
    xf_simlink_hal(&h->link, &hal);
    if (err == XF_OK) {
        err = xf_sim_attach(&h->sim, &hal);
    }
    for (i = 0; i < 256; i++) {
        if (h->fail[i] != 0u) {
            xf_sim_set_failure(&h->sim, (uint8_t)i, h->fail[i]);
        }
    }
    (void)xf_link_spec_for_simlink(&h->link, h->spec, sizeof(h->spec));
    if (err != XF_OK) {
        (void)cli_fail("sim: %s", xf_strerror(err));
    }
    return (int)err;
}

const char *xfpy_sim_spec(void *p) { return ((xfpy_sim *)p)->spec; }

int xfpy_sim_step(void *p, int *fd)
{
    xfpy_sim *h = (xfpy_sim *)p;
    (void)xf_sim_step(&h->sim, xf_posix_now_ms());
    *fd = xf_hal_fd(&h->sim.hal);
    return 5; /* the simulator moves the gimbal between packets too */
}

int xfpy_sim_stats(void *p, char *out, size_t cap)
{
    xfpy_sim *h = (xfpy_sim *)p;
    const xf_sim_stats *s = &h->sim.stats;
    json_t *executed = json_object();
    json_t *o;
    int i, rc;
    for (i = 0; i < 256; i++) {
        const char *name = xf_order_name((uint8_t)i);
        if (s->executed[i] != 0u) {
            json_object_set_new(executed, name != NULL ? name : "unknown", json_integer(s->executed[i]));
        }
    }
    o = json_pack("{s:I,s:I,s:I,s:I,s:I,s:I,s:I,s:o,s:i,s:f,s:f,s:f,s:f,s:f}", "packets_in", (json_int_t)s->packets_in,
                  "replies", (json_int_t)s->replies, "dropped", (json_int_t)s->dropped, "corrupted",
                  (json_int_t)s->corrupted, "photos", (json_int_t)s->photos, "recordings", (json_int_t)s->recordings,
                  "ins_valid_packets", (json_int_t)s->ins_valid_packets, "executed", executed, "mode", (int)h->sim.mode,
                  "roll", (double)h->sim.roll, "pitch", (double)h->sim.pitch, "yaw", (double)h->sim.yaw, "zoom_cam1",
                  (double)h->sim.zoom1, "zoom_cam2", (double)h->sim.zoom2);
    if (o == NULL) {
        return -1;
    }
    rc = dump_json(o, out, cap);
    json_decref(o);
    return rc;
}

void xfpy_sim_disconnect(void *p, long ms) { xf_simlink_disconnect(&((xfpy_sim *)p)->link, (uint32_t)ms); }

void xfpy_sim_free(void *p)
{
    xfpy_sim *h = (xfpy_sim *)p;
    if (h != NULL && h->opened) {
        xf_simlink_close(&h->link);
    }
    free(h);
}
