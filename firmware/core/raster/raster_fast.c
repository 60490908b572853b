/* SPDX-License-Identifier: MIT */
/* raster_fast.c — the default path's fast triangle: span loops specialised
 * per feature combination, integer stepping, no division per pixel.
 *
 * Coverage is the exact path's: the same sub-pixel vertices, edge functions
 * and top-left rule, evaluated per row instead of per pixel. For each edge
 * the columns a row covers form a half-line whose end is a quotient of two
 * integers; it is stepped from row to row by quotient and remainder, so
 * every row's span is exactly the set of pixels the per-pixel test accepts
 * (tests/unit/test_raster.c checks the two against each other).
 *
 * Depth: near/z at the first pixel of each span as the exact path computes
 * it, then stepped by the triangle's per-column gradient truncated toward
 * zero, so every stepped value lies between the exact values at the span's
 * ends (no clamp is needed, nothing wraps).
 *
 * Attributes (Gouraud intensity, texture coordinates) are perspective-correct
 * at the first pixel of a span and every 2^persp_log2 pixels after it (and
 * at its last pixel), and linear in between: one reciprocal per segment.
 * At those points the perspective weights w_i/z_i are formed in 32 bits
 * (edge values and near/z each normalised per triangle), the attributes in
 * integer formats fixed per triangle. The colour is computed in RGB565:
 * Gouraud as colour levels times intensity, textures stored as RGB565 with
 * power-of-two masks (raster_init converts them).
 *
 * This file sets a triangle up and walks its rows; the loops that draw a
 * row are raster_span.h's (raster_spans.c, raster_spans_host.c), chosen by
 * shade, texture source, depth size and outputs (raster_fast.h). */
#include "raster_span_lib.h"

/* ras_num_to_fix(a, scale), the same value: in fixed point its product
 * by the inline 32 x 32 -> 64 kernel, a power-of-two scale (the intensity's
 * 2^20) by a shift; one of at least 2^NUM_FRAC leaves nothing to round:
 * a 2^(pow2 - NUM_FRAC), saturated as ras_fix_round saturates, in 32 bits. */
static inline int32_t fast_to_fix(num a, int32_t scale, int pow2)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (pow2 >= NUM_FRAC && pow2 - NUM_FRAC <= 30) {
        const int k = pow2 - NUM_FRAC;
        const int32_t lim = INT32_MAX >> k;
        return a > lim ? INT32_MAX : (a < -lim ? -INT32_MAX : a * ((int32_t)1 << k));
    }
    return ras_fix_round(pow2 ? (int64_t)a * ((int64_t)1 << pow2) : num_smul32(a, scale));
#else
    (void)pow2;
    return ras_num_to_fix(a, scale);
#endif
}

#if NUM_MODE == NUM_MODE_FIXED
/* k where scale = 2^W - c, c = scale & 1 (0 or 1) and k = W - NUM_FRAC lies
 * in [0, 30] (a texture's scale: 2^(16 + its side's log2), less 1 where
 * nearest); else -1. */
static inline int scale_pow2_k(int32_t scale)
{
    const uint32_t s = (uint32_t)scale + ((uint32_t)scale & 1u);
    if (scale <= 0 || (s & (s - 1u))) return -1;
    const int k = 31 - num_clz32(s) - NUM_FRAC;
    return k >= 0 && k <= 30 ? k : -1;
}

/* ras_fix_round(a * scale) for scale_pow2_k(scale) = k >= 0: with m = |a|
 * and h = 2^(NUM_FRAC - 1), a 2^W - c a rounded is sign(a) (m 2^k +
 * floor((h - c m) / 2^NUM_FRAC)) (m 2^W being a multiple of 2^NUM_FRAC), a
 * sum in [0, INT32_MAX] where m <= INT32_MAX >> k (nothing to saturate):
 * 32-bit values there, the 64-bit product and rounding elsewhere. */
static inline int32_t fix_scale_k(num a, int32_t scale, int k)
{
    const uint32_t m = a < 0 ? 0u - (uint32_t)a : (uint32_t)a;
    if (m > ((uint32_t)INT32_MAX >> k)) return ras_fix_round(num_smul32(a, scale));
    const int32_t t = (int32_t)(1 << (NUM_FRAC - 1)) - (int32_t)((uint32_t)scale & 1u ? m : 0u);
    const int32_t q = (int32_t)(m << k) + asr32(t, NUM_FRAC);
    return a < 0 ? -q : q;
}
#endif

/* The least s with x >> s below 2^b (b < 32): x's bit length less b, from
 * num_clz32 (on ARMv6-M its table: a dozen instructions, where the loop
 * that shifts once a step took five a bit). */
static inline int shift_below(uint32_t x, int b)
{
    return x >> b ? 32 - b - num_clz32(x) : 0;
}

/* Corner values c0..c2 of attribute j; 0 when they do not fit the
 * fast path's formats (the triangle then takes the exact path). */
static int persp_attr(struct fpersp *p, int j, int32_t c0, int32_t c1, int32_t c2)
{
    const int32_t lim = (int32_t)1 << 30;
    if (c0 <= -lim || c0 >= lim || c1 <= -lim || c1 >= lim || c2 <= -lim || c2 >= lim) return 0;
    int32_t e1 = c1 - c0, e2 = c2 - c0;
    uint32_t m1 = e1 < 0 ? (uint32_t)-e1 : (uint32_t)e1, m2 = e2 < 0 ? (uint32_t)-e2 : (uint32_t)e2;
    uint32_t m = m1 > m2 ? m1 : m2;
    const int sh = shift_below(m, 14);
    if (sh > 16) return 0;
    p->at[j].a0 = c0;
    p->at[j].rs = 16 - sh;
    p->at[j].d1 = e1 >= 0 ? e1 >> sh : -(int32_t)(m1 >> sh);
    p->at[j].d2 = e2 >= 0 ? e2 >> sh : -(int32_t)(m2 >> sh);
    return 1;
}

/* One edge's bound on the columns of a row, k = column - c0:
 * kind 1: k >= q (lower), kind -1: k <= q (upper), kind 0: every column
 * while the row value n >= 0, none otherwise. q = floor(num / den) is
 * stepped per row by quotient dq and remainder dr (all 32-bit: the fast
 * path takes triangles whose box is at most 2^14 sub-pixel units a side). */
struct fedge { int kind; int32_t n, q, r, den, dq, dr; };

/* floor(n / d) and n - floor(n / d) * d for d > 0, in 32 bits (the
 * board's divider where it has one). */
static void floordiv32(int32_t n, int32_t d, int32_t *q, int32_t *r)
{
    int32_t qq = n / d, rr = n % d;
    if (rr < 0) { qq--; rr += d; }
    *q = qq;
    *r = rr;
}

static void fedge_init(struct fedge *e, int32_t a, int32_t b, int32_t w, int32_t bias)
{
    int64_t num, step, rem;
    /* pixel (c0 + k, row) is covered when w + k*a + bias >= 0 */
    if (a > 0) {          /* k >= ceil((-bias - w) / a) = floor((-bias - w + a - 1) / a) */
        e->kind = 1;
        e->den = a;
        num = (int64_t)-bias - w + a - 1;
        step = -(int64_t)b;
    } else if (a < 0) {   /* k <= floor((w + bias) / -a) */
        e->kind = -1;
        e->den = -a;
        num = (int64_t)w + bias;
        step = b;
    } else {
        e->kind = 0;
        e->den = 1;
        e->n = w + bias;
        e->dq = b;
        e->q = e->r = e->dr = 0;
        return;
    }
    e->n = 0;
    if (num > INT32_MIN && num <= INT32_MAX && step > INT32_MIN && step <= INT32_MAX) {
        floordiv32((int32_t)num, e->den, &e->q, &e->r);
        floordiv32((int32_t)step, e->den, &e->dq, &e->dr);
        return;
    }
    e->q = (int32_t)ras_floordiv(num, e->den, &rem);
    e->r = (int32_t)rem;
    e->dq = (int32_t)ras_floordiv(step, e->den, &rem);
    e->dr = (int32_t)rem;
}

/* Everything a triangle's rows need, kept between strips (struct
 * ras_fast_state is this, opaque to the rest of the rasterizer). The fields
 * the set-up and the row walks read come first: within 124 bytes of the
 * start, a word's offset from a base register fits ARMv6-M's LDR and STR
 * (past it each access first makes its offset). */
struct fstate {
    int32_t wr[3], a[3], b[3];   /* edge values at (c0, row), steps per column and row */
    int32_t wb[3];               /* (scan) wr + the top-left rule's bias: covered when all >= 0 */
    int32_t c0, kmax, row, last; /* box column, last column less c0, next row, last row */
    /* z32: the plane below (zrow, gy16) in 32-bit words, zrow = zhi * 2^16
     * + zfrac and gy16 = gyq * 2^16 + gyf (modulo 2^48; fractions below
     * 2^16), where every span's depths are proven to lie in [1, 2^32 - 2] */
    uint32_t zhi, zfrac, gyq, gyf;
    int32_t gxq;                 /* column gradient gxq * 2^16 + gxf */
    uint32_t gxf, dz;
    int scan;                    /* a narrow box: each row's span found by stepping across it */
    int z32;
    int shade, src, depth;       /* the span loop: raster_fast.h */
    int64_t zrow, gy16;          /* depth plane at (c0, row), Q32.16 */
    struct fedge fe[3];          /* (row bounds by division: scan == 0) */
    struct ras_fast_tri ftc;     /* the triangle's description, where T.ft points once kept */
    struct ftri T;
};
typedef char ras_fast_state_fits[sizeof(struct fstate) <= sizeof(struct ras_fast_state) ? 1 : -1];

/* The edge functions and their row bounds of triangle v0 v1 v2 (area > 0,
 * box its sub-pixel box, at most 2^14 a side) for rows from the strip's
 * first on, into S; *rtop = the box's top row. Returns 1 or 0 (nothing to
 * draw). */
#define RAS_SCAN_MAX 160
/* Edge i from (ax, ay) by (dx, dy): its value at the box's first pixel
 * (px, py), its steps and, where not scanned, its row bounds. */
static inline void fast_edge_w(struct fstate *S, int i, int32_t w, int32_t dx, int32_t dy, int sb, int scan)
{
    const int32_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : -1;
    /* (times 2^sb: |dx|, |dy| <= 2^14) */
    const int32_t a = -dy * ((int32_t)1 << sb), b = dx * ((int32_t)1 << sb);
    S->wr[i] = w;
    S->a[i] = a;
    S->b[i] = b;
    S->wb[i] = w + bias;
    if (!scan) fedge_init(&S->fe[i], a, b, w, bias);
}

static inline void fast_edge(struct fstate *S, int i, int32_t ax, int32_t ay, int32_t dx, int32_t dy, int32_t px,
                             int32_t py, int sb, int scan)
{
    /* ras_edge's value in 32 bits: the pixel lies within a pixel of the
     * box, so |dx|, |dy| <= 2^14 and the other factors < 2^14 + 2^9 */
    fast_edge_w(S, i, dx * (py - ay) - dy * (px - ax), dx, dy, sb, scan);
}

