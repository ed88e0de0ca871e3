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

#include "fields.h"
#include "hexin.h"

static const flag_name host_status_bits[] = {
    {XF_STATUS_INS_VALID, "ins_valid"}, {XF_STATUS_CTRL_VALID, "ctrl_valid"}, {0, NULL}};
static const flag_name error_bits[] = {{XF_ERROR_POD_HW_FAULT, "pod_hw_fault"},
                                       {XF_ERROR_MAVLINK_RATE, "mavlink_rate_abnormal"},
                                       {XF_ERROR_GNSS_NOT_FIXED, "gnss_not_positioned"},
                                       {XF_ERROR_GCU_HW_FAULT, "gcu_hw_fault"},
                                       {0, NULL}};
static const flag_name thermal_bits[] = {{XF_THERMAL_LOW_TEMP_ALARM, "low_temp_alarm"},
                                         {XF_THERMAL_HIGH_TEMP_ALARM, "high_temp_alarm"},
                                         {XF_THERMAL_SPOT_ON, "spot_temp_on"},
                                         {XF_THERMAL_ISOTHERM_ON, "isotherm_on"},
                                         {XF_THERMAL_ALARM_ON, "temp_alarm_on"},
                                         {XF_THERMAL_AREA_ON, "area_temp_on"},
                                         {XF_THERMAL_MEASURE_AVAILABLE, "temp_measurement_available"},
                                         {0, NULL}};
static const flag_name camera_bits[] = {{XF_CAMERA_RECORDING, "recording"},
                                        {XF_CAMERA_AUTO_FLIP_OFF, "auto_flip_off"},
                                        {XF_CAMERA_OSD_TARGET, "osd_shows_target"},
                                        {XF_CAMERA_OSD_ON, "osd_on"},
                                        {XF_CAMERA_DIGITAL_ZOOM_ON, "digital_zoom_on"},
                                        {XF_CAMERA_DETECTION_ON, "target_detection_on"},
                                        {0, NULL}};

static void append(char *buf, size_t cap, const char *s)
{
    size_t n = strlen(buf);
    if (n + 1u < cap) {
        snprintf(buf + n, cap - n, "%s%s", n > 0u ? " " : "", s);
    }
}

