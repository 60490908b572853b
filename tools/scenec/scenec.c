/* SPDX-License-Identifier: MIT */
/* scenec — compiles a scene file into C source for the firmware.
 *
 *   scenec [--size WxH] [--strip-rows N] [--fracs 20,...,12] [--id NAME]
 *          [--allow-wide] [--target-work BYTES[:SIBLING[:LAYOUT]]] [--deps OUT.d]
 *          [--target NAME] [--ram-budget N[K|M]] [--flash-budget N[K|M]] [--min-psnr DB]
 *          [--fast-textures ram|flash] -o OUT.c SCENE
 *
 * Writes OUT.c (the scene as const data: models, textures, lights in flash;
 * one static work buffer of exactly render_work_size() bytes) and OUT.h (its
 * declarations and the number format it was checked for). Prints the ranges
 * it found, the number format chosen and why no intermediate overflows, and
 * one "scenec-summary" line; or fails (exit 2) naming the object and the
 * quantity that cannot fit, or the RAM or flash the scene needs over the
 * target's budget (--target, default m0plus), before anything is written.
 *
 * scenec is built in the double mode: the values it emits are the parser's
 * doubles, written as NUM_C(literal), so the same file compiles to the exact
 * doubles in the double build and to the nearest fixed-point values in a
 * fixed build of any NUM_FRAC (NUM_C rounds exactly as num_from_double).
 * The work size is the target's: --target-work BYTES[:SIBLING], measured by
 * running render_work_size() (and render_sibling_work_size(), the second
 * core's context, SCENE_<ID>_SIBLING_WORK_SIZE) on the emulated Cortex-M0+
 * (tools/scenec/target_work.sh, as `make scenes` does). Without it scenec falls back to the fixed-point
 * core of this 64-bit host (core_api_fixed12), an upper bound: the work
 * structures hold pointers and sizes, 8 bytes here and 4 on the target, and
 * every other member has the same size and alignment on both.
 * The flash the scene's const data takes is counted at the target's sizes
 * of its types when --target-work carries them (LAYOUT, the work probe's
 * sizeof of each, tools/scenec/scene_layout.h; target_work.sh prints all
 * three fields), else at this host's fixed-point build's, an upper bound
 * (its pointers take 8 bytes).
 * --deps OUT.d writes a make rule: OUT.c and OUT.h depend on the scene and on
 * every file it made scenec read (images, model and material files), each of
 * those also a target of its own, so that a file that is gone later asks for
 * a new run instead of stopping make (as cc -MMD -MP).
 * --min-psnr DB (or the scene's quality block) chooses the scene's methods
 * first (tools/quality): the cheapest on --target (the block's target, else
 * m0plus) that renders within DB of the double build's exact render; the
 * choice is printed and compiled, so the board shows what host_sim shows
 * with the same target.
 * --fast-textures flash writes the texels the rasterizer's fast path samples
 * (mipmap.h: RGB565 for nearest textures, mip_fast_bilinear's words for
 * bilinear ones) as const data too, which render_init then uses instead of
 * making them in work memory: less RAM, more flash (default ram).
 * --spec-tables flash (the default) writes fast Phong's specular tables
 * (raster.h's raster_spec_table, one per exponent) as const data, made by
 * this program's fixed-point core of each NUM_FRAC the file may be compiled
 * at (12 up to the scene's), the same bits render_init makes on the target:
 * render_init of a fixed-point core then uses them instead of making them in
 * work memory (float and double cores still make theirs: OUT.h adds that
 * work for them).
 */
#define _XOPEN_SOURCE 700   /* realpath */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stddef.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "../common/file_id.h"
#include "core_api.h"
#include "mipmap.h"
#include "scene_format.h"
#include "scene_layout.h"
#include "scene_parse.h"
#include "suggest.h"
#include "tools/quality/quality.h"

/* the fixed-point core at NUM_FRAC 12 (mk/scene.mk): it loads every scene any
 * format can hold, and the work layout does not depend on NUM_FRAC */
extern const struct core_api core_api_fixed12;

/* ---- output helpers --------------------------------------------------- */

static FILE *out;

/* The outputs are written to temporary files next to them and renamed into
 * place only when both are complete (the .c last: it is what make waits
 * for), so an interrupted or failed run leaves the old files or none, never
 * a half-written one; a caught signal removes the temporaries. */
static char tmp_path[2][1100];
static volatile sig_atomic_t tmp_live[2];

static void on_signal(int sig)
{
    for (int i = 0; i < 2; i++)
        if (tmp_live[i]) unlink(tmp_path[i]);
    signal(sig, SIG_DFL);
    raise(sig);
}

static FILE *tmp_create(int i, const char *final)
{
    const char *slash = strrchr(final, '/');
    int dirlen = slash ? (int)(slash - final) + 1 : 0;
    if (snprintf(tmp_path[i], sizeof tmp_path[i], "%.*s.%s.XXXXXX", dirlen, final, slash ? slash + 1 : final) >=
        (int)sizeof tmp_path[i])
        return NULL;
    static int handlers;
    if (!handlers) {
        handlers = 1;
        const int sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU };
        for (size_t k = 0; k < sizeof sigs / sizeof sigs[0]; k++) signal(sigs[k], on_signal);
        signal(SIGPIPE, SIG_IGN);
        signal(SIGXFSZ, SIG_IGN);
    }
    int fd = mkstemp(tmp_path[i]);
    if (fd < 0) return NULL;
    tmp_live[i] = 1;
    mode_t mask = umask(0);
    umask(mask);
    (void)fchmod(fd, 0666 & ~mask);
    FILE *f = fdopen(fd, "w");
    if (!f) {
        close(fd);
        unlink(tmp_path[i]);
        tmp_live[i] = 0;
    }
    return f;
}

static void tmp_discard(void)
{
    for (int i = 0; i < 2; i++)
        if (tmp_live[i]) {
            unlink(tmp_path[i]);
            tmp_live[i] = 0;
        }
}
static size_t flash_bytes;      /* const data emitted, at layout's sizes */
/* The sizes the flash is counted at: the target's (--target-work's third
 * field, the work probe's) or this host's fixed-point build's, an upper
 * bound (tools/scenec/scene_layout.h); layout_of_target says which. */
static struct scene_layout layout;
static int layout_of_target;
#define LSIZE(name) layout.size[SCENE_LAYOUT_##name]
static size_t texture_bytes;    /* of which the textures' texels (every mip level) */
static const char *outh_path;   /* OUT.h (NULL in the dry run) */
static int fast_in_flash;       /* --fast-textures flash */
static int spec_in_flash = 1;   /* --spec-tables flash (the default) */
/* Fast Phong's specular tables per fixed-point format the scene may be
 * compiled at (SCENE_FORMAT_FRAC_MIN up to its own): made by that format's
 * core (make_spec_tables); none when the scene has no fast Phong, with
 * --spec-tables ram, or when the formats disagree on the exponents. */
static struct spec_set {
    uint16_t n;
    uint32_t exps[RASTER_SPEC_MAX];
    uint16_t tab[RASTER_SPEC_MAX * 257];
    uint32_t step[RASTER_SPEC_MAX * 2];
} spec_sets[SCENE_FORMAT_FRAC_MAX - SCENE_FORMAT_FRAC_MIN + 1];
static int spec_frac_max;       /* spec_sets[0 .. spec_frac_max - MIN]; below MIN: none */
static size_t spec_copies;      /* the work the tables in flash save (work_sizes) */
static int target_work_given;   /* the work size is the target's (--target-work) */
static uint32_t scene_features; /* render_features of the scene (work_sizes) */

/* The renderer features' names (firmware/core/scene_features.def), by bit. */
static const char *const feature_names[] = {
#define FEATURE(name, doc) #name,
#include "scene_features.def"
};

/* With out NULL nothing is written: a dry run that only adds up
 * flash_bytes (the budget check before anything is written). */
static void emit(const char *fmt, ...)
{
    if (!out) return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(out, fmt, ap);
    va_end(ap);
}

/* A num literal: the double, exactly (17 digits), as NUM_C(...). The result
 * lives in a ring of 16 buffers: one emit() may take at most 16 literals
 * (the 2D primitive takes 9, in an unspecified evaluation order). */
static const char *lit(num v)
{
    static char bufs[16][48];
    static int k;
    char *b = bufs[k++ & 15];
    double d = num_to_double(v);
    if (d == 0 && signbit(d)) return "NUM_C(-0.0)";
    char t[40];
    snprintf(t, sizeof t, "%.17g", d);
    if (!strpbrk(t, ".e")) strcat(t, ".0");
    snprintf(b, 48, "NUM_C(%s)", t);
    return b;
}

static void emit_vec3(vec3 v) { emit("{ %s, %s, %s }", lit(v.x), lit(v.y), lit(v.z)); }
static void emit_rgb(rgb c) { emit("{ %s, %s, %s }", lit(c.r), lit(c.g), lit(c.b)); }
static void emit_mat3(const mat3 *m)
{
    emit("{ { ");
    for (int i = 0; i < 3; i++)
        emit("{ %s, %s, %s }%s", lit(m->m[i][0]), lit(m->m[i][1]), lit(m->m[i][2]), i < 2 ? ", " : "");
    emit(" } }");
}
static void emit_anim(const struct scene_anim *a)
{
    emit("{ %s, ", lit(a->rot_y_per_frame));
    emit_vec3(a->move_per_frame);
    emit(" }");
}

