/* SPDX-License-Identifier: MIT */
/* raster_triangles.c — chapters 7 and 8: DrawFilledTriangle,
 * DrawShadedTriangle and the book's scan conversion (docs/book-demos.md), plus the
 * default path's edge-function triangle with the top-left fill rule. */
#include "raster_int.h"

#define RAS_MAX_STEPS 65536

void ras_book_sort_corners(const num y[3], int idx[3])
{
    idx[0] = 0; idx[1] = 1; idx[2] = 2;
    int t;
    if (y[idx[1]] < y[idx[0]]) { t = idx[0]; idx[0] = idx[1]; idx[1] = t; }
    if (y[idx[2]] < y[idx[0]]) { t = idx[0]; idx[0] = idx[2]; idx[2] = t; }
    if (y[idx[2]] < y[idx[1]]) { t = idx[1]; idx[1] = idx[2]; idx[2] = t; }
}

/* Length of Interpolate(i0, ..., i1, ...): the counter runs i0, i0+1, ... <= i1. */
static int32_t interp_len(num i0, num i1)
{
    if (i1 == i0) return 1;
    int32_t n = 0;
    for (num i = i0; i <= i1 && n < RAS_MAX_STEPS; n++) {
        num next = ras_count_next(i, i0, n + 1);
        if (next <= i) break;
        i = next;
    }
    return n;
}

/* Value k of Interpolate(i0, d0, i1, d1). */
static num interp_at(num i0, num d0, num i1, num d1, int32_t k)
{
    struct ras_interp it;
    ras_interp_init(&it, i0, d0, i1, d1);
    for (int32_t j = 0; j < k; j++) ras_interp_next(&it);
    return ras_interp_value(&it);
}

/* The edges of a sorted triangle for one value (x or an attribute). */
struct book_edge { struct ras_interp e01, e12, e02; };

enum { SPAN_TRUNCATED, SPAN_REAL };

static void book_scan(struct ras_ctx *rc, const num x[3], const num y[3], int nq,
                      const num (*q)[3], int span_kind, ras_book_pixel_fn fn, void *ud, rgb flat)
{
    struct book_edge ed[1 + RAS_MAX_ATTR];
    int nv = 1 + nq;
    int32_t len01 = interp_len(y[0], y[1]);
    int32_t len02 = interp_len(y[0], y[2]);
    int32_t split = len01 - 1;          /* first index of x012 taken from x12 */
    int32_t m = len02 / 2;

    /* left/right from the middle row (step 3) */
    num x02m = interp_at(y[0], x[0], y[2], x[2], m);
    num x012m = m < split ? interp_at(y[0], x[0], y[1], x[1], m)
                          : interp_at(y[1], x[1], y[2], x[2], m - split);
    int left_is_02 = x02m < x012m;

    for (int j = 0; j < nv; j++) {
        const num *v = j == 0 ? x : q[j - 1];
        ras_interp_init(&ed[j].e01, y[0], v[0], y[1], v[1]);
        ras_interp_init(&ed[j].e12, y[1], v[1], y[2], v[2]);
        ras_interp_init(&ed[j].e02, y[0], v[0], y[2], v[2]);
    }

    num yc = y[0];
    for (int32_t k = 0; k < len02; k++) {
        num a02[1 + RAS_MAX_ATTR], a012[1 + RAS_MAX_ATTR];
        for (int j = 0; j < nv; j++) {
            a02[j] = ras_interp_value(&ed[j].e02);
            a012[j] = k < split ? ras_interp_value(&ed[j].e01) : ras_interp_value(&ed[j].e12);
        }
        const num *L = left_is_02 ? a02 : a012, *R = left_is_02 ? a012 : a02;
        int32_t yi = num_to_int(yc);
        int row = ras_canvas_row(rc, yi);
        if (row < 0) break; /* rows only go up from here */
        if (row >= (int)rc->cur.t->y0 && row < (int)rc->cur.t->y1) {
            if (span_kind == SPAN_REAL) {
                int n = 0;
                for (num xs = L[0]; xs <= R[0] && n < RAS_MAX_STEPS; n++, xs = ras_count_next(xs, L[0], n)) {
                    if (ras_canvas_col(rc, num_to_int(xs)) >= (int)rc->w) break;
                    ras_put_canvas(rc, xs, yc, flat);
                }
            } else {
                int32_t xl = num_to_int(L[0]), xr = num_to_int(R[0]);
                struct ras_interp sp[RAS_MAX_ATTR];
                num qv[RAS_MAX_ATTR];
                for (int j = 0; j < nq; j++)
                    ras_interp_init(&sp[j], num_from_int(xl), L[1 + j], num_from_int(xr), R[1 + j]);
                for (int32_t xi = xl; xi <= xr; xi++) {
                    if (ras_canvas_col(rc, xi) >= (int)rc->w) break;
                    if (ras_canvas_col(rc, xi) >= 0) {
                        for (int j = 0; j < nq; j++) qv[j] = ras_interp_value(&sp[j]);
                        fn(rc, xi, yi, qv, ud);
                    }
                    for (int j = 0; j < nq; j++) ras_interp_next(&sp[j]);
                }
            }
        }
        for (int j = 0; j < nv; j++) {
            ras_interp_next(&ed[j].e02);
            if (k < split) ras_interp_next(&ed[j].e01);
            else ras_interp_next(&ed[j].e12);
        }
        num next = ras_count_next(yc, y[0], k + 1);
        if (next <= yc) break;
        yc = next;
    }
}

