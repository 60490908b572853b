/* SPDX-License-Identifier: MIT */
/* raster_span_lib.h — the helpers of the span loops (raster_span.h), for
 * the files that instantiate them (raster_spans.c, raster_spans_host.c). */
#ifndef RASTER_SPAN_LIB_H
#define RASTER_SPAN_LIB_H

#include "raster_fast.h"
#include "num/num_int.h"

/* RGB565 of levels r, g, b, each clamped to its top level. */
static inline uint16_t pack565_sat(uint32_t r, uint32_t g, uint32_t b)
{
    if (r > 31) r = 31;
    if (g > 63) g = 63;
    if (b > 31) b = 31;
    return (uint16_t)(r << 11 | g << 5 | b);
}

/* RGB565 to RGB888 by replicating each channel's top bits (host outputs). */
static inline void span_565_to_888(uint16_t c, uint8_t *o)
{
    uint32_t r = c >> 11, g = (c >> 5) & 63, b = c & 31;
    o[0] = (uint8_t)(r << 3 | r >> 2);
    o[1] = (uint8_t)(g << 2 | g >> 4);
    o[2] = (uint8_t)(b << 3 | b >> 2);
}

/* Bilinear texel at (u, v) of mip_fast_bilinear's texels tex (rows of
 * `row` words): u, v in texel units, Q16, of the bordered texture less half
 * a texel plus half a 16th (the texel centres at integers, the weights
 * rounded), both >= 0 (the clamp at the segment's ends). Weights of 4 bits
 * across and down; each step a + (b - a) * f on whole words (their fields
 * stay apart: every blend of them is a sum with non-negative weights).
 * *g gets the green word, the result is the R/B word (mip_fast_bilinear). */
static inline uint32_t span_bilinear(const uint32_t *tex, uint32_t u, uint32_t v, uint32_t row, uint32_t *g)
{
    const uint32_t *p = tex + (v >> 16) * row + ((u >> 16) << 1);
    const uint32_t fx = (u >> 12) & 15u, fy = (v >> 12) & 15u;
    uint32_t rb0 = (p[0] << 4) + (p[2] - p[0]) * fx, g0 = (p[1] << 4) + (p[3] - p[1]) * fx;
    p += row;
    uint32_t rb1 = (p[0] << 4) + (p[2] - p[0]) * fx, g1 = (p[1] << 4) + (p[3] - p[1]) * fx;
    *g = (g0 << 4) + (g1 - g0) * fy;
    return (rb0 << 4) + (rb1 - rb0) * fy;
}

/* u, v clamped to [0, umax], [0, vmax] (the texture's sides, Q16): the
 * bordered texels hold every texel a pixel between two such points reads */
static inline void span_clamp_uv(int32_t *uv, int32_t umax, int32_t vmax)
{
    uv[0] = uv[0] < 0 ? 0 : (uv[0] > umax ? umax : uv[0]);
    uv[1] = uv[1] < 0 ? 0 : (uv[1] > vmax ? vmax : uv[1]);
}

/* RGB565 of a blended texel: the levels in the fields' top bits */
static inline uint16_t span_bl_565(uint32_t rb, uint32_t g)
{
    return (uint16_t)(((rb << 16) >> 27) << 11 | (g >> 26) << 5 | rb >> 27);
}

/* 0x00RRGGBB of a blended texel (the fields back to 8-bit channels, rounded:
 * R, B (F - 896) * 255 / 63488 (their texels' half step of 1/8 level
 * added back), at most 255; G (F - 2^25) * 255 / (63 * 2^26)) */
static inline uint32_t span_bl_888(uint32_t rb, uint32_t g)
{
    uint32_t r = (((rb & 0xFFFFu) - 896u) * 33692u + (1u << 22)) >> 23;
    uint32_t b = (((rb >> 16) - 896u) * 33692u + (1u << 22)) >> 23;
    r = r > 255 ? 255 : r;
    b = b > 255 ? 255 : b;
    uint32_t gg = (((g - (1u << 25)) >> 12) * 4145u + (1u << 23)) >> 24;
    return r << 16 | gg << 8 | b;
}

/* One-word bilinear texel at (u, v) of mip_fast_bilinear_word's texels tex
 * (rows of `row` words): u, v as for span_bilinear but plus half an 8th of
 * a texel across and half a 4th down (SPAN_BW_U, SPAN_BW_V). Weights of 3
 * bits across and 2 down, each step a + (b - a) * f on the whole word,
 * then half a level added to each field: the levels in bits 26..30 (R),
 * 15..20 (G), 5..9 (B), rounded. */
