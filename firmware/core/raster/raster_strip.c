/* SPDX-License-Identifier: MIT */
/* raster_strip.c — render_strip: the background, the 2D primitives and 3D
 * lines binned to the strip, then RenderScene, each instance's triangles
 * that touch the strip through the path's RenderTriangle (the strip half of
 * the book's RenderInstance). */
#include <string.h>
#include "raster_int.h"

/* Word stores through an alias-safe type (the strip is uint16_t, the depth
 * buffer bytes of work memory). */
#if defined(__GNUC__) || defined(__clang__)
typedef uint32_t __attribute__((may_alias)) ras_word;
#define RAS_HAVE_WORD 1
#endif

#ifdef RAS_HAVE_WORD
/* Words w[0 .. 8 n8 - 1] = v (n8 > 0): on ARMv6-M by two four-register
 * stores a loop, else eight word stores. Returns w + 8 n8. */
static ras_word *ras_fill8(ras_word *w, size_t n8, uint32_t v)
{
#if defined(__ARM_ARCH_6M__)
    register ras_word *p __asm__("r0") = w;
    register uint32_t n __asm__("r1") = (uint32_t)n8;
    register uint32_t a __asm__("r2") = v, b __asm__("r3") = v, c __asm__("r4") = v, d __asm__("r5") = v;
    __asm__ volatile(".syntax unified\n"
                     "1:\n\t stmia %[p]!, {%[a], %[b], %[c], %[d]}\n\t stmia %[p]!, {%[a], %[b], %[c], %[d]}\n\t"
                     "subs %[n], #1\n\t bne 1b\n\t"
                     ".syntax divided\n"
                     : [p] "+l"(p), [n] "+l"(n)
                     : [a] "l"(a), [b] "l"(b), [c] "l"(c), [d] "l"(d)
                     : "cc", "memory");
    return p;
#else
    for (; n8; n8--, w += 8) { w[0] = v; w[1] = v; w[2] = v; w[3] = v; w[4] = v; w[5] = v; w[6] = v; w[7] = v; }
    return w;
#endif
}
#endif

/* n RGB565 pixels of value c: 32-bit stores, eight a loop. */
static void ras_fill16(uint16_t *p, size_t n, uint16_t c)
{
#ifdef RAS_HAVE_WORD
    if (n && ((uintptr_t)p & 2u)) { *p++ = c; n--; }
    ras_word *w = (ras_word *)(void *)p, v = (uint32_t)c * 0x00010001u;
    size_t nw = n / 2;
    if (nw >= 8) w = ras_fill8(w, nw / 8, v);
    nw &= 7u;
    while (nw--) *w++ = v;
    if (n & 1u) p[n - 1] = c;
#else
    for (size_t k = 0; k < n; k++) p[k] = c;
#endif
}

/* n bytes of zeros at p (4-byte aligned, n a multiple of 2). */
static void ras_fill_zero(uint8_t *p, size_t n)
{
#ifdef RAS_HAVE_WORD
    if (((uintptr_t)p & 3u) == 0) {
        ras_word *w = (ras_word *)(void *)p;
        size_t nw = n / 4;
        if (nw >= 8) w = ras_fill8(w, nw / 8, 0);
        nw &= 7u;
        while (nw--) *w++ = 0;
        p = (uint8_t *)w;
        n &= 3u;
    }
#endif
    memset(p, 0, n);
}

static int rows_hit(struct ras_range r, const struct render_target *t)
{
    return r.r0 <= r.r1 && r.r1 >= (int)t->y0 && r.r0 < (int)t->y1;
}

/* The strip's rows y0 .. y1 - 1 as bounds of packed rows (struct ras_trows):
 * a triangle's rows reach row y0 when r1 >= y0 >> row_shift, and begin
 * above row y1 when r0 < y1 rounded up >> row_shift. */
