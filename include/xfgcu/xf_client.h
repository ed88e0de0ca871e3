/*
 * xf_client.h - the host side of the protocol: the 30-50 Hz question-and-
 * answer loop, carrier data, control, commands, telemetry, link health.
 *
 * Portable C over xf_hal: no OS, no heap, no threads, no globals. The
 * application owns the xf_client storage and drives it by calling
 * xf_client_step(c, now_ms) often enough (at least at the packet rate;
 * xf_client_next_deadline() says when next). Any number of clients can
 * live in one process; a client is not thread-safe.
 *
 * Every packet is built from the latest inputs:
 *  - carrier state (attitude, accelerations without gravity, velocities):
 *    sent with ins_valid only while younger than carrier_max_age_ms,
 *    otherwise zeros with ins_valid clear. Never invented.
 *  - GNSS (position, satellites, week/ms, relative height): the sub frame
 *    is filled only while younger than gnss_max_age_ms, else all zero.
 *  - control quantities, with ctrl_valid: rates (deg/s) or angles (deg),
 *    whose meaning is the gimbal mode's (head lock: rates; euler: Euler
 *    angles; angle_control/fpv: angles relative to the carrier).
 *
 * Commands run the way the protocol wants: null packets by default; a
 * command is sent in every packet until a reply carries its execution
 * state; then null packets again, so two commands of the same order are
 * always separated by a null. A command of the same order as the last one
 * (or the exit of a stopped external-track stream) starts only once a
 * reply to a later, different packet has come back (nulls are sent until
 * then; not while the link is down), so a late reply to the previous
 * command of that order is never mistaken for this one's, however long
 * the link's delay. Calibration's "operating" keeps it going until its final
 * state. Results: ok, failed (with the failed-camera mask), timeout,
 * link lost; by callback and by polling the command's id.
 *
 * Rate watchdog: rates not refreshed for rate_watchdog_ms are replaced by
 * zero rates, so a stalled application never leaves a gimbal spinning.
 */
#ifndef XF_CLIENT_H
#define XF_CLIENT_H

#include <stddef.h>
#include <stdint.h>
#include "xf_command.h"
#include "xf_config.h"
#include "xf_error.h"
#include "xf_hal.h"
#include "xf_packet.h"
#include "xf_parser.h"
#include "xf_units.h"

XF_BEGIN_DECLS

#ifndef XF_CLIENT_QUEUE
#define XF_CLIENT_QUEUE 8 /**< commands waiting to run, per client */
#endif
#ifndef XF_CLIENT_RESULTS
#define XF_CLIENT_RESULTS 8 /**< finished commands kept for polling by id */
#endif
#if XF_CLIENT_QUEUE < 1 || XF_CLIENT_QUEUE > 64 || XF_CLIENT_RESULTS < 1 || XF_CLIENT_RESULTS > 64
#error "XF_CLIENT_QUEUE and XF_CLIENT_RESULTS must be in [1, 64]"
#endif

/** Link health. */
typedef enum xf_link_state {
    XF_LINK_DOWN =
        0, /**< no valid reply for down_ms (or never), or the transport was closed and no valid reply came since */
    XF_LINK_STALE = 1, /**< no valid reply for stale_ms */
    XF_LINK_UP = 2
} xf_link_state;

/** Where a command is. */
typedef enum xf_cmd_status {
    XF_CMD_UNKNOWN = 0,   /**< no such id (never submitted, or forgotten) */
    XF_CMD_QUEUED = 1,    /**< waiting behind other commands */
    XF_CMD_SENDING = 2,   /**< in every packet, no execution state yet */
    XF_CMD_OPERATING = 3, /**< the GCU said "operating" (calibration); final state to come */
    XF_CMD_OK = 4,
    XF_CMD_FAILED = 5,    /**< the GCU said failure; see failed_cameras */
    XF_CMD_TIMEOUT = 6,   /**< no execution state within the timeout */
    XF_CMD_LINK_LOST = 7, /**< the link went down before it finished */
    XF_CMD_CANCELLED = 8  /**< removed by xf_client_cancel_all */
} xf_cmd_status;

/** A command's outcome (or progress, for XF_CMD_OPERATING). */
typedef struct xf_cmd_result {
    uint32_t id;
    uint8_t order;
    uint8_t status;         /**< xf_cmd_status */
    uint8_t state;          /**< the GCU's state byte, when it sent one */
    uint8_t failed_cameras; /**< for orders that report a mask */
    uint16_t packets;       /**< packets that carried the command */
    uint32_t elapsed_ms;    /**< from first sent to this result */
} xf_cmd_result;

