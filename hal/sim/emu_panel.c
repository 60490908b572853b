/* SPDX-License-Identifier: MIT */
/* emu_panel.c — emulated ST7789 / ILI9341 / ST7735S / SSD1351 / GC9A01 / ILI9488 controller
 * behind a module glass.
 *
 * Model (datasheet behaviour; the rules are listed in docs/hal.md):
 * - A byte with D/C low is a command; with D/C high, a parameter of the
 *   current command (or pixel data after RAMWR/RAMWRC). A command's
 *   parameters end at the next command byte, a reset, or emu_panel_finish.
 * - Memory address mapping (MADCTL): MV exchanges the window's x/y with
 *   memory row/column, then MX mirrors the column and MY the row.
 * - The address counter moves along x, wraps to xs and steps y at xe, and
 *   wraps to (xs, ys) after (xe, ye).
 * - Waits: any command at least 5 ms after SWRESET, hardware reset, SLPIN and
 *   SLPOUT (120 ms after SLPOUT on the ST7735S); SLPOUT at least 120 ms
 *   after SLPIN, a hardware reset, or a SWRESET sent while awake; SLPIN at
 *   least 120 ms after SLPOUT.
 * - Memory size, COLMOD after reset and what SWRESET does to COLMOD are the
 *   model's (struct model below).
 * - GC9A01: the registers the datasheet does not describe (F_INTER) are
 *   refused until the inter-register enable, FEh then EFh (a reset or
 *   SWRESET disables it again).
 * - The SSD1351 is not DCS (its own rules, ssd_* below): window 15h/75h
 *   with one-byte addresses 0..127, write RAM 5Ch in 65k colours only,
 *   re-map A0h (vertical address increment at write; column remap, COM scan
 *   direction, COM split and colour order when the glass is shown), the
 *   command lock FDh (16h: every command but FDh ignored; after a reset
 *   A2h B1h B3h BBh BEh C1h are refused until FDh B1h), sleep AEh/AFh and no
 *   waits but the reset pulse (2 us).
 */
#include <stdio.h>
#include <string.h>
#include "emu_panel.h"

#define MS 1000000ull
#define M_ST (1u << EMU_ST7789)
#define M_IL (1u << EMU_ILI9341)
#define M_S7 (1u << EMU_ST7735S)
#define M_SD (1u << EMU_SSD1351)
#define M_GC (1u << EMU_GC9A01)
#define M_I8 (1u << EMU_ILI9488)
#define M_SIL (M_ST | M_IL | M_I8)
#define M_SI (M_ST | M_IL | M_GC | M_I8)
#define M_GAM (M_ST | M_IL | M_S7 | M_I8)
#define M_ALL (M_ST | M_IL | M_S7 | M_GC | M_I8)

/* Command flags (emu_commands.def, the table of accepted commands). */
enum { F_PIXELS = 1, F_NOTEMU = 2, F_READ = 4, F_LOCKB = 8, F_INTER = 16 };

struct cmd_info {
    uint8_t code;
    uint8_t models;
    uint8_t min, max;   /* parameter bytes */
    uint8_t flags;
    const char *name;
};

static const struct cmd_info cmds[] = {
#define CMD(code, models, min, max, flags, name) { code, models, min, max, flags, name },
#include "emu_commands.def"
#undef CMD
};

/* Facts of each controller model the rules depend on. */
static const struct model {
    const char *name;
    uint16_t mem_w, mem_h;       /* memory columns x rows (native) */
    uint8_t colmod_reset;        /* COLMOD after a hardware reset */
    uint8_t colmod_swreset;      /* 1: SWRESET resets COLMOD too, 0: keeps it */
    uint8_t colmod_16bit;        /* the 16-bit value named in the violation */
    uint16_t slpout_busy_ms;     /* no command for this long after SLPOUT */
    uint8_t dcs;                 /* 1: MIPI DCS rules, 0: the SSD1351's (ssd_*) */
    uint32_t reset_pulse_ns;     /* shortest RESET low pulse */
    uint8_t round;               /* its glass is the circle inscribed in the memory:
                                    the pixels outside it are not there (black) */
    uint8_t rgb666;              /* the serial interface takes 18-bit pixels only
                                    (COLMOD 0x66, three bytes: R G B in bits 7..2) */
} models[] = {
    [EMU_ST7789] = { "ST7789", 240, 320, 0x66, 1, 0x55, 5, 1, 10000, 0, 0 },
    [EMU_ILI9341] = { "ILI9341", 240, 320, 0x66, 1, 0x55, 5, 1, 10000, 0, 0 },
    [EMU_ST7735S] = { "ST7735S", 132, 162, 0x06, 0, 0x05, 120, 1, 10000, 0, 0 },
    [EMU_SSD1351] = { "SSD1351", 128, 128, 0, 0, 0, 0, 0, 2000, 0, 0 },
    [EMU_GC9A01] = { "GC9A01", 240, 240, 0x66, 1, 0x55, 5, 1, 10000, 1, 0 },
    [EMU_ILI9488] = { "ILI9488", 320, 480, 0x66, 1, 0x66, 5, 1, 10000, 0, 1 },
};
#define MODEL(p) (&models[(p)->mod->model])

