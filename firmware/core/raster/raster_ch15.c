/* SPDX-License-Identifier: MIT */
/* raster_ch15.c — chapter 15 on the default path: shadow maps with
 * percentage-closer filtering, stencil shadow volumes (depth-fail), the
 * procedural environment of environment mapping. Normal maps are applied
 * per pixel in raster_pixel.c (ras_default_pixel). Everything here works in camera
 * space, on the per-frame transformed vertices of raster_frame.c. */
#include <string.h>
#include "raster_int.h"

#define SM_DEFAULT 128
#define PCF_DEFAULT 3

static int ch15_path(const struct scene *s)
{
    return !s->ras.book_exact && !s->ras.wireframe && s->ras.shading == SHADE_PHONG;
}

static int shadow_light_index(const struct scene *s)
{
    if (s->ras.shadow_light) {
        int k = s->ras.shadow_light - 1;
        return k < s->nlights && s->lights[k].type != LIGHT_AMBIENT ? k : -1;
    }
    for (uint16_t k = 0; k < s->nlights && k < 127; k++)
        if (s->lights[k].type != LIGHT_AMBIENT) return k;
    return -1;
}

static int sm_wanted(const struct scene *s) { return ch15_path(s) && s->ras.shadow_map && shadow_light_index(s) >= 0; }
static int sv_wanted(const struct scene *s)
{
    return ch15_path(s) && s->ras.shadow_volume && s->ras.depth_test && shadow_light_index(s) >= 0;
}

static uint16_t sm_side(const struct scene *s)
{
    uint16_t n = s->ras.shadow_map_size ? s->ras.shadow_map_size : SM_DEFAULT;
    return n < 16 ? 16 : (n > 1024 ? 1024 : n);
}

size_t ras_ch15_adj_size(const struct scene *s, uint32_t ntris)
{
    return sv_wanted(s) ? (size_t)ntris * 3 * sizeof(uint16_t) : 0;
}

size_t ras_ch15_smap_size(const struct scene *s)
{
    return sm_wanted(s) ? (size_t)sm_side(s) * sm_side(s) * sizeof(uint16_t) : 0;
}

size_t ras_ch15_stencil_size(const struct scene *s, uint16_t w, uint16_t strip_rows)
{
    return sv_wanted(s) ? (size_t)w * strip_rows : 0;
}

/* Neighbour of every triangle across each of its edges (v[k], v[k+1]): the
 * triangle holding the same edge reversed. Once, at render_init. */
static void build_adjacency(struct ras_ctx *rc)
{
    const struct scene *s = rc->s;
    uint32_t tb = 0;
    for (uint16_t i = 0; i < s->ninstances; i++) {
        const struct ras_model *m = &s->models[s->instances[i].model];
        uint16_t *adj = rc->c15.adj + (size_t)tb * 3;
        for (uint32_t k = 0; k < (uint32_t)m->ntris * 3; k++) adj[k] = RAS_NO_ADJ;
        for (uint16_t a = 0; a < m->ntris; a++)
            for (int e = 0; e < 3; e++) {
                if (adj[a * 3 + e] != RAS_NO_ADJ) continue;
                uint16_t p = m->tris[a].v[e], q = m->tris[a].v[(e + 1) % 3];
                for (uint16_t b = (uint16_t)(a + 1); b < m->ntris && adj[a * 3 + e] == RAS_NO_ADJ; b++)
                    for (int f = 0; f < 3; f++)
                        if (m->tris[b].v[f] == q && m->tris[b].v[(f + 1) % 3] == p && adj[b * 3 + f] == RAS_NO_ADJ) {
                            adj[a * 3 + e] = b;
                            adj[b * 3 + f] = a;
                            break;
                        }
            }
        tb += m->ntris;
    }
}

