/* SPDX-License-Identifier: MIT */
/* num.c — scalar operations for the three numeric modes (see num.h). */
#define NUM_NO_INLINE   /* the out-of-line definitions live here */
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

#define mul_round num_mul_round

/* ---- integer kernels (shared with vec.c through num_int.h) ----------- */

/* 256-entry seed of the reciprocal: entry i is (1/x - 1) * 2^16 at the centre
 * x of [1/2 + i/512, 1/2 + (i+1)/512), relative error <= 2^-9. The entries
 * are integer constant expressions: no floating-point code is emitted. */
#define RCP(i) (uint16_t)(65536.0 * (1.0 / (0.5 + ((i) + 0.5) / 512.0) - 1.0) + 0.5)
#define RCP4(i) RCP(i), RCP((i) + 1), RCP((i) + 2), RCP((i) + 3)
#define RCP16(i) RCP4(i), RCP4((i) + 4), RCP4((i) + 8), RCP4((i) + 12)
#define RCP64(i) RCP16(i), RCP16((i) + 16), RCP16((i) + 32), RCP16((i) + 48)
#define CLZ2(v) v, v
#define CLZ4(v) CLZ2(v), CLZ2(v)
#define CLZ8(v) CLZ4(v), CLZ4(v)
#define CLZ16(v) CLZ8(v), CLZ8(v)
#define CLZ32(v) CLZ16(v), CLZ16(v)
#define CLZ64(v) CLZ32(v), CLZ32(v)
#define CLZ128(v) CLZ64(v), CLZ64(v)
const uint8_t num_clz8_tab[256] = { 8, 7, CLZ2(6), CLZ4(5), CLZ8(4), CLZ16(3), CLZ32(2), CLZ64(1), CLZ128(0) };

static const uint16_t rcp_seed[256] = { RCP64(0), RCP64(64), RCP64(128), RCP64(192) };

