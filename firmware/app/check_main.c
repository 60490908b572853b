/* SPDX-License-Identifier: MIT */
/* check_main.c — the bring-up application (the cgfs-check images): brings
 * the panel up as the scene images do (FW_PANEL, FW_ROTATION, FW_WIDTH x
 * FW_HEIGHT) and shows the bring-up pattern (check_pattern.h: bars,
 * gradients, corner marks, border, the settings), streamed in strips of
 * FW_STRIP_ROWS rows through panel_flush_rows, one core. The pattern is
 * sent again every FW_CHECK_PERIOD_MS (a loose wire that spoiled it shows
 * by the next time), each time after its lines on the UART (115200 8N1),
 * queued as the scene images' are:
 *   boot board=B cores=1 cpu_hz=H size=WxH strip_rows=R scenes=1
 *   begin scene=check frame=F t=T   (as the scene images' frames: rp2040sim)
 *   check panel=P size=WxH rotation=R offset=X,Y order=RGB|BGR invert=on|off spi_mhz=M clk_sys_mhz=M
 *   error ...   (panel_init or a flush failed) */
#include <stddef.h>
#include <stdint.h>
#include "check_pattern.h"
#include "fw_board.h"
#include "fw_start.h"
#include "fw_text.h"
#include "panel.h"

#ifndef FW_WIDTH
#define FW_WIDTH 240
#endif
#ifndef FW_HEIGHT
#define FW_HEIGHT 240
#endif
#ifndef FW_STRIP_ROWS
#define FW_STRIP_ROWS 8
#endif
#ifndef FW_PANEL
#define FW_PANEL panel_st7789_240x240
#endif
#ifndef FW_ROTATION
#define FW_ROTATION 0
#endif
/* FW_ROUND_GLASS 1: the panel's glass is round (the GC9A01): the pattern
 * inside the square its circle holds */
#ifndef FW_ROUND_GLASS
#define FW_ROUND_GLASS 0
#endif
#ifndef FW_CHECK_PERIOD_MS
#define FW_CHECK_PERIOD_MS 2000u
#endif

#define NSTRIPS ((FW_HEIGHT + FW_STRIP_ROWS - 1) / FW_STRIP_ROWS)

/* two strips: one drawn while the other is on the bus */
static uint16_t strip[2][FW_WIDTH * FW_STRIP_ROWS];
static struct check_layout layout;
static struct hal hal;
static struct panel panel;

/* The whole pattern, one window, strip by strip; 0 or the panel's error. */
static int send_pattern(void)
{
    int rc = panel_flush_begin(&panel, 0, 0, FW_WIDTH, FW_HEIGHT);
    for (unsigned k = 0; rc == 0 && k < NSTRIPS; k++) {
        const uint16_t y0 = (uint16_t)(k * FW_STRIP_ROWS);
        const uint16_t y1 = (uint16_t)(y0 + FW_STRIP_ROWS > FW_HEIGHT ? FW_HEIGHT : y0 + FW_STRIP_ROWS);
        /* strip k & 1 was sent two strips ago: panel_flush_rows waited for it */
        check_rows(&layout, strip[k & 1u], y0, y1);
        rc = panel_flush_rows(&panel, strip[k & 1u], (uint16_t)(y1 - y0), NULL, NULL);
    }
    int end = panel_flush_end(&panel);
    return rc ? rc : end;
}

int main(void)
{
    char line[160], uart[160], *p;
    if (fw_board_init(&hal, FW_PANEL.spi_max_hz) != 0) return 1;
    fw_boot_line(1, FW_WIDTH, FW_HEIGHT, FW_STRIP_ROWS, 1);
    if (fw_panel_start(&panel, &FW_PANEL, &hal, FW_ROTATION, FW_WIDTH, FW_HEIGHT) != 0) return 1;
    const struct check_settings s = {
        .panel = FW_PANEL.name,
        .width = FW_WIDTH,
        .height = FW_HEIGHT,
        .rotation = FW_ROTATION,
        .x_off = FW_PANEL.x_off[FW_ROTATION],
        .y_off = FW_PANEL.y_off[FW_ROTATION],
        .bgr = (uint8_t)panel_bgr(&panel),
        .invert = FW_PANEL.invert,
        .spi_hz = fw_board_spi_hz(),
        .sys_hz = fw_board_cpu_hz(),
        .round = FW_ROUND_GLASS,
    };
    check_setup(&layout, &s);
    check_uart_line(uart, sizeof uart, &s);

    uint32_t f = 0;
    do {
        const uint64_t t0 = hal.now_us(hal.ctx);
        p = put_u32(put_str(line, "begin scene=check frame="), f++);
        *put_str(put_u32(put_str(p, " t="), (uint32_t)t0), "\r\n") = 0;
        fw_board_puts(line);
        fw_board_puts(uart);
        if (send_pattern() != 0) fw_board_puts("error scene=check panel flush failed\r\n");
        while (hal.now_us(hal.ctx) - t0 < (uint64_t)FW_CHECK_PERIOD_MS * 1000u) {}
    } while (fw_board_again());
    return 0;
}
