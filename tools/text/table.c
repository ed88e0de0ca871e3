/*
 * table.c - the readable table of decode.
 *
 * Units follow docs/protocol.md; the GCU's angular rates depend on the
 * packet's version (0.01 deg/s in V0.1, 0.1 deg/s in V0.2), and the host's
 * control quantities on the gimbal's mode, which the packet does not say:
 * both readings are shown.
 */
#define _POSIX_C_SOURCE 200809L /* gmtime_r */

#include "table.h"

#include <string.h>
#include <time.h>

#include "fieldtext.h"
#include "hexin.h"
#include "warn.h"

static void append(char *buf, size_t cap, const char *s)
{
    size_t n = strlen(buf);
    if (n + 1u < cap) {
        snprintf(buf + n, cap - n, "%s%s", n > 0u ? " " : "", s);
    }
}

/* The named bits of a flag word @p f that are set (a number of several bits: "pip_mode 2"); bits
 * without a name are shown as a mask. */
static void bits_text(unsigned v, const xf_wire_field *f, char *buf, size_t cap)
{
    unsigned known = 0;
    size_t i;
    char item[48];
    for (i = 0; i < f->nbits; i++) {
        unsigned mask = f->bits[i].mask, shift = 0;
        known |= mask;
        while (((mask >> shift) & 1u) == 0u) {
            shift++;
        }
        if ((mask >> shift) != 1u) { /* several bits: a number */
            snprintf(item, sizeof(item), "%s %u", f->bits[i].name, (v & mask) >> shift);
            append(buf, cap, item);
        } else if ((v & mask) != 0u) {
            append(buf, cap, f->bits[i].name);
        }
    }
    if ((v & ~known) != 0u) {
        snprintf(item, sizeof(item), "reserved bits 0x%X", v & ~known);
        append(buf, cap, item);
    }
}

static void gnss_text(const uint8_t *pkt, long long week, char *buf, size_t cap)
{
    uint32_t gnss_ms = xf_get_u32le(pkt + XF_OFF_HOST_GNSS_MS);
    int64_t unix_ms;
    time_t t;
    struct tm tm;
    char when[32];
    if (week == 0 && gnss_ms == 0u) {
        snprintf(buf, cap, "not set");
        return;
    }
    if (xf_gnss_to_unix_ms((int16_t)week, gnss_ms, XF_LEAP_SECONDS_2017, &unix_ms) != XF_OK) {
        snprintf(buf, cap, "not a valid GNSS time");
        return;
    }
    t = (time_t)(unix_ms / 1000);
    if (gmtime_r(&t, &tm) == NULL || strftime(when, sizeof(when), "%Y-%m-%d %H:%M:%S", &tm) == 0u) {
        snprintf(buf, cap, "not a valid GNSS time");
        return;
    }
    snprintf(buf, cap, "%s.%03d UTC (with gnss_ms, %d leap seconds)", when, (int)(unix_ms % 1000),
             XF_LEAP_SECONDS_2017);
}

/* The flags of pod_status in the order it is read in, and which order that is when it is not
 * plainly the documented one (docs/protocol.md §11.7). */
static void pod_text(uint16_t raw, pod_reading how, char *buf, size_t cap)
{
    xf_pod_order order = pod_order_for(raw, how);
    xf_pod_order evidence = xf_pod_status_order(raw);
    bits_text(xf_pod_flags(raw, order), pod_row(), buf, cap);
    if (how != POD_READ_AUTO) {
        append(buf, cap,
               order == XF_POD_ORDER_BE ? "(read big-endian: --pod-order)" : "(read little-endian: --pod-order)");
    } else if (order == XF_POD_ORDER_BE) {
        append(buf, cap, "(read big-endian: little-endian sets reserved bits)");
    } else if (evidence == XF_POD_ORDER_UNDECIDED && xf_pod_flags(raw, XF_POD_ORDER_BE) != raw) {
        append(buf, cap,
               (raw & XF_POD_RESERVED_MASK) != 0u ? "(read little-endian: both orders set reserved bits)"
                                                  : "(read little-endian: big-endian would fit too)");
    }
}

/* What the packet alone cannot turn into one value: a control quantity's two readings, the GNSS
 * time, the time zone; 1 when @p f is one of them. */
