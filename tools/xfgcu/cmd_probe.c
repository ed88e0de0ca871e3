/*
 * cmd_probe.c - `xfgcu [LINK] probe [--move] [--json] [--window S]`.
 *
 * What a real gimbal is and does, for a person at a bench or a bug report:
 * its model, versions, the protocol version it answers in, the byte order
 * of its pod status word, the reply rate, the round-trip time, and how it
 * answers a set of orders chosen so that nothing moves and no setting is
 * left changed (docs/cli.md "probe" lists each order and why it is safe):
 * orders that leave things as they are (zoom stop, zoom to the reported
 * zoom, one autofocus, exiting a tracking that is not on) and orders that
 * set a state the GCU reports to the value it reports. Every answer is put
 * beside what V2.0.6's support list says of the model (xf_gimbal_supports()),
 * and disagreements are flagged. Then it asks the open questions of
 * docs/protocol.md section 12 that a gimbal can answer without moving or
 * changing a setting (probe_ask.c), and lists the others with the reason. With --move it also switches to head lock,
 * runs neutral, switches to Euler angle control, points back to where the
 * gimbal was, 5 degrees away and back, then restores the starting mode.
 *
 * Exit: 0 when the probe completed (whatever the GCU answered), 2 usage,
 * 3 no GCU, or the link lost or an interruption during the probe (what was
 * learnt is printed first).
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, gmtime_r */

#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "cmdargs.h"
#include "hexin.h"
#include "jsonpkt.h"
#include "table.h"
#include "online.h"
#include "probe_ask.h"

#define PROBE_MAX     40     /* orders in the report: planned, sent or not */
#define LEGS_MAX      4      /* motions of --move */
#define NULLS_AFTER   3u     /* null packets after the last command, before closing */
#define TOLERANCE_DEG 0.5    /* a point is reached within this */
#define STEP_DEG      5.0    /* --move's small point */
#define POINT_MS      10000u /* how long a point may take */
#define SETTLE_MS     5000u  /* how long neutral may take to come to rest */
#define STILL_MS      300u   /* at rest: the attitude moved less than STILL_DEG for this long */
#define STILL_DEG     0.1

XF_STATIC_ASSERT(PROBE_MAX >= XF_ORDER_COUNT, probe_reports_every_order);

void help_probe(FILE *out)
{
    fputs("usage: xfgcu [LINK OPTIONS] probe [--move] [--json] [--window S]\n\n"
          "Find out what the gimbal on the link is and how it answers, safely: its model, hardware and\n"
          "firmware versions, the protocol version it answers in, the byte order of its pod status\n"
          "word, its reply rate and round-trip time, and which orders it answers with success,\n"
          "failure (with the failed cameras) or nothing, compared with the vendor's V2.0.6 support\n"
          "list for its model. Without --move nothing moves and no setting is changed: the orders\n"
          "sent either change nothing (zoom stop, zoom to the reported zoom, one autofocus, exit a\n"
          "tracking that is not on) or set a state the GCU reports to the value it reports. Then it\n"
          "asks the open questions of docs/protocol.md section 12 that a gimbal can answer without\n"
          "moving (does it answer both version bytes, repeat the execution state, take a parameter\n"
          "of the wrong length on a zoom stop...) and lists the others with why not.\n\n"
          "  --move        also switch to head lock, run neutral, switch to Euler angle control,\n"
          "                point back to where the gimbal was, 5 deg away and back, then restore\n"
          "                the mode it was in: THE GIMBAL MOVES\n"
          "  --json        one JSON object (for a bug report) instead of text\n"
          "  --window S    how long to measure the reply rate, 0.2..60 s (default 1)\n\n"
          "exit status: 0 the probe completed (whatever the GCU answered), 2 usage error,\n"
          "3 no answer from the GCU, link lost or interrupted (what was learnt is printed first).\n\n",
          out);
    help_link_options(out);
    fputs("\nexample: xfgcu --tcp 192.168.144.108 probe --json > probe.json\n", out);
}

/* ---- the state of a probe ------------------------------------------------------------- */

typedef enum item_state { ITEM_PLANNED, ITEM_SENT, ITEM_SKIPPED } item_state;

typedef struct probe_item {
    xf_command cmd;  /* as planned (osd in send's convention: online_run() maps it to the GCU's version) */
    const char *why; /* what it does and why that is safe; or why it is not sent */
    item_state state;
    xf_cmd_result r;
} probe_item;

typedef struct probe_leg {
    const char *what;
    double pitch, yaw; /* the target (NAN: none, come to rest) */
    int reached;
    uint32_t ms; /* how long it took, or was waited */
    double end_pitch, end_yaw;
} probe_leg;

typedef struct probe {
    online *o;
    int json, move, help, has_window;
    text_view view; /* --raw: fields as wire integers */
    double window_s;
    struct timespec wall0, mono0; /* when the probe started */
    uint32_t start_ms;
    xf_telemetry t0; /* the telemetry the plan was made from */
    uint32_t win_ms, win_sent, win_replies;
    probe_item items[PROBE_MAX];
    size_t n;
    probe_leg legs[LEGS_MAX];
    size_t n_legs;
    size_t i_head_lock, i_neutral, i_euler, i_restore; /* --move's items */
    uint8_t on_wire[256];                              /* orders seen in the packets sent */
    const char *stopped;                               /* why the probe ended early; NULL: it completed */
    const char *move_note; /* --move: why the starting mode was not restored; NULL when it was */
    uint32_t total_ms;
    ask_report ask; /* the open questions */
} probe;

/* ---- arguments -------------------------------------------------------------------------- */

enum { O_MOVE = 256, O_JSON, O_WINDOW, O_HELP };

static const struct option probe_options[] = {
    {"move", no_argument, NULL, O_MOVE},
    {"json", no_argument, NULL, O_JSON},
    {"window", required_argument, NULL, O_WINDOW},
    {"help", no_argument, NULL, O_HELP},
    {NULL, 0, NULL, 0},
};

