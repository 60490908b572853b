/* SPDX-License-Identifier: MIT */
/* test_raytracer.c — the ray tracer in one numeric mode (built per mode).
 *
 * Double mode: the book demos' reference digests (tests/data/book_digests.txt),
 * SHA-256 over the 600x600 RGBA buffer, every pixel written (A = 255).
 * Every mode: strips equal one full frame; the robust sphere test on the
 * radius-5000 ground; CSG, planes, triangles, refraction; each chapter-5
 * optimisation keeps the image (or stays close) and does less work.
 * Scenes are the repository's scene files, parsed in the mode under test. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "sha256.h"
#include "book_digests.h"
#include "rt_render.h"
#include "scene_files.h"
#include "scene_format.h"

static int is_double(void) { return strcmp(NUM_NAME, "double") == 0; }

/* raytracer-0n of the book (firmware/scenes/book) */
static struct scene *rt_book(int n)
{
    char name[32];
    snprintf(name, sizeof name, "raytracer-0%d", n);
    return book_scene(name);
}

/* 64 small spheres on a plane: many objects (the bounding-sphere hierarchy) */
static struct scene *rt_grid64(void) { return scene_file("firmware/scenes/bench/grid64.scene"); }

/* chapter 5 in one scene (plane, triangle, CSG, glass), its speed-ups and
 * supersampling off: each test switches on what it measures */
static struct scene *rt_ch5(void)
{
    struct scene *s = scene_file("firmware/scenes/demo/raytracer-ch5.scene");
    s->rt.supersample = 1;
    s->rt.adaptive_ss = s->rt.shadow_any_hit = s->rt.shadow_cache = 0;
    return s;
}

static void digest(const uint8_t *rgb888, int w, int h, char hex[65])
{
    struct sha256 s;
    sha256_init(&s);
    for (int i = 0; i < w * h; i++) {
        uint8_t px[4] = { rgb888[3 * i], rgb888[3 * i + 1], rgb888[3 * i + 2], 255 };
        sha256_update(&s, px, 4);
    }
    sha256_hex(&s, hex);
}

static int max_diff(const uint8_t *a, const uint8_t *b, size_t n, size_t *count_over2)
{
    int m = 0;
    size_t c = 0;
    for (size_t i = 0; i < n; i++) {
        int d = abs((int)a[i] - (int)b[i]);
        if (d > m) m = d;
        if (d > 2) c++;
    }
    if (count_over2) *count_over2 = c;
    return m;
}

