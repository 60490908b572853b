/* SPDX-License-Identifier: MIT */
/* quality.c — methods chosen for an accuracy target (quality.h). */
#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core_api.h"
#include "quality.h"

/* ---- the cost model (tools/quality/cost_model.def) -------------------------- */

struct base_row {
    const char *target, *cls, *numeric;
    double per_work;
    int scenes;
};
struct method_row {
    const char *target, *cls, *numeric, *options;
    double factor;
    int scenes;
};

static const struct base_row base_rows[] = {
#define QUALITY_BASE(target, cls, numeric, per_work, scenes) { target, cls, numeric, per_work, scenes },
#include "cost_model.def"
};
static const struct method_row method_rows[] = {
#define QUALITY_METHOD(target, cls, numeric, options, factor, scenes) { target, cls, numeric, options, factor, scenes },
#include "cost_model.def"
};
struct shading_row {
    const char *cls, *shading;
};
static const struct shading_row shading_rows[] = {
#define QUALITY_SHADING(cls, shading) { cls, shading },
#include "cost_model.def"
};
/* Classes whose candidates are predicted from their own work (each one
 * rendered first): per_work x (its work + factor x its pixels). */
static const char *const own_work_classes[] = {
#define QUALITY_OWN_WORK(cls) cls,
#include "cost_model.def"
    NULL
};
#define NROWS(a) (sizeof(a) / sizeof((a)[0]))

static int own_work(const char *cls)
{
    for (size_t i = 0; own_work_classes[i]; i++)
        if (!strcmp(own_work_classes[i], cls)) return 1;
    return 0;
}

static const struct base_row *base_row(const char *target, const char *cls, const char *numeric)
{
    for (size_t i = 0; i < NROWS(base_rows); i++)
        if (!strcmp(base_rows[i].target, target) && !strcmp(base_rows[i].cls, cls) &&
            !strcmp(base_rows[i].numeric, numeric))
            return &base_rows[i];
    return NULL;
}

static const struct method_row *method_row(const char *target, const char *cls, const char *numeric,
                                           const char *options)
{
    for (size_t i = 0; i < NROWS(method_rows); i++)
        if (!strcmp(method_rows[i].target, target) && !strcmp(method_rows[i].cls, cls) &&
            !strcmp(method_rows[i].numeric, numeric) && !strcmp(method_rows[i].options, options))
            return &method_rows[i];
    return NULL;
}

/* What a unit of work costs more (or less) for a scene shaded `shading`
 * (cost_model.py lighting): a textured class's lab scenes are shaded one
 * way (QUALITY_SHADING); a scene shaded otherwise has the lit class's
 * per-pixel lighting added or taken out, whatever the method: the lit
 * class's cost per unit of work times its factor for the scene's shading
 * less its factor for the class's (none counts as flat, lit per triangle).
 * mt: the target of the method rows. */
static double lighting_per_work(const struct base_row *base, const char *mt, const char *shading)
{
    const char *cs = NULL;
    for (size_t i = 0; i < NROWS(shading_rows); i++)
        if (!strcmp(shading_rows[i].cls, base->cls)) cs = shading_rows[i].shading;
    if (!cs || !strcmp(cs, shading)) return 0;
    char a[80], b[80]; /* "shading=" and a value (PART bytes, below) */
    snprintf(a, sizeof a, "shading=%s", strcmp(shading, "none") ? shading : "flat");
    snprintf(b, sizeof b, "shading=%s", strcmp(cs, "none") ? cs : "flat");
    const struct base_row *lit = base_row(base->target, "lit", base->numeric);
    const struct method_row *fa = method_row(mt, "lit", base->numeric, a), *fb = method_row(mt, "lit", base->numeric, b);
    return lit && fa && fb ? lit->per_work * (fa->factor - fb->factor) : 0;
}

static const char *const target_names[] = { "m0plus", "m4f", "rp2040" };

const char *quality_target_name(int target)
{
    return target >= 1 && target <= 3 ? target_names[target - 1] : NULL;
}

int quality_target_of(const char *name)
{
    for (int i = 0; i < 3; i++)
        if (!strcmp(name, target_names[i])) return i + 1;
    return 0;
}

int quality_parse_psnr(const char *s, double *db)
{
    char *end;
    if (!*s || isspace((unsigned char)*s)) return -1;
    double v = strtod(s, &end);
    if (*end || !(v >= 1 && v <= 200)) return -1;
    *db = v;
    return 0;
}

