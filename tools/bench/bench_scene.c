/* SPDX-License-Identifier: MIT */
/* bench_scene.c — instructions per frame and per drawn pixel of one
 * compiled raster scene (firmware/scenes/bench/, built by tools/scenec at
 * its own number format) on the emulated MCUs, 240x240 in strips of 16 rows.
 *
 * The image is built once per scene with
 *   -DBENCH_SCENE_H='"bench/NAME.h"' -DBENCH_SCENE=scene_bench_NAME
 *   -DBENCH_WHAT='"scene:bench/NAME"'
 * A first, unmeasured pass over every frame of the scene counts the drawn
 * pixels with the target's `written` map; the measured pass times each
 * frame: render_begin_frame (transforms, binning) and every strip
 * (background fill included). render_init (texture conversion, mip chains)
 * is measured on its own. Reported, in instructions (not cycles):
 *   per "frame"  average over the scene's frames
 *   per "pixel"  that average / the average drawn pixels of a frame
 *   per "init"   render_init once
 *   per "triangle" the frame average / the scene's triangles (scenes of
 *                at least 1,000 triangles: the meshes)
 * with pixels=P (average drawn pixels a frame) and what was rendered
 * (bench_frame_line: frames=F, the checksum of the measured pass's last
 * frame, the options the variant sets), for the scene as written (variant
 * "default") and for each other method of the rasterizer's default path:
 * "perspective_step=1" (the exact per-pixel path, with lighting = exact),
 * 4 (textured scenes), 8, 16, 32 and, for Phong scenes, "lighting=exact",
 * "lighting=vertex". */
#include <string.h>
#include "bench.h"
#include "render.h"
#include BENCH_SCENE_H

#define W 240
#define H 240
#define STRIP 16

static uint64_t work[64 * 1024 / 8 * 16];  /* 1 MiB (the meshes' scenes) */
static uint16_t strip_px[W * STRIP];
static uint8_t strip_written[W * STRIP];
static uint32_t frame_sum;    /* bench_fnv565 of the last frame */
static uint64_t sum_instr;    /* instructions spent on it (not measured) */

#if NUM_MODE == NUM_MODE_FIXED
#define IMAGE_FRAC NUM_FRAC
#else
#define IMAGE_FRAC 0
#endif

/* Frame f of s into ctx; *pixels (if not null) gains its drawn pixels;
 * with sum, frame_sum becomes its checksum. */
static int frame(struct render_ctx *ctx, uint16_t f, uint32_t *pixels, int sum)
{
    frame_sum = BENCH_FNV_INIT;
    if (render_begin_frame(ctx, f) != 0) return -1;
    struct render_stats st;
    memset(&st, 0, sizeof st);
    for (int y = 0; y < H; y += STRIP) {
        struct render_target t = { .width = W, .height = H, .y0 = (uint16_t)y,
                                   .y1 = (uint16_t)(y + STRIP < H ? y + STRIP : H), .rgb565 = strip_px,
                                   .written = pixels ? strip_written : NULL };
        if (render_strip(ctx, &t, &st) != 0) return -1;
        if (pixels)
            for (int k = 0; k < (t.y1 - t.y0) * W; k++) *pixels += strip_written[k];
        if (sum) {
            uint64_t a = bench_now();
            frame_sum = bench_fnv565(frame_sum, strip_px, (uint32_t)(t.y1 - t.y0) * W);
            sum_instr += bench_now() - a;
        }
    }
    return 0;
}

static void report(const char *variant, const char *per, uint64_t milli, uint32_t pixels,
                   const struct bench_frame *bf)
{
    bench_report(BENCH_WHAT, NUM_NAME, variant, milli, per);
    bench_puts("BENCHX pixels=");
    bench_put_u64(pixels);
    bench_puts("\n");
    bench_frame_line(bf);
}

/* The scene with one method changed (`options`, in the scene file's terms),
 * measured and reported. */
