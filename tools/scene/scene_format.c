/* SPDX-License-Identifier: MIT */
/* scene_format.c — the number format a scene needs: ranges, choice, argument
 * (scene_format.h). */
#include "scene_format.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "raytracer.h"
#include "scene.h"

_Static_assert(SCENE_FORMAT_FITS_COLOUR == SCENE_FITS_COLOUR && SCENE_FORMAT_FITS_HIT == SCENE_FITS_HIT,
               "struct scene.fits bits");

/* Records v in r if it is the largest magnitude so far, with what it is. */
static void note(struct scene_format_range *r, double v, const char *fmt, ...)
{
    v = fabs(v);
    if (v <= r->value) return;
    r->value = v;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->what, sizeof r->what, fmt, ap);
    va_end(ap);
}

static double len3(vec3 v)
{
    double x = num_to_double(v.x), y = num_to_double(v.y), z = num_to_double(v.z);
    return sqrt(x * x + y * y + z * z);
}

static double dist3(vec3 a, vec3 b)
{
    double x = num_to_double(a.x) - num_to_double(b.x), y = num_to_double(a.y) - num_to_double(b.y),
           z = num_to_double(a.z) - num_to_double(b.z);
    return sqrt(x * x + y * y + z * z);
}

static double maxabs3(vec3 v)
{
    double m = fabs(num_to_double(v.x));
    if (fabs(num_to_double(v.y)) > m) m = fabs(num_to_double(v.y));
    if (fabs(num_to_double(v.z)) > m) m = fabs(num_to_double(v.z));
    return m;
}

/* Largest distance the camera moves from its start over the animation. */
static double anim_reach(const struct scene_anim *a, int frames)
{
    return len3(a->move_per_frame) * (frames - 1);
}

static void shortest_dir(struct scene_format *R, double v, const char *what)
{
    if (v > 0 && v < R->smallest_dir) {
        R->smallest_dir = v;
        snprintf(R->smallest_dir_what, sizeof R->smallest_dir_what, "%s", what);
    }
}

static void smallest(struct scene_format *R, double v, const char *what)
{
    v = fabs(v);
    if (v > 0 && v < R->smallest) {
        R->smallest = v;
        snprintf(R->smallest_what, sizeof R->smallest_what, "%s", what);
    }
}

/* Stencil shadow volumes (raster_ch15.c): per frame the core takes the
 * bounding centre c = the mean of the instances' bounding-sphere centres and
 * the radius r = max |vertex - c| + 0.01, and extrudes every silhouette
 * corner P away from the light by ext = |c - light| + 2 r (a directional
 * light: 3 r), so an extruded corner lies within r + ext of c. Distances are
 * unchanged by the camera transform, so the bound is found in world space:
 * c0, the mean at frame 0, moves by at most dc over the animation (an
 * instance moves by its reach, and one that turns swings its bounding
 * centre by up to twice its offset). The faces' normals (edge x edge of
 * extruded corners) and the projection's x * unproj stay wide in the core:
 * only positions are num. */
static void shadow_volume_ranges(const struct scene *s, struct scene_format *R, double cam)
{
    double c0[3] = { 0, 0, 0 }, dc = 0;
    int n = 0;
    for (int i = 0; i < s->ninstances; i++) {
        const struct ras_instance *in = &s->instances[i];
        const struct ras_model *m = &s->models[in->model];
        if (!m->nverts) continue;
        double sc = num_to_double(in->scale);
        vec3 b = m3_mul_v3(&in->rotation, m->bound_center);
        c0[0] += num_to_double(in->position.x) + sc * num_to_double(b.x);
        c0[1] += num_to_double(in->position.y) + sc * num_to_double(b.y);
        c0[2] += num_to_double(in->position.z) + sc * num_to_double(b.z);
        double d = anim_reach(&in->anim, s->frames);
        if (in->anim.rot_y_per_frame != 0 && s->frames > 1) d += 2 * sc * len3(m->bound_center);
        if (d > dc) dc = d;
        n++;
    }
    if (!n) return;
    for (int k = 0; k < 3; k++) c0[k] /= n;
    /* r: a still instance's vertices where they are; one that moves or
     * turns keeps them within sc * vmax of its origin, which moves by its
     * reach */
    double r = 0;
    for (int i = 0; i < s->ninstances; i++) {
        const struct ras_instance *in = &s->instances[i];
        const struct ras_model *m = &s->models[in->model];
        double sc = num_to_double(in->scale), v = 0;
        double tx = num_to_double(in->position.x) - c0[0], ty = num_to_double(in->position.y) - c0[1],
               tz = num_to_double(in->position.z) - c0[2];
        int still = s->frames <= 1 || (in->anim.rot_y_per_frame == 0 && anim_reach(&in->anim, s->frames) == 0);
        for (int k = 0; k < m->nverts; k++) {
            if (still) {
                vec3 p = m3_mul_v3(&in->rotation, m->verts[k]);
                double x = tx + sc * num_to_double(p.x), y = ty + sc * num_to_double(p.y), z = tz + sc * num_to_double(p.z);
                double d = sqrt(x * x + y * y + z * z);
                if (d > v) v = d;
            } else {
                double d = sqrt(tx * tx + ty * ty + tz * tz) + anim_reach(&in->anim, s->frames) + sc * len3(m->verts[k]);
                if (d > v) v = d;
            }
        }
        if (v > r) r = v;
    }
    r += dc + 0.01;
    double ext = 0;
    for (int k = 0; k < s->nlights; k++) {
        const struct scene_light *l = &s->lights[k];
        double e = 0;
        if (l->type == LIGHT_POINT) {
            double dx = num_to_double(l->v.x) - c0[0], dy = num_to_double(l->v.y) - c0[1],
                   dz = num_to_double(l->v.z) - c0[2];
            e = sqrt(dx * dx + dy * dy + dz * dz) + dc + 2 * r;
        } else if (l->type == LIGHT_DIRECTIONAL) {
            e = 3 * r;
        }
        if (e > ext) ext = e;
    }
    /* from the camera: |c| + r + ext, plus a margin for the core's rounding
     * of c, r and the unit directions (far below 0.01 at NUM_FRAC >= 12) */
    double e = sqrt(c0[0] * c0[0] + c0[1] * c0[1] + c0[2] * c0[2]) + dc + cam + r + ext + 0.01;
    note(&R->position, e, "shadow volume: extruded corner from the camera (extrusion %.6g, bound radius %.6g)", ext, r);
}

/* The lights, the viewport and the frames, for both renderers; returns the
 * colour bound (255 x the lights' total, diffuse plus specular). */
static double scan_lights_view(const struct scene *s, struct scene_format *R, double cam)
{
    double itot = 0;
    for (int i = 0; i < s->nlights; i++) {
        const struct scene_light *l = &s->lights[i];
        itot += num_to_double(l->intensity);
        if (l->type == LIGHT_POINT) note(&R->position, len3(l->v) + cam, "light %d: distance from the camera", i);
        if (l->type != LIGHT_AMBIENT) note(&R->position, maxabs3(l->v), "light %d: %s", i,
                                           l->type == LIGHT_POINT ? "position" : "direction");
    }
    /* diffuse and specular each add at most the light's intensity */
    double colour = 255 * (2 * itot > 1 ? 2 * itot : 1);
    note(&R->colour, colour, "colour x total light intensity %.3g (diffuse + specular)", 2 * itot);
    for (int i = 0; i < s->nlights; i++)
        if (s->lights[i].type == LIGHT_DIRECTIONAL) {
            smallest(R, len3(s->lights[i].v), "a light direction's length");
            if (s->kind == SCENE_RAYTRACE) shortest_dir(R, len3(s->lights[i].v), "a light direction");
        }
    /* the viewport and the frame count are num (angles x frames are reduced
     * exactly, num_mul_int_mod; positions x frames are bounded by the reach) */
    note(&R->other, num_to_double(s->viewport_w), "viewport width");
    note(&R->other, num_to_double(s->viewport_h), "viewport height");
    note(&R->other, num_to_double(s->projection_d), "viewport distance d");
    if (s->frames > 1) note(&R->other, s->frames - 1, "the last frame's index");
    note(&R->other, len3(s->camera_anim.move_per_frame) * (s->frames > 1 ? s->frames - 1 : 0) + cam,
         "camera: position at the last frame");
    return colour;
}

