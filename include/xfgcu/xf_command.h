/**
 * @file
 * @brief Typed parameters of every order (V0.1 and V0.2) and the GCU's
 * feedback.
 *
 * One plain struct, xf_command, holds the parameters of any order under
 * named members; each order uses the members its row of the table below
 * lists, in wire order. A table (xf_order_info) drives the byte layout, so
 * encoding, decoding, the CLI and JSON share one description; the table
 * also gives each order's TT range, and the checks the rule of each
 * member (union ranges, box corners; see xf_command_check()). Unknown orders
 * go through the raw escape hatch: set xf_host_packet.order / params /
 * params_len yourself. The orders and their ranges: docs/protocol.md §7, §10.
 *
 * The functions keep no state, never allocate and never block; the strings
 * they return are static.
 *
 * @code{.unparsed}
 *  order            wire parameters (members)
 *  null .. euler    none (also gaze_lock, fpv)
 *  gaze_geo         longitude S32, latitude S32, altitude S32
 *  track            cameras, value (1 start, 0 exit), x0, y0, x1, y1 U16
 *  click_to_aim     cameras, x0, y0 U16
 *  external_track   cameras, dx S16, dy S16, value (2 start, 0 exit)
 *  shutter, record, zoom_in, zoom_out, zoom_stop, focus    cameras
 *  zoom_to          cameras, zoom S16
 *  palette, night_vision                                   cameras, value
 *  osd, pip, lighting, ranging, osd_coordinate, auto_flip,
 *  target_detection, digital_zoom                          value
 *  time_zone        hours S8
 *  area_temp        cameras, value, x0, y0, x1, y1 U16
 *  temp_alarm, isotherm    cameras, value, temp_high S16, temp_low S16
 *  spot_temp        cameras, value, x0, y0 U16
 * @endcode
 */
#ifndef XF_COMMAND_H
#define XF_COMMAND_H

#include <stddef.h>
#include <stdint.h>
#include "xf_bytes.h"
#include "xf_config.h"
#include "xf_mem.h"
#include "xf_error.h"
#include "xf_packet.h"
#include "xf_protocol.h"

XF_BEGIN_DECLS

/** The parameters of one order. Members an order does not use are ignored on encode and zero after decode. */
typedef struct xf_command {
    uint8_t order;   /**< ::xf_order (the table row says which members it uses) */
    uint8_t cameras; /**< KK: camera mask, bit n = camera n+1; never 0 */
    uint8_t value;   /**< TT: action, mode, level or on/off, per order */
    int8_t hours;    /**< time_zone: hours from UTC, [-12, 14] */
    /** @var xf_command::x0
     *  box left edge, or the point x, on the [0, 10000] grid (x right) */
    uint16_t x0, y0; /**< box top edge, or the point y, on the [0, 10000] grid (y down) */
    /** @var xf_command::x1
     *  box right edge, [x0, 10000] */
    uint16_t x1, y1; /**< box bottom edge, [y0, 10000] */
    /** @var xf_command::dx
     *  external_track offset from the screen centre, [-1024, 1024]; both dx and dy >= 3071: target lost */
    int16_t dx, dy;    /**< external_track offset from the screen centre, [-1024, 1024] (see dx) */
    int16_t zoom;      /**< zoom_to: [-32768, -10] = -(rate x 10); [1, 10000] = fraction of the range */
    int16_t temp_high; /**< temp_alarm / isotherm high limit, 0.1 degC */
    int16_t temp_low;  /**< temp_alarm / isotherm low limit, 0.1 degC; <= temp_high when on */
    int32_t longitude; /**< gaze_geo, 1e-7 deg */
    int32_t latitude;  /**< gaze_geo, 1e-7 deg */
    int32_t altitude;  /**< gaze_geo, mm */
} xf_command;

/**
 * The members of xf_command, as items of an order's wire layout
 * (xf_order_info.fields), and as the member at fault that the checks report
 * (`bad_field`: ::XF_F_NONE when none is).
 */
typedef enum xf_field {
    XF_F_NONE = -1, /**< no member: what `bad_field` receives when no member is at fault */
    XF_F_CAMERAS,   /**< xf_command.cameras, U8 */
    XF_F_VALUE,     /**< xf_command.value, U8 */
    XF_F_HOURS,     /**< xf_command.hours, S8 */
    XF_F_X0,        /**< xf_command.x0, U16 */
    XF_F_Y0,        /**< xf_command.y0, U16 */
    XF_F_X1,        /**< xf_command.x1, U16 */
    XF_F_Y1,        /**< xf_command.y1, U16 */
    XF_F_DX,        /**< xf_command.dx, S16 */
    XF_F_DY,        /**< xf_command.dy, S16 */
    XF_F_ZOOM,      /**< xf_command.zoom, S16 */
    XF_F_TEMP_HIGH, /**< xf_command.temp_high, S16 */
    XF_F_TEMP_LOW,  /**< xf_command.temp_low, S16 */
    XF_F_LONGITUDE, /**< xf_command.longitude, S32 */
    XF_F_LATITUDE,  /**< xf_command.latitude, S32 */
    XF_F_ALTITUDE   /**< xf_command.altitude, S32 */
} xf_field;

#define XF_ORDER_MASK_FAILURE 0x01u /**< failure feedback is the mask of failed cameras (NN) */
#define XF_ORDER_OPERATING    0x02u /**< may answer 0x02 "operating" before its final state (calibration) */
#define XF_ORDER_STREAMED     0x04u /**< exempt from the once-rule: meant to be streamed (external_track) */
#define XF_ORDER_SETS_MODE    0x08u /**< switches the gimbal mode */
#define XF_ORDER_V1_ONLY      0x10u /**< a V0.1 order that V0.2 (V2.0.6) no longer lists (external_track) */

/**
 * One row of the order table (xf_order_lookup(), xf_order_at()). Its
 * canonical name is xf_order_name(order): the names are kept apart, so that
 * a firmware that never asks for one does not carry them (a row holds no
 * pointer; sizes in docs/performance.md).
 */
