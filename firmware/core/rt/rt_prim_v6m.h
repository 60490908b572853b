/* SPDX-License-Identifier: MIT */
/* rt_prim_v6m.h — the per-pixel part of a primary ray's lean sphere test
 * (prim_sphere_hit in rt_intersect.c), fixed point: b, the near root
 * beyond the limit (rt_near_beyond_na), CO x D and the discriminant
 * (rt_quad_disc_x) from the row's parts in rt_obj_cache. rt_prim_disc_c is
 * the C; on ARMv6-M (Cortex-M0+) rt_prim_disc_v6m does the same in Thumb-1
 * assembly, its 64-bit values in register pairs and its 32x32 -> 64
 * products from 16-bit halves, with the same bits
 * (tests/unit/test_rt_v6m.c compares the two on the emulated Cortex-M0+).
 * Internal to the ray tracer. */
#ifndef RT_PRIM_V6M_H
#define RT_PRIM_V6M_H

#include "rt_int.h"

#if NUM_MODE == NUM_MODE_FIXED

/* b at 2F fraction bits (bx), the discriminant dd 2^e (rt_quad_disc_x) */
struct rt_pdisc {
    int64_t bx;
    uint64_t dd;
    int32_t e;
};

/* For a sphere with the camera outside (c_cam > 0) and the row's parts of
 * ray's row in oc (px_row): 0 when b <= 0 (both roots behind), when the
 * near root is certainly beyond limit (near_ok, rt_near_beyond_na) or when
 * the discriminant is negative; else 1 with *o. near_ok is set only with
 * cm_cam in (0, 2^(62-F)) (rt_near_n_ok). */
RT_ALWAYS_INLINE int rt_prim_disc_c(const struct rt_obj_cache *oc, const struct rt_ray *ray, num limit,
                                    struct rt_pdisc *o)
{
    num dxx = ray->dx.x;
    int64_t bx = oc->px_b - num_smul32(oc->co_cam.x, dxx);
    if (bx <= 0) return 0;
    o->bx = bx;
    if (oc->near_ok && rt_near_beyond_na(bx, oc->cm_cam, limit)) return 0;
    int e;
    if (!rt_quad_disc_x(oc->px_x0, rt_mag64(num_smul32(oc->co_cam.z, dxx) - oc->px_cxd),
                        rt_mag64(oc->px_x2 - num_smul32(oc->co_cam.y, dxx)), ray->dxa, &oc->qs, &o->dd, &e))
        return 0;
    o->e = e;
    return 1;
}

/* The near root along the row's direction (prim_sphere_hit's common case):
 * from *pd, q (rt_quad_root_x) and t = c m / q (rt_quad_near_m) where its
 * rt_wdiv takes the 64/32 fast path: 1 with o->q and o->t when the
 * discriminant is positive, q != 0 and that path applies, else 0 (the
 * caller then solves the general way: the same values where this gives
 * them). pd from rt_prim_disc (bx > 0), c m = oc->cm_cam > 0. */
struct rt_pnear {
    wnum q;
    num t;
};

RT_ALWAYS_INLINE int rt_prim_near_c(const struct rt_pdisc *pd, const struct rt_obj_cache *oc, struct rt_pnear *o)
{
    wnum cm = oc->cm_cam;
    uint64_t dd = pd->dd;
    int e = (int)pd->e;
    if (dd == 0) return 0;
    if (e & 1) { dd <<= 1; e--; }
    int64_t qx = pd->bx + (int64_t)(num_isqrt64(dd, 0) << (e / 2));
    wnum q = rt_shr_round(qx, NUM_FRAC);
    if (q == 0) return 0;
    o->q = q;
    /* rt_quad_near_m, then rt_wdiv's fast path */
    int sh = rt_bitlen64(rt_mag64(q)) - 32;
    wnum n = cm, d = q;
    if (sh > 0) {
        n = rt_shr_round(cm, sh);
        d = rt_shr_round(q, sh);
    }
    if (!(n >= 0 && d > 0 && d <= (wnum)UINT32_MAX && n < ((wnum)1 << (63 - NUM_FRAC)))) return 0;
    uint64_t nn = (uint64_t)n << NUM_FRAC;
    uint32_t dv = (uint32_t)d, rm;
    if ((nn >> 32) >= dv) return 0;
    uint64_t t = num_udiv64_32(nn, dv, &rm);
    if (rm >= dv - rm) t++;
    if (t > (uint64_t)INT32_MAX) return 0;
    o->t = (num)t;
    return 1;
}