#define GLASS(nm, model, w, h, mem_x, mem_y, mirror_x, bgr, inverted, normally_black) \
    const struct emu_module emu_module_##nm = { #nm, EMU_##model, w, h, mem_x, mem_y, mirror_x, bgr, inverted, normally_black };
#define PANEL(...)
#include "panels.def"
#undef GLASS
#undef PANEL

const struct emu_module *emu_module_find(const char *name, uint8_t *view)
{
    static const struct { const char *name, *controller; const struct emu_module *m; uint8_t view; } t[] = {
#define PANEL(nm, controller, glass, v) { #nm, #controller, &emu_module_##glass, v },
#define GLASS(...)
#include "panels.def"
#undef PANEL
#undef GLASS
#define PANEL(...)
#define GLASS(nm, ...) { #nm, NULL, &emu_module_##nm, 0 },
#include "panels.def"
#undef PANEL
#undef GLASS
    };
    /* a PANEL, then a GLASS, by name; then a controller's first PANEL */
    for (int pass = 0; name && pass < 2; pass++)
        for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
            if (strcmp(name, pass ? (t[i].controller ? t[i].controller : "") : t[i].name) == 0) {
                if (view)
                    *view = t[i].view;
                return t[i].m;
            }
    return NULL;
}

static const struct cmd_info *lookup(const struct emu_panel *p, uint8_t code)
{
    unsigned bit = 1u << p->mod->model;
    for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; i++)
        if (cmds[i].code == code && (cmds[i].models & bit))
            return &cmds[i];
    return NULL;
}

static const char *cmd_name(const struct emu_panel *p, int code)
{
    const struct cmd_info *c = code < 0 ? NULL : lookup(p, (uint8_t)code);
    return c ? c->name : "UNKNOWN";
}

/* Records the first violation: "<NAME> (0x<HH>) at byte <N>: <what>", or
 * "<LINE> at byte <N>: <what>" when code < 0 (name is then the line). */
static void violate(struct emu_panel *p, const char *name, int code, uint64_t at, const char *what)
{
    if (p->violation[0])
        return;
    if (code >= 0)
        snprintf(p->violation, sizeof p->violation, "%s (0x%02X) at byte %llu: %s",
                 name, (unsigned)code, (unsigned long long)at, what);
    else
        snprintf(p->violation, sizeof p->violation, "%s at byte %llu: %s",
                 name, (unsigned long long)at, what);
}

static void vcmd(struct emu_panel *p, int code, const char *what)
{
    violate(p, cmd_name(p, code), code, p->offset, what);
}

/* Register state after a hardware reset (hw) or SWRESET (memory is kept). */
static void reset_regs(struct emu_panel *p, int hw)
{
    p->cur = -1;
    p->nparam = 0;
    p->half = 0;
    p->asleep = 1;
    p->display_on = 0;
    p->inverted = 0;
    p->idle = 0;
    if (hw || MODEL(p)->colmod_swreset)
        p->colmod = MODEL(p)->colmod_reset;
    p->madctl = 0;
    p->remap = 0x40;            /* 65k colours */
    p->locked = 0;
    p->protect = 1;
    p->mode = 0xA6;
    p->inter = 0;
    p->window_set = 0;
    p->cont_valid = 0;
    p->xs = 0;
    p->xe = (uint16_t)(MODEL(p)->mem_w - 1);
    p->ys = 0;
    p->ye = (uint16_t)(MODEL(p)->mem_h - 1);
    p->cx = 0;
    p->cy = 0;
}

