/* SPDX-License-Identifier: MIT */
/* Panel drivers: exact init streams, and round trips through the emulated
 * controller in every rotation of every descriptor. */
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "panel.h"
#include "sim/hal_sim.h"
#include "hal_rec.h"

static void expect_log(const char *name, const char *got, const char *want)
{
    check(strcmp(got, want) == 0, name, "got \"%.600s\", want \"%.600s\"", got, want);
}

static void test_init_streams(void)
{
    struct rec r; struct hal h; struct panel p;
    rec_init(&r, &h, 0);
    panel_init(&p, &panel_st7789_240x240, &h, 0);
    expect_log("st7789_240x240_init_stream", rec_take(&r),
        "CS1 DC1 BL0 RST1 RST0 D1 RST1 D120 "
        "CS0 DC0 01 DC1 CS1 D120 "                         /* SWRESET */
        "CS0 DC0 11 DC1 CS1 D120 "                         /* SLPOUT */
        "CS0 DC0 3A DC1 55 CS1 "                           /* COLMOD 16-bit */
        "CS0 DC0 B2 DC1 0C 0C 00 33 33 CS1 "               /* PORCTRL */
        "CS0 DC0 B7 DC1 35 CS1 CS0 DC0 BB DC1 20 CS1 "     /* GCTRL, VCOMS */
        "CS0 DC0 C0 DC1 2C CS1 CS0 DC0 C6 DC1 0F CS1 "     /* LCMCTRL, FRCTRL2 */
        "CS0 DC0 13 DC1 CS1 "                              /* NORON */
        "CS0 DC0 36 DC1 00 CS1 "                           /* MADCTL */
        "CS0 DC0 21 DC1 CS1 "                              /* INVON */
        "CS0 DC0 2A DC1 00 00 00 EF CS1 CS0 DC0 2B DC1 00 00 00 EF CS1 "
        "CS0 DC0 2C DC1 00x115200 CS1 "                    /* memory cleared */
        "CS0 DC0 29 DC1 CS1 BL1");                         /* DISPON, backlight */

    rec_init(&r, &h, 1);
    panel_init(&p, &panel_ili9341_320x240, &h, 0);
    expect_log("ili9341_320x240_init_stream", rec_take(&r),
        "CS1 DC1 BL0 RST1 RST0 D1 RST1 D120 "
        "CS0 DC0 01 DC1 CS1 D120 "
        "CS0 DC0 11 DC1 CS1 D120 "
        "CS0 DC0 3A DC1 55 CS1 "
        "CS0 DC0 C0 DC1 23 CS1 CS0 DC0 C1 DC1 10 CS1 "     /* PWCTRL1, PWCTRL2 */
        "CS0 DC0 C5 DC1 3E 28 CS1 CS0 DC0 C7 DC1 86 CS1 "  /* VMCTRL1, VMCTRL2 */
        "CS0 DC0 B1 DC1 00 1B CS1 "                        /* FRMCTR1 */
        "CS0 DC0 26 DC1 01 CS1 "                           /* GAMSET */
        "CS0 DC0 13 DC1 CS1 "
        "CS0 DC0 36 DC1 28 CS1 "                           /* MADCTL MV|BGR */
        "CS0 DC0 20 DC1 CS1 "                              /* INVOFF */
        "CS0 DC0 2A DC1 00 00 01 3F CS1 CS0 DC0 2B DC1 00 00 00 EF CS1 "
        "CS0 DC0 2C DC1 00x153600 CS1 "
        "CS0 DC0 29 DC1 CS1 BL1");

    rec_init(&r, &h, 0);
    panel_init(&p, &panel_st7735_80x160, &h, 0);
    expect_log("st7735_80x160_init_stream", rec_take(&r),
        "CS1 DC1 BL0 RST1 RST0 D1 RST1 D120 "
        "CS0 DC0 01 DC1 CS1 D120 "
        "CS0 DC0 11 DC1 CS1 D120 "                         /* SLPOUT: 120 ms on the ST7735S */
        "CS0 DC0 3A DC1 05 CS1 "                           /* COLMOD 16-bit */
        "CS0 DC0 B1 DC1 01 2C 2D CS1 "                     /* FRMCTR1 */
        "CS0 DC0 B4 DC1 07 CS1 "                           /* INVCTR */
        "CS0 DC0 13 DC1 CS1 "
        "CS0 DC0 36 DC1 08 CS1 "                           /* MADCTL BGR */
        "CS0 DC0 21 DC1 CS1 "                              /* INVON: IPS */
        "CS0 DC0 2A DC1 00 1A 00 69 CS1 CS0 DC0 2B DC1 00 01 00 A0 CS1 " /* columns 26.., row 1.. */
        "CS0 DC0 2C DC1 00x25600 CS1 "
        "CS0 DC0 29 DC1 CS1 BL1");

    rec_init(&r, &h, 0);
    panel_init(&p, &panel_ssd1351_128x128, &h, 0);
    expect_log("ssd1351_128x128_init_stream", rec_take(&r),
        "CS1 DC1 BL0 RST1 RST0 D1 RST1 D1 "
        "CS0 DC0 FD DC1 12 CS1 CS0 DC0 FD DC1 B1 CS1 "     /* command lock: open */
        "CS0 DC0 AE DC1 CS1 "                              /* sleep mode on */
        "CS0 DC0 B3 DC1 F1 CS1 CS0 DC0 CA DC1 7F CS1 CS0 DC0 A1 DC1 00 CS1 CS0 DC0 A2 DC1 00 CS1 "
        "CS0 DC0 B5 DC1 00 CS1 CS0 DC0 AB DC1 01 CS1 CS0 DC0 B1 DC1 32 CS1 CS0 DC0 BE DC1 05 CS1 "
        "CS0 DC0 C1 DC1 C8 80 C8 CS1 CS0 DC0 C7 DC1 0F CS1 CS0 DC0 B4 DC1 A0 B5 55 CS1 "
        "CS0 DC0 B6 DC1 01 CS1 "
        "CS0 DC0 A0 DC1 74 CS1 "                           /* re-map: rotation 0 */
        "CS0 DC0 A6 DC1 CS1 "                              /* normal display */
        "CS0 DC0 15 DC1 00 7F CS1 CS0 DC0 75 DC1 00 7F CS1 " /* one-byte addresses */
        "CS0 DC0 5C DC1 00x32768 CS1 "
        "CS0 DC0 AF DC1 CS1 BL1");                         /* sleep mode off */
    panel_set_rotation(&p, 1);
    uint16_t px1[2] = { 0xABCD, 0x0102 };
    panel_flush(&p, 3, 4, 2, 1, px1);
    expect_log("ssd1351_128x128_rotation1_rows_as_columns", rec_take(&r),
        "CS0 DC0 A0 DC1 77 CS1 "                           /* vertical address increment */
        "CS0 DC0 15 DC1 04 04 CS1 CS0 DC0 75 DC1 03 04 CS1 "
        "CS0 DC0 5C DC1 AB CD 01 02 CS1");

    rec_init(&r, &h, 0);
    panel_init(&p, &panel_st7789_240x240, &h, 2);
    rec_take(&r);
    uint16_t px[2] = { 0xABCD, 0x0102 };
    panel_flush(&p, 3, 4, 2, 1, px);
    expect_log("st7789_240x240_rotation2_row_offset_80", rec_take(&r),
        "CS0 DC0 2A DC1 00 03 00 04 CS1 CS0 DC0 2B DC1 00 54 00 54 CS1 "
        "CS0 DC0 2C DC1 AB CD 01 02 CS1");
    panel_set_rotation(&p, 3);
    panel_flush(&p, 3, 4, 1, 1, px);
    expect_log("st7789_240x240_rotation3_column_offset_80", rec_take(&r),
        "CS0 DC0 36 DC1 A0 CS1 "
        "CS0 DC0 2A DC1 00 53 00 53 CS1 CS0 DC0 2B DC1 00 04 00 04 CS1 "
        "CS0 DC0 2C DC1 AB CD CS1");
    check(panel_flush(&p, 239, 0, 2, 1, px) == -1 && panel_flush(&p, 0, 0, 0, 1, px) == -1 &&
          strcmp(rec_take(&r), "") == 0, "panel_flush_rejects_rectangles_off_the_panel", "sent");
    check(panel_init(&p, &panel_st7789_240x240, &h, 4) == -1, "panel_init_rejects_rotation_4", "accepted");
}

