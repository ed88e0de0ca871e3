/*
 * cmd_monitor.c - `xfgcu [LINK] monitor [--json] [--count N] [--duration S]`.
 *
 * --json: one object per GCU packet received (the keys of decode --json),
 * flushed line by line so a pipe sees them live. Without it: on a
 * terminal, a screen redrawn in place a few times per second; elsewhere
 * (a pipe, a file, CI), one plain line per second. The client keeps the
 * link going meanwhile (null packets); a lost link is shown and retried.
 * Ends after N packets, S seconds, or SIGINT/SIGTERM (exit 0).
 */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno */

#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "jsonpkt.h"
#include "online.h"

#define SCREEN_MS 250u  /* terminal redraw period */
#define LINE_MS   1000u /* plain line period */

void help_monitor(FILE *out)
{
    fputs("usage: xfgcu [LINK OPTIONS] monitor [--json] [--count N] [--duration S]\n\n"
          "Live telemetry while the link is kept up with null packets.\n"
          "On a terminal: a screen redrawn in place (mode, attitude, relative angles, rates, zoom,\n"
          "distance, target position, status flags, link state, reply rate, missing replies,\n"
          "model and versions). Otherwise (a pipe or a file): one plain line per second.\n\n"
          "  --json        one JSON object per GCU packet received, with the keys of\n"
          "                `xfgcu decode --json`, one per line\n"
          "  --count N     stop after N packets from the GCU (1..1000000000)\n"
          "  --duration S  stop after S seconds (0.1..31536000)\n"
          "Without --count or --duration it runs until Ctrl-C (exit 0). A lost link is shown (with\n"
          "--json: a note on stderr) and the link is retried.\n\n",
          out);
    help_link_options(out);
    fputs("\nexample: xfgcu --udp 192.168.144.108 monitor --json --count 50 > telemetry.jsonl\n", out);
}

typedef struct monitor {
    online *o;
    int json, help, tty;
    long count;
    double duration;
    int has_count, has_duration;
    uint32_t received;
    uint32_t start_ms; /* when the link was opened */
    uint8_t link_seen; /* the link state last seen, for notes */
    uint8_t was_up;
} monitor;

/* ---- arguments ---------------------------------------------------------------------- */

enum { O_JSON = 256, O_COUNT, O_DURATION, O_HELP };

static const struct option monitor_options[] = {
    {"json", no_argument, NULL, O_JSON},
    {"count", required_argument, NULL, O_COUNT},
    {"duration", required_argument, NULL, O_DURATION},
    {"help", no_argument, NULL, O_HELP},
    {NULL, 0, NULL, 0},
};

static int take_arg(monitor *m, const cli_args *a, int id)
{
    switch (id) {
    case O_JSON: m->json = 1; return XFGCU_EXIT_OK;
    case O_COUNT:
        return cli_value_long(a, 1, 1000000000L, "a number of packets, 1..1000000000", &m->count, &m->has_count);
    case O_DURATION:
        return cli_value_real(a, 0.1, 31536000.0, "seconds, 0.1..31536000", &m->duration, &m->has_duration);
    case O_HELP: m->help = 1; return XFGCU_EXIT_OK;
    case CLI_ARG: return cli_unexpected(a);
    default: return XFGCU_EXIT_USAGE; /* CLI_BAD: said */
    }
}

/* ---- callbacks ------------------------------------------------------------------------ */

static void on_bytes(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    monitor *m = (monitor *)user;
    (void)now_ms;
    if (dir != XF_DIR_GCU || (m->has_count && m->received >= (uint32_t)m->count)) {
        return;
    }
    m->received++;
    if (m->json) {
        (void)jsonpkt_print(data, len, XF_DIR_GCU, POD_READ_AUTO, stdout);
        fflush(stdout);
    }
}

static void on_link(void *user, xf_link_state state)
{
    monitor *m = (monitor *)user;
    int changed = (state == XF_LINK_DOWN) != (m->link_seen == XF_LINK_DOWN);
    if (m->json && m->was_up && changed) {
        cli_note("link %s on %s%s", state == XF_LINK_DOWN ? "down" : "back", m->o->desc,
                 state == XF_LINK_DOWN ? ": no reply for a second; retrying" : "");
    }
    m->was_up |= (uint8_t)(state == XF_LINK_UP);
    m->link_seen = (uint8_t)state;
}

