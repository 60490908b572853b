/* rt_book_scenes.c — see rt_book_scenes.h. */
#include "rt_book_scenes.h"

#define D(x) num_from_double(x)

static struct scene scenes[7];
static struct rt_object objs[7][4];
static struct scene_light lights[7][3];

static struct rt_object sphere(double x, double y, double z, double r, double cr, double cg, double cb,
                               double spec, double refl)
{
    struct rt_object o = { 0 };
    o.shape = RT_SPHERE;
    o.center = v3(D(x), D(y), D(z));
    o.radius = D(r);
    o.mat.color = rgb_make(D(cr), D(cg), D(cb));
    o.mat.specular = D(spec);
    o.mat.reflective = D(refl);
    o.mat.refraction = D(1.0);
    return o;
}

static void base(struct scene *s, const char *name)
{
    *s = (struct scene){ 0 };
    s->name = name;
    s->kind = SCENE_RAYTRACE;
    s->canvas_w = s->canvas_h = 600;
    s->viewport_w = s->viewport_h = s->projection_d = D(1.0);
    s->background = rgb_make(D(255), D(255), D(255));
    s->background_set = 1;
    s->camera.position = v3(D(0), D(0), D(0));
    s->camera.rotation = m3_identity();
    s->frames = 1;
    s->rt.recursion_depth = 3;
    s->rt.supersample = 1;
    s->rt.subsample = 1;
    s->rt.t_min_primary = D(1.0);
    s->rt.epsilon = D(0.001);
}

static const char *names[7] = { "", "raytracer-01", "raytracer-02", "raytracer-03", "raytracer-04",
                                 "raytracer-05", "raytracer-06" };

struct scene *rt_book_scene(int n)
{
    if (n < 1 || n > 6) return 0;
    struct scene *s = &scenes[n];
    base(s, names[n]);
    int spec = n >= 3, refl = n >= 5;
    objs[n][0] = sphere(0, -1, 3, 1, 255, 0, 0, spec ? 500 : -1, refl ? 0.2 : 0);
    objs[n][1] = sphere(-2, 0, 4, 1, 0, 255, 0, spec ? 10 : -1, refl ? 0.4 : 0);
    objs[n][2] = sphere(2, 0, 4, 1, 0, 0, 255, spec ? 500 : -1, refl ? 0.3 : 0);
    objs[n][3] = sphere(0, -5001, 0, 5000, 255, 255, 0, spec ? 1000 : -1, refl ? 0.5 : 0);
    s->nobjects = 4;
    s->objects = objs[n];
    if (n == 1) {
        s->rt.unlit = 1;
    } else {
        lights[n][0] = (struct scene_light){ LIGHT_AMBIENT, D(0.2), v3(D(0), D(0), D(0)) };
        lights[n][1] = (struct scene_light){ LIGHT_POINT, D(0.6), v3(D(2), D(1), D(0)) };
        lights[n][2] = (struct scene_light){ LIGHT_DIRECTIONAL, D(0.2), v3(D(1), D(4), D(4)) };
        s->nlights = 3;
        s->lights = lights[n];
        s->rt.diffuse = 1;
        s->rt.specular = (uint8_t)spec;
        s->rt.shadows = n >= 4;
    }
    if (n >= 5) s->background = rgb_make(D(0), D(0), D(0));
    if (n == 6) {
        s->camera.position = v3(D(3), D(0), D(1));
        mat3 m = { { { D(0.7071), D(0), D(-0.7071) }, { D(0), D(1), D(0) }, { D(0.7071), D(0), D(0.7071) } } };
        s->camera.rotation = m;
    }
    return s;
}

#define GRID_MAX 32
/* The lights of the grid and chapter-5 scenes: the book's, with the point
 * light raised to (2, 3, 0); all three lighting steps on. */
static struct scene_light test_lights[3];

static void lit_by_test_lights(struct scene *s)
{
    test_lights[0] = (struct scene_light){ LIGHT_AMBIENT, D(0.2), v3(D(0), D(0), D(0)) };
    test_lights[1] = (struct scene_light){ LIGHT_POINT, D(0.6), v3(D(2), D(3), D(0)) };
    test_lights[2] = (struct scene_light){ LIGHT_DIRECTIONAL, D(0.2), v3(D(1), D(4), D(4)) };
    s->nlights = 3;
    s->lights = test_lights;
    s->rt.diffuse = s->rt.specular = s->rt.shadows = 1;
}

