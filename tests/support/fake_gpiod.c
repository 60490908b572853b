/* SPDX-License-Identifier: MIT */
/* fake_gpiod.c — see fake_gpiod.h. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <gpiod.h>
#include <stdlib.h>
#include <string.h>
#include "fake_gpiod.h"

#ifndef GPIOD_API_MAJOR
#define GPIOD_API_MAJOR 1
#endif

struct fake_gpiod fake_gpiod = { "gpiochip0", 28, 0, -1, 0, 0, { { 0, 0, 0, 0 } }, NULL };

void fake_gpiod_reset(void)
{
    memset(&fake_gpiod, 0, sizeof fake_gpiod);
    fake_gpiod.chip_name = "gpiochip0";
    fake_gpiod.num_lines = 28;
    fake_gpiod.busy_line = -1;
}

static void event(unsigned off, int value, enum fake_gpiod_ev ev)
{
    if (fake_gpiod.on_event)
        fake_gpiod.on_event(off, value, ev);
}

struct gpiod_chip { int open; };
static struct gpiod_chip the_chip;

static struct gpiod_chip *chip_open(const char *name)
{
    if (fake_gpiod.chip_missing || strcmp(name, fake_gpiod.chip_name) != 0) {
        errno = ENOENT;
        return NULL;
    }
    the_chip.open = 1;
    fake_gpiod.chips_open++;
    return &the_chip;
}

void gpiod_chip_close(struct gpiod_chip *c)
{
    c->open = 0;
    fake_gpiod.chips_closed++;
}

/* Requests line off as an output at value; -1 and errno when refused. */
static int line_request(unsigned off, int value, int open_drain, int bias_disabled)
{
    if (off >= fake_gpiod.num_lines || off >= FAKE_GPIOD_LINES) {
        errno = EINVAL;
        return -1;
    }
    struct fake_gpiod_line *l = &fake_gpiod.lines[off];
    if ((int)off == fake_gpiod.busy_line || l->requested) {
        errno = EBUSY;
        return -1;
    }
    l->requested = 1;
    l->open_drain = open_drain;
    l->bias_disabled = bias_disabled;
    l->value = value != 0;
    event(off, l->value, FAKE_GPIOD_REQUEST);
    return 0;
}

static void line_set(unsigned off, int value)
{
    fake_gpiod.lines[off].value = value != 0;
    event(off, value != 0, FAKE_GPIOD_SET);
}

static void line_release(unsigned off)
{
    fake_gpiod.lines[off].requested = 0;
    event(off, fake_gpiod.lines[off].value, FAKE_GPIOD_RELEASE);
}

#if GPIOD_API_MAJOR >= 2

/* /dev/<chip_name> */
struct gpiod_chip *gpiod_chip_open(const char *path)
{
    if (strncmp(path, "/dev/", 5) != 0) {
        errno = ENOENT;
        return NULL;
    }
    return chip_open(path + 5);
}

struct gpiod_chip_info { size_t num_lines; };

struct gpiod_chip_info *gpiod_chip_get_info(struct gpiod_chip *chip)
{
    (void)chip;
    struct gpiod_chip_info *i = malloc(sizeof *i);
    if (i) i->num_lines = fake_gpiod.num_lines;
    return i;
}

size_t gpiod_chip_info_get_num_lines(struct gpiod_chip_info *info) { return info->num_lines; }
void gpiod_chip_info_free(struct gpiod_chip_info *info) { free(info); }

struct gpiod_line_settings {
    enum gpiod_line_direction dir;
    enum gpiod_line_drive drive;
    enum gpiod_line_value value;
    enum gpiod_line_bias bias;
};

struct gpiod_line_settings *gpiod_line_settings_new(void)
{
    return calloc(1, sizeof(struct gpiod_line_settings));
}

void gpiod_line_settings_free(struct gpiod_line_settings *s) { free(s); }

int gpiod_line_settings_set_direction(struct gpiod_line_settings *s, enum gpiod_line_direction d)
{
    s->dir = d;
    return 0;
}

int gpiod_line_settings_set_drive(struct gpiod_line_settings *s, enum gpiod_line_drive d)
{
    s->drive = d;
    return 0;
}

int gpiod_line_settings_set_bias(struct gpiod_line_settings *s, enum gpiod_line_bias b)
{
    s->bias = b;
    return 0;
}

int gpiod_line_settings_set_output_value(struct gpiod_line_settings *s, enum gpiod_line_value v)
{
    s->value = v;
    return 0;
}

