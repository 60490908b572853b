/* SPDX-License-Identifier: MIT */
/* rt_trace.c — TraceRay with reflections (chapter 4) and chapter 5's
 * transparency; the camera (CanvasToViewport, chapter 5's rotation) and the
 * primary rays through the canvas. */
#include "rt_int.h"
#include "rt_num.h"

static rgb background(const struct rt_state *rt) { return rt->s->background; }

/* The object whose material an item shows (a CSG shows operand a's). */
static int16_t item_material_object(const struct rt_state *rt, int16_t item)
{
    const struct scene *s = rt->s;
    return item >= (int16_t)s->nobjects ? (int16_t)s->csg[item - s->nobjects].a : item;
}

/* ReflectRay: R = N*(2*(V.N)) - V; fixed point, with |N_i| <= 2^(F+1) and
 * |V_i| <= 2^26, V.N and R in 32-bit arithmetic (rt_dot_small, rt_reflect:
 * the same bits). */
static vec3 reflect_ray(vec3 v, vec3 n)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (rt_v3_within(n, NUM_FRAC + 1) && rt_v3_within(v, 26)) return rt_reflect(n, v, rt_dot_small(n, v), 1);
#endif
    return rt_reflect(n, v, v3_dot(v, n), 0);
}

int rt_refract(vec3 d, vec3 n, num ior, vec3 *out)
{
    vec3 dn = v3_normalize(d);
    num cosi = num_neg(v3_dot(n, dn));
    num eta;
    if (cosi < 0) {            /* leaving the object */
        n = v3_neg(n);
        cosi = num_neg(cosi);
        eta = ior;
    } else {
        eta = num_div(NUM_ONE, ior);
    }
    num k = num_sub(NUM_ONE, num_mul(num_mul(eta, eta), num_sub(NUM_ONE, num_mul(cosi, cosi))));
    if (k < 0) return 0;
    *out = v3_add(v3_scale(dn, eta), v3_scale(n, num_sub(num_mul(eta, cosi), num_sqrt(k))));
    return 1;
}

/* Colour x weight and colour + colour, in 32-bit arithmetic when the
 * scene's format analysis proved colour intermediates in range
 * (SCENE_FITS_COLOUR: same bits, no saturation checks). */
static RT_NOINLINE rgb colour_scale_sat(rgb c, num k) { return rgb_scale(c, k); }
/* the proven case inline, the saturating one a call (code size) */
RT_ALWAYS_INLINE rgb colour_scale(const struct scene *s, rgb c, num k)
{
    if (s->fits & SCENE_FITS_COLOUR) {
#if NUM_MODE == NUM_MODE_FIXED && NUM_FRAC == 16
        /* a weight in [0, 1): two products a channel (rt_mul_round_u16, the same bits) */
        if ((uint32_t)k < 0x10000u)
            return rgb_make(rt_mul_round_u16(c.r, (uint32_t)k), rt_mul_round_u16(c.g, (uint32_t)k),
                            rt_mul_round_u16(c.b, (uint32_t)k));
#endif
        return rgb_make(num_mul_fit(c.r, k), num_mul_fit(c.g, k), num_mul_fit(c.b, k));
    }
    return colour_scale_sat(c, k);
}
static inline rgb colour_add(const struct scene *s, rgb a, rgb b)
{
    if (s->fits & SCENE_FITS_COLOUR) return rgb_make(num_add_fit(a.r, b.r), num_add_fit(a.g, b.g), num_add_fit(a.b, b.b));
    return rgb_add(a, b);
}

/* TraceRay: colour seen along the ray with t in (t_min, t_max); `depth`
 * more reflection/refraction bounces allowed (bounded recursion). A primary
 * ray notes what it found in *prim (else NULL). */
