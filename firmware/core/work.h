/* SPDX-License-Identifier: MIT */
/* work.h — a renderer's state carved out of the caller's work memory in one
 * walk (internal to the core).
 *
 * Each renderer lays out its state in a single carve function that runs
 * twice: once without memory (struct work_carve.base NULL) to measure the
 * bytes render_work_size() reports, once with the caller's memory to place
 * every table. The size asked for and the pointers set come from the same
 * lines, so they cannot disagree. Every block starts on a WORK_ALIGN
 * boundary (the largest alignment of the types placed: int64_t, double). */
#ifndef WORK_H
#define WORK_H

#include <stddef.h>
#include <stdint.h>

#define WORK_ALIGN 8

struct work_carve {
    uint8_t *base;   /* the memory being carved; NULL while measuring */
    size_t off;      /* bytes taken so far */
};

/* bytes rounded up to WORK_ALIGN */
static inline size_t work_round(size_t bytes) { return (bytes + (WORK_ALIGN - 1)) & ~(size_t)(WORK_ALIGN - 1); }

/* The next block of `bytes` (rounded up to WORK_ALIGN): its address, or
 * NULL while measuring. */
static inline void *work_take(struct work_carve *c, size_t bytes)
{
    void *p = c->base ? (void *)(c->base + c->off) : NULL;
    c->off += work_round(bytes);
    return p;
}

#endif
