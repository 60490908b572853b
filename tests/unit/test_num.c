/* SPDX-License-Identifier: MIT */
/* test_num.c — accuracy and edge cases of the numeric layer (num.h).
 *
 * Built once per numeric mode (and for fixed point with NUM_FRAC 12, 16, 20).
 * For each operation it measures the max and mean error against the double
 * result over an exhaustive or dense sweep plus edge cases, and fails when an
 * error exceeds the bound documented in docs/numerics.md.
 *   test_num            PASS/FAIL lines (tests/support/run.sh)
 *   test_num --report   one markdown table row per operation
 *
 * Error units: fixed point, 1 ulp = 2^-NUM_FRAC (absolute); float, 1 ulp of
 * the exact result (relative), except sin/cos where 1 unit = 2^-24
 * (absolute). The double build is the reference and only runs edge cases. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "num.h"
#include "check.h"
#define TEST_RNG_SEED 0x9E3779B97F4A7C15ull
#include "test_rng.h"

static int report;

#if NUM_MODE != NUM_MODE_DOUBLE

struct stat {
    const char *name, *domain, *bound_text;
    double max, sum, worst_in1, worst_in2;
    long n, over;
};

static void stat_add(struct stat *s, double err, double bound, double in1, double in2)
{
    if (err > s->max) { s->max = err; s->worst_in1 = in1; s->worst_in2 = in2; }
    s->sum += err;
    s->n++;
    if (!(err <= bound)) s->over++; /* NaN counts as over */
}

static void stat_end(struct stat *s)
{
    double mean = s->n ? s->sum / (double)s->n : 0;
    if (report) {
        char mode[32];
#if NUM_MODE == NUM_MODE_FIXED
        snprintf(mode, sizeof mode, "fixed Q%d.%d", 31 - NUM_FRAC, NUM_FRAC);
#else
        snprintf(mode, sizeof mode, "%s", NUM_NAME);
#endif
        printf("| %s | `%s` | %s | %ld | %.3f | %.4f | %s |\n", mode, s->name, s->domain, s->n, s->max, mean, s->bound_text);
        return;
    }
    char name[96];
    snprintf(name, sizeof name, "num_accuracy_%s", s->name);
    check(s->over == 0 && s->n > 0, name, "%ld of %ld samples beyond bound (%s); max %.4f at (%.9g, %.9g)",
          s->over, s->n, s->bound_text, s->max, s->worst_in1, s->worst_in2);
}

#endif

static double D(num a) { return num_to_double(a); }

#if NUM_MODE == NUM_MODE_FIXED
/* ---------------------------------------------------------------- fixed */
#define ULP ((double)NUM_ONE_RAW)
static double ferr(num r, double exact) { return fabs((double)r - exact * ULP); }

/* Random raw value with a log-uniform magnitude in [1, 2^bits). */
static int32_t rnd_raw(int bits)
{
    int b = (int)(rng() % (uint64_t)bits);
    int32_t v = (int32_t)((rng() >> 33) & ((1u << b) | ((1u << b) - 1)));
    if (v == 0) v = 1;
    return (rng() & 1) ? -v : v;
}

static int in_range(double raw) { return fabs(raw) < 2147483647.0; }

static void acc_mul(void)
{
    struct stat s = { "num_mul", "raw log-uniform pairs, 4M", "0.5", 0, 0, 0, 0, 0, 0 };
    for (long i = 0; i < 4000000; i++) {
        num a = rnd_raw(31), b = rnd_raw(31);
        double ex = D(a) * D(b);
        if (!in_range(ex * ULP)) continue;
        stat_add(&s, ferr(num_mul(a, b), ex), 0.5, D(a), D(b));
    }
    stat_end(&s);
}

