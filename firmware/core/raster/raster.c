/* SPDX-License-Identifier: MIT */
/* raster.c — the rasterizer's frame and strip loop: work memory, per-frame
 * transforms and binning (render_instance), and render_triangle for the
 * book path and the default path. */
#include <string.h>
#include "raster_int.h"

#define ALIGN 8
static size_t al(size_t n) { return (n + (ALIGN - 1)) & ~(size_t)(ALIGN - 1); }

struct layout {
    size_t ctx, inst, verts, tri_rows, prim_rows, line_rows, lights, mips, mipmem, tex565, texmem, pv, tri_flags,
        tri_shade, keep, spec, depth, adj, smap, stencil, total;
    uint32_t nverts, ntris;
};

/* Bytes of depth a pixel; none unless triangles are depth-tested (2D
 * primitives and 3D lines never are, so scenes of those need no buffer). */
static int depth_bytes(const struct scene *s)
{
    if (!s->ras.depth_test || s->ninstances == 0) return 0;
    if (s->ras.book_exact) return (int)sizeof(num);
    return s->ras.depth_bits == 16 ? 2 : 4;
}

/* The default path's triangles (not the book's, not wireframes): they keep
 * per-frame caches (projected vertices, triangle flags, lighting of
 * Gouraud and flat triangles). */
static int frame_cache(const struct scene *s)
{
    return !s->ras.book_exact && !s->ras.wireframe;
}

/* The fast path: the default path's triangles unless perspective_step = 1. */
static int fast_path(const struct scene *s)
{
    return frame_cache(s) && s->ras.persp_step != 1;
}

/* A chapter-15 feature that lights per pixel (always exactly). */
static int ch15_lit(const struct ras_options *o)
{
    return o->shadow_map || o->shadow_volume || o->env_map;
}

static int log2_exact(uint32_t v)
{
    for (int k = 0; k < 16; k++)
        if (v == (1u << k)) return k;
    return -1;
}

/* Bytes of the RGB565 copy of texture t the fast path samples: nearest
 * filtering, power-of-two sides, at most 2^15 texels (a byte offset of 16
 * bits); 0 when it does not qualify. */
static size_t tex565_size(const struct scene *s, const struct ras_texture *t)
{
    if (!fast_path(s) || t->filter != TEX_NEAREST || !t->rgb) return 0;
    if (log2_exact(t->w) < 0 || log2_exact(t->h) < 0 || log2_exact(t->w) + log2_exact(t->h) > 15) return 0;
    return (size_t)t->w * t->h * 2;
}


/* The default path's shading: Phong lit at the corners (lighting = vertex,
 * no chapter-15 feature) is Gouraud. */
static int eff_shading(const struct scene *s)
{
    const struct ras_options *o = &s->ras;
    if (o->shading == SHADE_PHONG && o->lighting == RAS_LIGHT_VERTEX && !o->book_exact && !ch15_lit(o))
        return SHADE_GOURAUD;
    return o->shading;
}

/* Fast Phong: the fast path, Phong shading, lighting = fast, no chapter-15 feature. */
static int phong_fast(const struct scene *s)
{
    const struct ras_options *o = &s->ras;
    return fast_path(s) && eff_shading(s) == SHADE_PHONG && o->lighting == RAS_LIGHT_FAST && !ch15_lit(o);
}

/* Distinct specular exponents of fast Phong's instances, one table each
 * (at most RAS_SPEC_MAX; more take the exact path). idx (if not NULL)
 * receives each instance's table: -1 no highlight, -2 none left. */
#define RAS_SPEC_MAX 16
static uint16_t spec_exponents(const struct scene *s, int16_t *idx, uint32_t exps[RAS_SPEC_MAX])
{
    uint32_t seen[RAS_SPEC_MAX];
    uint16_t n = 0;
    int fastp = phong_fast(s);
    for (uint16_t i = 0; i < s->ninstances; i++) {
        int16_t t = -1;
        if (fastp && s->instances[i].specular >= 0) {
            uint32_t e = (uint32_t)num_to_int(s->instances[i].specular);
            for (uint16_t k = 0; k < n && t < 0; k++)
                if (seen[k] == e) t = (int16_t)k;
            if (t < 0 && n < RAS_SPEC_MAX) {
                seen[n] = e;
                if (exps) exps[n] = e;
                t = (int16_t)n++;
            } else if (t < 0) {
                t = -2;
            }
        }
        if (idx) idx[i] = t;
    }
    return n;
}

static int shade_cache(const struct scene *s)
{
    return frame_cache(s) && (eff_shading(s) == SHADE_GOURAUD || eff_shading(s) == SHADE_FLAT);
}

/* Triangle set-ups the fast path keeps from one strip to the next: one
 * slot a triangle up to RAS_KEEP_MAX (triangle i in slot i mod slots). */
#define RAS_KEEP_MAX 32
static uint16_t keep_slots(const struct scene *s, uint32_t ntris)
{
    if (!fast_path(s)) return 0;
    return (uint16_t)(ntris < RAS_KEEP_MAX ? ntris : RAS_KEEP_MAX);
}

static int make_layout(const struct scene *s, uint16_t w, uint16_t strip_rows, struct layout *L)
{
    memset(L, 0, sizeof *L);
    for (uint16_t i = 0; i < s->ninstances; i++) {
        if (s->instances[i].model >= s->nmodels) return -1;
        const struct ras_model *m = &s->models[s->instances[i].model];
        L->nverts += m->nverts;
        L->ntris += m->ntris;
    }
    size_t off = 0;
    L->ctx = off; off += al(sizeof(struct ras_ctx));
    L->inst = off; off += al(sizeof(struct ras_inst) * s->ninstances);
    L->verts = off; off += al(sizeof(struct ras_vert) * L->nverts);
    L->tri_rows = off; off += al(sizeof(struct ras_range) * L->ntris);
    L->prim_rows = off; off += al(sizeof(struct ras_range) * s->nprims);
    L->line_rows = off; off += al(sizeof(struct ras_range) * s->nlines);
    L->lights = off; off += al(sizeof(struct ras_light) * s->nlights);
    L->mips = off; off += al(sizeof(struct ras_mips) * s->ntextures);
    L->mipmem = off;
    if (!s->ras.book_exact)
        for (uint16_t i = 0; i < s->ntextures; i++) off += al(ras_mips_size(&s->textures[i]));
    L->tex565 = off; off += al(sizeof(struct ras_tex565) * s->ntextures);
    L->texmem = off;
    for (uint16_t i = 0; i < s->ntextures; i++) off += al(tex565_size(s, &s->textures[i]));
    L->pv = off; off += al(frame_cache(s) ? sizeof(struct ras_pv) * L->nverts : 0);
    L->tri_flags = off; off += al(frame_cache(s) ? L->ntris : 0);
    L->tri_shade = off; off += al(shade_cache(s) ? sizeof(num) * 3 * L->ntris : 0);
    L->keep = off; off += al(sizeof(struct ras_fast_state) * keep_slots(s, L->ntris));
    L->spec = off;
    uint16_t nspec = spec_exponents(s, NULL, NULL);
    off += al(sizeof(uint16_t) * 257 * nspec) + al(sizeof(uint32_t) * 2 * nspec) + al(sizeof(int16_t) * s->ninstances);
    L->depth = off; off += al((size_t)depth_bytes(s) * w * strip_rows);
    L->adj = off; off += al(ras_ch15_adj_size(s, L->ntris));
    L->smap = off; off += al(ras_ch15_smap_size(s));
    L->stencil = off; off += al(ras_ch15_stencil_size(s, w, strip_rows));
    L->total = off + ALIGN; /* slack to align the caller's pointer */
    return 0;
}

