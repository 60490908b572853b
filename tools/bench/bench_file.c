/* SPDX-License-Identifier: MIT */
/* bench_file.c — instructions per frame of any scene file on the emulated
 * MCUs: the cost side of the speed/accuracy lab (tools/charts/lab.py).
 *
 * The image parses the scene on the target (the parser of the image's
 * numeric mode, file read through semihosting, not measured), so one image
 * per target, numeric mode and NUM_FRAC measures every scene and every
 * method choice written into a scene file. Arguments (qemu
 * -semihosting-config ...,arg=bench,arg=SCENE,arg=W,arg=H,arg=STRIP,arg=FRAMES[,arg=coarse]):
 * the render size, the strip height and how many of the scene's frames to
 * render (0: all of them); `coarse` renders each frame's progressive preview
 * pass only (render_set_pass RENDER_PASS_COARSE: one ray per block). In
 * fixed point the scene gets struct scene.fits from the format analysis at
 * the image's NUM_FRAC, as host_sim and the scene compiler give it. Measured, in instructions (qemu -icount, not
 * cycles): render_init once, and per frame render_begin_frame and every
 * render_strip. Printed:
 *   RESULT init=I frames=F total=T checksum=C rays=R pixels=P
 * T is the instructions of the F frames (init not included); C a checksum of
 * frame 0's RGB565 pixels (host_sim --out-raw of the same scene, tested by
 * lab.py, shows that the image measured is the image judged); R and P the
 * rays traced and the pixels written in frame 0. Errors: "ERROR message",
 * exit status 1. */
#include <stdlib.h>
#include <string.h>
#include "bench.h"
#include "render.h"
#include "scene_format.h"
#include "scene_parse.h"

void initialise_monitor_handles(void);

static void field(const char *name, uint64_t v)
{
    bench_puts(name);
    bench_put_u64(v);
}

int bench_main(void)
{
    initialise_monitor_handles();
    static char line[1200], err[600];
    if (bench_cmdline(line, sizeof line - 1)) return bench_fail("no command line");
    char *argv[8];
    int argc = 0;
    for (char *t = strtok(line, " "); t && argc < 8; t = strtok(NULL, " ")) argv[argc++] = t;
    if (argc != 6 && !(argc == 7 && !strcmp(argv[6], "coarse")))
        return bench_fail("usage: bench SCENE W H STRIP FRAMES [coarse]");
    int coarse = argc == 7;
    long w = strtol(argv[2], NULL, 10), h = strtol(argv[3], NULL, 10);
    long strip = strtol(argv[4], NULL, 10), nframes = strtol(argv[5], NULL, 10);
    if (w < 1 || w > 4096 || h < 1 || h > 4096 || strip < 1 || nframes < 0 || nframes > 10000)
        return bench_fail("bad size, strip or frames");
    if (strip > h) strip = h;
    struct scene *s = NULL;
    if (scene_load(argv[1], &s, err, sizeof err)) return bench_fail(err);
#if NUM_MODE == NUM_MODE_FIXED
    struct scene_format fmt;
    if (scene_format_choose(s, (int)w, (int)h, NULL, 0, 0, &fmt) == 0)
        s->fits = (uint8_t)scene_format_fits(&fmt, NUM_FRAC);
#endif
    uint16_t frames = s->frames ? s->frames : 1;
    if (nframes && nframes < frames) frames = (uint16_t)nframes;
    size_t need = render_work_size(s, (uint16_t)w, (uint16_t)h, (uint16_t)strip);
    void *work = malloc(need ? need : 1);
    uint16_t *px = malloc((size_t)w * (size_t)strip * sizeof *px);
    if (!work || !px) return bench_fail("out of memory");
    struct render_ctx ctx;
    uint64_t t0 = bench_now();
    if (render_init(&ctx, s, (uint16_t)w, (uint16_t)h, (uint16_t)strip, work, need) != 0)
        return bench_fail("render_init");
    uint64_t init = bench_now() - t0, total = 0;
    uint32_t sum = BENCH_FNV_INIT;   /* bench_fnv565 of frame 0's pixels */
    struct render_stats st0;
    memset(&st0, 0, sizeof st0);
    for (uint16_t f = 0; f < frames; f++) {
        struct render_stats st;
        memset(&st, 0, sizeof st);
        uint64_t a = bench_now();
        if (render_begin_frame(&ctx, f) != 0) return bench_fail("render_begin_frame");
        if (coarse && render_set_pass(&ctx, RENDER_PASS_COARSE) != 0) return bench_fail("render_set_pass");
        total += bench_now() - a;
        for (long y = 0; y < h; y += strip) {
            struct render_target t = { .width = (uint16_t)w, .height = (uint16_t)h, .y0 = (uint16_t)y,
                                       .y1 = (uint16_t)(y + strip < h ? y + strip : h), .rgb565 = px };
            a = bench_now();
            if (render_strip(&ctx, &t, &st) != 0) return bench_fail("render_strip");
            total += bench_now() - a;
            if (f == 0) sum = bench_fnv565(sum, px, (uint32_t)((t.y1 - t.y0) * w));
        }
        if (f == 0) st0 = st;
    }
    field("RESULT init=", init);
    field(" frames=", frames);
    field(" total=", total);
    field(" checksum=", sum);
    field(" rays=", st0.rays);
    field(" pixels=", st0.pixels_written);
    bench_puts("\n");
    return 0;
}
