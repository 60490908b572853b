/* SPDX-License-Identifier: MIT */
/* raster_frame.c — render_begin_frame: the camera and the lights in camera
 * space, every instance's vertices transformed and projected (the frame
 * half of the book's RenderInstance), and the binning of every primitive to
 * the rows it may touch, so each strip visits only its own. */
#include "raster_int.h"
#include "num/num_int.h"

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

/* Rows of sub-pixel rows lo..hi, one row of margin each side. */
static struct ras_range sub_rows(const struct ras_ctx *rc, int32_t lo, int32_t hi)
{
    struct ras_range r;
    int32_t r0 = (lo >> rc->def.sub_bits) - 1, r1 = (hi >> rc->def.sub_bits) + 1;
    if (r0 < 0) r0 = 0;
    if (r1 > rc->h - 1) r1 = rc->h - 1;
    if (r0 > r1) return no_rows();
    r.r0 = (int16_t)r0;
    r.r1 = (int16_t)r1;
    return r;
}

static int32_t min3(int32_t a, int32_t b, int32_t c) { int32_t m = a < b ? a : b; return m < c ? m : c; }
static int32_t max3(int32_t a, int32_t b, int32_t c) { int32_t m = a > b ? a : b; return m > c ? m : c; }

static struct ras_range default_tri_rows(const struct ras_ctx *rc, vec3 a, vec3 b, vec3 c)
{
    struct ras_cv in[3], out[RAS_CLIP_MAX];
    in[0].p = a; in[1].p = b; in[2].p = c;
    int n = ras_clip_triangle(rc, in, 0, out);
    if (n < 3) return no_rows();
    int32_t lo = INT32_MAX, hi = INT32_MIN;
    for (int k = 0; k < n; k++) {
        int32_t sx, sy;
        ras_project_sub(rc, out[k].p, &sx, &sy);
        if (sy < lo) lo = sy;
        if (sy > hi) hi = sy;
    }
    return sub_rows(rc, lo, hi);
}

/* RenderInstance, its frame half (the strip half is render_instance), in
 * three steps: instance_head (its matrices, culled against the viewport's
 * bounding sphere: ClipInstance), instance_vertices (to camera space,
 * ApplyTransform, and projected, ProjectVertex) and instance_triangles
 * (each triangle culled, lit and binned to the rows it may touch).
 * vb, tb: the instance's first vertex and triangle in the frame tables. */
/* Bits a .. b - 1 of the bit table t cleared (bit k: t[k >> 3] bit k & 7),
 * the whole bytes among them at once. */
static void bits_clear(uint8_t *t, uint32_t a, uint32_t b)
{
    for (; a < b && (a & 7u); a++) t[a >> 3] &= (uint8_t)~(1u << (a & 7u));
    for (; b - a >= 8u; a += 8u) t[a >> 3] = 0;
    for (; a < b; a++) t[a >> 3] &= (uint8_t)~(1u << (a & 7u));
}

static void instance_head(struct ras_ctx *rc, uint16_t i, uint16_t frame, uint32_t vb, uint32_t tb)
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
    /* its vertices' transform free of saturation, and all of them inside
     * every plane, known from its model's box or the sphere around its
     * vertices (the same bits, the same decisions) */
    struct ras_box cb;
    ri->vfit = (uint8_t)(o->instance_transform && ras_box_transform(&ri->m, &ri->box, &cb));
    ri->vsplit = (uint8_t)(ri->vfit ? ras_fit_split(&ri->m, &ri->box) : 0);
    /* the normals' transform likewise, for those within RAS_NORMAL_BOX */
    {
        struct ras_box nb, ncb;
        nb.ok = 1;
        for (int j = 0; j < 3; j++) {
            nb.lo[j] = num_neg(RAS_NORMAL_BOX);
            nb.hi[j] = RAS_NORMAL_BOX;
        }
        ri->nsplit = (uint8_t)(ras_box_transform(&ri->nmat, &nb, &ncb) ? ras_fit_split(&ri->nmat, &nb) : 0);
    }
    ri->vin = (uint8_t)(ri->vfit && ri->visible && rc->def.pv &&
                        (ras_box_inside(rc, &cb) ||
                         ras_sphere_inside(&ri->m, &ri->box, &cb, rc->def.near_z, rc->def.side_x, rc->def.side_y)));
    ri->vlit = (uint8_t)(rc->def.vert_shade && ras_vertex_lit(s, in));
    if (rc->def.mlight) ras_model_light_frame(rc, in, ri, &rc->def.mlight[i]);
    if (ri->vlit) {   /* no vertex lit yet this frame (by either part of the triangles) */
        bits_clear(rc->def.vert_lit, vb, vb + m->nverts);
        if (rc->def.vert_lit1) bits_clear(rc->def.vert_lit1, vb, vb + m->nverts);
    }
}

