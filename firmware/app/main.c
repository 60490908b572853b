/* SPDX-License-Identifier: MIT */
/* main.c — the firmware application: cycles through the scenes compiled
 * into the image, rendering each frame strip by strip while DMA sends the
 * previous strip, and shows the frame rate on screen and over UART. Every
 * pixel leaves through panel.h's streaming flush (the board's HAL sends
 * them, by DMA where it has it).
 *
 * Strips: FW_STRIP_ROWS rows of FW_WIDTH pixels, rendered into a ring of
 * FW_RING buffers (strip k into ring[k % FW_RING]) while DMA sends the ones
 * before them. The cores take strips in order from a shared counter, each
 * the next one whose buffer is available (strip k - FW_RING has been sent), so
 * the work balances itself whatever the strips cost; core 0 also sends the
 * strips in order as they are done, and renders when the next one to send
 * is not done yet. With one core the same loop renders strip k while strip
 * k - 1 is on the bus.
 *
 * UART lines (115200 8N1), one per event, parsed by tools/rp2040sim:
 *   boot board=B cores=N cpu_hz=H spi_hz=F size=WxH strip_rows=R scenes=S
 *   begin scene=NAME frame=F t=T   (T: the board's microsecond timer when the
 *                                  frame began, its low 32 bits: the line may
 *                                  leave the board later, fw_board_puts)
 *   coarse scene=NAME frame=F   (ray tracer: a preview of 8x8 blocks follows)
 *   first scene=NAME frame=F us=U   (the preview is on the glass, U after begin)
 *   fps scene=NAME frame=F us=U fps=X.Y
 *   error scene=NAME what   (render_strip failed, panel flush failed, ...)
 * The first frame of each scene carries no overlay (no frame was timed yet),
 * so it is exactly the renderer's image; later frames show "X.Y fps" in the
 * top-left corner.
 *
 * Only what changed goes over the bus (FW_SKIP_UNCHANGED, default on): for
 * each strip core 0 knows the columns outside of which the glass shows the
 * scene's background (render_background_565) there, and finds the same for
 * the new strip (nothing to look for when the renderer wrote no scene pixel
 * into it and the overlay does not reach it, else the first and last
 * columns of any row that differ from the background). It sends the columns
 * between the outermost of both (the strip's rows moved together in its
 * buffer, one window and one transfer), nothing when both are background
 * alone, and the whole width where the glass is not known (the first frame,
 * a preview, another background, a bus error). Strips sent whole follow one
 * another in one window. The last strip always reaches the last column, so
 * every frame ends with the panel's last pixel. Exact: the glass at the end
 * of every frame is what a full flush leaves. That trusts the wire; so that
 * a byte the panel took wrongly (noise on a long cable, a glitch) does not
 * stay for good where the glass stays background, one strip a frame goes
 * out whole, in turn (FW_REPAIR_STRIPS, default on): any damage is gone
 * within NSTRIPS frames (15 at 240 rows), for one strip's bytes a frame. */
#include <stddef.h>
#include <stdint.h>
#include "fw_board.h"
#include "fw_start.h"
#include "fw_text.h"
#include "fw_scenes.h"
#include "font5x7.h"
#include "panel.h"
#include "render.h"

#ifndef FW_WIDTH
#define FW_WIDTH 240
#endif
#ifndef FW_HEIGHT
#define FW_HEIGHT 240
#endif
#ifndef FW_STRIP_ROWS
#define FW_STRIP_ROWS 8
#endif
/* Frames of each scene before the next; 0: the scene's own (its `frames`,
 * the length of its animation; make image, mk/image.mk). */
#ifndef FW_FRAMES_PER_SCENE
#define FW_FRAMES_PER_SCENE 3
#endif
/* Progressive display of ray-traced frames: a preview of 8x8 blocks (one
 * ray each) on the whole screen first, then the frame refined in place. */
#ifndef FW_PROGRESSIVE
#define FW_PROGRESSIVE 1
#endif
#ifndef FW_PANEL
#define FW_PANEL panel_st7789_240x240
#endif
/* The panel's rotation (0..3, panel.h); odd ones swap its width and height,
 * which must then be FW_WIDTH x FW_HEIGHT. */
#ifndef FW_ROTATION
#define FW_ROTATION 0
#endif

