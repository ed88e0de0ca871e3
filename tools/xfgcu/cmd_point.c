/*
 * cmd_point.c - `xfgcu [LINK] point --pitch DEG --yaw DEG [--roll DEG]`.
 *
 * Euler angle control: the euler command first (with no control
 * quantities, which the mode before it would read as rates), then the
 * desired angles in every packet until the reported attitude is within
 * TOLERANCE of them. Prints the attitude reached; with --json, two JSON
 * lines instead: the mode's result and the motion's.
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
          "reports is within 0.5 deg of them. Prints the attitude reached.\n\n"
          "  --pitch DEG   desired pitch, -180..180 deg (down is negative)\n"
          "  --yaw DEG     desired yaw, -360..360 deg (absolute heading; 45 and -315 are the same)\n"
          "  --roll DEG    desired roll, -180..180 deg (default 0, and then not waited for)\n"
          "  --wait S      how long the gimbal may take to get there, 0.1..600 s (default 10)\n"
          "  --json        one JSON object per line instead, each with time_mono and time_utc: the\n"
          "                mode's result ({\"step\": \"mode\", \"status\": \"ok\", ...}, as send --json), then\n"
          "                the motion's ({\"step\": \"point\", \"status\": \"reached\", \"pitch\": -30.0, ...});\n"
          "                docs/cli.md lists the keys. Errors stay one line on stderr.\n\n"
          "exit status: 0 reached, 1 the GCU refused Euler angle control, 3 link error, no answer\n"
          "or not there in time.\n\n",
          out);
    help_link_options(out);
    fputs("\nexample: xfgcu --tcp 192.168.144.108 point --pitch -30 --yaw 45\n", out);
}

typedef struct point_args {
    double pitch, yaw, roll, wait_s;
    int has_pitch, has_yaw, has_roll, has_wait, json, help;
} point_args;

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

/* Is the attitude reported since @p since within the tolerance of the target? */
static int arrived(const xf_client *c, uint32_t since, const point_args *a)
{
    const xf_telemetry *t = xf_client_telemetry(c);
    if (!t->have_main || (int32_t)(xf_client_health(c)->last_rx_ms - since) <= 0) { /* the main frame's time */
        return 0;
    }
    return fabs((double)xf_cdeg(t->cam_pitch) - a->pitch) <= TOLERANCE_DEG &&
           fabs(cli_wrap180((double)xf_cdeg(t->cam_yaw) - a->yaw)) <= TOLERANCE_DEG &&
           (!a->has_roll || fabs((double)xf_cdeg(t->cam_roll) - a->roll) <= TOLERANCE_DEG);
}

/* --json: the motion's line. @p status: "reached", "not_there", "link_lost" or "interrupted". */
static void motion_json(const online *o, const point_args *a, const char *status, uint32_t elapsed_ms)
{
    const xf_telemetry *t = xf_client_telemetry(&o->client);
    json_t *obj = cli_json_times(json_object());
    if (obj == NULL) {
        return; /* out of memory: no line */
    }
    json_object_set_new(obj, "step", json_string("point"));
    json_object_set_new(obj, "status", json_string(status));
    json_object_set_new(obj, "target_roll", a->has_roll ? json_real(a->roll) : json_null());
    json_object_set_new(obj, "target_pitch", json_real(a->pitch));
    json_object_set_new(obj, "target_yaw", json_real(a->yaw));
    json_object_set_new(obj, "tolerance_deg", json_real(TOLERANCE_DEG));
    json_object_set_new(obj, "roll", online_field_json(o, "cam_roll", t->cam_roll));
    json_object_set_new(obj, "pitch", online_field_json(o, "cam_pitch", t->cam_pitch));
    json_object_set_new(obj, "yaw", online_field_json(o, "cam_yaw", t->cam_yaw));
    json_object_set_new(
        obj, "attitude_age_ms",
        json_integer((json_int_t)xf_ms_since(xf_posix_now_ms(), xf_client_health(&o->client)->last_rx_ms)));
    json_object_set_new(obj, "elapsed_ms", json_integer((json_int_t)elapsed_ms));
    json_object_set_new(obj, "link", json_string(o->desc));
    (void)cli_json_line(obj);
}

/* The gimbal did not get there: the JSON line if asked, then the one stderr line. */
static int not_there(online *o, const point_args *a, uint32_t start)
{
    char where[96];
    int down = xf_client_link(&o->client) == XF_LINK_DOWN, stop = cli_stop_requested();
    if (a->json) {
        motion_json(o, a,
                    down   ? "link_lost"
                    : stop ? "interrupted"
                           : "not_there",
                    xf_ms_since(xf_posix_now_ms(), start));
    }
    online_attitude_text(xf_client_telemetry(&o->client), where, sizeof(where));
    if (down) {
        return cli_fail_link("point: link lost on %s (at %s)", o->desc, where);
    }
    return cli_fail_link("point: %s: the gimbal is at %s, not within %.1f deg of pitch %.2f yaw %.2f",
                         stop ? "interrupted" : "not there in time", where, TOLERANCE_DEG, a->pitch, a->yaw);
}

/* Once in Euler angle control (online_mode_fn). */
static int stream_angles(online *o, const void *args)
{
    const point_args *a = (const point_args *)args;
    uint32_t start = xf_posix_now_ms(), limit = (uint32_t)(a->wait_s * 1000.0), elapsed;
    char where[96];
    while (!arrived(&o->client, start, a)) {
        uint32_t now = xf_posix_now_ms();
        if (cli_stop_requested() || xf_ms_since(now, start) >= limit || xf_client_link(&o->client) == XF_LINK_DOWN) {
            return not_there(o, a, start);
        }
        xf_client_set_angles(&o->client, (float)a->roll, (float)a->pitch, (float)a->yaw, now);
        online_poll(o, 20);
    }
    elapsed = xf_ms_since(xf_posix_now_ms(), start);
    online_linger(o, NULLS_AFTER);
    if (a->json) {
        motion_json(o, a, "reached", elapsed);
    } else {
        online_attitude_text(xf_client_telemetry(&o->client), where, sizeof(where));
        printf("reached %s in %.2f s\n", where, cli_seconds(elapsed));
    }
    return XFGCU_EXIT_OK;
}

int cmd_point(const cli_link *link, int argc, char **argv)
{
    point_args a;
    int rc = parse_args(&a, argc, argv);
    if (rc == XFGCU_EXIT_OK && a.help) {
        help_point(stdout);
    } else if (rc == XFGCU_EXIT_OK) {
        rc = online_run_in_mode(link, "point", XF_ORDER_EULER, "point: euler (Euler angle control)", a.json,
                                stream_angles, &a);
    }
    return rc;
}
