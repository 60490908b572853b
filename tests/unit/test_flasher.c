/* SPDX-License-Identifier: MIT */
/* test_flasher.c — PICOBOOT command encoding, UF2 loading, and the whole
 * flashing sequence against a fake USB device, with a failure injected at
 * every step. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "check.h"
#include "image.h"
#include "picoboot.h"

/* ---- a fake RP2040 boot ROM behind the transport ------------------------- */

#define FAKE_FLASH (2u * 1024u * 1024u)

enum phase { CMD, DATA_OUT, DATA_IN, ACK_IN, ACK_OUT };

struct fake {
    int open_result;
    long fail_at;          /* bulk call number from which every transfer fails (cable pulled); 0 = never */
    int corrupt_read;      /* flips a bit in READ data */
    long calls;
    enum phase ph;
    uint32_t token, addr, len;
    int exclusive, xip_exited, rebooted, protocol_error, closed;
    int resets, reset_before_cmd;   /* interface resets; 1 if the first came before any command */
    long cmds;
    uint32_t status_code;           /* what GET_COMMAND_STATUS reports after a failure */
    /* timeouts seen: largest of command blocks, of data phases, of the
     * acknowledgements after a data phase; smallest of those without one */
    unsigned cmd_timeout_max, data_timeout_max, data_ack_timeout_max, nodata_ack_timeout_min;
    int had_data;
    long nlog;                      /* every command, in order */
    struct { uint8_t id; uint32_t addr; } log[4096];
    uint8_t flash[FAKE_FLASH];
};

static uint32_t g32(const uint8_t *p) { return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24; }

static int in_range(const struct fake *f, uint32_t a, uint32_t n)
{
    (void)f;
    return a >= PB_FLASH_BASE && a - PB_FLASH_BASE + (uint64_t)n <= FAKE_FLASH;
}

static int f_open(void *ctx, char *detail, size_t n)
{
    struct fake *f = ctx;
    if (f->open_result == PB_OPEN_WRONG) snprintf(detail, n, "USB 2e8a:000a is a running program");
    return f->open_result;
}

static int bad(struct fake *f)
{
    f->protocol_error = 1;
    return -1;
}

static int f_out(void *ctx, const uint8_t *d, size_t n, unsigned ms)
{
    struct fake *f = ctx;
    unsigned *max = f->ph == CMD ? &f->cmd_timeout_max : f->ph == DATA_OUT ? &f->data_timeout_max
                  : &f->data_ack_timeout_max;
    if (ms > *max) *max = ms;
    if (f->fail_at && ++f->calls >= f->fail_at) return -1;
    if (!f->fail_at) f->calls++;
    switch (f->ph) {
    case CMD: {
        if (n != 32 || g32(d) != PB_MAGIC || g32(d + 4) != f->token + 1) return bad(f);
        f->cmds++;
        f->token = g32(d + 4);
        uint8_t id = d[8], sz = d[9];
        uint32_t tl = g32(d + 12);
        f->had_data = tl != 0;
        f->addr = g32(d + 16);
        f->len = g32(d + 20);
        if (f->nlog < (long)(sizeof f->log / sizeof f->log[0])) {
            f->log[f->nlog].id = id;
            f->log[f->nlog].addr = f->addr;
            f->nlog++;
        }
        switch (id) {
        case PB_EXCLUSIVE_ACCESS:
            if (sz != 1 || tl) return bad(f);
            f->exclusive = d[16];
            f->ph = ACK_IN;
            break;
        case PB_EXIT_XIP:
            if (sz != 0 || tl || !f->exclusive) return bad(f);
            f->xip_exited = 1;
            f->ph = ACK_IN;
            break;
        case PB_FLASH_ERASE:
            if (sz != 8 || tl || !f->xip_exited || f->addr % 4096 || f->len % 4096 || !in_range(f, f->addr, f->len))
                return bad(f);
            memset(f->flash + (f->addr - PB_FLASH_BASE), 0xFF, f->len);
            f->ph = ACK_IN;
            break;
        case PB_WRITE:
            if (sz != 8 || tl != f->len || f->addr % 256 || !in_range(f, f->addr, f->len)) return bad(f);
            f->ph = DATA_OUT;
            break;
        case PB_READ:
            if (sz != 8 || tl != f->len || !in_range(f, f->addr, f->len)) return bad(f);
            f->ph = DATA_IN;
            break;
        case PB_REBOOT:
            if (sz != 12 || tl) return bad(f);
            f->rebooted = 1;
            f->ph = ACK_IN;
            break;
        default:
            return bad(f);
        }
        return (int)n;
    }
    case DATA_OUT:
        if (n != f->len) return bad(f);
        /* Programming only clears bits, as NOR flash does. */
        for (size_t i = 0; i < n; i++) f->flash[f->addr - PB_FLASH_BASE + i] &= d[i];
        f->ph = ACK_IN;
        return (int)n;
    case ACK_OUT:
        if (n != 0) return bad(f);
        f->ph = CMD;
        return 0;
    default:
        return bad(f);
    }
}

