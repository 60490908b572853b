/* SPDX-License-Identifier: MIT */
/* check_pattern.c — the bring-up pattern (check_pattern.h). */
#include "check_pattern.h"
#include "font5x7.h"
#include "fw_text.h"

static const uint16_t bars[8] = { 0xffffu, 0xffe0u, 0x07ffu, 0x07e0u, 0xf81fu, 0xf800u, 0x001fu, 0x0000u };

/* Bounded text building (no printf). */
struct text {
    char *p, *end;
};

static void put_s(struct text *t, const char *s)
{
    while (*s && t->p < t->end) *t->p++ = *s++;
}

static void put_u(struct text *t, uint32_t v)
{
    char tmp[11];
    *put_u32(tmp, v) = 0;
    put_s(t, tmp);
}

/* hz in MHz with up to two decimals (62.5, 133, 20.83), "?" for 0 */
static void put_mhz(struct text *t, uint32_t hz)
{
    if (!hz) {
        put_s(t, "?");
        return;
    }
    const uint32_t c = (uint32_t)(((uint64_t)hz + 5000u) / 10000u); /* hundredths */
    put_u(t, c / 100u);
    if (c % 100u) {
        char d[4] = { '.', (char)('0' + c % 100u / 10u), (char)('0' + c % 10u), 0 };
        if (d[2] == '0') d[2] = 0;
        put_s(t, d);
    }
}

/* s in upper case (the font's letters) */
static void put_upper(struct text *t, const char *s)
{
    for (; *s && t->p < t->end; s++) *t->p++ = (char)(*s >= 'a' && *s <= 'z' ? *s - 'a' + 'A' : *s);
}

static void end_line(struct text *t) { *t->p = 0; }

static struct text line_at(char *line)
{
    struct text t = { line, line + CHECK_LINE_LEN - 1 };
    return t;
}

void check_setup(struct check_layout *l, const struct check_settings *s)
{
    const uint16_t w = s->width, h = s->height;
    /* a round glass: the square inside its circle, 3/20 of the side in
       (1 - 1/sqrt(2) = 0.146 of it halved is 0.146; a little more) */
    const unsigned in = s->round ? (w < h ? w : h) * 3u / 20u : 0u;
    const unsigned cw = w - 2u * in, ch = h - 2u * in, m = cw < ch ? cw : ch;
    l->w = w;
    l->h = h;
    l->inset = (uint16_t)in;
    l->mark = (uint16_t)(m / 8u);
    l->scale = m >= 200u ? 2u : 1u;
    l->bars_y = (uint16_t)(in + l->mark + 4u);
    l->bars_h = (uint16_t)(ch / 10u);
    l->grad_y = (uint16_t)(l->bars_y + l->bars_h + 2u);
    l->grad_h = (uint16_t)(ch / 30u > 2u ? ch / 30u : 2u);
    l->text_y = (uint16_t)(l->grad_y + 4u * l->grad_h + 2u);
    /* beside the blue square when the text would reach its rows */
    const unsigned text_h = CHECK_LINES * (unsigned)FONT5X7_BOX_H(l->scale);
    l->text_x = (uint16_t)(in + (l->text_y + text_h + 2u > h - in - l->mark - 2u ? l->mark + 6u : 4u));

    struct text t = line_at(l->lines[0]);
    put_upper(&t, s->panel);
    end_line(&t);
    t = line_at(l->lines[1]);
    put_u(&t, w);
    put_s(&t, "X");
    put_u(&t, h);
    put_s(&t, " ROT ");
    put_u(&t, s->rotation);
    end_line(&t);
    t = line_at(l->lines[2]);
    put_s(&t, "OFFSET ");
    put_u(&t, s->x_off);
    put_s(&t, ",");
    put_u(&t, s->y_off);
    end_line(&t);
    t = line_at(l->lines[3]);
    put_s(&t, s->bgr ? "BGR" : "RGB");
    put_s(&t, s->invert ? " INVERT ON" : " INVERT OFF");
    end_line(&t);
    t = line_at(l->lines[4]);
    put_s(&t, "SPI ");
    put_mhz(&t, s->spi_hz);
    put_s(&t, " MHZ");
    end_line(&t);
    t = line_at(l->lines[5]);
    put_s(&t, "CLK_SYS ");
    put_mhz(&t, s->sys_hz);
    put_s(&t, " MHZ");
    end_line(&t);
}

