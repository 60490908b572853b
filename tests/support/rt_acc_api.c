/* SPDX-License-Identifier: MIT */
/* rt_acc_api.c — one mode's entry in the accuracy test (compiled per mode). */
#include "rt_acc_api.h"
#include "rt_render.h"
#include "scene_files.h"
#include "scene_format.h"

static int16_t *item_probe;

/* Book scene raytracer-0n (NULL: no such scene). */
static struct scene *book_rt(int n)
{
    if (n < 1 || n > 9) return NULL;
    char name[32];
    snprintf(name, sizeof name, "raytracer-0%d", n);
    return book_scene(name);
}

static int render_book(int n, int w, int h, int formulation, uint8_t *rgb888, uint8_t *probe)
{
    struct scene *s = book_rt(n);
    if (!s) return -1;
    s->rt.formulation = (uint8_t)formulation;
    rt_render_item_probe = item_probe;
    return rt_render(s, w, h, 16, rgb888, probe, NULL);
}

static int render_moved(int n, int w, int h, double dx, double dy, double dz, uint8_t *rgb888, uint8_t *probe)
{
    struct scene *s = book_rt(n);
    if (!s) return -1;
    vec3 p = s->camera.position;
    s->camera.position = v3_make(num_from_double(num_to_double(p.x) + dx), num_from_double(num_to_double(p.y) + dy),
                                 num_from_double(num_to_double(p.z) + dz));
    rt_render_item_probe = item_probe;
    return rt_render(s, w, h, 16, rgb888, probe, NULL);
}

static int scene_frac(int n, int w, int h)
{
    struct scene *s = book_rt(n);
    struct scene_format f;
    if (!s || scene_format_choose(s, w, h, NULL, 0, 0, &f) != 0) return -1;
    return f.num_frac;
}

#if NUM_MODE == NUM_MODE_FIXED
#define RTACC_RES (1.0 / (double)NUM_ONE_RAW)
#else
#define RTACC_RES (1.0 / 2097152.0)
#endif

/* RTACC_NAME (rtacc_fixed, ...) comes from the build, one per mode. */
const struct rtacc_api RTACC_NAME = { NUM_NAME, render_book, render_moved, &item_probe, scene_frac, &num_saturations,
                                      RTACC_RES };
