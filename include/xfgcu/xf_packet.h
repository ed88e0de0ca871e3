/**
 * @file
 * @brief The four frames as typed structs, and packets packed and unpacked
 * field by field.
 *
 * Member names are the canonical names of docs/protocol.md (§2-§6); the
 * values are the raw wire integers (xf_units.h converts to physical units).
 * Reserved bytes are kept in `reserved_*` arrays so that unpack followed by
 * pack gives back the very same bytes.
 *
 * The functions keep no state, never allocate and never block. To decode a
 * byte stream (serial, TCP) feed it to the parser (xf_parser.h) first.
 */
#ifndef XF_PACKET_H
#define XF_PACKET_H

#include <stddef.h>
#include <stdint.h>
#include "xf_bytes.h"
#include "xf_config.h"
#include "xf_mem.h"
#include "xf_crc.h"
#include "xf_error.h"
#include "xf_protocol.h"

XF_BEGIN_DECLS

/** Host main frame, bytes 5-36. */
typedef struct xf_host_main {
    int16_t roll_ctrl;        /**< roll control quantity: rate or angle, per the mode (docs/protocol.md §11) */
    int16_t pitch_ctrl;       /**< pitch control quantity */
    int16_t yaw_ctrl;         /**< yaw control quantity */
    uint8_t status;           /**< ::XF_STATUS_INS_VALID, ::XF_STATUS_CTRL_VALID; other bits 0 */
    int16_t carrier_roll;     /**< carrier's absolute roll, 0.01 deg, [-18000, 18000) */
    int16_t carrier_pitch;    /**< carrier's absolute pitch, 0.01 deg, [-9000, 9000] */
    uint16_t carrier_yaw;     /**< carrier's absolute yaw, 0.01 deg, [0, 36000) */
    int16_t accel_north;      /**< 0.01 m/s^2, north positive, gravity excluded */
    int16_t accel_east;       /**< 0.01 m/s^2, east positive */
    int16_t accel_up;         /**< 0.01 m/s^2, up positive */
    int16_t vel_north;        /**< 0.01 m/s, north positive */
    int16_t vel_east;         /**< 0.01 m/s, east positive */
    int16_t vel_up;           /**< 0.01 m/s, up positive */
    uint8_t sub_request;      /**< sub frame asked of the GCU (::XF_SUB_HEADER) */
    uint8_t reserved_main[6]; /**< bytes 31-36, 0 */
} xf_host_main;

/** Host sub frame, bytes 37-68. All zero when there is no sub frame data. */
typedef struct xf_host_sub {
    uint8_t sub_header;      /**< ::XF_SUB_HEADER, or 0 with no sub frame data */
    int32_t longitude;       /**< longitude, 1e-7 deg */
    int32_t latitude;        /**< latitude, 1e-7 deg */
    int32_t altitude;        /**< altitude, mm */
    uint8_t satellites;      /**< satellites in use */
    uint32_t gnss_ms;        /**< GNSS milliseconds of week */
    int16_t gnss_week;       /**< GNSS week number */
    int32_t relative_height; /**< height, mm; may be 0 when not needed */
    uint8_t reserved_sub[8]; /**< bytes 61-68, 0 */
} xf_host_sub;

/** GCU main frame, bytes 5-36. */
typedef struct xf_gcu_main {
    uint8_t gimbal_mode;      /**< ::xf_mode */
    uint16_t pod_status;      /**< `XF_POD_*` bits */
    int16_t target_offset_x;  /**< horizontal target offset, [-1000, 1000], right positive */
    int16_t target_offset_y;  /**< vertical target offset, [-1000, 1000], down positive */
    int16_t rel_angle_x;      /**< camera's X-axis angle relative to the carrier, 0.01 deg */
    int16_t rel_angle_y;      /**< camera's Y-axis angle relative to the carrier, 0.01 deg */
    int16_t rel_angle_z;      /**< camera's Z-axis angle relative to the carrier, 0.01 deg */
    int16_t cam_roll;         /**< camera's absolute roll, 0.01 deg */
    int16_t cam_pitch;        /**< camera's absolute pitch, 0.01 deg */
    uint16_t cam_yaw;         /**< camera's absolute yaw, 0.01 deg, [0, 36000) */
    int16_t rate_x;           /**< angular velocity about X: 0.01 deg/s (V0.1) or 0.1 deg/s (V0.2) */
    int16_t rate_y;           /**< angular velocity about Y, unit as rate_x */
    int16_t rate_z;           /**< angular velocity about Z, unit as rate_x */
    uint8_t reserved_main[7]; /**< bytes 30-36 */
} xf_gcu_main;

