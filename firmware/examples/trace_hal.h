/* SPDX-License-Identifier: MIT */
/* trace_hal.h — a HAL of seven callbacks (hal/hal.h) whose bus is a text
 * trace: the shape of the HAL a board provides, with a file where the SPI
 * peripheral and the GPIO lines would be.
 *
 * Each callback writes what the wires would carry, in the notation of the
 * emulated panel's test vectors (docs/hal.md, "Test vectors"): "module
 * NAME" first, then "line dc|reset|cs|bl 0|1", "cmd HH" for a byte sent
 * with D/C low, "data HH ..." for bytes sent with D/C high, "delay_ms N",
 * and "# ..." notes. The project's emulated controller can replay such a
 * trace (build/asan/tests/test_panel_vectors FILE) and check every rule of
 * the protocol and what the glass shows.
 *
 * A HAL for real hardware keeps the same seven members: spi_write feeds the
 * SPI peripheral, line_set drives GPIO pins, delay_ms and now_us use a
 * timer; spi_write_async and spi_wait start and wait for DMA transfers, and
 * pixels_async sends pixels as 16-bit frames where the SPI can (NULL here:
 * the DCS layer then sends every byte through spi_write). */
#ifndef TRACE_HAL_H
#define TRACE_HAL_H

#include <stdint.h>
#include <stdio.h>
#include "hal.h"

struct trace_hal {
    FILE *out;
    int dc;              /* the D/C line's level */
    uint64_t us;         /* the clock: advanced by delay_ms only */
    unsigned on_line;    /* bytes on the current "data" line */
};

/* Fills *h with the trace's callbacks, writing to out; the trace starts
 * with "module MODULE" (the emulated module to replay it on). */
void trace_hal_init(struct trace_hal *t, struct hal *h, FILE *out, const char *module);

/* A note in the trace ("# text"). */
void trace_hal_note(struct trace_hal *t, const char *text);

/* 0 if every write reached the file so far, -1 otherwise. */
int trace_hal_error(struct trace_hal *t);

#endif