#ifndef FW_RING
#define FW_RING 4
#endif
/* FW_ROUND_GLASS 1: the panel's glass is round (the GC9A01): the ray tracer
 * does not trace the pixels outside its circle (render_set_round). */
#ifndef FW_ROUND_GLASS
#define FW_ROUND_GLASS 0
#endif
/* Without a TE line: frames start no sooner than one scan period (with a 2 %
 * margin) after the one before, so that none is overwritten before the
 * panel's scan reaches it (FW_SCAN_HZ: the controller's frame rate; 0 turns
 * the pacing off). */
#ifndef FW_SCAN_HZ
#define FW_SCAN_HZ 60
#endif
#ifndef FW_TE_TIMEOUT_US
#define FW_TE_TIMEOUT_US 50000u   /* three scans at 60 Hz */
#endif
#ifndef FW_REPAIR_STRIPS
#define FW_REPAIR_STRIPS 1
#endif
#ifndef FW_SKIP_UNCHANGED
#define FW_SKIP_UNCHANGED 1
#endif

#define NSTRIPS ((FW_HEIGHT + FW_STRIP_ROWS - 1) / FW_STRIP_ROWS)
#define MSG_FRAME 0x80000000u
#define MSG_FRAME_DONE 1u
/* core 0 -> core 1: your share of the frame's vertices (rasterized scene si
 * in the low 15 bits), then of its triangles; core 1 -> core 0: done
 * (MSG_VERTS_FAILED: it could not, core 0 does that share itself, and all
 * the triangles) */
#define MSG_VERTS 0x40000000u
#define MSG_TRIS 0x20000000u
#define MSG_VERTS_DONE 2u
#define MSG_VERTS_FAILED 3u
#define MSG_TRIS_DONE 4u

/* read as words too, two pixels at a time (content_cols): a union */
#if FW_WIDTH % 2
#error "FW_WIDTH must be even"
#endif
static union strip_buf {
    uint16_t px[FW_WIDTH * FW_STRIP_ROWS];
    uint32_t w[FW_WIDTH * FW_STRIP_ROWS / 2];
} ring[FW_RING];
/* the progressive preview's strips (core 1 may fill the ring meanwhile) */
static uint16_t preview_buf[2][FW_WIDTH * FW_STRIP_ROWS];

/* Shared by the cores, under fw_board_lock(). */
static struct {
    uint32_t claim;             /* next strip to take */
    uint32_t sent;              /* strips whose transfer has finished */
    uint8_t done[NSTRIPS];      /* 0 not yet, 1 rendered, 2 failed */
    uint8_t empty[NSTRIPS];     /* rendered with no scene content (background only) */
} sh;
/* What the glass shows in each strip's rows (core 0 only): when known, the
 * background colour bg everywhere outside columns x0..x1 (x0 > x1: nowhere). */
static struct {
    uint8_t known;
    uint16_t bg;
    int16_t x0, x1;
} glass[NSTRIPS];
static unsigned repair_k;     /* the strip this frame sends whole (FW_REPAIR_STRIPS) */
static int te_sync;           /* the board wires the panel's TE line and it is on */
static uint64_t last_begin_us; /* when the last frame began (FW_SCAN_HZ) */
static struct render_ctx ctx[2];
static struct hal hal;
static struct panel panel;

static void strip_rows(unsigned k, uint16_t *y0, uint16_t *y1)
{
    *y0 = (uint16_t)(k * FW_STRIP_ROWS);
    *y1 = (uint16_t)(*y0 + FW_STRIP_ROWS > FW_HEIGHT ? FW_HEIGHT : *y0 + FW_STRIP_ROWS);
}

/* Renders strip k into buf; *empty (when not NULL) says whether the scene
 * wrote none of its pixels (the background alone). */
static int render_one(struct render_ctx *c, unsigned k, uint16_t *buf, int *empty)
{
    struct render_target t = { .width = FW_WIDTH, .height = FW_HEIGHT, .rgb565 = buf };
    struct render_stats st = { 0 };
    strip_rows(k, &t.y0, &t.y1);
    int rc = render_strip(c, &t, &st);
    if (empty) *empty = st.pixels_written == 0;
    return rc;
}