size_t raster_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows)
{
    struct layout L;
    (void)height;
    if (make_layout(s, width, strip_rows, &L)) return 0;
    return L.total;
}

static struct ras_ctx *ctx_of(void *work)
{
    uintptr_t p = (uintptr_t)work;
    p = (p + (ALIGN - 1)) & ~(uintptr_t)(ALIGN - 1);
    return (struct ras_ctx *)p;
}

int raster_init(void *work, size_t work_size, const struct scene *s, uint16_t width, uint16_t height,
                uint16_t strip_rows)
{
    struct layout L;
    if (make_layout(s, width, strip_rows, &L) || work_size < L.total) return -1;
    if (s->canvas_h == 0 || s->viewport_h <= 0 || s->projection_d <= 0) return -1;
    struct ras_ctx *rc = ctx_of(work);
    uint8_t *base = (uint8_t *)rc;
    memset(rc, 0, sizeof *rc);
    rc->affine_from = -1;
    rc->s = s;
    rc->w = width;
    rc->h = height;
    rc->strip_rows = strip_rows;
    rc->book = s->ras.book_exact;
    rc->sub_bits = s->ras.subpixel_bits ? (s->ras.subpixel_bits > 8 ? 8 : s->ras.subpixel_bits) : RAS_SUBPIXEL_BITS;
    rc->depth_bytes = (uint8_t)depth_bytes(s);
    rc->fast = (uint8_t)fast_path(s);
    rc->persp_log2 = (uint8_t)(s->ras.persp_step == 8 ? 3 : (s->ras.persp_step == 32 ? 5 : 4));
    rc->nverts = L.nverts;
    rc->ntris = L.ntris;
    rc->inst = (struct ras_inst *)(void *)(base + L.inst);
    rc->verts = (struct ras_vert *)(void *)(base + L.verts);
    rc->tri_rows = (struct ras_range *)(void *)(base + L.tri_rows);
    rc->prim_rows = (struct ras_range *)(void *)(base + L.prim_rows);
    rc->line_rows = (struct ras_range *)(void *)(base + L.line_rows);
    rc->lights = (struct ras_light *)(void *)(base + L.lights);
    rc->mips = (struct ras_mips *)(void *)(base + L.mips);
    rc->tex565 = (struct ras_tex565 *)(void *)(base + L.tex565);
    rc->pv = frame_cache(s) ? (struct ras_pv *)(void *)(base + L.pv) : NULL;
    rc->tri_flags = frame_cache(s) ? base + L.tri_flags : NULL;
    rc->tri_shade = shade_cache(s) ? (num *)(void *)(base + L.tri_shade) : NULL;
    rc->nkeep = keep_slots(s, L.ntris);
    rc->phong_fast = (uint8_t)phong_fast(s);
    {
        /* the instances' tables (their count is the layout's) */
        uint8_t *sp = base + L.spec;
        rc->spec_tab = (uint16_t *)(void *)sp;
        uint32_t exps[RAS_SPEC_MAX];
        uint16_t nspec = spec_exponents(s, NULL, exps);
        rc->spec_step = (uint32_t *)(void *)(sp + al(sizeof(uint16_t) * 257 * nspec));
        rc->inst_spec = (int16_t *)(void *)((uint8_t *)rc->spec_step + al(sizeof(uint32_t) * 2 * nspec));
        spec_exponents(s, rc->inst_spec, NULL);   /* each instance's table */
        for (uint16_t k = 0; k < nspec; k++) ras_spec_table(rc->spec_tab + 257 * k, exps[k], rc->spec_step + 2 * k);
    }
    rc->keep = rc->nkeep ? (struct ras_fast_state *)(void *)(base + L.keep) : NULL;
    rc->depth = base + L.depth;
    rc->adj = (uint16_t *)(void *)(base + L.adj);
    rc->smap = (uint16_t *)(void *)(base + L.smap);
    rc->stencil = base + L.stencil;

    /* the render size's canvas: viewport height kept, width by aspect */
    rc->cw = num_from_int(rc->w);
    rc->vh = s->viewport_h;
    rc->vw = num_div(num_mul_int(s->viewport_h, rc->w), num_from_int(rc->h));
    rc->d = s->projection_d;
    rc->unproj = num_div(num_mul(rc->cw, rc->d), rc->vw);
    rc->scale2d = num_from_ratio(rc->h, s->canvas_h);
    rc->near_z = rc->d;
    /* side planes two pixels outside the viewport: the guard band keeps
     * rounded clip points from landing inside the image edge */
    rc->side_x = num_div(num_add(num_mul(rc->vw, NUM_HALF), num_div_int(num_mul_int(rc->vw, 2), rc->w)), rc->d);
    rc->side_y = num_div(num_add(num_mul(rc->vh, NUM_HALF), num_div_int(num_mul_int(rc->vh, 2), rc->h)), rc->d);
    rc->side_xk = num_sqrt(num_add(NUM_ONE, num_mul(rc->side_x, rc->side_x)));
    rc->side_yk = num_sqrt(num_add(NUM_ONE, num_mul(rc->side_y, rc->side_y)));

    uint8_t *mm = base + L.mipmem;
    for (uint16_t i = 0; i < s->ntextures; i++) {
        size_t n = rc->book ? 0 : ras_mips_size(&s->textures[i]);
        ras_mips_build(&s->textures[i], &rc->mips[i], n ? mm : NULL);
        mm += al(n);
    }
    uint8_t *tm = base + L.texmem;
    for (uint16_t i = 0; i < s->ntextures; i++) {
        const struct ras_texture *tx = &s->textures[i];
        size_t n = tex565_size(s, tx);
        rc->tex565[i].p = NULL;
        if (!n) continue;
        uint16_t *d = (uint16_t *)(void *)tm;
        for (size_t k = 0; k < (size_t)tx->w * tx->h; k++) {
            const uint8_t *c = tx->rgb + 3 * k;
            /* round(c * L / 255), as rgb_to_565 rounds an integral channel */
            uint32_t r = ((uint32_t)c[0] * 62 + 255) / 510, g = ((uint32_t)c[1] * 126 + 255) / 510,
                     b = ((uint32_t)c[2] * 62 + 255) / 510;
            d[k] = (uint16_t)(r << 11 | g << 5 | b);
        }
        rc->tex565[i].p = d;
        rc->tex565[i].wlog2 = (uint8_t)log2_exact(tx->w);
        rc->tex565[i].hlog2 = (uint8_t)log2_exact(tx->h);
        tm += al(n);
    }
    ras_ch15_init(rc);
    return 0;
}

