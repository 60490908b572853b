/* SPDX-License-Identifier: MIT */
/* num_rt.c — the fixed-point build's helpers that only the ray tracer
 * calls (see num.h): v3_div_len and the reciprocal divisor num_recip. A
 * file of their own so that an image running the rasterizer's numeric
 * layer from SRAM (RP2040_RAM_TEXT=raster, which takes num.o, num_sqrt.o
 * and vec.o) leaves them in flash. */
#include "num.h"

#if NUM_MODE == NUM_MODE_FIXED

#include "num_fix.h"

struct num_recip num_recip_make(num d)
{
    struct num_recip v;
    uint32_t ud = uabs32(d);
    v.d = d;
    v.m = 0;
    v.sh = 0;
    if (ud == 0) return v;
    int l = 32 - num_clz32(ud);
    /* 2^(30+L) / ud in (2^30, 2^31] (2^30 only for a power of two), rounded */
    v.m = num_udiv64_32(((uint64_t)1 << (30 + l)) + ud / 2, ud, 0);
    v.sh = (uint8_t)(30 + l - NUM_FRAC);
    return v;
}

num num_mul_recip(num a, const struct num_recip *v)
{
    if (v->m == 0) return num_div(a, v->d);
    /* a 2^F / |d| = a m / 2^(30 + L - F), m's relative error <= 2^-31;
     * |a| m < 2^62, the shift in [11, 53] */
    uint64_t p = num_umul32(uabs32(a), v->m);
    uint64_t q = ((p >> (v->sh - 1)) + 1) >> 1;
    return sat_signed(q, (a < 0) != (v->d < 0));
}

/* u0^2 + u1^2 + u2^2 of components <= 2^30, the same value as three
 * num_umul32 squares. On ARMv6-M (MULS 32x32->32 only) from the 16-bit
 * halves, u = h 2^16 + l (h <= 2^14, l < 2^16, and l = 0 when h = 2^14):
 * the h^2 sum <= 3 * 2^28 and the h l sum < 3 * 2^30 fit in 32 bits, and
 * sum u^2 = (sum h^2) 2^32 + (sum h l) 2^17 + sum l^2: nine products
 * instead of twelve. */
static inline uint64_t sumsq3_30(uint32_t u0, uint32_t u1, uint32_t u2)
{
#if NUM_V6M_ASM
    uint32_t h0 = u0 >> 16, h1 = u1 >> 16, h2 = u2 >> 16;
    uint32_t l0 = u0 & 0xffffu, l1 = u1 & 0xffffu, l2 = u2 & 0xffffu;
    uint32_t hh = h0 * h0 + h1 * h1 + h2 * h2;
    uint32_t hl = h0 * l0 + h1 * l1 + h2 * l2;
    uint64_t ll = (uint64_t)(l0 * l0) + (l1 * l1) + (l2 * l2);
    return ((uint64_t)hh << 32) + ((uint64_t)hl << 17) + ll;
#else
    return num_umul32(u0, u0) + num_umul32(u1, u1) + num_umul32(u2, u2);
#endif
}

num v3_div_len(num x, vec3 v)
{
    uint32_t u0 = uabs32(v.x), u1 = uabs32(v.y), u2 = uabs32(v.z);
    uint32_t mx = u0 > u1 ? u0 : u1;
    if (u2 > mx) mx = u2;
    if (mx == 0) return num_div(x, NUM_ZERO);
    if (x == 0) return 0;
    /* num_prescale3's shift, unrolled: the largest in [2^29, 2^30) */
    int sh = num_clz32(mx) - 2;
    if (sh >= 0) { u0 <<= sh; u1 <<= sh; u2 <<= sh; }
    else { sh = -1; u0 >>= 1; u1 >>= 1; u2 >>= 1; }
    uint64_t s = sumsq3_30(u0, u1, u2);   /* in [2^58, 3 * 2^60] */
    /* t = s 4^z in [2^62, 2^64); y = num_rsqrt_q30(t / 2^32) ~ 2^46 / sqrt(t / 2^32)
     * (2^-17.4), one more Newton step as num_rsqrt takes it (2^-27 with the
     * truncations). 1 / sqrt(s) = y 2^(z - 62), so x / |v| in raw units is
     * x 2^(F + sh) / sqrt(s) = x y 2^(F + sh + z - 62); the shift is >= 11. */
    uint32_t sh32 = (uint32_t)(s >> 32);             /* >= 2^26 */
    int z = sh32 >> 30 ? 0 : sh32 >> 28 ? 1 : 2;     /* num_clz64(s) >> 1 */
    uint32_t xh = z ? sh32 << (2 * z) | (uint32_t)s >> (32 - 2 * z) : sh32;
    uint32_t y = rsqrt_q30(xh);
    uint32_t w = num_mulhi32(xh, (uint32_t)(num_usq32(y) >> 32));   /* y y: a square */
    if (w <= (1u << 28)) y += num_mulhi32_small(y, ((1u << 28) - w) << 3);
    else y -= num_mulhi32_small(y, (w - (1u << 28)) << 3);
    int r = 62 - NUM_FRAC - sh - z;              /* in [11, 54] */
    uint64_t p = num_umul32(uabs32(x), y);
    uint64_t q = ((p >> (r - 1)) + 1) >> 1;
    return sat_signed(q, x < 0);
}

#endif