static void test_sha256(void)
{
    struct sha256 s;
    char hex[65];
    sha256_init(&s);
    sha256_update(&s, "abc", 3);
    sha256_hex(&s, hex);
    check(strcmp(hex, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad") == 0,
          "sha256_known_answer", "got %s", hex);
}

/* The book's demos and their non-default modes: the reference digests. */
static void test_book_digests(void)
{
    struct book_digest refs[BOOK_DIGESTS_MAX];
    int n = book_digests_read(refs, BOOK_DIGESTS_MAX), tested = 0;
    uint8_t *img = malloc(600 * 600 * 3);
    for (int i = 0; i < n; i++) {
        if (strncmp(refs[i].scene, "raytracer-", 10) || !refs[i].digest[0]) continue;
        struct scene *s = book_scene(refs[i].scene);
        char hex[65] = "", name[160];
        snprintf(name, sizeof name, "book_digest_%s%s%s", refs[i].scene, refs[i].options[0] ? "_" : "", refs[i].options);
        if (scene_options(s, refs[i].options)) {
            check(0, name, "unknown option in %s", refs[i].options);
            continue;
        }
        memset(img, 0, 600 * 600 * 3);
        int rc = rt_render(s, 600, 600, 600, img, NULL, NULL);
        digest(img, 600, 600, hex);
        check(rc == 0 && strncmp(hex, refs[i].digest, 16) == 0, name, "rc %d, sha256 %.16s, want %s", rc, hex,
              refs[i].digest);
        tested++;
    }
    check(tested > 0, "book_digests_raytracer_read", "no raytracer line in %s", BOOK_DIGESTS_FILE);
    free(img);
}

/* Strips of any height give the same pixels as one full-frame strip. */
static void test_strips(void)
{
    int w = 96, h = 72;
    uint8_t *a = malloc((size_t)w * h * 3), *b = malloc((size_t)w * h * 3);
    struct scene *sc[3] = { rt_book(5), rt_book(6), rt_ch5() };
    for (int k = 0; k < 3; k++) {
        for (int mode = 0; mode < 5; mode++) {
            struct scene *s = sc[k];
            s->rt.subsample = mode == 1 ? 3 : 1;
            s->rt.adaptive_ss = mode == 2;
            s->rt.supersample = mode == 2 ? 3 : 1;
            s->rt.adaptive_subsample = mode == 3 ? 2 : (mode == 4 ? 5 : 0);
            int ra = rt_render(s, w, h, h, a, NULL, NULL);
            int rb = rt_render(s, w, h, 7, b, NULL, NULL);
            char name[80];
            snprintf(name, sizeof name, "strips_equal_full_frame_%s_%s", s->name,
                     mode == 0 ? "plain" : mode == 1 ? "subsample" : mode == 2 ? "adaptive" :
                     mode == 3 ? "adaptive_subsample2" : "adaptive_subsample5");
            check(ra == 0 && rb == 0 && memcmp(a, b, (size_t)w * h * 3) == 0, name, "strip render differs");
            s->rt.subsample = 1;
            s->rt.adaptive_ss = 0;
            s->rt.supersample = 1;
            s->rt.adaptive_subsample = 0;
        }
    }
    free(a);
    free(b);
}

/* Progressive display: a coarse pass of 8x8 blocks, then the full pass over
 * the same context gives exactly the frame rendered without it; adaptive
 * subsampling traces fewer rays and stays close to the full render. */
static void test_progressive(void)
{
    int w = 100, h = 75, strip = 16;
    size_t n = (size_t)w * h * 3;
    uint8_t *ref = malloc(n), *img = malloc(n), *coarse = malloc(n);
    struct scene *s = rt_book(5);
    struct rt_run r0, r1;
    rt_render(s, w, h, strip, ref, NULL, &r0);
    size_t need = render_work_size(s, (uint16_t)w, (uint16_t)h, (uint16_t)strip);
    void *work = aligned_alloc(8, (need + 7) / 8 * 8);
    uint16_t *px = malloc(sizeof(uint16_t) * (size_t)w * strip);
    struct render_ctx ctx;
    int ok = render_init(&ctx, s, (uint16_t)w, (uint16_t)h, (uint16_t)strip, work, need) == 0 &&
             render_begin_frame(&ctx, 0) == 0;
    uint32_t rays_coarse = 0;
    for (int pass = 0; pass < 2 && ok; pass++) {
        struct render_stats st = { 0 };
        ok = render_set_pass(&ctx, pass == 0 ? RENDER_PASS_COARSE : RENDER_PASS_FULL) == 0;
        for (int y0 = 0; y0 < h && ok; y0 += strip) {
            struct render_target t = { (uint16_t)w, (uint16_t)h, (uint16_t)y0,
                                       (uint16_t)(y0 + strip < h ? y0 + strip : h), px,
                                       (pass ? img : coarse) + (size_t)3 * w * y0, NULL };
            ok = render_strip(&ctx, &t, &st) == 0;
        }
        if (pass == 0) rays_coarse = st.rays;
    }
    /* a block shows one colour */
    int blocks_flat = 1;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            if (memcmp(coarse + 3 * ((size_t)y * w + x), coarse + 3 * ((size_t)(y - y % 8) * w + (x - x % 8)), 3))
                blocks_flat = 0;
    check(ok && blocks_flat && memcmp(ref, img, n) == 0 && rays_coarse * 20 < r0.rays, "progressive_coarse_then_full_equals_full",
          "ok %d, blocks flat %d, coarse rays %u of %u", ok, blocks_flat, rays_coarse, r0.rays);
    check(render_set_pass(&ctx, 7) == -1, "progressive_unknown_pass_refused", "accepted");
    free(work);
    free(px);

    s->rt.adaptive_subsample = 2;
    rt_render(s, w, h, strip, img, NULL, &r1);
    size_t over;
    int md = max_diff(ref, img, n, &over);
    check(r1.primary_rays < r0.primary_rays * 3 / 4 && over < n / 50, "adaptive_subsample_fewer_rays_close",
          "primary rays %u of %u, %zu channels off by > 2 (max %d)", r1.primary_rays, r0.primary_rays, over, md);
    s->rt.adaptive_subsample = 0;
    free(ref);
    free(img);
    free(coarse);
}

/* A minimal state around a scene to call the intersection routines. */
struct probe_ctx {
    struct render_ctx ctx;
    void *work;
};

static struct rt_state *open_state(struct probe_ctx *p, const struct scene *s)
{
    size_t need = render_work_size(s, 64, 64, 64);
    p->work = aligned_alloc(8, (need + 7) / 8 * 8);
    if (render_init(&p->ctx, s, 64, 64, 64, p->work, need) != 0) return NULL;
    render_begin_frame(&p->ctx, 0);
    return rt_state_of(p->ctx.work);
}

static double dd(num v) { return num_to_double(v); }

/* The radius-5000 ground sphere: robust roots against the exact ones. */
static void test_ground_sphere(void)
{
    struct scene *s = rt_book(5);
    uint8_t saved = s->rt.formulation;
    s->rt.formulation = 2;
    struct probe_ctx p;
    struct rt_state *rt = open_state(&p, s);
    double worst = 0;
    int misses = 0;
    /* primary rays toward the ground, shadow-like rays, and long reflected rays */
    static const double rays[][6] = {
        { 0, 0, 0, 0.1, -0.3, 1 },    { 0, 0, 0, -0.4, -0.05, 1 }, { 0, 0, 0, 0.45, -0.011, 1 },
        { 2, 1, 0, 0.2, -0.9, 0.3 },  { 0.5, 0.9, 3.2, 0.01, -0.002, 1.2 },
        { 3, 0, 1, -0.7, -0.15, 0.7 }, { -1.9, 0.95, 4.1, 700, -1, 900 },
    };
    for (size_t i = 0; i < sizeof rays / sizeof rays[0]; i++) {
        const double *r = rays[i];
        struct rt_ray ray = rt_make_ray(v3_make(num_from_double(r[0]), num_from_double(r[1]), num_from_double(r[2])),
                                        v3_make(num_from_double(r[3]), num_from_double(r[4]), num_from_double(r[5])), -1, 0);
        /* exact roots in double from the rounded inputs */
        double o[3] = { dd(ray.o.x), dd(ray.o.y) + 5001, dd(ray.o.z) }, d[3] = { dd(ray.d.x), dd(ray.d.y), dd(ray.d.z) };
        long double a = (long double)d[0] * d[0] + (long double)d[1] * d[1] + (long double)d[2] * d[2];
        long double b = -((long double)o[0] * d[0] + (long double)o[1] * d[1] + (long double)o[2] * d[2]);
        long double c = (long double)o[0] * o[0] + (long double)o[1] * o[1] + (long double)o[2] * o[2] - 25000000.0L;
        long double disc = b * b - a * c;
        num t1, t2;
        int hit = rt_intersect_ray_sphere(rt, 3, &ray, &t1, &t2, NULL);
        if ((disc >= 0) != (hit != 0)) { misses++; continue; }
        if (!hit) continue;
        long double q = b + (b >= 0 ? sqrtl(disc) : -sqrtl(disc));
        long double near = fminl(q / a, c / q);
        /* error relative to the distance travelled, plus the resolution */
        double err = fabs((double)(dd(t2) - near)) / (1e-4 + fabs((double)near));
        if (fabs((double)near) < 16000 && err > worst) worst = err;
    }
    check(misses == 0 && worst < (strcmp(NUM_NAME, "float") == 0 ? 1e-3 : 2e-4), "robust_sphere_ground_radius_5000", "misses %d, worst relative error %g",
          misses, worst);
    /* analytic self-intersection: leaving the ground sphere upward finds nothing */
    struct rt_ray up = rt_make_ray(v3_make(NUM_ZERO, NUM_C(-1.0), NUM_ZERO), v3_make(NUM_C(0.3), NUM_C(1.0), NUM_C(-0.2)), 3, 0);
    struct rt_hit hit = { .t = 0, .item = -1, .surf = -1 };
    check(!rt_closest_intersection(rt, &up, NUM_ZERO, NUM_MAX, &hit, 0), "robust_self_no_acne_at_epsilon_zero",
          "upward ray from the ground hit item %d at t=%g", hit.item, dd(hit.t));
    free(p.work);
    s->rt.formulation = saved;
}

static void test_csg_planes_triangles(void)
{
    static struct rt_object o[6];
    static struct rt_csg g[1];
    struct scene *s = rt_book(2);
    struct scene save = *s;
    const struct rt_object *so = s->objects;
    o[0] = so[0];
    o[0].center = v3_make(NUM_ZERO, NUM_ZERO, NUM_C(5.0));
    o[0].csg_only = 1;
    o[1] = o[0];
    o[1].center = v3_make(NUM_ZERO, NUM_ZERO, NUM_C(4.5));
    s->objects = o;
    s->nobjects = 2;
    s->csg = g;
    s->ncsg = 1;
    static const struct { uint8_t op; double bz; double want; int surf; double nz; } cases[] = {
        { CSG_UNION, 4.5, 3.5, 1, -1 },        /* A [4,6] u B [3.5,5.5]: enter B at 3.5 */
        { CSG_INTERSECTION, 4.5, 4.0, 0, -1 }, /* [4, 5.5]: enter by A */
        { CSG_DIFFERENCE, 4.5, 5.5, 1, -1 },   /* [5.5, 6]: B's inside faces the viewer */
        { CSG_DIFFERENCE, 7.5, 4.0, 0, -1 },   /* B [6.5,8.5] misses A: A as is */
        { CSG_DIFFERENCE, 5.0, -1, -1, 0 },    /* B = A: nothing left */
    };
    for (int fm = 1; fm <= 2; fm++) {
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            o[1].center = v3_make(NUM_ZERO, NUM_ZERO, num_from_double(cases[i].bz));
            g[0] = (struct rt_csg){ cases[i].op, 0, 1 };
            s->rt.formulation = (uint8_t)fm;
            struct probe_ctx p;
            struct rt_state *rt = open_state(&p, s);
            struct rt_ray ray = rt_make_ray(v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO), v3_make(NUM_ZERO, NUM_ZERO, NUM_ONE), -1, 0);
            struct rt_hit hit;
            int got = rt_closest_intersection(rt, &ray, NUM_C(1.0), NUM_MAX, &hit, 0);
            char name[64];
            snprintf(name, sizeof name, "csg_%s_%s_bz%.1f", fm == 1 ? "book" : "robust",
                     cases[i].op == CSG_UNION ? "union" : cases[i].op == CSG_INTERSECTION ? "intersection" : "difference",
                     cases[i].bz);
            if (cases[i].want < 0) {
                check(!got, name, "unexpected hit at %g", got ? dd(hit.t) : 0.0);
            } else {
                vec3 pnt = v3_make(NUM_ZERO, NUM_ZERO, got ? hit.t : NUM_ZERO);
                vec3 n = got ? rt_hit_normal(rt, &hit, &pnt) : v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
                check(got && fabs(dd(hit.t) - cases[i].want) < 1e-3 && hit.surf == cases[i].surf &&
                          fabs(dd(n.z) - cases[i].nz) < 1e-3,
                      name, "got %d t=%g surf %d nz %g", got, got ? dd(hit.t) : 0.0, hit.surf, dd(n.z));
            }
            free(p.work);
        }
    }
    /* a plane y = -1 and a triangle */
    o[0] = (struct rt_object){ 0 };
    o[0].shape = RT_PLANE;
    o[0].normal = v3_make(NUM_ZERO, NUM_ONE, NUM_ZERO);
    o[0].dist = NUM_C(-1.0);
    o[1] = (struct rt_object){ 0 };
    o[1].shape = RT_TRIANGLE;
    o[1].p[0] = v3_make(NUM_C(-1.0), NUM_C(-0.5), NUM_C(4.0));
    o[1].p[1] = v3_make(NUM_C(1.0), NUM_C(-0.5), NUM_C(4.0));
    o[1].p[2] = v3_make(NUM_ZERO, NUM_C(1.0), NUM_C(4.0));
    s->nobjects = 2;
    s->ncsg = 0;
    s->rt.formulation = 0;
    struct probe_ctx p;
    struct rt_state *rt = open_state(&p, s);
    struct rt_hit hit;
    struct rt_ray down = rt_make_ray(v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO), v3_make(NUM_ZERO, NUM_C(-0.5), NUM_ONE), -1, 0);
    int got = rt_closest_intersection(rt, &down, NUM_C(0.5), NUM_MAX, &hit, 0);
    vec3 at = v3_make(NUM_ZERO, NUM_C(-1.0), NUM_C(2.0));
    vec3 n = rt_hit_normal(rt, &hit, &at);
    check(got && hit.item == 0 && fabs(dd(hit.t) - 2.0) < 1e-4 && dd(n.y) > 0.999, "plane_hit_y_minus_1",
          "got %d item %d t=%g", got, hit.item, dd(hit.t));
    struct rt_ray fwd = rt_make_ray(v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO), v3_make(NUM_C(0.05), NUM_C(0.05), NUM_ONE), -1, 0);
    got = rt_closest_intersection(rt, &fwd, NUM_C(0.5), NUM_MAX, &hit, 0);
    at = v3_make(NUM_C(0.2), NUM_C(0.2), NUM_C(4.0));
    n = rt_hit_normal(rt, &hit, &at);
    check(got && hit.item == 1 && fabs(dd(hit.t) - 4.0) < 1e-4 && dd(n.z) < -0.999, "triangle_hit_facing_viewer",
          "got %d item %d t=%g nz=%g", got, hit.item, dd(hit.t), dd(n.z));
    struct rt_ray side = rt_make_ray(v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO), v3_make(NUM_C(0.3), NUM_C(0.2), NUM_ONE), -1, 0);
    got = rt_closest_intersection(rt, &side, NUM_C(0.5), NUM_MAX, &hit, 0);
    check(!got, "triangle_miss_outside_edge", "hit item %d", hit.item);
    free(p.work);
    *s = save;
}

