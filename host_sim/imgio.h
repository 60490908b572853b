/* SPDX-License-Identifier: MIT */
/* imgio.h — host_sim's output files, written atomically, all or none.
 *
 * Every writer creates a temporary file in the destination's directory,
 * writes it completely and fsyncs it; img_commit renames every one of them
 * over its destination once the whole run has succeeded, img_discard (a
 * failed run) removes them. A destination is thus either the old file (or
 * absent) or the complete new one, never half-written, and a failed run
 * leaves every file as it was before it.
 *
 * A destination that is a FIFO or a character device (/dev/stdout) is
 * written in place instead; a FIFO that no program opens for reading within
 * IMG_FIFO_TIMEOUT_MS is refused (exit 2) instead of waiting forever. Signals that can be caught remove the temporary
 * file; SIGPIPE and SIGXFSZ are ignored so that the write fails with a
 * message (a FIFO's reader gone, `ulimit -f`).
 *
 * Return values follow host_sim's exit codes: 0 success; 2 the destination
 * cannot be created (missing or non-writable directory, bad name: a usage
 * error); 1 any other failure (short write, fsync, rename, libpng). One line
 * naming the file and the reason is written into err (no newline).
 */
#ifndef HOST_SIM_IMGIO_H
#define HOST_SIM_IMGIO_H

#include <stddef.h>
#include <stdint.h>

#define IMG_FIFO_TIMEOUT_MS 10000

/* Image formats of --out, chosen by the file name's extension. */
enum img_format { IMG_NONE = 0, IMG_PNG, IMG_PPM };

/* IMG_PNG for *.png, IMG_PPM for *.ppm (case-insensitive), IMG_NONE otherwise. */
enum img_format img_format_of(const char *path);

/* RGB565 (native-endian uint16, row-major, top row first, `stride` pixels a
 * row) as 8-bit RGB by bit replication: r8 = r5<<3 | r5>>2, g8 = g6<<2 | g6>>4. */
int img_write_565(const char *path, enum img_format fmt, const uint16_t *px,
                  unsigned w, unsigned h, size_t stride, char *err, size_t errlen);

/* The same pixels as raw RGB565, little-endian uint16, row-major, top row first. */
int img_write_raw565(const char *path, const uint16_t *px, unsigned w, unsigned h,
                     size_t stride, char *err, size_t errlen);

/* 8-bit RGB triples (3*w*h bytes, row-major) as binary PPM (P6). */
int img_write_ppm888(const char *path, const uint8_t *rgb, unsigned w, unsigned h,
                     char *err, size_t errlen);

/* Tests: img_write_raw565 sends SIGTERM to the process after its first row,
 * with the temporary file half-written. */
extern int img_fault_signal_in_write;

/* Renames every output written so far into place: 0, or 1 with the line in
 * err (the outputs not yet renamed are then removed). */
int img_commit(char *err, size_t errlen);

/* Removes every output written so far (a failed run: the files that were
 * there before it stay as they were). */
void img_discard(void);

/* 0 if a file could be created next to `path` (its directory exists and is
 * writable), else 2 with a message: lets host_sim refuse before rendering. */
int img_check_dest(const char *path, char *err, size_t errlen);

/* Expands one RGB565 pixel to 8-bit r, g, b (bit replication). */
static inline void img_565_to_888(uint16_t p, uint8_t out[3])
{
    unsigned r5 = (p >> 11) & 31u, g6 = (p >> 5) & 63u, b5 = p & 31u;
    out[0] = (uint8_t)(r5 << 3 | r5 >> 2);
    out[1] = (uint8_t)(g6 << 2 | g6 >> 4);
    out[2] = (uint8_t)(b5 << 3 | b5 >> 2);
}

#endif
