/* SPDX-License-Identifier: MIT */
/* fake_libusb.h — a libusb-1.0 without USB, for tests: the functions the
 * flasher's transport (tools/flasher/usb_libusb.c) calls, over the devices
 * in fake_libusb.devs. It counts contexts, opens and claims so a test can
 * check that each is paired with its release. */
#ifndef TESTS_FAKE_LIBUSB_H
#define TESTS_FAKE_LIBUSB_H

#define FAKE_LIBUSB_DEVS 8

struct fake_usb_dev {
    unsigned vid, pid, bus, address;
    const char *serial; /* NULL: no serial number string */
    int open_err;       /* libusb_open's result (0, or a LIBUSB_ERROR_*) */
    int no_iface;       /* no vendor interface with two bulk endpoints */
};

struct fake_libusb {
    struct fake_usb_dev devs[FAKE_LIBUSB_DEVS];
    int ndevs;
    int init_err; /* libusb_init's result */
    int inits, exits, opens, closes, claims, releases;
    int lists, list_frees, configs, config_frees;
};

extern struct fake_libusb fake_libusb;

/* No devices, every counter 0. */
void fake_libusb_reset(void);

#endif
