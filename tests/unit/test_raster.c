/* SPDX-License-Identifier: MIT */
/* test_raster.c — the default path's promises, in one numeric mode:
 * strips give identical images, the top-left rule writes every pixel of a
 * closed mesh exactly once, any camera position is safe, 16-bit depth
 * fails only beyond a known distance. */
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "raster_harness.h"
#include "scene_files.h"

static struct scene *default_scene(const char *name)
{
    struct scene *s = book_scene(name);
    s->ras.book_exact = 0;
    if (s->ras.clip) s->ras.clip = 2;
    return s;
}

static void strips_identical(void)
{
    static const char *const names[] = { "raster-03", "raster-08", "raster-10", "raster-11", "raster-13", "raster-rt-scene" };
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++)
        for (int book = 0; book < 2; book++) {
            struct frame f[3];
            static const int rows[3] = { 240, 8, 16 };
            int rc = 0;
            for (int k = 0; k < 3; k++) {
                struct scene *s = book ? book_scene(names[n]) : default_scene(names[n]);
                rc |= render_frame(s, 320, 240, rows[k], 0, &f[k]);
            }
            int same = !rc;
            for (int k = 1; k < 3 && same; k++)
                same = !memcmp(f[0].rgb888, f[k].rgb888, 320 * 240 * 3) && !memcmp(f[0].rgb565, f[k].rgb565, 320 * 240 * 2) &&
                       !memcmp(f[0].written, f[k].written, 320 * 240);
            char name[96];
            snprintf(name, sizeof name, "strips_8_16_240_identical_%s_%s", names[n], book ? "book" : "default");
            check(same, name, "images differ between strip heights");
            for (int k = 0; k < 3; k++) frame_free(&f[k]);
        }
}

/* The default path's triangles are binned to strips once a frame and each
 * context keeps the list of the strip it drew last (raster_strip.c): strips
 * in any order, as two cores take them (every other one each), backwards,
 * of any height up to the context's and at any row, give the image of one
 * strip the whole frame high. */
static void strip_order_free(void)
{
    static const char *const names[] = { "raster-11", "raster-rt-scene", "raster-13" };
    enum { W = 320, H = 240, R = 16 };
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++) {
        struct scene *s = default_scene(names[n]);
        struct frame whole;
        int bad = render_frame(s, W, H, H, 1, &whole) ? -1 : 0;
        size_t ws = render_work_size(s, W, H, R);
        void *work = malloc(ws);
        static uint16_t px[W * R], img[W * H];
        static uint8_t c888[W * R * 3], img888[W * H * 3];
        struct render_ctx ctx;
        if (!work || render_init(&ctx, s, W, H, R, work, ws)) bad = -1;
        for (int order = 0; order < 5 && bad == 0; order++) {
            /* 0: top down, 1: bottom up, 2: even strips then odd (two cores),
             * 3: rows of 5 at odd offsets, 4: 16-row strips from row 3 then rows 0..2 */
            int y0s[64], y1s[64], ns = 0;
            if (order <= 2) {
                int nst = (H + R - 1) / R;
                for (int k = 0; k < nst; k++) {
                    int i = order == 0 ? k : order == 1 ? nst - 1 - k : (k < (nst + 1) / 2 ? 2 * k : 2 * (k - (nst + 1) / 2) + 1);
                    y0s[ns] = i * R;
                    y1s[ns++] = i * R + R < H ? i * R + R : H;
                }
            } else if (order == 3) {
                for (int y = 0; y < H; y += 5) { y0s[ns] = y; y1s[ns++] = y + 5 < H ? y + 5 : H; }
            } else {
                for (int y = 3; y < H; y += R) { y0s[ns] = y; y1s[ns++] = y + R < H ? y + R : H; }
                y0s[ns] = 0;
                y1s[ns++] = 3;
            }
            memset(img, 0, sizeof img);
            if (render_begin_frame(&ctx, 1)) { bad = -1; break; }
            for (int k = 0; k < ns; k++) {
                struct render_target t = { W, H, (uint16_t)y0s[k], (uint16_t)y1s[k], px, c888, NULL };
                if (render_strip(&ctx, &t, NULL)) { bad = -1; break; }
                memcpy(img + (size_t)y0s[k] * W, px, (size_t)(y1s[k] - y0s[k]) * W * 2);
                memcpy(img888 + (size_t)y0s[k] * W * 3, c888, (size_t)(y1s[k] - y0s[k]) * W * 3);
            }
            if (memcmp(img, whole.rgb565, sizeof img) || memcmp(img888, whole.rgb888, sizeof img888)) bad = order + 1;
        }
        char name[96];
        snprintf(name, sizeof name, "strips_in_any_order_identical_%s", names[n]);
        check(bad == 0, name, bad < 0 ? "render failed" : "strip order %d gives another image", bad - 1);
        free(work);
        frame_free(&whole);
    }
}

