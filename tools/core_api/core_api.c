/* SPDX-License-Identifier: MIT */
/* core_api.c — the per-mode table (compiled once per NUM_MODE). */
#include "core_api.h"
#include "scene_format.h"
#include "scene_parse.h"
#include "raytracer.h"
#include "raster.h"

_Static_assert(CORE_SCENE_EINPUT == SCENE_EINPUT && CORE_SCENE_EIO == SCENE_EIO && CORE_SCENE_ENOMEM == SCENE_ENOMEM,
               "core_api.h repeats enum scene_status");

#define CAT2(a, b) a##b
#define CAT(a, b) CAT2(a, b)
#if NUM_MODE == NUM_MODE_FIXED
#define API core_api_fixed
#define API_FRAC NUM_FRAC
#elif NUM_MODE == NUM_MODE_FLOAT
#define API core_api_float
#else
#define API core_api_double
#endif
#ifndef API_FRAC
#define API_FRAC 0
#endif

static int load(const char *path, void **scene, char *err, size_t errlen)
{
    struct scene *s = NULL;
    int rc = scene_load(path, &s, err, errlen);
    *scene = s;
    return rc;
}

static int parse_text(const char *path, const char *text, size_t len, void **scene, char *err, size_t errlen)
{
    struct scene *s = NULL;
    int rc = scene_parse_text(path, text, len, &s, err, errlen);
    *scene = s;
    return rc;
}

static int read_text(const char *path, char **text, size_t *len, char *err, size_t errlen)
{
    return scene_read_text(path, text, len, err, errlen);
}

static void free_scene(void *scene) { scene_free(scene); }

static void info(const void *scene, struct scene_info *out)
{
    const struct scene *s = scene;
    out->name = s->name;
    out->kind = s->kind;
    out->canvas_w = s->canvas_w;
    out->canvas_h = s->canvas_h;
    out->frames = s->frames;
    out->nlights = s->nlights;
    out->uses_lights = s->kind == SCENE_RAYTRACE ? !s->rt.unlit : s->ras.shading != SHADE_NONE;
    out->ninstances = s->kind == SCENE_RAYTRACE ? 0 : s->ninstances;
    int rt = s->kind == SCENE_RAYTRACE;
    out->nobjects = rt ? s->nobjects : 0;
    out->recursion_depth = rt ? s->rt.recursion_depth : 0;
    out->supersample = rt ? s->rt.supersample : 0;
    out->bvh = rt ? s->rt.bvh : 0;
    uint32_t tris = 0;
    for (unsigned i = 0; !rt && i < s->ninstances; i++)
        if (s->instances[i].model < s->nmodels) tris += s->models[s->instances[i].model].ntris;
    out->triangles = tris;
    out->nprims = rt ? 0 : s->nprims;
    out->nlines = rt ? 0 : s->nlines;
    out->shadow_volumes = !rt && s->ras.shadow_volume;
    out->shadow_map = !rt && s->ras.shadow_map ? (s->ras.shadow_map_size ? s->ras.shadow_map_size : 128) : 0;
    size_t tb = 0;
    for (unsigned t = 0; t < s->ntextures; t++) {
        size_t w = s->textures[t].w, h = s->textures[t].h;
        for (unsigned l = 0; l < (s->textures[t].mip_levels ? s->textures[t].mip_levels : 1u); l++) {
            tb += w * h * 3;
            w = w > 1 ? w / 2 : 1;
            h = h > 1 ? h / 2 : 1;
        }
    }
    out->texture_bytes = tb;
    struct scene_quality q;
    scene_quality(s, &q);
    out->quality_psnr = q.psnr;
    out->quality_target = q.target;
    out->quality_line = q.line;
    out->quality_col = q.col;
    out->textured = !rt && s->ntextures > 0;
    out->npot_texture = 0;
    for (unsigned t = 0; !rt && t < s->ntextures; t++) {
        unsigned w = s->textures[t].w, h = s->textures[t].h;
        if ((w & (w - 1)) || (h & (h - 1))) out->npot_texture = 1;
    }
    out->reflective = 0;
    for (unsigned i = 0; rt && s->rt.recursion_depth && i < s->nobjects; i++)
        if (num_to_double(s->objects[i].mat.reflective) > 0) out->reflective = 1;
    out->shadows = !rt && (s->ras.shadow_map || s->ras.shadow_volume);
}