void ras_book_scan_triangle(struct ras_ctx *rc, const num x[3], const num y[3], int nq,
                            const num (*q)[3], ras_book_pixel_fn fn, void *ud)
{
    book_scan(rc, x, y, nq, q, SPAN_TRUNCATED, fn, ud, rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
}

void ras_draw_filled_triangle(struct ras_ctx *rc, const num x[3], const num y[3], rgb c)
{
    int i[3];
    ras_book_sort_corners(y, i);
    num xs[3] = { x[i[0]], x[i[1]], x[i[2]] }, ys[3] = { y[i[0]], y[i[1]], y[i[2]] };
    book_scan(rc, xs, ys, 0, NULL, SPAN_REAL, NULL, NULL, c);
}

struct shaded_ud { rgb c; };

static void shaded_pixel(struct ras_ctx *rc, int32_t x, int32_t y, const num *q, void *ud)
{
    const struct shaded_ud *s = ud;
    ras_put(rc, ras_canvas_col(rc, x), ras_canvas_row(rc, y), rgb_scale(s->c, q[0]));
}

void ras_draw_shaded_triangle(struct ras_ctx *rc, const num x[3], const num y[3], const num h[3], rgb c)
{
    int i[3];
    ras_book_sort_corners(y, i);
    num xs[3] = { x[i[0]], x[i[1]], x[i[2]] }, ys[3] = { y[i[0]], y[i[1]], y[i[2]] };
    num hs[1][3] = { { h[i[0]], h[i[1]], h[i[2]] } };
    struct shaded_ud ud = { c };
    book_scan(rc, xs, ys, 1, (const num (*)[3])hs, SPAN_TRUNCATED, shaded_pixel, &ud, c);
}

/* ---- default path ------------------------------------------------------ */

int64_t ras_edge(int32_t ax, int32_t ay, int32_t bx, int32_t by, int64_t px, int64_t py)
{
    return (int64_t)(bx - ax) * (py - ay) - (int64_t)(by - ay) * (px - ax);
}

void ras_sub_box(const struct ras_sv *v0, const struct ras_sv *v1, const struct ras_sv *v2, int32_t box[4])
{
    const struct ras_sv *vv[3] = { v0, v1, v2 };
    box[0] = box[2] = v0->x;
    box[1] = box[3] = v0->y;
    for (int i = 1; i < 3; i++) {
        if (vv[i]->x < box[0]) box[0] = vv[i]->x;
        if (vv[i]->y < box[1]) box[1] = vv[i]->y;
        if (vv[i]->x > box[2]) box[2] = vv[i]->x;
        if (vv[i]->y > box[3]) box[3] = vv[i]->y;
    }
}

/* Top-left rule: pixel centres exactly on a top or left edge belong to the
 * triangle, on other edges to the neighbour. */
static int64_t edge_bias(int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
    int32_t dx = bx - ax, dy = by - ay;
    return (dy < 0 || (dy == 0 && dx > 0)) ? 0 : -1;
}

/* The depth test of pixel di at depth d (near/z, before clamping) under
 * the strip's depth function; a passing RAS_DEPTH_LESS_WRITE pixel stores
 * its depth. */
static inline int depth_test(const struct ras_ctx *rc, size_t di, int64_t d)
{
    if (d < 0) d = 0;
    if (d > (int64_t)UINT32_MAX) d = UINT32_MAX;
    uint32_t cur, dv = (uint32_t)d;
    if (rc->depth_bytes == 2) {
        dv >>= 16;
        cur = ((uint16_t *)(void *)rc->depth)[di];
    } else {
        cur = ((uint32_t *)(void *)rc->depth)[di];
    }
    if (rc->cur.depth_func == RAS_DEPTH_EQUAL) return dv == cur;
    if (rc->cur.depth_func == RAS_DEPTH_BEHIND) return dv <= cur; /* not nearer: depth-fail counts the surface's own cap */
    if (dv <= cur) return 0;
    if (rc->depth_bytes == 2) ((uint16_t *)(void *)rc->depth)[di] = (uint16_t)dv;
    else ((uint32_t *)(void *)rc->depth)[di] = dv;
    return 1;
}

/* A pixel's z and its na attributes a[] from its screen barycentrics l1,
 * l2: perspective-correct (weights b_i/z_i), the ones from affine_from on
 * screen-linear. da1, da2: corner 1's and 2's attributes less corner 0's. */
static inline num pixel_attrs(const struct ras_ctx *rc, const struct ras_sv *v0, const struct ras_sv *v1,
                              const struct ras_sv *v2, int na, num l1, num l2, const num *da1, const num *da2,
                              num *a)
{
    num l0 = num_sub(num_sub(NUM_ONE, l1), l2);
    num p0 = num_mul(l0, v0->iz), p1 = num_mul(l1, v1->iz), p2 = num_mul(l2, v2->iz);
    num iz = num_add(num_add(p0, p1), p2);
    num z = num_recip(iz);
    if (na) {
        num q1 = num_mul(p1, z), q2 = num_mul(p2, z);
        int nf = rc->def.affine_from >= 0 && rc->def.affine_from < na ? rc->def.affine_from : na;
        for (int j = 0; j < nf; j++)
            a[j] = num_add(v0->a[j], num_add(num_mul(q1, da1[j]), num_mul(q2, da2[j])));
        for (int j = nf; j < na; j++) /* screen-linear (the book's linear u, v) */
            a[j] = num_add(v0->a[j], num_add(num_mul(l1, da1[j]), num_mul(l2, da2[j])));
    }
    return z;
}

uint32_t ras_fill_triangle(struct ras_ctx *rc, const struct ras_sv *v0, const struct ras_sv *v1,
                           const struct ras_sv *v2, int na, ras_pixel_fn fn, void *ud)
{
    const struct render_target *t = rc->cur.t;
    int sb = rc->def.sub_bits;
    int64_t area = ras_edge(v0->x, v0->y, v1->x, v1->y, v2->x, v2->y);
    if (area <= 0) return 0;

    /* bounding box in pixels, clipped to the strip */
    int32_t box[4];
    ras_sub_box(v0, v1, v2, box);
    const int32_t minx = box[0], miny = box[1], maxx = box[2], maxy = box[3];
    int32_t c0 = minx >> sb, c1 = (maxx >> sb) + 1, r0 = miny >> sb, r1 = (maxy >> sb) + 1;
    if (c0 < 0) c0 = 0;
    if (r0 < (int32_t)t->y0) r0 = t->y0;
    if (c1 > (int32_t)rc->w - 1) c1 = rc->w - 1;
    if (r1 > (int32_t)t->y1 - 1) r1 = t->y1 - 1;
    if (c0 > c1 || r0 > r1) return 0;

    /* edges opposite each corner: w0 from v1->v2, w1 from v2->v0, w2 from v0->v1 */
    int64_t b0 = edge_bias(v1->x, v1->y, v2->x, v2->y);
    int64_t b1 = edge_bias(v2->x, v2->y, v0->x, v0->y);
    int64_t b2 = edge_bias(v0->x, v0->y, v1->x, v1->y);
    int64_t half = (int64_t)1 << (sb - 1);
    int64_t px = ((int64_t)c0 << sb) + half, py = ((int64_t)r0 << sb) + half;
    int64_t w0r = ras_edge(v1->x, v1->y, v2->x, v2->y, px, py);
    int64_t w1r = ras_edge(v2->x, v2->y, v0->x, v0->y, px, py);
    int64_t w2r = ras_edge(v0->x, v0->y, v1->x, v1->y, px, py);
    /* steps per pixel */
    int64_t one = (int64_t)1 << sb;
    int64_t a0 = -(int64_t)(v2->y - v1->y) * one, bb0 = (int64_t)(v2->x - v1->x) * one;
    int64_t a1 = -(int64_t)(v0->y - v2->y) * one, bb1 = (int64_t)(v0->x - v2->x) * one;
    int64_t a2 = -(int64_t)(v1->y - v0->y) * one, bb2 = (int64_t)(v1->x - v0->x) * one;

    uint32_t written = 0;
    num da1[RAS_MAX_ATTR], da2[RAS_MAX_ATTR];
    for (int j = 0; j < na; j++) {
        da1[j] = num_sub(v1->a[j], v0->a[j]);
        da2[j] = num_sub(v2->a[j], v0->a[j]);
    }
    int64_t dd1 = (int64_t)v1->depth - v0->depth, dd2 = (int64_t)v2->depth - v0->depth;
    /* near/z is affine in screen space: dz = (dd1*w1 + dd2*w2)/area exactly,
     * truncated toward zero. The numerator is linear in the column, so the
     * quotient steps by a fixed quotient + remainder (no divide per pixel). */
    int64_t sq = 0, sr = 0;
    int depth = rc->depth_bytes != 0;
    if (depth) sq = ras_floordiv(dd1 * a1 + dd2 * a2, area, &sr);

    for (int32_t r = r0; r <= r1; r++) {
        int64_t w0 = w0r, w1 = w1r, w2 = w2r;
        int64_t zq = 0, zr = 0;
        if (depth) zq = ras_floordiv(dd1 * w1 + dd2 * w2, area, &zr);
        for (int32_t c = c0; c <= c1; c++) {
            if (w0 + b0 >= 0 && w1 + b1 >= 0 && w2 + b2 >= 0) {
                size_t di = (size_t)(r - t->y0) * rc->w + (size_t)c;
                /* (the quotient floor -> toward zero) */
                int pass = !depth || depth_test(rc, di, (int64_t)v0->depth + zq + (zq < 0 && zr != 0));
                if (pass && (!fn || na < 0)) {
                    if (fn) fn(rc, c, r, NULL, NUM_ZERO, ud);
                    written++;
                } else if (pass) {
                    num a[RAS_MAX_ATTR];
                    num z = pixel_attrs(rc, v0, v1, v2, na, ras_ratio(w1, area), ras_ratio(w2, area), da1, da2, a);
                    fn(rc, c, r, a, z, ud);
                    written++;
                }
            }
            w0 += a0; w1 += a1; w2 += a2;
            zq += sq; zr += sr;
            if (zr >= area) { zq++; zr -= area; }
        }
        w0r += bb0; w1r += bb1; w2r += bb2;
    }
    return written;
}
