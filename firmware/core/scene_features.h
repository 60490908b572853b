/* SPDX-License-Identifier: MIT */
/* scene_features.h — the renderer features an image is compiled with
 * (scene_features.def): FW_FEATURE_<NAME> 1 (in) or 0 (left out), each 1 unless
 * the build defines it (a board image of a scene set -include's the header
 * tools/scenec/features.sh writes for its scenes); RENDER_F(NAME), a
 * feature's bit in a mask; RENDER_FEATURES_ALL, every feature;
 * RENDER_FEATURES_BUILT, those of this build. render_init refuses a scene
 * that needs a feature the build left out (render_features, render.h). */
#ifndef SCENE_FEATURES_H
#define SCENE_FEATURES_H

#include <stdint.h>

enum render_feature_bit {
#define FEATURE(name, doc) RENDER_FEATURE_BIT_##name,
#include "scene_features.def"
    RENDER_FEATURE_COUNT
};
#define RENDER_F(name) ((uint32_t)1 << RENDER_FEATURE_BIT_##name)
#define RENDER_FEATURES_ALL ((uint32_t)(((uint64_t)1 << RENDER_FEATURE_COUNT) - 1u))
typedef char render_features_fit[RENDER_FEATURE_COUNT <= 31 ? 1 : -1];

/* one line a row of scene_features.def (a row without its line here fails to
 * compile: RENDER_FEATURES_BUILT names every FW_FEATURE_<NAME>) */
#ifndef FW_FEATURE_RAYTRACER
#define FW_FEATURE_RAYTRACER 1
#endif
#ifndef FW_FEATURE_RASTER
#define FW_FEATURE_RASTER 1
#endif
#ifndef FW_FEATURE_RAS_BOOK
#define FW_FEATURE_RAS_BOOK 1
#endif
#ifndef FW_FEATURE_RAS_DEFAULT
#define FW_FEATURE_RAS_DEFAULT 1
#endif
#ifndef FW_FEATURE_RAS_2D
#define FW_FEATURE_RAS_2D 1
#endif
#ifndef FW_FEATURE_RAS_CH15
#define FW_FEATURE_RAS_CH15 1
#endif
#ifndef FW_FEATURE_RAS_FAST
#define FW_FEATURE_RAS_FAST 1
#endif
#ifndef FW_FEATURE_RAS_FAST_PHONG
#define FW_FEATURE_RAS_FAST_PHONG 1
#endif
#ifndef FW_FEATURE_SPAN_NONE_CONST
#define FW_FEATURE_SPAN_NONE_CONST 1
#endif
#ifndef FW_FEATURE_SPAN_RGB_CONST
#define FW_FEATURE_SPAN_RGB_CONST 1
#endif
#ifndef FW_FEATURE_SPAN_PHONG_CONST
#define FW_FEATURE_SPAN_PHONG_CONST 1
#endif
#ifndef FW_FEATURE_SPAN_NONE_TEX
#define FW_FEATURE_SPAN_NONE_TEX 1
#endif
#ifndef FW_FEATURE_SPAN_LI_TEX
#define FW_FEATURE_SPAN_LI_TEX 1
#endif
#ifndef FW_FEATURE_SPAN_PHONG_TEX
#define FW_FEATURE_SPAN_PHONG_TEX 1
#endif
#ifndef FW_FEATURE_SPAN_NONE_TEXBL
#define FW_FEATURE_SPAN_NONE_TEXBL 1
#endif
#ifndef FW_FEATURE_SPAN_LI_TEXBL
#define FW_FEATURE_SPAN_LI_TEXBL 1
#endif
#ifndef FW_FEATURE_SPAN_PHONG_TEXBL
#define FW_FEATURE_SPAN_PHONG_TEXBL 1
#endif
#ifndef FW_FEATURE_SPAN_NONE_TEXBW
#define FW_FEATURE_SPAN_NONE_TEXBW 1
#endif
#ifndef FW_FEATURE_SPAN_LI_TEXBW
#define FW_FEATURE_SPAN_LI_TEXBW 1
#endif
#ifndef FW_FEATURE_SPAN_PHONG_TEXBW
#define FW_FEATURE_SPAN_PHONG_TEXBW 1
#endif
#ifndef FW_FEATURE_SPAN_Z0
#define FW_FEATURE_SPAN_Z0 1
#endif
#ifndef FW_FEATURE_SPAN_Z2
#define FW_FEATURE_SPAN_Z2 1
#endif
#ifndef FW_FEATURE_SPAN_Z4
#define FW_FEATURE_SPAN_Z4 1
#endif

/* the features of this build (an int constant: at most 31 rows) */
enum render_features_built {
    RENDER_FEATURES_BUILT_ = 0
#define FEATURE(name, doc) | (FW_FEATURE_##name ? 1 << RENDER_FEATURE_BIT_##name : 0)
#include "scene_features.def"
};
#define RENDER_FEATURES_BUILT ((uint32_t)RENDER_FEATURES_BUILT_)

#endif
