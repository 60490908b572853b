/* SPDX-License-Identifier: MIT */
/* test_num_v6m.c — the ARMv6-M integer kernels of num_int.h (Thumb-1
 * assembly: num_umul32, num_smul32, num_mul_round; the table-driven
 * num_clz32; the ray tracer's squares rt_usq32, rt_ssq32 of rt/rt_num.h)
 * give the bits of their definitions, on the emulated Cortex-M0+.
 *
 * Built as an image for m0plus-qemu at NUM_FRAC 16 (the num_mul_round
 * kernel of its own) and 20 (the general form), run by tools/bench/run.py
 * --smoke in `make test`. References are the compiler's own 64-bit
 * arithmetic (libgcc's __aeabi_lmul on this core) and a bit loop; inputs are
 * every pair of edge values (0, +-1, +-2^15, +-2^16, +-2^31 ...) and random
 * pairs of every bit length and sign. Prints one PASS or FAIL line per
 * kernel, and the kernels' instructions per call as BENCH lines. */
#include "bench.h"
#include "num.h"
#include "num/num_int.h"
#include "rt/rt_num.h"
#define TEST_RNG_SEED 0xA0761D6478BD642Full
#include "test_rng.h"

#define RANDOM_PAIRS 60000

static const uint32_t edges[] = {
    0u, 1u, 2u, 3u, 0x7FFFu, 0x8000u, 0x8001u, 0xFFFFu, 0x10000u, 0x10001u, 0x1FFFFu,
    0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFF0000u, 0xFFFF7FFFu, 0xFFFF8000u,
    0xFFFFFFFEu, 0xFFFFFFFFu, 0x12345678u, 0xDEADBEEFu, 0x0000FFFEu, 0x7FFF8000u,
};
#define NEDGES (sizeof edges / sizeof edges[0])

static int clz_ref(uint32_t x)
{
    int n = 0;
    while (!(x & 0x80000000u)) { n++; x <<= 1; }
    return n;
}

/* A random 32-bit value of random bit length and sign. */
static uint32_t rnd32(void)
{
    uint32_t v = (uint32_t)rnd_bits(32);
    return (rng() & 1) ? 0u - v : v;
}

static uint32_t fails_umul, fails_smul, fails_round, fails_clz, fails_sq;

static void check_pair(uint32_t a, uint32_t b)
{
    if (num_umul32(a, b) != (uint64_t)a * b) fails_umul++;
    int32_t sa = (int32_t)a, sb = (int32_t)b;
    if (num_smul32(sa, sb) != (int64_t)sa * sb) fails_smul++;
    if (num_mul_round(sa, sb) != (((int64_t)sa * sb + ((int64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC)) fails_round++;
    if (a && num_clz32(a) != clz_ref(a)) fails_clz++;
    if (rt_usq32(a) != (uint64_t)a * a || rt_ssq32(sb) != (int64_t)sb * sb) fails_sq++;
}

static int verdict(const char *name, uint32_t fails)
{
    bench_puts(fails ? "FAIL " : "PASS ");
    bench_puts(name);
    bench_puts(fails ? ": mismatches " : "");
    if (fails) bench_put_u64(fails);
    bench_puts("\n");
    return fails != 0;
}

/* Instructions per call of one kernel, the loop's own cost removed. */
static volatile uint32_t sink;
#define REPS 2000
#define COST(expr) do { \
        uint64_t t0 = bench_now(); \
        for (uint32_t i = 0; i < REPS; i++) { uint32_t x = i * 2654435761u, y = x ^ 0x5bd1e995u; (void)y; sink = (uint32_t)(expr); } \
        uint64_t t1 = bench_now(); \
        for (uint32_t i = 0; i < REPS; i++) { uint32_t x = i * 2654435761u, y = x ^ 0x5bd1e995u; (void)y; sink = x ^ y; } \
        uint64_t t2 = bench_now(); \
        cost = (t1 - t0) - (t2 - t1); \
    } while (0)

int bench_main(void)
{
    for (unsigned i = 0; i < NEDGES; i++)
        for (unsigned j = 0; j < NEDGES; j++) check_pair(edges[i], edges[j]);
    for (uint32_t k = 0; k < RANDOM_PAIRS; k++) check_pair(rnd32(), rnd32());
    for (int s = 0; s < 32; s++) check_pair(1u << s, (1u << s) - 1u);
    int bad = 0;
    bad |= verdict("num_umul32_v6m", fails_umul);
    bad |= verdict("num_smul32_v6m", fails_smul);
    bad |= verdict(NUM_FRAC == 16 ? "num_mul_round_v6m_q16" : "num_mul_round_v6m", fails_round);
    bad |= verdict("num_clz32_v6m", fails_clz);
    bad |= verdict("rt_usq32_v6m", fails_sq);

    uint64_t cost;
    COST(num_umul32(x, y) >> 7);
    bench_report("op:kernel_umul32", "fixed", "v6m", cost * 1000 / REPS, "op");
    COST(num_smul32((int32_t)x, (int32_t)y) >> 7);
    bench_report("op:kernel_smul32", "fixed", "v6m", cost * 1000 / REPS, "op");
    COST(num_mul_round((int32_t)x, (int32_t)y) >> 7);
    bench_report("op:kernel_mul_round", "fixed", NUM_FRAC == 16 ? "v6m-q16" : "v6m", cost * 1000 / REPS, "op");
    COST(rt_usq32(x) >> 7);
    bench_report("op:kernel_usq32", "fixed", "v6m", cost * 1000 / REPS, "op");
    COST(num_clz32(x | 1u));
    bench_report("op:kernel_clz32", "fixed", "v6m", cost * 1000 / REPS, "op");
    return bad;
}