/**
 * The gimbal's state as the GCU sent it: the wire's integers under the
 * spec's names (xf_gcu_main, xf_gcu_sub), 64 bytes rather than a copy of
 * every packet in floats. Physical units on read: xf_telemetry_convert()
 * for all of them at once, or xf_units.h's function named at each member.
 */
typedef struct xf_telemetry {
    /* main frame: in every reply, received at xf_health.last_rx_ms */
    uint8_t have_main;   /**< 0 until the first reply */
    uint8_t version;     /**< protocol version the GCU speaks */
    uint8_t gimbal_mode; /**< xf_mode */
    uint16_t pod_status; /**< XF_POD_* */
    int16_t cam_roll;    /**< 0.01 deg, absolute (xf_cdeg) */
    int16_t cam_pitch;
    uint16_t cam_yaw;    /**< [0, 36000) */
    int16_t rel_angle_x; /**< 0.01 deg relative to the carrier (xf_cdeg) */
    int16_t rel_angle_y;
    int16_t rel_angle_z;
    int16_t rate_x; /**< 0.01 deg/s in V0.1, 0.1 deg/s in V0.2 (xf_gcu_rate_dps(raw, version)) */
    int16_t rate_y;
    int16_t rate_z;
    int16_t target_offset_x, target_offset_y; /**< [-1000, 1000] */
    /* sub frame (sub_header 0x01): kept from the last one received */
    uint8_t have_sub; /**< 0 until the first sub frame */
    uint8_t hw_version, fw_version;
    uint8_t gimbal_code;    /**< xf_gimbal_model() */
    uint8_t thermal_status; /**< V0.2: XF_THERMAL_* */
    int8_t time_zone;       /**< V0.2 */
    uint16_t error_code;    /**< V0.2: XF_ERROR_* */
    uint16_t camera_status; /**< V0.2: XF_CAMERA_* */
    uint16_t zoom_cam1;     /**< 0.1 x (xf_zoom_x) */
    uint16_t zoom_cam2;
    int32_t target_distance;  /**< 0.1 m; <= 0: no valid measurement (xf_distance_m) */
    int32_t target_longitude; /**< 1e-7 deg (xf_deg7) */
    int32_t target_latitude;
    int32_t target_altitude; /**< mm */
    uint32_t sub_ms;         /**< when the last sub frame arrived (xf_client_step's clock) */
} xf_telemetry;

/** The telemetry's quantities in physical units (xf_telemetry_convert). */
typedef struct xf_telemetry_units {
    float cam_roll_deg, cam_pitch_deg, cam_yaw_deg;
    float rel_x_deg, rel_y_deg, rel_z_deg;
    float rate_x_dps, rate_y_dps, rate_z_dps; /**< unit of the wire picked by the version */
    float zoom_cam1, zoom_cam2;               /**< x */
    float target_distance_m;                  /**< 0 when distance_valid is 0 */
    uint8_t distance_valid;
} xf_telemetry_units;

/** Link health figures. The receive parser's counters: xf_client_parser_stats(). */
typedef struct xf_health {
    uint8_t link;             /**< xf_link_state */
    uint8_t watchdog_active;  /**< zero rates are being sent because rates went stale */
    uint8_t transport_closed; /**< the transport said the link is closed (a backend may be restoring it) */
    uint16_t reply_rate_hz;   /**< replies in the last full second */
    uint32_t last_rx_ms;      /**< when the last valid reply arrived */
    uint32_t packets_sent;
    uint32_t replies;         /**< valid GCU packets received */
    uint32_t replies_missing; /**< packets of the last full second that got no reply */
    uint32_t send_errors;     /**< HAL writes that failed */
    uint32_t watchdog_trips;
} xf_health;

/** Carrier state; gravity excluded from the accelerations. */
typedef struct xf_carrier {
    float roll_deg, pitch_deg, yaw_deg;      /**< absolute Euler angles (vendor appendix 2 frame) */
    float accel_north, accel_east, accel_up; /**< m/s^2, 0 when static or in steady flight */
    float vel_north, vel_east, vel_up;       /**< m/s */
} xf_carrier;

/**
 * GNSS data for the sub frame, in the wire's own integer units (what GNSS
 * receivers and autopilots give, and no double arithmetic on an MCU; from
 * degrees and metres: xf_deg7_raw(), xf_mm_raw()).
 */
