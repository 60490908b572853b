/* SPDX-License-Identifier: MIT */
/* main.c — host_sim: renders a scene strip by strip with one of the three
 * renderer cores and sends every strip through the panel driver into the
 * emulated controller (or a memory framebuffer), then writes what the glass
 * shows. The command line, exit codes and --stats fields are the project's
 * outside contract (docs/host_sim.md).
 */
#define _XOPEN_SOURCE 700   /* realpath */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <signal.h>
#include <unistd.h>

#include "../tools/common/file_id.h"
#include "host_sim/compare.h"
#include "core_api.h"
#include "host_sim/imgio.h"
#include "host_sim/panel_out.h"
#include "host_sim/quality_opts.h"
#include "tools/quality/quality.h"
#include "host_sim/window.h"
#include "firmware/app/check_pattern.h"
#include "firmware/app/font5x7.h"
#include "hal/panel.h"
#include "tools/scene/suggest.h"

/* Rows a strip has: what a small MCU can hold (16 rows x 320 x 2 bytes = 10 KiB). */
#define STRIP_ROWS_DEFAULT 16
/* Largest side accepted with --panel none (memory, not the panel, limits it). */
#define MAX_SIDE 8192

enum { EXIT_OK = 0, EXIT_INTERNAL = 1, EXIT_USAGE = 2, EXIT_PROTOCOL = 3 };

static const char usage_text[] =
    "usage: host_sim --scene FILE [options]\n"
    "       host_sim --pattern check [--panel NAME] [--rotation R] [--miswire WHAT] [--out FILE]\n"
    "  --panel NAME|none             the panel (hal/panels.def): a controller, %s\n"
    "                                (the module of the size), or a module,\n"
    "                                %s;\n"
    "                                none: a memory framebuffer (default %s)\n"
    "  --size WxH                    render size (default: the panel's native size;\n"
    "                                with --panel none, the scene's canvas size)\n"
    "  --numeric fixed|float|double  arithmetic of the renderer (default fixed; fixed point\n"
    "                                in the format the scene's ranges call for)\n"
    "  --out FILE.png|FILE.ppm       what the glass shows after the last frame\n"
    "  --out-raw FILE                the same as raw RGB565 (little-endian uint16)\n"
    "  --out-rgb888 FILE.ppm         the renderer's colour before RGB565 quantisation\n"
    "  --frames N                    render N frames (default 1)\n"
    "  --loop                        render the scene's animation (its frames, or the still\n"
    "                                frame) endlessly, one line per frame on stdout (frame,\n"
    "                                this host's frame rate and time, SPI bytes); SIGINT\n"
    "                                (Ctrl-C) or SIGTERM ends it after\n"
    "                                the frame, exit 0; --out FILE: the last frame\n"
    "  --loop-frames N               end --loop after N frames\n"
    "  --flush dirty|full            dirty: only the changed rectangles of each strip go to\n"
    "                                the panel (default with --loop); full: every row\n"
    "  --fps-overlay                 the frame rate drawn on the glass (top-left)\n"
    "  --window                      a live window of the glass (SDL2), updated per strip;\n"
    "                                without --loop it stays until closed (or SIGINT)\n"
    "  --window-scale N              its pixels per glass pixel (default 2)\n"
    "  --out PATTERN.png             with one %%d (or %%0Nd) in the name: a file per frame\n"
    "  (a progress line goes to stderr during long frames when stderr is a terminal)\n"
    "  --stats                       one JSON object per frame on stdout\n"
    "  --backend sim|linux           where the HAL's bytes go (default sim)\n"
    "  --rotation 0..3               quarter turns added to the panel's orientation (the\n"
    "                                module mounted turned): on a panel that is not square,\n"
    "                                1 and 3 show its native size turned (240x320 becomes\n"
    "                                320x240, landscape); with --size, odd turns need a\n"
    "                                square size (default 0)\n";
/* (two strings: C11 promises string literals of up to 4095 characters) */
static const char usage_text2[] =
    "Raspberry Pi (--backend linux: spidev + libgpiod; docs/raspberry-pi.md):\n"
    "  --spi-dev PATH                spidev device (default /dev/spidev0.0)\n"
    "  --spi-hz N                    SPI clock in Hz (default the controller's rated write\n"
    "                                clock: 62500000 for the ST7789VW, 10000000 for the\n"
    "                                ILI9341; a module tested faster may take more)\n"
    "  --spi-mode 0..3               SPI mode (default the panel's: 3 for the ST7789,\n"
    "                                CS-less modules need it; 0 for the others)\n"
    "  --gpio-chip NAME|PATH         GPIO chip of the lines (default gpiochip0)\n"
    "  --dc N, --rst N|none, --bl N|none\n"
    "                                BCM line numbers of D/C, RESET, backlight\n"
    "                                (default 25, 27, 18)\n"
    "tool options:\n"
    "  --compare fixed|float|double  also render with this core (memory framebuffer)\n"
    "                                and report psnr/max_err of the last frame's colours\n"
    "  --summary                     one line: scene, size, numeric, time, accuracy\n"
    "  --progressive                 ray tracer: each frame first as 8x8 blocks (one ray each)\n"
    "                                on the panel, then refined in place to the full frame\n"
    "  --strip-rows N                rows per strip (default 16)\n"
    "  --num-frac F                  fixed point in Q(31-F).F, F in 12..20, instead of\n"
    "                                the scene's own format\n"
    "  --max-memory N[K|M|G]         renderer work memory and the scene's textures allowed\n"
    "                                (default 1G)\n"
    "  --min-psnr DB                 choose the scene's methods: the cheapest on --target that\n"
    "                                renders within DB of double's exact render (tools/quality;\n"
    "                                the choice on stderr; the scene's quality block otherwise)\n"
    "  --target m0plus|m4f|rp2040    the target whose cost --min-psnr minimises (default: the\n"
    "                                quality block's, else m0plus)\n"
    "  --max-cost N[K|M|G]           a frame's estimated work allowed: the ray tracer's\n"
    "                                ray-object tests, the rasterizer's triangle-strip\n"
    "                                visits and pixels (default 20G; docs/host_sim.md)\n"
    "  --inject-fault NAME           make the panel driver misbehave (tests): %s;\n"
    "                                signal-in-write: SIGTERM to itself in the middle of\n"
    "                                writing --out-raw (tests: nothing is left behind)\n"
    "the bring-up pattern (the cgfs-check images; docs/firmware.md):\n"
    "  --pattern check               draw it instead of a scene: bars, gradients, corner marks,\n"
    "                                a border and the driver's settings; with --panel, --rotation,\n"
    "                                --miswire, --board-clocks, --strip-rows, --out, --out-raw and\n"
    "                                --backend (and its options), no other option\n"
    "  --board-clocks SPI_HZ,SYS_HZ  the clocks it prints (a board's; default the bus's SPI clock\n"
    "                                and no clk_sys)\n"
    "  --miswire %s\n"
    "                                the driver with one setting wrong, for a scene too (the\n"
    "                                emulated module stays true): offsets, colour order, inversion,\n"
    "                                rotation a half turn off, each pixel's bytes swapped\n"
    "exit status: 0 ok, 1 internal error, 2 usage or input error,\n"
    "             3 panel protocol violation\n";

struct opts {
    const char *spi_dev, *gpio_chip;
    unsigned spi_hz, rotation;
    int spi_mode, dc, rst, bl;   /* -1 / PANEL_OUT_PIN_DEFAULT: the default */
    const char *scene, *panel, *numeric, *out, *out_raw, *out_rgb888, *backend;
    const char *compare, *fault;
    const char *pattern, *miswire;   /* --pattern check, --miswire */
    uint32_t board_spi_hz, board_sys_hz;   /* --board-clocks */
    int has_clocks;
    int has_size, stats, summary, progressive;
    int loop, fps_overlay, window;
    unsigned loop_frames, window_scale;
    int flush;                 /* 0 default, 1 full, 2 dirty */
    int num_frac;              /* --num-frac, 0: the scene's own format */
    unsigned long long max_memory;   /* --max-memory: renderer work memory, bytes */
    double max_cost;           /* --max-cost: a frame's estimated work (check_cost) */
    unsigned width, height, frames, strip_rows;
    struct quality_opts quality;   /* --min-psnr, --target */
};

