/* SPDX-License-Identifier: MIT */
/* picoboot.c — PICOBOOT command encoding and the flashing sequence. */
#include <stdio.h>
#include <string.h>
#include "picoboot.h"

static void put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}

size_t pb_encode(uint8_t out[PB_CMD_LEN], uint32_t token, uint8_t cmd_id, uint32_t transfer_len,
                 const uint8_t *args, uint8_t args_len)
{
    memset(out, 0, PB_CMD_LEN);
    put32(out + 0, PB_MAGIC);
    put32(out + 4, token);
    out[8] = cmd_id;
    out[9] = args_len;
    put32(out + 12, transfer_len);
    if (args && args_len) memcpy(out + 16, args, args_len > 16 ? 16 : args_len);
    return PB_CMD_LEN;
}

size_t pb_encode_exclusive(uint8_t out[PB_CMD_LEN], uint32_t token, uint8_t mode)
{
    return pb_encode(out, token, PB_EXCLUSIVE_ACCESS, 0, &mode, 1);
}

size_t pb_encode_exit_xip(uint8_t out[PB_CMD_LEN], uint32_t token)
{
    return pb_encode(out, token, PB_EXIT_XIP, 0, NULL, 0);
}

static size_t range(uint8_t out[PB_CMD_LEN], uint32_t token, uint8_t id, uint32_t addr, uint32_t size,
                    uint32_t transfer)
{
    uint8_t a[8];
    put32(a, addr);
    put32(a + 4, size);
    return pb_encode(out, token, id, transfer, a, 8);
}

size_t pb_encode_erase(uint8_t out[PB_CMD_LEN], uint32_t token, uint32_t addr, uint32_t size)
{
    return range(out, token, PB_FLASH_ERASE, addr, size, 0);
}

size_t pb_encode_write(uint8_t out[PB_CMD_LEN], uint32_t token, uint32_t addr, uint32_t size)
{
    return range(out, token, PB_WRITE, addr, size, size);
}

size_t pb_encode_read(uint8_t out[PB_CMD_LEN], uint32_t token, uint32_t addr, uint32_t size)
{
    return range(out, token, PB_READ, addr, size, size);
}

size_t pb_encode_reboot(uint8_t out[PB_CMD_LEN], uint32_t token, uint32_t pc, uint32_t sp, uint32_t delay_ms)
{
    uint8_t a[12];
    put32(a, pc);
    put32(a + 4, sp);
    put32(a + 8, delay_ms);
    return pb_encode(out, token, PB_REBOOT, 0, a, 12);
}

const char *pb_status_name(uint32_t code)
{
    static const char *const names[] = {
        "OK", "UNKNOWN_CMD", "INVALID_CMD_LENGTH", "INVALID_TRANSFER_LENGTH", "INVALID_ADDRESS",
        "BAD_ALIGNMENT", "INTERLEAVED_WRITE", "REBOOTING", "UNKNOWN_ERROR",
    };
    return code < sizeof names / sizeof names[0] ? names[code] : "unknown status";
}

/* ---- the sequence -------------------------------------------------------- */

struct session {
    const struct pb_transport *t;
    uint32_t token;
    char *err;
    size_t err_len;
};

/* A failed transfer: the message, with the boot ROM's own account of the
 * command when it can still give one. */
static int fail(struct session *s, const char *what, uint32_t addr)
{
    const struct pb_transport *t = s->t;
    uint8_t st[16];
    char why[96] = "board unplugged or reset?";
    if (t->status && t->status(t->ctx, st) == 16) {
        uint32_t code = (uint32_t)st[4] | (uint32_t)st[5] << 8 | (uint32_t)st[6] << 16 | (uint32_t)st[7] << 24;
        if (code != PB_STATUS_OK)
            snprintf(why, sizeof why, "the boot ROM reports %s (%u)", pb_status_name(code), (unsigned)code);
    }
    snprintf(s->err, s->err_len, "USB transfer failed during %s at 0x%08x: %s Flash is not verified; "
             "nothing was rebooted", what, (unsigned)addr, why);
    return -1;
}

/* Sends a command, its data phase (OUT data or IN into `in`), and checks the
 * acknowledgement. */