static int fast_edges(const struct ras_ctx *rc, const int32_t box[4], const struct ras_sv *v0,
                      const struct ras_sv *v1, const struct ras_sv *v2, int32_t area, struct fstate *S, int32_t *rtop)
{
    const struct render_target *t = rc->cur.t;
    int sb = rc->def.sub_bits;
    /* (32-bit edge arithmetic: the caller took corners within 2^14 sub-pixel
     * units of each other, 1024 pixels at 4 sub-pixel bits) */
    const int32_t minx = box[0], miny = box[1], maxx = box[2], maxy = box[3];
    int32_t half = (int32_t)1 << (sb - 1), one = (int32_t)1 << sb;
    /* the box's columns; its rows those of the pixel centres within it (the
     * depth plane is taken at the row above, rtop, in every case) */
    int32_t c0 = minx >> sb, c1 = (maxx >> sb) + 1, r0 = (miny - half + one - 1) >> sb, r1 = (maxy - half) >> sb;
    /* the columns of the pixel centres within it, cl to cr: no pixel
     * outside them is covered */
    int32_t cl = (minx - half + one - 1) >> sb, cr = (maxx - half) >> sb;
    *rtop = miny >> sb;
    if (c0 < 0) c0 = 0;
    if (r0 < (int32_t)t->y0) r0 = t->y0;
    if (c1 > (int32_t)rc->w - 1) c1 = rc->w - 1;
    if (r1 > (int32_t)rc->h - 1) r1 = rc->h - 1;
    if (cl < c0) cl = c0;
    if (cr > c1) cr = c1;
    if (cl > cr || r0 > r1 || r0 >= (int32_t)t->y1) return 0;

    /* the exact path's edge functions at (c0, r0) and their steps; every
     * value inside the box is below 2^29 in magnitude */
    int32_t px = (c0 << sb) + half, py = (r0 << sb) + half;
    /* a box of few pixels a row (for the rows left) finds each row's span
     * by stepping the edge values across it, cheaper than the divisions
     * that bound it (the same columns either way) */
    const int scan = (c1 - c0 + 2) * (r1 - r0 + 1) <= RAS_SCAN_MAX;
    S->scan = scan;
    const int32_t x0 = v0->x, y0 = v0->y, x1 = v1->x, y1 = v1->y, x2 = v2->x, y2 = v2->y;
    fast_edge(S, 0, x1, y1, x2 - x1, y2 - y1, px, py, sb, scan);
    fast_edge(S, 1, x2, y2, x0 - x2, y0 - y2, px, py, sb, scan);
    /* the three edge values sum to the doubled area at every point (each
     * is zero on its own edge, the third the area at the opposite corner,
     * and their steps cancel): the third without its products, the same
     * value (|area| < 2^28, each value below 2^29) */
    fast_edge_w(S, 2, area - S->wr[0] - S->wr[1], x1 - x0, y1 - y0, sb, scan);
    S->c0 = c0;
    S->kmax = cr - c0;
    S->row = r0;
    S->last = r1;
    return 1;
}

/* Depth: a plane in Q32.16 (exact at (c0, the box's top row rtop),
 * gradients to 2^-16, stepped row by row from there whatever the strips),
 * stepped per pixel by the column gradient truncated toward zero. Returns
 * 1, or -1 when a gradient does not fit. */
/* dd * w, a depth difference (|dd| < 2^32) times an edge value or step
 * (|w| < 2^31): one 32 x 32 -> 64 product when dd fits 32 bits, as it does
 * across a small triangle (the same value either way). */
static int64_t mul_dw(int64_t dd, int32_t w)
{
    if (dd >= -INT32_MAX && dd <= INT32_MAX) return num_smul32((int32_t)dd, w);
    return dd * w;
}

/* Division by a triangle's doubled area d > 0, exact: floor(n / d) and the
 * remainder in [0, d). m = floor((2^32 - 1) / d) is made at the first |n| <
 * 2^32 (0: not yet); for those the estimate |n| m / 2^32 is below |n| / d
 * by less than 1, so one step up at most corrects it; larger n take
 * ras_floordiv. */
struct adiv { uint32_t d, m; };
static int64_t adiv_floor(struct adiv *A, int64_t n, int64_t *rem)
{
    uint64_t un = n < 0 ? (uint64_t)0 - (uint64_t)n : (uint64_t)n;
    if (un > UINT32_MAX) return ras_floordiv(n, A->d, rem);
    if (A->m == 0) A->m = 0xFFFFFFFFu / A->d;
    uint32_t x = (uint32_t)un, q = (uint32_t)(num_umul32(x, A->m) >> 32), r = x - q * A->d;
    if (r >= A->d) { r -= A->d; q++; }
    if (n >= 0) { *rem = r; return q; }
    if (r == 0) { *rem = 0; return -(int64_t)q; }
    *rem = A->d - r;
    return -(int64_t)q - 1;
}

/* The plane's 32-bit form (struct fstate's z32) when the corners' depths
 * lie in [2, 2^32 - 2]. A covered pixel's centre lies in the triangle, where
 * the exact plane is a mean of the corners' depths; the stepped Q32.16
 * value is below it by less than 2^16 (one truncation at the top row, one
 * per row and one per column, fewer than 2^15 in all), so a span's first
 * depth is at least the smallest corner's - 1, its last (stepped by the
 * column gradient truncated toward zero) between that and the exact value
 * at its last pixel, less at most 1: every one in [1, 2^32 - 2], where the
 * 64-bit row's clamp never applies and the low 32 bits are the value. */
static void depth_words(struct fstate *S, uint32_t d0, uint32_t d1, uint32_t d2)
{
    uint32_t lo = d0 < d1 ? d0 : d1, hi = d0 < d1 ? d1 : d0;
    if (d2 < lo) lo = d2;
    if (d2 > hi) hi = d2;
    S->z32 = lo >= 2 && hi <= UINT32_MAX - 1;
    S->zhi = (uint32_t)((uint64_t)S->zrow >> 16);
    S->zfrac = (uint32_t)S->zrow & 0xFFFFu;
    S->gyq = (uint32_t)((uint64_t)S->gy16 >> 16);
    S->gyf = (uint32_t)S->gy16 & 0xFFFFu;
}

/* floor(n / d) and the remainder in [0, d) for 0 < d < 2^16, m = floor((2^32
 * - 1) / d): the estimate |n| m / 2^32 is below |n| / d by less than 1, so
 * one step up at most corrects it. */
#if defined(__GNUC__) || defined(__clang__)
#define RAS_SETUP_INLINE static inline __attribute__((always_inline))
#else
#define RAS_SETUP_INLINE static inline
#endif
/* (inline: five calls a triangle, their remainders in registers) */
RAS_SETUP_INLINE int32_t sdiv16(int32_t n, uint32_t d, uint32_t m, int32_t *rem)
{
    uint32_t x = n < 0 ? 0u - (uint32_t)n : (uint32_t)n;
    uint32_t q = num_mulhi32(x, m), r = x - q * d;
    if (r >= d) {
        r -= d;
        q++;
    }
    if (n >= 0) {
        *rem = (int32_t)r;
        return (int32_t)q;
    }
    *rem = r != 0 ? (int32_t)(d - r) : 0;
    return -(int32_t)q - (r != 0);
}

/* floor(n / d) and the remainder in [0, d) for n = rd1 x1 + rd2 x2 (rd_i
 * in [0, d), |x1| + |x2| <= M < 2^16, |n| + 8 d < 2^31) from e_i in
 * (rd_i 2^15 / d - 2, rd_i 2^15 / d] (0 <= e_i < 2^15): the estimate
 * (e1 x1 + e2 x2) / 2^15 (|.| < 2^31) is below n / d by less than 2 M /
 * 2^15 < 4 in magnitude, its floor then corrected by steps of d (the
 * remainder below 2^31 in magnitude throughout). Two products and a
 * shift in place of sdiv16's division. */
RAS_SETUP_INLINE int32_t rdiv_est(int32_t n, int32_t e1, int32_t x1, int32_t e2, int32_t x2, int32_t d, int32_t *rem)
{
    int32_t q = asr32(e1 * x1 + e2 * x2, 15), r = n - q * d;
    while (r < 0) {
        r += d;
        q--;
    }
    while (r >= d) {
        r -= d;
        q++;
    }
    *rem = r;
    return q;
}

/* a - b for |a - b| < 2^31. */
static int32_t sdiff(uint32_t a, uint32_t b) { return a >= b ? (int32_t)(a - b) : -(int32_t)(b - a); }

/* floor(r 2^16 / d) for 0 <= r < d < 2^16 (the same m). The estimate
 * floor(r 2^16 m / 2^32) = floor(r m / 2^16) is below 2^16 (r m < 2^32), so
 * it is r mh + floor(r ml / 2^16) with m = mh 2^16 + ml: two 32-bit
 * products (num_mulhi32's value). */
RAS_SETUP_INLINE uint32_t frac16(int32_t r, uint32_t d, uint32_t m)
{
    const uint32_t ur = (uint32_t)r, q = ur * (m >> 16) + ((ur * (m & 0xFFFFu)) >> 16);
    return q + ((ur << 16) - q * d >= d);
}

/* floor((2^32 - 1) / d) for 0 < d < 2^16 (sdiv16's m), for d >= 2^8
 * without a division: 2^30 / s (rcp30, s = d scaled into [2^14, 2^15))
 * scaled to 2^32 / d and lowered by 2^-12 of itself, which leaves it below
 * the quotient; one product by it adds floor(r m / 2^32) <= r / d of the
 * remainder r = 2^32 - 1 - m d, and at most two steps of d finish it
 * (checked for every d below 2^16 against the division). */
static uint32_t area_recip(uint32_t d)
{
    if (d < (1u << 8)) return 0xFFFFFFFFu / d;
    uint32_t s = d;
    int k = 2;
    while (s < (1u << 14)) {
        s <<= 1;
        k++;
    }
    if (s >= (1u << 15)) {     /* (d >= 2^15: its low bit dropped) */
        s >>= 1;
        k--;
    }
    uint32_t m = rcp30(s) << k;
    m -= m >> 12;
    m += num_mulhi32(0xFFFFFFFFu - m * d, m);
    uint32_t r = 0xFFFFFFFFu - m * d;
    while (r >= d) {
        r -= d;
        m++;
    }
    return m;
}

/* |x| of an int32_t as uint32_t. */
static uint32_t uabs32(int32_t x) { return x < 0 ? 0u - (uint32_t)x : (uint32_t)x; }

/* fast_depth's plane in 32-bit words for a triangle of doubled area A below
 * 2^16 and corners' depths in [2, 2^32 - 2] (depth_words) whose
 * differences fit 32 bits: the same values. A numerator sum_i dd_i x_i
 * (dd_i corner i's depth less corner 0's, x_i the column step a_i, the row
 * step b_i or the edge value at the box's top row) is sum_i (qd_i A + rd_i)
 * x_i with dd_i = qd_i A + rd_i, rd_i in [0, A): its quotient by A is
 * sum_i qd_i x_i plus the quotient of the remainders' part sum_i rd_i x_i,
 * whose magnitude is at most (A - 1) M, M the largest |x_1| + |x_2| of the
 * three pairs, so below 2^31 where (A - 1) M < 2^31: 32-bit divisions. The
 * gradients' quotients are at most (Q + 1) M_ab in magnitude (Q the larger
 * |qd_i|, M_ab that of the steps): exact in 32 bits where that is below
 * 2^31; the top row's depth is needed modulo 2^32 only (zhi), so its
 * quotients' part wraps. Returns 1, or 0 where the ranges do not allow it. */