/* ---- where the ray tracer's hit points lie ------------------------------
 *
 * A hit point P = O + D t becomes a position in num (and |L| = |light - P|
 * for the lighting), so the positions' range must hold every P that can be
 * the closest hit of a ray. A sphere's P is not bounded only by |C| + r:
 * seen from an origin O outside the sphere, the closest hit is the near
 * root, the entry point, and t1 t2 = c / a puts it within the tangent
 * length sqrt(|C - O|^2 - r^2) of O — for the book's ground (r = 5000, one
 * unit below the camera) 100 units, where |C| + r is 10001. That holds when
 * the near root is above the ray's t_min, i.e. when every point within
 * t_min |D| of O along the ray lies outside the sphere; otherwise the far
 * root may be the hit (the exit point) and only |C| + r bounds P.
 *
 * The rays that make hit points: primary rays from the camera (t in
 * (t_min, ...), directions through the viewport), and, to the scene's
 * reflection depth, rays leaving the hits of reflective or transparent
 * objects (t in (epsilon, ...), reflected directions as long as the
 * incoming one, refracted ones unit). Shadow rays make no position. For
 * each object the bound H of its hit points' distance from the origin is
 * found level by level:
 * - from the camera: the points with t <= t_min of every primary ray lie in
 *   a ball of radius t_min s sqrt(xm^2 + ym^2 + d^2 / 4) around the camera +
 *   R (0, 0, d t_min / 2) (xm, ym: the viewport's half-sides plus a pixel;
 *   s: the camera matrix's largest singular value); a sphere clear of that
 *   ball by a margin is entered by every primary ray that hits it;
 * - from the hits of object j (a ball Bj around its points: a sphere
 *   itself, a triangle's centroid and farthest corner): a sphere i clear of
 *   Bj by more than epsilon times the longest secondary direction is entered
 *   by every such ray, within sqrt((|Ci - cj| + rj)^2 - ri^2) of O;
 * - a reflective sphere's own reflected rays never re-enter it but by the
 *   rounding of the reflected direction, whose inward part is a few steps
 *   per component (at most 2^-7 (1 + 1/min(d, 1)) of its length): along a
 *   chord of at most 2 r times that;
 * - anything else (overlapping objects, transparency, CSG, origins on a
 *   plane, the book formulation, a bounding-sphere hierarchy): |C| + r.
 * A sphere is clear of a ball when the gap exceeds 2^-10 + 2^-18 (r +
 * the centres' distance) (the stored values' rounding and the near root's).
 * A bound is |O| + the distance found, grown by 2^-10 and 2^-10 units for
 * the roots' rounding, and never above |C| + r. Planes' hit points are not
 * bounded here (rays may graze them: the roots saturate, and are no hit). */

/* The largest singular value of m (power iteration on m^T m, from above:
 * the Frobenius norm caps it, and the estimate is grown by 1e-6). */
static double mat3_norm(const mat3 *m)
{
    double a[3][3], v[3] = { 1, 0.7, 0.3 }, lam = 0, fro = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double x = num_to_double(m->m[i][j]);
            a[i][j] = x;
            fro += x * x;
        }
    for (int it = 0; it < 200; it++) {
        double w[3], u[3], n = 0;
        for (int i = 0; i < 3; i++) w[i] = a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2];
        for (int j = 0; j < 3; j++) u[j] = a[0][j] * w[0] + a[1][j] * w[1] + a[2][j] * w[2];
        for (int j = 0; j < 3; j++) n += u[j] * u[j];
        n = sqrt(n);
        if (n == 0) return sqrt(fro);
        for (int j = 0; j < 3; j++) v[j] = u[j] / n;
        lam = n;
    }
    double s = sqrt(lam) * (1 + 1e-6);
    return s < sqrt(fro) ? s : sqrt(fro);
}

/* The ball around an object's points: centre c, radius r, and far =
 * |c| + r, the farthest any of them lies from the origin (bounded 0 for a
 * plane). */
struct ball {
    double c[3], r, far;
    int bounded;
};

static struct ball object_ball(const struct rt_object *o)
{
    struct ball b = { { 0, 0, 0 }, 0, 0, 0 };
    if (o->shape == RT_SPHERE) {
        b.c[0] = num_to_double(o->center.x);
        b.c[1] = num_to_double(o->center.y);
        b.c[2] = num_to_double(o->center.z);
        b.r = fabs(num_to_double(o->radius));
    } else if (o->shape == RT_TRIANGLE) {
        b.c[0] = (num_to_double(o->p[0].x) + num_to_double(o->p[1].x) + num_to_double(o->p[2].x)) / 3;
        b.c[1] = (num_to_double(o->p[0].y) + num_to_double(o->p[1].y) + num_to_double(o->p[2].y)) / 3;
        b.c[2] = (num_to_double(o->p[0].z) + num_to_double(o->p[1].z) + num_to_double(o->p[2].z)) / 3;
        for (int k = 0; k < 3; k++) {
            double dx = num_to_double(o->p[k].x) - b.c[0], dy = num_to_double(o->p[k].y) - b.c[1],
                   dz = num_to_double(o->p[k].z) - b.c[2];
            b.r = fmax(b.r, sqrt(dx * dx + dy * dy + dz * dz));
        }
    } else {
        return b;
    }
    b.far = sqrt(b.c[0] * b.c[0] + b.c[1] * b.c[1] + b.c[2] * b.c[2]) + b.r;
    b.bounded = 1;
    return b;
}

static double dist_pt(const double a[3], const double b[3])
{
    double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return sqrt(x * x + y * y + z * z);
}

/* Sphere i (ball bi) entered by rays from origins in the ball (c, rho) with
 * t_min tmin and directions no longer than dlen: the distance of its hit
 * points from the origin, or -1 when the near root is not proven to be the
 * hit. */
static double entry_reach(const struct ball *bi, const double c[3], double rho, double tmin, double dlen)
{
    double r = bi->r, dc = dist_pt(bi->c, c);
    /* the format's rounding of the stored centres, radii and origins
     * (half a step of NUM_FRAC 12 each) and of the near root (29 or more
     * significant bits, rt_quad_solve) */
    double margin = ldexp(1, -10) + ldexp(r + dc, -18);
    if (dc - rho - r <= tmin * dlen * (1 + ldexp(1, -10)) + margin) return -1;
    double far = dc + rho;
    return sqrt(far * far - r * r);
}

/* The primary directions' extent: the viewport's half-sides plus a pixel
 * (its width follows the render size, Vw = Vh W / H), d, and the camera
 * matrix's largest singular value. */
struct view_ext {
    double xm, ym, d, sn;
};

static struct view_ext view_extent(const struct scene *s, int width, int height)
{
    struct view_ext v;
    double vh = fabs(num_to_double(s->viewport_h));
    double vw = fmax(fabs(num_to_double(s->viewport_w)), vh * width / (height > 0 ? height : 1));
    v.xm = vw / 2 + vw / (width > 0 ? width : 1);
    v.ym = vh / 2 + vh / (height > 0 ? height : 1);
    v.d = fabs(num_to_double(s->projection_d));
    v.sn = mat3_norm(&s->camera.rotation);
    return v;
}

/* The longest direction of a ray that makes hit points: primary ones
 * (through the viewport, turned by the camera matrix), reflected ones as
 * long as the incoming one, refracted ones unit; grown by 2^-8 for the
 * directions' rounding. */
static double ray_dir_max(const struct view_ext *v)
{
    return fmax(1, v->sn * sqrt(v->xm * v->xm + v->ym * v->ym + v->d * v->d)) * (1 + ldexp(1, -8));
}

/* H[i]: the bound on |P| of object i's hit points (-1 for planes: not
 * bounded here). The levels update H in place: a level that reads a bound
 * already grown in the same level only finds larger ones, still bounds. */
