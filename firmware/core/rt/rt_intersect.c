/* SPDX-License-Identifier: MIT */
/* rt_intersect.c — rays against objects: IntersectRaySphere (chapter 2),
 * ClosestIntersection (walking the bounding-sphere hierarchy rt_scene.c
 * builds), and chapter 5's planes, triangles and CSG of spheres.
 *
 * Two formulations of the sphere test (raytracer.h): the book's, for the
 * reference build, and a robust one for fixed point. Range argument of the
 * robust one, in Q15.16 with wnum = int64 Q47.16 (saturating at 2^61 raw,
 * 3.5e13 in value):
 *   the direction is scaled by a power of two to |D'| in [0.5, 2) (t scales
 *   back exactly by the same power), so with |CO| < 32768:
 *   |b| = |CO.D'| < 65536, b^2 < 4.3e9; a = D'.D' < 4; |c| = |CO.CO - r^2| <
 *   2.2e9; a*c < 8.6e9 — all far inside wnum. sqrt(b^2 - a c) <= |b|, q =
 *   b + sign(b) sqrt(..) < 131072 stays wide; the roots q/a and c/q are
 *   rounded once into num (saturating to +-NUM_MAX, which the strict range
 *   tests then reject). The near root c/q has no cancellation: for the
 *   book's ground seen from the camera c = 5001^2 - 5000^2 = 10001 exactly.
 */
#include "rt_int.h"
#include "rt_prim_v6m.h"

/* The ray, with a copy of its direction scaled by a power of two for the
 * robust tests: D' = D / 2^k with D'.D' in [0.25, 4), and tscale = 2^-k,
 * which turns a root t' along D' into t along D. */
static inline void ray_fill(struct rt_ray *r, const vec3 *op, const vec3 *dp, int16_t origin, uint8_t from_camera)
{
    /* by components: a struct copy here becomes a memcpy call on ARMv6-M */
    r->o.x = op->x; r->o.y = op->y; r->o.z = op->z;
    r->d.x = dp->x; r->d.y = dp->y; r->d.z = dp->z;
    r->origin = origin;
    r->from_camera = from_camera;
    r->exact = 0;   /* a, ds, as, aq and tscale: set by rt_ray_exact before any use */
    r->dxm = 0;
    r->dxrow = -1;
}

void rt_ray_init(struct rt_ray *r, const vec3 *op, const vec3 *dp, int16_t origin, uint8_t from_camera)
{
    vec3 o, d;
    o.x = op->x; o.y = op->y; o.z = op->z;
    d.x = dp->x; d.y = dp->y; d.z = dp->z;
    ray_fill(r, &o, &d, origin, from_camera);
    rt_cdir_set(&r->cd, o, d);
    r->cd_todo = 0;
}

void rt_ray_init_primary(struct rt_ray *r, const vec3 *op, const vec3 *dp)
{
    ray_fill(r, op, dp, -1, 1);
    r->cd_todo = 1;
}

void rt_ray_cd_now(struct rt_ray *r)
{
    r->cd_todo = 0;
    rt_cdir_set(&r->cd, r->o, r->d);
}

struct rt_ray rt_make_ray(vec3 o, vec3 d, int16_t origin, uint8_t from_camera)
{
    struct rt_ray r;
    rt_ray_init(&r, &o, &d, origin, from_camera);
    return r;
}

/* v3_scale(d, ts) for ts = 2^-k (k > 0): in fixed point with ts exactly
 * 2^(F-k) raw the rounded product (d_i 2^(F-k) + 2^(F-1)) >> F is (d_i +
 * 2^(k-1)) >> k, never saturating: d_i >> k plus bit k - 1 of d_i, the
 * same bits without the 64-bit products. */
static inline vec3 ray_scale_down(vec3 d, num ts, int k)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (k <= NUM_FRAC && ts == (num)((uint32_t)NUM_ONE_RAW >> k))
        return v3_make((d.x >> k) + ((d.x >> (k - 1)) & 1), (d.y >> k) + ((d.y >> (k - 1)) & 1),
                       (d.z >> k) + ((d.z >> (k - 1)) & 1));
#else
    (void)k;
#endif
    return v3_scale(d, ts);
}

#if NUM_MODE == NUM_MODE_FIXED
/* theta_j, the least t with t quartered j times ((t + 2) >> 2 each) at
 * least 4 (2^(F+2) raw): theta_0 = 2^(F+2), theta_(j+1) = 4 theta_j - 2
 * ((t + 2) >> 2 >= theta exactly when t >= 4 theta - 2), so theta_j =
 * 4^j 2^(F+2) - 2 (4^j - 1) / 3. */
#define RT_QTH(j) ((wnum)((((uint64_t)1 << (NUM_FRAC + 2 + 2 * (j))) - ((((uint64_t)1 << (2 * (j))) - 1) / 3) * 2)))
static const wnum rt_quarter_th[15] = { RT_QTH(0), RT_QTH(1), RT_QTH(2),  RT_QTH(3),  RT_QTH(4),
                                        RT_QTH(5), RT_QTH(6), RT_QTH(7),  RT_QTH(8),  RT_QTH(9),
                                        RT_QTH(10), RT_QTH(11), RT_QTH(12), RT_QTH(13), RT_QTH(14) };
#undef RT_QTH
#endif

void rt_ray_exact(struct rt_ray *r)
{
    if (r->exact) return;
    r->exact = 1;
    vec3 d = r->d;
    wnum a, aq = rt_dot_self2(d, &a);   /* a = v3_dot_wide(d, d), aq = rt_quad_a(d, a) */
    r->a = a;
    /* find k from a alone (a/4 per halving), then scale once: exact */
    num ts = NUM_ONE;
    wnum four = wnum_from_num(NUM_C(4.0)), quarter = wnum_from_num(NUM_C(0.25));
    int k = 0;
    /* t * 1/4 and t * 4 rounded as wnum_mul rounds them (t >= 0) */
#if NUM_MODE == NUM_MODE_FIXED
    /* the quarterings' count from a alone: t_j = a quartered j times
     * ((t + 2) >> 2 each) is >= 4 exactly when a >= rt_quarter_th[j] */
    (void)four;
    while (k < 15 && a >= rt_quarter_th[k]) k++;
#else
    for (wnum t = a; t >= four && k < 15; k++) t = wnum_div4_round(t);
#endif
    if (k == 0)
        for (wnum t = a; t < quarter && t > 0 && k > -8; k--) t = wnum_mul4(t);
    if (k > 0) {
#if NUM_MODE == NUM_MODE_FIXED
        /* wnum_to_num_shr(2^F raw, k): 2^(F-k) for k <= F, its rounding's
         * 1 for k = F + 1, else 0 */
        ts = k <= NUM_FRAC ? (num)(NUM_ONE_RAW >> k) : (num)(k == NUM_FRAC + 1);
#else
        ts = wnum_to_num_shr(wnum_from_num(NUM_ONE), k);
#endif
        d = ray_scale_down(d, ts, k);
        aq = rt_dot_self2(d, &a);
    } else if (k < 0) {
        ts = num_mul_int(NUM_ONE, 1 << -k);
        d = v3_scale(d, ts);
        aq = rt_dot_self2(d, &a);
    }
    r->ds = d;
    r->as = a;
    r->aq = aq;
    r->tscale = ts;
}

static num scale_t(num t, num tscale)
{
    return tscale == NUM_ONE ? t : num_mul(t, tscale);
}

/* The robust test's quadratic a t'^2 - 2 b t' + c = 0 along ds (t = t' ts),
 * up to q = b + sign(b) sqrt(b^2 - a c); 0 when it has no root or both
 * roots are <= 0 with the origin outside (c > 0, b <= 0), which every
 * caller rejects (t_min >= 0). Not for a ray leaving this sphere. */
struct sphere_quad {
    wnum a, c;
    num ts;
    int32_t m;            /* solved along the exact direction D m (ray->dx): roots t' m */
    wnum cm;              /* c m */
    struct rt_quad k;     /* q, disc > 0 (rt_num.h) */
};

/* sphere_quad along an unturned exact primary direction from the camera:
 * the row's parts of b and CO x D once a row per sphere (rt_obj_cache),
 * then three products a pixel instead of nine; the same integers, so the
 * same bits as rt_quad_solve. */
