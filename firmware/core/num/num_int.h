/* SPDX-License-Identifier: MIT */
/* num_int.h — integer kernels of the fixed-point build, shared by num.c and
 * vec.c. Internal to the numeric layer (algorithms use num.h only).
 *
 * Everything here gives the same bits on every target; the ARMv6-M paths
 * (Cortex-M0+, no long multiply, no CLZ, no divide) avoid library calls. */
#ifndef NUM_INT_H
#define NUM_INT_H

#include <stdint.h>

/* ARMv6-M (Cortex-M0/M0+) kernels in Thumb-1 assembly: MULS is 32x32->32
 * only, and the compiler's 64-bit arithmetic spills registers. Each is the
 * same function as its portable C twin below (tests/unit/test_num_v6m.c checks
 * them against it on the emulated Cortex-M0+). NUM_PORTABLE_INT selects
 * the C forms (host tests of the ARMv6-M paths). */
#if defined(__ARM_ARCH_6M__) && !defined(NUM_PORTABLE_INT) && (defined(__GNUC__) || defined(__clang__))
#define NUM_V6M_ASM 1
#else
#define NUM_V6M_ASM 0
#endif
/* The kernels are written in unified syntax; GCC's Thumb-1 inline assembly
 * is divided by default (clang's is unified). */
#if NUM_V6M_ASM && !defined(__clang__)
#define NUM_ASM_UNIFIED(text) ".syntax unified\n\t" text "\n\t.syntax divided"
#else
#define NUM_ASM_UNIFIED(text) text
#endif

/* Fragments of the kernels below, on the operands lo, t0, t1, t2, a, b
 * (NUM_V6M_OPERANDS). NUM_V6M_PIECES(SH): a and b split into 16-bit halves
 * (the high ones by SH: lsrs unsigned, asrs signed) and the four partial
 * products: lo = al bl, t0 = al bh, t1 = ah bl, a = ah bh. */
#define NUM_V6M_PIECES(SH) \
    "uxth  %[t0], %[a]\n\t" SH "  %[a], %[a], #16\n\t" \
    "uxth  %[t1], %[b]\n\t" SH "  %[b], %[b], #16\n\t" \
    "movs  %[lo], %[t0]\n\t" "muls  %[lo], %[t1]\n\t" "muls  %[t0], %[b]\n\t" \
    "muls  %[t1], %[a]\n\t" "muls  %[a], %[b]\n\t"
/* NUM_V6M_ADD_MID(T, SH): the middle product T added at 2^16 into a:lo
 * (its high half extended by SH). */
#define NUM_V6M_ADD_MID(T, SH) \
    "lsls  %[t2], %[" T "], #16\n\t" SH "  %[" T "], %[" T "], #16\n\t" \
    "adds  %[lo], %[lo], %[t2]\n\t" "adcs  %[a], %[" T "]"
/* NUM_V6M_ROUND_LO: lo = (lo + 2^15) >> 16, al bl rounded to its 2^16 units. */
#define NUM_V6M_ROUND_LO \
    "movs  %[t2], #1\n\t" "lsls  %[t2], %[t2], #15\n\t" \
    "adds  %[lo], %[lo], %[t2]\n\t" "lsrs  %[lo], %[lo], #16\n\t"
#define NUM_V6M_OPERANDS \
    [lo] "=&l"(lo), [t0] "=&l"(t0), [t1] "=&l"(t1), [t2] "=&l"(t2), [a] "+l"(a), [b] "+l"(b)

