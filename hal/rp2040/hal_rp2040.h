/* SPDX-License-Identifier: MIT */
/* hal_rp2040.h — the RP2040 backend of hal.h: SPI0 (PL022) + DMA + SIO GPIO
 * + the 1 MHz timer.
 *
 * Pins are build-time options (defaults: a 240x240 ST7789 module wired as in
 * docs/firmware.md): SCK GP18, MOSI GP19, CS GP17, DC GP16, RST GP20, BL GP21.
 * SPI0 runs in mode 3 (works with modules that tie CS low) at
 * clk_peri / RP2040_SPI_CPSDVSR = 125 MHz / 2 = 62.5 MHz by default: the
 * ST7789VW's 16 ns write cycle, beyond the ST7789V's and ILI9341's rated
 * clocks (docs/firmware.md: 8 gives 15.6 MHz, 14 gives 8.9 MHz).
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
#ifndef RP2040_SPI_CPSDVSR
#define RP2040_SPI_CPSDVSR 2   /* even, 2..254 */
#endif
#ifndef RP2040_SPI_DMA_CH
#define RP2040_SPI_DMA_CH 0
#endif

/* Configures pins, SPI0 and DMA; fills *h (all seven operations; pixels
 * go as 16-bit SPI frames by DMA, without byte swapping). What the backend
 * needs from the board: the resets of IO_BANK0, PADS_BANK0, DMA and SPI0
 * released, clk_peri running at clk_peri_hz, and a microsecond clock
 * (now_us and delay_ms use it). Returns 0. */
int hal_rp2040_init(struct hal *h, uint32_t clk_peri_hz, uint64_t (*now_us)(void));

/* SPI clock in Hz as configured. */
uint32_t hal_rp2040_spi_hz(void);

#endif
