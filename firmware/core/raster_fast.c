/* raster_fast.c — the default path's fast triangle: span loops specialised
 * per feature combination, integer stepping, no division per pixel.
 *
 * Coverage is the exact path's: the same sub-pixel vertices, edge functions
 * and top-left rule, evaluated per row instead of per pixel. For each edge
 * the columns a row covers form a half-line whose end is a quotient of two
 * integers; it is stepped from row to row by quotient and remainder, so
 * every row's span is exactly the set of pixels the per-pixel test accepts
 * (tests/test_raster.c checks the two against each other).
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
 * power-of-two masks (raster_init converts them). */
#include "raster_int.h"
#include "num_int.h"

#define FT_FLAT RAS_FT_FLAT
#define FT_GOURAUD RAS_FT_GOURAUD
#define FT_TEX RAS_FT_TEX
#define FT_TEX_GOURAUD RAS_FT_TEX_GOURAUD

/* One segment of a span: where it starts and what it steps. */
struct fspan {
    uint16_t *px;
    uint8_t *zb;
    uint32_t z, dz;
    int32_t u, du, v, dv;    /* texel coordinates, 16.16 */
    int32_t i, di;           /* intensity, Q20 */
    const struct ras_fast_tri *ft;
    uint8_t *rgb888, *written;   /* host outputs at the first pixel, or NULL */
};

static void ras_565_to_888(uint16_t c, uint8_t *o)
{
    uint32_t r = c >> 11, g = (c >> 5) & 63, b = c & 31;
    o[0] = (uint8_t)(r << 3 | r >> 2);
    o[1] = (uint8_t)(g << 2 | g >> 4);
    o[2] = (uint8_t)(b << 3 | b >> 2);
}

typedef uint32_t (*span_fn)(const struct fspan *s, int n);

#define SPAN_NAME span_flat_nz
#define SPAN_DEPTH 0
#define SPAN_KIND FT_FLAT
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_flat_z16
#define SPAN_DEPTH 2
#define SPAN_KIND FT_FLAT
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_flat_z32
#define SPAN_DEPTH 4
#define SPAN_KIND FT_FLAT
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_gour_nz
#define SPAN_DEPTH 0
#define SPAN_KIND FT_GOURAUD
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_gour_z16
#define SPAN_DEPTH 2
#define SPAN_KIND FT_GOURAUD
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_gour_z32
#define SPAN_DEPTH 4
#define SPAN_KIND FT_GOURAUD
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_tex_nz
#define SPAN_DEPTH 0
#define SPAN_KIND FT_TEX
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_tex_z16
#define SPAN_DEPTH 2
#define SPAN_KIND FT_TEX
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_tex_z32
#define SPAN_DEPTH 4
#define SPAN_KIND FT_TEX
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_texg_nz
#define SPAN_DEPTH 0
#define SPAN_KIND FT_TEX_GOURAUD
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_texg_z16
#define SPAN_DEPTH 2
#define SPAN_KIND FT_TEX_GOURAUD
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_texg_z32
#define SPAN_DEPTH 4
#define SPAN_KIND FT_TEX_GOURAUD
#define SPAN_EXTRA 0
#include "raster_span.h"
/* with the host's outputs */
#define SPAN_NAME span_flat_nz_x
#define SPAN_DEPTH 0
#define SPAN_KIND FT_FLAT
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_flat_z16_x
#define SPAN_DEPTH 2
#define SPAN_KIND FT_FLAT
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_flat_z32_x
#define SPAN_DEPTH 4
#define SPAN_KIND FT_FLAT
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_gour_nz_x
#define SPAN_DEPTH 0
#define SPAN_KIND FT_GOURAUD
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_gour_z16_x
#define SPAN_DEPTH 2
#define SPAN_KIND FT_GOURAUD
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_gour_z32_x
#define SPAN_DEPTH 4
#define SPAN_KIND FT_GOURAUD
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_tex_nz_x
#define SPAN_DEPTH 0
#define SPAN_KIND FT_TEX
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_tex_z16_x
#define SPAN_DEPTH 2
#define SPAN_KIND FT_TEX
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_tex_z32_x
#define SPAN_DEPTH 4
#define SPAN_KIND FT_TEX
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_texg_nz_x
#define SPAN_DEPTH 0
#define SPAN_KIND FT_TEX_GOURAUD
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_texg_z16_x
#define SPAN_DEPTH 2
#define SPAN_KIND FT_TEX_GOURAUD
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_texg_z32_x
#define SPAN_DEPTH 4
#define SPAN_KIND FT_TEX_GOURAUD
#define SPAN_EXTRA 1
#include "raster_span.h"

