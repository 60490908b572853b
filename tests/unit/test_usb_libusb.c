/* SPDX-License-Identifier: MIT */
/* test_usb_libusb.c — the flasher's libusb transport (tools/flasher/
 * usb_libusb.c) against a fake libusb (tests/support/fake_libusb.c): which
 * boot ROM it opens among several (--bus, --address, --serial), the error
 * that lists them when no choice is made, and that every open, failed or
 * retried, pairs libusb_init with libusb_exit and each open with its
 * close. */
#include <stdio.h>
#include <string.h>
#include <libusb.h>
#include "check.h"
#include "fake_libusb.h"
#include "picoboot.h"
#include "usb_libusb.h"

static void add(unsigned pid, unsigned bus, unsigned address, const char *serial)
{
    struct fake_usb_dev *d = &fake_libusb.devs[fake_libusb.ndevs++];
    d->vid = 0x2E8A;
    d->pid = pid;
    d->bus = bus;
    d->address = address;
    d->serial = serial;
}

/* Everything taken was given back. */
static int balanced(void)
{
    const struct fake_libusb *f = &fake_libusb;
    return f->inits == f->exits && f->opens == f->closes && f->claims == f->releases &&
           f->lists == f->list_frees && f->configs == f->config_frees;
}

static int open_with(const struct usb_choice *c, char *detail, size_t n, struct pb_transport *t)
{
    usb_libusb_transport(t, c);
    detail[0] = 0;
    return t->open(t->ctx, detail, n);
}

int main(void)
{
    struct pb_transport t;
    char detail[400], err[1024];
    struct usb_choice any = { 0, 0, NULL };

    /* retried while no device is there (as after --gpio-reset): each try
     * ends its own libusb context */
    fake_libusb_reset();
    int rc = 0;
    for (int i = 0; i < 50; i++) rc = open_with(&any, detail, sizeof detail, &t);
    check(rc == PB_OPEN_NODEV && fake_libusb.inits == 50 && balanced(), "usb_retried_open_pairs_init_and_exit",
          "rc %d, %d inits, %d exits", rc, fake_libusb.inits, fake_libusb.exits);

    fake_libusb_reset();
    add(0x000A, 1, 4, "RUNNING");
    rc = open_with(&any, detail, sizeof detail, &t);
    check(rc == PB_OPEN_WRONG && strstr(detail, "running a program") && balanced(), "usb_running_pico_is_wrong_device",
          "rc %d: %s", rc, detail);

    /* two boot ROMs and no choice: both listed, nothing opened */
    fake_libusb_reset();
    add(0x0003, 1, 5, "E6614103E7452D2F");
    add(0x0003, 2, 9, "E66141040396512A");
    rc = open_with(&any, detail, sizeof detail, &t);
    check(rc == PB_OPEN_MANY && strcmp(detail, "bus 1 address 5 serial E6614103E7452D2F; bus 2 address 9 serial "
                                               "E66141040396512A") == 0 &&
              fake_libusb.claims == 0 && balanced(),
          "usb_several_boot_roms_listed",
          "rc %d: '%s'", rc, detail);
    rc = pb_flash(&t, &(struct pb_image){ 0x10000000u, 256, (uint8_t[256]){ 0 }, NULL }, 1, err, sizeof err, NULL);
    check(rc == -1 && !strchr(err, '\n') && strstr(err, "several RP2040 boot ROMs attached (bus 1 address 5") &&
              strstr(err, "--serial") && balanced(),
          "usb_several_boot_roms_error_line", "rc %d: %s", rc, err);

    /* chosen by serial number, by bus, by bus and address */
    struct usb_choice by_serial = { 0, 0, "E66141040396512A" };
    rc = open_with(&by_serial, detail, sizeof detail, &t);
    int claimed = fake_libusb.claims;
    t.close(t.ctx);
    check(rc == PB_OPEN_OK && claimed == 1 && balanced(), "usb_choice_by_serial", "rc %d: %s", rc, detail);
    struct usb_choice by_bus = { 1, 0, NULL };
    rc = open_with(&by_bus, detail, sizeof detail, &t);
    t.close(t.ctx);
    check(rc == PB_OPEN_OK && balanced(), "usb_choice_by_bus", "rc %d: %s", rc, detail);
    struct usb_choice by_addr = { 2, 9, NULL };
    rc = open_with(&by_addr, detail, sizeof detail, &t);
    t.close(t.ctx);
    check(rc == PB_OPEN_OK && balanced(), "usb_choice_by_bus_and_address", "rc %d: %s", rc, detail);
    struct usb_choice none = { 3, 0, NULL };
    rc = open_with(&none, detail, sizeof detail, &t);
    check(rc == PB_OPEN_NODEV && strstr(detail, "2 attached, none matches") && balanced(),
          "usb_choice_matching_nothing", "rc %d: %s", rc, detail);
    struct usb_choice bad_serial = { 0, 0, "NOPE" };
    rc = open_with(&bad_serial, detail, sizeof detail, &t);
    check(rc == PB_OPEN_NODEV && strstr(detail, "none matches") && balanced(), "usb_choice_unknown_serial",
          "rc %d: %s", rc, detail);

    /* a failed open gives everything back */
    fake_libusb_reset();
    add(0x0003, 1, 5, "A");
    fake_libusb.devs[0].open_err = LIBUSB_ERROR_ACCESS;
    rc = open_with(&any, detail, sizeof detail, &t);
    check(rc == PB_OPEN_ACCESS && balanced(), "usb_permission_denied_releases_context", "rc %d, %d inits %d exits",
          rc, fake_libusb.inits, fake_libusb.exits);
    fake_libusb.devs[0].open_err = 0;
    fake_libusb.devs[0].no_iface = 1;
    rc = open_with(&any, detail, sizeof detail, &t);
    check(rc == PB_OPEN_WRONG && strstr(detail, "no PICOBOOT interface") && balanced(),
          "usb_no_picoboot_interface_releases_context", "rc %d: %s", rc, detail);

    /* a whole (failing) run through pb_flash closes what it opened */
    fake_libusb.devs[0].no_iface = 0;
    rc = pb_flash(&t, &(struct pb_image){ 0x10000000u, 256, (uint8_t[256]){ 0 }, NULL }, 1, err, sizeof err, NULL);
    check(rc == -1 && strstr(err, "USB transfer failed") && fake_libusb.opens == 1 && balanced(),
          "usb_flash_run_closes_device_and_context", "rc %d: %s", rc, err);
    return check_exit();
}
