/*
 * xf_sim.c - a simulated GCU (see xf_sim.h). Portable C over xf_hal; uses
 * libm for the geometry of ranging and gazing.
 */
#include <math.h>
#include <string.h>

#include "xfgcu/xf_sim.h"
#include "xfgcu/xf_units.h"

#define XF_SIM_FOV_DEG   60.0f /* horizontal field of view at 1x */
#define XF_SIM_VFOV_DEG  34.0f /* vertical */
#define XF_SIM_ZOOM2_MAX 8.0f  /* thermal camera's digital zoom */
#define XF_DEG2RAD       0.017453292519943295
#define XF_M_PER_DEG     111320.0 /* metres per degree of latitude */

void xf_sim_config_init(xf_sim_config *cfg)
{
    if (cfg == NULL) {
        return;
    }
    memset(cfg, 0, sizeof(*cfg));
    cfg->version = XF_PROTOCOL_V1;
    cfg->gimbal_code = 58; /* Z-9B_V4(T): the one model of V2.0.6's support list with every order */
    cfg->hw_version = 31;  /* versions in tenths, as V2.0.6's example: 3.1 */
    cfg->fw_version = 50;  /* 5.0 */
    cfg->slew_dps = 120.0f;
    cfg->max_rate_dps = 180.0f;
    cfg->zoom_max = 30.0f;
    cfg->zoom_speed = 6.0f;
    cfg->calibration_ms = 1500;
    cfg->main_camera = 1;
    cfg->seed = 1;
}

xf_err xf_sim_init_checked(xf_sim *s, const xf_sim_config *cfg, unsigned long options, size_t size)
{
    xf_sim_config def;
    if (options != XF_OPTIONS_WORD || size != sizeof(xf_sim)) {
        return XF_ERR_CONFIG; /* the caller's xf_sim is not ours: writing to it would overrun it */
    }
    if (s == NULL) {
        return XF_ERR_ARG;
    }
    if (cfg == NULL) {
        xf_sim_config_init(&def);
        cfg = &def;
    }
    if ((cfg->version != XF_PROTOCOL_V1 && cfg->version != XF_PROTOCOL_V2) || cfg->answer_only > XF_PROTOCOL_V2) {
        return XF_ERR_RANGE;
    }
    memset(s, 0, sizeof(*s));
    s->cfg = *cfg;
    if (s->cfg.zoom_max < 1.0f) {
        s->cfg.zoom_max = 1.0f;
    }
    s->rng = (cfg->seed != 0u) ? cfg->seed : 1u;
    xf_parser_init(&s->parser, XF_DIR_HOST);
    s->mode = XF_MODE_HEAD_LOCK;
    s->zoom1 = 1.0f;
    s->zoom2 = 1.0f;
    xf_sim_set_main_camera(s, cfg->main_camera);
    s->camera_status = XF_CAMERA_OSD_ON;
    s->thermal_status = XF_THERMAL_MEASURE_AVAILABLE;
    return XF_OK;
}

xf_err xf_sim_attach(xf_sim *s, const xf_hal *hal)
{
    if (s == NULL) {
        return XF_ERR_ARG;
    }
    if (hal == NULL) {
        s->attached = 0;
        return XF_OK;
    }
    if (xf_hal_check(hal) != XF_OK) {
        return XF_ERR_ARG;
    }
    s->hal = *hal;
    s->attached = 1;
    return XF_OK;
}

void xf_sim_set_failure(xf_sim *s, uint8_t order, uint8_t state)
{
    if (s != NULL) {
        s->fail_state[order] = state;
    }
}

void xf_sim_set_main_camera(xf_sim *s, uint8_t camera)
{
    if (s != NULL) {
        s->main_camera = (camera == 2u) ? 2u : 1u;
    }
}

const char *xf_sim_question_text(xf_sim_question q)
{
    switch (q) {
    case XF_SIM_Q_LENGTH:
        return "parameter bytes not the order's length: answered failure, not read as its first bytes";
    case XF_SIM_Q_RANGE: return "a parameter outside the range of the version the simulator speaks: answered failure";
    case XF_SIM_Q_RECORD:
        return "record with a parameter other than 0x01 (the vendor's start/stop toggle): answered "
               "failure, recording unchanged";
    case XF_SIM_Q_CAMERA:
        return "an order only camera 2 takes, with a camera mask other than 0x02: answered failure "
               "0x02";
    case XF_SIM_Q_ORDER: return "an order the protocol does not define: answered failure";
    case XF_SIM_Q_NEWER: return "an order V0.2 added, to a simulator that speaks V0.1: answered failure";
    default: return "";
    }
}

static uint32_t xf__rand(xf_sim *s)
{
    s->rng ^= s->rng << 13;
    s->rng ^= s->rng >> 17;
    s->rng ^= s->rng << 5;
    return s->rng;
}

static float xf__wrap180(float d) { return (float)xf_units_wrap360((double)d, -180.0); }
static float xf__clampf(float v, float lo, float hi) { return (v < lo) ? lo : ((v > hi) ? hi : v); }

/* ---- the carrier as the host reports it ------------------------------------------- */

static int xf__ins_valid(const xf_sim *s) { return s->have_host && (s->host.main.status & XF_STATUS_INS_VALID) != 0u; }

/* The carrier's attitude: as the last packet with valid INS data gave it. A packet without (a
 * camera command sent with "no carrier data", bytes 12-29 zero) does not turn the carrier. */
static void xf__carrier(const xf_sim *s, float *roll, float *pitch, float *yaw)
{
    *roll = s->carrier[0];
    *pitch = s->carrier[1];
    *yaw = s->carrier[2];
}

static int xf__ctrl_valid(const xf_sim *s)
{
    return s->have_host && (s->host.main.status & XF_STATUS_CTRL_VALID) != 0u;
}