/* The columns *x0..*x1 outside of which every pixel of the strip's rows
 * is bg (*x0 > *x1: all of them). Each row is looked at from both ends only
 * as far as the columns found so far, two pixels a word while both are
 * inside that bound. */
static void content_cols(const union strip_buf *b, unsigned rows, uint16_t bg, int *x0, int *x1)
{
    const uint32_t bg2 = (uint32_t)bg << 16 | bg;
    int lo = FW_WIDTH, hi = -1;
    for (unsigned r = 0; r < rows; r++) {
        const size_t o = (size_t)r * FW_WIDTH;           /* even: rows start on a word */
        int x = 0;
        while (x + 1 < lo && b->w[(o + (size_t)x) / 2] == bg2) x += 2;
        while (x < lo && b->px[o + (size_t)x] == bg) x++;
        lo = x;
        x = FW_WIDTH - 1;
        while (x - 1 > hi && b->w[(o + (size_t)x - 1) / 2] == bg2) x -= 2;
        while (x > hi && b->px[o + (size_t)x] == bg) x--;
        hi = x;
    }
    *x0 = lo;
    *x1 = hi;
}

/* The columns *x0..*x1 of strip k to send (*x0 > *x1: none) when the glass
 * is tracked (track), else the whole width; records what the glass shows
 * there afterwards. scan: the strip may hold more than the background (the
 * renderer wrote into it, or the overlay reaches it). Sent windows start
 * on an even column and have an even width (pack_cols moves words). */
static void changed_cols(unsigned k, const union strip_buf *sb, unsigned rows, uint16_t bg, int track, int scan,
                         int *x0, int *x1)
{
    const int whole = FW_REPAIR_STRIPS && k == repair_k;
    int c0 = 0, c1 = FW_WIDTH - 1;
    *x0 = 0;
    *x1 = FW_WIDTH - 1;
    if (track) {
        if (scan) content_cols(sb, rows, bg, &c0, &c1);
        else c0 = FW_WIDTH, c1 = -1;
        if (glass[k].known && glass[k].bg == bg) {
            *x0 = c0 < glass[k].x0 ? c0 : glass[k].x0;
            *x1 = c1 > glass[k].x1 ? c1 : glass[k].x1;
        }
        if (k + 1 == NSTRIPS) {     /* the frame ends with the last pixel */
            *x1 = FW_WIDTH - 1;
            if (*x0 > *x1) *x0 = *x1;
        }
        if (whole) {                /* this frame's repair strip */
            *x0 = 0;
            *x1 = FW_WIDTH - 1;
        }
        if (*x0 <= *x1) {
            *x0 &= ~1;
            *x1 |= 1;
        }
    }
    glass[k].known = (uint8_t)track;
    glass[k].bg = bg;
    glass[k].x0 = (int16_t)c0;
    glass[k].x1 = (int16_t)c1;
}

/* The columns x0 .. x0 + w - 1 of each row moved together to the front of
 * the buffer (x0 and w even: whole words; forward, each row's new place is
 * at or before its old one). */
static void pack_cols(union strip_buf *sb, unsigned rows, int x0, uint16_t w)
{
    for (unsigned r = 0; r < rows; r++) {
        size_t d = (size_t)r * w / 2u, q = ((size_t)r * FW_WIDTH + (size_t)x0) / 2u, qe = q + w / 2u;
        if (d != q)
            while (q != qe) sb->w[d++] = sb->w[q++];
    }
}

/* The streaming flush of a frame's strips (core 0): open, a flush is open
 * (the bus is idle when not); run, the open one is a window of whole rows to
 * the bottom, continued by whole strips; err, a transfer failed (from then
 * on the strips are only released, so that core 1 finishes the frame). */
struct bus {
    int open, run, err;
};

/* Ends the open streaming flush, if any (a run of whole rows may end before
 * its last row). */
static void flush_close(struct bus *b)
{
    if (b->open && (b->run ? panel_flush_stop(&panel) : panel_flush_end(&panel)) != 0) b->err = 1;
    b->open = b->run = 0;
}

/* Core 0's context of scene si (render_init), or core 1's: a sibling of
 * core 0's (render_init_sibling), which takes each frame core 0 prepared
 * (core 0 has begun the frame before it tells core 1 to start). */
