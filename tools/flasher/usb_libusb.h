/* SPDX-License-Identifier: MIT */
/* usb_libusb.h — the real PICOBOOT transport, over libusb-1.0. */
#ifndef FLASHER_USB_LIBUSB_H
#define FLASHER_USB_LIBUSB_H

#include "picoboot.h"

/* Fills t with the libusb transport (state is static: one at a time). */
void usb_libusb_transport(struct pb_transport *t);

#endif
