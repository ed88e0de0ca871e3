/*
 * cmd_decode.c - `xfgcu decode [--json] [--raw] [--pod-order le|be|auto] [--file FILE] [HEX ...]`.
 *
 * With arguments: each is one whole packet; all are checked before any is
 * printed, and the first bad one fails the command with its fault.
 *
 * Without: stdin is hex text in any layout, read as one byte stream and
 * run through two streaming parsers, one per direction, so host and GCU
 * packets can be mixed (a capture of both sides). The parsers return a
 * frame when it ends and may find one late (after a false header), so
 * frames wait in a small queue sorted by where they start, and leave it
 * once no parser can return anything that starts earlier: the output is
 * in stream order. A line may start with a time (a log: "12.345 A8 E5 ...",
 * "[2026-11-26 10:00:00.123] A8 E5 ..."): each packet then carries the time
 * of the line its last byte is on.
 *
 * A capture (the text format of record, or pcap) on stdin or in --file is
 * decoded as replay decodes it (replay_capture()).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "capture.h"
#include "capture_pcap.h"
#include "cli.h"
#include "hexin.h"
#include "jsonpkt.h"
#include "summary.h"
#include "table.h"

void help_decode(FILE *out)
{
    fputs("usage: xfgcu decode [--json] [--raw] [--pod-order le|be|auto] [--file FILE] [HEX ...]\n\n"
          "Decode packets of either direction (host A8 E5, GCU 8A 5E).\n"
          "Each HEX argument is one whole packet: hex digits, with spaces, colons, commas or 0x\n"
          "prefixes if you like (\"A8 E5 48 00 ...\", \"a8e54800...\", \"0xA8,0xE5,...\"). A bad\n"
          "packet (header, length, CRC, truncated) is an error that names the fault. Bytes given\n"
          "unquoted (decode A8 E5 48 00 ...) are read as one byte string of whole packets.\n"
          "Without HEX, stdin is read as hex text in any layout, one byte stream; every valid\n"
          "packet in it is printed in stream order and everything else is skipped. A line may\n"
          "start with a time: 12.345, [12.345], 2026-11-26T10:00:00.123[Z] or\n"
          "[2026-11-26 10:00:00.123]; each packet then shows the time of the line its last byte\n"
          "is on (\"t\" in seconds, or \"time\", in --json). A capture (`xfgcu capture`, pcap) is\n"
          "decoded as `xfgcu replay` does.\n\n"
          "  --file FILE  read FILE instead of stdin (hex text, a log, or a capture)\n"
          "  --json    one JSON object per packet and line: direction, version, length, order,\n"
          "            params (hex of bytes 70..S-3) and every field under its canonical name, in\n"
          "            engineering units (\"cam_pitch\": -30.0, degrees); reserved_main /\n"
          "            reserved_sub (hex) when not zero; extras: order_name, command /\n"
          "            command_error (host), feedback, mode_name, pod_status_order, pod_flags,\n"
          "            gimbal_model (GCU). `xfgcu encode --json` turns it back into the packet.\n"
          "  --raw     the fields as wire integers (\"cam_pitch\": -3000), in --json and the table;\n"
          "            `xfgcu encode --raw --json` reads them back\n"
          "  --pod-order le|be|auto\n"
          "            the byte order the flags of pod_status are read in (pod_status itself stays\n"
          "            the little-endian wire integer). auto (the default): per packet, the order\n"
          "            that leaves the reserved bits clear; little-endian, the documented order,\n"
          "            when both or neither do. The vendor's own example reads it big-endian.\n"
          "Without --json: a table of field, raw value and engineering value (docs/protocol.md,\n"
          "\"Units\").\n\n"
          "What the vendor's text does not allow (a yaw outside [0, 360), INS valid with a zero\n"
          "attitude, record 0x00, a wrong parameter length...) is a warning, never a refusal: a\n"
          "\"warnings\" list in the JSON, a \"warning:\" line each in the table (docs/protocol.md\n"
          "section 13). A stream (stdin, --file) ends with a summary: packets, bytes skipped, CRC\n"
          "errors and the frames the parsers gave up; with --json the line {\"summary\": {...}},\n"
          "which `xfgcu encode --json` skips.\n",
          out);
}

/* How to print: --json, --pod-order and --raw. */
typedef struct style {
    int json;
    pod_reading pod;
    text_view view;
} style;

