/*
 * xfpy.c - the flat C API of the Python package (xfpy.h): the text layer's JSON and named
 * commands (xfgcu::text, as the xfgcu program uses it), the client and the simulator behind
 * opaque handles. No process-wide state: messages go into the caller's buffer.
 */
#define _POSIX_C_SOURCE 200809L /* poll, nanosleep, clock_gettime */

#include "xfpy.h"

#include <jansson.h>
#include <poll.h>
#include <stddef.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cmdargs.h"
#include "encode.h"
#include "jsonpkt.h"
#include "xfgcu/posix/xf_link.h"
#include "xfgcu/posix/xf_posix.h"
#include "xfgcu/posix/xf_simlink.h"
#include "xfgcu/xf_client.h"
#include "xfgcu/xf_sim.h"

/* ---- messages: "note: ...\n" lines, then "error: ...\n", into the caller's buffer -------- */

/* The context's notes and failure into @p msgs (capacity @p cap; may be NULL when cap is 0). */
static void put_messages(const text_err *e, char *msgs, size_t cap)
{
    const char *p = e->notes;
    size_t used = 0;
    if (msgs == NULL || cap == 0u) {
        return;
    }
    msgs[0] = '\0';
    while (*p != '\0' && used < cap) {
        size_t n = strcspn(p, "\n");
        used += (size_t)snprintf(msgs + used, cap - used, "note: %.*s\n", (int)n, p);
        p += n + (p[n] == '\n');
    }
    if (e->failed && used < cap) {
        (void)snprintf(msgs + used, cap - used, "error: %s\n", e->message);
    }
}

/* A failure of @p code with its message, as the API returns it. */
static int fail(int code, char *msgs, size_t cap, const char *fmt, ...) TEXT_PRINTF(4, 5);

static int fail(int code, char *msgs, size_t cap, const char *fmt, ...)
{
    char text[1024];
    text_err e;
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(text, sizeof(text), fmt, ap);
    va_end(ap);
    text_err_init(&e);
    (void)text_fail(&e, NULL, "%s", text);
    put_messages(&e, msgs, cap);
    return code;
}

const char *xfpy_version(void) { return XF_VERSION_STRING; }

/* A JSON value into @p out as compact text: 0, or the size needed (text and NUL). */
static int dump_json(json_t *obj, char *out, size_t cap)
{
    char *text = jsonpkt_dumps(obj); /* the layer's one way of writing numbers: as the program does */
    size_t need = (text != NULL) ? strlen(text) : 0u;
    if (text == NULL) {
        return -1; /* jansson could not write it: an error, not a size to retry with */
    }
    if (need + 1u > cap) {
        free(text);
        return (int)need + 1;
    }
    memcpy(out, text, need + 1u);
    free(text);
    return 0;
}

/* ---- codec ----------------------------------------------------------------------------- */

int xfpy_decode(const uint8_t *buf, size_t len, int pod, int raw, char *out, size_t cap)
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
    obj = jsonpkt_from_wire(buf, len, dir, (pod_reading)pod, raw ? TEXT_RAW : TEXT_ENGINEERING);
    if (obj == NULL) {
        return (int)XF_ERR_IO;
    }
    rc = dump_json(obj, out, cap);
    json_decref(obj);
    return rc;
}

int xfpy_encode(const char *json, int version, int raw, uint8_t *out, size_t cap, size_t *len, char *msgs,
                size_t msgs_cap)
{
    text_err e;
    json_t *obj;
    int rc;
    text_err_init(&e);
    obj = jsonpkt_parse(json, strlen(json), "encode", &e);
    rc = (obj != NULL)
             ? jsonpkt_to_wire(obj, (uint8_t)version, raw ? TEXT_RAW : TEXT_ENGINEERING, "encode", out, cap, len, &e)
             : TEXT_BAD;
    json_decref(obj);
    put_messages(&e, msgs, msgs_cap);
    return (rc == TEXT_OK) ? 0 : 2;
}

