/* SPDX-License-Identifier: MIT */
/* test_span_bilinear.c — the fast path's bilinear texel blend
 * (raster_span_lib.h: lerp888, span_bilinear, pack888_565) against a
 * direct computation: every channel's blend rounded as the formula says,
 * texel centres giving their texel, indices clamped at the edges, the
 * RGB565 levels rounded as rgb_to_565 rounds. */
#include <stdio.h>
#include "check.h"
#include "raster/raster_span_lib.h"

static uint32_t lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* one channel: round((a * (256 - f) + b * f) / 256) */
static uint32_t ref_lerp(uint32_t a, uint32_t b, uint32_t f)
{
    return (a * (256 - f) + b * f + 128) / 256;
}

static uint32_t chan(uint32_t t, int k) { return (t >> (16 - 8 * k)) & 255u; }

int main(void)
{
    uint32_t s = 1, bad = 0;
    for (int i = 0; i < 200000; i++) {
        uint32_t a = lcg(&s) & 0xFFFFFFu, b = lcg(&s) & 0xFFFFFFu, f = lcg(&s) & 255u, r = lerp888(a, b, f);
        for (int k = 0; k < 3; k++) bad += chan(r, k) != ref_lerp(chan(a, k), chan(b, k), f);
        bad += (r >> 24) != 0;
    }
    check(bad == 0, "lerp888_every_channel", "%u channels off", bad);

    /* a 4x4 texture: centres (integers in this coordinate) give their texel */
    uint32_t tex[16];
    for (int i = 0; i < 16; i++) tex[i] = lcg(&s) & 0xFFFFFFu;
    bad = 0;
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) bad += span_bilinear(tex, (uint32_t)x << 16, (uint32_t)y << 16, 2, 3, 3) != tex[y * 4 + x];
    check(bad == 0, "bilinear_centres", "%u texels off", bad);

    /* half way between texels (1,1) and (2,1): their rounded mean */
    uint32_t m = span_bilinear(tex, 0x18000u, 0x10000u, 2, 3, 3), want = 0;
    for (int k = 0; k < 3; k++) want |= ref_lerp(chan(tex[5], k), chan(tex[6], k), 128) << (16 - 8 * k);
    check(m == want, "bilinear_half", "%06x, want %06x", m, want);

    /* outside: indices clamped, as the exact path clamps u, v to [0, 1] */
    check(span_bilinear(tex, (uint32_t)-0x8000, (uint32_t)-0x8000, 2, 3, 3) == tex[0], "bilinear_clamp_low", "%06x",
          span_bilinear(tex, (uint32_t)-0x8000, (uint32_t)-0x8000, 2, 3, 3));
    check(span_bilinear(tex, 0x38000u, 0x38000u, 2, 3, 3) == tex[15], "bilinear_clamp_high", "%06x",
          span_bilinear(tex, 0x38000u, 0x38000u, 2, 3, 3));
    check(span_bilinear(tex, (uint32_t)-0x50000, 0x20000u, 2, 3, 3) == tex[8], "bilinear_clamp_far", "%06x",
          span_bilinear(tex, (uint32_t)-0x50000, 0x20000u, 2, 3, 3));
    /* along the right edge between rows 1 and 2: the edge column's blend */
    m = span_bilinear(tex, 0x38000u, 0x18000u, 2, 3, 3);
    want = 0;
    for (int k = 0; k < 3; k++) want |= ref_lerp(chan(tex[7], k), chan(tex[11], k), 128) << (16 - 8 * k);
    check(m == want, "bilinear_edge_column", "%06x, want %06x", m, want);

    /* RGB565 levels: round(c * L / 255) for every 8-bit value */
    bad = 0;
    for (uint32_t c = 0; c < 256; c++) {
        uint16_t p = pack888_565(c << 16 | c << 8 | c);
        uint32_t r5 = (c * 31 * 2 + 255) / 510, g6 = (c * 63 * 2 + 255) / 510;
        bad += (uint32_t)(p >> 11) != r5 || (uint32_t)((p >> 5) & 63) != g6 || (uint32_t)(p & 31) != r5;
    }
    check(bad == 0, "pack888_565_levels", "%u values off", bad);
    return check_exit();
}