/* The time at the start of a log line. */
typedef enum log_kind { LOG_NONE, LOG_SECONDS, LOG_DATE } log_kind;
typedef struct log_time {
    log_kind kind;
    double seconds; /* LOG_SECONDS */
    char text[40];  /* LOG_DATE: "2026-11-26T10:00:00.123" (Z when given) */
} log_time;

/* The JSON object, with "t" or "time" in front when the line said when. */
static int print_json_at(const uint8_t *buf, size_t len, xf_direction dir, const style *how, const log_time *at)
{
    json_t *pkt = jsonpkt_from_wire(buf, len, dir, how->pod, how->view);
    json_t *obj = json_object();
    char *text = NULL;
    int ok = (pkt != NULL && obj != NULL);
    if (ok && at->kind == LOG_SECONDS) {
        ok = json_object_set_new(obj, "t", json_real(at->seconds)) == 0;
    } else if (ok && at->kind == LOG_DATE) {
        ok = json_object_set_new(obj, "time", json_string(at->text)) == 0;
    }
    if (ok && json_object_update(obj, pkt) == 0) {
        text = jsonpkt_dumps(obj);
    }
    json_decref(pkt);
    json_decref(obj);
    if (text == NULL) {
        return cli_fail("decode: out of memory");
    }
    printf("%s\n", text);
    free(text);
    return XFGCU_EXIT_OK;
}

static int print_packet(const uint8_t *buf, size_t len, xf_direction dir, const char *where, const style *how,
                        size_t index)
{
    static const log_time none = {LOG_NONE, 0.0, ""};
    if (how->json) {
        return print_json_at(buf, len, dir, how, &none);
    }
    if (index > 0u) {
        putchar('\n');
    }
    table_print(buf, len, dir, where, how->pod, how->view, stdout);
    return XFGCU_EXIT_OK;
}

/* ---- packets given as arguments -------------------------------------------- */

typedef struct arg_packet {
    uint8_t bytes[XF_PACKET_MAX_LEN];
    size_t len;
    xf_direction dir;
} arg_packet;

/* Say precisely what is wrong with a packet that xf_packet_check refused. */
static int packet_fault(const arg_packet *p, const char *where, xf_err err)
{
    size_t field = (p->len >= 4u) ? xf_get_u16le(p->bytes + XF_OFF_LENGTH) : 0u;
    switch (err) {
    case XF_ERR_HEADER:
        return cli_fail("decode: %s: bad header %02X %02X: a packet starts with A8 E5 (host) or 8A 5E (GCU)", where,
                        p->bytes[0], p->len > 1u ? p->bytes[1] : 0u);
    case XF_ERR_TRUNCATED:
        if (p->len < 4u) {
            return cli_fail("decode: %s: truncated packet: %zu bytes, a packet has at least %u", where, p->len,
                            XF_PACKET_MIN_LEN);
        }
        return cli_fail("decode: %s: truncated packet: %zu bytes, the length field says %zu", where, p->len, field);
    case XF_ERR_LENGTH:
        if (field < XF_PACKET_MIN_LEN || field > XF_PACKET_MAX_LEN) {
            return cli_fail("decode: %s: bad length: the length field says %zu, must be %u..%u", where, field,
                            XF_PACKET_MIN_LEN, XF_PACKET_MAX_LEN);
        }
        return cli_fail("decode: %s: bad length: %zu bytes, the length field says %zu (one packet per argument)", where,
                        p->len, field);
    case XF_ERR_CRC:
        return cli_fail("decode: %s: bad CRC: the packet says %02X %02X, its bytes give %02X %02X", where,
                        p->bytes[field - 2u], p->bytes[field - 1u], (unsigned)(xf_crc16(p->bytes, field - 2u) >> 8),
                        (unsigned)(xf_crc16(p->bytes, field - 2u) & 0xFFu));
    default: return cli_fail("decode: %s: %s", where, xf_strerror(err));
    }
}