static int depth_small(const struct ras_sv *v0, const struct ras_sv *v1, const struct ras_sv *v2, int32_t area,
                       int32_t rtop, struct fstate *S)
{
    const uint32_t d0 = v0->depth, d1 = v1->depth, d2 = v2->depth;
    const int32_t *wr = S->wr, *a = S->a, *b = S->b, r0 = S->row;
    if (area >= (1 << 16)) return 0;
    uint32_t lo = d0 < d1 ? d0 : d1, hi = d0 < d1 ? d1 : d0;
    if (d2 < lo) lo = d2;
    if (d2 > hi) hi = d2;
    if (lo < 2 || hi > UINT32_MAX - 1 || hi - lo > (uint32_t)INT32_MAX) return 0;
    int32_t w1t = wr[1] - (r0 - rtop) * b[1], w2t = wr[2] - (r0 - rtop) * b[2];
    /* (every edge value and step below 2^30 in magnitude: the sums below 2^31) */
    uint32_t Mab = uabs32(a[1]) + uabs32(a[2]), Mb = uabs32(b[1]) + uabs32(b[2]), M = uabs32(w1t) + uabs32(w2t);
    if (Mb > Mab) Mab = Mb;
    if (Mab > M) M = Mab;
    const uint32_t A = (uint32_t)area;
    /* (A - 1) M + 8 A < 2^31 (rdiv_est), in 32 bits where M < 2^16 (A < 2^16) */
    if (M >= (1u << 16) || (A - 1u) * M + 8u * A >= (1u << 31)) return 0;
    const uint32_t m = area_recip(A);
    /* (|dd_i| < 2^31: the depths' range) */
    int32_t dd1 = sdiff(d1, d0), dd2 = sdiff(d2, d0), rd1, rd2, rx, ry, rz;
    int32_t qd1 = sdiv16(dd1, A, m, &rd1), qd2 = sdiv16(dd2, A, m, &rd2);
    /* (Q + 1) M_ab < 2^31, in 32 bits where Q < 2^16 (M_ab < 2^16) */
    const uint32_t Q = uabs32(qd1) > uabs32(qd2) ? uabs32(qd1) : uabs32(qd2);
    if (Q < (1u << 16) ? (Q + 1u) * Mab >= (1u << 31) : num_umul32(Q + 1u, Mab) >= (1u << 31)) return 0;
    /* e_i = floor(rd_i m / 2^17), in (rd_i 2^15 / A - 2, rd_i 2^15 / A] (m
     * below 2^32 / A by at most 1): floor(rd_i m / 2^16) as frac16 forms it */
    const uint32_t mh = m >> 16, ml = m & 0xFFFFu;
    const int32_t e1 = (int32_t)(((uint32_t)rd1 * mh + (((uint32_t)rd1 * ml) >> 16)) >> 1),
                  e2 = (int32_t)(((uint32_t)rd2 * mh + (((uint32_t)rd2 * ml) >> 16)) >> 1), sA = (int32_t)A;
    int32_t qx = qd1 * a[1] + qd2 * a[2] + rdiv_est(rd1 * a[1] + rd2 * a[2], e1, a[1], e2, a[2], sA, &rx);
    int32_t qy = qd1 * b[1] + qd2 * b[2] + rdiv_est(rd1 * b[1] + rd2 * b[2], e1, b[1], e2, b[2], sA, &ry);
    uint32_t qz = (uint32_t)qd1 * (uint32_t)w1t + (uint32_t)qd2 * (uint32_t)w2t +
                  (uint32_t)rdiv_est(rd1 * w1t + rd2 * w2t, e1, w1t, e2, w2t, sA, &rz);
    S->gxq = qx;
    S->gxf = frac16(rx, A, m);
    S->dz = (uint32_t)(qx + (qx < 0 && rx != 0));      /* toward zero */
    S->gyq = (uint32_t)qy;
    S->gyf = frac16(ry, A, m);
    /* from the box's top row to r0 (fewer than 2^14 rows) */
    uint32_t n = (uint32_t)(r0 - rtop), f = frac16(rz, A, m) + n * S->gyf;
    S->zhi = d0 + qz + n * S->gyq + (f >> 16);
    S->zfrac = f & 0xFFFFu;
    S->zrow = S->gy16 = 0;   /* (unread where z32) */
    S->z32 = 1;
    return 1;
}

static int fast_depth(const struct ras_sv *v0, const struct ras_sv *v1, const struct ras_sv *v2,
                      int32_t area, int32_t rtop, struct fstate *S)
{
    const int32_t *wr = S->wr, *a = S->a, *b = S->b;
    const int32_t r0 = S->row;
    struct adiv A = { (uint32_t)area, 0 };
    int64_t dd1 = (int64_t)v1->depth - v0->depth, dd2 = (int64_t)v2->depth - v0->depth, rem, f;
    /* edge values at (c0, the box's top row): linear in the row (within a
     * pixel of the box, so below 2^30 in magnitude) */
    int32_t w1t = wr[1] - (r0 - rtop) * b[1], w2t = wr[2] - (r0 - rtop) * b[2];
    int64_t q = adiv_floor(&A, mul_dw(dd1, w1t) + mul_dw(dd2, w2t), &rem);
    int64_t zrow = ((int64_t)v0->depth + q) * 65536 + adiv_floor(&A, rem << 16, &f);
    q = adiv_floor(&A, mul_dw(dd1, a[1]) + mul_dw(dd2, a[2]), &rem);
    if (q > INT32_MAX || q < -INT32_MAX) return -1;
    S->gxq = (int32_t)q;
    S->gxf = (uint32_t)adiv_floor(&A, rem << 16, &f);
    S->dz = (uint32_t)(int32_t)(q + (q < 0 && rem != 0));      /* toward zero */
    q = adiv_floor(&A, mul_dw(dd1, b[1]) + mul_dw(dd2, b[2]), &rem);
    if (q > INT32_MAX || q < -INT32_MAX) return -1;
    S->gy16 = q * 65536 + adiv_floor(&A, rem << 16, &f);
    S->zrow = zrow + S->gy16 * (r0 - rtop);
    depth_words(S, v0->depth, v1->depth, v2->depth);
    return 1;
}

/* The perspective weights' normalisation of a triangle of this area with
 * these corners (struct fpersp's t, area_t, dn, u). */
static void persp_weights(struct fpersp *pp, const struct ras_sv *const vv[3], int32_t area)
{
    const int tt = shift_below((uint32_t)area, 15);
    pp->t = tt;
    pp->area_t = (uint32_t)(area >> tt);
    uint32_t dmax = vv[0]->depth;
    if (vv[1]->depth > dmax) dmax = vv[1]->depth;
    if (vv[2]->depth > dmax) dmax = vv[2]->depth;
    const int s = shift_below(dmax, 16);
    for (int i = 0; i < 3; i++) pp->dn[i] = vv[i]->depth >> s;
    uint32_t dnmax = pp->dn[0] > pp->dn[1] ? pp->dn[0] : pp->dn[1];
    if (pp->dn[2] > dnmax) dnmax = pp->dn[2];
    uint32_t smax = pp->area_t * dnmax;  /* < 2^31 */
    pp->u = shift_below(smax, 15);
}

/* Fast Phong's attributes: normal (Q14) and camera-space position (Q(pq)). */
static int attrs_phong(struct fpersp *pp, int *na, const struct ras_sv *const vv[3], const struct ras_fast_tri *ft)
{
    for (int c = 0; c < 6; c++) {
        int slot = c < 3 ? ft->ai_n + c : ft->ai_p + c - 3;
        int32_t sc = c < 3 ? 1 << 14 : (int32_t)1 << ft->fp->pq, x[3];
        for (int i = 0; i < 3; i++) x[i] = ras_num_to_fix(vv[i]->a[slot], sc);
        if (!persp_attr(pp, (*na)++, x[0], x[1], x[2])) return 0;
    }
    return 1;
}

/* Texture coordinates in 16.16 texels. */
static int attrs_uv(struct fpersp *pp, int *na, const struct ras_sv *const vv[3], const struct ras_fast_tri *ft)
{
    int32_t u[3], v[3];
#if NUM_MODE == NUM_MODE_FIXED
    const int ku = scale_pow2_k(ft->uscale), kv = scale_pow2_k(ft->vscale);
    if (ku >= 0 && kv >= 0)
        for (int i = 0; i < 3; i++) {
            u[i] = fix_scale_k(vv[i]->a[ft->ai_uv], ft->uscale, ku);
            v[i] = fix_scale_k(vv[i]->a[ft->ai_uv + 1], ft->vscale, kv);
        }
    else
#endif
        for (int i = 0; i < 3; i++) {
            u[i] = fast_to_fix(vv[i]->a[ft->ai_uv], ft->uscale, 0);
            v[i] = fast_to_fix(vv[i]->a[ft->ai_uv + 1], ft->vscale, 0);
        }
    return persp_attr(pp, (*na)++, u[0], u[1], u[2]) && persp_attr(pp, (*na)++, v[0], v[1], v[2]);
}

/* Gouraud's attributes: the channels' levels when none can reach its top
 * level + 1/2 (colour Q10 x intensity Q12, a margin of 2^-6 level), else
 * (and always for textures) the intensity with a clamp per pixel, *shade
 * then SPAN_SHADE_LI. */
static int attrs_gouraud(struct fpersp *pp, int *na, const struct ras_sv *const vv[3], const struct ras_fast_tri *ft,
                         int *shade)
{
    int32_t li[3], imax = 0;
    for (int i = 0; i < 3; i++) {
        int32_t x = fast_to_fix(vv[i]->a[ft->ai_i], 1 << 20, 20);
        li[i] = x < 0 ? 0 : (x > (8 << 20) - 1 ? (8 << 20) - 1 : x);
        if (li[i] > imax) imax = li[i];
    }
    if (*shade == SPAN_SHADE_RGB) {
        uint32_t i12 = (uint32_t)(imax >> 8) + 1;
        if (ft->kr * i12 < (31u << 22) + (1u << 21) - (1u << 16) &&
            ft->kg * i12 < (63u << 22) + (1u << 21) - (1u << 16) &&
            ft->kb * i12 < (31u << 22) + (1u << 21) - (1u << 16)) {
            const uint32_t i0 = (uint32_t)li[0] >> 8, i1 = (uint32_t)li[1] >> 8, i2 = (uint32_t)li[2] >> 8;
            /* level in Q16 + 1/2: Q10 x Q12 >> 6 */
#define RAS_LEVEL(k, i) ((int32_t)(((k) * (i) + (1u << 5)) >> 6) + (1 << 15))
            const int j = *na;
            *na = j + 3;
            return persp_attr(pp, j, RAS_LEVEL(ft->kr, i0), RAS_LEVEL(ft->kr, i1), RAS_LEVEL(ft->kr, i2)) &&
                   persp_attr(pp, j + 1, RAS_LEVEL(ft->kg, i0), RAS_LEVEL(ft->kg, i1), RAS_LEVEL(ft->kg, i2)) &&
                   persp_attr(pp, j + 2, RAS_LEVEL(ft->kb, i0), RAS_LEVEL(ft->kb, i1), RAS_LEVEL(ft->kb, i2));
#undef RAS_LEVEL
        }
        *shade = SPAN_SHADE_LI;
    }
    return persp_attr(pp, (*na)++, li[0], li[1], li[2]);
}

/* The perspective weights and the attributes of a shaded or textured
 * triangle (out of line: a flat triangle's set-up carries none of it).
 * Returns 1, or -1 when an attribute does not fit the span formats. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static int fast_attrs_persp(struct fpersp *pp, const struct ras_sv *const vv[3], const struct ras_fast_tri *ft,
                            int32_t area, int *shade)
{
    int na = 0;
    persp_weights(pp, vv, area);
    if (*shade == SPAN_SHADE_PHONG && !attrs_phong(pp, &na, vv, ft)) return -1;
    if (ft->src != SPAN_SRC_CONST && !attrs_uv(pp, &na, vv, ft)) return -1;
    if ((*shade == SPAN_SHADE_RGB || *shade == SPAN_SHADE_LI) && !attrs_gouraud(pp, &na, vv, ft, shade)) return -1;
    pp->na = na;
    return 1;
}

/* The triangle's description (the caller's ft, copied into S only when
 * the set-up is kept: ras_fast_fill) and its span constants, the
 * attributes in raster_fast.h's order. Returns 1, or -1 when an attribute
 * does not fit the span formats. */
static int fast_attrs(const struct ras_ctx *rc, const struct ras_sv *const vv[3], const struct ras_fast_tri *ft,
                      int32_t area, struct fstate *S)
{
    struct ftri *Tp = &S->T;
    struct fpersp *pp = &Tp->pp;
    int shade = ft->shade;
    Tp->ft = ft;
    pp->na = 0;
    S->src = ft->src;
    S->shade = shade;
    /* (a flat colour's span loops read the description only) */
    if (shade == SPAN_SHADE_NONE && ft->src == SPAN_SRC_CONST) return 1;
    Tp->slog = rc->fast.persp_log2;
    Tp->seg = (int32_t)1 << Tp->slog;
    Tp->a1 = S->a[1];
    Tp->a2 = S->a[2];
    Tp->sa1 = S->a[1] * Tp->seg;
    Tp->sa2 = S->a[2] * Tp->seg;
    if (fast_attrs_persp(pp, vv, ft, area, &shade) < 0) return -1;
    S->shade = shade;
    return 1;
}

#if defined(__ARM_ARCH_6M__) && defined(__GNUC__)
/* ARMv6-M: fast_covers' walk by hand. e points at S->wr, followed by a[3],
 * b[3] and wb[3] (words 3 to 11); kmax the box's last column less c0, rows
 * (> 0) the rows to walk. Returns the first row (from 0) holding a covered
 * pixel, its edge values with their bias left in wb, or rows when none
 * does. Registers: r0-r2 the row's edge values, r3 the columns left, r4-r6
 * the pixel's, r7 scratch; r8-r10 a0..a2, r11 kmax, r12 the row, lr e. */
