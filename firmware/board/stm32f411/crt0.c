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

/* "0x" and 8 hex digits of v at p; returns the end. */
static char *put_hex(char *p, uint32_t v)
{
    *p++ = '0';
    *p++ = 'x';
    for (int s = 28; s >= 0; s -= 4) *p++ = "0123456789abcdef"[(v >> s) & 15u];
    return p;
}

/* An unexpected fault or interrupt: the line
 *   fault ipsr=N pc=0x... lr=0x...
 * on USART1 when it is up (IPSR: 2 NMI, 3 HardFault, 4 MemManage, 5 BusFault,
 * 6 UsageFault, 16 + n IRQ n; pc and lr as the exception stacked them), then
 * a system reset (SCB AIRCR SYSRESETREQ): the board starts again instead of
 * waiting for a debugger. */
__attribute__((used)) static void fault_report(const uint32_t *frame)
{
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    if (REG(USART_CR1) & USART_CR1_UE) {
        char line[64], *p = line;
        for (const char *a = "fault ipsr="; *a;) *p++ = *a++;
        if (ipsr >= 100) *p++ = (char)('0' + ipsr / 100 % 10);
        if (ipsr >= 10) *p++ = (char)('0' + ipsr / 10 % 10);
        *p++ = (char)('0' + ipsr % 10);
        for (const char *a = " pc="; *a;) *p++ = *a++;
        p = put_hex(p, frame[6]);
        for (const char *a = " lr="; *a;) *p++ = *a++;
        p = put_hex(p, frame[5]);
        *p++ = '\r';
        *p++ = '\n';
        *p = 0;
        board_puts(line);   /* returns once the last character has left (TC) */
    }
    __asm__ volatile("dsb" ::: "memory");
    REG(SCB_AIRCR) = SCB_AIRCR_SYSRESETREQ;
    __asm__ volatile("dsb" ::: "memory");
    for (;;) {}
}

/* Every vector but reset: the stacked frame (MSP or PSP, from EXC_RETURN
 * bit 2) to fault_report. */
__attribute__((naked)) static void default_handler(void)
{
    __asm__ volatile(
        "tst  lr, #4\n"
        "ite  eq\n"
        "mrseq r0, msp\n"
        "mrsne r0, psp\n"
        "b    fault_report\n");
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
#ifdef STM32_TEST_FAULT
    __asm__ volatile("udf #0");   /* tests: the fault line and the reset */
#endif
    main();
    for (;;) __asm__ volatile("wfi");
}