static size_t work_size(const void *scene, uint16_t w, uint16_t h, uint16_t strip_rows)
{
    return render_work_size(scene, w, h, strip_rows);
}

static size_t sibling_work_size(const void *scene, uint16_t w, uint16_t h, uint16_t strip_rows)
{
    return render_sibling_work_size(scene, w, h, strip_rows);
}

static int init(struct render_ctx *ctx, const void *scene, uint16_t w, uint16_t h,
                uint16_t strip_rows, void *work, size_t work_size)
{
    return render_init(ctx, scene, w, h, strip_rows, work, work_size);
}

static int format(const void *scene, const char *path, uint16_t w, uint16_t h, struct scene_format *f,
                  char *msg, size_t msglen)
{
    if (!scene_format_choose(scene, w, h, NULL, 0, 0, f))
        return scene_given_zero(scene, f->num_frac, path, msg, msglen);
    scene_format_refusal(f, path, NULL, msg, msglen);
    return -1;
}

static void exact_methods(void *scene)
{
    struct scene *s = scene;
    s->ras.persp_step = 1;
    s->ras.lighting = RAS_LIGHT_EXACT;
    s->rt.adaptive_subsample = 0;
    s->rt.subsample = 1;
}

static void set_fits(void *scene, unsigned fits)
{
    struct scene *s = scene;
    s->fits = (uint8_t)fits;
}

static void decision_probe(struct render_ctx *ctx, uint8_t *shadow, int16_t *item)
{
    if (ctx->scene->kind != SCENE_RAYTRACE) return;
    rt_set_shadow_probe(ctx->work, shadow);
    rt_set_item_probe(ctx->work, item);
}

static void move_camera(void *scene, double dx, double dy, double dz)
{
    struct scene *s = scene;
    vec3 p = s->camera.position;
    s->camera.position = v3_make(num_from_double(num_to_double(p.x) + dx), num_from_double(num_to_double(p.y) + dy),
                                 num_from_double(num_to_double(p.z) + dz));
}

static int instance_facing(const struct render_ctx *ctx, uint16_t i, uint32_t *facing, uint32_t *culled,
                           const char **model)
{
    const struct scene *s = ctx->scene;
    if (s->kind != SCENE_RASTER || i >= s->ninstances) return -1;
    *model = s->models[s->instances[i].model].name;
    return raster_instance_facing(ctx->work, i, facing, culled);
}

static uint32_t features(const void *scene) { return render_features(scene); }

static void set_tex_fast(void *scene, const void *const *marks)
{
    struct scene *s = scene;
    s->tex_fast = marks;
}

static uint16_t spec_exponents(const void *scene, uint32_t exps[RASTER_SPEC_MAX])
{
    return raster_spec_exponents(scene, exps);
}

static void set_spec_tables(void *scene, uint16_t nspec, const uint16_t *tab, const uint32_t *step)
{
    struct scene *s = scene;
    s->nspec = tab ? nspec : 0;
    s->spec_tab = tab;
    s->spec_step = tab ? step : NULL;
}

static uint32_t shadow_rays(const struct render_ctx *ctx)
{
    return ctx->scene->kind == SCENE_RAYTRACE ? rt_shadow_rays(ctx->work) : 0;
}

const struct core_api API = {
    NUM_NAME, load, parse_text, read_text, free_scene, info, work_size, init, render_begin_frame, render_strip,
    &num_saturations, API_FRAC, format, exact_methods, render_set_pass, set_fits, decision_probe, move_camera,
    sibling_work_size, instance_facing, features, set_tex_fast, shadow_rays, spec_exponents, raster_spec_table,
    set_spec_tables,
};
