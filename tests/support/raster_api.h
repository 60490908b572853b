/* SPDX-License-Identifier: MIT */
/* raster_api.h — per-mode entry of the rasterizer tests (see raster_api.c). */
#ifndef RASTER_API_H
#define RASTER_API_H

struct frame;
struct raster_api {
    const char *numeric;
    /* Renders book scene `name` (firmware/scenes/book); book_exact 0 switches it
     * to the default path (clipping by splitting). 0 on success. */
    int (*render)(const char *name, int book_exact, int w, int h, int rows, struct frame *f);
    /* The same with the scene's texture replaced by a coordinate texture
     * (texel x, y encoded in R, G, B), unlit, nearest: the output names the
     * texel each pixel looked up. */
    int (*render_texel_probe)(const char *name, int book_exact, int w, int h, struct frame *f);
    /* Default path, the texture replaced by a 256x256 coordinate ramp (R =
     * texel x, G = texel y, B = 0) filtered trilinearly with its box-filtered
     * mipmaps, unlit: every level holds the level-0 coordinate of its texel
     * centres (up to the box filter's rounding), so the output names the
     * level-0 position each pixel's filtered lookup lands on, whatever level
     * it blends. */
    int (*render_texel_probe_trilinear)(const char *name, int w, int h, struct frame *f);
};
extern const struct raster_api raster_api_fixed, raster_api_float, raster_api_double;

#endif
