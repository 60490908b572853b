/* SPDX-License-Identifier: MIT */
/* image.h — loading a flash image from a UF2 or a flat .bin file. */
#ifndef FLASHER_IMAGE_H
#define FLASHER_IMAGE_H

#include <stddef.h>
#include <stdint.h>
#include "picoboot.h"

#define UF2_FAMILY_RP2040 0xE48BFF56u

/* 1 when buf starts with a UF2 block (both start magic numbers): the
 * format is decided by the content, not by the file name. */
int image_is_uf2(const uint8_t *buf, size_t len);

/* Parses UF2 bytes: every block must have the three magic numbers, a 256-
 * byte payload at a page-aligned address inside the first flash_size bytes
 * of flash, consistent block counts, no page twice, and (when flagged) the
 * RP2040 family ID; blocks of other families are skipped (a file with none
 * for the RP2040 is refused). The image spans the lowest to the highest
 * block; pages between blocks (a sparse image) are 0xFF, i.e. erased.
 * Returns 0, or -1 with a one-line reason in err. img->data is malloc'ed. */
int image_from_uf2(const uint8_t *buf, size_t len, uint32_t flash_size, struct pb_image *img, char *err,
                   size_t err_len);

/* A flat binary placed at addr, padded to a page with 0xFF; it must end
 * inside the first flash_size bytes of flash. */
int image_from_bin(const uint8_t *buf, size_t len, uint32_t addr, uint32_t flash_size, struct pb_image *img,
                   char *err, size_t err_len);

void image_free(struct pb_image *img);

#endif