/* 32x32 -> 64 unsigned product. */
static inline uint64_t num_umul32(uint32_t a, uint32_t b)
{
#if NUM_V6M_ASM
    /* four 16x16 partial products; the two middle ones added with carry:
     * 17 instructions */
    uint32_t lo, t0, t1, t2;
    __asm__(NUM_ASM_UNIFIED(NUM_V6M_PIECES("lsrs") NUM_V6M_ADD_MID("t0", "lsrs") "\n\t"
                            NUM_V6M_ADD_MID("t1", "lsrs"))
            : NUM_V6M_OPERANDS
            :
            : "cc");
    return (uint64_t)a << 32 | lo;
#elif defined(__ARM_ARCH_6M__) || defined(NUM_PORTABLE_INT)
    /* MULS is 32x32->32 only: four 16x16 partial products, no __aeabi_lmul. */
    uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
    uint32_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
    uint32_t mid = (ll >> 16) + (lh & 0xFFFFu) + (hl & 0xFFFFu); /* < 3 * 2^16 */
    uint32_t lo = (ll & 0xFFFFu) | (mid << 16);
    uint32_t hi = hh + (lh >> 16) + (hl >> 16) + (mid >> 16);
    return (uint64_t)hi << 32 | lo;
#else
    return (uint64_t)a * b;
#endif
}

/* a^2, the same value as num_umul32(a, a): on ARMv6-M from three 16x16
 * products, a^2 = ah^2 2^32 + al ah 2^17 + al^2 (10 instructions instead of
 * 17). */
static inline uint64_t num_usq32(uint32_t a)
{
#if NUM_V6M_ASM
    uint32_t lo, hi, t;
    __asm__(NUM_ASM_UNIFIED("uxth  %[lo], %[a]\n\t"
                            "lsrs  %[hi], %[a], #16\n\t"
                            "movs  %[t], %[lo]\n\t"
                            "muls  %[t], %[hi]\n\t"
                            "muls  %[lo], %[lo]\n\t"
                            "muls  %[hi], %[hi]\n\t"
                            "lsls  %[a], %[t], #17\n\t"
                            "lsrs  %[t], %[t], #15\n\t"
                            "adds  %[lo], %[lo], %[a]\n\t"
                            "adcs  %[hi], %[t]")
            : [lo] "=&l"(lo), [hi] "=&l"(hi), [t] "=&l"(t), [a] "+l"(a)
            :
            : "cc");
    return (uint64_t)hi << 32 | lo;
#else
    return num_umul32(a, a);
#endif
}

/* High word of the 32x32 product. */
static inline uint32_t num_mulhi32(uint32_t a, uint32_t b)
{
    return (uint32_t)(num_umul32(a, b) >> 32);
}

/* num_mulhi32(a, b), the same value, from two 16x16 products when b <
 * 2^16 (a Newton step's small correction): with a = ah 2^16 + al,
 * floor(a b / 2^32) = floor((ah b + floor(al b / 2^16)) / 2^16), and that
 * sum is below 2^32. */
static inline uint32_t num_mulhi32_small(uint32_t a, uint32_t b)
{
    if (b >> 16) return num_mulhi32(a, b);
    return ((a >> 16) * b + (((a & 0xFFFFu) * b) >> 16)) >> 16;
}

/* 32x32 -> 64 signed product (two's complement correction of the unsigned one). */
static inline int64_t num_smul32(int32_t a, int32_t b)
{
#if NUM_V6M_ASM
    /* a = ah 2^16 + al with ah = a >> 16 (signed) and al unsigned: the
     * products al bl (unsigned), al bh, ah bl (|.| < 2^31) and ah bh
     * (|.| <= 2^30) each fit a MULS; the middle two are added at 2^16
     * sign-extended: 17 instructions */
    uint32_t lo, t0, t1, t2;
    __asm__(NUM_ASM_UNIFIED(NUM_V6M_PIECES("asrs") NUM_V6M_ADD_MID("t0", "asrs") "\n\t"
                            NUM_V6M_ADD_MID("t1", "asrs"))
            : NUM_V6M_OPERANDS
            :
            : "cc");
    return (int64_t)((uint64_t)(uint32_t)a << 32 | lo);
#elif defined(__ARM_ARCH_6M__) || defined(NUM_PORTABLE_INT)
    uint64_t p = num_umul32((uint32_t)a, (uint32_t)b);
    if (a < 0) p -= (uint64_t)(uint32_t)b << 32;
    if (b < 0) p -= (uint64_t)(uint32_t)a << 32;
    return (int64_t)p;
#else
    return (int64_t)a * b;
#endif
}