static int check_packet(arg_packet *p, const char *where)
{
    xf_err err = xf_packet_direction(p->bytes, p->len, &p->dir);
    if (err == XF_OK) {
        err = xf_packet_check(p->bytes, p->len, p->dir);
    }
    return (err == XF_OK) ? XFGCU_EXIT_OK : packet_fault(p, where, err);
}

/* Hex of argument @p k into @p out (at most @p cap bytes); *n may exceed cap. */
static int argument_bytes(const char *text, int k, uint8_t *out, size_t cap, size_t *n)
{
    hex_fault fault;
    char why[96];
    if (hex_parse_string(text, out, cap, n, &fault) != 0) {
        hex_fault_text(&fault, why, sizeof(why));
        return cli_fail("decode: argument %d, position %zu: %s", k, fault.offset + 1u, why);
    }
    if (*n == 0u) {
        return cli_fail("decode: argument %d: no hex digits", k);
    }
    if (*n > cap) {
        return cli_fail("decode: argument %d: %zu bytes, longer than any packet (%u at most)", k, *n,
                        XF_PACKET_MAX_LEN);
    }
    return XFGCU_EXIT_OK;
}

/* A packet list that grows as packets are found. */
typedef struct packet_list {
    arg_packet *items;
    size_t count;
} packet_list;

static int one_per_argument(int count, char **hex, packet_list *list)
{
    int k, rc = XFGCU_EXIT_OK;
    for (k = 0; k < count && rc == XFGCU_EXIT_OK; k++) {
        arg_packet *p = &list->items[list->count++];
        char where[32];
        snprintf(where, sizeof(where), "argument %d", k + 1);
        rc = argument_bytes(hex[k], k + 1, p->bytes, sizeof(p->bytes), &p->len);
        if (rc == XFGCU_EXIT_OK) {
            rc = check_packet(p, where);
        }
    }
    return rc;
}

/* Cut @p bytes into whole packets, each checked; a fault names its byte offset. */
static int split_packets(const uint8_t *bytes, size_t total, packet_list *list)
{
    size_t at = 0;
    while (at < total) {
        arg_packet *p = &list->items[list->count++];
        size_t rest = total - at, field = (rest >= 4u) ? xf_get_u16le(bytes + at + XF_OFF_LENGTH) : rest;
        size_t take = (field >= XF_PACKET_MIN_LEN && field <= rest) ? field : rest;
        char where[64];
        int rc;
        p->len = (take < sizeof(p->bytes)) ? take : sizeof(p->bytes);
        memcpy(p->bytes, bytes + at, p->len);
        snprintf(where, sizeof(where), "the arguments as one byte string, byte %zu", at);
        rc = check_packet(p, where);
        if (rc != XFGCU_EXIT_OK) {
            return rc;
        }
        at += take;
    }
    return XFGCU_EXIT_OK;
}

/* `decode A8 E5 48 00 ...` unquoted gives one byte per argument: when no
 * argument is long enough to hold even a header and a length, the
 * arguments are read as one byte string of whole packets instead. */
static int all_arguments_short(int count, char **hex)
{
    int k;
    uint8_t tmp[4];
    for (k = 0; k < count; k++) {
        hex_fault fault;
        size_t n = 0;
        if (hex_parse_string(hex[k], tmp, sizeof(tmp), &n, &fault) != 0 || n >= 4u) {
            return 0;
        }
    }
    return count > 1;
}

static int joined_arguments(int count, char **hex, packet_list *list)
{
    uint8_t *bytes = malloc((size_t)count * 4u);
    size_t total = 0;
    int k, rc = XFGCU_EXIT_OK;
    if (bytes == NULL) {
        return cli_fail("decode: out of memory");
    }
    for (k = 0; k < count && rc == XFGCU_EXIT_OK; k++) {
        size_t n = 0;
        rc = argument_bytes(hex[k], k + 1, bytes + total, 4u, &n);
        total += n;
    }
    if (rc == XFGCU_EXIT_OK) {
        rc = split_packets(bytes, total, list);
    }
    free(bytes);
    return rc;
}

