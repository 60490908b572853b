/* SPDX-License-Identifier: MIT */
/* raster_work.c — the rasterizer's work memory and render_init: which
 * paths a scene takes, the layout of every table (one carve, run to measure
 * and to place), the render size's viewport and clipping planes, the
 * textures' mip chains and RGB565 copies. */
#include <string.h>
#include "raster_int.h"
#include "work.h"
#include "mipmap.h"

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

/* Bytes of the copy of texture t the fast path samples: nearest (RGB565,
 * 2 bytes a texel) or bilinear (mip_fast_bilinear_size: 8 bytes a texel, a border; with
 * bilinear_weights = coarse mip_fast_bilinear_word_size, 4 bytes a texel) filtering,
 * power-of-two sides, at most 2^15 texels (a byte offset of 16 bits); 0
 * when it does not qualify. */
static size_t tex565_size(const struct scene *s, const struct ras_texture *t)
{
    if (!fast_path(s) || (t->filter != TEX_NEAREST && t->filter != TEX_BILINEAR) || !t->rgb) return 0;
    if (log2_exact(t->w) < 0 || log2_exact(t->h) < 0 || log2_exact(t->w) + log2_exact(t->h) > 15) return 0;
    if (t->filter != TEX_BILINEAR) return (size_t)t->w * t->h * 2;
    return s->ras.bl_weights ? mip_fast_bilinear_word_size(t->w, t->h) : mip_fast_bilinear_size(t->w, t->h);
}

/* Texture i's texels made by scenec (in flash), or NULL. */
static const void *tex_fast(const struct scene *s, uint16_t i) { return s->tex_fast ? s->tex_fast[i] : NULL; }

