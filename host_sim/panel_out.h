/* SPDX-License-Identifier: MIT */
/* panel_out.h — where host_sim's strips go: a panel driver over a HAL
 * backend (the emulated controller by default), or a plain memory
 * framebuffer (--panel none).
 *
 * Every pixel host_sim shows leaves the renderer through panel_out_flush(),
 * a rectangle of whole rows, as on the board. The image files are read back
 * afterwards: from the emulated panel's glass (what the controller's memory
 * shows through MADCTL, inversion and DISPON), or from the framebuffer.
 *
 * Return codes match host_sim's exit status: 0 ok, 1 internal error, 2 usage
 * error, 3 protocol violation found by the emulated controller; err then
 * holds one line without a newline.
 */
#ifndef HOST_SIM_PANEL_OUT_H
#define HOST_SIM_PANEL_OUT_H

#include <stddef.h>
#include <stdint.h>

struct panel_out;
struct panel;

struct panel_out_opts {
    const char *panel;    /* a controller of hal/panels.def ("st7789", "ili9341"), a module of it
                             ("st7789_240x320"), or "none" */
    const char *backend;  /* "sim" or "linux" */
    const char *fault;    /* NULL, or a fault to inject (see panel_out_faults) */
    const char *miswire;  /* NULL, or a driver setting to get wrong (see panel_out_miswires) */
    uint16_t width, height;
    uint8_t rotation;     /* quarter turns added to the orientation the size picks
                             (the module mounted turned); odd turns need a square size */
    /* --backend linux (0 / NULL / PANEL_OUT_PIN_DEFAULT: hal_linux's defaults) */
    const char *spi_dev, *gpio_chip;
    uint32_t spi_hz;      /* 0: the panel's rated write clock (struct panel_desc spi_max_hz) */
    int spi_mode;         /* 0..3, or -1: the panel's (3 for the ST7789, which works with
                             CS-less modules; 0 else) */
    int dc, rst, bl;      /* line offsets; -1 not connected; PANEL_OUT_PIN_DEFAULT */
};

#define PANEL_OUT_PIN_DEFAULT (-2)

/* Names accepted in panel_out_opts.fault, separated by '|', for messages. */
extern const char panel_out_faults[];

/* Names accepted in panel_out_opts.miswire, separated by '|': the driver
 * (never the emulated module, which stays true to the hardware) with one
 * setting wrong, as a mistake in a descriptor or a HAL would have it:
 *   offset    the column and row offsets of the rotation in use taken from
 *             the rotation a half turn away where those differ, else 0, 0
 *             (a panel without offsets has none to get wrong: exit 2)
 *   bgr       the colour-order bit of the orientation parameter flipped
 *             (panel_ctl.order_bgr)
 *   invert    the inversion setting flipped
 *   rotation  the driver in the rotation a half turn away from the module's
 *             (the module mounted the other way up, FW_ROTATION not changed)
 *   byteswap  each pixel's two bytes sent in the other order (a HAL that
 *             sends little-endian memory as it lies) */
extern const char panel_out_miswires[];

/* The panel's native size (the default --size): a module's own size, or
 * for a controller its first module's in hal/panels.def; -1 for an unknown
 * panel. "none" has no native size (returns -1 too). */
int panel_out_native(const char *panel, uint16_t *w, uint16_t *h);

/* The controllers --panel accepts, "st7789|ili9341", into buf; -1 if it
 * does not fit. */
int panel_out_controllers(char *buf, size_t len);

/* The modules --panel accepts (hal/panels.def's PANEL names, separated by
 * '|'), into buf; -1 if it does not fit. */
int panel_out_modules(char *buf, size_t len);

/* The default panel: the controller of hal/panels.def's first module. */
const char *panel_out_default(void);

/* Opens the path and brings the panel up (reset, init sequence, display on).
 * Returns 2 if the panel is unknown or no module of it holds the size. */
int panel_out_open(struct panel_out **out, const struct panel_out_opts *o, char *err, size_t errlen);

/* Sends rows [y0, y1) of the image: px holds (y1-y0)*width pixels, row-major. */
int panel_out_flush(struct panel_out *p, uint16_t y0, uint16_t y1, const uint16_t *px,
                    char *err, size_t errlen);

/* Sends the rectangle (x, y) w x h of the image; px points at its top-left
 * pixel in rows of `stride` pixels (a dirty-rectangle update). */
int panel_out_flush_rect(struct panel_out *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h,
                         const uint16_t *px, size_t stride, char *err, size_t errlen);

/* After the last flush: the end of the stream (a command left without its
 * parameters, half a pixel) is checked too. 0 or 3. */
int panel_out_finish(struct panel_out *p, char *err, size_t errlen);

/* The driver's panel (its descriptor, a copy with --miswire, rotation,
 * offsets), NULL for --panel none. */
const struct panel *panel_out_panel(const struct panel_out *p);

/* 1 when the emulated glass is round (it has no pixel in its corner: the
 * GC9A01's), 0 otherwise and for a real panel. */
int panel_out_round(const struct panel_out *p);

/* The SPI clock the bus runs at, Hz: the emulated bus's, or spidev's (0 for
 * --panel none). */
uint32_t panel_out_spi_hz(const struct panel_out *p);

/* Bytes that went over the SPI bus so far (0 for --panel none). */
uint64_t panel_out_spi_bytes(const struct panel_out *p);

/* Simulated time of the emulated bus so far, microseconds (0 without one). */
uint64_t panel_out_bus_us(const struct panel_out *p);

/* Copies what the glass shows, width x height pixels at the flushed origin,
 * into dst (width*height RGB565 pixels, row-major). Returns 2 if the backend
 * has no readable glass (real hardware). */
int panel_out_read(struct panel_out *p, uint16_t *dst, char *err, size_t errlen);

void panel_out_close(struct panel_out *p);

#endif