typedef char fstate_edges_layout[offsetof(struct fstate, a) == offsetof(struct fstate, wr) + 12 &&
                                         offsetof(struct fstate, b) == offsetof(struct fstate, wr) + 24 &&
                                         offsetof(struct fstate, wb) == offsetof(struct fstate, wr) + 36
                                     ? 1
                                     : -1];
static uint32_t covers_v6m(int32_t *e, uint32_t kmax, uint32_t rows)
{
    register int32_t *r0 __asm__("r0") = e;
    register uint32_t r1 __asm__("r1") = kmax, r2 __asm__("r2") = rows;
    __asm__ volatile(
        ".syntax unified\n\t"
        "mov lr, r0\n\t mov r11, r1\n\t mov r7, r2\n\t"
        "ldr r6, [r0, #12]\n\t mov r8, r6\n\t ldr r6, [r0, #16]\n\t mov r9, r6\n\t"
        "ldr r6, [r0, #20]\n\t mov r10, r6\n\t"
        "ldr r1, [r0, #40]\n\t ldr r2, [r0, #44]\n\t ldr r0, [r0, #36]\n\t"
        "movs r3, #0\n\t mov r12, r3\n\t push {r7}\n"
        "1:\n\t movs r4, r0\n\t movs r5, r1\n\t movs r6, r2\n\t mov r3, r11\n"
        "2:\n\t movs r7, r4\n\t orrs r7, r5\n\t orrs r7, r6\n\t bpl 3f\n\t"
        "add r4, r8\n\t add r5, r9\n\t add r6, r10\n\t subs r3, #1\n\t bpl 2b\n\t"
        "mov r7, lr\n\t ldr r3, [r7, #24]\n\t adds r0, r0, r3\n\t ldr r3, [r7, #28]\n\t adds r1, r1, r3\n\t"
        "ldr r3, [r7, #32]\n\t adds r2, r2, r3\n\t"
        "mov r7, r12\n\t adds r7, #1\n\t mov r12, r7\n\t ldr r3, [sp]\n\t cmp r7, r3\n\t blo 1b\n\t"
        "b 4f\n"
        "3:\n\t mov r7, lr\n\t str r0, [r7, #36]\n\t str r1, [r7, #40]\n\t str r2, [r7, #44]\n"
        "4:\n\t add sp, #4\n\t mov r0, r12\n\t"
        ".syntax divided\n"
        : "+l"(r0), "+l"(r1), "+l"(r2)
        :
        : "r3", "r4", "r5", "r6", "r7", "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");
    return (uint32_t)(uintptr_t)r0;
}
#endif

/* Whether a scanned box's rows in this strip hold a covered pixel: its
 * edge values stepped across them as fast_rows' scan does. S is moved on
 * to the first row that does (the rows above it cover nothing: neither
 * scan need walk them, and the depth plane is set up at that row). */
static int fast_covers(const struct ras_ctx *rc, struct fstate *S)
{
    const int32_t r1 = S->last < (int32_t)rc->cur.t->y1 - 1 ? S->last : (int32_t)rc->cur.t->y1 - 1;
#if defined(__ARM_ARCH_6M__) && defined(__GNUC__)
    if (r1 < S->row) return 0;
    const uint32_t rows = (uint32_t)(r1 - S->row + 1), n = covers_v6m(S->wr, (uint32_t)S->kmax, rows);
    if (n >= rows) return 0;
    if (n) {
        S->wr[0] += (int32_t)n * S->b[0];
        S->wr[1] += (int32_t)n * S->b[1];
        S->wr[2] += (int32_t)n * S->b[2];
        S->row += (int32_t)n;
    }
    return 1;
#else
    const int32_t a0 = S->a[0], a1 = S->a[1], a2 = S->a[2], kmax = S->kmax;
    const int32_t b0 = S->b[0], b1 = S->b[1], b2 = S->b[2];
    int32_t w0 = S->wb[0], w1 = S->wb[1], w2 = S->wb[2];
    for (int32_t r = S->row; r <= r1; r++) {
        int32_t e0 = w0, e1 = w1, e2 = w2;
        for (int32_t k = 0; k <= kmax; k++) {
            if (!(((uint32_t)e0 | (uint32_t)e1 | (uint32_t)e2) >> 31)) {
                const int32_t n = r - S->row;
                if (n) {
                    S->wb[0] = w0;
                    S->wb[1] = w1;
                    S->wb[2] = w2;
                    S->wr[0] += n * b0;
                    S->wr[1] += n * b1;
                    S->wr[2] += n * b2;
                    S->row = r;
                }
                return 1;
            }
            e0 += a0;
            e1 += a1;
            e2 += a2;
        }
        w0 += b0;
        w1 += b1;
        w2 += b2;
    }
    return 0;
#endif
}

/* Set-up of triangle v0 v1 v2 for rows from the strip's first on (lazy:
 * none where a scanned box covers no pixel in this strip, for a set-up not
 * kept). Returns 1, 0 (nothing to draw) or -1 (the exact path's triangle). */
static int fast_setup(const struct ras_ctx *rc, const struct ras_sv *v0, const struct ras_sv *v1,
                      const struct ras_sv *v2, const struct ras_fast_tri *ft, struct fstate *S, int lazy)
{
    int32_t box[4];
    /* (ras_sub_box's box) */
    box[0] = v0->x < v1->x ? v0->x : v1->x;
    box[2] = v0->x < v1->x ? v1->x : v0->x;
    box[1] = v0->y < v1->y ? v0->y : v1->y;
    box[3] = v0->y < v1->y ? v1->y : v0->y;
    if (v2->x < box[0]) box[0] = v2->x;
    if (v2->x > box[2]) box[2] = v2->x;
    if (v2->y < box[1]) box[1] = v2->y;
    if (v2->y > box[3]) box[3] = v2->y;
    /* (the box's sides as unsigned differences: box[2] >= box[0], box[3] >= box[1]) */
    if ((uint32_t)box[2] - (uint32_t)box[0] > (1u << 14) || (uint32_t)box[3] - (uint32_t)box[1] > (1u << 14))
        return ras_edge(v0->x, v0->y, v1->x, v1->y, v2->x, v2->y) <= 0 ? 0 : -1;
    /* twice the area: differences of at most 2^14, products below 2^28 */
    const int32_t area = (v1->x - v0->x) * (v2->y - v0->y) - (v1->y - v0->y) * (v2->x - v0->x);
    if (area <= 0) return 0;
    int32_t rtop;
    int r = fast_edges(rc, box, v0, v1, v2, area, S, &rtop);
    if (r <= 0 || (lazy && S->scan && !fast_covers(rc, S))) return 0;
    S->depth = rc->depth_bytes != 0;
    if (!S->depth) {
        S->zrow = S->gy16 = 0;
        S->gxq = 0;
        S->gxf = S->dz = 0;
        S->z32 = 0;
        S->zhi = S->zfrac = S->gyq = S->gyf = 0;
    } else if (!depth_small(v0, v1, v2, area, rtop, S) && fast_depth(v0, v1, v2, area, rtop, S) < 0)
        return -1;       /* (each sets every depth field) */
    const struct ras_sv *const vv[3] = { v0, v1, v2 };
    return fast_attrs(rc, vv, ft, area, S);
}
/* fast_rows is compiled once for each way of bounding the rows (scan a
 * constant there), so the division's rows pay nothing for the other way. */
#if defined(__GNUC__) || defined(__clang__)
#define RAS_ALWAYS_INLINE static inline __attribute__((always_inline))
#else
#define RAS_ALWAYS_INLINE static inline
#endif

/* Rows of S from S->row to the strip's end (or the triangle's last row),
 * S left at the next row; scan is S->scan. Returns the pixels written
 * (host outputs) or drawn (board). */
RAS_ALWAYS_INLINE uint32_t fast_rows(const struct ras_ctx *rc, struct fstate *S, const int scan)
{
    const struct render_target *t = rc->cur.t;
    const struct ftri *Tp = &S->T;
    struct fedge *fe = S->fe;
    int32_t *wr = S->wr, *a = S->a, *b = S->b;
    int64_t zrow = S->zrow;
    const int64_t gy16 = S->gy16;
    const int32_t gxq = S->gxq, c0 = S->c0, kmax = S->kmax;
    const uint32_t gxf = S->gxf, dz = S->dz;
    const int depth = S->depth, z32 = S->z32;
    uint32_t zhi = S->zhi, zfrac = S->zfrac;
    const uint32_t gyq = S->gyq, gyf = S->gyf;
    int32_t r0 = S->row, r1 = S->last < (int32_t)t->y1 - 1 ? S->last : (int32_t)t->y1 - 1;
    const int di = rc->depth_bytes == 0 ? 0 : (rc->depth_bytes == 2 ? 1 : 2);
#if RENDER_HOST_OUTPUTS
    const int extra = t->rgb888 != NULL || t->written != NULL;
    span_fn fn = (extra ? ras_span_host : ras_span_board)[S->shade][S->src][di];
#else
    const int extra = 0;         /* (render_strip refuses host outputs here) */
    span_fn fn = ras_span_board[S->shade][S->src][di];
#endif
    struct frow R;
    R.z = 0;
    R.dz = dz;
    R.rgb888 = R.written = NULL;
    R.w1 = R.w2 = 0;
    uint32_t total = 0;
    const int attrs = S->shade != SPAN_SHADE_NONE || S->src != SPAN_SRC_CONST;
    /* the box's first pixel in the row, stepped by the row length */
    const size_t w = rc->w;
    size_t idx0 = (size_t)(r0 - t->y0) * w + (size_t)c0;
    /* (scan) the edge values with their bias, held across the rows */
    int32_t wb0 = S->wb[0], wb1 = S->wb[1], wb2 = S->wb[2];
    int32_t wr1 = wr[1], wr2 = wr[2];

    for (int32_t r = r0; r <= r1; r++, idx0 += w) {
        int32_t lo = 0, hi = kmax;
        int empty = 0;
        if (scan) {
            /* the covered columns: every edge value (bias included) >= 0 */
            int32_t e0 = wb0, e1 = wb1, e2 = wb2, k = 0;
            while (k <= kmax && ((uint32_t)e0 | (uint32_t)e1 | (uint32_t)e2) >> 31) {
                e0 += a[0];
                e1 += a[1];
                e2 += a[2];
                k++;
            }
            lo = k;
            while (k <= kmax && !(((uint32_t)e0 | (uint32_t)e1 | (uint32_t)e2) >> 31)) {
                e0 += a[0];
                e1 += a[1];
                e2 += a[2];
                k++;
            }
            hi = k - 1;
        } else
            for (int i = 0; i < 3; i++) {
                if (fe[i].kind > 0) { if (fe[i].q > lo) lo = fe[i].q; }
                else if (fe[i].kind < 0) { if (fe[i].q < hi) hi = fe[i].q; }
                else if (fe[i].n < 0) empty = 1;
            }
        if (!empty && lo <= hi) {
            size_t idx = idx0 + (size_t)lo;
            R.n = hi - lo + 1;
            R.px = t->rgb565 + idx;
            R.zb = rc->depth + idx * rc->depth_bytes;
            if (extra) {
                R.rgb888 = t->rgb888 ? t->rgb888 + 3 * idx : NULL;
                R.written = t->written ? t->written + idx : NULL;
            }
            if (z32) {
                /* the plane's integer part at column lo, modulo 2^32
                 * (depth_words: the value itself) */
                R.z = zhi + (uint32_t)lo * (uint32_t)gxq + ((zfrac + (uint32_t)lo * gxf) >> 16);
            } else if (depth) {
                /* lo * gx16 as two 32-bit products (lo < 2^14, gxf < 2^16) */
                int64_t zs = (zrow + num_smul32(lo, gxq) * 65536 + (int64_t)((uint32_t)lo * gxf)) >> 16;
                int64_t ze = zs + num_smul32(R.n - 1, (int32_t)dz);
                if (zs < 1 || zs > (int64_t)UINT32_MAX - 1 || ze < 1 || ze > (int64_t)UINT32_MAX - 1) {
                    /* at the near plane or infinity: this row's depth held flat */
                    R.z = zs < 0 ? 0 : (zs > (int64_t)UINT32_MAX ? UINT32_MAX : (uint32_t)zs);
                    R.dz = 0;
                } else {
                    R.z = (uint32_t)zs;
                    R.dz = dz;
                }
            }
            if (attrs) {
                R.w1 = wr1 + lo * a[1];
                R.w2 = wr2 + lo * a[2];
            }
            uint32_t wrote = fn(Tp, &R);
            total += extra ? wrote : (uint32_t)R.n;
        }
        if (z32) {
            zfrac += gyf;
            zhi += gyq + (zfrac >> 16);
            zfrac &= 0xFFFFu;
        } else
            zrow += gy16;
        wr1 += b[1];
        wr2 += b[2];
        if (scan) {
            wb0 += b[0];
            wb1 += b[1];
            wb2 += b[2];
            continue;
        }
        wr[0] += b[0];
        for (int i = 0; i < 3; i++) {
            struct fedge *e = &fe[i];
            if (e->kind == 0) { e->n += e->dq; continue; }
            e->q += e->dq;
            e->r += e->dr;
            if (e->r >= e->den) { e->q++; e->r -= e->den; }
        }
    }
    wr[1] = wr1;
    wr[2] = wr2;
    if (scan) {
        /* (wr[0] is read only through wb[0]) */
        S->wb[0] = wb0;
        S->wb[1] = wb1;
        S->wb[2] = wb2;
    }
    S->zrow = zrow;
    S->zhi = zhi;
    S->zfrac = zfrac;
    S->row = r1 + 1;
    return total;
}

