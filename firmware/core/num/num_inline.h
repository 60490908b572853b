/* SPDX-License-Identifier: MIT */
/* num_inline.h — inline forms of the fixed-point build's hottest operations
 * (included by num.h; NUM_NO_INLINE, set by num.c and vec.c, which define
 * the out-of-line functions, turns it off).
 *
 * Each is the same computation as its out-of-line twin in num.c / vec.c,
 * bit for bit, including saturation and the saturation counter: only the
 * call is gone (on ARMv6-M a call and its argument shuffling cost as much
 * as an addition's body). The names are function-like macros, so taking a
 * function's address still gets the out-of-line one. */
#ifndef NUM_INLINE_H
#define NUM_INLINE_H

#include "num_int.h"

#ifdef NUM_COUNT_SAT
#define NUM_I_SAT() (num_saturations++)
#else
#define NUM_I_SAT() ((void)0)
#endif

static inline num num_i_sat64(int64_t v)
{
    if (v > INT32_MAX) { NUM_I_SAT(); return NUM_MAX; }
    if (v < -(int64_t)INT32_MAX) { NUM_I_SAT(); return NUM_MIN; }
    return (num)v;
}

static inline num num_i_add(num a, num b)
{
    int32_t r = (int32_t)((uint32_t)a + (uint32_t)b);
    if (((a ^ r) & (b ^ r)) < 0) { NUM_I_SAT(); return a < 0 ? NUM_MIN : NUM_MAX; }
    if (r == INT32_MIN) { NUM_I_SAT(); return NUM_MIN; }
    return r;
}

static inline num num_i_sub(num a, num b)
{
    int32_t r = (int32_t)((uint32_t)a - (uint32_t)b);
    if (((a ^ b) & (a ^ r)) < 0) { NUM_I_SAT(); return a < 0 ? NUM_MIN : NUM_MAX; }
    if (r == INT32_MIN) { NUM_I_SAT(); return NUM_MIN; }
    return r;
}

static inline num num_i_neg(num a)
{
    if (a == INT32_MIN) { NUM_I_SAT(); return NUM_MAX; }
    return -a;
}
static inline num num_i_abs(num a)
{
    if (a == INT32_MIN) { NUM_I_SAT(); return NUM_MAX; }
    return a < 0 ? -a : a;
}

static inline num num_i_mul(num a, num b) { return num_i_sat64(num_mul_round(a, b)); }

/* wnum_add / wnum_sub: operands and result clamped to +-INT64_MAX/4 */
#define NUM_I_WLIM (INT64_MAX / 4)
static inline int64_t num_i_wclamp(int64_t v)
{
    if (v > NUM_I_WLIM) { NUM_I_SAT(); return NUM_I_WLIM; }
    if (v < -NUM_I_WLIM) { NUM_I_SAT(); return -NUM_I_WLIM; }
    return v;
}
static inline wnum num_i_wadd(wnum a, wnum b) { return num_i_wclamp(num_i_wclamp(a) + num_i_wclamp(b)); }
static inline wnum num_i_wsub(wnum a, wnum b) { return num_i_wclamp(num_i_wclamp(a) - num_i_wclamp(b)); }

/* wnum_mul: the renderers' usual case (both below 2^32 in magnitude) is
 * one rounded 32x32 product, as in num.c; anything else goes there. */
