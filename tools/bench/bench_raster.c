/* SPDX-License-Identifier: MIT */
/* bench_raster.c — instructions per frame and per drawn pixel of the
 * rasterizer on the emulated MCUs: raster-11 (two cubes and a sphere, Phong)
 * and raster-13 (textured cubes) at 240x240 in strips of 16 rows, each on
 * the book path (the scene as written) and on the default path (sub-pixel
 * edge functions, clipping by splitting; raster-13 with trilinear filtering
 * and its mip chain built in work memory). Scenes are const C data from
 * tools/scenec (build/scenes/book/raster-1{1,3}.c). A first, unmeasured
 * pass with the target's `written` map counts the drawn pixels; the
 * measured pass includes render_init (mip chain), render_begin_frame
 * (transforms, binning) and every strip (background fill included); the
 * checksum of its frame (not measured) and what it rendered follow each row
 * (bench_frame_line), the scene file's options each variant sets included.
 * Figures are instructions, not cycles. */
#include <string.h>
#include "bench.h"
#include "render.h"
#include "book/raster-11.h"
#include "book/raster-13.h"

#define W 240
#define H 240
#define STRIP 16

#if NUM_MODE == NUM_MODE_FIXED
#define IMAGE_FRAC NUM_FRAC
#else
#define IMAGE_FRAC 0
#endif

static uint64_t work[96 * 1024];      /* 768 KiB: the default path's mip chain of a 400x400 texture */
static uint16_t strip_px[W * STRIP];
static uint8_t strip_written[W * STRIP];

static uint32_t frame_sum;            /* bench_fnv565 of the last frame */

/* One frame of s; *pixels (if not null) receives the drawn pixel count.
 * Returns instructions (the checksum not counted), or 0 on failure. */
static uint64_t frame(const struct scene *s, uint32_t *pixels)
{
    uint64_t skip = 0;
    frame_sum = BENCH_FNV_INIT;
    struct render_ctx ctx;
    size_t need = render_work_size(s, W, H, STRIP);
    if (need == 0 || need > sizeof work) return 0;
    uint64_t t0 = bench_now();
    if (render_init(&ctx, s, W, H, STRIP, work, sizeof work) != 0) return 0;
    render_begin_frame(&ctx, 0);
    struct render_stats st;
    memset(&st, 0, sizeof st);
    for (int y = 0; y < H; y += STRIP) {
        struct render_target t = { .width = W, .height = H, .y0 = (uint16_t)y,
                                   .y1 = (uint16_t)(y + STRIP < H ? y + STRIP : H), .rgb565 = strip_px,
                                   .written = pixels ? strip_written : NULL };
        if (render_strip(&ctx, &t, &st) != 0) return 0;
        if (pixels)
            for (int k = 0; k < (t.y1 - t.y0) * W; k++) *pixels += strip_written[k];
        uint64_t t1 = bench_now();
        frame_sum = bench_fnv565(frame_sum, strip_px, (uint32_t)(t.y1 - t.y0) * W);
        skip += bench_now() - t1;
    }
    return bench_now() - t0 - skip;
}

/* The variant of scene file `scene` with `options` set (bench.h's terms):
 * what accuracy.py renders on the host. */
static int measure(const char *what, const char *variant, const struct scene *s, const char *scene,
                   const char *options)
{
    uint32_t px = 0;
    uint64_t instr = frame(s, &px) ? frame(s, NULL) : 0;
    if (!instr || !px) {
        bench_puts("FAIL bench_raster: ");
        bench_puts(what);
        bench_puts(" ");
        bench_puts(variant);
        bench_puts("\n");
        return 1;
    }
    const struct bench_frame bf = { .scene = scene, .options = options, .checksum = frame_sum, .width = W,
                                    .height = H, .strip_rows = STRIP, .frames = 1, .num_frac = IMAGE_FRAC };
    bench_report(what, NUM_NAME, variant, instr * 1000, "frame");
    bench_frame_line(&bf);
    bench_report(what, NUM_NAME, variant, instr * 1000 / px, "pixel");
    bench_frame_line(&bf);
    return 0;
}

/* The default path of a book scene: what real rasterizers add (in the
 * scene file's terms, DEFAULT_PATH). */
#define DEFAULT_PATH "book_exact=off,truncate=off,clip=split"
static struct scene default_path(const struct scene *book)
{
    struct scene s = *book;
    s.ras.book_exact = 0;
    s.ras.project_truncate = 0;
    s.ras.clip = 2;
    return s;
}

static struct ras_texture tex13[4];

int bench_main(void)
{
    int bad = 0;
    bad |= measure("scene:book/raster-11", "book", &scene_book_raster_11, "book/raster-11", "");
    struct scene s11 = default_path(&scene_book_raster_11);
    bad |= measure("scene:book/raster-11", "default", &s11, "book/raster-11", DEFAULT_PATH);

    bad |= measure("scene:book/raster-13", "book", &scene_book_raster_13, "book/raster-13", "");
    struct scene s13 = default_path(&scene_book_raster_13);
    if (s13.ntextures > 4) return 1;
    for (uint16_t i = 0; i < s13.ntextures; i++) {
        tex13[i] = s13.textures[i];
        tex13[i].filter = TEX_TRILINEAR;
        tex13[i].mip_levels = 0;   /* chain built by render_init */
        tex13[i].mip = NULL;
    }
    s13.textures = tex13;
    bad |= measure("scene:book/raster-13", "default-trilinear", &s13, "book/raster-13",
                   DEFAULT_PATH ",texture.filter=trilinear");
    return bad;
}