/* ---- per frame ---------------------------------------------------------- */

/* Scene canvas to render canvas: v*h/canvas_h with one rounding (exact at
 * the scene's own size). */
static num scale_canvas(const struct ras_ctx *rc, num v)
{
    return wnum_div(num_mul_wide(v, num_from_int(rc->h)), wnum_from_num(num_from_int(rc->s->canvas_h)));
}

static struct ras_range rows_of_canvas_y(const struct ras_ctx *rc, num ymin, num ymax)
{
    struct ras_range r;
    int64_t a = (int64_t)(rc->h / 2) - num_to_int(ymax) - 2, b = (int64_t)(rc->h / 2) - num_to_int(ymin) + 1;
    if (a < 0) a = 0;
    if (b > (int64_t)rc->h - 1) b = rc->h - 1;
    if (a > b) { r.r0 = 1; r.r1 = 0; return r; }
    r.r0 = (int16_t)a;
    r.r1 = (int16_t)b;
    return r;
}

static struct ras_range no_rows(void) { struct ras_range r = { 1, 0 }; return r; }

static void range3(const num v[3], num *lo, num *hi)
{
    *lo = num_min(num_min(v[0], v[1]), v[2]);
    *hi = num_max(num_max(v[0], v[1]), v[2]);
}

/* Screen position of a camera-space point inside the clip volume, in
 * sub-pixel units (y down): the default path's projection. */
static void project_sub(const struct ras_ctx *rc, vec3 p, int32_t *sx, int32_t *sy)
{
    num X = ras_mul_div(p.x, rc->unproj, p.z);
    num Y = ras_mul_div(p.y, rc->unproj, p.z);
    num fx = num_add(num_from_int(rc->w / 2), X);
    num fy = num_sub(num_from_int(rc->h / 2), Y);
    int sb = rc->sub_bits;
    /* integer and fraction apart, so Q15.16 never holds pixels << 8 */
    *sx = (int32_t)((uint32_t)num_floor_int(fx) << sb) + num_floor_int(num_add(num_mul_int(num_frac(fx), 1 << sb), NUM_HALF));
    *sy = (int32_t)((uint32_t)num_floor_int(fy) << sb) + num_floor_int(num_add(num_mul_int(num_frac(fy), 1 << sb), NUM_HALF));
}

/* Rows of sub-pixel rows lo..hi, one row of margin each side. */
static struct ras_range sub_rows(const struct ras_ctx *rc, int32_t lo, int32_t hi)
{
    struct ras_range r;
    int32_t r0 = (lo >> rc->sub_bits) - 1, r1 = (hi >> rc->sub_bits) + 1;
    if (r0 < 0) r0 = 0;
    if (r1 > rc->h - 1) r1 = rc->h - 1;
    if (r0 > r1) return no_rows();
    r.r0 = (int16_t)r0;
    r.r1 = (int16_t)r1;
    return r;
}

static struct ras_range default_tri_rows(const struct ras_ctx *rc, vec3 a, vec3 b, vec3 c)
{
    struct ras_cv in[3], out[RAS_CLIP_MAX];
    in[0].p = a; in[1].p = b; in[2].p = c;
    int n = ras_clip_triangle(rc, in, 0, out);
    if (n < 3) return no_rows();
    int32_t lo = INT32_MAX, hi = INT32_MIN;
    for (int k = 0; k < n; k++) {
        int32_t sx, sy;
        project_sub(rc, out[k].p, &sx, &sy);
        if (sy < lo) lo = sy;
        if (sy > hi) hi = sy;
    }
    return sub_rows(rc, lo, hi);
}

static void tri_cache(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                      const struct ras_model *m, const struct ras_triangle *t, uint32_t gi);

/* RenderInstance, its frame half (the strip half is render_instance):
 * the instance's vertices to camera space (ApplyTransform), culled against
 * the viewport's bounding sphere (ClipInstance), projected
 * (ProjectVertex), and each triangle binned to the rows it may touch.
 * vb, tb: the instance's first vertex and triangle in the frame tables. */
