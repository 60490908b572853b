/* SPDX-License-Identifier: MIT */
/* raytracer.c — the main loop (chapter 2), TraceRay with reflections
 * (chapter 4), the camera (chapter 5), and chapter 5's transparency,
 * supersampling and subsampling; rendering by strips of rows. */
#include "rt_int.h"
#include "rt_num.h"
#include "work.h"

/* Adaptive supersampling refines a pixel whose centre sample differs from
 * its left or upper neighbour in object or by more than this per channel. */
#define RT_ADAPTIVE_DIFF NUM_C(12.0)

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
    rt->vw = num_div(num_mul(s->viewport_h, rt->wn), rt->hn);
    rt->d = s->projection_d;
    rt->sx = num_div(rt->vw, rt->wn);
    rt->sy = num_div(rt->vh, rt->hn);
    /* viewport x of every column's centre sample (canvas_to_viewport) */
    for (uint16_t c = 0; c < rt->w; c++)
        rt->col_x[c] = num_div(num_mul(num_from_int(c - rt->w / 2), rt->vw), rt->wn);
    rt->row_y_row = -1;
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
    for (uint16_t k = 0; k < s->nlights; k++) rt->occluder[k] = -1;
    init_viewport(rt);
    rt->cam_pos = s->camera.position;
    rt->cam_rot = s->camera.rotation;
    rt_frame_constants(rt);
    rt_light_constants(rt);
    for (uint16_t i = 0; i < s->nobjects; i++) {
        num e = s->objects[i].mat.specular;
        rt->oc[i].spec_zero = e >= 0 ? rt_powi_zero_below((uint32_t)num_to_int(e)) : NUM_C(-1.0);
    }
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
    for (uint16_t k = 0; k < s->nlights; k++) rt->occluder[k] = -1;
    rt->last_row = -2;
    rt->pass = RENDER_PASS_FULL;
    rt->corner_row[0] = rt->corner_row[1] = -1;
    rt_frame_constants(rt);
    return 0;
}

/* Notes on a primary sample: what it hit and which lights it found shadowed. */
struct rt_prim {
    int16_t item;
    uint8_t shadow;
};

/* row_item of a supersampled pixel (not a single sample's item; subsampling
 * never interpolates across it): whether any of its rays hit an object. */
#define RT_ITEM_SS_NONE (-2)
#define RT_ITEM_SS_HIT  (-3)

/* An item note says the pixel shows an object (not only the background). */
static int item_covers(int16_t item) { return item >= 0 || item == RT_ITEM_SS_HIT; }

/* Writes pixel (x, y) of the strip, with render.h's coverage: the mask
 * (t->written) and the count of render_stats.pixels_written. */
static void rt_put(struct rt_state *rt, struct render_target *t, int x, int y, rgb c, int covered)
{
    render_put(t, x, y, c);
    if (t->written) t->written[(size_t)(y - t->y0) * t->width + (size_t)x] = (uint8_t)(covered != 0);
    rt->n.covered += covered != 0;
}

static rgb background(const struct rt_state *rt) { return rt->s->background; }

/* The object whose material an item shows (a CSG shows operand a's). */
static int16_t item_material_object(const struct rt_state *rt, int16_t item)
{
    const struct scene *s = rt->s;
    return item >= (int16_t)s->nobjects ? (int16_t)s->csg[item - s->nobjects].a : item;
}

/* ReflectRay: R = N*(2*(V.N)) - V. */
static vec3 reflect_ray(vec3 v, vec3 n)
{
    num d = v3_dot(v, n);
    return v3_sub(v3_scale(n, num_add(d, d)), v);     /* 2 (V.N) as a sum: the same bits */
}

int rt_refract(vec3 d, vec3 n, num ior, vec3 *out)
{
    vec3 dn = v3_normalize(d);
    num cosi = num_neg(v3_dot(n, dn));
    num eta;
    if (cosi < 0) {            /* leaving the object */
        n = v3_neg(n);
        cosi = num_neg(cosi);
        eta = ior;
    } else {
        eta = num_div(NUM_ONE, ior);
    }
    num k = num_sub(NUM_ONE, num_mul(num_mul(eta, eta), num_sub(NUM_ONE, num_mul(cosi, cosi))));
    if (k < 0) return 0;
    *out = v3_add(v3_scale(dn, eta), v3_scale(n, num_sub(num_mul(eta, cosi), num_sqrt(k))));
    return 1;
}

