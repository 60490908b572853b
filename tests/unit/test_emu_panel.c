/* SPDX-License-Identifier: MIT */
/* Emulated panel API and the sim backend (the command-level rules are in
 * the vectors, tests/vectors/panel, replayed by test_panel_vectors). */
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "dcs.h"
#include "sim/hal_sim.h"

static int done_calls;
static void on_done(void *arg) { (void)arg; done_calls++; }

int main(void)
{
    struct emu_panel *e = malloc(sizeof *e);
    uint16_t *g = malloc(sizeof(uint16_t) * 320 * 240);
    if (!e || !g)
        return 1;
    uint8_t view = 9;
    check(emu_module_find("ili9341", &view) == &emu_module_ili9341_240x320 && view == 1,
          "emu_module_find_ili9341_is_landscape_view", "view %u", view);
    check(emu_module_find("st7789", &view) == &emu_module_st7789_240x240 && view == 0 &&
          emu_module_find("nope", NULL) == NULL, "emu_module_find_names", "mismatch");
    check(emu_panel_init(e, &emu_module_st7789_240x240, 4) == -1, "emu_panel_init_rejects_view_4", "accepted");
    emu_panel_init(e, &emu_module_ili9341_240x320, 1);
    check(emu_panel_glass_width(e) == 320 && emu_panel_glass_height(e) == 240 &&
          emu_panel_glass(e, g, 240, 320) == -1 && emu_panel_glass(e, g, 320, 240) == 0,
          "emu_panel_glass_size_follows_view", "%ux%u", emu_panel_glass_width(e), emu_panel_glass_height(e));
    check(g[0] == 0xFFFF && emu_panel_violation(e) == NULL, "emu_panel_power_on_tn_glass_is_white_and_clean",
          "%04X", g[0]);
    check(emu_panel_mem(e, 0, 0) == 0xB63A && emu_panel_mem(e, 240, 0) == 0,
          "emu_panel_power_on_memory_is_xorshift32", "%04X", emu_panel_mem(e, 0, 0));

    /* The sim backend: delay moves the clock; a violation makes SPI writes fail. */
    struct hal_sim s; struct hal h; struct dcs d;
    emu_panel_init(e, &emu_module_st7789_240x240, 0);
    hal_sim_init(&s, &h, e);
    dcs_init(&d, &h);
    h.delay_ms(h.ctx, 120);
    check(h.now_us(h.ctx) == 120000, "hal_sim_delay_moves_clock", "%llu", (unsigned long long)h.now_us(h.ctx));
    h.line_set(h.ctx, HAL_LINE_CS, 0);
    h.line_set(h.ctx, HAL_LINE_DC, 0);
    int rc = h.spi_write_async(h.ctx, (const uint8_t *)"\x00", 1, on_done, NULL);   /* NOP */
    h.line_set(h.ctx, HAL_LINE_CS, 1);
    check(done_calls == 1 && rc == 0 && h.spi_wait(h.ctx) == 0, "hal_sim_async_completes_at_once",
          "done %d rc %d", done_calls, rc);
    rc = dcs_command(&d, DCS_SLPOUT, NULL, 0);
    check(rc == 0, "hal_sim_write_ok", "rc %d", rc);
    rc = dcs_command(&d, DCS_COLMOD, (const uint8_t *)"\x55", 1);  /* 0 ms after SLPOUT */
    check(rc == HAL_SIM_EPROTO && emu_panel_violation(e) &&
          strcmp(emu_panel_violation(e), "COLMOD (0x3A) at byte 2: sent 0 us after SLPOUT, needs 5000 us") == 0,
          "hal_sim_reports_violation", "rc %d: %s", rc, emu_panel_violation(e) ? emu_panel_violation(e) : "-");
    check(dcs_command(&d, DCS_NOP, NULL, 0) == HAL_SIM_EPROTO && emu_panel_finish(e, 0) == -1,
          "hal_sim_fails_after_violation", "accepted");

    /* No panel: bytes are only counted. */
    hal_sim_init(&s, &h, NULL);
    dcs_init(&d, &h);
    check(dcs_command(&d, 0xEE, (const uint8_t *)"\x01\x02", 2) == 0 && s.spi_bytes == 3,
          "hal_sim_without_panel_counts_bytes", "%llu", (unsigned long long)s.spi_bytes);
    free(e);
    free(g);
    return check_exit();
}