#if defined(__ARM_ARCH_6M__) && defined(__GNUC__)
#define RAS_SCAN_FLAT_V6M 1
/* ARMv6-M: fast_rows by hand for the rows most small triangles take (the
 * box scanned, one colour, 16-bit depth entries in the plane's 32-bit form,
 * the board's outputs only): each row's span found and drawn in one loop,
 * with the C loops' operations, so the same bits. fast_scan_flat's block
 * (its words at these offsets; in/out where it writes them back):
 *   0, 4, 8    wb0..wb2  (in/out) the edge values with their bias at the
 *                        row's box column c0
 *   12, 16, 20 b0..b2    their steps per row
 *   24         prow      (in/out) the row's pixel at column c0
 *   28         kmax2     2 kmax, the box's last column's byte offset
 *   32         stride    a row of pixels in bytes
 *   36         zoff      the depth entry's byte offset from its pixel
 *                        (modulo 2^32)
 *   40, 44     zq, zf    (in/out) the plane at (c0, the row): zhi + zf's
 *                        carry and zfrac as a sum of fractions, zf = zfrac0 +
 *                        (rows drawn) gyf, below 2^32 (at most 80 rows), zq =
 *                        zhi0 + (rows drawn) gyq modulo 2^32 (the plane at
 *                        column lo is zq + lo gxq + ((zf + lo gxf) >> 16),
 *                        fast_rows' value: the carries the same)
 *   48, 52     gxq, gxf  its column gradient, 56, 60 gyq, gyf its row one
 *   64         rows      (> 0) rows to draw, 0 on return
 *   68         total     (in/out) pixels of the spans (R.n summed)
 *   72         (the span's first pixel)
 *   76..84     a0..a2    the edge values' steps per column
 *   88         dz        the depth's step per column
 *   92         col       the colour, RGB565
 * Registers in the loops: r0-r2 the edge values, r3 the pixel, r4 z, r5,
 * r6 scratch, r7 the block (between rows) or zoff (in a span); r8-r10 a0..a2,
 * r11 the row's last pixel of the box, r12 dz, lr col; the block's address
 * on the stack. */
struct fscan {
    int32_t wb[3], b[3];
    uint16_t *prow;
    uint32_t kmax2, stride, zoff, zhi, zfrac, gxq, gxf, gyq, gyf, rows, total;
    uint16_t *plo;
    int32_t a[3];
    uint32_t dz, col;
    uint16_t *spans;   /* (fast_scan_spans) */
};
typedef char fscan_layout[offsetof(struct fscan, prow) == 24 && offsetof(struct fscan, zhi) == 40 &&
                                  offsetof(struct fscan, rows) == 64 && offsetof(struct fscan, a) == 76 &&
                                  offsetof(struct fscan, col) == 92 && offsetof(struct fscan, spans) == 96
                              ? 1
                              : -1];

RAS_HOT __attribute__((noinline)) static void fast_scan_flat(struct fscan *P)
{
    register struct fscan *r0 __asm__("r0") = P;
    __asm__ volatile(
        ".syntax unified\n\t"
        "push {r0}\n\t mov r7, r0\n\t"
        "ldr r6, [r7, #76]\n\t mov r8, r6\n\t ldr r6, [r7, #80]\n\t mov r9, r6\n\t"
        "ldr r6, [r7, #84]\n\t mov r10, r6\n\t ldr r6, [r7, #88]\n\t mov r12, r6\n\t"
        "ldr r6, [r7, #92]\n\t mov lr, r6\n\t"
        "ldr r0, [r7, #0]\n\t ldr r1, [r7, #4]\n\t ldr r2, [r7, #8]\n\t ldr r3, [r7, #24]\n"
        /* a row: r11 its last pixel, then the first covered column */
        "1:\n\t ldr r6, [r7, #28]\n\t adds r6, r6, r3\n\t mov r11, r6\n"
        "2:\n\t movs r6, r0\n\t orrs r6, r1\n\t orrs r6, r2\n\t bpl 3f\n\t"
        "add r0, r8\n\t add r1, r9\n\t add r2, r10\n\t adds r3, #2\n\t cmp r3, r11\n\t bls 2b\n\t"
        "b 6f\n"
        /* z = zq + lo gxq + ((zf + lo gxf) >> 16), lo the column */
        "3:\n\t ldr r6, [r7, #24]\n\t subs r6, r3, r6\n\t lsrs r6, r6, #1\n\t str r3, [r7, #72]\n\t"
        "ldr r4, [r7, #52]\n\t muls r4, r6, r4\n\t ldr r5, [r7, #44]\n\t adds r4, r4, r5\n\t lsrs r4, r4, #16\n\t"
        "ldr r5, [r7, #48]\n\t muls r5, r6, r5\n\t adds r4, r4, r5\n\t ldr r5, [r7, #40]\n\t adds r4, r4, r5\n\t"
        "ldr r7, [r7, #36]\n"
        /* the span: depth test, pixel, next column while every edge value >= 0 */
        "4:\n\t lsrs r5, r4, #16\n\t ldrh r6, [r3, r7]\n\t cmp r5, r6\n\t bls 5f\n\t"
        "strh r5, [r3, r7]\n\t mov r6, lr\n\t strh r6, [r3]\n"
        "5:\n\t add r4, r12\n\t adds r3, #2\n\t cmp r3, r11\n\t bhi 7f\n\t"
        "add r0, r8\n\t add r1, r9\n\t add r2, r10\n\t"
        "movs r6, r0\n\t orrs r6, r1\n\t orrs r6, r2\n\t bpl 4b\n"
        "7:\n\t ldr r7, [sp]\n\t ldr r5, [r7, #72]\n\t subs r5, r3, r5\n\t lsrs r5, r5, #1\n\t"
        "ldr r6, [r7, #68]\n\t adds r6, r6, r5\n\t str r6, [r7, #68]\n"
        /* the next row: zf, zq, the edge values (b0..b2 loaded with them), the pixel */
        "6:\n\t ldr r4, [r7, #44]\n\t ldr r5, [r7, #60]\n\t adds r4, r4, r5\n\t str r4, [r7, #44]\n\t"
        "ldr r4, [r7, #40]\n\t ldr r5, [r7, #56]\n\t adds r4, r4, r5\n\t str r4, [r7, #40]\n\t"
        "ldm r7!, {r0, r1, r2, r3, r4, r6}\n\t adds r0, r0, r3\n\t adds r1, r1, r4\n\t adds r2, r2, r6\n\t"
        "subs r7, #24\n\t stm r7!, {r0, r1, r2}\n\t subs r7, #12\n\t"
        "ldr r3, [r7, #24]\n\t ldr r4, [r7, #32]\n\t adds r3, r3, r4\n\t str r3, [r7, #24]\n\t"
        "ldr r4, [r7, #64]\n\t subs r4, #1\n\t str r4, [r7, #64]\n\t bne 1b\n\t"
        "add sp, #4\n\t"
        ".syntax divided\n"
        : "+l"(r0)
        :
        : "r1", "r2", "r3", "r4", "r5", "r6", "r7", "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");
}

/* ARMv6-M: the spans of the same rows (fast_scan_flat's block, its
 * offsets 0 to 32, 64, 76 to 84 and at 96 the spans' array, a halfword a
 * row: lo | n << 8, 0 where the row has none; lo <= 158 and n <= 159, a
 * scanned box being at most 160 columns wide), for the other span loops:
 * the columns fast_rows' scan finds, with its operations. Registers: r0-r2
 * the edge values, r3 the pixel, r4 the row's first one then lo, r5 the
 * next span, r6 scratch, r7 the block; r8-r10 a0..a2, r11 the row's last
 * pixel of the box. */
RAS_HOT __attribute__((noinline)) static void fast_scan_spans(struct fscan *P)
{
    register struct fscan *r0 __asm__("r0") = P;
    __asm__ volatile(
        ".syntax unified\n\t"
        "mov r7, r0\n\t"
        "ldr r6, [r7, #76]\n\t mov r8, r6\n\t ldr r6, [r7, #80]\n\t mov r9, r6\n\t"
        "ldr r6, [r7, #84]\n\t mov r10, r6\n\t ldr r5, [r7, #96]\n\t"
        "ldr r0, [r7, #0]\n\t ldr r1, [r7, #4]\n\t ldr r2, [r7, #8]\n\t ldr r3, [r7, #24]\n"
        "1:\n\t ldr r6, [r7, #28]\n\t adds r6, r6, r3\n\t mov r11, r6\n\t mov r4, r3\n"
        "2:\n\t movs r6, r0\n\t orrs r6, r1\n\t orrs r6, r2\n\t bpl 3f\n\t"
        "add r0, r8\n\t add r1, r9\n\t add r2, r10\n\t adds r3, #2\n\t cmp r3, r11\n\t bls 2b\n\t"
        "movs r6, #0\n\t b 5f\n"
        "3:\n\t subs r4, r3, r4\n\t lsrs r4, r4, #1\n"
        "4:\n\t adds r3, #2\n\t cmp r3, r11\n\t bhi 6f\n\t add r0, r8\n\t add r1, r9\n\t add r2, r10\n\t"
        "movs r6, r0\n\t orrs r6, r1\n\t orrs r6, r2\n\t bpl 4b\n"
        "6:\n\t ldr r6, [r7, #24]\n\t subs r6, r3, r6\n\t lsrs r6, r6, #1\n\t subs r6, r6, r4\n\t"
        "lsls r6, r6, #8\n\t orrs r6, r4\n"
        "5:\n\t strh r6, [r5]\n\t adds r5, #2\n\t"
        "ldm r7!, {r0, r1, r2, r3, r4, r6}\n\t adds r0, r0, r3\n\t adds r1, r1, r4\n\t adds r2, r2, r6\n\t"
        "subs r7, #24\n\t stm r7!, {r0, r1, r2}\n\t subs r7, #12\n\t"
        "ldr r3, [r7, #24]\n\t ldr r4, [r7, #32]\n\t adds r3, r3, r4\n\t str r3, [r7, #24]\n\t"
        "ldr r4, [r7, #64]\n\t subs r4, #1\n\t str r4, [r7, #64]\n\t bne 1b\n\t"
        ".syntax divided\n"
        : "+l"(r0)
        :
        : "r1", "r2", "r3", "r4", "r5", "r6", "r7", "r8", "r9", "r10", "r11", "cc", "memory");
}

