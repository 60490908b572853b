/* SPDX-License-Identifier: MIT */
/* raster_clip.c — chapter 11: clipping. Instances are culled by their
 * bounding sphere against the book's five planes; the book path drops
 * triangles straddling a plane, the default path splits them. */
#include "raster_int.h"

/* The book's planes: near z = 1, and four at 45 degrees (s2 = 1/sqrt 2). */
#define S2 NUM_C(0.70710678118654746)
static const struct { num x, y, z, dist; } book_planes[5] = {
    { NUM_C(0.0), NUM_C(0.0), NUM_C(1.0), NUM_C(-1.0) },
    { S2, NUM_C(0.0), S2, NUM_C(0.0) },
    { -S2, NUM_C(0.0), S2, NUM_C(0.0) },
    { NUM_C(0.0), -S2, S2, NUM_C(0.0) },
    { NUM_C(0.0), S2, S2, NUM_C(0.0) },
};

static num plane_dist(int i, vec3 p)
{
    return num_add(v3_dot(v3_make(book_planes[i].x, book_planes[i].y, book_planes[i].z), p), book_planes[i].dist);
}

int ras_triangle_inside(vec3 a, vec3 b, vec3 c)
{
    for (int i = 0; i < 5; i++)
        if (!(plane_dist(i, a) > 0 && plane_dist(i, b) > 0 && plane_dist(i, c) > 0)) return 0;
    return 1;
}

/* Signed distance-like value of p to the default path's plane i
 * (>= 0 inside): near z >= near_z; |x| <= side_x z; |y| <= side_y z. */
static num clip_value(const struct ras_ctx *rc, int i, vec3 p)
{
    switch (i) {
    case 0: return num_sub(p.z, rc->def.near_z);
    case 1: return num_add(p.x, num_mul(rc->def.side_x, p.z));
    case 2: return num_sub(num_mul(rc->def.side_x, p.z), p.x);
    case 3: return num_add(p.y, num_mul(rc->def.side_y, p.z));
    default: return num_sub(num_mul(rc->def.side_y, p.z), p.y);
    }
}

/* An instance is dropped when its bounding sphere lies wholly outside one
 * plane. The book path tests the book's planes; the default path the planes
 * its clipper uses (near z = d, sides at the viewport's edges), whose values
 * are distances scaled by sqrt(1 + side^2): with d < 1 or a viewport wider
 * than 90 degrees the book's planes would drop visible instances. The
 * sphere's radius is widened by two steps (NUM_EPS) so that rounding never drops an
 * instance that touches the frustum. */
int ras_instance_visible(const struct ras_ctx *rc, const struct ras_inst *ri,
                         const struct ras_model *m, num scale)
{
    vec4 c4 = { m->bound_center.x, m->bound_center.y, m->bound_center.z, NUM_ONE };
    c4 = m4_mul_v4(&ri->m, c4);
    vec3 c = v3_make(c4.x, c4.y, c4.z);
    num r = num_mul(m->bound_radius, scale);
    if (rc->book) {
        for (int i = 0; i < 5; i++)
            if (plane_dist(i, c) < num_neg(r)) return 0;
        return 1;
    }
    r = num_add(r, num_add(NUM_EPS, NUM_EPS));
    for (int i = 0; i < 5; i++) {
        num k = i == 0 ? NUM_ONE : i < 3 ? rc->def.side_xk : rc->def.side_yk;
        if (clip_value(rc, i, c) < num_neg(num_mul(r, k))) return 0;
    }
    return 1;
}

int ras_point_inside(const struct ras_ctx *rc, vec3 p)
{
    /* clip_value of the five planes, each side product formed once */
    if (num_sub(p.z, rc->def.near_z) < 0) return 0;
    num sx = num_mul(rc->def.side_x, p.z);
    if (num_add(p.x, sx) < 0 || num_sub(sx, p.x) < 0) return 0;
    num sy = num_mul(rc->def.side_y, p.z);
    return !(num_add(p.y, sy) < 0 || num_sub(sy, p.y) < 0);
}

int ras_box_inside(const struct ras_ctx *rc, const struct ras_box *b)
{
    /* a point's x >= lo[0], <= hi[0] (y alike) and z >= lo[2]; each value
     * below grows with z (the side slopes are not negative) and with x
     * (or falls with it): its least over the box is at these corners */
    if (!b->ok || rc->def.side_x < 0 || rc->def.side_y < 0) return 0;
    if (num_sub(b->lo[2], rc->def.near_z) < 0) return 0;
    num sx = num_mul(rc->def.side_x, b->lo[2]);
    if (num_add(b->lo[0], sx) < 0 || num_sub(sx, b->hi[0]) < 0) return 0;
    num sy = num_mul(rc->def.side_y, b->lo[2]);
    return !(num_add(b->lo[1], sy) < 0 || num_sub(sy, b->hi[1]) < 0);
}

static struct ras_cv lerp_cv(const struct ras_cv *a, const struct ras_cv *b, num t, int na)
{
    struct ras_cv r;
    r.p = v3_add(a->p, v3_scale(v3_sub(b->p, a->p), t));
    for (int j = 0; j < na; j++) r.a[j] = num_add(a->a[j], num_mul(num_sub(b->a[j], a->a[j]), t));
    return r;
}

int ras_clip_triangle(const struct ras_ctx *rc, const struct ras_cv in[3], int na, struct ras_cv *out)
{
    struct ras_cv buf[2][RAS_CLIP_MAX];
    int n = 3;
    for (int k = 0; k < 3; k++) buf[0][k] = in[k];
    int cur = 0;
    for (int pl = 0; pl < 5; pl++) {
        const struct ras_cv *src = buf[cur];
        struct ras_cv *dst = buf[cur ^ 1];
        int m = 0;
        for (int k = 0; k < n; k++) {
            const struct ras_cv *a = &src[k], *b = &src[(k + 1) % n];
            num da = clip_value(rc, pl, a->p), db = clip_value(rc, pl, b->p);
            if (da >= 0 && m < RAS_CLIP_MAX) dst[m++] = *a;
            if ((da >= 0) != (db >= 0) && m < RAS_CLIP_MAX) {
                num t = num_div(da, num_sub(da, db)); /* in [0, 1]: crossing point */
                struct ras_cv c = lerp_cv(a, b, num_clamp(t, NUM_ZERO, NUM_ONE), na);
                if (pl == 0) c.p.z = num_max(c.p.z, rc->def.near_z); /* exactly on the plane */
                dst[m++] = c;
            }
        }
        n = m;
        cur ^= 1;
        if (n < 3) return 0;
    }
    for (int k = 0; k < n; k++) out[k] = buf[cur][k];
    return n;
}