void ras_ch15_init(struct ras_ctx *rc)
{
    const struct scene *s = rc->s;
    rc->c15.sh_light = (int8_t)shadow_light_index(s);
    rc->c15.sm_on = (uint8_t)sm_wanted(s);
    rc->c15.sv_on = (uint8_t)sv_wanted(s);
    rc->c15.env_on = (uint8_t)(ch15_path(s) && s->ras.env_map);
    rc->c15.sm_size = sm_side(s);
    rc->c15.pcf = s->ras.pcf ? (s->ras.pcf > 3 ? 3 : s->ras.pcf) : PCF_DEFAULT;
    rc->c15.env_k = num_from_ratio(s->ras.env_reflect ? (s->ras.env_reflect > 100 ? 100 : s->ras.env_reflect) : 50, 100);
    if (rc->c15.sv_on) build_adjacency(rc);
}

/* ---- scene bounds and the light's frame ---------------------------------- */

static void scene_bounds(struct ras_ctx *rc)
{
    const struct scene *s = rc->s;
    vec3 c = v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    int n = 0;
    for (uint16_t i = 0; i < s->ninstances; i++) {
        const struct ras_model *m = &s->models[s->instances[i].model];
        if (!m->nverts) continue;
        vec4 b = { m->bound_center.x, m->bound_center.y, m->bound_center.z, NUM_ONE };
        b = m4_mul_v4(&rc->inst[i].m, b);
        c = v3_add(c, v3_make(b.x, b.y, b.z));
        n++;
    }
    if (n) c = v3_make(num_div_int(c.x, n), num_div_int(c.y, n), num_div_int(c.z, n));
    /* radius from the vertices themselves: exact for any instance transform */
    num r = NUM_ZERO;
    for (uint32_t k = 0; k < rc->nverts; k++) r = num_max(r, v3_len(v3_sub(rc->verts[k].c, c)));
    rc->c15.bound_c = c;
    rc->c15.bound_r = num_add(r, NUM_C(0.01));
}

/* An orthonormal frame with forward f (unit). */
static void frame_of(vec3 f, vec3 *r, vec3 *u)
{
    vec3 up = num_abs(f.y) < NUM_C(0.9) ? v3_make(NUM_ZERO, NUM_ONE, NUM_ZERO) : v3_make(NUM_ONE, NUM_ZERO, NUM_ZERO);
    *r = v3_normalize(v3_cross(up, f));
    *u = v3_cross(f, *r);
}

/* Map position (texels, +y down) and the light-space depth of p. */
static void sm_project(const struct ras_ctx *rc, vec3 p, num *mx, num *my, num *z)
{
    vec3 d = v3_sub(p, rc->c15.sm_o);
    num x = v3_dot(d, rc->c15.sm_r), y = v3_dot(d, rc->c15.sm_u);
    *z = v3_dot(d, rc->c15.sm_f);
    if (!rc->c15.sm_ortho) {
        num zz = num_max(*z, rc->c15.sm_near);
        x = num_div(x, zz);
        y = num_div(y, zz);
    }
    num half = num_from_int(rc->c15.sm_size / 2);
    *mx = num_add(half, num_mul(x, rc->c15.sm_scale));
    *my = num_sub(half, num_mul(y, rc->c15.sm_scale));
}

/* Closeness to the light, 32-bit, larger is nearer: affine in map space
 * (near/z for a perspective map, (R - z)/2R for an orthographic one). */
static uint32_t sm_closeness(const struct ras_ctx *rc, num z)
{
    if (rc->c15.sm_ortho) {
        num two_r = num_mul_int(rc->c15.bound_r, 2);
        num nz = num_clamp(num_sub(rc->c15.bound_r, z), NUM_C(0.001), num_sub(two_r, NUM_C(0.001)));
        return ras_depth32(nz, two_r);
    }
    return ras_depth32(rc->c15.sm_near, z);
}

