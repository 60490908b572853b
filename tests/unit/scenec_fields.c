/* SPDX-License-Identifier: MIT */
/* scenec_fields — the C data scenec emits equals the parsed scene, field by
 * field: each generated scene (compiled for the host in fixed point at the
 * NUM_FRAC scenec chose) against scene_load() of its file in the same build.
 * Numbers are compared as raw fixed-point values, strings and texels as
 * bytes, every array element by element. Built and run by
 * tests/system/test_scenec.sh with a generated table of (file, scene) pairs:
 *   scenec_fields    (no arguments; prints PASS/FAIL per scene) */
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "scene_parse.h"

struct scenec_entry {
    const char *path, *id;
    const struct scene *data;
};
extern const struct scenec_entry scenec_table[];

static char where[256];
static int bad;

static void fail(const char *field)
{
    if (!bad) snprintf(where, sizeof where, "%s", field);
    bad++;
}

#define EQ(a, b, field) do { if ((a) != (b)) fail(field); } while (0)

static void eq_vec3(vec3 a, vec3 b, const char *f) { EQ(a.x, b.x, f); EQ(a.y, b.y, f); EQ(a.z, b.z, f); }
static void eq_rgb(rgb a, rgb b, const char *f) { EQ(a.r, b.r, f); EQ(a.g, b.g, f); EQ(a.b, b.b, f); }
static void eq_mat3(const mat3 *a, const mat3 *b, const char *f)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) EQ(a->m[i][j], b->m[i][j], f);
}
static void eq_anim(const struct scene_anim *a, const struct scene_anim *b, const char *f)
{
    EQ(a->rot_y_per_frame, b->rot_y_per_frame, f);
    eq_vec3(a->move_per_frame, b->move_per_frame, f);
}
static void eq_str(const char *a, const char *b, const char *f)
{
    if (!a || !b || strcmp(a, b)) fail(f);
}