static int fail(int code, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static int fail(int code, const char *fmt, ...)
{
    va_list ap;
    fputs("host_sim: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return code;
}

/* A decimal count in 1..max, digits only; returns 0 if it is not one. */
static unsigned parse_count(const char *s, unsigned max)
{
    unsigned long v = 0;
    if (*s < '1' || *s > '9') return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return 0;
        v = v * 10 + (unsigned long)(*s - '0');
        if (v > max) return 0;
    }
    return (unsigned)v;
}

/* Why s (its first n characters) is not a decimal count in 1..max, into
 * why; 0 if it is one. */
static int count_why(const char *s, size_t n, unsigned long max, char *why, size_t len)
{
    size_t i = 0;
    unsigned long v = 0;
    while (i < n && s[i] >= '0' && s[i] <= '9') {
        v = v * 10 + (unsigned long)(s[i++] - '0');
        if (v > max) v = max + 1;
    }
    if (i == 0) snprintf(why, len, n ? "'%.*s' is not a number" : "no number", (int)n, s);
    else if (i < n) snprintf(why, len, "'%.*s' after the number", (int)(n - i), s + i);
    else if (v == 0) snprintf(why, len, "0 is less than 1");
    else if (v > max) snprintf(why, len, "larger than %lu", max);
    else return 0;
    return -1;
}

/* "WxH" with both sides in 1..MAX_SIDE; -1 with the reason in why. */
static int parse_size(const char *s, unsigned *w, unsigned *h, char *why, size_t len)
{
    char r[96];
    const char *x = strchr(s, 'x');
    if (!x) return snprintf(why, len, "no 'x' between width and height"), -1;
    if (count_why(s, (size_t)(x - s), MAX_SIDE, r, sizeof r)) return snprintf(why, len, "width: %s", r), -1;
    if (count_why(x + 1, strlen(x + 1), MAX_SIDE, r, sizeof r)) return snprintf(why, len, "height: %s", r), -1;
    *w = (unsigned)strtoul(s, NULL, 10);   /* (digits only, checked above) */
    *h = (unsigned)strtoul(x + 1, NULL, 10);
    return 0;
}

/* Option NAME (one of parse_args' with_arg) with its value VAL into o:
 * EXIT_OK, or EXIT_USAGE after the message. */
static int set_option(struct opts *o, const char *name, const char *val)
{
    if (!strcmp(name, "--scene")) o->scene = val;
    else if (!strcmp(name, "--panel")) {
        uint16_t pw, ph;
        char panels[128], modules[256];
        if (strcmp(val, "none") && panel_out_native(val, &pw, &ph)) {
            panel_out_controllers(panels, sizeof panels);
            panel_out_modules(modules, sizeof modules);
            return fail(EXIT_USAGE, "unknown panel '%s' (%s|%s|none)", val, panels, modules);
        }
        o->panel = val;
    } else if (!strcmp(name, "--size")) {
        char why[128];
        if (parse_size(val, &o->width, &o->height, why, sizeof why))
            return fail(EXIT_USAGE, "bad size '%s': %s (WxH, each side 1..%d)", val, why, MAX_SIDE);
        o->has_size = 1;
    } else if (!strcmp(name, "--numeric") || !strcmp(name, "--compare")) {
        if (!core_api_by_name(val))
            return fail(EXIT_USAGE, "unknown numeric mode '%s' (fixed|float|double)", val);
        if (!strcmp(name, "--numeric")) o->numeric = val; else o->compare = val;
    } else if (!strcmp(name, "--out")) o->out = val;
    else if (!strcmp(name, "--out-raw")) o->out_raw = val;
    else if (!strcmp(name, "--out-rgb888")) o->out_rgb888 = val;
    else if (!strcmp(name, "--frames")) {
        if (!(o->frames = parse_count(val, 65535)))
            return fail(EXIT_USAGE, "bad frame count '%s' (1..65535)", val);
    } else if (!strcmp(name, "--strip-rows")) {
        char why[128];
        if (count_why(val, strlen(val), MAX_SIDE, why, sizeof why))
            return fail(EXIT_USAGE, "bad strip height '%s': %s (1..%d)", val, why, MAX_SIDE);
        o->strip_rows = parse_count(val, MAX_SIDE);
    } else if (!strcmp(name, "--backend")) {
        if (strcmp(val, "sim") && strcmp(val, "linux"))
            return fail(EXIT_USAGE, "unknown backend '%s' (sim|linux)", val);
        o->backend = val;
    } else if (!strcmp(name, "--num-frac")) {
        unsigned f = parse_count(val, SCENE_FORMAT_FRAC_MAX);
        if (f < SCENE_FORMAT_FRAC_MIN)
            return fail(EXIT_USAGE, "bad --num-frac '%s' (%d..%d)", val, SCENE_FORMAT_FRAC_MIN,
                        SCENE_FORMAT_FRAC_MAX);
        o->num_frac = (int)f;
    } else if (!strcmp(name, "--max-memory") || !strcmp(name, "--max-cost")) {
        /* a count with an optional K, M or G (powers of 1024 for memory, of 1000 for cost) */
        char *e;
        errno = 0;
        unsigned long long v = strtoull(val, &e, 10);
        int mem = !strcmp(name, "--max-memory");
        unsigned long long k = mem ? 1024 : 1000, mul = 1;
        if (*e == 'K') mul = k, e++;
        else if (*e == 'M') mul = k * k, e++;
        else if (*e == 'G') mul = k * k * k, e++;
        if (val[0] < '0' || val[0] > '9' || *e || errno || v == 0 || v > ~0ull / mul)
            return fail(EXIT_USAGE, "bad %s '%s' (a positive count, optionally with K, M or G)", name, val);
        if (mem) o->max_memory = v * mul;
        else o->max_cost = (double)v * (double)mul;
    } else if (!strcmp(name, "--loop-frames")) {
        if (!(o->loop_frames = parse_count(val, 4000000000u)))
            return fail(EXIT_USAGE, "bad --loop-frames '%s' (1..4000000000)", val);
    } else if (!strcmp(name, "--window-scale")) {
        if (!(o->window_scale = parse_count(val, 8)))
            return fail(EXIT_USAGE, "bad --window-scale '%s' (1..8)", val);
    } else if (!strcmp(name, "--flush")) {
        if (strcmp(val, "full") && strcmp(val, "dirty"))
            return fail(EXIT_USAGE, "unknown --flush '%s' (dirty|full)", val);
        o->flush = !strcmp(val, "full") ? 1 : 2;
    } else if (!strcmp(name, "--spi-dev")) o->spi_dev = val;
    else if (!strcmp(name, "--gpio-chip")) o->gpio_chip = val;
    else if (!strcmp(name, "--spi-hz")) {
        if (!(o->spi_hz = parse_count(val, 125000000)))
            return fail(EXIT_USAGE, "bad --spi-hz '%s' (1..125000000)", val);
    } else if (!strcmp(name, "--spi-mode") || !strcmp(name, "--rotation")) {
        if (val[0] < '0' || val[0] > '3' || val[1])
            return fail(EXIT_USAGE, "bad %s '%s' (0..3)", name, val);
        if (!strcmp(name, "--spi-mode")) o->spi_mode = val[0] - '0';
        else o->rotation = (unsigned)(val[0] - '0');
    } else if (!strcmp(name, "--dc") || !strcmp(name, "--rst") || !strcmp(name, "--bl")) {
        int *pin = !strcmp(name, "--dc") ? &o->dc : !strcmp(name, "--rst") ? &o->rst : &o->bl;
        if (strcmp(name, "--dc") && !strcmp(val, "none")) *pin = -1;
        else if (!strcmp(val, "0")) *pin = 0;
        else if (!(*pin = (int)parse_count(val, 1023)))
            return fail(EXIT_USAGE, "bad %s '%s' (a line number 0..1023%s)", name, val,
                        strcmp(name, "--dc") ? " or none" : "");
    } else if (!strcmp(name, "--pattern")) {
        if (strcmp(val, "check")) return fail(EXIT_USAGE, "unknown pattern '%s' (check)", val);
        o->pattern = val;
    } else if (!strcmp(name, "--miswire")) {
        char list[128];
        snprintf(list, sizeof list, "|%s", panel_out_miswires);
        size_t n = strlen(val);
        const char *at = strstr(list, val);
        if (!at || at[-1] != '|' || (at[n] && at[n] != '|'))
            return fail(EXIT_USAGE, "unknown --miswire '%s' (%s)", val, panel_out_miswires);
        o->miswire = val;
    } else if (!strcmp(name, "--board-clocks")) {
        const char *c = strchr(val, ',');
        char why[128];
        if (!c || count_why(val, (size_t)(c - val), 1000000000u, why, sizeof why) ||
            count_why(c + 1, strlen(c + 1), 1000000000u, why, sizeof why))
            return fail(EXIT_USAGE, "bad --board-clocks '%s' (SPI_HZ,SYS_HZ, each 1..1000000000)", val);
        o->board_spi_hz = (uint32_t)strtoul(val, NULL, 10);
        o->board_sys_hz = (uint32_t)strtoul(c + 1, NULL, 10);
        o->has_clocks = 1;
    } else if (!strcmp(name, "--min-psnr") || !strcmp(name, "--target")) {
        return quality_opts_set(&o->quality, name, val);
    } else if (!strcmp(name, "--inject-fault")) {
        if (!strcmp(val, "signal-in-write")) img_fault_signal_in_write = 1;   /* imgio's, not the panel's */
        else o->fault = val;
    }
    return EXIT_OK;
}

/* Every option's name, for "did you mean" (those with an argument first). */
static const char *const option_names[] = {
    "--scene", "--panel", "--size", "--numeric", "--out", "--out-raw", "--out-rgb888",
    "--frames", "--backend", "--compare", "--strip-rows", "--inject-fault", "--num-frac",
    "--loop-frames", "--flush", "--window-scale", "--spi-dev", "--spi-hz", "--spi-mode", "--gpio-chip", "--dc",
    "--rst", "--bl", "--rotation", "--max-memory", "--max-cost", "--pattern", "--miswire", "--board-clocks", "--min-psnr", "--target", NULL,
    "--stats", "--summary", "--progressive", "--loop", "--fps-overlay", "--window", "--help", NULL,
};

/* An unknown option: exit 2, with the nearest known name if it is near. */
static int unknown_option(const char *a)
{
    const char *names[sizeof option_names / sizeof option_names[0]];
    size_t k = 0;
    for (size_t i = 0; i < sizeof option_names / sizeof option_names[0]; i++)
        if (option_names[i]) names[k++] = option_names[i];
    names[k] = NULL;
    const char *near = !strncmp(a, "--", 2) ? suggest_nearest(a, names) : NULL;
    if (near) return fail(EXIT_USAGE, "unknown option '%s' (did you mean '%s'? try --help)", a, near);
    return fail(EXIT_USAGE, "unknown option '%s' (try --help)", a);
}

static int parse_args(int argc, char **argv, struct opts *o)
{
    const char *const *with_arg = option_names;   /* up to its first NULL */
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *val = NULL;
        char name[32];
        const char *eq = strchr(a, '=');
        size_t n = eq ? (size_t)(eq - a) : strlen(a);
        if (strncmp(a, "--", 2) || n >= sizeof name) return unknown_option(a);
        memcpy(name, a, n);
        name[n] = 0;
        if (!strcmp(name, "--help") || !strcmp(name, "-h")) {
            char panels[128], modules[256];
            panel_out_controllers(panels, sizeof panels);
            panel_out_modules(modules, sizeof modules);
            printf(usage_text, panels, modules, panel_out_default());
            printf(usage_text2, panel_out_faults, panel_out_miswires);
            exit(EXIT_OK);
        }
        if (!strcmp(name, "--stats") || !strcmp(name, "--summary") || !strcmp(name, "--progressive") ||
            !strcmp(name, "--loop") || !strcmp(name, "--fps-overlay") || !strcmp(name, "--window")) {
            if (eq) return fail(EXIT_USAGE, "option %s takes no argument", name);
            if (!strcmp(name, "--stats")) o->stats = 1;
            else if (!strcmp(name, "--loop")) o->loop = 1;
            else if (!strcmp(name, "--fps-overlay")) o->fps_overlay = 1;
            else if (!strcmp(name, "--window")) o->window = 1;
            else if (!strcmp(name, "--summary")) o->summary = 1;
            else o->progressive = 1;
            continue;
        }
        int known = 0;
        for (int k = 0; with_arg[k]; k++) known |= !strcmp(name, with_arg[k]);
        if (!known) return unknown_option(name);
        if (eq) val = eq + 1;
        else if (i + 1 < argc) val = argv[++i];
        if (!val || !*val) return fail(EXIT_USAGE, "option %s needs an argument", name);
        int rc = set_option(o, name, val);
        if (rc != EXIT_OK) return rc;
    }
    if (o->scene && o->pattern) return fail(EXIT_USAGE, "--scene and --pattern: one or the other");
    if (!o->scene && !o->pattern) return fail(EXIT_USAGE, "--scene FILE is required (try --help)");
    if (o->has_clocks && !o->pattern) return fail(EXIT_USAGE, "--board-clocks needs --pattern check");
    if (o->pattern && (o->has_size || o->numeric || o->compare || o->frames || o->loop || o->loop_frames ||
                       o->stats || o->summary || o->progressive || o->fps_overlay || o->window ||
                       o->window_scale || o->out_rgb888 || o->num_frac || o->max_memory || o->max_cost > 0 ||
                       o->flush || o->fault))
        return fail(EXIT_USAGE, "--pattern check takes --panel, --rotation, --miswire, --board-clocks, "
                                "--strip-rows, --out, --out-raw and --backend with its options, no other option");
    if (o->num_frac && strcmp(o->numeric ? o->numeric : "fixed", "fixed") &&
        !(o->compare && !strcmp(o->compare, "fixed")))
        return fail(EXIT_USAGE, "--num-frac applies to fixed point (--numeric fixed or --compare fixed)");
    return EXIT_OK;
}

