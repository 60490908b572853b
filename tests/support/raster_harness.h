/* SPDX-License-Identifier: MIT */
/* raster_harness.h — renders a scene strip by strip into whole-frame test
 * buffers (RGB565, RGB888, coverage), through the core's render_* API. */
#ifndef RASTER_HARNESS_H
#define RASTER_HARNESS_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "render.h"

struct frame {
    int w, h;
    uint16_t *rgb565;
    uint8_t *rgb888, *written;
    struct render_stats st;
};

static inline void frame_free(struct frame *f)
{
    free(f->rgb565);
    free(f->rgb888);
    free(f->written);
    memset(f, 0, sizeof *f);
}

/* 0 on success. Strips of `rows` rows, each rendered into its own buffers
 * and copied into the frame. */
static inline int render_frame(const struct scene *s, int w, int h, int rows, uint16_t frame_no, struct frame *f)
{
    memset(f, 0, sizeof *f);
    f->w = w;
    f->h = h;
    size_t ws = render_work_size(s, (uint16_t)w, (uint16_t)h, (uint16_t)rows);
    void *work = malloc(ws ? ws : 1);
    uint16_t *s565 = malloc((size_t)w * rows * 2);
    uint8_t *s888 = malloc((size_t)w * rows * 3), *swr = malloc((size_t)w * rows);
    f->rgb565 = malloc((size_t)w * h * 2);
    f->rgb888 = malloc((size_t)w * h * 3);
    f->written = malloc((size_t)w * h);
    struct render_ctx ctx;
    int rc = -1;
    if (!work || !s565 || !s888 || !swr || !f->rgb565 || !f->rgb888 || !f->written) goto out;
    if (render_init(&ctx, s, (uint16_t)w, (uint16_t)h, (uint16_t)rows, work, ws)) goto out;
    if (render_begin_frame(&ctx, frame_no)) goto out;
    for (int y0 = 0; y0 < h; y0 += rows) {
        int y1 = y0 + rows < h ? y0 + rows : h;
        struct render_target t = { (uint16_t)w, (uint16_t)h, (uint16_t)y0, (uint16_t)y1, s565, s888, swr };
        if (render_strip(&ctx, &t, &f->st)) goto out;
        memcpy(f->rgb565 + (size_t)y0 * w, s565, (size_t)(y1 - y0) * w * 2);
        memcpy(f->rgb888 + (size_t)y0 * w * 3, s888, (size_t)(y1 - y0) * w * 3);
        memcpy(f->written + (size_t)y0 * w, swr, (size_t)(y1 - y0) * w);
    }
    rc = 0;
out:
    free(work);
    free(s565);
    free(s888);
    free(swr);
    return rc;
}

static inline long frame_written(const struct frame *f)
{
    long n = 0;
    for (long i = 0; i < (long)f->w * f->h; i++) n += f->written[i] != 0;
    return n;
}

/* First 16 hex digits of SHA-256 over the RGBA buffer of the book's
 * reference (unwritten pixels 0,0,0,0; written A = 255), via sha256sum. */
static inline int frame_digest(const struct frame *f, const char *tmpdir, char out[17])
{
    char path[512], cmd[600];
    snprintf(path, sizeof path, "%s/raster_digest_%ld.rgba", tmpdir, (long)(size_t)f);
    FILE *fp = fopen(path, "wb");
    if (!fp) return -1;
    for (long i = 0; i < (long)f->w * f->h; i++) {
        uint8_t px[4] = { 0, 0, 0, 0 };
        if (f->written[i]) { px[0] = f->rgb888[3 * i]; px[1] = f->rgb888[3 * i + 1]; px[2] = f->rgb888[3 * i + 2]; px[3] = 255; }
        fwrite(px, 1, 4, fp);
    }
    fclose(fp);
    snprintf(cmd, sizeof cmd, "sha256sum '%s'", path);
    FILE *p = popen(cmd, "r");
    if (!p) return -1;
    int ok = fscanf(p, "%16s", out) == 1;
    pclose(p);
    remove(path);
    return ok ? 0 : -1;
}

#endif