/* [extra][kind][depth 0/2/4 -> 0/1/2] */
static const span_fn span_table[2][4][3] = {
    { { span_flat_nz, span_flat_z16, span_flat_z32 },
      { span_gour_nz, span_gour_z16, span_gour_z32 },
      { span_tex_nz, span_tex_z16, span_tex_z32 },
      { span_texg_nz, span_texg_z16, span_texg_z32 } },
    { { span_flat_nz_x, span_flat_z16_x, span_flat_z32_x },
      { span_gour_nz_x, span_gour_z16_x, span_gour_z32_x },
      { span_tex_nz_x, span_tex_z16_x, span_tex_z32_x },
      { span_texg_nz_x, span_texg_z16_x, span_texg_z32_x } },
};

/* ---- set-up -------------------------------------------------------------- */

static int64_t edge(int32_t ax, int32_t ay, int32_t bx, int32_t by, int64_t px, int64_t py)
{
    return (int64_t)(bx - ax) * (py - ay) - (int64_t)(by - ay) * (px - ax);
}

/* One edge's bound on the columns of a row, k = column - c0:
 * kind 1: k >= q (lower), kind -1: k <= q (upper), kind 0: all columns
 * while the row value n >= 0, none otherwise. q = floor(n / den) stepped
 * per row by quotient dq and remainder dr. */
struct fedge { int kind; int64_t n, q, r, den, dq, dr, step; };

static void fedge_init(struct fedge *e, int64_t a, int64_t b, int64_t w, int64_t bias)
{
    /* pixel (c0 + k, row) is covered when w + k*a + bias >= 0 */
    if (a > 0) {          /* k >= ceil((-bias - w) / a) = floor((-bias - w + a - 1) / a) */
        e->kind = 1;
        e->den = a;
        e->n = -bias - w + a - 1;
        e->step = -b;
    } else if (a < 0) {   /* k <= floor((w + bias) / -a) */
        e->kind = -1;
        e->den = -a;
        e->n = w + bias;
        e->step = b;
    } else {
        e->kind = 0;
        e->den = 1;
        e->n = w + bias;
        e->step = b;
        e->q = e->r = e->dq = e->dr = 0;
        return;
    }
    e->q = ras_floordiv(e->n, e->den, &e->r);
    e->dq = ras_floordiv(e->step, e->den, &e->dr);
}

static void fedge_next(struct fedge *e)
{
    if (e->kind == 0) { e->n += e->step; return; }
    e->q += e->dq;
    e->r += e->dr;
    if (e->r >= e->den) { e->q++; e->r -= e->den; }
}

/* Perspective-correct attributes at a pixel from its edge values. */
struct fpersp {
    int t;                   /* edge values >> t < 2^15 */
    uint32_t area_t;         /* area >> t */
    uint32_t dn[3];          /* near/z of the corners >> s, < 2^16 */
    int na;                  /* attributes: 1 (intensity), 2 (u, v) or 3 (u, v, intensity) */
    int32_t a0[3];           /* corner 0's value in the span format */
    int32_t d1[3], d2[3];    /* (corner 1 - corner 0), (corner 2 - corner 0) >> sh */
    int sh[3];
};

