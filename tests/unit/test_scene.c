/* SPDX-License-Identifier: MIT */
/* test_scene — the scene parser: every book scene parses with the expected
 * contents, the book's doubles survive exactly (double build), and bad input
 * gets exit status 2 with the expected message at the expected position.
 * Built once per numeric mode (test_scene_fixed, _float, _double). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "scene_parse.h"

#ifndef SCENE_DIR
#define SCENE_DIR "firmware/scenes/"
#endif

struct expect {
    const char *name;
    int kind, nobjects, nlights, nmodels, ninstances, ntextures, nprims, nlines;
    int ntris;    /* triangles over all instances (rasterizer) */
};

static const struct expect book[] = {
    { "raytracer-01", SCENE_RAYTRACE, 4, 0, 0, 0, 0, 0, 0, 0 },
    { "raytracer-02", SCENE_RAYTRACE, 4, 3, 0, 0, 0, 0, 0, 0 },
    { "raytracer-03", SCENE_RAYTRACE, 4, 3, 0, 0, 0, 0, 0, 0 },
    { "raytracer-04", SCENE_RAYTRACE, 4, 3, 0, 0, 0, 0, 0, 0 },
    { "raytracer-05", SCENE_RAYTRACE, 4, 3, 0, 0, 0, 0, 0, 0 },
    { "raytracer-06", SCENE_RAYTRACE, 4, 3, 0, 0, 0, 0, 0, 0 },
    { "raster-01", SCENE_RASTER, 0, 0, 0, 0, 0, 2, 0, 0 },
    { "raster-02", SCENE_RASTER, 0, 0, 0, 0, 0, 2, 0, 0 },
    { "raster-03", SCENE_RASTER, 0, 0, 0, 0, 0, 2, 0, 0 },
    { "raster-04", SCENE_RASTER, 0, 0, 0, 0, 0, 1, 0, 0 },
    { "raster-05", SCENE_RASTER, 0, 0, 0, 0, 0, 0, 12, 0 },
    { "raster-06", SCENE_RASTER, 0, 0, 1, 1, 0, 0, 0, 12 },
    { "raster-07", SCENE_RASTER, 0, 0, 1, 2, 0, 0, 0, 24 },
    { "raster-08", SCENE_RASTER, 0, 0, 1, 2, 0, 0, 0, 24 },
    { "raster-09", SCENE_RASTER, 0, 0, 1, 3, 0, 0, 0, 36 },
    { "raster-10", SCENE_RASTER, 0, 0, 1, 2, 0, 0, 0, 24 },
    { "raster-11", SCENE_RASTER, 0, 3, 2, 3, 0, 0, 0, 474 },
    { "raster-12", SCENE_RASTER, 0, 3, 1, 3, 1, 0, 0, 36 },
    { "raster-13", SCENE_RASTER, 0, 3, 2, 2, 1, 0, 0, 24 },
    { "raster-rt-scene", SCENE_RASTER, 0, 3, 4, 4, 0, 0, 0, 1262 },
};

static int is_double_build(void) { return strcmp(NUM_NAME, "double") == 0; }

static void test_book(void)
{
    char path[256], err[512], name[128];
    for (size_t i = 0; i < sizeof book / sizeof book[0]; i++) {
        const struct expect *e = &book[i];
        struct scene *s = NULL;
        snprintf(path, sizeof path, SCENE_DIR "book/%s.scene", e->name);
        snprintf(name, sizeof name, "book_%s_parses_%s", e->name, NUM_NAME);
        int rc = scene_load(path, &s, err, sizeof err);
        if (!check(rc == 0, name, "%s", err)) continue;
        int ntris = 0;
        for (int k = 0; k < s->ninstances; k++) ntris += s->models[s->instances[k].model].ntris;
        snprintf(name, sizeof name, "book_%s_contents_%s", e->name, NUM_NAME);
        check(!strcmp(s->name, e->name) && s->kind == e->kind && s->nobjects == e->nobjects &&
                  s->nlights == e->nlights && s->nmodels == e->nmodels && s->ninstances == e->ninstances &&
                  s->ntextures == e->ntextures && s->nprims == e->nprims && s->nlines == e->nlines &&
                  ntris == e->ntris && s->canvas_w == 600 && s->canvas_h == 600 && s->frames == 1,
              name, "name %s kind %d objects %d lights %d models %d instances %d textures %d prims %d lines %d tris %d",
              s->name, s->kind, s->nobjects, s->nlights, s->nmodels, s->ninstances, s->ntextures, s->nprims,
              s->nlines, ntris);
        scene_free(s);
    }
}