static int f_in(void *ctx, uint8_t *d, size_t n, unsigned ms)
{
    struct fake *f = ctx;
    if (f->ph == ACK_IN && !f->had_data) {
        if (!f->nodata_ack_timeout_min || ms < f->nodata_ack_timeout_min) f->nodata_ack_timeout_min = ms;
    } else {
        unsigned *max = f->ph == DATA_IN ? &f->data_timeout_max : &f->data_ack_timeout_max;
        if (ms > *max) *max = ms;
    }
    if (f->fail_at && ++f->calls >= f->fail_at) return -1;
    if (!f->fail_at) f->calls++;
    switch (f->ph) {
    case DATA_IN:
        if (n != f->len) return bad(f);
        memcpy(d, f->flash + (f->addr - PB_FLASH_BASE), n);
        if (f->corrupt_read) d[n / 2] ^= 0x10;
        f->ph = ACK_OUT;
        return (int)n;
    case ACK_IN:
        /* a real buffer for the zero-length acknowledgement */
        if (n == 0 || !d) return bad(f);
        f->ph = CMD;
        return 0;
    default:
        return bad(f);
    }
}

static void f_close(void *ctx) { ((struct fake *)ctx)->closed = 1; }

static int f_reset(void *ctx)
{
    struct fake *f = ctx;
    if (f->resets++ == 0) f->reset_before_cmd = f->cmds == 0;
    f->ph = CMD;
    return 0;
}

static int f_status(void *ctx, uint8_t out[16])
{
    struct fake *f = ctx;
    memset(out, 0, 16);
    out[4] = (uint8_t)f->status_code;
    return 16;
}

static struct fake *fake_new(void)
{
    struct fake *f = calloc(1, sizeof *f);
    memset(f->flash, 0x5A, sizeof f->flash);  /* old contents */
    return f;
}

static struct pb_transport fake_transport(struct fake *f)
{
    struct pb_transport t = { f, f_open, f_out, f_in, f_close, f_reset, f_status };
    return t;
}

/* ---- helpers ------------------------------------------------------------- */

static void make_image(struct pb_image *img, uint32_t addr, uint32_t len)
{
    img->addr = addr;
    img->len = len;
    img->data = malloc(len);
    img->used = NULL;
    uint32_t s = 12345;
    for (uint32_t i = 0; i < len; i++) {
        s = s * 1103515245u + 12345u;
        img->data[i] = (uint8_t)(s >> 16);
    }
}

static void put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}

/* UF2 of `len` bytes at addr, family fam. */
static uint8_t *make_uf2(const uint8_t *data, uint32_t addr, uint32_t len, uint32_t fam, size_t *out_len)
{
    uint32_t n = len / 256;
    uint8_t *u = calloc(n, 512);
    for (uint32_t i = 0; i < n; i++) {
        uint8_t *b = u + 512 * i;
        put32(b, 0x0A324655u); put32(b + 4, 0x9E5D5157u); put32(b + 8, 0x2000u);
        put32(b + 12, addr + 256 * i); put32(b + 16, 256); put32(b + 20, i); put32(b + 24, n);
        put32(b + 28, fam);
        memcpy(b + 32, data + 256 * i, 256);
        put32(b + 508, 0x0AB16F30u);
    }
    *out_len = (size_t)n * 512;
    return u;
}

static int one_line(const char *s) { return s[0] && !strchr(s, '\n'); }

