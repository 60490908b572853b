/* SPDX-License-Identifier: MIT */
/* raster_shading.c — chapter 13: ComputeIllumination (camera space). */
#include "raster_int.h"

/* Book path: N as given (never normalised), the view vector from the
 * world-space camera position (the demos' quirk, wrong when the camera is
 * not at the origin). Default path: N normalised, V = -P. Lights are in
 * camera space (ras_ctx.lights, set per frame). */
num ras_compute_illumination(const struct ras_ctx *rc, vec3 p, vec3 n, num specular)
{
    return ras_compute_illumination_vis(rc, p, n, specular, -1, NUM_ONE);
}

/* Model space (light_space = model): a directional light's direction L
 * toward it, turned back into the model's space by the transpose of the
 * rotation nmat (normals to camera space) and normalised, times its
 * intensity; then a vertex's diffuse term is the dot product with its unit
 * model normal, max(N . L, 0) times the intensity, as in camera space up to
 * the roundings. Only ambient and directional lights, diffuse without
 * specular; otherwise (on 0) the vertices are lit in camera space. */
void ras_model_light_frame(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                           struct ras_mlight *ml)
{
    const struct scene *s = rc->s;
    const mat4 *m = &ri->nmat;
    ml->on = 0;
    ml->n = 0;
    ml->amb = NUM_ZERO;
    if (!ri->vlit || !s->ras.diffuse || (s->ras.specular && in->specular >= 0)) return;
    for (uint16_t k = 0; k < s->nlights; k++) {
        const struct ras_light *l = &rc->lights[k];
        if (l->type == LIGHT_AMBIENT) {
            ml->amb = num_add(ml->amb, l->intensity);
            continue;
        }
        if (l->type != LIGHT_DIRECTIONAL || ml->n == RAS_ML_LIGHTS) return;
        const vec3 v = l->v;
        vec3 d = v3_make(num_add(num_add(num_mul(m->m[0][0], v.x), num_mul(m->m[1][0], v.y)), num_mul(m->m[2][0], v.z)),
                         num_add(num_add(num_mul(m->m[0][1], v.x), num_mul(m->m[1][1], v.y)), num_mul(m->m[2][1], v.z)),
                         num_add(num_add(num_mul(m->m[0][2], v.x), num_mul(m->m[1][2], v.y)), num_mul(m->m[2][2], v.z)));
        ml->w[ml->n++] = v3_scale(v3_normalize(d), l->intensity);
    }
    ml->on = 1;
}

num ras_model_light(const struct ras_mlight *ml, vec3 n)
{
    num i = ml->amb;
    for (uint8_t k = 0; k < ml->n; k++) {
        const num c = v3_dot(n, ml->w[k]);
        if (c > 0) i = num_add(i, c);
    }
    return i;
}

num ras_compute_illumination_vis(const struct ras_ctx *rc, vec3 p, vec3 n, num specular, int shadow_k, num vis)
{
    const struct scene *s = rc->s;
    num i = NUM_ZERO;
    if (!rc->book) n = v3_normalize_unit(n);   /* (v3_normalize's bits; fast near unit length) */
    vec3 view = rc->book ? v3_sub(rc->cam_pos, p) : v3_neg(p);
    num len_n = rc->book ? v3_len(n) : v3_len_unit(n);
    for (uint16_t k = 0; k < s->nlights; k++) {
        const struct ras_light *l = &rc->lights[k];
        if (l->type == LIGHT_AMBIENT) { i = num_add(i, l->intensity); continue; }
        num li = l->intensity;
        if ((int)k == shadow_k) {
            if (vis <= 0) continue;
            li = num_mul(li, vis);
        }
        vec3 L = l->type == LIGHT_DIRECTIONAL ? l->v : v3_add(v3_scale(p, num_neg(NUM_ONE)), l->v);
        /* the cosines' numerators and denominators are products of two
         * distances (|L| |V| reaches the square of the scene's extent):
         * wide, in the same operation order (the same bits as the narrow
         * forms wherever those fit) */
        if (s->ras.diffuse) {
            const wnum dot = v3_dot_wide(L, n);
            num cos_a;
            if (l->type == LIGHT_DIRECTIONAL && len_n == NUM_ONE && wnum_from_num(wnum_to_num(dot)) == dot) {
                /* |L| |N| is |L|, and a numerator in num's range divides
                 * as num_div: by the frame's divisor (the same bits) */
                cos_a = num_div_by(wnum_to_num(dot), &l->div);
            } else {
                const num len_l = l->type == LIGHT_DIRECTIONAL ? l->len : v3_len(L); /* (made once a frame) */
                cos_a = wnum_div(dot, wnum_mul(wnum_from_num(len_l), wnum_from_num(len_n)));
            }
            if (cos_a > 0) i = num_add(i, num_mul(cos_a, li));
        }
        if (s->ras.specular && specular >= 0) {
            num nl2 = num_mul(NUM_C(2.0), v3_dot(n, L));
            vec3 r = v3_sub(v3_scale(n, nl2), L);
            num cos_b = wnum_div(v3_dot_wide(r, view), wnum_mul(wnum_from_num(v3_len(r)), wnum_from_num(v3_len(view))));
            if (cos_b > 0) i = num_add(i, num_mul(num_powi(cos_b, (uint32_t)num_to_int(specular)), li));
        }
    }
    return i;
}