#if NUM_MODE == NUM_MODE_FIXED
/* the row's parts of b and CO x D (rt_obj_cache.px_row) for ray's row */
RT_ALWAYS_INLINE void sphere_row_parts(struct rt_obj_cache *oc, const struct rt_ray *ray)
{
    vec3 co = oc->co_cam;
    if (oc->px_row != ray->dxrow) {
        oc->px_row = ray->dxrow;
        oc->px_b = -(num_smul32(co.y, ray->dx.y) + num_smul32(co.z, ray->dx.z));
        oc->px_x0 = rt_mag64(num_smul32(co.y, ray->dx.z) - num_smul32(co.z, ray->dx.y));
        oc->px_x2 = num_smul32(co.x, ray->dx.y);
        oc->px_cxd = num_smul32(co.x, ray->dx.z);
    }
}
#endif

RT_ALWAYS_INLINE int sphere_quad_row(struct rt_obj_cache *oc, const struct rt_ray *ray, struct sphere_quad *k, num limit)
{
#if NUM_MODE == NUM_MODE_FIXED
    vec3 co = oc->co_cam;
    sphere_row_parts(oc, ray);
    int64_t bx = oc->px_b - num_smul32(co.x, ray->dx.x);
    if (k->c > 0 && bx <= 0) return 0;
    /* the near root certainly beyond the limit (rt_near_beyond) */
    if (oc->near_ok && rt_near_beyond_na(bx, k->cm, limit)) return 0;
    return rt_quad_solve_x(bx, oc->px_x0, rt_mag64(num_smul32(co.z, ray->dx.x) - oc->px_cxd),
                           rt_mag64(oc->px_x2 - num_smul32(co.y, ray->dx.x)), k->a, &oc->qs, &k->k);
#else
    (void)oc; (void)ray; (void)k; (void)limit;
    return 0;
#endif
}

#if NUM_MODE == NUM_MODE_FIXED
static int turn_touch(const struct rt_state *rt, vec3 co, const struct rt_ray *ray, uint64_t r2x, wnum c,
                      struct rt_quad *k);
#endif

/* limit: 0 may also mean that the near root is certainly above it (then
 * sphere_first_hit's answer is "no hit" whatever the roots); NUM_MAX for
 * the roots themselves. */
static int sphere_quad(const struct rt_state *rt, int16_t obj, struct rt_ray *ray, struct sphere_quad *k,
                       int coarse_done, num limit)
{
    const struct rt_object *o = &rt->s->objects[obj];
    const struct rt_obj_cache *oc = &rt->oc[obj];
    int cam = ray->from_camera && rt->cached;
    /* certain misses, decided in 32-bit arithmetic (rt_num.h): the test
     * below would return 0 too (coarse_done: the caller has tried it) */
    if (rt->shortcuts && !coarse_done) {
        rt_ray_cd(ray);
        if (rt_coarse_sphere_miss(&ray->cd, &oc->cs)) return 0;
    }
    vec3 co;
    if (cam) {   /* by components: a struct copy here becomes a memcpy call on ARMv6-M */
        co.x = oc->co_cam.x;
        co.y = oc->co_cam.y;
        co.z = oc->co_cam.z;
    } else {
        co = v3_sub(ray->o, o->center);
    }
    /* c = CO.CO - r^2 (per frame from the camera: the same value) */
    k->c = cam ? oc->c_cam : wnum_sub(v3_dot_wide(co, co), oc->r2);
    const vec3 *dir;
    if (ray->dxm) {
        /* a pixel's primary ray along its exact direction (rt_exact_comp) */
        k->a = ray->dxa;
        k->m = ray->dxm;
        k->cm = cam ? oc->cm_cam : rt_quad_near_num(k->c, ray->dxm);   /* dxm is the height */
        k->ts = NUM_ONE;
        /* the row parts are a cache in the work memory, which is never const */
        if (cam && ray->dxrow >= 0) return sphere_quad_row((struct rt_obj_cache *)oc, ray, k, limit);
        dir = &ray->dx;
    } else {
        rt_ray_exact(ray);
        k->a = ray->aq;
        k->ts = ray->tscale;
        k->m = 0;
        dir = &ray->ds;
    }
    int got = rt_quad_solve(co, *dir, k->a, k->c, &oc->qs, &k->k);
#if NUM_MODE == NUM_MODE_FIXED
    /* a turned camera's direction, rounded once: a touch along the
     * unrounded one is kept (turn_touch) */
    if (!got && k->m && ray->dxrow < 0) got = turn_touch(rt, co, ray, oc->qs.r2x, k->c, &k->k);
#endif
    return got;
}

/* The quadratic's roots (q != 0), t along D: the near one c/q from
 * outside, and q/a. Along an exact direction D m the near root is c m / q;
 * the far one, needed only when the near one is not the hit (the camera
 * inside, or the near root at or before t_min: rare for primary rays), is
 * solved along D' (where that quadratic has no root, the near one), and
 * never below the near one. */
static num quad_near(const struct sphere_quad *k)
{
    if (k->m) return rt_quad_near_m(k->cm, &k->k);
    return scale_t(rt_wdiv(k->c, k->k.q), k->ts);
}

/* The near root's fraction (rt_frac): c m / q along an exact direction. */
static void quad_near_frac(const struct sphere_quad *k, struct rt_frac *f)
{
    f->n = k->m ? k->cm : 0;
    f->d = k->m ? k->k.q : 0;
}

/* Whether a near root t equal to limit comes before the hit that set it
 * (best, whose t is limit): only when both have fractions and t's is less. */
static int tie_first(const struct rt_frac *f, const struct rt_hit *best, num limit)
{
    return f->d > 0 && best->fr.d > 0 && best->t == limit && rt_frac_less(f->n, f->d, best->fr.n, best->fr.d);
}

static num quad_far(const struct rt_state *rt, int16_t obj, struct rt_ray *ray, const struct sphere_quad *k)
{
    if (!k->m) return scale_t(rt_quad_far(&k->k, k->a), k->ts);
    num near = quad_near(k);
    struct rt_quad k2;
    rt_ray_exact(ray);
    vec3 co = ray->from_camera && rt->cached ? rt->oc[obj].co_cam : v3_sub(ray->o, rt->s->objects[obj].center);
    if (!rt_quad_solve(co, ray->ds, ray->aq, k->c, &rt->oc[obj].qs, &k2) || k2.q == 0) return near;
    num far = scale_t(rt_quad_far(&k2, ray->aq), ray->tscale);
    return far > near ? far : near;
}

/* O on the sphere (the ray leaves it): b, with the roots exactly 0 and 2b/a. */
static wnum sphere_self_b(const struct rt_state *rt, int16_t obj, struct rt_ray *ray)
{
    rt_ray_exact(ray);
    vec3 co = v3_sub(ray->o, rt->s->objects[obj].center);
    return wnum_sub(wnum_from_num(NUM_ZERO), v3_dot_wide(co, ray->ds));
}

/* IntersectRaySphere: the two roots, t1 the far one and t2 the near one
 * (the book's order); 0 when the ray misses. */
int rt_intersect_ray_sphere(const struct rt_state *rt, int16_t obj, struct rt_ray *ray,
                            num *t1, num *t2, struct rt_frac *nf)
{
    const struct rt_object *o = &rt->s->objects[obj];
    const struct rt_obj_cache *oc = &rt->oc[obj];
    if (nf) nf->n = nf->d = 0;

    if (rt->book) {
        /* The demos' operation order, literally. */
        int cam = ray->from_camera && rt->cached;
        rt_ray_exact(ray);
        vec3 co = cam ? oc->co_cam : v3_sub(ray->o, o->center);
        num k1 = wnum_to_num(ray->a);
        num k2 = num_mul(NUM_C(2.0), v3_dot(co, ray->d));
        num k3 = cam ? oc->k3_cam : num_sub(v3_dot(co, co), num_mul(o->radius, o->radius));
        num disc = num_sub(num_mul(k2, k2), num_mul(num_mul(NUM_C(4.0), k1), k3));
        if (disc < 0) return 0;
        num sq = num_sqrt(disc);
        num den = num_mul(NUM_C(2.0), k1);
        *t1 = num_div(num_add(num_neg(k2), sq), den);
        *t2 = num_div(num_sub(num_neg(k2), sq), den);
        return 1;
    }
    if (ray->origin == obj) {
        /* O lies on this sphere: the roots are exactly 0 and 2b/a. */
        wnum b = sphere_self_b(rt, obj, ray);
        num far = scale_t(wnum_div(wnum_add(b, b), ray->as), ray->tscale);
        if (far > 0) { *t1 = far; *t2 = NUM_ZERO; }
        else { *t1 = NUM_ZERO; *t2 = far; }
        return 1;
    }
    struct sphere_quad k;
    if (!sphere_quad(rt, obj, ray, &k, 0, NUM_MAX)) return 0;
    if (k.k.q == 0) { *t1 = *t2 = NUM_ZERO; return 1; }
    num ra = quad_far(rt, obj, ray, &k);
    num rc = quad_near(&k);
    if (ra > rc) { *t1 = ra; *t2 = rc; }
    else { *t1 = rc; *t2 = ra; }
    if (nf && k.c > 0 && k.k.disc_pos) quad_near_frac(&k, nf);
    return 1;
}

