/*
 * jsonpkt.c - packet <-> JSON object (see jsonpkt.h for the keys).
 *
 * Both directions walk the rows of the codec's field table (xfgcu/xf_fields.h), so what decode
 * prints is exactly what encode reads back, in either view. Typed extras ("command",
 * "feedback") come from the codec's own decoders; on input they are only used when "params" is
 * absent, and a "command" that disagrees with the "params" next to it is refused rather than
 * silently dropped.
 */
#define _POSIX_C_SOURCE 200809L /* gmtime_r */

#include "jsonpkt.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hexin.h"
#include "warn.h"

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

json_t *jsonpkt_value(const xf_wire_field *f, int64_t raw, uint8_t version, text_view view)
{
    if (view == TEXT_ENGINEERING && xf_wire_field_decimals(f, version) > 0u) {
        return json_real(xf_wire_field_value(f, raw, version));
    }
    return json_integer((json_int_t)raw);
}

/* Typed parameters of a host packet's order, or why they do not decode. */
static void put_command(builder *b, uint8_t order, const uint8_t *params, size_t n, uint8_t version, text_view view)
{
    const xf_order_info *info = xf_order_lookup(order);
    xf_field bad = XF_F_NONE;
    char why[160];
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
            put(&c, xf_field_name(f), jsonpkt_value(xf_wire_param(f), xf_command_get(&cmd, f), version, view));
        }
        b->failed |= c.failed;
        put(b, "command", c.obj);
        return;
    }
    if (warn_params(order, params, n, version, why, sizeof(why))) {
        put(b, "command_error", json_string(why));
    }
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
static void put_reserved(builder *b, const uint8_t *buf, uint8_t version, const xf_wire_field *f)
{
    size_t i, n, at = reserved_span(f, version, &n);
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
    const xf_wire_field *row = pod_row();
    xf_pod_order order = pod_order_for(raw, how);
    unsigned flags = xf_pod_flags(raw, order);
    json_t *names = json_array();
    size_t i;
    put(b, "pod_status_order", json_string(pod_order_name(order)));
    for (i = 0; names != NULL && i < row->nbits; i++) {
        if ((flags & row->bits[i].mask) != 0u && json_array_append_new(names, json_string(row->bits[i].name)) != 0) {
            b->failed = 1;
        }
    }
    put(b, "pod_flags", names);
}

/* The extras after a field: the names of codes, the pod status word's flags. */
static void put_extras(builder *b, const xf_wire_field *f, int64_t v, pod_reading pod)
{
    const char *name = (f->value_name != NULL) ? f->value_name((uint8_t)v) : NULL;
    if (f == pod_row()) {
        put_pod(b, (uint16_t)v, pod);
    } else if (name != NULL && strcmp(f->name, "gimbal_mode") == 0) {
        put(b, "mode_name", json_string(name));
    } else if (name != NULL && strcmp(f->name, "gimbal_code") == 0) {
        put(b, "gimbal_model", json_string(name));
    }
}

static void put_fields(builder *b, const uint8_t *buf, xf_direction dir, uint8_t version, pod_reading pod,
                       text_view view)
{
    size_t i, n;
    const xf_wire_field *rows = xf_wire_fields(xf_wire_frames(dir), &n);
    for (i = 0; i < n; i++) {
        const xf_wire_field *f = &rows[i];
        int64_t v;
        if (f->kind == XF_WIRE_RESERVED) {
            put_reserved(b, buf, version, f);
            continue;
        }
        if (!xf_wire_field_present(f, version)) {
            continue;
        }
        v = xf_wire_field_get(f, buf);
        put(b, f->name, jsonpkt_value(f, v, version, view));
        put_extras(b, f, v, pod);
    }
}

/* What the vendor's text does not allow (warn.h), when there is any: "warnings", a list of lines. */
static void put_warnings(builder *b, const uint8_t *buf, size_t len, xf_direction dir)
{
    warn_list w;
    json_t *list;
    size_t i;
    if (warn_packet(buf, len, dir, &w) == 0u) {
        return;
    }
    list = json_array();
    for (i = 0; list != NULL && i < w.n; i++) {
        if (json_array_append_new(list, json_string(w.text[i])) != 0) {
            b->failed = 1;
        }
    }
    if (list != NULL && w.more > 0u && json_array_append_new(list, json_sprintf("%zu more", w.more)) != 0) {
        b->failed = 1;
    }
    put(b, "warnings", list);
}