/** GCU sub frame, bytes 37-68. */
typedef struct xf_gcu_sub {
    uint8_t sub_header;       /**< ::XF_SUB_HEADER, or 0 when the host asked for an unknown sub frame */
    uint8_t hw_version;       /**< hardware version */
    uint8_t fw_version;       /**< firmware version */
    uint8_t gimbal_code;      /**< model code (xf_gimbal_model()) */
    uint16_t error_code;      /**< V0.2: XF_ERROR_* bits; reserved in V0.1 */
    int32_t target_distance;  /**< laser range, 0.1 m; -10 or 0: no valid measurement */
    int32_t target_longitude; /**< target longitude, 1e-7 deg */
    int32_t target_latitude;  /**< target latitude, 1e-7 deg */
    int32_t target_altitude;  /**< target altitude, mm */
    uint16_t zoom_cam1;       /**< camera 1's zoom, 0.1 x */
    uint16_t zoom_cam2;       /**< camera 2's zoom, 0.1 x */
    uint8_t thermal_status;   /**< V0.2, byte 63: XF_THERMAL_* (reserved in V0.1) */
    uint16_t camera_status;   /**< V0.2, bytes 64-65: XF_CAMERA_* (reserved in V0.1) */
    int8_t time_zone;         /**< V0.2, byte 66: hours from UTC (reserved in V0.1) */
    uint8_t reserved_sub[2];  /**< bytes 67-68 */
} xf_gcu_sub;

/** A host -> GCU packet. */
typedef struct xf_host_packet {
    uint8_t version;               /**< byte 4: XF_PROTOCOL_V1 or XF_PROTOCOL_V2 */
    xf_host_main main;             /**< main frame, bytes 5-36 */
    xf_host_sub sub;               /**< sub frame, bytes 37-68 */
    uint8_t order;                 /**< byte 69: xf_order, or any other value (raw) */
    uint8_t params_len;            /**< parameter bytes used, 0..::XF_PARAMS_MAX */
    uint8_t params[XF_PARAMS_CAP]; /**< parameter bytes, from byte 70 (xf_command_encode() fills them) */
} xf_host_packet;

/** A GCU -> host packet. `params` holds the feedback bytes. */
typedef struct xf_gcu_packet {
    uint8_t version;               /**< byte 4: the protocol version the GCU speaks */
    xf_gcu_main main;              /**< main frame, bytes 5-36 */
    xf_gcu_sub sub;                /**< sub frame, bytes 37-68 */
    uint8_t order;                 /**< the order the feedback answers */
    uint8_t params_len;            /**< feedback bytes: 0 for the null order, 1 otherwise */
    uint8_t params[XF_PARAMS_CAP]; /**< feedback bytes, from byte 70 (xf_feedback_decode() reads them) */
} xf_gcu_packet;

/**
 * Check a whole packet in @p buf: header for @p dir, length field in
 * [72, XF_PACKET_MAX_LEN] and equal to @p len, CRC.
 * @param buf  the packet's bytes
 * @param len  number of bytes at @p buf: the whole packet, nothing after it
 * @param dir  the direction whose header is expected
 * @return ::XF_OK, ::XF_ERR_ARG (NULL buf, or @p dir not a direction),
 *   ::XF_ERR_TRUNCATED (fewer bytes than the header and length need, or than
 *   the length field says), ::XF_ERR_HEADER (not @p dir's header),
 *   ::XF_ERR_LENGTH (field out of range, or more bytes than it says),
 *   ::XF_ERR_CRC.
 */
XF_API xf_err xf_packet_check(const uint8_t *buf, size_t len, xf_direction dir);

/**
 * Which direction's header starts @p buf.
 * @param buf  the bytes
 * @param len  number of bytes at @p buf (only the first two are read)
 * @param dir  receives ::XF_DIR_HOST or ::XF_DIR_GCU; left alone on error
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p buf or @p dir), ::XF_ERR_TRUNCATED
 *   (@p len < 2), ::XF_ERR_HEADER (neither header)
 */
XF_API xf_err xf_packet_direction(const uint8_t *buf, size_t len, xf_direction *dir);

/**
 * Bytes a host packet will take once packed: 72 + params_len.
 * @param pkt  the packet (params_len is not checked against ::XF_PARAMS_MAX)
 * @return the size in bytes, or 0 for a NULL @p pkt
 */
