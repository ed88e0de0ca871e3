/**
 * @file
 * @brief One description of every field of the protocol, as data: where it is, how wide,
 * signed or not, its scale and engineering unit, the protocol versions that have it, the names
 * of its values or bits, and one line of what it means.
 *
 * The packers and unpackers (xf_packet.h, xf_command.h) stay explicit, field by field; this
 * table describes the same bytes for code that handles fields generically: the xfgcu program's
 * JSON and text, the Wireshark dissector's generator, the Python package and the field tables of
 * docs/protocol.md all read these rows, and a test holds every row against the packers. It is
 * metadata a firmware does not need: its definitions are emitted with the codec's
 * (`XF_IMPLEMENTATION`), each table in its own array, so a firmware that never references them
 * links none of them (`--gc-sections`; scripts/mcu_size.sh checks the symbols).
 *
 * Four groups of rows (::xf_wire_group): the packet's own bytes (length, version, order), the
 * host's two frames, the GCU's two frames, in wire order with the reserved blocks, and the
 * members of ::xf_command (an order's parameters, whose offsets depend on the order:
 * xf_order_info.fields).
 *
 * The unit rule (docs/protocol.md, "Units"): a field's engineering value is its wire integer
 * times 10^-decimals, in its unit ("deg", "deg/s", "m", "m/s", "m/s^2", "degC", "x", "h",
 * "ms", ...; "" for a plain number); the GCU's angular rates scale by the packet's version
 * (0.01 deg/s in V0.1, 0.1 deg/s in V0.2). A field whose unit depends on something the packet
 * does not carry (::XF_WIRE_CONTEXT: the control quantities, zoom_to's ZZ) has no engineering
 * value: it is its wire integer in every view.
 *
 * The functions keep no state, never allocate and never block; the strings are static.
 */
#ifndef XF_FIELDS_H
#define XF_FIELDS_H

#include <stddef.h>
#include <stdint.h>
#include "xf_bytes.h"
#include "xf_command.h"
#include "xf_config.h"
#include "xf_error.h"
#include "xf_protocol.h"

XF_BEGIN_DECLS

/** Which rows: xf_wire_fields(). */
typedef enum xf_wire_group {
    XF_WIRE_PACKET = 0, /**< the packet's own bytes, either direction: length, version, order */
    XF_WIRE_HOST = 1,   /**< the host's main and sub frame, bytes 5-68, reserved blocks included */
    XF_WIRE_GCU = 2,    /**< the GCU's main and sub frame, bytes 5-68, reserved blocks included */
    XF_WIRE_PARAMS = 3  /**< the members of ::xf_command, in ::xf_field order (offset 0: see xf_order_info.fields) */
} xf_wire_group;

/** What a field's integer is (xf_wire_field.kind). */
typedef enum xf_wire_kind {
    XF_WIRE_NUMBER = 0,  /**< a quantity: its engineering value is the integer x 10^-decimals, in `unit` */
    XF_WIRE_CONTEXT = 1, /**< a number whose unit the packet does not say (the control quantities: angle or rate
                              by the gimbal's mode; zoom_to's ZZ: factor or fraction by its sign): the wire integer */
    XF_WIRE_ENUM = 2,    /**< a code: value_name() names its values */
    XF_WIRE_FLAGS = 3,   /**< a word of flags: `bits` names them */
    XF_WIRE_BYTE = 4,    /**< a marker byte (a sub frame header, a camera mask): shown in hex */
    XF_WIRE_RESERVED = 5 /**< reserved bytes, not a field: `width` is the block's length */
} xf_wire_kind;

/** A named bit (or a few adjacent bits that hold a number) of a flag word. */
typedef struct xf_wire_bit {
    uint16_t mask;        /**< the bit; several adjacent bits hold a number (camera_status's pip_mode) */
    const char *name;     /**< canonical name: "tracking_ok" */
    const char *meaning;  /**< one line: what it means when set */
    const char *constant; /**< the codec's macro of the mask: "XF_POD_TRACKING_OK" */
} xf_wire_bit;