/* The command @p name with @p n named arguments, built for @p version as encode builds it. */
static int build_command(const char *name, int n, const char *const *names, const char *const *values, uint8_t version,
                         const char *who, cmd_spec *spec, xf_command *cmd, text_err *e)
{
    text_arg args[32];
    int i;
    if (!cmdargs_find(name, spec)) {
        return text_fail(e, who, "unknown command '%s'", name != NULL ? name : "");
    }
    if (n < 0 || n > 32) {
        return text_fail(e, who, "%s: %d arguments, at most 32", spec->name, n);
    }
    for (i = 0; i < n; i++) {
        args[i].name = names[i];
        args[i].value = values[i];
    }
    return cmdargs_build(spec, args, (size_t)n, version, who, cmd, e);
}

int xfpy_command(const char *name, int n, const char *const *names, const char *const *values, int version,
                 uint8_t *out, size_t cap, size_t *len, char *msgs, size_t msgs_cap)
{
    cmd_spec spec;
    xf_command cmd;
    text_err e;
    int rc;
    text_err_init(&e);
    rc = build_command(name, n, names, values, (uint8_t)version, NULL, &spec, &cmd, &e);
    if (rc == TEXT_OK) {
        rc = encode_command(&spec, &cmd, (uint8_t)version, out, cap, len, &e);
    }
    put_messages(&e, msgs, msgs_cap);
    return (rc == TEXT_OK) ? 0 : 2;
}

int xfpy_order_code(const char *name)
{
    uint8_t order = 0;
    return (xf_order_from_name(name, &order) == XF_OK) ? (int)order : -1;
}

const char *xfpy_model_name(int code)
{
    const char *name = xf_gimbal_model((uint8_t)code);
    return (name != NULL) ? name : "";
}

int xfpy_command_names(char *out, size_t cap)
{
    cmd_spec spec;
    size_t i, used = 0;
    if (cap > 0u) {
        out[0] = '\0';
    }
    for (i = 0; cmdargs_at(i, &spec); i++) {
        size_t n = strlen(spec.name) + 1u; /* the name and its newline */
        if (used + n < cap) {
            (void)snprintf(out + used, cap - used, "%s\n", spec.name);
        }
        used += n;
    }
    return (used < cap) ? 0 : (int)used + 1;
}

int xfpy_command_option(const char *name, size_t i, const char **arg, unsigned *values, int *real, const char **words,
                        int *cameras, double *lo, double *hi, const char **field, const char **help)
{
    cmd_spec spec;
    cmdargs_info info;
    if (!cmdargs_find(name, &spec)) {
        return -1;
    }
    if (!cmdargs_option_info(&spec, i, &info)) {
        return 0;
    }
    *arg = info.name;
    *values = info.values;
    *real = info.real;
    *words = info.words;
    *cameras = info.cameras;
    *lo = info.lo;
    *hi = info.hi;
    *field = info.field;
    *help = info.help;
    return 1;
}

int xfpy_field_at(int group, size_t i, const char **name, const char **unit, const char **meaning, int *kind,
                  int *since)
{
    size_t count = 0;
    const xf_wire_field *rows = xf_wire_fields((xf_wire_group)group, &count);
    if (rows == NULL || i >= count) {
        return 0;
    }
    *name = rows[i].name;
    *unit = rows[i].unit;
    *meaning = rows[i].meaning;
    *kind = rows[i].kind;
    *since = rows[i].since;
    return 1;
}

/* ---- settings: one table per struct, the one place of each range ---------------------- */

typedef struct setting {
    const char *name;
    size_t offset; /* of the member in its struct */
    size_t size;   /* 1, 2 or 4 bytes, unsigned */
    long long lo, hi;
} setting;

#define XFPY_ROW(type, key, member, lo, hi)                                                                            \
    {                                                                                                                  \
        key, offsetof(type, member), sizeof(((type *)0)->member), lo, hi                                               \
    }

