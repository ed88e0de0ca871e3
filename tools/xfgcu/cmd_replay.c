/*
 * cmd_replay.c - `xfgcu replay FILE [--json] [--brief] [--raw]`.
 *
 * Reads a capture (docs/capture-format.md: the text format or pcap) and runs each direction's
 * bytes through its own streaming parser, as a live link would, flushing
 * both at the end of the file. Each packet is printed when its last byte
 * arrives, with that chunk's time: as decode's table, as one line
 * (--brief), or as decode's JSON object with "t" (seconds) first (--json).
 */
#include <errno.h>
#include <jansson.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "jsonpkt.h"
#include "online.h"
#include "summary.h"
#include "table.h"
#include "capture.h"

void help_replay(FILE *out)
{
    fputs("usage: xfgcu replay FILE [--json | --brief] [--raw]\n\n"
          "Decode a capture written by `xfgcu capture` (FILE - reads stdin). Each direction's bytes\n"
          "go through their own streaming parser, as on a live link; every valid packet is\n"
          "printed with the time of the chunk that completed it and its direction.\n\n"
          "  (default)  decode's table for each packet\n"
          "  --brief    one line per packet: time, direction, order, feedback, attitude, zoom\n"
          "  --json     JSON Lines: decode --json's object with \"t\" (seconds) in front, and\n"
          "             \"time\" (UTC) when the capture says when it started\n"
          "  --raw      the fields as wire integers, not engineering units\n\n"
          "FILE is the text format of `capture` or pcap / pcapng (`capture --pcap`, tcpdump, Wireshark).\n"
          "A malformed capture is an error (exit 2): \"xfgcu: FILE:LINE: reason\" (pcap: the record).\n",
          out);
}

typedef enum replay_style { STYLE_TABLE, STYLE_BRIEF, STYLE_JSON } replay_style;

typedef struct replay {
    const char *file;
    int style, help;
    pod_reading pod;     /* how pod_status's flags are read (decode --pod-order) */
    text_view view;      /* --raw: wire integers */
    int has_start;       /* the capture says when it started: */
    int64_t start_ms;    /* wall clock of its first chunk, ms since 1970 */
    xf_parser parser[2]; /* by xf_direction */
    uint32_t t_ms[2];    /* time of the last chunk of each direction */
    size_t packets[2];
    int rc;
} replay;

/* ---- printing ------------------------------------------------------------------------ */

static int print_json(const replay *r, const uint8_t *buf, size_t len, xf_direction dir, uint32_t t_ms)
{
    json_t *pkt = jsonpkt_from_wire(buf, len, dir, r->pod, r->view);
    json_t *obj = json_object();
    char *text = NULL, wall[40];
    int ok = (pkt != NULL && obj != NULL && json_object_set_new(obj, "t", json_real(cli_seconds(t_ms))) == 0);
    if (ok && r->has_start) {
        jsonpkt_utc_text(r->start_ms + t_ms, wall, sizeof(wall));
        ok = json_object_set_new(obj, "time", json_string(wall)) == 0;
    }
    if (ok && json_object_update(obj, pkt) == 0) {
        text = jsonpkt_dumps(obj);
    }
    json_decref(pkt);
    json_decref(obj);
    if (text == NULL) {
        return cli_fail("replay: out of memory");
    }
    printf("%s\n", text);
    free(text);
    return XFGCU_EXIT_OK;
}

static void print_brief_gcu(const uint8_t *buf, size_t len, text_view view)
{
    xf_gcu_packet p;
    xf_feedback fb;
    const char *mode;
    if (xf_gcu_unpack(buf, len, &p) != XF_OK) {
        return;
    }
    mode = xf_mode_name(p.main.gimbal_mode);
    if (p.params_len > 0u && xf_feedback_decode(p.order, p.params, p.params_len, &fb) == XF_OK && fb.has_state) {
        printf(" state 0x%02X", fb.state);
    }
    if (view == TEXT_RAW) {
        printf("  mode %s cam_roll %d cam_pitch %d cam_yaw %u zoom_cam1 %u\n", mode ? mode : "unknown", p.main.cam_roll,
               p.main.cam_pitch, (unsigned)p.main.cam_yaw, (unsigned)p.sub.zoom_cam1);
        return;
    }
    printf("  mode %s roll %.2f pitch %.2f yaw %.2f deg zoom %.1fx\n", mode ? mode : "unknown",
           (double)xf_cdeg(p.main.cam_roll), (double)xf_cdeg(p.main.cam_pitch), (double)xf_cdeg(p.main.cam_yaw),
           (double)xf_zoom_x(p.sub.zoom_cam1));
}

