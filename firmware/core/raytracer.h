/* SPDX-License-Identifier: MIT */
/* raytracer.h — part I of the book: the ray tracer (chapters 2–5).
 *
 * Conventions (the book's): world +x right, +y up, +z forward; the camera at
 * scene->camera.position looks along +z turned by camera.rotation (applied to
 * primary directions only). The viewport keeps the scene's height; its width
 * follows the render size (Vw = Vh*W/H, see render.h). Pixel (column c, row r)
 * is canvas (x, y) = (c - W/2, H/2 - 1 - r), and its primary ray is
 *   D = canvas_to_viewport(x, y) = ((x*Vw)/W, (y*Vh)/H, d), rotated by the camera,
 * traced from the camera with t in (t_min_primary, +inf). As in the book, D is
 * not normalised: t is in units of |D|, so t = 1 is the projection plane and a
 * point light sits at t = 1 on its (unnormalised) shadow ray.
 *
 * Numbers (num.h). In fixed point the scene must keep every coordinate and
 * every hit distance along a ray (t*|D|) under 16000 in magnitude; sphere
 * radii up to 16000 are fine (radius 5000 is the book's ground).
 *
 * Formulations (rt_options.formulation, rt/rt_num.h):
 * - book: IntersectRaySphere's quadratic k1 t^2 + k2 t + k3 with the demos'
 *   operation order; normals N = (P - C) * (1/|P - C|); shadow and reflection
 *   rays start at t = epsilon. The double build reproduces the demos exactly.
 * - robust (fixed/float default): the same roots from a = D.D, b = -CO.D,
 *   c = CO.CO - r^2 in wide intermediates (wnum), Δ/4 = b^2 - a c, and the
 *   stable pair q = b + sign(b) sqrt(Δ/4), t = q/a and t = c/q (no
 *   cancellation for the near root); N = (P - C)/r. A ray leaving a surface
 *   carries that object: for a sphere its roots are then known exactly
 *   ({0, 2b/a}), for a plane or triangle there is none, so there is no
 *   self-shadowing ("acne") at any scene scale; epsilon only applies to other
 *   objects. Range argument in raytracer.md.
 *
 * Memory: all state lives in the caller's work memory (rt_work_size bytes,
 * 8-byte aligned); nothing is allocated and nothing is static. Stack: bounded
 * recursion, at most RT_MAX_DEPTH levels of trace_ray (figures in raytracer.md).
 * Not thread-safe per state; two states may render different strips of the
 * same scene.
 *
 * This header is the ray tracer's contract (conventions and limits) and its
 * entry points, which the dispatcher (render.c) calls: use render.h's. The
 * internals are rt/rt_int.h's.
 */
#ifndef RAYTRACER_H
#define RAYTRACER_H

#include "strip.h"

/* Deepest reflection/refraction recursion honoured (rt_options.recursion_depth
 * is clamped to it; the book's control allows 0..5). */
#define RT_MAX_DEPTH 5
/* Largest block side of adaptive subsampling (rt_options.adaptive_subsample). */
#define RT_MAX_ADAPT 8
/* Rays per pixel side for supersampling (4 -> 16 rays). */
#define RT_MAX_SS 4

/* ---- the entry points behind render.h -------------------------------- */

/* Work memory for this scene at this size (scene-dependent tables and one
 * row of per-pixel notes for subsampling and adaptive supersampling). */
size_t rt_work_size(const struct scene *s, uint16_t width, uint16_t height);
/* Builds the state in work (8-byte aligned, work_size bytes): tables, the
 * bounding-sphere hierarchy. 0, or -1 for a scene it cannot render. */
int rt_init(void *work, size_t work_size, const struct scene *s, uint16_t width, uint16_t height);
/* Per-frame constants: camera (with animation), per-object constants. */
int rt_begin_frame(void *work, uint16_t frame);
/* enum render_pass of the following strips. */
void rt_set_pass(void *work, uint8_t pass);
/* on 1: the frame is seen through a round glass, the circle of diameter
 * min(w, h) centred in it; the full pass's plain pixels outside it get the
 * background instead of a ray (render_set_round). Kept until changed. */
void rt_set_round(void *work, uint8_t on);
/* Rows [t->y0, t->y1) of the current frame. */
int rt_render_strip(void *work, struct render_target *t, struct render_stats *st);

/* ---- probes: what the render decided, for tests and accuracy reports --
 * (after rt_init; NULL stops; the caller's memory, w*h entries row-major
 * unless said; pixels not traced one by one, such as those of adaptive
 * subsampling, supersampling or the book's subsampling, keep what the
 * caller put there, but for 0xFF written into the shadow probe where the
 * book's subsampling interpolates) */
/* Each traced pixel's primary hit: bit k set when light k is shadowed,
 * 0x80 for no hit. */
void rt_set_shadow_probe(void *work, uint8_t *probe);
/* Each traced pixel's primary hit: the item hit (-1: none). */
void rt_set_item_probe(void *work, int16_t *probe);
/* Raises probe[k] (nobjects entries) to the largest |P| of the hit points
 * P the render shades on object k. */
void rt_set_hit_probe(void *work, num *probe);
/* The shadow rays traced since rt_init (each light's test of a shaded hit
 * that is not cached). */
uint32_t rt_shadow_rays(const void *work);

#endif
