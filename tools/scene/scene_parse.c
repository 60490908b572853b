/* SPDX-License-Identifier: MIT */
/* scene_parse.c — reads the scene notation (docs/scene-format.md) into a
 * struct scene in this build's numbers.
 *
 * Two passes: the text becomes a small syntax tree (blocks of key = value
 * entries, tuples, numbers, names, strings), then each known block is read
 * into the scene with its keys checked (unknown, duplicate, missing, wrong
 * type, out of range). Every error carries the position of the token at
 * fault and ends the parse (longjmp back to the entry point; everything
 * allocated so far lives in the arena and is released at once).
 *
 * Numbers are kept as doubles until they are stored, so the double build
 * holds exactly the doubles the book's demos compute (strtod gives the
 * nearest double to each literal; rotations and the sphere generator use the
 * constants of the book's demos, see rot_y and gen_sphere).
 */
#if defined(__unix__) || defined(__APPLE__)
#define _XOPEN_SOURCE 700   /* realpath */
#endif
#include <errno.h>
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stddef.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_parse.h"
#include "mipmap.h"
#include "raytracer.h"
#include "suggest.h"
#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>
#define HAVE_GETCWD 1
/* stat, open, poll and realpath: what a file is, and where a path leads */
#define HAVE_POSIX_FILES 1
#endif
#ifdef WITH_PNG
#include <png.h>
#endif

#define MAX_DEPTH      32
#define ARENA_LIMIT    ((size_t)256 << 20)   /* total bytes a scene may allocate */
#define MAX_LIGHTS     64
#define MAX_OBJECTS    4096
#define MAX_MODELS     256
#define MAX_INSTANCES  4096
#define MAX_TEXTURES   16
#define MAX_PRIMS      4096
#define MAX_LINES      4096
#define MAX_VERTS      65535
#define MAX_TRIS       65535
#define MAX_TEX_SIDE   1024
#define MAX_FRAMES     10000
#define MAX_CANVAS     4096

/* ---- arena ----------------------------------------------------------- */

struct chunk { struct chunk *next; size_t size, used; unsigned char *mem; };

struct arena { struct chunk *head; size_t total; };

static void arena_free(struct arena *a)
{
    struct chunk *c = a->head;
    while (c) {
        struct chunk *n = c->next;
        free(c->mem);
        free(c);
        c = n;
    }
    a->head = NULL;
    a->total = 0;
}

/* ---- syntax tree ----------------------------------------------------- */

enum nkind { N_NUM, N_NAME, N_STR, N_TUPLE, N_BLOCK };

static const char *const kind_names[] = { "a number", "a name", "a string", "a tuple", "a block" };

struct node {
    int kind;
    int line, col;          /* of the value */
    double num;
    const char *text;       /* N_NAME, N_STR */
    const char *key;        /* entry of a block / keyed tuple element; NULL otherwise */
    int kline, kcol;        /* of the key */
    struct node *first, *last, *next;
    int n;                  /* children */
};

struct parser {
    const char *file;
    const char *src;
    size_t len, pos;
    int line, col;
    int depth;
    int has_dir;
    char dir[1024];         /* directory of the scene file, for image files */
    struct arena arena;
    jmp_buf fail;
    char *err;
    size_t errlen;
    int oom;                /* the failure was an allocation */
    FILE *files[3];         /* files being read (open_file), closed when the parse fails */
    void *scratch[8];       /* a model file's temporary buffers (malloc) */
    struct scene_quality quality;   /* the quality block (scene_quality) */
};

static void set_error(struct parser *p, const char *file, int line, int col, const char *fmt, va_list ap)
{
    char msg[400];
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (p->err && p->errlen)
        snprintf(p->err, p->errlen, "%s:%d:%d: error: %s", file, line, col, msg);
}

static void fail_at(struct parser *p, int line, int col, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    set_error(p, p->file, line, col, fmt, ap);
    va_end(ap);
    longjmp(p->fail, 1);
}

/* An error in another file than the scene (a model, material or image file). */
static void fail_in(struct parser *p, const char *file, int line, int col, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    set_error(p, file, line, col, fmt, ap);
    va_end(ap);
    longjmp(p->fail, 1);
}

#define FAIL_N(p, nd, ...) fail_at((p), (nd)->line, (nd)->col, __VA_ARGS__)
#define FAIL_K(p, nd, ...) fail_at((p), (nd)->kline, (nd)->kcol, __VA_ARGS__)

/* A place in the scene file or in a file it reads. */
struct where { const char *file; int line, col; };

#define FAIL_W(p, w, ...) fail_in((p), (w)->file, (w)->line, (w)->col, __VA_ARGS__)

static struct where node_where(const struct parser *p, const struct node *n)
{
    struct where w = { p->file, n->line, n->col };
    return w;
}

static void *alloc(struct parser *p, size_t n)
{
    struct arena *a = &p->arena;
    n = (n + 15) & ~(size_t)15;
    if (n == 0) n = 16;
    if (!a->head || a->head->size - a->head->used < n) {
        size_t sz = n > 65536 ? n : 65536;
        if (a->total + sz > ARENA_LIMIT)
            fail_at(p, p->line, p->col, "scene needs more than %zu MiB of memory", ARENA_LIMIT >> 20);
        struct chunk *c = calloc(1, sizeof *c);
        unsigned char *m = c ? calloc(1, sz) : NULL;
        if (!m) {
            free(c);
            p->oom = 1;
            fail_at(p, p->line, p->col, "out of memory");
        }
        c->mem = m;
        c->size = sz;
        c->next = a->head;
        a->head = c;
        a->total += sz;
    }
    void *r = a->head->mem + a->head->used;
    a->head->used += n;
    return r;
}

static void *alloc_array(struct parser *p, size_t n, size_t size)
{
    if (size && n > ARENA_LIMIT / size)
        fail_at(p, p->line, p->col, "scene needs more than %zu MiB of memory", ARENA_LIMIT >> 20);
    return alloc(p, n * size);
}

static char *dup_str(struct parser *p, const char *s, size_t n)
{
    char *d = alloc(p, n + 1);
    memcpy(d, s, n);
    d[n] = 0;
    return d;
}

/* Temporary buffers of a model file (malloc'ed, not in the arena): freed as
 * soon as the file has been read, or when the parse fails. */
#define NSCRATCH (sizeof ((struct parser *)0)->scratch / sizeof(void *))

static void *scratch_alloc(struct parser *p, size_t n, size_t size)
{
    size_t i = 0;
    while (i < NSCRATCH && p->scratch[i]) i++;
    void *m = i < NSCRATCH && (!size || n <= ARENA_LIMIT / size) ? malloc(n * size + 1) : NULL;
    if (!m) {
        p->oom = 1;
        fail_at(p, p->line, p->col, "out of memory");
    }
    p->scratch[i] = m;
    return m;
}

static void scratch_free(struct parser *p, void *m)
{
    for (size_t i = 0; i < NSCRATCH; i++)
        if (p->scratch[i] == m) p->scratch[i] = NULL;
    free(m);
}

/* Closes the files a failed parse left open and frees its temporary buffers. */
static void release_files(struct parser *p)
{
    for (size_t i = 0; i < sizeof p->files / sizeof p->files[0]; i++) {
        if (p->files[i]) fclose(p->files[i]);
        p->files[i] = NULL;
    }
    for (size_t i = 0; i < NSCRATCH; i++) {
        free(p->scratch[i]);
        p->scratch[i] = NULL;
    }
}

/* ---- lexer ------------------------------------------------------------ */

enum tok { T_EOF, T_NAME, T_NUM, T_STR, T_LBRACE, T_RBRACE, T_LPAREN, T_RPAREN, T_EQ, T_COMMA, T_SEMI };

struct token {
    int t;
    int line, col;
    const char *s;
    size_t n;
    double num;
};

static int peekc(struct parser *p, size_t k)
{
    return p->pos + k < p->len ? (unsigned char)p->src[p->pos + k] : -1;
}

static void advance(struct parser *p)
{
    if (p->src[p->pos] == '\n') { p->line++; p->col = 1; }
    else p->col++;
    p->pos++;
}

