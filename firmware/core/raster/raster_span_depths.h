/* SPDX-License-Identifier: MIT */
/* raster_span_depths.h — the three depth sizes of one span combination
 * (SPAN_SHADE, SPAN_SRC, SPAN_TAG naming it): span_<tag>_z0, _z2, _z4,
 * each under its feature (scene_features.def). */
#if FW_FEATURE_SPAN_Z0
#define SPAN_DEPTH 0
#define SPAN_NAME SPAN_NAME_OF(SPAN_TAG, 0)
#include "raster_span.h"
#endif
#if FW_FEATURE_SPAN_Z2
#define SPAN_DEPTH 2
#define SPAN_NAME SPAN_NAME_OF(SPAN_TAG, 2)
#include "raster_span.h"
#endif
#if FW_FEATURE_SPAN_Z4
#define SPAN_DEPTH 4
#define SPAN_NAME SPAN_NAME_OF(SPAN_TAG, 4)
#include "raster_span.h"
#endif
#undef SPAN_SHADE
#undef SPAN_SRC
#undef SPAN_TAG