/** One field (one row of the table). */
typedef struct xf_wire_field {
    const char *name;                         /**< canonical name (docs/protocol.md): the JSON key */
    const char *unit;                         /**< engineering unit ("deg", "m/s^2", "x", ...); "" for none */
    const char *meaning;                      /**< one line of what it means */
    const char *constant;                     /**< the codec's name of its place: its offset macro
                                                   ("XF_OFF_GCU_CAM_PITCH"), or its ::xf_field ("XF_F_ZOOM") */
    const char *(*value_name)(uint8_t value); /**< ::XF_WIRE_ENUM: the codec's name of a value (NULL for one it
                                                   does not know); NULL for the other kinds */
    const xf_wire_bit *bits;                  /**< ::XF_WIRE_FLAGS: its named bits; NULL otherwise */
    uint8_t nbits;                            /**< the number of `bits` */
    uint8_t group;                            /**< ::xf_wire_group */
    uint8_t offset;                           /**< its first byte in the packet (XF_OFF_*); 0 for a parameter */
    uint8_t width;                            /**< bytes: 1, 2 or 4; a reserved block: its length */
    uint8_t is_signed;                        /**< 1: a two's complement integer */
    uint8_t kind;                             /**< ::xf_wire_kind */
    uint8_t decimals[2];                      /**< the scale, 10^-decimals, in V0.1 [0] and from V0.2 on [1] */
    uint8_t since;                            /**< the first protocol version that has it (1 or 2); before it,
                                                   its bytes are reserved */
} xf_wire_field;

/**
 * The rows of a group, in wire order (the host's and the GCU's frames) or in ::xf_field order
 * (the parameters).
 * @param group  ::xf_wire_group
 * @param count  receives the number of rows (may be NULL)
 * @return the first row, or NULL (count 0) for a value that is no group
 */
XF_API const xf_wire_field *xf_wire_fields(xf_wire_group group, size_t *count);
/**
 * The group of the frames of a direction.
 * @param dir  ::XF_DIR_HOST or ::XF_DIR_GCU
 * @return ::XF_WIRE_HOST or ::XF_WIRE_GCU (any other value: ::XF_WIRE_GCU)
 */
XF_API xf_wire_group xf_wire_frames(xf_direction dir);
/**
 * The row named @p name in a group (a reserved block is found as "reserved_main" and
 * "reserved_sub").
 * @param group  ::xf_wire_group
 * @param name   the canonical name (may be NULL: not found)
 * @return the row, or NULL
 */
XF_API const xf_wire_field *xf_wire_field_find(xf_wire_group group, const char *name);
/**
 * The row of a parameter member of ::xf_command.
 * @param member  the member
 * @return its row, or NULL for ::XF_F_NONE and values outside ::xf_field
 */
XF_API const xf_wire_field *xf_wire_param(xf_field member);
/**
 * Whether a packet of @p version has the field (V0.2's thermal_status, camera_status and
 * time_zone are reserved bytes in V0.1). Version 0 counts as 1.
 * @param f        the row
 * @param version  the packet's version byte
 * @return 1 or 0 (0 for a NULL @p f)
 */
XF_API int xf_wire_field_present(const xf_wire_field *f, uint8_t version);
/**
 * The field's integer in a packet's bytes, read little-endian with the row's sign.
 * @param f    the row (not a reserved block)
 * @param buf  the packet (at least offset + width bytes), or an order's parameter bytes with
 *   the row's offset where the parameter is
 * @return the wire integer (0 for a NULL argument)
 */
XF_API int64_t xf_wire_field_get(const xf_wire_field *f, const uint8_t *buf);
/**
 * Write a field's integer into a packet's bytes, little-endian (the CRC is not updated).
 * @param f    the row (not a reserved block)
 * @param buf  the packet
 * @param raw  the value, within xf_wire_field_range() (it is cut to the width otherwise)
 */
XF_API void xf_wire_field_put(const xf_wire_field *f, uint8_t *buf, int64_t raw);
/**
 * The range of a field's wire integer: its type's.
 * @param f   the row
 * @param lo  receives the lowest value
 * @param hi  receives the highest value
 */
XF_API void xf_wire_field_range(const xf_wire_field *f, int64_t *lo, int64_t *hi);
/**
 * The decimals of a field's scale in a packet of @p version (the GCU's rates: 2 in V0.1, 1
 * from V0.2 on): its engineering value is the integer / 10^decimals.
 * @param f        the row
 * @param version  the packet's version byte (0 counts as 1)
 * @return 0..7 (0 for a NULL @p f, and for the kinds without an engineering value)
 */
XF_API unsigned xf_wire_field_decimals(const xf_wire_field *f, uint8_t version);
/**
 * A wire integer as its engineering value (the unit rule above).
 * @param f        the row
 * @param raw      the wire integer
 * @param version  the packet's version byte
 * @return raw / 10^decimals: for a field of ::XF_WIRE_NUMBER, its value in the row's unit;
 *   for the others, the integer itself
 */
XF_API double xf_wire_field_value(const xf_wire_field *f, int64_t raw, uint8_t version);
/**
 * An engineering value as the wire integer that xf_wire_field_value() turns into it: exact,
 * never rounded to another value.
 * @param f        the row
 * @param value    the engineering value
 * @param version  the packet's version byte
 * @param raw      receives the wire integer (left alone on error)
 * @return ::XF_OK; ::XF_ERR_ARG (a NULL argument, NaN or infinity, or a value that is not a
 *   whole number of steps of 10^-decimals: 12.345 deg for a field of 0.01 deg); ::XF_ERR_RANGE
 *   (outside xf_wire_field_range() once scaled)
 */
