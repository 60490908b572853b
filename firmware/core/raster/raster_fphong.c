/* SPDX-License-Identifier: MIT */
/* raster_fphong.c — fast Phong: the default path's Phong lighting
 * (ras_compute_illumination with the normal normalised, V = -P) per pixel
 * in 32-bit integers, for the span loops; the frame's lights in those
 * formats; the specular power as a table. */
#include "raster_fast.h"

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

uint32_t ras_fphong_light(const struct ras_fast_tri *ft, const int32_t *np)
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