/* What rt_item_hit's book-order comparisons pick from rt_intersect_ray_sphere's
 * roots (the smallest in (t_min, limit)), with less work: 1 and *t when
 * there is one. Leaving the sphere, the roots are 0 and 2b/a, so b <= 0
 * means no hit without dividing. From outside with b^2 > a c the near root
 * c/q is the smaller (q^2 - a c >= disc - 1 ulp + 2 b h >= 0, and rounding
 * keeps the order), so the far root q/a is only needed when c/q <= t_min. */
static int sphere_first_hit(const struct rt_state *rt, int16_t obj, struct rt_ray *ray, num t_min, num limit,
                            const struct rt_hit *best, num *t, struct rt_frac *fr, int coarse_done)
{
    num t1, t2;
    fr->n = fr->d = 0;
    if (ray->origin == obj) {
        rt_ray_cd(ray);
        if (rt_coarse_dot_negative(&ray->cd, &rt->oc[obj].cs.c)) return 0;
        wnum b = sphere_self_b(rt, obj, ray);
        if (b <= 0) return 0;
        t1 = scale_t(wnum_div(wnum_add(b, b), ray->as), ray->tscale);
        if (t_min < t1 && t1 < limit) { *t = t1; return 1; }
        return 0;   /* the other root, 0, is never above t_min */
    }
    struct sphere_quad k;
    if (!sphere_quad(rt, obj, ray, &k, coarse_done, limit)) return 0;
    if (k.k.q == 0) {
        t1 = t2 = NUM_ZERO;
    } else if (k.c > 0 && k.k.disc_pos) {
        t2 = quad_near(&k);
        quad_near_frac(&k, fr);
        if (t2 > limit || (t2 == limit && !tie_first(fr, best, limit))) return 0;
        if (t_min < t2) { *t = t2; return 1; }
        fr->d = 0;
        t1 = quad_far(rt, obj, ray, &k);
    } else {
        num ra = quad_far(rt, obj, ray, &k);
        num rc = quad_near(&k);
        t1 = ra > rc ? ra : rc;
        t2 = ra > rc ? rc : ra;
    }
    /* book order: t1 first, then t2, strict comparisons */
    int got = 0;
    if (t_min < t1 && t1 < limit) { limit = t1; got = 1; }
    if (t_min < t2 && t2 < limit) { limit = t2; got = 1; }
    *t = limit;
    return got;
}

#if NUM_MODE == NUM_MODE_FIXED
/* A shadow test's sphere (not the ray's own): whether sphere_first_hit
 * finds a hit, for its common outcomes without the square root and the
 * division. From outside (c > 0, b > 0, a positive discriminant) with c and
 * a in rt_near_beyond's range the computed square root is at most b, so q
 * (at F bits) lies in [Ql, Qu], Ql = round(b) >= 1, Qu = round(2b)
 * (rt_near_beyond); the near root is t = w ts, rounded, with w = c 2^F / q
 * rounded (halves up, saturating) and ts = 2^-k, k >= 0. With n = c 2^F:
 * n >= (t_min + 1) 2^k Qu puts w at or above (t_min + 1) 2^k and t above
 * t_min; then n <= (limit - 1) 2^k Ql puts t below limit (a hit), and
 * n >= limit 2^k Qu, limit 2^k <= NUM_MAX, at or above it (none:
 * sphere_first_hit stops there; a larger limit 2^k, which a saturated w
 * may not reach, is left undecided).
 * 1: a hit, 0: none, -1: not decided (the test as before decides). */
static int shadow_sphere_decide(const struct rt_state *rt, int16_t obj, struct rt_ray *ray, num t_min, num limit,
                                int coarse_done)
{
    const struct rt_obj_cache *oc = &rt->oc[obj];
    /* sphere_quad's steps (a shadow ray: not from the camera, no exact
     * direction) up to the discriminant */
    if (!coarse_done) {
        rt_ray_cd(ray);
        if (rt_coarse_sphere_miss(&ray->cd, &oc->cs)) return 0;
    }
    vec3 co = v3_sub(ray->o, rt->s->objects[obj].center);
    wnum dot = v3_dot_wide(co, co);
    wnum c = wnum_sub(dot, oc->r2);
    rt_ray_exact(ray);
    vec3 d = ray->ds;
    int64_t bx = -(num_smul32(co.x, d.x) + num_smul32(co.y, d.y) + num_smul32(co.z, d.z));
    if (c > 0 && bx <= 0) return 0;
    uint32_t ts = (uint32_t)ray->tscale;
    if (bx < ((int64_t)1 << NUM_FRAC) || !rt_near_c_ok(c, dot) || !rt_near_na_ok(c, ray->aq) || t_min < 0 ||
        t_min >= (1 << 16) || limit <= 0 || ts == 0 || ts > (uint32_t)NUM_ONE_RAW || (ts & (ts - 1u)) != 0)
        return -1;
    uint64_t dd;
    int e;
    if (!rt_quad_disc_x(rt_mag64(num_smul32(co.y, d.z) - num_smul32(co.z, d.y)),
                        rt_mag64(num_smul32(co.z, d.x) - num_smul32(co.x, d.z)),
                        rt_mag64(num_smul32(co.x, d.y) - num_smul32(co.y, d.x)), ray->aq, &oc->qs, &dd, &e))
        return 0;
    (void)e;
    if (dd == 0) return -1;
    uint64_t qu = ((uint64_t)bx * 2u + (1u << (NUM_FRAC - 1))) >> NUM_FRAC;
    uint64_t ql = ((uint64_t)bx + (1u << (NUM_FRAC - 1))) >> NUM_FRAC;
    if (qu > UINT32_MAX) return -1;
    int k = NUM_FRAC - (31 - num_clz32(ts));   /* ts = 2^(F-k), 0 <= k <= F */
    uint64_t n = (uint64_t)c << NUM_FRAC;      /* c < 2^(62-F) (rt_near_n_ok) */
    if (n < num_umul32(((uint32_t)t_min + 1u) << k, (uint32_t)qu)) return -1;
    uint64_t wmax = (uint64_t)(uint32_t)(limit - 1) << k;
    if (n <= num_umul32(wmax > UINT32_MAX ? UINT32_MAX : (uint32_t)wmax, (uint32_t)ql)) return 1;
    /* limit 2^k within the format: w, even saturated, is then at or above it */
    uint64_t wlim = (uint64_t)(uint32_t)limit << k;
    if (wlim <= (uint64_t)NUM_MAX && n >= num_umul32((uint32_t)wlim, (uint32_t)qu)) return 0;
    return -1;
}
#endif

/* rt_item_hit of a plain sphere with the shortcuts on: the hit filled in
 * (a shadow test's, rt_state.shadow_test, without its t: t_max). */