XF_API xf_err xf_wire_field_raw(const xf_wire_field *f, double value, uint8_t version, int64_t *raw);

#if XF_EMIT_DEFINITIONS

/* Every string of the table is in an array of its own (one per row, one per bit: "name\0unit\0
 * meaning"), never a string literal of the codec's translation unit: literals share a section,
 * which any one use keeps in a firmware image. Unreferenced, each array goes with its table. */

/* clang-format off */
/* The bits of the flag words: X(word, mask, name, meaning). */
#define XF__BITS_STATUS(X) \
    X(status, XF_STATUS_INS_VALID, ins_valid, "the carrier's INS data (bytes 12-29) is valid") \
    X(status, XF_STATUS_CTRL_VALID, ctrl_valid, "the control quantities (bytes 5-10) are valid")
#define XF__BITS_POD(X) \
    X(pod, XF_POD_TRACKING_OK, tracking_ok, "tracking succeeds: the target offsets are valid") \
    X(pod, XF_POD_TARGET_VALID, target_valid, "the range and the target's coordinates are valid") \
    X(pod, XF_POD_RANGING_ON, ranging_on, "laser ranging is on") \
    X(pod, XF_POD_NIGHT_VISION_ON, night_vision_on, "night vision is on") \
    X(pod, XF_POD_LIGHTING_ON, lighting_on, "the fill light is on") \
    X(pod, XF_POD_UPWARD_MOUNT, upward_mount, "powered on facing up (0: hanging, facing down)")
#define XF__BITS_ERROR(X) \
    X(error, XF_ERROR_POD_HW_FAULT, pod_hw_fault, "pod hardware fault") \
    X(error, XF_ERROR_MAVLINK_RATE, mavlink_rate_abnormal, "MAVLink message rate abnormal") \
    X(error, XF_ERROR_GNSS_NOT_FIXED, gnss_not_positioned, "GNSS has no position fix") \
    X(error, XF_ERROR_GCU_HW_FAULT, gcu_hw_fault, "GCU hardware fault")
#define XF__BITS_THERMAL(X) \
    X(thermal, XF_THERMAL_LOW_TEMP_ALARM, low_temp_alarm, "low-temperature alarm") \
    X(thermal, XF_THERMAL_HIGH_TEMP_ALARM, high_temp_alarm, "high-temperature alarm") \
    X(thermal, XF_THERMAL_SPOT_ON, spot_temp_on, "spot temperature measurement on") \
    X(thermal, XF_THERMAL_ISOTHERM_ON, isotherm_on, "isotherm on") \
    X(thermal, XF_THERMAL_ALARM_ON, temp_alarm_on, "temperature alarm on") \
    X(thermal, XF_THERMAL_AREA_ON, area_temp_on, "area temperature measurement on") \
    X(thermal, XF_THERMAL_MEASURE_AVAILABLE, temp_measurement_available, "temperature measurement available")
#define XF__BITS_CAMERA(X) \
    X(camera, XF_CAMERA_PIP_MASK, pip_mode, "picture-in-picture mode, a number 0-7") \
    X(camera, XF_CAMERA_RECORDING, recording, "recording") \
    X(camera, XF_CAMERA_AUTO_FLIP_OFF, auto_flip_off, "image auto-flip off (0: on)") \
    X(camera, XF_CAMERA_OSD_TARGET, osd_shows_target, "the OSD shows the target's coordinates (0: the carrier's)") \
    X(camera, XF_CAMERA_OSD_ON, osd_on, "OSD on") \
    X(camera, XF_CAMERA_DIGITAL_ZOOM_ON, digital_zoom_on, "digital zoom on") \
    X(camera, XF_CAMERA_DETECTION_ON, target_detection_on, "target detection on")

/* The fields: X(group, OFFSET, name, width, signed, kind, decimals V0.1, decimals V0.2, since, unit,
 * value names, bits, meaning). */
#define XF__ROWS_PACKET(X) \
    X(packet, XF_OFF_LENGTH, length, 2, 0, NUMBER, 0, 0, 1, "", NULL, none, "the whole packet's length in bytes, header and CRC included") \
    X(packet, XF_OFF_VERSION, version, 1, 0, NUMBER, 0, 0, 1, "", NULL, none, "protocol version: 1 (V0.1) or 2 (V0.2)") \
    X(packet, XF_OFF_ORDER, order, 1, 0, ENUM, 0, 0, 1, "", xf_order_name, none, "the order (command) sent, or answered by the GCU's feedback")