/* The limits are the library's own (xf_client_config_problem() still judges the combination). */
static const setting client_settings[] = {
    XFPY_ROW(xf_client_config, "command_timeout_ms", command_timeout_ms, 1, 3600000),
    XFPY_ROW(xf_client_config, "operating_timeout_ms", operating_timeout_ms, 1, 3600000),
    XFPY_ROW(xf_client_config, "rate_hz", rate_hz, 1, 200),
    XFPY_ROW(xf_client_config, "carrier_max_age_ms", carrier_max_age_ms, 0, UINT16_MAX),
    XFPY_ROW(xf_client_config, "gnss_max_age_ms", gnss_max_age_ms, 0, UINT16_MAX),
    XFPY_ROW(xf_client_config, "stale_ms", stale_ms, 1, UINT16_MAX),
    XFPY_ROW(xf_client_config, "down_ms", down_ms, 1, UINT16_MAX),
    XFPY_ROW(xf_client_config, "rate_watchdog_ms", rate_watchdog_ms, 0, UINT16_MAX),
    XFPY_ROW(xf_client_config, "protocol_version", protocol_version, 1, 2),
    XFPY_ROW(xf_client_config, "version_auto", version_auto, 0, 1),
    XFPY_ROW(xf_client_config, "reorder_ms", reorder_ms, 0, 1000),
    XFPY_ROW(xf_client_config, "reorder_fixed", reorder_fixed, 0, 1),
};

static const setting sim_settings[] = {
    XFPY_ROW(xf_sim_config, "version", version, 1, 2),
    XFPY_ROW(xf_sim_config, "model", gimbal_code, 0, 255),
    XFPY_ROW(xf_sim_config, "hw_version", hw_version, 0, 255),
    XFPY_ROW(xf_sim_config, "fw_version", fw_version, 0, 255),
    XFPY_ROW(xf_sim_config, "calibration_ms", calibration_ms, 0, 600000),
    XFPY_ROW(xf_sim_config, "feedback_after", feedback_after, 0, UINT16_MAX),
    XFPY_ROW(xf_sim_config, "state_once", state_once, 0, 1),
    XFPY_ROW(xf_sim_config, "main_camera", main_camera, 1, 2),
    XFPY_ROW(xf_sim_config, "answer_only", answer_only, 0, 2),
    XFPY_ROW(xf_sim_config, "seed", seed, 0, 0x7FFFFFFF),
};

static const setting fault_settings[] = {
    XFPY_ROW(xf_sim_faults, "drop_next", drop_next, 0, UINT16_MAX),
    XFPY_ROW(xf_sim_faults, "drop_permille", drop_permille, 0, 1000),
    XFPY_ROW(xf_sim_faults, "corrupt_next", corrupt_next, 0, UINT16_MAX),
    XFPY_ROW(xf_sim_faults, "corrupt_permille", corrupt_permille, 0, 1000),
    XFPY_ROW(xf_sim_faults, "delay_ms", delay_ms, 0, 10000),
    XFPY_ROW(xf_sim_faults, "jitter_ms", jitter_ms, 0, 10000),
    XFPY_ROW(xf_sim_faults, "dup_permille", dup_permille, 0, 1000),
    XFPY_ROW(xf_sim_faults, "silent", silent, 0, 1),
};
#undef XFPY_ROW

/* Table @p table's rows into *@p rows. @return how many (0 for no table). */
static size_t settings(int table, const setting **rows)
{
    static const struct {
        const setting *rows;
        size_t n;
    } tables[] = {{client_settings, sizeof(client_settings) / sizeof(client_settings[0])},
                  {sim_settings, sizeof(sim_settings) / sizeof(sim_settings[0])},
                  {fault_settings, sizeof(fault_settings) / sizeof(fault_settings[0])}};
    if (table < 0 || table > 2) {
        return 0;
    }
    *rows = tables[table].rows;
    return tables[table].n;
}

int xfpy_setting_at(int table, size_t i, const char **name, long long *lo, long long *hi)
{
    const setting *rows = NULL;
    if (i >= settings(table, &rows)) {
        return 0;
    }
    *name = rows[i].name;
    *lo = rows[i].lo;
    *hi = rows[i].hi;
    return 1;
}

