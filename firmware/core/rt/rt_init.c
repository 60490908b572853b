/* SPDX-License-Identifier: MIT */
/* rt_init.c — the ray tracer's work memory (one carve, run to measure and
 * to place), rt_init (options, items, the render size's viewport, the
 * bounding-sphere hierarchy) and rt_begin_frame (the animated camera). */
#include "rt_int.h"
#include "rt_num.h"
#include "work.h"

/* Adaptive subsampling's block side: 0 (off) or 2 .. RT_MAX_ADAPT. */
static unsigned adapt_side(const struct scene *s)
{
    unsigned v = s->rt.adaptive_subsample;
    return v < 2 ? 0u : (v > RT_MAX_ADAPT ? RT_MAX_ADAPT : v);
}

/* Every table of the state, in order, from c (c->base NULL: measuring, rt
 * a scratch state). Tables of objects, items and lights hold at least one
 * entry. */
static void carve(const struct scene *s, uint16_t width, uint16_t height, struct rt_state *rt,
                  struct work_carve *c)
{
    unsigned ab = adapt_side(s);
    size_t nitems = (size_t)s->nobjects + s->ncsg;
    size_t nobj1 = s->nobjects ? s->nobjects : 1, nitem1 = nitems ? nitems : 1, nlight1 = s->nlights ? s->nlights : 1;
    (void)work_take(c, sizeof(struct rt_state));   /* the state itself, first */
    rt->oc = work_take(c, sizeof(struct rt_obj_cache) * nobj1);
    rt->items = work_take(c, sizeof(int16_t) * nitem1);
    rt->unbounded = work_take(c, sizeof(int16_t) * nitem1);
    rt->bvh = work_take(c, sizeof(struct rt_bvh_node) * (2 * nitems + 1));
    rt->bvh_items = work_take(c, sizeof(int16_t) * nitem1);
    rt->occluder = work_take(c, sizeof(int16_t) * nlight1);
    rt->light_ray = work_take(c, sizeof(struct rt_ray) * nlight1);
    rt->light_len = work_take(c, sizeof(num) * nlight1);
    rt->light_div = work_take(c, sizeof(struct num_divisor) * nlight1);
    rt->light_self = work_take(c, sizeof(struct rt_self_dir) * nlight1);
    rt->shadow_mask = work_take(c, sizeof(uint32_t) * (rt_shadow_masks_fit(s) ? nlight1 * nobj1 : 0u));
    rt->row_c = work_take(c, sizeof(rgb) * width);
    rt->row_item = work_take(c, sizeof(int16_t) * width);
    rt->col_x = work_take(c, sizeof(num) * width);
    /* adaptive subsampling visits rows out of order: every row's viewport y */
    num *row_y = work_take(c, sizeof(num) * (ab ? height : 0u));
    rt->row_y_tab = ab ? row_y : NULL;
    rt->adapt_ratio = work_take(c, sizeof(num) * (ab ? (ab + 1u) * (ab + 1u) : 0u));
    /* adaptive subsampling: two full rows of samples, a block's two columns
     * and its (B + 1)^2 grid, each with its flags (empty when off) */
    size_t nb = ab ? ab + 1u : 0, ng = nb * nb, nw = ab ? width : 0;
    for (int k = 0; k < 2; k++) {
        rt->corner[k] = work_take(c, sizeof(struct rt_sample) * nw);
        rt->corner_have[k] = work_take(c, nw);
    }
    for (int k = 0; k < 2; k++) {
        rt->colbuf[k] = work_take(c, sizeof(struct rt_sample) * nb);
        rt->colbuf_have[k] = work_take(c, nb);
    }
    rt->grid = work_take(c, sizeof(struct rt_sample) * ng);
    rt->grid_have = work_take(c, ng);
    size_t ntc = ((size_t)width + RT_TILE - 1) / RT_TILE;
    rt->ntc = (uint16_t)ntc;
    rt->tile_items = work_take(c, sizeof(int16_t) * ntc * nitem1);
    rt->tile_n = work_take(c, sizeof(uint16_t) * ntc);
    /* one row, or an adaptive block's rows (visited out of order) and one more */
    size_t ivr = ab ? ab + 2u : 1u;
    rt->iv_rows = (uint8_t)ivr;
    rt->iv = work_take(c, sizeof(int16_t) * 2 * ivr * nobj1);
    rt->iv_tag = work_take(c, sizeof(int32_t) * ivr);
}