#define XF__ROWS_HOST(X) \
    X(host, XF_OFF_HOST_ROLL_CTRL, roll_ctrl, 2, 1, CONTEXT, 0, 0, 1, "", NULL, none, "roll control quantity: an angle (0.01 deg) or a rate (0.1 deg/s / zoom), by the mode") \
    X(host, XF_OFF_HOST_PITCH_CTRL, pitch_ctrl, 2, 1, CONTEXT, 0, 0, 1, "", NULL, none, "pitch control quantity: an angle (0.01 deg) or a rate (0.1 deg/s / zoom), by the mode") \
    X(host, XF_OFF_HOST_YAW_CTRL, yaw_ctrl, 2, 1, CONTEXT, 0, 0, 1, "", NULL, none, "yaw control quantity: an angle (0.01 deg) or a rate (0.1 deg/s / zoom), by the mode") \
    X(host, XF_OFF_HOST_STATUS, status, 1, 0, FLAGS, 0, 0, 1, "", NULL, status, "validity flags of the carrier data and the control quantities") \
    X(host, XF_OFF_HOST_CARRIER_ROLL, carrier_roll, 2, 1, NUMBER, 2, 2, 1, "deg", NULL, none, "carrier's absolute roll, [-180, 180)") \
    X(host, XF_OFF_HOST_CARRIER_PITCH, carrier_pitch, 2, 1, NUMBER, 2, 2, 1, "deg", NULL, none, "carrier's absolute pitch, [-90, 90]") \
    X(host, XF_OFF_HOST_CARRIER_YAW, carrier_yaw, 2, 0, NUMBER, 2, 2, 1, "deg", NULL, none, "carrier's absolute yaw, [0, 360)") \
    X(host, XF_OFF_HOST_ACCEL_NORTH, accel_north, 2, 1, NUMBER, 2, 2, 1, "m/s^2", NULL, none, "carrier's acceleration, north positive, gravity excluded") \
    X(host, XF_OFF_HOST_ACCEL_EAST, accel_east, 2, 1, NUMBER, 2, 2, 1, "m/s^2", NULL, none, "carrier's acceleration, east positive") \
    X(host, XF_OFF_HOST_ACCEL_UP, accel_up, 2, 1, NUMBER, 2, 2, 1, "m/s^2", NULL, none, "carrier's acceleration, up positive") \
    X(host, XF_OFF_HOST_VEL_NORTH, vel_north, 2, 1, NUMBER, 2, 2, 1, "m/s", NULL, none, "carrier's velocity, north positive") \
    X(host, XF_OFF_HOST_VEL_EAST, vel_east, 2, 1, NUMBER, 2, 2, 1, "m/s", NULL, none, "carrier's velocity, east positive") \
    X(host, XF_OFF_HOST_VEL_UP, vel_up, 2, 1, NUMBER, 2, 2, 1, "m/s", NULL, none, "carrier's velocity, up positive") \
    X(host, XF_OFF_HOST_SUB_REQUEST, sub_request, 1, 0, BYTE, 0, 0, 1, "", NULL, none, "header of the sub frame the GCU is asked to send back (0x01)") \
    X(host, XF_OFF_HOST_RESERVED_MAIN, reserved_main, 6, 0, RESERVED, 0, 0, 1, "", NULL, none, "reserved (0)") \
    X(host, XF_OFF_HOST_SUB_HEADER, sub_header, 1, 0, BYTE, 0, 0, 1, "", NULL, none, "sub frame header: 0x01, or 0x00 when the whole frame is empty") \
    X(host, XF_OFF_HOST_LONGITUDE, longitude, 4, 1, NUMBER, 7, 7, 1, "deg", NULL, none, "carrier's longitude") \
    X(host, XF_OFF_HOST_LATITUDE, latitude, 4, 1, NUMBER, 7, 7, 1, "deg", NULL, none, "carrier's latitude") \
    X(host, XF_OFF_HOST_ALTITUDE, altitude, 4, 1, NUMBER, 3, 3, 1, "m", NULL, none, "carrier's altitude above sea level") \
    X(host, XF_OFF_HOST_SATELLITES, satellites, 1, 0, NUMBER, 0, 0, 1, "", NULL, none, "satellites in use") \
    X(host, XF_OFF_HOST_GNSS_MS, gnss_ms, 4, 0, NUMBER, 0, 0, 1, "ms", NULL, none, "GNSS time of week, [0, 604800000)") \
    X(host, XF_OFF_HOST_GNSS_WEEK, gnss_week, 2, 1, NUMBER, 0, 0, 1, "week", NULL, none, "GNSS week number (weeks since 1980-01-06)") \
    X(host, XF_OFF_HOST_RELATIVE_HEIGHT, relative_height, 4, 1, NUMBER, 3, 3, 1, "m", NULL, none, "carrier's relative height (0 when not needed)") \
    X(host, XF_OFF_HOST_RESERVED_SUB, reserved_sub, 8, 0, RESERVED, 0, 0, 1, "", NULL, none, "reserved (0)")
