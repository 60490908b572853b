/* SPDX-License-Identifier: MIT */
/* test_span_bilinear.c — the fast path's bilinear texels (mipmap.c:
 * mip_fast_bilinear) and their blend (raster_span_lib.h: span_bilinear,
 * span_bl_565, span_bl_888) against a direct computation: texel centres
 * giving their texel, RGB565 levels rounded as rgb_to_565 rounds, blends
 * within one 8-bit step of the exact blend with the 4-bit weights, the
 * border clamping at the edges; the one-word texels of `bilinear_weights =
 * coarse` (mip_fast_bilinear_word, span_bilinear_word, span_bw_565,
 * span_bw_888): the RGB565 levels blended exactly with weights of 3 bits
 * across and 2 down, rounded. */
#include <stdio.h>
#include <stdlib.h>
#include "check.h"
#include "mipmap.h"
#include "raster/raster_span_lib.h"

static uint32_t lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

enum { W = 8, H = 4 };
static uint8_t img[W * H * 3];
static uint32_t tex[(W + 2) * (H + 2) * 2];
static const uint32_t ROW = (W + 2) * 2;
static uint32_t texw[(W + 2) * (H + 2)];

/* the span's coordinates of texture point (x, y) in texels, Q16 */
static uint32_t cu(int32_t q16) { return (uint32_t)q16 + 0x8800u; }

static uint32_t texel(int x, int y, int k)
{
    x = x < 0 ? 0 : (x > W - 1 ? W - 1 : x);
    y = y < 0 ? 0 : (y > H - 1 ? H - 1 : y);
    return img[3 * (y * W + x) + k];
}

