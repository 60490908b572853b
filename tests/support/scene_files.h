/* SPDX-License-Identifier: MIT */
/* scene_files.h — scene files as test fixtures, loaded through the parser
 * (tools/scene/scene_parse.h) in the numeric mode the test is compiled in.
 *
 *   struct scene *s = scene_file("firmware/scenes/book/raytracer-05.scene");
 *
 * returns a freshly parsed scene, which the test may change; it stays valid
 * until the next call for the same path (which parses the file again). A
 * file that does not load is fatal: one FAIL line, exit status 1. Paths are
 * relative to the repository's top directory, where tests run.
 *
 * book_scene("raster-11") is scene_file of firmware/scenes/book/raster-11.scene;
 * scene_options(s, "shading=flat,uv=linear") applies the option changes of
 * tests/data/book_digests.txt. */
#ifndef TESTS_SCENE_FILES_H
#define TESTS_SCENE_FILES_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_parse.h"

#define SCENE_FILES_MAX 16

static inline struct scene *scene_file(const char *path)
{
    static struct { char path[160]; struct scene *s; } slot[SCENE_FILES_MAX];
    int i = 0;
    while (i < SCENE_FILES_MAX && slot[i].s && strcmp(slot[i].path, path)) i++;
    if (i == SCENE_FILES_MAX || strlen(path) >= sizeof slot[i].path) {
        printf("FAIL scene_file: too many scene files or too long a path: %s\n", path);
        exit(1);
    }
    if (slot[i].s) scene_free(slot[i].s);
    slot[i].s = NULL;
    char err[512];
    if (scene_load(path, &slot[i].s, err, sizeof err) != 0) {
        printf("FAIL scene_file: %s\n", err);
        exit(1);
    }
    snprintf(slot[i].path, sizeof slot[i].path, "%s", path);
    return slot[i].s;
}

static inline struct scene *book_scene(const char *name)
{
    char path[160];
    snprintf(path, sizeof path, "firmware/scenes/book/%s.scene", name);
    return scene_file(path);
}

/* Applies "KEY=VALUE[,KEY=VALUE]" (or "") to s: epsilon=0, recursion_depth=N,
 * depth=off, cull=off, shading=none|flat|gouraud|phong, uv=linear|perspective.
 * 0, or -1 for anything else. */
static inline int scene_options(struct scene *s, const char *opts)
{
    char buf[128];
    snprintf(buf, sizeof buf, "%s", opts);
    for (char *save = NULL, *kv = strtok_r(buf, ",", &save); kv; kv = strtok_r(NULL, ",", &save)) {
        char *v = strchr(kv, '=');
        if (!v) return -1;
        *v++ = 0;
        if (!strcmp(kv, "epsilon") && !strcmp(v, "0")) s->rt.epsilon = NUM_ZERO;
        else if (!strcmp(kv, "recursion_depth") && v[0] >= '0' && v[0] <= '9' && !v[1]) s->rt.recursion_depth = (uint8_t)(v[0] - '0');
        else if (!strcmp(kv, "depth") && !strcmp(v, "off")) s->ras.depth_test = 0;
        else if (!strcmp(kv, "cull") && !strcmp(v, "off")) s->ras.backface_cull = 0;
        else if (!strcmp(kv, "shading") && !strcmp(v, "none")) s->ras.shading = SHADE_NONE;
        else if (!strcmp(kv, "shading") && !strcmp(v, "flat")) s->ras.shading = SHADE_FLAT;
        else if (!strcmp(kv, "shading") && !strcmp(v, "gouraud")) s->ras.shading = SHADE_GOURAUD;
        else if (!strcmp(kv, "shading") && !strcmp(v, "phong")) s->ras.shading = SHADE_PHONG;
        else if (!strcmp(kv, "uv") && !strcmp(v, "linear")) s->ras.perspective_uv = 0;
        else if (!strcmp(kv, "uv") && !strcmp(v, "perspective")) s->ras.perspective_uv = 1;
        else return -1;
    }
    return 0;
}

#endif
