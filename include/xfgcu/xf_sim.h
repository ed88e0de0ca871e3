/*
 * xf_sim.h - a simulated GCU: the gimbal side of the protocol, for tests,
 * demos and development without hardware.
 *
 * Portable C over xf_hal like the client (no OS, no heap, no globals). It
 * answers only correct host packets, one reply each; keeps the once-rule
 * (an order runs once while it repeats, except external_track); gives the
 * feedback of every order, with configurable failures and an "operating"
 * phase for calibration; moves its attitude by mode (rates integrate,
 * angles slew at a finite speed, orthoview points down, FPV follows the
 * carrier); zooms, ranges, tracks; replies in protocol version 1 or 2;
 * and injects faults (drop, corrupt, delay) on request.
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
#define XF_SIM_DELAY_QUEUE 16 /**< replies held back by the delay fault */
#endif

typedef struct xf_sim_config {
    uint8_t version;                /**< version byte of replies: 1 or 2; default 1 */
    uint8_t gimbal_code;            /**< default 40 (D-80AI) */
    uint8_t hw_version, fw_version; /**< default 3, 12 */
    float slew_dps;                 /**< angle-control slew speed, default 120 deg/s */
    float max_rate_dps;             /**< rate clamp, default 180 deg/s */
    float zoom_max;                 /**< camera 1 optical zoom, default 30x */
    float zoom_speed;               /**< continuous zoom, x per second, default 6 */
    uint32_t calibration_ms;        /**< "operating" phase, default 1500 */
    uint16_t feedback_after;        /**< the state comes in the Nth reply after execution (0 = at once) */
    uint8_t state_once;             /**< 1: only one reply carries the state (default: every repeat does) */
    uint32_t seed;                  /**< PRNG for random faults, default 1 */
} xf_sim_config;

/** Faults to inject; set fields of xf_sim.fault at any time. */
typedef struct xf_sim_faults {
    uint16_t drop_next;     /**< drop the next N replies */
    uint16_t drop_permille; /**< drop this share of replies at random */
    uint16_t corrupt_next;  /**< flip a byte in the next N replies */
    uint16_t corrupt_permille;
    uint32_t delay_ms; /**< hold each reply this long (bounded by XF_SIM_DELAY_QUEUE) */
    uint8_t silent;    /**< answer nothing */
} xf_sim_faults;

/** What the simulator has seen and done. */
typedef struct xf_sim_stats {
    uint32_t packets_in; /**< correct host packets */
    uint32_t replies;    /**< replies written */
    uint32_t dropped, corrupted;
    uint32_t executed[256]; /**< executions per order (the once-rule counts here) */
    uint32_t photos, recordings;
    uint32_t ins_valid_packets; /**< host packets with ins_valid set */
    uint32_t write_errors;
} xf_sim_stats;

typedef struct xf_sim_delayed {
    uint32_t due_ms;
    uint8_t len;
    uint8_t bytes[XF_PACKET_MIN_LEN + 1u];
} xf_sim_delayed;

/** Simulator state; members are readable (tests use them), change them only through functions and `fault`. */
typedef struct xf_sim {
    xf_sim_config cfg;
    xf_sim_faults fault;
    xf_sim_stats stats;
    xf_hal hal;
    uint8_t attached;
    xf_parser parser;
    uint32_t now_ms, last_step_ms;
    uint8_t started;
    uint32_t rng;
    /* the last host packet */
    xf_host_packet host;
    uint8_t have_host;
    uint8_t last_order; /* order of the previous host packet, for the once-rule */
    uint8_t have_last_order;
    /* feedback of the last executed order */
    uint8_t fb_order, fb_state, fb_pending_replies, fb_sent;
    uint8_t fb_valid;
    uint8_t calibrating;
    uint32_t calibration_end_ms;
    uint8_t fail_state[256]; /* configured failure state per order; 0 = succeed */
    /* gimbal state */
    uint8_t mode;
    uint16_t pod_status;
    float roll, pitch, yaw;             /* camera absolute, deg */
    float rate[3];                      /* deg/s, last step */
    float hold_yaw_offset;              /* head follow: yaw relative to the carrier */
    float gaze_lat, gaze_lon, gaze_alt; /* gaze_geo target */
    float zoom1, zoom2, zoom_dir;       /* x; zoom_dir: +1 in, -1 out, 0 still */
    float zoom_target;                  /* zoom_to, 0 = none */
    float distance_m;
    int16_t track_x, track_y; /* target offsets */
    uint8_t thermal_status;
    uint16_t camera_status;
    int8_t time_zone;
    uint8_t lighting;
    uint8_t neutral; /* slewing back to neutral */
    float tgt[3];    /* click-to-aim / neutral target: roll, pitch, yaw */
    uint8_t have_tgt;
    xf_sim_delayed delayed[XF_SIM_DELAY_QUEUE];
    uint8_t n_delayed;
    /* xf_sim_process: replies go to this buffer instead of the link */
    uint8_t *cap_buf;
    size_t cap_cap, cap_len;
} xf_sim;

void xf_sim_config_init(xf_sim_config *cfg);

/** Start a simulator; @p cfg NULL means defaults. XF_ERR_RANGE for a version other than 1 or 2. */
xf_err xf_sim_init(xf_sim *s, const xf_sim_config *cfg);

/** Give it the link it talks on (NULL detaches: it then neither reads nor replies). */
xf_err xf_sim_attach(xf_sim *s, const xf_hal *hal);

/**
 * Read what the host sent, answer every correct packet, move the gimbal,
 * release delayed replies. Call it often (every few ms). Returns XF_OK or
 * the transport's error (XF_ERR_CLOSED while no host is connected).
 */
xf_err xf_sim_step(xf_sim *s, uint32_t now_ms);

/**
 * Offline use (no link): take @p len bytes of host stream and write the
 * replies, back to back, into @p out (capacity @p cap); *out_len set.
 * Faults other than drop/corrupt do not apply.
 */
xf_err xf_sim_process(xf_sim *s, const uint8_t *in, size_t len, uint32_t now_ms, uint8_t *out, size_t cap,
                      size_t *out_len);

/** Make executions of @p order answer @p state (0x01, or a failed-camera mask); 0 restores success. */
void xf_sim_set_failure(xf_sim *s, uint8_t order, uint8_t state);

/** The current gimbal state as the next reply would carry it. */
void xf_sim_snapshot(const xf_sim *s, xf_gcu_packet *pkt);

XF_END_DECLS

#endif /* XF_SIM_H */
