/* SPDX-License-Identifier: MIT */
/* test_spec_tables.c — fast Phong's specular tables as tools/scenec writes
 * them (--spec-tables flash: struct scene's nspec, spec_tab, spec_step)
 * against the ones this core makes (raster_spec_table, render_init's), at
 * the NUM_FRAC it is compiled at: the scene compiled by scenec
 * (tests/data/spec/exponents*.scene, identifier spec_scene) is linked in;
 * the same exponents in the same order, the same bits, the work memory
 * less their copies, and a frame's pixels the same with the tables given
 * and made. mk/scene.mk builds it at every format the scene holds. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "raster.h"
#include "render.h"

extern const struct scene scene_spec_scene;

#define W 64
#define H 64
#define ROWS 16

/* Frame 0 of s into px (W x H RGB565): 0, or -1. */
static int frame(const struct scene *s, uint16_t *px)
{
    size_t need = render_work_size(s, W, H, ROWS);
    void *work = malloc(need);
    struct render_ctx ctx;
    int rc = work && !render_init(&ctx, s, W, H, ROWS, work, need) && !render_begin_frame(&ctx, 0) ? 0 : -1;
    for (uint16_t y = 0; !rc && y < H; y += ROWS) {
        struct render_target t = { 0 };
        t.width = W;
        t.height = H;
        t.y0 = y;
        t.y1 = (uint16_t)(y + ROWS);
        t.rgb565 = px + (size_t)y * W;
        if (render_strip(&ctx, &t, NULL)) rc = -1;
    }
    free(work);
    return rc;
}

int main(void)
{
    const struct scene *s = &scene_spec_scene;
    uint32_t exps[RASTER_SPEC_MAX];
    uint16_t n = raster_spec_exponents(s, exps);
    char name[64];
    snprintf(name, sizeof name, "spec_tables_given_frac%d", NUM_FRAC);
    if (!check(n > 0 && s->nspec == n && s->spec_tab && s->spec_step, name, "scenec's %u tables, the core's %u",
               s->nspec, n))
        return check_exit();
    int bad = 0;
    for (uint16_t k = 0; k < n; k++) {
        uint16_t t[257];
        uint32_t step[2];
        raster_spec_table(t, exps[k], step);
        int same = !memcmp(t, s->spec_tab + 257 * k, sizeof t) && !memcmp(step, s->spec_step + 2 * k, sizeof step);
        snprintf(name, sizeof name, "spec_table_e%lu_frac%d", (unsigned long)exps[k], NUM_FRAC);
        bad += !check(same, name, "scenec's table of exponent %lu differs from raster_spec_table's",
                      (unsigned long)exps[k]);
    }
    /* the same scene without them: render_init makes them */
    struct scene v = *s;
    v.spec_tab = NULL;
    v.spec_step = NULL;
    v.nspec = 0;
    size_t with = render_work_size(s, W, H, ROWS), without = render_work_size(&v, W, H, ROWS);
    snprintf(name, sizeof name, "spec_tables_work_frac%d", NUM_FRAC);
    check(without >= with + (size_t)n * (257 * 2 + 2 * 4), name, "work %zu with the tables, %zu without", with,
          without);
    static uint16_t a[W * H], b[W * H];
    snprintf(name, sizeof name, "spec_tables_pixels_frac%d", NUM_FRAC);
    int fa = frame(s, a), fb = frame(&v, b);
    check(!fa && !fb && !memcmp(a, b, sizeof a), name, "frame 0 %s", fa || fb ? "not rendered" : "differs");
    return check_exit();
}
