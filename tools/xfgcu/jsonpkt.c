/*
 * jsonpkt.c - packet <-> JSON object (see jsonpkt.h for the keys).
 *
 * Both directions walk the same field rows (fields.h), so what decode
 * prints is exactly what encode reads back. Typed extras ("command",
 * "feedback") come from the codec's own decoders; on input they are only
 * used when "params" is absent, and a "command" that disagrees with the
 * "params" next to it is refused rather than silently dropped.
 */
#define _POSIX_C_SOURCE 200809L /* gmtime_r */

#include "jsonpkt.h"

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "fields.h"
#include "hexin.h"

/* ---- output ---------------------------------------------------------------- */

/* An object under construction; `failed` remembers an allocation failure. */
typedef struct builder {
    json_t *obj;
    int failed;
} builder;

static void put(builder *b, const char *key, json_t *value)
{
    if (value == NULL || json_object_set_new(b->obj, key, value) != 0) {
        b->failed = 1;
    }
}

static void put_hex(builder *b, const char *key, const uint8_t *bytes, size_t n)
{
    char text[3 * XF_PARAMS_MAX + 1];
    hex_format(bytes, n, '\0', text);
    put(b, key, json_string(text));
}

/* Typed parameters of a host packet's order, or why they do not decode. */
static void put_command(builder *b, uint8_t order, const uint8_t *params, size_t n, uint8_t version)
{
    const xf_order_info *info = xf_order_lookup(order);
    xf_field bad = XF_F_NONE;
    char why[128];
    xf_command cmd;
    xf_err err;
    size_t i;
    if (info == NULL || (info->nfields == 0u && n == 0u)) {
        return; /* unknown order, or nothing to show */
    }
    err = xf_command_decode(order, params, n, version, &cmd, &bad);
    if (err == XF_OK) {
        builder c = {json_object(), 0};
        if (c.obj == NULL) {
            b->failed = 1;
            return;
        }
        for (i = 0; i < info->nfields; i++) {
            xf_field f = (xf_field)info->fields[i];
            put(&c, xf_field_name(f), json_integer(xf_command_get(&cmd, f)));
        }
        b->failed |= c.failed;
        put(b, "command", c.obj);
        return;
    }
    if (err == XF_ERR_PARAMS) {
        snprintf(why, sizeof(why), "%s takes %zu parameter bytes, not %zu", xf_order_name(info->order),
                 xf_order_params_len(order), n);
    } else {
        snprintf(why, sizeof(why), "%s out of range", bad != XF_F_NONE ? xf_field_name(bad) : "a parameter");
    }
    put(b, "command_error", json_string(why));
}

static const char *result_name(xf_result result)
{
    switch (result) {
    case XF_RESULT_OK: return "ok";
    case XF_RESULT_OPERATING: return "operating";
    default: return "failed";
    }
}

static void put_feedback(builder *b, uint8_t order, const uint8_t *fb, size_t n)
{
    xf_feedback f;
    builder o;
    if (xf_feedback_decode(order, fb, n, &f) != XF_OK || !f.has_state) {
        return; /* no execution state in this reply */
    }
    o.obj = json_object();
    o.failed = 0;
    if (o.obj == NULL) {
        b->failed = 1;
        return;
    }
    put(&o, "result", json_string(result_name(f.result)));
    put(&o, "failed_cameras", json_integer(f.failed_cameras));
    b->failed |= o.failed;
    put(b, "feedback", o.obj);
}

/* A reserved block, as hex, when one of its bytes is not 0. */
static void put_reserved(builder *b, const uint8_t *buf, xf_direction dir, uint8_t version, const field_desc *f)
{
    size_t i, n, at = reserved_span(dir, f, version, &n);
    for (i = 0; i < n; i++) {
        if (buf[at + i] != 0u) {
            put_hex(b, f->name, buf + at, n);
            return;
        }
    }
}

