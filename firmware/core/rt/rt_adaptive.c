/* SPDX-License-Identifier: MIT */
/* rt_adaptive.c — 2-D adaptive subsampling: blocks of B x B pixels traced at
 * their corners and refined as a quadtree where the corners disagree. */
#include "rt_int.h"
#include "rt_num.h"

static inline rgb rgb_sub(rgb a, rgb b) { return rgb_make(num_sub(a.r, b.r), num_sub(a.g, b.g), num_sub(a.b, b.b)); }

/* Every channel of c in (-2^29, 2^29). */
static inline int rgb_within29(rgb c)
{
    uint32_t b = 1u << 29;
    return (((uint32_t)c.r + b) | ((uint32_t)c.g + b) | ((uint32_t)c.b + b)) < 2 * b;
}

/* rgb_scale by a bilinear weight in [0, 1]: the same bits (rt_mul_weight) */
static inline rgb rgb_weigh(rgb c, num w)
{
    return rgb_make(rt_mul_weight(c.r, w), rt_mul_weight(c.g, w), rt_mul_weight(c.b, w));
}

/* The samples of image row `row` traced so far: the block corners
 * (columns 0, B, 2B, ... and the last) at once, other columns when a block
 * needs them; kept for the next block row, whose top row it is. */
static int corner_row(struct rt_state *rt, int row)
{
    for (int k = 0; k < 2; k++)
        if (rt->corner_row[k] == row) return k;
    /* replace the row that is not the other block edge in use */
    int k = rt->corner_row[0] < rt->corner_row[1] ? 0 : 1;
    for (int col = 0; col < rt->w; col++) rt->corner_have[k][col] = 0;
    for (int col = 0;; col += rt->adapt) {
        if (col > rt->w - 1) col = rt->w - 1;
        rt_sample_pixel(rt, col, row, &rt->corner[k][col]);
        rt->corner_have[k][col] = 1;
        if (col == rt->w - 1) break;
    }
    rt->corner_row[k] = row;
    return k;
}

/* The block being refined: its samples on a (B+1) x (B+1) grid. Points
 * on its top and bottom rows live in the two row buffers (shared with the
 * blocks beside and, for the bottom row, with the next block row), points
 * on its left and right columns in the column buffers (shared with the
 * blocks beside), the rest in the block's own grid; each is traced once,
 * when first needed. */
struct rt_block {
    struct rt_state *rt;
    struct render_target *t;
    int c0, r0, wx, wy; /* image position of grid point (0, 0); size */
    int top, bot;       /* row buffers of rows r0 and r0 + wy */
};

static const struct rt_sample *grid_at(struct rt_block *bk, int gx, int gy)
{
    struct rt_state *rt = bk->rt;
    struct rt_sample *sp;
    uint8_t *have;
    if (gy == 0 || gy == bk->wy) {
        int k = gy == 0 ? bk->top : bk->bot;
        sp = &rt->corner[k][bk->c0 + gx];
        have = &rt->corner_have[k][bk->c0 + gx];
    } else if (gx == 0 || gx == bk->wx) {
        int k = gx == 0 ? rt->col_left : 1 - rt->col_left;
        sp = &rt->colbuf[k][gy];
        have = &rt->colbuf_have[k][gy];
    } else {
        int i = gy * (rt->adapt + 1) + gx;
        sp = &rt->grid[i];
        have = &rt->grid_have[i];
    }
    if (!*have) {
        rt_sample_pixel(rt, bk->c0 + gx, bk->r0 + gy, sp);
        *have = 1;
    }
    return sp;
}

/* The largest minus the smallest of four values (saturating as num_sub):
 * the largest of rt_colours_differ's pairwise differences. */
static inline num spread4(num a, num b, num c, num e)
{
    num lo = a, hi = a;
    if (b < lo) lo = b;
    if (b > hi) hi = b;
    if (c < lo) lo = c;
    if (c > hi) hi = c;
    if (e < lo) lo = e;
    if (e > hi) hi = e;
    return num_sub(hi, lo);
}

