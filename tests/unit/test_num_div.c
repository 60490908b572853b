/* SPDX-License-Identifier: MIT */
/* test_num_div.c — the fixed-point division kernels and the dot products
 * give exactly the bits of their definitions.
 *
 * Built for fixed point at NUM_FRAC 12 (portable ARMv6-M integer paths:
 * reciprocal digits, 16x16 products), 16 and 20 (the host's 32-bit divide
 * path, as on ARMv7-M). References are the slow, obvious forms: 64-bit and
 * 128-bit division, the product and sum of wide integers with a clamp after
 * every step (the former v3_dot_wide). Checked:
 *   num_rcp16       its two bounds on every value of dn >> 9 (exhaustive)
 *   num_rcp32       floor((2^64 - 1) / dn) - 2^32, both ends of every
 *                   num_rcp16 bucket and 4 million random dn (and
 *                   num_rcp32_est within 6 below it)
 *   ras_div_sub     a vertex's screen position, 1/z and depth against the
 *                   plain divisions, edge and random depths
 *   num_udiv64_32   quotient and remainder, every divisor magnitude (and
 *                   num_udiv64_32_pre, by a prepared divisor, alike)
 *   num_div, num_recip, num_from_ratio, num_div_int, wnum_div
 *                   correctly rounded (halves away from 0), saturation and
 *                   the saturation counter as the definitions give them
 *   num_smul32, num_mul_wide, v3_dot_wide, v3_dot, v3_cross
 *                   against 128-bit / clamped references, extremes included
 *   wnum_mul        against its general form (saturation counted alike) */
#include <stdio.h>
#include <stdlib.h>

#include "num.h"
#include "num/num_int.h"
#include "raster/raster_num.h"
#include "check.h"
#define TEST_RNG_SEED 0x9E3779B97F4A7C15ull
#include "test_rng.h"

__extension__ typedef unsigned __int128 u128; /* host test only (GCC, Clang) */
__extension__ typedef __int128 i128;



/* A signed raw value: log-uniform magnitude, both signs, extremes often. */
static int32_t rnd_num(void)
{
    switch (rng() % 16) {
    case 0: return INT32_MIN;
    case 1: return INT32_MAX;
    case 2: return -INT32_MAX;
    case 3: return (int32_t)(rng() % 5) - 2;
    default: break;
    }
    int32_t v = (int32_t)rnd_bits(31);
    return rng() & 1 ? -v : v;
}

static void test_rcp16(void)
{
    /* rh depends on dn >> 9 only: check the bucket's two ends against
     * 2^64 / dn exactly. Lower: (2^32 + rh 2^16) * dn_max <= 2^64;
     * upper: (2^32 + rh 2^16 + 2^17) * dn_min > 2^64. */
    long bad = 0;
    uint32_t badb = 0;
    const u128 two64 = (u128)1 << 64;
    for (uint32_t b = 1u << 22; b < (1u << 23); b++) {
        uint32_t dmin = b << 9, dmax = dmin | 511;
        uint32_t rh = num_rcp16(dmin);
        u128 v = ((u128)1 << 32) + ((u128)rh << 16);
        if (rh != num_rcp16(dmax) || rh >= 65536 || v * dmax > two64 || (v + (1u << 17)) * dmin <= two64) {
            bad++;
            badb = b;
        }
    }
    check(bad == 0, "num_rcp16_bounds_exhaustive", "%ld buckets out of bounds, e.g. dn >> 9 = %u", bad, badb);
}

static void test_rcp32(void)
{
    /* floor((2^64 - 1) / dn) - 2^32 exactly: both ends of every bucket of
     * num_rcp16's seed (dn >> 9), the ends of the range, and random dn */
    long bad = 0, bade = 0;
    uint32_t badd = 0, badde = 0;
    const u128 m64 = ((u128)1 << 64) - 1;
    for (long i = -2; i < (1L << 23) + 4000000; i++) {
        uint32_t dn;
        if (i < 0) dn = i == -2 ? 0x80000000u : 0xFFFFFFFFu;
        else if (i < (1L << 23)) dn = (uint32_t)((1u << 31) | ((uint32_t)(i >> 1) << 9) | (i & 1 ? 511u : 0u));
        else dn = (uint32_t)rnd_bits(32) | 0x80000000u;
        const u128 v = m64 / dn - ((u128)1 << 32), e = num_rcp32_est(dn);
        if ((u128)num_rcp32(dn) != v) {
            bad++;
            badd = dn;
        }
        if (e > v || e + 6 < v) {
            bade++;
            badde = dn;
        }
    }
    check(bad == 0, "num_rcp32_matches_division", "%ld mismatches, e.g. dn = %u", bad, badd);
    check(bade == 0, "num_rcp32_est_within_6_below", "%ld out of [v - 6, v], e.g. dn = %u", bade, badde);
}