static void acc_div(void)
{
    struct stat s = { "num_div", "raw log-uniform pairs, 4M", "0.5", 0, 0, 0, 0, 0, 0 };
    for (long i = 0; i < 4000000; i++) {
        num a = rnd_raw(31), b = rnd_raw(31);
        double ex = D(a) / D(b);
        if (!in_range(ex * ULP + 1)) continue;
        stat_add(&s, ferr(num_div(a, b), ex), 0.5 + 1e-6, D(a), D(b));
    }
    /* edge divisors: powers of two and their neighbours */
    for (int k = 0; k < 31; k++)
        for (int d = -1; d <= 1; d++) {
            num b = (num)(((uint32_t)1 << k) + (uint32_t)d);
            if (b <= 0) continue;
            num as[] = { 1, NUM_ONE, NUM_MAX, -NUM_MAX, 12345, b - 1 };
            for (unsigned j = 0; j < sizeof as / sizeof as[0]; j++) {
                double ex = D(as[j]) / D(b);
                if (in_range(ex * ULP + 1))
                    stat_add(&s, ferr(num_div(as[j], b), ex), 0.5 + 1e-6, D(as[j]), D(b));
            }
        }
    stat_end(&s);
}

static void acc_recip(void)
{
    struct stat s = { "num_recip", "exhaustive raw 1..2^22, 2M log-uniform, both signs", "0.5", 0, 0, 0, 0, 0, 0 };
    for (int32_t a = 1; a <= (1 << 22); a++) {
        double ex = 1.0 / D(a);
        if (in_range(ex * ULP + 1)) stat_add(&s, ferr(num_recip(a), ex), 0.5 + 1e-6, D(a), 0);
    }
    for (long i = 0; i < 2000000; i++) {
        num a = rnd_raw(31);
        double ex = 1.0 / D(a);
        if (in_range(ex * ULP + 1)) stat_add(&s, ferr(num_recip(a), ex), 0.5 + 1e-6, D(a), 0);
    }
    stat_end(&s);
}

static void acc_sqrt(void)
{
    struct stat s = { "num_sqrt", "exhaustive raw 0..2^22, 2M log-uniform", "0.5", 0, 0, 0, 0, 0, 0 };
    for (int32_t a = 0; a <= (1 << 22); a++)
        stat_add(&s, ferr(num_sqrt(a), sqrt(D(a))), 0.5 + 1e-6, D(a), 0);
    for (long i = 0; i < 2000000; i++) {
        num a = num_abs(rnd_raw(31));
        stat_add(&s, ferr(num_sqrt(a), sqrt(D(a))), 0.5 + 1e-6, D(a), 0);
    }
    stat_add(&s, ferr(num_sqrt(NUM_MAX), sqrt(D(NUM_MAX))), 0.5 + 1e-6, D(NUM_MAX), 0);
    stat_end(&s);
}

static void acc_rsqrt(void)
{
    struct stat s = { "num_rsqrt", "exhaustive raw 1..2^22, 2M log-uniform", "0.5", 0, 0, 0, 0, 0, 0 };
    for (int32_t a = 1; a <= (1 << 22); a++)
        stat_add(&s, ferr(num_rsqrt(a), 1.0 / sqrt(D(a))), 0.5 + 1e-6, D(a), 0);
    for (long i = 0; i < 2000000; i++) {
        num a = num_abs(rnd_raw(31));
        stat_add(&s, ferr(num_rsqrt(a), 1.0 / sqrt(D(a))), 0.5 + 1e-6, D(a), 0);
    }
    stat_add(&s, ferr(num_rsqrt(NUM_MAX), 1.0 / sqrt(D(NUM_MAX))), 0.5 + 1e-6, D(NUM_MAX), 0);
    stat_end(&s);
}

/* powi bound (documented in num.h): 0.5 ulp + |x^e| * e * 2^-30 relative. */
static double pow_bound(double ex_raw, uint32_t e) { return 0.5 + 1e-6 + fabs(ex_raw) * e * ldexp(1, -30); }