uint32_t num_rcp16(uint32_t dn)
{
    /* y0 = 2^16 + seed ~ 2^48 / dn (relative error <= 2^-9 + 2^-17), one
     * Newton-Raphson step y0 (2 - x y0) with x = (dn >> 9) / 2^39:
     * e0 = 2^39 - (dn >> 9) y0 has |e0| < 2^31, so it is exact as the low
     * word of the product (one 32x32->32 multiply). r = v - 2^32 with
     * v = y0 2^16 (1 + e0 / 2^39), kept halved (t = r / 2, below 2^31) so
     * that a slightly negative value near dn = 2^32 stays signed; the bias
     * 2^10 covers the truncation of dn (which can only raise the estimate),
     * so the result is from below. Newton's error (2^-18 relative) plus the
     * truncations stay below 2^17 units of r: tests/test_num_div.c checks
     * both bounds on every value of dn >> 9 (the only bits used). */
    uint32_t sd = rcp_seed[(dn >> 23) & 0xFF];
    int32_t e0 = (int32_t)(0u - (dn >> 9) * (0x10000u + sd));
    int32_t t = (int32_t)(sd << 15) + (e0 >> 8) + (((int32_t)sd * (e0 >> 16)) >> 8) - 1024;
    return t < 0 ? 0 : (uint32_t)t >> 15;
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

/* ---- square roots ------------------------------------------------------
 * Every root comes from one estimate: for x in [2^62, 2^64), u = x / 2^64,
 * a 384-entry seed of 1/sqrt(u) (entry j - 128 is 2^16 / (sqrt(j/512) +
 * sqrt((j+1)/512)), the best constant on [j/512, (j+1)/512): relative error
 * <= 2^-9), one Newton-Raphson step y' = y (3 - u y^2) / 2 (2^-17.4), a root
 * x * y and one Newton step on the root (within 2 units of sqrt(x)); then an
 * exact integer correction. Only 32x32 products (four MULS on ARMv6-M). The
 * table and the bounds are checked by tests/test_num_kernels.c. */
static const uint16_t rsqrt_seed[384] = {
    65408, 65155, 64905, 64658, 64414, 64172, 63933, 63697, 63463, 63232, 63003, 62777,
    62553, 62331, 62112, 61896, 61681, 61469, 61259, 61051, 60845, 60641, 60439, 60239,
    60041, 59845, 59651, 59459, 59269, 59081, 58894, 58709, 58526, 58344, 58165, 57986,
    57810, 57635, 57462, 57290, 57120, 56951, 56784, 56618, 56453, 56291, 56129, 55969,
    55810, 55653, 55497, 55342, 55188, 55036, 54885, 54735, 54587, 54439, 54293, 54148,
    54004, 53862, 53720, 53580, 53440, 53302, 53165, 53029, 52894, 52760, 52627, 52495,
    52363, 52233, 52104, 51976, 51849, 51722, 51597, 51473, 51349, 51226, 51105, 50984,
    50863, 50744, 50626, 50508, 50391, 50275, 50160, 50046, 49932, 49819, 49707, 49596,
    49485, 49376, 49266, 49158, 49050, 48943, 48837, 48731, 48627, 48522, 48419, 48316,
    48214, 48112, 48011, 47911, 47811, 47712, 47613, 47516, 47418, 47322, 47226, 47130,
    47035, 46941, 46847, 46754, 46661, 46569, 46477, 46386, 46296, 46206, 46116, 46027,
    45939, 45851, 45764, 45677, 45590, 45504, 45419, 45334, 45249, 45165, 45082, 44999,
    44916, 44834, 44752, 44671, 44590, 44510, 44430, 44350, 44271, 44192, 44114, 44036,
    43959, 43882, 43805, 43729, 43653, 43577, 43502, 43428, 43353, 43279, 43206, 43133,
    43060, 42987, 42915, 42844, 42772, 42701, 42631, 42560, 42490, 42421, 42352, 42283,
    42214, 42146, 42078, 42010, 41943, 41876, 41809, 41743, 41677, 41611, 41546, 41481,
    41416, 41352, 41288, 41224, 41160, 41097, 41034, 40971, 40909, 40847, 40785, 40723,
    40662, 40601, 40540, 40480, 40420, 40360, 40300, 40241, 40182, 40123, 40064, 40006,
    39948, 39890, 39832, 39775, 39718, 39661, 39604, 39548, 39492, 39436, 39380, 39325,
    39269, 39215, 39160, 39105, 39051, 38997, 38943, 38890, 38836, 38783, 38730, 38677,
    38625, 38573, 38520, 38469, 38417, 38365, 38314, 38263, 38212, 38162, 38111, 38061,
    38011, 37961, 37911, 37862, 37813, 37764, 37715, 37666, 37617, 37569, 37521, 37473,
    37425, 37378, 37330, 37283, 37236, 37189, 37142, 37096, 37050, 37003, 36957, 36912,
    36866, 36820, 36775, 36730, 36685, 36640, 36596, 36551, 36507, 36463, 36419, 36375,
    36331, 36287, 36244, 36201, 36158, 36115, 36072, 36030, 35987, 35945, 35903, 35861,
    35819, 35777, 35735, 35694, 35653, 35612, 35571, 35530, 35489, 35448, 35408, 35368,
    35327, 35287, 35248, 35208, 35168, 35129, 35089, 35050, 35011, 34972, 34933, 34894,
    34856, 34817, 34779, 34741, 34703, 34665, 34627, 34589, 34552, 34514, 34477, 34440,
    34403, 34366, 34329, 34292, 34255, 34219, 34183, 34146, 34110, 34074, 34038, 34002,
    33967, 33931, 33896, 33860, 33825, 33790, 33755, 33720, 33685, 33650, 33616, 33581,
    33547, 33513, 33478, 33444, 33410, 33377, 33343, 33309, 33276, 33242, 33209, 33175,
    33142, 33109, 33076, 33043, 33011, 32978, 32945, 32913, 32881, 32848, 32816, 32784,
};

uint32_t num_rsqrt_q30(uint32_t xh)
{
    uint32_t y = rsqrt_seed[(xh >> 23) - 128];  /* Q15, in (2^15, 2^16) */
    uint32_t w = num_mulhi32(xh, y * y);        /* u y^2, Q30: 2^30 (1 +- 2^-8) */
    return num_mulhi32(y << 16, 0xC0000000u - w);
}

/* sqrt(x) for x in [2^62, 2^64) given xh = x >> 32 and xm = x >> 20 mod
 * 2^32: r = sqrt(x) / 2^10 from x * y (22 bits, relative error < 2^-17, so
 * |r^2 - x / 2^20| < 2^23 * 2^5 = 2^28: the residual is exact in 32-bit
 * arithmetic mod 2^32), then one Newton step r + residual / (2 sqrt(x / 2^20)),
 * with 1 / (2 sqrt(x / 2^20)) = y / 2^53, scaled by 2^10: within 2 units
 * (the dropped low 20 bits of x move the root by < 2^-11). */
static uint32_t sqrt_core(uint32_t xh, uint32_t xm, uint32_t *ry)
{
    uint32_t y = num_rsqrt_q30(xh);
    uint32_t r = num_mulhi32(xh, y) >> 8;
    int32_t e = (int32_t)(xm - r * r);
    uint32_t c = num_mulhi32((e < 0 ? 0u - (uint32_t)e : (uint32_t)e) << 3, y) >> 14;
    *ry = y;
    return e < 0 ? (r << 10) - c : (r << 10) + c;
}

uint32_t num_sqrt_est(uint64_t v, int *k, uint32_t *ry)
{
    uint32_t hi = (uint32_t)(v >> 32), y;
    int s = (hi ? num_clz32(hi) : 32 + num_clz32((uint32_t)v)) & ~1;
    uint64_t x = v << s;                         /* in [2^62, 2^64) */
    uint32_t r = sqrt_core((uint32_t)(x >> 32), (uint32_t)(x >> 20), &y);
    *k = s >> 1;
    if (ry) *ry = y;
    return r;
}

uint32_t num_sqrt_est32(uint32_t xh)
{
    uint32_t y;
    return sqrt_core(xh, xh << 12, &y);
}

/* floor(sqrt(v)) from an estimate e of floor(sqrt(v)) (a few units off at
 * most): stepped exactly with (r+1)^2 = r^2 + 2r + 1; *rem = v - root^2. */
static uint32_t isqrt_fix(uint64_t v, uint32_t r, uint64_t *rem)
{
    uint64_t p = num_umul32(r, r);
    while (p > v) { r--; p -= 2 * (uint64_t)r + 1; }
    while (v - p > 2 * (uint64_t)r) { p += 2 * (uint64_t)r + 1; r++; }
    if (rem) *rem = v - p;
    return r;
}

uint64_t num_isqrt64(uint64_t v, uint64_t *rem)
{
    if (v == 0) { if (rem) *rem = 0; return 0; }
    int k;
    uint32_t r = num_sqrt_est(v, &k, 0);
    return isqrt_fix(v, r >> k, rem);
}

/* sqrt(v) rounded to nearest, i.e. floor(sqrt(v) + 1/2) (no ties between
 * integers): from the estimate when it has k >= 4 fraction bits and lies
 * more than 4/2^k away from a rounding boundary (its error is < 2/2^k),
 * otherwise r*r <= v < (r+1)^2 and v - r*r > r means v > (r + 1/2)^2. */
static uint64_t isqrt64_round(uint64_t v)
{
    if (v == 0) return 0;
    int k;
    uint32_t e = num_sqrt_est(v, &k, 0);
    if (k >= 4) {
        uint64_t t = (uint64_t)e + ((uint64_t)1 << (k - 1));
        uint32_t f = (uint32_t)t & ((1u << k) - 1);
        if (f >= 4 && f <= (1u << k) - 4) return t >> k;
    }
    uint64_t rm, r = isqrt_fix(v, e >> k, &rm);
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

num num_sqrt(num a)
{
    if (a <= 0) {
        if (a < 0) SAT_HIT(); /* outside the domain: clamped to 0 */
        return 0;
    }
    /* z = sqrt(a 2^F) = sqrt(a2 2^G), G = F or F - 1 even (a2 = a or 2a);
     * xh = a2 4^e in [2^30, 2^32): z = num_sqrt_est32(xh) / 2^sh with
     * sh = 16 + e - G/2 >= 6 (F <= 20), estimate error < 2 units. Rounded
     * from the estimate unless within 4 units of a rounding boundary. */
    uint32_t a2 = (uint32_t)a;
    int gh = NUM_FRAC / 2;
    if (NUM_FRAC & 1) a2 <<= 1;
    int s = num_clz32(a2) & ~1;
    int sh = 16 + s / 2 - gh;
    uint64_t t = (uint64_t)num_sqrt_est32(a2 << s) + ((uint64_t)1 << (sh - 1));
    uint32_t f = (uint32_t)t & ((1u << sh) - 1);
    if (f >= 4 && f <= (1u << sh) - 4) return (num)(t >> sh);
    /* a * 2^F < 2^51; the root < 2^26 always fits. */
    return (num)isqrt64_round((uint64_t)a << NUM_FRAC);
}

/* a * m^2 <= 2^(3F+2)? For m = 2y +- 1 within a few units of the exact
 * 2 sqrt(2^(3F)/a), a*m ~ 2^(1.5F+1) sqrt(a) < 2^48 and a*m^2 ~ 2^(3F+2)
 * <= 2^62, so the 64-bit pieces below cannot overflow. */
static int rsqrt_le(uint32_t a, uint32_t m)
{
    uint64_t p = num_umul32(a, m);
    uint64_t q = num_umul32((uint32_t)p, m) + ((uint64_t)((uint32_t)(p >> 32) * m) << 32);
    return q <= (uint64_t)1 << (3 * NUM_FRAC + 2);
}

num num_rsqrt(num a)
{
    if (a <= 0) { SAT_HIT(); return NUM_MAX; }
    /* Result raw y = round(z), z = sqrt(2^(3F) / a) = 2^(g/2) / sqrt(a2)
     * (a2 = a or 2a so that g = 3F or 3F+1 is even). With xh = a2 * 4^e in
     * [2^30, 2^32), num_rsqrt_q30(xh) = 2^(46 - e) / sqrt(a2), so
     * z = y30 / 2^sh, sh = 46 - g/2 - e. One Newton step gives y30 within
     * 2^-17 (enough when sh >= 17), a second one within 2^-27. The estimate
     * decides when it is farther than its error bound from a rounding
     * boundary; otherwise the exact test a(2y-1)^2 <= 2^(3F+2) < a(2y+1)^2. */
    uint32_t a2 = (uint32_t)a;
    int g = 3 * NUM_FRAC;
    if (g & 1) { a2 <<= 1; g++; }
    int s = num_clz32(a2) & ~1;
    uint32_t xh = a2 << s;
    uint32_t y = num_rsqrt_q30(xh);
    int sh = 46 - g / 2 - s / 2;
    uint32_t margin = 1u << 15;                  /* > 2^31 * 2^-17, in units of y */
    if (sh < 17) {
        /* y += y (1 - u y^2) / 2: h = (1 - u y^2) 2^28, |h| < 2^13. */
        uint32_t w = num_mulhi32(xh, num_mulhi32(y, y));
        if (w <= (1u << 28)) y += num_mulhi32(y, ((1u << 28) - w) << 3);
        else y -= num_mulhi32(y, (w - (1u << 28)) << 3);
        margin = 16;                             /* > 2^31 * 2^-28 + truncations */
    }
    /* sh in [1, 34] for F in 8..20 (g/2 in 12..30, s/2 in 0..15) */
    uint64_t t = (uint64_t)y + ((uint64_t)1 << (sh - 1));
    uint64_t f = t & (((uint64_t)1 << sh) - 1);
    if (f >= margin && f <= ((uint64_t)1 << sh) - margin) return (num)(t >> sh);
    uint32_t ua = (uint32_t)a, yy = (uint32_t)(t >> sh);
    while (rsqrt_le(ua, 2 * yy + 1)) yy++;
    while (yy > 0 && !rsqrt_le(ua, 2 * yy - 1)) yy--;
    return sat_signed(yy, 0);
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
 * (tests/test_num_div.c compares both). Only the final conversion to num
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
num num_mul_fit(num a, num b) { return a * b; }
num num_add_fit(num a, num b) { return a + b; }
num num_mul_int_mod(num a, int32_t k, num m)
{
    if (m <= 0) return 0;
    /* the product in the mode's precision, reduced */
    return F(fmod)(a * (num)k, m);
}
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
struct num_divisor num_divisor_make(num d) { struct num_divisor v; v.d = d; return v; }
num num_div_by(num a, const struct num_divisor *v) { return num_div(a, v->d); }
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

/* The book's operand order, x, y, z left to right (no contraction). */
wnum v3_dot_wide(vec3 a, vec3 b)
{
    wnum s = num_mul_wide(a.x, b.x);
    s = wnum_add(s, num_mul_wide(a.y, b.y));
    return wnum_add(s, num_mul_wide(a.z, b.z));
}

num v3_dot(vec3 a, vec3 b) { return wnum_to_num(v3_dot_wide(a, b)); }

vec3 v3_cross(vec3 a, vec3 b)
{
    return v3_make(wnum_to_num(wnum_sub(num_mul_wide(a.y, b.z), num_mul_wide(a.z, b.y))),
                   wnum_to_num(wnum_sub(num_mul_wide(a.z, b.x), num_mul_wide(a.x, b.z))),
              wnum_to_num(wnum_sub(num_mul_wide(a.x, b.y), num_mul_wide(a.y, b.x))));
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
    if (s == 0) return 0;
    int k;
    uint32_t e = num_sqrt_est(s, &k, 0);         /* sqrt(s) 2^k within 2 */
    if (sh > 0) {
        /* floor(sqrt(s)) / 2^sh rounded half up. floor(sqrt(s)) 2^k lies in
         * (e - 2 - 2^k, e + 2]: decided by the estimate when its fraction
         * below 2^(k+sh) is that far from the rounding boundary. */
        int kk = k + sh;
        if (kk < 32) {
            uint64_t t = (uint64_t)e + ((uint64_t)1 << (kk - 1));
            uint32_t f = (uint32_t)t & ((1u << kk) - 1);
            if (f >= (1u << k) + 3 && f <= (1u << kk) - 3) return (num)(t >> kk);
        }
    }
    uint64_t l = isqrt_fix(s, e >> k, &rm);      /* floor(sqrt(s)) < 2^32 */
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
    uint64_t s = sumsq(u);                       /* in [2^58, 3 * 2^60) */
    int k;
    uint32_t y, e = num_sqrt_est(s, &k, &y);     /* k = 1 or 2 */
    uint64_t rm;
    uint32_t l = isqrt_fix(s, e >> k, &rm);
    if (rm > l) l++;                             /* L = round(sqrt(s)) in [2^29, 2^31) */
    /* R = floor(2^60 / L) in (2^29, 2^31]: estimate 2^60 / sqrt(s) = y * 2^(k-2)
     * (relative error < 2^-17 + 2^-30), one Newton step R += R (2^60 - L R) / 2^60
     * (|2^60 - L R| < 2^44, so its >> 12 fits 32 bits; error then a few units),
     * exact correction by the remainder. */
    uint32_t r = y >> (2 - k);
    const uint64_t one = (uint64_t)1 << 60;
    uint64_t p = num_umul32(l, r);
    if (p <= one) r += num_mulhi32(r, (uint32_t)((one - p) >> 12)) >> 16;
    else r -= num_mulhi32(r, (uint32_t)((p - one) >> 12)) >> 16;
    p = num_umul32(l, r);
    while (p > one) { r--; p -= l; }
    while (one - p >= l) { r++; p += l; }
    /* Component = u * R / 2^(60-F) rounded; u < 2^30, R <= 2^31: the
     * product < 2^61. Error < 0.51 ulp. */
    num c[3];
    const num *in[3] = { &a.x, &a.y, &a.z };
    for (int i = 0; i < 3; i++) {
        uint64_t q = num_umul32(u[i], r);
        num m = (num)((q + ((uint64_t)1 << (59 - NUM_FRAC))) >> (60 - NUM_FRAC));
        c[i] = *in[i] < 0 ? -m : m;
    }
    return v3_make(c[0], c[1], c[2]);
}

#else /* floating point: the book's formulas, unchanged */

num v3_len(vec3 a) { return num_sqrt(v3_dot(a, a)); }

vec3 v3_normalize(vec3 a)
{
    num len = v3_len(a);
    if (len == 0) return v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    return v3_make(num_div(a.x, len), num_div(a.y, len), num_div(a.z, len));
}

#endif
