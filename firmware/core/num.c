/* num.c — scalar operations for the three numeric modes (see num.h). */
#include "num.h"

uint32_t num_saturations;

#ifdef NUM_COUNT_SAT
#define SAT_HIT() (num_saturations++)
#else
#define SAT_HIT() ((void)0)
#endif

#if NUM_MODE == NUM_MODE_FIXED

/* Arithmetic right shift of a negative int64 is implementation-defined in
 * C11; GCC and Clang define it as arithmetic on every target we build for,
 * so results are the same bits on x86 and ARM. */

static num sat64(int64_t v)
{
    if (v > INT32_MAX) { SAT_HIT(); return NUM_MAX; }
    if (v < -(int64_t)INT32_MAX) { SAT_HIT(); return NUM_MIN; }
    return (num)v;
}

static int64_t sat64w(int64_t v, int64_t lim)
{
    if (v > lim) { SAT_HIT(); return lim; }
    if (v < -lim) { SAT_HIT(); return -lim; }
    return v;
}

num num_from_int(int32_t i) { return sat64((int64_t)i * NUM_ONE_RAW); }
int32_t num_to_int(num a) { return a >= 0 ? a >> NUM_FRAC : -((-a) >> NUM_FRAC); }
int32_t num_floor_int(num a) { return a >> NUM_FRAC; }
num num_frac(num a) { return a & (NUM_ONE_RAW - 1); }

num num_from_ratio(int32_t p, int32_t q)
{
    return num_div(num_from_int(p), num_from_int(q));
}

num num_from_double(double d)
{
    double s = d * (double)NUM_ONE_RAW;
    if (s != s) return 0;
    if (s >= 2147483647.0) { SAT_HIT(); return NUM_MAX; }
    if (s <= -2147483647.0) { SAT_HIT(); return NUM_MIN; }
    return (num)(s >= 0 ? s + 0.5 : s - 0.5);
}

double num_to_double(num a) { return (double)a / (double)NUM_ONE_RAW; }

num num_add(num a, num b) { return sat64((int64_t)a + b); }
num num_sub(num a, num b) { return sat64((int64_t)a - b); }
num num_neg(num a) { return -a; }
num num_abs(num a) { return a < 0 ? -a : a; }

