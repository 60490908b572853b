/* SPDX-License-Identifier: MIT */
/* fw_board_stm32f411.c — the application's board interface on the
 * STM32F411 (one core: the mailbox functions are never called). */
#include "fw_board.h"
#include "board.h"
#include "hal_stm32f4.h"

const char fw_board_name[] = "stm32f411";

/* The SPI clock is STM32_SPI_BR's (hal_stm32f4.h), whatever the panel's
 * rated clock. */
int fw_board_init(struct hal *h, uint32_t spi_max_hz)
{
    (void)spi_max_hz;
    return hal_stm32f4_init(h, board_apb2_hz, board_now_us);
}

void fw_board_puts(const char *s) { board_puts(s); }

int fw_board_again(void) { return 1; }

unsigned fw_board_cores(void) { return 1u; }
int fw_board_core1_start(void (*entry)(void))
{
    (void)entry;
    return -1;
}
void fw_board_send(uint32_t v) { (void)v; }
uint32_t fw_board_recv(void) { return 0; }
void fw_board_lock(void) {}
void fw_board_unlock(void) {}
void fw_board_notify(void) {}
void fw_board_wait(void) {}
uint32_t fw_board_cpu_hz(void) { return board_sys_hz; }
uint32_t fw_board_spi_hz(void) { return hal_stm32f4_spi_hz(); }
int fw_board_te_wait(uint32_t timeout_us)
{
    (void)timeout_us;
    return -1; /* no TE line wired */
}