/* ---- the screen ------------------------------------------------------------------------- */

static const char *yes_no(unsigned v, const char *yes, const char *no) { return v != 0u ? yes : no; }

/* The pod status flags in the byte order the word itself shows (as decode's JSON reads them,
 * docs/protocol.md §11.7); little-endian when it does not tell. */
static uint16_t pod_flags(const xf_telemetry *t)
{
    return xf_pod_flags(t->pod_status, xf_pod_status_order(t->pod_status));
}

static void distance_text(const xf_telemetry *t, const xf_telemetry_units *u, char *buf, size_t cap)
{
    if (u->distance_valid && (pod_flags(t) & XF_POD_TARGET_VALID) != 0u) {
        snprintf(buf, cap, "%.1f m, target lat %.7f lon %.7f alt %.1f m", (double)u->target_distance_m,
                 xf_deg7(t->target_latitude), xf_deg7(t->target_longitude), (double)t->target_altitude / 1000.0);
    } else {
        snprintf(buf, cap, "no target");
    }
}

/* The client counts replies over whole seconds: "-" until the first one is over. */
static void rate_text(const monitor *m, char *buf, size_t cap)
{
    const xf_health *h = xf_client_health(&m->o->client);
    if (xf_ms_since(xf_posix_now_ms(), m->start_ms) < 1000u) {
        snprintf(buf, cap, "- replies/s, - missing/s");
    } else {
        snprintf(buf, cap, "%u replies/s, %u missing/s", (unsigned)h->reply_rate_hz, (unsigned)h->replies_missing);
    }
}

static void draw_v2(const xf_telemetry *t)
{
    if (t->version < XF_PROTOCOL_V2) {
        return;
    }
    printf("thermal     status 0x%02X   camera status 0x%04X (%s%s)   time zone UTC%+d\n", t->thermal_status,
           t->camera_status, yes_no(t->camera_status & XF_CAMERA_RECORDING, "recording", "not recording"),
           yes_no(t->camera_status & XF_CAMERA_OSD_ON, ", OSD on", ""), t->time_zone);
}

static void draw_screen(const monitor *m)
{
    const xf_telemetry *t = xf_client_telemetry(&m->o->client);
    const xf_health *h = xf_client_health(&m->o->client);
    const xf_parser_stats *ps = xf_client_parser_stats(&m->o->client);
    const char *model = xf_gimbal_model(t->gimbal_code);
    xf_telemetry_units u;
    char dist[160], rate[64];
    const char *mode = xf_mode_name(t->gimbal_mode);
    (void)xf_telemetry_convert(t, &u);
    distance_text(t, &u, dist, sizeof(dist));
    rate_text(m, rate, sizeof(rate));
    printf("\033[H\033[2J"); /* cursor home, clear */
    printf("xfgcu monitor: %s   (Ctrl-C to quit)\n\n", m->o->desc);
    printf("gimbal      %s (code %u), hardware %u, firmware %u, protocol %u\n", model ? model : "unknown model",
           t->gimbal_code, t->hw_version, t->fw_version, t->version);
    printf("mode        %s (0x%02X)\n", mode ? mode : "unknown", t->gimbal_mode);
    printf("attitude    roll %8.2f   pitch %8.2f   yaw %8.2f deg\n", (double)u.cam_roll_deg, (double)u.cam_pitch_deg,
           (double)u.cam_yaw_deg);
    printf("relative    x    %8.2f   y     %8.2f   z   %8.2f deg (to the carrier)\n", (double)u.rel_x_deg,
           (double)u.rel_y_deg, (double)u.rel_z_deg);
    printf("rates       x    %8.2f   y     %8.2f   z   %8.2f deg/s\n", (double)u.rate_x_dps, (double)u.rate_y_dps,
           (double)u.rate_z_dps);
    printf("zoom        camera 1 %.1fx   camera 2 %.1fx\n", (double)u.zoom_cam1, (double)u.zoom_cam2);
    printf("distance    %s\n", dist);
    printf("tracking    %s, target offset x %d y %d\n", yes_no(pod_flags(t) & XF_POD_TRACKING_OK, "on", "off"),
           t->target_offset_x, t->target_offset_y);
    printf("flags       ranging %s, night vision %s, lighting %s, error code 0x%04X\n",
           yes_no(pod_flags(t) & XF_POD_RANGING_ON, "on", "off"),
           yes_no(pod_flags(t) & XF_POD_NIGHT_VISION_ON, "on", "off"),
           yes_no(pod_flags(t) & XF_POD_LIGHTING_ON, "on", "off"), t->error_code);
    draw_v2(t);
    printf("link        %s, %s, %u sent, %u received\n", xf_link_state_name(h->link), rate, (unsigned)h->packets_sent,
           (unsigned)h->replies);
    printf("parser      %u CRC errors, %u length errors, %u bytes skipped\n", (unsigned)ps->crc_errors,
           (unsigned)ps->length_errors, (unsigned)ps->bytes_skipped);
    fflush(stdout);
}

