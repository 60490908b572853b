/* scene_parse.h — the scene file parser (host side: host_sim and scenec).
 *
 * Compiled once per numeric mode: the scene it builds is in that mode's
 * numbers (num.h). Memory comes from an arena owned by the scene handle.
 */
#ifndef SCENE_PARSE_H
#define SCENE_PARSE_H

#include <stddef.h>
#include "scene.h"

/* Loads FILE. Returns 0 and sets *out, or returns 2 (input error) and writes
 * one line "FILE:LINE:COLUMN: error: MESSAGE" (no newline) into err. */
int scene_load(const char *path, struct scene **out, char *err, size_t errlen);
void scene_free(struct scene *s);

#endif
