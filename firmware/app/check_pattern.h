/* SPDX-License-Identifier: MIT */
/* check_pattern.h — the bring-up pattern (the cgfs-check image, host_sim
 * --pattern check): what a person wiring a new panel module looks at to see
 * whether the wiring, the offsets, the colour order, the inversion and the
 * rotation are right.
 *
 * On a dark grey ground, for any size and rotation (w x h as the panel
 * shows it now):
 *   - a 1-pixel white border on the outermost rows and columns (a wrong
 *     column or row offset loses an edge or shows noise beside it);
 *   - a red square in the top-left corner, a green one top-right, a blue one
 *     bottom-left, nothing bottom-right, and "TOP" at the top centre (a
 *     wrong rotation or mirror puts them elsewhere);
 *   - eight colour bars: white, yellow, cyan, green, magenta, red, blue,
 *     black (a wrong colour order swaps red and blue; a wrong inversion
 *     shows them reversed, black first);
 *   - four gradients, left dark to right bright: grey, red, green, blue
 *     (bytes of a pixel swapped break them into bands and colours);
 *   - the settings: panel, size and rotation, offsets, colour order and
 *     inversion, SPI clock and clk_sys.
 * Pure integer, no heap: rows are drawn into a caller's strip buffer, so
 * any strip height streams it (panel_flush_rows). */
#ifndef CHECK_PATTERN_H
#define CHECK_PATTERN_H

#include <stddef.h>
#include <stdint.h>

/* RGB565 colours of the pattern */
#define CHECK_GROUND 0x2104u   /* dark grey (33, 32, 33) */
#define CHECK_WHITE 0xffffu
#define CHECK_RED 0xf800u
#define CHECK_GREEN 0x07e0u
#define CHECK_BLUE 0x001fu

#define CHECK_LINES 6          /* lines of settings on the glass */
#define CHECK_LINE_LEN 24

/* What the pattern prints: the driver's settings and the board's clocks. */
struct check_settings {
    const char *panel;         /* the descriptor's name ("st7789_240x240") */
    uint16_t width, height;    /* as the panel shows them in this rotation */
    uint8_t rotation;          /* 0..3 */
    uint16_t x_off, y_off;     /* the column and row offsets of this rotation */
    uint8_t bgr;               /* 1: BGR colour order, 0: RGB */
    uint8_t invert;            /* 1: inversion on */
    uint32_t spi_hz;           /* the SPI clock; 0: not known */
    uint32_t sys_hz;           /* the board's clk_sys; 0: not known */
    uint8_t round;             /* 1: a round glass (the GC9A01's): everything but the
                                  border inside the square the circle holds */
};

/* Where everything goes at one size, and the text (check_setup). */
struct check_layout {
    uint16_t w, h;
    uint16_t inset;            /* round glass: the margin of the square inside it, else 0 */
    uint16_t mark;             /* side of the corner squares */
    uint16_t bars_y, bars_h;   /* the colour bars' rows */
    uint16_t grad_y, grad_h;   /* the first gradient's rows; each is grad_h high */
    uint16_t text_x, text_y;   /* the settings' top-left */
    uint8_t scale;             /* of the font: 2 when the shorter side inside the inset is 200
                                  or more */
    char lines[CHECK_LINES][CHECK_LINE_LEN];
};

/* The layout for s's size (at least 16 x 16) and its text: the corner squares
 * mark = (the shorter side) / 8 pixels, 2 pixels inside the border; "TOP"
 * 2 rows below the border; the bars from row mark + 4, h / 10 high; after 2
 * rows the gradients, each max(h / 30, 2) high; after 2 more the settings,
 * at column 4, or beside the blue square where they would reach its rows
 * (a round glass: all of it inset, and h the inset square's). */
void check_setup(struct check_layout *l, const struct check_settings *s);

/* Rows [y0, y1) of the pattern into strip (row y at (y - y0) * l->w). */
void check_rows(const struct check_layout *l, uint16_t *strip, uint16_t y0, uint16_t y1);

/* The settings as one line for the serial console, with "\r\n":
 *   check panel=P size=WxH rotation=R offset=X,Y order=RGB|BGR invert=on|off
 *         spi_mhz=M clk_sys_mhz=M
 * (MHz with up to two decimals, "?" when not known), into buf (len bytes,
 * at least 160); returns its length. */
size_t check_uart_line(char *buf, size_t len, const struct check_settings *s);

#endif
