/* SPDX-License-Identifier: MIT */
/* raster_num.h — the few rasterizer primitives whose best form depends on the
 * numeric mode (see num.h). Algorithms in raster_*.c call only these and
 * num.h; only this file and raster_num.c test NUM_MODE.
 */
#ifndef NUM_RAS_H
#define NUM_RAS_H

#include <stdint.h>
#include "num.h"

/* The book's Interpolate(i0, d0, i1, d1) as a stream: value k is d0 at
 * k = 0 and moves by (d1 - d0)/(i1 - i0) per step (i1 > i0; for i1 == i0
 * the value stays d0).
 * - double: the book's accumulation d = d + a, so the double build
 *   reproduces the demos bit for bit.
 * - float: d0 + (k*(d1 - d0))/(i1 - i0), two roundings per value instead
 *   of k accumulated ones.
 * - fixed: exact rational stepping (quotient + remainder), value k is
 *   d0 + round(k*(d1-d0)/(i1-i0)): accumulating a rounded slope in Q15.16
 *   would drift by up to k/2 LSB, which moves 1/z by percents over a
 *   600-row edge.
 * ras_interp_value() reads the current value, ras_interp_next() steps once. */
struct ras_interp {
#if NUM_MODE == NUM_MODE_FIXED
    int64_t base, val, q, r, rem, den;
#elif NUM_MODE == NUM_MODE_FLOAT
    num d0, delta, n;
    int32_t k;
#else
    num d, a;
#endif
};
void ras_interp_init(struct ras_interp *it, num i0, num d0, num i1, num d1);
num  ras_interp_value(const struct ras_interp *it);
void ras_interp_next(struct ras_interp *it);

/* The book's ProjectVertex + ViewportToCanvas, x*d/z*cw/vw.
 * - double: ((x*d)/z)*cw/vw in the demos' order (bit-exact reference);
 * - fixed, float: (x*d*cw)/(z*vw) with one rounding, so points the
 *   reference puts exactly on a pixel boundary (then truncated) land
 *   there too instead of a rounding step short of it. */
num ras_project(num x, num d, num z, num cw, num vw);

/* The book's real-valued loop counters (a = a0, a0 + 1, ...): the value
 * after step k (k >= 1) given the previous value a, and the list index
 * T(a - a0) the demos derive from it. double: a + 1 and T(a - a0), as the
 * demos; fixed (exact) and float: a0 + k and k, so rounding of the counter
 * never shifts a line by a pixel. */
num ras_count_next(num a, num a0, int32_t k);
int32_t ras_count_index(num a, num a0, int32_t k);

/* p/q as a num (q != 0; result saturates). p, q are integers of up to 48
 * bits (edge functions in sub-pixel units). */
num ras_ratio(int64_t p, int64_t q);

/* floor(n / d) for d > 0, *rem = n - floor(n/d)*d in [0, d). Integers of
 * up to 62 bits (edge-function sums). Fixed point avoids the library's
 * 64-bit divide when the quotient and d fit 32 bits. */
int64_t ras_floordiv(int64_t n, int64_t d, int64_t *rem);

/* near/z as an unsigned 32-bit fraction, floor(near/z * (2^32 - 1)), for
 * z >= near > 0 (z < near gives 2^32 - 1, z <= 0 gives 2^32 - 1).
 * Fixed point: exact from the Q15.16 inputs. float: 24 significant bits. */
uint32_t ras_depth32(num near_z, num z);

/* m4_mul_point(m, p), the same bits; fixed point with num.h's inline
 * operations (vec.c's are calls: nine products and twelve sums a point). */
vec3 ras_mul_point(const mat4 *m, vec3 p);

/* The range of a model's coordinates: the least and greatest of each axis
 * (ok 0: none known; fixed point only, and only for at least one point),
 * and a sphere holding every point (sphere 1: known): its centre c, the
 * box's middle, and its radius r, in num's units, the distance from c of
 * the farthest point rounded up. */
struct ras_box { num lo[3], hi[3], c[3]; uint32_t r; uint8_t ok, sphere; };
void ras_box_of(struct ras_box *b, const vec3 *v, uint32_t n);
/* *out: the range of ras_mul_point(m, p)'s components over the points p
 * of box b, exactly (each rounded product is monotonic in p); 1 when no
 * product or sum of ras_mul_point saturates for any of those points, so
 * that ras_mul_point_fit gives its bits there; 0 (and out->ok 0) when one
 * may, or b is not known. */
