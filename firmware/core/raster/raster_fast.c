/* SPDX-License-Identifier: MIT */
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
#include "num/num_int.h"

#define FT_FLAT RAS_FT_FLAT
#define FT_GOURAUD RAS_FT_GOURAUD
#define FT_TEX RAS_FT_TEX
#define FT_TEX_GOURAUD RAS_FT_TEX_GOURAUD
#define FT_GOURAUD_SAT RAS_FT_GOURAUD_SAT
#define FT_PHONG RAS_FT_PHONG
#define FT_PHONG_TEX RAS_FT_PHONG_TEX

/* RGB565 of levels r, g, b, each clamped to its top level. */
static inline uint16_t pack565_sat(uint32_t r, uint32_t g, uint32_t b)
{
    if (r > 31) r = 31;
    if (g > 63) g = 63;
    if (b > 31) b = 31;
    return (uint16_t)(r << 11 | g << 5 | b);
}

static void ras_565_to_888(uint16_t c, uint8_t *o)
{
    uint32_t r = c >> 11, g = (c >> 5) & 63, b = c & 31;
    o[0] = (uint8_t)(r << 3 | r >> 2);
    o[1] = (uint8_t)(g << 2 | g >> 4);
    o[2] = (uint8_t)(b << 3 | b >> 2);
}

/* x / 2^n rounded toward minus infinity: >> on a negative int32_t, which
 * GCC and Clang define as the arithmetic shift on every target (the fixed-
 * point layer relies on the same); checked once below. */
static inline int32_t asr32(int32_t x, int n) { return x >> n; }
typedef char ras_asr_is_arithmetic[(-5 >> 1) == -3 ? 1 : -1];

/* 2^30 / (s * 64) at the middle of each of the 256 intervals of s in
 * [256, 512): round(2^30 / ((256 + i + 0.5) * 64)). */
static const uint16_t rcp_tab[256] = {
    65408, 65154, 64902, 64652, 64404, 64158, 63913, 63671, 63430, 63191, 62954, 62719,
    62485, 62253, 62023, 61795, 61568, 61343, 61119, 60897, 60677, 60458, 60241, 60026,
    59812, 59599, 59388, 59179, 58971, 58764, 58559, 58356, 58153, 57952, 57753, 57555,
    57358, 57163, 56968, 56776, 56584, 56394, 56205, 56017, 55831, 55646, 55462, 55279,
    55098, 54917, 54738, 54560, 54383, 54207, 54033, 53859, 53687, 53516, 53346, 53177,
    53009, 52842, 52676, 52511, 52347, 52184, 52022, 51862, 51702, 51543, 51385, 51228,
    51072, 50917, 50763, 50610, 50458, 50306, 50156, 50007, 49858, 49710, 49563, 49417,
    49272, 49128, 48985, 48842, 48700, 48559, 48419, 48280, 48141, 48003, 47867, 47730,
    47595, 47460, 47326, 47193, 47061, 46929, 46798, 46668, 46539, 46410, 46282, 46155,
    46028, 45902, 45777, 45652, 45528, 45405, 45283, 45161, 45040, 44919, 44799, 44680,
    44561, 44443, 44326, 44209, 44093, 43977, 43862, 43748, 43634, 43521, 43408, 43296,
    43185, 43074, 42963, 42854, 42744, 42636, 42528, 42420, 42313, 42207, 42101, 41996,
    41891, 41786, 41683, 41579, 41476, 41374, 41272, 41171, 41070, 40970, 40870, 40771,
    40672, 40574, 40476, 40378, 40281, 40185, 40089, 39993, 39898, 39804, 39709, 39616,
    39522, 39429, 39337, 39245, 39153, 39062, 38971, 38881, 38791, 38702, 38613, 38524,
    38436, 38348, 38260, 38173, 38087, 38000, 37915, 37829, 37744, 37659, 37575, 37491,
    37407, 37324, 37241, 37159, 37077, 36995, 36914, 36833, 36752, 36672, 36592, 36512,
    36433, 36354, 36275, 36197, 36119, 36041, 35964, 35887, 35810, 35734, 35658, 35583,
    35507, 35432, 35358, 35283, 35209, 35136, 35062, 34989, 34916, 34844, 34771, 34700,
    34628, 34557, 34486, 34415, 34344, 34274, 34204, 34135, 34065, 33996, 33928, 33859,
    33791, 33723, 33655, 33588, 33521, 33454, 33387, 33321, 33255, 33189, 33124, 33059,
    32994, 32929, 32864, 32800
};

