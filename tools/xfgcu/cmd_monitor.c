/*
 * cmd_monitor.c - `xfgcu [LINK] monitor [--json] [--raw] [--count N] [--duration S] [--wait S]`.
 *
 * --json: one object per GCU packet received (the keys of decode --json,
 * after time_mono and time_utc), and one per change of the link's state once
 * it was up ({"event": "link", "state": "down", ...}), flushed line by line so a
 * pipe sees them live. Without it: on a terminal, a screen redrawn in
 * place a few times per second; elsewhere (a pipe, a file, CI), one plain
 * line per second. Every figure shown carries its age: how long since the
 * reply it came from (the main frame's for the attitude, the sub frame's
 * for the zoom...), so that a lost link never shows old figures as if
 * they were current. The client keeps the link going meanwhile (null
 * packets); a lost link is shown and retried. Ends after N packets, S
 * seconds, or SIGINT/SIGTERM (exit 0).
 *
 * --wait S: the GCU may take S seconds to come up (a gimbal powering on);
 * a person at a terminal waits until Ctrl-C by default, a script --timeout.
 *
 * The client's health (the version the GCU answered, its judgement of the
 * link, the frames its parser gave up) is shown too: a row of the screen,
 * the end of each plain line ("health: ..."), and with --json an
 * {"event": "health"} object when the GCU comes up and when a figure changes
 * (at most once a second).
 * Packets that the vendor's text does not allow (warn.h) are counted, and
 * the last warning shown: a row of the screen, a "warning:" line of the
 * plain output (the packet objects of --json carry their "warnings").
 */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno */

#include <stdarg.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "jsonpkt.h"
#include "online.h"
#include "warn.h"

#define SCREEN_MS 250u      /* terminal redraw period */
#define LINE_MS   1000u     /* plain line period */
#define MAX_WAIT  1000000.0 /* --wait, seconds: its milliseconds fit 32 bits */

void help_monitor(FILE *out)
{
    fputs("usage: xfgcu [LINK OPTIONS] monitor [--json] [--raw] [--count N] [--duration S] [--wait S]\n\n"
          "Live telemetry while the link is kept up with null packets.\n"
          "On a terminal: a screen redrawn in place (mode, attitude, relative angles, rates, zoom,\n"
          "distance, target position, status flags, link state, reply rate, missing replies,\n"
          "model and versions), each figure with its age: how long since the reply it came from.\n"
          "Otherwise (a pipe or a file): one plain line per second, with the ages in brackets.\n\n"
          "  --json        one JSON object per line: each GCU packet received, with time_mono and\n"
          "                time_utc then the keys of `xfgcu decode --json`, and each change of the\n"
          "                link once it was up, {\"event\": \"link\", \"state\": \"stale\"|\"down\"|\"up\", ...}\n"
          "  --raw         the fields as wire integers, not engineering units (JSON and screen)\n"
          "  --count N     stop after N packets from the GCU (1..1000000000)\n"
          "  --duration S  stop after S seconds (0.1..31536000)\n"
          "  --wait S      wait up to S seconds (0..1000000) for the GCU to come up: the link to\n"
          "                open and the first reply. Default: on a terminal, until Ctrl-C; otherwise\n"
          "                --timeout, as --wait 0\n"
          "Without --count or --duration it runs until Ctrl-C (exit 0). A lost link is shown (with\n"
          "--json: a link event, and a note on stderr) and the link is retried.\n"
          "The client's health is shown too (the protocol version the GCU answered, whether the link\n"
          "keeps order, the reorder bound, replies out of turn, frames given up): a row of the\n"
          "screen, the end of each plain line, {\"event\": \"health\", ...} with --json. What the\n"
          "vendor's text does not allow in a reply is warned about (decode --help).\n\n",
          out);
    help_link_options(out);
    fputs("\nexample: xfgcu --udp 192.168.144.108 monitor --json --count 50 > telemetry.jsonl\n", out);
}

typedef struct monitor {
    online *o;
    int json, help, tty;
    text_view view; /* --raw: wire integers */
    long count;
    double duration, wait_s;
    int has_count, has_duration, has_wait;
    uint32_t received;
    uint32_t start_ms; /* when the GCU came up */
    uint8_t link_seen; /* the link state last seen, for notes */
    uint8_t was_up;
    char health[256];        /* the health last shown (online_health_text()) */
    uint32_t health_ms;      /* when */
    uint32_t warned;         /* GCU packets with warnings */
    uint32_t warned_shown;   /* of which already said by a plain line */
    char warning[WARN_TEXT]; /* the last warning */
} monitor;

