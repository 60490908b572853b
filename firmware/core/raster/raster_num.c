/* SPDX-License-Identifier: MIT */
/* raster_num.c — mode-specific rasterizer primitives (see raster_num.h). */
#include "raster_num.h"
#if NUM_MODE == NUM_MODE_FIXED
#include "num/num_int.h"
/* 64/32 divisions through num_udiv64_32 (table + Newton, exact) where the
 * library's 64-bit divide is a bit loop: ARMv6-M has no divide instruction.
 * ARMv7-M's __aeabi_uldivmod uses UDIV and measured faster there (make
 * bench); the host takes this path too so the tests cover it. Both give
 * the same bits. */
#if defined(__ARM_ARCH_6M__) || !defined(__arm__)
#define RAS_DIV64_32 1
#else
#define RAS_DIV64_32 0
#endif
#endif

/* un / d without the library's 64-bit division where it can (d < 2^32):
 * 1 with *q and *r, or 0. */
static int udiv_fast(uint64_t un, uint32_t d, uint64_t *q, uint32_t *r)
{
    if (un <= UINT32_MAX) {   /* small triangles' set-up: one 32-bit division */
        *q = (uint32_t)un / d;
        *r = (uint32_t)un - (uint32_t)*q * d;
        return 1;
    }
#if NUM_MODE == NUM_MODE_FIXED && RAS_DIV64_32
    if ((un >> 32) < d) {
        *q = num_udiv64_32(un, d, r);
        return 1;
    }
#endif
    return 0;
}

int64_t ras_floordiv(int64_t n, int64_t d, int64_t *rem)
{
    uint64_t un = n < 0 ? (uint64_t)0 - (uint64_t)n : (uint64_t)n, q;
    uint32_t r;
    if (d > 0 && d <= (int64_t)UINT32_MAX && udiv_fast(un, (uint32_t)d, &q, &r)) {
        /* |n| = q d + r: the floor of n / d and its remainder in [0, d) */
        if (n >= 0) { *rem = r; return (int64_t)q; }
        if (r == 0) { *rem = 0; return -(int64_t)q; }
        *rem = d - r;
        return -(int64_t)q - 1;
    }
    int64_t qs = n / d, rs = n % d;
    if (rs < 0) { qs--; rs += d; }
    *rem = rs;
    return qs;
}

/* ras_div_depth's four quotients by z, each its own division (float and
 * double; fixed point where z has no prepared reciprocal, out of line: the
 * rare case) */
#if NUM_MODE == NUM_MODE_FIXED
__attribute__((noinline))
#endif
static void div_depth_plain(num x, num y, num z, num unproj, num near_z, num *X, num *Y, num *iz, uint32_t *depth)
{
    *X = wnum_div(num_mul_wide(x, unproj), wnum_from_num(z));
    *Y = wnum_div(num_mul_wide(y, unproj), wnum_from_num(z));
    *iz = num_recip(z);
    *depth = ras_depth32(near_z, z);
}

#if NUM_MODE == NUM_MODE_FIXED

void ras_interp_init(struct ras_interp *it, num i0, num d0, num i1, num d1)
{
    it->base = d0;
    it->val = 0;
    it->q = it->r = 0;
    it->den = (int64_t)i1 - i0;
    if (it->den <= 0) { it->den = 1; it->rem = 0; return; }
    int64_t numer = ((int64_t)d1 - d0) * NUM_ONE_RAW; /* |.| < 2^48 */
    it->q = ras_floordiv(numer, it->den, &it->r);
    it->rem = it->den / 2; /* rounds k*q to nearest */
}

num ras_interp_value(const struct ras_interp *it)
{
    int64_t v = it->base + it->val;
    if (v > INT32_MAX) return NUM_MAX;
    if (v < -(int64_t)INT32_MAX) return NUM_MIN;
    return (num)v;
}

void ras_interp_next(struct ras_interp *it)
{
    it->val += it->q;
    it->rem += it->r;
    if (it->rem >= it->den) { it->val++; it->rem -= it->den; }
    /* keep far-off streams bounded (they saturate when read anyway) */
    if (it->val > ((int64_t)1 << 40)) it->val = (int64_t)1 << 40;
    if (it->val < -((int64_t)1 << 40)) it->val = -((int64_t)1 << 40);
}

num ras_count_next(num a, num a0, int32_t k) { (void)a0; (void)k; return num_add(a, NUM_ONE); }
int32_t ras_count_index(num a, num a0, int32_t k) { (void)a; (void)a0; return k; }

num ras_ratio(int64_t p, int64_t q)
{
    if (q == 0) return p == 0 ? 0 : (p > 0 ? NUM_MAX : NUM_MIN);
    if (q < 0) { p = -p; q = -q; }
    int neg = p < 0;
    uint64_t up = neg ? (uint64_t)0 - (uint64_t)p : (uint64_t)p;
    if (up >= ((uint64_t)1 << (62 - NUM_FRAC))) { /* keep p * 2^NUM_FRAC inside 64 bits */
        int s = 0;
        while (up >= ((uint64_t)1 << (62 - NUM_FRAC))) { up >>= 1; s++; }
        q >>= s;
        if (q == 0) return neg ? NUM_MIN : NUM_MAX;
    }
    uint64_t n = (up << NUM_FRAC) + (uint64_t)q / 2, r;
    if (RAS_DIV64_32 && (uint64_t)q <= UINT32_MAX)
        r = (n >> 32) >= (uint64_t)q ? (uint64_t)INT32_MAX : num_udiv64_32(n, (uint32_t)q, 0);
    else
        r = n / (uint64_t)q;
    if (r > (uint64_t)INT32_MAX) r = INT32_MAX;
    return neg ? -(num)r : (num)r;
}

num ras_project(num x, num d, num z, num cw, num vw)
{
    /* x*d and z*vw exact (Q.2F, under 2^62 in magnitude), shifted right
     * together until z*vw fits 32 bits (the hardware divider's 64/32; a
     * relative error under 2^-31 on either), then x*d*cw / (z*vw) rounded
     * once: a small x*d or z*vw (a tiny viewport, d or depth) keeps its
     * precision instead of being rounded to the format first */
    int64_t a = (int64_t)x * d, b = (int64_t)z * vw;
    int neg = (a < 0) != (b < 0);
    uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? (uint64_t)0 - (uint64_t)b : (uint64_t)b;
    if (ub == 0) return ua == 0 ? 0 : (neg ? NUM_MIN : NUM_MAX);
    if ((cw & (NUM_ONE_RAW - 1)) == 0 && cw > 0) {
        uint64_t cwi = (uint64_t)(cw >> NUM_FRAC);
        while (ub > UINT32_MAX || ua >= ((uint64_t)1 << 50)) {
            ua >>= 1;
            ub >>= 1;
        }
        if (ub == 0) return neg ? NUM_MIN : NUM_MAX;
        int64_t p = (int64_t)(ua * cwi);
        return ras_ratio(neg ? -p : p, (int64_t)ub);
    }
    int64_t xd = (a + (1 << (NUM_FRAC - 1))) >> NUM_FRAC;     /* Q.F */
    return num_div(num_mul(num_div(xd > INT32_MAX ? NUM_MAX : (xd < -INT32_MAX ? NUM_MIN : (num)xd), z), cw), vw);
}

uint32_t ras_depth32(num near_z, num z)
{
    if (z <= 0 || z <= near_z) return UINT32_MAX;
    /* near < z: the quotient fits 32 bits */
    uint64_t n = (uint64_t)(uint32_t)near_z << 32;
    return RAS_DIV64_32 ? num_udiv64_32(n, (uint32_t)z, 0) : (uint32_t)(n / (uint32_t)z);
}