static int sphere_item_hit(const struct rt_state *rt, int16_t item, struct rt_ray *ray, num t_min, num limit,
                           struct rt_hit *hit, int coarse_done)
{
    num t;
    struct rt_frac fr;
#if NUM_MODE == NUM_MODE_FIXED
    if (rt->shadow_test && item != ray->origin) {
        int got = shadow_sphere_decide(rt, item, ray, t_min, limit, coarse_done);
        if (got == 0) return 0;
        if (got > 0) {
            hit->t = limit;
            hit->fr.d = 0;
            hit->item = hit->surf = item;
            hit->flip = 0;
            return 1;
        }
        coarse_done = 1;   /* the coarse test has not rejected it */
    }
#endif
    if (!sphere_first_hit(rt, item, ray, t_min, limit, hit, &t, &fr, coarse_done)) return 0;
    hit->t = t;
    hit->fr.n = fr.n;   /* by fields: a struct copy is a memcpy call on ARMv6-M */
    hit->fr.d = fr.d;
    hit->item = hit->surf = item;
    hit->flip = 0;
    return 1;
}

/* n/d in [0, 1], decided without dividing (d != 0). */
static int ratio_in_unit(wnum n, wnum d)
{
    return d > 0 ? (n >= 0 && n <= d) : (n <= 0 && n >= d);
}

/* Plane n.p = dist: two-sided; the normal is turned toward the ray origin. */
static int intersect_ray_plane(const struct rt_state *rt, int16_t obj, struct rt_ray *ray,
                               num *t, uint8_t *flip)
{
    const struct rt_object *o = &rt->s->objects[obj];
    if (ray->origin == obj) return 0;   /* a flat surface never hits itself */
    rt_ray_exact(ray);
    num ts = ray->tscale;
    vec3 d = ray->ds;
    num den = v3_dot(o->normal, d);
    if (den == 0) return 0;
    num num_ = num_sub(o->dist, v3_dot(o->normal, ray->o));
    /* Only t > 0 can be a hit (every t_min is positive), and a quotient
     * beyond the number format is the far hit RT_T_FAR: both are decided
     * before dividing, so a grazing ray costs no division and saturates
     * nothing. */
    if (num_ == 0 || (num_ > 0) != (den > 0)) return 0;
    *flip = den > 0;
    if (wnum_from_num(num_abs(num_)) >= num_mul_wide(num_abs(den), NUM_MAX)) {
        *t = RT_T_FAR;
        return 1;
    }
    /* t' along ds in range, t = t' ts past it (a short direction): far too */
    num t_ = scale_t(num_div(num_, den), ts);
    *t = t_ >= RT_T_FAR ? RT_T_FAR : t_;
    return 1;
}

/* Triangle p0 p1 p2 (Möller–Trumbore on the cached edges). */
static int intersect_ray_triangle(const struct rt_state *rt, int16_t obj, struct rt_ray *ray,
                                  num *t, uint8_t *flip)
{
    const struct rt_object *o = &rt->s->objects[obj];
    const struct rt_obj_cache *oc = &rt->oc[obj];
    if (ray->origin == obj) return 0;
    rt_ray_exact(ray);
    num ts = ray->tscale;
    vec3 d = ray->ds;
    vec3 pv = v3_cross(d, oc->e2);
    wnum det = v3_dot_wide(oc->e1, pv);
    if (det == 0) return 0;
    vec3 tv = v3_sub(ray->o, o->p[0]);
    /* u = un/det and v = vn/det lie in [0, 1] only when the numerator has
     * det's sign and no larger magnitude: tested before dividing (a grazing
     * ray's tiny det would otherwise saturate the quotient), and t > 0 only
     * when tn has det's sign. */
    wnum un = v3_dot_wide(tv, pv);
    if (!ratio_in_unit(un, det)) return 0;
    num u = wnum_div(un, det);
    vec3 qv = v3_cross(tv, oc->e1);
    wnum vn = v3_dot_wide(d, qv);
    if (!ratio_in_unit(vn, det)) return 0;
    num v = wnum_div(vn, det);
    if (num_add(u, v) > NUM_ONE) return 0;
    wnum tn = v3_dot_wide(oc->e2, qv);
    if (tn == 0 || (tn > 0) != (det > 0)) return 0;
    *t = scale_t(wnum_div(tn, det), ts);
    *flip = v3_dot(oc->n, d) > 0;
    return 1;
}

/* One span [t0, t1] of a solid along the ray, with the surfaces it enters
 * and leaves by. */
struct span {
    num t0, t1;
    int16_t s0, s1;
    uint8_t f0, f1;
};

static int sphere_span(const struct rt_state *rt, int16_t obj, struct rt_ray *ray,
                       struct span *sp)
{
    num t1, t2;
    if (!rt_intersect_ray_sphere(rt, obj, ray, &t1, &t2, NULL)) return 0;
    sp->t0 = t2 < t1 ? t2 : t1;
    sp->t1 = t2 < t1 ? t1 : t2;
    sp->s0 = sp->s1 = obj;
    sp->f0 = sp->f1 = 0;
    return 1;
}

/* Spans of a CSG of two spheres; returns how many (0..2). */
static int csg_spans(const struct rt_state *rt, const struct rt_csg *g, struct rt_ray *ray,
                     struct span out[2])
{
    struct span A, B;
    int ha = sphere_span(rt, (int16_t)g->a, ray, &A);
    int hb = sphere_span(rt, (int16_t)g->b, ray, &B);
    switch (g->op) {
    case CSG_UNION:
        if (!ha && !hb) return 0;
        if (!hb) { out[0] = A; return 1; }
        if (!ha) { out[0] = B; return 1; }
        if (A.t0 <= B.t1 && B.t0 <= A.t1) {
            struct span u = A;
            if (B.t0 < u.t0) { u.t0 = B.t0; u.s0 = B.s0; }
            if (B.t1 > u.t1) { u.t1 = B.t1; u.s1 = B.s1; }
            out[0] = u;
            return 1;
        }
        out[0] = A.t0 < B.t0 ? A : B;
        out[1] = A.t0 < B.t0 ? B : A;
        return 2;
    case CSG_INTERSECTION: {
        if (!ha || !hb) return 0;
        struct span r = A;
        if (B.t0 > r.t0) { r.t0 = B.t0; r.s0 = B.s0; }
        if (B.t1 < r.t1) { r.t1 = B.t1; r.s1 = B.s1; }
        if (!(r.t0 < r.t1)) return 0;
        out[0] = r;
        return 1;
    }
    default: { /* CSG_DIFFERENCE: A minus B; B's surface shows its inside */
        if (!ha) return 0;
        if (!hb || B.t1 <= A.t0 || B.t0 >= A.t1) { out[0] = A; return 1; }
        int n = 0;
        if (A.t0 < B.t0) {
            struct span r = A;
            r.t1 = B.t0; r.s1 = B.s0; r.f1 = 1;
            out[n++] = r;
        }
        if (B.t1 < A.t1) {
            struct span r = A;
            r.t0 = B.t1; r.s0 = B.s1; r.f0 = 1;
            out[n++] = r;
        }
        return n;
    }
    }
}

int rt_item_hit(struct rt_state *rt, int16_t item, struct rt_ray *ray, num t_min, num t_max,
                struct rt_hit *hit)
{
    const struct scene *s = rt->s;
    num limit = t_max;
    int got = 0;
    rt->n.tests++;
    if (item >= (int16_t)s->nobjects) {
        struct span sp[2];
        int n = csg_spans(rt, &s->csg[CSG_ITEM(rt, item)], ray, sp);
        for (int i = 0; i < n; i++) {
            if (t_min < sp[i].t0 && sp[i].t0 < limit) {
                limit = sp[i].t0;
                hit->surf = sp[i].s0; hit->flip = sp[i].f0; got = 1;
            }
            if (t_min < sp[i].t1 && sp[i].t1 < limit) {
                limit = sp[i].t1;
                hit->surf = sp[i].s1; hit->flip = sp[i].f1; got = 1;
            }
        }
    } else {
        const struct rt_object *o = &s->objects[item];
        num t1, t2, t;
        uint8_t flip = 0;
        switch (o->shape) {
        case RT_SPHERE: {
            if (rt->shortcuts) return sphere_item_hit(rt, item, ray, t_min, limit, hit, 0);
            struct rt_frac nf;
            if (!rt_intersect_ray_sphere(rt, item, ray, &t1, &t2, &nf)) return 0;
            /* book order: t1 first, then t2, strict comparisons (a near
             * root equal to the best hit's goes by their fractions) */
            if (t_min < t1 && t1 < limit) { limit = t1; got = 1; }
            if (t_min < t2 && (t2 < limit || (t2 == limit && tie_first(&nf, hit, limit)))) {
                limit = t2;
                got = 2;
                hit->fr.n = nf.n;
                hit->fr.d = nf.d;
            }
            break;
        }
        case RT_PLANE:
            if (intersect_ray_plane(rt, item, ray, &t, &flip) && t_min < t && t < limit) { limit = t; got = 1; }
            break;
        default:
            if (intersect_ray_triangle(rt, item, ray, &t, &flip) && t_min < t && t < limit) { limit = t; got = 1; }
            break;
        }
        if (got) { hit->surf = item; hit->flip = flip; }
    }
    if (got) {
        hit->t = limit;
        hit->item = item;
        if (got != 2) hit->fr.d = 0;
    }
    return got != 0;
}

