/* SPDX-License-Identifier: MIT */
/* hal.h — what a display needs from a board.
 *
 * A backend (host emulation, Linux spidev + libgpiod, RP2040, ...) fills a
 * struct hal with its seven operations (docs/embedding.md). Nothing above this interface knows which
 * backend runs. All operations are called from one thread/core at a time.
 *
 * Lines are active-high logical levels as the panel sees them: DC 0 =
 * command, 1 = data; RESET 0 = held in reset; CS 0 = selected; BL 1 = on.
 */
#ifndef HAL_H
#define HAL_H

#include <stddef.h>
#include <stdint.h>

enum hal_line { HAL_LINE_DC = 0, HAL_LINE_RESET = 1, HAL_LINE_CS = 2, HAL_LINE_BL = 3 };

typedef void (*hal_done_fn)(void *arg);

struct hal {
    void *ctx;  /* backend state */
    /* Blocking SPI write of n bytes (MOSI only). Returns 0, or < 0 on error. */
    int (*spi_write)(void *ctx, const uint8_t *data, size_t n);
    /* Starts an SPI write and returns; `done(arg)` runs on completion (DMA).
     * `data` must stay valid until then. Backends without DMA complete at once. */
    int (*spi_write_async)(void *ctx, const uint8_t *data, size_t n, hal_done_fn done, void *arg);
    /* Waits until no asynchronous write is in flight. */
    int (*spi_wait)(void *ctx);
    /* Drives a control line. */
    void (*line_set)(void *ctx, enum hal_line line, int level);
    /* Waits at least ms milliseconds. */
    void (*delay_ms)(void *ctx, uint32_t ms);
    /* Monotonic microsecond clock. */
    uint64_t (*now_us)(void *ctx);
    /* Optional (NULL: the DCS layer byte-swaps the pixels through its own
     * buffers and sends them with spi_write_async or spi_write). Starts
     * sending n RGB565 pixels from native-endian memory as 16-bit SPI frames,
     * high byte first on the wire, inside a memory write (CS low, D/C high),
     * and returns; `done(arg)` runs on completion (DMA). `px` must stay
     * untouched until then or until spi_wait returns. */
    int (*pixels_async)(void *ctx, const uint16_t *px, size_t n, hal_done_fn done, void *arg);
};

#endif
