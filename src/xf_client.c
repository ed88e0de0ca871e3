/*
 * xf_client.c - the host side of the GCU protocol over xf_hal.
 * Portable: no OS, no heap, no globals. See xf_client.h for the contract.
 */
#include "xfgcu/xf_client.h"
#include "xfgcu/xf_mem.h"
#include "xfgcu/xf_units.h"

#define XF__CTRL_NONE     0u
#define XF__CTRL_RATES    1u
#define XF__CTRL_ANGLES   2u
#define XF__CTRL_DROPPED  3u /* none, because the last one was dropped (XF_CTRL_DROPPED) */
#define XF_READS_PER_STEP 16 /* bound the work of one step on a flooded link */
#define XF__STEADY        25 /* packet periods in a row with one reply each: a link that keeps order */
#define XF__PROMPT        6  /* ... or from the first packet on, each reply before the next, at one phase */
/* xf_cmd_slot.fits: the versions in which the parameters are valid and mean the same */
#define XF__FITS_V1  0x01u /* V0.1 (a version byte of 0 or 1) */
#define XF__FITS_V2  0x02u /* V0.2 (2 and up) */
#define XF__FITS_OSD 0x04u /* xf_client_osd()'s: params[0] is show, set for the GCU's version when it starts */

/* The defaults, in flash: no callbacks, and the times of xf_client_config's comments. */
static const xf_client_config xf__defaults = {
    .command_timeout_ms = 1000,
    .operating_timeout_ms = 60000,
    .rate_hz = 50,
    .carrier_max_age_ms = 200,
    .gnss_max_age_ms = 2000,
    .stale_ms = 250,
    .down_ms = 1000,
    .rate_watchdog_ms = 500,
    .protocol_version = XF_PROTOCOL_V1,
    .reorder_ms = 0,
};

void xf_client_config_init(xf_client_config *cfg)
{
    if (cfg != NULL) {
        *cfg = xf__defaults;
    }
}

size_t xf_client_size(void) { return sizeof(xf_client); }

xf_err xf_client_config_timing(const xf_client_config *cfg, xf_client_timing *t)
{
    uint32_t period;
    if (cfg == NULL || t == NULL || cfg->rate_hz == 0u || cfg->rate_hz > 200u) {
        return XF_ERR_ARG;
    }
    period = (1000u + cfg->rate_hz / 2u) / cfg->rate_hz;
    t->period_ms = period;
    /* A reply comes once a packet, and with reorder_ms the client is silent up to twice that
     * around a command. */
    t->gap_ms = period + 2u * cfg->reorder_ms;
    /* The command goes out at the next slot and its reply comes back before the one after. */
    t->round_trip_ms = 2u * period + 2u * cfg->reorder_ms;
    return XF_OK;
}

/* The rule of xf_client_config_problem(), without its text (a firmware that only starts a client
 * carries no strings): 0 when @p cfg can work, else the number of the line it breaks. *t gets the
 * times @p cfg implies. */
static int xf__config_fault(const xf_client_config *cfg, xf_client_timing *t)
{
    if (xf_client_config_timing(cfg, t) != XF_OK) {
        return 1;
    }
    if (cfg->protocol_version == 0u || cfg->operating_timeout_ms == 0u || cfg->reorder_ms > 1000u ||
        cfg->version_auto > 1u) {
        return 2;
    }
    /* A link that reads stale (or down) between two good replies cannot work. */
    if (cfg->stale_ms <= t->gap_ms || cfg->down_ms <= cfg->stale_ms) {
        return 3;
    }
    return (cfg->command_timeout_ms < t->round_trip_ms) ? 4 : 0;
}

/* The lines of xf__config_fault(), 1 first. */
static const char xf__config_lines[] =
    "rate_hz: 1..200\0"
    "protocol_version, operating_timeout_ms: >= 1; reorder_ms: <= 1000; version_auto: 0 or 1\0"
    "stale_ms: > 1000 / rate_hz + 2 reorder_ms (stale between packets); down_ms: > stale_ms\0"
    "command_timeout_ms: >= 2000 / rate_hz + 2 reorder_ms (a round trip)";

const char *xf_client_config_problem(const xf_client_config *cfg)
{
    xf_client_timing t;
    int fault = (cfg == NULL) ? 0 : xf__config_fault(cfg, &t); /* NULL: the defaults */
    return (fault == 0) ? NULL : xf__nth_name(xf__config_lines, (size_t)fault - 1u);
}

static void xf__set_bound(xf_client *c);

/* The largest reorder bound @p cfg's times allow (xf_client_config_problem(): stale_ms above a
 * period plus twice the bound, command_timeout_ms at least two periods plus twice it), at most
 * 1000 ms: the bound the client uses on a link that has not shown it keeps order. */
static uint16_t xf__auto_reorder_ms(const xf_client_config *cfg, uint32_t period)
{
    uint32_t by_stale = (cfg->stale_ms > period + 1u) ? (cfg->stale_ms - period - 1u) / 2u : 0u;
    uint32_t by_timeout = (cfg->command_timeout_ms > 2u * period) ? (cfg->command_timeout_ms - 2u * period) / 2u : 0u;
    uint32_t b = (by_stale < by_timeout) ? by_stale : by_timeout;
    return (uint16_t)((b < 1000u) ? b : 1000u);
}

xf_err xf_client_init_checked(xf_client *c, const xf_hal *hal, const xf_client_config *cfg, unsigned long options,
                              size_t size)
{
    xf_client_timing t;
    if (options != XF_OPTIONS_WORD || size != sizeof(xf_client)) {
        return XF_ERR_CONFIG; /* the caller's xf_client is not ours: writing to it would overrun it */
    }
    if (c == NULL || xf_hal_check(hal) != XF_OK) {
        return XF_ERR_ARG;
    }
    if (cfg == NULL) {
        cfg = &xf__defaults;
    }
    if (xf__config_fault(cfg, &t) != 0) {
        return XF_ERR_RANGE; /* a link that is never up, or commands that time out before they are sent */
    }
    XF_MEMSET(c, 0, sizeof(*c));
    c->cfg = *cfg;
    c->hal = *hal;
    xf_parser_init(&c->parser, XF_DIR_GCU);
    c->period_ms = (uint16_t)t.period_ms;
    c->next_id = 1;
    c->health.version_sent = cfg->protocol_version;
    xf__set_bound(c);
    return (cfg->rate_hz < 30u || cfg->rate_hz > 50u) ? XF_WARN_RATE : XF_OK;
}

/* ---- results ------------------------------------------------------------------ */

/* The id of queue position @p i (0: the head). Ids are handed out in
 * submission order and commands leave the queue from its head only, so the
 * queued ones hold the q_count ids before next_id, 0 skipped on the wrap. */
static uint32_t xf__queued_id(const xf_client *c, size_t i)
{
    uint32_t back = (uint32_t)(c->q_count - i);
    XF_ASSERT(i < c->q_count);
    return (back < c->next_id) ? c->next_id - back : c->next_id - back - 1u;
}

/* The other way: how many ids before next_id command @p id was handed out (1: the last one; 0: not
 * yet). The queue holds the last q_count; the results before them, newest first: commands finish
 * from the queue's head only, so in the order of their ids, and each once. */
static uint32_t xf__ids_back(const xf_client *c, uint32_t id)
{
    return (id < c->next_id) ? c->next_id - id : c->next_id - id - 1u;
}

