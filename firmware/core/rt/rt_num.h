/* SPDX-License-Identifier: MIT */
/* rt_num.h — what the ray tracer needs to know about the numeric mode.
 *
 * The ray tracer is one source for the three modes (no NUM_MODE tests in
 * it); the one mode-dependent choice it makes is which formulation of the
 * intersection and normal computations a scene gets by default:
 * - double, the reference build: the book demos' operation order, literally,
 *   so that the demos' reference images are reproduced bit for bit;
 * - fixed and float: the robust formulation (stable quadratic with wide
 *   intermediates, analytic self-intersection), which holds for the
 *   radius-5000 ground sphere in Q15.16 and in single precision.
 * rt_options.formulation overrides the default per scene.
 */
#ifndef NUM_RT_H
#define NUM_RT_H

#include "num.h"
#if NUM_MODE == NUM_MODE_FIXED
#include "num/num_int.h"
#endif

/* 1 when the mode is the reference (double), 0 otherwise. */
static inline int num_rt_reference_mode(void)
{
#if NUM_MODE == NUM_MODE_DOUBLE
    return 1;
#else
    return 0;
#endif
}

/* ---- conservative coarse sphere rejection (fixed point) ---------------
 *
 * rt_coarse_sphere_miss(cd, sp) returns 1 only when the robust sphere test
 * (rt_intersect.c) of the ray O + t D against the sphere sp would certainly
 * return "no intersection" (its computed discriminant negative, or the
 * sphere outside and behind), so skipping that test changes no pixel. It
 * returns 0 whenever it cannot tell, and always in the floating modes.
 *
 * Fixed point, in 32-bit integers (no 64-bit product but one 32x32->64 for
 * the margin; the rest one MULS each on ARMv6-M). co = C - O in units U,
 * from the two points each floored to units (error < 1 unit per
 * component), |co|_1 = n1 < 2^19; fine units U = 2^(F-10) raw (2^-10 scene
 * units) when |CO| allows, else U = 2^12 raw. D is scaled by a power of
 * two to |d_i| < 2^10 (max >= 2^9, floor), len >= |d| (max + (mid +
 * min)/2, at most 15 % above). With the truncation errors of both,
 * |X| = |co x d| > T = R (len + 2) + 2 len + 2 n1 + 3 proves that the line
 * passes more than R units from C, and co.d < -T that C lies more than R
 * units behind O. R = ceil(r / U) + m + 3, where m covers the robust test's
 * own rounding: its b, c, a and products carry errors of a few ulps
 * u = 2^-F, which move its discriminant by at most
 * M = u (6.25 |CO|^2 + 25 |CO| + 42) a, and a miss by r + m with
 * 2 r m >= M or m^2 >= M survives them; m is the smaller of the two
 * bounds (derivation in docs/raytracer.md). Used for NUM_FRAC >= 12 and
 * when D's largest raw component lies in [2^(F-8), 2^(F+13)), where the
 * robust test's direction scaling keeps D'.D' in [0.25, 4); otherwise
 * len = 0 (no coarse test for that ray). */
#define RT_FINE_SHIFT (NUM_FRAC - 10)

/* The coarse test runs a dozen times a pixel: inlined into each caller
 * (GCC would call it; the call costs about 15 of its 85 instructions on
 * ARMv6-M). */
#if defined(__GNUC__) || defined(__clang__)
#define RT_ALWAYS_INLINE static inline __attribute__((always_inline))
#define RT_NOINLINE __attribute__((noinline))
#else
#define RT_ALWAYS_INLINE static inline
#define RT_NOINLINE
#endif

/* A point in both coarse units (fixed: raw >> 12 and raw >> (F - 10)). */
struct rt_cpt {
#if NUM_MODE == NUM_MODE_FIXED
    int32_t x, y, z;
    int32_t fx, fy, fz;
#else
    uint8_t none;
#endif
};

/* A sphere for the coarse tests (per frame). Its margins in fine units are
 * made once for each class of |co|_1 (n1 < 2^10, then each bit length up
 * to 19): both bounds grow with n1, so the class's largest n1 bounds every
 * n1 in it; RT_MF_NONE: the class takes the coarse units. */
#define RT_MF_N 10
#define RT_MF_NONE 0xFFFFu
/* A sphere for the coarse tests (per frame). */
struct rt_csphere {
    struct rt_cpt c;
#if NUM_MODE == NUM_MODE_FIXED
    uint32_t rc, rcf;     /* ceil(r / U) in both units (r >= 0) */
    uint32_t inv2r;       /* >= 2^32 / (2 r raw), 0: r too small for the 2 r m bound */
    uint16_t mf[RT_MF_N]; /* fine units: the margin for n1 < 2^(10 + j) (rt_coarse_sphere_miss) */
    uint8_t ok;           /* 0: no coarse tests (negative radius) */
#endif
};

struct rt_cdir {
#if NUM_MODE == NUM_MODE_FIXED
    int32_t x, y, z;
    int32_t len;          /* 0: no coarse tests for this ray */
#else
    uint8_t none;
#endif
    struct rt_cpt o;      /* the ray's origin */
};

static inline void rt_cpt_set(struct rt_cpt *c, vec3 p)
{
#if NUM_MODE == NUM_MODE_FIXED
    c->x = p.x >> 12;
    c->y = p.y >> 12;
    c->z = p.z >> 12;
    c->fx = p.x >> (NUM_FRAC >= 12 ? RT_FINE_SHIFT : 0);
    c->fy = p.y >> (NUM_FRAC >= 12 ? RT_FINE_SHIFT : 0);
    c->fz = p.z >> (NUM_FRAC >= 12 ? RT_FINE_SHIFT : 0);
#else
    (void)p;
    c->none = 1;
#endif
}

static inline struct rt_cpt rt_cpt_make(vec3 p)
{
    struct rt_cpt c;
    rt_cpt_set(&c, p);
    return c;
}

#if NUM_MODE == NUM_MODE_FIXED
static inline uint32_t rt_uabs(int32_t v) { return v < 0 ? 0u - (uint32_t)v : (uint32_t)v; }

/* a^2 (num_usq32). */
static inline uint64_t rt_usq32(uint32_t a) { return num_usq32(a); }

/* a^2 of a signed value (num_smul32(a, a)). */
static inline int64_t rt_ssq32(int32_t a) { return (int64_t)rt_usq32(rt_uabs(a)); }

/* 1 when every component of v lies in [-2^k, 2^k) (raw, k <= 30): v_i +
 * 2^k in [0, 2^(k+1)) for each, so their bit-OR is below 2^(k+1). */
static inline int rt_v3_within(vec3 v, int k)
{
    uint32_t b = (uint32_t)1 << k;
    return (((uint32_t)v.x + b) | ((uint32_t)v.y + b) | ((uint32_t)v.z + b)) < 2 * b;
}

/* num_mul_round32(a, b) for 0 <= b < 2^16 in Q15.16 (a colour by a
 * weight below 1), in two 16x16 products instead of four: with a = ah 2^16
 * + al (ah = a >> 16 signed, al unsigned), a b / 2^16 = ah b + al b / 2^16,
 * |ah b| < 2^31 and al b + 2^15 < 2^32, so ah b + ((al b + 2^15) >> 16) is
 * the rounded product, modulo 2^32 as num_mul_round32's. */
