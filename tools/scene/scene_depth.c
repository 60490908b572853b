/* SPDX-License-Identifier: MIT */
/* scene_depth.c — the automatic choice of the default path's depth bits
 * (depth_bits unset): the depth range of the scene, and the closest
 * surfaces that overlap on screen.
 *
 * The depth buffer stores near/z (larger is nearer) in 16 or 32 bits. Two
 * rules, either of which asks for 32 bits:
 *  - range: a 16-bit step at the farthest depth any instance reaches
 *    (far^2 / (near * 65536), in depth units) above 1/256 of the smallest
 *    instance's bounding radius;
 *  - overlap: on some checked frame, more than 1/4096 of the canvas's
 *    pixels (and at least one) show a surface with another one behind it
 *    whose near/z is less than two 16-bit steps (2^-15) lower — there the
 *    16-bit buffer may round both to one value or swap them. Gaps under
 *    2^-30 are left out: surfaces that close (coplanar, or meeting at an
 *    intersection line's very pixels) are ties in 32 bits as well.
 * The overlap is measured in double on the scene's canvas (at most 256
 * pixels a side; 128, 64 or 32 where that much memory is not there): every instance's triangles transformed as the renderer
 * does (scene_anim), clipped at the near plane z = d, back faces dropped
 * when the scene culls, and at each pixel centre strictly inside a
 * triangle near/z interpolated (it is affine on the screen); per pixel the
 * nearest and the next value are kept. Frames checked: all when the scene
 * has at most 16, else 16 spread evenly from the first to the last. Only
 * the default and fast paths' depth tests read the choice: the overlap is
 * measured for scenes with `depth = on` off the book path. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene_parse.h"

#define DEPTH_FRAMES_CHECKED 16
#define DEPTH_GRID_MAX 256
#define DEPTH_GRID_MIN 32       /* the coarsest grid tried when memory is short */
#define DEPTH_GAP_STEPS16 2.0   /* the overlap rule's gap, in 16-bit steps */
#define DEPTH_GAP_TIE 0x1p-30   /* smaller gaps: ties whatever the bits */
#define DEPTH_PIXELS_SHARE 4096 /* more than pixels / this: 32 bits */

static double dist3(vec3 v)
{
    double x = num_to_double(v.x), y = num_to_double(v.y), z = num_to_double(v.z);
    return sqrt(x * x + y * y + z * z);
}

static double reach3(const struct scene_anim *a, int frames)
{
    return dist3(a->move_per_frame) * (frames > 1 ? frames - 1 : 0);
}

struct d3 {
    double x, y, z;
};

static struct d3 d3_of(vec3 v)
{
    return (struct d3){ num_to_double(v.x), num_to_double(v.y), num_to_double(v.z) };
}

/* 3x3 rotation in double, row-major as mat3 */
struct dmat {
    double m[3][3];
};

static struct dmat dmat_of(const mat3 *r)
{
    struct dmat d;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) d.m[i][j] = num_to_double(r->m[i][j]);
    return d;
}

/* frame f turns by f * rot_y_per_frame about y after the rotation as written
 * (raster_project.c's anim_rot), in double */
static struct dmat anim_rot(const mat3 *r, const struct scene_anim *a, int frame)
{
    struct dmat d = dmat_of(r);
    double deg = num_to_double(a->rot_y_per_frame) * frame;
    if (frame == 0 || deg == 0) return d;
    double t = fmod(deg, 360.0) * (3.14159265358979323846 / 180.0), c = cos(t), s = sin(t);
    /* the book's MakeOYRotationMatrix: [c 0 -s; 0 1 0; s 0 c] */
    double ry[3][3] = { { c, 0, -s }, { 0, 1, 0 }, { s, 0, c } };
    struct dmat o;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) o.m[i][j] = ry[i][0] * d.m[0][j] + ry[i][1] * d.m[1][j] + ry[i][2] * d.m[2][j];
    return o;
}

static struct d3 dmat_apply(const struct dmat *r, struct d3 v)
{
    return (struct d3){ r->m[0][0] * v.x + r->m[0][1] * v.y + r->m[0][2] * v.z,
                        r->m[1][0] * v.x + r->m[1][1] * v.y + r->m[1][2] * v.z,
                        r->m[2][0] * v.x + r->m[2][1] * v.y + r->m[2][2] * v.z };
}

static struct d3 dmat_apply_t(const struct dmat *r, struct d3 v)
{
    return (struct d3){ r->m[0][0] * v.x + r->m[1][0] * v.y + r->m[2][0] * v.z,
                        r->m[0][1] * v.x + r->m[1][1] * v.y + r->m[2][1] * v.z,
                        r->m[0][2] * v.x + r->m[1][2] * v.y + r->m[2][2] * v.z };
}

