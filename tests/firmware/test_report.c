/*
 * test_report.c - the MCU example's report (examples/mcu/report.c) on the host, with a fake
 * clock and a fake UART: the lines it writes, word for word (tests/firmware/firmware_loop.py
 * reads the same lines from the firmware under QEMU).
 *
 *   lines      the first line, link changes, results (singular and plural), the INS, the health
 *              line of a fresh client, and the counts of results by outcome
 *   times      "0.005 s" to "4294967.295 s"
 *   uart       a busy UART: nothing is lost while the ring has room; then whole lines are
 *              dropped, counted in the next health line, never cut in half
 *   cut        a line too long for the buffer ends in "..."
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "report.h"

static uint32_t g_now;
static char g_out[8192];
static size_t g_len;
static int g_busy; /* the fake UART takes nothing */

static uint32_t fake_now(void) { return g_now; }

static int fake_put(uint8_t byte)
{
    if (g_busy || g_len + 1u >= sizeof(g_out)) {
        return 0;
    }
    g_out[g_len++] = (char)byte;
    g_out[g_len] = '\0';
    return 1;
}

static int setup(void **state)
{
    (void)state;
    g_now = 0;
    g_len = 0;
    g_out[0] = '\0';
    g_busy = 0;
    report_init(fake_now, fake_put);
    return 0;
}

/* What the UART got since the last call. */
static const char *sent(void)
{
    static char copy[sizeof(g_out)];
    report_poll();
    memcpy(copy, g_out, g_len + 1u);
    g_len = 0;
    g_out[0] = '\0';
    return copy;
}

static xf_err no_write(void *ctx, const uint8_t *data, size_t len)
{
    (void)ctx;
    (void)data;
    (void)len;
    return XF_OK;
}

static xf_err no_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    (void)ctx;
    (void)buf;
    (void)cap;
    *out_len = 0;
    return XF_OK;
}

static const char fresh_health[] =
    "link down, 0 replies/s, 0 missing/s, 0 sent, 0 received; 0 CRC errors, 0 length errors, "
    "0 bytes skipped; commands %u ok, %u failed, %u timeout, %u link lost; 0 send errors, %u rx overruns, "
    "%u report lines lost\r\n";

static void expect_health(const xf_client *c, unsigned ok, unsigned failed, unsigned timeout, unsigned lost,
                          unsigned overruns, unsigned lines_lost)
{
    char want[512], body[400];
    snprintf(body, sizeof(body), fresh_health, ok, failed, timeout, lost, overruns, lines_lost);
    snprintf(want, sizeof(want), "xfgcu mcu: 2.000 s: %s", body);
    g_now = 2000;
    report_health(c, overruns);
    assert_string_equal(sent(), want);
}

static void result(uint8_t order, xf_cmd_status status, uint16_t packets, uint32_t ms)
{
    xf_cmd_result r;
    memset(&r, 0, sizeof(r));
    r.order = order;
    r.status = status;
    r.packets = packets;
    r.elapsed_ms = ms;
    report_result(NULL, &r);
}

static void test_lines(void **state)
{
    xf_client c;
    xf_hal hal = {NULL, no_write, no_read, NULL};
    (void)state;
    assert_int_equal(xf_client_init(&c, &hal, NULL), XF_OK);
    report_start("a board", 115200u, 10000u);
    assert_string_equal(sent(),
                        "xfgcu mcu: 0.000 s: started on a board; gimbal at 115200 baud, a photo every 10000 ms\r\n");
    g_now = 1234;
    report_link(NULL, XF_LINK_UP);
    report_link(NULL, XF_LINK_STALE);
    report_ins(1);
    report_ins(0);
    assert_string_equal(sent(), "xfgcu mcu: 1.234 s: link up\r\nxfgcu mcu: 1.234 s: link stale\r\n"
                                "xfgcu mcu: 1.234 s: ins valid\r\nxfgcu mcu: 1.234 s: ins no data\r\n");
    result(0x20, XF_CMD_OK, 1, 3);
    result(0x20, XF_CMD_FAILED, 2, 40);
    result(0x0A, XF_CMD_TIMEOUT, 50, 1000);
    result(0x20, XF_CMD_LINK_LOST, 7, 140);
    result(0xE6, XF_CMD_OPERATING, 3, 60); /* progress: reported, not counted */
    result(0x20, XF_CMD_OK, 1, 4);
    assert_string_equal(sent(), "xfgcu mcu: 1.234 s: order 0x20 ok (1 packet, 3 ms)\r\n"
                                "xfgcu mcu: 1.234 s: order 0x20 failed (2 packets, 40 ms)\r\n"
                                "xfgcu mcu: 1.234 s: order 0x0A timeout (50 packets, 1000 ms)\r\n"
                                "xfgcu mcu: 1.234 s: order 0x20 link lost (7 packets, 140 ms)\r\n"
                                "xfgcu mcu: 1.234 s: order 0xE6 operating (3 packets, 60 ms)\r\n"
                                "xfgcu mcu: 1.234 s: order 0x20 ok (1 packet, 4 ms)\r\n");
    expect_health(&c, 2, 1, 1, 1, 7, 0);
}

static void test_times(void **state)
{
    static const struct {
        uint32_t ms;
        const char *text;
    } cases[] = {{5, "0.005"},    {50, "0.050"},     {999, "0.999"},
                 {1000, "1.000"}, {12345, "12.345"}, {4294967295u, "4294967.295"}};
    size_t i;
    char want[64];
    (void)state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        g_now = cases[i].ms;
        report_text("x");
        snprintf(want, sizeof(want), "xfgcu mcu: %s s: x\r\n", cases[i].text);
        assert_string_equal(sent(), want);
    }
}

static void test_uart(void **state)
{
    xf_client c;
    xf_hal hal = {NULL, no_write, no_read, NULL};
    char want[64];
    int i;
    (void)state;
    assert_int_equal(xf_client_init(&c, &hal, NULL), XF_OK);
    g_busy = 1;
    for (i = 0; i < 40; i++) { /* 28 characters each: 18 fit in the 511 bytes of the ring */
        report_text(i < 10 ? "line 0" : "line 1");
        report_poll();
    }
    g_busy = 0;
    report_poll();
    assert_int_equal(g_len, 18u * 28u); /* the first 18 lines, whole, in order */
    snprintf(want, sizeof(want), "xfgcu mcu: 0.000 s: line 1\r\n");
    assert_memory_equal(g_out + 17u * 28u, want, 28u);
    (void)sent();
    expect_health(&c, 0, 0, 0, 0, 0, 22); /* said in the next health line */
}

static void test_cut(void **state)
{
    char text[600];
    const char *out;
    (void)state;
    memset(text, 'a', sizeof(text) - 1u);
    text[sizeof(text) - 1u] = '\0';
    report_text(text);
    out = sent();
    assert_int_equal(strlen(out), 384u);
    assert_memory_equal(out + 384u - 5u, "...\r\n", 5u);
    assert_memory_equal(out, "xfgcu mcu: 0.000 s: aaa", 23u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_lines, setup),
        cmocka_unit_test_setup(test_times, setup),
        cmocka_unit_test_setup(test_uart, setup),
        cmocka_unit_test_setup(test_cut, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
