/* SPDX-License-Identifier: MIT */
/* crt0.c — RP2040 vector table and reset handler (bare metal, no SDK).
 *
 * boot2 has set VTOR and MSP from this table and jumped to reset_handler.
 * The reset handler copies .data (and .ram_text) from flash to SRAM, zeroes
 * .bss, brings up clocks and peripherals (board_init) and calls main(). */
#include <stdint.h>
#include "board.h"
#include "rp2040_regs.h"

extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack0_top[];

int main(void);
void reset_handler(void);

/* "0x" and 8 hex digits of v at p; returns the end. */
static char *put_hex(char *p, uint32_t v)
{
    *p++ = '0';
    *p++ = 'x';
    for (int s = 28; s >= 0; s -= 4) *p++ = "0123456789abcdef"[(v >> s) & 15u];
    return p;
}

/* The report of an unexpected fault or interrupt, on UART0 when it is up:
 *   fault core=C ipsr=N pc=0x... lr=0x... xpsr=0x...
 * (IPSR: 2 NMI, 3 HardFault, 11 SVCall, 14 PendSV, 15 SysTick, 16 + n IRQ n;
 * pc, lr and xpsr as the exception stacked them), then the core sleeps. */
__attribute__((used)) static void fault_report(const uint32_t *frame)
{
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    if (REG(UARTCR) & 1u) {
        char line[96], *p = line;
        const char *a = "fault core=";
        while (*a) *p++ = *a++;
        *p++ = (char)('0' + (REG(SIO_CPUID) & 1u));
        a = " ipsr=";
        while (*a) *p++ = *a++;
        if (ipsr >= 10) *p++ = (char)('0' + ipsr / 10 % 10);
        *p++ = (char)('0' + ipsr % 10);
        const char *names[3] = { " pc=", " lr=", " xpsr=" };
        const uint32_t vals[3] = { frame[6], frame[5], frame[7] };
        for (int i = 0; i < 3; i++) {
            for (a = names[i]; *a;) *p++ = *a++;
            p = put_hex(p, vals[i]);
        }
        *p++ = '\r';
        *p++ = '\n';
        *p = 0;
        board_puts_sync(line);
    }
    for (;;) __asm__ volatile("wfi");
}

/* Every vector but reset: the stacked frame (MSP or PSP, from EXC_RETURN
 * bit 2) to fault_report. */
__attribute__((naked)) static void default_handler(void)
{
    __asm__ volatile(
        "movs r0, #4\n"
        "mov  r1, lr\n"
        "tst  r0, r1\n"
        "beq  1f\n"
        "mrs  r0, psp\n"
        "b    2f\n"
        "1:\n"
        "mrs  r0, msp\n"
        "2:\n"
        "bl   fault_report\n");
}


#define D2 default_handler, default_handler
#define D8 D2, D2, D2, D2

/* 16 system vectors + 26 RP2040 interrupts; the only interrupt used is
 * UART0's (IRQ 20, vector 36: the UART's transmit FIFO refilled from the log
 * ring, board.c; DMA completion is polled), all but it and reset point to
 * default_handler. */
__attribute__((section(".vectors"), used))
const vector_fn rp2040_vectors[16 + 26] = {
    (vector_fn)(uintptr_t)__stack0_top,
    reset_handler,
    D8, D8, D8, D8, D2,  /* vectors 2..35 */
    board_uart0_irq,     /* 36 = 16 + UART0_IRQ */
    D2, D2, default_handler,
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
