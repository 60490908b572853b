/* gpio_reset.c — RUN/BOOTSEL through libgpiod 1.6 (see gpio_reset.h). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "gpio_reset.h"

#ifdef FLASHER_GPIOD
#include <gpiod.h>

static void sleep_ms(unsigned ms)
{
    struct timespec ts = { (time_t)(ms / 1000u), (long)(ms % 1000u) * 1000000L };
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {}
}

int gpio_reset_available(void) { return 1; }

static struct gpiod_line *take(struct gpiod_chip *chip, const struct gpio_reset_cfg *cfg,
                               unsigned pin, const char *what, int level, char *err, size_t errlen)
{
    struct gpiod_line *l = gpiod_chip_get_line(chip, pin);
    if (!l) {
        snprintf(err, errlen, "gpio: %s line %u: %s (%s has %u lines)", what, pin, strerror(errno),
                 cfg->chip, gpiod_chip_num_lines(chip));
        return NULL;
    }
    if (gpiod_line_request_output_flags(l, "cgfs-flasher", GPIOD_LINE_REQUEST_FLAG_OPEN_DRAIN,
                                        level) != 0) {
        snprintf(err, errlen, "gpio: %s line %u of %s: %s", what, pin, cfg->chip, strerror(errno));
        return NULL;
    }
    return l;
}

int gpio_reset_bootsel(const struct gpio_reset_cfg *cfg, char *err, size_t errlen)
{
    if (cfg->run_pin == cfg->bootsel_pin) {
        snprintf(err, errlen, "gpio: RUN and BOOTSEL must be different lines (both %u)", cfg->run_pin);
        return -1;
    }
    errno = 0;
    struct gpiod_chip *chip = gpiod_chip_open_lookup(cfg->chip);
    if (!chip) {
        snprintf(err, errlen, "gpio: cannot open %s: %s", cfg->chip,
                 errno ? strerror(errno) : "no such gpiochip");
        return -1;
    }
    int rc = -1;
    struct gpiod_line *boot = take(chip, cfg, cfg->bootsel_pin, "BOOTSEL", 0, err, errlen);
    struct gpiod_line *run = boot ? take(chip, cfg, cfg->run_pin, "RUN", 0, err, errlen) : NULL;
    if (boot && run) {
        sleep_ms(GPIO_RESET_PULSE_MS);
        gpiod_line_set_value(run, 1);          /* released: the Pico starts, sees BOOTSEL low */
        sleep_ms(GPIO_BOOTSEL_HOLD_MS);
        gpiod_line_set_value(boot, 1);
        rc = 0;
    }
    if (run) gpiod_line_release(run);
    if (boot) gpiod_line_release(boot);
    gpiod_chip_close(chip);
    return rc;
}

#else

int gpio_reset_available(void) { return 0; }

int gpio_reset_bootsel(const struct gpio_reset_cfg *cfg, char *err, size_t errlen)
{
    (void)cfg;
    snprintf(err, errlen, "gpio: built without libgpiod (install libgpiod-dev and rebuild)");
    return -1;
}

#endif