/* Model point p of instance in to camera space (ApplyTransform). */
static vec3 cam_point(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri, vec3 p)
{
    const struct ras_options *o = &rc->s->ras;
    if (o->instance_transform)
        return ri->vsplit ? ras_mul_point_fit_split(&ri->m, p, ri->vsplit)
                          : (ri->vfit ? ras_mul_point_fit(&ri->m, p) : ras_mul_point(&ri->m, p));
    vec3 c = v3_add(p, in->position);
    return o->camera_transform ? ras_mul_point(&rc->cam, c) : c;
}

vec3 ras_cam_vertex_again(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                          const struct ras_model *m, uint32_t k, struct ras_vcache *vc)
{
    const uint32_t g = ri->vbase + k;
    if (!vc) return cam_point(rc, in, ri, m->verts[k]);
    struct ras_vcache *e = &vc[g & rc->def.vcache_mask];
    if (e->k != g) {
        e->k = g;
        e->c = cam_point(rc, in, ri, m->verts[k]);
    }
    return e->c;
}

/* The default path's projected vertex q of camera-space point c: its
 * sub-pixel position, reciprocal depth and depth where `shown` (visible and
 * inside every clip plane) and the position fits 16 bits, else RAS_PV_OUT. */
static inline void store_pv(const struct ras_subproj *k, struct ras_pv *q, vec3 c, int shown)
{
    if (shown)
        ras_div_sub_pv(k, q, c);   /* ras_project_sub_depth's bits */
    else
        q->sx = RAS_PV_OUT;
}

/* Vertices k0 .. k1 - 1 of instance i (after its instance_head); each
 * vertex writes only its own entries of the frame tables. */
static void instance_vertices(const struct ras_ctx *rc, uint16_t i, uint32_t k0, uint32_t k1)
{
    const struct scene *s = rc->s;
    const struct ras_options *o = &s->ras;
    const struct ras_instance *in = &s->instances[i];
    const struct ras_model *m = &s->models[in->model];
    const struct ras_inst *ri = &rc->inst[i];
    const uint32_t vb = ri->vbase;
    struct ras_subproj kp;
    ras_subproj_of(rc, &kp);
    if (ri->vfit && rc->def.pv && !rc->proj) {
        /* the default path's vertices of an instance whose transform
         * cannot saturate, every one inside every plane where ri->vin */
        const int tested = !ri->vin, sp = ri->vsplit;
        if (sp) {
            /* the transform 16 points at a time */
            vec3 cb[16];
            for (uint32_t k = k0; k < k1; k += 16) {
                const uint32_t n = k1 - k < 16 ? k1 - k : 16;
                ras_mul_points_fit_split(&ri->m, &m->verts[k], cb, n, sp);
                if (rc->verts)
                    for (uint32_t j = 0; j < n; j++) rc->verts[vb + k + j].c = cb[j];
                if (ri->visible && !tested)
                    ras_div_subs(&kp, cb, &rc->def.pv[vb + k], n);
                else
                    for (uint32_t j = 0; j < n; j++)
                        store_pv(&kp, &rc->def.pv[vb + k + j], cb[j], ri->visible && (!tested || ras_point_inside(rc, cb[j])));
            }
            return;
        }
        for (uint32_t k = k0; k < k1; k++) {
            const vec3 c = sp ? ras_mul_point_fit_split(&ri->m, m->verts[k], sp) : ras_mul_point_fit(&ri->m, m->verts[k]);
            if (rc->verts) rc->verts[vb + k].c = c;
            store_pv(&kp, &rc->def.pv[vb + k], c, ri->visible && (!tested || ras_point_inside(rc, c)));
        }
        return;
    }
    for (uint32_t k = k0; k < k1; k++) {
        const vec3 c = cam_point(rc, in, ri, m->verts[k]);
        if (rc->verts) rc->verts[vb + k].c = c;
        if (rc->proj) {
            struct ras_proj *q = &rc->proj[vb + k];
            ras_project_vertex(rc, c, &q->px, &q->py);
            if (o->project_truncate) {
                q->px = num_from_int(num_to_int(q->px));
                q->py = num_from_int(num_to_int(q->py));
            }
        }
        if (rc->def.pv) {
            store_pv(&kp, &rc->def.pv[vb + k], c, ri->visible && ras_point_inside(rc, c));
        }
    }
}

