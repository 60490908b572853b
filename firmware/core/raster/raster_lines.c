/* SPDX-License-Identifier: MIT */
/* raster_lines.c — PutPixel and chapter 6: lines (Interpolate, DrawLine). */
#include "raster_int.h"

/* Loop bound for the book's real-valued counters: ends lines whose
 * coordinates saturated or ran far off the canvas. */
#define RAS_LINE_MAX_STEPS 65536

void ras_put(struct ras_ctx *rc, int col, int row, rgb c)
{
    struct render_target *t = rc->cur.t;
    if (col < 0 || col >= (int)rc->w || row < (int)t->y0 || row >= (int)t->y1) return;
    render_put(t, col, row, c);
    if (t->written) t->written[(size_t)(row - t->y0) * t->width + (size_t)col] = 1;
    rc->cur.st->pixels_written++;
}

int ras_canvas_col(const struct ras_ctx *rc, int32_t x)
{
    int64_t c = (int64_t)(rc->w / 2) + x;
    return c < -1 ? -1 : (c > 65536 ? 65536 : (int)c);
}

int ras_canvas_row(const struct ras_ctx *rc, int32_t y)
{
    int64_t r = (int64_t)(rc->h / 2) - y - 1;
    return r < -1 ? -1 : (r > 65536 ? 65536 : (int)r);
}

void ras_put_canvas(struct ras_ctx *rc, num x, num y, rgb c)
{
    ras_put(rc, ras_canvas_col(rc, num_to_int(x)), ras_canvas_row(rc, num_to_int(y)), c);
}

/* raster-01's first attempt: one pixel per column, gaps on steep lines. */
void ras_draw_line_broken(struct ras_ctx *rc, num x0, num y0, num x1, num y1, rgb c)
{
    struct ras_interp ys;
    ras_interp_init(&ys, x0, y0, x1, y1);
    int n = 0;
    for (num x = x0; x <= x1 && n < RAS_LINE_MAX_STEPS; n++, x = ras_count_next(x, x0, n)) {
        ras_put_canvas(rc, x, ras_interp_value(&ys), c);
        ras_interp_next(&ys);
    }
}

/* One axis of ras_draw_line: the counter runs along `a` (the longer axis), the
 * other coordinate comes from Interpolate, indexed by T(a - a0) as the
 * demos do. */
static void line_along(struct ras_ctx *rc, num a0, num b0, num a1, num b1, int a_is_x, rgb c)
{
    struct ras_interp bs;
    ras_interp_init(&bs, a0, b0, a1, b1);
    int32_t j = 0;
    int n = 0;
    for (num a = a0; a <= a1 && n < RAS_LINE_MAX_STEPS; n++) {
        int32_t k = ras_count_index(a, a0, n);
        while (j < k) { ras_interp_next(&bs); j++; }
        num b = ras_interp_value(&bs);
        if (a_is_x) {
            if (ras_canvas_col(rc, num_to_int(a)) >= (int)rc->w) break;
            ras_put_canvas(rc, a, b, c);
        } else {
            if (ras_canvas_row(rc, num_to_int(a)) < 0) break;
            ras_put_canvas(rc, b, a, c);
        }
        num next = ras_count_next(a, a0, n + 1);
        if (next <= a) break; /* saturated */
        a = next;
    }
}

void ras_draw_line(struct ras_ctx *rc, num x0, num y0, num x1, num y1, rgb c)
{
    num dx = num_sub(x1, x0), dy = num_sub(y1, y0);
    if (num_abs(dx) > num_abs(dy)) {
        if (dx < 0) line_along(rc, x1, y1, x0, y0, 1, c);
        else line_along(rc, x0, y0, x1, y1, 1, c);
    } else {
        if (dy < 0) line_along(rc, y1, x1, y0, x0, 0, c);
        else line_along(rc, y0, x0, y1, x1, 0, c);
    }
}

void ras_draw_wireframe_triangle(struct ras_ctx *rc, const num x[3], const num y[3], rgb c)
{
    ras_draw_line(rc, x[0], y[0], x[1], y[1], c);
    ras_draw_line(rc, x[1], y[1], x[2], y[2], c);
    ras_draw_line(rc, x[0], y[0], x[2], y[2], c);
}
