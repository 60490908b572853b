/* SPDX-License-Identifier: MIT */
/* num.h — the numeric layer: one scalar type, three builds.
 *
 * Every renderer algorithm is written once against this interface; the build
 * picks the arithmetic with NUM_MODE:
 *   NUM_MODE_FIXED  (1, firmware default)  num = int32_t, Q(31-NUM_FRAC).NUM_FRAC
 *   NUM_MODE_FLOAT  (2)                    num = float
 *   NUM_MODE_DOUBLE (3, the reference)     num = double
 * Only files named num*.h / num*.c may test NUM_MODE; algorithms never do.
 *
 * Conventions that hold in every mode:
 * - Comparisons (<, <=, ==, ...) are the plain C operators on num.
 * - Arithmetic goes through the functions below (never +, -, * on num): in
 *   fixed point they round to nearest and saturate instead of overflowing.
 * - NUM_C(x) turns a double literal into a num constant at compile time
 *   (no floating-point code is emitted in the fixed build).
 * - wnum is the wide type for intermediates whose range argument needs it
 *   (int64_t with the same NUM_FRAC fraction bits in fixed point; the mode's
 *   floating type otherwise).
 *
 * Fixed point: int32 raw value r stands for r / 2^NUM_FRAC. NUM_FRAC is a
 * compile-time choice in 8..20 (tested at 12, 16, 20); default 16, Q15.16:
 *   range [-32768 + 2^-16, 32768 - 2^-16] (raw INT32_MIN is never produced),
 *   resolution 1 ulp = 2^-16 = 1.53e-5. With NUM_FRAC = F the range is
 *   +-2^(31-F) and 1 ulp = 2^-F. Every kind of quantity below uses this one
 *   format; the column gives the range the renderers keep it in (Q15.16):
 *     kind                      range kept           resolution / note
 *     positions, distances, t   |x| < 32768          2^-16 scene units
 *     directions, normals       components [-1, 1]   2^-16 (v3_normalize: 0.5 ulp)
 *     colours                   channels 0..255      2^-16 of a level; may exceed
 *                                                    255 before the final clamp
 *     intensities               0..~16               2^-16
 *     depths 1/z                (0, 1] for z >= 1    2^-16 (z up to 65536 distinct)
 *     texture coordinates       [0, 1] plus margin   2^-16 (1/65536 texel at 1 px)
 *     angles                    degrees, any value   reduced exactly modulo 360
 *   Products of two positions (dot products, |v|^2) exceed the range: use
 *   the wide forms (v3_dot_wide, num_mul_wide) or keep operands small.
 *   Overflow saturates to NUM_MAX / NUM_MIN and increments num_saturations
 *   when NUM_COUNT_SAT is defined (debug and test builds); so does an input
 *   outside an operation's domain (sqrt of a negative, rsqrt of <= 0,
 *   division by zero). Nothing traps, nothing is undefined.
 *   Errors (measured against the double result, see docs/numerics.md) are
 *   given next to each function in ulps of the fixed format.
 * Float and double modes call the C library (libm): the double build is the
 *   book's reference (no FMA contraction).
 */
#ifndef NUM_H
#define NUM_H

#include <stdint.h>

#define NUM_MODE_FIXED  1
#define NUM_MODE_FLOAT  2
#define NUM_MODE_DOUBLE 3

#ifndef NUM_MODE
#define NUM_MODE NUM_MODE_FIXED
#endif

#if NUM_MODE == NUM_MODE_FIXED
#ifndef NUM_FRAC
#define NUM_FRAC 16
#endif
typedef int32_t num;
typedef int64_t wnum;
#define NUM_ONE_RAW   ((int32_t)1 << NUM_FRAC)
/* Compile-time constant from a double literal, rounded to nearest. */
#define NUM_C(x)      ((num)((x) * (double)NUM_ONE_RAW + ((x) >= 0 ? 0.5 : -0.5)))
#define NUM_MAX       INT32_MAX
#define NUM_MIN       (-INT32_MAX) /* symmetric: negation never overflows */
#define NUM_EPS       ((num)1)     /* smallest positive value */
#define NUM_NAME      "fixed"
#elif NUM_MODE == NUM_MODE_FLOAT
typedef float num;
typedef float wnum;
#define NUM_C(x)      ((num)(x))
#define NUM_MAX       3.0e38f
#define NUM_MIN       (-3.0e38f)
#define NUM_EPS       1.0e-30f
#define NUM_NAME      "float"
#elif NUM_MODE == NUM_MODE_DOUBLE
typedef double num;
typedef double wnum;
#define NUM_C(x)      ((num)(x))
#define NUM_MAX       1.0e300
#define NUM_MIN       (-1.0e300)
#define NUM_EPS       1.0e-300
#define NUM_NAME      "double"
#else
#error "NUM_MODE must be NUM_MODE_FIXED, NUM_MODE_FLOAT or NUM_MODE_DOUBLE"
#endif

