/* SPDX-License-Identifier: MIT */
/* panel_demo.c — the renderer and the HAL in a program of your own.
 *
 * Two scenes compiled by tools/scenec (the book's raytracer-02, ray-traced,
 * and raster-11, rasterized) are rendered strip by strip into two
 * alternating strip buffers and streamed to an ST7789 240x240 module
 * through panel.h, over a HAL of seven callbacks (trace_hal.c, whose bus is
 * a text trace on stdout). The same source builds for the host and for the
 * Cortex-M0+ (`make examples`, mk/examples.mk; docs/embedding.md).
 *
 * What it needs besides this file: the core (every .c of firmware/core), the DCS
 * layer and the panel drivers (hal/dcs.c, hal/panel*.c), the scenes' C
 * from scenec, all compiled with -DNUM_MODE=1 and the scenes' NUM_FRAC.
 * Exit status 0, or 1 with one line on stderr. */
#include <stdio.h>
#include "panel.h"
#include "render.h"
#include "trace_hal.h"
#include "raster_11.h"
#include "raytracer_02.h"

#define WIDTH 240
#define HEIGHT 240
#define ROWS 16    /* the strip height the scenes were compiled for (scenec --strip-rows) */

/* Two strip buffers: the renderer fills one while the bus sends the other
 * (with a DMA HAL; this one sends at once). */
static uint16_t strip[2][WIDTH * ROWS];

struct demo_scene {
    const char *name;
    const struct scene *scene;
    uint8_t *work;       /* scenec's work buffer for it, ..._WORK_SIZE bytes */
    size_t work_size;
};

static const struct demo_scene scenes[] = {
    { "book/raytracer-02", &scene_raytracer_02, scene_raytracer_02_work, SCENE_RAYTRACER_02_WORK_SIZE },
    { "book/raster-11", &scene_raster_11, scene_raster_11_work, SCENE_RASTER_11_WORK_SIZE },
};

/* Frame 0 of one scene on the whole panel: 0, or what failed. */
static const char *show(struct panel *panel, const struct demo_scene *d)
{
    struct render_ctx ctx;
    struct render_stats stats = { 0 };
    if (render_init(&ctx, d->scene, WIDTH, HEIGHT, ROWS, d->work, d->work_size) != 0) return "render_init";
    if (render_begin_frame(&ctx, 0) != 0) return "render_begin_frame";
    if (panel_flush_begin(panel, 0, 0, WIDTH, HEIGHT) != 0) return "panel_flush_begin";
    const char *failed = NULL;
    for (uint16_t y = 0; y < HEIGHT && !failed; y += ROWS) {
        uint16_t *buf = strip[(y / ROWS) & 1];
        struct render_target t = { .width = WIDTH, .height = HEIGHT, .y0 = y,
                                   .y1 = (uint16_t)(y + ROWS < HEIGHT ? y + ROWS : HEIGHT), .rgb565 = buf };
        if (render_strip(&ctx, &t, &stats) != 0) failed = "render_strip";
        else if (panel_flush_rows(panel, buf, (uint16_t)(t.y1 - t.y0), NULL, NULL) != 0) failed = "panel_flush_rows";
    }
    if (panel_flush_end(panel) != 0 && !failed) failed = "panel_flush_end";
    return failed;
}

int main(void)
{
    struct trace_hal bus;
    struct hal hal;
    struct panel panel;
    trace_hal_init(&bus, &hal, stdout, panel_st7789_240x240.name);
    if (panel_init(&panel, &panel_st7789_240x240, &hal, 0) != 0) {
        fprintf(stderr, "panel_demo: panel_init failed\n");
        return 1;
    }
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        const char *failed = show(&panel, &scenes[i]);
        if (failed) {
            fprintf(stderr, "panel_demo: %s: %s failed\n", scenes[i].name, failed);
            return 1;
        }
        char note[64];
        snprintf(note, sizeof note, "shown %s", scenes[i].name);
        trace_hal_note(&bus, note);
    }
    if (trace_hal_error(&bus) != 0) {
        fprintf(stderr, "panel_demo: writing the trace failed\n");
        return 1;
    }
    return 0;
}
