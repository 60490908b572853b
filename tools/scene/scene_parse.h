/* SPDX-License-Identifier: MIT */
/* scene_parse.h — the scene file parser (host side: host_sim and scenec).
 *
 * Compiled once per numeric mode: the scene it builds is in that mode's
 * numbers (num.h). Every literal is read as the nearest double and turned
 * into `num` once (num_from_double); a value the mode cannot hold is an
 * input error, not a saturation. Memory comes from an arena owned by the
 * scene handle: scene_free() releases the scene and everything it points to.
 *
 * The notation is specified in docs/scene-format.md.
 *
 * Limits (anything beyond is an input error): file size SCENE_MAX_BYTES,
 * nesting depth 32, counts as in docs/scene-format.md.
 */
#ifndef SCENE_PARSE_H
#define SCENE_PARSE_H

#include <stddef.h>
#include "scene.h"

#define SCENE_MAX_BYTES (4u << 20)
/* A scene read from a FIFO (or a pipe as /dev/stdin): the longest wait for
 * data before it is refused (a FIFO no program writes to). The files a scene
 * names (images, OBJ and MTL files) must be regular files. */
#define SCENE_FIFO_TIMEOUT_MS 10000

/* What the functions below return: 0, or a negative code with one line
 * "FILE:LINE:COLUMN: error: MESSAGE" (no newline) in err. A program maps
 * them to its exit status (host_sim and scenec: 2 for SCENE_EINPUT and
 * SCENE_EIO, 1 for SCENE_ENOMEM). */
enum scene_status {
    SCENE_OK = 0,
    SCENE_EINPUT = -1,      /* not a valid scene (syntax, values, limits, a missing image file) */
    SCENE_EIO = -2,         /* the scene file cannot be opened or read */
    SCENE_ENOMEM = -3       /* out of memory */
};

/* Loads FILE. Returns 0 and sets *out, or an enum scene_status code with
 * the line in err. */
int scene_load(const char *path, struct scene **out, char *err, size_t errlen);

/* The two halves of scene_load, for a caller that parses one file several
 * times (once per numeric mode) but must read it once (a FIFO, /dev/stdin):
 * scene_read_text reads FILE (at most SCENE_MAX_BYTES + 1 bytes) into a
 * malloc'ed *text (free() it), 0 or a scene_status code; scene_parse_text
 * parses text as the content of FILE (image files relative to its
 * directory); the scene keeps no pointer into text. */
int scene_read_text(const char *path, char **text, size_t *len, char *err, size_t errlen);
int scene_parse_text(const char *path, const char *text, size_t len, struct scene **out, char *err,
                     size_t errlen);

/* The same from memory (fuzzing, tests). `name` is used in messages and as
 * the default scene name; image files cannot be referenced (no directory). */
int scene_parse_mem(const char *name, const char *text, size_t len, struct scene **out,
                    char *err, size_t errlen);

void scene_free(struct scene *s);

/* The scene's quality block (`quality { psnr = DB target = NAME }`): the
 * accuracy its methods are chosen for (tools/quality, docs/scene-format.md).
 * psnr 0: no block; target 0: none given, 1 m0plus, 2 m4f, 3 rp2040; line
 * and col: where the block starts. Of a scene this parser returned. */
struct scene_quality {
    double psnr;
    int target;
    int line, col;
};
void scene_quality(const struct scene *s, struct scene_quality *q);

/* Bits of the default path's depth buffer (near/z) a rasterized scene
 * needs (tools/scene/scene_depth.c): 32 when either
 *  - range: a 16-bit step at the farthest depth any instance reaches
 *    (far^2 / (near * 65536)) is more than 1/256 of the smallest instance's
 *    bounding radius, or
 *  - overlap: on a checked frame more than 1/4096 of the canvas's pixels
 *    show a surface with another one behind it less than two 16-bit steps
 *    of near/z away (and at least 2^-30),
 * else 16. Scenes without instances: 16. *facts (may be NULL) receives the
 * figures of both rules. -1: no memory for the overlap's grid (256 x 256
 * x 16 bytes at most, down to 32 x 32 where memory is short). */
struct scene_depth_facts {
    double far, step16, rmin;   /* the range rule's figures */
    int range_wants32;
    int overlap_checked;        /* 0: not measured (no instances, no memory) */
    int frames_checked, grid_w, grid_h;
    long close_pixels;          /* the most close pixels on one checked frame */
    int close_frame;            /* that frame */
    long close_limit;           /* more than this: 32 bits */
    double gap_min;             /* the smallest close gap seen (near/z units) */
    int overlap_wants32;
};
int scene_depth_bits(const struct scene *s, struct scene_depth_facts *facts);

/* Values given in the scene whose 0 means something else (a light's
 * intensity, a material's reflectivity or transparency, a sphere's radius,
 * an instance's scale, a rotation per frame, the ray tracer's epsilon and
 * t_min) that fixed point at NUM_FRAC frac would round to 0: meant for a
 * scene parsed in the double build (its exact values), with the format the
 * analysis chose (tools/scene/scene_format.h). 0, or -1 with one line
 * "PATH:1:1: error: ..." (no newline) in msg naming the first such value. */
int scene_given_zero(const struct scene *s, int frac, const char *path, char *msg, size_t len);

#endif
