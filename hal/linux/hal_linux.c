/* SPDX-License-Identifier: MIT */
/* hal_linux.c — HAL backend: spidev + libgpiod + CLOCK_MONOTONIC.
 *
 * libgpiod's API changed with its major version: 1.x (Debian 12) has line
 * objects (gpiod_chip_get_line, gpiod_line_request_output); 2.x (Debian 13,
 * current Raspberry Pi OS) has line requests built from settings and a line
 * config. GPIOD_API_MAJOR (1 or 2, from pkg-config's version of libgpiod,
 * mk/hal.mk) selects the one compiled; each line is its own request/object,
 * so an error names the line either way. */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <sys/ioctl.h>
#include <linux/spi/spidev.h>
#ifdef WITH_GPIOD
#include <gpiod.h>
#ifndef GPIOD_API_MAJOR
#define GPIOD_API_MAJOR 1
#endif
#endif
#include "hal_linux.h"

/* spidev refuses transfers larger than its buffer (4096 bytes by default). */
#define SPIDEV_MAX 4096

static void set_err(struct hal_linux *l, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(l->err, sizeof l->err, fmt, ap);
    va_end(ap);
}

#ifdef WITH_GPIOD
#if GPIOD_API_MAJOR >= 2
/* "gpiochip0" -> /dev/gpiochip0; a path (with '/') as it is. */
static struct gpiod_chip *open_chip(const char *name)
{
    char path[96];
    if (strchr(name, '/'))
        return gpiod_chip_open(name);
    if ((size_t)snprintf(path, sizeof path, "/dev/%s", name) >= sizeof path) {
        errno = ENAMETOOLONG;
        return NULL;
    }
    return gpiod_chip_open(path);
}

/* One output line as its own request, driven to level at once. */
static struct gpiod_line_request *request_output(struct gpiod_chip *chip, unsigned off, int level)
{
    struct gpiod_line_settings *ls = gpiod_line_settings_new();
    struct gpiod_line_config *lc = gpiod_line_config_new();
    struct gpiod_request_config *rc = gpiod_request_config_new();
    struct gpiod_line_request *req = NULL;
    if (ls && lc && rc && gpiod_line_settings_set_direction(ls, GPIOD_LINE_DIRECTION_OUTPUT) == 0 &&
        gpiod_line_settings_set_output_value(ls, level ? GPIOD_LINE_VALUE_ACTIVE
                                                       : GPIOD_LINE_VALUE_INACTIVE) == 0 &&
        gpiod_line_config_add_line_settings(lc, &off, 1, ls) == 0) {
        gpiod_request_config_set_consumer(rc, "cgfs-hal");
        req = gpiod_chip_request_lines(chip, rc, lc);
    }
    int e = errno;
    if (rc) gpiod_request_config_free(rc);
    if (lc) gpiod_line_config_free(lc);
    if (ls) gpiod_line_settings_free(ls);
    errno = e;
    return req;
}
#else
static struct gpiod_chip *open_chip(const char *name)
{
    return strchr(name, '/') ? gpiod_chip_open(name) : gpiod_chip_open_by_name(name);
}

static struct gpiod_line *request_output(struct gpiod_chip *chip, unsigned off, int level)
{
    struct gpiod_line *ln = gpiod_chip_get_line(chip, off);
    if (!ln || gpiod_line_request_output(ln, "cgfs-hal", level) < 0)
        return NULL;
    return ln;
}
#endif
#endif

void hal_linux_default_config(struct hal_linux_config *cfg)
{
    cfg->spi_dev = "/dev/spidev0.0";
    cfg->spi_hz = 32000000;
    cfg->spi_mode = 0;
    cfg->gpio_chip = "gpiochip0";
    cfg->dc = 25;
    cfg->reset = 27;
    cfg->cs = -1;
    cfg->bl = 18;
}

static int lx_spi_write(void *ctx, const uint8_t *data, size_t n)
{
    struct hal_linux *l = ctx;
    while (n > 0) {
        size_t m = n < SPIDEV_MAX ? n : SPIDEV_MAX;
        struct spi_ioc_transfer tr;
        memset(&tr, 0, sizeof tr);
        tr.tx_buf = (uint64_t)(uintptr_t)data;
        tr.len = (uint32_t)m;
        tr.speed_hz = l->spi_hz;
        tr.bits_per_word = 8;
        if (ioctl(l->fd, SPI_IOC_MESSAGE(1), &tr) < 0) {
            set_err(l, "hal_linux: SPI transfer failed: %s", strerror(errno));
            return -1;
        }
        data += m;
        n -= m;
    }
    return 0;
}

/* spidev has no asynchronous interface: the write completes before return. */
static int lx_spi_write_async(void *ctx, const uint8_t *data, size_t n, hal_done_fn done, void *arg)
{
    int rc = lx_spi_write(ctx, data, n);
    if (done)
        done(arg);
    return rc;
}