/* The zoom of the camera on the main screen, at least 1x. */
static float xf__main_zoom(const xf_sim *s)
{
    float z = (s->main_camera == 2u) ? s->zoom2 : s->zoom1;
    return (z >= 1.0f) ? z : 1.0f;
}

/* Control rates in deg/s: one raw unit is 0.1 deg/s divided by the main screen's zoom (V2.0.6). */
static float xf__ctrl_rate(const xf_sim *s, int16_t raw)
{
    float r = (float)raw * 0.1f / xf__main_zoom(s);
    return xf__clampf(r, -s->cfg.max_rate_dps, s->cfg.max_rate_dps);
}

/* The modes whose control quantities are desired angles. */
static int xf__angle_mode(xf_mode m) { return m == XF_MODE_ANGLE_CONTROL || m == XF_MODE_EULER || m == XF_MODE_FPV; }

/* Whether an angle mode reads the desired angle of @p axis (0 roll, 1 pitch, 2 yaw) relative to the
 * carrier (else as an Euler angle): FPV all three; angle control the yaw, and in V0.1 (V2.0.4's
 * "FPV") all three; Euler none. */
static int xf__relative_axis(const xf_sim *s, int axis)
{
    XF_ASSERT(axis >= 0 && axis < 3);
    if (s->mode == XF_MODE_FPV) {
        return 1;
    }
    return s->mode == XF_MODE_ANGLE_CONTROL && (axis == 2 || s->cfg.version < XF_PROTOCOL_V2);
}

/* An angle mode begins: its desired angles are the attitude the gimbal has, in the mode's frame,
 * until valid control quantities say otherwise. */
static void xf__want_current(xf_sim *s)
{
    float att[3], car[3];
    int i;
    att[0] = s->roll;
    att[1] = s->pitch;
    att[2] = s->yaw;
    xf__carrier(s, &car[0], &car[1], &car[2]);
    for (i = 0; i < 3; i++) {
        s->want[i] = xf__relative_axis(s, i) ? xf__wrap180(att[i] - car[i]) : att[i];
    }
}

/* ---- executing orders ---------------------------------------------------------- */

static void xf__set_bit16(uint16_t *v, uint16_t bit, int on)
{
    *v = (uint16_t)(on ? (*v | bit) : (*v & (uint16_t)~bit));
}

static void xf__set_bit8(uint8_t *v, uint8_t bit, int on) { *v = (uint8_t)(on ? (*v | bit) : (*v & (uint8_t)~bit)); }

/* zoom_to's target on a camera zooming up to max: a rate (-10 = 1x), or a
 * fraction of the range (V2.0.6: 5000 of a 30x camera is 15x). */
static float xf__zoom_to(const xf_command *c, float max)
{
    float x = (c->zoom < 0) ? (float)(-c->zoom) / 10.0f : max * (float)c->zoom / 10000.0f;
    return xf__clampf(x, 1.0f, max);
}

/* Zoom in, out, stop and to act on the cameras of the mask only. */
static void xf__zoom_order(xf_sim *s, const xf_command *c)
{
    float dir = (c->order == XF_ORDER_ZOOM_IN) ? 1.0f : (c->order == XF_ORDER_ZOOM_OUT) ? -1.0f : 0.0f;
    if (c->cameras & XF_CAM1) {
        s->zoom_dir = dir;
        s->zoom_target = (c->order == XF_ORDER_ZOOM_TO) ? xf__zoom_to(c, s->cfg.zoom_max) : 0.0f;
    }
    if (c->cameras & XF_CAM2) {
        s->zoom_dir2 = dir;
        s->zoom_target2 = (c->order == XF_ORDER_ZOOM_TO) ? xf__zoom_to(c, XF_SIM_ZOOM2_MAX) : 0.0f;
    }
}

/* Neutral: back to pitch 0 and the carrier's heading, without changing mode. */
static uint8_t xf__neutral(xf_sim *s)
{
    float cr, cp, cy;
    xf__carrier(s, &cr, &cp, &cy);
    switch (s->mode) {
    case XF_MODE_HEAD_LOCK:
    case XF_MODE_HEAD_FOLLOW:
        s->tgt[0] = 0.0f;
        s->tgt[1] = 0.0f;
        s->tgt[2] = cy;
        s->hold_yaw_offset = 0.0f;
        break;
    case XF_MODE_ORTHOVIEW:
        s->tgt[0] = 0.0f;
        s->tgt[1] = -90.0f;
        s->tgt[2] = cy;
        break;
    default: return XF_STATE_FAILURE; /* V2.0.6: no response in angle control, Euler, gaze, track and FPV */
    }
    s->have_tgt = 1;
    return XF_STATE_SUCCESS;
}

static uint8_t xf__mode_order(xf_sim *s, const xf_command *c)
{
    switch (c->order) {
    case XF_ORDER_ANGLE_CONTROL: s->mode = XF_MODE_ANGLE_CONTROL; break;
    case XF_ORDER_HEAD_LOCK: s->mode = XF_MODE_HEAD_LOCK; break;
    case XF_ORDER_HEAD_FOLLOW: {
        float cr, cp, cy;
        xf__carrier(s, &cr, &cp, &cy);
        s->hold_yaw_offset = xf__wrap180(s->yaw - cy);
        s->mode = XF_MODE_HEAD_FOLLOW;
        break;
    }
    case XF_ORDER_ORTHOVIEW: /* after head follow, yaw keeps following the carrier */
        s->ortho_follow = (s->mode == XF_MODE_HEAD_FOLLOW);
        s->mode = XF_MODE_ORTHOVIEW;
        break;
    case XF_ORDER_EULER: s->mode = XF_MODE_EULER; break;
    case XF_ORDER_FPV: s->mode = XF_MODE_FPV; break;
    case XF_ORDER_GAZE_GEO:
    case XF_ORDER_GAZE_LOCK:
        if (!xf__ins_valid(s)) {
            return XF_STATE_FAILURE; /* needs valid carrier INS data */
        }
        s->gaze_lat = (float)xf_deg7(c->latitude);
        s->gaze_lon = (float)xf_deg7(c->longitude);
        s->gaze_alt = (float)c->altitude / 1000.0f;
        if (c->order == XF_ORDER_GAZE_LOCK) {
            s->gaze_lat = 0.0f; /* hold the current line of sight */
            s->gaze_lon = 0.0f;
        }
        s->mode = XF_MODE_GAZE;
        break;
    default: return XF_STATE_FAILURE;
    }
    s->have_tgt = 0;
    if (xf__angle_mode(s->mode)) {
        xf__want_current(s);
    }
    return XF_STATE_SUCCESS;
}

