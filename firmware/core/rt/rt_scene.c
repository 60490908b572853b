/* SPDX-License-Identifier: MIT */
/* rt_scene.c — what the ray tracer derives from the scene before it traces:
 * the lights' shadow-ray forms, the per-frame object constants (camera-relative
 * sphere terms, triangle edges and normals) and the bounding-sphere hierarchy
 * over the items (chapter 5's acceleration structure).
 */
#include "rt_int.h"

static void item_bound(const struct rt_state *rt, int16_t item, vec3 *c, num *r)
{
    const struct scene *s = rt->s;
    if (item >= (int16_t)s->nobjects) {
        const struct rt_csg *g = &s->csg[CSG_ITEM(rt, item)];
        const struct rt_object *a = &s->objects[g->a], *b = &s->objects[g->b];
        if (g->op != CSG_UNION) { *c = a->center; *r = a->radius; return; }
        /* enclosing sphere of both operands (centred on a, simple and safe) */
        *c = a->center;
        *r = num_max(a->radius, num_add(v3_len(v3_sub(b->center, a->center)), b->radius));
        return;
    }
    const struct rt_object *o = &s->objects[item];
    if (o->shape == RT_SPHERE) { *c = o->center; *r = o->radius; return; }
    /* triangle: centroid, farthest corner */
    vec3 m = v3_scale(v3_add(v3_add(o->p[0], o->p[1]), o->p[2]), NUM_C(1.0 / 3.0));
    num rr = NUM_ZERO;
    for (int k = 0; k < 3; k++) rr = num_max(rr, v3_len(v3_sub(o->p[k], m)));
    *c = m;
    *r = rr;
}

void rt_light_constants(struct rt_state *rt)
{
    const struct scene *s = rt->s;
    /* rt_compute_lighting starts from the leading ambient lights' sum (the
     * same num_add steps from zero) */
    rt->amb_k = 0;
    rt->amb_i = NUM_ZERO;
    while (rt->amb_k < s->nlights && s->lights[rt->amb_k].type == LIGHT_AMBIENT)
        rt->amb_i = num_add(rt->amb_i, s->lights[rt->amb_k++].intensity);
    for (uint16_t k = 0; k < s->nlights; k++)
        if (s->lights[k].type == LIGHT_DIRECTIONAL) {
            rt->light_ray[k] = rt_make_ray(v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO), s->lights[k].v, -1, 0);
            rt_ray_exact(&rt->light_ray[k]);
            rt->light_len[k] = v3_len(s->lights[k].v);
            rt->light_div[k] = num_divisor_make(rt->light_len[k]);
            rt->light_self[k] = rt_self_dir_make(&s->lights[k].v, s->rt.epsilon);
        }
}

void rt_frame_constants(struct rt_state *rt)
{
    const struct scene *s = rt->s;
    for (int k = 0; k < rt->iv_rows; k++) rt->iv_tag[k] = -1;   /* the camera may have moved */
    for (uint16_t i = 0; i < s->nobjects; i++) {
        const struct rt_object *o = &s->objects[i];
        struct rt_obj_cache *oc = &rt->oc[i];
        oc->ivs.ok = 0;
        oc->r2 = num_mul_wide(o->radius, o->radius);
        oc->cs = rt_csphere_make(o->center, o->radius);
        struct rt_cpt cam = rt_cpt_make(rt->cam_pos);
        oc->ccam = rt_ccam_make(&oc->cs, &cam);
        oc->qs = rt_qsphere_make(o->radius);
        oc->rrcp = num_recip_make(o->radius);
        oc->rpow2 = -1;
#if NUM_MODE == NUM_MODE_FIXED
        for (int k = 0; k < 31 - NUM_FRAC; k++)
            if (o->radius == (num)(NUM_ONE_RAW << k)) oc->rpow2 = (int8_t)k;
#endif
        if (o->shape == RT_SPHERE) {
            oc->co_cam = v3_sub(rt->cam_pos, o->center);
            if (rt->book)
                oc->k3_cam = num_sub(v3_dot(oc->co_cam, oc->co_cam), num_mul(o->radius, o->radius));
            else
                oc->c_cam = wnum_sub(v3_dot_wide(oc->co_cam, oc->co_cam), oc->r2);
            /* the near root's numerator along exact pixel directions (rt_exact_comp: multiplier h) */
            oc->cm_cam = rt->book ? 0 : rt_quad_near_num(oc->c_cam, rt->h);
            oc->px_row = -1;   /* the camera may have moved: no row parts */
            /* and rt_near_beyond's range of n = c H and of a for every exact
             * primary direction (rt_near_dir_ok) */
            oc->near_ok = (uint8_t)(!rt->book && rt_near_c_ok(oc->c_cam, v3_dot_wide(oc->co_cam, oc->co_cam)) &&
                                    rt_near_n_ok(oc->cm_cam) && rt_near_dir_ok(rt->d, rt->h));
#if NUM_MODE == NUM_MODE_FIXED
            oc->ivs = rt_ivsphere_make(oc->co_cam, oc->qs.r2x, rt->vh);
#endif
        } else if (o->shape == RT_TRIANGLE) {
            oc->e1 = v3_sub(o->p[1], o->p[0]);
            oc->e2 = v3_sub(o->p[2], o->p[0]);
            oc->n = v3_normalize(v3_cross(oc->e1, oc->e2));
        }
    }
}