static int take_arg(probe *p, const cli_args *a, int id)
{
    switch (id) {
    case O_MOVE: p->move = 1; return XFGCU_EXIT_OK;
    case O_JSON: p->json = 1; return XFGCU_EXIT_OK;
    case O_WINDOW: return cli_value_real(a, 0.2, 60.0, "seconds, 0.2..60", &p->window_s, &p->has_window);
    case O_HELP: p->help = 1; return XFGCU_EXIT_OK;
    case CLI_ARG: return cli_unexpected(a);
    default: return XFGCU_EXIT_USAGE; /* CLI_BAD: said */
    }
}

/* ---- planning ----------------------------------------------------------------------------- */

static probe_item *add_item(probe *p, uint8_t order, item_state state, const char *why)
{
    probe_item *it = &p->items[p->n < PROBE_MAX ? p->n++ : PROBE_MAX - 1u];
    memset(it, 0, sizeof(*it));
    xf_command_init(&it->cmd, order);
    it->state = state;
    it->why = why;
    return it;
}

static xf_command *plan(probe *p, uint8_t order, const char *why)
{
    return &add_item(p, order, ITEM_PLANNED, why)->cmd;
}

static void skip(probe *p, uint8_t order, const char *why) { (void)add_item(p, order, ITEM_SKIPPED, why); }

/* A pod flag as this GCU reports it: 1 or 0; -1 when the word reads differently in the two byte
 * orders and the client has not yet learnt which one the GCU uses (docs/protocol.md §11.7). */
static int pod_flag(const xf_client *c, uint16_t flag)
{
    uint16_t w = xf_client_telemetry(c)->pod_status;
    xf_pod_order order = xf_client_pod_order(c);
    unsigned le = xf_pod_flags(w, XF_POD_ORDER_LE) & flag, be = xf_pod_flags(w, XF_POD_ORDER_BE) & flag;
    if (order != XF_POD_ORDER_UNDECIDED) {
        return (xf_pod_flags(w, order) & flag) != 0u;
    }
    return (le != 0u) == (be != 0u) ? (le != 0u) : -1;
}

/* Orders that change nothing: the zoom family (stop, to where it is), focus. */
static void plan_camera(probe *p, const xf_telemetry *t)
{
    xf_command *c = plan(p, XF_ORDER_ZOOM_STOP,
                         "stops a zoom that is not running; cameras 1 and 2, so that a "
                         "failure names the camera");
    c->cameras = 0x03u;
    if (t->have_sub && t->zoom_cam1 >= 10u && t->zoom_cam1 <= 32768u) {
        c = plan(p, XF_ORDER_ZOOM_TO, "camera 1 to the zoom it reports (to within the 0.1x of the report)");
        c->zoom = (int16_t) - (int32_t)t->zoom_cam1;
    } else {
        skip(p, XF_ORDER_ZOOM_TO, "camera 1 reports no zoom to stay at");
    }
    (void)plan(p, XF_ORDER_FOCUS, "one autofocus of camera 1; no setting changes");
}

/* Ranging and lighting, set to the state the pod status word reports. */
static void plan_pod(probe *p)
{
    const xf_client *c = &p->o->client;
    int ranging = pod_flag(c, XF_POD_RANGING_ON), lighting = pod_flag(c, XF_POD_LIGHTING_ON);
    if (ranging < 0) {
        skip(p, XF_ORDER_RANGING, "the pod status word does not tell yet whether ranging is on");
    } else {
        plan(p, XF_ORDER_RANGING, "ranging set to the state the pod status reports")->value = ranging ? 2u : 0u;
    }
    if (lighting != 0) {
        skip(p, XF_ORDER_LIGHTING, "the light is on (or may be), at a level the GCU does not report");
    } else {
        (void)plan(p, XF_ORDER_LIGHTING, "light off, as the pod status reports it");
    }
}

/* Exiting a tracking that is not on, in head lock only: the vendor's GCU (and the simulator) may
 * leave a tracking exit in head lock, so in any other mode it would change the mode. */
static void plan_track(probe *p, const xf_telemetry *t)
{
    static const char why[] = "exits a tracking that is not on (sent only in head lock with tracking off)";
    static const char no[] = "sent only in head lock with tracking off, where exiting tracking changes nothing";
    int idle = t->gimbal_mode == XF_MODE_HEAD_LOCK && pod_flag(&p->o->client, XF_POD_TRACKING_OK) == 0;
    if (idle) {
        (void)plan(p, XF_ORDER_TRACK, why);
        (void)plan(p, XF_ORDER_EXTERNAL_TRACK, why);
    } else {
        skip(p, XF_ORDER_TRACK, no);
        skip(p, XF_ORDER_EXTERNAL_TRACK, no);
    }
}

/* A V0.2 on/off order set to the state @p on the GCU reports (@p value_on: the value that means on). */
static void plan_state(probe *p, uint8_t order, int on, uint8_t value_on)
{
    plan(p, order, "set to the state the GCU reports")->value = on ? value_on : (uint8_t)(value_on ^ 1u);
}

/* A thermometry order: "off" when the GCU reports it off; when on, its settings are not reported. */
static void plan_thermal(probe *p, uint8_t order, uint8_t on_bit)
{
    if ((p->t0.thermal_status & on_bit) != 0u) {
        skip(p, order, "on: turning it off would change it, and its settings are not reported");
    } else {
        (void)plan(p, order, "off, as the GCU reports it; camera 2 (the thermal camera)");
    }
}

