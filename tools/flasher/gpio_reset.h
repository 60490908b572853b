/* SPDX-License-Identifier: MIT */
/* gpio_reset.h — puts a Pico into its boot ROM from a Raspberry Pi host:
 * libgpiod (1.x or 2.x API) drives the Pico's RUN and BOOTSEL lines.
 *
 * Wiring (defaults; the pins are options of the flasher):
 *   Pi GPIO23 (header pin 16)  → Pico RUN (pin 30)
 *   Pi GPIO24 (header pin 18)  → Pico BOOTSEL (the button's pad / TP6, QSPI SS)
 *   Pi GND                     ↔ Pico GND
 * Both lines are driven open-drain: low pulls the Pico's line down, "high"
 * lets go (the Pico's own pull-ups hold RUN and QSPI SS high), so the
 * wiring never fights the button or the flash chip. Both are requested
 * with bias disabled: the Pi's own pull-downs (the default on GPIO23/24)
 * would otherwise drag the released lines towards low against the Pico's
 * pull-ups.
 *
 * Sequence: BOOTSEL low, RUN low GPIO_RESET_PULSE_MS, RUN released, BOOTSEL
 * held GPIO_BOOTSEL_HOLD_MS while the boot ROM samples it, released. */
#ifndef GPIO_RESET_H
#define GPIO_RESET_H

#include <stddef.h>

#define GPIO_RESET_PULSE_MS 10u
#define GPIO_BOOTSEL_HOLD_MS 100u

struct gpio_reset_cfg {
    const char *chip;        /* "gpiochip0", a number, or a /dev path */
    unsigned run_pin;        /* line offsets on that chip */
    unsigned bootsel_pin;
};

#define GPIO_RESET_DEFAULTS { "gpiochip0", 23u, 24u }

/* 1 when the flasher was built with libgpiod. */
int gpio_reset_available(void);

/* Resets the Pico into the boot ROM. 0 on success; -1 with one line in err
 * (no gpiochip, line busy or out of range, no permission, built without
 * libgpiod). */
int gpio_reset_bootsel(const struct gpio_reset_cfg *cfg, char *err, size_t errlen);

#endif