/* Of which work memory: none when scenec made them. */
static size_t tex565_work(const struct scene *s, uint16_t i)
{
    return tex_fast(s, i) ? 0 : tex565_size(s, &s->textures[i]);
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
 * (at most RASTER_SPEC_MAX; more take the exact path). idx (if not NULL)
 * receives each instance's table: -1 no highlight, -2 none left. */
#define RAS_SPEC_MAX RASTER_SPEC_MAX
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

uint16_t raster_spec_exponents(const struct scene *s, uint32_t exps[RASTER_SPEC_MAX])
{
    return s->kind == SCENE_RASTER ? spec_exponents(s, NULL, exps) : 0;
}

void raster_spec_table(uint16_t t[257], uint32_t e, uint32_t step[2]) { ras_spec_table(t, e, step); }

/* The scene's own specular tables (scenec's, in flash) for its nspec
 * exponents: no copies in work memory. */
static int spec_given(const struct scene *s, uint16_t nspec)
{
    return nspec && s->spec_tab && s->spec_step && s->nspec == nspec;
}

static uint32_t scene_count(const struct scene *s, int verts);

/* Camera-space vertices kept a frame (ras_ctx.verts, 12 bytes a vertex in
 * fixed point): what the book path, wireframes, Phong and chapter 15 read
 * in every strip. The default path's other shadings read them only in the
 * frame's culling and lighting and for triangles it clips: for scenes of
 * more than RAS_CAM_TABLE_VERTS vertices (a mesh whose table would not fit
 * an RP2040's work memory beside the rest) it transforms them again there
 * (ras_cam_vertex), through a direct-mapped cache of at most RAS_VCACHE_MAX
 * vertices per part of the preparation, at the cost of about one more
 * transform for each vertex of a front face (bench/knot-16k-flat: 6 % of
 * its frame on the M0+). */
#define RAS_CAM_TABLE_VERTS 4096
#define RAS_VCACHE_MAX 256
static int cam_table(const struct scene *s)
{
    return !frame_cache(s) || eff_shading(s) == SHADE_PHONG || ch15_lit(&s->ras) ||
           scene_count(s, 1) <= RAS_CAM_TABLE_VERTS;
}

static uint32_t vcache_entries(const struct scene *s, uint32_t nverts)
{
    if (cam_table(s) || nverts == 0) return 0;
    uint32_t n = 1;
    while (n < nverts && n < RAS_VCACHE_MAX) n *= 2;
    return n;
}

static int shade_cache(const struct scene *s)
{
    return frame_cache(s) && (eff_shading(s) == SHADE_GOURAUD || eff_shading(s) == SHADE_FLAT);
}

/* An instance whose Gouraud corners are lit once per vertex: its model's
 * normals are the vertices' own (struct ras_model.vertex_normals), so a
 * vertex's corners would all get the same lighting. */
int ras_vertex_lit(const struct scene *s, const struct ras_instance *in)
{
    const struct ras_model *m = &s->models[in->model];
    return shade_cache(s) && eff_shading(s) == SHADE_GOURAUD && !s->ras.computed_normals && m->has_normals &&
           m->vertex_normals;
}

/* Which lighting caches the scene's instances need: bit 0 per corner (a
 * triangle's three values), bit 1 per vertex. */
static int shade_caches(const struct scene *s)
{
    int need = 0;
    if (!shade_cache(s)) return 0;
    for (uint16_t i = 0; i < s->ninstances; i++) need |= ras_vertex_lit(s, &s->instances[i]) ? 2 : 1;
    return need;
}

/* Triangle set-ups the fast path keeps from one strip to the next: a
 * power of two of slots, one a triangle up to RAS_KEEP_MAX (triangle i in
 * slot i mod slots, a mask). A frame uses them only when its strips draw
 * at most twice as many triangles as there are slots (raster_frame_finish);
 * a scene of more than twice that many triangles (a closed mesh draws
 * about half of its own, the others facing away) has none. */
#define RAS_KEEP_MAX 16
static uint16_t keep_slots(const struct scene *s, uint32_t ntris, uint16_t h, uint16_t strip_rows)
{
    if (!fast_path(s) || ntris == 0) return 0;
    if ((uint64_t)ntris * strip_rows > (uint64_t)4u * RAS_KEEP_MAX * ((uint32_t)h + strip_rows - 1u)) return 0;
    uint16_t n = 1;
    while (n < ntris && n < RAS_KEEP_MAX) n = (uint16_t)(n * 2);
    return n;
}

/* The tables a strip writes (its depth buffer, the runs it merges,
 * the set-ups kept between strips, the stencil): the whole of a sibling
 * context's own memory (struct ras_own), the last of an owner's. */
static void carve_strip_tables(const struct scene *s, uint16_t w, uint16_t h, uint16_t strip_rows, uint32_t ntris,
                               struct ras_ctx *rc, struct work_carve *c)
{
    rc->bins.runs = work_take(c, rc->bins.on ? sizeof(uint16_t) * 2 * rc->bins.nbuckets : 0);
    rc->fast.nkeep = keep_slots(s, ntris, h, strip_rows);
    void *keep = work_take(c, sizeof(struct ras_fast_state) * rc->fast.nkeep);
    rc->fast.keep = rc->fast.nkeep ? keep : NULL;
    rc->depth = work_take(c, (size_t)depth_bytes(s) * w * strip_rows);
    rc->c15.stencil = work_take(c, ras_ch15_stencil_size(s, w, strip_rows));
}

/* The binning of the default path's triangles to strips (struct ras_bins):
 * for scenes of at most 65535 triangles (16-bit indices). */
static int bins_on(const struct scene *s, uint32_t ntris)
{
    return frame_cache(s) && ntris > 0 && ntris <= 0xFFFFu;
}

/* Its buckets: one a strip_rows rows. */
static uint16_t bins_count(int on, uint16_t h, uint16_t strip_rows)
{
    return (uint16_t)(on && strip_rows ? (h + strip_rows - 1) / strip_rows : 0);
}

/* Every table of the state, in order, from c (c->base NULL: measuring, rc a
 * scratch context). The instances' models are checked first: -1 when one
 * is missing. */
static int carve(const struct scene *s, uint16_t w, uint16_t h, uint16_t strip_rows, struct ras_ctx *rc,
                 struct work_carve *c)
{
    uint32_t nverts = 0, ntris = 0;
    for (uint16_t i = 0; i < s->ninstances; i++) {
        if (s->instances[i].model >= s->nmodels) return -1;
        const struct ras_model *m = &s->models[s->instances[i].model];
        nverts += m->nverts;
        ntris += m->ntris;
    }
    rc->nverts = nverts;
    rc->ntris = ntris;
    (void)work_take(c, sizeof(struct ras_ctx));   /* the context itself, first */
    rc->inst = work_take(c, sizeof(struct ras_inst) * s->ninstances);
    void *verts = work_take(c, cam_table(s) ? sizeof(struct ras_vert) * nverts : 0);
    rc->verts = cam_table(s) ? verts : NULL;
    uint32_t nvc = vcache_entries(s, nverts);
    void *vc = work_take(c, sizeof(struct ras_vcache) * nvc);
    rc->def.vcache = nvc ? vc : NULL;
    rc->def.vcache_mask = (uint16_t)(nvc ? nvc - 1 : 0);
    void *proj = work_take(c, frame_cache(s) ? 0 : sizeof(struct ras_proj) * nverts);
    rc->proj = frame_cache(s) ? NULL : proj;
    rc->tri_rows = work_take(c, sizeof(struct ras_trows) * ntris);
    rc->prim_rows = work_take(c, sizeof(struct ras_range) * s->nprims);
    rc->line_rows = work_take(c, sizeof(struct ras_range) * s->nlines);
    rc->lights = work_take(c, sizeof(struct ras_light) * s->nlights);
    rc->def.mips = work_take(c, sizeof(struct ras_mips) * s->ntextures);
    rc->def.mip_mem = c->base ? c->base + c->off : NULL;    /* the chains, texture by texture */
    if (!s->ras.book_exact)
        for (uint16_t i = 0; i < s->ntextures; i++) (void)work_take(c, ras_mips_size(&s->textures[i]));
    rc->fast.tex565 = work_take(c, sizeof(struct ras_tex565) * s->ntextures);
    rc->fast.tex_mem = c->base ? c->base + c->off : NULL;   /* the RGB565 copies, the same way */
    for (uint16_t i = 0; i < s->ntextures; i++) (void)work_take(c, tex565_work(s, i));
    void *pv = work_take(c, frame_cache(s) ? sizeof(struct ras_pv) * nverts : 0);
    const int tflags = frame_cache(s) && !s->ras.backface_cull;   /* (struct ras_def.tri_flags) */
    void *flags = work_take(c, tflags ? ntris : 0);
    int caches = shade_caches(s);
    void *shade = work_take(c, (caches & 1) ? sizeof(num) * 3 * ntris : 0);
    void *vshade = work_take(c, (caches & 2) ? sizeof(num) * nverts : 0);
    void *vlit = work_take(c, (caches & 2) ? (nverts + 7) / 8 : 0);
    const int mlight = (caches & 2) && s->ras.light_space;
    void *ml = work_take(c, mlight ? sizeof(struct ras_mlight) * s->ninstances : 0);
    rc->def.pv = frame_cache(s) ? pv : NULL;
    rc->def.tri_flags = tflags ? flags : NULL;
    rc->def.tri_shade = (caches & 1) ? shade : NULL;
    rc->def.vert_shade = (caches & 2) ? vshade : NULL;
    rc->def.vert_lit = (caches & 2) ? vlit : NULL;
    rc->def.mlight = mlight ? ml : NULL;
    int bins = bins_on(s, ntris);
    rc->bins.on = (uint8_t)bins;
    rc->bins.nbuckets = bins_count(bins, h, strip_rows);
    rc->bins.order = work_take(c, bins ? sizeof(uint16_t) * ntris : 0);
    rc->bins.start = work_take(c, bins ? sizeof(uint16_t) * ((size_t)rc->bins.nbuckets + 1) : 0);
    rc->bins.reach = work_take(c, sizeof(int16_t) * rc->bins.nbuckets);
    uint16_t nspec = spec_exponents(s, NULL, NULL), made = spec_given(s, nspec) ? 0 : nspec;
    rc->fast.spec_tab = work_take(c, sizeof(uint16_t) * 257 * made);
    rc->fast.spec_step = work_take(c, sizeof(uint32_t) * 2 * made);
    rc->fast.inst_spec = work_take(c, sizeof(int16_t) * s->ninstances);
    rc->c15.adj = work_take(c, ras_ch15_adj_size(s, ntris));
    rc->c15.smap = work_take(c, ras_ch15_smap_size(s));
    carve_strip_tables(s, w, h, strip_rows, ntris, rc, c);
    return 0;
}

size_t raster_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows)
{
    struct ras_ctx scratch;
    struct work_carve c = { NULL, 0 };
    if (carve(s, width, height, strip_rows, &scratch, &c)) return 0;
    return c.off + WORK_ALIGN; /* slack to align the caller's pointer */
}

