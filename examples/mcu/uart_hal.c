/*
 * uart_hal.c - the xf_hal of the example firmware: USART2 with an RX ring
 * filled by the receive interrupt and a TX ring drained by the transmit
 * interrupt (UART_TX_IRQ=1), or by uart_hal_poll_tx() for a USART that
 * raises no TXE interrupt (UART_TX_IRQ=0, the emulated board).
 *
 * write() puts a whole packet into the TX ring or nothing (XF_ERR_AGAIN):
 * once sending starts, the ring holds the rest of the packet, so the line
 * sees no idle gap inside it, as the protocol asks.
 */
#include "uart_hal.h"

#include "board.h"

typedef struct ring {
    volatile uint16_t head, tail; /* head: written by the producer, tail: by the consumer */
} ring;

static uint8_t g_rx_buf[UART_RX_RING];
static uint8_t g_tx_buf[UART_TX_RING];
static ring g_rx, g_tx;
static volatile uint32_t g_rx_overruns;

static uint16_t ring_used(const ring *r, uint16_t size) { return (uint16_t)((r->head - r->tail) & (size - 1u)); }

void USART2_IRQHandler(void)
{
    uint32_t sr = USART2_SR;
    if (sr & (USART_SR_RXNE | USART_SR_ORE)) {
        uint8_t b = (uint8_t)USART2_DR; /* reading DR also clears an overrun */
        if (ring_used(&g_rx, UART_RX_RING) < UART_RX_RING - 1u) {
            g_rx_buf[g_rx.head & (UART_RX_RING - 1u)] = b;
            g_rx.head = (uint16_t)(g_rx.head + 1u);
        } else {
            g_rx_overruns++; /* the parser resynchronises on the gap */
        }
    }
    if ((sr & USART_SR_TXE) && (USART2_CR1 & USART_CR1_TXEIE)) {
        if (g_tx.tail != g_tx.head) {
            USART2_DR = g_tx_buf[g_tx.tail & (UART_TX_RING - 1u)];
            g_tx.tail = (uint16_t)(g_tx.tail + 1u);
        } else {
            USART2_CR1 &= ~USART_CR1_TXEIE; /* all sent */
        }
    }
}

static xf_err uart_write(void *ctx, const uint8_t *data, size_t len)
{
    size_t i;
    (void)ctx;
    if (len > (size_t)(UART_TX_RING - 1u - ring_used(&g_tx, UART_TX_RING))) {
        return XF_ERR_AGAIN; /* the previous packet is still going out: skip a cycle */
    }
    for (i = 0; i < len; i++) {
        g_tx_buf[(g_tx.head + i) & (UART_TX_RING - 1u)] = data[i];
    }
    __asm__ volatile("" ::: "memory"); /* the bytes before head: the consumer may be running */
    g_tx.head = (uint16_t)(g_tx.head + len);
#if UART_TX_IRQ
    USART2_CR1 |= USART_CR1_TXEIE;
#endif
    return XF_OK;
}

void uart_hal_poll_tx(void)
{
    while (g_tx.tail != g_tx.head && (USART2_SR & USART_SR_TXE) != 0u) {
        USART2_DR = g_tx_buf[g_tx.tail & (UART_TX_RING - 1u)];
        g_tx.tail = (uint16_t)(g_tx.tail + 1u);
    }
}

uint32_t uart_hal_rx_overruns(void) { return g_rx_overruns; }

static xf_err uart_read(void *ctx, uint8_t *buf, size_t cap, size_t *out_len)
{
    size_t n = 0;
    (void)ctx;
    while (n < cap && g_rx.tail != g_rx.head) {
        buf[n++] = g_rx_buf[g_rx.tail & (UART_RX_RING - 1u)];
        g_rx.tail = (uint16_t)(g_rx.tail + 1u);
    }
    *out_len = n;
    return XF_OK;
}

void uart_hal_init(uint32_t baud, xf_hal *hal)
{
    USART2_BRR = (BOARD_CLOCK_HZ + baud / 2u) / baud;
    USART2_CR1 = USART_CR1_UE | USART_CR1_TE | USART_CR1_RE | USART_CR1_RXNEIE; /* 8N1 */
    NVIC_ISER1 = 1u << (USART2_IRQN - 32u);
    hal->ctx = NULL;
    hal->write = uart_write;
    hal->read = uart_read;
    hal->fd = NULL; /* no descriptors on an MCU */
}
