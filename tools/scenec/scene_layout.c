/* SPDX-License-Identifier: MIT */
/* scene_layout.c — the sizes of a compiled scene's const data types in this
 * build (tools/scenec/scene_layout.h). Compiled into the work probe (the
 * target's) and, in fixed point, into scenec (this host's). No heap, no
 * stdio: it runs on the emulated Cortex-M0+ too. */
#include "scene_layout.h"

#include <string.h>

#include "scene.h"

const char *const scene_layout_names[SCENE_LAYOUT_COUNT] = {
#define SCENE_LAYOUT_NAME(name, type) #name,
    SCENE_LAYOUT_TYPES(SCENE_LAYOUT_NAME)
#undef SCENE_LAYOUT_NAME
};

void scene_layout_of_build(struct scene_layout *l)
{
#define SCENE_LAYOUT_SIZE(name, type) l->size[SCENE_LAYOUT_##name] = sizeof(type);
    SCENE_LAYOUT_TYPES(SCENE_LAYOUT_SIZE)
#undef SCENE_LAYOUT_SIZE
}

int scene_layout_format(const struct scene_layout *l, char *buf, size_t n)
{
    size_t k = 0;
    for (int i = 0; i < SCENE_LAYOUT_COUNT; i++) {
        char digits[24];
        size_t nd = 0, v = l->size[i], len = strlen(scene_layout_names[i]);
        do {
            digits[nd++] = (char)('0' + v % 10);
            v /= 10;
        } while (v && nd < sizeof digits);
        if (k + (i > 0) + len + 1 + nd + 1 > n) return -1;
        if (i > 0) buf[k++] = ',';
        memcpy(buf + k, scene_layout_names[i], len);
        k += len;
        buf[k++] = '=';
        while (nd) buf[k++] = digits[--nd];
    }
    if (!n) return -1;
    buf[k] = 0;
    return 0;
}

int scene_layout_parse(const char *s, struct scene_layout *l)
{
    struct scene_layout t;
    unsigned seen = 0;
    for (;;) {
        const char *eq = strchr(s, '=');
        if (!eq) return -1;
        int i = 0;
        while (i < SCENE_LAYOUT_COUNT && (strlen(scene_layout_names[i]) != (size_t)(eq - s) ||
                                          memcmp(s, scene_layout_names[i], (size_t)(eq - s))))
            i++;
        if (i == SCENE_LAYOUT_COUNT || seen >> i & 1u) return -1;
        seen |= 1u << i;
        size_t v = 0;
        s = eq + 1;
        if (*s < '0' || *s > '9') return -1;
        for (; *s >= '0' && *s <= '9'; s++) {
            v = v * 10 + (size_t)(*s - '0');
            if (v > 1000000) return -1;
        }
        if (v < 1) return -1;
        t.size[i] = v;
        if (!*s) break;
        if (*s++ != ',') return -1;
    }
    if (seen != (1u << SCENE_LAYOUT_COUNT) - 1u) return -1;
    *l = t;
    return 0;
}
