/**
 * @file
 * @brief A simulated GCU: the gimbal side of the protocol, for tests, demos
 * and development without hardware.
 *
 * Portable C over xf_hal like the client (no OS, no heap, no globals). It
 * answers only correct host packets, one reply each; keeps the once-rule
 * (an order runs once while it repeats, except external_track); reads each
 * command in the protocol version it speaks itself, whatever the host's
 * version byte; gives the feedback of every order, with configurable
 * failures and an "operating" phase for calibration; moves its attitude by
 * mode (rates integrate, angles slew at a finite speed, orthoview points
 * down, FPV follows the carrier; with ctrl_valid clear the desired angles
 * hold); reports relative angles from its own model of the motors, not from
 * the carrier data of the packet; zooms, ranges, tracks; replies in
 * protocol version 1 or 2; and injects faults (drop, corrupt, delay,
 * jitter, duplicates) on request.
 *
 * Where the vendor's V2.0.6 leaves a GCU's behaviour open (a parameter of
 * the wrong length, a record parameter other than 0x01, ...), it takes the
 * strict reading, answers failure, and says so through xf_sim_config.on_note
 * (docs/protocol.md, "Open questions for a real gimbal").
 *
 * Part of the xfgcu::client library (it needs libm, so not in builds
 * without a C library). No function waits: xf_sim_step() takes as long as
 * the link's read and write. A simulator is not thread-safe; drive it from
 * one thread (xf_posix_poll() steps clients and simulators together).
 */
#ifndef XF_SIM_H
#define XF_SIM_H

#include <stddef.h>
#include <stdint.h>
#include "xf_command.h"
#include "xf_config.h"
#include "xf_error.h"
#include "xf_hal.h"
#include "xf_packet.h"
#include "xf_parser.h"

XF_BEGIN_DECLS

#ifndef XF_SIM_DELAY_QUEUE
#define XF_SIM_DELAY_QUEUE 128 /**< packets held back by the delay, jitter and duplicate faults */
#endif

/**
 * The questions V2.0.6 leaves open that a host packet raised, and on which
 * the simulator took the strict reading (xf_sim_note.question).
 */
typedef enum xf_sim_question {
    XF_SIM_Q_LENGTH = 1, /**< parameter bytes not the order's length: failed, not read as its first bytes */
    XF_SIM_Q_RANGE = 2,  /**< a parameter outside the range of the version the simulator speaks: failed */
    XF_SIM_Q_RECORD = 3, /**< record with a parameter other than 0x01 (the vendor's toggle): failed */
    XF_SIM_Q_CAMERA = 4, /**< an order only camera 2 takes, with another camera mask than 0x02: failed */
    XF_SIM_Q_ORDER = 5,  /**< an order the protocol does not define: failed */
    XF_SIM_Q_NEWER = 6   /**< an order V0.2 added, to a simulator that speaks V0.1 (which does not know it): failed */
} xf_sim_question;

/** What the simulator tells xf_sim_config.on_note: a packet it read strictly. */
typedef struct xf_sim_note {
    xf_sim_question question; /**< which open question */
    uint8_t order;            /**< the order of the host packet */
    uint8_t state;            /**< the execution state it answered */
    uint8_t params_len;       /**< the packet's parameter bytes */
    uint8_t param0;           /**< the first of them (0 when there is none) */
    const char *text;         /**< xf_sim_question_text(question): one line, static */
} xf_sim_note;

/**
 * Called when the simulator answers a packet by the strict reading of an
 * open question, from inside xf_sim_step() or xf_sim_process(). It must not
 * call back into the simulator.
 * @param user  xf_sim_config.user
 * @param note  what happened, valid during the call only
 */
typedef void (*xf_sim_note_fn)(void *user, const xf_sim_note *note);

