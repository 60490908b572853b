/* scenes_builtin.c — the scene table when no compiled scenes are given: one
 * small C-built scene (the renderer's placeholder pattern on a dark blue
 * background), so the whole chain runs without the scene compiler. */
#include "fw_scenes.h"

static const struct scene builtin_pattern = {
    .name = "builtin/pattern",
    .kind = SCENE_RASTER,
    .canvas_w = 600,
    .canvas_h = 600,
    .viewport_w = NUM_C(1.0),
    .viewport_h = NUM_C(1.0),
    .projection_d = NUM_C(1.0),
    .background = { NUM_C(16.0), NUM_C(32.0), NUM_C(96.0) },
    .background_set = 1,
    .frames = 1,
};

const struct fw_scene fw_scenes[] = {
    { "builtin/pattern", &builtin_pattern, { NULL, NULL }, 0 },
};
const unsigned fw_scene_count = sizeof fw_scenes / sizeof fw_scenes[0];