XF_API size_t xf_host_packet_size(const xf_host_packet *pkt);
/**
 * Bytes a GCU packet will take once packed: 72 + params_len.
 * @param pkt  the packet (params_len is not checked against ::XF_PARAMS_MAX)
 * @return the size in bytes, or 0 for a NULL @p pkt
 */
XF_API size_t xf_gcu_packet_size(const xf_gcu_packet *pkt);

/**
 * Pack a host packet into bytes, header, length and CRC included. Every
 * field is written as it is (no range check); nothing is written on error.
 * @param pkt      the packet
 * @param buf      where the bytes go
 * @param cap      capacity of @p buf, in bytes
 * @param out_len  receives the packet's length (may be NULL)
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p pkt or @p buf), ::XF_ERR_RANGE
 *   (params_len > ::XF_PARAMS_MAX), ::XF_ERR_NO_SPACE (@p cap < the packet's
 *   size)
 */
XF_API xf_err xf_host_pack(const xf_host_packet *pkt, uint8_t *buf, size_t cap, size_t *out_len);
/**
 * Pack a GCU packet into bytes, as xf_host_pack() does for a host packet
 * (the GCU's side: the simulator, tests).
 * @param pkt      the packet
 * @param buf      where the bytes go
 * @param cap      capacity of @p buf, in bytes
 * @param out_len  receives the packet's length (may be NULL)
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p pkt or @p buf), ::XF_ERR_RANGE
 *   (params_len > ::XF_PARAMS_MAX), ::XF_ERR_NO_SPACE (@p cap < the packet's
 *   size)
 */
XF_API xf_err xf_gcu_pack(const xf_gcu_packet *pkt, uint8_t *buf, size_t cap, size_t *out_len);

/**
 * Check (as xf_packet_check()) and decode one whole host packet of @p len
 * bytes. Any version byte is accepted and kept. @p pkt is written only on
 * success.
 * @param buf  the packet's bytes
 * @param len  number of bytes: the whole packet, nothing after it
 * @param pkt  receives the decoded packet
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p buf or @p pkt), or the errors of
 *   xf_packet_check(): ::XF_ERR_TRUNCATED, ::XF_ERR_HEADER, ::XF_ERR_LENGTH,
 *   ::XF_ERR_CRC
 */
XF_API xf_err xf_host_unpack(const uint8_t *buf, size_t len, xf_host_packet *pkt);
/**
 * Check (as xf_packet_check()) and decode one whole GCU packet of @p len
 * bytes. Any version byte is accepted and kept. @p pkt is written only on
 * success. A frame the parser returned is decoded more cheaply by
 * xf_frame_gcu().
 * @param buf  the packet's bytes
 * @param len  number of bytes: the whole packet, nothing after it
 * @param pkt  receives the decoded packet
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p buf or @p pkt), or the errors of
 *   xf_packet_check(): ::XF_ERR_TRUNCATED, ::XF_ERR_HEADER, ::XF_ERR_LENGTH,
 *   ::XF_ERR_CRC
 */
XF_API xf_err xf_gcu_unpack(const uint8_t *buf, size_t len, xf_gcu_packet *pkt);

/**
 * Initialise a host packet: all zero, @p version, sub_request =
 * ::XF_SUB_HEADER, null order (no parameters). Does nothing for a NULL @p pkt.
 * @param pkt      the packet
 * @param version  protocol version byte, ::XF_PROTOCOL_V1 or ::XF_PROTOCOL_V2
 */
XF_API void xf_host_packet_init(xf_host_packet *pkt, uint8_t version);

/**
 * Low-level packet writing, for code that writes a frame's fields straight
 * into the bytes (as the client does) instead of through xf_host_pack():
 * the two header bytes of @p dir, the length and the version. Write the
 * frame fields (XF_OFF_MAIN ..), then call xf_packet_put_tail().
 * @param buf      at least @p len bytes; nothing is checked
 * @param dir      the direction, which picks the header bytes
 * @param len      the whole packet's length, XF_PACKET_MIN_LEN + parameters
 * @param version  the protocol version byte
 */
XF_API void xf_packet_put_header(uint8_t *buf, xf_direction dir, size_t len, uint8_t version);

/**
 * Low-level packet writing, after xf_packet_put_header() and the frame
 * fields: the order, the parameter bytes and the big-endian CRC over all
 * bytes before it.
 * @param buf         the packet, @p len bytes; nothing is checked
 * @param len         the whole packet's length (= XF_PACKET_MIN_LEN + @p params_len)
 * @param order       the order byte
 * @param params      the parameter bytes; may be NULL when @p params_len is 0
 * @param params_len  number of parameter bytes
 */
