/* crt0.c — RP2040 vector table and reset handler (bare metal, no SDK).
 *
 * boot2 has set VTOR and MSP from this table and jumped to reset_handler.
 * The reset handler copies .data (and .ram_text) from flash to SRAM, zeroes
 * .bss, brings up clocks and peripherals (board_init) and calls main(). */
#include <stdint.h>
#include "board.h"

extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack0_top[];

int main(void);
void reset_handler(void);

/* An unexpected fault or interrupt stops here; a debugger shows the cause. */
static void default_handler(void)
{
    for (;;) __asm__ volatile("bkpt #0");
}


#define D2 default_handler, default_handler
#define D8 D2, D2, D2, D2

/* 16 system vectors + 26 RP2040 interrupts; nothing here uses interrupts
 * (DMA completion is polled), so all but reset point to default_handler. */
__attribute__((section(".vectors"), used))
const vector_fn rp2040_vectors[16 + 26] = {
    (vector_fn)(uintptr_t)__stack0_top,
    reset_handler,
    D8, D8, D8, D8, D8, /* 40 = 16 + 26 - 2 */
};

void reset_handler(void)
{
    uint32_t *src = __data_load, *dst = __data_start;
    while (dst < __data_end) *dst++ = *src++;
    for (dst = __bss_start; dst < __bss_end; dst++) *dst = 0;
    board_init();
    main();
    for (;;) __asm__ volatile("wfi");
}
