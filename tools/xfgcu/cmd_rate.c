/*
 * cmd_rate.c - `xfgcu [LINK] rate --pitch DPS --yaw DPS --duration S`.
 *
 * Head lock: the head_lock command first (with no control quantities),
 * then the desired rates in every packet for S seconds, refreshed each
 * time round the loop (the client's watchdog zeroes rates that are not),
 * then zero rates for a few packets so the gimbal holds where it is.
 * Prints where it started and stopped; with --json, two JSON lines
 * instead: the mode's result and the motion's.
 */
#include <string.h>

#include "cli.h"
#include "online.h"

#define ZERO_PACKETS 5u
#define MAX_DPS      150.0 /* control quantity 1500 x 0.1 deg/s at zoom 1x */

void help_rate(FILE *out)
{
    fputs("usage: xfgcu [LINK OPTIONS] rate --pitch DPS --yaw DPS --duration S [--json]\n\n"
          "Turn the gimbal at a steady rate: switch it to head lock (the head_lock command, run the\n"
          "protocol's way), send the desired angular velocities in every packet for S seconds, then\n"
          "zero rates so it holds still. Prints where it started and where it stopped.\n\n"
          "  --pitch DPS     pitch rate, -150..150 deg/s (positive: the pitch angle grows)\n"
          "  --yaw DPS       yaw rate, -150..150 deg/s (positive: the yaw angle grows)\n"
          "  --duration S    how long, 0.02..3600 s\n"
          "  --json          one JSON object per line instead, each with time_mono and time_utc: the\n"
          "                  mode's result ({\"step\": \"mode\", \"status\": \"ok\", ...}, as send --json),\n"
          "                  then the motion's ({\"step\": \"rate\", \"status\": \"done\", \"yaw\": 64.98,\n"
          "                  \"rate_z\": 0.0, ...}); docs/cli.md lists the keys. Errors stay one line on stderr.\n\n"
          "The protocol scales rates by the zoom of the main camera (at 5x, 150 deg/s is sent as\n"
          "30 deg/s); the library does the scaling, so the gimbal turns at the rate asked as long\n"
          "as it is within 150 / zoom deg/s.\n\n"
          "exit status: 0 done, 1 the GCU refused head lock, 3 link error, no answer, interrupted.\n\n",
          out);
    help_link_options(out);
    fputs("\nexample: xfgcu --tcp 192.168.144.108 rate --pitch 0 --yaw 20 --duration 3\n", out);
}

typedef struct rate_args {
    double pitch, yaw, duration;
    int has_pitch, has_yaw, has_duration, json, help;
} rate_args;

enum { O_PITCH = 256, O_YAW, O_DURATION, O_JSON, O_HELP };

static const struct option rate_options[] = {
    {"pitch", required_argument, NULL, O_PITCH},
    {"yaw", required_argument, NULL, O_YAW},
    {"duration", required_argument, NULL, O_DURATION},
    {"json", no_argument, NULL, O_JSON},
    {"help", no_argument, NULL, O_HELP},
    {NULL, 0, NULL, 0},
};

static int take_arg(rate_args *r, const cli_args *a, int id)
{
    switch (id) {
    case O_PITCH: return cli_value_real(a, -MAX_DPS, MAX_DPS, "deg/s, -150..150", &r->pitch, &r->has_pitch);
    case O_YAW: return cli_value_real(a, -MAX_DPS, MAX_DPS, "deg/s, -150..150", &r->yaw, &r->has_yaw);
    case O_DURATION: return cli_value_real(a, 0.02, 3600.0, "seconds, 0.02..3600", &r->duration, &r->has_duration);
    case O_JSON: r->json = 1; return XFGCU_EXIT_OK;
    case O_HELP: r->help = 1; return XFGCU_EXIT_OK;
    case CLI_ARG: return cli_unexpected(a);
    default: return XFGCU_EXIT_USAGE; /* CLI_BAD: said */
    }
}

static int parse_args(rate_args *r, int argc, char **argv)
{
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    memset(r, 0, sizeof(*r));
    cli_args_init(&a, argc, argv, CLI_IN_ORDER, rate_options, "rate");
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        rc = take_arg(r, &a, id);
    }
    if (rc != XFGCU_EXIT_OK || r->help) {
        return rc;
    }
    if (!r->has_pitch) {
        return cli_fail("rate: missing --pitch DPS");
    }
    if (!r->has_yaw) {
        return cli_fail("rate: missing --yaw DPS");
    }
    if (!r->has_duration) {
        return cli_fail("rate: missing --duration S");
    }
    return XFGCU_EXIT_OK;
}

