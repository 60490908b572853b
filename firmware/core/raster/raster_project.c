/* SPDX-License-Identifier: MIT */
/* raster_project.c — chapters 9 and 10: ProjectVertex, instance and camera
 * transforms as homogeneous 4x4 matrices (the book's bracketing). */
#include "raster_int.h"

/* ProjectVertex + ViewportToCanvas: ((v.x*d)/v.z)*Cw/Vw (raster_num.h keeps
 * the demos' order in the double build). Canvas units, +y up. */
void ras_project_vertex(const struct ras_ctx *rc, vec3 v, num *x, num *y)
{
    /* cw/vw == ch/vh (the viewport width follows the aspect): one scale for
     * both axes, without the rounding of an aspect-derived vw */
    *x = ras_project(v.x, rc->d, v.z, num_from_int(rc->h), rc->vh);
    *y = ras_project(v.y, rc->d, v.z, num_from_int(rc->h), rc->vh);
}

/* Animation (scene_anim): frame f turns by f*rot_y_per_frame about y after
 * the scene's rotation and moves by f*move_per_frame. Frame 0 is the scene
 * as written, untouched. */
static vec3 anim_pos(vec3 p, const struct scene_anim *a, uint16_t frame)
{
    if (frame == 0) return p;
    return v3_add(p, v3_make(num_mul_int(a->move_per_frame.x, frame), num_mul_int(a->move_per_frame.y, frame),
                             num_mul_int(a->move_per_frame.z, frame)));
}

static mat3 anim_rot(const mat3 *r, const struct scene_anim *a, uint16_t frame)
{
    if (frame == 0 || a->rot_y_per_frame == NUM_ZERO) return *r;
    /* the angle rot x frame reduced modulo 360 exactly: no saturation, no drift */
    mat3 ry = m3_rot_y_deg(num_mul_int_mod(a->rot_y_per_frame, frame, NUM_C(360.0)));
    return m3_mul(&ry, r);
}

mat3 ras_instance_rotation(const struct ras_instance *in, uint16_t frame)
{
    return anim_rot(&in->rotation, &in->anim, frame);
}

/* M_inst = Translation(position) . (Rotation . Scale(scale)). */
mat4 ras_instance_matrix(const struct ras_instance *in, uint16_t frame)
{
    mat3 r3 = ras_instance_rotation(in, frame);
    mat4 r = m4_from_m3(&r3), s = m4_scale(in->scale), t = m4_translation(anim_pos(in->position, &in->anim, frame));
    mat4 rs = m4_mul(&r, &s);
    return m4_mul(&t, &rs);
}

/* M_cam = Transpose(camera rotation) . Translation(-position). */
mat4 ras_camera_matrix(const struct scene *s, uint16_t frame, mat4 *rot_t, vec3 *pos)
{
    mat3 r3 = anim_rot(&s->camera.rotation, &s->camera_anim, frame);
    *pos = anim_pos(s->camera.position, &s->camera_anim, frame);
    mat4 r = m4_from_m3(&r3);
    *rot_t = m4_transpose(&r);
    mat4 t = m4_translation(v3_scale(*pos, num_neg(NUM_ONE)));
    return m4_mul(rot_t, &t);
}

/* Face normals and projections kept wide (raster_int.h). In the floating
 * modes wnum is num's type and every step below is the same operation as
 * v3_cross / v3_dot / num_div(num_mul()), so those builds (the book's double
 * reference among them) give the same bits as the narrow forms. */
struct ras_wnormal ras_face_normal_wide(vec3 a, vec3 b, vec3 c)
{
    vec3 e1 = v3_sub(b, a), e2 = v3_sub(c, a);
    struct ras_wnormal n;
    n.x = wnum_sub(num_mul_wide(e1.y, e2.z), num_mul_wide(e1.z, e2.y));
    n.y = wnum_sub(num_mul_wide(e1.z, e2.x), num_mul_wide(e1.x, e2.z));
    n.z = wnum_sub(num_mul_wide(e1.x, e2.y), num_mul_wide(e1.y, e2.x));
    return n;
}

vec3 ras_wnormal_narrow(struct ras_wnormal n)
{
    return v3_make(wnum_to_num(n.x), wnum_to_num(n.y), wnum_to_num(n.z));
}

wnum ras_facing_wide(vec3 p, struct ras_wnormal n)
{
    wnum s = wnum_mul(wnum_from_num(num_neg(p.x)), n.x);
    s = wnum_add(s, wnum_mul(wnum_from_num(num_neg(p.y)), n.y));
    return wnum_add(s, wnum_mul(wnum_from_num(num_neg(p.z)), n.z));
}

num ras_mul_div(num x, num z, num unproj)
{
    return wnum_div(num_mul_wide(x, z), wnum_from_num(unproj));
}

/* i as a num: num_from_int without its call where it cannot saturate. */
static inline num centre_num(int32_t i)
{
#if NUM_MODE == NUM_MODE_FIXED
    if (i >= 0 && i <= (INT32_MAX >> NUM_FRAC)) return (num)((uint32_t)i << NUM_FRAC);
#endif
    return num_from_int(i);
}

/* Screen position of a camera-space point inside the clip volume, in
 * sub-pixel units (y down): the default path's projection. */
static void project_sub_xy(const struct ras_ctx *rc, num X, num Y, int32_t *sx, int32_t *sy)
{
    num fx = num_add(centre_num(rc->w / 2), X);
    num fy = num_sub(centre_num(rc->h / 2), Y);
    /* integer and fraction apart, so Q15.16 never holds pixels << 8 */
    *sx = ras_sub_pos(fx, rc->def.sub_bits);
    *sy = ras_sub_pos(fy, rc->def.sub_bits);
}

void ras_project_sub(const struct ras_ctx *rc, vec3 p, int32_t *sx, int32_t *sy)
{
    project_sub_xy(rc, ras_mul_div(p.x, rc->unproj, p.z), ras_mul_div(p.y, rc->unproj, p.z), sx, sy);
}

void ras_subproj_of(const struct ras_ctx *rc, struct ras_subproj *k)
{
    /* project_sub_xy's constants: ras_div_sub makes its steps */
    k->unproj = rc->unproj;
    k->near_z = rc->def.near_z;
    k->cx = centre_num(rc->w / 2);
    k->cy = centre_num(rc->h / 2);
    k->sb = rc->def.sub_bits;
}

void ras_project_sub_depth(const struct ras_ctx *rc, vec3 p, int32_t *sx, int32_t *sy, num *iz, uint32_t *depth)
{
    struct ras_subproj k;
    struct ras_subpos o;
    ras_subproj_of(rc, &k);
    ras_div_sub(&k, p.x, p.y, p.z, &o);
    *sx = o.sx;
    *sy = o.sy;
    *iz = o.iz;
    *depth = o.depth;
}

/* Scene canvas to render canvas: v*h/canvas_h with one rounding (exact at
 * the scene's own size). */
num ras_scale_canvas(const struct ras_ctx *rc, num v)
{
    return wnum_div(num_mul_wide(v, num_from_int(rc->h)), wnum_from_num(num_from_int(rc->s->canvas_h)));
}

/* A model-space corner normal in camera space (the instance's rotations). */
vec3 ras_corner_normal(const struct ras_inst *ri, vec3 n)
{
    return ri->nsplit ? ras_mul_normal_split(&ri->nmat, n, ri->nsplit) : ras_mul_point(&ri->nmat, n);
}
