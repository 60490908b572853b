/* SPDX-License-Identifier: MIT */
/* rt_acc_api.h — the ray tracer of each numeric mode side by side in one
 * program (the accuracy test). Each mode's core and scene parser are linked
 * into one object whose only global symbol is rtacc_<mode> (mk/raytracer.mk). */
#ifndef RT_ACC_API_H
#define RT_ACC_API_H

#include <stdint.h>

struct rtacc_api {
    const char *numeric;
    /* Renders book scene raytracer-0n at w x h (formulation: 0 the mode's
     * default, 1 book, 2 robust) into rgb888 (3*w*h) and, when probe is not
     * NULL, the primary hits' shadow bits (w*h). 0 on success. */
    int (*render_book)(int n, int w, int h, int formulation, uint8_t *rgb888, uint8_t *probe);
    /* The same with the camera moved by (dx, dy, dz) scene units. */
    int (*render_moved)(int n, int w, int h, double dx, double dy, double dz, uint8_t *rgb888, uint8_t *probe);
    /* When not NULL, the renders above also write the item each pixel's
     * primary ray hit (-1: none; w*h). */
    int16_t **item_probe;
    /* NUM_FRAC the format analysis chooses for raytracer-0n at w x h
     * (tools/scene/scene_format.c; -1: refused); meaningful on the double
     * build, whose scene holds the exact values. */
    int (*scene_frac)(int n, int w, int h);
    uint32_t *saturations;
    /* The format's resolution in scene units near the book scenes' objects:
     * fixed 2^-NUM_FRAC; float 2^-21 (24 bits at coordinates up to 8). */
    double resolution;
};

extern const struct rtacc_api rtacc_fixed, rtacc_float, rtacc_double;
/* Fixed point at NUM_FRAC 17 (the format of raytracer-01 ... 04). */
extern const struct rtacc_api rtacc_fixed17;

#endif
