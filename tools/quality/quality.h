/* SPDX-License-Identifier: MIT */
/* quality.h — methods chosen for an accuracy target (docs/scene-format.md,
 * "quality").
 *
 * The user says how accurate the picture must be (PSNR in dB against the
 * double build's exact render) on which target (m0plus, m4f, rp2040); the
 * choice is the cheapest of the methods `make charts` measures that meets it:
 *   candidates  the option sets of the cost model (tools/quality/cost_model.def,
 *               written by tools/quality/cost_model.py from the lab's rows) for
 *               the scene's class (ray tracer; rasterizer: textured, with
 *               chapter 15's shadows, or lit), less those that would change a
 *               key the scene sets itself (kept as the user wrote it);
 *   cost        predicted: the class's cost per unit of work on the target
 *               times the scene's work (host render of the scene as written:
 *               pixels written) times the method's factor against the
 *               class's base method (a textured scene shaded otherwise than
 *               its class's lab scenes: the lit class's per-pixel lighting
 *               added to each unit of work, or taken out); the ray tracer's
 *               classes (QUALITY_OWN_WORK): the class's cost per unit of work
 *               times the candidate's own work (its host render's rays,
 *               primary, reflected and shadow, times objects) plus the
 *               method's work beyond its rays a pixel times the pixels;
 *   accuracy    measured: each candidate rendered on the host in the image's
 *               numeric mode against the double build with the exact methods
 *               (perspective_step 1, exact lighting, trilinear filtering where
 *               the scene does not set a filter, one ray a pixel), over up to
 *               16 frames (all of a scene's frames up to 16, else 16 evenly
 *               spaced, the first and the last among them): the minimum PSNR.
 * Candidates are tried cheapest first (the ray tracer's all rendered first,
 * for their work); the first that meets the target on every frame checked
 * is the choice. Host programs only (allocates).
 */
#ifndef QUALITY_H
#define QUALITY_H

#include <stddef.h>
#include <stdio.h>

enum { QUALITY_M0PLUS = 1,
       QUALITY_M4F = 2,
       QUALITY_RP2040 = 3 };

/* "m0plus", "m4f", "rp2040" for 1..3; NULL otherwise */
const char *quality_target_name(int target);
/* 1..3 for a target's name; 0 otherwise */
int quality_target_of(const char *name);
/* A PSNR in dB as the command line gives it (a number in 1 .. 200): 0 with
 * *db set, -1 otherwise. */
int quality_parse_psnr(const char *s, double *db);

struct quality_request {
    const char *path; /* the scene file, for messages */
    const char *text; /* its text, len bytes */
    size_t len;
    unsigned width, height, strip_rows;
    const char *numeric; /* the image's: "fixed" (the scene's own format), "float" or "double" */
    int target;          /* QUALITY_* */
    double min_psnr;     /* dB */
    int line, col;       /* the quality block's place (0: the command line, --min-psnr), for messages */
    FILE *report;        /* the report's lines (NULL: none) */
};

struct quality_choice {
    char *text; /* the scene text with the chosen options (malloc; quality_free) */
    size_t len;
    char options[256];        /* the options set, "KEY=VALUE ..." ("" : the scene as written) */
    double predicted;         /* cost a frame on the target: instructions (m0plus, m4f) or cycles (rp2040) */
    double psnr;              /* measured, the minimum over the frames checked (INFINITY: identical) */
    int num_frac;             /* fixed point: the format rendered in; 0 otherwise */
    int candidates, rendered; /* candidates considered, and rendered before the choice */
};

/* What quality_choose returns besides 0. */
enum { QUALITY_EINPUT = 2,
       QUALITY_EINTERNAL = 1 };

/* Chooses (above). 0 with *ch filled; QUALITY_EINPUT with one line in err
 * (no candidate meets the target: the best one named; no cost model for the
 * scene); QUALITY_EINTERNAL (out of memory, a render that fails). */
int quality_choose(const struct quality_request *rq, struct quality_choice *ch, char *err, size_t errlen);
void quality_free(struct quality_choice *ch);

/* The scene text with one option KEY=VALUE (in the renderer block, added
 * when the scene has none) or BLOCK.KEY=VALUE (in every top-level BLOCK
 * block) set, as tools/charts/scenetext.py: malloc'd, NULL on a malformed
 * option or a missing BLOCK block (or out of memory). */
char *quality_set_option(const char *text, size_t len, const char *renderer, const char *opt, size_t *outlen);

#endif
