/* SPDX-License-Identifier: MIT */
/* board.c — RP2040 clocks, resets, UART0 (its log ring), timer and the second core. */
#include "board.h"
#include "rp2040_regs.h"

/* ---- the log ring ---------------------------------------------------------
 * Written by board_puts on core 0 with interrupts masked, read by the UART
 * interrupt on core 0: head and tail count characters (free-running, the
 * index is the count modulo the size). */
#ifndef RP2040_LOG_RING
#define RP2040_LOG_RING 512
#endif
#if RP2040_LOG_RING & (RP2040_LOG_RING - 1)
#error "RP2040_LOG_RING must be a power of two"
#endif
static char log_ring[RP2040_LOG_RING];
static volatile uint32_t log_head, log_tail;

static void unreset(uint32_t mask)
{
    REG_CLR(RESETS_RESET) = mask;
    while ((REG(RESETS_DONE) & mask) != mask) {}
}

/* f_out = 12 MHz * fbdiv / (pd1 * pd2); VCO = 12 MHz * fbdiv in 750..1600 MHz. */
static void pll_start(uint32_t base, uint32_t reset_bit, uint32_t fbdiv, uint32_t pd1, uint32_t pd2)
{
    REG_SET(RESETS_RESET) = reset_bit;
    unreset(reset_bit);
    REG(PLL_CS(base)) = 1;  /* REFDIV = 1 */
    REG(PLL_FBDIV(base)) = fbdiv;
    REG_CLR(PLL_PWR(base)) = PLL_PWR_PD | PLL_PWR_VCOPD;
    while (!(REG(PLL_CS(base)) & PLL_LOCK)) {}
    REG(PLL_PRIM(base)) = (pd1 << 16) | (pd2 << 12);
    REG_CLR(PLL_PWR(base)) = PLL_PWR_POSTDIVPD;
}

/* At least n cycles of clk_sys (an iteration takes more than one: a
 * subtraction and a taken branch; usable before the timer runs). */
void board_delay_cycles(uint32_t n)
{
    for (uint32_t i = n; i; i--) __asm__ volatile("" ::: "memory");
}

#if RP2040_FLASH_DIV != RP2040_BOOT2_DIV
/* The XIP SSI's clock divider; from SRAM (.ram_text, in every image), since
 * the SSI is disabled meanwhile: once the last flash access has left the
 * SSI, disabled, BAUDR written, enabled again (its other registers, boot2's
 * read mode, are kept; the flash stays in its continuous-read mode). */
__attribute__((section(".ram_text"), noinline)) static void xip_set_div(uint32_t div)
{
    while (REG(XIP_SSI_SR) & XIP_SSI_SR_BUSY) {}
    REG(XIP_SSI_SSIENR) = 0;
    REG(XIP_SSI_BAUDR) = div;
    REG(XIP_SSI_SSIENR) = 1;
}
#endif

static void clocks_init(void)
{
    REG(CLK_SYS_RESUS_CTRL) = 0;
    REG(XOSC_CTRL) = XOSC_RANGE_1_15MHZ;
    REG(XOSC_STARTUP) = 47;  /* ~1 ms: (12 MHz / 1000 + 128) / 256 */
    REG_SET(XOSC_CTRL) = XOSC_ENABLE;
    while (!(REG(XOSC_STATUS) & XOSC_STABLE)) {}

    /* Run from clk_ref while the PLLs change; clk_ref = XOSC / 1 (the
     * divider written rather than trusted to its reset value: the timer's
     * 1 us tick below assumes 12 MHz). */
    REG_CLR(CLK_SYS_CTRL) = CLK_SYS_SRC_AUX;
    while (!(REG(CLK_SYS_SELECTED) & 1u)) {}
    REG(CLK_REF_DIV) = 1u << 8;
    REG(CLK_REF_CTRL) = CLK_REF_SRC_XOSC;
    while (!(REG(CLK_REF_SELECTED) & (1u << CLK_REF_SRC_XOSC))) {}

#if RP2040_VREG_VSEL != 11
    /* A faster clk_sys needs the higher core voltage first: the regulator
     * is told, reports regulation, and gets at least 10 ms to settle
     * (60,000 iterations of board_delay_cycles, each two cycles or more of
     * the 12 MHz clk_ref) before anything runs faster. */
    REG(VREG_CTRL) = VREG_EN | VREG_VSEL(RP2040_VREG_VSEL);
    while (!(REG(VREG_CTRL) & VREG_ROK)) {}
    board_delay_cycles(60000);
#endif
#if RP2040_FLASH_DIV != RP2040_BOOT2_DIV
    /* The flash clock too, while clk_sys is still slow (boot2's read mode
     * is kept: only the divider changes). */
    xip_set_div(RP2040_FLASH_DIV);
#endif
    /* VCO RP2040_SYS_MHZ * P MHz (133: 1596/6/2; 125: 1500/6/2; 200 and 250: 1200 and 1500/6/1) */
    pll_start(PLL_SYS_BASE, RESET_PLL_SYS, RP2040_PLL_FBDIV, RP2040_PLL_PD1, RP2040_PLL_PD2);
    pll_start(PLL_USB_BASE, RESET_PLL_USB, 125, 6, 2);  /* 125 MHz for clk_peri */

    REG(CLK_SYS_DIV) = 1u << 8;
    REG(CLK_SYS_CTRL) = CLK_SYS_AUX_PLL_SYS;  /* AUXSRC first, then switch SRC */
    REG(CLK_SYS_CTRL) = CLK_SYS_AUX_PLL_SYS | CLK_SYS_SRC_AUX;
    while (!(REG(CLK_SYS_SELECTED) & 2u)) {}

    /* clk_peri has only an auxiliary mux, which is not glitch-free: stop
     * the clock, let the stop reach the output (two cycles of the old
     * source, which can be as slow as the 6.5 MHz ring oscillator: 3 of its
     * periods are under 64 clk_sys cycles), then change the source and
     * start it again. */
    REG_CLR(CLK_PERI_CTRL) = CLK_PERI_ENABLE;
    board_delay_cycles(64);
    REG(CLK_PERI_CTRL) = CLK_PERI_AUX_PLL_USB;
    REG(CLK_PERI_CTRL) = CLK_PERI_ENABLE | CLK_PERI_AUX_PLL_USB;

    /* Timer tick: 1 us from the 12 MHz clk_ref. */
    REG(WATCHDOG_TICK) = WATCHDOG_TICK_EN | 12u;
}