static rgb trace_ray(struct rt_state *rt, struct rt_ray *ray, num t_min, num t_max, int depth,
                     struct rt_prim *prim)
{
    const struct scene *s = rt->s;
    struct rt_hit hit;
    rt->n.rays++;
    if (!rt_closest_intersection(rt, ray, t_min, t_max, &hit, 0)) {
        if (prim) prim->item = -1;
        return background(rt);
    }
    if (prim) prim->item = hit.item;
    int16_t mo = item_material_object(rt, hit.item);
    const struct rt_material *m = &s->objects[mo].mat;
    /* P = O + D t; D t and the sum in 32-bit arithmetic when every hit is
     * proven to lie on a bounded object (SCENE_FITS_HIT: O and P, a camera
     * or hit point and a hit point, are positions, each within half the
     * format, so the sum is P itself, never saturated: v3_add's bits) */
    vec3 p = s->fits & SCENE_FITS_HIT
                 ? v3_make(num_add_fit(ray->o.x, num_mul_fit(ray->d.x, hit.t)),
                           num_add_fit(ray->o.y, num_mul_fit(ray->d.y, hit.t)),
                           num_add_fit(ray->o.z, num_mul_fit(ray->d.z, hit.t)))
             : hit.t == RT_T_FAR ? rt_far_point(ray)
                                 : v3_add(ray->o, v3_scale(ray->d, hit.t));
    if (rt->hit_probe) {
        num *m = &rt->hit_probe[hit.surf];
        *m = num_max(*m, v3_len(p));
    }
    vec3 n = rt_hit_normal(rt, &hit, &p);
    vec3 v = v3_neg(ray->d);
    rgb local;
    if (s->rt.unlit) {
        local = m->color;
    } else {
        /* (P - C) / r of a sphere: |N| = 1 up to rounding (the book
         * formulation normalises its own way) */
        int unit_n = !rt->book && (rt->all_spheres || s->objects[hit.surf].shape == RT_SPHERE);
        num i = rt_compute_lighting(rt, p, n, unit_n, v, m->specular, rt->oc[mo].spec_zero, hit.surf,
                                    prim ? &prim->shadow : NULL);
        local = colour_scale(s, m->color, i);
    }
    num r = m->reflective;
    num tr = m->transparency;
    if (depth <= 0 || (r <= 0 && tr <= 0)) return local;

    rgb out = local;
    if (r > 0) {
        struct rt_ray rr;
        vec3 rd = reflect_ray(v, n);
        rt_ray_init(&rr, &p, &rd, hit.surf, 0);
        rgb reflected = trace_ray(rt, &rr, s->rt.epsilon, NUM_MAX, depth - 1, NULL);
        out = colour_add(s, colour_scale(s, local, num_sub(NUM_ONE, r)), colour_scale(s, reflected, r));
    }
    if (tr > 0) {
        /* Transparency: what the refracted ray sees, by Snell's law; on total
         * internal reflection the ray reflects instead. */
        vec3 dir;
        if (!rt_refract(ray->d, n, m->refraction > 0 ? m->refraction : NUM_ONE, &dir))
            dir = reflect_ray(v, n);
        struct rt_ray tr_ray;
        rt_ray_init(&tr_ray, &p, &dir, hit.surf, 0);
        rgb seen = trace_ray(rt, &tr_ray, s->rt.epsilon, NUM_MAX, depth - 1, NULL);
        out = colour_add(s, colour_scale(s, out, num_sub(NUM_ONE, tr)), colour_scale(s, seen, tr));
    }
    return out;
}

/* Where a far plane hit (RT_T_FAR) is shaded: along the ray at distance
 * NUM_MAX / 8 from its origin. The true point lies farther than the format
 * reaches; this one is far from the lights of a scene the format analysis
 * sized (every position under NUM_MAX / 2), so a light vector L - P points
 * nearly as the true one does, and L - P stays inside the format. (Moved
 * onto the plane, so that N.L is the true one's, it measured worse:
 * demo/mirror-spheres 71.2 -> 65.7 dB.) The hit's order among the others
 * does not depend on it (RT_T_FAR). */
vec3 rt_far_point(const struct rt_ray *ray)
{
    num len = v3_len(ray->d);
    if (len <= 0) return ray->o;
    return v3_add(ray->o, v3_scale(ray->d, num_div(NUM_MAX / 8, len)));
}