typedef struct xf_gnss {
    int32_t latitude_e7, longitude_e7; /**< 1e-7 deg */
    int32_t altitude_mm;
    uint8_t satellites;
    int16_t week;
    uint32_t ms_of_week;
    int32_t relative_height_mm; /**< 0 when not needed */
} xf_gnss;

typedef void (*xf_on_result_fn)(void *user, const xf_cmd_result *result);
typedef void (*xf_on_telemetry_fn)(void *user, const xf_telemetry *telemetry);
typedef void (*xf_on_link_fn)(void *user, xf_link_state state);
/** Every packet sent and received, raw (for tracing and recording). */
typedef void (*xf_on_bytes_fn)(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms);

/**
 * Limits: the ages and link times are uint16_t, up to 65535 ms (a minute
 * is far longer than a 30-50 Hz link can stay silent and still be useful);
 * the two command timeouts are uint32_t. xf_client_init refuses values
 * that cannot work (XF_ERR_RANGE).
 */
typedef struct xf_client_config {
    xf_on_result_fn on_result;
    xf_on_telemetry_fn on_telemetry;
    xf_on_link_fn on_link;
    xf_on_bytes_fn on_bytes;
    void *user;
    uint32_t command_timeout_ms;   /**< no execution state within this: timeout; >= 1, default 1000 */
    uint32_t operating_timeout_ms; /**< after "operating", the final state within this; >= 1, default 60000 */
    uint16_t rate_hz;              /**< packets per second, 1..200; default 50 (30-50 recommended) */
    uint16_t carrier_max_age_ms;   /**< default 200 */
    uint16_t gnss_max_age_ms;      /**< default 2000 */
    uint16_t stale_ms;             /**< >= 1, default 250 */
    uint16_t down_ms;              /**< > stale_ms, default 1000 */
    uint16_t rate_watchdog_ms;     /**< default 500; 0 = off (not recommended) */
    uint8_t protocol_version;      /**< sent in byte 4; >= 1, default 1 */
} xf_client_config;

/* A command as it goes on the wire: checked and encoded once, at submit.
 * Its id is not kept: ids are handed out in queue order (xf_client.c's
 * xf__queued_id), which saves 4 bytes a slot. */
typedef struct xf_cmd_slot {
    uint8_t order;
    uint8_t params_len;
    uint8_t params[XF_PARAMS_KNOWN_MAX];
} xf_cmd_slot;

/* Carrier state as it goes on the wire, in the wire's order (host bytes
 * 12-29: roll, pitch, yaw, accelerations north, east, up, velocities
 * north, east, up; xf_host_main's units), converted once by
 * xf_client_set_carrier rather than kept as nine floats. */
#define XF__CARRIER_WORDS 9u

/** Client state: treat the members as private; use the functions. */
typedef struct xf_client {
    xf_client_config cfg;
    xf_hal hal;
    xf_parser parser;
    xf_telemetry tele;
    xf_health health;
    /* inputs; times on xf_client_step's clock */
    xf_gnss gnss;
    uint32_t gnss_ms, carrier_ms, ctrl_ms;
    float ctrl[3]; /* roll, pitch, yaw: deg/s or deg as ctrl_kind says */
    uint16_t carrier[XF__CARRIER_WORDS];
    uint8_t have_carrier, have_gnss;
    uint8_t ctrl_kind; /* 0 none, 1 rates, 2 angles */
    /* streamed external track: its parameter bytes, encoded once (order 0x1B's are 6) */
    uint8_t stream_on;
    uint8_t stream[6];
    /* commands */
    xf_cmd_slot queue[XF_CLIENT_QUEUE];
    uint8_t q_head, q_count;
    uint8_t active;      /* queue[q_head] is being sent */
    uint8_t operating;   /* ... and the GCU said "operating" */
    uint8_t guard_order; /* order of the last finished command (or of the stopped stream) */
    uint8_t guard_open;  /* no reply of another order seen since: a command of guard_order waits */
    uint8_t nulls_owed;  /* null packets to send before the next command */
    uint8_t r_next;      /* results[r_next] is overwritten next */
    uint32_t started_ms, operating_ms;
    uint32_t next_id; /* the id the next submitted command gets; never 0 */
    xf_cmd_result results[XF_CLIENT_RESULTS];
    /* timing */
    uint32_t now_ms;
    uint32_t next_send_ms;
    uint32_t window_start_ms;
    uint16_t window_sent, window_replies; /* in the window: at most a second's worth (replies saturate) */
    uint16_t period_ms;
    uint16_t packets; /* packets that carried the running command */
    uint8_t started;
    uint8_t awaiting;        /* the last packet sent has had no reply yet */
    uint8_t window_awaiting; /* the same, when the window started */
} xf_client;