static void upper(char *d, const char *s)
{
    for (; *s; s++) *d++ = (char)(*s >= 'a' && *s <= 'z' ? *s - 32 : *s);
    *d = 0;
}

/* ---- emission ------------------------------------------------------------- */

/* A member of struct rt_options or ras_options (firmware/core/scene_options.def):
 * where it lives, whether it is a num, and the line of the initializer it
 * goes on. */
struct member {
    const char *field;
    size_t offset, size;
    int is_num, line;
};

enum { KIND_BOOL = 0, KIND_NOT = 0, KIND_INT = 0, KIND_NUM = 1, KIND_CHOICE = 0, KIND_INDEX = 0 };

#define MEMBER(st, field, type, kind, emit_line) \
    { #field, offsetof(struct st, field), sizeof(type), KIND_##kind, emit_line },
static const struct member rt_members[] = {
#define RT_OPTION(key, field, type, kind, lo, hi, values, values_error, def, def_doc, emit_line, order, doc) \
    MEMBER(rt_options, field, type, kind, emit_line)
#include "scene_options.def"
};
static const struct member ras_members[] = {
#define RAS_OPTION(key, field, type, kind, lo, hi, values, values_error, def, def_doc, emit_line, order, doc) \
    MEMBER(ras_options, field, type, kind, emit_line)
#include "scene_options.def"
};
#undef MEMBER

/* `open` (".rt = { ") and the members of *opts, line by line as the table
 * says, continuation lines aligned under the first member. */
static void emit_members(const char *open, const struct member *m, size_t n, const void *opts)
{
    const unsigned char *base = opts;
    int last_line = 0;
    size_t left = n;
    for (size_t i = 0; i < n; i++)
        if (m[i].line > last_line) last_line = m[i].line;
    emit("%s", open);
    for (int line = 1; line <= last_line; line++) {
        size_t on_line = 0, k = 0;
        for (size_t i = 0; i < n; i++) on_line += m[i].line == line;
        for (size_t i = 0; i < n; i++) {
            if (m[i].line != line) continue;
            if (k++ == 0 && left < n) emit("%*s", (int)strlen(open), "");
            if (m[i].is_num) {
                num v;
                memcpy(&v, base + m[i].offset, sizeof v);
                emit(".%s = %s", m[i].field, lit(v));
            } else if (m[i].size == 1) {
                emit(".%s = %d", m[i].field, base[m[i].offset]);
            } else {
                uint16_t v;
                memcpy(&v, base + m[i].offset, sizeof v);
                emit(".%s = %d", m[i].field, v);
            }
            left--;
            emit(!left ? " },\n" : k == on_line ? ",\n" : ", ");
        }
    }
}

static void emit_lights(const struct scene *s)
{
    if (!s->nlights) return;
    emit("static const struct scene_light lights[%d] = {\n", s->nlights);
    for (int i = 0; i < s->nlights; i++) {
        emit("    { .type = %d, .intensity = %s, .v = ", s->lights[i].type, lit(s->lights[i].intensity));
        emit_vec3(s->lights[i].v);
        emit(" },\n");
    }
    emit("};\n\n");
    flash_bytes += s->nlights * LSIZE(light);
}

static void emit_objects(const struct scene *s)
{
    if (s->nobjects) {
        emit("static const struct rt_object objects[%d] = {\n", s->nobjects);
        for (int i = 0; i < s->nobjects; i++) {
            const struct rt_object *o = &s->objects[i];
            emit("    { .shape = %d, .csg_only = %d,\n      .mat = { .color = ", o->shape, o->csg_only);
            emit_rgb(o->mat.color);
            emit(", .specular = %s, .reflective = %s, .transparency = %s, .refraction = %s },\n      .center = ",
                 lit(o->mat.specular), lit(o->mat.reflective), lit(o->mat.transparency), lit(o->mat.refraction));
            emit_vec3(o->center);
            emit(", .radius = %s, .normal = ", lit(o->radius));
            emit_vec3(o->normal);
            emit(", .dist = %s,\n      .p = { ", lit(o->dist));
            for (int k = 0; k < 3; k++) { emit_vec3(o->p[k]); emit(k < 2 ? ", " : " },\n"); }
            emit("    },\n");
        }
        emit("};\n\n");
        flash_bytes += s->nobjects * LSIZE(object);
    }
    if (s->ncsg) {
        emit("static const struct rt_csg csg[%d] = {\n", s->ncsg);
        for (int i = 0; i < s->ncsg; i++) emit("    { .op = %d, .a = %d, .b = %d },\n", s->csg[i].op, s->csg[i].a, s->csg[i].b);
        emit("};\n\n");
        flash_bytes += s->ncsg * LSIZE(csg);
    }
}

/* Whether texture x's fast texels are written here (--fast-textures flash;
 * the work memory they would take is left out: work_sizes). */
static int fast_tex(const struct ras_texture *x)
{
    return fast_in_flash && (x->filter == TEX_NEAREST || x->filter == TEX_BILINEAR) && x->rgb &&
           mip_fast_sides(x->w, x->h);
}

static int any_fast_tex(const struct scene *s)
{
    for (int t = 0; t < s->ntextures; t++)
        if (fast_tex(&s->textures[t])) return 1;
    return 0;
}

/* A texture's fast-path texels as const data (scenec --fast-textures
 * flash): two words a texel for bilinear filtering (one with
 * `bilinear_weights = coarse`), RGB565 otherwise. */
static int emit_oom;   /* a buffer could not be had: the output is refused */
static void emit_fast_texels(const struct scene *s, const struct ras_texture *x, int t)
{
    int bl = x->filter == TEX_BILINEAR, bw = bl && s->ras.bl_weights;
    size_t size = bw ? mip_fast_bilinear_word_size(x->w, x->h)
                     : (bl ? mip_fast_bilinear_size(x->w, x->h) : (size_t)x->w * x->h * 2);
    size_t esz = bl ? 4 : 2, n = size / esz;
    flash_bytes += size;
    texture_bytes += size;
    if (!out) return;
    void *d = malloc(size);
    if (!d) {
        emit_oom = 1;
        return;
    }
    if (bw)
        mip_fast_bilinear_word(x->rgb, x->w, x->h, d);
    else if (bl)
        mip_fast_bilinear(x->rgb, x->w, x->h, d);
    else
        mip_fast_rgb565(x->rgb, x->w, x->h, d);
    emit("static const uint%d_t tex%d_fast[%zu] = {", bl ? 32 : 16, t, n);
    for (size_t k = 0; k < n; k++) {
        unsigned v = bl ? (unsigned)((const uint32_t *)d)[k] : ((const uint16_t *)d)[k];
        emit(bl ? "%s0x%08x," : "%s0x%04x,", k % (bl ? 8 : 12) ? "" : "\n   ", v);
    }
    emit("\n};\n");
    free(d);
}

static void emit_textures(const struct scene *s)
{
    for (int t = 0; t < s->ntextures; t++) {
        const struct ras_texture *x = &s->textures[t];
        int w = x->w, h = x->h;
        for (int l = 0; l < x->mip_levels; l++) {
            const uint8_t *px = l == 0 ? x->rgb : x->mip[l];
            size_t n = (size_t)w * h * 3;
            emit("static const uint8_t tex%d_level%d[%zu] = {", t, l, n);
            for (size_t k = 0; out && k < n; k++) emit("%s%u,", k % 24 ? "" : "\n   ", px[k]);
            emit("\n};\n");
            flash_bytes += n;
            texture_bytes += n;
            w = w > 1 ? w / 2 : 1;
            h = h > 1 ? h / 2 : 1;
        }
        if (fast_tex(x)) emit_fast_texels(s, x, t);
        if (x->mip_levels > 1) {
            emit("static const uint8_t *const tex%d_mip[%d] = {", t, x->mip_levels);
            for (int l = 0; l < x->mip_levels; l++) emit(" tex%d_level%d,", t, l);
            emit(" };\n");
            flash_bytes += x->mip_levels * LSIZE(ptr);
        }
        emit("\n");
    }
    if (s->ntextures) {
        emit("static const struct ras_texture textures[%d] = {\n", s->ntextures);
        for (int t = 0; t < s->ntextures; t++) {
            const struct ras_texture *x = &s->textures[t];
            emit("    { .w = %d, .h = %d, .rgb = tex%d_level0, .filter = %d, .mip_levels = %d, .mip = ", x->w, x->h,
                 t, x->filter, x->mip_levels);
            if (x->mip_levels > 1) emit("tex%d_mip },\n", t);
            else emit("0 },\n");
        }
        emit("};\n\n");
        flash_bytes += s->ntextures * LSIZE(texture);
        if (any_fast_tex(s)) {
            emit("static const void *const tex_fast[%d] = {", s->ntextures);
            for (int t = 0; t < s->ntextures; t++)
                if (fast_tex(&s->textures[t])) emit(" tex%d_fast,", t);
                else emit(" 0,");
            emit(" };\n\n");
            flash_bytes += s->ntextures * LSIZE(ptr);
        }
    }
}

/* Fast Phong's specular tables (--spec-tables flash): those of the format
 * the file is compiled at, one set per format; SCENE_SPEC_TABLES their count
 * (none in float and double, whose cores make their own). */
static void emit_spec_tables(void)
{
    if (spec_frac_max < SCENE_FORMAT_FRAC_MIN) return;
    const struct spec_set *t0 = &spec_sets[0];
    emit("/* fast Phong's specular tables, exponent%s", t0->n > 1 ? "s" : "");
    for (int k = 0; k < t0->n; k++) emit(" %lu", (unsigned long)t0->exps[k]);
    emit(" (raster_spec_table), at the core's\n   NUM_FRAC: render_init makes none */\n");
    for (int f = SCENE_FORMAT_FRAC_MIN; f <= spec_frac_max; f++) {
        const struct spec_set *t = &spec_sets[f - SCENE_FORMAT_FRAC_MIN];
        emit("#%s NUM_MODE == NUM_MODE_FIXED && NUM_FRAC == %d\n", f == SCENE_FORMAT_FRAC_MIN ? "if" : "elif", f);
        emit("#define SCENE_SPEC_TABLES %d\nstatic const uint16_t spec_tab[%d] = {", t->n, 257 * t->n);
        for (int k = 0; k < 257 * t->n; k++) emit("%s%u,", k % 16 ? " " : "\n   ", (unsigned)t->tab[k]);
        emit("\n};\nstatic const uint32_t spec_step[%d] = {", 2 * t->n);
        for (int k = 0; k < 2 * t->n; k++) emit(" %lu,", (unsigned long)t->step[k]);
        emit(" };\n");
    }
    emit("#endif\n\n");
    /* one set is compiled in: uint16_t and uint32_t take 2 and 4 bytes on every target */
    flash_bytes += (size_t)t0->n * (257 * 2 + 2 * 4);
}

static void emit_model_data(const struct ras_model *md, int m)
{
    emit("static const vec3 model%d_verts[%d] = {\n", m, md->nverts);
    for (int k = 0; k < md->nverts; k++) { emit("    "); emit_vec3(md->verts[k]); emit(",\n"); }
    emit("};\n");
    emit("static const struct ras_triangle model%d_tris[%d] = {\n", m, md->ntris);
    for (int k = 0; k < md->ntris; k++) {
        const struct ras_triangle *t = &md->tris[k];
        emit("    { .v = { %d, %d, %d }, .color = ", t->v[0], t->v[1], t->v[2]);
        emit_rgb(t->color);
        if (md->has_normals) {
            emit(",\n      .n = { ");
            for (int c = 0; c < 3; c++) { emit_vec3(t->n[c]); emit(c < 2 ? ", " : " }"); }
        }
        if (md->has_uvs) {
            emit(",\n      .uv = { ");
            for (int c = 0; c < 3; c++) emit("{ %s, %s }%s", lit(t->uv[c].u), lit(t->uv[c].v), c < 2 ? ", " : " }");
        }
        emit(" },\n");
    }
    emit("};\n\n");
    flash_bytes += md->nverts * LSIZE(vec3) + md->ntris * LSIZE(tri) + strlen(md->name) + 1;
}

static void emit_models(const struct scene *s)
{
    for (int m = 0; m < s->nmodels; m++) emit_model_data(&s->models[m], m);
    if (s->nmodels) {
        emit("static const struct ras_model models[%d] = {\n", s->nmodels);
        for (int m = 0; m < s->nmodels; m++) {
            const struct ras_model *md = &s->models[m];
            emit("    { .name = \"%s\", .nverts = %d, .ntris = %d, .verts = model%d_verts, .tris = model%d_tris,\n"
                 "      .has_normals = %d, .has_uvs = %d, .vertex_normals = %d, .bound_center = ",
                 md->name, md->nverts, md->ntris, m, m, md->has_normals, md->has_uvs, md->vertex_normals);
            emit_vec3(md->bound_center);
            emit(", .bound_radius = %s },\n", lit(md->bound_radius));
        }
        emit("};\n\n");
        flash_bytes += s->nmodels * LSIZE(model);
    }
    if (s->ninstances) {
        emit("static const struct ras_instance instances[%d] = {\n", s->ninstances);
        for (int i = 0; i < s->ninstances; i++) {
            const struct ras_instance *in = &s->instances[i];
            emit("    { .model = %d, .texture = %d, .normal_map = %d, .position = ", in->model, in->texture,
                 in->normal_map);
            emit_vec3(in->position);
            emit(",\n      .rotation = ");
            emit_mat3(&in->rotation);
            emit(",\n      .scale = %s, .specular = %s, .anim = ", lit(in->scale), lit(in->specular));
            emit_anim(&in->anim);
            emit(" },\n");
        }
        emit("};\n\n");
        flash_bytes += s->ninstances * LSIZE(instance);
    }
}

static void emit_primitives(const struct scene *s)
{
    if (s->nprims) {
        emit("static const struct prim2d prims[%d] = {\n", s->nprims);
        for (int i = 0; i < s->nprims; i++) {
            const struct prim2d *p = &s->prims[i];
            emit("    { .kind = %d, .npts = %d, .x = { %s, %s, %s }, .y = { %s, %s, %s }, .h = { %s, %s, %s }, .color = ",
                 p->kind, p->npts, lit(p->x[0]), lit(p->x[1]), lit(p->x[2]), lit(p->y[0]), lit(p->y[1]),
                 lit(p->y[2]), lit(p->h[0]), lit(p->h[1]), lit(p->h[2]));
            emit_rgb(p->color);
            emit(" },\n");
        }
        emit("};\n\n");
        flash_bytes += s->nprims * LSIZE(prim);
    }
    if (s->nlines) {
        emit("static const struct line3d lines[%d] = {\n", s->nlines);
        for (int i = 0; i < s->nlines; i++) {
            emit("    { .a = ");
            emit_vec3(s->lines[i].a);
            emit(", .b = ");
            emit_vec3(s->lines[i].b);
            emit(", .color = ");
            emit_rgb(s->lines[i].color);
            emit(" },\n");
        }
        emit("};\n\n");
        flash_bytes += s->nlines * LSIZE(line);
    }
}

/* struct scene itself, pointing at the arrays above. */
static void emit_scene_struct(const struct scene *s, const char *id, unsigned fits)
{
    emit("const struct scene scene_%s = {\n", id);
    emit("    .name = \"%s\", .kind = %d, .fits = %u, .canvas_w = %d, .canvas_h = %d,\n", s->name, s->kind, fits,
         s->canvas_w, s->canvas_h);
    emit("    .viewport_w = %s, .viewport_h = %s, .projection_d = %s,\n", lit(s->viewport_w), lit(s->viewport_h),
         lit(s->projection_d));
    emit("    .background = ");
    emit_rgb(s->background);
    emit(", .background_set = %d,\n    .camera = { .position = ", s->background_set);
    emit_vec3(s->camera.position);
    emit(", .rotation = ");
    emit_mat3(&s->camera.rotation);
    emit(",\n      .rot_q29 = { ");
    for (int i = 0; i < 3; i++)
        emit("{ %ld, %ld, %ld }%s", (long)s->camera.rot_q29[i][0], (long)s->camera.rot_q29[i][1],
             (long)s->camera.rot_q29[i][2], i < 2 ? ", " : "");
    emit(" } },\n    .camera_anim = ");
    emit_anim(&s->camera_anim);
    emit(", .frames = %d,\n", s->frames);
    emit("    .nlights = %d, .lights = %s,\n", s->nlights, s->nlights ? "lights" : "0");
    emit("    .nobjects = %d, .ncsg = %d, .objects = %s, .csg = %s,\n", s->nobjects, s->ncsg,
         s->nobjects ? "objects" : "0", s->ncsg ? "csg" : "0");
    emit_members("    .rt = { ", rt_members, sizeof rt_members / sizeof rt_members[0], &s->rt);
    emit("    .nmodels = %d, .ninstances = %d, .ntextures = %d, .nprims = %d, .nlines = %d,\n", s->nmodels,
         s->ninstances, s->ntextures, s->nprims, s->nlines);
    emit("    .models = %s, .instances = %s, .textures = %s, .prims = %s, .lines = %s,\n",
         s->nmodels ? "models" : "0", s->ninstances ? "instances" : "0", s->ntextures ? "textures" : "0",
         s->nprims ? "prims" : "0", s->nlines ? "lines" : "0");
    if (any_fast_tex(s)) emit("    .tex_fast = tex_fast,\n");
    if (spec_frac_max >= SCENE_FORMAT_FRAC_MIN)
        emit("#ifdef SCENE_SPEC_TABLES\n    .nspec = SCENE_SPEC_TABLES, .spec_tab = spec_tab, .spec_step = spec_step,\n"
             "#endif\n");
    emit_members("    .ras = { ", ras_members, sizeof ras_members / sizeof ras_members[0], &s->ras);
    emit("};\n\n");
    flash_bytes += LSIZE(scene) + strlen(s->name) + 1;
}

static void emit_scene(const struct scene *s, const char *id, const char *src, int frac, unsigned fits,
                       int width, int height, int strip)
{
    emit("/* %s.c — generated by tools/scenec from %s; do not edit. */\n", id, src);
    const char *hb = !outh_path ? "" : strrchr(outh_path, '/') ? strrchr(outh_path, '/') + 1 : outh_path;
    emit("#include \"scene.h\"\n#include \"%s\"\n\n", hb);
    /* a coarser format (smaller NUM_FRAC) holds every range this one does */
    emit("#if NUM_MODE == NUM_MODE_FIXED && NUM_FRAC > %d\n", frac);
    emit("#error \"scene %s was checked for NUM_FRAC <= %d\"\n#endif\n", id, frac);
    /* a core compiled without a feature the scene needs (an image's
     * features header of other scenes) */
    for (int k = 0; k < RENDER_FEATURE_COUNT; k++)
        if (scene_features >> k & 1u)
            emit("#if !FW_FEATURE_%s\n#error \"scene %s needs the renderer feature %s (firmware/core/scene_features.def)\"\n"
                 "#endif\n", feature_names[k], id, feature_names[k]);
    emit("\n");
    emit_lights(s);
    emit_objects(s);
    emit_textures(s);
    emit_models(s);
    emit_primitives(s);
    emit_spec_tables();
    emit_scene_struct(s, id, fits);
    emit("/* render_work_size(scene, %d, %d, %d) of the fixed-point core%s */\n", width, height, strip,
         target_work_given ? " on the target" : " (this host's: an upper bound)");
    char ID[256];
    upper(ID, id);
    emit("_Alignas(8) uint8_t scene_%s_work[SCENE_%s_WORK_SIZE > 0 ? SCENE_%s_WORK_SIZE : 1];\n", id, ID, ID);
}


/* ---- the files read (--deps) -------------------------------------------------- */

/* The parser opens every file it reads with fopen, which the link wraps
 * (mk/scene.mk: -Wl,--wrap=fopen): each path opened for reading is kept. */
FILE *__real_fopen(const char *path, const char *mode);
FILE *__wrap_fopen(const char *path, const char *mode);

static char *read_paths[64];
static size_t nread_paths, dropped_paths;

FILE *__wrap_fopen(const char *path, const char *mode)
{
    FILE *f = __real_fopen(path, mode);
    if (!f || mode[0] != 'r' || strchr(mode, '+')) return f;
    for (size_t i = 0; i < nread_paths; i++)
        if (!strcmp(read_paths[i], path)) return f;
    char *copy = nread_paths < sizeof read_paths / sizeof read_paths[0] ? malloc(strlen(path) + 1) : NULL;
    if (!copy) {
        dropped_paths++;
        return f;
    }
    read_paths[nread_paths++] = strcpy(copy, path);
    return f;
}

/* A path as a make word: 0, or -1 when make could not read it back. */
static int make_word(FILE *f, const char *path)
{
    if (strpbrk(path, " \t\n:#%$\\")) return -1;
    return fputs(path, f) < 0 ? -1 : 0;
}

/* OUT.d (written whole, then renamed into place): 0, or 1. */
static int write_deps(const char *dpath, const char *outc, const char *scene)
{
    char tmp[1100], outh[1100];
    size_t n = strlen(outc);
    if (n < 3 || strcmp(outc + n - 2, ".c")) return 0;   /* write_outputs says why */
    int ok = dropped_paths == 0 && snprintf(tmp, sizeof tmp, "%s.tmp", dpath) < (int)sizeof tmp &&
             snprintf(outh, sizeof outh, "%s", outc) < (int)sizeof outh;
    if (ok) outh[n - 1] = 'h';
    FILE *f = ok ? fopen(tmp, "w") : NULL;
    if (!f) {
        fprintf(stderr, "scenec: cannot write %s\n", dpath);
        return 1;
    }
    ok = make_word(f, outc) == 0 && fputc(' ', f) != EOF && make_word(f, outh) == 0 && fputs(":", f) >= 0;
    for (size_t i = 0; ok && i < nread_paths; i++) ok = fputc(' ', f) != EOF && make_word(f, read_paths[i]) == 0;
    ok = ok && fputc('\n', f) != EOF;
    for (size_t i = 0; ok && i < nread_paths; i++)
        if (strcmp(read_paths[i], scene)) ok = make_word(f, read_paths[i]) == 0 && fputs(":\n", f) >= 0;
    if (fclose(f) || !ok || rename(tmp, dpath)) {
        unlink(tmp);
        fprintf(stderr, "scenec: cannot write %s (a path make cannot read, or a write error)\n", dpath);
        return 1;
    }
    return 0;
}

/* ---- output paths ------------------------------------------------------------ */

static int usage_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* The directory of path ("." when it has none) into dir: 0, or -1 too long. */
static int dir_of(const char *path, char *dir, size_t len)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 1;
    if (slash && n == 0) n = 1;   /* "/file" */
    if (n >= len) return -1;
    memcpy(dir, slash ? path : ".", n);
    dir[n] = 0;
    return 0;
}