static uint64_t now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

/* The scene's name as the contract spells it: the path after "scenes/"
 * without ".scene" (book/raytracer-05), or the file name without it. */
static void scene_name(const char *path, char *out, size_t len)
{
    const char *s = NULL, *p = path;
    while ((p = strstr(p, "scenes/")) != NULL) s = p += 7;
    if (!s) {
        s = strrchr(path, '/');
        s = s ? s + 1 : path;
    }
    size_t n = strlen(s);
    if (n > 6 && !strcmp(s + n - 6, ".scene")) n -= 6;
    if (n >= len) n = len - 1;
    memcpy(out, s, n);
    out[n] = 0;
}

/* Writes s as a JSON string. */
static void json_str(const char *s)
{
    putchar('"');
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') printf("\\%c", c);
        else if (c < 0x20) printf("\\u%04x", c);
        else putchar(c);
    }
    putchar('"');
}

/* One renderer core set up for a scene and size. */
struct core {
    const struct core_api *api;
    void *scene;
    struct scene_info info;
    struct render_ctx ctx;
    void *work;
};

/* The scene file's text, read once (a FIFO or /dev/stdin can be read only
 * once) and parsed by each core that needs it. */
static char *scene_text;
static size_t scene_len;

static int core_open(struct core *c, const struct core_api *api, const char *path)
{
    char err[512] = "";
    c->api = api;
    int rc = api->scene_parse(path, scene_text, scene_len, &c->scene, err, sizeof err);
    if (rc) {
        fprintf(stderr, "%s\n", err[0] ? err : "scene: cannot load");
        return rc == CORE_SCENE_ENOMEM ? EXIT_INTERNAL : EXIT_USAGE;
    }
    api->scene_info(c->scene, &c->info);
    return EXIT_OK;
}

/* The scene analysis (tools/scene/scene_format.c) on the scene as the
 * double core parses it, at w x h: its return (0: a format fits) with *f
 * and the refusal's line in msg, or a load error's exit status in *load. */
static int analyse(const struct opts *o, unsigned w, unsigned h, struct scene_format *f, char *msg, size_t len,
                   int *load)
{
    struct core d = { 0 };
    *load = core_open(&d, &core_api_double, o->scene);
    if (*load) return -1;
    int rc = d.api->format(d.scene, o->scene, (uint16_t)w, (uint16_t)h, f, msg, len);
    d.api->scene_free(d.scene);
    return rc;
}

/* Float: the scene analysis's refusal that holds for float too (a sphere
 * around the camera too large for its rays to leave it, SCENE_ILL_INSIDE);
 * exit 2 with its line. */
static int float_check(const struct opts *o, unsigned w, unsigned h)
{
    struct scene_format f;
    char msg[768];
    int load, rc = analyse(o, w, h, &f, msg, sizeof msg, &load);
    if (load) return load;
    if (rc && f.ill == SCENE_ILL_INSIDE) {
        fprintf(stderr, "%s\n", msg);
        return EXIT_USAGE;
    }
    return EXIT_OK;
}

/* Frame 0 of the scene at w x h in core api, rendered quietly into rgb
 * (rows of strip_rows): 0, or -1 when the core cannot take it (a parse
 * error at that format, the work memory over --max-memory, ...). */
#define MAX_MEMORY_DEFAULT (1ull << 30)
static unsigned long long max_memory = MAX_MEMORY_DEFAULT;   /* --max-memory */
static int quiet_render(const struct core_api *api, const char *path, unsigned w, unsigned h, unsigned rows,
                        int exact, uint16_t *fb, uint8_t *rgb)
{
    char err[512];
    void *scene = NULL;
    if (!api || api->scene_parse(path, scene_text, scene_len, &scene, err, sizeof err)) return -1;
    if (exact) api->exact_methods(scene);
    int rc = -1;
    size_t ws = api->work_size(scene, (uint16_t)w, (uint16_t)h, (uint16_t)rows);
    void *work = ws <= max_memory ? malloc(ws ? ws : 1) : NULL;
    struct render_ctx ctx;
    struct render_stats st = { 0 };
    if (work && !api->init(&ctx, scene, (uint16_t)w, (uint16_t)h, (uint16_t)rows, work, ws) &&
        !api->begin_frame(&ctx, 0)) {
        rc = 0;
        for (unsigned y0 = 0; y0 < h && !rc; y0 += rows) {
            unsigned y1 = y0 + rows < h ? y0 + rows : h;
            struct render_target t = { .width = (uint16_t)w, .height = (uint16_t)h, .y0 = (uint16_t)y0,
                                       .y1 = (uint16_t)y1, .rgb565 = fb + (size_t)y0 * w,
                                       .rgb888 = rgb + (size_t)y0 * w * 3 };
            if (api->render_strip(&ctx, &t, &st)) rc = -1;
        }
    }
    free(work);
    api->scene_free(scene);
    return rc;
}

/* A refused scene (no --num-frac): what forcing each format would give,
 * measured on frame 0 at this size against the double build's exact
 * render, appended to the refusal's line. Only for renders up to 320x240
 * and within about two seconds of rendering: a hint, not a proof. */
static void forced_hint(const struct opts *o, unsigned w, unsigned h, char *msg, size_t len)
{
    if ((unsigned long long)w * h > 320u * 240u) return;
    unsigned rows = o->strip_rows ? o->strip_rows : STRIP_ROWS_DEFAULT;   /* as pick_core takes them */
    if (rows > h) rows = h;
    size_t npx = (size_t)w * h;
    uint16_t *fb = malloc(npx * sizeof *fb);
    uint8_t *ref = malloc(npx * 3), *rgb = malloc(npx * 3);
    uint64_t t0 = now_us();
    int best = -1;
    double best_db = -1;
    if (fb && ref && rgb && !quiet_render(&core_api_double, o->scene, w, h, rows, 1, fb, ref)) {
        for (int frac = 12; frac <= 20 && now_us() - t0 < 2000000; frac++) {
            memset(rgb, 0, npx * 3);
            if (quiet_render(core_api_fixed_frac(frac), o->scene, w, h, rows, 0, fb, rgb)) continue;
            struct compare_result cmp;
            compare_rgb888(rgb, ref, w, h, &cmp);
            double db = isinf(cmp.psnr) ? 99 : cmp.psnr;
            if (db > best_db) {
                best_db = db;
                best = frac;
            }
        }
    }
    free(fb);
    free(ref);
    free(rgb);
    size_t n = strlen(msg);
    if (best < 0 || n + 1 >= len) return;
    if (best_db >= 99)
        snprintf(msg + n, len - n, " (measured, not proven: with --num-frac %d frame 0 at %ux%u renders exactly as "
                 "double does)", best, w, h);
    else if (best_db >= 40)
        snprintf(msg + n, len - n, " (measured, not proven: with --num-frac %d frame 0 at %ux%u renders at %.1f dB "
                 "against double)", best, w, h, best_db);
    else
        snprintf(msg + n, len - n, " (measured: no format renders frame 0 at %ux%u at 40 dB against double; the "
                 "best, --num-frac %d, %.1f dB)", w, h, best, best_db);
}

/* The core of mode `numeric` for the scene at w x h. For fixed point: the
 * format of --num-frac, or the one the scene's ranges call for, analysed on
 * the scene as the double core parsed it (tools/scene/scene_format.c); a
 * scene that fits no format is an input error (exit 2, the analysis's line)
 * unless --num-frac forces one. *fits gets the products the analysis proved
 * in range at that format (struct scene.fits; 0 when it refused the scene). */
static int core_pick(const struct opts *o, const char *numeric, unsigned w, unsigned h,
                     const struct core_api **api, unsigned *fits)
{
    *fits = 0;
    if (strcmp(numeric, "fixed")) {
        *api = core_api_by_name(numeric);
        return strcmp(numeric, "float") ? EXIT_OK : float_check(o, w, h);
    }
    struct scene_format f;
    char msg[1024];
    int load, rc = analyse(o, w, h, &f, msg, sizeof msg, &load);
    if (load) return load;
    if (o->num_frac) {
        *api = core_api_fixed_frac(o->num_frac);
        if (!rc) *fits = scene_format_fits(&f, o->num_frac);
        return EXIT_OK;
    }
    if (rc) {
        if (f.ill != SCENE_ILL_INSIDE) forced_hint(o, w, h, msg, sizeof msg);
        fprintf(stderr, "%s\n", msg);
        return EXIT_USAGE;
    }
    *api = core_api_fixed_frac(f.num_frac);
    *fits = scene_format_fits(&f, f.num_frac);
    return *api ? EXIT_OK : fail(EXIT_INTERNAL, "no fixed-point core at NUM_FRAC %d", f.num_frac);
}


static int core_init(struct core *c, unsigned w, unsigned h, unsigned strip_rows)
{
    size_t ws = c->api->work_size(c->scene, (uint16_t)w, (uint16_t)h, (uint16_t)strip_rows);
    /* the scene's textures (their texels, every mip level) count too: the
       parser holds them for the whole run */
    unsigned long long tb = c->info.texture_bytes;
    if (tb && (unsigned long long)ws + tb > max_memory)
        return fail(EXIT_USAGE, "the scene at %ux%u needs %zu bytes of renderer work memory and %llu bytes of textures "
                                "(%llu in all), over the limit of %llu (--max-memory to raise it)", w, h, ws, tb,
                    (unsigned long long)ws + tb, max_memory);
    if ((unsigned long long)ws > max_memory)
        return fail(EXIT_USAGE, "the scene at %ux%u needs %zu bytes of renderer work memory, over the limit of %llu "
                                "(--max-memory to raise it)", w, h, ws, max_memory);
    c->work = malloc(ws ? ws : 1);
    if (!c->work) return fail(EXIT_INTERNAL, "out of memory (%zu bytes of renderer work memory)", ws);
    if (c->api->init(&c->ctx, c->scene, (uint16_t)w, (uint16_t)h, (uint16_t)strip_rows, c->work, ws))
        return fail(EXIT_INTERNAL, "renderer (%s) refused size %ux%u", c->api->numeric, w, h);
    return EXIT_OK;
}

