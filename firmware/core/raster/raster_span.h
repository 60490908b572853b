/* SPDX-License-Identifier: MIT */
/* raster_span.h — one span loop of the fast path (raster_fast.c), included
 * once per feature combination with these macros set:
 *   SPAN_NAME   function name
 *   SPAN_DEPTH  0 (no depth test), 2 (16-bit entries), 4 (32-bit entries)
 *   SPAN_KIND   FT_FLAT, FT_GOURAUD, FT_GOURAUD_SAT, FT_TEX, FT_TEX_GOURAUD
 *   SPAN_EXTRA  1: also the host's outputs (rgb888, written map) and the
 *               count of pixels written
 * Each combination is compiled on its own so the inner loop holds only what
 * it needs; every variant computes the same RGB565 bits for the same inputs.
 * Draws the row span R of triangle T: attributes perspective-correct at the
 * span's first pixel, every T->seg pixels and at its last pixel, linear in
 * between. Returns the pixels written when SPAN_EXTRA, else 0. */

/* the board's loops in fast memory; the host's variants (SPAN_EXTRA) never run there */
#if SPAN_EXTRA
static uint32_t SPAN_NAME(const struct ftri *T, const struct frow *R)
#else
RAS_HOT static uint32_t SPAN_NAME(const struct ftri *T, const struct frow *R)
#endif
{
    uint16_t *px = R->px;
    int32_t n = R->n;
    uint32_t written = 0;
#if SPAN_EXTRA
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
#if SPAN_KIND == FT_GOURAUD_SAT
#define SPAN_NA 1
#elif SPAN_KIND == FT_TEX
#define SPAN_NA 2
#elif SPAN_KIND == FT_PHONG
#define SPAN_NA 6
#elif SPAN_KIND == FT_PHONG_TEX
#define SPAN_NA 8
#else
#define SPAN_NA 3
#endif
#if SPAN_KIND == FT_PHONG || SPAN_KIND == FT_PHONG_TEX
#define SPAN_PHONG 1
#else
#define SPAN_PHONG 0
#endif
#if SPAN_KIND == FT_FLAT
    const uint16_t col = T->ft->c565;
#else
    int32_t w1 = R->w1, w2 = R->w2, cur[SPAN_NA], nxt[SPAN_NA];
    persp_at(&T->pp, SPAN_NA, w1, w2, cur);
    const int32_t seg = T->seg;
#endif
#if SPAN_KIND == FT_PHONG
    const uint32_t kr = T->ft->kr, kg = T->ft->kg, kb = T->ft->kb;
#endif
#if SPAN_KIND == FT_TEX || SPAN_KIND == FT_TEX_GOURAUD || SPAN_KIND == FT_PHONG_TEX
    /* byte offsets of texels straight from the coordinates: u doubled, v
     * times twice the width, each masked to its integer bits */
    const uint8_t *tex = (const uint8_t *)T->ft->tex;
    const uint32_t um = T->ft->wmask << 1, vm = T->ft->hmask << (T->ft->wlog2 + 1), vs = T->ft->wlog2 + 1;
#endif
#if SPAN_KIND == FT_GOURAUD_SAT
    const uint32_t kr = T->ft->kr, kg = T->ft->kg, kb = T->ft->kb;
#endif
    while (n > 0) {
        int32_t m = n;
#if SPAN_KIND != FT_FLAT
        int32_t d[SPAN_NA];
        if (n > seg) {          /* a whole segment, to the next one's first pixel */
            m = seg;
            w1 += T->sa1;
            w2 += T->sa2;
            persp_at(&T->pp, SPAN_NA, w1, w2, nxt);
            for (int j = 0; j < SPAN_NA; j++) d[j] = asr32(nxt[j] - cur[j], T->slog);
        } else if (n > 1) {     /* the rest, to the span's last pixel */
            int32_t k = n - 1;
            w1 += k * T->a1;
            w2 += k * T->a2;
            persp_at(&T->pp, SPAN_NA, w1, w2, nxt);
            for (int j = 0; j < SPAN_NA; j++)
                d[j] = (int32_t)(num_smul32(nxt[j] - cur[j], (int32_t)fast_inv_tab[k]) >> 16);
        } else {
            for (int j = 0; j < SPAN_NA; j++) { nxt[j] = cur[j]; d[j] = 0; }
        }
#endif
#if SPAN_KIND == FT_TEX || SPAN_KIND == FT_TEX_GOURAUD
        uint32_t u = (uint32_t)cur[0] << 1, v = (uint32_t)cur[1] << vs;
        const uint32_t du = (uint32_t)d[0] << 1, dv = (uint32_t)d[1] << vs;
#elif SPAN_KIND == FT_PHONG_TEX
        uint32_t u = (uint32_t)cur[6] << 1, v = (uint32_t)cur[7] << vs;
        const uint32_t du = (uint32_t)d[6] << 1, dv = (uint32_t)d[7] << vs;
#endif
#if SPAN_PHONG
        int32_t at[6];
        for (int j = 0; j < 6; j++) at[j] = cur[j];
#endif
#if SPAN_KIND == FT_GOURAUD
        uint32_t cr = (uint32_t)cur[0], cg = (uint32_t)cur[1], cb = (uint32_t)cur[2];
        const uint32_t dcr = (uint32_t)d[0], dcg = (uint32_t)d[1], dcb = (uint32_t)d[2];
#elif SPAN_KIND == FT_GOURAUD_SAT
        uint32_t li = (uint32_t)cur[0];
        const uint32_t dli = (uint32_t)d[0];
#elif SPAN_KIND == FT_TEX_GOURAUD
        uint32_t li = (uint32_t)cur[2];
        const uint32_t dli = (uint32_t)d[2];
#endif
        uint16_t *pe = px + m;
#if SPAN_KIND == FT_GOURAUD && SPAN_DEPTH == 2 && !SPAN_EXTRA && defined(__ARM_ARCH_6M__) && defined(__GNUC__)
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
#if SPAN_KIND == FT_FLAT
                uint16_t c = col;
#elif SPAN_KIND == FT_GOURAUD
                /* channel levels in Q16, half a level added: no channel
                 * passes its top level (the triangle's intensities allow it) */
                uint16_t c = (uint16_t)((cr >> 16) << 11 | (cg >> 16) << 5 | cb >> 16);
#elif SPAN_KIND == FT_PHONG
                uint32_t ii = phong_light(T->ft, at);       /* Q12 */
                uint16_t c = pack565_sat((kr * ii + (1u << 21)) >> 22, (kg * ii + (1u << 21)) >> 22,
                                         (kb * ii + (1u << 21)) >> 22);
#elif SPAN_KIND == FT_GOURAUD_SAT
                uint32_t ii = li >> 8;                      /* Q12 */
                uint16_t c = pack565_sat((kr * ii + (1u << 21)) >> 22, (kg * ii + (1u << 21)) >> 22,
                                         (kb * ii + (1u << 21)) >> 22);
#else
                uint16_t c = *(const uint16_t *)(const void *)(tex + (((v >> 16) & vm) | ((u >> 16) & um)));
#if SPAN_KIND == FT_TEX_GOURAUD || SPAN_KIND == FT_PHONG_TEX
                {
#if SPAN_KIND == FT_PHONG_TEX
                    uint32_t ii = phong_light(T->ft, at);   /* Q12 */
#else
                    uint32_t ii = li >> 8;                  /* Q12 */
#endif
                    c = pack565_sat(((uint32_t)(c >> 11) * ii + (1u << 11)) >> 12,
                                    ((uint32_t)((c >> 5) & 63) * ii + (1u << 11)) >> 12,
                                    ((uint32_t)(c & 31) * ii + (1u << 11)) >> 12);
                }
#endif
#endif
                *px = c;
#if SPAN_EXTRA
                written++;
                if (o888) {
#if SPAN_KIND == FT_FLAT
                    o888[0] = T->ft->c888[0];
                    o888[1] = T->ft->c888[1];
                    o888[2] = T->ft->c888[2];
#else
                    ras_565_to_888(c, o888);
#endif
                }
                if (owr) *owr = 1;
#endif
            }
#if SPAN_EXTRA
            if (o888) o888 += 3;
            if (owr) owr++;
#endif
#if SPAN_DEPTH
            zp++;
            z += dz;
#endif
#if SPAN_KIND == FT_TEX || SPAN_KIND == FT_TEX_GOURAUD || SPAN_KIND == FT_PHONG_TEX
            u += du;
            v += dv;
#endif
#if SPAN_PHONG
            for (int j = 0; j < 6; j++) at[j] += d[j];
#endif
#if SPAN_KIND == FT_GOURAUD
            cr += dcr;
            cg += dcg;
            cb += dcb;
#elif SPAN_KIND == FT_GOURAUD_SAT || SPAN_KIND == FT_TEX_GOURAUD
            li += dli;
#endif
        }
#endif
        n -= m;
#if SPAN_KIND != FT_FLAT
        for (int j = 0; j < SPAN_NA; j++) cur[j] = nxt[j];
#endif
    }
    return written;
}

#undef SPAN_NAME
#undef SPAN_DEPTH
#undef SPAN_KIND
#undef SPAN_EXTRA
#undef SPAN_NA
#undef SPAN_PHONG