/* An output's destination before anything is read: its directory exists,
 * and it is not a directory itself. 0, or 2 after the message. */
static int check_dest(const char *opt, const char *path)
{
    char dir[1100];
    struct stat st;
    if (dir_of(path, dir, sizeof dir)) return usage_error("%s %s: path too long", opt, path);
    if (stat(dir, &st) || !S_ISDIR(st.st_mode))
        return usage_error("%s %s: directory %s does not exist", opt, path, dir);
    if (!stat(path, &st) && S_ISDIR(st.st_mode)) return usage_error("%s %s: is a directory", opt, path);
    return 0;
}

/* The outputs (OUT.c, OUT.h, --deps) against each other and against every
 * file the scene made scenec read (the scene, its textures, OBJ and MTL
 * files): 0, or 2 after the message. */
static int check_outputs(const char *outc, const char *deps, const char *scene)
{
    char outh[1100];
    size_t n = strlen(outc);
    if (n < 3 || strcmp(outc + n - 2, ".c")) return 0;   /* write_outputs says why */
    if (n >= sizeof outh) return usage_error("-o %s: path too long", outc);
    memcpy(outh, outc, n + 1);
    outh[n - 1] = 'h';
    const char *outs[3] = { outc, outh, deps };
    for (int i = 0; i < 3; i++) {
        if (!outs[i]) continue;
        for (size_t k = 0; k < nread_paths; k++)
            if (file_same(outs[i], read_paths[k]))
                return usage_error("%s: is %s; refusing to overwrite it", outs[i],
                                   !strcmp(read_paths[k], scene) ? "the scene file" : "a file the scene reads");
        for (int j = 0; j < i; j++)
            if (outs[j] && file_same(outs[i], outs[j])) return usage_error("%s: given as two outputs", outs[i]);
    }
    return 0;
}