static void acc_powi(void)
{
    struct stat s = { "num_powi", "e 1..1000; abs(x) <= 1 dense + near 1, abs(x) <= 2 random; 1.2M",
                      "0.5 + abs(x^e) e 2^-30 (raw)", 0, 0, 0, 0, 0, 0 };
    struct stat s1 = { "num_powi_unit", "same, abs(x) <= 1 only", "0.5 + e 2^(F-30)", 0, 0, 0, 0, 0, 0 };
    for (long i = 0; i < 1200000; i++) {
        uint32_t e = 1 + (uint32_t)(rng() % 1000);
        num x;
        switch (i % 4) {
        case 0: x = (num)(rng() % (uint64_t)(NUM_ONE_RAW + 1)); break;       /* [0, 1] */
        case 1: x = NUM_ONE_RAW - (num)(rng() % 4096); break;                /* near 1 */
        case 2: x = -(num)(rng() % (uint64_t)(NUM_ONE_RAW + 1)); break;      /* [-1, 0] */
        default: x = (num)(rng() % (uint64_t)(4 * NUM_ONE_RAW)) - 2 * NUM_ONE_RAW; break;
        }
        double ex = pow(D(x), (double)e);
        if (!in_range(ex * ULP + 1)) continue;
        double err = ferr(num_powi(x, e), ex);
        stat_add(&s, err, pow_bound(ex * ULP, e), D(x), e);
        if (fabs(D(x)) <= 1) stat_add(&s1, err, 0.5 + 1e-6 + e * ldexp(1, NUM_FRAC - 30), D(x), e);
    }
    stat_end(&s);
    stat_end(&s1);
}

static void acc_sincos(void)
{
    struct stat s = { "num_sin_deg", "one turn (stride to <= 3M) + 1M random angles", "0.51", 0, 0, 0, 0, 0, 0 };
    struct stat c = { "num_cos_deg", "one turn (stride to <= 3M) + 1M random angles", "0.51", 0, 0, 0, 0, 0, 0 };
    const double k = 3.14159265358979323846 / 180;
    int32_t turn = 360 * NUM_ONE_RAW, step = turn / 3000000 + 1;
    for (long i = 0; i < 4000000; i++) {
        num d = i < 3000000 ? (num)(-turn / 2 + (int32_t)i * step) : (num)(uint32_t)rng();
        if (d == INT32_MIN) continue;
        if (i < 3000000 && d > turn) continue;
        double r = fmod(D(d), 360.0) * k; /* fmod is exact */
        stat_add(&s, ferr(num_sin_deg(d), sin(r)), 0.51, D(d), 0);
        stat_add(&c, ferr(num_cos_deg(d), cos(r)), 0.51, D(d), 0);
    }
    stat_end(&s);
    stat_end(&c);
}

static vec3 rnd_vec(int bits)
{
    return v3_make(rnd_raw(bits), rnd_raw(bits), rnd_raw(bits));
}

static void acc_vec(void)
{
    struct stat n = { "v3_normalize", "1M vectors, raw magnitudes 2^0..2^31 (tiny included)", "0.51", 0, 0, 0, 0, 0, 0 };
    struct stat l = { "v3_len", "1M vectors, max component < 2^30 raw", "0.5", 0, 0, 0, 0, 0, 0 };
    struct stat lh = { "v3_len_huge", "100k vectors, max component >= 2^30 raw", "0.5", 0, 0, 0, 0, 0, 0 };
    for (long i = 0; i < 1000000; i++) {
        vec3 v = rnd_vec(1 + (int)(i % 31));
        double x = D(v.x), y = D(v.y), z = D(v.z), len = sqrt(x * x + y * y + z * z);
        vec3 u = v3_normalize(v);
        stat_add(&n, ferr(u.x, x / len), 0.51, x, len);
        stat_add(&n, ferr(u.y, y / len), 0.51, y, len);
        stat_add(&n, ferr(u.z, z / len), 0.51, z, len);
        if (in_range(len * ULP + 1)) {
            int32_t m = abs(v.x) > abs(v.y) ? abs(v.x) : abs(v.y);
            if (abs(v.z) > m) m = abs(v.z);
            if (m < (1 << 30)) stat_add(&l, ferr(v3_len(v), len), 0.5 + 1e-6, len, 0);
            else stat_add(&lh, ferr(v3_len(v), len), 0.5 + 1e-6, len, 0);
        }
    }
    for (long i = 0; i < 100000; i++) {
        vec3 v = v3_make((num)(rng() >> 33) | (1 << 30), rnd_raw(31), rnd_raw(31));
        double x = D(v.x), y = D(v.y), z = D(v.z), len = sqrt(x * x + y * y + z * z);
        if (in_range(len * ULP + 1)) stat_add(&lh, ferr(v3_len(v), len), 0.5 + 1e-6, len, 0);
    }
    stat_end(&n);
    stat_end(&l);
    stat_end(&lh);
}