/* Texel coordinate in 1/2^sub_bits units, clamped to a band around the map. */
static int32_t sm_sub(const struct ras_ctx *rc, num m)
{
    num lim = num_from_int(rc->c15.sm_size);
    m = num_clamp(m, num_neg(lim), num_mul_int(lim, 2));
    int sb = rc->def.sub_bits;
    return (int32_t)((uint32_t)num_floor_int(m) << sb) + num_floor_int(num_add(num_mul_int(num_frac(m), 1 << sb), NUM_HALF));
}

static void render_shadow_map(struct ras_ctx *rc)
{
    const struct scene *s = rc->s;
    size_t n = (size_t)rc->c15.sm_size * rc->c15.sm_size;
    memset(rc->c15.smap, 0, n * sizeof(uint16_t));
    /* the rasterizer draws into the map as if it were one strip */
    struct render_target mt;
    memset(&mt, 0, sizeof mt);
    mt.width = mt.height = rc->c15.sm_size;
    mt.y0 = 0;
    mt.y1 = rc->c15.sm_size;
    struct render_target *save_t = rc->cur.t;
    uint16_t save_w = rc->w;
    uint8_t *save_depth = rc->depth, save_bytes = rc->depth_bytes, save_func = rc->cur.depth_func;
    rc->cur.t = &mt;
    rc->w = rc->c15.sm_size;
    rc->depth = (uint8_t *)rc->c15.smap;
    rc->depth_bytes = 2;
    rc->cur.depth_func = RAS_DEPTH_LESS_WRITE;
    for (uint16_t i = 0; i < s->ninstances; i++) {
        const struct ras_model *m = &s->models[s->instances[i].model];
        const struct ras_inst *ri = &rc->inst[i];
        for (uint16_t k = 0; k < m->ntris; k++) {
            const struct ras_triangle *t = &m->tris[k];
            struct ras_sv sv[3];
            int skip = 0;
            for (int j = 0; j < 3 && !skip; j++) {
                if (t->v[j] >= m->nverts) { skip = 1; break; }
                num mx, my, z;
                sm_project(rc, rc->verts[ri->vbase + t->v[j]].c, &mx, &my, &z);
                if (!rc->c15.sm_ortho && z <= rc->c15.sm_near) skip = 1;
                sv[j].x = sm_sub(rc, mx);
                sv[j].y = sm_sub(rc, my);
                sv[j].iz = NUM_ONE;
                sv[j].depth = sm_closeness(rc, z);
            }
            if (skip) continue;
            int64_t area = (int64_t)(sv[1].x - sv[0].x) * (sv[2].y - sv[0].y) -
                           (int64_t)(sv[1].y - sv[0].y) * (sv[2].x - sv[0].x);
            /* both faces cast: clockwise order for the filler */
            if (area > 0) ras_fill_triangle(rc, &sv[0], &sv[1], &sv[2], 0, NULL, NULL);
            else if (area < 0) ras_fill_triangle(rc, &sv[0], &sv[2], &sv[1], 0, NULL, NULL);
        }
    }
    rc->cur.t = save_t;
    rc->w = save_w;
    rc->depth = save_depth;
    rc->depth_bytes = save_bytes;
    rc->cur.depth_func = save_func;
}

