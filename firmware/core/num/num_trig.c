/* SPDX-License-Identifier: MIT */
/* num_trig.c — num_powi, num_sin_deg and num_cos_deg of the fixed-point
 * build (see num.h). */
#define NUM_NO_INLINE   /* the out-of-line definitions live here */
#include "num.h"

#if NUM_MODE == NUM_MODE_FIXED

#include "num_fix.h"

/* powi in a small floating format: value = m * 2^x, m in [2^31, 2^32)
 * (m == 0 for zero). Each product rounds to 32 significant bits, so after
 * the <= 2*log2(e) products of binary exponentiation the relative error is
 * below about e * 2^-31 (squaring doubles a relative error). */
typedef struct { uint32_t m; int32_t x; } pw;

static pw pw_mul(pw a, pw b)
{
    pw r;
    if (a.m == 0 || b.m == 0) { r.m = 0; r.x = 0; return r; }
    uint64_t p = num_umul32(a.m, b.m);           /* in [2^62, 2^64) */
    int32_t x = a.x + b.x;
    if (p >> 63) { x += 32; } else { p <<= 1; x += 31; }
    uint32_t hi = (uint32_t)(p >> 32);
    if ((uint32_t)p >= 0x80000000u) {            /* round to nearest */
        if (hi == UINT32_MAX) { hi = 0x80000000u; x++; } else hi++;
    }
    /* Keep exponents bounded: beyond +-4096 the value saturates or is 0. */
    if (x > 4096) x = 4096;
    if (x < -4096) { r.m = 0; r.x = 0; return r; }
    r.m = hi;
    r.x = x;
    return r;
}

num num_powi(num base, uint32_t e)
{
    if (e == 0) return NUM_ONE;
    if (base == 0) return 0;
    int neg = base < 0 && (e & 1u);
    uint32_t ub = uabs32(base);
    int s = num_clz32(ub);
    pw b = { ub << s, -s - NUM_FRAC }, r = { 0x80000000u, -31 };
    while (e) {
        if (e & 1u) r = pw_mul(r, b);
        e >>= 1;
        if (e) b = pw_mul(b, b);
    }
    if (r.m == 0) return 0;
    int sh = -(r.x + NUM_FRAC);                  /* raw = m / 2^sh */
    if (sh <= 0) { SAT_HIT(); return neg ? NUM_MIN : NUM_MAX; }
    if (sh > 32) return 0;
    uint64_t q = ((uint64_t)r.m + ((uint64_t)1 << (sh - 1))) >> sh;
    return sat_signed(q, neg);
}

/* sin/cos in degrees. The angle is reduced exactly modulo 360 in raw units,
 * folded to [0, 45] degrees, converted to radians in Q2.30 and evaluated by
 * Taylor polynomials (truncation < 2e-9 on [0, pi/4]) in Q2.30. */
#define Q30(x) ((int32_t)((x) * 1073741824.0 + ((x) >= 0 ? 0.5 : -0.5)))
static const int32_t sin_c[5] = { Q30(-1.0 / 6), Q30(1.0 / 120), Q30(-1.0 / 5040),
                                  Q30(1.0 / 362880), Q30(-1.0 / 39916800) };
static const int32_t cos_c[6] = { Q30(-1.0 / 2), Q30(1.0 / 24), Q30(-1.0 / 720),
                                  Q30(1.0 / 40320), Q30(-1.0 / 3628800), Q30(1.0 / 479001600) };
/* pi/180 * 2^37, rounded: degrees (raw, F fraction bits) to radians Q2.30 is
 * d * DEG_RAD >> (7 + F); d < 45*2^F+1 <= 2^26, so the product < 2^58. */
static const uint32_t deg_rad = 2398762259u;

static int32_t mulq30(int32_t a, int32_t b)
{
    return (int32_t)((num_smul32(a, b) + ((int64_t)1 << 29)) >> 30);
}

#define DEG(n) ((uint32_t)(n) << NUM_FRAC)

/* sin of d raw degrees, d in [0, 360*2^F). */
static num sin_reduced(uint32_t d)
{
    int neg = 0;
    if (d >= DEG(180)) { d -= DEG(180); neg = 1; }
    if (d > DEG(90)) d = DEG(180) - d;
    int use_cos = d > DEG(45);
    if (use_cos) d = DEG(90) - d;
    int32_t x = (int32_t)(num_umul32(d, deg_rad) >> (7 + NUM_FRAC));
    int32_t x2 = mulq30(x, x), s;
    if (use_cos) {
        s = cos_c[5];
        for (int i = 4; i >= 0; i--) s = cos_c[i] + mulq30(x2, s);
        s = (1 << 30) + mulq30(x2, s);
    } else {
        s = sin_c[4];
        for (int i = 3; i >= 0; i--) s = sin_c[i] + mulq30(x2, s);
        s = x + mulq30(x, mulq30(x2, s));
    }
    num r = (s + (1 << (29 - NUM_FRAC))) >> (30 - NUM_FRAC);
    return neg ? -r : r;
}

/* deg modulo 360 as raw units in [0, 360*2^F). */
static uint32_t deg_mod360(num deg)
{
    uint32_t rm;
    num_udiv64_32(uabs32(deg), DEG(360), &rm);
    if (deg < 0 && rm) rm = DEG(360) - rm;
    return rm;
}

num num_sin_deg(num deg) { return sin_reduced(deg_mod360(deg)); }

num num_cos_deg(num deg)
{
    uint32_t d = deg_mod360(deg) + DEG(90);
    if (d >= DEG(360)) d -= DEG(360);
    return sin_reduced(d);
}

#else
typedef int num_trig_fixed_only;   /* (a translation unit may not be empty) */
#endif