static void set_wait(uint64_t *until, const char **why, uint64_t t, uint64_t d, const char *reason,
                     uint64_t *since)
{
    *until = t + d;
    *why = reason;
    *since = t;
}

/* A hardware reset is released at t. */
static void hw_reset_done(struct emu_panel *p, uint64_t t)
{
    reset_regs(p, 1);
    set_wait(&p->busy_until_ns, &p->busy_why, t, MODEL(p)->dcs ? 5 * MS : 0, "hardware reset", &p->busy_since_ns);
    set_wait(&p->slpout_ok_ns, &p->slpout_why, t, 120 * MS, "hardware reset", &p->slpout_since_ns);
    p->slpin_ok_ns = 0;
}

int emu_panel_init(struct emu_panel *p, const struct emu_module *mod, uint8_t view)
{
    if (!mod || view > 3)
        return -1;
    memset(p, 0, sizeof *p);
    p->mod = mod;
    p->view = view;
    p->cs = 1;
    p->dc = 1;
    p->reset = 1;
    p->bl = 1;
    /* Power-on memory content is undefined; a fixed xorshift32 sequence
     * stands for it so that unwritten areas are visible and reproducible. */
    /* (the first 240x320 cells in the order they had before the memory
     * grew for the ILI9488, so that the other models' noise is unchanged) */
    uint32_t s = 0x2545F491u;
    for (int pass = 0; pass < 2; pass++)
        for (int r = 0; r < EMU_MEM_H; r++)
            for (int c = 0; c < EMU_MEM_W; c++) {
                if ((r < 320 && c < 240) != (pass == 0))
                    continue;
                s ^= s << 13;
                s ^= s >> 17;
                s ^= s << 5;
                p->mem[r][c] = (uint16_t)s;
            }
    hw_reset_done(p, 0);
    return 0;
}

/* Memory limits of the window's x and y in the current orientation. */
static uint16_t lim_x(const struct emu_panel *p) { return (p->madctl & 0x20) ? MODEL(p)->mem_h : MODEL(p)->mem_w; }
static uint16_t lim_y(const struct emu_panel *p) { return (p->madctl & 0x20) ? MODEL(p)->mem_w : MODEL(p)->mem_h; }

/* A memory write stopped inside a pixel: "<how> half a pixel (odd number
 * of data bytes)" ("<how> half a pixel" after a reset), or "<how> N of a
 * pixel's 3 bytes" (18-bit). */
static void partial_pixel(struct emu_panel *p, const char *how)
{
    char what[90];
    if (MODEL(p)->rgb666)
        snprintf(what, sizeof what, "%s %u of a pixel's 3 bytes", how, (unsigned)p->half);
    else if (how[0] == 'e')
        snprintf(what, sizeof what, "%s half a pixel (odd number of data bytes)", how);
    else
        snprintf(what, sizeof what, "%s half a pixel", how);
    vcmd(p, p->cur, what);
}

/* The current command ends (a new command, a reset, or the end). */
static void end_command(struct emu_panel *p)
{
    if (p->cur < 0)
        return;
    const struct cmd_info *c = lookup(p, (uint8_t)p->cur);
    char what[80];
    if (c->flags & F_PIXELS) {
        if (p->half)
            partial_pixel(p, "ended with");
    } else if (p->nparam < c->min) {
        snprintf(what, sizeof what, "%u parameter bytes, needs %u", (unsigned)p->nparam,
                 (unsigned)c->min);
        vcmd(p, p->cur, what);
    }
    p->cur = -1;
    p->nparam = 0;
    p->half = 0;
}

static int too_soon(struct emu_panel *p, uint8_t code, uint64_t t, uint64_t until,
                    uint64_t since, const char *why)
{
    if (t >= until)
        return 0;
    char what[100];
    snprintf(what, sizeof what, "sent %llu us after %s, needs %llu us",
             (unsigned long long)((t - since) / 1000), why,
             (unsigned long long)((until - since) / 1000));
    vcmd(p, code, what);
    return 1;
}