static wnum wabs(wnum a) { return a < 0 ? wnum_sub(wnum_from_num(NUM_ZERO), a) : a; }

/* The same normal's direction in num: narrowed as it is when every
 * component is under NUM_MAX / 2 (the same bits), else all three shifted
 * right by the same power of two until they are (a triangle larger than
 * the format's square: its length saturated, and with it the direction).
 * Here, not in raster_project.c: called only for lit triangles with
 * computed normals, it stays out of the SRAM that RP2040_RAM_TEXT=raster
 * fills. */
vec3 ras_wnormal_narrow_dir(struct ras_wnormal n)
{
    wnum m = wabs(n.x), lim = wnum_from_num(NUM_MAX / 2);
    if (wabs(n.y) > m) m = wabs(n.y);
    if (wabs(n.z) > m) m = wabs(n.z);
    if (m < lim) return ras_wnormal_narrow(n);
    int k = 0;
    while (m >= lim && k < 62) {
        m /= 2;
        k++;
    }
    return v3_make(wnum_to_num_shr(n.x, k), wnum_to_num_shr(n.y, k), wnum_to_num_shr(n.z, k));
}

/* sqrt(1 + s^2) of a clip plane's side slope s: as num forms it where s^2
 * fits (the same bits), else |s| sqrt(1 + (1/s)^2) (a view wider than about
 * 2 atan(sqrt(NUM_MAX / 2)) squares its side past the format). */
