#!/bin/sh
# SPDX-License-Identifier: MIT
# Models from OBJ files parsed on the emulated Cortex-M0+ (qemu-system-arm,
# mps2-an385, 4 MB of RAM): the benchmark image tools/bench/bench_file.c,
# which reads the scene and its model file through semihosting, loads and
# renders a torus of 8192 vertices and 16384 triangles in each image given
# (fixed point and double: the largest triangles); a PNG texture there, where
# there is no libpng, is a one-line error.
#   tests/system/test_obj_mcu.sh BENCH_FILE.elf...
set -u
[ $# -ge 1 ] || { echo "usage: test_obj_mcu.sh BENCH_FILE.elf..." >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }

# run ELF SCENE: bench_file's output in $out, qemu's exit status in $rc.
run() {
  out=$(timeout 600 qemu-system-arm -M mps2-an385 -nographic -monitor none -serial null \
    -semihosting-config "enable=on,target=native,arg=bench,arg=$2,arg=64,arg=64,arg=16,arg=1" -kernel "$1" 2>&1)
  rc=$?
}

python3 tests/support/obj_torus.py 128 64 "$tmp/torus.obj"
cp tests/data/obj/torus.scene "$tmp/"
printf 'texture { name = t file = "t.png" }\nline2d { p0 = (0, 0) p1 = (1, 1) color = (0, 0, 0) }\n' >"$tmp/png.scene"
cp tests/data/obj/tiles.png "$tmp/t.png"

for elf in "$@"; do
  mode=$(basename "$(dirname "$elf")")
  run "$elf" "$tmp/torus.scene"
  if [ "$rc" -eq 0 ] && printf '%s\n' "$out" | grep -q '^RESULT '; then
    pass "obj_16384_triangles_on_m0plus_$mode"
  else
    fail "obj_16384_triangles_on_m0plus_$mode" "exit $rc: $(printf '%s' "$out" | head -c 300)"
  fi
  run "$elf" "$tmp/png.scene"
  if [ "$rc" -ne 0 ] && printf '%s\n' "$out" | grep -q "^ERROR $tmp/png.scene:1:27: error: '$tmp/t.png': PNG textures need the host build"; then
    pass "png_needs_the_host_build_$mode"
  else
    fail "png_needs_the_host_build_$mode" "exit $rc: $(printf '%s' "$out" | head -c 300)"
  fi
done
