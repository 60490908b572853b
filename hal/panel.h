/* SPDX-License-Identifier: MIT */
/* panel.h — display controller drivers as data, on top of the DCS layer.
 *
 * A struct panel_desc describes one module (controller + glass): its size,
 * its initialisation table (commands, parameters, delays), MADCTL and the
 * column/row offsets for each rotation, colour order and inversion.
 * Adding a module means adding a descriptor, not code.
 *
 * What the generic driver sends for each operation (window, memory write,
 * orientation, inversion, display and sleep) is the controller's command
 * set, struct panel_ctl, named by the descriptor: MIPI DCS (panel_ctl_dcs)
 * unless the descriptor names another. A controller that does not speak
 * DCS but takes commands with D/C low and their parameters with D/C high
 * is described by its own panel_ctl, as data.
 *
 * Rotation r (0..3) turns the image r*90 degrees clockwise relative to the
 * descriptor's rotation 0; odd rotations swap width and height.
 * Pixels are RGB565, native uint16_t, row-major.
 *
 * Flushing a rectangle is the one way pixels leave a renderer: in one call
 * (panel_flush) or streamed, rows as they are rendered (panel_flush_begin,
 * panel_flush_rows ..., panel_flush_end). Both send the same bytes.
 */
#ifndef HAL_PANEL_H
#define HAL_PANEL_H

#include <stddef.h>
#include <stdint.h>
#include "hal.h"
#include "dcs.h"

#define PANEL_CMD_MAX_PARAMS 16

/* One step of an initialisation table: a command, its parameters, and the
 * delay to wait after it (ms). */
struct panel_cmd {
    uint8_t cmd;
    uint8_t n;                               /* parameter count, <= PANEL_CMD_MAX_PARAMS */
    uint16_t delay_ms;
    uint8_t params[PANEL_CMD_MAX_PARAMS];
};

/* An operation a controller does not have. */
#define PANEL_CMD_NONE 0x100

/* A controller's command set: the command (0..0xFF, or PANEL_CMD_NONE: the
 * operation is skipped) the generic driver sends for each operation. */
struct panel_ctl {
    const char *name;            /* "MIPI DCS", ... */
    uint16_t set_cols, set_rows; /* window: start and end column / row, */
    uint8_t addr_bytes;          /* each address in 1 byte or 2 (big-endian) */
    uint16_t write_mem;          /* memory write; pixels follow (RGB565, big-endian) */
    uint16_t orient;             /* one parameter: the descriptor's madctl[rotation] */
    uint16_t inv_on, inv_off;    /* no parameters, as the rest */
    uint16_t disp_on, disp_off;
    uint16_t sleep_in, sleep_out;
    uint16_t sleep_wait_ms;      /* wait after sleep_in and sleep_out */
    uint8_t xy_by_driver;        /* 1: the controller cannot exchange rows and
                                    columns (no DCS MV): in odd rotations the
                                    driver sends the window's columns with
                                    set_rows and its rows with set_cols, and
                                    the orientation parameter turns on the
                                    controller's vertical address increment */
    uint16_t te_on;              /* tearing-effect output on, in the vertical blank only
                                    (one parameter, 0); 0: the controller has none */
    uint8_t pixel_bytes;         /* bytes a pixel on the wire: 0 or 2, RGB565;
                                    3, RGB666 converted on the way out
                                    (struct dcs rgb666), never by the HAL's
                                    pixels_async */
    uint8_t order_bgr;           /* the orientation parameter's bit that sends
                                    RGB565's red to the glass's third colour
                                    (BGR order; DCS: MADCTL BGR, 08h) */
};

/* MIPI DCS: CASET/RASET (16-bit addresses), RAMWR, MADCTL, INVON/INVOFF,
 * DISPON/DISPOFF, SLPIN/SLPOUT and 120 ms after a sleep change, TEON. */
extern const struct panel_ctl panel_ctl_dcs;
/* Its fields, for a command set that is DCS but for one field (the
 * ILI9488's 18-bit pixels): { .name = ..., PANEL_CTL_DCS_FIELDS, .pixel_bytes = 3 }. */
#define PANEL_CTL_DCS_FIELDS                                                                    \
    .set_cols = DCS_CASET, .set_rows = DCS_RASET, .addr_bytes = 2, .write_mem = DCS_RAMWR,     \
    .orient = DCS_MADCTL, .inv_on = DCS_INVON, .inv_off = DCS_INVOFF, .disp_on = DCS_DISPON,   \
    .disp_off = DCS_DISPOFF, .sleep_in = DCS_SLPIN, .sleep_out = DCS_SLPOUT,                   \
    .sleep_wait_ms = 120, .te_on = DCS_TEON, .order_bgr = DCS_MADCTL_BGR
/* Solomon Systech SSD1351 (OLED): 15h/75h windows with 1-byte addresses,
 * write RAM 5Ch, remap A0h, A6h/A7h, sleep AEh/AFh (hal/panel_ssd1351.c). */
extern const struct panel_ctl panel_ctl_ssd1351;
/* MIPI DCS with 18-bit pixels, three bytes each (the ILI9488 on SPI, which
 * has no 16-bit mode there; hal/panel_ili9488.c). */
extern const struct panel_ctl panel_ctl_ili9488;