static inline int32_t rt_mul_round_u16(int32_t a, uint32_t b)
{
    uint32_t al = (uint32_t)a & 0xFFFFu;
    int32_t ah = a >> 16;
    return (int32_t)((uint32_t)(ah * (int32_t)b) + ((al * b + 0x8000u) >> 16));
}

/* v3_dot(a, b) for |a_i| <= 2^(F+1) and |b_i| <= 2^28 (raw; rt_v3_within):
 * each |a_i b_i| <= 2^(F+29), so each rounded product is <= 2^29 in
 * magnitude, their sum at most 3 * 2^29 < 2^31: the 32-bit sum of the
 * rounded products (num_mul_round32) is exact and v3_dot's saturation
 * never acts. The same value in fewer instructions. */
static inline num rt_dot_small(vec3 a, vec3 b)
{
    return num_mul_round32(a.x, b.x) + num_mul_round32(a.y, b.y) + num_mul_round32(a.z, b.z);
}

/* rt_dot_small(a, b) when every component of b is an integer (a multiple
 * of 2^F raw; a directional light such as (1, 4, 4)): each rounded product
 * a_i b_i / 2^F is a_i (b_i / 2^F) exactly, at most 2^(F+1) 2^(26-F) = 2^27
 * in magnitude under rt_dot_small's ranges: one 32-bit product each, the
 * same value. */
static inline num rt_dot_small_int(vec3 a, vec3 b)
{
    return a.x * (b.x >> NUM_FRAC) + a.y * (b.y >> NUM_FRAC) + a.z * (b.z >> NUM_FRAC);
}

/* 1 when every component of v is an integer (rt_dot_small_int). */
static inline int rt_v3_integral(vec3 v)
{
    return (((uint32_t)v.x | (uint32_t)v.y | (uint32_t)v.z) & ((1u << NUM_FRAC) - 1u)) == 0;
}

static inline uint32_t rt_umax3(uint32_t a, uint32_t b, uint32_t c)
{
    uint32_t m = a > b ? a : b;
    return c > m ? c : m;
}

/* v (largest component of bit length e) scaled by a power of two to
 * components < 2^10 in magnitude, the largest >= 2^9 (floor: error in
 * (-1, 0]; exact when scaled up) into c; returns an upper bound of |c|
 * without a square root: for a >= b >= c, (a + (b + c)/2)^2 >= a^2 + ab +
 * ac >= a^2 + b^2 + c^2, so max + (mid + min)/2 (at most 15 % above). */
static inline uint32_t rt_scale10(vec3 v, int e, int32_t c[3])
{
    if (e > 10) {
        c[0] = v.x >> (e - 10);
        c[1] = v.y >> (e - 10);
        c[2] = v.z >> (e - 10);
    } else {
        c[0] = v.x * (1 << (10 - e));
        c[1] = v.y * (1 << (10 - e));
        c[2] = v.z * (1 << (10 - e));
    }
    uint32_t ax = rt_uabs(c[0]), ay = rt_uabs(c[1]), az = rt_uabs(c[2]);
    uint32_t m = rt_umax3(ax, ay, az);
    return m + ((ax + ay + az - m + 1) >> 1);
}
#endif

/* The ray's coarse direction and origin, in place. */
static inline void rt_cdir_set(struct rt_cdir *c, vec3 o, vec3 d)
{
    rt_cpt_set(&c->o, o);
#if NUM_MODE == NUM_MODE_FIXED
    uint32_t m = rt_umax3(rt_uabs(d.x), rt_uabs(d.y), rt_uabs(d.z));
    c->len = 0;
    c->x = c->y = c->z = 0;
    if (m == 0) return;
    int e = 32 - num_clz32(m);               /* m < 2^e <= 2m */
    /* m in [2^(F-8), 2^(F+13)) */
    if (NUM_FRAC < 12 || e < NUM_FRAC - 7 || e > NUM_FRAC + 13) return;
    int32_t s[3];
    c->len = (int32_t)rt_scale10(d, e, s);
    c->x = s[0];
    c->y = s[1];
    c->z = s[2];
#else
    (void)d;
    c->none = 1;
#endif
}

/* The direction part of src into dst (a ray from another origin along the
 * same direction). */
static inline void rt_cdir_copy_dir(struct rt_cdir *dst, const struct rt_cdir *src)
{
#if NUM_MODE == NUM_MODE_FIXED
    dst->x = src->x;
    dst->y = src->y;
    dst->z = src->z;
    dst->len = src->len;
#else
    dst->none = src->none;
#endif
}

#if NUM_MODE == NUM_MODE_FIXED
/* k >= 0 with (t >> k) < 2^15 (t < 2^31). */
static inline int rt_fit15(uint32_t t) { return t < 32768u ? 0 : 17 - num_clz32(t); }

/* The line test in units where co = C - O, n1 = |co|_1 < 2^19 and the
 * sphere's radius with its margin is R units (rc: the radius alone). */
RT_ALWAYS_INLINE int rt_coarse_units_miss(const struct rt_cdir *cd, const int32_t co[3], uint32_t n1, uint32_t R,
                                       uint32_t rc)
{
    int32_t cx = co[0], cy = co[1], cz = co[2];
    uint32_t len = (uint32_t)cd->len;
    /* R < 2^19 + 2^17, len < 2^11: T < 2^31 */
    uint32_t T = R * (len + 2) + 2 * len + 2 * n1 + 3;
    /* |co_i| < 2^19, |d_i| < 2^10: every product < 2^29, the sums < 2^31 */
    int32_t p = cx * cd->x + cy * cd->y + cz * cd->z;
    if (p < 0) {
        uint32_t ap = rt_uabs(p);
        if (ap > T) return 1;                        /* more than R behind the origin */
        /* behind (b < 0, as rt_coarse_dot_negative) and certainly outside
         * (|CO| >= r + 2 units, so c > 0): the robust test's early-out */
        if (ap > 3 * len + 2 * n1 + 5) {
            uint32_t mx = rt_umax3(rt_uabs(cx), rt_uabs(cy), rt_uabs(cz));
            if (mx >= rc + 3 || n1 >= 2 * rc + 5) return 1;
        }
    }
    uint32_t xx = rt_uabs(cy * cd->z - cz * cd->y);
    if (xx > T) return 1;
    uint32_t xy = rt_uabs(cz * cd->x - cx * cd->z);
    if (xy > T) return 1;
    uint32_t xz = rt_uabs(cx * cd->y - cy * cd->x);
    if (xz > T) return 1;
    /* |X|^2 > T^2, scaled down until the squares fit: X rounded down and T
     * up, so the scaled test implies the exact one */
    int k = rt_fit15(T);
    T = (T >> k) + (k > 0);
    xx >>= k; xy >>= k; xz >>= k;
    return xx * xx + xy * xy + xz * xz > T * T;
}
/* The margins of rt_coarse_sphere_miss (derivation above), in fine units
 * U = 2^-10 scene units with n1 = |co|_1 < 2^19: with w = 2^-10,
 * A = (n1 + 2)^2, 2 r m >= M for m = (6.25 A w + 25 (n1 + 2) + 42 / w) /
 * (2 r_raw) (|CO| <= (n1 + 2) w), rt_coarse_margin_2r (all ones when
 * the sphere is too small for it or n1 >= 2^15); m^2 >= M for m = 5 (n1 +
 * 2) 2^(-F/2) + 9 2^(10 - F/2), rt_coarse_margin_sq. */