static void test_refraction(void)
{
    vec3 out;
    /* entering glass (1.5) at 30 degrees: sin t = 0.5/1.5 */
    vec3 n = v3_make(NUM_ZERO, NUM_ONE, NUM_ZERO);
    vec3 d = v3_make(num_from_double(0.5), num_from_double(-0.8660254), NUM_ZERO);
    int ok = rt_refract(d, n, NUM_C(1.5), &out);
    check(ok && fabs(dd(out.x) - 1.0 / 3.0) < 1e-3 && dd(out.y) < 0, "refraction_snell_entering", "ok %d x %g", ok,
          dd(out.x));
    /* leaving glass at 60 degrees: 1.5 sin 60 > 1, total internal reflection */
    vec3 d2 = v3_make(num_from_double(0.8660254), num_from_double(0.5), NUM_ZERO);
    check(!rt_refract(d2, n, NUM_C(1.5), &out), "refraction_total_internal_reflection", "refracted");
    vec3 d3 = v3_make(num_from_double(0.5), num_from_double(0.8660254), NUM_ZERO);
    ok = rt_refract(d3, n, NUM_C(1.5), &out);
    check(ok && fabs(dd(out.x) - 0.75) < 1e-3 && dd(out.y) > 0, "refraction_snell_leaving", "ok %d x %g", ok, dd(out.x));
}

/* Each optimisation: the image it gives and the work it saves. */
static void test_optimisations(void)
{
    int w = 120, h = 120;
    size_t n = (size_t)w * h * 3;
    uint8_t *ref = malloc(n), *img = malloc(n);
    struct rt_run r0, r1;
    struct scene *s = rt_book(5);
    char name[96];

    /* the chapter-5 options measured on the plain path (the shortcuts
     * include any-hit shadow rays) */
    s->rt.no_shortcuts = 1;
    rt_render(s, w, h, 16, ref, NULL, &r0);
    s->rt.shadow_any_hit = 1;
    rt_render(s, w, h, 16, img, NULL, &r1);
    check(memcmp(ref, img, n) == 0 && r1.tests < r0.tests, "shadow_any_hit_same_image_fewer_tests",
          "tests %u -> %u", r0.tests, r1.tests);
    s->rt.shadow_cache = 1;
    struct rt_run r2;
    rt_render(s, w, h, 16, img, NULL, &r2);
    check(memcmp(ref, img, n) == 0 && r2.tests <= r1.tests, "shadow_cache_same_image", "tests %u -> %u", r1.tests,
          r2.tests);
    s->rt.shadow_any_hit = s->rt.shadow_cache = 0;

    s->rt.no_frame_cache = 1;
    rt_render(s, w, h, 16, img, NULL, &r1);
    size_t over;
    int md = max_diff(ref, img, n, &over);
    check(md <= 2, "frame_cache_off_same_image", "max diff %d", md);
    s->rt.no_frame_cache = 0;

    for (int ss = 2; ss <= 4; ss++) {
        s->rt.supersample = (uint8_t)ss;
        rt_render(s, w, h, 16, img, NULL, &r1);
        snprintf(name, sizeof name, "supersample_%d_rays_per_pixel", ss * ss);
        check(r1.primary_rays == (uint32_t)(w * h * ss * ss), name, "primary rays %u", r1.primary_rays);
    }
    s->rt.adaptive_ss = 1;
    s->rt.supersample = 3;
    rt_render(s, w, h, 16, img, NULL, &r1);
    check(r1.primary_rays > (uint32_t)(w * h) && r1.primary_rays < (uint32_t)(w * h * 3), "adaptive_supersample_refines_edges_only",
          "primary rays %u for %d pixels", r1.primary_rays, w * h);
    s->rt.adaptive_ss = 0;
    s->rt.supersample = 1;

    s->rt.subsample = 2;
    rt_render(s, w, h, 16, img, NULL, &r1);
    md = max_diff(ref, img, n, &over);
    check(r1.primary_rays < (uint32_t)(w * h * 3 / 4) && over < n / 20, "subsample_same_object_rule",
          "primary rays %u, %zu channels off by > 2", r1.primary_rays, over);
    s->rt.subsample = 1;
    s->rt.no_shortcuts = 0;

    /* bounding-sphere hierarchy on a scene of many objects */
    struct scene *g = rt_grid64();
    rt_render(g, w, h, 16, ref, NULL, &r0);
    g->rt.bvh = 1;
    rt_render(g, w, h, 16, img, NULL, &r1);
    md = max_diff(ref, img, n, &over);
    check(over == 0 && r1.tests * 3 < r0.tests, "bvh_same_image_fewer_tests", "tests %u -> %u, %zu channels off",
          r0.tests, r1.tests, over);
    g->rt.bvh = 0;
    free(ref);
    free(img);
}