/* Both: 0 as rt_prim_disc_c's 0; 1 with o->pn (and o->pd); 2 with o->pd
 * only (rt_prim_near_c's 0: the caller solves the general way). */
struct rt_psolve {
    struct rt_pdisc pd;
    struct rt_pnear pn;
};

RT_ALWAYS_INLINE int rt_prim_solve_c(const struct rt_obj_cache *oc, const struct rt_ray *ray, num limit,
                                     struct rt_psolve *o)
{
    if (!rt_prim_disc_c(oc, ray, limit, &o->pd)) return 0;
    return rt_prim_near_c(&o->pd, oc, &o->pn) ? 1 : 2;
}

#if defined(__ARM_ARCH_6M__) && defined(__GNUC__) && !defined(__clang__) && NUM_FRAC >= 15 && NUM_FRAC <= 20
#define RT_PRIM_DISC_V6M 1
/* The offsets the assembly reads (oc, ray, the result). */
_Static_assert(offsetof(struct rt_obj_cache, co_cam) == 8 && offsetof(struct rt_obj_cache, cm_cam) == 32 &&
                   offsetof(struct rt_obj_cache, qs) + offsetof(struct rt_qsphere, r2s) == 192 &&
                   offsetof(struct rt_obj_cache, qs) + offsetof(struct rt_qsphere, kr) == 196 &&
                   offsetof(struct rt_obj_cache, px_b) == 224 && offsetof(struct rt_obj_cache, px_x2) == 232 &&
                   offsetof(struct rt_obj_cache, px_cxd) == 240 && offsetof(struct rt_obj_cache, px_x0) == 248 &&
                   offsetof(struct rt_obj_cache, near_ok) == 256,
               "rt_prim_disc_v6m: rt_obj_cache offsets");
_Static_assert(offsetof(struct rt_ray, dx) == 108 && offsetof(struct rt_ray, dxa) == 120,
               "rt_prim_disc_v6m: rt_ray offsets");
_Static_assert(offsetof(struct rt_pdisc, bx) == 0 && offsetof(struct rt_pdisc, dd) == 8 &&
                   offsetof(struct rt_pdisc, e) == 16,
               "rt_prim_disc_v6m: rt_pdisc offsets");

#define RT_PD_S2(x) #x
#define RT_PD_S(x) RT_PD_S2(x)
#define RT_PD_F RT_PD_S(NUM_FRAC)
/* to the label L unless cc (a far branch) */
#define RT_PD_FAIL_UNLESS(L, cc) "b" cc " 8f\n\t b " L "f\n8:\n\t"
/* a:lo = a b, 32x32 -> 64 from 16-bit halves (SH lsrs: unsigned, asrs:
 * signed), num_umul32's and num_smul32's pieces; b, t0, t1, t2 clobbered */
#define RT_PD_MUL(SH, a, b, lo, t0, t1, t2)                                                          \
    "uxth " t0 ", " a "\n\t " SH " " a ", " a ", #16\n\t uxth " t1 ", " b "\n\t " SH " " b ", " b    \
    ", #16\n\t movs " lo ", " t0 "\n\t muls " lo ", " t1 "\n\t muls " t0 ", " b "\n\t muls " t1 ", " \
    a "\n\t muls " a ", " b "\n\t lsls " t2 ", " t0 ", #16\n\t " SH " " t0 ", " t0 ", #16\n\t adds " \
    lo ", " lo ", " t2 "\n\t adcs " a ", " t0 "\n\t lsls " t2 ", " t1 ", #16\n\t " SH " " t1 ", "  \
    t1 ", #16\n\t adds " lo ", " lo ", " t2 "\n\t adcs " a ", " t1 "\n\t"