static int scene_init(struct render_ctx *c, unsigned si, unsigned core)
{
    const struct fw_scene *fs = &fw_scenes[si];
    int rc = core == 0 ? render_init(c, fs->scene, FW_WIDTH, FW_HEIGHT, FW_STRIP_ROWS, fs->work[0], fs->work_size[0])
                       : render_init_sibling(c, &ctx[0], fs->work[1], fs->work_size[1]);
    if (rc == 0 && FW_ROUND_GLASS) render_set_round(c, 1);
    return rc;
}

/* ---- text helpers (no printf: it would cost more flash than the app) ---- */

/* "X.Y" frames per second from a frame time in microseconds. */
static char *put_fps(char *p, uint32_t us)
{
    uint32_t tenths = us ? (10000000u + us / 2u) / us : 0;
    p = put_u32(p, tenths / 10u);
    *p++ = '.';
    *p++ = (char)('0' + tenths % 10u);
    return p;
}

/* ---- strips shared by the cores ------------------------------------------- */

/* The next strip whose buffer can be reused: its index; NSTRIPS when every strip
 * is taken; -1 when the next one's buffer is still being sent. */
static int claim_strip(void)
{
    int r;
    fw_board_lock();
    if (sh.claim >= NSTRIPS) r = NSTRIPS;
    else if (sh.claim >= sh.sent + FW_RING) r = -1;
    else r = (int)sh.claim++;
    fw_board_unlock();
    return r;
}

static void mark_done(unsigned k, int ok, int empty)
{
    fw_board_lock();
    sh.done[k] = ok ? 1u : 2u;
    sh.empty[k] = (uint8_t)(ok && empty);
    fw_board_unlock();
    fw_board_notify();
}

static unsigned strip_state(unsigned k)
{
    fw_board_lock();
    unsigned v = sh.done[k];
    fw_board_unlock();
    return v;
}

static int strip_empty(unsigned k)
{
    fw_board_lock();
    int v = sh.empty[k];
    fw_board_unlock();
    return v;
}

/* DMA finished sending strip k (called by the HAL on core 0): its buffer
 * and every one before it can be reused again. */
static void strip_sent(void *arg)
{
    fw_board_lock();
    sh.sent = (uint32_t)(uintptr_t)arg + 1u;
    fw_board_unlock();
    fw_board_notify();
}

/* ---- core 1 --------------------------------------------------------------- */

static void core1_main(void)
{
    int cur = -1;
    for (;;) {
        uint32_t m = fw_board_recv();
        if (!(m & MSG_FRAME) && (m & MSG_TRIS)) {
            /* the second half of the frame's triangles (after the vertices) */
            fw_board_send(render_frame_triangles(&ctx[1], 1, 2) == 0 ? MSG_TRIS_DONE : MSG_VERTS_FAILED);
            continue;
        }
        if (!(m & MSG_FRAME) && (m & MSG_VERTS)) {
            /* the second half of the frame's vertices, while core 0 does the first */
            unsigned si = m & 0x7fffu;
            int ok = 1;
            if ((int)si != cur) {
                ok = scene_init(&ctx[1], si, 1) == 0;
                cur = ok ? (int)si : -1;
            }
            ok = ok && render_frame_vertices(&ctx[1], 1, 2) == 0;
            fw_board_send(ok ? MSG_VERTS_DONE : MSG_VERTS_FAILED);
            continue;
        }
        if (!(m & MSG_FRAME)) continue;
        unsigned si = (m >> 16) & 0x7fffu;
        int ok = 1;
        if ((int)si != cur) {
            ok = scene_init(&ctx[1], si, 1) == 0;
            cur = ok ? (int)si : -1;
        }
        if (ok) ok = render_begin_frame(&ctx[1], (uint16_t)(m & 0xffffu)) == 0;
        for (;;) {
            int k = claim_strip();
            if (k == NSTRIPS) break;
            if (k < 0) {
                fw_board_wait();        /* core 0 notifies when a strip has been sent */
                continue;
            }
            /* a failed strip is still marked, so that core 0 never waits for it */
            int empty = 0;
            mark_done((unsigned)k, ok && render_one(&ctx[1], (unsigned)k, ring[k % FW_RING].px, &empty) == 0, empty);
        }
        fw_board_send(MSG_FRAME_DONE);
    }
}

/* ---- core 0 --------------------------------------------------------------- */