/* Colour x weight and colour + colour, in 32-bit arithmetic when the
 * scene's format analysis proved colour intermediates in range
 * (SCENE_FITS_COLOUR: same bits, no saturation checks). */
static inline rgb colour_scale(const struct scene *s, rgb c, num k)
{
    if (s->fits & SCENE_FITS_COLOUR) return rgb_make(num_mul_fit(c.r, k), num_mul_fit(c.g, k), num_mul_fit(c.b, k));
    return rgb_scale(c, k);
}
static inline rgb colour_add(const struct scene *s, rgb a, rgb b)
{
    if (s->fits & SCENE_FITS_COLOUR) return rgb_make(num_add_fit(a.r, b.r), num_add_fit(a.g, b.g), num_add_fit(a.b, b.b));
    return rgb_add(a, b);
}

/* TraceRay: colour seen along the ray with t in (t_min, t_max); `depth`
 * more reflection/refraction bounces allowed (bounded recursion). */
static rgb trace_ray(struct rt_state *rt, struct rt_ray *ray, num t_min, num t_max, int depth,
                     struct rt_prim *prim)
{
    const struct scene *s = rt->s;
    struct rt_hit hit;
    rt->n.rays++;
    if (!rt_closest_intersection(rt, ray, t_min, t_max, &hit, 0)) {
        if (prim) prim->item = -1;
        return background(rt);
    }
    if (prim) prim->item = hit.item;
    int16_t mo = item_material_object(rt, hit.item);
    const struct rt_material *m = &s->objects[mo].mat;
    /* P = O + D t; D t in 32-bit arithmetic when every hit is proven to lie
     * on a bounded object (SCENE_FITS_HIT) */
    vec3 p = s->fits & SCENE_FITS_HIT
                 ? v3_add(ray->o, v3_make(num_mul_fit(ray->d.x, hit.t), num_mul_fit(ray->d.y, hit.t), num_mul_fit(ray->d.z, hit.t)))
                 : v3_add(ray->o, v3_scale(ray->d, hit.t));
    vec3 n = rt_hit_normal(rt, &hit, p);
    vec3 v = v3_neg(ray->d);
    rgb local;
    if (s->rt.unlit) {
        local = m->color;
    } else {
        num i = rt_compute_lighting(rt, p, n, v, m->specular, rt->oc[mo].spec_zero, hit.surf,
                                    prim ? &prim->shadow : NULL);
        local = colour_scale(s, m->color, i);
    }
    num r = m->reflective;
    num tr = m->transparency;
    if (depth <= 0 || (r <= 0 && tr <= 0)) return local;

    rgb out = local;
    if (r > 0) {
        struct rt_ray rr;
        rt_ray_init(&rr, p, reflect_ray(v, n), hit.surf, 0);
        rgb reflected = trace_ray(rt, &rr, s->rt.epsilon, NUM_MAX, depth - 1, NULL);
        out = colour_add(s, colour_scale(s, local, num_sub(NUM_ONE, r)), colour_scale(s, reflected, r));
    }
    if (tr > 0) {
        /* Transparency: what the refracted ray sees, by Snell's law; on total
         * internal reflection the ray reflects instead. */
        vec3 dir;
        if (!rt_refract(ray->d, n, m->refraction > 0 ? m->refraction : NUM_ONE, &dir))
            dir = reflect_ray(v, n);
        struct rt_ray tr_ray;
        rt_ray_init(&tr_ray, p, dir, hit.surf, 0);
        rgb seen = trace_ray(rt, &tr_ray, s->rt.epsilon, NUM_MAX, depth - 1, NULL);
        out = colour_add(s, colour_scale(s, out, num_sub(NUM_ONE, tr)), colour_scale(s, seen, tr));
    }
    return out;
}