static void rt_hit_reach(const struct scene *s, int width, int height, double *H)
{
    const struct rt_options *opt = &s->rt;
    int n = s->nobjects;
    struct view_ext v = view_extent(s, width, height);
    double dsec = ray_dir_max(&v), cam_reach = anim_reach(&s->camera_anim, s->frames);
    double cam[3] = { num_to_double(s->camera.position.x), num_to_double(s->camera.position.y),
                      num_to_double(s->camera.position.z) };
    double camlen = sqrt(cam[0] * cam[0] + cam[1] * cam[1] + cam[2] * cam[2]);
    int fallback = opt->formulation == 1 || opt->bvh || s->ncsg > 0;
    /* the camera's near ball (centre m, radius rho) */
    double tmin = fabs(num_to_double(opt->t_min_primary)), m[3];
    double rho = tmin * v.sn * sqrt(v.xm * v.xm + v.ym * v.ym + v.d * v.d / 4) + cam_reach;
    for (int k = 0; k < 3; k++)
        m[k] = cam[k] + num_to_double(s->camera.rotation.m[k][2]) * v.d * tmin / 2;
    if (s->camera_anim.rot_y_per_frame != 0 && s->frames > 1) {
        for (int k = 0; k < 3; k++) m[k] = cam[k];
        rho += v.sn * v.d * tmin / 2;
    }
    for (int i = 0; i < n; i++) {
        const struct rt_object *o = &s->objects[i];
        struct ball b = object_ball(o);
        if (!b.bounded) {   /* a plane: hit, not bounded here, a source of any origin */
            H[i] = INFINITY;
            continue;
        }
        /* the entry point, from the camera's start and its moves (a CSG
         * operand's hits are the CSG's: fallback) */
        double e = o->shape == RT_SPHERE && !fallback ? entry_reach(&b, m, rho, 0, 1) : -1;
        if (e >= 0) {
            double far = dist_pt(b.c, cam) + cam_reach;
            e = camlen + cam_reach + sqrt(fmax(0, far * far - b.r * b.r));
        }
        H[i] = e < 0 ? b.far : e;
    }
    int depth = opt->recursion_depth > RT_MAX_DEPTH ? RT_MAX_DEPTH : opt->recursion_depth;
    /* a reflected direction's inward part, as a fraction of its length: a
     * few steps (2^-12 at the coarsest format) per component, over the
     * shortest direction (|D| >= d; refracted ones are unit) */
    double chord = fmin(1, 32 * ldexp(1, -12) * (1 + 1 / fmin(v.d > 0 ? v.d : 1e-300, 1)));
    double eps = fabs(num_to_double(opt->epsilon));
    for (int level = 0; level < depth; level++)
        for (int j = 0; j < n; j++) {
            const struct rt_object *oj = &s->objects[j];
            if (num_to_double(oj->mat.reflective) <= 0 && num_to_double(oj->mat.transparency) <= 0) continue;
            struct ball bj = object_ball(oj);
            for (int i = 0; i < n; i++) {
                const struct rt_object *o = &s->objects[i];
                if (o->shape == RT_PLANE) continue;
                struct ball bi = object_ball(o);
                double e = -1;
                if (!fallback && bj.bounded && o->shape == RT_SPHERE) {
                    if (i == j)
                        e = num_to_double(oj->mat.transparency) > 0 ? -1 : 2 * bi.r * chord;
                    else
                        e = entry_reach(&bi, bj.c, bj.r, eps, dsec);
                }
                H[i] = fmax(H[i], e < 0 ? bi.far : H[j] + e);
            }
        }
    for (int i = 0; i < n; i++) {
        struct ball b = object_ball(&s->objects[i]);
        H[i] = b.bounded ? fmin(b.far, H[i] * (1 + ldexp(1, -10)) + ldexp(1, -10)) : -1;
    }
}

void scene_format_hit_reach(const struct scene *s, int width, int height, double *H)
{
    rt_hit_reach(s, width, height, H);
}

/* ---- the tight argument: spheres alone ----------------------------------
 *
 * A ray tracer of spheres only (formulation robust, no CSG, no hierarchy:
 * struct scene_format.tight) forms these sums and differences of positions
 * in num (the rest is wide: dot products, squared lengths, the quadratic's
 * b, c, a and b^2 - a c, rt_intersect.c):
 * - rt_init.c: the camera's position at a frame (recorded: "camera:
 *   position at the last frame");
 * - rt_scene.c and rt_intersect.c: CO = O - C for a ray origin O (the
 *   camera, or a hit point of any object j: shadow rays leave every hit,
 *   reflected and refracted ones those of reflective or transparent
 *   objects) and a sphere's centre C: |CO| <= |camera| + |C| (recorded:
 *   "distance from the camera to the centre"), or for O on object j <=
 *   min(H_j + |C|, |c_j - C| + r_j), its hits within H_j of the origin
 *   (rt_hit_reach) and on its sphere;
 * - rt_trace.c: P = O + D t, the sum P (a hit point, recorded: H_i) and
 *   D t = P - O, <= H_i + |camera| from the camera and <= min(H_i + H_j,
 *   |c_i - c_j| + r_i + r_j) from a hit of object j;
 * - rt_intersect.c (rt_hit_normal): P - C of the sphere hit, <= r (its
 *   hits lie on it);
 * - rt_lighting.c: L = light - P (recorded: "distance to light k"), |L|
 *   (v3_len), |N| |L| (|N| = 1 up to rounding), R = N (2 N.L) - L with
 *   |R| = |L| (rt_reflect: 2 N.L is not narrowed on its own where it
 *   would not fit), R.V and |R| |V| (<= |L| |D|, recorded in scan_rt_rays)
 *   and N.L I (<= |L| I, scan_rt_rays).
 * None of these results is added to another num: each needs only to lie
 * in the range itself, and so do the positions that are its operands.
 * The hits lie on their sphere but for the roots' rounding: t to 29 or
 * more significant bits (rt_quad_solve), D t to half an ulp per component,
 * so a hit point lies within |D t| 2^-28 + 2^-12 <= 2^-9 + 2^-12 of the
 * sphere for |D t| < 2^19 (every format's range), and the other bounds
 * inherit that: scene_format_choose grows every position and result by
 * 2^-10 of itself and 2^-8. The ray parameters t (roots) and the
 * specular exponents are compared, scaled and multiplied, never added to
 * another num: they are results too. Colour, screen, square and other
 * values keep the factor 2 (sums of colours, the viewport's products). */
static void rt_tight_pairs(const struct scene *s, struct scene_format *R, const double *H, double cam)
{
    int n = s->nobjects;
    /* the roots along the scaled direction D' = D 2^-k (rt_ray_exact:
     * |D'| >= 1 for k > 0, |D'| = |D| for k = 0, |D'| >= 1/2 > |D| for
     * k < 0), t' |D'| <= |CO| + r: t' <= (|CO| + r) / min(dmin, 1), dmin the
     * shortest primary, reflected or directional shadow direction (|D| >=
     * d; refracted ones unit). A point light's shadow ray (t_max = 1) may
     * saturate a root beyond 1, which is no hit either way. */
    double dmin = fmin(1, fabs(num_to_double(s->projection_d)));
    for (int k = 0; k < s->nlights; k++)
        if (s->rt.shadows && s->lights[k].type == LIGHT_DIRECTIONAL) dmin = fmin(dmin, len3(s->lights[k].v));
    for (int i = 0; i < n; i++) {
        struct ball bi = object_ball(&s->objects[i]);
        double ci = sqrt(bi.c[0] * bi.c[0] + bi.c[1] * bi.c[1] + bi.c[2] * bi.c[2]);
        note(&R->result, bi.r, "sphere %d: a hit point - its centre (the normal's P - C)", i);
        note(&R->result, H[i] + cam, "sphere %d: D t of a primary ray (a hit point - the camera)", i);
        if (dmin > 0) note(&R->result, (cam + ci + bi.r) / dmin, "sphere %d: a root t of a primary ray", i);
        for (int j = 0; j < n; j++) {
            struct ball bj = object_ball(&s->objects[j]);
            double d = dist_pt(bi.c, bj.c), co = fmin(H[j] + ci, d + bj.r);
            note(&R->result, co, "sphere %d: CO of a ray leaving object %d", i, j);
            note(&R->result, fmin(H[i] + H[j], d + bi.r + bj.r),
                 "sphere %d: D t of a ray leaving object %d (a hit point - the origin)", i, j);
            if (dmin > 0) note(&R->result, (co + bi.r) / dmin, "sphere %d: a root t of a ray leaving object %d", i, j);
        }
    }
}

