/*
 * cmd_demo.c - `xfgcu demo`: the first thing a new user runs.
 *
 * A simulated GCU and a client in one process, over a real TCP
 * connection on 127.0.0.1, and a short tour of what the library does:
 * modes, motion, zoom, photos, ranging, tracking, a failure, calibration,
 * link health. Each step prints what the library sent (>) and what the
 * gimbal reported (<), and checks it: exit 0 when every step behaved,
 * else 1 with the first thing that did not.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "demo.h"
#include "online.h"

/* Where the simulated carrier hovers (sent as GNSS data in the sub frame). */
#define HOME_LAT    47.3977
#define HOME_LON    8.5456
#define HOME_ALT    500.0
#define HOME_HEIGHT 120.0

void help_demo(FILE *out)
{
    fputs("usage: xfgcu demo\n\n"
          "Start a simulated GCU and a client in this process, connected over a real TCP link on\n"
          "127.0.0.1, and run a short tour (about 12 s) of what the library does: head lock and\n"
          "rates, Euler angle control, laser ranging, orthoview, zoom, two photos in a row, tracking,\n"
          "a command that fails, calibration and the link's health. Each step shows what the\n"
          "library sent (>) and what the gimbal reported (<). No hardware, no argument.\n\n"
          "exit status: 0 every step behaved, 1 one did not (the reason is on stderr), 3 the\n"
          "simulator or the connection could not start.\n\n"
          "Then, with a real gimbal: xfgcu --tcp 192.168.144.108 monitor   (see xfgcu --help)\n",
          out);
}

static void print_intro(const demo *d)
{
    char model[64];
    fieldtext_model(d->sim.cfg.gimbal_code, model, sizeof(model));
    printf("xfgcu demo: a simulated gimbal and the xfgcu client talk over a real TCP link on this machine.\n\n");
    printf("  simulated GCU  %s on tcp 127.0.0.1:%u (xfgcu's simulator, protocol V0.1)\n", model,
           (unsigned)d->gcu_link.port);
    printf("  client         %u packets per second, protocol version %u, command timeout %u ms\n",
           (unsigned)d->client.cfg.rate_hz, (unsigned)d->client.cfg.protocol_version,
           (unsigned)d->client.cfg.command_timeout_ms);
    printf("  carrier        hovering %.0f m above %.4f N %.4f E (GNSS data in each packet's sub frame)\n", HOME_HEIGHT,
           HOME_LAT, HOME_LON);
    printf("\nThe host speaks first, %u times a second; the GCU answers each correct packet.\n"
           "'>' is what the library sent, '<' what the gimbal reported.\n",
           (unsigned)d->client.cfg.rate_hz);
    fflush(stdout);
}

/* ---- the telemetry's wire integers in physical units ------------------------------------------ */

static double deg(int32_t raw) { return (double)xf_cdeg(raw); }
static double zoom_x(const xf_telemetry *t) { return (double)xf_zoom_x(t->zoom_cam1); }

static double distance_m(const xf_telemetry *t)
{
    float m = 0.0f;
    (void)xf_distance_m(t->target_distance, &m);
    return (double)m;
}

/* ---- conditions ------------------------------------------------------------------------ */

static int link_up(const demo *d) { return xf_client_link(&d->client) == XF_LINK_UP; }

static int at_target(const demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    return fabs(deg(t->cam_pitch) - d->target_pitch) <= 0.5 &&
           fabs(cli_wrap180(deg(t->cam_yaw) - d->target_yaw)) <= 0.5;
}

static int at_pitch(const demo *d) { return fabs(deg(demo_tele(d)->cam_pitch) - d->target_pitch) <= 0.5; }

static int at_zoom(const demo *d) { return fabs(zoom_x(demo_tele(d)) - d->target_zoom) < 0.05; }

static int has_distance(const demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    return xf_distance_m(t->target_distance, NULL) && (t->pod_status & XF_POD_TARGET_VALID) != 0u;
}

/* ---- the steps ------------------------------------------------------------------------------ */

