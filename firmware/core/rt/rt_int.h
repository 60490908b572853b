/* SPDX-License-Identifier: MIT */
/* rt_int.h — the ray tracer's internals, shared by its files (and the
 * tests that look inside). Not for embedders: render.h is the interface,
 * raytracer.h the contract. */
#ifndef RT_INT_H
#define RT_INT_H

#include <stddef.h>
#include <stdint.h>
#include "raytracer.h"
#include "rt_num.h"

/* ---- state, rays, hits ------------------------------------------------ */

/* A ray O + t*D; `origin` is the object whose surface O lies on (-1: none).
 * The exact tests' forms of D (a, ds, as, tscale) are computed on first use
 * (rt_ray_exact): a ray that every coarse test rejects never needs them. */
struct rt_ray {
    vec3 o, d;
    struct rt_cdir cd;    /* coarse direction (rt_num.h) */
    wnum a;               /* D.D, wide (the book's k1) */
    vec3 ds;              /* D / 2^k with ds.ds = as in [0.25, 4) (robust tests) */
    wnum as;
    wnum aq;              /* rt_quad_a(ds): as the sphere test's quadratic takes it */
    num tscale;           /* 2^-k: t = t' * tscale for a root t' along ds */
    vec3 dx;              /* a primary ray through a pixel centre: D * dxm exactly (rt_exact_comp) */
    wnum dxa;             /* rt_quad_a(dx) */
    int32_t dxm;          /* 0: no exact direction */
    int32_t dxrow;        /* the pixel's row when dx.y, dx.z are its row's unturned (the row
                             parts of rt_obj_cache apply); -1 otherwise */
    int16_t origin;
    uint8_t from_camera;  /* O is the camera: per-frame sphere constants apply */
    uint8_t exact;        /* a, ds, as, tscale computed */
    uint8_t cd_todo;      /* cd not yet formed (rt_ray_cd) */
};

/* A near root as the fraction n / d it was rounded from (an exact primary
 * direction's, rt_quad_near_m; d = 0: none): hits whose t round equal are
 * ordered by it (rt_frac_less), as exact arithmetic orders them. */
struct rt_frac {
    wnum n, d;
};

/* What rt_closest_intersection found. */
struct rt_hit {
    num t;
    int16_t item;         /* drawn item: object index, or nobjects + CSG index */
    int16_t surf;         /* object whose surface was hit (a CSG operand for CSG) */
    uint8_t flip;         /* 1: the normal is the surface's, negated */
    struct rt_frac fr;    /* t's fraction, if it has one */
};

/* One traced primary sample: colour, item hit (-1: none), shadow bits. */
struct rt_sample {
    rgb c;
    int16_t item;
    uint8_t shadow;
};

/* Adaptive subsampling: a block is interpolated when its corners hit the
 * same item with the same shadows and no channel differs by more than
 * this many levels between them (rt_options.adaptive_threshold, default). */
#define RT_SUBSAMPLE_DIFF 6

/* A plane hit whose ray parameter lies beyond the number format (a grazing
 * ray toward a far part of the plane): a hit after every other (strict
 * comparisons against t_max = NUM_MAX still take it), shaded at
 * rt_far_point. Fixed point only: float and double hold such t. */
#define RT_T_FAR (NUM_MAX - NUM_EPS)

/* rt_self_shadowed's terms of the shadow ray's direction d and epsilon
 * (rt_lighting.c): e1 = 3 + floor(4 |d|_1) ulps, with A = d.d at 2F
 * fraction bits alim = A - A / 2^10 - 1 and rhs >= (eps + 16 u) A; ok 0:
 * the test decides nothing along d. */
struct rt_self_dir {
    uint64_t alim, rhs;
    uint32_t e1;
    uint8_t ok;
};

