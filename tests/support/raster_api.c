/* SPDX-License-Identifier: MIT */
/* raster_api.c — one numeric mode's rasterizer and scene parser behind a
 * table, so test_raster_modes can compare the three builds in one program
 * (compiled once per NUM_MODE, bundled by mk/raster.mk). */
#include "raster_api.h"
#include "raster_harness.h"
#include "scene_files.h"

static int render(const char *name, int book_exact, int w, int h, int rows, struct frame *f)
{
    struct scene *s = book_scene(name);
    if (!s) return -1;
    if (!book_exact) {
        s->ras.book_exact = 0;
        if (s->ras.clip) s->ras.clip = 2;
    }
    return render_frame(s, w, h, rows, 0, f);
}

static uint8_t probe_rgb[600 * 600 * 3];

static int render_texel_probe(const char *name, int book_exact, int w, int h, struct frame *f)
{
    struct scene *s = book_scene(name);
    if (!s || !s->ntextures) return -1;
    struct ras_texture *t = (struct ras_texture *)&s->textures[0];
    for (int y = 0; y < t->h; y++)
        for (int x = 0; x < t->w; x++) {
            uint8_t *p = &probe_rgb[(y * t->w + x) * 3];
            p[0] = (uint8_t)(x & 255);
            p[1] = (uint8_t)(y & 255);
            p[2] = (uint8_t)(((x >> 8) & 15) | ((y >> 8) & 15) << 4);
        }
    t->rgb = probe_rgb;
    t->filter = TEX_NEAREST;
    s->ras.shading = SHADE_NONE;
    if (!book_exact) {
        s->ras.book_exact = 0;
        if (s->ras.clip) s->ras.clip = 2;
    }
    return render_frame(s, w, h, 16, 0, f);
}

static int render_texel_probe_trilinear(const char *name, int w, int h, struct frame *f)
{
    struct scene *s = book_scene(name);
    if (!s || !s->ntextures) return -1;
    struct ras_texture *t = (struct ras_texture *)&s->textures[0];
    t->w = t->h = 256;
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 256; x++) {
            uint8_t *p = &probe_rgb[(y * 256 + x) * 3];
            p[0] = (uint8_t)x;
            p[1] = (uint8_t)y;
            p[2] = 0;
        }
    t->rgb = probe_rgb;
    t->filter = TEX_TRILINEAR;
    t->mip_levels = 0;
    t->mip = 0;
    s->ras.shading = SHADE_NONE;
    s->ras.book_exact = 0;
    if (s->ras.clip) s->ras.clip = 2;
    return render_frame(s, w, h, 16, 0, f);
}

#if NUM_MODE == NUM_MODE_FIXED
const struct raster_api raster_api_fixed = { "fixed", render, render_texel_probe, render_texel_probe_trilinear };
#elif NUM_MODE == NUM_MODE_FLOAT
const struct raster_api raster_api_float = { "float", render, render_texel_probe, render_texel_probe_trilinear };
#else
const struct raster_api raster_api_double = { "double", render, render_texel_probe, render_texel_probe_trilinear };
#endif
