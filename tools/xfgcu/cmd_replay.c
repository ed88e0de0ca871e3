/*
 * cmd_replay.c - `xfgcu replay FILE [--json] [--brief]`.
 *
 * Reads a capture (docs/capture-format.md) and runs each direction's
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
#include "table.h"
#include "capture.h"

void help_replay(FILE *out)
{
    fputs("usage: xfgcu replay FILE [--json | --brief]\n\n"
          "Decode a capture written by `xfgcu record` (FILE - reads stdin). Each direction's bytes\n"
          "go through their own streaming parser, as on a live link; every valid packet is\n"
          "printed with the time of the chunk that completed it and its direction.\n\n"
          "  (default)  decode's table for each packet\n"
          "  --brief    one line per packet: time, direction, order, feedback, attitude, zoom\n"
          "  --json     JSON Lines: decode --json's object with \"t\" (seconds) in front\n\n"
          "A malformed capture is an error (exit 2) that names its line.\n",
          out);
}

typedef enum replay_style { STYLE_TABLE, STYLE_BRIEF, STYLE_JSON } replay_style;

typedef struct replay {
    const char *file;
    int style, help;
    xf_parser parser[2]; /* by xf_direction */
    uint32_t t_ms[2];    /* time of the last chunk of each direction */
    size_t packets[2];
    int rc;
} replay;

/* ---- printing ------------------------------------------------------------------------ */

static int print_json(const uint8_t *buf, size_t len, xf_direction dir, uint32_t t_ms)
{
    json_t *pkt = jsonpkt_from_wire(buf, len, dir, POD_READ_AUTO);
    json_t *obj = json_object();
    char *text = NULL;
    if (pkt != NULL && obj != NULL && json_object_set_new(obj, "t", json_real(cli_seconds(t_ms))) == 0 &&
        json_object_update(obj, pkt) == 0) {
        text = json_dumps(obj, JSON_COMPACT | JSON_REAL_PRECISION(10));
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

static void print_brief_gcu(const uint8_t *buf, size_t len)
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

static void print_brief(const uint8_t *buf, size_t len, xf_direction dir, uint32_t t_ms)
{
    const char *name = xf_order_name(buf[XF_OFF_ORDER]);
    printf("%9.3f %s %-4s v%u %zu bytes, order 0x%02X %s", cli_seconds(t_ms), dir == XF_DIR_HOST ? ">" : "<",
           dir == XF_DIR_HOST ? "host" : "gcu", (unsigned)buf[XF_OFF_VERSION], len, buf[XF_OFF_ORDER],
           name ? name : "unknown");
    if (dir == XF_DIR_HOST) {
        print_brief_host(buf, len);
    } else {
        print_brief_gcu(buf, len);
    }
}

static void print_packet(replay *r, const xf_frame *f, xf_direction dir)
{
    uint32_t t = r->t_ms[dir];
    char where[64];
    if (r->rc != XFGCU_EXIT_OK) {
        return;
    }
    switch ((replay_style)r->style) {
    case STYLE_JSON: r->rc = print_json(f->data, f->len, dir, t); break;
    case STYLE_BRIEF: print_brief(f->data, f->len, dir, t); break;
    default:
        if (r->packets[0] + r->packets[1] > 0u) {
            putchar('\n');
        }
        snprintf(where, sizeof(where), "t %.3f s, %s", cli_seconds(t),
                 dir == XF_DIR_HOST ? "host to GCU" : "GCU to host");
        table_print(f->data, f->len, dir, where, POD_READ_AUTO, stdout);
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
    xf_capture_reader reader;
    xf_capture_record *rec = malloc(sizeof(*rec));
    xf_err err;
    if (rec == NULL) {
        return cli_fail("replay: out of memory");
    }
    err = xf_capture_open(&reader, in);
    while (err == XF_OK && r->rc == XFGCU_EXIT_OK && (err = xf_capture_next(&reader, rec)) == XF_OK) {
        feed(r, rec);
    }
    free(rec);
    if (err == XF_ERR_FORMAT) {
        return cli_fail("replay %s: %s", r->file, reader.error);
    }
    if (err == XF_ERR_IO) {
        return cli_fail("replay %s: cannot read: %s", r->file, reader.error);
    }
    if (err != XF_ERR_EOF && err != XF_OK) {
        return cli_fail("replay %s: cannot read: %s", r->file, xf_strerror(err));
    }
    flush_parsers(r);
    return r->rc;
}

static void print_summary(const replay *r)
{
    const xf_parser_stats *h = &r->parser[XF_DIR_HOST].stats, *g = &r->parser[XF_DIR_GCU].stats;
    printf("%s%zu packets: %zu host to GCU, %zu GCU to host; %u bytes skipped, %u CRC errors\n",
           r->style == STYLE_TABLE ? "\n" : "", r->packets[0] + r->packets[1], r->packets[XF_DIR_HOST],
           r->packets[XF_DIR_GCU], (unsigned)(h->bytes_skipped + g->bytes_skipped),
           (unsigned)(h->crc_errors + g->crc_errors));
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

int cmd_replay(const cli_link *link, int argc, char **argv)
{
    replay *r = calloc(1, sizeof(*r));
    FILE *in;
    cli_args a;
    int id, rc = XFGCU_EXIT_OK;
    (void)link; /* offline */
    if (r == NULL) {
        return cli_fail("replay: out of memory");
    }
    cli_args_init(&a, argc, argv, CLI_IN_ORDER, replay_options, "replay");
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&a)) != CLI_END) {
        rc = take_arg(r, &a, id);
    }
    if (rc == XFGCU_EXIT_OK && r->help) {
        help_replay(stdout);
    } else if (rc == XFGCU_EXIT_OK && r->file == NULL) {
        rc = cli_fail("replay: missing FILE (a capture written by xfgcu record)");
    } else if (rc == XFGCU_EXIT_OK) {
        in = (strcmp(r->file, "-") == 0) ? stdin : fopen(r->file, "r");
        if (in == NULL) {
            rc = cli_fail("replay: cannot open %s: %s", r->file, strerror(errno));
        } else {
            (void)xf_parser_init(&r->parser[XF_DIR_HOST], XF_DIR_HOST);
            (void)xf_parser_init(&r->parser[XF_DIR_GCU], XF_DIR_GCU);
            rc = read_capture(r, in);
            if (rc == XFGCU_EXIT_OK && r->style != STYLE_JSON) {
                print_summary(r);
            }
            if (in != stdin) {
                fclose(in);
            }
        }
    }
    free(r);
    return rc;
}
