/*
 * cmd_point.c - `xfgcu [LINK] point --pitch DEG --yaw DEG [--roll DEG]`.
 *
 * Euler angle control 0x14 where the GCU has it: the euler command first
 * (with no control quantities, which the mode before it would read as
 * rates), then the desired angles in every packet until the reported
 * attitude is within TOLERANCE of them. Where it does not (the model lacks
 * it by V2.0.6's support list, or the GCU answers euler with failure, as
 * GCU-side programs that know only angle control do), angle control 0x10,
 * the mode hosts in the field use: roll and pitch as Euler angles and yaw
 * relative to the carrier in V0.2, all three relative in V0.1
 * (docs/protocol.md §11.1); the output says which. Prints the attitude
 * reached; with --json, JSON lines instead: each mode's result and the
 * motion's.
 */
#include <math.h>
#include <string.h>

#include "cli.h"
#include "online.h"

#define TOLERANCE_DEG 0.5
#define NULLS_AFTER   3u

void help_point(FILE *out)
{
    fputs("usage: xfgcu [LINK OPTIONS] point --pitch DEG --yaw DEG [--roll DEG] [--wait S] [--json]\n\n"
          "Point the gimbal: switch it to Euler angle control (the euler command, run the protocol's\n"
          "way), then send the desired absolute angles in every packet until the attitude the GCU\n"
          "reports is within 0.5 deg of them. Prints the attitude reached and the mode used.\n"
          "A GCU that lacks Euler angle control (its model, by V2.0.6's support list, or it answers\n"
          "euler with failure) is pointed in angle control (0x10) instead: yaw is then relative to\n"
          "the carrier (in V0.1 pitch and roll too), and the output says so.\n\n"
          "  --pitch DEG   desired pitch, -180..180 deg (down is negative)\n"
          "  --yaw DEG     desired yaw, -360..360 deg (absolute heading; 45 and -315 are the same)\n"
          "  --roll DEG    desired roll, -180..180 deg (default 0, and then not waited for)\n"
          "  --wait S      how long the gimbal may take to get there, 0.1..600 s (default 10)\n"
          "  --json        one JSON object per line instead, each with time_mono and time_utc: the\n"
          "                mode's result ({\"step\": \"mode\", \"status\": \"ok\", ...}, as send --json), then\n"
          "                the motion's ({\"step\": \"point\", \"status\": \"reached\", \"pitch\": -30.0, ...});\n"
          "                docs/cli.md lists the keys. Errors stay one line on stderr.\n\n"
          "exit status: 0 reached, 1 the GCU refused both Euler angle control and angle control,\n"
          "3 link error, no answer or not there in time.\n\n",
          out);
    help_link_options(out);
    fputs("\nexample: xfgcu --tcp 192.168.144.108 point --pitch -30 --yaw 45\n", out);
}

typedef struct point_args {
    double pitch, yaw, roll, wait_s;
    int has_pitch, has_yaw, has_roll, has_wait, json, help;
} point_args;

/* The mode the angles are sent in, and how the GCU reads them there (docs/protocol.md §11.1). */
typedef struct point_mode {
    uint8_t order;        /* XF_ORDER_EULER, or XF_ORDER_ANGLE_CONTROL */
    int relative[3];      /* roll, pitch, yaw: read relative to the carrier (else as Euler angles) */
    const char *fallback; /* why angle control and not Euler; NULL for Euler */
} point_mode;

typedef struct point_run {
    const point_args *a;
    point_mode mode;
} point_run;

enum { O_PITCH = 256, O_YAW, O_ROLL, O_WAIT, O_JSON, O_HELP };

static const struct option point_options[] = {
    {"pitch", required_argument, NULL, O_PITCH},
    {"yaw", required_argument, NULL, O_YAW},
    {"roll", required_argument, NULL, O_ROLL},
    {"wait", required_argument, NULL, O_WAIT},
    {"json", no_argument, NULL, O_JSON},
    {"help", no_argument, NULL, O_HELP},
    {NULL, 0, NULL, 0},
};

static int take_arg(point_args *p, const cli_args *a, int id)
{
    switch (id) {
    case O_PITCH: return cli_value_real(a, -180.0, 180.0, "degrees, -180..180", &p->pitch, &p->has_pitch);
    case O_YAW: return cli_value_real(a, -360.0, 360.0, "degrees, -360..360", &p->yaw, &p->has_yaw);
    case O_ROLL: return cli_value_real(a, -180.0, 180.0, "degrees, -180..180", &p->roll, &p->has_roll);
    case O_WAIT: return cli_value_real(a, 0.1, 600.0, "seconds, 0.1..600", &p->wait_s, &p->has_wait);
    case O_JSON: p->json = 1; return XFGCU_EXIT_OK;
    case O_HELP: p->help = 1; return XFGCU_EXIT_OK;
    case CLI_ARG: return cli_unexpected(a);
    default: return XFGCU_EXIT_USAGE; /* CLI_BAD: said */
    }
}

