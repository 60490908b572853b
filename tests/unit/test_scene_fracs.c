/* SPDX-License-Identifier: MIT */
/* test_scene_fracs — the fixed-point renderers at every NUM_FRAC scenec may
 * choose, against the double build, on every scene under firmware/scenes.
 *
 * The core + parser is bundled once per format (core_api_fixed12 …
 * core_api_fixed20, mk/scene.mk; core_api_fixed is NUM_FRAC 16). Each scene
 * is rendered at 240x240 in 16-row strips, frame 0, by the double core and by
 * every fixed core whose format can hold the scene (the parser refuses values
 * outside the format's range; those are reported as "out of range", which is
 * scenec's refusal, not a renderer failure). A format passes a scene when
 * no intermediate saturated and the image is as close to double as the
 * Q15.16 build's limits (docs/scene-format.md "Formats the renderers pass").
 *
 *   test_scene_fracs --report SCENE...   figures of every scene at every format
 *                                         (the doc's table); never fails
 *   test_scene_fracs SCENE=F...          checks each scene at format F (the one
 *                                         scenec chose), Q15.16 as the yardstick
 *
 * A check passes when the image is within the limits every format meets on
 * the book scenes (SSIM >= 0.98, >= 97% of pixels within 2 levels, SSIM no
 * more than 0.005 below Q15.16's) and, for rasterized scenes, nothing
 * saturated. The ray tracer's intersection divisions saturate by design
 * when a ray grazes a plane, triangle or sphere and the hit lies beyond the
 * format's range (the saturated t is rejected as "no hit"), so for
 * ray-traced scenes saturations are reported, not failed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "compare.h"
#include "core_api.h"

extern const struct core_api core_api_fixed12, core_api_fixed13, core_api_fixed14, core_api_fixed15,
    core_api_fixed17, core_api_fixed18, core_api_fixed19, core_api_fixed20;

static const struct {
    int frac;
    const struct core_api *api;
} cores[] = {
    { 12, &core_api_fixed12 }, { 13, &core_api_fixed13 }, { 14, &core_api_fixed14 }, { 15, &core_api_fixed15 },
    { 16, &core_api_fixed }, { 17, &core_api_fixed17 }, { 18, &core_api_fixed18 }, { 19, &core_api_fixed19 },
    { 20, &core_api_fixed20 },
};
#define NCORES (sizeof cores / sizeof cores[0])

enum { W = 240, H = 240, STRIP = 16 };

/* Renders frame 0 of path with api into rgb888 (W*H*3). Returns 0, 1 when the
 * scene does not load (out of range for the format, message in err), -1 on a
 * render error. *sat gets the saturations counted while rendering. */
static int render(const struct core_api *api, const char *path, uint8_t *rgb888, uint32_t *sat, size_t *wsz,
                  char *err, size_t errlen)
{
    void *s = NULL;
    if (api->scene_load(path, &s, err, errlen)) return 1;
    size_t ws = api->work_size(s, W, H, STRIP);
    *wsz = ws;
    void *work = aligned_alloc(8, (ws + 7) & ~(size_t)7);
    static uint16_t px565[W * STRIP];
    struct render_ctx ctx;
    int rc = -1;
    *api->saturations = 0;
    if (work && !api->init(&ctx, s, W, H, STRIP, work, ws) && !api->begin_frame(&ctx, 0)) {
        rc = 0;
        for (int y = 0; y < H && !rc; y += STRIP) {
            struct render_target t = { W, H, (uint16_t)y, (uint16_t)(y + STRIP < H ? y + STRIP : H), px565,
                                       rgb888 + (size_t)3 * W * y, NULL };
            struct render_stats st = { 0 };
            rc = api->render_strip(&ctx, &t, &st);
        }
    }
    *sat = *api->saturations;
    free(work);
    api->scene_free(s);
    return rc;
}

