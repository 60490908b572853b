/* SPDX-License-Identifier: MIT */
/* fw_board.h — what the application needs from a board, beyond hal.h.
 *
 * Implemented once per board (firmware/board/<board>/fw_board_*.c). The
 * application (firmware/app/) never touches a register. */
#ifndef FW_BOARD_H
#define FW_BOARD_H

#include <stddef.h>
#include <stdint.h>
#include "hal.h"

/* Board name shown on UART ("rp2040", "stm32f411"). */
extern const char fw_board_name[];

/* Clocks, pins, bus; fills *h (the board's HAL backend, which sends the
 * pixels: every byte to the panel goes through panel.h). The bus runs at
 * the fastest clock the board has not above spi_max_hz, the panel's rated
 * write clock (struct panel_desc), unless a build option of the board says
 * otherwise. 0 on success. */
int fw_board_init(struct hal *h, uint32_t spi_max_hz);

/* Whether to show the scene table once more: 1 on the boards (forever); a
 * host build of the application stops after its passes. */
int fw_board_again(void);

/* Text to the serial console (UART), from core 0; whole, in order. It may
 * return before the text has left the board (the RP2040 queues it for the
 * UART's transmit interrupt), so a line's time is what it says, not when it
 * arrives. */
void fw_board_puts(const char *s);

/* Cores available for rendering: 1 or 2. */
unsigned fw_board_cores(void);
/* Starts the second core at entry (only when fw_board_cores() == 2); 0, or
 * -1 when it did not start (the application then renders on one core). */
int fw_board_core1_start(void (*entry)(void));
/* Inter-core mailbox, blocking, in order (each direction its own queue). */
void fw_board_send(uint32_t v);
uint32_t fw_board_recv(void);
/* Shared memory between the cores: lock/unlock a lock that orders every
 * access made while holding it (a hardware spinlock and memory barriers);
 * notify wakes a core in fw_board_wait (an event that is remembered if
 * the other core is not waiting yet); wait may also return spuriously.
 * No-ops on single-core boards. */
void fw_board_lock(void);
void fw_board_unlock(void);
void fw_board_notify(void);
void fw_board_wait(void);

/* Core clock in Hz (for cycle figures). */
uint32_t fw_board_cpu_hz(void);
/* The panel's SPI clock in Hz as fw_board_init set it. */
uint32_t fw_board_spi_hz(void);

/* The panel's tearing-effect output (TE), where the board wires it: waits
 * for its rising edge, the start of the panel's vertical blank, for at most
 * timeout_us. 1 when it rose, 0 after the timeout, -1 when no TE line is
 * wired (then it returns at once). */
int fw_board_te_wait(uint32_t timeout_us);

#endif
