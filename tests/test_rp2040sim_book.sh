#!/bin/sh
# The emulated Pico shows the book scenes exactly as host_sim renders them:
# the single-core book image (raytracer-02, then raster-11, one frame each)
# runs in rp2040js and each frame the emulated ST7789 shows must equal
#   host_sim --scene S --size 240x240 --numeric fixed --out-raw
# bit for bit. ~45 s of emulation (1.6 G cycles).
# usage: test_rp2040sim_book.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
elf=$b/firmware/pico/cgfs-book-1core.elf
scenes="book/raytracer-02 book/raster-11"
n=$(echo $scenes | wc -w)
if ! timeout 600 node tools/rp2040sim/rp2040sim.js --image "$elf" --frames "$n" --out-dir "$t/pico" \
     --json >"$t/json" 2>"$t/err"; then
  echo "FAIL rp2040sim_book_runs: $(tail -n 1 "$t/err")"
  exit 1
fi
echo "PASS rp2040sim_book_runs"
i=0
for s in $scenes; do
  name=rp2040sim_equals_host_sim_$(basename "$s")
  if ! sed -n "$((i + 1))p" "$t/json" | grep -q "\"what\":\"scene:$s\",\"frame\":0,.*\"cycles\":[1-9]"; then
    echo "FAIL $name: frame $i is not frame 0 of $s: $(sed -n "$((i + 1))p" "$t/json")"
  elif ! "$b/host_sim" --scene "firmware/scenes/$s.scene" --size 240x240 --numeric fixed \
       --out-raw "$t/host-$i.raw" >/dev/null 2>"$t/herr"; then
    echo "FAIL $name: host_sim: $(tail -n 1 "$t/herr")"
  elif cmp -s "$t/host-$i.raw" "$t/pico/frame-$i.raw"; then
    echo "PASS $name"
  else
    echo "FAIL $name: $(cmp "$t/host-$i.raw" "$t/pico/frame-$i.raw" 2>&1 | head -n 1)"
  fi
  i=$((i + 1))
done
