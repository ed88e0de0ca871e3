/**
 * @file
 * @brief Constants of the GCU private protocol V2.0.4 (protocol V0.1) and
 * V0.2, with the canonical names of docs/protocol.md.
 *
 * Headers, sizes and byte offsets (docs/protocol.md §2-§6), protocol
 * versions, orders (§7, §10), gimbal modes and status bits, camera masks,
 * feedback states, the gimbal model names, and the byte order of the pod
 * status word (§11.7). The functions keep no state and never block.
 */
#ifndef XF_PROTOCOL_H
#define XF_PROTOCOL_H

#include <stddef.h>
#include <stdint.h>
#include "xf_config.h"

XF_BEGIN_DECLS

/* ---- framing ---------------------------------------------------------- */
#define XF_HOST_HEADER0 0xA8u /**< host -> GCU, byte 0 */
#define XF_HOST_HEADER1 0xE5u /**< host -> GCU, byte 1 */
#define XF_GCU_HEADER0  0x8Au /**< GCU -> host, byte 0 */
#define XF_GCU_HEADER1  0x5Eu /**< GCU -> host, byte 1 */

#define XF_PACKET_MIN_LEN 72u  /**< header..order + CRC, no parameter */
#define XF_PACKET_LIMIT   255u /**< the protocol's own upper bound (the vendor CRC takes a uint8_t length) */
#define XF_PARAMS_MAX                                                                                                  \
    (XF_PACKET_MAX_LEN -                                                                                               \
     XF_PACKET_MIN_LEN) /**< parameter / feedback bytes of the longest packet this build packs and accepts */
/** Room for parameter / feedback bytes in a packet struct: the protocol's
 * most, whatever ::XF_PACKET_MAX_LEN, so that no packet struct changes with
 * an option (only ::XF_PARAMS_MAX of it is used). */
#define XF_PARAMS_CAP       (XF_PACKET_LIMIT - XF_PACKET_MIN_LEN)
#define XF_PARAMS_KNOWN_MAX 12u /**< longest parameter block of any known order (gaze_geo) */

/* byte offsets */
#define XF_OFF_LENGTH  2u  /**< `length` U16, bytes 2-3: the whole packet's size, header and CRC included */
#define XF_OFF_VERSION 4u  /**< `version` U8: the protocol version (::XF_PROTOCOL_V1, ::XF_PROTOCOL_V2) */
#define XF_OFF_MAIN    5u  /**< first byte of the main frame, bytes 5-36 */
#define XF_OFF_SUB     37u /**< first byte of the sub frame, bytes 37-68 */
#define XF_OFF_ORDER   69u /**< `order` U8 (::xf_order) */
#define XF_OFF_PARAMS  70u /**< first parameter byte (host) or feedback byte (GCU); the CRC follows the last */
#define XF_FRAME_LEN   32u /**< main and sub frames are 32 bytes each */

/* Byte offsets of every field of the four frames, under the spec's names
 * (docs/protocol.md §3-§6): the one copy of the layout, which the
 * packers, the decoders and the client all use. */