/* One line per config, as the callers use it. */
struct gpiod_line_config {
    int has;
    unsigned off;
    struct gpiod_line_settings s;
};

struct gpiod_line_config *gpiod_line_config_new(void)
{
    return calloc(1, sizeof(struct gpiod_line_config));
}

void gpiod_line_config_free(struct gpiod_line_config *c) { free(c); }

int gpiod_line_config_add_line_settings(struct gpiod_line_config *c, const unsigned int *offsets,
                                        size_t num_offsets, struct gpiod_line_settings *s)
{
    if (num_offsets != 1 || c->has) {
        errno = EINVAL;
        return -1;
    }
    c->has = 1;
    c->off = offsets[0];
    c->s = *s;
    return 0;
}

struct gpiod_request_config { int unused; };

struct gpiod_request_config *gpiod_request_config_new(void)
{
    return calloc(1, sizeof(struct gpiod_request_config));
}

void gpiod_request_config_free(struct gpiod_request_config *c) { free(c); }

void gpiod_request_config_set_consumer(struct gpiod_request_config *c, const char *consumer)
{
    (void)c;
    (void)consumer;
}

struct gpiod_line_request { unsigned off; };

struct gpiod_line_request *gpiod_chip_request_lines(struct gpiod_chip *chip,
                                                    struct gpiod_request_config *req_cfg,
                                                    struct gpiod_line_config *line_cfg)
{
    (void)req_cfg;
    if (!chip->open || !line_cfg->has || line_cfg->s.dir != GPIOD_LINE_DIRECTION_OUTPUT) {
        errno = EINVAL;
        return NULL;
    }
    struct gpiod_line_request *r = malloc(sizeof *r);
    if (!r) return NULL;
    if (line_request(line_cfg->off, line_cfg->s.value == GPIOD_LINE_VALUE_ACTIVE,
                     line_cfg->s.drive == GPIOD_LINE_DRIVE_OPEN_DRAIN,
                     line_cfg->s.bias == GPIOD_LINE_BIAS_DISABLED)) {
        free(r);
        return NULL;
    }
    r->off = line_cfg->off;
    return r;
}

int gpiod_line_request_set_value(struct gpiod_line_request *r, unsigned int offset,
                                 enum gpiod_line_value value)
{
    if (offset != r->off || (value != GPIOD_LINE_VALUE_ACTIVE && value != GPIOD_LINE_VALUE_INACTIVE)) {
        errno = EINVAL;
        return -1;
    }
    line_set(offset, value == GPIOD_LINE_VALUE_ACTIVE);
    return 0;
}

void gpiod_line_request_release(struct gpiod_line_request *r)
{
    line_release(r->off);
    free(r);
}

#else

struct gpiod_line { unsigned off; };
static struct gpiod_line the_lines[FAKE_GPIOD_LINES];

struct gpiod_chip *gpiod_chip_open_lookup(const char *descr) { return chip_open(descr); }
struct gpiod_chip *gpiod_chip_open_by_name(const char *name) { return chip_open(name); }

struct gpiod_chip *gpiod_chip_open(const char *path)
{
    if (strncmp(path, "/dev/", 5) != 0) {
        errno = ENOENT;
        return NULL;
    }
    return chip_open(path + 5);
}

unsigned int gpiod_chip_num_lines(struct gpiod_chip *c)
{
    (void)c;
    return fake_gpiod.num_lines;
}

struct gpiod_line *gpiod_chip_get_line(struct gpiod_chip *c, unsigned int offset)
{
    (void)c;
    if (offset >= fake_gpiod.num_lines || offset >= FAKE_GPIOD_LINES) {
        errno = EINVAL;
        return NULL;
    }
    the_lines[offset].off = offset;
    return &the_lines[offset];
}

int gpiod_line_request_output_flags(struct gpiod_line *l, const char *consumer, int flags,
                                    int default_val)
{
    (void)consumer;
    return line_request(l->off, default_val, (flags & GPIOD_LINE_REQUEST_FLAG_OPEN_DRAIN) != 0,
                        (flags & GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE) != 0);
}

int gpiod_line_request_output(struct gpiod_line *l, const char *consumer, int default_val)
{
    return gpiod_line_request_output_flags(l, consumer, 0, default_val);
}

int gpiod_line_set_value(struct gpiod_line *l, int value)
{
    if (!fake_gpiod.lines[l->off].requested) {
        errno = EPERM;
        return -1;
    }
    line_set(l->off, value);
    return 0;
}

void gpiod_line_release(struct gpiod_line *l) { line_release(l->off); }

#endif