/* Every two of the four samples agree (the same item and shadows, no
 * channel more than d apart as rt_colours_differ decides it), for the six
 * pairs at once: the items and the shadows all equal s00's (equality is
 * transitive), and each channel's spread within d (num_sub is monotone, so
 * the largest and the smallest value are the pair farthest apart). */
static int rect_agrees(const struct rt_sample *s00, const struct rt_sample *s01, const struct rt_sample *s10,
                       const struct rt_sample *s11, num d)
{
    if (s01->item != s00->item || s10->item != s00->item || s11->item != s00->item) return 0;
    if (s01->shadow != s00->shadow || s10->shadow != s00->shadow || s11->shadow != s00->shadow) return 0;
    return spread4(s00->c.r, s01->c.r, s10->c.r, s11->c.r) <= d && spread4(s00->c.g, s01->c.g, s10->c.g, s11->c.g) <= d &&
           spread4(s00->c.b, s01->c.b, s10->c.b, s11->c.b) <= d;
}

/* Pixels [x, x + wx) x [y, y + wy) of the block (grid units = pixels),
 * and the right / bottom edge too when it is the image's last column /
 * row: if the rectangle's four corners agree (or it is one pixel), its
 * pixels are the corners' bilinear interpolation (traced grid points keep
 * their own colour); otherwise it is split in halves and each refined. */
static void refine(struct rt_block *bk, int x, int y, int wx, int wy, int right, int bottom)
{
    struct render_target *t = bk->t;
    int ya = bk->r0 + y, yb = bk->r0 + y + wy + (bottom ? 1 : 0); /* image rows owned */
    if (yb <= t->y0 || ya >= t->y1) return;
    if (wx <= 1 && wy <= 1 && !right && !bottom) {
        const struct rt_sample *sp = grid_at(bk, x, y);
        rt_put(bk->rt, t, bk->c0 + x, ya, sp->c, sp->item >= 0); /* ya is in the strip */
        return;
    }
    const struct rt_sample *s00 = grid_at(bk, x, y), *s01 = grid_at(bk, x + wx, y);
    const struct rt_sample *s10 = grid_at(bk, x, y + wy), *s11 = grid_at(bk, x + wx, y + wy);
    if ((wx > 1 || wy > 1) && !rect_agrees(s00, s01, s10, s11, bk->rt->adapt_diff)) {
        int hx = wx > 1 ? wx / 2 : wx, hy = wy > 1 ? wy / 2 : wy;
        refine(bk, x, y, hx, hy, right && hx == wx, bottom && hy == wy);
        if (hx < wx) refine(bk, x + hx, y, wx - hx, hy, right, bottom && hy == wy);
        if (hy < wy) {
            refine(bk, x, y + hy, hx, wy - hy, right && hx == wx, bottom);
            if (hx < wx) refine(bk, x + hx, y + hy, wx - hx, wy - hy, right, bottom);
        }
        return;
    }
    /* the rectangle's pixels from its four corners alone (a point another
     * rectangle traced is interpolated here too: the pixels then depend on
     * this rectangle's corners only, whatever the strips) */
    if (wx <= 1 && wy <= 1) {
        /* one pixel: its own sample, and the image's last column/row */
        for (int gy = y; gy < y + wy + (bottom ? 1 : 0); gy++) {
            int row = bk->r0 + gy;
            if (row < t->y0 || row >= t->y1) continue;
            for (int gx = x; gx < x + wx + (right ? 1 : 0); gx++) {
                const struct rt_sample *sp = grid_at(bk, gx, gy);
                rt_put(bk->rt, t, bk->c0 + gx, row, sp->c, sp->item >= 0);
            }
        }
        return;
    }
    /* bilinear: per row the colours at the left and right edges, then
     * along the row L + (R - L) fx, with fx per column from a table */
    const num *ratio = bk->rt->adapt_ratio;
    const num *fxs = ratio + wx * (bk->rt->adapt + 1), *fys = ratio + wy * (bk->rt->adapt + 1);
    for (int gy = y; gy < y + wy + (bottom ? 1 : 0); gy++) {
        int row = bk->r0 + gy;
        if (row < t->y0 || row >= t->y1) continue;
        num fy = fys[gy - y];
        rgb lc = rgb_add(s00->c, rgb_weigh(rgb_sub(s10->c, s00->c), fy));
        rgb rc = rgb_add(s01->c, rgb_weigh(rgb_sub(s11->c, s01->c), fy));
        rgb dc = rgb_sub(rc, lc);
        /* L and R within 2^29: R - L is exact and L + (R - L) fx, with
         * |(R - L) fx| <= |R - L| < 2^30, stays inside the format, so the
         * plain sum is rgb_add's */
        int plain = rgb_within29(lc) && rgb_within29(rc);
        int cy = gy == y ? 0 : (gy == y + wy ? 1 : -1);
        for (int gx = x; gx < x + wx + (right ? 1 : 0); gx++) {
            rgb c;
            int cx = gx == x ? 0 : (gx == x + wx ? 1 : -1);
            if (cx >= 0 && cy >= 0) c = (cy ? (cx ? s11 : s10) : (cx ? s01 : s00))->c;
            else {
                rgb d = rgb_weigh(dc, fxs[gx - x]);
                c = plain ? rgb_make(lc.r + d.r, lc.g + d.g, lc.b + d.b) : rgb_add(lc, d);
            }
            rt_put(bk->rt, t, bk->c0 + gx, row, c, s00->item >= 0); /* the corners agree on it */
        }
    }
}

