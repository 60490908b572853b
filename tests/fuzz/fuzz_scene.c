/* SPDX-License-Identifier: MIT */
/* fuzz_scene — libFuzzer target for the scene parser: any input must give
 * 0 (a scene, which is then walked) or SCENE_EINPUT with a one-line
 * "FILE:LINE:COLUMN: error: ..." message; never a crash, leak or hang. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "scene_parse.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[512];
    struct scene *s = NULL;
    int rc = scene_parse_mem("fuzz.scene", (const char *)data, size, &s, err, sizeof err);
    if (rc == 0) {
        /* touch what the renderers read */
        uint32_t bad = 0;
        for (int i = 0; i < s->ninstances; i++) {
            const struct ras_model *m = &s->models[s->instances[i].model];
            for (int t = 0; t < m->ntris; t++)
                for (int k = 0; k < 3; k++) bad += m->tris[t].v[k] < m->nverts ? 0 : 1;
            if (s->instances[i].texture >= 0) bad += s->textures[s->instances[i].texture].w == 0;
        }
        if (bad) abort();
        scene_free(s);
    } else if (rc != SCENE_EINPUT || strncmp(err, "fuzz.scene:", 11) || !strstr(err, ": error: ") || strchr(err, '\n')) {
        abort();
    }
    return 0;
}