/* Ray tracer: the objects (spheres, planes, triangles); *hmax gets the
 * largest hit-point bound (rt_hit_reach). */
static void scan_rt_objects(const struct scene *s, struct scene_format *R, int width, int height, double cam,
                            double *hmax)
{
    int book = s->rt.formulation == 1;
    /* no memory for the bounds: each object's |C| + r */
    double *H = malloc(sizeof(double) * (size_t)(s->nobjects > 0 ? s->nobjects : 1));
    if (H) rt_hit_reach(s, width, height, H);
    else R->tight = 0;   /* the pairs below need the bounds */
    *hmax = 0;
    for (int i = 0; i < s->nobjects; i++) {
        const struct rt_object *o = &s->objects[i];
        double h = H ? H[i] : object_ball(o).far;   /* the hit points' bound */
        /* read by num_to_int and compared (rt_init.c, rt_lighting.c): held once when tight */
        note(R->tight ? &R->result : &R->other, num_to_double(o->mat.specular), "object %d: specular exponent", i);
        if (o->shape == RT_SPHERE) {
            double r = num_to_double(o->radius), c = len3(o->center);
            note(&R->position, c, "sphere %d: centre", i);
            note(&R->position, r, "sphere %d: radius", i);
            note(&R->position, h, "sphere %d: hit points (their reach)", i);
            if (h > *hmax) *hmax = h;
            if (book || s->rt.bvh || s->ncsg > 0) note(&R->position, c + r, "sphere %d: centre + radius", i);
            note(&R->position, c + cam, "sphere %d: distance from the camera to the centre", i);
            for (int k = 0; k < s->nlights; k++)
                if (s->lights[k].type == LIGHT_POINT)
                    note(&R->position, h + len3(s->lights[k].v), "sphere %d: distance to light %d", i, k);
            if (book) {
                note(&R->square, r * r, "sphere %d: radius %g makes r^2", i, r);
                note(&R->square, (c + cam) * (c + cam), "sphere %d: |CO|^2 from the camera", i);
            }
            smallest(R, r, "a sphere radius");
            if (r > 0 && r < R->smallest_radius) R->smallest_radius = r;
        } else if (o->shape == RT_PLANE) {
            note(&R->position, num_to_double(o->dist), "plane %d: distance from the origin", i);
        } else {
            for (int k = 0; k < 3; k++) note(&R->position, len3(o->p[k]) + cam, "triangle %d: corner %d", i, k);
            /* Moller-Trumbore keeps two cross products in num: D' x e2
             * (|D'| < 2) and (O - p0) x e1 */
            double e1 = dist3(o->p[1], o->p[0]), e2 = dist3(o->p[2], o->p[0]), o0 = len3(o->p[0]) + cam;
            note(&R->position, fmax(e1, e2), "triangle %d: an edge", i);
            note(&R->other, 2 * e2, "triangle %d: direction x edge 2", i);
            note(&R->other, o0 * e1, "triangle %d: (origin - corner 0) x edge 1", i);
            if (h > *hmax) *hmax = h;
            for (int k = 0; k < s->nlights; k++)
                if (s->lights[k].type == LIGHT_POINT)
                    note(&R->position, h + len3(s->lights[k].v), "triangle %d: distance to light %d", i, k);
        }
    }
    if (R->tight) rt_tight_pairs(s, R, H, cam);
    free(H);
}

/* Ray tracer, formulation = book: the sphere test keeps the quadratic's
 * terms in num (rt_intersect.c): k1 = D.D, k2 = 2 CO.D, k3 = CO.CO - r^2,
 * then k2^2, 4 k1 and (4 k1) k3, the discriminant and 2 k1. A ray's origin
 * O is the camera or a hit point (|O| <= reach), so |CO| <= reach + |C|;
 * its direction is a primary or reflected one (<= dmax) or, for a shadow
 * ray, the light vector L (<= lmax). */
static void scan_rt_book(const struct scene *s, struct scene_format *R, double hmax, double reach,
                         double dmax, double lmax, int secondary)
{
    double d = s->rt.shadows ? fmax(dmax, lmax) : dmax, d2 = d * d;
    double cam = len3(s->camera.position) + anim_reach(&s->camera_anim, s->frames);
    reach = fmax(reach, fmax(hmax, cam));
    /* a hit point is the root t times D, t from the quadratic's terms rounded
     * to num: it lies about |t D| 2^-NUM_FRAC off the surface, and a shadow or
     * reflected ray leaving it finds its own surface past epsilon once that
     * is more than epsilon (measured: tools/charts/sweeps.py rt-scale, the
     * book quadratic at Q15.16 holds to k = 2, reach x 2^-16 = 0.6 epsilon,
     * and fails from k = 4, 1.2 epsilon) */
    R->book_reach = secondary ? reach + cam : 0;
    for (int i = 0; i < s->nobjects; i++) {
        const struct rt_object *o = &s->objects[i];
        if (o->shape != RT_SPHERE) continue;
        double r = num_to_double(o->radius), co = reach + len3(o->center);
        double k3 = fmax(co * co, r * r);
        /* the quadratic's terms scale as (|D| r)^2: the shortest direction
         * (|D| >= d, a directional light's length) and this radius */
        double sm = R->smallest_dir < 1e300 ? R->smallest_dir * r : r;
        if (sm * sm < R->book_small) R->book_small = sm * sm;
        note(&R->square, d2, "sphere %d: the book's k1 = D.D", i);
        note(&R->square, 4 * d2 * k3, "sphere %d: the book's 4 k1 k3 (|CO| <= %.4g, |D| <= %.4g)", i, co, d);
        note(&R->square, 4 * d2 * co * co + 4 * d2 * k3,
             "sphere %d: the book's discriminant k2^2 - 4 k1 k3 (|CO| <= %.4g, |D| <= %.4g)", i, co, d);
    }
}

/* Ray tracer: the view direction D = (x vw / W, y vh / H, d) and the light
 * vectors stay unnormalised (the book's lighting), so two products are num:
 * the specular term's R.V and |R| |V| (|R| = |L|, |V| = |D|, reflections
 * keep |D|), and a root t = distance / |direction| (primary and reflected
 * rays: |D| >= d; shadow rays to a directional light: its direction's
 * length; point lights: t <= 1). Read after the objects: the largest
 * position so far bounds every distance. */