static int decode_arguments(int count, char **hex, const style *how)
{
    int joined = all_arguments_short(count, hex);
    size_t k, slots = joined ? ((size_t)count * 4u) / XF_PACKET_MIN_LEN + 1u : (size_t)count;
    packet_list list;
    int rc;
    list.count = 0;
    list.items = calloc(slots, sizeof(*list.items));
    if (list.items == NULL) {
        return cli_fail("decode: out of memory");
    }
    rc = joined ? joined_arguments(count, hex, &list) : one_per_argument(count, hex, &list);
    for (k = 0; k < list.count && rc == XFGCU_EXIT_OK; k++) {
        char where[32];
        snprintf(where, sizeof(where), joined ? "packet %zu of the arguments" : "argument %zu", k + 1u);
        rc = print_packet(list.items[k].bytes, list.items[k].len, list.items[k].dir, where, how, k);
    }
    free(list.items);
    return rc;
}

/* ---- a byte stream on stdin ------------------------------------------------ */

#define STREAM_CHUNK 64u /* bytes fed to the parsers at a time: bounds the queue */
#define QUEUE_MAX    32u /* > frames that can wait: (ring 256 + chunk 64) / 72 per parser, two parsers */

typedef struct found {
    size_t start; /* stream offset of the first byte */
    log_time at;  /* the time of the line that completed it */
    size_t len;
    xf_direction dir;
    uint8_t bytes[XF_PACKET_MAX_LEN];
} found;

typedef struct stream {
    xf_parser parser[2]; /* indexed by xf_direction */
    size_t fed;          /* bytes given to each parser */
    found queue[QUEUE_MAX];
    size_t queued;
    size_t printed;
    size_t packets[2]; /* printed, by xf_direction */
    size_t in_packets; /* bytes of the packets printed */
    style how;
    log_time now;     /* the time of the line being read */
    const char *name; /* "stdin" or the file */
    int rc;
} stream;

static void emit(stream *s, const found *f)
{
    char where[128];
    if (s->rc != XFGCU_EXIT_OK) {
        return;
    }
    if (f->at.kind == LOG_SECONDS) {
        snprintf(where, sizeof(where), "%.60s offset %zu, t %.3f s", s->name, f->start, f->at.seconds);
    } else if (f->at.kind == LOG_DATE) {
        snprintf(where, sizeof(where), "%.60s offset %zu, %s", s->name, f->start, f->at.text);
    } else {
        snprintf(where, sizeof(where), "%.60s offset %zu", s->name, f->start);
    }
    if (s->how.json && f->at.kind != LOG_NONE) {
        s->rc = print_json_at(f->bytes, f->len, f->dir, &s->how, &f->at);
    } else {
        s->rc = print_packet(f->bytes, f->len, f->dir, where, &s->how, s->printed);
    }
    s->printed++;
    s->packets[f->dir]++;
    s->in_packets += f->len;
}

/* Print the queued frames that start before @p limit, earliest first. */
static void flush(stream *s, size_t limit)
{
    size_t n = 0;
    while (n < s->queued && s->queue[n].start < limit) {
        emit(s, &s->queue[n]);
        n++;
    }
    memmove(s->queue, s->queue + n, (s->queued - n) * sizeof(s->queue[0]));
    s->queued -= n;
}

static void enqueue(stream *s, size_t start, xf_direction dir, const xf_frame *frame)
{
    size_t at;
    if (s->queued == QUEUE_MAX) {
        flush(s, s->queue[0].start + 1u); /* cannot happen with the bounds above; stay safe */
    }
    at = s->queued;
    while (at > 0u && s->queue[at - 1u].start > start) {
        at--;
    }
    memmove(s->queue + at + 1, s->queue + at, (s->queued - at) * sizeof(s->queue[0]));
    s->queue[at].start = start;
    s->queue[at].at = s->now;
    s->queue[at].len = frame->len;
    s->queue[at].dir = dir;
    memcpy(s->queue[at].bytes, frame->data, frame->len);
    s->queued++;
}

/* Nothing either parser returns from now on starts before this offset. */
static size_t watermark(const stream *s)
{
    size_t host = s->fed - xf_parser_pending(&s->parser[XF_DIR_HOST]);
    size_t gcu = s->fed - xf_parser_pending(&s->parser[XF_DIR_GCU]);
    return (host < gcu) ? host : gcu;
}

