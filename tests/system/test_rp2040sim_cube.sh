#!/bin/sh
# SPDX-License-Identifier: MIT
# The emulated Pico shows the cube scenes (small3dlib's workload,
# firmware/scenes/bench) as host_sim renders them. These are the scenes that
# run the rasterizer's fast span loops, which the Pico images execute from
# SRAM (RAS_RAM_TEXT, mk/firmware.mk); the book scenes do not reach them.
# The single-core cube image (N frames of each scene) runs in rp2040js:
#   - frame 0 of each scene equals
#     host_sim --scene S --size 240x240 --numeric fixed --num-frac F --out-raw
#     bit for bit (F: the image's format, fw_cube_num_frac.h);
#   - its last frame (N-1) equals host_sim's frame N-1 below the first three
#     8-row strips (the firmware draws "X.Y fps" over rows 2-19 of every frame
#     after the first);
#   - the --average line of each scene: N frames, cycles within [min, max].
# ~10 s of emulation (0.13 G cycles). IMAGE, PANEL and SIZE run another
# image of the cube scenes: cgfs-cube-ili9341-1core ili9341_320x240 320x240,
# the ILI9341 module in landscape (its scenes compiled at 320x240, format in
# fw_cube320_num_frac.h), cgfs-cube-st7735-1core st7735_128x160 128x160, the
# ST7735S 1.8" module (fw_cube128_num_frac.h), or cgfs-cube-ssd1351-1core
# ssd1351_128x128 128x128, the SSD1351 OLED (fw_cube128sq_num_frac.h), or
# cgfs-cube-gc9a01-1core gc9a01_240x240 240x240, the GC9A01 round module (the
# scenes of the ST7789 image; outside the circle the glass shows black, in the
# image as in host_sim's), or cgfs-cube-ili9488-1core ili9488_320x480 320x480,
# the ILI9488 (fw_cube480_num_frac.h; 18-bit pixels); host_sim renders on PANEL too; the cases' names
# then carry "_<SIZE>" ("_<PANEL>" at 240x240).
# usage: test_rp2040sim_cube.sh BUILD_DIR [FRAMES_PER_SCENE [IMAGE PANEL SIZE]]
set -u
b=${1:-build}
n=${2:-10}
image=${3:-cgfs-cube-1core}
panel=${4:-st7789_240x240}
size=${5:-240x240}
width=${size%x*}
set=cube
tag=_$size
case $size in
240x240) tag= ; [ "$panel" = st7789_240x240 ] || tag=_$panel ;;
128x160) set=cube128 ;;
128x128) set=cube128sq ;;
320x480) set=cube480 ;;
*) set=cube320 ;;
esac
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
elf=$b/firmware/pico/$image.elf
scenes="bench/cube-textured bench/cube-gouraud bench/cube-flat"
ns=$(echo $scenes | wc -w)
frac=$(sed -n 's/^#define NUM_FRAC \([0-9][0-9]*\)$/\1/p' "$b/firmware/scenes/fw_${set}_num_frac.h" 2>/dev/null)
[ -n "$frac" ] || { echo "FAIL rp2040sim_cube${tag}_format: no NUM_FRAC in $b/firmware/scenes/fw_${set}_num_frac.h"; exit 1; }
echo "# the cube image's format: NUM_FRAC $frac, $n frames per scene"
if ! timeout 300 node tools/rp2040sim/rp2040sim.js --image "$elf" --panel "$panel" --frames $((ns * n)) --out-dir "$t/pico" \
     --json >"$t/json" 2>"$t/err"; then
  echo "FAIL rp2040sim_cube${tag}_runs: $(tail -n 1 "$t/err")"
  exit 1
fi
echo "PASS rp2040sim_cube${tag}_runs"
skip=$((3 * 8 * width * 2))
i=0
for s in $scenes; do
  id=$(basename "$s")
  k=$((i * n))
  last=$((k + n - 1))
  if ! sed -n "$((k + 1))p" "$t/json" | grep "\"what\":\"scene:$s\"" | grep "\"frame\":0," | grep -q "\"cycles\":[1-9]"; then
    echo "FAIL rp2040sim_cube${tag}_equals_host_sim_$id: frame $k is not frame 0 of $s: $(sed -n "$((k + 1))p" "$t/json")"
  elif ! "$b/host_sim" --scene "firmware/scenes/$s.scene" --panel "$panel" --size "$size" --numeric fixed \
       --num-frac "$frac" --out-raw "$t/host0.raw" >/dev/null 2>"$t/herr"; then
    echo "FAIL rp2040sim_cube${tag}_equals_host_sim_$id: host_sim: $(tail -n 1 "$t/herr")"
  elif cmp -s "$t/host0.raw" "$t/pico/frame-$k.raw"; then
    echo "PASS rp2040sim_cube${tag}_equals_host_sim_$id"
  else
    echo "FAIL rp2040sim_cube${tag}_equals_host_sim_$id: $(cmp "$t/host0.raw" "$t/pico/frame-$k.raw" 2>&1 | head -n 1)"
  fi
  if [ "$n" -gt 1 ]; then
    if ! sed -n "$((last + 1))p" "$t/json" | grep "\"what\":\"scene:$s\"" | grep -q "\"frame\":$((n - 1)),"; then
      echo "FAIL rp2040sim_cube${tag}_last_frame_$id: frame $last is not frame $((n - 1)) of $s"
    elif ! "$b/host_sim" --scene "firmware/scenes/$s.scene" --panel "$panel" --size "$size" --numeric fixed \
         --num-frac "$frac" --frames "$n" --out-raw "$t/hostn.raw" >/dev/null 2>"$t/herr"; then
      echo "FAIL rp2040sim_cube${tag}_last_frame_$id: host_sim: $(tail -n 1 "$t/herr")"
    elif cmp -s -i "$skip" "$t/hostn.raw" "$t/pico/frame-$last.raw"; then
      echo "PASS rp2040sim_cube${tag}_last_frame_$id"
    else
      echo "FAIL rp2040sim_cube${tag}_last_frame_$id: $(cmp -i "$skip" "$t/hostn.raw" "$t/pico/frame-$last.raw" 2>&1 | head -n 1)"
    fi
  fi
  i=$((i + 1))
done
# --average: one line per scene, the mean of its frames
timeout 300 node tools/rp2040sim/rp2040sim.js --image "$elf" --panel "$panel" --frames $((ns * n)) --json --average \
  >"$t/avg" 2>"$t/err"
if [ "$(wc -l <"$t/avg")" -eq "$ns" ] && python3 - "$t/json" "$t/avg" "$n" <<'EOF'
import json, sys
frames = [json.loads(l) for l in open(sys.argv[1])]
avg = [json.loads(l) for l in open(sys.argv[2])]
n = int(sys.argv[3])
for i, a in enumerate(avg):
    fs = frames[i * n:(i + 1) * n]
    c = [f["cycles"] for f in fs]
    assert a["what"] == fs[0]["what"] and a["frames"] == n and a["cores"] == 1, a
    assert abs(a["cycles"] - sum(c) / n) <= 1 and a["cycles_min"] == min(c) and a["cycles_max"] == max(c), (a, c)
EOF
then
  echo "PASS rp2040sim${tag}_average_is_the_mean_of_each_scene"
else
  echo "FAIL rp2040sim${tag}_average_is_the_mean_of_each_scene: $(cat "$t/avg") $(tail -n 1 "$t/err")"
fi