#define NUM_ZERO NUM_C(0.0)
#define NUM_ONE  NUM_C(1.0)
#define NUM_HALF NUM_C(0.5)

/* Saturation counter (debug and test builds; always 0 otherwise). */
extern uint32_t num_saturations;

/* ---- conversions ---------------------------------------------------- */
num     num_from_int(int32_t i);          /* saturates outside the range */
int32_t num_to_int(num a);                /* truncates toward zero (the book's T) */
int32_t num_floor_int(num a);             /* floor */
num     num_from_ratio(int32_t p, int32_t q); /* p/q rounded; q == 0 saturates */
num     num_frac(num a);                  /* a - floor(a), in [0, 1) */
/* Host-side only (parsers, tests): never called by the firmware core. */
num     num_from_double(double d);        /* rounds to nearest, saturates */
double  num_to_double(num a);

/* ---- arithmetic (all modes; fixed point rounds to nearest, saturates) -- */
num num_add(num a, num b);
num num_sub(num a, num b);
num num_neg(num a);
num num_abs(num a);
num num_mul(num a, num b);                /* rounded to nearest: <= 0.5 ulp */
num num_mul_int(num a, int32_t k);
/* num_mul and num_add for operands whose exact result is known to lie in
 * num's range (a scene's format analysis proved it: struct scene.fits):
 * the same value without the saturation checks (fixed point: 32-bit
 * arithmetic, 17 instead of about 30 instructions a product on ARMv6-M).
 * Outside the range the result is unspecified (wrapped), never undefined. */
num num_mul_fit(num a, num b);
num num_add_fit(num a, num b);
/* (a * k) mod m (m > 0; 0 otherwise), with the sign of a * k: exact in fixed
 * point (the 64-bit product, reduced; saturates only if |a k| >= m 2^32), so
 * an angle per frame times a frame index neither saturates nor drifts
 * (animations); the floating modes reduce the product in their precision. */
num num_mul_int_mod(num a, int32_t k, num m);
num num_div(num a, num b);                /* correctly rounded (<= 0.5 ulp, halves away
                                           * from 0); b == 0: saturated, sign of a (0/0 = 0) */
num num_div_int(num a, int32_t k);
num num_recip(num a);                     /* 1/a, <= 0.5 ulp; a == 0 saturates */
num num_sqrt(num a);                      /* <= 0.5 ulp; a <= 0 gives 0 (a < 0 counted) */
num num_rsqrt(num a);                     /* 1/sqrt(a), <= 0.5 ulp; a <= 0 saturates to NUM_MAX */
num num_powi(num base, uint32_t e);       /* base^e, any e (tested 1..1000): error
                                           * <= 0.5 ulp + |base^e| * e * 2^-30 (relative
                                           * part), i.e. <= 0.5 + e*2^(F-30) ulp for
                                           * |base| <= 1; 0^0 = 1 */
num num_sin_deg(num deg);                 /* angles in degrees, any value: <= 0.51 ulp */
num num_cos_deg(num deg);                 /* <= 0.51 ulp */
num num_min(num a, num b);
num num_max(num a, num b);
num num_clamp(num a, num lo, num hi);
/* Colour channel quantisation, channel clamped to [0, 255] first (NaN -> 0):
 * num_chan_levels(c, L) = floor(c*L/255 + 1/2) (L = 31 or 63 for RGB565);
 * num_chan_byte(c) = c rounded to nearest, ties to even (the book's store). */
uint32_t num_chan_levels(num c, uint32_t levels);
uint8_t  num_chan_byte(num c);

/* Division by a value fixed in advance (a sphere's radius): num_div_by(a,
 * &v) is num_div(a, v.d) bit for bit, with two 32x32 products instead of a
 * division in fixed point when |d| >= 2^(F-3) (a reciprocal with an exact
 * remainder correction), num_div itself otherwise. */
struct num_divisor {
    num d;
#if NUM_MODE == NUM_MODE_FIXED
    uint32_t ud, m;       /* |d|, floor(2^(F+32-k) / |d|) */
    uint8_t k, fast;
#endif
};
struct num_divisor num_divisor_make(num d);
num num_div_by(num a, const struct num_divisor *v);

/* Division by a value fixed in advance, by its reciprocal alone (no
 * remainder correction): num_mul_recip(a, &v) is within half an ulp plus
 * 2^-31 of itself of a / v.d in fixed point (so almost always num_div's
 * bits; one 32x32 product), num_div itself in the floating modes and for
 * v.d == 0. */