/* The order pod_status is read in, and the names of its flags in that order. */
static void put_pod(builder *b, uint16_t raw, pod_reading how)
{
    xf_pod_order order = pod_order_for(raw, how);
    unsigned flags = xf_pod_flags(raw, order);
    json_t *names = json_array();
    size_t i;
    put(b, "pod_status_order", json_string(pod_order_name(order)));
    for (i = 0; names != NULL && pod_flag_names[i].name != NULL; i++) {
        if ((flags & pod_flag_names[i].mask) != 0u &&
            json_array_append_new(names, json_string(pod_flag_names[i].name)) != 0) {
            b->failed = 1;
        }
    }
    put(b, "pod_flags", names);
}

static void put_fields(builder *b, const uint8_t *buf, xf_direction dir, uint8_t version, pod_reading pod)
{
    size_t i, n;
    const field_desc *rows = fields_of(dir, &n);
    for (i = 0; i < n; i++) {
        const field_desc *f = &rows[i];
        long long v = field_get(buf, f);
        const char *name = NULL;
        if (f->unit == FU_RESERVED) {
            put_reserved(b, buf, dir, version, f);
            continue;
        }
        if (!field_present(f, version)) {
            continue;
        }
        put(b, f->name, json_integer(v));
        if (f->unit == FU_POD_STATUS) {
            put_pod(b, (uint16_t)v, pod);
        } else if (f->unit == FU_MODE && (name = xf_mode_name((uint8_t)v)) != NULL) {
            put(b, "mode_name", json_string(name));
        } else if (f->unit == FU_MODEL && (name = xf_gimbal_model((uint8_t)v)) != NULL) {
            put(b, "gimbal_model", json_string(name));
        }
    }
}

json_t *jsonpkt_from_wire(const uint8_t *buf, size_t len, xf_direction dir, pod_reading pod)
{
    uint8_t version, order;
    const uint8_t *params = buf + XF_OFF_PARAMS;
    size_t plen = len - XF_PACKET_MIN_LEN;
    const char *name;
    builder b;
    if (xf_packet_check(buf, len, dir) != XF_OK) {
        return NULL;
    }
    version = buf[XF_OFF_VERSION];
    order = buf[XF_OFF_ORDER];
    b.obj = json_object();
    b.failed = 0;
    if (b.obj == NULL) {
        return NULL;
    }
    put(&b, "direction", json_string(dir == XF_DIR_HOST ? "host" : "gcu"));
    put(&b, "version", json_integer(version));
    put(&b, "length", json_integer((json_int_t)len));
    put(&b, "order", json_integer(order));
    if ((name = xf_order_name(order)) != NULL) {
        put(&b, "order_name", json_string(name));
    }
    put_hex(&b, "params", params, plen);
    if (dir == XF_DIR_HOST) {
        put_command(&b, order, params, plen, version);
    } else {
        put_feedback(&b, order, params, plen);
    }
    put_fields(&b, buf, dir, version, pod);
    if (b.failed) {
        json_decref(b.obj);
        return NULL;
    }
    return b.obj;
}

int jsonpkt_print(const uint8_t *buf, size_t len, xf_direction dir, pod_reading pod, FILE *out)
{
    json_t *obj = jsonpkt_from_wire(buf, len, dir, pod);
    char *text = (obj != NULL) ? json_dumps(obj, JSON_COMPACT | JSON_PRESERVE_ORDER) : NULL;
    json_decref(obj);
    if (text == NULL) {
        return cli_fail("decode: out of memory");
    }
    fprintf(out, "%s\n", text);
    free(text);
    return XFGCU_EXIT_OK;
}

/* ---- input ----------------------------------------------------------------- */

typedef struct reader {
    const json_t *obj;
    const char *where;
    xf_direction dir;
    uint8_t version;
    uint8_t order;
    uint8_t params[XF_PARAMS_MAX];
    size_t params_len;
    int has_params;
} reader;