int ras_box_transform(const mat4 *m, const struct ras_box *b, struct ras_box *out);
/* ras_mul_point(m, p) for a point of a box ras_box_transform accepted with
 * m: the same bits in 32-bit arithmetic, without the saturation checks. */
vec3 ras_mul_point_fit(const mat4 *m, vec3 p);
/* The split of ras_mul_point_fit_split for m over the points of model box
 * b: s in [1, NUM_FRAC] where every product of it stays in 32 bits, or 0
 * (none: ras_mul_point_fit). */
int ras_fit_split(const mat4 *m, const struct ras_box *b);
/* ras_mul_point_fit(m, p) for a point p of the box ras_fit_split gave
 * split s > 0 for: the same bits, each coordinate split once at bit s and
 * each rounded product from two 32-bit products. */
vec3 ras_mul_point_fit_split(const mat4 *m, vec3 p, int s);
/* ras_mul_point_fit_split(m, p[k], s) into out[k] for k < n: the same
 * bits, the points in one loop (out may be p). */
void ras_mul_points_fit_split(const mat4 *m, const vec3 *p, vec3 *out, uint32_t n, int s);
/* A normal's transform: s = ras_fit_split(m, b) > 0 for the box b of
 * every component within +-RAS_NORMAL_BOX, which ras_box_transform
 * accepted with m. ras_mul_point(m, n)'s bits: ras_mul_point_fit_split's
 * where n lies in that box (a model's unit normals), else its own. */
#define RAS_NORMAL_BOX NUM_C(2.0)
vec3 ras_mul_normal_split(const mat4 *m, vec3 n, int s);
/* 1 when ras_mul_point_fit(m, p) of every point p of model box b (whose
 * camera-space range cb ras_box_transform gave) passes every clipping
 * plane's test (ras_point_inside: z >= near_z, |x| <= side_x z, |y| <=
 * side_y z), known from b's sphere turned by m; 0 when not known. */
int ras_sphere_inside(const mat4 *m, const struct ras_box *b, const struct ras_box *cb, num near_z, num side_x,
                      num side_y);

/* The divisions of a vertex's projection by its depth z > 0: X and Y =
 * x * unproj / z and y * unproj / z with the products kept wide (as
 * ras_mul_div), iz = 1/z (num_recip) and depth = ras_depth32(near_z, z),
 * the same bits as those calls. Fixed point divides once: z prepared as a
 * reciprocal (num_udiv_pre) serves the four. */
void ras_div_depth(num x, num y, num z, num unproj, num near_z, num *X, num *Y, num *iz, uint32_t *depth);

/* The default path's projection of a camera-space point (x, y, z), z > 0
 * expected: ras_div_depth's X, Y, iz and depth with the screen position
 * taken to sub-pixel units (y down) as ras_sub_pos(num_add(cx, X), sb) and
 * ras_sub_pos(num_sub(cy, Y), sb) give it, the same bits, in one call.
 * cx, cy: the canvas centre in num; 0 < sb <= 8. */
struct ras_subproj { num unproj, near_z, cx, cy; int32_t sb; };
struct ras_subpos { int32_t sx, sy; num iz; uint32_t depth; };
void ras_div_sub(const struct ras_subproj *k, num x, num y, num z, struct ras_subpos *o);

/* A projected vertex of the default path (raster_int.h): ras_div_sub's
 * sx, sy (as int16_t), iz and depth where sx lies in (INT16_MIN,
 * INT16_MAX] and sy in [INT16_MIN, INT16_MAX]; else sx alone is written,
 * RAS_PV_OUT. */
struct ras_pv { int16_t sx, sy; num iz; uint32_t depth; };
#define RAS_PV_OUT INT16_MIN
/* A shown point's entry: ras_div_sub's position where it fits 16 bits,
 * else RAS_PV_OUT. */
