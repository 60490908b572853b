/* SPDX-License-Identifier: MIT */
/* hal_stm32f4.c — SPI1 + DMA2 + GPIO + TIM2 behind hal.h. */
#include "hal_stm32f4.h"
#include "stm32f411_regs.h"

#if STM32_SPI_BR < 0 || STM32_SPI_BR > 7
#error "STM32_SPI_BR must be 0..7"
#endif

#define STREAM 3u
#define CHANNEL 3u
#define DMA_MAX 65535u

struct stm32_bus {
    hal_done_fn done;  /* completion of the transfer in flight */
    void *arg;
    uint8_t bits;      /* current SPI frame size: 8 or 16 */
    uint8_t busy;      /* a DMA transfer was started */
    uint32_t apb2_hz;  /* SPI1's clock */
    uint64_t (*now_us)(void);
};

static struct stm32_bus bus;

static void spi_idle(void)
{
    while (!(REG(SPI_SR) & SPI_SR_TXE)) {}
    while (REG(SPI_SR) & SPI_SR_BSY) {}
    /* TX only: drop what was received (clears an overrun as well). */
    while (REG(SPI_SR) & SPI_SR_RXNE) (void)REG(SPI_DR);
}

static void spi_frame_bits(uint8_t bits)
{
    if (bus.bits == bits) return;
    /* The frame format is changed with the port idle and disabled. */
    spi_idle();
    uint32_t cr1 = SPI_CR1_CPHA | SPI_CR1_CPOL | SPI_CR1_MSTR | SPI_CR1_BR(STM32_SPI_BR) |
                   SPI_CR1_SSI | SPI_CR1_SSM | (bits == 16 ? SPI_CR1_DFF : 0u);
    REG(SPI_CR1) = cr1;
    REG(SPI_CR1) = cr1 | SPI_CR1_SPE;
    bus.bits = bits;
}

static int st_spi_wait(void *ctx)
{
    (void)ctx;
    int rc = 0;
    if (bus.busy) {
        while (REG(DMA_SCR(STREAM)) & DMA_SCR_EN) {}
        if (REG(DMA_LISR) & DMA_S3_TEIF) rc = -1;
        REG(DMA_LIFCR) = DMA_S3_FLAGS;
        bus.busy = 0;
    }
    spi_idle();
    if (bus.done) {
        hal_done_fn done = bus.done;
        bus.done = 0;
        done(bus.arg);
    }
    return rc;
}

static int st_spi_write(void *ctx, const uint8_t *data, size_t n)
{
    int rc = st_spi_wait(ctx);
    spi_frame_bits(8);
    for (size_t i = 0; i < n; i++) {
        while (!(REG(SPI_SR) & SPI_SR_TXE)) {}
        REG(SPI_DR) = data[i];
    }
    spi_idle();
    return rc;
}

/* One DMA transfer of count frames (count <= DMA_MAX). */
static void dma_start(const void *src, uint32_t count, uint32_t size_bits)
{
    REG(DMA_LIFCR) = DMA_S3_FLAGS;
    REG(DMA_SPAR(STREAM)) = SPI_DR;
    REG(DMA_SM0AR(STREAM)) = (uint32_t)(uintptr_t)src;
    REG(DMA_SNDTR(STREAM)) = count;
    REG(DMA_SFCR(STREAM)) = 0;   /* direct mode */
    REG(DMA_SCR(STREAM)) = DMA_SCR_CHSEL(CHANNEL) | DMA_SCR_PL_HIGH | DMA_SCR_MINC |
                           DMA_SCR_DIR_M2P | size_bits | DMA_SCR_EN;
    bus.busy = 1;
}

static int dma_write(const void *src, size_t count, uint8_t bits, hal_done_fn done, void *arg)
{
    st_spi_wait(0);
    spi_frame_bits(bits);
    uint32_t size = bits == 16 ? (DMA_SCR_PSIZE_16 | DMA_SCR_MSIZE_16) : 0u;
    const uint8_t *p = src;
    /* Longer writes than one DMA transfer: all but the last block blocking. */
    while (count > DMA_MAX) {
        dma_start(p, DMA_MAX, size);
        st_spi_wait(0);
        p += (size_t)DMA_MAX * (bits / 8u);
        count -= DMA_MAX;
    }
    bus.done = done;
    bus.arg = arg;
    if (count) dma_start(p, (uint32_t)count, size);
    return 0;
}

static int st_spi_write_async(void *ctx, const uint8_t *data, size_t n, hal_done_fn done, void *arg)
{
    (void)ctx;
    return dma_write(data, n, 8, done, arg);
}

static int st_pixels_async(void *ctx, const uint16_t *px, size_t n, hal_done_fn done, void *arg)
{
    (void)ctx;
    return dma_write(px, n, 16, done, arg);
}

static const uint8_t line_pin[4] = {
    [HAL_LINE_DC] = STM32_PIN_DC, [HAL_LINE_RESET] = STM32_PIN_RST,
    [HAL_LINE_CS] = STM32_PIN_CS, [HAL_LINE_BL] = STM32_PIN_BL,
};

static void st_line_set(void *ctx, enum hal_line line, int level)
{
    if ((unsigned)line > HAL_LINE_BL) return;
    /* A line changes only once the bytes sent before it have left the wire. */
    st_spi_wait(ctx);
    stm32_pin_set(line_pin[line], level);
}

static uint64_t st_now_us(void *ctx)
{
    (void)ctx;
    return bus.now_us();
}

static void st_delay_ms(void *ctx, uint32_t ms)
{
    uint64_t end = st_now_us(ctx) + (uint64_t)ms * 1000u + 1u;   /* at least ms whole milliseconds */
    while (st_now_us(ctx) < end) {}
}

uint32_t hal_stm32f4_spi_hz(void) { return bus.apb2_hz >> (STM32_SPI_BR + 1); }

int hal_stm32f4_init(struct hal *h, uint32_t apb2_hz, uint64_t (*now_us)(void))
{
    bus.apb2_hz = apb2_hz;
    bus.now_us = now_us;
    /* Idle levels: CS high (deselected), DC high, RST high, BL off. */
    stm32_pin_output(STM32_PIN_CS, 1);
    stm32_pin_output(STM32_PIN_DC, 1);
    stm32_pin_output(STM32_PIN_RST, 1);
    stm32_pin_output(STM32_PIN_BL, 0);
    stm32_pin_af(STM32_PIN_SCK, 5u);
    stm32_pin_af(STM32_PIN_MOSI, 5u);

    bus.bits = 0;
    bus.busy = 0;
    bus.done = 0;
    spi_frame_bits(8);
    REG(SPI_CR2) = SPI_CR2_TXDMAEN;

    h->ctx = &bus;
    h->spi_write = st_spi_write;
    h->spi_write_async = st_spi_write_async;
    h->spi_wait = st_spi_wait;
    h->line_set = st_line_set;
    h->delay_ms = st_delay_ms;
    h->now_us = st_now_us;
    h->pixels_async = st_pixels_async;
    return 0;
}