/* CanvasToViewport for canvas point (x, y) (num, sub-pixel allowed), then
 * the camera rotation. */
static vec3 rotate_direction(const struct rt_state *rt, vec3 d)
{
    if (!rt->cam_rotated) return d;
    /* D'[i] = ((0 + D.x*M[i][0]) + D.y*M[i][1]) + D.z*M[i][2], the demo's order */
    vec3 r;
    const mat3 *m = &rt->cam_rot;
    r.x = num_add(num_add(num_add(NUM_ZERO, num_mul(d.x, m->m[0][0])), num_mul(d.y, m->m[0][1])), num_mul(d.z, m->m[0][2]));
    r.y = num_add(num_add(num_add(NUM_ZERO, num_mul(d.x, m->m[1][0])), num_mul(d.y, m->m[1][1])), num_mul(d.z, m->m[1][2]));
    r.z = num_add(num_add(num_add(NUM_ZERO, num_mul(d.x, m->m[2][0])), num_mul(d.y, m->m[2][1])), num_mul(d.z, m->m[2][2]));
    return r;
}

static vec3 canvas_to_viewport(const struct rt_state *rt, num x, num y)
{
    /* (x*Vw)/W rather than x*(Vw/W): Vw/W = 1/600 in Q15.16 is 0.02% off,
     * a whole pixel at the edge of a 600-pixel canvas */
    return rotate_direction(rt, v3_make(num_div(num_mul(x, rt->vw), rt->wn), num_div(num_mul(y, rt->vh), rt->hn), rt->d));
}

/* The same for a pixel's centre: x from the column table, y once a row. */
static vec3 pixel_to_viewport(struct rt_state *rt, int col, int row)
{
    if (rt->row_y_tab) return rotate_direction(rt, v3_make(rt->col_x[col], rt->row_y_tab[row], rt->d));
    if (rt->row_y_row != row) {
        rt->row_y = num_div(num_mul(num_from_int(rt->h / 2 - 1 - row), rt->vh), rt->hn);
        rt->row_y_row = row;
    }
    return rotate_direction(rt, v3_make(rt->col_x[col], rt->row_y, rt->d));
}

static rgb trace_primary(struct rt_state *rt, vec3 d, struct rt_prim *prim)
{
    struct rt_ray ray;
    rt_ray_init(&ray, rt->cam_pos, d, -1, 1);
    rt->n.primary_rays++;
    return trace_ray(rt, &ray, rt->s->rt.t_min_primary, NUM_MAX, rt->depth, prim);
}

static rgb primary(struct rt_state *rt, num x, num y, struct rt_prim *prim)
{
    return trace_primary(rt, canvas_to_viewport(rt, x, y), prim);
}

/* n x n rays on a regular grid inside the pixel, averaged; *hit set when
 * one of them hit an object. */
static rgb supersample(struct rt_state *rt, num x, num y, int n, int *hit)
{
    rgb sum = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    struct rt_prim pr;
    *hit = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            num ox = num_from_ratio(2 * i + 1 - n, 2 * n);
            num oy = num_from_ratio(2 * j + 1 - n, 2 * n);
            pr.item = -1;
            sum = rgb_add(sum, primary(rt, num_add(x, ox), num_add(y, oy), &pr));
            if (pr.item >= 0) *hit = 1;
        }
    return rgb_scale(sum, num_from_ratio(1, n * n));
}

/* Some channel of a and b more than `diff` apart. */
static int colours_differ(rgb a, rgb b, num diff)
{
    return num_abs(num_sub(a.r, b.r)) > diff || num_abs(num_sub(a.g, b.g)) > diff ||
           num_abs(num_sub(a.b, b.b)) > diff;
}

/* One pixel: plain, fixed supersampling, or adaptive (refine edges only).
 * The centre sample's colour and object are kept in the row notes (a
 * supersampled pixel's object as RT_ITEM_SS_*), and rt->px_covered says
 * whether the pixel shows an object. */
