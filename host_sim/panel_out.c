/* SPDX-License-Identifier: MIT */
/* panel_out.c — host_sim's display path (see panel_out.h).
 *
 * sim backend:   panel driver (hal/panel.c) -> DCS layer -> hal_sim ->
 *                emulated controller (hal/sim/emu_panel.c); the image files
 *                come from the emulated glass.
 * linux backend: panel driver -> DCS layer -> spidev + libgpiod; the image
 *                files come from a copy of what was sent (a real glass cannot
 *                be read back).
 * --panel none:  a plain memory framebuffer.
 *
 * The panels are those of hal/panels.def (panel_all): --panel names a
 * controller, and the size picks the module, or a module itself, which is
 * then taken first when it holds the size.
 */
#include "panel_out.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hal/panel.h"
#include "hal/sim/hal_sim.h"
#include "hal/linux/hal_linux.h"

/* The emulated bus clock: what an ST7789 accepts (62.5 MHz write cycle
 * limit) rounded down to a clock an RP2040 or a Raspberry Pi can make. It
 * only sets the simulated time the bus takes (bus_us in --stats). */
#define SIM_SPI_HZ 40000000u

const char panel_out_faults[] = "ramwr-no-window|early-after-slpout";
const char panel_out_miswires[] = "offset|bgr|invert|rotation|byteswap";

enum kind { OUT_MEMORY, OUT_SIM, OUT_LINUX };

struct panel_out {
    enum kind kind;
    uint16_t width, height;
    uint16_t *fb;                /* memory framebuffer, or the copy of what was sent (linux) */
    struct hal hal;
    struct hal_sim sim;
    struct emu_panel *emu;       /* ~300 KiB, so on the heap */
    struct panel panel;
    struct panel_desc wrong;     /* --miswire: the driver's descriptor, one setting wrong */
    int byteswap;                /* --miswire byteswap */
    uint32_t spi_hz;
    struct hal_linux lx;
    int lx_open;
};

/* A controller's first descriptor (panel_find of a controller name), NULL
 * for anything else. */
static const struct panel_desc *controller_default(const char *panel)
{
    const struct panel_desc *d = panel_find(panel);
    return d && !strcmp(d->controller, panel) ? d : NULL;
}

/* A module by its own name (panel_find of a PANEL name), NULL for anything else. */
static const struct panel_desc *module_named(const char *panel)
{
    const struct panel_desc *d = panel_find(panel);
    return d && !strcmp(d->name, panel) ? d : NULL;
}

int panel_out_native(const char *panel, uint16_t *w, uint16_t *h)
{
    const struct panel_desc *d = controller_default(panel);
    if (!d) d = module_named(panel);
    if (!d) return -1;
    *w = d->width;
    *h = d->height;
    return 0;
}

const char *panel_out_default(void) { return panel_all[0]->controller; }

int panel_out_modules(char *buf, size_t len)
{
    size_t n = 0;
    if (len) buf[0] = 0;
    for (size_t i = 0; panel_all[i]; i++) {
        int k = snprintf(buf + n, len - n, "%s%s", n ? "|" : "", panel_all[i]->name);
        if (k < 0 || (size_t)k >= len - n) return -1;
        n += (size_t)k;
    }
    return 0;
}

int panel_out_controllers(char *buf, size_t len)
{
    size_t n = 0;
    if (len) buf[0] = 0;
    for (size_t i = 0; panel_all[i]; i++)
        if (controller_default(panel_all[i]->controller) == panel_all[i]) {
            int k = snprintf(buf + n, len - n, "%s%s", n ? "|" : "", panel_all[i]->controller);
            if (k < 0 || (size_t)k >= len - n) return -1;
            n += (size_t)k;
        }
    return 0;
}

/* The module and rotation that show a w x h image: a module named by panel
 * if it holds it upright, else turned a quarter; else the first descriptor
 * of the controller (in panels.def's order, smallest first) that holds it
 * upright, else the first that holds it turned a quarter; NULL if none. */
static const struct panel_desc *pick_module(const char *panel, unsigned w, unsigned h, uint8_t *rot)
{
    const struct panel_desc *named = module_named(panel);
    if (named) {
        for (*rot = 0; *rot < 2; (*rot)++)
            if (w <= (*rot ? named->height : named->width) && h <= (*rot ? named->width : named->height))
                return named;
        panel = named->controller;
    }
    for (*rot = 0; *rot < 2; (*rot)++)
        for (size_t i = 0; panel_all[i]; i++) {
            const struct panel_desc *d = panel_all[i];
            unsigned pw = *rot ? d->height : d->width, ph = *rot ? d->width : d->height;
            if (!strcmp(d->controller, panel) && w <= pw && h <= ph) return d;
        }
    return NULL;
}

