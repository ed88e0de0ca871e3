/*
 * cmd_sim.c - `xfgcu sim [--serial PATH | --pty | --udp [PORT] | --tcp [PORT]]`.
 *
 * The library's simulated GCU (xf_sim) on the GCU's end of a link. When
 * it is ready it prints exactly one line on stdout, flushed, for scripts
 * and tests to read:
 *
 *     xfgcu sim: listening on tcp 127.0.0.1:2332
 *     xfgcu sim: listening on udp 127.0.0.1:2337
 *     xfgcu sim: listening on pty /dev/pts/5 [link PATH]
 *     xfgcu sim: listening on serial /dev/ttyUSB0 at 115200 baud
 *
 * then runs until SIGINT or SIGTERM (exit 0), or --duration, printing a
 * line for each packet it answered by a strict reading of an open question
 * (xf_sim_note: docs/protocol.md §12), with --verbose one for each order
 * it executes, and with --stats its counters. With --json, the same log as
 * JSON Lines, each object with time_mono and time_utc: {"event":
 * "listening", ...}, {"event": "note", ...}, {"event": "executed", ...},
 * {"event": "stats", ...}.
 */
#define _POSIX_C_SOURCE 200809L /* getpid */

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "online.h"
#include "xfgcu/xf_sim.h"

void help_sim(FILE *out)
{
    fputs("usage: xfgcu sim [--serial PATH | --pty [--link PATH] | --udp [PORT] | --tcp [PORT]] [OPTIONS]\n\n"
          "A simulated GCU that follows the protocol: it answers only correct packets, keeps the\n"
          "once-rule, gives feedback, moves its attitude by mode, zooms, ranges and tracks.\n"
          "When ready it prints one line, e.g. \"xfgcu sim: listening on tcp 127.0.0.1:2332\",\n"
          "then runs until Ctrl-C or SIGTERM (exit 0).\n\n"
          "link (one; default --tcp 2332):\n"
          "  --tcp [PORT]          TCP server for one client, like the GCU (default port 2332; 0 = any free)\n"
          "  --udp [PORT]          UDP on the GCU's port (default 2337; 0 = any free); answers the sender\n"
          "  --pty                 a new pseudo-terminal; connect with --serial and the path printed\n"
          "  --link PATH           with --pty: also a symbolic link PATH to it\n"
          "  --serial PATH         a real serial port (the GCU's end of a cable)\n"
          "  --baud N              with --serial: 115200 (default), 250000, 500000 or 1000000\n"
          "  --bind ADDR           address to listen on for --tcp and --udp (default 127.0.0.1)\n"
          "  --reply-to ADDR[:PORT] with --udp: send replies there, not to the sender, as the vendor's\n"
          "                        GCU sends to the LAN broadcast address, port 2338 (the default PORT)\n\n"
          "behaviour:\n"
          "  --protocol 1|2        version of the replies (default 1; V0.2 adds thermal and camera status)\n"
          "  --model CODE          the model code it reports, 0..255 (default 58, Z-9B_V4(T), which has\n"
          "                        every order); orders the model lacks (V2.0.6's support list) fail\n"
          "  --fail ORDER=STATE    executions of ORDER answer STATE: shutter=1, zoom-in=0x02 (camera 2\n"
          "                        failed), 0x20=1; repeatable\n"
          "  --drop PERMILLE       drop this share of replies at random, 0..1000\n"
          "  --delay MS            hold each reply MS ms, 0..10000\n"
          "  --jitter MS           hold each packet, both ways, a random 0..MS ms more, 0..10000: they\n"
          "                        overtake one another, as on a network that reorders\n"
          "  --dup PERMILLE        this share of packets, both ways, arrive twice, 0..1000\n"
          "  --noise PERMILLE      after each byte it sends, a random byte more with this chance, 0..1000\n"
          "  --drop-bytes PERMILLE each byte it would send is lost with this chance, 0..1000\n"
          "  --calibration-ms MS   how long calibration answers \"operating\", 0..600000 (default 1500)\n"
          "  --state-once          the execution state only in the first reply after an execution, 72-byte\n"
          "                        replies to the order's repeats (one reading of V2.0.6's flowchart)\n"
          "  --answer-only N       answer only packets of version byte N (1 or 2), ignore the others, as\n"
          "                        some GCU-side programs do; replies in version N unless --protocol says\n"
          "  --main-camera N       the camera on the main screen, 1 (default) or 2: its zoom scales the\n"
          "                        control rates\n"
          "  --duration S          stop by itself after S seconds\n"
          "  --verbose             print each order it executes (a packet read by a strict reading of an\n"
          "                        open question, docs/protocol.md section 12, is always printed)\n"
          "  --stats S             print its counters every S seconds, and when it stops\n"
          "  --json                its lines as JSON objects instead, one per line, with time_mono and\n"
          "                        time_utc: {\"event\": \"listening\", \"link\": \"tcp\", \"port\": 2332, ...},\n"
          "                        {\"event\": \"executed\", \"order_name\": \"shutter\", ...} (docs/cli.md)\n\n"
          "example: xfgcu sim --udp 0 &   then   xfgcu --udp 127.0.0.1 --gcu-port PORT --local-port 0 monitor\n",
          out);
}

