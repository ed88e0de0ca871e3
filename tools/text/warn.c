/*
 * warn.c - what the vendor's text does not allow in a packet that decodes (warn.h).
 *
 * The ranges are the vendor's (V2.0.4 and V2.0.6 field tables, docs/protocol.md §3 and §5); the
 * codec's field table gives each field's place, sign and scale, so a rule names the field and
 * its range and nothing else.
 */
#include "warn.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* A field's range by the vendor's text, as wire integers, and as the message writes it. */
typedef struct range_rule {
    xf_wire_group group;
    const char *field;
    int64_t lo, hi;
    const char *range; /* "[0, 360) deg" */
} range_rule;

static const range_rule ranges[] = {
    {XF_WIRE_HOST, "carrier_roll", -18000, 18000, "[-180, 180] deg"},
    {XF_WIRE_HOST, "carrier_pitch", -9000, 9000, "[-90, 90] deg"},
    {XF_WIRE_HOST, "carrier_yaw", 0, 35999, "[0, 360) deg"},
    {XF_WIRE_HOST, "longitude", -1800000000, 1800000000, "[-180, 180] deg"},
    {XF_WIRE_HOST, "latitude", -900000000, 900000000, "[-90, 90] deg"},
    {XF_WIRE_HOST, "gnss_ms", 0, 604799999, "a week of milliseconds, [0, 604800000)"},
    {XF_WIRE_GCU, "target_offset_x", -1000, 1000, "[-1000, 1000]"},
    {XF_WIRE_GCU, "target_offset_y", -1000, 1000, "[-1000, 1000]"},
    {XF_WIRE_GCU, "rel_angle_x", -18000, 18000, "[-180, 180] deg"},
    {XF_WIRE_GCU, "rel_angle_y", -18000, 18000, "[-180, 180] deg"},
    {XF_WIRE_GCU, "rel_angle_z", -18000, 18000, "[-180, 180] deg"},
    {XF_WIRE_GCU, "cam_roll", -18000, 18000, "[-180, 180] deg"},
    {XF_WIRE_GCU, "cam_pitch", -18000, 18000, "[-180, 180] deg"},
    {XF_WIRE_GCU, "cam_yaw", 0, 35999, "[0, 360) deg"},
    {XF_WIRE_GCU, "target_longitude", -1800000000, 1800000000, "[-180, 180] deg"},
    {XF_WIRE_GCU, "target_latitude", -900000000, 900000000, "[-90, 90] deg"},
};