/* The doubled area on screen of projected corners pa, pb, pc, in the order
 * a front face is drawn: |differences| < 2^16 (ras_pv), the products in 32
 * x 32 -> 64 bits; all four in [-2^14, 2^14) (a triangle of at most 1,024
 * pixels a side at 4 sub-pixel bits), the same in 32 bits. */
static inline int64_t pv_area(const struct ras_pv *pa, const struct ras_pv *pb, const struct ras_pv *pc)
{
    const int32_t d1x = pb->sx - pa->sx, d1y = pb->sy - pa->sy, d2x = pc->sx - pa->sx, d2y = pc->sy - pa->sy;
    return (((uint32_t)d1x + 0x4000u) | ((uint32_t)d1y + 0x4000u) | ((uint32_t)d2x + 0x4000u) |
            ((uint32_t)d2y + 0x4000u)) < 0x8000u
               ? (int64_t)(d1x * d2y - d1y * d2x)
               : num_smul32(d1x, d2y) - num_smul32(d1y, d2x);
}

/* What tri_live reads of an instance's triangles' loop, made once per
 * loop: the context, the instance, the front-face bound (at most
 * INT32_MAX), the part, the rows' constants and whether lighting is kept. */
struct tri_loop {
    struct ras_ctx *rc;
    const struct ras_instance *in;
    const struct ras_model *m;
    const struct ras_inst *ri;
    int32_t fbound;
    uint8_t *flags;          /* the instance's flag bytes, NULL: none kept */
    int part, plain, bins;   /* plain: no lighting kept (!vlit, no tri_shade) */
    int cull;                /* back faces culled */
    int32_t sb, half, hmax;  /* sub-pixel bits, half a pixel in them, the last row */
    uint32_t rshift;         /* ras_ctx.row_shift */
};

/* The camera-space facing test of triangle t (tri_facts: ras_facing_wide
 * of its first corner and ras_face_normal_wide of its corners) in a pass
 * that culls back faces: 1 when its value f > 0 (a front face, live), 0
 * when not (a back face or degenerate: culled). The same f: the normal's
 * products in 32 bits where every edge component lies in [-2^15, 2^15)
 * (|p| <= 2^30, and floor((p + 2^(F-1)) / 2^F) is num_mul_round's, with
 * nothing for wnum_sub to clamp), num_mul_wide's otherwise. */
static int cam_front(struct ras_ctx *rc, const struct tri_loop *L, const struct ras_triangle *t)
{
    struct ras_vcache *vc = L->part ? rc->def.vcache1 : rc->def.vcache;
    const vec3 a = ras_cam_vertex(rc, L->in, L->ri, L->m, t->v[0], vc);
    const vec3 b = ras_cam_vertex(rc, L->in, L->ri, L->m, t->v[1], vc);
    const vec3 c = ras_cam_vertex(rc, L->in, L->ri, L->m, t->v[2], vc);
    const vec3 e1 = v3_sub(b, a), e2 = v3_sub(c, a);
    wnum nx, ny, nz;
#if NUM_MODE == NUM_MODE_FIXED
    if ((((uint32_t)e1.x + 0x8000u) | ((uint32_t)e1.y + 0x8000u) | ((uint32_t)e1.z + 0x8000u) |
         ((uint32_t)e2.x + 0x8000u) | ((uint32_t)e2.y + 0x8000u) | ((uint32_t)e2.z + 0x8000u)) < 0x10000u) {
        const int32_t h = (int32_t)1 << (NUM_FRAC - 1);
        nx = (wnum)((e1.y * e2.z + h) >> NUM_FRAC) - (wnum)((e1.z * e2.y + h) >> NUM_FRAC);
        ny = (wnum)((e1.z * e2.x + h) >> NUM_FRAC) - (wnum)((e1.x * e2.z + h) >> NUM_FRAC);
        nz = (wnum)((e1.x * e2.y + h) >> NUM_FRAC) - (wnum)((e1.y * e2.x + h) >> NUM_FRAC);
    } else
#endif
    {
        nx = wnum_sub(num_mul_wide(e1.y, e2.z), num_mul_wide(e1.z, e2.y));
        ny = wnum_sub(num_mul_wide(e1.z, e2.x), num_mul_wide(e1.x, e2.z));
        nz = wnum_sub(num_mul_wide(e1.x, e2.y), num_mul_wide(e1.y, e2.x));
    }
    wnum f = wnum_mul(wnum_from_num(num_neg(a.x)), nx);
    f = wnum_add(f, wnum_mul(wnum_from_num(num_neg(a.y)), ny));
    f = wnum_add(f, wnum_mul(wnum_from_num(num_neg(a.z)), nz));
    return f > 0;
}