static void feed_parser(stream *s, xf_direction dir, const uint8_t *data, size_t n)
{
    size_t taken = 0, used = 0;
    xf_frame frame;
    while (xf_parser_feed(&s->parser[dir], data + taken, n - taken, &used, &frame) == XF_PARSE_FRAME) {
        taken += used;
        /* the frame ends where the held bytes begin */
        enqueue(s, s->fed + taken - xf_parser_pending(&s->parser[dir]) - frame.len, dir, &frame);
    }
}

static void feed(stream *s, const uint8_t *data, size_t n)
{
    while (n > 0u) {
        size_t k = (n < STREAM_CHUNK) ? n : STREAM_CHUNK;
        feed_parser(s, XF_DIR_HOST, data, k);
        feed_parser(s, XF_DIR_GCU, data, k);
        s->fed += k;
        flush(s, watermark(s));
        data += k;
        n -= k;
    }
}

/* End of input: each parser gives up the candidates that can no longer
 * complete (a false header near the end announces bytes that never come)
 * and returns the intact frames behind them. */
static void finish(stream *s)
{
    xf_frame frame;
    int d;
    for (d = 0; d < 2; d++) {
        while (xf_parser_flush(&s->parser[d], &frame) == XF_PARSE_FRAME) {
            /* the frame ends where the bytes still held begin */
            enqueue(s, s->fed - xf_parser_pending(&s->parser[d]) - frame.len, (xf_direction)d, &frame);
        }
    }
    flush(s, (size_t)-1);
}

static int hex_error(const stream *s, const hex_fault *fault)
{
    char why[96];
    hex_fault_text(fault, why, sizeof(why));
    return cli_fail("decode: %s, line %zu column %zu (offset %zu): %s", s->name, fault->line, fault->column,
                    fault->offset, why);
}

/* digits[.digits]: the length, 0 if none; *frac tells whether a point was there. */
static size_t seconds_at(const char *p, double *sec, int *frac)
{
    size_t k = strspn(p, "0123456789");
    *frac = 0;
    if (k == 0u || k > 12u) {
        return 0;
    }
    if (p[k] == '.') {
        size_t f = strspn(p + k + 1, "0123456789");
        if (f == 0u || f > 9u) {
            return 0;
        }
        *frac = 1;
        k += 1u + f;
    }
    *sec = strtod(p, NULL);
    return k;
}

/* YYYY-MM-DD, @p sep ('T', or ' ' too when bracketed), HH:MM:SS, then .digits and Z optionally. */
static size_t date_at(const char *p, int bracketed, log_time *t)
{
    static const char shape[] = "dddd-dd-dd?dd:dd:dd";
    size_t k, n;
    for (k = 0; shape[k] != '\0'; k++) {
        int ok = (shape[k] == 'd')   ? (p[k] >= '0' && p[k] <= '9')
                 : (shape[k] == '?') ? (p[k] == 'T' || (bracketed && p[k] == ' '))
                                     : (p[k] == shape[k]);
        if (!ok) {
            return 0;
        }
    }
    if (p[k] == '.') {
        n = strspn(p + k + 1, "0123456789");
        if (n == 0u || n > 9u) {
            return 0;
        }
        k += 1u + n;
    }
    k += (p[k] == 'Z');
    snprintf(t->text, sizeof(t->text), "%.*s", (int)k, p);
    t->text[10] = 'T';
    t->kind = LOG_DATE;
    return k;
}

/* The time a log line starts with (the formats of docs/cli.md, decode): the length of the prefix
 * with the blanks after it, 0 when the line has none. A time has a '.', '-' or '[' in it, which no
 * hex text has, so a line of hex is never taken for one. */
static size_t time_prefix(const char *line, log_time *t)
{
    int bracketed = (line[0] == '['), frac = 0;
    const char *p = line + bracketed;
    size_t k = date_at(p, bracketed, t);
    if (k == 0u && (k = seconds_at(p, &t->seconds, &frac)) > 0u) {
        t->kind = LOG_SECONDS;
        if (!frac && !bracketed) {
            return 0; /* "12 A8 ...": plain digits are hex */
        }
    }
    if (k == 0u || (bracketed && p[k] != ']')) {
        return 0;
    }
    k += (size_t)(2 * bracketed); /* in line: after the token and its ']' */
    if (line[k] != ' ' && line[k] != '\t' && line[k] != '\n' && line[k] != '\r' && line[k] != '\0') {
        return 0;
    }
    return k + strspn(line + k, " \t");
}

