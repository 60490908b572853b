/* SPDX-License-Identifier: MIT */
/* test_num_kernels.c — the fixed-point square-root kernels (num_int.h) and
 * the operations built on them give exactly the bits of their definitions.
 *
 * Built for fixed point at NUM_FRAC 12 (with the portable ARMv6-M integer
 * paths), 16 and 20. References are written the slow, obvious way (digit
 * recurrence, 128-bit integers, 64-bit division); the fast paths must match
 * them bit for bit on dense random samples, edge cases and exhaustive ranges:
 *   num_rsqrt_q30   relative error < 2^-17 (its documented bound)
 *   num_sqrt_est, num_sqrt_est32   within 2 units of sqrt(x)
 *   num_isqrt64     floor and remainder, every magnitude
 *   num_sqrt, wnum_sqrt, num_rsqrt, v3_len, v3_normalize   definitions in num.h */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "num.h"
#include "num/num_int.h"
#include "check.h"
#define TEST_RNG_SEED 0x2545F4914F6CDD1Dull
#include "test_rng.h"

__extension__ typedef unsigned __int128 u128; /* host test only (GCC, Clang) */



static uint64_t ref_isqrt(uint64_t v, uint64_t *rem)
{
    uint64_t r = 0, bit = (uint64_t)1 << 62;
    while (bit > v) bit >>= 2;
    while (bit) {
        if (v >= r + bit) { v -= r + bit; r = (r >> 1) + bit; }
        else r >>= 1;
        bit >>= 2;
    }
    *rem = v;
    return r;
}

static uint64_t ref_isqrt_round(uint64_t v)
{
    uint64_t rm, r = ref_isqrt(v, &rm);
    return rm > r ? r + 1 : r;
}

static void test_rsqrt_q30(void)
{
    /* every seed interval: both ends and 256 random points; plus a stride */
    double worst = 0, worst_x = 0;
    long n = 0;
    for (uint32_t j = 128; j < 512; j++)
        for (int i = 0; i < 258; i++) {
            uint32_t xh = j << 23;
            if (i == 1) xh |= (1u << 23) - 1;
            else if (i > 1) xh |= (uint32_t)(rng() >> 41);
            long double u = (long double)xh / 4294967296.0L;
            long double e = fabsl((long double)num_rsqrt_q30(xh) / 1073741824.0L * sqrtl(u) - 1);
            if (e > worst) { worst = (double)e; worst_x = xh; }
            n++;
        }
    for (uint64_t xh = 1u << 30; xh <= UINT32_MAX; xh += 997) {
        long double u = (long double)xh / 4294967296.0L;
        long double e = fabsl((long double)num_rsqrt_q30((uint32_t)xh) / 1073741824.0L * sqrtl(u) - 1);
        if (e > worst) { worst = (double)e; worst_x = (double)xh; }
        n++;
    }
    check(worst < ldexp(1, -17), "num_rsqrt_q30_bound", "relative error 2^%.2f at xh %.0f (%ld samples)",
          log2(worst), worst_x, n);
}

/* stride of the 32-bit sweeps: every value near the seed's interval ends */
static uint64_t i_step(uint64_t x) { return (x & ((1u << 23) - 1)) < 64 || (~x & ((1u << 23) - 1)) < 64 ? 1 : 211; }

static void test_sqrt_est(void)
{
    double worst = 0;
    uint64_t worst_v = 0;
    for (long i = 0; i < 3000000; i++) {
        uint64_t v = i < 64 ? (uint64_t)1 << i : rnd_bits(64);
        if (i % 7 == 3) v = UINT64_MAX - (rng() & 0xFFFF);
        int k;
        uint32_t e = num_sqrt_est(v, &k, 0);
        long double ex = sqrtl((long double)v) * ldexpl(1, k);
        double d = (double)fabsl((long double)e - ex);
        if (d > worst) { worst = d; worst_v = v; }
    }
    check(worst <= 2, "num_sqrt_est_within_2", "error %.3f at v %llu", worst, (unsigned long long)worst_v);
    worst = 0;
    for (uint64_t xh = 1u << 30; xh <= UINT32_MAX; xh += (i_step(xh))) {
        double d = (double)fabsl((long double)num_sqrt_est32((uint32_t)xh) - sqrtl((long double)xh) * 65536);
        if (d > worst) { worst = d; worst_v = xh; }
    }
    check(worst < 2, "num_sqrt_est32_within_2", "error %.3f at xh %llu", worst, (unsigned long long)worst_v);
}

