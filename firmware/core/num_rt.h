/* num_rt.h — what the ray tracer needs to know about the numeric mode.
 *
 * The ray tracer is one source for the three modes (no NUM_MODE tests in
 * it); the one mode-dependent choice it makes is which formulation of the
 * intersection and normal computations a scene gets by default:
 * - double, the reference build: the book demos' operation order, literally,
 *   so that the demos' reference images are reproduced bit for bit;
 * - fixed and float: the robust formulation (stable quadratic with wide
 *   intermediates, analytic self-intersection), which holds for the
 *   radius-5000 ground sphere in Q15.16 and in single precision.
 * rt_options.formulation overrides the default per scene.
 */
#ifndef NUM_RT_H
#define NUM_RT_H

#include "num.h"

/* 1 when the mode is the reference (double), 0 otherwise. */
static inline int num_rt_reference_mode(void)
{
#if NUM_MODE == NUM_MODE_DOUBLE
    return 1;
#else
    return 0;
#endif
}

#endif