static rgb pixel(struct rt_state *rt, int col, int row, int have_left, int have_up, uint8_t *probe)
{
    num x = num_from_int(col - rt->w / 2);
    num y = num_from_int(rt->h / 2 - 1 - row);
    if (rt->ss > 1 && !rt->ss_adaptive) {
        int hit;
        rgb c = supersample(rt, x, y, rt->ss, &hit);
        rt->row_item[col] = hit ? RT_ITEM_SS_HIT : RT_ITEM_SS_NONE;
        rt->px_covered = (uint8_t)hit;
        return c;
    }
    struct rt_prim pr = { -1, 0 };
    rgb c = trace_primary(rt, pixel_to_viewport(rt, col, row), &pr);
    rt->px_covered = pr.item >= 0;
    if (probe) *probe = pr.item < 0 ? 0x80 : pr.shadow;
    if (rt->ss_adaptive) {
        int n = rt->ss > 1 ? rt->ss : 2;
        int edge = 0;
        if (have_left && col > 0 && (rt->row_item[col - 1] != pr.item || colours_differ(rt->row_c[col - 1], c, RT_ADAPTIVE_DIFF))) edge = 1;
        if (have_up && (rt->row_item[col] != pr.item || colours_differ(rt->row_c[col], c, RT_ADAPTIVE_DIFF))) edge = 1;
        /* the row notes hold the centre samples: the left one is already this
         * row's, the one at col still the row above's until written here */
        rt->row_item[col] = pr.item;
        rt->row_c[col] = c;
        if (edge) {
            int hit;
            c = supersample(rt, x, y, n, &hit);
            rt->px_covered = (uint8_t)hit;
        }
        return c;
    }
    rt->row_item[col] = pr.item;
    rt->row_c[col] = c;
    return c;
}

/* Subsampling (chapter 5): trace every k-th column and the last; a pixel in
 * between whose two traced neighbours hit the same object takes their
 * linear interpolation, otherwise it is traced too. */
static void subsampled_row(struct rt_state *rt, struct render_target *t, int row, uint8_t *probe)
{
    int w = rt->w, k = rt->subsample;
    int col = 0;
    for (;;) {
        rt->row_c[col] = pixel(rt, col, row, 0, 0, probe ? probe + col : NULL);
        if (col == w - 1) break;
        col = col + k < w ? col + k : w - 1;
    }
    for (int a = 0; a < w - 1;) {
        int b = a + k < w ? a + k : w - 1;
        int same = rt->row_item[a] == rt->row_item[b] && rt->row_item[a] >= -1;
        for (int x = a + 1; x < b; x++) {
            if (same) {
                num wgt = num_from_ratio(x - a, b - a);
                rgb c = rgb_add(rgb_scale(rt->row_c[a], num_sub(NUM_ONE, wgt)), rgb_scale(rt->row_c[b], wgt));
                rt_put(rt, t, x, row, c, rt->row_item[a] >= 0);
                if (probe) probe[x] = 0xFF;   /* not traced */
            } else {
                rgb c = pixel(rt, x, row, 0, 0, probe ? probe + x : NULL);
                rt_put(rt, t, x, row, c, rt->px_covered);
            }
        }
        rt_put(rt, t, a, row, rt->row_c[a], item_covers(rt->row_item[a]));
        a = b;
    }
    rt_put(rt, t, w - 1, row, rt->row_c[w - 1], item_covers(rt->row_item[w - 1]));
}

static inline rgb rgb_sub(rgb a, rgb b) { return rgb_make(num_sub(a.r, b.r), num_sub(a.g, b.g), num_sub(a.b, b.b)); }

/* One primary ray through the centre of pixel (col, row). */
static struct rt_sample sample_at(struct rt_state *rt, int col, int row)
{
    struct rt_prim pr = { -1, 0 };
    struct rt_sample s;
    s.c = trace_primary(rt, pixel_to_viewport(rt, col, row), &pr);
    s.item = pr.item;
    s.shadow = pr.shadow;
    return s;
}

