/* SPDX-License-Identifier: MIT */
/* Replays the emulated-panel test vectors (the .txt files under tests/vectors/panel, format
 * in docs/hal.md) through emu_panel. The same files drive the JavaScript
 * port of the emulator, so both decode the protocol alike.
 * Usage: test_panel_vectors DIR|FILE...  — one PASS/FAIL per file. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "sim/emu_panel.h"

static uint32_t crc32_update(uint32_t crc, const uint8_t *b, size_t n)
{
    crc = ~crc;
    for (size_t i = 0; i < n; i++) {
        crc ^= b[i];
        for (int k = 0; k < 8; k++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

/* CRC-32 (IEEE) of the viewed glass as little-endian uint16, row-major. */
static uint32_t glass_crc(const struct emu_panel *p, uint16_t *g)
{
    uint16_t w = emu_panel_glass_width(p), h = emu_panel_glass_height(p);
    emu_panel_glass(p, g, w, h);
    uint32_t crc = 0;
    for (size_t i = 0; i < (size_t)w * h; i++) {
        uint8_t b[2] = { (uint8_t)g[i], (uint8_t)(g[i] >> 8) };
        crc = crc32_update(crc, b, 2);
    }
    return crc;
}

struct run {
    struct emu_panel *p;
    uint16_t *glass;
    uint64_t t_ns;
    uint32_t ns_per_byte;
    int have_module;
};

static void send(struct run *r, const uint8_t *b, size_t n)
{
    emu_panel_spi(r->p, b, n, r->t_ns, r->ns_per_byte);
    r->t_ns += (uint64_t)n * r->ns_per_byte;
}

/* Parses hex bytes from s into out (max cap); returns the count or -1. */
static int hex_bytes(const char *s, uint8_t *out, int cap)
{
    int n = 0;
    for (;;) {
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s)
            return n;
        char *end;
        unsigned long v = strtoul(s, &end, 16);
        if (end == s || v > 0xFF || n >= cap || (*end && *end != ' ' && *end != '\t'))
            return -1;
        out[n++] = (uint8_t)v;
        s = end;
    }
}

static int line_id(const char *s)
{
    static const char *const nm[] = { "dc", "reset", "cs", "bl" };
    for (int i = 0; i < 4; i++)
        if (strcmp(s, nm[i]) == 0)
            return i;
    return -1;
}