/* Checks before pixel data may follow RAMWR / RAMWRC. */
static void start_write(struct emu_panel *p, uint8_t code)
{
    char what[100];
    if (p->asleep) {
        vcmd(p, code, "memory write while asleep (no SLPOUT since reset or SLPIN)");
    } else if (p->window_set != 3) {
        vcmd(p, code, (p->window_set & 1) ? "memory write before RASET set the rows"
                     : (p->window_set & 2) ? "memory write before CASET set the columns"
                     : "memory write before CASET/RASET set a window");
    } else if (MODEL(p)->rgb666 && (p->colmod & 7) != 6) {
        snprintf(what, sizeof what, "memory write with COLMOD 0x%02X (the serial interface takes 18-bit only, 0x66)",
                 (unsigned)p->colmod);
        vcmd(p, code, what);
    } else if (!MODEL(p)->rgb666 && (p->colmod & 7) != 5) {
        snprintf(what, sizeof what, "memory write with COLMOD 0x%02X (only 16-bit, 0x%02X, emulated)",
                 (unsigned)p->colmod, (unsigned)MODEL(p)->colmod_16bit);
        vcmd(p, code, what);
    } else if (p->xe >= lim_x(p) || p->ye >= lim_y(p)) {
        snprintf(what, sizeof what, "window %u..%u x %u..%u outside the memory (%ux%u)",
                 (unsigned)p->xs, (unsigned)p->xe, (unsigned)p->ys, (unsigned)p->ye,
                 (unsigned)lim_x(p), (unsigned)lim_y(p));
        vcmd(p, code, what);
    } else if (code == 0x3C && !p->cont_valid) {
        vcmd(p, code, "no RAMWR to continue since the window or MADCTL changed");
    } else if (code == 0x2C) {
        p->cx = p->xs;
        p->cy = p->ys;
        p->cont_valid = 1;
    }
}

/* ---- SSD1351 ---------------------------------------------------------------- */

/* A command byte arrived (known, emulated): the lock, then its effect. */
static void ssd_command(struct emu_panel *p, uint8_t code, const struct cmd_info *c)
{
    if (p->locked && code != 0xFD) {
        vcmd(p, code, "ignored: the command lock is on (FDh 16h)");
        return;
    }
    if ((c->flags & F_LOCKB) && p->protect) {
        vcmd(p, code, "refused: locked until the command lock is given B1h (FDh B1h)");
        return;
    }
    p->cur = code;
    p->nparam = 0;
    switch (code) {
    case 0xAE: p->asleep = 1; break;
    case 0xAF: p->asleep = 0; break;
    case 0xA4: case 0xA5: case 0xA6: case 0xA7: p->mode = code; break;
    case 0x5C:
        if ((p->remap & 0xC0) != 0x40) {
            char what[100];
            snprintf(what, sizeof what, "memory write with re-map 0x%02X: %s colours (only 65k, A0h bits 7:6 01b, emulated)",
                     (unsigned)p->remap, (p->remap & 0x80) ? "262k" : "256");
            vcmd(p, code, what);
        }
        break;
    default: break;
    }
}

static void ssd_execute(struct emu_panel *p)
{
    const uint8_t *a = p->param;
    char what[100];
    switch (p->cur) {
    case 0x15:
    case 0x75: {
        int col = p->cur == 0x15;
        uint16_t lim = col ? MODEL(p)->mem_w : MODEL(p)->mem_h;
        if (a[0] > a[1]) {
            snprintf(what, sizeof what, "start %u after end %u", (unsigned)a[0], (unsigned)a[1]);
            vcmd(p, p->cur, what);
        } else if (a[1] >= lim) {
            snprintf(what, sizeof what, "%s %u..%u outside the memory (0..%u)", col ? "columns" : "rows",
                     (unsigned)a[0], (unsigned)a[1], (unsigned)(lim - 1));
            vcmd(p, p->cur, what);
        } else if (col) {
            p->xs = a[0]; p->xe = a[1]; p->cx = a[0];
        } else {
            p->ys = a[0]; p->ye = a[1]; p->cy = a[0];
        }
        break;
    }
    case 0xA0:
        if (a[0] & 0x08)
            vcmd(p, p->cur, "reserved bit 3 set");
        else
            p->remap = a[0];
        break;
    case 0xA1:
    case 0xA2:
        if (a[0])
            vcmd(p, p->cur, p->cur == 0xA1 ? "not emulated (a start line other than 0)"
                                           : "not emulated (a display offset other than 0)");
        break;
    case 0xCA:
        if (a[0] != 127)
            vcmd(p, p->cur, "not emulated (a multiplex ratio other than 127: 128 rows)");
        break;
    case 0xFD:
        switch (a[0]) {
        case 0x12: p->locked = 0; break;
        case 0x16: p->locked = 1; break;
        case 0xB0: p->protect = 1; break;
        case 0xB1: p->protect = 0; break;
        default:
            snprintf(what, sizeof what, "parameter 0x%02X (12h, 16h, B0h or B1h)", (unsigned)a[0]);
            vcmd(p, p->cur, what);
            break;
        }
        break;
    default: break;
    }
}