static int is_alpha(int c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
static int is_digit(int c) { return c >= '0' && c <= '9'; }

static void skip_space(struct parser *p)
{
    for (;;) {
        int c = peekc(p, 0);
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') advance(p);
        else if (c == '#' || (c == '/' && peekc(p, 1) == '/')) {
            while (p->pos < p->len && p->src[p->pos] != '\n') advance(p);
        } else return;
    }
}

static struct token lex(struct parser *p)
{
    struct token t;
    skip_space(p);
    memset(&t, 0, sizeof t);
    t.line = p->line;
    t.col = p->col;
    t.s = p->src + p->pos;
    int c = peekc(p, 0);
    if (c < 0) { t.t = T_EOF; return t; }
    switch (c) {
    case '{': t.t = T_LBRACE; advance(p); t.n = 1; return t;
    case '}': t.t = T_RBRACE; advance(p); t.n = 1; return t;
    case '(': t.t = T_LPAREN; advance(p); t.n = 1; return t;
    case ')': t.t = T_RPAREN; advance(p); t.n = 1; return t;
    case '=': t.t = T_EQ; advance(p); t.n = 1; return t;
    case ',': t.t = T_COMMA; advance(p); t.n = 1; return t;
    case ';': t.t = T_SEMI; advance(p); t.n = 1; return t;
    default: break;
    }
    if (is_alpha(c)) {
        while (is_alpha(peekc(p, 0)) || is_digit(peekc(p, 0))) advance(p);
        t.t = T_NAME;
        t.n = (size_t)(p->src + p->pos - t.s);
        if (t.n > 64) fail_at(p, t.line, t.col, "name longer than 64 characters");
        return t;
    }
    if (c == '"') {
        advance(p);
        while (peekc(p, 0) != '"') {
            int d = peekc(p, 0);
            if (d < 0 || d == '\n') fail_at(p, t.line, t.col, "unterminated string");
            if (d < 32 || d > 126) fail_at(p, p->line, p->col, "unexpected byte 0x%02x in string", d);
            advance(p);
            if (p->pos - (size_t)(t.s - p->src) > 256) fail_at(p, t.line, t.col, "string longer than 255 characters");
        }
        advance(p);
        t.t = T_STR;
        t.s += 1;
        t.n = (size_t)(p->src + p->pos - t.s) - 1;
        return t;
    }
    if (c == '-' || c == '+' || c == '.' || is_digit(c)) {
        /* [+-] digits [. digits] [e [+-] digits]: at least one digit */
        char buf[80];
        size_t k = 0;
        int digits = 0;
        if (c == '-' || c == '+') advance(p);
        while (is_digit(peekc(p, 0))) { advance(p); digits++; }
        if (peekc(p, 0) == '.') {
            advance(p);
            while (is_digit(peekc(p, 0))) { advance(p); digits++; }
        }
        if (!digits) fail_at(p, t.line, t.col, "malformed number");
        if (peekc(p, 0) == 'e' || peekc(p, 0) == 'E') {
            advance(p);
            if (peekc(p, 0) == '-' || peekc(p, 0) == '+') advance(p);
            if (!is_digit(peekc(p, 0))) fail_at(p, t.line, t.col, "malformed number (exponent)");
            while (is_digit(peekc(p, 0))) advance(p);
        }
        if (is_alpha(peekc(p, 0)) || peekc(p, 0) == '.')
            fail_at(p, t.line, t.col, "malformed number");
        t.n = (size_t)(p->src + p->pos - t.s);
        if (t.n >= sizeof buf) fail_at(p, t.line, t.col, "number longer than %zu characters", sizeof buf - 1);
        for (k = 0; k < t.n; k++) buf[k] = t.s[k];
        buf[k] = 0;
        errno = 0;
        t.num = strtod(buf, NULL);
        if (!isfinite(t.num)) fail_at(p, t.line, t.col, "number %s is too large", buf);
        /* a literal below the smallest normal double would be read as 0 (or
           a subnormal no numeric mode holds): an error, not a silent 0 */
        if ((errno == ERANGE && t.num == 0) || (t.num != 0 && fabs(t.num) < DBL_MIN))
            fail_at(p, t.line, t.col, "number %s is too small (under %g, it would be read as 0)", buf, DBL_MIN);
        t.t = T_NUM;
        return t;
    }
    if (c >= 33 && c <= 126) fail_at(p, t.line, t.col, "unexpected character '%c'", c);
    fail_at(p, t.line, t.col, "unexpected byte 0x%02x", c);
    return t;
}

static struct token peek_tok(struct parser *p)
{
    size_t pos = p->pos;
    int line = p->line, col = p->col;
    struct token t = lex(p);
    p->pos = pos;
    p->line = line;
    p->col = col;
    return t;
}

static const char *tok_desc(const struct token *t)
{
    switch (t->t) {
    case T_EOF: return "end of file";
    case T_NAME: return "a name";
    case T_NUM: return "a number";
    case T_STR: return "a string";
    case T_LBRACE: return "'{'";
    case T_RBRACE: return "'}'";
    case T_LPAREN: return "'('";
    case T_RPAREN: return "')'";
    case T_EQ: return "'='";
    case T_COMMA: return "','";
    default: return "';'";
    }
}

/* ---- syntax ----------------------------------------------------------- */

static struct node *new_node(struct parser *p, int kind, int line, int col)
{
    struct node *n = alloc(p, sizeof *n);
    n->kind = kind;
    n->line = line;
    n->col = col;
    return n;
}

static void add_child(struct node *parent, struct node *c)
{
    if (parent->last) parent->last->next = c;
    else parent->first = c;
    parent->last = c;
    parent->n++;
}

static struct node *parse_value(struct parser *p);

/* Entries up to `close` (T_RBRACE, or T_EOF at the top level):
 *   NAME '=' value | NAME block | value, optionally separated by ',' or ';'. */
static void parse_entries(struct parser *p, struct node *blk, int close)
{
    for (;;) {
        struct token t = peek_tok(p);
        if (t.t == close) { lex(p); return; }
        if (t.t == T_COMMA || t.t == T_SEMI) { lex(p); continue; }
        if (t.t == T_EOF) fail_at(p, t.line, t.col, "missing '}' (block opened at %d:%d)", blk->line, blk->col);
        if (t.t == T_RBRACE) fail_at(p, t.line, t.col, "unexpected '}'");
        if (t.t == T_NAME) {
            lex(p);
            struct token u = peek_tok(p);
            struct node *v;
            if (u.t == T_EQ) {
                lex(p);
                v = parse_value(p);
            } else if (u.t == T_LBRACE) {
                v = parse_value(p);
            } else {
                fail_at(p, u.line, u.col, "expected '=' or '{' after '%.*s', found %s",
                        (int)t.n, t.s, tok_desc(&u));
                return;
            }
            v->key = dup_str(p, t.s, t.n);
            v->kline = t.line;
            v->kcol = t.col;
            add_child(blk, v);
        } else {
            struct node *v = parse_value(p);
            v->kline = v->line;
            v->kcol = v->col;
            add_child(blk, v);
        }
    }
}

static struct node *parse_value(struct parser *p)
{
    struct token t = lex(p);
    struct node *n;
    switch (t.t) {
    case T_NUM:
        n = new_node(p, N_NUM, t.line, t.col);
        n->num = t.num;
        return n;
    case T_NAME:
        n = new_node(p, N_NAME, t.line, t.col);
        n->text = dup_str(p, t.s, t.n);
        return n;
    case T_STR:
        n = new_node(p, N_STR, t.line, t.col);
        n->text = dup_str(p, t.s, t.n);
        return n;
    case T_LBRACE:
        if (++p->depth > MAX_DEPTH) fail_at(p, t.line, t.col, "nesting deeper than %d", MAX_DEPTH);
        n = new_node(p, N_BLOCK, t.line, t.col);
        parse_entries(p, n, T_RBRACE);
        p->depth--;
        return n;
    case T_LPAREN:
        if (++p->depth > MAX_DEPTH) fail_at(p, t.line, t.col, "nesting deeper than %d", MAX_DEPTH);
        n = new_node(p, N_TUPLE, t.line, t.col);
        for (;;) {
            struct token u = peek_tok(p);
            if (u.t == T_RPAREN && n->n == 0) { lex(p); break; }
            struct node *e;
            if (u.t == T_NAME) {
                lex(p);
                struct token w = peek_tok(p);
                if (w.t == T_EQ) {
                    lex(p);
                    e = parse_value(p);
                    e->key = dup_str(p, u.s, u.n);
                    e->kline = u.line;
                    e->kcol = u.col;
                } else {
                    e = new_node(p, N_NAME, u.line, u.col);
                    e->text = dup_str(p, u.s, u.n);
                }
            } else {
                e = parse_value(p);
            }
            if (!e->key) { e->kline = e->line; e->kcol = e->col; }
            add_child(n, e);
            struct token v = lex(p);
            if (v.t == T_RPAREN) break;
            if (v.t != T_COMMA)
                fail_at(p, v.line, v.col, "expected ',' or ')' in tuple opened at %d:%d, found %s",
                        n->line, n->col, tok_desc(&v));
        }
        p->depth--;
        return n;
    default:
        fail_at(p, t.line, t.col, "expected a value, found %s", tok_desc(&t));
        return NULL;
    }
}

/* ---- typed access ------------------------------------------------------ */

static void want_kind(struct parser *p, const struct node *n, int kind, const char *what)
{
    if (n->kind != kind) FAIL_N(p, n, "%s must be %s, found %s", what, kind_names[kind], kind_names[n->kind]);
}

/* The range the build can hold (fixed point: |x| < 2^(31-NUM_FRAC)). */
static num to_num_at(struct parser *p, const struct where *at, double d, const char *what)
{
    double hi = num_to_double(NUM_MAX), lo = num_to_double(NUM_MIN);
    if (!(d <= hi && d >= lo))
        FAIL_W(p, at, "%s: %.17g is out of range for %s numbers (%.6g .. %.6g)", what, d, NUM_NAME, lo, hi);
    return num_from_double(d);
}

static num to_num(struct parser *p, const struct node *n, double d, const char *what)
{
    struct where at = node_where(p, n);
    return to_num_at(p, &at, d, what);
}

static double get_num(struct parser *p, const struct node *n, const char *what)
{
    want_kind(p, n, N_NUM, what);
    return n->num;
}

static double get_num_range(struct parser *p, const struct node *n, const char *what, double lo, double hi)
{
    double d = get_num(p, n, what);
    if (d < lo || d > hi) FAIL_N(p, n, "%s must be in %g .. %g, found %.17g", what, lo, hi, d);
    return d;
}

static long get_int(struct parser *p, const struct node *n, const char *what, long lo, long hi)
{
    double d = get_num(p, n, what);
    if (d != floor(d)) FAIL_N(p, n, "%s must be a whole number, found %.17g", what, d);
    if (d < (double)lo || d > (double)hi) FAIL_N(p, n, "%s must be in %ld .. %ld, found %.17g", what, lo, hi, d);
    return (long)d;
}

static int get_bool(struct parser *p, const struct node *n, const char *what)
{
    if (n->kind == N_NUM && (n->num == 0 || n->num == 1)) return n->num == 1;
    if (n->kind == N_NAME) {
        if (!strcmp(n->text, "on") || !strcmp(n->text, "true") || !strcmp(n->text, "yes")) return 1;
        if (!strcmp(n->text, "off") || !strcmp(n->text, "false") || !strcmp(n->text, "no")) return 0;
    }
    FAIL_N(p, n, "%s must be on or off", what);
    return 0;
}

/* One of the names in `names` (NULL-terminated); returns its index. */
static int get_choice(struct parser *p, const struct node *n, const char *what, const char *const *names)
{
    if (n->kind == N_NAME)
        for (int i = 0; names[i]; i++)
            if (!strcmp(n->text, names[i])) return i;
    char list[256] = "";
    for (int i = 0; names[i]; i++) {
        if (i) strncat(list, ", ", sizeof list - strlen(list) - 1);
        strncat(list, names[i], sizeof list - strlen(list) - 1);
    }
    if (n->kind == N_NAME) {
        const char *near = suggest_nearest(n->text, names);
        if (near) FAIL_N(p, n, "%s: unknown value '%s' (did you mean '%s'? expected one of %s)", what, n->text, near, list);
        FAIL_N(p, n, "%s: unknown value '%s' (expected one of %s)", what, n->text, list);
    }
    FAIL_N(p, n, "%s must be one of %s, found %s", what, list, kind_names[n->kind]);
    return 0;
}

static const char *get_name(struct parser *p, const struct node *n, const char *what)
{
    if (n->kind != N_NAME && n->kind != N_STR) FAIL_N(p, n, "%s must be a name, found %s", what, kind_names[n->kind]);
    return n->text;
}

/* A tuple of exactly k numbers (unkeyed). */
static void get_tuple(struct parser *p, const struct node *n, const char *what, int k, double *out)
{
    if (n->kind != N_TUPLE) FAIL_N(p, n, "%s must be a tuple of %d numbers, found %s", what, k, kind_names[n->kind]);
    if (n->n != k) FAIL_N(p, n, "%s must have %d components, found %d", what, k, n->n);
    int i = 0;
    for (const struct node *e = n->first; e; e = e->next, i++) {
        if (e->key) FAIL_K(p, e, "%s: unexpected key '%s' in a tuple of numbers", what, e->key);
        out[i] = get_num(p, e, what);
    }
}

static vec3 get_vec3(struct parser *p, const struct node *n, const char *what)
{
    double d[3];
    get_tuple(p, n, what, 3, d);
    return v3_make(to_num(p, n, d[0], what), to_num(p, n, d[1], what), to_num(p, n, d[2], what));
}

static rgb get_rgb(struct parser *p, const struct node *n, const char *what)
{
    double d[3];
    get_tuple(p, n, what, 3, d);
    for (int i = 0; i < 3; i++)
        if (d[i] < 0 || d[i] > 255) FAIL_N(p, n, "%s: channel %.17g is outside 0 .. 255", what, d[i]);
    return rgb_make(num_from_double(d[0]), num_from_double(d[1]), num_from_double(d[2]));
}

/* Collects the keyed entries of block `blk` named in `keys` (NULL-terminated)
 * into vals[]; an unknown key, a repeated key or an unkeyed value is an error. */
static void fields(struct parser *p, const struct node *blk, const char *what,
                   const char *const *keys, const struct node **vals)
{
    int nk = 0;
    while (keys[nk]) vals[nk++] = NULL;
    if (blk->kind != N_BLOCK && blk->kind != N_TUPLE)
        FAIL_N(p, blk, "%s must be a block { ... }, found %s", what, kind_names[blk->kind]);
    for (const struct node *e = blk->first; e; e = e->next) {
        if (!e->key) FAIL_N(p, e, "%s: expected 'key = value', found %s", what, kind_names[e->kind]);
        int i;
        for (i = 0; i < nk; i++)
            if (!strcmp(keys[i], e->key)) break;
        if (i == nk) {
            const char *near = suggest_nearest(e->key, keys);
            FAIL_K(p, e, "unknown key '%s' in %s%s%s%s", e->key, what, near ? " (did you mean '" : "",
                   near ? near : "", near ? "'?)" : "");
        }
        if (vals[i]) FAIL_K(p, e, "duplicate '%s' in %s (first at %d:%d)", e->key, what, vals[i]->kline, vals[i]->kcol);
        vals[i] = e;
    }
}

static const struct node *need(struct parser *p, const struct node *blk, const struct node *v,
                               const char *what, const char *key)
{
    if (!v) {
        int line = blk->key ? blk->kline : blk->line, col = blk->key ? blk->kcol : blk->col;
        fail_at(p, line, col, "%s: missing '%s'", what, key);
    }
    return v;
}

/* ---- rotations ---------------------------------------------------------- */

/* cos and sin of the angles the book's demos use, as their doubles
 * (docs/book-demos.md, "Angles and the sphere table"); other angles use
 * the generic formula. */
static const struct { double deg, c, s; } exact_angles[] = {
    { -30.0, 0.86602540378443871, -0.49999999999999994 },
    { 195.0, -0.96592582628906842, -0.25881904510252035 },
    { -15.0, 0.96592582628906831, -0.25881904510252074 },
    { 45.0, 0.70710678118654757, 0.70710678118654746 },
    { 180.0, -1.0, 1.2246467991473532e-16 },
    { 0.0, 1.0, 0.0 },
};

static void cos_sin_deg(double deg, double *c, double *s)
{
    for (size_t i = 0; i < sizeof exact_angles / sizeof exact_angles[0]; i++)
        if (exact_angles[i].deg == deg) { *c = exact_angles[i].c; *s = exact_angles[i].s; return; }
    double a = deg * 3.141592653589793 / 180.0;
    *c = cos(a);
    *s = sin(a);
}

static void mat_mul3(double r[3][3], double a[3][3], double b[3][3])
{
    double t[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            t[i][j] = ((0 + a[i][0] * b[0][j]) + a[i][1] * b[1][j]) + a[i][2] * b[2][j];
    memcpy(r, t, sizeof t);
}

/* rotation { y = DEG }, { x = .. y = .. z = .. } (applied x, then y, then z:
 * R = Rz·Ry·Rx) or { rows = ((..), (..), (..)) }. RotY is the book's
 * MakeOYRotationMatrix: rows [c, 0, -s], [0, 1, 0], [s, 0, c]. */
static mat3 get_rotation(struct parser *p, const struct node *n, const char *what, int32_t q29[3][3])
{
    static const char *const keys[] = { "x", "y", "z", "rows", NULL };
    const struct node *v[4];
    double m[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    mat3 r;
    if (q29) memset(q29, 0, sizeof(int32_t[3][3]));
    if (n->kind == N_NAME && !strcmp(n->text, "identity")) return m3_identity();
    fields(p, n, what, keys, v);
    if (v[3]) {
        if (v[0] || v[1] || v[2]) FAIL_K(p, v[3], "%s: 'rows' cannot be combined with angles", what);
        const struct node *rows = v[3];
        if (rows->kind != N_TUPLE || rows->n != 3) FAIL_N(p, rows, "%s: rows must be a tuple of 3 rows", what);
        int i = 0;
        for (const struct node *e = rows->first; e; e = e->next, i++) get_tuple(p, e, "rotation row", 3, m[i]);
    } else {
        if (v[0]) {
            double c, s;
            cos_sin_deg(get_num_range(p, v[0], "rotation x", -36000, 36000), &c, &s);
            double rx[3][3] = { { 1, 0, 0 }, { 0, c, -s }, { 0, s, c } };
            memcpy(m, rx, sizeof m);
        }
        if (v[1]) {
            double c, s;
            cos_sin_deg(get_num_range(p, v[1], "rotation y", -36000, 36000), &c, &s);
            double ry[3][3] = { { c, 0, -s }, { 0, 1, 0 }, { s, 0, c } };
            if (v[0]) mat_mul3(m, ry, m);
            else memcpy(m, ry, sizeof m);
        }
        if (v[2]) {
            double c, s;
            cos_sin_deg(get_num_range(p, v[2], "rotation z", -36000, 36000), &c, &s);
            double rz[3][3] = { { c, -s, 0 }, { s, c, 0 }, { 0, 0, 1 } };
            if (v[0] || v[1]) mat_mul3(m, rz, m);
            else memcpy(m, rz, sizeof m);
        }
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.m[i][j] = to_num(p, n, m[i][j], what);
    /* the precise copy, when every entry fits Q2.29 */
    int fits = 1;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) fits &= fabs(m[i][j]) < 3.999;
    for (int i = 0; i < 3 && q29 && fits; i++)
        for (int j = 0; j < 3; j++) q29[i][j] = (int32_t)lround(ldexp(m[i][j], 29));
    return r;
}

/* ---- scene building state ------------------------------------------------ */

/* A name defined in the scene (NULL: a model's part or a material's texture, which no entry can
 * name). A model read from an OBJ file is `parts` models in a row, one per texture of its
 * materials; tex is each part's texture (-1: none). */
struct named { const char *name; const struct node *at; int parts, tex; };

struct build {
    struct scene *s;
    struct scene_light *lights;
    struct rt_object *objects;
    struct rt_csg *csg;
    struct ras_model *models;
    struct ras_instance *instances;
    struct ras_texture *textures;
    struct prim2d *prims;
    struct line3d *lines;
    struct named *obj_names, *model_names, *tex_names;
    int nlights, nobjects, ncsg, nmodels, ninstances, ntextures, nprims, nlines;
    /* models, textures and instances grow past their entries' count: an OBJ file's parts and
       textures, and the instances of each part */
    int cap_models, cap_textures, cap_instances;
};

/* arr with room for `need` elements (*cap grows to at least that), the first n kept. */
static void *grow_array(struct parser *p, void *arr, int n, int *cap, int need, size_t size)
{
    if (need <= *cap) return arr;
    int nc = *cap * 2 > need ? *cap * 2 : need;
    void *na = alloc_array(p, (size_t)nc, size);
    if (n) memcpy(na, arr, (size_t)n * size);
    *cap = nc;
    return na;
}

#define GROW(p, arr, n, cap, need) ((arr) = grow_array((p), (arr), (n), &(cap), (need), sizeof *(arr)))

/* Room for `more` models, textures or instances; the scene's limits. */
static void more_models(struct parser *p, struct build *b, const struct node *at, int more)
{
    if (b->nmodels + more > MAX_MODELS)
        FAIL_N(p, at, "more than %d models (the parts of a model file count as models)", MAX_MODELS);
    int cap = b->cap_models;
    GROW(p, b->models, b->nmodels, cap, b->nmodels + more);
    GROW(p, b->model_names, b->nmodels, b->cap_models, b->nmodels + more);
}

static void more_textures(struct parser *p, struct build *b, const struct where *at, int more)
{
    if (b->ntextures + more > MAX_TEXTURES)
        FAIL_W(p, at, "more than %d textures (with the textures of model files' materials)", MAX_TEXTURES);
    int cap = b->cap_textures;
    GROW(p, b->textures, b->ntextures, cap, b->ntextures + more);
    GROW(p, b->tex_names, b->ntextures, b->cap_textures, b->ntextures + more);
}

static int find_named(const struct named *t, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (t[i].name && !strcmp(t[i].name, name)) return i;
    return -1;
}

static void read_anim(struct parser *p, const struct node *n, struct scene_anim *a)
{
    static const char *const keys[] = { "rotate_y", "move", NULL };
    const struct node *v[2];
    fields(p, n, "animate", keys, v);
    if (v[0]) a->rot_y_per_frame = to_num(p, v[0], get_num_range(p, v[0], "rotate_y", -360, 360), "rotate_y");
    if (v[1]) a->move_per_frame = get_vec3(p, v[1], "move");
}

static void read_camera(struct parser *p, const struct node *n, struct scene *s)
{
    static const char *const keys[] = { "position", "rotation", "animate", NULL };
    const struct node *v[3];
    fields(p, n, "camera", keys, v);
    if (v[0]) s->camera.position = get_vec3(p, v[0], "camera position");
    if (v[1]) s->camera.rotation = get_rotation(p, v[1], "camera rotation", s->camera.rot_q29);
    if (v[2]) read_anim(p, v[2], &s->camera_anim);
}

static void read_light(struct parser *p, const struct node *n, struct scene_light *l)
{
    static const char *const keys[] = { "type", "intensity", "position", "direction", NULL };
    static const char *const types[] = { "ambient", "point", "directional", NULL };
    const struct node *v[4];
    fields(p, n, "light", keys, v);
    l->type = (uint8_t)get_choice(p, need(p, n, v[0], "light", "type"), "light type", types);
    l->intensity = to_num(p, v[1], get_num_range(p, need(p, n, v[1], "light", "intensity"), "light intensity", 0, 16),
                          "light intensity");
    if (l->type == LIGHT_POINT) {
        if (v[3]) FAIL_K(p, v[3], "a point light has a position, not a direction");
        l->v = get_vec3(p, need(p, n, v[2], "point light", "position"), "light position");
    } else if (l->type == LIGHT_DIRECTIONAL) {
        if (v[2]) FAIL_K(p, v[2], "a directional light has a direction, not a position");
        l->v = get_vec3(p, need(p, n, v[3], "directional light", "direction"), "light direction");
        if (l->v.x == 0 && l->v.y == 0 && l->v.z == 0) FAIL_N(p, v[3], "light direction must not be zero");
    } else {
        if (v[2]) FAIL_K(p, v[2], "an ambient light has no position");
        if (v[3]) FAIL_K(p, v[3], "an ambient light has no direction");
    }
}

/* Material keys shared by sphere, plane and triangle (indices 0..4 of vals). */
static void read_material(struct parser *p, const struct node *blk, const struct node **v, const char *what,
                          struct rt_material *m)
{
    m->color = get_rgb(p, need(p, blk, v[0], what, "color"), "color");
    m->specular = num_from_int(-1);
    m->reflective = NUM_ZERO;
    m->transparency = NUM_ZERO;
    m->refraction = NUM_ONE;
    if (v[1]) m->specular = to_num(p, v[1], (double)get_int(p, v[1], "specular", -1, 10000), "specular");
    if (v[2]) m->reflective = num_from_double(get_num_range(p, v[2], "reflective", 0, 1));
    if (v[3]) m->transparency = num_from_double(get_num_range(p, v[3], "transparency", 0, 1));
    if (v[4]) m->refraction = num_from_double(get_num_range(p, v[4], "refraction", 0.1, 10));
}

static void read_object(struct parser *p, struct build *b, const struct node *n, int idx)
{
    struct rt_object *o = &b->objects[idx];
    const char *what = n->key;
    static const char *const sphere_keys[] = { "color", "specular", "reflective", "transparency", "refraction",
                                               "name", "csg_only", "center", "radius", NULL };
    static const char *const plane_keys[] = { "color", "specular", "reflective", "transparency", "refraction",
                                              "name", "csg_only", "normal", "dist", NULL };
    static const char *const tri_keys[] = { "color", "specular", "reflective", "transparency", "refraction",
                                            "name", "csg_only", "points", NULL };
    const struct node *v[9];
    if (!strcmp(what, "sphere")) {
        fields(p, n, what, sphere_keys, v);
        o->shape = RT_SPHERE;
        o->center = get_vec3(p, need(p, n, v[7], what, "center"), "sphere center");
        double r = get_num(p, need(p, n, v[8], what, "radius"), "sphere radius");
        if (!(r > 0)) FAIL_N(p, v[8], "sphere radius must be > 0, found %.17g", r);
        o->radius = to_num(p, v[8], r, "sphere radius");
    } else if (!strcmp(what, "plane")) {
        fields(p, n, what, plane_keys, v);
        o->shape = RT_PLANE;
        double d[3];
        get_tuple(p, need(p, n, v[7], what, "normal"), "plane normal", 3, d);
        double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(len > 0)) FAIL_N(p, v[7], "plane normal must not be zero");
        o->normal = v3_make(num_from_double(d[0] / len), num_from_double(d[1] / len), num_from_double(d[2] / len));
        o->dist = to_num(p, v[8], get_num(p, need(p, n, v[8], what, "dist"), "plane dist"), "plane dist");
    } else {
        fields(p, n, what, tri_keys, v);
        o->shape = RT_TRIANGLE;
        const struct node *pts = need(p, n, v[7], what, "points");
        if (pts->kind != N_TUPLE || pts->n != 3) FAIL_N(p, pts, "triangle points must be a tuple of 3 points");
        int i = 0;
        for (const struct node *e = pts->first; e; e = e->next, i++) o->p[i] = get_vec3(p, e, "triangle point");
    }
    read_material(p, n, v, what, &o->mat);
    if (v[5]) {
        const char *nm = get_name(p, v[5], "name");
        if (find_named(b->obj_names, idx, nm) >= 0) FAIL_N(p, v[5], "object '%s' is already defined", nm);
        b->obj_names[idx].name = nm;
        b->obj_names[idx].at = v[5];
    }
    if (v[6]) o->csg_only = (uint8_t)get_bool(p, v[6], "csg_only");
}

static int object_ref(struct parser *p, struct build *b, const struct node *n, int nobj, const char *what)
{
    int i;
    if (n->kind == N_NUM) i = (int)get_int(p, n, what, 0, nobj - 1);
    else {
        const char *nm = get_name(p, n, what);
        i = find_named(b->obj_names, nobj, nm);
        if (i < 0) FAIL_N(p, n, "%s: no object named '%s'", what, nm);
    }
    if (b->objects[i].shape != RT_SPHERE) FAIL_N(p, n, "%s: CSG operands must be spheres", what);
    return i;
}

static void read_csg(struct parser *p, struct build *b, const struct node *n, struct rt_csg *c, int nobj)
{
    static const char *const keys[] = { "op", "a", "b", NULL };
    static const char *const ops[] = { "union", "intersection", "difference", NULL };
    const struct node *v[3];
    fields(p, n, "csg", keys, v);
    c->op = (uint8_t)get_choice(p, need(p, n, v[0], "csg", "op"), "csg op", ops);
    c->a = (uint16_t)object_ref(p, b, need(p, n, v[1], "csg", "a"), nobj, "csg a");
    c->b = (uint16_t)object_ref(p, b, need(p, n, v[2], "csg", "b"), nobj, "csg b");
    if (c->a == c->b) FAIL_N(p, v[2], "csg: a and b are the same object");
}

/* ---- the option blocks: scene_options.def ----------------------------------- */

enum opt_kind { OPT_BOOL, OPT_NOT, OPT_INT, OPT_NUM, OPT_CHOICE, OPT_INDEX };

/* A row of scene_options.def, where its member lives in the options struct. */
struct option {
    const char *key;
    size_t offset, size;
    int kind;
    double lo, hi;
    const char *values, *values_error;
    double def;
    int order;
};

#define OPTION_ROW(st, key, field, type, kind, lo, hi, values, values_error, def, order) \
    { key, offsetof(struct st, field), sizeof(type), OPT_##kind, lo, hi, values, values_error, def, order },
static const struct option rt_option_rows[] = {
#define RT_OPTION(key, field, type, kind, lo, hi, values, values_error, def, def_doc, emit_line, order, doc) \
    OPTION_ROW(rt_options, key, field, type, kind, lo, hi, values, values_error, def, order)
#include "scene_options.def"
};
static const struct option ras_option_rows[] = {
#define RAS_OPTION(key, field, type, kind, lo, hi, values, values_error, def, def_doc, emit_line, order, doc) \
    OPTION_ROW(ras_options, key, field, type, kind, lo, hi, values, values_error, def, order)
#include "scene_options.def"
};
#undef OPTION_ROW

/* Every member is a num (kind NUM) or an unsigned integer of one or two bytes. */
#define OPTION_TYPE_CHECK(key, field, type, kind, ...) \
    _Static_assert(OPT_##kind == OPT_NUM ? sizeof(type) == sizeof(num) : sizeof(type) <= 2, "option " key);
#define RT_OPTION OPTION_TYPE_CHECK
#define RAS_OPTION OPTION_TYPE_CHECK
#include "scene_options.def"
#undef OPTION_TYPE_CHECK

#define MAX_OPTIONS 32
#define NROWS(t) (sizeof t / sizeof t[0])
_Static_assert(NROWS(rt_option_rows) <= MAX_OPTIONS && NROWS(ras_option_rows) <= MAX_OPTIONS, "MAX_OPTIONS");

/* One of the '|'-separated names of `list`; returns its index. */
static int get_choice_list(struct parser *p, const struct node *n, const char *what, const char *list)
{
    char buf[256];
    const char *names[MAX_OPTIONS + 1];
    int k = 0;
    snprintf(buf, sizeof buf, "%s", list);
    for (char *c = buf; k < MAX_OPTIONS; c++) {
        names[k++] = c;
        c = strchr(c, '|');
        if (!c) break;
        *c = 0;
    }
    names[k] = NULL;
    return get_choice(p, n, what, names);
}

/* k is one of the '|'-separated numbers or ranges a..b of `set`. */
static int in_set(const char *set, long k)
{
    for (const char *c = set; *c;) {
        char *e;
        long lo = strtol(c, &e, 10), hi = lo;
        if (e[0] == '.' && e[1] == '.') hi = strtol(e + 2, &e, 10);
        if (k >= lo && k <= hi) return 1;
        c = *e == '|' ? e + 1 : e;
    }
    return 0;
}

static void store_option(void *opts, const struct option *o, long k)
{
    unsigned char *at = (unsigned char *)opts + o->offset;
    if (o->size == 1) {
        uint8_t u = (uint8_t)k;
        memcpy(at, &u, 1);
    } else {
        uint16_t u = (uint16_t)k;
        memcpy(at, &u, 2);
    }
}

static void set_defaults(void *opts, const struct option *rows, size_t nrows)
{
    for (const struct option *o = rows; o < rows + nrows; o++) {
        if (o->kind == OPT_NUM) {
            num x = num_from_double(o->def);
            memcpy((unsigned char *)opts + o->offset, &x, sizeof x);
        } else {
            store_option(opts, o, (long)o->def);
        }
    }
}

static void read_option(struct parser *p, const struct node *v, const struct option *o, void *opts)
{
    long k;
    switch (o->kind) {
    case OPT_NUM: {
        num x = to_num(p, v, get_num_range(p, v, o->key, o->lo, o->hi), o->key);
        memcpy((unsigned char *)opts + o->offset, &x, sizeof x);
        return;
    }
    case OPT_BOOL: k = get_bool(p, v, o->key); break;
    case OPT_NOT: k = !get_bool(p, v, o->key); break;
    case OPT_CHOICE: k = get_choice_list(p, v, o->key, o->values); break;
    case OPT_INDEX: k = get_int(p, v, o->key, (long)o->lo, (long)o->hi) + 1; break;
    default:
        k = get_int(p, v, o->key, (long)o->lo, (long)o->hi);
        if (o->values && !in_set(o->values, k)) FAIL_N(p, v, "%s", o->values_error);
        break;
    }
    store_option(opts, o, k);
}

/* The block `what` of the options in `rows` into opts: unknown and duplicate
 * keys first, then each value given, in the rows' `order`. */
static void read_options(struct parser *p, const struct node *n, const char *what, const struct option *rows,
                         size_t nrows, void *opts)
{
    const char *keys[MAX_OPTIONS + 1];
    const struct node *v[MAX_OPTIONS];
    for (size_t i = 0; i < nrows; i++) keys[i] = rows[i].key;
    keys[nrows] = NULL;
    fields(p, n, what, keys, v);
    for (int k = 1; k <= (int)nrows; k++)
        for (size_t i = 0; i < nrows; i++)
            if (v[i] && rows[i].order == k) read_option(p, v[i], &rows[i], opts);
}

/* ---- models --------------------------------------------------------------- */

/* cos(i·δ), sin(i·δ) for δ = 2π/15 as the demos compute them (docs/book-demos.md). */
static const double sphere15_cos[15] = {
    1.0, 0.91354545764260087, 0.66913060635885824, 0.30901699437494745, -0.10452846326765333,
    -0.49999999999999978, -0.80901699437494734, -0.97814760073380558, -0.97814760073380569,
    -0.80901699437494745, -0.50000000000000044, -0.10452846326765423, 0.30901699437494723,
    0.66913060635885779, 0.91354545764260053,
};
static const double sphere15_sin[15] = {
    0.0, 0.40673664307580015, 0.74314482547739424, 0.95105651629515353, 0.99452189536827340,
    0.86602540378443871, 0.58778525229247325, 0.20791169081775973, -0.20791169081775907,
    -0.58778525229247303, -0.86602540378443849, -0.99452189536827329, -0.95105651629515364,
    -0.74314482547739458, -0.40673664307580093,
};

/* The book's GenerateSphere(divs, colour): divs+1 rings of divs vertices;
 * variant 0 ("s450") wraps around, variant 1 ("s420") leaves the last
 * column open as the raster-rt-scene demo does. Normals are the vertex
 * positions; bound: centre 0, radius 1. */
static void gen_sphere(struct parser *p, const struct node *at, struct ras_model *m, int divs, int variant, rgb col)
{
    int nv = (divs + 1) * divs;
    int nt = variant == 0 ? 2 * divs * divs : 2 * divs * (divs - 1);
    vec3 *verts = alloc_array(p, (size_t)nv, sizeof *verts);
    struct ras_triangle *tris = alloc_array(p, (size_t)nt, sizeof *tris);
    double delta = (2 * 3.141592653589793) / divs;
    for (int d = 0; d <= divs; d++) {
        double y = (2.0 / divs) * (d - divs / 2.0);
        double r = sqrt(1 - y * y);
        for (int i = 0; i < divs; i++) {
            double c = divs == 15 ? sphere15_cos[i] : cos(i * delta);
            double s = divs == 15 ? sphere15_sin[i] : sin(i * delta);
            verts[divs * d + i] = v3_make(to_num(p, at, r * c, "sphere vertex"), to_num(p, at, y, "sphere vertex"),
                                          to_num(p, at, r * s, "sphere vertex"));
        }
    }
    int t = 0;
    for (int d = 0; d < divs; d++)
        for (int i = 0; i < (variant == 0 ? divs : divs - 1); i++) {
            int i0 = divs * d + i, idx[2][3];
            if (variant == 0) {
                int i1 = divs * (d + 1) + (i + 1) % divs, i2 = divs * d + (i + 1) % divs;
                int a[2][3] = { { i0, i1, i2 }, { i0, i0 + divs, i1 } };
                memcpy(idx, a, sizeof idx);
            } else {
                int a[2][3] = { { i0, i0 + divs + 1, i0 + 1 }, { i0, i0 + divs, i0 + divs + 1 } };
                memcpy(idx, a, sizeof idx);
            }
            for (int k = 0; k < 2; k++, t++) {
                for (int c = 0; c < 3; c++) {
                    tris[t].v[c] = (uint16_t)idx[k][c];
                    tris[t].n[c] = verts[idx[k][c]];
                }
                tris[t].color = col;
            }
        }
    m->nverts = (uint16_t)nv;
    m->ntris = (uint16_t)nt;
    m->verts = verts;
    m->tris = tris;
    m->has_normals = 1;
    m->has_uvs = 0;
    m->bound_center = v3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    m->bound_radius = NUM_ONE;
}

static void read_triangle(struct parser *p, const struct node *e, struct ras_triangle *t, int nverts,
                          int *has_col, int *has_n, int *has_uv, rgb model_col, int model_has_col)
{
    if (e->kind != N_TUPLE) FAIL_N(p, e, "a triangle must be a tuple (i0, i1, i2, color = ...), found %s",
                                   kind_names[e->kind]);
    int k = 0, got_n = 0, got_uv = 0, got_col = 0;
    const struct node *seen[4] = { NULL, NULL, NULL, NULL };
    for (const struct node *c = e->first; c; c = c->next) {
        if (!c->key) {
            if (k >= 3) FAIL_N(p, c, "a triangle has 3 vertex indices");
            if (seen[0] || seen[1] || seen[2] || seen[3]) FAIL_N(p, c, "vertex indices come before the keys");
            t->v[k++] = (uint16_t)get_int(p, c, "vertex index", 0, nverts - 1);
            continue;
        }
        int which = !strcmp(c->key, "color") ? 0 : !strcmp(c->key, "normal") ? 1 : !strcmp(c->key, "normals") ? 2
                  : !strcmp(c->key, "uv") ? 3 : -1;
        if (which < 0) {
            static const char *const tri_keys[] = { "color", "normal", "normals", "uv", NULL };
            const char *near = suggest_nearest(c->key, tri_keys);
            FAIL_K(p, c, "unknown key '%s' in triangle%s%s%s", c->key, near ? " (did you mean '" : "",
                   near ? near : "", near ? "'?)" : "");
        }
        int slot = which == 2 ? 1 : which;
        if (seen[slot]) FAIL_K(p, c, "duplicate '%s' in triangle (first at %d:%d)", c->key, seen[slot]->kline,
                               seen[slot]->kcol);
        seen[slot] = c;
        if (which == 0) { t->color = get_rgb(p, c, "triangle color"); got_col = 1; }
        else if (which == 1) {
            vec3 nn = get_vec3(p, c, "triangle normal");
            t->n[0] = t->n[1] = t->n[2] = nn;
            got_n = 1;
        } else if (which == 2) {
            if (c->kind != N_TUPLE || c->n != 3) FAIL_N(p, c, "normals must be a tuple of 3 vectors");
            int i = 0;
            for (const struct node *q = c->first; q; q = q->next, i++) t->n[i] = get_vec3(p, q, "normal");
            got_n = 1;
        } else {
            if (c->kind != N_TUPLE || c->n != 3) FAIL_N(p, c, "uv must be a tuple of 3 (u, v) pairs");
            int i = 0;
            for (const struct node *q = c->first; q; q = q->next, i++) {
                double uv[2];
                get_tuple(p, q, "uv", 2, uv);
                t->uv[i].u = to_num(p, q, uv[0], "u");
                t->uv[i].v = to_num(p, q, uv[1], "v");
            }
            got_uv = 1;
        }
    }
    if (k < 3) FAIL_N(p, e, "a triangle needs 3 vertex indices, found %d", k);
    if (!got_col) {
        if (!model_has_col) FAIL_N(p, e, "triangle: missing 'color' (and the model has no default color)");
        t->color = model_col;
    }
    if (*has_n < 0) *has_n = got_n;
    else if (*has_n != got_n) FAIL_N(p, e, "triangle: either every triangle of a model has normals or none");
    if (*has_uv < 0) *has_uv = got_uv;
    else if (*has_uv != got_uv) FAIL_N(p, e, "triangle: either every triangle of a model has uv or none");
    (void)has_col;
}

/* The default bounding sphere of n points (get(pts, i, q) gives point i):
 * the centre of their bounding box, the radius to the farthest point; the
 * square of the radius in *r2. */
static void box_sphere(const void *pts, int n, void (*get)(const void *, int, double *), double c[3], double *r2)
{
    double lo[3], hi[3], q[3];
    for (int k = 0; k < 3; k++) { lo[k] = 1e300; hi[k] = -1e300; }
    for (int i = 0; i < n; i++) {
        get(pts, i, q);
        for (int k = 0; k < 3; k++) {
            if (q[k] < lo[k]) lo[k] = q[k];
            if (q[k] > hi[k]) hi[k] = q[k];
        }
    }
    for (int k = 0; k < 3; k++) c[k] = (lo[k] + hi[k]) / 2;
    *r2 = 0;
    for (int i = 0; i < n; i++) {
        get(pts, i, q);
        double dx = q[0] - c[0], dy = q[1] - c[1], dz = q[2] - c[2];
        double d2 = dx * dx + dy * dy + dz * dz;
        if (d2 > *r2) *r2 = d2;
    }
}

static void vec3_point(const void *pts, int i, double *q)
{
    const vec3 *v = (const vec3 *)pts + i;
    q[0] = num_to_double(v->x);
    q[1] = num_to_double(v->y);
    q[2] = num_to_double(v->z);
}

/* A model's default bound: box_sphere of its vertices. */
static void default_bound(struct parser *p, const struct node *at, struct ras_model *m)
{
    double c[3], r2;
    box_sphere(m->verts, m->nverts, vec3_point, c, &r2);
    m->bound_center = v3_make(num_from_double(c[0]), num_from_double(c[1]), num_from_double(c[2]));
    m->bound_radius = to_num(p, at, sqrt(r2), "bounding radius");
}

static void read_bound(struct parser *p, const struct node *n, struct ras_model *m)
{
    static const char *const bkeys[] = { "center", "radius", NULL };
    const struct node *bv[2];
    fields(p, n, "bound", bkeys, bv);
    m->bound_center = get_vec3(p, need(p, n, bv[0], "bound", "center"), "bound center");
    double r = get_num(p, need(p, n, bv[1], "bound", "radius"), "bound radius");
    if (!(r >= 0)) FAIL_N(p, bv[1], "bound radius must be >= 0");
    m->bound_radius = to_num(p, bv[1], r, "bound radius");
}

static void read_obj_model(struct parser *p, struct build *b, const struct node *n, const struct node *file,
                           const struct node *fit, const struct node *color, const struct node *bound);

static void read_model(struct parser *p, struct build *b, const struct node *n)
{
    static const char *const keys[] = { "name", "vertices", "triangles", "generate", "divs", "variant", "color",
                                        "bound", "file", "fit", NULL };
    static const char *const gens[] = { "sphere", NULL };
    static const char *const variants[] = { "s450", "s420", NULL };
    const struct node *v[10];
    more_models(p, b, n, 1);
    int idx = b->nmodels;
    struct ras_model *m = &b->models[idx];
    fields(p, n, "model", keys, v);
    const char *nm = get_name(p, need(p, n, v[0], "model", "name"), "model name");
    if (find_named(b->model_names, idx, nm) >= 0) FAIL_N(p, v[0], "model '%s' is already defined", nm);
    b->model_names[idx].name = nm;
    b->model_names[idx].at = v[0];
    b->model_names[idx].parts = 1;
    b->model_names[idx].tex = -1;
    m->name = nm;
    if (v[8]) {
        for (int k = 1; k <= 5; k++)
            if (v[k]) FAIL_K(p, v[k], "a model read from a file has no '%s'", keys[k]);
        read_obj_model(p, b, n, v[8], v[9], v[6], v[7]);
        return;
    }
    if (v[9]) FAIL_K(p, v[9], "'fit' is for models read from a file");
    b->nmodels++;
    rgb col = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    if (v[6]) col = get_rgb(p, v[6], "model color");
    if (v[3]) {
        get_choice(p, v[3], "generate", gens);
        if (v[1]) FAIL_K(p, v[1], "a generated model has no 'vertices'");
        if (v[2]) FAIL_K(p, v[2], "a generated model has no 'triangles'");
        int divs = (int)get_int(p, need(p, n, v[4], "model", "divs"), "divs", 3, 128);
        int variant = v[5] ? get_choice(p, v[5], "variant", variants) : 0;
        if (!v[6]) need(p, n, v[6], "generated model", "color");
        gen_sphere(p, v[3], m, divs, variant, col);
    } else {
        if (v[4]) FAIL_K(p, v[4], "'divs' needs 'generate'");
        if (v[5]) FAIL_K(p, v[5], "'variant' needs 'generate'");
        const struct node *vs = need(p, n, v[1], "model", "vertices");
        const struct node *ts = need(p, n, v[2], "model", "triangles");
        if (vs->kind != N_BLOCK) FAIL_N(p, vs, "vertices must be a block { (x, y, z) ... }");
        if (ts->kind != N_BLOCK) FAIL_N(p, ts, "triangles must be a block { (i0, i1, i2, color = ...) ... }");
        if (vs->n == 0) FAIL_N(p, vs, "model '%s' has no vertices", nm);
        if (ts->n == 0) FAIL_N(p, ts, "model '%s' has no triangles", nm);
        if (vs->n > MAX_VERTS) FAIL_N(p, vs, "more than %d vertices", MAX_VERTS);
        if (ts->n > MAX_TRIS) FAIL_N(p, ts, "more than %d triangles", MAX_TRIS);
        vec3 *verts = alloc_array(p, (size_t)vs->n, sizeof *verts);
        int i = 0;
        for (const struct node *e = vs->first; e; e = e->next, i++) {
            if (e->key) FAIL_K(p, e, "unexpected key '%s' in vertices", e->key);
            verts[i] = get_vec3(p, e, "vertex");
        }
        struct ras_triangle *tris = alloc_array(p, (size_t)ts->n, sizeof *tris);
        int has_n = -1, has_uv = -1, has_col = 0;
        i = 0;
        for (const struct node *e = ts->first; e; e = e->next, i++) {
            if (e->key) FAIL_K(p, e, "unexpected key '%s' in triangles", e->key);
            read_triangle(p, e, &tris[i], vs->n, &has_col, &has_n, &has_uv, col, v[6] != NULL);
        }
        m->nverts = (uint16_t)vs->n;
        m->ntris = (uint16_t)ts->n;
        m->verts = verts;
        m->tris = tris;
        m->has_normals = (uint8_t)has_n;
        m->has_uvs = (uint8_t)has_uv;
        /* Default bound: centre of the bounding box, radius to the farthest vertex. */
        default_bound(p, vs, m);
    }
    if (v[7]) read_bound(p, v[7], m);
}

/* ---- textures ---------------------------------------------------------------- */

/* A wooden crate, procedurally: planks with grain, a dark frame and an X
 * brace (stands in for the demo's crate-texture.jpg). Integer arithmetic
 * only, so every build gets the same bytes. */
/* A tangent-space normal map of round bumps, one per sq x sq cell: red
 * along +x (+u), green toward the top of the image, blue out of the
 * surface; channel = 127.5 * (component + 1). */
static void gen_bumps(uint8_t *px, int w, int h, int sq)
{
    double r = sq * 0.4;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double dx = (x % sq) + 0.5 - sq * 0.5, dy = (y % sq) + 0.5 - sq * 0.5;
            double nx = 0, ny = 0, nz = 1, d2 = dx * dx + dy * dy;
            if (d2 < r * r) {
                /* a spherical cap: the normal is the offset from its centre */
                double hz = sqrt(r * r - d2);
                double len = sqrt(d2 + hz * hz);
                nx = dx / len;
                ny = -dy / len;   /* image rows grow downward */
                nz = hz / len;
            }
            uint8_t *o = px + 3 * ((size_t)y * w + x);
            o[0] = (uint8_t)floor(127.5 * (nx + 1) + 0.5);
            o[1] = (uint8_t)floor(127.5 * (ny + 1) + 0.5);
            o[2] = (uint8_t)floor(127.5 * (nz + 1) + 0.5);
        }
}

static void gen_crate(uint8_t *px, int w, int h)
{
    int fw = w / 10, fh = h / 10, brace = (w < h ? w : h) / 14;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int plank = x * 6 / w;
            uint32_t hsh = (uint32_t)(x * 7 + plank * 131) * 2654435761u;
            int grain = (int)((hsh >> 28) & 7) + (int)(((unsigned)(y * 3 + plank * 57) % 23) < 3 ? 10 : 0);
            int r = 150 + plank * 5 - grain, g = 116 + plank * 3 - grain, bl = 80 - grain;
            int edge = (x * 6) % w < 6;                 /* gap between planks */
            /* distance to the diagonals, in pixels (scaled by w to stay integer) */
            long d1 = labs((long)x * h - (long)y * w), d2 = labs((long)x * h - (long)(h - 1 - y) * w);
            int on_brace = d1 < (long)brace * w || d2 < (long)brace * w;
            int on_frame = x < fw || x >= w - fw || y < fh || y >= h - fh;
            if (on_frame || on_brace) { r = 112 - grain; g = 80 - grain; bl = 52 - grain; }
            if ((on_frame && (x == fw || x == w - fw - 1 || y == fh || y == h - fh - 1)) || (!on_frame && edge)) {
                r = 60; g = 40; bl = 24;
            }
            px[3 * ((size_t)y * w + x) + 0] = (uint8_t)r;
            px[3 * ((size_t)y * w + x) + 1] = (uint8_t)g;
            px[3 * ((size_t)y * w + x) + 2] = (uint8_t)bl;
        }
}

/* dir + name into path[FILE_PATH_MAX]: the name of a file the scene reads (`what` says which
 * kind in messages) is a relative path inside the scene's directory, of letters, digits, '_',
 * '-', '.' and '/'. */
#define FILE_PATH_MAX 1400

static void file_path(struct parser *p, const struct where *at, const char *what, const char *dir, const char *name,
                      char *path)
{
    if (!*name || name[0] == '/' || strstr(name, ".."))
        FAIL_W(p, at, "%s '%s' must be a relative path inside the scene's directory", what, name);
    for (const char *c = name; *c; c++)
        if (!(is_alpha(*c) || is_digit(*c) || *c == '.' || *c == '/' || *c == '-'))
            FAIL_W(p, at, "%s name '%s' has a character other than letters, digits, '_', '-', '.', '/'", what, name);
    size_t nd = strlen(dir), nn = strlen(name);
    if (nd + nn >= FILE_PATH_MAX) FAIL_W(p, at, "%s path '%s%s' is too long", what, dir, name);
    memcpy(path, dir, nd);
    memcpy(path + nd, name, nn + 1);
#ifdef HAVE_POSIX_FILES
    /* a regular file (a FIFO or a device would block the parse or never
       end), and inside the scene's directory once every symbolic link is
       resolved; a path that does not exist is left to the open's message */
    struct stat st;
    if (stat(path, &st)) return;
    if (S_ISDIR(st.st_mode)) FAIL_W(p, at, "%s '%s' is a directory", what, path);
    if (!S_ISREG(st.st_mode)) FAIL_W(p, at, "%s '%s' is not a regular file (a FIFO or a device)", what, path);
    char *real = realpath(path, NULL), *top = realpath(p->dir[0] ? p->dir : ".", NULL);
    size_t nt = top ? strlen(top) : 0;
    int inside = real && top && !strncmp(real, top, nt) && (real[nt] == '/' || (nt == 1 && top[0] == '/'));
    free(real);
    free(top);
    if (!inside)
        FAIL_W(p, at, "%s '%s' leads outside the scene's directory (through a symbolic link)", what, name);
#endif
}

/* Opens path into slot k of p->files, which a failed parse closes. */
static FILE *open_file(struct parser *p, int k, const char *path)
{
    p->files[k] = fopen(path, "rb");
    return p->files[k];
}

/* Ends the parse for a file that did not open (errno from fopen): the
 * message names the path looked at, made absolute where the host can say
 * from where, and why it failed. */
static void fail_open(struct parser *p, const struct where *at, const char *what, const char *path,
                      const char *relative_to)
{
    const char *why = strerror(errno);
    char cwd[512] = "";
#ifdef HAVE_GETCWD
    if (path[0] != '/' && !getcwd(cwd, sizeof cwd)) cwd[0] = 0;
#endif
    FAIL_W(p, at, "cannot open %s '%s%s%s': %s (its path is relative to the %s's directory)", what, cwd,
           cwd[0] ? "/" : "", path, why, relative_to);
}

static void close_file(struct parser *p, int k)
{
    if (p->files[k]) fclose(p->files[k]);
    p->files[k] = NULL;
}

/* Binary PPM (P6, maxval 255). */
static uint8_t *read_ppm(struct parser *p, const struct where *at, FILE *f, const char *path, int *w, int *h)
{
    int maxv = 0;
    char magic[3] = { 0 };
    if (fscanf(f, "%2s %d %d %d", magic, w, h, &maxv) != 4 || strcmp(magic, "P6") || maxv != 255 ||
        fgetc(f) < 0 || *w < 1 || *h < 1 || *w > MAX_TEX_SIDE || *h > MAX_TEX_SIDE)
        FAIL_W(p, at, "'%s' is not a binary PPM (P6, maxval 255) or a PNG of at most %dx%d", path, MAX_TEX_SIDE,
               MAX_TEX_SIDE);
    size_t n = (size_t)*w * (size_t)*h * 3;
    uint8_t *px = alloc(p, n);
    size_t got = fread(px, 1, n, f);
    if (got != n) FAIL_W(p, at, "'%s' is truncated (%zu of %zu pixel bytes)", path, got, n);
    return px;
}

/* PNG through libpng, which host builds link (WITH_PNG); the benchmark
 * images that parse scenes on an emulated MCU have no libpng. Any PNG
 * colour type and depth comes out as 8-bit RGB; alpha is composited onto
 * black. */
static uint8_t *read_png(struct parser *p, const struct where *at, FILE *f, const char *path, int *w, int *h)
{
#ifdef WITH_PNG
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_stdio(&im, f)) FAIL_W(p, at, "'%s' is not a valid PNG: %s", path, im.message);
    if (im.width < 1 || im.height < 1 || im.width > MAX_TEX_SIDE || im.height > MAX_TEX_SIDE) {
        png_image_free(&im);
        FAIL_W(p, at, "'%s' is %ux%u: images are at most %dx%d", path, (unsigned)im.width, (unsigned)im.height,
               MAX_TEX_SIDE, MAX_TEX_SIDE);
    }
    *w = (int)im.width;
    *h = (int)im.height;
    im.format = PNG_FORMAT_RGB;
    uint8_t *px = alloc(p, (size_t)*w * (size_t)*h * 3);   /* zeroed: the black that alpha is composited onto */
    if (!png_image_finish_read(&im, NULL, px, 0, NULL)) FAIL_W(p, at, "'%s': %s", path, im.message);
    return px;
#else
    (void)f;
    (void)w;
    (void)h;
    FAIL_W(p, at, "'%s': PNG textures need the host build (libpng); this build reads binary PPM (P6) only", path);
    return NULL;
#endif
}

/* An image file at path, binary PPM or PNG (by its first bytes). */
static uint8_t *load_image(struct parser *p, const struct where *at, const char *path, int *w, int *h)
{
    static const unsigned char png_sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
    unsigned char sig[8];
    FILE *f = open_file(p, 2, path);
    if (!f) fail_open(p, at, "image file", path, "scene file");
    size_t n = fread(sig, 1, sizeof sig, f);
    rewind(f);
    uint8_t *px = n == sizeof sig && !memcmp(sig, png_sig, sizeof sig) ? read_png(p, at, f, path, w, h)
                                                                      : read_ppm(p, at, f, path, w, h);
    close_file(p, 2);
    return px;
}

/* The texture's mipmap chain down to 1x1 (firmware/core/mipmap.h). */
static void make_mips(struct parser *p, struct ras_texture *t, const uint8_t *base)
{
    unsigned levels = mip_levels(t->w, t->h), w = t->w, h = t->h;
    const uint8_t **mip = alloc_array(p, levels, sizeof *mip);
    mip[0] = base;
    for (unsigned l = 1; l < levels; l++) {
        uint8_t *m = alloc(p, (size_t)mip_side(w) * mip_side(h) * 3);
        mip_next(mip[l - 1], w, h, m);
        mip[l] = m;
        w = mip_side(w);
        h = mip_side(h);
    }
    t->mip_levels = (uint8_t)levels;
    t->mip = mip;
}

static void read_texture(struct parser *p, struct build *b, const struct node *n)
{
    static const char *const keys[] = { "name", "generate", "file", "width", "height", "square", "filter", "mipmaps",
                                        NULL };
    static const char *const gens[] = { "checkerboard", "crate", "bumps", NULL };
    static const char *const filters[] = { "nearest", "bilinear", "trilinear", "book_bilinear", NULL };
    const struct node *v[8];
    struct where at = node_where(p, n);
    more_textures(p, b, &at, 1);
    int idx = b->ntextures;
    struct ras_texture *t = &b->textures[idx];
    fields(p, n, "texture", keys, v);
    const char *nm = get_name(p, need(p, n, v[0], "texture", "name"), "texture name");
    if (find_named(b->tex_names, idx, nm) >= 0) FAIL_N(p, v[0], "texture '%s' is already defined", nm);
    b->tex_names[idx].name = nm;
    b->tex_names[idx].at = v[0];
    uint8_t *px;
    int w, h;
    if (v[1] && v[2]) FAIL_K(p, v[2], "a texture has either 'generate' or 'file'");
    if (v[1]) {
        int g = get_choice(p, v[1], "generate", gens);
        w = (int)get_int(p, need(p, n, v[3], "texture", "width"), "texture width", 1, MAX_TEX_SIDE);
        h = (int)get_int(p, need(p, n, v[4], "texture", "height"), "texture height", 1, MAX_TEX_SIDE);
        px = alloc(p, (size_t)w * h * 3);
        if (g == 0) {
            int sq = v[5] ? (int)get_int(p, v[5], "square", 1, MAX_TEX_SIDE) : 10;
            for (int y = 0; y < h; y++)
                for (int x = 0; x < w; x++) memset(px + 3 * ((size_t)y * w + x), ((x / sq + y / sq) % 2) ? 0 : 255, 3);
        } else if (g == 1) {
            if (v[5]) FAIL_K(p, v[5], "'square' is for checkerboard textures");
            gen_crate(px, w, h);
        } else {
            int sq = v[5] ? (int)get_int(p, v[5], "square", 2, MAX_TEX_SIDE) : 16;
            gen_bumps(px, w, h, sq);
        }
    } else if (v[2]) {
        if (v[3] || v[4] || v[5]) FAIL_K(p, v[3] ? v[3] : v[4] ? v[4] : v[5], "an image file has its own size");
        if (v[2]->kind != N_STR) FAIL_N(p, v[2], "file must be a string \"name.ppm\" or \"name.png\"");
        if (!p->has_dir) FAIL_N(p, v[2], "image files need a scene file (no directory to look in)");
        struct where at = node_where(p, v[2]);
        char path[FILE_PATH_MAX];
        file_path(p, &at, "image file", p->dir, v[2]->text, path);
        px = load_image(p, &at, path, &w, &h);
    } else {
        need(p, n, NULL, "texture", "generate' or 'file");
        return;
    }
    t->w = (uint16_t)w;
    t->h = (uint16_t)h;
    t->rgb = px;
    t->filter = v[6] ? (uint8_t)get_choice(p, v[6], "filter", filters) : TEX_NEAREST;
    t->mip_levels = 1;
    if ((v[7] && get_bool(p, v[7], "mipmaps")) || t->filter == TEX_TRILINEAR) make_mips(p, t, px);
    b->ntextures++;
}

/* ---- models from Wavefront OBJ files --------------------------------------------- */

/* `model { name = knot file = "knot.obj" }` (docs/scene-format.md,
 * "model"). The file is read through stdio twice, a statement at a time: the
 * first pass counts vertices, texture coordinates, normals and triangles
 * (each face fan-triangulated) per part and reads the material files; the
 * second stores them, positions as doubles until `fit` has scaled them.
 * A part is the faces of one texture (map_Kd, or none): each part is a
 * model of its own, the first under the model's name, and an instance of
 * the model is one instance per part (read_instance). */

#define OBJ_LINE_MAX   8192            /* bytes of a statement, continuation lines joined */
#define OBJ_SEGS       64              /* physical lines of one statement */
#define MAX_TEX_VERTS  (3 * MAX_TRIS)  /* vt and vn of a file: every corner its own */
#define MAX_MATERIALS  256
#define MAX_PARTS      (MAX_TEXTURES + 1)

/* The statements of an OBJ or MTL file, read in blocks. */
struct obj_reader {
    struct parser *p;
    FILE *f;
    const char *path;                  /* for messages */
    int line;                          /* physical lines read */
    int eof;
    size_t in_len, in_pos, len, pos, tok_off;
    int nseg, seg_line[OBJ_SEGS];      /* where each physical line of the statement begins */
    size_t seg_off[OBJ_SEGS];
    unsigned char in[4096];
    char buf[OBJ_LINE_MAX + 1];        /* the statement; tokens are NUL-terminated in place */
};

static struct where obj_where(const struct obj_reader *r, size_t off)
{
    int k = 0;
    while (k + 1 < r->nseg && r->seg_off[k + 1] <= off) k++;
    struct where w = { r->path, r->seg_line[k], (int)(off - r->seg_off[k]) + 1 };
    return w;
}

/* An error at byte `off` of the statement. */
static void obj_fail(struct obj_reader *r, size_t off, const char *fmt, ...)
{
    struct where w = obj_where(r, off);
    va_list ap;
    va_start(ap, fmt);
    set_error(r->p, w.file, w.line, w.col, fmt, ap);
    va_end(ap);
    longjmp(r->p->fail, 1);
}

static void obj_open(struct obj_reader *r, struct parser *p, FILE *f, const char *path)
{
    r->p = p;
    r->f = f;
    r->path = path;
    r->line = 0;
    r->eof = 0;
    r->in_len = r->in_pos = 0;
}

static int obj_byte(struct obj_reader *r)
{
    if (r->in_pos == r->in_len) {
        if (r->eof) return -1;
        r->in_len = fread(r->in, 1, sizeof r->in, r->f);
        r->in_pos = 0;
        if (r->in_len == 0) {
            if (ferror(r->f)) fail_in(r->p, r->path, r->line, 1, "read error");
            r->eof = 1;
            return -1;
        }
    }
    return r->in[r->in_pos++];
}

/* Blanks separate tokens; NUL ends a token cut from the statement. */
static int obj_blank(int c) { return c == ' ' || c == '\t' || c == '\r' || c == 0; }

/* The next statement that is not blank into r->buf: comments ('#' at the
 * start of a line or after a blank) removed, a line ending in '\' joined
 * with the next, CR and a UTF-8 byte order mark dropped. 0 at the end. */
static int obj_statement(struct obj_reader *r)
{
    for (;;) {
        size_t len = 0;
        int c = 0, more;
        r->nseg = 0;
        do {
            if (r->nseg == OBJ_SEGS) fail_in(r->p, r->path, r->line, 1, "more than %d continued lines", OBJ_SEGS);
            size_t start = len;
            r->seg_off[r->nseg] = len;
            r->seg_line[r->nseg++] = ++r->line;
            while ((c = obj_byte(r)) >= 0 && c != '\n') {
                if (len == OBJ_LINE_MAX)
                    fail_in(r->p, r->path, r->line, 1, "statement longer than %d bytes", OBJ_LINE_MAX);
                if (c < 32 && c != '\t' && c != '\r')
                    fail_in(r->p, r->path, r->line, (int)(len - start) + 1, "unexpected byte 0x%02x", c);
                r->buf[len++] = (char)c;
            }
            if (r->line == 1 && len >= 3 && !memcmp(r->buf, "\xEF\xBB\xBF", 3)) {
                memmove(r->buf, r->buf + 3, len - 3);
                len -= 3;
            }
            for (size_t i = start; i < len; i++)
                if (r->buf[i] == '#' && (i == start || obj_blank(r->buf[i - 1]))) {
                    len = i;
                    break;
                }
            while (len > start && r->buf[len - 1] == '\r') len--;
            more = c >= 0 && len > start && r->buf[len - 1] == '\\';
            if (more) r->buf[len - 1] = ' ';
        } while (more);
        r->buf[len] = 0;
        r->len = len;
        r->pos = 0;
        for (size_t i = 0; i < len; i++)
            if (!obj_blank(r->buf[i])) return 1;
        if (c < 0) return 0;
    }
}

/* The next token of the statement (NULL: none left); its offset in r->tok_off. */
static char *obj_tok(struct obj_reader *r)
{
    char *s = r->buf;
    while (r->pos < r->len && obj_blank(s[r->pos])) r->pos++;
    if (r->pos >= r->len) return NULL;
    r->tok_off = r->pos;
    while (r->pos < r->len && !obj_blank(s[r->pos])) r->pos++;
    if (r->pos < r->len) s[r->pos++] = 0;
    return s + r->tok_off;
}

/* The rest of the statement, blanks around it removed (names may hold spaces). */
static char *obj_rest(struct obj_reader *r)
{
    char *s = r->buf;
    while (r->pos < r->len && obj_blank(s[r->pos])) r->pos++;
    size_t end = r->len;
    while (end > r->pos && obj_blank(s[end - 1])) end--;
    s[end] = 0;
    r->tok_off = r->pos;
    r->pos = r->len;
    return s + r->tok_off;
}

/* A number of the file: the scene's notation ([+-] digits [. digits] [e [+-] digits]). */
static double obj_num(struct obj_reader *r, const char *t, const char *what)
{
    const char *c = t;
    int digits = 0;
    if (*c == '+' || *c == '-') c++;
    while (is_digit(*c)) { c++; digits++; }
    if (*c == '.') {
        c++;
        while (is_digit(*c)) { c++; digits++; }
    }
    if (digits && (*c == 'e' || *c == 'E')) {
        c++;
        if (*c == '+' || *c == '-') c++;
        if (!is_digit(*c)) digits = 0;
        while (is_digit(*c)) c++;
    }
    size_t off = (size_t)(t - r->buf);
    if (!digits || *c) obj_fail(r, off, "%s: '%s' is not a number", what, t);
    errno = 0;
    double d = strtod(t, NULL);
    if (!isfinite(d)) obj_fail(r, off, "%s: number %s is too large", what, t);
    if ((errno == ERANGE && d == 0) || (d != 0 && fabs(d) < DBL_MIN))
        obj_fail(r, off, "%s: number %s is too small (under %g, it would be read as 0)", what, t, DBL_MIN);
    return d;
}

/* Up to max numbers of the statement into d, their offsets into off; how many there were. */
static int obj_nums(struct obj_reader *r, const char *what, double *d, size_t *off, int max)
{
    int n = 0;
    for (char *t; (t = obj_tok(r)); n++) {
        if (n == max) obj_fail(r, r->tok_off, "%s has at most %d numbers", what, max);
        off[n] = r->tok_off;
        d[n] = obj_num(r, t, what);
    }
    return n;
}

static num obj_to_num(struct obj_reader *r, size_t off, double d, const char *what)
{
    struct where w = obj_where(r, off);
    return to_num_at(r->p, &w, d, what);
}

struct obj_mtl {
    const char *name;
    int has_kd;
    double kd[3];
    const char *map;                   /* map_Kd: the image's path; NULL: none */
    struct where map_at;               /* where the material file names it */
    int part;                          /* the part of its faces; -1: no face uses it yet */
};

struct obj_part {
    int mtl;                           /* the material whose map_Kd is the part's texture; -1: none */
    int ntris, first, next;            /* its triangles: tris[first .. first + ntris) */
    int has_uv, has_n, line;           /* -1 until its first face (at line) */
};

struct obj_model {
    struct obj_mtl *mtl;
    int nmtl, cur;                     /* cur: the material of the faces (usemtl); -1: none */
    struct obj_part part[MAX_PARTS];
    int nparts, ntex, nopart;          /* nopart: the part of faces without a material (-1: none yet) */
    int nv, nvt, nvn, ntris;           /* totals of the file (pass 1, within the limits) */
    int sv, svt, svn;                  /* counts so far (pass 2) */
    double *pos;                       /* pass 2: x, y, z of each vertex */
    struct tri_uv *uv;
    vec3 *nrm;
    struct ras_triangle *tris;
    int has_col;                       /* the model's `color`, for faces without Kd */
    rgb col;
    int check_range;                   /* no `fit`: positions must be numbers of the build as written */
};

/* The directory part of path (up to its last '/'), into dir[FILE_PATH_MAX]. */
static void dir_of(const char *path, char *dir)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) + 1 : 0;
    memcpy(dir, path, n);
    dir[n] = 0;
}