static num side_k(num s)
{
    if (num_mul_wide(s, s) < wnum_from_num(NUM_MAX / 2)) return num_sqrt(num_add(NUM_ONE, num_mul(s, s)));
    num r = num_div(NUM_ONE, s);
    return num_mul(num_abs(s), num_sqrt(num_add(NUM_ONE, num_mul(r, r))));
}

/* The render size's canvas: viewport height kept, width by aspect; the
 * default path's clipping planes. */
static void init_viewport(struct ras_ctx *rc)
{
    const struct scene *s = rc->s;
    rc->cw = num_from_int(rc->w);
    rc->vh = s->viewport_h;
    /* Vh W / H and W d / Vw with the products kept wide: a wide viewport
     * (Vh W) or a far projection plane (W d) may pass the format where the
     * quotients do not (the format analysis bounds the quotients) */
    rc->vw = wnum_div(num_mul_wide(s->viewport_h, num_from_int(rc->w)), wnum_from_num(num_from_int(rc->h)));
    rc->d = s->projection_d;
    rc->unproj = ras_mul_div(rc->cw, rc->d, rc->vw);
    rc->scale2d = num_from_ratio(rc->h, s->canvas_h);
    rc->def.near_z = rc->d;
    /* side planes two pixels outside the viewport: the guard band keeps
     * rounded clip points from landing inside the image edge */
    rc->def.side_x = num_div(num_add(num_mul(rc->vw, NUM_HALF), num_div_int(num_mul_int(rc->vw, 2), rc->w)), rc->d);
    rc->def.side_y = num_div(num_add(num_mul(rc->vh, NUM_HALF), num_div_int(num_mul_int(rc->vh, 2), rc->h)), rc->d);
    rc->def.side_xk = side_k(rc->def.side_x);
    rc->def.side_yk = side_k(rc->def.side_y);
    ras_front_init(&rc->def.front, rc->unproj, rc->def.near_z, rc->w, rc->h, rc->def.sub_bits);
}

/* Each texture's mip chain (default path) and RGB565 copy (fast path), in
 * the memory carve() set aside. */
