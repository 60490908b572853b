/* SPDX-License-Identifier: MIT */
/* raster_span.h — one span loop of the fast path, included once per
 * combination of its parameters (raster_fast.h) with these macros set:
 *   SPAN_NAME   function name
 *   SPAN_SHADE  SPAN_SHADE_NONE, _RGB, _LI, _PHONG
 *   SPAN_SRC    SPAN_SRC_CONST, SPAN_SRC_TEX, SPAN_SRC_TEXBL, SPAN_SRC_TEXBW
 *   SPAN_DEPTH  0 (no depth test), 2 (16-bit entries), 4 (32-bit entries)
 *   SPAN_HOST   1: also the host's outputs (rgb888, written map) and the
 *               count of pixels written
 * Each combination is compiled on its own so the inner loop holds only what
 * it needs; every variant computes the same RGB565 bits for the same inputs.
 * Draws the row span R of triangle T: attributes perspective-correct at the
 * span's first pixel, every T->seg pixels and at its last pixel, linear in
 * between. Returns the pixels written when SPAN_HOST, else 0. The helpers
 * it calls are raster_span_lib.h's. */

#if SPAN_SHADE == SPAN_SHADE_RGB && SPAN_SRC != SPAN_SRC_CONST
#error "RGB levels are interpolated for untextured triangles only"
#endif
/* attribute slots: Phong's normal and position, u and v, then the intensity or the levels */
#define SPAN_A_UV (SPAN_SHADE == SPAN_SHADE_PHONG ? 6 : 0)
#define SPAN_A_SH (SPAN_A_UV + (SPAN_SRC != SPAN_SRC_CONST ? 2 : 0))
#if SPAN_SHADE == SPAN_SHADE_RGB
#define SPAN_NA (SPAN_A_SH + 3)
#elif SPAN_SHADE == SPAN_SHADE_LI
#define SPAN_NA (SPAN_A_SH + 1)
#else
#define SPAN_NA SPAN_A_SH
#endif
/* the intensity (Q12) a pixel's colour or texel is scaled by */
#if SPAN_SHADE == SPAN_SHADE_PHONG
#define SPAN_LIGHT ras_fphong_light(T->ft, at)
#else
#define SPAN_LIGHT (li >> 8)
#endif
/* persp_at's loop unrolled (measured: not for a lit texture, short of registers;
 * not for Phong's attributes, its code in fast memory) */
#define SPAN_UNROLL (SPAN_NA <= 3 && (SPAN_SHADE != SPAN_SHADE_LI || SPAN_SRC == SPAN_SRC_CONST))

