/* SPDX-License-Identifier: MIT */
/* raster_span_all.h — every span loop the fast path selects and their
 * table SPAN_TABLE[shade][src][depth], for SPAN_HOST 0 (raster_spans.c)
 * or 1 (raster_spans_host.c). A new combination is one block below and
 * one row of the table (the compiler rejects a row without its loops, and
 * loops without their row stay unused, which -Werror rejects too). */
#include "raster_span_lib.h"

#define SPAN_NAME_(tag, d) span_##tag##_z##d
#define SPAN_NAME_OF(tag, d) SPAN_NAME_(tag, d)

#define SPAN_SHADE SPAN_SHADE_NONE      /* flat or unlit */
#define SPAN_SRC SPAN_SRC_CONST
#define SPAN_TAG none_const
#include "raster_span_depths.h"
#define SPAN_SHADE SPAN_SHADE_RGB       /* Gouraud, levels */
#define SPAN_SRC SPAN_SRC_CONST
#define SPAN_TAG rgb_const
#include "raster_span_depths.h"
#define SPAN_SHADE SPAN_SHADE_LI        /* Gouraud, saturating */
#define SPAN_SRC SPAN_SRC_CONST
#define SPAN_TAG li_const
#include "raster_span_depths.h"
#define SPAN_SHADE SPAN_SHADE_PHONG     /* fast Phong */
#define SPAN_SRC SPAN_SRC_CONST
#define SPAN_TAG phong_const
#include "raster_span_depths.h"
#define SPAN_SHADE SPAN_SHADE_NONE      /* texture, unlit */
#define SPAN_SRC SPAN_SRC_TEX
#define SPAN_TAG none_tex
#include "raster_span_depths.h"
#define SPAN_SHADE SPAN_SHADE_LI        /* texture, Gouraud */
#define SPAN_SRC SPAN_SRC_TEX
#define SPAN_TAG li_tex
#include "raster_span_depths.h"
#define SPAN_SHADE SPAN_SHADE_PHONG     /* texture, fast Phong */
#define SPAN_SRC SPAN_SRC_TEX
#define SPAN_TAG phong_tex
#include "raster_span_depths.h"
#define SPAN_SHADE SPAN_SHADE_NONE      /* texture, bilinear, unlit */
#define SPAN_SRC SPAN_SRC_TEXBL
#define SPAN_TAG none_texbl
#include "raster_span_depths.h"
#define SPAN_SHADE SPAN_SHADE_LI        /* texture, bilinear, Gouraud */
#define SPAN_SRC SPAN_SRC_TEXBL
#define SPAN_TAG li_texbl
#include "raster_span_depths.h"
#define SPAN_SHADE SPAN_SHADE_PHONG     /* texture, bilinear, fast Phong */
#define SPAN_SRC SPAN_SRC_TEXBL
#define SPAN_TAG phong_texbl
#include "raster_span_depths.h"

#define SPAN_ROW(shade, src, tag) \
    [SPAN_SHADE_##shade][SPAN_SRC_##src] = { span_##tag##_z0, span_##tag##_z2, span_##tag##_z4 }
const span_fn SPAN_TABLE[SPAN_SHADES][SPAN_SRCS][SPAN_DEPTHS] = {
    SPAN_ROW(NONE, CONST, none_const),
    SPAN_ROW(RGB, CONST, rgb_const),
    SPAN_ROW(LI, CONST, li_const),
    SPAN_ROW(PHONG, CONST, phong_const),
    SPAN_ROW(NONE, TEX, none_tex),
    SPAN_ROW(LI, TEX, li_tex),
    SPAN_ROW(PHONG, TEX, phong_tex),
    SPAN_ROW(NONE, TEXBL, none_texbl),
    SPAN_ROW(LI, TEXBL, li_texbl),
    SPAN_ROW(PHONG, TEXBL, phong_texbl),
};