/* CanvasToViewport for canvas point (x, y) (num, sub-pixel allowed), then
 * the camera rotation. */
static vec3 rotate_turned(const struct rt_state *rt, vec3 d)
{
    /* D'[i] = ((0 + D.x*M[i][0]) + D.y*M[i][1]) + D.z*M[i][2], the demo's order */
    vec3 r;
    const mat3 *m = &rt->cam_rot;
    r.x = num_add(num_add(num_add(NUM_ZERO, num_mul(d.x, m->m[0][0])), num_mul(d.y, m->m[0][1])), num_mul(d.z, m->m[0][2]));
    r.y = num_add(num_add(num_add(NUM_ZERO, num_mul(d.x, m->m[1][0])), num_mul(d.y, m->m[1][1])), num_mul(d.z, m->m[1][2]));
    r.z = num_add(num_add(num_add(NUM_ZERO, num_mul(d.x, m->m[2][0])), num_mul(d.y, m->m[2][1])), num_mul(d.z, m->m[2][2]));
    return r;
}

/* The common case, a camera not turned, without a call. */
static inline vec3 rotate_direction(const struct rt_state *rt, vec3 d)
{
    return rt->cam_rotated ? rotate_turned(rt, d) : d;
}

static vec3 canvas_to_viewport(const struct rt_state *rt, num x, num y)
{
    /* (x*Vw)/W rather than x*(Vw/W): Vw/W = 1/600 in Q15.16 is 0.02% off,
     * a whole pixel at the edge of a 600-pixel canvas */
    return rotate_direction(rt, v3_make(num_div(num_mul(x, rt->vw), rt->wn), num_div(num_mul(y, rt->vh), rt->hn), rt->d));
}

/* The same for a pixel's centre: x from the column table, y once a row. */
static vec3 pixel_to_viewport(struct rt_state *rt, int col, int row)
{
    if (rt->row_y_tab) return rotate_direction(rt, v3_make(rt->col_x[col], rt->row_y_tab[row], rt->d));
    if (rt->row_y_row != row) {
        rt->row_y = num_div(num_mul(num_from_int(rt->h / 2 - 1 - row), rt->vh), rt->hn);
        rt->row_y_row = row;
    }
    return rotate_direction(rt, v3_make(rt->col_x[col], rt->row_y, rt->d));
}

/* ---- primary rays' candidate lists -------------------------------------
 *
 * A tile's primary rays have directions D(x, y) = R (x Vw/W, y Vh/H, d),
 * affine in the canvas point, so every one lies within H of the centre Dc
 * of the tile's four corners, H their largest distance from it (plus the
 * pixels' own rounding). For unit directions |u - uc| <= 2 |D - Dc| / |Dc|,
 * so a line from the camera along any of them passes at least
 * |CO x Dc| / |Dc| - 2 |CO| H / |Dc| from a sphere's centre; when that is
 * more than r + rt_tile_eps the sphere test of each of those rays reports
 * a miss, and the sphere leaves the tile's list. So it does when the camera
 * is outside the sphere (c = CO.CO - r^2 > 0, formed as the sphere test
 * forms it) and CO.D >= CO.Dc - |CO| H stays positive: the whole sphere is
 * behind every ray (the robust test's early-out, c > 0 and b <= 0). The lists keep the book's
 * order, so ties go as without them: the image is the same bits. */

/* The viewport x and y of integer canvas coordinates, as the pixels' own;
 * canvas_dir's direction of (x, y) is rotate_direction of (x, y, d). */
static num canvas_vx(const struct rt_state *rt, int x) { return num_div(num_mul(num_from_int(x), rt->vw), rt->wn); }
static num canvas_vy(const struct rt_state *rt, int y) { return num_div(num_mul(num_from_int(y), rt->vh), rt->hn); }

/* A sphere's |CO| and margin for tile_misses (the same for every tile of
 * the frame): 0 when it is not tested (kept in every list). */
