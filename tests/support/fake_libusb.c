/* SPDX-License-Identifier: MIT */
/* fake_libusb.c — see fake_libusb.h. */
#include <stdlib.h>
#include <string.h>
#include <libusb.h>
#include "fake_libusb.h"

struct fake_libusb fake_libusb;

void fake_libusb_reset(void) { memset(&fake_libusb, 0, sizeof fake_libusb); }

struct libusb_context {
    int live;
};
struct libusb_device {
    int idx;
};
struct libusb_device_handle {
    int idx, claimed;
};

static struct libusb_context the_ctx;
static struct libusb_device the_devs[FAKE_LIBUSB_DEVS];

int libusb_init(libusb_context **ctx)
{
    if (fake_libusb.init_err) return fake_libusb.init_err;
    fake_libusb.inits++;
    the_ctx.live++;
    *ctx = &the_ctx;
    return 0;
}

void libusb_exit(libusb_context *ctx)
{
    ctx->live--;
    fake_libusb.exits++;
}

const char *libusb_strerror(int errcode)
{
    return errcode == LIBUSB_ERROR_ACCESS ? "Access denied (insufficient permissions)" : "fake libusb error";
}

ssize_t libusb_get_device_list(libusb_context *ctx, libusb_device ***list)
{
    (void)ctx;
    libusb_device **l = calloc((size_t)fake_libusb.ndevs + 1, sizeof *l);
    if (!l) return LIBUSB_ERROR_NO_MEM;
    for (int i = 0; i < fake_libusb.ndevs; i++) {
        the_devs[i].idx = i;
        l[i] = &the_devs[i];
    }
    fake_libusb.lists++;
    *list = l;
    return fake_libusb.ndevs;
}

void libusb_free_device_list(libusb_device **list, int unref_devices)
{
    (void)unref_devices;
    fake_libusb.list_frees++;
    free(list);
}

int libusb_get_device_descriptor(libusb_device *dev, struct libusb_device_descriptor *desc)
{
    const struct fake_usb_dev *d = &fake_libusb.devs[dev->idx];
    memset(desc, 0, sizeof *desc);
    desc->idVendor = (uint16_t)d->vid;
    desc->idProduct = (uint16_t)d->pid;
    desc->iSerialNumber = d->serial ? 3 : 0;
    return 0;
}

uint8_t libusb_get_bus_number(libusb_device *dev) { return (uint8_t)fake_libusb.devs[dev->idx].bus; }
uint8_t libusb_get_device_address(libusb_device *dev) { return (uint8_t)fake_libusb.devs[dev->idx].address; }

/* One configuration: interface 1 is the vendor interface with bulk
 * endpoints 0x03 (OUT) and 0x84 (IN), as the RP2040 boot ROM's. */
struct fake_config {
    struct libusb_config_descriptor cfg;
    struct libusb_interface ifc;
    struct libusb_interface_descriptor alt;
    struct libusb_endpoint_descriptor ep[2];
};

int libusb_get_active_config_descriptor(libusb_device *dev, struct libusb_config_descriptor **config)
{
    struct fake_config *c = calloc(1, sizeof *c);
    if (!c) return LIBUSB_ERROR_NO_MEM;
    c->ep[0].bEndpointAddress = 0x03;
    c->ep[0].bmAttributes = LIBUSB_TRANSFER_TYPE_BULK;
    c->ep[1].bEndpointAddress = 0x84;
    c->ep[1].bmAttributes = LIBUSB_TRANSFER_TYPE_BULK;
    c->alt.bInterfaceNumber = 1;
    c->alt.bInterfaceClass = fake_libusb.devs[dev->idx].no_iface ? 0x08 : 0xFF;
    c->alt.bNumEndpoints = 2;
    c->alt.endpoint = c->ep;
    c->ifc.altsetting = &c->alt;
    c->ifc.num_altsetting = 1;
    c->cfg.bNumInterfaces = 1;
    c->cfg.interface = &c->ifc;
    fake_libusb.configs++;
    *config = &c->cfg;
    return 0;
}

void libusb_free_config_descriptor(struct libusb_config_descriptor *config)
{
    fake_libusb.config_frees++;
    free(config); /* cfg is the first member */
}

int libusb_open(libusb_device *dev, libusb_device_handle **h)
{
    if (fake_libusb.devs[dev->idx].open_err) return fake_libusb.devs[dev->idx].open_err;
    libusb_device_handle *n = calloc(1, sizeof *n);
    if (!n) return LIBUSB_ERROR_NO_MEM;
    n->idx = dev->idx;
    fake_libusb.opens++;
    *h = n;
    return 0;
}

void libusb_close(libusb_device_handle *h)
{
    fake_libusb.closes++;
    free(h);
}

int libusb_get_string_descriptor_ascii(libusb_device_handle *h, uint8_t idx, unsigned char *data, int length)
{
    const char *s = fake_libusb.devs[h->idx].serial;
    if (idx != 3 || !s) return LIBUSB_ERROR_INVALID_PARAM;
    int n = (int)strlen(s) < length ? (int)strlen(s) : length;
    memcpy(data, s, (size_t)n);
    return n;
}

int libusb_claim_interface(libusb_device_handle *h, int iface)
{
    if (iface != 1) return LIBUSB_ERROR_NOT_FOUND;
    h->claimed = 1;
    fake_libusb.claims++;
    return 0;
}

int libusb_release_interface(libusb_device_handle *h, int iface)
{
    (void)iface;
    h->claimed = 0;
    fake_libusb.releases++;
    return 0;
}

/* No PICOBOOT behind the endpoints: transfers fail (the sequence itself is
 * tested against tests/unit/test_flasher.c's fake transport). */
int libusb_bulk_transfer(libusb_device_handle *h, unsigned char ep, unsigned char *data, int length,
                         int *actual, unsigned int timeout)
{
    (void)h;
    (void)ep;
    (void)data;
    (void)length;
    (void)timeout;
    *actual = 0;
    return LIBUSB_ERROR_PIPE;
}

int libusb_clear_halt(libusb_device_handle *h, unsigned char ep)
{
    (void)h;
    (void)ep;
    return 0;
}

int libusb_control_transfer(libusb_device_handle *h, uint8_t type, uint8_t req, uint16_t value, uint16_t index,
                            unsigned char *data, uint16_t len, unsigned int timeout)
{
    (void)h;
    (void)type;
    (void)value;
    (void)index;
    (void)timeout;
    if (req == 0x42 && len == 16) {
        memset(data, 0, 16);
        return 16;
    }
    return 0;
}