size_t rt_work_size(const struct scene *s, uint16_t width, uint16_t height)
{
    struct rt_state scratch;
    struct work_carve c = { NULL, 0 };
    carve(s, width, height, &scratch, &c);
    return c.off;   /* rt_init takes memory aligned to WORK_ALIGN: no slack */
}

void rt_set_shadow_probe(void *work, uint8_t *probe)
{
    rt_state_of(work)->shadow_probe = probe;
}

void rt_set_item_probe(void *work, int16_t *probe)
{
    rt_state_of(work)->item_probe = probe;
}

void rt_set_hit_probe(void *work, num *probe)
{
    rt_state_of(work)->hit_probe = probe;
}

uint32_t rt_shadow_rays(const void *work)
{
    return ((const struct rt_state *)work)->n.shadow_rays;
}

/* The scene's options as the state keeps them (clamped), and adaptive
 * subsampling's bilinear weights. */
static void init_options(struct rt_state *rt)
{
    const struct rt_options *o = &rt->s->rt;
    rt->book = o->formulation == 1 || (o->formulation == 0 && num_rt_reference_mode());
    rt->depth = o->recursion_depth > RT_MAX_DEPTH ? RT_MAX_DEPTH : o->recursion_depth;
    rt->cached = !o->no_frame_cache;
    rt->shortcuts = !o->no_shortcuts && !rt->book;
    rt->skip_item = -1;
    rt->ss = o->supersample < 1 ? 1 : (o->supersample > RT_MAX_SS ? RT_MAX_SS : o->supersample);
    rt->ss_adaptive = o->adaptive_ss;
    rt->subsample = o->subsample < 1 ? 1 : o->subsample;
    rt->adapt = (uint8_t)adapt_side(rt->s);
    rt->adapt_diff = num_from_int(o->adaptive_threshold ? o->adaptive_threshold : RT_SUBSAMPLE_DIFF);
    /* the bilinear weights i / w of every rectangle side w a block can have */
    for (int side = 1; side <= rt->adapt; side++)
        for (int i = 0; i <= side; i++) rt->adapt_ratio[side * (rt->adapt + 1) + i] = num_from_ratio(i, side);
    rt->corner_row[0] = rt->corner_row[1] = -1;
    rt->tiles = rt->shortcuts && !o->bvh;
    rt->tile_row = -1;
    rt->bg_row = -1;
    rt->prim_items = NULL;
    rt->prim_iv = NULL;
}

/* The render size's viewport: height kept, width follows the render size
 * (render.h); every column's (and with adaptive subsampling every row's)
 * viewport coordinate. */
static void init_viewport(struct rt_state *rt)
{
    const struct scene *s = rt->s;
    rt->wn = num_from_int(rt->w);
    rt->hn = num_from_int(rt->h);
    rt->vh = s->viewport_h;
    /* Vh W / H with the product wide (a flat render's Vh W may pass the
     * format where Vw does not; the same bits where it fits) */
    rt->vw = wnum_div(num_mul_wide(s->viewport_h, rt->wn), wnum_from_num(rt->hn));
    rt->d = s->projection_d;
    rt->sx = num_div(rt->vw, rt->wn);
    rt->sy = num_div(rt->vh, rt->hn);
    /* viewport x of every column's centre sample (canvas_to_viewport) */
    for (uint16_t c = 0; c < rt->w; c++)
        rt->col_x[c] = wnum_div(num_mul_wide(num_from_int(c - rt->w / 2), rt->vw), wnum_from_num(rt->wn));
    rt->row_y_row = -1;
    rt->dx_row = -1;
    /* bit 2 of dx_ok: every column's x vh fits the exact directions
     * (rt_exact_comp at both ends: |x vh| grows with |x|), formed in
     * exact_dir without the checks */
    num v0, v1;
    rt->dx_ok = (uint8_t)(rt_exact_comp(rt->vh, -(rt->w / 2), &v0) && rt_exact_comp(rt->vh, rt->w - 1 - rt->w / 2, &v1) ? 2 : 0);
    if (rt->row_y_tab)
        for (int r = 0; r < rt->h; r++)
            rt->row_y_tab[r] = num_div(num_mul(num_from_int(rt->h / 2 - 1 - r), rt->vh), rt->hn);
}