vec3 ras_mul_point(const mat4 *m, vec3 p)
{
    /* vec.c's m4_mul_point: each row summed from column 0, the translation
     * last (its first sum 0 + a product is the product: num_mul never
     * gives INT32_MIN) */
    vec3 r;
    r.x = num_add(num_add(num_add(num_mul(m->m[0][0], p.x), num_mul(m->m[0][1], p.y)), num_mul(m->m[0][2], p.z)),
                  m->m[0][3]);
    r.y = num_add(num_add(num_add(num_mul(m->m[1][0], p.x), num_mul(m->m[1][1], p.y)), num_mul(m->m[1][2], p.z)),
                  m->m[1][3]);
    r.z = num_add(num_add(num_add(num_mul(m->m[2][0], p.x), num_mul(m->m[2][1], p.y)), num_mul(m->m[2][2], p.z)),
                  m->m[2][3]);
    return r;
}

void ras_box_of(struct ras_box *b, const vec3 *v, uint32_t n)
{
    b->ok = n > 0;
    if (!n) return;
    b->lo[0] = b->hi[0] = v[0].x;
    b->lo[1] = b->hi[1] = v[0].y;
    b->lo[2] = b->hi[2] = v[0].z;
    for (uint32_t k = 1; k < n; k++) {
        const num c[3] = { v[k].x, v[k].y, v[k].z };
        for (int j = 0; j < 3; j++) {
            if (c[j] < b->lo[j]) b->lo[j] = c[j];
            if (c[j] > b->hi[j]) b->hi[j] = c[j];
        }
    }
    /* the sphere: the box's middle, and the greatest squared distance of a
     * point from it (each difference below 2^31 in magnitude, the sum of
     * three squares below 2^64), its square root rounded up */
    uint64_t r2 = 0;
    for (int j = 0; j < 3; j++) b->c[j] = (num)(b->lo[j] + ((int64_t)b->hi[j] - b->lo[j]) / 2);
    for (uint32_t k = 0; k < n; k++) {
        const num c[3] = { v[k].x, v[k].y, v[k].z };
        uint64_t d2 = 0;
        for (int j = 0; j < 3; j++) {
            const int64_t d = (int64_t)c[j] - b->c[j];
            d2 += (uint64_t)(d * d);
        }
        if (d2 > r2) r2 = d2;
    }
    uint64_t rem;
    const uint64_t r = num_isqrt64(r2, &rem) + (rem != 0);
    b->sphere = r < ((uint64_t)1 << 30);
    b->r = b->sphere ? (uint32_t)r : 0;
}

int ras_box_transform(const mat4 *m, const struct ras_box *b, struct ras_box *out)
{
    out->ok = 0;
    if (!b->ok) return 0;
    for (int i = 0; i < 3; i++) {
        /* row i's rounded products over the box (num_mul_round, before
         * num_mul's saturation), their sums' range and the largest
         * magnitude any partial sum can have */
        const num t = m->m[i][3];
        int64_t lo = t, hi = t, mag = t < 0 ? -(int64_t)t : t;
        for (int j = 0; j < 3; j++) {
            int64_t p = num_mul_round(m->m[i][j], b->lo[j]), q = num_mul_round(m->m[i][j], b->hi[j]);
            if (p > q) {
                const int64_t x = p;
                p = q;
                q = x;
            }
            lo += p;
            hi += q;
            mag += (p < 0 ? -p : p) > (q < 0 ? -q : q) ? (p < 0 ? -p : p) : (q < 0 ? -q : q);
        }
        /* every product and partial sum within +-(2^31 - 1): none saturates */
        if (mag > (int64_t)INT32_MAX) return 0;
        out->lo[i] = (num)lo;
        out->hi[i] = (num)hi;
    }
    out->ok = 1;
    return 1;
}

/* |a| / 2^F rounded up; a / 2^F rounded down when down, up otherwise */
static int64_t q_up_abs(int64_t a)
{
    const int64_t u = a < 0 ? -a : a;
    return (u + (((int64_t)1 << NUM_FRAC) - 1)) / ((int64_t)1 << NUM_FRAC);
}
static int64_t q_round(int64_t a, int down)
{
    int64_t rem;
    const int64_t q = ras_floordiv(a, (int64_t)1 << NUM_FRAC, &rem);
    return down ? q : q + (rem != 0);
}

int ras_sphere_inside(const mat4 *m, const struct ras_box *b, const struct ras_box *cb, num near_z, num side_x,
                      num side_y)
{
    /* In num's raw units (1 = 2^-F): a point p's camera coordinates
     * ras_mul_point_fit gives are P + e, P = M p + t exactly and each |e_i|
     * <= 3/2 (three products rounded to nearest, sums exact). A plane's
     * test value f . (P + e) + k (f = (1, 0, side_x) for x + side_x z and
     * alike, k = -near_z for z - near_z) is formed with one product
     * rounded to nearest, so it is >= 0 whenever the exact f . (P + e) + k
     * is >= 0. With p = c + d, |d| <= r (b's sphere):
     *   f . P + k >= f . (M c + t) + k - |M^T f| r,  |f . e| <= 3/2 sum |f_i|,
     * each bounded below in units of 2^-2F with 64-bit integers: M c + t
     * exactly (below 2^(33+F): cb bounds each product by 2^31), then
     * rounded towards the bound; |M^T f| from its components rounded up
     * to 2^-F, the square root rounded up. No test saturates: cb within
     * +-2^26 and 0 <= side < 2^(F+4) keep each product below 2^30. */
    if (!b->sphere || !cb->ok || side_x < 0 || side_y < 0) return 0;
    const int64_t side_max = (int64_t)1 << (NUM_FRAC + 4), lim = (int64_t)1 << 26;
    if (side_x >= side_max || side_y >= side_max || near_z < 0) return 0;
    for (int i = 0; i < 3; i++)
        if (cb->lo[i] <= -lim || cb->hi[i] >= lim) return 0;
    int64_t z[3];
    for (int i = 0; i < 3; i++) {
        z[i] = (int64_t)m->m[i][3] * ((int64_t)1 << NUM_FRAC);
        for (int j = 0; j < 3; j++) z[i] += (int64_t)m->m[i][j] * b->c[j];
    }
    const int64_t one = (int64_t)1 << NUM_FRAC;
    const int64_t f[5][3] = {
        { 0, 0, one }, { one, 0, side_x }, { -one, 0, side_x }, { 0, one, side_y }, { 0, -one, side_y },
    };
    for (int pl = 0; pl < 5; pl++) {
        int64_t a = pl == 0 ? -(int64_t)near_z * one : 0, fsum = 0;
        uint64_t g2 = 0;
        for (int i = 0; i < 3; i++) {
            a += f[pl][i] * q_round(z[i], f[pl][i] >= 0);
            fsum += f[pl][i] < 0 ? -f[pl][i] : f[pl][i];
        }
        for (int j = 0; j < 3; j++) {
            int64_t g = 0;
            for (int i = 0; i < 3; i++) g += f[pl][i] * m->m[i][j];
            const int64_t gu = q_up_abs(g);
            if (gu >= ((int64_t)1 << 31)) return 0;
            g2 += (uint64_t)(gu * gu);
        }
        uint64_t rem;
        const uint64_t gn = num_isqrt64(g2, &rem) + (rem != 0);
        if (a < (int64_t)(gn * b->r) + 2 * fsum) return 0;
    }
    return 1;
}

