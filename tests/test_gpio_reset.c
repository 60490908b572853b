/* test_gpio_reset.c — the flasher's RUN/BOOTSEL sequence (tools/flasher/
 * gpio_reset.c) against a fake libgpiod: the functions it calls are defined
 * here and record each line change with its time, so the order, the levels,
 * the open-drain requests, the hold times and the error paths are checked
 * without a Raspberry Pi. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <gpiod.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "check.h"
#include "gpio_reset.h"

#define NLINES 28
struct gpiod_chip { int open; };
struct gpiod_line { unsigned off; int requested, value, flags; };

static struct gpiod_chip chip;
static struct gpiod_line lines[NLINES];
static int chip_missing, busy_line = -1, closed;
static struct { unsigned off; int value; double t_ms; int release; } ev[32];
static int nev;

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

static void record(unsigned off, int value, int release)
{
    if (nev < 32) {
        ev[nev].off = off;
        ev[nev].value = value;
        ev[nev].t_ms = now_ms();
        ev[nev].release = release;
        nev++;
    }
}

struct gpiod_chip *gpiod_chip_open_lookup(const char *descr)
{
    if (chip_missing || strcmp(descr, "gpiochip0") != 0) {
        errno = ENOENT;
        return NULL;
    }
    chip.open = 1;
    return &chip;
}

void gpiod_chip_close(struct gpiod_chip *c)
{
    c->open = 0;
    closed++;
}

unsigned int gpiod_chip_num_lines(struct gpiod_chip *c)
{
    (void)c;
    return NLINES;
}

struct gpiod_line *gpiod_chip_get_line(struct gpiod_chip *c, unsigned int offset)
{
    (void)c;
    if (offset >= NLINES) {
        errno = EINVAL;
        return NULL;
    }
    lines[offset].off = offset;
    return &lines[offset];
}

int gpiod_line_request_output_flags(struct gpiod_line *l, const char *consumer, int flags,
                                    int default_val)
{
    (void)consumer;
    if ((int)l->off == busy_line) {
        errno = EBUSY;
        return -1;
    }
    l->requested = 1;
    l->flags = flags;
    l->value = default_val;
    record(l->off, default_val, 0);
    return 0;
}

int gpiod_line_set_value(struct gpiod_line *l, int value)
{
    l->value = value;
    record(l->off, value, 0);
    return 0;
}

void gpiod_line_release(struct gpiod_line *l)
{
    l->requested = 0;
    record(l->off, l->value, 1);
}

static void reset_fake(void)
{
    memset(lines, 0, sizeof lines);
    memset(ev, 0, sizeof ev);
    nev = 0;
    chip_missing = 0;
    busy_line = -1;
    closed = 0;
}

int main(void)
{
    struct gpio_reset_cfg cfg = GPIO_RESET_DEFAULTS;
    char err[200] = "";
    check(gpio_reset_available() == 1, "gpio_reset_built_with_libgpiod", "available() is 0");

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
    check(lines[23].flags == GPIOD_LINE_REQUEST_FLAG_OPEN_DRAIN &&
          lines[24].flags == GPIOD_LINE_REQUEST_FLAG_OPEN_DRAIN,
          "gpio_reset_lines_open_drain", "flags %d %d", lines[23].flags, lines[24].flags);
    check(!lines[23].requested && !lines[24].requested && closed == 1 && !chip.open,
          "gpio_reset_releases_lines_and_chip", "requested %d %d, closed %d", lines[23].requested,
          lines[24].requested, closed);

    reset_fake();
    chip_missing = 1;
    rc = gpio_reset_bootsel(&cfg, err, sizeof err);
    check(rc == -1 && strcmp(err, "gpio: cannot open gpiochip0: No such file or directory") == 0 &&
          nev == 0, "gpio_reset_no_gpiochip_one_line", "rc %d err '%s'", rc, err);

    reset_fake();
    busy_line = 23;
    rc = gpio_reset_bootsel(&cfg, err, sizeof err);
    check(rc == -1 && strcmp(err, "gpio: RUN line 23 of gpiochip0: Device or resource busy") == 0 &&
          !lines[24].requested && closed == 1,
          "gpio_reset_busy_line_releases_the_other", "rc %d err '%s'", rc, err);

    reset_fake();
    cfg.run_pin = 40;
    rc = gpio_reset_bootsel(&cfg, err, sizeof err);
    check(rc == -1 && strstr(err, "RUN line 40") && strstr(err, "has 28 lines") && closed == 1 &&
          !lines[24].requested, "gpio_reset_line_out_of_range", "rc %d err '%s'", rc, err);

    reset_fake();
    cfg.run_pin = 24;
    rc = gpio_reset_bootsel(&cfg, err, sizeof err);
    check(rc == -1 && nev == 0 && strstr(err, "different lines"), "gpio_reset_same_line_rejected",
          "rc %d err '%s'", rc, err);
    return check_exit();
}
