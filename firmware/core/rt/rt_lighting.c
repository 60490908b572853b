/* SPDX-License-Identifier: MIT */
/* rt_lighting.c — ComputeLighting (chapter 3) with shadows (chapter 4) and
 * chapter 5's shadow-ray optimisations.
 *
 * The formulas keep the demos' operation order in every mode: N unit (or
 * nearly), L and V unnormalised, i += (I*(n.l))/(|N|*|L|) and
 * i += I*pow((r.v)/(|R|*|V|), s). In Q15.16 they hold for |L| up to 16000:
 * n.l and r.v are wide dot products rounded once, |L| comes from a wide sum.
 * Fixed point, a sphere's normal (P - C) / r: |N| differs from 1 by the
 * roundings of P and N alone, so (I n.l) / |N| is taken to first order in
 * N.N - 1 (exact products; rt_div_near_unit) instead of rounding |N| to
 * the format, and / |L| from L.L without rounding |L| on its own
 * (v3_div_len), or by a directional light's reciprocal made once.
 */
#include "rt_int.h"

/* in_shadow over the candidates of the ray's sphere and light
 * (rt_shadow_masks; the shortcuts on): the others are certainly missed, so
 * the answer is the same; the cached occluder first when it is one. A call
 * of its own: the lighting's code for scenes without them stays as it was. */
static RT_NOINLINE int in_shadow_masked(struct rt_state *rt, struct rt_ray *ray, num t_max, uint16_t light,
                                        uint32_t mask)
{
    struct rt_hit hit;
    hit.fr.d = 0;
    rt->n.shadow_rays++;
    rt->shadow_test = 1;
    int got = rt_shadow_search(rt, ray, rt->s->rt.epsilon, t_max, mask, rt->occluder[light], &hit);
    rt->shadow_test = 0;
    if (got) rt->occluder[light] = hit.item;
    return got;
}

/* Shadow test: is anything between P and the light (t in (epsilon, t_max))?
 * With any-hit the search stops at the first occluder; with the cache the
 * last occluder of this light is tried first (shadows are coherent). */
static int in_shadow(struct rt_state *rt, struct rt_ray *ray, num t_max, uint16_t light, const uint32_t *mask)
{
    if (mask) return in_shadow_masked(rt, ray, t_max, light, *mask);
    const struct rt_options *o = &rt->s->rt;
    struct rt_hit hit;
    hit.fr.d = 0;   /* no best hit yet (rt_frac); the rest is written by a hit */
    rt->n.shadow_rays++;
    int cache = o->shadow_cache || rt->shortcuts;   /* same image either way */
    /* only whether something is in the way matters: with the shortcuts on,
     * the first occluder found answers (same image as the closest), and
     * the sphere tests need not find where */
    rt->shadow_test = rt->shortcuts;
    if (cache && rt->occluder[light] >= 0) {
        if (rt_item_hit(rt, rt->occluder[light], ray, o->epsilon, t_max, &hit)) {
            rt->shadow_test = 0;
            return 1;
        }
        rt->skip_item = rt->occluder[light];   /* tested already */
    }
    int found = rt_closest_intersection(rt, ray, o->epsilon, t_max, &hit, o->shadow_any_hit || rt->shortcuts);
    rt->skip_item = -1;
    rt->shadow_test = 0;
    if (!found) return 0;
    if (cache) rt->occluder[light] = hit.item;
    return 1;
}