static void init_textures(struct ras_ctx *rc)
{
    const struct scene *s = rc->s;
    uint8_t *mm = rc->def.mip_mem;
    for (uint16_t i = 0; i < s->ntextures; i++) {
        size_t n = rc->book ? 0 : ras_mips_size(&s->textures[i]);
        ras_mips_build(&s->textures[i], &rc->def.mips[i], n ? mm : NULL);
        mm += work_round(n);
    }
    uint8_t *tm = rc->fast.tex_mem;
    for (uint16_t i = 0; i < s->ntextures; i++) {
        const struct ras_texture *tx = &s->textures[i];
        size_t n = tex565_size(s, tx);
        rc->fast.tex565[i].p = NULL;
        if (!n) continue;
        const void *made = tex_fast(s, i);   /* by scenec, in flash: no copy */
        if (made) {
            rc->fast.tex565[i].p = made;
        } else {
            /* (the builders only in an image with their span loops:
             * render_init refuses a scene whose loops it lacks) */
            if (tx->filter == TEX_BILINEAR && s->ras.bl_weights) {
                if (FW_FEATURE_SPAN_NONE_TEXBW || FW_FEATURE_SPAN_LI_TEXBW || FW_FEATURE_SPAN_PHONG_TEXBW)
                    mip_fast_bilinear_word(tx->rgb, tx->w, tx->h, (uint32_t *)(void *)tm);
            } else if (tx->filter == TEX_BILINEAR) {
                if (FW_FEATURE_SPAN_NONE_TEXBL || FW_FEATURE_SPAN_LI_TEXBL || FW_FEATURE_SPAN_PHONG_TEXBL)
                    mip_fast_bilinear(tx->rgb, tx->w, tx->h, (uint32_t *)(void *)tm);
            } else if (FW_FEATURE_SPAN_NONE_TEX || FW_FEATURE_SPAN_LI_TEX || FW_FEATURE_SPAN_PHONG_TEX) {
                mip_fast_rgb565(tx->rgb, tx->w, tx->h, (uint16_t *)(void *)tm);
            }
            rc->fast.tex565[i].p = tm;
            tm += work_round(n);
        }
        rc->fast.tex565[i].wlog2 = (uint8_t)log2_exact(tx->w);
        rc->fast.tex565[i].hlog2 = (uint8_t)log2_exact(tx->h);
    }
}

int raster_init(void *work, size_t work_size, const struct scene *s, uint16_t width, uint16_t height,
                uint16_t strip_rows)
{
    if (work_size < raster_work_size(s, width, height, strip_rows)) return -1;
    if (s->canvas_h == 0 || s->viewport_h <= 0 || s->projection_d <= 0) return -1;
    struct ras_ctx *rc = ras_ctx_of(work);
    memset(rc, 0, sizeof *rc);
    struct work_carve c = { (uint8_t *)rc, 0 };
    if (carve(s, width, height, strip_rows, rc, &c)) return -1;
    rc->s = s;
    rc->w = width;
    rc->h = height;
    rc->strip_rows = strip_rows;
    while (height && ((height - 1u) >> rc->row_shift) > 255u) rc->row_shift++;
    rc->book = s->ras.book_exact;
    rc->depth_bytes = (uint8_t)depth_bytes(s);
    rc->def.affine_from = -1;
    rc->def.sub_bits = s->ras.subpixel_bits ? (s->ras.subpixel_bits > 8 ? 8 : s->ras.subpixel_bits) : RAS_SUBPIXEL_BITS;
    rc->def.shading = (uint8_t)eff_shading(s);
    rc->fast.on = (uint8_t)fast_path(s);
    rc->fast.persp_log2 = (uint8_t)(s->ras.persp_step == 2 ? 1 : s->ras.persp_step == 4 ? 2 : s->ras.persp_step == 8 ? 3 : (s->ras.persp_step == 32 ? 5 : 4));
    rc->fast.phong = (uint8_t)phong_fast(s);
    /* fast Phong's specular tables, one per exponent, and each instance's */
    uint32_t exps[RAS_SPEC_MAX];
    uint16_t nspec = spec_exponents(s, rc->fast.inst_spec, exps);
    if (spec_given(s, nspec)) {
        rc->fast.spec_tab = s->spec_tab;   /* scenec's: the same tables, in flash */
        rc->fast.spec_step = s->spec_step;
    } else {
        uint16_t *tab = (uint16_t *)rc->fast.spec_tab;   /* (work memory: carve's) */
        uint32_t *step = (uint32_t *)rc->fast.spec_step;
        for (uint16_t k = 0; FW_FEATURE_RAS_FAST_PHONG && k < nspec; k++)
            ras_spec_table(tab + 257 * k, exps[k], step + 2 * k);
    }
    init_viewport(rc);
    init_textures(rc);
    /* the buckets of the rows by a product: 2^16 / strip_rows + 1, if it
     * gives every row's quotient */
    rc->bins.div_mul = strip_rows ? 65536u / strip_rows + 1u : 0;
    for (uint32_t r = 0; rc->bins.div_mul && r < height; r++)
        if ((r * rc->bins.div_mul) >> 16 != r / strip_rows) rc->bins.div_mul = 0;
    /* each instance's model box (an earlier instance's of the same model) */
    for (uint16_t i = 0; i < s->ninstances; i++) {
        const struct ras_model *m = &s->models[s->instances[i].model];
        uint16_t j = 0;
        while (j < i && s->instances[j].model != s->instances[i].model) j++;
        if (j < i) rc->inst[i].box = rc->inst[j].box;
        else ras_box_of(&rc->inst[i].box, m->verts, m->nverts);
    }
    if (FW_FEATURE_RAS_CH15) ras_ch15_init(rc);
    return 0;
}