/* Gouraud lighting once per vertex (models whose corners of a vertex all
 * carry its normal, struct ras_model.vertex_normals, found by the parser)
 * gives the image of lighting every corner: raster-11's sphere qualifies,
 * its cubes (a normal per face at each corner) do not. */
static void vertex_lighting_same(void)
{
    struct scene *s = default_scene("raster-11");
    s->ras.shading = SHADE_GOURAUD;
    s->ras.lighting = RAS_LIGHT_EXACT;
    int sphere = -1, cubes_vn = 0;
    for (uint16_t m = 0; m < s->nmodels; m++) {
        if (s->models[m].ntris > 12) sphere = s->models[m].vertex_normals;
        else cubes_vn |= s->models[m].vertex_normals;
    }
    check(sphere == 1 && cubes_vn == 0, "vertex_normals_found_by_parser",
          "sphere %d (want 1), cubes %d (want 0)", sphere, cubes_vn);
    struct frame a, b;
    int rc = render_frame(s, 320, 240, 16, 0, &a);
    /* the same scene with every model lit per corner */
    struct ras_model *models = (struct ras_model *)(void *)s->models;
    uint8_t keep[64];
    for (uint16_t m = 0; m < s->nmodels && m < 64; m++) { keep[m] = models[m].vertex_normals; models[m].vertex_normals = 0; }
    rc |= render_frame(s, 320, 240, 16, 0, &b);
    for (uint16_t m = 0; m < s->nmodels && m < 64; m++) models[m].vertex_normals = keep[m];
    check(!rc && !memcmp(a.rgb888, b.rgb888, 320 * 240 * 3) && frame_written(&a) > 5000, "vertex_lighting_same_image",
          "per-vertex and per-corner Gouraud lighting differ (or nothing drawn)");
    frame_free(&a);
    frame_free(&b);
}

/* Two cores' contexts: an owner that prepares each frame and a sibling
 * (render_init_sibling) that shares it, taking strips in turn as the board
 * does (claiming the next free one), give every frame of one context, with
 * a fraction of its memory for the sibling. */
static void sibling_shares_frame(void)
{
    static const char *const names[] = { "raster-11", "raster-13", "raster-rt-scene", "raster-08" };
    enum { W = 320, H = 240, R = 16 };
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++)
        for (int book = 0; book < 2; book++) {
            struct scene *s = book ? book_scene(names[n]) : default_scene(names[n]);
            size_t ws = render_work_size(s, W, H, R), ss = render_sibling_work_size(s, W, H, R);
            void *w0 = malloc(ws), *w1 = malloc(ss);
            static uint16_t px[W * R], img[W * H];
            static uint8_t c888[W * R * 3], img888[W * H * 3];
            struct render_ctx c0, c1;
            int bad = !w0 || !w1 || render_init(&c0, s, W, H, R, w0, ws) || render_init_sibling(&c1, &c0, w1, ss);
            if (!bad && render_init_sibling(&c1, &c1, w1, ss) == 0) bad = 2;   /* a sibling's sibling */
            if (!bad && render_init_sibling(&c1, &c0, w1, ss - 1) == 0) bad = 3;
            if (!bad) bad = render_init_sibling(&c1, &c0, w1, ss);
            for (uint16_t f = 0; f < 3 && !bad; f++) {
                struct frame whole;
                if (render_frame(s, W, H, R, f, &whole)) { bad = 4; break; }
                if (render_begin_frame(&c0, f) || render_begin_frame(&c1, (uint16_t)(f + 1)) == 0 ||
                    render_begin_frame(&c1, f)) { bad = 5; frame_free(&whole); break; }
                /* strips in turn: 0, 1 on the owner, 2 on the sibling, ... in
                 * a pattern that changes with the frame */
                for (int k = 0; k * R < H && !bad; k++) {
                    int y0 = k * R, y1 = y0 + R < H ? y0 + R : H;
                    struct render_ctx *c = ((k * (f + 1)) / 2) % 2 ? &c1 : &c0;
                    struct render_target t = { W, H, (uint16_t)y0, (uint16_t)y1, px, c888, NULL };
                    if (render_strip(c, &t, NULL)) bad = 6;
                    memcpy(img + (size_t)y0 * W, px, (size_t)(y1 - y0) * W * 2);
                    memcpy(img888 + (size_t)y0 * W * 3, c888, (size_t)(y1 - y0) * W * 3);
                }
                if (!bad && (memcmp(img, whole.rgb565, sizeof img) || memcmp(img888, whole.rgb888, sizeof img888))) bad = 7;
                frame_free(&whole);
            }
            char name[96];
            snprintf(name, sizeof name, "sibling_context_same_frames_%s_%s", names[n], book ? "book" : "default");
            check(bad == 0 && ss < ws, name, "failure %d (sibling %zu bytes, owner %zu)", bad, ss, ws);
            free(w0);
            free(w1);
        }
}

