/* SPDX-License-Identifier: MIT */
/* bench_raytracer.c — instructions per frame of the ray tracer on the
 * emulated MCUs: raytracer-05 at 240x240 rendered in strips of 16 rows (the
 * firmware's way), then the same frame with each chapter-5 option switched
 * on or off, and the bounding-sphere hierarchy on a scene of many spheres.
 * Scenes are the scene files compiled by tools/scenec (book/raytracer-05,
 * book/raytracer-02, bench/grid64), copied to RAM to change their options;
 * the copy is not measured. Figures are instructions, not cycles. */
#include <string.h>
#include "bench.h"
#include "render.h"
#include "bench/grid64.h"
#include "book/raytracer-02.h"
#include "book/raytracer-05.h"

#ifndef BENCH_RT_SIZE
#define BENCH_RT_SIZE 240    /* the profile image (make profile-raytracer) is smaller */
#endif
#define W BENCH_RT_SIZE
#define H BENCH_RT_SIZE
#define STRIP 16

static uint64_t work[4096];          /* 32 KiB: ample for these scenes */
static uint16_t strip_px[W * STRIP];
static uint32_t frame_sum;           /* bench_fnv565 of the last frame's RGB565 pixels */
static int frame_w, frame_h;         /* its size */

#if NUM_MODE == NUM_MODE_FIXED
#define IMAGE_FRAC NUM_FRAC
#else
#define IMAGE_FRAC 0
#endif

/* One frame of s at w x h; returns instructions, or 0 on failure. With
 * coarse_only, only the progressive display's first pass (the preview of
 * 8x8 blocks): the time to the first whole-screen image. */
static uint64_t frame_pass(const struct scene *s, int w, int h, int coarse_only)
{
    struct render_ctx ctx;
    size_t need = render_work_size(s, (uint16_t)w, (uint16_t)h, STRIP);
    if (need > sizeof work) return 0;
    uint64_t t0 = bench_now(), skip = 0;
    frame_sum = BENCH_FNV_INIT;
    frame_w = w;
    frame_h = h;
    if (render_init(&ctx, s, (uint16_t)w, (uint16_t)h, STRIP, work, sizeof work) != 0) return 0;
    render_begin_frame(&ctx, 0);
    if (coarse_only && render_set_pass(&ctx, RENDER_PASS_COARSE) != 0) return 0;
    struct render_stats st;
    memset(&st, 0, sizeof st);
    for (int y = 0; y < h; y += STRIP) {
        struct render_target t = { .width = (uint16_t)w, .height = (uint16_t)h, .y0 = (uint16_t)y,
                                   .y1 = (uint16_t)(y + STRIP < h ? y + STRIP : h), .rgb565 = strip_px };
        if (render_strip(&ctx, &t, &st) != 0) return 0;
        uint64_t t1 = bench_now();
        frame_sum = bench_fnv565(frame_sum, strip_px, (uint32_t)w * (t.y1 - t.y0));
        skip += bench_now() - t1;        /* the checksum is not measured */
    }
    return bench_now() - t0 - skip;
}

static uint64_t frame(const struct scene *s, int w, int h) { return frame_pass(s, w, h, 0); }

/* The row of the frame just rendered: scene file `scene` with `options`
 * set (bench.h's terms; NULL: not an image of it), for accuracy.py. */
static int report(const char *what, const char *variant, uint64_t instr, const char *scene, const char *options)
{
    if (!instr) {
        bench_puts("FAIL bench_raytracer: ");
        bench_puts(variant);
        bench_puts("\n");
        return 1;
    }
    bench_report(what, NUM_NAME, variant, instr * 1000, "frame");
    const struct bench_frame bf = { .scene = scene, .options = options, .checksum = frame_sum,
                                    .width = (uint16_t)frame_w, .height = (uint16_t)frame_h, .strip_rows = STRIP,
                                    .frames = 1, .num_frac = IMAGE_FRAC };
    bench_frame_line(&bf);
    return 0;
}

/* The scene the first row renders, as the scene file states it (the
 * profile images change it: their rows have no accuracy) */
