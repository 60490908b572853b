/* SPDX-License-Identifier: MIT */
/* raster.h — the rasterizer of part II of the book (chapters 6–14), strip by strip.
 *
 * Coordinates (the book's): world and camera space have +x right, +y up, the
 * camera looks along +z. Canvas coordinates have their origin at the centre,
 * +y up; canvas (x, y) is screen column width/2 + x, row height/2 - y - 1
 * (PutPixel). The scene canvas is scaled to the render size by
 * height/canvas_h (2D primitives) and the viewport keeps its height, its
 * width following the render aspect (3D), so 600x600 is the book exactly.
 *
 * Two paths, chosen per scene by ras_options.book_exact:
 * - book_exact = 1: the demos' own pseudocode and quirks (Interpolate lists,
 *   truncated projections and spans, triangles straddling a clipping plane
 *   dropped whole, unnormalised normals, the world-space view vector). The
 *   double build at 600x600 reproduces the reference digests.
 * - book_exact = 0 (what real rasterizers add):
 *   * Pixel centres at (column + 1/2, row + 1/2); vertices snapped to
 *     1/2^RAS_SUBPIXEL_BITS pixel (ras_options.subpixel_bits overrides,
 *     1..8); integer edge functions with the top-left fill rule: a pixel
 *     whose centre lies on an edge belongs to the triangle for which the
 *     edge is a top edge (horizontal, interior below) or a left edge, so
 *     triangles sharing an edge never overlap or leave gaps, and
 *     zero-area triangles draw nothing.
 *   * Triangles are split against the near plane (z = projection_d) and
 *     the four side planes of the render's viewport (with a small guard
 *     band), so any camera position works; nothing is ever written
 *     outside the strip.
 *   * Colours, normals and texture coordinates are interpolated
 *     perspective-correctly; depth is near/z stored in 16 or 32 bits
 *     (larger is nearer, equal keeps the earlier triangle).
 *   * Front faces are those whose corners run clockwise as the camera
 *     sees them (x to the right, +y up; counter-clockwise in pixel
 *     coordinates, whose rows run downward); back faces are culled when
 *     ras_options.backface_cull is set.
 * 2D primitives (raster-01 … 04) and wireframes are drawn with the book's
 * routines in both paths.
 *
 * Memory: everything lives in the caller's work memory (raster_work_size()
 * bytes, any alignment): per-frame transformed vertices of every instance,
 * row ranges of every triangle (the binning of triangles to strips, done
 * once per frame), light vectors, and one strip's depth buffer.
 * Not thread-safe per context.
 *
 * This header is the rasterizer's contract (conventions) and its entry
 * points, which the dispatcher (render.c) calls: use render.h's. The
 * internals are raster/raster_int.h's.
 */
#ifndef RASTER_H
#define RASTER_H

#include <stddef.h>
#include "strip.h"

#define RAS_SUBPIXEL_BITS 4   /* default vertex precision: 1/16 pixel */

/* ---- the entry points behind render.h -------------------------------- */

/* The features (scene_features.def) the scene's frames may reach: render_features's. */
uint32_t raster_features(const struct scene *s);
/* Work memory for this scene at this size with strips of strip_rows rows;
 * 0 for a scene it cannot lay out (an instance of a missing model). */
size_t raster_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows);
/* Fast Phong's specular exponents, one table each (at most
 * RASTER_SPEC_MAX; more take the exact path), in table order: their count,
 * and in exps (if not NULL) the exponents. 0 for a scene without fast Phong. */
#define RASTER_SPEC_MAX 16
uint16_t raster_spec_exponents(const struct scene *s, uint32_t exps[RASTER_SPEC_MAX]);
/* Exponent e's specular table (257 entries of cos^e in Q14) and its index
 * step and end: the ones render_init makes, which scenec writes as const
 * data (struct scene's spec_tab, spec_step). */
void raster_spec_table(uint16_t t[257], uint32_t e, uint32_t step[2]);
/* Lays out the state in work (any alignment, work_size bytes). 0, or -1. */
int raster_init(void *work, size_t work_size, const struct scene *s, uint16_t width, uint16_t height,
                uint16_t strip_rows);
/* Per frame: transforms, binning of primitives to strips, lights. It is
 * raster_frame_start (camera, lights, every instance's matrices), then
 * raster_frame_vertices(work, 0, 1) (every vertex to camera space and the
 * screen), raster_frame_triangles(work, 0, 1) (every triangle culled and
 * lit), then raster_frame_finish (binning); render.h's render_frame_* split
 * the vertices and the triangles between two cores. */
int raster_begin_frame(void *work, uint16_t frame);
int raster_frame_start(void *work, uint16_t frame);
int raster_frame_vertices(const void *work, unsigned part, unsigned parts);
int raster_frame_triangles(void *work, unsigned part, unsigned parts);
int raster_frame_finish(void *work);
/* After a frame's raster_begin_frame (or its raster_frame_* steps): of
 * instance i's triangles, when its bounding sphere is in view, how many
 * face the camera or are drawn both ways (*facing) and how many face away
 * and are culled (*culled); degenerate ones neither. A host's check (every
 * triangle culled: the winding is probably reversed), not a frame's step.
 * 0, or -1 for no such instance. */
int raster_instance_facing(const void *work, uint16_t i, uint32_t *facing, uint32_t *culled);
/* Rows [t->y0, t->y1) of the current frame (at most strip_rows). */
int raster_strip(void *work, struct render_target *t, struct render_stats *st);
/* A sibling context (render.h's render_init_sibling): its work memory holds
 * only what strips write; raster_sibling_frame takes the owner's current
 * frame (after the owner's raster_begin_frame). */
size_t raster_sibling_work_size(const struct scene *s, uint16_t width, uint16_t height, uint16_t strip_rows);
int raster_init_sibling(void *work, size_t work_size, const void *owner_work);
int raster_sibling_frame(void *work);

#endif
