/* SPDX-License-Identifier: MIT */
/* test_render_contract.c — render.h's contract holds the same way for both
 * renderers: the coverage mask (render_target.written) is 1 exactly where a
 * pixel shows the scene and 0 where only the background is, the
 * render_stats.pixels_written of a frame counts the writes of scene content
 * (the 1s of the mask, plus the rasterizer's overdraw), the stats
 * pointer may be NULL, every strip height gives the same pixels and mask,
 * the entry points refuse bad arguments with -1 and the error codes, and no
 * pixel outside the strip is touched.
 *
 * Scenes: the book's raytracer-02 (white background, three spheres) and
 * raster-11 (its cubes and sphere), and raytracer-05 with each way the ray
 * tracer fills pixels (plain, supersampled, the book's subsampling, adaptive
 * subsampling, the progressive preview), and raytracer-02 through a round
 * glass (render_set_round). Built per numeric mode. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render.h"
#include "check.h"
#include "scene_files.h"

#define W 96
#define H 72

struct frame {
    uint16_t px[W * H];
    uint8_t mask[W * H];
    uint32_t written;           /* render_stats.pixels_written over the frame */
};

static uint64_t work[65536];
static int round_glass;         /* render(): render_set_round(ctx, 1) */
static uint32_t last_rays;      /* render(): render_stats.rays of the frame */

/* One frame in strips of `strip` rows with a guard word after each strip's
 * buffers; 0, or -1 when the renderer failed or wrote outside a strip. */
static int render(const struct scene *s, int strip, int pass, int null_stats, struct frame *f)
{
    struct render_ctx ctx;
    size_t need = render_work_size(s, W, H, (uint16_t)strip);
    if (need > sizeof work) return -1;
    if (render_init(&ctx, s, W, H, (uint16_t)strip, work, sizeof work) != 0) return -1;
    if (render_begin_frame(&ctx, 0) != 0) return -1;
    if (pass && render_set_pass(&ctx, (uint8_t)pass) != 0) return -1;
    if (round_glass && render_set_round(&ctx, 1) != 0) return -1;
    struct render_stats st = { 0 };
    static uint16_t spx[W * H + 8];
    static uint8_t smask[W * H + 8];
    for (int y0 = 0; y0 < H; y0 += strip) {
        int y1 = y0 + strip < H ? y0 + strip : H;
        size_t n = (size_t)(y1 - y0) * W;
        for (size_t i = 0; i < n + 8; i++) { spx[i] = 0xA5A5; smask[i] = 0x5A; }
        struct render_target t = { .width = W, .height = H, .y0 = (uint16_t)y0, .y1 = (uint16_t)y1,
                                   .rgb565 = spx, .written = smask };
        if (render_strip(&ctx, &t, null_stats ? NULL : &st) != 0) return -1;
        for (size_t i = n; i < n + 8; i++)
            if (spx[i] != 0xA5A5 || smask[i] != 0x5A) return -1;
        for (size_t i = 0; i < n; i++)
            if (smask[i] > 1) return -1;    /* every pixel's mask written, 0 or 1 */
        memcpy(f->px + (size_t)y0 * W, spx, n * sizeof *spx);
        memcpy(f->mask + (size_t)y0 * W, smask, n);
    }
    f->written = st.pixels_written;
    last_rays = st.rays;
    return 0;
}

static uint32_t ones(const struct frame *f)
{
    uint32_t n = 0;
    for (int i = 0; i < W * H; i++) n += f->mask[i];
    return n;
}

/* The mask against the picture: background-coloured where 0 (the scene's
 * background, RGB565), and somewhere covered and somewhere not. */
static void check_frame(const char *name, const struct scene *s, const struct frame *f)
{
    uint32_t n = ones(f);
    if (s->kind == SCENE_RAYTRACE)
        check(f->written == n, name, "pixels_written %lu, mask has %lu ones", (unsigned long)f->written,
              (unsigned long)n);
    else
        check(f->written >= n && f->written < 2 * n, name, "pixels_written %lu for %lu covered pixels",
              (unsigned long)f->written, (unsigned long)n);
    check(n > W * H / 20 && n < W * H - W * H / 20, name, "coverage %lu of %d pixels", (unsigned long)n, W * H);
    rgb bg = s->background_set ? s->background : rgb_make(NUM_C(255.0), NUM_C(255.0), NUM_C(255.0));
    uint16_t bgc = rgb_to_565(bg);
    long off = 0;
    for (int i = 0; i < W * H; i++) off += !f->mask[i] && f->px[i] != bgc;
    check(off == 0, name, "%ld uncovered pixels not the background", off);
}

static void same(const char *name, const struct frame *a, const struct frame *b)
{
    check(!memcmp(a->px, b->px, sizeof a->px) && !memcmp(a->mask, b->mask, sizeof a->mask) &&
              a->written == b->written,
          name, "pixels, mask or count differ between strip heights");
}