static struct scene *load_book(const char *n)
{
    char path[256], err[512];
    struct scene *s = NULL;
    snprintf(path, sizeof path, SCENE_DIR "book/%s.scene", n);
    if (scene_load(path, &s, err, sizeof err)) {
        printf("FAIL load_%s: %s\n", n, err);
        return NULL;
    }
    return s;
}

/* The book's numbers as the double build must hold them (docs/book-demos.md). */
static void test_exact_values(void)
{
    char name[128];
    struct scene *s = load_book("raytracer-06");
    if (s) {
        snprintf(name, sizeof name, "raytracer06_camera_literal_%s", NUM_NAME);
        double m00 = num_to_double(s->camera.rotation.m[0][0]);
        double m02 = num_to_double(s->camera.rotation.m[0][2]);
        check(is_double_build() ? (m00 == 0.7071 && m02 == -0.7071) : (m00 > 0.7070 && m00 < 0.7072), name,
              "m00 %.17g m02 %.17g", m00, m02);
        snprintf(name, sizeof name, "raytracer06_options_%s", NUM_NAME);
        check(s->rt.recursion_depth == 3 && num_to_double(s->rt.t_min_primary) == 1 && !s->rt.unlit &&
                  s->objects[3].mat.specular == num_from_int(1000) && s->lights[2].type == LIGHT_DIRECTIONAL,
              name, "depth %d", s->rt.recursion_depth);
        scene_free(s);
    }
    s = load_book("raytracer-01");
    if (s) {
        snprintf(name, sizeof name, "raytracer01_unlit_%s", NUM_NAME);
        check(s->rt.unlit == 1 && s->background_set && s->objects[3].radius == num_from_int(5000), name, "unlit %d",
              s->rt.unlit);
        scene_free(s);
    }
    s = load_book("raster-08");
    if (s) {
        /* RotY(195) from the demo's constants; RotY(-30) for the camera */
        const mat3 *r = &s->instances[1].rotation;
        snprintf(name, sizeof name, "raster08_roty_constants_%s", NUM_NAME);
        if (is_double_build())
            check(num_to_double(r->m[0][0]) == -0.96592582628906842 && num_to_double(r->m[0][2]) == 0.25881904510252035 &&
                      num_to_double(r->m[2][0]) == -0.25881904510252035 &&
                      num_to_double(s->camera.rotation.m[0][0]) == 0.86602540378443871 &&
                      num_to_double(s->camera.rotation.m[2][0]) == -0.49999999999999994 &&
                      num_to_double(s->instances[0].scale) == 0.75,
                  name, "m00 %.17g", num_to_double(r->m[0][0]));
        else
            check(num_to_double(r->m[0][0]) < -0.9659 && num_to_double(r->m[0][0]) > -0.9660, name, "m00 %.17g",
                  num_to_double(r->m[0][0]));
        snprintf(name, sizeof name, "raster08_options_%s", NUM_NAME);
        check(s->ras.wireframe && !s->ras.project_truncate && !s->ras.clip && !s->ras.depth_test &&
                  !s->ras.backface_cull && s->ras.instance_transform && s->ras.camera_transform && s->ras.book_exact,
              name, "options differ");
        scene_free(s);
    }
    s = load_book("raster-13");
    if (s) {
        snprintf(name, sizeof name, "raster13_roty0_negative_zero_%s", NUM_NAME);
        double m02 = num_to_double(s->camera.rotation.m[0][2]);
        check(m02 == 0 && (!is_double_build() || 1 / m02 < 0), name, "m02 %g", m02);
        const struct ras_texture *t = &s->textures[0];
        snprintf(name, sizeof name, "raster13_checkerboard_%s", NUM_NAME);
        /* white when floor(x/10) + floor(y/10) is even; top-left white */
        check(t->w == 400 && t->h == 400 && t->filter == TEX_BILINEAR_BOOK && t->rgb[0] == 255 &&
                  t->rgb[3 * 10] == 0 && t->rgb[3 * (400 * 10 + 10)] == 255 && t->rgb[3 * (400 * 399 + 9)] == 0,
              name, "texture differs");
        const struct ras_model *sph = &s->models[1];
        snprintf(name, sizeof name, "raster13_sphere_s420_%s", NUM_NAME);
        check(sph->nverts == 240 && sph->ntris == 420 && sph->has_normals && sph->tris[0].v[1] == 16 &&
                  sph->tris[1].v[2] == 16,
              name, "verts %d tris %d", sph->nverts, sph->ntris);
        scene_free(s);
    }
    s = load_book("raster-11");
    if (s) {
        const struct ras_model *sph = &s->models[1];
        /* ring 1 of GenerateSphere(15): y -0.8666666666666667, rho 0.49888765156985881 */
        vec3 v = sph->verts[15 + 2];
        snprintf(name, sizeof name, "raster11_sphere_ring_values_%s", NUM_NAME);
        if (is_double_build())
            check(num_to_double(v.y) == -0.8666666666666667 &&
                      num_to_double(v.x) == 0.49888765156985881 * 0.66913060635885824 &&
                      num_to_double(v.z) == 0.49888765156985881 * 0.74314482547739424 &&
                      num_to_double(sph->verts[15 * 7].y) == -0.066666666666666666 &&
                      num_to_double(sph->verts[15 * 7].x) == 0.99777530313971774 &&
                      num_to_double(sph->verts[15 * 15].y) == 1,
                  name, "vertex %.17g %.17g %.17g", num_to_double(v.x), num_to_double(v.y), num_to_double(v.z));
        else
            check(num_to_double(v.y) > -0.8667 && num_to_double(v.y) < -0.8666, name, "y %g", num_to_double(v.y));
        snprintf(name, sizeof name, "raster11_sphere_s450_%s", NUM_NAME);
        check(sph->ntris == 450 && sph->tris[0].v[0] == 0 && sph->tris[0].v[1] == 16 && sph->tris[0].v[2] == 1 &&
                  sph->tris[29].v[1] == 29 && sph->tris[29].v[2] == 15 && sph->tris[28].v[1] == 15 && sph->tris[28].v[2] == 0 &&
                  num_to_double(sph->bound_radius) == 1,
              name, "tri 28 %d %d %d", sph->tris[28].v[0], sph->tris[28].v[1], sph->tris[28].v[2]);
        snprintf(name, sizeof name, "raster11_cube_bound_%s", NUM_NAME);
        check(!is_double_build() || num_to_double(s->models[0].bound_radius) == 1.7320508075688772, name, "%.17g",
              num_to_double(s->models[0].bound_radius));
        snprintf(name, sizeof name, "raster11_lights_%s", NUM_NAME);
        check(s->nlights == 3 && s->lights[2].type == LIGHT_POINT && s->lights[2].v.z == num_from_int(-10) &&
                  s->ras.shading == SHADE_PHONG && s->instances[2].specular == num_from_int(50),
              name, "lights differ");
        scene_free(s);
    }
}

