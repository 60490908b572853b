/* SPDX-License-Identifier: MIT */
/* board.h — what the RP2040 start-up code offers the application.
 *
 * Clocks after board_init(): XOSC 12 MHz -> PLL_SYS -> clk_sys at
 * RP2040_SYS_MHZ (default 133); PLL_USB at 125 MHz -> clk_peri, so SPI0 can
 * run at exactly clk_peri/2 = 62.5 MHz, the ST7789's fastest write clock,
 * whatever clk_sys is. The 1 MHz timer counts from clk_ref = XOSC.
 * UART0 on RP2040_UART_TX (default GP0), 115200 8N1. */
#ifndef BOARD_H
#define BOARD_H

#include <stdint.h>

#ifndef RP2040_SYS_MHZ
#define RP2040_SYS_MHZ 133
#endif
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
