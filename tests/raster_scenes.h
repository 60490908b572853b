/* raster_scenes.h — the book's raster demos (book-scenes.md §3) built in C,
 * for the rasterizer's tests; compiled once per numeric mode. */
#ifndef RASTER_SCENES_H
#define RASTER_SCENES_H

#include "scene.h"

/* "raster-01" … "raster-13", "raster-rt-scene"; NULL if unknown. The scene
 * lives in static storage, valid until the next call; book_exact is set. */
struct scene *ras_test_scene(const char *name);

#endif