vec3 ras_mul_point_fit(const mat4 *m, vec3 p)
{
    /* ras_mul_point's order: each row from column 0, the translation last */
    vec3 r;
    r.x = num_add_fit(num_add_fit(num_add_fit(num_mul_fit(m->m[0][0], p.x), num_mul_fit(m->m[0][1], p.y)),
                                  num_mul_fit(m->m[0][2], p.z)),
                      m->m[0][3]);
    r.y = num_add_fit(num_add_fit(num_add_fit(num_mul_fit(m->m[1][0], p.x), num_mul_fit(m->m[1][1], p.y)),
                                  num_mul_fit(m->m[1][2], p.z)),
                      m->m[1][3]);
    r.z = num_add_fit(num_add_fit(num_add_fit(num_mul_fit(m->m[2][0], p.x), num_mul_fit(m->m[2][1], p.y)),
                                  num_mul_fit(m->m[2][2], p.z)),
                      m->m[2][3]);
    return r;
}

int ras_fit_split(const mat4 *m, const struct ras_box *b)
{
    /* a coordinate a = ah 2^s + al (ah = a >> s, al in [0, 2^s)) and an
     * entry e of m: (e a + 2^(F-1)) >> F, num_mul_round's value, is
     * (e ah + ((e al + 2^(F-1)) >> s)) >> (F - s) (nested floors), exact in
     * 32 bits when |e| <= M and |a| <= A give
     *   w = e al + 2^(F-1):  |w| <= M (2^s - 1) + 2^(F-1) < 2^31,
     *   u = e ah:            |u| <= M ((A >> s) + 1) < 2^31,
     *   u + (w >> s):        |.| <= that + (|w| >> s) + 1 < 2^31;
     * s the largest that keeps w (the others only get easier with s) */
    if (!b->ok) return 0;
    int64_t M = 0, A = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const int64_t e = m->m[i][j] < 0 ? -(int64_t)m->m[i][j] : m->m[i][j];
            if (e > M) M = e;
        }
    for (int j = 0; j < 3; j++) {
        const int64_t lo = b->lo[j] < 0 ? -(int64_t)b->lo[j] : b->lo[j];
        const int64_t hi = b->hi[j] < 0 ? -(int64_t)b->hi[j] : b->hi[j];
        if (lo > A) A = lo;
        if (hi > A) A = hi;
    }
    const int64_t lim = INT32_MAX, half = (int64_t)1 << (NUM_FRAC - 1);
    for (int s = NUM_FRAC < 30 ? NUM_FRAC : 30; s >= 1; s--) {
        const int64_t w = M * (((int64_t)1 << s) - 1) + half;
        if (w > lim) continue;
        const int64_t u = M * ((A >> s) + 1);
        return u + (w >> s) + 1 <= lim ? s : 0;
    }
    return 0;
}

/* (e a + 2^(F-1)) >> F from a's halves (ras_fit_split) */
static inline int32_t mul_split(int32_t e, int32_t ah, int32_t al, int s, int fs)
{
    return (e * ah + ((e * al + ((int32_t)1 << (NUM_FRAC - 1))) >> s)) >> fs;
}

#if defined(__ARM_ARCH_6M__) && defined(__GNUC__) && !defined(__clang__)
/* ARMv6-M: n >= 1 points by hand, column by column (each coordinate split
 * once, its three terms added to the rows' sums), mul_split's operations
 * in 32-bit registers. Registers: r0, r1 the coordinate's halves ah, al,
 * r2 the term, r3 the entry, r4 s, r5 F - s, r6 m, r7 the point; r8-r10
 * the rows' sums (from the translation), r11 2^(F-1), r12 the output, lr
 * the end of the points. */
#define XF_TERM(off, acc) \
    "ldr r3, [r6, #" #off "]\n\t movs r2, r1\n\t muls r2, r3, r2\n\t add r2, r11\n\t asrs r2, r4\n\t" \
    "muls r3, r0, r3\n\t adds r2, r2, r3\n\t asrs r2, r5\n\t add " acc ", r2\n\t"
#define XF_COLUMN(off, e0, e1, e2) \
    "ldr r1, [r7, #" #off "]\n\t movs r0, r1\n\t asrs r0, r4\n\t movs r2, r0\n\t lsls r2, r4\n\t" \
    "subs r1, r1, r2\n\t" XF_TERM(e0, "r8") XF_TERM(e1, "r9") XF_TERM(e2, "r10")
#define XF_STR2(x) #x
#define XF_STR(x) XF_STR2(x)
static inline __attribute__((always_inline)) void xf_points_v6m(const mat4 *m, const vec3 *p, vec3 *out, uint32_t n, int s)
{
    register const mat4 *r0 __asm__("r0") = m;
    register const vec3 *r1 __asm__("r1") = p;
    register vec3 *r2 __asm__("r2") = out;
    register uint32_t r3 __asm__("r3") = n;
    register int r4 __asm__("r4") = s;
    __asm__ volatile(
        ".syntax unified\n\t"
        "movs r5, #12\n\t muls r3, r5, r3\n\t adds r3, r1, r3\n\t mov lr, r3\n\t mov r12, r2\n\t"
        "movs r5, #" XF_STR(NUM_FRAC) "\n\t subs r5, r5, r4\n\t"
        "movs r3, #1\n\t lsls r3, r3, #" XF_STR(NUM_FRAC) " - 1\n\t mov r11, r3\n\t"
        "mov r6, r0\n\t mov r7, r1\n"
        "1:\n\t ldr r3, [r6, #12]\n\t mov r8, r3\n\t ldr r3, [r6, #28]\n\t mov r9, r3\n\t"
        "ldr r3, [r6, #44]\n\t mov r10, r3\n\t"
        XF_COLUMN(0, 0, 16, 32) XF_COLUMN(4, 4, 20, 36) XF_COLUMN(8, 8, 24, 40)
        "mov r0, r8\n\t mov r1, r9\n\t mov r2, r10\n\t mov r3, r12\n\t stm r3!, {r0, r1, r2}\n\t mov r12, r3\n\t"
        "adds r7, #12\n\t cmp r7, lr\n\t bne 1b\n\t"
        ".syntax divided\n"
        : "+l"(r0), "+l"(r1), "+l"(r2), "+l"(r3), "+l"(r4)
        :
        : "r5", "r6", "r7", "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");
}
#endif

void ras_mul_points_fit_split(const mat4 *m, const vec3 *p, vec3 *out, uint32_t n, int s)
{
#if defined(__ARM_ARCH_6M__) && defined(__GNUC__) && !defined(__clang__)
    if (n) xf_points_v6m(m, p, out, n, s);
#else
    for (uint32_t k = 0; k < n; k++) out[k] = ras_mul_point_fit_split(m, p[k], s);
#endif
}

vec3 ras_mul_point_fit_split(const mat4 *m, vec3 p, int s)
{
#if defined(__ARM_ARCH_6M__) && defined(__GNUC__) && !defined(__clang__)
    vec3 r;
    xf_points_v6m(m, &p, &r, 1, s);
    return r;
#else
    const int fs = NUM_FRAC - s;
    const uint32_t mask = ((uint32_t)1 << s) - 1u;
    const int32_t xh = p.x >> s, yh = p.y >> s, zh = p.z >> s;
    const int32_t xl = (int32_t)((uint32_t)p.x & mask), yl = (int32_t)((uint32_t)p.y & mask),
                  zl = (int32_t)((uint32_t)p.z & mask);
    /* (sums modulo 2^32 as num_add_fit's: the same in any order) */
    vec3 r;
    r.x = (num)((uint32_t)mul_split(m->m[0][0], xh, xl, s, fs) + (uint32_t)mul_split(m->m[0][1], yh, yl, s, fs) +
                (uint32_t)mul_split(m->m[0][2], zh, zl, s, fs) + (uint32_t)m->m[0][3]);
    r.y = (num)((uint32_t)mul_split(m->m[1][0], xh, xl, s, fs) + (uint32_t)mul_split(m->m[1][1], yh, yl, s, fs) +
                (uint32_t)mul_split(m->m[1][2], zh, zl, s, fs) + (uint32_t)m->m[1][3]);
    r.z = (num)((uint32_t)mul_split(m->m[2][0], xh, xl, s, fs) + (uint32_t)mul_split(m->m[2][1], yh, yl, s, fs) +
                (uint32_t)mul_split(m->m[2][2], zh, zl, s, fs) + (uint32_t)m->m[2][3]);
    return r;
#endif
}