/* Per-object constants, recomputed per frame. */
struct rt_obj_cache {
    wnum r2;              /* radius^2 */
    vec3 co_cam;          /* camera - centre */
    num k3_cam;           /* book: CO.CO - r*r for rays from the camera */
    wnum c_cam;           /* robust: the same, wide */
    wnum cm_cam;          /* c_cam times the render height (rt_quad_near_num) */
    vec3 e1, e2, n;       /* triangle: p1 - p0, p2 - p0, unit normal */
    vec3 bc;              /* bounding sphere of the item (BVH) */
    num br;
    num spec_zero;        /* rt_powi_zero_below(material's exponent) */
    struct rt_csphere cs; /* the sphere for the coarse tests (rt_num.h) */
    struct rt_ccam ccam;  /* ... for the camera's rays (rt_num.h) */
    struct rt_qsphere qs; /* the sphere for the robust test's quadratic (rt_num.h) */
    struct num_recip rrcp;   /* radius, for the normals (P - C) / r */
    int8_t rpow2;         /* fixed point: s >= 0 when the radius is 2^s exactly (rrcp's
                           * quotient is then P - C rounded by a shift), else -1 */
    /* exact primary directions (x vh, y vh, d h) from the camera: CO x D
     * and -CO.D at 2F fraction bits are linear in x, so a row's part is
     * kept (row px_row; -1: none): -CO.D = px_b + -co.x (x vh), |(CO x
     * D).x| = px_x0, .y = co.z (x vh) - px_cxd, .z = px_x2 - co.y (x vh) */
    int32_t px_row;
    int64_t px_b, px_x2, px_cxd;
    uint64_t px_x0;
    uint8_t near_ok;      /* rt_near_c_ok of c_cam and rt_near_na_ok of cm_cam and every exact primary
                             direction: near roots beyond a limit found before the square root */
    struct rt_ivsphere ivs;   /* its per-frame part of the row intervals (rt_num.h) */
};

/* Bounding-sphere hierarchy node: a leaf holds items [first, first+count). */
struct rt_bvh_node {
    vec3 c;
    num r;
    int16_t left, right;  /* children, -1 for a leaf */
    int16_t first, count;
};

struct rt_counters {
    uint32_t rays, primary_rays, shadow_rays;
    uint32_t tests;       /* ray-object (or ray-bound) intersection tests */
    uint32_t covered;     /* pixels written with an object's colour (render_stats.pixels_written) */
};