XF_API void xf_packet_put_tail(uint8_t *buf, size_t len, uint8_t order, const uint8_t *params, uint8_t params_len);

/**
 * A frame the streaming parser (xf_parser.h) returned. The bytes are in the parser or, when a
 * whole packet arrived in one chunk, in the caller's own data; either way
 * they stay valid until the next call on the parser, as long as the caller
 * does not change its data meanwhile.
 */
typedef struct xf_frame {
    const uint8_t *data; /**< the frame's first byte (its header) */
    size_t len;          /**< the frame's length in bytes, CRC included (its length field) */
} xf_frame;

/**
 * Decode a GCU frame the parser returned, without computing its CRC again
 * (the parser has checked header, length and CRC; only the header and
 * length are looked at again, cheaply). For bytes from anywhere else use
 * xf_gcu_unpack(). @p pkt is written only on success.
 * @param frame  the frame, as xf_parser_feed() gave it
 * @param pkt    receives the decoded packet
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p frame, frame data or @p pkt),
 *   ::XF_ERR_HEADER (a frame of the other direction), ::XF_ERR_LENGTH (the
 *   length is out of range or disagrees with the length field)
 */
XF_API xf_err xf_frame_gcu(const xf_frame *frame, xf_gcu_packet *pkt);
/**
 * Decode a host frame the parser returned (GCU side: the simulator), as
 * xf_frame_gcu() does for GCU frames. For bytes from anywhere else use
 * xf_host_unpack(). @p pkt is written only on success.
 * @param frame  the frame, as xf_parser_feed() gave it
 * @param pkt    receives the decoded packet
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p frame, frame data or @p pkt),
 *   ::XF_ERR_HEADER (a frame of the other direction), ::XF_ERR_LENGTH
 */
XF_API xf_err xf_frame_host(const xf_frame *frame, xf_host_packet *pkt);

#if XF_EMIT_DEFINITIONS

XF_API void xf_packet_put_header(uint8_t *buf, xf_direction dir, size_t len, uint8_t version)
{
    buf[0] = (dir == XF_DIR_HOST) ? XF_HOST_HEADER0 : XF_GCU_HEADER0;
    buf[1] = (dir == XF_DIR_HOST) ? XF_HOST_HEADER1 : XF_GCU_HEADER1;
    xf_put_u16le(buf + XF_OFF_LENGTH, (uint16_t)len);
    buf[XF_OFF_VERSION] = version;
}

XF_API void xf_packet_put_tail(uint8_t *buf, size_t len, uint8_t order, const uint8_t *params, uint8_t params_len)
{
    uint16_t crc;
    buf[XF_OFF_ORDER] = order;
    if (params_len > 0u) {
        XF_MEMCPY(buf + XF_OFF_PARAMS, params, params_len);
    }
    crc = xf_crc16(buf, len - 2u);
    buf[len - 2u] = (uint8_t)(crc >> 8); /* the CRC is big-endian */
    buf[len - 1u] = (uint8_t)(crc & 0xFFu);
}

XF_API xf_err xf_packet_direction(const uint8_t *buf, size_t len, xf_direction *dir)
{
    if (buf == NULL || dir == NULL) {
        return XF_ERR_ARG;
    }
    if (len < 2u) {
        return XF_ERR_TRUNCATED;
    }
    if (buf[0] == XF_HOST_HEADER0 && buf[1] == XF_HOST_HEADER1) {
        *dir = XF_DIR_HOST;
    } else if (buf[0] == XF_GCU_HEADER0 && buf[1] == XF_GCU_HEADER1) {
        *dir = XF_DIR_GCU;
    } else {
        return XF_ERR_HEADER;
    }
    return XF_OK;
}