vec3 ras_mul_normal_split(const mat4 *m, vec3 n, int s)
{
    /* |c| <= B as one unsigned comparison of c + B with 2B */
    const uint32_t b = (uint32_t)RAS_NORMAL_BOX;
    if ((uint32_t)n.x + b <= 2u * b && (uint32_t)n.y + b <= 2u * b && (uint32_t)n.z + b <= 2u * b)
        return ras_mul_point_fit_split(m, n, s);
    return ras_mul_point(m, n);
}

/* num_udiv64_32_pre(n, p, rem) for a divisor below 2^30 (p->s >= 2): its
 * estimate q is at most 3 below the quotient, so the remainder n - q d
 * lies below 4 d < 2^32 and is its low word, n's low word less q d modulo
 * 2^32 (one 32-bit product instead of the 64-bit one): the same quotient
 * and remainder. */
static inline __attribute__((always_inline)) uint32_t udiv_pre_small(uint64_t n, const struct num_udiv_pre *p,
                                                                     uint32_t *rem)
{
    const uint32_t s = p->s, d = p->d, hi = (uint32_t)(n >> 32), lo = (uint32_t)n;
    const uint32_t nh = hi << s | lo >> (32 - s);
    uint32_t q = nh + num_mulhi32(nh, p->v), r = lo - q * d;
    while (r >= d) {
        r -= d;
        q++;
    }
    *rem = r;
    return q;
}

/* wnum_div(a, z) for z > 0 by the prepared z: its path for a numerator
 * |a| 2^F below 2^63 and a quotient that does not saturate (the same
 * rounding, halves away from zero), wnum_div itself otherwise. Inline:
 * the prepared divisor stays in registers. */
static inline __attribute__((always_inline)) num wdiv_pre(wnum a, num z, const struct num_udiv_pre *p)
{
    const uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    if (ua < ((uint64_t)1 << (63 - NUM_FRAC))) {
        const uint64_t n = ua << NUM_FRAC;
        if ((n >> 32) < p->d) {
            uint32_t rm;
            const uint32_t q = p->s >= 2 ? udiv_pre_small(n, p, &rm) : num_udiv64_32_pre(n, p, &rm);
            if (q < (uint32_t)INT32_MAX || (q == (uint32_t)INT32_MAX && rm < p->d - rm)) {
                const num r = (num)q + (rm >= p->d - rm);
                return a < 0 ? -r : r;
            }
        }
    }
    return wnum_div(a, wnum_from_num(z));
}

/* wdiv_pre(wnum_from_num(NUM_ONE), z, p): 1/z, the numerator 2^2F a power
 * of two. With k = 2F + s in [32, 62], N = 2^2F 2^s has the high word
 * nh = 2^(k - 32) < dn and the low word 0, so num_udiv64_32_pre's estimate
 * nh + mulhi(nh, v) is nh + v >> (64 - k), and its remainder's low word
 * starts from 0 (the same quotient and remainder, the same rounding);
 * wnum_div itself otherwise. */
static num recip_pre(num z, const struct num_udiv_pre *p)
{
    const uint32_t s = p->s, dn = p->dn, k = 2 * NUM_FRAC + s;
    if (k < 32 || k > 62) return wnum_div(wnum_from_num(NUM_ONE), wnum_from_num(z));
    const uint32_t j = k - 32, nh = (uint32_t)1 << j;
    uint32_t q = nh + (j ? p->v >> (32 - j) : 0), rm;
    if (s >= 2) {
        /* the remainder 2^2F - q d below 4 d < 2^32 (udiv_pre_small) */
        const uint32_t d = p->d;
        rm = (uint32_t)((uint64_t)1 << (2 * NUM_FRAC)) - q * d;
        while (rm >= d) {
            rm -= d;
            q++;
        }
    } else {
        uint32_t rl;
        q = num_udiv_step(q, nh, 0, dn, &rl);
        rm = rl >> s;
    }
    if (q < (uint32_t)INT32_MAX || (q == (uint32_t)INT32_MAX && rm < p->d - rm)) return (num)q + (rm >= p->d - rm);
    return wnum_div(wnum_from_num(NUM_ONE), wnum_from_num(z));
}

void ras_div_depth(num x, num y, num z, num unproj, num near_z, num *X, num *Y, num *iz, uint32_t *depth)
{
    if (z <= 0) {
        div_depth_plain(x, y, z, unproj, near_z, X, Y, iz, depth);
        return;
    }
    const struct num_udiv_pre p = num_udiv_pre_make((uint32_t)z);
    *X = wdiv_pre(num_mul_round(x, unproj), z, &p);   /* num_mul_wide's bits, inline */
    *Y = wdiv_pre(num_mul_round(y, unproj), z, &p);
    *iz = recip_pre(z, &p);   /* num_div(1, z): wnum_div's rounding of 2^F 2^F / z */
    /* 0 < near < z: the quotient fits 32 bits */
    uint32_t rd;
    *depth = near_z <= 0 || z <= near_z ? ras_depth32(near_z, z)
             : p.s >= 2                 ? udiv_pre_small((uint64_t)(uint32_t)near_z << 32, &p, &rd)
                                        : num_udiv64_32_pre((uint64_t)(uint32_t)near_z << 32, &p, 0);
}

/* The fast path of ras_div_sub: a divisor d = z in (0, 2^28) (shift s =
 * clz(d) >= 4) and its reciprocal's estimate v = num_rcp32_est(d 2^s),
 * at most 6 below num_udiv_pre's. Each quotient's estimate nh +
 * mulhi(nh, v) is then never above udiv_pre_small's and at most 6 below
 * it (nh < 2^32), so at most 9 below the quotient: the remainder stays
 * below 10 d < 2^32, its low word, and the same steps take the quotient
 * to its exact value. */
struct div_est { uint32_t d, s, v; };

/* wdiv_pre(num_mul_round(x, u), z, p): 1 and *out where it comes from
 * udiv_pre_small without saturating, else 0. With P = x u + 2^(F-1)
 * (|P| < 2^63), num_mul_round is A = floor(P / 2^F), and wdiv_pre's
 * numerator |A| 2^F (always below 2^63) is P with its low F bits cleared,
 * negated when negative: its words straight from the product's. */
static inline __attribute__((always_inline)) int quot_est(num x, num u, const struct div_est *e, num *out)
{
    const uint64_t P = (uint64_t)num_smul32(x, u) + ((uint64_t)1 << (NUM_FRAC - 1));
    const uint32_t d = e->d, s = e->s;
    uint32_t hi = (uint32_t)(P >> 32), lo = (uint32_t)P >> NUM_FRAC << NUM_FRAC;
    const uint32_t neg = hi >> 31;
    if (neg) {
        hi = ~hi + (lo == 0);
        lo = 0u - lo;
    }
    if (hi >= d) return 0;
    const uint32_t nh = hi << s | lo >> (32 - s);
    uint32_t q = nh + num_mulhi32(nh, e->v), r = lo - q * d;
    while (r >= d) {
        r -= d;
        q++;
    }
    if (q >= (uint32_t)INT32_MAX) return 0;
    q += r >= d - r;
    *out = neg ? -(num)q : (num)q;
    return 1;
}