/* The frame's preparation split (render_frame_start, _vertices,
 * _triangles, _finish): the vertices in 2 or 3 parts and the triangles in
 * 2, taken by the owner and its sibling in either order, give the frames
 * of render_begin_frame. */
static void split_preparation_same_frames(void)
{
    /* raster-11 also in Gouraud, where its sphere is lit per vertex (the
     * sibling's part of the triangles lights into its own table); the
     * 16,384-triangle knots keep no camera-space table (each part of the
     * triangles transforms vertices again through its own cache) */
    static const char *const names[] = { "raster-11", "raster-rt-scene", "raster-08", "raster-11",
                                         "knot-16k-gouraud", "knot-16k-flat" };
    enum { W = 320, H = 240, R = 16 };
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++)
        for (int book = 0; book < 2; book++) {
            int gouraud = n == 3 || n == 4, knot = n >= 4;
            if ((gouraud || knot) && book) continue;
            char path[96];
            snprintf(path, sizeof path, "firmware/scenes/bench/%s.scene", names[n]);
            struct scene *s = knot ? scene_file(path) : book ? book_scene(names[n]) : default_scene(names[n]);
            if (n == 3) s->ras.shading = SHADE_GOURAUD;
            size_t ws = render_work_size(s, W, H, R), ss = render_sibling_work_size(s, W, H, R);
            void *w0 = malloc(ws), *w1 = malloc(ss);
            static uint16_t px[W * R], img[W * H];
            struct render_ctx c0, c1;
            int bad = !w0 || !w1 || render_init(&c0, s, W, H, R, w0, ws);
            /* part 1 of the triangles needs the sibling's table where vertices are lit */
            if (!bad && gouraud && (render_frame_start(&c0, 0) || render_frame_triangles(&c0, 1, 2) == 0)) bad = 10;
            bad = bad || render_init_sibling(&c1, &c0, w1, ss);
            if (!bad && (render_frame_start(&c1, 0) == 0 || render_frame_finish(&c1) == 0 ||
                         render_frame_vertices(&c0, 2, 2) == 0))
                bad = 2;   /* start and finish are the owner's; parts in range */
            for (uint16_t f = 0; f < 3 && !bad; f++) {
                struct frame whole;
                if (render_frame(s, W, H, R, f, &whole)) { bad = 3; break; }
                unsigned parts = f == 1 ? 3 : 2;
                bad = render_frame_start(&c0, f) ? 4 : 0;
                /* the sibling's parts first, the owner's last */
                for (unsigned p = parts; p-- > 0 && !bad;)
                    if (render_frame_vertices(p % 2 ? &c1 : &c0, p, parts)) bad = 5;
                /* the triangles in two parts, the sibling's first */
                if (!bad && (render_frame_triangles(&c1, 1, 2) || render_frame_triangles(&c0, 0, 2))) bad = 9;
                if (!bad && (render_frame_finish(&c0) || render_begin_frame(&c1, f))) bad = 6;
                for (int k = 0; k * R < H && !bad; k++) {
                    int y0 = k * R, y1 = y0 + R < H ? y0 + R : H;
                    struct render_target t = { W, H, (uint16_t)y0, (uint16_t)y1, px, NULL, NULL };
                    if (render_strip(k % 2 ? &c1 : &c0, &t, NULL)) bad = 7;
                    memcpy(img + (size_t)y0 * W, px, (size_t)(y1 - y0) * W * 2);
                }
                if (!bad && memcmp(img, whole.rgb565, sizeof img)) bad = 8;
                frame_free(&whole);
            }
            char name[96];
            snprintf(name, sizeof name, "split_preparation_same_frames_%s_%s", names[n],
                     gouraud ? "gouraud" : book ? "book" : "default");
            check(bad == 0, name, "failure %d", bad);
            free(w0);
            free(w1);
        }
}