static void acc_wide(void)
{
    struct stat s = { "wnum_div", "1M pairs, 64-bit magnitudes 2^0..2^61", "0.5", 0, 0, 0, 0, 0, 0 };
    for (long i = 0; i < 1000000; i++) {
        int ba = (int)(rng() % 62), bb = (int)(rng() % 62);
        int64_t a = (int64_t)(rng() >> (64 - ba - 1)) + 1, b = (int64_t)(rng() >> (64 - bb - 1)) + 1;
        if (rng() & 1) a = -a;
        long double ex = (long double)a * ULP / (long double)b;
        if (fabsl(ex) >= 2147483646.0L) continue;
        double err = (double)fabsl((long double)wnum_div(a, b) - ex);
        stat_add(&s, err, 0.5 + 1e-6, (double)a, (double)b);
    }
    stat_end(&s);
}

static void acc_chan(void)
{
    /* Exhaustive over every raw channel value in [-2^F, 256 * 2^F]. */
    long bad = 0;
    for (int32_t c = -NUM_ONE_RAW; c <= 256 * NUM_ONE_RAW; c++) {
        int32_t cc = c < 0 ? 0 : (c > 255 * NUM_ONE_RAW ? 255 * NUM_ONE_RAW : c);
        for (uint32_t L = 31; L <= 63; L += 32) {
            /* exact in double: cc * L < 2^34 */
            uint32_t want = (uint32_t)floor(((double)cc * L + 255.0 * NUM_ONE_RAW / 2) / (255.0 * NUM_ONE_RAW));
            if (num_chan_levels(c, L) != want) bad++;
        }
        if (num_chan_byte(c) != (uint8_t)nearbyint(D(cc))) bad++;
    }
    if (!report) check(bad == 0, "num_chan_levels_exhaustive", "%ld mismatches", bad);
}

/* The previous floating-point formula, kept as the reference of num_from_double. */
static num ref_from_double(double d)
{
    double s = d * (double)NUM_ONE_RAW;
    if (s != s) return 0;
    if (s >= 2147483647.0) return NUM_MAX;
    if (s <= -2147483647.0) return NUM_MIN;
    return (num)(s >= 0 ? s + 0.5 : s - 0.5);
}

static void conversions(void)
{
    long bad = 0, bad2 = 0;
    const double sp[] = { 0.0, -0.0, 1e-300, 5e-324, 0.5 / NUM_ONE_RAW, 1.5 / NUM_ONE_RAW, -0.5 / NUM_ONE_RAW,
                          2147483647.0 / NUM_ONE_RAW, 2147483646.5 / NUM_ONE_RAW, 2147483646.49 / NUM_ONE_RAW,
                          1e300, -1e300, HUGE_VAL, -HUGE_VAL, NAN };
    for (unsigned i = 0; i < sizeof sp / sizeof sp[0]; i++)
        if (num_from_double(sp[i]) != ref_from_double(sp[i])) bad++;
    for (long i = 0; i < 2000000; i++) {
        double d = ldexp((double)(rng() >> 11), (int)(rng() % 80) - 90 - NUM_FRAC);
        if (rng() & 1) d = -d;
        if (i & 1) d = ((double)(int32_t)(uint32_t)rng() + 0.5) / NUM_ONE_RAW; /* ties */
        if (num_from_double(d) != ref_from_double(d)) bad++;
        num a = (num)(uint32_t)rng();
        if (a != INT32_MIN && num_to_double(a) != (double)a / NUM_ONE_RAW) bad2++;
    }
    check(bad == 0, "num_from_double_integer_only_matches_formula", "%ld mismatches", bad);
    check(bad2 == 0 && num_to_double(INT32_MIN) == -2147483648.0 / NUM_ONE_RAW, "num_to_double_exact",
          "%ld mismatches", bad2);
}