/* The rest of a triangle k of three projected corners pa, pb, pc of
 * doubled area `area` > 0 on screen (at most INT32_MAX: a larger one's
 * taken as that, which only leaves its facing to the camera-space test),
 * not a culled back face: its rows packed (ras_trows_pack), its facing
 * where lighting needs it, its flags and its count. (Out of line: the
 * triangles' loop keeps its registers for the culled ones.) */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static struct ras_trows tri_live(const struct tri_loop *L, uint32_t k, const struct ras_pv *pa,
                                 const struct ras_pv *pb, const struct ras_pv *pc, int32_t area)
{
    const struct ras_trows none = { 1, 0 };
    const int32_t ya = pa->sy, yb = pb->sy, yc = pc->sy, sb = L->sb;
    const int32_t lo = min3(ya, yb, yc), hi = max3(ya, yb, yc);
    /* sub_rows: one row of margin each side */
    int32_t r0 = (lo >> sb) - 1, r1 = (hi >> sb) + 1;
    if (r0 < 0) r0 = 0;
    if (r1 > L->hmax) r1 = L->hmax;
    if (r0 > r1) return none;
    const int32_t xa = pa->sx, d1x = pb->sx - xa, d1y = yb - ya, d2x = pc->sx - xa, d2y = yc - ya;
    const int32_t Ls = (d1x < 0 ? -d1x : d1x) + (d1y < 0 ? -d1y : d1y) + (d2x < 0 ? -d2x : d2x) +
                       (d2y < 0 ? -d2y : d2y);
    struct ras_ctx *rc = L->rc;
    /* (|d| < 2^16: Ls < 2^18, no overflow) */
    const int32_t margin = (int32_t)ras_front_margin(&rc->def.front, area, Ls);
    /* one whose area is clear of every rounding is a front face by the
     * camera-space test too (raster_num.h): that test is not made, nor
     * anything else where no lighting is kept */
    /* (one it leaves unknown in a culling pass takes cam_front: tri_facts'
     * decision without its call) */
    if (L->plain) {
        if (margin > L->fbound || ras_front_known(&rc->def.front, margin, pa->iz, pb->iz, pc->iz) ||
            (L->cull && cam_front(rc, L, &L->m->tris[k]))) {
            if (L->flags) L->flags[k] = (uint8_t)(RAS_TRI_LIVE | RAS_TRI_FRONT);
        } else if (L->cull) {
            if (L->flags) L->flags[k] = 0;
            return none;
        } else if (!ras_tri_cache(rc, L->in, L->ri, L->m, &L->m->tris[k], L->ri->tbase + k, L->part, 0))
            return none;
    } else {
        int known = L->ri->vlit && (margin > L->fbound ||
                                    ras_front_known(&rc->def.front, margin, pa->iz, pb->iz, pc->iz));
        if (L->ri->vlit && !known && L->cull) {
            if (!cam_front(rc, L, &L->m->tris[k])) {
                if (L->flags) L->flags[k] = 0;
                return none;
            }
            known = 1;
        }
        if (!ras_tri_cache(rc, L->in, L->ri, L->m, &L->m->tris[k], L->ri->tbase + k, L->part, known))
            return none;
    }
    rc->part_drawn[L->part]++;
    if (L->bins) {
        /* the strips visit it only on the rows whose pixel centres lie
         * within lo..hi (none when no centre does) */
        r0 = (lo + L->half - 1) >> sb;
        r1 = (hi - L->half) >> sb;
        if (r0 < 0) r0 = 0;
        if (r1 > L->hmax) r1 = L->hmax;
        if (r0 > r1) return none;
    }
    struct ras_trows p;
    p.r0 = (uint8_t)((uint32_t)r0 >> L->rshift);
    p.r1 = (uint8_t)((uint32_t)r1 >> L->rshift);
    return p;
}

