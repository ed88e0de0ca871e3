/*
 * fields.c - the field rows of fields.h and typed access to them.
 *
 * Members are reached through offsetof() and memcpy() rather than casts,
 * so the access is free of alignment and aliasing assumptions.
 */
#include "fields.h"

#include <string.h>

#define HOST(m) offsetof(xf_host_packet, m)
#define GCU(m)  offsetof(xf_gcu_packet, m)

static const field_desc host_fields[] = {
    {"roll_ctrl", HOST(main.roll_ctrl), FT_S16, FU_CTRL, 0, 1},
    {"pitch_ctrl", HOST(main.pitch_ctrl), FT_S16, FU_CTRL, 0, 1},
    {"yaw_ctrl", HOST(main.yaw_ctrl), FT_S16, FU_CTRL, 0, 1},
    {"status", HOST(main.status), FT_U8, FU_HOST_STATUS, 0, 1},
    {"carrier_roll", HOST(main.carrier_roll), FT_S16, FU_CDEG, 0, 1},
    {"carrier_pitch", HOST(main.carrier_pitch), FT_S16, FU_CDEG, 0, 1},
    {"carrier_yaw", HOST(main.carrier_yaw), FT_U16, FU_CDEG, 0, 1},
    {"accel_north", HOST(main.accel_north), FT_S16, FU_ACCEL, 0, 1},
    {"accel_east", HOST(main.accel_east), FT_S16, FU_ACCEL, 0, 1},
    {"accel_up", HOST(main.accel_up), FT_S16, FU_ACCEL, 0, 1},
    {"vel_north", HOST(main.vel_north), FT_S16, FU_VEL, 0, 1},
    {"vel_east", HOST(main.vel_east), FT_S16, FU_VEL, 0, 1},
    {"vel_up", HOST(main.vel_up), FT_S16, FU_VEL, 0, 1},
    {"sub_request", HOST(main.sub_request), FT_U8, FU_BYTE_HEX, 0, 1},
    {"sub_header", HOST(sub.sub_header), FT_U8, FU_BYTE_HEX, 1, 1},
    {"longitude", HOST(sub.longitude), FT_S32, FU_DEG7, 1, 1},
    {"latitude", HOST(sub.latitude), FT_S32, FU_DEG7, 1, 1},
    {"altitude", HOST(sub.altitude), FT_S32, FU_MM, 1, 1},
    {"satellites", HOST(sub.satellites), FT_U8, FU_RAW, 1, 1},
    {"gnss_ms", HOST(sub.gnss_ms), FT_U32, FU_GNSS_MS, 1, 1},
    {"gnss_week", HOST(sub.gnss_week), FT_S16, FU_GNSS_WEEK, 1, 1},
    {"relative_height", HOST(sub.relative_height), FT_S32, FU_MM, 1, 1},
};

