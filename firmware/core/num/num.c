/* SPDX-License-Identifier: MIT */
/* num.c — scalar operations of the fixed-point build (see num.h): the
 * division kernels, conversions, arithmetic and wide intermediates; the
 * powers and sines (which use the division kernel inline); the square
 * roots are num_sqrt.c's, the floating-point modes' operations
 * num_float.c's. */
#define NUM_NO_INLINE   /* the out-of-line definitions live here */
#include "num.h"

uint32_t num_saturations;

/* Leading zeros of a byte (num_clz32 without CLZ, every numeric mode: the
 * fast rasterizer's integer set-up uses it in the float builds too). */
#define CLZ2(v) v, v
#define CLZ4(v) CLZ2(v), CLZ2(v)
#define CLZ8(v) CLZ4(v), CLZ4(v)
#define CLZ16(v) CLZ8(v), CLZ8(v)
#define CLZ32(v) CLZ16(v), CLZ16(v)
#define CLZ64(v) CLZ32(v), CLZ32(v)
#define CLZ128(v) CLZ64(v), CLZ64(v)
const uint8_t num_clz8_tab[256] = { 8, 7, CLZ2(6), CLZ4(5), CLZ8(4), CLZ16(3), CLZ32(2), CLZ64(1), CLZ128(0) };

#if NUM_MODE == NUM_MODE_FIXED

#include "num_fix.h"


/* Conventions of this file:
 * - No '/' or '%' on 64-bit operands: ARMv6-M has no divide instruction and
 *   the compiler would call __aeabi_ldivmod. Divisions go through
 *   num_udiv64_32() (table + Newton-Raphson, exact).
 * - Right shifts of negative signed values are arithmetic (GCC and Clang
 *   define it so on every target built here), so results are the same bits
 *   on x86 and ARM.
 * - Conversions of out-of-range unsigned values to signed types are modular
 *   (same compilers, same guarantee). */

_Static_assert(NUM_FRAC >= 8 && NUM_FRAC <= 20, "NUM_FRAC must be in 8..20");

static num sat64(int64_t v)
{
    if (v > INT32_MAX) { SAT_HIT(); return NUM_MAX; }
    if (v < -(int64_t)INT32_MAX) { SAT_HIT(); return NUM_MIN; }
    return (num)v;
}

#define mul_round num_mul_round

/* ---- integer kernels (shared with vec.c through num_int.h) ----------- */

/* 256-entry seed of the reciprocal: entry i is (1/x - 1) * 2^16 at the centre
 * x of [1/2 + i/512, 1/2 + (i+1)/512), relative error <= 2^-9. The entries
 * are integer constant expressions: no floating-point code is emitted. */
#define RCP(i) (uint16_t)(65536.0 * (1.0 / (0.5 + ((i) + 0.5) / 512.0) - 1.0) + 0.5)
#define RCP4(i) RCP(i), RCP((i) + 1), RCP((i) + 2), RCP((i) + 3)
#define RCP16(i) RCP4(i), RCP4((i) + 4), RCP4((i) + 8), RCP4((i) + 12)
#define RCP64(i) RCP16(i), RCP16((i) + 16), RCP16((i) + 32), RCP16((i) + 48)

const uint16_t num_rcp_seed[256] = { RCP64(0), RCP64(64), RCP64(128), RCP64(192) };

static inline uint32_t rcp16(uint32_t dn)
{
    /* y0 = 2^16 + seed ~ 2^48 / dn (relative error <= 2^-9 + 2^-17), one
     * Newton-Raphson step y0 (2 - x y0) with x = (dn >> 9) / 2^39:
     * e0 = 2^39 - (dn >> 9) y0 has |e0| < 2^31, so it is exact as the low
     * word of the product (one 32x32->32 multiply). r = v - 2^32 with
     * v = y0 2^16 (1 + e0 / 2^39), kept halved (t = r / 2, below 2^31) so
     * that a slightly negative value near dn = 2^32 stays signed; the bias
     * 2^10 covers the truncation of dn (which can only raise the estimate),
     * so the result is from below. Newton's error (2^-18 relative) plus the
     * truncations stay below 2^17 units of r: tests/unit/test_num_div.c checks
     * both bounds on every value of dn >> 9 (the only bits used). */
    uint32_t sd = num_rcp_seed[(dn >> 23) & 0xFF];
    int32_t e0 = (int32_t)(0u - (dn >> 9) * (0x10000u + sd));
    int32_t t = (int32_t)(sd << 15) + (e0 >> 8) + (((int32_t)sd * (e0 >> 16)) >> 8) - 1024;
    return t < 0 ? 0 : (uint32_t)t >> 15;
}