static int parse_args(point_args *p, int argc, char **argv)
{
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    memset(p, 0, sizeof(*p));
    p->wait_s = 10.0;
    cli_args_init(&a, argc, argv, CLI_IN_ORDER, point_options, "point");
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        rc = take_arg(p, &a, id);
    }
    if (rc == XFGCU_EXIT_OK && !p->help && !p->has_pitch) {
        rc = cli_fail("point: missing --pitch DEG");
    }
    if (rc == XFGCU_EXIT_OK && !p->help && !p->has_yaw) {
        rc = cli_fail("point: missing --yaw DEG");
    }
    return rc;
}

/* The angles the GCU reports that the mode's targets are to be compared with: the absolute Euler
 * angles, or for an axis the mode reads relative to the carrier, the relative angle (appendix 3:
 * roll = +Y, pitch = -X; the relative Z is the relative yaw). */
static void reported(const xf_telemetry *t, const point_mode *m, double out[3])
{
    out[0] = m->relative[0] ? (double)xf_cdeg(t->rel_angle_y) : (double)xf_cdeg(t->cam_roll);
    out[1] = m->relative[1] ? -(double)xf_cdeg(t->rel_angle_x) : (double)xf_cdeg(t->cam_pitch);
    out[2] = m->relative[2] ? (double)xf_cdeg(t->rel_angle_z) : (double)xf_cdeg(t->cam_yaw);
}

/* Is the attitude reported since @p since within the tolerance of the target? */
static int arrived(const xf_client *c, uint32_t since, const point_run *p)
{
    const xf_telemetry *t = xf_client_telemetry(c);
    const point_args *a = p->a;
    double at[3];
    if (!t->have_main || (int32_t)(xf_client_health(c)->last_rx_ms - since) <= 0) { /* the main frame's time */
        return 0;
    }
    reported(t, &p->mode, at);
    return fabs(at[1] - a->pitch) <= TOLERANCE_DEG && fabs(cli_wrap180(at[2] - a->yaw)) <= TOLERANCE_DEG &&
           (!a->has_roll || fabs(at[0] - a->roll) <= TOLERANCE_DEG);
}

/* The mode as the output names it: "Euler angle control 0x14", or angle control with its frames. */
static const char *mode_text(const point_mode *m)
{
    if (m->order == XF_ORDER_EULER) {
        return "Euler angle control 0x14";
    }
    return m->relative[1] ? "angle control 0x10: roll, pitch and yaw relative to the carrier (V0.1)"
                          : "angle control 0x10: yaw relative to the carrier";
}

/* --json: the motion's line. @p status: "reached", "not_there", "link_lost" or "interrupted". */
static void motion_json(const online *o, const point_run *p, const char *status, uint32_t elapsed_ms)
{
    const xf_telemetry *t = xf_client_telemetry(&o->client);
    const point_args *a = p->a;
    json_t *obj = cli_json_times(json_object());
    if (obj == NULL) {
        return; /* out of memory: no line */
    }
    json_object_set_new(obj, "step", json_string("point"));
    json_object_set_new(obj, "status", json_string(status));
    json_object_set_new(obj, "mode_order", json_integer(p->mode.order));
    json_object_set_new(obj, "mode_order_name", json_string(xf_order_name(p->mode.order)));
    json_object_set_new(obj, "yaw_relative", json_boolean(p->mode.relative[2]));
    json_object_set_new(obj, "fallback", p->mode.fallback ? json_string(p->mode.fallback) : json_null());
    json_object_set_new(obj, "target_roll", a->has_roll ? json_real(a->roll) : json_null());
    json_object_set_new(obj, "target_pitch", json_real(a->pitch));
    json_object_set_new(obj, "target_yaw", json_real(a->yaw));
    json_object_set_new(obj, "tolerance_deg", json_real(TOLERANCE_DEG));
    json_object_set_new(obj, "roll", online_field_json(o, "cam_roll", t->cam_roll));
    json_object_set_new(obj, "pitch", online_field_json(o, "cam_pitch", t->cam_pitch));
    json_object_set_new(obj, "yaw", online_field_json(o, "cam_yaw", t->cam_yaw));
    json_object_set_new(obj, "rel_angle_z", online_field_json(o, "rel_angle_z", t->rel_angle_z));
    json_object_set_new(
        obj, "attitude_age_ms",
        json_integer((json_int_t)xf_ms_since(xf_posix_now_ms(), xf_client_health(&o->client)->last_rx_ms)));
    json_object_set_new(obj, "elapsed_ms", json_integer((json_int_t)elapsed_ms));
    json_object_set_new(obj, "link", json_string(o->desc));
    (void)cli_json_line(obj);
}

/* The reported angles the targets are compared with, as text: "roll 0.00 pitch -30.00 yaw 45.00 deg",
 * "relative yaw" where the mode reads it so. */