/** A simulator's configuration; start from xf_sim_config_init(). */
typedef struct xf_sim_config {
    uint8_t version;     /**< version byte of replies: 1 or 2; default 1 */
    uint8_t gimbal_code; /**< model code reported; default 58 (Z-9B_V4(T), which has every order); an order the
                            model does not support (xf_gimbal_supports()) fails */
    /** @var xf_sim_config::hw_version
     *  hardware version reported, in tenths as the vendor's tools show it: default 31 (3.1) */
    uint8_t hw_version, fw_version; /**< firmware version reported, in tenths: default 50 (5.0) */
    float slew_dps;                 /**< angle-control slew speed, default 120 deg/s */
    float max_rate_dps;             /**< rate clamp, default 180 deg/s */
    float zoom_max;                 /**< camera 1 optical zoom, default 30x */
    float zoom_speed;               /**< continuous zoom, x per second, default 6 */
    uint32_t calibration_ms;        /**< "operating" phase, default 1500 */
    uint16_t feedback_after;        /**< the state comes in the Nth reply after execution (0 = at once) */
    /** 1: only the first reply after an execution carries its state, the replies to the order's repeats are
     *  72 bytes (one reading of V2.0.6's flowchart); 0 (default): every reply to a repeat carries it */
    uint8_t state_once;
    uint8_t main_camera; /**< the camera on its main screen, whose zoom scales the control rates and the field of
                            view: 1 (default) or 2 (any other value: 1); xf_sim_set_main_camera() changes it */
    /** answer only host packets whose version byte is this (1 or 2), and ignore the others as if they had not
     *  come, as some GCU-side peers do; 0 (default): answer every version */
    uint8_t answer_only;
    uint32_t seed;          /**< PRNG for random faults, default 1 */
    xf_sim_note_fn on_note; /**< told of each packet answered by a strict reading (xf_sim_note); NULL: none */
    void *user;             /**< passed to on_note */
} xf_sim_config;

/** Faults to inject; set fields of xf_sim.fault at any time. */
typedef struct xf_sim_faults {
    uint16_t drop_next;        /**< drop the next N replies */
    uint16_t drop_permille;    /**< drop this many replies per thousand, at random */
    uint16_t corrupt_next;     /**< flip a byte in the next N replies */
    uint16_t corrupt_permille; /**< flip a byte in this many replies per thousand, at random */
    /** hold each reply this long, < 2^31 with jitter_ms; at most XF_SIM_DELAY_QUEUE packets are held at once (a
     *  delay over about 2.5 s at 50 Hz fills it), and more replies are dropped and counted */
    uint32_t delay_ms;
    /** hold each reply, and each host packet before it is read, a random 0..jitter_ms more (each its
     *  own draw), so that packets overtake one another in both directions as on a network that
     *  reorders; host packets so held are executed in the order they come out */
    uint16_t jitter_ms;
    uint16_t dup_permille; /**< this many packets per thousand, in each direction, arrive twice (the copy has its
                                own jitter) */
    uint8_t silent;        /**< answer nothing (replies are not even counted as dropped) */
} xf_sim_faults;

/** What the simulator has seen and done. */
typedef struct xf_sim_stats {
    uint32_t packets_in; /**< correct host packets */
    uint32_t replies;    /**< replies written */
    /** @var xf_sim_stats::dropped
     *  replies dropped (faults, or a full delay queue) */
    uint32_t dropped, corrupted; /**< replies with a byte flipped */
    uint32_t executed[256];      /**< executions per order (the once-rule counts here) */
    /** @var xf_sim_stats::photos
     *  shutter executions */
    uint32_t photos, recordings; /**< recordings started */
    uint32_t ins_valid_packets;  /**< host packets with ins_valid set */
    uint32_t write_errors;       /**< replies the link (or xf_sim_process()'s buffer) did not take */
    uint32_t ignored;            /**< correct host packets of another version than answer_only, not answered */
    uint32_t strict;             /**< executions answered by a strict reading (xf_sim_note) */
} xf_sim_stats;

/** A packet held back by the delay, jitter or duplicate faults (a member of xf_sim). */
typedef struct xf_sim_delayed {
    uint32_t due_ms;                  /**< when it goes out (a reply) or is read (a host packet) */
    uint8_t len;                      /**< its length */
    uint8_t to_gcu;                   /**< 1: a host packet on its way in; 0: a reply */
    uint8_t bytes[XF_PACKET_MAX_LEN]; /**< the packet (any length the parser takes) */
} xf_sim_delayed;

