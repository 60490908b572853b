#!/bin/sh
# SPDX-License-Identifier: MIT
# The board's panel options in the emulator: the ILI9341 320x240 image
# (cgfs-ili9341, FW_PANEL=panel_ili9341_320x240) shows on the emulated
# ILI9341 module exactly the host's 320x240 render of the firmware's scene
# table, and the ST7789 image built with FW_ROTATION=2 (cgfs-rot2) shows the
# 240x240 render turned by 180 degrees, pixel for pixel.
# usage: test_rp2040sim_panels.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
sim=tools/rp2040sim/rp2040sim.js
"$b/fw_host_ref" 0 320 240 8 "$t/h320.raw" && "$b/fw_host_ref" 0 240 240 8 "$t/h240.raw" ||
  { echo "FAIL rp2040sim_panels: fw_host_ref failed"; exit 1; }
if ! timeout 120 node $sim --image "$b/firmware/pico/cgfs-ili9341.elf" --panel ili9341_320x240 --frames 1 \
     --json --out-raw "$t/ili.raw" >"$t/ili.json" 2>"$t/err"; then
  echo "FAIL rp2040sim_ili9341_320x240_equals_host: $(tail -n 1 "$t/err")"
elif ! grep -q '"width":320,"height":240' "$t/ili.json"; then
  echo "FAIL rp2040sim_ili9341_320x240_equals_host: $(cat "$t/ili.json")"
elif cmp -s "$t/h320.raw" "$t/ili.raw"; then
  echo "PASS rp2040sim_ili9341_320x240_equals_host"
else
  echo "FAIL rp2040sim_ili9341_320x240_equals_host: $(cmp "$t/h320.raw" "$t/ili.raw" 2>&1 | head -n 1)"
fi
if ! timeout 120 node $sim --image "$b/firmware/pico/cgfs-rot2.elf" --frames 1 --out-raw "$t/rot.raw" \
     >/dev/null 2>"$t/err"; then
  echo "FAIL rp2040sim_st7789_rotation_2_equals_host_turned: $(tail -n 1 "$t/err")"
elif python3 -c "
import sys
a = open(sys.argv[1], 'rb').read(); h = open(sys.argv[2], 'rb').read()
px = [a[i:i + 2] for i in range(0, len(a), 2)]
sys.exit(0 if b''.join(px[::-1]) == h else 1)" "$t/rot.raw" "$t/h240.raw"; then
  echo "PASS rp2040sim_st7789_rotation_2_equals_host_turned"
else
  echo "FAIL rp2040sim_st7789_rotation_2_equals_host_turned: the glass is not the host's image turned"
fi