static const char *const mtl_skipped[] = {
    "Ka", "Ks", "Ke", "Ns", "Ni", "d", "Tr", "Tf", "illum", "sharpness", "map_Ka", "map_Ks", "map_Ke", "map_Ns",
    "map_d", "map_bump", "map_Bump", "bump", "disp", "decal", "refl", "norm", "Pr", "Pm", "Ps", "Pc", "Pcr",
    "aniso", "anisor", "map_Pr", "map_Pm", "map_Ps", NULL,
};

static int in_list(const char *const *list, const char *s)
{
    for (int i = 0; list[i]; i++)
        if (!strcmp(list[i], s)) return 1;
    return 0;
}

/* A material file: newmtl, Kd (the colour), map_Kd (the texture); the
 * statements of mtl_skipped are read past. */
static void read_mtl(struct obj_model *om, struct obj_reader *r)
{
    struct parser *p = r->p;
    struct obj_mtl *cur = NULL;
    char dir[FILE_PATH_MAX];
    dir_of(r->path, dir);
    while (obj_statement(r)) {
        char *k = obj_tok(r);
        size_t ko = r->tok_off;
        if (!strcmp(k, "newmtl")) {
            char *nm = obj_rest(r);
            if (!*nm) obj_fail(r, ko, "newmtl needs a name");
            for (int i = 0; i < om->nmtl; i++)
                if (!strcmp(om->mtl[i].name, nm)) obj_fail(r, r->tok_off, "material '%s' is already defined", nm);
            if (om->nmtl == MAX_MATERIALS) obj_fail(r, ko, "more than %d materials", MAX_MATERIALS);
            cur = &om->mtl[om->nmtl++];
            memset(cur, 0, sizeof *cur);
            cur->name = dup_str(p, nm, strlen(nm));
            cur->part = -1;
        } else if (in_list(mtl_skipped, k)) {
            continue;
        } else if (!cur) {
            obj_fail(r, ko, "'%s' before the first newmtl", k);
        } else if (!strcmp(k, "Kd")) {
            double d[3];
            size_t off[3];
            size_t at = r->pos;
            char *t = obj_tok(r);
            if (t && (!strcmp(t, "spectral") || !strcmp(t, "xyz")))
                obj_fail(r, r->tok_off, "Kd %s is not supported (Kd r g b, each 0 .. 1)", t);
            r->pos = at;
            int n = obj_nums(r, "Kd", d, off, 3);
            if (n != 1 && n != 3) obj_fail(r, ko, "Kd needs r g b (or one value for all three), found %d numbers", n);
            if (n == 1) {
                d[1] = d[2] = d[0];
                off[1] = off[2] = off[0];
            }
            for (int i = 0; i < 3; i++)
                if (!(d[i] >= 0 && d[i] <= 1)) obj_fail(r, off[i], "Kd: %.17g is outside 0 .. 1", d[i]);
            memcpy(cur->kd, d, sizeof d);
            cur->has_kd = 1;
        } else if (!strcmp(k, "map_Kd")) {
            char *t = obj_tok(r);
            if (!t) obj_fail(r, ko, "map_Kd needs an image file name");
            if (t[0] == '-') obj_fail(r, r->tok_off, "map_Kd options ('%s') are not supported", t);
            size_t to = r->tok_off;
            if (obj_tok(r)) obj_fail(r, r->tok_off, "map_Kd takes one file name (without spaces)");
            char path[FILE_PATH_MAX];
            cur->map_at = obj_where(r, to);
            file_path(p, &cur->map_at, "image file", dir, t, path);
            cur->map = dup_str(p, path, strlen(path));
        } else {
            obj_fail(r, ko, "unknown material statement '%s'", k);
        }
    }
}