#define SPAN_BW_U 0x9000u
#define SPAN_BW_V 0xA000u
#define SPAN_BW_HALF (16u << 21 | 16u << 10 | 16u)
static inline uint32_t span_bilinear_word(const uint32_t *tex, uint32_t u, uint32_t v, uint32_t row)
{
    const uint32_t *p = tex + (v >> 16) * row + (u >> 16);
    const uint32_t fx = (u >> 13) & 7u, fy = (v >> 14) & 3u;
    uint32_t t0 = (p[0] << 3) + (p[1] - p[0]) * fx;
    p += row;
    uint32_t t1 = (p[0] << 3) + (p[1] - p[0]) * fx;
    return (t0 << 2) + (t1 - t0) * fy + SPAN_BW_HALF;
}

/* RGB565 of a one-word blend */
static inline uint16_t span_bw_565(uint32_t t)
{
    return (uint16_t)((t >> 26) << 11 | ((t << 11) >> 26) << 5 | (t << 22) >> 27);
}

/* 0x00RRGGBB of a one-word blend: each field F (its level in 32nds, half
 * a level added) back to 8 bits, (F - 16) * 255 / (L * 32) rounded (by a
 * product: 255 / 992 as 16846 / 2^16, 255 / 2016 as 8290 / 2^16), at most
 * 255 */
static inline uint32_t span_bw_888(uint32_t t)
{
    uint32_t r = ((((t >> 21) & 1023u) - 16u) * 16846u + 32768u) >> 16,
             g = ((((t >> 10) & 2047u) - 16u) * 8290u + 32768u) >> 16,
             b = (((t & 1023u) - 16u) * 16846u + 32768u) >> 16;
    return r << 16 | g << 8 | b;
}

/* Each 8-bit channel of 0x00RRGGBB times intensity ii (Q12), rounded,
 * clamped to 255. */
static inline uint32_t light888(uint32_t t, uint32_t ii)
{
    uint32_t r = ((t >> 16) * ii + (1u << 11)) >> 12, g = (((t >> 8) & 255u) * ii + (1u << 11)) >> 12,
             b = ((t & 255u) * ii + (1u << 11)) >> 12;
    return (r > 255 ? 255u : r) << 16 | (g > 255 ? 255u : g) << 8 | (b > 255 ? 255u : b);
}

/* round(c * L / 255) of an 8-bit channel (rgb_to_565's rounding) */
static inline uint32_t level8(uint32_t c, uint32_t L)
{
    return ((c * L + 127u) * 0x8081u) >> 23;
}

/* RGB565 of 0x00RRGGBB, each channel rounded to its level */
static inline uint16_t pack888_565(uint32_t t)
{
    return (uint16_t)(level8(t >> 16, 31) << 11 | level8((t >> 8) & 255u, 63) << 5 | level8(t & 255u, 31));
}

/* 2^30 / (s * 64) at the middle of each of the 256 intervals of s in
 * [256, 512): round(2^30 / ((256 + i + 0.5) * 64)). */
static const uint16_t rcp_tab[256] = {
    65408, 65154, 64902, 64652, 64404, 64158, 63913, 63671, 63430, 63191, 62954, 62719,
    62485, 62253, 62023, 61795, 61568, 61343, 61119, 60897, 60677, 60458, 60241, 60026,
    59812, 59599, 59388, 59179, 58971, 58764, 58559, 58356, 58153, 57952, 57753, 57555,
    57358, 57163, 56968, 56776, 56584, 56394, 56205, 56017, 55831, 55646, 55462, 55279,
    55098, 54917, 54738, 54560, 54383, 54207, 54033, 53859, 53687, 53516, 53346, 53177,
    53009, 52842, 52676, 52511, 52347, 52184, 52022, 51862, 51702, 51543, 51385, 51228,
    51072, 50917, 50763, 50610, 50458, 50306, 50156, 50007, 49858, 49710, 49563, 49417,
    49272, 49128, 48985, 48842, 48700, 48559, 48419, 48280, 48141, 48003, 47867, 47730,
    47595, 47460, 47326, 47193, 47061, 46929, 46798, 46668, 46539, 46410, 46282, 46155,
    46028, 45902, 45777, 45652, 45528, 45405, 45283, 45161, 45040, 44919, 44799, 44680,
    44561, 44443, 44326, 44209, 44093, 43977, 43862, 43748, 43634, 43521, 43408, 43296,
    43185, 43074, 42963, 42854, 42744, 42636, 42528, 42420, 42313, 42207, 42101, 41996,
    41891, 41786, 41683, 41579, 41476, 41374, 41272, 41171, 41070, 40970, 40870, 40771,
    40672, 40574, 40476, 40378, 40281, 40185, 40089, 39993, 39898, 39804, 39709, 39616,
    39522, 39429, 39337, 39245, 39153, 39062, 38971, 38881, 38791, 38702, 38613, 38524,
    38436, 38348, 38260, 38173, 38087, 38000, 37915, 37829, 37744, 37659, 37575, 37491,
    37407, 37324, 37241, 37159, 37077, 36995, 36914, 36833, 36752, 36672, 36592, 36512,
    36433, 36354, 36275, 36197, 36119, 36041, 35964, 35887, 35810, 35734, 35658, 35583,
    35507, 35432, 35358, 35283, 35209, 35136, 35062, 34989, 34916, 34844, 34771, 34700,
    34628, 34557, 34486, 34415, 34344, 34274, 34204, 34135, 34065, 33996, 33928, 33859,
    33791, 33723, 33655, 33588, 33521, 33454, 33387, 33321, 33255, 33189, 33124, 33059,
    32994, 32929, 32864, 32800
};

