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

num ras_compute_illumination_vis(const struct ras_ctx *rc, vec3 p, vec3 n, num specular, int shadow_k, num vis)
{
    const struct scene *s = rc->s;
    num i = NUM_ZERO;
    if (!rc->book) n = v3_normalize(n);
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