/* mtllib NAME...: each material file, relative to the model file. */
static void obj_mtllib(struct obj_model *om, struct obj_reader *r, struct obj_reader *mr)
{
    struct parser *p = r->p;
    char dir[FILE_PATH_MAX];
    dir_of(r->path, dir);
    size_t ko = r->tok_off;
    int n = 0;
    for (char *t; (t = obj_tok(r)); n++) {
        char path[FILE_PATH_MAX];
        struct where at = obj_where(r, r->tok_off);
        file_path(p, &at, "material file", dir, t, path);
        const char *kept = dup_str(p, path, strlen(path));   /* messages name it after the file is read */
        FILE *f = open_file(p, 1, kept);
        if (!f) fail_open(p, &at, "material file", kept, "model file");
        obj_open(mr, p, f, kept);
        read_mtl(om, mr);
        close_file(p, 1);
    }
    if (!n) obj_fail(r, ko, "mtllib needs a file name");
}

/* usemtl NAME: the material of the faces below. */
static void obj_usemtl(struct obj_model *om, struct obj_reader *r)
{
    size_t ko = r->tok_off;
    char *nm = obj_rest(r);
    if (!*nm) obj_fail(r, ko, "usemtl needs a material name");
    for (om->cur = 0; om->cur < om->nmtl; om->cur++)
        if (!strcmp(om->mtl[om->cur].name, nm)) return;
    obj_fail(r, r->tok_off, "no material named '%s' (in the material files of the mtllib statements above)", nm);
}