/* The times that monitor --json ("time_mono", "time_utc") and replay --json ("t", "time") put
 * on a packet are taken and ignored: what those commands print, encode reads back. */
static const char *const common_keys[] = {"direction", "version",  "length", "order", "order_name", "params",
                                          "time_mono", "time_utc", "t",      "time",  NULL};
static const char *const host_extra_keys[] = {"command", "command_error", NULL};
static const char *const gcu_extra_keys[] = {"feedback",  "mode_name",    "pod_status_order",
                                             "pod_flags", "gimbal_model", NULL};

static int in_list(const char *const *list, const char *key)
{
    for (; *list != NULL; list++) {
        if (strcmp(*list, key) == 0) {
            return 1;
        }
    }
    return 0;
}

static int check_keys(const reader *r)
{
    const char *key;
    json_t *value;
    const char *side = (r->dir == XF_DIR_HOST) ? "host" : "gcu";
    json_object_foreach((json_t *)r->obj, key, value)
    {
        const field_desc *f = field_find(r->dir, key);
        (void)value;
        if (f != NULL && !field_present(f, r->version)) {
            return cli_fail_in(
                r->where, "key '%s' needs version >= %u (in version %u these bytes are reserved: use reserved_sub)",
                key, (unsigned)f->since, (unsigned)r->version);
        }
        if (f == NULL && !in_list(common_keys, key) &&
            !in_list(r->dir == XF_DIR_HOST ? host_extra_keys : gcu_extra_keys, key)) {
            return cli_fail_in(r->where, "unknown key '%s' for a %s packet", key, side);
        }
    }
    return XFGCU_EXIT_OK;
}

/* An optional integer member in [lo, hi]; *present tells whether it was there. */
static int get_int(const reader *r, const json_t *obj, const char *prefix, const char *key, long long lo, long long hi,
                   long long *out, int *present)
{
    json_t *v = json_object_get(obj, key);
    *present = (v != NULL);
    if (v == NULL) {
        return XFGCU_EXIT_OK;
    }
    if (!json_is_integer(v)) {
        return cli_fail_in(r->where, "%s%s must be an integer in %lld..%lld", prefix, key, lo, hi);
    }
    *out = (long long)json_integer_value(v);
    if (*out < lo || *out > hi) {
        return cli_fail_in(r->where, "%s%s %lld is out of range %lld..%lld", prefix, key, *out, lo, hi);
    }
    return XFGCU_EXIT_OK;
}

/* A hex string member into @p out (at most @p cap bytes); *n gets its size. */
static int get_hex(const reader *r, const char *key, uint8_t *out, size_t cap, size_t *n, int *present)
{
    json_t *v = json_object_get(r->obj, key);
    hex_fault fault;
    char why[96];
    *present = (v != NULL);
    *n = 0;
    if (v == NULL) {
        return XFGCU_EXIT_OK;
    }
    if (!json_is_string(v)) {
        return cli_fail_in(r->where, "%s must be a string of hex bytes", key);
    }
    if (hex_parse_string(json_string_value(v), out, cap, n, &fault) != 0) {
        hex_fault_text(&fault, why, sizeof(why));
        return cli_fail_in(r->where, "%s, position %zu: %s", key, fault.offset + 1u, why);
    }
    if (*n > cap) {
        return cli_fail_in(r->where, "%s holds %zu bytes, at most %zu fit in a packet", key, *n, cap);
    }
    return XFGCU_EXIT_OK;
}

static int read_direction(reader *r)
{
    json_t *v = json_object_get(r->obj, "direction");
    const char *s = json_is_string(v) ? json_string_value(v) : NULL;
    if (v == NULL) {
        r->dir = XF_DIR_HOST;
    } else if (s != NULL && strcmp(s, "host") == 0) {
        r->dir = XF_DIR_HOST;
    } else if (s != NULL && strcmp(s, "gcu") == 0) {
        r->dir = XF_DIR_GCU;
    } else {
        return cli_fail_in(r->where, "direction must be \"host\" or \"gcu\"");
    }
    return XFGCU_EXIT_OK;
}