static void prepare_instance(struct ras_ctx *rc, uint16_t i, uint16_t frame, uint32_t vb, uint32_t tb)
{
    const struct scene *s = rc->s;
    const struct ras_options *o = &s->ras;
    const struct ras_instance *in = &s->instances[i];
    const struct ras_model *m = &s->models[in->model];
    struct ras_inst *ri = &rc->inst[i];
    ri->vbase = vb;
    ri->tbase = tb;
    mat3 r3 = ras_instance_rotation(in, frame);
    mat4 r4 = m4_from_m3(&r3);
    ri->nmat = m4_mul(&rc->cam_rot_t, &r4);
    if (o->instance_transform) {
        mat4 mi = ras_instance_matrix(in, frame);
        ri->m = o->camera_transform ? m4_mul(&rc->cam, &mi) : mi;
    } else {
        /* raster-07: vertices simply moved by the position */
        mat4 t = m4_translation(in->position);
        ri->m = o->camera_transform ? m4_mul(&rc->cam, &t) : t;
    }
    ri->visible = o->clip ? (uint8_t)ras_instance_visible(rc, ri, m, o->instance_transform ? in->scale : NUM_ONE) : 1;
    for (uint16_t k = 0; k < m->nverts; k++) {
        struct ras_vert *v = &rc->verts[vb + k];
        vec3 p = m->verts[k];
        if (o->instance_transform) {
            vec4 p4 = { p.x, p.y, p.z, NUM_ONE };
            p4 = m4_mul_v4(&ri->m, p4);
            v->c = v3_make(p4.x, p4.y, p4.z);
        } else {
            v->c = v3_add(p, in->position);
            if (o->camera_transform) {
                vec4 p4 = { v->c.x, v->c.y, v->c.z, NUM_ONE };
                p4 = m4_mul_v4(&rc->cam, p4);
                v->c = v3_make(p4.x, p4.y, p4.z);
            }
        }
        ras_project_vertex(rc, v->c, &v->px, &v->py);
        if (o->project_truncate) {
            v->px = num_from_int(num_to_int(v->px));
            v->py = num_from_int(num_to_int(v->py));
        }
        if (rc->pv) {
            struct ras_pv *q = &rc->pv[vb + k];
            q->inside = (uint8_t)(ri->visible && ras_point_inside(rc, v->c));
            if (q->inside) {
                project_sub(rc, v->c, &q->sx, &q->sy);
                q->iz = num_recip(v->c.z);
                q->depth = ras_depth32(rc->near_z, v->c.z);
            }
        }
    }
    for (uint16_t k = 0; k < m->ntris; k++) {
        const struct ras_triangle *t = &m->tris[k];
        struct ras_range *rr = &rc->tri_rows[tb + k];
        rc->tris_in++;
        *rr = no_rows();
        if (!ri->visible || t->v[0] >= m->nverts || t->v[1] >= m->nverts || t->v[2] >= m->nverts) continue;
        const struct ras_vert *a = &rc->verts[vb + t->v[0]], *b = &rc->verts[vb + t->v[1]],
                              *c = &rc->verts[vb + t->v[2]];
        if (rc->book || o->wireframe) {
            if (o->clip && !ras_triangle_inside(a->c, b->c, c->c)) continue;
            if (!rc->book && !o->clip && (a->c.z <= rc->near_z || b->c.z <= rc->near_z || c->c.z <= rc->near_z))
                continue; /* default path, clipping off: never project behind the camera */
            num ys[3] = { a->py, b->py, c->py }, lo, hi;
            range3(ys, &lo, &hi);
            *rr = rows_of_canvas_y(rc, lo, hi);
        } else {
            const struct ras_pv *pa = &rc->pv[vb + t->v[0]], *pb = &rc->pv[vb + t->v[1]], *pc = &rc->pv[vb + t->v[2]];
            if (pa->inside && pb->inside && pc->inside)
                *rr = sub_rows(rc, num_min(num_min(pa->sy, pb->sy), pc->sy), num_max(num_max(pa->sy, pb->sy), pc->sy));
            else
                *rr = default_tri_rows(rc, a->c, b->c, c->c);
            if (rr->r0 <= rr->r1) tri_cache(rc, in, ri, m, t, tb + k);
            else rc->tri_flags[tb + k] = 0;
        }
        if (rr->r0 <= rr->r1) rc->tris_drawn++;
    }
}

int raster_begin_frame(void *work, uint16_t frame)
{
    struct ras_ctx *rc = ctx_of(work);
    const struct scene *s = rc->s;
    const struct ras_options *o = &s->ras;
    mat4 id = m4_identity();
    rc->cam = id;
    rc->cam_rot_t = id;
    rc->cam_pos = v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    if (o->camera_transform) rc->cam = ras_camera_matrix(s, frame, &rc->cam_rot_t, &rc->cam_pos);
    else rc->cam_pos = s->camera.position;

    for (uint16_t k = 0; k < s->nlights; k++) {
        const struct scene_light *l = &s->lights[k];
        struct ras_light *rl = &rc->lights[k];
        vec4 v = { l->v.x, l->v.y, l->v.z, NUM_ONE };
        rl->type = l->type;
        rl->intensity = l->intensity;
        v = m4_mul_v4(l->type == LIGHT_POINT ? &rc->cam : &rc->cam_rot_t, v);
        rl->v = v3_make(v.x, v.y, v.z);
    }

    /* 2D primitives and 3D lines: rows they may touch */
    for (uint16_t i = 0; i < s->nprims; i++) {
        const struct prim2d *p = &s->prims[i];
        num ys[3] = { p->y[0], p->y[1], p->npts > 2 ? p->y[2] : p->y[1] }, lo, hi;
        range3(ys, &lo, &hi);
        rc->prim_rows[i] = rows_of_canvas_y(rc, scale_canvas(rc, lo), scale_canvas(rc, hi));
    }
    for (uint16_t i = 0; i < s->nlines; i++) {
        num ax, ay, bx, by;
        ras_project_vertex(rc, s->lines[i].a, &ax, &ay);
        ras_project_vertex(rc, s->lines[i].b, &bx, &by);
        rc->line_rows[i] = rows_of_canvas_y(rc, num_min(ay, by), num_max(ay, by));
    }

    for (uint16_t k = 0; k < rc->nkeep; k++) rc->keep[k].tri = UINT32_MAX;

    /* RenderInstance, its frame half, for every instance */
    uint32_t vb = 0, tb = 0;
    rc->tris_in = rc->tris_drawn = 0;
    for (uint16_t i = 0; i < s->ninstances; i++) {
        const struct ras_model *m = &s->models[s->instances[i].model];
        prepare_instance(rc, i, frame, vb, tb);
        vb += m->nverts;
        tb += m->ntris;
    }
    if (rc->phong_fast) ras_fphong_frame(rc);
    ras_ch15_frame(rc);
    return 0;
}

/* ---- render_triangle, book path (docs/book-demos.md, RenderTriangle) ----- */

struct book_tri {
    rgb color;
    num flat_i;
    num spec;
    int shading, textured, nq;
    const struct ras_texture *tex;
};

static void book_pixel(struct ras_ctx *rc, int32_t x, int32_t y, const num *q, void *ud)
{
    const struct book_tri *bt = ud;
    const struct scene *s = rc->s;
    int col = ras_canvas_col(rc, x), row = ras_canvas_row(rc, y);
    if (col < 0 || col >= (int)rc->w || row < (int)rc->t->y0 || row >= (int)rc->t->y1) return;
    num iz = q[0];
    if (rc->depth_bytes) {
        num *db = (num *)(void *)rc->depth;
        size_t di = (size_t)(row - rc->t->y0) * rc->w + (size_t)col;
        if (!(db[di] == NUM_ZERO || db[di] < iz)) return;
        db[di] = iz;
    }
    num i = NUM_ONE;
    int k = 1;
    switch (bt->shading) {
    case SHADE_FLAT: i = bt->flat_i; break;
    case SHADE_GOURAUD: i = q[k++]; break;
    case SHADE_PHONG: {
        num oz = num_recip(iz);
        vec3 p = v3_make(ras_mul_div(num_from_int(x), oz, rc->unproj), ras_mul_div(num_from_int(y), oz, rc->unproj), oz);
        i = ras_compute_illumination(rc, p, v3_make(q[k], q[k + 1], q[k + 2]), bt->spec);
        k += 3;
        break;
    }
    default: break;
    }
    rgb c = bt->color;
    if (bt->textured) {
        num u = q[k], v = q[k + 1];
        if (s->ras.perspective_uv) { u = num_div(u, iz); v = num_div(v, iz); }
        int nan = 0;
        c = ras_texel_book(bt->tex, u, v, &nan);
        if (nan) { ras_put(rc, col, row, rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO)); return; }
    }
    if (bt->shading != SHADE_NONE) c = rgb_scale(c, i);
    ras_put(rc, col, row, c);
}

