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
 * Integer arithmetic only, so every numeric mode gets the same texels. */
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

#endif