/* s:lo = s^2 (unsigned): ah^2 2^32 + al ah 2^17 + al^2; al, t clobbered */
#define RT_PD_SQ(s, al, lo, t)                                                                        \
    "uxth " al ", " s "\n\t lsrs " s ", " s ", #16\n\t movs " lo ", " al "\n\t muls " lo ", " al    \
    "\n\t muls " al ", " s "\n\t muls " s ", " s "\n\t lsls " t ", " al ", #17\n\t lsrs " al ", " al \
    ", #15\n\t adds " lo ", " lo ", " t "\n\t adcs " s ", " al "\n\t"
/* hi:lo = |hi:lo| (t the sign mask) */
#define RT_PD_ABS(lo, hi, t) \
    "asrs " t ", " hi ", #31\n\t eors " lo ", " t "\n\t eors " hi ", " t "\n\t subs " lo ", " lo ", " t "\n\t sbcs " hi ", " t "\n\t"
/* n = the bit length of v (v, t clobbered) */
#define RT_PD_BITLEN_STEP(v, n, t, k) \
    "lsrs " t ", " v ", #" k "\n\t beq 1f\n\t movs " v ", " t "\n\t adds " n ", #" k "\n1:\n\t"
#define RT_PD_BITLEN(v, n, t)                                                                            \
    "movs " n ", #0\n\t" RT_PD_BITLEN_STEP(v, n, t, "16") RT_PD_BITLEN_STEP(v, n, t, "8")                \
        RT_PD_BITLEN_STEP(v, n, t, "4") RT_PD_BITLEN_STEP(v, n, t, "2") RT_PD_BITLEN_STEP(v, n, t, "1") \
            "adds " n ", " n ", " v "\n\t"
/* hi:lo >>= k (k >= 0, below 256; k, t clobbered) */
#define RT_PD_SHR64(hi, lo, k, t)                                                                      \
    "cmp " k ", #32\n\t bhi 7f\n\t movs " t ", " hi "\n\t lsrs " lo ", " lo ", " k "\n\t lsrs " hi      \
    ", " hi ", " k "\n\t rsbs " k ", " k ", #0\n\t adds " k ", #32\n\t lsls " t ", " t ", " k "\n\t orrs " \
    lo ", " t "\n\t b 6f\n7:\n\t subs " k ", #32\n\t lsrs " hi ", " hi ", " k "\n\t movs " lo ", " hi   \
    "\n\t movs " hi ", #0\n6:\n\t"
#if NUM_FRAC > 15
/* cm 2^F / 2^(30-F) = cm 2^(2F-30) (cm < 2^(62-F): no bit lost) */
#define RT_PD_CM_SHIFT                                                                              \
    "lsls r6, r6, #(2 * " RT_PD_F " - 30)\n\t lsrs r7, r5, #(62 - 2 * " RT_PD_F ")\n\t orrs r6, r7\n\t" \
    "lsls r5, r5, #(2 * " RT_PD_F " - 30)\n\t"
#else
#define RT_PD_CM_SHIFT ""
#endif

/* rt_prim_disc_c in Thumb-1 (to FAIL when it returns 0). Registers: r0 oc
 * (r1 oc + 192 from A on, r8 at the end), r8 r9 a, r10 dx.x, r11 limit,
 * r12 o; A: bx = px_b - co.x dx.x (stored); B: rt_near_beyond_na (qs =
 * ((2 bx + 2^(F-1)) >> 30) + 1, the two floors of its shifts in one); C:
 * the cross product's magnitudes x0 (row), x1, x2 (r11:lr, r6:r5 then
 * r10), kx from the high words' bit length (r11), the three 30-bit parts
 * squared and summed (xx, r3:r5); D: a >> ka (ka from a's high word), a r^2
 * (r2:r0), both at the coarser scale, the difference. */