static const field_desc gcu_fields[] = {
    {"gimbal_mode", GCU(main.gimbal_mode), FT_U8, FU_MODE, 0, 1},
    {"pod_status", GCU(main.pod_status), FT_U16, FU_POD_STATUS, 0, 1},
    {"target_offset_x", GCU(main.target_offset_x), FT_S16, FU_RAW, 0, 1},
    {"target_offset_y", GCU(main.target_offset_y), FT_S16, FU_RAW, 0, 1},
    {"rel_angle_x", GCU(main.rel_angle_x), FT_S16, FU_CDEG, 0, 1},
    {"rel_angle_y", GCU(main.rel_angle_y), FT_S16, FU_CDEG, 0, 1},
    {"rel_angle_z", GCU(main.rel_angle_z), FT_S16, FU_CDEG, 0, 1},
    {"cam_roll", GCU(main.cam_roll), FT_S16, FU_CDEG, 0, 1},
    {"cam_pitch", GCU(main.cam_pitch), FT_S16, FU_CDEG, 0, 1},
    {"cam_yaw", GCU(main.cam_yaw), FT_U16, FU_CDEG, 0, 1},
    {"rate_x", GCU(main.rate_x), FT_S16, FU_GCU_RATE, 0, 1},
    {"rate_y", GCU(main.rate_y), FT_S16, FU_GCU_RATE, 0, 1},
    {"rate_z", GCU(main.rate_z), FT_S16, FU_GCU_RATE, 0, 1},
    {"sub_header", GCU(sub.sub_header), FT_U8, FU_BYTE_HEX, 1, 1},
    {"hw_version", GCU(sub.hw_version), FT_U8, FU_RAW, 1, 1},
    {"fw_version", GCU(sub.fw_version), FT_U8, FU_RAW, 1, 1},
    {"gimbal_code", GCU(sub.gimbal_code), FT_U8, FU_MODEL, 1, 1},
    {"error_code", GCU(sub.error_code), FT_U16, FU_ERROR_CODE, 1, 1},
    {"target_distance", GCU(sub.target_distance), FT_S32, FU_DISTANCE, 1, 1},
    {"target_longitude", GCU(sub.target_longitude), FT_S32, FU_DEG7, 1, 1},
    {"target_latitude", GCU(sub.target_latitude), FT_S32, FU_DEG7, 1, 1},
    {"target_altitude", GCU(sub.target_altitude), FT_S32, FU_MM, 1, 1},
    {"zoom_cam1", GCU(sub.zoom_cam1), FT_U16, FU_ZOOM, 1, 1},
    {"zoom_cam2", GCU(sub.zoom_cam2), FT_U16, FU_ZOOM, 1, 1},
    {"thermal_status", GCU(sub.thermal_status), FT_U8, FU_THERMAL, 1, 2},
    {"camera_status", GCU(sub.camera_status), FT_U16, FU_CAMERA, 1, 2},
    {"time_zone", GCU(sub.time_zone), FT_S8, FU_HOURS, 1, 2},
};