static int run(struct session *s, const uint8_t cmd[PB_CMD_LEN], const char *what, uint32_t addr,
               const uint8_t *out, uint8_t *in, uint32_t len)
{
    const struct pb_transport *t = s->t;
    uint8_t ack[1];
    unsigned ack_timeout = len ? PB_TIMEOUT_MS : PB_DATA_TIMEOUT_MS;
    if (t->bulk_out(t->ctx, cmd, PB_CMD_LEN, PB_TIMEOUT_MS) != (int)PB_CMD_LEN) return fail(s, what, addr);
    if (out && len && t->bulk_out(t->ctx, out, len, PB_DATA_TIMEOUT_MS) != (int)len) return fail(s, what, addr);
    if (in && len && t->bulk_in(t->ctx, in, len, PB_DATA_TIMEOUT_MS) != (int)len) return fail(s, what, addr);
    /* Acknowledgement: a zero-length packet the other way (read into a
     * one-byte buffer: anything longer is an error, not an overflow) */
    int rc = in ? t->bulk_out(t->ctx, NULL, 0, ack_timeout) : t->bulk_in(t->ctx, ack, sizeof ack, ack_timeout);
    if (rc != 0) return fail(s, what, addr);
    s->token++;
    return 0;
}

static int page_used(const struct pb_image *img, uint32_t page)
{
    return !img->used || img->used[page];
}

/* 1 when a page of the image lies in the sector at flash address a. */
static int sector_used(const struct pb_image *img, uint32_t a)
{
    uint32_t lo = a < img->addr ? img->addr : a;
    uint32_t hi = a + PB_SECTOR > img->addr + img->len ? img->addr + img->len : a + PB_SECTOR;
    for (uint32_t pa = lo; pa < hi; pa += PB_PAGE)
        if (page_used(img, (pa - img->addr) / PB_PAGE)) return 1;
    return 0;
}

static int write_page(struct session *s, const struct pb_image *img, uint32_t page)
{
    uint8_t cmd[PB_CMD_LEN];
    uint32_t off = page * PB_PAGE;
    pb_encode_write(cmd, s->token, img->addr + off, PB_PAGE);
    return run(s, cmd, "WRITE", img->addr + off, img->data + off, NULL, PB_PAGE);
}

/* Reads n <= PB_SECTOR bytes at flash address a and compares them with the
 * image. */
static int verify(struct session *s, const struct pb_image *img, uint32_t a, uint32_t n)
{
    static uint8_t back[PB_SECTOR];
    uint8_t cmd[PB_CMD_LEN];
    const uint8_t *want = img->data + (a - img->addr);
    pb_encode_read(cmd, s->token, a, n);
    if (run(s, cmd, "READ", a, NULL, back, n)) return -1;
    for (uint32_t i = 0; i < n; i++)
        if (back[i] != want[i]) {
            snprintf(s->err, s->err_len, "verify failed at 0x%08x (wrote 0x%02x, read 0x%02x): not rebooted "
                     "into a bad image; flash again", (unsigned)(a + i), want[i], back[i]);
            return -1;
        }
    return 0;
}

