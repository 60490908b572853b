/* SPDX-License-Identifier: MIT */
/* panel_st7789.c — Sitronix ST7789 modules (240x320 memory).
 *
 * The controller's memory is 240 columns x 320 rows. A 240x240 glass shows
 * rows 0..239; when MADCTL mirrors rows (MY, rotations 2 and 3 here) the
 * visible rows are addressed as 80..319, hence the offsets. The common
 * ST7789 modules use IPS glass, which shows true colours with INVON, and an
 * RGB colour filter.
 */
#include "panel.h"

/* After SWRESET: 5 ms before any command, 120 ms before SLPOUT.
 * After SLPOUT: 5 ms before any command, 120 ms before SLPIN; 120 ms also
 * lets the supply settle before the display turns on. */
static const struct panel_cmd st7789_init[] = {
    { DCS_SWRESET, 0, 120, { 0 } },
    { DCS_SLPOUT, 0, 120, { 0 } },
    { DCS_COLMOD, 1, 0, { DCS_COLMOD_16BIT } },
    { 0xB2, 5, 0, { 0x0C, 0x0C, 0x00, 0x33, 0x33 } },   /* PORCTRL: porches */
    { 0xB7, 1, 0, { 0x35 } },                           /* GCTRL: VGH/VGL */
    { 0xBB, 1, 0, { 0x20 } },                           /* VCOMS */
    { 0xC0, 1, 0, { 0x2C } },                           /* LCMCTRL */
    { 0xC6, 1, 0, { 0x0F } },                           /* FRCTRL2: 60 Hz */
    { DCS_NORON, 0, 0, { 0 } },
};

#define ST7789_MADCTL { 0x00, DCS_MADCTL_MX | DCS_MADCTL_MV, \
                        DCS_MADCTL_MX | DCS_MADCTL_MY, DCS_MADCTL_MY | DCS_MADCTL_MV }

const struct panel_desc panel_st7789_240x240 = {
    .name = "st7789_240x240",
    .controller = "st7789",
    .width = 240, .height = 240,
    .reset_low_ms = 1, .reset_wait_ms = 120,
    .init = st7789_init,
    .init_len = sizeof st7789_init / sizeof st7789_init[0],
    .madctl = ST7789_MADCTL,
    .x_off = { 0, 0, 0, 80 },
    .y_off = { 0, 0, 80, 0 },
    .invert = 1,
    .spi_mode = 3,
    .spi_max_hz = PANEL_WRITE_CYCLE_NS(16),  /* ST7789VW: t_SCYCW 16 ns, 62.5 MHz */
};

const struct panel_desc panel_st7789_240x320 = {
    .name = "st7789_240x320",
    .controller = "st7789",
    .width = 240, .height = 320,
    .reset_low_ms = 1, .reset_wait_ms = 120,
    .init = st7789_init,
    .init_len = sizeof st7789_init / sizeof st7789_init[0],
    .madctl = ST7789_MADCTL,
    .x_off = { 0, 0, 0, 0 },
    .y_off = { 0, 0, 0, 0 },
    .invert = 1,
    .spi_mode = 3,
    .spi_max_hz = PANEL_WRITE_CYCLE_NS(66),  /* ST7789V: t_SCYCW 66 ns, 15.2 MHz */
};