static void step_connect(demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    char model[64], hw[8], fw[8];
    long ms;
    demo_step(d, "connect");
    demo_sent("null packets (order 0x00, no command) until the GCU answers");
    ms = demo_pump_until(d, 2000, link_up);
    if (demo_check(d, ms >= 0, "no answer from the simulated GCU within 2 s")) {
        fieldtext_model(t->gimbal_code, model, sizeof(model)); /* the one way models and versions are shown */
        fieldtext_version(t->hw_version, hw, sizeof(hw));
        fieldtext_version(t->fw_version, fw, sizeof(fw));
        demo_got("first reply after %ld ms: %s, hardware %s, firmware %s, mode %s, pitch %.2f yaw %.2f deg", ms, model,
                 hw, fw, xf_mode_name(t->gimbal_mode), deg(t->cam_pitch), deg(t->cam_yaw));
    }
}

static void step_pan(demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    xf_command cmd;
    double yaw0 = deg(t->cam_yaw), moved;
    int k;
    demo_step(d, "head lock, then pan at 30 deg/s for 2 s");
    xf_command_init(&cmd, XF_ORDER_HEAD_LOCK);
    demo_command(d, &cmd, "head_lock", XF_CMD_OK, NULL);
    demo_sent("yaw rate +30 deg/s in every packet (refreshed each loop, or the watchdog zeroes it)");
    demo_rates(d, 0.0f, 30.0f);
    demo_mark(d);
    for (k = 1; k <= 4 && demo_pump(d, 500); k++) {
        demo_got("t %.1f s   yaw %6.2f deg   yaw rate %5.1f deg/s", demo_since(d), deg(t->cam_yaw),
                 (double)xf_gcu_rate_dps(t->rate_z, t->version));
    }
    demo_sent("zero rates: the gimbal holds its attitude");
    demo_rates_off(d);
    moved = cli_wrap180(deg(t->cam_yaw) - yaw0);
    demo_got("holding at yaw %.2f deg: turned %.1f deg", deg(t->cam_yaw), moved);
    demo_check(d, fabs(moved - 60.0) < 6.0, "the gimbal turned %.1f deg, not about 60", moved);
}

static void step_point(demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    xf_command cmd;
    long ms;
    demo_step(d, "point at pitch -30, yaw 45 (Euler angle control)");
    xf_command_init(&cmd, XF_ORDER_EULER);
    demo_command(d, &cmd, "euler", XF_CMD_OK, NULL);
    demo_sent("desired Euler angles pitch -30.00, yaw 45.00 deg in every packet");
    d->target_pitch = -30.0;
    d->target_yaw = 45.0;
    xf_client_set_angles(&d->client, 0.0f, -30.0f, 45.0f, xf_posix_now_ms());
    demo_mark(d);
    (void)demo_pump(d, 150);
    demo_got("t %.2f s  on the way: pitch %.2f yaw %.2f deg", demo_since(d), deg(t->cam_pitch), deg(t->cam_yaw));
    ms = demo_pump_until(d, 5000, at_target);
    if (demo_check(d, ms >= 0, "the gimbal did not reach pitch -30 yaw 45 within 5 s")) {
        demo_got("arrived after %.2f s: pitch %.2f yaw %.2f deg (within 0.5 deg)", demo_since(d), deg(t->cam_pitch),
                 deg(t->cam_yaw));
    }
    (void)demo_pump(d, 100);
    xf_client_clear_control(&d->client); /* in Euler mode the gimbal holds without them */
}

