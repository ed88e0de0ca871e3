/**
 * @file
 * @brief The host side of the protocol: the 30-50 Hz question-and-answer
 * loop, carrier data, control, commands, telemetry, link health.
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
 * always separated by a null. A new client runs no command until a reply
 * to one of its nulls has come back (a late reply to an earlier program's
 * command is not its own). A command of the same order as the last one
 * (or the exit of a stopped external-track stream), while a packet of that
 * one has no reply yet, starts only once the reply to a later null has
 * come back (nulls are sent until then), so a late reply to the previous
 * command of that order is never mistaken for this one's (every order waits
 * so with reorder_ms, or while another guard is open; a guard that had
 * none of the old command's replies gives up after command_timeout_ms,
 * leaving the client unsettled). Before it stops,
 * a program lets the client settle (xf_client_settled()). On a link that
 * reorders or duplicates, reorder_ms bounds how far; while it is 0 the
 * client uses a bound of its own until the link has shown that it keeps
 * order, and whenever replies come out of turn or twice (xf_health;
 * docs/protocol.md §7.4 says what each rule guarantees). Calibration's "operating" keeps it
 * going until its final state. Results: ok, failed (with the failed-camera
 * mask), timeout, link lost; by callback and by polling the command's id.
 *
 * Rate watchdog: rates not refreshed for rate_watchdog_ms are replaced by
 * zero rates, so a stalled application never leaves a gimbal spinning.
 *
 * Blocking: no client function waits. xf_client_step() takes as long as the
 * link's read and write (xf_hal; a POSIX serial or TCP write waits at most
 * 100 ms for a full driver buffer); every other function only updates the
 * client's memory.
 *
 * Callbacks (xf_client_config) run on the thread that steps the client, from
 * inside xf_client_step() (and on_result also from inside
 * xf_client_cancel_all()). What they may call on their own client is listed
 * at the callback types (xf_on_result_fn): everything but a step.
 */
#ifndef XF_CLIENT_H
#define XF_CLIENT_H

#include <stdbool.h>
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

/** Link health. */
typedef enum xf_link_state {
    XF_LINK_DOWN =
        0, /**< no valid reply for down_ms (or never), or the transport was closed and no valid reply came since */
    XF_LINK_STALE = 1, /**< no valid reply for stale_ms */
    XF_LINK_UP = 2     /**< a valid reply within the last stale_ms */
} xf_link_state;

/** Where a command is (xf_client_command_status(), xf_cmd_result.status). */
typedef enum xf_cmd_status {
    XF_CMD_UNKNOWN = 0,   /**< no such id (never submitted, or forgotten) */
    XF_CMD_QUEUED = 1,    /**< waiting: behind other commands, or until the link is settled (a reply to a null) */
    XF_CMD_SENDING = 2,   /**< in every packet, no execution state yet */
    XF_CMD_OPERATING = 3, /**< the GCU said "operating" (calibration); final state to come */
    XF_CMD_OK = 4,        /**< the GCU said success */
    XF_CMD_FAILED = 5,    /**< the GCU said failure; see failed_cameras */
    XF_CMD_TIMEOUT = 6,   /**< no execution state within the timeout */
    XF_CMD_LINK_LOST = 7, /**< the link went down before it finished */
    XF_CMD_CANCELLED = 8, /**< removed by xf_client_cancel_all */
    /** never sent: checked before the GCU had answered (for xf_client_gcu_version() then), its
     *  parameters are out of range, or mean something else, in the version the GCU speaks */
    XF_CMD_REFUSED = 9
} xf_cmd_status;

/**
 * A command's outcome (or progress, for XF_CMD_OPERATING). The client keeps
 * the last ones in a smaller form (xf_cmd_record) and gives them back as
 * this.
 */
typedef struct xf_cmd_result {
    uint32_t id;            /**< the id xf_client_submit() gave it */
    uint8_t order;          /**< its order (::xf_order) */
    xf_cmd_status status;   /**< where it is, or how it ended */
    uint8_t state;          /**< the GCU's state byte, when it sent one */
    uint8_t failed_cameras; /**< for orders that report a mask */
    uint16_t packets;       /**< packets that carried the command */
    uint32_t elapsed_ms;    /**< from first sent to this result */
} xf_cmd_result;

/**
 * The gimbal's state as the GCU sent it: the wire's integers under the
 * spec's names (xf_gcu_main, xf_gcu_sub), kept compact rather than as a
 * copy of every packet in floats (its size: docs/performance.md). Physical
 * units on read: xf_telemetry_convert() for all of them at once, or
 * xf_units.h's function named at each member.
 */
typedef struct xf_telemetry {
    /* main frame: in every reply, received at xf_health.last_rx_ms */
    uint8_t have_main;   /**< 0 until the first reply */
    uint8_t version;     /**< protocol version the GCU speaks */
    uint8_t gimbal_mode; /**< xf_mode */
    uint16_t pod_status; /**< the raw little-endian wire word; its flags: xf_client_pod_flags() */
    int16_t cam_roll;    /**< 0.01 deg, absolute (xf_cdeg) */
    int16_t cam_pitch;   /**< 0.01 deg, absolute (xf_cdeg) */
    uint16_t cam_yaw;    /**< 0.01 deg, absolute, [0, 36000) (xf_cdeg) */
    int16_t rel_angle_x; /**< 0.01 deg relative to the carrier (xf_cdeg) */
    int16_t rel_angle_y; /**< 0.01 deg relative to the carrier (xf_cdeg) */
    int16_t rel_angle_z; /**< 0.01 deg relative to the carrier (xf_cdeg) */
    int16_t rate_x;      /**< 0.01 deg/s in V0.1, 0.1 deg/s in V0.2 (xf_gcu_rate_dps(raw, version)) */
    int16_t rate_y;      /**< as rate_x */
    int16_t rate_z;      /**< as rate_x */
    /** @var xf_telemetry::target_offset_x
     *  horizontal target offset, [-1000, 1000], right positive */
    int16_t target_offset_x, target_offset_y; /**< vertical target offset, [-1000, 1000], down positive */
    /* sub frame (sub_header 0x01): kept from the last one received */
    uint8_t have_sub; /**< 0 until the first sub frame */
    /** @var xf_telemetry::hw_version
     *  hardware version */
    uint8_t hw_version, fw_version; /**< firmware version */
    uint8_t gimbal_code;            /**< xf_gimbal_model() */
    uint8_t thermal_status;         /**< V0.2: XF_THERMAL_* */
    int8_t time_zone;               /**< V0.2: hours from UTC */
    uint16_t error_code;            /**< V0.2: XF_ERROR_* */
    uint16_t camera_status;         /**< V0.2: XF_CAMERA_* */
    uint16_t zoom_cam1;             /**< camera 1's zoom, 0.1 x (xf_zoom_x) */
    uint16_t zoom_cam2;             /**< camera 2's zoom, 0.1 x (xf_zoom_x) */
    int32_t target_distance;        /**< 0.1 m; <= 0: no valid measurement (xf_distance_m) */
    int32_t target_longitude;       /**< target longitude, 1e-7 deg (xf_deg7) */
    int32_t target_latitude;        /**< target latitude, 1e-7 deg (xf_deg7) */
    int32_t target_altitude;        /**< target altitude, mm */
    uint32_t sub_ms;                /**< when the last sub frame arrived (xf_client_step's clock) */
} xf_telemetry;

