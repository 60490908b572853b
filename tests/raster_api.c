/* raster_api.c — one numeric mode's rasterizer and test scenes behind a
 * table, so test_raster_modes can compare the three builds in one program
 * (compiled once per NUM_MODE, bundled by mk/raster.mk). */
#include "raster_api.h"
#include "raster_harness.h"
#include "raster_scenes.h"

static int render(const char *name, int book_exact, int w, int h, int rows, struct frame *f)
{
    struct scene *s = ras_test_scene(name);
    if (!s) return -1;
    if (!book_exact) {
        s->ras.book_exact = 0;
        if (s->ras.clip) s->ras.clip = 2;
    }
    return render_frame(s, w, h, rows, 0, f);
}

#if NUM_MODE == NUM_MODE_FIXED
const struct raster_api raster_api_fixed = { "fixed", render };
#elif NUM_MODE == NUM_MODE_FLOAT
const struct raster_api raster_api_float = { "float", render };
#else
const struct raster_api raster_api_double = { "double", render };
#endif