static void print_brief_host(const uint8_t *buf, size_t len)
{
    xf_host_packet p;
    if (xf_host_unpack(buf, len, &p) != XF_OK) {
        return;
    }
    printf("  status 0x%02X ctrl %d %d %d\n", p.main.status, p.main.roll_ctrl, p.main.pitch_ctrl, p.main.yaw_ctrl);
}

static void print_brief(const uint8_t *buf, size_t len, xf_direction dir, uint32_t t_ms, text_view view)
{
    const char *name = xf_order_name(buf[XF_OFF_ORDER]);
    printf("%9.3f %s %-4s v%u %zu bytes, order 0x%02X %s", cli_seconds(t_ms), dir == XF_DIR_HOST ? ">" : "<",
           dir == XF_DIR_HOST ? "host" : "gcu", (unsigned)buf[XF_OFF_VERSION], len, buf[XF_OFF_ORDER],
           name ? name : "unknown");
    if (dir == XF_DIR_HOST) {
        print_brief_host(buf, len);
    } else {
        print_brief_gcu(buf, len, view);
    }
}

static void print_packet(replay *r, const xf_frame *f, xf_direction dir)
{
    uint32_t t = r->t_ms[dir];
    char where[96], wall[40] = "";
    if (r->rc != XFGCU_EXIT_OK) {
        return;
    }
    switch ((replay_style)r->style) {
    case STYLE_JSON: r->rc = print_json(r, f->data, f->len, dir, t); break;
    case STYLE_BRIEF: print_brief(f->data, f->len, dir, t, r->view); break;
    default:
        if (r->packets[0] + r->packets[1] > 0u) {
            putchar('\n');
        }
        if (r->has_start) {
            char stamp[sizeof(wall) - 2u];
            jsonpkt_utc_text(r->start_ms + t, stamp, sizeof(stamp));
            snprintf(wall, sizeof(wall), ", %s", stamp);
        }
        snprintf(where, sizeof(where), "t %.3f s%s, %s", cli_seconds(t), wall,
                 dir == XF_DIR_HOST ? "host to GCU" : "GCU to host");
        table_print(f->data, f->len, dir, where, r->pod, r->view, stdout);
        break;
    }
    r->packets[dir]++;
}

/* ---- reading -------------------------------------------------------------------------- */

static void feed(replay *r, const xf_capture_record *rec)
{
    xf_parser *p = &r->parser[rec->dir];
    const uint8_t *data = rec->data;
    size_t left = rec->len, used = 0;
    xf_frame f;
    r->t_ms[rec->dir] = rec->t_ms;
    while (xf_parser_feed(p, data, left, &used, &f) == XF_PARSE_FRAME) {
        print_packet(r, &f, rec->dir);
        data += used;
        left -= used;
    }
}

static void flush_parsers(replay *r)
{
    xf_frame f;
    int d;
    for (d = 0; d < 2; d++) {
        while (xf_parser_flush(&r->parser[d], &f) == XF_PARSE_FRAME) {
            print_packet(r, &f, (xf_direction)d);
        }
    }
}

static int read_capture(replay *r, FILE *in)
{
    capture_source src;
    xf_capture_record *rec = malloc(sizeof(*rec));
    xf_err err;
    if (rec == NULL) {
        fclose(in);
        return cli_fail("replay: out of memory");
    }
    err = capture_source_open(&src, in);
    /* output that cannot be written ends the reading: main() says so, at once rather than at the
     * end of the input */
    while (err == XF_OK && r->rc == XFGCU_EXIT_OK && !ferror(stdout) &&
           (err = capture_source_next(&src, rec)) == XF_OK) {
        r->has_start = src.has_start;
        r->start_ms = src.start_ms;
        feed(r, rec);
    }
    free(rec);
    capture_source_close(&src);
    if (err != XF_ERR_EOF && err != XF_OK) {
        return cli_fail("%s:%s", r->file, src.error);
    }
    flush_parsers(r);
    return r->rc;
}

/* The last line: the packets of each direction, the bytes skipped, the CRC errors and the frames the
 * parsers gave up (summary.h); with --json, the summary line. */
