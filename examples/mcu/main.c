/*
 * main.c - xfgcu on a bare-metal Cortex-M4: one gimbal on USART2 at
 * 115200 baud, the client at 50 Hz from the main loop, the carrier's
 * attitude fed from the (here: stand-in) INS, a photo every 10 s, and a
 * report of the link's health on the report UART (report.h). The same file
 * runs on the real board (board.c) and on the emulated one
 * (board_netduinoplus2.c).
 */
#include "xfgcu/xf_client.h"

#include "board.h"
#include "report.h"
#include "uart_hal.h"

#ifndef EXAMPLE_PHOTO_MS
#define EXAMPLE_PHOTO_MS 10000u /* a photo this often while the link is up */
#endif
#ifndef EXAMPLE_INS_ALIGN_MS
#define EXAMPLE_INS_ALIGN_MS 5000u /* the stand-in INS has no solution for this long after start */
#endif
#ifndef EXAMPLE_REPORT_MS
#define EXAMPLE_REPORT_MS 1000u /* a health line this often */
#endif
#if EXAMPLE_PHOTO_MS < 1u || EXAMPLE_REPORT_MS < 1u
#error "EXAMPLE_PHOTO_MS and EXAMPLE_REPORT_MS must be at least 1"
#endif

#define GIMBAL_BAUD 115200u

static xf_client g_gimbal;

/* Your INS here. The stand-in has no solution while it aligns, then reports
 * level, facing north, still. Returning 0 means "no valid data": the client
 * then sends zeros with ins_valid clear rather than anything invented. */
static int read_ins(uint32_t since_start_ms, xf_carrier *out)
{
    static uint8_t aligned;
    aligned = (uint8_t)(aligned || since_start_ms >= EXAMPLE_INS_ALIGN_MS);
    if (!aligned) {
        return 0;
    }
    out->roll_deg = out->pitch_deg = out->yaw_deg = 0.0f;
    out->accel_north = out->accel_east = out->accel_up = 0.0f;
    out->vel_north = out->vel_east = out->vel_up = 0.0f;
    return 1;
}

static int start_client(void)
{
    xf_hal hal;
    xf_client_config cfg;
    uart_hal_init(GIMBAL_BAUD, &hal);
    xf_client_config_init(&cfg);
    cfg.on_link = report_link;     /* a line per change of the link's state */
    cfg.on_result = report_result; /* a line per command result */
    cfg.reorder_fixed = 1;         /* a UART keeps order: no need to judge the link first */
    return xf_client_init(&g_gimbal, &hal, &cfg) == XF_OK;
}

int main(void)
{
    xf_command photo;
    uint32_t start, last_photo, last_report;
    int ins_was = 0;

    board_init();
    start = last_photo = last_report = board_millis();
    report_init(board_millis, board_report_put);
    report_start(board_name, GIMBAL_BAUD, EXAMPLE_PHOTO_MS);
    if (!start_client()) {
        report_text("xf_client_init failed: check the HAL and the configuration");
        for (;;) {
            report_poll();
        }
    }
    xf_command_init(&photo, XF_ORDER_SHUTTER);
    board_irq_on();
    for (;;) {
        uint32_t now = board_millis();
        xf_carrier ins;
        int ins_ok = read_ins(xf_ms_since(now, start), &ins);
        if (ins_ok) {
            xf_client_set_carrier(&g_gimbal, &ins, now);
        }
        if (ins_ok != ins_was) {
            ins_was = ins_ok;
            report_ins(ins_ok);
        }
        if (xf_client_link(&g_gimbal) == XF_LINK_UP && xf_ms_since(now, last_photo) >= EXAMPLE_PHOTO_MS) {
            last_photo = now;
            (void)xf_client_submit(&g_gimbal, &photo, NULL, NULL);
        }
        xf_client_step(&g_gimbal, now);
        if (xf_ms_since(now, last_report) >= EXAMPLE_REPORT_MS) {
            last_report = now;
            report_health(&g_gimbal, uart_hal_rx_overruns());
        }
        report_poll();
        board_wait_for_interrupt(); /* the next tick or byte */
    }
}