XF_API xf_err xf_packet_check(const uint8_t *buf, size_t len, xf_direction dir)
{
    xf_direction seen;
    xf_err err;
    size_t field;
    uint16_t crc;
    if (buf == NULL || (dir != XF_DIR_HOST && dir != XF_DIR_GCU)) {
        return XF_ERR_ARG;
    }
    err = xf_packet_direction(buf, len, &seen);
    if (err != XF_OK) {
        return err;
    }
    if (seen != dir) {
        return XF_ERR_HEADER;
    }
    if (len < 4u) {
        return XF_ERR_TRUNCATED;
    }
    field = xf_get_u16le(buf + XF_OFF_LENGTH);
    if (field < XF_PACKET_MIN_LEN || field > XF_PACKET_MAX_LEN) {
        return XF_ERR_LENGTH;
    }
    if (len < field) {
        return XF_ERR_TRUNCATED;
    }
    if (len > field) {
        return XF_ERR_LENGTH;
    }
    crc = (uint16_t)(((uint16_t)buf[field - 2u] << 8) | buf[field - 1u]);
    return (xf_crc16(buf, field - 2u) == crc) ? XF_OK : XF_ERR_CRC;
}

XF_API size_t xf_host_packet_size(const xf_host_packet *pkt)
{
    return (pkt == NULL) ? 0u : (size_t)XF_PACKET_MIN_LEN + pkt->params_len;
}

XF_API size_t xf_gcu_packet_size(const xf_gcu_packet *pkt)
{
    return (pkt == NULL) ? 0u : (size_t)XF_PACKET_MIN_LEN + pkt->params_len;
}

XF_API void xf_host_packet_init(xf_host_packet *pkt, uint8_t version)
{
    if (pkt != NULL) {
        XF_MEMSET(pkt, 0, sizeof(*pkt));
        pkt->version = version;
        pkt->main.sub_request = XF_SUB_HEADER;
    }
}

XF_API xf_err xf_host_pack(const xf_host_packet *pkt, uint8_t *buf, size_t cap, size_t *out_len)
{
    const xf_host_main *m;
    const xf_host_sub *s;
    size_t len;
    if (pkt == NULL || buf == NULL) {
        return XF_ERR_ARG;
    }
    if (pkt->params_len > XF_PARAMS_MAX) {
        return XF_ERR_RANGE;
    }
    len = xf_host_packet_size(pkt);
    if (cap < len) {
        return XF_ERR_NO_SPACE;
    }
    m = &pkt->main;
    s = &pkt->sub;
    xf_packet_put_header(buf, XF_DIR_HOST, len, pkt->version);
    xf_put_s16le(buf + XF_OFF_HOST_ROLL_CTRL, m->roll_ctrl);
    xf_put_s16le(buf + XF_OFF_HOST_PITCH_CTRL, m->pitch_ctrl);
    xf_put_s16le(buf + XF_OFF_HOST_YAW_CTRL, m->yaw_ctrl);
    buf[XF_OFF_HOST_STATUS] = m->status;
    xf_put_s16le(buf + XF_OFF_HOST_CARRIER_ROLL, m->carrier_roll);
    xf_put_s16le(buf + XF_OFF_HOST_CARRIER_PITCH, m->carrier_pitch);
    xf_put_u16le(buf + XF_OFF_HOST_CARRIER_YAW, m->carrier_yaw);
    xf_put_s16le(buf + XF_OFF_HOST_ACCEL_NORTH, m->accel_north);
    xf_put_s16le(buf + XF_OFF_HOST_ACCEL_EAST, m->accel_east);
    xf_put_s16le(buf + XF_OFF_HOST_ACCEL_UP, m->accel_up);
    xf_put_s16le(buf + XF_OFF_HOST_VEL_NORTH, m->vel_north);
    xf_put_s16le(buf + XF_OFF_HOST_VEL_EAST, m->vel_east);
    xf_put_s16le(buf + XF_OFF_HOST_VEL_UP, m->vel_up);
    buf[XF_OFF_HOST_SUB_REQUEST] = m->sub_request;
    XF_MEMCPY(buf + XF_OFF_HOST_RESERVED_MAIN, m->reserved_main, sizeof(m->reserved_main));
    buf[XF_OFF_HOST_SUB_HEADER] = s->sub_header;
    xf_put_s32le(buf + XF_OFF_HOST_LONGITUDE, s->longitude);
    xf_put_s32le(buf + XF_OFF_HOST_LATITUDE, s->latitude);
    xf_put_s32le(buf + XF_OFF_HOST_ALTITUDE, s->altitude);
    buf[XF_OFF_HOST_SATELLITES] = s->satellites;
    xf_put_u32le(buf + XF_OFF_HOST_GNSS_MS, s->gnss_ms);
    xf_put_s16le(buf + XF_OFF_HOST_GNSS_WEEK, s->gnss_week);
    xf_put_s32le(buf + XF_OFF_HOST_RELATIVE_HEIGHT, s->relative_height);
    XF_MEMCPY(buf + XF_OFF_HOST_RESERVED_SUB, s->reserved_sub, sizeof(s->reserved_sub));
    xf_packet_put_tail(buf, len, pkt->order, pkt->params, pkt->params_len);
    if (out_len != NULL) {
        *out_len = len;
    }
    return XF_OK;
}