/** Defaults, as documented in xf_client_config. */
void xf_client_config_init(xf_client_config *cfg);

/**
 * Start a client on @p hal (copied). @p cfg NULL means defaults.
 * @return XF_OK, XF_WARN_RATE (accepted; rate outside 30-50 Hz),
 *   XF_ERR_ARG (NULL, incomplete hal), XF_ERR_RANGE (rate 0 or > 200,
 *   version 0, stale_ms 0, down_ms <= stale_ms, a command timeout 0).
 */
xf_err xf_client_init(xf_client *c, const xf_hal *hal, const xf_client_config *cfg);

/**
 * Do what is due at @p now_ms: read and parse what arrived, update
 * telemetry and health, resolve commands, send the next packet when due.
 * Callbacks run from here. Returns XF_OK, or the transport's error of this
 * step (XF_ERR_CLOSED while the link is down; the client keeps going).
 */
xf_err xf_client_step(xf_client *c, uint32_t now_ms);

/** When the next packet is due (for a poll timeout). */
uint32_t xf_client_next_deadline(const xf_client *c);

/* ---- inputs ------------------------------------------------------------------ */

void xf_client_set_carrier(xf_client *c, const xf_carrier *carrier, uint32_t now_ms);
void xf_client_set_gnss(xf_client *c, const xf_gnss *gnss, uint32_t now_ms);
/** Desired angular velocities (deg/s), scaled by the zoom the GCU reports. Subject to the watchdog. */
void xf_client_set_rates(xf_client *c, float roll_dps, float pitch_dps, float yaw_dps, uint32_t now_ms);
/** Desired angles (deg): Euler or relative to the carrier, as the mode says. Roll and yaw are wrapped into [-180, 180),
 * pitch is clamped to [-180, 180]. */
void xf_client_set_angles(xf_client *c, float roll_deg, float pitch_deg, float yaw_deg, uint32_t now_ms);
/** No control quantities (ctrl_valid clear). */
void xf_client_clear_control(xf_client *c);

/* ---- commands ---------------------------------------------------------------- */

/**
 * Queue @p cmd (checked against the protocol version). *id (may be NULL)
 * identifies it for xf_client_command_status and the result callback.
 * @return XF_OK, XF_ERR_ARG, XF_ERR_RANGE / XF_ERR_UNSUPPORTED (from
 *   xf_command_check; *bad_field names the member), XF_ERR_BUSY (queue full).
 */
xf_err xf_client_submit(xf_client *c, const xf_command *cmd, uint32_t *id, const char **bad_field);

/** Status of command @p id; *result (may be NULL) gets its result once finished. */
xf_cmd_status xf_client_command_status(const xf_client *c, uint32_t id, xf_cmd_result *result);

/** Commands queued or running. */
size_t xf_client_pending(const xf_client *c);

/** Drop every queued command (XF_CMD_CANCELLED); the one running is cancelled too. */
void xf_client_cancel_all(xf_client *c);

/**
 * External track is streamed, not run once: while on, every packet that
 * carries no other command carries order 0x1B with these offsets.
 * xf_client_external_track_stop() sends the exit (value 0) as a command.
 */
xf_err xf_client_external_track(xf_client *c, uint8_t cameras, int16_t dx, int16_t dy);
xf_err xf_client_external_track_stop(xf_client *c, uint32_t *id);

/* ---- state ------------------------------------------------------------------- */

const xf_telemetry *xf_client_telemetry(const xf_client *c);
/**
 * @p t in physical units (computed on read: the client keeps the wire's
 * integers). @return XF_OK, XF_ERR_ARG (NULL).
 */
xf_err xf_telemetry_convert(const xf_telemetry *t, xf_telemetry_units *u);
const xf_health *xf_client_health(const xf_client *c);
/** The receive parser's counters (frames, CRC and length errors, bytes skipped); NULL if @p c is NULL. */
const xf_parser_stats *xf_client_parser_stats(const xf_client *c);
xf_link_state xf_client_link(const xf_client *c);
const char *xf_link_state_name(xf_link_state s);
const char *xf_cmd_status_name(xf_cmd_status s);

XF_END_DECLS

#endif /* XF_CLIENT_H */