/* ---- scene text: tokens, blocks, options (tools/charts/scenetext.py) ---------- */

struct tok {
    size_t a, b;
};

static int is_punct(char c) { return c == '{' || c == '}' || c == '(' || c == ')' || c == '=' || c == ',' || c == ';'; }

/* Every significant token (no blanks or comments): count, or -1 (memory). */
static long tokens(const char *t, size_t n, struct tok **out)
{
    size_t cap = 256, k = 0, i = 0;
    struct tok *v = malloc(cap * sizeof *v);
    if (!v) return -1;
    while (i < n) {
        size_t s = i;
        char c = t[i];
        if (isspace((unsigned char)c)) {
            i++;
            continue;
        }
        if (c == '#' || (c == '/' && i + 1 < n && t[i + 1] == '/')) {
            while (i < n && t[i] != '\n') i++;
            continue;
        }
        if (c == '"') {
            i++;
            while (i < n && t[i] != '"' && t[i] != '\n') i++;
            if (i < n && t[i] == '"') i++;
        } else if (is_punct(c)) {
            i++;
        } else {
            while (i < n && !isspace((unsigned char)t[i]) && !is_punct(t[i]) && t[i] != '#' && t[i] != '"') i++;
        }
        if (k == cap) {
            struct tok *w = realloc(v, 2 * cap * sizeof *v);
            if (!w) return free(v), -1;
            v = w;
            cap *= 2;
        }
        v[k].a = s;
        v[k].b = i;
        k++;
    }
    *out = v;
    return (long)k;
}

static int tok_is(const char *t, const struct tok *k, const char *s)
{
    size_t n = strlen(s);
    return k->b - k->a == n && !memcmp(t + k->a, s, n);
}

static int tok_open(const char *t, const struct tok *k) { return tok_is(t, k, "{") || tok_is(t, k, "("); }
static int tok_close(const char *t, const struct tok *k) { return tok_is(t, k, "}") || tok_is(t, k, ")"); }

/* The next top-level NAME block from token *i on: its braces' token indices
 * in *open and *close; 0, or -1 when there is none. */
static int next_block(const char *t, const struct tok *v, long n, long *i, const char *name, long *open, long *close)
{
    int depth = 0;
    for (; *i < n; (*i)++) {
        if (tok_open(t, &v[*i])) depth++;
        else if (tok_close(t, &v[*i])) depth--;
        else if (depth == 0 && tok_is(t, &v[*i], name)) {
            long j = *i + 1;
            if (j < n && tok_is(t, &v[j], "=")) j++;
            if (j >= n || !tok_is(t, &v[j], "{")) continue;
            int d = 0;
            long k = j;
            for (; k < n; k++) {
                if (tok_open(t, &v[k])) d++;
                else if (tok_close(t, &v[k]) && --d == 0) break;
            }
            if (k == n) return -1;
            *open = j;
            *close = k;
            *i = k + 1;
            return 0;
        }
    }
    return -1;
}

/* The value token of KEY directly inside the block (open, close): its index, or -1. */
static long key_in_block(const char *t, const struct tok *v, long open, long close, const char *key)
{
    int depth = 0;
    for (long i = open + 1; i < close; i++) {
        if (tok_open(t, &v[i])) depth++;
        else if (tok_close(t, &v[i])) depth--;
        else if (depth == 0 && tok_is(t, &v[i], key) && i + 2 < close && tok_is(t, &v[i + 1], "="))
            return i + 2;
    }
    return -1;
}

static char *splice(const char *t, size_t n, size_t a, size_t b, const char *ins, size_t *outlen)
{
    size_t m = strlen(ins), len = n - (b - a) + m;
    char *r = malloc(len + 1);
    if (!r) return NULL;
    memcpy(r, t, a);
    memcpy(r + a, ins, m);
    memcpy(r + a + m, t + b, n - b);
    r[len] = 0;
    *outlen = len;
    return r;
}

#define PART 64

/* Copies n bytes of src into dst (PART bytes) as a string: 0, or -1 when they do not fit. */
static int part(char *dst, const char *src, size_t n)
{
    if (n == 0 || n >= PART) return -1;
    memcpy(dst, src, n);
    dst[n] = 0;
    return 0;
}

/* An option's parts (each PART bytes): BLOCK (the renderer's when not
 * given), KEY, VALUE; -1 when malformed. */
