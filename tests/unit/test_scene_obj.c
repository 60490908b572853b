/* SPDX-License-Identifier: MIT */
/* test_scene_obj — models read from Wavefront OBJ files (docs/scene-format.md,
 * "Model files"): the fixtures of tests/data/obj/ parse into the models,
 * parts, textures and instances they describe (negative indices, quads and a
 * pentagon split into triangles, v turned to 1 - v, Kd as the colour, fit),
 * and bad files give their exact message at the exact line and column of
 * the model, material or scene file. Built once per numeric mode
 * (test_scene_obj_fixed, _float, _double). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "scene_parse.h"

#define OBJ_DIR "tests/data/obj/"

static char name[160];

static const char *tag(const char *what)
{
    snprintf(name, sizeof name, "%s_%s", what, NUM_NAME);
    return name;
}

static struct scene *load(const char *file)
{
    char err[600];
    struct scene *s = NULL;
    int rc = scene_load(file, &s, err, sizeof err);
    check(rc == 0, tag(file + strlen(OBJ_DIR)), "%s", err);
    return rc ? NULL : s;
}

static int near(num x, double want) { return fabs(num_to_double(x) - want) <= 1e-4; }

static int uv_is(struct tri_uv t, double u, double v) { return near(t.u, u) && near(t.v, v); }

static int vec_is(vec3 a, double x, double y, double z) { return near(a.x, x) && near(a.y, y) && near(a.z, z); }

static void test_cube(void)
{
    struct scene *s = load(OBJ_DIR "obj-cube.scene");
    if (!s) return;
    const struct ras_model *m = &s->models[0];
    check(s->nmodels == 1 && s->ninstances == 2 && s->ntextures == 1 && !strcmp(m->name, "cube") &&
              m->nverts == 8 && m->ntris == 12 && m->has_normals && m->has_uvs,
          tag("obj_cube_counts"), "models %d instances %d textures %d verts %d tris %d", s->nmodels, s->ninstances,
          s->ntextures, m->nverts, m->ntris);
    /* the second quad, f -4/-4/-1 -8/-3/-1 -5/-2/-1 -1/-1/-1 after 8 v, 4 vt, 2 vn: corners 4 0 3 7 */
    const struct ras_triangle *t = &m->tris[2], *u = &m->tris[3];
    check(t->v[0] == 4 && t->v[1] == 0 && t->v[2] == 3 && u->v[0] == 4 && u->v[1] == 3 && u->v[2] == 7 &&
              vec_is(t->n[0], 1, 0, 0) && vec_is(u->n[2], 1, 0, 0),
          tag("obj_negative_indices"), "%d %d %d / %d %d %d", t->v[0], t->v[1], t->v[2], u->v[0], u->v[1], u->v[2]);
    /* vt 0 1, 1 1, 1 0: v = 0 at the bottom of the image, the scene's v = 0 at the top */
    check(uv_is(t->uv[0], 0, 0) && uv_is(t->uv[1], 1, 0) && uv_is(t->uv[2], 1, 1) && uv_is(u->uv[2], 0, 1),
          tag("obj_uv_flipped"), "uv (%g, %g)", num_to_double(t->uv[1].u), num_to_double(t->uv[1].v));
    /* the face continued on the next line: f 6/1/3 5/2/3 \ 8/3/3 7/4/3 */
    check(m->tris[4].v[0] == 5 && m->tris[5].v[1] == 7 && m->tris[5].v[2] == 6 && vec_is(m->tris[5].n[1], 0, 0, -1),
          tag("obj_continued_line"), "%d %d", m->tris[5].v[1], m->tris[5].v[2]);
    check(near(t->color.r, 127.5) && near(t->color.g, 63.75) && near(t->color.b, 255), tag("obj_kd_colour"),
          "%g %g %g", num_to_double(t->color.r), num_to_double(t->color.g), num_to_double(t->color.b));
    check(vec_is(m->bound_center, 0, 0, 0) && near(m->bound_radius, 1.7320508075688772), tag("obj_default_bound"),
          "radius %g", num_to_double(m->bound_radius));
    const struct ras_texture *tx = &s->textures[0];
    /* checker.png: 8x8 paletted, white and (20, 110, 40) squares of 2 texels */
    check(tx->w == 8 && tx->h == 8 && tx->rgb[0] == 255 && tx->rgb[3 * 2] == 20 && tx->rgb[3 * 2 + 1] == 110 &&
              tx->rgb[3 * (8 * 2 + 2)] == 255 && s->instances[0].texture == 0 && s->instances[1].texture == -1,
          tag("png_texture"), "%dx%d %d", tx->w, tx->h, tx->rgb[0]);
    scene_free(s);

    s = load(OBJ_DIR "obj-cube-fit.scene");
    if (!s) return;
    m = &s->models[0];
    double r = 0;
    int ok = m->nverts == 8;
    for (int i = 0; i < m->nverts; i++) {
        double x = num_to_double(m->verts[i].x), y = num_to_double(m->verts[i].y), z = num_to_double(m->verts[i].z);
        ok &= fabs(fabs(x) - 1) < 1e-5 && fabs(fabs(y) - 1) < 1e-5 && fabs(fabs(z) - 1) < 1e-5;
        if (sqrt(x * x + y * y + z * z) > r) r = sqrt(x * x + y * y + z * z);
    }
    check(ok && fabs(r - 1.7320508075688772) < 1e-5 && near(m->bound_radius, 1.7320508075688772) &&
              vec_is(m->bound_center, 0, 0, 0) && vec_is(m->verts[0], 1, 1, 1),
          tag("obj_fit"), "farthest vertex %.9g", r);
    scene_free(s);
}