static void scan_rt_rays(const struct scene *s, struct scene_format *R, double hmax, double dmax)
{
    double dd = fabs(num_to_double(s->projection_d)), dmin = dd, lmax = 0;
    int planes = 0;
    for (int i = 0; i < s->nobjects; i++) planes |= s->objects[i].shape == RT_PLANE;
    shortest_dir(R, dd, "the view direction (|D| >= viewport d)");
    for (int k = 0; k < s->nlights; k++) {
        const struct scene_light *l = &s->lights[k];
        /* |L| = |light - P|: P within the hit points' reach (planes' are not
         * bounded: the largest position then) */
        double lp = len3(l->v) + (planes ? R->position.value : hmax);
        if (l->type == LIGHT_POINT && lp > lmax) lmax = lp;
        if (l->type == LIGHT_DIRECTIONAL) {
            double ll = len3(l->v);
            if (ll > lmax) lmax = ll;
            if (s->rt.shadows && ll < dmin) dmin = ll;
        }
    }
    /* R.V, |R| |V| and t are compared and divided, never added to another
     * num: held once when tight (rt_tight_pairs) */
    struct scene_format_range *once = R->tight ? &R->result : &R->other;
    if (s->rt.specular) note(once, lmax * dmax, "specular: R.V of the longest light vector and view ray");
    if (R->tight) {
        /* the diffuse term's N.L I (num_mul); the roots t: rt_tight_pairs */
        double imax = 0;
        for (int k = 0; k < s->nlights; k++)
            if (s->lights[k].type != LIGHT_AMBIENT) imax = fmax(imax, fabs(num_to_double(s->lights[k].intensity)));
        if (s->rt.diffuse) note(&R->result, lmax * imax, "diffuse: N.L of the longest light vector x its intensity");
    } else if (dmin > 0) {
        note(&R->other, R->position.value / dmin, "a ray parameter t: distance / |direction| (%.3g)", dmin);
    }
    /* rays that leave a hit point: shadow rays to a light that casts them,
     * or reflected ones */
    int secondary = s->rt.recursion_depth > 0;
    for (int k = 0; k < s->nlights; k++) secondary |= s->rt.shadows && s->lights[k].type != LIGHT_AMBIENT;
    R->t_dir = secondary ? dmax : 0;
    R->epsilon = fabs(num_to_double(s->rt.epsilon));
    if (s->rt.formulation == 1)
        scan_rt_book(s, R, hmax, planes ? R->position.value : hmax, dmax, lmax, secondary);
}

static void scan_rt(const struct scene *s, struct scene_format *R, int width, int height, double cam, double colour)
{
    /* a ray from the viewport runs at most this far across the scene */
    /* the primary directions step by Vh / H across and down (the render's
     * viewport width follows its aspect: Vw = Vh W / H, rt_init.c) */
    double vh = fabs(num_to_double(s->viewport_h)), vwr = vh * width / (height > 0 ? height : 1);
    R->pixel_step = vh / (height > 0 ? height : 1);
    smallest(R, R->pixel_step, "viewport step per pixel");
    smallest(R, num_to_double(s->rt.epsilon), "epsilon");
    note(&R->other, num_to_double(s->rt.t_min_primary), "t_min");
    note(&R->other, width > height ? width : height, "render size (pixel counts are num)");
    /* canvas x times viewport size, before the division by the width (a
     * sub-pixel x for supersampling; columns' are formed wide) */
    note(&R->other, vwr, "the render's viewport width Vh x W / H");
    note(&R->other, fmax(width / 2.0 * vwr, height / 2.0 * vh), "canvas coordinate x viewport size");
    /* supersampling sums n^2 colours before dividing */
    int n = s->rt.supersample > 1 ? s->rt.supersample : 1;
    if (n > 1) note(&R->colour, colour * n * n, "supersample %d: the sum of %d colours", n, n * n);
    R->tight = R->tight && s->rt.formulation != 1 && !s->rt.bvh && s->ncsg == 0;
    for (int i = 0; i < s->nobjects; i++) R->tight &= s->objects[i].shape == RT_SPHERE;
    double hmax;
    scan_rt_objects(s, R, width, height, cam, &hmax);
    struct view_ext v = view_extent(s, width, height);
    scan_rt_rays(s, R, hmax, ray_dir_max(&v));
}

/* Rasterizer: what the projection to the screen (x d / z x w / W) needs,
 * and the camera's reach. */
struct ras_view {
    double cam, w, W, d;
    double k;                  /* canvas units per unit of x / z: H / Vh (the render's viewport
                                  width follows its aspect, so W / Vw is the same) */
    int face_normals;          /* face normals are shading normals (narrowed to num) only when the
                                  triangles are shaded with computed normals or the model has none */
};

/* Rasterizer: the 2D primitives, the 3D lines and every model as written. */
static void scan_ras_prims_models(const struct scene *s, struct scene_format *R, const struct ras_view *v)
{
    for (int i = 0; i < s->nprims; i++)
        for (int k = 0; k < s->prims[i].npts; k++) {
            note(&R->screen, num_to_double(s->prims[i].x[k]), "2D primitive %d: x", i);
            note(&R->screen, num_to_double(s->prims[i].y[k]), "2D primitive %d: y", i);
        }
    for (int i = 0; i < s->nlines; i++) {
        const struct line3d *l = &s->lines[i];
        vec3 e[2] = { l->a, l->b };
        for (int k = 0; k < 2; k++) {
            note(&R->position, len3(e[k]) + v->cam, "line %d: end %d", i, k);
            /* ProjectVertex of the end as written (the lines take no
             * camera transform), behind the camera too: z = 0 has no
             * projection */
            double z = num_to_double(e[k].z);
            double px = z != 0 ? num_to_double(e[k].x) * v->d / z * v->k : INFINITY;
            double py = z != 0 ? num_to_double(e[k].y) * v->d / z * v->k : INFINITY;
            note(&R->screen, px, "line %d: projected x of end %d", i, k);
            note(&R->screen, py, "line %d: projected y of end %d", i, k);
            /* a step of x or y moves the end by d k / |z| pixels, a step of
             * z by |x'| / |z| (x' the projected coordinate) */
            double per = z != 0 ? (fabs(v->d) * v->k + fmax(fabs(px), fabs(py))) / fabs(z) : INFINITY;
            if (per > R->line_px) {
                R->line_px = per;
                R->line = i;
            }
        }
    }
    /* every model as written (parsed into num whether instanced or not) */
    for (int i = 0; i < s->nmodels; i++) {
        const struct ras_model *m = &s->models[i];
        for (int k = 0; k < m->nverts; k++)
            note(&R->position, maxabs3(m->verts[k]), "model %s: vertex %d as written", m->name, k);
        note(&R->position, len3(m->bound_center) + num_to_double(m->bound_radius), "model %s: bounding sphere",
             m->name);
        for (int k = 0; k < m->ntris && m->has_normals; k++)
            for (int c = 0; c < 3; c++)
                note(&R->other, maxabs3(m->tris[k].n[c]), "model %s: normal of triangle %d as written", m->name, k);
    }
}

/* Rasterizer, instance i: face normals are edge x edge of camera-space
 * corners, at most the square of the instance's diameter (diam2). The core
 * keeps them wide (culling and facing tests are wide triple products) and
 * narrows one to num only where it is the shading normal. */
static void scan_face_normals(const struct scene *s, struct scene_format *R, int i, double diam2, double far,
                              double cam)
{
    const struct ras_model *m = &s->models[s->instances[i].model];
    /* |e1 x e2| is the same in model and camera space up to scale^2 (the
     * rotations keep lengths): the largest of the model's triangles, plus
     * the transformed corners' rounding (a few steps of the coarsest format
     * on each edge, times the other edge) */
    double sc = fabs(num_to_double(s->instances[i].scale)), nmax = 0, emax = 0;
    for (int k = 0; k < m->ntris; k++) {
        const struct ras_triangle *t = &m->tris[k];
        if (t->v[0] >= m->nverts || t->v[1] >= m->nverts || t->v[2] >= m->nverts) continue;
        double a[3], e1[3], e2[3];
        vec3 p0 = m->verts[t->v[0]], p1 = m->verts[t->v[1]], p2 = m->verts[t->v[2]];
        a[0] = num_to_double(p0.x), a[1] = num_to_double(p0.y), a[2] = num_to_double(p0.z);
        e1[0] = num_to_double(p1.x) - a[0], e1[1] = num_to_double(p1.y) - a[1], e1[2] = num_to_double(p1.z) - a[2];
        e2[0] = num_to_double(p2.x) - a[0], e2[1] = num_to_double(p2.y) - a[1], e2[2] = num_to_double(p2.z) - a[2];
        double c0 = e1[1] * e2[2] - e1[2] * e2[1], c1 = e1[2] * e2[0] - e1[0] * e2[2], c2 = e1[0] * e2[1] - e1[1] * e2[0];
        double n = sqrt(c0 * c0 + c1 * c1 + c2 * c2);
        double e = fmax(sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]),
                        sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]));
        if (n > nmax) nmax = n;
        if (e > emax) emax = e;
    }
    double step = 8 * ldexp(1.0, -12);
    nmax = fmin(diam2, (sc * sc * nmax + 2 * (sc * emax + step) * step) * (1 + ldexp(1.0, -10)));
    /* the default path narrows the normal's direction only
     * (ras_wnormal_narrow_dir): a range on the book path alone */
    if (!s->ras.book_exact) return;
    note(&R->square, nmax, "instance %d (%s): face normal edge x edge", i, m->name);
    diam2 = nmax;   /* |N| below */
    /* the book path never normalises N: 2 N (N.L) - L of
     * ras_compute_illumination is |N|^2 |L| x 2 (N.L and the
     * cosines' products are wide) */
    double lmax = far + cam;
    for (int k = 0; k < s->nlights; k++)
        if (s->lights[k].type != LIGHT_AMBIENT && far + len3(s->lights[k].v) > lmax)
            lmax = far + len3(s->lights[k].v);
    note(&R->square, 2 * diam2 * diam2 * lmax + lmax,
         "instance %d (%s): reflected light of the unnormalised face normal", i, m->name);
    note(&R->square, 2 * diam2 * lmax, "instance %d (%s): 2 N.L of the unnormalised face normal", i, m->name);
}

