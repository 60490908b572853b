/* SPDX-License-Identifier: MIT */
/* usb_libusb.h — the real PICOBOOT transport, over libusb-1.0. */
#ifndef FLASHER_USB_LIBUSB_H
#define FLASHER_USB_LIBUSB_H

#include "picoboot.h"

/* Which boot ROM to open when several are attached: bus and address
 * (1..255, 1..127; 0 = any) and the USB serial number (NULL = any). */
struct usb_choice {
    unsigned bus, address;
    const char *serial;
};

/* Fills t with the libusb transport (state is static: one at a time; the
 * choice is kept by pointer). Each open makes its own libusb context and a
 * failed open ends it again (libusb_init and libusb_exit pair up, however
 * often the open is retried); close ends a successful one. Several devices
 * that match the choice: PB_OPEN_MANY, the detail listing them (bus,
 * address, serial). */
void usb_libusb_transport(struct pb_transport *t, const struct usb_choice *choice);

#endif