typedef enum sim_kind { SIM_TCP, SIM_UDP, SIM_PTY, SIM_SERIAL } sim_kind;

typedef struct sim_args {
    int kind, has_kind;
    long port;
    const char *serial, *bind, *link, *reply_to;
    long baud;
    uint8_t version;
    long model;
    int has_model;
    uint8_t fail[256];
    long drop, delay, jitter, dup, calibration_ms, noise, drop_bytes;
    int has_baud, has_drop, has_delay, has_jitter, has_dup, has_calibration;
    double duration, stats;
    int has_duration, has_stats, verbose, json, help;
    int state_once;
    long answer_only, main_camera;
    int has_answer_only, has_main_camera, has_version;
} sim_args;

/* ---- arguments ------------------------------------------------------------------------- */

/* The ids of the options: the link's are O_KIND + its sim_kind. */
enum {
    O_KIND = 256,
    O_LINK = 300,
    O_BAUD,
    O_BIND,
    O_PROTOCOL,
    O_MODEL,
    O_REPLY_TO,
    O_FAIL,
    O_DROP,
    O_DELAY,
    O_JITTER,
    O_DUP,
    O_NOISE,
    O_DROP_BYTES,
    O_STATS,
    O_CALIBRATION,
    O_DURATION,
    O_STATE_ONCE,
    O_ANSWER_ONLY,
    O_MAIN_CAMERA,
    O_VERBOSE,
    O_JSON,
    O_HELP
};

static const struct option sim_options[] = {
    {"tcp", optional_argument, NULL, O_KIND + SIM_TCP},
    {"udp", optional_argument, NULL, O_KIND + SIM_UDP},
    {"pty", no_argument, NULL, O_KIND + SIM_PTY},
    {"serial", required_argument, NULL, O_KIND + SIM_SERIAL},
    {"link", required_argument, NULL, O_LINK},
    {"baud", required_argument, NULL, O_BAUD},
    {"bind", required_argument, NULL, O_BIND},
    {"protocol", required_argument, NULL, O_PROTOCOL},
    {"model", required_argument, NULL, O_MODEL},
    {"reply-to", required_argument, NULL, O_REPLY_TO},
    {"fail", required_argument, NULL, O_FAIL},
    {"drop", required_argument, NULL, O_DROP},
    {"delay", required_argument, NULL, O_DELAY},
    {"jitter", required_argument, NULL, O_JITTER},
    {"dup", required_argument, NULL, O_DUP},
    {"noise", required_argument, NULL, O_NOISE},
    {"drop-bytes", required_argument, NULL, O_DROP_BYTES},
    {"stats", required_argument, NULL, O_STATS},
    {"calibration-ms", required_argument, NULL, O_CALIBRATION},
    {"duration", required_argument, NULL, O_DURATION},
    {"state-once", no_argument, NULL, O_STATE_ONCE},
    {"answer-only", required_argument, NULL, O_ANSWER_ONLY},
    {"main-camera", required_argument, NULL, O_MAIN_CAMERA},
    {"verbose", no_argument, NULL, O_VERBOSE},
    {"json", no_argument, NULL, O_JSON},
    {"help", no_argument, NULL, O_HELP},
    {NULL, 0, NULL, 0},
};