static uint8_t xf__track_order(xf_sim *s, const xf_command *c)
{
    if (c->order == XF_ORDER_TRACK) {
        if (c->value == 0u) {
            xf__set_bit16(&s->pod_status, XF_POD_TRACKING_OK, 0);
            s->mode = XF_MODE_HEAD_LOCK;
            return XF_STATE_SUCCESS;
        }
        s->track_x = (int16_t)((((int32_t)c->x0 + (int32_t)c->x1) / 2 - 5000) / 5);
        s->track_y = (int16_t)((((int32_t)c->y0 + (int32_t)c->y1) / 2 - 5000) / 5);
    } else { /* external track: offsets given by an outside tracker, every packet */
        if (c->value == 0u) {
            xf__set_bit16(&s->pod_status, XF_POD_TRACKING_OK, 0);
            s->mode = XF_MODE_HEAD_LOCK;
            return XF_STATE_SUCCESS;
        }
        if (c->dx >= XF_EXT_TRACK_LOST && c->dy >= XF_EXT_TRACK_LOST) {
            xf__set_bit16(&s->pod_status, XF_POD_TRACKING_OK, 0);
            return XF_STATE_SUCCESS;
        }
        s->track_x = (int16_t)((int32_t)c->dx * 1000 / 1024);
        s->track_y = (int16_t)((int32_t)c->dy * 1000 / 1024);
    }
    s->mode = XF_MODE_TRACK;
    xf__set_bit16(&s->pod_status, XF_POD_TRACKING_OK, 1);
    return XF_STATE_SUCCESS;
}

static uint8_t xf__camera_order(xf_sim *s, const xf_command *c)
{
    switch (c->order) {
    case XF_ORDER_SHUTTER: s->stats.photos++; break;
    case XF_ORDER_RECORD:
        xf__set_bit16(&s->camera_status, XF_CAMERA_RECORDING, (s->camera_status & XF_CAMERA_RECORDING) == 0u);
        if (s->camera_status & XF_CAMERA_RECORDING) {
            s->stats.recordings++;
        }
        break;
    case XF_ORDER_ZOOM_IN:
    case XF_ORDER_ZOOM_OUT:
    case XF_ORDER_ZOOM_STOP:
    case XF_ORDER_ZOOM_TO: xf__zoom_order(s, c); break;
    case XF_ORDER_FOCUS:
    case XF_ORDER_PALETTE: break;
    case XF_ORDER_NIGHT_VISION: xf__set_bit16(&s->pod_status, XF_POD_NIGHT_VISION_ON, c->value != 0u); break;
    case XF_ORDER_LIGHTING:
        s->lighting = c->value;
        xf__set_bit16(&s->pod_status, XF_POD_LIGHTING_ON, c->value != 0u);
        if (c->value != 0u) {
            xf__set_bit16(&s->pod_status, XF_POD_NIGHT_VISION_ON, 1); /* light on turns night vision on, not off */
        }
        break;
    case XF_ORDER_RANGING: xf__set_bit16(&s->pod_status, XF_POD_RANGING_ON, c->value == 2u); break;
    case XF_ORDER_OSD: /* the meaning of TT follows the version the simulator speaks */
        xf__set_bit16(&s->camera_status, XF_CAMERA_OSD_ON, c->value == xf_osd_value(1, s->cfg.version));
        break;
    case XF_ORDER_PIP: {
        uint16_t pip = (uint16_t)(c->value != 0u ? c->value : ((s->camera_status & XF_CAMERA_PIP_MASK) % 4u) + 1u);
        s->camera_status = (uint16_t)((s->camera_status & (uint16_t)~XF_CAMERA_PIP_MASK) | pip);
        break;
    }
    case XF_ORDER_OSD_COORDINATE: xf__set_bit16(&s->camera_status, XF_CAMERA_OSD_TARGET, c->value == 1u); break;
    case XF_ORDER_AUTO_FLIP: xf__set_bit16(&s->camera_status, XF_CAMERA_AUTO_FLIP_OFF, c->value == 1u); break;
    case XF_ORDER_TIME_ZONE: s->time_zone = c->hours; break;
    case XF_ORDER_AREA_TEMP: xf__set_bit8(&s->thermal_status, XF_THERMAL_AREA_ON, c->value == 1u); break;
    case XF_ORDER_TEMP_ALARM: xf__set_bit8(&s->thermal_status, XF_THERMAL_ALARM_ON, c->value == 1u); break;
    case XF_ORDER_ISOTHERM: xf__set_bit8(&s->thermal_status, XF_THERMAL_ISOTHERM_ON, c->value == 1u); break;
    case XF_ORDER_SPOT_TEMP: xf__set_bit8(&s->thermal_status, XF_THERMAL_SPOT_ON, c->value == 1u); break;
    case XF_ORDER_TARGET_DETECTION: xf__set_bit16(&s->camera_status, XF_CAMERA_DETECTION_ON, c->value == 1u); break;
    case XF_ORDER_DIGITAL_ZOOM: xf__set_bit16(&s->camera_status, XF_CAMERA_DIGITAL_ZOOM_ON, c->value == 1u); break;
    default: return XF_STATE_FAILURE;
    }
    return XF_STATE_SUCCESS;
}