/* host -> GCU: main frame 5..36, sub frame 37..68 */
#define XF_OFF_HOST_ROLL_CTRL       XF_OFF_MAIN /**< `roll_ctrl` S16, bytes 5-6 */
#define XF_OFF_HOST_PITCH_CTRL      7u          /**< `pitch_ctrl` S16, bytes 7-8 */
#define XF_OFF_HOST_YAW_CTRL        9u          /**< `yaw_ctrl` S16, bytes 9-10 */
#define XF_OFF_HOST_STATUS          11u         /**< `status` U8, byte 11: `XF_STATUS_*` bits */
#define XF_OFF_HOST_CARRIER_ROLL    12u         /**< `carrier_roll` S16, bytes 12-13, 0.01 deg */
#define XF_OFF_HOST_CARRIER_PITCH   14u         /**< `carrier_pitch` S16, bytes 14-15, 0.01 deg */
#define XF_OFF_HOST_CARRIER_YAW     16u         /**< `carrier_yaw` U16, bytes 16-17, 0.01 deg */
#define XF_OFF_HOST_ACCEL_NORTH     18u         /**< `accel_north` S16, bytes 18-19, 0.01 m/s^2 */
#define XF_OFF_HOST_ACCEL_EAST      20u         /**< `accel_east` S16, bytes 20-21, 0.01 m/s^2 */
#define XF_OFF_HOST_ACCEL_UP        22u         /**< `accel_up` S16, bytes 22-23, 0.01 m/s^2 */
#define XF_OFF_HOST_VEL_NORTH       24u         /**< `vel_north` S16, bytes 24-25, 0.01 m/s */
#define XF_OFF_HOST_VEL_EAST        26u         /**< `vel_east` S16, bytes 26-27, 0.01 m/s */
#define XF_OFF_HOST_VEL_UP          28u         /**< `vel_up` S16, bytes 28-29, 0.01 m/s */
#define XF_OFF_HOST_SUB_REQUEST     30u         /**< `sub_request` U8, byte 30: sub frame asked of the GCU */
#define XF_OFF_HOST_RESERVED_MAIN   31u         /**< reserved, bytes 31-36 (6 bytes, 0) */
#define XF_OFF_HOST_SUB_HEADER      XF_OFF_SUB  /**< `sub_header` U8, byte 37: 0x01, or 0 (no data) */
#define XF_OFF_HOST_LONGITUDE       38u         /**< `longitude` S32, bytes 38-41, 1e-7 deg */
#define XF_OFF_HOST_LATITUDE        42u         /**< `latitude` S32, bytes 42-45, 1e-7 deg */
#define XF_OFF_HOST_ALTITUDE        46u         /**< `altitude` S32, bytes 46-49, mm */
#define XF_OFF_HOST_SATELLITES      50u         /**< `satellites` U8, byte 50 */
#define XF_OFF_HOST_GNSS_MS         51u         /**< `gnss_ms` U32, bytes 51-54: ms of GNSS week */
#define XF_OFF_HOST_GNSS_WEEK       55u         /**< `gnss_week` S16, bytes 55-56 */
#define XF_OFF_HOST_RELATIVE_HEIGHT 57u         /**< `relative_height` S32, bytes 57-60, mm */
#define XF_OFF_HOST_RESERVED_SUB    61u         /**< reserved, bytes 61-68 (8 bytes, 0) */
/* GCU -> host: main frame 5..36, sub frame 37..68 */
#define XF_OFF_GCU_GIMBAL_MODE      XF_OFF_MAIN /**< `gimbal_mode` U8, byte 5 (::xf_mode) */
#define XF_OFF_GCU_POD_STATUS       6u          /**< `pod_status` U16, bytes 6-7: `XF_POD_*` bits */
#define XF_OFF_GCU_TARGET_OFFSET_X  8u          /**< `target_offset_x` S16, bytes 8-9 */
#define XF_OFF_GCU_TARGET_OFFSET_Y  10u         /**< `target_offset_y` S16, bytes 10-11 */
#define XF_OFF_GCU_REL_ANGLE_X      12u         /**< `rel_angle_x` S16, bytes 12-13, 0.01 deg */
#define XF_OFF_GCU_REL_ANGLE_Y      14u         /**< `rel_angle_y` S16, bytes 14-15, 0.01 deg */
#define XF_OFF_GCU_REL_ANGLE_Z      16u         /**< `rel_angle_z` S16, bytes 16-17, 0.01 deg */
#define XF_OFF_GCU_CAM_ROLL         18u         /**< `cam_roll` S16, bytes 18-19, 0.01 deg */
#define XF_OFF_GCU_CAM_PITCH        20u         /**< `cam_pitch` S16, bytes 20-21, 0.01 deg */
#define XF_OFF_GCU_CAM_YAW          22u         /**< `cam_yaw` U16, bytes 22-23, 0.01 deg */
#define XF_OFF_GCU_RATE_X           24u         /**< `rate_x` S16, bytes 24-25 (unit set by the version) */
#define XF_OFF_GCU_RATE_Y           26u         /**< `rate_y` S16, bytes 26-27 */
#define XF_OFF_GCU_RATE_Z           28u         /**< `rate_z` S16, bytes 28-29 */
#define XF_OFF_GCU_RESERVED_MAIN    30u         /**< reserved, bytes 30-36 (7 bytes) */
#define XF_OFF_GCU_SUB_HEADER       XF_OFF_SUB  /**< `sub_header` U8, byte 37: 0x01, or 0 (not asked) */
#define XF_OFF_GCU_HW_VERSION       38u         /**< `hw_version` U8, byte 38 */
#define XF_OFF_GCU_FW_VERSION       39u         /**< `fw_version` U8, byte 39 */
#define XF_OFF_GCU_GIMBAL_CODE      40u         /**< `gimbal_code` U8, byte 40 (xf_gimbal_model()) */
#define XF_OFF_GCU_ERROR_CODE       41u         /**< `error_code` U16, bytes 41-42: `XF_ERROR_*` (V0.2) */
#define XF_OFF_GCU_TARGET_DISTANCE  43u         /**< `target_distance` S32, bytes 43-46, 0.1 m */
#define XF_OFF_GCU_TARGET_LONGITUDE 47u         /**< `target_longitude` S32, bytes 47-50, 1e-7 deg */
#define XF_OFF_GCU_TARGET_LATITUDE  51u         /**< `target_latitude` S32, bytes 51-54, 1e-7 deg */
#define XF_OFF_GCU_TARGET_ALTITUDE  55u         /**< `target_altitude` S32, bytes 55-58, mm */
#define XF_OFF_GCU_ZOOM_CAM1        59u         /**< `zoom_cam1` U16, bytes 59-60, 0.1 x */
#define XF_OFF_GCU_ZOOM_CAM2        61u         /**< `zoom_cam2` U16, bytes 61-62, 0.1 x */
#define XF_OFF_GCU_THERMAL_STATUS   63u         /**< `thermal_status` U8, byte 63 (V0.2) */
#define XF_OFF_GCU_CAMERA_STATUS    64u         /**< `camera_status` U16, bytes 64-65 (V0.2) */
#define XF_OFF_GCU_TIME_ZONE        66u         /**< `time_zone` S8, byte 66 (V0.2) */
#define XF_OFF_GCU_RESERVED_SUB     67u         /**< reserved, bytes 67-68 (2 bytes) */