static void core_close(struct core *c)
{
    if (c->scene) c->api->scene_free(c->scene);
    free(c->work);
}

/* Renders frame f of c into full-frame buffers (memory only, no panel):
 * the reference of --compare. */
static int core_render_memory(struct core *c, unsigned f, uint16_t *fb, uint8_t *rgb)
{
    struct render_stats st = { 0 };
    if (c->api->begin_frame(&c->ctx, (uint16_t)f))
        return fail(EXIT_INTERNAL, "renderer (%s) failed to begin frame %u", c->api->numeric, f);
    unsigned w = c->ctx.width, h = c->ctx.height, rows = c->ctx.strip_rows;
    for (unsigned y0 = 0; y0 < h; y0 += rows) {
        unsigned y1 = y0 + rows < h ? y0 + rows : h;
        struct render_target t = { .width = (uint16_t)w, .height = (uint16_t)h,
                                   .y0 = (uint16_t)y0, .y1 = (uint16_t)y1,
                                   .rgb565 = fb + (size_t)y0 * w, .rgb888 = rgb + (size_t)y0 * w * 3 };
        if (c->api->render_strip(&c->ctx, &t, &st))
            return fail(EXIT_INTERNAL, "renderer (%s) failed on rows %u..%u", c->api->numeric, y0, y1);
    }
    return EXIT_OK;
}

/* Everything allocated by run(), freed in one place. */
struct bufs {
    struct window *win;
    uint16_t *strip, *fb, *ref_fb, *shown, *glass;
    uint8_t *rgb, *ref_rgb;
    uint8_t *probe, *ref_probe;   /* --compare, ray tracer: primary decisions (w*h): shadow bits */
    int16_t *item, *ref_item;     /* and the item hit */
};

/* --loop ends after the frame in progress on SIGINT or SIGTERM (or the
 * window closing). */
static volatile sig_atomic_t loop_stop;

/* What --loop, --flush dirty, --fps-overlay and the progress line add to
 * sending a frame. */
struct live {
    struct window *win;        /* --window, or NULL */
    uint16_t *glass;           /* w*h: what the glass shows, for the window */
    uint16_t *shown;           /* --flush dirty: what the glass shows (w*h), else NULL */
    const char *overlay;       /* text drawn top-left into each frame, or NULL */
    int progress;              /* stderr is a terminal: a progress line in long frames */
    uint64_t frame_t0;         /* now_us() at the frame's start */
    int progress_shown;
    unsigned rects;            /* rectangles sent this frame (dirty) */
};

/* Sends rows [y0, y1) of strip, or with l->shown only the rectangles in it
 * that differ from what the glass shows: each run of changed rows as one
 * rectangle spanning their changed columns. */
static int flush_strip(struct panel_out *po, struct live *l, unsigned w, unsigned y0, unsigned y1,
                       const uint16_t *strip, char *err, size_t errlen)
{
    if (!l || !l->shown)
        return panel_out_flush(po, (uint16_t)y0, (uint16_t)y1, strip, err, errlen);
    unsigned n = y1 - y0, r = 0;
    size_t rowb = (size_t)w * sizeof *strip;
    while (r < n) {
        while (r < n && !memcmp(strip + (size_t)r * w, l->shown + (size_t)(y0 + r) * w, rowb)) r++;
        if (r == n) break;
        unsigned e = r, x0 = w, x1 = 0;
        for (; e < n; e++) {
            const uint16_t *a = strip + (size_t)e * w, *g = l->shown + (size_t)(y0 + e) * w;
            unsigned lo = 0, hi = w;
            while (lo < w && a[lo] == g[lo]) lo++;
            if (lo == w) break;
            while (hi > lo && a[hi - 1] == g[hi - 1]) hi--;
            if (lo < x0) x0 = lo;
            if (hi > x1) x1 = hi;
        }
        int rc = panel_out_flush_rect(po, (uint16_t)x0, (uint16_t)(y0 + r), (uint16_t)(x1 - x0),
                                      (uint16_t)(e - r), strip + (size_t)r * w + x0, w, err, errlen);
        if (rc) return rc;
        for (unsigned k = r; k < e; k++)
            memcpy(l->shown + (size_t)(y0 + k) * w + x0, strip + (size_t)k * w + x0,
                   (size_t)(x1 - x0) * sizeof *strip);
        l->rects++;
        r = e;
    }
    return 0;
}

/* FNV-1a (32-bit) of n RGB565 pixels continued from h, each pixel's low
 * byte first (--out-raw's byte order): the frame checksum of --stats, the
 * one the benchmark images print (tools/bench/bench.h). */
static uint32_t fnv1a_565(uint32_t h, const uint16_t *px, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        h = (h ^ (px[i] & 0xFFu)) * 16777619u;
        h = (h ^ (uint32_t)(px[i] >> 8)) * 16777619u;
    }
    return h;
}

/* Renders every strip of frame f into strip (and rgb, a full-frame buffer,
 * if not NULL) and sends each to the panel; adds the times spent to
 * *render_us and *flush_us; *sum (if not NULL) receives the checksum of the
 * frame's pixels as the renderer wrote them (before an --fps-overlay). */
static int send_strips(struct core *c, struct panel_out *po, uint16_t *strip, uint8_t *rgb, unsigned f,
                       struct render_stats *rs, uint64_t *render_us, uint64_t *flush_us, struct live *l,
                       uint32_t *sum)
{
    unsigned w = c->ctx.width, h = c->ctx.height, rows = c->ctx.strip_rows;
    char err[512];
    int rc;
    if (sum) *sum = 2166136261u;
    for (unsigned y0 = 0; y0 < h; y0 += rows) {
        unsigned y1 = y0 + rows < h ? y0 + rows : h;
        struct render_target t = { .width = (uint16_t)w, .height = (uint16_t)h,
                                   .y0 = (uint16_t)y0, .y1 = (uint16_t)y1, .rgb565 = strip,
                                   .rgb888 = rgb ? rgb + (size_t)y0 * w * 3 : NULL };
        uint64_t t0 = now_us();
        if (c->api->render_strip(&c->ctx, &t, rs))
            return fail(EXIT_INTERNAL, "renderer failed on rows %u..%u of frame %u", y0, y1, f);
        uint64_t t1 = now_us();
        *render_us += t1 - t0;
        if (sum) *sum = fnv1a_565(*sum, strip, (size_t)(y1 - y0) * w);
        if (l && l->overlay)
            font5x7_draw(strip, (int)w, (int)y0, (int)y1, 2, 2, 2, l->overlay, 0xffff, 0x0000);
        if ((rc = flush_strip(po, l, w, y0, y1, strip, err, sizeof err))) return fail(rc, "%s", err);
        if (l && l->win) {
            if ((rc = panel_out_read(po, l->glass, err, sizeof err))) return fail(rc, "%s", err);
            window_update(l->win, l->glass, y0, y1);
            if (window_closed(l->win)) loop_stop = 1;
        }
        uint64_t t2 = now_us();
        *flush_us += t2 - t1;
        if (l && l->progress && t2 - l->frame_t0 > 500000) {
            fprintf(stderr, "\rhost_sim: frame %u: rows %u/%u (%u%%), %.1f s", f, y1, h, y1 * 100u / h,
                    (double)(t2 - l->frame_t0) / 1e6);
            l->progress_shown = 1;
        }
    }
    if (l && l->progress_shown) {
        fputs("\r\033[K", stderr);
        l->progress_shown = 0;
    }
    return EXIT_OK;
}

static void on_loop_signal(int sig)
{
    (void)sig;
    loop_stop = 1;
}

static void loop_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_loop_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

/* --out with a frame number: one "%d" or "%0Nd" (N 1..9) and no other
 * '%' but "%%". 1 a pattern, 0 a plain name, -1 a bad one. */
static int out_pattern(const char *s)
{
    int conv = 0;
    for (; *s; s++) {
        if (*s != '%') continue;
        if (s[1] == '%') { s++; continue; }
        const char *q = s + 1;
        if (*q == '0' && q[1] >= '1' && q[1] <= '9') q += 2;
        if (*q != 'd' || conv++) return -1;
        s = q;
    }
    return conv;
}

/* The name of frame f of a pattern (checked by out_pattern). */
static void out_name(char *buf, size_t len, const char *pattern, unsigned f)
{
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
#endif
    snprintf(buf, len, pattern, (int)(f & 0x7fffffffu));
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
}

/* What run() works out once, shared by its steps. */
struct run_state {
    const struct opts *o;
    struct core *c, *ref;      /* the renderer; the --compare reference */
    struct panel_out **pp;
    struct bufs *b;
    const char *panel, *backend, *numeric;   /* the options or their defaults */
    int none;                  /* --panel none */
    int pattern;               /* --out names a file per frame */
    const char *outs[3];       /* --out (frame 0's with a pattern), --out-raw, --out-rgb888 */
    char frame_out[4096];      /* the file of the frame written (pattern) */
    char name[256];            /* the scene's name (scene_name) */
    unsigned w, h, rows;       /* render size, rows per strip */
    unsigned rotation;         /* quarter turns added to what the size picks (--rotation) */
    size_t npx;
    unsigned frames;           /* frames rendered (fewer if --loop is stopped) */
    unsigned anim;             /* the scene's animation's frames (at least 1) */
    struct live lv;
    char overlay[32];          /* --fps-overlay: the text drawn */
    uint64_t total_render_us;
    struct compare_result cmp; /* --compare, the last frame */
    long dec_off, dec_below;   /* --compare double, ray tracer: primary decisions that differ, and
                                  how many of them double takes too with its camera moved by the
                                  format's resolution (-1: not counted) */
};

/* What one frame measured. */
struct frame_meas {
    uint64_t render_us, flush_us;
    uint64_t coarse_us;        /* --progressive: the coarse pass */
    unsigned long coarse_rays;
    uint64_t spi0, bus0;       /* the panel's counters before the frame */
    uint32_t sat0;             /* the core's saturations before it */
    uint32_t shadow0;          /* the ray tracer's shadow rays before its full pass */
    uint32_t checksum;         /* FNV-1a of the frame's pixels (send_strips) */
    struct render_stats rs;
};