struct rt_state {
    const struct scene *s;
    uint16_t w, h;
    uint8_t book;         /* 1: book formulation, 0: robust */
    uint8_t depth;        /* reflection depth of primary rays */
    uint8_t cam_rotated;
    uint8_t cached;       /* per-frame constants in use */
    uint8_t shortcuts;    /* coarse rejections and exact early-outs in use */
    uint8_t ss, ss_adaptive, subsample;
    uint8_t adapt;        /* adaptive subsampling block side (0: off) */
    num adapt_diff;       /* its colour threshold */
    num *adapt_ratio;     /* [w (adapt + 1) + i] = num_from_ratio(i, w) for w <= adapt (bilinear weights) */
    uint8_t pass;         /* enum render_pass of the following strips */
    uint8_t round;        /* 1: only the circle inscribed in the frame is seen (rt_set_round) */
    mat3 cam_rot;
    vec3 cam_pos;
    num vw, vh, d;        /* viewport of this render size */
    num sx, sy;           /* Vw/W, Vh/H (cached canvas_to_viewport scale) */
    num wn, hn;           /* W, H as num */
    struct rt_obj_cache *oc;   /* nobjects */
    int16_t *items;            /* drawn items, book order */
    uint16_t nitems;
    int16_t *unbounded;        /* planes (not in the hierarchy) */
    uint16_t nunbounded;
    struct rt_bvh_node *bvh;   /* 2*nitems nodes */
    uint16_t nbvh;
    int16_t *bvh_items;
    int16_t *occluder;         /* per light: last occluder (-1: none) */
    struct rt_ray *light_ray;  /* per light: directional lights' shadow ray (rt_light_constants; its origin set by each shadow test) */
    num *light_len;            /* per light: |L| of directional lights */
    struct num_divisor *light_div; /* per light: the same, as a divisor */
    struct rt_self_dir *light_self; /* per light: a directional light's terms of rt_self_shadowed */
    uint32_t light_fit;        /* bit k: light k (k < 32) a point light whose L = Lpos - P is formed in
                                  32 bits (rt_init) */
    /* shadow candidates (rt_shadow_masks, rt_lighting.c): [j nlights + k]
     * bit i: object i may lie between light k and a point of sphere j
     * (within r_j (1 + 2^-6) of its centre); NULL: none */
    uint32_t *shadow_mask;
    uint32_t shadow_self_ok;   /* bit j: sphere j's radius lets a lit point skip its own test */
    uint16_t amb_k;            /* the lights before the first non-ambient one ... */
    num amb_i;                 /* ... and their intensities' sum, in the lighting's order */
    rgb *row_c;                /* one row of colours (subsampling/adaptive) */
    int16_t *row_item;
    num *col_x;                /* viewport x of each column's centre */
    num *row_y_tab;            /* adaptive subsampling: viewport y of every row (else NULL) */
    num row_y;                 /* viewport y of row row_y_row */
    int32_t row_y_row;
    /* exact primary directions (rt_exact_comp): row dx_row's y vh, d h and
     * their squares' sum at 2F bits; dx_ok bit 1: they fit, bit 2: every
     * column's x vh fits (rt_init.c, init_viewport) */
    int32_t dx_row;
    num dx_y, dx_z;
    wnum dx_yz;
    uint8_t dx_ok;
    /* a turned camera: its rotation at 29 fraction bits (scene_camera.rot_q29;
     * NULL: none, or the animation turned it), and row dx_row's part of the
     * turned direction (rt_exact_turn_row) */
    const int32_t (*cam_q29)[3];
    int64_t dx_turn[3];
    int16_t skip_item;         /* item rt_closest_intersection skips (already tested), -1 none */
    int32_t last_row;          /* row of the notes in row_c/row_item (-2: none) */
    uint8_t px_covered;        /* the last pixel() shows an object */
    uint8_t *shadow_probe;     /* optional, w*h: shadow bits of primary hits */
    int16_t *item_probe;       /* optional, w*h: the item each traced pixel's primary ray hit (-1: none) */
    num *hit_probe;            /* optional, nobjects: largest |P| of each object's hit points */
    struct rt_sample *corner[2]; /* adaptive subsampling: two rows of samples (width) */
    uint8_t *corner_have[2];     /* which of them are traced */
    struct rt_sample *colbuf[2]; /* a block's left and right columns (B + 1) */
    uint8_t *colbuf_have[2];
    uint8_t col_left;            /* which colbuf is the left column */
    int32_t corner_row[2];       /* their image rows (-1: none) */
    struct rt_sample *grid;      /* the block being refined, (B + 1)^2 samples */
    uint8_t *grid_have;          /* which of them are traced */
    /* primary rays' candidate lists (rt_trace.c): per tile column of the
     * current tile row, the items a primary ray through the tile can hit,
     * in book order */
    int16_t *tile_items;         /* ntc * nitems */
    uint16_t *tile_n;            /* ntc */
    uint16_t ntc;
    uint8_t tiles;               /* lists in use (shortcuts, no hierarchy) */
    uint8_t all_spheres;         /* every drawn item a plain sphere (rt_init) */
    uint8_t shadow_test;         /* a shadow ray's search (rt_lighting.c, in_shadow): only whether it hits
                                    matters, not where (sphere tests decide it without the root's value) */
    int32_t tile_row;            /* tile row the lists hold (-1: none) */
    const int16_t *prim_items;   /* the traced primary ray's list (NULL: every item) */
    uint16_t prim_n;
    /* primary rays' candidate intervals (rt_iv_row): per slot (a row modulo
     * iv_rows, its row in iv_tag, -1 none) and object the columns [lo, hi]
     * whose rays may meet the sphere; RT_IV_TODO: not yet formed,
     * INT16_MIN: not proven (the coarse test decides) */
    int16_t *iv;                 /* iv_rows * nobjects * 2 */
    int32_t *iv_tag;             /* iv_rows */
    uint8_t iv_rows;             /* 1, or B + 2 with adaptive subsampling */
    int16_t *dx_iv;              /* row dx_row's (NULL: none) */
    int16_t *prim_iv;            /* the traced primary ray's row (NULL: none) */
    int16_t prim_col;            /* ... and its column (also a turned camera's primary ray's: turn_touch) */
    /* a run of primary rays certainly missing everything: row bg_row's
     * columns [bg_lo, bg_hi] (-1: none), where every candidate's interval
     * left the ray at bg_lo out and begins after bg_hi, inside bg_lo's tile
     * (closest_prim); its rays take the background without a test
     * (rt_trace_pixel), counted as the bg_tests tests they skip */
    int32_t bg_row;
    int16_t bg_lo, bg_hi;
    uint16_t bg_tests;
    struct rt_counters n;
};

/* Tiles of the primary rays' candidate lists: RT_TILE x RT_TILE pixels. A
 * tile row's lists serve its rows and RT_MAX_ADAPT below (adaptive
 * subsampling's blocks reach that far past a tile's edge), and are proven
 * for one row and one column more on every side (sub-pixel samples). */
#define RT_TILE 16