/* ---- tests --------------------------------------------------------------- */

static void test_encoding(void)
{
    uint8_t c[32];
    pb_encode_write(c, 7, 0x10000100u, 256);
    static const uint8_t want[32] = {
        0x0b, 0xd1, 0x1f, 0x43, 7, 0, 0, 0, 0x05, 8, 0, 0, 0x00, 0x01, 0, 0,
        0x00, 0x01, 0x00, 0x10, 0x00, 0x01, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    };
    check(memcmp(c, want, 32) == 0, "picoboot_write_command_bytes", "encoding differs");
    pb_encode_read(c, 9, 0x10000000u, 4096);
    check(c[8] == 0x84 && c[9] == 8 && g32(c + 12) == 4096 && g32(c + 16) == 0x10000000u && g32(c + 20) == 4096,
          "picoboot_read_command_has_in_bit_and_length", "id %02x size %u", c[8], c[9]);
    pb_encode_erase(c, 3, 0x10001000u, 4096);
    check(c[8] == 0x03 && c[9] == 8 && g32(c + 12) == 0 && g32(c + 16) == 0x10001000u,
          "picoboot_erase_has_no_data_phase", "id %02x tl %u", c[8], g32(c + 12));
    pb_encode_exclusive(c, 1, PB_EXCLUSIVE);
    check(c[8] == 0x01 && c[9] == 1 && c[16] == 1 && g32(c + 12) == 0, "picoboot_exclusive_access_args",
          "bad");
    pb_encode_exit_xip(c, 2);
    check(c[8] == 0x06 && c[9] == 0, "picoboot_exit_xip_no_args", "bad");
    pb_encode_reboot(c, 5, 0, 0x20042000u, 100);
    check(c[8] == 0x02 && c[9] == 12 && g32(c + 20) == 0x20042000u && g32(c + 24) == 100,
          "picoboot_reboot_args_pc_sp_delay", "bad");
}

