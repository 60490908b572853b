/* SPDX-License-Identifier: MIT */
/* bench.h — measurement API of the emulated-MCU benchmark images.
 *
 * An image runs in qemu-system-arm with -icount shift=0 (one instruction =
 * 1 ns of virtual time) on mps2-an385 (code built for cortex-m0plus) or
 * mps2-an386 (cortex-m4, FPU enabled). bench_now() reads the board's
 * SysTick (25 MHz, extended to 64 bits by its interrupt) and returns virtual
 * nanoseconds, i.e. instructions executed; resolution 40 instructions.
 * These are instruction counts, not cycles.
 *
 * Output goes through semihosting; tools/bench/run.py turns each
 *   BENCH <what> <numeric> <variant> <milli-instructions> <per>
 * line into one JSON line of build/bench/results.jsonl. The image's
 * bench_main() returns 0 on success; the exit status reaches qemu. */
#ifndef BENCH_H
#define BENCH_H

#include <stdint.h>

uint64_t bench_now(void);                 /* virtual ns = instructions since reset */
void bench_puts(const char *s);           /* semihosting SYS_WRITE0 */
void bench_put_u64(uint64_t v);
/* One result line: what ("op:NAME", "scene:NAME"), numeric ("fixed",
 * "float", "double"), variant (method, no spaces), instructions per unit
 * `per` ("op", "frame", "pixel") in thousandths (12345 means 12.345). */
void bench_report(const char *what, const char *numeric, const char *variant,
                  uint64_t milli_instructions, const char *per);
/* The frame checksum: 32-bit FNV-1a of RGB565 pixels, row by row, each
 * pixel's low byte first (host_sim --out-raw's byte order), continued from
 * h; a frame's sum starts at BENCH_FNV_INIT. host_sim --stats prints the
 * same sum of every frame it renders ("checksum"). */
#define BENCH_FNV_INIT 2166136261u
uint32_t bench_fnv565(uint32_t h, const uint16_t *px, uint32_t n);
/* What a scene row measured, for tools/bench/accuracy.py, which measures
 * the row's accuracy on exactly this configuration and checks that host_sim
 * renders the same frame. Printed by bench_frame_line() as
 *   BENCHX frame_checksum=C scene=S options=O width=W height=H strip_rows=R frames=F [num_frac=Q]
 * right after the row's BENCH line (options= only when options is not NULL). */
struct bench_frame {
    const char *scene;       /* firmware/scenes/<scene>.scene, e.g. "book/raster-11" */
    const char *options;     /* the options set on the scene as written, in the scene file's
                              * terms: KEY=VALUE,... of its rasterizer or raytracer block,
                              * texture.KEY=VALUE for every texture; "" none; NULL: the row
                              * is no image of the scene (a pass of it): no accuracy */
    uint32_t checksum;       /* of the last frame rendered (bench_fnv565) */
    uint16_t width, height, strip_rows;
    uint16_t frames;         /* frames 0 .. frames-1 rendered in order; checksum of the last */
    uint8_t num_frac;        /* the image's NUM_FRAC in fixed point, else 0 */
};
void bench_frame_line(const struct bench_frame *f);
/* The arguments qemu was given (-semihosting-config ...,arg=A,arg=B) as one
 * line "A B", by semihosting SYS_GET_CMDLINE; 0 on success. */
int bench_cmdline(char *buf, unsigned len);
/* "ERROR <msg>" on its own line; returns 1 (for bench_main's exit status). */
int bench_fail(const char *msg);
int bench_main(void);                     /* provided by the image */

#endif
