/* SPDX-License-Identifier: MIT */
/* raster_default.c — the default path's RenderTriangle (book_exact = 0):
 * the triangle's facts (kept per frame where the scene allows), its
 * attributes, clipping at the planes and the sub-pixel projection, then
 * each triangle of the clipped fan through the fast span loops
 * (raster_fast.c) or the exact per-pixel fill (ras_fill_triangle with
 * ras_default_pixel). */
#include "raster_fast.h"
#include "num/num_int.h"

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

static int rgb_same(rgb a, rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

/* levels_q10 of c, remembered for the next triangle of the same colour. */
static int levels_memo(struct ras_ctx *rc, rgb c, struct ras_fast_tri *ft)
{
    struct ras_colour_memo *m = &rc->fast.memo;
    if (!m->kvalid || !rgb_same(m->ck, c)) {
        m->kok = (uint8_t)levels_q10(c, ft);
        m->kr = ft->kr;
        m->kg = ft->kg;
        m->kb = ft->kb;
        m->ck = c;
        m->kvalid = 1;
        return m->kok;
    }
    ft->kr = m->kr;
    ft->kg = m->kg;
    ft->kb = m->kb;
    return m->kok;
}

/* A flat colour's RGB565 and RGB888 forms, remembered for the next
 * triangle of the same colour. */
static inline __attribute__((always_inline)) void colour_memo(struct ras_ctx *rc, rgb c, struct ras_fast_tri *ft)
{
    struct ras_colour_memo *m = &rc->fast.memo;
    if (!m->valid || !rgb_same(m->c, c)) {
        m->c = c;
        m->c565 = rgb_to_565(c);
        rgb_to_888(c, m->c888);
        m->valid = 1;
    }
    ft->c565 = m->c565;
    ft->c888[0] = m->c888[0];
    ft->c888[1] = m->c888[1];
    ft->c888[2] = m->c888[2];
}

/* The fast span loops' description of a triangle; 0 when it needs the
 * exact per-pixel path (chapter 15 passes and normal maps, Phong without
 * fast Phong, trilinear or non-power-of-two textures, screen-linear uv,
 * textures under flat shading). */
static int fast_describe(struct ras_ctx *rc, const struct ras_def_tri *dt, struct ras_fast_tri *ft, ptrdiff_t inst)
{
    const struct ras_options *o = &rc->s->ras;
    if (!FW_FEATURE_RAS_FAST || !rc->fast.on || rc->cur.depth_only || rc->cur.depth_func != RAS_DEPTH_LESS_WRITE ||
        dt->nmap >= 0)
        return 0;
    int gour = dt->shading == SHADE_GOURAUD, phong = dt->shading == SHADE_PHONG;
    if (phong && (!rc->fast.phong || !rc->fast.fp.ok || rc->fast.inst_spec[inst] == -2)) return 0;
    ft->ai_i = dt->ai_i;
    ft->ai_uv = dt->ai_uv;
    if (phong) {
        ft->ai_n = dt->ai_n;
        ft->ai_p = dt->ai_p;
        ft->fp = &rc->fast.fp;
        int16_t st = rc->fast.inst_spec[inst];
        ft->spec = st >= 0 ? rc->fast.spec_tab + 257 * st : NULL;
        ft->spec_scale = st >= 0 ? rc->fast.spec_step[2 * st] : 0;
        ft->spec_umax = st >= 0 ? rc->fast.spec_step[2 * st + 1] : 0;
        if (dt->tex < 0) {
            ft->shade = SPAN_SHADE_PHONG;
            ft->src = SPAN_SRC_CONST;
            return levels_memo(rc, dt->color, ft);
        }
    }
    if (dt->tex >= 0) {
        const struct ras_tex565 *t5 = &rc->fast.tex565[dt->tex];
        if (!t5->p || !o->perspective_uv || dt->shading == SHADE_FLAT) return 0;
        ft->shade = (uint8_t)(phong ? SPAN_SHADE_PHONG : (gour ? SPAN_SHADE_LI : SPAN_SHADE_NONE));
        int bl = rc->s->textures[dt->tex].filter == TEX_BILINEAR;
        ft->src = bl ? (o->bl_weights ? SPAN_SRC_TEXBW : SPAN_SRC_TEXBL) : SPAN_SRC_TEX;
        ft->tex = t5->p;
        ft->wlog2 = t5->wlog2;
        ft->wmask = (1u << t5->wlog2) - 1;
        ft->hmask = (1u << t5->hlog2) - 1;
        /* nearest: u = 1 maps to the last texel's far edge less 2^-16,
         * clamping for u, v in [0, 1], repeating outside; bilinear: u times
         * the width (its loop clamps the texel indices) */
        ft->uscale = (int32_t)((1u << t5->wlog2) * 65536u - (bl ? 0u : 1u));
        ft->vscale = (int32_t)((1u << t5->hlog2) * 65536u - (bl ? 0u : 1u));
        return 1;
    }
    if (gour) {
        ft->shade = SPAN_SHADE_RGB;   /* (SPAN_SHADE_LI when a level may saturate) */
        ft->src = SPAN_SRC_CONST;
        return levels_memo(rc, dt->color, ft);
    }
    ft->shade = SPAN_SHADE_NONE;
    ft->src = SPAN_SRC_CONST;
    colour_memo(rc, dt->shading == SHADE_FLAT ? rgb_scale(dt->color, dt->flat_i) : dt->color, ft);
    return 1;
}

/* Camera-space corners, facing and (want_n) shading normals of a triangle
 * of the default path; 0 when it draws nothing (degenerate, or a culled
 * back face). */
static int tri_facts(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                     const struct ras_model *m, const struct ras_triangle *t, vec3 V[3], vec3 N[3], int *front,
                     int want_n, struct ras_vcache *vc)
{
    const struct ras_options *o = &rc->s->ras;
    for (int k = 0; k < 3; k++) V[k] = ras_cam_vertex(rc, in, ri, m, t->v[k], vc);
    struct ras_wnormal wf = ras_face_normal_wide(V[0], V[1], V[2]);
    wnum facing = ras_facing_wide(V[0], wf);
    if (facing == 0 && wf.x == 0 && wf.y == 0 && wf.z == 0) return 0; /* degenerate */
    *front = facing > 0;
    if (o->backface_cull && !*front) return 0;
    if (!want_n) return 1;
    int face_n = o->computed_normals || !m->has_normals;
    /* the default path's lighting takes the normal's direction only */
    vec3 nf = face_n ? ras_wnormal_narrow_dir(wf) : v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    for (int k = 0; k < 3; k++) N[k] = face_n ? nf : ras_corner_normal(ri, t->n[k]);
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
 * default_render_triangle would compute in each strip); 1 when it is live.
 * known: the caller found it a front face from its three projected corners
 * (ras_front_known; only where no face normals are wanted, below). */
int ras_tri_cache(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                  const struct ras_model *m, const struct ras_triangle *t, uint32_t gi, int part, int known)
{
    vec3 V[3], N[3];
    int front = 0;
    struct ras_vcache *vc = part ? rc->def.vcache1 : rc->def.vcache;
    const int want_n = !ri->vlit && rc->def.tri_shade;   /* (normals only for the lighting kept below) */
    if (known) {
        front = 1;
    } else if (!tri_facts(rc, in, ri, m, t, V, N, &front, want_n, vc)) {
        return ras_tri_flag(rc, gi, 0);
    }
    (void)ras_tri_flag(rc, gi, RAS_TRI_LIVE | (front ? RAS_TRI_FRONT : 0));
    if (ri->vlit) {
        /* each vertex lit once (per part), by the first live triangle that
         * uses it: its corners' normals are all the same, so is their
         * lighting; both parts store it in the same table (the same bits) */
        uint8_t *lit = part ? rc->def.vert_lit1 : rc->def.vert_lit;
        num *shade = rc->def.vert_shade;
        const struct ras_mlight *ml = rc->def.mlight ? &rc->def.mlight[ri - rc->inst] : NULL;
        if (ml && !ml->on) ml = NULL;
        for (int k = 0; k < 3; k++) {
            uint32_t v = ri->vbase + t->v[k];
            uint8_t bit = (uint8_t)(1u << (v & 7));
            if (lit[v >> 3] & bit) continue;
            lit[v >> 3] |= bit;
            if (ml) {
                shade[v] = ras_model_light(ml, t->n[k]);   /* (light_space = model) */
                continue;
            }
            const vec3 p = known ? ras_cam_vertex(rc, in, ri, m, t->v[k], vc) : V[k];
            shade[v] = ras_compute_illumination(rc, p, ras_corner_normal(ri, t->n[k]), in->specular);
        }
        return 1;
    }
    if (!rc->def.tri_shade) return 1;
    num *sh = rc->def.tri_shade + 3 * (size_t)gi;
    if (rc->def.shading == SHADE_GOURAUD)
        for (int k = 0; k < 3; k++) sh[k] = ras_compute_illumination(rc, V[k], N[k], in->specular);
    else
        sh[0] = ras_compute_illumination(rc, tri_centre(V), N[0], in->specular);
    return 1;
}

/* The rest of triangle gi begun in the strip above, from its kept set-up:
 * 1 when that drew it; *slot (NULL: none) is its slot either way. */
static int resume_kept(struct ras_ctx *rc, uint32_t gi, struct ras_fast_state **slot)
{
    *slot = NULL;
    /* (keep_on: slots there, nkeep > 0) */
    if (!FW_FEATURE_RAS_FAST || !rc->fast.keep_on || rc->cur.depth_only || rc->cur.depth_func != RAS_DEPTH_LESS_WRITE)
        return 0;
    *slot = &rc->fast.keep[gi & (rc->fast.nkeep - 1u)];
    uint32_t drawn;
    if ((*slot)->tri == gi && ras_fast_resume(rc, *slot, &drawn)) {
        rc->cur.st->pixels_written += drawn;
        return 1;
    }
    return 0;
}

/* Camera-space corners V, facing and normals N of triangle gi, from the
 * frame's cache where it has them (N then only when not shaded from the
 * cache); 0 when it draws nothing. Where the frame keeps no camera-space
 * table, a triangle of three projected corners takes none (its pixels need
 * only the projections: no Phong, no normal map there). */
static int corners(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                   const struct ras_model *m, const struct ras_triangle *t, uint32_t gi, int cached_shade, vec3 V[3],
                   vec3 N[3], int *front)
{
    *front = 0;
    if (!rc->def.pv) return tri_facts(rc, in, ri, m, t, V, N, front, 1, NULL);
    uint8_t f = ras_tri_flags(rc, gi);
    if (!(f & RAS_TRI_LIVE)) return 0;
    *front = (f & RAS_TRI_FRONT) != 0;
    /* unshaded triangles need no normals: the corners are all they take */
    if (!cached_shade && rc->def.shading != SHADE_NONE) return tri_facts(rc, in, ri, m, t, V, N, front, 1, NULL);
    const struct ras_pv *pv = rc->def.pv + ri->vbase;
    const int need = rc->verts || !ras_pv_in(&pv[t->v[0]]) || !ras_pv_in(&pv[t->v[1]]) || !ras_pv_in(&pv[t->v[2]]);
    for (int k = 0; k < 3; k++)
        V[k] = need ? ras_cam_vertex(rc, in, ri, m, t->v[k], NULL) : v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    return 1;
}

/* What the pixels of the triangle need: colour, shading, texture, and for
 * a normal map the tangents from this triangle's uv derivatives. */
static void describe(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_model *m,
                     const struct ras_triangle *t, const vec3 V[3], struct ras_def_tri *dt)
{
    const int sh = rc->def.shading;
    dt->color = t->color;
    dt->spec = in->specular;
    dt->shading = sh;
    dt->tex = (in->texture >= 0 && in->texture < rc->s->ntextures && m->has_uvs) ? in->texture : -1;
    dt->flat_i = NUM_ONE;
    dt->ai_i = dt->ai_n = dt->ai_uv = dt->ai_p = 0;
    dt->nmap = -1;
    if (sh == SHADE_PHONG && in->normal_map >= 0 && in->normal_map < rc->s->ntextures && m->has_uvs) {
        vec3 e1 = v3_sub(V[1], V[0]), e2 = v3_sub(V[2], V[0]);
        num du1 = num_sub(t->uv[1].u, t->uv[0].u), dv1 = num_sub(t->uv[1].v, t->uv[0].v);
        num du2 = num_sub(t->uv[2].u, t->uv[0].u), dv2 = num_sub(t->uv[2].v, t->uv[0].v);
        num det = num_sub(num_mul(du1, dv2), num_mul(du2, dv1));
        if (det != 0) {
            dt->nmap = in->normal_map;
            /* dP/du and dP/dv up to the common factor 1/det (its sign kept) */
            vec3 pu = v3_sub(v3_scale(e1, dv2), v3_scale(e2, dv1));
            vec3 pv = v3_sub(v3_scale(e2, du1), v3_scale(e1, du2));
            if (det < 0) { pu = v3_neg(pu); pv = v3_neg(pv); }
            dt->tan_u = v3_normalize(pu);
            dt->tan_v = v3_normalize(v3_neg(pv));
        }
    }
}

/* The corners' attributes in cin (their slots in dt), and the flat
 * intensity; shade: the frame's lighting of the triangle, or NULL. Returns
 * the attribute count. */
static int attributes(const struct ras_ctx *rc, struct ras_def_tri *dt, const struct ras_triangle *t,
                      const vec3 V[3], const vec3 N[3], const num *shade, struct ras_cv cin[3])
{
    const int sh = dt->shading;
    int na = 0;
    if (sh == SHADE_GOURAUD) dt->ai_i = na++;
    if (sh == SHADE_PHONG) { dt->ai_n = na; na += 3; }
    /* fast Phong also needs the camera-space position at each pixel */
    if (sh == SHADE_PHONG && rc->fast.phong) { dt->ai_p = na; na += 3; }
    int uv = dt->tex >= 0 || dt->nmap >= 0;
    if (uv) { dt->ai_uv = na; na += 2; }
    for (int k = 0; k < 3; k++) {
        cin[k].p = V[k];
        if (sh == SHADE_GOURAUD)
            cin[k].a[dt->ai_i] = shade ? shade[k] : ras_compute_illumination(rc, V[k], N[k], dt->spec);
        if (sh == SHADE_PHONG) {
            vec3 n = v3_normalize(N[k]);
            cin[k].a[dt->ai_n] = n.x; cin[k].a[dt->ai_n + 1] = n.y; cin[k].a[dt->ai_n + 2] = n.z;
            if (rc->fast.phong) { cin[k].a[dt->ai_p] = V[k].x; cin[k].a[dt->ai_p + 1] = V[k].y; cin[k].a[dt->ai_p + 2] = V[k].z; }
        }
        if (uv) { cin[k].a[dt->ai_uv] = t->uv[k].u; cin[k].a[dt->ai_uv + 1] = t->uv[k].v; }
    }
    if (sh == SHADE_FLAT) dt->flat_i = shade ? shade[0] : ras_compute_illumination(rc, tri_centre(V), N[0], dt->spec);
    return na;
}

/* The triangle's corners on screen, clockwise, in sv: its three
 * projections of this frame when they lie inside every plane, else the
 * clipped polygon projected. Returns the corner count (< 3: nothing). */
static int screen_corners(const struct ras_ctx *rc, const struct ras_inst *ri, const struct ras_triangle *t,
                          int front, const struct ras_cv cin[3], int na, struct ras_sv sv[RAS_CLIP_MAX])
{
    const struct ras_pv *pv = rc->def.pv ? rc->def.pv + ri->vbase : NULL;
    if (pv && ras_pv_in(&pv[t->v[0]]) && ras_pv_in(&pv[t->v[1]]) && ras_pv_in(&pv[t->v[2]])) {
        /* inside every plane: the clipper would return the corners as they
         * are; their projections were made once this frame */
        for (int k = 0; k < 3; k++) {
            int c = front ? k : 2 - k;
            const struct ras_pv *q = &pv[t->v[c]];
            sv[k].x = q->sx;
            sv[k].y = q->sy;
            sv[k].iz = q->iz;
            sv[k].depth = q->depth;
            for (int j = 0; j < na; j++) sv[k].a[j] = cin[c].a[j];
        }
        return 3;
    }
    struct ras_cv poly[RAS_CLIP_MAX];
    int n = ras_clip_triangle(rc, cin, na, poly);
    if (n < 3) return n;
    for (int k = 0; k < n; k++) {
        /* back faces (culling off) are drawn with their corners reversed */
        const struct ras_cv *c = &poly[front ? k : n - 1 - k];
        ras_project_sub_depth(rc, c->p, &sv[k].x, &sv[k].y, &sv[k].iz, &sv[k].depth);
        for (int j = 0; j < na; j++) sv[k].a[j] = c->a[j];
    }
    return n;
}

/* The triangle's description, attributes and corners on screen (sv,
 * clockwise) where its three corners are projected and its pixels need no
 * camera-space position (no Phong, so no normal map either) and its
 * lighting is the frame's (shade) or none: what corners, describe,
 * attributes and screen_corners give, without the camera-space corners.
 * Returns the attribute count. */
static int projected_corners(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_model *m,
                             const struct ras_triangle *t, int front, const struct ras_pv *pv, const num *shade,
                             struct ras_def_tri *dt, struct ras_sv sv[3])
{
    describe(rc, in, m, t, NULL, dt);
    const int sh = dt->shading, uv = dt->tex >= 0;
    int na = 0;
    if (sh == SHADE_GOURAUD) dt->ai_i = na++;
    if (uv) { dt->ai_uv = na; na += 2; }
    if (sh == SHADE_FLAT) dt->flat_i = shade[0];
    for (int k = 0; k < 3; k++) {
        const int c = front ? k : 2 - k;
        const struct ras_pv *q = &pv[t->v[c]];
        sv[k].x = q->sx;
        sv[k].y = q->sy;
        sv[k].iz = q->iz;
        sv[k].depth = q->depth;
        if (sh == SHADE_GOURAUD) sv[k].a[dt->ai_i] = shade[c];
        if (uv) { sv[k].a[dt->ai_uv] = t->uv[c].u; sv[k].a[dt->ai_uv + 1] = t->uv[c].v; }
    }
    return na;
}

/* Trilinear filtering's level of detail for fan triangle a b c: texels^2
 * per pixel at depth 1/iz_eff. */
static void trilinear_lod(const struct ras_ctx *rc, const struct ras_texture *tx, struct ras_def_tri *dt,
                          const struct ras_sv *a, const struct ras_sv *b, const struct ras_sv *c)
{
    int64_t area = (int64_t)(b->x - a->x) * (c->y - a->y) - (int64_t)(b->y - a->y) * (c->x - a->x);
    num du1 = num_sub(b->a[dt->ai_uv], a->a[dt->ai_uv]), dv1 = num_sub(b->a[dt->ai_uv + 1], a->a[dt->ai_uv + 1]);
    num du2 = num_sub(c->a[dt->ai_uv], a->a[dt->ai_uv]), dv2 = num_sub(c->a[dt->ai_uv + 1], a->a[dt->ai_uv + 1]);
    num uv2 = num_abs(num_sub(num_mul(du1, dv2), num_mul(du2, dv1)));
    if (area > 0) {
        num k2 = ras_ratio(((int64_t)tx->w * tx->h) << (2 * rc->def.sub_bits), area);
        dt->lod_base = num_mul(uv2, k2);
    }
    dt->iz_eff = num_div_int(num_add(num_add(a->iz, b->iz), c->iz), 3);
}

int ras_default_lean(const struct ras_ctx *rc)
{
    const int sh = rc->def.shading;
    /* the fast loops take the pass, no set-up is kept between strips, and
     * every triangle the strips visit is a live front face (no flag byte:
     * back faces culled) */
    return FW_FEATURE_RAS_FAST && rc->fast.on && !rc->fast.keep_on && !rc->cur.depth_only &&
           rc->cur.depth_func == RAS_DEPTH_LESS_WRITE && rc->def.pv && !rc->def.tri_flags &&
           (sh == SHADE_NONE || sh == SHADE_FLAT || sh == SHADE_GOURAUD);
}

/* A projected corner's screen position and depth for the fast loops (its
 * 1/z left unset: they do not read it). */
static inline void sv_from_pv(struct ras_sv *sv, const struct ras_pv *q)
{
    sv->x = q->sx;
    sv->y = q->sy;
    sv->depth = q->depth;
}

/* ras_default_render_triangle of an untextured triangle of three projected
 * corners lit by the frame (or unlit) where rc->cur.lean: what
 * projected_corners and fast_describe give (clockwise corners: a front
 * face), straight to the fast loops. 0 when it does not apply or the fast
 * loops decline it (nothing drawn: the full path then takes it). */
static int render_lean(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                       const struct ras_model *m, const struct ras_triangle *t, uint32_t gi)
{
    if (in->texture >= 0 && in->texture < rc->s->ntextures && m->has_uvs) return 0;
    const struct ras_pv *pv = rc->def.pv + ri->vbase;
    const uint32_t v0 = t->v[0], v1 = t->v[1], v2 = t->v[2];
    const struct ras_pv *q0 = &pv[v0], *q1 = &pv[v1], *q2 = &pv[v2];
    if (!ras_pv_in(q0) || !ras_pv_in(q1) || !ras_pv_in(q2)) return 0;
    struct ras_sv sv[3];
    struct ras_fast_tri ft;
    sv_from_pv(&sv[0], q0);
    sv_from_pv(&sv[1], q1);
    sv_from_pv(&sv[2], q2);
    ft.src = SPAN_SRC_CONST;
    ft.ai_i = ft.ai_uv = 0;
    const int sh = rc->def.shading;
    if (sh == SHADE_GOURAUD) {
        if (ri->vlit) {
            const num *vs = rc->def.vert_shade + ri->vbase;
            sv[0].a[0] = vs[v0];
            sv[1].a[0] = vs[v1];
            sv[2].a[0] = vs[v2];
        } else if (rc->def.tri_shade) {
            const num *ts = rc->def.tri_shade + 3 * (size_t)gi;
            sv[0].a[0] = ts[0];
            sv[1].a[0] = ts[1];
            sv[2].a[0] = ts[2];
        } else {
            return 0;
        }
        ft.shade = SPAN_SHADE_RGB;
        if (!levels_memo(rc, t->color, &ft)) return 0;
    } else {
        rgb c = t->color;
        if (sh == SHADE_FLAT) {
            num fi;
            if (ri->vlit) fi = rc->def.vert_shade[ri->vbase + v0];
            else if (rc->def.tri_shade) fi = rc->def.tri_shade[3 * (size_t)gi];
            else return 0;
            c = rgb_scale(c, fi);
        }
        ft.shade = SPAN_SHADE_NONE;
        colour_memo(rc, c, &ft);
    }
    const int32_t drawn = ras_fast_fill(rc, &sv[0], &sv[1], &sv[2], &ft, NULL);
    if (drawn < 0) return 0;
    rc->cur.st->pixels_written += (uint32_t)drawn;
    return 1;
}

/* RenderTriangle of the default path: the triangle's corners (the frame's
 * cache), attributes, clipping and projection, then the fan of its
 * polygon, each by the fast span loops where they take it (ft) and by the
 * exact per-pixel path otherwise. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static void render_full(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                        const struct ras_model *m, const struct ras_triangle *t, uint32_t gi)
{
    struct ras_fast_state *slot;
    if (resume_kept(rc, gi, &slot)) return;
    vec3 V[3], N[3];
    int front;
    num vsh[3];
    const num *shade = rc->def.tri_shade ? rc->def.tri_shade + 3 * (size_t)gi : NULL;
    if (ri->vlit) {
        const num *vs = rc->def.vert_shade;
        for (int k = 0; k < 3; k++) vsh[k] = vs[ri->vbase + t->v[k]];
        shade = vsh;
    }
    struct ras_def_tri dt;
    struct ras_sv sv[RAS_CLIP_MAX];
    int n, na;
    const struct ras_pv *pv = rc->def.pv ? rc->def.pv + ri->vbase : NULL;
    if (pv && rc->def.shading != SHADE_PHONG && (shade || rc->def.shading == SHADE_NONE) &&
        ras_pv_in(&pv[t->v[0]]) && ras_pv_in(&pv[t->v[1]]) && ras_pv_in(&pv[t->v[2]])) {
        const uint8_t f = ras_tri_flags(rc, gi);
        if (!(f & RAS_TRI_LIVE)) return;
        na = projected_corners(rc, in, m, t, (f & RAS_TRI_FRONT) != 0, pv, shade, &dt, sv);
        n = 3;
    } else {
        if (!corners(rc, in, ri, m, t, gi, shade != NULL, V, N, &front)) return;
        describe(rc, in, m, t, V, &dt);
        struct ras_cv cin[3];
        na = attributes(rc, &dt, t, V, N, shade, cin);
        n = screen_corners(rc, ri, t, front, cin, na, sv);
        if (n < 3) return;
    }
    const struct ras_texture *tx = dt.tex >= 0 ? &rc->s->textures[dt.tex] : NULL;
    int uv = dt.tex >= 0 || dt.nmap >= 0;
    struct ras_fast_tri ft;
    int fast = fast_describe(rc, &dt, &ft, ri - rc->inst);
    for (int k = 1; k + 1 < n; k++) {
        const struct ras_sv *a = &sv[0], *b = &sv[k], *c = &sv[k + 1];
        if (fast) {
            /* an unclipped triangle's set-up is kept for the strips below */
            struct ras_fast_state *k1 = n == 3 ? slot : NULL;
            if (k1) k1->tri = gi;
            int32_t drawn = ras_fast_fill(rc, a, b, c, &ft, k1);
            if (drawn >= 0) { rc->cur.st->pixels_written += (uint32_t)drawn; continue; }
            if (k1) k1->tri = UINT32_MAX;
        }
        dt.lod_base = NUM_ZERO;
        dt.iz_eff = NUM_ONE;
        if (tx && tx->filter == TEX_TRILINEAR) trilinear_lod(rc, tx, &dt, a, b, c);
        rc->def.affine_from = (int8_t)(uv && !rc->s->ras.perspective_uv ? dt.ai_uv : -1);
        ras_fill_triangle(rc, a, b, c, na, rc->cur.depth_only ? NULL : ras_default_pixel, &dt);
    }
}

/* (render_full apart: a lean triangle's call sets up none of its frame) */
void ras_default_render_triangle(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                                 const struct ras_model *m, const struct ras_triangle *t, uint32_t gi)
{
    if (rc->cur.lean && render_lean(rc, in, ri, m, t, gi)) return;
    render_full(rc, in, ri, m, t, gi);
}
