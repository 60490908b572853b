/* SPDX-License-Identifier: MIT */
/* raster_texture.c — chapter 14: texel lookups, filtering, mipmaps. */
#include "raster_int.h"
#include "mipmap.h"

static num texel_chan(const uint8_t *img, int64_t idx, int ch)
{
    return num_from_int(img[idx * 3 + ch]);
}

/* The demos' addressing: linear index, no wrap or clamp; outside the array
 * the demos read NaN (stored as 0), reported through *nan. */
rgb ras_texel_book(const struct ras_texture *t, num u, num v, int *nan)
{
    int64_t size = (int64_t)t->w * t->h;
    rgb black = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    if (t->filter == TEX_BILINEAR_BOOK) {
        /* raster-13 as coded: indices toward zero, the fourth texel two rows
         * below the first, the red byte only */
        num us = num_sub(num_mul_int(u, t->w), NUM_HALF), vs = num_sub(num_mul_int(v, t->h), NUM_HALF);
        int32_t iu = num_to_int(us), iv = num_to_int(vs);
        num fu = num_sub(us, num_from_int(iu)), fv = num_sub(vs, num_from_int(iv));
        int64_t o00 = (int64_t)iv * t->w + iu, o10 = o00 + 1, o01 = o00 + t->w, o11 = o01 + t->w;
        if (o00 < 0 || o10 < 0 || o01 < 0 || o11 < 0 || o00 >= size || o10 >= size || o01 >= size ||
            o11 >= size) {
            *nan = 1;
            return black;
        }
        num ifu = num_sub(NUM_ONE, fu), ifv = num_sub(NUM_ONE, fv);
        num top = num_add(num_mul(texel_chan(t->rgb, o00, 0), ifu), num_mul(texel_chan(t->rgb, o10, 0), fu));
        num bot = num_add(num_mul(texel_chan(t->rgb, o01, 0), ifu), num_mul(texel_chan(t->rgb, o11, 0), fu));
        num r = num_add(num_mul(top, ifv), num_mul(bot, fv));
        return rgb_make(r, r, r);
    }
    int32_t iu = num_to_int(num_mul_int(u, t->w)), iv = num_to_int(num_mul_int(v, t->h));
    int64_t idx = (int64_t)iv * t->w + iu;
    if (idx < 0 || idx >= size) { *nan = 1; return black; }
    return rgb_make(texel_chan(t->rgb, idx, 0), texel_chan(t->rgb, idx, 1), texel_chan(t->rgb, idx, 2));
}

static int clampi(int32_t v, int32_t lo, int32_t hi) { return v < lo ? lo : (v > hi ? hi : v); }

static rgb fetch(const uint8_t *img, int w, int h, int32_t x, int32_t y)
{
    int64_t idx = (int64_t)clampi(y, 0, h - 1) * w + clampi(x, 0, w - 1);
    return rgb_make(texel_chan(img, idx, 0), texel_chan(img, idx, 1), texel_chan(img, idx, 2));
}

static rgb lerp_rgb(rgb a, rgb b, num f)
{
    return rgb_make(num_add(a.r, num_mul(num_sub(b.r, a.r), f)), num_add(a.g, num_mul(num_sub(b.g, a.g), f)),
                    num_add(a.b, num_mul(num_sub(b.b, a.b), f)));
}

/* Texel centres at (i + 1/2)/w; clamped at the edges. */
static rgb sample_level(const uint8_t *img, int w, int h, num u, num v, int bilinear)
{
    num us = num_mul_int(num_clamp(u, NUM_ZERO, NUM_ONE), w), vs = num_mul_int(num_clamp(v, NUM_ZERO, NUM_ONE), h);
    if (!bilinear) return fetch(img, w, h, num_floor_int(us), num_floor_int(vs));
    us = num_sub(us, NUM_HALF);
    vs = num_sub(vs, NUM_HALF);
    int32_t x = num_floor_int(us), y = num_floor_int(vs);
    num fx = num_frac(us), fy = num_frac(vs);
    rgb top = lerp_rgb(fetch(img, w, h, x, y), fetch(img, w, h, x + 1, y), fx);
    rgb bot = lerp_rgb(fetch(img, w, h, x, y + 1), fetch(img, w, h, x + 1, y + 1), fx);
    return lerp_rgb(top, bot, fy);
}

/* log2 for x > 0: exact integer part, linear in the octave (error < 0.09). */
num ras_log2(num x)
{
    if (x <= 0) return num_from_int(-64);
    int32_t e = 0;
    while (x >= NUM_C(2.0) && e < 64) { x = num_mul(x, NUM_HALF); e++; }
    while (x < NUM_ONE && e > -64) { x = num_add(x, x); e--; }
    return num_add(num_from_int(e), num_sub(x, NUM_ONE));
}

size_t ras_mips_size(const struct ras_texture *t)
{
    if (t->filter != TEX_TRILINEAR || t->mip_levels > 1) return 0;
    size_t n = 0;
    unsigned w = t->w, h = t->h;
    for (int l = 1; l < RAS_MIP_MAX && (w > 1 || h > 1); l++) {
        w = mip_side(w);
        h = mip_side(h);
        n += (size_t)w * h * 3;
    }
    return n;
}

/* The texture's own chain, or one built by mipmap.h's box filter into mem
 * (ras_mips_size bytes; level 0 is the image itself). */
void ras_mips_build(const struct ras_texture *t, struct ras_mips *m, uint8_t *mem)
{
    m->levels = 1;
    m->w[0] = t->w;
    m->h[0] = t->h;
    m->p[0] = t->rgb;
    if (t->mip_levels > 1 && t->mip) {
        for (int l = 1; l < t->mip_levels && l < RAS_MIP_MAX; l++) {
            m->w[l] = t->w >> l ? (uint16_t)(t->w >> l) : 1;
            m->h[l] = t->h >> l ? (uint16_t)(t->h >> l) : 1;
            m->p[l] = t->mip[l];
            m->levels++;
        }
        return;
    }
    if (!mem) return;
    for (int l = 1; l < RAS_MIP_MAX && (m->w[l - 1] > 1 || m->h[l - 1] > 1); l++) {
        unsigned pw = m->w[l - 1], ph = m->h[l - 1];
        mip_next(m->p[l - 1], pw, ph, mem);
        m->w[l] = (uint16_t)mip_side(pw);
        m->h[l] = (uint16_t)mip_side(ph);
        m->p[l] = mem;
        mem += (size_t)m->w[l] * m->h[l] * 3;
        m->levels++;
    }
}

rgb ras_sample(const struct ras_ctx *rc, int tex, num u, num v, num lod)
{
    const struct ras_texture *t = &rc->s->textures[tex];
    const struct ras_mips *m = &rc->def.mips[tex];
    if (t->filter == TEX_NEAREST) return sample_level(t->rgb, t->w, t->h, u, v, 0);
    if (t->filter != TEX_TRILINEAR || m->levels <= 1) return sample_level(t->rgb, t->w, t->h, u, v, 1);
    if (lod <= 0) return sample_level(m->p[0], m->w[0], m->h[0], u, v, 1);
    int32_t l = num_floor_int(lod);
    if (l >= m->levels - 1) {
        int k = m->levels - 1;
        return sample_level(m->p[k], m->w[k], m->h[k], u, v, 1);
    }
    rgb a = sample_level(m->p[l], m->w[l], m->h[l], u, v, 1);
    rgb b = sample_level(m->p[l + 1], m->w[l + 1], m->h[l + 1], u, v, 1);
    return lerp_rgb(a, b, num_frac(lod));
}