static void test_parts(void)
{
    struct scene *s = load(OBJ_DIR "obj-two.scene");
    if (!s) return;
    const struct ras_model *m = s->models;
    check(s->nmodels == 3 && s->ninstances == 3 && s->ntextures == 2 && !strcmp(m[0].name, "two") &&
              !strcmp(m[1].name, "two:1") && !strcmp(m[2].name, "two:2"),
          tag("obj_parts"), "models %d instances %d textures %d", s->nmodels, s->ninstances, s->ntextures);
    if (s->nmodels != 3 || s->ninstances != 3 || s->ntextures != 2) {
        scene_free(s);
        return;
    }
    /* part 0: the red quad and the blue pentagon (vertices 1 2 4 5 7 8 10 of the file) */
    check(m[0].nverts == 7 && m[0].ntris == 5 && !m[0].has_uvs && m[0].has_normals && m[0].tris[0].v[2] == 3 &&
              m[0].tris[4].v[0] == 2 && m[0].tris[4].v[1] == 6 && m[0].tris[4].v[2] == 4 &&
              vec_is(m[0].verts[6], -1, -2, 5) && near(m[0].tris[0].color.r, 255) && near(m[0].tris[4].color.b, 255) &&
              near(m[0].tris[4].color.r, 0),
          tag("obj_part_untextured"), "verts %d tris %d", m[0].nverts, m[0].ntris);
    check(m[1].nverts == 4 && m[1].ntris == 2 && m[1].has_uvs && m[2].nverts == 4 && m[2].has_uvs &&
              vec_is(m[2].verts[0], 0, 0, 5),
          tag("obj_part_textured"), "verts %d %d", m[1].nverts, m[2].nverts);
    const struct ras_instance *in = s->instances;
    const struct ras_texture *t = s->textures;
    /* tiles.png (4x4, a yellow top row) and stripes.ppm (4x2), read once each; 'unused' not at all */
    check(in[0].model == 0 && in[1].model == 1 && in[2].model == 2 && in[0].texture == -1 && in[1].texture == 0 &&
              in[2].texture == 1 && t[0].w == 4 && t[0].h == 4 && t[0].rgb[0] == 250 && t[0].rgb[3 * 4 + 1] == 200 &&
              t[1].w == 4 && t[1].h == 2 && t[1].rgb[0] == 240,
          tag("obj_part_instances"), "textures %d %d %d", in[0].texture, in[1].texture, in[2].texture);
    scene_free(s);
}

/* ---- bad files ---------------------------------------------------------------- */

static char dir[64];

static void put(const char *file, const char *text, size_t len)
{
    char path[160];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(text, 1, len, f) != len || fclose(f)) {
        printf("FAIL %s: cannot write %s\n", tag("obj_fixture"), path);
        exit(1);
    }
}

static void put_str(const char *file, const char *text) { put(file, text, strlen(text)); }

