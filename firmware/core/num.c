/* num.c — scalar operations for the three numeric modes (see num.h). */
#include "num.h"

uint32_t num_saturations;

#ifdef NUM_COUNT_SAT
#define SAT_HIT() (num_saturations++)
#else
#define SAT_HIT() ((void)0)
#endif

#if NUM_MODE == NUM_MODE_FIXED

#include "num_int.h"

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

/* Magnitude q with sign neg, saturated to [NUM_MIN, NUM_MAX]. */
static num sat_signed(uint64_t q, int neg)
{
    if (q > (uint64_t)INT32_MAX) { SAT_HIT(); return neg ? NUM_MIN : NUM_MAX; }
    return neg ? -(num)q : (num)q;
}

static uint32_t uabs32(int32_t a) { return a < 0 ? 0u - (uint32_t)a : (uint32_t)a; }

/* ---- integer kernels (shared with vec.c through num_int.h) ----------- */

/* 256-entry seed of the reciprocal: entry i is (1/x - 1) * 2^16 at the centre
 * x of [1/2 + i/512, 1/2 + (i+1)/512), relative error <= 2^-9. The entries
 * are integer constant expressions: no floating-point code is emitted. */
#define RCP(i) (uint16_t)(65536.0 * (1.0 / (0.5 + ((i) + 0.5) / 512.0) - 1.0) + 0.5)
#define RCP4(i) RCP(i), RCP((i) + 1), RCP((i) + 2), RCP((i) + 3)
#define RCP16(i) RCP4(i), RCP4((i) + 4), RCP4((i) + 8), RCP4((i) + 12)
#define RCP64(i) RCP16(i), RCP16((i) + 16), RCP16((i) + 32), RCP16((i) + 48)
static const uint16_t rcp_seed[256] = { RCP64(0), RCP64(64), RCP64(128), RCP64(192) };

/* One Newton-Raphson step for v = 2^32 + r ~ 2^64 / dn:
 * v' = v + v*e/2^64 with e = 2^64 - dn*v (|e| < 2^56 after the seed). */
static uint32_t rcp_step(uint32_t dn, uint32_t r)
{
    uint64_t a = (uint64_t)(0u - dn) << 32; /* (2^32 - dn) * 2^32, dn >= 2^31 */
    uint64_t b = num_umul32(dn, r);
    int64_t nr;
    if (a >= b) {
        uint32_t eh = (uint32_t)((a - b) >> 32);
        nr = (int64_t)r + eh + (int64_t)(num_umul32(r, eh) >> 32);
    } else {
        uint32_t eh = (uint32_t)((b - a) >> 32);
        nr = (int64_t)r - eh - (int64_t)(num_umul32(r, eh) >> 32);
    }
    if (nr < 0) return 0;
    if (nr > (int64_t)UINT32_MAX) return UINT32_MAX;
    return (uint32_t)nr;
}

