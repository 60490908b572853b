#!/bin/sh
# SPDX-License-Identifier: MIT
# The benchmark meshes of firmware/scenes/bench/ are what tools/bench/gen_mesh.py
# makes: regenerated here and compared byte for byte.
#   tests/system/test_meshes.sh
set -u
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
check() {   # name, generator arguments
  name=$1
  shift
  if ! python3 tools/bench/gen_mesh.py "$@" "$t/$name" 2>"$t/err"; then
    echo "FAIL mesh_current_$name: gen_mesh.py failed: $(head -n 1 "$t/err")"
  elif cmp -s "$t/$name" "firmware/scenes/bench/$name"; then
    echo "PASS mesh_current_$name"
  else
    echo "FAIL mesh_current_$name: firmware/scenes/bench/$name is not what tools/bench/gen_mesh.py $* makes"
  fi
}
check knot-4k.obj 64 32
check knot-16k.obj --no-uv 128 64
exit 0