/* ---- arguments ---------------------------------------------------------------------- */

enum { O_JSON = 256, O_COUNT, O_DURATION, O_WAIT, O_HELP };

static const struct option monitor_options[] = {
    {"json", no_argument, NULL, O_JSON},
    {"count", required_argument, NULL, O_COUNT},
    {"duration", required_argument, NULL, O_DURATION},
    {"wait", required_argument, NULL, O_WAIT},
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
    case O_WAIT: return cli_value_real(a, 0.0, MAX_WAIT, "seconds, 0..1000000", &m->wait_s, &m->has_wait);
    case O_HELP: m->help = 1; return XFGCU_EXIT_OK;
    case CLI_ARG: return cli_unexpected(a);
    default: return XFGCU_EXIT_USAGE; /* CLI_BAD: said */
    }
}

/* ---- callbacks ------------------------------------------------------------------------ */

/* --json: the packet's object of decode --json, after the two times. */
static void json_packet(const uint8_t *data, size_t len, text_view view)
{
    json_t *pkt = jsonpkt_from_wire(data, len, XF_DIR_GCU, POD_READ_AUTO, view);
    json_t *obj = cli_json_times(json_object());
    if (pkt == NULL || obj == NULL || json_object_update(obj, pkt) != 0) {
        json_decref(obj);
        obj = NULL; /* cli_json_line() fails on it: out of memory */
    }
    json_decref(pkt);
    (void)cli_json_line(obj);
}

static void on_bytes(void *user, xf_direction dir, const uint8_t *data, size_t len, uint32_t now_ms)
{
    monitor *m = (monitor *)user;
    warn_list w;
    (void)now_ms;
    if (dir != XF_DIR_GCU || (m->has_count && m->received >= (uint32_t)m->count)) {
        return;
    }
    m->received++;
    if (warn_packet(data, len, dir, &w) > 0u && w.n > 0u) {
        m->warned++;
        snprintf(m->warning, sizeof(m->warning), "%s", w.text[w.n - 1u]);
    }
    if (m->json) {
        json_packet(data, len, m->view);
    }
}

/* --json: {"event": "link", "state": ..., "link": ..., "reply_age_ms": ..., times}. */
static void json_link_event(const monitor *m, xf_link_state state)
{
    const xf_health *h = xf_client_health(&m->o->client);
    json_t *obj = cli_json_times(json_object());
    if (obj != NULL) {
        json_object_set_new(obj, "event", json_string("link"));
        json_object_set_new(obj, "state", json_string(xf_link_state_name(state)));
        json_object_set_new(obj, "link", json_string(m->o->desc));
        json_object_set_new(obj, "reply_age_ms",
                            h->replies == 0u ? json_null()
                                             : json_integer((json_int_t)xf_ms_since(xf_posix_now_ms(), h->last_rx_ms)));
    }
    (void)cli_json_line(obj);
}

static void on_link(void *user, xf_link_state state)
{
    monitor *m = (monitor *)user;
    int changed = (state == XF_LINK_DOWN) != (m->link_seen == XF_LINK_DOWN);
    if (m->json && m->was_up) { /* monitor starts when the link is up: the changes after that */
        json_link_event(m, state);
    }
    if (m->json && m->was_up && changed) {
        cli_note("link %s on %s%s", state == XF_LINK_DOWN ? "down" : "back", m->o->desc,
                 state == XF_LINK_DOWN ? ": no reply for a second; retrying" : "");
    }
    m->was_up |= (uint8_t)(state == XF_LINK_UP);
    m->link_seen = (uint8_t)state;
}

/* ---- ages --------------------------------------------------------------------------------- */

/* Each figure comes from the main frame (in every reply: mode, attitude, rates, pod status) or
 * the sub frame (kept from the last one: model, versions, zoom, distance, V0.2 status). */
typedef struct ages {
    char main[24], sub[24]; /* "0.02 s", or "-" when none came yet */
} ages;