struct bad {
    const char *text;
    const char *msg;       /* expected "L:C: error: MESSAGE-prefix" after the file name */
};

static const struct bad bad_cases[] = {
    { "", "1:1: error: empty file" },
    { "# only a comment\n", "1:1: error: the file has no scene in it" },
    { "sphere { center = (0, 0, 3) radius = 1 color = (255, 0, 0) colour = 1 }", "1:60: error: unknown key 'colour' in sphere" },
    { "sphere { center = (0, 0, 3) radius = 1 radius = 2 color = (1, 2, 3) }", "1:40: error: duplicate 'radius' in sphere (first at 1:29)" },
    { "sphere { center = (0, 0, 3) color = (1, 2, 3) }", "1:1: error: sphere: missing 'radius'" },
    { "sphere { center = (0, 0) radius = 1 color = (1, 2, 3) }", "1:19: error: sphere center must have 3 components, found 2" },
    { "sphere { center = (0, 0, 3) radius = red color = (1, 2, 3) }", "1:38: error: sphere radius must be a number, found a name" },
    { "sphere { center = (0, 0, 3) radius = -1 color = (1, 2, 3) }", "1:38: error: sphere radius must be > 0" },
    { "sphere { center = (0, 0, 3) radius = 1 color = (1, 2, 300) }", "1:48: error: color: channel 300 is outside 0 .. 255" },
    { "instance { model = cube }", "1:20: error: instance: no model named 'cube'" },
    { "sphere { center = (0, 0, 3) radius = 1 color = (1, 2, 3) ", "1:58: error: missing '}' (block opened at 1:8)" },
    { "sphere { center = (0, 0, 3 radius = 1 }", "1:28: error: expected ',' or ')' in tuple opened at 1:19, found a name" },
    { "sphere { center = (0, 0, 3) radius = 1.5.2 }", "1:38: error: malformed number" },
    { "sphere { center = (0, 0, 3) radius = 1 color = (1, 2, 3) }\n\x01", "2:1: error: unexpected byte 0x01" },
    { "sphere @", "1:8: error: unexpected character '@'" },
    { "sphere { center = (0, 0, 3) radius = 1e999 color = (1, 2, 3) }", "1:38: error: number 1e999 is too large" },
    { "light { type = spot intensity = 1 }", "1:16: error: light type: unknown value 'spot'" },
    { "light { type = point intensity = 0.5 }\nsphere { center = (0, 0, 3) radius = 1 color = (1, 2, 3) }", "1:1: error: point light: missing 'position'" },
    { "camera { position = (0, 0, 0) }", "1:1: error: the scene has nothing to draw" },
    { "background = (0, 0, 0)\nbackground = (1, 1, 1)\nline2d { p0 = (0, 0) p1 = (1, 1) color = (0, 0, 0) }", "2:1: error: duplicate 'background' (first at 1:1)" },
    { "foo = 1", "1:1: error: unknown key 'foo'" },
    { "model { name = m vertices { (0, 0, 0) (1, 0, 0) (0, 1, 0) } triangles { (0, 1, 3, color = (1, 1, 1)) } }",
      "1:80: error: vertex index must be in 0 .. 2, found 3" },
    { "model { name = m vertices { } triangles { (0, 1, 2) } }", "1:27: error: model 'm' has no vertices" },
    { "model { name = m generate = sphere divs = 15 }", "1:1: error: generated model: missing 'color'" },
    { "model { name = m generate = sphere divs = 1000 color = (1, 1, 1) }", "1:43: error: divs must be in 3 .. 128, found 1000" },
    { "texture { name = t file = \"../etc/passwd\" }", "1:27: error: image files need a scene file" },
    { "texture { name = t generate = checkerboard width = 100000 height = 1 }", "1:52: error: texture width must be in 1 .. 1024" },
    { "raytracer { recursion_depth = 2.5 }\nsphere { center = (0, 0, 3) radius = 1 color = (1, 2, 3) }", "1:31: error: recursion_depth must be a whole number" },
    { "rasterizer { shading = phong }\nsphere { center = (0, 0, 3) radius = 1 color = (1, 2, 3) }", "1:1: error: 'rasterizer' options in a ray-traced scene" },
    { "sphere { center = (0, 0, 3) radius = 1 color = (1, 2, 3) }\nline2d { p0 = (0, 0) p1 = (1, 1) color = (0, 0, 0) }", "1:1: error: the scene mixes" },
    { "sphere { center = ((((((((((((((((((((((((((((((((((1)))))))))))))))))))))))))))))))))) }", "1:50: error: nesting deeper than 32" },
    { "sphere { center = (0, 0, 3) radius = 1 color = (1, 2, 3) name = \"abc }", "1:65: error: unterminated string" },
    { "(1, 2, 3)", "1:1: error: expected 'key = value' or 'key { ... }' at the top level, found a tuple" },
    { "sphere = 3", "1:10: error: sphere must be a block { ... }, found a number" },
    { "camera { rotation { y = 10 rows = ((1,0,0),(0,1,0),(0,0,1)) } }\nline2d { p0 = (0, 0) p1 = (1, 1) color = (0, 0, 0) }", "1:28: error: camera rotation: 'rows' cannot be combined with angles" },
    { "frames = 0\nline2d { p0 = (0, 0) p1 = (1, 1) color = (0, 0, 0) }", "1:10: error: frames must be in 1 .. 10000, found 0" },
    { "csg { op = union a = x b = y }\nsphere { center = (0, 0, 3) radius = 1 color = (1, 2, 3) }", "1:22: error: csg a: no object named 'x'" },
};