/* Triangle k of instance i (its frame facts kept), as part `part` of the
 * frame's triangles: the rows the strips visit it on. (Inline: one call a
 * triangle less, half of them culled in a few instructions.) */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((always_inline))
#endif
static inline struct ras_range instance_triangle(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_model *m,
                                          const struct ras_inst *ri, uint32_t k, int part)
{
    const struct ras_options *o = &rc->s->ras;
    const uint32_t vb = ri->vbase, tb = ri->tbase;
    const struct ras_triangle *t = &m->tris[k];
    struct ras_range r = no_rows();
    if (!ri->visible || t->v[0] >= m->nverts || t->v[1] >= m->nverts || t->v[2] >= m->nverts) return r;
    if (FW_FEATURE_RAS_BOOK && (rc->book || o->wireframe)) {
        /* (these paths keep the camera-space table) */
        const struct ras_vert *a = &rc->verts[vb + t->v[0]], *b = &rc->verts[vb + t->v[1]],
                              *c = &rc->verts[vb + t->v[2]];
        if (o->clip && !ras_triangle_inside(a->c, b->c, c->c)) return r;
        if (!rc->book && !o->clip && (a->c.z <= rc->def.near_z || b->c.z <= rc->def.near_z || c->c.z <= rc->def.near_z))
            return r; /* default path, clipping off: never project behind the camera */
        num ys[3] = { rc->proj[vb + t->v[0]].py, rc->proj[vb + t->v[1]].py, rc->proj[vb + t->v[2]].py }, lo, hi;
        range3(ys, &lo, &hi);
        r = rows_of_canvas_y(rc, lo, hi);
        if (r.r0 > r.r1) return r;
        /* counted unless the book's culling will drop it (as ras_book_render_triangle decides) */
        if (rc->book && !o->wireframe && o->backface_cull &&
            ras_facing_wide(a->c, ras_face_normal_wide(a->c, b->c, c->c)) <= 0)
            return r;
        rc->part_drawn[part]++;
    } else if (FW_FEATURE_RAS_DEFAULT) {
        /* (a triangle of three projected corners takes tri_live, from
         * instance_triangles' loop: this is the clipper's) */
        struct ras_vcache *vc = part ? rc->def.vcache1 : rc->def.vcache;
        r = default_tri_rows(rc, ras_cam_vertex(rc, in, ri, m, t->v[0], vc), ras_cam_vertex(rc, in, ri, m, t->v[1], vc),
                             ras_cam_vertex(rc, in, ri, m, t->v[2], vc));
        if (r.r0 > r.r1) return r;
        /* what the strips visit: live triangles only (a culled or
         * degenerate one draws nothing) */
        if (!ras_tri_cache(rc, in, ri, m, t, tb + k, part, 0)) return no_rows();
        rc->part_drawn[part]++;
    }
    return r;
}

/* Triangles k0 .. k1 - 1 of instance i, as part `part` of the frame's
 * triangles: each writes only its own entries, its counts in part_in and
 * part_drawn, and the lighting of its vertices in its part's table. */