/* Usage checks that need no scene first, so a bad command fails at once;
 * then every output's destination. */
static int check_usage(struct run_state *r)
{
    const struct opts *o = r->o;
    char err[512];
    int rc;
    if (o->out && img_format_of(o->out) == IMG_NONE)
        return fail(EXIT_USAGE, "--out %s: the file name must end in .png or .ppm", o->out);
    r->pattern = o->out ? out_pattern(o->out) : 0;
    if (r->pattern < 0)
        return fail(EXIT_USAGE, "--out %s: a per-frame name takes one %%d or %%0Nd (N 1..9), no other %%", o->out);
    if (o->loop && (o->compare || o->frames))
        return fail(EXIT_USAGE, "--loop renders the scene's own frames: not with %s", o->compare ? "--compare" : "--frames");
    if (o->loop_frames && !o->loop)
        return fail(EXIT_USAGE, "--loop-frames needs --loop");
    if (o->window && !window_available())
        return fail(EXIT_USAGE, "--window: this build has no SDL2 (install libsdl2-dev and rebuild)");
    if (o->window_scale && !o->window)
        return fail(EXIT_USAGE, "--window-scale needs --window");
    if (o->out_rgb888 && img_format_of(o->out_rgb888) != IMG_PPM)
        return fail(EXIT_USAGE, "--out-rgb888 %s: the file name must end in .ppm", o->out_rgb888);
    if (o->miswire && r->none)
        return fail(EXIT_USAGE, "--miswire needs a panel's driver, not --panel none");
    if (o->fault && r->none)
        return fail(EXIT_USAGE, "--inject-fault needs an emulated panel, not --panel none");
    if (o->compare && !strcmp(r->backend, "linux"))
        return fail(EXIT_USAGE, "--compare needs --backend sim");
    if (strcmp(r->backend, "linux") && (o->spi_dev || o->gpio_chip || o->spi_hz || o->spi_mode >= 0 ||
                                        o->dc != PANEL_OUT_PIN_DEFAULT || o->rst != PANEL_OUT_PIN_DEFAULT ||
                                        o->bl != PANEL_OUT_PIN_DEFAULT))
        return fail(EXIT_USAGE, "--spi-dev, --spi-hz, --spi-mode, --gpio-chip, --dc, --rst and --bl "
                                "need --backend linux");
    if (r->pattern) out_name(r->frame_out, sizeof r->frame_out, o->out, 0);
    r->outs[0] = r->pattern ? r->frame_out : o->out;
    r->outs[1] = o->out_raw;
    r->outs[2] = o->out_rgb888;
    for (int i = 0; i < 3; i++)
        if (r->outs[i] && (rc = img_check_dest(r->outs[i], err, sizeof err)))
            return fail(rc, "%s", err);
    return EXIT_OK;
}

/* ---- the files a run reads, and output identity ------------------------------ */

/* The scene parser opens every file it reads (the scene, its textures, OBJ
 * and MTL files) with fopen, which the link wraps (mk/host_sim.mk:
 * -Wl,--wrap=fopen): each file opened for reading is kept by its device and
 * inode, so that no output is written onto one of them. */
FILE *__real_fopen(const char *path, const char *mode);
FILE *__wrap_fopen(const char *path, const char *mode);

struct read_file { dev_t dev; ino_t ino; };
static struct read_file *read_files;
static size_t nread_files, read_files_cap;

FILE *__wrap_fopen(const char *path, const char *mode)
{
    FILE *f = __real_fopen(path, mode);
    struct stat st;
    if (!f || mode[0] != 'r' || strchr(mode, '+') || fstat(fileno(f), &st)) return f;
    for (size_t i = 0; i < nread_files; i++)
        if (read_files[i].dev == st.st_dev && read_files[i].ino == st.st_ino) return f;
    if (nread_files == read_files_cap) {
        size_t cap = read_files_cap ? read_files_cap * 2 : 16;
        struct read_file *n = realloc(read_files, cap * sizeof *n);
        if (!n) return f;   /* (the scene's own file is the first, always kept) */
        read_files = n;
        read_files_cap = cap;
    }
    read_files[nread_files].dev = st.st_dev;
    read_files[nread_files].ino = st.st_ino;
    nread_files++;
    return f;
}

/* 1 if path is a regular file the run has read (the scene, a texture, an
 * OBJ or MTL file). */
static int is_read_file(const char *path)
{
    struct stat st;
    if (stat(path, &st) || !S_ISREG(st.st_mode)) return 0;
    for (size_t i = 0; i < nread_files; i++)
        if (read_files[i].dev == st.st_dev && read_files[i].ino == st.st_ino) return 1;
    return 0;
}

/* The scene file: there, not overwritten by an output, read, and parsed by
 * r->c (the double core for fixed point: core_pick picks the format). */
static int open_scene(struct run_state *r)
{
    const struct opts *o = r->o;
    char err[512];
    int rc;
    struct stat st;
    if (stat(o->scene, &st))
        return fail(EXIT_USAGE, "%s: cannot open scene: %s", o->scene, strerror(errno));
    if (S_ISDIR(st.st_mode))
        return fail(EXIT_USAGE, "%s: cannot open scene: is a directory", o->scene);
    /* an output must not overwrite the scene, nor two outputs each other */
    for (int i = 0; i < 3; i++) {
        struct stat so;
        if (!r->outs[i]) continue;
        if (!stat(r->outs[i], &so) && so.st_dev == st.st_dev && so.st_ino == st.st_ino && S_ISREG(st.st_mode))
            return fail(EXIT_USAGE, "%s: is the scene file; refusing to overwrite it", r->outs[i]);
        for (int j = 0; j < i; j++)
            if (r->outs[j] && file_same(r->outs[i], r->outs[j]))
                return fail(EXIT_USAGE, "%s: given as two outputs", r->outs[i]);
    }
    if ((rc = core_api_double.scene_read(o->scene, &scene_text, &scene_len, err, sizeof err))) {
        fprintf(stderr, "%s\n", err);
        return rc == CORE_SCENE_ENOMEM ? EXIT_INTERNAL : EXIT_USAGE;
    }
    /* The scene's canvas (for --panel none) from the double parse, which holds
     * any scene the format analysis may accept. */
    if ((rc = core_open(r->c, !strcmp(r->numeric, "fixed") ? &core_api_double : core_api_by_name(r->numeric),
                        o->scene)))
        return rc;
    /* nor a file the scene reads (its textures, OBJ and MTL files) */
    for (int i = 0; i < 3; i++)
        if (r->outs[i] && is_read_file(r->outs[i]))
            return fail(EXIT_USAGE, "%s: is a file the scene reads; refusing to overwrite it", r->outs[i]);
    return EXIT_OK;
}

/* The render size (--size, the panel's or the scene's canvas), the strip
 * height, and for fixed point the core of the scene's format. */
static int pick_core(struct run_state *r)
{
    const struct opts *o = r->o;
    struct core *c = r->c;
    int rc;
    unsigned w = o->width, h = o->height;
    if (!o->has_size) {
        uint16_t nw, nh;
        if (r->none) {
            nw = c->info.canvas_w;
            nh = c->info.canvas_h;
        } else if (panel_out_native(r->panel, &nw, &nh)) {
            return fail(EXIT_USAGE, "unknown panel '%s'", r->panel);
        }
        w = nw;
        h = nh;
        /* a panel that is not square mounted a quarter turn: its native
           size turned, which the module then shows turned (the first odd
           turn is that one, the other a half turn more) */
        if (!r->none && (o->rotation & 1) && w != h) {
            w = nh;
            h = nw;
            r->rotation = o->rotation - 1;
        }
        if (!w || !h || w > MAX_SIDE || h > MAX_SIDE)
            return fail(EXIT_USAGE, "%s: canvas size %ux%u is not renderable (1..%d a side)",
                        o->scene, w, h, MAX_SIDE);
    }
    r->w = w;
    r->h = h;
    r->npx = (size_t)w * h;
    r->rows = o->strip_rows ? o->strip_rows : STRIP_ROWS_DEFAULT;
    if (r->rows > h) r->rows = h;
    if (!strcmp(r->numeric, "float") && (rc = float_check(o, w, h))) return rc;
    if (!strcmp(r->numeric, "fixed")) {
        const struct core_api *api;
        unsigned fits;
        if ((rc = core_pick(o, r->numeric, w, h, &api, &fits))) return rc;
        core_close(c);
        memset(c, 0, sizeof *c);
        if ((rc = core_open(c, api, o->scene))) return rc;
        c->api->set_fits(c->scene, fits);
    }
    return EXIT_OK;
}

/* An accuracy target (--min-psnr, --target, the scene's quality block): the
 * methods chosen (tools/quality), written into the scene's text, which every
 * core then parses; the report on stderr. */
static int choose_methods(struct run_state *r)
{
    const struct opts *o = r->o;
    const struct scene_info *in = &r->c->info;
    double psnr = o->quality.min_psnr ? o->quality.min_psnr : in->quality_psnr;
    if (!psnr) {
        if (o->quality.target) return fail(EXIT_USAGE, "--target needs --min-psnr (or a quality block in the scene)");
        return EXIT_OK;
    }
    int target = o->quality.target ? o->quality.target : in->quality_target ? in->quality_target : QUALITY_M0PLUS;
    struct quality_request rq = { .path = o->scene, .text = scene_text, .len = scene_len, .width = r->w,
                                  .height = r->h, .strip_rows = r->rows, .numeric = r->numeric, .target = target,
                                  .min_psnr = psnr, .report = stderr,
                                  .line = o->quality.min_psnr ? 0 : in->quality_line,
                                  .col = o->quality.min_psnr ? 0 : in->quality_col };
    struct quality_choice ch;
    char err[768];
    int rc = quality_choose(&rq, &ch, err, sizeof err);
    if (rc) {
        quality_free(&ch);
        fprintf(stderr, "%s\n", err);
        return rc == QUALITY_EINPUT ? EXIT_USAGE : EXIT_INTERNAL;
    }
    free(scene_text);
    scene_text = ch.text;
    scene_len = ch.len;
    core_close(r->c);
    memset(r->c, 0, sizeof *r->c);
    if ((rc = core_open(r->c, !strcmp(r->numeric, "fixed") ? &core_api_double : core_api_by_name(r->numeric),
                        o->scene)))
        return rc;
    return pick_core(r);
}