XF_API xf_err xf_gcu_pack(const xf_gcu_packet *pkt, uint8_t *buf, size_t cap, size_t *out_len)
{
    const xf_gcu_main *m;
    const xf_gcu_sub *s;
    size_t len;
    if (pkt == NULL || buf == NULL) {
        return XF_ERR_ARG;
    }
    if (pkt->params_len > XF_PARAMS_MAX) {
        return XF_ERR_RANGE;
    }
    len = xf_gcu_packet_size(pkt);
    if (cap < len) {
        return XF_ERR_NO_SPACE;
    }
    m = &pkt->main;
    s = &pkt->sub;
    xf_packet_put_header(buf, XF_DIR_GCU, len, pkt->version);
    buf[XF_OFF_GCU_GIMBAL_MODE] = m->gimbal_mode;
    xf_put_u16le(buf + XF_OFF_GCU_POD_STATUS, m->pod_status);
    xf_put_s16le(buf + XF_OFF_GCU_TARGET_OFFSET_X, m->target_offset_x);
    xf_put_s16le(buf + XF_OFF_GCU_TARGET_OFFSET_Y, m->target_offset_y);
    xf_put_s16le(buf + XF_OFF_GCU_REL_ANGLE_X, m->rel_angle_x);
    xf_put_s16le(buf + XF_OFF_GCU_REL_ANGLE_Y, m->rel_angle_y);
    xf_put_s16le(buf + XF_OFF_GCU_REL_ANGLE_Z, m->rel_angle_z);
    xf_put_s16le(buf + XF_OFF_GCU_CAM_ROLL, m->cam_roll);
    xf_put_s16le(buf + XF_OFF_GCU_CAM_PITCH, m->cam_pitch);
    xf_put_u16le(buf + XF_OFF_GCU_CAM_YAW, m->cam_yaw);
    xf_put_s16le(buf + XF_OFF_GCU_RATE_X, m->rate_x);
    xf_put_s16le(buf + XF_OFF_GCU_RATE_Y, m->rate_y);
    xf_put_s16le(buf + XF_OFF_GCU_RATE_Z, m->rate_z);
    XF_MEMCPY(buf + XF_OFF_GCU_RESERVED_MAIN, m->reserved_main, sizeof(m->reserved_main));
    buf[XF_OFF_GCU_SUB_HEADER] = s->sub_header;
    buf[XF_OFF_GCU_HW_VERSION] = s->hw_version;
    buf[XF_OFF_GCU_FW_VERSION] = s->fw_version;
    buf[XF_OFF_GCU_GIMBAL_CODE] = s->gimbal_code;
    xf_put_u16le(buf + XF_OFF_GCU_ERROR_CODE, s->error_code);
    xf_put_s32le(buf + XF_OFF_GCU_TARGET_DISTANCE, s->target_distance);
    xf_put_s32le(buf + XF_OFF_GCU_TARGET_LONGITUDE, s->target_longitude);
    xf_put_s32le(buf + XF_OFF_GCU_TARGET_LATITUDE, s->target_latitude);
    xf_put_s32le(buf + XF_OFF_GCU_TARGET_ALTITUDE, s->target_altitude);
    xf_put_u16le(buf + XF_OFF_GCU_ZOOM_CAM1, s->zoom_cam1);
    xf_put_u16le(buf + XF_OFF_GCU_ZOOM_CAM2, s->zoom_cam2);
    buf[XF_OFF_GCU_THERMAL_STATUS] = s->thermal_status;
    xf_put_u16le(buf + XF_OFF_GCU_CAMERA_STATUS, s->camera_status);
    buf[XF_OFF_GCU_TIME_ZONE] = (uint8_t)s->time_zone;
    XF_MEMCPY(buf + XF_OFF_GCU_RESERVED_SUB, s->reserved_sub, sizeof(s->reserved_sub));
    xf_packet_put_tail(buf, len, pkt->order, pkt->params, pkt->params_len);
    if (out_len != NULL) {
        *out_len = len;
    }
    return XF_OK;
}