/* "order": a number or a canonical name; without it, "order_name"; else the null order. */
static int read_order(reader *r)
{
    json_t *v = json_object_get(r->obj, "order");
    if (v == NULL) {
        v = json_object_get(r->obj, "order_name");
    }
    if (v == NULL) {
        r->order = XF_ORDER_NULL;
        return XFGCU_EXIT_OK;
    }
    if (json_is_integer(v) && json_integer_value(v) >= 0 && json_integer_value(v) <= 255) {
        r->order = (uint8_t)json_integer_value(v);
        return XFGCU_EXIT_OK;
    }
    if (json_is_string(v) && xf_order_from_name(json_string_value(v), &r->order) == XF_OK) {
        return XFGCU_EXIT_OK;
    }
    return cli_fail_in(r->where, "order must be an integer 0..255 or the name of an order, like \"zoom_to\"");
}

/* The range of a member: what xf_command_set() saturates to, its type's. */
static void member_range(xf_field f, long long *lo, long long *hi)
{
    xf_command c;
    memset(&c, 0, sizeof(c));
    xf_command_set(&c, f, INT32_MIN);
    *lo = xf_command_get(&c, f);
    xf_command_set(&c, f, INT32_MAX);
    *hi = xf_command_get(&c, f);
}

static int command_member(const reader *r, const xf_order_info *info, const char *key, xf_field *f)
{
    char names[128] = "";
    size_t i;
    for (i = 0; i < info->nfields; i++) {
        if (strcmp(xf_field_name((xf_field)info->fields[i]), key) == 0) {
            *f = (xf_field)info->fields[i];
            return XFGCU_EXIT_OK;
        }
        strncat(names, i > 0u ? ", " : "", sizeof(names) - strlen(names) - 1u);
        strncat(names, xf_field_name((xf_field)info->fields[i]), sizeof(names) - strlen(names) - 1u);
    }
    return cli_fail_in(r->where, "command.%s is not a parameter of %s (%s)", key, xf_order_name(info->order),
                       info->nfields > 0u ? names : "it takes none");
}

/* Parameters from a "command" object: missing members take xf_command_init's defaults. */
static int params_from_command(const reader *r, const json_t *c, uint8_t *out, size_t *n)
{
    const xf_order_info *info = xf_order_lookup(r->order);
    const char *key;
    xf_field bad = XF_F_NONE;
    json_t *value;
    xf_command cmd;
    xf_err err;
    if (info == NULL) {
        return cli_fail_in(r->where, "command needs a known order; 0x%02X is not one (give params instead)", r->order);
    }
    if (!json_is_object(c)) {
        return cli_fail_in(r->where, "command must be an object of %s's parameters", xf_order_name(info->order));
    }
    xf_command_init(&cmd, r->order);
    json_object_foreach((json_t *)c, key, value)
    {
        xf_field f = XF_F_CAMERAS;
        long long v = 0, lo, hi;
        int present, rc = command_member(r, info, key, &f);
        (void)value;
        member_range(f, &lo, &hi);
        if (rc == XFGCU_EXIT_OK) {
            rc = get_int(r, c, "command.", key, lo, hi, &v, &present);
        }
        if (rc != XFGCU_EXIT_OK) {
            return rc;
        }
        xf_command_set(&cmd, f, (int32_t)v);
    }
    err = xf_command_encode(&cmd, r->version, out, XF_PARAMS_MAX, n, &bad);
    if (err != XF_OK) {
        return cli_fail_in(r->where, "command.%s is out of range for %s (protocol %u)",
                           bad != XF_F_NONE ? xf_field_name(bad) : "?", xf_order_name(info->order),
                           (unsigned)r->version);
    }
    return XFGCU_EXIT_OK;
}

