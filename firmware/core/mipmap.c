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

void mip_fast_rgb565(const uint8_t *rgb, unsigned w, unsigned h, uint16_t *d)
{
    for (size_t k = 0; k < (size_t)w * h; k++) {
        const uint8_t *c = rgb + 3 * k;
        /* round(c * L / 255), as rgb_to_565 rounds an integral channel: x / 255
         * as (x * 0x8081) >> 23 (x < 2^16), no division */
        uint32_t r = ((uint32_t)c[0] * 31 + 127) * 0x8081u >> 23, g = ((uint32_t)c[1] * 63 + 127) * 0x8081u >> 23,
                 b = ((uint32_t)c[2] * 31 + 127) * 0x8081u >> 23;
        d[k] = (uint16_t)(r << 11 | g << 5 | b);
    }
}

/* The source texel under texel (x, y) of a w x h texture's bordered copy
 * (one texel of border, repeating the edge). */
static inline const uint8_t *bordered_texel(const uint8_t *rgb, unsigned w, unsigned h, unsigned x, unsigned y)
{
    unsigned sx = x == 0 ? 0 : (x > w ? w - 1u : x - 1u), sy = y == 0 ? 0 : (y > h ? h - 1u : y - 1u);
    return rgb + 3 * ((size_t)sy * w + sx);
}

void mip_fast_bilinear(const uint8_t *rgb, unsigned w, unsigned h, uint32_t *d)
{
    const unsigned W = w + 2u, H = h + 2u;
    for (unsigned y = 0; y < H; y++)
        for (unsigned x = 0; x < W; x++) {
            const uint8_t *c = bordered_texel(rgb, w, h, x, y);
            /* x / 255 as (x * 0x8081) >> 23 (x < 2^16), (x * 0x80808081) >> 39 (x < 2^32) */
            uint32_t r = ((uint32_t)c[0] * 248u * 0x8081u >> 23) + 4u, b = ((uint32_t)c[2] * 248u * 0x8081u >> 23) + 4u;
            uint32_t g = (uint32_t)(((uint64_t)(((uint32_t)c[1] * 63u << 18) + 127u) * 0x80808081u) >> 39) + (1u << 17);
            d[2 * ((size_t)y * W + x)] = b << 16 | r;
            d[2 * ((size_t)y * W + x) + 1] = g;
        }
}

void mip_fast_bilinear_word(const uint8_t *rgb, unsigned w, unsigned h, uint32_t *d)
{
    const unsigned W = w + 2u, H = h + 2u;
    for (unsigned y = 0; y < H; y++)
        for (unsigned x = 0; x < W; x++) {
            const uint8_t *c = bordered_texel(rgb, w, h, x, y);
            /* round(c * L / 255) as mip_fast_rgb565 */
            uint32_t r = ((uint32_t)c[0] * 31 + 127) * 0x8081u >> 23, g = ((uint32_t)c[1] * 63 + 127) * 0x8081u >> 23,
                     b = ((uint32_t)c[2] * 31 + 127) * 0x8081u >> 23;
            d[(size_t)y * W + x] = r << 21 | g << 10 | b;
        }
}