static void test_success(void)
{
    struct fake *f = fake_new();
    struct pb_transport t = fake_transport(f);
    struct pb_image img;
    char err[512];
    make_image(&img, 0x10000000u, 3 * 4096 + 512);
    int rc = pb_flash(&t, &img, 1, err, sizeof err, NULL);
    int same = memcmp(f->flash, img.data, img.len) == 0;
    /* The rest of the last erased sector is erased (0xFF), beyond it untouched. */
    int tail = f->flash[img.len] == 0xFF && f->flash[4 * 4096] == 0x5A;
    check(rc == 0 && same && tail && f->rebooted && !f->protocol_error && f->closed,
          "flash_sequence_writes_verifies_and_reboots", "rc %d same %d tail %d reboot %d proto %d: %s", rc,
          same, tail, f->rebooted, f->protocol_error, err);
    long total = f->calls;
    check(f->resets == 1 && f->reset_before_cmd, "flash_resets_the_interface_before_the_first_command",
          "%d resets, before: %d", f->resets, f->reset_before_cmd);
    check(f->cmd_timeout_max == 3000 && f->data_timeout_max == 10000 && f->data_ack_timeout_max == 3000 &&
          f->nodata_ack_timeout_min == 10000, "flash_transfer_timeouts",
          "command %u ms, data %u ms, ack after data %u ms, ack without data (erase) %u ms", f->cmd_timeout_max,
          f->data_timeout_max, f->data_ack_timeout_max, f->nodata_ack_timeout_min);
    free(f);

    /* without the reboot, exclusive access is given back at the end */
    f = fake_new();
    t = fake_transport(f);
    rc = pb_flash(&t, &img, 0, err, sizeof err, NULL);
    check(rc == 0 && !f->rebooted && f->exclusive == PB_NOT_EXCLUSIVE && f->closed,
          "no_reboot_releases_exclusive_access", "rc %d rebooted %d exclusive %d: %s", rc, f->rebooted,
          f->exclusive, err);
    free(f);

    /* a failure names the boot ROM's status code when it gives one */
    f = fake_new();
    f->fail_at = 12;
    f->status_code = PB_STATUS_INVALID_ADDRESS;
    t = fake_transport(f);
    rc = pb_flash(&t, &img, 1, err, sizeof err, NULL);
    check(rc == -1 && one_line(err) && strstr(err, "INVALID_ADDRESS (4)"), "failure_reports_boot_rom_status",
          "rc %d: %s", rc, err);
    free(f);

    /* A failure at every bulk transfer: exit 2, one line, never a reboot
     * before the image was verified. */
    int all_ok = 1;
    long bad_at = -1;
    for (long k = 1; k <= total; k++) {
        f = fake_new();
        f->fail_at = k;
        t = fake_transport(f);
        rc = pb_flash(&t, &img, 1, err, sizeof err, NULL);
        int reboot_cmd_sent = f->rebooted;
        /* Only the last 2 transfers (REBOOT command and its ack) may come
         * after the reboot was accepted. */
        int ok = rc == -1 && one_line(err) && strstr(err, "USB transfer failed") && f->closed &&
                 (!reboot_cmd_sent || k >= total);
        if (!ok && all_ok) {
            all_ok = 0;
            bad_at = k;
        }
        free(f);
    }
    check(all_ok, "flash_failure_at_every_transfer_exits_2_without_reboot", "failed at transfer %ld of %ld",
          bad_at, total);

    f = fake_new();
    f->corrupt_read = 1;
    t = fake_transport(f);
    rc = pb_flash(&t, &img, 1, err, sizeof err, NULL);
    check(rc == -1 && one_line(err) && strstr(err, "verify failed") && !f->rebooted,
          "verify_mismatch_fails_and_does_not_reboot", "rc %d reboot %d: %s", rc, f->rebooted, err);
    free(f);

    static const struct { int r; const char *word; const char *name; } opens[] = {
        { PB_OPEN_NODEV, "no RP2040 in BOOTSEL mode", "no_device_exits_2" },
        { PB_OPEN_ACCESS, "60-picoboot.rules", "permission_denied_names_the_udev_rule" },
        { PB_OPEN_WRONG, "wrong device", "wrong_device_exits_2" },
        { PB_OPEN_ERROR, "cannot open", "usb_error_exits_2" },
    };
    for (size_t i = 0; i < sizeof opens / sizeof opens[0]; i++) {
        f = fake_new();
        f->open_result = opens[i].r;
        t = fake_transport(f);
        rc = pb_flash(&t, &img, 1, err, sizeof err, NULL);
        check(rc == -1 && one_line(err) && strstr(err, opens[i].word) && f->calls == 0, opens[i].name,
              "rc %d: %s", rc, err);
        free(f);
    }
    image_free(&img);
}