uint32_t num_rcp16(uint32_t dn) { return rcp16(dn); }

/* num_rcp32's value before its last step (the remainder's correction):
 * v - 6 <= est <= v */
static inline uint32_t rcp32_est(uint32_t dn)
{
    /* V0 = 2^32 + rh 2^16 with 0 < 2^64 / dn - V0 < 2^17 (num_rcp16; V0 <
     * 2^33 = 2^64 / dn for dn = 2^31, so the difference is never 0), and
     * e = 2^64 - V0 dn: 0 < e < 2^17 dn, a multiple of 2^16. The result is
     * V0 - 2^32 + floor((e - 1) / dn).
     * Et = floor(e / 2^17) < dn from E = e / 2^16 = A 2^16 - B, A = (2^32 -
     * dn) - rh (dn >> 16) >= 0 and B = rh (dn & 0xFFFF) < 2^32 - 2^17: Et =
     * A 2^15 - ceil(B / 2), exact modulo 2^32 since Et < 2^32.
     * The quotient's estimate q = floor(Et V0 / 2^47) = floor(Et / 2^15 + Et
     * rh / 2^31) in two 16x16 pieces (each below 2^32, their sum too) and
     * two floors is at most Et 2^17 V0 / 2^64 <= e V0 / 2^64 < e / dn, so
     * at most floor((e - 1) / dn); it is below e / dn by at most
     * (e - Et 2^17) / dn < 2^-14, Et 2^17 (2^64 / dn - V0) / 2^64 < 2^49
     * 2^17 / 2^64 = 4 and the floors (< 2 + 2^-15): at most 6 below. The
     * remainder 2^64 - 1 - (2^32 + v) dn (< 7 dn < 2^35, in 32-bit halves)
     * then steps it up (num_rcp32). */
    const uint32_t rh = rcp16(dn);
    const uint32_t a = (0u - dn) - rh * (dn >> 16), b = rh * (dn & 0xFFFFu);
    const uint32_t et = (a << 15) - ((b >> 1) + (b & 1u));
    return (rh << 16) + (et >> 15) + (((et >> 16) * rh + (((et & 0xFFFFu) * rh) >> 16)) >> 15);
}

uint32_t num_rcp32_est(uint32_t dn) { return rcp32_est(dn); }

uint32_t num_rcp32(uint32_t dn)
{
    /* 2^64 - 1 - 2^32 dn = ~dn 2^32 + 2^32 - 1, divided by dn from the
     * estimate */
    uint32_t rl;
    return num_udiv_step(num_rcp32_est(dn), ~dn, 0xFFFFFFFFu, dn, &rl);
}

#if !NUM_HW_DIV32
/* One base-2^16 digit of x / dn: x < dn * 2^16 (so the digit is < 2^16),
 * dn in [2^31, 2^32), rh = num_rcp16(dn). The estimate xh (1 + rh / 2^16)
 * from the top 16 bits xh of x is never above the digit and at most 4
 * below it (x's dropped bits: < 1, rh's error < 2^17 / 2^16 = 2 units
 * times xh / 2^16 < 1, the floor: < 1, the low bits times rh: < 1); the
 * remainder then steps it up. Three 32x32->32 multiplies. */
static uint32_t div_digit(uint64_t x, uint32_t dn, uint32_t rh, uint32_t *rem)
{
    uint32_t xh = (uint32_t)(x >> 32);
    uint32_t q = xh + ((xh * rh) >> 16);
    uint64_t r = x - (((uint64_t)(q * (dn >> 16)) << 16) + q * (dn & 0xFFFFu)); /* < 5 dn */
    while (r >= dn) { r -= dn; q++; }
    *rem = (uint32_t)r;
    return q;
}
#else
/* One base-2^16 digit of x / dn with the 32-bit hardware divide: the
 * estimate (x >> 16) / (dn >> 16) (capped at 2^16 - 1) is never below the
 * digit and at most 2 above it for a normalised dn (the classic bound of
 * schoolbook division); the signed remainder steps it down. */
