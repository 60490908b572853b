/* SPDX-License-Identifier: MIT */
/* core_api.h — one renderer core per numeric mode, side by side in one program.
 *
 * The core (firmware/core) and the scene parser (tools/scene) are compiled
 * three times, once per NUM_MODE, and each copy is linked into a single
 * relocatable object whose only global symbol is its core_api_<mode>; host
 * programs pick a mode at run time through this table. Scenes are opaque
 * here because their numbers differ between modes.
 */
#ifndef CORE_API_H
#define CORE_API_H

#include <stddef.h>
#include <stdint.h>
#include "render.h"
#include "raster.h"
#include "scene_format.h"

struct scene_info {
    const char *name;
    int kind;                  /* enum scene_kind */
    uint16_t canvas_w, canvas_h;
    uint16_t frames;
    uint16_t nlights;
    uint8_t uses_lights;       /* ray tracer: not unlit; rasterizer: a shading mode other than none */
    uint16_t ninstances;       /* rasterizer: model instances (0 for the ray tracer) */
    /* ray tracer: what host_sim's cost estimate counts (0 for the rasterizer) */
    uint16_t nobjects;         /* objects (spheres, planes, triangles, CSG operands) */
    uint8_t recursion_depth, supersample, bvh;
    /* rasterizer: what host_sim's cost estimate counts (0 for the ray tracer) */
    uint32_t triangles;        /* a frame's: every instance's model's triangles */
    uint16_t nprims, nlines;   /* 2-D primitives and 3-D lines */
    uint8_t shadow_volumes;    /* chapter 15's shadow volumes: the triangles drawn again */
    uint16_t shadow_map;       /* chapter 15's shadow map: its side (0: none) */
    /* both: the texels the scene holds, every mip level (host_sim's --max-memory) */
    size_t texture_bytes;
    /* the scene's quality block (scene_parse.h's struct scene_quality):
     * psnr 0 when it has none; target 0 none, 1 m0plus, 2 m4f, 3 rp2040;
     * where the block starts */
    double quality_psnr;
    int quality_target, quality_line, quality_col;
    /* rasterizer: the scene has textures (one of them not a power of two a
     * side: the span loops leave it to the per-pixel filler), chapter 15's
     * shadows; ray tracer: reflective objects and reflections traced */
    uint8_t textured, npot_texture, shadows, reflective;
};

/* What scene_load, scene_parse and scene_read return besides 0
 * (scene_parse.h's enum scene_status, for programs without a numeric mode). */
#define CORE_SCENE_EINPUT (-1)
#define CORE_SCENE_EIO    (-2)
#define CORE_SCENE_ENOMEM (-3)

