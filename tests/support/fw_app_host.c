/* SPDX-License-Identifier: MIT */
/* fw_app_host.c — the firmware application (firmware/app/main.c, built with
 * main renamed fw_app_main) on a host board: its HAL is hal/sim's, into the
 * strict emulated ST7789, so the byte sequence the board sends (init, the
 * progressive preview, the strips streamed through panel_flush_rows, the fps
 * overlay) is checked by the C emulator. Every scene of the table passes
 * once, FW_FRAMES_PER_SCENE frames each; cases:
 *   fw_app_<scene>_frame0_glass   the glass after frame 0 equals the core's
 *                                 render of frame 0, bit for bit
 *   fw_app_protocol               no violation, no error line, main returns 0
 * usage: fw_app_host */
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "fw_board.h"
#include "fw_scenes.h"
#include "render.h"
#include "sim/emu_panel.h"
#include "sim/hal_sim.h"

#ifndef FW_STRIP_ROWS
#define FW_STRIP_ROWS 8
#endif
#define W 240
#define H 240

int fw_app_main(void);

static struct emu_panel *emu;
static struct hal_sim sim;
static uint16_t glass[W * H], ref[W * H];
static int errors;

const char fw_board_name[] = "host";

int fw_board_init(struct hal *h, uint32_t spi_max_hz)
{
    (void)spi_max_hz;
    uint8_t view;
    const struct emu_module *m = emu_module_find("st7789_240x240", &view);
    emu = calloc(1, sizeof *emu);
    if (!m || !emu || emu_panel_init(emu, m, view) != 0)
        return -1;
    hal_sim_init(&sim, h, emu);
    hal_sim_set_spi_hz(&sim, 62500000u);
    return 0;
}

/* Frame 0 of the scene called name, rendered by the core into ref. */
static int reference(const char *name)
{
    for (unsigned i = 0; i < fw_scene_count; i++) {
        const struct fw_scene *fs = &fw_scenes[i];
        if (strcmp(fs->name, name) != 0)
            continue;
        void *work = fs->work_size[0] ? malloc(fs->work_size[0]) : NULL;
        struct render_ctx ctx;
        int rc = render_init(&ctx, fs->scene, W, H, FW_STRIP_ROWS, work, fs->work_size[0]);
        if (rc == 0)
            rc = render_begin_frame(&ctx, 0);
        for (uint16_t y = 0; rc == 0 && y < H; y += FW_STRIP_ROWS) {
            struct render_target t = { .width = W, .height = H, .y0 = y,
                                       .y1 = (uint16_t)(y + FW_STRIP_ROWS > H ? H : y + FW_STRIP_ROWS),
                                       .rgb565 = ref + (size_t)y * W };
            struct render_stats st = { 0 };
            rc = render_strip(&ctx, &t, &st);
        }
        free(work);
        return rc;
    }
    return -1;
}

/* The application's UART: after "fps scene=NAME frame=0 ..." the glass holds
 * frame 0 (the flush has ended). */
void fw_board_puts(const char *s)
{
    fputs(s, stderr);
    if (!strncmp(s, "error", 5))
        errors++;
    if (strncmp(s, "fps scene=", 10) != 0)
        return;
    char name[64], test[96];
    size_t n = strcspn(s + 10, " ");
    if (n >= sizeof name || strncmp(s + 10 + n, " frame=0 ", 9) != 0)
        return;
    memcpy(name, s + 10, n);
    name[n] = 0;
    snprintf(test, sizeof test, "fw_app_%s_frame0_glass", name);
    for (char *p = test; *p; p++)
        if (*p == '/' || *p == '-')
            *p = '_';
    int rc = emu_panel_glass(emu, glass, W, H);
    long bad = 0;
    if (rc == 0 && reference(name) == 0)
        for (size_t i = 0; i < (size_t)W * H; i++)
            bad += glass[i] != ref[i];
    else
        bad = -1;
    check(bad == 0 && !emu_panel_violation(emu), test, "%ld pixels differ (%s)", bad,
          emu_panel_violation(emu) ? emu_panel_violation(emu) : "no violation");
}

int fw_board_again(void) { return 0; }
unsigned fw_board_cores(void) { return 1; }
int fw_board_core1_start(void (*entry)(void))
{
    (void)entry;
    return -1;
}
void fw_board_send(uint32_t v) { (void)v; }
uint32_t fw_board_recv(void) { return 0; }
void fw_board_lock(void) {}
void fw_board_unlock(void) {}
void fw_board_notify(void) {}
void fw_board_wait(void) {}
uint32_t fw_board_cpu_hz(void) { return 133000000u; }
uint32_t fw_board_spi_hz(void) { return 62500000u; }
int fw_board_te_wait(uint32_t timeout_us)
{
    (void)timeout_us;
    return -1;
}

int main(void)
{
    int rc = fw_app_main();
    int fin = emu ? emu_panel_finish(emu, sim.t_ns) : -1;
    check(rc == 0 && fin == 0 && errors == 0, "fw_app_protocol", "main %d, %s, %d error lines", rc,
          emu && emu_panel_violation(emu) ? emu_panel_violation(emu) : "no violation", errors);
    free(emu);
    return check_exit();
}