/* 1 only when the shadow ray from P along d certainly meets its own sphere
 * obj (P on it, n = (P - C) / r as rt_hit_normal rounds it, unflipped) at
 * the root it takes leaving it, t1 = 2b/a' (rt_intersect.c), with eps < t1
 * < 1: a hit in (eps, t_max) for a point light (t_max = 1) and a
 * directional one, so the light is shadowed whatever else lies in the way.
 * For |n_i| <= 2^(F+1), |d_i| <= 2^26 raw and u = 2^-F: ndl = n.d as the
 * lighting rounds it (within 1.5 u), P - C = r n + r h (|h_i| <= 0.51 u),
 * d' = d 2^-k + e (|e_i| <= u/2, 0 for k = 0; A = d.d >= 1/2 so k >= 0 and
 * 2^k <= 1.0001 sqrt(A)), so the root's exact value tau = 2 (B - CO.e 2^k)
 * / (A + 2 d.e 2^k + e.e 4^k), B = -CO.d, lies within 2 r u e1 (e1 = 3 +
 * floor(4 |d|_1) ulps: 1.5 + 0.51 |d|_1 + 3.01 |d|_1) of 2 r (-ndl) over
 * A (1 +- 1.74 u), and the computed t1 within u of tau. So 2 r (m - e1) >=
 * (eps + 16 u) A and 2 r (m + e1) <= (1 - 2^-10) A (m = -ndl) put t1 in
 * (eps, 1). In integers: raw values, products at 2F fraction bits. The
 * terms of d and eps alone (rt_self_dir) are made once for a directional
 * light (rt_light_constants). */
struct rt_self_dir rt_self_dir_make(const vec3 *d, num epsilon)
{
    struct rt_self_dir sd = { 0, 0, 0, 0 };
#if NUM_MODE == NUM_MODE_FIXED
    uint32_t eps = (uint32_t)epsilon;
    uint32_t ax = rt_uabs(d->x), ay = rt_uabs(d->y), az = rt_uabs(d->z);
    sd.e1 = 3u + ((ax + ay + az) >> (NUM_FRAC - 2));
    /* eps in [0, 2^20) */
    if (eps >= (1u << 20)) return sd;
    uint64_t a = rt_usq32(ax) + rt_usq32(ay) + rt_usq32(az);   /* A, below 2^54 */
    if (a < ((uint64_t)1 << (2 * NUM_FRAC - 1))) return sd;   /* A < 1/2: k may be negative */
    sd.alim = a - (a >> 10) - 1;
    uint64_t a16 = (a >> NUM_FRAC) + 1;                       /* >= A / 2^F, below 2^(54-F) + 1 */
    eps += 16u;
    sd.rhs = num_umul32(eps, (uint32_t)a16) + ((uint64_t)(eps * (uint32_t)(a16 >> 32)) << 32);
    sd.ok = 1;
#else
    (void)d; (void)epsilon;
#endif
    return sd;
}

RT_NOINLINE int rt_self_shadowed(const struct rt_state *rt, int16_t obj, num ndl, const vec3 *d,
                                 const struct rt_self_dir *sdp)
{
#if NUM_MODE == NUM_MODE_FIXED
    struct rt_self_dir sd;
    if (!sdp) {
        sd = rt_self_dir_make(d, rt->s->rt.epsilon);
        sdp = &sd;
    }
    uint32_t r = (uint32_t)rt->s->objects[obj].radius;
    uint32_t m = 0u - (uint32_t)ndl;   /* ndl < 0 */
    /* m > e1 and r > 0 */
    if (!sdp->ok || m <= sdp->e1 || (int32_t)r <= 0) return 0;
    if (2 * num_umul32(r, m + sdp->e1) > sdp->alim) return 0;
    return 2 * num_umul32(r, m - sdp->e1) >= sdp->rhs;
#else
    (void)rt; (void)obj; (void)ndl; (void)d; (void)sdp;
    return 0;
#endif
}