static const setting *find_setting(int table, const char *name)
{
    const setting *rows = NULL;
    size_t i, n = settings(table, &rows);
    for (i = 0; name != NULL && i < n; i++) {
        if (strcmp(rows[i].name, name) == 0) {
            return &rows[i];
        }
    }
    return NULL;
}

/* Setting @p name of @p table in the struct at @p base to @p v: 0, or -1 (unknown, out of range: never cut). */
static int put_setting(int table, void *base, const char *name, long long v)
{
    const setting *s = find_setting(table, name);
    uint8_t *at;
    if (s == NULL || v < s->lo || v > s->hi) {
        return -1;
    }
    at = (uint8_t *)base + s->offset;
    if (s->size == 1u) {
        *at = (uint8_t)v;
    } else if (s->size == 2u) {
        uint16_t u = (uint16_t)v;
        memcpy(at, &u, sizeof(u));
    } else {
        uint32_t u = (uint32_t)v;
        memcpy(at, &u, sizeof(u));
    }
    return 0;
}

static long long get_setting(int table, const void *base, const char *name)
{
    const setting *s = find_setting(table, name);
    const uint8_t *at;
    uint16_t u16;
    uint32_t u32;
    if (s == NULL) {
        return -1;
    }
    at = (const uint8_t *)base + s->offset;
    if (s->size == 1u) {
        return *at;
    }
    if (s->size == 2u) {
        memcpy(&u16, at, sizeof(u16));
        return u16;
    }
    memcpy(&u32, at, sizeof(u32));
    return u32;
}

/* ---- the setters' limits: where the library's conversions are exact ------------------- */

typedef struct limit {
    const char *name;
    double lo, hi;
    int wraps;
} limit;

int xfpy_limit_at(size_t i, const char **name, double *lo, double *hi, int *wraps)
{
    /* Each bound is where the library's converter stops: beyond it, it clamps. An angle that the
     * library wraps is taken over one turn either way (a float beyond that loses the degree). */
    const double angle = xf_ctrl_angle_raw(1e9f) / 100.0;    /* set_angles' pitch: 180 deg */
    const double rate = xf_ctrl_rate_raw(1e9f, 1.0f) / 10.0; /* at zoom 1: 150 deg/s */
    const double pitch = xf_carrier_pitch_raw(1e9f) / 100.0; /* the carrier's: 90 deg */
    const double accel_lo = xf_accel_raw(-1e9f) / 100.0, accel_hi = xf_accel_raw(1e9f) / 100.0;
    const double vel_lo = xf_velocity_raw(-1e9f) / 100.0, vel_hi = xf_velocity_raw(1e9f) / 100.0;
    const double mm_lo = xf_mm_raw(-1e18) / 1000.0, mm_hi = xf_mm_raw(1e18) / 1000.0;
    const limit rows[] = {
        {"set_angles.roll", -360.0, 360.0, 1},
        {"set_angles.pitch", -angle, angle, 0},
        {"set_angles.yaw", -360.0, 360.0, 1},
        {"set_rates.roll", -rate, rate, 0},
        {"set_rates.pitch", -rate, rate, 0},
        {"set_rates.yaw", -rate, rate, 0},
        {"set_carrier.roll", -360.0, 360.0, 1},
        {"set_carrier.pitch", -pitch, pitch, 0},
        {"set_carrier.yaw", -360.0, 360.0, 1},
        {"set_carrier.accel_north", accel_lo, accel_hi, 0},
        {"set_carrier.accel_east", accel_lo, accel_hi, 0},
        {"set_carrier.accel_up", accel_lo, accel_hi, 0},
        {"set_carrier.vel_north", vel_lo, vel_hi, 0},
        {"set_carrier.vel_east", vel_lo, vel_hi, 0},
        {"set_carrier.vel_up", vel_lo, vel_hi, 0},
        {"set_gnss.latitude", -90.0, 90.0, 0}, /* a latitude's own range */
        {"set_gnss.longitude", xf_deg7_raw(-1e3) / 1e7, xf_deg7_raw(1e3) / 1e7, 0},
        {"set_gnss.altitude", mm_lo, mm_hi, 0},
        {"set_gnss.relative_height", mm_lo, mm_hi, 0},
        {"set_gnss.satellites", 0.0, UINT8_MAX, 0},              /* xf_gnss.satellites */
        {"set_gnss.week", 0.0, INT16_MAX, 0},                    /* xf_gnss.week: no week before 1980 */
        {"set_gnss.ms_of_week", 0.0, 7.0 * 86400000.0 - 1.0, 0}, /* within one week */
        {"disconnect.ms", 0.0, 3600000.0, 0},                    /* an hour: a test's longest outage */
        {"set_main_camera.camera", 1.0, 2.0, 0},                 /* xf_client_set_main_camera() */
    };
    if (i >= sizeof(rows) / sizeof(rows[0])) {
        return 0;
    }
    *name = rows[i].name;
    *lo = rows[i].lo;
    *hi = rows[i].hi;
    *wraps = rows[i].wraps;
    return 1;
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
    struct timespec mono, wall; /* when it came: monitor --json's time_mono and time_utc */
} reply;

