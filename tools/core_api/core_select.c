/* SPDX-License-Identifier: MIT */
/* core_select.c — picks a numeric mode's core by name. */
#include <string.h>
#include "core_api.h"

const struct core_api *core_api_by_name(const char *numeric)
{
    if (!strcmp(numeric, "fixed")) return &core_api_fixed;
    if (!strcmp(numeric, "float")) return &core_api_float;
    if (!strcmp(numeric, "double")) return &core_api_double;
    return NULL;
}