static struct d3 anim_pos(vec3 p, const struct scene_anim *a, int frame)
{
    struct d3 d = d3_of(p), m = d3_of(a->move_per_frame);
    return (struct d3){ d.x + m.x * frame, d.y + m.y * frame, d.z + m.z * frame };
}

/* The grid: per pixel the nearest near/z and the next one. */
struct grid {
    int w, h;
    double sx, sy; /* canvas units → grid pixels */
    double near;
    double *best; /* 2 per pixel, 0 = nothing */
};

/* one screen-space vertex: grid position and near/z */
struct sv {
    double x, y, iz;
};

static void raster_tri(struct grid *g, struct sv a, struct sv b, struct sv c)
{
    double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (!(fabs(area) > 0)) return;
    double x0 = fmin(a.x, fmin(b.x, c.x)), x1 = fmax(a.x, fmax(b.x, c.x));
    double y0 = fmin(a.y, fmin(b.y, c.y)), y1 = fmax(a.y, fmax(b.y, c.y));
    if (x1 < 0 || y1 < 0 || x0 > g->w || y0 > g->h) return;
    int ix0 = x0 < 0 ? 0 : (int)floor(x0), ix1 = x1 >= g->w ? g->w - 1 : (int)floor(x1);
    int iy0 = y0 < 0 ? 0 : (int)floor(y0), iy1 = y1 >= g->h ? g->h - 1 : (int)floor(y1);
    double inv = 1.0 / area;
    for (int y = iy0; y <= iy1; y++) {
        double py = y + 0.5;
        for (int x = ix0; x <= ix1; x++) {
            double px = x + 0.5;
            double w0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) * inv;
            double w1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) * inv;
            double w2 = 1.0 - w0 - w1;
            if (!(w0 > 0 && w1 > 0 && w2 > 0)) continue; /* strictly inside: a shared edge is nobody's */
            double v = w0 * a.iz + w1 * b.iz + w2 * c.iz;
            double *p = g->best + 2 * ((size_t)y * (size_t)g->w + (size_t)x);
            if (v > p[0]) {
                p[1] = p[0];
                p[0] = v;
            } else if (v > p[1]) {
                p[1] = v;
            }
        }
    }
}

static struct sv project(const struct grid *g, struct d3 p)
{
    /* canvas units x * d / z (+y up), the grid's y down */
    return (struct sv){ g->w * 0.5 + p.x * g->near / p.z * g->sx, g->h * 0.5 - p.y * g->near / p.z * g->sy,
                        g->near / p.z };
}

static struct d3 lerp_z(struct d3 a, struct d3 b, double z)
{
    double t = (z - a.z) / (b.z - a.z);
    return (struct d3){ a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, z };
}

/* a camera-space triangle clipped at z = near (0, 1 or 2 triangles) */
static void clip_draw(struct grid *g, struct d3 v[3])
{
    struct d3 poly[4];
    int n = 0;
    for (int i = 0; i < 3; i++) {
        struct d3 a = v[i], b = v[(i + 1) % 3];
        int ina = a.z >= g->near, inb = b.z >= g->near;
        if (ina) poly[n++] = a;
        if (ina != inb) poly[n++] = lerp_z(a, b, g->near);
    }
    if (n < 3) return;
    struct sv s[4];
    for (int i = 0; i < n; i++) s[i] = project(g, poly[i]);
    raster_tri(g, s[0], s[1], s[2]);
    if (n == 4) raster_tri(g, s[0], s[2], s[3]);
}

/* Pixels of frame `frame` whose nearest surface has another one less than
 * the overlap gap behind it; *gap_min the smallest such gap seen (kept). */
