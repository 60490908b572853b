/* SPDX-License-Identifier: MIT */
/* quality_opts.h — host_sim's --min-psnr and --target (tools/quality). */
#ifndef QUALITY_OPTS_H
#define QUALITY_OPTS_H

struct quality_opts {
    double min_psnr; /* --min-psnr DB, 0: not given */
    int target;      /* --target, 0: not given (QUALITY_*) */
};

/* Option NAME with VAL into q: 0, 1 when NAME is not one of these, or 2
 * (usage error, its line printed). */
int quality_opts_set(struct quality_opts *q, const char *name, const char *val);

#endif