/* Out-of-range values for the build's numbers: only the fixed build has
 * |x| < 32768 (Q15.16). */
static void test_bad(void)
{
    char err[512], name[128], want[512];
    for (size_t i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++) {
        struct scene *s = NULL;
        int rc = scene_parse_mem("bad.scene", bad_cases[i].text, strlen(bad_cases[i].text), &s, err, sizeof err);
        snprintf(name, sizeof name, "bad_input_%02zu_%s", i, NUM_NAME);
        snprintf(want, sizeof want, "bad.scene:%s", bad_cases[i].msg);
        check(rc == SCENE_EINPUT && s == NULL && !strncmp(err, want, strlen(want)), name, "rc %d: got \"%s\", want \"%s...\"", rc,
              rc ? err : "", want);
        if (rc == 0) scene_free(s);
    }
    const char *big = "sphere { center = (0, 0, 40000) radius = 1 color = (1, 2, 3) }";
    struct scene *s = NULL;
    int rc = scene_parse_mem("big.scene", big, strlen(big), &s, err, sizeof err);
    snprintf(name, sizeof name, "out_of_range_for_mode_%s", NUM_NAME);
    if (!strcmp(NUM_NAME, "fixed"))
        check(rc == SCENE_EINPUT && strstr(err, "big.scene:1:19: error: sphere center: 40000 is out of range for fixed numbers"),
              name, "rc %d %s", rc, err);
    else
        check(rc == 0, name, "rc %d %s", rc, err);
    if (rc == 0) scene_free(s);

    /* a file over the size cap */
    size_t n = SCENE_MAX_BYTES + 10;
    char *huge = malloc(n);
    memset(huge, ' ', n);
    rc = scene_parse_mem("huge.scene", huge, n, &s, err, sizeof err);
    snprintf(name, sizeof name, "huge_file_refused_%s", NUM_NAME);
    check(rc == SCENE_EINPUT && strstr(err, "huge.scene:1:1: error: file larger than"), name, "rc %d %s", rc, err);
    free(huge);

    rc = scene_load("/nonexistent/x.scene", &s, err, sizeof err);
    snprintf(name, sizeof name, "missing_file_%s", NUM_NAME);
    check(rc == SCENE_EIO && !strncmp(err, "/nonexistent/x.scene:1:1: error: cannot open file", 49), name, "%s", err);
}