static uint32_t div_digit(uint64_t x, uint32_t dn, uint32_t rh, uint32_t *rem)
{
    (void)rh;
    uint32_t q = (uint32_t)(x >> 16) / (dn >> 16);
    if (q > 0xFFFFu) q = 0xFFFFu;
    int64_t r = (int64_t)x - (int64_t)((uint64_t)q * dn);  /* in [-2 dn, dn) */
    while (r < 0) { r += dn; q--; }
    *rem = (uint32_t)r;
    return q;
}
#endif

uint32_t num_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem)
{
    /* Schoolbook division in two base-2^16 digits by the normalised divisor
     * dn = d 2^s in [2^31, 2^32): N = n 2^s < dn 2^32, so N >> 16 < dn 2^16
     * gives the high digit, and (its remainder) 2^16 + the low 16 bits of
     * N the low one. Both remainders are below dn < 2^32. */
    int s = num_clz32(d);
    uint32_t dn = d << s, r;
    uint64_t nn = n << s;
    uint32_t rh = NUM_HW_DIV32 ? 0 : num_rcp16(dn);
    uint32_t qh = div_digit(nn >> 16, dn, rh, &r);
    uint32_t ql = div_digit((uint64_t)r << 16 | ((uint32_t)nn & 0xFFFFu), dn, rh, &r);
    if (rem) *rem = r >> s;
    return qh << 16 | ql;
}

/* n / d rounded to nearest (halves away from zero), with sign; d != 0. */
static num div_round_signed(uint64_t n, uint32_t d, int neg)
{
    if ((n >> 32) >= d) { SAT_HIT(); return neg ? NUM_MIN : NUM_MAX; } /* quotient >= 2^32 */
    uint32_t rm;
    uint64_t q = num_udiv64_32(n, d, &rm);
    if (rm >= d - rm) q++;
    return sat_signed(q, neg);
}

/* ---- conversions ------------------------------------------------------ */

num num_from_int(int32_t i)
{
    if (i > (INT32_MAX >> NUM_FRAC)) { SAT_HIT(); return NUM_MAX; }
    if (i < -(INT32_MAX >> NUM_FRAC)) { SAT_HIT(); return NUM_MIN; }
    return (num)((uint32_t)i << NUM_FRAC);
}

int32_t num_to_int(num a)
{
    uint32_t m = uabs32(a) >> NUM_FRAC;
    return a < 0 ? -(int32_t)m : (int32_t)m;
}

int32_t num_floor_int(num a) { return a >> NUM_FRAC; }
num num_frac(num a) { return a & (NUM_ONE_RAW - 1); }

num num_from_ratio(int32_t p, int32_t q)
{
    if (q == 0) return num_div(p, 0);
    /* |p| * 2^F < 2^51: fits the 64-bit numerator. */
    return div_round_signed((uint64_t)uabs32(p) << NUM_FRAC, uabs32(q), (p < 0) != (q < 0));
}

/* The two conversions from and to double work on the IEEE-754 binary64
 * bits with integer operations only, so the fixed build of the core emits no
 * floating-point code even though these host-side helpers are linked in. */
union num_dbits { double d; uint64_t u; };

num num_from_double(double d)
{
    /* raw = d * 2^F rounded half away from zero; |d * 2^F| >= INT32_MAX
     * saturates (and counts); NaN gives 0. */
    union num_dbits b;
    b.d = d;
    int neg = (int)(b.u >> 63);
    int e = (int)((b.u >> 52) & 0x7FF);
    uint64_t m = b.u & (((uint64_t)1 << 52) - 1);
    if (e == 0x7FF && m) return 0;                   /* NaN */
    if (e == 0) e = 1; else m |= (uint64_t)1 << 52;  /* subnormal / normal */
    int k = 1075 - NUM_FRAC - e;                      /* |raw| = m / 2^k */
    if (m == 0 || k >= 64) return 0;
    if (k <= 0) { SAT_HIT(); return neg ? NUM_MIN : NUM_MAX; } /* >= 2^52 */
    uint64_t q = m >> k;
    if (q >= (uint64_t)INT32_MAX) { SAT_HIT(); return neg ? NUM_MIN : NUM_MAX; }
    q += (m >> (k - 1)) & 1;
    return sat_signed(q, neg);
}

