/* SPDX-License-Identifier: MIT */
/* code_probe.c — every entry point of render.h an application calls, on a
 * scene the compiler cannot see (probe_scene): linked for the Cortex-M0+
 * with --gc-sections against a core compiled with one scene's features
 * (tools/scenec/scene_code.sh), what is left is the renderer code an image
 * of that scene carries. Never run. */
#include "render.h"

const struct scene *volatile probe_scene;
static struct render_ctx ctx[2];
static _Alignas(8) uint8_t work[2][64];
static uint16_t strip[64];

int main(void)
{
    const struct scene *s = probe_scene;
    struct render_target t = { 0 };
    t.rgb565 = strip;
    t.width = 8;
    t.y1 = 1;
    int rc = (int)render_features(s) + (int)render_work_size(s, 8, 8, 1) + (int)render_sibling_work_size(s, 8, 8, 1);
    rc += render_init(&ctx[0], s, 8, 8, 1, work[0], sizeof work[0]);
    rc += render_init_sibling(&ctx[1], &ctx[0], work[1], sizeof work[1]);
    rc += render_set_pass(&ctx[0], RENDER_PASS_COARSE) + render_set_round(&ctx[0], 1);
    rc += render_frame_start(&ctx[0], 0) + render_frame_vertices(&ctx[0], 0, 2) +
          render_frame_triangles(&ctx[0], 0, 2) + render_frame_finish(&ctx[0]);
    rc += render_begin_frame(&ctx[0], 1) + render_begin_frame(&ctx[1], 1);
    rc += render_strip(&ctx[0], &t, NULL) + render_strip(&ctx[1], &t, NULL);
    return rc + render_background_565(&ctx[0]);
}