typedef struct xfpy_client {
    xf_client_config cfg;
    xf_link link;
    xf_hal hal;
    xf_client client;
    uint8_t last[XF_PACKET_MAX_LEN]; /* the last GCU packet (on_bytes), until its telemetry comes */
    size_t last_len;
    uint8_t sent[XF_PACKET_MAX_LEN]; /* the last packet the link accepted */
    size_t sent_len;
    uint8_t main_camera; /* whose zoom scales the rates: 1 or 2 */
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
    } else if (dir == XF_DIR_HOST && len <= sizeof(h->sent)) {
        memcpy(h->sent, data, len);
        h->sent_len = len;
    }
}

static void on_telemetry(void *user, const xf_telemetry *t)
{
    xfpy_client *h = (xfpy_client *)user;
    reply *r = &h->ring[h->replies % RING];
    memcpy(r->bytes, h->last, h->last_len);
    r->len = (uint8_t)h->last_len;
    (void)t; /* its packet is kept instead: the JSON of the two views comes from the bytes */
    clock_gettime(CLOCK_MONOTONIC, &r->mono);
    clock_gettime(CLOCK_REALTIME, &r->wall);
    h->replies++;
}

void *xfpy_client_new(void)
{
    xfpy_client *h = (xfpy_client *)calloc(1, sizeof(*h));
    if (h != NULL) {
        xf_client_config_init(&h->cfg);
        h->main_camera = 1u;
    }
    return h;
}

int xfpy_client_config(void *p, const char *name, long long v)
{
    return put_setting(0, &((xfpy_client *)p)->cfg, name, v);
}

long long xfpy_client_config_get(void *p, const char *name) { return get_setting(0, &((xfpy_client *)p)->cfg, name); }

const char *xfpy_client_config_problem(void *p) { return xf_client_config_problem(&((xfpy_client *)p)->cfg); }

