/*
 * cmd_point.c - `xfgcu [LINK] point --pitch DEG --yaw DEG [--roll DEG]`.
 *
 * Euler angle control: the euler command first (with no control
 * quantities, which the mode before it would read as rates), then the
 * desired angles in every packet until the reported attitude is within
 * TOLERANCE of them. Prints the attitude reached.
 */
#include <math.h>
#include <string.h>

#include "cli.h"
#include "online.h"

#define TOLERANCE_DEG 0.5
#define NULLS_AFTER   3u

void help_point(FILE *out)
{
    fputs("usage: xfgcu [LINK OPTIONS] point --pitch DEG --yaw DEG [--roll DEG] [--wait S]\n\n"
          "Point the gimbal: switch it to Euler angle control (the euler command, run the protocol's\n"
          "way), then send the desired absolute angles in every packet until the attitude the GCU\n"
          "reports is within 0.5 deg of them. Prints the attitude reached.\n\n"
          "  --pitch DEG   desired pitch, -180..180 deg (down is negative)\n"
          "  --yaw DEG     desired yaw, -360..360 deg (absolute heading; 45 and -315 are the same)\n"
          "  --roll DEG    desired roll, -180..180 deg (default 0, and then not waited for)\n"
          "  --wait S      how long the gimbal may take to get there, 0.1..600 s (default 10)\n\n"
          "exit status: 0 reached, 1 the GCU refused Euler angle control, 3 link error, no answer\n"
          "or not there in time.\n\n",
          out);
    help_link_options(out);
    fputs("\nexample: xfgcu --tcp 192.168.144.108 point --pitch -30 --yaw 45\n", out);
}

typedef struct point_args {
    double pitch, yaw, roll, wait_s;
    int has_pitch, has_yaw, has_roll, has_wait, help;
} point_args;

static int take_arg(point_args *a, int argc, char **argv, int *i)
{
    int rc =
        cli_opt_real("point", argc, argv, i, "--pitch", -180.0, 180.0, "degrees, -180..180", &a->pitch, &a->has_pitch);
    if (rc < 0) {
        rc = cli_opt_real("point", argc, argv, i, "--yaw", -360.0, 360.0, "degrees, -360..360", &a->yaw, &a->has_yaw);
    }
    if (rc < 0) {
        rc =
            cli_opt_real("point", argc, argv, i, "--roll", -180.0, 180.0, "degrees, -180..180", &a->roll, &a->has_roll);
    }
    if (rc < 0) {
        rc = cli_opt_real("point", argc, argv, i, "--wait", 0.1, 600.0, "seconds, 0.1..600", &a->wait_s, &a->has_wait);
    }
    if (rc < 0 && strcmp(argv[*i], "--help") == 0) {
        a->help = 1;
        rc = XFGCU_EXIT_OK;
    }
    return (rc < 0) ? cli_unexpected("point", argv[*i]) : rc;
}

static int parse_args(point_args *a, int argc, char **argv)
{
    int i, rc = XFGCU_EXIT_OK;
    memset(a, 0, sizeof(*a));
    a->wait_s = 10.0;
    for (i = 1; i < argc && rc == XFGCU_EXIT_OK; i++) {
        rc = take_arg(a, argc, argv, &i);
    }
    if (rc == XFGCU_EXIT_OK && !a->help && !a->has_pitch) {
        rc = cli_fail("point: missing --pitch DEG");
    }
    if (rc == XFGCU_EXIT_OK && !a->help && !a->has_yaw) {
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

static int stream_angles(online *o, const point_args *a)
{
    uint32_t start = xf_posix_now_ms(), limit = (uint32_t)(a->wait_s * 1000.0);
    const xf_telemetry *t = xf_client_telemetry(&o->client);
    char where[96];
    while (!arrived(&o->client, start, a)) {
        uint32_t now = xf_posix_now_ms();
        if (cli_stop_requested() || xf_ms_since(now, start) >= limit || xf_client_link(&o->client) == XF_LINK_DOWN) {
            online_attitude_text(t, where, sizeof(where));
            if (xf_client_link(&o->client) == XF_LINK_DOWN) {
                return cli_fail_link("point: link lost on %s (at %s)", o->desc, where);
            }
            return cli_fail_link("point: %s: the gimbal is at %s, not within %.1f deg of pitch %.2f yaw %.2f",
                                 cli_stop_requested() ? "interrupted" : "not there in time", where, TOLERANCE_DEG,
                                 a->pitch, a->yaw);
        }
        xf_client_set_angles(&o->client, (float)a->roll, (float)a->pitch, (float)a->yaw, now);
        online_poll(o, 20);
    }
    online_linger(o, NULLS_AFTER);
    online_attitude_text(t, where, sizeof(where));
    printf("reached %s in %.2f s\n", where, cli_seconds(xf_ms_since(xf_posix_now_ms(), start)));
    return XFGCU_EXIT_OK;
}

static int run_point(const cli_link *link, const point_args *a)
{
    online *o = online_new();
    xf_command cmd;
    xf_cmd_result r;
    int rc = (o != NULL) ? online_open(o, link, "point", NULL) : XFGCU_EXIT_USAGE;
    if (rc == XFGCU_EXIT_OK) {
        xf_client_clear_control(&o->client); /* no angles until the mode reads them as angles */
        xf_command_init(&cmd, XF_ORDER_EULER);
        rc = online_run(o, &cmd, &r, NULL, NULL);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = online_result_exit(o, "point: euler (Euler angle control)", &r);
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = stream_angles(o, a);
    }
    online_free(o);
    return rc;
}

int cmd_point(const cli_link *link, int argc, char **argv)
{
    point_args a;
    int rc = parse_args(&a, argc, argv);
    if (rc != XFGCU_EXIT_OK) {
        return rc;
    }
    if (a.help) {
        help_point(stdout);
        return XFGCU_EXIT_OK;
    }
    cli_signals_init();
    return run_point(link, &a);
}
