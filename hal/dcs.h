/* SPDX-License-Identifier: MIT */
/* dcs.h — the generic MIPI DCS/DBI command layer (type C, 4-wire SPI).
 *
 * Everything a panel driver sends goes through here: a command byte with D/C
 * low, its parameters with D/C high, CS held low for the whole transaction.
 * Controller drivers (panel_*.c) are tables on top of this layer.
 *
 * Conventions:
 * - Window coordinates are inclusive, in the controller's current MADCTL
 *   orientation, before the module offsets; dcs adds x_off/y_off.
 * - Pixels are RGB565 as native uint16_t in memory and go on the wire
 *   big-endian (high byte first), as COLMOD 16-bit expects.
 * - Functions return 0 or the negative value the HAL returned.
 * - Not reentrant: one struct dcs per bus, used from one thread/core.
 */
#ifndef HAL_DCS_H
#define HAL_DCS_H

#include <stddef.h>
#include <stdint.h>
#include "hal.h"

/* MIPI DCS command codes (write commands a driver sends). */
#define DCS_NOP        0x00
#define DCS_SWRESET    0x01
#define DCS_SLPIN      0x10
#define DCS_SLPOUT     0x11
#define DCS_PTLON      0x12
#define DCS_NORON      0x13
#define DCS_INVOFF     0x20
#define DCS_INVON      0x21
#define DCS_GAMSET     0x26
#define DCS_DISPOFF    0x28
#define DCS_DISPON     0x29
#define DCS_CASET      0x2A
#define DCS_RASET      0x2B
#define DCS_RAMWR      0x2C
#define DCS_TEOFF      0x34
#define DCS_TEON       0x35
#define DCS_MADCTL     0x36
#define DCS_IDMOFF     0x38
#define DCS_IDMON      0x39
#define DCS_COLMOD     0x3A
#define DCS_RAMWRC     0x3C

/* MADCTL bits. */
#define DCS_MADCTL_MY  0x80  /* row address order (mirror rows) */
#define DCS_MADCTL_MX  0x40  /* column address order (mirror columns) */
#define DCS_MADCTL_MV  0x20  /* row/column exchange */
#define DCS_MADCTL_ML  0x10  /* vertical refresh order (no effect on the image) */
#define DCS_MADCTL_BGR 0x08  /* colour filter order BGR */
#define DCS_MADCTL_MH  0x04  /* horizontal refresh order (no effect on the image) */

/* COLMOD value for 16 bits per pixel (65k colours) on the MCU interface. */
#define DCS_COLMOD_16BIT 0x55

/* Size of each of the two byte buffers pixels are converted through
 * (big-endian swap). Even; two buffers so that one converts while the other
 * is on the bus when the HAL has a real asynchronous write. */
#ifndef DCS_CHUNK_BYTES
#define DCS_CHUNK_BYTES 512
#endif

#if DCS_CHUNK_BYTES < 6 || DCS_CHUNK_BYTES % 2
#error "DCS_CHUNK_BYTES: even, at least 6"
#endif

struct dcs {
    const struct hal *hal;       /* not owned; must outlive the dcs */
    uint8_t rgb666;              /* 1: pixels go as three bytes, R G B in bits 7..2
                                    (COLMOD 18-bit: the ILI9488 on SPI); 0: RGB565 */
    uint16_t x_off, y_off;       /* added to CASET / RASET addresses */
    uint32_t bytes_sent;         /* SPI bytes sent so far (statistics; wraps) */
    uint8_t next_buf;            /* buffer to fill next (the other may be on the bus) */
    uint8_t buf[2][DCS_CHUNK_BYTES];
};

/* Binds d to hal, offsets 0. Drives CS high (deselected) and D/C high. */
int dcs_init(struct dcs *d, const struct hal *hal);

/* Sends command cmd followed by n parameter bytes (params may be NULL when
 * n == 0), CS low for the whole transaction. */
int dcs_command(struct dcs *d, uint8_t cmd, const uint8_t *params, size_t n);

/* Waits ms milliseconds through the HAL. */
void dcs_delay_ms(struct dcs *d, uint32_t ms);

/* Hardware reset: RESET low for low_ms (>= 1), then high, then wait_ms. */
int dcs_hw_reset(struct dcs *d, uint32_t low_ms, uint32_t wait_ms);

/* CASET x0..x1 and RASET y0..y1 (inclusive, x0 <= x1, y0 <= y1), each plus
 * the offsets. Returns -1 without sending if x0 > x1 or y0 > y1 or an address
 * plus offset exceeds 0xFFFF. */
int dcs_set_window(struct dcs *d, uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1);
/* The same with a controller's own commands and address width: col_cmd with
 * start and end column, row_cmd with start and end row, each address plus
 * its offset in addr_bytes bytes (1 or 2; 2 is big-endian). Returns -1
 * without sending if x0 > x1, y0 > y1, addr_bytes is not 1 or 2, or an
 * address plus offset does not fit addr_bytes. dcs_set_window is
 * dcs_set_window_cmds(d, DCS_CASET, DCS_RASET, 2, ...). */
int dcs_set_window_cmds(struct dcs *d, uint8_t col_cmd, uint8_t row_cmd, uint8_t addr_bytes,
                        uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1);

/* Starts a memory write: CS low, RAMWR (or RAMWRC when cont != 0), then D/C
 * high; the bus stays selected for dcs_write_pixels/dcs_write_data until
 * dcs_write_end. */
int dcs_write_begin(struct dcs *d, int cont);
/* The same with a controller's own memory write command cmd. */
int dcs_write_begin_cmd(struct dcs *d, uint8_t cmd);
/* Sends n raw data bytes inside a write begun with dcs_write_begin. */
int dcs_write_data(struct dcs *d, const uint8_t *data, size_t n);
/* Sends n RGB565 pixels big-endian, converted in chunks through d->buf;
 * with d->rgb666 each as three bytes (every 5- or 6-bit channel widened to 8
 * bits by repeating its top bits), DCS_CHUNK_BYTES / 3 pixels a chunk: no
 * buffer of a whole frame. */
int dcs_write_pixels(struct dcs *d, const uint16_t *px, size_t n);
/* Sends n RGB565 pixels inside a write begun with dcs_write_begin and
 * returns; done(arg) (may be NULL) runs once px may be reused. With the HAL's
 * pixels_async (and not d->rgb666) the pixels go as 16-bit frames by DMA and done runs on
 * completion (px untouched until then, or until dcs_wait/dcs_write_end);
 * otherwise they are converted as dcs_write_pixels does and done runs
 * before this returns. The bytes on the wire are the same either way. */
int dcs_write_pixels_async(struct dcs *d, const uint16_t *px, size_t n, hal_done_fn done, void *arg);
/* Waits until no asynchronous write is in flight (completions run). */
int dcs_wait(struct dcs *d);
/* Sends n copies of one RGB565 colour. */
int dcs_write_fill(struct dcs *d, uint16_t colour, size_t n);
/* Waits for the bus and deselects (CS high). */
int dcs_write_end(struct dcs *d);

/* Window + RAMWR + w*h pixels (row-major, stride w) + end: one rectangle.
 * Returns -1 if w or h is 0. */
int dcs_flush(struct dcs *d, uint16_t x, uint16_t y, uint16_t w, uint16_t h, const uint16_t *px);

#endif