static void test_uf2(void)
{
    struct pb_image src, img;
    char err[256];
    size_t n;
    make_image(&src, 0x10000000u, 8 * 256);
    uint8_t *u = make_uf2(src.data, src.addr, src.len, UF2_FAMILY_RP2040, &n);
    int rc = image_from_uf2(u, n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == 0 && img.addr == src.addr && img.len == src.len && memcmp(img.data, src.data, src.len) == 0,
          "uf2_blocks_make_the_image", "rc %d: %s", rc, err);
    if (rc == 0) image_free(&img);

    u[512 * 3 + 508] ^= 1;
    rc = image_from_uf2(u, n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "block 3") && strstr(err, "magic"), "uf2_bad_magic_rejected", "%s", err);
    free(u);

    u = make_uf2(src.data, src.addr, src.len, 0x12345678u, &n);
    rc = image_from_uf2(u, n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "no RP2040 blocks"), "uf2_other_family_rejected", "%s", err);
    free(u);

    u = make_uf2(src.data, src.addr, src.len, UF2_FAMILY_RP2040, &n);
    rc = image_from_uf2(u, n - 512, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "truncated"), "uf2_truncated_rejected", "%s", err);
    rc = image_from_uf2(u, n - 5, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "multiple of 512"), "uf2_partial_block_rejected", "%s", err);
    free(u);

    /* a page given twice: a duplicate block, or one block moved onto another */
    u = make_uf2(src.data, src.addr, src.len, UF2_FAMILY_RP2040, &n);
    memcpy(u + 512 * 5, u + 512 * 2, 512);
    put32(u + 512 * 5 + 20, 5);
    rc = image_from_uf2(u, n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "given twice") && strstr(err, "block 5"), "uf2_duplicate_block_rejected", "%s",
          err);
    free(u);
    u = make_uf2(src.data, src.addr, src.len, UF2_FAMILY_RP2040, &n);
    put32(u + 512 * 6 + 12, src.addr + 256 * 1);
    rc = image_from_uf2(u, n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "given twice"), "uf2_overlapping_block_rejected", "%s", err);
    free(u);

    /* addresses past the flash limit (2 MiB by default), and inside a larger one */
    u = make_uf2(src.data, 0x10000000u + PB_FLASH_LIMIT - 4 * 256, src.len, UF2_FAMILY_RP2040, &n);
    rc = image_from_uf2(u, n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "outside the 2048 KB of flash"), "uf2_past_flash_limit_rejected", "%s", err);
    rc = image_from_uf2(u, n, 2 * PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == 0, "uf2_inside_larger_flash_accepted", "%s", err);
    if (rc == 0) image_free(&img);
    free(u);

    /* a sparse image: the gap between its blocks is erased (0xFF) */
    u = make_uf2(src.data, src.addr, src.len, UF2_FAMILY_RP2040, &n);
    for (int i = 4; i < 8; i++) put32(u + 512 * i + 12, src.addr + 4096 + 256 * (uint32_t)i);
    rc = image_from_uf2(u, n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == 0 && img.len == 4096 + 8 * 256 && img.data[4 * 256] == 0xFF && img.data[4096 + 4 * 256] ==
          src.data[4 * 256], "uf2_sparse_image_gaps_erased", "rc %d len %u: %s", rc, (unsigned)img.len, err);
    if (rc == 0) image_free(&img);

    /* the format is the content's: UF2 bytes are UF2 whatever the name */
    check(image_is_uf2(u, n) && !image_is_uf2(src.data, src.len) && !image_is_uf2(u, 100),
          "uf2_decided_by_content", "wrong");
    free(u);

    rc = image_from_bin(src.data, 300, PB_FLASH_BASE, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == 0 && img.len == 512 && img.data[300] == 0xFF && img.data[0] == src.data[0],
          "bin_padded_to_pages_with_ff", "rc %d len %u", rc, (unsigned)img.len);
    if (rc == 0) image_free(&img);
    rc = image_from_bin(src.data, 300, PB_FLASH_BASE + PB_FLASH_LIMIT - 256, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "does not fit"), "bin_past_flash_limit_rejected", "%s", err);
    image_free(&src);
}

static int all_bytes(const uint8_t *p, size_t n, uint8_t v)
{
    for (size_t i = 0; i < n; i++)
        if (p[i] != v) return 0;
    return 1;
}

/* Page 0 (boot2) is written last, after everything else is written and
 * verified: an interruption anywhere before leaves it erased (or, before
 * the first erase, the old flash untouched). */
