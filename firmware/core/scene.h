/* SPDX-License-Identifier: MIT */
/* scene.h — what a scene contains, in the renderer's numbers.
 *
 * The one data model shared by the scene parser (host, tools/scene/), the
 * scene compiler (tools/scenec, which emits this struct as const C data for
 * the firmware) and both renderers. All numbers are `num` (see num.h), so a
 * scene exists once per numeric mode; all arrays are pointers to data owned
 * by whoever built the scene (the parser's arena on the host, flash on the
 * firmware). Nothing in here is written by a renderer.
 *
 * Conventions (the book's): world space has +x right, +y up, +z forward;
 * the camera looks along +z from `camera.position`, turned by
 * `camera.rotation`; angles in the scene files are degrees.
 * Canvas coordinates (2D primitives): origin at the centre, +y up, in units
 * of the scene canvas (canvas_w x canvas_h, normally 600 x 600); the
 * renderer scales them to the render size.
 */
#ifndef SCENE_H
#define SCENE_H

#include <stdint.h>
#include "num.h"
#include "scene_features.h"

enum scene_kind { SCENE_RAYTRACE = 0, SCENE_RASTER = 1 };

enum light_type { LIGHT_AMBIENT = 0, LIGHT_POINT = 1, LIGHT_DIRECTIONAL = 2 };

struct scene_light {
    uint8_t type;         /* enum light_type */
    num intensity;
    vec3 v;               /* position (point) or direction toward the light (directional),
                             world space, unnormalised as given */
};

struct scene_camera {
    vec3 position;
    mat3 rotation;        /* applied to primary directions (ray tracer) / inverse applied
                             to the world (rasterizer), as the book does */
    int32_t rot_q29[3][3]; /* the same at 29 fraction bits, as the scene file states it (every
                              entry below 4 in magnitude; all 0: not given): the ray tracer's
                              exact primary directions (rt_num.h) turn by it in fixed point */
};

/* Animation: per-frame increments applied before frame f (f = 0 is the
 * scene as written). Angles in degrees per frame about the y axis. */
struct scene_anim {
    num rot_y_per_frame;
    vec3 move_per_frame;
};

/* ---- ray tracer objects (part I) ---------------------------------------- */

/* Material of a ray-traced object. specular < 0: no highlight (the book's -1). */
struct rt_material {
    rgb color;
    num specular;         /* exponent, integral, 0..1000+; < 0 none */
    num reflective;       /* 0..1 */
    num transparency;     /* 0..1, chapter 5 extension */
    num refraction;       /* index of refraction (1 = none) */
};

enum rt_shape { RT_SPHERE = 0, RT_PLANE = 1, RT_TRIANGLE = 2 };

struct rt_object {
    uint8_t shape;        /* enum rt_shape */
    uint8_t csg_only;     /* 1: only used as a CSG operand, not drawn on its own */
    struct rt_material mat;
    vec3 center;          /* sphere centre */
    num radius;           /* sphere radius */
    vec3 normal;          /* plane: unit normal; plane points p satisfy dot(normal, p) = dist */
    num dist;
    vec3 p[3];            /* triangle corners */
};

enum csg_op { CSG_UNION = 0, CSG_INTERSECTION = 1, CSG_DIFFERENCE = 2 };

/* Constructive solid geometry of two spheres (indices into objects[]). The
 * result takes operand a's material. */
struct rt_csg {
    uint8_t op;           /* enum csg_op */
    uint16_t a, b;
};

/* Chapter 5 switches of the ray tracer: the `raytracer { ... }` options, one
 * member per row of scene_options.def (key, range, default and meaning
 * there; the rows' order is this struct's layout). */
struct rt_options {
#define RT_OPTION(key, field, type, ...) type field;
#include "scene_options.def"
};

/* ---- rasterizer data (part II) ------------------------------------------ */

struct tri_uv { num u, v; };

struct ras_triangle {
    uint16_t v[3];        /* vertex indices */
    rgb color;
    vec3 n[3];            /* per-corner normals (model space); unused if has_normals == 0 */
    struct tri_uv uv[3];  /* per-corner texture coordinates; unused if model untextured */
};

struct ras_model {
    const char *name;
    uint16_t nverts, ntris;
    const vec3 *verts;
    const struct ras_triangle *tris;
    uint8_t has_normals;
    uint8_t has_uvs;
    uint8_t vertex_normals; /* 1: every corner of a vertex has the same normal (the
                               renderer may light the vertex once, not each corner) */
    vec3 bound_center;
    num bound_radius;
};

enum tex_filter { TEX_NEAREST = 0, TEX_BILINEAR = 1, TEX_TRILINEAR = 2, TEX_BILINEAR_BOOK = 3 };

struct ras_texture {
    uint16_t w, h;
    const uint8_t *rgb;   /* w*h*3 bytes, row 0 at the top */
    uint8_t filter;       /* enum tex_filter */
    uint8_t mip_levels;   /* >1 when mipmaps are present (level i at mip[i]) */
    const uint8_t *const *mip;
};