static void where_text(const online *o, const point_mode *m, char *buf, size_t cap)
{
    double at[3];
    reported(xf_client_telemetry(&o->client), m, at);
    snprintf(buf, cap, "roll %.2f pitch %.2f %syaw %.2f deg", at[0], at[1], m->relative[2] ? "relative " : "",
             m->relative[2] ? at[2] : (double)xf_cdeg(xf_client_telemetry(&o->client)->cam_yaw));
}

/* The gimbal did not get there: the JSON line if asked, then the one stderr line. */
static int not_there(online *o, const point_run *p, uint32_t start)
{
    char where[96];
    int down = xf_client_link(&o->client) == XF_LINK_DOWN, stop = cli_stop_requested();
    if (p->a->json) {
        motion_json(o, p,
                    down   ? "link_lost"
                    : stop ? "interrupted"
                           : "not_there",
                    xf_ms_since(xf_posix_now_ms(), start));
    }
    where_text(o, &p->mode, where, sizeof(where));
    if (down) {
        return cli_fail_link("point: link lost on %s (at %s)", o->desc, where);
    }
    return cli_fail_link("point: %s: the gimbal is at %s, not within %.1f deg of pitch %.2f yaw %.2f (%s)",
                         stop ? "interrupted" : "not there in time", where, TOLERANCE_DEG, p->a->pitch, p->a->yaw,
                         mode_text(&p->mode));
}

/* Once in the mode: the angles in every packet until the gimbal is there. */
static int stream_angles(online *o, const point_run *p)
{
    const point_args *a = p->a;
    uint32_t start = xf_posix_now_ms(), limit = (uint32_t)(a->wait_s * 1000.0), elapsed;
    char where[96];
    while (!arrived(&o->client, start, p)) {
        uint32_t now = xf_posix_now_ms();
        if (cli_stop_requested() || xf_ms_since(now, start) >= limit || xf_client_link(&o->client) == XF_LINK_DOWN) {
            return not_there(o, p, start);
        }
        xf_client_set_angles(&o->client, (float)a->roll, (float)a->pitch, (float)a->yaw, now);
        online_poll(o, 20);
    }
    elapsed = xf_ms_since(xf_posix_now_ms(), start);
    online_linger(o, NULLS_AFTER);
    if (a->json) {
        motion_json(o, p, "reached", elapsed);
    } else {
        where_text(o, &p->mode, where, sizeof(where));
        printf("reached %s in %.2f s, %s%s%s\n", where, cli_seconds(elapsed), mode_text(&p->mode),
               p->mode.fallback ? "; " : "", p->mode.fallback ? p->mode.fallback : "");
    }
    return XFGCU_EXIT_OK;
}

/* Angle control 0x10, as the GCU's version reads it: yaw relative to the carrier, and in V0.1
 * (V2.0.4's "FPV") roll and pitch too. */
static void angle_control(point_mode *m, uint8_t version, const char *why)
{
    m->order = XF_ORDER_ANGLE_CONTROL;
    m->relative[0] = m->relative[1] = version < XF_PROTOCOL_V2;
    m->relative[2] = 1;
    m->fallback = why;
}

/* Euler where the GCU has it, else angle control: the mode switched to, as send runs it. */
static int switch_mode(online *o, point_run *p)
{
    xf_cmd_result r;
    int rc;
    memset(&p->mode, 0, sizeof(p->mode));
    p->mode.order = XF_ORDER_EULER;
    if (xf_client_supports(&o->client, XF_ORDER_EULER) == XF_SUPPORT_NO) {
        angle_control(&p->mode, xf_client_gcu_version(&o->client),
                      "the GCU's model lacks Euler angle control by V2.0.6's support list");
    } else {
        rc = online_run_mode(o, XF_ORDER_EULER, p->a->json, &r);
        if (rc != XFGCU_EXIT_OK || r.status != XF_CMD_FAILED) {
            return (rc == XFGCU_EXIT_OK) ? online_result_exit(o, "point: euler (Euler angle control)", &r) : rc;
        }
        angle_control(&p->mode, xf_client_gcu_version(&o->client), "the GCU answered euler (0x14) with failure");
    }
    rc = online_run_mode(o, XF_ORDER_ANGLE_CONTROL, p->a->json, &r);
    return (rc == XFGCU_EXIT_OK) ? online_result_exit(o, "point: angle-control (angle control)", &r) : rc;
}

static int run_point(const cli_link *link, const point_args *a)
{
    online *o = online_new();
    point_run p;
    int rc = (o != NULL) ? XFGCU_EXIT_OK : XFGCU_EXIT_USAGE;
    p.a = a;
    cli_signals_init();
    if (rc == XFGCU_EXIT_OK) {
        rc = online_open(o, link, "point", NULL);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = switch_mode(o, &p);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = stream_angles(o, &p);
    }
    online_free(o);
    return rc;
}

int cmd_point(const cli_link *link, int argc, char **argv)
{
    point_args a;
    int rc = parse_args(&a, argc, argv);
    if (rc == XFGCU_EXIT_OK && a.help) {
        help_point(stdout);
    } else if (rc == XFGCU_EXIT_OK) {
        rc = run_point(link, &a);
    }
    return rc;
}
