/* SPDX-License-Identifier: MIT */
/* scenes_builtin.c — the scene table when no compiled scenes are given: one
 * small C-built scene (an empty raster scene: its dark blue background), so
 * the whole chain runs without the scene compiler. */
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

/* Work memory for the built-in scene: enough for a raster scene's strip
 * state at 240x240 with 8-row strips (the scene compiler sizes it exactly). */
#ifndef FW_BUILTIN_WORK
#define FW_BUILTIN_WORK 1024
#endif
static uint64_t work0[FW_BUILTIN_WORK / 8], work1[FW_BUILTIN_WORK / 8];

const struct fw_scene fw_scenes[] = {
    { "builtin/pattern", &builtin_pattern, { work0, work1 }, { sizeof work0, sizeof work1 } },
};
const unsigned fw_scene_count = sizeof fw_scenes / sizeof fw_scenes[0];