/* The orders of V0.2, set to the state its sub frame reports (camera, thermal status, time zone). */
static void plan_v2(probe *p, const xf_telemetry *t)
{
    static const uint8_t v2[] = {XF_ORDER_OSD,       XF_ORDER_OSD_COORDINATE, XF_ORDER_AUTO_FLIP,
                                 XF_ORDER_TIME_ZONE, XF_ORDER_DIGITAL_ZOOM,   XF_ORDER_TARGET_DETECTION,
                                 XF_ORDER_AREA_TEMP, XF_ORDER_TEMP_ALARM,     XF_ORDER_ISOTHERM,
                                 XF_ORDER_SPOT_TEMP};
    size_t i;
    if (t->version < XF_PROTOCOL_V2 || !t->have_sub) {
        for (i = 0; i < sizeof(v2); i++) {
            skip(p, v2[i],
                 t->have_sub ? "the GCU answers in V0.1, whose replies do not report this state"
                             : "no sub frame from the GCU: its state is unknown");
        }
        return;
    }
    plan_state(p, XF_ORDER_OSD, (t->camera_status & XF_CAMERA_OSD_ON) != 0u, 0u); /* send's convention: 0 shows */
    plan_state(p, XF_ORDER_OSD_COORDINATE, (t->camera_status & XF_CAMERA_OSD_TARGET) != 0u, 1u);
    plan_state(p, XF_ORDER_AUTO_FLIP, (t->camera_status & XF_CAMERA_AUTO_FLIP_OFF) != 0u, 1u); /* 1 = off */
    if (t->time_zone >= -12 && t->time_zone <= 14) {
        plan(p, XF_ORDER_TIME_ZONE, "set to the time zone the GCU reports")->hours = t->time_zone;
    } else {
        skip(p, XF_ORDER_TIME_ZONE, "the GCU reports a time zone outside -12..14");
    }
    plan_state(p, XF_ORDER_DIGITAL_ZOOM, (t->camera_status & XF_CAMERA_DIGITAL_ZOOM_ON) != 0u, 1u);
    plan_state(p, XF_ORDER_TARGET_DETECTION, (t->camera_status & XF_CAMERA_DETECTION_ON) != 0u, 1u);
    plan_thermal(p, XF_ORDER_AREA_TEMP, XF_THERMAL_AREA_ON);
    plan_thermal(p, XF_ORDER_TEMP_ALARM, XF_THERMAL_ALARM_ON);
    plan_thermal(p, XF_ORDER_ISOTHERM, XF_THERMAL_ISOTHERM_ON);
    plan_thermal(p, XF_ORDER_SPOT_TEMP, XF_THERMAL_SPOT_ON);
}

/* --move's orders; their runs depend on one another (run_motion). */
static void plan_move(probe *p)
{
    static const char moves[] = "moves the gimbal: only with --move";
    if (!p->move) {
        skip(p, XF_ORDER_HEAD_LOCK, moves);
        skip(p, XF_ORDER_NEUTRAL, moves);
        skip(p, XF_ORDER_EULER, moves);
        return;
    }
    p->i_head_lock = p->n;
    (void)plan(p, XF_ORDER_HEAD_LOCK, "--move: head lock, with zero rates (neutral answers in it)");
    p->i_neutral = p->n;
    (void)plan(p, XF_ORDER_NEUTRAL, "--move: back to the centre");
    p->i_euler = p->n;
    (void)plan(p, XF_ORDER_EULER, "--move: Euler angle control, to point back to where the gimbal was");
}

/* The orders never sent, and why. */
static void plan_never(probe *p)
{
    static const struct {
        uint8_t order;
        const char *why;
    } never[] = {
        {XF_ORDER_CALIBRATION, "recalibrates the gimbal (it must be kept still): a lasting change"},
        {XF_ORDER_ANGLE_CONTROL, "changes the mode (--move probes head_lock and euler)"},
        {XF_ORDER_HEAD_FOLLOW, "changes the mode; the gimbal follows the carrier"},
        {XF_ORDER_ORTHOVIEW, "points the gimbal straight down"},
        {XF_ORDER_FPV, "changes the mode"},
        {XF_ORDER_GAZE_GEO, "turns the gimbal; needs carrier INS data"},
        {XF_ORDER_GAZE_LOCK, "changes the mode; needs carrier INS data"},
        {XF_ORDER_CLICK_TO_AIM, "turns the gimbal"},
        {XF_ORDER_SHUTTER, "takes a picture: leaves a file on the camera's card"},
        {XF_ORDER_RECORD, "starts or stops recording (a toggle)"},
        {XF_ORDER_ZOOM_IN, "changes the zoom"},
        {XF_ORDER_ZOOM_OUT, "changes the zoom"},
        {XF_ORDER_PALETTE, "changes the thermal palette; the one in use is not reported"},
        {XF_ORDER_NIGHT_VISION, "its setting (off, on or auto) is not reported, so it cannot be set back"},
        {XF_ORDER_PIP, "changes the view; V0.2's reported view number is not documented as the order's"},
    };
    size_t i;
    for (i = 0; i < sizeof(never) / sizeof(never[0]); i++) {
        skip(p, never[i].order, never[i].why);
    }
}

/* Drop planned commands that do not fit the version the GCU speaks (cannot happen with the values
 * chosen above; checked so that online_run() never refuses one). */
static void check_plan(probe *p)
{
    size_t i;
    for (i = 0; i < p->n; i++) {
        xf_command sent = p->items[i].cmd;
        uint8_t version = xf_client_gcu_version(&p->o->client);
        cmdargs_for_version(&sent, version);
        if (p->items[i].state == ITEM_PLANNED && xf_command_check(&sent, version, NULL) != XF_OK) {
            p->items[i].state = ITEM_SKIPPED;
            p->items[i].why = "its parameters do not fit the GCU's protocol version";
        }
    }
}

static void make_plan(probe *p)
{
    const xf_telemetry *t = &p->t0;
    plan_camera(p, t);
    plan_pod(p);
    plan_track(p, t);
    plan_v2(p, t);
    plan_move(p);
    plan_never(p);
    check_plan(p);
}

/* ---- the link ------------------------------------------------------------------------------ */

static void on_bytes(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    probe *p = (probe *)user;
    (void)now_ms;
    if (dir == XF_DIR_HOST && len > XF_OFF_ORDER) {
        p->on_wire[data[XF_OFF_ORDER]] = 1u;
    } else if (dir == XF_DIR_GCU) {
        ask_observe(&p->ask, data, len);
    }
}