static struct scene grid_scene;
static struct rt_object grid_objs[GRID_MAX * GRID_MAX + 1];

struct scene *rt_grid_scene(int count)
{
    if (count > GRID_MAX) count = GRID_MAX;
    struct scene *s = &grid_scene;
    base(s, "grid");
    s->background = rgb_make(D(20), D(20), D(40));
    int k = 0;
    grid_objs[k] = (struct rt_object){ 0 };
    grid_objs[k].shape = RT_PLANE;
    grid_objs[k].normal = v3(D(0), D(1), D(0));
    grid_objs[k].dist = D(-1);
    grid_objs[k].mat.color = rgb_make(D(200), D(200), D(200));
    grid_objs[k].mat.specular = D(-1);
    grid_objs[k].mat.refraction = D(1);
    k++;
    for (int i = 0; i < count; i++)
        for (int j = 0; j < count; j++) {
            double x = -4.0 + 8.0 * (i + 0.5) / count, z = 4.0 + 8.0 * (j + 0.5) / count;
            grid_objs[k++] = sphere(x, -0.75 + 0.1 * ((i + j) % 3), z, 0.2, 60 + 190 * i / count, 80,
                                    60 + 190 * j / count, 50, (i + j) % 4 == 0 ? 0.3 : 0);
        }
    s->nobjects = (uint16_t)k;
    s->objects = grid_objs;
    lit_by_test_lights(s);
    return s;
}

static struct scene ch5_scene;
static struct rt_object ch5_objs[12];
static struct rt_csg ch5_csg[3];

struct scene *rt_ch5_scene(void)
{
    struct scene *s = &ch5_scene;
    base(s, "chapter5");
    s->background = rgb_make(D(30), D(30), D(60));
    int k = 0;
    struct rt_object *o = ch5_objs;
    o[k] = (struct rt_object){ 0 };
    o[k].shape = RT_PLANE;
    o[k].normal = v3(D(0), D(1), D(0));
    o[k].dist = D(-1);
    o[k].mat.color = rgb_make(D(230), D(230), D(200));
    o[k].mat.specular = D(-1);
    o[k].mat.reflective = D(0.2);
    o[k].mat.refraction = D(1);
    k++;
    o[k] = (struct rt_object){ 0 };
    o[k].shape = RT_TRIANGLE;
    o[k].p[0] = v3(D(-3.5), D(-1), D(7));
    o[k].p[1] = v3(D(-1.5), D(-1), D(8));
    o[k].p[2] = v3(D(-2.5), D(1.5), D(7.5));
    o[k].mat.color = rgb_make(D(255), D(128), D(0));
    o[k].mat.specular = D(50);
    o[k].mat.refraction = D(1);
    k++;
    /* glass sphere */
    o[k] = sphere(0, -0.2, 3.5, 0.8, 240, 240, 255, 200, 0.1);
    o[k].mat.transparency = D(0.7);
    o[k].mat.refraction = D(1.5);
    k++;
    /* CSG operands (not drawn on their own) */
    int a0 = k;
    o[k++] = sphere(2.0, 0, 5, 0.8, 255, 0, 0, 100, 0);
    o[k++] = sphere(2.5, 0.3, 4.6, 0.6, 0, 255, 0, 100, 0);
    o[k++] = sphere(-1.0, 1.2, 6, 0.7, 0, 0, 255, 100, 0);
    o[k++] = sphere(-0.5, 1.2, 6, 0.7, 0, 255, 0, 100, 0);
    o[k++] = sphere(0.8, 1.6, 7, 0.8, 255, 0, 255, 100, 0);
    o[k++] = sphere(1.5, 1.6, 7.5, 0.8, 0, 255, 255, 100, 0);
    for (int i = a0; i < k; i++) o[i].csg_only = 1;
    ch5_csg[0] = (struct rt_csg){ CSG_DIFFERENCE, (uint16_t)a0, (uint16_t)(a0 + 1) };
    ch5_csg[1] = (struct rt_csg){ CSG_INTERSECTION, (uint16_t)(a0 + 2), (uint16_t)(a0 + 3) };
    ch5_csg[2] = (struct rt_csg){ CSG_UNION, (uint16_t)(a0 + 4), (uint16_t)(a0 + 5) };
    s->nobjects = (uint16_t)k;
    s->objects = o;
    s->ncsg = 3;
    s->csg = ch5_csg;
    lit_by_test_lights(s);
    return s;
}