static inline uint32_t rt_coarse_margin_sq(uint32_t n1)
{
    return ((5u * (n1 + 2) + (1u << (NUM_FRAC / 2)) - 1) >> (NUM_FRAC / 2)) + ((9u << 10) >> (NUM_FRAC / 2)) + 1;
}

static inline uint32_t rt_coarse_margin_2r(const struct rt_csphere *sp, uint32_t n1)
{
    if (!sp->inv2r || n1 >= (1u << 15)) return UINT32_MAX;
    uint32_t a = (n1 + 2) * (n1 + 2);            /* < 2^31 */
    uint32_t num = (((a >> 4) + 1) * 25 >> 8) + 1 + 25 * (n1 + 2) + 43008u;
    return (uint32_t)(num_umul32(num, sp->inv2r) >> 32) + 1;
}

/* R in the coarse units U = 2^12 raw (n1 < 2^19): rc < 2^19 and the margin
 * < 2^16 (F >= 12), so R < 2^19 + 2^17; m = 5 (n1 + 2) 2^(-F/2) +
 * 9 2^(F/2 - 12) <= ceil(5 n1 2^(-F/2)) + 3. */
static inline uint32_t rt_coarse_big_R(const struct rt_csphere *sp, uint32_t n1)
{
    return sp->rc + ((5u * n1 + (1u << (NUM_FRAC / 2)) - 1) >> (NUM_FRAC / 2)) + 3;
}
#endif

#if NUM_MODE == NUM_MODE_FIXED
/* The margin rt_coarse_sphere_miss takes in fine units for n1 <= n (< 2^19):
 * the smaller of the two bounds at n, both non-decreasing in n1; RT_MF_NONE
 * when R = rcf + m + 3 would not stay below 2^19 + 2^17. */
static inline uint32_t rt_coarse_margin_fine(const struct rt_csphere *sp, uint32_t n)
{
    uint32_t m = rt_coarse_margin_sq(n), m2 = rt_coarse_margin_2r(sp, n);
    if (m2 < m) m = m2;
    return sp->rcf + m + 3 < (1u << 19) + (1u << 17) ? m : RT_MF_NONE;
}
#endif

static inline struct rt_csphere rt_csphere_make(vec3 center, num r)
{
    struct rt_csphere s;
    s.c = rt_cpt_make(center);
#if NUM_MODE == NUM_MODE_FIXED
    s.ok = r >= 0;
    uint32_t ur = r > 0 ? (uint32_t)r : 0u;
    s.rc = (ur + 4095u) >> 12;
    s.rcf = NUM_FRAC >= 12 ? (uint32_t)(((uint64_t)ur + (1u << RT_FINE_SHIFT) - 1) >> RT_FINE_SHIFT) : 0u;
    /* floor(2^32 / 2r) + 1 > 2^32 / 2r; r below 2^-10 gets the other bound */
    s.inv2r = ur >= (1u << (NUM_FRAC - 10)) ? num_udiv64_32((uint64_t)1 << 32, 2u * ur, 0) + 1u : 0u;
    for (int j = 0; j < RT_MF_N; j++) s.mf[j] = (uint16_t)rt_coarse_margin_fine(&s, ((uint32_t)1 << (10 + j)) - 1u);
#else
    (void)r;
#endif
    return s;
}

/* num_mul(a, w) for any a and a weight w: with 0 <= w < 1 in Q15.16 the
 * product is below |a| and never saturates, so rt_mul_round_u16 gives its
 * bits; anything else is num_mul's. */
static inline num rt_mul_weight(num a, num w)
{
#if NUM_MODE == NUM_MODE_FIXED && NUM_FRAC == 16
    if ((uint32_t)w < 0x10000u) return rt_mul_round_u16(a, (uint32_t)w);
#endif
    return num_mul(a, w);
}

static inline int rt_coarse_sphere_miss(const struct rt_cdir *cd, const struct rt_csphere *sp)
{
#if NUM_MODE == NUM_MODE_FIXED
    int32_t co[3];
    if (cd->len == 0 || !sp->ok) return 0;
    co[0] = sp->c.fx - cd->o.fx;
    co[1] = sp->c.fy - cd->o.fy;
    co[2] = sp->c.fz - cd->o.fz;
    uint32_t n1 = rt_uabs(co[0]) + rt_uabs(co[1]) + rt_uabs(co[2]);
    if (n1 < (1u << 19)) {
        /* the margin of n1's class (rt_csphere.mf, made once a frame): x =
         * n1 >> 10 < 2^9, class = x's bit length. R < 2^19 + 2^17 keeps T
         * below 2^31; larger spheres use U = 2^12 */
        uint32_t x = n1 >> 10;
        uint32_t m = sp->mf[x >> 8 ? 9 : 8 - num_clz8_tab[x]];
        if (m != RT_MF_NONE) return rt_coarse_units_miss(cd, co, n1, sp->rcf + m + 3, sp->rcf);
    }
    co[0] = sp->c.x - cd->o.x;
    co[1] = sp->c.y - cd->o.y;
    co[2] = sp->c.z - cd->o.z;
    n1 = rt_uabs(co[0]) + rt_uabs(co[1]) + rt_uabs(co[2]);
    if (n1 >= (1u << 19)) return 0;
    return rt_coarse_units_miss(cd, co, n1, rt_coarse_big_R(sp, n1), sp->rc);
#else
    (void)cd; (void)sp;
    return 0;
#endif
}

/* rt_coarse_sphere_miss for rays from one origin (the camera's primary
 * rays): everything but the direction made once a frame. The units, co,
 * |co|_1 and the margin are the ones rt_coarse_sphere_miss picks; of its
 * two margins the smaller is kept (a smaller R only proves more misses, and
 * each is a proof on its own), so a ray it rejects is rejected here too. */
struct rt_ccam {
#if NUM_MODE == NUM_MODE_FIXED
    int32_t co[3];
    uint32_t n1, R, rc;
    uint8_t ok;           /* 0: no coarse tests from this origin */
#else
    uint8_t none;
#endif
};

static inline struct rt_ccam rt_ccam_make(const struct rt_csphere *sp, const struct rt_cpt *o)
{
    struct rt_ccam cc;
#if NUM_MODE == NUM_MODE_FIXED
    cc.ok = 0;
    cc.co[0] = cc.co[1] = cc.co[2] = 0;
    cc.n1 = cc.R = cc.rc = 0;
    if (!sp->ok) return cc;
    int32_t co[3] = { sp->c.fx - o->fx, sp->c.fy - o->fy, sp->c.fz - o->fz };
    uint32_t n1 = rt_uabs(co[0]) + rt_uabs(co[1]) + rt_uabs(co[2]);
    int fine = 0;
    if (n1 < (1u << 19)) {
        uint32_t m = rt_coarse_margin_sq(n1);
        if (sp->rcf + m + 3 < (1u << 19) + (1u << 17)) {
            uint32_t m2 = rt_coarse_margin_2r(sp, n1);
            if (m2 < m) m = m2;
            cc.R = sp->rcf + m + 3;
            cc.rc = sp->rcf;
            fine = 1;
        }
    }
    if (!fine) {
        co[0] = sp->c.x - o->x;
        co[1] = sp->c.y - o->y;
        co[2] = sp->c.z - o->z;
        n1 = rt_uabs(co[0]) + rt_uabs(co[1]) + rt_uabs(co[2]);
        if (n1 >= (1u << 19)) return cc;
        cc.R = rt_coarse_big_R(sp, n1);
        cc.rc = sp->rc;
    }
    cc.co[0] = co[0];
    cc.co[1] = co[1];
    cc.co[2] = co[2];
    cc.n1 = n1;
    cc.ok = 1;
#else
    (void)sp; (void)o;
    cc.none = 1;
#endif
    return cc;
}

