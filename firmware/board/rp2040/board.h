/* SPDX-License-Identifier: MIT */
/* board.h — what the RP2040 start-up code offers the application.
 *
 * Clocks after board_init(): XOSC 12 MHz -> PLL_SYS -> clk_sys at
 * RP2040_SYS_MHZ (default 133, the RP2040's rated clock at the regulator's
 * reset voltage; make FW_CLK_MHZ=N, 125..300, below); PLL_USB at 125 MHz ->
 * clk_peri, so SPI0 and UART0 keep their clocks whatever clk_sys is (SPI0 at
 * clk_peri/2 = 62.5 MHz at most, the ST7789VW's rated write clock). The
 * 1 MHz timer counts from clk_ref = XOSC. UART0 on RP2040_UART_TX (default
 * GP0), 115200 8N1.
 *
 * Above 133 MHz the core voltage is raised first (VREG VSEL: 1.15 V up to
 * 200 MHz, 1.20 V up to 250 MHz, 1.30 V, the regulator's highest, up to
 * 300 MHz), and the XIP flash clock, clk_sys / RP2040_FLASH_DIV, is kept
 * within the flash's rating (RP2040_FLASH_MAX_MHZ, for boot2's read mode:
 * mk/firmware.mk): boot2 sets clk_sys / RP2040_BOOT2_DIV, and a larger
 * divider is written before clk_sys is raised. */
#ifndef BOARD_H
#define BOARD_H

#include <stdint.h>

#ifndef RP2040_SYS_MHZ
#define RP2040_SYS_MHZ 133
#endif
#if RP2040_SYS_MHZ < 125 || RP2040_SYS_MHZ > 300
#error "RP2040_SYS_MHZ (make FW_CLK_MHZ) must be 125..300"
#endif

/* PLL_SYS: VCO = 12 MHz * FBDIV = RP2040_SYS_MHZ * POSTDIV1 * POSTDIV2, in
 * 750..1600 MHz; the highest VCO that gives the clock exactly (P, the
 * product of the post dividers, from the largest down). */
#define RP2040_PLL_FITS(p) \
    ((RP2040_SYS_MHZ * (p)) % 12 == 0 && RP2040_SYS_MHZ * (p) >= 750 && RP2040_SYS_MHZ * (p) <= 1600)
#define RP2040_PLL_P                                                                                    \
    (RP2040_PLL_FITS(49) ? 49 : RP2040_PLL_FITS(42) ? 42 : RP2040_PLL_FITS(36) ? 36 :                   \
     RP2040_PLL_FITS(35) ? 35 : RP2040_PLL_FITS(30) ? 30 : RP2040_PLL_FITS(28) ? 28 :                   \
     RP2040_PLL_FITS(25) ? 25 : RP2040_PLL_FITS(24) ? 24 : RP2040_PLL_FITS(21) ? 21 :                   \
     RP2040_PLL_FITS(20) ? 20 : RP2040_PLL_FITS(18) ? 18 : RP2040_PLL_FITS(16) ? 16 :                   \
     RP2040_PLL_FITS(15) ? 15 : RP2040_PLL_FITS(14) ? 14 : RP2040_PLL_FITS(12) ? 12 :                   \
     RP2040_PLL_FITS(10) ? 10 : RP2040_PLL_FITS(9) ? 9 : RP2040_PLL_FITS(8) ? 8 :                       \
     RP2040_PLL_FITS(7) ? 7 : RP2040_PLL_FITS(6) ? 6 : RP2040_PLL_FITS(5) ? 5 :                        \
     RP2040_PLL_FITS(4) ? 4 : RP2040_PLL_FITS(3) ? 3 : RP2040_PLL_FITS(2) ? 2 : 0)
#if RP2040_PLL_P == 0
#error "RP2040_SYS_MHZ: no PLL_SYS setting gives this clock exactly (12 MHz * FBDIV / (POSTDIV1 * POSTDIV2))"
#endif
#define RP2040_PLL_FBDIV (RP2040_SYS_MHZ * RP2040_PLL_P / 12)
/* P as POSTDIV1 * POSTDIV2, POSTDIV1 >= POSTDIV2, each 1..7 */
#define RP2040_PLL_PD1                                                                                  \
    (RP2040_PLL_P % 7 == 0 ? 7 : RP2040_PLL_P % 6 == 0 ? 6 : RP2040_PLL_P % 5 == 0 ? 5 :                \
     RP2040_PLL_P % 4 == 0 ? 4 : RP2040_PLL_P % 3 == 0 ? 3 : 2)
