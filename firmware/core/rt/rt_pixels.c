/* SPDX-License-Identifier: MIT */
/* rt_pixels.c — the main loop (chapter 2) by strips of rows: plain pixels,
 * chapter 5's supersampling (fixed and adaptive) and subsampling along
 * rows, the coarse pass of the progressive preview; rt_render_strip. */
#include "rt_int.h"
#include "rt_num.h"

/* Adaptive supersampling refines a pixel whose centre sample differs from
 * its left or upper neighbour in object or by more than this per channel. */
#define RT_ADAPTIVE_DIFF NUM_C(12.0)

/* row_item of a supersampled pixel (not a single sample's item; subsampling
 * never interpolates across it): whether any of its rays hit an object. */
#define RT_ITEM_SS_NONE (-2)
#define RT_ITEM_SS_HIT  (-3)

/* An item note says the pixel shows an object (not only the background). */
static int item_covers(int16_t item) { return item >= 0 || item == RT_ITEM_SS_HIT; }

void rt_put(struct rt_state *rt, struct render_target *t, int x, int y, rgb c, int covered)
{
    render_put(t, x, y, c);
    if (t->written) t->written[(size_t)(y - t->y0) * t->width + (size_t)x] = (uint8_t)(covered != 0);
    rt->n.covered += covered != 0;
}

int rt_colours_differ(rgb a, rgb b, num diff)
{
    return num_abs(num_sub(a.r, b.r)) > diff || num_abs(num_sub(a.g, b.g)) > diff ||
           num_abs(num_sub(a.b, b.b)) > diff;
}

/* n x n rays on a regular grid inside the pixel, averaged; *hit set when
 * one of them hit an object. */
static rgb supersample(struct rt_state *rt, num x, num y, int n, int *hit)
{
    rgb sum = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    *hit = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            num ox = num_from_ratio(2 * i + 1 - n, 2 * n);
            num oy = num_from_ratio(2 * j + 1 - n, 2 * n);
            struct rt_prim pr;
            sum = rgb_add(sum, rt_trace_canvas(rt, num_add(x, ox), num_add(y, oy), &pr));
            if (pr.item >= 0) *hit = 1;
        }
    return rgb_scale(sum, num_from_ratio(1, n * n));
}

/* The canvas point of pixel (col, row), for its sub-pixel samples (a
 * plain pixel takes its direction from the tables). */
static num canvas_x(const struct rt_state *rt, int col) { return num_from_int(col - rt->w / 2); }
static num canvas_y(const struct rt_state *rt, int row) { return num_from_int(rt->h / 2 - 1 - row); }

/* One pixel: plain, fixed supersampling, or adaptive (refine edges only).
 * The centre sample's colour and object are kept in the row notes (a
 * supersampled pixel's object as RT_ITEM_SS_*), and rt->px_covered says
 * whether the pixel shows an object. */
static rgb pixel(struct rt_state *rt, int col, int row, int have_left, int have_up, uint8_t *probe)
{
    if (rt->ss > 1 && !rt->ss_adaptive) {
        int hit;
        rgb c = supersample(rt, canvas_x(rt, col), canvas_y(rt, row), rt->ss, &hit);
        rt->row_item[col] = hit ? RT_ITEM_SS_HIT : RT_ITEM_SS_NONE;
        rt->px_covered = (uint8_t)hit;
        return c;
    }
    struct rt_prim pr;
    rgb c = rt_trace_pixel(rt, col, row, &pr);
    rt->px_covered = pr.item >= 0;
    if (probe) *probe = pr.item < 0 ? 0x80 : pr.shadow;
    if (rt->item_probe) rt->item_probe[(size_t)row * rt->w + col] = pr.item;
    if (rt->ss_adaptive) {
        int n = rt->ss > 1 ? rt->ss : 2;
        int edge = 0;
        if (have_left && col > 0 && (rt->row_item[col - 1] != pr.item || rt_colours_differ(rt->row_c[col - 1], c, RT_ADAPTIVE_DIFF))) edge = 1;
        if (have_up && (rt->row_item[col] != pr.item || rt_colours_differ(rt->row_c[col], c, RT_ADAPTIVE_DIFF))) edge = 1;
        /* the row notes hold the centre samples: the left one is already this
         * row's, the one at col still the row above's until written here */
        rt->row_item[col] = pr.item;
        rt->row_c[col] = c;
        if (edge) {
            int hit;
            c = supersample(rt, canvas_x(rt, col), canvas_y(rt, row), n, &hit);
            rt->px_covered = (uint8_t)hit;
        }
        return c;
    }
    /* the notes a subsampled row decides by (nothing else reads a plain
     * pixel's) */
    if (rt->subsample > 1) {
        rt->row_item[col] = pr.item;
        rt->row_c[col] = c;
    }
    return c;
}