/* Names of the set bits; bits without a name are shown as a mask. */
static void bits_text(unsigned v, unsigned ignore, const flag_name *names, char *buf, size_t cap)
{
    unsigned known = ignore;
    char rest[32];
    for (; names->name != NULL; names++) {
        known |= names->mask;
        if ((v & names->mask) != 0u) {
            append(buf, cap, names->name);
        }
    }
    if ((v & ~known) != 0u) {
        snprintf(rest, sizeof(rest), "reserved bits 0x%X", v & ~known);
        append(buf, cap, rest);
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
    bits_text(xf_pod_flags(raw, order), 0, pod_flag_names, buf, cap);
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

static void named(const char *name, const char *unknown, char *buf, size_t cap)
{
    snprintf(buf, cap, "%s", name != NULL ? name : unknown);
}

static void physical(const field_desc *f, long long raw, const uint8_t *pkt, uint8_t version, pod_reading pod,
                     char *buf, size_t cap)
{
    double r = (double)raw;
    buf[0] = '\0';
    switch ((field_unit)f->unit) {
    case FU_CTRL:
        snprintf(buf, cap, "%.2f deg (angle modes) or %.1f deg/s / zoom (rate modes)", r / 100.0, r / 10.0);
        break;
    case FU_CDEG: snprintf(buf, cap, "%.2f deg", r / 100.0); break;
    case FU_ACCEL: snprintf(buf, cap, "%.2f m/s^2", r / 100.0); break;
    case FU_VEL: snprintf(buf, cap, "%.2f m/s", r / 100.0); break;
    case FU_DEG7: snprintf(buf, cap, "%.7f deg", r / 1e7); break;
    case FU_MM: snprintf(buf, cap, "%.3f m", r / 1000.0); break;
    case FU_DISTANCE:
        if (raw <= 0) {
            snprintf(buf, cap, "no valid measurement");
        } else {
            snprintf(buf, cap, "%.1f m", r / 10.0);
        }
        break;
    case FU_ZOOM: snprintf(buf, cap, "%.1fx", r / 10.0); break;
    case FU_GCU_RATE:
        snprintf(buf, cap, version >= XF_PROTOCOL_V2 ? "%.1f deg/s" : "%.2f deg/s",
                 (double)xf_gcu_rate_dps((int16_t)raw, version));
        break;
    case FU_GNSS_MS: snprintf(buf, cap, "%.3f s into the week", r / 1000.0); break;
    case FU_GNSS_WEEK: gnss_text(pkt, raw, buf, cap); break;
    case FU_HOURS: snprintf(buf, cap, "UTC%+lld", raw); break;
    case FU_MODE: named(xf_mode_name((uint8_t)raw), "unknown mode", buf, cap); break;
    case FU_MODEL: named(xf_gimbal_model((uint8_t)raw), "unknown model", buf, cap); break;
    case FU_HOST_STATUS: bits_text((unsigned)raw, 0, host_status_bits, buf, cap); break;
    case FU_POD_STATUS: pod_text((uint16_t)raw, pod, buf, cap); break;
    case FU_ERROR_CODE:
        if (version >= XF_PROTOCOL_V2) {
            bits_text((unsigned)raw, 0, error_bits, buf, cap);
        } else if (raw != 0) {
            snprintf(buf, cap, "reserved in V0.1");
        }
        break;
    case FU_THERMAL: bits_text((unsigned)raw, 0, thermal_bits, buf, cap); break;
    case FU_CAMERA:
        snprintf(buf, cap, "pip_mode %u", (unsigned)(raw & XF_CAMERA_PIP_MASK));
        bits_text((unsigned)raw, XF_CAMERA_PIP_MASK, camera_bits, buf, cap);
        break;
    default: break;
    }
}

static void raw_text(const field_desc *f, long long raw, char *buf, size_t cap)
{
    int hex = f->unit == FU_BYTE_HEX || f->unit == FU_HOST_STATUS || f->unit == FU_POD_STATUS ||
              f->unit == FU_ERROR_CODE || f->unit == FU_THERMAL || f->unit == FU_CAMERA || f->unit == FU_MODE;
    if (hex) {
        snprintf(buf, cap, (f->size == 2u) ? "0x%04llX" : "0x%02llX", raw);
    } else {
        snprintf(buf, cap, "%lld", raw);
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

/* One parameter of a host command, with its unit where it has one. */
static void member_text(xf_field f, int32_t v, char *buf, size_t cap)
{
    const char *name = xf_field_name(f);
    switch (f) {
    case XF_F_CAMERAS: snprintf(buf, cap, "%s=0x%02X", name, (unsigned)v); break;
    case XF_F_LONGITUDE:
    case XF_F_LATITUDE: snprintf(buf, cap, "%s=%.7f deg", name, (double)v / 1e7); break;
    case XF_F_ALTITUDE: snprintf(buf, cap, "%s=%.3f m", name, (double)v / 1000.0); break;
    case XF_F_TEMP_HIGH:
    case XF_F_TEMP_LOW: snprintf(buf, cap, "%s=%.1f C", name, (double)v / 10.0); break;
    case XF_F_ZOOM:
        snprintf(buf, cap, v < 0 ? "%s=%ld (%.1fx)" : "%s=%ld (%.2f%% of the range)", name, (long)v,
                 v < 0 ? -(double)v / 10.0 : (double)v / 100.0);
        break;
    default: snprintf(buf, cap, "%s=%ld", name, (long)v); break;
    }
}

static void command_text(uint8_t order, const uint8_t *params, size_t n, uint8_t version, char *buf, size_t cap)
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
        member_text((xf_field)info->fields[i], xf_command_get(&cmd, (xf_field)info->fields[i]), item, sizeof(item));
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

static void print_head(const uint8_t *buf, size_t len, xf_direction dir, const char *where, FILE *out)
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
        command_text(order, params, n, version, text, sizeof(text));
    } else {
        feedback_text(order, params, n, text, sizeof(text));
    }
    row(out, "params", n > 0u ? hex : "(none)", text);
}

static void print_reserved(const uint8_t *pkt, xf_direction dir, uint8_t version, const field_desc *f, FILE *out)
{
    char hex[3 * RESERVED_MAX + 1], count[32];
    size_t i, n, at = reserved_span(dir, f, version, &n);
    for (i = 0; i < n; i++) {
        if (pkt[at + i] != 0u) {
            hex_format(pkt + at, n, ' ', hex);
            snprintf(count, sizeof(count), "%zu bytes", n);
            row(out, f->name, count, hex);
            return;
        }
    }
}

void table_print(const uint8_t *buf, size_t len, xf_direction dir, const char *where, pod_reading pod, FILE *out)
{
    uint8_t version = buf[XF_OFF_VERSION];
    size_t i, n;
    const field_desc *rows = fields_of(dir, &n);
    print_head(buf, len, dir, where, out);
    for (i = 0; i < n; i++) {
        char raw[24], value[160];
        long long v = field_get(buf, &rows[i]);
        if (rows[i].unit == FU_RESERVED) {
            print_reserved(buf, dir, version, &rows[i], out);
        } else if (field_present(&rows[i], version)) {
            raw_text(&rows[i], v, raw, sizeof(raw));
            physical(&rows[i], v, buf, version, pod, value, sizeof(value));
            row(out, rows[i].name, raw, value);
        }
    }
}
