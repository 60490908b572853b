/* SPDX-License-Identifier: MIT */
/* raster_spans.c — the fast path's span loops for every image: RGB565
 * and depth only (raster_span.h, one loop per combination). */
#define SPAN_HOST 0
#define SPAN_TABLE ras_span_board
#include "raster_span_all.h"