json_t *jsonpkt_from_wire(const uint8_t *buf, size_t len, xf_direction dir, pod_reading pod, text_view view)
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
        put_command(&b, order, params, plen, version, view);
    } else {
        put_feedback(&b, order, params, plen);
    }
    put_fields(&b, buf, dir, version, pod, view);
    put_warnings(&b, buf, len, dir);
    if (b.failed) {
        json_decref(b.obj);
        return NULL;
    }
    return b.obj;
}

char *jsonpkt_dumps(const json_t *obj)
{
    /* 15 significant digits: the decimal of every engineering value (at most 10 digits) without
     * a double's binary tail (0.29, not 0.28999999999999998), which reads back to it exactly */
    return (obj != NULL) ? json_dumps(obj, JSON_COMPACT | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(15)) : NULL;
}

json_t *jsonpkt_parse(const char *text, size_t len, const char *where, text_err *e)
{
    json_error_t error;
    const char *nul = memchr(text, '\0', len);
    json_t *v;
    if (nul != NULL) {
        text_fail(e, where, "NUL byte at column %zu (the JSON text must not hold one)", (size_t)(nul - text) + 1u);
        return NULL;
    }
    v = json_loadb(text, len, JSON_REJECT_DUPLICATES, &error);
    if (v == NULL) {
        text_fail(e, where, "invalid JSON at column %d: %s", error.column, error.text);
    }
    return v;
}

/* ---- input ----------------------------------------------------------------- */

typedef struct reader {
    json_t *obj; /* not changed: jansson's key iteration takes a non-const object */
    const char *where;
    text_err *err;
    text_view view;
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
                                          "time_mono", "time_utc", "t",      "time",  "warnings",   NULL};
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
    json_object_foreach(r->obj, key, value)
    {
        const xf_wire_field *f = xf_wire_field_find(xf_wire_frames(r->dir), key);
        (void)value;
        if (f != NULL && !xf_wire_field_present(f, r->version)) {
            return text_fail(r->err, r->where,
                             "key '%s' needs version >= %u (in version %u these bytes are reserved: use reserved_sub)",
                             key, (unsigned)f->since, (unsigned)r->version);
        }
        if (f == NULL && !in_list(common_keys, key) &&
            !in_list(r->dir == XF_DIR_HOST ? host_extra_keys : gcu_extra_keys, key)) {
            return text_fail(r->err, r->where, "unknown key '%s' for a %s packet", key, side);
        }
    }
    return TEXT_OK;
}

/* An optional integer member in [lo, hi]; *present tells whether it was there. */
static int get_int(const reader *r, const json_t *obj, const char *prefix, const char *key, long long lo, long long hi,
                   long long *out, int *present)
{
    json_t *v = json_object_get(obj, key);
    *present = (v != NULL);
    if (v == NULL) {
        return TEXT_OK;
    }
    if (!json_is_integer(v)) {
        return text_fail(r->err, r->where, "%s%s must be an integer in %lld..%lld", prefix, key, lo, hi);
    }
    *out = (long long)json_integer_value(v);
    if (*out < lo || *out > hi) {
        return text_fail(r->err, r->where, "%s%s %lld is out of range %lld..%lld", prefix, key, *out, lo, hi);
    }
    return TEXT_OK;
}

/* An optional field's value in the reader's view: its wire integer into *out. */
static int get_field(const reader *r, const json_t *obj, const char *prefix, const xf_wire_field *f, int64_t *out,
                     int *present)
{
    json_t *v = json_object_get(obj, f->name);
    unsigned d = (r->view == TEXT_RAW) ? 0u : xf_wire_field_decimals(f, r->version);
    int64_t lo, hi;
    long long i = 0;
    xf_err err;
    xf_wire_field_range(f, &lo, &hi);
    if (d == 0u) { /* a wire integer */
        int rc = get_int(r, obj, prefix, f->name, (long long)lo, (long long)hi, &i, present);
        *out = (int64_t)i;
        return rc;
    }
    *present = (v != NULL);
    if (v == NULL) {
        return TEXT_OK;
    }
    err = json_is_number(v) ? xf_wire_field_raw(f, json_number_value(v), r->version, out) : XF_ERR_ARG;
    if (err == XF_OK) {
        return TEXT_OK;
    }
    if (!json_is_number(v)) {
        return text_fail(r->err, r->where, "%s%s must be a number (%s), %.*f..%.*f", prefix, f->name, f->unit, (int)d,
                         xf_wire_field_value(f, lo, r->version), (int)d, xf_wire_field_value(f, hi, r->version));
    }
    if (err == XF_ERR_RANGE) {
        return text_fail(r->err, r->where, "%s%s %.15g is out of range %.*f..%.*f %s", prefix, f->name,
                         json_number_value(v), (int)d, xf_wire_field_value(f, lo, r->version), (int)d,
                         xf_wire_field_value(f, hi, r->version), f->unit);
    }
    return text_fail(r->err, r->where, "%s%s %.15g is not a whole number of steps of %.*f %s (the wire's resolution)",
                     prefix, f->name, json_number_value(v), (int)d, xf_wire_field_value(f, 1, r->version), f->unit);
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
        return TEXT_OK;
    }
    if (!json_is_string(v)) {
        return text_fail(r->err, r->where, "%s must be a string of hex bytes", key);
    }
    if (hex_parse_string(json_string_value(v), out, cap, n, &fault) != 0) {
        hex_fault_text(&fault, why, sizeof(why));
        return text_fail(r->err, r->where, "%s, position %zu: %s", key, fault.offset + 1u, why);
    }
    if (*n > cap) {
        return text_fail(r->err, r->where, "%s holds %zu bytes, at most %zu fit in a packet", key, *n, cap);
    }
    return TEXT_OK;
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
        return text_fail(r->err, r->where, "direction must be \"host\" or \"gcu\"");
    }
    return TEXT_OK;
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
        return TEXT_OK;
    }
    if (json_is_integer(v) && json_integer_value(v) >= 0 && json_integer_value(v) <= 255) {
        r->order = (uint8_t)json_integer_value(v);
        return TEXT_OK;
    }
    if (json_is_string(v) && xf_order_from_name(json_string_value(v), &r->order) == XF_OK) {
        return TEXT_OK;
    }
    return text_fail(r->err, r->where, "order must be an integer 0..255 or the name of an order, like \"zoom_to\"");
}