/* floor-ish 2^30 / s for s in [2^14, 2^15), within 2 of the quotient: the
 * table's 9-bit estimate and one Newton step, all in 32 bits. */
static uint32_t rcp30(uint32_t s)
{
    int32_t r0 = rcp_tab[(s >> 6) - 256];
    int32_t e = (int32_t)((1u << 30) - s * (uint32_t)r0);   /* |e| <= 2^22 */
    return (uint32_t)(r0 + asr32(r0 * asr32(e, 7), 23));
}

/* Perspective-correct attributes at a pixel from its edge values. */
struct fpersp {               /* (the scalars first: small offsets for ARMv6-M loads) */
    int t;                   /* edge values >> t < 2^15 */
    int u;                   /* S >> u < 2^15 for every S of the triangle */
    int na;                  /* attributes (SPAN_NA of the kind) */
    uint32_t area_t;         /* area >> t */
    uint32_t dn[3];          /* near/z of the corners >> s, < 2^16 */
    struct {
        int32_t a0;          /* corner 0's value in the span format, |a0| < 2^30 */
        int32_t d1, d2;      /* (corner 1 - corner 0), (corner 2 - corner 0) >> sh: < 2^14 */
        int32_t sh;          /* <= 16 */
    } at[RAS_FAST_NA];       /* (per attribute: the first ones at small offsets) */
};

static inline void persp_at(const struct fpersp *p, int na, int32_t w1, int32_t w2, int32_t *out)
{
    uint32_t b1 = (uint32_t)w1 >> p->t, b2 = (uint32_t)w2 >> p->t;
    uint32_t b0 = p->area_t - b1 - b2;       /* >= (w0 >> t) >= 0 */
    uint32_t P1 = b1 * p->dn[1], P2 = b2 * p->dn[2];
    uint32_t S = b0 * p->dn[0] + P1 + P2;    /* <= area_t * 2^16 < 2^31 */
    int32_t q1 = 0, q2 = 0;
    /* S into [2^14, 2^15), the weights with it (P <= S): the triangle's
     * shift brings its largest S below 2^15, the rest is at most a few
     * doublings */
    S >>= p->u;
    if (S) {
        P1 >>= p->u;
        P2 >>= p->u;
        while (S < (1u << 14)) { S <<= 1; P1 <<= 1; P2 <<= 1; }
        uint32_t R = rcp30(S);
        q1 = (int32_t)((P1 * R) >> 14);      /* Q16; P*R <= 2^31 */
        q2 = (int32_t)((P2 * R) >> 14);
    }
    for (int j = 0; j < na; j++)
        out[j] = p->at[j].a0 + asr32(q1 * p->at[j].d1 + q2 * p->at[j].d2, 16 - p->at[j].sh);
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
    int sh = 0;
    while ((m >> sh) >= (1u << 14)) sh++;
    if (sh > 16) return 0;
    p->at[j].a0 = c0;
    p->at[j].sh = sh;
    p->at[j].d1 = e1 >= 0 ? e1 >> sh : -(int32_t)(m1 >> sh);
    p->at[j].d2 = e2 >= 0 ? e2 >> sh : -(int32_t)(m2 >> sh);
    return 1;
}

/* round(2^16 / k) for the last segment of a span, k = 1..32 */
static const uint32_t fast_inv_tab[33] = {
    0, 65536, 32768, 21845, 16384, 13107, 10923, 9362, 8192, 7282, 6554, 5958, 5461, 5041, 4681, 4369, 4096,
    3855, 3641, 3449, 3277, 3121, 2979, 2849, 2731, 2621, 2521, 2427, 2341, 2260, 2185, 2114, 2048,
};

/* ---- fast Phong: lighting per pixel in 32-bit integers ------------------- */

/* 2^15 / sqrt(M) at the middle of 96 intervals of M in [1, 4):
 * round(32768 / sqrt((32 + i + 0.5) / 32)). */
static const uint16_t rsq_tab[96] = {
    32515, 32026, 31558, 31111, 30682, 30270, 29874, 29494, 29127, 28774, 28434, 28105,
    27787, 27480, 27183, 26895, 26617, 26346, 26084, 25830, 25583, 25342, 25109, 24882,
    24660, 24445, 24235, 24031, 23831, 23637, 23447, 23262, 23080, 22904, 22731, 22562,
    22396, 22235, 22077, 21922, 21770, 21621, 21476, 21333, 21193, 21056, 20921, 20789,
    20660, 20533, 20408, 20285, 20165, 20047, 19930, 19816, 19704, 19594, 19485, 19378,
    19273, 19170, 19068, 18968, 18870, 18773, 18677, 18583, 18490, 18399, 18309, 18220,
    18133, 18047, 17962, 17878, 17795, 17714, 17634, 17554, 17476, 17399, 17323, 17248,
    17174, 17100, 17028, 16957, 16886, 16817, 16748, 16680, 16613, 16546, 16481, 16416
};

