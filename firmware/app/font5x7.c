/* SPDX-License-Identifier: MIT */
/* font5x7.c — glyph bitmaps and the strip-clipped text drawer. */
#include <stddef.h>
#include "font5x7.h"

static const uint8_t digits[10][7] = {
    { 0x0e, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0e },  /* 0 */
    { 0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e },  /* 1 */
    { 0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f },  /* 2 */
    { 0x1f, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0e },  /* 3 */
    { 0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02 },  /* 4 */
    { 0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e },  /* 5 */
    { 0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e },  /* 6 */
    { 0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08 },  /* 7 */
    { 0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e },  /* 8 */
    { 0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c },  /* 9 */
};
static const uint8_t g_dot[7] = { 0, 0, 0, 0, 0, 0x0c, 0x0c };
static const uint8_t g_space[7] = { 0 };
static const uint8_t g_f[7] = { 0x06, 0x09, 0x08, 0x1c, 0x08, 0x08, 0x08 };
static const uint8_t g_p[7] = { 0, 0, 0x1e, 0x11, 0x1e, 0x10, 0x10 };
static const uint8_t g_s[7] = { 0, 0, 0x0e, 0x10, 0x0e, 0x01, 0x1e };

const uint8_t *font5x7_glyph(char c)
{
    if (c >= '0' && c <= '9') return digits[c - '0'];
    switch (c) {
    case '.': return g_dot;
    case ' ': return g_space;
    case 'f': return g_f;
    case 'p': return g_p;
    case 's': return g_s;
    default: return NULL;
    }
}

static void put(uint16_t *strip, int width, int y0, int y1, int x, int y, uint16_t c)
{
    if (x >= 0 && x < width && y >= y0 && y < y1) strip[(y - y0) * width + x] = c;
}

void font5x7_draw(uint16_t *strip, int width, int y0, int y1, int x, int y, int scale,
                  const char *s, uint16_t fg, uint16_t bg)
{
    int n = 0;
    while (s[n]) n++;
    int bw = n * 6 * scale + 3, bh = FONT5X7_BOX_H(scale);
    if (y + bh <= y0 || y >= y1) return;
    for (int yy = y; yy < y + bh; yy++)
        for (int xx = x; xx < x + bw; xx++) put(strip, width, y0, y1, xx, yy, bg);
    for (int i = 0; i < n; i++) {
        const uint8_t *g = font5x7_glyph(s[i]);
        if (!g) continue;
        for (int r = 0; r < 7; r++)
            for (int col = 0; col < 5; col++) {
                if (!(g[r] & (0x10 >> col))) continue;
                for (int dy = 0; dy < scale; dy++)
                    for (int dx = 0; dx < scale; dx++)
                        put(strip, width, y0, y1, x + 2 + (i * 6 + col) * scale + dx,
                            y + 2 + r * scale + dy, fg);
            }
    }
}