/** Which side sent a packet: selects the header bytes and the frame layout. */
typedef enum xf_direction {
    XF_DIR_HOST = 0, /**< host -> GCU, header A8 E5 */
    XF_DIR_GCU = 1   /**< GCU -> host, header 8A 5E */
} xf_direction;

/* ---- protocol versions (byte 4) --------------------------------------- */
#define XF_PROTOCOL_V1 0x01u /**< V0.1, vendor document V2.0.4 */
#define XF_PROTOCOL_V2 0x02u /**< V0.2, vendor documents V2.0.5 / V2.0.6 */

/* ---- host main frame: status byte (11) -------------------------------- */
#define XF_STATUS_INS_VALID  0x01u /**< bit0: the carrier's INS data is valid */
#define XF_STATUS_CTRL_VALID 0x04u /**< bit2: the control quantities are valid */

#define XF_SUB_HEADER 0x01u /**< the only defined sub frame header */

/* ---- orders (byte 69) -------------------------------------------------- */
/**
 * The orders (commands) of protocol V0.1 and V0.2, as byte 69 carries them
 * (docs/protocol.md §7, §10). Their parameters are the members of
 * ::xf_command that xf_order_lookup() lists; the GCU runs an order once while
 * it repeats (except external_track), so two commands of the same order need
 * a null packet between them.
 */
