/* SPDX-License-Identifier: MIT */
/* bench_num.c — instructions per operation of the numeric layer, in the
 * numeric mode the image is built for, beside the toolchain's own float,
 * double and 64-bit integer routines (fixed-point images only, so each is
 * reported once per target).
 *
 * Each operation runs BENCH_N times through a non-inlined wrapper called by
 * pointer; the same loop around a wrapper that returns its argument is
 * subtracted, so a figure is the operation plus its call and return. */
#include "bench.h"
#include "num.h"

#ifdef BENCH_SMOKE
#define BENCH_LOG2N 4
#else
#define BENCH_LOG2N 10
#endif
#define BENCH_N (1u << BENCH_LOG2N)

#define NOINLINE __attribute__((noinline))

#if NUM_MODE == NUM_MODE_FIXED
#define STR2(x) #x
#define STR(x) STR2(x)
#define VARIANT "frac" STR(NUM_FRAC)
#elif defined(__ARM_FP) && NUM_MODE == NUM_MODE_FLOAT
#define VARIANT "hardfp"
#elif defined(__ARM_FP) && (__ARM_FP & 8) && NUM_MODE == NUM_MODE_DOUBLE
#define VARIANT "hardfp"
#else
#define VARIANT "softfp"
#endif

static num A[BENCH_N], B[BENCH_N], U[BENCH_N], DEG[BENCH_N];
static uint32_t E[BENCH_N];
static wnum WA[BENCH_N], WB[BENCH_N];
static volatile num sink;
static volatile wnum wsink;
static volatile float fsink;
static volatile double dsink;
static volatile int64_t lsink;

typedef num (*op2)(num, num, uint32_t);

static NOINLINE num w_base(num a, num b, uint32_t i) { (void)b; (void)i; return a; }
static NOINLINE num w_add(num a, num b, uint32_t i) { (void)i; return num_add(a, b); }
static NOINLINE num w_mul(num a, num b, uint32_t i) { (void)i; return num_mul(a, b); }
static NOINLINE num w_div(num a, num b, uint32_t i) { (void)i; return num_div(a, b); }
static NOINLINE num w_recip(num a, num b, uint32_t i) { (void)b; (void)i; return num_recip(a); }
static NOINLINE num w_sqrt(num a, num b, uint32_t i) { (void)b; (void)i; return num_sqrt(a); }
static NOINLINE num w_rsqrt(num a, num b, uint32_t i) { (void)b; (void)i; return num_rsqrt(a); }
static NOINLINE num w_powi(num a, num b, uint32_t i) { (void)a; (void)b; return num_powi(U[i], E[i]); }
static NOINLINE num w_sin(num a, num b, uint32_t i) { (void)a; (void)b; return num_sin_deg(DEG[i]); }
static NOINLINE num w_cos(num a, num b, uint32_t i) { (void)a; (void)b; return num_cos_deg(DEG[i]); }
static NOINLINE num w_dot(num a, num b, uint32_t i) { (void)i; return v3_dot(v3_make(a, b, a), v3_make(b, a, b)); }
static NOINLINE num w_len(num a, num b, uint32_t i) { (void)i; return v3_len(v3_make(a, b, U[i])); }
static NOINLINE num w_norm(num a, num b, uint32_t i) { (void)i; return v3_normalize(v3_make(a, b, U[i])).x; }
static NOINLINE num w_cross(num a, num b, uint32_t i) { (void)i; return v3_cross(v3_make(a, b, U[i]), v3_make(b, U[i], a)).x; }
static NOINLINE num w_wmul(num a, num b, uint32_t i) { (void)b; wsink = wnum_mul(WA[i], WB[i]); return a; }
static NOINLINE num w_wsub(num a, num b, uint32_t i) { (void)b; wsink = wnum_sub(WA[i], WB[i]); return a; }
static NOINLINE num w_wdiv(num a, num b, uint32_t i) { (void)a; (void)b; return wnum_div(WA[i], WB[i]); }
static NOINLINE num w_wsqrt(num a, num b, uint32_t i) { (void)b; wsink = wnum_sqrt(WA[i]); return a; }
static NOINLINE num w_chan(num a, num b, uint32_t i)
{
    (void)b;
    return (num)rgb_to_565(rgb_make(a, U[i], DEG[i]));
}

static uint64_t run(op2 f)
{
    uint64_t t0 = bench_now();
    for (uint32_t i = 0; i < BENCH_N; i++) sink = f(A[i], B[i], i);
    return bench_now() - t0;
}

static void report_op(const char *what, op2 f, uint64_t base)
{
    uint64_t t = run(f);
    uint64_t d = t > base ? t - base : 0;
    bench_report(what, NUM_NAME, VARIANT, (d * 1000u) >> BENCH_LOG2N, "op");
}

#if NUM_MODE == NUM_MODE_FIXED
/* The toolchain's routines on operands the compiler cannot fold. */
static volatile float fa = 1.2345f, fb = 3.4567f;
static volatile double da = 1.2345, db = 3.4567;
static volatile int64_t la = 0x123456789ABCll, lb = 12345;
typedef void (*rawop)(void);
static NOINLINE void r_base(void) { fsink = fa; }
static NOINLINE void r_fadd(void) { fsink = fa + fb; }
static NOINLINE void r_fmul(void) { fsink = fa * fb; }
static NOINLINE void r_fdiv(void) { fsink = fa / fb; }
static NOINLINE void r_f2i(void) { lsink = (int32_t)(fa * 100.0f); }
static NOINLINE void r_dadd(void) { dsink = da + db; }
static NOINLINE void r_dmul(void) { dsink = da * db; }
static NOINLINE void r_ddiv(void) { dsink = da / db; }
static NOINLINE void r_lmul(void) { lsink = la * lb; }
static NOINLINE void r_ldiv(void) { lsink = la / lb; }
float sqrtf(float);
double sqrt(double);
float sinf(float);
float powf(float, float);
static NOINLINE void r_sqrtf(void) { fsink = sqrtf(fa); }
static NOINLINE void r_sqrt(void) { dsink = sqrt(da); }
static NOINLINE void r_sinf(void) { fsink = sinf(fa); }
static NOINLINE void r_powf(void) { fsink = powf(fa * 0.5f, 50.0f); }