/** The telemetry's quantities in physical units (xf_telemetry_convert). */
typedef struct xf_telemetry_units {
    /** @var xf_telemetry_units::cam_roll_deg
     *  camera's absolute roll, deg */
    /** @var xf_telemetry_units::cam_pitch_deg
     *  camera's absolute pitch, deg */
    float cam_roll_deg, cam_pitch_deg, cam_yaw_deg; /**< camera's absolute yaw, deg, [0, 360) */
    /** @var xf_telemetry_units::rel_x_deg
     *  camera's X-axis angle relative to the carrier, deg */
    /** @var xf_telemetry_units::rel_y_deg
     *  camera's Y-axis angle relative to the carrier, deg */
    float rel_x_deg, rel_y_deg, rel_z_deg; /**< camera's Z-axis angle relative to the carrier, deg */
    /** @var xf_telemetry_units::rate_x_dps
     *  angular velocity about X, deg/s (the wire unit picked by the version) */
    /** @var xf_telemetry_units::rate_y_dps
     *  angular velocity about Y, deg/s */
    float rate_x_dps, rate_y_dps, rate_z_dps; /**< angular velocity about Z, deg/s */
    /** @var xf_telemetry_units::zoom_cam1
     *  camera 1's zoom, x */
    float zoom_cam1, zoom_cam2; /**< camera 2's zoom, x */
    float target_distance_m;    /**< 0 when distance_valid is false */
    bool distance_valid;        /**< target_distance_m holds a valid measurement (xf_distance_m()) */
} xf_telemetry_units;

/** Link health figures. The receive parser's counters: xf_client_parser_stats(). */
typedef struct xf_health {
    xf_link_state link;       /**< up, stale or down */
    uint8_t watchdog_active;  /**< zero rates are being sent because rates went stale */
    uint8_t transport_closed; /**< the transport said the link is closed (a backend may be restoring it) */
    uint16_t reply_rate_hz;   /**< replies in the last full second (window of at least 1 s) */
    uint32_t last_rx_ms;      /**< when the last valid reply arrived */
    uint32_t packets_sent;    /**< packets the link accepted */
    uint32_t replies;         /**< valid GCU packets received */
    uint32_t replies_missing; /**< packets of the last full second that got no reply */
    uint32_t send_errors;     /**< HAL writes that failed */
    uint32_t watchdog_trips;  /**< times the rate watchdog started sending zero rates */
    uint8_t version_sent;     /**< the version byte the client sends now (with version_auto: the one it tries) */
    /** the version byte of the packets the GCU answers: the one a reply to a null came for; 0 before (and,
     *  with version_auto, while the client looks for it again after the link went down) */
    uint8_t version_answered;
    /** 1: the link has shown that it keeps order (its first six packets each answered before the next was
     *  sent, all with the same round trip within an eighth of a period, or 25 packet periods in a row with
     *  one reply each) and no reply came out of turn since; never again once a reply came that no link in
     *  order delivers (docs/protocol.md §7.4) */
    uint8_t in_order;
    /** the reorder bound in force, ms: xf_client_config.reorder_ms when the application set one (or fixed
     *  0); else the client's own while the link is not in_order, 0 while it is */
    uint16_t reorder_ms;
    /** replies that came out of turn or twice: more in one packet period than packets sent in it, a reply
     *  of a command's order after another order's reply that followed one of its own, more replies of a
     *  command than its packets. On a link that keeps order and does not duplicate, 0. */
    uint32_t out_of_turn;
} xf_health;

/** Carrier state; gravity excluded from the accelerations. */
typedef struct xf_carrier {
    /** @var xf_carrier::roll_deg
     *  absolute roll, deg (vendor appendix 2 frame; wrapped into [-180, 180)) */
    /** @var xf_carrier::pitch_deg
     *  absolute pitch, deg (clamped to [-90, 90]) */
    float roll_deg, pitch_deg, yaw_deg; /**< absolute yaw, deg (wrapped into [0, 360)) */
    /** @var xf_carrier::accel_north
     *  m/s^2, north positive; 0 when static or in steady flight */
    /** @var xf_carrier::accel_east
     *  m/s^2, east positive */
    float accel_north, accel_east, accel_up; /**< m/s^2, up positive, gravity excluded */
    /** @var xf_carrier::vel_north
     *  m/s, north positive */
    /** @var xf_carrier::vel_east
     *  m/s, east positive */
    float vel_north, vel_east, vel_up; /**< m/s, up positive */
} xf_carrier;

/**
 * GNSS data for the sub frame, in the wire's own integer units (what GNSS
 * receivers and autopilots give, and no double arithmetic on an MCU; from
 * degrees and metres: xf_deg7_raw(), xf_mm_raw()).
 */
typedef struct xf_gnss {
    /** @var xf_gnss::latitude_e7
     *  latitude, 1e-7 deg */
    int32_t latitude_e7, longitude_e7; /**< longitude, 1e-7 deg */
    int32_t altitude_mm;               /**< altitude, mm */
    uint8_t satellites;                /**< satellites in use */
    int16_t week;                      /**< GNSS week number */
    uint32_t ms_of_week;               /**< GNSS milliseconds of week (xf_unix_ms_to_gnss()) */
    int32_t relative_height_mm;        /**< 0 when not needed */
} xf_gnss;

