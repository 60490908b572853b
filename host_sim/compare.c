/* SPDX-License-Identifier: MIT */
/* compare.c — PSNR, SSIM and per-pixel difference counts. */
#include <math.h>
#include <stdlib.h>
#include "compare.h"

static double luma(const uint8_t *p) { return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]; }

/* SSIM (Wang et al. 2004) with the usual constants for 8-bit data, over
 * uniform 8x8 windows every 4 pixels; images smaller than a window use one
 * window of the whole image. */
static double ssim_luma(const uint8_t *a, const uint8_t *b, unsigned w, unsigned h)
{
    const double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
    unsigned win = w < 8 || h < 8 ? (w < h ? w : h) : 8, step = win < 8 ? win : 4;
    if (win == 0) return 1.0;
    double sum = 0;
    unsigned count = 0;
    for (unsigned y0 = 0; y0 + win <= h; y0 += step)
        for (unsigned x0 = 0; x0 + win <= w; x0 += step) {
            double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, n = (double)win * win;
            for (unsigned y = y0; y < y0 + win; y++)
                for (unsigned x = x0; x < x0 + win; x++) {
                    size_t i = ((size_t)y * w + x) * 3;
                    double la = luma(a + i), lb = luma(b + i);
                    sa += la; sb += lb; saa += la * la; sbb += lb * lb; sab += la * lb;
                }
            double ma = sa / n, mb = sb / n;
            double va = saa / n - ma * ma, vb = sbb / n - mb * mb, cov = sab / n - ma * mb;
            sum += ((2 * ma * mb + c1) * (2 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
            count++;
        }
    return count ? sum / count : 1.0;
}

void compare_rgb888(const uint8_t *a, const uint8_t *b, unsigned w, unsigned h,
                    struct compare_result *r)
{
    size_t npx = (size_t)w * h, ndiff = 0, nwithin = 0;
    double se = 0;
    int mx = 0;
    for (size_t p = 0; p < npx; p++) {
        int worst = 0;
        for (int c = 0; c < 3; c++) {
            int d = abs((int)a[3 * p + c] - (int)b[3 * p + c]);
            se += (double)d * d;
            if (d > worst) worst = d;
        }
        if (worst > mx) mx = worst;
        if (worst) ndiff++;
        if (worst <= 2) nwithin++;
    }
    r->psnr = se == 0 ? INFINITY : 10.0 * log10(255.0 * 255.0 * 3.0 * (double)npx / se);
    r->max_err = mx;
    r->pct_diff = npx ? 100.0 * (double)ndiff / (double)npx : 0;
    r->pct_within2 = npx ? 100.0 * (double)nwithin / (double)npx : 100;
    r->ssim = ssim_luma(a, b, w, h);
}
