/* SPDX-License-Identifier: MIT */
/* mipmap.h — the box filter that makes a texture's mipmaps (chapter 14).
 *
 * Level l + 1 of a w x h RGB888 image is (w > 1 ? w / 2 : 1) x
 * (h > 1 ? h / 2 : 1); each of its texels is the mean of the 2x2 texels it
 * covers, rounded half up, the last column or row repeated where the level
 * above has an odd or unit size. Levels go down to 1x1.
 *
 * The one builder of mipmaps: the scene parser makes a texture's chain with
 * it (tools/scene; scenec stores the chain in flash), and the rasterizer
 * with it in work memory for a trilinear texture that comes without one.
 * Integer arithmetic only, so every numeric mode gets the same texels.
 *
 * Also the texels the rasterizer's fast path samples (raster/raster_span.h):
 * made in work memory by render_init, or by scenec as const data in flash
 * (struct scene's `tex_fast`). */
#ifndef MIPMAP_H
#define MIPMAP_H

#include <stddef.h>
#include <stdint.h>

/* The size of the level below a side of n texels. */
static inline unsigned mip_side(unsigned n) { return n > 1 ? n / 2 : 1; }

/* Levels of a w x h image, level 0 (the image) included. */
unsigned mip_levels(unsigned w, unsigned h);

/* Writes the level below src (w x h, RGB888) into dst (mip_side(w) x
 * mip_side(h) x 3 bytes). */
void mip_next(const uint8_t *src, unsigned w, unsigned h, uint8_t *dst);

/* Whether the fast path samples a w x h texture (nearest or bilinear):
 * power-of-two sides, at most 2^15 texels. */
static inline int mip_fast_sides(unsigned w, unsigned h)
{
    return w && h && !(w & (w - 1)) && !(h & (h - 1)) && (size_t)w * h <= 32768u;
}

/* The fast path's nearest texels: RGB565 of each texel, every channel
 * rounded to its level as rgb_to_565 rounds (w x h x 2 bytes). */
void mip_fast_rgb565(const uint8_t *rgb, unsigned w, unsigned h, uint16_t *d);

/* The fast path's bilinear texels (SPAN_SRC_TEXBL): the w x h RGB888 image
 * with a border of one texel on each side (a copy of its edge: the clamped
 * addressing), row by row, (w + 2) texels a row, two words a texel:
 *   word 0  R in bits 0..15, B in bits 16..31: each floor(c * 248 / 255) + 4
 *           (its RGB565 level in eighths, plus half a level's 1/256: a
 *           texel's own level rounded as rgb_to_565 rounds)
 *   word 1  G: round(c * 63 * 2^18 / 255) + 2^17
 * Blended with weights of 4 bits across and 4 down (256 in all), each field
 * stays in its 16 (or 32) bits and ends with the level in its top bits,
 * rounded (R, B: bits 11..15 of their half; G: bits 26..31). */
static inline size_t mip_fast_bilinear_size(unsigned w, unsigned h) { return (size_t)(w + 2) * (h + 2) * 8; }
void mip_fast_bilinear(const uint8_t *rgb, unsigned w, unsigned h, uint32_t *d);

/* The fast path's bilinear texels of one word (SPAN_SRC_TEXBW,
 * `bilinear_weights = coarse`): the same bordered layout, a texel's RGB565
 * levels (rounded as mip_fast_rgb565 rounds) spread to R in bits 21..25,
 * G in bits 10..15, B in bits 0..4, so that a blend with weights of 3 bits
 * across and 2 down (32 in all) leaves each level with 5 bits of fraction
 * in its own field (B 0..9, G 10..20, R 21..30): 4 bytes a texel. */
static inline size_t mip_fast_bilinear_word_size(unsigned w, unsigned h) { return (size_t)(w + 2) * (h + 2) * 4; }
void mip_fast_bilinear_word(const uint8_t *rgb, unsigned w, unsigned h, uint32_t *d);

#endif