/* ras_div_sub against the plain forms: wnum_div(num_mul_wide(x, u), z),
 * num_recip(z), ras_depth32(near, z), and the screen positions
 * ras_sub_pos(num_add(cx, X), sb), ras_sub_pos(num_sub(cy, Y), sb) */
static void test_div_sub(void)
{
    long bad = 0, n = 0;
    int32_t bx = 0, by = 0, bz = 0;
    const num ONE = NUM_ONE_RAW;
    const num zs[] = { 1, 2, 3, 15, 16, 17, ONE - 1, ONE, ONE + 1, (1 << 27) - 1, 1 << 27, (1 << 28) - 1, 1 << 28,
                       (1 << 28) + 1, INT32_MAX - 1, INT32_MAX, 0, -1, -ONE, INT32_MIN };
    for (long i = 0; i < 3000000; i++) {
        struct ras_subproj k;
        const int c = (int)(rng() % 8);
        k.unproj = c == 0 ? rnd_num() : (num)(rng() % ((uint64_t)1 << (NUM_FRAC + 10)));
        k.near_z = c == 1 ? rnd_num() : (num)(rng() % ((uint64_t)2 << NUM_FRAC)) + 1;
        k.cx = c == 2 ? rnd_num() : (num)((rng() % 400) << NUM_FRAC);
        k.cy = c == 3 ? rnd_num() : (num)((rng() % 400) << NUM_FRAC);
        k.sb = (int32_t)(rng() % 8) + 1;
        num x = rnd_num(), y = rnd_num(), z;
        switch (rng() % 4) {
        case 0: z = zs[rng() % (sizeof zs / sizeof zs[0])]; break;
        case 1: {
            const int64_t w = (int64_t)k.near_z + (int64_t)(rng() % 3) - 1;
            z = w > INT32_MAX ? INT32_MAX : (num)w;
            break;
        }
        default: z = (num)rnd_bits(31); break;
        }
        if (rng() % 2) { /* inside a view: |x|, |y| below about z */
            const int64_t m = (int64_t)(z < 0 ? -(int64_t)z : z) * 2 + 1;
            x = (num)((int64_t)(rng() % (uint64_t)m) - m / 2);
            y = (num)((int64_t)(rng() % (uint64_t)m) - m / 2);
        }
        struct ras_subpos o;
        ras_div_sub(&k, x, y, z, &o);
        const num X = wnum_div(num_mul_wide(x, k.unproj), wnum_from_num(z));
        const num Y = wnum_div(num_mul_wide(y, k.unproj), wnum_from_num(z));
        const int32_t sx = ras_sub_pos(num_add(k.cx, X), (int)k.sb), sy = ras_sub_pos(num_sub(k.cy, Y), (int)k.sb);
        n++;
        if (o.sx != sx || o.sy != sy || o.iz != num_recip(z) || o.depth != ras_depth32(k.near_z, z)) {
            bad++;
            bx = x;
            by = y;
            bz = z;
        }
    }
    check(bad == 0, "ras_div_sub_matches_division", "%ld of %ld mismatch, e.g. x %d y %d z %d", bad, n, (int)bx,
          (int)by, (int)bz);
}