/* Closed meshes drawn with additive colour: each covered pixel must get
 * exactly one triangle. A counting render: every triangle writes colour 1
 * in red; the rgb888 red channel after rendering with depth off would only
 * hold the last write, so count through the written mask of one triangle
 * at a time instead. */
static void fill_rule_closed_mesh(void)
{
    static const char *const names[] = { "raster-11", "raster-rt-scene" };
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++) {
        struct scene *s = default_scene(names[n]);
        s->ras.depth_test = 0;
        s->ras.backface_cull = 1;
        s->ras.shading = SHADE_NONE;
        /* one instance at a time: the sphere (or cube) is closed, so its
         * front faces tile its silhouette */
        const struct ras_instance *all = s->instances;
        uint16_t ninst = s->ninstances;
        long bad = 0, covered = 0;
        for (uint16_t i = 0; i < ninst; i++) {
            const struct ras_model *m = &s->models[all[i].model];
            if (m->ntris < 12) continue; /* the floor is not closed */
            static uint16_t count[240 * 320];
            static uint8_t any[240 * 320];
            memset(count, 0, sizeof count);
            memset(any, 0, sizeof any);
            struct ras_model one = *m;
            struct scene s1 = *s;
            s1.instances = &all[i];
            s1.ninstances = 1;
            s1.models = &one;
            s1.nmodels = 1;
            struct ras_instance in = all[i];
            in.model = 0;
            s1.instances = &in;
            for (uint16_t k = 0; k < m->ntris; k++) {
                one.tris = &m->tris[k];
                one.ntris = 1;
                struct frame f;
                if (render_frame(&s1, 320, 240, 240, 0, &f)) { bad = -1; break; }
                for (long p = 0; p < 320 * 240; p++) if (f.written[p]) { count[p]++; any[p] = 1; }
                frame_free(&f);
            }
            /* the whole instance at once: the same coverage */
            one = *m;
            struct frame g;
            render_frame(&s1, 320, 240, 240, 0, &g);
            for (long p = 0; p < 320 * 240; p++) {
                if (count[p] > 1) bad++;
                if (g.written[p] != any[p]) bad++;
                covered += count[p] == 1;
            }
            frame_free(&g);
        }
        char name[96];
        snprintf(name, sizeof name, "top_left_rule_each_pixel_once_%s", names[n]);
        check(bad == 0 && covered > 1000, name, "%ld pixels written twice or coverage mismatch (%ld covered)", bad, covered);
    }
}

/* The fast span loops cover exactly the pixels of the exact per-pixel
 * path (same edge functions and fill rule, evaluated per row): with the
 * depth test off, the written maps of perspective_step 8, 16, 32 equal
 * that of perspective_step 1 for every shading the fast path draws. */