static uint64_t run_raw(rawop f)
{
    uint64_t t0 = bench_now();
    for (uint32_t i = 0; i < BENCH_N; i++) f();
    return bench_now() - t0;
}

static void report_raw(const char *what, const char *numeric, rawop f, uint64_t base)
{
    uint64_t t = run_raw(f), d = t > base ? t - base : 0;
#if defined(__ARM_FP)
    const char *v = "toolchain-hardfp";
#else
    const char *v = "toolchain-softfp";
#endif
    bench_report(what, numeric, v, (d * 1000u) >> BENCH_LOG2N, "op");
}
#endif

/* Known instruction count: "subs; bne" executes 2n instructions. */
static uint64_t calib(uint32_t n)
{
    uint64_t t0 = bench_now();
    __asm__ volatile(".syntax unified\n1:\tsubs %0, %0, #1\n\tbne 1b\n\t.syntax divided" : "+l"(n) : : "cc");
    return bench_now() - t0;
}

int bench_main(void)
{
    /* Operands: a, b in [0.5, 100.5), u in [0, 1], degrees in [-720, 720). */
    uint32_t x = 12345u;
    for (uint32_t i = 0; i < BENCH_N; i++) {
        x = x * 1664525u + 1013904223u;
        A[i] = num_from_ratio((int32_t)(x >> 16) % 10000 + 50, 100);
        x = x * 1664525u + 1013904223u;
        B[i] = num_from_ratio((int32_t)(x >> 16) % 10000 + 50, 100);
        x = x * 1664525u + 1013904223u;
        U[i] = num_from_ratio((int32_t)(x >> 16) % 1001, 1000);
        x = x * 1664525u + 1013904223u;
        DEG[i] = num_from_ratio((int32_t)(x >> 16) % 14400 - 7200, 10);
        x = x * 1664525u + 1013904223u;
        E[i] = 1 + (x >> 16) % 1000;
    }
    /* wide operands: a*b in [0.25, 10100), a*u in [0, 100.5] */
    for (uint32_t i = 0; i < BENCH_N; i++) {
        WA[i] = num_mul_wide(A[i], B[i]);
        WB[i] = num_mul_wide(A[i], U[i]);
        if (WB[i] == 0) WB[i] = wnum_from_num(NUM_ONE);
    }
    uint64_t c = calib(100000);
    /* 200000 instructions plus the timer reads; one SysTick tick is 40 */
    int calib_ok = c >= 200000 && c <= 200400;
    bench_report("op:calibration_2e5", "none", "subs-bne", c * 1000u, "op");
    if (!calib_ok) {
        bench_puts("FAIL bench_instruction_count: a loop of 200000 instructions measured ");
        bench_put_u64(c);
        bench_puts("\n");
        return 1;
    }
    uint64_t base = run(w_base);
    report_op("op:num_add", w_add, base);
    report_op("op:num_mul", w_mul, base);
    report_op("op:num_div", w_div, base);
    report_op("op:num_recip", w_recip, base);
    report_op("op:num_sqrt", w_sqrt, base);
    report_op("op:num_rsqrt", w_rsqrt, base);
    report_op("op:num_powi", w_powi, base);
    report_op("op:num_sin_deg", w_sin, base);
    report_op("op:num_cos_deg", w_cos, base);
    report_op("op:v3_dot", w_dot, base);
    report_op("op:v3_len", w_len, base);
    report_op("op:v3_normalize", w_norm, base);
    report_op("op:rgb_to_565", w_chan, base);
    report_op("op:v3_cross", w_cross, base);
    report_op("op:wnum_mul", w_wmul, base);
    report_op("op:wnum_sub", w_wsub, base);
    report_op("op:wnum_div", w_wdiv, base);
    report_op("op:wnum_sqrt", w_wsqrt, base);
#if NUM_MODE == NUM_MODE_FIXED
    uint64_t rb = run_raw(r_base);
    report_raw("op:float_add", "float", r_fadd, rb);
    report_raw("op:float_mul", "float", r_fmul, rb);
    report_raw("op:float_div", "float", r_fdiv, rb);
    report_raw("op:float_to_int", "float", r_f2i, rb);
    report_raw("op:sqrtf", "float", r_sqrtf, rb);
    report_raw("op:sinf", "float", r_sinf, rb);
    report_raw("op:powf", "float", r_powf, rb);
    report_raw("op:double_add", "double", r_dadd, rb);
    report_raw("op:double_mul", "double", r_dmul, rb);
    report_raw("op:double_div", "double", r_ddiv, rb);
    report_raw("op:sqrt", "double", r_sqrt, rb);
    report_raw("op:int64_mul", "int", r_lmul, rb);
    report_raw("op:int64_div", "int", r_ldiv, rb);
#endif
    bench_puts("PASS bench_instruction_count\n");
    return 0;
}
