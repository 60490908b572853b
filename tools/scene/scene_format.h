/* SPDX-License-Identifier: MIT */
/* scene_format.h — the fixed-point number format a scene needs (host side:
 * tools/scenec for the firmware, host_sim for --numeric fixed).
 *
 * The analysis reads a parsed scene's numbers through num_to_double, so it is
 * meant for a scene parsed in the double build (exact values; every fixed
 * build rounds them). It records the largest magnitude of each kind of
 * quantity the renderers keep in `num` (positions and distances, squares
 * narrowed back to num, colour intermediates, screen quantities), each with
 * the object it comes from, and picks the largest NUM_FRAC among the
 * candidates whose range 2^(31 - NUM_FRAC) holds twice the largest quantity
 * (one sum or difference of two of them; longer sums and products are taken
 * wide by the core) — or, for a ray tracer of spheres alone (robust, no CSG
 * or hierarchy: struct scene_format.tight), every sum and difference of
 * positions the core forms, each bounded as formed, and the positions held
 * once. docs/scene-format.md states the argument.
 *
 * Everything in struct scene_format is plain C (no `num`): host programs
 * built without a numeric mode read it through tools/core_api/core_api.h.
 */
#ifndef SCENE_FORMAT_H
#define SCENE_FORMAT_H

#include <math.h>
#include <stddef.h>
#include <stdio.h>

/* struct scene.fits's bits (scene.h's SCENE_FITS_*; repeated here for host
 * programs without a numeric mode, checked equal in scene_format.c). */
#define SCENE_FORMAT_FITS_COLOUR 1u
#define SCENE_FORMAT_FITS_HIT    2u

/* The formats the renderers are checked at (tests/unit/test_scene_fracs.c). */
#define SCENE_FORMAT_FRAC_MIN 12
#define SCENE_FORMAT_FRAC_MAX 20

struct scene_format_range {
    double value;              /* largest magnitude found (0: none) */
    char what[160];            /* object and quantity */
};

/* The farthest from the origin the hit points of a sphere around the
 * camera may lie (scene_format.c, rt_inside). */
#define SCENE_FORMAT_INSIDE_LIMIT 4096.0

/* Why a scene is ill-conditioned for fixed point (scene_format.ill). */
enum scene_ill {
    SCENE_ILL_DIRECTION = 1, SCENE_ILL_RADIUS = 2, SCENE_ILL_PIXEL_STEP = 3, SCENE_ILL_INSIDE = 4, SCENE_ILL_BOOK = 5,
    SCENE_ILL_NEAR = 6, SCENE_ILL_LINE = 7, SCENE_ILL_BOOK_SMALL = 8, SCENE_ILL_T_STEP = 9
};

struct scene_format {
    int width, height;         /* the render size analysed */
    struct scene_format_range position; /* world and camera-space coordinates, distances */
    struct scene_format_range square;   /* squared distances kept in num */
    struct scene_format_range colour;   /* unclamped colour intermediates */
    struct scene_format_range screen;   /* projected coordinates, 1/z, texel coordinates */
    struct scene_format_range other;    /* parameters and their products kept in num: exponents,
                                           t_min, scales, normals, viewport products, frames */
    double smallest;           /* smallest nonzero magnitude relied on (1e300: none) */
    char smallest_what[160];
    double smallest_dir;       /* shortest direction whose squared length the ray tracer forms
                                  (a light direction, the view direction; 1e300: none) */
    char smallest_dir_what[160];
    double pixel_step;         /* ray tracer: the smaller of Vw / W and Vh / H (1e300: none) */
    double book_reach;         /* ray tracer, formulation = book with shadow or reflected rays: the
                                  farthest hit point from the camera (0: none), placed to about
                                  book_reach x 2^-NUM_FRAC, which must stay under epsilon */
    double epsilon;            /* the scene's epsilon (SCENE_ILL_BOOK, SCENE_ILL_T_STEP) */
    double t_dir;              /* ray tracer with shadow or reflected rays: the longest direction a hit
                                  point is formed along (P = O + D t, t in num: P steps by |D| 2^-F) */
    double book_small;         /* formulation = book: the smallest (|D| r)^2 of a sphere, the scale of its
                                  quadratic's k2^2 and k1 k3 (1e300: none) */
    double near_d;             /* rasterizer: the near plane's distance d (0: none) */
    int pixel_at_depth;        /* rasterizer: pixel_step is a pixel's size at the nearest depth */
    double line_px;            /* rasterizer: pixels a 3D line's end moves per step of its x, y or z
                                  (ProjectVertex x d k / z), the largest (0: none) */
    int line;                  /* its line */
    double smallest_radius;    /* smallest sphere radius (ray tracer; 1e300: none): a normal
                                  (P - C) / r is only as precise as r in steps */
    int ill;                   /* refused as ill-conditioned at ill_frac, the format the largest
                                  quantity needs: enum scene_ill (scene_format_refusal) */
    int ill_frac;
    int inside;                /* ray tracer: the sphere around the camera whose hit points lie farthest
                                  from the origin (-1: none) */
    double inside_radius, inside_far;   /* its radius, and |C| + r */
    double inside_limit;       /* SCENE_FORMAT_INSIDE_LIMIT (SCENE_ILL_INSIDE) */
    struct scene_format_range result;   /* ray tracer, tight (below): the sums and differences of
                                           positions and the other results the core forms and never
                                           adds to another num, each bound as formed (held once) */
    int tight;                 /* ray tracer with spheres only, robust, no CSG or hierarchy: positions
                                  and results are held once, the rest twice (scene_format.c) */
    struct scene_format_range big;      /* the largest of the six above */
    double need;               /* 2 x big.value; tight: the larger of twice the largest colour,
                                  screen, square and other value and the largest position or result
                                  grown by 2^-10 of itself and 2^-8 */
    int num_frac;              /* the chosen NUM_FRAC; -1 when nothing fits (refused) */
    int coarsest;              /* the smallest candidate NUM_FRAC */
    int wide;                  /* nothing fits, allow_wide: num_frac = coarsest, wide paths assumed */
    int raytrace;              /* a ray-traced scene */
    int planes;                /* ray tracer: the scene has plane objects (unbounded hits) */
};