/* The part of the current material's faces: one per texture. */
static int obj_part_of(struct obj_model *om, struct obj_reader *r, size_t off, int ntex_scene)
{
    int *slot = om->cur >= 0 ? &om->mtl[om->cur].part : &om->nopart;
    if (*slot >= 0) return *slot;
    const char *map = om->cur >= 0 ? om->mtl[om->cur].map : NULL;
    for (int k = 0; k < om->nparts; k++) {
        const char *pm = om->part[k].mtl >= 0 ? om->mtl[om->part[k].mtl].map : NULL;
        if ((!pm && !map) || (pm && map && !strcmp(pm, map))) return *slot = k;
    }
    if (map && ntex_scene + om->ntex + 1 > MAX_TEXTURES)
        obj_fail(r, off, "material '%s' needs a texture more than the %d a scene may have", om->mtl[om->cur].name,
                 MAX_TEXTURES);
    struct obj_part *pt = &om->part[om->nparts];
    memset(pt, 0, sizeof *pt);
    pt->mtl = map ? om->cur : -1;
    pt->has_uv = pt->has_n = -1;
    om->ntex += map != NULL;
    return *slot = om->nparts++;
}

static const char *const obj_skipped[] = { "o", "g", "s", "mg", "l", "p", "vp", NULL };
static const char *const obj_freeform[] = { "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm",
                                            "trim", "hole", "scrv", "sp", "end", "con", NULL };

