/* SPDX-License-Identifier: MIT */
/* dcs.c — MIPI DCS/DBI command layer over struct hal. */
#include "dcs.h"

static int spi(struct dcs *d, const uint8_t *b, size_t n)
{
    d->bytes_sent += (uint32_t)n;
    return d->hal->spi_write(d->hal->ctx, b, n);
}

int dcs_init(struct dcs *d, const struct hal *hal)
{
    d->hal = hal;
    d->x_off = 0;
    d->y_off = 0;
    d->bytes_sent = 0;
    d->next_buf = 0;
    d->rgb666 = 0;
    hal->line_set(hal->ctx, HAL_LINE_CS, 1);
    hal->line_set(hal->ctx, HAL_LINE_DC, 1);
    return 0;
}

/* CS low, D/C low, the command byte, D/C high: parameters follow. */
static int begin(struct dcs *d, uint8_t cmd)
{
    const struct hal *h = d->hal;
    h->line_set(h->ctx, HAL_LINE_CS, 0);
    h->line_set(h->ctx, HAL_LINE_DC, 0);
    int rc = spi(d, &cmd, 1);
    h->line_set(h->ctx, HAL_LINE_DC, 1);
    return rc;
}

static void end(struct dcs *d)
{
    d->hal->line_set(d->hal->ctx, HAL_LINE_CS, 1);
}

int dcs_command(struct dcs *d, uint8_t cmd, const uint8_t *params, size_t n)
{
    int rc = begin(d, cmd);
    if (rc == 0 && n > 0)
        rc = spi(d, params, n);
    end(d);
    return rc;
}

void dcs_delay_ms(struct dcs *d, uint32_t ms)
{
    d->hal->delay_ms(d->hal->ctx, ms);
}

int dcs_hw_reset(struct dcs *d, uint32_t low_ms, uint32_t wait_ms)
{
    const struct hal *h = d->hal;
    h->line_set(h->ctx, HAL_LINE_RESET, 1);
    h->line_set(h->ctx, HAL_LINE_RESET, 0);
    h->delay_ms(h->ctx, low_ms ? low_ms : 1);
    h->line_set(h->ctx, HAL_LINE_RESET, 1);
    h->delay_ms(h->ctx, wait_ms);
    return 0;
}

static int addr_pair(struct dcs *d, uint8_t cmd, uint8_t bytes, uint16_t a0, uint16_t a1, uint16_t off)
{
    uint32_t s = (uint32_t)a0 + off, e = (uint32_t)a1 + off;
    uint8_t p[4] = { (uint8_t)(s >> 8), (uint8_t)s, (uint8_t)(e >> 8), (uint8_t)e };
    if (bytes == 1) {
        p[0] = (uint8_t)s;
        p[1] = (uint8_t)e;
    }
    return dcs_command(d, cmd, p, 2u * bytes);
}

int dcs_set_window_cmds(struct dcs *d, uint8_t col_cmd, uint8_t row_cmd, uint8_t addr_bytes,
                        uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1)
{
    uint32_t max = addr_bytes == 1 ? 0xFFu : 0xFFFFu;
    if ((addr_bytes != 1 && addr_bytes != 2) || x0 > x1 || y0 > y1 || (uint32_t)x1 + d->x_off > max ||
        (uint32_t)y1 + d->y_off > max)
        return -1;
    int rc = addr_pair(d, col_cmd, addr_bytes, x0, x1, d->x_off);
    if (rc == 0)
        rc = addr_pair(d, row_cmd, addr_bytes, y0, y1, d->y_off);
    return rc;
}

int dcs_set_window(struct dcs *d, uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1)
{
    return dcs_set_window_cmds(d, DCS_CASET, DCS_RASET, 2, x0, y0, x1, y1);
}

int dcs_write_begin(struct dcs *d, int cont)
{
    return begin(d, cont ? DCS_RAMWRC : DCS_RAMWR);
}

int dcs_write_begin_cmd(struct dcs *d, uint8_t cmd)
{
    return begin(d, cmd);
}

int dcs_write_data(struct dcs *d, const uint8_t *data, size_t n)
{
    return n ? spi(d, data, n) : 0;
}

/* Sends chunk k (bytes in d->buf[k]); with an asynchronous HAL the previous
 * chunk is waited for first, so the other buffer can be refilled meanwhile. */
static int send_chunk(struct dcs *d, int k, size_t n)
{
    const struct hal *h = d->hal;
    if (h->spi_write_async && h->spi_wait) {
        int rc = h->spi_wait(h->ctx);
        if (rc != 0)
            return rc;
        d->bytes_sent += (uint32_t)n;
        return h->spi_write_async(h->ctx, d->buf[k], n, 0, 0);
    }
    return spi(d, d->buf[k], n);
}

