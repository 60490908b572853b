#!/bin/sh
# SPDX-License-Identifier: MIT
# The README's pictures: a few scenes rendered exactly as `make run` renders
# them (tools/run_scenes.sh: host_sim on the emulated ST7789 at 240x240, fixed
# point in the scene's own format), each written as OUT/<name>.png; and
# docs/firmware.md's: the bring-up pattern as cgfs-check shows it (the
# board's clocks, 62.5 MHz SPI and 133 MHz clk_sys) and with each wrong
# driver setting of host_sim --miswire, OUT/check.png and OUT/check-<what>.png.
#   tools/pictures.sh HOST_SIM OUT
# `make pictures` writes them into docs/images/; tests/system/test_pictures.py
# renders them again and compares the pixels with the committed files.
# Exit status 0, or 1 naming the scene that failed.
set -u
host_sim=${1:?usage: pictures.sh HOST_SIM OUT}
out=${2:?usage: pictures.sh HOST_SIM OUT}
out=${out%/}

# name:scene (under firmware/scenes/, without .scene)
PICTURES="raytracer-05:book/raytracer-05 raster-11:book/raster-11 spinning-crate:demo/spinning-crate
knot-4k-textured:bench/knot-4k-textured"

mkdir -p "$out" || exit 1
for p in $PICTURES; do
  name=${p%%:*}
  scene=firmware/scenes/${p#*:}.scene
  if ! "$host_sim" --scene "$scene" --panel st7789 --numeric fixed --out "$out/$name.png"; then
    echo "pictures.sh: $scene failed" >&2
    exit 1
  fi
  echo "$scene -> $out/$name.png"
done
for what in "" offset bgr invert rotation byteswap; do
  name=check${what:+-$what}
  if ! "$host_sim" --pattern check --panel st7789 --board-clocks 62500000,133000000 ${what:+--miswire $what} \
       --out "$out/$name.png"; then
    echo "pictures.sh: the pattern${what:+ with --miswire $what} failed" >&2
    exit 1
  fi
  echo "--pattern check${what:+ --miswire $what} -> $out/$name.png"
done