static void edges_fixed(void)
{
    num_saturations = 0;
    num r = num_add(NUM_MAX, NUM_ONE);
#ifdef NUM_COUNT_SAT
    check(r == NUM_MAX && num_saturations == 1, "num_add_saturates_and_counts", "r=%d sat=%u", r,
          (unsigned)num_saturations);
#else
    check(r == NUM_MAX, "num_add_saturates", "r=%d", r);
#endif
    check(num_sub(NUM_MIN, NUM_ONE) == NUM_MIN, "num_sub_saturates", "");
    check(num_add(0, INT32_MIN) == NUM_MIN && num_neg(INT32_MIN) == NUM_MAX && num_abs(INT32_MIN) == NUM_MAX,
          "num_int32_min_input_defined", "");
    check(num_to_int(INT32_MIN) == -(1 << (31 - NUM_FRAC)), "num_to_int_int32_min", "%d", num_to_int(INT32_MIN));
    check(num_mul(NUM_MAX, NUM_MAX) == NUM_MAX && num_mul(NUM_MAX, NUM_MIN) == NUM_MIN, "num_mul_saturates", "");
    check(num_div(NUM_MAX, 1) == NUM_MAX && num_div(-NUM_MAX, 1) == NUM_MIN, "num_div_overflow_saturates", "");
    check(num_div(INT32_MIN, NUM_ONE) == NUM_MIN, "num_div_int32_min", "%d", num_div(INT32_MIN, NUM_ONE));
    check(num_div_int(NUM_C(7.5), 2) == NUM_C(3.75) && num_div_int(-3, 2) == -2 && num_div_int(5, INT32_MIN) == 0,
          "num_div_int_rounds", "%d %d", num_div_int(NUM_C(7.5), 2), num_div_int(-3, 2));
    check(num_from_ratio(1, 3) == NUM_C(1.0 / 3) && num_from_ratio(-2, 3) == NUM_C(-2.0 / 3) &&
              num_from_ratio(1, 0) == NUM_MAX,
          "num_from_ratio_rounds", "%d", num_from_ratio(1, 3));
    check(num_from_int(1 << 20) == NUM_MAX && num_from_int(-(1 << 20)) == NUM_MIN, "num_from_int_saturates", "");
    check(num_powi(NUM_C(2.0), 1000) == NUM_MAX && num_powi(NUM_C(-2.0), 999) == NUM_MIN &&
              num_powi(NUM_C(0.5), 1000) == 0,
          "num_powi_saturates_and_underflows", "");
    check(num_sin_deg(NUM_MAX) == num_sin_deg(NUM_MAX) && num_cos_deg(NUM_MIN) == num_cos_deg(-NUM_MAX),
          "num_sincos_extreme_angles", "");
    check(wnum_div(INT64_MAX, 1) == NUM_MAX && wnum_div(INT64_MIN, 3) == NUM_MIN && wnum_div(5, 0) == NUM_MAX,
          "wnum_div_saturates", "");
    check(wnum_mul(INT64_MAX, INT64_MAX) == INT64_MAX / 4 && wnum_add(INT64_MAX, INT64_MAX) == INT64_MAX / 4,
          "wnum_saturates", "");
    check(wnum_sqrt(INT64_MAX / 4) > 0 && wnum_to_num_shr(INT64_MAX, 100) >= 0, "wnum_extremes_defined", "");
    /* tiny vectors keep their direction */
    vec3 u = v3_normalize(v3_make(1, 1, 0));
    check(u.x == NUM_C(0.70710678118654752) && u.y == u.x && u.z == 0, "v3_normalize_tiny", "%d %d %d", u.x,
          u.y, u.z);
    u = v3_normalize(v3_make(0, -1, 0));
    check(u.x == 0 && u.y == -NUM_ONE && u.z == 0, "v3_normalize_one_raw", "%d %d %d", u.x, u.y, u.z);
    u = v3_normalize(v3_make(NUM_MAX, NUM_MIN, INT32_MIN));
    check(u.x > 0 && u.y < 0 && u.z < 0, "v3_normalize_extreme", "%d %d %d", u.x, u.y, u.z);
    check(v3_len(v3_make(3, 4, 0)) == 5 && v3_len(v3_make(1, 1, 1)) == 2, "v3_len_tiny_exact_rounding", "%d",
          v3_len(v3_make(1, 1, 1)));
    /* v3_len_unit: v3_len's bits, for normalised vectors (its fast case),
     * vectors a few ulps off unit length, and any */
    long bad = 0;
    for (long i = 0; i < 300000; i++) {
        vec3 v = rnd_vec(1 + (int)(i % 31));
        vec3 u = v3_normalize(v);
        vec3 w = v3_make(u.x + (num)(rng() % 9) - 4, u.y + (num)(rng() % 9) - 4, u.z + (num)(rng() % 9) - 4);
        bad += v3_len_unit(u) != v3_len(u);
        bad += v3_len_unit(w) != v3_len(w);
        bad += v3_len_unit(v) != v3_len(v);
    }
    check(bad == 0, "v3_len_unit_is_v3_len", "%ld differ", bad);
    /* v3_normalize_unit: v3_normalize's bits, for vectors near unit length
     * (up to 2^-11 off, its fast case) and any */
    bad = 0;
    for (long i = 0; i < 300000; i++) {
        vec3 v = rnd_vec(1 + (int)(i % 31));
        vec3 u = v3_normalize(v);
        const int es = NUM_FRAC - 12 - (int)(i % 8);
        const int32_t e = (int32_t)1 << (es > 0 ? es : 0);
        vec3 w = v3_make(u.x + (num)(rng() % (uint64_t)(2 * e + 1)) - e, u.y + (num)(rng() % (uint64_t)(2 * e + 1)) - e,
                         u.z + (num)(rng() % (uint64_t)(2 * e + 1)) - e);
        vec3 a = v3_normalize_unit(u), b = v3_normalize_unit(w), c = v3_normalize_unit(v);
        vec3 a0 = v3_normalize(u), b0 = v3_normalize(w), c0 = v3_normalize(v);
        bad += a.x != a0.x || a.y != a0.y || a.z != a0.z;
        bad += b.x != b0.x || b.y != b0.y || b.z != b0.z;
        bad += c.x != c0.x || c.y != c0.y || c.z != c0.z;
    }
    check(bad == 0, "v3_normalize_unit_is_v3_normalize", "%ld differ", bad);
}
#else
/* --------------------------------------------------------- floating point */
#if NUM_MODE == NUM_MODE_FLOAT
static double ulp_of(double x)
{
    int e;
    if (x == 0) return ldexp(1, -149);
    frexp(x, &e);
    if (e < -125) e = -125;
    return ldexp(1, e - 24);
}
static double ferr(num r, double exact) { return fabs((double)r - exact) / ulp_of(exact); }
static double aerr(num r, double exact) { return fabs((double)r - exact) / ldexp(1, -24); }