/* Subsampling (chapter 5): trace every k-th column and the last; a pixel in
 * between whose two traced neighbours hit the same object takes their
 * linear interpolation, otherwise it is traced too. */
static void subsampled_row(struct rt_state *rt, struct render_target *t, int row, uint8_t *probe)
{
    int w = rt->w, k = rt->subsample;
    int col = 0;
    for (;;) {
        rt->row_c[col] = pixel(rt, col, row, 0, 0, probe ? probe + col : NULL);
        if (col == w - 1) break;
        col = col + k < w ? col + k : w - 1;
    }
    for (int a = 0; a < w - 1;) {
        int b = a + k < w ? a + k : w - 1;
        int same = rt->row_item[a] == rt->row_item[b] && rt->row_item[a] >= -1;
        for (int x = a + 1; x < b; x++) {
            if (same) {
                num wgt = num_from_ratio(x - a, b - a);
                rgb c = rgb_add(rgb_scale(rt->row_c[a], num_sub(NUM_ONE, wgt)), rgb_scale(rt->row_c[b], wgt));
                rt_put(rt, t, x, row, c, rt->row_item[a] >= 0);
                if (probe) probe[x] = 0xFF;   /* not traced */
            } else {
                rgb c = pixel(rt, x, row, 0, 0, probe ? probe + x : NULL);
                rt_put(rt, t, x, row, c, rt->px_covered);
            }
        }
        rt_put(rt, t, a, row, rt->row_c[a], item_covers(rt->row_item[a]));
        a = b;
    }
    rt_put(rt, t, w - 1, row, rt->row_c[w - 1], item_covers(rt->row_item[w - 1]));
}

/* RENDER_PASS_COARSE: one ray per block, at the block's centre pixel. */
static void coarse_strip(struct rt_state *rt, struct render_target *t)
{
    const int b = RENDER_COARSE_BLOCK;
    for (int r0 = t->y0 - t->y0 % b; r0 < t->y1; r0 += b) {
        int r1 = r0 + b < rt->h ? r0 + b : rt->h;
        for (int c0 = 0; c0 < rt->w; c0 += b) {
            int c1 = c0 + b < rt->w ? c0 + b : rt->w;
            struct rt_sample sm;
            rt_sample_pixel(rt, (c0 + c1 - 1) / 2, (r0 + r1 - 1) / 2, &sm);
            rgb c = sm.c;
            int covered = sm.item >= 0;
            uint16_t v = rgb_to_565(c);
            for (int y = r0 > t->y0 ? r0 : t->y0; y < r1 && y < t->y1; y++) {
                if (t->rgb888 || t->written) {
                    for (int x = c0; x < c1; x++) rt_put(rt, t, x, y, c, covered);
                    continue;
                }
                uint16_t *row = t->rgb565 + (size_t)(y - t->y0) * t->width;
                for (int x = c0; x < c1; x++) row[x] = v;   /* the block's one colour */
                if (covered) rt->n.covered += (uint32_t)(c1 - c0);
            }
        }
    }
}

