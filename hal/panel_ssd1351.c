/* SPDX-License-Identifier: MIT */
/* panel_ssd1351.c — Solomon Systech SSD1351 RGB OLED modules (128x128).
 *
 * The first controller here that does not speak MIPI DCS: its window
 * commands are 15h (columns) and 75h (rows) with one-byte addresses, its
 * memory write is 5Ch, its orientation and colour depth one register,
 * "re-map" A0h, and it has no row/column exchange: rotations 1 and 3 turn
 * on the vertical address increment (A0h bit 0) and the driver exchanges
 * the window's rows and columns (panel_ctl.xy_by_driver). Display on and
 * off are the controller's sleep mode off and on (AFh/AEh); A6h/A7h are
 * normal and inverse display. Commands A2h, B1h, B3h, BBh, BEh and C1h are
 * refused after a reset until the command lock (FDh) is given B1h.
 *
 * A0h bits: 0 vertical address increment, 1 column address 127 to SEG0,
 * 2 colour order C-B-A (RGB565's red in the first bits), 4 COM scan from
 * COM127, 5 odd/even COM split (the 128x128 glasses are wired for it),
 * 7:6 colour depth (01: 65k colours, two bytes a pixel).
 */
#include "panel.h"

const struct panel_ctl panel_ctl_ssd1351 = {
    .name = "SSD1351",
    .set_cols = 0x15,
    .set_rows = 0x75,
    .addr_bytes = 1,
    .write_mem = 0x5C,
    .orient = 0xA0,
    .inv_on = 0xA7,
    .inv_off = 0xA6,
    .disp_on = 0xAF,
    .disp_off = 0xAE,
    .sleep_in = 0xAE,
    .sleep_out = 0xAF,
    .sleep_wait_ms = 0,
    .xy_by_driver = 1,
    .order_bgr = 0x04,   /* A0h bit 2: colour order C-B-A */
};

/* The vendor's initialisation: unlock, display off, clocks, multiplex
 * ratio, start line and offset 0, GPIO off, internal VDD regulator,
 * phase lengths, VCOMH, contrast, segment low voltage. The re-map
 * register is set per rotation afterwards (orientation). */
static const struct panel_cmd ssd1351_init[] = {
    { 0xFD, 1, 0, { 0x12 } },               /* command lock: unlock the interface */
    { 0xFD, 1, 0, { 0xB1 } },               /* and commands A2h B1h B3h BBh BEh C1h */
    { 0xAE, 0, 0, { 0 } },                  /* sleep mode on (display off) */
    { 0xB3, 1, 0, { 0xF1 } },               /* clock: divide by 2, oscillator frequency 15 */
    { 0xCA, 1, 0, { 0x7F } },               /* multiplex ratio 128 */
    { 0xA1, 1, 0, { 0x00 } },               /* display start line 0 */
    { 0xA2, 1, 0, { 0x00 } },               /* display offset 0 */
    { 0xB5, 1, 0, { 0x00 } },               /* GPIO0/1 off */
    { 0xAB, 1, 0, { 0x01 } },               /* internal VDD regulator, 8-bit interface */
    { 0xB1, 1, 0, { 0x32 } },               /* phase 1 and 2 lengths */
    { 0xBE, 1, 0, { 0x05 } },               /* VCOMH 0.82 x VCC */
    { 0xC1, 3, 0, { 0xC8, 0x80, 0xC8 } },   /* contrast of A, B, C */
    { 0xC7, 1, 0, { 0x0F } },               /* master contrast: full */
    { 0xB4, 3, 0, { 0xA0, 0xB5, 0x55 } },   /* segment low voltage: external VSL */
    { 0xB6, 1, 0, { 0x01 } },               /* second precharge period */
};

/* 65k colours, COM split, colour order C-B-A in every rotation; then
 * rotation 0: COM scan from COM127 (the glass's top row shows row 0),
 * 1: and vertical increment, columns remapped, 2: columns remapped,
 * scan from COM0, 3: vertical increment, scan from COM0. */
const struct panel_desc panel_ssd1351_128x128 = {
    .name = "ssd1351_128x128",
    .controller = "ssd1351",
    .ctl = &panel_ctl_ssd1351,
    .width = 128, .height = 128,
    .reset_low_ms = 1, .reset_wait_ms = 1,
    .init = ssd1351_init,
    .init_len = sizeof ssd1351_init / sizeof ssd1351_init[0],
    .madctl = { 0x74, 0x77, 0x66, 0x65 },
    .x_off = { 0, 0, 0, 0 },
    .y_off = { 0, 0, 0, 0 },
    .invert = 0,
    .spi_mode = 0,
    .spi_max_hz = PANEL_WRITE_CYCLE_NS(50),  /* t_cycle 50 ns, 20 MHz */
};
