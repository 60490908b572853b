/* SPDX-License-Identifier: MIT */
/* panel_ili9341.c — Ilitek ILI9341 modules (240x320 memory and glass).
 *
 * The common modules have a BGR colour filter (MADCTL BGR set in every
 * rotation), TN glass (INVOFF), and their glass's column 0 on the side of
 * memory column 239, so portrait upright needs MX.
 */
#include "panel.h"

/* Same waits as the ST7789: 5 ms after SWRESET (120 ms before SLPOUT),
 * 5 ms after SLPOUT (120 ms before SLPIN). */
static const struct panel_cmd ili9341_init[] = {
    { DCS_SWRESET, 0, 120, { 0 } },
    { DCS_SLPOUT, 0, 120, { 0 } },
    { DCS_COLMOD, 1, 0, { DCS_COLMOD_16BIT } },
    { 0xC0, 1, 0, { 0x23 } },              /* PWCTRL1: GVDD 4.6 V */
    { 0xC1, 1, 0, { 0x10 } },              /* PWCTRL2: step-up factor */
    { 0xC5, 2, 0, { 0x3E, 0x28 } },        /* VMCTRL1: VCOMH, VCOML */
    { 0xC7, 1, 0, { 0x86 } },              /* VMCTRL2: VCOM offset */
    { 0xB1, 2, 0, { 0x00, 0x1B } },        /* FRMCTR1: 70 Hz */
    { DCS_GAMSET, 1, 0, { 0x01 } },        /* gamma curve 1 */
    { DCS_NORON, 0, 0, { 0 } },
};

#define M_MX  DCS_MADCTL_MX
#define M_MY  DCS_MADCTL_MY
#define M_MV  DCS_MADCTL_MV
#define M_BGR DCS_MADCTL_BGR

const struct panel_desc panel_ili9341_240x320 = {
    .name = "ili9341_240x320",
    .controller = "ili9341",
    .width = 240, .height = 320,
    .reset_low_ms = 1, .reset_wait_ms = 120,
    .init = ili9341_init,
    .init_len = sizeof ili9341_init / sizeof ili9341_init[0],
    .madctl = { M_MX | M_BGR, M_MV | M_BGR, M_MY | M_BGR, M_MX | M_MY | M_MV | M_BGR },
    .x_off = { 0, 0, 0, 0 },
    .y_off = { 0, 0, 0, 0 },
    .invert = 0,
    .spi_mode = 0,
    .spi_max_hz = PANEL_WRITE_CYCLE_NS(100),  /* t_scycw 100 ns, 10 MHz */
};

/* The same module held landscape: its rotation 0 is the portrait's 1. */
const struct panel_desc panel_ili9341_320x240 = {
    .name = "ili9341_320x240",
    .controller = "ili9341",
    .width = 320, .height = 240,
    .reset_low_ms = 1, .reset_wait_ms = 120,
    .init = ili9341_init,
    .init_len = sizeof ili9341_init / sizeof ili9341_init[0],
    .madctl = { M_MV | M_BGR, M_MY | M_BGR, M_MX | M_MY | M_MV | M_BGR, M_MX | M_BGR },
    .x_off = { 0, 0, 0, 0 },
    .y_off = { 0, 0, 0, 0 },
    .invert = 0,
    .spi_mode = 0,
    .spi_max_hz = PANEL_WRITE_CYCLE_NS(100),  /* t_scycw 100 ns, 10 MHz */
};