static void say(const char *a, const char *name, const char *b)
{
    char line[160], *p = line;
    p = put_str(p, a);
    p = put_str(p, name);
    p = put_str(p, b);
    *p = 0;
    fw_board_puts(line);
}

/* Starts the UART line "<what>NAME frame=F" in line; returns its end. */
static char *put_frame(char *line, const char *what, const char *name, uint16_t f)
{
    return put_u32(put_str(put_str(put_str(line, what), name), " frame="), f);
}

/* Frame f of scene si begins: no strip taken or sent yet, and core 1 (when
 * dual) told to start on its strips. */
static void strips_start(unsigned si, uint16_t f, int dual)
{
    /* core 1 is idle between frames (it said so with MSG_FRAME_DONE) */
    fw_board_lock();
    sh.claim = 0;
    sh.sent = 0;
    for (unsigned k = 0; k < NSTRIPS; k++) sh.done[k] = 0;
    fw_board_unlock();
    if (dual) fw_board_send(MSG_FRAME | ((uint32_t)si << 16) | f);
}

/* The progressive preview of frame f (the coarse pass set): core 0 renders
 * it and sends it as one window of the whole screen while core 1 starts on
 * its strips, says "coarse" before and "first" (U after t0) once it is on
 * the glass, and sets the full pass again. *err: a strip failed to render. */
static void send_preview(const char *name, uint16_t f, uint64_t t0, int *err, struct bus *b)
{
    char line[160];
    *put_str(put_frame(line, "coarse scene=", name, f), "\r\n") = 0;
    fw_board_puts(line);
    if (panel_flush_begin(&panel, 0, 0, FW_WIDTH, FW_HEIGHT) != 0) b->err = 1;
    for (unsigned k = 0; k < NSTRIPS; k++) {
        uint16_t *buf = preview_buf[k & 1u];
        uint16_t y0, y1;
        strip_rows(k, &y0, &y1);
        if (render_one(&ctx[0], k, buf, NULL) != 0) *err = 1;
        if (!b->err && panel_flush_rows(&panel, buf, (uint16_t)(y1 - y0), NULL, NULL) != 0) b->err = 1;
    }
    if (panel_flush_end(&panel) != 0) b->err = 1;
    for (unsigned k = 0; k < NSTRIPS; k++) glass[k].known = 0;   /* the preview's blocks */
    uint64_t cu = hal.now_us(hal.ctx) - t0;
    char *p = put_str(put_frame(line, "first scene=", name, f), " us=");
    *put_str(put_u32(p, cu > 0xffffffffu ? 0xffffffffu : (uint32_t)cu), "\r\n") = 0;
    fw_board_puts(line);
    render_set_pass(&ctx[0], RENDER_PASS_FULL);
}

/* Sends strip k, the next one in order, done (st 1 rendered, 2 failed;
 * text: the overlay drawn into it, or NULL): the columns changed_cols finds,
 * moved together unless they are the whole width (those continue one window
 * of whole rows), or nothing. Its buffer is released once the bus has
 * finished with it. */
static void send_strip(unsigned k, unsigned st, uint16_t bg, const char *text, struct bus *b)
{
    union strip_buf *sb = &ring[k % FW_RING];
    uint16_t *buf = sb->px;
    uint16_t y0, y1;
    strip_rows(k, &y0, &y1);
    const unsigned rows = (unsigned)(y1 - y0);
    if (text)
        font5x7_draw(buf, FW_WIDTH, y0, y1, 2, 2, 2, text, 0xffffu, 0x0000u);
    int x0, x1, track = FW_SKIP_UNCHANGED && st == 1 && !b->err;
    changed_cols(k, sb, rows, bg, track,
                 track && (!strip_empty(k) || (text && y0 < 2 + FONT5X7_BOX_H(2))), &x0, &x1);
    if (x0 > x1) {
        /* nothing changed: the strip's buffer is free once the bus has
         * finished with the ones before it */
        flush_close(b);
        if (panel_wait(&panel) != 0) b->err = 1;
        strip_sent((void *)(uintptr_t)k);
        return;
    }
    const uint16_t w = (uint16_t)(x1 - x0 + 1);
    if (!b->err && w == FW_WIDTH && !b->run) {
        flush_close(b);
        b->open = b->run = 1;
        if (panel_flush_begin(&panel, 0, y0, FW_WIDTH, (uint16_t)(FW_HEIGHT - y0)) != 0) b->err = 1;
    } else if (!b->err && w != FW_WIDTH) {
        pack_cols(sb, rows, x0, w);
        flush_close(b);
        b->open = 1;
        if (panel_flush_begin(&panel, (uint16_t)x0, y0, w, (uint16_t)rows) != 0) b->err = 1;
    }
    /* after a bus error the strips are only released */
    if (b->err || panel_flush_rows(&panel, buf, (uint16_t)rows, strip_sent, (void *)(uintptr_t)k) != 0) {
        b->err = 1;
        strip_sent((void *)(uintptr_t)k);
    }
}