/**
 * @name Callbacks, and what they may call
 *
 * The four callbacks run on the thread that steps the client, from inside
 * xf_client_step(); on_result also from inside xf_client_cancel_all(). On
 * its own client a callback may call:
 *
 * - Reading state, yes: xf_client_telemetry(), xf_client_health(),
 *   xf_client_parser_stats(), xf_client_link(), xf_client_command_status(),
 *   xf_client_pending(), xf_client_next_deadline(), xf_telemetry_convert().
 *   They give the state as it is at that moment: on_bytes for a reply runs
 *   before the client has processed it; in on_link, and in on_result for
 *   ::XF_CMD_LINK_LOST, xf_health.link is already the new state; in
 *   on_result the command's own status is already final.
 * - Commands, yes: xf_client_submit() and xf_client_external_track_stop()
 *   queue behind the commands already there. One submitted while every
 *   command is being finished (link lost, xf_client_cancel_all()) is not
 *   part of that sweep: it stays queued, and runs next.
 * - xf_client_cancel_all(), yes: every command queued at that moment is
 *   cancelled and reported to on_result from inside the call (nested in the
 *   callback).
 * - Inputs, yes: xf_client_set_carrier(), xf_client_set_gnss(),
 *   xf_client_set_rates(), xf_client_set_angles(),
 *   xf_client_clear_control(), xf_client_external_track(). The next packet
 *   built uses them (this step's, if one is due and not yet sent). Pass the
 *   time of the step (on_bytes has it).
 * - xf_client_step(), no: a step is not re-entrant (a nested one would read
 *   and parse new bytes in the middle of the outer step's parse), so called
 *   from a callback it returns ::XF_ERR_BUSY at once and does nothing. Nor
 *   xf_posix_poll() with this client among its clients.
 * - xf_client_init(), no: it would wipe the client under the step that runs
 *   the callback (not checked).
 *
 * A callback may step and drive other clients. Pointers it receives are
 * valid during the call only.
 * @{
 */

/**
 * A command reached its final status, exactly once per submitted command
 * (and, for calibration, once more earlier with ::XF_CMD_OPERATING). Runs
 * inside xf_client_step(), or inside xf_client_cancel_all() for
 * ::XF_CMD_CANCELLED; what it may call: see above. A command submitted
 * from here while the client is finishing every queued command (link lost,
 * xf_client_cancel_all()) survives that sweep, so a callback that resubmits
 * what failed does not keep the sweep going: the new command runs next (and
 * with the link down, ends in ::XF_CMD_LINK_LOST at its timeout unless a
 * reply comes first).
 * @param user    xf_client_config.user
 * @param result  the result, valid during the call only (final results are
 *   also kept for xf_client_command_status())
 */
typedef void (*xf_on_result_fn)(void *user, const xf_cmd_result *result);
/**
 * A valid reply arrived and the telemetry was updated: once per reply,
 * after that reply's on_link and on_result. Runs inside xf_client_step();
 * what it may call: see above.
 * @param user       xf_client_config.user
 * @param telemetry  the client's telemetry (as xf_client_telemetry() gives
 *   it); it changes with the next reply
 */
typedef void (*xf_on_telemetry_fn)(void *user, const xf_telemetry *telemetry);
/**
 * The link state changed. On ::XF_LINK_DOWN every command that was queued
 * or running has already been finished with ::XF_CMD_LINK_LOST (those that
 * on_result submitted meanwhile stay queued). Runs inside
 * xf_client_step(); what it may call: see above.
 * @param user   xf_client_config.user
 * @param state  the new state
 */
typedef void (*xf_on_link_fn)(void *user, xf_link_state state);
/**
 * Every packet sent and received, raw (for tracing and recording): each
 * packet the link accepted (::XF_DIR_HOST), and each valid GCU packet
 * received (::XF_DIR_GCU), before the client processes it. Bytes that belong
 * to no valid packet are not reported (wrap the HAL to see the raw stream).
 * Runs inside xf_client_step(); what it may call: see above.
 * @param user    xf_client_config.user
 * @param dir     ::XF_DIR_HOST (sent) or ::XF_DIR_GCU (received)
 * @param data    the packet, valid during the call only
 * @param len     its length in bytes
 * @param now_ms  the time given to xf_client_step()
 */
typedef void (*xf_on_bytes_fn)(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms);

/** @} */

/**
 * Limits: the ages and link times are uint16_t, up to 65535 ms (a minute
 * is far longer than a 30-50 Hz link can stay silent and still be useful);
 * the two command timeouts are uint32_t. xf_client_init refuses values
 * that cannot work (XF_ERR_RANGE). Start from xf_client_config_init(),
 * then change what you need.
 */
typedef struct xf_client_config {
    xf_on_result_fn on_result;       /**< command results; NULL: none (poll xf_client_command_status()) */
    xf_on_telemetry_fn on_telemetry; /**< telemetry after each reply; NULL: none */
    xf_on_link_fn on_link;           /**< link state changes; NULL: none */
    xf_on_bytes_fn on_bytes;         /**< every packet sent and received; NULL: none */
    void *user;                      /**< passed to every callback */
    uint32_t command_timeout_ms;     /**< no execution state within this: timeout; >= 1, default 1000 */
    uint32_t operating_timeout_ms;   /**< after "operating", the final state within this; >= 1, default 60000 */
    uint16_t rate_hz;                /**< packets per second, 1..200; default 50 (30-50 recommended) */
    uint16_t carrier_max_age_ms; /**< carrier data older than this is not sent (zeros, ins_valid clear); default 200 */
    uint16_t gnss_max_age_ms;    /**< GNSS data older than this is not sent (sub frame all zero); default 2000 */
    uint16_t stale_ms;           /**< no valid reply for this long: ::XF_LINK_STALE; >= 1, default 250 */
    uint16_t down_ms;            /**< no valid reply for this long: ::XF_LINK_DOWN; > stale_ms, default 1000 */
    uint16_t rate_watchdog_ms;   /**< rates older than this become zero rates; default 500; 0 = off (not recommended) */
    uint8_t protocol_version;    /**< sent in byte 4, and the version commands are checked for; >= 1, default 1 */
    /** 1: find the version the GCU answers (xf_client_answered_version()): send protocol_version, and the other
     *  version (1 or 2) whenever no reply has come for stale_ms, until a null is answered; then keep the version
     *  that was answered, looking again only once the link has gone down. 0 (default): send protocol_version. */
    uint8_t version_auto;
    /** The longest a packet or a reply can be overtaken by a later one on the link, ms; default 0:
     *  the link keeps order (serial, TCP, UDP on loopback or a wired LAN). Over a network that can
     *  reorder or duplicate datagrams, set the bound: the client then waits this long around each
     *  command (docs/protocol.md §7.4), so that no reply is taken for the wrong command and the
     *  GCU runs each command once. At most 1000, and stale_ms must exceed a packet period plus
     *  twice this (xf_client_config_problem()). While it is 0, and unless reorder_fixed is set, the client
     *  judges the link itself: a new client's first command waits while the first six packet periods can
     *  still show the link in order, and commands run with the largest bound stale_ms and
     *  command_timeout_ms allow (114 ms with the defaults) while the link has not shown it
     *  (xf_health.reorder_ms, in_order, out_of_turn; docs/protocol.md §7.4). */
    uint16_t reorder_ms;
    /** 1: keep reorder_ms as set (0 included) whatever the link shows, and never wait for the link to be
     *  judged (for a link known to keep order: a serial line, TCP); 0 (default): the client may apply a
     *  bound of its own on a link that reorders or duplicates, while reorder_ms is 0 */
    uint8_t reorder_fixed;
} xf_client_config;

