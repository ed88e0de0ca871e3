/* uart_hal.h - xf_hal over an interrupt-driven UART with two ring buffers. */
#ifndef UART_HAL_H
#define UART_HAL_H

#include "xfgcu/xf_hal.h"

#ifndef UART_RX_RING
#define UART_RX_RING 256u /* two replies' worth at 50 Hz, a power of two */
#endif
#ifndef UART_TX_RING
#define UART_TX_RING 128u /* one host packet (72..84 bytes), a power of two */
#endif

void uart_hal_init(uint32_t baud, xf_hal *hal);
void USART2_IRQHandler(void);

#endif