static void step_ranging(demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    xf_command cmd;
    long ms;
    demo_step(d, "laser ranging on");
    xf_command_init(&cmd, XF_ORDER_RANGING);
    cmd.value = 2; /* continuous ranging */
    demo_command(d, &cmd, "ranging --on", XF_CMD_OK, NULL);
    ms = demo_pump_until(d, 1000, has_distance);
    if (demo_check(d, ms >= 0, "no valid distance within 1 s")) {
        demo_got("distance %.1f m (%.0f m high, looking 30 deg down)", distance_m(t), HOME_HEIGHT);
        demo_got("target at %.7f N %.7f E, altitude %.1f m: north-east of the carrier, as yaw 45 says",
                 xf_deg7(t->target_latitude), xf_deg7(t->target_longitude), (double)t->target_altitude / 1000.0);
        demo_check(d, fabs(distance_m(t) - 240.0) < 10.0, "distance %.1f m, expected about 240", distance_m(t));
        demo_check(d, xf_deg7(t->target_latitude) > HOME_LAT && xf_deg7(t->target_longitude) > HOME_LON,
                   "the target is not north-east of the carrier");
    }
}

static void step_orthoview(demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    xf_command cmd;
    long ms;
    demo_step(d, "orthoview: look straight down");
    xf_command_init(&cmd, XF_ORDER_ORTHOVIEW);
    demo_command(d, &cmd, "orthoview", XF_CMD_OK, NULL);
    d->target_pitch = -90.0;
    ms = demo_pump_until(d, 3000, at_pitch);
    if (demo_check(d, ms >= 0, "pitch did not reach -90 within 3 s")) {
        (void)demo_pump(d, 60);
        demo_got("mode %s, pitch %.2f deg after %.2f s; distance now %.1f m (straight down)",
                 xf_mode_name(t->gimbal_mode), deg(t->cam_pitch), cli_seconds((uint32_t)ms), distance_m(t));
        demo_check(d, fabs(distance_m(t) - HOME_HEIGHT) < 2.0, "distance %.1f m, expected %.0f", distance_m(t),
                   HOME_HEIGHT);
    }
}

static void step_zoom_to(demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    xf_command cmd;
    double zoom0 = zoom_x(t);
    long ms;
    demo_step(d, "zoom to 5x");
    xf_command_init(&cmd, XF_ORDER_ZOOM_TO);
    cmd.zoom = xf_zoom_to_rate_raw(5.0f); /* -50: a rate, not a fraction of the range */
    demo_command(d, &cmd, "zoom_to --rate 5", XF_CMD_OK, NULL);
    d->target_zoom = 5.0;
    ms = demo_pump_until(d, 3000, at_zoom);
    if (demo_check(d, ms >= 0, "zoom did not reach 5.0x within 3 s (it is %.1fx)", zoom_x(t))) {
        demo_got("zoom of camera 1: %.1fx -> %.1fx", zoom0, zoom_x(t));
    }
}

static void step_zoom_in(demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    xf_command cmd;
    double zoom0 = zoom_x(t), zoom1, zoom2;
    demo_step(d, "zoom in for a second, then stop");
    xf_command_init(&cmd, XF_ORDER_ZOOM_IN);
    demo_command(d, &cmd, "zoom_in", XF_CMD_OK, NULL);
    (void)demo_pump(d, 500);
    demo_got("zooming: %.1fx", zoom_x(t));
    (void)demo_pump(d, 500);
    xf_command_init(&cmd, XF_ORDER_ZOOM_STOP);
    demo_command(d, &cmd, "zoom_stop", XF_CMD_OK, NULL);
    zoom1 = zoom_x(t);
    (void)demo_pump(d, 300);
    zoom2 = zoom_x(t);
    demo_got("zoom %.1fx -> %.1fx, and it stays there (%.1fx 0.3 s later)", zoom0, zoom1, zoom2);
    demo_check(d, zoom1 > zoom0 + 2.0, "zoom did not grow (%.1fx -> %.1fx)", zoom0, zoom1);
    demo_check(d, fabs(zoom2 - zoom1) < 0.15, "zoom kept moving after zoom_stop (%.1fx -> %.1fx)", zoom1, zoom2);
}