/**
 * Internal (a member of xf_client): a queued command as it goes on the
 * wire, checked and encoded once, at submit. Its id is not kept: ids are
 * handed out in queue order (xf_client.c's xf__queued_id), which saves RAM
 * per slot (docs/performance.md).
 */
typedef struct xf_cmd_slot {
    uint8_t order;                       /**< the order byte */
    uint8_t params_len;                  /**< parameter bytes used */
    uint8_t fits;                        /**< the versions in which they are valid and mean the same (bits) */
    uint8_t params[XF_PARAMS_KNOWN_MAX]; /**< the encoded parameters */
} xf_cmd_slot;

/**
 * Internal (a member of xf_client): a finished command's result as the
 * client keeps it for xf_client_command_status(): xf_cmd_result with the
 * status in one byte, and without the id (commands finish in the order of
 * their ids, so a record's id follows from its place: xf_client.c's
 * xf__id_back), so that each of the ::XF_CLIENT_RESULTS kept takes 12 bytes
 * on a 32-bit target whatever the size of its enums.
 */
typedef struct xf_cmd_record {
    uint8_t order;          /**< as xf_cmd_result.order */
    uint8_t status;         /**< xf_cmd_result.status (an ::xf_cmd_status); 0: no record yet */
    uint8_t state;          /**< as xf_cmd_result.state */
    uint8_t failed_cameras; /**< as xf_cmd_result.failed_cameras */
    uint16_t packets;       /**< as xf_cmd_result.packets */
    uint32_t elapsed_ms;    /**< as xf_cmd_result.elapsed_ms */
} xf_cmd_record;

/* Carrier state as it goes on the wire, in the wire's order (host bytes
 * 12-29: roll, pitch, yaw, accelerations north, east, up, velocities
 * north, east, up; xf_host_main's units), converted once by
 * xf_client_set_carrier rather than kept as nine floats. */
#define XF__CARRIER_WORDS 9u
/* GNSS data as it goes on the wire: host bytes 38-60 (longitude .. relative height), written once
 * by xf_client_set_gnss. */
#define XF__GNSS_BYTES 23u

/**
 * Client state: treat the members as private; use the functions. The
 * members are grouped by size (1, 2, then 4 bytes, the structs last), so
 * that a 32-bit target pads none of them, and the ones the client reads
 * most come first: a Cortex-M's 2-byte load reaches the first 32 bytes of a
 * struct (bytes), 64 (halfwords) or 128 (words), beyond them it takes 4.
 */
typedef struct xf_client {
    /* commands */
    /** @var xf_client::q_head
     *  private: index of the oldest queued command */
    uint8_t q_head, q_count; /**< private: commands in the queue */
    uint8_t active;          /**< private: queue[q_head] is being sent */
    uint8_t operating;       /**< private: ... and the GCU said "operating" */
    uint8_t nulls_owed;      /**< private: null packets to send before the next command */
    uint8_t r_next;          /**< private: results[r_next] is overwritten next */
    uint8_t head_new;        /**< private: the queue's head is new: it waits from the next step's time */
    uint8_t guard_order;     /**< private: order of the last finished command (or of the stopped stream) */
    uint8_t guard_open;  /**< private: no null's reply since the guarded packets: guard_order waits (every order with
                            reorder_ms or guard_multi) */
    uint8_t guard_wait;  /**< private: a reply of guard_order must come first (none had come when it ended) */
    uint8_t guard_multi; /**< private: the guard holds for every order (another guard was still open) */
    uint8_t stream_on;   /**< private: the external-track stream is on */
    /* inputs */
    /** @var xf_client::have_carrier
     *  private: carrier state was set */
    uint8_t have_carrier, have_gnss; /**< private: GNSS data was set */
    uint8_t ctrl_kind;   /**< private: 0 none, 1 rates, 2 angles, 3 none: dropped (xf_client_control_status()) */
    uint8_t ctrl_mode;   /**< private: the reported mode that last read the setpoint (0: none yet) */
    uint8_t main_camera; /**< private: the camera on the main screen, whose zoom scales rates (1 or 2) */
    uint8_t pod_order;   /**< private: xf_pod_order of pod_status in use; 0x80 set: forced */
    /* the link */
    uint8_t started;         /**< private: the first step has run */
    uint8_t awaiting;        /**< private: the last packet sent has had no reply yet */
    uint8_t window_awaiting; /**< private: the same, when the window started */
    uint8_t busy; /**< private: in xf_client_step() or xf_client_cancel_all(): a nested step returns ::XF_ERR_BUSY */
    /** private: 0; 1: a reply to a null has come back; 2: and reorder_ms has passed, commands may start */
    uint8_t synced;
    uint8_t round_replies; /**< private: replies since the last packet sent (saturating) */
    uint8_t run_order;     /**< private: the order of the running command, or of the last one */
    uint8_t run_seen;      /**< private: 1: a reply of run_order came since it started; 2: and then one of another */
    uint8_t steady;        /**< private: packet periods in a row with one reply each */
    uint8_t out_of_order;  /**< private: a reply came that no link in order can deliver: never in_order again */
    /** @var xf_client::phase_ms
     *  private: the time from packet to reply in the first of the steady periods (xf__judge_round) */
    uint8_t phase_ms, round_rtt; /**< private: the time from the last packet to the first reply since; 255: later */
    /* streamed external track: its parameter bytes, encoded once (order 0x1B's are 6) */
    uint8_t stream[6]; /**< private: the stream's encoded parameters */
    /** @var xf_client::window_sent
     *  private: packets sent in the window */
    uint16_t window_sent, window_replies; /**< private: replies in the window (saturating) */
    uint16_t period_ms;                   /**< private: ms between packets */
    uint16_t packets;                     /**< private: packets that carried the running command */
    uint16_t answered;                    /**< private: replies of the running command's order so far */
    uint16_t carrier[XF__CARRIER_WORDS];  /**< private: carrier state as it goes on the wire */
    /* times, on xf_client_step's clock */
    uint32_t now_ms;       /**< private: the time of the current step */
    uint32_t next_send_ms; /**< private: when the next packet is due */
    /** @var xf_client::last_tx_ms
     *  private: when the last packet went out */
    /** @var xf_client::sync_ms
     *  private: when synced became 1 */
    /** @var xf_client::head_ms
     *  private: when the queue's head began to wait, or (running) was first sent */
    uint32_t last_tx_ms, sync_ms, head_ms;
    uint32_t next_id; /**< private: the id the next submitted command gets; never 0 */
    /** @var xf_client::gnss_ms
     *  private: when the GNSS data was set */
    /** @var xf_client::carrier_ms
     *  private: when the carrier state was set */
    uint32_t gnss_ms, carrier_ms, ctrl_ms;    /**< private: when the control quantities were set */
    uint32_t operating_ms;                    /**< private: when the GCU said "operating" */
    uint32_t window_start_ms;                 /**< private: start of the current one-second window */
    uint32_t guard_ms;                        /**< private: when the guard opened */
    uint32_t version_ms;                      /**< private: when the client began to send the version it sends now */
    float ctrl[3];                            /**< private: roll, pitch, yaw: deg/s or deg as ctrl_kind says */
    xf_client_config cfg;                     /**< private: the configuration (a copy) */
    xf_health health;                         /**< private: xf_client_health() */
    xf_hal hal;                               /**< private: the link (a copy) */
    xf_telemetry tele;                        /**< private: xf_client_telemetry() */
    xf_cmd_record results[XF_CLIENT_RESULTS]; /**< private: the last finished commands, a ring */
    xf_parser parser;                         /**< private: parser of the GCU's replies */
    xf_cmd_slot queue[XF_CLIENT_QUEUE];       /**< private: commands queued or running, a ring */
    uint8_t gnss[XF__GNSS_BYTES];             /**< private: the last GNSS data, as it goes on the wire */
} xf_client;

