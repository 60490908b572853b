/* SPDX-License-Identifier: MIT */
/* fw_host_ref.c — renders frame 0 of scene `index` of a firmware scene table
 * (firmware/app/fw_scenes.h) on the host through the fixed-point core, as
 * raw RGB565 little-endian: the reference the emulated Pico's glass must
 * equal bit for bit.  usage: fw_host_ref INDEX W H STRIP_ROWS OUT.raw */
#include <stdio.h>
#include <stdlib.h>
#include "core_api.h"
#include "fw_scenes.h"

int main(int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: fw_host_ref INDEX W H STRIP_ROWS OUT.raw\n");
        return 2;
    }
    unsigned idx = (unsigned)atoi(argv[1]);
    uint16_t w = (uint16_t)atoi(argv[2]), h = (uint16_t)atoi(argv[3]), rows = (uint16_t)atoi(argv[4]);
    if (idx >= fw_scene_count || !w || !h || !rows) {
        fprintf(stderr, "fw_host_ref: bad arguments\n");
        return 2;
    }
    const struct core_api *api = &core_api_fixed;
    const void *s = fw_scenes[idx].scene;
    size_t ws = api->work_size(s, w, h, rows);
    if (getenv("FW_HOST_REF_VERBOSE")) fprintf(stderr, "work_size %zu\n", ws);
    void *work = ws ? malloc(ws) : NULL;
    uint16_t *px = malloc((size_t)w * h * 2);
    struct render_ctx ctx;
    if (api->init(&ctx, s, w, h, rows, work, ws) != 0 || api->begin_frame(&ctx, 0) != 0) {
        fprintf(stderr, "fw_host_ref: render_init failed\n");
        return 1;
    }
    for (uint16_t y = 0; y < h; y += rows) {
        struct render_target t = { .width = w, .height = h, .y0 = y,
                                  .y1 = (uint16_t)(y + rows > h ? h : y + rows), .rgb565 = px + (size_t)y * w };
        struct render_stats st = { 0 };
        if (api->render_strip(&ctx, &t, &st) != 0) {
            fprintf(stderr, "fw_host_ref: render_strip failed\n");
            return 1;
        }
    }
    FILE *f = fopen(argv[5], "wb");
    if (!f) return 1;
    for (size_t i = 0; i < (size_t)w * h; i++) {
        uint8_t b[2] = { (uint8_t)px[i], (uint8_t)(px[i] >> 8) };
        fwrite(b, 1, 2, f);
    }
    fclose(f);
    free(work);
    free(px);
    return 0;
}
