/* board.c - clock tick, pins and report UART for the example board (STM32F4, HSI 16 MHz). */
#include "board.h"

const char board_name[] = "STM32F4 (HSI 16 MHz)";

static volatile uint32_t g_millis;

void SysTick_Handler(void);
void SysTick_Handler(void) { g_millis++; }

uint32_t board_millis(void) { return g_millis; }

void board_init(void)
{
    RCC_AHB1ENR |= 1u << 0;  /* GPIOA */
    RCC_APB1ENR |= 1u << 17; /* USART2 */
    RCC_APB2ENR |= 1u << 4;  /* USART1 */
    /* PA2 (TX), PA3 (RX): USART2; PA9: USART1 TX; alternate function 7 */
    GPIOA_MODER = (GPIOA_MODER & ~((0xFu << 4) | (0x3u << 18))) | (0xAu << 4) | (0x2u << 18);
    GPIOA_AFRL = (GPIOA_AFRL & ~(0xFFu << 8)) | (0x77u << 8);
    GPIOA_AFRH = (GPIOA_AFRH & ~(0xFu << 4)) | (0x7u << 4);
    board_report_init();
    /* 1 ms tick */
    SYST_RVR = BOARD_CLOCK_HZ / 1000u - 1u;
    SYST_CVR = 0;
    SYST_CSR = 7u; /* processor clock, interrupt, enable */
}
