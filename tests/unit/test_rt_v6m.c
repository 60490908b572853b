/* SPDX-License-Identifier: MIT */
/* test_rt_v6m.c — rt_prim_disc_v6m (rt_prim_v6m.h: the per-pixel part of a
 * primary ray's lean sphere test, ARMv6-M assembly on the Cortex-M0+)
 * gives the bits of rt_prim_disc_c, on the emulated Cortex-M0+.
 *
 * Built as an image for m0plus-qemu at NUM_FRAC 16 and 20 (the assembly's
 * range of F, its two ends near them), run by tools/bench/run.py --smoke.
 * Inputs: the row's parts made from a centre offset CO and a row direction
 * as sphere_row_parts makes them, with components of every bit length up to
 * 30 and the edge values (0, +-1, +-(2^30 - 1), +-2^29), a from the
 * direction or of every bit length up to 62, radii of every bit length (kr
 * 0 ... 31), limits at and around the near-root test's ends (-1, 0, 2^30 -
 * 1, 2^30, INT32_MAX) and random, near_ok on and off with c m of every bit
 * length below 2^(62-F), and rays aimed just past and at the sphere (a
 * discriminant near 0). Prints a PASS or FAIL line, and the instructions
 * per call of both forms as BENCH lines. rt_prim_near_v6m (the near root
 * from it, num_isqrt64 and num_udiv64_32 called) likewise against
 * rt_prim_near_c: on every case above with a root, and on discriminants,
 * b and c m of every bit length (q below and above 2^32, quotients at and
 * around 2^31, a zero discriminant); rt_prim_solve_v6m (both in one call)
 * against rt_prim_solve_c on the first's cases. */
#include <string.h>
#include "bench.h"
#include "num.h"
#include "rt/rt_prim_v6m.h"
#define TEST_RNG_SEED 0xD1B54A32D192ED03ull
#include "test_rng.h"

#ifndef RT_PRIM_DISC_V6M
#error "test_rt_v6m: built for ARMv6-M with 15 <= NUM_FRAC <= 20 only"
#endif

#define RANDOM_CASES 60000

static uint32_t fails, checked, hits;
static uint64_t bad_seed;

static __attribute__((noinline)) int ref_disc(const struct rt_obj_cache *oc, const struct rt_ray *ray, num limit,
                                              struct rt_pdisc *o)
{
    return rt_prim_disc_c(oc, ray, limit, o);
}

static __attribute__((noinline)) int ref_near(const struct rt_pdisc *pd, const struct rt_obj_cache *oc,
                                              struct rt_pnear *o)
{
    return rt_prim_near_c(pd, oc, o);
}

static uint32_t nfails, nchecked, nfast, sfails;

static __attribute__((noinline)) int ref_solve(const struct rt_obj_cache *oc, const struct rt_ray *ray, num limit,
                                               struct rt_psolve *o)
{
    return rt_prim_solve_c(oc, ray, limit, o);
}

/* rt_prim_near of pd and c m (cm_cam) both ways */
static void check_near(const struct rt_pdisc *pd, struct rt_obj_cache *oc, uint64_t seed)
{
    struct rt_pnear got, want;
    memset(&got, 0x5A, sizeof got);
    memset(&want, 0x5A, sizeof want);
    int g = rt_prim_near_v6m(pd, oc, &got);
    int w = ref_near(pd, oc, &want);
    nchecked++;
    nfast += w != 0;
    if (g != w || (w && (got.q != want.q || got.t != want.t))) {
        if (!nfails && !fails) bad_seed = seed;
        nfails++;
    }
}

static int32_t rnd_signed(int bits)
{
    int32_t v = (int32_t)rnd_bits(bits);
    return (rng() & 1) ? -v : v;
}

static const int32_t edges[] = { 0, 1, -1, 0x3FFFFFFF, -0x3FFFFFFF, 0x20000000, -0x20000000, 0x10000, -0x10000 };
#define NEDGES (sizeof edges / sizeof edges[0])

static int32_t comp(void)
{
    return (rng() % 8) == 0 ? edges[rng() % NEDGES] : rnd_signed(30);
}

static const num limits[] = { -1, 0, 1, 0x3FFFFFFF, 0x40000000, INT32_MAX, INT32_MIN };