static void xf__publish(xf_client *c, const xf_cmd_result *r)
{
    if (r->status != XF_CMD_OPERATING) {
        xf_cmd_record *k;
        XF_ASSERT(c->r_next < XF_CLIENT_RESULTS);
        k = &c->results[c->r_next]; /* kept in 12 bytes (xf_cmd_record) */
        k->order = r->order;
        k->status = (uint8_t)r->status;
        k->state = r->state;
        k->failed_cameras = r->failed_cameras;
        k->packets = r->packets;
        k->elapsed_ms = r->elapsed_ms;
        c->r_next = (uint8_t)((c->r_next + 1u) % XF_CLIENT_RESULTS);
    }
    if (c->cfg.on_result != NULL) {
        c->cfg.on_result(c->cfg.user, r);
    }
}

/* The result of the queue's head, with what the GCU's reply @p fb said (NULL: no reply). */
static void xf__result_of(const xf_client *c, xf_cmd_status st, const xf_feedback *fb, xf_cmd_result *r)
{
    XF_MEMSET(r, 0, sizeof(*r));
    r->id = xf__queued_id(c, 0);
    r->order = c->queue[c->q_head].order;
    r->status = st;
    r->elapsed_ms = xf_ms_since(c->now_ms, c->head_ms); /* since first sent; never sent: how long it waited */
    if (c->active) {
        r->packets = c->packets;
    }
    if (fb != NULL) {
        r->state = fb->state;
        r->failed_cameras = fb->failed_cameras;
    }
}

/* Replies of @p order may still be in flight: no command of that order starts until a null's
 * reply has come after them (@p wait: none of them has come yet, so one must come first). A
 * guard still open for another order keeps its hold too: then every order waits. */
static void xf__guard(xf_client *c, uint8_t order, int wait)
{
    c->guard_multi = (uint8_t)(c->guard_multi || (c->guard_open && (c->guard_order != order || c->guard_wait)));
    c->guard_order = order;
    c->guard_open = 1;
    c->guard_wait = (uint8_t)wait;
    c->guard_ms = c->now_ms;
}

/* End the running command (or the queue's head) with @p st. */
static void xf__finish(xf_client *c, xf_cmd_status st, const xf_feedback *fb)
{
    xf_cmd_result r;
    XF_ASSERT(c->q_count > 0u && c->q_head < XF_CLIENT_QUEUE); /* there is a head to end */
    xf__result_of(c, st, fb, &r);
    if (c->active) {
        c->nulls_owed = 1; /* back to null packets: the next command of any order is separated */
        /* Replies of this order may still be in flight, unless every packet that carried it has
         * had its reply (a link that keeps order and does not duplicate: reorder_ms 0). A null's
         * reply closes the guard only once one of this order has come, if none had: before
         * that, it answers a null sent before the command (the link is slower than the command
         * was long). */
        if (c->answered < c->packets || c->health.reorder_ms > 0u) {
            xf__guard(c, r.order, c->answered == 0u);
        }
    }
    c->active = 0;
    c->operating = 0;
    c->q_head = (uint8_t)((c->q_head + 1u) % XF_CLIENT_QUEUE);
    c->q_count--;
    c->head_ms = c->now_ms; /* the next command waits from now */
    xf__publish(c, &r);
}

/* Finish every command queued when the sweep starts, and only those: one
 * that on_result submits meanwhile survives it (else a callback that always
 * resubmits would never let it end). Ids go out in submission order and
 * commands leave from the head, so the newer ones are the queue's last
 * `added` (fewer once a nested sweep has taken every older one); 0 is
 * skipped on the wrap. */
static void xf__fail_all(xf_client *c, xf_cmd_status st)
{
    uint32_t first_new = c->next_id;
    for (;;) {
        uint32_t added = c->next_id - first_new - ((c->next_id < first_new) ? 1u : 0u);
        if (c->q_count <= added) {
            break;
        }
        xf__finish(c, st, NULL);
    }
}

/* ---- link health ---------------------------------------------------------------- */

static xf_link_state xf__link_now(const xf_client *c)
{
    uint32_t age;
    if (c->health.transport_closed || c->health.replies == 0u) {
        return XF_LINK_DOWN;
    }
    age = xf_ms_since(c->now_ms, c->health.last_rx_ms);
    if (age >= c->cfg.down_ms) {
        return XF_LINK_DOWN;
    }
    return (age >= c->cfg.stale_ms) ? XF_LINK_STALE : XF_LINK_UP;
}

static void xf__update_link(xf_client *c)
{
    xf_link_state s = xf__link_now(c);
    if (s == c->health.link) {
        return;
    }
    c->health.link = s;
    if (s == XF_LINK_DOWN) {
        xf__fail_all(c, XF_CMD_LINK_LOST); /* fail fast: never run a stale command later */
        if (c->cfg.version_auto) {
            c->health.version_answered = 0; /* a GCU may come back another: look again, from this version */
            c->version_ms = c->now_ms;
        }
    }
    if (c->cfg.on_link != NULL) {
        c->cfg.on_link(c->cfg.user, s);
    }
}

static void xf__update_window(xf_client *c)
{
    if (xf_ms_since(c->now_ms, c->window_start_ms) < 1000u) {
        return;
    }
    c->health.reply_rate_hz = c->window_replies;
    {
        /* Question and answer: at most one reply is in flight across a window's edge, so
         * count the one awaited at the start and not the one awaited at the end. */
        int32_t missing =
            (int32_t)c->window_sent - (int32_t)c->window_replies - (int32_t)c->awaiting + (int32_t)c->window_awaiting;
        c->health.replies_missing = (missing > 0) ? (uint32_t)missing : 0u;
        c->window_awaiting = c->awaiting;
    }
    c->window_start_ms = c->now_ms;
    c->window_sent = 0;
    c->window_replies = 0;
}

/* ---- receiving ---------------------------------------------------------------- */

/*
 * Telemetry is read straight from the frame's bytes (a frame out of the
 * parser is whole, of the GCU, its CRC checked): one row per field, wire
 * offset to member, at the offsets of the GCU frames (docs/protocol.md
 * section 4, as in xf_frame_gcu; a test checks the two agree). On an MCU
 * this is 0.3 KB less code than decoding a whole xf_gcu_packet (and 88
 * bytes less stack) and then copying its fields.
 */
typedef struct xf__tele_field {
    uint8_t wire;   /* byte offset in the packet */
    uint8_t size;   /* 1, 2 or 4 bytes, little-endian; the member's size */
    uint8_t member; /* offsetof(xf_telemetry, ...) */
} xf__tele_field;

#define XF__TF(wire, m)                                                                                                \
    {                                                                                                                  \
        (wire), (uint8_t)sizeof(((xf_telemetry *)0)->m), (uint8_t)offsetof(xf_telemetry, m)                            \
    }