/* v scaled to unit length in Q14 (v's components below 2^15 in any one
 * format); a zero vector stays zero. Table and one Newton step: relative
 * error below 2^-13. */
static inline void unit3(int32_t v[3])
{
    uint32_t m = (uint32_t)(v[0] * v[0]) + (uint32_t)(v[1] * v[1]) + (uint32_t)(v[2] * v[2]);
    if (!m) return;
    /* m << k in [2^30, 2^32) with k even, found by halving steps (no CLZ
     * instruction on ARMv6-M) */
    int k = 0;
    if (m < (1u << 16)) { m <<= 16; k = 16; }
    if (m < (1u << 24)) { m <<= 8; k += 8; }
    if (m < (1u << 28)) { m <<= 4; k += 4; }
    if (m < (1u << 30)) { m <<= 2; k += 2; }
    uint32_t y = rsq_tab[(m >> 25) - 32];    /* 2^15 / sqrt(m / 2^30) */
    uint32_t x = ((m >> 16) * ((y * y) >> 15)) >> 14;
    y = (y * (3u * 32768u - x)) >> 16;
    /* v / sqrt(s) = v * y * 2^(k/2) / 2^30, in Q14 */
    int sh = 16 - (k >> 1);
    v[0] = asr32(v[0] * (int32_t)y, sh);
    v[1] = asr32(v[1] * (int32_t)y, sh);
    v[2] = asr32(v[2] * (int32_t)y, sh);
}

static inline int32_t dot14(const int32_t a[3], const int32_t b[3])
{
    return asr32(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], 14);
}

/* cos^e from the table at c (Q14, 0 < c <= 2^14). */
static inline int32_t spec_pow(const struct ras_fast_tri *ft, int32_t c)
{
    uint32_t u = (uint32_t)((1 << 14) - c);
    if (u >= ft->spec_umax) return 0;                      /* beyond the table: below e^-8 */
    uint32_t k = u * ft->spec_scale;                       /* Q16 index, < 2^24 */
    uint32_t i = k >> 16;
    int32_t a = ft->spec[i], b = ft->spec[i + 1];
    return a + asr32((b - a) * (int32_t)((k & 0xFFFFu) >> 2), 14);
}

/* Intensity in Q12 at a pixel with normal n (any length, Q14 scale) and
 * camera-space position p (Q(pq)): the default path's ras_compute_illumination
 * (normal normalised, V = -P) in integers. */
static uint32_t phong_light(const struct ras_fast_tri *ft, const int32_t *np)
{
    const struct ras_fphong *fp = ft->fp;
    int32_t n[3] = { np[0], np[1], np[2] }, v[3] = { -np[3], -np[4], -np[5] };
    unit3(n);
    unit3(v);
    /* R.V = 2 (N.L)(N.V) - L.V for R = 2 (N.L) N - L */
    const int32_t nv = dot14(n, v);
    int32_t i = fp->ambient;
    const int spec = fp->specular && ft->spec, diff = fp->diffuse;
    for (int k = 0; k < fp->nl; k++) {
        int32_t L[3];
        const int32_t *lv = fp->l[k].v;
        if (fp->l[k].type == LIGHT_DIRECTIONAL) {
            L[0] = lv[0]; L[1] = lv[1]; L[2] = lv[2];
        } else {
            L[0] = lv[0] - np[3]; L[1] = lv[1] - np[4]; L[2] = lv[2] - np[5];
            unit3(L);
        }
        int32_t nl = dot14(n, L);
        if (diff && nl > 0) i += asr32(fp->l[k].li * nl, 14);
        if (spec) {
            int32_t rv = asr32(2 * nl * nv, 14) - dot14(L, v);
            if (rv > 0) i += asr32(fp->l[k].li * spec_pow(ft, rv > (1 << 14) ? (1 << 14) : rv), 14);
        }
    }
    if (i < 0) i = 0;
    if (i > (8 << 14) - 1) i = (8 << 14) - 1;
    return (uint32_t)i >> 2;
}