/* One index of a face corner: 1 … total from the start of the file, -1 … -sofar back from the
 * statement; 0-based. */
static int obj_ref(struct obj_reader *r, char *s, int sofar, int total, const char *what)
{
    size_t off = (size_t)(s - r->buf);
    const char *c = s + (*s == '-');
    int32_t i = 0;
    int digits = 0;
    for (; is_digit(*c); c++, digits++)
        if (digits < 9) i = i * 10 + (*c - '0');
    if (!digits || *c) obj_fail(r, off, "%s index '%s' is not a whole number", what, s);
    if (digits > 9) obj_fail(r, off, "%s index %s is out of range (the file has %d)", what, s, total);
    if (*s == '-') i = -i;
    if (i == 0) obj_fail(r, off, "%s index 0: indices count from 1 (negative ones back from the last)", what);
    if (i > total) obj_fail(r, off, "%s index %ld is out of range (the file has %d)", what, (long)i, total);
    if (i < 0 && -i > sofar) obj_fail(r, off, "%s index %ld is out of range (%d above it)", what, (long)i, sofar);
    return (int)(i > 0 ? i - 1 : sofar + i);
}

/* Pass 1: counts, material files, the parts of the faces. */
static void obj_count(struct obj_model *om, struct obj_reader *r, struct obj_reader *mr, int ntex_scene)
{
    int vline = 0, tline = 0;
    int64_t nv = 0, ntris = 0;
    while (obj_statement(r)) {
        char *k = obj_tok(r);
        size_t ko = r->tok_off;
        if (!strcmp(k, "v")) {
            if (++nv == MAX_VERTS + 1) vline = r->line;
        } else if (!strcmp(k, "vt")) {
            if (++om->nvt > MAX_TEX_VERTS) obj_fail(r, ko, "more than %d texture coordinates (vt)", MAX_TEX_VERTS);
        } else if (!strcmp(k, "vn")) {
            if (++om->nvn > MAX_TEX_VERTS) obj_fail(r, ko, "more than %d normals (vn)", MAX_TEX_VERTS);
        } else if (!strcmp(k, "f")) {
            int n = 0;
            while (obj_tok(r)) n++;
            if (n < 3) obj_fail(r, ko, "a face needs at least 3 corners, found %d", n);
            int pt = obj_part_of(om, r, ko, ntex_scene);
            ntris += n - 2;
            if (ntris > MAX_TRIS && !tline) tline = r->line;
            if (!tline) om->part[pt].ntris += n - 2;
        } else if (!strcmp(k, "mtllib")) {
            obj_mtllib(om, r, mr);
        } else if (!strcmp(k, "usemtl")) {
            obj_usemtl(om, r);
        } else if (in_list(obj_freeform, k)) {
            obj_fail(r, ko, "free-form geometry ('%s') is not supported", k);
        } else if (!in_list(obj_skipped, k)) {
            obj_fail(r, ko, "unknown statement '%s'", k);
        }
    }
    if (vline)
        fail_in(r->p, r->path, vline, 1, "%.0f vertices: a model has at most %d", (double)nv, MAX_VERTS);
    if (tline)
        fail_in(r->p, r->path, tline, 1, "%.0f triangles: a model has at most %d", (double)ntris, MAX_TRIS);
    om->nv = (int)nv;
    om->ntris = (int)ntris;
}

/* f: the face's triangles (a fan around its first corner) into its part. */
static void obj_face(struct obj_model *om, struct obj_reader *r)
{
    size_t ko = r->tok_off;
    struct obj_part *pt = &om->part[om->cur >= 0 ? om->mtl[om->cur].part : om->nopart];
    const struct obj_mtl *mt = om->cur >= 0 ? &om->mtl[om->cur] : NULL;
    rgb col = om->col;
    if (mt && mt->has_kd)
        col = rgb_make(num_from_double(mt->kd[0] * 255), num_from_double(mt->kd[1] * 255),
                       num_from_double(mt->kd[2] * 255));
    else if (!om->has_col)
        obj_fail(r, ko, mt ? "face without a colour: material '%s' has no Kd and the model no 'color'"
                           : "face without a colour: no material (usemtl) and the model has no 'color'",
                 mt ? mt->name : "");
    int v[3] = { 0, 0, 0 }, t[3] = { 0, 0, 0 }, n[3] = { 0, 0, 0 }, form = -1, k = 0;
    for (char *c; (c = obj_tok(r)); k++) {
        char *s2 = strchr(c, '/'), *s3 = s2 ? strchr(s2 + 1, '/') : NULL;
        if (s2) *s2++ = 0;
        if (s3) *s3++ = 0;
        int f = (s2 && *s2 ? 1 : 0) | (s3 ? 2 : 0);
        if ((s2 && !*s2 && !s3) || (s3 && !*s3)) obj_fail(r, r->tok_off, "corner %d ends in '/'", k + 1);
        if (form < 0) form = f;
        else if (f != form)
            obj_fail(r, r->tok_off, "corner %d has another form (v, v/vt, v//vn, v/vt/vn) than the first", k + 1);
        int at = k < 2 ? k : 2;
        v[at] = obj_ref(r, c, om->sv, om->nv, "vertex");
        if (f & 1) t[at] = obj_ref(r, s2, om->svt, om->nvt, "texture coordinate (vt)");
        if (f & 2) n[at] = obj_ref(r, s3, om->svn, om->nvn, "normal (vn)");
        if (k < 2) continue;
        struct ras_triangle *tri = &om->tris[pt->next++];
        for (int i = 0; i < 3; i++) {
            tri->v[i] = (uint16_t)v[i];
            if (f & 1) tri->uv[i] = om->uv[t[i]];
            if (f & 2) tri->n[i] = om->nrm[n[i]];
        }
        tri->color = col;
        v[1] = v[2];
        t[1] = t[2];
        n[1] = n[2];
    }
    int uv = form & 1, nrm = form >> 1;
    if (pt->has_uv < 0) {
        pt->has_uv = uv;
        pt->has_n = nrm;
        pt->line = r->line;
    }
    if (pt->has_uv != uv || pt->has_n != nrm)
        obj_fail(r, ko, "face %s %s, unlike the face at line %d: the faces of one texture all have them or none do",
                 (pt->has_uv != uv ? uv : nrm) ? "with" : "without",
                 pt->has_uv != uv ? "texture coordinates (vt)" : "normals (vn)", pt->line);
    if (pt->mtl >= 0 && !uv)
        obj_fail(r, ko, "material '%s' has a texture (map_Kd) but this face no texture coordinates (vt)", mt->name);
}

/* Pass 2: the vertices, texture coordinates, normals and triangles. */
static void obj_store(struct obj_model *om, struct obj_reader *r)
{
    while (obj_statement(r)) {
        char *k = obj_tok(r);
        size_t ko = r->tok_off;
        double d[4];
        size_t off[4];
        if (!strcmp(k, "v")) {
            int n = obj_nums(r, "v", d, off, 4);
            if (n < 3) obj_fail(r, ko, "v needs x y z, found %d numbers", n);
            double *q = om->pos + 3 * (size_t)om->sv++;
            for (int i = 0; i < 3; i++) {
                q[i] = d[i];
                if (om->check_range) obj_to_num(r, off[i], d[i], "vertex");
            }
        } else if (!strcmp(k, "vt")) {
            int n = obj_nums(r, "vt", d, off, 3);
            if (n < 1) obj_fail(r, ko, "vt needs u [v]");
            struct tri_uv *t = &om->uv[om->svt++];
            t->u = obj_to_num(r, off[0], d[0], "u");
            t->v = obj_to_num(r, n > 1 ? off[1] : ko, 1 - (n > 1 ? d[1] : 0), "1 - v");
        } else if (!strcmp(k, "vn")) {
            if (obj_nums(r, "vn", d, off, 3) != 3) obj_fail(r, ko, "vn needs x y z");
            om->nrm[om->svn++] = v3_make(obj_to_num(r, off[0], d[0], "normal"),
                                         obj_to_num(r, off[1], d[1], "normal"),
                                         obj_to_num(r, off[2], d[2], "normal"));
        } else if (!strcmp(k, "f")) {
            obj_face(om, r);
        } else if (!strcmp(k, "usemtl")) {
            obj_usemtl(om, r);
        }
    }
}

static void double_point(const void *pts, int i, double *q)
{
    memcpy(q, (const double *)pts + 3 * (size_t)i, 3 * sizeof *q);
}

static void read_obj_model(struct parser *p, struct build *b, const struct node *n, const struct node *file,
                           const struct node *fit, const struct node *color, const struct node *bound)
{
    const char *nm = b->model_names[b->nmodels].name;
    struct where at = node_where(p, file);
    if (file->kind != N_STR) FAIL_N(p, file, "file must be a string \"name.obj\"");
    if (!p->has_dir) FAIL_N(p, file, "model files need a scene file (no directory to look in)");
    char path[FILE_PATH_MAX];
    file_path(p, &at, "model file", p->dir, file->text, path);
    const char *opath = dup_str(p, path, strlen(path));
    double radius = fit ? get_num(p, fit, "fit") : 0;
    if (fit && !(radius > 0)) FAIL_N(p, fit, "fit must be > 0, found %.17g", radius);
    if (fit) to_num(p, fit, radius, "fit");

    struct obj_model om;
    memset(&om, 0, sizeof om);
    om.cur = om.nopart = -1;
    om.has_col = color != NULL;
    if (color) om.col = get_rgb(p, color, "model color");
    om.check_range = fit == NULL;
    om.mtl = scratch_alloc(p, MAX_MATERIALS, sizeof *om.mtl);
    struct obj_reader *r = scratch_alloc(p, 2, sizeof *r);
    FILE *f = open_file(p, 0, opath);
    if (!f) {
        struct where fat = node_where(p, file);
        fail_open(p, &fat, "model file", opath, "scene file");
    }
    obj_open(r, p, f, opath);
    obj_count(&om, r, r + 1, b->ntextures);

    rewind(f);
    obj_open(r, p, f, opath);
    om.pos = scratch_alloc(p, 3 * (size_t)om.nv, sizeof *om.pos);
    om.uv = scratch_alloc(p, (size_t)om.nvt, sizeof *om.uv);
    om.nrm = scratch_alloc(p, (size_t)om.nvn, sizeof *om.nrm);
    om.tris = alloc_array(p, (size_t)om.ntris, sizeof *om.tris);
    for (int k = 0, first = 0; k < om.nparts; first += om.part[k++].ntris)
        om.part[k].first = om.part[k].next = first;
    om.cur = -1;
    obj_store(&om, r);
    if (om.ntris == 0) FAIL_N(p, file, "model file '%s' has no faces", opath);
    close_file(p, 0);
    scratch_free(p, r);
    scratch_free(p, om.uv);
    scratch_free(p, om.nrm);

    /* fit: the centre of the vertices' bounding box to the origin, the farthest vertex at radius */
    if (fit) {
        double c[3], r2;
        box_sphere(om.pos, om.nv, double_point, c, &r2);
        if (!(r2 > 0)) FAIL_N(p, fit, "fit: the vertices of '%s' are all at one point", opath);
        if (!(r2 < 1e300)) FAIL_N(p, fit, "fit: the vertices of '%s' lie too far apart", opath);
        double s = radius / sqrt(r2);
        for (size_t i = 0; i < 3 * (size_t)om.nv; i++) om.pos[i] = (om.pos[i] - c[i % 3]) * s;
    }

    /* one model per part, with the vertices its triangles use (in the file's order) */
    more_models(p, b, n, om.nparts);
    int idx = b->nmodels;
    int32_t *map = scratch_alloc(p, (size_t)om.nv, sizeof *map);
    for (int k = 0; k < om.nparts; k++) {
        const struct obj_part *pt = &om.part[k];
        struct ras_model *m = &b->models[idx + k];
        struct named *name = &b->model_names[idx + k];
        struct ras_triangle *tris = om.tris + pt->first;
        for (int i = 0; i < om.nv; i++) map[i] = -1;
        for (int i = 0; i < pt->ntris; i++)
            for (int c = 0; c < 3; c++) map[tris[i].v[c]] = 0;
        int nverts = 0;
        for (int i = 0; i < om.nv; i++)
            if (map[i] == 0) map[i] = nverts++;
        vec3 *verts = alloc_array(p, (size_t)nverts, sizeof *verts);
        for (int i = 0; i < om.nv; i++)
            if (map[i] >= 0) {
                const double *q = om.pos + 3 * (size_t)i;
                verts[map[i]] = v3_make(to_num(p, fit ? fit : file, q[0], "vertex"),
                                        to_num(p, fit ? fit : file, q[1], "vertex"),
                                        to_num(p, fit ? fit : file, q[2], "vertex"));
            }
        for (int i = 0; i < pt->ntris; i++)
            for (int c = 0; c < 3; c++) tris[i].v[c] = (uint16_t)map[tris[i].v[c]];
        if (k) {
            char pn[80];
            snprintf(pn, sizeof pn, "%s:%d", nm, k);
            m->name = dup_str(p, pn, strlen(pn));
        } else {
            m->name = nm;
        }
        m->nverts = (uint16_t)nverts;
        m->ntris = (uint16_t)pt->ntris;
        m->verts = verts;
        m->tris = tris;
        m->has_normals = (uint8_t)pt->has_n;
        m->has_uvs = (uint8_t)pt->has_uv;
        if (bound) read_bound(p, bound, m);
        else default_bound(p, file, m);
        name->name = k ? NULL : nm;
        name->at = n;
        name->parts = k ? 1 : om.nparts;
        name->tex = -1;
        if (pt->mtl >= 0) {
            const struct obj_mtl *mt = &om.mtl[pt->mtl];
            int w, h;
            uint8_t *px = load_image(p, &mt->map_at, mt->map, &w, &h);
            more_textures(p, b, &mt->map_at, 1);
            struct ras_texture *t = &b->textures[b->ntextures];
            t->w = (uint16_t)w;
            t->h = (uint16_t)h;
            t->rgb = px;
            t->filter = TEX_NEAREST;
            t->mip_levels = 1;
            b->tex_names[b->ntextures].name = NULL;
            b->tex_names[b->ntextures].at = n;
            name->tex = b->ntextures++;
        }
    }
    b->nmodels += om.nparts;
    scratch_free(p, map);
    scratch_free(p, om.pos);
    scratch_free(p, om.mtl);
}