const field_desc *fields_of(xf_direction dir, size_t *count)
{
    if (dir == XF_DIR_HOST) {
        *count = sizeof(host_fields) / sizeof(host_fields[0]);
        return host_fields;
    }
    *count = sizeof(gcu_fields) / sizeof(gcu_fields[0]);
    return gcu_fields;
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

long long field_get(const void *pkt, const field_desc *f)
{
    const unsigned char *p = (const unsigned char *)pkt + f->offset;
    switch ((field_type)f->type) {
    case FT_U8: {
        uint8_t v;
        memcpy(&v, p, sizeof(v));
        return v;
    }
    case FT_S8: {
        int8_t v;
        memcpy(&v, p, sizeof(v));
        return v;
    }
    case FT_U16: {
        uint16_t v;
        memcpy(&v, p, sizeof(v));
        return v;
    }
    case FT_S16: {
        int16_t v;
        memcpy(&v, p, sizeof(v));
        return v;
    }
    case FT_U32: {
        uint32_t v;
        memcpy(&v, p, sizeof(v));
        return v;
    }
    case FT_S32: {
        int32_t v;
        memcpy(&v, p, sizeof(v));
        return v;
    }
    default: return 0;
    }
}

void field_set(void *pkt, const field_desc *f, long long v)
{
    unsigned char *p = (unsigned char *)pkt + f->offset;
    switch ((field_type)f->type) {
    case FT_U8: {
        uint8_t x = (uint8_t)v;
        memcpy(p, &x, sizeof(x));
        break;
    }
    case FT_S8: {
        int8_t x = (int8_t)v;
        memcpy(p, &x, sizeof(x));
        break;
    }
    case FT_U16: {
        uint16_t x = (uint16_t)v;
        memcpy(p, &x, sizeof(x));
        break;
    }
    case FT_S16: {
        int16_t x = (int16_t)v;
        memcpy(p, &x, sizeof(x));
        break;
    }
    case FT_U32: {
        uint32_t x = (uint32_t)v;
        memcpy(p, &x, sizeof(x));
        break;
    }
    case FT_S32: {
        int32_t x = (int32_t)v;
        memcpy(p, &x, sizeof(x));
        break;
    }
    default: break;
    }
}

void field_range(const field_desc *f, long long *lo, long long *hi)
{
    switch ((field_type)f->type) {
    case FT_U8:
        *lo = 0;
        *hi = UINT8_MAX;
        break;
    case FT_S8:
        *lo = INT8_MIN;
        *hi = INT8_MAX;
        break;
    case FT_U16:
        *lo = 0;
        *hi = UINT16_MAX;
        break;
    case FT_S16:
        *lo = INT16_MIN;
        *hi = INT16_MAX;
        break;
    case FT_U32:
        *lo = 0;
        *hi = UINT32_MAX;
        break;
    default:
        *lo = INT32_MIN;
        *hi = INT32_MAX;
        break;
    }
}

/* ---- reserved bytes ------------------------------------------------------ */

const char *reserved_name(int block) { return (block == RESERVED_MAIN) ? "reserved_main" : "reserved_sub"; }

/* A V0.1 GCU packet: bytes 63-66 are reserved there, though the struct names them for V0.2. */
static int gcu_v1_sub(xf_direction dir, uint8_t version, int block)
{
    return dir == XF_DIR_GCU && block == RESERVED_SUB && version < XF_PROTOCOL_V2;
}

size_t reserved_size(xf_direction dir, uint8_t version, int block)
{
    if (dir == XF_DIR_HOST) {
        return (block == RESERVED_MAIN) ? sizeof(((xf_host_main *)0)->reserved_main)
                                        : sizeof(((xf_host_sub *)0)->reserved_sub);
    }
    if (block == RESERVED_MAIN) {
        return sizeof(((xf_gcu_main *)0)->reserved_main);
    }
    return gcu_v1_sub(dir, version, block) ? 6u : sizeof(((xf_gcu_sub *)0)->reserved_sub);
}

size_t reserved_get(const void *pkt, xf_direction dir, uint8_t version, int block, uint8_t *out)
{
    size_t n = reserved_size(dir, version, block);
    if (dir == XF_DIR_HOST) {
        const xf_host_packet *h = (const xf_host_packet *)pkt;
        memcpy(out, (block == RESERVED_MAIN) ? h->main.reserved_main : h->sub.reserved_sub, n);
    } else {
        const xf_gcu_packet *g = (const xf_gcu_packet *)pkt;
        if (block == RESERVED_MAIN) {
            memcpy(out, g->main.reserved_main, n);
        } else if (gcu_v1_sub(dir, version, block)) {
            /* bytes 63-68 in wire order */
            out[0] = g->sub.thermal_status;
            out[1] = (uint8_t)(g->sub.camera_status & 0xFFu);
            out[2] = (uint8_t)(g->sub.camera_status >> 8);
            out[3] = (uint8_t)g->sub.time_zone;
            memcpy(out + 4, g->sub.reserved_sub, 2);
        } else {
            memcpy(out, g->sub.reserved_sub, n);
        }
    }
    return n;
}

void reserved_set(void *pkt, xf_direction dir, uint8_t version, int block, const uint8_t *in)
{
    size_t n = reserved_size(dir, version, block);
    if (dir == XF_DIR_HOST) {
        xf_host_packet *h = (xf_host_packet *)pkt;
        memcpy((block == RESERVED_MAIN) ? h->main.reserved_main : h->sub.reserved_sub, in, n);
    } else {
        xf_gcu_packet *g = (xf_gcu_packet *)pkt;
        if (block == RESERVED_MAIN) {
            memcpy(g->main.reserved_main, in, n);
        } else if (gcu_v1_sub(dir, version, block)) {
            g->sub.thermal_status = in[0];
            g->sub.camera_status = (uint16_t)(in[1] | (in[2] << 8));
            g->sub.time_zone = xf_u8_to_s8(in[3]);
            memcpy(g->sub.reserved_sub, in + 4, 2);
        } else {
            memcpy(g->sub.reserved_sub, in, n);
        }
    }
}
