/* raster_scenes.c — the raster demos of book-scenes.md as C data (see
 * raster_scenes.h). Numbers are the document's; doubles become `num`
 * through num_from_double, so the double build holds them exactly. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "raster_scenes.h"

#define D(x) num_from_double(x)

static struct scene sc;
static struct ras_model models[4];
static struct ras_instance insts[4];
static struct scene_light lights[3];
static struct prim2d prims[2];
static struct line3d lines[12];
static struct ras_texture textures[1];
static vec3 cube_v[8], sphere_v[240], floor_v[4];
static struct ras_triangle cube_t[12], sphere_t[450], floor_t[2];
static uint8_t tex_rgb[600 * 600 * 3];

static const double cube_xyz[8][3] = { { 1, 1, 1 }, { -1, 1, 1 }, { -1, -1, 1 }, { 1, -1, 1 },
                                       { 1, 1, -1 }, { -1, 1, -1 }, { -1, -1, -1 }, { 1, -1, -1 } };
static const double RED[3] = { 255, 0, 0 }, GREEN[3] = { 0, 255, 0 }, BLUE[3] = { 0, 0, 255 },
                    YELLOW[3] = { 255, 255, 0 }, PURPLE[3] = { 255, 0, 255 }, CYAN[3] = { 0, 255, 255 };
static const int cubeA[12][3] = { { 0, 1, 2 }, { 0, 2, 3 }, { 4, 0, 3 }, { 4, 3, 7 }, { 5, 4, 7 }, { 5, 7, 6 },
                                  { 1, 5, 6 }, { 1, 6, 2 }, { 4, 5, 1 }, { 4, 1, 0 }, { 2, 6, 7 }, { 2, 7, 3 } };
static const double *const cubeA_c[12] = { RED, RED, GREEN, GREEN, BLUE, BLUE, YELLOW, YELLOW, PURPLE, PURPLE, CYAN, CYAN };
static const int cubeB[12][3] = { { 0, 1, 2 }, { 0, 2, 3 }, { 1, 5, 6 }, { 1, 6, 2 }, { 2, 6, 7 }, { 2, 7, 3 },
                                  { 4, 0, 3 }, { 4, 1, 0 }, { 4, 3, 7 }, { 4, 5, 1 }, { 5, 4, 7 }, { 5, 7, 6 } };
static const double *const cubeB_c[12] = { RED, RED, YELLOW, YELLOW, CYAN, CYAN, GREEN, PURPLE, GREEN, PURPLE, BLUE, BLUE };
static const int cubeC[12][3] = { { 0, 1, 2 }, { 0, 2, 3 }, { 4, 0, 3 }, { 4, 3, 7 }, { 5, 4, 7 }, { 5, 7, 6 },
                                  { 1, 5, 6 }, { 1, 6, 2 }, { 1, 0, 5 }, { 5, 0, 4 }, { 2, 6, 7 }, { 2, 7, 3 } };
static const double cubeC_n[12][3] = { { 0, 0, 1 }, { 0, 0, 1 }, { 1, 0, 0 }, { 1, 0, 0 }, { 0, 0, -1 }, { 0, 0, -1 },
                                       { -1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, -1, 0 } };
static const double uvA[3][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 } }, uvB[3][2] = { { 0, 0 }, { 1, 1 }, { 0, 1 } },
                    uvC[3][2] = { { 0, 1 }, { 1, 1 }, { 0, 0 } };

static const double sph_cos[15] = { 1, 0.91354545764260087, 0.66913060635885824, 0.30901699437494745,
    -0.10452846326765333, -0.49999999999999978, -0.80901699437494734, -0.97814760073380558,
    -0.97814760073380569, -0.80901699437494745, -0.50000000000000044, -0.10452846326765423,
    0.30901699437494723, 0.66913060635885779, 0.91354545764260053 };
static const double sph_sin[15] = { 0, 0.40673664307580015, 0.74314482547739424, 0.95105651629515353,
    0.99452189536827340, 0.86602540378443871, 0.58778525229247325, 0.20791169081775973,
    -0.20791169081775907, -0.58778525229247303, -0.86602540378443849, -0.99452189536827329,
    -0.95105651629515364, -0.74314482547739458, -0.40673664307580093 };

static rgb col3(const double *c) { return rgb_make(D(c[0]), D(c[1]), D(c[2])); }
static vec3 vd(double x, double y, double z) { return v3(D(x), D(y), D(z)); }

static mat3 roty(double c, double s, int neg_zero_s)
{
    mat3 m = { { { D(c), D(0), neg_zero_s ? D(-0.0) : D(-s) }, { D(0), D(1), D(0) }, { D(s), D(0), D(c) } } };
    return m;
}

static void cube_model(struct ras_model *m, const int (*tri)[3], const double *const *cols, int with_nuv)
{
    for (int i = 0; i < 8; i++) cube_v[i] = vd(cube_xyz[i][0], cube_xyz[i][1], cube_xyz[i][2]);
    for (int i = 0; i < 12; i++) {
        struct ras_triangle *t = &cube_t[i];
        memset(t, 0, sizeof *t);
        for (int k = 0; k < 3; k++) t->v[k] = (uint16_t)tri[i][k];
        t->color = col3(cols ? cols[i] : cubeA_c[i]);
        if (with_nuv) {
            const double (*uv)[2] = i == 9 ? uvC : (i % 2 ? uvB : uvA);
            for (int k = 0; k < 3; k++) {
                t->n[k] = vd(cubeC_n[i][0], cubeC_n[i][1], cubeC_n[i][2]);
                t->uv[k].u = D(uv[k][0]);
                t->uv[k].v = D(uv[k][1]);
            }
        }
    }
    memset(m, 0, sizeof *m);
    m->name = "cube";
    m->nverts = 8;
    m->ntris = 12;
    m->verts = cube_v;
    m->tris = cube_t;
    m->has_normals = (uint8_t)with_nuv;
    m->has_uvs = (uint8_t)with_nuv;
    m->bound_center = vd(0, 0, 0);
    m->bound_radius = D(1.7320508075688772);
}

static void sphere_model(struct ras_model *m, const double *colour, int s450)
{
    for (int d = 0; d < 16; d++) {
        double y = (2.0 / 15) * (d - 15.0 / 2);
        double r = sqrt(1 - y * y);
        for (int i = 0; i < 15; i++) sphere_v[15 * d + i] = vd(r * sph_cos[i], y, r * sph_sin[i]);
    }
    int n = 0;
    for (int d = 0; d < 15; d++)
        for (int i = 0; i < (s450 ? 15 : 14); i++) {
            int i0 = 15 * d + i, tri[2][3];
            if (s450) {
                int i1 = 15 * (d + 1) + (i + 1) % 15, i2 = 15 * d + (i + 1) % 15;
                int a[2][3] = { { i0, i1, i2 }, { i0, i0 + 15, i1 } };
                memcpy(tri, a, sizeof a);
            } else {
                int a[2][3] = { { i0, i0 + 16, i0 + 1 }, { i0, i0 + 15, i0 + 16 } };
                memcpy(tri, a, sizeof a);
            }
            for (int h = 0; h < 2; h++) {
                struct ras_triangle *t = &sphere_t[n++];
                memset(t, 0, sizeof *t);
                for (int k = 0; k < 3; k++) {
                    t->v[k] = (uint16_t)tri[h][k];
                    t->n[k] = sphere_v[tri[h][k]];
                }
                t->color = col3(colour);
            }
        }
    memset(m, 0, sizeof *m);
    m->name = "sphere";
    m->nverts = 240;
    m->ntris = (uint16_t)n;
    m->verts = sphere_v;
    m->tris = sphere_t;
    m->has_normals = 1;
    m->bound_center = vd(0, 0, 0);
    m->bound_radius = D(1);
}

static void instance(int i, int model, double x, double y, double z, mat3 rot, double scale, double spec)
{
    struct ras_instance *in = &insts[i];
    memset(in, 0, sizeof *in);
    in->model = (uint16_t)model;
    in->texture = -1;
    in->normal_map = -1;
    in->position = vd(x, y, z);
    in->rotation = rot;
    in->scale = D(scale);
    in->specular = D(spec);
}

static void std_lights(int rt)
{
    lights[0].type = LIGHT_AMBIENT;
    lights[0].intensity = D(0.2);
    lights[0].v = vd(0, 0, 0);
    if (rt) {
        lights[1].type = LIGHT_POINT; lights[1].intensity = D(0.6); lights[1].v = vd(2, 1, 0);
        lights[2].type = LIGHT_DIRECTIONAL; lights[2].intensity = D(0.2); lights[2].v = vd(1, 4, 4);
    } else {
        lights[1].type = LIGHT_DIRECTIONAL; lights[1].intensity = D(0.2); lights[1].v = vd(-1, 0, 1);
        lights[2].type = LIGHT_POINT; lights[2].intensity = D(0.6); lights[2].v = vd(-3, 2, -10);
    }
    sc.nlights = 3;
    sc.lights = lights;
}

static void prim(int i, int kind, int npts, const double (*p)[3], const double *c)
{
    struct prim2d *q = &prims[i];
    memset(q, 0, sizeof *q);
    q->kind = (uint8_t)kind;
    q->npts = (uint8_t)npts;
    for (int k = 0; k < npts; k++) { q->x[k] = D(p[k][0]); q->y[k] = D(p[k][1]); q->h[k] = D(p[k][2]); }
    q->color = col3(c);
}

struct scene *ras_test_scene(const char *name)
{
    static const double BLACK[3] = { 0, 0, 0 };
    memset(&sc, 0, sizeof sc);
    sc.name = name;
    sc.kind = SCENE_RASTER;
    sc.canvas_w = sc.canvas_h = 600;
    sc.viewport_w = sc.viewport_h = sc.projection_d = D(1);
    sc.frames = 1;
    sc.camera.rotation = m3_identity();
    sc.models = models;
    sc.instances = insts;
    sc.textures = textures;
    sc.prims = prims;
    sc.lines = lines;
    struct ras_options *o = &sc.ras;
    o->book_exact = 1;
    o->shading = SHADE_NONE;
    o->depth_bits = 32;
    o->perspective_uv = 1;
    mat3 id = m3_identity();
    mat3 r_m30 = roty(0.86602540378443871, -0.49999999999999994, 0);
    mat3 r_195 = roty(-0.96592582628906842, -0.25881904510252035, 0);

    if (!strcmp(name, "raster-01") || !strcmp(name, "raster-02")) {
        static const double a[2][3] = { { -200, -100, 0 }, { 240, 120, 0 } }, b[2][3] = { { -50, -200, 0 }, { 60, 240, 0 } };
        int k = name[8] == '1' ? P2D_LINE_BROKEN : P2D_LINE;
        prim(0, k, 2, a, BLACK);
        prim(1, k, 2, b, BLACK);
        sc.nprims = 2;
        return &sc;
    }
    if (!strcmp(name, "raster-03")) {
        static const double p[3][3] = { { -200, -250, 0 }, { 200, 50, 0 }, { 20, 250, 0 } };
        prim(0, P2D_FILLED_TRI, 3, p, GREEN);
        prim(1, P2D_WIRE_TRI, 3, p, BLACK);
        sc.nprims = 2;
        return &sc;
    }
    if (!strcmp(name, "raster-04")) {
        static const double p[3][3] = { { -200, -250, 0.3 }, { 200, 50, 0.1 }, { 20, 250, 1.0 } };
        prim(0, P2D_SHADED_TRI, 3, p, GREEN);
        sc.nprims = 1;
        return &sc;
    }
    if (!strcmp(name, "raster-05")) {
        static const double f[4][2] = { { -2, -0.5 }, { -2, 0.5 }, { -1, 0.5 }, { -1, -0.5 } };
        int n = 0;
        for (int k = 0; k < 4; k++) {
            int j = (k + 1) % 4;
            lines[n].a = vd(f[k][0], f[k][1], 5); lines[n].b = vd(f[j][0], f[j][1], 5); lines[n++].color = col3(BLUE);
        }
        for (int k = 0; k < 4; k++) {
            int j = (k + 1) % 4;
            lines[n].a = vd(f[k][0], f[k][1], 6); lines[n].b = vd(f[j][0], f[j][1], 6); lines[n++].color = col3(RED);
        }
        for (int k = 0; k < 4; k++) {
            lines[n].a = vd(f[k][0], f[k][1], 5); lines[n].b = vd(f[k][0], f[k][1], 6); lines[n++].color = col3(GREEN);
        }
        sc.nlines = 12;
        return &sc;
    }
    if (!strcmp(name, "raster-06") || !strcmp(name, "raster-07") || !strcmp(name, "raster-08") ||
        !strcmp(name, "raster-09")) {
        int demo = name[8] - '0';
        cube_model(&models[0], cubeA, cubeA_c, 0);
        sc.nmodels = 1;
        o->wireframe = 1;
        if (demo <= 7) {
            instance(0, 0, -1.5, 0, 7, id, 1, -1);
            instance(1, 0, 1.25, 2, 7.5, id, 1, -1);
            sc.ninstances = demo == 6 ? 1 : 2;
            return &sc;
        }
        o->instance_transform = o->camera_transform = 1;
        sc.camera.position = vd(-3, 1, 2);
        sc.camera.rotation = r_m30;
        instance(0, 0, -1.5, 0, 7, id, 0.75, -1);
        instance(1, 0, 1.25, 2.5, 7.5, r_195, 1, -1);
        sc.ninstances = 2;
        if (demo == 9) {
            instance(2, 0, 0, 0, -10, r_195, 1, -1);
            sc.ninstances = 3;
            o->clip = 1;
        }
        return &sc;
    }
    /* raster-10 and later: filled, truncated, clipped, depth, culling */
    o->instance_transform = o->camera_transform = 1;
    o->project_truncate = 1;
    o->clip = 1;
    o->depth_test = 1;
    o->backface_cull = 1;
    sc.camera.position = vd(-3, 1, 2);
    sc.camera.rotation = r_m30;
    if (!strcmp(name, "raster-10")) {
        cube_model(&models[0], cubeB, cubeB_c, 0);
        sc.nmodels = 1;
        instance(0, 0, -1.5, 0, 7, id, 0.75, -1);
        instance(1, 0, 1.25, 2.5, 7.5, r_195, 1, -1);
        sc.ninstances = 2;
        return &sc;
    }
    o->shading = SHADE_PHONG;
    o->diffuse = o->specular = 1;
    if (!strcmp(name, "raster-11")) {
        cube_model(&models[0], cubeC, NULL, 1);
        sphere_model(&models[1], GREEN, 1);
        sc.nmodels = 2;
        std_lights(0);
        instance(0, 0, -1.5, 0, 7, id, 0.75, 50);
        instance(1, 0, 1.25, 2.5, 7.5, r_195, 1, 50);
        instance(2, 1, 1.75, -0.5, 7, id, 1.5, 50);
        sc.ninstances = 3;
        return &sc;
    }
    if (!strcmp(name, "raster-12") || !strcmp(name, "raster-13")) {
        int d13 = name[8] == '3';
        cube_model(&models[0], cubeC, NULL, 1);
        sc.nmodels = 1;
        std_lights(0);
        struct ras_texture *t = &textures[0];
        memset(t, 0, sizeof *t);
        int w = d13 ? 400 : 600;
        t->w = t->h = (uint16_t)w;
        t->rgb = tex_rgb;
        t->filter = d13 ? TEX_BILINEAR_BOOK : TEX_NEAREST;
        for (int y = 0; y < w; y++)
            for (int x = 0; x < w; x++) {
                uint8_t *p = &tex_rgb[(y * w + x) * 3];
                if (d13) {
                    uint8_t v = ((x / 10 + y / 10) % 2) ? 0 : 255;
                    p[0] = p[1] = p[2] = v;
                } else { /* a procedural crate: frame, brace, planks */
                    int fr = x < 60 || x >= 540 || y < 60 || y >= 540;
                    int br = abs(x - y) < 40 || abs(x + y - 599) < 40;
                    int pl = (x / 60) % 2;
                    p[0] = (uint8_t)(fr ? 90 : br ? 120 : pl ? 160 : 145);
                    p[1] = (uint8_t)(fr ? 66 : br ? 90 : pl ? 122 : 112);
                    p[2] = (uint8_t)(fr ? 44 : br ? 60 : pl ? 86 : 80);
                }
            }
        sc.ntextures = 1;
        if (d13) {
            sc.camera.position = vd(0, 0, 0);
            sc.camera.rotation = roty(1, 0, 1);
            instance(0, 0, -1, 0, 3, roty(0.96592582628906831, -0.25881904510252074, 0), 1, 50);
            instance(1, 0, 5.5, 5, 20, roty(0.70710678118654757, 0.70710678118654746, 0), 1, 50);
            sc.ninstances = 2;
        } else {
            instance(0, 0, -1.5, 0, 7, id, 0.75, 50);
            instance(1, 0, 1.25, 2.5, 7.5, r_195, 1, 50);
            instance(2, 0, 1.75, 0, 5, r_m30, 1, 50);
            sc.ninstances = 3;
        }
        for (int i = 0; i < sc.ninstances; i++) insts[i].texture = 0;
        return &sc;
    }
    if (!strcmp(name, "raster-rt-scene")) {
        sc.camera.position = vd(0, 0, 0);
        sc.camera.rotation = id;
        std_lights(1);
        sphere_model(&models[0], RED, 0);
        /* three spheres of different colours share vertices; colours differ per model */
        static struct ras_triangle tg[420], tb[420];
        models[1] = models[0];
        models[2] = models[0];
        for (int i = 0; i < 420; i++) {
            tg[i] = sphere_t[i]; tg[i].color = col3(GREEN);
            tb[i] = sphere_t[i]; tb[i].color = col3(BLUE);
        }
        models[1].tris = tg;
        models[2].tris = tb;
        floor_v[0] = vd(-49, 0, 50); floor_v[1] = vd(49, 0, 50);
        floor_v[2] = vd(0.999, 0, 1.01); floor_v[3] = vd(-0.999, 0, 1.01);
        static const int ft[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };
        for (int i = 0; i < 2; i++) {
            memset(&floor_t[i], 0, sizeof floor_t[i]);
            for (int k = 0; k < 3; k++) { floor_t[i].v[k] = (uint16_t)ft[i][k]; floor_t[i].n[k] = vd(0, 1, 0); }
            floor_t[i].color = col3(YELLOW);
        }
        struct ras_model *m = &models[3];
        memset(m, 0, sizeof *m);
        m->name = "floor"; m->nverts = 4; m->ntris = 2; m->verts = floor_v; m->tris = floor_t;
        m->has_normals = 1; m->bound_center = vd(0, 0, 1000); m->bound_radius = D(1);
        sc.nmodels = 4;
        instance(0, 0, 0, -1, 3, id, 1, 500);
        instance(1, 1, -2, 0, 4, roty(-1, 1.2246467991473532e-16, 0), 1, 10);
        instance(2, 2, 2, 0, 4, id, 1, 500);
        instance(3, 3, 0, -1, 0, id, 1, 50);
        sc.ninstances = 4;
        return &sc;
    }
    return NULL;
}