/* Read hex text line by line, convert, feed; stops at the first fault (*bad set, *fault filled). */
static int read_text(stream *s, FILE *in, int *bad, hex_fault *fault)
{
    char *line = NULL;
    size_t cap = 0, out_cap = 0;
    uint8_t *bytes = NULL;
    ssize_t got;
    hex_reader reader;
    hex_reader_init(&reader);
    *bad = 0;
    errno = 0;
    while (!*bad && s->rc == XFGCU_EXIT_OK && (got = getline(&line, &cap, in)) > 0) {
        size_t n = 0, skip;
        log_time t;
        memset(&t, 0, sizeof(t));
        if (out_cap < (size_t)got) {
            free(bytes);
            out_cap = (size_t)got;
            bytes = malloc(out_cap);
            if (bytes == NULL) {
                free(line);
                return cli_fail("decode: out of memory");
            }
        }
        skip = time_prefix(line, &t);
        if (skip > 0u) {
            s->now = t;              /* lines without a time keep the last one */
            memset(line, ' ', skip); /* the columns of later faults stay right */
        }
        *bad = hex_reader_feed(&reader, line, (size_t)got, bytes, out_cap, &n, fault) != 0;
        feed(s, bytes, n); /* the bytes before a fault are good */
        errno = 0;         /* what getline() says next is its own */
    }
    free(line);
    free(bytes);
    if (!*bad && (ferror(in) || errno == ENOMEM)) { /* out of memory is not the end of the input */
        return cli_fail("decode: cannot read %s: %s", s->name, strerror(errno));
    }
    if (!*bad) {
        *bad = hex_reader_finish(&reader, fault) != 0;
    }
    return XFGCU_EXIT_OK;
}

/* The stream's last word: its packets, the bytes in none, the CRC errors and the frames the two
 * parsers gave up (each parser reads every byte: a byte in no packet is one neither returned). */
static int print_summary(const stream *s)
{
    const xf_parser_stats *h = &s->parser[XF_DIR_HOST].stats;
    const xf_parser_stats *g = &s->parser[XF_DIR_GCU].stats;
    text_summary sum;
    sum.host_packets = s->packets[XF_DIR_HOST];
    sum.gcu_packets = s->packets[XF_DIR_GCU];
    sum.bytes_skipped = (s->fed > s->in_packets) ? (uint64_t)(s->fed - s->in_packets) : 0u;
    sum.crc_errors = (uint64_t)h->crc_errors + g->crc_errors;
    sum.given_up = (uint64_t)h->given_up + g->given_up;
    if (!s->how.json) {
        putchar('\n');
    }
    return summary_print(&sum, s->how.json, stdout) == TEXT_OK ? XFGCU_EXIT_OK : cli_fail("decode: out of memory");
}

static int decode_text(FILE *in, const char *name, const style *how)
{
    stream *s = calloc(1, sizeof(*s));
    hex_fault fault;
    int rc, bad = 0;
    if (s == NULL) {
        return cli_fail("decode: out of memory");
    }
    s->how = *how;
    s->name = name;
    (void)xf_parser_init(&s->parser[XF_DIR_HOST], XF_DIR_HOST);
    (void)xf_parser_init(&s->parser[XF_DIR_GCU], XF_DIR_GCU);
    rc = read_text(s, in, &bad, &fault);
    if (rc == XFGCU_EXIT_OK) {
        finish(s); /* the packets before a hex fault are printed before it is reported */
        rc = s->rc;
    }
    if (rc == XFGCU_EXIT_OK && bad) {
        rc = hex_error(s, &fault);
    } else if (rc == XFGCU_EXIT_OK && s->printed == 0u) {
        uint32_t given_up = s->parser[XF_DIR_HOST].stats.given_up + s->parser[XF_DIR_GCU].stats.given_up;
        rc = (given_up == 0u) ? cli_fail("decode: no valid packet in the %zu bytes read from %s", s->fed, name)
                              : cli_fail("decode: no valid packet in the %zu bytes read from %s (the parsers gave up "
                                         "%u times: false headers)",
                                         s->fed, name, (unsigned)given_up);
    } else if (rc == XFGCU_EXIT_OK) {
        rc = print_summary(s);
    }
    free(s);
    return rc;
}