/* The fields of a host packet already checked (header, length, CRC). */
static inline void xf__host_fields(const uint8_t *buf, size_t len, xf_host_packet *pkt)
{
    xf_host_main *m;
    xf_host_sub *s;
    m = &pkt->main;
    s = &pkt->sub;
    pkt->version = buf[XF_OFF_VERSION];
    m->roll_ctrl = xf_get_s16le(buf + XF_OFF_HOST_ROLL_CTRL);
    m->pitch_ctrl = xf_get_s16le(buf + XF_OFF_HOST_PITCH_CTRL);
    m->yaw_ctrl = xf_get_s16le(buf + XF_OFF_HOST_YAW_CTRL);
    m->status = buf[XF_OFF_HOST_STATUS];
    m->carrier_roll = xf_get_s16le(buf + XF_OFF_HOST_CARRIER_ROLL);
    m->carrier_pitch = xf_get_s16le(buf + XF_OFF_HOST_CARRIER_PITCH);
    m->carrier_yaw = xf_get_u16le(buf + XF_OFF_HOST_CARRIER_YAW);
    m->accel_north = xf_get_s16le(buf + XF_OFF_HOST_ACCEL_NORTH);
    m->accel_east = xf_get_s16le(buf + XF_OFF_HOST_ACCEL_EAST);
    m->accel_up = xf_get_s16le(buf + XF_OFF_HOST_ACCEL_UP);
    m->vel_north = xf_get_s16le(buf + XF_OFF_HOST_VEL_NORTH);
    m->vel_east = xf_get_s16le(buf + XF_OFF_HOST_VEL_EAST);
    m->vel_up = xf_get_s16le(buf + XF_OFF_HOST_VEL_UP);
    m->sub_request = buf[XF_OFF_HOST_SUB_REQUEST];
    XF_MEMCPY(m->reserved_main, buf + XF_OFF_HOST_RESERVED_MAIN, sizeof(m->reserved_main));
    s->sub_header = buf[XF_OFF_HOST_SUB_HEADER];
    s->longitude = xf_get_s32le(buf + XF_OFF_HOST_LONGITUDE);
    s->latitude = xf_get_s32le(buf + XF_OFF_HOST_LATITUDE);
    s->altitude = xf_get_s32le(buf + XF_OFF_HOST_ALTITUDE);
    s->satellites = buf[XF_OFF_HOST_SATELLITES];
    s->gnss_ms = xf_get_u32le(buf + XF_OFF_HOST_GNSS_MS);
    s->gnss_week = xf_get_s16le(buf + XF_OFF_HOST_GNSS_WEEK);
    s->relative_height = xf_get_s32le(buf + XF_OFF_HOST_RELATIVE_HEIGHT);
    XF_MEMCPY(s->reserved_sub, buf + XF_OFF_HOST_RESERVED_SUB, sizeof(s->reserved_sub));
    pkt->order = buf[XF_OFF_ORDER];
    pkt->params_len = (uint8_t)(len - XF_PACKET_MIN_LEN);
    XF_MEMCPY(pkt->params, buf + XF_OFF_PARAMS, pkt->params_len);
}

