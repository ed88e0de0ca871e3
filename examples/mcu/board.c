/* board.c - clock tick and pins for the example board (STM32F4, HSI 16 MHz). */
#include "board.h"

static volatile uint32_t g_millis;

void SysTick_Handler(void);
void SysTick_Handler(void) { g_millis++; }

uint32_t board_millis(void) { return g_millis; }

void board_init(void)
{
    RCC_AHB1ENR |= 1u << 0;  /* GPIOA */
    RCC_APB1ENR |= 1u << 17; /* USART2 */
    /* PA2 (TX), PA3 (RX): alternate function 7 */
    GPIOA_MODER = (GPIOA_MODER & ~(0xFu << 4)) | (0xAu << 4);
    GPIOA_AFRL = (GPIOA_AFRL & ~(0xFFu << 8)) | (0x77u << 8);
    /* 1 ms tick */
    SYST_RVR = BOARD_CLOCK_HZ / 1000u - 1u;
    SYST_CVR = 0;
    SYST_CSR = 7u; /* processor clock, interrupt, enable */
}