static int tile_sphere(const struct rt_object *o, const struct rt_obj_cache *oc, num *colen, num *eps)
{
    /* r + |CO| + 1 below NUM_MAX: rt_tile_eps's sum and r + eps hold */
    if (o->radius < NUM_C(1.0 / 64) || o->radius >= NUM_MAX / 2) return 0;
    *colen = v3_len(oc->co_cam);
    if (*colen >= NUM_MAX / 2 || num_add(o->radius, *colen) >= num_sub(NUM_MAX, NUM_ONE)) return 0;
    *eps = rt_tile_eps(o->radius, *colen);
    return 1;
}

/* 1 when every line from the camera within hh of direction dc (length
 * dclen) certainly misses sphere o, whose per-frame constants are oc (CO
 * and c as the sphere test takes them) and colen, eps (tile_sphere).
 * Saturation only ever lowers |CO x Dc| (a lower bound stays one); the
 * right side is kept far from it. */
static int tile_misses(const struct rt_object *o, const struct rt_obj_cache *oc, num colen, num eps, vec3 dc,
                       num dclen, num hh)
{
    vec3 co = oc->co_cam;
    /* the rounding of the lengths and products below: 2^-10 and 16 ulps */
    wnum ulp16 = wnum_from_num(16 * NUM_EPS), rel = wnum_from_num(NUM_C(1.0 / 1024));
    wnum sweep = num_mul_wide(colen, hh);
    sweep = wnum_add(sweep, wnum_add(wnum_mul(sweep, rel), ulp16));
    if (oc->c_cam > 0 && v3_dot_wide(co, dc) > sweep) return 1;   /* behind */
    wnum rhs = wnum_add(num_mul_wide(num_add(o->radius, eps), dclen), wnum_add(sweep, sweep));
    rhs = wnum_add(rhs, wnum_add(wnum_mul(rhs, rel), ulp16));
    return wnum_from_num(v3_len(v3_cross(co, dc))) > rhs;
}

/* tile_lists keeps tile_sphere's forms of the first items for the whole
 * tile row (the others are formed again a tile) */
#define TILE_KEPT 8

/* The rows tile row tr's lists serve (RT_TILE in rt_int.h). */
static int tile_first_row(int32_t tr) { return tr * RT_TILE; }
static int tile_last_row(int32_t tr) { return tr * RT_TILE + RT_TILE - 1 + RT_MAX_ADAPT; }

/* Tile column tc's list. */
static int16_t *tile_list(struct rt_state *rt, int tc)
{
    return rt->tile_items + (size_t)tc * (rt->nitems ? rt->nitems : 1);
}

/* The lists of tile row tr: every tile column's items (book order), for
 * the rows it serves and one more either side (sub-pixel samples). Not
 * inlined: prim_list, once a pixel, stays a small function. */