/* The ray tracer's work a frame, estimated before rendering (an upper
 * bound, docs/host_sim.md): rays (pixels x supersample^2, each followed
 * through recursion_depth reflections, each hit with a shadow ray per light)
 * times the objects each ray is tested against (with bvh, 2 log2 of them).
 * Over --max-cost it is refused (exit 2). */
#define MAX_COST_DEFAULT 20e9
static int check_raster_cost(const struct run_state *r, double max);
static int check_cost(const struct run_state *r)
{
    const struct scene_info *in = &r->c->info;
    double max = r->o->max_cost > 0 ? r->o->max_cost : MAX_COST_DEFAULT;
    if (in->kind != SCENE_RAYTRACE) return check_raster_cost(r, max);
    double ss = in->supersample ? in->supersample : 1;
    double rays = (double)r->w * r->h * ss * ss * (in->recursion_depth + 1.0) * (in->nlights + 1.0);
    double objs = in->bvh ? 2.0 * ceil(log2(in->nobjects + 1.0)) + 1.0 : in->nobjects;
    double cost = rays * (objs > 1 ? objs : 1);
    if (cost <= max) return EXIT_OK;
    return fail(EXIT_USAGE, "%s: about %.3g ray-object tests a frame (%ux%u pixels, %.0f rays a pixel, %u levels, "
                            "%u lights, %u objects), over the limit of %.3g (--max-cost to raise it)",
                r->o->scene, cost, r->w, r->h, ss * ss, (unsigned)in->recursion_depth + 1, (unsigned)in->nlights,
                (unsigned)in->nobjects, max);
}

/* The rasterizer's work a frame, estimated before rendering (an upper
 * bound, docs/host_sim.md): every triangle of every instance visited by
 * every strip (the binning finds a triangle only in the strips it covers,
 * but one may cover them all), twice with shadow volumes, plus the pixels
 * (each written at least once) and the shadow map's texels. Over --max-cost
 * it is refused (exit 2). */
static int check_raster_cost(const struct run_state *r, double max)
{
    const struct scene_info *in = &r->c->info;
    double strips = ceil((double)r->h / (r->rows ? r->rows : 1));
    double prims = (double)in->triangles * (in->shadow_volumes ? 2.0 : 1.0) + in->nprims + in->nlines;
    double pixels = (double)r->w * r->h + (double)in->shadow_map * in->shadow_map;
    double cost = prims * strips + pixels;
    if (cost <= max) return EXIT_OK;
    return fail(EXIT_USAGE, "%s: about %.3g triangle-strip visits and pixels a frame (%.0f triangles, lines and 2-D "
                            "primitives x %.0f strips of %u rows at %ux%u), over the limit of %.3g (--max-cost to "
                            "raise it)", r->o->scene, cost, prims, strips, r->rows, r->w, r->h, max);
}

/* The panel and the renderer at the render size; warnings about the scene
 * and the command, once every check has passed. */
static int open_panel(struct run_state *r)
{
    const struct opts *o = r->o;
    const struct core *c = r->c;
    char err[512];
    int rc;
    struct panel_out_opts po = { .panel = r->panel, .backend = r->backend, .fault = o->fault, .miswire = o->miswire,
                                 .width = (uint16_t)r->w, .height = (uint16_t)r->h,
                                 .rotation = (uint8_t)r->rotation, .spi_dev = o->spi_dev,
                                 .gpio_chip = o->gpio_chip, .spi_hz = o->spi_hz, .spi_mode = o->spi_mode,
                                 .dc = o->dc, .rst = o->rst, .bl = o->bl };
    if ((rc = check_cost(r))) return rc;
    if ((rc = panel_out_open(r->pp, &po, err, sizeof err))) return fail(rc, "%s", err);
    if ((rc = core_init(r->c, r->w, r->h, r->rows))) return rc;
    /* valid, but almost certainly not what was meant: said (once every check
     * has passed, so an error stays the only line), not refused */
    if (c->info.uses_lights && c->info.nlights == 0 && (c->info.kind == SCENE_RAYTRACE || c->info.ninstances))
        fprintf(stderr, "host_sim: warning: %s: no lights: every lit surface renders black%s\n", o->scene,
                c->info.kind == SCENE_RAYTRACE ? " (add a light, or raytracer { lighting = off } for unlit colours)" : " (add a light, or rasterizer { shading = none })");
    if (!c->info.uses_lights && c->info.nlights && c->info.kind != SCENE_RAYTRACE)
        fprintf(stderr, "host_sim: warning: %s: %u lights, but no shading mode uses them (rasterizer { shading = none })\n",
                o->scene, (unsigned)c->info.nlights);
    if (!o->out && !o->out_raw && !o->out_rgb888 && !o->stats && !o->summary && !o->compare && !o->loop)
        fprintf(stderr, "host_sim: warning: no output given (--out, --out-raw, --out-rgb888, --stats, --summary): "
                        "the frame is rendered and discarded\n");
    return EXIT_OK;
}

/* The frame buffers, the frame count (--loop: its signals) and what --window,
 * --fps-overlay, --flush dirty and the progress line add to a frame. */
static int setup_frames(struct run_state *r)
{
    const struct opts *o = r->o;
    struct bufs *b = r->b;
    char err[512];
    int rc;
    size_t npx = r->npx;
    int want_rgb = o->out_rgb888 || o->compare;
    b->strip = malloc((size_t)r->rows * r->w * sizeof *b->strip);
    b->fb = malloc(npx * sizeof *b->fb);
    b->rgb = want_rgb ? malloc(npx * 3) : NULL;
    if (!b->strip || !b->fb || (want_rgb && !b->rgb))
        return fail(EXIT_INTERNAL, "out of memory for a %ux%u image", r->w, r->h);
    memset(b->fb, 0, npx * sizeof *b->fb);
    if (want_rgb) memset(b->rgb, 0, npx * 3);
    r->dec_off = r->dec_below = -1;
    if (o->compare && !strcmp(o->compare, "double") && r->c->info.kind == SCENE_RAYTRACE) {
        /* 0xFF: not traced (what is left so stays out of the count) */
        if (!(b->probe = malloc(npx)) || !(b->item = malloc(npx * sizeof *b->item)))
            return fail(EXIT_INTERNAL, "out of memory for a %ux%u image", r->w, r->h);
        memset(b->probe, 0xFF, npx);
        r->c->api->decision_probe(&r->c->ctx, b->probe, b->item);
    }

    scene_name(o->scene, r->name, sizeof r->name);
    r->frames = o->frames ? o->frames : 1;
    /* --loop: the scene's animation over and over (frame index f mod its
     * frames), until --loop-frames or a signal */
    r->anim = r->c->info.frames ? r->c->info.frames : 1;
    if (o->loop) {
        r->frames = o->loop_frames ? o->loop_frames : UINT32_MAX;
        loop_stop = 0;
        loop_signals();
    }
    if (o->window) {
        char title[300];
        snprintf(title, sizeof title, "host_sim %s", r->name);
        if (!(b->glass = malloc(npx * sizeof *b->glass)))
            return fail(EXIT_INTERNAL, "out of memory for a %ux%u image", r->w, r->h);
        if ((rc = window_open(&b->win, title, r->w, r->h, o->window_scale ? o->window_scale : 2, err, sizeof err)))
            return fail(rc, "%s", err);
        r->lv.win = b->win;
        r->lv.glass = b->glass;
    }
    r->lv.progress = isatty(STDERR_FILENO);
    if (o->fps_overlay) r->lv.overlay = r->overlay;
    if (o->flush == 2 || (o->loop && o->flush == 0)) {
        /* panel_init cleared the controller's memory to black */
        if (!(b->shown = calloc(npx, sizeof *b->shown)))
            return fail(EXIT_INTERNAL, "out of memory for a %ux%u image", r->w, r->h);
        r->lv.shown = b->shown;
    }
    return EXIT_OK;
}

/* Renders frame fi of the scene to the panel: with --progressive the
 * coarse pass first, then the full one. */
static int render_frame(struct run_state *r, unsigned fi, struct frame_meas *m)
{
    struct core *c = r->c;
    int rc;
    r->lv.frame_t0 = now_us();
    r->lv.rects = 0;
    m->sat0 = *c->api->saturations;
    m->spi0 = panel_out_spi_bytes(*r->pp);
    m->bus0 = panel_out_bus_us(*r->pp);
    uint64_t t0 = now_us();
    if (c->api->begin_frame(&c->ctx, (uint16_t)fi))
        return fail(EXIT_INTERNAL, "renderer failed to begin frame %u", fi);
    m->render_us += now_us() - t0;
    if (r->o->progressive && c->api->set_pass(&c->ctx, RENDER_PASS_COARSE) == 0) {
        struct render_stats cs = { 0 };
        uint64_t coarse_flush_us = 0;
        if ((rc = send_strips(c, *r->pp, r->b->strip, NULL, fi, &cs, &m->coarse_us, &coarse_flush_us, &r->lv,
                              NULL)))
            return rc;
        m->coarse_rays = cs.rays;
        m->render_us += m->coarse_us;
        c->api->set_pass(&c->ctx, RENDER_PASS_FULL);
    }
    m->shadow0 = c->api->shadow_rays(&c->ctx);
    return send_strips(c, *r->pp, r->b->strip, r->b->rgb, fi, &m->rs, &m->render_us, &m->flush_us, &r->lv,
                       &m->checksum);
}

/* --stats: frame f's JSON object; after the last frame, with --compare,
 * left open for the comparison's fields. */
static void print_frame_stats(const struct run_state *r, unsigned f, const struct frame_meas *m)
{
    const struct core *c = r->c;
    struct panel_out *po = *r->pp;
    printf("{\"scene\":");
    json_str(r->name);
    printf(",\"file\":");
    json_str(r->o->scene);
    printf(",\"numeric\":\"%s\",", c->api->numeric);
    if (c->api->num_frac) printf("\"num_frac\":%d,", c->api->num_frac);
    else printf("\"num_frac\":null,");
    printf("\"panel\":\"%s\",\"backend\":\"%s\",\"width\":%u,"
           "\"height\":%u,\"frame\":%u,\"strip_rows\":%u,\"render_us\":%llu,"
           "\"flush_us\":%llu,\"bus_us\":%llu,\"pixels_written\":%lu,\"spi_bytes\":%llu,"
           "\"triangles_in\":%lu,\"triangles_drawn\":%lu,\"rays\":%lu,\"saturations\":%lu",
           r->panel, r->backend, r->w, r->h, f, r->rows, (unsigned long long)m->render_us,
           (unsigned long long)m->flush_us, (unsigned long long)(panel_out_bus_us(po) - m->bus0),
           (unsigned long)m->rs.pixels_written,
           (unsigned long long)(panel_out_spi_bytes(po) - m->spi0),
           (unsigned long)m->rs.triangles_in, (unsigned long)m->rs.triangles_drawn,
           (unsigned long)m->rs.rays, (unsigned long)(uint32_t)(*c->api->saturations - m->sat0));
    printf(",\"shadow_rays\":%lu", (unsigned long)(uint32_t)(c->api->shadow_rays(&c->ctx) - m->shadow0));
    printf(",\"checksum\":%lu", (unsigned long)m->checksum);
    if (r->o->progressive)
        printf(",\"coarse_us\":%llu,\"coarse_rays\":%lu", (unsigned long long)m->coarse_us, m->coarse_rays);
    if (!(r->o->compare && f + 1 == r->frames)) printf("}\n");
}

