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
#include "strip.h"

struct render_ctx {
    const struct scene *scene;
    uint16_t width, height, strip_rows;
    uint16_t frame;
    void *work;              /* renderer state, in caller memory */
    size_t work_size;
    const struct render_ctx *owner;  /* a sibling's owner (render_init_sibling), NULL: none */
};

/* Bytes of work memory the renderer needs for this scene at this size with
 * strips of at most strip_rows rows. */
size_t render_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows);

/* 0 on success; -1 if work_size is too small, the size is invalid or the
 * scene needs a feature this build left out (render_features). */
int render_init(struct render_ctx *ctx, const struct scene *s, uint16_t width, uint16_t height,
                uint16_t strip_rows, void *work, size_t work_size);

/* The renderer features the scene needs (scene_features.def: a mask of
 * RENDER_F(NAME) bits): every path, loop and table any frame of it may
 * reach. Those a build has are RENDER_FEATURES_BUILT (scene_features.h); a scene
 * with render_features(s) & ~RENDER_FEATURES_BUILT is refused by
 * render_init. */
uint32_t render_features(const struct scene *s);

/* A sibling context: another core rendering other strips of the frames
 * `owner` (an initialised context, not itself a sibling) prepares. For a
 * rasterized scene its work memory holds only what a strip writes (a depth
 * buffer, the list of the strip's triangles, set-ups kept between strips,
 * the stencil: render_sibling_work_size bytes, a fraction of the owner's
 * for a mesh) and it reads everything else from the owner's: the frame's
 * transformed vertices, binning and lighting are made once, by the owner.
 * render_begin_frame(ctx, f) on it takes the owner's frame f: call it after
 * the owner's render_begin_frame(owner, f) has returned, and call the
 * owner's next one only once the sibling's strips of frame f are done. For
 * a ray-traced scene a sibling is an independent context (the size is
 * render_work_size's, and it prepares its own frames). 0, or -1 (work_size
 * too small, owner a sibling). */
size_t render_sibling_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows);
int render_init_sibling(struct render_ctx *ctx, const struct render_ctx *owner, void *work, size_t work_size);

/* Prepares frame `frame` (animation, per-frame constants, binning); on a
 * sibling, takes the owner's frame `frame` (-1 when the owner's current
 * frame is another). */
int render_begin_frame(struct render_ctx *ctx, uint16_t frame);

/* The same preparation in four steps, so that two cores share its middle:
 * render_frame_start(owner, f) (camera, lights, every instance's
 * matrices); render_frame_vertices(c, part, parts) for each part
 * 0 .. parts-1, by the owner or its siblings, in any order or at once on
 * different cores (each transforms and projects its share of the frame's
 * vertices and writes only theirs); once every part has returned,
 * render_frame_triangles(c, part, parts) the same way for the triangles
 * (culled and lit), with parts 1 or 2, part 1 by the owner's sibling (the
 * lighting it makes lives in the sibling's memory); once both have
 * returned, render_frame_finish(owner) (the binning). The same frame as
 * render_begin_frame(owner, f). A ray-traced frame is prepared whole by
 * render_frame_start; the other steps do nothing for it. 0, or -1 (start or
 * finish on a sibling, a part out of range, part 1 of the triangles
 * without a sibling where the scene lights vertices). */
int render_frame_start(struct render_ctx *ctx, uint16_t frame);
int render_frame_vertices(const struct render_ctx *ctx, unsigned part, unsigned parts);
int render_frame_triangles(struct render_ctx *ctx, unsigned part, unsigned parts);
int render_frame_finish(struct render_ctx *ctx);

/* Renders rows [t->y0, t->y1) of the current frame into t (at most
 * strip_rows of them, the full width): every pixel of the strip and, when
 * given, of t->rgb888 and t->written; nothing outside them. 0, or -1 for a
 * strip that is empty, too tall, past the frame or of another width, or
 * that asks for host outputs in a build without them (RENDER_HOST_OUTPUTS
 * 0, strip.h). st may be NULL. */
int render_strip(struct render_ctx *ctx, struct render_target *t, struct render_stats *st);

/* The scene's background in RGB565: what render_strip writes where the
 * scene covers nothing (white for a rasterized scene without one). */
uint16_t render_background_565(const struct render_ctx *ctx);

/* How the following strips of the current frame are rendered (enum
 * render_pass, strip.h): RENDER_PASS_FULL (the default, reset by
 * render_begin_frame) or RENDER_PASS_COARSE, the ray tracer's preview; -1
 * for a pass the scene's renderer does not have (nothing changes). */
int render_set_pass(struct render_ctx *ctx, uint8_t pass);

/* on 1: the frame is seen through a round glass (the GC9A01's), the circle
 * of diameter min(width, height) centred in it: the ray tracer writes the
 * background to the pixels outside it instead of tracing them (the plain
 * full pass; supersampled, subsampled and adaptive frames are traced whole).
 * The rasterizer draws as before. 0, or -1 for a rasterized scene (nothing
 * changes). Kept until changed. */
int render_set_round(struct render_ctx *ctx, int on);

#endif
