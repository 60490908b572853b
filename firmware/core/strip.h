/* SPDX-License-Identifier: MIT */
/* strip.h — what a renderer writes a strip of the frame into, and how: the
 * target rows (struct render_target), what it counts (struct render_stats),
 * the pass (full or preview) and the pixel write both renderers share. It
 * lies below both renderers and the dispatcher (render.h), which includes it:
 * a renderer never includes render.h.
 *
 * Host outputs: struct render_target's rgb888 and written maps are the
 * host's (tests, host_sim). A build with RENDER_HOST_OUTPUTS 0 (the board
 * images: -DRENDER_HOST_OUTPUTS=0) leaves out the code that writes them,
 * about 21 KB of the rasterizer's span loops that a board would otherwise
 * copy into SRAM, and render_strip refuses a target that asks for them. */
#ifndef STRIP_H
#define STRIP_H

#include <stddef.h>
#include <stdint.h>
#include "scene.h"

#ifndef RENDER_HOST_OUTPUTS
#define RENDER_HOST_OUTPUTS 1
#endif

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
    uint32_t triangles_in, triangles_drawn;  /* rasterizer: the frame's, counted with its first strip;
                                                drawn: not culled (in view, on a row, not degenerate,
                                                not a back face with culling on) */
    uint32_t pixels_written;
};

/* How the following strips of the current frame are rendered (progressive
 * display). RENDER_PASS_FULL (the default, reset by render_begin_frame):
 * the frame as the scene asks for it. RENDER_PASS_COARSE: a preview, one
 * ray per 8x8 block (at its centre pixel) drawn as a block, so a whole
 * screen costs 1/64 of the rays; rendering the frame again in
 * RENDER_PASS_FULL then refines it in place. Ray tracer only: for other
 * scenes RENDER_PASS_COARSE returns -1 and nothing changes. */
enum render_pass { RENDER_PASS_FULL = 0, RENDER_PASS_COARSE = 1 };
#define RENDER_COARSE_BLOCK 8

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