int main(int argc, char **argv)
{
    int report = argc > 1 && !strcmp(argv[1], "--report");
    static uint8_t ref[W * H * 3], img[W * H * 3];
    if (report)
        printf("%-28s %4s %9s %8s %8s %7s %9s %6s\n", "scene", "frac", "psnr_dB", "ssim", "max_err", "diff%",
               "within2%", "sat");
    for (int a = 1 + report; a < argc; a++) {
        char path[1024], err[600], name[256];
        int want = -1;
        snprintf(path, sizeof path, "%s", argv[a]);
        char *eq = strrchr(path, '=');
        if (eq) { *eq = 0; want = atoi(eq + 1); }
        if (!report && (want < 12 || want > 20)) {
            check(0, "scene_fracs_args", "%s: expected SCENE=F with F in 12..20", argv[a]);
            continue;
        }
        const char *base = strstr(path, "scenes/") ? strstr(path, "scenes/") + 7 : path;
        uint32_t sat;
        size_t ws, ws12 = 0, wsmax = 0;
        int fmax = 0;
        if (render(&core_api_double, path, ref, &sat, &ws, err, sizeof err)) {
            check(0, "scene_fracs_double", "%s: %s", path, err);
            continue;
        }
        int kind = SCENE_RASTER;
        {
            void *sc = NULL;
            struct scene_info info;
            if (!core_api_double.scene_load(path, &sc, err, sizeof err)) {
                core_api_double.scene_info(sc, &info);
                kind = info.kind;
                core_api_double.scene_free(sc);
            }
        }
        struct compare_result r16 = { 0 };
        int have16 = 0;
        for (size_t c = 0; c < NCORES; c++) {
            int f = cores[c].frac;
            snprintf(name, sizeof name, "scene_frac%d_%.*s", f, (int)(strlen(base) - 6), base);
            int rc = render(cores[c].api, path, img, &sat, &ws, err, sizeof err);
            if (rc != 1) {
                if (f == 12) ws12 = ws;
                if (ws > wsmax) { wsmax = ws; fmax = f; }
            }
            if (rc == 1) {
                if (report) printf("%-28.*s %4d  out of range: %s\n", (int)(strlen(base) - 6), base, f, err);
                continue;
            }
            if (rc) {
                check(0, name, "render failed");
                continue;
            }
            struct compare_result r;
            compare_rgb888(img, ref, W, H, &r);
            if (f == 16) { r16 = r; have16 = 1; }
            if (!report && f != want) continue;
            if (report) {
                printf("%-28.*s %4d %9.2f %8.5f %8d %7.2f %9.3f %6u\n", (int)(strlen(base) - 6), base, f, r.psnr,
                       r.ssim, r.max_err, r.pct_diff, r.pct_within2, (unsigned)sat);
                continue;
            }
            int ok = r.ssim >= 0.98 && r.pct_within2 >= 97.0 && (!have16 || r.ssim >= r16.ssim - 0.005);
            if (kind == SCENE_RASTER && sat) ok = 0;
            check(ok, name, "ssim %.5f (Q15.16: %.5f), %.3f%% within 2 levels, max error %d, %u saturations", r.ssim,
                  r16.ssim, r.pct_within2, r.max_err, (unsigned)sat);
            if (ok) printf("# %s: ssim %.5f (Q15.16 %.5f), %.3f%% within 2 levels, %u saturations\n", name, r.ssim,
                           r16.ssim, r.pct_within2, (unsigned)sat);
        }
        /* scenec sizes a scene's work memory once, with the core built at
         * NUM_FRAC 12 (tools/scenec/work_probe.c), for whichever format it
         * chooses: that holds only while no format needs more work than
         * NUM_FRAC 12's. Checked here on the host's core at every format
         * that holds the scene (the layout's choices are the target's; only
         * the sizes of pointers differ). */
        if (!report) {
            snprintf(name, sizeof name, "scene_work_frac12_bound_%.*s", (int)(strlen(base) - 6), base);
            check(ws12 > 0 && wsmax <= ws12, name, "NUM_FRAC 12 needs %zu bytes of work, NUM_FRAC %d %zu", ws12, fmax,
                  wsmax);
        }
    }
    return report ? 0 : check_exit();
}