static const xf__tele_field xf__tele_fields[] = {
    /* main frame, in every reply */
    XF__TF(XF_OFF_VERSION, version), XF__TF(XF_OFF_GCU_GIMBAL_MODE, gimbal_mode),
    XF__TF(XF_OFF_GCU_POD_STATUS, pod_status), XF__TF(XF_OFF_GCU_TARGET_OFFSET_X, target_offset_x),
    XF__TF(XF_OFF_GCU_TARGET_OFFSET_Y, target_offset_y), XF__TF(XF_OFF_GCU_REL_ANGLE_X, rel_angle_x),
    XF__TF(XF_OFF_GCU_REL_ANGLE_Y, rel_angle_y), XF__TF(XF_OFF_GCU_REL_ANGLE_Z, rel_angle_z),
    XF__TF(XF_OFF_GCU_CAM_ROLL, cam_roll), XF__TF(XF_OFF_GCU_CAM_PITCH, cam_pitch), XF__TF(XF_OFF_GCU_CAM_YAW, cam_yaw),
    XF__TF(XF_OFF_GCU_RATE_X, rate_x), XF__TF(XF_OFF_GCU_RATE_Y, rate_y), XF__TF(XF_OFF_GCU_RATE_Z, rate_z),
    /* sub frame (byte 37 is its header) */
    XF__TF(XF_OFF_GCU_HW_VERSION, hw_version), XF__TF(XF_OFF_GCU_FW_VERSION, fw_version),
    XF__TF(XF_OFF_GCU_GIMBAL_CODE, gimbal_code), XF__TF(XF_OFF_GCU_ERROR_CODE, error_code),
    XF__TF(XF_OFF_GCU_TARGET_DISTANCE, target_distance), XF__TF(XF_OFF_GCU_TARGET_LONGITUDE, target_longitude),
    XF__TF(XF_OFF_GCU_TARGET_LATITUDE, target_latitude), XF__TF(XF_OFF_GCU_TARGET_ALTITUDE, target_altitude),
    XF__TF(XF_OFF_GCU_ZOOM_CAM1, zoom_cam1), XF__TF(XF_OFF_GCU_ZOOM_CAM2, zoom_cam2),
    XF__TF(XF_OFF_GCU_THERMAL_STATUS, thermal_status), XF__TF(XF_OFF_GCU_CAMERA_STATUS, camera_status),
    XF__TF(XF_OFF_GCU_TIME_ZONE, time_zone)};
#define XF__TELE_MAIN_FIELDS 14u

/* Copy rows [from, to) of the table from @p buf into the telemetry. */
static void xf__tele_read(xf_telemetry *t, const uint8_t *buf, size_t from, size_t to)
{
    size_t i, k;
    for (i = from; i < to; i++) {
        const xf__tele_field *f = &xf__tele_fields[i];
        uint32_t v = 0;
        uint8_t *m = (uint8_t *)t + f->member;
        for (k = f->size; k > 0u; k--) {
            v = (v << 8) | buf[f->wire + k - 1u]; /* little-endian on the wire, any order in memory */
        }
        if (f->size == 1u) {
            *m = (uint8_t)v; /* int8_t time_zone: the same two's complement byte */
        } else if (f->size == 2u) {
            uint16_t h = (uint16_t)v;
            XF_MEMCPY(m, &h, sizeof(h));
        } else {
            XF_MEMCPY(m, &v, sizeof(v));
        }
    }
}

/* A setpoint that was on the wire is dropped when the mode that read it
 * changes: the next mode may read the same bytes as something else (after
 * click-to-aim, head lock reads angles as rates). */
static void xf__drop_ctrl(xf_client *c)
{
    c->ctrl_kind = XF__CTRL_DROPPED;
    c->ctrl_mode = 0;
}

#define XF__POD_FORCED 0x80u

static void xf__update_telemetry(xf_client *c, const uint8_t *buf)
{
    xf_telemetry *t = &c->tele;
    t->have_main = 1;
    xf__tele_read(t, buf, 0, XF__TELE_MAIN_FIELDS);
    if (c->pod_order == XF_POD_ORDER_UNDECIDED) { /* the first word that tells fixes it for this GCU */
        c->pod_order = (uint8_t)xf_pod_status_order(t->pod_status);
    }
    if (c->ctrl_mode != 0u && t->gimbal_mode != c->ctrl_mode) { /* ctrl_mode: a setpoint was on the wire */
        xf__drop_ctrl(c);
    }
    if (buf[XF_OFF_GCU_SUB_HEADER] == XF_SUB_HEADER) {
        t->have_sub = 1;
        xf__tele_read(t, buf, XF__TELE_MAIN_FIELDS, sizeof(xf__tele_fields) / sizeof(xf__tele_fields[0]));
        t->sub_ms = c->now_ms;
    }
}

/* Match a reply against the running command. */
static void xf__match(xf_client *c, const xf_frame *f)
{
    uint8_t order = f->data[XF_OFF_ORDER];
    xf_feedback fb;
    XF_ASSERT(!c->active || c->q_count > 0u); /* a running command is the queue's head */
    if (!c->active || order != c->queue[c->q_head].order) {
        return;
    }
    if (xf_feedback_decode(order, f->data + XF_OFF_PARAMS, f->len - XF_PACKET_MIN_LEN, &fb) != XF_OK || !fb.has_state) {
        return;
    }
    switch (fb.result) {
    case XF_RESULT_OK: xf__finish(c, XF_CMD_OK, &fb); break;
    case XF_RESULT_OPERATING:
        if (!c->operating) {
            xf_cmd_result r;
            c->operating = 1;
            c->operating_ms = c->now_ms;
            xf__result_of(c, XF_CMD_OPERATING, &fb, &r);
            xf__publish(c, &r);
        }
        break;
    default: xf__finish(c, XF_CMD_FAILED, &fb); break;
    }
}

/* What a reply of @p order says about the replies still to come: the guard, the start-up rule,
 * the version answered. */
static void xf__reply_order(xf_client *c, uint8_t order)
{
    int own_null = order == XF_ORDER_NULL || (order == XF_ORDER_EXTERNAL_TRACK && c->stream_on);
    if (c->active && order == c->queue[c->q_head].order && c->answered < UINT16_MAX) {
        c->answered++;
    }
    if (order == c->guard_order) {
        c->guard_wait = 0;
    } else if (!c->guard_wait && own_null) {
        /* The reply to a null (or to the stream) sent after the guarded packets: in order, none
         * of theirs can follow. A late reply to another command closes nothing. */
        c->guard_open = 0;
        c->guard_multi = 0;
    }
    if (c->health.version_answered == 0u && own_null) {
        c->health.version_answered = c->health.version_sent; /* what it answers: kept from now on */
    }
    if (!c->synced && order == XF_ORDER_NULL) {
        /* A reply to a null: every reply to what was sent before (by an earlier client, on this
         * link) is in, or, where the link reorders, is within reorder_ms. Commands may start. */
        c->synced = 1;
        c->sync_ms = c->now_ms;
    }
}

/* Whether the reorder bound is the client's to choose: the application set none and did not fix 0. */
static int xf__own_bound(const xf_client *c) { return !c->cfg.reorder_fixed && c->cfg.reorder_ms == 0u; }

/* The reorder bound in force: the application's, when it set one (or fixed 0); else the client's
 * own while the link has not shown that it keeps order (a command that starts before the link
 * could be judged is protected), 0 once it has. */
static void xf__set_bound(xf_client *c)
{
    if (!xf__own_bound(c)) {
        c->health.reorder_ms = c->cfg.reorder_ms;
    } else {
        c->health.reorder_ms = c->health.in_order ? 0u : xf__auto_reorder_ms(&c->cfg, c->period_ms);
    }
}

/* @p n replies came out of turn or twice (docs/protocol.md §7.4): counted, and the link is no
 * longer taken to keep order; for good when @p proof (a reply no link that keeps order and does
 * not duplicate can deliver), else until it has been steady again (XF__STEADY periods). */
XF__NOINLINE void xf__out_of_turn(xf_client *c, uint32_t n, int proof)
{
    c->health.out_of_turn += n;
    c->health.in_order = 0;
    c->steady = 0;
    c->out_of_order = (uint8_t)(c->out_of_order | (proof != 0));
    xf__set_bound(c);
}

/* Whether the first periods may still show the link in order (XF__PROMPT): every period since
 * the first packet brought one reply, at one phase (xf__judge_round()). */
static int xf__judging(const xf_client *c) { return !c->health.in_order && c->steady == c->health.packets_sent; }

