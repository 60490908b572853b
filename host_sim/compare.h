/* SPDX-License-Identifier: MIT */
/* compare.h — image accuracy figures against a reference (the double build). */
#ifndef COMPARE_H
#define COMPARE_H

#include <stddef.h>
#include <stdint.h>

struct compare_result {
    double psnr;        /* dB over the three 8-bit channels; INFINITY when identical */
    double ssim;        /* mean SSIM of the luma, 8x8 windows with stride 4, in [-1, 1] */
    int max_err;        /* largest difference of one channel, 0..255 */
    double pct_diff;    /* percent of pixels with any channel different */
    double pct_within2; /* percent of pixels with every channel within 2 levels */
};

/* a and b are w*h RGB888 images (3 bytes a pixel, row-major). */
void compare_rgb888(const uint8_t *a, const uint8_t *b, unsigned w, unsigned h,
                    struct compare_result *r);

#endif