static int command_member(const reader *r, const xf_order_info *info, const char *key, xf_field *f)
{
    char names[128] = "";
    size_t i;
    for (i = 0; i < info->nfields; i++) {
        if (strcmp(xf_field_name((xf_field)info->fields[i]), key) == 0) {
            *f = (xf_field)info->fields[i];
            return TEXT_OK;
        }
        strncat(names, i > 0u ? ", " : "", sizeof(names) - strlen(names) - 1u);
        strncat(names, xf_field_name((xf_field)info->fields[i]), sizeof(names) - strlen(names) - 1u);
    }
    return text_fail(r->err, r->where, "command.%s is not a parameter of %s (%s)", key, xf_order_name(info->order),
                     info->nfields > 0u ? names : "it takes none");
}

/* Parameters from a "command" object: missing members take xf_command_init's defaults. */
static int params_from_command(const reader *r, json_t *c, uint8_t *out, size_t *n)
{
    const xf_order_info *info = xf_order_lookup(r->order);
    const char *key;
    xf_field bad = XF_F_NONE;
    json_t *value;
    xf_command cmd;
    xf_err err;
    if (info == NULL) {
        return text_fail(r->err, r->where, "command needs a known order; 0x%02X is not one (give params instead)",
                         r->order);
    }
    if (!json_is_object(c)) {
        return text_fail(r->err, r->where, "command must be an object of %s's parameters", xf_order_name(info->order));
    }
    xf_command_init(&cmd, r->order);
    json_object_foreach(c, key, value)
    {
        xf_field f = XF_F_CAMERAS;
        int64_t v = 0;
        int present, rc = command_member(r, info, key, &f);
        (void)value;
        if (rc == TEXT_OK) {
            rc = get_field(r, c, "command.", xf_wire_param(f), &v, &present);
        }
        if (rc != TEXT_OK) {
            return rc;
        }
        xf_command_set(&cmd, f, (int32_t)v);
    }
    err = xf_command_encode(&cmd, r->version, out, XF_PARAMS_MAX, n, &bad);
    if (err != XF_OK) {
        return text_fail(r->err, r->where, "command.%s is out of range for %s (protocol %u)",
                         bad != XF_F_NONE ? xf_field_name(bad) : "?", xf_order_name(info->order), (unsigned)r->version);
    }
    return TEXT_OK;
}

