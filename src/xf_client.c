/*
 * xf_client.c - the host side of the GCU protocol over xf_hal.
 * Portable: no OS, no heap, no globals. See xf_client.h for the contract.
 */
#include "xfgcu/xf_client.h"
#include "xfgcu/xf_mem.h"
#include "xfgcu/xf_units.h"

#define XF_CTRL_NONE      0u
#define XF_CTRL_RATES     1u
#define XF_CTRL_ANGLES    2u
#define XF_READS_PER_STEP 16 /* bound the work of one step on a flooded link */

void xf_client_config_init(xf_client_config *cfg)
{
    if (cfg == NULL) {
        return;
    }
    XF_MEMSET(cfg, 0, sizeof(*cfg));
    cfg->protocol_version = XF_PROTOCOL_V1;
    cfg->rate_hz = 50;
    cfg->carrier_max_age_ms = 200;
    cfg->gnss_max_age_ms = 2000;
    cfg->stale_ms = 250;
    cfg->down_ms = 1000;
    cfg->command_timeout_ms = 1000;
    cfg->operating_timeout_ms = 60000;
    cfg->rate_watchdog_ms = 500;
}

xf_err xf_client_init(xf_client *c, const xf_hal *hal, const xf_client_config *cfg)
{
    xf_client_config def;
    if (c == NULL || xf_hal_check(hal) != XF_OK) {
        return XF_ERR_ARG;
    }
    if (cfg == NULL) {
        xf_client_config_init(&def);
        cfg = &def;
    }
    if (cfg->rate_hz == 0u || cfg->rate_hz > 200u || cfg->protocol_version == 0u || cfg->stale_ms == 0u ||
        cfg->down_ms <= cfg->stale_ms || cfg->command_timeout_ms == 0u || cfg->operating_timeout_ms == 0u) {
        return XF_ERR_RANGE; /* a link that is never up, or commands that time out before they are sent */
    }
    XF_MEMSET(c, 0, sizeof(*c));
    c->cfg = *cfg;
    c->hal = *hal;
    xf_parser_init(&c->parser, XF_DIR_GCU);
    c->period_ms = (uint16_t)((1000u + cfg->rate_hz / 2u) / cfg->rate_hz);
    c->next_id = 1;
    return (cfg->rate_hz < 30u || cfg->rate_hz > 50u) ? XF_WARN_RATE : XF_OK;
}

/* ---- results ------------------------------------------------------------------ */

/* The id of queue position @p i (0: the head). Ids are handed out in
 * submission order and commands leave the queue from its head only, so the
 * queued ones hold the q_count ids before next_id, 0 skipped on the wrap. */
static uint32_t xf__queued_id(const xf_client *c, size_t i)
{
    uint32_t back = (uint32_t)(c->q_count - i);
    return (back < c->next_id) ? c->next_id - back : c->next_id - back - 1u;
}

static void xf__publish(xf_client *c, const xf_cmd_result *r)
{
    if (r->status != XF_CMD_OPERATING) {
        c->results[c->r_next] = *r;
        c->r_next = (uint8_t)((c->r_next + 1u) % XF_CLIENT_RESULTS);
    }
    if (c->cfg.on_result != NULL) {
        c->cfg.on_result(c->cfg.user, r);
    }
}

/* The result of the queue's head. */
static void xf__result_of(const xf_client *c, xf_cmd_status st, xf_cmd_result *r)
{
    XF_MEMSET(r, 0, sizeof(*r));
    r->id = xf__queued_id(c, 0);
    r->order = c->queue[c->q_head].order;
    r->status = (uint8_t)st;
    if (c->active) {
        r->packets = c->packets;
        r->elapsed_ms = xf_ms_since(c->now_ms, c->started_ms);
    }
}

/* End the running command (or the queue's head) with @p st. */
static void xf__finish(xf_client *c, xf_cmd_status st, const xf_feedback *fb)
{
    xf_cmd_result r;
    xf__result_of(c, st, &r);
    if (fb != NULL) {
        r.state = fb->state;
        r.failed_cameras = fb->failed_cameras;
    }
    if (c->active) {
        c->nulls_owed = 1;        /* back to null packets: the next command of any order is separated */
        c->guard_order = r.order; /* replies of this order may still be in flight */
        c->guard_open = 1;
    }
    c->active = 0;
    c->operating = 0;
    c->q_head = (uint8_t)((c->q_head + 1u) % XF_CLIENT_QUEUE);
    c->q_count--;
    xf__publish(c, &r);
}

