/* SPDX-License-Identifier: MIT */
/* mipmap.c — see mipmap.h. */
#include "mipmap.h"

unsigned mip_levels(unsigned w, unsigned h)
{
    unsigned n = 1;
    while (w > 1 || h > 1) {
        w = mip_side(w);
        h = mip_side(h);
        n++;
    }
    return n;
}

void mip_next(const uint8_t *src, unsigned w, unsigned h, uint8_t *dst)
{
    unsigned nw = mip_side(w), nh = mip_side(h);
    for (unsigned y = 0; y < nh; y++) {
        unsigned y0 = 2 * y < h ? 2 * y : h - 1, y1 = 2 * y + 1 < h ? 2 * y + 1 : h - 1;
        for (unsigned x = 0; x < nw; x++) {
            unsigned x0 = 2 * x < w ? 2 * x : w - 1, x1 = 2 * x + 1 < w ? 2 * x + 1 : w - 1;
            for (unsigned c = 0; c < 3; c++) {
                unsigned s = src[(y0 * w + x0) * 3 + c] + src[(y0 * w + x1) * 3 + c] + src[(y1 * w + x0) * 3 + c] +
                             src[(y1 * w + x1) * 3 + c];
                dst[(y * nw + x) * 3 + c] = (uint8_t)((s + 2) / 4);
            }
        }
    }
}
