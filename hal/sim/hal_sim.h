/* SPDX-License-Identifier: MIT */
/* hal_sim.h — the host HAL backend: bytes and lines go into an emulated
 * panel, time is a simulated clock.
 *
 * The clock starts at 0 and only moves when delay_ms is called or, if
 * spi_hz is set, by the time each SPI byte takes on the bus (8 bits at
 * spi_hz). Asynchronous writes complete at once (the callback runs before
 * spi_write_async returns).
 *
 * After the panel records a violation, spi_write returns HAL_SIM_EPROTO so
 * that drivers stop early; read the message with emu_panel_violation.
 * panel may be NULL: bytes are only counted.
 */
#ifndef HAL_SIM_H
#define HAL_SIM_H

#include <stdint.h>
#include "hal.h"
#include "emu_panel.h"

#define HAL_SIM_EPROTO (-3)

struct hal_sim {
    struct emu_panel *panel;     /* not owned; may be NULL */
    uint64_t t_ns;               /* simulated time */
    uint32_t spi_hz;             /* 0: SPI bytes take no time */
    uint64_t spi_bytes;          /* bytes written */
    uint32_t line_changes;
};

/* Fills *out with operations on s (out->ctx = s). */
void hal_sim_init(struct hal_sim *s, struct hal *out, struct emu_panel *panel);
/* Bus clock for SPI timing, 0 = instant. */
void hal_sim_set_spi_hz(struct hal_sim *s, uint32_t hz);
/* Simulated time in microseconds (same as the HAL's now_us). */
uint64_t hal_sim_now_us(const struct hal_sim *s);

#endif