void ras_ch15_frame(struct ras_ctx *rc)
{
    if (!rc->c15.sm_on && !rc->c15.sv_on) return;
    scene_bounds(rc);
    if (!rc->c15.sm_on) return;
    const struct ras_light *l = &rc->lights[rc->c15.sh_light];
    num S = num_from_int(rc->c15.sm_size);
    if (l->type == LIGHT_DIRECTIONAL) {
        rc->c15.sm_ortho = 1;
        rc->c15.sm_f = v3_normalize(v3_neg(l->v));
        rc->c15.sm_o = rc->c15.bound_c;
        rc->c15.sm_scale = num_div(S, num_mul_int(rc->c15.bound_r, 2));
        rc->c15.sm_texel = num_recip(rc->c15.sm_scale);
    } else {
        rc->c15.sm_ortho = 0;
        vec3 to_c = v3_sub(rc->c15.bound_c, l->v);
        num dist = v3_len(to_c);
        rc->c15.sm_f = dist > 0 ? v3_normalize(to_c) : v3_make(NUM_ZERO, NUM_ZERO, NUM_ONE);
        rc->c15.sm_o = l->v;
        frame_of(rc->c15.sm_f, &rc->c15.sm_r, &rc->c15.sm_u);
        /* the frustum fitted to the vertices in front of the light: the
         * nearest one sets the near plane, the widest angle the field;
         * triangles reaching behind the near plane cast nothing */
        num eps = num_mul(rc->c15.bound_r, NUM_C(0.02)), zmin = NUM_MAX;
        for (uint32_t k = 0; k < rc->nverts; k++) {
            num z = v3_dot(v3_sub(rc->verts[k].c, l->v), rc->c15.sm_f);
            if (z > eps) zmin = num_min(zmin, z);
        }
        num near = zmin == NUM_MAX ? num_max(eps, NUM_C(0.01)) : num_max(num_mul(zmin, NUM_C(0.9)), num_max(eps, NUM_C(0.01)));
        num tan_h = NUM_C(0.01);
        for (uint32_t k = 0; k < rc->nverts; k++) {
            vec3 d = v3_sub(rc->verts[k].c, l->v);
            num z = v3_dot(d, rc->c15.sm_f);
            if (z <= near) continue;
            num ext = num_max(num_abs(v3_dot(d, rc->c15.sm_r)), num_abs(v3_dot(d, rc->c15.sm_u)));
            if (ext > num_mul(z, NUM_C(2.0))) { tan_h = NUM_C(2.0); continue; }
            tan_h = num_max(tan_h, num_div(ext, z));
        }
        /* at most +-63 degrees: wider fields waste the map's texels;
         * what lies outside is never shadowed */
        tan_h = num_mul(tan_h, NUM_C(1.01));
        rc->c15.sm_near = near;
        rc->c15.sm_scale = num_div(num_mul(S, NUM_HALF), tan_h);
        rc->c15.sm_texel = num_recip(rc->c15.sm_scale);
    }
    if (rc->c15.sm_ortho) frame_of(rc->c15.sm_f, &rc->c15.sm_r, &rc->c15.sm_u);
    render_shadow_map(rc);
}

num ras_shadow_map_vis(const struct ras_ctx *rc, vec3 p, vec3 n)
{
    if (!rc->c15.sm_on) return NUM_ONE;
    num mx, my, z;
    sm_project(rc, p, &mx, &my, &z);
    if (!rc->c15.sm_ortho && z <= rc->c15.sm_near) return NUM_ONE;
    /* against self-shadowing: the point moved 1.5 texels along its normal
     * (steep faces), then one texel of depth bias */
    num texel = rc->c15.sm_ortho ? rc->c15.sm_texel : num_mul(rc->c15.sm_texel, z);
    sm_project(rc, v3_add(p, v3_scale(n, num_mul(texel, NUM_C(1.5)))), &mx, &my, &z);
    num zb = num_sub(z, texel);
    if (!rc->c15.sm_ortho) zb = num_max(zb, num_add(rc->c15.sm_near, NUM_C(0.001)));
    uint32_t c = sm_closeness(rc, zb) >> 16;
    int k = rc->c15.pcf;
    int32_t x0 = num_floor_int(mx), y0 = num_floor_int(my);
    if (k == 2) { x0 = num_floor_int(num_sub(mx, NUM_HALF)); y0 = num_floor_int(num_sub(my, NUM_HALF)); }
    else if (k == 3) { x0--; y0--; }
    int lit = 0;
    for (int dy = 0; dy < k; dy++)
        for (int dx = 0; dx < k; dx++) {
            int32_t x = x0 + dx, y = y0 + dy;
            if (x < 0 || y < 0 || x >= rc->c15.sm_size || y >= rc->c15.sm_size) { lit++; continue; }
            if (c >= rc->c15.smap[(size_t)y * rc->c15.sm_size + (size_t)x]) lit++;
        }
    return num_from_ratio(lit, k * k);
}