static int lx_spi_wait(void *ctx)
{
    (void)ctx;
    return 0;
}

static void lx_line_set(void *ctx, enum hal_line line, int level)
{
#ifdef WITH_GPIOD
    struct hal_linux *l = ctx;
    if ((unsigned)line >= 4 || !l->lines[line])
        return;
#if GPIOD_API_MAJOR >= 2
    gpiod_line_request_set_value(l->lines[line], l->offs[line],
                                 level ? GPIOD_LINE_VALUE_ACTIVE : GPIOD_LINE_VALUE_INACTIVE);
#else
    gpiod_line_set_value(l->lines[line], level != 0);
#endif
#else
    (void)ctx; (void)line; (void)level;
#endif
}

static void lx_delay_ms(void *ctx, uint32_t ms)
{
    (void)ctx;
    struct timespec ts = { (time_t)(ms / 1000), (long)(ms % 1000) * 1000000L };
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR)
        ;
}

static uint64_t lx_now_us(void *ctx)
{
    (void)ctx;
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

void hal_linux_close(struct hal_linux *l)
{
#ifdef WITH_GPIOD
    for (int i = 0; i < 4; i++)
        if (l->lines[i])
#if GPIOD_API_MAJOR >= 2
            gpiod_line_request_release(l->lines[i]);
#else
            gpiod_line_release(l->lines[i]);
#endif
    if (l->chip)
        gpiod_chip_close(l->chip);
#endif
    for (int i = 0; i < 4; i++)
        l->lines[i] = NULL;
    l->chip = NULL;
    if (l->fd >= 0)
        close(l->fd);
    l->fd = -1;
}

const char *hal_linux_error(const struct hal_linux *l)
{
    return l->err;
}

int hal_linux_open(struct hal_linux *l, struct hal *out, const struct hal_linux_config *cfg)
{
    memset(l, 0, sizeof *l);
    l->fd = -1;
    l->spi_hz = cfg->spi_hz;
    uint8_t mode = cfg->spi_mode, bits = 8;
    uint32_t hz = cfg->spi_hz;
    if (cfg->spi_mode > 3) {
        set_err(l, "hal_linux: SPI mode %u out of range 0..3", (unsigned)cfg->spi_mode);
        return -1;
    }
    l->fd = open(cfg->spi_dev, O_RDWR);
    if (l->fd < 0) {
        set_err(l, "hal_linux: cannot open %s: %s", cfg->spi_dev, strerror(errno));
        return -1;
    }
    if (ioctl(l->fd, SPI_IOC_WR_MODE, &mode) < 0 || ioctl(l->fd, SPI_IOC_WR_BITS_PER_WORD, &bits) < 0 ||
        ioctl(l->fd, SPI_IOC_WR_MAX_SPEED_HZ, &hz) < 0) {
        set_err(l, "hal_linux: cannot configure %s: %s", cfg->spi_dev, strerror(errno));
        hal_linux_close(l);
        return -1;
    }
    const int offs[4] = { cfg->dc, cfg->reset, cfg->cs, cfg->bl };
    static const char *const names[4] = { "DC", "RESET", "CS", "BL" };
#ifndef WITH_GPIOD
    for (int i = 0; i < 4; i++)
        if (offs[i] >= 0) {
            set_err(l, "hal_linux: %s line %d needs libgpiod; install libgpiod-dev and rebuild",
                    names[i], offs[i]);
            hal_linux_close(l);
            return -1;
        }
#else
    static const int initial[4] = { 1, 1, 1, 0 };
    int any = 0;
    for (int i = 0; i < 4; i++)
        any |= offs[i] >= 0;
    if (any) {
        l->chip = open_chip(cfg->gpio_chip);
        if (!l->chip) {
            set_err(l, "hal_linux: cannot open GPIO chip %s: %s", cfg->gpio_chip, strerror(errno));
            hal_linux_close(l);
            return -1;
        }
    }
    for (int i = 0; i < 4; i++) {
        if (offs[i] < 0)
            continue;
        errno = 0;
        void *ln = request_output(l->chip, (unsigned)offs[i], initial[i]);
        if (!ln) {
            set_err(l, "hal_linux: cannot drive %s line %d on %s: %s", names[i], offs[i],
                    cfg->gpio_chip, errno ? strerror(errno) : "request refused");
            hal_linux_close(l);
            return -1;
        }
        l->lines[i] = ln;
        l->offs[i] = (unsigned)offs[i];
    }
#endif
    out->ctx = l;
    out->spi_write = lx_spi_write;
    out->spi_write_async = lx_spi_write_async;
    out->spi_wait = lx_spi_wait;
    out->line_set = lx_line_set;
    out->delay_ms = lx_delay_ms;
    out->now_us = lx_now_us;
    out->pixels_async = NULL;   /* the DCS layer converts pixels to bytes */
    return 0;
}