void ras_div_sub(const struct ras_subproj *k, num x, num y, num z, struct ras_subpos *o)
{
    num X, Y;
    /* 2F + s in [32, 62] for recip_pre's form of 1/z */
    if (z > 0 && z < ((num)1 << 28)) {
        struct div_est e;
        e.d = (uint32_t)z;
        e.s = (uint32_t)num_clz32(e.d);
        if (2 * NUM_FRAC + e.s >= 32 && 2 * NUM_FRAC + e.s <= 62) {
            e.v = num_rcp32_est(e.d << e.s);
            if (quot_est(x, k->unproj, &e, &X) && quot_est(y, k->unproj, &e, &Y)) {
                /* recip_pre: 2^2F / z, nh = 2^j, the estimate's product a shift */
                const uint32_t d = e.d, j = 2 * NUM_FRAC + e.s - 32;
                uint32_t q = ((uint32_t)1 << j) + (j ? e.v >> (32 - j) : 0);
                uint32_t r = (uint32_t)((uint64_t)1 << (2 * NUM_FRAC)) - q * d;
                while (r >= d) {
                    r -= d;
                    q++;
                }
                if (q < (uint32_t)INT32_MAX) {
                    o->iz = (num)(q + (r >= d - r));
                    const num near_z = k->near_z;
                    if (near_z > 0 && z > near_z) {
                        /* near 2^32 / z, below 2^32: nh = near 2^s, the low word 0 */
                        const uint32_t nh = (uint32_t)near_z << e.s;
                        q = nh + num_mulhi32(nh, e.v);
                        r = 0u - q * d;
                        while (r >= d) {
                            r -= d;
                            q++;
                        }
                        o->depth = q;
                    } else {
                        o->depth = ras_depth32(near_z, z);
                    }
                    o->sx = ras_sub_pos(num_add(k->cx, X), (int)k->sb);
                    o->sy = ras_sub_pos(num_sub(k->cy, Y), (int)k->sb);
                    return;
                }
            }
        }
    }
    div_depth_plain(x, y, z, k->unproj, k->near_z, &X, &Y, &o->iz, &o->depth);
    o->sx = ras_sub_pos(num_add(k->cx, X), (int)k->sb);
    o->sy = ras_sub_pos(num_sub(k->cy, Y), (int)k->sb);
}

#if defined(__ARM_ARCH_6M__) && defined(__GNUC__) && !defined(__clang__) && NUM_FRAC >= 16 && NUM_FRAC <= 20
#define RAS_DIV_SUBS_V6M 1
/* ARMv6-M: ras_div_sub's fast path for a run of points by hand, its
 * operations in 32-bit registers, the same bits: z in [2^(2F-31), 2^28)
 * (clz s in [4, 62 - 2F]); s and dn = z 2^s by the byte table, v =
 * num_rcp32_est(dn) inline (num_rcp16's seed and step, then its
 * estimate); each of X, Y: P = x u + 2^(F-1) (num_smul32's pieces, the
 * half added to a middle product, or to al bl at F = 16), its low F bits
 * cleared and |P| by the sign mask m, the quotient's estimate nh +
 * mulhi(nh, v) stepped up by the remainder, rounded, signed by m; the
 * screen position (cx + X + 2^(F-1-sb)) >> (F - sb), ras_sub_pos's value
 * (the sum's overflow flag: the C path); iz and depth as ras_div_sub. It
 * stops at a point the C path must take (z out of range, a quotient that
 * saturates, z <= near) and returns it. Frame (sp): 0 u (its high half for
 * div_subs_v6m_uh), 4 near_z, 8
 * cx + 2^(F-1-sb), 12 cy + 2^(F-1-sb), 16 F - sb, 20 num_clz8_tab, 24
 * num_rcp_seed, 28 the points' end, 32 the output. Registers: r3 z, r8
 * x then sx, r9 y then sy, r10 v, r11 the next point, r12 s, lr the sign
 * mask then iz. */
struct div_subs_frame {
    num u, near_z, cxc, cyc;
    int32_t fs;
    const uint8_t *clz;
    const uint16_t *seed;
    const vec3 *end;
};
#define DS_STR2(x) #x
#define DS_STR(x) DS_STR2(x)
#define DS_F DS_STR(NUM_FRAC)
/* a far branch to the C path (9) when the condition's opposite fails */
#define DS_FAIL_UNLESS(cc) "b" cc " 8f\n\t b 9f\n8:\n\t"
#if NUM_FRAC >= 17
#define DS_HALF "adds r4, #(1 << (" DS_F " - 17))\n\t"
#else
#define DS_HALF "movs r7, #1\n\t lsls r7, r7, #15\n\t adds r2, r2, r7\n\t"
#endif
/* r0:r2 = |P| with P's low F bits cleared, r6 the sign mask; r0 = x, r1 = u */
#define DS_NUM                                                                                 \
    "uxth r4, r0\n\t asrs r0, r0, #16\n\t uxth r6, r1\n\t asrs r1, r1, #16\n\t"              \
    "movs r2, r4\n\t muls r2, r6\n\t muls r4, r1\n\t muls r6, r0\n\t muls r0, r1\n\t" DS_HALF \
    "lsls r7, r4, #16\n\t asrs r4, r4, #16\n\t adds r2, r2, r7\n\t adcs r0, r4\n\t"          \
    "lsls r7, r6, #16\n\t asrs r6, r6, #16\n\t adds r2, r2, r7\n\t adcs r0, r6\n\t"          \
    "lsrs r2, r2, #" DS_F "\n\t lsls r2, r2, #" DS_F "\n\t"                                  \
    "asrs r6, r0, #31\n\t eors r2, r6\n\t eors r0, r6\n\t subs r2, r2, r6\n\t sbcs r0, r6\n\t"
/* DS_NUM for u = uh 2^16 (its low half 0; r1 = uh < 2^15): with x = xh
 * 2^16 + xl, P = xh uh 2^32 + (xl uh + 2^(F-17)) 2^16, t = xl uh +
 * 2^(F-17) < 2^31: hi = xh uh + (t >> 16), lo = t << 16 (at F = 16 the
 * half lies in the cleared bits) */
#if NUM_FRAC >= 17
#define DS_NUM_UH_LO "adds r2, #(1 << (" DS_F " - 17))\n\t lsrs r4, r2, #16\n\t adds r0, r0, r4\n\t" \
    "lsrs r2, r2, #(" DS_F " - 16)\n\t lsls r2, r2, #" DS_F "\n\t"
#else
#define DS_NUM_UH_LO "lsrs r4, r2, #16\n\t adds r0, r0, r4\n\t lsls r2, r2, #16\n\t"
#endif
#define DS_NUM_UH                                                                                   \
    "uxth r2, r0\n\t asrs r0, r0, #16\n\t muls r2, r1\n\t muls r0, r1\n\t" DS_NUM_UH_LO          \
    "asrs r6, r0, #31\n\t eors r2, r6\n\t eors r0, r6\n\t subs r2, r2, r6\n\t sbcs r0, r6\n\t"
