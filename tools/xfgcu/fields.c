/*
 * fields.c - the field rows of fields.h and typed access to them.
 *
 * A row names the codec's offset macro: HOST(ROLL_CTRL, ...) is at
 * XF_OFF_HOST_ROLL_CTRL and called "roll_ctrl", and it ends where the next
 * row starts (the last one at the order byte). Values are read and written
 * with the codec's little-endian accessors (xf_bytes.h).
 */
#include "fields.h"

#include <ctype.h>
#include <string.h>

typedef struct row_spec {
    const char *name; /* the codec's offset name, upper case */
    unsigned offset;
    uint8_t is_signed, unit, since;
} row_spec;

/* One row a line, as the spec's tables read. */
/* clang-format off */
#define S 1 /* signed */
#define U 0 /* unsigned */
#define HOST(name, sign, unit)     {#name, XF_OFF_HOST_##name, sign, unit, 1}
#define GCU(name, sign, unit, ver) {#name, XF_OFF_GCU_##name, sign, unit, ver}

static const row_spec host_rows[] = {
    HOST(ROLL_CTRL, S, FU_CTRL),
    HOST(PITCH_CTRL, S, FU_CTRL),
    HOST(YAW_CTRL, S, FU_CTRL),
    HOST(STATUS, U, FU_HOST_STATUS),
    HOST(CARRIER_ROLL, S, FU_CDEG),
    HOST(CARRIER_PITCH, S, FU_CDEG),
    HOST(CARRIER_YAW, U, FU_CDEG),
    HOST(ACCEL_NORTH, S, FU_ACCEL),
    HOST(ACCEL_EAST, S, FU_ACCEL),
    HOST(ACCEL_UP, S, FU_ACCEL),
    HOST(VEL_NORTH, S, FU_VEL),
    HOST(VEL_EAST, S, FU_VEL),
    HOST(VEL_UP, S, FU_VEL),
    HOST(SUB_REQUEST, U, FU_BYTE_HEX),
    HOST(RESERVED_MAIN, U, FU_RESERVED),
    HOST(SUB_HEADER, U, FU_BYTE_HEX),
    HOST(LONGITUDE, S, FU_DEG7),
    HOST(LATITUDE, S, FU_DEG7),
    HOST(ALTITUDE, S, FU_MM),
    HOST(SATELLITES, U, FU_RAW),
    HOST(GNSS_MS, U, FU_GNSS_MS),
    HOST(GNSS_WEEK, S, FU_GNSS_WEEK),
    HOST(RELATIVE_HEIGHT, S, FU_MM),
    HOST(RESERVED_SUB, U, FU_RESERVED),
};

static const row_spec gcu_rows[] = {
    GCU(GIMBAL_MODE, U, FU_MODE, 1),
    GCU(POD_STATUS, U, FU_POD_STATUS, 1),
    GCU(TARGET_OFFSET_X, S, FU_RAW, 1),
    GCU(TARGET_OFFSET_Y, S, FU_RAW, 1),
    GCU(REL_ANGLE_X, S, FU_CDEG, 1),
    GCU(REL_ANGLE_Y, S, FU_CDEG, 1),
    GCU(REL_ANGLE_Z, S, FU_CDEG, 1),
    GCU(CAM_ROLL, S, FU_CDEG, 1),
    GCU(CAM_PITCH, S, FU_CDEG, 1),
    GCU(CAM_YAW, U, FU_CDEG, 1),
    GCU(RATE_X, S, FU_GCU_RATE, 1),
    GCU(RATE_Y, S, FU_GCU_RATE, 1),
    GCU(RATE_Z, S, FU_GCU_RATE, 1),
    GCU(RESERVED_MAIN, U, FU_RESERVED, 1),
    GCU(SUB_HEADER, U, FU_BYTE_HEX, 1),
    GCU(HW_VERSION, U, FU_RAW, 1),
    GCU(FW_VERSION, U, FU_RAW, 1),
    GCU(GIMBAL_CODE, U, FU_MODEL, 1),
    GCU(ERROR_CODE, U, FU_ERROR_CODE, 1),
    GCU(TARGET_DISTANCE, S, FU_DISTANCE, 1),
    GCU(TARGET_LONGITUDE, S, FU_DEG7, 1),
    GCU(TARGET_LATITUDE, S, FU_DEG7, 1),
    GCU(TARGET_ALTITUDE, S, FU_MM, 1),
    GCU(ZOOM_CAM1, U, FU_ZOOM, 1),
    GCU(ZOOM_CAM2, U, FU_ZOOM, 1),
    GCU(THERMAL_STATUS, U, FU_THERMAL, 2),
    GCU(CAMERA_STATUS, U, FU_CAMERA, 2),
    GCU(TIME_ZONE, S, FU_HOURS, 2),
    GCU(RESERVED_SUB, U, FU_RESERVED, 1),
};
/* clang-format on */