void ras_spec_table(uint16_t t[257], uint32_t e, uint32_t step[2])
{
    /* the table spans 1 - cos in [0, w], w = min(1, 8/e): beyond it cos^e < e^-8 */
    uint32_t w16 = e > 8 ? (uint32_t)((8u << 16) / e) : (1u << 16);   /* w in Q16 */
    for (int k = 0; k <= 256; k++) {
        num c = num_sub(NUM_ONE, num_div_int(num_mul_int(num_from_ratio((int32_t)w16, 65536), k), 256));
        int32_t v = ras_num_to_fix(num_powi(c, e), 1 << 14);
        t[k] = (uint16_t)(v < 0 ? 0 : (v > (1 << 14) ? (1 << 14) : v));
    }
    /* index = (1 - cos) * 256 / w: Q16 index per Q14 unit */
    step[0] = (uint32_t)(((uint64_t)256 << 18) / w16);
    step[1] = (256u << 16) / step[0];
}

void ras_fphong_frame(struct ras_ctx *rc)
{
    struct ras_fphong *fp = &rc->fast.fp;
    const struct scene *s = rc->s;
    fp->ok = 0;
    /* the largest camera-space coordinate of the frame's vertices and point lights */
    num mx = NUM_ZERO;
    for (uint32_t k = 0; k < rc->nverts; k++) {
        vec3 c = rc->verts[k].c;
        mx = num_max(mx, num_max(num_abs(c.x), num_max(num_abs(c.y), num_abs(c.z))));
    }
    int nl = 0;
    fp->ambient = 0;
    for (uint16_t k = 0; k < s->nlights; k++) {
        const struct ras_light *l = &rc->lights[k];
        if (l->type == LIGHT_AMBIENT) { fp->ambient += ras_num_to_fix(l->intensity, 1 << 14); continue; }
        if (nl == RAS_FP_LIGHTS) return;
        if (l->type == LIGHT_POINT) mx = num_max(mx, num_max(num_abs(l->v.x), num_max(num_abs(l->v.y), num_abs(l->v.z))));
        nl++;
    }
    int pq = 0;
    while (pq < 24 && ras_num_to_fix(mx, (int32_t)1 << (pq + 1)) < (1 << 14)) pq++;
    if (ras_num_to_fix(mx, (int32_t)1 << pq) >= (1 << 14)) return;   /* beyond 2^14 units: exact Phong */
    fp->pq = (int8_t)pq;
    fp->nl = 0;
    for (uint16_t k = 0; k < s->nlights; k++) {
        const struct ras_light *l = &rc->lights[k];
        if (l->type == LIGHT_AMBIENT) continue;
        int j = fp->nl++;
        fp->l[j].type = l->type;
        int32_t li = ras_num_to_fix(l->intensity, 1 << 14);
        fp->l[j].li = li < 0 ? 0 : (li > (8 << 14) - 1 ? (8 << 14) - 1 : li);
        if (l->type == LIGHT_DIRECTIONAL) {
            vec3 d = v3_normalize(l->v);
            fp->l[j].v[0] = ras_num_to_fix(d.x, 1 << 14);
            fp->l[j].v[1] = ras_num_to_fix(d.y, 1 << 14);
            fp->l[j].v[2] = ras_num_to_fix(d.z, 1 << 14);
        } else {
            fp->l[j].v[0] = ras_num_to_fix(l->v.x, (int32_t)1 << pq);
            fp->l[j].v[1] = ras_num_to_fix(l->v.y, (int32_t)1 << pq);
            fp->l[j].v[2] = ras_num_to_fix(l->v.z, (int32_t)1 << pq);
        }
    }
    fp->diffuse = s->ras.diffuse;
    fp->specular = s->ras.specular;
    fp->ok = 1;
}

/* A triangle's constants for its row spans. */
struct ftri {
    const struct ras_fast_tri *ft;
    int32_t seg, slog;       /* segment length 2^slog */
    int32_t a1, a2;          /* per-column steps of edge values w1, w2 */
    int32_t sa1, sa2;        /* the same per segment */
    struct fpersp pp;
};

/* One row's span. */
struct frow {
    uint16_t *px;
    uint8_t *zb;
    uint8_t *rgb888, *written;   /* host outputs at the first pixel, or NULL */
    uint32_t z, dz;
    int32_t n;                   /* pixels */
    int32_t w1, w2;              /* edge values at the first pixel */
};

typedef uint32_t (*span_fn)(const struct ftri *T, const struct frow *R);


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