/* r0 = nh = hi 2^s | lo >> (32 - s) */
#define DS_NH "mov r4, r12\n\t lsls r0, r4\n\t movs r1, #32\n\t subs r1, r1, r4\n\t movs r4, r2\n\t lsrs r4, r1\n\t orrs r0, r4\n\t"
/* r0 = nh + mulhi(nh, v) (r1, r4-r7 used) */
#define DS_QEST                                                                                \
    "mov r1, r10\n\t uxth r4, r0\n\t lsrs r5, r0, #16\n\t uxth r6, r1\n\t lsrs r1, r1, #16\n\t" \
    "movs r7, r4\n\t muls r7, r6\n\t muls r4, r1\n\t muls r6, r5\n\t muls r5, r1\n\t"          \
    "lsls r1, r4, #16\n\t lsrs r4, r4, #16\n\t adds r7, r7, r1\n\t adcs r5, r4\n\t"            \
    "lsls r1, r6, #16\n\t lsrs r6, r6, #16\n\t adds r7, r7, r1\n\t adcs r5, r6\n\t adds r0, r0, r5\n\t"
/* the quotient r0 stepped up while the remainder r2 >= d (r3) */
#define DS_STEP "cmp r2, r3\n\t blo 2f\n1:\n\t subs r2, r2, r3\n\t adds r0, #1\n\t cmp r2, r3\n\t bhs 1b\n2:\n\t"
/* q < INT32_MAX, then q + (r >= d - r) */
#define DS_ROUND                                                                     \
    "adds r1, r0, #1\n\t" DS_FAIL_UNLESS("cc") DS_FAIL_UNLESS("pl") "lsls r1, r2, #1\n\t" \
    "cmp r1, r3\n\t bcc 1f\n\t adds r0, #1\n1:\n\t"
/* X or Y of x or y in r0: r0 = ±q (the sign mask in lr) */
#define DS_QUOT(NUM)                                                                          \
    "ldr r1, [sp, #0]\n\t" NUM "cmp r0, r3\n\t" DS_FAIL_UNLESS("lo") "mov lr, r6\n\t" DS_NH   \
        DS_QEST "movs r1, r0\n\t muls r1, r3\n\t subs r2, r2, r1\n\t" DS_STEP DS_ROUND          \
    "mov r1, lr\n\t eors r0, r1\n\t subs r0, r0, r1\n\t"

/* the run's function NAME with the numerator form NUM (DS_NUM, DS_NUM_UH) */
#define DS_FUNC(NAME, NUM) \
static const vec3 *NAME(const struct div_subs_frame *f, const vec3 *c, struct ras_pv *out)                                       \
{                                                                                                                                \
    register const void *r0 __asm__("r0") = f;                                                                                   \
    register const vec3 *r1 __asm__("r1") = c;                                                                                   \
    register struct ras_pv *r2 __asm__("r2") = out;                                                                              \
    __asm__ volatile(                                                                                                            \
        ".syntax unified\n\t"                                                                                                    \
        "mov r11, r1\n\t push {r2}\n\t ldm r0, {r0-r7}\n\t push {r0-r7}\n"                                                       \
        "0:\n\t mov r0, r11\n\t ldm r0!, {r1, r2, r3}\n\t mov r11, r0\n\t"                                                       \
        "lsrs r4, r3, #28\n\t" DS_FAIL_UNLESS("eq") "lsrs r4, r3, #(2 * " DS_F " - 31)\n\t" DS_FAIL_UNLESS("ne")                 \
        "mov r8, r1\n\t mov r9, r2\n\t"                                                                                          \
        /* s = clz(z), r4 = dn */                                                                                                \
        "movs r4, r3\n\t movs r5, #0\n\t lsrs r6, r4, #16\n\t bne 1f\n\t lsls r4, r4, #16\n\t movs r5, #16\n"                    \
        "1:\n\t lsrs r6, r4, #24\n\t bne 1f\n\t lsls r4, r4, #8\n\t adds r5, #8\n\t lsrs r6, r4, #24\n"                          \
        "1:\n\t ldr r7, [sp, #20]\n\t ldrb r6, [r7, r6]\n\t adds r5, r5, r6\n\t lsls r4, r4, r6\n\t mov r12, r5\n\t"             \
        /* num_rcp16(dn) */                                                                                                      \
        "lsls r6, r4, #1\n\t lsrs r6, r6, #24\n\t lsls r6, r6, #1\n\t ldr r7, [sp, #24]\n\t ldrh r6, [r7, r6]\n\t"               \
        "lsrs r0, r4, #9\n\t lsls r7, r0, #16\n\t muls r0, r6\n\t adds r0, r0, r7\n\t negs r0, r0\n\t"                           \
        "asrs r7, r0, #16\n\t muls r7, r6\n\t asrs r7, r7, #8\n\t asrs r0, r0, #8\n\t adds r0, r0, r7\n\t"                       \
        "lsls r6, r6, #5\n\t subs r6, #1\n\t lsls r6, r6, #10\n\t adds r0, r0, r6\n\t"                                           \
        "asrs r0, r0, #15\n\t bpl 1f\n\t movs r0, #0\n1:\n\t"                                                                    \
        /* num_rcp32_est(dn) */                                                                                                  \
        "lsrs r6, r4, #16\n\t muls r6, r0\n\t negs r7, r4\n\t subs r7, r7, r6\n\t"                                               \
        "uxth r6, r4\n\t muls r6, r0\n\t adds r6, #1\n\t lsrs r6, r6, #1\n\t"                                                    \
        "lsls r7, r7, #15\n\t subs r7, r7, r6\n\t"                                                                               \
        "uxth r6, r7\n\t muls r6, r0\n\t lsrs r6, r6, #16\n\t"                                                                   \
        "lsrs r1, r7, #16\n\t muls r1, r0\n\t adds r6, r6, r1\n\t lsrs r6, r6, #15\n\t"                                          \
        "lsrs r7, r7, #15\n\t adds r6, r6, r7\n\t lsls r0, r0, #16\n\t adds r0, r0, r6\n\t mov r10, r0\n\t"                      \
        /* sx */                                                                                                                 \
        "mov r0, r8\n\t" DS_QUOT(NUM)                                                                                            \
        "ldr r1, [sp, #8]\n\t adds r0, r0, r1\n\t" DS_FAIL_UNLESS("vc") "ldr r1, [sp, #16]\n\t asrs r0, r1\n\t mov r8, r0\n\t"   \
        /* sy */                                                                                                                 \
        "mov r0, r9\n\t" DS_QUOT(NUM)                                                                                            \
        "ldr r1, [sp, #12]\n\t subs r0, r1, r0\n\t" DS_FAIL_UNLESS("vc") "ldr r1, [sp, #16]\n\t asrs r0, r1\n\t mov r9, r0\n\t"  \
        /* iz: 2^2F / z, nh = 2^j (j = 2F + s - 32) */                                                                           \
        "mov r5, r12\n\t adds r5, #(2 * " DS_F " - 32)\n\t mov r1, r10\n\t movs r4, #32\n\t subs r4, r4, r5\n\t lsrs r1, r4\n\t" \
        "movs r0, #1\n\t lsls r0, r5\n\t adds r0, r0, r1\n\t movs r2, r0\n\t muls r2, r3\n\t negs r2, r2\n\t"                    \
        DS_STEP DS_ROUND "mov lr, r0\n\t"                                                                                        \
        /* depth: near 2^32 / z for 0 < near < z */                                                                              \
        "ldr r0, [sp, #4]\n\t cmp r3, r0\n\t" DS_FAIL_UNLESS("gt") "mov r5, r12\n\t lsls r0, r5\n\t"                             \
        DS_QEST "movs r2, r0\n\t muls r2, r3\n\t negs r2, r2\n\t" DS_STEP                                                        \
        /* store_pv's ranges: sx in (INT16_MIN, INT16_MAX], sy an int16_t */                                                     \
        "mov r1, r8\n\t mov r2, r9\n\t"                                                                                          \
        "sxth r4, r1\n\t cmp r4, r1\n\t bne 6f\n\t lsls r4, r1, #16\n\t negs r4, r4\n\t bvs 6f\n\t"                              \
        "sxth r4, r2\n\t cmp r4, r2\n\t bne 6f\n\t"                                                                              \
        "uxth r1, r1\n\t lsls r2, r2, #16\n\t orrs r1, r2\n\t mov r2, lr\n\t movs r3, r0\n\t"                                    \
        "ldr r0, [sp, #32]\n\t stm r0!, {r1, r2, r3}\n\t str r0, [sp, #32]\n"                                                    \
        "5:\n\t mov r0, r11\n\t ldr r1, [sp, #28]\n\t cmp r0, r1\n\t beq 7f\n\t b 0b\n"                                          \
        "6:\n\t ldr r0, [sp, #32]\n\t movs r1, #1\n\t lsls r1, r1, #15\n\t strh r1, [r0]\n\t adds r0, #12\n\t"                   \
        "str r0, [sp, #32]\n\t b 5b\n"                                                                                           \
        "9:\n\t mov r0, r11\n\t subs r0, #12\n"                                                                                  \
        "7:\n\t add sp, #36\n\t"                                                                                                 \
        ".syntax divided\n"                                                                                                      \
        : "+l"(r0), "+l"(r1), "+l"(r2)                                                                                           \
        :                                                                                                                        \
        : "r3", "r4", "r5", "r6", "r7", "r8", "r9", "r10", "r11", "r12", "lr", "cc", "memory");                                  \
    return (const vec3 *)r0;                                                                                                     \
}
DS_FUNC(div_subs_v6m, DS_NUM)
DS_FUNC(div_subs_v6m_uh, DS_NUM_UH)
#else
#define RAS_DIV_SUBS_V6M 0
#endif