/* One RGB565 pixel as three bytes, each channel's top bits repeated below
 * it (31 -> 255, 63 -> 255, 0 -> 0): the controller reads bits 7..2. */
static void put666(uint8_t *b, uint16_t v)
{
    unsigned r = v >> 11, g = (v >> 5) & 0x3Fu, bl = v & 0x1Fu;
    b[0] = (uint8_t)(r << 3 | r >> 2);
    b[1] = (uint8_t)(g << 2 | g >> 4);
    b[2] = (uint8_t)(bl << 3 | bl >> 2);
}

static int write_pixels666(struct dcs *d, const uint16_t *px, size_t n)
{
    int k = d->next_buf;
    while (n > 0) {
        size_t m = n < DCS_CHUNK_BYTES / 3 ? n : DCS_CHUNK_BYTES / 3;
        uint8_t *b = d->buf[k];
        for (size_t i = 0; i < m; i++)
            put666(b + 3 * i, px[i]);
        int rc = send_chunk(d, k, 3 * m);
        if (rc != 0)
            return rc;
        px += m;
        n -= m;
        k ^= 1;
        d->next_buf = (uint8_t)k;
    }
    return 0;
}

int dcs_write_pixels(struct dcs *d, const uint16_t *px, size_t n)
{
    int k = d->next_buf;
    if (d->rgb666)
        return write_pixels666(d, px, n);
    while (n > 0) {
        size_t m = n < DCS_CHUNK_BYTES / 2 ? n : DCS_CHUNK_BYTES / 2;
        uint8_t *b = d->buf[k];
        for (size_t i = 0; i < m; i++) {
            b[2 * i] = (uint8_t)(px[i] >> 8);
            b[2 * i + 1] = (uint8_t)px[i];
        }
        int rc = send_chunk(d, k, 2 * m);
        if (rc != 0)
            return rc;
        px += m;
        n -= m;
        k ^= 1;
        d->next_buf = (uint8_t)k;
    }
    return 0;
}

int dcs_write_pixels_async(struct dcs *d, const uint16_t *px, size_t n, hal_done_fn done, void *arg)
{
    const struct hal *h = d->hal;
    if (h->pixels_async && !d->rgb666) {
        d->bytes_sent += (uint32_t)(2u * n);
        return h->pixels_async(h->ctx, px, n, done, arg);
    }
    int rc = dcs_write_pixels(d, px, n);
    if (rc == 0 && done)
        done(arg);
    return rc;
}

int dcs_wait(struct dcs *d)
{
    const struct hal *h = d->hal;
    return h->spi_wait ? h->spi_wait(h->ctx) : 0;
}

int dcs_write_fill(struct dcs *d, uint16_t colour, size_t n)
{
    /* One buffer never changes while it is on the bus, so it is filled once. */
    size_t bpp = d->rgb666 ? 3 : 2;
    size_t per = DCS_CHUNK_BYTES / bpp;
    size_t m0 = n < per ? n : per;
    int k = d->next_buf;
    if (n == 0)
        return 0;
    for (size_t i = 0; i < m0; i++) {
        if (d->rgb666) {
            put666(d->buf[k] + 3 * i, colour);
        } else {
            d->buf[k][2 * i] = (uint8_t)(colour >> 8);
            d->buf[k][2 * i + 1] = (uint8_t)colour;
        }
    }
    d->next_buf = (uint8_t)(k ^ 1);
    while (n > 0) {
        size_t m = n < per ? n : per;
        int rc = send_chunk(d, k, bpp * m);
        if (rc != 0)
            return rc;
        n -= m;
    }
    return 0;
}

int dcs_write_end(struct dcs *d)
{
    int rc = 0;
    if ((d->hal->spi_write_async || d->hal->pixels_async) && d->hal->spi_wait)
        rc = d->hal->spi_wait(d->hal->ctx);
    end(d);
    return rc;
}

int dcs_flush(struct dcs *d, uint16_t x, uint16_t y, uint16_t w, uint16_t h, const uint16_t *px)
{
    if (w == 0 || h == 0 || (uint32_t)x + w - 1 > 0xFFFFu || (uint32_t)y + h - 1 > 0xFFFFu)
        return -1;
    int rc = dcs_set_window(d, x, y, (uint16_t)(x + w - 1), (uint16_t)(y + h - 1));
    if (rc == 0)
        rc = dcs_write_begin(d, 0);
    if (rc == 0)
        rc = dcs_write_pixels(d, px, (size_t)w * h);
    int rc2 = dcs_write_end(d);
    return rc ? rc : rc2;
}
