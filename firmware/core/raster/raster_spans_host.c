/* SPDX-License-Identifier: MIT */
/* raster_spans_host.c — the same loops with the host's outputs as well
 * (rgb888, written map, pixels written); left out of builds without them
 * (RENDER_HOST_OUTPUTS 0: the board images). */
#include "raster_fast.h"

#if RENDER_HOST_OUTPUTS
#define SPAN_HOST 1
#define SPAN_TABLE ras_span_host
#include "raster_span_all.h"
#else
typedef int ras_spans_host_left_out;   /* (a translation unit may not be empty) */
#endif