typedef struct xf_order_info {
    uint8_t order;           /**< the order (::xf_order) */
    uint8_t since;           /**< protocol version that introduced it: 1 or 2 */
    uint8_t flags;           /**< `XF_ORDER_*` flags (::XF_ORDER_MASK_FAILURE, ...) */
    uint8_t default_cameras; /**< the spec's KK default, 0 when the order takes no mask */
    uint8_t nfields;         /**< number of parameter members, 0..6 */
    uint8_t fields[6];       /**< ::xf_field values, in wire order (the first nfields are used) */
} xf_order_info;

/**
 * The table row of an order.
 * @param order  the order byte
 * @return the row (in a static table), or NULL for an order the protocol
 *   does not define
 */
XF_API const xf_order_info *xf_order_lookup(uint8_t order);
/**
 * The i-th row of the order table, to list every order (rows are sorted by
 * order value).
 * @param i  index, 0 .. ::XF_ORDER_COUNT - 1
 * @return the row, or NULL when @p i >= ::XF_ORDER_COUNT
 */
XF_API const xf_order_info *xf_order_at(size_t i);
/**
 * Canonical name of an order, as docs/protocol.md §7 and §10 give it.
 * @param order  the order byte
 * @return a static string such as "zoom_to", or NULL for an unknown order
 */
XF_API const char *xf_order_name(uint8_t order);
/**
 * Look an order up by canonical name; '-' and '_' are the same
 * ("zoom-to" finds zoom_to), letters must be lower case.
 * @param name   the name
 * @param order  receives the order byte; left alone on error
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p name or @p order), ::XF_ERR_NOT_FOUND
 *   (no order has that name: as an unknown order byte is for xf_command_check())
 */
XF_API xf_err xf_order_from_name(const char *name, uint8_t *order);
/**
 * Name of a gimbal mode (GCU byte 5).
 * @param mode  the mode byte (::xf_mode)
 * @return a static string such as "head_lock", or NULL for an unknown mode
 */
XF_API const char *xf_mode_name(uint8_t mode);
/**
 * Name of a member of xf_command, as used in error reports (the text of
 * what `bad_field` receives).
 * @param f  the member
 * @return a static string such as "x0"; "none" for ::XF_F_NONE; "?" for a
 *   value outside ::xf_field
 */
XF_API const char *xf_field_name(xf_field f);
/**
 * Wire size of a member.
 * @param f  the member
 * @return 1, 2 or 4 bytes; 0 for ::XF_F_NONE (2 for a value outside ::xf_field)
 */
XF_API size_t xf_field_size(xf_field f);
/**
 * Parameter bytes of an order on the wire.
 * @param order  the order byte
 * @return the number of bytes (0 for orders without parameters, and for
 *   unknown orders)
 */
XF_API size_t xf_order_params_len(uint8_t order);

/**
 * The `value` (TT) of an ::XF_ORDER_OSD command that shows or hides the
 * on-screen display, for the protocol version the GCU speaks: its meaning
 * was inverted (docs/protocol.md §11.4). V0.1 (V2.0.4): 0 shows, 1 hides;
 * V0.2 (V2.0.6): 0 = off, 1 = on.
 * @param show     nonzero to show the OSD, 0 to hide it
 * @param version  the protocol version the GCU speaks (1 or 2; above 2 as 2)
 * @return 0 or 1
 */
XF_API uint8_t xf_osd_value(int show, uint8_t version);

/**
 * Whether a gimbal model supports an order, as the vendor's V2.0.6 support
 * list (its appendix 8) says: xf_gimbal_supports().
 */
typedef enum xf_support {
    XF_SUPPORT_UNKNOWN = 0, /**< the list does not know the model (or the order): nothing is claimed */
    XF_SUPPORT_NO = 1,      /**< the list marks the order as not supported by the model */
    XF_SUPPORT_YES = 2      /**< supported: marked so, or an order the list leaves out (every model has those) */
} xf_support;

/**
 * What V2.0.6's support list says of @p order on the model with
 * @p gimbal_code (GCU sub frame byte 40, xf_gimbal_model()). The list marks
 * 18 orders for each of its 20 models (docs/protocol.md §11.8); an order it
 * leaves out is one every model supports. ::XF_SUPPORT_UNKNOWN for a code
 * the list does not have (the models only the older V2.0.4 lists, unknown
 * codes), for external_track (which V2.0.6 dropped) and for a byte that is
 * no order. The client refuses an order the GCU's model does not support
 * unless told to insist (xf_client_submit_opt()).
 * @param gimbal_code  the model code the GCU reports
 * @param order        the order byte (::xf_order)
 * @return ::XF_SUPPORT_YES, ::XF_SUPPORT_NO or ::XF_SUPPORT_UNKNOWN
 */
XF_API xf_support xf_gimbal_supports(uint8_t gimbal_code, uint8_t order);

/**
 * Zero @p cmd and set its order and the spec's default camera mask
 * (xf_order_info.default_cameras; 0 for an order without a mask or an
 * unknown order). Does nothing for a NULL @p cmd.
 * @param cmd    the command
 * @param order  the order byte (::xf_order)
 */
XF_API void xf_command_init(xf_command *cmd, uint8_t order);

/**
 * Read a member as a 32-bit integer (for generic code: the CLI, JSON).
 * @param cmd  the command
 * @param f    the member
 * @return the member's value; 0 for a NULL @p cmd, ::XF_F_NONE or a value
 *   outside ::xf_field
 */
XF_API int32_t xf_command_get(const xf_command *cmd, xf_field f);
/**
 * Set a member from a 32-bit integer, saturating to the member's type
 * (300 into a uint8_t member gives 255). No range check of the order: that
 * is xf_command_check()'s. Does nothing for a NULL @p cmd, ::XF_F_NONE or a
 * value outside ::xf_field.
 * @param cmd  the command
 * @param f    the member
 * @param v    the value
 */
XF_API void xf_command_set(xf_command *cmd, xf_field f, int32_t v);

