/* SPDX-License-Identifier: MIT */
/* panel_ili9488.c — Ilitek ILI9488 modules (320x480 memory and glass) on SPI.
 *
 * MIPI DCS, but on the serial interface the ILI9488 takes 18-bit pixels
 * only (COLMOD 66h: three bytes a pixel, R G B in bits 7..2): its command
 * set is DCS's with pixel_bytes 3, and the DCS layer widens each RGB565
 * pixel to three bytes as it sends it, through its two chunk buffers (no
 * frame buffer), half as many bytes again as 16-bit. The common modules
 * have a BGR colour filter, TN glass (INVOFF), and their glass's column 0
 * on the side of memory column 319, as the ILI9341 modules: portrait
 * upright needs MX.
 */
#include "panel.h"

const struct panel_ctl panel_ctl_ili9488 = {
    .name = "MIPI DCS, 18-bit pixels",
    PANEL_CTL_DCS_FIELDS,
    .pixel_bytes = 3,
};

/* The vendor's initialisation: gamma, power, VCOM, 18-bit pixels,
 * interface, frame rate, inversion, display function, adjust control 3. */
static const struct panel_cmd ili9488_init[] = {
    { DCS_SWRESET, 0, 120, { 0 } },
    { 0xE0, 15, 0, { 0x00, 0x03, 0x09, 0x08, 0x16, 0x0A, 0x3F, 0x78, 0x4C, 0x09, 0x0A, 0x08, 0x16, 0x1A, 0x0F } },
    { 0xE1, 15, 0, { 0x00, 0x16, 0x19, 0x03, 0x0F, 0x05, 0x32, 0x45, 0x46, 0x04, 0x0E, 0x0D, 0x35, 0x37, 0x0F } },
    { 0xC0, 2, 0, { 0x17, 0x15 } },         /* PWCTRL1: VREG1OUT, VREG2OUT */
    { 0xC1, 1, 0, { 0x41 } },               /* PWCTRL2: VGH, VGL */
    { 0xC5, 4, 0, { 0x00, 0x12, 0x80, 0x40 } }, /* VMCTRL: VCOM */
    { DCS_COLMOD, 1, 0, { 0x66 } },         /* 18 bits a pixel: the only mode on SPI */
    { 0xB0, 1, 0, { 0x00 } },               /* IFMODE */
    { 0xB1, 2, 0, { 0xA0, 0x11 } },         /* FRMCTR1: 60 Hz */
    { 0xB4, 1, 0, { 0x02 } },               /* INVTR: 2-dot inversion */
    { 0xB6, 3, 0, { 0x02, 0x02, 0x3B } },   /* DISCTRL */
    { 0xE9, 1, 0, { 0x00 } },               /* SETIMAGE: 24-bit bus off */
    { 0xF7, 4, 0, { 0xA9, 0x51, 0x2C, 0x82 } }, /* ADJCTRL3 */
    { DCS_SLPOUT, 0, 120, { 0 } },
    { DCS_NORON, 0, 0, { 0 } },
};

#define M_MX  DCS_MADCTL_MX
#define M_MY  DCS_MADCTL_MY
#define M_MV  DCS_MADCTL_MV
#define M_BGR DCS_MADCTL_BGR

const struct panel_desc panel_ili9488_320x480 = {
    .name = "ili9488_320x480",
    .controller = "ili9488",
    .ctl = &panel_ctl_ili9488,
    .width = 320, .height = 480,
    .reset_low_ms = 1, .reset_wait_ms = 120,
    .init = ili9488_init,
    .init_len = sizeof ili9488_init / sizeof ili9488_init[0],
    .madctl = { M_MX | M_BGR, M_MV | M_BGR, M_MY | M_BGR, M_MX | M_MY | M_MV | M_BGR },
    .x_off = { 0, 0, 0, 0 },
    .y_off = { 0, 0, 0, 0 },
    .invert = 0,
    .spi_mode = 0,
    .spi_max_hz = PANEL_WRITE_CYCLE_NS(50),  /* t_scycw 50 ns, 20 MHz */
};
