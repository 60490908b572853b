#!/bin/sh
# SPDX-License-Identifier: MIT
# The board's panel options in the emulator: the ILI9341 320x240 image
# (cgfs-ili9341, FW_PANEL=panel_ili9341_320x240) shows on the emulated
# ILI9341 module exactly the host's 320x240 render of the firmware's scene
# table, and the ST7789 image built with FW_ROTATION=2 (cgfs-rot2) shows the
# 240x240 render turned by 180 degrees, pixel for pixel; the book scenes on
# the GC9A01, SSD1351 and ILI9488 equal host_sim's there (below). SPI0 runs
# at the fastest clock not above each controller's rated write clock (the
# boot line's spi_hz: 8.93 MHz for the ILI9341, 62.5 MHz for the ST7789VW).
# usage: test_rp2040sim_panels.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
sim=tools/rp2040sim/rp2040sim.js
"$b/fw_host_ref" 0 320 240 8 "$t/h320.raw" && "$b/fw_host_ref" 0 240 240 8 "$t/h240.raw" ||
  { echo "FAIL rp2040sim_panels: fw_host_ref failed"; exit 1; }
if ! timeout 120 node $sim --image "$b/firmware/pico/cgfs-ili9341.elf" --panel ili9341_320x240 --frames 1 \
     --json --uart --out-raw "$t/ili.raw" >"$t/ili.json" 2>"$t/err"; then
  echo "FAIL rp2040sim_ili9341_320x240_equals_host: $(tail -n 1 "$t/err")"
elif ! grep -q '"width":320,"height":240' "$t/ili.json"; then
  echo "FAIL rp2040sim_ili9341_320x240_equals_host: $(cat "$t/ili.json")"
elif cmp -s "$t/h320.raw" "$t/ili.raw"; then
  echo "PASS rp2040sim_ili9341_320x240_equals_host"
else
  echo "FAIL rp2040sim_ili9341_320x240_equals_host: $(cmp "$t/h320.raw" "$t/ili.raw" 2>&1 | head -n 1)"
fi
if grep -q '^boot .* spi_hz=8928571 ' "$t/err"; then
  echo "PASS rp2040sim_ili9341_spi_at_rated_clock_8_93mhz"
else
  echo "FAIL rp2040sim_ili9341_spi_at_rated_clock_8_93mhz: $(grep '^boot' "$t/err")"
fi
if ! timeout 120 node $sim --image "$b/firmware/pico/cgfs-rot2.elf" --frames 1 --out-raw "$t/rot.raw" \
     --uart >/dev/null 2>"$t/err"; then
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
if grep -q '^boot .* spi_hz=62500000 ' "$t/err"; then
  echo "PASS rp2040sim_st7789vw_spi_at_rated_clock_62_5mhz"
else
  echo "FAIL rp2040sim_st7789vw_spi_at_rated_clock_62_5mhz: $(grep '^boot' "$t/err")"
fi
# The book scenes on the other panels: on the GC9A01 round module
# (cgfs-book-gc9a01, FW_ROUND_GLASS: the ray tracer leaves out the pixels
# outside the glass's circle) they show what host_sim shows on the same
# panel, which traces every pixel: the skipped pixels are the ones the glass
# does not have; on the SSD1351 (128x128, not DCS) and the ILI9488 (320x480,
# three bytes a pixel) likewise, compiled at their sizes. ~70 s.
book_on() {   # IMAGE MODULE SET
  frac=$(sed -n 's/^#define NUM_FRAC \([0-9][0-9]*\)$/\1/p' "$b/firmware/scenes/fw_$3_num_frac.h" 2>/dev/null)
  name=rp2040sim_${2%%_*}_book_equals_host_sim
  if [ -z "$frac" ]; then
    echo "FAIL $name: no NUM_FRAC in $b/firmware/scenes/fw_$3_num_frac.h"; return
  fi
  rm -rf "$t/bk"
  if ! timeout 300 node $sim --image "$b/firmware/pico/$1.elf" --panel "$2" --frames 2 \
       --json --out-dir "$t/bk" >"$t/bk.json" 2>"$t/err"; then
    echo "FAIL $name: $(tail -n 1 "$t/err")"; return
  fi
  k=0 bad=
  for s in book/raytracer-02 book/raster-11; do
    if ! "$b/host_sim" --scene "firmware/scenes/$s.scene" --panel "$2" --numeric fixed --num-frac "$frac" \
         --out-raw "$t/bh.raw" >/dev/null 2>"$t/herr"; then
      bad="$bad [$s: host_sim: $(tail -n 1 "$t/herr")]"
    elif ! sed -n "$((k + 1))p" "$t/bk.json" | grep -q "\"what\":\"scene:$s\""; then
      bad="$bad [frame $k is not $s]"
    elif ! cmp -s "$t/bh.raw" "$t/bk/frame-$k.raw"; then
      bad="$bad [$s: $(cmp "$t/bh.raw" "$t/bk/frame-$k.raw" 2>&1 | head -n 1)]"
    fi
    k=$((k + 1))
  done
  if [ -z "$bad" ]; then echo "PASS $name"; else echo "FAIL $name:$bad"; fi
}
book_on cgfs-book-gc9a01 gc9a01_240x240 book
book_on cgfs-book-ssd1351 ssd1351_128x128 book128sq
book_on cgfs-book-ili9488 ili9488_320x480 book480