static void instance_triangles(struct ras_ctx *rc, uint16_t i, uint32_t k0, uint32_t k1, int part)
{
    const struct ras_instance *in = &rc->s->instances[i];
    const struct ras_model *m = &rc->s->models[in->model];
    const struct ras_inst *ri = &rc->inst[i];
    const uint32_t tb = ri->tbase;
    struct ras_trows *rows = rc->tri_rows;
    rc->part_in[part] += k1 - k0;
    /* ras_front_known's bound at the instance's nearest projected vertex,
     * where every one of them passes its iz_min: a margin above it is one
     * above every triangle's own bound (INT64_MAX: none) */
    int64_t fbound = INT64_MAX;
    if (FW_FEATURE_RAS_DEFAULT && rc->def.pv && rc->def.front.g1 && ri->visible) {
        const struct ras_pv *pv = rc->def.pv + ri->vbase;
        num lo = NUM_MAX, hi = 0;
        for (uint32_t v = 0; v < m->nverts; v++)
            if (ras_pv_in(&pv[v])) {
                if (pv[v].iz < lo) lo = pv[v].iz;
                if (pv[v].iz > hi) hi = pv[v].iz;
            }
        const uint64_t b = lo <= hi && lo >= rc->def.front.iz_min ? ras_front_bound(&rc->def.front, hi, hi, hi) : 0;
        if (b) fbound = (int64_t)b;
    }
    if (FW_FEATURE_RAS_DEFAULT && rc->def.pv && ri->visible && !(FW_FEATURE_RAS_BOOK && (rc->book || rc->s->ras.wireframe))) {
        /* instance_triangle's default path with what the loop reads held
         * in locals (its stores, bytes, would make every field read again),
         * a back face of three projected corners dropped here */
        const struct ras_pv *pv = rc->def.pv + ri->vbase;
        const struct ras_triangle *tris = m->tris;
        const uint32_t nv = m->nverts;
        const int cull = rc->s->ras.backface_cull;
        uint8_t *flags = rc->def.tri_flags ? rc->def.tri_flags + tb : NULL;
        struct ras_trows *rk = rows + tb;
        const struct ras_trows none = { 1, 0 };
        struct tri_loop tl;
        tl.rc = rc;
        tl.in = in;
        tl.m = m;
        tl.ri = ri;
        tl.fbound = fbound > INT32_MAX ? INT32_MAX : (int32_t)fbound;
        tl.flags = flags;
        tl.part = part;
        tl.plain = !ri->vlit && !rc->def.tri_shade;
        tl.cull = cull;
        tl.bins = rc->bins.on;
        tl.sb = rc->def.sub_bits;
        tl.half = (int32_t)1 << (tl.sb - 1);
        tl.hmax = (int32_t)rc->h - 1;
        tl.rshift = rc->row_shift;
        /* every projected corner lies within two pixels of the viewport
         * (raster_int.h), so on a render of at most 2^14 sub-pixel units
         * less 32 pixels a side their differences lie within +-2^14 and
         * the doubled area takes 32-bit products (pv_area's test, made
         * once) */
        const uint32_t side = rc->w > rc->h ? rc->w : rc->h;
        const int small = ((side + 32u) << tl.sb) <= 0x4000u;
        for (uint32_t k = k0; k < k1; k++) {
            const struct ras_triangle *t = &tris[k];
            const uint32_t a = t->v[0], b = t->v[1], c = t->v[2];
            if (a >= nv || b >= nv || c >= nv) {
                rk[k] = none;
                continue;
            }
            const struct ras_pv *pa = &pv[a], *pb = &pv[b], *pc = &pv[c];
            const int32_t xa = pa->sx, xb = pb->sx, xc = pc->sx;
            if (xa == RAS_PV_OUT || xb == RAS_PV_OUT || xc == RAS_PV_OUT) {
                rk[k] = ras_trows_pack(rc, instance_triangle(rc, in, m, ri, k, part));
                continue;
            }
            int32_t area32;
            if (small) {
                const int32_t ya = pa->sy;
                area32 = (xb - xa) * (pc->sy - ya) - (pb->sy - ya) * (xc - xa);
            } else {
                const int64_t area = pv_area(pa, pb, pc);
                area32 = area > INT32_MAX ? INT32_MAX : area < 0 ? -1 : (int32_t)area;
            }
            if (area32 <= 0) {
                if (cull) {
                    if (flags) flags[k] = 0;
                    rk[k] = none;
                    continue;
                }
                area32 = 0;   /* (no margin: the camera-space test decides) */
            }
            rk[k] = tri_live(&tl, k, pa, pb, pc, area32);
        }
        return;
    }
    for (uint32_t k = k0; k < k1; k++)
        rows[tb + k] = ras_trows_pack(rc, instance_triangle(rc, in, m, ri, k, part));
}

/* The live triangles of the frame sorted by the bucket of their first row
 * (struct ras_bins), stable, and the last row each bucket reaches. (What
 * the loops read held in locals; a bucket's reach kept as the packed last
 * row until the end, then ras_trows_last of it: the same where row_shift
 * is 0.) */