/* Rasterizer, instance i with clip off: no near plane, the projection of
 * each vertex, as placed. */
static void scan_unclipped(const struct scene *s, struct scene_format *R, int i, const struct ras_view *v)
{
    const struct ras_instance *in = &s->instances[i];
    const struct ras_model *m = &s->models[in->model];
    double sc = num_to_double(in->scale);
    for (int k = 0; k < m->nverts; k++) {
        vec3 p = m3_mul_v3(&in->rotation, m->verts[k]);
        double x = num_to_double(p.x) * sc + num_to_double(in->position.x) - num_to_double(s->camera.position.x);
        double y = num_to_double(p.y) * sc + num_to_double(in->position.y) - num_to_double(s->camera.position.y);
        double z = num_to_double(p.z) * sc + num_to_double(in->position.z) - num_to_double(s->camera.position.z);
        if (z > 0) {
            note(&R->screen, x * v->d / z * v->k, "instance %d: projected vertex %d", i, k);
            note(&R->screen, y * v->d / z * v->k, "instance %d: projected vertex %d", i, k);
            note(&R->screen, 1 / z, "instance %d: 1/z of vertex %d", i, k);
        }
    }
}

static void scan_instance(const struct scene *s, struct scene_format *R, int i, const struct ras_view *v)
{
    const struct ras_instance *in = &s->instances[i];
    const struct ras_model *m = &s->models[in->model];
    double sc = num_to_double(in->scale), t = len3(in->position) + anim_reach(&in->anim, s->frames);
    double vmax = 0;
    for (int k = 0; k < m->nverts; k++)
        if (len3(m->verts[k]) > vmax) vmax = len3(m->verts[k]);
    note(&R->other, sc, "instance %d (%s): scale", i, m->name);
    note(&R->other, num_to_double(in->specular), "instance %d (%s): specular exponent", i, m->name);
    note(&R->position, sc * (len3(m->bound_center) + num_to_double(m->bound_radius)),
         "instance %d (%s): scaled bounding sphere", i, m->name);
    double far = t + sc * vmax;
    note(&R->position, t + sc * len3(m->bound_center) + v->cam, "instance %d (%s): bounding-sphere centre", i,
         m->name);
    /* the unprojection x * z / unproj (Phong) and the projection
     * x * unproj / z keep the product wide (ras_mul_div): only the
     * result, a position or a screen coordinate, is num */
    note(&R->position, far + v->cam, "instance %d (%s): farthest vertex from the camera", i, m->name);
    double diam2 = (2 * sc * vmax) * (2 * sc * vmax);
    if (v->face_normals && (s->ras.computed_normals || !m->has_normals)) scan_face_normals(s, R, i, diam2, far, v->cam);
    for (int k = 0; k < s->nlights; k++)
        if (s->lights[k].type == LIGHT_POINT)
            note(&R->position, far + len3(s->lights[k].v), "instance %d: distance to light %d", i, k);
    if (!s->ras.clip) scan_unclipped(s, R, i, v);
    /* uv is read only for an instance with a texture or a normal map */
    int textured = (in->texture >= 0 && in->texture < s->ntextures) ||
                   (in->normal_map >= 0 && in->normal_map < s->ntextures);
    for (int k = 0; k < m->ntris && textured; k++)
        for (int c = 0; c < 3 && m->has_uvs; c++) {
            note(&R->screen, num_to_double(m->tris[k].uv[c].u) * 1024, "instance %d: u x texture size", i);
            note(&R->screen, num_to_double(m->tris[k].uv[c].v) * 1024, "instance %d: v x texture size", i);
        }
}

static void scan_ras(const struct scene *s, struct scene_format *R, int width, int height, double cam)
{
    double vh = fabs(num_to_double(s->viewport_h)), h = height > 0 ? height : 1;
    struct ras_view v = { cam, width, num_to_double(s->viewport_w), num_to_double(s->projection_d),
                          vh > 0 ? h / vh : 0, s->ras.shading != SHADE_NONE && !s->ras.wireframe };
    /* the render's viewport (raster_work.c): Vw = Vh W / H, the projection's
     * scale W d / Vw = H d / Vh, and the clip planes' sides
     * (Vw / 2 + 2 Vw / W) / d times the farthest depth */
    double vw = vh * width / h, dd = fabs(v.d);
    note(&R->other, vw, "the render's viewport width Vh x W / H");
    if (s->ninstances > 0) R->near_d = dd;
    /* (the instances' path only: 2D primitives and 3D lines project by ras_project) */
    if (s->ninstances > 0) note(&R->screen, v.k * dd, "the projection's scale H x d / Vh");
    /* Per instance: the clip planes' side slope times its farthest depth;
     * and the nearest depth it reaches. A position's rounding moves a
     * projected vertex by step x H d / (Vh z) (x and z alike, within the
     * view): the pixel at the nearest depth an instance reaches, Vh z / (H d),
     * is the rasterizer's pixel step. An on-screen point at distance D from
     * the camera has z >= D c, c the view's half-diagonal cosine; clipping
     * keeps z >= d. */
    if (s->ninstances > 0 && dd > 0) {
        double side = fmax(vw / 2 + 2 * vw / (width > 0 ? width : 1), vh / 2 + 2 * vh / h) / dd;
        double sx = vw / (2 * dd), sy = vh / (2 * dd), c = 1 / sqrt(1 + sx * sx + sy * sy), zn = INFINITY;
        note(&R->other, side, "the clip planes' side slope (Vw / 2 + 2 Vw / W) / d");
        for (int i = 0; i < s->ninstances; i++) {
            const struct ras_instance *in = &s->instances[i];
            const struct ras_model *m = &s->models[in->model];
            double sc = num_to_double(in->scale), ball = len3(m->bound_center) + num_to_double(m->bound_radius);
            double reach = anim_reach(&in->anim, s->frames);
            double far = len3(in->position) + reach + cam + sc * ball;
            note(&R->other, side * far, "instance %d: the clip planes' side slope x its farthest depth", i);
            double z = (dist3(in->position, s->camera.position) - reach - anim_reach(&s->camera_anim, s->frames) -
                        fabs(sc) * ball) * c;
            if (s->ras.clip) z = fmax(z, dd);
            if (z < zn) zn = z;
        }
        if (vh > 0 && zn > 0 && zn < INFINITY) {
            double px = zn * vh / (h * dd);
            if (px < R->pixel_step) {
                R->pixel_step = px;
                R->pixel_at_depth = 1;
            }
        }
    }
    smallest(R, 1.0 / 1024, "texture coordinates (1/1024 of a texture)");
    note(&R->screen, v.w > height ? v.w : height, "render size");
    note(&R->screen, s->canvas_w > s->canvas_h ? s->canvas_w : s->canvas_h, "scene canvas size");
    scan_ras_prims_models(s, R, &v);
    for (int i = 0; i < s->ninstances; i++) scan_instance(s, R, i, &v);
    if (s->ras.shadow_volume) shadow_volume_ranges(s, R, cam);
}