static void age_text(char *buf, size_t cap, int have, uint32_t at_ms, uint32_t now)
{
    if (have) {
        snprintf(buf, cap, "%.2f s", cli_seconds(xf_ms_since(now, at_ms)));
    } else {
        snprintf(buf, cap, "-");
    }
}

static void get_ages(const monitor *m, ages *a)
{
    const xf_telemetry *t = xf_client_telemetry(&m->o->client);
    const xf_health *h = xf_client_health(&m->o->client);
    uint32_t now = xf_posix_now_ms();
    age_text(a->main, sizeof(a->main), t->have_main, h->last_rx_ms, now);
    age_text(a->sub, sizeof(a->sub), t->have_sub, t->sub_ms, now);
}

/* ---- the screen ------------------------------------------------------------------------- */

static const char *yes_no(unsigned v, const char *yes, const char *no) { return v != 0u ? yes : no; }

/* The pod status flags in the byte order the word itself shows (as decode's JSON reads them,
 * docs/protocol.md §11.7); little-endian when it does not tell. */
static uint16_t pod_flags(const xf_telemetry *t)
{
    return xf_pod_flags(t->pod_status, xf_pod_status_order(t->pod_status));
}

static void distance_text(const xf_telemetry *t, const xf_telemetry_units *u, text_view view, char *buf, size_t cap)
{
    if (view == TEXT_RAW) {
        snprintf(buf, cap, "target_distance %ld, target_latitude %ld target_longitude %ld target_altitude %ld",
                 (long)t->target_distance, (long)t->target_latitude, (long)t->target_longitude,
                 (long)t->target_altitude);
    } else if (u->distance_valid && (pod_flags(t) & XF_POD_TARGET_VALID) != 0u) {
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

/* One row of the screen: its label, its text, and the age of what it shows (NULL: none). */
static void row(const char *label, const char *age, const char *fmt, ...) CLI_PRINTF(3, 4);

static void row(const char *label, const char *age, const char *fmt, ...)
{
    char text[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof(text), fmt, ap);
    va_end(ap);
    printf("%-12s%-58s %s\n", label, text, age != NULL ? age : ""); /* 77 columns with the age */
}

static void draw_gimbal(const xf_telemetry *t, const ages *a)
{
    char model[64], hw[8], fw[8];
    fieldtext_model(t->gimbal_code, model, sizeof(model));
    fieldtext_version(t->hw_version, hw, sizeof(hw));
    fieldtext_version(t->fw_version, fw, sizeof(fw));
    row("gimbal", a->sub, "%s, hardware %s, firmware %s, protocol %u", model, hw, fw, t->version);
    row("error code", a->sub, "0x%04X", t->error_code);
    if (t->version >= XF_PROTOCOL_V2) {
        row("thermal", a->sub, "status 0x%02X", t->thermal_status);
        row("camera", a->sub, "status 0x%04X (%s%s)", t->camera_status,
            yes_no(t->camera_status & XF_CAMERA_RECORDING, "recording", "not recording"),
            yes_no(t->camera_status & XF_CAMERA_OSD_ON, ", OSD on", ""));
        row("time zone", a->sub, "UTC%+d", t->time_zone);
    }
}

/* The angles and rates as wire integers (--raw). */
static void draw_main_raw(const xf_telemetry *t, const ages *a)
{
    row("attitude", a->main, "cam_roll %6d cam_pitch %6d cam_yaw %6u", t->cam_roll, t->cam_pitch, (unsigned)t->cam_yaw);
    row("relative", a->main, "rel_angle_x %6d y %6d z %6d", t->rel_angle_x, t->rel_angle_y, t->rel_angle_z);
    row("rates", a->main, "rate_x %6d rate_y %6d rate_z %6d", t->rate_x, t->rate_y, t->rate_z);
}

static void draw_main(const xf_telemetry *t, const xf_telemetry_units *u, const ages *a, text_view view)
{
    const char *mode = xf_mode_name(t->gimbal_mode);
    row("mode", a->main, "%s (0x%02X)", mode ? mode : "unknown", t->gimbal_mode);
    if (view == TEXT_RAW) {
        draw_main_raw(t, a);
    } else {
        row("attitude", a->main, "roll %8.2f   pitch %8.2f   yaw %8.2f deg", (double)u->cam_roll_deg,
            (double)u->cam_pitch_deg, (double)u->cam_yaw_deg);
        row("relative", a->main, "x    %8.2f   y     %8.2f   z   %8.2f deg", (double)u->rel_x_deg, /* to the carrier */
            (double)u->rel_y_deg, (double)u->rel_z_deg);
        row("rates", a->main, "x    %8.2f   y     %8.2f   z   %8.2f deg/s", (double)u->rate_x_dps,
            (double)u->rate_y_dps, (double)u->rate_z_dps);
    }
    row("tracking", a->main, "%s, target offset x %d y %d", yes_no(pod_flags(t) & XF_POD_TRACKING_OK, "on", "off"),
        t->target_offset_x, t->target_offset_y);
    row("flags", a->main, "ranging %s, night vision %s, lighting %s",
        yes_no(pod_flags(t) & XF_POD_RANGING_ON, "on", "off"),
        yes_no(pod_flags(t) & XF_POD_NIGHT_VISION_ON, "on", "off"),
        yes_no(pod_flags(t) & XF_POD_LIGHTING_ON, "on", "off"));
}

static void draw_screen(const monitor *m)
{
    const xf_telemetry *t = xf_client_telemetry(&m->o->client);
    const xf_health *h = xf_client_health(&m->o->client);
    const xf_parser_stats *ps = xf_client_parser_stats(&m->o->client);
    xf_telemetry_units u;
    char dist[160], rate[64], health[256];
    ages a;
    (void)xf_telemetry_convert(t, &u);
    distance_text(t, &u, m->view, dist, sizeof(dist));
    rate_text(m, rate, sizeof(rate));
    get_ages(m, &a);
    printf("\033[H\033[2J"); /* cursor home, clear */
    printf("xfgcu monitor: %s   (Ctrl-C to quit)\n", m->o->desc);
    printf("%s\n\n", h->link == XF_LINK_UP ? ""
                                           : "NO CURRENT DATA: the link is not up; the figures are the last received, "
                                             "as old as their age says");
    printf("%-70s %s\n", "", "age");
    draw_gimbal(t, &a);
    draw_main(t, &u, &a, m->view);
    if (m->view == TEXT_RAW) {
        row("zoom", a.sub, "zoom_cam1 %u   zoom_cam2 %u", (unsigned)t->zoom_cam1, (unsigned)t->zoom_cam2);
    } else {
        row("zoom", a.sub, "camera 1 %.1fx   camera 2 %.1fx", (double)u.zoom_cam1, (double)u.zoom_cam2);
    }
    row("distance", a.sub, "%s", dist);
    row("link", a.main, "%s, %s, %u sent, %u received", xf_link_state_name(h->link), rate, (unsigned)h->packets_sent,
        (unsigned)h->replies);
    row("parser", NULL, "%u CRC errors, %u length errors, %u bytes skipped, %u given up", (unsigned)ps->crc_errors,
        (unsigned)ps->length_errors, (unsigned)ps->bytes_skipped, (unsigned)ps->given_up);
    online_health_text(m->o, health, sizeof(health));
    printf("%-12s%s\n", "health", health); /* one line: it does not fit the columns */
    if (m->warned > 0u) {
        printf("%-12s%u packets; last: %s\n", "warnings", (unsigned)m->warned, m->warning);
    }
    fflush(stdout);
}

static void print_line(const monitor *m, uint32_t elapsed)
{
    const xf_telemetry *t = xf_client_telemetry(&m->o->client);
    const xf_health *h = xf_client_health(&m->o->client);
    const char *mode = xf_mode_name(t->gimbal_mode);
    xf_telemetry_units u;
    char dist[160], rate[64], health[256];
    ages a;
    (void)xf_telemetry_convert(t, &u);
    distance_text(t, &u, m->view, dist, sizeof(dist));
    rate_text(m, rate, sizeof(rate));
    get_ages(m, &a);
    online_health_text(m->o, health, sizeof(health));
    if (m->view == TEXT_RAW) {
        printf("%7.1f s  link %s, %s  mode %s  cam_roll %d cam_pitch %d cam_yaw %u%s (age %s)  zoom_cam1 %u "
               "zoom_cam2 %u  %s (age %s)  health: %s\n",
               cli_seconds(elapsed), xf_link_state_name(h->link), rate, mode ? mode : "unknown", t->cam_roll,
               t->cam_pitch, (unsigned)t->cam_yaw, yes_no(pod_flags(t) & XF_POD_TRACKING_OK, "  tracking", ""), a.main,
               (unsigned)t->zoom_cam1, (unsigned)t->zoom_cam2, dist, a.sub, health);
        fflush(stdout);
        return;
    }
    printf("%7.1f s  link %s, %s  mode %s  roll %.2f pitch %.2f yaw %.2f deg%s (age %s)  zoom %.1fx/%.1fx  %s "
           "(age %s)  health: %s\n",
           cli_seconds(elapsed), xf_link_state_name(h->link), rate, mode ? mode : "unknown", (double)u.cam_roll_deg,
           (double)u.cam_pitch_deg, (double)u.cam_yaw_deg, yes_no(pod_flags(t) & XF_POD_TRACKING_OK, "  tracking", ""),
           a.main, (double)u.zoom_cam1, (double)u.zoom_cam2, dist, a.sub, health);
    fflush(stdout);
}

/* ---- health and warnings ------------------------------------------------------------------- */

/* --json: {"event": "health", "link": ..., the figures of online_health_json(), times}. */
static void json_health(const monitor *m)
{
    json_t *obj = cli_json_times(json_object());
    json_t *h = online_health_json(m->o);
    if (obj != NULL && h != NULL) {
        json_object_set_new(obj, "event", json_string("health"));
        json_object_set_new(obj, "link", json_string(m->o->desc));
        if (json_object_update(obj, h) != 0) {
            json_decref(obj);
            obj = NULL; /* out of memory: cli_json_line() says nothing of it */
        }
    }
    json_decref(h);
    (void)cli_json_line(obj);
}

/* --json: the client's health when the GCU came up and when a figure changed (at most once a
 * second); the screen and the plain lines show it each time. */
static void show_health(monitor *m, int first)
{
    char now[256];
    online_health_text(m->o, now, sizeof(now));
    if (strcmp(now, m->health) == 0 || (!first && xf_ms_since(xf_posix_now_ms(), m->health_ms) < 1000u)) {
        return;
    }
    snprintf(m->health, sizeof(m->health), "%s", now);
    m->health_ms = xf_posix_now_ms();
    json_health(m);
}

/* The plain output: the last warning, with the number of packets that had one since the last line. */
static void show_warnings(monitor *m)
{
    if (m->warned != m->warned_shown) {
        printf("warning: %s (%u packets with warnings)\n", m->warning, (unsigned)(m->warned - m->warned_shown));
        m->warned_shown = m->warned;
    }
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
    if (m->json) {
        show_health(m, 1); /* the GCU is up: which version it answered, even with --count 1 */
    }
    /* the first line always (--count 1: the packet that came while the link opened is counted) */
    while ((first && !m->json) || !finished(m, elapsed)) {
        uint32_t period = m->tty ? SCREEN_MS : LINE_MS;
        if (m->json) {
            show_health(m, 0);
        } else if (first || xf_ms_since(elapsed, last) >= period) {
            if (m->tty) {
                draw_screen(m);
            } else {
                print_line(m, elapsed);
                show_warnings(m);
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

/* --wait S, or its default: a person at a terminal waits until Ctrl-C, a script --timeout. */
static void set_wait(monitor *m, int terminal)
{
    if (m->has_wait) {
        m->o->wait_ms = (uint32_t)(m->wait_s * 1000.0 + 0.5);
    } else if (terminal) {
        m->o->wait_ms = ONLINE_WAIT_FOREVER;
    }
    m->o->wait_note = terminal;
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
    m.view = link->view; /* --raw: taken anywhere on the line */
    m.tty = isatty(fileno(stdout));
    memset(&hooks, 0, sizeof(hooks));
    hooks.on_bytes = on_bytes;
    hooks.on_link = on_link;
    hooks.user = &m;
    cli_signals_init();
    m.o = online_new();
    if (m.o != NULL) {
        set_wait(&m, isatty(fileno(stdin)) && m.tty);
    }
    rc = (m.o != NULL) ? online_open(m.o, link, "monitor", &hooks) : XFGCU_EXIT_USAGE;
    if (rc == XFGCU_EXIT_OK) {
        m.start_ms = xf_posix_now_ms(); /* the GCU is up: the reply rate counts from here */
        run_loop(&m);
    }
    online_free(m.o);
    return rc;
}