/* A controller described by its own command set: other codes, 8-bit
 * addresses, no orientation command; the driver sends only what it names. */
static const struct panel_ctl ctl_other = {
    .name = "other",
    .set_cols = 0x15, .set_rows = 0x75, .addr_bytes = 1,
    .write_mem = 0x5C,
    .orient = PANEL_CMD_NONE,
    .inv_on = 0xA7, .inv_off = 0xA6,
    .disp_on = 0xAF, .disp_off = 0xAE,
    .sleep_in = 0xAE, .sleep_out = PANEL_CMD_NONE,
    .sleep_wait_ms = 3,
};
static const struct panel_cmd other_init[] = { { 0xFD, 1, 0, { 0x12 } } };
static const struct panel_desc desc_other = {
    .name = "other_96x64", .controller = "other", .ctl = &ctl_other,
    .width = 96, .height = 64, .reset_low_ms = 1, .reset_wait_ms = 2,
    .init = other_init, .init_len = 1,
    .madctl = { 0, 0, 0, 0 }, .x_off = { 1, 2, 3, 4 }, .y_off = { 5, 6, 7, 8 },
    .invert = 1, .spi_mode = 0,
};

static void test_other_command_set(void)
{
    struct rec r; struct hal h; struct panel p;
    uint16_t px[2] = { 0xABCD, 0x0102 };
    rec_init(&r, &h, 0);
    int rc = panel_init(&p, &desc_other, &h, 1);
    expect_log("other_command_set_init_stream", rec_take(&r),
        "CS1 DC1 BL0 RST1 RST0 D1 RST1 D2 "
        "CS0 DC0 FD DC1 12 CS1 "                           /* init table */
        "CS0 DC0 A7 DC1 CS1 "                              /* inversion on */
        "CS0 DC0 15 DC1 02 41 CS1 CS0 DC0 75 DC1 06 65 CS1 " /* 8-bit window plus offsets */
        "CS0 DC0 5C DC1 00x12288 CS1 "
        "CS0 DC0 AF DC1 CS1 BL1");
    rc |= panel_flush(&p, 3, 4, 2, 1, px);
    rc |= panel_sleep(&p, 1);
    rc |= panel_sleep(&p, 0);
    rc |= panel_display(&p, 0);
    expect_log("other_command_set_ops", rec_take(&r),
        "CS0 DC0 15 DC1 05 06 CS1 CS0 DC0 75 DC1 0A 0A CS1 CS0 DC0 5C DC1 AB CD 01 02 CS1 "
        "CS0 DC0 AE DC1 CS1 D3 CS0 DC0 AE DC1 CS1");
    check(rc == 0 && panel_ctl(&p) == &ctl_other, "other_command_set_rc", "rc %d", rc);
    /* 8-bit addresses: a window beyond 255 after the offset is refused (no
     * command sent, the bus only deselected) */
    struct panel_desc big = desc_other;
    big.width = 300;
    rec_init(&r, &h, 0);
    panel_init(&p, &big, &h, 0);
    rec_take(&r);
    int ok = panel_flush(&p, 253, 0, 2, 1, px) == 0 && strstr(rec_take(&r), "CS0 DC0 15 DC1 FE FF CS1");
    int refused = panel_flush(&p, 254, 0, 2, 1, px) == -1;
    const char *after = rec_take(&r);
    check(ok && refused && strcmp(after, "CS1") == 0, "other_command_set_8bit_address_overflow",
          "ok %d refused %d sent \"%s\"", ok, refused, after);
    /* the DCS descriptors name no command set: DCS is the default */
    rec_init(&r, &h, 0);
    panel_init(&p, &panel_st7789_240x240, &h, 0);
    check(panel_st7789_240x240.ctl == NULL && panel_ctl(&p) == &panel_ctl_dcs, "dcs_is_the_default_command_set",
          "not DCS");
}

