/* SPDX-License-Identifier: MIT */
/* suggest.h — "did you mean ...?" for a misspelt name: the nearest of a
 * list of valid names by edit distance (insertions, deletions,
 * substitutions, and swaps of two neighbouring characters, each counting
 * one), when it is near enough to be a slip of the keyboard.
 *
 * Used by the scene parser (unknown keys and values), host_sim and scenec
 * (unknown command-line options). Header only: every program that needs it
 * compiles its own copy, whatever it links.
 */
#ifndef SUGGEST_H
#define SUGGEST_H

#include <string.h>

/* Longest name compared; longer names get no suggestion. */
#define SUGGEST_MAX_LEN 64

/* Edit distance of a and b (both at most SUGGEST_MAX_LEN characters, else
 * SUGGEST_MAX_LEN + 1), each character compared case-insensitively. */
static inline unsigned suggest_distance(const char *a, const char *b)
{
    size_t na = strlen(a), nb = strlen(b);
    if (na > SUGGEST_MAX_LEN || nb > SUGGEST_MAX_LEN) return SUGGEST_MAX_LEN + 1;
    /* three rows of the table: i - 2, i - 1, i */
    unsigned rows[3][SUGGEST_MAX_LEN + 1];
    for (size_t j = 0; j <= nb; j++) rows[1][j] = (unsigned)j;
    for (size_t i = 1; i <= na; i++) {
        unsigned *cur = rows[(i + 1) % 3], *prev = rows[i % 3], *prev2 = rows[(i + 2) % 3];
        cur[0] = (unsigned)i;
        for (size_t j = 1; j <= nb; j++) {
            int ca = a[i - 1] | 0x20, cb = b[j - 1] | 0x20;   /* ASCII letters folded to lower case */
            unsigned d = prev[j - 1] + (ca != cb);
            if (prev[j] + 1 < d) d = prev[j] + 1;
            if (cur[j - 1] + 1 < d) d = cur[j - 1] + 1;
            if (i > 1 && j > 1 && ca == (b[j - 2] | 0x20) && (a[i - 2] | 0x20) == cb && prev2[j - 2] + 1 < d)
                d = prev2[j - 2] + 1;
            cur[j] = d;
        }
    }
    return rows[(na + 1) % 3][nb];
}

/* The name of names (NULL-terminated) nearest to word, if it is within
 * reach: 1 edit for words of up to 4 characters, 2 up to 8, 3 beyond, and
 * fewer edits than the word has characters; NULL when none is (or word is
 * itself one of them). The first of equally near names wins. */
static inline const char *suggest_nearest(const char *word, const char *const *names)
{
    size_t n = strlen(word);
    unsigned reach = n <= 4 ? 1u : n <= 8 ? 2u : 3u;
    if (reach >= n) reach = n ? (unsigned)n - 1 : 0;
    unsigned best = reach + 1;
    const char *pick = NULL;
    for (int i = 0; names[i]; i++) {
        unsigned d = suggest_distance(word, names[i]);
        if (d == 0) return NULL;
        if (d < best) {
            best = d;
            pick = names[i];
        }
    }
    return pick;
}

#endif