static void test_isqrt64(void)
{
    long bad = 0;
    uint64_t badv = 0;
    for (uint64_t v = 0; v < (1u << 20); v++) {
        uint64_t r1, r2, a = num_isqrt64(v, &r1), b = ref_isqrt(v, &r2);
        if (a != b || r1 != r2) { bad++; badv = v; }
    }
    for (long i = 0; i < 3000000; i++) {
        uint64_t v;
        switch (i % 4) {
        case 0: v = rnd_bits(64); break;
        case 1: { uint64_t r = rnd_bits(32); v = r * r + (rng() % 3) - 1; break; } /* squares +-1 */
        case 2: { uint64_t r = rnd_bits(32); v = r * r + r + (rng() % 3) - 1; break; } /* rounding edge */
        default: v = UINT64_MAX - (rng() % 100000); break;
        }
        uint64_t r1, r2, a = num_isqrt64(v, &r1), b = ref_isqrt(v, &r2);
        if (a != b || r1 != r2) { bad++; badv = v; }
    }
    check(bad == 0, "num_isqrt64_matches_reference", "%ld mismatches, e.g. v %llu", bad, (unsigned long long)badv);
}

static void test_sqrt_ops(void)
{
    long bad = 0, badw = 0;
    int32_t bada = 0;
    for (int32_t a = 0; a <= (1 << 22); a++)
        if ((uint64_t)num_sqrt(a) != ref_isqrt_round((uint64_t)a << NUM_FRAC)) { bad++; bada = a; }
    for (long i = 0; i < 3000000; i++) {
        int32_t a = (int32_t)rnd_bits(31);
        if ((uint64_t)num_sqrt(a) != ref_isqrt_round((uint64_t)a << NUM_FRAC)) { bad++; bada = a; }
        /* wnum_sqrt: the value below 2^(64-F) */
        int64_t w = (int64_t)rnd_bits(63 - NUM_FRAC);
        if ((uint64_t)wnum_sqrt(w) != ref_isqrt_round((uint64_t)w << NUM_FRAC)) badw++;
    }
    check(bad == 0 && num_sqrt(NUM_MAX) == (num)ref_isqrt_round((uint64_t)NUM_MAX << NUM_FRAC),
          "num_sqrt_correctly_rounded_exact", "%ld mismatches, e.g. raw %d", bad, bada);
    check(badw == 0, "wnum_sqrt_correctly_rounded_exact", "%ld mismatches", badw);
}

/* round(sqrt(2^(3F) / a)): a (2y-1)^2 <= 2^(3F+2) < a (2y+1)^2. */
static int rsqrt_ok(int32_t a, int32_t y)
{
    u128 k = (u128)1 << (3 * NUM_FRAC + 2), m1 = 2 * (u128)y - 1, m2 = 2 * (u128)y + 1;
    return y > 0 && (u128)a * m1 * m1 <= k && k < (u128)a * m2 * m2;
}

static void test_rsqrt(void)
{
    long bad = 0;
    int32_t bada = 0;
    for (int32_t a = 1; a <= (1 << 22); a++)
        if (!rsqrt_ok(a, num_rsqrt(a))) { bad++; bada = a; }
    for (long i = 0; i < 3000000; i++) {
        int32_t a = (int32_t)rnd_bits(31);
        if (i & 1) a = (int32_t)(rnd_bits(31) & ~0xFFu); /* near powers of two and squares */
        if (a <= 0) a = 1;
        if (!rsqrt_ok(a, num_rsqrt(a))) { bad++; bada = a; }
    }
    if (!rsqrt_ok(NUM_MAX, num_rsqrt(NUM_MAX))) bad++;
    check(bad == 0, "num_rsqrt_correctly_rounded_exact", "%ld wrong, e.g. raw %d -> %d", bad, bada,
          num_rsqrt(bada));
}

/* v3_len and v3_normalize by their definitions in num.c: components
 * pre-scaled so the largest is in [2^29, 2^30) (or halved when >= 2^30),
 * L = round(sqrt(sum of squares)), R = floor(2^60 / L), u * R / 2^(60-F)
 * rounded. */
static void ref_norm(vec3 a, num out[3], num *len)
{
    int32_t in[3] = { a.x, a.y, a.z };
    uint64_t u[3], mx = 0;
    for (int i = 0; i < 3; i++) {
        u[i] = (uint64_t)llabs((long long)in[i]);
        if (u[i] > mx) mx = u[i];
    }
    int sh = 0;
    if (mx >= (1u << 30)) sh = -1;
    else while ((mx << sh) < (1u << 29)) sh++;
    uint64_t s = 0, s0 = 0;
    for (int i = 0; i < 3; i++) {
        s0 += u[i] * u[i];
        u[i] = sh >= 0 ? u[i] << sh : u[i] >> 1;
        s += u[i] * u[i];
    }
    uint64_t rm, l = ref_isqrt(s, &rm);
    if (sh > 0) *len = (num)((l + ((uint64_t)1 << (sh - 1))) >> sh);
    else {
        uint64_t r0m, l0 = ref_isqrt(s0, &r0m);
        if (r0m > l0) l0++;
        *len = l0 > INT32_MAX ? NUM_MAX : (num)l0;
    }
    if (rm > l) l++;
    uint64_t R = ((uint64_t)1 << 60) / l;
    for (int i = 0; i < 3; i++) {
        num m = (num)((u[i] * R + ((uint64_t)1 << (59 - NUM_FRAC))) >> (60 - NUM_FRAC));
        out[i] = in[i] < 0 ? -m : m;
    }
}

