/* test_raster.c — the default path's promises, in one numeric mode:
 * strips give identical images, the top-left rule writes every pixel of a
 * closed mesh exactly once, any camera position is safe, 16-bit depth
 * fails only beyond a known distance. */
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "raster_harness.h"
#include "raster_scenes.h"

static struct scene *default_scene(const char *name)
{
    struct scene *s = ras_test_scene(name);
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
                struct scene *s = book ? ras_test_scene(names[n]) : default_scene(names[n]);
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
            s->camera.position = v3(num_from_double(pos[k][0]), num_from_double(pos[k][1]), num_from_double(pos[k][2]));
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
            v[q * 4 + 0] = v3(num_from_double(-z), num_from_double(-z), num_from_double(zz[q]));
            v[q * 4 + 1] = v3(num_from_double(z), num_from_double(-z), num_from_double(zz[q]));
            v[q * 4 + 2] = v3(num_from_double(z), num_from_double(z), num_from_double(zz[q]));
            v[q * 4 + 3] = v3(num_from_double(-z), num_from_double(z), num_from_double(zz[q]));
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
        s->camera.position = v3(NUM_ZERO, NUM_ZERO, NUM_ZERO);
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

int main(void)
{
    strips_identical();
    fill_rule_closed_mesh();
    any_camera();
    depth_precision();
    return check_exit();
}