/* ---- the target's budget -------------------------------------------------- */

/* What a compiled scene may take of a target's memory, the firmware's own
 * share taken off (docs/scene-format.md, "Budgets"): RAM for the renderer's
 * work memory (on the RP2040 with a second core's context, as the two-core
 * board images allocate it), flash for the scene's const data. */
struct target {
    const char *name;
    long long ram, flash;      /* bytes; -1: no budget */
    int sibling;               /* the second core's context counts */
    const char *what;
};
static const struct target targets[] = {
    /* 264 KB SRAM: the largest share a two-core board image leaves to its
       two work buffers (docs/firmware.md: 228,896 bytes with
       RP2040_RAM_TEXT=0, 160,496 with raster, about 52,900 with the whole
       core in SRAM, more with only the code an image's scenes need; make
       image checks the image's own figure); 2 MB flash
       less 256 KB for the firmware (175 KB: boot2, vectors, code) */
    { "rp2040", 228896, 2048 * 1024 - 256 * 1024, 1, "RP2040 board image, two cores" },
    /* qemu's mps2-an385 and mps2-an386 as tools/bench/mps2.ld lays them
       out: 4 MB of code, 4 MB of RAM, 512 KB of each kept for the image */
    { "m0plus", 4096 * 1024 - 512 * 1024, 4096 * 1024 - 512 * 1024, 0, "emulated Cortex-M0+, mps2-an385" },
    { "m4f", 4096 * 1024 - 512 * 1024, 4096 * 1024 - 512 * 1024, 0, "emulated Cortex-M4F, mps2-an386" },
    /* STM32F411: 128 KB SRAM less 32 KB (strips, stack, data), 512 KB flash
       less 192 KB (the fixed-point image's code) */
    { "stm32f411", 96 * 1024, 320 * 1024, 0, "STM32F411 board image" },
    { "none", -1, -1, 0, "no budget" },
};
#define TARGET_DEFAULT 1   /* m0plus: every scene the Makefiles compile fits */