static int stop_now(probe *p)
{
    if (p->stopped == NULL && cli_stop_requested()) {
        p->stopped = "interrupted";
    } else if (p->stopped == NULL && xf_client_link(&p->o->client) == XF_LINK_DOWN) {
        p->stopped = "link lost";
    }
    return p->stopped != NULL;
}

/* The model comes in the sub frame, which the client asks for in every packet: wait for one. */
static void wait_sub(probe *p)
{
    uint32_t start = xf_posix_now_ms();
    while (!xf_client_telemetry(&p->o->client)->have_sub && !stop_now(p) &&
           xf_ms_since(xf_posix_now_ms(), start) < (uint32_t)p->o->opt->timeout_ms) {
        online_poll(p->o, 20);
    }
}

/* Null packets only, for the window: replies per second. */
static void measure_rate(probe *p)
{
    const xf_health *h = xf_client_health(&p->o->client);
    uint32_t start = xf_posix_now_ms(), limit = (uint32_t)(p->window_s * 1000.0 + 0.5);
    uint32_t sent0 = h->packets_sent, replies0 = h->replies;
    while (!stop_now(p) && xf_ms_since(xf_posix_now_ms(), start) < limit) {
        online_poll(p->o, 20);
    }
    p->win_ms = xf_ms_since(xf_posix_now_ms(), start);
    p->win_sent = h->packets_sent - sent0;
    p->win_replies = h->replies - replies0;
}

/* Run one planned item as send runs a command; a lost link or a signal stops the probe. */
static int run_item(probe *p, probe_item *it)
{
    int rc;
    if (it->state != ITEM_PLANNED || stop_now(p)) {
        return XFGCU_EXIT_OK;
    }
    rc = online_run(p->o, &it->cmd, &it->r, NULL, NULL);
    if (rc == XFGCU_EXIT_OK) {
        it->state = ITEM_SENT;
        if (it->r.status == XF_CMD_LINK_LOST || it->r.status == XF_CMD_CANCELLED) {
            p->stopped = it->r.status == XF_CMD_LINK_LOST ? "link lost" : "interrupted";
        }
    }
    return rc;
}

static int stop_cb(void *user) { return stop_now((probe *)user); }

static int run_safe(probe *p)
{
    size_t i;
    int rc = XFGCU_EXIT_OK;
    for (i = 0; i < p->n && rc == XFGCU_EXIT_OK; i++) {
        if (!p->move || (i != p->i_head_lock && i != p->i_neutral && i != p->i_euler && i != p->i_restore)) {
            rc = run_item(p, &p->items[i]);
        }
    }
    return rc;
}

/* ---- --move ------------------------------------------------------------------------------------ */

static double pitch_now(const probe *p) { return (double)xf_cdeg(xf_client_telemetry(&p->o->client)->cam_pitch); }
static double yaw_now(const probe *p) { return (double)xf_cdeg(xf_client_telemetry(&p->o->client)->cam_yaw); }

static probe_leg *new_leg(probe *p, const char *what, double pitch, double yaw)
{
    probe_leg *l = &p->legs[p->n_legs < LEGS_MAX ? p->n_legs++ : LEGS_MAX - 1u];
    memset(l, 0, sizeof(*l));
    l->what = what;
    l->pitch = pitch;
    l->yaw = yaw;
    return l;
}

static void end_leg(probe *p, probe_leg *l, uint32_t start, int reached)
{
    l->reached = reached;
    l->ms = xf_ms_since(xf_posix_now_ms(), start);
    l->end_pitch = pitch_now(p);
    l->end_yaw = yaw_now(p);
}

/* Euler angle control: the angles in every packet until the reported attitude is there, then
 * STILL_MS more for the gimbal to settle on them (the time reported is the time to get there). */
static void point_leg(probe *p, const char *what, double pitch, double yaw)
{
    probe_leg *l = new_leg(p, what, pitch, yaw);
    float roll = xf_cdeg(p->t0.cam_roll);
    uint32_t start = xf_posix_now_ms(), now = start, there_ms = 0;
    int there = 0;
    while (!stop_now(p) && (there ? xf_ms_since(now, there_ms) < STILL_MS : xf_ms_since(now, start) < POINT_MS)) {
        xf_client_set_angles(&p->o->client, roll, (float)pitch, (float)yaw, now);
        online_poll(p->o, 20);
        now = xf_posix_now_ms();
        if (!there && fabs(pitch_now(p) - pitch) <= TOLERANCE_DEG &&
            fabs(cli_wrap180(yaw_now(p) - yaw)) <= TOLERANCE_DEG) {
            there = 1;
            there_ms = now;
        }
    }
    end_leg(p, l, start, there);
    l->ms = there ? xf_ms_since(there_ms, start) : l->ms;
}

/* After neutral: wait until the attitude has stopped changing. */
static void settle_leg(probe *p)
{
    probe_leg *l = new_leg(p, "neutral, until at rest", (double)NAN, (double)NAN); /* NAN is a float */
    uint32_t start = xf_posix_now_ms(), still = start, now = start;
    double pitch = pitch_now(p), yaw = yaw_now(p);
    while (!stop_now(p) && xf_ms_since(now, start) < SETTLE_MS && xf_ms_since(now, still) < STILL_MS) {
        online_poll(p->o, 20);
        now = xf_posix_now_ms();
        if (fabs(pitch_now(p) - pitch) > STILL_DEG || fabs(cli_wrap180(yaw_now(p) - yaw)) > STILL_DEG) {
            pitch = pitch_now(p);
            yaw = yaw_now(p);
            still = now;
        }
    }
    end_leg(p, l, start, xf_ms_since(now, still) >= STILL_MS);
}

/* Did item @p i end ok? */
static int went_ok(const probe *p, size_t i)
{
    return i < p->n && p->items[i].state == ITEM_SENT && p->items[i].r.status == XF_CMD_OK;
}