/* 1 only when rt_coarse_sphere_miss would be 1 or the robust test misses
 * (cd's origin the one cc was made for). */
RT_ALWAYS_INLINE int rt_coarse_cam_miss(const struct rt_cdir *cd, const struct rt_ccam *cc)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (cd->len == 0 || !cc->ok) return 0;
    return rt_coarse_units_miss(cd, cc->co, cc->n1, cc->R, cc->rc);
#else
    (void)cd; (void)cc;
    return 0;
#endif
}

/* 1 only when (C - O).D is certainly negative by more than 2^12 raw times
 * |D|, so that the robust test's b = -(O - C).D' (rounded, error <= 1.5
 * ulp) is negative: with the coarse forms' errors, |co.d - exact| <=
 * 2 len + n1 + 3, and co.d < -(len + 2) puts C's projection more than one
 * unit behind O. */
static inline int rt_coarse_dot_negative(const struct rt_cdir *cd, const struct rt_cpt *ctr)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (cd->len == 0) return 0;
    int32_t cx = ctr->x - cd->o.x, cy = ctr->y - cd->o.y, cz = ctr->z - cd->o.z;
    uint32_t n1 = rt_uabs(cx) + rt_uabs(cy) + rt_uabs(cz);
    if (n1 >= (1u << 19)) return 0;
    int32_t p = cx * cd->x + cy * cd->y + cz * cd->z;
    return p < 0 && rt_uabs(p) > 3 * (uint32_t)cd->len + 2 * n1 + 5;
#else
    (void)cd; (void)ctr;
    return 0;
#endif
}

/* 1 when num_div(a, b) <= t, decided without dividing (fixed point:
 * correctly rounded quotients, halves away from zero, so for a >= 0, b > 0
 * the quotient is <= t exactly when 2a 2^F < (2t + 1) b). */
static inline int rt_div_at_most(num a, num b, num t)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (a < 0 || b <= 0 || t < 0) return num_div(a, b) <= t;
    return (uint64_t)(uint32_t)a << (NUM_FRAC + 1) < num_umul32(2u * (uint32_t)t + 1u, (uint32_t)b);
#else
    return num_div(a, b) <= t;
#endif
}

/* The largest x in [0, 1] with num_powi(x, e) == 0 (num_powi is monotone
 * in x >= 0: every step of its binary powering rounds monotonically), or
 * -1 when there is none worth using (e == 0, floating modes: pow is 0 only
 * on underflow). */
static inline num rt_powi_zero_below(uint32_t e)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (e == 0) return NUM_C(-1.0);
    num lo = 0, hi = NUM_ONE;             /* powi(lo) == 0, powi(hi) == 1 */
    while (hi - lo > 1) {
        num mid = lo + (hi - lo) / 2;
        if (num_powi(mid, e) == 0) lo = mid;
        else hi = mid;
    }
    return lo;
#else
    (void)e;
    return NUM_C(-1.0);
#endif
}

#if NUM_MODE == NUM_MODE_FIXED
/* v's form for rt_coarse_cos_at_most (rt_scale10); 0 when v's largest
 * component is below 2^(F-2) (|v| < 1/4). *ub gets an upper bound of the
 * scaled |v| + 1. */
static inline int rt_coarse_vec(vec3 v, int32_t c[3], uint32_t *ub)
{
    uint32_t m = rt_umax3(rt_uabs(v.x), rt_uabs(v.y), rt_uabs(v.z));
    if (m < (1u << (NUM_FRAC - 2))) return 0;
    *ub = rt_scale10(v, 32 - num_clz32(m), c) + 1;
    return 1;
}
#endif

/* 1 only when the lighting's cosine num_div(v3_dot(r, v), num_mul(v3_len(r),
 * v3_len(v))) is certainly <= t, decided from 10-bit forms of r and v in
 * 32-bit products (and one 32x32->64): the forms' truncation bounds the
 * true cosine by N / sqrt(Dr Dv) with N = r'.v' + 2 (|r'| + |v'|) + 3 and
 * Dr = r'.r' - 4 |r'|; the exact computation's roundings move the cosine by
 * less than 40 ulps for |r|, |v| >= 1/4, and the test keeps 64 ulps. */
static inline int rt_coarse_cos_at_most(vec3 r, vec3 v, num t)
{
#if NUM_MODE == NUM_MODE_FIXED
    num tm = t - 64;
    int32_t rc[3], vc[3];
    uint32_t lr, lv;
    if (NUM_FRAC < 12 || t < 64 || t > NUM_ONE || !rt_coarse_vec(r, rc, &lr) || !rt_coarse_vec(v, vc, &lv))
        return 0;
    int32_t dp = rc[0] * vc[0] + rc[1] * vc[1] + rc[2] * vc[2];
    int32_t n = dp + (int32_t)(2 * (lr + lv) + 3);
    if (n <= 0) return 1;
    uint32_t dr = (uint32_t)(rc[0] * rc[0] + rc[1] * rc[1] + rc[2] * rc[2]) - 4 * lr;
    uint32_t dv = (uint32_t)(vc[0] * vc[0] + vc[1] * vc[1] + vc[2] * vc[2]) - 4 * lv;
    /* N < 2^22, Dr, Dv < 2^22: mantissas Nh = ceil(N / 2^8) < 2^14,
     * Drh = floor(Dr / 2^6) < 2^16, th = floor(t' 2^(15-F)) <= 2^15;
     * N^2 2^2F <= t'^2 Dr Dv follows from Nh^2 2^34 <= th^2 Drh Dvh */
    uint32_t nh = ((uint32_t)n + 255u) >> 8;
    uint32_t th = NUM_FRAC >= 15 ? (uint32_t)tm >> (NUM_FRAC >= 15 ? NUM_FRAC - 15 : 0)
                                 : (uint32_t)tm << (NUM_FRAC < 15 ? 15 - NUM_FRAC : 0);
    uint64_t lhs = (uint64_t)(nh * nh) << 34;
    uint64_t rhs = num_umul32(th * th, (dr >> 6) * (dv >> 6));
    return lhs <= rhs;
#else
    (void)r; (void)v; (void)t;
    return 0;
#endif
}

/* wnum_mul(t, 1/4) and wnum_mul(t, 4) for 0 <= t < 2^52, bit for bit:
 * round(t / 4) halves up, and 4 t (exact). */
static inline wnum wnum_div4_round(wnum t)
{
#if NUM_MODE == NUM_MODE_FIXED
    return (t + 2) >> 2;
#else
    return wnum_mul(t, NUM_C(0.25));
#endif
}
static inline wnum wnum_mul4(wnum t)
{
#if NUM_MODE == NUM_MODE_FIXED
    return t * 4;
#else
    return wnum_mul(t, NUM_C(4.0));
#endif
}