static uint8_t xf__click_to_aim(xf_sim *s, const xf_command *c)
{
    float fov = XF_SIM_FOV_DEG / xf__main_zoom(s), vfov = XF_SIM_VFOV_DEG / xf__main_zoom(s);
    s->tgt[0] = s->roll;
    s->tgt[1] = xf__clampf(s->pitch - ((float)c->y0 / 10000.0f - 0.5f) * vfov, -90.0f, 90.0f);
    s->tgt[2] = s->yaw + ((float)c->x0 / 10000.0f - 0.5f) * fov;
    s->have_tgt = 1;
    s->mode = XF_MODE_HEAD_LOCK; /* V2.0.6: the gimbal aims, then it is in head lock */
    return XF_STATE_SUCCESS;
}

/* An order only camera 2 (the thermal camera) takes: V2.0.6 prints its parameter as 0x02 and its
 * failure as 0x02 (palette and the four thermometry orders). */
static int xf__camera2_order(const xf_order_info *info)
{
    return info != NULL && (info->flags & XF_ORDER_MASK_FAILURE) != 0u && info->default_cameras == XF_CAM2;
}

/* The state a failure of @p order answers (V2.0.6): 0x01; for an NN order the mask of the cameras
 * asked (@p cameras, 0 when the parameters could not be read: the order's default); 0x02 for an
 * order only camera 2 takes, whatever was asked. */
static uint8_t xf__failure(uint8_t order, uint8_t cameras)
{
    const xf_order_info *info = xf_order_lookup(order);
    if (info == NULL || (info->flags & XF_ORDER_MASK_FAILURE) == 0u) {
        return XF_STATE_FAILURE;
    }
    if (xf__camera2_order(info)) {
        return XF_CAM2;
    }
    return (cameras != 0u) ? cameras : info->default_cameras;
}

/* The open question a packet raises, given what decoding it (in the simulator's version @p version)
 * gave: 0 when it raises none. An order a later version added is as unknown to this GCU as one no
 * version defines. A record parameter or a camera-2 order's mask is checked before the range,
 * which also refuses a mask of 0. */
static xf_sim_question xf__question(const xf_host_packet *p, uint8_t version, xf_err decoded)
{
    const xf_order_info *info = xf_order_lookup(p->order);
    if (decoded == XF_ERR_NOT_FOUND) {
        return XF_SIM_Q_ORDER;
    }
    if (info != NULL && info->since > version) {
        return XF_SIM_Q_NEWER;
    }
    if (decoded == XF_ERR_PARAMS) {
        return XF_SIM_Q_LENGTH;
    }
    if (p->order == XF_ORDER_RECORD && p->params[0] != XF_CAM1) {
        return XF_SIM_Q_RECORD;
    }
    if (xf__camera2_order(info) && p->params[0] != XF_CAM2) {
        return XF_SIM_Q_CAMERA;
    }
    return (decoded != XF_OK) ? XF_SIM_Q_RANGE : (xf_sim_question)0;
}

/* Answer @p p by the strict reading of question @p q: a failure, counted and told to on_note. */
static uint8_t xf__strict(xf_sim *s, const xf_host_packet *p, xf_sim_question q)
{
    xf_sim_note note;
    note.question = q;
    note.order = p->order;
    note.state = xf__failure(p->order, 0u);
    note.params_len = p->params_len;
    note.param0 = (p->params_len > 0u) ? p->params[0] : 0u;
    note.text = xf_sim_question_text(q);
    s->stats.strict++;
    if (s->cfg.on_note != NULL) {
        s->cfg.on_note(s->cfg.user, &note);
    }
    return note.state;
}

/* Run one order, read in the simulator's own version (the host's version byte says what the host
 * speaks, not what the GCU understands); returns its execution state. */
static uint8_t xf__execute(xf_sim *s, const xf_host_packet *p)
{
    xf_command c;
    xf_sim_question q;
    s->stats.executed[p->order]++;
    q = xf__question(p, s->cfg.version,
                     xf_command_decode(p->order, p->params, p->params_len, s->cfg.version, &c, NULL));
    if (q != 0) {
        return xf__strict(s, p, q);
    }
    if (s->fail_state[p->order] != 0u) {
        return s->fail_state[p->order];
    }
    if (xf_gimbal_supports(s->cfg.gimbal_code, p->order) == XF_SUPPORT_NO) {
        return xf__failure(p->order, c.cameras); /* the model has no such function (V2.0.6's support list) */
    }
    switch (p->order) {
    case XF_ORDER_CALIBRATION:
        s->calibrating = 1;
        s->calibration_end_ms = s->now_ms + s->cfg.calibration_ms;
        return XF_STATE_OPERATING;
    case XF_ORDER_NEUTRAL: return xf__neutral(s);
    case XF_ORDER_TRACK:
    case XF_ORDER_EXTERNAL_TRACK: return xf__track_order(s, &c);
    case XF_ORDER_CLICK_TO_AIM: return xf__click_to_aim(s, &c);
    default: break;
    }
    {
        const xf_order_info *info = xf_order_lookup(p->order);
        if (info != NULL && (info->flags & XF_ORDER_SETS_MODE) != 0u) {
            return xf__mode_order(s, &c);
        }
    }
    return xf__camera_order(s, &c);
}

/* ---- motion -------------------------------------------------------------------- */

static float xf__slew(float from, float to, float max_step, int wrap)
{
    float d = wrap ? xf__wrap180(to - from) : (to - from);
    return from + xf__clampf(d, -max_step, max_step);
}