/* The shortcuts (coarse rejections, exact early-outs) change no pixel. */
static void test_shortcuts_same_image(void)
{
    int w = 96, h = 72;
    size_t n = (size_t)w * h * 3;
    uint8_t *a = malloc(n), *b = malloc(n);
    struct scene *sc[] = { rt_book(2), rt_book(4), rt_book(5), rt_book(6), rt_ch5(), rt_grid64() };
    for (size_t k = 0; k < sizeof sc / sizeof sc[0]; k++) {
        for (int variant = 0; variant < 3; variant++) {
            struct scene *s = sc[k];
            struct rt_options keep = s->rt;
            if (variant == 1) { s->rt.epsilon = NUM_ZERO; s->rt.shadow_any_hit = 1; s->rt.bvh = 1; }
            if (variant == 2) { s->rt.adaptive_ss = 1; s->rt.supersample = 2; s->rt.shadow_cache = 1; }
            struct rt_run r0, r1;
            s->rt.no_shortcuts = 1;
            int ra = rt_render(s, w, h, 16, a, NULL, &r0);
            s->rt.no_shortcuts = 0;
            int rb = rt_render(s, w, h, 16, b, NULL, &r1);
            char name[96];
            snprintf(name, sizeof name, "shortcuts_same_image_%s_%d", s->name, variant);
            check(ra == 0 && rb == 0 && memcmp(a, b, n) == 0 && r1.rays == r0.rays, name,
                  "images differ (rays %u / %u)", r0.rays, r1.rays);
            s->rt = keep;
        }
    }
    free(a);
    free(b);
}

static double urand(uint32_t *st)
{
    *st = *st * 1664525u + 1013904223u;
    return (double)(*st >> 8) / 16777216.0;
}

/* rt_book(5)'s settings (lights, epsilon, depth) over the caller's n
 * objects, robust formulation, no CSG; *save keeps the scene to restore. */
static struct scene *probe_spheres_scene(struct rt_object *o, int n, struct scene *save)
{
    struct scene *s = rt_book(5);
    *save = *s;
    s->objects = o;
    s->nobjects = n;
    s->ncsg = 0;
    s->rt.formulation = 2;
    return s;
}

/* o[0] a sphere of radius r at a random centre c in a 40-unit box. */
static void random_sphere(struct rt_object *o, double r, double c[3], uint32_t *st)
{
    for (int i = 0; i < 3; i++) c[i] = (urand(st) - 0.5) * 40;
    memset(o, 0, sizeof *o);
    o[0].shape = RT_SPHERE;
    o[0].center = v3_make(num_from_double(c[0]), num_from_double(c[1]), num_from_double(c[2]));
    o[0].radius = num_from_double(r);
}

/* The primary rays' candidate lists change no pixel: raytracer-02's four
 * spheres moved to random places and sizes (0.02 .. 3, and now and then a
 * ground-sized one), seen from random turned cameras, plain, supersampled
 * and with adaptive subsampling blocks that straddle the tiles' rows. */
static void test_tiles_same_image(void)
{
    int w = 80, h = 60;
    size_t n = (size_t)w * h * 3;
    uint8_t *a = malloc(n), *b = malloc(n);
    struct scene *s = rt_book(2);
    struct rt_options keep = s->rt;
    uint32_t st = 12345;
    int bad = 0, runs = 0;
    for (int it = 0; it < 24; it++) {
        for (uint16_t i = 0; i < s->nobjects; i++) {
            struct rt_object *o = (struct rt_object *)&s->objects[i];   /* the test's own copy */
            double r = urand(&st) < 0.15 ? 200.0 + 4000.0 * urand(&st) : 0.02 + 3.0 * urand(&st);
            double z = 2.0 + 12.0 * urand(&st);
            o->center = v3_make(num_from_double((urand(&st) - 0.5) * z), num_from_double((urand(&st) - 0.5) * z),
                                num_from_double(r > 100.0 ? (urand(&st) < 0.5 ? -r - 1.5 : r + z) : z));
            o->radius = num_from_double(r);
        }
        mat3 ry = m3_rot_y_deg(num_from_double(360.0 * urand(&st)));
        s->camera.rotation = it % 3 == 0 ? m3_identity() : ry;
        s->camera.position = v3_make(num_from_double(urand(&st) - 0.5), NUM_ZERO, num_from_double(urand(&st) - 0.5));
        for (int variant = 0; variant < 3; variant++) {
            s->rt = keep;
            if (variant == 1) { s->rt.supersample = 2; s->rt.adaptive_ss = 1; }
            if (variant == 2) s->rt.adaptive_subsample = 3;
            rt_render_no_tiles = 1;
            int ra = rt_render(s, w, h, 16, a, NULL, NULL);
            rt_render_no_tiles = 0;
            int rb = rt_render(s, w, h, 16, b, NULL, NULL);
            runs++;
            if (ra != 0 || rb != 0 || memcmp(a, b, n) != 0) bad++;
        }
    }
    s->rt = keep;
    check(bad == 0, "tiles_same_image", "%d of %d random scenes differ with the tile lists", bad, runs);
    free(a);
    free(b);
}

/* The primary rays' row intervals (rt_iv_row): along a row of exact
 * directions, every column outside the proven interval is a miss of the
 * exact test (rt_quad_solve, which also rejects a sphere behind the
 * camera), for spheres of radii 0.01 .. 5000 in and around the view (some
 * behind, some holding the camera), viewports and distances d of 0.5 .. 1.5
 * and 240 or 600 rows; most rows get an interval, and a tight one. */
#if NUM_MODE == NUM_MODE_FIXED
static void test_row_intervals(void)
{
    uint32_t st = 777;
    long wrong = 0, proven = 0, rows = 0, loose = 0, inside = 0;
    for (int k = 0; k < 4000; k++) {
        int h = k % 3 ? 240 : 600, w = k % 5 ? h : h * 4 / 3;
        num vh = k % 4 ? NUM_ONE : num_from_double(0.5 + urand(&st)), dd = k % 4 ? NUM_ONE : num_from_double(0.5 + urand(&st));
        double r = exp(log(0.01) + urand(&st) * (log(5000.0) - log(0.01)));
        double dist = k % 13 == 0 ? r * urand(&st) : r * (1.0 + exp((urand(&st) - 0.6) * 12)) + 0.01;
        if (dist > 12000) dist = 12000;
        double u[3] = { (urand(&st) - 0.5) * 1.6, (urand(&st) - 0.5) * 1.6, k % 7 == 0 ? -1.0 : 1.0 }, len = 0;
        for (int i = 0; i < 3; i++) len += u[i] * u[i];
        len = sqrt(len);
        vec3 co = v3_make(num_from_double(-u[0] / len * dist), num_from_double(-u[1] / len * dist),
                          num_from_double(-u[2] / len * dist));
        num rn = num_from_double(r);
        /* the centre's row, give or take the sphere's own size */
        double cy = u[1] / u[2] * num_to_double(dd) / num_to_double(vh) * h;
        double spread = (r / dist * 1.5 + 0.01) * num_to_double(dd) / num_to_double(vh) * h + 3;
        int row = (int)(h / 2 - 1 - cy + (urand(&st) - 0.5) * 2 * spread);
        if (row < 0) row = 0;
        if (row > h - 1) row = h - 1;
        num y, z;
        if (!rt_exact_comp(vh, h / 2 - 1 - row, &y) || !rt_exact_comp(dd, h, &z)) continue;
        wnum yz = rt_exact_sq(y) + rt_exact_sq(z);
        struct rt_qsphere qs = rt_qsphere_make(rn);
        wnum c = wnum_sub(v3_dot_wide(co, co), num_mul_wide(rn, rn));
        struct rt_ivsphere ivs = rt_ivsphere_make(co, qs.r2x, vh);
        int32_t lo, hi;
        rows++;
        if (!rt_iv_row(&ivs, c, y, z, yz, -(w / 2), w - 1 - w / 2, &lo, &hi)) continue;
        proven++;
        for (int32_t col = -(w / 2); col <= w - 1 - w / 2; col++) {
            num x;
            if (!rt_exact_comp(vh, col, &x)) continue;
            struct rt_quad q;
            int hit = rt_quad_solve(co, v3_make(x, y, z), yz + rt_exact_sq(x), c, &qs, &q);
            if (col < lo || col > hi) wrong += hit;
            else inside++, loose += !hit;
        }
    }
    printf("# row intervals: %ld of %ld rows proven, %ld of %ld columns inside miss\n", proven, rows, loose, inside);
    check(wrong == 0 && proven * 10 > rows * 6 && loose * 20 < inside, "row_intervals_only_certain_misses",
          "%ld hits outside the intervals; %ld of %ld rows proven, %ld of %ld columns inside miss", wrong, proven,
          rows, loose, inside);
}
#endif