static int option_parts(const char *opt, const char *renderer, char *block, char *key, char *value)
{
    const char *eq = strchr(opt, '=');
    if (!eq || part(value, eq + 1, strlen(eq + 1))) return -1;
    for (const char *c = value; *c; c++)
        if (!isalnum((unsigned char)*c) && !strchr("_.+-", *c)) return -1;
    const char *dot = memchr(opt, '.', (size_t)(eq - opt));
    if (dot) return part(block, opt, (size_t)(dot - opt)) || part(key, dot + 1, (size_t)(eq - dot - 1)) ? -1 : 0;
    return part(block, renderer, strlen(renderer)) || part(key, opt, (size_t)(eq - opt)) ? -1 : 0;
}

char *quality_set_option(const char *text, size_t len, const char *renderer, const char *opt, size_t *outlen)
{
    char block[PART], key[PART], value[PART];
    if (option_parts(opt, renderer, block, key, value)) return NULL;
    struct tok *v;
    long n = tokens(text, len, &v);
    if (n < 0) return NULL;
    long i = 0, open, close, opens[64], closes[64];
    int nb = 0;
    while (nb < 64 && !next_block(text, v, n, &i, block, &open, &close)) {
        opens[nb] = open;
        closes[nb++] = close;
    }
    char *r = NULL;
    if (nb == 0) {
        if (strcmp(block, renderer)) return free(v), NULL;
        char add[200];
        snprintf(add, sizeof add, "\n%s { %s = %s }\n", block, key, value);
        size_t e = len;
        while (e > 0 && text[e - 1] == '\n') e--;
        r = splice(text, len, e, len, add, outlen);
    } else {
        /* from the last block back, so that the earlier offsets stay valid */
        char *cur = NULL;
        size_t curlen = len;
        const char *src = text;
        for (int b = nb - 1; b >= 0; b--) {
            long at = key_in_block(text, v, opens[b], closes[b], key);
            char ins[200];
            char *next;
            if (at >= 0 && !tok_open(text, &v[at]) && !tok_close(text, &v[at])) {
                snprintf(ins, sizeof ins, "%s", value);
                next = splice(src, curlen, v[at].a, v[at].b, ins, &curlen);
            } else {
                snprintf(ins, sizeof ins, " %s = %s", key, value);
                next = splice(src, curlen, v[opens[b]].b, v[opens[b]].b, ins, &curlen);
            }
            free(cur);
            cur = next;
            src = cur;
            if (!cur) break;
        }
        r = cur;
        *outlen = curlen;
    }
    free(v);
    return r;
}

/* The value the scene itself gives an option's key (into val), 1; 0 when it
 * gives none (every BLOCK block looked at for BLOCK.KEY). */
static int scene_sets(const char *text, size_t len, const char *renderer, const char *opt, char *val, size_t sz)
{
    char block[PART], key[PART], value[PART];
    if (option_parts(opt, renderer, block, key, value)) return 0;
    struct tok *v;
    long n = tokens(text, len, &v);
    if (n < 0) return 0;
    long i = 0, open, close;
    int found = 0;
    while (!found && !next_block(text, v, n, &i, block, &open, &close)) {
        long at = key_in_block(text, v, open, close, key);
        if (at >= 0) {
            snprintf(val, sz, "%.*s", (int)(v[at].b - v[at].a), text + v[at].a);
            found = 1;
        }
    }
    free(v);
    return found;
}

/* ---- renders ------------------------------------------------------------------- */

#define QUALITY_FRAMES 16

struct frames {
    unsigned n, f[QUALITY_FRAMES];
};

/* Every frame of a scene of up to QUALITY_FRAMES, else QUALITY_FRAMES
 * evenly spaced ones, the first and the last among them. */
static void pick_frames(unsigned total, struct frames *fr)
{
    if (total <= QUALITY_FRAMES) {
        fr->n = total ? total : 1;
        for (unsigned i = 0; i < fr->n; i++) fr->f[i] = i;
        return;
    }
    fr->n = QUALITY_FRAMES;
    for (unsigned i = 0; i < QUALITY_FRAMES; i++)
        fr->f[i] = (unsigned)((unsigned long long)i * (total - 1) / (QUALITY_FRAMES - 1));
}

struct render_out {
    uint8_t *rgb; /* fr.n frames of w*h*3 */
    double work;  /* the render's work a frame (see quality.h) */
    int num_frac;
};