typedef enum xf_order {
    XF_ORDER_NULL = 0x00,           /**< no command; separates two commands of the same order */
    XF_ORDER_CALIBRATION = 0x01,    /**< calibrate (keep the gimbal still); answers "operating" until done */
    XF_ORDER_NEUTRAL = 0x03,        /**< back to neutral, keeping the mode (head lock, head follow, orthoview) */
    XF_ORDER_OSD_COORDINATE = 0x06, /**< V0.2: OSD shows carrier (TT 0) or target (TT 1) coordinates */
    XF_ORDER_AUTO_FLIP = 0x07,      /**< V0.2: image auto-flip on (TT 0) or off (TT 1) */
    XF_ORDER_TIME_ZONE = 0x08,      /**< V0.2: time zone, hours from UTC */
    /** mode: angle control (V2.0.6): roll and pitch control quantities are Euler angles, yaw is an angle
     * relative to the carrier. V2.0.4 called 0x10 "FPV", with all three relative to the carrier (V0.2's FPV
     * is 0x1C). docs/protocol.md §11.1 */
    XF_ORDER_ANGLE_CONTROL = 0x10,
    XF_ORDER_HEAD_LOCK = 0x11,        /**< mode: head lock; control quantities are rates, at 0 the attitude holds */
    XF_ORDER_HEAD_FOLLOW = 0x12,      /**< mode: head follow; pitch and yaw rates, yaw follows the carrier */
    XF_ORDER_ORTHOVIEW = 0x13,        /**< mode: orthoview, pitch locked at -90 deg */
    XF_ORDER_EULER = 0x14,            /**< mode: Euler angle control; control quantities are Euler angles */
    XF_ORDER_GAZE_GEO = 0x15,         /**< gaze at a geo-coordinate; needs valid carrier INS data */
    XF_ORDER_GAZE_LOCK = 0x16,        /**< keep aiming at the point now in the centre of view; needs valid INS data */
    XF_ORDER_TRACK = 0x17,            /**< track the target in a box on the [0, 10000] screen grid (start, exit) */
    XF_ORDER_CLICK_TO_AIM = 0x1A,     /**< aim at a point of the [0, 10000] screen grid */
    XF_ORDER_EXTERNAL_TRACK = 0x1B,   /**< offsets from an outside tracker; streamed, exempt from the once-rule */
    XF_ORDER_FPV = 0x1C,              /**< V0.2 mode: FPV, all three control quantities relative to the carrier */
    XF_ORDER_SHUTTER = 0x20,          /**< take a picture */
    XF_ORDER_RECORD = 0x21,           /**< start or stop recording (a toggle) */
    XF_ORDER_ZOOM_IN = 0x22,          /**< zoom in continuously */
    XF_ORDER_ZOOM_OUT = 0x23,         /**< zoom out continuously */
    XF_ORDER_ZOOM_STOP = 0x24,        /**< stop zooming */
    XF_ORDER_ZOOM_TO = 0x25,          /**< zoom to a rate or a fraction of the zoom range (xf_command.zoom) */
    XF_ORDER_FOCUS = 0x26,            /**< focus */
    XF_ORDER_PALETTE = 0x2A,          /**< thermal palette (TT; 0 = next) */
    XF_ORDER_NIGHT_VISION = 0x2B,     /**< night vision off (TT 0), on (1) or auto (2) */
    XF_ORDER_AREA_TEMP = 0x30,        /**< V0.2: area temperature measurement off / on, with a box */
    XF_ORDER_TEMP_ALARM = 0x31,       /**< V0.2: temperature alarm off / on, with high and low limits */
    XF_ORDER_ISOTHERM = 0x32,         /**< V0.2: isotherm off / on, with high and low limits */
    XF_ORDER_SPOT_TEMP = 0x33,        /**< V0.2: spot temperature measurement off / on, at a point */
    XF_ORDER_OSD = 0x73,              /**< on-screen display; TT's meaning varies by version, docs/protocol.md §11 */
    XF_ORDER_PIP = 0x74,              /**< picture-in-picture view (TT; 0 = next) */
    XF_ORDER_TARGET_DETECTION = 0x75, /**< V0.2: target detection off (TT 0) / on (1) */
    XF_ORDER_DIGITAL_ZOOM = 0x76,     /**< V0.2: digital zoom off (TT 0) / on (1) */
    XF_ORDER_LIGHTING = 0x80,         /**< fill light intensity, TT in [0, 255]; on also turns night vision on */
    XF_ORDER_RANGING = 0x81           /**< laser ranging off (TT 0) / on (TT 2) */
} xf_order;