static void fast_coverage_exact(void)
{
    static const char *const names[] = { "raster-08", "raster-10", "raster-11", "raster-13", "raster-rt-scene" };
    static const uint8_t shadings[] = { SHADE_NONE, SHADE_FLAT, SHADE_GOURAUD };
    static const uint8_t steps[] = { 8, 16, 32 };
    for (size_t n = 0; n < sizeof names / sizeof names[0]; n++)
        for (size_t sh = 0; sh < sizeof shadings; sh++) {
            struct scene *s = default_scene(names[n]);
            s->ras.depth_test = 0;
            s->ras.backface_cull = 1;
            s->ras.shading = shadings[sh];
            s->ras.persp_step = 1;
            struct frame ref;
            int rc = render_frame(s, 320, 240, 16, 0, &ref);
            long diff = 0, covered = frame_written(&ref);
            for (size_t k = 0; k < sizeof steps && !rc; k++) {
                s->ras.persp_step = steps[k];
                struct frame f;
                rc |= render_frame(s, 320, 240, 16, 0, &f);
                for (long p = 0; !rc && p < 320 * 240; p++) diff += f.written[p] != ref.written[p];
                if (!rc) frame_free(&f);
            }
            frame_free(&ref);
            char name[96];
            snprintf(name, sizeof name, "fast_coverage_equals_exact_%s_shading%d", names[n], shadings[sh]);
            check(!rc && diff == 0 && covered > 1000, name, "%ld pixels differ (%ld covered)", diff, covered);
        }
}

/* Any camera position, including inside a model and behind everything:
 * no crash, nothing outside the target (ASan), finite work. */
static void any_camera(void)
{
    static const double pos[][3] = { { -1.5, 0, 7 }, { 1.75, -0.5, 7 }, { 0, 0, 100 }, { 0, 0, -50 }, { -1.5, 0, 6.3 },
                                     { 1.25, 2.5, 7.5 }, { 0, 30000, 0 }, { -1.6, 0.1, 6.9 } };
    int ok = 1;
    long total = 0;
    for (size_t k = 0; k < sizeof pos / sizeof pos[0]; k++)
        for (int ang = 0; ang < 360; ang += 45) {
            struct scene *s = default_scene("raster-11");
            s->camera.position = v3_make(num_from_double(pos[k][0]), num_from_double(pos[k][1]), num_from_double(pos[k][2]));
            s->camera.rotation = m3_rot_y_deg(num_from_int(ang));
            s->ras.backface_cull = (uint8_t)(ang / 45 % 2);
            struct frame f;
            if (render_frame(s, 96, 64, 16, 0, &f)) ok = 0;
            total += frame_written(&f);
            frame_free(&f);
        }
    check(ok, "any_camera_position_renders", "render failed");
    printf("# any_camera: %ld pixels written over 64 camera placements\n", total);
}

/* Instance culling on the default path follows the frustum the image shows:
 * a small cube wholly in front of the book's near plane z = 1 but behind
 * d = 0.5, and one beside a viewport wider than the book's 45-degree planes,
 * must both be drawn (the book's planes would drop them). */
static void culling_follows_viewport(void)
{
    static const struct { const char *what; double vh, d, x, z, scale; } cases[] = {
        { "near_plane_d_0_5", 1.0, 0.5, 0.0, 0.8, 0.1 },
        { "wide_viewport_4", 4.0, 1.0, 2.0, 1.2, 0.2 },
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        static struct ras_instance in;
        struct scene *s = default_scene("raster-11");
        in = s->instances[0];
        in.position = v3_make(num_from_double(cases[k].x), NUM_ZERO, num_from_double(cases[k].z));
        in.rotation = m3_identity();
        in.scale = num_from_double(cases[k].scale);
        s->instances = &in;
        s->ninstances = 1;
        s->camera.position = v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        s->camera.rotation = m3_identity();
        s->viewport_h = num_from_double(cases[k].vh);
        s->projection_d = num_from_double(cases[k].d);
        struct frame f;
        int rc = render_frame(s, 320, 240, 16, 0, &f);
        long n = rc ? 0 : frame_written(&f);
        char name[96];
        snprintf(name, sizeof name, "instance_culling_%s", cases[k].what);
        check(n > 200, name, "cube drawn on %ld pixels (render status %d)", n, rc);
        frame_free(&f);
    }
}

/* Depth precision: two parallel quads 0.01 apart, the farther drawn first;
 * moving both away, the farther one starts to show through when the depth
 * format can no longer tell them apart. */