/* floor-ish 2^30 / s for s in [2^14, 2^15), within 2 of the quotient: the
 * table's 9-bit estimate and one Newton step, all in 32 bits. */
static uint32_t rcp30(uint32_t s)
{
    int32_t r0 = rcp_tab[(s >> 6) - 256];
    int32_t e = (int32_t)((1u << 30) - s * (uint32_t)r0);   /* |e| <= 2^22 */
    return (uint32_t)(r0 + asr32(r0 * asr32(e, 7), 23));
}

/* The first na attributes at a pixel with edge values w1, w2 (unroll a
 * constant: the attributes' loop unrolled). */
static inline void persp_at(const struct fpersp *p, int na, int32_t w1, int32_t w2, int32_t *out, int unroll)
{
    uint32_t b1 = (uint32_t)w1 >> p->t, b2 = (uint32_t)w2 >> p->t;
    uint32_t b0 = p->area_t - b1 - b2;       /* >= (w0 >> t) >= 0 */
    uint32_t P1 = b1 * p->dn[1], P2 = b2 * p->dn[2];
    uint32_t S = b0 * p->dn[0] + P1 + P2;    /* <= area_t * 2^16 < 2^31 */
    int32_t q1 = 0, q2 = 0;
    /* S into [2^14, 2^15), the weights with it (P <= S): the triangle's
     * shift brings its largest S below 2^15, the rest is at most a few
     * doublings */
    S >>= p->u;
    if (S) {
        P1 >>= p->u;
        P2 >>= p->u;
        while (S < (1u << 14)) { S <<= 1; P1 <<= 1; P2 <<= 1; }
        uint32_t R = rcp30(S);
        q1 = (int32_t)((P1 * R) >> 14);      /* Q16; P*R <= 2^31 */
        q2 = (int32_t)((P2 * R) >> 14);
    }
    /* (na a constant of the loop; unrolled where that measured faster) */
    if (unroll) {
#if defined(__GNUC__)
#pragma GCC unroll 8
#endif
        for (int j = 0; j < na; j++) out[j] = p->at[j].a0 + asr32(q1 * p->at[j].d1 + q2 * p->at[j].d2, p->at[j].rs);
    } else
        for (int j = 0; j < na; j++) out[j] = p->at[j].a0 + asr32(q1 * p->at[j].d1 + q2 * p->at[j].d2, p->at[j].rs);
}

/* floor(x r / 2^16) for 0 < r <= 2^16 (fast_inv_tab's), in 32-bit
 * products: x = xh 2^16 + xl with xl in [0, 2^16), so the quotient is xh r
 * (within [-2^31, 2^31 - 2^16]) plus floor(xl r / 2^16) (xl r < 2^32). */
static inline int32_t span_mul_inv(int32_t x, uint32_t r)
{
    const int32_t xh = asr32(x, 16);
    const uint32_t xl = (uint32_t)x & 0xFFFFu;
    return xh * (int32_t)r + (int32_t)((xl * r) >> 16);
}

/* round(2^16 / k) for the last segment of a span, k = 1..32 */
static const uint32_t fast_inv_tab[33] = {
    0, 65536, 32768, 21845, 16384, 13107, 10923, 9362, 8192, 7282, 6554, 5958, 5461, 5041, 4681, 4369, 4096,
    3855, 3641, 3449, 3277, 3121, 2979, 2849, 2731, 2621, 2521, 2427, 2341, 2260, 2185, 2114, 2048,
};

#endif