/* sphere_item_hit of a sphere along a primary ray's exact row direction
 * (from the camera, per-frame c, unturned: sphere_quad_row), for the common
 * outcome without the general path's layers: the camera outside (c > 0),
 * the near root c m / q a hit or beyond the limit. Anything else (q = 0, a
 * zero discriminant, the camera inside, the near root at or before t_min)
 * goes to sphere_item_hit, which solves the same quadratic again: the same
 * answer either way. Fixed point only. */
static int prim_sphere_hit(struct rt_state *rt, int16_t item, struct rt_ray *ray, num t_min, num limit,
                           struct rt_hit *hit)
{
#if NUM_MODE == NUM_MODE_FIXED
    struct rt_obj_cache *oc = &rt->oc[item];
    if (oc->c_cam > 0) {
        /* sphere_quad_row's solve with c > 0 (rt_prim_v6m.h) */
        struct rt_psolve ps;
        sphere_row_parts(oc, ray);
        int near = rt_prim_solve(oc, ray, limit, &ps);
        if (!near) return 0;
        if (near == 2) {
            /* the general way: a zero discriminant or q, or rt_wdiv's slow path */
            struct rt_quad q;
            rt_quad_root_x(ps.pd.bx, ps.pd.dd, ps.pd.e, &q);
            near = q.q != 0 && q.disc_pos;
            if (near) {
                ps.pn.q = q.q;
                ps.pn.t = rt_quad_near_m(oc->cm_cam, &q);
            }
        }
        if (near) {
            struct rt_frac fr;
            num t2 = ps.pn.t;
            fr.n = oc->cm_cam;
            fr.d = ps.pn.q;
            if (t2 > limit || (t2 == limit && !tie_first(&fr, hit, limit))) return 0;
            if (t_min < t2) {
                hit->t = t2;
                hit->fr.n = fr.n;   /* field by field: cheaper than the struct copy on ARMv6-M */
                hit->fr.d = fr.d;
                hit->item = hit->surf = item;
                hit->flip = 0;
                return 1;
            }
        }
    }
#endif
    return sphere_item_hit(rt, item, ray, t_min, limit, hit, 1);
}

int rt_shadow_search(struct rt_state *rt, struct rt_ray *ray, num t_min, num t_max, uint32_t mask, int16_t first,
                     struct rt_hit *hit)
{
    if (first >= 0 && ((mask >> first) & 1u)) {
        /* the cached occluder first (rt_item_hit's sphere case) */
        rt->n.tests++;
        if (sphere_item_hit(rt, first, ray, t_min, t_max, hit, 0)) return 1;
        mask &= ~((uint32_t)1 << first);
    }
    for (int16_t item = 0; mask; item++, mask >>= 1) {
        if (!(mask & 1u)) continue;
        rt->n.tests++;
        /* rt_closest_intersection's sphere case (the ray's own sphere takes
         * sphere_first_hit's path) */
        int other = item != ray->origin;
        if (other && rt_coarse_sphere_miss(&ray->cd, &rt->oc[item].cs)) continue;
        if (sphere_item_hit(rt, item, ray, t_min, t_max, hit, other)) return 1;
    }
    return 0;
}

/* Conservative ray / bounding-sphere test (robust form, both formulations):
 * 0 only when the ray certainly misses the sphere within t > 0. */
static int bound_hit(struct rt_state *rt, vec3 c, num r, struct rt_ray *ray)
{
    rt->n.tests++;
    rt_ray_exact(ray);
    wnum a = ray->as;
    vec3 d;   /* by components: a struct copy here becomes a memcpy call on ARMv6-M */
    d.x = ray->ds.x;
    d.y = ray->ds.y;
    d.z = ray->ds.z;
    vec3 co = v3_sub(ray->o, c);
    wnum cc = wnum_sub(v3_dot_wide(co, co), num_mul_wide(r, r));
    if (cc <= 0) return 1;                 /* origin inside */
    wnum b = wnum_sub(wnum_from_num(NUM_ZERO), v3_dot_wide(co, d));
    if (b <= 0) return 0;                  /* outside and moving away */
    return wnum_sub(wnum_mul(b, b), wnum_mul(a, cc)) >= 0;
}

/* rt_closest_intersection of a primary ray along its row's candidate
 * intervals (rt->prim_iv): outside its interval a sphere is certainly
 * missed; inside, the coarse test seldom rejects and is skipped where the
 * interval is proven. */
static int closest_prim(struct rt_state *rt, struct rt_ray *ray, num t_min, num limit, struct rt_hit *hit,
                        const int16_t *items, uint16_t nitems)
{
    const struct rt_object *objs = rt->s->objects;
    /* (rt->skip_item is -1: it is set only around a shadow ray's search,
     * rt_lighting.c) */
    int16_t *iv = rt->prim_iv, nobj = (int16_t)rt->s->nobjects, col = rt->prim_col;
    int found = 0, tried = 0;
    uint32_t tests = 0;   /* the sphere tests, counted once at the end */
    /* along the row's exact directions with the per-frame constants: the
     * lean path (prim_sphere_hit). Always, in fixed point: rt->prim_iv is
     * set only for a pixel's primary ray from the camera (origin -1) with
     * its unturned exact direction (dxm = H, dxrow its row) and the
     * per-frame constants in use (exact_dir, row_iv in rt_trace.c). */
    const int lean = NUM_MODE == NUM_MODE_FIXED;
    /* every item a plain sphere: no item's shape to look up */
    const int sph = rt->all_spheres;
    /* the background run's last column (rt_state.bg_*): the tile's last
     * one (its list), then before every later interval */
    int16_t run = rt->prim_items ? (int16_t)(col / RT_TILE * RT_TILE + RT_TILE - 1) : INT16_MAX;
    for (uint16_t i = 0; i < nitems; i++) {
        int16_t item = items[i];
        if (sph || (item < nobj && objs[item].shape == RT_SPHERE)) {
            tests++;
            int16_t *e = iv + 2 * item;
            if (e[0] == RT_IV_TODO) rt_row_interval(rt, item, e);
            if (col < e[0]) {
                if (e[0] <= run) run = (int16_t)(e[0] - 1);
                continue;
            }
            if (col > e[1]) continue;
            tried = 1;
            if (e[0] == INT16_MIN) {
                rt_ray_cd(ray);
                if (rt_coarse_cam_miss(&ray->cd, &rt->oc[item].ccam)) continue;
            }
            if (!(lean ? prim_sphere_hit(rt, item, ray, t_min, limit, hit)
                       : sphere_item_hit(rt, item, ray, t_min, limit, hit, 1)))
                continue;
        } else {
            tried = 1;
            if (!rt_item_hit(rt, item, ray, t_min, limit, hit)) continue;
        }
        limit = hit->t;
        found = 1;
    }
    rt->n.tests += tests;
    if (!tried) {
        /* an empty list: the run goes on through the tiles after it whose
         * lists are empty too (their rays test nothing either) */
        if (nitems == 0 && rt->prim_items)
            for (unsigned tc = (unsigned)col / RT_TILE + 1; tc < rt->ntc && rt->tile_n[tc] == 0; tc++) run += RT_TILE;
        /* every candidate's interval leaves this column out: so it does for
         * the columns up to run, the pixels' background (rt_trace_pixel) */
        rt->bg_row = ray->dxrow;
        rt->bg_lo = col;
        rt->bg_hi = run;
        rt->bg_tests = (uint16_t)nitems;
    }
    return found;
}

