/* SPDX-License-Identifier: MIT */
/* hal_linux.h — HAL backend for Linux: spidev for SPI, libgpiod (the 1.x
 * or the 2.x API, whichever pkg-config finds at build time) for the D/C,
 * RESET, CS and backlight lines, CLOCK_MONOTONIC for time.
 *
 * Typical Raspberry Pi wiring: spi_dev "/dev/spidev0.0", gpio_chip
 * "gpiochip0", DC 25, RESET 27, BL 18, CS handled by spidev (cs = -1).
 *
 * Built without libgpiod (no pkg-config libgpiod at build time),
 * hal_linux_open fails with a message saying so unless every line is -1.
 */
#ifndef HAL_LINUX_H
#define HAL_LINUX_H

#include <stdint.h>
#include "hal.h"

struct hal_linux_config {
    const char *spi_dev;         /* e.g. "/dev/spidev0.0" */
    uint32_t spi_hz;             /* bus clock, e.g. 32000000 */
    uint8_t spi_mode;            /* 0..3 (ST7789 modules without CS often need 3) */
    const char *gpio_chip;       /* e.g. "gpiochip0" (in /dev), or a path */
    int dc, reset, cs, bl;       /* line offsets on gpio_chip; -1 = not connected */
};

struct hal_linux {
    int fd;                      /* spidev, -1 when closed */
    uint32_t spi_hz;
    void *chip;                  /* struct gpiod_chip * */
    void *lines[4];              /* by enum hal_line: struct gpiod_line * (1.x),
                                    struct gpiod_line_request * (2.x) */
    unsigned offs[4];            /* their line offsets */
    int async_pending;
    char err[160];               /* last error, one line */
};

/* Sets cfg to the Raspberry Pi defaults above. */
void hal_linux_default_config(struct hal_linux_config *cfg);

/* Opens the devices and fills *out (out->ctx = l). Returns 0, or -1 with a
 * one-line message in hal_linux_error(l); nothing stays open on failure. */
int hal_linux_open(struct hal_linux *l, struct hal *out, const struct hal_linux_config *cfg);
void hal_linux_close(struct hal_linux *l);
const char *hal_linux_error(const struct hal_linux *l);

#endif