#define N_HOST (sizeof(host_rows) / sizeof(host_rows[0]))
#define N_GCU  (sizeof(gcu_rows) / sizeof(gcu_rows[0]))

static void build(const row_spec *spec, size_t n, field_desc *rows)
{
    size_t i, k;
    for (i = 0; i < n; i++) {
        unsigned end = (i + 1u < n) ? spec[i + 1u].offset : XF_OFF_ORDER;
        for (k = 0; spec[i].name[k] != '\0' && k + 1u < sizeof(rows[i].name); k++) {
            rows[i].name[k] = (char)tolower((unsigned char)spec[i].name[k]);
        }
        rows[i].name[k] = '\0';
        rows[i].offset = (uint8_t)spec[i].offset;
        rows[i].size = (uint8_t)(end - spec[i].offset);
        rows[i].is_signed = spec[i].is_signed;
        rows[i].unit = spec[i].unit;
        rows[i].since = spec[i].since;
    }
}

const field_desc *fields_of(xf_direction dir, size_t *count)
{
    static field_desc host[N_HOST], gcu[N_GCU];
    static int built = 0;
    if (!built) {
        build(host_rows, N_HOST, host);
        build(gcu_rows, N_GCU, gcu);
        built = 1;
    }
    *count = (dir == XF_DIR_HOST) ? N_HOST : N_GCU;
    return (dir == XF_DIR_HOST) ? host : gcu;
}

const field_desc *field_find(xf_direction dir, const char *name)
{
    size_t i, n;
    const field_desc *rows = fields_of(dir, &n);
    for (i = 0; i < n; i++) {
        if (strcmp(rows[i].name, name) == 0) {
            return &rows[i];
        }
    }
    return NULL;
}

int field_present(const field_desc *f, uint8_t version)
{
    uint8_t v = (version == 0u) ? 1u : version;
    return v >= f->since;
}

long long field_get(const uint8_t *pkt, const field_desc *f)
{
    const uint8_t *p = pkt + f->offset;
    switch (f->size) {
    case 1u: return f->is_signed ? (long long)xf_u8_to_s8(p[0]) : (long long)p[0];
    case 2u: return f->is_signed ? (long long)xf_get_s16le(p) : (long long)xf_get_u16le(p);
    default: return f->is_signed ? (long long)xf_get_s32le(p) : (long long)xf_get_u32le(p);
    }
}

void field_set(uint8_t *pkt, const field_desc *f, long long v)
{
    uint8_t *p = pkt + f->offset;
    switch (f->size) {
    case 1u: p[0] = (uint8_t)v; break;
    case 2u: xf_put_u16le(p, (uint16_t)v); break;
    default: xf_put_u32le(p, (uint32_t)v); break;
    }
}

void field_range(const field_desc *f, long long *lo, long long *hi)
{
    long long span = 1LL << (8u * f->size); /* 2^bits */
    *lo = f->is_signed ? -span / 2 : 0;
    *hi = f->is_signed ? span / 2 - 1 : span - 1;
}

size_t reserved_span(xf_direction dir, const field_desc *f, uint8_t version, size_t *len)
{
    size_t n;
    const field_desc *first = fields_of(dir, &n);
    const field_desc *start = f;
    while (start > first && !field_present(start - 1, version)) {
        start--;
    }
    *len = (size_t)(f->offset + f->size - start->offset);
    return start->offset;
}

/* ---- pod status ------------------------------------------------------------- */

const flag_name pod_flag_names[] = {{XF_POD_TRACKING_OK, "tracking_ok"},
                                    {XF_POD_TARGET_VALID, "target_valid"},
                                    {XF_POD_RANGING_ON, "ranging_on"},
                                    {XF_POD_NIGHT_VISION_ON, "night_vision_on"},
                                    {XF_POD_LIGHTING_ON, "lighting_on"},
                                    {XF_POD_UPWARD_MOUNT, "upward_mount"},
                                    {0, NULL}};

xf_pod_order pod_order_for(uint16_t pod_status, pod_reading how)
{
    switch (how) {
    case POD_READ_LE: return XF_POD_ORDER_LE;
    case POD_READ_BE: return XF_POD_ORDER_BE;
    default:
        /* the word does not tell: the order both documents state */
        return (xf_pod_status_order(pod_status) == XF_POD_ORDER_BE) ? XF_POD_ORDER_BE : XF_POD_ORDER_LE;
    }
}

const char *pod_order_name(xf_pod_order order) { return (order == XF_POD_ORDER_BE) ? "be" : "le"; }
