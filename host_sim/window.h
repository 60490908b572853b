/* SPDX-License-Identifier: MIT */
/* window.h — host_sim --window: a live window of the glass (SDL2 from the
 * distribution), scaled by a whole factor, updated per strip. Built without
 * SDL2 (no pkg-config sdl2 at build time), window_open fails with one line
 * saying so. */
#ifndef HOST_SIM_WINDOW_H
#define HOST_SIM_WINDOW_H

#include <stddef.h>
#include <stdint.h>

struct window;

/* 1 when built with SDL2. */
int window_available(void);

/* Opens a window of w*scale x h*scale pixels titled title. 0, or 2 with one
 * line in err (no SDL2 in this build, no display). */
int window_open(struct window **win, const char *title, unsigned w, unsigned h, unsigned scale,
                char *err, size_t errlen);

/* Shows rows [y0, y1) of the glass (w x h RGB565 pixels, row-major). */
void window_update(struct window *win, const uint16_t *glass, unsigned y0, unsigned y1);

/* Handles pending window events; 1 once the window was closed. */
int window_closed(struct window *win);

void window_close(struct window *win);

#endif