static RT_NOINLINE void tile_lists(struct rt_state *rt, int32_t tr)
{
    const struct scene *s = rt->s;
    int r0 = tile_first_row(tr) - 1, r1 = tile_last_row(tr) + 1;
    /* the corners' viewport y once for the tile row, x once a tile */
    num vy0 = canvas_vy(rt, rt->h / 2 - 1 - r0), vy1 = canvas_vy(rt, rt->h / 2 - 1 - r1);
    num colen[TILE_KEPT], eps[TILE_KEPT];
    uint8_t tested[TILE_KEPT];
    for (uint16_t i = 0; i < rt->nitems && i < TILE_KEPT; i++) {
        int16_t item = rt->items[i];
        tested[i] = item < (int16_t)s->nobjects && s->objects[item].shape == RT_SPHERE &&
                    tile_sphere(&s->objects[item], &rt->oc[item], &colen[i], &eps[i]);
    }
    for (uint16_t tc = 0; tc < rt->ntc; tc++) {
        num vx0 = canvas_vx(rt, tc * RT_TILE - 1 - rt->w / 2), vx1 = canvas_vx(rt, tc * RT_TILE + RT_TILE - rt->w / 2);
        vec3 k[4] = { rotate_direction(rt, v3_make(vx0, vy0, rt->d)), rotate_direction(rt, v3_make(vx1, vy0, rt->d)),
                      rotate_direction(rt, v3_make(vx0, vy1, rt->d)), rotate_direction(rt, v3_make(vx1, vy1, rt->d)) };
        vec3 dc = v3_scale(v3_add(v3_add(k[0], k[1]), v3_add(k[2], k[3])), NUM_C(0.25));
        num dclen = v3_len(dc), hh = NUM_ZERO;
        for (int i = 0; i < 4; i++) hh = num_max(hh, v3_len(v3_sub(k[i], dc)));
        /* each pixel's direction: a few roundings off the affine family */
        hh = num_add(num_add(hh, 16 * NUM_EPS), num_mul(dclen, NUM_C(1.0 / 4096)));
        int16_t *list = tile_list(rt, tc);
        uint16_t n = 0;
        for (uint16_t i = 0; i < rt->nitems; i++) {
            int16_t item = rt->items[i];
            num cl = NUM_ZERO, ep = NUM_ZERO;
            int t;
            if (i < TILE_KEPT) {
                t = tested[i];
                cl = colen[i];
                ep = eps[i];
            } else {
                t = item < (int16_t)s->nobjects && s->objects[item].shape == RT_SPHERE &&
                    tile_sphere(&s->objects[item], &rt->oc[item], &cl, &ep);
            }
            if (t && tile_misses(&s->objects[item], &rt->oc[item], cl, ep, dc, dclen, hh)) continue;
            list[n++] = item;
        }
        rt->tile_n[tc] = n;
    }
    rt->tile_row = tr;
}

/* The list of the primary rays through pixel (col, row) (clamped to the
 * image), built when its tile row's lists are not at hand. */
static void prim_list(struct rt_state *rt, int col, int row)
{
    /* the coarse preview's one ray a block does not repay a tile row's lists */
    if (!rt->tiles || rt->pass == RENDER_PASS_COARSE) return;
    if (col < 0) col = 0;
    if (col >= rt->w) col = rt->w - 1;
    if (row < 0) row = 0;
    if (row >= rt->h) row = rt->h - 1;
    int32_t tr = rt->tile_row;
    /* tr < 0, or row outside [tile_first_row(tr), tile_last_row(tr)] */
    if (tr < 0 || (uint32_t)(row - tile_first_row(tr)) > (uint32_t)(RT_TILE - 1 + RT_MAX_ADAPT))
        tile_lists(rt, row / RT_TILE);
    unsigned tc = (unsigned)col / RT_TILE;
    rt->prim_items = tile_list(rt, (int)tc);
    rt->prim_n = rt->tile_n[tc];
}

/* Row row's candidate intervals (rt_state.iv): its slot, claimed with
 * every interval still to form when it holds another row (they are formed
 * on first use, rt_row_interval); NULL without the tile lists or the
 * per-frame constants. */
static int16_t *row_iv(struct rt_state *rt, int row)
{
    if (!rt->tiles || !rt->cached) return NULL;
    unsigned slot = (unsigned)row % rt->iv_rows;
    uint16_t n = rt->s->nobjects;
    int16_t *iv = rt->iv + (size_t)slot * 2 * n;
    if (rt->iv_tag[slot] != row) {
        rt->iv_tag[slot] = row;
        for (uint16_t i = 0; i < n; i++) iv[2 * i] = RT_IV_TODO;
    }
    return iv;
}

/* A primary ray through pixel (col, row) with the camera not turned, or
 * turned by the scene's own rotation: its exact direction (x vh, y vh, d h)
 * (rt_exact_comp in rt_num.h), the row's part once a row; turned by the
 * precise rotation (rt_exact_turn). Nothing where it does not fit. */