/**
 * Fill @p cfg with the defaults documented at each member of
 * xf_client_config (no callbacks, 50 Hz, protocol version 1). Does nothing
 * for a NULL @p cfg.
 * @param cfg  the configuration to fill
 */
void xf_client_config_init(xf_client_config *cfg);

/**
 * Start a client on @p hal (copied). @p cfg NULL means defaults.
 *
 * A macro over xf_client_init_checked(), which also checks that the caller
 * and the library were built with the same layout options (xf_config.h).
 * No I/O: the first xf_client_step() sends the first packet. Never blocks.
 * On error @p c is left alone.
 * @param c    the client's storage
 * @param hal  the link (copied; what its ctx points to must outlive the client)
 * @param cfg  the configuration (copied), or NULL for xf_client_config_init()'s defaults
 * @return XF_OK, XF_WARN_RATE (accepted; rate outside 30-50 Hz),
 *   XF_ERR_ARG (NULL, incomplete hal), XF_ERR_RANGE (a configuration that
 *   cannot work: xf_client_config_problem() says why),
 *   ::XF_ERR_CONFIG (built with other layout options than the library).
 */
#define xf_client_init(c, hal, cfg) xf_client_init_checked((c), (hal), (cfg), XF_OPTIONS_CHECK, sizeof(xf_client))

/**
 * What xf_client_init() calls, with the caller's build options: use the
 * macro. A foreign-function interface calls this directly with the values
 * of the library it loads (xf_options_word(), xf_client_size()).
 * @param c        as for xf_client_init()
 * @param hal      as for xf_client_init()
 * @param cfg      as for xf_client_init()
 * @param options  the caller's ::XF_OPTIONS_WORD
 * @param size     the caller's sizeof(xf_client)
 * @return what xf_client_init() returns, or ::XF_ERR_CONFIG when @p options
 *   or @p size differ from the library's (nothing is written to @p c).
 */
xf_err xf_client_init_checked(xf_client *c, const xf_hal *hal, const xf_client_config *cfg, unsigned long options,
                              size_t size);

/**
 * Why xf_client_init() would refuse @p cfg with ::XF_ERR_RANGE, as one
 * short line naming the members and their limits: a rate outside 1..200; a version or
 * operating timeout of 0; reorder_ms over 1000; version_auto other than 0 or 1; stale_ms not above one packet
 * period plus twice reorder_ms (the link would read stale between two good
 * replies: at 1 Hz the default 250 ms is), down_ms not above stale_ms;
 * command_timeout_ms under a round trip (two packet periods plus twice
 * reorder_ms).
 * @param cfg  the configuration (NULL: the defaults, which are fine)
 * @return NULL when it can work, else a static string
 */
const char *xf_client_config_problem(const xf_client_config *cfg);

/** The times a configuration implies, which xf_client_config_problem() checks. */
typedef struct xf_client_timing {
    uint32_t period_ms;     /**< between two packets: 1000 / rate_hz, rounded */
    uint32_t gap_ms;        /**< the longest a working link goes without a reply: period_ms plus twice
                                 reorder_ms (the silence around a command); stale_ms must exceed it */
    uint32_t round_trip_ms; /**< the shortest command_timeout_ms: two packet periods plus twice reorder_ms */
} xf_client_timing;

/**
 * The times @p cfg implies, as numbers, for a caller that explains a
 * configuration xf_client_config_problem() refuses in its own terms (the
 * program names its options), with the library's arithmetic.
 * @param cfg  the configuration
 * @param t    receives the times
 * @return ::XF_OK, or ::XF_ERR_ARG (NULL, or rate_hz outside 1..200; @p t is left alone)
 */
xf_err xf_client_config_timing(const xf_client_config *cfg, xf_client_timing *t);

/**
 * Whether the client may stop without leaving a reply to one of its commands in flight: nothing
 * queued or running, and every packet that carried a command answered, or followed by a null
 * packet whose reply is back (docs/protocol.md §7.4). A program that exits while this is 0 may
 * leave the GCU's "ok" to its last command on the link, where the next program to run a
 * command of that order could take it for its own; keep stepping until it is 1 (or give up
 * after a bound, and say so).
 * @param c  the client
 * @return 1 or 0 (0 for a NULL @p c)
 */
int xf_client_settled(const xf_client *c);

/**
 * sizeof(xf_client) in the library (for a foreign-function interface).
 * @return the size in bytes
 */
size_t xf_client_size(void);

/**
 * Do what is due at @p now_ms: read and parse what arrived, update
 * telemetry and health, resolve commands, send the next packet when due.
 * Callbacks run from here. Returns XF_OK, or the transport's error of this
 * step (XF_ERR_CLOSED while the link is down; the client keeps going).
 *
 * One step reads the link up to 16 times (fewer when it runs dry), handles
 * every valid reply, updates the link state, times commands out, and sends
 * at most one packet: a step that comes late sends one packet, not a burst
 * to catch up. Never waits itself, but takes as long as the link's read and
 * write (a POSIX serial or TCP write waits at most 100 ms for a full driver
 * buffer). Not re-entrant: called from one of the client's callbacks
 * it returns ::XF_ERR_BUSY and does nothing.
 *
 * Cost: O(bytes read) through the parser, plus O(::XF_CLIENT_QUEUE) at most for commands it
 * ends, plus the link's read and write calls; stack: a receive buffer of ::XF_PACKET_MAX_LEN
 * bytes and the packet being sent, plus what the callbacks use. Never allocates. Measured CPU
 * and RAM per gimbal: docs/performance.md.
 * @param c       the client
 * @param now_ms  the time, ms, on a wrapping clock the application keeps
 *   (xf_posix_now_ms() on POSIX); the same clock for every call and input
 * @return ::XF_OK; ::XF_ERR_ARG (NULL @p c); ::XF_ERR_BUSY (called from one
 *   of the client's callbacks, or from inside xf_client_cancel_all(): nothing
 *   done, not even the time taken); or the link's error of this
 *   step: a read error (::XF_ERR_CLOSED, ::XF_ERR_IO, the latter also for a
 *   read that says it copied more than asked, none of which is read: reading
 *   stops for this step, the packet due is still sent) takes precedence over a write
 *   error (::XF_ERR_AGAIN, ::XF_ERR_CLOSED, ::XF_ERR_IO: counted in
 *   xf_health.send_errors; that packet is not sent again, the next goes at
 *   the next period)
 */