int xfpy_client_open(void *p, const char *spec, char *msgs, size_t msgs_cap)
{
    xfpy_client *h = (xfpy_client *)p;
    xf_err err = xf_link_open(&h->link, spec);
    if (err != XF_OK) {
        return fail((int)err, msgs, msgs_cap, "%s",
                    h->link.error.text[0] != '\0' ? h->link.error.text : xf_strerror(err));
    }
    h->opened = 1;
    (void)xf_link_describe(&h->link, h->desc, sizeof(h->desc));
    err = xf_link_hal(&h->link, &h->hal);
    if (xf_link_keeps_order(&h->link.spec)) {
        h->cfg.reorder_fixed = 1; /* serial and TCP keep order: no need to judge the link first */
    }
    h->cfg.on_bytes = on_bytes;
    h->cfg.on_telemetry = on_telemetry;
    h->cfg.user = h;
    if (err == XF_OK) {
        err = xf_client_init(&h->client, &h->hal, &h->cfg);
    }
    if (err > XF_OK) { /* a warning: the client runs */
        text_err e;
        text_err_init(&e);
        text_note(&e, "rate_hz=%u: %s", (unsigned)h->cfg.rate_hz, xf_strerror(err));
        put_messages(&e, msgs, msgs_cap);
        return 0;
    }
    if (err != XF_OK) {
        return fail((int)err, msgs, msgs_cap, "%s: %s", h->desc, xf_strerror(err));
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

int xfpy_client_telemetry(void *p, uint32_t seq, int raw, char *out, size_t cap)
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
    pkt = jsonpkt_from_wire(r->bytes, r->len, XF_DIR_GCU, POD_READ_AUTO, raw ? TEXT_RAW : TEXT_ENGINEERING);
    obj = json_object();
    if (pkt == NULL || obj == NULL) {
        json_decref(pkt);
        json_decref(obj);
        return -1;
    }
    (void)jsonpkt_times(obj, &r->mono, &r->wall); /* first, as monitor --json has them */
    json_object_update(obj, pkt);
    json_decref(pkt);
    rc = dump_json(obj, out, cap);
    json_decref(obj);
    return rc;
}

/* xf_ctrl_status, as health's "control" says it */
static const char *const ctrl_names[] = {"sent", "not_set", "no_mode", "wrong_kind", "not_read", "command", "dropped"};

/* The version bytes as health says them: 0 (none yet) is null. */
static json_t *version_json(uint8_t v) { return (v != 0u) ? json_integer(v) : json_null(); }

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
    json_object_set_new(o, "version_sent", version_json(he->version_sent));
    json_object_set_new(o, "version_answered", version_json(he->version_answered));
    json_object_set_new(
        o, "version_gcu",
        version_json(xf_client_telemetry(&h->client)->have_main ? xf_client_gcu_version(&h->client) : 0u));
    json_object_set_new(o, "in_order", json_boolean(he->in_order != 0u));
    json_object_set_new(o, "out_of_turn", json_integer(he->out_of_turn));
    json_object_set_new(o, "reorder_ms", json_integer(he->reorder_ms));
    rc = dump_json(o, out, cap);
    json_decref(o);
    return rc;
}

int xfpy_client_last_sent(void *p, uint8_t *out, size_t cap)
{
    xfpy_client *h = (xfpy_client *)p;
    if (h->sent_len > cap) {
        return 0;
    }
    memcpy(out, h->sent, h->sent_len);
    return (int)h->sent_len;
}

double xfpy_client_rate_limit(void *p)
{
    xfpy_client *h = (xfpy_client *)p;
    const xf_telemetry *t = xf_client_telemetry(&h->client);
    float zoom = xf_zoom_x((h->main_camera == 2u) ? t->zoom_cam2 : t->zoom_cam1);
    zoom = (zoom >= 1.0f) ? zoom : 1.0f; /* as xf_ctrl_rate_raw() reads it */
    return (double)xf_ctrl_rate_raw(1e9f, zoom) / (10.0 * (double)zoom);
}

void xfpy_client_set_main_camera(void *p, int camera)
{
    xfpy_client *h = (xfpy_client *)p;
    h->main_camera = (camera == 2) ? 2u : 1u;
    xf_client_set_main_camera(&h->client, h->main_camera);
}

