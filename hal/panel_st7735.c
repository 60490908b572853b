/* SPDX-License-Identifier: MIT */
/* panel_st7735.c — Sitronix ST7735S modules (132x162 memory).
 *
 * The controller's memory is 132 columns x 162 rows; the glasses here sit
 * centred in it: the 1.8" 128x160 module at column 2, row 1 (TN glass,
 * INVOFF), the 0.96" 80x160 module at column 26, row 1 (IPS glass, INVON).
 * Both have a BGR colour filter. A centred glass has the same offsets
 * whether MADCTL mirrors or not; MV exchanges them.
 */
#include "panel.h"

/* After a hardware reset: 5 ms before any command, 120 ms before SLPOUT.
 * After SLPOUT: 120 ms before the next command. */
static const struct panel_cmd st7735_init[] = {
    { DCS_SWRESET, 0, 120, { 0 } },
    { DCS_SLPOUT, 0, 120, { 0 } },
    { DCS_COLMOD, 1, 0, { 0x05 } },                     /* 16 bits per pixel */
    { 0xB1, 3, 0, { 0x01, 0x2C, 0x2D } },               /* FRMCTR1: the reset frame rate */
    { 0xB4, 1, 0, { 0x07 } },                           /* INVCTR: column inversion */
    { DCS_NORON, 0, 0, { 0 } },
};

#define M_BGR DCS_MADCTL_BGR
#define ST7735_MADCTL { M_BGR, DCS_MADCTL_MX | DCS_MADCTL_MV | M_BGR, \
                        DCS_MADCTL_MX | DCS_MADCTL_MY | M_BGR, DCS_MADCTL_MY | DCS_MADCTL_MV | M_BGR }

const struct panel_desc panel_st7735_128x160 = {
    .name = "st7735_128x160",
    .controller = "st7735",
    .width = 128, .height = 160,
    .reset_low_ms = 1, .reset_wait_ms = 120,
    .init = st7735_init,
    .init_len = sizeof st7735_init / sizeof st7735_init[0],
    .madctl = ST7735_MADCTL,
    .x_off = { 2, 1, 2, 1 },
    .y_off = { 1, 2, 1, 2 },
    .invert = 0,
    .spi_mode = 0,
    .spi_max_hz = PANEL_WRITE_CYCLE_NS(66),  /* ST7735S: t_SCYCW 66 ns, 15.2 MHz */
};

const struct panel_desc panel_st7735_80x160 = {
    .name = "st7735_80x160",
    .controller = "st7735",
    .width = 80, .height = 160,
    .reset_low_ms = 1, .reset_wait_ms = 120,
    .init = st7735_init,
    .init_len = sizeof st7735_init / sizeof st7735_init[0],
    .madctl = ST7735_MADCTL,
    .x_off = { 26, 1, 26, 1 },
    .y_off = { 1, 26, 1, 26 },
    .invert = 1,
    .spi_mode = 0,
    .spi_max_hz = PANEL_WRITE_CYCLE_NS(66),  /* ST7735S: t_SCYCW 66 ns, 15.2 MHz */
};