/* --tcp [PORT], --udp [PORT], --pty, --serial PATH: the port is optional, taken when the next
 * argument does not look like an option. */
static int take_kind(sim_args *s, cli_args *a, int kind)
{
    if (s->has_kind) {
        return cli_fail("sim: give only one of --tcp, --udp, --pty, --serial");
    }
    s->has_kind = 1;
    s->kind = kind;
    switch ((sim_kind)kind) {
    case SIM_SERIAL: return cli_value_text(a, "a device path", &s->serial);
    case SIM_PTY: return XFGCU_EXIT_OK;
    default:
        s->port = (kind == SIM_TCP) ? (long)XF_GCU_TCP_PORT : (long)XF_GCU_UDP_PORT;
        cli_optional_next(a);
        return (a->value != NULL) ? cli_value_long(a, 0, 65535, "a port 0..65535 (0: any free port)", &s->port, NULL)
                                  : XFGCU_EXIT_OK;
    }
}

/* --fail ORDER=STATE */
static int take_fail(sim_args *a, const char *text)
{
    char name[64];
    const char *eq = (text != NULL) ? strchr(text, '=') : NULL;
    long long order = -1, state = -1;
    uint8_t o8;
    if (eq == NULL || (size_t)(eq - text) >= sizeof(name) || eq == text) {
        return cli_fail("sim: --fail %s: expected ORDER=STATE, e.g. shutter=1 or zoom-in=0x02",
                        text != NULL ? text : "needs a value");
    }
    memcpy(name, text, (size_t)(eq - text));
    name[eq - text] = '\0';
    if (xf_order_from_name(name, &o8) == XF_OK) {
        order = o8;
    } else if (text_parse_int(name, &order) != 0 || order < 0 || order > 255) {
        return cli_fail("sim: --fail %s: '%s' is not an order (a name like zoom-in, or a number 0..255)", text, name);
    }
    if (text_parse_int(eq + 1, &state) != 0 || state < 0 || state > 255) {
        return cli_fail("sim: --fail %s: STATE must be 0..255 (1 failure, or a mask of failed cameras)", text);
    }
    a->fail[order] = (uint8_t)state;
    return XFGCU_EXIT_OK;
}

static int take_arg(sim_args *s, cli_args *a, int id)
{
    switch (id) {
    case O_LINK: return cli_value_text(a, "PATH", &s->link);
    case O_BAUD: return cli_value_baud(a, &s->baud, &s->has_baud);
    case O_BIND: return cli_value_text(a, "ADDR", &s->bind);
    case O_PROTOCOL: s->has_version = 1; return cli_value_protocol(a, &s->version);
    case O_MODEL: return cli_value_long(a, 0, 255, "a model code 0..255", &s->model, &s->has_model);
    case O_REPLY_TO: return cli_value_text(a, "ADDR[:PORT]", &s->reply_to);
    case O_FAIL: return take_fail(s, a->value);
    case O_DROP: return cli_value_long(a, 0, 1000, "per mille, 0..1000", &s->drop, &s->has_drop);
    case O_DELAY: return cli_value_long(a, 0, 10000, "milliseconds, 0..10000", &s->delay, &s->has_delay);
    case O_JITTER: return cli_value_long(a, 0, 10000, "milliseconds, 0..10000", &s->jitter, &s->has_jitter);
    case O_DUP: return cli_value_long(a, 0, 1000, "per mille, 0..1000", &s->dup, &s->has_dup);
    case O_NOISE: return cli_value_long(a, 0, 1000, "per mille, 0..1000", &s->noise, NULL);
    case O_DROP_BYTES: return cli_value_long(a, 0, 1000, "per mille, 0..1000", &s->drop_bytes, NULL);
    case O_STATS: return cli_value_real(a, 0.1, 86400.0, "seconds, 0.1..86400", &s->stats, &s->has_stats);
    case O_CALIBRATION:
        return cli_value_long(a, 0, 600000, "milliseconds, 0..600000", &s->calibration_ms, &s->has_calibration);
    case O_DURATION:
        return cli_value_real(a, 0.1, 31536000.0, "seconds, 0.1..31536000", &s->duration, &s->has_duration);
    case O_STATE_ONCE: s->state_once = 1; return XFGCU_EXIT_OK;
    case O_ANSWER_ONLY: return cli_value_long(a, 1, 2, "a version byte, 1 or 2", &s->answer_only, &s->has_answer_only);
    case O_MAIN_CAMERA: return cli_value_long(a, 1, 2, "a camera, 1 or 2", &s->main_camera, &s->has_main_camera);
    case O_VERBOSE: s->verbose = 1; return XFGCU_EXIT_OK;
    case O_JSON: s->json = 1; return XFGCU_EXIT_OK;
    case O_HELP: s->help = 1; return XFGCU_EXIT_OK;
    case CLI_ARG: return cli_unexpected(a);
    case CLI_BAD: return XFGCU_EXIT_USAGE;
    default: return take_kind(s, a, id - O_KIND);
    }
}