static int tex_ref(struct parser *p, struct build *b, const struct node *n, int ntex, const char *what)
{
    const char *nm = get_name(p, n, what);
    int i = find_named(b->tex_names, ntex, nm);
    if (i < 0) FAIL_N(p, n, "%s: no texture named '%s'", what, nm);
    return i;
}

/* An instance of a model read from an OBJ file is one instance per part:
 * a part with a material texture (map_Kd) takes it; the instance's own
 * `texture` goes to the parts without one that have uv, `normal_map` to
 * every part with uv. */
static void read_instance(struct parser *p, struct build *b, const struct node *n)
{
    static const char *const keys[] = { "model", "texture", "normal_map", "specular", "transform", "animate", NULL };
    const struct node *v[6];
    struct ras_instance in;
    memset(&in, 0, sizeof in);
    fields(p, n, "instance", keys, v);
    const char *mn = get_name(p, need(p, n, v[0], "instance", "model"), "instance model");
    int mi = find_named(b->model_names, b->nmodels, mn);
    if (mi < 0) FAIL_N(p, v[0], "instance: no model named '%s' (models are defined before their instances)", mn);
    int parts = b->model_names[mi].parts, any_uv = 0, bare_uv = 0;
    for (int k = mi; k < mi + parts; k++) {
        any_uv |= b->models[k].has_uvs;
        bare_uv |= b->models[k].has_uvs && b->model_names[k].tex < 0;
    }
    int tex = -1, nmap = -1;
    if (v[1]) {
        tex = tex_ref(p, b, v[1], b->ntextures, "instance texture");
        if (!any_uv) FAIL_N(p, v[1], "instance: model '%s' has no uv to map texture with", mn);
        if (!bare_uv) FAIL_N(p, v[1], "instance: every part of model '%s' with uv has its material's texture", mn);
    }
    if (v[2]) {
        nmap = tex_ref(p, b, v[2], b->ntextures, "instance normal_map");
        if (!any_uv) FAIL_N(p, v[2], "instance: model '%s' has no uv to map a normal map with", mn);
    }
    in.specular = num_from_int(50);
    if (v[3]) in.specular = to_num(p, v[3], (double)get_int(p, v[3], "specular", -1, 10000), "specular");
    in.rotation = m3_identity();
    in.scale = NUM_ONE;
    if (v[4]) {
        static const char *const tkeys[] = { "scale", "rotation", "translation", NULL };
        const struct node *t[3];
        fields(p, v[4], "transform", tkeys, t);
        if (t[0]) {
            double s = get_num(p, t[0], "scale");
            if (!(s > 0)) FAIL_N(p, t[0], "scale must be > 0, found %.17g", s);
            in.scale = to_num(p, t[0], s, "scale");
        }
        if (t[1]) in.rotation = get_rotation(p, t[1], "instance rotation", NULL);
        if (t[2]) in.position = get_vec3(p, t[2], "translation");
    }
    if (v[5]) read_anim(p, v[5], &in.anim);
    if (b->ninstances + parts > MAX_INSTANCES)
        FAIL_K(p, n, "more than %d instances (an instance of a model file has one per part)", MAX_INSTANCES);
    GROW(p, b->instances, b->ninstances, b->cap_instances, b->ninstances + parts);
    for (int k = mi; k < mi + parts; k++) {
        struct ras_instance *o = &b->instances[b->ninstances++];
        int uv = b->models[k].has_uvs;
        *o = in;
        o->model = (uint16_t)k;
        o->texture = (int16_t)(b->model_names[k].tex >= 0 ? b->model_names[k].tex : uv ? tex : -1);
        o->normal_map = (int16_t)(uv ? nmap : -1);
    }
}

static void read_prim(struct parser *p, const struct node *n, struct prim2d *q)
{
    double xy[2];
    if (!strcmp(n->key, "line2d")) {
        static const char *const keys[] = { "p0", "p1", "color", "method", NULL };
        static const char *const methods[] = { "interpolate", "broken", NULL };
        const struct node *v[4];
        fields(p, n, "line2d", keys, v);
        q->npts = 2;
        for (int i = 0; i < 2; i++) {
            get_tuple(p, need(p, n, v[i], "line2d", i ? "p1" : "p0"), "point", 2, xy);
            q->x[i] = to_num(p, v[i], xy[0], "x");
            q->y[i] = to_num(p, v[i], xy[1], "y");
        }
        q->color = get_rgb(p, need(p, n, v[2], "line2d", "color"), "color");
        int m = v[3] ? get_choice(p, v[3], "method", methods) : 0;
        q->kind = m ? P2D_LINE_BROKEN : P2D_LINE;
        if (q->kind == P2D_LINE_BROKEN && q->x[0] == q->x[1]) FAIL_N(p, v[1], "line2d: the broken method needs x0 != x1");
    } else {
        static const char *const keys[] = { "p0", "p1", "p2", "color", "style", "h", NULL };
        static const char *const styles[] = { "wireframe", "filled", "shaded", NULL };
        static const int kinds[] = { P2D_WIRE_TRI, P2D_FILLED_TRI, P2D_SHADED_TRI };
        const struct node *v[6];
        fields(p, n, "triangle2d", keys, v);
        q->npts = 3;
        for (int i = 0; i < 3; i++) {
            static const char *const pk[] = { "p0", "p1", "p2" };
            get_tuple(p, need(p, n, v[i], "triangle2d", pk[i]), "point", 2, xy);
            q->x[i] = to_num(p, v[i], xy[0], "x");
            q->y[i] = to_num(p, v[i], xy[1], "y");
        }
        q->color = get_rgb(p, need(p, n, v[3], "triangle2d", "color"), "color");
        q->kind = (uint8_t)kinds[get_choice(p, need(p, n, v[4], "triangle2d", "style"), "style", styles)];
        if (q->kind == P2D_SHADED_TRI) {
            double h[3];
            get_tuple(p, need(p, n, v[5], "shaded triangle2d", "h"), "h", 3, h);
            for (int i = 0; i < 3; i++) q->h[i] = to_num(p, v[5], h[i], "h");
        } else if (v[5]) FAIL_K(p, v[5], "'h' is for shaded triangles");
    }
}

static void read_line3d(struct parser *p, const struct node *n, struct line3d *l)
{
    static const char *const keys[] = { "p0", "p1", "color", NULL };
    const struct node *v[3];
    fields(p, n, "line3d", keys, v);
    l->a = get_vec3(p, need(p, n, v[0], "line3d", "p0"), "p0");
    l->b = get_vec3(p, need(p, n, v[1], "line3d", "p1"), "p1");
    l->color = get_rgb(p, need(p, n, v[2], "line3d", "color"), "color");
}

/* ---- the scene -------------------------------------------------------------- */

enum top_key {
#define SCENE_KEY(key, repeatable) TOP_##key,
#include "scene_options.def"
    NTOP
};

static const struct { const char *key; int repeatable; } top_rows[NTOP] = {
#define SCENE_KEY(key, repeatable) { #key, repeatable },
#include "scene_options.def"
};

/* The top level's entries by key: the one entry of each key that may occur
 * once, and how many of each. */
struct top {
    const struct node *single[NTOP];
    int count[NTOP];
};

static int top_index(const char *k)
{
    for (int i = 0; i < NTOP; i++)
        if (!strcmp(top_rows[i].key, k)) return i;
    return -1;
}

/* Unkeyed values, unknown keys, duplicates and counts, before anything is read. */
static void check_top(struct parser *p, const struct node *top, struct top *t, struct build *b)
{
    memset(t, 0, sizeof *t);
    for (const struct node *e = top->first; e; e = e->next) {
        if (!e->key) FAIL_N(p, e, "expected 'key = value' or 'key { ... }' at the top level, found %s",
                            kind_names[e->kind]);
        int i = top_index(e->key);
        if (i < 0) {
            const char *keys[NTOP + 1];
            for (int k = 0; k < NTOP; k++) keys[k] = top_rows[k].key;
            keys[NTOP] = NULL;
            const char *near = suggest_nearest(e->key, keys);
            FAIL_K(p, e, "unknown key '%s'%s%s%s", e->key, near ? " (did you mean '" : "", near ? near : "",
                   near ? "'?)" : "");
        }
        if (!top_rows[i].repeatable) {
            const struct node *f = t->single[i];
            if (f) FAIL_K(p, e, "duplicate '%s' (first at %d:%d)", e->key, f->kline, f->kcol);
            t->single[i] = e;
        }
        t->count[i]++;
    }
    b->nlights = t->count[TOP_light];
    b->nobjects = t->count[TOP_sphere] + t->count[TOP_plane] + t->count[TOP_triangle];
    b->ncsg = t->count[TOP_csg];
    b->cap_models = t->count[TOP_model];
    b->cap_instances = t->count[TOP_instance];
    b->cap_textures = t->count[TOP_texture];
    b->nprims = t->count[TOP_line2d] + t->count[TOP_triangle2d];
    b->nlines = t->count[TOP_line3d];
    if (b->nlights > MAX_LIGHTS) fail_at(p, 1, 1, "more than %d lights", MAX_LIGHTS);
    if (b->nobjects > MAX_OBJECTS || b->ncsg > MAX_OBJECTS) fail_at(p, 1, 1, "more than %d objects", MAX_OBJECTS);
    if (b->cap_models > MAX_MODELS) fail_at(p, 1, 1, "more than %d models", MAX_MODELS);
    if (b->cap_instances > MAX_INSTANCES) fail_at(p, 1, 1, "more than %d instances", MAX_INSTANCES);
    if (b->cap_textures > MAX_TEXTURES) fail_at(p, 1, 1, "more than %d textures", MAX_TEXTURES);
    if (b->nprims > MAX_PRIMS) fail_at(p, 1, 1, "more than %d 2D primitives", MAX_PRIMS);
    if (b->nlines > MAX_LINES) fail_at(p, 1, 1, "more than %d 3D lines", MAX_LINES);
}

/* light_space = model: every model normal normalised (v3_normalize), as
 * the renderer's model-space lighting takes them. */
static void unit_normals(struct ras_model *m)
{
    if (!m->has_normals) return;
    struct ras_triangle *t = (struct ras_triangle *)(uintptr_t)m->tris;
    for (uint32_t i = 0; i < m->ntris; i++)
        for (int k = 0; k < 3; k++) t[i].n[k] = v3_normalize(t[i].n[k]);
}

/* struct ras_model.vertex_normals: 1 when the corners of each vertex all
 * carry the same normal (bit for bit), so the renderer may light a vertex
 * once for all its corners. 0 when it cannot tell (no memory to look). */
static void mark_vertex_normals(struct ras_model *m)
{
    m->vertex_normals = 0;
    if (!m->has_normals || m->nverts == 0) return;
    uint32_t *first = malloc(sizeof *first * m->nverts);
    if (!first) return;
    for (uint32_t v = 0; v < m->nverts; v++) first[v] = UINT32_MAX;
    int same = 1;
    for (uint32_t t = 0; t < m->ntris && same; t++)
        for (int k = 0; k < 3 && same; k++) {
            uint16_t v = m->tris[t].v[k];
            if (v >= m->nverts) continue;
            if (first[v] == UINT32_MAX) { first[v] = 3 * t + (uint32_t)k; continue; }
            const vec3 *a = &m->tris[first[v] / 3].n[first[v] % 3], *b = &m->tris[t].n[k];
            same = !memcmp(a, b, sizeof *a);
        }
    m->vertex_normals = (uint8_t)same;
    free(first);
}

/* name, canvas, viewport, background, frames, camera */
static void read_view(struct parser *p, const struct top *t, struct scene *s, const char *default_name)
{
    const struct node *e;
    s->name = t->single[TOP_name] ? get_name(p, t->single[TOP_name], "name") : default_name;
    s->canvas_w = s->canvas_h = 600;
    s->viewport_w = s->viewport_h = s->projection_d = NUM_ONE;
    s->frames = 1;
    s->camera.rotation = m3_identity();
    if ((e = t->single[TOP_canvas])) {
        static const char *const keys[] = { "width", "height", NULL };
        const struct node *v[2];
        fields(p, e, "canvas", keys, v);
        if (v[0]) s->canvas_w = (uint16_t)get_int(p, v[0], "canvas width", 1, MAX_CANVAS);
        if (v[1]) s->canvas_h = (uint16_t)get_int(p, v[1], "canvas height", 1, MAX_CANVAS);
    }
    if ((e = t->single[TOP_viewport])) {
        static const char *const keys[] = { "width", "height", "d", NULL };
        const struct node *v[3];
        fields(p, e, "viewport", keys, v);
        if (v[0]) s->viewport_w = to_num(p, v[0], get_num_range(p, v[0], "viewport width", 1e-3, 1000), "viewport width");
        if (v[1]) s->viewport_h = to_num(p, v[1], get_num_range(p, v[1], "viewport height", 1e-3, 1000), "viewport height");
        if (v[2]) s->projection_d = to_num(p, v[2], get_num_range(p, v[2], "viewport d", 1e-3, 1000), "viewport d");
    }
    if ((e = t->single[TOP_background])) {
        s->background = get_rgb(p, e, "background");
        s->background_set = 1;
    }
    if ((e = t->single[TOP_frames])) s->frames = (uint16_t)get_int(p, e, "frames", 1, MAX_FRAMES);
    if ((e = t->single[TOP_camera])) read_camera(p, e, s);
}