/* A protocol violation recorded by the emulated panel: 3 and its line. */
static int violation(struct panel_out *p, char *err, size_t errlen)
{
    const char *v = p->emu ? emu_panel_violation(p->emu) : NULL;
    if (!v) return 0;
    snprintf(err, errlen, "%s", v);
    return 3;
}

/* Drives the panel the wrong way on purpose, so that tests can see the
 * emulated controller catch it (--inject-fault). */
static int inject_fault(struct panel_out *p, const struct panel_desc *d, const char *fault,
                        char *err, size_t errlen)
{
    struct dcs *dcs = &p->panel.dcs;
    const uint8_t colmod = DCS_COLMOD_16BIT;
    const uint16_t px[4] = { 0xf800, 0x07e0, 0x001f, 0xffff };
    dcs_init(dcs, &p->hal);
    if (!strcmp(fault, "ramwr-no-window")) {
        /* A correct wake-up, then a memory write with no CASET/RASET since reset. */
        dcs_hw_reset(dcs, d->reset_low_ms, d->reset_wait_ms);
        dcs_command(dcs, DCS_SLPOUT, NULL, 0);
        dcs_delay_ms(dcs, 120);
        dcs_command(dcs, DCS_COLMOD, &colmod, 1);
        dcs_command(dcs, DCS_DISPON, NULL, 0);
        dcs_write_begin(dcs, 0);
        dcs_write_pixels(dcs, px, 4);
        dcs_write_end(dcs);
    } else if (!strcmp(fault, "early-after-slpout")) {
        /* The next command right after SLPOUT, without the wait it needs. */
        dcs_hw_reset(dcs, d->reset_low_ms, d->reset_wait_ms);
        dcs_command(dcs, DCS_SLPOUT, NULL, 0);
        dcs_command(dcs, DCS_COLMOD, &colmod, 1);
    } else {
        snprintf(err, errlen, "unknown fault '%s' (%s)", fault, panel_out_faults);
        return 2;
    }
    emu_panel_finish(p->emu, p->sim.t_ns);
    if (violation(p, err, errlen)) return 3;
    snprintf(err, errlen, "injected fault %s was not reported by the emulated panel", fault);
    return 1;
}

/* --miswire: *d replaced by a copy with one of its settings wrong (offset,
 * bgr, invert), the driver's rotation *drv turned a half turn (rotation), or
 * the pixels' bytes swapped (byteswap); 2 and err for an unknown name or a
 * setting the panel does not have. */
static int miswire(struct panel_out *p, const struct panel_desc **d, uint8_t rot, uint8_t *drv, const char *what,
                   char *err, size_t errlen)
{
    struct panel_desc *w = &p->wrong;
    const uint8_t half = (uint8_t)((rot + 2) & 3);
    const struct panel_ctl *ctl = (*d)->ctl ? (*d)->ctl : &panel_ctl_dcs;
    *w = **d;
    if (!strcmp(what, "offset")) {
        if (w->x_off[rot] != w->x_off[half] || w->y_off[rot] != w->y_off[half]) {
            w->x_off[rot] = w->x_off[half];
            w->y_off[rot] = w->y_off[half];
        } else if (w->x_off[rot] || w->y_off[rot]) {
            w->x_off[rot] = w->y_off[rot] = 0;
        } else {
            snprintf(err, errlen, "--miswire offset: %s has no offsets to get wrong in rotation %u", w->name,
                     (unsigned)rot);
            return 2;
        }
    } else if (!strcmp(what, "bgr")) {
        if (!ctl->order_bgr) {
            snprintf(err, errlen, "--miswire bgr: %s has no colour-order setting", w->name);
            return 2;
        }
        w->madctl[rot] ^= ctl->order_bgr;
    } else if (!strcmp(what, "invert")) {
        w->invert = !w->invert;
    } else if (!strcmp(what, "rotation")) {
        *drv = half;
    } else if (!strcmp(what, "byteswap")) {
        p->byteswap = 1;
    } else {
        snprintf(err, errlen, "unknown --miswire '%s' (%s)", what, panel_out_miswires);
        return 2;
    }
    *d = w;
    return 0;
}

static int open_memory(struct panel_out *p, char *err, size_t errlen)
{
    p->fb = calloc((size_t)p->width * p->height, sizeof *p->fb);
    if (!p->fb) {
        snprintf(err, errlen, "out of memory for a %ux%u framebuffer", p->width, p->height);
        return 1;
    }
    return 0;
}