/* Bearing and elevation from the carrier to the gaze point (flat earth, short range). */
static int xf__gaze_angles(const xf_sim *s, float *pitch, float *yaw)
{
    const xf_host_sub *h = &s->host.sub;
    double lat, lon, north, east, up, horiz;
    if (h->sub_header != XF_SUB_HEADER || (s->gaze_lat == 0.0f && s->gaze_lon == 0.0f)) {
        return 0;
    }
    lat = xf_deg7(h->latitude);
    lon = xf_deg7(h->longitude);
    north = ((double)s->gaze_lat - lat) * XF_M_PER_DEG;
    east = ((double)s->gaze_lon - lon) * XF_M_PER_DEG * cos(lat * XF_DEG2RAD);
    up = (double)s->gaze_alt - (double)h->altitude / 1000.0;
    horiz = sqrt(north * north + east * east);
    *yaw = (float)(atan2(east, north) / XF_DEG2RAD);
    *pitch = (float)(atan2(up, horiz) / XF_DEG2RAD);
    return 1;
}

/* An angle mode (Euler, angle control, FPV): slew to the desired angles, which valid control
 * quantities @p a set and which hold their value while the quantities are invalid (@p a NULL;
 * V2.0.6, status byte B2). A relative angle is kept as the carrier turns. */
static void xf__move_angles(xf_sim *s, const float *a, float slew)
{
    float car[3], to[3];
    int i;
    xf__carrier(s, &car[0], &car[1], &car[2]);
    for (i = 0; i < 3; i++) {
        if (a != NULL) {
            s->want[i] = a[i];
        }
        to[i] = xf__relative_axis(s, i) ? car[i] + s->want[i] : s->want[i];
    }
    s->roll = xf__slew(s->roll, to[0], slew, 0);
    s->pitch = xf__slew(s->pitch, to[1], slew, 0);
    s->yaw = xf__slew(s->yaw, to[2], slew, 1);
}

static void xf__move(xf_sim *s, float dt)
{
    float cr, cp, cy, slew = s->cfg.slew_dps * dt;
    float r[3] = {0.0f, 0.0f, 0.0f}, a[3] = {0.0f, 0.0f, 0.0f};
    int ctrl = xf__ctrl_valid(s);
    xf__carrier(s, &cr, &cp, &cy);
    if (ctrl) {
        r[0] = xf__ctrl_rate(s, s->host.main.roll_ctrl);
        r[1] = xf__ctrl_rate(s, s->host.main.pitch_ctrl);
        r[2] = xf__ctrl_rate(s, s->host.main.yaw_ctrl);
        a[0] = xf_cdeg(s->host.main.roll_ctrl);
        a[1] = xf_cdeg(s->host.main.pitch_ctrl);
        a[2] = xf_cdeg(s->host.main.yaw_ctrl);
    }
    if (s->have_tgt && (r[1] != 0.0f || r[2] != 0.0f) &&
        (s->mode == XF_MODE_HEAD_LOCK || s->mode == XF_MODE_HEAD_FOLLOW)) {
        s->have_tgt = 0; /* the operator takes over */
    }
    if (s->have_tgt) {
        s->roll = xf__slew(s->roll, s->tgt[0], slew, 0);
        s->pitch = xf__slew(s->pitch, s->tgt[1], slew, 0);
        s->yaw = xf__slew(s->yaw, s->tgt[2], slew, 1);
        if (fabsf(s->pitch - s->tgt[1]) < 0.01f && fabsf(xf__wrap180(s->yaw - s->tgt[2])) < 0.01f) {
            s->have_tgt = 0;
            if (s->mode == XF_MODE_HEAD_FOLLOW) {
                s->hold_yaw_offset = xf__wrap180(s->yaw - cy);
            }
        }
        return;
    }
    switch (s->mode) {
    case XF_MODE_HEAD_LOCK: /* rates; at 0 the Euler angles hold */
        s->roll = xf__slew(s->roll, 0.0f, slew, 0);
        s->pitch += r[1] * dt;
        s->yaw += r[2] * dt;
        break;
    case XF_MODE_HEAD_FOLLOW: /* pitch rate; yaw follows the carrier, offset by the yaw rate */
        s->roll = xf__slew(s->roll, 0.0f, slew, 0);
        s->pitch += r[1] * dt;
        s->hold_yaw_offset += r[2] * dt;
        s->yaw = xf__slew(s->yaw, cy + s->hold_yaw_offset, slew, 1);
        break;
    case XF_MODE_ORTHOVIEW: /* pitch locked at -90, yaw controllable; after head follow it follows the carrier */
        s->roll = xf__slew(s->roll, 0.0f, slew, 0);
        s->pitch = xf__slew(s->pitch, -90.0f, slew, 0);
        if (s->ortho_follow) {
            s->hold_yaw_offset += r[2] * dt;
            s->yaw = xf__slew(s->yaw, cy + s->hold_yaw_offset, slew, 1);
        } else {
            s->yaw += r[2] * dt;
        }
        break;
    case XF_MODE_EULER:
    case XF_MODE_ANGLE_CONTROL:
    case XF_MODE_FPV: xf__move_angles(s, ctrl ? a : NULL, slew); break;
    case XF_MODE_GAZE: {
        float gp, gy;
        if (r[1] != 0.0f || r[2] != 0.0f) {
            s->gaze_lat = 0.0f; /* V2.0.6: a valid non-zero quantity turns gaze-geo into gaze lock */
            s->gaze_lon = 0.0f;
        }
        if (xf__gaze_angles(s, &gp, &gy)) {
            s->pitch = xf__slew(s->pitch, gp, slew, 0);
            s->yaw = xf__slew(s->yaw, gy, slew, 1);
        } else { /* gaze lock: rates move the aim point, else it holds */
            s->pitch += r[1] * dt;
            s->yaw += r[2] * dt;
        }
        break;
    }
    case XF_MODE_TRACK: { /* the image processor centres the target */
        float k = xf__clampf(3.0f * dt, 0.0f, 1.0f);
        float fov = XF_SIM_FOV_DEG / xf__main_zoom(s);
        if (s->pod_status & XF_POD_TRACKING_OK) {
            s->yaw += (float)s->track_x / 1000.0f * fov * 0.5f * k;
            s->pitch -= (float)s->track_y / 1000.0f * fov * 0.5f * k;
            s->track_x = (int16_t)((float)s->track_x * (1.0f - k));
            s->track_y = (int16_t)((float)s->track_y * (1.0f - k));
        }
        break;
    }
    default: break;
    }
}