/* The coarse sphere rejection (rt_num.h) against the exact robust test on
 * rays aimed just past random spheres of radii 0.01 .. 5000: every claimed
 * miss is a miss of the exact test, and a claimed negative b is one. */
static void test_coarse_rejection(void)
{
    static struct rt_object o[2];
    struct scene save;
    struct scene *s = probe_spheres_scene(o, 2, &save);
    struct probe_ctx p;
    uint32_t st = 12345;
    long wrong = 0, rejected = 0, total = 0, negwrong = 0, negclaims = 0;
    for (int round = 0; round < 60; round++) {
        double r = exp(log(0.01) + urand(&st) * (log(5000.0) - log(0.01)));
        double c[3];
        random_sphere(o, r, c, &st);
        o[1] = o[0];
        struct rt_state *rt = open_state(&p, s);
        if (!rt) break;
        for (int k = 0; k < 500; k++) {
            /* origin 1.05 .. 3 radii away (capped inside the format), aimed at
             * a point (1 +- delta) r from the centre across the line of sight */
            double dist = r * (k % 7 == 6 ? 0.3 + 0.6 * urand(&st) : 1.05 + 2 * urand(&st)); /* some inside */
            if (dist > 9000) dist = 9000 * (0.5 + urand(&st));
            double u[3], len = 0;
            for (int i = 0; i < 3; i++) { u[i] = urand(&st) - 0.5; len += u[i] * u[i]; }
            len = sqrt(len);
            double org[3], tgt[3], side[3] = { -u[1], u[0], 0 }, sl = sqrt(u[0] * u[0] + u[1] * u[1]) + 1e-9;
            double delta = (urand(&st) - 0.5) * (k % 3 == 0 ? 0.002 : 0.2);
            for (int i = 0; i < 3; i++) {
                org[i] = c[i] + u[i] / len * dist;
                tgt[i] = c[i] + side[i] / sl * r * (1 + delta);
            }
            double scale = exp((urand(&st) - 0.5) * 8);    /* |D| from 0.02 to 50 */
            vec3 O = v3_make(num_from_double(org[0]), num_from_double(org[1]), num_from_double(org[2]));
            vec3 D = v3_make(num_from_double((tgt[0] - org[0]) * scale / dist), num_from_double((tgt[1] - org[1]) * scale / dist),
                             num_from_double((tgt[2] - org[2]) * scale / dist));
            if (k % 5 == 4) D = v3_neg(D);                   /* away from the sphere */
            struct rt_ray ray = rt_make_ray(O, D, -1, 0);
            struct rt_csphere cs = rt_csphere_make(o[0].center, o[0].radius);
            int claim = rt_coarse_sphere_miss(&ray.cd, &cs);
            rt->shortcuts = 0;
            num t1, t2;
            int hit = rt_intersect_ray_sphere(rt, 0, &ray, &t1, &t2, NULL);
            total++;
            if (claim) { rejected++; if (hit) wrong++; }
            /* a ray leaving the sphere's surface point nearest O: b < 0 claimed */
            double pt[3];
            for (int i = 0; i < 3; i++) pt[i] = c[i] + u[i] / len * r;
            vec3 P = v3_make(num_from_double(pt[0]), num_from_double(pt[1]), num_from_double(pt[2]));
            struct rt_ray leave = rt_make_ray(P, D, 1, 0);
            if (rt_coarse_dot_negative(&leave.cd, &cs.c)) {
                negclaims++;
                rt_intersect_ray_sphere(rt, 1, &leave, &t1, &t2, NULL);
                if (t1 > 0 || t2 > 0) negwrong++;
            }
        }
        free(p.work);
    }
    *s = save;
    int fixed = strcmp(NUM_NAME, "fixed") == 0;
    check(wrong == 0 && negwrong == 0 && (!fixed || (rejected * 10 > total && negclaims * 10 > total)),
          "coarse_sphere_rejection_only_certain_misses",
          "%ld of %ld claimed misses hit, %ld of %ld negative claims wrong (%ld rays)", wrong, rejected, negwrong,
          negclaims, total);

    /* rt_near_beyond: a near root it claims beyond the limit is beyond it
     * (or the quadratic has no root); spheres of radii 0.01 .. 5000 seen
     * from outside, directions of lengths 1/4 .. 2^9 with multipliers m of
     * 1 .. 1024 (exact primary directions) or none, limits around the root */
    long nwrong = 0, nclaims = 0, ntried = 0;
    for (int k = 0; k < 40000; k++) {
        double r = exp(log(0.01) + urand(&st) * (log(5000.0) - log(0.01)));
        double dist = r * (1.0 + exp((urand(&st) - 0.9) * 12)) + 0.01;
        if (dist > 12000) dist = 12000;
        double u[3], len = 0;
        for (int i = 0; i < 3; i++) { u[i] = urand(&st) - 0.5; len += u[i] * u[i]; }
        len = sqrt(len);
        vec3 co = v3_make(num_from_double(u[0] / len * dist), num_from_double(u[1] / len * dist),
                          num_from_double(u[2] / len * dist));
        /* towards the centre, off by up to about the sphere's angle */
        double dl = exp((urand(&st) - 0.3) * 6), spread = 2.5 * r / dist;
        int32_t m = k % 2 ? 1 + (int32_t)(urand(&st) * 1024) : 0;
        vec3 d = v3_make(num_from_double((-u[0] / len + (urand(&st) - 0.5) * spread) * dl),
                         num_from_double((-u[1] / len + (urand(&st) - 0.5) * spread) * dl),
                         num_from_double((-u[2] / len + (urand(&st) - 0.5) * spread) * dl));
        num rn = num_from_double(r);
        struct rt_qsphere qs = rt_qsphere_make(rn);
        wnum dot = v3_dot_wide(co, co), c = wnum_sub(dot, num_mul_wide(rn, rn));
        wnum aq = rt_quad_a(d, v3_dot_wide(d, d));
        struct rt_quad q;
        wnum n = m ? rt_quad_near_num(c, m) : c;
        int got = rt_quad_solve(co, d, aq, c, &qs, &q) && q.q != 0;
        num t = got ? (m ? rt_quad_near_m(n, &q) : wnum_div(c, q.q)) : NUM_MAX;
        int64_t l64 = got && k % 4 && t < NUM_MAX - 8 ? (int64_t)t + (int64_t)(urand(&st) * 9) - 4 : 0;
        num lim = l64 > 0 ? (num)l64 : num_from_double(urand(&st) * 40);
        if (!rt_near_c_ok(c, dot)) continue;
        ntried++;
        /* b at 2F bits, exactly as rt_quad_solve forms it (fixed point: only
         * there does rt_near_c_ok pass) */
        int64_t bx = -((int64_t)co.x * (int64_t)d.x + (int64_t)co.y * (int64_t)d.y + (int64_t)co.z * (int64_t)d.z);
        if (c > 0 && bx > 0 && rt_near_beyond(bx, n, aq, lim)) {
            nclaims++;
            if (got && t <= lim) nwrong++;
        }
    }
    check(nwrong == 0 && (!fixed || nclaims * 20 > ntried), "near_root_beyond_only_certain",
          "%ld of %ld claims wrong (%ld tried)", nwrong, nclaims, ntried);

    /* rt_div_at_most is num_div(a, b) <= t; the zero threshold of powers */
    long bad = 0;
    for (int k = 0; k < 20000; k++) {
        num a = num_from_double(urand(&st) * 3), b = num_from_double(urand(&st) * 3 + 1e-4);
        num t = num_from_double(urand(&st));
        if (k % 4 == 0) t = num_div(a, b);                   /* on the boundary */
        if (rt_div_at_most(a, b, t) != (num_div(a, b) <= t)) bad++;
    }
    static const uint32_t ex[] = { 1, 2, 10, 100, 500, 1000, 5000 };
    for (size_t i = 0; i < sizeof ex / sizeof ex[0]; i++) {
        num z = rt_powi_zero_below(ex[i]);
        if (fixed) {
            if (num_powi(z, ex[i]) != 0 || num_powi(z + 1, ex[i]) == 0) bad++;
            for (int k = 0; k < 200; k++) {
                num x = (num)(urand(&st) * (double)z);
                if (num_powi(x, ex[i]) != 0) bad++;
            }
        } else if (z >= 0) {
            bad++;
        }
    }
    check(bad == 0, "coarse_div_and_power_thresholds_exact", "%ld mismatches", bad);

    /* num_div_by: num_div bit for bit, divisors from tiny to huge, quotients
     * around every rounding boundary and up to saturation */
    long dbad = 0;
    for (int k = 0; k < 60000; k++) {
        double dv = exp((urand(&st) - 0.3) * 14) * (urand(&st) < 0.5 ? -1 : 1);
        num d = num_from_double(dv);
        if (k % 97 == 0) d = (num)(k % 5 == 0 ? NUM_MAX : NUM_MIN + k % 3);
        struct num_divisor v = num_divisor_make(d);
        num a = num_from_double((urand(&st) - 0.5) * 4 * (k % 3 == 0 ? 1 : fabs(dv)));
        if (k % 11 == 0) a = (num)((double)NUM_MAX * (urand(&st) - 0.5) * 2);
        if (num_div_by(a, &v) != num_div(a, d)) dbad++;
    }
    check(dbad == 0, "num_div_by_equals_num_div", "%ld of 60000 differ", dbad);
}

