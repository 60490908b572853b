/* SPDX-License-Identifier: MIT */
/* rt_render.h — render a ray-tracer scene through the core's entry points
 * into caller buffers (tests; compiled once per numeric mode). */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "render.h"
#include "rt/rt_int.h"

struct rt_run {
    uint32_t rays, primary_rays, shadow_rays, tests;
};

/* Set to 1: rt_render renders without the primary rays' candidate lists
 * (everything else as the scene says), for tests that compare the two. */
static int rt_render_no_tiles;
/* Non-NULL: rt_render records in it each object's hit points
 * (rt_set_hit_probe; nobjects entries, zeroed by the caller). */
static num *rt_render_hit_probe;
/* Non-NULL: rt_render writes the item each primary ray hit (rt_set_item_probe). */
static int16_t *rt_render_item_probe;

/* Renders frame 0 of s at w x h in strips of `strip` rows into rgb888
 * (3*w*h bytes) and, if probe != NULL, the shadow bits of primary hits
 * (w*h bytes). Returns 0 on success. */
static int rt_render(const struct scene *s, int w, int h, int strip, uint8_t *rgb888, uint8_t *probe,
                     struct rt_run *run)
{
    size_t need = render_work_size(s, (uint16_t)w, (uint16_t)h, (uint16_t)strip);
    void *work = aligned_alloc(8, (need + 7) / 8 * 8);
    uint16_t *px = malloc(sizeof(uint16_t) * (size_t)w * (size_t)strip);
    struct render_ctx ctx;
    int rc = -1;
    if (!work || !px) goto out;
    if (render_init(&ctx, s, (uint16_t)w, (uint16_t)h, (uint16_t)strip, work, need) != 0) goto out;
    if (rt_render_no_tiles && s->kind == SCENE_RAYTRACE) rt_state_of(ctx.work)->tiles = 0;
    if (rt_render_hit_probe && s->kind == SCENE_RAYTRACE) rt_set_hit_probe(ctx.work, rt_render_hit_probe);
    if (rt_render_item_probe && s->kind == SCENE_RAYTRACE) rt_set_item_probe(ctx.work, rt_render_item_probe);
    if (probe) {
        memset(probe, 0, (size_t)w * (size_t)h);
        rt_set_shadow_probe(ctx.work, probe);
    }
    if (render_begin_frame(&ctx, 0) != 0) goto out;
    struct render_stats st = { 0 };
    for (int y0 = 0; y0 < h; y0 += strip) {
        struct render_target t = { 0 };
        t.width = (uint16_t)w;
        t.height = (uint16_t)h;
        t.y0 = (uint16_t)y0;
        t.y1 = (uint16_t)(y0 + strip < h ? y0 + strip : h);
        t.rgb565 = px;
        t.rgb888 = rgb888 + (size_t)3 * w * y0;
        /* render_put indexes rgb888 relative to the strip */
        if (render_strip(&ctx, &t, &st) != 0) goto out;
    }
    if (run) {
        struct rt_state *rt = rt_state_of(ctx.work);
        run->rays = rt->n.rays;
        run->primary_rays = rt->n.primary_rays;
        run->shadow_rays = rt->n.shadow_rays;
        run->tests = rt->n.tests;
    }
    rc = 0;
out:
    free(work);
    free(px);
    return rc;
}

#endif
