/* SPDX-License-Identifier: MIT */
/* Minimal test helpers: each case prints "PASS name" or "FAIL name: why";
 * tests/support/run.sh totals them. A test program returns check_exit(). */
#ifndef TESTS_CHECK_H
#define TESTS_CHECK_H

#include <stdio.h>
#include <stdarg.h>

static int check_failures;

/* Records one case: cond true passes; otherwise prints the formatted reason. */
static inline int check(int cond, const char *name, const char *fmt, ...)
{
    if (cond) {
        printf("PASS %s\n", name);
    } else {
        va_list ap;
        printf("FAIL %s: ", name);
        va_start(ap, fmt);
        vprintf(fmt, ap);
        va_end(ap);
        printf("\n");
        check_failures++;
    }
    fflush(stdout);
    return cond;
}

static inline int check_exit(void) { return check_failures ? 1 : 0; }

#endif