static void xf__fail_all(xf_client *c, xf_cmd_status st)
{
    while (c->q_count > 0u) {
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
    if ((uint8_t)s == c->health.link) {
        return;
    }
    c->health.link = (uint8_t)s;
    if (s == XF_LINK_DOWN) {
        xf__fail_all(c, XF_CMD_LINK_LOST); /* fail fast: never run a stale command later */
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

/* Keep the wire's integers: converting on read costs nothing here, and
 * floats or a copy of the packet would double the client's RAM on an MCU. */
static void xf__update_telemetry(xf_client *c, const xf_gcu_packet *p)
{
    xf_telemetry *t = &c->tele;
    const xf_gcu_main *m = &p->main;
    const xf_gcu_sub *s = &p->sub;
    t->have_main = 1;
    t->version = p->version;
    t->gimbal_mode = m->gimbal_mode;
    t->pod_status = m->pod_status;
    t->cam_roll = m->cam_roll;
    t->cam_pitch = m->cam_pitch;
    t->cam_yaw = m->cam_yaw;
    t->rel_angle_x = m->rel_angle_x;
    t->rel_angle_y = m->rel_angle_y;
    t->rel_angle_z = m->rel_angle_z;
    t->rate_x = m->rate_x;
    t->rate_y = m->rate_y;
    t->rate_z = m->rate_z;
    t->target_offset_x = m->target_offset_x;
    t->target_offset_y = m->target_offset_y;
    if (s->sub_header == XF_SUB_HEADER) {
        t->have_sub = 1;
        t->hw_version = s->hw_version;
        t->fw_version = s->fw_version;
        t->gimbal_code = s->gimbal_code;
        t->thermal_status = s->thermal_status;
        t->time_zone = s->time_zone;
        t->error_code = s->error_code;
        t->camera_status = s->camera_status;
        t->zoom_cam1 = s->zoom_cam1;
        t->zoom_cam2 = s->zoom_cam2;
        t->target_distance = s->target_distance;
        t->target_longitude = s->target_longitude;
        t->target_latitude = s->target_latitude;
        t->target_altitude = s->target_altitude;
        t->sub_ms = c->now_ms;
    }
}

/* Match a reply against the running command. */
static void xf__match(xf_client *c, const xf_gcu_packet *p)
{
    xf_feedback fb;
    const xf_cmd_slot *cmd;
    if (!c->active) {
        return;
    }
    cmd = &c->queue[c->q_head];
    if (p->order != cmd->order) {
        return;
    }
    if (xf_feedback_decode(p->order, p->params, p->params_len, &fb) != XF_OK || !fb.has_state) {
        return;
    }
    switch (fb.result) {
    case XF_RESULT_OK: xf__finish(c, XF_CMD_OK, &fb); break;
    case XF_RESULT_OPERATING:
        if (!c->operating) {
            xf_cmd_result r;
            c->operating = 1;
            c->operating_ms = c->now_ms;
            xf__result_of(c, XF_CMD_OPERATING, &r);
            r.state = fb.state;
            xf__publish(c, &r);
        }
        break;
    default: xf__finish(c, XF_CMD_FAILED, &fb); break;
    }
}

static void xf__on_frame(xf_client *c, const xf_frame *f)
{
    xf_gcu_packet p;
    if (xf_frame_gcu(f, &p) != XF_OK) {
        return; /* cannot happen: the parser checked it */
    }
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
    if (p.order != c->guard_order) {
        c->guard_open = 0; /* the separating null's reply: no late reply of guard_order can follow */
    }
    xf__update_telemetry(c, &p);
    xf__update_link(c);
    xf__match(c, &p);
    if (c->cfg.on_telemetry != NULL) {
        c->cfg.on_telemetry(c->cfg.user, &c->tele);
    }
}

static xf_err xf__receive(xf_client *c)
{
    uint8_t buf[512];
    int i;
    for (i = 0; i < XF_READS_PER_STEP; i++) {
        size_t n = 0, off = 0;
        xf_err err = c->hal.read(c->hal.ctx, buf, sizeof(buf), &n);
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
        /* Until no frame is left: also after the input is used up, since
         * more intact frames can be held behind one just returned. */
        for (;;) {
            size_t used = 0;
            xf_frame f;
            int r = xf_parser_feed(&c->parser, buf + off, n - off, &used, &f);
            off += used;
            if (r != XF_PARSE_FRAME) {
                break;
            }
            xf__on_frame(c, &f);
        }
    }
    return XF_OK;
}

/* ---- sending ------------------------------------------------------------------- */

static void xf__put_carrier(const xf_client *c, xf_host_packet *pkt)
{
    const xf_carrier_wire *k = &c->carrier;
    if (!c->have_carrier || xf_ms_since(c->now_ms, c->carrier_ms) > c->cfg.carrier_max_age_ms) {
        return; /* zeros with ins_valid clear: never invent carrier data */
    }
    pkt->main.status |= XF_STATUS_INS_VALID;
    pkt->main.carrier_roll = k->roll;
    pkt->main.carrier_pitch = k->pitch;
    pkt->main.carrier_yaw = k->yaw;
    pkt->main.accel_north = k->accel_north;
    pkt->main.accel_east = k->accel_east;
    pkt->main.accel_up = k->accel_up;
    pkt->main.vel_north = k->vel_north;
    pkt->main.vel_east = k->vel_east;
    pkt->main.vel_up = k->vel_up;
}

static void xf__put_gnss(const xf_client *c, xf_host_packet *pkt)
{
    const xf_gnss *g = &c->gnss;
    if (!c->have_gnss || xf_ms_since(c->now_ms, c->gnss_ms) > c->cfg.gnss_max_age_ms) {
        return; /* "no sub frame data": bytes 37-68 all zero */
    }
    pkt->sub.sub_header = XF_SUB_HEADER;
    pkt->sub.longitude = g->longitude_e7;
    pkt->sub.latitude = g->latitude_e7;
    pkt->sub.altitude = g->altitude_mm;
    pkt->sub.satellites = g->satellites;
    pkt->sub.gnss_ms = g->ms_of_week;
    pkt->sub.gnss_week = g->week;
    pkt->sub.relative_height = g->relative_height_mm;
}

static void xf__put_control(xf_client *c, xf_host_packet *pkt)
{
    xf_host_main *m = &pkt->main;
    if (c->ctrl_kind == XF_CTRL_NONE) {
        return;
    }
    m->status |= XF_STATUS_CTRL_VALID;
    if (c->ctrl_kind == XF_CTRL_ANGLES) {
        /* Roll and yaw go round: 240 deg is -120 deg, not a clamped 180. */
        m->roll_ctrl = xf_ctrl_angle_raw(xf_units_wrap360f(c->ctrl[0], -180.0f));
        m->pitch_ctrl = xf_ctrl_angle_raw(c->ctrl[1]);
        m->yaw_ctrl = xf_ctrl_angle_raw(xf_units_wrap360f(c->ctrl[2], -180.0f));
        return;
    }
    if (c->cfg.rate_watchdog_ms != 0u && xf_ms_since(c->now_ms, c->ctrl_ms) > c->cfg.rate_watchdog_ms) {
        if (!c->health.watchdog_active) {
            c->health.watchdog_active = 1;
            c->health.watchdog_trips++;
        }
        return; /* zero rates, still valid: the gimbal holds still */
    }
    {
        /* One raw unit is 0.1 deg/s divided by the main screen's zoom. */
        float zoom = xf_zoom_x(c->tele.zoom_cam1); /* 0 until a sub frame came: counts as 1 */
        m->roll_ctrl = xf_ctrl_rate_raw(c->ctrl[0], zoom);
        m->pitch_ctrl = xf_ctrl_rate_raw(c->ctrl[1], zoom);
        m->yaw_ctrl = xf_ctrl_rate_raw(c->ctrl[2], zoom);
    }
}

/* The order of the next packet: a command, an owed null, the stream, or null. */
static void xf__put_order(xf_client *c, xf_host_packet *pkt)
{
    const xf_cmd_slot *cmd = &c->queue[c->q_head];
    if (!c->active && c->q_count > 0u && c->nulls_owed == 0u) {
        if (c->guard_open && cmd->order == c->guard_order && c->health.link != XF_LINK_DOWN) {
            /* Replies to the previous packets of this order may still be on
             * their way, each with that command's state. Replies come in
             * order: keep sending nulls until one of theirs is back, then
             * every reply of this order answers this command. */
            return;
        }
        c->active = 1;
        c->operating = 0;
        c->packets = 0;
        c->started_ms = c->now_ms;
    }
    if (c->active) { /* checked and encoded at submit */
        pkt->order = cmd->order;
        pkt->params_len = cmd->params_len;
        XF_MEMCPY(pkt->params, cmd->params, cmd->params_len);
    } else if (c->nulls_owed > 0u) {
        c->nulls_owed--;
    } else if (c->stream_on) {
        pkt->order = XF_ORDER_EXTERNAL_TRACK;
        pkt->params_len = (uint8_t)sizeof(c->stream);
        XF_MEMCPY(pkt->params, c->stream, sizeof(c->stream));
    }
}

static xf_err xf__send(xf_client *c)
{
    xf_host_packet pkt;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    xf_err err;
    xf_host_packet_init(&pkt, c->cfg.protocol_version);
    xf__put_carrier(c, &pkt);
    xf__put_gnss(c, &pkt);
    xf__put_control(c, &pkt);
    xf__put_order(c, &pkt);
    if (xf_host_pack(&pkt, buf, sizeof(buf), &len) != XF_OK) {
        return XF_ERR_ARG;
    }
    err = c->hal.write(c->hal.ctx, buf, len);
    if (err != XF_OK) {
        c->health.send_errors++;
        if (err == XF_ERR_CLOSED) {
            c->health.transport_closed = 1;
        }
        return err;
    }
    c->health.packets_sent++;
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

static void xf__check_timeouts(xf_client *c)
{
    uint32_t limit, since;
    if (!c->active) {
        return;
    }
    since = c->operating ? c->operating_ms : c->started_ms;
    limit = c->operating ? c->cfg.operating_timeout_ms : c->cfg.command_timeout_ms;
    if (xf_ms_since(c->now_ms, since) >= limit) {
        xf__finish(c, (c->health.link == XF_LINK_DOWN) ? XF_CMD_LINK_LOST : XF_CMD_TIMEOUT, NULL);
    }
}

xf_err xf_client_step(xf_client *c, uint32_t now_ms)
{
    xf_err rx, tx = XF_OK;
    if (c == NULL) {
        return XF_ERR_ARG;
    }
    c->now_ms = now_ms;
    if (!c->started) {
        c->started = 1;
        c->next_send_ms = now_ms;
        c->window_start_ms = now_ms;
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
    return (rx != XF_OK) ? rx : tx;
}

uint32_t xf_client_next_deadline(const xf_client *c) { return (c == NULL) ? 0u : c->next_send_ms; }

/* ---- inputs -------------------------------------------------------------------- */

void xf_client_set_carrier(xf_client *c, const xf_carrier *carrier, uint32_t now_ms)
{
    if (c != NULL && carrier != NULL) {
        xf_carrier_wire *k = &c->carrier;
        k->roll = xf_carrier_roll_raw(carrier->roll_deg);
        k->pitch = xf_carrier_pitch_raw(carrier->pitch_deg);
        k->yaw = xf_carrier_yaw_raw(carrier->yaw_deg);
        k->accel_north = xf_accel_raw(carrier->accel_north);
        k->accel_east = xf_accel_raw(carrier->accel_east);
        k->accel_up = xf_accel_raw(carrier->accel_up);
        k->vel_north = xf_velocity_raw(carrier->vel_north);
        k->vel_east = xf_velocity_raw(carrier->vel_east);
        k->vel_up = xf_velocity_raw(carrier->vel_up);
        c->carrier_ms = now_ms;
        c->have_carrier = 1;
    }
}

void xf_client_set_gnss(xf_client *c, const xf_gnss *gnss, uint32_t now_ms)
{
    if (c != NULL && gnss != NULL) {
        c->gnss = *gnss;
        c->gnss_ms = now_ms;
        c->have_gnss = 1;
    }
}

static void xf__set_ctrl(xf_client *c, uint8_t kind, float a, float b, float d, uint32_t now_ms)
{
    c->ctrl_kind = kind;
    c->ctrl[0] = a;
    c->ctrl[1] = b;
    c->ctrl[2] = d;
    c->ctrl_ms = now_ms;
    c->health.watchdog_active = 0;
}

void xf_client_set_rates(xf_client *c, float roll_dps, float pitch_dps, float yaw_dps, uint32_t now_ms)
{
    if (c != NULL) {
        xf__set_ctrl(c, XF_CTRL_RATES, roll_dps, pitch_dps, yaw_dps, now_ms);
    }
}

void xf_client_set_angles(xf_client *c, float roll_deg, float pitch_deg, float yaw_deg, uint32_t now_ms)
{
    if (c != NULL) {
        xf__set_ctrl(c, XF_CTRL_ANGLES, roll_deg, pitch_deg, yaw_deg, now_ms);
    }
}

void xf_client_clear_control(xf_client *c)
{
    if (c != NULL) {
        c->ctrl_kind = XF_CTRL_NONE;
        c->health.watchdog_active = 0;
    }
}

/* ---- commands ------------------------------------------------------------------ */

/* Check @p cmd and encode it into @p slot once: every packet then copies the bytes. */
static xf_err xf__slot_encode(xf_cmd_slot *slot, const xf_command *cmd, uint8_t version, const char **bad_field)
{
    size_t n = 0;
    xf_err err = xf_command_encode(cmd, version, slot->params, sizeof(slot->params), &n, bad_field);
    if (err != XF_OK) {
        return err;
    }
    slot->order = cmd->order;
    slot->params_len = (uint8_t)n;
    return XF_OK;
}

xf_err xf_client_submit(xf_client *c, const xf_command *cmd, uint32_t *id, const char **bad_field)
{
    xf_cmd_slot encoded, *slot;
    xf_err err;
    if (c == NULL || cmd == NULL) {
        return XF_ERR_ARG;
    }
    err = xf__slot_encode(&encoded, cmd, c->cfg.protocol_version, bad_field);
    if (err != XF_OK) {
        return err;
    }
    if (c->q_count >= XF_CLIENT_QUEUE) {
        return XF_ERR_BUSY;
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
    c->q_count++;
    return XF_OK;
}

xf_cmd_status xf_client_command_status(const xf_client *c, uint32_t id, xf_cmd_result *result)
{
    size_t i;
    if (c == NULL || id == 0u) {
        return XF_CMD_UNKNOWN;
    }
    for (i = 0; i < c->q_count; i++) {
        if (xf__queued_id(c, i) == id) {
            if (i == 0u && c->active) {
                return c->operating ? XF_CMD_OPERATING : XF_CMD_SENDING;
            }
            return XF_CMD_QUEUED;
        }
    }
    for (i = 0; i < XF_CLIENT_RESULTS; i++) {
        if (c->results[i].id == id) {
            if (result != NULL) {
                *result = c->results[i];
            }
            return (xf_cmd_status)c->results[i].status;
        }
    }
    return XF_CMD_UNKNOWN;
}

size_t xf_client_pending(const xf_client *c) { return (c == NULL) ? 0u : c->q_count; }

void xf_client_cancel_all(xf_client *c)
{
    if (c != NULL) {
        xf__fail_all(c, XF_CMD_CANCELLED);
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
    err = xf__slot_encode(&encoded, &cmd, c->cfg.protocol_version, NULL);
    if (err == XF_OK) { /* a refused call leaves a running stream as it was */
        XF_MEMCPY(c->stream, encoded.params, sizeof(c->stream));
        c->stream_on = 1;
    }
    return err;
}

xf_err xf_client_external_track_stop(xf_client *c, uint32_t *id)
{
    xf_command cmd;
    if (c == NULL) {
        return XF_ERR_ARG;
    }
    xf_command_init(&cmd, XF_ORDER_EXTERNAL_TRACK);
    if (c->stream_on) {
        cmd.cameras = c->stream[0]; /* external_track's parameters start with KK */
        /* The stream's replies (same order, with their own state) may still
         * be in flight: the exit's result must be its own. */
        c->guard_order = XF_ORDER_EXTERNAL_TRACK;
        c->guard_open = 1;
    }
    c->stream_on = 0;
    return xf_client_submit(c, &cmd, id, NULL); /* value 0: exit */
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
    u->distance_valid = (uint8_t)xf_distance_m(t->target_distance, &u->target_distance_m);
    return XF_OK;
}
xf_link_state xf_client_link(const xf_client *c) { return (c == NULL) ? XF_LINK_DOWN : (xf_link_state)c->health.link; }

const char *xf_link_state_name(xf_link_state s)
{
    switch (s) {
    case XF_LINK_UP: return "up";
    case XF_LINK_STALE: return "stale";
    default: return "down";
    }
}

const char *xf_cmd_status_name(xf_cmd_status s)
{
    switch (s) {
    case XF_CMD_QUEUED: return "queued";
    case XF_CMD_SENDING: return "sending";
    case XF_CMD_OPERATING: return "operating";
    case XF_CMD_OK: return "ok";
    case XF_CMD_FAILED: return "failed";
    case XF_CMD_TIMEOUT: return "timeout";
    case XF_CMD_LINK_LOST: return "link lost";
    case XF_CMD_CANCELLED: return "cancelled";
    default: return "unknown";
    }
}
