/*
 * report.c - the firmware's report (report.h). Each line is built whole in
 * a buffer and queued only if the ring has room for all of it, so that a
 * slow UART loses whole lines (counted, and said in the next health line),
 * never parts of one. Numbers are written by hand: no printf in the image.
 */
#include "report.h"

#include <string.h>

/* The longest line, the health line with the time and every count at 10 digits, is 358
 * characters with its CR LF. A longer one (a long report_text()) ends in "..." where it was cut. */
#define LINE_MAX 384u
#define TEXT_MAX (LINE_MAX - 5u) /* room for "...\r\n" */

typedef struct line {
    char text[LINE_MAX];
    uint32_t n;
    uint8_t cut; /* something did not fit */
} line;

/* The report's state: main loop only, no interrupt touches it. */
typedef struct report {
    uint32_t (*now_ms)(void);
    int (*put)(uint8_t byte);
    char ring[REPORT_RING];
    uint32_t head, tail;
    uint32_t lost_lines;
    uint32_t ok, failed, timeout, link_lost; /* command results so far */
} report;

static report g_report;

static void put_str(line *l, const char *s)
{
    while (*s != '\0' && l->n < TEXT_MAX) {
        l->text[l->n++] = *s++;
    }
    l->cut = (uint8_t)(l->cut || *s != '\0');
}

static void put_u32(line *l, uint32_t v)
{
    char digits[11];
    uint32_t k = sizeof(digits) - 1u;
    digits[k] = '\0';
    do {
        digits[--k] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0u);
    put_str(l, digits + k);
}

/* "3 CRC errors, ": numbers, each with the words that follow it */
typedef struct count {
    uint32_t n;
    const char *words;
} count;

static void put_counts(line *l, const count *c, uint32_t k)
{
    uint32_t i;
    for (i = 0; i < k; i++) {
        put_u32(l, c[i].n);
        put_str(l, c[i].words);
    }
}

/* "0x20": an order byte as docs/protocol.md and `xfgcu decode` show it */
static void put_hex8(line *l, uint8_t v)
{
    static const char hex[] = "0123456789ABCDEF";
    char text[5] = {'0', 'x', hex[v >> 4], hex[v & 0xFu], '\0'};
    put_str(l, text);
}

/* "xfgcu mcu: 12.345 s: ", the time on the client's clock */
static void begin(line *l)
{
    uint32_t now = g_report.now_ms(), frac = now % 1000u;
    l->n = 0;
    l->cut = 0;
    put_str(l, "xfgcu mcu: ");
    put_u32(l, now / 1000u);
    put_str(l, frac < 10u ? ".00" : frac < 100u ? ".0" : ".");
    put_u32(l, frac);
    put_str(l, " s: ");
}

static void finish(line *l)
{
    uint32_t i;
    if (l->cut) {
        l->text[l->n++] = '.';
        l->text[l->n++] = '.';
        l->text[l->n++] = '.';
    }
    l->text[l->n++] = '\r';
    l->text[l->n++] = '\n';
    if (l->n > REPORT_RING - 1u - (g_report.head - g_report.tail)) {
        g_report.lost_lines++;
        return;
    }
    for (i = 0; i < l->n; i++) {
        g_report.ring[(g_report.head + i) & (REPORT_RING - 1u)] = l->text[i];
    }
    g_report.head += l->n;
}

void report_poll(void)
{
    report *r = &g_report;
    while (r->tail != r->head && r->put((uint8_t)r->ring[r->tail & (REPORT_RING - 1u)])) {
        r->tail++;
    }
}

void report_init(uint32_t (*now_ms)(void), int (*put)(uint8_t byte))
{
    memset(&g_report, 0, sizeof(g_report));
    g_report.now_ms = now_ms;
    g_report.put = put;
}

void report_start(const char *board, uint32_t baud, uint32_t photo_ms)
{
    line l;
    const count counts[] = {{baud, " baud, a photo every "}, {photo_ms, " ms"}};
    begin(&l);
    put_str(&l, "started on ");
    put_str(&l, board);
    put_str(&l, "; gimbal at ");
    put_counts(&l, counts, 2u);
    finish(&l);
}

void report_text(const char *text)
{
    line l;
    begin(&l);
    put_str(&l, text);
    finish(&l);
}

void report_link(void *user, xf_link_state state)
{
    line l;
    (void)user;
    begin(&l);
    put_str(&l, "link ");
    put_str(&l, xf_link_state_name(state));
    finish(&l);
}

static void count_result(xf_cmd_status status)
{
    switch (status) {
    case XF_CMD_OK: g_report.ok++; break;
    case XF_CMD_FAILED: g_report.failed++; break;
    case XF_CMD_TIMEOUT: g_report.timeout++; break;
    case XF_CMD_LINK_LOST: g_report.link_lost++; break;
    default: break; /* operating: progress, not a result */
    }
}

/* "order 0x20 ok (2 packets, 40 ms)", in the words `xfgcu send` gives the outcome. The order goes
 * by its number: xf_order_name() would link every order's name into the image. */
void report_result(void *user, const xf_cmd_result *result)
{
    line l;
    (void)user;
    count_result(result->status);
    begin(&l);
    put_str(&l, "order ");
    put_hex8(&l, result->order);
    put_str(&l, " ");
    put_str(&l, xf_cmd_status_name(result->status));
    put_str(&l, " (");
    put_u32(&l, result->packets);
    put_str(&l, result->packets == 1u ? " packet, " : " packets, ");
    put_u32(&l, result->elapsed_ms);
    put_str(&l, " ms)");
    finish(&l);
}

void report_ins(int valid) { report_text(valid ? "ins valid" : "ins no data"); }

/* The first part in the words of `xfgcu monitor`'s link row ("link up, 50 replies/s, 0 missing/s,
 * 600 sent, 598 received"), the second in those of its parser row. */
void report_health(const xf_client *c, uint32_t rx_overruns)
{
    const xf_health *h = xf_client_health(c);
    const xf_parser_stats *ps = xf_client_parser_stats(c);
    const count counts[] = {
        {h->reply_rate_hz, " replies/s, "},
        {h->replies_missing, " missing/s, "},
        {h->packets_sent, " sent, "},
        {h->replies, " received; "},
        {ps->crc_errors, " CRC errors, "},
        {ps->length_errors, " length errors, "},
        {ps->bytes_skipped, " bytes skipped; commands "},
        {g_report.ok, " ok, "},
        {g_report.failed, " failed, "},
        {g_report.timeout, " timeout, "},
        {g_report.link_lost, " link lost; "},
        {h->send_errors, " send errors, "},
        {rx_overruns, " rx overruns, "},
        {g_report.lost_lines, " report lines lost"},
    };
    line l;
    begin(&l);
    put_str(&l, "link ");
    put_str(&l, xf_link_state_name(h->link));
    put_str(&l, ", ");
    put_counts(&l, counts, (uint32_t)(sizeof(counts) / sizeof(counts[0])));
    finish(&l);
}
