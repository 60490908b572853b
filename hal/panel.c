/* SPDX-License-Identifier: MIT */
/* panel.c — the generic part of the panel drivers: runs a descriptor's
 * tables through the DCS layer. Controller specifics live in the
 * descriptors (panel_st7789.c, panel_ili9341.c) and in the command set they
 * name (struct panel_ctl; panel_dcs.c): no command code is named here. */
#include <string.h>
#include "panel.h"

const struct panel_desc *const panel_all[] = {
#define PANEL(name, controller, glass, view) &panel_##name,
#define GLASS(...)
#include "panels.def"
#undef PANEL
#undef GLASS
    NULL,
};

const struct panel_desc *panel_find(const char *name)
{
    if (!name)
        return NULL;
    for (size_t i = 0; panel_all[i]; i++)
        if (strcmp(name, panel_all[i]->name) == 0 || strcmp(name, panel_all[i]->controller) == 0)
            return panel_all[i];
    return NULL;
}

const struct panel_ctl *panel_ctl(const struct panel *p)
{
    return p->desc->ctl ? p->desc->ctl : &panel_ctl_dcs;
}

/* Sends command c (skipped if PANEL_CMD_NONE) with n parameters. */
static int send(struct panel *p, uint16_t c, const uint8_t *params, size_t n)
{
    return c == PANEL_CMD_NONE ? 0 : dcs_command(&p->dcs, (uint8_t)c, params, n);
}

/* The window x0..x1 x y0..y1 and the start of a memory write into it. A
 * controller without a row/column exchange (xy_by_driver) takes the
 * window's rows as columns and its columns as rows in odd rotations; the
 * offsets stay with the commands (x_off: the column command's). */
static int open_window(struct panel *p, uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1)
{
    const struct panel_ctl *c = panel_ctl(p);
    if (c->set_cols == PANEL_CMD_NONE || c->set_rows == PANEL_CMD_NONE || c->write_mem == PANEL_CMD_NONE)
        return -1;
    int rc = (c->xy_by_driver && (p->rotation & 1))
                 ? dcs_set_window_cmds(&p->dcs, (uint8_t)c->set_cols, (uint8_t)c->set_rows, c->addr_bytes, y0, x0, y1, x1)
                 : dcs_set_window_cmds(&p->dcs, (uint8_t)c->set_cols, (uint8_t)c->set_rows, c->addr_bytes, x0, y0, x1, y1);
    return rc ? rc : dcs_write_begin_cmd(&p->dcs, (uint8_t)c->write_mem);
}

int panel_set_rotation(struct panel *p, uint8_t rotation)
{
    if (rotation > 3)
        return -1;
    const struct panel_desc *d = p->desc;
    p->rotation = rotation;
    p->width = (rotation & 1) ? d->height : d->width;
    p->height = (rotation & 1) ? d->width : d->height;
    p->dcs.x_off = d->x_off[rotation];
    p->dcs.y_off = d->y_off[rotation];
    return send(p, panel_ctl(p)->orient, &d->madctl[rotation], 1);
}

int panel_init(struct panel *p, const struct panel_desc *d, const struct hal *hal, uint8_t rotation)
{
    if (rotation > 3 || !d || !hal)
        return -1;
    p->desc = d;
    p->flush_w = 0;
    p->flush_rows = 0;
    int rc = dcs_init(&p->dcs, hal);
    p->dcs.rgb666 = panel_ctl(p)->pixel_bytes == 3;
    hal->line_set(hal->ctx, HAL_LINE_BL, 0);
    if (rc == 0)
        rc = dcs_hw_reset(&p->dcs, d->reset_low_ms, d->reset_wait_ms);
    for (size_t i = 0; rc == 0 && i < d->init_len; i++) {
        const struct panel_cmd *c = &d->init[i];
        rc = dcs_command(&p->dcs, c->cmd, c->params, c->n);
        if (rc == 0 && c->delay_ms)
            dcs_delay_ms(&p->dcs, c->delay_ms);
    }
    if (rc == 0)
        rc = panel_set_rotation(p, rotation);
    if (rc == 0)
        rc = send(p, d->invert ? panel_ctl(p)->inv_on : panel_ctl(p)->inv_off, NULL, 0);
    /* Memory holds noise after power-on: clear it before the glass shows it. */
    if (rc == 0)
        rc = panel_fill(p, 0, 0, p->width, p->height, 0x0000);
    if (rc == 0)
        rc = panel_display(p, 1);
    if (rc == 0)
        hal->line_set(hal->ctx, HAL_LINE_BL, 1);
    return rc;
}