static int special_text(const xf_wire_field *f, int64_t raw, const uint8_t *pkt, char *buf, size_t cap)
{
    double r = (double)raw;
    if (f->kind == XF_WIRE_CONTEXT) {
        snprintf(buf, cap, "%.2f deg (angle modes) or %.1f deg/s / zoom (rate modes)", r / 100.0, r / 10.0);
    } else if (strcmp(f->name, "gnss_ms") == 0) {
        snprintf(buf, cap, "%.3f s into the week", r / 1000.0);
    } else if (strcmp(f->name, "gnss_week") == 0) {
        gnss_text(pkt, raw, buf, cap);
    } else if (strcmp(f->name, "time_zone") == 0) {
        snprintf(buf, cap, "UTC%+lld", (long long)raw);
    } else {
        return 0;
    }
    return 1;
}

/* The value column: the engineering value (not in TEXT_RAW), the name of a code, the flags set. */
static void physical(const xf_wire_field *f, int64_t raw, const uint8_t *pkt, uint8_t version, pod_reading pod,
                     text_view view, char *buf, size_t cap)
{
    const char *name = (f->value_name != NULL) ? f->value_name((uint8_t)raw) : NULL;
    buf[0] = '\0';
    if (f->kind == XF_WIRE_ENUM) {
        snprintf(buf, cap, "%s",
                 name != NULL                         ? name
                 : (f->value_name == xf_gimbal_model) ? "unknown model"
                                                      : "unknown mode");
    } else if (f == pod_row()) {
        pod_text((uint16_t)raw, pod, buf, cap);
    } else if (f->kind == XF_WIRE_FLAGS && strcmp(f->name, "error_code") == 0 && version < XF_PROTOCOL_V2) {
        snprintf(buf, cap, "%s", raw != 0 ? "reserved in V0.1" : "");
    } else if (f->kind == XF_WIRE_FLAGS) {
        bits_text((unsigned)raw, f, buf, cap);
    } else if (view == TEXT_RAW || special_text(f, raw, pkt, buf, cap)) {
        return;
    } else if (f->kind == XF_WIRE_NUMBER && (xf_wire_field_decimals(f, version) > 0u || f->unit[0] != '\0')) {
        fieldtext_value(f, raw, version, view, buf, cap);
    }
}

static void raw_text(const xf_wire_field *f, int64_t raw, char *buf, size_t cap)
{
    if (fieldtext_hex(f)) {
        snprintf(buf, cap, (f->width == 2u) ? "0x%04llX" : "0x%02llX", (long long)raw);
    } else {
        snprintf(buf, cap, "%lld", (long long)raw);
    }
}

static void row(FILE *out, const char *name, const char *raw, const char *value)
{
    if (value[0] == '\0') {
        fprintf(out, "  %-17s %s\n", name, raw);
    } else {
        fprintf(out, "  %-17s %-12s %s\n", name, raw, value);
    }
}

void table_member_text(xf_field f, int32_t v, uint8_t version, text_view view, char *buf, size_t cap)
{
    const xf_wire_field *member = xf_wire_param(f);
    char value[64];
    if (f == XF_F_CAMERAS) {
        snprintf(buf, cap, "%s=0x%02X", member->name, (unsigned)v);
    } else if (f == XF_F_ZOOM && view != TEXT_RAW) {
        snprintf(buf, cap, v < 0 ? "%s=%ld (%.1fx)" : "%s=%ld (%.2f%% of the range)", member->name, (long)v,
                 v < 0 ? -(double)v / 10.0 : (double)v / 100.0);
    } else {
        fieldtext_value(member, v, version, view, value, sizeof(value));
        snprintf(buf, cap, "%s=%s", member->name, value);
    }
}

static void command_text(uint8_t order, const uint8_t *params, size_t n, uint8_t version, text_view view, char *buf,
                         size_t cap)
{
    const xf_order_info *info = xf_order_lookup(order);
    xf_field bad = XF_F_NONE;
    xf_command cmd;
    size_t i;
    xf_err err;
    buf[0] = '\0';
    if (info == NULL) {
        return;
    }
    err = xf_command_decode(order, params, n, version, &cmd, &bad);
    if (err == XF_ERR_PARAMS) {
        snprintf(buf, cap, "(%s takes %zu bytes)", xf_order_name(info->order), xf_order_params_len(order));
    } else if (err != XF_OK) {
        snprintf(buf, cap, "(%s out of range)", bad != XF_F_NONE ? xf_field_name(bad) : "a parameter");
    }
    for (i = 0; err == XF_OK && i < info->nfields; i++) {
        char item[64];
        table_member_text((xf_field)info->fields[i], xf_command_get(&cmd, (xf_field)info->fields[i]), version, view,
                          item, sizeof(item));
        append(buf, cap, item);
    }
}

