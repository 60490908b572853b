/* SPDX-License-Identifier: MIT */
/* raster_pixel.c — the default path's exact pixel (the per-pixel path of
 * ras_fill_triangle): texture sample, flat / Gouraud / Phong lighting
 * through ras_compute_illumination, and chapter 15's normal maps, shadows
 * and environment. */
#include "raster_int.h"

/* Chapter 15 at one pixel (Phong): normal map, shadows, environment. */
static rgb ch15_pixel(struct ras_ctx *rc, const struct ras_def_tri *dt, int col, int row, vec3 p, vec3 n, const num *a, rgb c)
{
    n = v3_normalize(n);
    if (dt->nmap >= 0) {
        /* tangent-space normal: channel/127.5 - 1, red along +u, green toward the image's top */
        rgb t = ras_sample(rc, dt->nmap, a[dt->ai_uv], a[dt->ai_uv + 1], NUM_ZERO);
        num tx = num_sub(num_div_int(num_mul_int(t.r, 2), 255), NUM_ONE);
        num ty = num_sub(num_div_int(num_mul_int(t.g, 2), 255), NUM_ONE);
        num tz = num_sub(num_div_int(num_mul_int(t.b, 2), 255), NUM_ONE);
        n = v3_normalize(v3_add(v3_add(v3_scale(dt->tan_u, tx), v3_scale(dt->tan_v, ty)), v3_scale(n, tz)));
    }
    num vis = NUM_ONE;
    if (rc->c15.sm_on) vis = ras_shadow_map_vis(rc, p, n);
    if (rc->c15.sv_on && rc->c15.stencil[(size_t)(row - rc->cur.t->y0) * rc->w + (size_t)col]) vis = NUM_ZERO;
    num i = ras_compute_illumination_vis(rc, p, n, dt->spec, rc->c15.sh_light, vis);
    c = rgb_scale(c, i);
    if (rc->c15.env_on) {
        /* mirror direction of the view ray about n */
        vec3 d = v3_normalize(p);
        vec3 r = v3_sub(d, v3_scale(n, num_mul_int(v3_dot(d, n), 2)));
        rgb e = ras_env_colour(rc, r);
        num k = rc->c15.env_k, k1 = num_sub(NUM_ONE, k);
        c = rgb_make(num_add(num_mul(c.r, k1), num_mul(e.r, k)), num_add(num_mul(c.g, k1), num_mul(e.g, k)),
                     num_add(num_mul(c.b, k1), num_mul(e.b, k)));
    }
    return c;
}

void ras_default_pixel(struct ras_ctx *rc, int col, int row, const num *a, num z, void *ud)
{
    const struct ras_def_tri *dt = ud;
    rgb c = dt->color;
    if (dt->tex >= 0) {
        num lod = NUM_ZERO;
        if (rc->s->textures[dt->tex].filter == TEX_TRILINEAR) {
            num zr = num_mul(z, dt->iz_eff);
            lod = num_mul(ras_log2(num_mul(dt->lod_base, num_mul(zr, zr))), NUM_HALF);
        }
        c = ras_sample(rc, dt->tex, a[dt->ai_uv], a[dt->ai_uv + 1], lod);
    }
    num i = NUM_ONE;
    if (dt->shading == SHADE_FLAT) i = dt->flat_i;
    else if (dt->shading == SHADE_GOURAUD) i = a[dt->ai_i];
    else if (dt->shading == SHADE_PHONG) {
        /* the pixel centre, unprojected at its depth */
        num cx = num_add(num_from_int(col - rc->w / 2), NUM_HALF);
        num cy = num_sub(num_from_int(rc->h / 2 - row), NUM_HALF);
        vec3 p = v3_make(ras_mul_div(cx, z, rc->unproj), ras_mul_div(cy, z, rc->unproj), z);
        vec3 n = v3_make(a[dt->ai_n], a[dt->ai_n + 1], a[dt->ai_n + 2]);
        if (FW_FEATURE_RAS_CH15 && (dt->nmap >= 0 || rc->c15.sm_on || rc->c15.sv_on || rc->c15.env_on)) {
            ras_put(rc, col, row, ch15_pixel(rc, dt, col, row, p, n, a, c));
            return;
        }
        i = ras_compute_illumination(rc, p, n, dt->spec);
    }
    if (dt->shading != SHADE_NONE) c = rgb_scale(c, i);
    ras_put(rc, col, row, c);
}