static vec3 corner_normal(const struct ras_inst *ri, vec3 n)
{
    vec4 v = { n.x, n.y, n.z, NUM_ONE };
    v = m4_mul_v4(&ri->nmat, v);
    return v3_make(v.x, v.y, v.z);
}

static void book_render_triangle(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                                 const struct ras_model *m, const struct ras_triangle *t)
{
    const struct ras_options *o = &rc->s->ras;
    const struct ras_vert *cv[3] = { &rc->verts[ri->vbase + t->v[0]], &rc->verts[ri->vbase + t->v[1]],
                                     &rc->verts[ri->vbase + t->v[2]] };
    num px[3] = { cv[0]->px, cv[1]->px, cv[2]->px }, py[3] = { cv[0]->py, cv[1]->py, cv[2]->py };
    if (o->wireframe) { ras_draw_wireframe_triangle(rc, px, py, t->color); return; }
    /* the face normal stays wide for the culling test; it is narrowed to
     * num only where it serves as the shading normal */
    struct ras_wnormal wf = ras_face_normal_wide(cv[0]->c, cv[1]->c, cv[2]->c);
    if (o->backface_cull && ras_facing_wide(cv[0]->c, wf) <= 0) return;
    int face_n = o->computed_normals || !m->has_normals;
    vec3 nf = face_n ? ras_wnormal_narrow(wf) : v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    int idx[3];
    ras_book_sort_corners(py, idx);
    num sx[3], sy[3], q[1 + RAS_MAX_ATTR][3];
    vec3 V[3], N[3];
    struct book_tri bt;
    bt.color = t->color;
    bt.spec = in->specular;
    bt.shading = o->shading;
    bt.textured = in->texture >= 0 && in->texture < rc->s->ntextures && m->has_uvs;
    bt.tex = bt.textured ? &rc->s->textures[in->texture] : NULL;
    bt.flat_i = NUM_ONE;
    for (int k = 0; k < 3; k++) {
        int c = idx[k];
        sx[k] = px[c];
        sy[k] = py[c];
        V[k] = cv[c]->c;
        N[k] = face_n ? nf : corner_normal(ri, t->n[c]);
        q[0][k] = num_recip(V[k].z);
    }
    int nq = 1;
    if (o->shading == SHADE_FLAT) {
        vec3 centre = v3_make(num_div_int(num_add(num_add(V[0].x, V[1].x), V[2].x), 3),
                              num_div_int(num_add(num_add(V[0].y, V[1].y), V[2].y), 3),
                         num_div_int(num_add(num_add(V[0].z, V[1].z), V[2].z), 3));
        bt.flat_i = ras_compute_illumination(rc, centre, N[0], bt.spec);
    } else if (o->shading == SHADE_GOURAUD) {
        for (int k = 0; k < 3; k++) q[nq][k] = ras_compute_illumination(rc, V[k], N[k], bt.spec);
        nq++;
    } else if (o->shading == SHADE_PHONG) {
        for (int k = 0; k < 3; k++) { q[nq][k] = N[k].x; q[nq + 1][k] = N[k].y; q[nq + 2][k] = N[k].z; }
        nq += 3;
    }
    if (bt.textured) {
        for (int k = 0; k < 3; k++) {
            int c = idx[k];
            num u = t->uv[c].u, v = t->uv[c].v;
            if (o->perspective_uv) { u = num_div(u, V[k].z); v = num_div(v, V[k].z); }
            q[nq][k] = u;
            q[nq + 1][k] = v;
        }
        nq += 2;
    }
    ras_book_scan_triangle(rc, sx, sy, nq, (const num (*)[3])q, book_pixel, &bt);
    if (o->outlines) {
        /* raster-10's outlines: P0P1, P0P2, P2P1 of the sorted corners */
        rgb oc = rgb_scale(t->color, NUM_C(0.75));
        ras_draw_line(rc, sx[0], sy[0], sx[1], sy[1], oc);
        ras_draw_line(rc, sx[0], sy[0], sx[2], sy[2], oc);
        ras_draw_line(rc, sx[2], sy[2], sx[1], sy[1], oc);
    }
}

/* ---- render_triangle, default path -------------------------------------- */

struct def_tri {
    rgb color;
    num flat_i, spec;
    int shading, tex;
    int ai_i, ai_n, ai_uv, ai_p; /* attribute slots */
    num lod_base, iz_eff;    /* trilinear: texels^2 per pixel at depth 1/iz_eff */
    int nmap;                /* normal map texture, -1: none */
    vec3 tan_u, tan_v;       /* unit tangents along +u and toward the image's top (-v) */
};

/* Chapter 15 at one pixel (Phong): normal map, shadows, environment. */
static rgb ch15_pixel(struct ras_ctx *rc, const struct def_tri *dt, int col, int row, vec3 p, vec3 n, const num *a, rgb c)
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
    if (rc->sm_on) vis = ras_shadow_map_vis(rc, p, n);
    if (rc->sv_on && rc->stencil[(size_t)(row - rc->t->y0) * rc->w + (size_t)col]) vis = NUM_ZERO;
    num i = ras_compute_illumination_vis(rc, p, n, dt->spec, rc->sh_light, vis);
    c = rgb_scale(c, i);
    if (rc->env_on) {
        /* mirror direction of the view ray about n */
        vec3 d = v3_normalize(p);
        vec3 r = v3_sub(d, v3_scale(n, num_mul_int(v3_dot(d, n), 2)));
        rgb e = ras_env_colour(rc, r);
        num k = rc->env_k, k1 = num_sub(NUM_ONE, k);
        c = rgb_make(num_add(num_mul(c.r, k1), num_mul(e.r, k)), num_add(num_mul(c.g, k1), num_mul(e.g, k)),
                     num_add(num_mul(c.b, k1), num_mul(e.b, k)));
    }
    return c;
}

static void default_pixel(struct ras_ctx *rc, int col, int row, const num *a, num z, void *ud)
{
    const struct def_tri *dt = ud;
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
        if (dt->nmap >= 0 || rc->sm_on || rc->sv_on || rc->env_on) {
            ras_put(rc, col, row, ch15_pixel(rc, dt, col, row, p, n, a, c));
            return;
        }
        i = ras_compute_illumination(rc, p, n, dt->spec);
    }
    if (dt->shading != SHADE_NONE) c = rgb_scale(c, i);
    ras_put(rc, col, row, c);
}

/* Colour levels of RGB565 in Q10, round(c * L * 1024 / 255); 0 when a
 * channel lies outside 0..255. */