static void test_udiv(void)
{
    long bad = 0, badp = 0;
    uint64_t bn = 0;
    uint32_t bd = 0;
    for (long i = 0; i < 4000000; i++) {
        uint32_t d = (uint32_t)rnd_bits(32);
        if (i % 13 == 0) d = UINT32_MAX - (uint32_t)(rng() % 3);
        if (i % 17 == 0) d = (uint32_t)1 << (rng() % 32);
        /* n < d 2^32: a log-uniform quotient, or edges near multiples of d */
        uint64_t n;
        switch (i % 4) {
        case 0: n = rng() % ((uint64_t)d << 32 | 0xFFFFFFFFu); break;
        case 1: n = (rnd_bits(32) % ((uint64_t)1 << 32)) * d + rng() % d; break;
        case 2: { uint64_t q = rng() >> 32; n = q * d + (rng() & 1 ? d - 1 : 0); break; }
        default: n = rnd_bits(64) % ((uint64_t)d << 32); break;
        }
        if ((n >> 32) >= d) n = ((uint64_t)d << 32) - 1;
        uint32_t r, q = num_udiv64_32(n, d, &r);
        if (q != n / d || r != n % d || num_udiv64_32(n, d, 0) != q) { bad++; bn = n; bd = d; }
        const struct num_udiv_pre p = num_udiv_pre_make(d);
        q = num_udiv64_32_pre(n, &p, &r);
        if (q != n / d || r != n % d || num_udiv64_32_pre(n, &p, 0) != q) { badp++; bn = n; bd = d; }
    }
    for (uint32_t d = 1; d < 70000; d++) { /* small divisors, largest quotients */
        uint64_t n = ((uint64_t)d << 32) - 1 - (rng() % d);
        uint32_t r, q = num_udiv64_32(n, d, &r);
        if (q != n / d || r != n % d) { bad++; bn = n; bd = d; }
        const struct num_udiv_pre p = num_udiv_pre_make(d);
        q = num_udiv64_32_pre(n, &p, &r);
        if (q != n / d || r != n % d) { badp++; bn = n; bd = d; }
    }
    check(bad == 0, "num_udiv64_32_matches_division", "%ld mismatches, e.g. %llu / %u", bad,
          (unsigned long long)bn, bd);
    check(badp == 0, "num_udiv64_32_pre_matches_division", "%ld mismatches, e.g. %llu / %u", badp,
          (unsigned long long)bn, bd);
}

/* n / d rounded half away from 0 with sign; saturated beyond INT32_MAX. */
static num ref_round(u128 n, u128 d, int neg, int *sat)
{
    u128 q = n / d, r = n % d;
    if (r >= d - r) q++;
    *sat = q > INT32_MAX;
    if (*sat) return neg ? NUM_MIN : NUM_MAX;
    return neg ? -(num)q : (num)q;
}

static u128 uabs128(i128 v) { return v < 0 ? (u128)-v : (u128)v; }

/* The definitions of num.h: b == 0 gives 0 for a == 0, else the signed
 * saturated value (counted). */
static num ref_div(i128 a, i128 b, int frac, int *sat)
{
    *sat = 0;
    if (b == 0) {
        if (a == 0) return 0;
        *sat = 1;
        return a > 0 ? NUM_MAX : NUM_MIN;
    }
    return ref_round(uabs128(a) << frac, uabs128(b), (a < 0) != (b < 0), sat);
}

/* op's result and saturation count equal the reference's */
static int same(num got, uint32_t sat_before, num want, int want_sat)
{
    return got == want && num_saturations - sat_before == (uint32_t)want_sat;
}

static void test_div_ops(void)
{
    long bad_div = 0, bad_rcp = 0, bad_ratio = 0, bad_int = 0;
    int32_t ba = 0, bb = 0;
    int s;
    for (long i = 0; i < 4000000; i++) {
        int32_t a = rnd_num(), b = rnd_num();
        if (i % 7 == 0) b = (int32_t)(rng() % 4096) - 2048;            /* small divisors */
        if (i % 11 == 0) a = (int32_t)((int64_t)(b / 2) * (int64_t)(rng() % 3 + 1)); /* halves, exact ratios */
        uint32_t c = num_saturations;
        num want = ref_div(a, b, NUM_FRAC, &s);
        if (!same(num_div(a, b), c, want, s)) { bad_div++; ba = a; bb = b; }
        c = num_saturations;
        want = ref_div(NUM_ONE, b, NUM_FRAC, &s);
        if (!same(num_recip(b), c, want, s)) bad_rcp++;
        c = num_saturations;
        want = ref_div(a, b, NUM_FRAC, &s);
        if (!same(num_from_ratio(a, b), c, want, s)) bad_ratio++;
        c = num_saturations;
        want = ref_div(a, b, 0, &s);
        if (!same(num_div_int(a, b), c, want, s)) bad_int++;
    }
    for (int32_t b = -(1 << 21); b <= (1 << 21); b++) { /* every small divisor */
        uint32_t c = num_saturations;
        num want = ref_div(NUM_ONE, b, NUM_FRAC, &s);
        if (!same(num_recip(b), c, want, s)) bad_rcp++;
    }
    check(bad_div == 0, "num_div_matches_definition", "%ld mismatches, e.g. %d / %d -> %d", bad_div, ba, bb,
          num_div(ba, bb));
    check(bad_rcp == 0, "num_recip_matches_definition", "%ld mismatches", bad_rcp);
    check(bad_ratio == 0, "num_from_ratio_matches_definition", "%ld mismatches", bad_ratio);
    check(bad_int == 0, "num_div_int_matches_definition", "%ld mismatches", bad_int);
}