/* rt_self_shadowed: a shadow ray it claims blocked by its own sphere is:
 * the sphere's exact test (the root 2b/a' of a ray leaving it) puts a hit in
 * (epsilon, 1). Radii 0.01 .. 5000 (powers of two among them), points on
 * the sphere as the normal rounds them, lights behind the surface from
 * grazing to straight through, near and far, and epsilon 0 .. 0.1. */
static void test_self_shadow(void)
{
    static struct rt_object o[1];
    struct scene save;
    struct scene *s = probe_spheres_scene(o, 1, &save);
    struct probe_ctx p;
    uint32_t st = 777;
    long wrong = 0, claims = 0, tried = 0;
    static const double epss[] = { 0.0, 0.001, 0.01, 0.1 };
    for (int round = 0; round < 80; round++) {
        double r = round % 5 == 0 ? ldexp(1.0, (int)(urand(&st) * 12) - 4)
                                  : exp(log(0.01) + urand(&st) * (log(5000.0) - log(0.01)));
        double c[3];
        random_sphere(o, r, c, &st);
        s->rt.epsilon = num_from_double(epss[round % 4]);
        struct rt_state *rt = open_state(&p, s);
        if (!rt) break;
        for (int k = 0; k < 1000; k++) {
            double u[3], len = 0;
            for (int i = 0; i < 3; i++) { u[i] = urand(&st) - 0.5; len += u[i] * u[i]; }
            len = sqrt(len);
            vec3 P = v3_make(num_from_double(c[0] + u[0] / len * r), num_from_double(c[1] + u[1] / len * r),
                             num_from_double(c[2] + u[2] / len * r));
            struct rt_hit hit;
            memset(&hit, 0, sizeof hit);
            vec3 n = rt_hit_normal(rt, &hit, &P);
            /* inward along -u by cos, across by sin: from grazing to straight in */
            double cs = k % 4 == 0 ? urand(&st) * 0.01 : urand(&st), w[3], wl = 0;
            for (int i = 0; i < 3; i++) { w[i] = urand(&st) - 0.5; }
            double wu = (w[0] * u[0] + w[1] * u[1] + w[2] * u[2]) / len;
            for (int i = 0; i < 3; i++) { w[i] -= wu * u[i] / len; wl += w[i] * w[i]; }
            wl = sqrt(wl) + 1e-12;
            double dist = k % 2 ? r * exp((urand(&st) - 0.3) * 6) : exp((urand(&st) - 0.5) * 10);
            if (dist > 9000) dist = 9000;
            vec3 d = v3_make(num_from_double((-cs * u[0] / len + sqrt(1 - cs * cs) * w[0] / wl) * dist),
                             num_from_double((-cs * u[1] / len + sqrt(1 - cs * cs) * w[1] / wl) * dist),
                             num_from_double((-cs * u[2] / len + sqrt(1 - cs * cs) * w[2] / wl) * dist));
            if (k % 7 == 0) d = v3_make(num_from_int(1), num_from_int(4), num_from_int(4));   /* a directional light */
#if NUM_MODE == NUM_MODE_FIXED
            if (!rt_v3_within(n, NUM_FRAC + 1) || !rt_v3_within(d, 26)) continue;
            num ndl = rt_v3_integral(d) ? rt_dot_small_int(n, d) : rt_dot_small(n, d);
#else
            num ndl = v3_dot(n, d);
#endif
            tried++;
            /* the terms of d made once (a directional light's) decide the same */
            struct rt_self_dir sd = rt_self_dir_make(&d, s->rt.epsilon);
            int self = ndl < 0 && rt_self_shadowed(rt, 0, ndl, &d, NULL);
            if (ndl < 0 && self != rt_self_shadowed(rt, 0, ndl, &d, &sd)) wrong++;
            if (!self) continue;
            claims++;
            struct rt_ray ray = rt_make_ray(P, d, 0, 0);
            num t1, t2;
            rt->shortcuts = 0;
            int got = rt_intersect_ray_sphere(rt, 0, &ray, &t1, &t2, NULL);
            rt->shortcuts = 1;
            if (!got || !(s->rt.epsilon < t1 && t1 < NUM_ONE)) wrong++;
        }
        free(p.work);
    }
    *s = save;
    int fixed = strcmp(NUM_NAME, "fixed") == 0;
    check(wrong == 0 && (!fixed || claims * 5 > tried), "self_shadow_only_certain",
          "%ld of %ld claims wrong (%ld tried)", wrong, claims, tried);
}

/* Chapter 5 scene renders in every mode; its glass sphere shows the plane through it. */
/* The format analysis's bound on where hit points lie
 * (scene_format_hit_reach) against every hit point the render shades
 * (rt_set_hit_probe): the repository's ray-traced scenes, and generated
 * ones of the shape where the bound is the tangent length rather than
 * |C| + r — a ground sphere under the camera (its horizon hits lie at the
 * tangent length), small spheres above it or sunk into it, reflections to
 * depth 0 … 4, shadows, a turned camera. A bound too small by a few
 * percent fails here. */