/* Loads DIR/s.scene; the error must begin with DIR/msg, each '@' of msg standing for "DIR/". */
static void expect(const char *what, const char *msg)
{
    char path[160], err[600], want[600];
    size_t k = (size_t)snprintf(want, sizeof want, "%s/", dir);
    for (const char *c = msg; *c && k + 64 < sizeof want; c++)
        k += (size_t)(*c == '@' ? snprintf(want + k, sizeof want - k, "%s/", dir) : (want[k] = *c, 1));
    want[k] = 0;
    snprintf(path, sizeof path, "%s/s.scene", dir);
    struct scene *s = NULL;
    int rc = scene_load(path, &s, err, sizeof err);
    check(rc == SCENE_EINPUT && !s && !strncmp(err, want, strlen(want)), tag(what), "rc %d: got \"%s\", want \"%s...\"",
          rc, rc ? err : "", want);
    if (!rc) scene_free(s);
}

#define SCENE_M "model { name = m file = \"m.obj\" color = (1, 2, 3) }\ninstance { model = m }\n"
#define TRI "v 0 0 0\nv 1 0 0\nv 0 1 0\n"

struct bad_obj {
    const char *what, *obj, *mtl, *scene, *msg;
};

static const struct bad_obj bad_cases[] = {
    { "obj_index_zero", TRI "f 1 2 0\n", NULL, NULL, "m.obj:4:7: error: vertex index 0: indices count from 1" },
    { "obj_index_out_of_range", TRI "f 1 2 4\n", NULL, NULL,
      "m.obj:4:7: error: vertex index 4 is out of range (the file has 3)" },
    { "obj_negative_index_out_of_range", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", NULL, NULL,
      "m.obj:3:9: error: vertex index -3 is out of range (2 above it)" },
    { "obj_vt_index_out_of_range", TRI "vt 0 0\nf 1/1 2/1 3/2\n", NULL, NULL,
      "m.obj:5:13: error: texture coordinate (vt) index 2 is out of range (the file has 1)" },
    { "obj_vn_index_bad", TRI "vn 0 0 1\nf 1//1 2//1 3//x\n", NULL, NULL,
      "m.obj:5:16: error: normal (vn) index 'x' is not a whole number" },
    { "obj_not_a_number", "v 0 zero 0\n", NULL, NULL, "m.obj:1:5: error: v: 'zero' is not a number" },
    { "obj_nan", "v 0 0 nan\n", NULL, NULL, "m.obj:1:7: error: v: 'nan' is not a number" },
    { "obj_v_too_few", "v 0 0\n", NULL, NULL, "m.obj:1:1: error: v needs x y z, found 2 numbers" },
    { "obj_face_two_corners", TRI "\n# a line\nf 1 2\n", NULL, NULL,
      "m.obj:6:1: error: a face needs at least 3 corners, found 2" },
    { "obj_corner_forms", TRI "vt 0 0\nf 1/1 2 3/1\n", NULL, NULL,
      "m.obj:5:7: error: corner 2 has another form (v, v/vt, v//vn, v/vt/vn) than the first" },
    { "obj_corner_slash", TRI "f 1 2 3/\n", NULL, NULL, "m.obj:4:7: error: corner 3 ends in '/'" },
    { "obj_uv_on_some_faces", TRI "vt 0 0\nf 1/1 2/1 3/1\nf 3 2 1\n", NULL, NULL,
      "m.obj:6:1: error: face without texture coordinates (vt), unlike the face at line 5" },
    { "obj_normals_on_some_faces", TRI "vn 0 0 1\nf 1 2 3\nf 3//1 2//1 1//1\n", NULL, NULL,
      "m.obj:6:1: error: face with normals (vn), unlike the face at line 5" },
    { "obj_unknown_statement", TRI "f 1 2 3\nfoo 1 2\n", NULL, NULL, "m.obj:5:1: error: unknown statement 'foo'" },
    { "obj_free_form", "cstype bspline\n", NULL, NULL,
      "m.obj:1:1: error: free-form geometry ('cstype') is not supported" },
    { "obj_control_byte", "v 0 0 0\x01\n", NULL, NULL, "m.obj:1:8: error: unexpected byte 0x01" },
    { "obj_no_faces", TRI, NULL, NULL, "s.scene:1:25: error: model file '@m.obj' has no faces" },
    { "obj_missing_file", NULL, NULL, NULL, "s.scene:1:25: error: cannot open model file '@m.obj'" },
    { "obj_path_outside", NULL, NULL, "model { name = m file = \"../m.obj\" }\ninstance { model = m }\n",
      "s.scene:1:25: error: model file '../m.obj' must be a relative path inside the scene's directory" },
    { "obj_no_colour", TRI "f 1 2 3\n", NULL, "model { name = m file = \"m.obj\" }\ninstance { model = m }\n",
      "m.obj:4:1: error: face without a colour: no material (usemtl) and the model has no 'color'" },
    { "obj_missing_mtl", "mtllib nope.mtl\n" TRI "f 1 2 3\n", NULL, NULL,
      "m.obj:1:8: error: cannot open material file '@nope.mtl'" },
    { "obj_unknown_material", "mtllib m.mtl\n" TRI "usemtl b\nf 1 2 3\n", "newmtl a\nKd 1 0 0\n", NULL,
      "m.obj:5:8: error: no material named 'b'" },
    { "obj_material_without_kd", "mtllib m.mtl\n" TRI "usemtl a\nf 1 2 3\n", "newmtl a\nKs 1 1 1\n",
      "model { name = m file = \"m.obj\" }\ninstance { model = m }\n",
      "m.obj:6:1: error: face without a colour: material 'a' has no Kd and the model no 'color'" },
    { "obj_kd_range", "mtllib m.mtl\n", "newmtl a\nKd 0.5 2 0\n", NULL, "m.mtl:2:8: error: Kd: 2 is outside 0 .. 1" },
    { "obj_kd_spectral", "mtllib m.mtl\n", "newmtl a\nKd spectral x.rfl\n", NULL,
      "m.mtl:2:4: error: Kd spectral is not supported" },
    { "obj_mtl_unknown", "mtllib m.mtl\n", "newmtl a\nKd 1 1 1\nwhatever 1\n", NULL,
      "m.mtl:3:1: error: unknown material statement 'whatever'" },
    { "obj_mtl_before_newmtl", "mtllib m.mtl\n", "Kd 1 1 1\n", NULL, "m.mtl:1:1: error: 'Kd' before the first newmtl" },
    { "obj_map_options", "mtllib m.mtl\n", "newmtl a\nmap_Kd -clamp on t.ppm\n", NULL,
      "m.mtl:2:8: error: map_Kd options ('-clamp') are not supported" },
    { "obj_missing_texture", "mtllib m.mtl\n" TRI "vt 0 0\nusemtl a\nf 1/1 2/1 3/1\n", "newmtl a\nmap_Kd nope.png\n",
      NULL, "m.mtl:2:8: error: cannot open image file '@nope.png'" },
    { "obj_texture_without_vt", "mtllib m.mtl\n" TRI "usemtl a\nf 1 2 3\n", "newmtl a\nKd 1 1 1\nmap_Kd t.ppm\n",
      NULL, "m.obj:6:1: error: material 'a' has a texture (map_Kd) but this face no texture coordinates (vt)" },
    { "obj_instance_texture_no_part", "mtllib m.mtl\n" TRI "vt 0 0\nusemtl a\nf 1/1 2/1 3/1\nusemtl b\nf 3 2 1\n",
      "newmtl a\nKd 1 1 1\nmap_Kd t.ppm\nnewmtl b\nKd 0 0 1\n",
      "texture { name = t file = \"t.ppm\" }\nmodel { name = m file = \"m.obj\" }\n"
      "instance { model = m texture = t }\n",
      "s.scene:3:32: error: instance: every part of model 'm' with uv has its material's texture" },
    { "obj_fit_zero", TRI "f 1 2 3\n", NULL, "model { name = m file = \"m.obj\" color = (1, 2, 3) fit = 0 }\n",
      "s.scene:1:57: error: fit must be > 0" },
    { "obj_fit_one_point", "v 1 1 1\nf 1 1 1\n", NULL,
      "model { name = m file = \"m.obj\" color = (1, 2, 3) fit = 1 }\ninstance { model = m }\n",
      "s.scene:1:57: error: fit: the vertices of '@m.obj' are all at one point" },
    { "obj_file_and_vertices", NULL, NULL, "model { name = m file = \"m.obj\" vertices { (0, 0, 0) } }\n",
      "s.scene:1:33: error: a model read from a file has no 'vertices'" },
    { "fit_without_file", NULL, NULL,
      "model { name = m fit = 1 vertices { (0, 0, 0) (1, 0, 0) (0, 1, 0) } triangles { (0, 1, 2) } }\n",
      "s.scene:1:18: error: 'fit' is for models read from a file" },
};