/* The fields of a GCU packet already checked (header, length, CRC). */
static inline void xf__gcu_fields(const uint8_t *buf, size_t len, xf_gcu_packet *pkt)
{
    xf_gcu_main *m;
    xf_gcu_sub *s;
    m = &pkt->main;
    s = &pkt->sub;
    pkt->version = buf[XF_OFF_VERSION];
    m->gimbal_mode = buf[XF_OFF_GCU_GIMBAL_MODE];
    m->pod_status = xf_get_u16le(buf + XF_OFF_GCU_POD_STATUS);
    m->target_offset_x = xf_get_s16le(buf + XF_OFF_GCU_TARGET_OFFSET_X);
    m->target_offset_y = xf_get_s16le(buf + XF_OFF_GCU_TARGET_OFFSET_Y);
    m->rel_angle_x = xf_get_s16le(buf + XF_OFF_GCU_REL_ANGLE_X);
    m->rel_angle_y = xf_get_s16le(buf + XF_OFF_GCU_REL_ANGLE_Y);
    m->rel_angle_z = xf_get_s16le(buf + XF_OFF_GCU_REL_ANGLE_Z);
    m->cam_roll = xf_get_s16le(buf + XF_OFF_GCU_CAM_ROLL);
    m->cam_pitch = xf_get_s16le(buf + XF_OFF_GCU_CAM_PITCH);
    m->cam_yaw = xf_get_u16le(buf + XF_OFF_GCU_CAM_YAW);
    m->rate_x = xf_get_s16le(buf + XF_OFF_GCU_RATE_X);
    m->rate_y = xf_get_s16le(buf + XF_OFF_GCU_RATE_Y);
    m->rate_z = xf_get_s16le(buf + XF_OFF_GCU_RATE_Z);
    XF_MEMCPY(m->reserved_main, buf + XF_OFF_GCU_RESERVED_MAIN, sizeof(m->reserved_main));
    s->sub_header = buf[XF_OFF_GCU_SUB_HEADER];
    s->hw_version = buf[XF_OFF_GCU_HW_VERSION];
    s->fw_version = buf[XF_OFF_GCU_FW_VERSION];
    s->gimbal_code = buf[XF_OFF_GCU_GIMBAL_CODE];
    s->error_code = xf_get_u16le(buf + XF_OFF_GCU_ERROR_CODE);
    s->target_distance = xf_get_s32le(buf + XF_OFF_GCU_TARGET_DISTANCE);
    s->target_longitude = xf_get_s32le(buf + XF_OFF_GCU_TARGET_LONGITUDE);
    s->target_latitude = xf_get_s32le(buf + XF_OFF_GCU_TARGET_LATITUDE);
    s->target_altitude = xf_get_s32le(buf + XF_OFF_GCU_TARGET_ALTITUDE);
    s->zoom_cam1 = xf_get_u16le(buf + XF_OFF_GCU_ZOOM_CAM1);
    s->zoom_cam2 = xf_get_u16le(buf + XF_OFF_GCU_ZOOM_CAM2);
    s->thermal_status = buf[XF_OFF_GCU_THERMAL_STATUS];
    s->camera_status = xf_get_u16le(buf + XF_OFF_GCU_CAMERA_STATUS);
    s->time_zone = xf_u8_to_s8(buf[XF_OFF_GCU_TIME_ZONE]);
    XF_MEMCPY(s->reserved_sub, buf + XF_OFF_GCU_RESERVED_SUB, sizeof(s->reserved_sub));
    pkt->order = buf[XF_OFF_ORDER];
    pkt->params_len = (uint8_t)(len - XF_PACKET_MIN_LEN);
    XF_MEMCPY(pkt->params, buf + XF_OFF_PARAMS, pkt->params_len);
}

XF_API xf_err xf_host_unpack(const uint8_t *buf, size_t len, xf_host_packet *pkt)
{
    xf_err err;
    if (pkt == NULL) {
        return XF_ERR_ARG;
    }
    err = xf_packet_check(buf, len, XF_DIR_HOST);
    if (err == XF_OK) {
        xf__host_fields(buf, len, pkt);
    }
    return err;
}

XF_API xf_err xf_gcu_unpack(const uint8_t *buf, size_t len, xf_gcu_packet *pkt)
{
    xf_err err;
    if (pkt == NULL) {
        return XF_ERR_ARG;
    }
    err = xf_packet_check(buf, len, XF_DIR_GCU);
    if (err == XF_OK) {
        xf__gcu_fields(buf, len, pkt);
    }
    return err;
}

/* Header and length of a frame the parser returned, before decoding it. */
static inline xf_err xf__frame_ok(const xf_frame *f, uint8_t h0, uint8_t h1)
{
    if (f == NULL || f->data == NULL) {
        return XF_ERR_ARG;
    }
    if (f->len < XF_PACKET_MIN_LEN || f->len > XF_PACKET_MAX_LEN ||
        ((size_t)f->data[2] | ((size_t)f->data[3] << 8)) != f->len) {
        return XF_ERR_LENGTH;
    }
    return (f->data[0] == h0 && f->data[1] == h1) ? XF_OK : XF_ERR_HEADER;
}

XF_API xf_err xf_frame_gcu(const xf_frame *frame, xf_gcu_packet *pkt)
{
    xf_err err = (pkt == NULL) ? XF_ERR_ARG : xf__frame_ok(frame, XF_GCU_HEADER0, XF_GCU_HEADER1);
    if (err == XF_OK) {
        xf__gcu_fields(frame->data, frame->len, pkt);
    }
    return err;
}

XF_API xf_err xf_frame_host(const xf_frame *frame, xf_host_packet *pkt)
{
    xf_err err = (pkt == NULL) ? XF_ERR_ARG : xf__frame_ok(frame, XF_HOST_HEADER0, XF_HOST_HEADER1);
    if (err == XF_OK) {
        xf__host_fields(frame->data, frame->len, pkt);
    }
    return err;
}

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_PACKET_H */