/* One camera's zoom: a continuous direction, or a slew to a zoom_to target. */
static void xf__zoom_camera(float *zoom, float dir, float *target, float step, float max)
{
    if (dir != 0.0f) {
        *zoom = xf__clampf(*zoom + dir * step, 1.0f, max);
    } else if (*target > 0.0f) {
        *zoom = xf__slew(*zoom, *target, step, 0);
        if (*zoom == *target) {
            *target = 0.0f;
        }
    }
}

static void xf__zoom(xf_sim *s, float dt)
{
    float step = s->cfg.zoom_speed * dt;
    xf__zoom_camera(&s->zoom1, s->zoom_dir, &s->zoom_target, step, s->cfg.zoom_max);
    xf__zoom_camera(&s->zoom2, s->zoom_dir2, &s->zoom_target2, step * 0.25f, XF_SIM_ZOOM2_MAX);
}

static void xf__range(xf_sim *s)
{
    int on = (s->pod_status & XF_POD_RANGING_ON) != 0u;
    if (on) {
        double h =
            (s->have_host && s->host.sub.relative_height > 0) ? (double)s->host.sub.relative_height / 1000.0 : 120.0;
        double d = (s->pitch < -3.0f) ? h / sin(-(double)s->pitch * XF_DEG2RAD) : 1500.0;
        s->distance_m = (float)((d > 3000.0) ? 3000.0 : d);
    }
    xf__set_bit16(&s->pod_status, XF_POD_TARGET_VALID, on);
}

static void xf__integrate(xf_sim *s, float dt)
{
    float before[3];
    int i;
    before[0] = s->roll;
    before[1] = s->pitch;
    before[2] = s->yaw;
    xf__move(s, dt);
    s->pitch = xf__clampf(s->pitch, -90.0f, 90.0f);
    s->roll = xf__clampf(s->roll, -90.0f, 90.0f);
    s->yaw = (float)xf_units_wrap360((double)s->yaw, 0.0);
    for (i = 0; i < 3; i++) {
        float d = (i == 2) ? xf__wrap180(s->yaw - before[2]) : (i == 1 ? s->pitch - before[1] : s->roll - before[0]);
        s->rate[i] = (dt > 0.0f) ? d / dt : 0.0f;
    }
    xf__zoom(s, dt);
    xf__range(s);
}

/* ---- replies ------------------------------------------------------------------- */

void xf_sim_snapshot(const xf_sim *s, xf_gcu_packet *pkt)
{
    float cr, cp, cy;
    uint8_t v;
    if (s == NULL || pkt == NULL) {
        return;
    }
    v = s->cfg.version;
    xf__carrier(s, &cr, &cp, &cy);
    memset(pkt, 0, sizeof(*pkt));
    pkt->version = v;
    pkt->main.gimbal_mode = (uint8_t)s->mode;
    pkt->main.pod_status = s->pod_status;
    pkt->main.target_offset_x = (s->mode == XF_MODE_TRACK) ? s->track_x : 0;
    pkt->main.target_offset_y = (s->mode == XF_MODE_TRACK) ? s->track_y : 0;
    pkt->main.rel_angle_x = xf_ctrl_angle_raw(-xf__wrap180(s->pitch - cp)); /* appendix 3: pitch = -X */
    pkt->main.rel_angle_y = xf_ctrl_angle_raw(xf__wrap180(s->roll - cr));   /* roll = +Y */
    pkt->main.rel_angle_z = xf_ctrl_angle_raw(xf__wrap180(s->yaw - cy));
    pkt->main.cam_roll = xf_carrier_pitch_raw(s->roll); /* [-90, 90] */
    pkt->main.cam_pitch = xf_ctrl_angle_raw(s->pitch);
    pkt->main.cam_yaw = xf_carrier_yaw_raw(s->yaw);
    pkt->main.rate_x = xf_gcu_rate_raw(-s->rate[1], v);
    pkt->main.rate_y = xf_gcu_rate_raw(s->rate[0], v);
    pkt->main.rate_z = xf_gcu_rate_raw(s->rate[2], v);
    if (!s->have_host || s->host.main.sub_request != XF_SUB_HEADER) {
        return; /* an unknown sub frame request: bytes 37-68 all zero */
    }
    pkt->sub.sub_header = XF_SUB_HEADER;
    pkt->sub.hw_version = s->cfg.hw_version;
    pkt->sub.fw_version = s->cfg.fw_version;
    pkt->sub.gimbal_code = s->cfg.gimbal_code;
    pkt->sub.zoom_cam1 = xf_zoom_raw(s->zoom1);
    pkt->sub.zoom_cam2 = xf_zoom_raw(s->zoom2);
    if (s->pod_status & XF_POD_TARGET_VALID) {
        const xf_host_sub *h = &s->host.sub;
        double horiz = (double)s->distance_m * cos((double)s->pitch * XF_DEG2RAD);
        double lat = xf_deg7(h->latitude);
        pkt->sub.target_distance = (int32_t)(s->distance_m * 10.0f + 0.5f);
        pkt->sub.target_latitude = xf_deg7_raw(lat + horiz * cos((double)s->yaw * XF_DEG2RAD) / XF_M_PER_DEG);
        pkt->sub.target_longitude = xf_deg7_raw(xf_deg7(h->longitude) + horiz * sin((double)s->yaw * XF_DEG2RAD) /
                                                                            (XF_M_PER_DEG * cos(lat * XF_DEG2RAD)));
        pkt->sub.target_altitude = h->altitude + xf_mm_raw((double)s->distance_m * sin((double)s->pitch * XF_DEG2RAD));
    } else {
        pkt->sub.target_distance = XF_DISTANCE_INVALID_RAW;
    }
    if (v >= XF_PROTOCOL_V2) {
        pkt->sub.thermal_status = s->thermal_status;
        pkt->sub.camera_status = s->camera_status;
        pkt->sub.time_zone = s->time_zone;
    }
}