static long overlap_frame(const struct scene *s, struct grid *g, int frame, double *gap_min)
{
    memset(g->best, 0, sizeof(double) * 2 * (size_t)g->w * (size_t)g->h);
    struct dmat cam = anim_rot(&s->camera.rotation, &s->camera_anim, frame);
    struct d3 cpos = anim_pos(s->camera.position, &s->camera_anim, frame);
    for (int i = 0; i < s->ninstances; i++) {
        const struct ras_instance *in = &s->instances[i];
        if (in->model >= s->nmodels) continue;
        const struct ras_model *m = &s->models[in->model];
        struct dmat r = anim_rot(&in->rotation, &in->anim, frame);
        struct d3 pos = anim_pos(in->position, &in->anim, frame);
        double sc = num_to_double(in->scale);
        for (int t = 0; t < m->ntris; t++) {
            struct d3 v[3];
            int bad = 0;
            for (int k = 0; k < 3; k++) {
                uint16_t vi = m->tris[t].v[k];
                if (vi >= m->nverts) {
                    bad = 1;
                    break;
                }
                struct d3 p = d3_of(m->verts[vi]);
                p = dmat_apply(&r, (struct d3){ p.x * sc, p.y * sc, p.z * sc });
                p = (struct d3){ p.x + pos.x - cpos.x, p.y + pos.y - cpos.y, p.z + pos.z - cpos.z };
                v[k] = dmat_apply_t(&cam, p);
            }
            if (bad) continue;
            if (s->ras.backface_cull) {
                struct d3 e1 = { v[1].x - v[0].x, v[1].y - v[0].y, v[1].z - v[0].z };
                struct d3 e2 = { v[2].x - v[0].x, v[2].y - v[0].y, v[2].z - v[0].z };
                struct d3 n = { e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x };
                if (-(v[0].x * n.x + v[0].y * n.y + v[0].z * n.z) <= 0) continue;
            }
            clip_draw(g, v);
        }
    }
    long count = 0;
    const double lim = DEPTH_GAP_STEPS16 / 65536.0;
    for (size_t p = 0; p < (size_t)g->w * (size_t)g->h; p++) {
        double a = g->best[2 * p], b = g->best[2 * p + 1];
        if (b <= 0) continue;
        double gap = a - b;
        if (gap < DEPTH_GAP_TIE || gap >= lim) continue;
        count++;
        if (gap < *gap_min) *gap_min = gap;
    }
    return count;
}

static int overlap(const struct scene *s, struct scene_depth_facts *f)
{
    double near = num_to_double(s->projection_d), vw = num_to_double(s->viewport_w),
           vh = num_to_double(s->viewport_h);
    int cw = s->canvas_w, ch = s->canvas_h;
    if (!(near > 0) || !(vw > 0) || !(vh > 0) || cw <= 0 || ch <= 0) return 0;
    /* a coarser grid where the memory is short (a big scene parsed on an
       emulated MCU): the share of close pixels is about the same */
    struct grid g = { .near = near };
    for (int side = DEPTH_GRID_MAX; !g.best; side /= 2) {
        if (side < DEPTH_GRID_MIN) return -1;
        double k = cw > ch ? (double)side / cw : (double)side / ch;
        if (k > 1) k = 1;
        g.w = (int)ceil(cw * k);
        g.h = (int)ceil(ch * k);
        g.best = malloc(sizeof(double) * 2 * (size_t)g.w * (size_t)g.h);
    }
    g.sx = g.w / vw;
    g.sy = g.h / vh;
    int frames = s->frames > 0 ? s->frames : 1;
    int n = frames <= DEPTH_FRAMES_CHECKED ? frames : DEPTH_FRAMES_CHECKED;
    f->overlap_checked = 1;
    f->frames_checked = n;
    f->grid_w = g.w;
    f->grid_h = g.h;
    for (int i = 0; i < n; i++) {
        int frame = n == frames ? i : (int)((long)i * (frames - 1) / (n - 1));
        long c = overlap_frame(s, &g, frame, &f->gap_min);
        if (c > f->close_pixels) {
            f->close_pixels = c;
            f->close_frame = frame;
        }
    }
    free(g.best);
    long limit = (long)g.w * g.h / DEPTH_PIXELS_SHARE;
    f->close_limit = limit;
    f->overlap_wants32 = f->close_pixels > limit;
    return 0;
}

int scene_depth_bits(const struct scene *s, struct scene_depth_facts *facts)
{
    struct scene_depth_facts f = { .rmin = 1e300, .gap_min = 1e300 };
    double cam_reach = reach3(&s->camera_anim, s->frames);
    for (int i = 0; i < s->ninstances; i++) {
        const struct ras_instance *in = &s->instances[i];
        if (in->model >= s->nmodels) continue;
        const struct ras_model *m = &s->models[in->model];
        double sc = fabs(num_to_double(in->scale)), vmax = 0;
        for (int k = 0; k < m->nverts; k++) vmax = fmax(vmax, dist3(m->verts[k]));
        vec3 rel = v3_sub(in->position, s->camera.position);
        double far = dist3(rel) + reach3(&in->anim, s->frames) + cam_reach + sc * vmax;
        if (far > f.far) f.far = far;
        double r = sc * num_to_double(m->bound_radius);
        if (r > 0 && r < f.rmin) f.rmin = r;
    }
    double near = num_to_double(s->projection_d);
    f.step16 = near > 0 ? f.far * f.far / (near * 65536.0) : 1e300;
    int bits = 16;
    if (s->ninstances) {
        f.range_wants32 = !(f.step16 <= f.rmin / 256);
        if (s->ras.depth_test && !s->ras.book_exact && overlap(s, &f) < 0) return -1;
        bits = f.range_wants32 || f.overlap_wants32 ? 32 : 16;
    }
    if (facts) *facts = f;
    return bits;
}
