/* SPDX-License-Identifier: MIT */
/* Deterministic random numbers for the numeric tests (xorshift64*).
 * Define TEST_RNG_SEED before including to give a test its own sequence. */
#ifndef TESTS_TEST_RNG_H
#define TESTS_TEST_RNG_H

#include <stdint.h>

#ifndef TEST_RNG_SEED
#define TEST_RNG_SEED 0x9E3779B97F4A7C15ull
#endif

static uint64_t rng_state = TEST_RNG_SEED;

static inline uint64_t rng(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717ull;
}

/* Random value with a uniformly chosen bit length 1..bits (1 <= bits <= 64). */
static inline uint64_t rnd_bits(int bits)
{
    int b = 1 + (int)(rng() % (uint64_t)bits);
    uint64_t v = rng() >> (64 - b);
    return v | (uint64_t)1 << (b - 1);
}

#endif