static double depth_fail_distance(int bits)
{
    static vec3 v[8];
    static struct ras_triangle t[4];
    static struct ras_model m;
    static struct ras_instance in;
    for (double z = 2; z < 2000; z *= 1.05) {
        struct scene *s = default_scene("raster-10");
        double zz[2] = { z + 0.01, z }; /* the far quad (blue) first */
        for (int q = 0; q < 2; q++) {
            v[q * 4 + 0] = v3_make(num_from_double(-z), num_from_double(-z), num_from_double(zz[q]));
            v[q * 4 + 1] = v3_make(num_from_double(z), num_from_double(-z), num_from_double(zz[q]));
            v[q * 4 + 2] = v3_make(num_from_double(z), num_from_double(z), num_from_double(zz[q]));
            v[q * 4 + 3] = v3_make(num_from_double(-z), num_from_double(z), num_from_double(zz[q]));
            static const int ix[2][3] = { { 0, 2, 1 }, { 0, 3, 2 } };
            for (int h = 0; h < 2; h++) {
                struct ras_triangle *tr = &t[q * 2 + h];
                memset(tr, 0, sizeof *tr);
                for (int k = 0; k < 3; k++) tr->v[k] = (uint16_t)(q * 4 + ix[h][k]);
                tr->color = q ? rgb_make(num_from_int(255), NUM_ZERO, NUM_ZERO) : rgb_make(NUM_ZERO, NUM_ZERO, num_from_int(255));
            }
        }
        /* the near quad, drawn second, hides the far one while depth can
         * tell them apart; ties keep the earlier (far) triangle */
        memset(&m, 0, sizeof m);
        m.nverts = 8; m.ntris = 4; m.verts = v; m.tris = t; m.bound_radius = num_from_int(30000);
        memset(&in, 0, sizeof in);
        in.texture = in.normal_map = -1;
        in.rotation = m3_identity();
        in.scale = NUM_ONE;
        s->models = &m; s->nmodels = 1; s->instances = &in; s->ninstances = 1;
        s->camera.position = v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        s->camera.rotation = m3_identity();
        s->ras.backface_cull = 0;
        s->ras.depth_bits = (uint8_t)bits;
        struct frame f;
        render_frame(s, 64, 64, 64, 0, &f);
        long blue = 0;
        for (long p = 0; p < 64 * 64; p++) blue += f.written[p] && f.rgb888[3 * p + 2] > 128;
        frame_free(&f);
        if (blue > 0) return z;
    }
    return 2000;
}

static void depth_precision(void)
{
    double z16 = depth_fail_distance(16), z32 = depth_fail_distance(32);
    printf("# depth: surfaces 0.01 apart (near plane 1) merge at z = %.1f with 16 bits, %.1f with 32 bits\n", z16, z32);
    check(z16 > 10 && z16 < 100 && z32 > z16, "depth16_fails_at_known_distance",
          "16-bit fails at %.1f, 32-bit at %.1f", z16, z32);
}


/* raster-10's "outlines" control: every pixel the outlines change gets a
 * cube colour x 0.75 (DrawLine, no depth test). */
static void outlines_raster10(void)
{
    struct frame a, b;
    struct scene *s = book_scene("raster-10");
    int rc = render_frame(s, 240, 240, 16, 0, &a);
    s = book_scene("raster-10");
    s->ras.outlines = 1;
    rc |= render_frame(s, 240, 240, 16, 0, &b);
    static const uint8_t cols[6][3] = { { 191, 0, 0 }, { 0, 191, 0 }, { 0, 0, 191 }, { 191, 191, 0 }, { 191, 0, 191 }, { 0, 191, 191 } };
    long changed = 0, bad = 0;
    for (long p = 0; !rc && p < 240L * 240; p++) {
        if (!memcmp(a.rgb888 + 3 * p, b.rgb888 + 3 * p, 3)) continue;
        changed++;
        int ok = 0;
        for (int k = 0; k < 6; k++) ok |= !memcmp(b.rgb888 + 3 * p, cols[k], 3);
        bad += !ok;
    }
    check(!rc && changed > 500 && bad == 0, "raster10_outlines", "%ld pixels changed (want > 500), %ld not a colour x 0.75", changed, bad);
    frame_free(&a);
    frame_free(&b);
}

/* A floor x in [-half, half], z from 3 to zfar, 1 under the camera, uv v = 1 at the near edge,
 * 0 at the far one; texture tex (w x h), shading none, default path. */
