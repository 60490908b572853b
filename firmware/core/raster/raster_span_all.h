/* SPDX-License-Identifier: MIT */
/* raster_span_all.h — every span loop the fast path selects and their
 * table SPAN_TABLE[shade][src][depth], for SPAN_HOST 0 (raster_spans.c)
 * or 1 (raster_spans_host.c). A new combination is one block below and
 * one row of the table (the compiler rejects a row without its loops, and
 * loops without their row stay unused, which -Werror rejects too), both
 * under its feature (scene_features.def), and the depth sizes under theirs
 * (raster_span_depths.h). */
#include "raster_span_lib.h"

#define SPAN_NAME_(tag, d) span_##tag##_z##d
#define SPAN_NAME_OF(tag, d) SPAN_NAME_(tag, d)

#if FW_FEATURE_SPAN_NONE_CONST
#define SPAN_SHADE SPAN_SHADE_NONE      /* flat or unlit */
#define SPAN_SRC SPAN_SRC_CONST
#define SPAN_TAG none_const
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_RGB_CONST
#define SPAN_SHADE SPAN_SHADE_RGB       /* Gouraud, levels */
#define SPAN_SRC SPAN_SRC_CONST
#define SPAN_TAG rgb_const
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_RGB_CONST
#define SPAN_SHADE SPAN_SHADE_LI        /* Gouraud, saturating */
#define SPAN_SRC SPAN_SRC_CONST
#define SPAN_TAG li_const
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_PHONG_CONST
#define SPAN_SHADE SPAN_SHADE_PHONG     /* fast Phong */
#define SPAN_SRC SPAN_SRC_CONST
#define SPAN_TAG phong_const
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_NONE_TEX
#define SPAN_SHADE SPAN_SHADE_NONE      /* texture, unlit */
#define SPAN_SRC SPAN_SRC_TEX
#define SPAN_TAG none_tex
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_LI_TEX
#define SPAN_SHADE SPAN_SHADE_LI        /* texture, Gouraud */
#define SPAN_SRC SPAN_SRC_TEX
#define SPAN_TAG li_tex
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_PHONG_TEX
#define SPAN_SHADE SPAN_SHADE_PHONG     /* texture, fast Phong */
#define SPAN_SRC SPAN_SRC_TEX
#define SPAN_TAG phong_tex
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_NONE_TEXBL
#define SPAN_SHADE SPAN_SHADE_NONE      /* texture, bilinear, unlit */
#define SPAN_SRC SPAN_SRC_TEXBL
#define SPAN_TAG none_texbl
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_LI_TEXBL
#define SPAN_SHADE SPAN_SHADE_LI        /* texture, bilinear, Gouraud */
#define SPAN_SRC SPAN_SRC_TEXBL
#define SPAN_TAG li_texbl
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_PHONG_TEXBL
#define SPAN_SHADE SPAN_SHADE_PHONG     /* texture, bilinear, fast Phong */
#define SPAN_SRC SPAN_SRC_TEXBL
#define SPAN_TAG phong_texbl
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_NONE_TEXBW
#define SPAN_SHADE SPAN_SHADE_NONE      /* texture, bilinear of one word, unlit */
#define SPAN_SRC SPAN_SRC_TEXBW
#define SPAN_TAG none_texbw
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_LI_TEXBW
#define SPAN_SHADE SPAN_SHADE_LI        /* texture, bilinear of one word, Gouraud */
#define SPAN_SRC SPAN_SRC_TEXBW
#define SPAN_TAG li_texbw
#include "raster_span_depths.h"
#endif
#if FW_FEATURE_SPAN_PHONG_TEXBW
#define SPAN_SHADE SPAN_SHADE_PHONG     /* texture, bilinear of one word, fast Phong */
#define SPAN_SRC SPAN_SRC_TEXBW
#define SPAN_TAG phong_texbw
#include "raster_span_depths.h"
#endif

/* a loop of a depth size the image left out (scene_features.def): no entry */
#if FW_FEATURE_SPAN_Z0
#define SPAN_Z0(tag) span_##tag##_z0
#else
#define SPAN_Z0(tag) NULL
#endif
#if FW_FEATURE_SPAN_Z2
#define SPAN_Z2(tag) span_##tag##_z2
#else
#define SPAN_Z2(tag) NULL
#endif
#if FW_FEATURE_SPAN_Z4
#define SPAN_Z4(tag) span_##tag##_z4
#else
#define SPAN_Z4(tag) NULL
#endif
#define SPAN_ROW(shade, src, tag) \
    [SPAN_SHADE_##shade][SPAN_SRC_##src] = { SPAN_Z0(tag), SPAN_Z2(tag), SPAN_Z4(tag) }
/* the rows of the combinations the image has (render_init refuses a scene
 * that needs another: raster_features) */
const span_fn SPAN_TABLE[SPAN_SHADES][SPAN_SRCS][SPAN_DEPTHS] = {
#if FW_FEATURE_SPAN_NONE_CONST
    SPAN_ROW(NONE, CONST, none_const),
#endif
#if FW_FEATURE_SPAN_RGB_CONST
    SPAN_ROW(RGB, CONST, rgb_const),
    SPAN_ROW(LI, CONST, li_const),
#endif
#if FW_FEATURE_SPAN_PHONG_CONST
    SPAN_ROW(PHONG, CONST, phong_const),
#endif
#if FW_FEATURE_SPAN_NONE_TEX
    SPAN_ROW(NONE, TEX, none_tex),
#endif
#if FW_FEATURE_SPAN_LI_TEX
    SPAN_ROW(LI, TEX, li_tex),
#endif
#if FW_FEATURE_SPAN_PHONG_TEX
    SPAN_ROW(PHONG, TEX, phong_tex),
#endif
#if FW_FEATURE_SPAN_NONE_TEXBL
    SPAN_ROW(NONE, TEXBL, none_texbl),
#endif
#if FW_FEATURE_SPAN_LI_TEXBL
    SPAN_ROW(LI, TEXBL, li_texbl),
#endif
#if FW_FEATURE_SPAN_PHONG_TEXBL
    SPAN_ROW(PHONG, TEXBL, phong_texbl),
#endif
#if FW_FEATURE_SPAN_NONE_TEXBW
    SPAN_ROW(NONE, TEXBW, none_texbw),
#endif
#if FW_FEATURE_SPAN_LI_TEXBW
    SPAN_ROW(LI, TEXBW, li_texbw),
#endif
#if FW_FEATURE_SPAN_PHONG_TEXBW
    SPAN_ROW(PHONG, TEXBW, phong_texbw),
#endif
#if !(FW_FEATURE_SPAN_NONE_CONST || FW_FEATURE_SPAN_RGB_CONST || FW_FEATURE_SPAN_PHONG_CONST || \
      FW_FEATURE_SPAN_NONE_TEX || FW_FEATURE_SPAN_LI_TEX || FW_FEATURE_SPAN_PHONG_TEX || \
      FW_FEATURE_SPAN_NONE_TEXBL || FW_FEATURE_SPAN_LI_TEXBL || FW_FEATURE_SPAN_PHONG_TEXBL || \
      FW_FEATURE_SPAN_NONE_TEXBW || FW_FEATURE_SPAN_LI_TEXBW || FW_FEATURE_SPAN_PHONG_TEXBW)
    { { NULL } },
#endif
};