#define RP2040_PLL_PD2 (RP2040_PLL_P / RP2040_PLL_PD1)

/* The core voltage for the clock (VREG VSEL; 11, 1.10 V, is its reset value) */
#if RP2040_SYS_MHZ <= 133
#define RP2040_VREG_VSEL 11
#elif RP2040_SYS_MHZ <= 200
#define RP2040_VREG_VSEL 12
#elif RP2040_SYS_MHZ <= 250
#define RP2040_VREG_VSEL 13
#else
#define RP2040_VREG_VSEL 15
#endif

/* The XIP flash clock: boot2's divider (RP2040_BOOT2_DIV, 2 for w25q16jv's
 * EBh reads, 4 for generic_03h's 03h reads), raised to the smallest even
 * one that keeps the flash at or below RP2040_FLASH_MAX_MHZ (133 for EBh,
 * 50 for 03h: W25Q16JV datasheet, AC electrical characteristics). */
#ifndef RP2040_BOOT2_DIV
#define RP2040_BOOT2_DIV 2
#endif
#ifndef RP2040_FLASH_MAX_MHZ
#define RP2040_FLASH_MAX_MHZ 133
#endif
#define RP2040_FLASH_DIV_NEED ((RP2040_SYS_MHZ + RP2040_FLASH_MAX_MHZ - 1) / RP2040_FLASH_MAX_MHZ)
#define RP2040_FLASH_DIV_EVEN (RP2040_FLASH_DIV_NEED + (RP2040_FLASH_DIV_NEED & 1))
#define RP2040_FLASH_DIV \
    (RP2040_FLASH_DIV_EVEN > RP2040_BOOT2_DIV ? RP2040_FLASH_DIV_EVEN : RP2040_BOOT2_DIV)
#define RP2040_PERI_HZ 125000000u
#ifndef RP2040_UART_TX
#define RP2040_UART_TX 0
#endif

/* The vector table (crt0.c); core 1 starts with the same table. */
typedef void (*vector_fn)(void);
extern const vector_fn rp2040_vectors[16 + 26];

/* Brings core 1, the spinlocks and the blocks used to a known state (core 0
 * may have been reset alone), then clocks, GPIO, timer, DMA, SPI0, UART0. */
void board_init(void);

/* Microseconds since boot (64-bit timer, never wraps in practice). */
uint64_t board_now_us(void);
void board_delay_us(uint32_t us);
void board_delay_cycles(uint32_t n);   /* at least n cycles of clk_sys */

/* UART0 output (core 0 only): the text joins a ring of RP2040_LOG_RING
 * characters that the UART's transmit interrupt moves into its 32-character
 * FIFO as it drains, so the caller does not wait for the line; only when the
 * ring is full does it wait, for room in the FIFO, passing the oldest
 * character there itself. The text is never dropped. */
void board_puts(const char *s);
/* The ring emptied, then the text written straight to the FIFO, waiting for
 * room (a fault report: from a handler, with the interrupt not taken). */
void board_puts_sync(const char *s);
/* UART0's interrupt handler (vector 36). */
void board_uart0_irq(void);

/* Core id (0 or 1) of the caller. */
uint32_t board_core_id(void);

/* Starts core 1 at entry(), with its stack top at stack_top (8-byte aligned),
 * through the boot ROM's SIO FIFO handshake; 0, or -1 when core 1 did not
 * complete it within RP2040_LAUNCH_TIMEOUT_US. */
#ifndef RP2040_LAUNCH_TIMEOUT_US
#define RP2040_LAUNCH_TIMEOUT_US 100000u
#endif
int board_core1_launch(void (*entry)(void), uint32_t *stack_top);

/* The inter-core lock: SIO spinlock 31, with memory barriers (an access
 * inside it is not moved out by the compiler or the bus). */
void board_lock(void);
void board_unlock(void);

/* Inter-core FIFO (8 words each direction); blocking push and pop. */
void board_fifo_push(uint32_t v);
uint32_t board_fifo_pop(void);

#endif