static int levels_q10(rgb c, struct ras_fast_tri *ft)
{
    int32_t r = ras_num_to_fix(c.r, 31 * 1024 * 2), g = ras_num_to_fix(c.g, 63 * 1024 * 2),
            b = ras_num_to_fix(c.b, 31 * 1024 * 2);
    ft->kr = r <= 0 ? 0 : (uint32_t)(r + 255) / 510;
    ft->kg = g <= 0 ? 0 : (uint32_t)(g + 255) / 510;
    ft->kb = b <= 0 ? 0 : (uint32_t)(b + 255) / 510;
    return !(ft->kr > 31u * 1024 || ft->kg > 63u * 1024 || ft->kb > 31u * 1024);
}

/* The fast span loops' description of a triangle; 0 when it needs the
 * exact per-pixel path (chapter 15 passes and normal maps, Phong without
 * fast Phong, filtered or non-power-of-two textures, screen-linear uv,
 * textures under flat shading). */
static int fast_setup(const struct ras_ctx *rc, const struct def_tri *dt, struct ras_fast_tri *ft, ptrdiff_t inst)
{
    const struct ras_options *o = &rc->s->ras;
    if (!rc->fast || rc->depth_only || rc->depth_func != RAS_DEPTH_LESS_WRITE || dt->nmap >= 0) return 0;
    int gour = dt->shading == SHADE_GOURAUD, phong = dt->shading == SHADE_PHONG;
    if (phong && (!rc->phong_fast || !rc->fp.ok || rc->inst_spec[inst] == -2)) return 0;
    ft->ai_i = dt->ai_i;
    ft->ai_uv = dt->ai_uv;
    if (phong) {
        ft->ai_n = dt->ai_n;
        ft->ai_p = dt->ai_p;
        ft->fp = &rc->fp;
        int16_t st = rc->inst_spec[inst];
        ft->spec = st >= 0 ? rc->spec_tab + 257 * st : NULL;
        ft->spec_scale = st >= 0 ? rc->spec_step[2 * st] : 0;
        ft->spec_umax = st >= 0 ? rc->spec_step[2 * st + 1] : 0;
        if (dt->tex < 0) {
            ft->kind = RAS_FT_PHONG;
            return levels_q10(dt->color, ft);
        }
    }
    if (dt->tex >= 0) {
        const struct ras_tex565 *t5 = &rc->tex565[dt->tex];
        if (!t5->p || !o->perspective_uv || dt->shading == SHADE_FLAT) return 0;
        ft->kind = (uint8_t)(phong ? RAS_FT_PHONG_TEX : (gour ? RAS_FT_TEX_GOURAUD : RAS_FT_TEX));
        ft->tex = t5->p;
        ft->wlog2 = t5->wlog2;
        ft->wmask = (1u << t5->wlog2) - 1;
        ft->hmask = (1u << t5->hlog2) - 1;
        /* u = 1 maps to the last texel's far edge less 2^-16: nearest with
         * clamping for u, v in [0, 1], repeating outside */
        ft->uscale = (int32_t)((1u << t5->wlog2) * 65536u - 1u);
        ft->vscale = (int32_t)((1u << t5->hlog2) * 65536u - 1u);
        return 1;
    }
    if (gour) {
        ft->kind = RAS_FT_GOURAUD;
        return levels_q10(dt->color, ft);
    }
    ft->kind = RAS_FT_FLAT;
    rgb c = dt->shading == SHADE_FLAT ? rgb_scale(dt->color, dt->flat_i) : dt->color;
    ft->c565 = rgb_to_565(c);
    rgb_to_888(c, ft->c888);
    return 1;
}

/* Camera-space corners, facing and shading normals of a triangle of the
 * default path; 0 when it draws nothing (degenerate, or a culled back face). */
static int tri_facts(const struct ras_ctx *rc, const struct ras_inst *ri, const struct ras_model *m,
                     const struct ras_triangle *t, vec3 V[3], vec3 N[3], int *front)
{
    const struct ras_options *o = &rc->s->ras;
    for (int k = 0; k < 3; k++) V[k] = rc->verts[ri->vbase + t->v[k]].c;
    struct ras_wnormal wf = ras_face_normal_wide(V[0], V[1], V[2]);
    wnum facing = ras_facing_wide(V[0], wf);
    if (facing == 0 && wf.x == 0 && wf.y == 0 && wf.z == 0) return 0; /* degenerate */
    *front = facing > 0;
    if (o->backface_cull && !*front) return 0;
    int face_n = o->computed_normals || !m->has_normals;
    vec3 nf = face_n ? ras_wnormal_narrow(wf) : v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    for (int k = 0; k < 3; k++) N[k] = face_n ? nf : corner_normal(ri, t->n[k]);
    return 1;
}

static vec3 tri_centre(const vec3 V[3])
{
    return v3_make(num_div_int(num_add(num_add(V[0].x, V[1].x), V[2].x), 3),
                   num_div_int(num_add(num_add(V[0].y, V[1].y), V[2].y), 3),
              num_div_int(num_add(num_add(V[0].z, V[1].z), V[2].z), 3));
}

/* Per frame: the facts of triangle gi kept for every strip, and the
 * lighting of its Gouraud corners or flat face (the values
 * default_render_triangle would compute in each strip). */
static void tri_cache(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                      const struct ras_model *m, const struct ras_triangle *t, uint32_t gi)
{
    vec3 V[3], N[3];
    int front = 0;
    if (!tri_facts(rc, ri, m, t, V, N, &front)) { rc->tri_flags[gi] = 0; return; }
    rc->tri_flags[gi] = (uint8_t)(RAS_TRI_LIVE | (front ? RAS_TRI_FRONT : 0));
    if (!rc->tri_shade) return;
    num *sh = rc->tri_shade + 3 * (size_t)gi;
    if (eff_shading(rc->s) == SHADE_GOURAUD)
        for (int k = 0; k < 3; k++) sh[k] = ras_compute_illumination(rc, V[k], N[k], in->specular);
    else
        sh[0] = ras_compute_illumination(rc, tri_centre(V), N[0], in->specular);
}

