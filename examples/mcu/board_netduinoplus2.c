/*
 * board_netduinoplus2.c - the example's board file for QEMU's netduinoplus2
 * machine, an emulated STM32F405, used in place of board.c. It holds what
 * differs from the real board, as a port to a new board would:
 *
 * - Clock. The machine runs at a fixed 168 MHz, and SysTick counts that
 *   processor clock: the image is built with BOARD_CLOCK_HZ=168000000u.
 * - Pins. QEMU models no RCC and no GPIO: no clock to enable, no pin to
 *   route.
 * - UART. The emulated USART sends each byte the moment DR is written and
 *   keeps TXE set, but never raises the TXE interrupt. So uart_hal.c is
 *   built with UART_TX_IRQ=0 and the tick sends what write() queued
 *   (uart_hal_poll_tx()). On a real USART at 115200 baud, TXE is set again
 *   only after each byte's 87 us, so this would send one byte per tick.
 */
#include "board.h"
#include "uart_hal.h"

const char board_name[] = "QEMU netduinoplus2 (emulated STM32F405, 168 MHz)";

static volatile uint32_t g_millis;

void SysTick_Handler(void);
void SysTick_Handler(void)
{
    g_millis++;
    uart_hal_poll_tx(); /* the TX ring's only consumer */
}

uint32_t board_millis(void) { return g_millis; }

void board_init(void)
{
    board_report_init();
    SYST_RVR = BOARD_CLOCK_HZ / 1000u - 1u; /* 1 ms tick */
    SYST_CVR = 0;
    SYST_CSR = 7u; /* processor clock, interrupt, enable */
}
