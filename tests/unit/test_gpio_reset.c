/* SPDX-License-Identifier: MIT */
/* test_gpio_reset.c — the flasher's RUN/BOOTSEL sequence (tools/flasher/
 * gpio_reset.c) against a fake libgpiod (tests/support/fake_gpiod.c, in the API
 * gpio_reset.c is compiled for: 1.x, or 2.x with GPIOD_API_MAJOR=2) that
 * records each line change with its time, so the order, the levels, the
 * open-drain requests with bias disabled, the hold times and the error paths are checked
 * without a Raspberry Pi. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "check.h"
#include "fake_gpiod.h"
#include "gpio_reset.h"

static struct { unsigned off; int value; double t_ms; int release; } ev[32];
static int nev;

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

static void record(unsigned off, int value, enum fake_gpiod_ev kind)
{
    if (nev < 32) {
        ev[nev].off = off;
        ev[nev].value = value;
        ev[nev].t_ms = now_ms();
        ev[nev].release = kind == FAKE_GPIOD_RELEASE;
        nev++;
    }
}

static void reset_fake(void)
{
    fake_gpiod_reset();
    fake_gpiod.on_event = record;
    memset(ev, 0, sizeof ev);
    nev = 0;
}

int main(void)
{
    struct gpio_reset_cfg cfg = GPIO_RESET_DEFAULTS;
    char err[200] = "";
    const struct fake_gpiod_line *L = fake_gpiod.lines;
    check(gpio_reset_available() == 1, "gpio_reset_built_with_libgpiod", "available() is 0");
#if GPIOD_API_MAJOR >= 2
    check(1, "gpio_reset_libgpiod_api_2", "");
#else
    check(1, "gpio_reset_libgpiod_api_1", "");
#endif

    reset_fake();
    int rc = gpio_reset_bootsel(&cfg, err, sizeof err);
    /* expected: BOOTSEL(24)=0, RUN(23)=0, RUN=1, BOOTSEL=1, releases */
    int order = rc == 0 && nev == 6 && ev[0].off == 24 && ev[0].value == 0 && ev[1].off == 23 &&
                ev[1].value == 0 && ev[2].off == 23 && ev[2].value == 1 && ev[3].off == 24 &&
                ev[3].value == 1 && ev[4].release && ev[5].release;
    check(order, "gpio_reset_sequence_bootsel_low_then_run_pulse", "rc %d, %d events, err '%s'", rc,
          nev, err);
    if (order) {
        check(ev[2].t_ms - ev[1].t_ms >= GPIO_RESET_PULSE_MS, "gpio_reset_run_pulse_long_enough",
              "RUN low %.2f ms", ev[2].t_ms - ev[1].t_ms);
        check(ev[3].t_ms - ev[2].t_ms >= GPIO_BOOTSEL_HOLD_MS, "gpio_reset_bootsel_held_after_run",
              "BOOTSEL held %.2f ms after RUN", ev[3].t_ms - ev[2].t_ms);
    }
    check(L[23].open_drain && L[24].open_drain, "gpio_reset_lines_open_drain", "open drain %d %d",
          L[23].open_drain, L[24].open_drain);
    check(L[23].bias_disabled && L[24].bias_disabled, "gpio_reset_lines_bias_disabled", "bias disabled %d %d",
          L[23].bias_disabled, L[24].bias_disabled);
    check(!L[23].requested && !L[24].requested && fake_gpiod.chips_closed == 1 &&
          fake_gpiod.chips_open == 1, "gpio_reset_releases_lines_and_chip",
          "requested %d %d, opened %d, closed %d", L[23].requested, L[24].requested,
          fake_gpiod.chips_open, fake_gpiod.chips_closed);

    reset_fake();
    fake_gpiod.chip_missing = 1;
    rc = gpio_reset_bootsel(&cfg, err, sizeof err);
    check(rc == -1 && strcmp(err, "gpio: cannot open gpiochip0: No such file or directory") == 0 &&
          nev == 0, "gpio_reset_no_gpiochip_one_line", "rc %d err '%s'", rc, err);

    reset_fake();
    fake_gpiod.busy_line = 23;
    rc = gpio_reset_bootsel(&cfg, err, sizeof err);
    check(rc == -1 && strcmp(err, "gpio: RUN line 23 of gpiochip0: Device or resource busy") == 0 &&
          !L[24].requested && fake_gpiod.chips_closed == 1,
          "gpio_reset_busy_line_releases_the_other", "rc %d err '%s'", rc, err);

    reset_fake();
    cfg.run_pin = 40;
    rc = gpio_reset_bootsel(&cfg, err, sizeof err);
    check(rc == -1 && strstr(err, "RUN line 40") && strstr(err, "has 28 lines") && fake_gpiod.chips_closed == 1 &&
          !L[24].requested, "gpio_reset_line_out_of_range", "rc %d err '%s'", rc, err);

    reset_fake();
    cfg.run_pin = 24;
    rc = gpio_reset_bootsel(&cfg, err, sizeof err);
    check(rc == -1 && nev == 0 && strstr(err, "different lines"), "gpio_reset_same_line_rejected",
          "rc %d err '%s'", rc, err);
    return check_exit();
}
