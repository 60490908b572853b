/* SPDX-License-Identifier: MIT */
/* A recording fake HAL for tests: every operation is appended to a text log
 * ("CS0 DC0 2A DC1 00 00 00 EF CS1 D120 ..."); runs of 8 or more equal
 * bytes are written "BBxN". With async = 1 the asynchronous write stays in
 * flight until spi_wait, and a buffer changed while in flight is noted. */
#ifndef TESTS_HAL_REC_H
#define TESTS_HAL_REC_H

#include <stdio.h>
#include <string.h>
#include "hal.h"

struct rec {
    char log[8192];
    size_t len;
    int last;                 /* last byte, -1 none */
    size_t run;               /* its pending repetitions */
    uint64_t t_us;
    size_t bytes;
    /* asynchronous write in flight */
    const uint8_t *fl_data;
    size_t fl_n;
    uint8_t fl_copy[4096];
    hal_done_fn fl_done;
    void *fl_arg;
    int async_writes, clobbered;
};

static void rec_put(struct rec *r, const char *s)
{
    size_t n = strlen(s);
    if (r->len + n + 2 < sizeof r->log) {
        if (r->len)
            r->log[r->len++] = ' ';
        memcpy(r->log + r->len, s, n);
        r->len += n;
        r->log[r->len] = 0;
    }
}

static void rec_flush_run(struct rec *r)
{
    char t[32];
    if (r->last < 0 || r->run == 0)
        return;
    if (r->run >= 8) {
        snprintf(t, sizeof t, "%02Xx%zu", (unsigned)r->last, r->run);
        rec_put(r, t);
    } else {
        for (size_t i = 0; i < r->run; i++) {
            snprintf(t, sizeof t, "%02X", (unsigned)r->last);
            rec_put(r, t);
        }
    }
    r->run = 0;
    r->last = -1;
}

static void rec_bytes(struct rec *r, const uint8_t *d, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        if ((int)d[i] != r->last)
            rec_flush_run(r);
        r->last = d[i];
        r->run++;
    }
    r->bytes += n;
}

static int rec_spi_write(void *ctx, const uint8_t *d, size_t n)
{
    rec_bytes(ctx, d, n);
    return 0;
}

static int rec_spi_wait(void *ctx)
{
    struct rec *r = ctx;
    if (r->fl_data) {
        if (memcmp(r->fl_data, r->fl_copy, r->fl_n) != 0)
            r->clobbered++;
        rec_bytes(r, r->fl_data, r->fl_n);
        r->fl_data = NULL;
        if (r->fl_done)
            r->fl_done(r->fl_arg);
    }
    return 0;
}

static int rec_spi_write_async(void *ctx, const uint8_t *d, size_t n, hal_done_fn done, void *arg)
{
    struct rec *r = ctx;
    rec_spi_wait(r);
    if (n > sizeof r->fl_copy)
        return -1;
    memcpy(r->fl_copy, d, n);
    r->fl_data = d;
    r->fl_n = n;
    r->fl_done = done;
    r->fl_arg = arg;
    r->async_writes++;
    return 0;
}

static void rec_line_set(void *ctx, enum hal_line line, int level)
{
    static const char *const nm[] = { "DC", "RST", "CS", "BL" };
    char t[16];
    struct rec *r = ctx;
    rec_flush_run(r);
    snprintf(t, sizeof t, "%s%d", nm[line], level);
    rec_put(r, t);
}

static void rec_delay_ms(void *ctx, uint32_t ms)
{
    char t[24];
    struct rec *r = ctx;
    rec_flush_run(r);
    snprintf(t, sizeof t, "D%u", (unsigned)ms);
    rec_put(r, t);
    r->t_us += (uint64_t)ms * 1000u;
}

static uint64_t rec_now_us(void *ctx)
{
    return ((struct rec *)ctx)->t_us;
}

static void rec_init(struct rec *r, struct hal *h, int async)
{
    memset(r, 0, sizeof *r);
    r->last = -1;
    h->ctx = r;
    h->spi_write = rec_spi_write;
    h->spi_write_async = async ? rec_spi_write_async : NULL;
    h->spi_wait = async ? rec_spi_wait : NULL;
    h->line_set = rec_line_set;
    h->delay_ms = rec_delay_ms;
    h->now_us = rec_now_us;
    h->pixels_async = NULL;
}

/* The log so far (pending runs written out), reset afterwards. */
static const char *rec_take(struct rec *r)
{
    static char out[8192];
    rec_flush_run(r);
    memcpy(out, r->log, r->len + 1);
    r->len = 0;
    r->log[0] = 0;
    return out;
}

#endif
