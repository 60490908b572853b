#!/bin/sh
# SPDX-License-Identifier: MIT
# The emulated Pico shows the book scenes exactly as host_sim renders them:
# the single-core book image (raytracer-02, then raster-11, one frame each)
# runs in rp2040js and each frame the emulated ST7789 shows must equal
#   host_sim --scene S --size 240x240 --numeric fixed --num-frac F --out-raw
# bit for bit. F is the image's format: its core is built at the coarsest
# NUM_FRAC among the scenes it links (fw_book_num_frac.h, mk/firmware.mk), so
# a scene whose own format is finer (raster-11: Q12.19) is rendered by the
# image, and here, at that coarser one. The --json row's frame_checksum
# must be host_sim --stats' checksum of that frame. ~45 s of emulation (1.6 G cycles).
# usage: test_rp2040sim_book.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
elf=$b/firmware/pico/cgfs-book-1core.elf
scenes="book/raytracer-02 book/raster-11"
n=$(echo $scenes | wc -w)
frac=$(sed -n 's/^#define NUM_FRAC \([0-9][0-9]*\)$/\1/p' "$b/firmware/scenes/fw_book_num_frac.h" 2>/dev/null)
[ -n "$frac" ] || frac=16
echo "# the book image's format: NUM_FRAC $frac"
if ! timeout 600 node tools/rp2040sim/rp2040sim.js --image "$elf" --frames "$n" --out-dir "$t/pico" \
     --json >"$t/json" 2>"$t/err"; then
  echo "FAIL rp2040sim_book_runs: $(tail -n 1 "$t/err")"
  exit 1
fi
echo "PASS rp2040sim_book_runs"
i=0
for s in $scenes; do
  name=rp2040sim_equals_host_sim_$(basename "$s")
  if ! sed -n "$((i + 1))p" "$t/json" | grep "\"what\":\"scene:$s\"" | grep "\"frame\":0," | grep -q "\"cycles\":[1-9]"; then
    echo "FAIL $name: frame $i is not frame 0 of $s: $(sed -n "$((i + 1))p" "$t/json")"
  elif ! "$b/host_sim" --scene "firmware/scenes/$s.scene" --size 240x240 --numeric fixed \
       --num-frac "$frac" --out-raw "$t/host-$i.raw" >/dev/null 2>"$t/herr"; then
    echo "FAIL $name: host_sim: $(tail -n 1 "$t/herr")"
  elif cmp -s "$t/host-$i.raw" "$t/pico/frame-$i.raw"; then
    echo "PASS $name"
  else
    echo "FAIL $name: $(cmp "$t/host-$i.raw" "$t/pico/frame-$i.raw" 2>&1 | head -n 1)"
  fi
  # the row's frame_checksum (tools/bench/accuracy.py measures board rows by it) is host_sim's
  psum=$(sed -n "$((i + 1))p" "$t/json" | sed -n 's/.*"frame_checksum":\([0-9][0-9]*\).*/\1/p')
  hsum=$("$b/host_sim" --scene "firmware/scenes/$s.scene" --size 240x240 --numeric fixed --num-frac "$frac" \
         --panel none --stats 2>/dev/null | sed -n 's/.*"checksum":\([0-9][0-9]*\).*/\1/p' | tail -n 1)
  if [ -n "$psum" ] && [ "$psum" = "$hsum" ]; then
    echo "PASS rp2040sim_frame_checksum_$(basename "$s")"
  else
    echo "FAIL rp2040sim_frame_checksum_$(basename "$s"): rp2040sim '$psum', host_sim '$hsum'"
  fi
  i=$((i + 1))
done