int rt_init(void *work, size_t work_size, const struct scene *s, uint16_t width, uint16_t height)
{
    if (((uintptr_t)work & (WORK_ALIGN - 1)) != 0) return -1;
    if ((size_t)s->nobjects + s->ncsg > 16000) return -1;
    for (uint16_t k = 0; k < s->ncsg; k++)
        if (s->csg[k].a >= s->nobjects || s->csg[k].b >= s->nobjects ||
            s->objects[s->csg[k].a].shape != RT_SPHERE || s->objects[s->csg[k].b].shape != RT_SPHERE)
            return -1;
    if (work_size < rt_work_size(s, width, height)) return -1;
    struct rt_state *rt = rt_state_of(work);
    *rt = (struct rt_state){ 0 };
    struct work_carve c = { (uint8_t *)work, 0 };
    carve(s, width, height, rt, &c);
    rt->s = s;
    rt->w = width;
    rt->h = height;
    init_options(rt);
    /* drawn items in the book's order: objects, then CSG results */
    for (uint16_t i = 0; i < s->nobjects; i++)
        if (!s->objects[i].csg_only) rt->items[rt->nitems++] = (int16_t)i;
    for (uint16_t k = 0; k < s->ncsg; k++) rt->items[rt->nitems++] = (int16_t)(s->nobjects + k);
    rt->all_spheres = 1;
    for (uint16_t i = 0; i < rt->nitems; i++)
        if (rt->items[i] >= (int16_t)s->nobjects || s->objects[rt->items[i]].shape != RT_SPHERE) rt->all_spheres = 0;
    for (uint16_t k = 0; k < s->nlights; k++) {
        rt->occluder[k] = -1;
        /* a hit point proven within half the format (SCENE_FITS_HIT) and a
         * light inside it: L = Lpos - P in 32 bits is never saturated
         * (rt_compute_lighting; the lights from 32 on take v3_sub, the
         * same bits) */
#if NUM_MODE == NUM_MODE_FIXED
        if (k < 32 && (s->fits & SCENE_FITS_HIT) && rt_v3_within(s->lights[k].v, 30))
            rt->light_fit |= (uint32_t)1 << k;
#endif
    }
    init_viewport(rt);
    rt->cam_pos = s->camera.position;
    rt->cam_rot = s->camera.rotation;
    rt_frame_constants(rt);
    rt_light_constants(rt);
    for (uint16_t i = 0; i < s->nobjects; i++) {
        num e = s->objects[i].mat.specular;
        rt->oc[i].spec_zero = e >= 0 ? rt_powi_zero_below((uint32_t)num_to_int(e)) : NUM_C(-1.0);
    }
    rt_shadow_masks(rt);
    if (s->rt.bvh) rt_build_bvh(rt);
    return 0;
}

static int is_identity(const mat3 *m)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (m->m[i][j] != (i == j ? NUM_ONE : NUM_ZERO)) return 0;
    return 1;
}

int rt_begin_frame(void *work, uint16_t frame)
{
    struct rt_state *rt = rt_state_of(work);
    const struct scene *s = rt->s;
    /* animation: the camera moves and turns about y by per-frame increments */
    /* position + move x frame and the angle rot x frame modulo 360, both
     * from exact integer products (a frame index past the format's range
     * neither saturates nor drifts) */
    vec3 mv = s->camera_anim.move_per_frame;
    rt->cam_pos = v3_add(s->camera.position, v3_make(num_mul_int(mv.x, frame), num_mul_int(mv.y, frame),
                                                 num_mul_int(mv.z, frame)));
    rt->cam_rot = s->camera.rotation;
    if (frame && s->camera_anim.rot_y_per_frame != 0) {
        mat3 ry = m3_rot_y_deg(num_mul_int_mod(s->camera_anim.rot_y_per_frame, frame, NUM_C(360.0)));
        rt->cam_rot = m3_mul(&ry, &s->camera.rotation);
    }
    rt->cam_rotated = !is_identity(&rt->cam_rot);
    /* the exact primary directions turn by the precise rotation while it is
     * the scene's own (not the animation's) */
    rt->cam_q29 = NULL;
    if (rt->cam_rotated && !(frame && s->camera_anim.rot_y_per_frame != 0))
        for (int i = 0; i < 9; i++)
            if (s->camera.rot_q29[i / 3][i % 3]) rt->cam_q29 = s->camera.rot_q29;
    rt->dx_row = -1;
    for (uint16_t k = 0; k < s->nlights; k++) rt->occluder[k] = -1;
    rt->last_row = -2;
    rt->pass = RENDER_PASS_FULL;
    rt->corner_row[0] = rt->corner_row[1] = -1;
    rt->tile_row = -1;           /* the camera may have moved */
    rt->bg_row = -1;
    rt_frame_constants(rt);
    return 0;
}