static void step_photos(demo *d)
{
    xf_command cmd;
    uint32_t photos0 = d->sim.stats.photos;
    char log[256];
    demo_step(d, "two photos in a row");
    demo_say("the GCU runs an order once while it repeats: two shutters need a null packet between them");
    xf_command_init(&cmd, XF_ORDER_SHUTTER);
    demo_log_start(d);
    demo_command(d, &cmd, "shutter", XF_CMD_OK, NULL);
    demo_command(d, &cmd, "shutter", XF_CMD_OK, NULL);
    demo_log_text(d, log, sizeof(log));
    demo_sent("the packets sent: %s", log);
    demo_got("the simulated camera took %u photos", (unsigned)(d->sim.stats.photos - photos0));
    demo_check(d, d->sim.stats.photos - photos0 == 2u, "%u photos taken, expected 2",
               (unsigned)(d->sim.stats.photos - photos0));
}

static void step_track(demo *d)
{
    const xf_telemetry *t = demo_tele(d);
    xf_command cmd;
    int x0, k;
    demo_step(d, "track the target in a box (the gimbal's own image processor)");
    xf_command_init(&cmd, XF_ORDER_TRACK);
    cmd.value = 1; /* start */
    cmd.x0 = 6000;
    cmd.y0 = 3000;
    cmd.x1 = 7000;
    cmd.y1 = 4000;
    demo_command(d, &cmd, "track --start --box 6000,3000,7000,4000", XF_CMD_OK, NULL);
    (void)demo_pump(d, 40);
    x0 = abs(t->target_offset_x);
    demo_got("mode %s, tracking %s, target offset x %d y %d (of +-1000)", xf_mode_name(t->gimbal_mode),
             (t->pod_status & XF_POD_TRACKING_OK) ? "ok" : "lost", t->target_offset_x, t->target_offset_y);
    for (k = 0; k < 4 && demo_pump(d, 150); k++) {
        demo_got("t %.2f s  target offset x %4d y %4d  (the gimbal turns to centre it: yaw %.2f deg)", demo_since(d),
                 t->target_offset_x, t->target_offset_y, deg(t->cam_yaw));
    }
    demo_check(d, t->gimbal_mode == XF_MODE_TRACK && (t->pod_status & XF_POD_TRACKING_OK) != 0u,
               "the gimbal is not tracking");
    demo_check(d, x0 > 0 && abs(t->target_offset_x) < x0 / 2, "the target offset did not shrink (%d -> %d)", x0,
               t->target_offset_x);
    xf_command_init(&cmd, XF_ORDER_TRACK); /* value 0: stop */
    demo_command(d, &cmd, "track --stop", XF_CMD_OK, NULL);
    (void)demo_pump(d, 40);
    demo_got("mode %s, tracking %s", xf_mode_name(t->gimbal_mode), (t->pod_status & XF_POD_TRACKING_OK) ? "on" : "off");
    demo_check(d, (t->pod_status & XF_POD_TRACKING_OK) == 0u, "tracking did not stop");
}

static void step_failure(demo *d)
{
    xf_command cmd;
    xf_cmd_result r;
    demo_step(d, "a command that fails");
    demo_say("the simulator is told that its thermal camera (camera 2) refuses palette changes");
    xf_sim_set_failure(&d->sim, XF_ORDER_PALETTE, 0x02);
    xf_command_init(&cmd, XF_ORDER_PALETTE); /* cameras 0x02, palette 0 = next */
    demo_command(d, &cmd, "palette --mode 0 (camera mask 0x02)", XF_CMD_FAILED, &r);
    demo_check(d, r.failed_cameras == 0x02, "failed camera mask 0x%02X, expected 0x02", r.failed_cameras);
    xf_sim_set_failure(&d->sim, XF_ORDER_PALETTE, 0);
}

static void step_calibration(demo *d)
{
    xf_command cmd;
    demo_step(d, "calibration (a real gimbal must be kept still meanwhile)");
    demo_say("the GCU answers \"operating\" until it is done; the client keeps sending until the final state");
    xf_command_init(&cmd, XF_ORDER_CALIBRATION);
    demo_command(d, &cmd, "calibration", XF_CMD_OK, NULL);
}