static int32_t asr32(int32_t x, int n)
{
    return x >= 0 ? x >> n : -(int32_t)((uint32_t)(-(int64_t)x - 1) >> n) - 1;
}

static void persp_at(const struct fpersp *p, int64_t w1, int64_t w2, int32_t *out)
{
    uint32_t b1 = (uint32_t)(w1 >> p->t), b2 = (uint32_t)(w2 >> p->t);
    uint32_t b0 = p->area_t - b1 - b2;       /* >= (w0 >> t) >= 0 */
    uint32_t P0 = b0 * p->dn[0], P1 = b1 * p->dn[1], P2 = b2 * p->dn[2];
    uint32_t S = P0 + P1 + P2;               /* <= area_t * 2^16 < 2^31 */
    int32_t q1 = 0, q2 = 0;
    if (S) {
        int u = 17 - num_clz32(S);
        if (u > 0) { S >>= u; P1 >>= u; P2 >>= u; }
        if (S == 0) S = 1;
        uint32_t R = (1u << 30) / S;         /* S < 2^15: R > 2^15 */
        q1 = (int32_t)((P1 * R) >> 14);      /* Q16; P <= S, so P*R <= 2^30 */
        q2 = (int32_t)((P2 * R) >> 14);
    }
    for (int j = 0; j < p->na; j++) {
        int32_t d = q1 * p->d1[j] + q2 * p->d2[j];   /* |d| < 2^16 * 2^14 */
        int s = 16 - p->sh[j];
        int64_t v = s >= 0 ? (int64_t)asr32(d, s) : (int64_t)d * ((int64_t)1 << -s);
        v += p->a0[j];
        out[j] = v > INT32_MAX ? INT32_MAX : (v < -INT32_MAX ? -INT32_MAX : (int32_t)v);
    }
}

static void persp_attr(struct fpersp *p, int j, int32_t c0, int32_t c1, int32_t c2)
{
    int64_t e1 = (int64_t)c1 - c0, e2 = (int64_t)c2 - c0;
    int64_t m = e1 < 0 ? -e1 : e1;
    if ((e2 < 0 ? -e2 : e2) > m) m = e2 < 0 ? -e2 : e2;
    int sh = 0;
    while ((m >> sh) >= ((int64_t)1 << 14)) sh++;
    p->a0[j] = c0;
    p->sh[j] = sh;
    p->d1[j] = (int32_t)(e1 >= 0 ? e1 >> sh : -((-e1) >> sh));
    p->d2[j] = (int32_t)(e2 >= 0 ? e2 >> sh : -((-e2) >> sh));
}