static void xf__write_reply(xf_sim *s, const uint8_t *bytes, size_t len)
{
    XF_ASSERT(s->cap_buf == NULL || s->cap_len <= s->cap_cap);
    if (s->cap_buf != NULL) {
        if (s->cap_len + len <= s->cap_cap) {
            memcpy(s->cap_buf + s->cap_len, bytes, len);
            s->cap_len += len;
            s->stats.replies++;
        } else {
            s->stats.write_errors++;
        }
        return;
    }
    if (s->attached && s->hal.write(s->hal.ctx, bytes, len) == XF_OK) {
        s->stats.replies++;
    } else {
        s->stats.write_errors++;
    }
}

static int xf__chance(xf_sim *s, uint16_t permille) { return permille > 0u && (xf__rand(s) % 1000u) < permille; }

/* Keep @p bytes until @p due_ms, behind every packet due no later (the queue stays in due order). */
static void xf__hold(xf_sim *s, const uint8_t *bytes, size_t len, uint8_t to_gcu, uint32_t due_ms)
{
    xf_sim_delayed *d;
    uint16_t i = s->n_delayed;
    if (s->n_delayed >= XF_SIM_DELAY_QUEUE || len > sizeof(d->bytes)) {
        s->stats.dropped++; /* a host packet dropped on the way in is counted here too */
        return;
    }
    while (i > 0u && (int32_t)(s->delayed[i - 1u].due_ms - due_ms) > 0) {
        i--;
    }
    memmove(&s->delayed[i + 1u], &s->delayed[i], (size_t)(s->n_delayed - i) * sizeof(s->delayed[0]));
    d = &s->delayed[i];
    d->due_ms = due_ms;
    d->len = (uint8_t)len;
    d->to_gcu = to_gcu;
    memcpy(d->bytes, bytes, len);
    s->n_delayed++;
    s->n_held_in = (uint16_t)(s->n_held_in + to_gcu);
}

/* How many copies of a packet arrive: two with the duplicate fault. */
static int xf__copies(xf_sim *s) { return 1 + xf__chance(s, s->fault.dup_permille); }

/* When one copy is due: after @p delay and its own draw of the jitter. */
static uint32_t xf__due(xf_sim *s, uint32_t delay)
{
    return s->now_ms + delay + ((s->fault.jitter_ms > 0u) ? xf__rand(s) % (s->fault.jitter_ms + 1u) : 0u);
}

/* Whether a copy due at @p due waits in the queue: it is due later, or another of its direction
 * waits (the queue is in due order: a packet due now does not overtake one of its direction that
 * is due already; one held for later, by jitter, it may, as on a network). Replies held by the
 * delay never hold back a host packet. xf_sim_process() has no later: it never holds. */
static int xf__waits(const xf_sim *s, uint32_t due, uint8_t to_gcu)
{
    unsigned same = to_gcu ? s->n_held_in : (unsigned)(s->n_delayed - s->n_held_in);
    return s->cap_buf == NULL && (due != s->now_ms || same > 0u);
}

static void xf__on_packet(xf_sim *s, const xf_host_packet *p);

static void xf__release_delayed(xf_sim *s)
{
    while (s->n_delayed > 0u && (int32_t)(s->now_ms - s->delayed[0].due_ms) >= 0) {
        xf_sim_delayed d = s->delayed[0];
        XF_ASSERT(d.len <= sizeof(d.bytes) && s->n_held_in >= d.to_gcu); /* as xf__hold() kept it */
        s->n_delayed--;
        s->n_held_in = (uint16_t)(s->n_held_in - d.to_gcu);
        memmove(&s->delayed[0], &s->delayed[1], (size_t)s->n_delayed * sizeof(s->delayed[0]));
        if (d.to_gcu) {
            xf_host_packet p;
            if (xf_host_unpack(d.bytes, d.len, &p) == XF_OK) {
                xf__on_packet(s, &p); /* its reply may join the queue: d is a copy */
            }
        } else {
            xf__write_reply(s, d.bytes, d.len);
        }
    }
}

/* Faults, then the link (now or later). */
static void xf__send_reply(xf_sim *s, uint8_t *bytes, size_t len)
{
    int copies;
    if (s->fault.silent) {
        return;
    }
    if (s->fault.drop_next > 0u || xf__chance(s, s->fault.drop_permille)) {
        if (s->fault.drop_next > 0u) {
            s->fault.drop_next--;
        }
        s->stats.dropped++;
        return;
    }
    if (s->fault.corrupt_next > 0u || xf__chance(s, s->fault.corrupt_permille)) {
        if (s->fault.corrupt_next > 0u) {
            s->fault.corrupt_next--;
        }
        bytes[5u + xf__rand(s) % (len - 7u)] ^= 0x5Au; /* inside the frames: only the CRC can tell */
        s->stats.corrupted++;
    }
    for (copies = xf__copies(s); copies > 0; copies--) { /* jitter and duplicates; replies wait delay_ms */
        uint32_t due = xf__due(s, s->fault.delay_ms);
        if (xf__waits(s, due, 0u)) {
            xf__hold(s, bytes, len, 0u, due);
        } else {
            xf__write_reply(s, bytes, len);
        }
    }
}

