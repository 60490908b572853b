/* SPDX-License-Identifier: MIT */
/* num_sqrt.c — square roots of the fixed-point build: the one estimate
 * every root starts from, num_sqrt, num_rsqrt, wnum_sqrt, v3_len and
 * v3_normalize (see num.h). */
#define NUM_NO_INLINE   /* the out-of-line definitions live here */
#include "num.h"

#if NUM_MODE == NUM_MODE_FIXED

#include "num_fix.h"

/* ---- square roots ------------------------------------------------------
 * Every root comes from one estimate: for x in [2^62, 2^64), u = x / 2^64,
 * a 384-entry seed of 1/sqrt(u) (entry j - 128 is 2^16 / (sqrt(j/512) +
 * sqrt((j+1)/512)), the best constant on [j/512, (j+1)/512): relative error
 * <= 2^-9), one Newton-Raphson step y' = y (3 - u y^2) / 2 (2^-17.4), a root
 * x * y and one Newton step on the root (within 2 units of sqrt(x)); then an
 * exact integer correction. Only 32x32 products (four MULS on ARMv6-M). The
 * table and the bounds are checked by tests/unit/test_num_kernels.c. */
const uint16_t num_rsqrt_seed[384] = {
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
    return rsqrt_q30(xh);
}

/* sqrt(x) for x in [2^62, 2^64) given xh = x >> 32 and xm = x >> 20 mod
 * 2^32: r = sqrt(x) / 2^10 from x * y (22 bits, relative error < 2^-17, so
 * |r^2 - x / 2^20| < 2^23 * 2^5 = 2^28: the residual is exact in 32-bit
 * arithmetic mod 2^32), then one Newton step r + residual / (2 sqrt(x / 2^20)),
 * with 1 / (2 sqrt(x / 2^20)) = y / 2^53, scaled by 2^10: within 2 units
 * (the dropped low 20 bits of x move the root by < 2^-11). */
NUM_FIX_INLINE uint32_t sqrt_core(uint32_t xh, uint32_t xm, uint32_t *ry)
{
    uint32_t y = rsqrt_q30(xh);
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
    uint64_t p = num_usq32(r);
    while (p > v) { r--; p -= 2 * (uint64_t)r + 1; }
    while (v - p > 2 * (uint64_t)r) { p += 2 * (uint64_t)r + 1; r++; }
    if (rem) *rem = v - p;
    return r;
}

/* num_sqrt_est and isqrt_fix in one function, in 32-bit halves (ARMv6-M has
 * no 64-bit shifts), without their calls: the same estimate, so the same
 * steps; the remainder v - r^2 as a signed 64-bit difference (|.| < 2^35
 * while the estimate is being stepped). */