/* Replies on a link that keeps order and does not duplicate answer the packets in the order they
 * were sent, once each. A reply of the last command's order after a reply of another order that
 * came after one of its own, or more replies of the running command than it had packets, cannot
 * be that. */
static void xf__judge_reply(xf_client *c, uint8_t order)
{
    if (c->round_replies == 0u) {
        uint32_t rtt = xf_ms_since(c->now_ms, c->last_tx_ms);
        c->round_rtt = (uint8_t)((rtt < UINT8_MAX) ? rtt : UINT8_MAX); /* 255: too late for the fast verdict */
    }
    if (c->round_replies < UINT8_MAX) {
        c->round_replies++;
    }
    if (c->active && order == c->queue[c->q_head].order && c->answered > c->packets) {
        xf__out_of_turn(c, 1, 1); /* a reply to a packet sent once came twice */
    }
    if (c->run_order == XF_ORDER_EXTERNAL_TRACK) {
        return; /* the stream answers with that order between commands */
    }
    if (order == c->run_order) {
        if (c->run_seen == 2u) {
            xf__out_of_turn(c, 1, 1);
        }
        c->run_seen = 1;
    } else if (c->run_seen == 1u) {
        c->run_seen = 2;
    }
}

/* The link has shown that it keeps order: commands run without a bound of the client's own. */
static void xf__in_order(xf_client *c)
{
    if (!c->health.in_order && !c->out_of_order) {
        c->health.in_order = 1;
        xf__set_bound(c);
    }
}

/*
 * At a packet due one period after the last (not after a silence, not late): the replies that
 * came since. A link that keeps order with a steady delay brings one reply a period; a link whose
 * delay varies by a period or more, as one that reorders does, brings none in some periods and
 * several in others (held back and overtaken, or copies; so do a GCU, or a loaded host, that
 * answer in bursts). So the link is taken to keep order after XF__STEADY periods in a row with one
 * reply each, or after XF__PROMPT from the first packet on whose replies also came at one phase:
 * each before the next packet (so it answered its own: nothing else was in flight at first), each
 * as long after its packet as the first (within an eighth of a period, and a millisecond for the
 * clock's grain). A link that reorders rarely answers so six times from the start; one reply a
 * period at random phases is far more common there (docs/protocol.md §7.4 has the figures).
 * Periods before the third packet are not counted out of turn: replies to a program that ran
 * before on the link may still come.
 */
static void xf__judge_round(xf_client *c)
{
    uint32_t since = xf_ms_since(c->now_ms, c->last_tx_ms);
    if (since <= c->period_ms + c->period_ms / 2u) {
        uint32_t tol = c->period_ms / 8u + 1u;
        int off_phase =
            c->steady + 1u == c->health.packets_sent && /* the first periods, each answered so far */
            (c->round_rtt > c->phase_ms + tol || c->phase_ms > c->round_rtt + tol || c->round_rtt == UINT8_MAX);
        if (c->health.packets_sent >= 3u && c->round_replies > 1u) {
            xf__out_of_turn(c, c->round_replies - 1u, 0);
        }
        if (c->round_replies != 1u) {
            c->steady = 0;
        } else if (c->steady == 0u || off_phase) {
            c->steady = 1; /* a run starts here: after an off-phase reply, not from the first packet */
            c->phase_ms = c->round_rtt;
        } else if (c->steady < UINT8_MAX) {
            c->steady++;
        }
        if (c->steady >= (xf__judging(c) ? XF__PROMPT : XF__STEADY)) {
            xf__in_order(c);
        }
    }
    c->round_replies = 0;
}

/* A frame out of the parser: whole, of the GCU (the parser's direction), its CRC checked. */
static void xf__on_frame(xf_client *c, const xf_frame *f)
{
    /* every offset read below (telemetry, order, parameters) lies within a whole frame */
    XF_ASSERT(f->len >= XF_PACKET_MIN_LEN && f->len <= XF_PACKET_MAX_LEN);
    if (c->cfg.on_bytes != NULL) {
        c->cfg.on_bytes(c->cfg.user, XF_DIR_GCU, f->data, f->len, c->now_ms);
    }
    c->health.replies++;
    if (c->window_replies < UINT16_MAX) {
        c->window_replies++; /* a flooding peer saturates the count */
    }
    c->awaiting = 0;
    c->health.last_rx_ms = c->now_ms;
    c->health.transport_closed = 0; /* a GCU answers over the (reopened) transport */
    xf__reply_order(c, f->data[XF_OFF_ORDER]);
    xf__judge_reply(c, f->data[XF_OFF_ORDER]);
    xf__update_telemetry(c, f->data);
    xf__update_link(c);
    xf__match(c, f);
    if (c->cfg.on_telemetry != NULL) {
        c->cfg.on_telemetry(c->cfg.user, &c->tele);
    }
}

static xf_err xf__receive(xf_client *c)
{
    /* The longest packet the parser keeps: a datagram link hands over whole
     * packets, and on an MCU (84) this is most of the step's stack. */
    uint8_t buf[XF_PACKET_MAX_LEN];
    int i;
    for (i = 0; i < XF_READS_PER_STEP; i++) {
        size_t n = 0, off = 0;
        xf_err err = xf_hal_read(&c->hal, buf, sizeof(buf), &n);
        if (err == XF_ERR_CLOSED) {
            c->health.transport_closed = 1;
            return err;
        }
        if (err != XF_OK) {
            return err;
        }
        if (n == 0u) {
            break;
        }
        /* A call returns at most one frame, from the call that feeds its last byte, and says
         * how far it read: a read that holds several packets takes a call for each. */
        while (off < n) {
            size_t used = 0;
            xf_frame f;
            xf_parse_status r = xf_parser_feed(&c->parser, buf + off, n - off, &used, &f);
            off += used;
            if (r != XF_PARSE_FRAME) {
                break; /* every byte taken */
            }
            xf__on_frame(c, &f);
        }
    }
    return XF_OK;
}

/* ---- sending ------------------------------------------------------------------- */

/*
 * Packets are written straight into their bytes, at the offsets of the
 * host frames (docs/protocol.md section 3, as in xf_host_pack; a test checks
 * that the two agree byte for byte): no xf_host_packet filled and then
 * packed field by field, which on an MCU was 0.6 KB of code and 88 bytes
 * of stack. Bytes not written are 0, which the protocol wants for data
 * that is absent.
 */

/* The runs the loops below write as consecutive 16-bit words. */
XF_STATIC_ASSERT(XF_OFF_HOST_YAW_CTRL == XF_OFF_HOST_ROLL_CTRL + 4u, control_words_in_a_row);
XF_STATIC_ASSERT(XF_OFF_HOST_RELATIVE_HEIGHT + 4u == XF_OFF_HOST_LONGITUDE + XF__GNSS_BYTES, gnss_bytes_in_a_row);
XF_STATIC_ASSERT(XF_OFF_HOST_VEL_UP == XF_OFF_HOST_CARRIER_ROLL + 2u * (XF__CARRIER_WORDS - 1u),
                 carrier_words_in_a_row);

/* @p n bytes of @p v, little-endian (one loop for every field: fewer instructions than each put inlined). */
static void xf__put_le(uint8_t *p, uint32_t v, size_t n)
{
    for (; n > 0u; n--, v >>= 8) {
        *p++ = (uint8_t)v;
    }
}

