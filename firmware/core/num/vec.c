/* SPDX-License-Identifier: MIT */
/* vec.c — vectors, matrices and colours on top of the scalar layer.
 * Mode-independent: the same source serves fixed, float and double. Operand
 * order follows the book (dot products x, y, z left to right; matrix rows
 * summed from column 0) so the double build reproduces the demos exactly. */
#define NUM_NO_INLINE   /* the out-of-line definitions live here */
#include "num.h"

vec3 v3_make(num x, num y, num z) { vec3 r = { x, y, z }; return r; }
vec3 v3_add(vec3 a, vec3 b) { return v3_make(num_add(a.x, b.x), num_add(a.y, b.y), num_add(a.z, b.z)); }
vec3 v3_sub(vec3 a, vec3 b) { return v3_make(num_sub(a.x, b.x), num_sub(a.y, b.y), num_sub(a.z, b.z)); }
vec3 v3_neg(vec3 a) { return v3_make(num_neg(a.x), num_neg(a.y), num_neg(a.z)); }
vec3 v3_scale(vec3 a, num s) { return v3_make(num_mul(a.x, s), num_mul(a.y, s), num_mul(a.z, s)); }

/* v3_dot, v3_dot_wide, v3_cross, v3_len and v3_normalize depend on the
 * mode: see num.c. */

vec3 m3_mul_v3(const mat3 *m, vec3 v)
{
    vec3 r;
    r.x = num_add(num_add(num_mul(m->m[0][0], v.x), num_mul(m->m[0][1], v.y)), num_mul(m->m[0][2], v.z));
    r.y = num_add(num_add(num_mul(m->m[1][0], v.x), num_mul(m->m[1][1], v.y)), num_mul(m->m[1][2], v.z));
    r.z = num_add(num_add(num_mul(m->m[2][0], v.x), num_mul(m->m[2][1], v.y)), num_mul(m->m[2][2], v.z));
    return r;
}

mat3 m3_mul(const mat3 *a, const mat3 *b)
{
    mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            num s = NUM_ZERO;
            for (int k = 0; k < 3; k++) s = num_add(s, num_mul(a->m[i][k], b->m[k][j]));
            r.m[i][j] = s;
        }
    return r;
}

mat3 m3_transpose(const mat3 *a)
{
    mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = a->m[j][i];
    return r;
}

mat3 m3_identity(void)
{
    mat3 r = { { { NUM_ONE, NUM_ZERO, NUM_ZERO }, { NUM_ZERO, NUM_ONE, NUM_ZERO },
                 { NUM_ZERO, NUM_ZERO, NUM_ONE } } };
    return r;
}

mat3 m3_rot_y_deg(num deg)
{
    num c = num_cos_deg(deg), s = num_sin_deg(deg);
    mat3 r = { { { c, NUM_ZERO, num_neg(s) }, { NUM_ZERO, NUM_ONE, NUM_ZERO }, { s, NUM_ZERO, c } } };
    return r;
}

vec4 m4_mul_v4(const mat4 *m, vec4 v)
{
    num in[4] = { v.x, v.y, v.z, v.w }, out[4];
    for (int i = 0; i < 4; i++) {
        num s = NUM_ZERO;
        for (int k = 0; k < 4; k++) s = num_add(s, num_mul(m->m[i][k], in[k]));
        out[i] = s;
    }
    vec4 r = { out[0], out[1], out[2], out[3] };
    return r;
}

vec3 m4_mul_point(const mat4 *m, vec3 p)
{
    num in[3] = { p.x, p.y, p.z }, out[3];
    for (int i = 0; i < 3; i++) {
        num s = NUM_ZERO;
        for (int k = 0; k < 3; k++) s = num_add(s, num_mul(m->m[i][k], in[k]));
        out[i] = num_add(s, m->m[i][3]);   /* num_mul(m, NUM_ONE) is m: no rounding */
    }
    return v3_make(out[0], out[1], out[2]);
}

mat4 m4_mul(const mat4 *a, const mat4 *b)
{
    mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            num s = NUM_ZERO;
            for (int k = 0; k < 4; k++) s = num_add(s, num_mul(a->m[i][k], b->m[k][j]));
            r.m[i][j] = s;
        }
    return r;
}

mat4 m4_transpose(const mat4 *a)
{
    mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) r.m[i][j] = a->m[j][i];
    return r;
}

mat4 m4_identity(void)
{
    mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) r.m[i][j] = i == j ? NUM_ONE : NUM_ZERO;
    return r;
}

mat4 m4_from_m3(const mat3 *a)
{
    mat4 r = m4_identity();
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = a->m[i][j];
    return r;
}

mat4 m4_translation(vec3 t)
{
    mat4 r = m4_identity();
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}

mat4 m4_scale(num k)
{
    mat4 r = m4_identity();
    r.m[0][0] = k;
    r.m[1][1] = k;
    r.m[2][2] = k;
    return r;
}

rgb rgb_make(num r, num g, num b) { rgb c = { r, g, b }; return c; }
rgb rgb_scale(rgb c, num k) { return rgb_make(num_mul(c.r, k), num_mul(c.g, k), num_mul(c.b, k)); }
rgb rgb_add(rgb a, rgb b) { return rgb_make(num_add(a.r, b.r), num_add(a.g, b.g), num_add(a.b, b.b)); }

uint16_t rgb_to_565(rgb c)
{
    return (uint16_t)(num_chan_levels(c.r, 31) << 11 | num_chan_levels(c.g, 63) << 5 |
                      num_chan_levels(c.b, 31));
}

void rgb_to_888(rgb c, uint8_t out[3])
{
    out[0] = num_chan_byte(c.r);
    out[1] = num_chan_byte(c.g);
    out[2] = num_chan_byte(c.b);
}
