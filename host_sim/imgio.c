/* SPDX-License-Identifier: MIT */
/* imgio.c — atomic PNG/PPM/raw writers (see imgio.h). */
#include "imgio.h"

#include <errno.h>
#include <fcntl.h>
#include <png.h>
#include <setjmp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* The temporary file being written, removed by the signal handler if the
 * program is killed by a signal it can catch, so nothing half-written is
 * left behind even then (SIGKILL cannot be caught: a temporary
 * ".NAME.XXXXXX" can then remain, never a half-written NAME). SIGPIPE and
 * SIGXFSZ (a FIFO's reader gone, `ulimit -f` exceeded) are ignored instead,
 * so that the write fails with EPIPE / EFBIG and is reported on one line. */
static char tmp_name[4096];
static volatile sig_atomic_t tmp_live;
/* The outputs written so far, each a complete temporary file next to its
 * destination (staged[i].tmp), renamed into place by img_commit only when
 * the whole run has succeeded; until then every earlier file stays as it
 * was. The signal handler removes them too (nstaged grows only after its
 * entry is complete, with the signals blocked). */
struct staged { char *tmp, *dest; };
static struct staged *staged;
static volatile sig_atomic_t nstaged;
static size_t staged_cap;
int img_fault_signal_in_write;

static void on_signal(int sig)
{
    if (tmp_live) unlink(tmp_name);
    for (sig_atomic_t i = 0; i < nstaged; i++) unlink(staged[i].tmp);
    signal(sig, SIG_DFL);
    raise(sig);
}

static void install_handlers(void)
{
    static int done;
    if (done) return;
    done = 1;
    static const int sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2,
                                SIGXCPU, SIGVTALRM, SIGPROF };
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigfillset(&sa.sa_mask);
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) sigaction(sigs[i], &sa, NULL);
    signal(SIGPIPE, SIG_IGN);
    signal(SIGXFSZ, SIG_IGN);
}

/* Keeps tmp_name as the staged file of dest: 0, or -1 out of memory. */
static int stage(const char *dest)
{
    sigset_t all, old;
    char *t = malloc(strlen(tmp_name) + 1), *d = malloc(strlen(dest) + 1);
    if (!t || !d) {
        free(t);
        free(d);
        return -1;
    }
    strcpy(t, tmp_name);
    strcpy(d, dest);
    sigfillset(&all);
    sigprocmask(SIG_BLOCK, &all, &old);
    int rc = 0;
    if ((size_t)nstaged == staged_cap) {
        size_t cap = staged_cap ? staged_cap * 2 : 8;
        struct staged *n = realloc(staged, cap * sizeof *n);
        if (n) {
            staged = n;
            staged_cap = cap;
        } else {
            rc = -1;
        }
    }
    if (!rc) {
        staged[nstaged].tmp = t;
        staged[nstaged].dest = d;
        nstaged++;
        tmp_live = 0;
    }
    sigprocmask(SIG_SETMASK, &old, NULL);
    if (rc) {
        free(t);
        free(d);
    }
    return rc;
}

static void staged_free(void)
{
    for (sig_atomic_t i = 0; i < nstaged; i++) {
        free(staged[i].tmp);
        free(staged[i].dest);
    }
    nstaged = 0;
    free(staged);
    staged = NULL;
    staged_cap = 0;
}

void img_discard(void)
{
    for (sig_atomic_t i = 0; i < nstaged; i++) unlink(staged[i].tmp);
    staged_free();
}

int img_commit(char *err, size_t errlen)
{
    int rc = 0;
    for (sig_atomic_t i = 0; i < nstaged; i++) {
        if (!rc && rename(staged[i].tmp, staged[i].dest)) {
            snprintf(err, errlen, "%s: rename failed: %s", staged[i].dest, strerror(errno));
            rc = 1;
        }
        if (rc) unlink(staged[i].tmp);
    }
    staged_free();
    return rc;
}

/* A FIFO or character device is written in place (renaming a file over it
 * would replace the device by a regular file). */
static int in_place;

enum img_format img_format_of(const char *path)
{
    size_t n = strlen(path);
    if (n < 4) return IMG_NONE;
    const char *e = path + n - 4;
    char low[5];
    for (int i = 0; i < 4; i++) low[i] = (char)(e[i] >= 'A' && e[i] <= 'Z' ? e[i] - 'A' + 'a' : e[i]);
    low[4] = 0;
    if (!strcmp(low, ".png")) return IMG_PNG;
    if (!strcmp(low, ".ppm")) return IMG_PPM;
    return IMG_NONE;
}

