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

/* Clocks, pins, bus; fills *h. 0 on success. */
int fw_board_init(struct hal *h);

/* Sends n RGB565 pixels (native-endian memory, big-endian on the wire) by
 * DMA inside a memory write the DCS layer began (CS low, D/C high). The
 * buffer must stay untouched until hal->spi_wait() returns or done runs. */
int fw_board_pixels_async(struct hal *h, const uint16_t *px, size_t n, hal_done_fn done, void *arg);

/* Text to the serial console (UART), blocking. */
void fw_board_puts(const char *s);

/* Cores available for rendering: 1 or 2. */
unsigned fw_board_cores(void);
/* Starts the second core at entry (only when fw_board_cores() == 2). */
void fw_board_core1_start(void (*entry)(void));
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

#endif
