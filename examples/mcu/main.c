/*
 * main.c - xfgcu on a bare-metal Cortex-M4: one gimbal on USART2 at
 * 115200 baud, the client at 50 Hz from the main loop, the carrier's
 * attitude fed from the (here: stand-in) INS, a photo every 10 s.
 */
#include "xfgcu/xf_client.h"

#include "board.h"
#include "uart_hal.h"

static xf_client g_gimbal;

/* Your INS here: its driver would set this when a solution is ready. */
static volatile uint8_t g_ins_ready;

/* Returning 0 means "no valid data": the client then sends zeros with
 * ins_valid clear rather than anything invented. */
static int read_ins(xf_carrier *out)
{
    if (!g_ins_ready) {
        return 0;
    }
    out->roll_deg = out->pitch_deg = out->yaw_deg = 0.0f; /* the stand-in INS: level, facing north, still */
    out->accel_north = out->accel_east = out->accel_up = 0.0f;
    out->vel_north = out->vel_east = out->vel_up = 0.0f;
    return 1;
}

int main(void)
{
    xf_hal hal;
    xf_command photo;
    uint32_t last_photo = 0;

    board_init();
    uart_hal_init(115200u, &hal);
    if (xf_client_init(&g_gimbal, &hal, NULL) < 0) {
        for (;;) {
        }
    }
    xf_command_init(&photo, XF_ORDER_SHUTTER);
    board_irq_on();
    for (;;) {
        uint32_t now = board_millis();
        xf_carrier ins;
        if (read_ins(&ins)) {
            xf_client_set_carrier(&g_gimbal, &ins, now);
        }
        if (xf_client_link(&g_gimbal) == XF_LINK_UP && xf_ms_since(now, last_photo) >= 10000u) {
            last_photo = now;
            (void)xf_client_submit(&g_gimbal, &photo, NULL, NULL);
        }
        xf_client_step(&g_gimbal, now);
        board_wait_for_interrupt(); /* the next tick or byte */
    }
}