/* ---- shadow volumes ------------------------------------------------------- */

struct sv_ud { int8_t delta; };

static void stencil_pixel(struct ras_ctx *rc, int col, int row, const num *a, num z, void *ud)
{
    (void)a;
    (void)z;
    const struct sv_ud *u = ud;
    uint8_t *st = &rc->c15.stencil[(size_t)(row - rc->cur.t->y0) * rc->w + (size_t)col];
    *st = (uint8_t)(*st + u->delta);
}

/* One face of a volume: front faces (seen from the camera) decrement,
 * back faces increment where they lie behind the visible surface. The
 * face normal of extruded corners reaches (|bound_r| + extrusion)^2 and
 * only its side of the camera matters: it stays wide (never narrowed to
 * num), as does the projection's x * unproj before the division by z. */
static void volume_triangle(struct ras_ctx *rc, vec3 a, vec3 b, vec3 c)
{
    struct ras_wnormal nf = ras_face_normal_wide(a, b, c);
    if (nf.x == 0 && nf.y == 0 && nf.z == 0) return;
    int front = ras_facing_wide(a, nf) > 0;
    struct ras_cv in[3], poly[RAS_CLIP_MAX];
    in[0].p = a; in[1].p = b; in[2].p = c;
    int n = ras_clip_triangle(rc, in, 0, poly);
    if (n < 3) return;
    struct ras_sv sv[RAS_CLIP_MAX];
    for (int k = 0; k < n; k++) {
        const struct ras_cv *q = &poly[front ? k : n - 1 - k];
        vec3 p = q->p;
        num X = ras_mul_div(p.x, rc->unproj, p.z), Y = ras_mul_div(p.y, rc->unproj, p.z);
        num fx = num_add(num_from_int(rc->w / 2), X), fy = num_sub(num_from_int(rc->h / 2), Y);
        int sb = rc->def.sub_bits;
        sv[k].x = (int32_t)((uint32_t)num_floor_int(fx) << sb) + num_floor_int(num_add(num_mul_int(num_frac(fx), 1 << sb), NUM_HALF));
        sv[k].y = (int32_t)((uint32_t)num_floor_int(fy) << sb) + num_floor_int(num_add(num_mul_int(num_frac(fy), 1 << sb), NUM_HALF));
        sv[k].iz = num_recip(p.z);
        sv[k].depth = ras_depth32(rc->def.near_z, p.z);
    }
    struct sv_ud u = { (int8_t)(front ? -1 : 1) };
    for (int k = 1; k + 1 < n; k++) ras_fill_triangle(rc, &sv[0], &sv[k], &sv[k + 1], -1, stencil_pixel, &u);
}

