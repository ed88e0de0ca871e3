/*
 * test_fields.h - the wire layout of the four frames, written from the spec
 * (docs/protocol.md §2-§6 and §10), tied to the members of the codec's
 * structs.
 *
 * Each row says: this struct member lives at this byte offset, this many
 * bytes, with this signedness (spec type). The tests use the table both to
 * build expected bytes independently of xf_*_pack and to compare structs
 * member by member. The tables also carry the version (byte 4) and the
 * order (byte 69), so that together they cover bytes 4..69 exactly once
 * (test_packet.c checks that).
 */
#ifndef XFGCU_TEST_FIELDS_H
#define XFGCU_TEST_FIELDS_H

#include "test_util.h"

/* The spec's wire types. */
typedef enum field_kind { FK_U8, FK_S8, FK_U16, FK_S16, FK_U32, FK_S32, FK_BYTES } field_kind;

typedef struct field_desc {
    const char *name;
    size_t member_off;  /* offsetof in the packet struct */
    size_t member_size; /* sizeof the member */
    int member_kind;    /* field_kind of the member's C type (from _Generic) */
    size_t wire_off;    /* byte offset in the packet, from the spec */
    field_kind kind;    /* type the spec gives the field */
    size_t nbytes;      /* bytes on the wire, from the spec */
} field_desc;

/* The C type of a member, as a field_kind (arrays decay to pointers: FK_BYTES). */
#define KIND_OF(x)                                                                                                     \
    _Generic((x), uint8_t                                                                                              \
             : FK_U8, int8_t                                                                                           \
             : FK_S8, uint16_t                                                                                         \
             : FK_U16, int16_t                                                                                         \
             : FK_S16, uint32_t                                                                                        \
             : FK_U32, int32_t                                                                                         \
             : FK_S32, default                                                                                         \
             : FK_BYTES)

#define FD(type, member, wire, kind, n)                                                                                \
    {                                                                                                                  \
#member, offsetof(type, member), sizeof(((type *)0)->member), KIND_OF(((type *)0)->member), (wire), (kind),    \
            (n)                                                                                                        \
    }

/* docs/protocol.md §2, §3, §4 */
static const field_desc host_fields[] = {
    FD(xf_host_packet, version, 4, FK_U8, 1),
    FD(xf_host_packet, main.roll_ctrl, 5, FK_S16, 2),
    FD(xf_host_packet, main.pitch_ctrl, 7, FK_S16, 2),
    FD(xf_host_packet, main.yaw_ctrl, 9, FK_S16, 2),
    FD(xf_host_packet, main.status, 11, FK_U8, 1),
    FD(xf_host_packet, main.carrier_roll, 12, FK_S16, 2),
    FD(xf_host_packet, main.carrier_pitch, 14, FK_S16, 2),
    FD(xf_host_packet, main.carrier_yaw, 16, FK_U16, 2),
    FD(xf_host_packet, main.accel_north, 18, FK_S16, 2),
    FD(xf_host_packet, main.accel_east, 20, FK_S16, 2),
    FD(xf_host_packet, main.accel_up, 22, FK_S16, 2),
    FD(xf_host_packet, main.vel_north, 24, FK_S16, 2),
    FD(xf_host_packet, main.vel_east, 26, FK_S16, 2),
    FD(xf_host_packet, main.vel_up, 28, FK_S16, 2),
    FD(xf_host_packet, main.sub_request, 30, FK_U8, 1),
    FD(xf_host_packet, main.reserved_main, 31, FK_BYTES, 6),
    FD(xf_host_packet, sub.sub_header, 37, FK_U8, 1),
    FD(xf_host_packet, sub.longitude, 38, FK_S32, 4),
    FD(xf_host_packet, sub.latitude, 42, FK_S32, 4),
    FD(xf_host_packet, sub.altitude, 46, FK_S32, 4),
    FD(xf_host_packet, sub.satellites, 50, FK_U8, 1),
    FD(xf_host_packet, sub.gnss_ms, 51, FK_U32, 4),
    FD(xf_host_packet, sub.gnss_week, 55, FK_S16, 2),
    FD(xf_host_packet, sub.relative_height, 57, FK_S32, 4),
    FD(xf_host_packet, sub.reserved_sub, 61, FK_BYTES, 8),
    FD(xf_host_packet, order, 69, FK_U8, 1),
};

