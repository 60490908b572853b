/* SPDX-License-Identifier: MIT */
/* num_fix.h — what the fixed-point build's definitions share (num.c,
 * num_sqrt.c, num_rt.c): the saturation counter's hook and small helpers.
 * Internal to the numeric layer. */
#ifndef NUM_FIX_H
#define NUM_FIX_H

#include "num_int.h"

#ifdef NUM_COUNT_SAT
#define SAT_HIT() (num_saturations++)
#else
#define SAT_HIT() ((void)0)
#endif

/* Magnitude q with sign neg, saturated to [NUM_MIN, NUM_MAX]. */
static inline num sat_signed(uint64_t q, int neg)
{
    if (q > (uint64_t)INT32_MAX) { SAT_HIT(); return neg ? NUM_MIN : NUM_MAX; }
    return neg ? -(num)q : (num)q;
}

#if defined(__GNUC__) || defined(__clang__)
#define NUM_FIX_INLINE static inline __attribute__((always_inline))
#else
#define NUM_FIX_INLINE static inline
#endif

/* num_rsqrt_q30 inline (num_sqrt.c's seed table; the estimate is described
 * there). */
extern const uint16_t num_rsqrt_seed[384];
NUM_FIX_INLINE uint32_t rsqrt_q30(uint32_t xh)
{
    uint32_t y = num_rsqrt_seed[(xh >> 23) - 128];   /* Q15, in (2^15, 2^16) */
    uint32_t w = num_mulhi32(xh, y * y);             /* u y^2, Q30: 2^30 (1 +- 2^-8) */
    /* num_mulhi32(y << 16, t) = floor(y t / 2^16) for y < 2^16, from two
     * 16x16 products: y (t >> 16) + floor(y (t mod 2^16) / 2^16) */
    uint32_t t = 0xC0000000u - w;
    return y * (t >> 16) + ((y * (t & 0xFFFFu)) >> 16);
}

static inline uint32_t uabs32(int32_t a) { return a < 0 ? 0u - (uint32_t)a : (uint32_t)a; }

/* Pre-scale: components shifted so the largest magnitude lies in
 * [2^29, 2^30); the sum of squares is then exact and < 3 * 2^60.
 * Returns the left shift (-1 when the largest is >= 2^30: one bit dropped). */
static inline int num_prescale3(vec3 a, uint32_t u[3])
{
    u[0] = uabs32(a.x);
    u[1] = uabs32(a.y);
    u[2] = uabs32(a.z);
    uint32_t mx = u[0] > u[1] ? u[0] : u[1];
    if (u[2] > mx) mx = u[2];
    if (mx == 0) return 0;
    int sh = num_clz32(mx) - 2;
    if (sh < 0) sh = -1;
    for (int i = 0; i < 3; i++) u[i] = sh >= 0 ? u[i] << sh : u[i] >> 1;
    return sh;
}

static inline uint64_t num_sumsq3(const uint32_t u[3])
{
    return num_usq32(u[0]) + num_usq32(u[1]) + num_usq32(u[2]);
}

#endif