#define XF__ROWS_GCU(X) \
    X(gcu, XF_OFF_GCU_GIMBAL_MODE, gimbal_mode, 1, 0, ENUM, 0, 0, 1, "", xf_mode_name, none, "the gimbal's mode") \
    X(gcu, XF_OFF_GCU_POD_STATUS, pod_status, 2, 0, FLAGS, 0, 0, 1, "", NULL, pod, "pod status flags (their byte order: docs/protocol.md 11.7)") \
    X(gcu, XF_OFF_GCU_TARGET_OFFSET_X, target_offset_x, 2, 1, NUMBER, 0, 0, 1, "", NULL, none, "tracked target's offset from the image centre, [-1000, 1000], right positive") \
    X(gcu, XF_OFF_GCU_TARGET_OFFSET_Y, target_offset_y, 2, 1, NUMBER, 0, 0, 1, "", NULL, none, "tracked target's offset from the image centre, [-1000, 1000], down positive") \
    X(gcu, XF_OFF_GCU_REL_ANGLE_X, rel_angle_x, 2, 1, NUMBER, 2, 2, 1, "deg", NULL, none, "camera's X-axis angle relative to the carrier") \
    X(gcu, XF_OFF_GCU_REL_ANGLE_Y, rel_angle_y, 2, 1, NUMBER, 2, 2, 1, "deg", NULL, none, "camera's Y-axis angle relative to the carrier") \
    X(gcu, XF_OFF_GCU_REL_ANGLE_Z, rel_angle_z, 2, 1, NUMBER, 2, 2, 1, "deg", NULL, none, "camera's Z-axis angle relative to the carrier") \
    X(gcu, XF_OFF_GCU_CAM_ROLL, cam_roll, 2, 1, NUMBER, 2, 2, 1, "deg", NULL, none, "camera's absolute roll") \
    X(gcu, XF_OFF_GCU_CAM_PITCH, cam_pitch, 2, 1, NUMBER, 2, 2, 1, "deg", NULL, none, "camera's absolute pitch") \
    X(gcu, XF_OFF_GCU_CAM_YAW, cam_yaw, 2, 0, NUMBER, 2, 2, 1, "deg", NULL, none, "camera's absolute yaw, [0, 360)") \
    X(gcu, XF_OFF_GCU_RATE_X, rate_x, 2, 1, NUMBER, 2, 1, 1, "deg/s", NULL, none, "camera's absolute angular velocity about X") \
    X(gcu, XF_OFF_GCU_RATE_Y, rate_y, 2, 1, NUMBER, 2, 1, 1, "deg/s", NULL, none, "camera's absolute angular velocity about Y") \
    X(gcu, XF_OFF_GCU_RATE_Z, rate_z, 2, 1, NUMBER, 2, 1, 1, "deg/s", NULL, none, "camera's absolute angular velocity about Z") \
    X(gcu, XF_OFF_GCU_RESERVED_MAIN, reserved_main, 7, 0, RESERVED, 0, 0, 1, "", NULL, none, "reserved") \
    X(gcu, XF_OFF_GCU_SUB_HEADER, sub_header, 1, 0, BYTE, 0, 0, 1, "", NULL, none, "sub frame header: 0x01, or 0x00 when the host asked for an unknown one") \
    X(gcu, XF_OFF_GCU_HW_VERSION, hw_version, 1, 0, NUMBER, 1, 1, 1, "", NULL, none, "hardware version, in tenths (31: 3.1)") \
    X(gcu, XF_OFF_GCU_FW_VERSION, fw_version, 1, 0, NUMBER, 1, 1, 1, "", NULL, none, "firmware version, in tenths (50: 5.0)") \
    X(gcu, XF_OFF_GCU_GIMBAL_CODE, gimbal_code, 1, 0, ENUM, 0, 0, 1, "", xf_gimbal_model, none, "the gimbal's model code") \
    X(gcu, XF_OFF_GCU_ERROR_CODE, error_code, 2, 0, FLAGS, 0, 0, 1, "", NULL, error, "fault flags (V0.2; reserved in V0.1)") \
    X(gcu, XF_OFF_GCU_TARGET_DISTANCE, target_distance, 4, 1, NUMBER, 1, 1, 1, "m", NULL, none, "laser range to the target; 0 or less (-1 m, 0 m): no valid measurement") \
    X(gcu, XF_OFF_GCU_TARGET_LONGITUDE, target_longitude, 4, 1, NUMBER, 7, 7, 1, "deg", NULL, none, "target's longitude") \
    X(gcu, XF_OFF_GCU_TARGET_LATITUDE, target_latitude, 4, 1, NUMBER, 7, 7, 1, "deg", NULL, none, "target's latitude") \
    X(gcu, XF_OFF_GCU_TARGET_ALTITUDE, target_altitude, 4, 1, NUMBER, 3, 3, 1, "m", NULL, none, "target's altitude") \
    X(gcu, XF_OFF_GCU_ZOOM_CAM1, zoom_cam1, 2, 0, NUMBER, 1, 1, 1, "x", NULL, none, "camera 1's zoom (the visible-light zoom camera by default)") \
    X(gcu, XF_OFF_GCU_ZOOM_CAM2, zoom_cam2, 2, 0, NUMBER, 1, 1, 1, "x", NULL, none, "camera 2's zoom (the thermal camera by default)") \
    X(gcu, XF_OFF_GCU_THERMAL_STATUS, thermal_status, 1, 0, FLAGS, 0, 0, 2, "", NULL, thermal, "thermal camera status flags") \
    X(gcu, XF_OFF_GCU_CAMERA_STATUS, camera_status, 2, 0, FLAGS, 0, 0, 2, "", NULL, camera, "camera status: picture-in-picture mode and flags") \
    X(gcu, XF_OFF_GCU_TIME_ZONE, time_zone, 1, 1, NUMBER, 0, 0, 2, "h", NULL, none, "the GCU's time zone, hours from UTC") \
    X(gcu, XF_OFF_GCU_RESERVED_SUB, reserved_sub, 2, 0, RESERVED, 0, 0, 1, "", NULL, none, "reserved")
