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
#ifndef UART_TX_IRQ
#define UART_TX_IRQ 1 /* 1: the TXE interrupt sends; 0: uart_hal_poll_tx() does */
#endif
#if UART_TX_IRQ != 0 && UART_TX_IRQ != 1
#error "UART_TX_IRQ must be 0 or 1"
#endif

void uart_hal_init(uint32_t baud, xf_hal *hal);
void USART2_IRQHandler(void);
/* UART_TX_IRQ=0 only: send what the TX ring holds while the USART takes bytes (TXE). Call it
 * from one context only, e.g. the tick: it is the ring's consumer. */
void uart_hal_poll_tx(void);
/* Bytes lost because the RX ring was full (the receive interrupt's count). */
uint32_t uart_hal_rx_overruns(void);

#endif