/* ---- the features a scene needs (scene_features.def) ---- */

/* The span loops instance i's triangles take (fast_describe in
 * raster_default.c, from the scene's choices above): 0 when they take the
 * exact path. */
static uint32_t instance_spans(const struct scene *s, const struct ras_instance *in)
{
    const struct ras_options *o = &s->ras;
    const int sh = eff_shading(s);
    const int tex = in->texture >= 0 && in->texture < s->ntextures && in->model < s->nmodels &&
                    s->models[in->model].has_uvs;
    const int bl = tex && s->textures[in->texture].filter == TEX_BILINEAR;
    if (sh == SHADE_PHONG) {
        if (!phong_fast(s)) return 0;
        if (!tex) return RENDER_F(SPAN_PHONG_CONST);
        if (bl) return o->bl_weights ? RENDER_F(SPAN_PHONG_TEXBW) : RENDER_F(SPAN_PHONG_TEXBL);
        return RENDER_F(SPAN_PHONG_TEX);
    }
    if (tex) {
        /* (a nearest or bilinear texture whose copy tex565_size refuses
         * takes the exact path: its loops counted all the same) */
        if ((!bl && s->textures[in->texture].filter != TEX_NEAREST) || !o->perspective_uv || sh == SHADE_FLAT)
            return 0;
        if (bl && o->bl_weights) return sh == SHADE_GOURAUD ? RENDER_F(SPAN_LI_TEXBW) : RENDER_F(SPAN_NONE_TEXBW);
        if (bl) return sh == SHADE_GOURAUD ? RENDER_F(SPAN_LI_TEXBL) : RENDER_F(SPAN_NONE_TEXBL);
        return sh == SHADE_GOURAUD ? RENDER_F(SPAN_LI_TEX) : RENDER_F(SPAN_NONE_TEX);
    }
    return sh == SHADE_GOURAUD ? RENDER_F(SPAN_RGB_CONST) : RENDER_F(SPAN_NONE_CONST);
}

uint32_t raster_features(const struct scene *s)
{
    const struct ras_options *o = &s->ras;
    uint32_t f = RENDER_F(RASTER);
    if (s->nprims || s->nlines) f |= RENDER_F(RAS_2D);
    if (!s->ninstances) return f;
    if (!frame_cache(s)) return f | RENDER_F(RAS_BOOK);
    f |= RENDER_F(RAS_DEFAULT);
    int nmap = 0;
    for (uint16_t i = 0; i < s->ninstances; i++) nmap |= s->instances[i].normal_map >= 0;
    if (ch15_lit(o) || (nmap && eff_shading(s) == SHADE_PHONG)) f |= RENDER_F(RAS_CH15);
    if (!fast_path(s)) return f;
    f |= RENDER_F(RAS_FAST);
    if (phong_fast(s)) f |= RENDER_F(RAS_FAST_PHONG);
    uint32_t spans = 0;
    for (uint16_t i = 0; i < s->ninstances; i++) spans |= instance_spans(s, &s->instances[i]);
    if (spans) {
        const int db = depth_bytes(s);
        f |= spans | (db == 0 ? RENDER_F(SPAN_Z0) : db == 2 ? RENDER_F(SPAN_Z2) : RENDER_F(SPAN_Z4));
    }
    return f;
}

/* ---- a sibling context: another core's strips of the owner's frames ---- */

