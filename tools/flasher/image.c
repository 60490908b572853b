/* SPDX-License-Identifier: MIT */
/* image.c — UF2 and .bin images for the flasher. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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
    img->data = NULL;
    if (flash_size > PB_FLASH_SIZE) flash_size = PB_FLASH_SIZE;
    if (len == 0 || len % 512) {
        snprintf(err, err_len, "not a UF2 file: %zu bytes is not a multiple of 512", len);
        return -1;
    }
    /* one bit per page of flash: a page given twice (duplicate or
     * overlapping blocks) would make the image depend on block order */
    uint8_t *seen = calloc(flash_size / PB_PAGE / 8 + 1, 1);
    if (!seen) {
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
            return -1;
        }
        if (flags & UF2_FLAG_NOT_MAIN) continue;
        if ((flags & UF2_FLAG_FAMILY) && family != UF2_FAMILY_RP2040) continue;
        if (size != PB_PAGE || addr % PB_PAGE) {
            snprintf(err, err_len, "UF2 block %zu: %u bytes at 0x%08x, expected 256 at a page boundary",
                     b, (unsigned)size, (unsigned)addr);
            free(seen);
            return -1;
        }
        if (!in_flash(addr, size, flash_size)) {
            snprintf(err, err_len, "UF2 block %zu: address 0x%08x is outside the %u KB of flash (--flash-size)",
                     b, (unsigned)addr, (unsigned)(flash_size / 1024));
            free(seen);
            return -1;
        }
        if (total == 0 || bno >= total || (count && total != count)) {
            snprintf(err, err_len, "UF2 block %zu: block number %u of %u is inconsistent", b,
                     (unsigned)bno, (unsigned)total);
            free(seen);
            return -1;
        }
        uint32_t page = (addr - PB_FLASH_BASE) / PB_PAGE;
        if (seen[page / 8] & (1u << (page % 8))) {
            snprintf(err, err_len, "UF2 block %zu: page 0x%08x is given twice (duplicate or overlapping blocks)",
                     b, (unsigned)addr);
            free(seen);
            return -1;
        }
        seen[page / 8] |= (uint8_t)(1u << (page % 8));
        count = total;
        nblocks++;
        if (addr < lo) lo = addr;
        if (addr + size > hi) hi = addr + size;
    }
    free(seen);
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
    if (!img->data) {
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
    }
    return 0;
}

int image_from_bin(const uint8_t *buf, size_t len, uint32_t addr, uint32_t flash_size, struct pb_image *img,
                   char *err, size_t err_len)
{
    img->data = NULL;
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
    img->data = NULL;
}