static void test_page0_last(void)
{
    struct fake *f = fake_new();
    struct pb_transport t = fake_transport(f);
    struct pb_image img;
    char err[512];
    make_image(&img, 0x10000000u, 2 * 4096 + 768);
    int rc = pb_flash(&t, &img, 1, err, sizeof err, NULL);
    long w0 = -1, last_other_write = -1, last_other_read = -1, first_erase = -1, reads_of_0 = 0;
    for (long i = 0; i < f->nlog; i++) {
        uint8_t id = f->log[i].id;
        uint32_t a = f->log[i].addr;
        if (id == PB_FLASH_ERASE && first_erase < 0) first_erase = i;
        if (id == PB_FLASH_ERASE && first_erase == i && a != 0x10000000u) first_erase = -2;
        if (id == PB_WRITE && a == 0x10000000u) w0 = i;
        else if (id == PB_WRITE) last_other_write = i;
        else if (id == PB_READ && a == 0x10000000u) reads_of_0++;
        else if (id == PB_READ) last_other_read = i;
    }
    int ordered = rc == 0 && first_erase >= 0 && w0 > last_other_write && w0 > last_other_read &&
                  last_other_read > last_other_write && f->log[w0 + 1].id == PB_READ &&
                  f->log[w0 + 1].addr == 0x10000000u && reads_of_0 == 1 && f->log[w0 + 2].id == PB_REBOOT &&
                  memcmp(f->flash, img.data, img.len) == 0;
    check(ordered, "flash_writes_page0_last_after_verify",
          "rc %d: erase of sector 0 at %ld, page 0 written at command %ld, last other write %ld, last other "
          "read %ld, page 0 read %ld times: %s", rc, first_erase, w0, last_other_write, last_other_read,
          reads_of_0, err);
    long total = f->calls;
    free(f);

    /* cut at every transfer: page 0 is the old one (nothing erased yet) or
     * erased, unless the rest of the image is already in flash */
    int all_ok = 1;
    long bad_at = -1;
    for (long k = 1; k <= total; k++) {
        f = fake_new();
        f->fail_at = k;
        t = fake_transport(f);
        rc = pb_flash(&t, &img, 1, err, sizeof err, NULL);
        int old = all_bytes(f->flash, 256, 0x5A), erased = all_bytes(f->flash, 256, 0xFF);
        int rest = memcmp(f->flash + 256, img.data + 256, img.len - 256) == 0;
        if (rc != -1 || !(old || erased || rest)) {
            all_ok = 0;
            bad_at = k;
            free(f);
            break;
        }
        free(f);
    }
    check(all_ok, "flash_interrupted_leaves_page0_erased", "cut at transfer %ld of %ld", bad_at, total);

    /* an image that does not start at page 0 keeps its order */
    f = fake_new();
    t = fake_transport(f);
    image_free(&img);
    make_image(&img, 0x10002000u, 1024);
    rc = pb_flash(&t, &img, 1, err, sizeof err, NULL);
    check(rc == 0 && f->log[3].id == PB_WRITE && f->log[3].addr == 0x10002000u &&
          all_bytes(f->flash, 0x2000, 0x5A), "flash_image_past_page0_in_address_order", "rc %d: %s", rc, err);
    free(f);
    image_free(&img);
}

/* A sparse UF2: only the sectors holding its pages are erased. */
static void test_sparse_erase(void)
{
    struct pb_image src, img;
    char err[512];
    size_t n;
    make_image(&src, 0x10000000u, 4 * 256);
    uint8_t *u = make_uf2(src.data, src.addr, src.len, UF2_FAMILY_RP2040, &n);
    /* pages at 0, 0x100 (sector 0), 0x10000 (sector 16), 0x1FF00 (sector 31) */
    put32(u + 512 * 2 + 12, 0x10010000u);
    put32(u + 512 * 3 + 12, 0x1001FF00u);
    int rc = image_from_uf2(u, n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == 0 && img.len == 0x20000 && img.used && img.used[0] && img.used[1] && !img.used[2] &&
          img.used[0x100] && img.used[0x1FF], "uf2_sparse_marks_used_pages", "rc %d: %s", rc, err);
    if (rc != 0) {
        free(u);
        image_free(&src);
        return;
    }
    struct fake *f = fake_new();
    struct pb_transport t = fake_transport(f);
    rc = pb_flash(&t, &img, 1, err, sizeof err, NULL);
    int erases = 0, writes = 0, erased_ok = 1;
    for (long i = 0; i < f->nlog; i++) {
        if (f->log[i].id == PB_FLASH_ERASE) {
            erases++;
            uint32_t a = f->log[i].addr;
            if (a != 0x10000000u && a != 0x10010000u && a != 0x1001F000u) erased_ok = 0;
        }
        writes += f->log[i].id == PB_WRITE;
    }
    uint8_t *fl = f->flash;
    int gaps_kept = all_bytes(fl + 0x1000, 0x10000 - 0x1000, 0x5A) && all_bytes(fl + 0x11000, 0x1F000 - 0x11000, 0x5A);
    int pages = memcmp(fl, src.data, 512) == 0 && memcmp(fl + 0x10000, src.data + 512, 256) == 0 &&
                memcmp(fl + 0x1FF00, src.data + 768, 256) == 0;
    int sectors_erased = all_bytes(fl + 512, 4096 - 512, 0xFF) && all_bytes(fl + 0x10100, 0xF00, 0xFF) &&
                         all_bytes(fl + 0x1F000, 0xF00, 0xFF) && all_bytes(fl + 0x20000, 0x1000, 0x5A);
    check(rc == 0 && erases == 3 && erased_ok && writes == 4 && gaps_kept && pages && sectors_erased,
          "sparse_uf2_erases_only_its_sectors", "rc %d, %d erases (ok %d), %d writes, gaps kept %d, pages %d, "
          "sectors erased %d: %s", rc, erases, erased_ok, writes, gaps_kept, pages, sectors_erased, err);
    free(f);
    image_free(&img);
    free(u);
    image_free(&src);
}