int panel_out_open(struct panel_out **out, const struct panel_out_opts *o, char *err, size_t errlen)
{
    int linux_be = !strcmp(o->backend, "linux");
    int none = !strcmp(o->panel, "none");
    *out = NULL;
    if (none && linux_be) {
        snprintf(err, errlen, "--backend linux needs a panel, not --panel none");
        return 2;
    }
    uint8_t rot = 0;
    const struct panel_desc *d = none ? NULL : pick_module(o->panel, o->width, o->height, &rot);
    if (!none && !d) {
        if (!controller_default(o->panel) && !module_named(o->panel))
            snprintf(err, errlen, "unknown panel '%s'", o->panel);
        else snprintf(err, errlen, "size %ux%u is larger than every %s module", o->width, o->height, o->panel);
        return 2;
    }
    struct panel_out *p = calloc(1, sizeof *p);
    if (!p) {
        snprintf(err, errlen, "out of memory");
        return 1;
    }
    *out = p;
    p->width = o->width;
    p->height = o->height;
    if (none) {
        p->kind = OUT_MEMORY;
        return open_memory(p, err, errlen);
    }
    const char *name = d->name;
    if (o->rotation > 3 || ((o->rotation & 1) && o->width != o->height)) {
        snprintf(err, errlen, "--rotation %u: %s", (unsigned)o->rotation,
                 o->rotation > 3 ? "quarter turns 0..3" :
                 "with --size, odd turns need a square size (WxH itself picks portrait or landscape; "
                 "without --size a panel turned a quarter shows its native size turned)");
        return 2;
    }
    rot = (uint8_t)((rot + o->rotation) & 3);
    uint8_t drv = rot;   /* the driver's rotation (the module's but with --miswire rotation) */
    int rc;
    if (o->miswire && (rc = miswire(p, &d, rot, &drv, o->miswire, err, errlen))) return rc;
    if (linux_be) {
        struct hal_linux_config cfg;
        if (o->fault) {
            snprintf(err, errlen, "--inject-fault needs the emulated panel (--backend sim)");
            return 2;
        }
        p->kind = OUT_LINUX;
        if ((rc = open_memory(p, err, errlen))) return rc;
        hal_linux_default_config(&cfg);
        if (o->spi_dev) cfg.spi_dev = o->spi_dev;
        if (o->gpio_chip) cfg.gpio_chip = o->gpio_chip;
        /* the panel's rated write clock and its mode unless told otherwise */
        cfg.spi_hz = o->spi_hz ? o->spi_hz : d->spi_max_hz;
        cfg.spi_mode = (uint8_t)(o->spi_mode >= 0 ? o->spi_mode : d->spi_mode);
        if (o->dc != PANEL_OUT_PIN_DEFAULT) cfg.dc = o->dc;
        if (o->rst != PANEL_OUT_PIN_DEFAULT) cfg.reset = o->rst;
        if (o->bl != PANEL_OUT_PIN_DEFAULT) cfg.bl = o->bl;
        if (hal_linux_open(&p->lx, &p->hal, &cfg)) {
            snprintf(err, errlen, "backend linux: %s", hal_linux_error(&p->lx));
            return 2;
        }
        p->lx_open = 1;
        p->spi_hz = cfg.spi_hz;
        if (panel_init(&p->panel, d, &p->hal, drv)) {
            snprintf(err, errlen, "backend linux: %s init failed: %s", name, hal_linux_error(&p->lx));
            return 1;
        }
        return 0;
    }
    p->kind = OUT_SIM;
    uint8_t view;
    const struct emu_module *m = emu_module_find(name, &view);
    p->emu = malloc(sizeof *p->emu);
    if (!m || !p->emu) {
        snprintf(err, errlen, m ? "out of memory" : "no emulated module shows %s (hal/panels.def)", name);
        return 1;
    }
    if (emu_panel_init(p->emu, m, (uint8_t)((view + rot) & 3))) {
        snprintf(err, errlen, "emulated panel %s refused view %u", name, (unsigned)((view + rot) & 3));
        return 1;
    }
    hal_sim_init(&p->sim, &p->hal, p->emu);
    hal_sim_set_spi_hz(&p->sim, SIM_SPI_HZ);
    p->spi_hz = SIM_SPI_HZ;
    if (o->fault) return inject_fault(p, d, o->fault, err, errlen);
    rc = panel_init(&p->panel, d, &p->hal, drv);
    if (violation(p, err, errlen)) return 3;
    if (rc) {
        snprintf(err, errlen, "%s: panel_init failed (%d)", name, rc);
        return 1;
    }
    return 0;
}

