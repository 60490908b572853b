/* SPDX-License-Identifier: MIT */
/* fw_text.h — the UART lines' text, without printf (it would cost more
 * flash than the apps): a string and an unsigned number appended at p,
 * each returning the end. The caller's buffer holds the line. */
#ifndef FW_TEXT_H
#define FW_TEXT_H

#include <stdint.h>

static inline char *put_str(char *p, const char *s)
{
    while (*s) *p++ = *s++;
    return p;
}

static inline char *put_u32(char *p, uint32_t v)
{
    char tmp[10];
    int n = 0;
    do {
        tmp[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    while (n) *p++ = tmp[--n];
    return p;
}

#endif
