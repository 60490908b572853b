/* rt_book_scenes.h — the book's ray-tracer demo scenes built in C
 * (book-scenes.md §1.3 and §2), for tests that must not depend on the scene
 * parser. Compiled once per numeric mode; storage is static per scene slot. */
#ifndef RT_BOOK_SCENES_H
#define RT_BOOK_SCENES_H

#include "scene.h"

/* raytracer-0n, n = 1..6, with the demo's default settings. Returns NULL for
 * another n. The scene stays valid until the next call with the same n. */
struct scene *rt_book_scene(int n);

/* A scene of count x count small spheres on a plane (bounding-sphere
 * hierarchy tests). */
struct scene *rt_grid_scene(int count);

/* Chapter 5 showcase: plane, triangle, CSG (union, intersection,
 * difference) and a glass sphere under the book's lights. */
struct scene *rt_ch5_scene(void);

#endif