num num_mul(num a, num b)
{
    int64_t p = (int64_t)a * b;
    return sat64((p + ((int64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC);
}

num num_mul_int(num a, int32_t k) { return sat64((int64_t)a * k); }

/* Rounded quotient of two int64 values (b != 0), halves away from zero. */
static int64_t div_round(int64_t a, int64_t b)
{
    int neg = (a < 0) != (b < 0);
    uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? (uint64_t)0 - (uint64_t)b : (uint64_t)b;
    uint64_t q = (ua + ub / 2) / ub;
    if (q > (uint64_t)INT64_MAX) q = (uint64_t)INT64_MAX;
    return neg ? -(int64_t)q : (int64_t)q;
}

num num_div(num a, num b)
{
    if (b == 0) {
        if (a == 0) return 0;
        SAT_HIT();
        return a > 0 ? NUM_MAX : NUM_MIN;
    }
    return sat64(div_round((int64_t)a * NUM_ONE_RAW, b));
}

num num_div_int(num a, int32_t k)
{
    if (k == 0) return num_div(a, 0);
    return sat64(div_round(a, k));
}

num num_recip(num a) { return num_div(NUM_ONE, a); }

static uint64_t isqrt64(uint64_t v)
{
    uint64_t r = 0, bit = (uint64_t)1 << 62;
    while (bit > v) bit >>= 2;
    while (bit) {
        if (v >= r + bit) { v -= r + bit; r = (r >> 1) + bit; }
        else r >>= 1;
        bit >>= 2;
    }
    /* round to nearest: r*r <= v0 < (r+1)^2; v now holds v0 - r*r */
    if (v > r) r++;
    return r;
}

num num_sqrt(num a)
{
    if (a <= 0) return 0;
    return (num)isqrt64((uint64_t)a << NUM_FRAC);
}

num num_rsqrt(num a)
{
    if (a <= 0) { SAT_HIT(); return NUM_MAX; }
    return num_recip(num_sqrt(a));
}

num num_powi(num base, uint32_t e)
{
    num r = NUM_ONE;
    while (e) {
        if (e & 1u) r = num_mul(r, base);
        e >>= 1;
        if (e) base = num_mul(base, base);
    }
    return r;
}

/* sin of an angle in degrees by reduction to [0, 90] and a Taylor series
 * in radians evaluated in Q2.29-ish integer steps. */
num num_sin_deg(num deg)
{
    /* reduce to [0, 360) */
    int64_t full = (int64_t)360 * NUM_ONE_RAW;
    int64_t d = (int64_t)deg % full;
    if (d < 0) d += full;
    int neg = 0;
    if (d >= full / 2) { d -= full / 2; neg = 1; }
    if (d > full / 4) d = full / 2 - d;
    /* x in radians, Q2.30 */
    const int64_t pi_over_180_q30 = 18740330; /* pi/180 * 2^30 */
    int64_t x = (d * pi_over_180_q30) >> NUM_FRAC; /* Q2.30 */
    int64_t x2 = (x * x) >> 30;
    int64_t term = x, sum = x;
    for (int k = 1; k <= 6; k++) {
        term = -((term * x2) >> 30) / ((2 * k) * (2 * k + 1));
        sum += term;
    }
    int64_t r = (sum + ((int64_t)1 << (29 - NUM_FRAC))) >> (30 - NUM_FRAC);
    return (num)(neg ? -r : r);
}

num num_cos_deg(num deg) { return num_sin_deg(num_add(deg, num_from_int(90))); }

wnum wnum_from_num(num a) { return a; }
num  wnum_to_num(wnum a) { return sat64(a); }
wnum wnum_add(wnum a, wnum b) { return sat64w(a + b, INT64_MAX / 4); }
wnum wnum_sub(wnum a, wnum b) { return sat64w(a - b, INT64_MAX / 4); }

wnum wnum_mul(wnum a, wnum b)
{
    /* |a*b| >> NUM_FRAC without 128-bit arithmetic: split b. */
    int neg = (a < 0) != (b < 0);
    uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? (uint64_t)0 - (uint64_t)b : (uint64_t)b;
    uint64_t lim = (uint64_t)(INT64_MAX / 4);
    uint64_t bh = ub >> NUM_FRAC, bl = ub & ((1u << NUM_FRAC) - 1);
    if (bh && ua > lim / bh) { SAT_HIT(); return neg ? -(int64_t)lim : (int64_t)lim; }
    uint64_t hi = ua * bh;
    uint64_t lo;
    if (ua > (UINT64_MAX >> NUM_FRAC)) lo = (ua >> NUM_FRAC) * bl;
    else lo = (ua * bl + ((uint64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC;
    uint64_t r = hi + lo;
    if (r > lim) { SAT_HIT(); r = lim; }
    return neg ? -(int64_t)r : (int64_t)r;
}

wnum num_mul_wide(num a, num b)
{
    int64_t p = (int64_t)a * b;
    return (p + ((int64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC;
}

num wnum_div(wnum a, wnum b)
{
    if (b == 0) {
        if (a == 0) return 0;
        SAT_HIT();
        return a > 0 ? NUM_MAX : NUM_MIN;
    }
    /* a * 2^NUM_FRAC may overflow: reduce both while it would. */
    while (a > (INT64_MAX >> NUM_FRAC) || a < -(INT64_MAX >> NUM_FRAC)) {
        a /= 2;
        b /= 2;
        if (b == 0) { SAT_HIT(); return a > 0 ? NUM_MAX : NUM_MIN; }
    }
    return sat64(div_round(a * NUM_ONE_RAW, b));
}

wnum wnum_sqrt(wnum a)
{
    if (a <= 0) return 0;
    uint64_t ua = (uint64_t)a;
    if (ua < ((uint64_t)1 << (63 - NUM_FRAC))) return (wnum)isqrt64(ua << NUM_FRAC);
    /* large: sqrt(a * 2^F) = sqrt(a / 2^F) * 2^F */
    return (wnum)(isqrt64(ua >> NUM_FRAC) << NUM_FRAC);
}

num wnum_to_num_shr(wnum a, int bits)
{
    if (bits <= 0) return sat64(a);
    return sat64((a + ((int64_t)1 << (bits - 1))) >> bits);
}

#else /* floating-point modes */

#include <math.h>

#if NUM_MODE == NUM_MODE_FLOAT
#define F(x) x##f
#else
#define F(x) x
#endif

num num_from_int(int32_t i) { return (num)i; }
int32_t num_to_int(num a)
{
    if (a != a) return 0;
    if (a >= 2147483647.0) return INT32_MAX;
    if (a <= -2147483647.0) return -INT32_MAX;
    return (int32_t)a;
}
int32_t num_floor_int(num a) { return num_to_int(F(floor)(a)); }
num num_frac(num a) { return a - F(floor)(a); }
num num_from_ratio(int32_t p, int32_t q) { return q ? (num)p / (num)q : num_div((num)p, 0); }
num num_from_double(double d) { return (num)d; }
double num_to_double(num a) { return (double)a; }
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
    /* exact: floor((c*L + 255*2^F/2) / (255*2^F)) */
    uint64_t n = (uint64_t)c * levels + (uint64_t)255 * (NUM_ONE_RAW / 2);
    return (uint32_t)(n / ((uint64_t)255 * NUM_ONE_RAW));
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