static void print_line(const monitor *m, uint32_t elapsed)
{
    const xf_telemetry *t = xf_client_telemetry(&m->o->client);
    const xf_health *h = xf_client_health(&m->o->client);
    const char *mode = xf_mode_name(t->gimbal_mode);
    xf_telemetry_units u;
    char dist[160], rate[64];
    (void)xf_telemetry_convert(t, &u);
    distance_text(t, &u, dist, sizeof(dist));
    rate_text(m, rate, sizeof(rate));
    printf("%7.1f s  link %s, %s  mode %s  roll %.2f pitch %.2f yaw %.2f deg  zoom %.1fx/%.1fx  %s%s\n",
           cli_seconds(elapsed), xf_link_state_name(h->link), rate, mode ? mode : "unknown", (double)u.cam_roll_deg,
           (double)u.cam_pitch_deg, (double)u.cam_yaw_deg, (double)u.zoom_cam1, (double)u.zoom_cam2, dist,
           yes_no(pod_flags(t) & XF_POD_TRACKING_OK, "  tracking", ""));
    fflush(stdout);
}

/* ---- the loop ------------------------------------------------------------------------------ */

static int finished(const monitor *m, uint32_t elapsed)
{
    return cli_stop_requested() || ferror(stdout) || (m->has_count && m->received >= (uint32_t)m->count) ||
           (m->has_duration && cli_seconds(elapsed) >= m->duration);
}

static void run_loop(monitor *m)
{
    uint32_t start = xf_posix_now_ms(), last = 0, elapsed = 0;
    int first = 1;
    while (!finished(m, elapsed)) {
        uint32_t period = m->tty ? SCREEN_MS : LINE_MS;
        if (!m->json && (first || xf_ms_since(elapsed, last) >= period)) {
            if (m->tty) {
                draw_screen(m);
            } else {
                print_line(m, elapsed);
            }
            last = elapsed;
            first = 0;
        }
        online_poll(m->o, 50);
        elapsed = xf_ms_since(xf_posix_now_ms(), start);
    }
    if (!m->json && m->tty) {
        draw_screen(m); /* the last state stays on the screen */
    }
}

int cmd_monitor(const cli_link *link, int argc, char **argv)
{
    monitor m;
    online_hooks hooks;
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    memset(&m, 0, sizeof(m));
    cli_args_init(&a, argc, argv, CLI_IN_ORDER, monitor_options, "monitor");
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        rc = take_arg(&m, &a, id);
    }
    if (rc != XFGCU_EXIT_OK || m.help) {
        if (m.help && rc == XFGCU_EXIT_OK) {
            help_monitor(stdout);
        }
        return rc;
    }
    m.tty = isatty(fileno(stdout));
    memset(&hooks, 0, sizeof(hooks));
    hooks.on_bytes = on_bytes;
    hooks.on_link = on_link;
    hooks.user = &m;
    cli_signals_init();
    m.start_ms = xf_posix_now_ms();
    m.o = online_new();
    rc = (m.o != NULL) ? online_open(m.o, link, "monitor", &hooks) : XFGCU_EXIT_USAGE;
    if (rc == XFGCU_EXIT_OK) {
        run_loop(&m);
    }
    online_free(m.o);
    return rc;
}
