/* SPDX-License-Identifier: MIT */
/* main.c — build/flasher: writes a UF2 or .bin image to an RP2040 in
 * BOOTSEL mode over USB (PICOBOOT), verifies it, then reboots the board.
 *
 * usage: flasher [--no-reboot] [--base ADDR] [--flash-size BYTES]
 *                [--bus N] [--address N] [--serial S]
 *                [--gpio-reset [--gpio-chip CHIP] [--run-pin N] [--bootsel-pin N]]
 *                FILE.uf2|FILE.bin        (flasher --help: every option)
 * A file named *.uf2 (any case) must be a valid UF2; any other name is a
 * UF2 when its content is one, else a flat binary placed at --base
 * (default 0x10000000). Only a regular file is read (image_read_file). --flash-size (default 2 MiB,
 * the Pico's) bounds where an image may go; everything about the image is
 * checked before the board is touched.
 * --gpio-reset first puts the Pico into its boot ROM through a Raspberry Pi's
 * GPIO lines (gpio_reset.h), then waits up to 5 s for the boot ROM's USB
 * device. --bus/--address/--serial choose among several boot ROMs attached
 * (with more than one and no choice: an error listing them).
 * Exit status: 0 flashed and verified (and --help); 2 any error (one line on
 * stderr). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <time.h>
#include "gpio_reset.h"
#include "image.h"
#include "picoboot.h"
#include "usb_libusb.h"

static void progress(const char *stage, uint32_t done, uint32_t total)
{
    fprintf(stderr, "\r%-6s %3u%%", stage, total ? (unsigned)((uint64_t)done * 100 / total) : 100u);
    fflush(stderr);
}

static int die(const char *msg)
{
    fprintf(stderr, "flasher: %s\n", msg);
    return 2;
}

#define USAGE "usage: flasher [--no-reboot] [--base ADDR] [--flash-size BYTES] [--bus N] [--address N] " \
              "[--serial S] [--gpio-reset [--gpio-chip CHIP] [--run-pin N] [--bootsel-pin N]] FILE.uf2|FILE.bin " \
              "(--help: all options)"

static const char help[] =
    "usage: flasher [OPTIONS] FILE.uf2|FILE.bin\n"
    "Writes an image to an RP2040 in BOOTSEL mode over USB (PICOBOOT), reads it back\n"
    "and compares, then reboots the board into it.\n"
    "\n"
    "FILE: a name ending in .uf2 (any case) must be a valid UF2; any other name is a\n"
    "UF2 when its content is one, else a flat binary placed at --base.\n"
    "\n"
    "Options (default in brackets):\n"
    "  --no-reboot          stay in the boot ROM after verifying [reboot into the image]\n"
    "  --base ADDR          flash address of a flat binary [0x10000000]\n"
    "  --flash-size BYTES   flash an image may use, a multiple of 4096 up to 16777216\n"
    "                       [2097152, the Pico's 2 MiB]\n"
    "  --bus N              only the boot ROM on USB bus N [any]\n"
    "  --address N          only the boot ROM at USB device address N [any]\n"
    "  --serial S           only the boot ROM with USB serial number S [any]\n"
    "                       (with several boot ROMs attached, one must be chosen)\n"
    "  --gpio-reset         first reset the Pico into its boot ROM through a Raspberry\n"
    "                       Pi's GPIO lines, then wait up to 5 s for it on USB [off]\n"
    "  --gpio-chip CHIP     gpiochip of those lines: name, number or path [gpiochip0]\n"
    "  --run-pin N          line wired to the Pico's RUN pin [23]\n"
    "  --bootsel-pin N      line wired to the Pico's BOOTSEL (QSPI SS) [24]\n"
    "  --help               this help\n"
    "\n"
    "Exit status: 0 written, verified (and rebooted unless --no-reboot); 2 any error\n"
    "(bad option or image, no or several boards, USB failure, verify mismatch), with\n"
    "one line on stderr. --help: 0.\n";

/* After a GPIO reset the boot ROM needs a moment to enumerate on USB: the
 * open is retried while no device is found, for up to 5 s. */
struct wait_open {
    struct pb_transport inner;
};

static int wait_open(void *ctx, char *detail, size_t detail_len)
{
    struct wait_open *w = ctx;
    int rc = PB_OPEN_NODEV;
    for (int i = 0; i < 50; i++) {
        rc = w->inner.open(w->inner.ctx, detail, detail_len);
        if (rc != PB_OPEN_NODEV) break;
        struct timespec ts = { 0, 100000000L };
        nanosleep(&ts, NULL);
    }
    return rc;
}
static int wait_out(void *ctx, const uint8_t *d, size_t n, unsigned ms)
{
    struct wait_open *w = ctx;
    return w->inner.bulk_out(w->inner.ctx, d, n, ms);
}
static int wait_in(void *ctx, uint8_t *d, size_t n, unsigned ms)
{
    struct wait_open *w = ctx;
    return w->inner.bulk_in(w->inner.ctx, d, n, ms);
}
static void wait_close(void *ctx)
{
    struct wait_open *w = ctx;
    w->inner.close(w->inner.ctx);
}
static int wait_reset(void *ctx)
{
    struct wait_open *w = ctx;
    return w->inner.reset ? w->inner.reset(w->inner.ctx) : 0;
}
static int wait_status(void *ctx, uint8_t out[16])
{
    struct wait_open *w = ctx;
    return w->inner.status ? w->inner.status(w->inner.ctx, out) : -1;
}

