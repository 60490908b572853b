/* SPDX-License-Identifier: MIT */
/* image.c — UF2 and .bin images for the flasher. */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "image.h"

#define UF2_MAGIC0 0x0A324655u
#define UF2_MAGIC1 0x9E5D5157u
#define UF2_MAGIC_END 0x0AB16F30u
#define UF2_FLAG_NOT_MAIN 0x00000001u
#define UF2_FLAG_FAMILY 0x00002000u

static uint32_t get32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static int in_flash(uint32_t a, uint32_t n, uint32_t flash_size)
{
    return a >= PB_FLASH_BASE && (uint64_t)a - PB_FLASH_BASE + n <= flash_size;
}

int image_is_uf2(const uint8_t *buf, size_t len)
{
    return len >= 512 && get32(buf) == UF2_MAGIC0 && get32(buf + 4) == UF2_MAGIC1;
}

int image_from_uf2(const uint8_t *buf, size_t len, uint32_t flash_size, struct pb_image *img, char *err,
                   size_t err_len)
{
    img->data = img->used = NULL;
    if (flash_size > PB_FLASH_SIZE) flash_size = PB_FLASH_SIZE;
    if (len >= 8 && (get32(buf) != UF2_MAGIC0 || get32(buf + 4) != UF2_MAGIC1)) {
        snprintf(err, err_len, "not a UF2 file: block 0 has bad magic");
        return -1;
    }
    if (len == 0 || len % 512) {
        snprintf(err, err_len, "not a UF2 file: %zu bytes is not a multiple of 512", len);
        return -1;
    }
    /* one bit per page of flash: a page given twice (duplicate or
     * overlapping blocks) would make the image depend on block order; one
     * bit per block number: a number given twice is a second image */
    size_t nfile = len / 512;
    uint8_t *seen = calloc(flash_size / PB_PAGE / 8 + 1, 1);
    uint8_t *seen_no = calloc(nfile / 8 + 1, 1);
    if (!seen || !seen_no) {
        free(seen);
        free(seen_no);
        snprintf(err, err_len, "out of memory");
        return -1;
    }
    uint32_t lo = 0xFFFFFFFFu, hi = 0, nblocks = 0, count = 0;
    for (size_t b = 0; b < len / 512; b++) {
        const uint8_t *p = buf + 512 * b;
        uint32_t flags = get32(p + 8), addr = get32(p + 12), size = get32(p + 16);
        uint32_t bno = get32(p + 20), total = get32(p + 24), family = get32(p + 28);
        if (get32(p) != UF2_MAGIC0 || get32(p + 4) != UF2_MAGIC1 || get32(p + 508) != UF2_MAGIC_END) {
            snprintf(err, err_len, "UF2 block %zu: bad magic number", b);
            free(seen);
            free(seen_no);
            return -1;
        }
        if (flags & UF2_FLAG_NOT_MAIN) continue;
        if ((flags & UF2_FLAG_FAMILY) && family != UF2_FAMILY_RP2040) continue;
        if (size != PB_PAGE || addr % PB_PAGE) {
            snprintf(err, err_len, "UF2 block %zu: %u bytes at 0x%08x, expected 256 at a page boundary",
                     b, (unsigned)size, (unsigned)addr);
            free(seen);
            free(seen_no);
            return -1;
        }
        if (!in_flash(addr, size, flash_size)) {
            snprintf(err, err_len, "UF2 block %zu: address 0x%08x is outside the %u KB of flash (--flash-size)",
                     b, (unsigned)addr, (unsigned)(flash_size / 1024));
            free(seen);
            free(seen_no);
            return -1;
        }
        if (total == 0 || bno >= total || (count && total != count)) {
            snprintf(err, err_len, "UF2 block %zu: block number %u of %u is inconsistent", b,
                     (unsigned)bno, (unsigned)total);
            free(seen);
            free(seen_no);
            return -1;
        }
        if (total > nfile) {
            snprintf(err, err_len, "UF2 file has %zu blocks, its block %zu says %u: truncated", nfile, b,
                     (unsigned)total);
            free(seen);
            free(seen_no);
            return -1;
        }
        if (seen_no[bno / 8] & (1u << (bno % 8))) {
            snprintf(err, err_len, "UF2 block %zu: block number %u of %u appears twice (two images in one "
                                   "file?)",
                     b, (unsigned)bno, (unsigned)total);
            free(seen);
            free(seen_no);
            return -1;
        }
        seen_no[bno / 8] |= (uint8_t)(1u << (bno % 8));
        uint32_t page = (addr - PB_FLASH_BASE) / PB_PAGE;
        if (seen[page / 8] & (1u << (page % 8))) {
            snprintf(err, err_len, "UF2 block %zu: page 0x%08x is given twice (duplicate or overlapping blocks)",
                     b, (unsigned)addr);
            free(seen);
            free(seen_no);
            return -1;
        }
        seen[page / 8] |= (uint8_t)(1u << (page % 8));
        count = total;
        nblocks++;
        if (addr < lo) lo = addr;
        if (addr + size > hi) hi = addr + size;
    }
    free(seen);
    free(seen_no);
    if (nblocks == 0) {
        snprintf(err, err_len, "UF2 file has no RP2040 blocks (family 0x%08x)", UF2_FAMILY_RP2040);
        return -1;
    }
    if (nblocks != count) {
        snprintf(err, err_len, "UF2 file has %u of %u blocks: truncated", (unsigned)nblocks, (unsigned)count);
        return -1;
    }
    img->addr = lo;
    img->len = hi - lo;
    img->data = malloc(img->len);
    img->used = calloc(img->len / PB_PAGE, 1);
    if (!img->data || !img->used) {
        image_free(img);
        snprintf(err, err_len, "out of memory");
        return -1;
    }
    memset(img->data, 0xFF, img->len);
    for (size_t b = 0; b < len / 512; b++) {
        const uint8_t *p = buf + 512 * b;
        uint32_t flags = get32(p + 8);
        if ((flags & UF2_FLAG_NOT_MAIN) || ((flags & UF2_FLAG_FAMILY) && get32(p + 28) != UF2_FAMILY_RP2040))
            continue;
        memcpy(img->data + (get32(p + 12) - lo), p + 32, PB_PAGE);
        img->used[(get32(p + 12) - lo) / PB_PAGE] = 1;
    }
    return 0;
}