static void xf__put_carrier(const xf_client *c, uint8_t *buf)
{
    size_t i;
    if (!c->have_carrier || xf_ms_since(c->now_ms, c->carrier_ms) > c->cfg.carrier_max_age_ms) {
        return; /* zeros with ins_valid clear: never invent carrier data */
    }
    buf[XF_OFF_HOST_STATUS] |= XF_STATUS_INS_VALID;
    for (i = 0; i < XF__CARRIER_WORDS; i++) {
        xf__put_le(buf + XF_OFF_HOST_CARRIER_ROLL + 2u * i /* roll .. vel_up: 9 words in a row */, c->carrier[i], 2);
    }
}

static void xf__put_gnss(const xf_client *c, uint8_t *buf)
{
    if (!c->have_gnss || xf_ms_since(c->now_ms, c->gnss_ms) > c->cfg.gnss_max_age_ms) {
        return; /* "no sub frame data": bytes 37-68 all zero */
    }
    buf[XF_OFF_HOST_SUB_HEADER] = XF_SUB_HEADER;
    XF_MEMCPY(buf + XF_OFF_HOST_LONGITUDE, c->gnss, XF__GNSS_BYTES);
}

/* The kind of control quantities a mode reads (docs/protocol.md §11.1). */
static uint8_t xf__mode_reads(uint8_t mode)
{
    switch (mode) {
    case XF_MODE_ANGLE_CONTROL:
    case XF_MODE_EULER:
    case XF_MODE_FPV: return XF__CTRL_ANGLES;
    case XF_MODE_HEAD_LOCK:
    case XF_MODE_HEAD_FOLLOW:
    case XF_MODE_ORTHOVIEW:
    case XF_MODE_GAZE: return XF__CTRL_RATES;
    default: return XF__CTRL_NONE; /* track, and modes the client does not know */
    }
}

/* Orders that want the control quantities invalid while they run (§11.2): neutral, track and
 * click-to-aim say so; gaze-geo turns into gaze lock on any valid non-zero quantity. */
static int xf__order_wants_invalid(uint8_t order)
{
    return order == XF_ORDER_NEUTRAL || order == XF_ORDER_TRACK || order == XF_ORDER_CLICK_TO_AIM ||
           order == XF_ORDER_GAZE_GEO;
}

/* Orders during which no control quantities go: those, and every order that sets the mode, which
 * changes how the GCU reads them from the packet that carries it on. */
static int xf__order_holds_ctrl(uint8_t order)
{
    const xf_order_info *info = xf_order_lookup(order);
    return xf__order_wants_invalid(order) || (info != NULL && (info->flags & XF_ORDER_SETS_MODE) != 0u);
}

xf_ctrl_status xf_client_control_status(const xf_client *c)
{
    uint8_t reads;
    if (c == NULL || c->ctrl_kind == XF__CTRL_NONE) {
        return XF_CTRL_NOT_SET;
    }
    if (c->ctrl_kind == XF__CTRL_DROPPED) {
        return XF_CTRL_DROPPED;
    }
    if (c->active && xf__order_holds_ctrl(c->queue[c->q_head].order)) {
        return XF_CTRL_COMMAND;
    }
    if (!c->tele.have_main) {
        return XF_CTRL_NO_MODE;
    }
    reads = xf__mode_reads(c->tele.gimbal_mode);
    if (reads == XF__CTRL_NONE) {
        return XF_CTRL_NOT_READ;
    }
    return (reads == c->ctrl_kind) ? XF_CTRL_SENT : XF_CTRL_WRONG_KIND;
}

/* The control quantities, with ctrl_valid, only when xf_client_control_status() says they are
 * read as what the application set; else zeros with ctrl_valid clear. */
static void xf__put_control(xf_client *c, uint8_t *buf)
{
    size_t i;
    float zoom;
    int tripped;
    if (xf_client_control_status(c) != XF_CTRL_SENT) {
        return;
    }
    c->ctrl_mode = c->tele.gimbal_mode; /* the mode that reads it: a change drops it */
    buf[XF_OFF_HOST_STATUS] |= XF_STATUS_CTRL_VALID;
    /* Rates not renewed within rate_watchdog_ms: zero rates, still valid, and the gimbal holds still. */
    tripped = c->ctrl_kind == XF__CTRL_RATES && c->cfg.rate_watchdog_ms != 0u &&
              xf_ms_since(c->now_ms, c->ctrl_ms) > c->cfg.rate_watchdog_ms;
    if (tripped && !c->health.watchdog_active) {
        c->health.watchdog_active = 1;
        c->health.watchdog_trips++;
    }
    /* One raw unit of rate is 0.1 deg/s divided by the main screen's zoom (0 before a sub frame: 1). */
    zoom = xf_zoom_x((c->main_camera == 2u) ? c->tele.zoom_cam2 : c->tele.zoom_cam1);
    for (i = 0; i < 3u; i++) { /* roll, pitch, yaw */
        float q = c->ctrl[i];
        int16_t v;
        if (c->ctrl_kind == XF__CTRL_ANGLES) {
            /* Roll and yaw go round: 240 deg is -120 deg, not a clamped 180. */
            v = xf_ctrl_angle_raw((i == 1u) ? q : xf_units_wrap360f(q, -180.0f));
        } else {
            v = tripped ? 0 : xf_ctrl_rate_raw(q, zoom);
        }
        xf__put_le(buf + XF_OFF_HOST_ROLL_CTRL + 2u * i, (uint16_t)v, 2);
    }
}

/* Whether the queue's head may start now (docs/protocol.md §7.4). */
static int xf__may_start(xf_client *c)
{
    uint8_t order = c->queue[c->q_head].order;
    if (c->synced == 1u && xf_ms_since(c->now_ms, c->sync_ms) >= c->health.reorder_ms) {
        c->synced = 2; /* what earlier clients sent has landed, even where the link reorders */
    }
    if (c->active || c->q_count == 0u || c->nulls_owed > 0u || c->synced != 2u) {
        return 0; /* nothing to start, a null owed, or replies from before this client may be in flight */
    }
    if (xf__judging(c) && xf__own_bound(c)) {
        return 0; /* the first periods may yet show the link in order: a few periods, not the bound */
    }
    /* Replies to the previous packets of this order may still be on their way, each with that
     * command's state. Replies come in order: send nulls until one of theirs is back, then every
     * reply of this order answers this command. Where the link reorders, every command waits so
     * (a late reply could be of any earlier command's order). */
    return !(c->guard_open && (order == c->guard_order || c->health.reorder_ms > 0u || c->guard_multi) &&
             !(c->guard_wait && xf_ms_since(c->now_ms, c->guard_ms) >= c->cfg.command_timeout_ms));
}

/* The bit of xf_cmd_slot.fits for version @p v (docs/protocol.md §9.17: 0 and 1 are V0.1). */
static uint8_t xf__fits_bit(uint8_t v) { return (v >= XF_PROTOCOL_V2) ? XF__FITS_V2 : XF__FITS_V1; }

/* Whether the queue's head may go to a GCU that speaks version @p v (docs/protocol.md §10.1): its
 * parameters, checked at submit for the version known then, are valid in @p v and mean the same
 * there. xf_client_osd()'s value is set for @p v here. */
static int xf__fits_version(xf_cmd_slot *slot, uint8_t v)
{
    if (slot->fits == XF__FITS_OSD) {
        slot->params[0] = xf_osd_value(slot->params[0], v);
        slot->fits = xf__fits_bit(v);
    }
    return (slot->fits & xf__fits_bit(v)) != 0u;
}

/* The order of the next packet: a command, an owed null, the stream, or null; or -1: send
 * nothing in this slot (reorder_ms: let what was sent land before a packet that must not
 * overtake it or be overtaken by it). Sets *params (the bytes to send, *n of them). */