static int check_args(const sim_args *a)
{
    if (a->link != NULL && a->kind != SIM_PTY) {
        return cli_fail("sim: --link %s goes only with --pty", a->link);
    }
    if (a->bind != NULL && a->kind != SIM_TCP && a->kind != SIM_UDP) {
        return cli_fail("sim: --bind %s goes only with --tcp or --udp", a->bind);
    }
    if (a->reply_to != NULL && a->kind != SIM_UDP) {
        return cli_fail("sim: --reply-to %s goes only with --udp", a->reply_to);
    }
    if (a->has_baud && a->kind != SIM_SERIAL) {
        return cli_fail("sim: --baud goes only with --serial");
    }
    return XFGCU_EXIT_OK;
}

/* ---- running --------------------------------------------------------------------------- */

typedef struct sim_run {
    xf_simlink link;
    xf_serial serial;
    xf_simlink_wire wire; /* --noise, --drop-bytes */
    xf_sim sim;
    xf_hal hal;
    int opened;
    int json;               /* --json: the log's lines as objects */
    uint32_t start_ms;      /* when it became ready: the log's times count from here */
    uint32_t executed[256]; /* seen so far, for --verbose */
} sim_run;

/* --reply-to ADDR[:PORT]: replies to a fixed address, port 2338 unless given (an IPv4 address
 * or a name; the last colon splits off the port). */
static int reply_to(sim_run *s, const char *text, char *what, size_t cap)
{
    char host[256];
    const char *colon = strrchr(text, ':');
    long long port = XF_HOST_UDP_PORT;
    size_t n = (colon != NULL) ? (size_t)(colon - text) : strlen(text);
    xf_err err;
    if (n == 0u || n >= sizeof(host) ||
        (colon != NULL && (text_parse_int(colon + 1, &port) != 0 || port < 1 || port > 65535))) {
        return cli_fail("sim: --reply-to %s: expected ADDR[:PORT], PORT 1..65535", text);
    }
    memcpy(host, text, n);
    host[n] = '\0';
    err = xf_simlink_udp_reply_to(&s->link, host, (uint16_t)port);
    if (err != XF_OK) {
        xf_simlink_close(&s->link);
        return cli_fail_link("sim --reply-to %s: %s", text,
                             s->link.error.text[0] != '\0' ? s->link.error.text : xf_strerror(err));
    }
    snprintf(what + strlen(what), cap - strlen(what), " --reply-to %s", text);
    return XFGCU_EXIT_OK;
}

static int open_gcu_link(sim_run *s, const sim_args *a)
{
    xf_err err;
    const char *text;
    char what[320];
    switch ((sim_kind)a->kind) {
    case SIM_SERIAL:
        snprintf(what, sizeof(what), "--serial %s", a->serial);
        err = xf_serial_open(&s->serial, a->serial, (uint32_t)a->baud);
        xf_serial_hal(&s->serial, &s->hal);
        text = s->serial.error.text;
        break;
    case SIM_PTY:
        snprintf(what, sizeof(what), "--pty");
        err = xf_simlink_open_pty(&s->link, a->link);
        xf_simlink_hal(&s->link, &s->hal);
        text = s->link.error.text;
        break;
    default:
        snprintf(what, sizeof(what), "--%s %ld", a->kind == SIM_TCP ? "tcp" : "udp", a->port);
        err = (a->kind == SIM_TCP) ? xf_simlink_open_tcp(&s->link, a->bind, (uint16_t)a->port)
                                   : xf_simlink_open_udp(&s->link, a->bind, (uint16_t)a->port);
        if (err == XF_OK && a->reply_to != NULL) {
            int rc = reply_to(s, a->reply_to, what, sizeof(what));
            if (rc != XFGCU_EXIT_OK) {
                return rc;
            }
        }
        xf_simlink_hal(&s->link, &s->hal);
        text = s->link.error.text;
        break;
    }
    if (err != XF_OK) {
        return cli_fail_link("sim %s: %s", what, text[0] != '\0' ? text : xf_strerror(err));
    }
    s->opened = 1;
    return XFGCU_EXIT_OK;
}