static void test_hit_reach(void)
{
    static const char *files[] = {
        "firmware/scenes/book/raytracer-01.scene", "firmware/scenes/book/raytracer-02.scene",
        "firmware/scenes/book/raytracer-04.scene", "firmware/scenes/book/raytracer-05.scene",
        "firmware/scenes/book/raytracer-06.scene", "firmware/scenes/demo/mirror-spheres.scene",
        "firmware/scenes/demo/raytracer-ch5.scene", "firmware/scenes/bench/grid64.scene",
    };
    enum { W = 48, NGEN = 40 };
    static uint8_t rgb[W * W * 3];
    int bad = 0, checked = 0, tight = 0;
    double closest = 0;
    uint32_t st = 12345;
    char text[2048], what[200] = "";
    for (int k = 0; k < (int)(sizeof files / sizeof files[0]) + NGEN; k++) {
        struct scene *s = NULL;
        char err[256];
        if (k < (int)(sizeof files / sizeof files[0])) {
            s = scene_file(files[k]);
        } else {
            double big = 300 + urand(&st) * 20000, h = 0.3 + 2.7 * urand(&st);
            if (k % 2) {
                /* the horizon just above the centre column's ray of canvas
                 * row -j: that ray hits the ground next to its tangent point */
                int j = 2 + (int)(urand(&st) * (W / 2 - 3));
                double a = atan((double)j / W) * (1 - pow(10, -6 + 3 * urand(&st)));
                h = big * (1 / cos(a) - 1);
            }
            int n = snprintf(text, sizeof text,
                             "renderer = raytracer\nviewport { width = 1 height = 1 d = 1 }\n"
                             "camera { position = (0, 0, 0) rotation { y = %d } }\n"
                             "raytracer { recursion_depth = %d t_min = %g shadows = %s }\n"
                             "sphere { center = (0, %.6g, 0) radius = %.6g color = (255, 255, 0) reflective = %.2f }\n"
                             "light { type = ambient intensity = 0.2 }\n"
                             "light { type = point intensity = 0.6 position = (2, 1, 0) }\n",
                             k % 2 ? 0 : (int)(urand(&st) * 60) - 30, (int)(urand(&st) * 5), urand(&st) < 0.5 ? 1.0 : 0.01,
                             urand(&st) < 0.5 ? "on" : "off", -big - h, big, urand(&st) * 0.6);
            for (int i = 0, m = 1 + (int)(urand(&st) * 4); i < m; i++) {
                double rad = 0.3 + 1.2 * urand(&st), sunk = urand(&st) < 0.3;
                double y = -h + (sunk ? (urand(&st) - 0.5) * rad : rad + 0.01 + 2 * urand(&st));
                n += snprintf(text + n, sizeof text - (size_t)n,
                              "sphere { center = (%.4g, %.4g, %.4g) radius = %.4g color = (0, 255, 255) "
                              "reflective = %.2f }\n",
                              (urand(&st) - 0.5) * 6, y, 2.5 + 6 * urand(&st), rad, urand(&st) * 0.8);
            }
            if (scene_parse_mem("generated", text, strlen(text), &s, err, sizeof err) != 0) {
                printf("FAIL hit_reach_scene_parses: %s\n", err);
                bad++;
                continue;
            }
        }
        double H[64];
        num probe[64];
        if (s->nobjects > 64) continue;
        scene_format_hit_reach(s, W, W, H);
        memset(probe, 0, sizeof probe);
        rt_render_hit_probe = probe;
        int rc = rt_render(s, W, W, 16, rgb, NULL, NULL);
        rt_render_hit_probe = NULL;
        for (int i = 0; i < s->nobjects && rc == 0; i++) {
            double got = num_to_double(probe[i]);
            if (H[i] < 0) continue;
            checked++;
            /* the tangent bounds (below centre + radius) in particular */
            const struct rt_object *o = &s->objects[i];
            double full = sqrt(dd(o->center.x) * dd(o->center.x) + dd(o->center.y) * dd(o->center.y) +
                               dd(o->center.z) * dd(o->center.z)) + dd(o->radius);
            if (got > 0.5 * H[i]) tight++;
            if (o->shape == RT_SPHERE && H[i] < 0.999 * full && got / H[i] > closest) closest = got / H[i];
            if (got > H[i]) {
                if (!bad) snprintf(what, sizeof what, "%s: object %d hit at |P| = %.6g > bound %.6g",
                                   k < (int)(sizeof files / sizeof files[0]) ? files[k] : "generated", i, got, H[i]);
                bad++;
            }
        }
        if (rc != 0) bad++;
        if (k >= (int)(sizeof files / sizeof files[0])) scene_free(s);
    }
    check(bad == 0 && checked > 0, "hit_reach_bounds_every_hit", "%d of %d objects beyond the bound; %s", bad, checked,
          what);
    /* the bound is not vacuous: many objects are hit beyond half of it */
    check(tight * 4 >= checked && closest > 0.99, "hit_reach_bound_is_tight",
          "%d of %d objects hit beyond half the bound, the closest to a tangent bound at %.4f of it", tight, checked, closest);
    printf("# hit_reach: %d objects, %d hit beyond half their bound, the closest to a tangent bound at %.6f of it\n",
           checked, tight,
           closest);
}

/* The tight format argument (tools/scene/scene_format.c, rt_tight_pairs:
 * positions and the sums and differences the core forms held once) on
 * worst-case scenes: a ray tracer of spheres alone grown until the analysis
 * just accepts it at this build's format — a ground sphere whose far side
 * a reflection reaches (small spheres on it, touching or sunk into it),
 * reflections to depth 4, shadows, a point light far off — renders without
 * a saturation, and with the 32-bit paths the analysis allows (struct
 * scene.fits) gives the same image, and the narrow operations of the
 * argument's list at their extreme inputs saturate nothing
 * (tight_extremes). And rt_reflect where 2 N.L is past the range but R is
 * not. */
#if NUM_MODE == NUM_MODE_FIXED
static vec3 v3_of(const double v[3]) { return v3_make(num_from_double(v[0]), num_from_double(v[1]), num_from_double(v[2])); }

/* The narrow operations of the tight argument's list at their extreme
 * inputs for scene s (spheres alone): for every pair of spheres i, j the
 * point O of j farthest from i's centre C and the point P of i farthest
 * from O (CO = O - C, D t = P - O), and for every point light the point P
 * of each sphere farthest from it with its normal N, L = light - P, N.L
 * (-|L|), R = N (2 N.L) - L as the lighting forms it, a view direction V
 * of the longest primary length along R (R.V = |R| |V|) and |R| |V|, and
 * N.L times the light's intensity. Returns the saturations counted. */
static uint32_t tight_extremes(const struct scene *s, const struct scene_format *F)
{
    uint32_t sat0 = num_saturations;
    double vmax = sqrt(0.25 * (1 + 2.0 / F->width) * (1 + 2.0 / F->width) +
                       0.25 * (1 + 2.0 / F->height) * (1 + 2.0 / F->height) + 1);   /* viewport 1 x 1, d = 1 */
    for (int i = 0; i < s->nobjects; i++) {
        const struct rt_object *oi = &s->objects[i];
        double ci[3] = { dd(oi->center.x), dd(oi->center.y), dd(oi->center.z) }, ri = dd(oi->radius);
        for (int j = 0; j < s->nobjects; j++) {
            const struct rt_object *oj = &s->objects[j];
            double cj[3] = { dd(oj->center.x), dd(oj->center.y), dd(oj->center.z) }, rj = dd(oj->radius), u[3];
            double len = sqrt((cj[0] - ci[0]) * (cj[0] - ci[0]) + (cj[1] - ci[1]) * (cj[1] - ci[1]) +
                              (cj[2] - ci[2]) * (cj[2] - ci[2]));
            for (int c = 0; c < 3; c++) u[c] = len > 0 ? (cj[c] - ci[c]) / len : c == 1;
            double o[3], p[3];
            for (int c = 0; c < 3; c++) o[c] = cj[c] + rj * u[c], p[c] = ci[c] - ri * u[c];
            (void)v3_sub(v3_of(o), oi->center);   /* CO */
            (void)v3_sub(v3_of(p), v3_of(o));     /* D t */
        }
        for (int k = 0; k < s->nlights; k++) {
            const struct scene_light *lt = &s->lights[k];
            if (lt->type != LIGHT_POINT) continue;
            double lp[3] = { dd(lt->v.x), dd(lt->v.y), dd(lt->v.z) }, u[3], p[3], nd[3];
            double len = sqrt((lp[0] - ci[0]) * (lp[0] - ci[0]) + (lp[1] - ci[1]) * (lp[1] - ci[1]) +
                              (lp[2] - ci[2]) * (lp[2] - ci[2]));
            for (int c = 0; c < 3; c++) {
                u[c] = len > 0 ? (lp[c] - ci[c]) / len : c == 1;
                p[c] = ci[c] - ri * u[c];
                nd[c] = -u[c];
            }
            vec3 n = v3_of(nd), l = v3_sub(lt->v, v3_of(p));
            num ndl = v3_dot(n, l);
            int small = rt_v3_within(n, NUM_FRAC + 1) && rt_v3_within(l, 26);
            vec3 r = rt_reflect(n, l, ndl, small);
            double rl = sqrt(dd(r.x) * dd(r.x) + dd(r.y) * dd(r.y) + dd(r.z) * dd(r.z));
            double vd[3] = { dd(r.x) / rl * vmax, dd(r.y) / rl * vmax, dd(r.z) / rl * vmax };
            vec3 v = v3_of(vd);
            (void)v3_dot(r, v);
            (void)num_mul(v3_len(r), v3_len(v));
            (void)num_mul(v3_len(n), v3_len(l));
            (void)rt_mul_weight(ndl, lt->intensity);
        }
    }
    return num_saturations - sat0;
}
#endif

