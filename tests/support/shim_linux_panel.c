/* SPDX-License-Identifier: MIT */
/* shim_linux_panel.c — an LD_PRELOAD library that puts the emulated strict
 * panel (hal/sim/emu_panel.c) behind the Linux HAL backend: host_sim
 * --backend linux runs unchanged, its spidev device and its GPIO lines are
 * replaced, and every SPI transfer and line change goes into the emulated
 * controller, so the real byte stream of the backend is checked and its
 * glass can be compared with the sim backend's (tests/system/test_linux_backend.sh).
 *
 *   spidev    open() of $CGFS_SHIM_SPIDEV returns a descriptor of /dev/null;
 *             ioctl() on it accepts the spidev configuration requests and
 *             SPI_IOC_MESSAGE(1) transfers, each framed by the controller's
 *             CS going low and high again as spidev's hardware CS does.
 *   GPIO      libgpiod's functions (1.x or 2.x API, as built) from
 *             tests/support/fake_gpiod.c: DC, RESET and BL are the line offsets of
 *             $CGFS_SHIM_PINS ("dc,reset,bl", default "25,27,18").
 *   time      CLOCK_MONOTONIC (the backend really sleeps), never earlier
 *             than the end of the last transfer at the requested clock.
 *
 * $CGFS_SHIM_MODULE (e.g. st7789_240x240) and $CGFS_SHIM_ROT (the rotation
 * the driver uses) set up the emulated module. When the spidev descriptor is
 * closed, the glass is written to $CGFS_SHIM_GLASS as raw RGB565
 * (little-endian, glass width x height) and one line to $CGFS_SHIM_LOG:
 *   mode M bits B hz H transfers T bytes N lines L violation none|<line>
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <sys/ioctl.h>
#include <linux/spi/spidev.h>
#include "fake_gpiod.h"
#include "sim/emu_panel.h"

static int spi_fd = -1;
static struct emu_panel *emu;
static uint64_t t0_ns, t_last;
static uint32_t hz = 1000000, bits;
static uint8_t mode;
static unsigned long transfers, nbytes, nlines;
static int pin[4] = { 25, 27, -1, 18 };    /* by enum hal_line; CS is spidev's */

static uint64_t mono_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

static uint64_t now(void)
{
    uint64_t t = mono_ns() - t0_ns;
    if (t < t_last) t = t_last;
    t_last = t;
    return t;
}

static void on_line(unsigned off, int value, enum fake_gpiod_ev ev)
{
    if (!emu || ev == FAKE_GPIOD_RELEASE) return;
    for (int i = 0; i < 4; i++)
        if (pin[i] >= 0 && (unsigned)pin[i] == off) {
            emu_panel_line(emu, i, value, now());
            nlines++;
        }
}

/* Sets up the emulated module the first time the spidev is opened. */
static int shim_start(void)
{
    const char *name = getenv("CGFS_SHIM_MODULE"), *rot = getenv("CGFS_SHIM_ROT");
    const char *pins = getenv("CGFS_SHIM_PINS");
    uint8_t view;
    const struct emu_module *m = emu_module_find(name ? name : "st7789_240x240", &view);
    if (!m) return -1;
    emu = malloc(sizeof *emu);
    if (!emu) return -1;
    if (emu_panel_init(emu, m, (uint8_t)((view + (rot ? atoi(rot) : 0)) & 3))) {
        free(emu);
        emu = NULL;
        return -1;
    }
    if (pins && sscanf(pins, "%d,%d,%d", &pin[0], &pin[1], &pin[3]) != 3) return -1;
    t0_ns = mono_ns();
    t_last = 0;
    fake_gpiod.on_event = on_line;
    return 0;
}