/* ---- shadow candidates per light and receiving sphere -----------------
 *
 * A point P within rho = r_j + r_j / 64 + 2^-10 of sphere j's centre C_j
 * sends its shadow ray along segments P -> L (a point light) or rays P + t l
 * (a directional one), all inside the capsule (or half-infinite cylinder)
 * of radius rho around C_j -> L (C_j + t l, t >= 0). A sphere (C, r) whose
 * centre lies more than R = r + rho + m + 2^-10 (1 + r + X + |a|) from that
 * axis (a = L - C_j or l, X = |C - C_j| + rho >= |P - C|) is missed by
 * every such ray. The robust test's discriminant a (r^2 - d^2) (d the
 * line's distance from C) moves by at most a M, M = 4 u (6.25 X^2 + 25 X +
 * 42) (the coarse test's bound, docs/raytracer.md, "Shortcuts"), and m =
 * M / 2r: a line farther than r + m from C is a miss; one nearer meets the
 * sphere only past an end of the segment (the end lies more than r + m
 * from C), and its computed roots, t_c +- sqrt(r^2 - d^2 + M) / |D| at
 * most, stay past it, since (r + m)^2 > r^2 + M. The lengths below carry a
 * few ulps (tile_misses' relative 2^-10 and 16 ulps). A lit point of
 * its own sphere skips that test too (rt_shadow_self_out). */
#if NUM_MODE == NUM_MODE_FIXED && NUM_FRAC >= 14
static int shadow_pair_clear(const struct rt_object *oj, const struct rt_object *os, const struct scene_light *lt)
{
    int directional = lt->type != LIGHT_POINT;
    /* positions, radii below 2^13 and X below 2^10: no sum below saturates */
    if (!rt_v3_within(oj->center, 29) || !rt_v3_within(os->center, 29) || !rt_v3_within(lt->v, 29)) return 0;
    if (oj->radius < 0 || os->radius < NUM_C(1.0 / 16) || oj->radius >= NUM_C(4096.0) || os->radius >= NUM_C(4096.0))
        return 0;
    num rho = oj->radius + (oj->radius >> 6) + (NUM_ONE >> 10) + 1;
    vec3 w = v3_sub(os->center, oj->center);
    vec3 a = directional ? lt->v : v3_sub(lt->v, oj->center);
    wnum aa = v3_dot_wide(a, a), wa = v3_dot_wide(w, a);
    if (aa < wnum_from_num(NUM_ONE)) return 0;   /* |a| >= 1 */
    num wl = v3_len(w), al = v3_len(a);
    num x = wl + rho + 2;
    if (x >= NUM_C(1024.0)) return 0;
    /* m: 4 (6.25 X^2 + 25 X + 42) ulps over 2 r, X rounded up to an integer */
    uint32_t xi = (uint32_t)(x >> NUM_FRAC) + 1u;
    uint64_t mraw = 25u * (uint64_t)xi * xi + 100u * (uint64_t)xi + 168u;   /* 4 (...) in ulps */
    uint64_t m = ((mraw << NUM_FRAC) / (2u * (uint64_t)(uint32_t)os->radius)) + 1u;
    if (m >= (uint64_t)NUM_C(64.0)) return 0;
    /* |a| may lie near the range's end: the sum in 64 bits */
    num eps = (num)m + (num)(((int64_t)NUM_ONE + os->radius + x + al) >> 10) + 1;
    num big = os->radius + rho + eps;   /* below 2^14 scene units */
    wnum lhs, rhs;
    if (wa < -(wnum)16) {
        /* the closest point of the axis is C_j (wa certainly negative) */
        lhs = wnum_from_num(wl);
        rhs = wnum_from_num(big);
    } else if (!directional && wa > aa + 16) {
        /* ... or L */
        lhs = wnum_from_num(v3_len(v3_sub(os->center, lt->v)));
        rhs = wnum_from_num(big);
    } else {
        /* the line's distance |w x a| / |a| (saturation only lowers it) */
        lhs = wnum_from_num(v3_len(v3_cross(w, a)));
        rhs = num_mul_wide(big, al);
    }
    rhs = wnum_add(rhs, wnum_add(wnum_mul(rhs, wnum_from_num(NUM_C(1.0 / 1024))), wnum_from_num(16 * NUM_EPS)));
    return lhs > rhs;
}
#endif