/* stdin or --file: a capture (by its first byte: '#' or a pcap magic), else hex text or a log.
 * A pcapng file (its first byte is a newline) is recognised in a --file only: on stdin that
 * byte starts hex text. */
static int decode_input(const char *file, const style *how)
{
    FILE *in = (file != NULL) ? fopen(file, "r") : stdin;
    const char *name = (file != NULL) ? file : "stdin";
    int c, rc;
    if (in == NULL) {
        return cli_fail("decode: cannot open %s: %s", file, strerror(errno));
    }
    c = getc(in);
    if (c != EOF) {
        (void)ungetc(c, in);
    } else if (ferror(in)) { /* say why now: errno is reset before the text reader's own reads */
        int e = errno;
        if (in != stdin) {
            fclose(in);
        }
        return cli_fail("decode: cannot read %s: %s", name, strerror(e));
    }
    if (c == '#' || (pcap_magic_byte(c) && (c != '\n' || file != NULL))) {
        return replay_capture(in, name, how->json, (int)how->pod, (int)how->view, 1); /* closes in */
    }
    rc = decode_text(in, name, how);
    if (in != stdin) {
        fclose(in);
    }
    return rc;
}

/* ---- the command ------------------------------------------------------------- */

enum { O_JSON = 256, O_POD_ORDER, O_FILE, O_HELP };

static const struct option decode_options[] = {
    {"json", no_argument, NULL, O_JSON},
    {"pod-order", required_argument, NULL, O_POD_ORDER},
    {"file", required_argument, NULL, O_FILE},
    {"help", no_argument, NULL, O_HELP},
    {NULL, 0, NULL, 0},
};

static int pod_order_option(const cli_args *a, pod_reading *pod)
{
    static const char *const words[] = {"auto", "le", "be"}; /* indexed by pod_reading */
    const char *what = "le, be or auto";
    const char *text = NULL;
    size_t k;
    int rc = cli_value_text(a, what, &text);
    for (k = 0; rc == XFGCU_EXIT_OK && k < sizeof(words) / sizeof(words[0]); k++) {
        if (strcmp(text, words[k]) == 0) {
            *pod = (pod_reading)k;
            return XFGCU_EXIT_OK;
        }
    }
    return (rc == XFGCU_EXIT_OK) ? cli_fail_in(a->context, "--%s %s: must be %s", a->opt->name, text, what) : rc;
}

int cmd_decode(const cli_link *link, int argc, char **argv)
{
    int id, help = 0, nhex = 0, rc = XFGCU_EXIT_OK;
    style how = {0, POD_READ_AUTO, TEXT_ENGINEERING};
    const char *file = NULL;
    char **hex = calloc((size_t)argc, sizeof(*hex));
    cli_args a;
    if (hex == NULL) {
        return cli_fail("decode: out of memory");
    }
    cli_args_init(&a, argc, argv, CLI_IN_ORDER, decode_options, "decode");
    while (rc == XFGCU_EXIT_OK && !help && (id = cli_next(&a)) != CLI_END) {
        switch (id) {
        case O_JSON: how.json = 1; break;
        case O_POD_ORDER: rc = pod_order_option(&a, &how.pod); break;
        case O_FILE: rc = cli_value_text(&a, "a file name", &file); break;
        case O_HELP: help = 1; break;
        case CLI_ARG: hex[nhex++] = a.argv[a.index]; break;
        default: rc = XFGCU_EXIT_USAGE; break; /* CLI_BAD: said */
        }
    }
    how.view = link->view; /* --raw: taken anywhere on the line */
    if (rc == XFGCU_EXIT_OK && help) {
        help_decode(stdout);
    } else if (rc == XFGCU_EXIT_OK) {
        if (nhex > 0 && file != NULL) {
            rc = cli_fail("decode: --file and HEX arguments exclude each other");
        } else {
            rc = (nhex > 0) ? decode_arguments(nhex, hex, &how) : decode_input(file, &how);
        }
    }
    free(hex);
    return rc;
}