/* The text in numeric mode (fixed: its own format) rendered at the frames
 * of fr into out->rgb (exact: the exact methods); 0, -1 (the scene does not
 * load or fit at that mode: msg), -2 (memory). */
static int render_text(const struct quality_request *rq, const char *text, size_t len, const char *numeric,
                       int exact, const struct frames *fr, struct render_out *out, char *msg, size_t msglen)
{
    const struct core_api *api = core_api_by_name(numeric);
    unsigned fits = 0;
    unsigned w = rq->width, h = rq->height, rows = rq->strip_rows;
    void *scene = NULL;
    out->num_frac = 0;
    if (!strcmp(numeric, "fixed")) {
        struct scene_format f;
        if (core_api_double.scene_parse(rq->path, text, len, &scene, msg, msglen)) return -1;
        int rc = core_api_double.format(scene, rq->path, (uint16_t)w, (uint16_t)h, &f, msg, msglen);
        core_api_double.scene_free(scene);
        scene = NULL;
        if (rc) return -1;
        api = core_api_fixed_frac(f.num_frac);
        fits = scene_format_fits(&f, f.num_frac);
        out->num_frac = f.num_frac;
    }
    if (!api) return snprintf(msg, msglen, "no core for %s", numeric), -1;
    if (api->scene_parse(rq->path, text, len, &scene, msg, msglen)) return -1;
    api->set_fits(scene, fits);
    if (exact) api->exact_methods(scene);
    struct scene_info info;
    api->scene_info(scene, &info);
    size_t npx = (size_t)w * h, ws = api->work_size(scene, (uint16_t)w, (uint16_t)h, (uint16_t)rows);
    void *work = malloc(ws ? ws : 1);
    uint16_t *fb = malloc(npx * sizeof *fb);
    int rc = work && fb ? 0 : -2;
    struct render_ctx ctx;
    double work_sum = 0;
    if (!rc && api->init(&ctx, scene, (uint16_t)w, (uint16_t)h, (uint16_t)rows, work, ws)) {
        snprintf(msg, msglen, "the renderer refused %ux%u", w, h);
        rc = -1;
    }
    for (unsigned k = 0; k < fr->n && !rc; k++) {
        struct render_stats st = { 0 };
        uint8_t *rgb = out->rgb + k * npx * 3;
        uint32_t shadow0 = api->shadow_rays(&ctx);
        if (api->begin_frame(&ctx, (uint16_t)fr->f[k])) {
            snprintf(msg, msglen, "frame %u failed", fr->f[k]);
            rc = -1;
        }
        for (unsigned y0 = 0; y0 < h && !rc; y0 += rows) {
            unsigned y1 = y0 + rows < h ? y0 + rows : h;
            struct render_target t = { .width = (uint16_t)w, .height = (uint16_t)h, .y0 = (uint16_t)y0, .y1 = (uint16_t)y1, .rgb565 = fb + (size_t)y0 * w, .rgb888 = rgb + (size_t)y0 * w * 3 };
            if (api->render_strip(&ctx, &t, &st)) {
                snprintf(msg, msglen, "rows %u..%u of frame %u failed", y0, y1, fr->f[k]);
                rc = -1;
            }
        }
        /* the ray tracer's every ray: primary, reflected and shadow rays */
        uint32_t shadow = api->shadow_rays(&ctx) - shadow0;
        work_sum += info.kind == SCENE_RAYTRACE
                        ? ((double)st.rays + (double)shadow) * (info.nobjects > 1 ? info.nobjects : 1)
                        : (double)st.pixels_written;
    }
    out->work = work_sum / fr->n;
    free(work);
    free(fb);
    api->scene_free(scene);
    return rc;
}

/* PSNR of two w*h RGB888 images over the three 8-bit channels, as host_sim
 * --compare measures it (host_sim/compare.c); INFINITY when identical. */
static double psnr888(const uint8_t *a, const uint8_t *b, size_t npx)
{
    double se = 0;
    for (size_t i = 0; i < 3 * npx; i++) {
        double d = (double)a[i] - (double)b[i];
        se += d * d;
    }
    return se == 0 ? INFINITY : 10.0 * log10(255.0 * 255.0 * 3.0 * (double)npx / se);
}

/* ---- the choice ------------------------------------------------------------------ */