/* The mark of a candidate interval not yet formed. */
#define RT_IV_TODO INT16_MAX

/* A CSG item's index into scene.csg (items past the objects are CSGs). */
#define CSG_ITEM(rt, item) ((item) - (int16_t)(rt)->s->nobjects)

/* The state inside the work memory (render_ctx.work). */
static inline struct rt_state *rt_state_of(void *work) { return (struct rt_state *)work; }

/* The probes (rt_set_shadow_probe, ...) are declared in raytracer.h. */

/* rt_intersect.c */
struct rt_ray rt_make_ray(vec3 o, vec3 d, int16_t origin, uint8_t from_camera);
void rt_ray_init(struct rt_ray *r, const vec3 *o, const vec3 *d, int16_t origin, uint8_t from_camera);
/* A primary ray from the camera whose coarse direction is formed on first
 * use (rt_ray_cd): along its row's candidate intervals few spheres need it. */
void rt_ray_init_primary(struct rt_ray *r, const vec3 *o, const vec3 *d);
void rt_ray_cd_now(struct rt_ray *r);
static inline void rt_ray_cd(struct rt_ray *r)
{
    if (r->cd_todo) rt_ray_cd_now(r);
}
/* Computes the exact tests' forms of the direction (once per ray). */
void rt_ray_exact(struct rt_ray *r);
/* The book's IntersectRaySphere: its two roots (the book's order); 0 for a
 * miss. *nf (may be NULL) gets t2's fraction when it is an exact primary
 * direction's near root (else d = 0). */
int rt_intersect_ray_sphere(const struct rt_state *rt, int16_t obj, struct rt_ray *ray,
                            num *t1, num *t2, struct rt_frac *nf);
/* The book's ClosestIntersection: closest hit with t_min < t < t_max (strict, earlier item wins ties); 0 if none.
 * any_hit: stop at the first hit found (shadow rays). */
int rt_closest_intersection(struct rt_state *rt, struct rt_ray *ray, num t_min, num t_max,
                            struct rt_hit *hit, int any_hit);
/* Whether `item` is hit with t_min < t < t_max. */
int rt_item_hit(struct rt_state *rt, int16_t item, struct rt_ray *ray, num t_min, num t_max,
                struct rt_hit *hit);
/* A shadow ray's search (with the shortcuts) over the objects of mask (bit
 * i: object i, a plain sphere): first (-1: none) when it is one of them,
 * then the others in book order; 1 at the first hit, its item in
 * hit->item. */
int rt_shadow_search(struct rt_state *rt, struct rt_ray *ray, num t_min, num t_max, uint32_t mask, int16_t first,
                     struct rt_hit *hit);
vec3 rt_hit_normal(const struct rt_state *rt, const struct rt_hit *hit, const vec3 *p);
vec3 rt_far_point(const struct rt_ray *ray);
/* The interval of object obj in the traced primary ray's row (rt->dx_row)
 * into e[0], e[1] (rt_state.iv). */
void rt_row_interval(const struct rt_state *rt, int16_t obj, int16_t *e);

/* rt_scene.c: the bounding-sphere hierarchy over rt->items (planes aside,
 * unbounded); the per-frame object constants (after the camera moved). */
void rt_build_bvh(struct rt_state *rt);
void rt_frame_constants(struct rt_state *rt);
/* Directional lights' shadow-ray forms and |L| (the lights do not move). */
void rt_light_constants(struct rt_state *rt);

/* rt_trace.c: refraction direction (unit) by Snell's law for incoming D
 * (any length) at a surface with unit normal N and index of refraction ior
 * (N facing the incoming ray: entering; otherwise leaving); 0 on total
 * internal reflection. */
int rt_refract(vec3 d, vec3 n, num ior, vec3 *out);
/* What a primary ray found: the item it hit (-1: none) and the lights it
 * found shadowed there (bit k: light k). */
struct rt_prim {
    int16_t item;
    uint8_t shadow;
};
/* rt_trace.c, TraceRay of one primary ray (from the camera, to the scene's
 * reflection depth) through canvas point (x, y) (sub-pixel allowed), or
 * through the centre of pixel (col, row) (its viewport x and y from the
 * tables): its colour, and *prim. */