#define RT_PD_DISC_BODY(FAIL) \
    "mov r12, r3\n\t mov r11, r2\n\t" \
    "ldr r4, [r1, #108]\n\t mov r10, r4\n\t ldr r4, [r1, #120]\n\t mov r8, r4\n\t" \
    "ldr r4, [r1, #124]\n\t mov r9, r4\n\t movs r1, r0\n\t adds r1, #192\n\t" \
    /* A */ \
    "ldr r2, [r0, #8]\n\t mov r3, r10\n\t" RT_PD_MUL("asrs", "r2", "r3", "r4", "r5", "r6", "r7") \
    "ldr r5, [r1, #32]\n\t ldr r6, [r1, #36]\n\t subs r5, r5, r4\n\t sbcs r6, r2\n\t" \
    "cmp r6, #0\n\t" RT_PD_FAIL_UNLESS(FAIL, "ge") "bne 1f\n\t cmp r5, #0\n\t" RT_PD_FAIL_UNLESS(FAIL, "ne") \
    "1:\n\t mov r3, r12\n\t str r5, [r3]\n\t str r6, [r3, #4]\n\t" \
    /* B */ \
    "movs r3, #64\n\t ldrb r3, [r1, r3]\n\t cmp r3, #0\n\t beq 5f\n\t" \
    "mov r2, r11\n\t lsrs r3, r2, #30\n\t bne 5f\n\t lsrs r3, r6, #28\n\t bne 5f\n\t" \
    "cmp r6, #0\n\t bne 1f\n\t lsrs r3, r5, #" RT_PD_F "\n\t beq 5f\n1:\n\t" \
    "movs r4, r6\n\t adds r7, r5, r5\n\t adcs r4, r6\n\t" \
    "movs r3, #1\n\t lsls r3, r3, #(" RT_PD_F " - 1)\n\t adds r7, r7, r3\n\t movs r3, #0\n\t adcs r4, r3\n\t" \
    "lsls r4, r4, #2\n\t lsrs r7, r7, #30\n\t orrs r4, r7\n\t adds r4, #1\n\t adds r2, #1\n\t" \
    RT_PD_MUL("lsrs", "r2", "r4", "r3", "r5", "r6", "r7") \
    "ldr r5, [r0, #32]\n\t ldr r6, [r0, #36]\n\t" RT_PD_CM_SHIFT \
    "cmp r6, r2\n\t" RT_PD_FAIL_UNLESS(FAIL, "ls") "bne 5f\n\t cmp r5, r3\n\t" RT_PD_FAIL_UNLESS(FAIL, "lo") \
    "5:\n\t" \
    /* C */ \
    "ldr r2, [r0, #16]\n\t mov r3, r10\n\t" RT_PD_MUL("asrs", "r2", "r3", "r4", "r5", "r6", "r7") \
    "ldr r5, [r1, #48]\n\t ldr r6, [r1, #52]\n\t subs r4, r4, r5\n\t sbcs r2, r6\n\t" \
    RT_PD_ABS("r4", "r2", "r5") "mov lr, r4\n\t mov r11, r2\n\t" \
    "ldr r2, [r0, #12]\n\t mov r3, r10\n\t" RT_PD_MUL("asrs", "r2", "r3", "r4", "r5", "r6", "r7") \
    "ldr r5, [r1, #40]\n\t ldr r6, [r1, #44]\n\t subs r5, r5, r4\n\t sbcs r6, r2\n\t" \
    RT_PD_ABS("r5", "r6", "r7") "mov r10, r5\n\t" \
    "ldr r3, [r1, #56]\n\t ldr r4, [r1, #60]\n\t mov r2, r11\n\t" \
    "movs r0, r4\n\t orrs r0, r2\n\t orrs r0, r6\n\t beq 2f\n\t" \
    RT_PD_BITLEN("r0", "r7", "r5") "adds r7, #2\n\t b 3f\n" \
    "2:\n\t mov r0, lr\n\t orrs r0, r3\n\t mov r5, r10\n\t orrs r0, r5\n\t lsrs r0, r0, #30\n\t" \
    "movs r7, r0\n\t cmp r0, #3\n\t bne 3f\n\t movs r7, #2\n" \
    "3:\n\t mov r11, r7\n\t cmp r7, #32\n\t bls 4f\n\t" \
    "mov r3, r4\n\t mov lr, r2\n\t mov r10, r6\n\t movs r4, #0\n\t movs r2, #0\n\t movs r6, #0\n\t subs r7, #32\n" \
    "4:\n\t movs r0, #32\n\t subs r0, r0, r7\n\t" \
    "lsrs r3, r3, r7\n\t lsls r4, r4, r0\n\t orrs r3, r4\n\t" \
    "mov r4, lr\n\t lsrs r4, r4, r7\n\t lsls r2, r2, r0\n\t orrs r2, r4\n\t" \
    "mov r4, r10\n\t lsrs r4, r4, r7\n\t lsls r6, r6, r0\n\t orrs r6, r4\n\t" \
    RT_PD_SQ("r3", "r4", "r5", "r7") RT_PD_SQ("r2", "r4", "r0", "r7") \
    "adds r5, r5, r0\n\t adcs r3, r2\n\t" \
    RT_PD_SQ("r6", "r4", "r0", "r7") "adds r5, r5, r0\n\t adcs r3, r6\n\t" \
    /* D */ \
    "mov r0, r9\n\t mov r2, r8\n\t cmp r0, #0\n\t beq 2f\n\t movs r6, r0\n\t" \
    RT_PD_BITLEN("r6", "r4", "r7") "adds r4, #1\n\t" \
    "movs r6, #32\n\t subs r6, r6, r4\n\t lsrs r2, r2, r4\n\t lsls r0, r0, r6\n\t orrs r2, r0\n\t b 3f\n" \
    "2:\n\t lsrs r4, r2, #31\n\t lsrs r2, r2, r4\n" \
    "3:\n\t ldr r6, [r1, #4]\n\t adds r4, r4, r6\n\t mov r10, r4\n\t ldr r6, [r1, #0]\n\t" \
    "mov r8, r1\n\t" RT_PD_MUL("lsrs", "r2", "r6", "r0", "r7", "r4", "r1") \
    "mov r4, r11\n\t lsls r4, r4, #1\n\t mov r6, r10\n\t cmp r4, r6\n\t bls 2f\n\t" \
    "subs r6, r4, r6\n\t" RT_PD_SHR64("r2", "r0", "r6", "r7") "b 3f\n" \
    "2:\n\t subs r4, r6, r4\n\t" RT_PD_SHR64("r3", "r5", "r4", "r7") "movs r4, r6\n" \
    "3:\n\t cmp r2, r3\n\t" RT_PD_FAIL_UNLESS(FAIL, "hs") "bne 1f\n\t cmp r0, r5\n\t" RT_PD_FAIL_UNLESS(FAIL, "hs") \
    "1:\n\t subs r0, r0, r5\n\t sbcs r2, r3\n\t" \
    "mov r3, r12\n\t str r0, [r3, #8]\n\t str r2, [r3, #12]\n\t str r4, [r3, #16]\n\t"