static float rnd_f(void)
{
    int e = (int)(rng() % 40) - 20;
    float m = (float)((double)(rng() >> 11) * ldexp(1, -53));
    float v = ldexpf(1.0f + m, e);
    return (rng() & 1) ? -v : v;
}

static void acc_float(void)
{
    struct stat m = { "num_mul", "1M pairs, magnitudes 2^-20..2^20", "0.5", 0, 0, 0, 0, 0, 0 };
    struct stat d = { "num_div", "1M pairs, magnitudes 2^-20..2^20", "0.5", 0, 0, 0, 0, 0, 0 };
    struct stat r = { "num_recip", "1M, magnitudes 2^-20..2^20", "0.5", 0, 0, 0, 0, 0, 0 };
    struct stat q = { "num_sqrt", "1M, 2^-20..2^20", "0.5", 0, 0, 0, 0, 0, 0 };
    struct stat rq = { "num_rsqrt", "1M, 2^-20..2^20", "1.5", 0, 0, 0, 0, 0, 0 };
    for (long i = 0; i < 1000000; i++) {
        float a = rnd_f(), b = rnd_f();
        stat_add(&m, ferr(num_mul(a, b), (double)a * b), 0.5, a, b);
        stat_add(&d, ferr(num_div(a, b), (double)a / b), 0.5, a, b);
        stat_add(&r, ferr(num_recip(a), 1.0 / a), 0.5, a, 0);
        float p = fabsf(a);
        stat_add(&q, ferr(num_sqrt(p), sqrt((double)p)), 0.5, p, 0);
        stat_add(&rq, ferr(num_rsqrt(p), 1.0 / sqrt((double)p)), 1.5, p, 0);
    }
    stat_end(&m); stat_end(&d); stat_end(&r); stat_end(&q); stat_end(&rq);

    struct stat pw = { "num_powi", "e 1..1000, x in [-2, 2], 1M", "1", 0, 0, 0, 0, 0, 0 };
    for (long i = 0; i < 1000000; i++) {
        uint32_t e = 1 + (uint32_t)(rng() % 1000);
        float x = (float)((double)(rng() >> 11) * ldexp(1, -52)) - 1.0f;
        if (i & 1) x = 1.0f - (float)(rng() % 4096) * ldexpf(1, -24);
        double ex = pow((double)x, (double)e);
        if (fabs(ex) < FLT_MIN || fabs(ex) > FLT_MAX) continue;
        stat_add(&pw, ferr(num_powi(x, e), ex), 1, x, e);
    }
    stat_end(&pw);

    struct stat s = { "num_sin_deg", "1M angles in [-360, 360] (absolute, units 2^-24)", "24", 0, 0, 0, 0, 0, 0 };
    struct stat c = { "num_cos_deg", "1M angles in [-360, 360] (absolute, units 2^-24)", "24", 0, 0, 0, 0, 0, 0 };
    for (long i = 0; i < 1000000; i++) {
        float a = (float)((double)(rng() >> 11) * ldexp(1, -53) * 720.0 - 360.0);
        double rad = (double)a * 3.14159265358979323846 / 180;
        stat_add(&s, aerr(num_sin_deg(a), sin(rad)), 24, a, 0);
        stat_add(&c, aerr(num_cos_deg(a), cos(rad)), 24, a, 0);
    }
    stat_end(&s); stat_end(&c);

    struct stat n = { "v3_normalize", "1M vectors, magnitudes 2^-20..2^20 (abs., units 2^-24)", "4", 0, 0, 0, 0, 0, 0 };
    for (long i = 0; i < 1000000; i++) {
        vec3 v = v3_make(rnd_f(), rnd_f(), rnd_f());
        double x = v.x, y = v.y, z = v.z, len = sqrt(x * x + y * y + z * z);
        vec3 u = v3_normalize(v);
        stat_add(&n, aerr(u.x, x / len), 4, x, len);
        stat_add(&n, aerr(u.y, y / len), 4, y, len);
        stat_add(&n, aerr(u.z, z / len), 4, z, len);
    }
    stat_end(&n);
}