int rt_shadow_masks_fit(const struct scene *s)
{
    /* The same in every number mode and format: scenec sizes the work
     * memory once, with the fixed-point core at NUM_FRAC 12 (an upper bound
     * of the other formats' sizes), where the masks themselves are not made. */
    return s->ncsg == 0 && s->rt.shadows && s->nobjects >= 1 && s->nobjects <= 32;
}

void rt_shadow_masks(struct rt_state *rt)
{
    const struct scene *s = rt->s;
    rt->shadow_self_ok = 0;
    if (!rt_shadow_masks_fit(s) || rt->book || !rt->shortcuts || !rt->all_spheres || rt->nitems != s->nobjects ||
        !s->rt.shadows) {
        rt->shadow_mask = NULL;
        return;
    }
#if NUM_MODE == NUM_MODE_FIXED && NUM_FRAC >= 14
    uint32_t all = ~(uint32_t)0 >> (32 - s->nobjects);
    for (uint16_t j = 0; j < s->nobjects; j++) {
        const struct rt_object *oj = &s->objects[j];
        if (oj->radius >= NUM_C(0.25)) rt->shadow_self_ok |= (uint32_t)1 << j;
        for (uint16_t k = 0; k < s->nlights; k++) {
            uint32_t m = all;
            if (s->lights[k].type != LIGHT_AMBIENT)
                for (uint16_t i = 0; i < s->nobjects; i++)
                    if (i != j && shadow_pair_clear(oj, &s->objects[i], &s->lights[k])) m &= ~((uint32_t)1 << i);
            rt->shadow_mask[(size_t)j * s->nlights + k] = m;
        }
    }
#else
    rt->shadow_mask = NULL; /* its words stay unused in this mode */
#endif
}

#if NUM_MODE == NUM_MODE_FIXED
/* 1 when the shadow ray from a point P of a plain sphere of radius r >=
 * 1/4 along d (|d_i| <= 2^26 raw) certainly misses that sphere: its test
 * (the ray's own sphere, rt_intersect.c) finds b = -CO.d' <= 0, no hit.
 * For a point that took its sphere's candidates (|n| <= 1 + 2^-7, n as
 * rt_hit_normal rounds it, ndl = n.d as the lighting rounds it), u = 2^-F
 * and |d|_1 in scene units: CO = P - C = r n + r h (|h_i| <= 0.51 u), so
 * CO.d >= r (ndl - 1.5 u - 0.51 u |d|_1) and |CO|_1 <= 1.76 r; d' = d 2^-k
 * + e (|e_i| <= u/2, 2^k <= 1.0001 |d| for k > 0; exact for k <= 0), so
 * CO.d' >= 2^-k CO.d - 0.88 r u. With e1 = 3 + floor(4 |d|_1) ulps
 * (rt_self_dir), ndl > 8 e1 >= (16 + 32 |d|_1) u leaves CO.d' >= 7.6 u for
 * k > 0 and >= 3.6 u for k <= 0, more than the 1.5 u of b's three rounded
 * products. */
static inline int rt_shadow_self_out(num ndl, const vec3 *d)
{
    uint32_t e1 = 3u + ((rt_uabs(d->x) + rt_uabs(d->y) + rt_uabs(d->z)) >> (NUM_FRAC - 2));
    return (uint32_t)ndl > 8u * e1;
}
#endif