#if FW_FEATURE_SPAN_RGB_CONST || FW_FEATURE_SPAN_LI_TEX
/* ARMv6-M: the rows of a scanned triangle with 16-bit depth entries (a
 * span loop's operations row after row in one loop, fast_scan_spans'
 * spans in the array: the same bits), without a call a span: Gouraud
 * levels (fast_rgb_rows) and a nearest texture lit by Gouraud intensity
 * (fast_tex_rows). A span longer than a segment hands back to the caller
 * (the spans pointer at its row). Their block (in/out where written back):
 *   0, 4       sp, spe   (in/out) the next row's span (lo | n << 8, 0: none)
 *                        and the end of the array
 *   8, 12      zq, zf    (in/out) the plane at (c0, the row), as
 *                        fast_run_spans' zq, zf
 *   16, 20     w1, w2    (in/out) the edge values 1, 2 at (c0, the row)
 *   24         prow      (in/out) the row's pixel at column c0
 *   28, 32     gyq, gyf  the plane's steps per row, 36, 40 b1, b2 the edge
 *                        values', 44 the row in bytes
 *   48, 52     gxq, gxf  the plane's column gradient, 56, 60 a1, a2 the
 *                        edge values' steps per column
 *   64         dz        the depth's step per column
 *   68         zoff      the depth entry's byte offset from its pixel
 *   72         pp        the triangle's perspective constants
 *   76         seg       the segment's length
 *   80         total     (in/out) pixels of the spans
 *   84         rcp       rcp_tab's address less 512 bytes
 *   88         inv       fast_inv_tab
 *   92..104    (scratch: the span's pixels left, its first point's levels)
 *   108        tex       (fast_tex_rows) the texels, RGB565
 *   112, 116   um, vm    the masks of a texel's byte offset across and down
 *   120        vs        the shift of v: the texture's width's log2 + 1
 * Registers: the block at [sp]; in a span r8 the pixel, r9 z, r10, r11 the
 * edge values. The point's subroutine (persp_at for three attributes)
 * takes r1, r2 the edge values and r7 the constants, gives the attributes
 * in r4-r6 and uses r0-r3. */
struct frows {
    const uint16_t *sp, *spe;
    uint32_t zq, zf;
    int32_t w1, w2;
    uint16_t *prow;
    uint32_t gyq, gyf;
    int32_t b1, b2;
    uint32_t stride, gxq, gxf;
    int32_t a1, a2;
    uint32_t dz, zoff;
    const struct fpersp *pp;
    int32_t seg;
    uint32_t total, rcp;
    const uint32_t *inv;
    int32_t scratch[4];
    const uint8_t *tex;
    uint32_t um, vm, vs;
};
typedef char frows_layout[offsetof(struct frows, prow) == 24 && offsetof(struct frows, stride) == 44 &&
                                  offsetof(struct frows, dz) == 64 && offsetof(struct frows, total) == 80 &&
                                  offsetof(struct frows, scratch) == 92 && offsetof(struct frows, tex) == 108 &&
                                  offsetof(struct frows, vs) == 120 && offsetof(struct fpersp, area_t) == 12 &&
                                  offsetof(struct fpersp, at) == 28 && sizeof(((struct fpersp *)0)->at[0]) == 16
                              ? 1
                              : -1];

/* (the pieces both row loops share: a row's span and its first pixel,
 * the next row, the point's subroutine) */
#define FROWS_SPAN \
        /* a row: its span, or the next row */ \
        "1:\n\t ldr r7, [sp]\n\t ldm r7!, {r0, r1}\n\t subs r7, #8\n\t cmp r0, r1\n\t bne 20f\n\t b 9f\n" \
        "20:\n\t ldrh r1, [r0]\n\t lsrs r2, r1, #8\n\t bne 24f\n\t b 8f\n" \
        "24:\n\t" \
        "ldr r3, [r7, #76]\n\t cmp r2, r3\n\t ble 21f\n\t b 9f\n" \
        "21:\n\t str r2, [r7, #92]\n\t ldr r3, [r7, #80]\n\t adds r3, r3, r2\n\t str r3, [r7, #80]\n\t" \
        "uxtb r1, r1\n\t" \
        /* the pixel, z = zq + lo gxq + ((zf + lo gxf) >> 16), the edge values */ \
        "ldr r3, [r7, #24]\n\t lsls r0, r1, #1\n\t adds r3, r3, r0\n\t mov r8, r3\n\t" \
        "ldr r4, [r7, #52]\n\t muls r4, r1, r4\n\t ldr r5, [r7, #12]\n\t adds r4, r4, r5\n\t lsrs r4, r4, #16\n\t" \
        "ldr r5, [r7, #48]\n\t muls r5, r1, r5\n\t adds r4, r4, r5\n\t ldr r5, [r7, #8]\n\t adds r4, r4, r5\n\t mov r9, r4\n\t" \
        "ldr r5, [r7, #56]\n\t muls r5, r1, r5\n\t ldr r6, [r7, #16]\n\t adds r5, r5, r6\n\t mov r10, r5\n\t" \
        "ldr r6, [r7, #60]\n\t muls r6, r1, r6\n\t ldr r0, [r7, #20]\n\t adds r6, r6, r0\n\t mov r11, r6\n\t" \
        "cmp r2, #2\n\t bgt 30f\n"
#define FROWS_NEXT_ROW \
        /* the next row: the plane, the edge values, the pixel */ \
        "8:\n\t ldr r7, [sp]\n\t ldr r0, [r7, #0]\n\t adds r0, #2\n\t str r0, [r7, #0]\n\t" \
        "adds r7, #8\n\t ldm r7!, {r0, r1, r2, r3, r4}\n\t ldm r7!, {r5, r6}\n\t adds r0, r0, r5\n\t adds r1, r1, r6\n\t" \
        "ldm r7!, {r5, r6}\n\t adds r2, r2, r5\n\t adds r3, r3, r6\n\t ldm r7!, {r5}\n\t adds r4, r4, r5\n\t" \
        "subs r7, #40\n\t stm r7!, {r0, r1, r2, r3, r4}\n\t b 1b\n"
#define FROWS_POINT3 \
        /* the point's levels: persp_at's operations */ \
        "50:\n\t ldr r0, [r7, #0]\n\t lsrs r1, r0\n\t lsrs r2, r0\n\t ldr r0, [r7, #12]\n\t subs r0, r0, r1\n\t subs r0, r0, r2\n\t" \
        "ldr r3, [r7, #16]\n\t muls r0, r3, r0\n\t ldr r3, [r7, #20]\n\t muls r1, r3, r1\n\t ldr r3, [r7, #24]\n\t muls r2, r3, r2\n\t" \
        "adds r0, r0, r1\n\t adds r0, r0, r2\n\t ldr r3, [r7, #4]\n\t lsrs r0, r3\n\t beq 53f\n\t lsrs r1, r3\n\t lsrs r2, r3\n\t" \
        "movs r3, #1\n\t lsls r3, r3, #14\n\t cmp r0, r3\n\t bhs 52f\n" \
        "51:\n\t lsls r0, r0, #1\n\t lsls r1, r1, #1\n\t lsls r2, r2, #1\n\t cmp r0, r3\n\t blo 51b\n" \
        /* rcp30 */ \
        "52:\n\t lsrs r3, r0, #6\n\t lsls r3, r3, #1\n\t ldr r4, [sp]\n\t ldr r4, [r4, #84]\n\t ldrh r3, [r4, r3]\n\t" \
        "movs r4, r3\n\t muls r4, r0, r4\n\t movs r5, #1\n\t lsls r5, r5, #30\n\t subs r5, r5, r4\n\t asrs r5, r5, #7\n\t" \
        "muls r5, r3, r5\n\t asrs r5, r5, #23\n\t adds r3, r3, r5\n\t" \
        "muls r1, r3, r1\n\t lsrs r1, r1, #14\n\t muls r2, r3, r2\n\t lsrs r2, r2, #14\n\t b 54f\n" \
        "53:\n\t movs r1, #0\n\t movs r2, #0\n" \
        /* the three levels */ \
        "54:\n\t ldr r4, [r7, #32]\n\t muls r4, r1, r4\n\t ldr r0, [r7, #36]\n\t muls r0, r2, r0\n\t adds r4, r4, r0\n\t" \
        "ldr r0, [r7, #40]\n\t asrs r4, r0\n\t ldr r0, [r7, #28]\n\t adds r4, r4, r0\n\t" \
        "ldr r5, [r7, #48]\n\t muls r5, r1, r5\n\t ldr r0, [r7, #52]\n\t muls r0, r2, r0\n\t adds r5, r5, r0\n\t" \
        "ldr r0, [r7, #56]\n\t asrs r5, r0\n\t ldr r0, [r7, #44]\n\t adds r5, r5, r0\n\t" \
        "ldr r6, [r7, #64]\n\t muls r6, r1, r6\n\t ldr r0, [r7, #68]\n\t muls r0, r2, r0\n\t adds r6, r6, r0\n\t" \
        "ldr r0, [r7, #72]\n\t asrs r6, r0\n\t ldr r0, [r7, #60]\n\t adds r6, r6, r0\n\t bx lr\n"
#endif

#if FW_FEATURE_SPAN_RGB_CONST
/* ARMv6-M: the Gouraud levels' rows (span_rgb_const_z2's operations). In a
 * span's loop r0 the pixel, r1-r3 the levels, r4 z, r5 zoff, r8 the span's
 * end, r9 dz, r10-r12 the levels' steps. */
RAS_HOT __attribute__((noinline)) static void fast_rgb_rows(struct frows *P)
{
    register struct frows *r0 __asm__("r0") = P;
    __asm__ volatile(
        ".syntax unified\n\t"
        "push {r0}\n"
        FROWS_SPAN
        /* one or two pixels: each one's depth test, then its levels at a point */
        "22:\n\t mov r0, r9\n\t lsrs r0, r0, #16\n\t mov r3, r8\n\t ldr r1, [r7, #68]\n\t ldrh r2, [r3, r1]\n\t"
        "cmp r0, r2\n\t bls 23f\n\t strh r0, [r3, r1]\n\t"
        "mov r1, r10\n\t mov r2, r11\n\t ldr r7, [r7, #72]\n\t bl 50f\n\t"
        "lsrs r4, r4, #16\n\t lsls r4, r4, #11\n\t lsrs r5, r5, #16\n\t lsls r5, r5, #5\n\t orrs r4, r5\n\t"
        "lsrs r6, r6, #16\n\t orrs r4, r6\n\t mov r3, r8\n\t strh r4, [r3]\n\t ldr r7, [sp]\n"
        "23:\n\t ldr r0, [r7, #92]\n\t subs r0, #1\n\t bne 25f\n\t b 8f\n"
        "25:\n\t str r0, [r7, #92]\n\t"
        "mov r3, r8\n\t adds r3, #2\n\t mov r8, r3\n\t"
        "ldr r1, [r7, #64]\n\t add r9, r1\n\t ldr r1, [r7, #56]\n\t add r10, r1\n\t ldr r1, [r7, #60]\n\t add r11, r1\n\t"
        "b 22b\n"
        /* three pixels or more (at most a segment): the first point's levels,
         * the last one's, the steps by span_mul_inv's products */
        "30:\n\t mov r1, r10\n\t mov r2, r11\n\t ldr r7, [r7, #72]\n\t bl 50f\n\t"
        "ldr r7, [sp]\n\t str r4, [r7, #96]\n\t str r5, [r7, #100]\n\t str r6, [r7, #104]\n\t"
        "ldr r0, [r7, #92]\n\t subs r0, #1\n\t"
        "ldr r1, [r7, #56]\n\t muls r1, r0, r1\n\t add r1, r10\n\t"
        "ldr r2, [r7, #60]\n\t muls r2, r0, r2\n\t add r2, r11\n\t"
        "ldr r7, [r7, #72]\n\t bl 50f\n\t"
        "ldr r7, [sp]\n\t ldr r0, [r7, #92]\n\t subs r0, #1\n\t lsls r0, r0, #2\n\t ldr r1, [r7, #88]\n\t ldr r0, [r1, r0]\n\t"
        "ldr r1, [r7, #96]\n\t subs r4, r4, r1\n\t asrs r2, r4, #16\n\t muls r2, r0, r2\n\t uxth r4, r4\n\t muls r4, r0, r4\n\t"
        "lsrs r4, r4, #16\n\t adds r4, r4, r2\n\t mov r10, r4\n\t"
        "ldr r1, [r7, #100]\n\t subs r5, r5, r1\n\t asrs r2, r5, #16\n\t muls r2, r0, r2\n\t uxth r5, r5\n\t muls r5, r0, r5\n\t"
        "lsrs r5, r5, #16\n\t adds r5, r5, r2\n\t mov r11, r5\n\t"
        "ldr r1, [r7, #104]\n\t subs r6, r6, r1\n\t asrs r2, r6, #16\n\t muls r2, r0, r2\n\t uxth r6, r6\n\t muls r6, r0, r6\n\t"
        "lsrs r6, r6, #16\n\t adds r6, r6, r2\n\t mov r12, r6\n\t"
        /* the pixels: raster_span.h's loop of the levels */
        "mov r0, r8\n\t ldr r6, [r7, #92]\n\t lsls r6, r6, #1\n\t adds r6, r0, r6\n\t mov r8, r6\n\t"
        "mov r4, r9\n\t ldr r6, [r7, #64]\n\t mov r9, r6\n\t"
        "ldr r1, [r7, #96]\n\t ldr r2, [r7, #100]\n\t ldr r3, [r7, #104]\n\t ldr r5, [r7, #68]\n"
        "31:\n\t lsrs r6, r4, #16\n\t ldrh r7, [r0, r5]\n\t cmp r6, r7\n\t bls 32f\n\t strh r6, [r0, r5]\n\t"
        "lsrs r6, r1, #16\n\t lsls r6, r6, #11\n\t lsrs r7, r2, #16\n\t lsls r7, r7, #5\n\t orrs r6, r7\n\t"
        "lsrs r7, r3, #16\n\t orrs r6, r7\n\t strh r6, [r0]\n"
        "32:\n\t adds r0, #2\n\t add r4, r9\n\t add r1, r10\n\t add r2, r11\n\t add r3, r12\n\t cmp r0, r8\n\t bne 31b\n"
        FROWS_NEXT_ROW
        FROWS_POINT3
        "9:\n\t add sp, #4\n\t"
        ".syntax divided\n"
        : "+l"(r0)
        :
        : "r1", "r2", "r3", "r4", "r5", "r6", "r7", "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");
}
#endif