/** Simulator state; members are readable (tests use them), change them only through functions and `fault`. */
typedef struct xf_sim {
    xf_sim_config cfg;   /**< the configuration (a copy) */
    xf_sim_faults fault; /**< faults to inject: set its members at any time */
    xf_sim_stats stats;  /**< what it has seen and done */
    xf_hal hal;          /**< the link (a copy), when attached */
    uint8_t attached;    /**< a link is attached */
    xf_parser parser;    /**< parser of the host's packets */
    /** @var xf_sim::now_ms
     *  the time of the current step */
    uint32_t now_ms, last_step_ms; /**< the time of the previous step that moved the gimbal */
    uint8_t started;               /**< the first step has run */
    uint32_t rng;                  /**< state of the fault PRNG */
    /* the last host packet */
    xf_host_packet host;     /**< the last correct host packet */
    uint8_t have_host;       /**< host holds a packet */
    uint8_t last_order;      /**< order of the previous host packet, for the once-rule */
    uint8_t have_last_order; /**< last_order is set */
    /* feedback of the last executed order */
    /** @var xf_sim::fb_order
     *  the last executed order */
    /** @var xf_sim::fb_state
     *  its execution state */
    /** @var xf_sim::fb_pending_replies
     *  replies still to go before the state is sent (feedback_after) */
    uint8_t fb_order, fb_state, fb_pending_replies, fb_sent; /**< the state has been sent once */
    uint8_t fb_valid;                                        /**< fb_order and fb_state are set */
    uint8_t calibrating;                                     /**< calibration is in its "operating" phase */
    uint32_t calibration_end_ms;                             /**< when calibration ends */
    uint8_t fail_state[256]; /**< configured failure state per order; 0 = succeed (xf_sim_set_failure()) */
    /* gimbal state */
    xf_mode mode;        /**< gimbal mode */
    uint16_t pod_status; /**< `XF_POD_*` bits */
    /** @var xf_sim::roll
     *  camera's absolute roll, deg */
    /** @var xf_sim::pitch
     *  camera's absolute pitch, deg */
    float roll, pitch, yaw; /**< camera's absolute yaw, deg */
    float rate[3];          /**< angular velocities of the last step, deg/s: roll, pitch, yaw */
    float hold_yaw_offset;  /**< head follow: yaw relative to the carrier */
    /** @var xf_sim::gaze_lat
     *  gaze_geo target latitude, deg (0 with gaze_lon 0: gaze lock) */
    /** @var xf_sim::gaze_lon
     *  gaze_geo target longitude, deg */
    float gaze_lat, gaze_lon, gaze_alt; /**< gaze_geo target altitude, m */
    /** @var xf_sim::zoom1
     *  camera 1's zoom, x */
    /** @var xf_sim::zoom2
     *  camera 2's zoom, x */
    float zoom1, zoom2, zoom_dir; /**< camera 1's continuous zoom: +1 in, -1 out, 0 still */
    float zoom_dir2;              /**< camera 2's continuous zoom, as zoom_dir */
    float zoom_target;            /**< camera 1's zoom_to target, x; 0 = none */
    float zoom_target2;           /**< camera 2's zoom_to target, x; 0 = none */
    float distance_m;             /**< laser range, m */
    /** @var xf_sim::track_x
     *  target offset x, as target_offset_x */
    int16_t track_x, track_y; /**< target offset y, as target_offset_y */
    uint8_t thermal_status;   /**< V0.2 `XF_THERMAL_*` bits */
    uint16_t camera_status;   /**< V0.2 `XF_CAMERA_*` bits */
    int8_t time_zone;         /**< V0.2 time zone, hours */
    uint8_t lighting;         /**< fill light intensity */
    uint8_t ortho_follow;     /**< orthoview entered from head follow: yaw follows the carrier */
    float tgt[3];             /**< click-to-aim / neutral target: roll, pitch, yaw */
    uint8_t have_tgt;         /**< slewing to tgt */
    uint8_t main_camera;      /**< the camera on the main screen: 1 or 2 */
    /** the desired angles of an angle mode (angle control, Euler, FPV), deg, in that mode's frame: set from
     *  valid control quantities, kept while they are invalid (V2.0.6), the attitude held when the mode began */
    float want[3];
    float carrier[3]; /**< the carrier's roll, pitch, yaw, deg, from the last packet with valid INS data (0 before) */
    xf_sim_delayed delayed[XF_SIM_DELAY_QUEUE]; /**< packets held back, in the order they are due */
    uint16_t n_delayed;                         /**< packets in delayed */
    uint16_t n_held_in;                         /**< of which host packets on their way in */
    /* xf_sim_process: replies go to this buffer instead of the link */
    uint8_t *cap_buf; /**< xf_sim_process()'s output, NULL otherwise */
    /** @var xf_sim::cap_cap
     *  its capacity */
    size_t cap_cap, cap_len; /**< bytes written to it */
} xf_sim;

/**
 * Fill @p cfg with the defaults documented at each member of xf_sim_config.
 * Does nothing for a NULL @p cfg.
 * @param cfg  the configuration to fill
 */
void xf_sim_config_init(xf_sim_config *cfg);

/**
 * Start a simulator (a macro over xf_sim_init_checked(), which checks that
 * the caller and the library were built with the same options).
 * @param s    the simulator to set up (caller's storage)
 * @param cfg  its configuration; NULL means defaults
 * @return ::XF_OK, ::XF_ERR_ARG (@p s NULL), ::XF_ERR_RANGE (a version other
 *   than 1 or 2, an answer_only other than 0, 1 or 2), ::XF_ERR_CONFIG (built
 *   with other options).
 */
#define xf_sim_init(s, cfg) xf_sim_init_checked((s), (cfg), XF_OPTIONS_CHECK, sizeof(xf_sim))