static int rect_ok(const struct panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h)
{
    return w > 0 && h > 0 && (uint32_t)x + w <= p->width && (uint32_t)y + h <= p->height;
}

int panel_flush_begin(struct panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h)
{
    if (!rect_ok(p, x, y, w, h) || p->flush_rows)
        return -1;
    int rc = open_window(p, x, y, (uint16_t)(x + w - 1), (uint16_t)(y + h - 1));
    if (rc != 0) {
        dcs_write_end(&p->dcs);
        return rc;
    }
    p->flush_w = w;
    p->flush_rows = h;
    return 0;
}

int panel_flush_rows(struct panel *p, const uint16_t *px, uint16_t rows, hal_done_fn done, void *arg)
{
    if (!px || rows == 0 || rows > p->flush_rows)
        return -1;
    p->flush_rows = (uint16_t)(p->flush_rows - rows);
    size_t n = (size_t)p->flush_w * rows;
    const struct hal *h = p->dcs.hal;
    if (h->pixels_async && !p->dcs.rgb666) {  /* the DMA path, without a call through dcs.c */
        p->dcs.bytes_sent += (uint32_t)(2u * n);
        return h->pixels_async(h->ctx, px, n, done, arg);
    }
    return dcs_write_pixels_async(&p->dcs, px, n, done, arg);
}

int panel_flush_end(struct panel *p)
{
    int left = p->flush_rows != 0;
    p->flush_rows = 0;
    int rc = dcs_write_end(&p->dcs);
    return rc ? rc : (left ? -1 : 0);
}

int panel_flush_stop(struct panel *p)
{
    p->flush_rows = 0;
    return dcs_write_end(&p->dcs);
}

int panel_wait(struct panel *p)
{
    return dcs_wait(&p->dcs);
}

int panel_flush(struct panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h, const uint16_t *px)
{
    if (!rect_ok(p, x, y, w, h) || !px)
        return -1;
    int rc = panel_flush_begin(p, x, y, w, h);
    if (rc != 0)
        return rc;
    rc = panel_flush_rows(p, px, h, NULL, NULL);
    int rc2 = panel_flush_end(p);
    return rc ? rc : rc2;
}

int panel_fill(struct panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h, uint16_t colour)
{
    if (!rect_ok(p, x, y, w, h))
        return -1;
    int rc = open_window(p, x, y, (uint16_t)(x + w - 1), (uint16_t)(y + h - 1));
    if (rc == 0)
        rc = dcs_write_fill(&p->dcs, colour, (size_t)w * h);
    int rc2 = dcs_write_end(&p->dcs);
    return rc ? rc : rc2;
}

int panel_display(struct panel *p, int on)
{
    return send(p, on ? panel_ctl(p)->disp_on : panel_ctl(p)->disp_off, NULL, 0);
}

/* The wait after a sleep change is the command set's (panel_dcs.c: DCS). */
int panel_sleep(struct panel *p, int sleep)
{
    const struct panel_ctl *c = panel_ctl(p);
    uint16_t cmd = sleep ? c->sleep_in : c->sleep_out;
    int rc = send(p, cmd, NULL, 0);
    if (cmd != PANEL_CMD_NONE && c->sleep_wait_ms)
        dcs_delay_ms(&p->dcs, c->sleep_wait_ms);
    return rc;
}

int panel_tear_effect(struct panel *p)
{
    static const uint8_t vblank_only = 0;
    uint16_t c = panel_ctl(p)->te_on;
    if (c == 0 || c == PANEL_CMD_NONE) return -1;
    return send(p, c, &vblank_only, 1);
}

int panel_bgr(const struct panel *p) { return (p->desc->madctl[p->rotation] & panel_ctl(p)->order_bgr) != 0; }

uint16_t panel_width(const struct panel *p) { return p->width; }
uint16_t panel_height(const struct panel *p) { return p->height; }