#if FW_FEATURE_SPAN_LI_TEX
/* ARMv6-M: the rows of a scanned triangle of a nearest texture lit by
 * Gouraud intensity with 16-bit depth entries (span_li_tex_z2's
 * operations row after row in one loop: the same bits), without a call a
 * span; fast_rgb_rows' walk, block and point (u, v and the intensity for
 * the three levels). A lit texel: each channel c times ii = li >> 8 (Q12),
 * (c ii + 2^11) >> 12 as ((c ii >> 11) + 1) >> 1 (c ii < 63 2^24: no
 * wrap), clamped to its top level. Registers in a span's loop: r0 the
 * pixel, r1 zoff, r2 the texels, r3 vm, r4-r7 scratch, r8 the span's end,
 * r9 z, r10 u << 1, r11 v << vs, r12 li, lr dz; on the stack um and the
 * steps of u << 1, v << vs and li. */
RAS_HOT __attribute__((noinline)) static void fast_tex_rows(struct frows *P)
{
    register struct frows *r0 __asm__("r0") = P;
    __asm__ volatile(
        ".syntax unified\n\t"
        "push {r0}\n"
        FROWS_SPAN
        /* one or two pixels: each one's depth test, then its texel at a point */
        "22:\n\t mov r0, r9\n\t lsrs r0, r0, #16\n\t mov r3, r8\n\t ldr r1, [r7, #68]\n\t ldrh r2, [r3, r1]\n\t"
        "cmp r0, r2\n\t bls 23f\n\t strh r0, [r3, r1]\n\t"
        "mov r1, r10\n\t mov r2, r11\n\t ldr r7, [r7, #72]\n\t bl 50f\n\t ldr r7, [sp]\n\t"
        /* the texel at ((u << 1) >> 16 & um) | ((v << vs) >> 16 & vm) bytes */
        "lsls r4, r4, #1\n\t lsrs r4, r4, #16\n\t ldr r0, [r7, #112]\n\t ands r4, r0\n\t"
        "ldr r0, [r7, #120]\n\t lsls r5, r0\n\t lsrs r5, r5, #16\n\t ldr r0, [r7, #116]\n\t ands r5, r0\n\t"
        "orrs r4, r5\n\t ldr r0, [r7, #108]\n\t ldrh r4, [r0, r4]\n\t lsrs r6, r6, #8\n\t"
        /* lit: r0 red, r1 green, r4 blue */
        "lsrs r0, r4, #11\n\t muls r0, r6, r0\n\t lsrs r0, r0, #11\n\t adds r0, #1\n\t lsrs r0, r0, #1\n\t"
        "cmp r0, #31\n\t bls 26f\n\t movs r0, #31\n"
        "26:\n\t lsls r1, r4, #21\n\t lsrs r1, r1, #26\n\t muls r1, r6, r1\n\t lsrs r1, r1, #11\n\t adds r1, #1\n\t"
        "lsrs r1, r1, #1\n\t cmp r1, #63\n\t bls 27f\n\t movs r1, #63\n"
        "27:\n\t lsls r0, r0, #6\n\t orrs r0, r1\n\t"
        "lsls r4, r4, #27\n\t lsrs r4, r4, #27\n\t muls r4, r6, r4\n\t lsrs r4, r4, #11\n\t adds r4, #1\n\t"
        "lsrs r4, r4, #1\n\t cmp r4, #31\n\t bls 28f\n\t movs r4, #31\n"
        "28:\n\t lsls r0, r0, #5\n\t orrs r0, r4\n\t mov r3, r8\n\t strh r0, [r3]\n"
        "23:\n\t ldr r0, [r7, #92]\n\t subs r0, #1\n\t bne 25f\n\t b 8f\n"
        "25:\n\t str r0, [r7, #92]\n\t"
        "mov r3, r8\n\t adds r3, #2\n\t mov r8, r3\n\t"
        "ldr r1, [r7, #64]\n\t add r9, r1\n\t ldr r1, [r7, #56]\n\t add r10, r1\n\t ldr r1, [r7, #60]\n\t add r11, r1\n\t"
        "b 22b\n"
        /* three pixels or more (at most a segment): the first point's u, v,
         * li, the last one's, the steps by span_mul_inv's products */
        "30:\n\t mov r1, r10\n\t mov r2, r11\n\t ldr r7, [r7, #72]\n\t bl 50f\n\t"
        "ldr r7, [sp]\n\t str r4, [r7, #96]\n\t str r5, [r7, #100]\n\t str r6, [r7, #104]\n\t"
        "ldr r0, [r7, #92]\n\t subs r0, #1\n\t"
        "ldr r1, [r7, #56]\n\t muls r1, r0, r1\n\t add r1, r10\n\t"
        "ldr r2, [r7, #60]\n\t muls r2, r0, r2\n\t add r2, r11\n\t"
        "ldr r7, [r7, #72]\n\t bl 50f\n\t"
        "ldr r7, [sp]\n\t ldr r0, [r7, #92]\n\t subs r0, #1\n\t lsls r0, r0, #2\n\t ldr r1, [r7, #88]\n\t ldr r0, [r1, r0]\n\t"
        "ldr r1, [r7, #96]\n\t subs r4, r4, r1\n\t asrs r2, r4, #16\n\t muls r2, r0, r2\n\t uxth r4, r4\n\t muls r4, r0, r4\n\t"
        "lsrs r4, r4, #16\n\t adds r4, r4, r2\n\t"
        "ldr r1, [r7, #100]\n\t subs r5, r5, r1\n\t asrs r2, r5, #16\n\t muls r2, r0, r2\n\t uxth r5, r5\n\t muls r5, r0, r5\n\t"
        "lsrs r5, r5, #16\n\t adds r5, r5, r2\n\t"
        "ldr r1, [r7, #104]\n\t subs r6, r6, r1\n\t asrs r2, r6, #16\n\t muls r2, r0, r2\n\t uxth r6, r6\n\t muls r6, r0, r6\n\t"
        "lsrs r6, r6, #16\n\t adds r6, r6, r2\n\t"
        /* on the stack um, the steps of u << 1, v << vs, li; then the first
         * point's values, dz, the span's end, zoff, the texels, vm */
        "lsls r4, r4, #1\n\t ldr r1, [r7, #120]\n\t lsls r5, r1\n\t ldr r3, [r7, #112]\n\t push {r3, r4, r5, r6}\n\t"
        "ldr r4, [r7, #96]\n\t lsls r4, r4, #1\n\t mov r10, r4\n\t"
        "ldr r4, [r7, #100]\n\t lsls r4, r1\n\t mov r11, r4\n\t"
        "ldr r4, [r7, #104]\n\t mov r12, r4\n\t ldr r4, [r7, #64]\n\t mov lr, r4\n\t"
        "mov r0, r8\n\t ldr r4, [r7, #92]\n\t lsls r4, r4, #1\n\t adds r4, r0, r4\n\t mov r8, r4\n\t"
        "ldr r1, [r7, #68]\n\t ldr r2, [r7, #108]\n\t ldr r3, [r7, #116]\n"
        /* the pixels: raster_span.h's loop of the lit texture */
        "31:\n\t mov r4, r9\n\t lsrs r4, r4, #16\n\t ldrh r5, [r0, r1]\n\t cmp r4, r5\n\t bls 32f\n\t strh r4, [r0, r1]\n\t"
        "mov r4, r11\n\t lsrs r4, r4, #16\n\t ands r4, r3\n\t mov r5, r10\n\t lsrs r5, r5, #16\n\t ldr r6, [sp, #0]\n\t"
        "ands r5, r6\n\t orrs r4, r5\n\t ldrh r4, [r2, r4]\n\t mov r5, r12\n\t lsrs r5, r5, #8\n\t"
        "lsrs r6, r4, #11\n\t muls r6, r5, r6\n\t lsrs r6, r6, #11\n\t adds r6, #1\n\t lsrs r6, r6, #1\n\t"
        "cmp r6, #31\n\t bls 33f\n\t movs r6, #31\n"
        "33:\n\t lsls r7, r4, #21\n\t lsrs r7, r7, #26\n\t muls r7, r5, r7\n\t lsrs r7, r7, #11\n\t adds r7, #1\n\t"
        "lsrs r7, r7, #1\n\t cmp r7, #63\n\t bls 34f\n\t movs r7, #63\n"
        "34:\n\t lsls r6, r6, #6\n\t orrs r6, r7\n\t"
        "lsls r4, r4, #27\n\t lsrs r4, r4, #27\n\t muls r4, r5, r4\n\t lsrs r4, r4, #11\n\t adds r4, #1\n\t"
        "lsrs r4, r4, #1\n\t cmp r4, #31\n\t bls 35f\n\t movs r4, #31\n"
        "35:\n\t lsls r6, r6, #5\n\t orrs r6, r4\n\t strh r6, [r0]\n"
        "32:\n\t adds r0, #2\n\t add r9, lr\n\t ldr r4, [sp, #4]\n\t add r10, r4\n\t ldr r4, [sp, #8]\n\t add r11, r4\n\t"
        "ldr r4, [sp, #12]\n\t add r12, r4\n\t cmp r0, r8\n\t bne 31b\n\t add sp, #16\n"
        FROWS_NEXT_ROW
        FROWS_POINT3
        "9:\n\t add sp, #4\n\t"
        ".syntax divided\n"
        : "+l"(r0)
        :
        : "r1", "r2", "r3", "r4", "r5", "r6", "r7", "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");
}
#endif

/* The block's fields both scans read: the edge values and their steps, the
 * first row's pixel at the box's left column, the box's width, the stride
 * and the rows. */
static void fscan_begin(const struct ras_ctx *rc, const struct fstate *S, struct fscan *P, int32_t r0,
                        uint32_t rows)
{
    const struct render_target *t = rc->cur.t;
    for (int i = 0; i < 3; i++) {
        P->wb[i] = S->wb[i];
        P->a[i] = S->a[i];
        P->b[i] = S->b[i];
    }
    P->prow = t->rgb565 + (size_t)(r0 - (int32_t)t->y0) * rc->w + (size_t)S->c0;
    P->kmax2 = (uint32_t)S->kmax * 2u;
    P->stride = (uint32_t)rc->w * 2u;
    P->rows = rows;
}

/* fast_rows(rc, S, 1) of a scanned triangle whose plane has its 32-bit form
 * (board outputs): its spans by fast_scan_spans, then drawn by its loop. */