num rt_compute_lighting(struct rt_state *rt, vec3 p, vec3 n, int unit_normal, vec3 v, num s, num s_zero,
                        int16_t origin, uint8_t *shadow_bits)
{
    const struct scene *sc = rt->s;
    const struct rt_options *o = &sc->rt;
    num i = rt->amb_i;   /* the leading ambient lights (rt_light_constants) */
    /* |N| and |V| as the demos compute them, each once and only if a term
     * needs it */
    num len_n = NUM_ZERO, len_v = NUM_ZERO;
    int have_n = 0, have_v = 0;
    int unit_n = unit_normal ? -1 : 0;   /* -1: N.N - 1 not yet formed (rt_near_unit_err) */
    int32_t unit_e = 0;
    if (!rt->shortcuts) {
        len_n = v3_len(n);
        len_v = v3_len(v);
        have_n = have_v = 1;
    }
#if NUM_MODE == NUM_MODE_FIXED
    /* |N_i| and |V_i| at most 2 (2^(F+1) raw): with |L_i| <= 2^26 raw the
     * products below take 32-bit forms of the same values (rt_dot_small) */
    int n_small = rt_v3_within(n, NUM_FRAC + 1), v_small = rt_v3_within(v, NUM_FRAC + 1);
    /* the shadow candidates of P's sphere (rt_shadow_masks) where P lies
     * within r (1 + 2^-6) of its centre: n = (P - C) / r rounded, P - C = r
     * n + r h (|h_i| <= 0.51 u), and with b_i = ceil(|n_i| / 2^(F-14)) the
     * sum of b_i^2 <= 2^28 + 2^22 gives |n| <= 1 + 2^-7 */
    const uint32_t *smask = NULL;
#if NUM_FRAC >= 14
    if (rt->shadow_mask && unit_normal && n_small && origin >= 0 && o->shadows) {
        uint32_t bx = (rt_uabs(n.x) + (1u << (NUM_FRAC - 14)) - 1u) >> (NUM_FRAC - 14);
        uint32_t by = (rt_uabs(n.y) + (1u << (NUM_FRAC - 14)) - 1u) >> (NUM_FRAC - 14);
        uint32_t bz = (rt_uabs(n.z) + (1u << (NUM_FRAC - 14)) - 1u) >> (NUM_FRAC - 14);
        if (bx * bx + by * by + bz * bz <= (1u << 28) + (1u << 22))
            smask = rt->shadow_mask + (size_t)origin * sc->nlights;
    }
#endif
#endif
    for (uint16_t k = rt->amb_k; k < sc->nlights; k++) {
        const struct scene_light *lt = &sc->lights[k];
        if (lt->type == LIGHT_AMBIENT) {
            i = num_add(i, lt->intensity);
            continue;
        }
        vec3 l;
        num t_max;
        int directional = lt->type != LIGHT_POINT;
        if (!directional) {
#if NUM_MODE == NUM_MODE_FIXED
            /* a hit point proven within half the format (SCENE_FITS_HIT)
             * and a light inside it (rt_state.light_fit): the 32-bit
             * difference is never saturated, v3_sub's bits */
            if (k < 32 && ((rt->light_fit >> k) & 1u))
                l = v3_make((num)((uint32_t)lt->v.x - (uint32_t)p.x), (num)((uint32_t)lt->v.y - (uint32_t)p.y),
                            (num)((uint32_t)lt->v.z - (uint32_t)p.z));
            else
#endif
                l = v3_sub(lt->v, p);
            t_max = NUM_ONE;       /* L unnormalised: the light is at t = 1 */
        } else {
            l = lt->v;
            t_max = NUM_MAX;
        }
#if NUM_MODE == NUM_MODE_FIXED
        /* |N_i| <= 2^(F+1), |L_i| <= 2^26: |N.L| <= 3 * 2^27, |2 N.L| <= 3 * 2^28 */
        int small = n_small && rt_v3_within(l, 26);
        /* a directional light's integer components: one product each */
        num n_dot_l = !small ? v3_dot(n, l) : directional && rt_v3_integral(l) ? rt_dot_small_int(n, l)
                                                                                : rt_dot_small(n, l);
#else
        num n_dot_l = v3_dot(n, l);
#endif
        if (o->shadows) {
#if NUM_MODE == NUM_MODE_FIXED
            /* a light behind the surface of a sphere (no CSG: a plain one,
             * its normal unflipped): its own sphere shadows it
             * (rt_self_shadowed), without the ray */
            if (n_dot_l < 0 && small && unit_normal && rt->shortcuts && sc->ncsg == 0 &&
                rt_self_shadowed(rt, origin, n_dot_l, &l, directional ? &rt->light_self[k] : NULL)) {
                rt->n.shadow_rays++;
                if (shadow_bits && k < 7) *shadow_bits |= (uint8_t)(1u << k);
                continue;
            }
#endif
            const uint32_t *mk = NULL;
#if NUM_MODE == NUM_MODE_FIXED
            uint32_t mown;
            if (smask) {
                mk = &smask[k];
                /* a lit point's ray leaves its own sphere (rt_shadow_self_out) */
                if (n_dot_l > 0 && small && ((rt->shadow_self_ok >> origin) & 1u) &&
                    rt_shadow_self_out(n_dot_l, &l)) {
                    mown = *mk & ~((uint32_t)1 << origin);
                    mk = &mown;
                }
                if (*mk == 0) {
                    /* nothing can lie in the way: not shadowed, without the ray */
                    rt->n.shadow_rays++;
                    goto lit;
                }
            }
#endif
            struct rt_ray sr, *srp = &sr;
            if (directional && rt->shortcuts) {
                /* the light's own ray (rt_light_constants), the direction's
                 * forms made once: only its origin changes (the tests
                 * leave the rest as it is) */
                srp = &rt->light_ray[k];
                srp->o.x = p.x; srp->o.y = p.y; srp->o.z = p.z;   /* no memcpy call */
                rt_cpt_set(&srp->cd.o, p);
                srp->origin = origin;
            } else {
                rt_ray_init(&sr, &p, &l, origin, 0);
            }
            if (in_shadow(rt, srp, t_max, k, mk)) {
                if (shadow_bits && k < 7) *shadow_bits |= (uint8_t)(1u << k);
                continue;
            }
        }
#if NUM_MODE == NUM_MODE_FIXED
    lit:
#endif
        if (o->diffuse && n_dot_l > 0) {
            num in = rt_mul_weight(n_dot_l, lt->intensity), q;
            if (unit_n < 0) unit_n = rt_near_unit_err(n, &unit_e);
            if (unit_n && rt_div_near_unit(in, unit_e, &q)) {
                /* (I n.l) / |N| to first order in |N|^2 - 1, then / |L|: a
                 * directional light's by its reciprocal made once (num_div_by:
                 * the same bits as num_div), a point light's from L.L exactly */
                i = num_add(i, directional ? num_div_by(q, &rt->light_div[k]) : v3_div_len(q, l));
            } else {
                num len_l = directional && rt->shortcuts ? rt->light_len[k] : v3_len(l);
                if (!have_n) { len_n = v3_len(n); have_n = 1; }
                i = num_add(i, num_div(in, num_mul(len_n, len_l)));
            }
        }
        /* The demos run this step even when n.l <= 0; only shadows stop it. */
        if (o->specular && s >= 0) {
#if NUM_MODE == NUM_MODE_FIXED
            vec3 r = rt_reflect(n, l, n_dot_l, small);
#else
            vec3 r = rt_reflect(n, l, n_dot_l, 0);
#endif
#if NUM_MODE == NUM_MODE_FIXED
            const num r_dot_v = v_small && rt_v3_within(r, 28) ? rt_dot_small(v, r) : v3_dot(r, v);
#else
            const num r_dot_v = v3_dot(r, v);
#endif
            if (r_dot_v > 0) {
                /* cos <= s_zero: pow(cos, s) is exactly 0, and so is the term */
                if (rt->shortcuts && rt_coarse_cos_at_most(r, v, s_zero)) continue;
                if (!have_v) { len_v = v3_len(v); have_v = 1; }
                num den = num_mul(v3_len(r), len_v);
                if (rt->shortcuts && rt_div_at_most(r_dot_v, den, s_zero)) continue;
                num cosb = num_div(r_dot_v, den);
                i = num_add(i, rt_mul_weight(num_powi(cosb, (uint32_t)num_to_int(s)), lt->intensity));
            }
        }
    }
    return i;
}