static uint32_t crc32_str(const char *s)
{
    uint32_t crc = 0xFFFFFFFFu;
    for (; *s; s++) {
        crc ^= (uint8_t)*s;
        for (int k = 0; k < 8; k++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

/* The command streams of the DCS descriptors, pinned: the CRC-32 of the
 * recorded log of panel_init in each rotation, and of a run of every other
 * operation after it (flush, fill, streamed flush, stopped flush, display
 * off/on, sleep in/out, the next rotation, a pixel), as the driver sent them
 * before the command sets (struct panel_ctl) existed; and the SSD1351's,
 * GC9A01's and ILI9488's as first written (its init stream and rotation-1 window spelled out in
 * test_init_streams, all four rotations shown by the emulated glass in
 * round_trip). */
static void test_streams_pinned(void)
{
    static const struct { const char *name; uint8_t rot; uint32_t init, ops; } pin[] = {
        { "st7789_240x240", 0, 0x991AE6C2u, 0xD3D52803u },  { "st7789_240x240", 1, 0x855A4ABCu, 0x928849AFu },
        { "st7789_240x240", 2, 0x38D1E9E9u, 0x609102C0u },  { "st7789_240x240", 3, 0x1D706808u, 0x97D78997u },
        { "st7789_240x320", 0, 0x0FA22AC9u, 0xABC5475Bu },  { "st7789_240x320", 1, 0xC76AF323u, 0x60BFD969u },
        { "st7789_240x320", 2, 0x40FA9C07u, 0x92DF18F0u },  { "st7789_240x320", 3, 0x9FB28DB9u, 0xC5ECE8E7u },
        { "ili9341_320x240", 0, 0x5E5E6B0Eu, 0xA6DE2B64u }, { "ili9341_320x240", 1, 0xAE17EA18u, 0x8E476F5Du },
        { "ili9341_320x240", 2, 0x06861594u, 0xD9749F4Au }, { "ili9341_320x240", 3, 0x9696B2E4u, 0xB75D30F6u },
        { "ili9341_240x320", 0, 0x9696B2E4u, 0xB75D30F6u }, { "ili9341_240x320", 1, 0x5E5E6B0Eu, 0xA6DE2B64u },
        { "ili9341_240x320", 2, 0xAE17EA18u, 0x8E476F5Du }, { "ili9341_240x320", 3, 0x06861594u, 0xD9749F4Au },
        { "ssd1351_128x128", 0, 0xC12E4400u, 0xBB463552u }, { "ssd1351_128x128", 1, 0x9A6CE112u, 0x9C431795u },
        { "ssd1351_128x128", 2, 0x4B239178u, 0xEEC8C60Bu }, { "ssd1351_128x128", 3, 0x1061346Au, 0xC9CDE4CCu },
        { "gc9a01_240x240", 0, 0x5F908109u, 0x5304318Bu }, { "gc9a01_240x240", 1, 0x43D02D77u, 0xC9825A12u },
        { "gc9a01_240x240", 2, 0x10C837C7u, 0x6A1E6E20u }, { "gc9a01_240x240", 3, 0x1B0853EDu, 0x6CD16B9Cu },
        { "ili9488_320x480", 0, 0x0F0A2F2Bu, 0x17741552u }, { "ili9488_320x480", 1, 0xE3B371CFu, 0x75257064u },
        { "ili9488_320x480", 2, 0x378B77D7u, 0x02181F0Bu }, { "ili9488_320x480", 3, 0xBB6B0F55u, 0xF15C3ABBu },
    };
    int bad = 0;
    char first[80] = "";
    for (size_t i = 0; i < sizeof pin / sizeof pin[0]; i++)
        for (int async = 0; async < 2; async++) {
            struct rec r; struct hal h; struct panel p;
            uint16_t px[6] = { 0x1234, 0xABCD, 0xFFFF, 0, 0x0F0F, 0xF0F0 };
            rec_init(&r, &h, async);
            int rc = panel_init(&p, panel_find(pin[i].name), &h, pin[i].rot);
            uint32_t c_init = crc32_str(rec_take(&r));
            rc |= panel_flush(&p, 1, 2, 3, 2, px);
            rc |= panel_fill(&p, (uint16_t)(p.width - 4), (uint16_t)(p.height - 3), 4, 3, 0xBEEF);
            rc |= panel_flush_begin(&p, 0, 0, 2, 3);
            rc |= panel_flush_rows(&p, px, 1, NULL, NULL);
            rc |= panel_flush_rows(&p, px + 2, 2, NULL, NULL);
            rc |= panel_flush_end(&p);
            rc |= panel_flush_begin(&p, 0, 0, 2, 3);
            rc |= panel_flush_rows(&p, px, 1, NULL, NULL);
            rc |= panel_flush_stop(&p);
            rc |= panel_display(&p, 0);
            rc |= panel_display(&p, 1);
            rc |= panel_sleep(&p, 1);
            rc |= panel_sleep(&p, 0);
            rc |= panel_set_rotation(&p, (uint8_t)((pin[i].rot + 1) & 3));
            rc |= panel_flush(&p, 0, 0, 1, 1, px);
            rc |= panel_wait(&p);
            uint32_t c_ops = crc32_str(rec_take(&r));
            if (getenv("PIN_PRINT"))
                printf("pin %s %u %08X %08X\n", pin[i].name, (unsigned)pin[i].rot, (unsigned)c_init, (unsigned)c_ops);
            if (rc || c_init != pin[i].init || c_ops != pin[i].ops) {
                if (!bad++)
                    snprintf(first, sizeof first, "%s rotation %u async %d: rc %d, %08X %08X", pin[i].name,
                             (unsigned)pin[i].rot, async, rc, (unsigned)c_init, (unsigned)c_ops);
            }
        }
    check(!bad, "dcs_descriptor_streams_pinned", "%d differ, first %s", bad, first);
}

static void test_find(void)
{
    check(panel_find("st7789") == &panel_st7789_240x240 && panel_find("ili9341") == &panel_ili9341_320x240 &&
          panel_find("st7735") == &panel_st7735_128x160 && panel_find("st7735_80x160") == &panel_st7735_80x160 &&
          panel_find("st7789_240x320") == &panel_st7789_240x320 &&
          panel_find("ili9341_240x320") == &panel_ili9341_240x320 && panel_find("ssd1306") == NULL,
          "panel_find_names", "mismatch");
    /* hal/panels.def: each PANEL names its descriptor's own controller and a
     * glass the emulator has, with the glass's size in the view it is shown
     * (the round trips below check the pixels) */
    int bad = 0, n = 0;
#define PANEL(p_name, p_ctl, p_glass, p_view)                                                                \
    {                                                                                                    \
        uint8_t v = 9;                                                                                   \
        const struct panel_desc *d = panel_find(#p_name);                                                   \
        const struct emu_module *m = emu_module_find(#p_name, &v);                                          \
        bad += !d || d != panel_all[n] || strcmp(d->controller, #p_ctl) || m != &emu_module_##p_glass || \
               v != (p_view) || ((p_view) & 1 ? m->glass_h : m->glass_w) != d->width ||                      \
               ((p_view) & 1 ? m->glass_w : m->glass_h) != d->height;                                      \
        n++;                                                                                             \
    }
#define GLASS(...)
#include "panels.def"
#undef PANEL
#undef GLASS
    check(!bad && !panel_all[n], "panels_def_consistent", "%d of %d PANEL lines disagree with their descriptor", bad, n);
    /* every descriptor states its bus: a mode 0..3 and its controller's rated
     * write clock (a serial write cycle of 10 to 1000 ns) */
    int bus_bad = 0;
    for (size_t i = 0; panel_all[i]; i++)
        bus_bad += panel_all[i]->spi_mode > 3 || panel_all[i]->spi_max_hz < PANEL_WRITE_CYCLE_NS(1000) ||
                   panel_all[i]->spi_max_hz > PANEL_WRITE_CYCLE_NS(10);
    check(!bus_bad, "panels_state_spi_mode_and_rated_clock", "%d descriptor(s) without a mode or rated clock", bus_bad);
}

static uint16_t pattern(uint32_t x, uint32_t y)
{
    return (uint16_t)(x * 0x9E37u + y * 0x79B9u + x * y);
}

/* A full-screen pattern flushed in strips, and a small rectangle, in
 * rotation r must show on the glass (viewed as the descriptor's rotation 0)
 * turned r*90 degrees clockwise (where there is glass: a round one has
 * none in the corners). */
static void round_trip(const struct panel_desc *d, uint8_t rot, struct emu_panel *e, uint16_t *img, uint16_t *glass)
{
    char name[80];
    uint8_t view;
    const struct emu_module *m = emu_module_find(d->name, &view);
    struct hal_sim s; struct hal h; struct panel p;
    emu_panel_init(e, m, view);
    hal_sim_init(&s, &h, e);
    int rc = panel_init(&p, d, &h, rot);
    uint16_t W = panel_width(&p), H = panel_height(&p);
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++)
            img[y * W + x] = pattern(x, y);
    for (uint16_t y = 0; y < H && rc == 0; y += 16) {
        uint16_t rows = (uint16_t)(H - y < 16 ? H - y : 16);
        rc = panel_flush(&p, 0, y, W, rows, img + (size_t)y * W);
    }
    /* A 3x2 marker at (5, 7) over the pattern. */
    uint16_t mk[6] = { 1, 2, 3, 4, 5, 6 };
    if (rc == 0)
        rc = panel_flush(&p, 5, 7, 3, 2, mk);
    for (int i = 0; i < 6; i++)
        img[(7 + i / 3) * W + 5 + i % 3] = mk[i];
    emu_panel_finish(e, s.t_ns);
    uint16_t gw = emu_panel_glass_width(e), gh = emu_panel_glass_height(e);
    snprintf(name, sizeof name, "round_trip_%s_rotation%u", d->name, (unsigned)rot);
    if (!check(rc == 0 && !emu_panel_violation(e) && gw == d->width && gh == d->height, name,
               "rc %d, %s, glass %ux%u", rc, emu_panel_violation(e) ? emu_panel_violation(e) : "-", gw, gh))
        return;
    emu_panel_glass(e, glass, gw, gh);
    long bad = 0, first = -1;
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++) {
            uint32_t dx, dy;
            switch (rot) {
            case 1: dx = H - 1 - y; dy = x; break;
            case 2: dx = W - 1 - x; dy = H - 1 - y; break;
            case 3: dx = y; dy = W - 1 - x; break;
            default: dx = x; dy = y; break;
            }
            if (emu_panel_shown(e, (uint16_t)dx, (uint16_t)dy) && glass[dy * gw + dx] != img[y * W + x]) {
                if (first < 0)
                    first = (long)(y * W + x);
                bad++;
            }
        }
    check(bad == 0, name, "%ld pixels misplaced, first at logical (%ld, %ld)", bad,
          first < 0 ? 0 : first % W, first < 0 ? 0 : first / W);
}

/* SPI timing moves the simulated clock: a full 240x240 frame at 62.5 MHz. */
static void test_sim_timing(struct emu_panel *e)
{
    struct hal_sim s; struct hal h; struct panel p;
    uint8_t view = 0;
    const struct emu_module *m = emu_module_find("st7789", &view);
    emu_panel_init(e, m, view);
    hal_sim_init(&s, &h, e);
    panel_init(&p, &panel_st7789_240x240, &h, 0);
    hal_sim_set_spi_hz(&s, 62500000);
    uint64_t t0 = hal_sim_now_us(&s), b0 = s.spi_bytes;
    panel_fill(&p, 0, 0, 240, 240, 0xFFFF);
    uint64_t us = hal_sim_now_us(&s) - t0;
    check(s.spi_bytes - b0 == 115200 + 11 && us == (115211ull * 128) / 1000, "sim_spi_time_at_62_5mhz",
          "%llu bytes in %llu us", (unsigned long long)(s.spi_bytes - b0), (unsigned long long)us);
}

/* A 16-bit-frame pixel operation for the recording HAL: the bytes it would
 * put on the wire, high byte first, and the completion at once. */
static int rec_pixels(void *ctx, const uint16_t *px, size_t n, hal_done_fn done, void *arg)
{
    for (size_t i = 0; i < n; i++) {
        uint8_t b[2] = { (uint8_t)(px[i] >> 8), (uint8_t)px[i] };
        rec_spi_write(ctx, b, 2);
    }
    if (done)
        done(arg);
    return 0;
}

static void count_done(void *arg) { ++*(int *)arg; }

/* The streaming flush sends what panel_flush sends, with and without the
 * HAL's pixel operation, and refuses rows beyond its window. */
static void test_streaming(void)
{
    static const uint16_t px[6] = { 0x1234, 0xABCD, 0x0001, 0xFF00, 0x00FF, 0x8001 };
    char want[600];
    for (int mode = 0; mode < 3; mode++) {
        struct rec r; struct hal h; struct panel p;
        char name[64];
        rec_init(&r, &h, mode > 0);
        if (mode == 2)
            h.pixels_async = rec_pixels;
        panel_init(&p, &panel_st7789_240x240, &h, 0);
        rec_take(&r);
        panel_flush(&p, 10, 20, 2, 3, px);
        snprintf(want, sizeof want, "%s", rec_take(&r));
        int done = 0;
        int rc = panel_flush_begin(&p, 10, 20, 2, 3);
        rc |= panel_flush_rows(&p, px, 1, count_done, &done);
        rc |= panel_flush_rows(&p, px + 2, 2, count_done, &done);
        int over = panel_flush_rows(&p, px, 1, NULL, NULL);
        rc |= panel_flush_end(&p);
        snprintf(name, sizeof name, "panel_streaming_flush_same_bytes_mode%d", mode);
        expect_log(name, rec_take(&r), want);
        snprintf(name, sizeof name, "panel_streaming_flush_rules_mode%d", mode);
        check(rc == 0 && over == -1 && done == 2, name, "rc %d, extra row %d, %d completions", rc, over, done);
        /* an end before every row was sent closes the write and says so */
        panel_flush_begin(&p, 0, 0, 2, 2);
        panel_flush_rows(&p, px, 1, NULL, NULL);
        int short_end = panel_flush_end(&p);
        int again = panel_flush_begin(&p, 0, 0, 1, 1);
        panel_flush_end(&p);
        snprintf(name, sizeof name, "panel_streaming_flush_short_end_mode%d", mode);
        check(short_end == -1 && again == 0, name, "end %d, next begin %d", short_end, again);
        if (mode == 0)
            check(panel_flush_begin(&p, 239, 0, 2, 1) == -1, "panel_streaming_flush_window_outside", "accepted");
    }
}

/* The ILI9488's 18-bit pixels: each RGB565 pixel as three bytes, every
 * channel's top bits repeated below it, with or without the HAL's 16-bit
 * pixel operation (never used for them), in a flush, a streamed flush and
 * a fill; a frame is 1.5 times the bytes of 16-bit. */
static void test_rgb666(void)
{
    static const uint16_t px[4] = { 0xF800, 0x07E0, 0x001F, 0x8410 };
    for (int mode = 0; mode < 3; mode++) {
        struct rec r; struct hal h; struct panel p;
        char name[64];
        rec_init(&r, &h, mode > 0);
        if (mode == 2)
            h.pixels_async = rec_pixels;
        panel_init(&p, &panel_ili9488_320x480, &h, 0);
        rec_take(&r);
        panel_flush(&p, 1, 2, 2, 2, px);
        panel_flush_begin(&p, 0, 0, 4, 1);
        panel_flush_rows(&p, px, 1, NULL, NULL);
        panel_flush_end(&p);
        panel_fill(&p, 0, 0, 1, 1, 0x8410);
        snprintf(name, sizeof name, "ili9488_rgb666_mode%d", mode);
        expect_log(name, rec_take(&r),
            "CS0 DC0 2A DC1 00 01 00 02 CS1 CS0 DC0 2B DC1 00 02 00 03 CS1 "
            "CS0 DC0 2C DC1 FF 00 00 00 FF 00 00 00 FF 84 82 84 CS1 "
            "CS0 DC0 2A DC1 00 00 00 03 CS1 CS0 DC0 2B DC1 00 00 00 00 CS1 "
            "CS0 DC0 2C DC1 FF 00 00 00 FF 00 00 00 FF 84 82 84 CS1 "
            "CS0 DC0 2A DC1 00 00 00 00 CS1 CS0 DC0 2B DC1 00 00 00 00 CS1 "
            "CS0 DC0 2C DC1 84 82 84 CS1");
    }
    struct rec r; struct hal h; struct panel p;
    rec_init(&r, &h, 0);
    panel_init(&p, &panel_ili9488_320x480, &h, 0);
    uint32_t b0 = p.dcs.bytes_sent;
    panel_fill(&p, 0, 0, 320, 480, 0);
    check(p.dcs.bytes_sent - b0 == 320u * 480u * 3u + 11u, "ili9488_frame_bytes", "%u bytes",
          (unsigned)(p.dcs.bytes_sent - b0));
    rec_take(&r);
}

int main(void)
{
    struct emu_panel *e = malloc(sizeof *e);
    uint16_t *img = malloc(sizeof(uint16_t) * 320 * 480), *glass = malloc(sizeof(uint16_t) * 320 * 480);
    if (!e || !img || !glass)
        return 1;
    test_init_streams();
    test_find();
    test_other_command_set();
    test_streams_pinned();
    test_streaming();
    test_rgb666();
    for (size_t i = 0; panel_all[i]; i++)
        for (uint8_t r = 0; r < 4; r++)
            round_trip(panel_all[i], r, e, img, glass);
    test_sim_timing(e);
    free(e); free(img); free(glass);
    return check_exit();
}