/* --move ends in the mode the gimbal was in, by its order (the mode orders' codes are the modes'). */
static void plan_restore(probe *p)
{
    uint8_t mode = p->t0.gimbal_mode;
    int plain = mode == XF_MODE_ANGLE_CONTROL || mode == XF_MODE_HEAD_LOCK || mode == XF_MODE_HEAD_FOLLOW ||
                mode == XF_MODE_ORTHOVIEW || mode == XF_MODE_FPV;
    if (plain) {
        p->i_restore = p->n;
        (void)plan(p, mode, "--move: back to the mode the gimbal was in");
    } else if (mode != XF_MODE_EULER) {
        p->move_note = "the starting mode has no order to go back to: the gimbal is left in Euler angle control";
    }
}

static int run_motion(probe *p)
{
    double pitch0 = (double)xf_cdeg(p->t0.cam_pitch), yaw0 = (double)xf_cdeg(p->t0.cam_yaw);
    double away = (pitch0 - STEP_DEG < -80.0) ? pitch0 + STEP_DEG : pitch0 - STEP_DEG;
    int rc = run_item(p, &p->items[p->i_head_lock]);
    xf_client_clear_control(&p->o->client); /* zero rates in head lock; nothing for neutral */
    if (rc == XFGCU_EXIT_OK && went_ok(p, p->i_head_lock)) {
        rc = run_item(p, &p->items[p->i_neutral]);
        if (rc == XFGCU_EXIT_OK && !stop_now(p) && went_ok(p, p->i_neutral)) {
            settle_leg(p);
        }
    }
    rc = (rc == XFGCU_EXIT_OK) ? run_item(p, &p->items[p->i_euler]) : rc;
    if (rc == XFGCU_EXIT_OK && went_ok(p, p->i_euler)) {
        point_leg(p, "back to where it was", pitch0, yaw0);
        point_leg(p, "5 deg away", away, yaw0);
        point_leg(p, "back to where it was", pitch0, yaw0);
    }
    xf_client_clear_control(&p->o->client); /* no angles for the mode restored to read */
    if (rc == XFGCU_EXIT_OK && p->i_restore < p->n) {
        rc = run_item(p, &p->items[p->i_restore]);
    }
    return rc;
}

/* ---- figures --------------------------------------------------------------------------------- */

/* Does the answer contradict V2.0.6's list? 1 yes, 0 no, -1 nothing to compare. */
static int disagrees(const probe *p, const probe_item *it)
{
    xf_support s = p->t0.have_sub ? xf_gimbal_supports(p->t0.gimbal_code, it->cmd.order) : XF_SUPPORT_UNKNOWN;
    if (it->state != ITEM_SENT || s == XF_SUPPORT_UNKNOWN) {
        return -1;
    }
    switch (it->r.status) {
    case XF_CMD_OK: return s == XF_SUPPORT_NO;
    case XF_CMD_FAILED:
    case XF_CMD_TIMEOUT: return s == XF_SUPPORT_YES;
    default: return -1;
    }
}

static const char *support_name(const probe *p, uint8_t order)
{
    xf_support s = p->t0.have_sub ? xf_gimbal_supports(p->t0.gimbal_code, order) : XF_SUPPORT_UNKNOWN;
    return s == XF_SUPPORT_YES ? "yes" : s == XF_SUPPORT_NO ? "no" : "unknown";
}

typedef struct rtt {
    size_t n;
    uint32_t min, max;
    double median;
} rtt;

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Round trips of the commands answered: from the command's first packet to the reply with its state. */
static rtt round_trips(const probe *p)
{
    uint32_t ms[PROBE_MAX];
    rtt r;
    size_t i;
    memset(&r, 0, sizeof(r));
    for (i = 0; i < p->n; i++) {
        const probe_item *it = &p->items[i];
        if (it->state == ITEM_SENT && (it->r.status == XF_CMD_OK || it->r.status == XF_CMD_FAILED)) {
            ms[r.n++] = it->r.elapsed_ms;
        }
    }
    if (r.n > 0u) {
        qsort(ms, r.n, sizeof(ms[0]), cmp_u32);
        r.min = ms[0];
        r.max = ms[r.n - 1u];
        size_t mid = r.n / 2u;
        r.median = (r.n % 2u) ? (double)ms[mid] : ((double)ms[mid - 1u] + (double)ms[mid]) / 2.0;
    }
    return r;
}

static double rate_hz(const probe *p)
{
    return p->win_ms > 0u ? (double)p->win_replies * 1000.0 / (double)p->win_ms : 0.0;
}

static const char *pod_order_text(xf_pod_order order)
{
    return order == XF_POD_ORDER_LE ? "le" : order == XF_POD_ORDER_BE ? "be" : "undecided";
}

/* The parameters as sent, as decode's table shows them: "cameras=0x01 zoom=-10 (1.0x)" (osd with
 * the value of the GCU's version). */
static void params_text(const probe *p, const probe_item *it, char *buf, size_t cap)
{
    const xf_order_info *info = xf_order_lookup(it->cmd.order);
    xf_command sent = it->cmd;
    size_t i, n = 0;
    char item[64];
    buf[0] = '\0';
    cmdargs_for_version(&sent, p->t0.version);
    for (i = 0; info != NULL && i < info->nfields && n < cap; i++) {
        xf_field f = (xf_field)info->fields[i];
        table_member_text(f, xf_command_get(&sent, f), p->t0.version, p->view, item, sizeof(item));
        n += (size_t)snprintf(buf + n, cap - n, "%s%s", n ? " " : "", item);
    }
}

/* The parameter bytes as sent, in hex. */
static void params_hex(const probe *p, const probe_item *it, char *buf)
{
    uint8_t bytes[XF_PARAMS_KNOWN_MAX];
    size_t n = 0;
    xf_command sent = it->cmd;
    cmdargs_for_version(&sent, p->t0.version);
    if (xf_command_encode(&sent, p->t0.version, bytes, sizeof(bytes), &n, NULL) != XF_OK) {
        n = 0;
    }
    hex_format(bytes, n, '\0', buf);
}

