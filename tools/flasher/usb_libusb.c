/* SPDX-License-Identifier: MIT */
/* usb_libusb.c — finds the RP2040 boot ROM (2e8a:0003), claims its vendor
 * (class 0xFF) interface and moves bulk transfers. */
#include <stdio.h>
#include <string.h>
#include <libusb.h>
#include "usb_libusb.h"

#define PB_REQ_INTERFACE_RESET 0x41
#define PB_REQ_GET_COMMAND_STATUS 0x42

struct usb_state {
    const struct usb_choice *choice;
    libusb_context *usb;
    libusb_device_handle *h;
    int iface;
    unsigned char ep_out, ep_in;
};

static struct usb_state st;

/* The vendor interface's bulk endpoints; -1 if the device has none. */
static int find_iface(libusb_device *dev, struct usb_state *s)
{
    struct libusb_config_descriptor *cfg;
    if (libusb_get_active_config_descriptor(dev, &cfg) != 0) return -1;
    int found = -1;
    for (int i = 0; i < cfg->bNumInterfaces && found < 0; i++) {
        const struct libusb_interface_descriptor *d = &cfg->interface[i].altsetting[0];
        if (d->bInterfaceClass != 0xFF || d->bNumEndpoints != 2) continue;
        s->ep_out = s->ep_in = 0;
        for (int e = 0; e < 2; e++) {
            const struct libusb_endpoint_descriptor *ep = &d->endpoint[e];
            if ((ep->bmAttributes & 3) != LIBUSB_TRANSFER_TYPE_BULK) continue;
            if (ep->bEndpointAddress & 0x80) s->ep_in = ep->bEndpointAddress;
            else s->ep_out = ep->bEndpointAddress;
        }
        if (s->ep_in && s->ep_out) {
            s->iface = d->bInterfaceNumber;
            found = 0;
        }
    }
    libusb_free_config_descriptor(cfg);
    return found;
}

/* The serial number of a device ("?" when it cannot be opened or has
 * none). */
static void read_serial(libusb_device *dev, char *out, size_t n)
{
    struct libusb_device_descriptor d;
    libusb_device_handle *h;
    snprintf(out, n, "?");
    if (libusb_get_device_descriptor(dev, &d) != 0 || !d.iSerialNumber || libusb_open(dev, &h) != 0) return;
    int r = libusb_get_string_descriptor_ascii(h, d.iSerialNumber, (unsigned char *)out, (int)n - 1);
    if (r > 0 && (size_t)r < n) out[r] = 0;
    else snprintf(out, n, "?");
    libusb_close(h);
}

static void u_close(void *ctx);

#define MAX_BOOT 16

static int u_open(void *ctx, char *detail, size_t dlen)
{
    struct usb_state *s = ctx;
    const struct usb_choice *c = s->choice;
    s->h = NULL;
    int rc = libusb_init(&s->usb);
    if (rc != 0) {
        snprintf(detail, dlen, "no USB access here (libusb: %s)", libusb_strerror(rc));
        s->usb = NULL;
        return PB_OPEN_NODEV;
    }
    libusb_device **list;
    ssize_t n = libusb_get_device_list(s->usb, &list);
    if (n < 0) {
        snprintf(detail, dlen, "libusb: %s", libusb_strerror((int)n));
        u_close(s);
        return PB_OPEN_ERROR;
    }
    /* every boot ROM that matches the choice; serial numbers are read (the
     * device opened) only to match --serial or to list several */
    libusb_device *boot[MAX_BOOT];
    char serial[MAX_BOOT][64];
    int nboot = 0, nall = 0, other_pid = -1;
    for (ssize_t i = 0; i < n; i++) {
        struct libusb_device_descriptor d;
        if (libusb_get_device_descriptor(list[i], &d) != 0 || d.idVendor != PB_VID) continue;
        if (d.idProduct != PB_PID_RP2040_BOOT) {
            other_pid = d.idProduct;
            continue;
        }
        nall++;
        if (c && c->bus && libusb_get_bus_number(list[i]) != c->bus) continue;
        if (c && c->address && libusb_get_device_address(list[i]) != c->address) continue;
        if (nboot == MAX_BOOT) continue;
        serial[nboot][0] = 0;
        if (c && c->serial) {
            read_serial(list[i], serial[nboot], sizeof serial[nboot]);
            if (strcmp(serial[nboot], c->serial) != 0) continue;
        }
        boot[nboot++] = list[i];
    }
    int res = PB_OPEN_OK;
    if (nboot == 0) {
        if (nall > 0) {
            snprintf(detail, dlen, "%d attached, none matches --bus, --address or --serial", nall);
            res = PB_OPEN_NODEV;
        } else if (other_pid >= 0) {
            snprintf(detail, dlen, "USB %04x:%04x is a Raspberry Pi device running a program, not the "
                     "RP2040 boot ROM (%04x:%04x): hold BOOTSEL and reset it", PB_VID, (unsigned)other_pid,
                     PB_VID, PB_PID_RP2040_BOOT);
            res = PB_OPEN_WRONG;
        } else {
            res = PB_OPEN_NODEV;
        }
    } else if (nboot > 1) {
        size_t used = 0;
        detail[0] = 0;
        for (int i = 0; i < nboot && used < dlen; i++) {
            if (!serial[i][0]) read_serial(boot[i], serial[i], sizeof serial[i]);
            int w = snprintf(detail + used, dlen - used, "%sbus %u address %u serial %s", i ? "; " : "",
                             (unsigned)libusb_get_bus_number(boot[i]),
                             (unsigned)libusb_get_device_address(boot[i]), serial[i]);
            if (w < 0) break;
            used += (size_t)w;
        }
        res = PB_OPEN_MANY;
    } else if (find_iface(boot[0], s) != 0) {
        snprintf(detail, dlen, "USB %04x:%04x has no PICOBOOT interface (vendor class, 2 bulk endpoints)",
                 PB_VID, PB_PID_RP2040_BOOT);
        res = PB_OPEN_WRONG;
    } else {
        rc = libusb_open(boot[0], &s->h);
        if (rc != 0) s->h = NULL;
        if (rc == LIBUSB_ERROR_ACCESS) res = PB_OPEN_ACCESS;
        else if (rc != 0) {
            snprintf(detail, dlen, "libusb_open: %s", libusb_strerror(rc));
            res = PB_OPEN_ERROR;
        } else if ((rc = libusb_claim_interface(s->h, s->iface)) != 0) {
            snprintf(detail, dlen, "claiming the PICOBOOT interface: %s", libusb_strerror(rc));
            res = rc == LIBUSB_ERROR_ACCESS ? PB_OPEN_ACCESS : PB_OPEN_ERROR;
            libusb_close(s->h);
            s->h = NULL;
        }
    }
    libusb_free_device_list(list, 1);
    /* a failed open leaves nothing behind: pb_flash closes only what it opened */
    if (res != PB_OPEN_OK) u_close(s);
    return res;
}