/* the board's loops in fast memory; the host's variants never run there */
#if SPAN_HOST
static uint32_t SPAN_NAME(const struct ftri *T, const struct frow *R)
#else
RAS_HOT static uint32_t SPAN_NAME(const struct ftri *T, const struct frow *R)
#endif
{
    uint16_t *px = R->px;
    int32_t n = R->n;
    uint32_t written = 0;
#if SPAN_HOST
    uint8_t *o888 = R->rgb888, *owr = R->written;
#endif
#if SPAN_DEPTH
    uint32_t z = R->z;
    const uint32_t dz = R->dz;
#endif
#if SPAN_DEPTH == 2
    uint16_t *zp = (uint16_t *)(void *)R->zb;
#elif SPAN_DEPTH == 4
    uint32_t *zp = (uint32_t *)(void *)R->zb;
#endif
#if SPAN_NA == 0
    const uint16_t col = T->ft->c565;
#else
    int32_t w1 = R->w1, w2 = R->w2, cur[SPAN_NA], nxt[SPAN_NA];
#if SPAN_SHADE == SPAN_SHADE_RGB && SPAN_DEPTH == 2 && !SPAN_HOST && defined(__ARM_ARCH_6M__) && defined(__GNUC__)
#define SPAN_RGB_V6M 1
#else
#define SPAN_RGB_V6M 0
#endif
#if SPAN_RGB_V6M
    if (n <= 2) {
        /* a span of one or two pixels (most of a small triangle's): each
         * pixel's depth test, then its levels, a perspective-correct point's
         * (the second's the span's last point: its step is the whole
         * difference), where drawn */
        for (; n > 0; n--, px++, zp++, z += dz, w1 += T->a1, w2 += T->a2) {
            const uint32_t zz = z >> 16;
            if (zz > *zp) {
                persp_at(&T->pp, SPAN_NA, w1, w2, cur, SPAN_UNROLL);
                *zp = (uint16_t)zz;
                *px = (uint16_t)(((uint32_t)cur[SPAN_A_SH] >> 16) << 11 | ((uint32_t)cur[SPAN_A_SH + 1] >> 16) << 5 |
                                 (uint32_t)cur[SPAN_A_SH + 2] >> 16);
            }
        }
        return written;
    }
#elif SPAN_DEPTH && !SPAN_HOST
    if (n <= 2) {
        /* a span of one or two pixels (most of a small triangle's): each
         * pixel's attributes are those of a perspective-correct point (the
         * second's the span's last point: its step is the whole difference),
         * so a pixel behind the depth buffer is left out before any is made */
#if SPAN_DEPTH == 2
#define SPAN_FRONT(zv, e) ((zv) >> 16 > (e))
#else
#define SPAN_FRONT(zv, e) ((zv) > (e))
#endif
        if (!SPAN_FRONT(z, *zp)) {
            if (n == 1 || !SPAN_FRONT(z + dz, zp[1])) return written;
            px++;
            zp++;
            z += dz;
            w1 += T->a1;
            w2 += T->a2;
            n = 1;
        } else if (n == 2 && !SPAN_FRONT(z + dz, zp[1]))
            n = 1;
#undef SPAN_FRONT
    }
#endif
    persp_at(&T->pp, SPAN_NA, w1, w2, cur, SPAN_UNROLL);
    const int32_t seg = T->seg;
#endif
#if SPAN_SRC == SPAN_SRC_CONST && (SPAN_SHADE == SPAN_SHADE_LI || SPAN_SHADE == SPAN_SHADE_PHONG)
    const uint32_t kr = T->ft->kr, kg = T->ft->kg, kb = T->ft->kb;
#endif
#if SPAN_SRC == SPAN_SRC_TEX
    /* byte offsets of texels straight from the coordinates: u doubled, v
     * times twice the width, each masked to its integer bits */
    const uint8_t *tex = (const uint8_t *)T->ft->tex;
    const uint32_t um = T->ft->wmask << 1, vm = T->ft->hmask << (T->ft->wlog2 + 1), vs = T->ft->wlog2 + 1;
#elif SPAN_SRC == SPAN_SRC_TEXBL || SPAN_SRC == SPAN_SRC_TEXBW
    /* the bordered texels' rows (words) and the coordinates' range */
    const uint32_t *tex = (const uint32_t *)T->ft->tex;
    const uint32_t row = (T->ft->wmask + 3u) * (SPAN_SRC == SPAN_SRC_TEXBL ? 2u : 1u);
    /* (at most 2^30: no attribute the fast path takes is larger) */
    const int32_t umax = T->ft->wmask < 0x4000u ? (int32_t)((T->ft->wmask + 1u) << 16) : 0x40000000,
                  vmax = T->ft->hmask < 0x4000u ? (int32_t)((T->ft->hmask + 1u) << 16) : 0x40000000;
    span_clamp_uv(cur + SPAN_A_UV, umax, vmax);
#if SPAN_SHADE == SPAN_SHADE_NONE && SPAN_DEPTH == 2 && !SPAN_HOST && defined(__ARM_ARCH_6M__) && defined(__GNUC__)
    uint32_t ast[5] = { dz, (uint32_t)(uintptr_t)tex, row * 4u, 0, 0 };   /* (the loop by hand below) */
#endif
#endif
    while (n > 0) {
        int32_t m = n;
#if SPAN_NA
        int32_t d[SPAN_NA];
        if (n > seg) {          /* a whole segment, to the next one's first pixel */
            m = seg;
            w1 += T->sa1;
            w2 += T->sa2;
            persp_at(&T->pp, SPAN_NA, w1, w2, nxt, SPAN_UNROLL);
#if SPAN_SRC == SPAN_SRC_TEXBL || SPAN_SRC == SPAN_SRC_TEXBW
            span_clamp_uv(nxt + SPAN_A_UV, umax, vmax);
#endif
            for (int j = 0; j < SPAN_NA; j++) d[j] = asr32(nxt[j] - cur[j], T->slog);
        } else if (n > 1) {     /* the rest, to the span's last pixel */
            int32_t k = n - 1;
            w1 += k * T->a1;
            w2 += k * T->a2;
            persp_at(&T->pp, SPAN_NA, w1, w2, nxt, SPAN_UNROLL);
#if SPAN_SRC == SPAN_SRC_TEXBL || SPAN_SRC == SPAN_SRC_TEXBW
            span_clamp_uv(nxt + SPAN_A_UV, umax, vmax);
#endif
            for (int j = 0; j < SPAN_NA; j++) d[j] = span_mul_inv(nxt[j] - cur[j], fast_inv_tab[k]);
        } else {
            for (int j = 0; j < SPAN_NA; j++) { nxt[j] = cur[j]; d[j] = 0; }
        }
#endif
#if SPAN_SRC == SPAN_SRC_TEX
        uint32_t u = (uint32_t)cur[SPAN_A_UV] << 1, v = (uint32_t)cur[SPAN_A_UV + 1] << vs;
        const uint32_t du = (uint32_t)d[SPAN_A_UV] << 1, dv = (uint32_t)d[SPAN_A_UV + 1] << vs;
#elif SPAN_SRC == SPAN_SRC_TEXBL
        /* texel units in Q16 of the bordered texture (one texel more) less
         * half a texel, plus half a 16th: span_bilinear */
        uint32_t u = (uint32_t)cur[SPAN_A_UV] + 0x8800u, v = (uint32_t)cur[SPAN_A_UV + 1] + 0x8800u;
        const uint32_t du = (uint32_t)d[SPAN_A_UV], dv = (uint32_t)d[SPAN_A_UV + 1];
#elif SPAN_SRC == SPAN_SRC_TEXBW
        /* the same less half a texel, plus half an 8th across and half a
         * 4th down: span_bilinear_word */
        uint32_t u = (uint32_t)cur[SPAN_A_UV] + SPAN_BW_U, v = (uint32_t)cur[SPAN_A_UV + 1] + SPAN_BW_V;
        const uint32_t du = (uint32_t)d[SPAN_A_UV], dv = (uint32_t)d[SPAN_A_UV + 1];
#endif
#if SPAN_SHADE == SPAN_SHADE_PHONG
        int32_t at[6];
        for (int j = 0; j < 6; j++) at[j] = cur[j];
#elif SPAN_SHADE == SPAN_SHADE_RGB
        uint32_t cr = (uint32_t)cur[SPAN_A_SH], cg = (uint32_t)cur[SPAN_A_SH + 1], cb = (uint32_t)cur[SPAN_A_SH + 2];
        const uint32_t dcr = (uint32_t)d[SPAN_A_SH], dcg = (uint32_t)d[SPAN_A_SH + 1], dcb = (uint32_t)d[SPAN_A_SH + 2];
#elif SPAN_SHADE == SPAN_SHADE_LI
        uint32_t li = (uint32_t)cur[SPAN_A_SH];
        const uint32_t dli = (uint32_t)d[SPAN_A_SH];
#endif
        uint16_t *pe = px + m;
#if SPAN_SHADE == SPAN_SHADE_RGB && SPAN_DEPTH == 2 && !SPAN_HOST && defined(__ARM_ARCH_6M__) && defined(__GNUC__)
        {
            /* ARMv6-M: the loop below by hand, every value in a register (the
             * same operations as the C loop, so the same bits) */
            uint32_t st[5] = { (uint32_t)(uintptr_t)pe, dz, dcr, dcg, dcb };
            uint32_t a0 = (uint32_t)(uintptr_t)st, t1;
            __asm__ volatile(
                ".syntax unified\n\t"
                "ldr %[t1], [%[a0], #0]\n\t mov r8, %[t1]\n\t"
                "ldr %[t1], [%[a0], #4]\n\t mov r9, %[t1]\n\t"
                "ldr %[t1], [%[a0], #8]\n\t mov r10, %[t1]\n\t"
                "ldr %[t1], [%[a0], #12]\n\t mov r11, %[t1]\n\t"
                "ldr %[t1], [%[a0], #16]\n\t mov r12, %[t1]\n\t"
                "cmp %[px], r8\n\t beq 3f\n"
                "1:\n\t lsrs %[a0], %[z], #16\n\t ldrh %[t1], [%[zp]]\n\t cmp %[a0], %[t1]\n\t bls 2f\n\t"
                "strh %[a0], [%[zp]]\n\t"
                "lsrs %[a0], %[cr], #16\n\t lsls %[a0], %[a0], #11\n\t"
                "lsrs %[t1], %[cg], #16\n\t lsls %[t1], %[t1], #5\n\t orrs %[a0], %[t1]\n\t"
                "lsrs %[t1], %[cb], #16\n\t orrs %[a0], %[t1]\n\t strh %[a0], [%[px]]\n"
                "2:\n\t adds %[px], #2\n\t adds %[zp], #2\n\t add %[z], r9\n\t add %[cr], r10\n\t"
                "add %[cg], r11\n\t add %[cb], r12\n\t cmp %[px], r8\n\t bne 1b\n"
                "3:\n\t"
                ".syntax divided\n"
                : [px] "+l"(px), [zp] "+l"(zp), [z] "+l"(z), [cr] "+l"(cr), [cg] "+l"(cg), [cb] "+l"(cb),
                  [a0] "+l"(a0), [t1] "=&l"(t1)
                :
                : "r8", "r9", "r10", "r11", "r12", "cc", "memory");
        }
#elif SPAN_SHADE == SPAN_SHADE_NONE && SPAN_SRC == SPAN_SRC_TEX && SPAN_DEPTH == 2 && !SPAN_HOST && \
    defined(__ARM_ARCH_6M__) && defined(__GNUC__)
        {
            /* ARMv6-M: the loop below by hand (the same operations as the C
             * loop, so the same bits). r0 the pixel, r1 the depth entry's
             * offset from it, r2 the texels, r3 um, r4 vm, r5, r6 scratch,
             * r7 z, r8 the span's end, r9 u, r10 v, r11 du, r12 dv, lr dz
             * (the span's end, the steps, u and v handed over in st). */
            uint16_t *px0 = px;
            uint32_t st[6] = { (uint32_t)(uintptr_t)pe, du, dv, dz, u, v };
            register uint32_t r0 __asm__("r0") = (uint32_t)(uintptr_t)px;
            register uint32_t r1 __asm__("r1") = (uint32_t)(uintptr_t)zp - (uint32_t)(uintptr_t)px;
            register uint32_t r2 __asm__("r2") = (uint32_t)(uintptr_t)tex;
            register uint32_t r3 __asm__("r3") = um;
            register uint32_t r4 __asm__("r4") = vm;
            register uint32_t r5 __asm__("r5") = (uint32_t)(uintptr_t)st;
            register uint32_t r6 __asm__("r6") = 0;
            register uint32_t r7 __asm__("r7") = z;
            __asm__ volatile(
                ".syntax unified\n\t"
                "ldr r6, [r5, #0]\n\t mov r8, r6\n\t ldr r6, [r5, #4]\n\t mov r11, r6\n\t"
                "ldr r6, [r5, #8]\n\t mov r12, r6\n\t ldr r6, [r5, #12]\n\t mov lr, r6\n\t"
                "ldr r6, [r5, #16]\n\t mov r9, r6\n\t ldr r6, [r5, #20]\n\t mov r10, r6\n\t"
                "cmp r0, r8\n\t beq 3f\n"
                /* depth */
                "1:\n\t lsrs r5, r7, #16\n\t ldrh r6, [r0, r1]\n\t cmp r5, r6\n\t bls 2f\n\t strh r5, [r0, r1]\n\t"
                /* the texel at ((v >> 16) & vm) | ((u >> 16) & um) bytes */
                "mov r5, r10\n\t lsrs r5, r5, #16\n\t ands r5, r4\n\t mov r6, r9\n\t lsrs r6, r6, #16\n\t"
                "ands r6, r3\n\t orrs r5, r6\n\t ldrh r5, [r2, r5]\n\t strh r5, [r0]\n"
                "2:\n\t adds r0, #2\n\t add r7, lr\n\t add r9, r11\n\t add r10, r12\n\t cmp r0, r8\n\t bne 1b\n"
                "3:\n\t"
                ".syntax divided\n"
                : "+l"(r0), "+l"(r1), "+l"(r2), "+l"(r3), "+l"(r4), "+l"(r5), "+l"(r6), "+l"(r7)
                :
                : "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");
            px = (uint16_t *)(uintptr_t)r0;
            z = r7;
            zp += px - px0;
        }
#elif SPAN_SHADE == SPAN_SHADE_NONE && SPAN_SRC == SPAN_SRC_TEXBL && SPAN_DEPTH == 2 && !SPAN_HOST && \
    defined(__ARM_ARCH_6M__) && defined(__GNUC__)
        {
            /* ARMv6-M: the loop below by hand (the same operations as the C
             * loop, so the same bits; the products' order changes nothing:
             * every blend is exact modulo 2^32). r0 the pixel, r8 the span's
             * end, r9 u, r10 v, r11 z, r12 the texels, lr their row in bytes;
             * on the stack dz, du, dv and the depth entry's offset from the
             * pixel. A texel's two words and its right neighbour's are
             * consecutive: one LDM a row, the bottom one into the registers
             * its address was in. */
            uint16_t *px0 = px;
            ast[3] = du;
            ast[4] = dv;
            register uint32_t r0 __asm__("r0") = (uint32_t)(uintptr_t)px;
            register uint32_t r1 __asm__("r1") = (uint32_t)(uintptr_t)pe;
            register uint32_t r2 __asm__("r2") = z;
            register uint32_t r3 __asm__("r3") = u;
            register uint32_t r4 __asm__("r4") = v;
            register uint32_t r5 __asm__("r5") = (uint32_t)(uintptr_t)ast;
            register uint32_t r6 __asm__("r6") = (uint32_t)(uintptr_t)zp - (uint32_t)(uintptr_t)px;
            register uint32_t r7 __asm__("r7") = 0;
            __asm__ volatile(
                ".syntax unified\n\t"
                "mov r8, r1\n\t mov r11, r2\n\t mov r9, r3\n\t mov r10, r4\n\t push {r6}\n\t"
                "ldr r1, [r5, #16]\n\t push {r1}\n\t"
                "ldr r1, [r5, #12]\n\t push {r1}\n\t"
                "ldr r1, [r5, #0]\n\t push {r1}\n\t"
                "ldr r1, [r5, #4]\n\t mov r12, r1\n\t"
                "ldr r1, [r5, #8]\n\t mov lr, r1\n\t"
                "cmp r0, r8\n\t beq 3f\n"
                "1:\n\t"
                /* depth */
                "ldr r7, [sp, #12]\n\t mov r1, r11\n\t lsrs r1, r1, #16\n\t ldrh r2, [r0, r7]\n\t"
                "cmp r1, r2\n\t bls 2f\n\t strh r1, [r0, r7]\n\t"
                /* r3 = the texels' address, r1 = fx; r2 the top row, r3 the bottom one */
                "mov r3, r10\n\t lsrs r3, r3, #16\n\t mov r4, lr\n\t muls r3, r4, r3\n\t"
                "mov r1, r9\n\t lsrs r4, r1, #16\n\t lsls r4, r4, #3\n\t adds r3, r3, r4\n\t add r3, r12\n\t"
                "lsls r1, r1, #16\n\t lsrs r1, r1, #28\n\t mov r2, r3\n\t add r3, lr\n\t"
                /* top row: r4 R/B, r5 green */
                "ldm r2!, {r4, r5, r6, r7}\n\t"
                "subs r6, r6, r4\n\t muls r6, r1, r6\n\t lsls r4, r4, #4\n\t adds r4, r4, r6\n\t"
                "subs r7, r7, r5\n\t muls r7, r1, r7\n\t lsls r5, r5, #4\n\t adds r5, r5, r7\n\t"
                /* bottom row: r2 R/B, r3 green */
                "ldm r3, {r2, r3, r6, r7}\n\t"
                "subs r6, r6, r2\n\t muls r6, r1, r6\n\t lsls r2, r2, #4\n\t adds r2, r2, r6\n\t"
                "subs r7, r7, r3\n\t muls r7, r1, r7\n\t lsls r3, r3, #4\n\t adds r3, r3, r7\n\t"
                /* fy, the blends down: green's level in r5, R/B in r4 */
                "mov r1, r10\n\t lsls r1, r1, #16\n\t lsrs r1, r1, #28\n\t"
                "subs r3, r3, r5\n\t muls r3, r1, r3\n\t lsls r5, r5, #4\n\t adds r5, r5, r3\n\t lsrs r5, r5, #26\n\t"
                "subs r2, r2, r4\n\t muls r2, r1, r2\n\t lsls r4, r4, #4\n\t adds r4, r4, r2\n\t"
                /* RGB565 */
                "lsls r2, r4, #16\n\t lsrs r2, r2, #27\n\t lsls r2, r2, #6\n\t orrs r2, r5\n\t lsls r2, r2, #5\n\t"
                "lsrs r4, r4, #27\n\t orrs r2, r4\n\t strh r2, [r0]\n"
                "2:\n\t adds r0, #2\n\t"
                "ldr r1, [sp, #0]\n\t add r11, r1\n\t"
                "ldr r1, [sp, #4]\n\t add r9, r1\n\t"
                "ldr r1, [sp, #8]\n\t add r10, r1\n\t"
                "cmp r0, r8\n\t bne 1b\n"
                "3:\n\t add sp, #16\n\t mov r2, r11\n\t"
                ".syntax divided\n"
                : "+l"(r0), "+l"(r1), "+l"(r2), "+l"(r3), "+l"(r4), "+l"(r5), "+l"(r6), "+l"(r7)
                :
                : "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");
            px = (uint16_t *)(uintptr_t)r0;
            z = r2;
            zp += px - px0;
        }
#elif SPAN_SHADE == SPAN_SHADE_NONE && SPAN_SRC == SPAN_SRC_TEXBW && SPAN_DEPTH == 2 && !SPAN_HOST && \
    defined(__ARM_ARCH_6M__) && defined(__GNUC__)
        {
            /* ARMv6-M: the loop below by hand (the same operations as the C
             * loop, so the same bits). r0 the pixel, r7 the depth entry's
             * offset from it, r8 the span's end, r9 u, r10 v, r11 z, r12 the
             * texels, lr their row in bytes; on the stack dz, du, dv and
             * SPAN_BW_HALF. A texel and its right neighbour: one LDM. */
            uint16_t *px0 = px;
            ast[3] = du;
            ast[4] = dv;
            register uint32_t r0 __asm__("r0") = (uint32_t)(uintptr_t)px;
            register uint32_t r1 __asm__("r1") = (uint32_t)(uintptr_t)pe;
            register uint32_t r2 __asm__("r2") = z;
            register uint32_t r3 __asm__("r3") = u;
            register uint32_t r4 __asm__("r4") = v;
            register uint32_t r5 __asm__("r5") = (uint32_t)(uintptr_t)ast;
            register uint32_t r6 __asm__("r6") = SPAN_BW_HALF;
            register uint32_t r7 __asm__("r7") = (uint32_t)(uintptr_t)zp - (uint32_t)(uintptr_t)px;
            __asm__ volatile(
                ".syntax unified\n\t"
                "mov r8, r1\n\t mov r11, r2\n\t mov r9, r3\n\t mov r10, r4\n\t push {r6}\n\t"
                "ldr r1, [r5, #16]\n\t push {r1}\n\t"
                "ldr r1, [r5, #12]\n\t push {r1}\n\t"
                "ldr r1, [r5, #0]\n\t push {r1}\n\t"
                "ldr r1, [r5, #4]\n\t mov r12, r1\n\t"
                "ldr r1, [r5, #8]\n\t mov lr, r1\n\t"
                "cmp r0, r8\n\t beq 3f\n"
                "1:\n\t"
                /* depth */
                "mov r1, r11\n\t lsrs r1, r1, #16\n\t ldrh r2, [r0, r7]\n\t"
                "cmp r1, r2\n\t bls 2f\n\t strh r1, [r0, r7]\n\t"
                /* r2 the texel's address, r3 the one below, r1 = fx, r6 = v */
                "mov r6, r10\n\t lsrs r3, r6, #16\n\t mov r4, lr\n\t muls r3, r4, r3\n\t"
                "mov r1, r9\n\t lsrs r4, r1, #16\n\t lsls r4, r4, #2\n\t adds r3, r3, r4\n\t add r3, r12\n\t"
                "lsls r1, r1, #16\n\t lsrs r1, r1, #29\n\t mov r2, r3\n\t add r3, lr\n\t"
                /* the blend across, top (r4) and bottom (r3) */
                "ldm r2!, {r4, r5}\n\t"
                "subs r5, r5, r4\n\t muls r5, r1, r5\n\t lsls r4, r4, #3\n\t adds r4, r4, r5\n\t"
                "ldm r3, {r3, r5}\n\t"
                "subs r5, r5, r3\n\t muls r5, r1, r5\n\t lsls r3, r3, #3\n\t adds r3, r3, r5\n\t"
                /* fy, the blend down, half a level */
                "lsls r6, r6, #16\n\t lsrs r6, r6, #30\n\t"
                "subs r3, r3, r4\n\t muls r3, r6, r3\n\t lsls r4, r4, #2\n\t adds r4, r4, r3\n\t"
                "ldr r1, [sp, #12]\n\t adds r4, r4, r1\n\t"
                /* RGB565 */
                "lsrs r2, r4, #26\n\t lsls r2, r2, #6\n\t lsls r3, r4, #11\n\t lsrs r3, r3, #26\n\t orrs r2, r3\n\t"
                "lsls r2, r2, #5\n\t lsls r4, r4, #22\n\t lsrs r4, r4, #27\n\t orrs r2, r4\n\t strh r2, [r0]\n"
                "2:\n\t adds r0, #2\n\t"
                "ldr r1, [sp, #0]\n\t add r11, r1\n\t"
                "ldr r1, [sp, #4]\n\t add r9, r1\n\t"
                "ldr r1, [sp, #8]\n\t add r10, r1\n\t"
                "cmp r0, r8\n\t bne 1b\n"
                "3:\n\t add sp, #16\n\t mov r2, r11\n\t"
                ".syntax divided\n"
                : "+l"(r0), "+l"(r1), "+l"(r2), "+l"(r3), "+l"(r4), "+l"(r5), "+l"(r6), "+l"(r7)
                :
                : "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");
            px = (uint16_t *)(uintptr_t)r0;
            z = r2;
            zp += px - px0;
        }
#else
        for (; px != pe; px++) {
#if SPAN_DEPTH == 2
            uint32_t zz = z >> 16;
            if (zz > *zp) {
                *zp = (uint16_t)zz;
#elif SPAN_DEPTH == 4
            if (z > *zp) {
                *zp = z;
#else
            {
#endif
#if SPAN_SRC == SPAN_SRC_CONST
#if SPAN_SHADE == SPAN_SHADE_NONE
                uint16_t c = col;
#elif SPAN_SHADE == SPAN_SHADE_RGB
                /* channel levels in Q16, half a level added: no channel
                 * passes its top level (the triangle's intensities allow it) */
                uint16_t c = (uint16_t)((cr >> 16) << 11 | (cg >> 16) << 5 | cb >> 16);
#else
                uint32_t ii = SPAN_LIGHT;                   /* Q12 */
                uint16_t c = pack565_sat((kr * ii + (1u << 21)) >> 22, (kg * ii + (1u << 21)) >> 22,
                                         (kb * ii + (1u << 21)) >> 22);
#endif
#elif SPAN_SRC == SPAN_SRC_TEXBL
                /* the blended texel; lit: its 8-bit channels lit, then their levels */
                uint32_t tg, trb = span_bilinear(tex, u, v, row, &tg);
#if SPAN_SHADE != SPAN_SHADE_NONE
                uint32_t t8 = light888(span_bl_888(trb, tg), SPAN_LIGHT);
                uint16_t c = pack888_565(t8);
#else
                uint16_t c = span_bl_565(trb, tg);
#if SPAN_HOST
                uint32_t t8 = span_bl_888(trb, tg);
#endif
#endif
#elif SPAN_SRC == SPAN_SRC_TEXBW
                uint32_t tw = span_bilinear_word(tex, u, v, row);
#if SPAN_SHADE != SPAN_SHADE_NONE
                uint32_t t8 = light888(span_bw_888(tw), SPAN_LIGHT);
                uint16_t c = pack888_565(t8);
#else
                uint16_t c = span_bw_565(tw);
#if SPAN_HOST
                uint32_t t8 = span_bw_888(tw);
#endif
#endif
#else /* SPAN_SRC_TEX */
                uint16_t c = *(const uint16_t *)(const void *)(tex + (((v >> 16) & vm) | ((u >> 16) & um)));
#if SPAN_SHADE != SPAN_SHADE_NONE
                {
                    uint32_t ii = SPAN_LIGHT;               /* Q12 */
                    c = pack565_sat(((uint32_t)(c >> 11) * ii + (1u << 11)) >> 12,
                                    ((uint32_t)((c >> 5) & 63) * ii + (1u << 11)) >> 12,
                                    ((uint32_t)(c & 31) * ii + (1u << 11)) >> 12);
                }
#endif
#endif
                *px = c;
#if SPAN_HOST
                written++;
                if (o888) {
#if SPAN_NA == 0
                    o888[0] = T->ft->c888[0];
                    o888[1] = T->ft->c888[1];
                    o888[2] = T->ft->c888[2];
#elif SPAN_SRC == SPAN_SRC_TEXBL || SPAN_SRC == SPAN_SRC_TEXBW
                    o888[0] = (uint8_t)(t8 >> 16);
                    o888[1] = (uint8_t)(t8 >> 8);
                    o888[2] = (uint8_t)t8;
#else
                    span_565_to_888(c, o888);
#endif
                }
                if (owr) *owr = 1;
#endif
            }
#if SPAN_HOST
            if (o888) o888 += 3;
            if (owr) owr++;
#endif
#if SPAN_DEPTH
            zp++;
            z += dz;
#endif
#if SPAN_SRC != SPAN_SRC_CONST
            u += du;
            v += dv;
#endif
#if SPAN_SHADE == SPAN_SHADE_PHONG
            for (int j = 0; j < 6; j++) at[j] += d[j];
#elif SPAN_SHADE == SPAN_SHADE_RGB
            cr += dcr;
            cg += dcg;
            cb += dcb;
#elif SPAN_SHADE == SPAN_SHADE_LI
            li += dli;
#endif
        }
#endif
        n -= m;
#if SPAN_NA
        for (int j = 0; j < SPAN_NA; j++) cur[j] = nxt[j];
#endif
    }
    return written;
}

#undef SPAN_NAME
#undef SPAN_DEPTH
#undef SPAN_A_UV
#undef SPAN_A_SH
#undef SPAN_NA
#undef SPAN_LIGHT
#undef SPAN_UNROLL
#undef SPAN_RGB_V6M