int32_t ras_fast_fill(struct ras_ctx *rc, const struct ras_sv *v0, const struct ras_sv *v1, const struct ras_sv *v2,
                      const struct ras_fast_tri *ft)
{
    const struct render_target *t = rc->t;
    int sb = rc->sub_bits;
    int64_t area = edge(v0->x, v0->y, v1->x, v1->y, v2->x, v2->y);
    if (area <= 0) return 0;

    int32_t minx = v0->x, maxx = v0->x, miny = v0->y, maxy = v0->y;
    const struct ras_sv *vv[3] = { v0, v1, v2 };
    for (int i = 1; i < 3; i++) {
        if (vv[i]->x < minx) minx = vv[i]->x;
        if (vv[i]->x > maxx) maxx = vv[i]->x;
        if (vv[i]->y < miny) miny = vv[i]->y;
        if (vv[i]->y > maxy) maxy = vv[i]->y;
    }
    int32_t c0 = minx >> sb, c1 = (maxx >> sb) + 1, r0 = miny >> sb, r1 = (maxy >> sb) + 1;
    if (c0 < 0) c0 = 0;
    if (r0 < (int32_t)t->y0) r0 = t->y0;
    if (c1 > (int32_t)rc->w - 1) c1 = rc->w - 1;
    if (r1 > (int32_t)t->y1 - 1) r1 = t->y1 - 1;
    if (c0 > c1 || r0 > r1) return 0;

    /* the exact path's edge functions at (c0, r0) and their steps */
    int64_t half = (int64_t)1 << (sb - 1), one = (int64_t)1 << sb;
    int64_t px = ((int64_t)c0 << sb) + half, py = ((int64_t)r0 << sb) + half;
    const struct ras_sv *ea[3] = { v1, v2, v0 }, *eb[3] = { v2, v0, v1 };
    int64_t wr[3], a[3], b[3];
    struct fedge fe[3];
    for (int i = 0; i < 3; i++) {
        int32_t dx = eb[i]->x - ea[i]->x, dy = eb[i]->y - ea[i]->y;
        int64_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : -1;
        wr[i] = edge(ea[i]->x, ea[i]->y, eb[i]->x, eb[i]->y, px, py);
        a[i] = -(int64_t)dy * one;
        b[i] = (int64_t)dx * one;
        fedge_init(&fe[i], a[i], b[i], wr[i], bias);
    }

    /* depth: exact at each span's first pixel, then the truncated gradient */
    int depth = rc->depth_bytes != 0;
    int64_t dd1 = (int64_t)v1->depth - v0->depth, dd2 = (int64_t)v2->depth - v0->depth;
    uint32_t dz = 0;
    if (depth) {
        int64_t k = dd1 * a[1] + dd2 * a[2];
        int64_t g = k / area;                 /* toward zero */
        if (g > INT32_MAX || g < -INT32_MAX) return -1;
        dz = (uint32_t)(int32_t)g;
    }

    /* attributes */
    struct fpersp pp;
    int na = 0, slog = rc->persp_log2;
    if (ft->kind != FT_FLAT) {
        int tt = 0;
        while ((area >> tt) >= ((int64_t)1 << 15)) tt++;
        pp.t = tt;
        pp.area_t = (uint32_t)(area >> tt);
        uint32_t dmax = v0->depth;
        if (v1->depth > dmax) dmax = v1->depth;
        if (v2->depth > dmax) dmax = v2->depth;
        int s = 0;
        while ((dmax >> s) >= (1u << 16)) s++;
        pp.dn[0] = v0->depth >> s;
        pp.dn[1] = v1->depth >> s;
        pp.dn[2] = v2->depth >> s;
        if (ft->kind == FT_TEX || ft->kind == FT_TEX_GOURAUD) {
            int32_t u[3], v[3];
            for (int i = 0; i < 3; i++) {
                u[i] = ras_num_to_fix(vv[i]->a[ft->ai_uv], ft->uscale);
                v[i] = ras_num_to_fix(vv[i]->a[ft->ai_uv + 1], ft->vscale);
            }
            persp_attr(&pp, na++, u[0], u[1], u[2]);
            persp_attr(&pp, na++, v[0], v[1], v[2]);
        }
        if (ft->kind == FT_GOURAUD || ft->kind == FT_TEX_GOURAUD) {
            int32_t li[3];
            for (int i = 0; i < 3; i++) {
                int32_t x = ras_num_to_fix(vv[i]->a[ft->ai_i], 1 << 20);
                li[i] = x < 0 ? 0 : (x > (8 << 20) - 1 ? (8 << 20) - 1 : x);
            }
            persp_attr(&pp, na++, li[0], li[1], li[2]);
        }
        pp.na = na;
    }
    int ai = ft->kind == FT_GOURAUD ? 0 : 2;   /* index of the intensity in the attribute list */

    int extra = t->rgb888 != NULL || t->written != NULL;
    span_fn fn = span_table[extra][ft->kind][rc->depth_bytes == 0 ? 0 : (rc->depth_bytes == 2 ? 1 : 2)];
    struct fspan sp;
    sp.ft = ft;
    sp.z = 0;
    sp.dz = dz;
    sp.u = sp.du = sp.v = sp.dv = sp.i = sp.di = 0;
    sp.rgb888 = sp.written = NULL;
    uint32_t total = 0;
    int32_t kmax = c1 - c0;

    for (int32_t r = r0; r <= r1; r++) {
        int64_t lo = 0, hi = kmax;
        int empty = 0;
        for (int i = 0; i < 3; i++) {
            if (fe[i].kind > 0) { if (fe[i].q > lo) lo = fe[i].q; }
            else if (fe[i].kind < 0) { if (fe[i].q < hi) hi = fe[i].q; }
            else if (fe[i].n < 0) empty = 1;
        }
        if (!empty && lo <= hi) {
            int32_t L = c0 + (int32_t)lo, R = c0 + (int32_t)hi;
            size_t idx = (size_t)(r - t->y0) * rc->w + (size_t)L;
            sp.px = t->rgb565 + idx;
            sp.zb = rc->depth + idx * rc->depth_bytes;
            if (extra) {
                sp.rgb888 = t->rgb888 ? t->rgb888 + 3 * idx : NULL;
                sp.written = t->written ? t->written + idx : NULL;
            }
            int64_t w1 = wr[1] + lo * a[1], w2 = wr[2] + lo * a[2];
            if (depth) {
                int64_t zr;
                int64_t zq = ras_floordiv(dd1 * w1 + dd2 * w2, area, &zr);
                int64_t d = (int64_t)v0->depth + zq + (zq < 0 && zr != 0);
                if (d < 0) d = 0;
                if (d > (int64_t)UINT32_MAX) d = UINT32_MAX;
                sp.z = (uint32_t)d;
            }
            int32_t n = R - L + 1;
            if (ft->kind == FT_FLAT) {
                total += fn(&sp, n);
            } else {
                int32_t cur[3], nxt[3];
                persp_at(&pp, w1, w2, cur);
                int32_t seg = (int32_t)1 << slog;
                while (n > 0) {
                    int32_t m = n > seg ? seg : n;   /* pixels drawn now */
                    int32_t steps;
                    if (n > seg) {
                        w1 += (int64_t)seg * a[1];
                        w2 += (int64_t)seg * a[2];
                        steps = seg;
                    } else {
                        w1 += (int64_t)(n - 1) * a[1];
                        w2 += (int64_t)(n - 1) * a[2];
                        steps = n - 1;
                    }
                    if (steps > 0) persp_at(&pp, w1, w2, nxt);
                    else for (int j = 0; j < na; j++) nxt[j] = cur[j];
                    int32_t dv[3];
                    for (int j = 0; j < na; j++) {
                        int64_t dlt = (int64_t)nxt[j] - cur[j];
                        dv[j] = steps == seg ? (int32_t)(dlt >= 0 ? dlt >> slog : -((-dlt) >> slog))
                                             : (steps > 0 ? (int32_t)(dlt / steps) : 0);
                    }
                    if (ft->kind != FT_GOURAUD) { sp.u = cur[0]; sp.du = dv[0]; sp.v = cur[1]; sp.dv = dv[1]; }
                    if (ft->kind == FT_GOURAUD || ft->kind == FT_TEX_GOURAUD) { sp.i = cur[ai]; sp.di = dv[ai]; }
                    total += fn(&sp, m);
                    sp.px += m;
                    sp.zb += (size_t)m * rc->depth_bytes;
                    sp.z += (uint32_t)m * dz;
                    if (sp.rgb888) sp.rgb888 += 3 * m;
                    if (sp.written) sp.written += m;
                    for (int j = 0; j < na; j++) cur[j] = nxt[j];
                    n -= m;
                }
            }
        }
        for (int i = 0; i < 3; i++) {
            wr[i] += b[i];
            fedge_next(&fe[i]);
        }
    }
    return (int32_t)total;
}
