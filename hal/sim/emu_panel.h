/* SPDX-License-Identifier: MIT */
/* emu_panel.h — an emulated SPI display controller (ST7789, ILI9341, ST7735S,
 * SSD1351, GC9A01, ILI9488).
 *
 * Decodes the byte stream and line changes a driver produces, as the
 * controllers' datasheets describe, keeps the controller's frame memory
 * (RGB565, in the controller's native orientation: 240 columns x 320 rows,
 * 132 x 162 on the ST7735S, 128 x 128 on the SSD1351, 240 x 240 on the GC9A01,
 * 320 x 480 on the ILI9488)
 * and shows what the module's glass displays.
 *
 * Strict: the first protocol violation is recorded as one line,
 *   "<NAME> (0x<HH>) at byte <N>: <what>"
 * where N is the 0-based offset in the SPI stream of the byte at which the
 * violation was found (line events name the line instead of a command, at
 * the offset of the next byte). After a violation all further input is
 * ignored. The rules are listed in docs/hal.md.
 *
 * Time: every call carries the simulated time in nanoseconds (monotonic);
 * the waits after reset and sleep changes are checked against it.
 *
 * Memory: no heap; struct emu_panel holds the frame memory (~300 KiB), the
 * caller provides it (static or malloc).
 */
#ifndef HAL_EMU_PANEL_H
#define HAL_EMU_PANEL_H

#include <stddef.h>
#include <stdint.h>

#define EMU_MEM_W 320   /* controller memory columns (native; the largest model's) */
#define EMU_MEM_H 480   /* controller memory rows (native; the largest model's) */
#define EMU_MSG_LEN 160

enum emu_model { EMU_ST7789 = 0, EMU_ILI9341 = 1, EMU_ST7735S = 2, EMU_SSD1351 = 3, EMU_GC9A01 = 4, EMU_ILI9488 = 5 };

/* A module: a controller behind a glass. Facts of the hardware, not of the
 * driver; the modules are the GLASS lines of hal/panels.def. */
struct emu_module {
    const char *name;            /* "st7789_240x240", "ili9341_240x320", "st7735s_80x160", ... */
    enum emu_model model;
    uint16_t glass_w, glass_h;   /* visible pixels, native orientation */
    uint16_t mem_x, mem_y;       /* memory column/row of the glass's top-left */
    uint8_t mirror_x;            /* glass column 0 shows memory column mem_x+glass_w-1 */
    uint8_t bgr;                 /* colour filter is BGR: needs MADCTL BGR for true colours */
    uint8_t inverted;            /* IPS glass: needs INVON for true colours */
    uint8_t normally_black;      /* colour shown when the display is off or asleep */
};

/* emu_module_st7789_240x240, ...: one per GLASS of hal/panels.def */
#define GLASS(name, ...) extern const struct emu_module emu_module_##name;
#define PANEL(...)
#include "panels.def"
#undef GLASS
#undef PANEL

struct emu_panel {
    const struct emu_module *mod;
    uint8_t view;                /* glass viewed turned by view*90 degrees, see emu_panel_init */
    /* bus state */
    uint8_t cs, dc, reset, bl;   /* line levels */
    uint8_t cs_tied_low;         /* module without CS pin: always selected */
    uint64_t offset;             /* SPI bytes seen */
    uint64_t reset_low_ns;
    /* command decoding */
    int cur;                     /* current command, -1 none */
    uint32_t nparam;             /* parameters received for cur */
    uint8_t param[16];
    uint8_t half;                /* bytes of a pixel pending (1, or 1..2 for 3-byte pixels) */
    uint8_t hi, mid;
    /* controller state */
    uint8_t asleep, display_on, inverted, idle, colmod, madctl;
    uint8_t remap;               /* SSD1351: re-map / colour depth (A0h) */
    uint8_t locked;              /* SSD1351: command lock on (FDh 16h) */
    uint8_t protect;             /* SSD1351: A2h B1h B3h BBh BEh C1h refused (FDh B0h, reset) */
    uint8_t mode;                /* SSD1351: display mode, A4h..A7h */
    uint8_t inter;               /* GC9A01: inter-register enable, 0, 1 (FEh), 2 (FEh EFh) */
    uint8_t window_set;          /* bit 0: CASET seen, bit 1: RASET seen */
    uint8_t cont_valid;          /* RAMWRC may continue */
    uint16_t xs, xe, ys, ye;     /* window (logical, inclusive) */
    uint16_t cx, cy;             /* address counter (logical) */
    uint64_t busy_until_ns;      /* no command before this time ... */
    uint64_t busy_since_ns;      /* ... counted from this event */
    const char *busy_why;        /* ... named so */
    uint64_t slpout_ok_ns, slpout_since_ns;  /* no SLPOUT before this time */
    const char *slpout_why;
    uint64_t slpin_ok_ns, slpin_since_ns;    /* no SLPIN before this time */
    const char *slpin_why;
    uint64_t pixels_written;
    char violation[EMU_MSG_LEN]; /* empty: none */
    uint16_t mem[EMU_MEM_H][EMU_MEM_W];
};

/* Looks a module up by panel name as panel_find accepts (a PANEL of
 * hal/panels.def, "st7789_240x240", or a controller, "st7789": its first
 * PANEL) or by module name (a GLASS, view 0); *view receives the glass view
 * rotation matching that panel descriptor's rotation 0 (may be NULL).
 * Returns NULL if unknown. */
const struct emu_module *emu_module_find(const char *name, uint8_t *view);

/* Power-on: memory filled with the documented pseudo-random pattern, lines
 * CS high, DC high, RESET high, state as after a hardware reset at time 0.
 * view 0..3: emu_panel_glass shows the glass turned view*90 degrees
 * counter-clockwise (so an image a driver writes in rotation view appears
 * upright). Returns -1 for a bad view. */
int emu_panel_init(struct emu_panel *p, const struct emu_module *mod, uint8_t view);

/* SPI bytes, the first at t_ns, each following one ns_per_byte later. */
void emu_panel_spi(struct emu_panel *p, const uint8_t *data, size_t n, uint64_t t_ns, uint32_t ns_per_byte);
/* Line change (line is a hal.h enum hal_line value: 0 DC, 1 RESET, 2 CS, 3 BL). */
void emu_panel_line(struct emu_panel *p, int line, int level, uint64_t t_ns);
/* End of the stream: a command left with too few parameters or half a pixel
 * is a violation. Returns 0, or -1 if a violation is recorded. */
int emu_panel_finish(struct emu_panel *p, uint64_t t_ns);

/* The violation line, or NULL if none. */
const char *emu_panel_violation(const struct emu_panel *p);

/* Size of the glass as viewed (after view rotation). */
uint16_t emu_panel_glass_width(const struct emu_panel *p);
uint16_t emu_panel_glass_height(const struct emu_panel *p);
/* What the glass shows, as RGB565 in true RGB order, row-major, top row
 * first, w*h values; w and h must equal the viewed glass size (-1 if not). */
int emu_panel_glass(const struct emu_panel *p, uint16_t *out, uint16_t w, uint16_t h);

/* 1 if the viewed glass has a pixel at (x, y), 0 if not (outside a round
 * glass, GC9A01: emu_panel_glass shows black there) or outside the glass. */
int emu_panel_shown(const struct emu_panel *p, uint16_t x, uint16_t y);

/* Controller memory cell (native column/row), for tests. */
uint16_t emu_panel_mem(const struct emu_panel *p, uint16_t col, uint16_t row);

#endif
