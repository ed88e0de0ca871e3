/*
 * xf_protocol.h - constants of the GCU private protocol V2.0.4 (protocol
 * V0.1) and V0.2, with the canonical names of shared/spec/gcu-protocol.md.
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

#define XF_PACKET_MIN_LEN   72u  /**< header..order + CRC, no parameter */
#define XF_PACKET_LIMIT     255u /**< the protocol's own upper bound (the vendor CRC takes a uint8_t length) */
#define XF_PARAMS_MAX       (XF_PACKET_MAX_LEN - XF_PACKET_MIN_LEN) /**< parameter / feedback bytes a packet struct holds */
#define XF_PARAMS_KNOWN_MAX 12u /**< longest parameter block of any known order (gaze_geo) */

/* byte offsets */
#define XF_OFF_LENGTH  2u
#define XF_OFF_VERSION 4u
#define XF_OFF_MAIN    5u
#define XF_OFF_SUB     37u
#define XF_OFF_ORDER   69u
#define XF_OFF_PARAMS  70u
#define XF_FRAME_LEN   32u /**< main and sub frames are 32 bytes each */

/* Byte offsets of every field of the four frames, under the spec's names
 * (gcu-protocol.md sections 3 and 4): the one copy of the layout, which the
 * packers, the decoders and the client all use. */
/* host -> GCU: main frame 5..36, sub frame 37..68 */
#define XF_OFF_HOST_ROLL_CTRL       XF_OFF_MAIN
#define XF_OFF_HOST_PITCH_CTRL      7u
#define XF_OFF_HOST_YAW_CTRL        9u
#define XF_OFF_HOST_STATUS          11u
#define XF_OFF_HOST_CARRIER_ROLL    12u
#define XF_OFF_HOST_CARRIER_PITCH   14u
#define XF_OFF_HOST_CARRIER_YAW     16u
#define XF_OFF_HOST_ACCEL_NORTH     18u
#define XF_OFF_HOST_ACCEL_EAST      20u
#define XF_OFF_HOST_ACCEL_UP        22u
#define XF_OFF_HOST_VEL_NORTH       24u
#define XF_OFF_HOST_VEL_EAST        26u
#define XF_OFF_HOST_VEL_UP          28u
#define XF_OFF_HOST_SUB_REQUEST     30u
#define XF_OFF_HOST_RESERVED_MAIN   31u
#define XF_OFF_HOST_SUB_HEADER      XF_OFF_SUB
#define XF_OFF_HOST_LONGITUDE       38u
#define XF_OFF_HOST_LATITUDE        42u
#define XF_OFF_HOST_ALTITUDE        46u
#define XF_OFF_HOST_SATELLITES      50u
#define XF_OFF_HOST_GNSS_MS         51u
#define XF_OFF_HOST_GNSS_WEEK       55u
#define XF_OFF_HOST_RELATIVE_HEIGHT 57u
#define XF_OFF_HOST_RESERVED_SUB    61u
/* GCU -> host: main frame 5..36, sub frame 37..68 */
#define XF_OFF_GCU_GIMBAL_MODE      XF_OFF_MAIN
#define XF_OFF_GCU_POD_STATUS       6u
#define XF_OFF_GCU_TARGET_OFFSET_X  8u
#define XF_OFF_GCU_TARGET_OFFSET_Y  10u
#define XF_OFF_GCU_REL_ANGLE_X      12u
#define XF_OFF_GCU_REL_ANGLE_Y      14u
#define XF_OFF_GCU_REL_ANGLE_Z      16u
#define XF_OFF_GCU_CAM_ROLL         18u
#define XF_OFF_GCU_CAM_PITCH        20u
#define XF_OFF_GCU_CAM_YAW          22u
#define XF_OFF_GCU_RATE_X           24u
#define XF_OFF_GCU_RATE_Y           26u
#define XF_OFF_GCU_RATE_Z           28u
#define XF_OFF_GCU_RESERVED_MAIN    30u
#define XF_OFF_GCU_SUB_HEADER       XF_OFF_SUB
#define XF_OFF_GCU_HW_VERSION       38u
#define XF_OFF_GCU_FW_VERSION       39u
#define XF_OFF_GCU_GIMBAL_CODE      40u
#define XF_OFF_GCU_ERROR_CODE       41u
#define XF_OFF_GCU_TARGET_DISTANCE  43u
#define XF_OFF_GCU_TARGET_LONGITUDE 47u
#define XF_OFF_GCU_TARGET_LATITUDE  51u
#define XF_OFF_GCU_TARGET_ALTITUDE  55u
#define XF_OFF_GCU_ZOOM_CAM1        59u
#define XF_OFF_GCU_ZOOM_CAM2        61u
#define XF_OFF_GCU_THERMAL_STATUS   63u
#define XF_OFF_GCU_CAMERA_STATUS    64u
#define XF_OFF_GCU_TIME_ZONE        66u
#define XF_OFF_GCU_RESERVED_SUB     67u

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
typedef enum xf_order {
    XF_ORDER_NULL = 0x00,
    XF_ORDER_CALIBRATION = 0x01,
    XF_ORDER_NEUTRAL = 0x03,
    XF_ORDER_OSD_COORDINATE = 0x06, /**< V0.2 */
    XF_ORDER_AUTO_FLIP = 0x07,      /**< V0.2 */
    XF_ORDER_TIME_ZONE = 0x08,      /**< V0.2 */
    XF_ORDER_ANGLE_CONTROL = 0x10,  /**< "FPV" in V2.0.4 */
    XF_ORDER_HEAD_LOCK = 0x11,
    XF_ORDER_HEAD_FOLLOW = 0x12,
    XF_ORDER_ORTHOVIEW = 0x13,
    XF_ORDER_EULER = 0x14,
    XF_ORDER_GAZE_GEO = 0x15,
    XF_ORDER_GAZE_LOCK = 0x16,
    XF_ORDER_TRACK = 0x17,
    XF_ORDER_CLICK_TO_AIM = 0x1A,
    XF_ORDER_EXTERNAL_TRACK = 0x1B,
    XF_ORDER_FPV = 0x1C, /**< V0.2 */
    XF_ORDER_SHUTTER = 0x20,
    XF_ORDER_RECORD = 0x21,
    XF_ORDER_ZOOM_IN = 0x22,
    XF_ORDER_ZOOM_OUT = 0x23,
    XF_ORDER_ZOOM_STOP = 0x24,
    XF_ORDER_ZOOM_TO = 0x25,
    XF_ORDER_FOCUS = 0x26,
    XF_ORDER_PALETTE = 0x2A,
    XF_ORDER_NIGHT_VISION = 0x2B,
    XF_ORDER_AREA_TEMP = 0x30,  /**< V0.2 */
    XF_ORDER_TEMP_ALARM = 0x31, /**< V0.2 */
    XF_ORDER_ISOTHERM = 0x32,   /**< V0.2 */
    XF_ORDER_SPOT_TEMP = 0x33,  /**< V0.2 */
    XF_ORDER_OSD = 0x73,
    XF_ORDER_PIP = 0x74,
    XF_ORDER_TARGET_DETECTION = 0x75, /**< V0.2 */
    XF_ORDER_DIGITAL_ZOOM = 0x76,     /**< V0.2 */
    XF_ORDER_LIGHTING = 0x80,
    XF_ORDER_RANGING = 0x81
} xf_order;

