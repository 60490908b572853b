/* Placeholder loader: checks the file can be read and returns a scene with
 * a background only. The real parser replaces it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_parse.h"

int scene_load(const char *path, struct scene **out, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s:1:1: error: cannot open file", path);
        return 2;
    }
    fclose(f);
    struct scene *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "%s:1:1: error: out of memory", path);
        return 2;
    }
    s->name = "placeholder";
    s->kind = strstr(path, "raster") ? SCENE_RASTER : SCENE_RAYTRACE;
    s->canvas_w = s->canvas_h = 600;
    s->frames = 1;
    s->background = rgb_make(NUM_C(0.0), NUM_C(0.0), NUM_C(64.0));
    s->background_set = 1;
    *out = s;
    return 0;
}

void scene_free(struct scene *s) { free(s); }
