/* SPDX-License-Identifier: MIT */
/* quality_opts.c — host_sim's --min-psnr and --target (docs/host_sim.md). */
#include <stdio.h>
#include <string.h>

#include "host_sim/quality_opts.h"
#include "tools/quality/quality.h"
#include "tools/scene/suggest.h"

int quality_opts_set(struct quality_opts *q, const char *name, const char *val)
{
    if (!strcmp(name, "--min-psnr")) {
        if (quality_parse_psnr(val, &q->min_psnr)) {
            fprintf(stderr, "host_sim: bad --min-psnr '%s' (a PSNR in dB, 1 .. 200)\n", val);
            return 2;
        }
        return 0;
    }
    if (!strcmp(name, "--target")) {
        static const char *const names[] = { "m0plus", "m4f", "rp2040", NULL };
        if (!(q->target = quality_target_of(val))) {
            const char *near = suggest_nearest(val, names);
            fprintf(stderr, "host_sim: unknown --target '%s'%s%s%s (m0plus, m4f or rp2040)\n", val,
                    near ? " (did you mean '" : "", near ? near : "", near ? "'?)" : "");
            return 2;
        }
        return 0;
    }
    return 1;
}