static int print_summary(const replay *r)
{
    const xf_parser_stats *h = &r->parser[XF_DIR_HOST].stats, *g = &r->parser[XF_DIR_GCU].stats;
    text_summary sum;
    sum.host_packets = r->packets[XF_DIR_HOST];
    sum.gcu_packets = r->packets[XF_DIR_GCU];
    sum.bytes_skipped = (uint64_t)h->bytes_skipped + g->bytes_skipped;
    sum.crc_errors = (uint64_t)h->crc_errors + g->crc_errors;
    sum.given_up = (uint64_t)h->given_up + g->given_up;
    fputs(r->style == STYLE_TABLE ? "\n" : "", stdout);
    return summary_print(&sum, r->style == STYLE_JSON, stdout) == TEXT_OK ? XFGCU_EXIT_OK
                                                                          : cli_fail("%s: out of memory", r->file);
}

/* ---- the command ------------------------------------------------------------------------ */

enum { O_JSON = 256, O_BRIEF, O_HELP };

static const struct option replay_options[] = {
    {"json", no_argument, NULL, O_JSON},
    {"brief", no_argument, NULL, O_BRIEF},
    {"help", no_argument, NULL, O_HELP},
    {NULL, 0, NULL, 0},
};

static int take_arg(replay *r, const cli_args *a, int id)
{
    int style = (id == O_JSON) ? STYLE_JSON : STYLE_BRIEF;
    switch (id) {
    case O_JSON:
    case O_BRIEF:
        if (r->style != STYLE_TABLE && r->style != style) {
            return cli_fail("replay: --json and --brief exclude each other");
        }
        r->style = style;
        return XFGCU_EXIT_OK;
    case O_HELP: r->help = 1; return XFGCU_EXIT_OK;
    case CLI_ARG:
        if (r->file != NULL) {
            return cli_unexpected(a);
        }
        r->file = a->value;
        return XFGCU_EXIT_OK;
    default: return XFGCU_EXIT_USAGE; /* CLI_BAD: said */
    }
}

int replay_capture(FILE *in, const char *name, int json, int pod, int view, int summary)
{
    replay *r = calloc(1, sizeof(*r));
    int rc;
    if (r == NULL) {
        fclose(in);
        return cli_fail("%s: out of memory", name);
    }
    r->file = name;
    r->style = json ? STYLE_JSON : STYLE_TABLE;
    r->pod = (pod_reading)pod;
    r->view = (text_view)view;
    (void)xf_parser_init(&r->parser[XF_DIR_HOST], XF_DIR_HOST);
    (void)xf_parser_init(&r->parser[XF_DIR_GCU], XF_DIR_GCU);
    rc = read_capture(r, in);
    if (rc == XFGCU_EXIT_OK && summary) {
        rc = print_summary(r);
    }
    free(r);
    return rc;
}

static int replay_file(replay *r)
{
    FILE *in = (strcmp(r->file, "-") == 0) ? stdin : fopen(r->file, "r");
    int rc;
    if (in == NULL) {
        return cli_fail("replay: cannot open %s: %s", r->file, strerror(errno));
    }
    (void)xf_parser_init(&r->parser[XF_DIR_HOST], XF_DIR_HOST);
    (void)xf_parser_init(&r->parser[XF_DIR_GCU], XF_DIR_GCU);
    rc = read_capture(r, in); /* closes in */
    if (rc == XFGCU_EXIT_OK) {
        rc = print_summary(r);
    }
    return rc;
}

int cmd_replay(const cli_link *link, int argc, char **argv)
{
    replay *r = calloc(1, sizeof(*r));
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    if (r == NULL) {
        return cli_fail("replay: out of memory");
    }
    r->pod = POD_READ_AUTO;
    cli_args_init(&a, argc, argv, CLI_IN_ORDER, replay_options, "replay");
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        rc = take_arg(r, &a, id);
    }
    r->view = link->view; /* --raw: taken anywhere on the line */
    if (rc == XFGCU_EXIT_OK && r->help) {
        help_replay(stdout);
    } else if (rc == XFGCU_EXIT_OK && r->file == NULL) {
        rc = cli_fail("replay: missing FILE (a capture written by xfgcu capture)");
    } else if (rc == XFGCU_EXIT_OK) {
        rc = replay_file(r);
    }
    free(r);
    return rc;
}
