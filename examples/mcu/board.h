/*
 * board.h - the few STM32F4 registers this example touches (USART2 on
 * PA2/PA3, SysTick, NVIC), written out so that no vendor SDK is needed.
 * Porting to another MCU means rewriting board.c and uart_hal.c only.
 */
#ifndef BOARD_H
#define BOARD_H

#include <stdint.h>

#define REG32(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

/* RCC */
#define RCC_AHB1ENR REG32(0x40023830u)
#define RCC_APB1ENR REG32(0x40023840u)
/* GPIOA */
#define GPIOA_MODER REG32(0x40020000u)
#define GPIOA_AFRL  REG32(0x40020020u)
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
/* SysTick and NVIC */
#define SYST_CSR    REG32(0xE000E010u)
#define SYST_RVR    REG32(0xE000E014u)
#define SYST_CVR    REG32(0xE000E018u)
#define NVIC_ISER1  REG32(0xE000E104u)
#define USART2_IRQN 38u

#define BOARD_CLOCK_HZ 16000000u /* HSI after reset: no PLL set-up needed for 115200 baud */

void board_init(void);
uint32_t board_millis(void);

static inline void board_irq_off(void) { __asm__ volatile("cpsid i" ::: "memory"); }
static inline void board_irq_on(void) { __asm__ volatile("cpsie i" ::: "memory"); }
static inline void board_wait_for_interrupt(void) { __asm__ volatile("wfi"); }

#endif