static int64_t rnd_wide(void)
{
    int64_t v;
    switch (rng() % 12) {
    case 0: v = INT64_MAX; break;
    case 1: v = INT64_MIN; break;
    case 2: v = (int64_t)(rng() % 5) - 2; break;
    default: v = (int64_t)rnd_bits(63); if (rng() & 1) v = -v; break;
    }
    return v;
}

static void test_wnum_div(void)
{
    long bad = 0;
    int64_t ba = 0, bb = 0;
    int s;
    for (long i = 0; i < 3000000; i++) {
        int64_t a = rnd_wide(), b = rnd_wide();
        if (i % 3 == 0) b = (int64_t)rnd_bits(33) * (rng() & 1 ? -1 : 1); /* fast path and just beyond */
        if (i % 5 == 0) a = (int64_t)rnd_bits(63 - NUM_FRAC) * (rng() & 1 ? -1 : 1);
        uint32_t c = num_saturations;
        num want = ref_div(a, b, NUM_FRAC, &s);
        if (!same(wnum_div(a, b), c, want, s)) { bad++; ba = a; bb = b; }
    }
    check(bad == 0, "wnum_div_matches_definition", "%ld mismatches, e.g. %lld / %lld", bad, (long long)ba,
          (long long)bb);
}

/* ---- products and dot products ---------------------------------------- */

#define WLIM_REF (INT64_MAX / 4)
static int64_t ref_clamp(i128 v)
{
    return v > WLIM_REF ? WLIM_REF : v < -(i128)WLIM_REF ? -WLIM_REF : (int64_t)v;
}

/* round(a b / 2^F), halves up (the arithmetic shift of p + 2^(F-1)) */
static int64_t ref_mul_wide(int32_t a, int32_t b)
{
    i128 p = (i128)a * b + ((i128)1 << (NUM_FRAC - 1));
    return (int64_t)(p >> NUM_FRAC);
}

/* The former v3_dot_wide: clamp to +-INT64_MAX/4 after every step. */
static int64_t ref_dot_wide(vec3 a, vec3 b)
{
    int64_t s = ref_clamp((i128)ref_clamp(ref_mul_wide(a.x, b.x)) + ref_clamp(ref_mul_wide(a.y, b.y)));
    return ref_clamp((i128)ref_clamp(s) + ref_clamp(ref_mul_wide(a.z, b.z)));
}

static num ref_sat(int64_t v, int *sat)
{
    *sat = v > INT32_MAX || v < -(int64_t)INT32_MAX;
    return v > INT32_MAX ? NUM_MAX : v < -(int64_t)INT32_MAX ? NUM_MIN : (num)v;
}