struct core_api {
    const char *numeric;       /* "fixed", "float", "double" */
    int (*scene_load)(const char *path, void **scene, char *err, size_t errlen);
    /* scene_parse.h's scene_parse_text and scene_read_text (the text is the
     * same for every mode: read once, parse per mode) */
    int (*scene_parse)(const char *path, const char *text, size_t len, void **scene, char *err, size_t errlen);
    int (*scene_read)(const char *path, char **text, size_t *len, char *err, size_t errlen);
    void (*scene_free)(void *scene);
    void (*scene_info)(const void *scene, struct scene_info *info);
    size_t (*work_size)(const void *scene, uint16_t w, uint16_t h, uint16_t strip_rows);
    int (*init)(struct render_ctx *ctx, const void *scene, uint16_t w, uint16_t h,
                uint16_t strip_rows, void *work, size_t work_size);
    int (*begin_frame)(struct render_ctx *ctx, uint16_t frame);
    int (*render_strip)(struct render_ctx *ctx, struct render_target *t, struct render_stats *st);
    uint32_t *saturations;     /* the mode's saturation counter */
    int num_frac;              /* NUM_FRAC of a fixed-point core, 0 in float and double */
    /* The number format the scene needs at w x h (tools/scene/scene_format.h):
     * 0 with f->num_frac set, or -1 with the refusal, one line naming PATH, in
     * msg: no format holds the scene, or (f->num_frac set) a value given in
     * the scene would be 0 at that format (scene_parse.h, scene_given_zero).
     * Meaningful on the double core, whose scene holds the exact values. */
    int (*format)(const void *scene, const char *path, uint16_t w, uint16_t h, struct scene_format *f,
                  char *msg, size_t msglen);
    /* Switches a loaded scene to the rasterizer's exact methods (perspective_step = 1,
     * lighting = exact):
     * the reference of --compare. */
    void (*exact_methods)(void *scene);
    /* render_set_pass (render.h): progressive display */
    int (*set_pass)(struct render_ctx *ctx, uint8_t pass);
    /* Sets struct scene.fits (SCENE_FITS_*, from scene_format_fits for this
     * core's NUM_FRAC) on a loaded scene: the products the analysis proved
     * in range, which the core then takes in 32-bit arithmetic. */
    void (*set_fits)(void *scene, unsigned fits);
    /* The ray tracer's primary decisions (nothing for a rasterized scene):
     * once ctx is initialised, each pixel traced one by one afterwards
     * writes to shadow[y * w + x] (w*h bytes, the caller's) the bits of the
     * lights its primary hit found shadowed, 0x80 for no hit (0xFF where
     * the book's subsampling interpolated it), and to item[y * w + x] the
     * item hit (-1: none); other pixels keep what was there. NULL stops. */
    void (*decision_probe)(struct render_ctx *ctx, uint8_t *shadow, int16_t *item);
    /* Moves a loaded scene's camera by (dx, dy, dz) scene units (then init). */
    void (*move_camera)(void *scene, double dx, double dy, double dz);
    /* render_sibling_work_size (render.h): a second core's context */
    size_t (*sibling_work_size)(const void *scene, uint16_t w, uint16_t h, uint16_t strip_rows);
    /* raster_instance_facing (raster.h) of instance i after begin_frame, and
     * its model's name: 0, or -1 (a ray-traced scene, no such instance). */
    int (*instance_facing)(const struct render_ctx *ctx, uint16_t i, uint32_t *facing, uint32_t *culled,
                           const char **model);
    /* render_features (render.h): the features (firmware/core/scene_features.def)
     * a loaded scene needs */
    uint32_t (*features)(const void *scene);
    /* the scene's textures given fast texels (struct scene's tex_fast,
     * scenec --fast-textures flash: one entry per texture, NULL or not):
     * render_work_size then leaves their copies out. scenec's marks point
     * at no texels: for sizes only, never rendered with; the array stays
     * the caller's. */
    void (*set_tex_fast)(void *scene, const void *const *marks);
    /* The shadow rays the ray tracer has traced since ctx was initialised
     * (modulo 2^32: the difference of two readings counts those between;
     * render_stats.rays counts the primary and reflected ones); 0 for a
     * rasterized scene. */
    uint32_t (*shadow_rays)(const struct render_ctx *ctx);
    /* Fast Phong's specular tables (raster.h): a loaded scene's exponents in
     * table order (their count; exps may be NULL), and exponent e's table as
     * this core makes it (in fixed point the same bits as render_init's on
     * any target at this NUM_FRAC). */
    uint16_t (*spec_exponents)(const void *scene, uint32_t exps[RASTER_SPEC_MAX]);
    void (*spec_table)(uint16_t t[257], uint32_t e, uint32_t step[2]);
    /* Gives a loaded scene specular tables (struct scene's nspec, spec_tab,
     * spec_step; scenec --spec-tables flash): render_work_size then leaves
     * their copies out. NULL tab: none. The arrays stay the caller's. */
    void (*set_spec_tables)(void *scene, uint16_t nspec, const uint16_t *tab, const uint32_t *step);
};

extern const struct core_api core_api_fixed, core_api_float, core_api_double;

/* The table for "fixed", "float" or "double"; NULL otherwise. */
const struct core_api *core_api_by_name(const char *numeric);

/* The fixed-point core at NUM_FRAC frac (SCENE_FORMAT_FRAC_MIN .. MAX; NULL
 * otherwise): core_api_fixed12 … core_api_fixed20, core_api_fixed for 16
 * (tools/core_api/core_fracs.c; link the bundles of mk/core.mk's core_frac_bundles). */
const struct core_api *core_api_fixed_frac(int frac);

#endif