static int bulk(struct usb_state *s, unsigned char ep, uint8_t *data, size_t n, unsigned timeout_ms)
{
    int done = 0;
    uint8_t dummy;
    if (!s->h) return -1;
    int rc = libusb_bulk_transfer(s->h, ep, n ? data : &dummy, (int)n, &done, timeout_ms);
    return rc == 0 ? done : -1;
}

static int u_out(void *ctx, const uint8_t *data, size_t n, unsigned timeout_ms)
{
    struct usb_state *s = ctx;
    return bulk(s, s->ep_out, (uint8_t *)(uintptr_t)data, n, timeout_ms);
}

static int u_in(void *ctx, uint8_t *data, size_t n, unsigned timeout_ms)
{
    struct usb_state *s = ctx;
    return bulk(s, s->ep_in, data, n, timeout_ms);
}

/* Both endpoints' halt cleared, then the interface's own reset request. */
static int u_reset(void *ctx)
{
    struct usb_state *s = ctx;
    if (!s->h) return -1;
    if (libusb_clear_halt(s->h, s->ep_in) != 0 || libusb_clear_halt(s->h, s->ep_out) != 0) return -1;
    int rc = libusb_control_transfer(s->h, LIBUSB_REQUEST_TYPE_VENDOR | LIBUSB_RECIPIENT_INTERFACE |
                                     LIBUSB_ENDPOINT_OUT, PB_REQ_INTERFACE_RESET, 0, (uint16_t)s->iface,
                                     NULL, 0, PB_TIMEOUT_MS);
    return rc == 0 ? 0 : -1;
}

static int u_status(void *ctx, uint8_t out[16])
{
    struct usb_state *s = ctx;
    if (!s->h) return -1;
    int rc = libusb_control_transfer(s->h, LIBUSB_REQUEST_TYPE_VENDOR | LIBUSB_RECIPIENT_INTERFACE |
                                     LIBUSB_ENDPOINT_IN, PB_REQ_GET_COMMAND_STATUS, 0, (uint16_t)s->iface,
                                     out, 16, PB_TIMEOUT_MS);
    return rc;
}

static void u_close(void *ctx)
{
    struct usb_state *s = ctx;
    if (s->h) {
        libusb_release_interface(s->h, s->iface);
        libusb_close(s->h);
        s->h = NULL;
    }
    if (s->usb) libusb_exit(s->usb);
    s->usb = NULL;
}

void usb_libusb_transport(struct pb_transport *t, const struct usb_choice *choice)
{
    memset(&st, 0, sizeof st);
    st.choice = choice;
    t->ctx = &st;
    t->open = u_open;
    t->bulk_out = u_out;
    t->bulk_in = u_in;
    t->close = u_close;
    t->reset = u_reset;
    t->status = u_status;
}
