/* main.c — build/flasher: writes a UF2 or .bin image to an RP2040 in
 * BOOTSEL mode over USB (PICOBOOT), verifies it, then reboots the board.
 *
 * usage: flasher [--no-reboot] [--base ADDR] FILE.uf2|FILE.bin
 * Exit status: 0 flashed and verified; 2 any error (one line on stderr). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
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

int main(int argc, char **argv)
{
    int reboot = 1;
    uint32_t base = PB_FLASH_BASE;
    const char *file = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--no-reboot") == 0) {
            reboot = 0;
        } else if (strcmp(argv[i], "--base") == 0 && i + 1 < argc) {
            char *end;
            unsigned long v = strtoul(argv[++i], &end, 0);
            if (*end || v > 0xFFFFFFFFul) return die("--base needs a number");
            base = (uint32_t)v;
        } else if (argv[i][0] == '-' || file) {
            return die("usage: flasher [--no-reboot] [--base ADDR] FILE.uf2|FILE.bin");
        } else {
            file = argv[i];
        }
    }
    if (!file) return die("usage: flasher [--no-reboot] [--base ADDR] FILE.uf2|FILE.bin");

    FILE *f = fopen(file, "rb");
    if (!f) {
        char m[512];
        snprintf(m, sizeof m, "%s: cannot open", file);
        return die(m);
    }
    static uint8_t buf[2 * PB_FLASH_SIZE + 1];
    size_t len = fread(buf, 1, sizeof buf, f);
    fclose(f);

    struct pb_image img;
    char err[512];
    size_t fl = strlen(file);
    int is_uf2 = fl >= 4 && strcmp(file + fl - 4, ".uf2") == 0;
    if ((is_uf2 ? image_from_uf2(buf, len, &img, err, sizeof err)
                : image_from_bin(buf, len, base, &img, err, sizeof err)) != 0) {
        char m[700];
        snprintf(m, sizeof m, "%s: %s", file, err);
        return die(m);
    }
    struct pb_transport t;
    usb_libusb_transport(&t);
    int rc = pb_flash(&t, &img, reboot, err, sizeof err, isatty(2) ? progress : NULL);
    image_free(&img);
    if (isatty(2)) fputc('\n', stderr);
    if (rc) return die(err);
    fprintf(stderr, "flasher: %s: %u bytes written at 0x%08x and verified%s\n", file, (unsigned)img.len,
            (unsigned)img.addr, reboot ? "; rebooted" : "");
    return 0;
}