/* Corners a, b, c inside every plane, at depths z >= near: the
 * camera-space test's value f = -a . ((b - a) x (c - a)) is, exactly,
 * D = A_e z_a z_b z_c / (S^2 u^2), A_e the exact projection's doubled area
 * on screen (S = 2^sub_bits sub-pixel units a pixel, u = unproj), so
 * D > 0 when A_e > 0. Its computed form rounds each of the normal's six
 * products to within ulp/2 = 2^-F/2 (each component within ulp) and each
 * of the three products with a to within ulp/2, with no saturation while
 * the coordinates stay small (iz_min, below), so
 * |f - D| <= ulp (|a.x| + |a.y| + z_a + 3/2); with |a.x| + |a.y| <= z_a
 * (W + H + 16) / (2u) (the side planes, two pixels out, and their
 * roundings) the screen area that error stands for, |f - D| S^2 u^2 /
 * (z_a z_b z_c), is at most
 *   S^2 ulp (u^2 + u (W + H + 16) / 2) / (z_b z_c) + 3/2 S^2 ulp u^2 / (z_a z_b z_c)
 *   <= (g1 + g2 (iz_a + 1) 2^-F) (iz_b + 1)(iz_c + 1) 2^-2F
 * (iz in num's bits, within 1 of 2^2F / z). The snapped corners lie within
 * e = 1/2 + h of the exact projection (ras_project_sub: its rounding to
 * the sub-pixel grid and h = S ulp (1/(2 near) + 1), the quotient's), which
 * moves the area by at most 2 e L + 8 e^2 (each difference moves by 2e):
 * with 2h <= 2^-ks, ks >= 3, that is below L + (L >> ks) + 1 + 3. So A >
 * L + (L >> ks) + 4 + that bound gives A_e > the error's area, D > |f - D|
 * and f > 0. */
void ras_front_init(struct ras_front *fb, num unproj, num near_z, int32_t w, int32_t h, int sub_bits)
{
    const int F = NUM_FRAC;
    fb->g1 = fb->g2 = 0;
    fb->iz_min = NUM_MAX;
    fb->ks = 0;
    if (F < 8 || unproj <= 0 || near_z <= 0 || sub_bits < 1 || sub_bits > 8) return;
    const uint64_t S = (uint64_t)1 << sub_bits, nr = (uint64_t)near_z, half = (uint64_t)1 << (F - 1);
    const uint64_t u = (uint64_t)(unproj >> F) + 1, wh = (uint64_t)w + (uint64_t)h + 16;
    /* 2h = 2 S (2^(F-1) / near + 1) 2^-F <= 2^-ks, in num's bits */
    const uint64_t hq = 2 * S * ((half + nr - 1) / nr + 1);
    int ks = 0;
    while (ks < 16 && (hq << (ks + 1)) <= ((uint64_t)1 << F)) ks++;
    if (u > (1u << 16) || ks < 3) return;
    const uint64_t g1 = ((S * S * (u * u + (u * wh + 1) / 2)) >> F) + 1;
    const uint64_t g2 = ((3 * S * S * u * u) >> (F + 1)) + 1;
    if (g1 >= ((uint64_t)1 << 30) || g2 >= ((uint64_t)1 << 30)) return;
    /* coordinates below c = min(NUM_MAX / 4, 2^((55 + 2F) / 3)) in num's
     * bits: their differences do not saturate, nor do the test's wide
     * products (3 c (2 (2c)^2 2^-F) 2^-F < 2^60). |x|, |y|, z <= z (1 +
     * (W + H + 16) / (2u)) < c for z < z_lim, so 1/z above 2^2F / z_lim */
    const uint64_t ud = (uint64_t)(unproj >> F);
    const int cb = (55 + 2 * F) / 3;
    const uint64_t c = cb >= 29 ? (uint64_t)NUM_MAX / 4 : (uint64_t)1 << cb;
    const uint64_t zlim = c * 2 * ud / (2 * ud + wh);
    if (ud == 0 || zlim == 0) return;
    const uint64_t izl = (((uint64_t)1 << (2 * F)) / zlim) + 2;
    if (izl > (uint64_t)NUM_MAX) return;
    fb->iz_min = (num)izl;
    fb->ks = ks;
    fb->g1 = (uint32_t)g1;
    fb->g2 = (uint32_t)g2;
}

uint64_t ras_front_bound(const struct ras_front *fb, num iza, num izb, num izc)
{
    if (fb->g1 == 0 || iza < fb->iz_min || izb < fb->iz_min || izc < fb->iz_min) return 0;
    /* g = g1 + floor(g2 (iz_a + 1) 2^-F) + 1 (below 2^31 + 1 where the
     * quotient is below 2^30),
     * then g (iz_b + 1)(iz_c + 1) 2^-2F, rounded up (F = NUM_FRAC: shifts
     * by a constant, and the product's high word tested first) */
    const uint64_t q = num_umul32(fb->g2, (uint32_t)iza + 1u) >> NUM_FRAC;
    if (q >> 30) return 0;
    const uint32_t g = fb->g1 + (uint32_t)q + 1u;
    const uint64_t pp = num_umul32((uint32_t)izb + 1u, (uint32_t)izc + 1u);
    if ((uint32_t)(pp >> 32) >> (NUM_FRAC - 1)) return 0; /* p >= 2^31 */
    const uint32_t p = (uint32_t)(pp >> NUM_FRAC) + 1u;
    if (p >> 31) return 0;
    return (num_umul32(p, g) >> NUM_FRAC) + 1;
}

int ras_front_known(const struct ras_front *fb, int64_t margin, num iza, num izb, num izc)
{
    if (margin <= 0) return 0;
    const uint64_t bound = ras_front_bound(fb, iza, izb, izc);
    return bound != 0 && (uint64_t)margin > bound;
}

int32_t ras_num_to_fix(num a, int32_t scale)
{
    /* a * scale in Q.NUM_FRAC, exact in 64 bits */
    return ras_fix_round((int64_t)a * scale);
}

#else

