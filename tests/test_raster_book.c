/* test_raster_book.c — the book path (ras_options.book_exact) in the double
 * build at 600x600 reproduces the demos' reference digests (book-scenes.md
 * Appendix A), whole frame and in strips. */
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "raster_harness.h"
#include "raster_scenes.h"

static const struct { const char *name; long written; const char *digest; } refs[] = {
    { "raster-01", 551, "ad20bd43d34a1db2" },   { "raster-02", 881, "30d10a2bf363e381" },
    { "raster-03", 67179, "f5ea238b253d3b2d" }, { "raster-04", 67246, "b67542a95364dd04" },
    { "raster-05", 992, "58840995734152f4" },   { "raster-06", 2509, "f78d55ebe1e48d7f" },
    { "raster-07", 4999, "42b71d786b125e90" },  { "raster-08", 5648, "25d25b128ba67462" },
    { "raster-09", 5648, "25d25b128ba67462" },  { "raster-10", 98820, "dd24e787ef86f8cf" },
    { "raster-11", 160789, "20fe4df8f257c722" }, { "raster-12", 136399, NULL },
    { "raster-13", 193606, "a5aeeae10b0a8b83" }, { "raster-rt-scene", 213197, "0df09e3ac5a4a8cd" },
};

/* Non-default modes with known digests. */
static void variants(const char *tmp)
{
    static const struct { const char *scene, *what, *digest; } v[] = {
        { "raster-10", "nodepth", "ebd4f4425248ed5d" }, { "raster-11", "flat", "aa12619ff8474d0b" },
        { "raster-11", "gouraud", "200e10ffb1b07eb5" }, { "raster-13", "linear_uv", "113b449eb5feb64d" },
    };
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
        struct scene *s = ras_test_scene(v[i].scene);
        if (!strcmp(v[i].what, "nodepth")) s->ras.depth_test = s->ras.backface_cull = 0;
        if (!strcmp(v[i].what, "flat")) s->ras.shading = SHADE_FLAT;
        if (!strcmp(v[i].what, "gouraud")) s->ras.shading = SHADE_GOURAUD;
        if (!strcmp(v[i].what, "linear_uv")) s->ras.perspective_uv = 0;
        struct frame f;
        char d[17] = "", name[96];
        int rc = render_frame(s, 600, 600, 600, 0, &f);
        if (!rc) rc = frame_digest(&f, tmp, d);
        snprintf(name, sizeof name, "book_digest_%s_%s", v[i].scene, v[i].what);
        check(!rc && !strcmp(d, v[i].digest), name, "digest %s, want %s", d, v[i].digest);
        frame_free(&f);
    }
}

int main(int argc, char **argv)
{
    const char *tmp = argc > 1 ? argv[1] : "/tmp";
    for (size_t i = 0; i < sizeof refs / sizeof refs[0]; i++) {
        struct scene *s = ras_test_scene(refs[i].name);
        struct frame f, g;
        char d[17] = "", name[96];
        int rc = render_frame(s, 600, 600, 600, 0, &f);
        if (!rc && refs[i].digest) rc = frame_digest(&f, tmp, d);
        long n = rc ? -1 : frame_written(&f);
        snprintf(name, sizeof name, "book_digest_%s", refs[i].name);
        if (refs[i].digest)
            check(!rc && n == refs[i].written && !strcmp(d, refs[i].digest), name,
                  "written %ld (want %ld), digest %s (want %s)", n, refs[i].written, d, refs[i].digest);
        else
            check(!rc && n == refs[i].written, name, "written %ld (want %ld)", n, refs[i].written);
        /* strips of 16 rows give the same image */
        rc = render_frame(s, 600, 600, 16, 0, &g);
        snprintf(name, sizeof name, "book_strips16_same_%s", refs[i].name);
        check(!rc && !memcmp(f.rgb888, g.rgb888, 600 * 600 * 3) && !memcmp(f.written, g.written, 600 * 600), name,
              "strip rendering differs from the whole frame");
        frame_free(&f);
        frame_free(&g);
    }
    variants(tmp);
    return check_exit();
}