#define XF_ORDER_COUNT 36u /**< known orders: 26 of V0.1 and 10 added by V0.2 */

/* ---- GCU main frame: gimbal_mode (5) ----------------------------------- */
/** The gimbal's mode as the GCU reports it in byte 5 (docs/protocol.md §5); xf_mode_name() names it. */
typedef enum xf_mode {
    XF_MODE_ANGLE_CONTROL = 0x10, /**< angle control: roll, pitch Euler angles, yaw relative ("FPV" in V2.0.4) */
    XF_MODE_HEAD_LOCK = 0x11,     /**< head lock */
    XF_MODE_HEAD_FOLLOW = 0x12,   /**< head follow */
    XF_MODE_ORTHOVIEW = 0x13,     /**< orthoview (looking straight down) */
    XF_MODE_EULER = 0x14,         /**< Euler angle control */
    XF_MODE_GAZE = 0x16,          /**< gaze (at a geo-coordinate, or locked on a point) */
    XF_MODE_TRACK = 0x17,         /**< tracking a target */
    XF_MODE_FPV = 0x1C            /**< V0.2: FPV */
} xf_mode;

/* ---- GCU main frame: pod_status bits (6-7) ----------------------------- */
#define XF_POD_TRACKING_OK     0x0001u /**< bit 0: tracking succeeds */
#define XF_POD_TARGET_VALID    0x0080u /**< bit 7: range and target coordinates valid */
#define XF_POD_RANGING_ON      0x0100u /**< bit 8: laser ranging on */
#define XF_POD_NIGHT_VISION_ON 0x0200u /**< bit 9: night vision on */
#define XF_POD_LIGHTING_ON     0x0400u /**< bit 10: fill light on */
#define XF_POD_UPWARD_MOUNT    0x1000u /**< bit 12: powered on facing up (0: facing down) */
/** The bits of `pod_status` no document defines (15-13, 11, 6-1): a word read in
 * the GCU's byte order has them clear, which is how xf_pod_status_order() tells
 * the order (docs/protocol.md §11.7). */
#define XF_POD_RESERVED_MASK 0xE87Eu

/**
 * Byte order of the pod status word, GCU bytes 6-7 (docs/protocol.md §11.7).
 * Both vendor documents say little-endian, like every field; V2.0.6's own
 * worked example reads its bytes `01 80` big-endian. The codec keeps the
 * word as the wire gives it read little-endian (xf_gcu_main.pod_status);
 * these values say how to read the flags out of it.
 */
typedef enum xf_pod_order {
    XF_POD_ORDER_UNDECIDED = 0, /**< the word itself does not tell (xf_pod_status_order()) */
    XF_POD_ORDER_LE = 1,        /**< little-endian, as documented: byte 6 holds bits 0-7 */
    XF_POD_ORDER_BE = 2         /**< big-endian, as V2.0.6's example: byte 6 holds bits 8-15 */
} xf_pod_order;