rgb rt_trace_canvas(struct rt_state *rt, num x, num y, struct rt_prim *prim);
rgb rt_trace_pixel(struct rt_state *rt, int col, int row, struct rt_prim *prim);
/* The same for pixel (col, row), as a sample. */
static inline void rt_sample_pixel(struct rt_state *rt, int col, int row, struct rt_sample *s)
{
    struct rt_prim pr;
    s->c = rt_trace_pixel(rt, col, row, &pr);
    s->item = pr.item;
    s->shadow = pr.shadow;
}

/* rt_adaptive.c: the strip by 2-D adaptive subsampling (rt->adapt > 0). */
void rt_adaptive_strip(struct rt_state *rt, struct render_target *t);

/* rt_pixels.c: writes pixel (x, y) of the strip, with render.h's coverage:
 * the mask (t->written) and the count of render_stats.pixels_written. */
void rt_put(struct rt_state *rt, struct render_target *t, int x, int y, rgb c, int covered);
/* rt_pixels.c: some channel of a and b more than `diff` apart. */
int rt_colours_differ(rgb a, rgb b, num diff);

/* N (2 N.L) - L: the book's ReflectRay (L = V) and the specular term's R,
 * for ndl = N.L as v3_dot rounds it. small (fixed point): |N_i| <= 2^(F+1)
 * and |L_i| <= 2^26 (rt_v3_within), so |N.L| <= 3 * 2^27 and
 * |N_i 2 N.L| / 2^F <= 2 * 3 * 2^28 < 2^31 - 2^26 - 1: the rounded products
 * and the differences in 32 bits, never saturating (the same bits as
 * v3_scale and v3_sub); 2 N.L as a sum, the same bits as the product. */
RT_ALWAYS_INLINE vec3 rt_reflect(vec3 n, vec3 l, num ndl, int small)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (small) {
        vec3 r;
        num m = 2 * ndl;
        r.x = num_mul_round32(n.x, m) - l.x;
        r.y = num_mul_round32(n.y, m) - l.y;
        r.z = num_mul_round32(n.z, m) - l.z;
        return r;
    }
    /* 2 N.L past the range (|N.L| > NUM_MAX / 2, with |L| above half the
     * range: the format analysis holds |L| and |R| = |L| once, not twice):
     * each component's product (2 N_i) N.L exact and rounded once, as
     * num_mul rounds N_i (2 N.L), and the difference narrowed once; where
     * 2 N.L fits, the path below, unchanged */
    if (ndl > NUM_MAX / 2 || ndl < -(NUM_MAX / 2))
        return v3_make(wnum_to_num(wnum_sub(num_mul_wide(num_add(n.x, n.x), ndl), wnum_from_num(l.x))),
                       wnum_to_num(wnum_sub(num_mul_wide(num_add(n.y, n.y), ndl), wnum_from_num(l.y))),
                       wnum_to_num(wnum_sub(num_mul_wide(num_add(n.z, n.z), ndl), wnum_from_num(l.z))));
#else
    (void)small;
#endif
    return v3_sub(v3_scale(n, num_add(ndl, ndl)), l);
}

/* rt_lighting.c, fixed point: 1 only when a shadow ray from P along d (|d_i|
 * <= 2^26 raw) certainly meets its own plain sphere obj at the root 2b/a'
 * in (epsilon, 1), for the normal n = rt_hit_normal's (|n_i| <= 2^(F+1))
 * and ndl = n.d as the lighting rounds it, ndl < 0; sd: the terms of d
 * (rt_self_dir_make(d, epsilon), made once for a directional light), or
 * NULL (made here). */
int rt_self_shadowed(const struct rt_state *rt, int16_t obj, num ndl, const vec3 *d, const struct rt_self_dir *sd);
struct rt_self_dir rt_self_dir_make(const vec3 *d, num epsilon);
/* rt_lighting.c: the shadow candidates (rt_state.shadow_mask), once at
 * rt_init (objects and lights do not move). */
void rt_shadow_masks(struct rt_state *rt);
/* Whether a scene gets them (its work memory holds them). */
int rt_shadow_masks_fit(const struct scene *s);

/* rt_lighting.c, the book's ComputeLighting: intensity at P (normal N, view V = -D) for specular exponent s
 * (unit_normal: N is a sphere's (P - C) / r, of length 1 up to rounding)
 * (s_zero: rt_powi_zero_below of it, or -1).
 * *shadow_bits gets bit k set when light k is shadowed (may be NULL). */
num rt_compute_lighting(struct rt_state *rt, vec3 p, vec3 n, int unit_normal, vec3 v, num s, num s_zero,
                        int16_t origin, uint8_t *shadow_bits);

#endif