int rt_closest_intersection(struct rt_state *rt, struct rt_ray *ray, num t_min, num t_max,
                            struct rt_hit *hit, int any_hit)
{
    num limit = t_max;
    int found = 0;
    hit->fr.d = 0;   /* no best hit yet (rt_frac) */
    if (!rt->s->rt.bvh || rt->nbvh == 0) {
        const struct rt_object *objs = rt->s->objects;
        /* a primary ray: its tile's candidates (rt_trace.c), else every item */
        const int16_t *items = rt->items;
        uint16_t nitems = rt->nitems;
        if (ray->from_camera && rt->prim_items) { items = rt->prim_items; nitems = rt->prim_n; }
        /* a primary ray along its row's exact directions: the candidate intervals */
        if (ray->from_camera && rt->prim_iv && !any_hit && rt->shortcuts)
            return closest_prim(rt, ray, t_min, limit, hit, items, nitems);
        int cam = ray->from_camera && rt->cached;   /* the camera's coarse forms (rt_ccam) */
        for (uint16_t i = 0; i < nitems; i++) {
            int16_t item = items[i];
            if (item == rt->skip_item) continue;
            if (rt->shortcuts && item < (int16_t)rt->s->nobjects && objs[item].shape == RT_SPHERE) {
                /* rt_item_hit's sphere case, without its dispatch */
                rt->n.tests++;
                /* the common outcome first, without the calls: a certain
                 * miss (the ray's own sphere takes sphere_first_hit's path) */
                int other = item != ray->origin;
                if (other && (cam ? rt_coarse_cam_miss(&ray->cd, &rt->oc[item].ccam)
                                  : rt_coarse_sphere_miss(&ray->cd, &rt->oc[item].cs)))
                    continue;
                if (!sphere_item_hit(rt, item, ray, t_min, limit, hit, other)) continue;
                limit = hit->t;
                found = 1;
                if (any_hit) return 1;
                continue;
            }
            if (rt_item_hit(rt, item, ray, t_min, limit, hit)) {
                limit = hit->t;
                found = 1;
                if (any_hit) return 1;
            }
        }
        return found;
    }
    for (uint16_t i = 0; i < rt->nunbounded; i++)
        if (rt->unbounded[i] != rt->skip_item && rt_item_hit(rt, rt->unbounded[i], ray, t_min, limit, hit)) {
            limit = hit->t;
            found = 1;
            if (any_hit) return 1;
        }
    int16_t stack[48];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const struct rt_bvh_node *nd = &rt->bvh[stack[--sp]];
        if (!bound_hit(rt, nd->c, nd->r, ray)) continue;
        if (nd->left < 0) {
            for (int16_t k = 0; k < nd->count; k++)
                if (rt->bvh_items[nd->first + k] != rt->skip_item &&
                    rt_item_hit(rt, rt->bvh_items[nd->first + k], ray, t_min, limit, hit)) {
                    limit = hit->t;
                    found = 1;
                    if (any_hit) return 1;
                }
        } else if (sp + 2 <= (int)(sizeof stack / sizeof stack[0])) {
            stack[sp++] = nd->right;
            stack[sp++] = nd->left;
        }
    }
    return found;
}

/* ---- primary rays' candidate intervals (rt_num.h, rt_iv_row) ---------- */

#if NUM_MODE == NUM_MODE_FIXED
static inline struct rt_s128 rt_s128_add(struct rt_s128 a, struct rt_s128 b)
{
    struct rt_s128 r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo);
    return r;
}

static inline struct rt_s128 rt_s128_neg(struct rt_s128 a)
{
    struct rt_s128 r;
    r.lo = 0u - a.lo;
    r.hi = 0u - a.hi - (a.lo != 0);
    return r;
}

static inline int rt_s128_isneg(struct rt_s128 a) { return (a.hi >> 63) != 0; }
static inline int rt_s128_le0(struct rt_s128 a) { return rt_s128_isneg(a) || (a.hi == 0 && a.lo == 0); }

static inline struct rt_s128 rt_s128_from64(int64_t v)
{
    struct rt_s128 r;
    r.lo = (uint64_t)v;
    r.hi = v < 0 ? ~(uint64_t)0 : 0u;
    return r;
}

/* a b for unsigned 64-bit a, b (calls: code size; a few a row and sphere). */
static RT_NOINLINE struct rt_s128 rt_u128_mul64(uint64_t a, uint64_t b)
{
    uint32_t a0 = (uint32_t)a, a1 = (uint32_t)(a >> 32), b0 = (uint32_t)b, b1 = (uint32_t)(b >> 32);
    uint64_t p00 = num_umul32(a0, b0), p01 = num_umul32(a0, b1), p10 = num_umul32(a1, b0);
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;   /* < 3 2^32 */
    struct rt_s128 r;
    r.lo = (mid << 32) | (uint32_t)p00;
    r.hi = num_umul32(a1, b1) + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return r;
}

/* a b for signed 64-bit a, b. */
static inline struct rt_s128 rt_s128_mul64(int64_t a, int64_t b)
{
    struct rt_s128 r = rt_u128_mul64(rt_mag64(a), rt_mag64(b));
    return (a < 0) != (b < 0) ? rt_s128_neg(r) : r;
}

/* x k, |x k| < 2^127, |k| < 2^31. */
static RT_NOINLINE struct rt_s128 rt_s128_mul32(struct rt_s128 x, int32_t k)
{
    int neg = rt_s128_isneg(x) != (k < 0);
    if (rt_s128_isneg(x)) x = rt_s128_neg(x);
    uint32_t m = k < 0 ? 0u - (uint32_t)k : (uint32_t)k;
    uint64_t p0 = num_umul32((uint32_t)x.lo, m);
    uint64_t p1 = num_umul32((uint32_t)(x.lo >> 32), m) + (p0 >> 32);
    uint64_t p2 = num_umul32((uint32_t)x.hi, m) + (p1 >> 32);
    uint32_t p3 = (uint32_t)(x.hi >> 32) * m + (uint32_t)(p2 >> 32);
    struct rt_s128 r;
    r.lo = (p1 << 32) | (uint32_t)p0;
    r.hi = ((uint64_t)p3 << 32) | (uint32_t)p2;
    return neg ? rt_s128_neg(r) : r;
}

/* Bit length of |x|. */
static inline int rt_s128_bits(struct rt_s128 x)
{
    if (rt_s128_isneg(x)) x = rt_s128_neg(x);
    return x.hi ? 64 + rt_bitlen64(x.hi) : rt_bitlen64(x.lo);
}

/* x / 2^s rounded toward minus infinity, into int64 (the caller keeps
 * |x| / 2^s below 2^62; 0 <= s < 128). */
static inline int64_t rt_s128_shr(struct rt_s128 x, int s)
{
    uint64_t lo;
    if (s == 0) lo = x.lo;
    else if (s < 64) lo = (x.lo >> s) | (x.hi << (64 - s));
    else lo = (uint64_t)((int64_t)x.hi >> (s - 64 > 63 ? 63 : s - 64));
    return (int64_t)lo;
}

/* x / 2^s rounded toward minus infinity, 0 < s < 64. */
static inline struct rt_s128 rt_s128_sar(struct rt_s128 x, int s)
{
    struct rt_s128 r;
    r.lo = (x.lo >> s) | (x.hi << (64 - s));
    r.hi = (uint64_t)((int64_t)x.hi >> s);
    return r;
}

/* A turned camera's exact primary direction Dm (rt_exact_turn) is E, the
 * scene's rotation at 29 fraction bits applied exactly (F + 29 bits),
 * rounded once: E = 2^29 Dm + rho, |rho_i| <= 2^28. A line along E that
 * touches or meets the sphere may miss it along Dm (raytracer-06 has one
 * exactly tangent, in the scene's 0.7071 matrix). When the solve along Dm
 * finds no root, the discriminant along E decides it:
 *   r^2 |E|^2 - |CO x E|^2 = 2^58 G + 2^30 S1 + S2,
 * G = r^2 a - |CO x Dm|^2, S1 = r^2 (Dm.rho) - (CO x Dm).(CO x rho),
 * S2 = r^2 |rho|^2 - |CO x rho|^2, all from exact products (|CO x Dm_i| <
 * 2^58, |CO x rho_i| < 2^60, |Dm.rho| < 2^56, r^2 < 2^62 at 2F bits), so its
 * sign is that of the integer Z = 2^28 G + S1 + floor(S2 / 2^30) (within 1
 * below the exact quotient), in 128-bit arithmetic for |G| < 2^96. Z >= 0:
 * the ray touches or meets the sphere, and is taken as tangent along Dm
 * (q = b, the book's hit at b^2 = a c). Rare: a turned primary ray that
 * passed the coarse test and missed. */