/* A name ending in .uf2 must hold a UF2: never flashed as a raw binary. */
static void test_uf2_name(void)
{
    struct pb_image src, img;
    char err[256];
    size_t n;
    size_t cap = 2 * PB_FLASH_SIZE + 1;
    check(image_name_is_uf2("a.uf2") && image_name_is_uf2("dir/X.UF2") && image_name_is_uf2(".Uf2") &&
          !image_name_is_uf2("a.bin") && !image_name_is_uf2("uf2") && !image_name_is_uf2("a.uf2.bin"),
          "uf2_name_any_case", "wrong");
    make_image(&src, 0x10000000u, 4 * 256);
    uint8_t *u = make_uf2(src.data, src.addr, src.len, UF2_FAMILY_RP2040, &n);

    u[0] ^= 1;   /* the first magic word damaged */
    int rc = image_load(u, n, cap, "fw.uf2", PB_FLASH_BASE, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && one_line(err) && strcmp(err, "not a UF2 file: block 0 has bad magic") == 0,
          "uf2_name_damaged_magic_refused", "rc %d: %s", rc, err);
    if (rc == 0) image_free(&img);
    /* the same bytes under another name are a flat binary, as before */
    rc = image_load(u, n, cap, "fw.bin", PB_FLASH_BASE, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == 0 && img.len == n && img.used == NULL, "bin_name_damaged_uf2_is_a_binary", "rc %d: %s", rc, err);
    if (rc == 0) image_free(&img);
    u[0] ^= 1;
    rc = image_load(u, n, cap, "fw.bin", PB_FLASH_BASE, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == 0 && img.len == src.len && memcmp(img.data, src.data, src.len) == 0, "bin_name_uf2_content_is_uf2",
          "rc %d: %s", rc, err);
    if (rc == 0) image_free(&img);
    rc = image_load(u, n, cap, "FW.UF2", PB_FLASH_BASE, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == 0 && img.len == src.len, "uf2_name_upper_case_valid_accepted", "rc %d: %s", rc, err);
    if (rc == 0) image_free(&img);

    static const char text[] = "hello, this is not an image\n";
    rc = image_load((const uint8_t *)text, sizeof text - 1, cap, "t.uf2", PB_FLASH_BASE, PB_FLASH_LIMIT, &img,
                    err, sizeof err);
    check(rc == -1 && one_line(err) && strstr(err, "not a UF2 file"), "uf2_name_text_refused", "rc %d: %s", rc,
          err);
    if (rc == 0) image_free(&img);
    uint8_t zero[512] = { 0 };
    rc = image_load(zero, sizeof zero, cap, "z.Uf2", PB_FLASH_BASE, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strcmp(err, "not a UF2 file: block 0 has bad magic") == 0, "uf2_name_zero_block_refused",
          "rc %d: %s", rc, err);
    if (rc == 0) image_free(&img);
    rc = image_load(zero, 3, cap, "short.uf2", PB_FLASH_BASE, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "not a UF2 file"), "uf2_name_short_file_refused", "rc %d: %s", rc, err);
    if (rc == 0) image_free(&img);
    free(u);
    image_free(&src);
}