static void add(warn_list *w, const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void add(warn_list *w, const char *fmt, ...)
{
    va_list ap;
    if (w->n == WARN_MAX) {
        w->more++;
        return;
    }
    va_start(ap, fmt);
    vsnprintf(w->text[w->n++], WARN_TEXT, fmt, ap);
    va_end(ap);
}

/* A field's value as "54537 (545.37 deg)", or the integer alone for a field without a scale. */
static void value_text(const xf_wire_field *f, int64_t raw, uint8_t version, char *buf, size_t cap)
{
    unsigned d = xf_wire_field_decimals(f, version);
    if (d == 0u) {
        snprintf(buf, cap, "%lld", (long long)raw);
    } else {
        snprintf(buf, cap, "%lld (%.*f%s%s)", (long long)raw, (int)d, xf_wire_field_value(f, raw, version),
                 f->unit[0] != '\0' ? " " : "", f->unit);
    }
}

/* A heading of -180..180 deg written into the U16 yaw field as a signed value (a host in the field
 * does) reads as 360..655.35 deg, which a GCU takes modulo 360: say what it stands for. */
static void yaw_hint(const char *field, int64_t raw, char *buf, size_t cap)
{
    int64_t meant = raw - 65536; /* the signed value */
    buf[0] = '\0';
    if (strcmp(field, "carrier_yaw") == 0 && raw >= 36000 && meant >= -18000) {
        snprintf(buf, cap,
                 "; as a signed value it is %.2f deg: a heading of -180..180 deg in the U16 field, which a GCU "
                 "takes for %.2f deg",
                 (double)meant / 100.0, (double)(raw % 36000) / 100.0);
    }
}

static void check_ranges(const uint8_t *buf, xf_direction dir, uint8_t version, warn_list *w)
{
    size_t i;
    for (i = 0; i < sizeof(ranges) / sizeof(ranges[0]); i++) {
        const xf_wire_field *f = xf_wire_field_find(ranges[i].group, ranges[i].field);
        char value[64], hint[160];
        int64_t v;
        if (ranges[i].group != xf_wire_frames(dir) || f == NULL) {
            continue;
        }
        v = xf_wire_field_get(f, buf);
        if (v < ranges[i].lo || v > ranges[i].hi) {
            value_text(f, v, version, value, sizeof(value));
            yaw_hint(f->name, v, hint, sizeof(hint));
            add(w, "%s %s is outside the vendor's range %s%s", f->name, value, ranges[i].range, hint);
        }
    }
}

/* Valid control quantities beyond an angle's range (a rate's, ±1500, is narrower, but the packet
 * does not say which one the gimbal's mode reads: docs/protocol.md §11.1). */
static void check_control(const uint8_t *buf, warn_list *w)
{
    static const char *const names[] = {"roll_ctrl", "pitch_ctrl", "yaw_ctrl"};
    size_t i;
    if ((buf[XF_OFF_HOST_STATUS] & XF_STATUS_CTRL_VALID) == 0u) {
        return;
    }
    for (i = 0; i < 3u; i++) {
        const xf_wire_field *f = xf_wire_field_find(XF_WIRE_HOST, names[i]);
        int64_t v = xf_wire_field_get(f, buf);
        if (v < -18000 || v > 18000) {
            add(w,
                "%s %lld is valid but outside [-18000, 18000], the range of an angle (0.01 deg; a rate's is "
                "[-1500, 1500])",
                names[i], (long long)v);
        }
    }
}

/* ins_valid with an all-zero attitude: invented data (V2.0.4: wrong carrier data spoils the
 * gimbal's attitude); a host without INS data sends zeros with ins_valid clear. */
static void check_ins(const uint8_t *buf, warn_list *w)
{
    if ((buf[XF_OFF_HOST_STATUS] & XF_STATUS_INS_VALID) != 0u && xf_get_u16le(buf + XF_OFF_HOST_CARRIER_ROLL) == 0u &&
        xf_get_u16le(buf + XF_OFF_HOST_CARRIER_PITCH) == 0u && xf_get_u16le(buf + XF_OFF_HOST_CARRIER_YAW) == 0u) {
        add(w, "ins_valid is set with carrier_roll, carrier_pitch and carrier_yaw all 0: invented INS data spoils the "
               "gimbal's attitude; without an INS, send zeros with ins_valid clear");
    }
}

int warn_params(uint8_t order, const uint8_t *params, size_t n, uint8_t version, char *buf, size_t cap)
{
    xf_field bad = XF_F_NONE;
    xf_command cmd;
    xf_err err;
    if (xf_order_lookup(order) == NULL) {
        return 0;
    }
    err = xf_command_decode(order, params, n, version, &cmd, &bad);
    if (err == XF_OK) {
        return 0;
    }
    if (err == XF_ERR_PARAMS) {
        snprintf(buf, cap, "%s takes %zu parameter bytes, not %zu", xf_order_name(order), xf_order_params_len(order),
                 n);
    } else {
        snprintf(buf, cap, "%s out of range", bad != XF_F_NONE ? xf_field_name(bad) : "a parameter");
    }
    return 1;
}

/* The order and its parameters: one the protocol does not define, or parameters it does not take
 * (record's 0x00 is a known host's "stop", where the vendor has a toggle with the fixed 0x01). */
static void check_params(const uint8_t *buf, size_t len, uint8_t version, warn_list *w)
{
    uint8_t order = buf[XF_OFF_ORDER];
    size_t n = len - XF_PACKET_MIN_LEN;
    char why[128];
    if (xf_order_lookup(order) == NULL) {
        add(w, "order 0x%02X is not an order of the protocol (V0.1 or V0.2)", order);
    } else if (order == XF_ORDER_RECORD && n == 1u && buf[XF_OFF_PARAMS] == 0u) {
        add(w, "record with parameter 0x00: the vendor's record is a start/stop toggle with the fixed parameter 0x01; "
               "a host that means stop by 0x00 gets what the GCU makes of it (docs/protocol.md section 12)");
    } else if (warn_params(order, buf + XF_OFF_PARAMS, n, version, why, sizeof(why))) {
        add(w, "parameters the order does not take: %s", why);
    }
}

/* A reply's execution state: one byte, and none for the null order (V2.0.6). */
static void check_feedback(const uint8_t *buf, size_t len, warn_list *w)
{
    size_t n = len - XF_PACKET_MIN_LEN;
    if (n > 1u) {
        add(w, "an execution state is one byte; this reply has %zu after the order", n);
    } else if (n == 1u && buf[XF_OFF_ORDER] == XF_ORDER_NULL) {
        add(w, "a reply to the null order with an execution state (0x%02X): V2.0.6 gives the null none (72 bytes)",
            buf[XF_OFF_PARAMS]);
    }
}

size_t warn_packet(const uint8_t *buf, size_t len, xf_direction dir, warn_list *w)
{
    uint8_t version = buf[XF_OFF_VERSION];
    memset(w, 0, sizeof(*w));
    if (version != XF_PROTOCOL_V1 && version != XF_PROTOCOL_V2) {
        add(w, "version %u: the vendor defines 1 (V0.1) and 2 (V0.2)", version);
    }
    if (dir == XF_DIR_HOST) {
        check_control(buf, w);
        check_ins(buf, w);
    }
    check_ranges(buf, dir, version, w);
    if (dir == XF_DIR_HOST) {
        check_params(buf, len, version, w);
    } else {
        check_feedback(buf, len, w);
    }
    return w->n + w->more;
}