int xfpy_client_submit(void *p, const char *name, int n, const char *const *names, const char *const *values, int force,
                       uint32_t *id, char *msgs, size_t msgs_cap)
{
    xfpy_client *h = (xfpy_client *)p;
    uint8_t version = xf_client_gcu_version(&h->client);
    xf_field bad = XF_F_NONE;
    cmd_spec spec;
    xf_command cmd;
    text_err e;
    xf_err err;
    int rc = 0;
    text_err_init(&e);
    if (build_command(name, n, names, values, version, NULL, &spec, &cmd, &e) != TEXT_OK) {
        rc = 2;
    }
    if (rc == 0) {
        cmdargs_for_version(&cmd, version); /* as send does: the GCU's meaning */
        err = xf_client_submit_opt(&h->client, &cmd, force ? XF_SUBMIT_ANY_MODEL : 0u, id, &bad);
        if (err == XF_ERR_UNSUPPORTED) {
            char model[64];
            fieldtext_model(xf_client_telemetry(&h->client)->gimbal_code, model, sizeof(model));
            (void)text_fail(&e, NULL,
                            "%s: the GCU's model %s does not support it, by V2.0.6's support list; "
                            "send it with force=True all the same",
                            spec.name, model);
            rc = 1;
        } else if (err != XF_OK) {
            (void)text_fail(&e, NULL, "%s: %s%s%s", spec.name, xf_strerror(err), bad != XF_F_NONE ? ": " : "",
                            bad != XF_F_NONE ? xf_field_name(bad) : "");
            rc = 2;
        }
    }
    put_messages(&e, msgs, msgs_cap);
    return rc;
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

#define NOTES 16u /* the simulator's notes kept */

typedef struct xfpy_sim {
    xf_sim_config cfg;
    xf_simlink link;
    xf_sim sim;
    uint8_t fail[256];
    int opened;
    char spec[XF_LINK_SPEC_MAX + 1u];
    char notes[NOTES][200];
    uint32_t nnotes;
} xfpy_sim;

static void on_note(void *user, const xf_sim_note *n)
{
    xfpy_sim *h = (xfpy_sim *)user;
    const char *order = xf_order_name(n->order);
    (void)snprintf(h->notes[h->nnotes % NOTES], sizeof(h->notes[0]), "%s (0x%02X): %s; answered state 0x%02X",
                   order != NULL ? order : "unknown order", n->order, n->text, n->state);
    h->nnotes++;
}

void *xfpy_sim_new(void)
{
    xfpy_sim *h = (xfpy_sim *)calloc(1, sizeof(*h));
    if (h != NULL) {
        xf_sim_config_init(&h->cfg);
        h->cfg.on_note = on_note;
        h->cfg.user = h;
    }
    return h;
}

int xfpy_sim_config(void *p, const char *name, long long v) { return put_setting(1, &((xfpy_sim *)p)->cfg, name, v); }

long long xfpy_sim_config_get(void *p, const char *name) { return get_setting(1, &((xfpy_sim *)p)->cfg, name); }

int xfpy_sim_fault(void *p, const char *name, long long v)
{
    return put_setting(2, &((xfpy_sim *)p)->sim.fault, name, v);
}

long long xfpy_sim_fault_get(void *p, const char *name) { return get_setting(2, &((xfpy_sim *)p)->sim.fault, name); }

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

int xfpy_sim_open(void *p, const char *kind, const char *where, int port, char *msgs, size_t msgs_cap)
{
    xfpy_sim *h = (xfpy_sim *)p;
    xf_hal hal;
    int i;
    xf_err err = open_simlink(h, kind, where, port);
    if (err != XF_OK) {
        return fail((int)err, msgs, msgs_cap, "sim %s: %s", kind,
                    h->link.error.text[0] != '\0' ? h->link.error.text : xf_strerror(err));
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
    (void)xf_simlink_host_spec(&h->link, h->spec, sizeof(h->spec));
    if (err != XF_OK) {
        return fail((int)err, msgs, msgs_cap, "sim: %s", xf_strerror(err));
    }
    return 0;
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
    json_object_set_new(o, "ignored", json_integer(s->ignored));
    json_object_set_new(o, "strict", json_integer(s->strict));
    json_object_set_new(o, "write_errors", json_integer(s->write_errors));
    rc = dump_json(o, out, cap);
    json_decref(o);
    return rc;
}

int xfpy_sim_notes(void *p, char *out, size_t cap)
{
    xfpy_sim *h = (xfpy_sim *)p;
    json_t *a = json_array();
    uint32_t i = (h->nnotes > NOTES) ? h->nnotes - NOTES : 0u;
    int rc;
    if (a == NULL) {
        return -1;
    }
    for (; i < h->nnotes; i++) {
        json_array_append_new(a, json_string(h->notes[i % NOTES]));
    }
    rc = dump_json(a, out, cap);
    json_decref(a);
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