/* one row of everything but the text and the border */
static void row(const struct check_layout *l, uint16_t *px, unsigned y)
{
    const unsigned in = l->inset, w = l->w - in, h = l->h - in, m = l->mark;
    const unsigned x0 = in + 2u, n = w - x0 - 2u; /* the bars' and gradients' columns: x0 .. x0 + n - 1 */
    for (unsigned x = 0; x < l->w; x++) px[x] = CHECK_GROUND;
    if (y >= l->bars_y && y < (unsigned)l->bars_y + l->bars_h)
        for (unsigned x = x0; x < x0 + n; x++) px[x] = bars[(x - x0) * 8u / n];
    if (y >= l->grad_y && y < (unsigned)l->grad_y + 4u * l->grad_h) {
        const unsigned band = (y - l->grad_y) / l->grad_h, d = n > 1u ? n - 1u : 1u;
        for (unsigned x = x0; x < x0 + n; x++) {
            const unsigned t = x - x0, v5 = t * 31u / d, v6 = t * 63u / d;
            uint16_t c;
            if (band == 0) c = (uint16_t)((v6 >> 1) << 11 | v6 << 5 | (v6 >> 1));
            else if (band == 1) c = (uint16_t)(v5 << 11);
            else if (band == 2) c = (uint16_t)(v6 << 5);
            else c = (uint16_t)v5;
            px[x] = c;
        }
    }
    if (y >= in + 2u && y < in + 2u + m) {
        for (unsigned x = x0; x < x0 + m; x++) px[x] = CHECK_RED;
        for (unsigned x = w - 2u - m; x < w - 2u; x++) px[x] = CHECK_GREEN;
    }
    if (y + 2u + m >= h && y + 2u < h)
        for (unsigned x = x0; x < x0 + m; x++) px[x] = CHECK_BLUE;
}

void check_rows(const struct check_layout *l, uint16_t *strip, uint16_t y0, uint16_t y1)
{
    const int w = l->w, s = l->scale;
    for (unsigned y = y0; y < y1; y++) row(l, strip + (size_t)(y - y0) * (size_t)w, y);
    /* "TOP", centred, and the settings */
    const int top_w = 3 * 6 * s + 3;
    font5x7_draw(strip, w, y0, y1, (w - top_w) / 2, l->inset + 2, s, "TOP", CHECK_WHITE, 0x0000u);
    for (int i = 0; i < CHECK_LINES; i++)
        font5x7_draw(strip, w, y0, y1, l->text_x, l->text_y + i * FONT5X7_BOX_H(s), s, l->lines[i], CHECK_WHITE,
                     0x0000u);
    /* the border, over everything */
    for (unsigned y = y0; y < y1; y++) {
        uint16_t *px = strip + (size_t)(y - y0) * (size_t)w;
        if (y == 0 || y + 1u == l->h)
            for (int x = 0; x < w; x++) px[x] = CHECK_WHITE;
        px[0] = px[w - 1] = CHECK_WHITE;
    }
}

size_t check_uart_line(char *buf, size_t len, const struct check_settings *s)
{
    if (!len) return 0;
    struct text t = { buf, buf + len - 1 };
    put_s(&t, "check panel=");
    put_s(&t, s->panel);
    put_s(&t, " size=");
    put_u(&t, s->width);
    put_s(&t, "x");
    put_u(&t, s->height);
    put_s(&t, " rotation=");
    put_u(&t, s->rotation);
    put_s(&t, " offset=");
    put_u(&t, s->x_off);
    put_s(&t, ",");
    put_u(&t, s->y_off);
    put_s(&t, s->bgr ? " order=BGR" : " order=RGB");
    put_s(&t, s->invert ? " invert=on" : " invert=off");
    put_s(&t, " spi_mhz=");
    put_mhz(&t, s->spi_hz);
    put_s(&t, " clk_sys_mhz=");
    put_mhz(&t, s->sys_hz);
    put_s(&t, "\r\n");
    *t.p = 0;
    return (size_t)(t.p - buf);
}