/* Leading zeros of a byte (8 for 0), for num_clz32 without CLZ. */
extern const uint8_t num_clz8_tab[256];

/* Leading zeros of x != 0. */
static inline int num_clz32(uint32_t x)
{
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__ARM_ARCH_6M__) && !defined(NUM_PORTABLE_INT)
    return __builtin_clz(x);
#else
    /* two halving steps, then the top byte's leading zeros from a table
     * (ARMv6-M has no CLZ): 12 instructions instead of 28 */
    int n = 0;
    if (!(x >> 16)) { n = 16; x <<= 16; }
    if (!(x >> 24)) { n += 8; x <<= 8; }
    return n + num_clz8_tab[x >> 24];
#endif
}

/* Leading zeros of x != 0. */
static inline int num_clz64(uint64_t x)
{
    uint32_t h = (uint32_t)(x >> 32);
    return h ? num_clz32(h) : 32 + num_clz32((uint32_t)x);
}

/* 1 when a 32/32 divide instruction exists (ARMv7-M UDIV, the host):
 * num_udiv64_32 then estimates its digits with it. ARMv6-M and the
 * portable build (NUM_PORTABLE_INT) use the reciprocal num_rcp16. */
#if defined(__ARM_ARCH_6M__) || defined(NUM_PORTABLE_INT)
#define NUM_HW_DIV32 0
#elif defined(__ARM_FEATURE_IDIV) || !defined(__arm__)
#define NUM_HW_DIV32 1
#else
#define NUM_HW_DIV32 0
#endif

/* floor(n / d) for d != 0 and n < d * 2^32 (the quotient fits 32 bits);
 * *rem (if not null) gets the remainder. Exact: schoolbook division in two
 * base-2^16 digits by the normalised divisor, each digit estimated (from
 * num_rcp16 with 32x32->32 multiplies, or by a 32/32 hardware divide) and
 * stepped to the exact value by its remainder. */
uint32_t num_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem);

/* floor((2^64 - 1) / dn) - 2^32 for dn in [2^31, 2^32), exact: num_rcp16's
 * estimate, one Newton step in 32-bit products (at most 6 below) and the
 * remainder's correction, without a division (num.c proves the bound). */
uint32_t num_rcp32(uint32_t dn);
/* num_rcp32(dn)'s estimate before its remainder's correction, est in
 * [v - 6, v] (v = num_rcp32(dn)), in 32x32->32 products only: a divisor's
 * reciprocal for quotients whose remainder's correction tolerates up to 6
 * more steps of the quotient than num_udiv64_32_pre's (nh + mulhi(nh, est)
 * is never above nh + mulhi(nh, v) and at most 6 below it). */
uint32_t num_rcp32_est(uint32_t dn);

/* A divisor d != 0 prepared for num_udiv64_32_pre, which divides by it
 * with two products instead of a division: dn = d 2^s in [2^31, 2^32) and
 * v = floor((2^64 - 1) / dn) - 2^32 (num_rcp32 or, with a divide
 * instruction, one num_udiv64_32: the numerator (2^32 - 1 - dn) 2^32 +
 * 2^32 - 1 has its high word below dn). */
struct num_udiv_pre { uint32_t d, dn, v; uint8_t s; };
static inline struct num_udiv_pre num_udiv_pre_make(uint32_t d)
{
    struct num_udiv_pre p;
    p.d = d;
    p.s = (uint8_t)num_clz32(d);
    p.dn = d << p.s;
    p.v = NUM_HW_DIV32 ? num_udiv64_32((uint64_t)~p.dn << 32 | 0xFFFFFFFFu, p.dn, 0) : num_rcp32(p.dn);
    return p;
}