/* rt_prim_near_c in Thumb-1 (to FAIL when it returns 0), num_isqrt64 and
 * num_udiv64_32 called (the caller keeps the stack 8-byte aligned, the
 * remainder at sp). Registers: r7 pd, r11 oc, r10 the result; r4 e / 2; q
 * (r1:r0) then d (r0), n (r3:r2), sh r6. */
#define RT_PD_NEAR_BODY(FAIL) \
    "ldr r0, [r7, #8]\n\t ldr r1, [r7, #12]\n\t movs r2, r0\n\t orrs r2, r1\n\t" RT_PD_FAIL_UNLESS(FAIL, "ne") \
    "ldr r4, [r7, #16]\n\t lsrs r4, r4, #1\n\t bcc 1f\n\t adds r0, r0, r0\n\t adcs r1, r1\n1:\n\t" \
    "movs r2, #0\n\t bl num_isqrt64\n\t" \
    /* hx = root << (e / 2) */ \
    "cmp r4, #32\n\t bhs 2f\n\t movs r3, #32\n\t subs r3, r3, r4\n\t movs r2, r0\n\t lsrs r2, r2, r3\n\t" \
    "lsls r1, r1, r4\n\t orrs r1, r2\n\t lsls r0, r0, r4\n\t b 3f\n" \
    "2:\n\t subs r4, #32\n\t lsls r0, r0, r4\n\t movs r1, r0\n\t movs r0, #0\n" \
    "3:\n\t ldr r2, [r7, #0]\n\t ldr r3, [r7, #4]\n\t adds r0, r0, r2\n\t adcs r1, r3\n\t" \
    /* q = (qx + 2^(F-1)) >> F */ \
    "movs r2, #1\n\t lsls r2, r2, #(" RT_PD_F " - 1)\n\t movs r3, #0\n\t adds r0, r0, r2\n\t adcs r1, r3\n\t" \
    "lsrs r0, r0, #" RT_PD_F "\n\t lsls r2, r1, #(32 - " RT_PD_F ")\n\t orrs r0, r2\n\t lsrs r1, r1, #" RT_PD_F "\n\t" \
    "movs r2, r0\n\t orrs r2, r1\n\t" RT_PD_FAIL_UNLESS(FAIL, "ne") \
    "mov r2, r10\n\t str r0, [r2]\n\t str r1, [r2, #4]\n\t" \
    /* n = cm, d = q, both by 2^sh rounded when q >= 2^32 */ \
    "mov r3, r11\n\t ldr r2, [r3, #32]\n\t ldr r3, [r3, #36]\n\t" \
    "cmp r1, #0\n\t beq 4f\n\t" \
    "movs r5, r1\n\t" RT_PD_BITLEN("r5", "r6", "r4") \
    "movs r4, #1\n\t subs r5, r6, #1\n\t lsls r4, r4, r5\n\t movs r5, #0\n\t adds r0, r0, r4\n\t adcs r1, r5\n\t" \
    "movs r5, #32\n\t subs r5, r5, r6\n\t lsrs r0, r0, r6\n\t movs r4, r1\n\t lsls r4, r4, r5\n\t orrs r0, r4\n\t" \
    "lsrs r1, r1, r6\n\t cmp r1, #0\n\t" RT_PD_FAIL_UNLESS(FAIL, "eq") \
    "movs r4, #1\n\t subs r1, r6, #1\n\t lsls r4, r4, r1\n\t movs r1, #0\n\t adds r2, r2, r4\n\t adcs r3, r1\n\t" \
    "lsrs r2, r2, r6\n\t movs r4, r3\n\t lsls r4, r4, r5\n\t orrs r2, r4\n\t lsrs r3, r3, r6\n" \
    "4:\n\t" \
    /* rt_wdiv's fast path: n >= 0, n < 2^(63-F), (n 2^F) >> 32 < d */ \
    "cmp r3, #0\n\t" RT_PD_FAIL_UNLESS(FAIL, "ge") "lsrs r4, r3, #(31 - " RT_PD_F ")\n\t" RT_PD_FAIL_UNLESS(FAIL, "eq") \
    "lsls r3, r3, #" RT_PD_F "\n\t lsrs r4, r2, #(32 - " RT_PD_F ")\n\t orrs r3, r4\n\t lsls r2, r2, #" RT_PD_F "\n\t" \
    "cmp r3, r0\n\t" RT_PD_FAIL_UNLESS(FAIL, "lo") \
    "movs r5, r0\n\t movs r0, r2\n\t movs r1, r3\n\t movs r2, r5\n\t mov r3, sp\n\t bl num_udiv64_32\n\t" \
    "cmp r0, #0\n\t" RT_PD_FAIL_UNLESS(FAIL, "ge") \
    "ldr r3, [sp]\n\t subs r2, r5, r3\n\t cmp r3, r2\n\t blo 1f\n\t adds r0, #1\n\t" RT_PD_FAIL_UNLESS(FAIL, "pl") "1:\n\t" \
    "mov r2, r10\n\t str r0, [r2, #8]\n\t"