#define SPAN_NAME span_gsat_nz
#define SPAN_DEPTH 0
#define SPAN_KIND FT_GOURAUD_SAT
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_gsat_z16
#define SPAN_DEPTH 2
#define SPAN_KIND FT_GOURAUD_SAT
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_gsat_z32
#define SPAN_DEPTH 4
#define SPAN_KIND FT_GOURAUD_SAT
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_gsat_nz_x
#define SPAN_DEPTH 0
#define SPAN_KIND FT_GOURAUD_SAT
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_gsat_z16_x
#define SPAN_DEPTH 2
#define SPAN_KIND FT_GOURAUD_SAT
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_gsat_z32_x
#define SPAN_DEPTH 4
#define SPAN_KIND FT_GOURAUD_SAT
#define SPAN_EXTRA 1
#include "raster_span.h"

#define SPAN_NAME span_phong_nz
#define SPAN_DEPTH 0
#define SPAN_KIND FT_PHONG
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_phong_z16
#define SPAN_DEPTH 2
#define SPAN_KIND FT_PHONG
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_phong_z32
#define SPAN_DEPTH 4
#define SPAN_KIND FT_PHONG
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_phong_nz_x
#define SPAN_DEPTH 0
#define SPAN_KIND FT_PHONG
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_phong_z16_x
#define SPAN_DEPTH 2
#define SPAN_KIND FT_PHONG
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_phong_z32_x
#define SPAN_DEPTH 4
#define SPAN_KIND FT_PHONG
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_phongt_nz
#define SPAN_DEPTH 0
#define SPAN_KIND FT_PHONG_TEX
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_phongt_z16
#define SPAN_DEPTH 2
#define SPAN_KIND FT_PHONG_TEX
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_phongt_z32
#define SPAN_DEPTH 4
#define SPAN_KIND FT_PHONG_TEX
#define SPAN_EXTRA 0
#include "raster_span.h"
#define SPAN_NAME span_phongt_nz_x
#define SPAN_DEPTH 0
#define SPAN_KIND FT_PHONG_TEX
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_phongt_z16_x
#define SPAN_DEPTH 2
#define SPAN_KIND FT_PHONG_TEX
#define SPAN_EXTRA 1
#include "raster_span.h"
#define SPAN_NAME span_phongt_z32_x
#define SPAN_DEPTH 4
#define SPAN_KIND FT_PHONG_TEX
#define SPAN_EXTRA 1
#include "raster_span.h"

/* [extra][kind][depth 0/2/4 -> 0/1/2] */
static const span_fn span_table[2][7][3] = {
    { { span_flat_nz, span_flat_z16, span_flat_z32 },
      { span_gour_nz, span_gour_z16, span_gour_z32 },
      { span_tex_nz, span_tex_z16, span_tex_z32 },
      { span_texg_nz, span_texg_z16, span_texg_z32 },
      { span_gsat_nz, span_gsat_z16, span_gsat_z32 },
      { span_phong_nz, span_phong_z16, span_phong_z32 },
      { span_phongt_nz, span_phongt_z16, span_phongt_z32 } },
    { { span_flat_nz_x, span_flat_z16_x, span_flat_z32_x },
      { span_gour_nz_x, span_gour_z16_x, span_gour_z32_x },
      { span_tex_nz_x, span_tex_z16_x, span_tex_z32_x },
      { span_texg_nz_x, span_texg_z16_x, span_texg_z32_x },
      { span_gsat_nz_x, span_gsat_z16_x, span_gsat_z32_x },
      { span_phong_nz_x, span_phong_z16_x, span_phong_z32_x },
      { span_phongt_nz_x, span_phongt_z16_x, span_phongt_z32_x } },
};

/* ---- set-up -------------------------------------------------------------- */


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
 * ras_fast_state is this, opaque to the rest of the rasterizer). */
struct fstate {
    struct ras_fast_tri ftc;     /* the triangle's description (T.ft points here) */
    struct ftri T;
    struct fedge fe[3];
    int32_t wr[3], a[3], b[3];   /* edge values at (c0, row), steps per column and row */
    int64_t zrow, gy16;          /* depth plane at (c0, row), Q32.16 */
    int32_t gxq;                 /* column gradient gxq * 2^16 + gxf */
    uint32_t gxf, dz;
    int32_t c0, kmax, row, last; /* box column, width - 1, next row, last row */
    int kind, depth;
};
typedef char ras_fast_state_fits[sizeof(struct fstate) <= sizeof(struct ras_fast_state) ? 1 : -1];

