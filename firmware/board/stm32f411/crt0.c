/* SPDX-License-Identifier: MIT */
/* crt0.c — STM32F411 vector table and reset handler (bare metal).
 *
 * The reset handler turns the FPU on first (CP10/CP11 full access in
 * CPACR): code built with -mfloat-abi=hard may use FPU registers anywhere,
 * even in the copy loops below. Then .data is copied from flash, .bss
 * zeroed, clocks and peripherals brought up (board_init), and main() runs. */
#include <stdint.h>
#include "board.h"
#include "stm32f411_regs.h"

extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_top[];

int main(void);
void reset_handler(void);

/* An unexpected fault or interrupt stops here; a debugger shows the cause. */
static void default_handler(void)
{
    for (;;) __asm__ volatile("bkpt #0");
}

#define D2 default_handler, default_handler
#define D8 D2, D2, D2, D2

/* 16 system vectors + 86 STM32F411 interrupts; nothing uses interrupts
 * (DMA completion is polled), so all but reset point to default_handler. */
__attribute__((section(".vectors"), used))
const vector_fn stm32f411_vectors[16 + 86] = {
    (vector_fn)(uintptr_t)__stack_top,
    reset_handler,
    D8, D8, D8, D8, D8, D8, D8, D8, D8, D8, D8, D8, D2, D2, /* 100 = 16 + 86 - 2 */
};

void reset_handler(void)
{
    REG(SCB_CPACR) |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
    uint32_t *src = __data_load, *dst = __data_start;
    while (dst < __data_end) *dst++ = *src++;
    for (dst = __bss_start; dst < __bss_end; dst++) *dst = 0;
    board_init();
    main();
    for (;;) __asm__ volatile("wfi");
}