/* In xf_field order: xf_wire_param() indexes it. */
#define XF__ROWS_PARAMS(X) \
    X(param, XF_F_CAMERAS, cameras, 1, 0, BYTE, 0, 0, 1, "", NULL, none, "KK: camera mask, bit n = camera n+1") \
    X(param, XF_F_VALUE, value, 1, 0, NUMBER, 0, 0, 1, "", NULL, none, "TT: an action, mode, level or on/off, by order") \
    X(param, XF_F_HOURS, hours, 1, 1, NUMBER, 0, 0, 2, "h", NULL, none, "time zone, hours from UTC, [-12, 14]") \
    X(param, XF_F_X0, x0, 2, 0, NUMBER, 0, 0, 1, "", NULL, none, "box left edge, or the point's x, on the [0, 10000] screen grid") \
    X(param, XF_F_Y0, y0, 2, 0, NUMBER, 0, 0, 1, "", NULL, none, "box top edge, or the point's y, on the [0, 10000] screen grid") \
    X(param, XF_F_X1, x1, 2, 0, NUMBER, 0, 0, 1, "", NULL, none, "box right edge, [x0, 10000]") \
    X(param, XF_F_Y1, y1, 2, 0, NUMBER, 0, 0, 1, "", NULL, none, "box bottom edge, [y0, 10000]") \
    X(param, XF_F_DX, dx, 2, 1, NUMBER, 0, 0, 1, "", NULL, none, "target's offset from the screen centre, [-1024, 1024]; both >= 3071: lost") \
    X(param, XF_F_DY, dy, 2, 1, NUMBER, 0, 0, 1, "", NULL, none, "target's offset from the screen centre, [-1024, 1024]; both >= 3071: lost") \
    X(param, XF_F_ZOOM, zoom, 2, 1, CONTEXT, 0, 0, 1, "", NULL, none, "ZZ: -(factor x 10) when negative; a fraction of the zoom range, 1-10000, when positive") \
    X(param, XF_F_TEMP_HIGH, temp_high, 2, 1, NUMBER, 1, 1, 2, "degC", NULL, none, "high temperature limit") \
    X(param, XF_F_TEMP_LOW, temp_low, 2, 1, NUMBER, 1, 1, 2, "degC", NULL, none, "low temperature limit, not above temp_high when on") \
    X(param, XF_F_LONGITUDE, longitude, 4, 1, NUMBER, 7, 7, 1, "deg", NULL, none, "longitude to gaze at") \
    X(param, XF_F_LATITUDE, latitude, 4, 1, NUMBER, 7, 7, 1, "deg", NULL, none, "latitude to gaze at") \
    X(param, XF_F_ALTITUDE, altitude, 4, 1, NUMBER, 3, 3, 1, "m", NULL, none, "altitude to gaze at")
/* clang-format on */

#define XF__BIT_TEXT(word, mask, name, meaning)                                                                        \
    static const char xf__wb_##word##_##name[] = #name "\0" meaning "\0" #mask;