static void bin_triangles(struct ras_ctx *rc)
{
    struct ras_bins *B = &rc->bins;
    uint16_t *start = B->start, *order = B->order;
    int16_t *reach = B->reach;
    const struct ras_trows *rows = rc->tri_rows;
    const uint32_t nb = B->nbuckets, n = rc->ntris, sh = rc->row_shift;
    for (uint32_t b = 0; b <= nb; b++) start[b] = 0;
    for (uint32_t b = 0; b < nb; b++) reach[b] = -1;
    const uint32_t dm = B->div_mul, sr = rc->strip_rows;
    if (dm)
        for (uint32_t gi = 0; gi < n; gi++) {
            const uint32_t r0 = rows[gi].r0;
            if (r0 > rows[gi].r1) continue;
            start[(((r0 << sh) * dm) >> 16) + 1]++;
        }
    else
        for (uint32_t gi = 0; gi < n; gi++) {
            const uint32_t r0 = rows[gi].r0;
            if (r0 > rows[gi].r1) continue;
            start[(r0 << sh) / sr + 1]++;
        }
    for (uint32_t b = 1; b <= nb; b++) start[b] = (uint16_t)(start[b] + start[b - 1]);
    /* start[b] walks bucket b's run; afterwards it holds the run's end,
     * which is bucket b + 1's start */
    for (uint32_t gi = 0; gi < n; gi++) {
        const uint32_t r0 = rows[gi].r0, r1 = rows[gi].r1;
        if (r0 > r1) continue;
        const uint32_t f = r0 << sh, b = dm ? (f * dm) >> 16 : f / sr;
        order[start[b]++] = (uint16_t)gi;
        if ((int32_t)r1 > reach[b]) reach[b] = (int16_t)r1;
    }
    if (sh)
        for (uint32_t b = 0; b < nb; b++)
            if (reach[b] >= 0) reach[b] = (int16_t)((((uint32_t)reach[b] + 1u) << sh) - 1u);
    for (uint32_t b = nb; b > 0; b--) start[b] = start[b - 1];
    start[0] = 0;
}

int raster_frame_start(void *work, uint16_t frame)
{
    struct ras_ctx *rc = ras_ctx_of(work);
    if (rc->owner) return -1;
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
        rl->len = l->type == LIGHT_DIRECTIONAL ? v3_len(rl->v) : NUM_ZERO;
        rl->div = num_divisor_make(rl->len);
    }

    /* 2D primitives and 3D lines: rows they may touch */
    for (uint16_t i = 0; i < s->nprims; i++) {
        const struct prim2d *p = &s->prims[i];
        num ys[3] = { p->y[0], p->y[1], p->npts > 2 ? p->y[2] : p->y[1] }, lo, hi;
        range3(ys, &lo, &hi);
        rc->prim_rows[i] = rows_of_canvas_y(rc, ras_scale_canvas(rc, lo), ras_scale_canvas(rc, hi));
    }
    for (uint16_t i = 0; i < s->nlines; i++) {
        num ax, ay, bx, by;
        ras_project_vertex(rc, s->lines[i].a, &ax, &ay);
        ras_project_vertex(rc, s->lines[i].b, &bx, &by);
        rc->line_rows[i] = rows_of_canvas_y(rc, num_min(ay, by), num_max(ay, by));
    }

    for (uint16_t k = 0; k < rc->fast.nkeep; k++) rc->fast.keep[k].tri = UINT32_MAX;
    /* the caches of camera-space vertices start empty */
    for (uint32_t k = 0; rc->def.vcache && k <= rc->def.vcache_mask; k++) {
        rc->def.vcache[k].k = UINT32_MAX;
        if (rc->def.vcache1) rc->def.vcache1[k].k = UINT32_MAX;
    }

    /* RenderInstance, its frame half: every instance's matrices here, its
     * vertices in raster_frame_vertices, its triangles in raster_frame_triangles */
    uint32_t vb = 0, tb = 0;
    for (uint16_t i = 0; i < s->ninstances; i++) {
        const struct ras_model *m = &s->models[s->instances[i].model];
        instance_head(rc, i, frame, vb, tb);
        vb += m->nverts;
        tb += m->ntris;
    }
    rc->part_in[0] = rc->part_in[1] = rc->part_drawn[0] = rc->part_drawn[1] = 0;
    return 0;
}

/* Part `part` of `parts` equal ranges of n items numbered across the
 * instances (vertices or triangles): instance i's share, items k0 .. k1 - 1
 * of it (base, count: its first item and how many); 0 when it has none. */
static int part_slice(uint32_t n, unsigned part, unsigned parts, uint32_t base, uint32_t count, uint32_t *k0,
                      uint32_t *k1)
{
    const uint32_t lo = (uint32_t)((uint64_t)n * part / parts), hi = (uint32_t)((uint64_t)n * (part + 1) / parts);
    if (hi <= base || lo >= base + count) return 0;
    *k0 = lo > base ? lo - base : 0;
    *k1 = hi < base + count ? hi - base : count;
    return *k0 < *k1;
}