int panel_out_flush(struct panel_out *p, uint16_t y0, uint16_t y1, const uint16_t *px,
                    char *err, size_t errlen)
{
    if (y0 >= y1 || y1 > p->height) {
        snprintf(err, errlen, "flush of rows %u..%u outside the %u-row image", y0, y1, p->height);
        return 1;
    }
    if (p->fb) memcpy(p->fb + (size_t)y0 * p->width, px, (size_t)(y1 - y0) * p->width * sizeof *px);
    if (p->byteswap) return panel_out_flush_rect(p, 0, y0, p->width, (uint16_t)(y1 - y0), px, p->width, err, errlen);
    if (p->kind != OUT_MEMORY) {
        int rc = panel_flush(&p->panel, 0, y0, p->width, (uint16_t)(y1 - y0), px);
        if (violation(p, err, errlen)) return 3;
        if (rc) {
            snprintf(err, errlen, "panel_flush of rows %u..%u failed (%d)", y0, y1, rc);
            return 1;
        }
    }
    return 0;
}

int panel_out_flush_rect(struct panel_out *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h,
                         const uint16_t *px, size_t stride, char *err, size_t errlen)
{
    if (!w || !h || x + w > p->width || y + h > p->height) {
        snprintf(err, errlen, "flush of %ux%u at (%u,%u) outside the %ux%u image", w, h, x, y,
                 p->width, p->height);
        return 1;
    }
    if (x == 0 && w == p->width && stride == p->width && !p->byteswap)
        return panel_out_flush(p, y, (uint16_t)(y + h), px, err, errlen);
    uint16_t *packed = malloc((size_t)w * h * sizeof *packed);
    if (!packed) {
        snprintf(err, errlen, "out of memory");
        return 1;
    }
    for (unsigned r = 0; r < h; r++) {
        memcpy(packed + (size_t)r * w, px + (size_t)r * stride, (size_t)w * sizeof *px);
        if (p->fb) memcpy(p->fb + (size_t)(y + r) * p->width + x, px + (size_t)r * stride, (size_t)w * sizeof *px);
    }
    if (p->byteswap)   /* --miswire byteswap: what was sent, not what was meant */
        for (size_t i = 0; i < (size_t)w * h; i++) packed[i] = (uint16_t)(packed[i] << 8 | packed[i] >> 8);
    int rc = 0;
    if (p->kind != OUT_MEMORY) {
        int prc = panel_flush(&p->panel, x, y, w, h, packed);
        if ((rc = violation(p, err, errlen)) == 0 && prc) {
            snprintf(err, errlen, "panel_flush of %ux%u at (%u,%u) failed (%d)", w, h, x, y, prc);
            rc = 1;
        }
    }
    free(packed);
    return rc;
}

int panel_out_finish(struct panel_out *p, char *err, size_t errlen)
{
    if (p->kind == OUT_SIM) {
        emu_panel_finish(p->emu, p->sim.t_ns);
        return violation(p, err, errlen);
    }
    (void)p; (void)err; (void)errlen;
    return 0;
}

const struct panel *panel_out_panel(const struct panel_out *p) { return p->kind == OUT_MEMORY ? NULL : &p->panel; }

uint32_t panel_out_spi_hz(const struct panel_out *p) { return p->spi_hz; }

int panel_out_round(const struct panel_out *p) { return p->kind == OUT_SIM && !emu_panel_shown(p->emu, 0, 0); }

uint64_t panel_out_spi_bytes(const struct panel_out *p)
{
    if (p->kind == OUT_SIM) return p->sim.spi_bytes;
    if (p->kind == OUT_LINUX) return p->panel.dcs.bytes_sent;
    (void)p;
    return 0;
}

uint64_t panel_out_bus_us(const struct panel_out *p)
{
    if (p->kind == OUT_SIM) return hal_sim_now_us(&p->sim);
    (void)p;
    return 0;
}

int panel_out_read(struct panel_out *p, uint16_t *dst, char *err, size_t errlen)
{
    if (p->kind == OUT_SIM) {
        uint16_t gw = emu_panel_glass_width(p->emu), gh = emu_panel_glass_height(p->emu);
        if (gw < p->width || gh < p->height) {
            snprintf(err, errlen, "the emulated glass is %ux%u, smaller than the %ux%u image",
                     gw, gh, p->width, p->height);
            return 1;
        }
        uint16_t *g = malloc((size_t)gw * gh * sizeof *g);
        if (!g) {
            snprintf(err, errlen, "out of memory");
            return 1;
        }
        if (emu_panel_glass(p->emu, g, gw, gh)) {
            free(g);
            snprintf(err, errlen, "cannot read the emulated glass");
            return 1;
        }
        for (unsigned y = 0; y < p->height; y++)
            memcpy(dst + (size_t)y * p->width, g + (size_t)y * gw, (size_t)p->width * sizeof *dst);
        free(g);
        return 0;
    }
    (void)err; (void)errlen;
    memcpy(dst, p->fb, (size_t)p->width * p->height * sizeof *dst);
    return 0;
}

void panel_out_close(struct panel_out *p)
{
    if (!p) return;
    if (p->lx_open) hal_linux_close(&p->lx);
    free(p->emu);
    free(p->fb);
    free(p);
}
