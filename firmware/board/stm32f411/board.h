/* SPDX-License-Identifier: MIT */
/* board.h — STM32F411 bring-up (bare metal, no vendor library).
 *
 * Clocks: HSE crystal STM32_HSE_MHZ (default 25, as on the common
 * "Black Pill" boards) → PLL (M = HSE MHz, N = 200, P = 2) → 100 MHz SYSCLK,
 * AHB 100 MHz, APB2 100 MHz (SPI1, USART1), APB1 50 MHz (TIM2 at 100 MHz),
 * regulator scale 1, 3 flash wait states with prefetch and caches.
 * The FPU is enabled (CPACR) by the reset handler before any C code runs. */
#ifndef STM32F411_BOARD_H
#define STM32F411_BOARD_H

#include <stdint.h>

#ifndef STM32_HSE_MHZ
#define STM32_HSE_MHZ 25   /* 2..63 */
#endif
#define STM32_SYS_HZ  100000000u
#define STM32_APB2_HZ 100000000u
#define STM32_HSI_HZ  16000000u
/* Each clock wait gives up after this many polls (at least 4 cycles each at
 * the 16 MHz HSI the chip starts on: over 100 ms). */
#ifndef STM32_CLOCK_WAIT
#define STM32_CLOCK_WAIT 400000u
#endif

/* Pins: port * 16 + index */
#define STM32_PA(n) (n)
#define STM32_PB(n) (16 + (n))
#define STM32_PC(n) (32 + (n))

typedef void (*vector_fn)(void);

/* Clocks, USART1 (115200 8N1 on PA9), the microsecond timer. Every clock
 * wait has a timeout (STM32_CLOCK_WAIT): without the crystal (HSE not ready)
 * the PLL runs from the HSI instead, at the same 100 MHz, and the first
 * UART line says so ("clock HSE not ready: PLL from HSI"); when the PLL does
 * not lock, VOSRDY does not come or the switch to the PLL does not happen,
 * the chip runs on, from the HSI at 16 MHz, after the line
 * "error clock: ... timed out: HSI at 16 MHz". */
void board_init(void);
/* SYSCLK and APB2 (SPI1, USART1) as brought up: 100 MHz, or 16 MHz on the HSI. */
extern uint32_t board_sys_hz, board_apb2_hz;
/* Microseconds since board_init (TIM2 at 1 MHz, extended to 64 bits; it must
 * be read at least once every 71 minutes, which every frame does). */
uint64_t board_now_us(void);
void board_delay_us(uint32_t us);
/* Blocking text to USART1. */
void board_puts(const char *s);

#endif