/* The state byte this reply carries for the last executed order, if any. */
static int xf__feedback_byte(xf_sim *s, uint8_t order, uint8_t *state)
{
    if (!s->fb_valid || s->fb_order != order) {
        return 0;
    }
    if (s->fb_pending_replies > 0u) {
        s->fb_pending_replies--;
        return 0;
    }
    if (s->cfg.state_once && s->fb_sent) {
        return 0;
    }
    if (order == XF_ORDER_CALIBRATION && s->calibrating) {
        if ((int32_t)(s->now_ms - s->calibration_end_ms) < 0) {
            *state = XF_STATE_OPERATING;
            return 1; /* "operating" is not the final state: keep it repeatable */
        }
        s->calibrating = 0;
        s->fb_state = s->fail_state[order] != 0u ? s->fail_state[order] : XF_STATE_SUCCESS;
    }
    *state = s->fb_state;
    s->fb_sent = 1;
    return 1;
}

static void xf__on_packet(xf_sim *s, const xf_host_packet *p)
{
    xf_gcu_packet r;
    uint8_t buf[XF_PACKET_MAX_LEN];
    size_t len = 0;
    uint8_t state = 0;
    int runs;
    if (s->cfg.answer_only != 0u && p->version != s->cfg.answer_only) {
        s->stats.ignored++; /* as if it had not come: no reply, nothing read from it */
        return;
    }
    s->stats.packets_in++;
    if (p->main.status & XF_STATUS_INS_VALID) {
        s->stats.ins_valid_packets++;
        s->carrier[0] = xf_cdeg(p->main.carrier_roll);
        s->carrier[1] = xf_cdeg(p->main.carrier_pitch);
        s->carrier[2] = xf_cdeg(p->main.carrier_yaw);
    }
    s->host = *p;
    s->have_host = 1;
    /* The once-rule: an order runs when it differs from the previous packet's. */
    runs = p->order != XF_ORDER_NULL &&
           (!s->have_last_order || p->order != s->last_order || p->order == XF_ORDER_EXTERNAL_TRACK);
    s->last_order = p->order;
    s->have_last_order = 1;
    if (runs) {
        s->fb_order = p->order;
        s->fb_state = xf__execute(s, p);
        s->fb_valid = 1;
        s->fb_sent = 0;
        s->fb_pending_replies = (uint8_t)((s->cfg.feedback_after > 255u) ? 255u : s->cfg.feedback_after);
    }
    xf_sim_snapshot(s, &r);
    r.order = p->order;
    if (p->order != XF_ORDER_NULL && xf__feedback_byte(s, p->order, &state)) {
        r.params[0] = state;
        r.params_len = 1;
    }
    if (xf_gcu_pack(&r, buf, sizeof(buf), &len) == XF_OK) {
        xf__send_reply(s, buf, len);
    }
}

/* A host packet in: now, or (jitter, duplicates) each copy when it is due. */
static void xf__arrive(xf_sim *s, const xf_frame *f)
{
    int copies;
    for (copies = xf__copies(s); copies > 0; copies--) {
        uint32_t due = xf__due(s, 0u);
        xf_host_packet p;
        if (xf__waits(s, due, 1u)) {
            xf__hold(s, f->data, f->len, 1u, due);
        } else if (xf_frame_host(f, &p) == XF_OK) {
            xf__on_packet(s, &p);
        }
    }
}

static void xf__feed(xf_sim *s, const uint8_t *data, size_t n)
{
    size_t off = 0;
    XF_ASSERT(data != NULL || n == 0u); /* xf_sim_process() refused NULL with a length */
    for (;;) {
        size_t used = 0;
        xf_frame f;
        xf_parse_status r = xf_parser_feed(&s->parser, data + off, n - off, &used, &f);
        off += used;
        if (r != XF_PARSE_FRAME) {
            break;
        }
        xf__arrive(s, &f);
    }
}

static void xf__advance(xf_sim *s, uint32_t now_ms)
{
    uint32_t dt_ms;
    s->now_ms = now_ms;
    if (!s->started) {
        s->started = 1;
        s->last_step_ms = now_ms;
    }
    dt_ms = xf_ms_since(now_ms, s->last_step_ms);
    if (dt_ms > 0u) {
        xf__integrate(s, (float)((dt_ms > 200u) ? 200u : dt_ms) / 1000.0f);
        s->last_step_ms = now_ms;
    }
}

xf_err xf_sim_step(xf_sim *s, uint32_t now_ms)
{
    uint8_t buf[512];
    int i;
    if (s == NULL) {
        return XF_ERR_ARG;
    }
    xf__advance(s, now_ms);
    if (!s->attached) {
        return XF_OK;
    }
    for (i = 0; i < 16; i++) {
        size_t n = 0;
        xf_err err = xf_hal_read(&s->hal, buf, sizeof(buf), &n);
        if (err == XF_ERR_CLOSED && s->n_delayed > 0u) {
            /* the host went away: what was on the wire goes with it, never to the next host */
            s->stats.dropped += s->n_delayed;
            s->n_delayed = 0;
            s->n_held_in = 0;
        }
        if (err != XF_OK) {
            return err;
        }
        if (n == 0u) {
            break;
        }
        xf__feed(s, buf, n);
    }
    xf__release_delayed(s);
    return XF_OK;
}

xf_err xf_sim_process(xf_sim *s, const uint8_t *in, size_t len, uint32_t now_ms, uint8_t *out, size_t cap,
                      size_t *out_len)
{
    if (s == NULL || (in == NULL && len > 0u) || (out == NULL && cap > 0u)) {
        return XF_ERR_ARG;
    }
    xf__advance(s, now_ms);
    s->cap_buf = out;
    s->cap_cap = cap;
    s->cap_len = 0;
    xf__feed(s, in, len);
    if (out_len != NULL) {
        *out_len = s->cap_len;
    }
    s->cap_buf = NULL;
    return (s->stats.write_errors > 0u && s->cap_len == 0u && len > 0u) ? XF_ERR_NO_SPACE : XF_OK;
}