/* Top-down build: split the item range at the median of the longest axis
 * of the centres. Recursion depth is log2(items) + 1. */
static int16_t build_node(struct rt_state *rt, int16_t first, int16_t count)
{
    int16_t id = (int16_t)rt->nbvh++;
    struct rt_bvh_node *nd = &rt->bvh[id];
    int16_t *it = rt->bvh_items + first;
    /* centre: mean of item centres; radius: farthest item surface */
    vec3 lo = v3_make(NUM_MAX, NUM_MAX, NUM_MAX), hi = v3_make(NUM_MIN, NUM_MIN, NUM_MIN);
    for (int16_t k = 0; k < count; k++) {
        vec3 c;
        num r;
        item_bound(rt, it[k], &c, &r);
        lo = v3_make(num_min(lo.x, c.x), num_min(lo.y, c.y), num_min(lo.z, c.z));
        hi = v3_make(num_max(hi.x, c.x), num_max(hi.y, c.y), num_max(hi.z, c.z));
    }
    vec3 mid = v3_scale(v3_add(lo, hi), NUM_HALF);
    num rad = NUM_ZERO;
    for (int16_t k = 0; k < count; k++) {
        vec3 c;
        num r;
        item_bound(rt, it[k], &c, &r);
        rad = num_max(rad, num_add(v3_len(v3_sub(c, mid)), r));
    }
    /* a little margin so rounding never culls a real hit */
    nd->c = mid;
    nd->r = num_add(num_add(rad, num_mul(rad, NUM_C(1.0 / 256))), NUM_C(0.01));
    nd->first = first;
    nd->count = count;
    nd->left = nd->right = -1;
    if (count <= 2) return id;
    vec3 ext = v3_sub(hi, lo);
    int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    /* insertion sort by centre along the axis */
    for (int16_t k = 1; k < count; k++) {
        int16_t v = it[k];
        vec3 cv;
        num rv;
        item_bound(rt, v, &cv, &rv);
        num kv = axis == 0 ? cv.x : (axis == 1 ? cv.y : cv.z);
        int16_t j = k;
        while (j > 0) {
            vec3 cj;
            num rj;
            item_bound(rt, it[j - 1], &cj, &rj);
            num kj = axis == 0 ? cj.x : (axis == 1 ? cj.y : cj.z);
            if (kj <= kv) break;
            it[j] = it[j - 1];
            j--;
        }
        it[j] = v;
    }
    int16_t half = (int16_t)(count / 2);
    int16_t l = build_node(rt, first, half);
    int16_t r = build_node(rt, (int16_t)(first + half), (int16_t)(count - half));
    rt->bvh[id].left = l;
    rt->bvh[id].right = r;
    return id;
}

void rt_build_bvh(struct rt_state *rt)
{
    const struct scene *s = rt->s;
    uint16_t nb = 0;
    rt->nunbounded = 0;
    rt->nbvh = 0;
    for (uint16_t i = 0; i < rt->nitems; i++) {
        int16_t item = rt->items[i];
        if (item < (int16_t)s->nobjects && s->objects[item].shape == RT_PLANE)
            rt->unbounded[rt->nunbounded++] = item;
        else
            rt->bvh_items[nb++] = item;
    }
    if (nb > 0) build_node(rt, 0, (int16_t)nb);
}
