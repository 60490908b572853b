/* SPDX-License-Identifier: MIT */
/* render.c — the dispatcher: render.h's entry points, each handed to the
 * scene's renderer (raytracer.h, raster.h). */
#include <string.h>
#include "render.h"
#include "raytracer.h"
#include "raster.h"

size_t render_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows)
{
    if (FW_FEATURE_RAYTRACER && s->kind == SCENE_RAYTRACE) return rt_work_size(s, width, height);
    if (FW_FEATURE_RASTER && s->kind == SCENE_RASTER) return raster_work_size(s, width, height, strip_rows);
    return 0;
}

int render_init(struct render_ctx *ctx, const struct scene *s, uint16_t width, uint16_t height,
                uint16_t strip_rows, void *work, size_t work_size)
{
    if (width == 0 || height == 0 || strip_rows == 0) return -1;
    if (work_size < render_work_size(s, width, height, strip_rows)) return -1;
    /* (a build with every feature has nothing to check) */
    if (RENDER_FEATURES_BUILT != RENDER_FEATURES_ALL && (render_features(s) & ~RENDER_FEATURES_BUILT)) return -1;
    ctx->scene = s;
    ctx->width = width;
    ctx->height = height;
    ctx->strip_rows = strip_rows;
    ctx->frame = 0;
    ctx->work = work;
    ctx->work_size = work_size;
    ctx->owner = NULL;
    if (FW_FEATURE_RAYTRACER && s->kind == SCENE_RAYTRACE) return rt_init(work, work_size, s, width, height);
    if (FW_FEATURE_RASTER && s->kind == SCENE_RASTER) return raster_init(work, work_size, s, width, height, strip_rows);
    return -1;
}

size_t render_sibling_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows)
{
    if (FW_FEATURE_RASTER && s->kind == SCENE_RASTER) return raster_sibling_work_size(s, width, height, strip_rows);
    return render_work_size(s, width, height, strip_rows);
}

int render_init_sibling(struct render_ctx *ctx, const struct render_ctx *owner, void *work, size_t work_size)
{
    const struct scene *s = owner->scene;
    if (owner->owner) return -1;
    if (!FW_FEATURE_RASTER || s->kind != SCENE_RASTER)
        return render_init(ctx, s, owner->width, owner->height, owner->strip_rows, work, work_size);
    if (work_size < raster_sibling_work_size(s, owner->width, owner->height, owner->strip_rows)) return -1;
    *ctx = *owner;
    ctx->work = work;
    ctx->work_size = work_size;
    ctx->owner = owner;
    return raster_init_sibling(work, work_size, owner->work);
}

int render_set_pass(struct render_ctx *ctx, uint8_t pass)
{
    if (pass == RENDER_PASS_FULL) {
        if (FW_FEATURE_RAYTRACER && ctx->scene->kind == SCENE_RAYTRACE) rt_set_pass(ctx->work, RENDER_PASS_FULL);
        return 0;
    }
    if (!FW_FEATURE_RAYTRACER || pass != RENDER_PASS_COARSE || ctx->scene->kind != SCENE_RAYTRACE) return -1;
    rt_set_pass(ctx->work, pass);
    return 0;
}

int render_set_round(struct render_ctx *ctx, int on)
{
    if (!FW_FEATURE_RAYTRACER || ctx->scene->kind != SCENE_RAYTRACE) return -1;
    rt_set_round(ctx->work, (uint8_t)(on != 0));
    return 0;
}

int render_begin_frame(struct render_ctx *ctx, uint16_t frame)
{
    if (ctx->owner) {
        if (ctx->owner->frame != frame) return -1;
        ctx->frame = frame;
        return FW_FEATURE_RASTER ? raster_sibling_frame(ctx->work) : -1;
    }
    ctx->frame = frame;
    if (FW_FEATURE_RAYTRACER && ctx->scene->kind == SCENE_RAYTRACE) return rt_begin_frame(ctx->work, frame);
    if (FW_FEATURE_RASTER && ctx->scene->kind == SCENE_RASTER) return raster_begin_frame(ctx->work, frame);
    return 0;
}

int render_frame_start(struct render_ctx *ctx, uint16_t frame)
{
    if (ctx->owner) return -1;
    if (!FW_FEATURE_RASTER || ctx->scene->kind != SCENE_RASTER) return render_begin_frame(ctx, frame);
    ctx->frame = frame;
    return raster_frame_start(ctx->work, frame);
}

int render_frame_vertices(const struct render_ctx *ctx, unsigned part, unsigned parts)
{
    if (parts == 0 || part >= parts) return -1;
    if (!FW_FEATURE_RASTER || ctx->scene->kind != SCENE_RASTER) return 0;
    return raster_frame_vertices(ctx->work, part, parts);
}

int render_frame_triangles(struct render_ctx *ctx, unsigned part, unsigned parts)
{
    if (parts == 0 || parts > 2 || part >= parts) return -1;
    if (!FW_FEATURE_RASTER || ctx->scene->kind != SCENE_RASTER) return 0;
    return raster_frame_triangles(ctx->work, part, parts);
}

int render_frame_finish(struct render_ctx *ctx)
{
    if (ctx->owner) return -1;
    if (!FW_FEATURE_RASTER || ctx->scene->kind != SCENE_RASTER) return 0;
    return raster_frame_finish(ctx->work);
}

int render_strip(struct render_ctx *ctx, struct render_target *t, struct render_stats *st)
{
    struct render_stats ignored;
    if (t->y0 >= t->y1 || t->y1 > ctx->height || t->width != ctx->width || t->y1 - t->y0 > ctx->strip_rows)
        return -1;
#if !RENDER_HOST_OUTPUTS
    if (t->rgb888 || t->written) return -1;   /* this build has no code for them */
#endif
    if (!st) {
        memset(&ignored, 0, sizeof ignored);
        st = &ignored;      /* the renderers count into it; the caller asked for nothing */
    }
    if (FW_FEATURE_RAYTRACER && ctx->scene->kind == SCENE_RAYTRACE) return rt_render_strip(ctx->work, t, st);
    if (FW_FEATURE_RASTER && ctx->scene->kind == SCENE_RASTER) return raster_strip(ctx->work, t, st);
    return -1;  /* not a kind this core renders */
}

/* The ray tracer's features are its one (rt/ is linked whole); the
 * rasterizer's are raster_features's (raster_work.c, beside the choices
 * they follow), or just RASTER where a build has no rasterizer. */
uint32_t render_features(const struct scene *s)
{
    if (s->kind == SCENE_RAYTRACE) return RENDER_F(RAYTRACER);
    if (s->kind == SCENE_RASTER) return FW_FEATURE_RASTER ? raster_features(s) : RENDER_F(RASTER);
    return 0;
}

uint16_t render_background_565(const struct render_ctx *ctx)
{
    return rgb_to_565(scene_background(ctx->scene));
}