/**
 * Check @p cmd's members against the ranges of its order for protocol
 * @p version (docs/protocol.md §7, §10): cameras not 0, TT within the
 * order's range for the version (V0.2's for any version >= 2), hours in
 * [-12, 14], box corners on the [0, 10000] grid with x1 >= x0 and y1 >= y0,
 * external_track offsets in [-1024, 1024] unless both are >= 3071 (lost),
 * zoom in [-32768, -10] or [1, 10000], temp_low <= temp_high when the order
 * turns the function on. One-byte members are checked first, then the others
 * in wire order; the first that fails is reported. An order newer than
 * @p version (xf_order_info.since) is not refused.
 * @param cmd        the command
 * @param version    protocol version the command is for (::XF_PROTOCOL_V1, ::XF_PROTOCOL_V2)
 * @param bad_field  receives the member at fault on ::XF_ERR_RANGE
 *   (xf_field_name() gives its name), ::XF_F_NONE on any other result; may
 *   be NULL
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p cmd), ::XF_ERR_NOT_FOUND (an order
 *   the protocol does not define: send it raw), ::XF_ERR_RANGE
 */
XF_API xf_err xf_command_check(const xf_command *cmd, uint8_t version, xf_field *bad_field);

/**
 * Encode @p cmd's parameters, checked first as by xf_command_check(), into
 * their wire bytes. Nothing is written on error.
 * @param cmd        the command
 * @param version    protocol version the command is for
 * @param params     where the parameter bytes go; may be NULL for an order
 *   without parameters
 * @param cap        capacity of @p params, in bytes
 * @param out_len    receives the number of bytes written (may be NULL)
 * @param bad_field  receives the member at fault on ::XF_ERR_RANGE,
 *   ::XF_F_NONE on any other result; may be NULL
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p cmd, or NULL @p params for an order
 *   with parameters), ::XF_ERR_NOT_FOUND (unknown order), ::XF_ERR_RANGE,
 *   ::XF_ERR_NO_SPACE (@p cap < xf_order_params_len())
 */
XF_API xf_err xf_command_encode(const xf_command *cmd, uint8_t version, uint8_t *params, size_t cap, size_t *out_len,
                                xf_field *bad_field);

/**
 * Decode the @p len parameter bytes of @p order into @p cmd and check them
 * as xf_command_check() does. @p cmd is written only on success.
 * @param order      the order byte (byte 69)
 * @param params     the parameter bytes (byte 70 on); may be NULL when @p len is 0
 * @param len        number of parameter bytes
 * @param version    protocol version of the packet, for the ranges
 * @param cmd        receives the command
 * @param bad_field  receives the member at fault on ::XF_ERR_RANGE,
 *   ::XF_F_NONE on any other result; may be NULL
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p cmd, or NULL @p params with
 *   @p len > 0), ::XF_ERR_NOT_FOUND (unknown order: use the raw bytes),
 *   ::XF_ERR_PARAMS (@p len is not the order's parameter length),
 *   ::XF_ERR_RANGE
 */
XF_API xf_err xf_command_decode(uint8_t order, const uint8_t *params, size_t len, uint8_t version, xf_command *cmd,
                                xf_field *bad_field);

/**
 * Put @p cmd into a host packet (order, params and params_len), checked and
 * encoded for the packet's version. The packet is left alone on error.
 * @param pkt        the packet (its version must be set)
 * @param cmd        the command
 * @param bad_field  receives the member at fault on ::XF_ERR_RANGE,
 *   ::XF_F_NONE on any other result; may be NULL
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p pkt or @p cmd), ::XF_ERR_NOT_FOUND
 *   (unknown order: set order and params yourself), ::XF_ERR_RANGE
 */
XF_API xf_err xf_host_set_command(xf_host_packet *pkt, const xf_command *cmd, xf_field *bad_field);

/* ---- feedback ------------------------------------------------------------ */

/** What the GCU's execution state byte says (xf_feedback.result). */
typedef enum xf_result {
    XF_RESULT_OK = 0,       /**< success (0x00) */
    XF_RESULT_FAILED = 1,   /**< failure: 0x01, or the failed-camera mask NN */
    XF_RESULT_OPERATING = 2 /**< 0x02 while calibrating: the final state comes later */
} xf_result;

/** The GCU's answer to an order. */
typedef struct xf_feedback {
    uint8_t order;          /**< the order answered (byte 69) */
    uint8_t has_state;      /**< 1 if byte 70 carries an execution state */
    uint8_t state;          /**< byte 70 as received */
    uint8_t failed_cameras; /**< NN for orders that report a failed-camera mask, else 0 */
    xf_result result;       /**< what the state says, meaningful when has_state (::XF_RESULT_OK without one) */
} xf_feedback;

/**
 * Decode the feedback bytes of a GCU packet (xf_gcu_packet.params). Zero
 * bytes means "no execution state" (the null order's reply, or a reply that
 * does not answer yet); bytes after the first are ignored. 0x00 is success;
 * 0x02 is "operating" for calibration only; anything else is a failure, and
 * for the orders that report one (::XF_ORDER_MASK_FAILURE) the byte is the
 * mask of the cameras that failed.
 * @param order  the order answered (byte 69)
 * @param fb     the feedback bytes; may be NULL when @p len is 0
 * @param len    number of feedback bytes
 * @param out    receives the decoded feedback
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p out, or NULL @p fb with @p len > 0)
 */
XF_API xf_err xf_feedback_decode(uint8_t order, const uint8_t *fb, size_t len, xf_feedback *out);

/**
 * The state byte a GCU sends for @p result (GCU side: the simulator).
 * ::XF_RESULT_OPERATING is for calibration only: for a camera-mask order 0x02
 * would read back as "camera 2 failed".
 * @param order           the order answered
 * @param result          the outcome
 * @param failed_cameras  for a failure of an order that reports a camera
 *   mask, the cameras that failed (0: a plain failure)
 * @return 0x00 for success, 0x02 for operating, @p failed_cameras for a
 *   failure with a mask, 0x01 for any other failure
 */