/* Host: "command" builds the params when they are absent, and must agree with them when present. */
static int read_command(reader *r)
{
    const json_t *c = json_object_get(r->obj, "command");
    uint8_t bytes[XF_PARAMS_MAX];
    size_t n = 0;
    int rc;
    if (c == NULL) {
        return XFGCU_EXIT_OK;
    }
    rc = params_from_command(r, c, bytes, &n);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    if (!r->has_params) {
        memcpy(r->params, bytes, n);
        r->params_len = n;
        r->has_params = 1;
    } else if (n != r->params_len || memcmp(bytes, r->params, n) != 0) {
        return cli_fail_in(r->where, "command and params disagree; give only one of them");
    }
    return XFGCU_EXIT_OK;
}

/* GCU: "feedback" builds the state byte only when params are absent (it is derived from them). */
static int read_feedback(reader *r)
{
    const json_t *f = json_object_get(r->obj, "feedback");
    const json_t *res = json_object_get(f, "result");
    const char *s = json_is_string(res) ? json_string_value(res) : "";
    long long cams = 0;
    int present, rc;
    xf_result result;
    if (f == NULL || r->has_params) {
        return XFGCU_EXIT_OK;
    }
    if (strcmp(s, "ok") == 0) {
        result = XF_RESULT_OK;
    } else if (strcmp(s, "failed") == 0) {
        result = XF_RESULT_FAILED;
    } else if (strcmp(s, "operating") == 0) {
        result = XF_RESULT_OPERATING;
    } else {
        return cli_fail_in(r->where, "feedback.result must be \"ok\", \"failed\" or \"operating\"");
    }
    rc = get_int(r, f, "feedback.", "failed_cameras", 0, 255, &cams, &present);
    if (rc == XFGCU_EXIT_OK) {
        r->params[0] = xf_feedback_state(r->order, result, (uint8_t)cams);
        r->params_len = 1;
        r->has_params = 1;
    }
    return rc;
}

static int read_params(reader *r)
{
    long long length = 0;
    int present, rc = get_hex(r, "params", r->params, sizeof(r->params), &r->params_len, &r->has_params);
    if (rc == XFGCU_EXIT_OK) {
        rc = (r->dir == XF_DIR_HOST) ? read_command(r) : read_feedback(r);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = get_int(r, r->obj, "", "length", XF_PACKET_MIN_LEN, XF_PACKET_MAX_LEN, &length, &present);
    }
    if (rc == XFGCU_EXIT_OK && present && (size_t)length != XF_PACKET_MIN_LEN + r->params_len) {
        return cli_fail_in(r->where, "length %lld disagrees with %zu params bytes (the packet is %zu bytes)", length,
                           r->params_len, (size_t)XF_PACKET_MIN_LEN + r->params_len);
    }
    return rc;
}

/* The fields and reserved blocks into the packet's bytes @p out. */
static int read_fields(const reader *r, uint8_t *out)
{
    size_t i, n, len, at;
    const field_desc *rows = fields_of(r->dir, &n);
    for (i = 0; i < n; i++) {
        const field_desc *f = &rows[i];
        uint8_t bytes[RESERVED_MAX];
        long long v = 0, lo, hi;
        size_t got = 0;
        int present, rc;
        if (f->unit == FU_RESERVED) {
            at = reserved_span(r->dir, f, r->version, &len);
            rc = get_hex(r, f->name, bytes, sizeof(bytes), &got, &present);
            if (rc == XFGCU_EXIT_OK && present && got != len) {
                rc = cli_fail_in(r->where, "%s must hold %zu bytes for this packet, not %zu", f->name, len, got);
            } else if (rc == XFGCU_EXIT_OK && present) {
                memcpy(out + at, bytes, len);
            }
        } else if (field_present(f, r->version)) {
            field_range(f, &lo, &hi);
            rc = get_int(r, r->obj, "", f->name, lo, hi, &v, &present);
            field_set(out, f, v);
        } else {
            continue;
        }
        if (rc != XFGCU_EXIT_OK) {
            return rc;
        }
    }
    return XFGCU_EXIT_OK;
}