static void check(const struct rt_obj_cache *oc, const struct rt_ray *ray, num limit, uint64_t seed)
{
    struct rt_pdisc got, want;
    memset(&got, 0x5A, sizeof got);
    memset(&want, 0x5A, sizeof want);
    int g = rt_prim_disc_v6m(oc, ray, limit, &got);
    int w = ref_disc(oc, ray, limit, &want);
    checked++;
    hits += w != 0;
    if (g != w || (w && (got.bx != want.bx || got.dd != want.dd || got.e != want.e))) {
        if (!fails) bad_seed = seed;
        fails++;
    }
    if (w) check_near(&want, (struct rt_obj_cache *)oc, seed);
    /* both in one call: its result, o->pd for 1 and 2, o->pn for 1 */
    struct rt_psolve sg, sw;
    memset(&sg, 0x5A, sizeof sg);
    memset(&sw, 0x5A, sizeof sw);
    int gs = rt_prim_solve_v6m(oc, ray, limit, &sg);
    int ws = ref_solve(oc, ray, limit, &sw);
    if (gs != ws ||
        (ws && (sg.pd.bx != sw.pd.bx || sg.pd.dd != sw.pd.dd || sg.pd.e != sw.pd.e)) ||
        (ws == 1 && (sg.pn.q != sw.pn.q || sg.pn.t != sw.pn.t))) {
        if (!fails && !nfails && !sfails) bad_seed = seed;
        sfails++;
    }
}

/* a sphere, its row's parts and a ray from the generator's state */
static void make_case(struct rt_obj_cache *oc, struct rt_ray *ray, num *limit)
{
    memset(oc, 0, sizeof *oc);
    memset(ray, 0, sizeof *ray);
    vec3 co = { comp(), comp(), comp() };
    ray->dx.x = comp();
    ray->dx.y = comp();
    ray->dx.z = comp();
    if (rng() % 4 == 0) {
        /* small offsets and directions, as a scene's: a few units at F bits */
        co.x = rnd_signed(NUM_FRAC + 4);
        co.y = rnd_signed(NUM_FRAC + 4);
        co.z = rnd_signed(NUM_FRAC + 4);
        ray->dx.x = rnd_signed(NUM_FRAC + 2);
        ray->dx.y = rnd_signed(NUM_FRAC + 2);
        ray->dx.z = rnd_signed(NUM_FRAC + 2);
    }
    oc->co_cam = co;
    oc->px_b = -(num_smul32(co.y, ray->dx.y) + num_smul32(co.z, ray->dx.z));
    oc->px_x0 = rt_mag64(num_smul32(co.y, ray->dx.z) - num_smul32(co.z, ray->dx.y));
    oc->px_x2 = num_smul32(co.x, ray->dx.y);
    oc->px_cxd = num_smul32(co.x, ray->dx.z);
    ray->dxa = (rng() % 4) ? rt_quad_a(ray->dx, 0) : (wnum)rnd_bits(62);
    /* the radius: every bit length, or the distance of the line from the
     * centre (a discriminant near 0) */
    num r;
    if (rng() % 3 == 0) {
        /* |CO x D| / |D| ~ sqrt(|x|^2 / a), in num units */
        uint64_t x1 = rt_mag64(num_smul32(co.z, ray->dx.x) - oc->px_cxd);
        uint64_t x2 = rt_mag64(oc->px_x2 - num_smul32(co.y, ray->dx.x));
        uint64_t m = oc->px_x0 > x1 ? oc->px_x0 : x1;
        if (x2 > m) m = x2;
        uint64_t d = (uint64_t)rt_mag64(ray->dx.x) + rt_mag64(ray->dx.y) + rt_mag64(ray->dx.z);
        uint64_t q = d ? m / d : m;
        r = (num)(q > (uint64_t)INT32_MAX ? INT32_MAX : q) + (num)(rng() % 5) - 2;
        if (r < 0) r = 0;
    } else {
        r = (num)rnd_bits(31);
    }
    oc->qs = rt_qsphere_make(r);
    oc->near_ok = (uint8_t)(rng() % 4 != 0);
    oc->cm_cam = (wnum)rnd_bits(61 - NUM_FRAC);
    switch (rng() % 4) {
    case 0: *limit = limits[rng() % (sizeof limits / sizeof limits[0])]; break;
    case 1: *limit = (num)rnd_bits(30); break;
    case 2: *limit = rnd_signed(31); break;
    default: {
        /* around the near-root test's threshold: cm 2^(2F-30) ~ (L+1) qs */
        uint64_t bx = (uint64_t)(oc->px_b - num_smul32(co.x, ray->dx.x));
        uint32_t qs = (uint32_t)(((bx * 2u + (1u << (NUM_FRAC - 1))) >> 30) & 0x7FFFFFFF) + 1u;
        uint64_t n = ((uint64_t)oc->cm_cam << NUM_FRAC) >> (30 - NUM_FRAC);
        uint64_t l = n / qs;
        *limit = (num)((l > 0x40000000u ? 0x40000000u : l) - 1u + (uint32_t)(rng() % 3)) ;
        break;
    }
    }
}