static int xf__next_order(xf_client *c, const uint8_t **params, size_t *n)
{
    const xf_cmd_slot *cmd;
    uint32_t quiet = xf_ms_since(c->now_ms, c->last_tx_ms);
    int start = xf__may_start(c);
    /* A command checked before the GCU had answered (or for another GCU) starts only if it means
     * the same to this one: never sent otherwise. The GCU has answered a null by now. */
    while (start && !xf__fits_version(&c->queue[c->q_head], xf_client_gcu_version(c))) {
        xf__finish(c, XF_CMD_REFUSED, NULL);
        start = xf__may_start(c);
    }
    cmd = &c->queue[c->q_head];
    *params = c->stream;
    *n = 0;
    if (c->health.reorder_ms > 0u && c->health.packets_sent > 0u && quiet < c->health.reorder_ms &&
        (c->nulls_owed > 0u || start)) {
        /* The null after a command must not overtake the command's last packet, nor a command the
         * packet before it: either way the GCU would run the command twice. */
        return -1;
    }
    if (start) {
        c->active = 1;
        c->operating = 0;
        c->packets = 0;
        c->answered = 0;
        c->head_ms = c->now_ms; /* from waiting to being sent */
        c->run_order = cmd->order;
        c->run_seen = 0;
        /* What was set before it must not be read after it; a setpoint that a mode change waits for
         * (held: the reported mode reads the other kind) is kept for the new mode. */
        if ((c->ctrl_kind == XF__CTRL_RATES || c->ctrl_kind == XF__CTRL_ANGLES) &&
            (xf__order_wants_invalid(cmd->order) || (xf__order_holds_ctrl(cmd->order) && c->ctrl_mode != 0u))) {
            xf__drop_ctrl(c);
        }
    }
    if (c->active) { /* checked and encoded at submit */
        *params = cmd->params;
        *n = cmd->params_len;
        return cmd->order;
    }
    if (c->nulls_owed > 0u) {
        c->nulls_owed--;
        return XF_ORDER_NULL;
    }
    if (!c->stream_on || c->q_count > 0u) {
        return XF_ORDER_NULL; /* a command waits (rule 5, or the start-up rule): nulls, not the stream */
    }
    *n = sizeof(c->stream);
    return XF_ORDER_EXTERNAL_TRACK;
}

/* version_auto: while no packet of the version sent has been answered for stale_ms (a link
 * that works answers well within it), try the other version. */
static void xf__search_version(xf_client *c)
{
    if (!c->cfg.version_auto || c->health.version_answered != 0u ||
        xf_ms_since(c->now_ms, c->version_ms) < c->cfg.stale_ms ||
        (c->health.replies != 0u && xf_ms_since(c->now_ms, c->health.last_rx_ms) < c->cfg.stale_ms)) {
        return;
    }
    c->health.version_sent = (c->health.version_sent == XF_PROTOCOL_V2) ? XF_PROTOCOL_V1 : XF_PROTOCOL_V2;
    c->version_ms = c->now_ms;
}

static xf_err xf__send(xf_client *c)
{
    uint8_t buf[XF_PACKET_MIN_LEN + XF_PARAMS_KNOWN_MAX];
    const uint8_t *params;
    size_t n, len;
    int order;
    xf_err err;
    XF_MEMSET(buf, 0, XF_PACKET_MIN_LEN);
    buf[XF_OFF_HOST_SUB_REQUEST] = XF_SUB_HEADER; /* ask for the GCU's sub frame in every reply */
    xf__put_carrier(c, buf);
    xf__put_gnss(c, buf);
    xf__judge_round(c); /* before a command may start in this slot: unprotected, it would be too late */
    order = xf__next_order(c, &params, &n); /* first: a command that starts here decides the control */
    if (order < 0) {
        return XF_OK;
    }
    XF_ASSERT(n <= XF_PARAMS_KNOWN_MAX); /* the parameters fit buf: a slot's or the stream's */
    xf__put_control(c, buf);
    len = XF_PACKET_MIN_LEN + n;
    /* header, order, parameters and CRC as the codec's packer writes them */
    xf__search_version(c);
    xf_packet_put_header(buf, XF_DIR_HOST, len, c->health.version_sent);
    xf_packet_put_tail(buf, len, (uint8_t)order, params, (uint8_t)n);
    err = c->hal.write(c->hal.ctx, buf, len);
    if (err != XF_OK) {
        c->health.send_errors++;
        if (err == XF_ERR_CLOSED) {
            c->health.transport_closed = 1;
        }
        return err;
    }
    c->health.packets_sent++;
    c->last_tx_ms = c->now_ms;
    c->window_sent++;
    c->awaiting = 1;
    if (c->active) {
        c->packets++;
    }
    if (c->cfg.on_bytes != NULL) {
        c->cfg.on_bytes(c->cfg.user, XF_DIR_HOST, buf, len, c->now_ms);
    }
    return XF_OK;
}

/* A command that ran too long ends: since it was first sent, or since the GCU said "operating".
 * One that never started ends after twice the timeout: no reply to a null yet, or the last
 * command's replies never settled (the guard gives up waiting for those after one). */
static void xf__check_timeouts(xf_client *c)
{
    uint32_t since, limit;
    if (c->q_count == 0u) {
        return; /* nothing to time out (a running command is the queue's head) */
    }
    since = xf_ms_since(c->now_ms, c->operating ? c->operating_ms : c->head_ms);
    limit = c->operating ? c->cfg.operating_timeout_ms : c->cfg.command_timeout_ms;
    if (!c->active) {
        since /= 2u;
    }
    if (since >= limit) {
        xf__finish(c, (c->health.link == XF_LINK_DOWN) ? XF_CMD_LINK_LOST : XF_CMD_TIMEOUT, NULL);
    }
}

xf_err xf_client_step(xf_client *c, uint32_t now_ms)
{
    xf_err rx, tx = XF_OK;
    if (c == NULL) {
        return XF_ERR_ARG;
    }
    if (c->busy) {
        return XF_ERR_BUSY; /* from a callback: the outer step (or sweep) is half done */
    }
    c->busy = 1;
    c->now_ms = now_ms;
    if (!c->started) {
        c->started = 1;
        c->next_send_ms = now_ms; /* (a command submitted before it waits from here: head_new) */
        c->window_start_ms = now_ms;
        c->version_ms = now_ms;
    }
    if (c->head_new) {
        c->head_new = 0;
        c->head_ms = now_ms;
    }
    rx = xf__receive(c);
    xf__update_link(c);
    xf__check_timeouts(c);
    if ((int32_t)(now_ms - c->next_send_ms) >= 0) {
        tx = xf__send(c);
        c->next_send_ms += c->period_ms;
        if ((int32_t)(now_ms - c->next_send_ms) >= 0) {
            c->next_send_ms = now_ms + c->period_ms; /* fell behind: no burst to catch up */
        }
        xf__update_link(c);
    }
    xf__update_window(c);
    c->busy = 0;
    return (rx != XF_OK) ? rx : tx;
}

uint32_t xf_client_next_deadline(const xf_client *c) { return (c == NULL) ? 0u : c->next_send_ms; }

/* ---- inputs -------------------------------------------------------------------- */

