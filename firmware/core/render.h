/* SPDX-License-Identifier: MIT */
/* render.h — the renderer core's entry points, shared by both renderers.
 *
 * Conventions (the book's, with what real firmware adds):
 * - Screen: width x height pixels, row 0 at the top. Canvas coordinates have
 *   their origin at the centre, +x right, +y up: canvas (x, y) is column
 *   width/2 + x, row height/2 - y - 1 (PutPixel of the book).
 * - The scene's viewport keeps its height; its width follows the render
 *   size's aspect ratio (viewport_w = viewport_h * width / height), so a
 *   320x240 panel sees more to the sides, never a stretched image.
 * - A frame is rendered strip by strip: render_strip() fills rows
 *   [t->y0, t->y1) of a caller-provided buffer; a full frame is one strip.
 *   Pixels the scene does not cover get the scene background (white for raster
 *   scenes without one, as the book's page shows unwritten pixels).
 * - Memory: no heap. The caller provides `work` memory of render_work_size()
 *   bytes for the chosen size and strip height, and the strip buffers.
 * - Not thread-safe per context; two cores may render different strips with
 *   two contexts built from the same scene.
 */
#ifndef RENDER_H
#define RENDER_H

#include <stddef.h>
#include <stdint.h>
#include "scene.h"

struct render_target {
    uint16_t width, height;  /* whole frame */
    uint16_t y0, y1;         /* rows of this strip: y0 <= row < y1 */
    uint16_t *rgb565;        /* (y1-y0)*width pixels, native endian, row y at (y-y0)*width */
    uint8_t *rgb888;         /* optional (NULL on firmware): 3 bytes a pixel, the colour
                                before RGB565 quantisation (clamped, rounded half to even) */
    uint8_t *written;        /* optional (NULL on firmware): (y1-y0)*width bytes, set to 1 where
                                the scene wrote the pixel, 0 where only the background is */
};

/* What render_strip adds up (the caller zeroes it; NULL: not counted).
 * pixels_written means the same for both renderers: writes of the scene's
 * own content into the strip, not the background fill; a pixel drawn over
 * again (rasterizer overdraw) counts again, and the ray tracer writes every
 * covered pixel once. render_target.written marks the pixels so covered. */
struct render_stats {
    uint32_t rays;                           /* ray tracer: rays traced (primary and secondary) */
    uint32_t triangles_in, triangles_drawn;  /* rasterizer: the frame's, counted with its first strip */
    uint32_t pixels_written;
};

struct render_ctx {
    const struct scene *scene;
    uint16_t width, height, strip_rows;
    uint16_t frame;
    void *work;              /* renderer state, in caller memory */
    size_t work_size;
};

/* Bytes of work memory the renderer needs for this scene at this size with
 * strips of at most strip_rows rows. */
size_t render_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows);

/* 0 on success; -1 if work_size is too small or the size is invalid. */
int render_init(struct render_ctx *ctx, const struct scene *s, uint16_t width, uint16_t height,
                uint16_t strip_rows, void *work, size_t work_size);

/* Prepares frame `frame` (animation, per-frame constants, binning). */
int render_begin_frame(struct render_ctx *ctx, uint16_t frame);

/* Renders rows [t->y0, t->y1) of the current frame into t (at most
 * strip_rows of them, the full width): every pixel of the strip and, when
 * given, of t->rgb888 and t->written; nothing outside them. 0, or -1 for a
 * strip that is empty, too tall, past the frame or of another width. st may
 * be NULL. */
int render_strip(struct render_ctx *ctx, struct render_target *t, struct render_stats *st);

/* The scene's background in RGB565: what render_strip writes where the
 * scene covers nothing (white for a rasterized scene without one). */
uint16_t render_background_565(const struct render_ctx *ctx);

/* How the following strips of the current frame are rendered (progressive
 * display). RENDER_PASS_FULL (the default, reset by render_begin_frame):
 * the frame as the scene asks for it. RENDER_PASS_COARSE: a preview, one
 * ray per 8x8 block (at its centre pixel) drawn as a block, so a whole
 * screen costs 1/64 of the rays; rendering the frame again in
 * RENDER_PASS_FULL then refines it in place. Ray tracer only: for other
 * scenes RENDER_PASS_COARSE returns -1 and nothing changes. */
enum render_pass { RENDER_PASS_FULL = 0, RENDER_PASS_COARSE = 1 };
#define RENDER_COARSE_BLOCK 8
int render_set_pass(struct render_ctx *ctx, uint8_t pass);

/* Writes one pixel of a strip (both outputs); x, y are screen coordinates
 * inside the strip. Shared by both renderers (inline: on ARMv6-M the call
 * and the by-value colour cost as much as the conversion). */
static inline void render_put(struct render_target *t, int x, int y, rgb c)
{
    size_t i = (size_t)(y - t->y0) * t->width + (size_t)x;
    t->rgb565[i] = rgb_to_565(c);
    if (t->rgb888) rgb_to_888(c, t->rgb888 + 3 * i);
}

#endif