static void exact_dir(struct rt_state *rt, struct rt_ray *ray, int col, int row)
{
    if (rt->dx_row != row) {
        rt->dx_row = row;
        int ok = rt->h <= 1024 && rt_exact_comp(rt->vh, rt->h / 2 - 1 - row, &rt->dx_y) &&
                 rt_exact_comp(rt->d, rt->h, &rt->dx_z);
        rt->dx_ok = (uint8_t)((rt->dx_ok & 2) | ok);   /* the columns' bit is the render's */
        if (ok && rt->cam_rotated) rt_exact_turn_row(rt->cam_q29, rt->dx_y, rt->dx_z, rt->dx_turn);
        else if (ok) rt->dx_yz = rt_exact_sq(rt->dx_y) + rt_exact_sq(rt->dx_z);
        rt->dx_iv = ok && !rt->cam_rotated ? row_iv(rt, row) : NULL;
    }
    num vx;
    if (!(rt->dx_ok & 1)) return;
    if (rt->dx_ok & 2) vx = rt->vh * (col - rt->w / 2);   /* every column fits (init_viewport) */
    else if (!rt_exact_comp(rt->vh, col - rt->w / 2, &vx)) return;
    if (!rt->cam_rotated) {
        ray->dx.x = vx;
        ray->dx.y = rt->dx_y;
        ray->dx.z = rt->dx_z;
        ray->dxa = rt->dx_yz + rt_exact_sq(vx);
        ray->dxrow = row;
        rt->prim_iv = rt->dx_iv;
        rt->prim_col = (int16_t)col;
    } else if (rt_exact_turn(rt->cam_q29, rt->dx_turn, vx, &ray->dx)) {
        ray->dxa = rt_exact_sq(ray->dx.x) + rt_exact_sq(ray->dx.y) + rt_exact_sq(ray->dx.z);
        rt->prim_col = (int16_t)col;   /* the unrounded direction's column (turn_touch) */
    } else {
        return;
    }
    ray->dxm = rt->h;
}

/* One primary ray along d (from the camera); through pixel (col, row)
 * (col < 0: a sub-pixel sample) the sphere tests take its exact direction
 * where it has one (exact_dir). */
static rgb trace_primary(struct rt_state *rt, vec3 d, int col, int row, struct rt_prim *prim)
{
    struct rt_ray ray;
    prim->item = -1;
    prim->shadow = 0;
    rt_ray_init_primary(&ray, &rt->cam_pos, &d);
    if (col >= 0 && !rt->book && (!rt->cam_rotated || rt->cam_q29)) exact_dir(rt, &ray, col, row);
    if (!rt->prim_iv) rt_ray_cd_now(&ray);   /* no intervals: the coarse tests decide */
    rt->n.primary_rays++;
    rgb c = trace_ray(rt, &ray, rt->s->rt.t_min_primary, NUM_MAX, rt->depth, prim);
    rt->prim_items = NULL;
    rt->prim_iv = NULL;
    return c;
}

rgb rt_trace_canvas(struct rt_state *rt, num x, num y, struct rt_prim *prim)
{
    /* the pixel nearest to canvas point (x, y): its tile's list covers the
     * sample (one column and row of margin) */
    prim_list(rt, num_floor_int(num_add(x, NUM_HALF)) + rt->w / 2, rt->h / 2 - 1 - num_floor_int(num_add(y, NUM_HALF)));
    return trace_primary(rt, canvas_to_viewport(rt, x, y), -1, -1, prim);
}

rgb rt_trace_pixel(struct rt_state *rt, int col, int row, struct rt_prim *prim)
{
    if (row == rt->bg_row && col >= rt->bg_lo && col <= rt->bg_hi) {
        /* certainly the background (a run closest_prim found): the ray
         * trace_primary would trace, and its tests, counted */
        rt->n.rays++;
        rt->n.primary_rays++;
        rt->n.tests += rt->bg_tests;
        prim->item = -1;
        prim->shadow = 0;
        return background(rt);
    }
    prim_list(rt, col, row);
    return trace_primary(rt, pixel_to_viewport(rt, col, row), col, row, prim);
}