/* ---- primary rays' candidate lists -----------------------------------
 *
 * How much farther than r from a sphere's centre a line must pass for the
 * sphere test of every ray along it to report a miss (rt_trace.c drops the
 * sphere from a tile's list only then), for a sphere of radius r at
 * distance colen from the camera: 2^-10 (1 + r + colen) covers the fixed
 * test (its discriminant is right to 2^-27 of its terms, rt_quad_solve) and
 * the direction's own rounding when it is scaled (a few ulps, about
 * colen 2^-F); single precision's b^2 - a c adds 3 2^-24 colen^2 / 2r,
 * covered by colen^2 2^-20 / r. */
static inline num rt_tile_eps(num r, num colen)
{
    num e = num_mul(num_add(num_add(NUM_ONE, r), colen), NUM_C(1.0 / 1024));
#if NUM_MODE != NUM_MODE_FIXED
    e = num_add(e, num_div(num_mul(num_mul(colen, colen), NUM_C(1.0 / 1048576)), r));
#endif
    return e;
}

/* ---- the robust sphere test's quadratic --------------------------------
 *
 * a t'^2 - 2 b t' + c = 0 along the scaled direction D' (a = D'.D',
 * b = -CO.D', c = CO.CO - r^2), solved up to q = b + sign(b) sqrt(b^2 - a c).
 *
 * Fixed point forms it from the exact products of the stored inputs: every
 * product of two num is exact at 2F fraction bits in 64 bits, so b is exact,
 * and the discriminant comes from Lagrange's identity
 *   b^2 - a c = a r^2 - |CO x D'|^2
 * whose two terms are built from CO x D' and a (both exact), each brought to
 * 31 bits by a shift before its 32x32 products: the difference keeps at
 * least 29 significant bits of the larger term whatever the cancellation
 * near a silhouette (rounding b and c to the format first, as the floating
 * modes do in their own precision, loses up to about 6 |CO| ulps there).
 * Range: |CO| < 2^15 and |D'_i| < 2 give raw |CO_i D'_j| < 2^(32+F) and
 * sums of three below 2^(34+F), inside int64 for F <= 29; sqrt(disc) <=
 * sqrt(a) r < 2^(16+2F).
 * The floating modes: b and c in wnum, disc = b b - a c. */

/* The sphere's own constant (per frame): r^2, exact at 2F bits (fixed). */
struct rt_qsphere {
#if NUM_MODE == NUM_MODE_FIXED
    uint64_t r2x;
    uint32_t r2s;         /* r2x >> kr, below 2^31 (rt_quad_solve_x's factor) */
    int32_t kr;
#else
    uint8_t none;
#endif
};

static inline struct rt_qsphere rt_qsphere_make(num r)
{
    struct rt_qsphere q;
#if NUM_MODE == NUM_MODE_FIXED
    q.r2x = (uint64_t)num_smul32(r, r);
    int lr = q.r2x ? 64 - num_clz64(q.r2x) : 0;
    q.kr = lr > 31 ? lr - 31 : 0;
    q.r2s = (uint32_t)(q.r2x >> q.kr);
#else
    (void)r;
    q.none = 1;
#endif
    return q;
}

/* One solved quadratic: q in wnum, whether disc > 0; fixed point also
 * keeps q at 2F fraction bits for the far root. */
struct rt_quad {
    wnum q;
    int disc_pos;
#if NUM_MODE == NUM_MODE_FIXED
    int64_t qx;
#endif
};

#if NUM_MODE == NUM_MODE_FIXED
static inline uint64_t rt_mag64(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }
static inline int rt_bitlen64(uint64_t v) { return v ? 64 - num_clz64(v) : 0; }
/* v >> k for k >= 0 (0 from 64 on), in 32-bit halves (ARMv6-M has no
 * 64-bit shift): below 32, (hi << 1) << (31 - k) is hi << (32 - k), and 0
 * for k = 0. */
static inline uint64_t rt_shr64(uint64_t v, int k)
{
    uint32_t hi = (uint32_t)(v >> 32), lo = (uint32_t)v;
    if (k >= 64) return 0;
    if (k >= 32) return hi >> (k - 32);
    return (uint64_t)(hi >> k) << 32 | (lo >> k | (hi << 1) << (31 - k));
}
/* v / 2^k rounded to nearest (half away from zero), 0 <= k < 63. */
static inline int64_t rt_shr_round(int64_t v, int k)
{
    if (k == 0) return v;
    uint64_t m = (rt_mag64(v) + ((uint64_t)1 << (k - 1))) >> k;
    return v < 0 ? -(int64_t)m : (int64_t)m;
}
/* (uint32_t)(v >> k) for 0 <= k < 64 when v >> k < 2^32, in 32-bit halves
 * (ARMv6-M has no 64-bit shift): below 32, (hi << 1) << (31 - k) is hi << (32
 * - k), and 0 for k = 0. */
static inline uint32_t rt_shr64_to32(uint64_t v, int k)
{
    uint32_t hi = (uint32_t)(v >> 32), lo = (uint32_t)v;
    if (k >= 32) return hi >> (k - 32);
    return lo >> k | (hi << 1) << (31 - k);
}
#endif

/* a = D'.D' as the quadratic takes it (once per ray), from D' and its
 * wide dot product as: exact at 2F fraction bits in fixed point, as itself
 * otherwise. */
static inline wnum rt_quad_a(vec3 d, wnum as)
{
#if NUM_MODE == NUM_MODE_FIXED
    (void)as;
    return rt_ssq32(d.x) + rt_ssq32(d.y) + rt_ssq32(d.z);
#else
    (void)d;
    return as;
#endif
}

/* D.D both as v3_dot_wide forms it (*w: each square rounded to F bits,
 * num_mul_round) and as rt_quad_a does (returned), from one set of exact
 * products in fixed point. */
static inline wnum rt_dot_self2(vec3 d, wnum *w)
{
#if NUM_MODE == NUM_MODE_FIXED
    int64_t x = rt_ssq32(d.x), y = rt_ssq32(d.y), z = rt_ssq32(d.z);
    int64_t h = (int64_t)1 << (NUM_FRAC - 1);
    *w = ((x + h) >> NUM_FRAC) + ((y + h) >> NUM_FRAC) + ((z + h) >> NUM_FRAC);
    return x + y + z;
#else
    *w = v3_dot_wide(d, d);
    return rt_quad_a(d, *w);
#endif
}

/* Solves the quadratic of CO and D' (aq = rt_quad_a(D'), c in wnum): 0 when
 * the discriminant is negative or when c > 0 and b <= 0 (both roots at or
 * behind the origin, outside the sphere). */
#if NUM_MODE == NUM_MODE_FIXED
/* The rest of rt_quad_solve from b and CO x D' at 2F fraction bits (bx,
 * x0, x1, x2 exact, x's as magnitudes), once the caller has rejected
 * c > 0 with bx <= 0 (before forming the cross product). */
/* Its discriminant b^2 - a c = a r^2 - |CO x D'|^2 as dd 2^e (at 4F
 * fraction bits): 0 when it is negative, else 1 with *dd and *ep. */