static void test_tight_bounds(void)
{
#if NUM_MODE == NUM_MODE_FIXED
    enum { W = 40, NGEN = 24 };
    static uint8_t a[W * W * 3], b[W * W * 3];
    static const int frac[1] = { NUM_FRAC };
    double lim = ldexp(1.0, 31 - NUM_FRAC), closest = 0;
    uint32_t st = 4711;
    int tried = 0, bad = 0;
    char text[2048], what[240] = "";
    for (int k = 0; k < NGEN; k++) {
        double u[24];
        for (int i = 0; i < 24; i++) u[i] = urand(&st);
        struct scene *s = NULL;
        struct scene_format F;
        int ok = 0;
        for (double big = lim / 2; big > 4 && !ok; big *= 0.97) {
            double h = 0.5 + 2 * u[0], lx = big * (0.05 + 0.4 * u[1]);
            int n = snprintf(text, sizeof text,
                             "renderer = raytracer\nviewport { width = 1 height = 1 d = 1 }\n"
                             "camera { position = (0, 0, 0) rotation { y = %d } }\n"
                             "raytracer { recursion_depth = %d shadows = %s }\n"
                             "sphere { center = (0, %.9g, 0) radius = %.9g color = (255, 255, 0) specular = %d "
                             "reflective = %.2f }\n"
                             "light { type = ambient intensity = 0.2 }\n"
                             "light { type = point intensity = %.2f position = (%.6g, %.6g, 0) }\n"
                             "light { type = directional intensity = 0.2 direction = (1, 4, 4) }\n",
                             (int)(u[2] * 60) - 30, 1 + (int)(u[3] * 4), u[4] < 0.7 ? "on" : "off", -big - h, big,
                             10 + (int)(u[5] * 990), 0.2 + 0.6 * u[8], 0.2 + 0.6 * u[6], lx, 1 + u[7] * big * 0.2);
            for (int i = 0, m = 1 + (int)(u[9] * 4); i < m; i++) {
                double rad = 0.4 + 1.1 * u[10 + i], y = -h + (u[14 + i] < 0.4 ? 1.0001 * rad : (u[18 + i] - 0.3) * rad);
                n += snprintf(text + n, sizeof text - (size_t)n,
                              "sphere { center = (%.4g, %.6g, %.4g) radius = %.4g color = (0, 255, 255) specular = 500 "
                              "reflective = %.2f }\n",
                              (u[10 + i] - 0.5) * 6, y, 2.5 + 5 * u[14 + i], rad, 0.2 + 0.6 * u[18 + i]);
            }
            char err[256];
            if (scene_parse_mem("generated", text, strlen(text), &s, err, sizeof err) != 0) {
                s = NULL;
                continue;
            }
            ok = scene_format_choose(s, W, W, frac, 1, 0, &F) == 0 && F.tight;
            if (!ok) {
                scene_free(s);
                s = NULL;
            }
        }
        if (!ok) continue;
        tried++;
        if (F.need / lim > closest) closest = F.need / lim;
        uint32_t sat_x = tight_extremes(s, &F);
        if (sat_x && !bad) snprintf(what, sizeof what, "scene %d: %u saturations at the extreme inputs", k, sat_x);
        s->fits = 0;
        uint32_t sat0 = num_saturations;
        int rc = rt_render(s, W, W, 8, a, NULL, NULL);
        uint32_t sat = num_saturations - sat0;
        s->fits = (uint8_t)scene_format_fits(&F, NUM_FRAC);
        int rc2 = rt_render(s, W, W, 8, b, NULL, NULL);
        if (sat_x || rc || rc2 || sat || memcmp(a, b, sizeof a)) {
            if (!bad && !sat_x)
                snprintf(what, sizeof what, "scene %d (need %.6g of %.6g, fits %d): rc %d/%d, %u saturations, %s", k,
                         F.need, lim, s->fits, rc, rc2, sat, memcmp(a, b, sizeof a) ? "images differ" : "same image");
            bad++;
        }
        scene_free(s);
    }
    check(bad == 0 && tried * 2 >= NGEN && closest > 0.9, "tight_format_bounds_hold",
          "%d of %d worst-case scenes wrong (%d accepted, the closest to the range at %.4f of it); %s", bad, NGEN, tried,
          closest, what);
    printf("# tight bounds: %d scenes accepted, the closest to the range at %.4f of it\n", tried, closest);
    /* N unit along x, L = (3/4 NUM_MAX, -1/8 NUM_MAX, 0): N.L = 3/4 NUM_MAX,
     * 2 N.L past the range, R = 2 N (N.L) - L = (3/4, 1/8, 0) NUM_MAX */
    vec3 n = v3_make(NUM_ONE, NUM_ZERO, NUM_ZERO), l = v3_make(NUM_MAX / 4 * 3, -(NUM_MAX / 8), NUM_ZERO);
    num ndl = v3_dot(n, l);
    uint32_t sat0 = num_saturations;
    vec3 r = rt_reflect(n, l, ndl, 0);
    check(ndl == l.x && r.x == l.x && r.y == -l.y && r.z == 0 && num_saturations == sat0, "reflect_past_half_range",
          "R = (%ld, %ld, %ld) raw for L = (%ld, %ld, 0), %u saturations", (long)r.x, (long)r.y, (long)r.z, (long)l.x,
          (long)l.y, num_saturations - sat0);
#endif
}

static void test_ch5_scene(void)
{
    int w = 80, h = 80;
    uint8_t *img = malloc((size_t)w * h * 3);
    struct scene *s = rt_ch5();
    uint32_t sat0 = num_saturations;
    int rc = rt_render(s, w, h, 8, img, NULL, NULL);
    check(rc == 0 && num_saturations == sat0, "ch5_scene_renders_without_saturation", "rc %d, saturations %u", rc,
          num_saturations - sat0);
    free(img);
}

/* test_raytracer dump FILE.ppm [ss]: writes the chapter 5 scene at 240x240. */
static int dump(const char *path, int ss)
{
    int w = 240, h = 240;
    uint8_t *img = malloc((size_t)w * h * 3);
    struct scene *s = rt_ch5();
    s->rt.supersample = (uint8_t)ss;
    int rc = rt_render(s, w, h, 16, img, NULL, NULL);
    FILE *f = fopen(path, "wb");
    if (!f || rc) return 1;
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    fwrite(img, 1, (size_t)w * h * 3, f);
    fclose(f);
    free(img);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 2 && strcmp(argv[1], "dump") == 0) return dump(argv[2], argc > 3 ? atoi(argv[3]) : 1);
    int quick = argc > 1 && strcmp(argv[1], "quick") == 0;
    test_sha256();
    if (is_double() && !quick) {
        test_book_digests();
    }
    test_strips();
    test_progressive();
    test_ground_sphere();
    test_csg_planes_triangles();
    test_refraction();
    test_optimisations();
    test_shortcuts_same_image();
    test_tiles_same_image();
    test_coarse_rejection();
    test_self_shadow();
#if NUM_MODE == NUM_MODE_FIXED
    test_row_intervals();
#endif
    test_ch5_scene();
    test_hit_reach();
    test_tight_bounds();
    return check_exit();
}