struct num_recip {
    num d;
#if NUM_MODE == NUM_MODE_FIXED
    uint32_t m;           /* round(2^(30+L) / |d|) in [2^30, 2^31], L the bit length of |d| */
    uint8_t sh;           /* 30 + L - F */
#endif
};
struct num_recip num_recip_make(num d);
num num_mul_recip(num a, const struct num_recip *v);

/* ---- wide intermediates ---------------------------------------------- */
wnum wnum_from_num(num a);
num  wnum_to_num(wnum a);                 /* saturates */
wnum wnum_add(wnum a, wnum b);
wnum wnum_sub(wnum a, wnum b);
wnum wnum_mul(wnum a, wnum b);            /* saturates */
wnum num_mul_wide(num a, num b);          /* exact product, one rounding, no saturation */
num  wnum_div(wnum a, wnum b);            /* correctly rounded; saturates; b == 0 as num_div */
wnum wnum_sqrt(wnum a);                   /* a <= 0 gives 0 */
num  wnum_to_num_shr(wnum a, int bits);   /* a / 2^bits, saturated */

/* ---- vectors, matrices, colours (mode-independent code in vec.c) ------- */
typedef struct { num x, y, z; } vec3;
typedef struct { num x, y, z, w; } vec4;
typedef struct { num m[3][3]; } mat3;     /* row-major, acts on column vectors */
typedef struct { num m[4][4]; } mat4;     /* row-major, acts on column vectors */
typedef struct { num r, g, b; } rgb;      /* channels 0..255, unclamped */

vec3 v3_make(num x, num y, num z);
vec3 v3_add(vec3 a, vec3 b);
vec3 v3_sub(vec3 a, vec3 b);
vec3 v3_neg(vec3 a);
vec3 v3_scale(vec3 a, num s);
num  v3_dot(vec3 a, vec3 b);              /* summed wide, rounded once */
wnum v3_dot_wide(vec3 a, vec3 b);
vec3 v3_cross(vec3 a, vec3 b);
num  v3_len(vec3 a);                      /* correctly rounded (exact sum of squares) */
num  v3_len_unit(vec3 a);                 /* v3_len(a), the same bits; fast for a length
                                           * near 1 (v3_normalize's results) */
/* x / |v|, |v| from the exact sum of squares (never rounded to the format
 * on its own): fixed point multiplies by a reciprocal square root refined
 * to about 2^-27, so the result is within half an ulp plus 2^-26 of itself
 * (saturating; v = 0 as a division by zero); the floating modes divide by
 * v3_len(v). */
num  v3_div_len(num x, vec3 v);
vec3 v3_normalize(vec3 a);                /* <= 0.51 ulp per component for any non-zero
                                           * input, tiny ones included (pre-scaled);
                                           * zero vector stays zero */
vec3 v3_normalize_unit(vec3 a);           /* v3_normalize(a), the same bits; fast for a
                                           * length near 1 (a unit normal turned) */
vec3 m3_mul_v3(const mat3 *m, vec3 v);
mat3 m3_mul(const mat3 *a, const mat3 *b);
mat3 m3_transpose(const mat3 *a);
mat3 m3_identity(void);
mat3 m3_rot_y_deg(num deg);               /* the book's MakeOYRotationMatrix */
vec4 m4_mul_v4(const mat4 *m, vec4 v);
/* x, y, z of m4_mul_v4(m, (p, 1)), the same bits, without the fourth row
 * and the products by 1 (a point through an affine matrix). */
vec3 m4_mul_point(const mat4 *m, vec3 p);
mat4 m4_mul(const mat4 *a, const mat4 *b);
mat4 m4_transpose(const mat4 *a);
mat4 m4_identity(void);
mat4 m4_from_m3(const mat3 *r);
mat4 m4_translation(vec3 t);
mat4 m4_scale(num k);

rgb  rgb_make(num r, num g, num b);
rgb  rgb_scale(rgb c, num k);
rgb  rgb_add(rgb a, rgb b);
/* Final colour write (contract's colour rules): channel clamped to [0, 255],
 * RGB565 by r5 = floor(c*31/255 + 1/2) etc.; 8-bit by round half to even. */
uint16_t rgb_to_565(rgb c);
void     rgb_to_888(rgb c, uint8_t out[3]);

/* Fixed point: the hottest operations inline (same bits; num_inline.h). */
#if NUM_MODE == NUM_MODE_FIXED && !defined(NUM_NO_INLINE)
#include "num/num_inline.h"
#endif

#endif
