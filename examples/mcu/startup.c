/*
 * startup.c - vector table and reset handler for the example (Cortex-M4),
 * in C: copy .data, zero .bss, run main.
 */
#include <stdint.h>

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
int main(void);
void Reset_Handler(void);
void Default_Handler(void);
void SysTick_Handler(void);
void USART2_IRQHandler(void);

void Default_Handler(void)
{
    for (;;) {
    }
}

void Reset_Handler(void)
{
    uint32_t *src = &_sidata, *dst = &_sdata;
    /* The linker's section bounds: comparing them is what startup code does. */
    // cppcheck-suppress comparePointers
    while (dst < &_edata) {
        *dst++ = *src++;
    }
    // cppcheck-suppress comparePointers
    for (dst = &_sbss; dst < &_ebss;) {
        *dst++ = 0;
    }
    /* Cortex-M4F: enable the FPU (CP10, CP11 full access) before any float code runs. */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n isb");
    (void)main();
    for (;;) {
    }
}

/* 16 system exceptions, then the STM32F4's interrupts up to USART2 (IRQ 38). */
typedef void (*vector)(void);
__attribute__((section(".isr_vector"), used)) static const vector g_vectors[16 + 39] = {
    [0] = (vector)(uintptr_t)&_estack,
    [1] = Reset_Handler,
    [2] = Default_Handler, /* NMI */
    [3] = Default_Handler, /* HardFault */
    [4] = Default_Handler,
    [5] = Default_Handler,
    [6] = Default_Handler,
    [11] = Default_Handler, /* SVCall */
    [14] = Default_Handler, /* PendSV */
    [15] = SysTick_Handler,
    [16 + 38] = USART2_IRQHandler,
};