static const char *order_name(uint8_t order)
{
    const char *name = xf_order_name(order);
    return name != NULL ? name : "?";
}

/* ---- text ---------------------------------------------------------------------------------------- */

static void wall_text(const struct timespec *ts, char *buf, size_t cap) { jsonpkt_utc_text(jsonpkt_ms(ts), buf, cap); }

static void print_gimbal(const probe *p)
{
    const xf_telemetry *t = xf_client_telemetry(&p->o->client);
    const char *mode = xf_mode_name(p->t0.gimbal_mode);
    xf_pod_order order = xf_client_pod_order(&p->o->client);
    char model[64], hw[8], fw[8];
    fieldtext_model(t->gimbal_code, model, sizeof(model));
    fieldtext_version(t->hw_version, hw, sizeof(hw));
    fieldtext_version(t->fw_version, fw, sizeof(fw));
    if (t->have_sub) {
        printf("gimbal       %s, hardware %s, firmware %s\n", model, hw, fw);
    } else {
        printf("gimbal       no sub frame within %ld ms: model and versions unknown\n", p->o->opt->timeout_ms);
    }
    printf("protocol     the GCU answers in V0.%u (version byte %u); sent %u\n", t->version, t->version,
           (unsigned)xf_client_health(&p->o->client)->version_sent);
    printf("version      it answered packets of version %u (--protocol %s)\n",
           (unsigned)xf_client_health(&p->o->client)->version_answered,
           p->o->opt->version_auto                 ? "auto"
           : p->o->opt->protocol == XF_PROTOCOL_V2 ? "2"
                                                   : "1");
    printf("pod status   %s\n", order == XF_POD_ORDER_LE   ? "little-endian (the words it sent tell)"
                                : order == XF_POD_ORDER_BE ? "big-endian (the words it sent tell)"
                                                           : "byte order undecided: every word it sent reads the "
                                                             "same both ways (read little-endian meanwhile)");
    printf("mode         %s (0x%02X) at the start\n", mode ? mode : "unknown", p->t0.gimbal_mode);
}

static void print_timing(const probe *p)
{
    rtt r = round_trips(p);
    printf("reply rate   %.1f replies/s over %.2f s (%u packets sent, %u replies); first reply after %u ms\n",
           rate_hz(p), cli_seconds(p->win_ms), (unsigned)p->win_sent, (unsigned)p->win_replies, (unsigned)p->o->up_ms);
    if (r.n > 0u) {
        printf("round trip   min %u ms, median %.1f ms, max %u ms over %zu commands (first packet to reply)\n",
               (unsigned)r.min, r.median, (unsigned)r.max, r.n);
    } else {
        printf("round trip   no command answered\n");
    }
}

static void print_item(const probe *p, const probe_item *it)
{
    char params[160], result[64];
    int d = disagrees(p, it);
    params_text(p, it, params, sizeof(params));
    online_result_text(&it->r, result, sizeof(result));
    printf("  %-17s %-19s %5u %6u  %-7s %s%s\n", order_name(it->cmd.order), result, (unsigned)it->r.packets,
           (unsigned)it->r.elapsed_ms, support_name(p, it->cmd.order), d == 1 ? "DISAGREES  " : "", params);
}

static void print_orders(const probe *p)
{
    size_t i, n = 0;
    printf("\n  %-17s %-19s %5s %6s  %-7s %s\n", "order sent", "result", "pkts", "ms", "V2.0.6", "parameters");
    for (i = 0; i < p->n; i++) {
        if (p->items[i].state == ITEM_SENT) {
            print_item(p, &p->items[i]);
        }
    }
    printf("\n  not sent:\n");
    for (i = 0; i < p->n; i++) {
        if (p->items[i].state != ITEM_SENT) {
            printf("  %-17s %s\n", order_name(p->items[i].cmd.order), p->items[i].why);
        }
    }
    for (i = 0; i < p->n; i++) {
        n += disagrees(p, &p->items[i]) == 1;
    }
    printf("\ndisagreements with V2.0.6's support list: %zu\n", n);
}

static void print_legs(const probe *p)
{
    size_t i;
    for (i = 0; i < p->n_legs; i++) {
        const probe_leg *l = &p->legs[i];
        printf("move         %-24s %s in %.2f s, at pitch %.2f yaw %.2f deg\n", l->what,
               l->reached ? "reached" : "NOT reached", cli_seconds(l->ms), l->end_pitch, l->end_yaw);
    }
    if (p->move_note != NULL) {
        printf("move         %s\n", p->move_note);
    }
}

static void print_text(const probe *p)
{
    char wall[64], health[256];
    wall_text(&p->wall0, wall, sizeof(wall));
    printf("xfgcu probe: %s, %s, xfgcu %s%s\n", p->o->desc, wall, XF_VERSION_STRING,
           p->stopped ? " (stopped early)" : "");
    print_gimbal(p);
    print_timing(p);
    print_legs(p);
    print_orders(p);
    ask_print(&p->ask, stdout);
    online_health_text(p->o, health, sizeof(health));
    printf("\nhealth       %s\n", health);
}

/* ---- JSON -------------------------------------------------------------------------------------- */

typedef struct jobj {
    json_t *obj;
    int *failed;
} jobj;

static void jset(jobj o, const char *key, json_t *value)
{
    if (o.obj == NULL || value == NULL) {
        json_decref(value);
        *o.failed = 1;
    } else if (json_object_set_new(o.obj, key, value) != 0) {
        *o.failed = 1;
    }
}

static jobj jchild(jobj parent, const char *key)
{
    jobj c;
    c.obj = json_object();
    c.failed = parent.failed;
    jset(parent, key, c.obj);
    return c;
}