static const char *const kind_names[] = {"tcp", "udp", "pty", "serial"};

/* --json: the ready line as {"event": "listening", "link": KIND, ...where..., times}. */
static void json_ready(const sim_run *s, const sim_args *a)
{
    json_t *obj = cli_json_times(json_object());
    if (obj != NULL) {
        json_object_set_new(obj, "event", json_string("listening"));
        json_object_set_new(obj, "link", json_string(kind_names[a->kind]));
        switch ((sim_kind)a->kind) {
        case SIM_SERIAL:
            json_object_set_new(obj, "path", json_string(a->serial));
            json_object_set_new(obj, "baud", json_integer(a->baud));
            break;
        case SIM_PTY:
            json_object_set_new(obj, "path", json_string(s->link.pty_path));
            json_object_set_new(obj, "link_path", a->link != NULL ? json_string(a->link) : json_null());
            break;
        default:
            json_object_set_new(obj, "host", json_string(s->link.bind_host));
            json_object_set_new(obj, "port", json_integer(s->link.port));
            json_object_set_new(obj, "reply_to", a->reply_to != NULL ? json_string(a->reply_to) : json_null());
            break;
        }
        json_object_set_new(obj, "protocol", json_integer(a->version));
        json_object_set_new(obj, "state_once", json_boolean(a->state_once));
        json_object_set_new(obj, "answer_only", a->has_answer_only ? json_integer(a->answer_only) : json_null());
        json_object_set_new(obj, "main_camera", json_integer(a->has_main_camera ? a->main_camera : 1));
        json_object_set_new(obj, "pid", json_integer((json_int_t)getpid()));
    }
    (void)cli_json_line(obj);
}

static void print_ready(const sim_run *s, const sim_args *a)
{
    if (a->json) {
        json_ready(s, a);
        return;
    }
    switch ((sim_kind)a->kind) {
    case SIM_SERIAL: printf("xfgcu sim: listening on serial %s at %ld baud\n", a->serial, a->baud); break;
    case SIM_PTY:
        printf("xfgcu sim: listening on pty %s%s%s\n", s->link.pty_path, a->link ? " link " : "",
               a->link ? a->link : "");
        break;
    default:
        printf(strchr(s->link.bind_host, ':') != NULL ? "xfgcu sim: listening on %s [%s]:%u\n"
                                                      : "xfgcu sim: listening on %s %s:%u\n",
               a->kind == SIM_TCP ? "tcp" : "udp", s->link.bind_host, (unsigned)s->link.port);
        break;
    }
    fflush(stdout);
}

/* A packet answered by a strict reading (xf_sim_note): one line of the log, whatever --verbose. The
 * question's number is its row in docs/protocol.md section 12 (xf_sim_question's value). */
static void on_note(void *user, const xf_sim_note *n)
{
    const sim_run *s = (const sim_run *)user;
    const char *name = xf_order_name(n->order);
    uint32_t elapsed = xf_ms_since(xf_posix_now_ms(), s->start_ms);
    json_t *obj;
    if (!s->json) {
        printf("xfgcu sim: %.3f s: note: open question %d: %s (0x%02X) with %u parameter bytes, first 0x%02X, "
               "answered state 0x%02X: %s\n",
               cli_seconds(elapsed), (int)n->question, name ? name : "unknown order", (unsigned)n->order,
               (unsigned)n->params_len, (unsigned)n->param0, (unsigned)n->state, n->text);
        fflush(stdout);
        return;
    }
    obj = cli_json_times(json_object());
    if (obj != NULL) {
        json_object_set_new(obj, "event", json_string("note"));
        json_object_set_new(obj, "t", json_real(cli_seconds(elapsed)));
        json_object_set_new(obj, "question", json_integer((json_int_t)n->question));
        json_object_set_new(obj, "order", json_integer(n->order));
        json_object_set_new(obj, "order_name", name != NULL ? json_string(name) : json_null());
        json_object_set_new(obj, "params_len", json_integer(n->params_len));
        json_object_set_new(obj, "param0", json_integer(n->param0));
        json_object_set_new(obj, "state", json_integer(n->state));
        json_object_set_new(obj, "text", json_string(n->text));
    }
    (void)cli_json_line(obj);
}