/* A file of n lines `line` after `head`, then `tail`. */
static void put_repeated(const char *file, const char *head, const char *line, long n, const char *tail)
{
    size_t hl = strlen(head), ll = strlen(line), tl = strlen(tail), len = hl + ll * (size_t)n + tl;
    char *text = malloc(len);
    if (!text) exit(1);
    memcpy(text, head, hl);
    for (long i = 0; i < n; i++) memcpy(text + hl + ll * (size_t)i, line, ll);
    memcpy(text + hl + ll * (size_t)n, tail, tl);
    put(file, text, len);
    free(text);
}

static void test_bad(void)
{
    snprintf(dir, sizeof dir, "/tmp/test_scene_obj.XXXXXX");
    if (!mkdtemp(dir)) {
        printf("FAIL %s: mkdtemp\n", tag("obj_tmpdir"));
        return;
    }
    static const char ppm[] = "P6\n1 1\n255\n\x10\x20\x30";
    put("t.ppm", ppm, sizeof ppm - 1);
    for (size_t i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++) {
        const struct bad_obj *c = &bad_cases[i];
        char path[160];
        snprintf(path, sizeof path, "%s/m.obj", dir);
        remove(path);
        if (c->obj) put_str("m.obj", c->obj);
        if (c->mtl) put_str("m.mtl", c->mtl);
        put_str("s.scene", c->scene ? c->scene : SCENE_M);
        expect(c->what, c->msg);
    }
    /* the limits: 65536 vertices; 65536 triangles (the last face's line is named) */
    put_repeated("m.obj", "", "v 0 0 0\n", 65536, "f 1 2 3\n");
    put_str("s.scene", SCENE_M);
    expect("obj_too_many_vertices", "m.obj:65536:1: error: 65536 vertices: a model has at most 65535");
    put_repeated("m.obj", TRI, "f 1 2 3\n", 65536, "");
    expect("obj_too_many_triangles", "m.obj:65539:1: error: 65536 triangles: a model has at most 65535");
    put_repeated("m.obj", TRI "f", " 1 2 3", 21846, "\n");
    expect("obj_polygon_too_long", "m.obj:4:1: error: statement longer than 8192 bytes");
    /* a PNG that is not one */
    put_str("m.obj", "mtllib m.mtl\n" TRI "vt 0 0\nusemtl a\nf 1/1 2/1 3/1\n");
    put_str("m.mtl", "newmtl a\nKd 1 1 1\nmap_Kd bad.png\n");
    put("bad.png", "\x89PNG\r\n\x1a\nxxxxxxxxxxxx", 20);
    expect("png_damaged", "m.mtl:3:8: error: '@bad.png' is not a valid PNG");
    /* without fit, positions must be numbers of the build as written */
    if (!strcmp(NUM_NAME, "fixed")) {
        put_str("m.obj", "v 0 0 0\nv 40000 0 0\nv 0 1 0\nf 1 2 3\n");
        put_str("s.scene", SCENE_M);
        expect("obj_vertex_out_of_range", "m.obj:2:3: error: vertex: 40000 is out of range for fixed numbers");
        put_str("s.scene", "model { name = m file = \"m.obj\" color = (1, 2, 3) fit = 2 }\ninstance { model = m }\n");
        struct scene *s = NULL;
        char path[160], err[600];
        snprintf(path, sizeof path, "%s/s.scene", dir);
        int rc = scene_load(path, &s, err, sizeof err);
        check(rc == 0 && near(s->models[0].bound_radius, 2), tag("obj_fit_brings_into_range"), "%s", rc ? err : "");
        if (!rc) scene_free(s);
    }
    static const char *const files[] = { "m.obj", "m.mtl", "s.scene", "t.ppm", "bad.png" };
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        char path[160];
        snprintf(path, sizeof path, "%s/%s", dir, files[i]);
        remove(path);
    }
    rmdir(dir);
}

int main(void)
{
    test_cube();
    test_parts();
    test_bad();
    return check_exit();
}
