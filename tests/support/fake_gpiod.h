/* SPDX-License-Identifier: MIT */
/* fake_gpiod.h — a libgpiod without a kernel, for tests: the functions the
 * Linux HAL backend (hal/linux/hal_linux.c) and the flasher's GPIO reset
 * (tools/flasher/gpio_reset.c) call, in the 1.x API or the 2.x API
 * (GPIOD_API_MAJOR, as they are compiled), over one chip of
 * fake_gpiod.num_lines lines. Each request, value change and release is
 * passed to fake_gpiod.on_event. Linked into test programs, or into the
 * LD_PRELOAD shim (tests/support/shim_linux_panel.c), where it takes the place of the
 * real library's functions. */
#ifndef TESTS_FAKE_GPIOD_H
#define TESTS_FAKE_GPIOD_H

#define FAKE_GPIOD_LINES 64

enum fake_gpiod_ev { FAKE_GPIOD_REQUEST, FAKE_GPIOD_SET, FAKE_GPIOD_RELEASE };

struct fake_gpiod_line {
    int requested, value, open_drain;
    int bias_disabled;   /* requested with the pull-up/down resistors off */
};

struct fake_gpiod {
    const char *chip_name;       /* the chip's name ("gpiochip0"); /dev/<name> in 2.x */
    unsigned num_lines;          /* <= FAKE_GPIOD_LINES */
    int chip_missing;            /* opening fails with ENOENT */
    int busy_line;               /* requesting it fails with EBUSY; -1: none */
    int chips_open, chips_closed;
    struct fake_gpiod_line lines[FAKE_GPIOD_LINES];
    void (*on_event)(unsigned off, int value, enum fake_gpiod_ev ev);
};

extern struct fake_gpiod fake_gpiod;

/* Back to one chip "gpiochip0" of 28 free lines, no callback. */
void fake_gpiod_reset(void);

#endif