/* num_udiv64_32(n, p->d, rem), the same quotient and remainder (n <
 * d 2^32). With N = n 2^s = Nh 2^32 + Nl and V = 2^32 + v <= 2^64 / dn,
 * the estimate q = floor(Nh V / 2^32) = Nh + mulhi(Nh, v) is never above
 * N / dn, and N / dn - Nh V / 2^32 = Nl / dn + Nh (2^64 / dn - V) / 2^32
 * < 2 + (1 + 2^-31) (Nl < 2^32 <= 2 dn; 2^64 / dn - V < 1 + 1 / dn;
 * Nh < 2^32): q is at most 3 below the quotient, which the remainder
 * N - q dn (< 4 dn < 2^34) steps up to. */
/* An estimate q of floor(N / dn), N = nh 2^32 + nl, never above it and
 * with the remainder N - q dn below 2^32 dn (modulo 2^32 in q: the
 * quotient's low word), stepped up to it by the remainder, in 32-bit halves
 * (ARMv6-M has no 64-bit shifts or compares): the remainder rh 2^32 + rl,
 * *rl_out its low word (then below dn). */
static inline uint32_t num_udiv_step(uint32_t q, uint32_t nh, uint32_t nl, uint32_t dn, uint32_t *rl_out)
{
    const uint64_t qd = num_umul32(q, dn);
    const uint32_t ql = (uint32_t)qd;
    uint32_t rl = nl - ql, rh = nh - (uint32_t)(qd >> 32) - (nl < ql);
    while (rh || rl >= dn) {
        rh -= rl < dn;
        rl -= dn;
        q++;
    }
    *rl_out = rl;
    return q;
}

static inline uint32_t num_udiv64_32_pre(uint64_t n, const struct num_udiv_pre *p, uint32_t *rem)
{
    /* N = n 2^s = nh 2^32 + nl */
    const uint32_t s = p->s, hi = (uint32_t)(n >> 32), lo = (uint32_t)n;
    const uint32_t nh = s ? hi << s | lo >> (32 - s) : hi, nl = lo << s;
    uint32_t rl;
    const uint32_t q = num_udiv_step(nh + num_mulhi32(nh, p->v), nh, nl, p->dn, &rl);
    if (rem) *rem = rl >> s;
    return q;
}

/* For dn in [2^31, 2^32): rh with 2^32 + rh 2^16 <= 2^64 / dn <
 * 2^32 + rh 2^16 + 2^17 (rh < 2^16; depends on dn >> 9 only). Table seed
 * and one Newton-Raphson step in 32x32->32 multiplies. */
uint32_t num_rcp16(uint32_t dn);
/* num_rcp16's seed: entry i is (1/x - 1) 2^16 at the centre x of
 * [1/2 + i/512, 1/2 + (i+1)/512) (for kernels that inline num_rcp16). */
extern const uint16_t num_rcp_seed[256];

/* floor(sqrt(v)); *rem (if not null) gets v - root^2. Estimate from
 * num_sqrt_est, then exact correction. */
uint64_t num_isqrt64(uint64_t v, uint64_t *rem);

/* 2^30 / sqrt(xh / 2^32) for xh in [2^30, 2^32), i.e. Q30 in (2^30, 2^31]:
 * table seed and one Newton step, relative error < 2^-17 (from below up to
 * the last-bit truncations). */
uint32_t num_rsqrt_q30(uint32_t xh);

/* For v != 0: x = v * 4^k in [2^62, 2^64) (*k set), returns sqrt(x) within
 * 2 units (so sqrt(v) = result / 2^k within 2 / 2^k); *y (if not null) gets
 * num_rsqrt_q30 of x's high word. */
uint32_t num_sqrt_est(uint64_t v, int *k, uint32_t *y);

/* sqrt(xh) * 2^16 within 2 units, xh in [2^30, 2^32) (the same estimate for
 * a 32-bit input, residual in 32-bit arithmetic). */
uint32_t num_sqrt_est32(uint32_t xh);

#ifndef NUM_FRAC
#define NUM_FRAC 16
#endif

