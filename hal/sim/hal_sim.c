/* SPDX-License-Identifier: MIT */
/* hal_sim.c — HAL backend into an emulated panel with a simulated clock. */
#include "hal_sim.h"

static int sim_spi_write(void *ctx, const uint8_t *data, size_t n)
{
    struct hal_sim *s = ctx;
    uint32_t ns_per_byte = s->spi_hz ? (uint32_t)(8000000000ull / s->spi_hz) : 0;
    if (s->panel) {
        if (emu_panel_violation(s->panel))
            return HAL_SIM_EPROTO;
        emu_panel_spi(s->panel, data, n, s->t_ns, ns_per_byte);
    }
    s->t_ns += (uint64_t)n * ns_per_byte;
    s->spi_bytes += n;
    return (s->panel && emu_panel_violation(s->panel)) ? HAL_SIM_EPROTO : 0;
}

static int sim_spi_write_async(void *ctx, const uint8_t *data, size_t n, hal_done_fn done, void *arg)
{
    int rc = sim_spi_write(ctx, data, n);
    if (done)
        done(arg);
    return rc;
}

/* 16-bit frames: each pixel high byte first, as a DMA to a 16-bit SPI port
 * sends them. */
static int sim_pixels_async(void *ctx, const uint16_t *px, size_t n, hal_done_fn done, void *arg)
{
    uint8_t b[256];
    int rc = 0;
    while (rc == 0 && n > 0) {
        size_t m = n < sizeof b / 2 ? n : sizeof b / 2;
        for (size_t i = 0; i < m; i++) {
            b[2 * i] = (uint8_t)(px[i] >> 8);
            b[2 * i + 1] = (uint8_t)px[i];
        }
        rc = sim_spi_write(ctx, b, 2 * m);
        px += m;
        n -= m;
    }
    if (done)
        done(arg);
    return rc;
}

static int sim_spi_wait(void *ctx)
{
    (void)ctx;
    return 0;
}

static void sim_line_set(void *ctx, enum hal_line line, int level)
{
    struct hal_sim *s = ctx;
    s->line_changes++;
    if (s->panel)
        emu_panel_line(s->panel, (int)line, level, s->t_ns);
}

static void sim_delay_ms(void *ctx, uint32_t ms)
{
    struct hal_sim *s = ctx;
    s->t_ns += (uint64_t)ms * 1000000u;
}

static uint64_t sim_now_us(void *ctx)
{
    return hal_sim_now_us(ctx);
}

void hal_sim_init(struct hal_sim *s, struct hal *out, struct emu_panel *panel)
{
    s->panel = panel;
    s->t_ns = 0;
    s->spi_hz = 0;
    s->spi_bytes = 0;
    s->line_changes = 0;
    out->ctx = s;
    out->spi_write = sim_spi_write;
    out->spi_write_async = sim_spi_write_async;
    out->spi_wait = sim_spi_wait;
    out->line_set = sim_line_set;
    out->delay_ms = sim_delay_ms;
    out->now_us = sim_now_us;
    out->pixels_async = sim_pixels_async;
}

void hal_sim_set_spi_hz(struct hal_sim *s, uint32_t hz)
{
    s->spi_hz = hz;
}

uint64_t hal_sim_now_us(const struct hal_sim *s)
{
    return s->t_ns / 1000u;
}
