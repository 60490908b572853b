/* SPDX-License-Identifier: MIT */
/* scene_layout.h — the sizes of the types a compiled scene's const data is
 * made of (tools/scenec), as one build lays them out: the work probe's
 * (tools/scenec/work_probe.c, the Cortex-M0+ in fixed point: the target's)
 * or this host's fixed-point build (an upper bound: pointers take 8 bytes
 * here and 4 on the target). scenec counts a scene's flash with them.
 *
 * The text form, "scene=N,light=N,...", names each type once in the order
 * below (the work probe prints it, tools/scenec/target_work.sh passes it on,
 * scenec --target-work reads it). */
#ifndef SCENE_LAYOUT_H
#define SCENE_LAYOUT_H
#include <stddef.h>

/* X(name, type) */
#define SCENE_LAYOUT_TYPES(X) \
    X(scene, struct scene) \
    X(light, struct scene_light) \
    X(object, struct rt_object) \
    X(csg, struct rt_csg) \
    X(vec3, vec3) \
    X(tri, struct ras_triangle) \
    X(model, struct ras_model) \
    X(texture, struct ras_texture) \
    X(instance, struct ras_instance) \
    X(prim, struct prim2d) \
    X(line, struct line3d) \
    X(ptr, const void *)

enum scene_layout_type {
#define SCENE_LAYOUT_ENUM(name, type) SCENE_LAYOUT_##name,
    SCENE_LAYOUT_TYPES(SCENE_LAYOUT_ENUM)
#undef SCENE_LAYOUT_ENUM
        SCENE_LAYOUT_COUNT
};

struct scene_layout {
    size_t size[SCENE_LAYOUT_COUNT]; /* bytes, by enum scene_layout_type */
};

/* The type names of the text form, by enum scene_layout_type. */
extern const char *const scene_layout_names[SCENE_LAYOUT_COUNT];

/* This build's sizes (sizeof of each type as compiled here). */
void scene_layout_of_build(struct scene_layout *l);

/* The text form into buf (at most n bytes with its NUL); 0, or -1 when it
 * does not fit. */
int scene_layout_format(const struct scene_layout *l, char *buf, size_t n);

/* The text form s (exactly every name once, in any order, each size 1 ..
 * 1000000) into *l; 0, or -1 (l unchanged). */
int scene_layout_parse(const char *s, struct scene_layout *l);

#endif
