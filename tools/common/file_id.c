/* SPDX-License-Identifier: MIT */
/* file_id.c — see file_id.h. */
#define _XOPEN_SOURCE 700   /* realpath */
#include "file_id.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int file_norm_path(const char *path, char *out, size_t len)
{
    char dir[4096], *rd;
    const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
    size_t n = slash ? (size_t)(slash - path) : 0;
    if (slash && n == 0) n = 1;   /* "/file" */
    if (n >= sizeof dir) return -1;
    if (slash) memcpy(dir, path, n);
    else dir[n++] = '.';
    dir[n] = 0;
    if (!(rd = realpath(dir, NULL))) return -1;
    int w = snprintf(out, len, "%s/%s", strcmp(rd, "/") ? rd : "", base);
    free(rd);
    return w < 0 || (size_t)w >= len ? -1 : 0;
}

int file_same(const char *a, const char *b)
{
    struct stat sa, sb;
    int ea = !stat(a, &sa), eb = !stat(b, &sb);
    if (ea || eb) return ea && eb && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    char na[4200], nb[4200];
    if (file_norm_path(a, na, sizeof na) || file_norm_path(b, nb, sizeof nb)) return !strcmp(a, b);
    return !strcmp(na, nb);
}