/* RENDER_PASS_COARSE: one ray per block, at the block's centre pixel. */
static void coarse_strip(struct rt_state *rt, struct render_target *t)
{
    const int b = RENDER_COARSE_BLOCK;
    for (int r0 = t->y0 - t->y0 % b; r0 < t->y1; r0 += b) {
        int r1 = r0 + b < rt->h ? r0 + b : rt->h;
        for (int c0 = 0; c0 < rt->w; c0 += b) {
            int c1 = c0 + b < rt->w ? c0 + b : rt->w;
            struct rt_sample sm = sample_at(rt, (c0 + c1 - 1) / 2, (r0 + r1 - 1) / 2);
            rgb c = sm.c;
            int covered = sm.item >= 0;
            uint16_t v = rgb_to_565(c);
            for (int y = r0 > t->y0 ? r0 : t->y0; y < r1 && y < t->y1; y++) {
                if (t->rgb888 || t->written) {
                    for (int x = c0; x < c1; x++) rt_put(rt, t, x, y, c, covered);
                    continue;
                }
                uint16_t *row = t->rgb565 + (size_t)(y - t->y0) * t->width;
                for (int x = c0; x < c1; x++) row[x] = v;   /* the block's one colour */
                if (covered) rt->n.covered += (uint32_t)(c1 - c0);
            }
        }
    }
}

/* The samples of image row `row` traced so far: the block corners
 * (columns 0, B, 2B, ... and the last) at once, other columns when a block
 * needs them; kept for the next block row, whose top row it is. */
static int corner_row(struct rt_state *rt, int row)
{
    for (int k = 0; k < 2; k++)
        if (rt->corner_row[k] == row) return k;
    /* replace the row that is not the other block edge in use */
    int k = rt->corner_row[0] < rt->corner_row[1] ? 0 : 1;
    for (int col = 0; col < rt->w; col++) rt->corner_have[k][col] = 0;
    for (int col = 0;; col += rt->adapt) {
        if (col > rt->w - 1) col = rt->w - 1;
        rt->corner[k][col] = sample_at(rt, col, row);
        rt->corner_have[k][col] = 1;
        if (col == rt->w - 1) break;
    }
    rt->corner_row[k] = row;
    return k;
}

static int samples_agree(const struct rt_sample *a, const struct rt_sample *b, num diff)
{
    return a->item == b->item && a->shadow == b->shadow && !colours_differ(a->c, b->c, diff);
}

/* The block being refined: its samples on a (B+1) x (B+1) grid. Points
 * on its top and bottom rows live in the two row buffers (shared with the
 * blocks beside and, for the bottom row, with the next block row), points
 * on its left and right columns in the column buffers (shared with the
 * blocks beside), the rest in the block's own grid; each is traced once,
 * when first needed. */
struct rt_block {
    struct rt_state *rt;
    struct render_target *t;
    int c0, r0, wx, wy;        /* image position of grid point (0, 0); size */
    int top, bot;              /* row buffers of rows r0 and r0 + wy */
};

static const struct rt_sample *grid_at(struct rt_block *bk, int gx, int gy)
{
    struct rt_state *rt = bk->rt;
    struct rt_sample *sp;
    uint8_t *have;
    if (gy == 0 || gy == bk->wy) {
        int k = gy == 0 ? bk->top : bk->bot;
        sp = &rt->corner[k][bk->c0 + gx];
        have = &rt->corner_have[k][bk->c0 + gx];
    } else if (gx == 0 || gx == bk->wx) {
        int k = gx == 0 ? rt->col_left : 1 - rt->col_left;
        sp = &rt->colbuf[k][gy];
        have = &rt->colbuf_have[k][gy];
    } else {
        int i = gy * (rt->adapt + 1) + gx;
        sp = &rt->grid[i];
        have = &rt->grid_have[i];
    }
    if (!*have) {
        *sp = sample_at(rt, bk->c0 + gx, bk->r0 + gy);
        *have = 1;
    }
    return sp;
}

static int rect_agrees(const struct rt_sample *s00, const struct rt_sample *s01, const struct rt_sample *s10,
                       const struct rt_sample *s11, num d)
{
    return samples_agree(s00, s01, d) && samples_agree(s00, s10, d) && samples_agree(s00, s11, d) &&
           samples_agree(s01, s10, d) && samples_agree(s01, s11, d) && samples_agree(s10, s11, d);
}