#define XF__BIT_ROW(word, mask, name, meaning)                                                                         \
    {(uint16_t)(mask), xf__wb_##word##_##name, xf__wb_##word##_##name + sizeof(#name),                                 \
     xf__wb_##word##_##name + sizeof(#name) + sizeof(meaning)},
XF__BITS_STATUS(XF__BIT_TEXT)
XF__BITS_POD(XF__BIT_TEXT)
XF__BITS_ERROR(XF__BIT_TEXT)
XF__BITS_THERMAL(XF__BIT_TEXT)
XF__BITS_CAMERA(XF__BIT_TEXT)
static const xf_wire_bit xf__bits_status[] = {XF__BITS_STATUS(XF__BIT_ROW)};
static const xf_wire_bit xf__bits_pod[] = {XF__BITS_POD(XF__BIT_ROW)};
static const xf_wire_bit xf__bits_error[] = {XF__BITS_ERROR(XF__BIT_ROW)};
static const xf_wire_bit xf__bits_thermal[] = {XF__BITS_THERMAL(XF__BIT_ROW)};
static const xf_wire_bit xf__bits_camera[] = {XF__BITS_CAMERA(XF__BIT_ROW)};

/* A row's bits by the word's name: its array and count, or none. */
#define XF__BITS_OF(word)   xf__bits_##word, (uint8_t)(sizeof(xf__bits_##word) / sizeof(xf__bits_##word[0]))
#define XF__BITS_OF_status  XF__BITS_OF(status)
#define XF__BITS_OF_pod     XF__BITS_OF(pod)
#define XF__BITS_OF_error   XF__BITS_OF(error)
#define XF__BITS_OF_thermal XF__BITS_OF(thermal)
#define XF__BITS_OF_camera  XF__BITS_OF(camera)
#define XF__BITS_OF_none    NULL, 0
#define XF__FIELD_TEXT(group, off, name, width, sign, kind, d1, d2, since, unit, names, bits, meaning)                 \
    static const char xf__wf_##group##_##name[] = #name "\0" unit "\0" meaning "\0" #off;
#define XF__FIELD_ROW(group, off, name, width, sign, kind, d1, d2, since, unit, names, bits, meaning)                  \
    {xf__wf_##group##_##name,                                                                                          \
     xf__wf_##group##_##name + sizeof(#name),                                                                          \
     xf__wf_##group##_##name + sizeof(#name) + sizeof(unit),                                                           \
     xf__wf_##group##_##name + sizeof(#name) + sizeof(unit) + sizeof(meaning),                                         \
     names,                                                                                                            \
     XF__BITS_OF_##bits,                                                                                               \
     (uint8_t)XF__GROUP_##group,                                                                                       \
     (uint8_t)XF__OFF_##group(off),                                                                                    \
     (width),                                                                                                          \
     (sign),                                                                                                           \
     (uint8_t)XF_WIRE_##kind,                                                                                          \
     {(d1), (d2)},                                                                                                     \
     (since)},
#define XF__GROUP_packet    XF_WIRE_PACKET
#define XF__GROUP_host      XF_WIRE_HOST
#define XF__GROUP_gcu       XF_WIRE_GCU
#define XF__GROUP_param     XF_WIRE_PARAMS
#define XF__OFF_packet(off) (off)
#define XF__OFF_host(off)   (off)
#define XF__OFF_gcu(off)    (off)
#define XF__OFF_param(off)  0 /* the member's ::xf_field: its offset depends on the order */

XF__ROWS_PACKET(XF__FIELD_TEXT)
XF__ROWS_HOST(XF__FIELD_TEXT)
XF__ROWS_GCU(XF__FIELD_TEXT)
XF__ROWS_PARAMS(XF__FIELD_TEXT)
static const xf_wire_field xf__wire_packet[] = {XF__ROWS_PACKET(XF__FIELD_ROW)};
static const xf_wire_field xf__wire_host[] = {XF__ROWS_HOST(XF__FIELD_ROW)};
static const xf_wire_field xf__wire_gcu[] = {XF__ROWS_GCU(XF__FIELD_ROW)};
static const xf_wire_field xf__wire_params[] = {XF__ROWS_PARAMS(XF__FIELD_ROW)};

#define XF__WIRE_COUNT(a) (sizeof(a) / sizeof((a)[0]))
XF_STATIC_ASSERT(XF__WIRE_COUNT(xf__wire_params) == (size_t)XF_F_ALTITUDE + 1u, one_param_row_per_member);

XF_API const xf_wire_field *xf_wire_fields(xf_wire_group group, size_t *count)
{
    const xf_wire_field *rows = NULL;
    size_t n = 0;
    switch (group) {
    case XF_WIRE_PACKET: rows = xf__wire_packet, n = XF__WIRE_COUNT(xf__wire_packet); break;
    case XF_WIRE_HOST: rows = xf__wire_host, n = XF__WIRE_COUNT(xf__wire_host); break;
    case XF_WIRE_GCU: rows = xf__wire_gcu, n = XF__WIRE_COUNT(xf__wire_gcu); break;
    case XF_WIRE_PARAMS: rows = xf__wire_params, n = XF__WIRE_COUNT(xf__wire_params); break;
    default: break;
    }
    if (count != NULL) {
        *count = n;
    }
    return rows;
}

XF_API xf_wire_group xf_wire_frames(xf_direction dir) { return (dir == XF_DIR_HOST) ? XF_WIRE_HOST : XF_WIRE_GCU; }

XF_API const xf_wire_field *xf_wire_field_find(xf_wire_group group, const char *name)
{
    size_t i, k, n;
    const xf_wire_field *rows = xf_wire_fields(group, &n);
    for (i = 0; name != NULL && i < n; i++) {
        for (k = 0; rows[i].name[k] != '\0' && rows[i].name[k] == name[k]; k++) {
        }
        if (rows[i].name[k] == '\0' && name[k] == '\0') {
            return &rows[i];
        }
    }
    return NULL;
}

XF_API const xf_wire_field *xf_wire_param(xf_field member)
{
    return ((unsigned)member <= (unsigned)XF_F_ALTITUDE) ? &xf__wire_params[(unsigned)member] : NULL;
}

XF_API int xf_wire_field_present(const xf_wire_field *f, uint8_t version)
{
    return f != NULL && ((version == 0u) ? 1u : version) >= f->since;
}

XF_API int64_t xf_wire_field_get(const xf_wire_field *f, const uint8_t *buf)
{
    const uint8_t *p;
    if (f == NULL || buf == NULL) {
        return 0;
    }
    p = buf + f->offset;
    switch (f->width) {
    case 1u: return f->is_signed ? (int64_t)xf_u8_to_s8(p[0]) : (int64_t)p[0];
    case 2u: return f->is_signed ? (int64_t)xf_get_s16le(p) : (int64_t)xf_get_u16le(p);
    default: return f->is_signed ? (int64_t)xf_get_s32le(p) : (int64_t)xf_get_u32le(p);
    }
}

XF_API void xf_wire_field_put(const xf_wire_field *f, uint8_t *buf, int64_t raw)
{
    uint8_t *p;
    if (f == NULL || buf == NULL) {
        return;
    }
    p = buf + f->offset;
    switch (f->width) {
    case 1u: p[0] = (uint8_t)((uint64_t)raw & 0xFFu); break;
    case 2u: xf_put_u16le(p, (uint16_t)((uint64_t)raw & 0xFFFFu)); break;
    default: xf_put_u32le(p, (uint32_t)((uint64_t)raw & 0xFFFFFFFFu)); break;
    }
}

XF_API void xf_wire_field_range(const xf_wire_field *f, int64_t *lo, int64_t *hi)
{
    int64_t span = (f != NULL && f->width <= 4u) ? ((int64_t)1 << (8u * f->width)) : 1; /* 2^bits */
    int sign = f != NULL && f->is_signed;
    if (lo != NULL) {
        *lo = sign ? -span / 2 : 0;
    }
    if (hi != NULL) {
        *hi = sign ? span / 2 - 1 : span - 1;
    }
}

XF_API unsigned xf_wire_field_decimals(const xf_wire_field *f, uint8_t version)
{
    if (f == NULL || f->kind != (uint8_t)XF_WIRE_NUMBER) {
        return 0u;
    }
    return f->decimals[version >= XF_PROTOCOL_V2];
}

/* 10^n for the decimals of the table (0..7): exact doubles. */
static inline double xf__pow10(unsigned n)
{
    double p = 1.0;
    for (; n > 0u; n--) {
        p *= 10.0;
    }
    return p;
}

XF_API double xf_wire_field_value(const xf_wire_field *f, int64_t raw, uint8_t version)
{
    /* a division by an exact power of ten: the double nearest the decimal raw / 10^n */
    return (double)raw / xf__pow10(xf_wire_field_decimals(f, version));
}

XF_API xf_err xf_wire_field_raw(const xf_wire_field *f, double value, uint8_t version, int64_t *raw)
{
    int64_t lo, hi, r;
    double scaled;
    if (f == NULL || raw == NULL || value != value || value > 1e18 || value < -1e18) {
        return XF_ERR_ARG; /* NaN, infinities and absurd values */
    }
    scaled = value * xf__pow10(xf_wire_field_decimals(f, version));
    r = (int64_t)((scaled >= 0.0) ? (scaled + 0.5) : (scaled - 0.5));
    /* what a decimal text of the value gives back, within a double's error; a step more is a
     * value the wire cannot hold */
    if ((double)r - scaled > 1e-3 || scaled - (double)r > 1e-3) {
        return XF_ERR_ARG;
    }
    xf_wire_field_range(f, &lo, &hi);
    if (r < lo || r > hi) {
        return XF_ERR_RANGE;
    }
    *raw = r;
    return XF_OK;
}

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_FIELDS_H */
