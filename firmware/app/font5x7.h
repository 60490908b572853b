/* SPDX-License-Identifier: MIT */
/* font5x7.h — a tiny built-in font for the frame-rate overlay and the
 * bring-up pattern (check_pattern.h): digits, 'A'..'Z', '.', ',', '_', '-',
 * '?', ' ', 'f', 'p', 's'; 5x7 pixels per glyph, 6 pixels advance. */
#ifndef FONT5X7_H
#define FONT5X7_H

#include <stdint.h>

/* Rows of glyph c top to bottom, bit 4 = leftmost column; NULL if the font
 * lacks c. */
const uint8_t *font5x7_glyph(char c);

/* Draws s at (x, y) scaled by `scale`, colour fg on a bg box with a 2-pixel
 * margin, into rows [y0, y1) of a strip buffer of `width` columns (row y at
 * (y - y0) * width). Parts outside the strip or the width are clipped. */
void font5x7_draw(uint16_t *strip, int width, int y0, int y1, int x, int y, int scale,
                  const char *s, uint16_t fg, uint16_t bg);

/* Height in pixels of the box font5x7_draw fills for this scale. */
#define FONT5X7_BOX_H(scale) (7 * (scale) + 4)

#endif