#if defined(BENCH_RT_PROFILE_02) || defined(BENCH_RT_ADAPT) || defined(BENCH_RT_THRESH)
#define BASE_OPTIONS NULL
#else
#define BASE_OPTIONS ""
#endif
#ifdef BENCH_RT_PROFILE_02
#define BASE_SCENE "book/raytracer-02"
#else
#define BASE_SCENE "book/raytracer-05"
#endif

#ifndef BENCH_RT_QUICK
/* One frame of raytracer-05 with s's options as set (`options` in the scene
 * file's terms), reported as `variant`; the options go back to base
 * afterwards. */
static int rt05(struct scene *s, const struct rt_options *base, const char *variant, const char *options)
{
    int r = report("scene:book/raytracer-05", variant, frame(s, W, H), "book/raytracer-05", options);
    s->rt = *base;
    return r;
}
#endif

int bench_main(void)
{
    int bad = 0;
    static struct scene s05;
#ifdef BENCH_RT_PROFILE_02
    s05 = scene_book_raytracer_02;               /* make profile-raytracer-02 */
#else
    s05 = scene_book_raytracer_05;
#endif
    struct scene *s = &s05;
#ifdef BENCH_RT_ADAPT
    s->rt.adaptive_subsample = BENCH_RT_ADAPT;   /* the adaptive profile image */
#endif
#ifdef BENCH_RT_THRESH
    s->rt.adaptive_threshold = BENCH_RT_THRESH;
#endif
    bad |= report("scene:" BASE_SCENE, "strip16", frame(s, W, H), BASE_SCENE, BASE_OPTIONS);
#ifndef BENCH_RT_QUICK
    /* each variant's options as the scene file writes them (accuracy.py
     * measures its accuracy with them set); the coarse pass is no image */
    const struct rt_options base = s->rt;
    bad |= report("scene:book/raytracer-05", "coarse_pass", frame_pass(s, W, H, 1), "book/raytracer-05", NULL);
    s->rt.adaptive_subsample = 2;
    bad |= rt05(s, &base, "adaptive_subsample=2", "adaptive_subsample=2");
    s->rt.adaptive_subsample = 4;
    bad |= rt05(s, &base, "adaptive_subsample=4", "adaptive_subsample=4");
    s->rt.adaptive_subsample = 8;
    bad |= rt05(s, &base, "adaptive_subsample=8", "adaptive_subsample=8");
    /* the real-time option at its cheapest setting above 55 dB */
    s->rt.adaptive_subsample = 4;
    s->rt.adaptive_threshold = 7;
    bad |= rt05(s, &base, "adaptive_subsample=4,adaptive_threshold=7",
                "adaptive_subsample=4,adaptive_threshold=7");
    s->rt.no_shortcuts = 1;
    bad |= rt05(s, &base, "shortcuts=off", "shortcuts=off");
    s->rt.no_frame_cache = 1;
    bad |= rt05(s, &base, "frame_cache=off", "frame_cache=off");
    s->rt.shadow_any_hit = 1;
    bad |= rt05(s, &base, "shadow_any_hit=on", "shadow_any_hit=on");
    s->rt.shadow_any_hit = s->rt.shadow_cache = 1;
    bad |= rt05(s, &base, "shadow_any_hit+cache", "shadow_any_hit=on,shadow_cache=on");
    s->rt.subsample = 2;
    bad |= rt05(s, &base, "subsample=2", "subsample=2");
    s->rt.supersample = 2;
    bad |= rt05(s, &base, "supersample=2", "supersample=2");
    s->rt.adaptive_ss = 1;
    bad |= rt05(s, &base, "adaptive_supersample=on", "adaptive_supersample=on");
    static struct scene s02, grid;
    s02 = scene_book_raytracer_02;
    bad |= report("scene:book/raytracer-02", "strip16", frame(&s02, W, H), "book/raytracer-02", "");
    /* many objects: 8x8 spheres on a plane, 80x80 */
    grid = scene_bench_grid64;
    struct scene *g = &grid;
    bad |= report("scene:grid64@80x80", "plain", frame(g, 80, 80), "bench/grid64", "");
    g->rt.bvh = 1;
    bad |= report("scene:grid64@80x80", "bvh", frame(g, 80, 80), "bench/grid64", "bvh=on");
#endif
    return bad;
}
