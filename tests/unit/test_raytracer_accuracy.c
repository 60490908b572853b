/* SPDX-License-Identifier: MIT */
/* test_raytracer_accuracy.c — fixed and float against the double build.
 *
 * raytracer-02 … 06 at 240x240 and 600x600: at least 99% of pixels with
 * every channel within 2 levels, PSNR of at least 45 dB (fixed point: at
 * least its floor below, half a decibel under what the sphere test's exact
 * quadratic measures), and shadow decisions on primary hits (which lights
 * are shadowed) different on no more than 0.1% of the pixels both builds
 * hit. Counts the primary rays' decisions (item hit, lights shadowed) that
 * differ from double's and how many lie below the mode's resolution
 * (count_decisions); fixed point may not add any beyond it. Fixed point runs
 * at Q15.16 and, where the format analysis picks another for the scene
 * (raytracer-02 … 04: Q14.17), at that one too. Also reports the double build's
 * robust formulation against its book formulation.
 * Usage: test_raytracer_accuracy [sizes...] (default 240 600). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "rt_acc_api.h"

struct acc {
    double within2, psnr, shadow_diff;
    int max_err;
};

static struct acc compare(const uint8_t *ref, const uint8_t *img, const uint8_t *pref, const uint8_t *pimg, int w,
                          int h)
{
    struct acc a = { 0, 0, 0, 0 };
    size_t n = (size_t)w * h, ok = 0, hits = 0, sdiff = 0;
    double se = 0;
    for (size_t i = 0; i < n; i++) {
        int good = 1;
        for (int c = 0; c < 3; c++) {
            int d = abs((int)ref[3 * i + c] - (int)img[3 * i + c]);
            se += (double)d * d;
            if (d > 2) good = 0;
            if (d > a.max_err) a.max_err = d;
        }
        ok += (size_t)good;
        if (!good && getenv("RT_ACC_VERBOSE"))
            printf("#   pixel (%zu, %zu): ref %d %d %d got %d %d %d\n", i % (size_t)w, i / (size_t)w, ref[3 * i],
                   ref[3 * i + 1], ref[3 * i + 2], img[3 * i], img[3 * i + 1], img[3 * i + 2]);
        if (pref && pref[i] != 0x80 && pimg[i] != 0x80) {
            hits++;
            sdiff += pref[i] != pimg[i];
        }
    }
    a.within2 = 100.0 * (double)ok / (double)n;
    double mse = se / (3.0 * (double)n);
    a.psnr = mse == 0 ? 99.0 : 10.0 * log10(255.0 * 255.0 / mse);
    a.shadow_diff = hits ? 100.0 * (double)sdiff / (double)hits : 0;
    return a;
}

/* Decisions (which item is hit, which lights are shadowed) of the primary
 * rays that differ from double's, and how many of them double itself takes
 * as the mode does when its camera moves by the mode's resolution (±res
 * along x, y or z: six renders): those lie below the format's resolution. */
struct decisions {
    size_t off, below;
};

/* One render's primary decisions: shadow bits and items, w*h each. */
struct prims {
    uint8_t *shadow;
    int16_t *item;
};

static int prim_differ(const struct prims *a, const struct prims *b, size_t i)
{
    return a->shadow[i] != b->shadow[i] || a->item[i] != b->item[i];
}

/* Renders raytracer-0sc with api (formulation f; camera moved by d when
 * not NULL), its primary decisions into *p. */
static int render_prims(const struct rtacc_api *api, int sc, int w, int h, int f, const double *d, uint8_t *rgb,
                        struct prims *p)
{
    *api->item_probe = p->item;
    int rc = d ? api->render_moved(sc, w, h, d[0], d[1], d[2], rgb, p->shadow)
               : api->render_book(sc, w, h, f, rgb, p->shadow);
    *api->item_probe = NULL;
    return rc;
}

static struct decisions count_decisions(const struct rtacc_api *mode, int sc, int w, int h, const struct prims *ref,
                                        const struct prims *img)
{
    struct decisions d = { 0, 0 };
    size_t n = (size_t)w * h;
    for (size_t i = 0; i < n; i++) d.off += (size_t)prim_differ(ref, img, i);
    if (d.off == 0) return d;
    uint8_t *rgb = malloc(3 * n), *ok = calloc(n, 1);
    struct prims m = { malloc(n), malloc(n * sizeof(int16_t)) };
    for (int k = 0; k < 6; k++) {
        double v = (k & 1) ? -mode->resolution : mode->resolution;
        double mv[3] = { k / 2 == 0 ? v : 0, k / 2 == 1 ? v : 0, k / 2 == 2 ? v : 0 };
        render_prims(&rtacc_double, sc, w, h, 0, mv, rgb, &m);
        for (size_t i = 0; i < n; i++)
            if (prim_differ(ref, img, i) && !prim_differ(&m, img, i)) ok[i] = 1;
    }
    for (size_t i = 0; i < n; i++) {
        d.below += ok[i];
        if (prim_differ(ref, img, i) && getenv("RT_ACC_VERBOSE"))
            printf("#   decision (%zu, %zu): double item %d shadows %#x, %s item %d shadows %#x%s\n", i % (size_t)w,
                   i / (size_t)w, ref->item[i], ref->shadow[i], mode->numeric, img->item[i], img->shadow[i],
                   ok[i] ? " (below resolution)" : "");
    }
    free(rgb);
    free(ok);
    free(m.shadow);
    free(m.item);
    return d;
}