static void default_render_triangle(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                                    const struct ras_model *m, const struct ras_triangle *t, uint32_t gi)
{
    const struct ras_options *o = &rc->s->ras;
    struct ras_fast_state *slot = NULL;
    if (rc->keep && !rc->depth_only && rc->depth_func == RAS_DEPTH_LESS_WRITE) {
        /* the rest of a triangle begun in the strip above */
        slot = &rc->keep[gi % rc->nkeep];
        uint32_t drawn;
        if (slot->tri == gi && ras_fast_resume(rc, slot, &drawn)) {
            rc->st->pixels_written += drawn;
            return;
        }
    }
    vec3 V[3], N[3];
    int front = 0;
    const num *shade = rc->tri_shade ? rc->tri_shade + 3 * (size_t)gi : NULL;
    if (rc->tri_flags) {
        uint8_t f = rc->tri_flags[gi];
        if (!(f & RAS_TRI_LIVE)) return;
        front = (f & RAS_TRI_FRONT) != 0;
        if (shade) {
            for (int k = 0; k < 3; k++) V[k] = rc->verts[ri->vbase + t->v[k]].c;
        } else if (!tri_facts(rc, ri, m, t, V, N, &front)) {
            return;
        }
    } else if (!tri_facts(rc, ri, m, t, V, N, &front)) {
        return;
    }

    struct def_tri dt;
    dt.color = t->color;
    dt.spec = in->specular;
    const int sh = eff_shading(rc->s);
    dt.shading = sh;
    dt.tex = (in->texture >= 0 && in->texture < rc->s->ntextures && m->has_uvs) ? in->texture : -1;
    dt.flat_i = NUM_ONE;
    dt.ai_i = dt.ai_n = dt.ai_uv = dt.ai_p = 0;
    dt.nmap = -1;
    if (sh == SHADE_PHONG && in->normal_map >= 0 && in->normal_map < rc->s->ntextures && m->has_uvs) {
        /* tangents from the uv derivatives of this triangle */
        vec3 e1 = v3_sub(V[1], V[0]), e2 = v3_sub(V[2], V[0]);
        num du1 = num_sub(t->uv[1].u, t->uv[0].u), dv1 = num_sub(t->uv[1].v, t->uv[0].v);
        num du2 = num_sub(t->uv[2].u, t->uv[0].u), dv2 = num_sub(t->uv[2].v, t->uv[0].v);
        num det = num_sub(num_mul(du1, dv2), num_mul(du2, dv1));
        if (det != 0) {
            dt.nmap = in->normal_map;
            /* dP/du and dP/dv up to the common factor 1/det (its sign kept) */
            vec3 pu = v3_sub(v3_scale(e1, dv2), v3_scale(e2, dv1));
            vec3 pv = v3_sub(v3_scale(e2, du1), v3_scale(e1, du2));
            if (det < 0) { pu = v3_neg(pu); pv = v3_neg(pv); }
            dt.tan_u = v3_normalize(pu);
            dt.tan_v = v3_normalize(v3_neg(pv));
        }
    }
    struct ras_cv cin[3], poly[RAS_CLIP_MAX];
    int na = 0;
    if (sh == SHADE_GOURAUD) dt.ai_i = na++;
    if (sh == SHADE_PHONG) { dt.ai_n = na; na += 3; }
    /* fast Phong also needs the camera-space position at each pixel */
    if (sh == SHADE_PHONG && rc->phong_fast) { dt.ai_p = na; na += 3; }
    int uv = dt.tex >= 0 || dt.nmap >= 0;
    if (uv) { dt.ai_uv = na; na += 2; }
    for (int k = 0; k < 3; k++) {
        cin[k].p = V[k];
        if (sh == SHADE_GOURAUD)
            cin[k].a[dt.ai_i] = shade ? shade[k] : ras_compute_illumination(rc, V[k], N[k], dt.spec);
        if (sh == SHADE_PHONG) {
            vec3 n = v3_normalize(N[k]);
            cin[k].a[dt.ai_n] = n.x; cin[k].a[dt.ai_n + 1] = n.y; cin[k].a[dt.ai_n + 2] = n.z;
            if (rc->phong_fast) { cin[k].a[dt.ai_p] = V[k].x; cin[k].a[dt.ai_p + 1] = V[k].y; cin[k].a[dt.ai_p + 2] = V[k].z; }
        }
        if (uv) { cin[k].a[dt.ai_uv] = t->uv[k].u; cin[k].a[dt.ai_uv + 1] = t->uv[k].v; }
    }
    if (sh == SHADE_FLAT) dt.flat_i = shade ? shade[0] : ras_compute_illumination(rc, tri_centre(V), N[0], dt.spec);
    struct ras_sv sv[RAS_CLIP_MAX];
    int n;
    const struct ras_pv *pv = rc->pv ? rc->pv + ri->vbase : NULL;
    if (pv && pv[t->v[0]].inside && pv[t->v[1]].inside && pv[t->v[2]].inside) {
        /* inside every plane: the clipper would return the corners as they
         * are; their projections were made once this frame */
        n = 3;
        for (int k = 0; k < 3; k++) {
            int c = front ? k : 2 - k;
            const struct ras_pv *q = &pv[t->v[c]];
            sv[k].x = q->sx;
            sv[k].y = q->sy;
            sv[k].iz = q->iz;
            sv[k].depth = q->depth;
            for (int j = 0; j < na; j++) sv[k].a[j] = cin[c].a[j];
        }
    } else {
        n = ras_clip_triangle(rc, cin, na, poly);
        if (n < 3) return;
        for (int k = 0; k < n; k++) {
            /* back faces (culling off) are drawn with their corners reversed */
            const struct ras_cv *c = &poly[front ? k : n - 1 - k];
            project_sub(rc, c->p, &sv[k].x, &sv[k].y);
            sv[k].iz = num_recip(c->p.z);
            sv[k].depth = ras_depth32(rc->near_z, c->p.z);
            for (int j = 0; j < na; j++) sv[k].a[j] = c->a[j];
        }
    }
    const struct ras_texture *tx = dt.tex >= 0 ? &rc->s->textures[dt.tex] : NULL;
    struct ras_fast_tri ft;
    int fast = fast_setup(rc, &dt, &ft, ri - rc->inst);
    for (int k = 1; k + 1 < n; k++) {
        const struct ras_sv *a = &sv[0], *b = &sv[k], *c = &sv[k + 1];
        if (fast) {
            /* an unclipped triangle's set-up is kept for the strips below */
            struct ras_fast_state *k1 = n == 3 ? slot : NULL;
            if (k1) k1->tri = gi;
            int32_t drawn = ras_fast_fill(rc, a, b, c, &ft, k1);
            if (drawn >= 0) { rc->st->pixels_written += (uint32_t)drawn; continue; }
            if (k1) k1->tri = UINT32_MAX;
        }
        dt.lod_base = NUM_ZERO;
        dt.iz_eff = NUM_ONE;
        if (tx && tx->filter == TEX_TRILINEAR) {
            int64_t area = (int64_t)(b->x - a->x) * (c->y - a->y) - (int64_t)(b->y - a->y) * (c->x - a->x);
            num du1 = num_sub(b->a[dt.ai_uv], a->a[dt.ai_uv]), dv1 = num_sub(b->a[dt.ai_uv + 1], a->a[dt.ai_uv + 1]);
            num du2 = num_sub(c->a[dt.ai_uv], a->a[dt.ai_uv]), dv2 = num_sub(c->a[dt.ai_uv + 1], a->a[dt.ai_uv + 1]);
            num uv2 = num_abs(num_sub(num_mul(du1, dv2), num_mul(du2, dv1)));
            if (area > 0) {
                num k2 = ras_ratio(((int64_t)tx->w * tx->h) << (2 * rc->sub_bits), area);
                dt.lod_base = num_mul(uv2, k2);
            }
            dt.iz_eff = num_div_int(num_add(num_add(a->iz, b->iz), c->iz), 3);
        }
        rc->affine_from = (int8_t)(uv && !o->perspective_uv ? dt.ai_uv : -1);
        ras_fill_triangle(rc, a, b, c, na, rc->depth_only ? NULL : default_pixel, &dt);
    }
}