static void step_health(demo *d)
{
    const xf_health *h = xf_client_health(&d->client);
    const xf_parser_stats *ps = xf_client_parser_stats(&d->client);
    demo_step(d, "link health");
    (void)demo_pump(d, 50);
    demo_got("link %s: %u packets sent, %u replies, %u replies/s, %u missing in the last second",
             xf_link_state_name(h->link), (unsigned)h->packets_sent, (unsigned)h->replies, (unsigned)h->reply_rate_hz,
             (unsigned)h->replies_missing);
    demo_got("parser: %u frames, %u CRC errors, %u bytes skipped; simulator: %u correct packets in, %u replies out",
             (unsigned)ps->frames, (unsigned)ps->crc_errors, (unsigned)ps->bytes_skipped,
             (unsigned)d->sim.stats.packets_in, (unsigned)d->sim.stats.replies);
    demo_check(d, h->link == XF_LINK_UP && ps->crc_errors == 0u && h->replies + 5u >= h->packets_sent,
               "the link was not healthy");
}

/* ---- the tour ----------------------------------------------------------------------------- */

static int tour(demo *d)
{
    static void (*const steps[])(demo * d) = {step_connect,   step_pan,     step_point,       step_ranging,
                                              step_orthoview, step_zoom_to, step_zoom_in,     step_photos,
                                              step_track,     step_failure, step_calibration, step_health};
    size_t i;
    print_intro(d);
    for (i = 0; i < sizeof(steps) / sizeof(steps[0]) && !cli_stop_requested(); i++) {
        steps[i](d);
        if (i == 0 && d->failure[0] != '\0') {
            break; /* no link: nothing else can work */
        }
        if (ferror(stdout)) {
            return XFGCU_EXIT_USAGE; /* a tour nobody can read: main() says so */
        }
    }
    if (cli_stop_requested() && d->failure[0] == '\0') {
        snprintf(d->failure, sizeof(d->failure), "interrupted at step %d", d->step);
    }
    printf("\n");
    if (d->failure[0] != '\0') {
        printf("%s after %.1f s.\n", cli_stop_requested() ? "Interrupted" : "Something did not behave",
               cli_seconds(xf_ms_since(xf_posix_now_ms(), d->t0)));
        cli_fail("demo: %s", d->failure);
        return XFGCU_EXIT_FAILED;
    }
    printf("Every step behaved (%.1f s). Next, with a real gimbal:\n"
           "  xfgcu --tcp 192.168.144.108 monitor          Ethernet (the GCU's default address)\n"
           "  xfgcu --serial /dev/ttyUSB0 send shutter     a UART\n"
           "  xfgcu --help                                 everything else\n",
           cli_seconds(xf_ms_since(xf_posix_now_ms(), d->t0)));
    return XFGCU_EXIT_OK;
}

int cmd_demo(const cli_link *link, int argc, char **argv)
{
    static const struct option demo_options[] = {{"help", no_argument, NULL, 'h'}, {NULL, 0, NULL, 0}};
    demo *d;
    cli_args a;
    int rc;
    (void)link; /* its own link */
    cli_args_init(&a, argc, argv, CLI_IN_ORDER, demo_options, "demo");
    switch (cli_next(&a)) {
    case 'h': help_demo(stdout); return XFGCU_EXIT_OK;
    case CLI_ARG: return cli_unexpected(&a);
    case CLI_END: break;
    default: return XFGCU_EXIT_USAGE; /* CLI_BAD: said */
    }
    d = calloc(1, sizeof(*d));
    if (d == NULL) {
        return cli_fail("demo: out of memory");
    }
    d->gnss.latitude_e7 = xf_deg7_raw(HOME_LAT);
    d->gnss.longitude_e7 = xf_deg7_raw(HOME_LON);
    d->gnss.altitude_mm = xf_mm_raw(HOME_ALT);
    d->gnss.relative_height_mm = xf_mm_raw(HOME_HEIGHT);
    d->gnss.satellites = 14;
    cli_signals_init();
    rc = demo_start(d);
    if (rc == XFGCU_EXIT_OK) {
        rc = tour(d);
    }
    demo_stop(d);
    free(d);
    return rc;
}