/* The scene's triangles (vertices) in every instance (carve's counts, without its checks). */
static uint32_t scene_count(const struct scene *s, int verts)
{
    uint32_t n = 0;
    for (uint16_t i = 0; i < s->ninstances; i++)
        if (s->instances[i].model < s->nmodels) {
            const struct ras_model *m = &s->models[s->instances[i].model];
            n += verts ? m->nverts : m->ntris;
        }
    return n;
}

/* A sibling's own tables: carve_strip_tables', then the part-1 bits of
 * the vertices lit by a split preparation (raster_frame_triangles) where
 * the scene lights vertices (their lighting goes to the owner's table). */
static void carve_sibling(const struct scene *s, uint16_t w, uint16_t h, uint16_t strip_rows, struct ras_ctx *rc,
                          struct work_carve *c)
{
    uint32_t ntris = scene_count(s, 0), nverts = scene_count(s, 1);
    (void)work_take(c, sizeof(struct ras_ctx));
    carve_strip_tables(s, w, h, strip_rows, ntris, rc, c);
    int vl = (shade_caches(s) & 2) != 0;
    void *vb = work_take(c, vl ? (nverts + 7) / 8 : 0);
    uint32_t nvc = vcache_entries(s, nverts);
    void *vc = work_take(c, sizeof(struct ras_vcache) * nvc);
    rc->own.depth = rc->depth;
    rc->own.runs = rc->bins.runs;
    rc->own.keep = rc->fast.keep;
    rc->own.stencil = rc->c15.stencil;
    rc->own.vcache = nvc ? vc : NULL;
    rc->own.vlit = vl ? vb : NULL;
}

size_t raster_sibling_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows)
{
    struct ras_ctx scratch;
    struct work_carve c = { NULL, 0 };
    memset(&scratch, 0, sizeof scratch);
    scratch.bins.on = (uint8_t)bins_on(s, scene_count(s, 0));
    scratch.bins.nbuckets = bins_count(scratch.bins.on, height, strip_rows);
    carve_sibling(s, width, height, strip_rows, &scratch, &c);
    return c.off + WORK_ALIGN;
}

/* The per-strip state of a sibling made new: its own tables, nothing kept. */
static void sibling_reset(struct ras_ctx *rc, const struct ras_ctx *ow, const struct ras_own *own)
{
    rc->owner = ow;
    rc->own = *own;
    rc->depth = own->depth;
    rc->bins.runs = own->runs;
    rc->fast.keep = own->keep;
    rc->c15.stencil = own->stencil;
    for (uint16_t k = 0; k < rc->fast.nkeep; k++) rc->fast.keep[k].tri = UINT32_MAX;
}

int raster_init_sibling(void *work, size_t work_size, const void *owner_work)
{
    const struct ras_ctx *ow = ras_ctx_of((void *)(uintptr_t)owner_work);
    if (ow->owner) return -1;   /* a sibling's sibling: take the owner's */
    if (work_size < raster_sibling_work_size(ow->s, ow->w, ow->h, ow->strip_rows)) return -1;
    struct ras_ctx *rc = ras_ctx_of(work);
    *rc = *ow;
    struct work_carve c = { (uint8_t *)rc, 0 };
    carve_sibling(ow->s, ow->w, ow->h, ow->strip_rows, rc, &c);
    struct ras_own own = rc->own;
    /* the owner's part-1 vertices lit and camera-space cache live here:
     * registered with it, nothing lit yet */
    struct ras_ctx *owm = (struct ras_ctx *)(uintptr_t)ow;
    owm->def.vert_lit1 = own.vlit;
    owm->def.vcache1 = own.vcache;
    for (uint32_t k = 0; own.vcache && k <= ow->def.vcache_mask; k++) own.vcache[k].k = UINT32_MAX;
    if (own.vlit) memset(own.vlit, 0, (ow->nverts + 7) / 8);
    sibling_reset(rc, ow, &own);
    return 0;
}

int raster_sibling_frame(void *work)
{
    struct ras_ctx *rc = ras_ctx_of(work);
    const struct ras_ctx *ow = rc->owner;
    if (!ow) return -1;
    struct ras_own own = rc->own;
    *rc = *ow;   /* the frame: camera, lights, fast Phong's lights, counts, every table's address */
    sibling_reset(rc, ow, &own);
    return 0;
}
