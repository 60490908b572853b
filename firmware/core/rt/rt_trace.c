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

/* ReflectRay: R = N*(2*(V.N)) - V. */
static vec3 reflect_ray(vec3 v, vec3 n)
{
    num d = v3_dot(v, n);
    return v3_sub(v3_scale(n, num_add(d, d)), v);     /* 2 (V.N) as a sum: the same bits */
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
static inline rgb colour_scale(const struct scene *s, rgb c, num k)
{
    if (s->fits & SCENE_FITS_COLOUR) return rgb_make(num_mul_fit(c.r, k), num_mul_fit(c.g, k), num_mul_fit(c.b, k));
    return rgb_scale(c, k);
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
    /* P = O + D t; D t in 32-bit arithmetic when every hit is proven to lie
     * on a bounded object (SCENE_FITS_HIT) */
    vec3 p = s->fits & SCENE_FITS_HIT
                 ? v3_add(ray->o, v3_make(num_mul_fit(ray->d.x, hit.t), num_mul_fit(ray->d.y, hit.t), num_mul_fit(ray->d.z, hit.t)))
                 : v3_add(ray->o, v3_scale(ray->d, hit.t));
    vec3 n = rt_hit_normal(rt, &hit, p);
    vec3 v = v3_neg(ray->d);
    rgb local;
    if (s->rt.unlit) {
        local = m->color;
    } else {
        num i = rt_compute_lighting(rt, p, n, v, m->specular, rt->oc[mo].spec_zero, hit.surf,
                                    prim ? &prim->shadow : NULL);
        local = colour_scale(s, m->color, i);
    }
    num r = m->reflective;
    num tr = m->transparency;
    if (depth <= 0 || (r <= 0 && tr <= 0)) return local;

    rgb out = local;
    if (r > 0) {
        struct rt_ray rr;
        rt_ray_init(&rr, p, reflect_ray(v, n), hit.surf, 0);
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
        rt_ray_init(&tr_ray, p, dir, hit.surf, 0);
        rgb seen = trace_ray(rt, &tr_ray, s->rt.epsilon, NUM_MAX, depth - 1, NULL);
        out = colour_add(s, colour_scale(s, out, num_sub(NUM_ONE, tr)), colour_scale(s, seen, tr));
    }
    return out;
}

/* CanvasToViewport for canvas point (x, y) (num, sub-pixel allowed), then
 * the camera rotation. */
static vec3 rotate_direction(const struct rt_state *rt, vec3 d)
{
    if (!rt->cam_rotated) return d;
    /* D'[i] = ((0 + D.x*M[i][0]) + D.y*M[i][1]) + D.z*M[i][2], the demo's order */
    vec3 r;
    const mat3 *m = &rt->cam_rot;
    r.x = num_add(num_add(num_add(NUM_ZERO, num_mul(d.x, m->m[0][0])), num_mul(d.y, m->m[0][1])), num_mul(d.z, m->m[0][2]));
    r.y = num_add(num_add(num_add(NUM_ZERO, num_mul(d.x, m->m[1][0])), num_mul(d.y, m->m[1][1])), num_mul(d.z, m->m[1][2]));
    r.z = num_add(num_add(num_add(NUM_ZERO, num_mul(d.x, m->m[2][0])), num_mul(d.y, m->m[2][1])), num_mul(d.z, m->m[2][2]));
    return r;
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

/* One primary ray along d (from the camera). */
static rgb trace_primary(struct rt_state *rt, vec3 d, struct rt_prim *prim)
{
    struct rt_ray ray;
    prim->item = -1;
    prim->shadow = 0;
    rt_ray_init(&ray, rt->cam_pos, d, -1, 1);
    rt->n.primary_rays++;
    return trace_ray(rt, &ray, rt->s->rt.t_min_primary, NUM_MAX, rt->depth, prim);
}

rgb rt_trace_canvas(struct rt_state *rt, num x, num y, struct rt_prim *prim)
{
    return trace_primary(rt, canvas_to_viewport(rt, x, y), prim);
}

rgb rt_trace_pixel(struct rt_state *rt, int col, int row, struct rt_prim *prim)
{
    return trace_primary(rt, pixel_to_viewport(rt, col, row), prim);
}
