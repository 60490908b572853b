/* raster_span.h — one span loop of the fast path (raster_fast.c), included
 * once per feature combination with these macros set:
 *   SPAN_NAME   function name
 *   SPAN_DEPTH  0 (no depth test), 2 (16-bit entries), 4 (32-bit entries)
 *   SPAN_KIND   FT_FLAT, FT_GOURAUD, FT_TEX, FT_TEX_GOURAUD
 *   SPAN_EXTRA  1: also the host's outputs (rgb888, written map)
 * Each combination is compiled on its own so the inner loop holds only what
 * it needs; every variant computes the same RGB565 bits for the same inputs.
 * Draws n pixels of s from s->px on, stepping depth and attributes per
 * pixel; returns the pixels that passed the depth test. */

RAS_HOT static uint32_t SPAN_NAME(const struct fspan *s, int n)
{
    uint16_t *px = s->px;
    uint32_t written = 0;
#if SPAN_DEPTH
    uint32_t z = s->z;
    const uint32_t dz = s->dz;
#endif
#if SPAN_DEPTH == 2
    uint16_t *zb = (uint16_t *)(void *)s->zb;
#elif SPAN_DEPTH == 4
    uint32_t *zb = (uint32_t *)(void *)s->zb;
#endif
#if SPAN_KIND == FT_FLAT
    const uint16_t col = s->ft->c565;
#endif
#if SPAN_KIND == FT_TEX || SPAN_KIND == FT_TEX_GOURAUD
    uint32_t u = (uint32_t)s->u, v = (uint32_t)s->v;
    const uint32_t du = (uint32_t)s->du, dv = (uint32_t)s->dv;
    const uint16_t *tex = s->ft->tex;
    const uint32_t wm = s->ft->wmask, hm = s->ft->hmask, tl = s->ft->wlog2;
#endif
#if SPAN_KIND == FT_GOURAUD || SPAN_KIND == FT_TEX_GOURAUD
    uint32_t li = (uint32_t)s->i;
    const uint32_t dli = (uint32_t)s->di;
#endif
#if SPAN_KIND == FT_GOURAUD
    const uint32_t kr = s->ft->kr, kg = s->ft->kg, kb = s->ft->kb;
#endif
    for (int k = 0; k < n; k++) {
#if SPAN_DEPTH == 2
        uint32_t zz = z >> 16;
        if (zz > zb[k]) {
            zb[k] = (uint16_t)zz;
#elif SPAN_DEPTH == 4
        if (z > zb[k]) {
            zb[k] = z;
#else
        {
#endif
#if SPAN_KIND == FT_FLAT
            uint16_t c = col;
#elif SPAN_KIND == FT_GOURAUD
            uint32_t ii = li >> 8;                      /* Q12 */
            uint32_t r = (kr * ii + (1u << 21)) >> 22, g = (kg * ii + (1u << 21)) >> 22,
                     b = (kb * ii + (1u << 21)) >> 22;
            if (r > 31) r = 31;
            if (g > 63) g = 63;
            if (b > 31) b = 31;
            uint16_t c = (uint16_t)(r << 11 | g << 5 | b);
#else
            uint16_t c = tex[((v >> 16) & hm) << tl | ((u >> 16) & wm)];
#if SPAN_KIND == FT_TEX_GOURAUD
            {
                uint32_t ii = li >> 8;                  /* Q12 */
                uint32_t r = ((uint32_t)(c >> 11) * ii + (1u << 11)) >> 12,
                         g = ((uint32_t)((c >> 5) & 63) * ii + (1u << 11)) >> 12,
                         b = ((uint32_t)(c & 31) * ii + (1u << 11)) >> 12;
                if (r > 31) r = 31;
                if (g > 63) g = 63;
                if (b > 31) b = 31;
                c = (uint16_t)(r << 11 | g << 5 | b);
            }
#endif
#endif
            px[k] = c;
            written++;
#if SPAN_EXTRA
            if (s->rgb888) {
#if SPAN_KIND == FT_FLAT
                s->rgb888[3 * k] = s->ft->c888[0];
                s->rgb888[3 * k + 1] = s->ft->c888[1];
                s->rgb888[3 * k + 2] = s->ft->c888[2];
#else
                ras_565_to_888(c, s->rgb888 + 3 * k);
#endif
            }
            if (s->written) s->written[k] = 1;
#endif
        }
#if SPAN_DEPTH
        z += dz;
#endif
#if SPAN_KIND == FT_TEX || SPAN_KIND == FT_TEX_GOURAUD
        u += du;
        v += dv;
#endif
#if SPAN_KIND == FT_GOURAUD || SPAN_KIND == FT_TEX_GOURAUD
        li += dli;
#endif
    }
    return written;
}

#undef SPAN_NAME
#undef SPAN_DEPTH
#undef SPAN_KIND
#undef SPAN_EXTRA
