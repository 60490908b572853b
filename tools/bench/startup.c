/* SPDX-License-Identifier: MIT */
/* startup.c — minimal start-up for the MPS2 AN385/AN386 emulated boards:
 * vector table, reset handler (.data/.bss, FPU enable on the M4F), SysTick
 * time base and semihosting output/exit. Memory map (both boards): code in
 * SSRAM1 at 0x00000000 (4 MB), data in SSRAM2/3 at 0x20000000 (4 MB). */
#include <stdint.h>

#include "bench.h"

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;

#define REG(a) (*(volatile uint32_t *)(a))
#define SYST_CSR REG(0xE000E010u)
#define SYST_RVR REG(0xE000E014u)
#define SYST_CVR REG(0xE000E018u)
#define CPACR    REG(0xE000ED88u)
#define ICSR     REG(0xE000ED04u)
#define ICSR_PENDSTSET (1u << 26)
#define SYST_RELOAD 0xFFFFFFu
#define TICK_NS 40u /* SysTick on the processor clock, 25 MHz */

static volatile uint32_t systick_wraps;

static int semihost(int op, const void *arg)
{
    register int r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void bench_puts(const char *s) { semihost(0x04, s); }

void bench_put_u64(uint64_t v)
{
    char buf[24];
    int i = 23;
    buf[i] = 0;
    do {
        /* v % 10 and v / 10 without a 64-bit divide call */
        uint64_t q = 0, r = v;
        for (int b = 63; b >= 0; b--)
            if ((r >> b) >= 10) { r -= (uint64_t)10 << b; q |= (uint64_t)1 << b; }
        buf[--i] = (char)('0' + (int)r);
        v = q;
    } while (v);
    bench_puts(buf + i);
}

void bench_report(const char *what, const char *numeric, const char *variant, uint64_t milli,
                  const char *per)
{
    bench_puts("BENCH ");
    bench_puts(what);
    bench_puts(" ");
    bench_puts(numeric);
    bench_puts(" ");
    bench_puts(variant);
    bench_puts(" ");
    bench_put_u64(milli);
    bench_puts(" ");
    bench_puts(per);
    bench_puts("\n");
}

uint32_t bench_fnv565(uint32_t h, const uint16_t *px, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        h = (h ^ (px[i] & 0xFFu)) * 16777619u;
        h = (h ^ (uint32_t)(px[i] >> 8)) * 16777619u;
    }
    return h;
}

static void put_field(const char *key, uint64_t v)
{
    bench_puts(key);
    bench_put_u64(v);
}

void bench_frame_line(const struct bench_frame *f)
{
    put_field("BENCHX frame_checksum=", f->checksum);
    bench_puts(" scene=");
    bench_puts(f->scene);
    if (f->options) {
        bench_puts(" options=");
        bench_puts(f->options);
    }
    put_field(" width=", f->width);
    put_field(" height=", f->height);
    put_field(" strip_rows=", f->strip_rows);
    put_field(" frames=", f->frames);
    if (f->num_frac) put_field(" num_frac=", f->num_frac);
    bench_puts("\n");
}

int bench_cmdline(char *buf, unsigned len)
{
    struct { char *p; uint32_t n; } blk = { buf, len };
    return semihost(0x15, &blk);
}

int bench_fail(const char *msg)
{
    bench_puts("ERROR ");
    bench_puts(msg);
    bench_puts("\n");
    return 1;
}

uint64_t bench_now(void)
{
    uint32_t w1, w2, v, pending;
    do {
        w1 = systick_wraps;
        v = SYST_CVR;
        pending = ICSR & ICSR_PENDSTSET;
        w2 = systick_wraps;
    } while (w1 != w2);
    /* The counter may have wrapped before its interrupt was taken (qemu
     * delivers interrupts between translation blocks): a pending SysTick with
     * a value from the top half means v was read after that wrap. */
    if (pending && v > SYST_RELOAD / 2) w1++;
    uint64_t ticks = (uint64_t)w1 * (SYST_RELOAD + 1u) + (SYST_RELOAD - v);
    return ticks * TICK_NS;
}

void SysTick_Handler(void) { systick_wraps++; }

static void exit_semihost(int status)
{
    /* SYS_EXIT with ADP_Stopped_ApplicationExit (qemu exits 0) or
     * ADP_Stopped_RunTimeErrorUnknown (qemu exits 1). */
    semihost(0x18, (const void *)(uintptr_t)(status == 0 ? 0x20026u : 0x20023u));
    for (;;) {}
}

void Reset_Handler(void)
{
    uint32_t *src = &_sidata, *dst = &_sdata;
    while (dst < &_edata) *dst++ = *src++;
    for (dst = &_sbss; dst < &_ebss; dst++) *dst = 0;
#if defined(__ARM_FP)
    CPACR |= 0xFu << 20; /* CP10, CP11 full access: enable the FPU */
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    SYST_RVR = SYST_RELOAD;
    SYST_CVR = 0;
    SYST_CSR = 7; /* processor clock, interrupt, enable */
    exit_semihost(bench_main());
}

static void Fault_Handler(void)
{
    bench_puts("FAIL bench: fault\n");
    exit_semihost(1);
}

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))(uintptr_t)&_estack, Reset_Handler, Fault_Handler, Fault_Handler,
    Fault_Handler, Fault_Handler, Fault_Handler, 0, 0, 0, 0, Fault_Handler, Fault_Handler, 0,
    Fault_Handler, SysTick_Handler,
};