/* Set-up of triangle v0 v1 v2 for rows from the strip's first on.
 * Returns 1, 0 (nothing to draw) or -1 (the exact path's triangle). */
static int fast_setup(struct ras_ctx *rc, const struct ras_sv *v0, const struct ras_sv *v1, const struct ras_sv *v2,
                      const struct ras_fast_tri *ft, struct fstate *S)
{
    const struct render_target *t = rc->cur.t;
    int sb = rc->def.sub_bits;
    int64_t area64 = ras_edge(v0->x, v0->y, v1->x, v1->y, v2->x, v2->y);
    if (area64 <= 0) return 0;

    int32_t box[4];
    ras_sub_box(v0, v1, v2, box);
    const int32_t minx = box[0], miny = box[1], maxx = box[2], maxy = box[3];
    const struct ras_sv *vv[3] = { v0, v1, v2 };
    /* 32-bit edge arithmetic: corners within 2^14 sub-pixel units of each
     * other (1024 pixels at 4 sub-pixel bits); larger ones take the exact path */
    if ((int64_t)maxx - minx > (1 << 14) || (int64_t)maxy - miny > (1 << 14)) return -1;
    int32_t c0 = minx >> sb, c1 = (maxx >> sb) + 1, rtop = miny >> sb, r0 = rtop, r1 = (maxy >> sb) + 1;
    if (c0 < 0) c0 = 0;
    if (r0 < (int32_t)t->y0) r0 = t->y0;
    if (c1 > (int32_t)rc->w - 1) c1 = rc->w - 1;
    if (r1 > (int32_t)rc->h - 1) r1 = rc->h - 1;
    if (c0 > c1 || r0 > r1 || r0 >= (int32_t)t->y1) return 0;

    /* the exact path's edge functions at (c0, r0) and their steps; every
     * value inside the box is below 2^29 in magnitude */
    int32_t half = (int32_t)1 << (sb - 1), one = (int32_t)1 << sb;
    int64_t px = ((int64_t)c0 << sb) + half, py = ((int64_t)r0 << sb) + half;
    const struct ras_sv *ea[3] = { v1, v2, v0 }, *eb[3] = { v2, v0, v1 };
    int32_t *wr = S->wr, *a = S->a, *b = S->b;
    struct fedge *fe = S->fe;
    for (int i = 0; i < 3; i++) {
        int32_t dx = eb[i]->x - ea[i]->x, dy = eb[i]->y - ea[i]->y;
        int32_t bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : -1;
        wr[i] = (int32_t)ras_edge(ea[i]->x, ea[i]->y, eb[i]->x, eb[i]->y, px, py);
        a[i] = -dy * one;
        b[i] = dx * one;
        fedge_init(&fe[i], a[i], b[i], wr[i], bias);
    }
    int32_t area = (int32_t)area64;

    /* depth: a plane in Q32.16 (exact at (c0, the box's top row), gradients
     * to 2^-16, stepped row by row from there whatever the strips), stepped
     * per pixel by the column gradient truncated toward zero */
    int depth = rc->depth_bytes != 0;
    int64_t zrow = 0, gy16 = 0;
    int32_t gxq = 0;
    uint32_t gxf = 0;
    uint32_t dz = 0;
    if (depth) {
        int64_t dd1 = (int64_t)v1->depth - v0->depth, dd2 = (int64_t)v2->depth - v0->depth, rem, f;
        /* edge values at (c0, the box's top row): linear in the row */
        int64_t w1t = wr[1] - (int64_t)(r0 - rtop) * b[1], w2t = wr[2] - (int64_t)(r0 - rtop) * b[2];
        int64_t q = ras_floordiv(dd1 * w1t + dd2 * w2t, area, &rem);
        zrow = ((int64_t)v0->depth + q) * 65536 + ras_floordiv(rem << 16, area, &f);
        q = ras_floordiv(dd1 * a[1] + dd2 * a[2], area, &rem);
        if (q > INT32_MAX || q < -INT32_MAX) return -1;
        gxq = (int32_t)q;
        gxf = (uint32_t)ras_floordiv(rem << 16, area, &f);
        dz = (uint32_t)(int32_t)(q + (q < 0 && rem != 0));      /* toward zero */
        q = ras_floordiv(dd1 * b[1] + dd2 * b[2], area, &rem);
        if (q > INT32_MAX || q < -INT32_MAX) return -1;
        gy16 = q * 65536 + ras_floordiv(rem << 16, area, &f);
        zrow += gy16 * (r0 - rtop);
    }

    /* attributes */
    int kind = ft->kind;
    S->ftc = *ft;
    ft = &S->ftc;
    struct ftri *Tp = &S->T;
    struct fpersp *pp = &Tp->pp;
    int na = 0;
    Tp->ft = ft;
    Tp->slog = rc->fast.persp_log2;
    Tp->seg = (int32_t)1 << Tp->slog;
    Tp->a1 = a[1];
    Tp->a2 = a[2];
    Tp->sa1 = a[1] * Tp->seg;
    Tp->sa2 = a[2] * Tp->seg;
    pp->na = 0;
    if (ft->kind != FT_FLAT) {
        int tt = 0;
        while ((area >> tt) >= (1 << 15)) tt++;
        pp->t = tt;
        pp->area_t = (uint32_t)(area >> tt);
        uint32_t dmax = v0->depth;
        if (v1->depth > dmax) dmax = v1->depth;
        if (v2->depth > dmax) dmax = v2->depth;
        int s = 0;
        while ((dmax >> s) >= (1u << 16)) s++;
        pp->dn[0] = v0->depth >> s;
        pp->dn[1] = v1->depth >> s;
        pp->dn[2] = v2->depth >> s;
        uint32_t dnmax = pp->dn[0] > pp->dn[1] ? pp->dn[0] : pp->dn[1];
        if (pp->dn[2] > dnmax) dnmax = pp->dn[2];
        uint32_t smax = pp->area_t * dnmax;  /* < 2^31 */
        pp->u = 0;
        while ((smax >> pp->u) >= (1u << 15)) pp->u++;
        if (ft->kind == FT_PHONG || ft->kind == FT_PHONG_TEX) {
            /* normal (Q14) and camera-space position (Q(pq)) */
            for (int c = 0; c < 6; c++) {
                int slot = c < 3 ? ft->ai_n + c : ft->ai_p + c - 3;
                int32_t sc = c < 3 ? 1 << 14 : (int32_t)1 << ft->fp->pq, x[3];
                for (int i = 0; i < 3; i++) x[i] = ras_num_to_fix(vv[i]->a[slot], sc);
                if (!persp_attr(pp, na++, x[0], x[1], x[2])) return -1;
            }
        }
        if (ft->kind == FT_TEX || ft->kind == FT_TEX_GOURAUD || ft->kind == FT_PHONG_TEX) {
            int32_t u[3], v[3];
            for (int i = 0; i < 3; i++) {
                u[i] = ras_num_to_fix(vv[i]->a[ft->ai_uv], ft->uscale);
                v[i] = ras_num_to_fix(vv[i]->a[ft->ai_uv + 1], ft->vscale);
            }
            if (!persp_attr(pp, na++, u[0], u[1], u[2]) || !persp_attr(pp, na++, v[0], v[1], v[2])) return -1;
        }
        if (ft->kind == FT_GOURAUD || ft->kind == FT_TEX_GOURAUD) {
            int32_t li[3], imax = 0;
            for (int i = 0; i < 3; i++) {
                int32_t x = ras_num_to_fix(vv[i]->a[ft->ai_i], 1 << 20);
                li[i] = x < 0 ? 0 : (x > (8 << 20) - 1 ? (8 << 20) - 1 : x);
                if (li[i] > imax) imax = li[i];
            }
            if (ft->kind == FT_GOURAUD) {
                /* the channels' levels interpolated when none can reach its
                 * top level + 1/2 (colour Q10 x intensity Q12, a margin of
                 * 2^-6 level); the intensity and a clamp per pixel otherwise */
                uint32_t i12 = (uint32_t)(imax >> 8) + 1;
                if (ft->kr * i12 < (31u << 22) + (1u << 21) - (1u << 16) &&
                    ft->kg * i12 < (63u << 22) + (1u << 21) - (1u << 16) &&
                    ft->kb * i12 < (31u << 22) + (1u << 21) - (1u << 16)) {
                    const uint32_t kc[3] = { ft->kr, ft->kg, ft->kb };
                    for (int c = 0; c < 3; c++) {
                        int32_t l[3];
                        for (int i = 0; i < 3; i++)   /* level in Q16 + 1/2: Q10 x Q12 >> 6 */
                            l[i] = (int32_t)((kc[c] * ((uint32_t)li[i] >> 8) + (1u << 5)) >> 6) + (1 << 15);
                        if (!persp_attr(pp, na++, l[0], l[1], l[2])) return -1;
                    }
                } else {
                    kind = FT_GOURAUD_SAT;
                }
            }
            if (kind != FT_GOURAUD && !persp_attr(pp, na++, li[0], li[1], li[2])) return -1;
        }
        pp->na = na;
    }

    S->zrow = zrow;
    S->gy16 = gy16;
    S->gxq = gxq;
    S->gxf = gxf;
    S->dz = dz;
    S->c0 = c0;
    S->kmax = c1 - c0;
    S->row = r0;
    S->last = r1;
    S->kind = kind;
    S->depth = depth;
    return 1;
}