static const char help_text[] =
    "usage: scenec [options] -o OUT.c SCENE\n"
    "Compiles the scene file SCENE into C source for the firmware: OUT.c (the scene as\n"
    "const data and one static work buffer) and OUT.h (its declarations and the number\n"
    "format it was checked for); prints the scene's ranges, the format chosen and why no\n"
    "intermediate overflows (docs/scene-format.md, \"tools/scenec\").\n"
    "  -o OUT.c                      the C file to write (required; OUT.h beside it)\n"
    "  --size WxH                    render size, each side 1..4096 (default 240x240)\n"
    "  --strip-rows N                rows per strip, 1..4096 (default 16; at most the height)\n"
    "  --fracs F,F,...               the fixed-point formats Q(31-F).F allowed, F in 12..20,\n"
    "                                finest first (default 20,19,18,17,16,15,14,13,12)\n"
    "  --id NAME                     the C identifier of the scene (default: its path under\n"
    "                                firmware/scenes/ without .scene, other characters as _)\n"
    "  --allow-wide                  when no format of --fracs holds the scene, take the\n"
    "                                coarsest of them anyway instead of refusing it\n"
    "  --target-work BYTES[:SIBLING[:LAYOUT]]\n"
    "                                the renderer's work memory on the target (and of a\n"
    "                                second core's context), as measured there (default:\n"
    "                                this host's fixed-point core, an upper bound); LAYOUT:\n"
    "                                the target's sizes of the const data's types, which\n"
    "                                the flash is counted at (tools/scenec/target_work.sh\n"
    "                                prints all three)\n"
    "  --deps OUT.d                  also write a make rule: OUT.c and OUT.h depend on the\n"
    "                                scene and every file it made scenec read\n"
    "  --target NAME                 the budget of RAM and flash the scene must fit:\n"
    "                                rp2040, m0plus, m4f, stm32f411 or none (default m0plus)\n"
    "  --ram-budget N[K|M]           RAM the scene's work memory may take instead of the\n"
    "                                target's (K = 1024 bytes, M = 1024 K)\n"
    "  --flash-budget N[K|M]         flash the scene's const data may take instead of the\n"
    "                                target's\n"
    "  --chosen-scene FILE           with an accuracy target: also write the scene text with\n"
    "                                the chosen options (for the work probe)\n"
    "  --work-of-choice              --target-work was measured for the chosen options\n"
    "  --fast-textures ram|flash     where the fast path's texels are: made in work memory\n"
    "                                by render_init (ram, the default) or written here as\n"
    "                                const data (flash)\n"
    "  --spec-tables ram|flash       where fast Phong's specular tables are: made in work\n"
    "                                memory by render_init (ram) or written here as const\n"
    "                                data, one set per fixed-point format (flash, the\n"
    "                                default)\n"
    "  --min-psnr DB                 choose the scene's methods for this accuracy (PSNR\n"
    "                                against double's exact render, 1..200): the cheapest on\n"
    "                                --target (m0plus, m4f or rp2040; default: the scene's\n"
    "                                quality block's, else m0plus); the scene's quality block\n"
    "                                does the same without it\n"
    "  -h, --help                    this text\n"
    "exit status: 0 ok, 1 internal or output error, 2 usage or input error (scene errors\n"
    "             as FILE:LINE:COLUMN: error: MESSAGE; a scene no format holds; a\n"
    "             scene over the RAM or flash budget)\n";

/* ---- command line ------------------------------------------------------------ */

struct args {
    int width, height, strip, allow_wide;
    long target_work;             /* -1: not given */
    long target_sibling;          /* -1: not given (then this host's) */
    int fracs[16], nfracs;
    const char *outc, *path, *idarg, *deps;
    const struct target *target;
    long long ram_budget, flash_budget;   /* -1: none; from --target unless given */
    int ram_given, flash_given;
    int target_given;             /* --target given */
    double min_psnr;              /* --min-psnr, 0: not given */
    const char *chosen_scene;     /* --chosen-scene: the scene text with the chosen options */
    int work_of_choice;           /* --work-of-choice: --target-work is the chosen methods' */
};

/* --fracs 20,...,12 into a->fracs; 0, or -1 for a malformed list */
static int parse_fracs(char *p, struct args *a)
{
    a->nfracs = 0;
    if (!*p) return -1;
    while (*p) {
        if (a->nfracs == 16) return -1;
        char *e;
        long f = strtol(p, &e, 10);
        if (e == p || f < 12 || f > 20) return -1;
        a->fracs[a->nfracs++] = (int)f;
        p = e;
        if (*p == ',' && p[1]) p++;
        else if (*p) return -1;
    }
    return 0;
}