/* acc - a b (code size: turn_touch's nine products through one call). */
static RT_NOINLINE struct rt_s128 rt_s128_submul(struct rt_s128 acc, int64_t a, int64_t b)
{
    return rt_s128_add(acc, rt_s128_neg(rt_s128_mul64(a, b)));
}

/* 1 when turn_touch's Z < 0 is certain from 64-bit bounds, before its
 * 128-bit products. With rho' = rho / 2^29 (|rho'_i| <= 1/2, so |rho'| <
 * 0.87), the discriminant along E / 2^29 is G + 2 S1' + S2', S1' = r^2
 * (Dm.rho') - (CO x Dm).(CO x rho'), S2' = r^2 |rho'|^2 - |CO x rho'|^2.
 * With w = max(|CO|^2, r^2) and |Dm| < 2^h, h = ceil(bitlen(a) / 2):
 * 2 |S1'| <= 2 |rho'| |Dm| (r^2 + |CO|^2) < 3.47 w |Dm| and S2' < 0.75 w,
 * so 2 S1' + S2' < 4 w (|Dm| + 1) <= w 2^(h+3). -G is bounded below at
 * one scale 2^s by |CO x Dm|^2 truncated down less r^2 a rounded up; a
 * bound above w 2^(h+3) leaves the discriminant along E negative. */
static RT_NOINLINE int turn_far_miss(const num *o, const num *dm, uint64_t r2x, uint64_t a)
{
    uint64_t x0 = rt_mag64(num_smul32(o[1], dm[2]) - num_smul32(o[2], dm[1]));
    uint64_t x1 = rt_mag64(num_smul32(o[2], dm[0]) - num_smul32(o[0], dm[2]));
    uint64_t x2 = rt_mag64(num_smul32(o[0], dm[1]) - num_smul32(o[1], dm[0]));
    int lx = rt_bitlen64(x0 | x1 | x2), kx = lx > 30 ? lx - 30 : 0;
    /* |CO x Dm|^2 >= xx 2^(2 kx) */
    uint64_t xx = rt_usq32(rt_shr64_to32(x0, kx)) + rt_usq32(rt_shr64_to32(x1, kx)) +
                  rt_usq32(rt_shr64_to32(x2, kx));
    /* r^2 a <= ar 2^(ka + kr), both factors at most 2^31 */
    int la = rt_bitlen64(a), lr = rt_bitlen64(r2x);
    int ka = la > 31 ? la - 31 : 0, kr = lr > 31 ? lr - 31 : 0;
    uint64_t ar = num_umul32(rt_shr64_to32(a, ka) + 1u, rt_shr64_to32(r2x, kr) + 1u);
    int s = 2 * kx > ka + kr ? 2 * kx : ka + kr;
    uint64_t lo = rt_shr64(xx, s - 2 * kx), hi = rt_shr64(ar, s - ka - kr) + 1u;
    if (lo <= hi) return 0;
    uint64_t d = lo - hi;   /* -G >= d 2^s */
    uint64_t w = (uint64_t)rt_ssq32(o[0]) + (uint64_t)rt_ssq32(o[1]) + (uint64_t)rt_ssq32(o[2]);
    if (w < r2x) w = r2x;
    int t = (la + 1) / 2 + 3 - s;   /* w 2^(h+3) = w 2^t 2^s */
    if (t >= 0) return rt_bitlen64(w) + t < 64 && d > (w << t);
    return d > rt_shr64(w, -t) + 1u;
}

static RT_NOINLINE int turn_touch(const struct rt_state *rt, vec3 co, const struct rt_ray *ray, uint64_t r2x, wnum c,
                                  struct rt_quad *k)
{
    const num dm[3] = { ray->dx.x, ray->dx.y, ray->dx.z }, o[3] = { co.x, co.y, co.z };
    int64_t bx = -(num_smul32(o[0], dm[0]) + num_smul32(o[1], dm[1]) + num_smul32(o[2], dm[2]));
    if ((c > 0 && bx <= 0) || r2x >= ((uint64_t)1 << 62)) return 0;
    if (turn_far_miss(o, dm, r2x, (uint64_t)ray->dxa)) return 0;
    /* the column's x vh as exact_dir formed it (it fits: |x vh| < 2^(F+10)) */
    num vx = rt->vh * (rt->prim_col - rt->w / 2);
    int32_t rho[3];
    int64_t dmr = 0;
    for (int i = 0; i < 3; i++) {
        int64_t e = rt->dx_turn[i] + num_smul32(rt->cam_q29[i][0], vx);
        rho[i] = (int32_t)(e - (int64_t)dm[i] * ((int64_t)1 << 29));
        dmr += num_smul32(dm[i], rho[i]);
    }
    uint64_t rr = (uint64_t)num_smul32(rho[0], rho[0]) + (uint64_t)num_smul32(rho[1], rho[1]) +
                  (uint64_t)num_smul32(rho[2], rho[2]);
    struct rt_s128 g = rt_u128_mul64(r2x, (uint64_t)ray->dxa), s2 = rt_u128_mul64(r2x, rr), s1 = { 0, 0 };
    s1 = rt_s128_submul(s1, -(int64_t)r2x, dmr);
    for (int i = 0; i < 3; i++) {
        /* a component of CO x Dm and of CO x rho (pairs 01, 12, 20) */
        int j = i == 2 ? 0 : i + 1;
        int64_t xd = num_smul32(o[i], dm[j]) - num_smul32(o[j], dm[i]);
        int64_t xr = num_smul32(o[i], rho[j]) - num_smul32(o[j], rho[i]);
        g = rt_s128_submul(g, xd, xd);
        s1 = rt_s128_submul(s1, xd, xr);
        s2 = rt_s128_submul(s2, xr, xr);
    }
    if (rt_s128_bits(g) > 96) return 0;
    struct rt_s128 g28;   /* 2^28 G */
    g28.lo = g.lo << 28;
    g28.hi = (g.hi << 28) | (g.lo >> 36);
    if (rt_s128_isneg(rt_s128_add(rt_s128_add(g28, s1), rt_s128_sar(s2, 30)))) return 0;
    k->qx = bx;
    k->q = rt_shr_round(bx, NUM_FRAC);
    k->disc_pos = 0;
    return 1;
}

/* n / d truncated toward zero as C divides int64_t (d != 0), by the
 * 32-bit division when both lie in (-2^31, 2^31): the same quotient
 * without the 64-bit division's library call. */
static inline int64_t rt_div64_narrow(int64_t n, int64_t d)
{
    if (n > INT32_MIN && n <= INT32_MAX && d > INT32_MIN && d <= INT32_MAX) return (int32_t)n / (int32_t)d;
    return n / d;
}

/* g(k) <= 0 and the condition on its slope (side < 0: A (2k - 1) + 2B >= 0,
 * every k' <= k at or below; side > 0: A (2k + 1) + 2B <= 0, every k' >= k). */
static RT_NOINLINE int rt_iv_proven(const struct rt_ivsphere *iv, struct rt_s128 b2, struct rt_s128 c, int32_t k, int side)
{
    struct rt_s128 ak = rt_s128_mul32(iv->a, k);
    struct rt_s128 slope = rt_s128_add(rt_s128_add(ak, ak), b2);   /* A 2k + 2B */
    if (side < 0) {
        slope = rt_s128_add(slope, rt_s128_neg(iv->a));
        if (rt_s128_isneg(slope)) return 0;
    } else {
        slope = rt_s128_add(slope, iv->a);
        if (!rt_s128_le0(slope)) return 0;
    }
    return rt_s128_le0(rt_s128_add(rt_s128_mul32(rt_s128_add(ak, b2), k), c));   /* (A k + 2B) k + C */
}
#endif