XF_API uint8_t xf_feedback_state(uint8_t order, xf_result result, uint8_t failed_cameras);

/* Private: the @p i-th (from 0) of the NUL-ended names packed in @p names (the codec's order and
 * field names, the client's status and configuration texts). Names packed in one array, not a
 * literal each: literals share a section, which a firmware that links any of them keeps whole. */
static inline const char *xf__nth_name(const char *names, size_t i)
{
    for (; i > 0u; i--) {
        while (*names++ != '\0') {
        }
    }
    return names;
}

#if XF_EMIT_DEFINITIONS

/* The order table, one row per order, read like the spec's table; sorted by
 * order; 26 orders of V0.1 and 10 of V0.2. Columns: order, protocol
 * version that introduced it, XF_ORDER_* flags, default KK, the number of
 * fields and the fields, the largest TT in V0.1 and in V0.2 (for orders
 * that take one), the name. Expanded three times: into the rows, the value
 * ranges and the packed names (string literals would all share one
 * section that any single use keeps in a firmware image; an array is its
 * own). */
/* clang-format off */
#define XF__ORDER_ROWS(X) \
    X(XF_ORDER_NULL, 1, 0, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "null") \
    X(XF_ORDER_CALIBRATION, 1, XF_ORDER_OPERATING, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "calibration") \
    X(XF_ORDER_NEUTRAL, 1, 0, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "neutral") \
    X(XF_ORDER_OSD_COORDINATE, 2, 0, 0, 1, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, 1, 1, "osd_coordinate") \
    X(XF_ORDER_AUTO_FLIP, 2, 0, 0, 1, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, 1, 1, "auto_flip") \
    X(XF_ORDER_TIME_ZONE, 2, 0, 0, 1, XF_F_HOURS, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "time_zone") \
    X(XF_ORDER_ANGLE_CONTROL, 1, XF_ORDER_SETS_MODE, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "angle_control") \
    X(XF_ORDER_HEAD_LOCK, 1, XF_ORDER_SETS_MODE, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "head_lock") \
    X(XF_ORDER_HEAD_FOLLOW, 1, XF_ORDER_SETS_MODE, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "head_follow") \
    X(XF_ORDER_ORTHOVIEW, 1, XF_ORDER_SETS_MODE, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "orthoview") \
    X(XF_ORDER_EULER, 1, XF_ORDER_SETS_MODE, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "euler") \
    X(XF_ORDER_GAZE_GEO, 1, XF_ORDER_SETS_MODE, 0, 3, XF_F_LONGITUDE, XF_F_LATITUDE, XF_F_ALTITUDE, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "gaze_geo") \
    X(XF_ORDER_GAZE_LOCK, 1, XF_ORDER_SETS_MODE, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "gaze_lock") \
    X(XF_ORDER_TRACK, 1, XF_ORDER_MASK_FAILURE | XF_ORDER_SETS_MODE, XF_CAM1, 6, XF_F_CAMERAS, XF_F_VALUE, XF_F_X0, XF_F_Y0, XF_F_X1, XF_F_Y1, 1, 1, "track") \
    X(XF_ORDER_CLICK_TO_AIM, 1, XF_ORDER_MASK_FAILURE, XF_CAM1, 3, XF_F_CAMERAS, XF_F_X0, XF_F_Y0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "click_to_aim") \
    X(XF_ORDER_EXTERNAL_TRACK, 1, XF_ORDER_MASK_FAILURE | XF_ORDER_STREAMED | XF_ORDER_V1_ONLY, XF_CAM1, 4, XF_F_CAMERAS, XF_F_DX, XF_F_DY, XF_F_VALUE, XF__Z, XF__Z, XF__V_0_OR_2, XF__V_0_OR_2, "external_track") \
    X(XF_ORDER_FPV, 2, XF_ORDER_SETS_MODE, 0, 0, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "fpv") \
    X(XF_ORDER_SHUTTER, 1, 0, XF_CAM1, 1, XF_F_CAMERAS, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "shutter") \
    X(XF_ORDER_RECORD, 1, 0, XF_CAM1, 1, XF_F_CAMERAS, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "record") \
    X(XF_ORDER_ZOOM_IN, 1, XF_ORDER_MASK_FAILURE, XF_CAM1, 1, XF_F_CAMERAS, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "zoom_in") \
    X(XF_ORDER_ZOOM_OUT, 1, XF_ORDER_MASK_FAILURE, XF_CAM1, 1, XF_F_CAMERAS, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "zoom_out") \
    X(XF_ORDER_ZOOM_STOP, 1, XF_ORDER_MASK_FAILURE, XF_CAM1, 1, XF_F_CAMERAS, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "zoom_stop") \
    X(XF_ORDER_ZOOM_TO, 1, XF_ORDER_MASK_FAILURE, XF_CAM1, 2, XF_F_CAMERAS, XF_F_ZOOM, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "zoom_to") \
    X(XF_ORDER_FOCUS, 1, 0, XF_CAM1, 1, XF_F_CAMERAS, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, "focus") \
    X(XF_ORDER_PALETTE, 1, XF_ORDER_MASK_FAILURE, XF_CAM2, 2, XF_F_CAMERAS, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, 100, 10, "palette") \
    X(XF_ORDER_NIGHT_VISION, 1, 0, XF_CAM1, 2, XF_F_CAMERAS, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, 2, 2, "night_vision") \
    X(XF_ORDER_AREA_TEMP, 2, XF_ORDER_MASK_FAILURE, XF_CAM2, 6, XF_F_CAMERAS, XF_F_VALUE, XF_F_X0, XF_F_Y0, XF_F_X1, XF_F_Y1, 1, 1, "area_temp") \
    X(XF_ORDER_TEMP_ALARM, 2, XF_ORDER_MASK_FAILURE, XF_CAM2, 4, XF_F_CAMERAS, XF_F_VALUE, XF_F_TEMP_HIGH, XF_F_TEMP_LOW, XF__Z, XF__Z, 1, 1, "temp_alarm") \
    X(XF_ORDER_ISOTHERM, 2, XF_ORDER_MASK_FAILURE, XF_CAM2, 4, XF_F_CAMERAS, XF_F_VALUE, XF_F_TEMP_HIGH, XF_F_TEMP_LOW, XF__Z, XF__Z, 1, 1, "isotherm") \
    X(XF_ORDER_SPOT_TEMP, 2, XF_ORDER_MASK_FAILURE, XF_CAM2, 4, XF_F_CAMERAS, XF_F_VALUE, XF_F_X0, XF_F_Y0, XF__Z, XF__Z, 1, 1, "spot_temp") \
    X(XF_ORDER_OSD, 1, 0, 0, 1, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, 1, 1, "osd") \
    X(XF_ORDER_PIP, 1, 0, 0, 1, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, 0, 4, "pip") \
    X(XF_ORDER_TARGET_DETECTION, 2, 0, 0, 1, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, 1, 1, "target_detection") \
    X(XF_ORDER_DIGITAL_ZOOM, 2, 0, 0, 1, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, 1, 1, "digital_zoom") \
    X(XF_ORDER_LIGHTING, 1, 0, 0, 1, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, 255, 255, "lighting") \
    X(XF_ORDER_RANGING, 1, 0, 0, 1, XF_F_VALUE, XF__Z, XF__Z, XF__Z, XF__Z, XF__Z, XF__V_0_OR_2, XF__V_0_OR_2, "ranging")