struct ras_instance {
    uint16_t model;
    int16_t texture;      /* -1: none */
    int16_t normal_map;   /* -1: none */
    vec3 position;
    mat3 rotation;
    num scale;
    num specular;         /* exponent; < 0 none */
    struct scene_anim anim;
};

enum shading { SHADE_FLAT = 0, SHADE_GOURAUD = 1, SHADE_PHONG = 2, SHADE_NONE = 3 };

/* How the default path lights Phong-shaded pixels: fast Phong (integer
 * vectors, table powers), ras_compute_illumination per pixel, or at the corners
 * (Gouraud). */
enum ras_lighting { RAS_LIGHT_FAST = 0, RAS_LIGHT_EXACT = 1, RAS_LIGHT_VERTEX = 2 };

/* 2D canvas primitives of raster-01 … raster-04. */
enum prim2d_kind {
    P2D_LINE_BROKEN = 0,  /* raster-01 DrawLineBroken */
    P2D_LINE = 1,         /* DrawLine */
    P2D_WIRE_TRI = 2,     /* DrawWireframeTriangle */
    P2D_FILLED_TRI = 3,   /* DrawFilledTriangle (untruncated spans) */
    P2D_SHADED_TRI = 4,   /* DrawShadedTriangle, h per corner */
};

struct prim2d {
    uint8_t kind;         /* enum prim2d_kind */
    uint8_t npts;         /* 2 (lines) or 3 */
    num x[3], y[3], h[3]; /* canvas coordinates, intensities */
    rgb color;
};

/* 3D lines in world space drawn through ProjectVertex (raster-05). */
struct line3d { vec3 a, b; rgb color; };

/* The `rasterizer { ... }` options, one member per row of scene_options.def
 * (key, range, default and meaning there; the rows' order is this struct's
 * layout). */
struct ras_options {
#define RAS_OPTION(key, field, type, ...) type field;
#include "scene_options.def"
};

/* ---- the scene ------------------------------------------------------- */

/* Products the scene's format analysis (tools/scene/scene_format.c) proved
 * to stay inside num's range at the scene's NUM_FRAC (and every coarser
 * one): the core computes them in 32-bit arithmetic without saturation
 * checks (num_mul_fit, num_add_fit: the same bits as num_mul and num_add
 * wherever the result is in range). struct scene.fits; 0 when the scene was
 * not analysed. */
#define SCENE_FITS_COLOUR 1u      /* ray tracer: colour x intensity, reflection and transparency
                                     weights, their sums (colour intermediates) */
#define SCENE_FITS_HIT    2u      /* ray tracer: D t of a hit point (no planes in the scene: every
                                     hit lies on a bounded object) */

struct scene {
    const char *name;
    uint8_t kind;                 /* enum scene_kind */
    uint8_t fits;                 /* SCENE_FITS_* proved for this scene */
    uint16_t canvas_w, canvas_h;  /* the scene's own canvas (book: 600 x 600) */
    num viewport_w, viewport_h, projection_d;
    rgb background;               /* colour of pixels nothing covers */
    uint8_t background_set;       /* 0: raster default (unwritten = white) */
    struct scene_camera camera;
    struct scene_anim camera_anim;
    uint16_t frames;              /* frames of animation the scene defines (>= 1) */

    uint16_t nlights;
    const struct scene_light *lights;

    /* ray tracer */
    uint16_t nobjects, ncsg;
    const struct rt_object *objects;
    const struct rt_csg *csg;
    struct rt_options rt;

    /* rasterizer */
    uint16_t nmodels, ninstances, ntextures, nprims, nlines;
    const struct ras_model *models;
    const struct ras_instance *instances;
    const struct ras_texture *textures;
    /* per texture, the fast path's texels made by scenec (--fast-textures
     * flash): RGB565 (nearest) or mip_fast_bilinear's words (bilinear),
     * mipmap.h; NULL (or no array): render_init makes them in work memory */
    const void *const *tex_fast;
    /* fast Phong's specular tables made by scenec (--spec-tables flash) at
     * the core's number format: nspec tables of 257 entries and their index
     * step and end (raster_spec_table), one per exponent in the order
     * raster_spec_exponents gives; spec_tab NULL, or nspec not that count:
     * render_init makes them in work memory */
    uint16_t nspec;
    const uint16_t *spec_tab;
    const uint32_t *spec_step;
    const struct prim2d *prims;
    const struct line3d *lines;
    struct ras_options ras;
};

/* The colour of the pixels nothing covers: the scene's background, white
 * for a rasterized scene without one. */
static inline rgb scene_background(const struct scene *s)
{
    return s->kind == SCENE_RASTER && !s->background_set ? rgb_make(NUM_C(255.0), NUM_C(255.0), NUM_C(255.0))
                                                         : s->background;
}

#endif
