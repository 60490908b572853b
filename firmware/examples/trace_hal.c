/* SPDX-License-Identifier: MIT */
/* trace_hal.c — see trace_hal.h. */
#include "trace_hal.h"

/* Ends a "data" line in progress. */
static void end_line(struct trace_hal *t)
{
    if (t->on_line) {
        fputc('\n', t->out);
        t->on_line = 0;
    }
}

static int spi_write(void *ctx, const uint8_t *data, size_t n)
{
    struct trace_hal *t = ctx;
    for (size_t i = 0; i < n; i++) {
        if (!t->dc) {
            /* a command byte; "cmd" leaves the replayed D/C high, the wire keeps it low */
            end_line(t);
            fprintf(t->out, "cmd %02X\nline dc 0\n", data[i]);
            continue;
        }
        if (t->on_line == 32) end_line(t);
        fprintf(t->out, t->on_line ? " %02X" : "data %02X", data[i]);
        t->on_line++;
    }
    return ferror(t->out) ? -1 : 0;
}

/* No DMA: nothing is ever in flight. */
static int spi_wait(void *ctx)
{
    struct trace_hal *t = ctx;
    return ferror(t->out) ? -1 : 0;
}

static void line_set(void *ctx, enum hal_line line, int level)
{
    static const char *const names[] = { "dc", "reset", "cs", "bl" };
    struct trace_hal *t = ctx;
    if (line == HAL_LINE_DC) t->dc = level != 0;
    end_line(t);
    fprintf(t->out, "line %s %d\n", names[line], level != 0);
}

static void delay_ms(void *ctx, uint32_t ms)
{
    struct trace_hal *t = ctx;
    end_line(t);
    fprintf(t->out, "delay_ms %lu\n", (unsigned long)ms);
    t->us += (uint64_t)ms * 1000u;
}

static uint64_t now_us(void *ctx)
{
    struct trace_hal *t = ctx;
    return t->us;
}

void trace_hal_init(struct trace_hal *t, struct hal *h, FILE *out, const char *module)
{
    *t = (struct trace_hal){ .out = out, .dc = 1 };
    *h = (struct hal){
        .ctx = t,
        .spi_write = spi_write,
        .spi_write_async = NULL,   /* no DMA: the DCS layer uses spi_write */
        .spi_wait = spi_wait,
        .line_set = line_set,
        .delay_ms = delay_ms,
        .now_us = now_us,
        .pixels_async = NULL,      /* no 16-bit frames: the DCS layer byte-swaps */
    };
    fprintf(out, "module %s\n", module);
}

void trace_hal_note(struct trace_hal *t, const char *text)
{
    end_line(t);
    fprintf(t->out, "# %s\n", text);
}

int trace_hal_error(struct trace_hal *t)
{
    end_line(t);
    return fflush(t->out) || ferror(t->out) ? -1 : 0;
}