/* docs/protocol.md §2, §5, §6, §10 (thermal_status 63, camera_status 64-65, time_zone 66, error_code 41-42) */
static const field_desc gcu_fields[] = {
    FD(xf_gcu_packet, version, 4, FK_U8, 1),
    FD(xf_gcu_packet, main.gimbal_mode, 5, FK_U8, 1),
    FD(xf_gcu_packet, main.pod_status, 6, FK_U16, 2),
    FD(xf_gcu_packet, main.target_offset_x, 8, FK_S16, 2),
    FD(xf_gcu_packet, main.target_offset_y, 10, FK_S16, 2),
    FD(xf_gcu_packet, main.rel_angle_x, 12, FK_S16, 2),
    FD(xf_gcu_packet, main.rel_angle_y, 14, FK_S16, 2),
    FD(xf_gcu_packet, main.rel_angle_z, 16, FK_S16, 2),
    FD(xf_gcu_packet, main.cam_roll, 18, FK_S16, 2),
    FD(xf_gcu_packet, main.cam_pitch, 20, FK_S16, 2),
    FD(xf_gcu_packet, main.cam_yaw, 22, FK_U16, 2),
    FD(xf_gcu_packet, main.rate_x, 24, FK_S16, 2),
    FD(xf_gcu_packet, main.rate_y, 26, FK_S16, 2),
    FD(xf_gcu_packet, main.rate_z, 28, FK_S16, 2),
    FD(xf_gcu_packet, main.reserved_main, 30, FK_BYTES, 7),
    FD(xf_gcu_packet, sub.sub_header, 37, FK_U8, 1),
    FD(xf_gcu_packet, sub.hw_version, 38, FK_U8, 1),
    FD(xf_gcu_packet, sub.fw_version, 39, FK_U8, 1),
    FD(xf_gcu_packet, sub.gimbal_code, 40, FK_U8, 1),
    FD(xf_gcu_packet, sub.error_code, 41, FK_U16, 2),
    FD(xf_gcu_packet, sub.target_distance, 43, FK_S32, 4),
    FD(xf_gcu_packet, sub.target_longitude, 47, FK_S32, 4),
    FD(xf_gcu_packet, sub.target_latitude, 51, FK_S32, 4),
    FD(xf_gcu_packet, sub.target_altitude, 55, FK_S32, 4),
    FD(xf_gcu_packet, sub.zoom_cam1, 59, FK_U16, 2),
    FD(xf_gcu_packet, sub.zoom_cam2, 61, FK_U16, 2),
    FD(xf_gcu_packet, sub.thermal_status, 63, FK_U8, 1),
    FD(xf_gcu_packet, sub.camera_status, 64, FK_U16, 2),
    FD(xf_gcu_packet, sub.time_zone, 66, FK_S8, 1),
    FD(xf_gcu_packet, sub.reserved_sub, 67, FK_BYTES, 2),
    FD(xf_gcu_packet, order, 69, FK_U8, 1),
};

static inline int kind_is_signed(field_kind k) { return k == FK_S8 || k == FK_S16 || k == FK_S32; }

/* Store the wire image @p wire (f->nbytes bytes, little-endian) into the
 * member, converting through the spec's signedness: what an unpack must do. */
static inline void field_store_wire(void *pkt, const field_desc *f, const uint8_t *wire)
{
    uint8_t *m = (uint8_t *)pkt + f->member_off;
    switch (f->kind) {
    case FK_U8: {
        uint8_t v = wire[0];
        memcpy(m, &v, 1);
        break;
    }
    case FK_S8: {
        int8_t v = (int8_t)le_get_signed(wire, 1);
        memcpy(m, &v, 1);
        break;
    }
    case FK_U16: {
        uint16_t v = (uint16_t)le_get(wire, 2);
        memcpy(m, &v, 2);
        break;
    }
    case FK_S16: {
        int16_t v = (int16_t)le_get_signed(wire, 2);
        memcpy(m, &v, 2);
        break;
    }
    case FK_U32: {
        uint32_t v = (uint32_t)le_get(wire, 4);
        memcpy(m, &v, 4);
        break;
    }
    case FK_S32: {
        int32_t v = (int32_t)le_get_signed(wire, 4);
        memcpy(m, &v, 4);
        break;
    }
    default: memcpy(m, wire, f->nbytes); break;
    }
}