int image_from_bin(const uint8_t *buf, size_t len, uint32_t addr, uint32_t flash_size, struct pb_image *img,
                   char *err, size_t err_len)
{
    img->data = img->used = NULL;
    if (flash_size > PB_FLASH_SIZE) flash_size = PB_FLASH_SIZE;
    if (len == 0 || len > flash_size || addr % PB_PAGE ||
        !in_flash(addr, (uint32_t)((len + PB_PAGE - 1) / PB_PAGE * PB_PAGE), flash_size)) {
        snprintf(err, err_len, "binary of %zu bytes does not fit in the %u KB of flash at 0x%08x (--flash-size)",
                 len, (unsigned)(flash_size / 1024), (unsigned)addr);
        return -1;
    }
    uint32_t padded = (uint32_t)((len + PB_PAGE - 1) / PB_PAGE * PB_PAGE);
    img->data = malloc(padded);
    if (!img->data) {
        snprintf(err, err_len, "out of memory");
        return -1;
    }
    memset(img->data, 0xFF, padded);
    memcpy(img->data, buf, len);
    img->addr = addr;
    img->len = padded;
    return 0;
}

void image_free(struct pb_image *img)
{
    free(img->data);
    free(img->used);
    img->data = img->used = NULL;
}

int image_name_is_uf2(const char *name)
{
    size_t n = strlen(name);
    if (n < 4 || name[n - 4] != '.') return 0;
    return tolower((unsigned char)name[n - 3]) == 'u' && tolower((unsigned char)name[n - 2]) == 'f' &&
           name[n - 1] == '2';
}

