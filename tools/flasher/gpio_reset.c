/* SPDX-License-Identifier: MIT */
/* gpio_reset.c — RUN/BOOTSEL through libgpiod (see gpio_reset.h): the 1.x
 * API or the 2.x one, as GPIOD_API_MAJOR says (pkg-config's version of
 * libgpiod at build time, mk/firmware.mk). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "gpio_reset.h"

#ifdef WITH_GPIOD
#include <gpiod.h>
#ifndef GPIOD_API_MAJOR
#define GPIOD_API_MAJOR 1
#endif

static void sleep_ms(unsigned ms)
{
    struct timespec ts = { (time_t)(ms / 1000u), (long)(ms % 1000u) * 1000000L };
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {}
}

int gpio_reset_available(void) { return 1; }

#if GPIOD_API_MAJOR >= 2
/* gpiod_chip_open_lookup's forms: a path, a number (gpiochipN) or a name. */
static struct gpiod_chip *open_lookup(const char *descr)
{
    char path[96];
    int n;
    if (strchr(descr, '/'))
        return gpiod_chip_open(descr);
    size_t d = strspn(descr, "0123456789");
    n = descr[0] && !descr[d] ? snprintf(path, sizeof path, "/dev/gpiochip%s", descr)
                              : snprintf(path, sizeof path, "/dev/%s", descr);
    if (n < 0 || (size_t)n >= sizeof path) {
        errno = ENAMETOOLONG;
        return NULL;
    }
    return gpiod_chip_open(path);
}

/* One open-drain output line as its own request, at level, with the
 * SoC's pull resistors off (see gpio_reset.h). */
static struct gpiod_line_request *take(struct gpiod_chip *chip, const struct gpio_reset_cfg *cfg,
                                       unsigned pin, const char *what, int level, char *err, size_t errlen)
{
    struct gpiod_chip_info *info = gpiod_chip_get_info(chip);
    size_t nlines = info ? gpiod_chip_info_get_num_lines(info) : 0;
    if (info) gpiod_chip_info_free(info);
    if (pin >= nlines) {
        snprintf(err, errlen, "gpio: %s line %u: %s (%s has %zu lines)", what, pin, strerror(EINVAL),
                 cfg->chip, nlines);
        return NULL;
    }
    struct gpiod_line_settings *ls = gpiod_line_settings_new();
    struct gpiod_line_config *lc = gpiod_line_config_new();
    struct gpiod_request_config *rc = gpiod_request_config_new();
    struct gpiod_line_request *req = NULL;
    errno = 0;
    if (ls && lc && rc && gpiod_line_settings_set_direction(ls, GPIOD_LINE_DIRECTION_OUTPUT) == 0 &&
        gpiod_line_settings_set_drive(ls, GPIOD_LINE_DRIVE_OPEN_DRAIN) == 0 &&
        gpiod_line_settings_set_bias(ls, GPIOD_LINE_BIAS_DISABLED) == 0 &&
        gpiod_line_settings_set_output_value(ls, level ? GPIOD_LINE_VALUE_ACTIVE
                                                       : GPIOD_LINE_VALUE_INACTIVE) == 0 &&
        gpiod_line_config_add_line_settings(lc, &pin, 1, ls) == 0) {
        gpiod_request_config_set_consumer(rc, "cgfs-flasher");
        req = gpiod_chip_request_lines(chip, rc, lc);
    }
    int e = errno;
    if (rc) gpiod_request_config_free(rc);
    if (lc) gpiod_line_config_free(lc);
    if (ls) gpiod_line_settings_free(ls);
    if (!req)
        snprintf(err, errlen, "gpio: %s line %u of %s: %s", what, pin, cfg->chip,
                 e ? strerror(e) : "request refused");
    return req;
}

int gpio_reset_bootsel(const struct gpio_reset_cfg *cfg, char *err, size_t errlen)
{
    if (cfg->run_pin == cfg->bootsel_pin) {
        snprintf(err, errlen, "gpio: RUN and BOOTSEL must be different lines (both %u)", cfg->run_pin);
        return -1;
    }
    errno = 0;
    struct gpiod_chip *chip = open_lookup(cfg->chip);
    if (!chip) {
        snprintf(err, errlen, "gpio: cannot open %s: %s", cfg->chip,
                 errno ? strerror(errno) : "no such gpiochip");
        return -1;
    }
    int rc = -1;
    struct gpiod_line_request *boot = take(chip, cfg, cfg->bootsel_pin, "BOOTSEL", 0, err, errlen);
    struct gpiod_line_request *run = boot ? take(chip, cfg, cfg->run_pin, "RUN", 0, err, errlen) : NULL;
    if (boot && run) {
        sleep_ms(GPIO_RESET_PULSE_MS);
        gpiod_line_request_set_value(run, cfg->run_pin, GPIOD_LINE_VALUE_ACTIVE);
        sleep_ms(GPIO_BOOTSEL_HOLD_MS);
        gpiod_line_request_set_value(boot, cfg->bootsel_pin, GPIOD_LINE_VALUE_ACTIVE);
        rc = 0;
    }
    if (run) gpiod_line_request_release(run);
    if (boot) gpiod_line_request_release(boot);
    gpiod_chip_close(chip);
    return rc;
}

#else
static struct gpiod_line *take(struct gpiod_chip *chip, const struct gpio_reset_cfg *cfg,
                               unsigned pin, const char *what, int level, char *err, size_t errlen)
{
    struct gpiod_line *l = gpiod_chip_get_line(chip, pin);
    if (!l) {
        snprintf(err, errlen, "gpio: %s line %u: %s (%s has %u lines)", what, pin, strerror(errno),
                 cfg->chip, gpiod_chip_num_lines(chip));
        return NULL;
    }
    if (gpiod_line_request_output_flags(l, "cgfs-flasher", GPIOD_LINE_REQUEST_FLAG_OPEN_DRAIN |
                                        GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE, level) != 0) {
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

#endif

#else

int gpio_reset_available(void) { return 0; }

int gpio_reset_bootsel(const struct gpio_reset_cfg *cfg, char *err, size_t errlen)
{
    (void)cfg;
    snprintf(err, errlen, "gpio: built without libgpiod (install libgpiod-dev and rebuild)");
    return -1;
}

#endif