/* The automatic depth bits (tools/scene/scene_depth.c): two squares `gap`
 * apart at distance z, tilted 30 degrees (tools/scene/gen_sweep.py's depth
 * sweep). */
static int depth_choice(double z, double gap, const char *opts, struct scene_depth_facts *f)
{
    char text[2048], err[600];
    double h = 0.9 * z;
    snprintf(text, sizeof text,
             "renderer = rasterizer\ncanvas { width = 240 height = 240 }\nviewport { width = 1 height = 1 d = 1 }\n"
             "rasterizer { book_exact = off clip = split shading = none %s }\n"
             "model { name = far color = (0, 0, 255) vertices { (%g, %g, %g) (%g, %g, %g) (%g, %g, %g) (%g, %g, %g) }\n"
             "  triangles { (0, 2, 1) (0, 3, 2) } }\n"
             "model { name = near color = (255, 0, 0) vertices { (%g, %g, 0) (%g, %g, 0) (%g, %g, 0) (%g, %g, 0) }\n"
             "  triangles { (0, 2, 1) (0, 3, 2) } }\n"
             "instance { model = far transform { rotation { x = 30 } translation = (0, 0, %g) } }\n"
             "instance { model = near transform { rotation { x = 30 } translation = (0, 0, %g) } }\n",
             opts, -h, -h, gap, h, -h, gap, h, h, gap, -h, h, gap, -h, -h, h, -h, h, h, -h, h, z, z);
    struct scene *s = NULL;
    if (scene_parse_mem("depth.scene", text, strlen(text), &s, err, sizeof err)) {
        check(0, "depth_parse", "%s", err);
        return -1;
    }
    int bits = s->ras.depth_bits, again = scene_depth_bits(s, f);
    if (!strstr(opts, "depth_bits"))
        check(bits == again, "depth_parse_same", "parse %d, scene_depth_bits %d", bits, again);
    scene_free(s);
    return bits;
}