/* Conversions of the float build: num_from_double / num_to_double work on the
 * IEEE bits (no double arithmetic on a single-precision FPU); they must equal
 * the C conversions bit for bit. */
static void conversions_float(void)
{
    long bad = 0, bad2 = 0;
    const double sp[] = { 0.0, -0.0, 1.0, -1.5, 5e-324, -5e-324, 1e-46, 7e-46, 1.4e-45, 2.1e-45, 1.1754942e-38,
                          1.17549435e-38, 3.4028235e38, 3.4028236e38, 3.5e38, -3.5e38, 1e300, HUGE_VAL,
                          -HUGE_VAL, NAN, 16777217.0, 16777219.0, 0.1 };
    union { float f; uint32_t u; } a, b;
    for (long i = 0; i < 2000000 + (long)(sizeof sp / sizeof sp[0]); i++) {
        double d;
        if (i < (long)(sizeof sp / sizeof sp[0])) d = sp[i];
        else {
            union { double d; uint64_t u; } r;
            r.u = rng();
            /* mostly the float range and its edges, some anywhere */
            if (i & 3) r.u = (r.u & 0x800FFFFFFFFFFFFFull) | (uint64_t)(1023 - 160 + (int)(rng() % 300)) << 52;
            if ((i & 15) == 1) r.u &= ~(((uint64_t)1 << 29) - 1) | (uint64_t)1 << 28; /* ties */
            d = r.d;
        }
        a.f = num_from_double(d);
        b.f = (float)d;
        if (d != d ? a.f == a.f : a.u != b.u) bad++;
        a.u = (uint32_t)rng();
        double back = num_to_double(a.f);
        if (a.f == a.f ? !(back == (double)a.f && !signbit(back) == !signbit(a.f)) : back == back) bad2++;
    }
    check(bad == 0, "num_from_double_float_bits_match_c", "%ld mismatches", bad);
    check(bad2 == 0, "num_to_double_float_exact", "%ld mismatches", bad2);
    check(num_to_int(2147483648.0f) == INT32_MAX && num_to_int(2147483520.0f) == 2147483520 &&
              num_to_int(-2147483648.0f) == -INT32_MAX && num_to_int(-2147483520.0f) == -2147483520 &&
              num_to_int(NAN) == 0 && num_to_int(-1.75f) == -1 && num_floor_int(-1.25f) == -2 &&
              num_to_int(HUGE_VALF) == INT32_MAX && num_floor_int(-HUGE_VALF) == -INT32_MAX,
          "num_to_int_float_limits", "%d %d", num_to_int(2147483520.0f), num_floor_int(-1.25f));
}
#endif
#endif