static void uart_init(void)
{
    unreset(RESET_UART0);
    /* 125 MHz / (16 * 115200) = 67.817: IBRD 67, FBRD round(0.817 * 64) = 52 */
    REG(UARTIBRD) = 67;
    REG(UARTFBRD) = 52;
    REG(UARTLCR_H) = (3u << 5) | (1u << 4);  /* 8 bits, FIFOs on */
    REG(UARTIFLS) = 0;                       /* transmit interrupt at 1/8 full (4 left) */
    REG(UARTIMSC) = 0;
    REG(UARTICR) = 0x7ffu;
    REG(UARTCR) = (1u << 0) | (1u << 8);     /* UARTEN, TXE */
    REG(GPIO_CTRL(RP2040_UART_TX)) = GPIO_FUNC_UART;
    log_head = log_tail = 0;
    REG(NVIC_ICPR) = 1u << UART0_IRQ;
    REG(NVIC_ISER) = 1u << UART0_IRQ;        /* core 0's NVIC: core 1 never takes it */
}

/* Core 0 may start with the rest of the chip still running: after a reset
 * of core 0 alone (a debug probe's reset, SYSRESETREQ) core 1 is where the
 * last run left it (rendering, or waiting for a message that will not come),
 * a spinlock may be held, and DMA may still be sending. So core 1 goes back
 * to the boot ROM through the power-on state machine (forced off, then
 * released: it waits for the launch sequence again), every spinlock is
 * released and the blocks the firmware uses are reset. */
static void chip_to_known_state(void)
{
    REG_SET(PSM_FRCE_OFF) = PSM_PROC1;
    while (!(REG(PSM_FRCE_OFF) & PSM_PROC1)) {}
    REG_CLR(PSM_FRCE_OFF) = PSM_PROC1;
    for (unsigned n = 0; n < 32; n++) REG(SIO_SPINLOCK(n)) = 1;   /* a write releases it */
    REG_SET(RESETS_RESET) = RESET_IO_RESETS;
}

void board_init(void)
{
    chip_to_known_state();
    clocks_init();
    unreset(RESET_IO_BANK0 | RESET_PADS_BANK0 | RESET_TIMER | RESET_DMA | RESET_SPI0);
    uart_init();
}

uint64_t board_now_us(void)
{
    /* Read high, low, high again: retry if the low word wrapped in between. */
    uint32_t hi, lo;
    do {
        hi = REG(TIMER_RAWH);
        lo = REG(TIMER_RAWL);
    } while (hi != REG(TIMER_RAWH));
    return ((uint64_t)hi << 32) | lo;
}

void board_delay_us(uint32_t us)
{
    uint64_t end = board_now_us() + us;
    while (board_now_us() < end) {}
}


static uint32_t irq_mask(void)
{
    uint32_t m;
    __asm__ volatile("mrs %0, primask\n cpsid i" : "=r"(m)::"memory");
    return m;
}