static int measure(const struct scene *s, const char *variant, const char *options)
{
    struct render_ctx ctx;
    size_t need = render_work_size(s, W, H, STRIP);
    uint16_t frames = s->frames ? s->frames : 1;
    if (need == 0 || need > sizeof work) { bench_puts("FAIL bench_scene: work memory\n"); return 1; }
    uint64_t t0 = bench_now();
    if (render_init(&ctx, s, W, H, STRIP, work, sizeof work) != 0) { bench_puts("FAIL bench_scene: init\n"); return 1; }
    uint64_t init = bench_now() - t0;
    uint32_t px = 0;
    for (uint16_t f = 0; f < frames; f++)
        if (frame(&ctx, f, &px, 0) != 0) { bench_puts("FAIL bench_scene: frame\n"); return 1; }
    uint64_t total = 0;
    for (uint16_t f = 0; f < frames; f++) {
        sum_instr = 0;
        uint64_t a = bench_now();
        frame(&ctx, f, NULL, f + 1 == frames);   /* the last frame's checksum */
        total += bench_now() - a - sum_instr;
    }
    uint32_t avg_px = (px + frames / 2) / frames;
    const struct bench_frame bf = { .scene = BENCH_WHAT + 6 /* "scene:" */, .options = options,
                                    .checksum = frame_sum, .width = W, .height = H, .strip_rows = STRIP,
                                    .frames = frames, .num_frac = IMAGE_FRAC };
    report(variant, "frame", total * 1000 / frames, avg_px, &bf);
    report(variant, "pixel", avg_px ? total * 1000 / frames / avg_px : 0, avg_px, &bf);
    report(variant, "init", init * 1000, avg_px, &bf);
    uint32_t tris = 0;
    for (uint16_t i = 0; s->kind == SCENE_RASTER && i < s->ninstances; i++)
        if (s->instances[i].model < s->nmodels) tris += s->models[s->instances[i].model].ntris;
    if (tris >= 1000) report(variant, "triangle", total * 1000 / frames / tris, avg_px, &bf);
    return 0;
}

int bench_main(void)
{
    const struct scene *s = &BENCH_SCENE;
    int bad = measure(s, "default", "");
#ifdef BENCH_DEFAULT_ONLY
    return bad;   /* (for profiling: the scene as written only) */
#endif
    if (s->kind != SCENE_RASTER || s->ninstances == 0 || s->ras.book_exact) return bad;
    static const uint8_t steps[] = { 1, 4, 8, 16, 32 };
    static const char *const step_names[] = { "perspective_step=1", "perspective_step=4", "perspective_step=8",
                                              "perspective_step=16", "perspective_step=32" };
    static const char *const step_options[] = { "perspective_step=1,lighting=exact", "perspective_step=4",
                                                "perspective_step=8", "perspective_step=16", "perspective_step=32" };
    struct scene v = *s;
    for (unsigned k = 0; k < sizeof steps; k++) {
        if (steps[k] == (s->ras.persp_step ? s->ras.persp_step : 16)) continue;   /* the default row */
        if (steps[k] == 4 && s->ntextures == 0) continue;                          /* (textured scenes only) */
        v.ras.persp_step = steps[k];
        v.ras.lighting = steps[k] == 1 ? RAS_LIGHT_EXACT : s->ras.lighting;
        bad |= measure(&v, step_names[k], step_options[k]);
    }
    int bilinear = 0;
    for (uint16_t i = 0; i < s->ntextures; i++) bilinear |= s->textures[i].filter == TEX_BILINEAR;
    if (bilinear && !s->ras.bl_weights) {
        /* the one-word texels (made by render_init: scenec's, if any, are
         * the scene's own format) */
        v = *s;
        v.ras.bl_weights = 1;
        v.tex_fast = NULL;
        bad |= measure(&v, "bilinear_weights=coarse", "bilinear_weights=coarse");
    }
    if (s->ras.shading == SHADE_GOURAUD && !s->ras.light_space) {
        /* (the scene's normals as written: the cost of model-space lighting) */
        v = *s;
        v.ras.light_space = 1;
        bad |= measure(&v, "light_space=model", "light_space=model");
    }
    if (s->ras.shading == SHADE_PHONG) {
        v = *s;
        v.ras.lighting = RAS_LIGHT_EXACT;
        bad |= measure(&v, "lighting=exact", "lighting=exact");
        v.ras.lighting = RAS_LIGHT_VERTEX;
        bad |= measure(&v, "lighting=vertex", "lighting=vertex");
    }
    return bad;
}
