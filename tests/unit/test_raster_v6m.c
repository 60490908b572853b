/* SPDX-License-Identifier: MIT */
/* test_raster_v6m.c — ras_div_subs (raster_num.c: the default path's
 * projection of a run of points, ARMv6-M assembly on the Cortex-M0+) gives
 * the bits of one ras_div_sub per point with store_pv's ranges, on the
 * emulated Cortex-M0+.
 *
 * Built as an image for m0plus-qemu at NUM_FRAC 16 and 20 (the assembly's
 * two forms of P's rounding half), run by tools/bench/run.py --smoke.
 * Inputs: every combination of edge coordinates (0, +-1, the ends of the
 * assembly's range of z, near_z, values whose quotients or positions
 * saturate) and random points of every bit length and sign, for several
 * unproj (whole, fractional, negative), near_z and sub-pixel bits. Prints a
 * PASS or FAIL line, and the instructions per point of both forms as BENCH
 * lines. */
#include <string.h>
#include "bench.h"
#include "num.h"
#include "raster/raster_num.h"
#define TEST_RNG_SEED 0x9E3779B97F4A7C15ull
#include "test_rng.h"

#define RUN 16
#define RANDOM_RUNS 6000

static uint32_t fails, checked;
static int32_t bad_x, bad_y, bad_z;

static void check_run(const struct ras_subproj *k, const vec3 *c, uint32_t n)
{
    struct ras_pv got[RUN], want[RUN];
    memset(got, 0x5A, sizeof got);
    memset(want, 0x5A, sizeof want);
    ras_div_subs(k, c, got, n);
    for (uint32_t j = 0; j < n; j++) {
        ras_div_sub_pv(k, &want[j], c[j]);
        checked++;
        if (memcmp(&got[j], &want[j], sizeof got[j]) != 0) {
            if (!fails) {
                bad_x = c[j].x;
                bad_y = c[j].y;
                bad_z = c[j].z;
            }
            fails++;
        }
    }
}

static const int32_t xy_edges[] = {
    0,
    1,
    -1,
    2,
    -2,
    0x7FFF,
    -0x8000,
    0x10000,
    -0x10000,
    0x123456,
    -0x123456,
    0x7FFFFF,
    -0x800000,
    0x3FFFFFFF,
    -0x40000000,
    0x7FFFFFFF,
    INT32_MIN,
    0x7FFFFFFE,
    INT32_MIN + 1,
    0x0FFFFFFF,
    -0x0FFFFFFF,
};
#define NXY (sizeof xy_edges / sizeof xy_edges[0])

/* z: around the assembly's range [2^(2F-31), 2^28) and near_z */
static int32_t z_edge(unsigned i, num near_z)
{
    const int32_t lo = (int32_t)1 << (2 * NUM_FRAC - 31);
    const int32_t e[] = { 0, 1, -1, lo - 1, lo, lo + 1, near_z - 1, near_z, near_z + 1, 0x0FFFFFFF,
                          0x10000000, 0x10000001, 0x7FFFFFFF, INT32_MIN, NUM_ONE, 3 * NUM_ONE / 2, 7 * NUM_ONE };
    return e[i % (sizeof e / sizeof e[0])];
}
#define NZ 17

static int32_t rnd_coord(void)
{
    int32_t v = (int32_t)rnd_bits(31);
    return (rng() & 1) ? -v : v;
}

int bench_main(void)
{
    const num unprojs[] = { 120 * NUM_ONE, 240 * NUM_ONE, NUM_C(120.3), NUM_C(0.75), 3 * NUM_ONE + 7, -120 * NUM_ONE };
    const num nears[] = { NUM_C(0.25), NUM_C(0.05), 0, -NUM_ONE };
    const int32_t sbs[] = { 4, 1, 8 };
    for (unsigned iu = 0; iu < sizeof unprojs / sizeof unprojs[0]; iu++)
        for (unsigned in = 0; in < sizeof nears / sizeof nears[0]; in++)
            for (unsigned is = 0; is < sizeof sbs / sizeof sbs[0]; is++) {
                struct ras_subproj k = { unprojs[iu], nears[in], 120 * NUM_ONE, 120 * NUM_ONE, sbs[is] };
                vec3 c[RUN];
                uint32_t n = 0;
                for (unsigned a = 0; a < NXY; a++)
                    for (unsigned b = 0; b < NXY; b += 3)
                        for (unsigned z = 0; z < NZ; z++) {
                            c[n].x = xy_edges[a];
                            c[n].y = xy_edges[(b + z) % NXY];
                            c[n].z = z_edge(z, k.near_z);
                            if (++n == RUN) {
                                check_run(&k, c, n);
                                n = 0;
                            }
                        }
                if (n) check_run(&k, c, n);
                for (uint32_t r = 0; r < RANDOM_RUNS / 24; r++) {
                    const uint32_t m = 1 + (uint32_t)(rng() % RUN);
                    for (uint32_t j = 0; j < m; j++) {
                        c[j].x = rnd_coord();
                        c[j].y = rnd_coord();
                        /* mostly in front of the camera, every bit length */
                        c[j].z = (rng() % 8) ? (int32_t)rnd_bits(29) : rnd_coord();
                    }
                    check_run(&k, c, m);
                }
            }
    /* a screen's worth of points in a whole-number unproj frame */
    {
        struct ras_subproj k = { 120 * NUM_ONE, NUM_C(0.25), 120 * NUM_ONE, 120 * NUM_ONE, 4 };
        vec3 c[RUN];
        for (uint32_t r = 0; r < RANDOM_RUNS; r++) {
            for (uint32_t j = 0; j < RUN; j++) {
                c[j].z = NUM_C(0.5) + (int32_t)(rng() % (uint64_t)(3 * NUM_ONE));
                c[j].x = (int32_t)(rng() % (uint64_t)c[j].z) * 2 - c[j].z;
                c[j].y = (int32_t)(rng() % (uint64_t)c[j].z) * 2 - c[j].z;
            }
            check_run(&k, c, RUN);
        }
        /* instructions per point of both forms */
        struct ras_pv out[RUN];
        uint64_t t0 = bench_now();
        for (int rep = 0; rep < 64; rep++) ras_div_subs(&k, c, out, RUN);
        uint64_t t1 = bench_now();
        for (int rep = 0; rep < 64; rep++)
            for (uint32_t j = 0; j < RUN; j++) ras_div_sub_pv(&k, &out[j], c[j]);
        uint64_t t2 = bench_now();
        bench_report("op:ras_div_subs", "fixed", "v6m", (t1 - t0) * 1000 / (64 * RUN), "op");
        bench_report("op:ras_div_sub_pv", "fixed", "c", (t2 - t1) * 1000 / (64 * RUN), "op");
    }
    bench_puts(fails ? "FAIL " : "PASS ");
    bench_puts("ras_div_subs_v6m: ");
    bench_put_u64(checked);
    bench_puts(" points");
    if (fails) {
        bench_puts(", mismatches ");
        bench_put_u64(fails);
        bench_puts(" e.g. x ");
        bench_put_u64((uint32_t)bad_x);
        bench_puts(" y ");
        bench_put_u64((uint32_t)bad_y);
        bench_puts(" z ");
        bench_put_u64((uint32_t)bad_z);
    }
    bench_puts("\n");
    return fails != 0;
}