static void test_depth_bits(void)
{
    struct scene_depth_facts f;
    /* far from each other: both rules say 16 */
    int b = depth_choice(10, 1, "depth = on", &f);
    check(b == 16 && !f.range_wants32 && !f.overlap_wants32 && f.overlap_checked, "depth_bits_apart", "%d", b);
    /* 0.01 apart at z = 40: the range rule alone says 16 (the radius grows with
       z); near/z of the two differs by about 0.01/z^2 = 0.4 of a 16-bit step */
    b = depth_choice(40, 0.01, "depth = on", &f);
    check(b == 32 && !f.range_wants32 && f.overlap_wants32, "depth_bits_close_overlap", "%d range %d pixels %ld",
          b, f.range_wants32, f.close_pixels);
    check(f.gap_min * 65536 > 0.2 && f.gap_min * 65536 < 0.6, "depth_bits_gap", "%g steps", f.gap_min * 65536);
    /* the same 0.01 at z = 3: 17 steps apart */
    b = depth_choice(3, 0.01, "depth = on", &f);
    check(b == 16 && f.close_pixels == 0, "depth_bits_close_near", "%d, %ld pixels", b, f.close_pixels);
    /* coplanar (a tie in either format): not a reason for 32 bits */
    b = depth_choice(40, 0, "depth = on", &f);
    check(b == 16 && f.close_pixels == 0, "depth_bits_coplanar", "%d, %ld pixels", b, f.close_pixels);
    /* as the scene asks */
    b = depth_choice(40, 0.01, "depth = on depth_bits = 16", &f);
    check(b == 16, "depth_bits_asked", "%d", b);
    /* depth off: no overlap measured */
    b = depth_choice(40, 0.01, "depth = off", &f);
    check(!f.overlap_checked, "depth_bits_depth_off", "%d", b);
}

int main(void)
{
    test_book();
    test_exact_values();
    test_bad();
    test_depth_bits();
    return check_exit();
}