/* Pixels [x, x + wx) x [y, y + wy) of the block (grid units = pixels),
 * and the right / bottom edge too when it is the image's last column /
 * row: if the rectangle's four corners agree (or it is one pixel), its
 * pixels are the corners' bilinear interpolation (traced grid points keep
 * their own colour); otherwise it is split in halves and each refined. */
static void refine(struct rt_block *bk, int x, int y, int wx, int wy, int right, int bottom)
{
    struct render_target *t = bk->t;
    int ya = bk->r0 + y, yb = bk->r0 + y + wy + (bottom ? 1 : 0);      /* image rows owned */
    if (yb <= t->y0 || ya >= t->y1) return;
    if (wx <= 1 && wy <= 1 && !right && !bottom) {
        const struct rt_sample *sp = grid_at(bk, x, y);
        rt_put(bk->rt, t, bk->c0 + x, ya, sp->c, sp->item >= 0);   /* ya is in the strip */
        return;
    }
    const struct rt_sample *s00 = grid_at(bk, x, y), *s01 = grid_at(bk, x + wx, y);
    const struct rt_sample *s10 = grid_at(bk, x, y + wy), *s11 = grid_at(bk, x + wx, y + wy);
    if ((wx > 1 || wy > 1) && !rect_agrees(s00, s01, s10, s11, bk->rt->adapt_diff)) {
        int hx = wx > 1 ? wx / 2 : wx, hy = wy > 1 ? wy / 2 : wy;
        refine(bk, x, y, hx, hy, right && hx == wx, bottom && hy == wy);
        if (hx < wx) refine(bk, x + hx, y, wx - hx, hy, right, bottom && hy == wy);
        if (hy < wy) {
            refine(bk, x, y + hy, hx, wy - hy, right && hx == wx, bottom);
            if (hx < wx) refine(bk, x + hx, y + hy, wx - hx, wy - hy, right, bottom);
        }
        return;
    }
    /* the rectangle's pixels from its four corners alone (a point another
     * rectangle traced is interpolated here too: the pixels then depend on
     * this rectangle's corners only, whatever the strips) */
    if (wx <= 1 && wy <= 1) {
        /* one pixel: its own sample, and the image's last column/row */
        for (int gy = y; gy < y + wy + (bottom ? 1 : 0); gy++) {
            int row = bk->r0 + gy;
            if (row < t->y0 || row >= t->y1) continue;
            for (int gx = x; gx < x + wx + (right ? 1 : 0); gx++) {
                const struct rt_sample *sp = grid_at(bk, gx, gy);
                rt_put(bk->rt, t, bk->c0 + gx, row, sp->c, sp->item >= 0);
            }
        }
        return;
    }
    /* bilinear: per row the colours at the left and right edges, then
     * along the row L + (R - L) fx, with fx per column from a table */
    const num *ratio = bk->rt->adapt_ratio;
    const num *fxs = ratio + wx * (bk->rt->adapt + 1), *fys = ratio + wy * (bk->rt->adapt + 1);
    for (int gy = y; gy < y + wy + (bottom ? 1 : 0); gy++) {
        int row = bk->r0 + gy;
        if (row < t->y0 || row >= t->y1) continue;
        num fy = fys[gy - y];
        rgb lc = rgb_add(s00->c, rgb_scale(rgb_sub(s10->c, s00->c), fy));
        rgb rc = rgb_add(s01->c, rgb_scale(rgb_sub(s11->c, s01->c), fy));
        rgb dc = rgb_sub(rc, lc);
        int cy = gy == y ? 0 : (gy == y + wy ? 1 : -1);
        for (int gx = x; gx < x + wx + (right ? 1 : 0); gx++) {
            rgb c;
            int cx = gx == x ? 0 : (gx == x + wx ? 1 : -1);
            if (cx >= 0 && cy >= 0) c = (cy ? (cx ? s11 : s10) : (cx ? s01 : s00))->c;
            else c = rgb_add(lc, rgb_scale(dc, fxs[gx - x]));
            rt_put(bk->rt, t, bk->c0 + gx, row, c, s00->item >= 0);   /* the corners agree on it */
        }
    }
}