int pb_flash(const struct pb_transport *t, const struct pb_image *img, int reboot,
             char *err, size_t err_len, void (*progress)(const char *stage, uint32_t done, uint32_t total))
{
    struct session s = { t, 1, err, err_len };
    uint8_t cmd[PB_CMD_LEN];
    char detail[400] = "";
    err[0] = 0;

    if (img->len == 0 || img->addr % PB_PAGE || img->len % PB_PAGE || img->addr < PB_FLASH_BASE ||
        img->addr - PB_FLASH_BASE + (uint64_t)img->len > PB_FLASH_SIZE) {
        snprintf(err, err_len, "image of %u bytes at 0x%08x is not page-aligned flash", (unsigned)img->len,
                 (unsigned)img->addr);
        return -1;
    }

    int o = t->open(t->ctx, detail, sizeof detail);
    switch (o) {
    case PB_OPEN_OK: break;
    case PB_OPEN_NODEV:
        snprintf(err, err_len, "no RP2040 in BOOTSEL mode found (USB %04x:%04x): hold BOOTSEL while "
                 "plugging the board in%s%s", PB_VID, PB_PID_RP2040_BOOT, detail[0] ? "; " : "", detail);
        return -1;
    case PB_OPEN_ACCESS:
        snprintf(err, err_len, "permission denied opening the RP2040 boot ROM (USB %04x:%04x): install "
                 "tools/flasher/60-picoboot.rules in /etc/udev/rules.d (docs/firmware.md)", PB_VID,
                 PB_PID_RP2040_BOOT);
        return -1;
    case PB_OPEN_MANY:
        snprintf(err, err_len, "several RP2040 boot ROMs attached (%s): choose one with --bus and --address, "
                 "or --serial", detail);
        return -1;
    case PB_OPEN_WRONG:
        snprintf(err, err_len, "wrong device: %s", detail[0] ? detail : "no PICOBOOT interface");
        return -1;
    default:
        snprintf(err, err_len, "cannot open the RP2040 boot ROM: %s", detail[0] ? detail : "USB error");
        return -1;
    }

    int rc = 0;
    uint32_t npages = img->len / PB_PAGE;
    uint32_t erase_lo = img->addr & ~(PB_SECTOR - 1);
    uint32_t erase_hi = (img->addr + img->len + PB_SECTOR - 1) & ~(PB_SECTOR - 1);
    /* boot2's page is held back until the rest is written and verified */
    int boot2 = img->addr == PB_FLASH_BASE && page_used(img, 0);

    if (t->reset && t->reset(t->ctx) != 0) {
        snprintf(err, err_len, "cannot reset the PICOBOOT interface of the RP2040 boot ROM: unplug the board "
                 "and hold BOOTSEL while plugging it in again");
        rc = -1;
        goto out;
    }
    pb_encode_exclusive(cmd, s.token, PB_EXCLUSIVE);
    if ((rc = run(&s, cmd, "EXCLUSIVE_ACCESS", img->addr, NULL, NULL, 0))) goto out;
    pb_encode_exit_xip(cmd, s.token);
    if ((rc = run(&s, cmd, "EXIT_XIP", img->addr, NULL, NULL, 0))) goto out;

    /* Only sectors that hold a page of the image are erased, in address
     * order (so the sector of page 0 first): the rest of such a sector,
     * inside or around the image, ends up erased (0xFF, as the image's pad). */
    for (uint32_t a = erase_lo; a < erase_hi; a += PB_SECTOR) {
        if (!sector_used(img, a)) continue;
        if (progress) progress("erase", a - erase_lo, erase_hi - erase_lo);
        pb_encode_erase(cmd, s.token, a, PB_SECTOR);
        if ((rc = run(&s, cmd, "FLASH_ERASE", a, NULL, NULL, 0))) goto out;
    }
    for (uint32_t p = boot2 ? 1 : 0; p < npages; p++) {
        if (!page_used(img, p)) continue;
        if (progress && p % (PB_SECTOR / PB_PAGE) == 0) progress("write", p * PB_PAGE, img->len);
        if ((rc = write_page(&s, img, p))) goto out;
    }
    /* Read back what was erased or written: each erased sector's part of
     * the image (unused pages there read 0xFF), page 0 aside. */
    for (uint32_t a = erase_lo; a < erase_hi; a += PB_SECTOR) {
        if (!sector_used(img, a)) continue;
        uint32_t lo = a < img->addr ? img->addr : a;
        uint32_t hi = a + PB_SECTOR > img->addr + img->len ? img->addr + img->len : a + PB_SECTOR;
        if (boot2 && lo == PB_FLASH_BASE) lo += PB_PAGE;
        if (progress) progress("verify", lo - img->addr, img->len);
        if (lo < hi && (rc = verify(&s, img, lo, hi - lo))) goto out;
    }
    if (boot2) {
        if ((rc = write_page(&s, img, 0))) goto out;
        if ((rc = verify(&s, img, PB_FLASH_BASE, PB_PAGE))) goto out;
    }
    if (reboot) {
        /* pc = 0: a normal boot from flash after delay_ms. */
        pb_encode_reboot(cmd, s.token, 0, 0x20042000u, 100);
        if ((rc = run(&s, cmd, "REBOOT", 0, NULL, NULL, 0))) goto out;
    } else {
        /* staying in the boot ROM: give its mass-storage drive back */
        pb_encode_exclusive(cmd, s.token, PB_NOT_EXCLUSIVE);
        if ((rc = run(&s, cmd, "EXCLUSIVE_ACCESS", 0, NULL, NULL, 0))) goto out;
    }
out:
    t->close(t->ctx);
    return rc;
}