/* A pixel at the address counter; it moves along the columns (A0h bit 0
 * clear) or along the rows, wrapping in the window. */
static void ssd_pixel(struct emu_panel *p, uint16_t v)
{
    p->mem[p->cy][p->cx] = v;
    p->pixels_written++;
    if (p->remap & 1) {
        if (p->cy < p->ye) {
            p->cy++;
        } else {
            p->cy = p->ys;
            p->cx = p->cx < p->xe ? (uint16_t)(p->cx + 1) : p->xs;
        }
    } else if (p->cx < p->xe) {
        p->cx++;
    } else {
        p->cx = p->xs;
        p->cy = p->cy < p->ye ? (uint16_t)(p->cy + 1) : p->ys;
    }
}

/* The glass: its top row is COM127 and its left column SEG0 (mirror_x:
 * SEG127). A0h bit 1 maps column address 127 to SEG0, bit 4 scans from
 * COM127 (row 0 on the top row), bit 5 splits odd and even COMs as these
 * glasses are wired (clear: the rows interleave), bit 2 orders the colours
 * C-B-A. Sleep (AEh) shows black, A4h black, A5h white, A7h inverts. */
/* Viewed pixel (ox, oy) -> glass pixel: the glass turned view*90 degrees. */
static void view_to_glass(const struct emu_panel *p, uint16_t ox, uint16_t oy, uint16_t *gx, uint16_t *gy)
{
    uint16_t gw = p->mod->glass_w, gh = p->mod->glass_h;
    switch (p->view) {
    case 1: *gx = (uint16_t)(gw - 1 - oy); *gy = ox; break;
    case 2: *gx = (uint16_t)(gw - 1 - ox); *gy = (uint16_t)(gh - 1 - oy); break;
    case 3: *gx = oy; *gy = (uint16_t)(gh - 1 - ox); break;
    default: *gx = ox; *gy = oy; break;
    }
}

static void ssd_glass(const struct emu_panel *p, uint16_t *out, uint16_t w, uint16_t h)
{
    const struct emu_module *m = p->mod;
    uint16_t mw = MODEL(p)->mem_w, mh = MODEL(p)->mem_h;
    int dark = p->asleep || !p->reset || p->mode == 0xA4;
    int invert = (p->mode == 0xA7) != (m->inverted != 0);
    int swap = ((p->remap & 0x04) != 0) != (m->bgr != 0);
    uint16_t gw = m->glass_w;
    for (uint16_t oy = 0; oy < h; oy++)
        for (uint16_t ox = 0; ox < w; ox++) {
            uint16_t gx, gy;
            view_to_glass(p, ox, oy, &gx, &gy);
            uint16_t seg = (uint16_t)(m->mem_x + (m->mirror_x ? gw - 1 - gx : gx));
            uint16_t line = (uint16_t)(m->mem_y + gy);      /* counted from COM127 */
            uint16_t col = (p->remap & 0x02) ? (uint16_t)(mw - 1 - seg) : seg;
            uint16_t row = (p->remap & 0x10) ? line : (uint16_t)(mh - 1 - line);
            if (!(p->remap & 0x20))
                row = (row & 1) ? (uint16_t)(mh / 2 + row / 2) : (uint16_t)(row / 2);
            uint16_t v = p->mem[row][col];
            if (dark) {
                v = 0x0000;
            } else if (p->mode == 0xA5) {
                v = 0xFFFF;
            } else {
                if (invert)
                    v = (uint16_t)~v;
                if (swap)
                    v = (uint16_t)((v & 0x07E0) | (v >> 11) | ((v & 0x1F) << 11));
            }
            out[(size_t)oy * w + ox] = v;
        }
}