void (*image_read_hook)(const char *path);

static const char *file_kind(mode_t m)
{
    return S_ISFIFO(m) ? "a FIFO" : S_ISCHR(m) ? "a character device"
                                : S_ISBLK(m)   ? "a block device"
                                : S_ISSOCK(m)  ? "a socket"
                                               : "not a file";
}

static int same_file_state(const struct stat *a, const struct stat *b)
{
    return a->st_dev == b->st_dev && a->st_ino == b->st_ino && a->st_size == b->st_size &&
           a->st_mtim.tv_sec == b->st_mtim.tv_sec && a->st_mtim.tv_nsec == b->st_mtim.tv_nsec;
}

int image_read_file(const char *path, uint8_t *buf, size_t cap, size_t *len, char *err, size_t err_len)
{
    struct stat before, opened, after;
    *len = 0;
    /* Looked at before it is opened: a FIFO would block the open and the
     * read until a writer came. */
    if (stat(path, &before) != 0) {
        snprintf(err, err_len, "cannot open: %s", strerror(errno));
        return -1;
    }
    if (S_ISDIR(before.st_mode)) {
        snprintf(err, err_len, "cannot read: %s (an image is a file)", strerror(EISDIR));
        return -1;
    }
    if (!S_ISREG(before.st_mode)) {
        snprintf(err, err_len, "not a regular file (%s)", file_kind(before.st_mode));
        return -1;
    }
    if (before.st_size == 0) {
        snprintf(err, err_len, "empty file (0 bytes), not an image");
        return -1;
    }
    /* O_NONBLOCK: should the name have become a FIFO since, the open does
     * not wait for a writer (and fstat refuses it) */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        snprintf(err, err_len, "cannot open: %s", strerror(errno));
        return -1;
    }
    if (fstat(fd, &opened) != 0 || !same_file_state(&before, &opened) || !S_ISREG(opened.st_mode)) {
        close(fd);
        snprintf(err, err_len, "changed while it was read (replaced); try again");
        return -1;
    }
    size_t n = 0;
    while (n < cap) {
        ssize_t r = read(fd, buf + n, cap - n);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) {
            int e = errno;
            close(fd);
            snprintf(err, err_len, "read error: %s", strerror(e));
            return -1;
        }
        if (r == 0) break;
        n += (size_t)r;
    }
    if (image_read_hook) image_read_hook(path);
    int changed = fstat(fd, &after) != 0 || !same_file_state(&opened, &after) ||
                  (n < cap && (off_t)n != after.st_size);
    close(fd);
    if (changed) {
        snprintf(err, err_len, "changed while it was read (size or modification time differ); try again");
        return -1;
    }
    *len = n;
    return 0;
}

int image_load(const uint8_t *buf, size_t len, size_t cap, const char *name, uint32_t base,
               uint32_t flash_size, struct pb_image *img, char *err, size_t err_len)
{
    img->data = img->used = NULL;
    /* a .uf2 name is a promise: a damaged UF2 is never flashed as raw bytes */
    int is_uf2 = image_name_is_uf2(name) || image_is_uf2(buf, len);
    if (is_uf2 && !image_is_uf2(buf, len))
        return image_from_uf2(buf, len, flash_size, img, err, err_len);
    /* a UF2 block carries 256 of its 512 bytes */
    if (len >= cap || len > (is_uf2 ? 2 * (size_t)flash_size : (size_t)flash_size)) {
        snprintf(err, err_len, "%s%zu bytes, more than %u KB of flash can hold (--flash-size)",
                 len >= cap ? "over " : "", len, (unsigned)(flash_size / 1024));
        return -1;
    }
    return is_uf2 ? image_from_uf2(buf, len, flash_size, img, err, err_len)
                  : image_from_bin(buf, len, base, flash_size, img, err, err_len);
}