int raster_frame_vertices(const void *work, unsigned part, unsigned parts)
{
    const struct ras_ctx *rc = ras_ctx_of((void *)(uintptr_t)work);
    if (rc->owner) rc = rc->owner;   /* a sibling works on its owner's frame */
    if (parts == 0 || part >= parts) return -1;
    const struct scene *s = rc->s;
    uint32_t k0, k1;
    for (uint16_t i = 0; i < s->ninstances; i++)
        if (part_slice(rc->nverts, part, parts, rc->inst[i].vbase, s->models[s->instances[i].model].nverts, &k0, &k1))
            instance_vertices(rc, i, k0, k1);
    return 0;
}

int raster_frame_triangles(void *work, unsigned part, unsigned parts)
{
    struct ras_ctx *rc = ras_ctx_of(work);
    if (rc->owner) rc = (struct ras_ctx *)(uintptr_t)rc->owner;   /* the owner's frame */
    if (parts == 0 || parts > 2 || part >= parts) return -1;
    /* part 1 marks the vertices it lights in the sibling's table: one must be there */
    if (part == 1 && rc->def.vert_shade && !rc->def.vert_lit1) return -1;
    const struct scene *s = rc->s;
    rc->part_in[part] = rc->part_drawn[part] = 0;
    if (parts == 1) rc->part_in[1] = rc->part_drawn[1] = 0;
    uint32_t k0, k1;
    for (uint16_t i = 0; i < s->ninstances; i++)
        if (part_slice(rc->ntris, part, parts, rc->inst[i].tbase, s->models[s->instances[i].model].ntris, &k0, &k1))
            instance_triangles(rc, i, k0, k1, (int)part);
    return 0;
}

int raster_instance_facing(const void *work, uint16_t i, uint32_t *facing, uint32_t *culled)
{
    const struct ras_ctx *rc = ras_ctx_of((void *)(uintptr_t)work);
    if (rc->owner) rc = rc->owner;
    const struct scene *s = rc->s;
    *facing = *culled = 0;
    if (i >= s->ninstances) return -1;
    const struct ras_inst *ri = &rc->inst[i];
    if (!ri->visible) return 0;
    const struct ras_model *m = &s->models[s->instances[i].model];
    const int cull = s->ras.backface_cull && !s->ras.wireframe;
    for (uint32_t k = 0; k < m->ntris; k++) {
        const struct ras_triangle *t = &m->tris[k];
        if (t->v[0] >= m->nverts || t->v[1] >= m->nverts || t->v[2] >= m->nverts) continue;
        const struct ras_instance *in = &s->instances[i];
        vec3 a = ras_cam_vertex(rc, in, ri, m, t->v[0], NULL), b = ras_cam_vertex(rc, in, ri, m, t->v[1], NULL),
             c = ras_cam_vertex(rc, in, ri, m, t->v[2], NULL);
        struct ras_wnormal wf = ras_face_normal_wide(a, b, c);
        wnum f = ras_facing_wide(a, wf);
        if (f == 0 && wf.x == 0 && wf.y == 0 && wf.z == 0) continue;   /* degenerate */
        if (f <= 0 && cull) (*culled)++;
        else (*facing)++;
    }
    return 0;
}

int raster_frame_finish(void *work)
{
    struct ras_ctx *rc = ras_ctx_of(work);
    if (rc->owner) return -1;
    rc->tris_in = rc->part_in[0] + rc->part_in[1];
    rc->tris_drawn = rc->part_drawn[0] + rc->part_drawn[1];
    /* a strip's triangles take slots i mod nkeep: with many more of them
     * than slots, a set-up kept for the next strip is all but never found
     * there, and keeping it costs a copy (on: at most 2 nkeep triangles a
     * strip, strips counted as h / strip_rows rounded up) */
    rc->fast.keep_on = (uint8_t)(rc->fast.nkeep && (uint64_t)rc->tris_drawn * rc->strip_rows <=
                                                       (uint64_t)2u * rc->fast.nkeep * (rc->h + rc->strip_rows - 1u));
    if (rc->bins.on) bin_triangles(rc);
    if (FW_FEATURE_RAS_FAST_PHONG && rc->fast.phong) ras_fphong_frame(rc);
    if (FW_FEATURE_RAS_CH15) ras_ch15_frame(rc);
    return 0;
}

int raster_begin_frame(void *work, uint16_t frame)
{
    if (raster_frame_start(work, frame) != 0) return -1;
    (void)raster_frame_vertices(work, 0, 1);
    (void)raster_frame_triangles(work, 0, 1);
    return raster_frame_finish(work);
}