/* Core 0's part of the frame's strips: sends them in order as they are done
 * (send_strip), and renders the next free one when the one to send is not
 * done yet; then ends the flush (after a bus error the glass is unknown).
 * bg: the scene's background, text: the overlay or NULL; *err: a strip
 * failed to render. */
static void send_strips(uint16_t bg, const char *text, int *err, struct bus *b)
{
    for (unsigned next = 0; next < NSTRIPS;) {
        unsigned st = strip_state(next);
        if (st) {
            /* the next strip in order is done: on the bus with it; the
             * first one at the start of the panel's vertical blank, so that
             * the writes run ahead of its scan (TE wired: no tearing while
             * the frame's strips come faster than the scan's rows) */
            if (next == 0 && te_sync && fw_board_te_wait(FW_TE_TIMEOUT_US) == 0) {
                te_sync = 0;
                fw_board_puts("warning panel TE line did not rise: frames go out unsynchronised\r\n");
            }

            if (st != 1) *err = 1;
            send_strip(next, st, bg, text, b);
            next++;
            continue;
        }
        int k = claim_strip();
        if (k >= 0 && k < NSTRIPS) {
            int empty = 0;
            int ok = render_one(&ctx[0], (unsigned)k, ring[k % FW_RING].px, &empty) == 0;
            mark_done((unsigned)k, ok, empty);
            continue;
        }
        /* the next strip is core 1's and not done yet: let the bus finish
         * (releasing the buffers core 1 may be waiting for), then sleep until
         * core 1 marks a strip */
        if (panel_wait(&panel) != 0) b->err = 1;
        if (!strip_state(next)) fw_board_wait();
    }
    if (b->open && panel_flush_end(&panel) != 0) b->err = 1;
    if (b->err)
        for (unsigned k = 0; k < NSTRIPS; k++) glass[k].known = 0;   /* what arrived is unknown */
    repair_k = repair_k + 1 < NSTRIPS ? repair_k + 1 : 0;
}

/* The frame's line: "fps" with its time us, or an "error" one; returns the
 * time in us (at least 1), 0 on error. */
static uint32_t frame_report(const char *name, uint16_t f, uint64_t us, int err, int bus_err)
{
    if (bus_err) {
        say("error scene=", name, " panel flush failed\r\n");
        return 0;
    }
    if (err) {
        say("error scene=", name, " render_strip failed\r\n");
        return 0;
    }
    uint32_t u = us > 0xffffffffu ? 0xffffffffu : (us ? (uint32_t)us : 1u);
    char line[160], *p = put_str(put_frame(line, "fps scene=", name, f), " us=");
    p = put_str(put_u32(p, u), " fps=");
    *put_str(put_fps(p, u), "\r\n") = 0;
    fw_board_puts(line);
    return u;
}

/* Renders and sends frame f of scene si; returns its time in us, 0 on error.
 * last_us: the previous frame's time, drawn as "X.Y fps" (0: no overlay). */