static void command(struct emu_panel *p, uint8_t code, uint64_t t)
{
    end_command(p);
    if (p->violation[0])
        return;
    const struct cmd_info *c = lookup(p, code);
    char what[60];
    if (!c) {
        /* "an" before a letter said with a vowel first: "an SSD1351", "a GC9A01" */
        snprintf(what, sizeof what, "not %s %s command", strchr("AEFHILMNORSX", MODEL(p)->name[0]) ? "an" : "a",
                 MODEL(p)->name);
        vcmd(p, code, what);
        return;
    }
    if (c->flags & F_NOTEMU) {
        vcmd(p, code, "not emulated");
        return;
    }
    if (!MODEL(p)->dcs) {
        ssd_command(p, code, c);
        return;
    }
    if (too_soon(p, code, t, p->busy_until_ns, p->busy_since_ns, p->busy_why))
        return;
    if ((c->flags & F_INTER) && p->inter != 2) {
        vcmd(p, code, "refused: a vendor register, locked until the inter-register enable (FEh, then EFh)");
        return;
    }
    p->cur = code;
    p->nparam = 0;
    if (p->mod->model == EMU_GC9A01 && (code == 0xFE || code == 0xEF)) {
        p->inter = code == 0xFE ? 1 : p->inter ? 2 : 0;
        return;
    }
    switch (code) {
    case 0x01: {    /* SWRESET */
        int awake = !p->asleep;
        reset_regs(p, 0);
        set_wait(&p->busy_until_ns, &p->busy_why, t, 5 * MS, "SWRESET", &p->busy_since_ns);
        if (awake)
            set_wait(&p->slpout_ok_ns, &p->slpout_why, t, 120 * MS, "SWRESET", &p->slpout_since_ns);
        p->slpin_ok_ns = 0;
        p->cur = code;
        break;
    }
    case 0x10:      /* SLPIN */
        if (too_soon(p, code, t, p->slpin_ok_ns, p->slpin_since_ns, p->slpin_why))
            return;
        if (!p->asleep) {
            p->asleep = 1;
            set_wait(&p->slpout_ok_ns, &p->slpout_why, t, 120 * MS, "SLPIN", &p->slpout_since_ns);
        }
        set_wait(&p->busy_until_ns, &p->busy_why, t, 5 * MS, "SLPIN", &p->busy_since_ns);
        break;
    case 0x11:      /* SLPOUT */
        if (too_soon(p, code, t, p->slpout_ok_ns, p->slpout_since_ns, p->slpout_why))
            return;
        if (p->asleep) {
            p->asleep = 0;
            set_wait(&p->slpin_ok_ns, &p->slpin_why, t, 120 * MS, "SLPOUT", &p->slpin_since_ns);
        }
        set_wait(&p->busy_until_ns, &p->busy_why, t, MODEL(p)->slpout_busy_ms * MS, "SLPOUT", &p->busy_since_ns);
        break;
    case 0x20: p->inverted = 0; break;
    case 0x21: p->inverted = 1; break;
    case 0x28: p->display_on = 0; break;
    case 0x29: p->display_on = 1; break;
    case 0x38: p->idle = 0; break;
    case 0x39: p->idle = 1; break;
    case 0x2C:
    case 0x3C: start_write(p, code); break;
    default: break;
    }
}

/* The last parameter of a command with parameters arrived. */
static void execute(struct emu_panel *p)
{
    const uint8_t *a = p->param;
    char what[100];
    if (!MODEL(p)->dcs) {
        ssd_execute(p);
        return;
    }
    switch (p->cur) {
    case 0x2A:
    case 0x2B: {
        uint16_t s = (uint16_t)(a[0] << 8 | a[1]), e = (uint16_t)(a[2] << 8 | a[3]);
        int col = p->cur == 0x2A;
        uint16_t lim = col ? lim_x(p) : lim_y(p);
        if (s > e) {
            snprintf(what, sizeof what, "start %u after end %u", (unsigned)s, (unsigned)e);
            vcmd(p, p->cur, what);
        } else if (e >= lim) {
            snprintf(what, sizeof what, "%s %u..%u outside the memory (0..%u)",
                     col ? "columns" : "rows", (unsigned)s, (unsigned)e, (unsigned)(lim - 1));
            vcmd(p, p->cur, what);
        } else if (col) {
            p->xs = s; p->xe = e; p->window_set |= 1;
        } else {
            p->ys = s; p->ye = e; p->window_set |= 2;
        }
        p->cont_valid = 0;
        break;
    }
    case 0x36: p->madctl = a[0]; p->cont_valid = 0; break;
    case 0x37:      /* the scroll start line: 0 shows the memory unscrolled */
        if (a[0] || a[1])
            vcmd(p, p->cur, "not emulated (a scroll start other than 0)");
        break;
    case 0x3A: p->colmod = a[0]; break;
    default: break;
    }
}