/* A GCU field of the telemetry under its name, in the probe's view (the unit rule). */
static json_t *field_json(const probe *p, const char *name, int64_t raw)
{
    return jsonpkt_value(xf_wire_field_find(XF_WIRE_GCU, name), raw, xf_client_telemetry(&p->o->client)->version,
                         p->view);
}

static void json_gimbal(const probe *p, jobj g)
{
    const xf_telemetry *t = xf_client_telemetry(&p->o->client);
    const char *model = xf_gimbal_model(t->gimbal_code), *mode = xf_mode_name(p->t0.gimbal_mode);
    jset(g, "have_sub", json_boolean(t->have_sub));
    jset(g, "gimbal_code", t->have_sub ? json_integer(t->gimbal_code) : json_null());
    jset(g, "gimbal_model", t->have_sub && model ? json_string(model) : json_null());
    jset(g, "hw_version", t->have_sub ? field_json(p, "hw_version", t->hw_version) : json_null());
    jset(g, "fw_version", t->have_sub ? field_json(p, "fw_version", t->fw_version) : json_null());
    jset(g, "protocol", json_integer(t->version));
    jset(g, "version_answered", json_integer(xf_client_health(&p->o->client)->version_answered));
    jset(g, "pod_status", json_integer(t->pod_status));
    jset(g, "pod_status_order", json_string(pod_order_text(xf_client_pod_order(&p->o->client))));
    jset(g, "gimbal_mode", json_integer(p->t0.gimbal_mode));
    jset(g, "mode_name", mode ? json_string(mode) : json_null());
    jset(g, "zoom_cam1", field_json(p, "zoom_cam1", t->zoom_cam1));
    jset(g, "zoom_cam2", field_json(p, "zoom_cam2", t->zoom_cam2));
    if (t->version >= XF_PROTOCOL_V2) {
        jset(g, "error_code", json_integer(t->error_code));
        jset(g, "thermal_status", json_integer(t->thermal_status));
        jset(g, "camera_status", json_integer(t->camera_status));
        jset(g, "time_zone", json_integer(t->time_zone));
    }
}

static void json_timing(const probe *p, jobj top)
{
    jobj w = jchild(top, "reply_rate");
    jobj r = jchild(top, "round_trip_ms");
    rtt t = round_trips(p);
    jset(w, "window_s", json_real(cli_seconds(p->win_ms)));
    jset(w, "packets_sent", json_integer(p->win_sent));
    jset(w, "replies", json_integer(p->win_replies));
    jset(w, "hz", json_real(floor(rate_hz(p) * 10.0 + 0.5) / 10.0));
    jset(r, "commands", json_integer((json_int_t)t.n));
    jset(r, "min", t.n ? json_integer(t.min) : json_null());
    jset(r, "median", t.n ? json_real(t.median) : json_null());
    jset(r, "max", t.n ? json_integer(t.max) : json_null());
    jset(top, "first_reply_ms", json_integer(p->o->up_ms));
}

static json_t *json_item(const probe *p, const probe_item *it, int *failed)
{
    char hex[3 * XF_PARAMS_KNOWN_MAX + 1], result[64];
    jobj o;
    int d = disagrees(p, it);
    o.obj = json_object();
    o.failed = failed;
    jset(o, "order", json_integer(it->cmd.order));
    jset(o, "order_name", json_string(order_name(it->cmd.order)));
    jset(o, "support", json_string(support_name(p, it->cmd.order)));
    if (it->state != ITEM_SENT) {
        jset(o, "result", json_string("not sent"));
        jset(o, "why", json_string(it->why));
        return o.obj;
    }
    params_hex(p, it, hex);
    online_result_text(&it->r, result, sizeof(result));
    if (it->r.status == XF_CMD_FAILED) {
        result[strlen("failed")] = '\0'; /* "failed cameras 0x02": the mask has its own key */
    }
    jset(o, "params", json_string(hex));
    jset(o, "result", json_string(result));
    jset(o, "state", json_integer(it->r.state));
    jset(o, "failed_cameras", json_integer(it->r.failed_cameras));
    jset(o, "packets", json_integer(it->r.packets));
    jset(o, "elapsed_ms", json_integer(it->r.elapsed_ms));
    jset(o, "agrees", d < 0 ? json_null() : json_boolean(d == 0));
    jset(o, "why", json_string(it->why));
    return o.obj;
}

static void json_orders(const probe *p, jobj top)
{
    json_t *orders = json_array(), *dis = json_array(), *wire = json_array();
    size_t i;
    for (i = 0; i < p->n; i++) {
        if (json_array_append_new(orders, json_item(p, &p->items[i], top.failed)) != 0 ||
            (disagrees(p, &p->items[i]) == 1 &&
             json_array_append_new(dis, json_string(order_name(p->items[i].cmd.order))) != 0)) {
            *top.failed = 1;
        }
    }
    for (i = 0; i < 256u; i++) {
        if (p->on_wire[i] && json_array_append_new(wire, json_integer((json_int_t)i)) != 0) {
            *top.failed = 1;
        }
    }
    jset(top, "orders", orders);
    jset(top, "disagreements", dis);
    jset(top, "orders_on_wire", wire);
}

/* Degrees as the GCU reports them, to 0.01: no float noise in the text. */
static double hundredths(double deg) { return floor(deg * 100.0 + 0.5) / 100.0; }

static void json_legs(const probe *p, jobj top)
{
    json_t *legs = json_array();
    size_t i;
    for (i = 0; i < p->n_legs; i++) {
        const probe_leg *l = &p->legs[i];
        jobj o;
        o.obj = json_object();
        o.failed = top.failed;
        jset(o, "what", json_string(l->what));
        jset(o, "pitch", isnan(l->pitch) ? json_null() : json_real(hundredths(l->pitch)));
        jset(o, "yaw", isnan(l->yaw) ? json_null() : json_real(hundredths(l->yaw)));
        jset(o, "reached", json_boolean(l->reached));
        jset(o, "s", json_real(cli_seconds(l->ms)));
        jset(o, "end_pitch", field_json(p, "cam_pitch", (int64_t)floor(l->end_pitch * 100.0 + 0.5)));
        jset(o, "end_yaw", field_json(p, "cam_yaw", (int64_t)floor(l->end_yaw * 100.0 + 0.5)));
        if (json_array_append_new(legs, o.obj) != 0) {
            *top.failed = 1;
        }
    }
    jset(top, "moves", legs);
    jset(top, "move_note", p->move_note ? json_string(p->move_note) : json_null());
}