#define XF_ORDER_COUNT 36u /**< known orders: 26 of V0.1 and 10 added by V0.2 */

/* ---- GCU main frame: gimbal_mode (5) ----------------------------------- */
typedef enum xf_mode {
    XF_MODE_ANGLE_CONTROL = 0x10, /**< "FPV" in V2.0.4 */
    XF_MODE_HEAD_LOCK = 0x11,
    XF_MODE_HEAD_FOLLOW = 0x12,
    XF_MODE_ORTHOVIEW = 0x13,
    XF_MODE_EULER = 0x14,
    XF_MODE_GAZE = 0x16,
    XF_MODE_TRACK = 0x17,
    XF_MODE_FPV = 0x1C /**< V0.2 */
} xf_mode;

/* ---- GCU main frame: pod_status bits (6-7) ----------------------------- */
#define XF_POD_TRACKING_OK     0x0001u
#define XF_POD_TARGET_VALID    0x0080u /**< range and target coordinates valid */
#define XF_POD_RANGING_ON      0x0100u
#define XF_POD_NIGHT_VISION_ON 0x0200u
#define XF_POD_LIGHTING_ON     0x0400u
#define XF_POD_UPWARD_MOUNT    0x1000u /**< 1: powered on facing up */

/* ---- GCU sub frame, V0.2 ----------------------------------------------- */
#define XF_THERMAL_LOW_TEMP_ALARM    0x01u
#define XF_THERMAL_HIGH_TEMP_ALARM   0x02u
#define XF_THERMAL_SPOT_ON           0x08u
#define XF_THERMAL_ISOTHERM_ON       0x10u
#define XF_THERMAL_ALARM_ON          0x20u
#define XF_THERMAL_AREA_ON           0x40u
#define XF_THERMAL_MEASURE_AVAILABLE 0x80u

#define XF_CAMERA_PIP_MASK        0x0007u /**< bits 0-2: picture-in-picture mode number */
#define XF_CAMERA_RECORDING       0x0010u
#define XF_CAMERA_AUTO_FLIP_OFF   0x0800u /**< 1: image auto-flip OFF (0 = on) */
#define XF_CAMERA_OSD_TARGET      0x1000u /**< 1: OSD shows target coordinates (0: carrier) */
#define XF_CAMERA_OSD_ON          0x2000u
#define XF_CAMERA_DIGITAL_ZOOM_ON 0x4000u
#define XF_CAMERA_DETECTION_ON    0x8000u

#define XF_ERROR_POD_HW_FAULT   0x0080u
#define XF_ERROR_MAVLINK_RATE   0x2000u
#define XF_ERROR_GNSS_NOT_FIXED 0x4000u
#define XF_ERROR_GCU_HW_FAULT   0x8000u

/* ---- camera masks (KK / NN) --------------------------------------------- */
#define XF_CAM1    0x01u /**< camera 1, visible-light zoom by default */
#define XF_CAM2    0x02u /**< camera 2, thermal by default */
#define XF_CAM_ALL 0xFFu

/* ---- feedback execution state (byte 70) ------------------------------ */
#define XF_STATE_SUCCESS   0x00u
#define XF_STATE_FAILURE   0x01u
#define XF_STATE_OPERATING 0x02u /**< calibration only */

/* ---- target_distance sentinels (0.1 m) ---------------------------------- */
#define XF_DISTANCE_INVALID_RAW (-10) /**< -1 m: no valid measurement (0 too) */

/* ---- screen grids -------------------------------------------------------- */
#define XF_GRID_MAX       10000u /**< track / click / thermal boxes: [0, 10000] */
#define XF_EXT_TRACK_MAX  1024   /**< external track offsets: [-1024, 1024] */
#define XF_EXT_TRACK_LOST 3071   /**< both offsets >= this: target lost */

/** Model name of a gimbal_code, or NULL when the code is not in the vendor's tables. */
XF_API const char *xf_gimbal_model(uint8_t gimbal_code);

#if XF_EMIT_DEFINITIONS
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
    case 31: return "Z-9B";
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
