/*
 * report.c - the firmware's report (report.h). Each line is built whole in
 * a buffer and queued only if the ring has room for all of it, so that a
 * slow UART loses whole lines (counted, and said in the next health line),
 * never parts of one. Numbers are written by hand: no printf in the image.
 */
#include "report.h"

#include "board.h"

/* The longest line, the health line with every count at 10 digits, is 316 characters. */
#define LINE_MAX 320u

typedef struct line {
    char text[LINE_MAX];
    uint32_t n;
} line;

static char g_ring[REPORT_RING];
static uint32_t g_head, g_tail; /* main loop only: no interrupt touches them */
static uint32_t g_lost_lines;
static uint32_t g_ok, g_failed, g_timeout, g_link_lost; /* command results so far */

static void put_str(line *l, const char *s)
{
    while (*s != '\0' && l->n < LINE_MAX) {
        l->text[l->n++] = *s++;
    }
}

static void put_u32(line *l, uint32_t v)
{
    char digits[10];
    uint32_t k = 0;
    do {
        digits[k++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0u);
    while (k > 0u && l->n < LINE_MAX) {
        l->text[l->n++] = digits[--k];
    }
}

/* "xfgcu mcu: 12.345 s: ", the time on the client's clock */
static void begin(line *l)
{
    uint32_t now = board_millis(), frac = now % 1000u;
    l->n = 0;
    put_str(l, "xfgcu mcu: ");
    put_u32(l, now / 1000u);
    put_str(l, frac < 10u ? ".00" : frac < 100u ? ".0" : ".");
    put_u32(l, frac);
    put_str(l, " s: ");
}

static void finish(line *l)
{
    uint32_t i;
    put_str(l, "\r\n");
    if (l->n > REPORT_RING - 1u - (g_head - g_tail)) {
        g_lost_lines++;
        return;
    }
    for (i = 0; i < l->n; i++) {
        g_ring[(g_head + i) & (REPORT_RING - 1u)] = l->text[i];
    }
    g_head += l->n;
}

void report_poll(void)
{
    while (g_tail != g_head && board_report_put((uint8_t)g_ring[g_tail & (REPORT_RING - 1u)])) {
        g_tail++;
    }
}

void report_start(uint32_t baud, uint32_t photo_ms)
{
    line l;
    begin(&l);
    put_str(&l, "started on ");
    put_str(&l, board_name);
    put_str(&l, "; gimbal at ");
    put_u32(&l, baud);
    put_str(&l, " baud, a photo every ");
    put_u32(&l, photo_ms);
    put_str(&l, " ms");
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
    case XF_CMD_OK: g_ok++; break;
    case XF_CMD_FAILED: g_failed++; break;
    case XF_CMD_TIMEOUT: g_timeout++; break;
    case XF_CMD_LINK_LOST: g_link_lost++; break;
    default: break; /* operating: progress, not a result */
    }
}

/* "shutter ok (2 packets, 40 ms)", with the words `xfgcu send` names the outcome in */
void report_result(void *user, const xf_cmd_result *result)
{
    const char *name = xf_order_name(result->order);
    line l;
    (void)user;
    count_result(result->status);
    begin(&l);
    put_str(&l, name != NULL ? name : "order");
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

/* "link up, 50 replies/s, 0 missing/s, 600 sent, 598 received", as `xfgcu monitor` prints it */
static void put_link(line *l, const xf_health *h)
{
    put_str(l, "link ");
    put_str(l, xf_link_state_name(h->link));
    put_str(l, ", ");
    put_u32(l, h->reply_rate_hz);
    put_str(l, " replies/s, ");
    put_u32(l, h->replies_missing);
    put_str(l, " missing/s, ");
    put_u32(l, h->packets_sent);
    put_str(l, " sent, ");
    put_u32(l, h->replies);
    put_str(l, " received");
}

/* "0 CRC errors, 0 length errors, 0 bytes skipped", as `xfgcu monitor` prints the parser's */
static void put_parser(line *l, const xf_parser_stats *ps)
{
    put_u32(l, ps->crc_errors);
    put_str(l, " CRC errors, ");
    put_u32(l, ps->length_errors);
    put_str(l, " length errors, ");
    put_u32(l, ps->bytes_skipped);
    put_str(l, " bytes skipped");
}

static void put_commands(line *l)
{
    put_str(l, "commands ");
    put_u32(l, g_ok);
    put_str(l, " ok, ");
    put_u32(l, g_failed);
    put_str(l, " failed, ");
    put_u32(l, g_timeout);
    put_str(l, " timeout, ");
    put_u32(l, g_link_lost);
    put_str(l, " link lost");
}

void report_health(const xf_client *c, uint32_t rx_overruns)
{
    const xf_health *h = xf_client_health(c);
    line l;
    begin(&l);
    put_link(&l, h);
    put_str(&l, "; ");
    put_parser(&l, xf_client_parser_stats(c));
    put_str(&l, "; ");
    put_commands(&l);
    put_str(&l, "; ");
    put_u32(&l, h->send_errors);
    put_str(&l, " send errors, ");
    put_u32(&l, rx_overruns);
    put_str(&l, " rx overruns, ");
    put_u32(&l, g_lost_lines);
    put_str(&l, " report lines lost");
    finish(&l);
}