uint64_t num_isqrt64(uint64_t v, uint64_t *rem)
{
    uint32_t hi = (uint32_t)(v >> 32), lo = (uint32_t)v, xh, xl, y;
    if (!(hi | lo)) { if (rem) *rem = 0; return 0; }
    int s = (hi ? num_clz32(hi) : 32 + num_clz32(lo)) & ~1;
    if (s >= 32) { xh = lo << (s - 32); xl = 0; }
    else if (s) { xh = hi << s | lo >> (32 - s); xl = lo << s; }
    else { xh = hi; xl = lo; }
    uint32_t r = sqrt_core(xh, xh << 12 | xl >> 20, &y) >> (s >> 1);
    int64_t d = (int64_t)(v - num_usq32(r));
    while (d < 0) { r--; d += 2 * (int64_t)r + 1; }
    while (d > 2 * (int64_t)r) { d -= 2 * (int64_t)r + 1; r++; }
    if (rem) *rem = (uint64_t)d;
    return r;
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
        uint32_t w = num_mulhi32(xh, (uint32_t)(num_usq32(y) >> 32));
        if (w <= (1u << 28)) y += num_mulhi32_small(y, ((1u << 28) - w) << 3);
        else y -= num_mulhi32_small(y, (w - (1u << 28)) << 3);
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

/* ---- vector length and normalisation (mode-dependent accuracy) ------- */

num v3_len(vec3 a)
{
    uint32_t u[3];
    int sh = num_prescale3(a, u);
    if (sh < 0) {
        /* Largest >= 2^30: the unscaled squares (each <= 2^62) still sum
         * below 3 * 2^62 < 2^64, so use them directly. */
        u[0] = uabs32(a.x);
        u[1] = uabs32(a.y);
        u[2] = uabs32(a.z);
    }
    uint64_t rm, s = num_sumsq3(u);
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

/* Each of v3_len's branches gives floor(sqrt(s) + 1/2), s = x^2 + y^2 +
 * z^2 exactly (a floor of the scaled root rounded half up at 2^sh is
 * floor((floor(2^sh sqrt(s)) + 2^(sh-1)) / 2^sh), the same). Near unit
 * length, s = 2^2F + D with |D| <= 2^(F+3): the root is r = 2^F + d,
 * |d| <= 5, the one with r^2 - r < s <= r^2 + r, i.e.
 * 2^(F+1) d + d^2 - r < D <= 2^(F+1) d + d^2 + r (32-bit values), d stepped
 * from D / 2^(F+1). A normalised vector's s lies within 2^(F+2) of 2^2F
 * (each component within 0.51 ulp of the exact one). */
num v3_len_unit(vec3 a)
{
    const uint64_t s = num_usq32(uabs32(a.x)) + num_usq32(uabs32(a.y)) + num_usq32(uabs32(a.z));
    const uint64_t lim = (uint64_t)1 << (NUM_FRAC + 3);
    const uint64_t off = s + lim - ((uint64_t)1 << (2 * NUM_FRAC));   /* D + lim (mod 2^64) */
    if (off > 2 * lim) return v3_len(a);
    const int32_t D = (int32_t)off - (int32_t)lim, one = (int32_t)1 << NUM_FRAC;
    int32_t d = D >> (NUM_FRAC + 1);
    while (D > d * (2 * one) + d * d + one + d) d++;
    while (D <= d * (2 * one) + d * d - one - d) d--;
    return (num)(one + d);
}

/* v3_normalize(a)'s bits for a of length near 1 (a model's unit normal
 * turned): with S = |a|^2 exactly, D = S - 2^2F, and v3_normalize's
 * pre-scale 2^sh making its sum of squares s = 4^sh S, where T = 2^A,
 * A = F + sh, is 2^29 or 2^30 (the root's scale):
 *   L = round(sqrt(s)) = T + m, the m with 2Tm + m^2 - T - m < 4^sh D <=
 *     2Tm + m^2 + T + m, i.e. m^2 - m - T < 2^sh E <= m^2 + m + T with
 *     E = 2^sh D - 2^(F+1) m, stepped from m = floor(D / 2^(F+1-sh)) less
 *     m^2 / 2^(A+1);
 *   R = floor(2^60 / L) = 2^(60-A) - m 2^c + j, c = 60 - 2A: (T + m)
 *     (2^(60-A) - m 2^c) = 2^60 - m^2 2^c, so j = floor(m^2 2^c / L),
 *     from (m^2 2^c) / 2^A (at least j) stepped down by the remainder;
 *   the components from R as v3_normalize's.
 * No square root and no reciprocal; where |D| < 2^min(2F-10, 30) and
 * F + 1 > sh, else v3_normalize itself. test_num compares the two. */
vec3 v3_normalize_unit(vec3 a)
{
    const uint32_t n[3] = { uabs32(a.x), uabs32(a.y), uabs32(a.z) };
    uint32_t mx = n[0] > n[1] ? n[0] : n[1];
    if (n[2] > mx) mx = n[2];
    if (mx == 0 || mx >= (1u << 29)) return v3_normalize(a);
    const int sh = num_clz32(mx) - 2, A = NUM_FRAC + sh;
    const uint64_t S = num_usq32(n[0]) + num_usq32(n[1]) + num_usq32(n[2]);
    const int lb = 2 * NUM_FRAC - 10 < 30 ? 2 * NUM_FRAC - 10 : 30;   /* |D| < 2^lb: |a| within 2^-11 of 1 */
    const uint64_t off = S + ((uint64_t)1 << lb) - ((uint64_t)1 << (2 * NUM_FRAC));   /* D + 2^lb */
    const int k = NUM_FRAC + 1 - sh;                      /* (F + 1 - A + F: >= 1 for F >= 15) */
    if ((A != 29 && A != 30) || k < 1 || off >= ((uint64_t)1 << (lb + 1))) return v3_normalize(a);
    const int32_t D = (int32_t)off - (1 << lb);
    int32_t m = D >> k;
    int32_t E = (int32_t)((uint32_t)(D - (int32_t)((uint32_t)m << k)) << sh);   /* in [0, 2^(F+1)) */
    /* the second-order term: m less m^2 / 2^(A+1) (|m| < 2^(A-11), so
     * that is below 2^(A-23)), the rest a step or two */
    const uint64_t mm = num_usq32(uabs32(m));
    const int32_t dm = (int32_t)((uint32_t)(mm >> 32) << (31 - A) | (uint32_t)mm >> (A + 1));
    m -= dm;
    E += (int32_t)((uint32_t)dm << (NUM_FRAC + 1));
    const uint32_t T = 1u << A;
    for (;;) {
        const int64_t e = num_smul32(E, 1 << sh), m2 = (int64_t)num_usq32(uabs32(m));
        if (e > m2 + m + T) {
            m++;
            E -= 1 << (NUM_FRAC + 1);
        } else if (e <= m2 - m - (int64_t)T) {
            m--;
            E += 1 << (NUM_FRAC + 1);
        } else {
            break;
        }
    }
    const uint32_t L = T + (uint32_t)m;
    const int c = 60 - 2 * A;                             /* 0 or 2 */
    const uint64_t m2c = num_usq32(uabs32(m) << (c >> 1));   /* m^2 2^c */
    uint32_t j = (uint32_t)(m2c >> 32) << (32 - A) | (uint32_t)m2c >> A;
    int64_t r = (int64_t)m2c - (int64_t)num_umul32(j, L);
    while (r < 0) {
        j--;
        r += L;
    }
    while (r >= (int64_t)L) {
        j++;
        r -= L;
    }
    const uint32_t R = (1u << (60 - A)) - ((uint32_t)m << c) + j;
    num cc[3];
    const num *in[3] = { &a.x, &a.y, &a.z };
    for (int i = 0; i < 3; i++) {
        const uint64_t q = num_umul32(n[i] << sh, R);
        const num v = (num)((q + ((uint64_t)1 << (59 - NUM_FRAC))) >> (60 - NUM_FRAC));
        cc[i] = *in[i] < 0 ? -v : v;
    }
    return v3_make(cc[0], cc[1], cc[2]);
}

vec3 v3_normalize(vec3 a)
{
    uint32_t u[3];
    if (a.x == 0 && a.y == 0 && a.z == 0) return a;
    num_prescale3(a, u);
    uint64_t s = num_sumsq3(u);                       /* in [2^58, 3 * 2^60) */
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

#else
typedef int num_sqrt_fixed_only;   /* (a translation unit may not be empty) */
#endif