static int start_sim(sim_run *s, const sim_args *a)
{
    xf_sim_config sc;
    int k;
    xf_sim_config_init(&sc);
    sc.version = a->version;
    if (a->has_model) {
        sc.gimbal_code = (uint8_t)a->model;
    }
    if (a->has_calibration) {
        sc.calibration_ms = (uint32_t)a->calibration_ms;
    }
    xf_simlink_wire_init(&s->wire, &s->hal, 1u, &s->hal); /* no fault unless asked */
    s->wire.noise_permille = (uint16_t)a->noise;
    s->wire.drop_permille = (uint16_t)a->drop_bytes;
    sc.state_once = (uint8_t)a->state_once;
    sc.answer_only = (uint8_t)a->answer_only; /* 0: every version */
    sc.main_camera = (uint8_t)(a->has_main_camera ? a->main_camera : 1);
    sc.on_note = on_note;
    sc.user = s;
    s->json = a->json;
    if (xf_sim_init(&s->sim, &sc) != XF_OK || xf_sim_attach(&s->sim, &s->hal) != XF_OK) {
        return cli_fail("sim: cannot start the simulator");
    }
    for (k = 0; k < 256; k++) {
        xf_sim_set_failure(&s->sim, (uint8_t)k, a->fail[k]);
    }
    s->sim.fault.drop_permille = (uint16_t)a->drop;
    s->sim.fault.delay_ms = (uint32_t)a->delay;
    s->sim.fault.jitter_ms = (uint16_t)a->jitter;
    s->sim.fault.dup_permille = (uint16_t)a->dup;
    return XFGCU_EXIT_OK;
}

/* --verbose --json: {"event": "executed", "t": ..., "order": ..., "order_name": ..., "state": ..., times}. */
static void json_executed(uint32_t elapsed, int order, const char *name, unsigned state)
{
    json_t *obj = cli_json_times(json_object());
    if (obj != NULL) {
        json_object_set_new(obj, "event", json_string("executed"));
        json_object_set_new(obj, "t", json_real(cli_seconds(elapsed)));
        json_object_set_new(obj, "order", json_integer(order));
        json_object_set_new(obj, "order_name", name != NULL ? json_string(name) : json_null());
        json_object_set_new(obj, "state", json_integer(state));
    }
    (void)cli_json_line(obj);
}

static void report_executed(sim_run *s, uint32_t elapsed, int json)
{
    int k;
    for (k = 0; k < 256; k++) {
        if (s->sim.stats.executed[k] != s->executed[k]) {
            const char *name = xf_order_name((uint8_t)k);
            unsigned state = s->sim.fb_order == k ? s->sim.fb_state : 0u;
            s->executed[k] = s->sim.stats.executed[k];
            if (json) {
                json_executed(elapsed, k, name, state);
                continue;
            }
            printf("xfgcu sim: %.3f s: executed %s (0x%02X), state 0x%02X\n", cli_seconds(elapsed),
                   name ? name : "unknown order", (unsigned)k, state);
            fflush(stdout);
        }
    }
}

