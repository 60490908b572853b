/* SPDX-License-Identifier: MIT */
/* hal_rp2040.c — SPI0 + DMA + GPIO + timer behind hal.h. */
#include "hal_rp2040.h"
#include "rp2040_regs.h"

#if defined(RP2040_SPI_HZ) && !(RP2040_SPI_HZ + 0 > 0)
#error "RP2040_SPI_HZ must be a clock in Hz, above 0"
#endif

#define CH RP2040_SPI_DMA_CH

struct rp2040_bus {
    hal_done_fn done;  /* completion of the transfer in flight */
    void *arg;
    uint8_t bits;      /* current SPI frame size: 8 or 16 */
    uint32_t cr0;      /* SSPCR0 but for the frame size: SCR, SPH, SPO */
    uint32_t div;      /* clk_peri / SPI clock: 2 * (1 + SCR) */
    uint32_t peri_hz;  /* clk_peri */
    uint64_t (*now_us)(void);
};

static struct rp2040_bus bus;

static void spi_frame_bits(uint8_t bits)
{
    if (bus.bits == bits) return;
    /* The frame size is changed with the port idle and disabled. */
    while (REG(SSPSR) & SSPSR_BSY) {}
    REG(SSPCR1) = 0;
    /* SCR, SPH and SPO (the mode), Motorola frames, DSS = bits - 1 */
    REG(SSPCR0) = bus.cr0 | (uint32_t)(bits - 1u);
    REG(SSPCR1) = SSPCR1_SSE;
    bus.bits = bits;
}

static void spi_drain_rx(void)
{
    while (REG(SSPSR) & SSPSR_RNE) (void)REG(SSPDR);
}

static int rp_spi_wait(void *ctx)
{
    (void)ctx;
    while (REG(DMA_CTRL_TRIG(CH)) & DMA_BUSY) {}
    while (REG(SSPSR) & SSPSR_BSY) {}
    spi_drain_rx();  /* TX-only DMA leaves received words (and an overrun) behind */
    if (bus.done) {
        hal_done_fn done = bus.done;
        bus.done = 0;
        done(bus.arg);
    }
    return 0;
}

static int rp_spi_write(void *ctx, const uint8_t *data, size_t n)
{
    rp_spi_wait(ctx);
    spi_frame_bits(8);
    for (size_t i = 0; i < n; i++) {
        while (!(REG(SSPSR) & SSPSR_TNF)) {}
        REG(SSPDR) = data[i];
        if (REG(SSPSR) & SSPSR_RNE) (void)REG(SSPDR);
    }
    while (REG(SSPSR) & SSPSR_BSY) {}
    spi_drain_rx();
    return 0;
}

/* Both callers have waited for the bus (rp_spi_wait) before. */
static int dma_start(const void *src, size_t count, uint32_t size, hal_done_fn done, void *arg)
{
    bus.done = done;
    bus.arg = arg;
    if (count == 0) return 0;
    REG(DMA_READ_ADDR(CH)) = (uint32_t)(uintptr_t)src;
    REG(DMA_WRITE_ADDR(CH)) = SSPDR;
    REG(DMA_TRANS_COUNT(CH)) = (uint32_t)count;
    REG(DMA_CTRL_TRIG(CH)) = DMA_CTRL_EN | size | DMA_INCR_READ | DMA_CHAIN_TO(CH) |
                             DMA_TREQ(DREQ_SPI0_TX);
    return 0;
}

static int rp_spi_write_async(void *ctx, const uint8_t *data, size_t n, hal_done_fn done, void *arg)
{
    (void)ctx;
    rp_spi_wait(0);
    spi_frame_bits(8);
    return dma_start(data, n, DMA_SIZE_BYTE, done, arg);
}

static int rp_pixels_async(void *ctx, const uint16_t *px, size_t n, hal_done_fn done, void *arg)
{
    (void)ctx;
    rp_spi_wait(0);
    spi_frame_bits(16);
    return dma_start(px, n, DMA_SIZE_HALF, done, arg);
}