xf_err xf_client_step(xf_client *c, uint32_t now_ms);

/**
 * When the next packet is due, on xf_client_step()'s clock: the time to
 * step the client next (for a poll timeout), unless its link becomes
 * readable first.
 * @param c  the client
 * @return the time, ms; 0 for a NULL @p c and before the first step (due at
 *   once)
 */
uint32_t xf_client_next_deadline(const xf_client *c);

/* ---- inputs ------------------------------------------------------------------ */

/**
 * The carrier's latest state, converted at once to the wire's units
 * (roll and yaw wrapped, pitch clamped; xf_carrier). Packets carry it with
 * ins_valid set while it is at most carrier_max_age_ms old, and zeros with
 * ins_valid clear after that: never invented. Does nothing for a NULL
 * @p c or @p carrier.
 * @param c        the client
 * @param carrier  the state (copied)
 * @param now_ms   when it was measured, on xf_client_step()'s clock
 */
void xf_client_set_carrier(xf_client *c, const xf_carrier *carrier, uint32_t now_ms);
/**
 * The latest GNSS data. Packets carry it in the sub frame while it is at
 * most gnss_max_age_ms old; after that the sub frame is all zero. Does
 * nothing for a NULL @p c or @p gnss.
 * @param c       the client
 * @param gnss    the data (copied)
 * @param now_ms  when it was measured, on xf_client_step()'s clock
 */
void xf_client_set_gnss(xf_client *c, const xf_gnss *gnss, uint32_t now_ms);
/**
 * The pod status flags (`XF_POD_*`) of the last reply, read in the byte
 * order this GCU uses. The vendor documents the word as little-endian but
 * decodes its own example big-endian (docs/protocol.md §11.7); the client
 * decides from the data: the first reply whose word reads with the
 * reserved bits clear in one order only (xf_pod_status_order()) fixes the
 * order for this client, and it stays until the application forces one
 * (xf_client_set_pod_order()). Until then the word is read little-endian.
 * telemetry.pod_status stays the raw wire word.
 * @param c  the client
 * @return the flags; 0 for a NULL @p c
 */
uint16_t xf_client_pod_flags(const xf_client *c);

/**
 * The byte order the client reads the pod status word in: what
 * xf_client_pod_flags() uses.
 * @param c  the client
 * @return ::XF_POD_ORDER_LE or ::XF_POD_ORDER_BE once decided or forced,
 *   ::XF_POD_ORDER_UNDECIDED before (read as little-endian meanwhile), or
 *   for a NULL @p c
 */
xf_pod_order xf_client_pod_order(const xf_client *c);

/**
 * Force the byte order of the pod status word (::XF_POD_ORDER_LE or
 * ::XF_POD_ORDER_BE), or go back to deciding it from the data
 * (::XF_POD_ORDER_UNDECIDED). Does nothing for a NULL @p c.
 * @param c      the client
 * @param order  the order, or ::XF_POD_ORDER_UNDECIDED for automatic
 */
void xf_client_set_pod_order(xf_client *c, xf_pod_order order);

/**
 * Say which camera is on the main screen: its zoom scales the rates
 * (xf_client_set_rates()), since the protocol's rate unit is 0.1 deg/s
 * divided by the main screen's zoom. The GCU does not report which camera
 * that is (its picture-in-picture mode is a number whose views the vendor
 * does not define), so the application, which chose the view, tells the
 * client; until it does, camera 1 (the zoom camera by default). Does
 * nothing for a NULL @p c.
 * @param c       the client
 * @param camera  1 or 2 (any other value: camera 1)
 */
void xf_client_set_main_camera(xf_client *c, uint8_t camera);

/**
 * Whether the control quantities the application set are on the wire, and
 * if not, why: xf_client_control_status(), and what xf_client_set_rates()
 * and xf_client_set_angles() return.
 *
 * The rule (V2.0.6, docs/protocol.md §11.1 and §11.2). A packet carries the
 * quantities, with ctrl_valid set, only when the mode the GCU last reported
 * reads the kind the application set:
 *
 * | mode the GCU reports                                         | reads  |
 * |--------------------------------------------------------------|--------|
 * | angle control 0x10, Euler 0x14, FPV 0x1C                     | angles |
 * | head lock 0x11, head follow 0x12, orthoview 0x13, gaze 0x16  | rates  |
 * | track 0x17, any other mode, no reply yet                     | none   |
 *
 * and never while a neutral, click-to-aim or mode command (one that sets
 * the mode: angle control, head lock, ..., track, gaze-geo, FPV) runs: the
 * first three need the quantities invalid (after click-to-aim the gimbal is
 * in head lock, and a valid non-zero quantity turns gaze-geo into gaze
 * lock), and a mode command changes how the GCU reads them from its first
 * packet on. Otherwise the packet carries zeros with ctrl_valid clear. A
 * setpoint is dropped, and must be set again, when the mode that read it
 * changes, when a mode command starts while it is on the wire, and when a
 * neutral, track, click-to-aim or gaze-geo command starts: the next mode
 * may read the same bytes as something else. A setpoint held because the
 * mode reads the other kind is kept, and goes out once a mode that reads it
 * is reported ("set the angles, then switch to Euler").
 */
typedef enum xf_ctrl_status {
    XF_CTRL_SENT = 0,       /**< on the wire, ctrl_valid set (zero rates when the watchdog has tripped) */
    XF_CTRL_NOT_SET = 1,    /**< no setpoint: none set, or xf_client_clear_control() */
    XF_CTRL_NO_MODE = 2,    /**< held: no reply yet, so the mode that would read it is unknown */
    XF_CTRL_WRONG_KIND = 3, /**< held: the reported mode reads the other kind (rates, angles) */
    XF_CTRL_NOT_READ = 4,   /**< held: the reported mode reads no control quantities (track) */
    XF_CTRL_COMMAND = 5,    /**< held: a neutral, click-to-aim or mode command runs (track, gaze-geo, Euler, ...) */
    XF_CTRL_DROPPED = 6     /**< dropped: the mode that read it changed, or one of those commands started */
} xf_ctrl_status;