/* --stats: {"event": "stats", "t": ..., "packets_in": ..., ...counters..., times}, or a line. */
static void report_stats(const sim_run *s, uint32_t elapsed, int json)
{
    const xf_sim_stats *st = &s->sim.stats;
    json_t *obj;
    if (!json) {
        printf("xfgcu sim: %.3f s: %u packets in, %u replies, %u dropped, %u corrupted, %u photos, %u with ins_valid, "
               "%u noise bytes, %u bytes dropped\n",
               cli_seconds(elapsed), (unsigned)st->packets_in, (unsigned)st->replies, (unsigned)st->dropped,
               (unsigned)st->corrupted, (unsigned)st->photos, (unsigned)st->ins_valid_packets,
               (unsigned)s->wire.noise_bytes, (unsigned)s->wire.dropped_bytes);
        fflush(stdout);
        return;
    }
    obj = cli_json_times(json_object());
    if (obj != NULL) {
        json_object_set_new(obj, "event", json_string("stats"));
        json_object_set_new(obj, "t", json_real(cli_seconds(elapsed)));
        json_object_set_new(obj, "packets_in", json_integer(st->packets_in));
        json_object_set_new(obj, "replies", json_integer(st->replies));
        json_object_set_new(obj, "dropped", json_integer(st->dropped));
        json_object_set_new(obj, "corrupted", json_integer(st->corrupted));
        json_object_set_new(obj, "photos", json_integer(st->photos));
        json_object_set_new(obj, "ins_valid_packets", json_integer(st->ins_valid_packets));
        json_object_set_new(obj, "noise_bytes", json_integer(s->wire.noise_bytes));
        json_object_set_new(obj, "dropped_bytes", json_integer(s->wire.dropped_bytes));
    }
    (void)cli_json_line(obj);
}

static void run_sim(sim_run *s, const sim_args *a)
{
    xf_sim *sims[1];
    uint32_t start = xf_posix_now_ms(), elapsed = 0, stats_ms = (uint32_t)(a->stats * 1000.0 + 0.5), last_stats = start;
    s->start_ms = start;
    sims[0] = &s->sim;
    /* a log (stdout) that cannot be written ends the simulator: main() says so */
    while (!cli_stop_requested() && !(a->has_duration && cli_seconds(elapsed) >= a->duration) && !ferror(stdout)) {
        uint32_t now;
        (void)xf_posix_poll(NULL, 0, sims, 1, 50);
        now = xf_posix_now_ms();
        elapsed = xf_ms_since(now, start);
        if (a->verbose) {
            report_executed(s, elapsed, a->json);
        }
        if (a->has_stats && xf_ms_since(now, last_stats) >= stats_ms) {
            last_stats = now - xf_ms_since(now, last_stats) % stats_ms; /* on the grid from the start */
            report_stats(s, elapsed, a->json);
        }
    }
    if (a->has_stats) {
        report_stats(s, elapsed, a->json); /* the totals */
    }
}

static void close_gcu_link(sim_run *s, const sim_args *a)
{
    if (a->kind == SIM_SERIAL) {
        xf_serial_close(&s->serial);
    } else {
        xf_simlink_close(&s->link);
    }
}

int cmd_sim(const cli_link *link, int argc, char **argv)
{
    sim_args a;
    sim_run *s;
    cli_args args;
    int id, rc = XFGCU_EXIT_OK;
    memset(&a, 0, sizeof(a));
    a.port = (long)XF_GCU_TCP_PORT;
    a.version = link->protocol;
    a.baud = link->baud;
    cli_args_init(&args, argc, argv, CLI_IN_ORDER, sim_options, "sim");
    while (rc == XFGCU_EXIT_OK && (id = cli_next(&args)) != CLI_END) {
        rc = take_arg(&a, &args, id);
    }
    if (rc == XFGCU_EXIT_OK && a.help) {
        help_sim(stdout);
        return XFGCU_EXIT_OK;
    }
    if (a.has_answer_only && !a.has_version) {
        a.version = (uint8_t)a.answer_only; /* a GCU that answers version N only speaks N */
    }
    if (rc != XFGCU_EXIT_OK || (rc = check_args(&a)) != XFGCU_EXIT_OK) {
        return rc;
    }
    s = calloc(1, sizeof(*s));
    if (s == NULL) {
        return cli_fail("sim: out of memory");
    }
    cli_signals_init();
    rc = open_gcu_link(s, &a);
    if (rc == XFGCU_EXIT_OK && (rc = start_sim(s, &a)) == XFGCU_EXIT_OK) {
        print_ready(s, &a);
        run_sim(s, &a);
    }
    if (s->opened) {
        close_gcu_link(s, &a);
    }
    free(s);
    return rc;
}