double num_to_double(num a)
{
    /* Exact: a 31-bit magnitude fits the 53-bit significand. */
    union num_dbits b;
    uint32_t u = uabs32(a);
    if (u == 0) return 0.0;
    int lz = num_clz32(u);
    uint64_t mant = ((uint64_t)u << (lz + 21)) & (((uint64_t)1 << 52) - 1);
    uint64_t exp = (uint64_t)(1023 + (31 - lz) - NUM_FRAC);
    b.u = (uint64_t)(a < 0) << 63 | exp << 52 | mant;
    return b.d;
}

/* ---- arithmetic ------------------------------------------------------- */

num num_add(num a, num b)
{
    int32_t r = (int32_t)((uint32_t)a + (uint32_t)b);
    if (((a ^ r) & (b ^ r)) < 0) { SAT_HIT(); return a < 0 ? NUM_MIN : NUM_MAX; }
    if (r == INT32_MIN) { SAT_HIT(); return NUM_MIN; }
    return r;
}

num num_sub(num a, num b)
{
    int32_t r = (int32_t)((uint32_t)a - (uint32_t)b);
    if (((a ^ b) & (a ^ r)) < 0) { SAT_HIT(); return a < 0 ? NUM_MIN : NUM_MAX; }
    if (r == INT32_MIN) { SAT_HIT(); return NUM_MIN; }
    return r;
}

num num_neg(num a)
{
    if (a == INT32_MIN) { SAT_HIT(); return NUM_MAX; }
    return -a;
}

num num_abs(num a)
{
    if (a == INT32_MIN) { SAT_HIT(); return NUM_MAX; }
    return a < 0 ? -a : a;
}

num num_mul(num a, num b)
{
    /* |a*b| <= 2^62: the exact product needs the 64-bit intermediate. */
    return sat64(mul_round(a, b));
}

num num_mul_int(num a, int32_t k) { return sat64(num_smul32(a, k)); }
num (num_mul_fit)(num a, num b) { return num_mul_round32(a, b); }
num (num_add_fit)(num a, num b) { return (num)((uint32_t)a + (uint32_t)b); }

num num_mul_int_mod(num a, int32_t k, num m)
{
    if (m <= 0) return NUM_ZERO;
    /* the exact 64-bit product, reduced by an exact division without a
     * software 64-bit divide: |result| < m. The quotient must fit 32 bits
     * (|a k| < m 2^32: always for an angle, m = 360 in any format and
     * |k| < 2^16); otherwise it saturates */
    int64_t p = num_smul32(a, k);
    uint64_t u = p < 0 ? (uint64_t)0 - (uint64_t)p : (uint64_t)p;
    if ((u >> 32) >= (uint64_t)(uint32_t)m) return p < 0 ? NUM_MIN : NUM_MAX;
    uint32_t r;
    (void)num_udiv64_32(u, (uint32_t)m, &r);
    return p < 0 ? -(num)r : (num)r;
}

num num_div(num a, num b)
{
    if (b == 0) {
        if (a == 0) return 0;
        SAT_HIT();
        return a > 0 ? NUM_MAX : NUM_MIN;
    }
    /* |a| * 2^F < 2^51: the scaled numerator needs 64 bits. */
    return div_round_signed((uint64_t)uabs32(a) << NUM_FRAC, uabs32(b), (a < 0) != (b < 0));
}

struct num_divisor num_divisor_make(num d)
{
    struct num_divisor v;
    v.d = d;
    v.ud = uabs32(d);
    v.fast = 0;
    v.k = 0;
    v.m = 0;
    if (v.ud >= (1u << (NUM_FRAC - 3))) {
        /* L = bit length of |d|; k = max(0, F + 2 - L) keeps m < 2^32 */
        int l = 32 - num_clz32(v.ud);
        int k = NUM_FRAC + 2 - l;
        if (k < 0) k = 0;
        v.k = (uint8_t)k;
        v.m = num_udiv64_32((uint64_t)1 << (NUM_FRAC + 32 - k), v.ud, 0);
        v.fast = 1;
    }
    return v;
}