/**
 * Where the application's setpoint stands (xf_ctrl_status): on the wire,
 * held and why, dropped, or none.
 * @param c  the client
 * @return the status; ::XF_CTRL_NOT_SET for a NULL @p c
 */
xf_ctrl_status xf_client_control_status(const xf_client *c);

/**
 * Desired angular velocities (deg/s), scaled by the zoom the GCU reports. Subject to the watchdog.
 *
 * Sent with ctrl_valid in every packet whose mode reads rates
 * (::xf_ctrl_status), each converted with
 * xf_ctrl_rate_raw() using the main camera's zoom (xf_client_set_main_camera(); camera 1
 * by default) from the telemetry (1 until a
 * sub frame arrived), clamped to [-1500, 1500] raw. When they are older
 * than rate_watchdog_ms, zero rates are sent instead (still valid, so the
 * gimbal holds still) and xf_health.watchdog_active is set until the next
 * call. Which axes a mode reads: docs/protocol.md §11. Replaces any angles.
 * Does nothing for a NULL @p c.
 * @param c          the client
 * @param roll_dps   roll rate, deg/s
 * @param pitch_dps  pitch rate, deg/s
 * @param yaw_dps    yaw rate, deg/s
 * @param now_ms     the time, on xf_client_step()'s clock (starts the watchdog)
 * @return where the setpoint stands now (::XF_CTRL_SENT: the next packet
 *   carries it); ::XF_CTRL_NOT_SET for a NULL @p c
 */
xf_ctrl_status xf_client_set_rates(xf_client *c, float roll_dps, float pitch_dps, float yaw_dps, uint32_t now_ms);
/**
 * Desired angles (deg): Euler or relative to the carrier, as the mode says. Roll and yaw are wrapped into [-180, 180),
 * pitch is clamped to [-180, 180].
 *
 * Sent with ctrl_valid in every packet whose mode reads angles
 * (::xf_ctrl_status), until replaced or dropped; not subject to the rate
 * watchdog. Replaces any rates. Which axes a mode reads:
 * docs/protocol.md §11. Does nothing for a NULL @p c.
 * @param c          the client
 * @param roll_deg   roll, deg
 * @param pitch_deg  pitch, deg
 * @param yaw_deg    yaw, deg
 * @param now_ms     the time, on xf_client_step()'s clock
 * @return as xf_client_set_rates()
 */
xf_ctrl_status xf_client_set_angles(xf_client *c, float roll_deg, float pitch_deg, float yaw_deg, uint32_t now_ms);
/**
 * No control quantities: packets carry zeros with ctrl_valid clear (the
 * gimbal holds; needed during neutral, track and click-to-aim,
 * docs/protocol.md §11). Does nothing for a NULL @p c.
 * @param c  the client
 */
void xf_client_clear_control(xf_client *c);

/* ---- commands ---------------------------------------------------------------- */

/**
 * Queue @p cmd (checked against the protocol version). *id (may be NULL)
 * identifies it for xf_client_command_status and the result callback.
 *
 * The command is checked and encoded now, for the version the GCU speaks
 * (xf_client_gcu_version(): cfg.protocol_version until it answers), and
 * runs when the commands before it have finished. If the GCU turns out to
 * speak the other version, it is checked again when it would start: when
 * its parameters are out of range there, or mean something else (OSD's
 * value), it ends as ::XF_CMD_REFUSED, never sent. It is sent in every
 * packet until a reply carries its execution state, then a null packet
 * follows. A command of the same order as the last one, while a packet of
 * that one has no reply yet, waits until the reply to a null sent after it
 * has come back (see xf_client.h and docs/protocol.md §7.4). Its result comes once,
 * through on_result and xf_client_command_status(). ::XF_ORDER_NULL is
 * accepted, but a GCU whose null replies carry no execution state (72-byte
 * replies, as V0.2 documents) never answers it: it ends in ::XF_CMD_TIMEOUT.
 * Never blocks; may be called from the client's callbacks.
 *
 * Cost: O(the order's parameters): the command is checked for both protocol versions and
 * encoded once, into the queue; no call to the link. Never allocates.
 * @param c          the client
 * @param cmd        the command (copied)
 * @param id         receives the command's id, never 0 (may be NULL)
 * @param bad_field  receives the member at fault on ::XF_ERR_RANGE,
 *   ::XF_F_NONE on any other result (xf_command_check()); may be NULL
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p c or @p cmd), ::XF_ERR_RANGE
 *   (*bad_field names the member) or ::XF_ERR_NOT_FOUND (an order the
 *   protocol does not define), from xf_command_check(); ::XF_ERR_UNSUPPORTED
 *   (the GCU's model does not support the order: xf_client_submit_opt());
 *   ::XF_ERR_BUSY (queue full: ::XF_CLIENT_QUEUE commands)
 */
xf_err xf_client_submit(xf_client *c, const xf_command *cmd, uint32_t *id, xf_field *bad_field);

/**
 * The protocol version whose meaning the client follows: the one the GCU
 * speaks (the version byte of its replies) once it has answered, before
 * that cfg.protocol_version. Commands are checked and encoded for it
 * (ranges such as palette and picture-in-picture); the version byte the
 * client sends is cfg.protocol_version, or with version_auto the one the GCU
 * answers (xf_client_answered_version()).
 * @param c  the client
 * @return 1 or 2 (what the GCU sends), or 0 for a NULL @p c
 */
uint8_t xf_client_gcu_version(const xf_client *c);

/**
 * The version byte of the host packets the GCU answers: the one the client
 * was sending when the reply to one of its nulls came back. With
 * xf_client_config.version_auto the client keeps sending it; the GCU's own
 * version, whose meaning the client follows, is xf_client_gcu_version().
 * Also in xf_health.version_answered.
 * @param c  the client
 * @return 1 or 2 (protocol_version without version_auto), or 0 before a null
 *   has been answered (and while a version_auto client looks again after
 *   the link went down), and for a NULL @p c
 */
uint8_t xf_client_answered_version(const xf_client *c);

/**
 * Show or hide the on-screen display: an ::XF_ORDER_OSD command with the
 * value that means it in the GCU's version (xf_osd_value(); the meaning was
 * inverted between V0.1 and V0.2), queued as xf_client_submit() queues.
 * The value is chosen when the command starts, once the GCU has answered,
 * so it means show or hide whatever version the GCU turns out to speak.
 * @param c     the client
 * @param show  nonzero to show the OSD, 0 to hide it
 * @param id    receives the command's id (may be NULL)
 * @return as xf_client_submit()
 */
xf_err xf_client_osd(xf_client *c, int show, uint32_t *id);

/** xf_client_submit_opt() flag: queue the command even if the GCU's model does not support it. */
#define XF_SUBMIT_ANY_MODEL 0x01u