#define XF__ROW(o, s, fl, kk, n, a, b, c, d, e, f, v1, v2, nm) \
    { (uint8_t)(o), (s), (fl), (kk), (n), { (a), (b), (c), (d), (e), (f) } },
#define XF__NAME(o, s, fl, kk, n, a, b, c, d, e, f, v1, v2, nm) nm "\0"
#define XF__VMAX(o, s, fl, kk, n, a, b, c, d, e, f, v1, v2, nm) { (v1), (v2) },
/* clang-format on */
#define XF__Z        0u
#define XF__V_0_OR_2 0xFEu /* TT is 0 or 2 (off / on, stop / keep going) */

/* The tables are at file scope, under their own names: defined where the
 * definitions are emitted only, once a program (nm shows each once). */
static const xf_order_info xf__order_rows[XF_ORDER_COUNT] = {XF__ORDER_ROWS(XF__ROW)};
static inline const xf_order_info *xf__order_table(void) { return xf__order_rows; }

/* The largest TT of each row in V0.1 and V0.2 (or XF__V_0_OR_2), in the table's order. */
static const uint8_t xf__order_vmax[XF_ORDER_COUNT][2] = {XF__ORDER_ROWS(XF__VMAX)};
static inline const uint8_t (*xf__value_max(void))[2] { return xf__order_vmax; }

/* The names of the table's rows, in its order, each ended by a NUL. */
static const char xf__order_name_list[] = XF__ORDER_ROWS(XF__NAME);
static inline const char *xf__order_names(void) { return xf__order_name_list; }

XF_API const xf_order_info *xf_order_at(size_t i) { return (i < XF_ORDER_COUNT) ? &xf__order_table()[i] : NULL; }

XF_API const xf_order_info *xf_order_lookup(uint8_t order)
{
    /* Binary search over the sorted table. */
    const xf_order_info *t = xf__order_table();
    size_t lo = 0, hi = XF_ORDER_COUNT;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2u;
        if (t[mid].order == order) {
            return &t[mid];
        }
        if (t[mid].order < order) {
            lo = mid + 1u;
        } else {
            hi = mid;
        }
    }
    return NULL;
}

XF_API const char *xf_order_name(uint8_t order)
{
    const xf_order_info *info = xf_order_lookup(order);
    return (info != NULL) ? xf__nth_name(xf__order_names(), (size_t)(info - xf__order_table())) : NULL;
}

XF_API xf_err xf_order_from_name(const char *name, uint8_t *order)
{
    const char *n = xf__order_names();
    size_t i, k;
    if (name == NULL || order == NULL) {
        return XF_ERR_ARG;
    }
    for (i = 0; i < XF_ORDER_COUNT; i++, n += k + 1u) {
        int same = 1;
        for (k = 0; n[k] != '\0'; k++) {
            same = same && name[k] != '\0' && ((name[k] == '-') ? '_' : name[k]) == n[k];
        }
        if (same && name[k] == '\0') {
            *order = xf__order_table()[i].order;
            return XF_OK;
        }
    }
    return XF_ERR_NOT_FOUND;
}

XF_API const char *xf_mode_name(uint8_t mode)
{
    switch (mode) {
    case XF_MODE_ANGLE_CONTROL: return "angle_control";
    case XF_MODE_HEAD_LOCK: return "head_lock";
    case XF_MODE_HEAD_FOLLOW: return "head_follow";
    case XF_MODE_ORTHOVIEW: return "orthoview";
    case XF_MODE_EULER: return "euler";
    case XF_MODE_GAZE: return "gaze";
    case XF_MODE_TRACK: return "track";
    case XF_MODE_FPV: return "fpv";
    default: return NULL;
    }
}

/* An array, not a literal per member: the bad-field reports of
 * xf_command_check are all a firmware keeps of the codec's names. */
static const char xf__field_name_list[] = "cameras\0value\0hours\0x0\0y0\0x1\0y1\0dx\0dy\0zoom\0temp_high\0"
                                          "temp_low\0longitude\0latitude\0altitude\0?\0none";

XF_API const char *xf_field_name(xf_field f)
{
    size_t i = (size_t)XF_F_ALTITUDE + ((f == XF_F_NONE) ? 2u : 1u); /* "none", or "?" */
    if ((unsigned)f <= (unsigned)XF_F_ALTITUDE) {
        i = (size_t)f;
    }
    return xf__nth_name(xf__field_name_list, i);
}