/* 2-D adaptive subsampling (chapter 5's subsampling over blocks, refined
 * as a quadtree): the corners of B x B blocks are traced; a block whose
 * four corners agree (item, shadows, colours within the threshold) is
 * filled by bilinear interpolation, any other is split in four and each
 * quarter decided the same way from its own corners, down to single
 * pixels. Block rows cover [r0, r0 + B) and the last one also row h - 1,
 * likewise columns; a strip that starts inside a block row refines that
 * block row again (only the rows it owns are written), so every strip
 * height gives the same pixels. Images of at least 2 x 2 pixels. */
void rt_adaptive_strip(struct rt_state *rt, struct render_target *t)
{
    const int b = rt->adapt, w = rt->w, h = rt->h;
    if (w < 2 || h < 2) {
        for (int y = t->y0; y < t->y1; y++)
            for (int x = 0; x < w; x++) {
                struct rt_sample sm;
                rt_sample_pixel(rt, x, y, &sm);
                rt_put(rt, t, x, y, sm.c, sm.item >= 0);
            }
        return;
    }
    int r0 = t->y0 - t->y0 % b;
    if (r0 == h - 1) r0 -= b; /* the last row belongs to the block above */
    for (; r0 < t->y1 && r0 < h - 1; r0 += b) {
        int r1 = r0 + b < h - 1 ? r0 + b : h - 1; /* bottom corner row */
        int top = corner_row(rt, r0), bot = corner_row(rt, r1);
        /* the first block's left column starts empty */
        rt->col_left = 0;
        for (int i = 0; i <= b; i++) rt->colbuf_have[0][i] = 0;
        for (int c0 = 0; c0 < w - 1; c0 += b) {
            int c1 = c0 + b < w - 1 ? c0 + b : w - 1;
            int n = (b + 1) * (b + 1);
            for (int i = 0; i < n; i++) rt->grid_have[i] = 0;
            for (int i = 0; i <= b; i++) rt->colbuf_have[1 - rt->col_left][i] = 0;
            struct rt_block bk = { rt, t, c0, r0, c1 - c0, r1 - r0, top, bot };
            refine(&bk, 0, 0, c1 - c0, r1 - r0, c1 == w - 1, r1 == h - 1);
            rt->col_left = 1 - rt->col_left; /* this block's right column is the next one's left */
        }
    }
}