static void test_vec(void)
{
    long bad = 0, badl = 0;
    vec3 bv = v3_make(0, 0, 0);
    for (long i = 0; i < 2000000; i++) {
        int bits = 1 + (int)(i % 31);
        vec3 v = v3_make((num)rnd_bits(bits), (num)rnd_bits(bits), (num)rnd_bits(bits));
        if (rng() & 1) v.x = -v.x;
        if (rng() & 1) v.y = -v.y;
        if (i % 5 == 0) v.z = 0;
        if (i % 11 == 0) v.y = v.x;
        num want[3], wl;
        ref_norm(v, want, &wl);
        vec3 u = v3_normalize(v);
        if (u.x != want[0] || u.y != want[1] || u.z != want[2]) { bad++; bv = v; }
        if (v3_len(v) != wl) badl++;
    }
    check(bad == 0, "v3_normalize_matches_definition", "%ld mismatches, e.g. (%d, %d, %d)", bad, bv.x, bv.y, bv.z);
    check(badl == 0, "v3_len_matches_definition", "%ld mismatches", badl);
}

/* v3_div_len against x 2^F / sqrt(sum of squares) in long double: within
 * half an ulp plus 2^-26 of the quotient, saturating beyond the format. */
static void test_div_len(void)
{
    long bad = 0, n = 0;
    double worst = 0;
    for (long i = 0; i < 1000000; i++) {
        int bits = 1 + (int)(i % 31);
        vec3 v = v3_make((num)rnd_bits(bits), (num)rnd_bits(bits), (num)rnd_bits(bits));
        if (rng() & 1) v.x = -v.x;
        if (i % 7 == 0) v.z = 0;
        num x = (num)rnd_bits(1 + (int)(rng() % 31));
        if (rng() & 1) x = -x;
        if (v.x == 0 && v.y == 0 && v.z == 0) continue;
        long double ss = (long double)v.x * v.x + (long double)v.y * v.y + (long double)v.z * v.z;
        long double q = (long double)x * (long double)NUM_ONE / sqrtl(ss);
        num got = v3_div_len(x, v);
        if (fabsl(q) >= (long double)INT32_MAX) {
            if (got != (q > 0 ? NUM_MAX : NUM_MIN)) bad++;
            continue;
        }
        double err = (double)fabsl((long double)got - q);
        double lim = 0.5 + fabs((double)q) * ldexp(1.0, -26) + 1e-9;
        if (err > lim) bad++;
        if (err - 0.5 > worst) worst = err - 0.5;
        n++;
    }
    check(bad == 0 && n > 900000, "v3_div_len_bounded", "%ld of %ld beyond the bound", bad, n);
}

/* num_mul_recip against a 2^F / d in long double: within half an ulp plus
 * 2^-31 of the quotient, and num_div's bits nearly always. */
static void test_mul_recip(void)
{
    long bad = 0, same = 0, n = 0, small = 0;
    for (long i = 0; i < 1000000; i++) {
        num d = (num)rnd_bits(1 + (int)(i % 31)), a = (num)rnd_bits(1 + (int)(rng() % 31));
        if (d == 0) d = 1;
        if (rng() & 1) d = -d;
        if (rng() & 1) a = -a;
        struct num_recip r = num_recip_make(d);
        long double q = (long double)a * (long double)NUM_ONE / (long double)d;
        num got = num_mul_recip(a, &r);
        if (fabsl(q) >= (long double)INT32_MAX) {
            if (got != (q > 0 ? NUM_MAX : NUM_MIN)) bad++;
            continue;
        }
        if ((double)fabsl((long double)got - q) > 0.5 + fabs((double)q) * ldexp(1.0, -31) + 1e-9) bad++;
        if (fabsl(q) < (long double)(1 << 24)) {
            same += got == num_div(a, d);
            small++;
        }
        n++;
    }
    check(bad == 0 && n > 500000, "num_mul_recip_bounded", "%ld of %ld beyond the bound", bad, n);
    /* below 2^24 ulps the reciprocal's error is under 2^-7 ulp */
    check(same * 100 >= small * 99, "num_mul_recip_mostly_num_div", "%ld of %ld as num_div", same, small);
}

int main(void)
{
    test_div_len();
    test_mul_recip();
    test_rsqrt_q30();
    test_sqrt_est();
    test_isqrt64();
    test_sqrt_ops();
    test_rsqrt();
    test_vec();
    return check_exit();
}