static void alloc_build(struct parser *p, struct build *b)
{
    b->lights = alloc_array(p, (size_t)b->nlights, sizeof *b->lights);
    b->objects = alloc_array(p, (size_t)b->nobjects, sizeof *b->objects);
    b->obj_names = alloc_array(p, (size_t)b->nobjects, sizeof *b->obj_names);
    b->csg = alloc_array(p, (size_t)b->ncsg, sizeof *b->csg);
    b->models = alloc_array(p, (size_t)b->cap_models, sizeof *b->models);
    b->model_names = alloc_array(p, (size_t)b->cap_models, sizeof *b->model_names);
    b->instances = alloc_array(p, (size_t)b->cap_instances, sizeof *b->instances);
    b->textures = alloc_array(p, (size_t)b->cap_textures, sizeof *b->textures);
    b->tex_names = alloc_array(p, (size_t)b->cap_textures, sizeof *b->tex_names);
    b->prims = alloc_array(p, (size_t)b->nprims, sizeof *b->prims);
    b->lines = alloc_array(p, (size_t)b->nlines, sizeof *b->lines);
}

/* The repeatable entries, in file order: a reference must name something defined above it. */
static void read_entries(struct parser *p, const struct node *top, struct build *b)
{
    int il = 0, io = 0, ic = 0, ip = 0, i3 = 0;
    for (const struct node *e = top->first; e; e = e->next) {
        switch (top_index(e->key)) {
        case TOP_light: read_light(p, e, &b->lights[il++]); break;
        case TOP_sphere: case TOP_plane: case TOP_triangle: read_object(p, b, e, io); io++; break;
        case TOP_csg: read_csg(p, b, e, &b->csg[ic++], io); break;
        case TOP_model: read_model(p, b, e); break;
        case TOP_texture: read_texture(p, b, e); break;
        case TOP_instance: read_instance(p, b, e); break;
        case TOP_line2d: case TOP_triangle2d: read_prim(p, e, &b->prims[ip++]); break;
        case TOP_line3d: read_line3d(p, e, &b->lines[i3++]); break;
        default: break;
        }
    }
}

/* The renderer: as the scene says, or from what it contains; each option block only for its renderer. */
static void read_kind(struct parser *p, const struct top *t, const struct build *b, struct scene *s)
{
    int rt = b->nobjects + b->ncsg > 0, ras = b->nmodels + b->ninstances + b->nprims + b->nlines > 0;
    const struct node *r = t->single[TOP_renderer];
    const struct node *rto = t->single[TOP_raytracer], *raso = t->single[TOP_rasterizer];
    if (r) {
        static const char *const kinds[] = { "raytracer", "rasterizer", NULL };
        int k = get_choice(p, r, "renderer", kinds);
        if (k == 0 && ras) FAIL_N(p, r, "renderer is raytracer, but the scene has rasterizer data");
        if (k == 1 && rt) FAIL_N(p, r, "renderer is rasterizer, but the scene has ray tracer objects");
        s->kind = (uint8_t)k;
    } else {
        if (rt && ras) fail_at(p, 1, 1, "the scene mixes ray tracer objects and rasterizer data; say 'renderer = ...'");
        if (!rt && !ras) fail_at(p, 1, 1, "the scene has nothing to draw (no sphere, plane, triangle, instance, line or triangle2d)");
        s->kind = rt ? SCENE_RAYTRACE : SCENE_RASTER;
    }
    if (s->kind == SCENE_RAYTRACE && raso) FAIL_K(p, raso, "'rasterizer' options in a ray-traced scene");
    if (s->kind == SCENE_RASTER && rto) FAIL_K(p, rto, "'raytracer' options in a rasterized scene");
    if (s->ras.shadow_light) {
        int k = s->ras.shadow_light - 1;
        if (k >= b->nlights || b->lights[k].type == LIGHT_AMBIENT)
            FAIL_K(p, raso, "shadow_light = %d: lights are counted from 0 and it must be a point or directional light", k);
    }
}

/* quality { psnr = DB target = m0plus|m4f|rp2040 }: the accuracy the
 * compiler chooses methods for (tools/quality); the renderers never see it. */
static void read_quality(struct parser *p, const struct node *n)
{
    static const char *const keys[] = { "psnr", "target", NULL };
    static const char *const targets[] = { "m0plus", "m4f", "rp2040", NULL };
    const struct node *v[2];
    fields(p, n, "quality", keys, v);
    p->quality.psnr = get_num_range(p, need(p, n, v[0], "quality", "psnr"), "quality psnr", 1, 200);
    p->quality.target = v[1] ? get_choice(p, v[1], "quality target", targets) + 1 : 0;
    p->quality.line = n->kline;
    p->quality.col = n->kcol;
}

static void read_scene(struct parser *p, const struct node *top, struct scene *s, const char *default_name)
{
    struct top t;
    struct build b;
    memset(&b, 0, sizeof b);
    b.s = s;
    check_top(p, top, &t, &b);
    read_view(p, &t, s, default_name);
    if (t.single[TOP_quality]) read_quality(p, t.single[TOP_quality]);
    /* the options: the book's defaults (scene_options.def); depth_bits 0 is chosen from the scene's
       depth range after parsing, unless given */
    set_defaults(&s->rt, rt_option_rows, NROWS(rt_option_rows));
    if (t.single[TOP_raytracer])
        read_options(p, t.single[TOP_raytracer], "raytracer", rt_option_rows, NROWS(rt_option_rows), &s->rt);
    set_defaults(&s->ras, ras_option_rows, NROWS(ras_option_rows));
    if (t.single[TOP_rasterizer])
        read_options(p, t.single[TOP_rasterizer], "rasterizer", ras_option_rows, NROWS(ras_option_rows), &s->ras);
    alloc_build(p, &b);
    read_entries(p, top, &b);
    read_kind(p, &t, &b, s);
    s->nlights = (uint16_t)b.nlights;
    s->lights = b.lights;
    s->nobjects = (uint16_t)b.nobjects;
    s->objects = b.objects;
    s->ncsg = (uint16_t)b.ncsg;
    s->csg = b.csg;
    s->nmodels = (uint16_t)b.nmodels;
    if (s->ras.light_space) /* lit in model space: the normals of unit length */
        for (int i = 0; i < b.nmodels; i++) unit_normals(&b.models[i]);
    for (int i = 0; i < b.nmodels; i++) mark_vertex_normals(&b.models[i]);
    s->models = b.models;
    s->ninstances = (uint16_t)b.ninstances;
    s->instances = b.instances;
    s->ntextures = (uint16_t)b.ntextures;
    s->textures = b.textures;
    s->nprims = (uint16_t)b.nprims;
    s->prims = b.prims;
    s->nlines = (uint16_t)b.nlines;
    s->lines = b.lines;
}

/* ---- values given that a format would round to 0 ---------------------------- */

int scene_given_zero(const struct scene *s, int frac, const char *path, char *msg, size_t len)
{
    const double half = ldexp(1, -(frac + 1));
    char what[96] = "";
    double bad = 0;
#define GIVEN(v, ...)                                                   \
    do {                                                                \
        double d_ = num_to_double(v);                                   \
        if (!what[0] && d_ != 0 && fabs(d_) <= half) {                  \
            snprintf(what, sizeof what, __VA_ARGS__);                   \
            bad = d_;                                                   \
        }                                                               \
    } while (0)
    for (int i = 0; i < s->nlights; i++) GIVEN(s->lights[i].intensity, "light %d intensity", i);
    for (int i = 0; s->kind == SCENE_RAYTRACE && i < s->nobjects; i++) {
        GIVEN(s->objects[i].mat.reflective, "object %d reflective", i);
        GIVEN(s->objects[i].mat.transparency, "object %d transparency", i);
        if (s->objects[i].shape == RT_SPHERE) GIVEN(s->objects[i].radius, "sphere %d radius", i);
    }
    for (int i = 0; s->kind == SCENE_RASTER && i < s->ninstances; i++) {
        GIVEN(s->instances[i].scale, "instance %d scale", i);
        GIVEN(s->instances[i].anim.rot_y_per_frame, "instance %d rotate_y", i);
    }
    GIVEN(s->camera_anim.rot_y_per_frame, "camera rotate_y");
    if (s->kind == SCENE_RAYTRACE) {
        GIVEN(s->rt.epsilon, "raytracer epsilon");
        GIVEN(s->rt.t_min_primary, "raytracer t_min");
    }
#undef GIVEN
    if (!what[0]) return 0;
    snprintf(msg, len, "%s:1:1: error: %s %.6g would be 0 in the format Q%d.%d the scene needs (step %.3g): give 0 or "
                       "a value of at least half a step", path, what, bad, 31 - frac, frac, ldexp(1, -frac));
    return -1;
}

/* ---- entry points -------------------------------------------------------- */

struct scene_box {
    struct scene s;          /* first: scene_free() gets this pointer */
    struct arena arena;
    struct scene_quality quality;
};

static int parse(const char *file, const char *dir, const char *text, size_t len, struct scene **out, char *err,
                 size_t errlen)
{
    struct parser *p = calloc(1, sizeof *p);
    *out = NULL;
    if (!p) {
        snprintf(err, errlen, "%s:1:1: error: out of memory", file);
        return SCENE_ENOMEM;
    }
    p->file = file;
    p->src = text;
    p->len = len;
    p->line = p->col = 1;
    /* a UTF-8 byte order mark, which some editors write first, is not part of the text */
    if (len >= 3 && (unsigned char)text[0] == 0xEF && (unsigned char)text[1] == 0xBB && (unsigned char)text[2] == 0xBF)
        p->pos = 3;
    p->err = err;
    p->errlen = errlen;
    if (dir) {
        p->has_dir = 1;
        snprintf(p->dir, sizeof p->dir, "%s", dir);
    }
    if (setjmp(p->fail)) {
        int rc = p->oom ? SCENE_ENOMEM : SCENE_EINPUT;
        release_files(p);
        arena_free(&p->arena);
        free(p);
        return rc;
    }
    if (len == 0) fail_at(p, 1, 1, "empty file");
    if (len > SCENE_MAX_BYTES) fail_at(p, 1, 1, "file larger than %u bytes", SCENE_MAX_BYTES);
    struct scene_box *box = alloc(p, sizeof *box);
    struct node *top = new_node(p, N_BLOCK, 1, 1);
    parse_entries(p, top, T_EOF);
    if (top->n == 0) fail_at(p, 1, 1, "the file has no scene in it (only spaces and comments)");
    /* default name: the file name without directory and extension */
    const char *base = strrchr(file, '/') ? strrchr(file, '/') + 1 : file;
    const char *dot = strrchr(base, '.');
    const char *dname = dup_str(p, base, dot && dot != base ? (size_t)(dot - base) : strlen(base));
    read_scene(p, top, &box->s, dname);
    if (box->s.kind == SCENE_RASTER && box->s.ras.depth_bits == 0) {
        int bits = scene_depth_bits(&box->s, NULL);
        if (bits < 0) {
            p->oom = 1;
            fail_at(p, 1, 1, "out of memory (the depth analysis)");
        }
        box->s.ras.depth_bits = (uint8_t)bits;
    }
    box->arena = p->arena;
    box->quality = p->quality;
    free(p);
    *out = &box->s;
    return 0;
}

int scene_parse_mem(const char *name, const char *text, size_t len, struct scene **out, char *err, size_t errlen)
{
    return parse(name, NULL, text, len, out, err, errlen);
}

#ifdef HAVE_POSIX_FILES
/* A FIFO (or a pipe as /dev/stdin) read without blocking forever: opened
 * with O_NONBLOCK, each read waits at most SCENE_FIFO_TIMEOUT_MS for data
 * (a FIFO no program writes to is refused instead of hanging). */
static int read_fifo(const char *path, char **text, size_t *len, char *err, size_t errlen)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    if (fd < 0) {
        snprintf(err, errlen, "%s:1:1: error: cannot open file: %s", path, strerror(errno));
        return SCENE_EIO;
    }
    size_t cap = 65536, n = 0;
    char *buf = malloc(cap);
    int rc = buf ? 0 : SCENE_ENOMEM;
    while (!rc) {
        if (n == cap) {
            if (cap > SCENE_MAX_BYTES) break;
            char *nb = realloc(buf, cap * 2);
            if (!nb) { rc = SCENE_ENOMEM; break; }
            buf = nb;
            cap *= 2;
        }
        /* (before a writer has opened it, a read would say end of file:
           poll first, which waits for data or for the last writer leaving) */
        struct pollfd pfd = { .fd = fd, .events = POLLIN };
        int pr = poll(&pfd, 1, SCENE_FIFO_TIMEOUT_MS);
        if (pr == 0) {
            close(fd);
            free(buf);
            snprintf(err, errlen, "%s:1:1: error: a FIFO with nothing written to it for %d s (no writer?)", path,
                     SCENE_FIFO_TIMEOUT_MS / 1000);
            return SCENE_EIO;
        }
        if (pr < 0) {
            if (errno != EINTR) rc = SCENE_EIO;
            continue;
        }
        ssize_t got = read(fd, buf + n, cap - n);
        if (got > 0) { n += (size_t)got; continue; }
        if (got == 0) break;
        if (errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK) rc = SCENE_EIO;
    }
    close(fd);
    if (rc) {
        free(buf);
        snprintf(err, errlen, "%s:1:1: error: %s", path, rc == SCENE_ENOMEM ? "out of memory" : "read error");
        return rc;
    }
    *text = buf;
    *len = n;
    return 0;
}
#endif

int scene_read_text(const char *path, char **text, size_t *len, char *err, size_t errlen)
{
    *text = NULL;
    *len = 0;
#ifdef HAVE_POSIX_FILES
    /* a regular file or a FIFO (a pipe); stat before opening, so that
       nothing here blocks */
    struct stat st;
    if (!stat(path, &st)) {
        if (S_ISDIR(st.st_mode)) {
            snprintf(err, errlen, "%s:1:1: error: cannot open file: is a directory", path);
            return SCENE_EIO;
        }
        if (S_ISFIFO(st.st_mode)) return read_fifo(path, text, len, err, errlen);
        if (!S_ISREG(st.st_mode)) {
            snprintf(err, errlen, "%s:1:1: error: not a regular file or a FIFO (a device or a socket)", path);
            return SCENE_EIO;
        }
    }
#endif
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s:1:1: error: cannot open file: %s", path, strerror(errno));
        return SCENE_EIO;
    }
    /* read at most SCENE_MAX_BYTES + 1 so a huge (or endless) file is refused */
    size_t cap = 65536, n = 0;
    char *buf = malloc(cap);
    while (buf) {
        if (n == cap) {
            if (cap > SCENE_MAX_BYTES) break;
            char *nb = realloc(buf, cap * 2);
            if (!nb) { free(buf); buf = NULL; break; }
            buf = nb;
            cap *= 2;
        }
        size_t got = fread(buf + n, 1, cap - n, f);
        if (got == 0) break;
        n += got;
    }
    int ioerr = ferror(f);
    fclose(f);
    if (!buf || ioerr) {
        free(buf);
        snprintf(err, errlen, "%s:1:1: error: %s", path, buf ? "read error" : "out of memory");
        return buf ? SCENE_EIO : SCENE_ENOMEM;
    }
    *text = buf;
    *len = n;
    return 0;
}

int scene_parse_text(const char *path, const char *text, size_t len, struct scene **out, char *err,
                     size_t errlen)
{
    *out = NULL;
    char dir[1024] = "";
    const char *slash = strrchr(path, '/');
    if (slash && (size_t)(slash - path) + 1 < sizeof dir) {
        memcpy(dir, path, (size_t)(slash - path) + 1);
        dir[slash - path + 1] = 0;
    }
    return parse(path, dir, text, len, out, err, errlen);
}

int scene_load(const char *path, struct scene **out, char *err, size_t errlen)
{
    char *buf;
    size_t n;
    *out = NULL;
    int rrc = scene_read_text(path, &buf, &n, err, errlen);
    if (rrc) return rrc;
    int rc = scene_parse_text(path, buf, n, out, err, errlen);
    /* the scene keeps no pointer into the text */
    free(buf);
    return rc;
}

void scene_quality(const struct scene *s, struct scene_quality *q)
{
    *q = ((const struct scene_box *)s)->quality;
}

void scene_free(struct scene *s)
{
    if (!s) return;
    struct scene_box *box = (struct scene_box *)s;
    struct arena a = box->arena;
    arena_free(&a);
}