#if NUM_MODE == NUM_MODE_FLOAT
num ras_count_next(num a, num a0, int32_t k) { (void)a; return a0 + (num)k; }
int32_t ras_count_index(num a, num a0, int32_t k) { (void)a; (void)a0; return k; }
#else
num ras_count_next(num a, num a0, int32_t k) { (void)a0; (void)k; return a + 1; }
int32_t ras_count_index(num a, num a0, int32_t k) { (void)k; return num_to_int(a - a0); }
#endif

#if NUM_MODE == NUM_MODE_FLOAT
void ras_interp_init(struct ras_interp *it, num i0, num d0, num i1, num d1)
{
    it->d0 = d0;
    it->delta = d1 - d0;
    it->n = i1 - i0;
    it->k = 0;
}

num ras_interp_value(const struct ras_interp *it)
{
    if (it->n == 0 || it->k == 0) return it->d0;
    return it->d0 + ((num)it->k * it->delta) / it->n;
}

void ras_interp_next(struct ras_interp *it) { it->k++; }
#else
void ras_interp_init(struct ras_interp *it, num i0, num d0, num i1, num d1)
{
    it->d = d0;
    it->a = i1 == i0 ? 0 : (d1 - d0) / (i1 - i0);
}

num ras_interp_value(const struct ras_interp *it) { return it->d; }
void ras_interp_next(struct ras_interp *it) { it->d = it->d + it->a; }
#endif

num ras_ratio(int64_t p, int64_t q)
{
    if (q == 0) return p == 0 ? 0 : (p > 0 ? NUM_MAX : NUM_MIN);
    return (num)p / (num)q;
}

num ras_project(num x, num d, num z, num cw, num vw)
{
#if NUM_MODE == NUM_MODE_DOUBLE
    return num_div(num_mul(num_div(num_mul(x, d), z), cw), vw);
#else
    return num_div(x * d * cw, z * vw);
#endif
}

vec3 ras_mul_point(const mat4 *m, vec3 p) { return m4_mul_point(m, p); }

void ras_box_of(struct ras_box *b, const vec3 *v, uint32_t n)
{
    (void)v;
    (void)n;
    b->ok = 0;
    b->sphere = 0;
}

int ras_box_transform(const mat4 *m, const struct ras_box *b, struct ras_box *out)
{
    (void)m;
    (void)b;
    out->ok = 0;
    return 0;
}

vec3 ras_mul_point_fit(const mat4 *m, vec3 p) { return m4_mul_point(m, p); }

int ras_fit_split(const mat4 *m, const struct ras_box *b)
{
    (void)m;
    (void)b;
    return 0;
}

vec3 ras_mul_point_fit_split(const mat4 *m, vec3 p, int s)
{
    (void)s;
    return m4_mul_point(m, p);
}

vec3 ras_mul_normal_split(const mat4 *m, vec3 n, int s)
{
    (void)s;
    return m4_mul_point(m, n);
}

void ras_mul_points_fit_split(const mat4 *m, const vec3 *p, vec3 *out, uint32_t n, int s)
{
    (void)s;
    for (uint32_t k = 0; k < n; k++) out[k] = m4_mul_point(m, p[k]);
}

int ras_sphere_inside(const mat4 *m, const struct ras_box *b, const struct ras_box *cb, num near_z, num side_x,
                      num side_y)
{
    (void)m;
    (void)b;
    (void)cb;
    (void)near_z;
    (void)side_x;
    (void)side_y;
    return 0;
}

void ras_div_depth(num x, num y, num z, num unproj, num near_z, num *X, num *Y, num *iz, uint32_t *depth)
{
    div_depth_plain(x, y, z, unproj, near_z, X, Y, iz, depth);
}

void ras_div_sub(const struct ras_subproj *k, num x, num y, num z, struct ras_subpos *o)
{
    num X, Y;
    div_depth_plain(x, y, z, k->unproj, k->near_z, &X, &Y, &o->iz, &o->depth);
    o->sx = ras_sub_pos(num_add(k->cx, X), (int)k->sb);
    o->sy = ras_sub_pos(num_sub(k->cy, Y), (int)k->sb);
}

uint32_t ras_depth32(num near_z, num z)
{
    if (!(z > near_z)) return UINT32_MAX;
    num r = near_z / z;
    if (!(r > 0)) return 0;
#if NUM_MODE == NUM_MODE_FLOAT
    /* floor(r * (2^32 - 1)) = floor(X - r) with X = r * 2^32 (exact), in
     * single precision only (no double routines on an FPv4-SP FPU) */
    num X = r * 4294967296.0f;
    if (X >= 4294967296.0f) return UINT32_MAX;
    uint32_t xi = (uint32_t)X;
    if (X - (num)xi < r && xi) xi--;
    return xi;
#else
    double v = r * 4294967295.0;
    if (v >= 4294967295.0) return UINT32_MAX;
    return (uint32_t)v;
#endif
}

void ras_front_init(struct ras_front *fb, num unproj, num near_z, int32_t w, int32_t h, int sub_bits)
{
    (void)unproj; (void)near_z; (void)w; (void)h; (void)sub_bits;
    fb->g1 = fb->g2 = 0;
    fb->iz_min = 0;
    fb->ks = 0;
}

uint64_t ras_front_bound(const struct ras_front *fb, num iza, num izb, num izc)
{
    (void)fb; (void)iza; (void)izb; (void)izc;
    return 0;
}

int ras_front_known(const struct ras_front *fb, int64_t margin, num iza, num izb, num izc)
{
    (void)fb; (void)margin; (void)iza; (void)izb; (void)izc;
    return 0;
}

int32_t ras_num_to_fix(num a, int32_t scale)
{
    /* in the mode's own type (no double routines in the float build) */
    num p = a * (num)scale;
    if (!(p < (num)2147483520.0)) return p != p ? 0 : INT32_MAX;
    if (!(p > (num)-2147483520.0)) return -INT32_MAX;
    return (int32_t)(p >= 0 ? p + (num)0.5 : p - (num)0.5);
}

#endif

#ifndef RAS_DIV_SUBS_V6M
#define RAS_DIV_SUBS_V6M 0
#endif

void ras_div_subs(const struct ras_subproj *k, const vec3 *c, struct ras_pv *out, uint32_t n)
{
    uint32_t j = 0;
#if RAS_DIV_SUBS_V6M
    /* the hand-written runs where cx + X and cy - Y move by 2^(F-1-sb)
     * (sb < F) without overflow and near_z > 0; the C path for the points
     * it stops at */
    const int32_t sb = k->sb;
    if (n && k->near_z > 0 && sb >= 1 && sb < NUM_FRAC && k->cx >= 0 && k->cy >= 0) {
        const num h = (num)1 << (NUM_FRAC - 1 - sb);
        if (k->cx <= NUM_MAX - h && k->cy <= NUM_MAX - h) {
            /* unproj = uh 2^16 (u > 0, its low half 0: a whole number at F >= 16):
             * P from two products */
            const int uh = k->unproj > 0 && !(k->unproj & 0xFFFF);
            const struct div_subs_frame f = { uh ? k->unproj >> 16 : k->unproj, k->near_z, k->cx + h, k->cy + h,
                                              NUM_FRAC - sb, num_clz8_tab, num_rcp_seed, c + n };
            while (j < n) {
                j = (uint32_t)((uh ? div_subs_v6m_uh(&f, c + j, out + j) : div_subs_v6m(&f, c + j, out + j)) - c);
                if (j < n) {
                    ras_div_sub_pv(k, &out[j], c[j]);
                    j++;
                }
            }
        }
    }
#endif
    for (; j < n; j++) ras_div_sub_pv(k, &out[j], c[j]);
}