/* a*b / 2^F rounded (halves up: the arithmetic shift of the exact product
 * plus 2^(F-1)); |result| <= 2^(62-F) + 1 <= 2^54 + 1. On ARMv6-M with
 * F <= 16 the shift is folded into the 16x16 pieces: with a = ah 2^16 + al
 * (ah = a >> 16 signed, al in [0, 2^16)), a*b = ah bh 2^32 + (ah bl + al bh)
 * 2^16 + al bl, and the first two terms are multiples of 2^F, so only
 * al bl + 2^(F-1) (< 2^32) is shifted. Every piece fits 32 bits: |ah bh| <=
 * 2^30, |ah bl|, |al bh| < 2^31. Four MULS, no 64-bit shift. */
static inline int64_t num_mul_round(int32_t a, int32_t b)
{
#if NUM_V6M_ASM && NUM_FRAC == 16
    /* the same pieces in Thumb-1: hh 2^16 | round(al bl / 2^16) (the low
     * half of hh 2^16 is zero, so an OR adds them), then the middle
     * products sign-extended: 22 instructions */
    uint32_t lo, t0, t1, t2;
    __asm__(NUM_ASM_UNIFIED(NUM_V6M_PIECES("asrs") NUM_V6M_ROUND_LO
            "lsls  %[t2], %[a], #16\n\t"
            "asrs  %[a], %[a], #16\n\t"
            "orrs  %[lo], %[t2]\n\t"
            "asrs  %[t2], %[t0], #31\n\t"
            "adds  %[lo], %[lo], %[t0]\n\t"
            "adcs  %[a], %[t2]\n\t"
            "asrs  %[t2], %[t1], #31\n\t"
            "adds  %[lo], %[lo], %[t1]\n\t"
            "adcs  %[a], %[t2]")
            : NUM_V6M_OPERANDS
            :
            : "cc");
    return (int64_t)((uint64_t)(uint32_t)a << 32 | lo);
#elif !NUM_V6M_ASM && (defined(__ARM_ARCH_6M__) || defined(NUM_PORTABLE_INT)) && NUM_FRAC <= 16
    int32_t ah = a >> 16, bh = b >> 16;
    uint32_t al = (uint32_t)a & 0xFFFFu, bl = (uint32_t)b & 0xFFFFu;
    int64_t hi = (int64_t)(ah * bh) * ((int64_t)1 << (32 - NUM_FRAC));
    int64_t mid = ((int64_t)(ah * (int32_t)bl) + (int32_t)al * bh) * (1 << (16 - NUM_FRAC));
    return hi + mid + ((al * bl + (1u << (NUM_FRAC - 1))) >> NUM_FRAC);
#else
    return (num_smul32(a, b) + ((int64_t)1 << (NUM_FRAC - 1))) >> NUM_FRAC;
#endif
}

/* num_mul_round(a, b) for a product whose result is known to lie in
 * (-2^31, 2^31): the same value in 32-bit arithmetic (the pieces summed
 * modulo 2^32 are exact when the sum fits). Only for products the scene's
 * format analysis proved in range (num_mul_fit). */
static inline int32_t num_mul_round32(int32_t a, int32_t b)
{
#if NUM_V6M_ASM && NUM_FRAC == 16
    /* hh 2^16 + al bh + ah bl + round(al bl / 2^16), mod 2^32: 17 instructions */
    uint32_t lo, t0, t1, t2;
    __asm__(NUM_ASM_UNIFIED(NUM_V6M_PIECES("asrs") NUM_V6M_ROUND_LO
            "lsls  %[a], %[a], #16\n\t"
            "adds  %[lo], %[lo], %[a]\n\t"
            "adds  %[lo], %[lo], %[t0]\n\t"
            "adds  %[lo], %[lo], %[t1]")
            : NUM_V6M_OPERANDS
            :
            : "cc");
    return (int32_t)lo;
#else
    return (int32_t)(uint32_t)(uint64_t)num_mul_round(a, b);
#endif
}

#endif
