/* SPDX-License-Identifier: MIT */
/* window.c — see window.h. */
#include "host_sim/window.h"

#include <stdio.h>
#include <stdlib.h>

#ifdef WITH_SDL2
#include <SDL.h>

int window_available(void) { return 1; }

struct window {
    SDL_Window *win;
    SDL_Renderer *ren;
    SDL_Texture *tex;
    unsigned w, h;
    int closed;
};

int window_open(struct window **out, const char *title, unsigned w, unsigned h, unsigned scale,
                char *err, size_t errlen)
{
    *out = NULL;
    /* SDL would fall back to a framebuffer or an invisible window */
    if (!getenv("DISPLAY") && !getenv("WAYLAND_DISPLAY") && !getenv("SDL_VIDEODRIVER")) {
        snprintf(err, errlen, "--window: no display (DISPLAY and WAYLAND_DISPLAY are not set)");
        return 2;
    }
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        snprintf(err, errlen, "--window: %s", SDL_GetError());
        return 2;
    }
    struct window *v = calloc(1, sizeof *v);
    if (!v) {
        SDL_Quit();
        snprintf(err, errlen, "out of memory");
        return 1;
    }
    v->w = w;
    v->h = h;
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "0");   /* whole-pixel blocks */
    v->win = SDL_CreateWindow(title, SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                              (int)(w * scale), (int)(h * scale), 0);
    if (v->win) v->ren = SDL_CreateRenderer(v->win, -1, SDL_RENDERER_SOFTWARE);
    if (v->ren) v->tex = SDL_CreateTexture(v->ren, SDL_PIXELFORMAT_RGB565, SDL_TEXTUREACCESS_STREAMING,
                                           (int)w, (int)h);
    if (!v->tex) {
        snprintf(err, errlen, "--window: %s", SDL_GetError());
        window_close(v);
        return 2;
    }
    SDL_SetRenderDrawColor(v->ren, 0, 0, 0, 255);
    SDL_RenderClear(v->ren);
    SDL_RenderPresent(v->ren);
    *out = v;
    return 0;
}

void window_update(struct window *v, const uint16_t *glass, unsigned y0, unsigned y1)
{
    SDL_Rect r = { 0, (int)y0, (int)v->w, (int)(y1 - y0) };
    SDL_UpdateTexture(v->tex, &r, glass + (size_t)y0 * v->w, (int)(v->w * sizeof *glass));
    SDL_RenderCopy(v->ren, v->tex, NULL, NULL);
    SDL_RenderPresent(v->ren);
    window_closed(v);
}

int window_closed(struct window *v)
{
    SDL_Event e;
    while (SDL_PollEvent(&e))
        if (e.type == SDL_QUIT ||
            (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE))
            v->closed = 1;
    return v->closed;
}

void window_close(struct window *v)
{
    if (!v) return;
    if (v->tex) SDL_DestroyTexture(v->tex);
    if (v->ren) SDL_DestroyRenderer(v->ren);
    if (v->win) SDL_DestroyWindow(v->win);
    free(v);
    SDL_Quit();
}

#else

struct window { int unused; };

int window_available(void) { return 0; }

int window_open(struct window **out, const char *title, unsigned w, unsigned h, unsigned scale,
                char *err, size_t errlen)
{
    (void)title; (void)w; (void)h; (void)scale;
    *out = NULL;
    snprintf(err, errlen, "--window: this build has no SDL2 (install libsdl2-dev and rebuild)");
    return 2;
}

void window_update(struct window *v, const uint16_t *glass, unsigned y0, unsigned y1)
{
    (void)v; (void)glass; (void)y0; (void)y1;
}

int window_closed(struct window *v)
{
    (void)v;
    return 1;
}

void window_close(struct window *v) { (void)v; }

#endif