static void pixel(struct emu_panel *p, uint16_t v)
{
    if (!MODEL(p)->dcs) {
        ssd_pixel(p, v);
        return;
    }
    uint16_t c = p->cx, r = p->cy;
    if (p->madctl & 0x20) { c = p->cy; r = p->cx; }
    if (p->madctl & 0x40) c = (uint16_t)(MODEL(p)->mem_w - 1 - c);
    if (p->madctl & 0x80) r = (uint16_t)(MODEL(p)->mem_h - 1 - r);
    p->mem[r][c] = v;
    p->pixels_written++;
    if (p->cx < p->xe) {
        p->cx++;
    } else {
        p->cx = p->xs;
        p->cy = p->cy < p->ye ? (uint16_t)(p->cy + 1) : p->ys;
    }
}

static void data(struct emu_panel *p, uint8_t b)
{
    if (p->cur < 0) {
        char what[60];
        snprintf(what, sizeof what, "data byte 0x%02X without a command", (unsigned)b);
        violate(p, "DATA", -1, p->offset, what);
        return;
    }
    const struct cmd_info *c = lookup(p, (uint8_t)p->cur);
    if (c->flags & F_PIXELS) {
        if (MODEL(p)->rgb666) {     /* R, G, B in bits 7..2; kept as RGB565 */
            if (p->half == 2) {
                p->half = 0;
                pixel(p, (uint16_t)((p->hi >> 3) << 11 | (p->mid >> 2) << 5 | b >> 3));
            } else {
                if (p->half)
                    p->mid = b;
                else
                    p->hi = b;
                p->half++;
            }
        } else if (p->half) {
            p->half = 0;
            pixel(p, (uint16_t)(p->hi << 8 | b));
        } else {
            p->half = 1;
            p->hi = b;
        }
        return;
    }
    if (p->nparam >= c->max) {
        char what[60];
        snprintf(what, sizeof what, "too many parameter bytes (takes %u)", (unsigned)c->max);
        vcmd(p, p->cur, what);
        return;
    }
    if (p->nparam < sizeof p->param)
        p->param[p->nparam] = b;
    p->nparam++;
    if (p->nparam == c->max)
        execute(p);
}

void emu_panel_spi(struct emu_panel *p, const uint8_t *bytes, size_t n, uint64_t t_ns, uint32_t ns_per_byte)
{
    for (size_t i = 0; i < n; i++, p->offset++) {
        if (p->violation[0])
            continue;
        uint64_t t = t_ns + (uint64_t)i * ns_per_byte;
        if (!p->reset)
            violate(p, "RESET", -1, p->offset, "byte sent while RESET is low");
        else if (p->cs && !p->cs_tied_low)   /* a real controller would drop it */
            violate(p, "CS", -1, p->offset, "byte sent while CS is high (controller deselected)");
        else if (p->dc == 0)
            command(p, bytes[i], t);
        else
            data(p, bytes[i]);
    }
}

void emu_panel_line(struct emu_panel *p, int line, int level, uint64_t t_ns)
{
    if (p->violation[0])
        return;
    level = level != 0;
    switch (line) {
    case 0: p->dc = (uint8_t)level; break;
    case 1:
        if (p->reset && !level) {
            p->reset_low_ns = t_ns;
            /* a reset aborts the command in progress: one that had not got
             * all its bytes was cut short */
            if (p->cur >= 0) {
                const struct cmd_info *c = lookup(p, (uint8_t)p->cur);
                char what[80];
                if ((c->flags & F_PIXELS) && p->half) {
                    partial_pixel(p, "cut short by a hardware reset with");
                } else if (!(c->flags & F_PIXELS) && p->nparam < c->min) {
                    snprintf(what, sizeof what, "cut short by a hardware reset: %u parameter bytes, needs %u",
                             (unsigned)p->nparam, (unsigned)c->min);
                    vcmd(p, p->cur, what);
                }
            }
            p->cur = -1;
            p->half = 0;
        } else if (!p->reset && level) {
            if (t_ns - p->reset_low_ns < MODEL(p)->reset_pulse_ns) {
                char what[60];
                snprintf(what, sizeof what, "pulse of %llu ns, needs %u us",
                         (unsigned long long)(t_ns - p->reset_low_ns), (unsigned)(MODEL(p)->reset_pulse_ns / 1000));
                violate(p, "RESET", -1, p->offset, what);
            } else {
                hw_reset_done(p, t_ns);
            }
        }
        p->reset = (uint8_t)level;
        break;
    case 2: p->cs = (uint8_t)level; break;
    case 3: p->bl = (uint8_t)level; break;
    default: break;
    }
}