RT_ALWAYS_INLINE int rt_quad_disc_x(uint64_t x0, uint64_t x1, uint64_t x2, wnum aq, const struct rt_qsphere *sp,
                                    uint64_t *dd, int *ep)
{
    uint64_t ax = (uint64_t)aq;
    /* |CO x D'|^2 at scale 2^(2 kx), each component >> kx below 2^30 */
    int lx = rt_bitlen64(x0 | x1 | x2);
    int kx = lx > 30 ? lx - 30 : 0;
    uint32_t s0 = rt_shr64_to32(x0, kx), s1 = rt_shr64_to32(x1, kx), s2 = rt_shr64_to32(x2, kx);
    uint64_t xx = rt_usq32(s0) + rt_usq32(s1) + rt_usq32(s2);
    /* a r^2 at scale 2^(ka + kr), both factors below 2^31 */
    int la = rt_bitlen64(ax);
    int ka = la > 31 ? la - 31 : 0, kr = sp->kr;
    uint64_t ar = num_umul32((uint32_t)(ax >> ka), sp->r2s);
    /* to the coarser scale e = max(2 kx, ka + kr): one of the two shifts */
    int e;
    if (2 * kx > ka + kr) {
        e = 2 * kx;
        ar = rt_shr64(ar, e - ka - kr);
    } else {
        e = ka + kr;
        xx = rt_shr64(xx, e - 2 * kx);
    }
    if (ar < xx) return 0;
    *dd = ar - xx;
    *ep = e;
    return 1;
}

/* q from b (bx) and the discriminant dd 2^e of rt_quad_disc_x. */
RT_ALWAYS_INLINE void rt_quad_root_x(int64_t bx, uint64_t dd, int e, struct rt_quad *k)
{
    k->disc_pos = dd > 0;
    if (e & 1) { dd <<= 1; e--; }            /* dd < 2^62 */
    int64_t hx = (int64_t)(num_isqrt64(dd, 0) << (e / 2));
    k->qx = bx >= 0 ? bx + hx : bx - hx;
    k->q = rt_shr_round(k->qx, NUM_FRAC);
}

RT_ALWAYS_INLINE int rt_quad_solve_x(int64_t bx, uint64_t x0, uint64_t x1, uint64_t x2, wnum aq,
                                     const struct rt_qsphere *sp, struct rt_quad *k)
{
    uint64_t dd;
    int e;
    if (!rt_quad_disc_x(x0, x1, x2, aq, sp, &dd, &e)) return 0;
    rt_quad_root_x(bx, dd, e, k);
    return 1;
}
#endif

/* ---- a near root beyond the limit, decided before the square root -----
 *
 * From outside (c > 0) with b > 0 the near root is c / q, q = b + h, h the
 * computed sqrt of the discriminant. When c >= |CO|^2 2^-16 (exactly, at 2F
 * bits) and a >= 2^28, h <= b: rt_quad_solve_x's truncations raise its
 * discriminant above b^2 - a c by at most E <= 2^-25 |CO x D'|^2 (kx > 0)
 * + 2^e, with |CO x D'|^2 <= a |CO|^2, and 2^e <= max(1, a 2^-30)
 * max(1, r^2 2^-30) (r^2 < |CO|^2), both below a c; so its h^2 <= b^2. Then
 * q <= Qu = floor((2 bx + 2^(F-1)) / 2^F) (bx: b at 2F bits), and the
 * rounded near root n / q (wnum_div: halves up, saturating; or, for
 * q >= 2^32, both shifted by sh with q >= 2^(31+sh), rt_quad_near_m) is
 * above a limit 0 <= L < 2^30 whenever n 2^F >= (L + 1) Qu: the shifts' half
 * units cost at most q (L 2^-32 + 2^(F-32)) < q / 2 of the half unit L + 1
 * has over L + 1/2. rt_near_c_ok checks the first condition from c and
 * dot = CO.CO in wnum (each within 2 units of the exact values at F bits):
 * c >= ((dot + 2) >> 16) + 3 implies it. Fixed point only. */
static inline int rt_near_c_ok(wnum c, wnum dot)
{
#if NUM_MODE == NUM_MODE_FIXED
    return dot >= 0 && dot < ((wnum)1 << 60) && c >= ((dot + 2) >> 16) + 3;
#else
    (void)c; (void)dot;
    return 0;
#endif
}

/* n and aq within rt_near_beyond's range (0 in floating modes): checked
 * once a frame for the camera's spheres (rt_obj_cache.near_ok), aq there
 * for every exact primary direction (x vh, y vh, d h) at once by
 * rt_near_dir_ok: a = (x vh)^2 + (y vh)^2 + (d h)^2 >= 2^28 when |d| h >=
 * 2^14 raw. */
static inline int rt_near_n_ok(wnum n)
{
#if NUM_MODE == NUM_MODE_FIXED
    return NUM_FRAC <= 20 && n > 0 && n < ((wnum)1 << (62 - NUM_FRAC));
#else
    (void)n;
    return 0;
#endif
}

static inline int rt_near_na_ok(wnum n, wnum aq)
{
#if NUM_MODE == NUM_MODE_FIXED
    return rt_near_n_ok(n) && aq >= ((wnum)1 << 28);
#else
    (void)n; (void)aq;
    return 0;
#endif
}

static inline int rt_near_dir_ok(num d, uint32_t h)
{
#if NUM_MODE == NUM_MODE_FIXED
    uint32_t ad = d < 0 ? 0u - (uint32_t)d : (uint32_t)d;
    return ad >= (1u << 14) || ad * h >= (1u << 14);   /* ad < 2^14, h < 2^16: no overflow */
#else
    (void)d; (void)h;
    return 0;
#endif
}

/* rt_near_beyond once rt_near_na_ok(n, aq) holds. */
RT_ALWAYS_INLINE int rt_near_beyond_na(int64_t bx, wnum n, num limit)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (limit < 0 || limit >= ((num)1 << 30) || bx < ((int64_t)1 << NUM_FRAC) || bx >= ((int64_t)1 << 60))
        return 0;
    /* Qu < 2^(61-F) (bx < 2^60): both sides divided by 2^s, s = 30 - F
     * (constant shifts; Qu / 2^s < 2^31), Qu rounded up: floor(n 2^F / 2^s)
     * >= (L + 1) (floor(Qu / 2^s) + 1) implies the unscaled test. (For the
     * Qu of a pixel's ray, about 2^37, the rounding up costs 2^-23 of it.) */
    const int s = 30 - NUM_FRAC;
    uint64_t qu = ((uint64_t)bx * 2u + (1u << (NUM_FRAC - 1))) >> NUM_FRAC;
    uint32_t qs = (uint32_t)(qu >> s) + 1u;
    return ((uint64_t)n << NUM_FRAC) >> s >= num_umul32((uint32_t)limit + 1u, qs);
#else
    (void)bx; (void)n; (void)limit;
    return 0;
#endif
}

/* 1 only when the near root n / q of the quadratic with b = bx (2F bits),
 * a = aq, c and |CO|^2 passing rt_near_c_ok is certainly above limit (0 in
 * floating modes). */
static inline int rt_near_beyond(int64_t bx, wnum n, wnum aq, num limit)
{
    return rt_near_na_ok(n, aq) && rt_near_beyond_na(bx, n, limit);
}