/* The quantities the renderers keep in `num` (num.h's kinds), for this scene
 * at width x height, each recorded with the object it comes from. */
static void scan(const struct scene *s, struct scene_format *R, int width, int height)
{
    R->smallest = 1e300;
    R->smallest_dir = 1e300;
    R->smallest_radius = 1e300;
    R->pixel_step = 1e300;
    R->book_small = 1e300;
    double cam = len3(s->camera.position) + anim_reach(&s->camera_anim, s->frames);
    note(&R->position, cam, "camera position");
    double colour = scan_lights_view(s, R, cam);
    if (s->kind == SCENE_RAYTRACE)
        scan_rt(s, R, width, height, cam, colour);
    else
        scan_ras(s, R, width, height, cam);
}

/* Ray tracer: a sphere the camera stands inside (at frame 0 or over its
 * moves) is hit from within: its hit points lie up to |C| + r from the
 * origin, and every shadow ray from them starts on its inner surface. Past
 * SCENE_FORMAT_INSIDE_LIMIT those shadow decisions go wrong in float and
 * fixed point alike (a larger epsilon does not help): measured with a
 * sphere of radius 1 and two lights inside a wall centred on the camera
 * (host_sim --compare double --summary), radius 3,000: 49.0 dB fixed,
 * 26.2 dB float; 10,000: 35.7 / 15.9 dB; 40,000: 27.8 / 12.3 dB, and with
 * reflective walls 21.5 / 8.2 dB. Such a sphere is refused. */
static void rt_inside(const struct scene *s, struct scene_format *f)
{
    f->inside = -1;
    f->inside_limit = SCENE_FORMAT_INSIDE_LIMIT;
    if (s->kind != SCENE_RAYTRACE) return;
    double reach = anim_reach(&s->camera_anim, s->frames);
    for (int i = 0; i < s->nobjects; i++) {
        const struct rt_object *o = &s->objects[i];
        if (o->shape != RT_SPHERE) continue;
        double r = fabs(num_to_double(o->radius));
        if (dist3(o->center, s->camera.position) - reach >= r) continue;
        double far = len3(o->center) + r;
        if (f->inside < 0 || far > f->inside_far) {
            f->inside = i;
            f->inside_radius = r;
            f->inside_far = far;
        }
    }
}

/* scene_format_choose with the doubled argument (tight 0) or, for a scene
 * of spheres alone, the tight one (tight 1; f->tight says whether it held). */
static int choose_once(const struct scene *s, int width, int height, const int *fracs, int nfracs, int allow_wide,
                       struct scene_format *f, int tight)
{
    memset(f, 0, sizeof *f);
    f->width = width;
    f->height = height;
    f->tight = tight;
    scan(s, f, width, height);
    if (s->kind != SCENE_RAYTRACE) f->tight = 0;
    /* the largest quantity, with a factor-2 margin for one sum or difference
     * of two of them (a - b of two positions, colour plus reflected colour);
     * longer sums (dot products) are taken wide by the core */
    f->big = f->position;
    if (f->other.value > f->big.value) f->big = f->other;
    if (f->square.value > f->big.value) f->big = f->square;
    if (f->colour.value > f->big.value) f->big = f->colour;
    if (f->screen.value > f->big.value) f->big = f->screen;
    if (f->result.value > f->big.value) f->big = f->result;
    f->need = 2 * f->big.value;
    if (f->tight) {
        /* positions and results held once, grown for the hits' rounding
         * (rt_tight_pairs); the other kinds twice */
        double twice = fmax(fmax(f->other.value, f->square.value), fmax(f->colour.value, f->screen.value));
        double once = fmax(f->position.value, f->result.value);
        f->need = fmax(2 * twice, once * (1 + ldexp(1, -10)) + ldexp(1, -8));
    }
    f->num_frac = -1;
    f->coarsest = fracs[0];
    for (int i = 0; i < nfracs; i++) {
        double lim = ldexp(1.0, 31 - fracs[i]);
        if (f->need < lim && (f->num_frac < 0 || fracs[i] > f->num_frac)) f->num_frac = fracs[i];
        if (fracs[i] < f->coarsest) f->coarsest = fracs[i];
    }
    rt_inside(s, f);
    if (f->inside >= 0 && f->inside_far > f->inside_limit) {
        f->ill = SCENE_ILL_INSIDE;
        f->ill_frac = f->num_frac;
        f->num_frac = -1;
        return -1;
    }
    /* Ill-conditioned for fixed point, at the finest format that holds the
     * largest quantity: the primary rays step from pixel to pixel by under 16
     * steps (directions quantised coarser than 1/16 pixel); a sphere radius
     * is under 256 steps (its normal (P - C) / r is off by more than 0.4 %,
     * which reflections multiply into the ray directions); a direction's
     * squared length, from which the robust tests scale it by a power of
     * two, is under 64 steps (no precision left, or 0). */
    if (f->num_frac >= 0) {
        double step = ldexp(1.0, -f->num_frac);
        f->ill = f->pixel_step < 16 * step                            ? SCENE_ILL_PIXEL_STEP
                 : f->smallest_radius < 256 * step                    ? SCENE_ILL_RADIUS
                 : f->smallest_dir * f->smallest_dir < 64 * step      ? SCENE_ILL_DIRECTION
                 : f->book_reach * step >= f->epsilon && f->book_reach > 0 ? SCENE_ILL_BOOK
                 : f->book_small < 64 * step                            ? SCENE_ILL_BOOK_SMALL
                 : f->t_dir * step > f->epsilon / 2                     ? SCENE_ILL_T_STEP
                 : f->near_d > 0 && f->near_d < 32 * step               ? SCENE_ILL_NEAR
                 : f->line_px * step > 0.25                             ? SCENE_ILL_LINE
                                                                      : 0;
        if (f->ill) {
            f->ill_frac = f->num_frac;
            f->num_frac = -1;
            return -1;
        }
    }
    f->raytrace = s->kind == SCENE_RAYTRACE;
    for (int i = 0; i < s->nobjects; i++)
        if (s->objects[i].shape == RT_PLANE) f->planes = 1;
    if (f->num_frac >= 0) return 0;
    if (!allow_wide) return -1;
    f->num_frac = f->coarsest;
    f->wide = 1;
    return 0;
}

int scene_format_choose(const struct scene *s, int width, int height, const int *fracs, int nfracs,
                        int allow_wide, struct scene_format *f)
{
    static const int all[] = { 20, 19, 18, 17, 16, 15, 14, 13, 12 };
    if (!fracs || nfracs < 1) {
        fracs = all;
        nfracs = (int)(sizeof all / sizeof all[0]);
    }
    int rc = choose_once(s, width, height, fracs, nfracs, allow_wide, f, 0);
    /* The tight argument (rt_tight_pairs) where the doubled one leaves a
     * ray-traced scene of spheres alone at the coarsest candidate, wide or
     * refused: there a bit of precision matters most (demo/planet-horizon,
     * Q19.12 54.7 dB -> Q18.13 60.9 dB against double at 240x240). A scene
     * the doubled argument gives a finer format keeps it: the book's
     * raytracer-05 and 06 would go from Q15.16 to Q14.17 for no clear gain
     * (69.4 -> 69.6 and 57.4 -> 57.9 dB at 240x240, 71.3 -> 70.1 and
     * 64.1 -> 65.0 dB at 600x600). */
    if (s->kind == SCENE_RAYTRACE && (rc != 0 || f->wide || f->num_frac == f->coarsest)) {
        struct scene_format *t = malloc(sizeof *t);
        if (t && choose_once(s, width, height, fracs, nfracs, 0, t, 1) == 0 && t->tight &&
            (rc != 0 || f->wide || t->num_frac > f->num_frac)) {
            *f = *t;
            rc = 0;
        }
        free(t);
    }
    return rc;
}