int emu_panel_finish(struct emu_panel *p, uint64_t t_ns)
{
    (void)t_ns;
    if (!p->violation[0] && p->cur >= 0) {
        /* Checked as if the command ended, but it stays current: more
         * data may still follow. */
        const struct cmd_info *c = lookup(p, (uint8_t)p->cur);
        char what[80];
        if (c->flags & F_PIXELS) {
            if (p->half)
                partial_pixel(p, "ended with");
        } else if (p->nparam < c->min) {
            snprintf(what, sizeof what, "%u parameter bytes, needs %u", (unsigned)p->nparam,
                     (unsigned)c->min);
            vcmd(p, p->cur, what);
        }
    }
    return p->violation[0] ? -1 : 0;
}

const char *emu_panel_violation(const struct emu_panel *p)
{
    return p->violation[0] ? p->violation : NULL;
}

uint16_t emu_panel_glass_width(const struct emu_panel *p)
{
    return (p->view & 1) ? p->mod->glass_h : p->mod->glass_w;
}

uint16_t emu_panel_glass_height(const struct emu_panel *p)
{
    return (p->view & 1) ? p->mod->glass_w : p->mod->glass_h;
}

int emu_panel_shown(const struct emu_panel *p, uint16_t x, uint16_t y)
{
    int32_t w = emu_panel_glass_width(p), h = emu_panel_glass_height(p);
    if (x >= w || y >= h)
        return 0;
    int32_t dx = 2 * x + 1 - w, dy = 2 * y + 1 - h;
    return !MODEL(p)->round || dx * dx + dy * dy <= w * w;
}

uint16_t emu_panel_mem(const struct emu_panel *p, uint16_t col, uint16_t row)
{
    return (col < MODEL(p)->mem_w && row < MODEL(p)->mem_h) ? p->mem[row][col] : 0;
}

int emu_panel_glass(const struct emu_panel *p, uint16_t *out, uint16_t w, uint16_t h)
{
    const struct emu_module *m = p->mod;
    if (w != emu_panel_glass_width(p) || h != emu_panel_glass_height(p))
        return -1;
    if (!MODEL(p)->dcs) {
        ssd_glass(p, out, w, h);
        return 0;
    }
    int dark = p->asleep || !p->display_on || !p->bl || !p->reset;
    uint16_t off = (m->normally_black || !p->bl) ? 0x0000 : 0xFFFF;
    int invert = p->inverted != m->inverted;
    int swap = ((p->madctl & 0x08) != 0) != (m->bgr != 0);
    uint16_t gw = m->glass_w, gh = m->glass_h;
    for (uint16_t oy = 0; oy < h; oy++)
        for (uint16_t ox = 0; ox < w; ox++) {
            uint16_t gx, gy;
            view_to_glass(p, ox, oy, &gx, &gy);
            uint16_t col = (uint16_t)(m->mem_x + (m->mirror_x ? gw - 1 - gx : gx));
            uint16_t row = (uint16_t)(m->mem_y + gy);
            uint16_t v = p->mem[row][col];
            int32_t dx = 2 * gx + 1 - gw, dy = 2 * gy + 1 - gh;
            if (MODEL(p)->round && dx * dx + dy * dy > (int32_t)gw * gw) {
                v = 0x0000;     /* no glass there */
            } else if (dark) {
                v = off;
            } else {
                if (invert)
                    v = (uint16_t)~v;
                if (p->idle)    /* 8 colours: each channel's top bit */
                    v = (uint16_t)((v & 0x8000 ? 0xF800 : 0) | (v & 0x0400 ? 0x07E0 : 0) |
                                   (v & 0x0010 ? 0x001F : 0));
                if (swap)
                    v = (uint16_t)((v & 0x07E0) | (v >> 11) | ((v & 0x1F) << 11));
            }
            out[(size_t)oy * w + ox] = v;
        }
    return 0;
}