RT_ALWAYS_INLINE int rt_quad_solve(vec3 co, vec3 d, wnum aq, wnum c, const struct rt_qsphere *sp, struct rt_quad *k)
{
#if NUM_MODE == NUM_MODE_FIXED
    int64_t bx = -(num_smul32(co.x, d.x) + num_smul32(co.y, d.y) + num_smul32(co.z, d.z));
    if (c > 0 && bx <= 0) return 0;
    return rt_quad_solve_x(bx, rt_mag64(num_smul32(co.y, d.z) - num_smul32(co.z, d.y)),
                           rt_mag64(num_smul32(co.z, d.x) - num_smul32(co.x, d.z)),
                           rt_mag64(num_smul32(co.x, d.y) - num_smul32(co.y, d.x)), aq, sp, k);
#else
    (void)sp;
    wnum b = wnum_sub(wnum_from_num(NUM_ZERO), v3_dot_wide(co, d));
    if (c > 0 && b <= 0) return 0;
    wnum disc = wnum_sub(wnum_mul(b, b), wnum_mul(aq, c));
    if (disc < 0) return 0;
    k->disc_pos = disc > 0;
    wnum h = wnum_sqrt(disc);
    k->q = b >= 0 ? wnum_add(b, h) : wnum_sub(b, h);
#endif
    return 1;
}

/* x / |N| for a vector of length 1 up to rounding (a sphere's (P - C) / r),
 * fixed point: with e = N.N - 1 from exact products, 1 / |N| = 1 - e/2 +
 * 3 e^2 / 8 - ..., so x (1 - e/2) is within 2^-25 |x| of x / |N| when
 * |e| < 2^-12. rt_near_unit_err: 1 and e at 2F fraction bits in that case
 * (once per normal), else 0 (and 0 in floating modes, whose callers divide
 * by |N|); rt_div_near_unit: 1 and x (1 - e/2) rounded, 0 if it leaves the
 * format. */
static inline int rt_near_unit_err(vec3 n, int32_t *e)
{
#if NUM_MODE == NUM_MODE_FIXED
    int64_t d = rt_ssq32(n.x) + rt_ssq32(n.y) + rt_ssq32(n.z) - ((int64_t)1 << (2 * NUM_FRAC));
    int64_t lim = (int64_t)1 << (2 * NUM_FRAC - 12);
    if (d <= -lim || d >= lim) return 0;
    *e = (int32_t)d;
    return 1;
#else
    (void)n; (void)e;
    return 0;
#endif
}

static inline int rt_div_near_unit(num x, int32_t e, num *out)
{
#if NUM_MODE == NUM_MODE_FIXED
    /* |x e| < 2^31 2^(2F-12) <= 2^59; x - x e / 2^(2F+1), rounded */
    int64_t r = (int64_t)x - rt_shr_round(num_smul32(x, e), 2 * NUM_FRAC + 1);
    if (r > INT32_MAX || r < INT32_MIN) return 0;
    *out = (num)r;
    return 1;
#else
    (void)x; (void)e; (void)out;
    return 0;
#endif
}

/* ---- primary rays' exact candidate intervals, per row and sphere ---------
 *
 * Along a row of exact primary directions D = (v k, Y, Z) (v = Vh raw, k the
 * canvas column, rt_exact_comp) the sphere test of rt_quad_solve_x reports
 * a miss when a r^2 < |CO x D|^2 after its truncations: s_i = |x_i| >> kx
 * loses less than 2^(kx+1) sum |x_i| of |CO x D|^2 (at 2^-2kx), a and r^2
 * only lose, and the final shifts one unit of 2^e, e = max(2 kx, ka + kr).
 * With 2^kx <= max |x_i| 2^-29 (kx > 0), 2^ka <= max(1, a 2^-30), 2^kr <=
 * max(1, r^2 2^-30) and |CO x D|^2 <= |CO|^2 a, that is at most
 *   E = a (|CO|^2 2^-25 + r^2 2^-60 + 2^-30) + r^2 2^-30 + 2^34,
 * so the test misses wherever
 *   g(k) = a (r^2 + T) + R0 - |CO x D|^2 <= 0
 * (T = floor(|CO|^2 2^-25) + floor(r^2 2^-60) + 3, R0 = floor(r^2 2^-30) +
 * 2^34 + 1; every quantity an exact integer at 2F or 4F fraction bits). g is
 * a quadratic in k: g = A k^2 + 2 B k + C with
 *   A = v^2 (r^2 + T - CO.y^2 - CO.z^2)            (per frame)
 *   B = v CO.x P, P = CO.y Y + CO.z Z              (per row)
 *   C = (Y^2 + Z^2)(r^2 + T - CO.x^2) - (CO.y Z - CO.z Y)^2 + R0,
 * and for A < 0 concave: g(p) <= 0 with g(p) >= g(p - 1) (A (2p - 1) + 2B
 * >= 0) puts every k <= p at or below g(p), and g(p) <= 0 with g(p + 1) <=
 * g(p) every k >= p. The roots are found approximately (64-bit, the three
 * coefficients scaled alike), then proven by those two conditions in exact
 * 128-bit arithmetic; the columns outside [lo, hi] skip the sphere. So do
 * all when c > 0 and b <= 0 at both ends (b is linear in k: behind the
 * camera). Range: |CO_i| < 2^30, |Y|, |Z|, |v k| < 2^28, v < 2^20 and |k| <=
 * 2^10 keep every sum and product below 2^126. Fixed point only; the
 * functions are in rt_intersect.c. */
#if NUM_MODE == NUM_MODE_FIXED
struct rt_s128 {
    uint64_t lo, hi;      /* two's complement */
};
#endif

/* A sphere's per-frame part of the row intervals (A, r^2 + T - CO.x^2, R0,
 * v CO.x); ok 0: none (every column tries the sphere). */
struct rt_ivsphere {
#if NUM_MODE == NUM_MODE_FIXED
    struct rt_s128 a;
    int64_t rc;
    uint64_t r0;
    int64_t vcx;
    int32_t v, cy, cz;
    uint8_t ok;
#else
    uint8_t ok;
#endif
};

/* The sphere's part from CO (camera - centre), r^2 at 2F bits and v = Vh
 * (rt_intersect.c). */
struct rt_ivsphere rt_ivsphere_make(vec3 co, uint64_t r2x, num v);

/* The columns k in [kmin, kmax] of the row (Y, Z; yz = Y^2 + Z^2 at 2F
 * bits) whose rays may meet the sphere (c = CO.CO - r^2 as the test takes
 * it): 1 and [*lo, *hi] (lo > hi: none), or 0 when not proven (every column
 * tries it). */
int rt_iv_row(const struct rt_ivsphere *iv, wnum c, num y, num z, wnum yz, int32_t kmin, int32_t kmax,
              int32_t *lo, int32_t *hi);