/* Host: "command" builds the params when they are absent, and must agree with them when present. */
static int read_command(reader *r)
{
    json_t *c = json_object_get(r->obj, "command");
    uint8_t bytes[XF_PARAMS_MAX];
    size_t n = 0;
    int rc;
    if (c == NULL) {
        return TEXT_OK;
    }
    rc = params_from_command(r, c, bytes, &n);
    if (rc != TEXT_OK) {
        return rc;
    }
    if (!r->has_params) {
        memcpy(r->params, bytes, n);
        r->params_len = n;
        r->has_params = 1;
    } else if (n != r->params_len || memcmp(bytes, r->params, n) != 0) {
        return text_fail(r->err, r->where, "command and params disagree; give only one of them");
    }
    return TEXT_OK;
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
        return TEXT_OK;
    }
    if (strcmp(s, "ok") == 0) {
        result = XF_RESULT_OK;
    } else if (strcmp(s, "failed") == 0) {
        result = XF_RESULT_FAILED;
    } else if (strcmp(s, "operating") == 0) {
        result = XF_RESULT_OPERATING;
    } else {
        return text_fail(r->err, r->where, "feedback.result must be \"ok\", \"failed\" or \"operating\"");
    }
    rc = get_int(r, f, "feedback.", "failed_cameras", 0, 255, &cams, &present);
    if (rc == TEXT_OK) {
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
    if (rc == TEXT_OK) {
        rc = (r->dir == XF_DIR_HOST) ? read_command(r) : read_feedback(r);
    }
    if (rc == TEXT_OK) {
        rc = get_int(r, r->obj, "", "length", XF_PACKET_MIN_LEN, XF_PACKET_MAX_LEN, &length, &present);
    }
    if (rc == TEXT_OK && present && (size_t)length != XF_PACKET_MIN_LEN + r->params_len) {
        return text_fail(r->err, r->where, "length %lld disagrees with %zu params bytes (the packet is %zu bytes)",
                         length, r->params_len, (size_t)XF_PACKET_MIN_LEN + r->params_len);
    }
    return rc;
}

/* A reserved block's hex, when given, into the packet's bytes @p out. */
static int read_reserved(const reader *r, const xf_wire_field *f, uint8_t *out)
{
    uint8_t bytes[RESERVED_MAX];
    size_t got = 0, len, at = reserved_span(f, r->version, &len);
    int present, rc = get_hex(r, f->name, bytes, sizeof(bytes), &got, &present);
    if (rc == TEXT_OK && present && got != len) {
        return text_fail(r->err, r->where, "%s must hold %zu bytes for this packet, not %zu", f->name, len, got);
    }
    if (rc == TEXT_OK && present) {
        memcpy(out + at, bytes, len);
    }
    return rc;
}

/* The fields and reserved blocks into the packet's bytes @p out. */
static int read_fields(const reader *r, uint8_t *out)
{
    size_t i, n;
    const xf_wire_field *rows = xf_wire_fields(xf_wire_frames(r->dir), &n);
    for (i = 0; i < n; i++) {
        const xf_wire_field *f = &rows[i];
        int64_t v = 0;
        int present, rc = TEXT_OK;
        if (f->kind == XF_WIRE_RESERVED) {
            rc = read_reserved(r, f, out);
        } else if (xf_wire_field_present(f, r->version)) {
            rc = get_field(r, r->obj, "", f, &v, &present);
            xf_wire_field_put(f, out, v);
        }
        if (rc != TEXT_OK) {
            return rc;
        }
    }
    return TEXT_OK;
}

static int read_header(reader *r, uint8_t default_version)
{
    long long v = default_version;
    int present;
    int rc = read_direction(r);
    if (rc == TEXT_OK) {
        rc = get_int(r, r->obj, "", "version", 0, 255, &v, &present);
        r->version = (uint8_t)v;
    }
    if (rc == TEXT_OK) {
        rc = check_keys(r);
    }
    if (rc == TEXT_OK) {
        rc = read_order(r);
    }
    return (rc == TEXT_OK) ? read_params(r) : rc;
}

/* The packet of a host or GCU packet struct: only the codec writes the header, length and CRC. */
static xf_err pack(xf_direction dir, const xf_host_packet *host, const xf_gcu_packet *gcu, uint8_t *out, size_t cap,
                   size_t *len)
{
    return (dir == XF_DIR_HOST) ? xf_host_pack(host, out, cap, len) : xf_gcu_pack(gcu, out, cap, len);
}

int jsonpkt_to_wire(json_t *obj, uint8_t default_version, text_view view, const char *where, uint8_t *out, size_t cap,
                    size_t *len, text_err *e)
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
    r.err = e;
    r.view = view;
    if (!json_is_object(obj)) {
        return text_fail(e, where, "expected a JSON object");
    }
    rc = read_header(&r, default_version);
    if (rc != TEXT_OK) {
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
        if (rc != TEXT_OK) {
            return rc;
        }
        frame.data = out;
        frame.len = *len;
        err = (r.dir == XF_DIR_HOST) ? xf_frame_host(&frame, &host) : xf_frame_gcu(&frame, &gcu);
    }
    if (err == XF_OK) {
        err = pack(r.dir, &host, &gcu, out, cap, len);
    }
    return (err == XF_OK) ? TEXT_OK : text_fail(e, where, "cannot build the packet: %s", xf_strerror(err));
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
