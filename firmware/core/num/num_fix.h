/* SPDX-License-Identifier: MIT */
/* num_fix.h — what the fixed-point build's definitions share (num.c,
 * num_sqrt.c): the saturation counter's hook and two small
 * helpers. Internal to the numeric layer. */
#ifndef NUM_FIX_H
#define NUM_FIX_H

#include "num_int.h"

#ifdef NUM_COUNT_SAT
#define SAT_HIT() (num_saturations++)
#else
#define SAT_HIT() ((void)0)
#endif

/* Magnitude q with sign neg, saturated to [NUM_MIN, NUM_MAX]. */
static inline num sat_signed(uint64_t q, int neg)
{
    if (q > (uint64_t)INT32_MAX) { SAT_HIT(); return neg ? NUM_MIN : NUM_MAX; }
    return neg ? -(num)q : (num)q;
}

static inline uint32_t uabs32(int32_t a) { return a < 0 ? 0u - (uint32_t)a : (uint32_t)a; }

#endif
