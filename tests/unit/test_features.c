/* SPDX-License-Identifier: MIT */
/* test_features.c — a core built without some renderer features
 * (scene_features.def; tests/system/test_features.sh builds it with
 * FW_FEATURE_RAYTRACER 0 and FW_FEATURE_RAS_FAST 0): render_features names
 * what each scene needs, and render_init refuses exactly the scenes that
 * need a feature the build left out, renders the others.
 * usage: test_features SCENE=MISSING... (MISSING: 1 refused, 0 rendered) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "render.h"
#include "scene_parse.h"

int main(int argc, char **argv)
{
    check(RENDER_FEATURES_BUILT == (RENDER_FEATURES_ALL & ~(RENDER_F(RAYTRACER) | RENDER_F(RAS_FAST))),
          "features_built", "0x%lx", (unsigned long)RENDER_FEATURES_BUILT);
    for (int i = 1; i < argc; i++) {
        char path[512], err[600];
        snprintf(path, sizeof path, "%s", argv[i]);
        char *eq = strrchr(path, '=');
        if (!eq) return 2;
        *eq = 0;
        int want_missing = eq[1] == '1';
        struct scene *s;
        if (scene_load(path, &s, err, sizeof err)) {
            check(0, path, "%s", err);
            continue;
        }
        uint32_t need = render_features(s), missing = need & ~RENDER_FEATURES_BUILT;
        size_t n = render_work_size(s, 64, 64, 8);
        void *w = malloc(n ? n : 1);
        struct render_ctx c;
        int rc = render_init(&c, s, 64, 64, 8, w, n);
        uint16_t px[64 * 8];
        struct render_target t = { 0 };
        t.rgb565 = px;
        t.width = 64;
        t.y1 = 8;
        if (rc == 0) rc = render_begin_frame(&c, 0) || render_strip(&c, &t, NULL);
        char name[600];
        snprintf(name, sizeof name, "features_%s", path);
        check((missing != 0) == want_missing && (rc != 0) == want_missing && need != 0, name,
              "needs 0x%lx, missing 0x%lx, render %d", (unsigned long)need, (unsigned long)missing, rc);
        free(w);
        scene_free(s);
    }
    return check_exit();
}
