/* SPDX-License-Identifier: MIT */
/* file_id.h — which file a path names, for the host tools' checks that an
 * output does not land on an input or on another output (host_sim,
 * scenec). POSIX: stat and realpath. */
#ifndef FILE_ID_H
#define FILE_ID_H

#include <stddef.h>

/* path with its directory resolved (realpath) into out: 0, or -1 (the
 * directory does not resolve, or out is too short). */
int file_norm_path(const char *path, char *out, size_t len);

/* 1 if a and b name the same file: the same device and inode when either
 * exists (both must), else the same path once their directories are
 * resolved. */
int file_same(const char *a, const char *b);

#endif