uint32_t num_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem)
{
    /* Normalise d to dn in [2^31, 2^32); r ~ 2^64/dn - 2^32 from the seed
     * (2^-9) and two Newton steps (2^-18, then a few units of 2^-32). */
    int s = num_clz32(d);
    uint32_t dn = d << s;
    uint32_t r = (uint32_t)rcp_seed[(dn >> 23) & 0xFF] << 16;
    r = rcp_step(dn, r);
    r = rcp_step(dn, r);
    /* Quotient estimate from the high word of n*2^s (< dn*2^32 because
     * n < d*2^32): within a few units of the true quotient. */
    uint32_t nh = (uint32_t)((n << s) >> 32);
    uint64_t qe = (uint64_t)nh + (num_umul32(nh, r) >> 32);
    uint32_t q = qe > UINT32_MAX ? UINT32_MAX : (uint32_t)qe;
    /* Exact correction by the remainder. */
    uint64_t p = num_umul32(q, d);
    while (p > n) { q--; p -= d; }
    uint64_t rm = n - p;
    while (rm >= d) { rm -= d; q++; }
    if (rem) *rem = (uint32_t)rm;
    return q;
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

uint64_t num_isqrt64(uint64_t v, uint64_t *rem)
{
    /* Digit recurrence, one result bit per step (no division). */
    uint64_t r = 0, bit;
    int lz = num_clz64(v | 1);
    bit = (uint64_t)1 << ((63 - lz) & ~1);
    while (bit) {
        if (v >= r + bit) { v -= r + bit; r = (r >> 1) + bit; }
        else r >>= 1;
        bit >>= 2;
    }
    if (rem) *rem = v; /* v0 - r^2 */
    return r;
}

/* sqrt(v) rounded to nearest: r*r <= v < (r+1)^2 and v - r*r > r means
 * v > (r + 1/2)^2 (no ties between integers). */
static uint64_t isqrt64_round(uint64_t v)
{
    uint64_t rm, r = num_isqrt64(v, &rm);
    return rm > r ? r + 1 : r;
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
    int64_t p = num_smul32(a, b);
    return sat64((p + ((int64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC);
}

num num_mul_int(num a, int32_t k) { return sat64(num_smul32(a, k)); }

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

num num_div_int(num a, int32_t k)
{
    if (k == 0) return num_div(a, 0);
    return div_round_signed(uabs32(a), uabs32(k), (a < 0) != (k < 0));
}

num num_recip(num a) { return num_div(NUM_ONE, a); }

num num_sqrt(num a)
{
    if (a <= 0) {
        if (a < 0) SAT_HIT(); /* outside the domain: clamped to 0 */
        return 0;
    }
    /* a * 2^F < 2^51; the root < 2^26 always fits. */
    return (num)isqrt64_round((uint64_t)a << NUM_FRAC);
}

num num_rsqrt(num a)
{
    if (a <= 0) { SAT_HIT(); return NUM_MAX; }
    /* Result raw y = round(sqrt(2^(3F) / a)), a raw. Estimate it from a
     * 31-bit root of a normalised, then correct exactly: y is right when
     * a*(2y-1)^2 <= 2^(3F+2) < a*(2y+1)^2. Range: for y within a few units
     * of the root, a*(2y+1)^2 ~ 2^(3F+2) + 2^(1.5F+17.5) < 2^63 (F <= 20). */
    uint32_t a2 = (uint32_t)a;
    int g = 3 * NUM_FRAC;
    if (g & 1) { a2 <<= 1; g++; }            /* even power of two: sqrt exact */
    int e = (num_clz32(a2) + 30) >> 1;       /* a2 * 4^e in [2^60, 2^62) */
    uint64_t m = (uint64_t)a2 << (2 * e);
    uint32_t t = (uint32_t)num_isqrt64(m, 0); /* in [2^30, 2^31) */
    uint64_t y = num_udiv64_32((uint64_t)1 << (g / 2 + e), t, 0);
    const uint64_t k = (uint64_t)1 << (3 * NUM_FRAC + 2);
    uint64_t ua = (uint64_t)a;
    while (ua * ((2 * y + 1) * (2 * y + 1)) <= k) y++;
    while (y > 0 && ua * ((2 * y - 1) * (2 * y - 1)) > k) y--;
    return sat_signed(y, 0);
}

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

wnum num_mul_wide(num a, num b)
{
    int64_t p = num_smul32(a, b);
    return (p + ((int64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC;
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

wnum wnum_sqrt(wnum a)
{
    if (a <= 0) {
        if (a < 0) SAT_HIT();
        return 0;
    }
    uint64_t ua = (uint64_t)a;
    if (ua < ((uint64_t)1 << (64 - NUM_FRAC))) return (wnum)isqrt64_round(ua << NUM_FRAC);
    /* Large: sqrt(a*2^F) = sqrt(a*2^k) * 2^((F-k)/2) with k the largest
     * shift of the same parity as F that keeps a*2^k below 2^64. */
    int k = num_clz64(ua);
    if ((NUM_FRAC - k) & 1) k--;
    uint64_t r = k >= 0 ? isqrt64_round(ua << k) : isqrt64_round(ua >> -k);
    return (wnum)(r << ((NUM_FRAC - k) / 2));
}

num wnum_to_num_shr(wnum a, int bits)
{
    if (bits <= 0) return sat64(a);
    if (bits > 62) bits = 62;
    /* Rounded shift without forming a + 2^(bits-1) (could overflow). */
    return sat64((a >> bits) + ((a >> (bits - 1)) & 1));
}

#else /* floating-point modes */

#include <math.h>

#if NUM_MODE == NUM_MODE_FLOAT
#define F(x) x##f
#else
#define F(x) x
#endif

/* Every constant below is written in the mode's own type (F(2147483648.0)
 * is a float literal in the float build): a double constant would promote
 * the comparison to double, which a single-precision FPU (Cortex-M4F) runs
 * in software (__aeabi_dcmpge, __aeabi_f2d). */
num num_from_int(int32_t i) { return (num)i; }
int32_t num_to_int(num a)
{
    /* Truncation toward zero; NaN gives 0; a >= 2^31 gives INT32_MAX and
     * a <= -2^31 gives -INT32_MAX (2^31 is exact in both types; every value
     * strictly between converts without overflow). */
    if (a != a) return 0;
    if (a >= F(2147483648.0)) return INT32_MAX;
    if (a <= F(-2147483648.0)) return -INT32_MAX;
    return (int32_t)a;
}
int32_t num_floor_int(num a) { return num_to_int(F(floor)(a)); }
num num_frac(num a) { return a - F(floor)(a); }
num num_from_ratio(int32_t p, int32_t q) { return q ? (num)p / (num)q : num_div((num)p, 0); }
#if NUM_MODE == NUM_MODE_FLOAT
/* The two double conversions of the float build work on the IEEE-754 bits
 * with integer operations (same results as the C conversions: round to
 * nearest even, overflow to infinity, NaN kept), so the float core contains
 * no double-precision arithmetic even where doubles are declared. */
union num_dbits { double d; uint64_t u; };
union num_fbits { float f; uint32_t u; };

num num_from_double(double d)
{
    union num_dbits b;
    union num_fbits r;
    b.d = d;
    uint32_t sign = (uint32_t)(b.u >> 32) & 0x80000000u;
    int e = (int)((b.u >> 52) & 0x7FF);
    uint64_t m = b.u & (((uint64_t)1 << 52) - 1);
    if (e == 0x7FF) {                                  /* infinity or NaN */
        r.u = sign | 0x7F800000u | (m ? 0x00400000u | (uint32_t)(m >> 29) : 0);
        return r.f;
    }
    int fe = e - 1023 + 127;                           /* float exponent field */
    if (fe >= 255) { r.u = sign | 0x7F800000u; return r.f; }
    int sh;                                            /* bits of m dropped */
    if (fe >= 1) {
        sh = 29;
    } else {                                           /* float subnormal or 0 */
        if (e == 0 || fe < -24) { r.u = sign; return r.f; } /* < 2^-150: rounds to 0 */
        m |= (uint64_t)1 << 52;
        sh = 30 - fe;                                  /* 30..54 */
        fe = 0;
    }
    uint64_t keep = m >> sh, rest = m & (((uint64_t)1 << sh) - 1), half = (uint64_t)1 << (sh - 1);
    uint32_t bits = ((uint32_t)fe << 23) + (uint32_t)keep;
    if (rest > half || (rest == half && (keep & 1))) bits++; /* a carry moves into the exponent */
    r.u = sign | bits;
    return r.f;
}

double num_to_double(num a)
{
    /* Exact: every float is a double. */
    union num_fbits f;
    union num_dbits b;
    f.f = a;
    uint64_t sign = (uint64_t)(f.u >> 31) << 63;
    int e = (int)((f.u >> 23) & 0xFF);
    uint64_t m = f.u & 0x7FFFFFu;
    if (e == 0xFF) b.u = sign | (uint64_t)0x7FF << 52 | m << 29;
    else if (e != 0) b.u = sign | (uint64_t)(e - 127 + 1023) << 52 | m << 29;
    else if (m == 0) b.u = sign;
    else {                                             /* subnormal: normalise */
        int s = 0;
        while (!(m & 0x800000u)) { m <<= 1; s++; }
        b.u = sign | (uint64_t)(1 - 127 - s + 1023) << 52 | (m & 0x7FFFFFu) << 29;
    }
    return b.d;
}
#else
num num_from_double(double d) { return d; }
double num_to_double(num a) { return a; }
#endif
num num_add(num a, num b) { return a + b; }
num num_sub(num a, num b) { return a - b; }
num num_neg(num a) { return -a; }
num num_abs(num a) { return F(fabs)(a); }
num num_mul(num a, num b) { return a * b; }
num num_mul_int(num a, int32_t k) { return a * (num)k; }
num num_div(num a, num b)
{
    if (b == 0) {
        if (a == 0) return 0;
        SAT_HIT();
        return a > 0 ? NUM_MAX : NUM_MIN;
    }
    return a / b;
}
num num_div_int(num a, int32_t k) { return num_div(a, (num)k); }
num num_recip(num a) { return num_div(1, a); }
num num_sqrt(num a) { return a <= 0 ? 0 : F(sqrt)(a); }
num num_rsqrt(num a) { return a <= 0 ? NUM_MAX : 1 / F(sqrt)(a); }
num num_powi(num base, uint32_t e) { return F(pow)(base, (num)e); }
num num_sin_deg(num deg) { return F(sin)(deg * (num)3.14159265358979323846 / 180); }
num num_cos_deg(num deg) { return F(cos)(deg * (num)3.14159265358979323846 / 180); }
wnum wnum_from_num(num a) { return a; }
num  wnum_to_num(wnum a) { return a; }
wnum wnum_add(wnum a, wnum b) { return a + b; }
wnum wnum_sub(wnum a, wnum b) { return a - b; }
wnum wnum_mul(wnum a, wnum b) { return a * b; }
wnum num_mul_wide(num a, num b) { return a * b; }
num  wnum_div(wnum a, wnum b) { return num_div(a, b); }
wnum wnum_sqrt(wnum a) { return a <= 0 ? 0 : F(sqrt)(a); }
num  wnum_to_num_shr(wnum a, int bits) { return F(ldexp)(a, -bits); }

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
#else
uint32_t num_chan_levels(num c, uint32_t levels)
{
    if (!(c > 0)) return 0;
    if (c >= 255) return levels;
    return (uint32_t)F(floor)(c * (num)levels / 255 + (num)0.5);
}

uint8_t num_chan_byte(num c)
{
    if (!(c > 0)) return 0;
    if (c >= 255) return 255;
    return (uint8_t)F(rint)(c);
}
#endif

/* ---- vector length and normalisation (mode-dependent accuracy) ------- */

#if NUM_MODE == NUM_MODE_FIXED

/* Pre-scale: components shifted so the largest magnitude lies in
 * [2^29, 2^30); the sum of squares is then exact and < 3 * 2^60.
 * Returns the left shift (-1 when the largest is >= 2^30: one bit dropped). */
static int prescale(vec3 a, uint32_t u[3])
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

static uint64_t sumsq(const uint32_t u[3])
{
    return num_umul32(u[0], u[0]) + num_umul32(u[1], u[1]) + num_umul32(u[2], u[2]);
}

num v3_len(vec3 a)
{
    uint32_t u[3];
    int sh = prescale(a, u);
    if (sh < 0) {
        /* Largest >= 2^30: the unscaled squares (each <= 2^62) still sum
         * below 3 * 2^62 < 2^64, so use them directly. */
        u[0] = uabs32(a.x);
        u[1] = uabs32(a.y);
        u[2] = uabs32(a.z);
    }
    uint64_t rm, s = sumsq(u);
    uint64_t l = num_isqrt64(s, &rm);            /* < 2^32 */
    if (sh > 0) return (num)((l + ((uint64_t)1 << (sh - 1))) >> sh); /* rounds sqrt(s)/2^sh */
    if (rm > l) l++;                              /* rounds sqrt(s) */
    if (l > (uint64_t)INT32_MAX) { SAT_HIT(); return NUM_MAX; }
    return (num)l;
}

vec3 v3_normalize(vec3 a)
{
    uint32_t u[3];
    if (a.x == 0 && a.y == 0 && a.z == 0) return a;
    prescale(a, u);
    uint64_t rm, s = sumsq(u);
    uint64_t l = num_isqrt64(s, &rm);
    if (rm > l) l++;                              /* L in [2^29, 2^31) */
    /* R = floor(2^60 / L) in (2^29, 2^31]; component = u * R / 2^(60-F),
     * u < 2^30 so the product < 2^61. Error < 0.51 ulp. */
    uint32_t r = num_udiv64_32((uint64_t)1 << 60, (uint32_t)l, 0);
    num c[3];
    const num *in[3] = { &a.x, &a.y, &a.z };
    for (int i = 0; i < 3; i++) {
        uint64_t p = num_umul32(u[i], r); /* u < 2^30, r <= 2^31 */
        num m = (num)((p + ((uint64_t)1 << (59 - NUM_FRAC))) >> (60 - NUM_FRAC));
        c[i] = *in[i] < 0 ? -m : m;
    }
    return v3(c[0], c[1], c[2]);
}

#else /* floating point: the book's formulas, unchanged */

num v3_len(vec3 a) { return num_sqrt(v3_dot(a, a)); }

vec3 v3_normalize(vec3 a)
{
    num len = v3_len(a);
    if (len == 0) return v3(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    return v3(num_div(a.x, len), num_div(a.y, len), num_div(a.z, len));
}

#endif