struct panel_desc {
    const char *name;            /* "st7789_240x240", ... (panel_find key) */
    const char *controller;      /* "st7789", "ili9341" */
    const struct panel_ctl *ctl; /* the controller's command set; NULL: panel_ctl_dcs */
    uint16_t width, height;      /* visible size in rotation 0 */
    uint16_t reset_low_ms;       /* hardware reset pulse */
    uint16_t reset_wait_ms;      /* wait after releasing RESET */
    const struct panel_cmd *init;/* sent after the hardware reset, in order */
    size_t init_len;
    uint8_t madctl[4];           /* orientation (DCS: MADCTL) per rotation, BGR bit included */
    uint16_t x_off[4], y_off[4]; /* column/row offset per rotation */
    uint8_t invert;              /* 1: inversion on (INVON, IPS glass), 0: off (INVOFF) */
    uint8_t spi_mode;            /* SPI mode a host drives the module in by default
                                    (ST7789: 3, which CS-less modules need and
                                    modules with CS accept; ILI9341: 0) */
    uint32_t spi_max_hz;         /* the controller's rated serial write clock:
                                    1 / the minimum serial write cycle of its
                                    datasheet (PANEL_WRITE_CYCLE_NS), for the
                                    chip revision the module carries; a host
                                    drives the bus at this clock or below
                                    unless told otherwise */
};

/* The rated clock of a serial write cycle of ns nanoseconds, in Hz (rounded
 * down: the cycle is a minimum). */
#define PANEL_WRITE_CYCLE_NS(ns) (1000000000u / (ns))

/* panel_st7789_240x240, ...: every descriptor of panels.def */
#define PANEL(name, controller, glass, view) extern const struct panel_desc panel_##name;
#define GLASS(...)
#include "panels.def"
#undef PANEL
#undef GLASS

struct panel {
    const struct panel_desc *desc;
    struct dcs dcs;
    uint8_t rotation;
    uint16_t width, height;      /* in the current rotation */
    uint16_t flush_w;            /* streaming flush: the window's width, */
    uint16_t flush_rows;         /* and its rows not sent yet (0: no flush open) */
};

/* Looks a descriptor up by name: a full name ("st7789_240x240") or a
 * controller name, meaning the controller's first descriptor in panels.def
 * ("st7789" = st7789_240x240, "ili9341" = ili9341_320x240).
 * Returns NULL if unknown. */
const struct panel_desc *panel_find(const char *name);
/* The descriptors panel_find knows, in panels.def's order, NULL-terminated. */
extern const struct panel_desc *const panel_all[];

/* The command set p's descriptor names (panel_ctl_dcs if it names none). */
const struct panel_ctl *panel_ctl(const struct panel *p);

/* Resets and initialises the panel (hardware reset, init table, orientation
 * for rotation, inversion, memory cleared to black, display on, backlight on).
 * rotation 0..3; returns -1 for a bad rotation, else 0 or the HAL's error. */
int panel_init(struct panel *p, const struct panel_desc *d, const struct hal *hal, uint8_t rotation);

/* Changes the rotation (orientation command and offsets); width/height follow. */
int panel_set_rotation(struct panel *p, uint8_t rotation);

/* Sends the w*h pixels px (row-major, stride w) to the rectangle at (x, y).
 * Returns -1 if the rectangle is empty or leaves the panel (nothing sent). */
int panel_flush(struct panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h, const uint16_t *px);

/* Streaming flush of the w x h rectangle at (x, y): begin opens the window
 * (columns, rows, memory write: CASET, RASET, RAMWR on DCS; -1 and nothing sent if it is empty or leaves the
 * panel, or a flush is open), each panel_flush_rows call sends the next rows
 * (rows * w pixels, stride w; -1 and nothing sent for more rows than are
 * left), end waits for the bus and closes the write (-1 if rows were left,
 * after closing it).
 *
 * panel_flush_rows returns once the pixels are on their way: with a HAL that
 * has pixels_async (DMA) px must stay untouched until done(arg) runs (done
 * may be NULL), which is at the latest in the next panel call that waits for
 * the bus (panel_wait, panel_flush_rows, panel_flush_end); without it, done
 * runs before panel_flush_rows returns. Every call returns 0 or the HAL's
 * error; after an error the flush should still be ended. */
int panel_flush_begin(struct panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h);
int panel_flush_rows(struct panel *p, const uint16_t *px, uint16_t rows, hal_done_fn done, void *arg);
int panel_flush_end(struct panel *p);
/* Ends a streaming flush early, like panel_flush_end but without the -1 for
 * rows left: the rows of the window not sent keep what the glass shows (a
 * memory write may stop anywhere; the next command ends it). */
int panel_flush_stop(struct panel *p);
/* Waits until the bus is idle (pending completions run). */
int panel_wait(struct panel *p);

/* Fills a rectangle with one colour (same rules as panel_flush). */
int panel_fill(struct panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h, uint16_t colour);

/* Display on/off and sleep in/out (DISPON/DISPOFF, SLPIN/SLPOUT on DCS),
 * sleep changes with the wait they need. */
int panel_display(struct panel *p, int on);
int panel_sleep(struct panel *p, int sleep);
/* Turns on the controller's tearing-effect output (a pulse at the start of
 * each vertical blank, for boards that wire TE: fw_board_te_wait); -1 when
 * its command set has none (panel_ctl.te_on). */
int panel_tear_effect(struct panel *p);

/* 1 when the orientation parameter of p's rotation selects BGR order
 * (panel_ctl.order_bgr), 0 for RGB. */
int panel_bgr(const struct panel *p);

uint16_t panel_width(const struct panel *p);
uint16_t panel_height(const struct panel *p);

#endif
