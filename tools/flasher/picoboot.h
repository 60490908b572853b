/* SPDX-License-Identifier: MIT */
/* picoboot.h — the RP2040 boot ROM's PICOBOOT USB interface (vendor
 * interface of USB device 2e8a:0003 in BOOTSEL mode), and the flashing
 * sequence built on it.
 *
 * A command is a 32-byte little-endian block sent on the bulk OUT endpoint:
 *   u32 magic 0x431FD10B, u32 token, u8 command id (bit 7 set = data IN),
 *   u8 size of the arguments, u16 0, u32 transfer length, 16 bytes of args.
 * A data phase of `transfer length` bytes follows (OUT for WRITE, IN for
 * READ); then the device acknowledges with a zero-length packet in the
 * direction opposite to the data (IN after OUT commands, OUT after IN).
 *
 * Control requests of the interface (vendor, recipient interface):
 *   INTERFACE_RESET (0x41, OUT, no data): clears a stalled command state;
 *   GET_COMMAND_STATUS (0x42, IN, 16 bytes): u32 token, u32 status code,
 *   u8 command id, u8 in progress — why the last command failed.
 *
 * The USB layer is behind struct pb_transport, so the whole sequence runs
 * against a fake in tests. */
#ifndef PICOBOOT_H
#define PICOBOOT_H

#include <stddef.h>
#include <stdint.h>

#define PB_MAGIC            0x431FD10Bu
#define PB_VID              0x2E8Au
#define PB_PID_RP2040_BOOT  0x0003u
#define PB_FLASH_BASE       0x10000000u
#define PB_FLASH_SIZE       (16u * 1024u * 1024u)  /* XIP address space */
#define PB_FLASH_LIMIT      (2u * 1024u * 1024u)   /* default image limit: the Pico's W25Q16JV */
#define PB_SECTOR           4096u   /* erase unit */
#define PB_PAGE             256u    /* program unit */
#define PB_CMD_LEN          32u

enum pb_cmd_id {
    PB_EXCLUSIVE_ACCESS = 0x01,
    PB_REBOOT = 0x02,
    PB_FLASH_ERASE = 0x03,
    PB_READ = 0x84,
    PB_WRITE = 0x05,
    PB_EXIT_XIP = 0x06,
};

enum pb_exclusive { PB_NOT_EXCLUSIVE = 0, PB_EXCLUSIVE = 1, PB_EXCLUSIVE_AND_EJECT = 2 };

/* GET_COMMAND_STATUS codes of the RP2040 boot ROM. */
enum pb_status {
    PB_STATUS_OK = 0,
    PB_STATUS_UNKNOWN_CMD = 1,
    PB_STATUS_INVALID_CMD_LENGTH = 2,
    PB_STATUS_INVALID_TRANSFER_LENGTH = 3,
    PB_STATUS_INVALID_ADDRESS = 4,
    PB_STATUS_BAD_ALIGNMENT = 5,
    PB_STATUS_INTERLEAVED_WRITE = 6,
    PB_STATUS_REBOOTING = 7,
    PB_STATUS_UNKNOWN_ERROR = 8,
};
const char *pb_status_name(uint32_t code);

/* Transfer timeouts, as picotool's: a command block 3 s; a data phase 10 s;
 * the acknowledgement 3 s after a data phase, 10 s after a command without
 * one (an erase: a 4 KB sector takes up to 400 ms, longer on worn parts). */
#define PB_TIMEOUT_MS       3000u
#define PB_DATA_TIMEOUT_MS  10000u

/* Result of pb_transport.open. */
enum pb_open {
    PB_OPEN_OK = 0,
    PB_OPEN_NODEV = -1,       /* no device 2e8a:0003 */
    PB_OPEN_ACCESS = -2,      /* found, but no permission to open it */
    PB_OPEN_WRONG = -3,       /* an RP2040 is there, but not in the boot ROM (or no PICOBOOT interface) */
    PB_OPEN_ERROR = -4,       /* anything else (libusb failure) */
    PB_OPEN_MANY = -5,        /* several boot ROMs match: the detail lists them */
};

struct pb_transport {
    void *ctx;
    /* Finds and claims the PICOBOOT interface; enum pb_open. `detail`
     * (may be empty) receives a short description for the error line. */
    int (*open)(void *ctx, char *detail, size_t detail_len);
    /* Bulk transfers: bytes transferred, or < 0 on a USB error (cable
     * pulled, stall, timeout after timeout_ms). n == 0 is a zero-length
     * packet. */
    int (*bulk_out)(void *ctx, const uint8_t *data, size_t n, unsigned timeout_ms);
    int (*bulk_in)(void *ctx, uint8_t *data, size_t n, unsigned timeout_ms);
    void (*close)(void *ctx);
    /* Optional (may be NULL). reset: clear both endpoints' halt and send
     * INTERFACE_RESET; 0 or < 0. status: GET_COMMAND_STATUS into out[16];
     * 16 or < 0. */
    int (*reset)(void *ctx);
    int (*status)(void *ctx, uint8_t out[16]);
};

/* Encodes a command into out[32]; returns PB_CMD_LEN. args_len <= 16. */
size_t pb_encode(uint8_t out[PB_CMD_LEN], uint32_t token, uint8_t cmd_id, uint32_t transfer_len,
                 const uint8_t *args, uint8_t args_len);

/* Encoders of each command (token as given). */
size_t pb_encode_exclusive(uint8_t out[PB_CMD_LEN], uint32_t token, uint8_t mode);
size_t pb_encode_exit_xip(uint8_t out[PB_CMD_LEN], uint32_t token);
size_t pb_encode_erase(uint8_t out[PB_CMD_LEN], uint32_t token, uint32_t addr, uint32_t size);
size_t pb_encode_write(uint8_t out[PB_CMD_LEN], uint32_t token, uint32_t addr, uint32_t size);
size_t pb_encode_read(uint8_t out[PB_CMD_LEN], uint32_t token, uint32_t addr, uint32_t size);
size_t pb_encode_reboot(uint8_t out[PB_CMD_LEN], uint32_t token, uint32_t pc, uint32_t sp, uint32_t delay_ms);

/* An image to flash: `len` bytes at flash address `addr` (both multiples of
 * PB_PAGE once loaded; the loader pads with 0xFF). `used` (may be NULL:
 * every page) holds one byte per page, nonzero for a page the image gives;
 * the others (a sparse UF2's gaps) are neither written nor erased unless
 * they share a 4 KB sector with a page that is. */
struct pb_image {
    uint32_t addr;
    uint32_t len;
    uint8_t *data;
    uint8_t *used;
};

/* The whole sequence: open, reset the interface (a previous run may have
 * left it stalled), exclusive access, exit XIP, erase the 4 KB sectors that
 * hold a page of the image (img->used: a sparse image's gaps stay as they
 * were), write its pages, read them back and compare, and only then reboot
 * into it (nothing half-written runs); without reboot, exclusive access is
 * released instead. Page 0 of flash (0x10000000, boot2), when the image
 * gives it, is erased first and written last, after the rest is written and
 * verified: an interrupted run leaves no boot2 in front of a partial image,
 * so the board stays in BOOTSEL. Returns 0, or -1 with a one-line message
 * (no newline) in err, which names the boot ROM's status code when it gives
 * one. `progress` may be NULL. */
int pb_flash(const struct pb_transport *t, const struct pb_image *img, int reboot,
             char *err, size_t err_len, void (*progress)(const char *stage, uint32_t done, uint32_t total));

#endif