/* The plain pixels after col of a background run (rt_state.bg_*) that
 * covers col in row row (px: the row's RGB565 pixels), written as the
 * background without their rays
 * (which rt_trace_pixel would answer so; counted as it counts them); the
 * last column written, or col. */
static int background_run(struct rt_state *rt, uint16_t *px, int col, int row)
{
    if (rt->bg_row != row || col < rt->bg_lo || col >= rt->bg_hi) return col;
    int last = rt->bg_hi < rt->w - 1 ? rt->bg_hi : rt->w - 1;
    uint16_t v = rgb_to_565(rt->s->background);
    for (int x = col + 1; x <= last; x++) px[x] = v;
    uint32_t k = (uint32_t)(last - col);
    rt->n.rays += k;
    rt->n.primary_rays += k;
    rt->n.tests += k * rt->bg_tests;
    return last;
}

/* Every pixel of the strip (plain, supersampled, or the book's subsampling). */
static void full_strip(struct rt_state *rt, struct render_target *t)
{
    /* plain pixels whose runs of background need nothing but the colour */
    int runs = rt->ss <= 1 && !rt->ss_adaptive && rt->subsample <= 1 && !rt->round && !rt->shadow_probe && !rt->item_probe &&
               !t->rgb888 && !t->written;
    for (int row = t->y0; row < t->y1; row++) {
        uint8_t *probe = rt->shadow_probe ? rt->shadow_probe + (size_t)row * rt->w : NULL;
        if (rt->subsample > 1 && rt->w > 1) {
            subsampled_row(rt, t, row, probe);
            rt->last_row = -2;
            continue;
        }
        /* adaptive supersampling compares with the row above when that was
         * the last row rendered (also across strips) */
        int have_up = row == rt->last_row + 1;
        /* a round glass: plain pixels outside its circle are not traced */
        int32_t d = rt->w < rt->h ? rt->w : rt->h, dy = 2 * row + 1 - rt->h;
        int skip = rt->round && rt->ss <= 1;
        /* the row's RGB565 pixels and its covered count for the plain
         * pixels' loop, once a row */
        uint16_t *px = runs ? t->rgb565 + (size_t)(row - t->y0) * t->width : NULL;
        uint32_t covered = 0;
        for (int col = 0; col < rt->w; col++) {
            int32_t dx = 2 * col + 1 - rt->w;
            if (skip && dx * dx + dy * dy > d * d) {
                rt_put(rt, t, col, row, rt->s->background, 0);
                continue;
            }
            if (runs) {
                /* pixel()'s and rt_put's work for a plain pixel and the
                 * RGB565 output alone, without their calls */
                struct rt_prim pr;
                rgb c = rt_trace_pixel(rt, col, row, &pr);
                px[col] = rgb_to_565(c);
                covered += pr.item >= 0;
                col = background_run(rt, px, col, row);
                continue;
            }
            rgb c = pixel(rt, col, row, 1, have_up, probe ? probe + col : NULL);
            rt_put(rt, t, col, row, c, rt->px_covered);
        }
        rt->n.covered += covered;
        rt->last_row = row;
    }
}

void rt_set_pass(void *work, uint8_t pass)
{
    rt_state_of(work)->pass = pass;
}

void rt_set_round(void *work, uint8_t on)
{
    rt_state_of(work)->round = on != 0;
}

int rt_render_strip(void *work, struct render_target *t, struct render_stats *st)
{
    struct rt_state *rt = rt_state_of(work);
    uint32_t rays0 = rt->n.rays, covered0 = rt->n.covered;
    if (rt->pass == RENDER_PASS_COARSE) coarse_strip(rt, t);
    else if (rt->adapt) rt_adaptive_strip(rt, t);
    else full_strip(rt, t);
    if (st) {
        st->rays += rt->n.rays - rays0;
        st->pixels_written += rt->n.covered - covered0;
    }
    return 0;
}