static void edges_all(void)
{
    check(num_div(NUM_ONE, NUM_ZERO) == NUM_MAX && num_div(num_neg(NUM_ONE), NUM_ZERO) == NUM_MIN &&
              num_div(NUM_ZERO, NUM_ZERO) == NUM_ZERO,
          "num_div_by_zero_saturates", "");
    check(num_recip(NUM_ZERO) == NUM_MAX, "num_recip_zero_saturates", "");
    check(num_sqrt(num_neg(NUM_ONE)) == NUM_ZERO && num_sqrt(NUM_ZERO) == NUM_ZERO, "num_sqrt_nonpositive_is_zero", "");
    check(num_rsqrt(NUM_ZERO) == NUM_MAX && num_rsqrt(num_neg(NUM_ONE)) == NUM_MAX, "num_rsqrt_nonpositive_saturates", "");
    check(num_powi(NUM_C(0.5), 0) == NUM_ONE && num_powi(NUM_ZERO, 5) == NUM_ZERO &&
              num_powi(num_neg(NUM_ONE), 3) == num_neg(NUM_ONE) && num_powi(NUM_C(0.5), 2) == NUM_C(0.25),
          "num_powi_exact_cases", "");
    check(num_sin_deg(NUM_ZERO) == NUM_ZERO && num_sin_deg(NUM_C(90.0)) == NUM_ONE &&
              num_cos_deg(NUM_ZERO) == NUM_ONE && num_sin_deg(NUM_C(-90.0)) == num_neg(NUM_ONE) &&
              num_cos_deg(NUM_C(180.0)) == num_neg(NUM_ONE),
          "num_sincos_exact_angles", "%.9g %.9g", D(num_sin_deg(NUM_C(90.0))), D(num_cos_deg(NUM_C(180.0))));
    vec3 z = v3_normalize(v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
    check(z.x == NUM_ZERO && z.y == NUM_ZERO && z.z == NUM_ZERO, "v3_normalize_zero_stays_zero", "");
    check(num_clamp(NUM_C(2.0), NUM_ZERO, NUM_ONE) == NUM_ONE && num_min(NUM_ONE, NUM_ZERO) == NUM_ZERO &&
              num_max(NUM_ONE, NUM_ZERO) == NUM_ONE,
          "num_min_max_clamp", "");
    check(rgb_to_565(rgb_make(NUM_C(255.0), NUM_C(128.0), NUM_C(-3.0))) == (31u << 11 | 32u << 5),
          "rgb_to_565_contract_rounding", "%04x", rgb_to_565(rgb_make(NUM_C(255.0), NUM_C(128.0), NUM_C(-3.0))));
}

int main(int argc, char **argv)
{
    report = argc > 1 && strcmp(argv[1], "--report") == 0;
    if (!report) edges_all();
#if NUM_MODE == NUM_MODE_FIXED
    if (!report) {
        edges_fixed();
        conversions();
    }
    acc_mul();
    acc_div();
    acc_recip();
    acc_sqrt();
    acc_rsqrt();
    acc_powi();
    acc_sincos();
    acc_vec();
    acc_wide();
    acc_chan();
#elif NUM_MODE == NUM_MODE_FLOAT
    if (!report) conversions_float();
    acc_float();
#endif
    return check_exit();
}