/* Directory part of path ("." if none) into buf. */
static int dir_of(const char *path, char *buf, size_t len)
{
    const char *slash = strrchr(path, '/');
    if (!slash) return snprintf(buf, len, ".") >= (int)len ? -1 : 0;
    size_t n = (size_t)(slash - path);
    if (n == 0) n = 1;  /* "/file" lives in "/" */
    if (n + 1 > len) return -1;
    memcpy(buf, path, n);
    buf[n] = 0;
    return 0;
}

int img_check_dest(const char *path, char *err, size_t errlen)
{
    char dir[4096];
    struct stat st;
    if (!*path || path[strlen(path) - 1] == '/') {
        snprintf(err, errlen, "%s: not a file name", path);
        return 2;
    }
    if (dir_of(path, dir, sizeof dir)) {
        snprintf(err, errlen, "%s: path too long", path);
        return 2;
    }
    if (stat(dir, &st) || !S_ISDIR(st.st_mode)) {
        snprintf(err, errlen, "%s: directory %s does not exist", path, dir);
        return 2;
    }
    if (access(dir, W_OK | X_OK)) {
        snprintf(err, errlen, "%s: directory %s is not writable", path, dir);
        return 2;
    }
    if (!stat(path, &st)) {
        if (S_ISDIR(st.st_mode)) {
            snprintf(err, errlen, "%s: is a directory", path);
            return 2;
        }
        if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode) && !S_ISCHR(st.st_mode)) {
            snprintf(err, errlen, "%s: not a regular file, FIFO or character device", path);
            return 2;
        }
    }
    return 0;
}

/* Opens the temporary file next to `path`. */
static FILE *tmp_open(const char *path, char *err, size_t errlen)
{
    char dir[4096];
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (dir_of(path, dir, sizeof dir) ||
        snprintf(tmp_name, sizeof tmp_name, "%s/.%s.XXXXXX", dir, base) >= (int)sizeof tmp_name) {
        snprintf(err, errlen, "%s: path too long", path);
        return NULL;
    }
    install_handlers();
    struct stat st;
    in_place = !stat(path, &st) && (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode));
    if (in_place) {
        /* without O_NONBLOCK, opening a FIFO that no program reads would wait
           forever: tried every 10 ms for IMG_FIFO_TIMEOUT_MS, then refused */
        int pfd = -1;
        for (int waited = 0;; waited += 10) {
            pfd = open(path, O_WRONLY | O_NONBLOCK);
            if (pfd >= 0 || errno != ENXIO || waited >= IMG_FIFO_TIMEOUT_MS) break;
            struct timespec ts = { 0, 10000000L };
            nanosleep(&ts, NULL);
        }
        if (pfd < 0 && errno == ENXIO) {
            snprintf(err, errlen, "%s: a FIFO that no program read for %d s", path, IMG_FIFO_TIMEOUT_MS / 1000);
            return NULL;
        }
        int fl = pfd < 0 ? -1 : fcntl(pfd, F_GETFL);
        FILE *pf = fl < 0 || fcntl(pfd, F_SETFL, fl & ~O_NONBLOCK) ? NULL : fdopen(pfd, "wb");
        if (!pf) {
            snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
            if (pfd >= 0) close(pfd);
        }
        return pf;
    }
    int fd = mkstemp(tmp_name);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot create a file in %s: %s", path, dir, strerror(errno));
        return NULL;
    }
    tmp_live = 1;
    /* mkstemp makes the file 0600; give it the mode a plain create would. */
    mode_t mask = umask(0);
    umask(mask);
    (void)fchmod(fd, 0666 & ~mask);
    FILE *f = fdopen(fd, "wb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        close(fd);
        unlink(tmp_name);
        tmp_live = 0;
    }
    return f;
}

/* Finishes the temporary file: flush, fsync, close, rename. `ok` false (a
 * failed write) or any failure here removes it. Returns 0 or 1. */
static int tmp_close(FILE *f, const char *path, int ok, char *err, size_t errlen)
{
    if (ok && (fflush(f) || ferror(f))) {
        snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
        ok = 0;
    }
    if (in_place) {
        if (fclose(f) && ok) {
            snprintf(err, errlen, "%s: close failed: %s", path, strerror(errno));
            ok = 0;
        }
        in_place = 0;
        return ok ? 0 : 1;
    }
    if (ok && fsync(fileno(f))) {
        snprintf(err, errlen, "%s: fsync failed: %s", path, strerror(errno));
        ok = 0;
    }
    if (fclose(f) && ok) {
        snprintf(err, errlen, "%s: close failed: %s", path, strerror(errno));
        ok = 0;
    }
    if (ok && stage(path)) {
        snprintf(err, errlen, "%s: out of memory", path);
        ok = 0;
    }
    if (!ok) unlink(tmp_name);
    tmp_live = 0;
    return ok ? 0 : 1;
}