int main(void)
{
    uint32_t s = 1, bad = 0;
    for (int i = 0; i < W * H * 3; i++) img[i] = (uint8_t)lcg(&s);
    img[0] = img[1] = img[2] = 255;     /* the extremes */
    img[3] = img[4] = img[5] = 0;
    check(mip_fast_bilinear_size(W, H) == sizeof tex, "texbl_size", "%zu", mip_fast_bilinear_size(W, H));
    mip_fast_bilinear(img, W, H, tex);

    /* centres give their texel: the levels rounded as rgb_to_565 rounds,
     * 8-bit channels within one step (R and B kept in 249 steps) */
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            uint32_t g, rb = span_bilinear(tex, cu(x * 65536 + 32768), cu(y * 65536 + 32768), ROW, &g);
            uint32_t c8 = span_bl_888(rb, g), want = texel(x, y, 0) << 16 | texel(x, y, 1) << 8 | texel(x, y, 2);
            uint32_t r5 = (texel(x, y, 0) * 62 + 255) / 510, g6 = (texel(x, y, 1) * 126 + 255) / 510,
                     b5 = (texel(x, y, 2) * 62 + 255) / 510;
            for (int k = 0; k < 3; k++) {
                int d = (int)((c8 >> (16 - 8 * k)) & 255u) - (int)((want >> (16 - 8 * k)) & 255u);
                bad += d > 1 || d < -1 || (k == 1 && d != 0);
            }
            bad += span_bl_565(rb, g) != (r5 << 11 | g6 << 5 | b5);
        }
    check(bad == 0, "bilinear_centres", "%u texels off", bad);

    /* anywhere (the edges' clamp included): within one 8-bit step of the
     * exact blend with the weights rounded to 16ths */
    bad = 0;
    for (int i = 0; i < 100000; i++) {
        int32_t u = (int32_t)(lcg(&s) % ((W << 16) + 1)), v = (int32_t)(lcg(&s) % ((H << 16) + 1));
        uint32_t g, rb = span_bilinear(tex, cu(u), cu(v), ROW, &g), c8 = span_bl_888(rb, g);
        int32_t us = u - 32768 + 2048, vs = v - 32768 + 2048;   /* centres at integers, rounded 16ths */
        int x = (int)((us + 65536) >> 16) - 1, y = (int)((vs + 65536) >> 16) - 1;
        double fx = (double)(((us + 65536) >> 12) & 15) / 16, fy = (double)(((vs + 65536) >> 12) & 15) / 16;
        for (int k = 0; k < 3; k++) {
            double top = texel(x, y, k) * (1 - fx) + texel(x + 1, y, k) * fx;
            double bot = texel(x, y + 1, k) * (1 - fx) + texel(x + 1, y + 1, k) * fx;
            double want = top * (1 - fy) + bot * fy, got = (c8 >> (16 - 8 * k)) & 255u;
            bad += got > want + 1.0 || got < want - 1.0;
        }
    }
    check(bad == 0, "bilinear_blend", "%u channels off by more than one step", bad);

    /* half way between texels (1,1) and (2,1): their mean */
    {
        uint32_t g, rb = span_bilinear(tex, cu(2 * 65536), cu(65536 + 32768), ROW, &g), c8 = span_bl_888(rb, g);
        for (int k = 0; k < 3; k++) {
            double want = (texel(1, 1, k) + texel(2, 1, k)) / 2.0, got = (c8 >> (16 - 8 * k)) & 255u;
            bad += got > want + 1.0 || got < want - 1.0;
        }
        check(bad == 0, "bilinear_half", "%06x", (unsigned)c8);
    }

    /* the corners of the texture (u, v = 0 or the side): the corner texels */
    {
        uint32_t g, rb = span_bilinear(tex, cu(0), cu(0), ROW, &g);
        check(span_bl_888(rb, g) == 0xFFFFFFu && span_bl_565(rb, g) == 0xFFFF, "bilinear_clamp_low", "%06x",
              (unsigned)span_bl_888(rb, g));
        rb = span_bilinear(tex, cu(W << 16), cu(H << 16), ROW, &g);
        uint32_t want = texel(W - 1, H - 1, 0) << 16 | texel(W - 1, H - 1, 1) << 8 | texel(W - 1, H - 1, 2);
        check(span_bl_888(rb, g) == want, "bilinear_clamp_high", "%06x, want %06x", (unsigned)span_bl_888(rb, g),
              (unsigned)want);
    }

    /* RGB565 levels: round(c * L / 255) for every 8-bit value */
    bad = 0;
    for (uint32_t c = 0; c < 256; c++) {
        uint16_t p = pack888_565(c << 16 | c << 8 | c);
        uint32_t r5 = (c * 31 * 2 + 255) / 510, g6 = (c * 63 * 2 + 255) / 510;
        bad += (uint32_t)(p >> 11) != r5 || (uint32_t)((p >> 5) & 63) != g6 || (uint32_t)(p & 31) != r5;
    }
    check(bad == 0, "pack888_565_levels", "%u values off", bad);

    /* one word a texel: each level the exact blend of the texels' RGB565
     * levels with the weights rounded to 8ths across and 4ths down,
     * rounded; the 8-bit channels within one step of the level's */
    check(mip_fast_bilinear_word_size(W, H) == sizeof texw, "texbw_size", "%zu", mip_fast_bilinear_word_size(W, H));
    mip_fast_bilinear_word(img, W, H, texw);
    bad = 0;
    for (int i = 0; i < 100000; i++) {
        int32_t u = (int32_t)(lcg(&s) % ((W << 16) + 1)), v = (int32_t)(lcg(&s) % ((H << 16) + 1));
        if (i == 0) u = v = 0;
        if (i == 1) u = W << 16, v = H << 16;
        uint32_t t = span_bilinear_word(texw, (uint32_t)u + SPAN_BW_U, (uint32_t)v + SPAN_BW_V, W + 2);
        uint16_t c = span_bw_565(t);
        uint32_t c8 = span_bw_888(t);
        int32_t us = u - 32768 + 4096, vs = v - 32768 + 8192;   /* centres at integers, rounded 8ths, 4ths */
        int x = (int)((us + 65536) >> 16) - 1, y = (int)((vs + 65536) >> 16) - 1;
        uint32_t fx = (uint32_t)((us + 65536) >> 13) & 7u, fy = (uint32_t)((vs + 65536) >> 14) & 3u;
        static const uint32_t L[3] = { 31, 63, 31 }, at[3] = { 11, 5, 0 };
        for (int k = 0; k < 3; k++) {
            uint32_t q[4];
            for (int j = 0; j < 4; j++) q[j] = (texel(x + (j & 1), y + (j >> 1), k) * L[k] * 2 + 255) / 510;
            uint32_t sum = ((q[0] * (8 - fx) + q[1] * fx) * (4 - fy) + (q[2] * (8 - fx) + q[3] * fx) * fy);
            uint32_t lv = (sum + 16) / 32, got = (c >> at[k]) & L[k];
            double want8 = sum * 255.0 / (L[k] * 32.0), got8 = (c8 >> (16 - 8 * k)) & 255u;
            bad += got != lv || got8 > want8 + 0.52 || got8 < want8 - 0.52;
        }
    }
    check(bad == 0, "bilinear_word_blend", "%u channels off", bad);
    return check_exit();
}
