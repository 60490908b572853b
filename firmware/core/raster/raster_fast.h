/* SPDX-License-Identifier: MIT */
/* raster_fast.h — what the fast path's set-up (raster_fast.c), its span
 * loops (raster_spans.c, raster_spans_host.c) and its lighting model
 * (raster_fphong.c) share; inside the rasterizer only.
 *
 * A span loop is chosen by four independent parameters, each a template
 * parameter of raster_span.h:
 *   shade  SPAN_SHADE_NONE   one colour (flat, unlit)
 *          SPAN_SHADE_RGB    Gouraud: the channels' levels interpolated
 *          SPAN_SHADE_LI     Gouraud: the intensity interpolated, times the
 *                            colour or texel per pixel, saturating
 *          SPAN_SHADE_PHONG  fast Phong: normal and position interpolated,
 *                            lit per pixel (raster_fphong.c)
 *   src    SPAN_SRC_CONST    the triangle's colour
 *          SPAN_SRC_TEX      RGB565 texels, nearest, power-of-two sides
 *          SPAN_SRC_TEXBL    bilinear: texels of two words (R and B in one,
 *                            G in the other, mip_fast_bilinear) blended with
 *                            4-bit weights, a border for the clamp at the
 *                            edges, power-of-two sides
 *          SPAN_SRC_TEXBW    bilinear, `bilinear_weights = coarse`: one word
 *                            a texel (RGB565 levels spread,
 *                            mip_fast_bilinear_word) blended with weights of
 *                            3 bits across and 2 down, the same border
 *   depth  0 (no test), 2 or 4 bytes an entry
 *   out    the board's outputs (RGB565) or also the host's (rgb888, written
 *          map, pixels written): ras_span_board or ras_span_host
 * The attributes a loop interpolates are laid out in that order: the
 * Phong normal and position (6), then u, v (2), then the intensity (1) or
 * the three levels (3). */
#ifndef RASTER_FAST_H
#define RASTER_FAST_H

#include "raster_int.h"

/* (macros: the span template tests them with #if) */
#define SPAN_SHADE_NONE 0
#define SPAN_SHADE_RGB 1
#define SPAN_SHADE_LI 2
#define SPAN_SHADE_PHONG 3
#define SPAN_SHADES 4
#define SPAN_SRC_CONST 0
#define SPAN_SRC_TEX 1
#define SPAN_SRC_TEXBL 2
#define SPAN_SRC_TEXBW 3
#define SPAN_SRCS 4
#define SPAN_DEPTHS 3            /* 0, 2, 4 bytes an entry: index 0, 1, 2 */

/* x / 2^n rounded toward minus infinity: >> on a negative int32_t, which
 * GCC and Clang define as the arithmetic shift on every target (the fixed-
 * point layer relies on the same); checked once below. */
static inline int32_t asr32(int32_t x, int n) { return x >> n; }
typedef char ras_asr_is_arithmetic[(-5 >> 1) == -3 ? 1 : -1];

/* Perspective-correct attributes at a pixel from its edge values. */
struct fpersp {               /* (the scalars first: small offsets for ARMv6-M loads) */
    int t;                   /* edge values >> t < 2^15 */
    int u;                   /* S >> u < 2^15 for every S of the triangle */
    int na;                  /* attributes (SPAN_NA of the loop) */
    uint32_t area_t;         /* area >> t */
    uint32_t dn[3];          /* near/z of the corners >> s, < 2^16 */
    struct {
        int32_t a0;          /* corner 0's value in the span format, |a0| < 2^30 */
        int32_t d1, d2;      /* (corner 1 - corner 0), (corner 2 - corner 0) >> sh: < 2^14 */
        int32_t rs;          /* 16 - sh, sh <= 16 */
    } at[RAS_FAST_NA];       /* (per attribute: the first ones at small offsets) */
};

/* A triangle's constants for its row spans. */
struct ftri {
    const struct ras_fast_tri *ft;
    int32_t seg, slog;       /* segment length 2^slog */
    int32_t a1, a2;          /* per-column steps of edge values w1, w2 */
    int32_t sa1, sa2;        /* the same per segment */
    struct fpersp pp;
};

/* One row's span. */
struct frow {
    uint16_t *px;
    uint8_t *zb;
    uint8_t *rgb888, *written;   /* host outputs at the first pixel, or NULL */
    uint32_t z, dz;
    int32_t n;                   /* pixels */
    int32_t w1, w2;              /* edge values at the first pixel */
};

/* Draws row span R of triangle T; returns the pixels written (host
 * loops) or 0 (board loops). */
typedef uint32_t (*span_fn)(const struct ftri *T, const struct frow *R);

/* [shade][src][depth]: NULL where no triangle takes the combination. */
extern const span_fn ras_span_board[SPAN_SHADES][SPAN_SRCS][SPAN_DEPTHS];
#if RENDER_HOST_OUTPUTS
extern const span_fn ras_span_host[SPAN_SHADES][SPAN_SRCS][SPAN_DEPTHS];
#endif

/* Fast Phong's intensity in Q12 at a pixel: np = normal (Q14 scale, any
 * length) and camera-space position (Q(pq)) (raster_fphong.c). */
uint32_t ras_fphong_light(const struct ras_fast_tri *ft, const int32_t *np);

#endif