/* After frame f (the scene's fi): the overlay's next text, the frame's file
 * (--out PATTERN) and its --loop line. */
static int frame_done(struct run_state *r, unsigned f, unsigned fi, const struct frame_meas *m)
{
    const struct opts *o = r->o;
    char err[512];
    int rc;
    uint64_t frame_us = now_us() - r->lv.frame_t0;
    double fps = frame_us ? 1e6 / (double)frame_us : 0.0;
    if (o->fps_overlay) snprintf(r->overlay, sizeof r->overlay, "%.1f fps", fps);
    if (r->pattern) {
        /* this frame's glass, as --out does after the last one */
        out_name(r->frame_out, sizeof r->frame_out, o->out, f);
        if (is_read_file(r->frame_out))
            return fail(EXIT_USAGE, "%s: is a file the scene reads; refusing to overwrite it", r->frame_out);
        for (int i = 1; i < 3; i++)
            if (r->outs[i] && file_same(r->frame_out, r->outs[i]))
                return fail(EXIT_USAGE, "%s: given as two outputs", r->frame_out);
        if ((rc = panel_out_read(*r->pp, r->b->fb, err, sizeof err))) return fail(rc, "%s", err);
        if ((rc = img_write_565(r->frame_out, img_format_of(r->frame_out), r->b->fb, r->w, r->h, r->w,
                                err, sizeof err)))
            return fail(rc, "%s", err);
        if (o->loop) loop_signals();   /* (imgio's own handlers while it writes) */
    }
    if (o->loop) {
        printf("frame %u (%u/%u): host %.1f fps, %.2f ms, %llu SPI bytes, %u rects\n", f, fi + 1, r->anim, fps,
               (double)frame_us / 1000.0, (unsigned long long)(panel_out_spi_bytes(*r->pp) - m->spi0),
               r->lv.rects);
        if (fflush(stdout)) return fail(EXIT_INTERNAL, "stdout: write failed");
    }
    return EXIT_OK;
}

/* After the first frame of a rasterized scene: a warning for the instances
 * in view whose every triangle faced away and was culled (a model wound the
 * other way draws nothing, silently otherwise). */
static void warn_culled(const struct run_state *r)
{
    const struct core *c = r->c;
    unsigned all_culled = 0, first = 0;
    uint32_t first_n = 0;
    const char *first_model = "";
    for (unsigned i = 0; i < c->info.ninstances; i++) {
        uint32_t facing, culled;
        const char *model = "";
        if (c->api->instance_facing(&c->ctx, (uint16_t)i, &facing, &culled, &model) || facing || !culled) continue;
        if (!all_culled++) {
            first = i;
            first_n = culled;
            first_model = model;
        }
    }
    if (!all_culled) return;
    fprintf(stderr, "host_sim: warning: %s: instance %u (model '%s'): all %lu of its triangles face away and are "
                    "culled", r->o->scene, first, first_model, (unsigned long)first_n);
    if (all_culled > 1) fprintf(stderr, " (and %u more instances)", all_culled - 1);
    fputs("; front faces run clockwise as the camera sees them: list each triangle's corners the other way round, "
          "or rasterizer { cull = off }\n", stderr);
}

/* Every frame; with --loop, until a signal (the frame in progress ends). */
static int run_frames(struct run_state *r)
{
    const struct opts *o = r->o;
    int rc;
    for (unsigned f = 0; f < r->frames; f++) {
        const unsigned fi = o->loop ? f % r->anim : f;
        struct frame_meas m = { 0 };
        if ((rc = render_frame(r, fi, &m))) return rc;
        if (f == 0 && r->c->info.kind == SCENE_RASTER) warn_culled(r);
        r->total_render_us += m.render_us;
        if (o->stats) print_frame_stats(r, f, &m);
        if ((rc = frame_done(r, f, fi, &m))) return rc;
        if (o->loop && loop_stop) {
            r->frames = f + 1;
            break;
        }
    }
    return EXIT_OK;
}

/* The panel's last bytes; without --loop the window shows the last frame
 * until it is closed. */
static int finish_panel(struct run_state *r)
{
    char err[512];
    int rc;
    if ((rc = panel_out_finish(*r->pp, err, sizeof err))) return fail(rc, "%s", err);
    if (r->b->win && !r->o->loop) {
        /* the last frame stays on view until the window is closed */
        struct timespec ts = { 0, 20000000L };
        loop_stop = 0;
        loop_signals();
        while (!loop_stop && !window_closed(r->b->win)) nanosleep(&ts, NULL);
    }
    return EXIT_OK;
}

/* --compare double on a ray-traced scene: the primary decisions (which
 * item is hit, which lights are shadowed; pixels the render traced one by
 * one) that differ
 * from double's, and how many of those double itself takes when its camera
 * moves by the renderer's resolution (fixed point: 2^-NUM_FRAC; float:
 * 2^-21, 24 bits at coordinates up to 8) along x, y or z either way: those
 * are decided below what the format can tell apart. Six more double renders
 * when any differs. */
/* Pixel i traced one by one in both renders, with another decision. */
static int decision_off(const struct bufs *b, size_t i)
{
    return b->probe[i] != 0xFF && b->ref_probe[i] != 0xFF &&
           (b->probe[i] != b->ref_probe[i] || b->item[i] != b->ref_item[i]);
}

/* The reference render with the camera moved by (dx, dy, dz): its
 * decisions into pm and im (fb and rgb: its frame). */
static int moved_decisions(struct run_state *r, double dx, double dy, double dz, uint8_t *pm, int16_t *im,
                           uint16_t *fb, uint8_t *rgb)
{
    struct core m = { 0 };
    int rc = core_open(&m, r->ref->api, r->o->scene);
    if (!rc) {
        m.api->set_fits(m.scene, 0);
        m.api->exact_methods(m.scene);
        m.api->move_camera(m.scene, dx, dy, dz);
        rc = core_init(&m, r->w, r->h, r->rows);
    }
    if (!rc) {
        memset(pm, 0xFF, r->npx);
        m.api->decision_probe(&m.ctx, pm, im);
        for (unsigned f = 0; f < r->frames && !rc; f++) rc = core_render_memory(&m, f, fb, rgb);
    }
    core_close(&m);
    return rc;
}

static int count_decisions(struct run_state *r)
{
    struct bufs *b = r->b;
    size_t n = r->npx;
    long off = 0, traced = 0;
    for (size_t i = 0; i < n; i++) {
        traced += b->probe[i] != 0xFF && b->ref_probe[i] != 0xFF;
        off += decision_off(b, i);
    }
    if (traced == 0) return EXIT_OK;   /* nothing traced pixel by pixel (adaptive subsampling) */
    r->dec_off = off;
    r->dec_below = 0;
    double res = r->c->api->num_frac ? ldexp(1.0, -r->c->api->num_frac)
                                     : strcmp(r->c->api->numeric, "float") ? 0 : ldexp(1.0, -21);
    if (!off || res <= 0) return EXIT_OK;
    uint8_t *ok = calloc(n, 1), *pm = malloc(n), *rgb = malloc(n * 3);
    int16_t *im = malloc(n * sizeof *im);
    uint16_t *fb = malloc(n * sizeof *fb);
    int rc = ok && pm && rgb && im && fb ? EXIT_OK : fail(EXIT_INTERNAL, "out of memory");
    for (int k = 0; k < 6 && !rc; k++) {
        double v = (k & 1) ? -res : res;
        rc = moved_decisions(r, k / 2 == 0 ? v : 0, k / 2 == 1 ? v : 0, k / 2 == 2 ? v : 0, pm, im, fb, rgb);
        for (size_t i = 0; i < n && !rc; i++) ok[i] |= decision_off(b, i) && pm[i] == b->probe[i] && im[i] == b->item[i];
    }
    for (size_t i = 0; i < n && !rc; i++) r->dec_below += ok[i];
    free(ok);
    free(pm);
    free(im);
    free(fb);
    free(rgb);
    return rc;
}

/* --compare: the same frames with the reference core in memory, its colours
 * against the renderer's after the last frame (r->cmp; --stats: the fields
 * that close the last frame's object). */
static int compare_ref(struct run_state *r)
{
    const struct opts *o = r->o;
    struct core *ref = r->ref;
    struct bufs *b = r->b;
    const struct core_api *rapi;
    unsigned rfits;
    int rc;
    if ((rc = core_pick(o, o->compare, r->w, r->h, &rapi, &rfits))) return rc;
    if ((rc = core_open(ref, rapi, o->scene))) return rc;
    ref->api->set_fits(ref->scene, rfits);
    ref->api->exact_methods(ref->scene);   /* every method is measured against the exact one */
    if ((rc = core_init(ref, r->w, r->h, r->rows))) return rc;
    b->ref_fb = malloc(r->npx * sizeof *b->ref_fb);
    b->ref_rgb = malloc(r->npx * 3);
    if (!b->ref_fb || !b->ref_rgb) return fail(EXIT_INTERNAL, "out of memory");
    memset(b->ref_rgb, 0, r->npx * 3);
    if (b->probe) {
        if (!(b->ref_probe = malloc(r->npx)) || !(b->ref_item = malloc(r->npx * sizeof *b->ref_item)))
            return fail(EXIT_INTERNAL, "out of memory");
        memset(b->ref_probe, 0xFF, r->npx);
        ref->api->decision_probe(&ref->ctx, b->ref_probe, b->ref_item);
    }
    for (unsigned f = 0; f < r->frames; f++)  /* animation state may carry over */
        if ((rc = core_render_memory(ref, f, b->ref_fb, b->ref_rgb))) return rc;
    compare_rgb888(b->rgb, b->ref_rgb, r->w, r->h, &r->cmp);
    if (b->probe && (rc = count_decisions(r))) return rc;
    if (o->stats) {
        const struct compare_result *cmp = &r->cmp;
        printf(",\"compare\":\"%s\",", o->compare);
        if (isinf(cmp->psnr)) printf("\"psnr\":null"); else printf("\"psnr\":%.2f", cmp->psnr);
        printf(",\"ssim\":%.5f,\"max_err\":%d,\"pct_diff\":%.3f,\"pct_within2\":%.3f",
               cmp->ssim, cmp->max_err, cmp->pct_diff, cmp->pct_within2);
        if (r->dec_off >= 0) printf(",\"decisions_off\":%ld,\"decisions_below_resolution\":%ld", r->dec_off,
                                    r->dec_below);
        printf("}\n");
    }
    return EXIT_OK;
}