struct trows_strip { uint32_t y0, y1; };
static struct trows_strip trows_strip(const struct ras_ctx *rc, const struct render_target *t)
{
    struct trows_strip b = { (uint32_t)t->y0 >> rc->row_shift,
                             ((uint32_t)t->y1 + (1u << rc->row_shift) - 1u) >> rc->row_shift };
    return b;
}

static int trows_hit(struct ras_trows r, struct trows_strip b)
{
    return r.r0 <= r.r1 && r.r1 >= b.y0 && r.r0 < b.y1;
}

/* RenderInstance, its strip half: the instance's triangles that touch the
 * strip (binned by prepare_instance), each through RenderTriangle. */
static void render_instance(struct ras_ctx *rc, uint16_t i, const struct render_target *t)
{
    const struct scene *s = rc->s;
    const struct ras_instance *in = &s->instances[i];
    const struct ras_inst *ri = &rc->inst[i];
    const struct ras_model *m = &s->models[in->model];
    const struct trows_strip b = trows_strip(rc, t);
    if (!ri->visible) return;
    for (uint16_t k = 0; k < m->ntris; k++) {
        if (!trows_hit(rc->tri_rows[ri->tbase + k], b)) continue;
        if (FW_FEATURE_RAS_BOOK && (rc->book || s->ras.wireframe)) ras_book_render_triangle(rc, in, ri, m, &m->tris[k]);
        else if (FW_FEATURE_RAS_DEFAULT) ras_default_render_triangle(rc, in, ri, m, &m->tris[k], ri->tbase + k);
    }
}

/* The binned triangles that reach strip t, in drawing order, each through
 * RenderTriangle: the runs of the buckets begun up to the strip's last row
 * whose triangles reach down to it (ras_bins.reach), the triangles ended
 * above it skipped, merged by index (each run is in drawing order). Each
 * run's cursor rests on its next triangle that reaches the strip (skipped
 * to once, when the cursor moves). */
static void render_bins(struct ras_ctx *rc, const struct render_target *t)
{
    const struct ras_bins *B = &rc->bins;
    const struct scene *s = rc->s;
    const struct ras_trows *rows = rc->tri_rows;
    const uint16_t *order = B->order;
    const int32_t y0 = t->y0;
    const struct trows_strip tb = trows_strip(rc, t);
    uint16_t *cur = B->runs, *end = B->runs + B->nbuckets;
    uint32_t lastb = ((uint32_t)t->y1 - 1) / rc->strip_rows, n = 0;
    for (uint32_t b = 0; b <= lastb && b < B->nbuckets; b++)
        if (B->reach[b] >= y0 && B->start[b] < B->start[b + 1]) {
            uint32_t c = B->start[b], e = B->start[b + 1];
            while (c < e && rows[order[c]].r1 < tb.y0) c++;
            if (c == e) continue;
            cur[n] = (uint16_t)c;
            end[n++] = (uint16_t)e;
        }
    uint16_t i = 0;
    while (n) {
        uint32_t bj = 0, best = order[cur[0]];
        for (uint32_t j = 1; j < n; j++) {
            const uint32_t h = order[cur[j]];
            if (h < best) {
                best = h;
                bj = j;
            }
        }
        uint32_t c = cur[bj] + 1u;
        const uint32_t e = end[bj];
        while (c < e && rows[order[c]].r1 < tb.y0) c++;
        if (c == e) { /* the run is done: the last one takes its place */
            n--;
            cur[bj] = cur[n];
            end[bj] = end[n];
        } else {
            cur[bj] = (uint16_t)c;
        }
        if (!trows_hit(rows[best], tb)) continue;
        while (i + 1 < s->ninstances && best >= rc->inst[i + 1].tbase) i++;
        const struct ras_instance *in = &s->instances[i];
        const struct ras_inst *ri = &rc->inst[i];
        const struct ras_model *m = &s->models[in->model];
        ras_default_render_triangle(rc, in, ri, m, &m->tris[best - ri->tbase], best);
    }
}