static const uint8_t line_pin[4] = {
    [HAL_LINE_DC] = RP2040_PIN_DC, [HAL_LINE_RESET] = RP2040_PIN_RST,
    [HAL_LINE_CS] = RP2040_PIN_CS, [HAL_LINE_BL] = RP2040_PIN_BL,
};

static void rp_line_set(void *ctx, enum hal_line line, int level)
{
    if ((unsigned)line > HAL_LINE_BL) return;
    /* A line changes only once the bytes sent before it have left the wire. */
    rp_spi_wait(ctx);
    uint32_t bit = 1u << line_pin[line];
    if (level) REG(SIO_GPIO_OUT_SET) = bit;
    else REG(SIO_GPIO_OUT_CLR) = bit;
}

static uint64_t rp_now_us(void *ctx)
{
    (void)ctx;
    return bus.now_us();
}

static void rp_delay_ms(void *ctx, uint32_t ms)
{
    uint64_t end = rp_now_us(ctx) + (uint64_t)ms * 1000u;
    while (rp_now_us(ctx) < end) {}
}

uint32_t hal_rp2040_spi_hz(void) { return bus.div ? bus.peri_hz / bus.div : 0; }

uint32_t hal_rp2040_spi_div(uint32_t clk_peri_hz, uint32_t max_hz)
{
    if (max_hz == 0) return 512;
    uint32_t n = clk_peri_hz / max_hz;
    if (n * max_hz < clk_peri_hz) n++;   /* the smallest n with clk_peri / n <= max_hz */
    n += n & 1u;
    return n < 2 ? 2 : n > 512 ? 512 : n;
}

int hal_rp2040_init(struct hal *h, uint32_t clk_peri_hz, uint32_t spi_max_hz, uint64_t (*now_us)(void))
{
#ifdef RP2040_SPI_HZ
    spi_max_hz = RP2040_SPI_HZ;
#endif
    bus.peri_hz = clk_peri_hz;
    bus.now_us = now_us;
    bus.div = hal_rp2040_spi_div(clk_peri_hz, spi_max_hz);
    /* SCR in bits 15:8 (CPSDVSR is 2); SPH = 1, SPO = 1: mode 3 */
    bus.cr0 = ((bus.div / 2u - 1u) << 8) | (1u << 7) | (1u << 6);
    static const uint8_t sio_pins[] = { RP2040_PIN_CS, RP2040_PIN_DC, RP2040_PIN_RST, RP2040_PIN_BL };
    for (unsigned i = 0; i < sizeof sio_pins; i++) {
        uint32_t bit = 1u << sio_pins[i];
        /* Idle levels: CS high (deselected), DC high, RST high, BL off. */
        if (sio_pins[i] == RP2040_PIN_BL) REG(SIO_GPIO_OUT_CLR) = bit;
        else REG(SIO_GPIO_OUT_SET) = bit;
        REG(SIO_GPIO_OE_SET) = bit;
        REG(GPIO_CTRL(sio_pins[i])) = GPIO_FUNC_SIO;
    }
    /* Fast slew and 12 mA on the clock and data pins for a 62.5 MHz edge. */
    REG(PADS_GPIO(RP2040_PIN_SCK)) = PADS_IE | PADS_DRIVE_12MA | PADS_SLEWFAST;
    REG(PADS_GPIO(RP2040_PIN_MOSI)) = PADS_IE | PADS_DRIVE_12MA | PADS_SLEWFAST;
    REG(GPIO_CTRL(RP2040_PIN_SCK)) = GPIO_FUNC_SPI;
    REG(GPIO_CTRL(RP2040_PIN_MOSI)) = GPIO_FUNC_SPI;

    REG(SSPCPSR) = 2;
    bus.bits = 0;
    spi_frame_bits(8);
    REG(SSPDMACR) = SSPDMACR_TXDMAE;

    h->ctx = &bus;
    h->spi_write = rp_spi_write;
    h->spi_write_async = rp_spi_write_async;
    h->spi_wait = rp_spi_wait;
    h->line_set = rp_line_set;
    h->delay_ms = rp_delay_ms;
    h->now_us = rp_now_us;
    h->pixels_async = rp_pixels_async;
    return 0;
}
