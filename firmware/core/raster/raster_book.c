/* SPDX-License-Identifier: MIT */
/* raster_book.c — the book path's RenderTriangle (book_exact = 1,
 * docs/book-demos.md): the demos' pseudocode with their quirks, through
 * the book's scan conversion (raster_triangles.c), per-pixel depth in num,
 * flat, Gouraud and Phong shading, the demos' textures and raster-10's
 * outlines; wireframes for both paths. */
#include "raster_int.h"

struct book_tri {
    rgb color;
    num flat_i;
    num spec;
    int shading, textured, nq;
    const struct ras_texture *tex;
};

static void book_pixel(struct ras_ctx *rc, int32_t x, int32_t y, const num *q, void *ud)
{
    const struct book_tri *bt = ud;
    const struct scene *s = rc->s;
    int col = ras_canvas_col(rc, x), row = ras_canvas_row(rc, y);
    if (col < 0 || col >= (int)rc->w || row < (int)rc->cur.t->y0 || row >= (int)rc->cur.t->y1) return;
    num iz = q[0];
    if (rc->depth_bytes) {
        num *db = (num *)(void *)rc->depth;
        size_t di = (size_t)(row - rc->cur.t->y0) * rc->w + (size_t)col;
        if (!(db[di] == NUM_ZERO || db[di] < iz)) return;
        db[di] = iz;
    }
    num i = NUM_ONE;
    int k = 1;
    switch (bt->shading) {
    case SHADE_FLAT: i = bt->flat_i; break;
    case SHADE_GOURAUD: i = q[k++]; break;
    case SHADE_PHONG: {
        num oz = num_recip(iz);
        vec3 p = v3_make(ras_mul_div(num_from_int(x), oz, rc->unproj), ras_mul_div(num_from_int(y), oz, rc->unproj), oz);
        i = ras_compute_illumination(rc, p, v3_make(q[k], q[k + 1], q[k + 2]), bt->spec);
        k += 3;
        break;
    }
    default: break;
    }
    rgb c = bt->color;
    if (bt->textured) {
        num u = q[k], v = q[k + 1];
        if (s->ras.perspective_uv) { u = num_div(u, iz); v = num_div(v, iz); }
        int nan = 0;
        c = ras_texel_book(bt->tex, u, v, &nan);
        if (nan) { ras_put(rc, col, row, rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO)); return; }
    }
    if (bt->shading != SHADE_NONE) c = rgb_scale(c, i);
    ras_put(rc, col, row, c);
}

void ras_book_render_triangle(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                              const struct ras_model *m, const struct ras_triangle *t)
{
    const struct ras_options *o = &rc->s->ras;
    const struct ras_vert *cv[3] = { &rc->verts[ri->vbase + t->v[0]], &rc->verts[ri->vbase + t->v[1]],
                                     &rc->verts[ri->vbase + t->v[2]] };
    const struct ras_proj *pr = rc->proj + ri->vbase;
    num px[3] = { pr[t->v[0]].px, pr[t->v[1]].px, pr[t->v[2]].px }, py[3] = { pr[t->v[0]].py, pr[t->v[1]].py, pr[t->v[2]].py };
    if (o->wireframe) { ras_draw_wireframe_triangle(rc, px, py, t->color); return; }
    /* the face normal stays wide for the culling test; it is narrowed to
     * num only where it serves as the shading normal */
    struct ras_wnormal wf = ras_face_normal_wide(cv[0]->c, cv[1]->c, cv[2]->c);
    if (o->backface_cull && ras_facing_wide(cv[0]->c, wf) <= 0) return;
    int face_n = o->computed_normals || !m->has_normals;
    vec3 nf = face_n ? ras_wnormal_narrow(wf) : v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    int idx[3];
    ras_book_sort_corners(py, idx);
    num sx[3], sy[3], q[1 + RAS_MAX_ATTR][3];
    vec3 V[3], N[3];
    struct book_tri bt;
    bt.color = t->color;
    bt.spec = in->specular;
    bt.shading = o->shading;
    bt.textured = in->texture >= 0 && in->texture < rc->s->ntextures && m->has_uvs;
    bt.tex = bt.textured ? &rc->s->textures[in->texture] : NULL;
    bt.flat_i = NUM_ONE;
    for (int k = 0; k < 3; k++) {
        int c = idx[k];
        sx[k] = px[c];
        sy[k] = py[c];
        V[k] = cv[c]->c;
        N[k] = face_n ? nf : ras_corner_normal(ri, t->n[c]);
        q[0][k] = num_recip(V[k].z);
    }
    int nq = 1;
    if (o->shading == SHADE_FLAT) {
        vec3 centre = v3_make(num_div_int(num_add(num_add(V[0].x, V[1].x), V[2].x), 3),
                              num_div_int(num_add(num_add(V[0].y, V[1].y), V[2].y), 3),
                         num_div_int(num_add(num_add(V[0].z, V[1].z), V[2].z), 3));
        bt.flat_i = ras_compute_illumination(rc, centre, N[0], bt.spec);
    } else if (o->shading == SHADE_GOURAUD) {
        for (int k = 0; k < 3; k++) q[nq][k] = ras_compute_illumination(rc, V[k], N[k], bt.spec);
        nq++;
    } else if (o->shading == SHADE_PHONG) {
        for (int k = 0; k < 3; k++) { q[nq][k] = N[k].x; q[nq + 1][k] = N[k].y; q[nq + 2][k] = N[k].z; }
        nq += 3;
    }
    if (bt.textured) {
        for (int k = 0; k < 3; k++) {
            int c = idx[k];
            num u = t->uv[c].u, v = t->uv[c].v;
            if (o->perspective_uv) { u = num_div(u, V[k].z); v = num_div(v, V[k].z); }
            q[nq][k] = u;
            q[nq + 1][k] = v;
        }
        nq += 2;
    }
    ras_book_scan_triangle(rc, sx, sy, nq, (const num (*)[3])q, book_pixel, &bt);
    if (o->outlines) {
        /* raster-10's outlines: P0P1, P0P2, P2P1 of the sorted corners */
        rgb oc = rgb_scale(t->color, NUM_C(0.75));
        ras_draw_line(rc, sx[0], sy[0], sx[1], sy[1], oc);
        ras_draw_line(rc, sx[0], sy[0], sx[2], sy[2], oc);
        ras_draw_line(rc, sx[2], sy[2], sx[1], sy[1], oc);
    }
}