int main(void)
{
    static struct frame f, g;
    char name[96];

    /* both renderers, every strip height the same frame */
    const char *scenes[] = { "raytracer-02", "raster-11" };
    for (int k = 0; k < 2; k++) {
        struct scene *s = book_scene(scenes[k]);
        snprintf(name, sizeof name, "mask_%s_%s", scenes[k], NUM_NAME);
        check(render(s, H, 0, 0, &f) == 0, name, "render failed or wrote outside the strip");
        check_frame(name, s, &f);
        static const int strips[] = { 1, 7, 16 };
        for (int j = 0; j < 3; j++) {
            snprintf(name, sizeof name, "mask_%s_strip%d_%s", scenes[k], strips[j], NUM_NAME);
            check(render(s, strips[j], 0, 0, &g) == 0, name, "render failed or wrote outside the strip");
            same(name, &f, &g);
        }
        snprintf(name, sizeof name, "stats_null_%s_%s", scenes[k], NUM_NAME);
        check(render(s, 16, 0, 1, &g) == 0 && !memcmp(f.px, g.px, sizeof f.px) && !memcmp(f.mask, g.mask, sizeof f.mask),
              name, "render_strip with NULL stats differs");
    }

    /* every way the ray tracer fills pixels keeps the contract */
    struct {
        const char *name;
        uint8_t ss, adaptive_ss, subsample, adapt, pass;
    } modes[] = {
        { "plain", 1, 0, 1, 0, 0 },
        { "supersample3", 3, 0, 1, 0, 0 },
        { "adaptive_ss", 2, 1, 1, 0, 0 },
        { "subsample3", 1, 0, 3, 0, 0 },
        { "adaptive_subsample4", 1, 0, 1, 4, 0 },
        { "coarse_pass", 1, 0, 1, 0, RENDER_PASS_COARSE },
    };
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        struct scene *s = book_scene("raytracer-02");
        s->rt.supersample = modes[m].ss;
        s->rt.adaptive_ss = modes[m].adaptive_ss;
        s->rt.subsample = modes[m].subsample;
        s->rt.adaptive_subsample = modes[m].adapt;
        snprintf(name, sizeof name, "mask_raytracer_%s_%s", modes[m].name, NUM_NAME);
        check(render(s, 16, modes[m].pass, 0, &f) == 0, name, "render failed or wrote outside the strip");
        check_frame(name, s, &f);
        snprintf(name, sizeof name, "mask_raytracer_%s_strip5_%s", modes[m].name, NUM_NAME);
        check(render(s, 5, modes[m].pass, 0, &g) == 0, name, "render failed or wrote outside the strip");
        if (modes[m].pass == 0) same(name, &f, &g);
        else check(g.written == ones(&g), name, "count differs from the mask");
    }

    /* a round glass (render_set_round): the plain pixels outside the circle
     * of diameter H centred in the frame get the background, no ray; inside
     * it the frame is the same; the contract holds; a rasterized scene
     * refuses it */
    {
        struct scene *s = book_scene("raytracer-02");
        snprintf(name, sizeof name, "round_glass_raytracer_%s", NUM_NAME);
        int ok = render(s, 16, 0, 0, &f) == 0;
        uint32_t rays_all = last_rays;
        round_glass = 1;
        ok = ok && render(s, 16, 0, 0, &g) == 0;
        round_glass = 0;
        rgb bg = s->background;
        long wrong = 0, outside = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int32_t dx = 2 * x + 1 - W, dy = 2 * y + 1 - H;
                int i = y * W + x;
                if (dx * dx + dy * dy > H * H) {
                    outside++;
                    wrong += g.px[i] != rgb_to_565(bg) || g.mask[i];
                } else {
                    wrong += g.px[i] != f.px[i] || g.mask[i] != f.mask[i];
                }
            }
        check(ok && wrong == 0 && rays_all - last_rays >= (uint32_t)outside, name,
              "%ld pixels wrong, rays %lu -> %lu for %ld pixels outside", wrong, (unsigned long)rays_all,
              (unsigned long)last_rays, outside);
        check_frame(name, s, &g);
        struct render_ctx ctx;
        check(render_init(&ctx, book_scene("raster-11"), W, H, 16, work, sizeof work) == 0 &&
                  render_set_round(&ctx, 1) == -1,
              "round_glass_raster_refused", "accepted");
    }

    /* bad arguments: -1, nothing rendered */
    {
        struct scene *s = book_scene("raytracer-02");
        struct render_ctx ctx;
        check(render_init(&ctx, s, 0, H, 16, work, sizeof work) == -1, "init_zero_width", "accepted");
        check(render_init(&ctx, s, W, H, 16, work, 8) == -1, "init_small_work", "accepted");
        check(render_init(&ctx, s, W, H, 16, work, sizeof work) == 0, "init_ok", "refused");
        render_begin_frame(&ctx, 0);
        struct render_target t = { .width = W, .height = H, .y0 = 10, .y1 = 10, .rgb565 = f.px };
        check(render_strip(&ctx, &t, NULL) == -1, "strip_empty", "accepted");
        t.y1 = H + 1;
        check(render_strip(&ctx, &t, NULL) == -1, "strip_past_end", "accepted");
        t.y1 = 20;
        check(render_strip(&ctx, &t, NULL) == 0, "strip_ok", "refused");
        t.y1 = 27;
        check(render_strip(&ctx, &t, NULL) == -1, "strip_taller_than_init", "accepted");
        t.y1 = 20;
        t.width = W - 1;
        check(render_strip(&ctx, &t, NULL) == -1, "strip_wrong_width", "accepted");
        check(render_set_pass(&ctx, 7) == -1, "pass_unknown", "accepted");
        struct scene *r = book_scene("raster-11");
        check(render_init(&ctx, r, W, H, 16, work, sizeof work) == 0 &&
                  render_set_pass(&ctx, RENDER_PASS_COARSE) == -1,
              "pass_coarse_raster", "accepted");
    }
    return check_exit();
}
