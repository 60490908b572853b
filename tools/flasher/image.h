/* SPDX-License-Identifier: MIT */
/* image.h — loading a flash image from a UF2 or a flat .bin file. */
#ifndef FLASHER_IMAGE_H
#define FLASHER_IMAGE_H

#include <stddef.h>
#include <stdint.h>
#include "picoboot.h"

#define UF2_FAMILY_RP2040 0xE48BFF56u

/* 1 when buf starts with a UF2 block (both start magic numbers). */
int image_is_uf2(const uint8_t *buf, size_t len);

/* 1 when the file name ends in ".uf2", in any case. */
int image_name_is_uf2(const char *name);

/* Reads the whole of a regular file into buf (at most cap bytes; a file of
 * cap bytes or more reads as cap). Refused with a one-line reason in err
 * (-1): a missing or unreadable file (strerror's reason), a directory, a
 * FIFO, device or socket (never opened for a blocking read), an empty file,
 * and a file whose size or modification time differ after the read from
 * before it (it changed while it was read). */
int image_read_file(const char *path, uint8_t *buf, size_t cap, size_t *len, char *err, size_t err_len);

/* Called by image_read_file between the read and the second look at the
 * file (tests change the file there); NULL normally. */
extern void (*image_read_hook)(const char *path);

/* The image in a file's bytes: a name ending in .uf2 (any case) must hold
 * a valid UF2; any other name is a UF2 when its content starts with a UF2
 * block, else a flat binary placed at base. Also refuses bytes that more
 * than flash_size can hold (len == the reader's cap counts as larger).
 * 0, or -1 with a one-line reason in err. */
int image_load(const uint8_t *buf, size_t len, size_t cap, const char *name, uint32_t base,
               uint32_t flash_size, struct pb_image *img, char *err, size_t err_len);

/* Parses UF2 bytes: every block must have the three magic numbers, a 256-
 * byte payload at a page-aligned address inside the first flash_size bytes
 * of flash, consistent block counts, no block number twice (two images
 * concatenated are not one), no page twice, and (when flagged) the
 * RP2040 family ID; blocks of other families are skipped (a file with none
 * for the RP2040 is refused). The image spans the lowest to the highest
 * block; pages between blocks (a sparse image) are 0xFF and marked unused
 * (img->used), so they are neither written nor erased.
 * Returns 0, or -1 with a one-line reason in err. img->data and img->used
 * are malloc'ed. */
int image_from_uf2(const uint8_t *buf, size_t len, uint32_t flash_size, struct pb_image *img, char *err,
                   size_t err_len);

/* A flat binary placed at addr, padded to a page with 0xFF (every page
 * used); it must end inside the first flash_size bytes of flash. */
int image_from_bin(const uint8_t *buf, size_t len, uint32_t addr, uint32_t flash_size, struct pb_image *img,
                   char *err, size_t err_len);

void image_free(struct pb_image *img);

#endif