/* A decimal number lo..hi. */
static int num_arg(const char *s, unsigned long lo, unsigned long hi, unsigned *out)
{
    char *end;
    if (*s < '0' || *s > '9') return -1;
    unsigned long v = strtoul(s, &end, 10);
    if (*end || v < lo || v > hi) return -1;
    *out = (unsigned)v;
    return 0;
}

/* A line offset 0..1023. */
static int pin_arg(const char *s, unsigned *out)
{
    return num_arg(s, 0, 1023, out);
}

int main(int argc, char **argv)
{
    int reboot = 1, gpio = 0;
    struct gpio_reset_cfg gcfg = GPIO_RESET_DEFAULTS;
    uint32_t base = PB_FLASH_BASE, flash_size = PB_FLASH_LIMIT;
    const char *file = NULL;
    struct usb_choice choice = { 0, 0, NULL };
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(help, stdout);
            return 0;
        }
    }
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--no-reboot") == 0) {
            reboot = 0;
        } else if (strcmp(argv[i], "--gpio-reset") == 0) {
            gpio = 1;
        } else if (strcmp(argv[i], "--gpio-chip") == 0 && i + 1 < argc) {
            gcfg.chip = argv[++i];
        } else if (strcmp(argv[i], "--run-pin") == 0 && i + 1 < argc) {
            if (pin_arg(argv[++i], &gcfg.run_pin)) return die("--run-pin needs a line number 0..1023");
        } else if (strcmp(argv[i], "--bootsel-pin") == 0 && i + 1 < argc) {
            if (pin_arg(argv[++i], &gcfg.bootsel_pin))
                return die("--bootsel-pin needs a line number 0..1023");
        } else if (strcmp(argv[i], "--flash-size") == 0 && i + 1 < argc) {
            char *end;
            unsigned long v = strtoul(argv[++i], &end, 0);
            if (*end || v < 4096 || v > PB_FLASH_SIZE || v % 4096)
                return die("--flash-size needs a multiple of 4096 up to 16777216");
            flash_size = (uint32_t)v;
        } else if (strcmp(argv[i], "--base") == 0 && i + 1 < argc) {
            char *end;
            unsigned long v = strtoul(argv[++i], &end, 0);
            if (*end || v > 0xFFFFFFFFul) return die("--base needs a number");
            base = (uint32_t)v;
        } else if (strcmp(argv[i], "--bus") == 0 && i + 1 < argc) {
            if (num_arg(argv[++i], 1, 255, &choice.bus)) return die("--bus needs a bus number 1..255");
        } else if (strcmp(argv[i], "--address") == 0 && i + 1 < argc) {
            if (num_arg(argv[++i], 1, 127, &choice.address)) return die("--address needs a device address 1..127");
        } else if (strcmp(argv[i], "--serial") == 0 && i + 1 < argc) {
            choice.serial = argv[++i];
            if (!*choice.serial) return die("--serial needs a serial number");
        } else if (argv[i][0] == '-' || file) {
            return die(USAGE);
        } else {
            file = argv[i];
        }
    }
    if (!file) return die(USAGE);

    /* a UF2 block carries 256 of its 512 bytes: twice the flash and one more
     * byte tells a file that is too large for any image */
    static uint8_t buf[2 * PB_FLASH_SIZE + 1];
    size_t len;
    char m[1300], err[1024];
    struct pb_image img;
    if (image_read_file(file, buf, sizeof buf, &len, err, sizeof err) != 0 ||
        image_load(buf, len, sizeof buf, file, base, flash_size, &img, err, sizeof err) != 0) {
        snprintf(m, sizeof m, "%s: %s", file, err);
        return die(m);
    }
    struct pb_transport t;
    usb_libusb_transport(&t, &choice);
    static struct wait_open w;
    if (gpio) {
        if (gpio_reset_bootsel(&gcfg, err, sizeof err) != 0) {
            image_free(&img);
            return die(err);
        }
        w.inner = t;
        t = (struct pb_transport){ &w, wait_open, wait_out, wait_in, wait_close, wait_reset, wait_status };
    }
    int rc = pb_flash(&t, &img, reboot, err, sizeof err, isatty(2) ? progress : NULL);
    image_free(&img);
    if (isatty(2)) fputc('\n', stderr);
    if (rc) return die(err);
    fprintf(stderr, "flasher: %s: %u bytes written at 0x%08x and verified%s\n", file, (unsigned)img.len,
            (unsigned)img.addr, reboot ? "; rebooted" : "");
    return 0;
}