struct cand {
    const struct method_row *m;
    double predicted, psnr;
    double work; /* its render's work a frame (ray tracer: the unit of its cost) */
    unsigned worst_frame;
    int num_frac, failed; /* failed: did not render (msg) */
    char msg[200];
};

static int by_cost(const void *a, const void *b)
{
    const struct cand *x = a, *y = b;
    if (x->predicted != y->predicted) return x->predicted < y->predicted ? -1 : 1;
    return strcmp(x->m->options, y->m->options);
}

static const char *class_of(const struct scene_info *in)
{
    if (in->kind == SCENE_RAYTRACE) return in->reflective ? "rt-reflective" : "rt";
    if (in->shadows) return "shadows";
    if (in->textured) return in->npot_texture ? "textured-npot" : "textured";
    return "lit";
}

static void fmt_cost(char *buf, size_t n, double c, int target)
{
    const char *unit = target == QUALITY_RP2040 ? "cycles" : "instructions";
    if (c >= 1e6) snprintf(buf, n, "%.1f M %s", c / 1e6, unit);
    else snprintf(buf, n, "%.0f %s", c, unit);
}

static void fmt_db(char *buf, size_t n, double db)
{
    if (isinf(db)) snprintf(buf, n, "identical");
    else snprintf(buf, n, "%.1f dB", db);
}

/* The options of a candidate the scene does not already set so, into out (n bytes). */
static void changed(const struct quality_request *rq, const char *renderer, const char *options, char *out, size_t n)
{
    char opts[256], *save = NULL, val[PART];
    size_t k = 0;
    out[0] = 0;
    snprintf(opts, sizeof opts, "%s", options);
    for (char *o = strtok_r(opts, " ", &save); o; o = strtok_r(NULL, " ", &save)) {
        if (scene_sets(rq->text, rq->len, renderer, o, val, sizeof val) && !strcmp(val, strchr(o, '=') + 1)) continue;
        int w = snprintf(out + k, n - k, "%s%s", k ? " " : "", o);
        if (w < 0 || (size_t)w >= n - k) break;
        k += (size_t)w;
    }
}

static const char *shown(const char *options) { return *options ? options : "(the scene as written)"; }

/* The scene text with every option of `options` set, one after the other
 * (malloc'd; NULL: an option cannot be set, or memory), *len its length. */
static char *cand_text(const struct quality_request *rq, const char *renderer, const char *options, size_t *len)
{
    char opts[256], *save = NULL, *t = NULL;
    size_t tl = rq->len;
    snprintf(opts, sizeof opts, "%s", options);
    for (char *p = strtok_r(opts, " ", &save); p; p = strtok_r(NULL, " ", &save)) {
        char *n = quality_set_option(t ? t : rq->text, t ? tl : rq->len, renderer, p, &tl);
        free(t);
        t = n;
        if (!n) return NULL;
    }
    if (!t) { /* no option: the scene as written */
        t = malloc(rq->len + 1);
        if (!t) return NULL;
        memcpy(t, rq->text, rq->len);
        t[rq->len] = 0;
    }
    *len = tl;
    return t;
}

/* Candidate x rendered in the request's mode (into got) and measured
 * against ref: its lowest PSNR over the frames checked, that frame, its
 * format and its work; x->failed with x->msg when it cannot be set or does
 * not render. *text (when text is not NULL): its scene text (NULL: the scene
 * as written). 0, or -2 (memory). */
static int measure(const struct quality_request *rq, const char *renderer, struct cand *x, const struct frames *fr,
                   struct render_out *got, const struct render_out *ref, char **text, size_t *len)
{
    size_t fbytes = (size_t)rq->width * rq->height * 3, tl = rq->len;
    char *t = NULL;
    if (x->m->options[0] && !(t = cand_text(rq, renderer, x->m->options, &tl))) {
        x->failed = 1;
        snprintf(x->msg, sizeof x->msg, "cannot set %s", x->m->options);
        return 0;
    }
    int r = render_text(rq, t ? t : rq->text, t ? tl : rq->len, rq->numeric, 0, fr, got, x->msg, sizeof x->msg);
    if (r) {
        free(t);
        if (r == -2) return -2;
        x->failed = 1;
        return 0;
    }
    x->num_frac = got->num_frac;
    x->work = got->work;
    x->psnr = INFINITY;
    for (unsigned k = 0; k < fr->n; k++) {
        double p = psnr888(got->rgb + k * fbytes, ref->rgb + k * fbytes, (size_t)rq->width * rq->height);
        if (p < x->psnr) {
            x->psnr = p;
            x->worst_frame = fr->f[k];
        }
    }
    if (text) {
        *text = t;
        *len = tl;
    } else {
        free(t);
    }
    return 0;
}

