/* SPDX-License-Identifier: MIT */
/* fw_board_rp2040.c — the application's board interface on the RP2040.
 *
 * RP2040_SINGLE_CORE=1 renders on core 0 only (the rp2040js emulator models
 * one core and no SIO FIFO). */
#include "fw_board.h"
#include "board.h"
#include "hal_rp2040.h"
#include "rp2040_regs.h"

#ifndef RP2040_SINGLE_CORE
#define RP2040_SINGLE_CORE 0
#endif
#ifndef RP2040_CORE1_STACK
#define RP2040_CORE1_STACK 8192  /* bytes */
#endif

const char fw_board_name[] = "rp2040";

static uint64_t core1_stack[RP2040_CORE1_STACK / 8];

int fw_board_init(struct hal *h, uint32_t spi_max_hz)
{
    return hal_rp2040_init(h, RP2040_PERI_HZ, spi_max_hz, board_now_us);
}

void fw_board_puts(const char *s) { board_puts(s); }

int fw_board_again(void) { return 1; }

unsigned fw_board_cores(void) { return RP2040_SINGLE_CORE ? 1u : 2u; }

int fw_board_core1_start(void (*entry)(void))
{
    return board_core1_launch(entry, (uint32_t *)(core1_stack + RP2040_CORE1_STACK / 8));
}

void fw_board_send(uint32_t v) { board_fifo_push(v); }
uint32_t fw_board_recv(void) { return board_fifo_pop(); }
void fw_board_lock(void) { board_lock(); }
void fw_board_unlock(void) { board_unlock(); }
void fw_board_notify(void) { __asm__ volatile("dmb\n sev" ::: "memory"); }
void fw_board_wait(void) { __asm__ volatile("wfe" ::: "memory"); }
uint32_t fw_board_cpu_hz(void) { return RP2040_SYS_MHZ * 1000000u; }
uint32_t fw_board_spi_hz(void) { return hal_rp2040_spi_hz(); }

/* RP2040_PIN_TE: the GPIO the panel's TE output is wired to (-1, the
 * default: none; the common 240x240 modules do not bring it out). */
#ifndef RP2040_PIN_TE
#define RP2040_PIN_TE -1
#endif

int fw_board_te_wait(uint32_t timeout_us)
{
#if RP2040_PIN_TE < 0
    (void)timeout_us;
    return -1;
#else
    static int ready;
    const uint32_t bit = 1u << RP2040_PIN_TE;
    if (!ready) {   /* an input through SIO, pulled down (a module without TE reads low) */
        REG(PADS_GPIO(RP2040_PIN_TE)) = PADS_IE | PADS_PDE;
        REG(GPIO_CTRL(RP2040_PIN_TE)) = GPIO_FUNC_SIO;
        ready = 1;
    }
    const uint64_t t0 = board_now_us();
    while (REG(SIO_GPIO_IN) & bit)      /* in the blank now: wait for the next one */
        if (board_now_us() - t0 >= timeout_us) return 0;
    while (!(REG(SIO_GPIO_IN) & bit))
        if (board_now_us() - t0 >= timeout_us) return 0;
    return 1;
#endif
}