/* RenderScene for one strip: every instance, in the scene's order; with
 * shadow volumes (chapter 15) three passes: depth only, the volumes into
 * the stencil, then shading where the depth equals the visible surface's. */
static void render_scene(struct ras_ctx *rc, const struct render_target *t)
{
    for (int pass = rc->c15.sv_on ? 0 : 2; pass < 3; pass++) {
        if (pass == 1) { if (FW_FEATURE_RAS_CH15) ras_shadow_volumes(rc); continue; }
        rc->cur.depth_only = (uint8_t)(pass == 0);
        rc->cur.depth_func = (uint8_t)(rc->c15.sv_on && pass == 2 ? RAS_DEPTH_EQUAL : RAS_DEPTH_LESS_WRITE);
        rc->cur.lean = (uint8_t)(FW_FEATURE_RAS_DEFAULT && ras_default_lean(rc));
        if (FW_FEATURE_RAS_DEFAULT && rc->bins.on) render_bins(rc, t);
        else
            for (uint16_t i = 0; i < rc->s->ninstances; i++) render_instance(rc, i, t);
    }
}

int raster_strip(void *work, struct render_target *t, struct render_stats *st)
{
    struct ras_ctx *rc = ras_ctx_of(work);
    const struct scene *s = rc->s;
    if (t->y1 - t->y0 > rc->strip_rows) return -1;
    rc->cur.t = t;
    rc->cur.st = st;
    rgb bg = scene_background(s);
    size_t npx = (size_t)(t->y1 - t->y0) * t->width;
    ras_fill16(t->rgb565, npx, rgb_to_565(bg));
    if (t->rgb888) {
        uint8_t c[3];
        rgb_to_888(bg, c);
        for (size_t k = 0; k < npx; k++) memcpy(t->rgb888 + 3 * k, c, 3);
    }
    if (t->written) memset(t->written, 0, npx);
    if (rc->depth_bytes) ras_fill_zero(rc->depth, (size_t)rc->depth_bytes * rc->w * (size_t)(t->y1 - t->y0));

    for (uint16_t i = 0; FW_FEATURE_RAS_2D && i < s->nprims; i++) {
        if (!rows_hit(rc->prim_rows[i], t)) continue;
        const struct prim2d *p = &s->prims[i];
        num x[3], y[3];
        for (int k = 0; k < 3; k++) {
            x[k] = ras_scale_canvas(rc, p->x[k]);
            y[k] = ras_scale_canvas(rc, p->y[k]);
        }
        switch (p->kind) {
        case P2D_LINE_BROKEN: ras_draw_line_broken(rc, x[0], y[0], x[1], y[1], p->color); break;
        case P2D_LINE: ras_draw_line(rc, x[0], y[0], x[1], y[1], p->color); break;
        case P2D_WIRE_TRI: ras_draw_wireframe_triangle(rc, x, y, p->color); break;
        case P2D_FILLED_TRI: ras_draw_filled_triangle(rc, x, y, p->color); break;
        case P2D_SHADED_TRI: ras_draw_shaded_triangle(rc, x, y, p->h, p->color); break;
        default: break;
        }
    }
    for (uint16_t i = 0; FW_FEATURE_RAS_2D && i < s->nlines; i++) {
        if (!rows_hit(rc->line_rows[i], t)) continue;
        num ax, ay, bx, by;
        ras_project_vertex(rc, s->lines[i].a, &ax, &ay);
        ras_project_vertex(rc, s->lines[i].b, &bx, &by);
        ras_draw_line(rc, ax, ay, bx, by, s->lines[i].color);
    }
    render_scene(rc, t);
    rc->cur.depth_only = 0;
    rc->cur.lean = 0;
    rc->cur.depth_func = RAS_DEPTH_LESS_WRITE;
    if (t->y0 == 0) {
        st->triangles_in += rc->tris_in;
        st->triangles_drawn += rc->tris_drawn;
    }
    return 0;
}
