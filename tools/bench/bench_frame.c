/* SPDX-License-Identifier: MIT */
/* bench_frame.c — instructions per frame of the renderer core alone (no
 * board, no SPI) for each scene of the firmware's scene table, in the
 * numeric mode the image is built for: the qemu benchmark images of
 * mk/bench.mk (mps2-an386 = Cortex-M4F, mps2-an385 = Cortex-M0+ code).
 * Renders frame 0 at FW_WIDTH x FW_HEIGHT in strips of FW_STRIP_ROWS rows
 * into one strip buffer and reports
 *   BENCH scene:<name> <numeric> strip<R> <milli-instructions> frame
 * followed by what it rendered (bench_frame_line: the frame's checksum, the
 * scene as written, size, strips, the image's format), so that the row's
 * accuracy is measured on the same frame. Only render_strip() is timed; the
 * checksum between strips is not counted. */
#include "bench.h"
#include "fw_scenes.h"
#include "render.h"

#ifndef FW_WIDTH
#define FW_WIDTH 240
#endif
#ifndef FW_HEIGHT
#define FW_HEIGHT 240
#endif
#ifndef FW_STRIP_ROWS
#define FW_STRIP_ROWS 8
#endif

#if NUM_MODE == NUM_MODE_FIXED
#define IMAGE_FRAC NUM_FRAC   /* the image's format (its scenes' coarsest) */
#else
#define IMAGE_FRAC 0
#endif

#define STR2(x) #x
#define STR(x) STR2(x)

static uint16_t strip[FW_WIDTH * FW_STRIP_ROWS];

int bench_main(void)
{
    int rc = 0;
    for (unsigned si = 0; si < fw_scene_count; si++) {
        const struct fw_scene *fs = &fw_scenes[si];
        struct render_ctx ctx;
        uint32_t sum = BENCH_FNV_INIT;
        uint64_t n = 0;
        if (render_init(&ctx, fs->scene, FW_WIDTH, FW_HEIGHT, FW_STRIP_ROWS, fs->work[0],
                        fs->work_size[0]) != 0 ||
            render_begin_frame(&ctx, 0) != 0) {
            bench_puts("FAIL bench_frame: render_init\n");
            rc = 1;
            continue;
        }
        for (uint16_t y = 0; y < FW_HEIGHT; y += FW_STRIP_ROWS) {
            struct render_target t = { .width = FW_WIDTH, .height = FW_HEIGHT, .y0 = y,
                                       .y1 = (uint16_t)(y + FW_STRIP_ROWS > FW_HEIGHT
                                                        ? FW_HEIGHT : y + FW_STRIP_ROWS),
                                       .rgb565 = strip };
            struct render_stats st = { 0 };
            uint64_t t0 = bench_now();
            if (render_strip(&ctx, &t, &st) != 0) rc = 1;
            n += bench_now() - t0;
            sum = bench_fnv565(sum, strip, (uint32_t)(t.y1 - t.y0) * FW_WIDTH);
        }
        char what[80] = "scene:", *p = what + 6;
        for (const char *s = fs->name; *s && p < what + sizeof what - 1; s++) *p++ = *s;
        *p = 0;
        bench_report(what, NUM_NAME, "strip" STR(FW_STRIP_ROWS), n * 1000u, "frame");
        const struct bench_frame bf = { .scene = fs->name, .options = "", .checksum = sum,
                                        .width = FW_WIDTH, .height = FW_HEIGHT, .strip_rows = FW_STRIP_ROWS,
                                        .frames = 1, .num_frac = IMAGE_FRAC };
        bench_frame_line(&bf);
    }
    return rc;
}