/* Block numbers: each once, so two images in one file are not one. */
static void test_uf2_block_numbers(void)
{
    struct pb_image src, img;
    char err[256];
    size_t n;
    make_image(&src, 0x10000000u, 4 * 256);
    uint8_t *u = make_uf2(src.data, src.addr, src.len, UF2_FAMILY_RP2040, &n);
    put32(u + 512 * 3 + 20, 0);   /* blocks 0 1 2 0, four pages, "4 blocks" */
    int rc = image_from_uf2(u, n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && one_line(err) && strstr(err, "block number 0 of 4 appears twice") && strstr(err, "block 3"),
          "uf2_duplicate_block_number_rejected", "rc %d: %s", rc, err);
    if (rc == 0) image_free(&img);
    free(u);

    /* two whole images of 2 blocks each, at different addresses, one after the other */
    uint8_t *a = make_uf2(src.data, src.addr, 512, UF2_FAMILY_RP2040, &n);
    uint8_t *b = make_uf2(src.data, src.addr + 8192, 512, UF2_FAMILY_RP2040, &n);
    uint8_t *ab = malloc(2 * n);
    memcpy(ab, a, n);
    memcpy(ab + n, b, n);
    rc = image_from_uf2(ab, 2 * n, PB_FLASH_LIMIT, &img, err, sizeof err);
    check(rc == -1 && strstr(err, "appears twice"), "uf2_two_images_concatenated_rejected", "rc %d: %s", rc, err);
    if (rc == 0) image_free(&img);
    free(a);
    free(b);
    free(ab);
    image_free(&src);
}

/* ---- reading the file ---------------------------------------------------- */

static char hook_path[256];
static void grow_file(const char *path)
{
    FILE *f = fopen(path, "ab");
    if (f) {
        fputs("more", f);
        fclose(f);
    }
    strncpy(hook_path, path, sizeof hook_path - 1);
}

static void test_read_file(void)
{
    char dir[] = "/tmp/test_flasher_XXXXXX", p[300], err[256];
    static uint8_t buf[8192];
    size_t len = 99;
    if (!mkdtemp(dir)) {
        check(0, "read_file_tmpdir", "mkdtemp failed");
        return;
    }
    snprintf(p, sizeof p, "%s/ok.bin", dir);
    FILE *f = fopen(p, "wb");
    fputs("0123456789", f);
    fclose(f);
    int rc = image_read_file(p, buf, sizeof buf, &len, err, sizeof err);
    check(rc == 0 && len == 10 && memcmp(buf, "0123456789", 10) == 0, "read_file_regular", "rc %d: %s", rc, err);

    image_read_hook = grow_file;
    rc = image_read_file(p, buf, sizeof buf, &len, err, sizeof err);
    image_read_hook = NULL;
    check(rc == -1 && one_line(err) && strstr(err, "changed while it was read") && hook_path[0],
          "read_file_changed_while_read_refused", "rc %d: %s", rc, err);

    snprintf(p, sizeof p, "%s/missing.uf2", dir);
    rc = image_read_file(p, buf, sizeof buf, &len, err, sizeof err);
    check(rc == -1 && strcmp(err, "cannot open: No such file or directory") == 0, "read_file_missing_says_why",
          "rc %d: %s", rc, err);

    rc = image_read_file(dir, buf, sizeof buf, &len, err, sizeof err);
    check(rc == -1 && one_line(err) && strstr(err, "Is a directory"), "read_file_directory_refused", "rc %d: %s",
          rc, err);

    snprintf(p, sizeof p, "%s/empty.uf2", dir);
    fclose(fopen(p, "wb"));
    rc = image_read_file(p, buf, sizeof buf, &len, err, sizeof err);
    check(rc == -1 && strstr(err, "empty file (0 bytes)"), "read_file_empty_refused", "rc %d: %s", rc, err);
    unlink(p);

    /* a FIFO with no writer: refused at once, never a hang */
    snprintf(p, sizeof p, "%s/fifo.uf2", dir);
    if (mkfifo(p, 0600) == 0) {
        rc = image_read_file(p, buf, sizeof buf, &len, err, sizeof err);
        check(rc == -1 && strcmp(err, "not a regular file (a FIFO)") == 0, "read_file_fifo_refused", "rc %d: %s",
              rc, err);
        unlink(p);
    }
    rc = image_read_file("/dev/null", buf, sizeof buf, &len, err, sizeof err);
    check(rc == -1 && strstr(err, "a character device"), "read_file_device_refused", "rc %d: %s", rc, err);

    snprintf(p, sizeof p, "%s/ok.bin", dir);
    unlink(p);
    rmdir(dir);
}

int main(void)
{
    test_encoding();
    test_success();
    test_uf2();
    test_uf2_name();
    test_uf2_block_numbers();
    test_page0_last();
    test_sparse_erase();
    test_read_file();
    return check_exit();
}