/* ---- GCU sub frame, V0.2 ----------------------------------------------- */
#define XF_THERMAL_LOW_TEMP_ALARM    0x01u /**< `thermal_status` bit 0: low-temperature alarm */
#define XF_THERMAL_HIGH_TEMP_ALARM   0x02u /**< bit 1: high-temperature alarm */
#define XF_THERMAL_SPOT_ON           0x08u /**< bit 3: spot temperature measurement on */
#define XF_THERMAL_ISOTHERM_ON       0x10u /**< bit 4: isotherm on */
#define XF_THERMAL_ALARM_ON          0x20u /**< bit 5: temperature alarm on */
#define XF_THERMAL_AREA_ON           0x40u /**< bit 6: area temperature measurement on */
#define XF_THERMAL_MEASURE_AVAILABLE 0x80u /**< bit 7: temperature measurement available */

#define XF_CAMERA_PIP_MASK        0x0007u /**< `camera_status` bits 0-2: picture-in-picture mode number */
#define XF_CAMERA_RECORDING       0x0010u /**< bit 4: recording */
#define XF_CAMERA_AUTO_FLIP_OFF   0x0800u /**< bit 11, 1: image auto-flip OFF (0 = on) */
#define XF_CAMERA_OSD_TARGET      0x1000u /**< bit 12, 1: OSD shows target coordinates (0: carrier) */
#define XF_CAMERA_OSD_ON          0x2000u /**< bit 13: OSD on */
#define XF_CAMERA_DIGITAL_ZOOM_ON 0x4000u /**< bit 14: digital zoom on */
#define XF_CAMERA_DETECTION_ON    0x8000u /**< bit 15: target detection on */

#define XF_ERROR_POD_HW_FAULT   0x0080u /**< `error_code` (V0.2) bit 7: pod hardware fault */
#define XF_ERROR_MAVLINK_RATE   0x2000u /**< bit 13: MAVLink rate abnormal */
#define XF_ERROR_GNSS_NOT_FIXED 0x4000u /**< bit 14: GNSS not positioned */
#define XF_ERROR_GCU_HW_FAULT   0x8000u /**< bit 15: GCU hardware fault */

/* ---- camera masks (KK / NN) --------------------------------------------- */
#define XF_CAM1    0x01u /**< camera 1, visible-light zoom by default */
#define XF_CAM2    0x02u /**< camera 2, thermal by default */
#define XF_CAM_ALL 0xFFu /**< every camera */

/* ---- feedback execution state (byte 70) ------------------------------ */
#define XF_STATE_SUCCESS   0x00u /**< the order succeeded */
#define XF_STATE_FAILURE   0x01u /**< the order failed (some orders send the failed-camera mask instead) */
#define XF_STATE_OPERATING 0x02u /**< calibration only */

/* ---- target_distance sentinels (0.1 m) ---------------------------------- */
#define XF_DISTANCE_INVALID_RAW (-10) /**< -1 m: no valid measurement (0 too) */

/* ---- screen grids -------------------------------------------------------- */
#define XF_GRID_MAX       10000u /**< track / click / thermal boxes: [0, 10000] */
#define XF_EXT_TRACK_MAX  1024   /**< external track offsets: [-1024, 1024] */
#define XF_EXT_TRACK_LOST 3071   /**< both offsets >= this: target lost */

/**
 * Model name of a gimbal code (GCU sub frame byte 40), from the vendor's
 * tables of V2.0.4 and V0.2 (docs/protocol.md §6, §10).
 * @param gimbal_code  the code, as xf_gcu_sub.gimbal_code carries it
 * @return a static string such as "D-80AI", or NULL when the code is not in
 *   the vendor's tables
 */
XF_API const char *xf_gimbal_model(uint8_t gimbal_code);

