/* SPDX-License-Identifier: MIT */
/* hal_stm32f4.h — the STM32F4 backend of hal.h: SPI1 + DMA2 + GPIO + TIM2.
 *
 * Pins are build-time options, numbered port * 16 + index (PA5 = 5,
 * PB0 = 16). Defaults (a 240x240 ST7789 module on a "Black Pill"
 * STM32F411 board, wiring in docs/firmware.md): SCK PA5, MOSI PA7 (SPI1,
 * AF5), CS PA4, DC PA3, RST PA2, BL PA1.
 * SPI1 runs in mode 3 (works with modules that tie CS low) at
 * f_PCLK2 / 2 = 50 MHz, the fastest SPI1 clock under the ST7789's 62.5 MHz.
 *
 * Pixels go by DMA2 stream 3 channel 3 (SPI1_TX). Completion is polled (no
 * interrupts): `done` runs inside the next spi_wait() or line_set(). */
#ifndef HAL_STM32F4_H
#define HAL_STM32F4_H

#include <stddef.h>
#include <stdint.h>
#include "hal.h"

#ifndef STM32_PIN_SCK
#define STM32_PIN_SCK 5      /* PA5 (SPI1 SCK: PA5 or PB3) */
#endif
#ifndef STM32_PIN_MOSI
#define STM32_PIN_MOSI 7     /* PA7 (SPI1 MOSI: PA7 or PB5) */
#endif
#ifndef STM32_PIN_CS
#define STM32_PIN_CS 4       /* PA4 */
#endif
#ifndef STM32_PIN_DC
#define STM32_PIN_DC 3       /* PA3 */
#endif
#ifndef STM32_PIN_RST
#define STM32_PIN_RST 2      /* PA2 */
#endif
#ifndef STM32_PIN_BL
#define STM32_PIN_BL 1       /* PA1 */
#endif
#ifndef STM32_SPI_BR
#define STM32_SPI_BR 0       /* SPI clock f_PCLK2 / 2^(BR+1), 0..7 */
#endif

/* Configures pins, SPI1 and DMA2; fills *h (all seven operations; pixels
 * go as 16-bit SPI frames by DMA, without byte swapping). What the backend
 * needs from the board: the clocks of the GPIO ports, DMA2 and SPI1 enabled,
 * SPI1's bus clock (APB2) at apb2_hz, and a microsecond clock (now_us and
 * delay_ms use it). Returns 0. */
int hal_stm32f4_init(struct hal *h, uint32_t apb2_hz, uint64_t (*now_us)(void));

/* SPI clock in Hz as configured. */
uint32_t hal_stm32f4_spi_hz(void);

#endif