void xf_client_set_carrier(xf_client *c, const xf_carrier *carrier, uint32_t now_ms)
{
    if (c != NULL && carrier != NULL) {
        uint16_t *k = c->carrier; /* wire order */
        k[0] = (uint16_t)xf_carrier_roll_raw(carrier->roll_deg);
        k[1] = (uint16_t)xf_carrier_pitch_raw(carrier->pitch_deg);
        k[2] = xf_carrier_yaw_raw(carrier->yaw_deg);
        k[3] = (uint16_t)xf_accel_raw(carrier->accel_north);
        k[4] = (uint16_t)xf_accel_raw(carrier->accel_east);
        k[5] = (uint16_t)xf_accel_raw(carrier->accel_up);
        k[6] = (uint16_t)xf_velocity_raw(carrier->vel_north);
        k[7] = (uint16_t)xf_velocity_raw(carrier->vel_east);
        k[8] = (uint16_t)xf_velocity_raw(carrier->vel_up);
        c->carrier_ms = now_ms;
        c->have_carrier = 1;
    }
}

void xf_client_set_gnss(xf_client *c, const xf_gnss *gnss, uint32_t now_ms)
{
    if (c != NULL && gnss != NULL) {
#define XF__GNSS_AT(off) (c->gnss + ((off)-XF_OFF_HOST_LONGITUDE)) /* a field at its wire offset */
        xf__put_le(XF__GNSS_AT(XF_OFF_HOST_LONGITUDE), (uint32_t)gnss->longitude_e7, 4);
        xf__put_le(XF__GNSS_AT(XF_OFF_HOST_LATITUDE), (uint32_t)gnss->latitude_e7, 4);
        xf__put_le(XF__GNSS_AT(XF_OFF_HOST_ALTITUDE), (uint32_t)gnss->altitude_mm, 4);
        *XF__GNSS_AT(XF_OFF_HOST_SATELLITES) = gnss->satellites;
        xf__put_le(XF__GNSS_AT(XF_OFF_HOST_GNSS_MS), gnss->ms_of_week, 4);
        xf__put_le(XF__GNSS_AT(XF_OFF_HOST_GNSS_WEEK), (uint16_t)gnss->week, 2);
        xf__put_le(XF__GNSS_AT(XF_OFF_HOST_RELATIVE_HEIGHT), (uint32_t)gnss->relative_height_mm, 4);
#undef XF__GNSS_AT
        c->gnss_ms = now_ms;
        c->have_gnss = 1;
    }
}

static xf_ctrl_status xf__set_ctrl(xf_client *c, uint8_t kind, float a, float b, float d, uint32_t now_ms)
{
    if (kind != c->ctrl_kind) {
        c->ctrl_mode = 0; /* a new kind has not been read in any mode yet */
    }
    c->ctrl_kind = kind;
    c->ctrl[0] = a;
    c->ctrl[1] = b;
    c->ctrl[2] = d;
    c->ctrl_ms = now_ms;
    c->health.watchdog_active = 0;
    return xf_client_control_status(c);
}

xf_ctrl_status xf_client_set_rates(xf_client *c, float roll_dps, float pitch_dps, float yaw_dps, uint32_t now_ms)
{
    return (c != NULL) ? xf__set_ctrl(c, XF__CTRL_RATES, roll_dps, pitch_dps, yaw_dps, now_ms) : XF_CTRL_NOT_SET;
}

xf_ctrl_status xf_client_set_angles(xf_client *c, float roll_deg, float pitch_deg, float yaw_deg, uint32_t now_ms)
{
    return (c != NULL) ? xf__set_ctrl(c, XF__CTRL_ANGLES, roll_deg, pitch_deg, yaw_deg, now_ms) : XF_CTRL_NOT_SET;
}

uint16_t xf_client_pod_flags(const xf_client *c)
{
    return (c == NULL) ? 0u : xf_pod_flags(c->tele.pod_status, xf_client_pod_order(c));
}

xf_pod_order xf_client_pod_order(const xf_client *c)
{
    return (c == NULL) ? XF_POD_ORDER_UNDECIDED : (xf_pod_order)(c->pod_order & ~XF__POD_FORCED);
}

void xf_client_set_pod_order(xf_client *c, xf_pod_order order)
{
    if (c != NULL) {
        int forced = order == XF_POD_ORDER_LE || order == XF_POD_ORDER_BE;
        c->pod_order = forced ? (uint8_t)(order | XF__POD_FORCED) : (uint8_t)XF_POD_ORDER_UNDECIDED;
        if (!forced && c->tele.have_main) {
            c->pod_order = (uint8_t)xf_pod_status_order(c->tele.pod_status);
        }
    }
}

void xf_client_set_main_camera(xf_client *c, uint8_t camera)
{
    if (c != NULL) {
        c->main_camera = (camera == 2u) ? 2u : 1u;
    }
}

void xf_client_clear_control(xf_client *c)
{
    if (c != NULL) {
        c->ctrl_kind = XF__CTRL_NONE;
        c->ctrl_mode = 0;
        c->health.watchdog_active = 0;
    }
}

/* ---- commands ------------------------------------------------------------------ */

/* Check @p cmd and encode it into @p slot once: every packet then copies the bytes. */
static xf_err xf__slot_encode(xf_cmd_slot *slot, const xf_command *cmd, uint8_t version, xf_field *bad_field)
{
    size_t n = 0;
    uint8_t other = (version >= XF_PROTOCOL_V2) ? XF_PROTOCOL_V1 : XF_PROTOCOL_V2;
    xf_err err = xf_command_encode(cmd, version, slot->params, sizeof(slot->params), &n, bad_field);
    if (err != XF_OK) {
        return err;
    }
    slot->order = cmd->order;
    slot->params_len = (uint8_t)n;
    /* Valid in the other version too, with the same meaning? OSD's value means the opposite there
     * (docs/protocol.md §11.4); the ranges are the codec's. */
    slot->fits = xf__fits_bit(version);
    if (cmd->order != XF_ORDER_OSD && xf_command_check(cmd, other, NULL) == XF_OK) {
        slot->fits |= xf__fits_bit(other);
    }
    return XF_OK;
}

uint8_t xf_client_gcu_version(const xf_client *c)
{
    if (c == NULL) {
        return 0;
    }
    return c->tele.have_main ? c->tele.version : c->cfg.protocol_version;
}

uint8_t xf_client_answered_version(const xf_client *c) { return (c == NULL) ? 0u : c->health.version_answered; }

xf_err xf_client_osd(xf_client *c, int show, uint32_t *id)
{
    xf_command cmd;
    xf_err err;
    if (c == NULL) {
        return XF_ERR_ARG;
    }
    xf_command_init(&cmd, XF_ORDER_OSD);
    err = xf_client_submit(c, &cmd, id, NULL);
    if (err == XF_OK) { /* the value for the GCU's version is set when it starts (xf__fits_version) */
        xf_cmd_slot *slot = &c->queue[(c->q_head + c->q_count - 1u) % XF_CLIENT_QUEUE];
        XF_ASSERT(c->q_count > 0u); /* just queued: the last slot is this command's */
        slot->params[0] = (uint8_t)(show != 0);
        slot->fits = XF__FITS_OSD;
    }
    return err;
}

xf_support xf_client_supports(const xf_client *c, uint8_t order)
{
    if (c == NULL || !c->tele.have_sub) {
        return XF_SUPPORT_UNKNOWN; /* the model comes with the sub frame */
    }
    return xf_gimbal_supports(c->tele.gimbal_code, order);
}

xf_err xf_client_submit(xf_client *c, const xf_command *cmd, uint32_t *id, xf_field *bad_field)
{
    return xf_client_submit_opt(c, cmd, 0u, id, bad_field);
}