wnum wnum_mul(wnum a, wnum b);
static inline wnum num_i_wmul(wnum a, wnum b)
{
    uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? (uint64_t)0 - (uint64_t)b : (uint64_t)b;
    if ((ua | ub) >> 32) return (wnum_mul)(a, b);
    uint64_t r = (num_umul32((uint32_t)ua, (uint32_t)ub) + ((uint64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC;
    return (a < 0) != (b < 0) ? -(int64_t)r : (int64_t)r;
}

static inline wnum num_i_dot_wide(vec3 a, vec3 b)
{
    return num_mul_round(a.x, b.x) + num_mul_round(a.y, b.y) + num_mul_round(a.z, b.z);
}

static inline vec3 num_i_v3_add(vec3 a, vec3 b)
{
    vec3 r = { num_i_add(a.x, b.x), num_i_add(a.y, b.y), num_i_add(a.z, b.z) };
    return r;
}
static inline vec3 num_i_v3_sub(vec3 a, vec3 b)
{
    vec3 r = { num_i_sub(a.x, b.x), num_i_sub(a.y, b.y), num_i_sub(a.z, b.z) };
    return r;
}
static inline vec3 num_i_v3(num x, num y, num z)
{
    vec3 r = { x, y, z };
    return r;
}
static inline rgb num_i_rgb_make(num r, num g, num b)
{
    rgb c = { r, g, b };
    return c;
}
static inline vec3 num_i_v3_neg(vec3 a)
{
    vec3 r = { num_i_neg(a.x), num_i_neg(a.y), num_i_neg(a.z) };
    return r;
}
static inline vec3 num_i_v3_scale(vec3 a, num s)
{
    vec3 r = { num_i_mul(a.x, s), num_i_mul(a.y, s), num_i_mul(a.z, s) };
    return r;
}
static inline rgb num_i_rgb_scale(rgb c, num k)
{
    rgb r = { num_i_mul(c.r, k), num_i_mul(c.g, k), num_i_mul(c.b, k) };
    return r;
}
static inline rgb num_i_rgb_add(rgb a, rgb b)
{
    rgb r = { num_i_add(a.r, b.r), num_i_add(a.g, b.g), num_i_add(a.b, b.b) };
    return r;
}


/* num_chan_levels for L = 31 or 63 (RGB565), as in num.c: x < 255 L + 128
 * < 2^16, so x / 255 is always the multiply-shift; c L + 255 2^(F-1) <
 * 2^(F+14) fits 32 bits for F <= 17. */
static inline uint32_t num_i_chan565(num c, uint32_t levels)
{
    if (c <= 0) return 0;
    if (c >= (num)(255 * NUM_ONE_RAW)) return levels;
#if NUM_FRAC <= 17
    uint32_t x = ((uint32_t)c * levels + 255u * (NUM_ONE_RAW / 2)) >> NUM_FRAC;
#else
    uint32_t x = (uint32_t)((num_umul32((uint32_t)c, levels) + (uint64_t)255 * (NUM_ONE_RAW / 2)) >> NUM_FRAC);
#endif
    return (x * 0x8081u) >> 23;
}
static inline uint16_t num_i_rgb_to_565(rgb c)
{
    return (uint16_t)(num_i_chan565(c.r, 31) << 11 | num_i_chan565(c.g, 63) << 5 | num_i_chan565(c.b, 31));
}

#define num_add(a, b)      num_i_add(a, b)
#define num_sub(a, b)      num_i_sub(a, b)
#define num_mul(a, b)      num_i_mul(a, b)
#define num_mul_fit(a, b)  num_mul_round32(a, b)
#define num_add_fit(a, b)  ((num)((uint32_t)(a) + (uint32_t)(b)))
#define num_neg(a)         num_i_neg(a)
#define num_abs(a)         num_i_abs(a)
#define wnum_add(a, b)     num_i_wadd(a, b)
#define wnum_sub(a, b)     num_i_wsub(a, b)
#define wnum_mul(a, b)     num_i_wmul(a, b)
#define wnum_from_num(a)   ((wnum)(a))
#define v3_dot_wide(a, b)  num_i_dot_wide(a, b)
#define v3_dot(a, b)       num_i_sat64(num_i_dot_wide(a, b))
#define v3_add(a, b)       num_i_v3_add(a, b)
#define v3_sub(a, b)       num_i_v3_sub(a, b)
#define v3_scale(a, s)     num_i_v3_scale(a, s)
#define v3_neg(a)          num_i_v3_neg(a)
#define v3_make(x, y, z)        num_i_v3(x, y, z)
#define rgb_make(r, g, b)  num_i_rgb_make(r, g, b)
#define rgb_scale(c, k)    num_i_rgb_scale(c, k)
#define rgb_add(a, b)      num_i_rgb_add(a, b)
#define rgb_to_565(c)      num_i_rgb_to_565(c)

#endif