num num_div_by(num a, const struct num_divisor *v)
{
    if (!v->fast) return num_div(a, v->d);
    uint32_t ua = uabs32(a), d = v->ud;
    uint64_t n = (uint64_t)ua << NUM_FRAC;
    int neg = (a < 0) != (v->d < 0);
    if ((n >> 32) >= d) { SAT_HIT(); return neg ? NUM_MIN : NUM_MAX; }   /* as div_round_signed */
    /* q <= floor(n / d) and at most 2^(k-1) + 1 below it (both floors);
     * the remainder steps it up */
    uint64_t p = num_umul32(ua, v->m);                 /* q < 2^32: 32-bit pieces */
    uint32_t q = v->k ? (uint32_t)(p >> 32) << v->k | (uint32_t)p >> (32 - v->k) : (uint32_t)(p >> 32);
    uint64_t rm = n - num_umul32(q, d);
    while (rm >= d) { rm -= d; q++; }
    if (rm >= d - rm) q++;
    return sat_signed(q, neg);
}

num num_div_int(num a, int32_t k)
{
    if (k == 0) return num_div(a, 0);
    return div_round_signed(uabs32(a), uabs32(k), (a < 0) != (k < 0));
}

num num_recip(num a) { return num_div(NUM_ONE, a); }

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

/* ---- wide intermediates ------------------------------------------------ */

#define WLIM (INT64_MAX / 4)

static int64_t wclamp(int64_t v)
{
    if (v > WLIM) { SAT_HIT(); return WLIM; }
    if (v < -WLIM) { SAT_HIT(); return -WLIM; }
    return v;
}

static uint64_t uabs64(int64_t a) { return a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a; }

wnum wnum_from_num(num a) { return a; }
num  wnum_to_num(wnum a) { return sat64(a); }
/* Operands are clamped to +-INT64_MAX/4 first, so the sum cannot overflow. */
wnum wnum_add(wnum a, wnum b) { return wclamp(wclamp(a) + wclamp(b)); }
wnum wnum_sub(wnum a, wnum b) { return wclamp(wclamp(a) - wclamp(b)); }