/* The member's numeric value (as its spec type says), or for byte arrays the
 * little-endian value of its first bytes (only used for messages). */
static inline int64_t field_value(const void *pkt, const field_desc *f)
{
    const uint8_t *m = (const uint8_t *)pkt + f->member_off;
    switch (f->kind) {
    case FK_U8: {
        uint8_t v;
        memcpy(&v, m, 1);
        return v;
    }
    case FK_S8: {
        int8_t v;
        memcpy(&v, m, 1);
        return v;
    }
    case FK_U16: {
        uint16_t v;
        memcpy(&v, m, 2);
        return v;
    }
    case FK_S16: {
        int16_t v;
        memcpy(&v, m, 2);
        return v;
    }
    case FK_U32: {
        uint32_t v;
        memcpy(&v, m, 4);
        return v;
    }
    case FK_S32: {
        int32_t v;
        memcpy(&v, m, 4);
        return v;
    }
    default: return (int64_t)le_get(m, f->nbytes < 8u ? f->nbytes : 8u);
    }
}

/* The wire image of a member: what a pack must write at f->wire_off. */
static inline void field_load_wire(const void *pkt, const field_desc *f, uint8_t *wire)
{
    if (f->kind == FK_BYTES) {
        memcpy(wire, (const uint8_t *)pkt + f->member_off, f->nbytes);
    } else {
        le_put(wire, (uint64_t)field_value(pkt, f), f->nbytes);
    }
}

/* Encode a whole packet from the table, independently of xf_*_pack. */
static inline size_t ref_pack(const void *pkt, const field_desc *fields, size_t nfields, uint8_t params_len,
                              const uint8_t *params, xf_direction dir, uint8_t *buf)
{
    size_t i, len = 72u + params_len;
    memset(buf, 0, len);
    for (i = 0; i < nfields; i++) {
        field_load_wire(pkt, &fields[i], buf + fields[i].wire_off);
    }
    memcpy(buf + 70, params, params_len);
    ref_finish_packet(buf, len, dir);
    return len;
}

/* Two packets equal member by member (the table covers every member but the
 * parameters, compared here up to params_len). Reports the first difference. */
static inline void test_pkt_equal(const void *got, const void *want, const field_desc *fields, size_t nfields,
                                  uint8_t got_plen, const uint8_t *got_params, uint8_t want_plen,
                                  const uint8_t *want_params, const char *file, int line)
{
    size_t i;
    for (i = 0; i < nfields; i++) {
        const field_desc *f = &fields[i];
        if (memcmp((const uint8_t *)got + f->member_off, (const uint8_t *)want + f->member_off, f->member_size) != 0) {
            print_error("member %s differs: got %lld, expected %lld\n", f->name, (long long)field_value(got, f),
                        (long long)field_value(want, f));
            _fail(file, line);
        }
    }
    if (got_plen != want_plen) {
        print_error("params_len differs: got %u, expected %u\n", got_plen, want_plen);
        _fail(file, line);
    }
    test_bytes_equal(got_params, want_params, want_plen, file, line);
}

#define assert_host_pkt_equal(got, want)                                                                               \
    test_pkt_equal((got), (want), host_fields, ARRAY_LEN(host_fields), (got)->params_len, (got)->params,               \
                   (want)->params_len, (want)->params, __FILE__, __LINE__)
#define assert_gcu_pkt_equal(got, want)                                                                                \
    test_pkt_equal((got), (want), gcu_fields, ARRAY_LEN(gcu_fields), (got)->params_len, (got)->params,                 \
                   (want)->params_len, (want)->params, __FILE__, __LINE__)

#endif /* XFGCU_TEST_FIELDS_H */