/**
 * Which byte order of a pod status word leaves the reserved bits
 * (::XF_POD_RESERVED_MASK) clear: the one reading that gives a word the
 * documents define is taken to be the GCU's. It looks at this one word:
 * the bytes of one reply, nothing remembered.
 * @param pod_status  the word as the codec unpacks it (xf_gcu_main.pod_status:
 *   byte 6 + 256 x byte 7, the little-endian reading)
 * @return ::XF_POD_ORDER_LE when only the little-endian reading has the
 *   reserved bits clear, ::XF_POD_ORDER_BE when only the big-endian one has;
 *   ::XF_POD_ORDER_UNDECIDED when both have (each byte is 0x00 or 0x01: 00 00,
 *   01 00, 00 01, 01 01; of these, 01 00 and 00 01 mean different flags in the
 *   two orders) or when neither has (both readings set a reserved bit: the
 *   word is one no document describes, damaged or from an unknown firmware,
 *   and says nothing about the order)
 */
XF_API xf_pod_order xf_pod_status_order(uint16_t pod_status);
/**
 * The pod status flags (`XF_POD_*` bits) of a word read in a byte order.
 * `xf_pod_flags(w, xf_pod_status_order(w))` is the robust reading of
 * docs/protocol.md §11.7, with the documented little-endian order where the
 * word does not tell.
 * @param pod_status  the word as the codec unpacks it (little-endian reading)
 * @param order       ::XF_POD_ORDER_BE swaps the two bytes; any other value
 *   (::XF_POD_ORDER_LE, ::XF_POD_ORDER_UNDECIDED) keeps the word as it is
 * @return the word in that order, reserved bits included (test them with
 *   ::XF_POD_RESERVED_MASK)
 */
XF_API uint16_t xf_pod_flags(uint16_t pod_status, xf_pod_order order);

#if XF_EMIT_DEFINITIONS
XF_API xf_pod_order xf_pod_status_order(uint16_t pod_status)
{
    int le_clean = (pod_status & XF_POD_RESERVED_MASK) == 0u;
    int be_clean = (xf_pod_flags(pod_status, XF_POD_ORDER_BE) & XF_POD_RESERVED_MASK) == 0u;
    if (le_clean == be_clean) {
        return XF_POD_ORDER_UNDECIDED; /* both fit, or neither: no evidence either way */
    }
    return le_clean ? XF_POD_ORDER_LE : XF_POD_ORDER_BE;
}

XF_API uint16_t xf_pod_flags(uint16_t pod_status, xf_pod_order order)
{
    if (order != XF_POD_ORDER_BE) {
        return pod_status;
    }
    return (uint16_t)(((unsigned)pod_status >> 8) | (((unsigned)pod_status & 0xFFu) << 8));
}

XF_API const char *xf_gimbal_model(uint8_t gimbal_code)
{
    /* V2.0.4 codes, then those added by the V0.2 documents (31 renamed there). */
    switch (gimbal_code) {
    case 0: return "Z-6A";
    case 2: return "Z-6C";
    case 3: return "M-2400G2";
    case 21: return "Z-8TA";
    case 22: return "Z-8TB";
    case 24: return "Z-8RA";
    case 25: return "Z-8RB";
    case 26: return "Z-8RC";
    case 27: return "Z-8LA";
    case 30: return "Z-9A";
    case 31: return "Z-9B_V3"; /* "Z-9B" in V2.0.4 */
    case 40: return "D-80AI";
    case 41: return "D-90AI";
    case 44: return "D-80Pro";
    case 45: return "D-90Pro(TA)";
    case 49: return "Z-1Pro";
    case 50: return "Z-1Mini";
    case 52: return "Z-2Mini";
    case 53: return "D-125AI(T)";
    case 55: return "D-90DE";
    case 57: return "D-125AI(V)";
    case 58: return "Z-9B_V4(T)";
    case 59: return "Z-9B_V4(V)";
    case 60: return "D-90Pro(VA)";
    case 61: return "D-90Pro(T)";
    case 62: return "D-90Pro(V)";
    default: return NULL;
    }
}
#endif

XF_END_DECLS

#endif /* XF_PROTOCOL_H */
