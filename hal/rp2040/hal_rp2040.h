/* SPDX-License-Identifier: MIT */
/* hal_rp2040.h — the RP2040 backend of hal.h: SPI0 (PL022) + DMA + SIO GPIO
 * + the 1 MHz timer.
 *
 * Pins are build-time options (defaults: a 240x240 ST7789 module wired as in
 * docs/firmware.md): SCK GP18, MOSI GP19, CS GP17, DC GP16, RST GP20, BL GP21.
 * SPI0 runs in mode 3 at the fastest clock
 * clk_peri / (CPSDVSR * (1 + SCR)) not above the panel's rated write clock
 * (struct panel_desc spi_max_hz; with clk_peri at 125 MHz: 62.5 MHz for the
 * ST7789VW, 8.93 MHz for the ILI9341), or not above RP2040_SPI_HZ when it is
 * defined: a clock the module was tested at beyond its controller's rating
 * (make FW_SPI_HZ=62500000; docs/firmware.md, "SPI clock"). Mode 3 for
 * every panel: each controller here samples on the rising edge and takes
 * either clock level at CS's falling edge (so modules that tie CS low work),
 * and the PL022 with SPH = 0 (modes 0 and 2) pulses its frame signal between
 * words, a gap a continuous transfer does not have in mode 3.
 *
 * Completion of asynchronous writes is polled (no interrupts): `done` runs
 * inside the next spi_wait() or line_set() on the same core. Only core 0
 * touches this backend. DMA channel RP2040_SPI_DMA_CH (default 0) is used. */
#ifndef HAL_RP2040_H
#define HAL_RP2040_H

#include <stddef.h>
#include <stdint.h>
#include "hal.h"

#ifndef RP2040_PIN_SCK
#define RP2040_PIN_SCK 18
#endif
#ifndef RP2040_PIN_MOSI
#define RP2040_PIN_MOSI 19
#endif
#ifndef RP2040_PIN_CS
#define RP2040_PIN_CS 17
#endif
#ifndef RP2040_PIN_DC
#define RP2040_PIN_DC 16
#endif
#ifndef RP2040_PIN_RST
#define RP2040_PIN_RST 20
#endif
#ifndef RP2040_PIN_BL
#define RP2040_PIN_BL 21
#endif
#ifdef RP2040_SPI_CPSDVSR
#error "RP2040_SPI_CPSDVSR is gone: the divider follows the panel's rated clock, or RP2040_SPI_HZ (make FW_SPI_HZ=...)"
#endif
#ifndef RP2040_SPI_DMA_CH
#define RP2040_SPI_DMA_CH 0
#endif

/* Configures pins, SPI0 and DMA; fills *h (all seven operations; pixels
 * go as 16-bit SPI frames by DMA, without byte swapping). SPI0 runs at the
 * fastest clock clk_peri_hz / n (n even, 2..512) not above spi_max_hz (the
 * panel's rated clock), or not above RP2040_SPI_HZ when that is defined
 * (never below clk_peri / 512). What the backend needs from the board: the
 * resets of IO_BANK0, PADS_BANK0, DMA and SPI0 released, clk_peri running
 * at clk_peri_hz, and a microsecond clock (now_us and delay_ms use it).
 * Returns 0. */
int hal_rp2040_init(struct hal *h, uint32_t clk_peri_hz, uint32_t spi_max_hz, uint64_t (*now_us)(void));

/* clk_peri's divider for the fastest SPI clock not above max_hz: the even
 * n = CPSDVSR * (1 + SCR) of 2..512 (CPSDVSR 2, SCR n / 2 - 1). */
uint32_t hal_rp2040_spi_div(uint32_t clk_peri_hz, uint32_t max_hz);

/* SPI clock in Hz as configured. */
uint32_t hal_rp2040_spi_hz(void);

#endif