static struct scene *floor_scene(double half, double zfar, struct ras_texture *tex)
{
    static vec3 v[4];
    static struct ras_triangle t[2];
    static struct ras_model m;
    static struct ras_instance in;
    struct scene *s = default_scene("raster-13");
    v[0] = v3_make(num_from_double(-half), num_from_double(-1), num_from_double(3));
    v[1] = v3_make(num_from_double(half), num_from_double(-1), num_from_double(3));
    v[2] = v3_make(num_from_double(half), num_from_double(-1), num_from_double(zfar));
    v[3] = v3_make(num_from_double(-half), num_from_double(-1), num_from_double(zfar));
    static const int ix[2][3] = { { 0, 2, 1 }, { 0, 3, 2 } };
    static const double uv[4][2] = { { 0, 1 }, { 1, 1 }, { 1, 0 }, { 0, 0 } };
    for (int h = 0; h < 2; h++) {
        memset(&t[h], 0, sizeof t[h]);
        for (int k = 0; k < 3; k++) {
            t[h].v[k] = (uint16_t)ix[h][k];
            t[h].uv[k].u = num_from_double(uv[ix[h][k]][0]);
            t[h].uv[k].v = num_from_double(uv[ix[h][k]][1]);
        }
        t[h].color = rgb_make(num_from_int(255), num_from_int(255), num_from_int(255));
    }
    memset(&m, 0, sizeof m);
    m.nverts = 4; m.ntris = 2; m.verts = v; m.tris = t; m.has_uvs = 1;
    m.bound_center = v3_make(NUM_ZERO, num_from_int(-1), num_from_double((3 + zfar) / 2));
    m.bound_radius = num_from_double((zfar - 3) / 2 + 3);
    memset(&in, 0, sizeof in);
    in.texture = 0;
    in.normal_map = -1;
    in.rotation = m3_identity();
    in.scale = NUM_ONE;
    in.specular = num_from_int(-1);
    s->models = &m; s->nmodels = 1; s->instances = &in; s->ninstances = 1;
    s->textures = tex; s->ntextures = 1;
    s->camera.position = v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    s->camera.rotation = m3_identity();
    s->ras.shading = SHADE_NONE;
    s->ras.backface_cull = 0;
    return s;
}

/* Rows of column 120 the floor covers. */
static int floor_rows(const struct frame *f, int *top, int *bot)
{
    *top = -1;
    *bot = -1;
    for (int r = 0; r < f->h; r++)
        if (f->written[r * f->w + f->w / 2]) { if (*top < 0) *top = r; *bot = r; }
    return *top >= 0 && *bot - *top > 20;
}

/* uv = linear on the default path: v is screen-linear, so halfway between
 * the floor's far and near rows it is 1/2 (perspective-correct: 0.8). */