/**
 * What xf_sim_init() calls, with the caller's build options: use the macro.
 * @param s        as for xf_sim_init()
 * @param cfg      as for xf_sim_init()
 * @param options  the caller's ::XF_OPTIONS_WORD
 * @param size     the caller's sizeof(xf_sim)
 * @return what xf_sim_init() returns, or ::XF_ERR_CONFIG when @p options or
 *   @p size differ from the library's (nothing is written to @p s).
 */
xf_err xf_sim_init_checked(xf_sim *s, const xf_sim_config *cfg, unsigned long options, size_t size);

/**
 * Give it the link it talks on (NULL detaches: it then neither reads nor replies).
 * @param s    the simulator
 * @param hal  the link (copied), or NULL
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p s, or a link without the required functions)
 */
xf_err xf_sim_attach(xf_sim *s, const xf_hal *hal);

/**
 * Read what the host sent, answer every correct packet, move the gimbal,
 * release delayed replies. Call it often (every few ms). Returns XF_OK or
 * the transport's error (XF_ERR_CLOSED while no host is connected).
 *
 * Reads the link up to 16 times. Replies the link does not take are counted
 * in xf_sim_stats.write_errors, not returned. Never waits itself, but takes
 * as long as the link's read and write.
 *
 * Cost: O(bytes read) through the parser and one reply packed and written per host packet;
 * under the delay, jitter and duplicate faults also O(::XF_SIM_DELAY_QUEUE) per packet held or
 * released. Stack: a 512-byte read buffer and one reply. Never allocates.
 * @param s       the simulator
 * @param now_ms  the time, ms, on a wrapping clock (the gimbal moves by the
 *   time since the previous step, at most 200 ms at once)
 * @return ::XF_OK (also when detached), ::XF_ERR_ARG (NULL @p s), or the
 *   link's read error (::XF_ERR_CLOSED, ::XF_ERR_IO, the latter also for a
 *   read that says it copied more than asked, none of which is read); delayed
 *   replies are then not released in this step
 */
xf_err xf_sim_step(xf_sim *s, uint32_t now_ms);

/**
 * Offline use (no link): take @p len bytes of host stream and write the
 * replies, back to back, into @p out (capacity @p cap); *out_len set.
 * The delay fault does not apply; drop, corrupt and silent do.
 *
 * Replies that do not fit are dropped and counted in
 * xf_sim_stats.write_errors. Never blocks.
 * @param s        the simulator
 * @param in       host bytes; may be NULL when @p len is 0
 * @param len      number of bytes at @p in
 * @param now_ms   the time, ms
 * @param out      where the replies go; may be NULL when @p cap is 0
 * @param cap      capacity of @p out
 * @param out_len  receives the number of reply bytes written (may be NULL)
 * @return ::XF_OK, ::XF_ERR_ARG (NULL @p s, or NULL @p in / @p out with a
 *   non-zero length), ::XF_ERR_NO_SPACE (input given, no reply written, and
 *   xf_sim_stats.write_errors not 0: a count that also includes earlier calls)
 */
xf_err xf_sim_process(xf_sim *s, const uint8_t *in, size_t len, uint32_t now_ms, uint8_t *out, size_t cap,
                      size_t *out_len);

/**
 * Make executions of @p order answer @p state (0x01, or a failed-camera mask) as given; 0 restores
 * success. (Without it, a failure answers what V2.0.6 gives the order: 0x01, the mask of the cameras
 * asked for an NN order, 0x02 for the orders only camera 2 takes.)
 * Does nothing for a NULL @p s.
 * @param s      the simulator
 * @param order  the order byte
 * @param state  the state byte to answer (0 = succeed and execute)
 */
void xf_sim_set_failure(xf_sim *s, uint8_t order, uint8_t state);

/**
 * Which camera is on the simulator's main screen: its zoom divides the
 * control rates (V2.0.6: 0.1 deg/s divided by the main screen's zoom) and
 * sets the field of view of click-to-aim and tracking. Does nothing for a
 * NULL @p s.
 * @param s       the simulator
 * @param camera  1 or 2 (any other value: 1)
 */
void xf_sim_set_main_camera(xf_sim *s, uint8_t camera);

/**
 * One line that says what the simulator did with an open question, for a log.
 * @param q  the question
 * @return a static string; "" for a value that is no question
 */
const char *xf_sim_question_text(xf_sim_question q);

/**
 * The current gimbal state as the next reply would carry it (order and
 * feedback excepted: null order, no feedback bytes). Does nothing when
 * @p s or @p pkt is NULL.
 * @param s    the simulator
 * @param pkt  receives the packet
 */
void xf_sim_snapshot(const xf_sim *s, xf_gcu_packet *pkt);

XF_END_DECLS

#endif /* XF_SIM_H */