_Static_assert(offsetof(struct rt_pnear, q) == 0 && offsetof(struct rt_pnear, t) == 8, "rt_prim_near_v6m: offsets");
_Static_assert(offsetof(struct rt_psolve, pd) == 0 && offsetof(struct rt_psolve, pn) == 24,
               "rt_prim_solve_v6m: offsets");
#define RT_PD_OPERANDS                 \
    : "+l"(r0), "+l"(r1), "+l"(r2), "+l"(r3) \
    :                                  \
    : "r4", "r5", "r6", "r7", "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory"

/* rt_prim_disc_c and rt_prim_near_c on their own (tests/unit/test_rt_v6m.c) */
__attribute__((noinline, unused)) static int rt_prim_disc_v6m(const struct rt_obj_cache *oc, const struct rt_ray *ray,
                                                             num limit, struct rt_pdisc *o)
{
    register uint32_t r0 __asm__("r0") = (uint32_t)(uintptr_t)oc;
    register const struct rt_ray *r1 __asm__("r1") = ray;
    register num r2 __asm__("r2") = limit;
    register struct rt_pdisc *r3 __asm__("r3") = o;
    __asm__ volatile(".syntax unified\n\t" RT_PD_DISC_BODY("9") "movs r0, #1\n\t b 0f\n"
                     "9:\n\t movs r0, #0\n"
                     "0:\n\t .syntax divided\n" RT_PD_OPERANDS);
    return (int)r0;
}