static inline void ras_div_sub_pv(const struct ras_subproj *k, struct ras_pv *q, vec3 c)
{
    struct ras_subpos o;
    q->sx = RAS_PV_OUT;
    ras_div_sub(k, c.x, c.y, c.z, &o);
    if (o.sx > INT16_MIN && o.sx <= INT16_MAX && o.sy >= INT16_MIN && o.sy <= INT16_MAX) {
        q->sx = (int16_t)o.sx;
        q->sy = (int16_t)o.sy;
        q->iz = o.iz;
        q->depth = o.depth;
    }
}
/* Points c[0 .. n-1] (camera space, each shown) projected into out[0 ..
 * n-1] so, one ras_div_sub each: the same bits. */
void ras_div_subs(const struct ras_subproj *k, const vec3 *c, struct ras_pv *out, uint32_t n);

/* A canvas coordinate f (pixels) in sub-pixel units, 0 < sb <= 8: floor(f)
 * 2^sb + floor(frac(f) 2^sb + 1/2), num_floor_int, num_frac, num_mul_int
 * and num_add's bits (raster_project.c's form); fixed point in integers
 * where frac(f) 2^sb + 1/2 cannot saturate. */
static inline int32_t ras_sub_pos(num f, int sb)
{
#if NUM_MODE == NUM_MODE_FIXED && NUM_FRAC <= 22
    return (int32_t)((uint32_t)(f >> NUM_FRAC) << sb) +
           (int32_t)(((((uint32_t)f & (NUM_ONE_RAW - 1u)) << sb) + (NUM_ONE_RAW >> 1)) >> NUM_FRAC);
#else
    return (int32_t)((uint32_t)num_floor_int(f) << sb) + num_floor_int(num_add(num_mul_int(num_frac(f), 1 << sb), NUM_HALF));
#endif
}

/* A front face known from the screen: triangle a b c of three projected
 * corners (inside every plane, z >= near) whose doubled area on screen
 * A (sub-pixel units) exceeds L + (L >> ks) + 4 + g (iz_b + 1)(iz_c + 1)
 * 2^-2F, g = g1 + floor(g2 (iz_a + 1) 2^-F) + 1 (L: the sum of its edges'
 * |dx| + |dy| on screen, iz 1/z in num's bits, a the corner the
 * camera-space test is taken at) is one by that test too, whatever its
 * roundings (raster_num.c derives the bound). Fixed point only: g1 = 0
 * (never known) in the floating modes, whose roundings are relative. */
struct ras_front { uint32_t g1, g2; num iz_min; int ks; };
void ras_front_init(struct ras_front *fb, num unproj, num near_z, int32_t w, int32_t h, int sub_bits);
/* The margin the bound is tested against: A - L - (L >> ks) - 4, for
 * doubled area A and sum L >= 0. */
static inline int64_t ras_front_margin(const struct ras_front *fb, int64_t area, int32_t L)
{
    return area - L - (L >> fb->ks) - 4;
}
/* 1 when margin (ras_front_margin, > 0) passes the bound for corners at
 * 1/z iza, izb, izc; 0 when unknown. */
int ras_front_known(const struct ras_front *fb, int64_t margin, num iza, num izb, num izc);
/* The bound ras_front_known tests the margin against for corners at 1/z
 * iza, izb, izc (> 0, non-decreasing in each, where each is at least
 * iz_min); 0: none (never known). */
uint64_t ras_front_bound(const struct ras_front *fb, num iza, num izb, num izc);

/* round(a * scale) as an integer (halves away from zero), saturated to
 * +-(2^31 - 1): a num turned into the integer formats of the fast span
 * path (raster_fast.c). Exact in fixed point; float and double round the
 * product formed in double. */
int32_t ras_num_to_fix(num a, int32_t scale);

#if NUM_MODE == NUM_MODE_FIXED
/* p >> NUM_FRAC rounded half away from zero, saturated to +-(2^31 - 1):
 * the rounding of ras_num_to_fix's product p = a * scale. */
static inline int32_t ras_fix_round(int64_t p)
{
    const int64_t h = (int64_t)1 << (NUM_FRAC - 1);
    const int64_t r = p >= 0 ? (p + h) >> NUM_FRAC : -((-p + h) >> NUM_FRAC);
    if (r > INT32_MAX) return INT32_MAX;
    if (r < -INT32_MAX) return -INT32_MAX;
    return (int32_t)r;
}
#endif

#endif