void ras_shadow_volumes(struct ras_ctx *rc)
{
    const struct scene *s = rc->s;
    const struct ras_light *l = &rc->lights[rc->c15.sh_light];
    int point = l->type == LIGHT_POINT;
    vec3 ldir = point ? l->v : v3_normalize(l->v);
    /* extrusion length: beyond every receiver (all lie in the bounding sphere) */
    num ext = point ? num_add(v3_len(v3_sub(rc->c15.bound_c, l->v)), num_mul_int(rc->c15.bound_r, 2))
                    : num_mul_int(rc->c15.bound_r, 3);
    memset(rc->c15.stencil, 0, (size_t)rc->w * (size_t)(rc->cur.t->y1 - rc->cur.t->y0));
    uint8_t save_func = rc->cur.depth_func;
    rc->cur.depth_func = RAS_DEPTH_BEHIND;
    uint32_t tb = 0;
    for (uint16_t i = 0; i < s->ninstances; i++) {
        const struct ras_model *m = &s->models[s->instances[i].model];
        const struct ras_inst *ri = &rc->inst[i];
        const uint16_t *adj = rc->c15.adj + (size_t)tb * 3;
        tb += m->ntris;
        for (uint16_t k = 0; k < m->ntris; k++) {
            const struct ras_triangle *t = &m->tris[k];
            if (t->v[0] >= m->nverts || t->v[1] >= m->nverts || t->v[2] >= m->nverts) continue;
            vec3 P[3], E[3];
            for (int j = 0; j < 3; j++) P[j] = rc->verts[ri->vbase + t->v[j]].c;
            /* face normals wide: only their side of the light matters */
            struct ras_wnormal nf = ras_face_normal_wide(P[0], P[1], P[2]);
            vec3 tl = point ? v3_sub(ldir, P[0]) : ldir;
            if (ras_facing_wide(v3_neg(tl), nf) <= 0) continue; /* only faces toward the light bound a volume */
            for (int j = 0; j < 3; j++) {
                vec3 away = point ? v3_normalize(v3_sub(P[j], ldir)) : v3_neg(ldir);
                E[j] = v3_add(P[j], v3_scale(away, ext));
            }
            volume_triangle(rc, P[0], P[1], P[2]);   /* front cap */
            volume_triangle(rc, E[0], E[2], E[1]);   /* back cap, reversed */
            for (int e = 0; e < 3; e++) {
                uint16_t nb = adj[(size_t)k * 3 + e];
                if (nb != RAS_NO_ADJ) {
                    const struct ras_triangle *o = &m->tris[nb];
                    vec3 Q[3];
                    for (int j = 0; j < 3; j++) Q[j] = rc->verts[ri->vbase + o->v[j]].c;
                    struct ras_wnormal no = ras_face_normal_wide(Q[0], Q[1], Q[2]);
                    if (ras_facing_wide(v3_neg(point ? v3_sub(ldir, Q[0]) : ldir), no) > 0) continue; /* not a silhouette */
                }
                int a = e, b = (e + 1) % 3;
                volume_triangle(rc, P[b], P[a], E[a]);
                volume_triangle(rc, P[b], E[a], E[b]);
            }
        }
    }
    rc->cur.depth_func = save_func;
}

/* ---- environment ---------------------------------------------------------- */

rgb ras_env_colour(const struct ras_ctx *rc, vec3 r)
{
    /* camera -> world: the transpose of the world -> camera rotation */
    const mat4 *m = &rc->cam_rot_t;
    vec3 w = v3_normalize(v3_make(num_add(num_add(num_mul(m->m[0][0], r.x), num_mul(m->m[1][0], r.y)), num_mul(m->m[2][0], r.z)),
                                  num_add(num_add(num_mul(m->m[0][1], r.x), num_mul(m->m[1][1], r.y)), num_mul(m->m[2][1], r.z)),
                             num_add(num_add(num_mul(m->m[0][2], r.x), num_mul(m->m[1][2], r.y)), num_mul(m->m[2][2], r.z))));
    if (w.y >= 0) {
        /* sky: pale at the horizon, deep blue at the zenith */
        num t = w.y;
        return rgb_make(num_sub(NUM_C(200.0), num_mul(NUM_C(170.0), t)), num_sub(NUM_C(220.0), num_mul(NUM_C(130.0), t)),
                        num_sub(NUM_C(255.0), num_mul(NUM_C(45.0), t)));
    }
    /* ground: a brown checkerboard on the plane y = -1, hazy near the horizon */
    num down = num_neg(w.y);
    if (down < NUM_C(0.05)) return rgb_make(NUM_C(170.0), NUM_C(160.0), NUM_C(150.0));
    num gx = num_div(w.x, down), gz = num_div(w.z, down);
    int odd = (num_floor_int(gx) + num_floor_int(gz)) & 1;
    return odd ? rgb_make(NUM_C(120.0), NUM_C(80.0), NUM_C(40.0)) : rgb_make(NUM_C(190.0), NUM_C(150.0), NUM_C(90.0));
}