int bench_main(void)
{
    struct rt_obj_cache oc;
    struct rt_ray ray;
    num limit;
    for (uint32_t i = 0; i < RANDOM_CASES; i++) {
        uint64_t seed = rng_state;
        make_case(&oc, &ray, &limit);
        check(&oc, &ray, limit, seed);
    }
    /* the near root from discriminants, b and c m of every bit length: q
     * below and above 2^32, quotients near 2^31, the division's ends */
    for (uint32_t i = 0; i < RANDOM_CASES; i++) {
        uint64_t seed = rng_state;
        struct rt_pdisc pd;
        memset(&oc, 0, sizeof oc);
        pd.bx = (int64_t)rnd_bits(61);
        pd.dd = (rng() % 16) ? rnd_bits(62) : 0;
        pd.e = (int32_t)(rng() % 63);
        if (rng() % 2) pd.e &= 7;
        oc.cm_cam = (wnum)rnd_bits(62);
        check_near(&pd, &oc, seed);
        /* c m near the division's limits for this q */
        struct rt_pnear r;
        r.q = 0;
        if (ref_near(&pd, &oc, &r) || r.q > 0) {
            uint64_t q = (uint64_t)r.q;
            int sh = rt_bitlen64(q) > 32 ? rt_bitlen64(q) - 32 : 0;
            uint64_t d = sh ? (q + ((uint64_t)1 << (sh - 1))) >> sh : q;
            /* n 2^F = d (2^31 - 1 + j/2), j small: t at and around INT32_MAX */
            uint64_t n = (d * (uint64_t)0x7FFFFFFF) >> NUM_FRAC;
            n += (uint64_t)(rng() % 5) * (d >> (NUM_FRAC + 1));
            oc.cm_cam = (wnum)((sh && sh < 40) ? n << sh : n);
            if (oc.cm_cam > 0) check_near(&pd, &oc, seed);
        }
    }
    /* instructions per call of both forms, on scene-like cases */
    {
        struct rt_psolve o;
        uint64_t tv = 0, tc = 0;
        uint32_t n = 0;
        for (uint32_t i = 0; i < 256; i++) {
            make_case(&oc, &ray, &limit);
            uint64_t t0 = bench_now();
            (void)rt_prim_solve_v6m(&oc, &ray, limit, &o);
            uint64_t t1 = bench_now();
            (void)ref_solve(&oc, &ray, limit, &o);
            uint64_t t2 = bench_now();
            tv += t1 - t0;
            tc += t2 - t1;
            n++;
        }
        bench_report("op:rt_prim_solve", "fixed", "v6m", tv * 1000 / n, "op");
        bench_report("op:rt_prim_solve", "fixed", "c", tc * 1000 / n, "op");
        /* the near root of a typical pixel: q about 2^37, t a few units */
        struct rt_pdisc pd = { (int64_t)1 << 36, (uint64_t)1 << 60, 12 };
        struct rt_pnear pn;
        oc.cm_cam = (wnum)5 << 50;
        uint64_t t0 = bench_now();
        (void)rt_prim_near_v6m(&pd, &oc, &pn);
        uint64_t t1 = bench_now();
        (void)ref_near(&pd, &oc, &pn);
        uint64_t t2 = bench_now();
        bench_report("op:rt_prim_near", "fixed", "v6m", (t1 - t0) * 1000, "op");
        bench_report("op:rt_prim_near", "fixed", "c", (t2 - t1) * 1000, "op");
    }
    bench_puts(fails || nfails || sfails ? "FAIL " : "PASS ");
    bench_puts("rt_prim_disc_v6m: ");
    bench_put_u64(checked);
    bench_puts(" cases, ");
    bench_put_u64(hits);
    bench_puts(" with a root; rt_prim_near_v6m: ");
    bench_put_u64(nchecked);
    bench_puts(" cases, ");
    bench_put_u64(nfast);
    bench_puts(" on the fast path");
    bench_puts("; rt_prim_solve_v6m on the first's");
    if (fails || nfails || sfails) {
        bench_puts(", mismatches ");
        bench_put_u64(fails);
        bench_puts(", ");
        bench_put_u64(nfails);
        bench_puts(", ");
        bench_put_u64(sfails);
        bench_puts(" e.g. the generator's state ");
        bench_put_u64(bad_seed);
    }
    bench_puts("\n");
    return fails != 0 || nfails != 0 || sfails != 0;
}