/* Rates for the duration; returns early on a signal or a lost link. */
static void stream_rates(online *o, const rate_args *a, uint32_t *elapsed)
{
    uint32_t start = xf_posix_now_ms(), limit = (uint32_t)(a->duration * 1000.0 + 0.5);
    uint32_t now = start;
    while (xf_ms_since(now, start) < limit && !cli_stop_requested() && xf_client_link(&o->client) != XF_LINK_DOWN) {
        xf_client_set_rates(&o->client, 0.0f, (float)a->pitch, (float)a->yaw, now); /* each loop: the watchdog */
        online_poll(o, 10);
        now = xf_posix_now_ms();
    }
    *elapsed = xf_ms_since(now, start);
    xf_client_set_rates(&o->client, 0.0f, 0.0f, 0.0f, now);
    online_linger(o, ZERO_PACKETS);
}

/* --json: the motion's line, with where it started (@p start, raw 0.01 deg: roll, pitch, yaw). */
static void motion_json(const online *o, const rate_args *a, const int32_t start[3], uint32_t elapsed_ms)
{
    const xf_telemetry *t = xf_client_telemetry(&o->client);
    const char *status = xf_client_link(&o->client) == XF_LINK_DOWN ? "link_lost"
                         : cli_stop_requested()                     ? "interrupted"
                                                                    : "done";
    json_t *obj = cli_json_times(json_object());
    if (obj != NULL) {
        json_object_set_new(obj, "step", json_string("rate"));
        json_object_set_new(obj, "status", json_string(status));
        json_object_set_new(obj, "pitch_dps", json_real(a->pitch));
        json_object_set_new(obj, "yaw_dps", json_real(a->yaw));
        json_object_set_new(obj, "duration_s", json_real(a->duration));
        json_object_set_new(obj, "elapsed_ms", json_integer((json_int_t)elapsed_ms));
        json_object_set_new(obj, "start_roll", online_field_json(o, "cam_roll", start[0]));
        json_object_set_new(obj, "start_pitch", online_field_json(o, "cam_pitch", start[1]));
        json_object_set_new(obj, "start_yaw", online_field_json(o, "cam_yaw", start[2]));
        json_object_set_new(obj, "roll", online_field_json(o, "cam_roll", t->cam_roll));
        json_object_set_new(obj, "pitch", online_field_json(o, "cam_pitch", t->cam_pitch));
        json_object_set_new(obj, "yaw", online_field_json(o, "cam_yaw", t->cam_yaw));
        json_object_set_new(obj, "rate_x", online_field_json(o, "rate_x", t->rate_x));
        json_object_set_new(obj, "rate_y", online_field_json(o, "rate_y", t->rate_y));
        json_object_set_new(obj, "rate_z", online_field_json(o, "rate_z", t->rate_z));
        json_object_set_new(
            obj, "attitude_age_ms",
            json_integer((json_int_t)xf_ms_since(xf_posix_now_ms(), xf_client_health(&o->client)->last_rx_ms)));
        json_object_set_new(obj, "link", json_string(o->desc));
    }
    (void)cli_json_line(obj);
}

/* Once in head lock (online_mode_fn). */
static int turn(online *o, const void *args)
{
    const rate_args *a = (const rate_args *)args;
    const xf_telemetry *t = xf_client_telemetry(&o->client);
    int32_t start[3];
    uint32_t elapsed = 0;
    char where[96];
    start[0] = t->cam_roll;
    start[1] = t->cam_pitch;
    start[2] = t->cam_yaw;
    stream_rates(o, a, &elapsed);
    if (a->json) {
        motion_json(o, a, start, elapsed);
    } else {
        online_attitude_text(t, where, sizeof(where));
        printf("turned %.2f s: pitch %.2f -> %.2f deg, yaw %.2f -> %.2f deg; holding at %s\n", cli_seconds(elapsed),
               (double)xf_cdeg(start[1]), (double)xf_cdeg(t->cam_pitch), (double)xf_cdeg(start[2]),
               (double)xf_cdeg(t->cam_yaw), where);
    }
    if (xf_client_link(&o->client) == XF_LINK_DOWN) {
        return cli_fail_link("rate: link lost on %s after %.2f s", o->desc, cli_seconds(elapsed));
    }
    if (cli_stop_requested()) {
        return cli_fail_link("rate: interrupted after %.2f s of %.2f s (rates stopped)", cli_seconds(elapsed),
                             a->duration);
    }
    return XFGCU_EXIT_OK;
}

int cmd_rate(const cli_link *link, int argc, char **argv)
{
    rate_args a;
    int rc = parse_args(&a, argc, argv);
    if (rc == XFGCU_EXIT_OK && a.help) {
        help_rate(stdout);
    } else if (rc == XFGCU_EXIT_OK) {
        rc = online_run_in_mode(link, "rate", XF_ORDER_HEAD_LOCK, "rate: head_lock", a.json, turn, &a);
    }
    return rc;
}