static uint32_t frame(unsigned si, uint16_t f, uint32_t last_us, int dual)
{
    const char *name = fw_scenes[si].name;
    char text[16], line[160];
    if (last_us) *put_str(put_fps(text, last_us), " fps") = 0;
    /* no TE: the frame begins one scan period (and the margin) after the
     * last one at the soonest; the wait is before its begin line, so the
     * frame's own time stays the renderer's and the bus's */
    if (!te_sync && FW_SCAN_HZ > 0 && last_begin_us) {
        const uint64_t period = 1020000u / (FW_SCAN_HZ > 0 ? FW_SCAN_HZ : 1);
        uint64_t prev = 0, now;
        unsigned same = 0;
        while ((now = hal.now_us(hal.ctx)) - last_begin_us < period) {
            /* a clock that only moves with the bus or a delay (the host's
             * simulated board): let a millisecond pass */
            same = now == prev ? same + 1 : 0;
            prev = now;
            if (same > 1000) {
                hal.delay_ms(hal.ctx, 1);
                same = 0;
            }
        }
    }
    uint64_t t0 = hal.now_us(hal.ctx);
    last_begin_us = t0;
    *put_str(put_u32(put_str(put_frame(line, "begin scene=", name, f), " t="), (uint32_t)t0), "\r\n") = 0;
    fw_board_puts(line);

    /* a rasterized frame is prepared by both cores (core 1 is idle between
     * frames): each takes half of its vertices, then half of its triangles;
     * core 0 bins them */
    int split = dual && fw_scenes[si].scene->kind == SCENE_RASTER;
    if (render_frame_start(&ctx[0], f) != 0) return 0;
    if (split) fw_board_send(MSG_VERTS | si);
    int ok = render_frame_vertices(&ctx[0], 0, split ? 2 : 1) == 0;
    if (split && fw_board_recv() != MSG_VERTS_DONE) {
        ok = ok && render_frame_vertices(&ctx[0], 1, 2) == 0;
        split = 0;        /* core 1 has no context: the triangles are core 0's */
    }
    if (split) fw_board_send(MSG_TRIS);
    ok = ok && render_frame_triangles(&ctx[0], 0, split ? 2 : 1) == 0;
    if (split && fw_board_recv() != MSG_TRIS_DONE)
        ok = ok && render_frame_triangles(&ctx[0], 0, 1) == 0;   /* all of them here, again */
    if (!ok || render_frame_finish(&ctx[0]) != 0) return 0;
    strips_start(si, f, dual);
    int err = 0;
    struct bus b = { 0, 0, 0 };
    if (FW_PROGRESSIVE && render_set_pass(&ctx[0], RENDER_PASS_COARSE) == 0) send_preview(name, f, t0, &err, &b);
    send_strips(render_background_565(&ctx[0]), last_us ? text : NULL, &err, &b);
    if (dual) (void)fw_board_recv();     /* MSG_FRAME_DONE: core 1 is idle again */
    return frame_report(name, f, hal.now_us(hal.ctx) - t0, err, b.err);
}

int main(void)
{
    if (fw_board_init(&hal, FW_PANEL.spi_max_hz) != 0) return 1;
    int dual = fw_board_cores() == 2;

    fw_boot_line(dual ? 2u : 1u, FW_WIDTH, FW_HEIGHT, FW_STRIP_ROWS, fw_scene_count);
    if (fw_panel_start(&panel, &FW_PANEL, &hal, FW_ROTATION, FW_WIDTH, FW_HEIGHT) != 0) return 1;
    /* a board that wires TE: the controller's TE output on, frames synchronised to it */
    te_sync = fw_board_te_wait(0) >= 0 && panel_tear_effect(&panel) == 0;
    if (dual && fw_board_core1_start(core1_main) != 0) {
        fw_board_puts("error core 1 did not answer the launch sequence: one core\r\n");
        dual = 0;
    }

    do {
        for (unsigned si = 0; si < fw_scene_count; si++) {
            if (scene_init(&ctx[0], si, 0) != 0) {
                /* (an image's scenes need only what it has: tools/scenec/features.sh) */
                if (RENDER_FEATURES_BUILT != RENDER_FEATURES_ALL &&
                    (render_features(fw_scenes[si].scene) & ~RENDER_FEATURES_BUILT))
                    say("error scene=", fw_scenes[si].name, " needs a renderer feature this image left out\r\n");
                else
                    say("error scene=", fw_scenes[si].name, " work memory too small\r\n");
                continue;
            }
            uint32_t last = 0;
            const uint16_t frames = FW_FRAMES_PER_SCENE ? (uint16_t)FW_FRAMES_PER_SCENE : fw_scenes[si].scene->frames;
            for (uint16_t f = 0; f < frames; f++) last = frame(si, f, last, dual);
        }
    } while (fw_board_again());
    return 0;
}