/* A usage error: its line on stderr; returns 2. */
static int usage_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int usage_error(const char *fmt, ...)
{
    va_list ap;
    fputs("scenec: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return 2;
}

/* A decimal integer in lo..hi, digits only; -1 if it is not one. */
static long parse_int(const char *s, long lo, long hi)
{
    char *e;
    if (*s < '0' || *s > '9') return -1;
    long v = strtol(s, &e, 10);
    return *e || v < lo || v > hi ? -1 : v;
}

/* Why s (its first n characters) is not a decimal integer in lo..hi, into
 * why; 0 if it is one. */
static int int_why(const char *s, size_t n, long lo, long hi, char *why, size_t len)
{
    size_t i = 0;
    long v = 0;
    while (i < n && s[i] >= '0' && s[i] <= '9') {
        v = v * 10 + (s[i++] - '0');
        if (v > hi) v = hi + 1;
    }
    if (i == 0) snprintf(why, len, n ? "'%.*s' is not a number" : "no number", (int)n, s);
    else if (i < n) snprintf(why, len, "'%.*s' after the number", (int)(n - i), s + i);
    else if (v < lo) snprintf(why, len, "%ld is less than %ld", v, lo);
    else if (v > hi) snprintf(why, len, "larger than %ld", hi);
    else return 0;
    return -1;
}

/* N, NK or NM (K = 1024 bytes), 1 .. 2047 M; -1 if it is not one. */
static long long parse_bytes(const char *s)
{
    char *e;
    if (*s < '0' || *s > '9') return -1;
    errno = 0;
    long long v = strtoll(s, &e, 10), mul = 1;
    if (*e == 'K') mul = 1024, e++;
    else if (*e == 'M') mul = 1024 * 1024, e++;
    if (*e || errno || v < 1 || v > 2047LL * 1024 * 1024 / mul) return -1;
    return v * mul;
}

/* 0, 2 after the message of a bad command line, or -1 for --help (printed). */
static int parse_args(int argc, char **argv, struct args *a)
{
    /* every format the renderers are checked at (tests/unit/test_scene_fracs.c) */
    static const int all_fracs[] = { 20, 19, 18, 17, 16, 15, 14, 13, 12 };
    static const char *const with_arg[] = { "--size", "--strip-rows", "--fracs", "--id", "--target-work",
                                            "--deps", "--target", "--ram-budget", "--flash-budget", "--min-psnr",
                                            "--chosen-scene", "--fast-textures", "--spec-tables", "-o", NULL };
    static const char *const all[] = { "--size", "--strip-rows", "--fracs", "--id", "--target-work",
                                       "--deps", "--target", "--ram-budget", "--flash-budget", "--min-psnr",
                                       "--chosen-scene", "--work-of-choice", "--allow-wide", "--fast-textures",
                                       "--spec-tables", "--help", NULL };
    memset(a, 0, sizeof *a);
    scene_layout_of_build(&layout); /* (scene_layout.o is this host's fixed-point build: mk/scene.mk) */
    layout_of_target = 0;
    a->width = a->height = 240;
    a->strip = 16;
    a->target_work = -1;
    a->target_sibling = -1;
    memcpy(a->fracs, all_fracs, sizeof all_fracs);
    a->nfracs = 9;
    a->target = &targets[TARGET_DEFAULT];
    for (int i = 1; i < argc; i++) {
        const char *opt = argv[i];
        if (!strcmp(opt, "--help") || !strcmp(opt, "-h")) {
            fputs(help_text, stdout);
            return -1;
        }
        if (!strcmp(opt, "--allow-wide")) {
            a->allow_wide = 1;
            continue;
        }
        if (!strcmp(opt, "--work-of-choice")) {
            a->work_of_choice = 1;
            continue;
        }
        int takes = 0;
        for (int k = 0; with_arg[k]; k++) takes |= !strcmp(opt, with_arg[k]);
        if (!takes) {
            if (opt[0] != '-') {
                if (a->path) return usage_error("one scene file only: '%s' and '%s' (try --help)", a->path, opt);
                a->path = opt;
                continue;
            }
            const char *near = !strncmp(opt, "--", 2) ? suggest_nearest(opt, all) : NULL;
            if (near) return usage_error("unknown option '%s' (did you mean '%s'? try --help)", opt, near);
            return usage_error("unknown option '%s' (try --help)", opt);
        }
        if (i + 1 >= argc || !argv[i + 1][0]) return usage_error("option %s needs an argument", opt);
        char *val = argv[++i];
        if (!strcmp(opt, "--size")) {
            char *x = strchr(val, 'x');
            long w = -1, h = -1;
            if (x) {
                *x = 0;
                w = parse_int(val, 1, 4096);
                h = parse_int(x + 1, 1, 4096);
                *x = 'x';
            }
            if (w < 0 || h < 0) {
                char why[128] = "no 'x' between width and height", r[96];
                if (x && int_why(val, (size_t)(x - val), 1, 4096, r, sizeof r)) snprintf(why, sizeof why, "width: %s", r);
                else if (x && int_why(x + 1, strlen(x + 1), 1, 4096, r, sizeof r))
                    snprintf(why, sizeof why, "height: %s", r);
                return usage_error("bad size '%s': %s (WxH, each side 1..4096)", val, why);
            }
            a->width = (int)w;
            a->height = (int)h;
        } else if (!strcmp(opt, "--strip-rows")) {
            long n = parse_int(val, 1, 4096);
            char why[128];
            if (n < 0 && !int_why(val, strlen(val), 1, 4096, why, sizeof why)) snprintf(why, sizeof why, "not 1..4096");
            if (n < 0) return usage_error("bad strip height '%s': %s (1..4096)", val, why);
            a->strip = (int)n;
        } else if (!strcmp(opt, "--fracs")) {
            if (parse_fracs(val, a)) {
                /* the first item that is not one of 12..20, else the list's form */
                char why[128] = "", r[96];
                const char *q = val;
                for (int k = 0; *q && !why[0]; k++) {
                    size_t m = strcspn(q, ",");
                    if (k == 16) snprintf(why, sizeof why, "more than 16 formats");
                    else if (int_why(q, m, 12, 20, r, sizeof r)) snprintf(why, sizeof why, "item %d: %s", k + 1, r);
                    q += m + (q[m] == ',');
                }
                if (!why[0]) snprintf(why, sizeof why, "an empty item");
                return usage_error("bad --fracs '%s': %s (up to 16 of 12..20, comma-separated)", val, why);
            }
        } else if (!strcmp(opt, "--id")) {
            a->idarg = val;
        } else if (!strcmp(opt, "--fast-textures")) {
            if (strcmp(val, "ram") && strcmp(val, "flash"))
                return usage_error("bad --fast-textures '%s' (ram or flash)", val);
            fast_in_flash = !strcmp(val, "flash");
        } else if (!strcmp(opt, "--spec-tables")) {
            if (strcmp(val, "ram") && strcmp(val, "flash"))
                return usage_error("bad --spec-tables '%s' (ram or flash)", val);
            spec_in_flash = !strcmp(val, "flash");
        } else if (!strcmp(opt, "--target-work")) {
            char *colon = strchr(val, ':'), *colon2 = colon ? strchr(colon + 1, ':') : NULL;
            int bad_layout = 0;
            if (colon) *colon = 0;
            if (colon2) *colon2 = 0;
            a->target_work = parse_int(val, 0, 0x7fffffffL);
            if (colon) {
                *colon = ':';
                a->target_sibling = parse_int(colon + 1, 0, 0x7fffffffL);
            }
            if (colon2) {
                *colon2 = ':';
                bad_layout = scene_layout_parse(colon2 + 1, &layout) != 0;
                layout_of_target = !bad_layout;
            }
            if (a->target_work < 0 || (colon && a->target_sibling < 0) || bad_layout)
                return usage_error("bad --target-work '%s' (BYTES, BYTES:SIBLING or BYTES:SIBLING:LAYOUT, each byte "
                                   "count 0..2147483647, LAYOUT as tools/scenec/target_work.sh prints it)", val);
        } else if (!strcmp(opt, "--deps")) {
            a->deps = val;
        } else if (!strcmp(opt, "--target")) {
            size_t k, n = sizeof targets / sizeof targets[0];
            const char *names[sizeof targets / sizeof targets[0] + 1];
            for (k = 0; k < n; k++) names[k] = targets[k].name;
            names[n] = NULL;
            for (k = 0; k < n && strcmp(val, targets[k].name); k++) continue;
            if (k == n) {
                const char *near = suggest_nearest(val, names);
                return usage_error("unknown --target '%s'%s%s%s (rp2040, m0plus, m4f, stm32f411 or none)", val,
                                   near ? " (did you mean '" : "", near ? near : "", near ? "'?)" : "");
            }
            a->target = &targets[k];
            a->target_given = 1;
        } else if (!strcmp(opt, "--chosen-scene")) {
            a->chosen_scene = val;
        } else if (!strcmp(opt, "--min-psnr")) {
            if (quality_parse_psnr(val, &a->min_psnr))
                return usage_error("bad --min-psnr '%s' (a PSNR in dB, 1 .. 200)", val);
        } else if (!strcmp(opt, "--ram-budget") || !strcmp(opt, "--flash-budget")) {
            long long b = parse_bytes(val);
            if (b < 0) return usage_error("bad %s '%s' (bytes, optionally with K or M: 1..2047M)", opt, val);
            if (opt[2] == 'r') a->ram_budget = b, a->ram_given = 1;
            else a->flash_budget = b, a->flash_given = 1;
        } else {
            a->outc = val;
        }
    }
    if (!a->outc) return usage_error("-o OUT.c is required (try --help)");
    if (!a->path) return usage_error("a scene file is required (try --help)");
    if (a->strip > a->height) a->strip = a->height;
    return 0;
}

/* The budget of --target (or of the quality block's target), unless given. */
static void set_budget(struct args *a)
{
    if (!a->ram_given) a->ram_budget = a->target->ram;
    if (!a->flash_given) a->flash_budget = a->target->flash;
}

/* An accuracy target (--min-psnr, the scene's quality block): the methods
 * chosen (tools/quality) into *text, the scene parsed again into *s; the
 * report on stdout. 0, or the exit status after the error's line. */
static int choose_methods(struct args *a, char **text, size_t *len, struct scene **s)
{
    struct scene_quality q;
    scene_quality(*s, &q);
    double psnr = a->min_psnr ? a->min_psnr : q.psnr;
    if (!psnr) return 0;
    int target = a->target_given ? quality_target_of(a->target->name) : q.target ? q.target : QUALITY_M0PLUS;
    if (!target) {
        fprintf(stderr, "scenec: no cost model for --target %s: an accuracy target needs m0plus, m4f or rp2040\n",
                a->target->name);
        return 2;
    }
    if (!a->target_given)
        for (size_t k = 0; k < sizeof targets / sizeof targets[0]; k++)
            if (!strcmp(targets[k].name, quality_target_name(target))) a->target = &targets[k];
    struct quality_request rq = { .path = a->path, .text = *text, .len = *len, .width = (unsigned)a->width,
                                  .height = (unsigned)a->height, .strip_rows = (unsigned)a->strip,
                                  .numeric = "fixed", .target = target, .min_psnr = psnr,
                                  .report = stdout, .line = a->min_psnr ? 0 : q.line, .col = a->min_psnr ? 0 : q.col };
    struct quality_choice ch;
    char err[768];
    int rc = quality_choose(&rq, &ch, err, sizeof err);
    if (rc) {
        quality_free(&ch);
        fprintf(stderr, "%s\n", err);
        return rc == QUALITY_EINPUT ? 2 : 1;
    }
    /* --target-work is the scene's as written: it stays only when the chosen
       methods need the same work memory on this host (else this host's, an
       upper bound) */
    if (a->chosen_scene) {
        FILE *f = fopen(a->chosen_scene, "w");
        int bad = !f || fwrite(ch.text, 1, ch.len, f) != ch.len;
        if (f && fclose(f)) bad = 1;
        if (bad) {
            quality_free(&ch);
            fprintf(stderr, "scenec: cannot write %s\n", a->chosen_scene);
            return 1;
        }
    }
    if (a->target_work >= 0 && !a->work_of_choice && strcmp(ch.text, *text)) {
        size_t before = 0, after = 0, sb = 0, sa = 0;
        void *fs = NULL;
        if (!core_api_fixed12.scene_parse(a->path, *text, *len, &fs, err, sizeof err)) {
            before = core_api_fixed12.work_size(fs, (uint16_t)a->width, (uint16_t)a->height, (uint16_t)a->strip);
            sb = core_api_fixed12.sibling_work_size(fs, (uint16_t)a->width, (uint16_t)a->height, (uint16_t)a->strip);
            core_api_fixed12.scene_free(fs);
        }
        if (!core_api_fixed12.scene_parse(a->path, ch.text, ch.len, &fs, err, sizeof err)) {
            after = core_api_fixed12.work_size(fs, (uint16_t)a->width, (uint16_t)a->height, (uint16_t)a->strip);
            sa = core_api_fixed12.sibling_work_size(fs, (uint16_t)a->width, (uint16_t)a->height, (uint16_t)a->strip);
            core_api_fixed12.scene_free(fs);
        }
        if (!before || before != after || sb != sa) {
            printf("quality: the chosen methods change the work memory (this host's %zu bytes, as written %zu): "
                   "this host's sizes, an upper bound, instead of --target-work\n", after, before);
            a->target_work = a->target_sibling = -1;
        }
    }
    free(*text);
    *text = ch.text;
    *len = ch.len;
    scene_free(*s);
    *s = NULL;
    if ((rc = scene_parse_text(a->path, *text, *len, s, err, sizeof err))) {
        fprintf(stderr, "%s\n", err);
        return rc == SCENE_ENOMEM ? 1 : 2;
    }
    return 0;
}

/* The C identifier: --id, or the path under firmware/scenes/ without .scene. */
static void make_id(const struct args *a, char *id, size_t size)
{
    const char *base = a->idarg;
    if (!base) base = strstr(a->path, "scenes/") ? strstr(a->path, "scenes/") + 7 : a->path;
    size_t k = 0;
    for (const char *c = base; *c && k < size - 1; c++) {
        if (!a->idarg && !strcmp(c, ".scene")) break;
        id[k++] = (char)((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') ? *c : '_');
    }
    id[k] = 0;
}

/* ---- steps ------------------------------------------------------------------- */

/* The scene's ranges and the number format, printed: 0, or 2 when no format holds it. */
static int analyse(const struct args *a, const struct scene *s, struct scene_format *F)
{
    char err[600];
    int refused = scene_format_choose(s, a->width, a->height, a->fracs, a->nfracs, a->allow_wide, F);
    printf("scenec: %s: %s scene \"%s\", %d objects, %d lights, %d models, %d instances, %d textures, %d frames\n",
           a->path, s->kind == SCENE_RAYTRACE ? "ray-traced" : "rasterized", s->name, s->nobjects, s->nlights,
           s->nmodels, s->ninstances, s->ntextures, s->frames);
    scene_format_print_ranges(stdout, F);
    if (refused) {
        scene_format_refusal(F, a->path, "--allow-wide", err, sizeof err);
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    scene_format_print_argument(stdout, F);
    unsigned fits = scene_format_fits(F, F->num_frac);
    if (fits)
        printf("  32-bit products (no saturation checks, struct scene.fits = %u):%s%s\n", fits,
               fits & SCENE_FITS_COLOUR ? " colour intermediates" : "",
               fits & SCENE_FITS_HIT ? ", hit points D t" : "");
    if (s->kind == SCENE_RASTER && s->ninstances && !s->ras.book_exact && s->ras.depth_test) {
        struct scene_depth_facts f;
        int bits = scene_depth_bits(s, &f);
        if (bits < 0) {
            fprintf(stderr, "scenec: out of memory (the depth analysis)\n");
            return 2;
        }
        printf("  depth buffer: %d bits a pixel%s: a 16-bit step of near/z at the farthest depth %.3g is %.3g,\n"
               "    %s 1/256 of the smallest instance radius (%.3g)\n",
               s->ras.depth_bits, s->ras.depth_bits == bits ? " (chosen)" : " (as the scene asks)", f.far, f.step16,
               f.range_wants32 ? "more than" : "within", f.rmin);
        if (f.overlap_checked)
            printf("    overlapping surfaces less than two 16-bit steps apart: at most %ld pixels a frame (frame %d;"
                   " %d frames checked at %dx%d), %s the limit %ld\n",
                   f.close_pixels, f.close_frame, f.frames_checked, f.grid_w, f.grid_h,
                   f.overlap_wants32 ? "over" : "within", f.close_limit);
        if (f.overlap_checked && f.close_pixels)
            printf("    the closest such gap: %.3g of near/z (%.2f 16-bit steps)\n", f.gap_min, f.gap_min * 65536.0);
    }
    return 0;
}

/* Fast Phong's specular tables of every format from SCENE_FORMAT_FRAC_MIN
 * to frac, each made by that format's core from the scene's text (the
 * exponents as that core reads them): spec_sets, spec_frac_max. 0, or the
 * exit status after the error's line. */
static int make_spec_tables(const struct args *a, const char *text, size_t len, int frac)
{
    spec_frac_max = SCENE_FORMAT_FRAC_MIN - 1;
    if (!spec_in_flash) return 0;
    for (int f = SCENE_FORMAT_FRAC_MIN; f <= frac; f++) {
        const struct core_api *api = core_api_fixed_frac(f);
        struct spec_set *t = &spec_sets[f - SCENE_FORMAT_FRAC_MIN];
        char err[600];
        void *fs = NULL;
        if (!api || api->scene_parse(a->path, text, len, &fs, err, sizeof err)) {
            fprintf(stderr, "%s\n", api ? err : "scenec: no fixed-point core of that format");
            return 2;
        }
        t->n = api->spec_exponents(fs, t->exps);
        api->scene_free(fs);
        for (int k = 0; k < t->n; k++) api->spec_table(t->tab + 257 * k, t->exps[k], t->step + 2 * k);
        /* every format the same exponents (else none: render_init makes them) */
        if (!t->n || t->n != spec_sets[0].n || memcmp(t->exps, spec_sets[0].exps, sizeof t->exps[0] * t->n)) return 0;
    }
    spec_frac_max = frac;
    return 0;
}

/* The renderer's work memory: *work the target's (--target-work) or else the
 * fixed-point core's on this host, *host_work the latter; *sibling the same
 * of the second core's context. 0, or 2. */
static int work_sizes(const struct args *a, const struct scene *s, const char *text, size_t len, size_t *work,
                      size_t *host_work, size_t *sibling)
{
    char err[600];
    void *fs = NULL;
    if (core_api_fixed12.scene_parse(a->path, text, len, &fs, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    *host_work = core_api_fixed12.work_size(fs, (uint16_t)a->width, (uint16_t)a->height, (uint16_t)a->strip);
    size_t fast_copies = 0;   /* the work the fast texels in flash save (the same bytes on the target) */
    if (fast_in_flash && s->ntextures) {
        static const char mark;   /* (a non-NULL entry: the texture's texels are in flash) */
        const void **marks = calloc(s->ntextures, sizeof *marks);
        if (!marks) {
            core_api_fixed12.scene_free(fs);
            fprintf(stderr, "scenec: out of memory\n");
            return 1;
        }
        for (int i = 0; i < s->ntextures; i++) marks[i] = fast_tex(&s->textures[i]) ? &mark : NULL;
        core_api_fixed12.set_tex_fast(fs, marks);
        size_t w = core_api_fixed12.work_size(fs, (uint16_t)a->width, (uint16_t)a->height, (uint16_t)a->strip);
        core_api_fixed12.set_tex_fast(fs, NULL);
        free(marks);
        fast_copies = *host_work - w;
        *host_work = w;
    }
    spec_copies = 0;
    if (spec_frac_max >= SCENE_FORMAT_FRAC_MIN) {
        /* (the format-12 core's tables: the sizes are every format's) */
        const struct spec_set *t = &spec_sets[12 - SCENE_FORMAT_FRAC_MIN];
        size_t before = core_api_fixed12.work_size(fs, (uint16_t)a->width, (uint16_t)a->height, (uint16_t)a->strip);
        core_api_fixed12.set_spec_tables(fs, t->n, t->tab, t->step);
        size_t w = core_api_fixed12.work_size(fs, (uint16_t)a->width, (uint16_t)a->height, (uint16_t)a->strip);
        core_api_fixed12.set_spec_tables(fs, 0, NULL, NULL);
        spec_copies = before - w;
        fast_copies += spec_copies;
        *host_work -= spec_copies;
    }
    scene_features = core_api_fixed12.features(fs);
    size_t host_sibling = core_api_fixed12.sibling_work_size(fs, (uint16_t)a->width, (uint16_t)a->height,
                                                             (uint16_t)a->strip);
    core_api_fixed12.scene_free(fs);
    *sibling = a->target_sibling >= 0 ? (size_t)a->target_sibling : host_sibling;
    if (a->target_sibling > (long)host_sibling) {
        fprintf(stderr, "%s:1:1: error: --target-work sibling size %ld exceeds this host's %zu; the probe image is "
                        "stale or for another scene\n", a->path, a->target_sibling, host_sibling);
        return 2;
    }
    *work = a->target_work >= 0 ? (size_t)a->target_work - fast_copies : *host_work;
    if (a->target_work >= 0 && (size_t)a->target_work - fast_copies > *host_work) {
        /* the target's structures are never larger than the host's */
        fprintf(stderr, "%s:1:1: error: --target-work %ld exceeds this host's work size %zu; the probe image is "
                        "stale or for another scene\n", a->path, a->target_work, *host_work);
        return 2;
    }
    return 0;
}

static void write_header(FILE *h, const struct args *a, const char *id, int frac, size_t work, size_t sibling)
{
    char ID[256];
    upper(ID, id);
    size_t strip_bytes = (size_t)a->width * a->strip * 2;
    fprintf(h, "/* scene_%s.h — generated by tools/scenec from %s; do not edit.\n *\n"
               " * Checked for the fixed-point core at NUM_FRAC <= %d, a %dx%d frame in strips of %d rows.\n"
               " * RAM: scene_%s_work (SCENE_%s_WORK_SIZE bytes, for render_init) plus the caller's\n"
               " * strip buffer (SCENE_%s_STRIP_BYTES = width x strip rows x 2 bytes of RGB565); a\n"
               " * second core's context (render_init_sibling) SCENE_%s_SIBLING_WORK_SIZE bytes.\n */\n",
            id, a->path, frac, a->width, a->height, a->strip, id, ID, ID, ID);
    fprintf(h, "#ifndef SCENE_%s_H\n#define SCENE_%s_H\n\n#include <stdint.h>\n#include \"scene.h\"\n\n", ID, ID);
    fprintf(h, "#define SCENE_%s_NUM_FRAC   %d\n#define SCENE_%s_WIDTH      %d\n#define SCENE_%s_HEIGHT     %d\n"
               "#define SCENE_%s_STRIP_ROWS %d\n#define SCENE_%s_WORK_SIZE  %zu\n#define SCENE_%s_STRIP_BYTES %zu\n"
               "#define SCENE_%s_SIBLING_WORK_SIZE %zu\n\n",
            ID, frac, ID, a->width, ID, a->height, ID, a->strip, ID, work, ID, strip_bytes, ID, sibling);
    if (spec_copies)
        fprintf(h, "/* float and double cores make fast Phong's specular tables in work memory */\n"
                   "#if NUM_MODE != NUM_MODE_FIXED\n#undef SCENE_%s_WORK_SIZE\n#define SCENE_%s_WORK_SIZE (%zu + %zu)\n"
                   "#endif\n\n", ID, ID, work, spec_copies);
    /* the renderer features it needs: one line each (0 or 1), which an
     * image's header merges over its scenes (tools/scenec/features.sh) */
    fprintf(h, "/* the renderer features it needs (firmware/core/scene_features.def, render_features) */\n");
    fprintf(h, "#define SCENE_%s_FEATURES 0x%08lxu\n", ID, (unsigned long)scene_features);
    for (int k = 0; k < RENDER_FEATURE_COUNT; k++)
        fprintf(h, "#define SCENE_%s_FEATURE_%s %d\n", ID, feature_names[k], (int)(scene_features >> k & 1u));
    fprintf(h, "\nextern const struct scene scene_%s;\nextern uint8_t scene_%s_work[];\n\n#endif\n", id, id);
}

/* OUT.h, then OUT.c, each complete before either replaces the old one: 0,
 * 1 (an output cannot be written) or 2 (OUT does not end in .c). */
static int write_outputs(const struct args *a, const struct scene *s, const char *id, int frac, unsigned fits,
                         size_t work, size_t sibling)
{
    static char outh[1024];
    snprintf(outh, sizeof outh, "%s", a->outc);
    size_t n = strlen(outh);
    if (n < 3 || strcmp(outh + n - 2, ".c")) {
        fprintf(stderr, "scenec: output must end in .c\n");
        return 2;
    }
    outh[n - 1] = 'h';
    outh_path = outh;
    FILE *h = tmp_create(0, outh);
    if (!h) {
        fprintf(stderr, "scenec: cannot write %s\n", outh);
        return 1;
    }
    write_header(h, a, id, frac, work, sibling);
    int herr = ferror(h);
    if (fclose(h) || herr) {
        fprintf(stderr, "scenec: error writing %s\n", outh);
        tmp_discard();
        return 1;
    }
    out = tmp_create(1, a->outc);
    if (!out) {
        fprintf(stderr, "scenec: cannot write %s\n", a->outc);
        tmp_discard();
        return 1;
    }
    target_work_given = a->target_work >= 0;
    emit_oom = 0;
    emit_scene(s, id, a->path, frac, fits, a->width, a->height, a->strip);
    int cerr = ferror(out);
    if (emit_oom) {
        fclose(out);
        fprintf(stderr, "scenec: out of memory (a texture's fast texels)\n");
        tmp_discard();
        return 1;
    }
    if (fclose(out) || cerr || rename(tmp_path[0], outh) || (tmp_live[0] = 0, rename(tmp_path[1], a->outc))) {
        fprintf(stderr, "scenec: error writing %s\n", a->outc);
        tmp_discard();
        return 1;
    }
    tmp_live[1] = 0;
    return 0;
}

/* The scene against the budget (--target, --ram-budget, --flash-budget),
 * before anything is written: the flash its const data takes (a dry run of
 * the emission, at the target's sizes or this host's fixed-point build's, an
 * upper bound of the target's: layout) and the
 * RAM of its work memory. 0, or 2 after one line naming the need, the budget
 * and the option. */
static int check_budget(const struct args *a, const struct scene *s, const char *id, int frac, unsigned fits,
                        size_t work, size_t sibling)
{
    flash_bytes = texture_bytes = 0;
    out = NULL;
    outh_path = NULL;
    emit_scene(s, id, a->path, frac, fits, a->width, a->height, a->strip);
    size_t flash = flash_bytes;
    const char *tname = a->target->name;
    unsigned long long ram = (unsigned long long)work + (a->target->sibling ? sibling : 0);
    if (a->ram_budget >= 0 && ram > (unsigned long long)a->ram_budget) {
        char sib[64] = "";
        if (a->target->sibling) snprintf(sib, sizeof sib, " + %zu of a second core's context", sibling);
        if (a->ram_given)
            return usage_error("%s: needs %llu bytes of RAM at %dx%d (renderer work memory %zu%s), over the RAM budget "
                               "of %lld bytes (--ram-budget)", a->path, ram, a->width, a->height, work, sib,
                               a->ram_budget);
        return usage_error("%s: needs %llu bytes of RAM at %dx%d (renderer work memory %zu%s), over the %s RAM budget "
                           "of %lld bytes (--ram-budget or --target to change it)", a->path, ram, a->width, a->height,
                           work, sib, tname, a->ram_budget);
    }
    if (a->flash_budget >= 0 && flash > (unsigned long long)a->flash_budget) {
        if (a->flash_given)
            return usage_error("%s: needs %zu bytes of flash (the scene's const data, %zu of them textures), over the "
                               "flash budget of %lld bytes (--flash-budget)", a->path, flash, texture_bytes,
                               a->flash_budget);
        return usage_error("%s: needs %zu bytes of flash (the scene's const data, %zu of them textures), over the %s "
                           "flash budget of %lld bytes (--flash-budget or --target to change it)", a->path, flash,
                           texture_bytes, tname, a->flash_budget);
    }
    flash_bytes = texture_bytes = 0;
    return 0;
}

int main(int argc, char **argv)
{
    struct args a;
    int prc = parse_args(argc, argv, &a);
    if (prc) return prc < 0 ? 0 : prc;

    char err[600];
    struct scene *s = NULL;
    if ((prc = check_dest("-o", a.outc)) || (a.deps && (prc = check_dest("--deps", a.deps)))) return prc;
    /* read once (a FIFO or /dev/stdin), parsed by the double and the fixed core */
    char *text;
    size_t text_len;
    int rc = scene_read_text(a.path, &text, &text_len, err, sizeof err);
    if (rc) {
        fprintf(stderr, "%s\n", err);
        return rc == SCENE_ENOMEM ? 1 : 2;
    }
    if ((rc = scene_parse_text(a.path, text, text_len, &s, err, sizeof err))) {
        fprintf(stderr, "%s\n", err);
        free(text);
        return rc == SCENE_ENOMEM ? 1 : 2;
    }
    if ((rc = check_outputs(a.outc, a.deps, a.path)) || (rc = choose_methods(&a, &text, &text_len, &s))) {
        scene_free(s);
        free(text);
        return rc;
    }
    set_budget(&a);
    char id[256];
    make_id(&a, id, sizeof id);

    /* ranges, and the number format (tools/scene/scene_format.c) */
    struct scene_format F;
    size_t work = 0, host_work = 0, sibling = 0;
    rc = analyse(&a, s, &F);
    if (!rc) rc = make_spec_tables(&a, text, text_len, F.num_frac);
    if (!rc) rc = work_sizes(&a, s, text, text_len, &work, &host_work, &sibling);
    free(text);
    if (!rc && scene_given_zero(s, F.num_frac, a.path, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        rc = 2;
    }
    if (!rc) rc = check_budget(&a, s, id, F.num_frac, scene_format_fits(&F, F.num_frac), work, sibling);
    if (!rc && a.deps) rc = write_deps(a.deps, a.outc, a.path);
    if (!rc) rc = write_outputs(&a, s, id, F.num_frac, scene_format_fits(&F, F.num_frac), work, sibling);
    if (rc) {
        scene_free(s);
        return rc;
    }
    int frac = F.num_frac;
    size_t strip_bytes = (size_t)a.width * a.strip * 2;
    char budget[160];
    if (a.ram_budget < 0 && a.flash_budget < 0) snprintf(budget, sizeof budget, "no budget (--target none)");
    else
        snprintf(budget, sizeof budget, "the budget (%s, %s): RAM %lld, flash %lld bytes", a.target->name,
                 a.target->what, a.ram_budget, a.flash_budget);
    printf("  memory: RAM %zu bytes of work (%s; this host's core: %zu) + %zu bytes of strip (%dx%d, %d rows);\n"
           "    a second core's context (render_init_sibling) %zu bytes more;\n"
           "    flash: the const data of %s, %zu bytes (%zu of textures; %s);\n"
           "    %s\n",
           work, a.target_work >= 0 ? "the target's render_work_size" : "this host's render_work_size, an upper bound",
           host_work, strip_bytes, a.width, a.height, a.strip, sibling, a.outc, flash_bytes, texture_bytes,
           layout_of_target ? "the target's sizes" : "this host's fixed-point sizes, an upper bound", budget);
    char feats[600] = "";
    for (int k = 0, n = 0; k < RENDER_FEATURE_COUNT; k++)
        if (scene_features >> k & 1u)
            n += snprintf(feats + n, sizeof feats - (size_t)n, "%s%s", n ? "," : "", feature_names[k]);
    printf("  renderer features: %s (firmware/core/scene_features.def)\n", feats[0] ? feats : "none");
    printf("scenec-summary id=%s num_frac=%d work=%zu host_work=%zu target=%d strip=%zu sibling=%zu flash=%zu "
           "features=%s\n", id, frac, work, host_work, a.target_work >= 0, strip_bytes, sibling, flash_bytes,
           feats[0] ? feats : "none");
    scene_free(s);
    return 0;
}