static void row_565_to_888(const uint16_t *src, unsigned w, uint8_t *dst)
{
    for (unsigned x = 0; x < w; x++) img_565_to_888(src[x], dst + 3 * x);
}

static int write_ppm_565(FILE *f, const uint16_t *px, unsigned w, unsigned h, size_t stride,
                         uint8_t *row)
{
    if (fprintf(f, "P6\n%u %u\n255\n", w, h) < 0) return 0;
    for (unsigned y = 0; y < h; y++) {
        row_565_to_888(px + (size_t)y * stride, w, row);
        if (fwrite(row, 3, w, f) != w) return 0;
    }
    return 1;
}

struct png_err { char *msg; size_t len; };

static void png_on_error(png_structp p, png_const_charp msg)
{
    struct png_err *e = png_get_error_ptr(p);
    snprintf(e->msg, e->len, "libpng: %s", msg);
    png_longjmp(p, 1);
}

static void png_on_warning(png_structp p, png_const_charp msg) { (void)p; (void)msg; }

/* Returns 1 on success; on failure err holds libpng's message. */
static int write_png_565(FILE *f, const uint16_t *px, unsigned w, unsigned h, size_t stride,
                         uint8_t *row, char *err, size_t errlen)
{
    struct png_err pe = { err, errlen };
    png_structp p = png_create_write_struct(PNG_LIBPNG_VER_STRING, &pe, png_on_error, png_on_warning);
    if (!p) return 0;
    png_infop info = png_create_info_struct(p);
    if (!info) {
        png_destroy_write_struct(&p, NULL);
        return 0;
    }
    if (setjmp(png_jmpbuf(p))) {
        png_destroy_write_struct(&p, &info);
        return 0;
    }
    png_init_io(p, f);
    png_set_IHDR(p, info, w, h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(p, info);
    for (unsigned y = 0; y < h; y++) {
        row_565_to_888(px + (size_t)y * stride, w, row);
        png_write_row(p, row);
    }
    png_write_end(p, NULL);
    png_destroy_write_struct(&p, &info);
    return 1;
}

int img_write_565(const char *path, enum img_format fmt, const uint16_t *px,
                  unsigned w, unsigned h, size_t stride, char *err, size_t errlen)
{
    uint8_t *row = malloc((size_t)w * 3 + 1);
    if (!row) {
        snprintf(err, errlen, "%s: out of memory", path);
        return 1;
    }
    FILE *f = tmp_open(path, err, errlen);
    if (!f) {
        free(row);
        return 2;
    }
    int ok;
    err[0] = 0;
    if (fmt == IMG_PNG)
        ok = write_png_565(f, px, w, h, stride, row, err, errlen);
    else
        ok = write_ppm_565(f, px, w, h, stride, row);
    free(row);
    if (!ok) {
        if (!err[0]) snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
        tmp_close(f, path, 0, err, errlen);
        return 1;
    }
    return tmp_close(f, path, 1, err, errlen);
}

int img_write_raw565(const char *path, const uint16_t *px, unsigned w, unsigned h,
                     size_t stride, char *err, size_t errlen)
{
    uint8_t *row = malloc((size_t)w * 2 + 1);
    if (!row) {
        snprintf(err, errlen, "%s: out of memory", path);
        return 1;
    }
    FILE *f = tmp_open(path, err, errlen);
    if (!f) {
        free(row);
        return 2;
    }
    int ok = 1;
    for (unsigned y = 0; y < h && ok; y++) {
        const uint16_t *src = px + (size_t)y * stride;
        for (unsigned x = 0; x < w; x++) {
            row[2 * x] = (uint8_t)(src[x] & 0xff);
            row[2 * x + 1] = (uint8_t)(src[x] >> 8);
        }
        ok = fwrite(row, 2, w, f) == w;
        if (img_fault_signal_in_write && y == 0) {
            fflush(f);
            raise(SIGTERM);
        }
    }
    free(row);
    if (!ok) snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
    return tmp_close(f, path, ok, err, errlen);
}

int img_write_ppm888(const char *path, const uint8_t *rgb, unsigned w, unsigned h,
                     char *err, size_t errlen)
{
    FILE *f = tmp_open(path, err, errlen);
    if (!f) return 2;
    int ok = fprintf(f, "P6\n%u %u\n255\n", w, h) > 0 &&
             fwrite(rgb, 3 * (size_t)w, h, f) == h;
    if (!ok) snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
    return tmp_close(f, path, ok, err, errlen);
}