xf_err xf_client_submit_opt(xf_client *c, const xf_command *cmd, unsigned flags, uint32_t *id, xf_field *bad_field)
{
    xf_cmd_slot encoded, *slot;
    xf_err err;
    if (c == NULL) {
        if (bad_field != NULL) {
            *bad_field = XF_F_NONE;
        }
        return XF_ERR_ARG;
    }
    err = xf__slot_encode(&encoded, cmd, xf_client_gcu_version(c), bad_field);
    if (err != XF_OK) {
        return err;
    }
    if (!(flags & XF_SUBMIT_ANY_MODEL) && xf_client_supports(c, cmd->order) == XF_SUPPORT_NO) {
        return XF_ERR_UNSUPPORTED; /* the GCU's model would only refuse it (V2.0.6's support list) */
    }
    if (c->q_count >= XF_CLIENT_QUEUE) {
        return XF_ERR_BUSY;
    }
    if (cmd->order == XF_ORDER_EXTERNAL_TRACK && c->stream_on) {
        xf__guard(c, XF_ORDER_EXTERNAL_TRACK, 0); /* the stream's replies carry this order's state */
    }
    slot = &c->queue[(c->q_head + c->q_count) % XF_CLIENT_QUEUE];
    *slot = encoded;
    if (id != NULL) {
        *id = c->next_id;
    }
    c->next_id++;
    if (c->next_id == 0u) {
        c->next_id = 1; /* 0 never names a command */
    }
    if (c->q_count++ == 0u) {
        c->head_new = 1; /* it waits from the next step (now_ms may be old) */
    }
    return XF_OK;
}

xf_cmd_status xf_client_command_status(const xf_client *c, uint32_t id, xf_cmd_result *result)
{
    uint32_t back;
    const xf_cmd_record *k;
    if (c == NULL || id == 0u) {
        return XF_CMD_UNKNOWN;
    }
    back = xf__ids_back(c, id);
    if (back >= 1u && back <= c->q_count) { /* queued; the head is the oldest */
        if (back == c->q_count && c->active) {
            return c->operating ? XF_CMD_OPERATING : XF_CMD_SENDING;
        }
        return XF_CMD_QUEUED;
    }
    back -= c->q_count + 1u; /* finished: 0 the newest (a huge number for an id not handed out) */
    if (back >= XF_CLIENT_RESULTS) {
        return XF_CMD_UNKNOWN;
    }
    k = &c->results[(c->r_next + XF_CLIENT_RESULTS - 1u - back) % XF_CLIENT_RESULTS];
    if (k->status != XF_CMD_UNKNOWN && result != NULL) {
        result->id = id;
        result->order = k->order;
        result->status = (xf_cmd_status)k->status; /* stored in a byte */
        result->state = k->state;
        result->failed_cameras = k->failed_cameras;
        result->packets = k->packets;
        result->elapsed_ms = k->elapsed_ms;
    }
    return (xf_cmd_status)k->status; /* XF_CMD_UNKNOWN (0): fewer commands have finished */
}

size_t xf_client_pending(const xf_client *c) { return (c == NULL) ? 0u : c->q_count; }

int xf_client_settled(const xf_client *c)
{
    return c != NULL && !c->active && c->q_count == 0u && !c->guard_open && !c->stream_on;
}

void xf_client_cancel_all(xf_client *c)
{
    if (c != NULL) {
        uint8_t outer = c->busy; /* set when called from a callback of a step */
        c->busy = 1;
        xf__fail_all(c, XF_CMD_CANCELLED);
        c->busy = outer;
    }
}

xf_err xf_client_external_track(xf_client *c, uint8_t cameras, int16_t dx, int16_t dy)
{
    xf_command cmd;
    xf_cmd_slot encoded;
    xf_err err;
    if (c == NULL) {
        return XF_ERR_ARG;
    }
    xf_command_init(&cmd, XF_ORDER_EXTERNAL_TRACK);
    cmd.cameras = cameras;
    cmd.dx = dx;
    cmd.dy = dy;
    cmd.value = 2; /* start / keep tracking */
    err = xf__slot_encode(&encoded, &cmd, xf_client_gcu_version(c), NULL);
    if (err == XF_OK) { /* a refused call leaves a running stream as it was */
        XF_MEMCPY(c->stream, encoded.params, sizeof(c->stream));
        c->stream_on = 1;
    }
    return err;
}

xf_err xf_client_external_track_stop(xf_client *c, uint32_t *id)
{
    xf_command cmd;
    xf_err err;
    if (c == NULL) {
        return XF_ERR_ARG;
    }
    xf_command_init(&cmd, XF_ORDER_EXTERNAL_TRACK);
    if (c->stream_on) {
        cmd.cameras = c->stream[0]; /* external_track's parameters start with KK */
    }
    /* Queue the exit before touching the stream: a refused one (queue full)
     * must leave the stream on, so that calling again sends the exit to the
     * stream's cameras, not to camera 1. Nothing is sent before the next
     * step, so the guard set after the submit still applies to the exit. */
    err = xf_client_submit(c, &cmd, id, NULL); /* value 0: exit */
    if (err == XF_OK && c->stream_on) {
        /* The stream's replies (same order, with their own state) may still
         * be in flight: the exit's result must be its own. */
        xf__guard(c, XF_ORDER_EXTERNAL_TRACK, 0); /* the stream has been answered all along */
        c->stream_on = 0;
    }
    return err;
}

/* ---- state --------------------------------------------------------------------- */

const xf_telemetry *xf_client_telemetry(const xf_client *c) { return (c == NULL) ? NULL : &c->tele; }
const xf_health *xf_client_health(const xf_client *c) { return (c == NULL) ? NULL : &c->health; }
const xf_parser_stats *xf_client_parser_stats(const xf_client *c) { return (c == NULL) ? NULL : &c->parser.stats; }

xf_err xf_telemetry_convert(const xf_telemetry *t, xf_telemetry_units *u)
{
    if (t == NULL || u == NULL) {
        return XF_ERR_ARG;
    }
    u->cam_roll_deg = xf_cdeg(t->cam_roll);
    u->cam_pitch_deg = xf_cdeg(t->cam_pitch);
    u->cam_yaw_deg = xf_cdeg(t->cam_yaw);
    u->rel_x_deg = xf_cdeg(t->rel_angle_x);
    u->rel_y_deg = xf_cdeg(t->rel_angle_y);
    u->rel_z_deg = xf_cdeg(t->rel_angle_z);
    u->rate_x_dps = xf_gcu_rate_dps(t->rate_x, t->version);
    u->rate_y_dps = xf_gcu_rate_dps(t->rate_y, t->version);
    u->rate_z_dps = xf_gcu_rate_dps(t->rate_z, t->version);
    u->zoom_cam1 = xf_zoom_x(t->zoom_cam1);
    u->zoom_cam2 = xf_zoom_x(t->zoom_cam2);
    u->target_distance_m = 0.0f;
    u->distance_valid = xf_distance_m(t->target_distance, &u->target_distance_m);
    return XF_OK;
}
xf_link_state xf_client_link(const xf_client *c) { return (c == NULL) ? XF_LINK_DOWN : c->health.link; }

/* The names of xf_link_state's values, in their order (0: down). */
static const char xf__link_names[] = "down\0stale\0up"; /* test_state_names holds each */

const char *xf_link_state_name(xf_link_state s)
{
    return xf__nth_name(xf__link_names, ((unsigned)s <= (unsigned)XF_LINK_UP) ? (size_t)s : 0u);
}

/* The names of xf_cmd_status's values, in their order (0: unknown). */
static const char xf__cmd_status_names[] =
    "unknown\0queued\0sending\0operating\0ok\0failed\0timeout\0link lost\0cancelled\0refused";

const char *xf_cmd_status_name(xf_cmd_status s)
{
    return xf__nth_name(xf__cmd_status_names, ((unsigned)s <= (unsigned)XF_CMD_REFUSED) ? (size_t)s : 0u);
}