/**
 * xf_client_submit() with options. It refuses an order that the model the
 * GCU reports (sub frame byte 40) does not support by V2.0.6's support list
 * (xf_client_supports() says ::XF_SUPPORT_NO) with ::XF_ERR_UNSUPPORTED and
 * queues nothing; with ::XF_SUBMIT_ANY_MODEL in @p flags it queues it all
 * the same (the application insists: a firmware may do more than the list
 * says). Before the first sub frame the model is unknown and nothing is
 * refused for it.
 * @param c          the client
 * @param cmd        the command (copied)
 * @param flags      0, or ::XF_SUBMIT_ANY_MODEL
 * @param id         receives the command's id, never 0 (may be NULL)
 * @param bad_field  as for xf_client_submit()
 * @return what xf_client_submit() returns, and ::XF_ERR_UNSUPPORTED (the
 *   GCU's model does not support the order: nothing queued)
 */
xf_err xf_client_submit_opt(xf_client *c, const xf_command *cmd, unsigned flags, uint32_t *id, xf_field *bad_field);

/**
 * What V2.0.6's support list says of @p order on the GCU's model
 * (xf_gimbal_supports() on the code of the last sub frame).
 * @param c      the client
 * @param order  the order byte
 * @return ::XF_SUPPORT_YES, ::XF_SUPPORT_NO, or ::XF_SUPPORT_UNKNOWN (no sub
 *   frame yet, a model or an order the list does not have, NULL @p c)
 */
xf_support xf_client_supports(const xf_client *c, uint8_t order);

/**
 * Status of command @p id; *result (may be NULL) gets its result once finished.
 * @param c       the client
 * @param id      the id xf_client_submit() gave
 * @param result  receives the result when the command has finished and is
 *   still among the last ::XF_CLIENT_RESULTS finished (may be NULL); left
 *   alone otherwise
 * @return ::XF_CMD_QUEUED, ::XF_CMD_SENDING or ::XF_CMD_OPERATING while it
 *   runs; its final status once finished; ::XF_CMD_UNKNOWN for id 0, a NULL
 *   @p c, an id never given, or a result already overwritten by newer ones
 */
xf_cmd_status xf_client_command_status(const xf_client *c, uint32_t id, xf_cmd_result *result);

/**
 * Commands queued or running.
 * @param c  the client
 * @return their number, 0..::XF_CLIENT_QUEUE; 0 for a NULL @p c
 */
size_t xf_client_pending(const xf_client *c);

/**
 * Drop every queued command (XF_CMD_CANCELLED); the one running is cancelled too.
 *
 * Each is reported to on_result from inside this call, and kept for
 * xf_client_command_status(). A running command may already have reached
 * the GCU and be executed all the same; the next packet is a null. The
 * external-track stream is not stopped (xf_client_external_track_stop()).
 * Commands that on_result submits meanwhile are not cancelled: they stay
 * queued. Never blocks; may be called from the client's callbacks (then
 * its on_result calls nest in the callback's). Does nothing for a NULL
 * @p c.
 * @param c  the client
 */
void xf_client_cancel_all(xf_client *c);

/**
 * External track is streamed, not run once: while on, every packet that
 * carries no other command carries order 0x1B with these offsets.
 * xf_client_external_track_stop() sends the exit (value 0) as a command.
 *
 * Starts the stream or updates its offsets (value 2: start / keep
 * tracking), checked as a command would be. The stream's replies are not
 * reported. Never blocks; may be called from the client's callbacks.
 * @param c        the client
 * @param cameras  camera mask (KK), not 0
 * @param dx       target offset from the screen centre, [-1024, 1024]
 * @param dy       target offset from the screen centre, [-1024, 1024];
 *   dx and dy both >= 3071 say the target is lost
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p c), ::XF_ERR_RANGE (a value out of
 *   range: refused, and a running stream keeps its previous offsets)
 */
xf_err xf_client_external_track(xf_client *c, uint8_t cameras, int16_t dx, int16_t dy);
/**
 * Stop the external-track stream and queue its exit (value 0, the stream's
 * cameras; camera 1 when no stream was on) as a command, whose result comes
 * like any command's. The exit starts only once the reply to a null sent
 * after the stream has come back, so that a late reply to the stream is
 * not taken for its own. Never blocks.
 *
 * On failure nothing changes: the stream (if on) keeps running and nothing
 * is queued, so calling again (once the queue has room) sends the same exit
 * to the same cameras.
 * @param c   the client
 * @param id  receives the exit command's id (may be NULL; left alone on
 *   failure)
 * @return as xf_client_submit(): ::XF_OK, ::XF_ERR_ARG (NULL @p c),
 *   ::XF_ERR_BUSY (queue full: nothing changed; call again)
 */
xf_err xf_client_external_track_stop(xf_client *c, uint32_t *id);

/* ---- state ------------------------------------------------------------------- */

/**
 * The gimbal's state as the GCU last reported it.
 * @param c  the client
 * @return the client's own telemetry (valid as long as the client, updated
 *   by each step: have_main and have_sub say what has arrived), or NULL for
 *   a NULL @p c
 */
const xf_telemetry *xf_client_telemetry(const xf_client *c);
/**
 * @p t in physical units (computed on read: the client keeps the wire's
 * integers).
 * @param t  the telemetry (xf_client_telemetry())
 * @param u  receives the quantities in physical units
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p t or @p u)
 */
xf_err xf_telemetry_convert(const xf_telemetry *t, xf_telemetry_units *u);
/**
 * The link's health.
 * @param c  the client
 * @return the client's own figures (valid as long as the client, updated by
 *   each step), or NULL for a NULL @p c
 */
const xf_health *xf_client_health(const xf_client *c);
/**
 * The receive parser's counters (frames, CRC and length errors, bytes skipped); NULL if @p c is NULL.
 * @param c  the client
 * @return the counters (valid as long as the client), or NULL
 */
const xf_parser_stats *xf_client_parser_stats(const xf_client *c);
/**
 * The link state as of the last step (the same as xf_health.link).
 * @param c  the client
 * @return the state; ::XF_LINK_DOWN for a NULL @p c
 */
xf_link_state xf_client_link(const xf_client *c);
/**
 * Name of a link state, for messages.
 * @param s  the state
 * @return "up", "stale" or "down" (any other value: "down"); static
 */
const char *xf_link_state_name(xf_link_state s);
/**
 * Name of a command status, for messages.
 * @param s  the status
 * @return "queued", "sending", "operating", "ok", "failed", "timeout",
 *   "link lost", "cancelled", "refused", or "unknown" (::XF_CMD_UNKNOWN and any other
 *   value); static
 */
const char *xf_cmd_status_name(xf_cmd_status s);

XF_END_DECLS

#endif /* XF_CLIENT_H */