__attribute__((noinline, unused)) static int rt_prim_near_v6m(const struct rt_pdisc *pd,
                                                             const struct rt_obj_cache *oc, struct rt_pnear *o)
{
    register uint32_t r0 __asm__("r0") = (uint32_t)(uintptr_t)pd;
    register const struct rt_obj_cache *r1 __asm__("r1") = oc;
    register struct rt_pnear *r2 __asm__("r2") = o;
    register uint32_t r3 __asm__("r3") = 0;
    __asm__ volatile(".syntax unified\n\t sub sp, #4\n\t mov r10, r2\n\t mov r11, r1\n\t movs r7, r0\n\t"
                     RT_PD_NEAR_BODY("9") "movs r0, #1\n\t b 0f\n"
                     "9:\n\t movs r0, #0\n"
                     "0:\n\t add sp, #4\n\t .syntax divided\n" RT_PD_OPERANDS);
    return (int)r0;
}

/* rt_prim_solve_c: both in one call, the discriminant kept in registers
 * (o->pd stored for the general way); between them r7 = o, r10 = &o->pn,
 * r11 = oc (from r8). */
__attribute__((noinline)) static int rt_prim_solve_v6m(const struct rt_obj_cache *oc,
                                                              const struct rt_ray *ray, num limit,
                                                              struct rt_psolve *o)
{
    register uint32_t r0 __asm__("r0") = (uint32_t)(uintptr_t)oc;
    register const struct rt_ray *r1 __asm__("r1") = ray;
    register num r2 __asm__("r2") = limit;
    register struct rt_psolve *r3 __asm__("r3") = o;
    __asm__ volatile(".syntax unified\n\t sub sp, #4\n\t" RT_PD_DISC_BODY("9")
                     "mov r7, r12\n\t movs r3, r7\n\t adds r3, #24\n\t mov r10, r3\n\t"
                     "mov r3, r8\n\t subs r3, #192\n\t mov r11, r3\n\t"
                     RT_PD_NEAR_BODY("91") "movs r0, #1\n\t b 0f\n"
                     "91:\n\t movs r0, #2\n\t b 0f\n"
                     "9:\n\t movs r0, #0\n"
                     "0:\n\t add sp, #4\n\t .syntax divided\n" RT_PD_OPERANDS);
    return (int)r0;
}
#endif

/* rt_prim_solve_c, by the assembly where there is one */
RT_ALWAYS_INLINE int rt_prim_solve(const struct rt_obj_cache *oc, const struct rt_ray *ray, num limit,
                                   struct rt_psolve *o)
{
#ifdef RT_PRIM_DISC_V6M
    return rt_prim_solve_v6m(oc, ray, limit, o);
#else
    return rt_prim_solve_c(oc, ray, limit, o);
#endif
}

#endif
#endif