int quality_choose(const struct quality_request *rq, struct quality_choice *ch, char *err, size_t errlen)
{
    memset(ch, 0, sizeof *ch);
    const char *tname = quality_target_name(rq->target);
    if (!tname) return snprintf(err, errlen, "%s:1:1: error: no accuracy target", rq->path), QUALITY_EINPUT;
    void *ds = NULL;
    if (core_api_double.scene_parse(rq->path, rq->text, rq->len, &ds, err, errlen)) return QUALITY_EINPUT;
    struct scene_info in;
    core_api_double.scene_info(ds, &in);
    core_api_double.scene_free(ds);
    const char *cls = class_of(&in), *renderer = in.kind == SCENE_RAYTRACE ? "raytracer" : "rasterizer";
    /* the model's rows: RP2040 runs Cortex-M0+ code (its methods' factors are the M0+'s) */
    const char *mt = rq->target == QUALITY_RP2040 ? "m0plus" : tname;
    const struct base_row *base = base_row(tname, cls, rq->numeric);
    size_t nm = NROWS(method_rows);
    struct cand *c = calloc(nm, sizeof *c);
    if (!c) return snprintf(err, errlen, "out of memory"), QUALITY_EINTERNAL;
    int nc = 0;
    char why_kept[200] = "";
    for (size_t i = 0; base && i < nm; i++) {
        const struct method_row *m = &method_rows[i];
        if (strcmp(m->target, mt) || strcmp(m->cls, cls) || strcmp(m->numeric, rq->numeric)) continue;
        /* a key the scene sets stays as set: no candidate changes it */
        char opts[256], *save = NULL, val[64];
        int keep = 1;
        snprintf(opts, sizeof opts, "%s", m->options);
        /* a scene with chapter 15's shadows keeps shadows: the method (a map,
           the volumes) is chosen, not whether there are any */
        int shadow = !strcmp(cls, "shadows");
        if (shadow && strstr(m->options, "shadows=off") && !strstr(m->options, "shadow_volumes=on")) continue;
        for (char *o = strtok_r(opts, " ", &save); o && keep; o = strtok_r(NULL, " ", &save))
            if (!(shadow && (!strncmp(o, "shadows=", 8) || !strncmp(o, "shadow_volumes=", 15))) &&
                scene_sets(rq->text, rq->len, renderer, o, val, sizeof val) && strcmp(val, strchr(o, '=') + 1)) {
                keep = 0;
                if (!why_kept[0]) snprintf(why_kept, sizeof why_kept, "%.*s", (int)(strchr(o, '=') - o), o);
            }
        if (keep) c[nc++].m = m;
    }
    char book[PART];
    int line = rq->line ? rq->line : 1, col = rq->line ? rq->col : 1;
    if (in.kind != SCENE_RAYTRACE && scene_sets(rq->text, rq->len, renderer, "book_exact=x", book, sizeof book) &&
        strcmp(book, "off") && strcmp(book, "0") && strcmp(book, "false") && strcmp(book, "no")) {
        free(c);
        snprintf(err, errlen, "%s:%d:%d: error: the scene sets book_exact = %s: the book's path has no methods to "
                              "choose (the candidates are the default path's: book_exact = off)",
                 rq->path, line, col, book);
        return QUALITY_EINPUT;
    }
    if (!base) {
        free(c);
        snprintf(err, errlen,
                 "%s:%d:%d: error: no cost model for a %s scene (%s) in %s on %s (tools/quality/cost_model.def)",
                 rq->path, line, col, cls, renderer, rq->numeric, tname);
        return QUALITY_EINPUT;
    }
    if (nc == 0) {
        free(c);
        snprintf(err, errlen, "%s:%d:%d: error: every candidate method would change %s, which the scene sets",
                 rq->path, line, col, why_kept);
        return QUALITY_EINPUT;
    }
    struct frames fr;
    pick_frames(in.frames, &fr);
    size_t fbytes = (size_t)rq->width * rq->height * 3;
    struct render_out ref = { 0 }, got = { 0 };
    ref.rgb = malloc(fbytes * fr.n);
    got.rgb = malloc(fbytes * fr.n);
    int rc = ref.rgb && got.rgb ? 0 : QUALITY_EINTERNAL;
    char msg[600];
    /* the scene's work, as written, in the image's mode */
    if (!rc && render_text(rq, rq->text, rq->len, rq->numeric, 0, &fr, &got, msg, sizeof msg)) {
        snprintf(err, errlen, "%s", msg);
        rc = QUALITY_EINPUT;
    }
    double work = got.work;
    char shading[PART] = "none";
    if (in.kind != SCENE_RAYTRACE) scene_sets(rq->text, rq->len, renderer, "shading=x", shading, sizeof shading);
    double light = base ? lighting_per_work(base, mt, shading) : 0;
    /* the reference: double, exact methods, trilinear where the scene sets no filter */
    char *ref_text = NULL;
    size_t ref_len = rq->len;
    if (!rc) {
        char val[64];
        if (in.textured && !scene_sets(rq->text, rq->len, renderer, "texture.filter=x", val, sizeof val))
            ref_text = quality_set_option(rq->text, rq->len, renderer, "texture.filter=trilinear", &ref_len);
        if (in.shadows) { /* exact hard shadows: the stencil volumes */
            static const char *const vol[] = { "shadows=off", "shadow_volumes=on" };
            for (int k = 0; k < 2; k++) {
                size_t nl;
                char *n = quality_set_option(ref_text ? ref_text : rq->text, ref_text ? ref_len : rq->len, renderer,
                                             vol[k], &nl);
                free(ref_text);
                ref_text = n;
                ref_len = nl;
                if (!n) break;
            }
            if (!ref_text) rc = QUALITY_EINTERNAL, snprintf(err, errlen, "out of memory");
        }
        if (!rc && render_text(rq, ref_text ? ref_text : rq->text, ref_text ? ref_len : rq->len, "double", 1, &fr, &ref,
                               msg, sizeof msg)) {
            snprintf(err, errlen, "%s", msg);
            rc = QUALITY_EINPUT;
        }
    }
    if (rq->report && !rc) {
        char why[160]; /* where the target comes from */
        if (rq->line) snprintf(why, sizeof why, "the quality block at %s:%d:%d", rq->path, rq->line, rq->col);
        else snprintf(why, sizeof why, "--min-psnr");
        fprintf(rq->report,
                "quality: %s, at least %.1f dB (%s): %d candidate methods (%s scene, %s), frames checked:", tname,
                rq->min_psnr, why, nc, cls, rq->numeric);
    }
    if (rq->report && !rc) {
        for (unsigned k = 0; k < fr.n; k++) fprintf(rq->report, "%s %u", k ? "," : "", fr.f[k]);
        fprintf(rq->report, " of %u, %ux%u, against double with the exact methods%s%s%s\n", in.frames ? in.frames : 1,
                rq->width, rq->height, why_kept[0] ? "; kept as the scene sets it: " : "", why_kept,
                why_kept[0] ? " (and any other key it sets)" : "");
    }
    /* a class predicted from each candidate's own work (the ray tracer's:
       its rays): every one is rendered before they are ordered */
    int own = own_work(cls);
    int chosen = -1, best = -1;
    for (int i = 0; own && i < nc && !rc; i++) {
        ch->rendered++;
        if (measure(rq, renderer, &c[i], &fr, &got, &ref, NULL, NULL) == -2) {
            rc = QUALITY_EINTERNAL;
            snprintf(err, errlen, "out of memory");
        }
    }
    double npx = (double)rq->width * rq->height;
    for (int i = 0; i < nc; i++) { /* cost_model.py predicted */
        double pw = base->per_work * c[i].m->factor, w = c[i].work + c[i].m->factor * npx;
        if (c[i].failed) c[i].predicted = HUGE_VAL;
        else if (own) c[i].predicted = base->per_work * (w > 0.1 * c[i].work ? w : 0.1 * c[i].work);
        else c[i].predicted = (pw + light > 0.1 * pw ? pw + light : 0.1 * pw) * work;
    }
    qsort(c, (size_t)nc, sizeof *c, by_cost);
    for (int i = 0; own && !rc && i < nc; i++) /* the most accurate, for the message when none reaches it */
        if (!c[i].failed && (best < 0 || c[i].psnr > c[best].psnr)) best = i;
    for (int i = 0; i < nc && !rc && chosen < 0; i++) {
        char *t = NULL;
        size_t tl = rq->len;
        if (!own) {
            ch->rendered++;
            int r = measure(rq, renderer, &c[i], &fr, &got, &ref, &t, &tl);
            if (r == -2) {
                rc = QUALITY_EINTERNAL;
                snprintf(err, errlen, "out of memory");
                break;
            }
            if (!c[i].failed && (best < 0 || c[i].psnr > c[best].psnr)) best = i;
        } else if (!c[i].failed && c[i].psnr >= rq->min_psnr && c[i].m->options[0]) {
            t = cand_text(rq, renderer, c[i].m->options, &tl);
            if (!t) {
                rc = QUALITY_EINTERNAL;
                snprintf(err, errlen, "out of memory");
                break;
            }
        }
        if (!c[i].failed && c[i].psnr >= rq->min_psnr) {
            chosen = i;
            ch->text = t ? t : malloc(rq->len + 1);
            if (!t && ch->text) {
                memcpy(ch->text, rq->text, rq->len);
                ch->text[rq->len] = 0;
            }
            ch->len = t ? tl : rq->len;
            if (!ch->text) rc = QUALITY_EINTERNAL;
        } else {
            free(t);
        }
    }
    ch->candidates = nc;
    char cost[64], db[32];
    if (!rc && chosen < 0) {
        if (best >= 0) {
            char bo[256];
            changed(rq, renderer, c[best].m->options, bo, sizeof bo);
            fmt_db(db, sizeof db, c[best].psnr);
            snprintf(err, errlen, "%s:%d:%d: error: no method reaches %.1f dB on %s: the most accurate, %s, measures %s",
                     rq->path, rq->line ? rq->line : 1, rq->line ? rq->col : 1, rq->min_psnr, tname, shown(bo), db);
        } else {
            snprintf(err, errlen, "%s:1:1: error: no candidate method renders (%s)", rq->path, c[0].msg);
        }
        rc = QUALITY_EINPUT;
    }
    if (!rc) {
        struct cand *x = &c[chosen];
        changed(rq, renderer, x->m->options, ch->options, sizeof ch->options);
        ch->predicted = x->predicted;
        ch->psnr = x->psnr;
        ch->num_frac = x->num_frac;
        if (rq->report) {
            char fmtq[24] = "";
            if (x->num_frac) snprintf(fmtq, sizeof fmtq, " Q%d.%d", 31 - x->num_frac, x->num_frac);
            fmt_cost(cost, sizeof cost, x->predicted, rq->target);
            fmt_db(db, sizeof db, x->psnr);
            fprintf(rq->report, "quality: chosen %s (%s%s): predicted %s a frame on %s, measured %s (lowest, frame %u)\n",
                    shown(ch->options), rq->numeric, fmtq, cost, tname, db, x->worst_frame);
            if (chosen > 0) {
                struct cand *y = &c[chosen - 1];
                char yo[256];
                changed(rq, renderer, y->m->options, yo, sizeof yo);
                fmt_cost(cost, sizeof cost, y->predicted, rq->target);
                if (y->failed)
                    fprintf(rq->report, "quality: the next cheaper, %s (predicted %s), does not render: %s\n",
                            shown(yo), cost, y->msg);
                else {
                    fmt_db(db, sizeof db, y->psnr);
                    fprintf(rq->report, "quality: the next cheaper, %s (predicted %s), measures %s on frame %u, "
                                        "below %.1f dB\n",
                            shown(yo), cost, db, y->worst_frame, rq->min_psnr);
                }
            } else {
                fprintf(rq->report, "quality: it is the cheapest candidate\n");
            }
            char ps[32] = "inf";
            if (!isinf(x->psnr)) snprintf(ps, sizeof ps, "%.3f", x->psnr);
            fprintf(rq->report, "quality-summary target=%s min_psnr=%g options=\"%s\" numeric=%s num_frac=%d "
                                "predicted=%.0f psnr=%s candidates=%d rendered=%d\n",
                    tname, rq->min_psnr, ch->options, rq->numeric, x->num_frac, x->predicted, ps, nc, ch->rendered);
        }
    }
    free(ref_text);
    free(ref.rgb);
    free(got.rgb);
    free(c);
    return rc;
}

void quality_free(struct quality_choice *ch)
{
    free(ch->text);
    ch->text = NULL;
}