XF_API size_t xf_field_size(xf_field f)
{
    switch (f) {
    case XF_F_NONE: return 0u;
    case XF_F_CAMERAS:
    case XF_F_VALUE:
    case XF_F_HOURS: return 1u;
    case XF_F_LONGITUDE:
    case XF_F_LATITUDE:
    case XF_F_ALTITUDE: return 4u;
    default: return 2u;
    }
}

/* The parameter bytes of a table row: its fields' sizes. */
static size_t xf__row_params_len(const xf_order_info *info)
{
    size_t i, n = 0;
    for (i = 0; i < info->nfields; i++) {
        n += xf_field_size((xf_field)info->fields[i]);
    }
    return n;
}

XF_API size_t xf_order_params_len(uint8_t order)
{
    const xf_order_info *info = xf_order_lookup(order);
    return (info != NULL) ? xf__row_params_len(info) : 0u;
}

XF_API void xf_command_init(xf_command *cmd, uint8_t order)
{
    const xf_order_info *info = xf_order_lookup(order);
    if (cmd != NULL) {
        XF_MEMSET(cmd, 0, sizeof(*cmd));
        cmd->order = order;
        cmd->cameras = (info != NULL) ? info->default_cameras : 0u;
    }
}

static inline int32_t xf__sat(int32_t v, int32_t lo, int32_t hi) { return (v < lo) ? lo : ((v > hi) ? hi : v); }

XF_API int32_t xf_command_get(const xf_command *cmd, xf_field f)
{
    if (cmd == NULL) {
        return 0;
    }
    switch (f) {
    case XF_F_CAMERAS: return cmd->cameras;
    case XF_F_VALUE: return cmd->value;
    case XF_F_HOURS: return cmd->hours;
    case XF_F_X0: return cmd->x0;
    case XF_F_Y0: return cmd->y0;
    case XF_F_X1: return cmd->x1;
    case XF_F_Y1: return cmd->y1;
    case XF_F_DX: return cmd->dx;
    case XF_F_DY: return cmd->dy;
    case XF_F_ZOOM: return cmd->zoom;
    case XF_F_TEMP_HIGH: return cmd->temp_high;
    case XF_F_TEMP_LOW: return cmd->temp_low;
    case XF_F_LONGITUDE: return cmd->longitude;
    case XF_F_LATITUDE: return cmd->latitude;
    case XF_F_ALTITUDE: return cmd->altitude;
    default: return 0;
    }
}

XF_API void xf_command_set(xf_command *cmd, xf_field f, int32_t v)
{
    if (cmd == NULL) {
        return;
    }
    switch (f) {
    case XF_F_CAMERAS: cmd->cameras = (uint8_t)xf__sat(v, 0, 255); break;
    case XF_F_VALUE: cmd->value = (uint8_t)xf__sat(v, 0, 255); break;
    case XF_F_HOURS: cmd->hours = (int8_t)xf__sat(v, -128, 127); break;
    case XF_F_X0: cmd->x0 = (uint16_t)xf__sat(v, 0, 65535); break;
    case XF_F_Y0: cmd->y0 = (uint16_t)xf__sat(v, 0, 65535); break;
    case XF_F_X1: cmd->x1 = (uint16_t)xf__sat(v, 0, 65535); break;
    case XF_F_Y1: cmd->y1 = (uint16_t)xf__sat(v, 0, 65535); break;
    case XF_F_DX: cmd->dx = (int16_t)xf__sat(v, -32768, 32767); break;
    case XF_F_DY: cmd->dy = (int16_t)xf__sat(v, -32768, 32767); break;
    case XF_F_ZOOM: cmd->zoom = (int16_t)xf__sat(v, -32768, 32767); break;
    case XF_F_TEMP_HIGH: cmd->temp_high = (int16_t)xf__sat(v, -32768, 32767); break;
    case XF_F_TEMP_LOW: cmd->temp_low = (int16_t)xf__sat(v, -32768, 32767); break;
    case XF_F_LONGITUDE: cmd->longitude = v; break;
    case XF_F_LATITUDE: cmd->latitude = v; break;
    case XF_F_ALTITUDE: cmd->altitude = v; break;
    default: break;
    }
}

/*
 * The ranges of docs/protocol.md sections 7 and 10, field by field along the
 * order's layout (a table row says which members an order has, and its TT
 * range): one-byte members first (cameras, value, hours), then the rest,
 * the order in which the rules name a bad member.
 */
static inline int xf__field_ok(const xf_command *c, xf_field f, uint8_t vmax)
{
    switch (f) {
    case XF_F_CAMERAS: return c->cameras != 0u; /* a mask of no camera addresses nothing */
    case XF_F_VALUE: return (vmax == XF__V_0_OR_2) ? (c->value == 0u || c->value == 2u) : (c->value <= vmax);
    case XF_F_HOURS: return c->hours >= -12 && c->hours <= 14;
    /* boxes: top-left then bottom-right; an exit/off box may be all zero */
    case XF_F_X0: return c->x0 <= XF_GRID_MAX;
    case XF_F_Y0: return c->y0 <= XF_GRID_MAX;
    case XF_F_X1: return c->x1 <= XF_GRID_MAX && c->x1 >= c->x0;
    case XF_F_Y1: return c->y1 <= XF_GRID_MAX && c->y1 >= c->y0;
    case XF_F_DX:
    case XF_F_DY: {
        int v = (f == XF_F_DX) ? c->dx : c->dy;
        int lost = c->dx >= XF_EXT_TRACK_LOST && c->dy >= XF_EXT_TRACK_LOST; /* the "lost" marker */
        return lost || (v >= -XF_EXT_TRACK_MAX && v <= XF_EXT_TRACK_MAX);
    }
    case XF_F_ZOOM: return (c->zoom <= -10 || c->zoom >= 1) && c->zoom <= 10000;
    case XF_F_TEMP_LOW: return c->value != 1u || c->temp_high >= c->temp_low; /* when on */
    default: return 1;                                                        /* temp_high, gaze_geo's position: any */
    }
}

/* No member at fault (yet): what every result but XF_ERR_RANGE leaves in *bad_field. */
static inline void xf__no_bad_field(xf_field *bad_field)
{
    if (bad_field != NULL) {
        *bad_field = XF_F_NONE;
    }
}