wnum wnum_mul(wnum a, wnum b)
{
    /* |a*b| >> F without a 128-bit product: split b = bh*2^F + bl. */
    int neg = (a < 0) != (b < 0);
    uint64_t ua = uabs64(a), ub = uabs64(b);
    uint64_t lim = (uint64_t)WLIM;
    if (((ua | ub) >> 32) == 0) {
        /* Both below 2^32 (the renderers' usual case): the split below sums
         * to ua bh + ((ua bl + 2^(F-1)) >> F) = (ua ub + 2^(F-1)) >> F (ua bh 2^F
         * is a multiple of 2^F), below 2^(64-F) <= 2^56 < lim: the same bits
         * from one 32x32 product, and nothing to saturate. */
        uint64_t r = (num_umul32((uint32_t)ua, (uint32_t)ub) + ((uint64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC;
        return neg ? -(int64_t)r : (int64_t)r;
    }
    uint64_t bh = ub >> NUM_FRAC, bl = ub & (((uint64_t)1 << NUM_FRAC) - 1);
    uint64_t hi = 0;
    if (bh && ua) {
        /* bit lengths: la + lb <= 61 keeps the product below 2^61 (<= lim);
         * la + lb >= 63 puts it at or above 2^61. */
        int l = (64 - num_clz64(ua)) + (64 - num_clz64(bh));
        if (l >= 63) { SAT_HIT(); return neg ? -(int64_t)lim : (int64_t)lim; }
        hi = ua * bh;
    }
    uint64_t lo;
    if (ua >= ((uint64_t)1 << (64 - NUM_FRAC))) lo = (ua >> NUM_FRAC) * bl;
    else lo = (ua * bl + ((uint64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC;
    uint64_t r = hi + lo;
    if (hi > lim || r > lim) { SAT_HIT(); r = lim; }
    return neg ? -(int64_t)r : (int64_t)r;
}

wnum num_mul_wide(num a, num b) { return mul_round(a, b); }

/* Dot and cross products: each product rounded as num_mul_wide, then summed.
 * Range: each rounded product is at most 2^54 + 1 in magnitude (F >= 8), so
 * a sum or difference of three stays below 2^56, far inside wnum_add's clamp
 * at +-INT64_MAX/4 = 2^61: the clamps of the generic form (wnum_add after
 * every product) can never act, and plain 64-bit sums give the same bits
 * (tests/unit/test_num_div.c compares both). Only the final conversion to num
 * saturates. */
wnum v3_dot_wide(vec3 a, vec3 b)
{
    return mul_round(a.x, b.x) + mul_round(a.y, b.y) + mul_round(a.z, b.z);
}

num v3_dot(vec3 a, vec3 b) { return sat64(v3_dot_wide(a, b)); }

vec3 v3_cross(vec3 a, vec3 b)
{
    return v3_make(sat64(mul_round(a.y, b.z) - mul_round(a.z, b.y)),
                   sat64(mul_round(a.z, b.x) - mul_round(a.x, b.z)),
              sat64(mul_round(a.x, b.y) - mul_round(a.y, b.x)));
}

num wnum_div(wnum a, wnum b)
{
    if (b == 0) {
        if (a == 0) return 0;
        SAT_HIT();
        return a > 0 ? NUM_MAX : NUM_MIN;
    }
    int neg = (a < 0) != (b < 0);
    uint64_t ua = uabs64(a), ub = uabs64(b);
    /* Fast path: the scaled numerator fits 64 bits and b fits 32. */
    if (ub <= UINT32_MAX && ua < ((uint64_t)1 << (63 - NUM_FRAC)))
        return div_round_signed(ua << NUM_FRAC, (uint32_t)ub, neg);
    /* General case: restoring division, one quotient bit per step. The
     * quotient must stay below 2^31: ua >> (31-F) >= ub means it would not. */
    if ((ua >> (31 - NUM_FRAC)) >= ub) { SAT_HIT(); return neg ? NUM_MIN : NUM_MAX; }
    uint64_t q = 0, r = ua;
    for (int i = 30 - NUM_FRAC; i >= 0; i--)
        if ((r >> i) >= ub) { r -= ub << i; q |= (uint64_t)1 << i; }
    /* r < ub <= 2^63: r << 1 cannot overflow. */
    for (int i = 0; i < NUM_FRAC; i++) {
        r <<= 1;
        q <<= 1;
        if (r >= ub) { r -= ub; q |= 1; }
    }
    if (r >= ub - r) q++;
    return sat_signed(q, neg);
}

num wnum_to_num_shr(wnum a, int bits)
{
    if (bits <= 0) return sat64(a);
    if (bits > 62) bits = 62;
    /* Rounded shift without forming a + 2^(bits-1) (could overflow). */
    return sat64((a >> bits) + ((a >> (bits - 1)) & 1));
}

#endif

num num_min(num a, num b) { return a < b ? a : b; }
num num_max(num a, num b) { return a > b ? a : b; }
num num_clamp(num a, num lo, num hi) { return a < lo ? lo : (a > hi ? hi : a); }

#if NUM_MODE == NUM_MODE_FIXED
uint32_t num_chan_levels(num c, uint32_t levels)
{
    if (c <= 0) return 0;
    if (c >= num_from_int(255)) return levels;
    /* exact: floor((c*L + 255*2^F/2) / (255*2^F)) = floor(x / 255) with
     * x = floor((c*L + 255*2^(F-1)) / 2^F) < 255*L + 128. */
    uint64_t x = (num_umul32((uint32_t)c, levels) + (uint64_t)255 * (NUM_ONE_RAW / 2)) >> NUM_FRAC;
    if (x < 65536) return ((uint32_t)x * 0x8081u) >> 23; /* = x/255 for every x < 2^16 */
    return num_udiv64_32(x, 255, 0);                          /* x < 255 * 2^32 */
}

uint8_t num_chan_byte(num c)
{
    if (c <= 0) return 0;
    if (c >= num_from_int(255)) return 255;
    uint32_t i = (uint32_t)c >> NUM_FRAC;
    uint32_t f = (uint32_t)c & (NUM_ONE_RAW - 1);
    uint32_t half = NUM_ONE_RAW / 2;
    if (f > half || (f == half && (i & 1u))) i++;
    return (uint8_t)i;
}
#endif