static int read_header(reader *r, uint8_t default_version)
{
    long long v = default_version;
    int present;
    int rc = read_direction(r);
    if (rc == XFGCU_EXIT_OK) {
        rc = get_int(r, r->obj, "", "version", 0, 255, &v, &present);
        r->version = (uint8_t)v;
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = check_keys(r);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = read_order(r);
    }
    return (rc == XFGCU_EXIT_OK) ? read_params(r) : rc;
}

/* The packet of a host or GCU packet struct: only the codec writes the header, length and CRC. */
static xf_err pack(xf_direction dir, const xf_host_packet *host, const xf_gcu_packet *gcu, uint8_t *out, size_t cap,
                   size_t *len)
{
    return (dir == XF_DIR_HOST) ? xf_host_pack(host, out, cap, len) : xf_gcu_pack(gcu, out, cap, len);
}

int jsonpkt_to_wire(const json_t *obj, uint8_t default_version, const char *where, uint8_t *out, size_t cap,
                    size_t *len)
{
    reader r;
    xf_host_packet host;
    xf_gcu_packet gcu;
    xf_frame frame;
    int rc;
    xf_err err;
    memset(&r, 0, sizeof(r));
    r.obj = obj;
    r.where = where;
    if (!json_is_object(obj)) {
        return cli_fail_in(r.where, "expected a JSON object");
    }
    rc = read_header(&r, default_version);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    /* The codec packs the header, order, params and CRC around frames of zeros (missing fields
     * are 0); the fields go into the frames; the codec reads the frames back (xf_frame_* skip the
     * CRC, stale now) and packs them again. */
    memset(&host, 0, sizeof(host));
    memset(&gcu, 0, sizeof(gcu));
    host.version = gcu.version = r.version;
    host.order = gcu.order = r.order;
    host.params_len = gcu.params_len = (uint8_t)r.params_len;
    memcpy(host.params, r.params, r.params_len);
    memcpy(gcu.params, r.params, r.params_len);
    err = pack(r.dir, &host, &gcu, out, cap, len);
    if (err == XF_OK) {
        rc = read_fields(&r, out);
        if (rc != XFGCU_EXIT_OK) {
            return rc;
        }
        frame.data = out;
        frame.len = *len;
        err = (r.dir == XF_DIR_HOST) ? xf_frame_host(&frame, &host) : xf_frame_gcu(&frame, &gcu);
    }
    if (err == XF_OK) {
        err = pack(r.dir, &host, &gcu, out, cap, len);
    }
    return (err == XF_OK) ? XFGCU_EXIT_OK : cli_fail_in(r.where, "cannot build the packet: %s", xf_strerror(err));
}

/* ---- times ------------------------------------------------------------------------ */

void jsonpkt_utc_text(int64_t ms, char *buf, size_t cap)
{
    time_t sec = (time_t)(ms / 1000);
    struct tm tm;
    char date[32];
    if (gmtime_r(&sec, &tm) == NULL || strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%S", &tm) == 0u) {
        snprintf(buf, cap, "?");
        return;
    }
    snprintf(buf, cap, "%s.%03dZ", date, (int)(ms % 1000));
}

int64_t jsonpkt_ms(const struct timespec *wall) { return (int64_t)wall->tv_sec * 1000 + wall->tv_nsec / 1000000L; }

json_t *jsonpkt_times(json_t *obj, const struct timespec *mono, const struct timespec *wall)
{
    char text[40];
    if (obj != NULL) {
        jsonpkt_utc_text(jsonpkt_ms(wall), text, sizeof(text));
        json_object_set_new(obj, "time_mono", json_real((double)mono->tv_sec + (double)mono->tv_nsec / 1e9));
        json_object_set_new(obj, "time_utc", json_string(text));
    }
    return obj;
}