static void linear_uv_default(void)
{
    static uint8_t rows[4 * 256 * 3];
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 4; x++) { uint8_t *p = rows + 3 * (y * 4 + x); p[0] = (uint8_t)y; p[1] = 0; p[2] = 0; }
    static struct ras_texture tex;
    memset(&tex, 0, sizeof tex);
    tex.w = 4; tex.h = 256; tex.rgb = rows; tex.filter = TEX_NEAREST; tex.mip_levels = 1;
    int red[2] = { -1, -1 }, mid = -1;
    for (int persp = 0; persp < 2; persp++) {
        struct scene *s = floor_scene(1, 12, &tex);
        s->ras.perspective_uv = (uint8_t)persp;
        struct frame f;
        int top, bot;
        if (!render_frame(s, 240, 240, 16, 0, &f) && floor_rows(&f, &top, &bot)) {
            mid = (top + bot) / 2;
            red[persp] = f.rgb888[3 * (mid * 240 + 120)];
        }
        frame_free(&f);
    }
    /* expected: v interpolated linearly on screen inside the triangle that
     * holds the pixel centre (120.5, mid + 0.5); perspective: v of the
     * floor point seen there */
    /* inside the view volume, so no clipping adds corners */
    static const double P[4][3] = { { -1, 3, 1 }, { 1, 3, 1 }, { 1, 12, 0 }, { -1, 12, 0 } }; /* x, z, v */
    static const int T[2][3] = { { 0, 2, 1 }, { 0, 3, 2 } };
    double px = 120.5, py = mid + 0.5, want_lin = -1;
    for (int h = 0; h < 2; h++) {
        double X[3], Y[3], V[3];
        for (int k = 0; k < 3; k++) {
            const double *q = P[T[h][k]];
            X[k] = 120 + q[0] / q[1] * 240;
            Y[k] = 120 + 1.0 / q[1] * 240;
            V[k] = q[2];
        }
        double den = (Y[1] - Y[2]) * (X[0] - X[2]) + (X[2] - X[1]) * (Y[0] - Y[2]);
        double l0 = ((Y[1] - Y[2]) * (px - X[2]) + (X[2] - X[1]) * (py - Y[2])) / den;
        double l1 = ((Y[2] - Y[0]) * (px - X[2]) + (X[0] - X[2]) * (py - Y[2])) / den, l2 = 1 - l0 - l1;
        if (l0 >= 0 && l1 >= 0 && l2 >= 0) want_lin = (l0 * V[0] + l1 * V[1] + l2 * V[2]) * 256;
    }
    double z = 240.0 / (py - 120), want_persp = (12 - z) / 9 * 256;
    check(mid > 0 && want_lin >= 0 && red[0] >= want_lin - 3 && red[0] <= want_lin + 3 && red[1] >= want_persp - 3 &&
          red[1] <= want_persp + 3, "default_path_linear_uv",
          "texture row at row %d: linear %d (want %.1f), perspective %d (want %.1f)", mid, red[0], want_lin, red[1], want_persp);
    printf("# uv at row %d: linear %d (screen-linear %.1f), perspective %d (%.1f)\n", mid, red[0], want_lin, red[1], want_persp);
}

/* Trilinear: level k of a mip chain is the solid colour (32k, 0, 255 - 32k),
 * so red/32 reads the level (and the blend between two) a pixel used. A
 * floor receding from z = 3 to 60 must pick non-decreasing levels from its
 * near edge to its far one, from below 1 to above 3. */
static void trilinear_levels(void)
{
    static uint8_t lv[7][64 * 64 * 3];
    static const uint8_t *mip[7];
    for (int k = 0; k < 7; k++) {
        int n = 64 >> k;
        for (int i = 0; i < n * n; i++) { lv[k][3 * i] = (uint8_t)(32 * k); lv[k][3 * i + 1] = 0; lv[k][3 * i + 2] = (uint8_t)(255 - 32 * k); }
        mip[k] = lv[k];
    }
    static struct ras_texture tex;
    memset(&tex, 0, sizeof tex);
    tex.w = 64; tex.h = 64; tex.rgb = lv[0]; tex.filter = TEX_TRILINEAR; tex.mip_levels = 7; tex.mip = mip;
    struct scene *s = floor_scene(2, 60, &tex);
    struct frame f;
    int top = 0, bot = 0, ok = !render_frame(s, 240, 240, 16, 0, &f) && floor_rows(&f, &top, &bot);
    double prev = -1, near_l = -1, far_l = -1, worst = 0;
    for (int r = bot; ok && r >= top; r--) {
        double l = f.rgb888[3 * (r * 240 + 120)] / 32.0;
        if (prev >= 0 && prev - l > worst) worst = prev - l;
        if (near_l < 0) near_l = l;
        far_l = l;
        prev = l;
    }
    printf("# trilinear: level %.2f at the near edge (row %d), %.2f at the far edge (row %d)\n", near_l, bot, far_l, top);
    check(ok && worst <= 1.0 / 32 + 1e-9 && near_l < 1 && far_l > 3, "trilinear_level_increases_with_depth",
          "levels %.2f (near) .. %.2f (far), largest step back %.3f", near_l, far_l, worst);
    frame_free(&f);
}

int main(void)
{
    strips_identical();
    strip_order_free();
    vertex_lighting_same();
    sibling_shares_frame();
    split_preparation_same_frames();
    fill_rule_closed_mesh();
    fast_coverage_exact();
    any_camera();
    culling_follows_viewport();
    depth_precision();
    outlines_raster10();
    linear_uv_default();
    trilinear_levels();
    return check_exit();
}