XF_API xf_err xf_command_check(const xf_command *cmd, uint8_t version, xf_field *bad_field)
{
    const xf_order_info *info;
    uint8_t vmax;
    size_t pass, i;
    xf__no_bad_field(bad_field);
    if (cmd == NULL) {
        return XF_ERR_ARG;
    }
    info = xf_order_lookup(cmd->order);
    if (info == NULL) {
        return XF_ERR_NOT_FOUND;
    }
    vmax = xf__value_max()[info - xf__order_table()][version >= XF_PROTOCOL_V2];
    if (version >= XF_PROTOCOL_V2 && (cmd->order == XF_ORDER_TRACK || cmd->order == XF_ORDER_CLICK_TO_AIM) &&
        cmd->cameras != XF_CAM1) {
        if (bad_field != NULL) {
            *bad_field = XF_F_CAMERAS; /* V2.0.6 fixes this byte at 0x01: it is no mask there */
        }
        return XF_ERR_RANGE;
    }
    for (pass = 0; pass < 2u; pass++) {
        for (i = 0; i < info->nfields; i++) {
            xf_field f = (xf_field)info->fields[i];
            if ((xf_field_size(f) == 1u) == (pass == 0u) && !xf__field_ok(cmd, f, vmax)) {
                if (bad_field != NULL) {
                    *bad_field = f;
                }
                return XF_ERR_RANGE;
            }
        }
    }
    return XF_OK;
}

XF_API xf_err xf_command_encode(const xf_command *cmd, uint8_t version, uint8_t *params, size_t cap, size_t *out_len,
                                xf_field *bad_field)
{
    const xf_order_info *info;
    size_t i, n, off = 0;
    xf_err err = xf_command_check(cmd, version, bad_field); /* XF_ERR_ARG for a NULL cmd */
    if (err != XF_OK) {
        return err;
    }
    info = xf_order_lookup(cmd->order); /* found: xf_command_check() looked it up */
    n = xf__row_params_len(info);
    if (n > 0u && params == NULL) {
        return XF_ERR_ARG;
    }
    if (cap < n) {
        return XF_ERR_NO_SPACE;
    }
    for (i = 0; i < info->nfields; i++) {
        xf_field f = (xf_field)info->fields[i];
        int32_t v = xf_command_get(cmd, f);
        size_t sz = xf_field_size(f);
        /* Never true (n is the sum of the sizes), but it shows gcc 12 -O3
         * that the writes stay in params[0, n) of a caller's 1-byte array
         * (-Warray-bounds, -Wstringop-overflow: tests/matrix/user_tu.c). */
        if (off + sz > n) {
            break;
        }
        switch (sz) {
        case 1u: params[off] = (uint8_t)(v & 0xFF); break;
        case 2u: xf_put_u16le(params + off, (uint16_t)(v & 0xFFFF)); break;
        default: xf_put_s32le(params + off, v); break;
        }
        off += sz;
    }
    if (out_len != NULL) {
        *out_len = n;
    }
    return XF_OK;
}

XF_API xf_err xf_command_decode(uint8_t order, const uint8_t *params, size_t len, uint8_t version, xf_command *cmd,
                                xf_field *bad_field)
{
    const xf_order_info *info = xf_order_lookup(order);
    xf_command tmp;
    size_t i, off = 0;
    xf__no_bad_field(bad_field);
    if (cmd == NULL || (params == NULL && len > 0u)) {
        return XF_ERR_ARG;
    }
    if (info == NULL) {
        return XF_ERR_NOT_FOUND;
    }
    if (len != xf_order_params_len(order)) {
        return XF_ERR_PARAMS;
    }
    XF_MEMSET(&tmp, 0, sizeof(tmp));
    tmp.order = order;
    for (i = 0; i < info->nfields; i++) {
        xf_field f = (xf_field)info->fields[i];
        int32_t v;
        int is_signed = (f == XF_F_HOURS || f == XF_F_DX || f == XF_F_DY || f == XF_F_ZOOM || f == XF_F_TEMP_HIGH ||
                         f == XF_F_TEMP_LOW);
        size_t sz = xf_field_size(f);
        if (off + sz > len) { /* never (len was checked): as in xf_command_encode() */
            return XF_ERR_PARAMS;
        }
        switch (sz) {
        case 1u: v = is_signed ? xf_u8_to_s8(params[off]) : params[off]; break;
        case 2u: v = is_signed ? xf_get_s16le(params + off) : xf_get_u16le(params + off); break;
        default: v = xf_get_s32le(params + off); break;
        }
        xf_command_set(&tmp, f, v);
        off += sz;
    }
    {
        xf_err err = xf_command_check(&tmp, version, bad_field);
        if (err != XF_OK) {
            return err;
        }
    }
    *cmd = tmp;
    return XF_OK;
}

XF_API xf_err xf_host_set_command(xf_host_packet *pkt, const xf_command *cmd, xf_field *bad_field)
{
    size_t n = 0;
    xf_err err;
    if (pkt == NULL || cmd == NULL) {
        xf__no_bad_field(bad_field);
        return XF_ERR_ARG;
    }
    err = xf_command_encode(cmd, pkt->version, pkt->params, sizeof(pkt->params), &n, bad_field);
    if (err != XF_OK) {
        return err;
    }
    pkt->order = cmd->order;
    pkt->params_len = (uint8_t)n;
    return XF_OK;
}

