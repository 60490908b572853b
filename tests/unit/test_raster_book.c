/* SPDX-License-Identifier: MIT */
/* test_raster_book.c — the book path (ras_options.book_exact) in the double
 * build at 600x600 reproduces the demos' reference digests and coverage
 * (tests/data/book_digests.txt), whole frame and in strips, and those of
 * the non-default modes. The scenes are firmware/scenes/book's files. */
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "book_digests.h"
#include "raster_harness.h"
#include "scene_files.h"

int main(int argc, char **argv)
{
    const char *tmp = argc > 1 ? argv[1] : "/tmp";
    struct book_digest refs[BOOK_DIGESTS_MAX];
    int nrefs = book_digests_read(refs, BOOK_DIGESTS_MAX), tested = 0;
    for (int i = 0; i < nrefs; i++) {
        const struct book_digest *r = &refs[i];
        if (strncmp(r->scene, "raster-", 7)) continue;
        struct scene *s = book_scene(r->scene);
        struct frame f, g;
        char d[17] = "", name[160];
        snprintf(name, sizeof name, "book_digest_%s%s%s", r->scene, r->options[0] ? "_" : "", r->options);
        if (scene_options(s, r->options)) {
            check(0, name, "unknown option in %s", r->options);
            continue;
        }
        int rc = render_frame(s, 600, 600, 600, 0, &f);
        if (!rc && r->digest[0]) rc = frame_digest(&f, tmp, d);
        long n = rc ? -1 : frame_written(&f);
        check(!rc && (r->written < 0 || n == r->written) && (!r->digest[0] || !strcmp(d, r->digest)), name,
              "written %ld (want %ld), digest %s (want %s)", n, r->written, d, r->digest[0] ? r->digest : "-");
        tested++;
        /* strips of 16 rows give the same image */
        if (!r->options[0]) {
            rc = render_frame(s, 600, 600, 16, 0, &g);
            snprintf(name, sizeof name, "book_strips16_same_%s", r->scene);
            check(!rc && !memcmp(f.rgb888, g.rgb888, 600 * 600 * 3) && !memcmp(f.written, g.written, 600 * 600),
                  name, "strip rendering differs from the whole frame");
            frame_free(&g);
        }
        frame_free(&f);
    }
    check(tested > 0, "book_digests_raster_read", "no raster line in %s", BOOK_DIGESTS_FILE);
    return check_exit();
}