static void shim_finish(void)
{
    uint64_t t = now();
    emu_panel_finish(emu, t);
    const char *v = emu_panel_violation(emu);
    const char *glass = getenv("CGFS_SHIM_GLASS"), *log = getenv("CGFS_SHIM_LOG");
    uint16_t gw = emu_panel_glass_width(emu), gh = emu_panel_glass_height(emu);
    if (glass) {
        uint16_t *g = malloc((size_t)gw * gh * sizeof *g);
        FILE *f = fopen(glass, "wb");
        if (g && f && emu_panel_glass(emu, g, gw, gh) == 0)
            for (size_t i = 0; i < (size_t)gw * gh; i++) {
                fputc(g[i] & 0xff, f);
                fputc(g[i] >> 8, f);
            }
        if (f) fclose(f);
        free(g);
    }
    if (log) {
        FILE *f = fopen(log, "w");
        if (f) {
            fprintf(f, "mode %u bits %u hz %lu transfers %lu bytes %lu lines %lu glass %ux%u violation %s\n",
                    (unsigned)mode, (unsigned)bits, (unsigned long)hz, transfers, nbytes, nlines,
                    (unsigned)gw, (unsigned)gh, v ? v : "none");
            fclose(f);
        }
    }
    free(emu);
    emu = NULL;
}

typedef int (*open_fn)(const char *, int, ...);
typedef int (*ioctl_fn)(int, unsigned long, ...);
typedef int (*close_fn)(int);

static int shim_open(const char *sym, const char *path, int flags, mode_t md)
{
    const char *dev = getenv("CGFS_SHIM_SPIDEV");
    open_fn real = (open_fn)(uintptr_t)dlsym(RTLD_NEXT, sym);
    if (dev && path && !strcmp(path, dev)) {
        if (spi_fd >= 0 || shim_start()) {
            errno = EBUSY;
            return -1;
        }
        spi_fd = real("/dev/null", O_RDWR);
        return spi_fd;
    }
    return real(path, flags, md);
}

int open(const char *path, int flags, ...)
{
    mode_t md = 0;
    if (flags & (O_CREAT | O_TMPFILE)) {
        va_list ap;
        va_start(ap, flags);
        md = (mode_t)va_arg(ap, int);
        va_end(ap);
    }
    return shim_open("open", path, flags, md);
}

int open64(const char *path, int flags, ...)
{
    mode_t md = 0;
    if (flags & (O_CREAT | O_TMPFILE)) {
        va_list ap;
        va_start(ap, flags);
        md = (mode_t)va_arg(ap, int);
        va_end(ap);
    }
    return shim_open("open64", path, flags, md);
}

int ioctl(int fd, unsigned long req, ...)
{
    va_list ap;
    va_start(ap, req);
    void *arg = va_arg(ap, void *);
    va_end(ap);
    if (fd != spi_fd || spi_fd < 0) {
        ioctl_fn real = (ioctl_fn)(uintptr_t)dlsym(RTLD_NEXT, "ioctl");
        return real(fd, req, arg);
    }
    if (req == SPI_IOC_WR_MODE) { mode = *(const uint8_t *)arg; return 0; }
    if (req == SPI_IOC_WR_BITS_PER_WORD) { bits = *(const uint8_t *)arg; return 0; }
    if (req == SPI_IOC_WR_MAX_SPEED_HZ) { hz = *(const uint32_t *)arg; return 0; }
    if (req == SPI_IOC_MESSAGE(1)) {
        const struct spi_ioc_transfer *tr = arg;
        uint32_t h = tr->speed_hz ? tr->speed_hz : hz;
        uint32_t nspb = (uint32_t)(8000000000ull / h);
        if (tr->len > 4096 || (tr->bits_per_word && tr->bits_per_word != 8)) {
            errno = EMSGSIZE;
            return -1;
        }
        emu_panel_line(emu, 2, 0, now());
        emu_panel_spi(emu, (const uint8_t *)(uintptr_t)tr->tx_buf, tr->len, now(), nspb);
        t_last += (uint64_t)tr->len * nspb;
        emu_panel_line(emu, 2, 1, now());
        transfers++;
        nbytes += tr->len;
        return (int)tr->len;
    }
    errno = ENOTTY;
    return -1;
}

int close(int fd)
{
    close_fn real = (close_fn)(uintptr_t)dlsym(RTLD_NEXT, "close");
    if (fd >= 0 && fd == spi_fd) {
        shim_finish();
        spi_fd = -1;
    }
    return real(fd);
}