/* Runs one statement; returns NULL or a failure text (in msg). */
static const char *step(struct run *r, char *ln, char *msg, size_t msz)
{
    char word[32] = "";
    int used = 0;
    sscanf(ln, "%31s%n", word, &used);
    char *rest = ln + used;
    while (*rest == ' ')
        rest++;
    uint8_t b[256];
    if (strcmp(word, "module") == 0) {
        uint8_t view = 0;
        const struct emu_module *m = emu_module_find(rest, &view);
        if (!m)
            return "unknown module";
        emu_panel_init(r->p, m, view);
        r->t_ns = 0;
        r->ns_per_byte = 0;
        r->have_module = 1;
        return NULL;
    }
    if (!r->have_module)
        return "first statement must be 'module'";
    if (strcmp(word, "view") == 0) {
        return emu_panel_init(r->p, r->p->mod, (uint8_t)atoi(rest)) ? "bad view" : NULL;
    } else if (strcmp(word, "cs_tied_low") == 0) {
        r->p->cs_tied_low = 1;
    } else if (strcmp(word, "line") == 0) {
        char nm[16];
        int lv;
        if (sscanf(rest, "%15s %d", nm, &lv) != 2 || line_id(nm) < 0)
            return "bad line statement";
        emu_panel_line(r->p, line_id(nm), lv, r->t_ns);
    } else if (strcmp(word, "reset") == 0) {
        emu_panel_line(r->p, 1, 0, r->t_ns);
        r->t_ns += 10000;
        emu_panel_line(r->p, 1, 1, r->t_ns);
    } else if (strcmp(word, "cmd") == 0) {
        int n = hex_bytes(rest, b, (int)sizeof b);
        if (n < 1)
            return "bad cmd bytes";
        emu_panel_line(r->p, 0, 0, r->t_ns);
        send(r, b, 1);
        emu_panel_line(r->p, 0, 1, r->t_ns);
        send(r, b + 1, (size_t)n - 1);
    } else if (strcmp(word, "data") == 0) {
        int n = hex_bytes(rest, b, (int)sizeof b);
        if (n < 1)
            return "bad data bytes";
        emu_panel_line(r->p, 0, 1, r->t_ns);
        send(r, b, (size_t)n);
    } else if (strcmp(word, "pixels") == 0) {
        char *end;
        unsigned long count = strtoul(rest, &end, 10);
        unsigned px[64];
        int k = 0, used2;
        while (k < 64 && sscanf(end, "%x%n", &px[k], &used2) == 1) {
            end += used2;
            k++;
        }
        if (k == 0 || count == 0)
            return "bad pixels statement";
        emu_panel_line(r->p, 0, 1, r->t_ns);
        for (unsigned long i = 0; i < count; i++) {
            uint8_t be[2] = { (uint8_t)(px[i % (unsigned)k] >> 8), (uint8_t)px[i % (unsigned)k] };
            send(r, be, 2);
        }
    } else if (strcmp(word, "delay_ms") == 0) {
        r->t_ns += strtoull(rest, NULL, 10) * 1000000ull;
    } else if (strcmp(word, "delay_us") == 0) {
        r->t_ns += strtoull(rest, NULL, 10) * 1000ull;
    } else if (strcmp(word, "spi_ns") == 0) {
        r->ns_per_byte = (uint32_t)strtoul(rest, NULL, 10);
    } else if (strcmp(word, "finish") == 0) {
        emu_panel_finish(r->p, r->t_ns);
    } else if (strcmp(word, "expect_ok") == 0) {
        const char *v = emu_panel_violation(r->p);
        if (v) {
            snprintf(msg, msz, "unexpected violation: %s", v);
            return msg;
        }
    } else if (strcmp(word, "expect_violation") == 0) {
        const char *v = emu_panel_violation(r->p);
        if (!v || strcmp(v, rest) != 0) {
            snprintf(msg, msz, "violation \"%s\", want \"%s\"", v ? v : "(none)", rest);
            return msg;
        }
    } else if (strcmp(word, "expect_size") == 0) {
        unsigned w, h;
        if (sscanf(rest, "%u %u", &w, &h) != 2)
            return "bad expect_size";
        if (w != emu_panel_glass_width(r->p) || h != emu_panel_glass_height(r->p)) {
            snprintf(msg, msz, "glass %ux%u, want %ux%u", (unsigned)emu_panel_glass_width(r->p),
                     (unsigned)emu_panel_glass_height(r->p), w, h);
            return msg;
        }
    } else if (strcmp(word, "expect_glass") == 0 || strcmp(word, "expect_mem") == 0) {
        unsigned x, y, v;
        if (sscanf(rest, "%u %u %x", &x, &y, &v) != 3)
            return "bad expect statement";
        unsigned got;
        if (word[7] == 'g') {
            uint16_t w = emu_panel_glass_width(r->p), h = emu_panel_glass_height(r->p);
            if (x >= w || y >= h)
                return "pixel outside the glass";
            emu_panel_glass(r->p, r->glass, w, h);
            got = r->glass[(size_t)y * w + x];
        } else {
            got = emu_panel_mem(r->p, (uint16_t)x, (uint16_t)y);
        }
        if (got != v) {
            snprintf(msg, msz, "%s %u %u is %04X, want %04X", word, x, y, got, v);
            return msg;
        }
    } else if (strcmp(word, "expect_glass_crc32") == 0) {
        uint32_t want = (uint32_t)strtoul(rest, NULL, 16), got = glass_crc(r->p, r->glass);
        if (got != want) {
            snprintf(msg, msz, "glass crc32 %08X, want %08X", (unsigned)got, (unsigned)want);
            return msg;
        }
    } else {
        snprintf(msg, msz, "unknown statement '%s'", word);
        return msg;
    }
    return NULL;
}

static void run_file(struct run *r, const char *path)
{
    FILE *f = fopen(path, "r");
    char ln[1024], msg[400];
    const char *why = NULL;
    int lineno = 0, expects = 0;
    r->have_module = 0;
    if (!f) {
        check(0, path, "cannot open");
        return;
    }
    while (!why && fgets(ln, sizeof ln, f)) {
        lineno++;
        char *e = strchr(ln, '#');
        if (e)
            *e = 0;
        size_t n = strlen(ln);
        while (n && (ln[n - 1] == '\n' || ln[n - 1] == '\r' || ln[n - 1] == ' '))
            ln[--n] = 0;
        char *s = ln;
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s)
            continue;
        expects += strncmp(s, "expect", 6) == 0;
        why = step(r, s, msg, sizeof msg);
    }
    fclose(f);
    if (!why && expects == 0)
        why = "no expectations";
    check(why == NULL, path, "line %d: %s", lineno, why);
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

int main(int argc, char **argv)
{
    struct run r;
    memset(&r, 0, sizeof r);
    r.p = malloc(sizeof *r.p);
    r.glass = malloc(sizeof(uint16_t) * EMU_MEM_W * EMU_MEM_H);
    if (!r.p || !r.glass)
        return 1;
    int files = 0;
    for (int i = 1; i < argc; i++) {
        DIR *d = opendir(argv[i]);
        if (!d) {
            run_file(&r, argv[i]);
            files++;
            continue;
        }
        char *names[512];
        int n = 0;
        struct dirent *de;
        while ((de = readdir(d)) && n < 512) {
            size_t l = strlen(de->d_name);
            if (l > 4 && strcmp(de->d_name + l - 4, ".txt") == 0) {
                names[n] = malloc(strlen(argv[i]) + l + 2);
                sprintf(names[n], "%s/%s", argv[i], de->d_name);
                n++;
            }
        }
        closedir(d);
        qsort(names, (size_t)n, sizeof names[0], cmp_str);
        for (int k = 0; k < n; k++) {
            run_file(&r, names[k]);
            free(names[k]);
            files++;
        }
    }
    check(files > 0, "vectors_found", "no vector files given");
    free(r.p);
    free(r.glass);
    return check_exit();
}