/* What the glass shows (or the framebuffer) after the last frame, and the
 * renderer's colours (staged: main renames them into place only when the
 * whole run succeeds). */
static int write_outputs(const struct run_state *r)
{
    const struct opts *o = r->o;
    struct bufs *b = r->b;
    char err[512];
    int rc;
    unsigned w = r->w, h = r->h;
    if ((o->out && !r->pattern) || o->out_raw) {
        if ((rc = panel_out_read(*r->pp, b->fb, err, sizeof err))) return fail(rc, "%s", err);
        if (o->out && !r->pattern &&
            (rc = img_write_565(o->out, img_format_of(o->out), b->fb, w, h, w, err, sizeof err)))
            return fail(rc, "%s", err);
        if (o->out_raw && (rc = img_write_raw565(o->out_raw, b->fb, w, h, w, err, sizeof err)))
            return fail(rc, "%s", err);
    }
    if (o->out_rgb888 && (rc = img_write_ppm888(o->out_rgb888, b->rgb, w, h, err, sizeof err)))
        return fail(rc, "%s", err);
    return EXIT_OK;
}

/* --summary: one line, scene, size, numeric, time a frame, accuracy. */
static void print_summary(const struct run_state *r)
{
    const struct opts *o = r->o;
    const struct core *c = r->c;
    const struct compare_result *cmp = &r->cmp;
    char fmt[16] = "-";
    if (c->api->num_frac) snprintf(fmt, sizeof fmt, "Q%d.%d", 31 - c->api->num_frac, c->api->num_frac);
    printf("%-28s %4ux%-4u %-6s %-6s %-7s %9.1f ms", r->name, r->w, r->h, c->api->numeric, fmt, r->panel,
           (double)r->total_render_us / 1000.0 / r->frames);
    if (o->compare) {
        if (isinf(cmp->psnr)) printf("  exact vs %s", o->compare);
        else printf("  PSNR %.1f dB, SSIM %.4f, max err %d, %.2f%% within 2 vs %s", cmp->psnr,
                    cmp->ssim, cmp->max_err, cmp->pct_within2, o->compare);
        if (r->dec_off > 0)
            printf("; %ld primary decision%s off, %ld below resolution", r->dec_off, r->dec_off == 1 ? "" : "s",
                   r->dec_below);
    }
    putchar('\n');
}

/* --pattern check: the bring-up pattern (firmware/app/check_pattern.h) at
 * the panel's size in its rotation, streamed strip by strip to the panel as
 * the cgfs-check images do, with the driver's settings printed on it; then
 * --out and --out-raw, what the glass shows. What main() frees is in *pp
 * and *b. */
static int run_pattern(const struct opts *o, struct panel_out **pp, struct bufs *b)
{
    const char *panel = o->panel ? o->panel : panel_out_default();
    const char *backend = o->backend ? o->backend : "sim";
    char err[512];
    int rc;
    uint16_t w, h;
    unsigned rotation = o->rotation;
    if (!strcmp(panel, "none")) return fail(EXIT_USAGE, "--pattern check needs a panel, not --panel none");
    if (panel_out_native(panel, &w, &h)) return fail(EXIT_USAGE, "unknown panel '%s'", panel);
    if ((rotation & 1) && w != h) {   /* as for a scene: the native size turned (pick_core) */
        uint16_t t = w;
        w = h;
        h = t;
        rotation--;
    }
    if (strcmp(backend, "linux") && (o->spi_dev || o->gpio_chip || o->spi_hz || o->spi_mode >= 0 ||
                                     o->dc != PANEL_OUT_PIN_DEFAULT || o->rst != PANEL_OUT_PIN_DEFAULT ||
                                     o->bl != PANEL_OUT_PIN_DEFAULT))
        return fail(EXIT_USAGE, "--spi-dev, --spi-hz, --spi-mode, --gpio-chip, --dc, --rst and --bl "
                                "need --backend linux");
    const char *outs[2] = { o->out, o->out_raw };
    if (o->out && img_format_of(o->out) == IMG_NONE)
        return fail(EXIT_USAGE, "--out %s: the file name must end in .png or .ppm", o->out);
    if (o->out && out_pattern(o->out))
        return fail(EXIT_USAGE, "--out %s: --pattern check draws one picture (no %%d in the name)", o->out);
    for (int i = 0; i < 2; i++)
        if (outs[i] && (rc = img_check_dest(outs[i], err, sizeof err))) return fail(rc, "%s", err);
    if (outs[0] && outs[1] && file_same(outs[0], outs[1])) return fail(EXIT_USAGE, "%s: given as two outputs", outs[1]);

    struct panel_out_opts po = { .panel = panel, .backend = backend, .miswire = o->miswire, .width = w,
                                 .height = h, .rotation = (uint8_t)rotation, .spi_dev = o->spi_dev,
                                 .gpio_chip = o->gpio_chip, .spi_hz = o->spi_hz, .spi_mode = o->spi_mode,
                                 .dc = o->dc, .rst = o->rst, .bl = o->bl };
    if ((rc = panel_out_open(pp, &po, err, sizeof err))) return fail(rc, "%s", err);
    if (!o->out && !o->out_raw && strcmp(backend, "linux"))
        fprintf(stderr, "host_sim: warning: no output given (--out, --out-raw): the pattern is drawn and discarded\n");
    const struct panel *pn = panel_out_panel(*pp);
    /* the driver's settings, as the firmware prints them */
    struct check_settings cs = { .panel = pn->desc->name, .width = w, .height = h, .rotation = pn->rotation,
                                 .x_off = pn->desc->x_off[pn->rotation], .y_off = pn->desc->y_off[pn->rotation],
                                 .bgr = (uint8_t)panel_bgr(pn), .invert = pn->desc->invert,
                                 .spi_hz = o->has_clocks ? o->board_spi_hz : panel_out_spi_hz(*pp),
                                 .sys_hz = o->has_clocks ? o->board_sys_hz : 0,
                                 .round = (uint8_t)panel_out_round(*pp) };
    struct check_layout lay;
    check_setup(&lay, &cs);
    unsigned rows = o->strip_rows ? o->strip_rows : STRIP_ROWS_DEFAULT;
    if (rows > h) rows = h;
    size_t npx = (size_t)w * h;
    b->strip = malloc((size_t)rows * w * sizeof *b->strip);
    b->fb = malloc(npx * sizeof *b->fb);
    if (!b->strip || !b->fb) return fail(EXIT_INTERNAL, "out of memory for a %ux%u image", w, h);
    for (unsigned y0 = 0; y0 < h; y0 += rows) {
        unsigned y1 = y0 + rows < h ? y0 + rows : h;
        check_rows(&lay, b->strip, (uint16_t)y0, (uint16_t)y1);
        if ((rc = panel_out_flush(*pp, (uint16_t)y0, (uint16_t)y1, b->strip, err, sizeof err))) return fail(rc, "%s", err);
    }
    if ((rc = panel_out_finish(*pp, err, sizeof err))) return fail(rc, "%s", err);
    if (o->out || o->out_raw) {
        if ((rc = panel_out_read(*pp, b->fb, err, sizeof err))) return fail(rc, "%s", err);
        if (o->out && (rc = img_write_565(o->out, img_format_of(o->out), b->fb, w, h, w, err, sizeof err)))
            return fail(rc, "%s", err);
        if (o->out_raw && (rc = img_write_raw565(o->out_raw, b->fb, w, h, w, err, sizeof err)))
            return fail(rc, "%s", err);
    }
    return EXIT_OK;
}

/* One host_sim run: what main() frees is in *c, *ref, *pp and *b. */
static int run(const struct opts *o, struct core *c, struct core *ref, struct panel_out **pp,
               struct bufs *b)
{
    struct run_state r = { .o = o, .c = c, .ref = ref, .pp = pp, .b = b };
    int rc;
    r.panel = o->panel ? o->panel : panel_out_default();
    r.backend = o->backend ? o->backend : "sim";
    r.numeric = o->numeric ? o->numeric : "fixed";
    r.none = !strcmp(r.panel, "none");
    r.rotation = o->rotation;
    if ((rc = check_usage(&r)) || (rc = open_scene(&r)) || (rc = pick_core(&r)) || (rc = choose_methods(&r)) ||
        (rc = open_panel(&r)) ||
        (rc = setup_frames(&r)) || (rc = run_frames(&r)) || (rc = finish_panel(&r)))
        return rc;
    if (o->compare && (rc = compare_ref(&r))) return rc;
    fflush(stdout);
    if ((rc = write_outputs(&r))) return rc;
    if (o->summary) print_summary(&r);
    return fflush(stdout) ? EXIT_INTERNAL : EXIT_OK;
}

int main(int argc, char **argv)
{
    struct opts o = { .spi_mode = -1, .dc = PANEL_OUT_PIN_DEFAULT, .rst = PANEL_OUT_PIN_DEFAULT,
                      .bl = PANEL_OUT_PIN_DEFAULT };
    int rc = parse_args(argc, argv, &o);
    if (rc) return rc;
    if (o.max_memory) max_memory = o.max_memory;
    struct core c = { 0 }, ref = { 0 };
    struct panel_out *p = NULL;
    struct bufs b = { 0 };
    rc = o.pattern ? run_pattern(&o, &p, &b) : run(&o, &c, &ref, &p, &b);
    if (p) panel_out_close(p);
    /* every output at once, or none: a failed run leaves the files before it */
    if (rc == EXIT_OK) {
        char err[512];
        if (img_commit(err, sizeof err)) rc = fail(EXIT_INTERNAL, "%s", err);
    } else {
        img_discard();
    }
    core_close(&c);
    core_close(&ref);
    free(b.strip);
    free(b.fb);
    free(b.rgb);
    free(b.ref_fb);
    free(b.ref_rgb);
    free(b.probe);
    free(b.ref_probe);
    free(b.item);
    free(b.ref_item);
    free(b.shown);
    free(b.glass);
    window_close(b.win);
    return rc;
}
