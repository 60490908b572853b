/* SPDX-License-Identifier: MIT */
/* core_fracs.c — picks the fixed-point core of a NUM_FRAC (mk/core.mk bundles
 * one per format the scene analysis may choose). */
#include "core_api.h"

extern const struct core_api core_api_fixed12, core_api_fixed13, core_api_fixed14, core_api_fixed15,
    core_api_fixed17, core_api_fixed18, core_api_fixed19, core_api_fixed20;

const struct core_api *core_api_fixed_frac(int frac)
{
    static const struct core_api *const cores[SCENE_FORMAT_FRAC_MAX - SCENE_FORMAT_FRAC_MIN + 1] = {
        &core_api_fixed12, &core_api_fixed13, &core_api_fixed14, &core_api_fixed15, &core_api_fixed,
        &core_api_fixed17, &core_api_fixed18, &core_api_fixed19, &core_api_fixed20,
    };
    if (frac < SCENE_FORMAT_FRAC_MIN || frac > SCENE_FORMAT_FRAC_MAX) return 0;
    return cores[frac - SCENE_FORMAT_FRAC_MIN];
}