static void json_head(const probe *p, jobj top)
{
    jobj l;
    jset(top, "probe", json_integer(1));
    (void)jsonpkt_times(top.obj, &p->mono0, &p->wall0); /* when the probe started */
    jset(top, "program", json_string("xfgcu"));
    jset(top, "version", json_string(XF_VERSION_STRING));
    l = jchild(top, "link");
    jset(l, "option", json_string(p->o->option));
    jset(l, "where", json_string(p->o->desc));
    jset(l, "protocol_sent", json_integer(xf_client_health(&p->o->client)->version_sent));
    jset(l, "protocol_setting", p->o->opt->version_auto ? json_string("auto") : json_integer(p->o->opt->protocol));
    jset(l, "rate_hz", json_integer(p->o->opt->rate_hz));
    jset(l, "timeout_ms", json_integer(p->o->opt->timeout_ms));
    jset(top, "move", json_boolean(p->move));
    jset(top, "complete", json_boolean(p->stopped == NULL));
    jset(top, "stopped", p->stopped ? json_string(p->stopped) : json_null());
    jset(top, "duration_s", json_real(cli_seconds(p->total_ms)));
}

/* The report as an object; *failed set when memory ran out on the way. */
static json_t *json_report(probe *p, int *failed)
{
    jobj top;
    top.obj = json_object();
    top.failed = failed;
    json_head(p, top);
    json_gimbal(p, jchild(top, "gimbal"));
    json_timing(p, top);
    json_legs(p, top);
    json_orders(p, top);
    jset(top, "questions", ask_json(&p->ask));
    jset(top, "health", online_health_json(p->o));
    return top.obj;
}

static int print_json(probe *p)
{
    int failed = 0;
    json_t *obj = json_report(p, &failed);
    char *text = failed ? NULL : jsonpkt_dumps(obj);
    json_decref(obj);
    if (text == NULL) {
        return cli_fail("probe: out of memory");
    }
    printf("%s\n", text);
    free(text);
    return XFGCU_EXIT_OK;
}

/* ---- the command ------------------------------------------------------------------------------ */

/* What was planned and not sent, and why. */
static void unsent(probe *p)
{
    size_t i;
    for (i = 0; i < p->n; i++) {
        if (p->items[i].state == ITEM_PLANNED) {
            p->items[i].state = ITEM_SKIPPED;
            p->items[i].why = p->stopped != NULL               ? "the probe stopped before it"
                              : (i == p->i_neutral && p->move) ? "--move: sent only once head_lock is ok"
                                                               : "not sent";
        }
    }
}

static int run_probe(probe *p)
{
    int rc;
    wait_sub(p);
    measure_rate(p);
    p->t0 = *xf_client_telemetry(&p->o->client);
    p->o->submit_flags = XF_SUBMIT_ANY_MODEL; /* the point is to see what the gimbal answers */
    xf_client_clear_control(&p->o->client);
    make_plan(p);
    if (p->move) {
        plan_restore(p);
    }
    rc = run_safe(p);
    if (rc == XFGCU_EXIT_OK) {
        ask_questions(p->o, &p->ask, stop_cb, p);
    }
    if (rc == XFGCU_EXIT_OK && p->move) {
        rc = run_motion(p);
    }
    if (rc == XFGCU_EXIT_OK && p->stopped == NULL) {
        online_linger(p->o, NULLS_AFTER);
    }
    unsent(p);
    p->total_ms = xf_ms_since(xf_posix_now_ms(), p->start_ms);
    return rc;
}

static int finish(probe *p)
{
    int rc = p->json ? print_json(p) : (print_text(p), XFGCU_EXIT_OK);
    if (rc == XFGCU_EXIT_OK && p->stopped != NULL) {
        rc = cli_fail_link("probe: %s on %s before the probe completed", p->stopped, p->o->desc);
    }
    return rc;
}

/* Open the link, probe, report. */
static int probe_link(probe *p, const cli_link *link)
{
    online_hooks hooks;
    int rc;
    memset(&hooks, 0, sizeof(hooks));
    hooks.on_bytes = on_bytes;
    hooks.user = p;
    cli_signals_init();
    clock_gettime(CLOCK_REALTIME, &p->wall0);
    clock_gettime(CLOCK_MONOTONIC, &p->mono0);
    p->start_ms = xf_posix_now_ms();
    p->o = online_new();
    rc = (p->o != NULL) ? online_open(p->o, link, "probe", &hooks) : XFGCU_EXIT_USAGE;
    rc = (rc == XFGCU_EXIT_OK) ? run_probe(p) : rc;
    rc = (rc == XFGCU_EXIT_OK) ? finish(p) : rc;
    ask_free(&p->ask);
    online_free(p->o);
    return rc;
}

int cmd_probe(const cli_link *link, int argc, char **argv)
{
    probe *p = calloc(1, sizeof(*p));
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    if (p == NULL) {
        return cli_fail("probe: out of memory");
    }
    p->window_s = 1.0;
    ask_init(&p->ask);
    p->i_head_lock = p->i_neutral = p->i_euler = p->i_restore = PROBE_MAX;
    cli_args_init(&a, argc, argv, CLI_IN_ORDER, probe_options, "probe");
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        rc = take_arg(p, &a, id);
    }
    p->view = link->view; /* --raw: taken anywhere on the line */
    if (rc == XFGCU_EXIT_OK && p->help) {
        help_probe(stdout);
    } else if (rc == XFGCU_EXIT_OK) {
        rc = probe_link(p, link);
    }
    free(p);
    return rc;
}