struct rt_ivsphere rt_ivsphere_make(vec3 co, uint64_t r2x, num v)
{
    struct rt_ivsphere iv = { 0 };
#if NUM_MODE == NUM_MODE_FIXED
    const int32_t lim = (int32_t)1 << 30;
    if (co.x <= -lim || co.x >= lim || co.y <= -lim || co.y >= lim || co.z <= -lim || co.z >= lim ||
        v <= 0 || v >= (1 << 20) || r2x >= ((uint64_t)1 << 62))
        return iv;
    uint64_t cx2 = (uint64_t)num_smul32(co.x, co.x), cy2 = (uint64_t)num_smul32(co.y, co.y),
             cz2 = (uint64_t)num_smul32(co.z, co.z);
    uint64_t rt = r2x + ((cx2 + cy2 + cz2) >> 25) + (r2x >> 60) + 3;   /* r^2 + T < 2^63 */
    int64_t ayz = (int64_t)rt - (int64_t)(cy2 + cz2);                  /* both < 2^63 */
    if (ayz >= 0) return iv;   /* not concave in k: no interval */
    iv.a = rt_s128_mul64((int64_t)num_umul32((uint32_t)v, (uint32_t)v), ayz);
    iv.rc = (int64_t)rt - (int64_t)cx2;
    iv.r0 = (r2x >> 30) + ((uint64_t)1 << 34) + 1;
    iv.vcx = num_smul32(v, co.x);
    iv.v = v;
    iv.cy = co.y;
    iv.cz = co.z;
    iv.ok = 1;
#else
    (void)co; (void)r2x; (void)v;
#endif
    return iv;
}

int rt_iv_row(const struct rt_ivsphere *iv, wnum c, num y, num z, wnum yz, int32_t kmin, int32_t kmax, int32_t *lo,
              int32_t *hi)
{
#if NUM_MODE == NUM_MODE_FIXED
    const int32_t lim = (int32_t)1 << 28;
    int32_t km = kmax > -kmin ? kmax : -kmin;
    if (!iv->ok || y <= -lim || y >= lim || z <= -lim || z >= lim || km > 1024 || iv->v * km >= lim) return 0;
    int64_t p = num_smul32(iv->cy, y) + num_smul32(iv->cz, z);      /* |.| < 2^59 */
    int64_t x0 = num_smul32(iv->cy, z) - num_smul32(iv->cz, y);
    struct rt_s128 b2 = rt_s128_mul64(iv->vcx, p);
    b2 = rt_s128_add(b2, b2);
    struct rt_s128 cc = rt_s128_add(rt_s128_mul64(yz, iv->rc), rt_s128_neg(rt_u128_mul64(rt_mag64(x0), rt_mag64(x0))));
    cc = rt_s128_add(cc, rt_s128_from64((int64_t)iv->r0));
    /* approximate roots: A, 2B, C scaled alike to below 2^20, 2^31, 2^40
     * (|k| <= 2^10) */
    int m = rt_s128_bits(iv->a) + 20, mb = rt_s128_bits(b2) + 9, mc = rt_s128_bits(cc);
    if (mb > m) m = mb;
    if (mc > m) m = mc;
    int s = m > 40 ? m - 40 : 0;
    int64_t as = rt_s128_shr(iv->a, s), bs = rt_s128_shr(b2, s), cs = rt_s128_shr(cc, s);
    if (as >= 0) return 0;
    /* (2B)^2 / 4 - A C, each below 2^60 */
    int64_t disc = (bs / 2) * (bs / 2) - as * cs;
    int64_t kl, kr;
    if (disc < 0) {
        kl = kr = rt_div64_narrow(bs / 2, -as);
    } else {
        int64_t h = (int64_t)num_isqrt64((uint64_t)disc, 0);
        kl = rt_div64_narrow(-(bs / 2) + h, as) - 1;
        kr = rt_div64_narrow(-(bs / 2) - h, as) + 1;
    }
    int32_t l = kmin, r = kmax;
    if (kl >= kmin) {
        int32_t k = kl > kmax ? kmax : (int32_t)kl;
        for (int i = 0; i < 4 && k >= kmin; i++, k--)
            if (rt_iv_proven(iv, b2, cc, k, -1)) { l = k + 1; break; }
    }
    if (kr <= kmax) {
        int32_t k = kr < kmin ? kmin : (int32_t)kr;
        for (int i = 0; i < 4 && k <= kmax; i++, k++)
            if (rt_iv_proven(iv, b2, cc, k, 1)) { r = k - 1; break; }
    }
    /* behind: c > 0 and b = -P - v CO.x k <= 0 at both ends (b linear in k) */
    if (l <= r && c > 0 && -p - iv->vcx * l <= 0 && -p - iv->vcx * r <= 0) r = l - 1;
    *lo = l;
    *hi = r;
    return 1;
#else
    (void)iv; (void)c; (void)y; (void)z; (void)yz; (void)kmin; (void)kmax; (void)lo; (void)hi;
    return 0;
#endif
}

void rt_row_interval(const struct rt_state *rt, int16_t obj, int16_t *e)
{
    const struct rt_obj_cache *oc = &rt->oc[obj];
    int32_t half = rt->w / 2, lo, hi;
    if (!rt_iv_row(&oc->ivs, oc->c_cam, rt->dx_y, rt->dx_z, rt->dx_yz, -half, rt->w - 1 - half, &lo, &hi)) {
        e[0] = INT16_MIN;
        e[1] = INT16_MAX;
    } else if (lo > hi) {
        e[0] = 1;   /* no column */
        e[1] = 0;
    } else {
        e[0] = (int16_t)(lo + half);
        e[1] = (int16_t)(hi + half);
    }
}

#if NUM_MODE == NUM_MODE_FIXED
/* a / 2^s, s > 0, |a| rounded half up and signed as a: num_mul_recip's
 * result for the divisor 2^s (multiplier 2^31, shift 31 + s) */
static inline num rt_div_pow2(num a, int s)
{
    uint32_t u = a < 0 ? 0u - (uint32_t)a : (uint32_t)a;
    uint32_t q = ((u >> (s - 1)) + 1u) >> 1;
    return a < 0 ? -(num)q : (num)q;
}
#endif

vec3 rt_hit_normal(const struct rt_state *rt, const struct rt_hit *hit, const vec3 *p)
{
    const struct rt_object *o = &rt->s->objects[hit->surf];
    vec3 n;
    if (o->shape == RT_SPHERE) {
        /* a hit point and a centre proven within half the format
         * (SCENE_FITS_HIT): their difference in 32 bits is never saturated,
         * v3_sub's bits */
        if (rt->s->fits & SCENE_FITS_HIT)
            n = v3_make(num_add_fit(p->x, -o->center.x), num_add_fit(p->y, -o->center.y), num_add_fit(p->z, -o->center.z));
        else
            n = v3_sub(*p, o->center);
        if (rt->book) {
            n = v3_scale(n, num_div(NUM_ONE, v3_len(n)));  /* N * (1/|N|), as the demos */
        } else {
            /* divide by r: 1/r in the format is too coarse in Q15.16 for
             * r = 5000; by its 31-bit reciprocal (num_mul_recip: within
             * half an ulp plus 2^-31 of the quotient) */
            const struct rt_obj_cache *oc = &rt->oc[hit->surf];
#if NUM_MODE == NUM_MODE_FIXED
            if (oc->rpow2 >= 0) {
                /* r = 2^s exactly: num_mul_recip's multiplier is 2^31, so its
                 * quotient is |a| / 2^s rounded half up, signed as a (|a| <
                 * 2^31: v3_sub never gives INT32_MIN); s = 0 leaves P - C */
                if (oc->rpow2 > 0)
                    n = v3_make(rt_div_pow2(n.x, oc->rpow2), rt_div_pow2(n.y, oc->rpow2),
                                rt_div_pow2(n.z, oc->rpow2));
                return hit->flip ? v3_neg(n) : n;
            }
#endif
            const struct num_recip *r = &oc->rrcp;
            n = v3_make(num_mul_recip(n.x, r), num_mul_recip(n.y, r), num_mul_recip(n.z, r));
        }
    } else if (o->shape == RT_PLANE) {
        n = o->normal;
    } else {
        n = rt->oc[hit->surf].n;
    }
    return hit->flip ? v3_neg(n) : n;
}
