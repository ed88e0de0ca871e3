/*
 * board.h - the few STM32F4 registers this example touches (USART2 on
 * PA2/PA3 for the gimbal, USART1 on PA9 for the report, SysTick, NVIC),
 * written out so that no vendor SDK is needed, and the board's functions.
 * Porting to another MCU means rewriting board.c and uart_hal.c only; the
 * emulated board (board_netduinoplus2.c) is such a port.
 */
#ifndef BOARD_H
#define BOARD_H

#include <stdint.h>

#define REG32(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

/* RCC */
#define RCC_AHB1ENR REG32(0x40023830u)
#define RCC_APB1ENR REG32(0x40023840u)
#define RCC_APB2ENR REG32(0x40023844u)
/* GPIOA */
#define GPIOA_MODER REG32(0x40020000u)
#define GPIOA_AFRL  REG32(0x40020020u)
#define GPIOA_AFRH  REG32(0x40020024u)
/* USART2 */
#define USART2_SR        REG32(0x40004400u)
#define USART2_DR        REG32(0x40004404u)
#define USART2_BRR       REG32(0x40004408u)
#define USART2_CR1       REG32(0x4000440Cu)
#define USART_SR_RXNE    (1u << 5)
#define USART_SR_TXE     (1u << 7)
#define USART_SR_ORE     (1u << 3)
#define USART_CR1_UE     (1u << 13)
#define USART_CR1_TXEIE  (1u << 7)
#define USART_CR1_RXNEIE (1u << 5)
#define USART_CR1_TE     (1u << 3)
#define USART_CR1_RE     (1u << 2)
/* USART1: the report (board_report_put) */
#define USART1_SR  REG32(0x40011000u)
#define USART1_DR  REG32(0x40011004u)
#define USART1_BRR REG32(0x40011008u)
#define USART1_CR1 REG32(0x4001100Cu)
/* SysTick and NVIC */
#define SYST_CSR    REG32(0xE000E010u)
#define SYST_RVR    REG32(0xE000E014u)
#define SYST_CVR    REG32(0xE000E018u)
#define NVIC_ISER1  REG32(0xE000E104u)
#define USART2_IRQN 38u

#ifndef BOARD_CLOCK_HZ
#define BOARD_CLOCK_HZ 16000000u /* HSI after reset: no PLL set-up needed for 115200 baud */
#endif
#define BOARD_REPORT_BAUD 115200u

extern const char board_name[]; /* for the report's first line */

void board_init(void); /* the millisecond tick, the pins, the report UART */
uint32_t board_millis(void);

/* The report UART (USART1, TX only, 8N1), the same on both boards. */
static inline void board_report_init(void)
{
    USART1_BRR = (BOARD_CLOCK_HZ + BOARD_REPORT_BAUD / 2u) / BOARD_REPORT_BAUD;
    USART1_CR1 = USART_CR1_UE | USART_CR1_TE;
}

/* One byte to the report UART if its transmitter can take it now: 1, else 0. Never waits. */
static inline int board_report_put(uint8_t b)
{
    if ((USART1_SR & USART_SR_TXE) == 0u) {
        return 0;
    }
    USART1_DR = b;
    return 1;
}

static inline void board_irq_off(void) { __asm__ volatile("cpsid i" ::: "memory"); }
static inline void board_irq_on(void) { __asm__ volatile("cpsie i" ::: "memory"); }
static inline void board_wait_for_interrupt(void) { __asm__ volatile("wfi"); }

#endif