static void feedback_text(uint8_t order, const uint8_t *fb, size_t n, char *buf, size_t cap)
{
    xf_feedback f;
    if (xf_feedback_decode(order, fb, n, &f) != XF_OK || !f.has_state) {
        snprintf(buf, cap, "no execution state");
    } else if (f.result == XF_RESULT_OK) {
        snprintf(buf, cap, "feedback: ok");
    } else if (f.result == XF_RESULT_OPERATING) {
        snprintf(buf, cap, "feedback: operating");
    } else if (f.failed_cameras != 0u) {
        snprintf(buf, cap, "feedback: failed, cameras 0x%02X", f.failed_cameras);
    } else {
        snprintf(buf, cap, "feedback: failed");
    }
}

static void print_head(const uint8_t *buf, size_t len, xf_direction dir, const char *where, text_view view, FILE *out)
{
    uint8_t order = buf[XF_OFF_ORDER], version = buf[XF_OFF_VERSION];
    const uint8_t *params = buf + XF_OFF_PARAMS;
    size_t n = len - XF_PACKET_MIN_LEN;
    const char *name = xf_order_name(order);
    char hex[3 * XF_PARAMS_MAX + 1], text[256], raw[8];
    fprintf(out, "%s packet (%s): %zu bytes, version %u, CRC 0x%02X%02X\n", dir == XF_DIR_HOST ? "host" : "gcu", where,
            len, (unsigned)version, buf[len - 2u], buf[len - 1u]);
    row(out, "field", "raw", "value");
    snprintf(raw, sizeof(raw), "0x%02X", order);
    row(out, "order", raw, name != NULL ? name : "unknown order");
    hex_format(params, n, ' ', hex);
    if (dir == XF_DIR_HOST) {
        command_text(order, params, n, version, view, text, sizeof(text));
    } else {
        feedback_text(order, params, n, text, sizeof(text));
    }
    row(out, "params", n > 0u ? hex : "(none)", text);
}

static void print_reserved(const uint8_t *pkt, uint8_t version, const xf_wire_field *f, FILE *out)
{
    char hex[3 * RESERVED_MAX + 1], count[32];
    size_t i, n, at = reserved_span(f, version, &n);
    for (i = 0; i < n; i++) {
        if (pkt[at + i] != 0u) {
            hex_format(pkt + at, n, ' ', hex);
            snprintf(count, sizeof(count), "%zu bytes", n);
            row(out, f->name, count, hex);
            return;
        }
    }
}

/* What the vendor's text does not allow (warn.h): one line each, after the rows. */
static void print_warnings(const uint8_t *buf, size_t len, xf_direction dir, FILE *out)
{
    warn_list w;
    size_t i;
    (void)warn_packet(buf, len, dir, &w);
    for (i = 0; i < w.n; i++) {
        fprintf(out, "warning: %s\n", w.text[i]);
    }
    if (w.more > 0u) {
        fprintf(out, "warning: %zu more\n", w.more);
    }
}

void table_print(const uint8_t *buf, size_t len, xf_direction dir, const char *where, pod_reading pod, text_view view,
                 FILE *out)
{
    uint8_t version = buf[XF_OFF_VERSION];
    size_t i, n;
    const xf_wire_field *rows = xf_wire_fields(xf_wire_frames(dir), &n);
    print_head(buf, len, dir, where, view, out);
    for (i = 0; i < n; i++) {
        char raw[24], value[160];
        if (rows[i].kind == XF_WIRE_RESERVED) {
            print_reserved(buf, version, &rows[i], out);
        } else if (xf_wire_field_present(&rows[i], version)) {
            int64_t v = xf_wire_field_get(&rows[i], buf);
            raw_text(&rows[i], v, raw, sizeof(raw));
            physical(&rows[i], v, buf, version, pod, view, value, sizeof(value));
            row(out, rows[i].name, raw, value);
        }
    }
    print_warnings(buf, len, dir, out);
}