static void irq_restore(uint32_t m) { __asm__ volatile("msr primask, %0" ::"r"(m) : "memory"); }

/* Moves characters from the ring to the FIFO while it has room (never
 * waits); the transmit interrupt stays enabled while the ring holds more. */
static void log_kick(void)
{
    uint32_t t = log_tail;
    const uint32_t h = log_head;
    while (t != h && !(REG(UARTFR) & UARTFR_TXFF)) REG(UARTDR) = (uint8_t)log_ring[t++ % RP2040_LOG_RING];
    log_tail = t;
    /* the FIFO is full when characters are left: the interrupt comes when
     * it has drained to its trigger level */
    if (t != h) REG_SET(UARTIMSC) = UART_TXIM;
    else REG_CLR(UARTIMSC) = UART_TXIM;
}

void board_uart0_irq(void)
{
    REG(UARTICR) = UART_TXIM;
    log_kick();
}

void board_puts(const char *s)
{
    const uint32_t m = irq_mask();
    for (; *s; s++) {
        if (log_head - log_tail == RP2040_LOG_RING) {
            /* full: the oldest character to the FIFO as soon as it has room */
            while (REG(UARTFR) & UARTFR_TXFF) {}
            REG(UARTDR) = (uint8_t)log_ring[log_tail++ % RP2040_LOG_RING];
        }
        log_ring[log_head++ % RP2040_LOG_RING] = *s;
    }
    log_kick();
    irq_restore(m);
}

void board_puts_sync(const char *s)
{
    const uint32_t m = irq_mask();
    REG_CLR(UARTIMSC) = UART_TXIM;
    while (log_tail != log_head) {
        while (REG(UARTFR) & UARTFR_TXFF) {}
        REG(UARTDR) = (uint8_t)log_ring[log_tail++ % RP2040_LOG_RING];
    }
    for (; *s; s++) {
        while (REG(UARTFR) & UARTFR_TXFF) {}
        REG(UARTDR) = (uint8_t)*s;
    }
    irq_restore(m);
}

uint32_t board_core_id(void) { return REG(SIO_CPUID); }

void board_lock(void)
{
    while (REG(SIO_SPINLOCK(31)) == 0) {}
    __asm__ volatile("dmb" ::: "memory");
}

void board_unlock(void)
{
    __asm__ volatile("dmb" ::: "memory");
    REG(SIO_SPINLOCK(31)) = 0;
}

void board_fifo_push(uint32_t v)
{
    while (!(REG(SIO_FIFO_ST) & SIO_FIFO_RDY)) {}
    REG(SIO_FIFO_WR) = v;
    __asm__ volatile("sev");
}

uint32_t board_fifo_pop(void)
{
    while (!(REG(SIO_FIFO_ST) & SIO_FIFO_VLD)) __asm__ volatile("wfe");
    return REG(SIO_FIFO_RD);
}

static void fifo_drain(void)
{
    while (REG(SIO_FIFO_ST) & SIO_FIFO_VLD) (void)REG(SIO_FIFO_RD);
}

/* The FIFO's next word into *v, waiting until the deadline (board_now_us);
 * 0, or -1 when none came. */
static int fifo_pop_until(uint32_t *v, uint64_t deadline)
{
    while (!(REG(SIO_FIFO_ST) & SIO_FIFO_VLD))
        if (board_now_us() >= deadline) return -1;
    *v = REG(SIO_FIFO_RD);
    return 0;
}

int board_core1_launch(void (*entry)(void), uint32_t *stack_top)
{
    /* The boot ROM on core 1 waits for 0, 0, 1, VTOR, SP, PC, echoing each
     * word; a wrong echo restarts the sequence. A 0 is sent only after
     * draining, since core 1 may have stale words queued. A core 1 that
     * does not answer (not in the boot ROM) fails the launch after
     * RP2040_LAUNCH_TIMEOUT_US. */
    const uint32_t seq[6] = { 0, 0, 1, (uint32_t)(uintptr_t)rp2040_vectors,
                              (uint32_t)(uintptr_t)stack_top, (uint32_t)(uintptr_t)entry };
    const uint64_t deadline = board_now_us() + RP2040_LAUNCH_TIMEOUT_US;
    unsigned i = 0;
    while (i < 6) {
        if (seq[i] == 0) {
            fifo_drain();
            __asm__ volatile("sev");
        }
        while (!(REG(SIO_FIFO_ST) & SIO_FIFO_RDY))
            if (board_now_us() >= deadline) return -1;
        REG(SIO_FIFO_WR) = seq[i];
        __asm__ volatile("sev");
        uint32_t echo;
        if (fifo_pop_until(&echo, deadline) != 0) return -1;
        i = (echo == seq[i]) ? i + 1 : 0;
    }
    return 0;
}