static void compare(const struct scene *a, const struct scene *b)
{
    eq_str(a->name, b->name, "name");
    EQ(a->kind, b->kind, "kind");
    EQ(a->canvas_w, b->canvas_w, "canvas_w");
    EQ(a->canvas_h, b->canvas_h, "canvas_h");
    EQ(a->viewport_w, b->viewport_w, "viewport_w");
    EQ(a->viewport_h, b->viewport_h, "viewport_h");
    EQ(a->projection_d, b->projection_d, "projection_d");
    eq_rgb(a->background, b->background, "background");
    EQ(a->background_set, b->background_set, "background_set");
    eq_vec3(a->camera.position, b->camera.position, "camera.position");
    eq_mat3(&a->camera.rotation, &b->camera.rotation, "camera.rotation");
    eq_anim(&a->camera_anim, &b->camera_anim, "camera_anim");
    EQ(a->frames, b->frames, "frames");

    EQ(a->nlights, b->nlights, "nlights");
    for (int i = 0; i < a->nlights && i < b->nlights; i++) {
        EQ(a->lights[i].type, b->lights[i].type, "lights[].type");
        EQ(a->lights[i].intensity, b->lights[i].intensity, "lights[].intensity");
        eq_vec3(a->lights[i].v, b->lights[i].v, "lights[].v");
    }

    EQ(a->nobjects, b->nobjects, "nobjects");
    for (int i = 0; i < a->nobjects && i < b->nobjects; i++) {
        const struct rt_object *x = &a->objects[i], *y = &b->objects[i];
        EQ(x->shape, y->shape, "objects[].shape");
        EQ(x->csg_only, y->csg_only, "objects[].csg_only");
        eq_rgb(x->mat.color, y->mat.color, "objects[].mat.color");
        EQ(x->mat.specular, y->mat.specular, "objects[].mat.specular");
        EQ(x->mat.reflective, y->mat.reflective, "objects[].mat.reflective");
        EQ(x->mat.transparency, y->mat.transparency, "objects[].mat.transparency");
        EQ(x->mat.refraction, y->mat.refraction, "objects[].mat.refraction");
        eq_vec3(x->center, y->center, "objects[].center");
        EQ(x->radius, y->radius, "objects[].radius");
        eq_vec3(x->normal, y->normal, "objects[].normal");
        EQ(x->dist, y->dist, "objects[].dist");
        for (int k = 0; k < 3; k++) eq_vec3(x->p[k], y->p[k], "objects[].p");
    }
    EQ(a->ncsg, b->ncsg, "ncsg");
    for (int i = 0; i < a->ncsg && i < b->ncsg; i++) {
        EQ(a->csg[i].op, b->csg[i].op, "csg[].op");
        EQ(a->csg[i].a, b->csg[i].a, "csg[].a");
        EQ(a->csg[i].b, b->csg[i].b, "csg[].b");
    }
    const struct rt_options *r = &a->rt, *q = &b->rt;
#define RT_OPTION(key, field, ...) EQ(r->field, q->field, "rt." #field);
#include "scene_options.def"

    EQ(a->nmodels, b->nmodels, "nmodels");
    for (int m = 0; m < a->nmodels && m < b->nmodels; m++) {
        const struct ras_model *x = &a->models[m], *y = &b->models[m];
        eq_str(x->name, y->name, "models[].name");
        EQ(x->nverts, y->nverts, "models[].nverts");
        EQ(x->ntris, y->ntris, "models[].ntris");
        EQ(x->has_normals, y->has_normals, "models[].has_normals");
        EQ(x->has_uvs, y->has_uvs, "models[].has_uvs");
        eq_vec3(x->bound_center, y->bound_center, "models[].bound_center");
        EQ(x->bound_radius, y->bound_radius, "models[].bound_radius");
        for (int k = 0; k < x->nverts && k < y->nverts; k++) eq_vec3(x->verts[k], y->verts[k], "models[].verts");
        for (int k = 0; k < x->ntris && k < y->ntris; k++) {
            const struct ras_triangle *s = &x->tris[k], *t = &y->tris[k];
            for (int c = 0; c < 3; c++) EQ(s->v[c], t->v[c], "models[].tris[].v");
            eq_rgb(s->color, t->color, "models[].tris[].color");
            if (x->has_normals)
                for (int c = 0; c < 3; c++) eq_vec3(s->n[c], t->n[c], "models[].tris[].n");
            if (x->has_uvs)
                for (int c = 0; c < 3; c++) {
                    EQ(s->uv[c].u, t->uv[c].u, "models[].tris[].uv");
                    EQ(s->uv[c].v, t->uv[c].v, "models[].tris[].uv");
                }
        }
    }
    EQ(a->ntextures, b->ntextures, "ntextures");
    for (int i = 0; i < a->ntextures && i < b->ntextures; i++) {
        const struct ras_texture *x = &a->textures[i], *y = &b->textures[i];
        EQ(x->w, y->w, "textures[].w");
        EQ(x->h, y->h, "textures[].h");
        EQ(x->filter, y->filter, "textures[].filter");
        EQ(x->mip_levels, y->mip_levels, "textures[].mip_levels");
        if (x->w != y->w || x->h != y->h || x->mip_levels != y->mip_levels) continue;
        if (memcmp(x->rgb, y->rgb, (size_t)x->w * x->h * 3)) fail("textures[].rgb");
        size_t w = x->w, h = x->h;
        for (int l = 1; l < x->mip_levels; l++) {
            w = w > 1 ? w / 2 : 1;
            h = h > 1 ? h / 2 : 1;
            if (memcmp(x->mip[l], y->mip[l], w * h * 3)) fail("textures[].mip");
        }
    }
    EQ(a->ninstances, b->ninstances, "ninstances");
    for (int i = 0; i < a->ninstances && i < b->ninstances; i++) {
        const struct ras_instance *x = &a->instances[i], *y = &b->instances[i];
        EQ(x->model, y->model, "instances[].model");
        EQ(x->texture, y->texture, "instances[].texture");
        EQ(x->normal_map, y->normal_map, "instances[].normal_map");
        eq_vec3(x->position, y->position, "instances[].position");
        eq_mat3(&x->rotation, &y->rotation, "instances[].rotation");
        EQ(x->scale, y->scale, "instances[].scale");
        EQ(x->specular, y->specular, "instances[].specular");
        eq_anim(&x->anim, &y->anim, "instances[].anim");
    }
    EQ(a->nprims, b->nprims, "nprims");
    for (int i = 0; i < a->nprims && i < b->nprims; i++) {
        const struct prim2d *x = &a->prims[i], *y = &b->prims[i];
        EQ(x->kind, y->kind, "prims[].kind");
        EQ(x->npts, y->npts, "prims[].npts");
        for (int k = 0; k < 3; k++) {
            EQ(x->x[k], y->x[k], "prims[].x");
            EQ(x->y[k], y->y[k], "prims[].y");
            EQ(x->h[k], y->h[k], "prims[].h");
        }
        eq_rgb(x->color, y->color, "prims[].color");
    }
    EQ(a->nlines, b->nlines, "nlines");
    for (int i = 0; i < a->nlines && i < b->nlines; i++) {
        eq_vec3(a->lines[i].a, b->lines[i].a, "lines[].a");
        eq_vec3(a->lines[i].b, b->lines[i].b, "lines[].b");
        eq_rgb(a->lines[i].color, b->lines[i].color, "lines[].color");
    }
    const struct ras_options *o = &a->ras, *p = &b->ras;
#define RAS_OPTION(key, field, ...) EQ(o->field, p->field, "ras." #field);
#include "scene_options.def"
}

int main(void)
{
    for (const struct scenec_entry *e = scenec_table; e->path; e++) {
        char err[600], name[200];
        struct scene *s = NULL;
        snprintf(name, sizeof name, "scenec_fields_%s", e->id);
        if (scene_load(e->path, &s, err, sizeof err)) {
            check(0, name, "%s", err);
            continue;
        }
        bad = 0;
        where[0] = 0;
        compare(e->data, s);
        check(!bad, name, "%d fields differ, first %s", bad, where);
        scene_free(s);
    }
    return check_exit();
}
