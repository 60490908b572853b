/* SPDX-License-Identifier: MIT */
/* Exact byte streams and line changes of the DCS layer. */
#include <string.h>
#include "check.h"
#include "dcs.h"
#include "hal_rec.h"

static void EXPECT(const char *name, const char *got, const char *want)
{
    check(strcmp(got, want) == 0, name, "got \"%.300s\", want \"%.300s\"", got, want);
}

static void test_command(void)
{
    struct rec r; struct hal h; struct dcs d;
    rec_init(&r, &h, 0);
    dcs_init(&d, &h);
    EXPECT("dcs_init_deselects_and_sets_dc_high", rec_take(&r), "CS1 DC1");
    uint8_t p[2] = { 0x12, 0x34 };
    dcs_command(&d, 0xB2, p, 2);
    EXPECT("dcs_command_cs_low_dc_low_cmd_dc_high_params", rec_take(&r), "CS0 DC0 B2 DC1 12 34 CS1");
    dcs_command(&d, DCS_DISPON, NULL, 0);
    EXPECT("dcs_command_without_params", rec_take(&r), "CS0 DC0 29 DC1 CS1");
    check(d.bytes_sent == 4, "dcs_counts_bytes_sent", "%u", (unsigned)d.bytes_sent);
    dcs_delay_ms(&d, 7);
    EXPECT("dcs_delay_goes_to_hal", rec_take(&r), "D7");
    dcs_hw_reset(&d, 2, 120);
    EXPECT("dcs_hw_reset_pulse_then_wait", rec_take(&r), "RST1 RST0 D2 RST1 D120");
    dcs_hw_reset(&d, 0, 5);
    EXPECT("dcs_hw_reset_pulse_at_least_1ms", rec_take(&r), "RST1 RST0 D1 RST1 D5");
}

static void test_window(void)
{
    struct rec r; struct hal h; struct dcs d;
    rec_init(&r, &h, 0);
    dcs_init(&d, &h);
    rec_take(&r);
    dcs_set_window(&d, 0, 0, 239, 319);
    EXPECT("dcs_window_caset_raset_big_endian", rec_take(&r),
           "CS0 DC0 2A DC1 00 00 00 EF CS1 CS0 DC0 2B DC1 00 00 01 3F CS1");
    d.x_off = 80; d.y_off = 0x100;
    dcs_set_window(&d, 1, 2, 3, 4);
    EXPECT("dcs_window_adds_offsets", rec_take(&r),
           "CS0 DC0 2A DC1 00 51 00 53 CS1 CS0 DC0 2B DC1 01 02 01 04 CS1");
    check(dcs_set_window(&d, 5, 0, 4, 0) == -1 && strcmp(rec_take(&r), "") == 0,
          "dcs_window_rejects_start_after_end", "sent something");
    d.x_off = 10;
    check(dcs_set_window(&d, 0, 0, 0xFFFF, 0) == -1 && strcmp(rec_take(&r), "") == 0,
          "dcs_window_rejects_offset_overflow", "sent something");
    /* a controller's own window commands, 8-bit addresses */
    d.x_off = 2; d.y_off = 1;
    dcs_set_window_cmds(&d, 0x15, 0x75, 1, 0, 3, 127, 158);
    dcs_write_begin_cmd(&d, 0x5C);
    dcs_write_end(&d);
    EXPECT("dcs_window_cmds_8bit", rec_take(&r),
           "CS0 DC0 15 DC1 02 81 CS1 CS0 DC0 75 DC1 04 9F CS1 CS0 DC0 5C DC1 CS1");
    check(dcs_set_window_cmds(&d, 0x15, 0x75, 1, 0, 0, 254, 0) == -1 &&
          dcs_set_window_cmds(&d, 0x15, 0x75, 3, 0, 0, 1, 1) == -1 && strcmp(rec_take(&r), "") == 0,
          "dcs_window_cmds_rejects_8bit_overflow_and_bad_width", "sent something");
}

static void test_pixels(void)
{
    struct rec r; struct hal h; struct dcs d;
    rec_init(&r, &h, 0);
    dcs_init(&d, &h);
    rec_take(&r);
    uint16_t px[3] = { 0xF800, 0x07E0, 0x1234 };
    dcs_flush(&d, 4, 5, 3, 1, px);
    EXPECT("dcs_flush_window_ramwr_big_endian_pixels", rec_take(&r),
           "CS0 DC0 2A DC1 00 04 00 06 CS1 CS0 DC0 2B DC1 00 05 00 05 CS1 "
           "CS0 DC0 2C DC1 F8 00 07 E0 12 34 CS1");
    dcs_write_begin(&d, 1);
    dcs_write_data(&d, (const uint8_t *)"\xAB", 1);
    dcs_write_end(&d);
    EXPECT("dcs_write_continue_is_ramwrc", rec_take(&r), "CS0 DC0 3C DC1 AB CS1");
    check(dcs_flush(&d, 0, 0, 0, 1, px) == -1 && strcmp(rec_take(&r), "") == 0,
          "dcs_flush_rejects_empty_rectangle", "sent something");

    /* Many pixels: chunking keeps order and count. */
    static uint16_t big[1000];
    for (int i = 0; i < 1000; i++)
        big[i] = 0xA55A;
    dcs_write_begin(&d, 0);
    dcs_write_pixels(&d, big, 1000);
    dcs_write_end(&d);
    static char want[8192];
    strcpy(want, "CS0 DC0 2C DC1");
    for (int i = 0; i < 1000; i++)
        strcat(want, " A5 5A");
    strcat(want, " CS1");
    EXPECT("dcs_pixels_in_chunks_keep_order", rec_take(&r), want);
}

/* The same pixels through the asynchronous path: identical bytes, and no
 * buffer is modified while it is on the bus, across calls too. */
static void test_async(void)
{
    struct rec r1, r2; struct hal h1, h2; struct dcs d1, d2;
    static uint16_t px[2000];
    for (int i = 0; i < 2000; i++)
        px[i] = (uint16_t)(i * 2654435761u >> 7);
    rec_init(&r1, &h1, 0);
    rec_init(&r2, &h2, 1);
    dcs_init(&d1, &h1);
    dcs_init(&d2, &h2);
    for (int k = 0; k < 3; k++) {
        dcs_write_begin(&d1, k);
        dcs_write_begin(&d2, k);
        dcs_write_pixels(&d1, px, 700 + (size_t)k * 300);
        dcs_write_pixels(&d2, px, 700 + (size_t)k * 300);
        dcs_write_pixels(&d1, px + 3, 5);
        dcs_write_pixels(&d2, px + 3, 5);
        dcs_write_fill(&d1, 0x1234, 600);
        dcs_write_fill(&d2, 0x1234, 600);
        dcs_write_end(&d1);
        dcs_write_end(&d2);
    }
    check(r1.bytes == r2.bytes && strcmp(rec_take(&r1), rec_take(&r2)) == 0,
          "dcs_async_path_sends_same_bytes", "%zu vs %zu bytes", r1.bytes, r2.bytes);
    check(r2.async_writes > 6 && r2.clobbered == 0, "dcs_async_never_touches_buffer_in_flight",
          "%d writes, %d clobbered", r2.async_writes, r2.clobbered);
    check(d2.bytes_sent == d1.bytes_sent, "dcs_async_counts_bytes", "%u vs %u",
          (unsigned)d2.bytes_sent, (unsigned)d1.bytes_sent);
}

int main(void)
{
    test_command();
    test_window();
    test_pixels();
    test_async();
    return check_exit();
}
