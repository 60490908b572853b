/* SPDX-License-Identifier: MIT */
/* num_float.c — scalar operations of the floating-point modes (float and
 * double builds; see num.h): the math library's functions in the mode's
 * type. */
#define NUM_NO_INLINE   /* the out-of-line definitions live here */
#include "num.h"

#if NUM_MODE != NUM_MODE_FIXED

#ifdef NUM_COUNT_SAT
#define SAT_HIT() (num_saturations++)
#else
#define SAT_HIT() ((void)0)
#endif

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
struct num_recip num_recip_make(num d)
{
    struct num_recip v;
    v.d = d;
    return v;
}
num num_mul_recip(num a, const struct num_recip *v) { return num_div(a, v->d); }
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

num v3_len(vec3 a) { return num_sqrt(v3_dot(a, a)); }
num v3_len_unit(vec3 a) { return v3_len(a); }
vec3 v3_normalize_unit(vec3 a) { return v3_normalize(a); }

num v3_div_len(num x, vec3 v) { return num_div(x, v3_len(v)); }

vec3 v3_normalize(vec3 a)
{
    num len = v3_len(a);
    if (len == 0) return v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    return v3_make(num_div(a.x, len), num_div(a.y, len), num_div(a.z, len));
}

#else
typedef int num_float_modes_only;   /* (a translation unit may not be empty) */
#endif