XF_API xf_err xf_feedback_decode(uint8_t order, const uint8_t *fb, size_t len, xf_feedback *out)
{
    const xf_order_info *info = xf_order_lookup(order);
    uint8_t flags = (info != NULL) ? info->flags : 0u;
    if (out == NULL || (fb == NULL && len > 0u)) {
        return XF_ERR_ARG;
    }
    XF_MEMSET(out, 0, sizeof(*out));
    out->order = order;
    if (len == 0u) {
        return XF_OK; /* no execution state in this reply */
    }
    out->has_state = 1u;
    out->state = fb[0];
    if (fb[0] == XF_STATE_SUCCESS) {
        out->result = XF_RESULT_OK;
    } else if ((flags & XF_ORDER_OPERATING) != 0u && fb[0] == XF_STATE_OPERATING) {
        out->result = XF_RESULT_OPERATING;
    } else {
        out->result = XF_RESULT_FAILED;
        out->failed_cameras = ((flags & XF_ORDER_MASK_FAILURE) != 0u) ? fb[0] : 0u;
    }
    return XF_OK;
}

XF_API uint8_t xf_feedback_state(uint8_t order, xf_result result, uint8_t failed_cameras)
{
    const xf_order_info *info = xf_order_lookup(order);
    uint8_t flags = (info != NULL) ? info->flags : 0u;
    switch (result) {
    case XF_RESULT_OK: return XF_STATE_SUCCESS;
    case XF_RESULT_OPERATING: return XF_STATE_OPERATING;
    default:
        if ((flags & XF_ORDER_MASK_FAILURE) != 0u && failed_cameras != 0u) {
            return failed_cameras;
        }
        return XF_STATE_FAILURE;
    }
}

/* V2.0.6's support list (appendix 8): its 18 orders, in its order, and per
 * model a mask with bit k set when the model supports order k. Each comment
 * repeats the row as the vendor marks it, one column per order. */
#define XF__SUPPORT_ORDERS 18u
#define XF__SUPPORT_MODELS 20u
static const uint8_t xf__support_orders[XF__SUPPORT_ORDERS] = {XF_ORDER_TRACK,
                                                               XF_ORDER_OSD_COORDINATE,
                                                               XF_ORDER_AUTO_FLIP,
                                                               XF_ORDER_TIME_ZONE,
                                                               XF_ORDER_ZOOM_TO,
                                                               XF_ORDER_FOCUS,
                                                               XF_ORDER_PALETTE,
                                                               XF_ORDER_NIGHT_VISION,
                                                               XF_ORDER_AREA_TEMP,
                                                               XF_ORDER_TEMP_ALARM,
                                                               XF_ORDER_ISOTHERM,
                                                               XF_ORDER_SPOT_TEMP,
                                                               XF_ORDER_OSD,
                                                               XF_ORDER_PIP,
                                                               XF_ORDER_TARGET_DETECTION,
                                                               XF_ORDER_DIGITAL_ZOOM,
                                                               XF_ORDER_LIGHTING,
                                                               XF_ORDER_RANGING};
static const uint8_t xf__support_codes[XF__SUPPORT_MODELS] = {0,  2,  25, 26, 31, 40, 41, 44, 45, 49,
                                                              50, 52, 53, 55, 57, 58, 59, 60, 61, 62};
static const uint32_t xf__support_masks[XF__SUPPORT_MODELS] = {
    0x000A1u, /*  0 Z-6A         Y----Y-Y---------- */
    0x000A0u, /*  2 Z-6C         -----Y-Y---------- */
    0x200A1u, /* 25 Z-8RB        Y----Y-Y---------Y */
    0x200A0u, /* 26 Z-8RC        -----Y-Y---------Y */
    0x320E1u, /* 31 Z-9B_V3      Y----YYY-----Y--YY */
    0x130B1u, /* 40 D-80AI       Y---YY-Y----YY--Y- */
    0x230F1u, /* 41 D-90AI       Y---YYYY----YY---Y */
    0x100B1u, /* 44 D-80Pro      Y---YY-Y--------Y- */
    0x2FFFFu, /* 45 D-90Pro(TA)  YYYYYYYYYYYYYYYY-Y */
    0x0501Fu, /* 49 Z-1Pro       YYYYY-------Y-Y--- */
    0x0501Fu, /* 50 Z-1Mini      YYYYY-------Y-Y--- */
    0x0705Fu, /* 52 Z-2Mini      YYYYY-Y-----YYY--- */
    0x2FFFFu, /* 53 D-125AI(T)   YYYYYYYYYYYYYYYY-Y */
    0x230B1u, /* 55 D-90DE       Y---YY-Y----YY---Y */
    0x2F0FFu, /* 57 D-125AI(V)   YYYYYYYY----YYYY-Y */
    0x3FFFFu, /* 58 Z-9B_V4(T)   YYYYYYYYYYYYYYYYYY */
    0x3F0FFu, /* 59 Z-9B_V4(V)   YYYYYYYY----YYYYYY */
    0x2F0FFu, /* 60 D-90Pro(VA)  YYYYYYYY----YYYY-Y */
    0x2BFFEu, /* 61 D-90Pro(T)   -YYYYYYYYYYYYY-Y-Y */
    0x2B0FEu, /* 62 D-90Pro(V)   -YYYYYYY----YY-Y-Y */
};

XF_API uint8_t xf_osd_value(int show, uint8_t version)
{
    return (uint8_t)((version >= XF_PROTOCOL_V2) == (show != 0)); /* V0.2: 1 = on; V0.1: 0 = shown */
}

XF_API xf_support xf_gimbal_supports(uint8_t gimbal_code, uint8_t order)
{
    unsigned m = 0, k = 0;
    while (m < XF__SUPPORT_MODELS && xf__support_codes[m] != gimbal_code) {
        m++;
    }
    if (m == XF__SUPPORT_MODELS || order == XF_ORDER_EXTERNAL_TRACK || xf_order_lookup(order) == NULL) {
        return XF_SUPPORT_UNKNOWN;
    }
    while (k < XF__SUPPORT_ORDERS && xf__support_orders[k] != order) {
        k++;
    }
    if (k == XF__SUPPORT_ORDERS) {
        return XF_SUPPORT_YES; /* the list's rule: an order it leaves out is supported by every model */
    }
    return ((xf__support_masks[m] >> k) & 1u) ? XF_SUPPORT_YES : XF_SUPPORT_NO;
}

#endif /* XF_EMIT_DEFINITIONS */

XF_END_DECLS

#endif /* XF_COMMAND_H */