struct scene;

/* Analyses S rendered at WIDTH x HEIGHT (both >= 1) and picks among
 * FRACS[0 .. NFRACS) (each in SCENE_FORMAT_FRAC_MIN..MAX; NFRACS >= 1; NULL
 * for all of 20 … 12). Returns 0 with f->num_frac set, or -1 when no candidate
 * holds the scene and ALLOW_WIDE is 0 (f->num_frac = -1; see
 * scene_format_refusal). */
int scene_format_choose(const struct scene *s, int width, int height, const int *fracs, int nfracs,
                        int allow_wide, struct scene_format *f);

/* The products the core may take in 32-bit arithmetic at NUM_FRAC frac
 * (struct scene.fits, SCENE_FITS_*; ray-traced scenes): every quantity of the analysis, twice
 * over, inside 2^(31 - frac), i.e. frac no finer than the format chosen; 0
 * for a refused or wide scene. Colour intermediates are bounded by
 * 255 x 2 x the lights' total intensity (the colour range); a hit point D t
 * by the distance between two points of the scene (the position range),
 * which needs every object bounded (no planes). Inline: host programs read
 * it without a numeric mode (tools/core_api). */
static inline unsigned scene_format_fits(const struct scene_format *f, int frac)
{
    if (!f->raytrace || f->num_frac < 0 || f->wide || frac > f->num_frac || !(f->need < ldexp(1.0, 31 - frac)))
        return 0;
    return SCENE_FORMAT_FITS_COLOUR | (f->planes ? 0u : SCENE_FORMAT_FITS_HIT);
}

/* The bound the analysis takes on where the ray tracer's hit points lie
 * (scene_format.c, "where the ray tracer's hit points lie"): H[k] >= |P|
 * for every hit point P shaded on object k at WIDTH x HEIGHT, or -1 for a
 * plane (its hits are not bounded). H has nobjects entries. */
void scene_format_hit_reach(const struct scene *s, int width, int height, double *H);

/* The ranges found, one per line ("  ranges: ..."), as scenec prints them. */
void scene_format_print_ranges(FILE *out, const struct scene_format *f);

/* The format chosen and the no-overflow argument, several lines (nothing when
 * refused). */
void scene_format_print_argument(FILE *out, const struct scene_format *f);

/* The refusal as one line "PATH:1:1: error: QUANTITY ... exceeds the widest
 * number format ...; WHAT TO CHANGE" (no newline) into msg (len >= 1). The
 * position is the file's start: the quantity is a property of the whole
 * scene, named by object and index in the message. wide_option: the
 * calling tool's option that takes the widest format with 64-bit
 * intermediates (scenec's "--allow-wide"), named as the fix; NULL for a
 * tool without one (the fix named is floating point). */
void scene_format_refusal(const struct scene_format *f, const char *path, const char *wide_option, char *msg,
                          size_t len);

#endif