static void test_products(void)
{
    long bad_mul = 0, bad_wide = 0, bad_dot = 0, bad_cross = 0, bad_sat = 0;
    vec3 bv = v3_make(0, 0, 0);
    for (long i = 0; i < 4000000; i++) {
        int32_t a = rnd_num(), b = rnd_num();
        if (num_smul32(a, b) != (int64_t)a * b) bad_mul++;
        if (num_mul_wide(a, b) != ref_mul_wide(a, b)) bad_wide++;
        vec3 u = v3_make(rnd_num(), rnd_num(), rnd_num()), v = v3_make(rnd_num(), rnd_num(), rnd_num());
        if (i % 4 == 0) { v = u; }                                  /* squares: the largest sums */
        if (i % 8 == 1) { u.x = u.y = u.z = INT32_MIN; v.x = v.y = v.z = (i & 16) ? INT32_MIN : INT32_MAX; }
        int64_t w = ref_dot_wide(u, v);
        int s;
        if (v3_dot_wide(u, v) != w) { bad_dot++; bv = u; }
        uint32_t c = num_saturations;
        num d = ref_sat(w, &s);
        if (!same(v3_dot(u, v), c, d, s)) bad_sat++;
        vec3 x = v3_cross(u, v);
        num cx = ref_sat(ref_clamp((i128)ref_clamp(ref_mul_wide(u.y, v.z)) - ref_clamp(ref_mul_wide(u.z, v.y))), &s);
        num cy = ref_sat(ref_clamp((i128)ref_clamp(ref_mul_wide(u.z, v.x)) - ref_clamp(ref_mul_wide(u.x, v.z))), &s);
        num cz = ref_sat(ref_clamp((i128)ref_clamp(ref_mul_wide(u.x, v.y)) - ref_clamp(ref_mul_wide(u.y, v.x))), &s);
        if (x.x != cx || x.y != cy || x.z != cz) bad_cross++;
    }
    check(bad_mul == 0, "num_smul32_exact", "%ld mismatches", bad_mul);
    check(bad_wide == 0, "num_mul_wide_matches_definition", "%ld mismatches", bad_wide);
    check(bad_dot == 0, "v3_dot_wide_matches_clamped_sum", "%ld mismatches, e.g. (%d, %d, %d)", bad_dot, bv.x, bv.y,
          bv.z);
    check(bad_sat == 0, "v3_dot_matches_definition", "%ld mismatches (value or saturation count)", bad_sat);
    check(bad_cross == 0, "v3_cross_matches_definition", "%ld mismatches", bad_cross);
}

/* The former wnum_mul (general split, used for every operand before the
 * 32-bit fast path): |a*b| >> F with b = bh 2^F + bl, saturated at
 * INT64_MAX/4 (counted). */
static int64_t ref_wnum_mul(int64_t a, int64_t b, int *sat)
{
    int neg = (a < 0) != (b < 0);
    uint64_t ua = (uint64_t)(a < 0 ? -(i128)a : a), ub = (uint64_t)(b < 0 ? -(i128)b : b);
    uint64_t lim = (uint64_t)WLIM_REF;
    uint64_t bh = ub >> NUM_FRAC, bl = ub & (((uint64_t)1 << NUM_FRAC) - 1);
    uint64_t hi = 0;
    *sat = 0;
    if (bh && ua) {
        int l = (64 - __builtin_clzll(ua)) + (64 - __builtin_clzll(bh));
        if (l >= 63) { *sat = 1; return neg ? -(int64_t)lim : (int64_t)lim; }
        hi = ua * bh;
    }
    uint64_t lo;
    if (ua >= ((uint64_t)1 << (64 - NUM_FRAC))) lo = (ua >> NUM_FRAC) * bl;
    else lo = (ua * bl + ((uint64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC;
    uint64_t r = hi + lo;
    if (hi > lim || r > lim) { *sat = 1; r = lim; }
    return neg ? -(int64_t)r : (int64_t)r;
}

static void test_wnum_mul(void)
{
    long bad = 0;
    int64_t ba = 0, bb = 0;
    for (long i = 0; i < 3000000; i++) {
        int64_t a, b;
        if (i % 3) { /* both below 2^32 in magnitude, the fast path, and its edges */
            a = (int64_t)rnd_bits(i % 5 ? 32 : 33);
            b = (int64_t)rnd_bits(i % 7 ? 32 : 33);
            if (rng() & 1) a = -a;
            if (rng() & 1) b = -b;
            if (i % 11 == 0) a = rng() & 1 ? 0xFFFFFFFFll : -0xFFFFFFFFll;
        } else {
            a = rnd_wide();
            b = rnd_wide();
        }
        int s;
        int64_t want = ref_wnum_mul(a, b, &s);
        uint32_t c = num_saturations;
        int64_t got = wnum_mul(a, b);
        if (got != want || num_saturations - c != (uint32_t)s) { bad++; ba = a; bb = b; }
    }
    check(bad == 0, "wnum_mul_matches_definition", "%ld mismatches, e.g. %lld * %lld", bad, (long long)ba,
          (long long)bb);
}

int main(void)
{
    test_rcp16();
    test_rcp32();
    test_div_sub();
    test_udiv();
    test_div_ops();
    test_wnum_div();
    test_products();
    test_wnum_mul();
    return check_exit();
}
