/* panel.h — display controller drivers as data, on top of the DCS layer.
 *
 * A struct panel_desc describes one module (controller + glass): its size,
 * its initialisation table (commands, parameters, delays), MADCTL and the
 * column/row offsets for each rotation, colour order and inversion.
 * Adding a module means adding a descriptor, not code.
 *
 * Rotation r (0..3) turns the image r*90 degrees clockwise relative to the
 * descriptor's rotation 0; odd rotations swap width and height.
 * Pixels are RGB565, native uint16_t, row-major.
 *
 * Flushing a rectangle (panel_flush) is the one way pixels leave a renderer.
 */
#ifndef HAL_PANEL_H
#define HAL_PANEL_H

#include <stddef.h>
#include <stdint.h>
#include "hal.h"
#include "dcs.h"

#define PANEL_CMD_MAX_PARAMS 16

/* One step of an initialisation table: a command, its parameters, and the
 * delay to wait after it (ms). */
struct panel_cmd {
    uint8_t cmd;
    uint8_t n;                               /* parameter count, <= PANEL_CMD_MAX_PARAMS */
    uint16_t delay_ms;
    uint8_t params[PANEL_CMD_MAX_PARAMS];
};

struct panel_desc {
    const char *name;            /* "st7789_240x240", ... (panel_find key) */
    const char *controller;      /* "st7789", "ili9341" */
    uint16_t width, height;      /* visible size in rotation 0 */
    uint16_t reset_low_ms;       /* hardware reset pulse */
    uint16_t reset_wait_ms;      /* wait after releasing RESET */
    const struct panel_cmd *init;/* sent after the hardware reset, in order */
    size_t init_len;
    uint8_t madctl[4];           /* MADCTL per rotation, BGR bit included */
    uint16_t x_off[4], y_off[4]; /* column/row offset per rotation */
    uint8_t invert;              /* 1: INVON (IPS glass), 0: INVOFF */
};

extern const struct panel_desc panel_st7789_240x240;
extern const struct panel_desc panel_st7789_240x320;
extern const struct panel_desc panel_ili9341_320x240;
extern const struct panel_desc panel_ili9341_240x320;

struct panel {
    const struct panel_desc *desc;
    struct dcs dcs;
    uint8_t rotation;
    uint16_t width, height;      /* in the current rotation */
};

/* Looks a descriptor up by name: a full name ("st7789_240x240") or a
 * controller name ("st7789" = st7789_240x240, "ili9341" = ili9341_320x240).
 * Returns NULL if unknown. */
const struct panel_desc *panel_find(const char *name);
/* The descriptors panel_find knows, NULL-terminated. */
extern const struct panel_desc *const panel_all[];

/* Resets and initialises the panel (hardware reset, init table, MADCTL for
 * rotation, inversion, memory cleared to black, display on, backlight on).
 * rotation 0..3; returns -1 for a bad rotation, else 0 or the HAL's error. */
int panel_init(struct panel *p, const struct panel_desc *d, const struct hal *hal, uint8_t rotation);

/* Changes the rotation (MADCTL and offsets); width/height follow. */
int panel_set_rotation(struct panel *p, uint8_t rotation);

/* Sends the w*h pixels px (row-major, stride w) to the rectangle at (x, y).
 * Returns -1 if the rectangle is empty or leaves the panel (nothing sent). */
int panel_flush(struct panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h, const uint16_t *px);

/* Fills a rectangle with one colour (same rules as panel_flush). */
int panel_fill(struct panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h, uint16_t colour);

/* DISPON/DISPOFF and SLPIN/SLPOUT with the waits they need. */
int panel_display(struct panel *p, int on);
int panel_sleep(struct panel *p, int sleep);

uint16_t panel_width(const struct panel *p);
uint16_t panel_height(const struct panel *p);

#endif
