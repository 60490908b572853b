#!/bin/sh
# SPDX-License-Identifier: MIT
# A core built without some renderer features (firmware/core/scene_features.def):
# tests/unit/test_features.c and the core, compiled for this host with
# FW_FEATURE_RAYTRACER 0 and FW_FEATURE_RAS_FAST 0 (ASan and UBSan), refuse
# exactly the scenes that need one of them and render the others; and the
# feature header of a scene set is the union of its scenes' lines
# (tools/scenec/features.sh). usage: test_features.sh
set -u
cc=${CC:-cc}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if $cc -std=c11 -D_POSIX_C_SOURCE=200809L -O1 -g -Wall -Wextra -Werror -pedantic -fsanitize=address,undefined \
     -fno-sanitize-recover=all -DNUM_MODE=1 -DNUM_FRAC=16 -DFW_FEATURE_RAYTRACER=0 -DFW_FEATURE_RAS_FAST=0 \
     -I. -Ifirmware/core -Itools/scene -Itests/support -o "$t/test_features" tests/unit/test_features.c \
     tools/scene/scene_parse.c tools/scene/scene_depth.c $(find firmware/core -name '*.c' | sort) -lm 2>"$t/err"; then
  echo "PASS features_core_builds_without_some"
  "$t/test_features" firmware/scenes/bench/cube-flat.scene=1 firmware/scenes/bench/phong.scene=1 \
    firmware/scenes/book/raytracer-02.scene=1 firmware/scenes/book/raster-06.scene=0 \
    firmware/scenes/book/raster-01.scene=0 firmware/scenes/demo/ch15-shadow-volume.scene=1
else
  echo "FAIL features_core_builds_without_some: $(head -n 3 "$t/err")"
fi
# the union of two scenes' lines, 0 where neither needs a feature
printf '#define SCENE_A_FEATURE_RASTER 1\n#define SCENE_A_FEATURE_RAS_FAST 0\n#define SCENE_A_FEATURE_RAYTRACER 0\n' >"$t/a.h"
printf '#define SCENE_B_FEATURE_RASTER 0\n#define SCENE_B_FEATURE_RAS_FAST 1\n#define SCENE_B_FEATURE_RAYTRACER 0\n' >"$t/b.h"
if tools/scenec/features.sh "$t/f.h" "$t/a.h" "$t/b.h" && grep -q '^#define FW_FEATURE_RASTER 1$' "$t/f.h" &&
   grep -q '^#define FW_FEATURE_RAS_FAST 1$' "$t/f.h" && grep -q '^#define FW_FEATURE_RAYTRACER 0$' "$t/f.h"; then
  echo "PASS features_union_of_the_scenes"
else
  echo "FAIL features_union_of_the_scenes: $(cat "$t/f.h" 2>&1)"
fi
# a header without the lines: one line, exit 2, no output
printf '#define SCENE_C_NUM_FRAC 16\n' >"$t/c.h"
tools/scenec/features.sh "$t/g.h" "$t/a.h" "$t/c.h" 2>"$t/gerr"; rc=$?
if [ "$rc" -eq 2 ] && [ ! -e "$t/g.h" ] && [ "$(wc -l <"$t/gerr")" -eq 1 ]; then
  echo "PASS features_refuses_a_header_without_them"
else
  echo "FAIL features_refuses_a_header_without_them: rc $rc, $(cat "$t/gerr")"
fi
