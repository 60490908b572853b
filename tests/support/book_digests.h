/* SPDX-License-Identifier: MIT */
/* book_digests.h — the reference digests of the book's demos, read from
 * tests/data/book_digests.txt (the only place they are written down).
 *
 *   int n = book_digests_read(refs, BOOK_DIGESTS_MAX);
 *
 * fills refs[0 .. n-1] in file order, or prints one FAIL line and returns
 * -1 when the file cannot be read or a line is malformed. The path is
 * relative to the repository's top directory, where tests run. */
#ifndef TESTS_BOOK_DIGESTS_H
#define TESTS_BOOK_DIGESTS_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BOOK_DIGESTS_FILE "tests/data/book_digests.txt"
#define BOOK_DIGESTS_MAX 64

struct book_digest {
    char scene[40];     /* "raytracer-05", "raster-rt-scene" */
    char options[80];   /* "" or "KEY=VALUE[,KEY=VALUE]" */
    long written;       /* -1: not checked */
    char digest[17];    /* "" : not checked */
};

static inline int book_digests_read(struct book_digest *out, int max)
{
    FILE *f = fopen(BOOK_DIGESTS_FILE, "r");
    if (!f) {
        printf("FAIL book_digests: cannot open %s\n", BOOK_DIGESTS_FILE);
        return -1;
    }
    char line[256];
    int n = 0, lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        char scene[64], opts[128], written[32], digest[64], extra[2];
        int k = sscanf(line, "%63s %127s %31s %63s %1s", scene, opts, written, digest, extra);
        if (k <= 0 || scene[0] == '#') continue;
        char *end = NULL;
        long w = strcmp(written, "-") ? strtol(written, &end, 10) : -1;
        if (k != 4 || n == max || strlen(scene) >= sizeof out->scene || strlen(opts) >= sizeof out->options ||
            (w != -1 && (*end || w < 0)) || (strcmp(digest, "-") && strlen(digest) != 16)) {
            printf("FAIL book_digests: %s:%d: want \"scene options written digest\"\n", BOOK_DIGESTS_FILE, lineno);
            fclose(f);
            return -1;
        }
        struct book_digest *d = &out[n++];
        memcpy(d->scene, scene, strlen(scene) + 1);
        if (strcmp(opts, "-")) memcpy(d->options, opts, strlen(opts) + 1);
        else d->options[0] = 0;
        d->written = w;
        if (strcmp(digest, "-")) memcpy(d->digest, digest, sizeof d->digest);
        else d->digest[0] = 0;
    }
    fclose(f);
    return n;
}

#endif