/* ---- primary rays along their exact directions ---------------------------
 *
 * A pixel's primary direction is D = (x Vw / W, y Vh / H, d) with
 * Vw = Vh W / H, i.e. (x Vh, y Vh, d H) / H for the integer canvas point
 * (x, y): a direction the format cannot hold exactly (x / 240 is rounded)
 * but whose multiple by H it can, when Vh and d are in the format and the
 * products fit. The sphere test's decision and its near root depend only
 * on the line, so fixed point solves the quadratic along Dm = D H from the
 * exact products of its inputs (rt_quad_solve) and takes t = c H / q:
 * hits and misses as exact arithmetic decides them (up to the
 * discriminant's 29 significant bits), not as the rounded D would — a ray
 * exactly tangent to a sphere, or missing it by less than the direction's
 * rounding, no longer turns on that rounding. Range: |Dm_i| < 2^10 keeps
 * the products of rt_quad_solve within int64 (|CO_i Dm_j| < 2^(41+F), sums
 * of three and a = Dm.Dm below 2^(63)) and c H below 2^61 raw (H <= 1024).
 * The floating modes keep D (rt_exact_comp says 0). */

/* v k for |k| <= 1024 exactly into *out, 1 when it fits the exact
 * directions' range (|v k| < 2^(F+10)); 0 otherwise and in floating modes. */
static inline int rt_exact_comp(num v, int32_t k, num *out)
{
#if NUM_MODE == NUM_MODE_FIXED
    /* |v| < 2^20 and |k| <= 1024: the product fits 31 bits (one MULS) */
    int32_t lim = (int32_t)1 << (NUM_FRAC + 10 < 30 ? NUM_FRAC + 10 : 30);
    if (k < -1024 || k > 1024 || v <= -(1 << 20) || v >= (1 << 20)) return 0;
    int32_t p = v * k;
    if (p <= -lim || p >= lim) return 0;
    *out = p;
    return 1;
#else
    (void)v; (void)k; (void)out;
    return 0;
#endif
}

/* A turned camera (rotation q at 29 fraction bits): row part rp = q (0, vy,
 * vz) at F + 29 bits, once a row. */
static inline void rt_exact_turn_row(const int32_t (*q)[3], num vy, num vz, int64_t rp[3])
{
#if NUM_MODE == NUM_MODE_FIXED
    for (int i = 0; i < 3; i++) rp[i] = num_smul32(q[i][1], vy) + num_smul32(q[i][2], vz);
#else
    (void)q; (void)vy; (void)vz;
    rp[0] = rp[1] = rp[2] = 0;
#endif
}

/* The turned direction q (vx, vy, vz) rounded once to the format into *out
 * (rp from rt_exact_turn_row): 1 when every component stays within the exact
 * directions' range |c| < 2^(F+10). Not exact, but 0.5 ulp of a direction
 * H times longer than D, and of the scene file's own matrix rather than
 * its rounding to the format. */
static inline int rt_exact_turn(const int32_t (*q)[3], const int64_t rp[3], num vx, vec3 *out)
{
#if NUM_MODE == NUM_MODE_FIXED
    num c[3];
    int64_t lim = (int64_t)1 << (NUM_FRAC + 10);
    for (int i = 0; i < 3; i++) {
        /* |q| < 2^31, |v| < 2^(F+10): each term < 2^(41+F), the sum < 2^(43+F) */
        int64_t v = rt_shr_round(rp[i] + num_smul32(q[i][0], vx), 29);
        if (v <= -lim || v >= lim) return 0;
        c[i] = (num)v;
    }
    out->x = c[0];
    out->y = c[1];
    out->z = c[2];
    return 1;
#else
    (void)q; (void)rp; (void)vx; (void)out;
    return 0;
#endif
}

/* One component's square at 2F fraction bits (a part of rt_quad_a). */
static inline wnum rt_exact_sq(num v)
{
#if NUM_MODE == NUM_MODE_FIXED
    return rt_ssq32(v);
#else
    return wnum_mul(wnum_from_num(v), wnum_from_num(v));
#endif
}

/* wnum_div(a, b), bit for bit, with its common case inline: fixed point,
 * a >= 0, 0 < b < 2^32 and a 2^F < 2^63, the rounded quotient below 2^31
 * (halves up, as div_round_signed in num.c); anything else, saturation
 * included, goes to wnum_div. */
static inline num rt_wdiv(wnum a, wnum b)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (a >= 0 && b > 0 && b <= (wnum)UINT32_MAX && a < ((wnum)1 << (63 - NUM_FRAC))) {
        uint64_t n = (uint64_t)a << NUM_FRAC;
        uint32_t d = (uint32_t)b, rm;
        if ((n >> 32) < d) {
            uint64_t q = num_udiv64_32(n, d, &rm);
            if (rm >= d - rm) q++;
            if (q <= (uint64_t)INT32_MAX) return (num)q;
        }
    }
#endif
    return wnum_div(a, b);
}

/* c m, the numerator of the near root c m / q along D of a quadratic
 * solved along D m (|c m| < 2^61 raw: m <= 1024 and |CO| in the format). */
static inline wnum rt_quad_near_num(wnum c, int32_t m)
{
#if NUM_MODE == NUM_MODE_FIXED
    return c * m;
#else
    return wnum_mul(c, num_from_int(m));
#endif
}

/* The near root n / q along D (q != 0, n = rt_quad_near_num(c, m)): fixed
 * point shifts both to the division's 64/32 fast path (q along D m is m
 * times larger than along D). */
static inline num rt_quad_near_m(wnum n, const struct rt_quad *k)
{
#if NUM_MODE == NUM_MODE_FIXED
    /* q to 32 bits (n then stays within the fast path: n / q = t < 2^(31-F)) */
    int sh = rt_bitlen64(rt_mag64(k->q)) - 32;
    if (sh <= 0) return rt_wdiv(n, k->q);
    return rt_wdiv(rt_shr_round(n, sh), rt_shr_round(k->q, sh));
#else
    return wnum_div(n, k->q);
#endif
}

/* n1/d1 < n2/d2 for positive fractions (rt_frac), decided on 31
 * significant bits of the numerators and of the denominators (each pair
 * shifted alike): ties at that precision, about 2^-30, are not less. */
static inline int rt_frac_less(wnum n1, wnum d1, wnum n2, wnum d2)
{
#if NUM_MODE == NUM_MODE_FIXED
    uint64_t a = (uint64_t)n1, b = (uint64_t)d2, c = (uint64_t)n2, d = (uint64_t)d1;
    int ln = rt_bitlen64(a | c), ld = rt_bitlen64(b | d);
    int kn = ln > 31 ? ln - 31 : 0, kd = ld > 31 ? ld - 31 : 0;
    return num_umul32((uint32_t)(a >> kn), (uint32_t)(b >> kd)) < num_umul32((uint32_t)(c >> kn), (uint32_t)(d >> kd));
#else
    return n1 * d2 < n2 * d1;
#endif
}

/* The far root q/a along D' (q != 0); fixed point divides q and a at 2F
 * bits, shifted together into the division's 64/32 fast path. */
static inline num rt_quad_far(const struct rt_quad *k, wnum aq)
{
#if NUM_MODE == NUM_MODE_FIXED
    int lq = rt_bitlen64(rt_mag64(k->qx)), la = rt_bitlen64((uint64_t)aq);
    int sh = la - 32 > lq - (62 - NUM_FRAC) ? la - 32 : lq - (62 - NUM_FRAC);
    if (sh < 0) sh = 0;
    return rt_wdiv(rt_shr_round(k->qx, sh), (wnum)((uint64_t)aq >> sh));
#else
    return wnum_div(k->q, aq);
#endif
}

#endif