/* 2-D adaptive subsampling (chapter 5's subsampling over blocks, refined
 * as a quadtree): the corners of B x B blocks are traced; a block whose
 * four corners agree (item, shadows, colours within the threshold) is
 * filled by bilinear interpolation, any other is split in four and each
 * quarter decided the same way from its own corners, down to single
 * pixels. Block rows cover [r0, r0 + B) and the last one also row h - 1,
 * likewise columns; a strip that starts inside a block row refines that
 * block row again (only the rows it owns are written), so every strip
 * height gives the same pixels. Images of at least 2 x 2 pixels. */
static void adaptive_strip(struct rt_state *rt, struct render_target *t)
{
    const int b = rt->adapt, w = rt->w, h = rt->h;
    if (w < 2 || h < 2) {
        for (int y = t->y0; y < t->y1; y++)
            for (int x = 0; x < w; x++) {
                struct rt_sample sm = sample_at(rt, x, y);
                rt_put(rt, t, x, y, sm.c, sm.item >= 0);
            }
        return;
    }
    int r0 = t->y0 - t->y0 % b;
    if (r0 == h - 1) r0 -= b;                    /* the last row belongs to the block above */
    for (; r0 < t->y1 && r0 < h - 1; r0 += b) {
        int r1 = r0 + b < h - 1 ? r0 + b : h - 1;   /* bottom corner row */
        int top = corner_row(rt, r0), bot = corner_row(rt, r1);
        /* the first block's left column starts empty */
        rt->col_left = 0;
        for (int i = 0; i <= b; i++) rt->colbuf_have[0][i] = 0;
        for (int c0 = 0; c0 < w - 1; c0 += b) {
            int c1 = c0 + b < w - 1 ? c0 + b : w - 1;
            int n = (b + 1) * (b + 1);
            for (int i = 0; i < n; i++) rt->grid_have[i] = 0;
            for (int i = 0; i <= b; i++) rt->colbuf_have[1 - rt->col_left][i] = 0;
            struct rt_block bk = { rt, t, c0, r0, c1 - c0, r1 - r0, top, bot };
            refine(&bk, 0, 0, c1 - c0, r1 - r0, c1 == w - 1, r1 == h - 1);
            rt->col_left = 1 - rt->col_left;   /* this block's right column is the next one's left */
        }
    }
}

/* Every pixel of the strip (plain, supersampled, or the book's subsampling). */
static void full_strip(struct rt_state *rt, struct render_target *t)
{
    for (int row = t->y0; row < t->y1; row++) {
        uint8_t *probe = rt->shadow_probe ? rt->shadow_probe + (size_t)row * rt->w : NULL;
        if (rt->subsample > 1 && rt->w > 1) {
            subsampled_row(rt, t, row, probe);
            rt->last_row = -2;
            continue;
        }
        /* adaptive supersampling compares with the row above when that was
         * the last row rendered (also across strips) */
        int have_up = row == rt->last_row + 1;
        for (int col = 0; col < rt->w; col++) {
            rgb c = pixel(rt, col, row, 1, have_up, probe ? probe + col : NULL);
            rt_put(rt, t, col, row, c, rt->px_covered);
        }
        rt->last_row = row;
    }
}

void rt_set_pass(void *work, uint8_t pass)
{
    rt_state_of(work)->pass = pass;
}

int rt_render_strip(void *work, struct render_target *t, struct render_stats *st)
{
    struct rt_state *rt = rt_state_of(work);
    uint32_t rays0 = rt->n.rays, covered0 = rt->n.covered;
    if (rt->pass == RENDER_PASS_COARSE) coarse_strip(rt, t);
    else if (rt->adapt) adaptive_strip(rt, t);
    else full_strip(rt, t);
    if (st) {
        st->rays += rt->n.rays - rays0;
        st->pixels_written += rt->n.covered - covered0;
    }
    return 0;
}