static uint32_t fast_run_spans(const struct ras_ctx *rc, struct fstate *S)
{
    const struct render_target *t = rc->cur.t;
    const int32_t r0 = S->row, r1 = S->last < (int32_t)t->y1 - 1 ? S->last : (int32_t)t->y1 - 1;
    if (r1 < r0) {
        S->row = r1 + 1;
        return 0;
    }
    struct fscan P;
    uint16_t sp[RAS_SCAN_MAX / 2];
    const uint32_t rows = (uint32_t)(r1 - r0 + 1);
    fscan_begin(rc, S, &P, r0, rows);
    size_t idx0 = (size_t)(P.prow - t->rgb565);
    P.spans = sp;
    fast_scan_spans(&P);
    S->wb[0] = P.wb[0];
    S->wb[1] = P.wb[1];
    S->wb[2] = P.wb[2];
    const span_fn fn = ras_span_board[S->shade][S->src][rc->depth_bytes == 2 ? 1 : 2];
    struct frow R;
    R.dz = S->dz;
    R.rgb888 = R.written = NULL;
    R.w1 = R.w2 = 0;
    const int attrs = S->shade != SPAN_SHADE_NONE || S->src != SPAN_SRC_CONST;
    /* the plane as fast_scan_flat's zq, zf */
    uint32_t zq = S->zhi, zf = S->zfrac, total = 0;
    const uint32_t gxq = (uint32_t)S->gxq, gxf = S->gxf, gyq = S->gyq, gyf = S->gyf;
    int32_t wr1 = S->wr[1], wr2 = S->wr[2];
    const int32_t a1 = S->a[1], a2 = S->a[2], b1 = S->b[1], b2 = S->b[2];
    for (uint32_t i = 0; i < rows; i++, idx0 += rc->w) {
        const uint32_t s = sp[i];
        if (s >> 8) {
            const uint32_t lo = s & 255u;
            const size_t idx = idx0 + lo;
            R.n = (int32_t)(s >> 8);
            R.px = t->rgb565 + idx;
            R.zb = rc->depth + idx * rc->depth_bytes;
            R.z = zq + lo * gxq + ((zf + lo * gxf) >> 16);
            if (attrs) {
                R.w1 = wr1 + (int32_t)lo * a1;
                R.w2 = wr2 + (int32_t)lo * a2;
            }
            fn(&S->T, &R);
            total += (uint32_t)R.n;
        }
        zq += gyq;
        zf += gyf;
        wr1 += b1;
        wr2 += b2;
    }
    S->zhi = zq + (zf >> 16);
    S->zfrac = zf & 0xFFFFu;
    S->wr[1] = wr1;
    S->wr[2] = wr2;
    S->row = r1 + 1;
    return total;
}

#if FW_FEATURE_SPAN_RGB_CONST || FW_FEATURE_SPAN_LI_TEX
/* fast_rows(rc, S, 1) of a scanned triangle with 16-bit depth entries whose
 * plane has its 32-bit form (board outputs) for a row loop of struct
 * frows' block (rows: fast_rgb_rows, fast_tex_rows; tex: whether it reads
 * the texture's fields): its spans by fast_scan_spans, then its rows in
 * one loop, a span longer than a segment by the span loop fn. */
RAS_ALWAYS_INLINE uint32_t fast_run_rows(const struct ras_ctx *rc, struct fstate *S, void (*rows)(struct frows *),
                                         const span_fn fn, const int tex)
{
    const struct render_target *t = rc->cur.t;
    const int32_t r0 = S->row, r1 = S->last < (int32_t)t->y1 - 1 ? S->last : (int32_t)t->y1 - 1;
    if (r1 < r0) {
        S->row = r1 + 1;
        return 0;
    }
    struct fscan P;
    uint16_t sp[RAS_SCAN_MAX / 2];
    const uint32_t rows_n = (uint32_t)(r1 - r0 + 1);
    fscan_begin(rc, S, &P, r0, rows_n);
    uint16_t *const prow = P.prow;
    P.spans = sp;
    fast_scan_spans(&P);
    S->wb[0] = P.wb[0];
    S->wb[1] = P.wb[1];
    S->wb[2] = P.wb[2];
    struct frow R;
    R.dz = S->dz;
    R.rgb888 = R.written = NULL;
    struct frows G;
    G.sp = sp;
    G.spe = sp + rows_n;
    G.zq = S->zhi;
    G.zf = S->zfrac;
    G.w1 = S->wr[1];
    G.w2 = S->wr[2];
    G.prow = prow;
    G.gyq = S->gyq;
    G.gyf = S->gyf;
    G.b1 = S->b[1];
    G.b2 = S->b[2];
    G.stride = (uint32_t)rc->w * 2u;
    G.gxq = (uint32_t)S->gxq;
    G.gxf = S->gxf;
    G.a1 = S->a[1];
    G.a2 = S->a[2];
    G.dz = S->dz;
    G.zoff = (uint32_t)(uintptr_t)rc->depth - (uint32_t)(uintptr_t)t->rgb565;
    G.pp = &S->T.pp;
    G.seg = S->T.seg;
    G.total = 0;
    G.rcp = (uint32_t)(uintptr_t)rcp_tab - 512u;
    G.inv = fast_inv_tab;
    if (tex) {
        /* raster_span.h's byte offsets of a texel: u doubled, v times twice the width */
        const struct ras_fast_tri *ft = S->T.ft;
        G.tex = (const uint8_t *)ft->tex;
        G.um = ft->wmask << 1;
        G.vm = ft->hmask << (ft->wlog2 + 1);
        G.vs = ft->wlog2 + 1;
    }
    for (;;) {
        rows(&G);
        if (G.sp == G.spe) break;
        const uint32_t s = *G.sp, lo = s & 255u;
        const size_t idx = (size_t)(G.prow - t->rgb565) + lo;
        R.n = (int32_t)(s >> 8);
        R.px = t->rgb565 + idx;
        R.zb = rc->depth + idx * 2u;
        R.z = G.zq + lo * G.gxq + ((G.zf + lo * G.gxf) >> 16);
        R.w1 = G.w1 + (int32_t)lo * G.a1;
        R.w2 = G.w2 + (int32_t)lo * G.a2;
        fn(&S->T, &R);
        G.total += (uint32_t)R.n;
        G.sp++;
        G.zq += G.gyq;
        G.zf += G.gyf;
        G.w1 += G.b1;
        G.w2 += G.b2;
        G.prow += rc->w;
        if (G.sp == G.spe) break;
    }
    S->zhi = G.zq + (G.zf >> 16);
    S->zfrac = G.zf & 0xFFFFu;
    S->wr[1] = G.w1;
    S->wr[2] = G.w2;
    S->row = r1 + 1;
    return G.total;
}
#endif

#if FW_FEATURE_SPAN_RGB_CONST
/* fast_run_rows of Gouraud levels (fast_rgb_rows). */
__attribute__((noinline)) static uint32_t fast_run_rgb(const struct ras_ctx *rc, struct fstate *S)
{
    return fast_run_rows(rc, S, fast_rgb_rows, ras_span_board[SPAN_SHADE_RGB][SPAN_SRC_CONST][1], 0);
}
#endif

#if FW_FEATURE_SPAN_LI_TEX
/* fast_run_rows of a nearest texture lit by Gouraud intensity
 * (fast_tex_rows). */
__attribute__((noinline)) static uint32_t fast_run_tex(const struct ras_ctx *rc, struct fstate *S)
{
    return fast_run_rows(rc, S, fast_tex_rows, ras_span_board[SPAN_SHADE_LI][SPAN_SRC_TEX][1], 1);
}
#endif

/* fast_rows(rc, S, 1) of a triangle fast_scan_flat draws; S is left at
 * the next row only where kept (a set-up not kept is not read again). */
__attribute__((noinline)) static uint32_t fast_run_flat(const struct ras_ctx *rc, struct fstate *S, const int kept)
{
    const struct render_target *t = rc->cur.t;
    const int32_t r0 = S->row, r1 = S->last < (int32_t)t->y1 - 1 ? S->last : (int32_t)t->y1 - 1;
    if (r1 >= r0) {
        struct fscan P;
        const uint32_t rows = (uint32_t)(r1 - r0 + 1);
        fscan_begin(rc, S, &P, r0, rows);
        P.zoff = (uint32_t)(uintptr_t)rc->depth - (uint32_t)(uintptr_t)t->rgb565;
        P.zhi = S->zhi;
        P.zfrac = S->zfrac;
        P.gxq = (uint32_t)S->gxq;
        P.gxf = S->gxf;
        P.gyq = S->gyq;
        P.gyf = S->gyf;
        P.total = 0;
        P.dz = S->dz;
        P.col = S->T.ft->c565;
        fast_scan_flat(&P);
        if (!kept) return P.total;
        for (int i = 0; i < 3; i++) S->wb[i] = P.wb[i];
        S->wr[1] += (int32_t)rows * S->b[1];
        S->wr[2] += (int32_t)rows * S->b[2];
        S->zhi = P.zhi + (P.zfrac >> 16);
        S->zfrac = P.zfrac & 0xFFFFu;
        S->row = r1 + 1;
        return P.total;
    }
    S->row = r1 + 1;
    return 0;
}
#else
#define RAS_SCAN_FLAT_V6M 0
#endif

/* 1 when fast_run_flat (shade SPAN_SHADE_NONE, src SPAN_SRC_CONST),
 * fast_run_rgb (SPAN_SHADE_RGB, SPAN_SRC_CONST) or fast_run_tex
 * (SPAN_SHADE_LI, SPAN_SRC_TEX) draws S's rows. */
static inline int fast_scan16(const struct ras_ctx *rc, const struct fstate *S)
{
    return S->scan && S->z32 &&
#if RENDER_HOST_OUTPUTS
           rc->cur.t->rgb888 == NULL && rc->cur.t->written == NULL &&
#endif
           rc->depth_bytes == 2;
}

static uint32_t fast_run(const struct ras_ctx *rc, struct fstate *S, const int kept)
{
#if RAS_SCAN_FLAT_V6M
    if (S->scan && S->z32
#if RENDER_HOST_OUTPUTS
        && rc->cur.t->rgb888 == NULL && rc->cur.t->written == NULL
#endif
    )
        return rc->depth_bytes == 2 && S->shade == SPAN_SHADE_NONE && S->src == SPAN_SRC_CONST ? fast_run_flat(rc, S, kept)
                                                                                             : fast_run_spans(rc, S);
#else
    (void)kept;
#endif
    return S->scan ? fast_rows(rc, S, 1) : fast_rows(rc, S, 0);
}

int32_t ras_fast_fill(struct ras_ctx *rc, const struct ras_sv *v0, const struct ras_sv *v1, const struct ras_sv *v2,
                      const struct ras_fast_tri *ft, struct ras_fast_state *keep)
{
    struct fstate local, *S = keep ? (struct fstate *)(void *)keep : &local;
    int r = fast_setup(rc, v0, v1, v2, ft, S, keep == NULL);
    if (r <= 0) {
        if (keep) S->row = -1;
        return r;
    }
#if RAS_SCAN_FLAT_V6M
    /* (fast_run_flat, fast_run_rgb and fast_run_tex called straight: none
     * of fast_run's frame) */
    uint32_t drawn;
    if (!fast_scan16(rc, S))
        drawn = fast_run(rc, S, keep != NULL);
    else if (S->src == SPAN_SRC_CONST && S->shade == SPAN_SHADE_NONE)
        drawn = fast_run_flat(rc, S, keep != NULL);
#if FW_FEATURE_SPAN_RGB_CONST
    else if (S->src == SPAN_SRC_CONST && S->shade == SPAN_SHADE_RGB)
        drawn = fast_run_rgb(rc, S);
#endif
#if FW_FEATURE_SPAN_LI_TEX
    else if (S->src == SPAN_SRC_TEX && S->shade == SPAN_SHADE_LI)
        drawn = fast_run_tex(rc, S);
#endif
    else
        drawn = fast_run(rc, S, keep != NULL);
#else
    uint32_t drawn = fast_run(rc, S, keep != NULL);
#endif
    if (keep && S->row <= S->last) {
        /* continued in the next strip: its own copy of the description */
        S->ftc = *ft;
        S->T.ft = &S->ftc;
    }
    return (int32_t)drawn;
}

int ras_fast_resume(struct ras_ctx *rc, struct ras_fast_state *keep, uint32_t *drawn)
{
    struct fstate *S = (struct fstate *)(void *)keep;
    if (S->row != (int32_t)rc->cur.t->y0 || S->row > S->last) return 0;
    *drawn = fast_run(rc, S, 1);
    return 1;
}