void scene_format_print_ranges(FILE *out, const struct scene_format *f)
{
    fprintf(out, "  ranges: positions and distances <= %.6g (%s)\n", f->position.value, f->position.what);
    if (f->square.value > 0)
        fprintf(out, "          squares kept in num <= %.6g (%s)\n", f->square.value, f->square.what);
    fprintf(out, "          colour intermediates <= %.6g (%s)\n", f->colour.value, f->colour.what);
    if (f->screen.value > 0)
        fprintf(out, "          screen quantities <= %.6g (%s)\n", f->screen.value, f->screen.what);
    if (f->other.value > 0)
        fprintf(out, "          other values kept in num <= %.6g (%s)\n", f->other.value, f->other.what);
    if (f->result.value > 0)
        fprintf(out, "          results held once <= %.6g (%s)\n", f->result.value, f->result.what);
    if (f->smallest < 1e300)
        fprintf(out, "          smallest step relied on: %.6g (%s)\n", f->smallest, f->smallest_what);
}

void scene_format_print_argument(FILE *out, const struct scene_format *f)
{
    if (f->num_frac < 0) return;
    int frac = f->num_frac;
    if (f->wide)
        fprintf(out, "  --allow-wide: the largest quantity exceeds every format; NUM_FRAC %d, wide paths assumed\n",
                frac);
    double lim = ldexp(1.0, 31 - frac);
    fprintf(out, "  number format: NUM_FRAC %d (Q%d.%d): |x| < %.6g, resolution %.3g\n", frac, 31 - frac, frac, lim,
            ldexp(1.0, -frac));
    if (f->tight)
        fprintf(out, "  no overflow: spheres alone: every sum and difference of positions the core forms is a result\n"
                     "    above, held once with the positions (grown by 2^-10 and 2^-8 for the hits' rounding), the\n"
                     "    rest twice (one sum or difference of two of them): at most %.6g < %.6g. Products of two\n"
                     "    quantities (dot products, squared lengths, r^2) are taken wide (wnum = int64 with %d fraction\n"
                     "    bits, |x| < %.3g), where %.6g^2 = %.3g fits.\n",
                f->need, lim, frac, ldexp(1.0, 63 - frac), f->need, f->need * f->need);
    else
        fprintf(out, "  no overflow: every num quantity above is <= %.6g; twice that (one sum or difference of two\n"
                     "    of them) is %.6g < %.6g. Products of two quantities (dot products, squared lengths, r^2) are\n"
                     "    taken wide (wnum = int64 with %d fraction bits, |x| < %.3g), where %.6g^2 = %.3g fits.\n",
                f->big.value, f->need, lim, frac, ldexp(1.0, 63 - frac), f->need, f->need * f->need);
    if (f->smallest < 1e300 && f->smallest < 4 * ldexp(1.0, -frac))
        fprintf(out, "  warning: %s = %.3g is within 4 steps of the resolution %.3g\n", f->smallest_what, f->smallest,
                ldexp(1.0, -frac));
}

void scene_format_refusal(const struct scene_format *f, const char *path, const char *wide_option, char *msg,
                          size_t len)
{
    if (f->ill == SCENE_ILL_INSIDE) {
        snprintf(msg, len,
                 "%s:1:1: error: ill-conditioned for fixed point and float: the camera stands inside sphere %d "
                 "(radius %.6g), whose hit points lie up to %.6g from the origin, more than %.6g: the shadow "
                 "rays leaving them go wrong (under 20 dB against double); make the sphere smaller "
                 "(double renders it)",
                 path, f->inside, f->inside_radius, f->inside_far, f->inside_limit);
        return;
    }
    if (f->ill) {
        char what[320];
        if (f->ill == SCENE_ILL_BOOK) {
            snprintf(msg, len,
                     "%s:1:1: error: ill-conditioned for fixed point: with formulation = book, hit points up to "
                     "%.6g from the camera lie about %.3g off their surface at NUM_FRAC %d (the finest format "
                     "that holds %s = %.6g), not under epsilon %.3g: shadow and reflected rays would find "
                     "their own surface; use formulation = robust, or an epsilon above %.3g (float and double "
                     "render it)",
                     path, f->book_reach, f->book_reach * ldexp(1.0, -f->ill_frac), f->ill_frac, f->big.what,
                     f->big.value, f->epsilon, f->book_reach * ldexp(1.0, -f->ill_frac));
            return;
        }
        if (f->ill == SCENE_ILL_T_STEP)
            snprintf(what, sizeof what,
                     "a hit point P = O + D t, t in num, steps by the longest direction |D| = %.3g times the "
                     "step, %.3g, over half of epsilon %.3g (shadow and reflected rays leave it)",
                     f->t_dir, f->t_dir * ldexp(1.0, -f->ill_frac), f->epsilon);
        else if (f->ill == SCENE_ILL_BOOK_SMALL)
            snprintf(what, sizeof what,
                     "with formulation = book, the sphere test's terms k2^2 and k1 k3 scale as (|D| r)^2 = %.3g "
                     "(the shortest direction times the smallest radius), under 64 steps",
                     f->book_small);
        else if (f->ill == SCENE_ILL_LINE)
            snprintf(what, sizeof what,
                     "3D line %d's end moves %.3g pixels per step (ProjectVertex x d k / z of a small z), over "
                     "1/4 pixel",
                     f->line, f->line_px * ldexp(1.0, -f->ill_frac));
        else if (f->ill == SCENE_ILL_NEAR)
            snprintf(what, sizeof what,
                     "the near plane's distance d = %.3g is under 32 steps (the depths the clip planes make "
                     "near it err by over 3 %%)",
                     f->near_d);
        else if (f->ill == SCENE_ILL_PIXEL_STEP)
            snprintf(what, sizeof what, "%s, %.3g, is under 16 steps",
                     f->pixel_at_depth ? "a pixel's size at the nearest depth an instance reaches"
                                       : "the viewport step from pixel to pixel",
                     f->pixel_step);
        else if (f->ill == SCENE_ILL_RADIUS)
            snprintf(what, sizeof what, "a sphere of radius %.3g is under 256 steps (its normals are imprecise)",
                     f->smallest_radius);
        else
            snprintf(what, sizeof what, "%s has length %.3g, whose square %.3g is under 64 steps",
                     f->smallest_dir_what, f->smallest_dir, f->smallest_dir * f->smallest_dir);
        const char *fix = f->ill == SCENE_ILL_T_STEP       ? "shorten the viewport's d, raise epsilon"
                          : f->ill == SCENE_ILL_BOOK_SMALL   ? "use formulation = robust"
                          : f->ill == SCENE_ILL_LINE         ? "move the line away from z = 0"
                          : f->ill == SCENE_ILL_NEAR         ? "move the viewport's d out"
                          : f->ill == SCENE_ILL_PIXEL_STEP ? "widen the viewport, render smaller"
                          : f->ill == SCENE_ILL_RADIUS   ? "make the sphere larger"
                                                         : "make the direction longer";
        snprintf(msg, len,
                 "%s:1:1: error: ill-conditioned for fixed point: %s of NUM_FRAC %d, the finest format that holds "
                 "%s = %.6g; %s or make the scene smaller (float and double render it)",
                 path, what, f->ill_frac, f->big.what, f->big.value, fix);
        return;
    }
    double lim = ldexp(1.0, 31 - f->coarsest);
    /* a square kept in num is the book's operation order: the robust one keeps it wide */
    const char *fix = f->big.value == f->square.value
                          ? "use a plane, or formulation = robust (64-bit intermediates) for this scene"
                      : wide_option ? "scale the scene down, or allow 64-bit intermediates for this scene"
                                    : "scale the scene down, or render it in floating point (--numeric float)";
    snprintf(msg, len,
             "%s:1:1: error: %s = %.6g (x2 margin: %.6g) exceeds the widest number format (|x| < %.6g at "
             "NUM_FRAC %d); %s%s%s%s",
             path, f->big.what, f->big.value, f->need, lim, f->coarsest, fix,
             f->big.value != f->square.value && wide_option ? " (" : "",
             f->big.value != f->square.value && wide_option ? wide_option : "",
             f->big.value != f->square.value && wide_option ? ")" : "");
}
