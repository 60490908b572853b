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
/* The arguments qemu was given (-semihosting-config ...,arg=A,arg=B) as one
 * line "A B", by semihosting SYS_GET_CMDLINE; 0 on success. */
int bench_cmdline(char *buf, unsigned len);
/* "ERROR <msg>" on its own line; returns 1 (for bench_main's exit status). */
int bench_fail(const char *msg);
int bench_main(void);                     /* provided by the image */

#endif