/* Rows of S from S->row to the strip's end (or the triangle's last row),
 * S left at the next row. Returns the pixels written (host outputs) or
 * drawn (board). */
static uint32_t fast_run(struct ras_ctx *rc, struct fstate *S)
{
    const struct render_target *t = rc->cur.t;
    const struct ftri *Tp = &S->T;
    struct fedge *fe = S->fe;
    int32_t *wr = S->wr, *a = S->a, *b = S->b;
    int64_t zrow = S->zrow;
    const int64_t gy16 = S->gy16;
    const int32_t gxq = S->gxq, c0 = S->c0, kmax = S->kmax;
    const uint32_t gxf = S->gxf, dz = S->dz;
    const int depth = S->depth;
    int32_t r0 = S->row, r1 = S->last < (int32_t)t->y1 - 1 ? S->last : (int32_t)t->y1 - 1;
    int extra = t->rgb888 != NULL || t->written != NULL;
    span_fn fn = span_table[extra][S->kind][rc->depth_bytes == 0 ? 0 : (rc->depth_bytes == 2 ? 1 : 2)];
    struct frow R;
    R.z = 0;
    R.dz = dz;
    R.rgb888 = R.written = NULL;
    R.w1 = R.w2 = 0;
    uint32_t total = 0;

    for (int32_t r = r0; r <= r1; r++) {
        int32_t lo = 0, hi = kmax;
        int empty = 0;
        for (int i = 0; i < 3; i++) {
            if (fe[i].kind > 0) { if (fe[i].q > lo) lo = fe[i].q; }
            else if (fe[i].kind < 0) { if (fe[i].q < hi) hi = fe[i].q; }
            else if (fe[i].n < 0) empty = 1;
        }
        if (!empty && lo <= hi) {
            int32_t L = c0 + lo;
            size_t idx = (size_t)(r - t->y0) * rc->w + (size_t)L;
            R.n = hi - lo + 1;
            R.px = t->rgb565 + idx;
            R.zb = rc->depth + idx * rc->depth_bytes;
            if (extra) {
                R.rgb888 = t->rgb888 ? t->rgb888 + 3 * idx : NULL;
                R.written = t->written ? t->written + idx : NULL;
            }
            if (depth) {
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
            if (S->kind != FT_FLAT) {
                R.w1 = wr[1] + lo * a[1];
                R.w2 = wr[2] + lo * a[2];
            }
            uint32_t wrote = fn(Tp, &R);
            total += extra ? wrote : (uint32_t)R.n;
        }
        zrow += gy16;
        for (int i = 0; i < 3; i++) {
            wr[i] += b[i];
            struct fedge *e = &fe[i];
            if (e->kind == 0) { e->n += e->dq; continue; }
            e->q += e->dq;
            e->r += e->dr;
            if (e->r >= e->den) { e->q++; e->r -= e->den; }
        }
    }
    S->zrow = zrow;
    S->row = r1 + 1;
    return total;
}

int32_t ras_fast_fill(struct ras_ctx *rc, const struct ras_sv *v0, const struct ras_sv *v1, const struct ras_sv *v2,
                      const struct ras_fast_tri *ft, struct ras_fast_state *keep)
{
    struct fstate local, *S = keep ? (struct fstate *)(void *)keep : &local;
    int r = fast_setup(rc, v0, v1, v2, ft, S);
    if (r <= 0) {
        if (keep) S->row = -1;
        return r;
    }
    return (int32_t)fast_run(rc, S);
}

int ras_fast_resume(struct ras_ctx *rc, struct ras_fast_state *keep, uint32_t *drawn)
{
    struct fstate *S = (struct fstate *)(void *)keep;
    if (S->row != (int32_t)rc->cur.t->y0 || S->row > S->last) return 0;
    *drawn = fast_run(rc, S);
    return 1;
}
