/* SPDX-License-Identifier: MIT */
/* work_probe.c — the renderer's work memory for one scene, measured on the
 * target: an image for the emulated Cortex-M0+ (qemu-system-arm, mps2-an385,
 * tools/bench's start-up code) that parses a scene file with the fixed-point
 * parser and prints render_work_size() as the 32-bit firmware computes it.
 *
 *   qemu-system-arm -M mps2-an385 ... -semihosting-config \
 *       enable=on,target=native,arg=probe,arg=SCENE,arg=W,arg=H,arg=STRIP -kernel work_probe.elf
 *   -> "WORK <bytes>", "SIBLING <bytes>" (render_sibling_work_size: the
 *      second core's context) and "LAYOUT <sizes>" (the sizes of the types of
 *      a compiled scene's const data on the target, tools/scenec/scene_layout.h:
 *      scenec counts its flash with them) (exit 0), or "ERROR <message>" (exit 1)
 *
 * The file is read through semihosting (newlib's rdimon). The work layout
 * depends on the scene's counts and options, not on its numbers, and the
 * image is built at NUM_FRAC 12 (the widest range), so one image serves every
 * scene scenec accepts at any format (tools/scenec/target_work.sh). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bench.h"
#include "render.h"
#include "scene_layout.h"
#include "scene_parse.h"

void initialise_monitor_handles(void);

int bench_main(void)
{
    initialise_monitor_handles();
    static char line[1200], err[600];
    if (bench_cmdline(line, sizeof line - 1)) return bench_fail("no command line");
    char *argv[6];
    int argc = 0;
    for (char *t = strtok(line, " "); t && argc < 6; t = strtok(NULL, " ")) argv[argc++] = t;
    if (argc != 5) return bench_fail("usage: probe SCENE W H STRIP");
    long w = strtol(argv[2], NULL, 10), h = strtol(argv[3], NULL, 10), strip = strtol(argv[4], NULL, 10);
    if (w < 1 || w > 4096 || h < 1 || h > 4096 || strip < 1 || strip > 4096) return bench_fail("bad size");
    struct scene *s = NULL;
    if (scene_load(argv[1], &s, err, sizeof err)) return bench_fail(err);
    size_t n = render_work_size(s, (uint16_t)w, (uint16_t)h, (uint16_t)(strip > h ? h : strip));
    size_t m = render_sibling_work_size(s, (uint16_t)w, (uint16_t)h, (uint16_t)(strip > h ? h : strip));
    scene_free(s);
    bench_puts("WORK ");
    bench_put_u64(n);
    bench_puts("\nSIBLING ");
    bench_put_u64(m);
    struct scene_layout l;
    static char layout[400];
    scene_layout_of_build(&l);
    if (scene_layout_format(&l, layout, sizeof layout)) return bench_fail("layout text too long");
    bench_puts("\nLAYOUT ");
    bench_puts(layout);
    bench_puts("\n");
    return 0;
}