/* ---- the strip ------------------------------------------------------------ */

/* Word stores through an alias-safe type (the strip is uint16_t, the depth
 * buffer bytes of work memory). */
#if defined(__GNUC__) || defined(__clang__)
typedef uint32_t __attribute__((may_alias)) ras_word;
#define RAS_HAVE_WORD 1
#endif

/* n RGB565 pixels of value c: 32-bit stores, eight a loop. */
static void ras_fill16(uint16_t *p, size_t n, uint16_t c)
{
#ifdef RAS_HAVE_WORD
    if (n && ((uintptr_t)p & 2u)) { *p++ = c; n--; }
    ras_word *w = (ras_word *)(void *)p, v = (uint32_t)c * 0x00010001u;
    size_t nw = n / 2;
    for (; nw >= 8; nw -= 8, w += 8) { w[0] = v; w[1] = v; w[2] = v; w[3] = v; w[4] = v; w[5] = v; w[6] = v; w[7] = v; }
    while (nw--) *w++ = v;
    if (n & 1u) p[n - 1] = c;
#else
    for (size_t k = 0; k < n; k++) p[k] = c;
#endif
}

/* n bytes of zeros at p (4-byte aligned, n a multiple of 2). */
static void ras_fill_zero(uint8_t *p, size_t n)
{
#ifdef RAS_HAVE_WORD
    if (((uintptr_t)p & 3u) == 0) {
        ras_word *w = (ras_word *)(void *)p;
        size_t nw = n / 4;
        for (; nw >= 8; nw -= 8, w += 8) { w[0] = 0; w[1] = 0; w[2] = 0; w[3] = 0; w[4] = 0; w[5] = 0; w[6] = 0; w[7] = 0; }
        while (nw--) *w++ = 0;
        p = (uint8_t *)w;
        n &= 3u;
    }
#endif
    memset(p, 0, n);
}

static int rows_hit(struct ras_range r, const struct render_target *t)
{
    return r.r0 <= r.r1 && r.r1 >= (int)t->y0 && r.r0 < (int)t->y1;
}

/* RenderInstance, its strip half: the instance's triangles that touch the
 * strip (binned by prepare_instance), each through RenderTriangle. */
static void render_instance(struct ras_ctx *rc, uint16_t i, const struct render_target *t)
{
    const struct scene *s = rc->s;
    const struct ras_instance *in = &s->instances[i];
    const struct ras_inst *ri = &rc->inst[i];
    const struct ras_model *m = &s->models[in->model];
    if (!ri->visible) return;
    for (uint16_t k = 0; k < m->ntris; k++) {
        if (!rows_hit(rc->tri_rows[ri->tbase + k], t)) continue;
        if (rc->book || s->ras.wireframe) book_render_triangle(rc, in, ri, m, &m->tris[k]);
        else default_render_triangle(rc, in, ri, m, &m->tris[k], ri->tbase + k);
    }
}

/* RenderScene for one strip: every instance, in the scene's order; with
 * shadow volumes (chapter 15) three passes: depth only, the volumes into
 * the stencil, then shading where the depth equals the visible surface's. */
static void render_scene(struct ras_ctx *rc, const struct render_target *t)
{
    for (int pass = rc->sv_on ? 0 : 2; pass < 3; pass++) {
        if (pass == 1) { ras_shadow_volumes(rc); continue; }
        rc->depth_only = (uint8_t)(pass == 0);
        rc->depth_func = (uint8_t)(rc->sv_on && pass == 2 ? RAS_DEPTH_EQUAL : RAS_DEPTH_LESS_WRITE);
        for (uint16_t i = 0; i < rc->s->ninstances; i++) render_instance(rc, i, t);
    }
}

int raster_strip(void *work, struct render_target *t, struct render_stats *st)
{
    struct ras_ctx *rc = ctx_of(work);
    const struct scene *s = rc->s;
    if (t->y1 - t->y0 > rc->strip_rows) return -1;
    rc->t = t;
    rc->st = st;
    rgb bg = scene_background(s);
    size_t npx = (size_t)(t->y1 - t->y0) * t->width;
    ras_fill16(t->rgb565, npx, rgb_to_565(bg));
    if (t->rgb888) {
        uint8_t c[3];
        rgb_to_888(bg, c);
        for (size_t k = 0; k < npx; k++) memcpy(t->rgb888 + 3 * k, c, 3);
    }
    if (t->written) memset(t->written, 0, npx);
    if (rc->depth_bytes) ras_fill_zero(rc->depth, (size_t)rc->depth_bytes * rc->w * (size_t)(t->y1 - t->y0));

    for (uint16_t i = 0; i < s->nprims; i++) {
        if (!rows_hit(rc->prim_rows[i], t)) continue;
        const struct prim2d *p = &s->prims[i];
        num x[3], y[3];
        for (int k = 0; k < 3; k++) {
            x[k] = scale_canvas(rc, p->x[k]);
            y[k] = scale_canvas(rc, p->y[k]);
        }
        switch (p->kind) {
        case P2D_LINE_BROKEN: ras_draw_line_broken(rc, x[0], y[0], x[1], y[1], p->color); break;
        case P2D_LINE: ras_draw_line(rc, x[0], y[0], x[1], y[1], p->color); break;
        case P2D_WIRE_TRI: ras_draw_wireframe_triangle(rc, x, y, p->color); break;
        case P2D_FILLED_TRI: ras_draw_filled_triangle(rc, x, y, p->color); break;
        case P2D_SHADED_TRI: ras_draw_shaded_triangle(rc, x, y, p->h, p->color); break;
        default: break;
        }
    }
    for (uint16_t i = 0; i < s->nlines; i++) {
        if (!rows_hit(rc->line_rows[i], t)) continue;
        num ax, ay, bx, by;
        ras_project_vertex(rc, s->lines[i].a, &ax, &ay);
        ras_project_vertex(rc, s->lines[i].b, &bx, &by);
        ras_draw_line(rc, ax, ay, bx, by, s->lines[i].color);
    }
    render_scene(rc, t);
    rc->depth_only = 0;
    rc->depth_func = RAS_DEPTH_LESS_WRITE;
    if (t->y0 == 0) {
        st->triangles_in += rc->tris_in;
        st->triangles_drawn += rc->tris_drawn;
    }
    return 0;
}
