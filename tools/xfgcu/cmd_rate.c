/*
 * cmd_rate.c - `xfgcu [LINK] rate --pitch DPS --yaw DPS --duration S`.
 *
 * Head lock: the head_lock command first (with no control quantities),
 * then the desired rates in every packet for S seconds, refreshed each
 * time round the loop (the client's watchdog zeroes rates that are not),
 * then zero rates for a few packets so the gimbal holds where it is.
 */
#include <string.h>

#include "cli.h"
#include "online.h"

#define ZERO_PACKETS 5u
#define MAX_DPS      150.0 /* control quantity 1500 x 0.1 deg/s at zoom 1x */

void help_rate(FILE *out)
{
    fputs("usage: xfgcu [LINK OPTIONS] rate --pitch DPS --yaw DPS --duration S\n\n"
          "Turn the gimbal at a steady rate: switch it to head lock (the head_lock command, run the\n"
          "protocol's way), send the desired angular velocities in every packet for S seconds, then\n"
          "zero rates so it holds still. Prints where it started and where it stopped.\n\n"
          "  --pitch DPS     pitch rate, -150..150 deg/s (positive: the pitch angle grows)\n"
          "  --yaw DPS       yaw rate, -150..150 deg/s (positive: the yaw angle grows)\n"
          "  --duration S    how long, 0.02..3600 s\n\n"
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
    int has_pitch, has_yaw, has_duration, help;
} rate_args;

enum { O_PITCH = 256, O_YAW, O_DURATION, O_HELP };

static const struct option rate_options[] = {
    {"pitch", required_argument, NULL, O_PITCH},
    {"yaw", required_argument, NULL, O_YAW},
    {"duration", required_argument, NULL, O_DURATION},
    {"help", no_argument, NULL, O_HELP},
    {NULL, 0, NULL, 0},
};

static int take_arg(rate_args *r, const cli_args *a, int id)
{
    switch (id) {
    case O_PITCH: return cli_value_real(a, -MAX_DPS, MAX_DPS, "deg/s, -150..150", &r->pitch, &r->has_pitch);
    case O_YAW: return cli_value_real(a, -MAX_DPS, MAX_DPS, "deg/s, -150..150", &r->yaw, &r->has_yaw);
    case O_DURATION: return cli_value_real(a, 0.02, 3600.0, "seconds, 0.02..3600", &r->duration, &r->has_duration);
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

/* Once in head lock (online_mode_fn). */
static int turn(online *o, const void *args)
{
    const rate_args *a = (const rate_args *)args;
    const xf_telemetry *t = xf_client_telemetry(&o->client);
    double pitch0 = (double)xf_cdeg(t->cam_pitch), yaw0 = (double)xf_cdeg(t->cam_yaw);
    uint32_t elapsed = 0;
    char where[96];
    stream_rates(o, a, &elapsed);
    online_attitude_text(t, where, sizeof(where));
    printf("turned %.2f s: pitch %.2f -> %.2f deg, yaw %.2f -> %.2f deg; holding at %s\n", cli_seconds(elapsed), pitch0,
           (double)xf_cdeg(t->cam_pitch), yaw0, (double)xf_cdeg(t->cam_yaw), where);
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
        rc = online_run_in_mode(link, "rate", XF_ORDER_HEAD_LOCK, "rate: head_lock", turn, &a);
    }
    return rc;
}