/* Fixed point's PSNR floor for raytracer-0`sc` at size w, at NUM_FRAC frac
 * (45 dB at other sizes): half a decibel under what it measures. */
static double fixed_floor(int sc, int w, int frac)
{
    static const double f240[7] = { 0, 0, 82.1, 81.6, 82.3, 68.8, 66.2 };
    static const double f600[7] = { 0, 0, 81.8, 81.0, 81.1, 70.8, 68.2 };
    static const double q17_240[7] = { 0, 0, 83.7, 83.3, 65.7, 45, 45 };
    static const double q17_600[7] = { 0, 0, 82.5, 82.3, 67.4, 45, 45 };
    if (w == 240) return frac == 17 ? q17_240[sc] : f240[sc];
    if (w == 600) return frac == 17 ? q17_600[sc] : f600[sc];
    return 45.0;
}

/* Fixed point's decisions off beyond its resolution, at most (240x240 and
 * 600x600): raytracer-04 and 05's are self-shadowing rays at the
 * terminator whose root 2b/a lies within one step of epsilon (a light at
 * n.l = -0.003, no visible effect), which moving the camera does not
 * reproduce; 06's, reflections. A change that adds one fails here. */
static size_t fixed_beyond(int sc, int w)
{
    static const size_t b240[7] = { 0, 0, 0, 0, 1, 1, 1 };
    static const size_t b600[7] = { 0, 0, 0, 0, 2, 2, 4 };
    return w == 240 ? b240[sc] : (w == 600 ? b600[sc] : (size_t)-1);
}

int main(int argc, char **argv)
{
    int sizes[4] = { 240, 600 }, nsizes = 2;
    if (argc > 1) {
        nsizes = 0;
        for (int i = 1; i < argc && nsizes < 4; i++) sizes[nsizes++] = atoi(argv[i]);
    }
    for (int si = 0; si < nsizes; si++) {
        int w = sizes[si], h = sizes[si];
        size_t n = (size_t)w * h;
        uint8_t *ref = malloc(3 * n), *img = malloc(3 * n);
        struct prims pref = { malloc(n), malloc(n * sizeof(int16_t)) }, pimg = { malloc(n), malloc(n * sizeof(int16_t)) };
        for (int sc = 2; sc <= 6; sc++) {
            if (render_prims(&rtacc_double, sc, w, h, 0, NULL, ref, &pref) != 0) {
                check(0, "render_double", "raytracer-0%d failed", sc);
                continue;
            }
            /* fixed point at Q15.16 and at the scene's own format, float */
            int own = rtacc_double.scene_frac(sc, w, h);
            const struct rtacc_api *modes[3] = { &rtacc_fixed, &rtacc_float, own == 17 ? &rtacc_fixed17 : NULL };
            const int fracs[3] = { 16, 0, 17 };
            for (int m = 0; m < 3; m++) {
                if (!modes[m]) continue;
                uint32_t sat0 = *modes[m]->saturations;
                int rc = render_prims(modes[m], sc, w, h, 0, NULL, img, &pimg);
                struct acc a = compare(ref, img, pref.shadow, pimg.shadow, w, h);
                struct decisions dc = count_decisions(modes[m], sc, w, h, &pref, &pimg);
                char name[96];
                snprintf(name, sizeof name, "accuracy_%s%s_raytracer-0%d_%dx%d", modes[m]->numeric,
                         m == 2 ? "17" : "", sc, w, h);
                printf("# %-40s within2 %.3f%%  psnr %.2f dB  max_err %d  shadow_diff %.4f%%  saturations %u  "
                       "decisions off %zu (%zu below resolution)%s\n",
                       name, a.within2, a.psnr, a.max_err, a.shadow_diff, *modes[m]->saturations - sat0, dc.off,
                       dc.below, fracs[m] == own ? "  [the scene's format]" : "");
                double floor_db = m != 1 ? fixed_floor(sc, w, fracs[m]) : 45.0;
                size_t beyond = dc.off - dc.below, beyond_max = m != 1 ? fixed_beyond(sc, w) : (size_t)-1;
                check(beyond <= beyond_max, name, "%zu decisions off beyond the resolution (at most %zu)", beyond,
                      beyond_max);
                check(rc == 0 && a.within2 >= 99.0 && a.psnr >= floor_db && a.shadow_diff <= 0.1, name,
                      "within2 %.3f%% psnr %.2f dB (floor %.1f) shadow_diff %.4f%%", a.within2, a.psnr, floor_db,
                      a.shadow_diff);
            }
            /* the robust formulation in double, against the book's */
            render_prims(&rtacc_double, sc, w, h, 2, NULL, img, &pimg);
            struct acc a = compare(ref, img, pref.shadow, pimg.shadow, w, h);
            printf("# %-40s within2 %.3f%%  psnr %.2f dB  max_err %d  shadow_diff %.4f%%\n", "robust-double", a.within2,
                   a.psnr, a.max_err, a.shadow_diff);
        }
        free(ref);
        free(img);
        free(pref.shadow);
        free(pref.item);
        free(pimg.shadow);
        free(pimg.item);
    }
    return check_exit();
}
