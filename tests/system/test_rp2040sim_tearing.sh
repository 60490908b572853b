#!/bin/sh
# SPDX-License-Identifier: MIT
# Tearing on the emulated board (tools/rp2040sim: emu_panel.js scans the
# glass at the controller's frame rate and marks a frame torn when its writes
# showed over more than one pass):
#   cgfs-cube (no TE line): frames go out faster than the ST7789's 60 Hz
#     scan and some are torn;
#   cgfs-cube-te with the panel's TE output wired (--te-pin 22, the image's
#     RP2040_PIN_TE): the firmware turns TE on and starts each frame's
#     writes in the vertical blank: none torn, each scene at the scan rate,
#     and the frames are still the host's bit for bit;
#   cgfs-cube-te with nothing on the pin: one warning line, then frames as
#     without TE.
# usage: test_rp2040sim_tearing.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
sim=tools/rp2040sim/rp2040sim.js
frac=$(sed -n 's/^#define NUM_FRAC \([0-9][0-9]*\)$/\1/p' "$b/firmware/scenes/fw_cube_num_frac.h" 2>/dev/null)
[ -n "$frac" ] || { echo "FAIL rp2040sim_tearing: no NUM_FRAC in fw_cube_num_frac.h"; exit 1; }
"$b/host_sim" --scene firmware/scenes/bench/cube-gouraud.scene --size 240x240 --numeric fixed --num-frac "$frac" \
  --out-raw "$t/gouraud.raw" >/dev/null 2>"$t/herr" || { echo "FAIL rp2040sim_tearing: host_sim: $(tail -n 1 "$t/herr")"; exit 1; }
torn() { grep -o '"torn_frames":[0-9]*' "$1" | sed 's/.*://' | awk '{ s += $1 } END { print s + 0 }'; }

if timeout 300 node $sim --image "$b/firmware/pico/cgfs-cube.elf" --frames 30 --json --average >"$t/free.json" 2>"$t/free.err"; then
  n=$(torn "$t/free.json")
  [ "$n" -gt 0 ] && echo "PASS rp2040sim_tearing_without_te ($n of 30 torn; shown whole a second: $(grep -o '"shown_fps":[0-9.]*' "$t/free.json" | sed 's/.*://' | tr '\n' ' '))" ||
    echo "FAIL rp2040sim_tearing_without_te: no frame torn at $(grep -o '"fps":[0-9.]*' "$t/free.json" | tr '\n' ' ')"
else
  echo "FAIL rp2040sim_tearing_without_te: $(tail -n 1 "$t/free.err")"
fi

if timeout 300 node $sim --image "$b/firmware/pico/cgfs-cube-te.elf" --te-pin 22 --frames 30 --json --average \
     >"$t/te.json" 2>"$t/te.err" &&
   timeout 300 node $sim --image "$b/firmware/pico/cgfs-cube-te.elf" --te-pin 22 --frames 11 --out-dir "$t/te" \
     >/dev/null 2>>"$t/te.err"; then
  n=$(torn "$t/te.json")
  fast=$(grep -o '"fps":[0-9.]*' "$t/te.json" | sed 's/.*://' | awk '$1 > 60.5' | wc -l)
  lost=$(grep -o '"fps":[0-9.]*,.*"shown_fps":[0-9.]*' "$t/te.json" |
         sed 's/"fps":\([0-9.]*\),.*"shown_fps":\([0-9.]*\)/\1 \2/' | awk '$2 < $1 - 0.001' | wc -l)
  if [ "$n" -ne 0 ]; then
    echo "FAIL rp2040sim_tearing_with_te: $n of 30 torn"
  elif [ "$fast" -ne 0 ]; then
    echo "FAIL rp2040sim_tearing_with_te: a scene faster than the 60 Hz scan: $(grep -o '"fps":[0-9.]*' "$t/te.json" | tr '\n' ' ')"
  elif [ "$lost" -ne 0 ]; then
    echo "FAIL rp2040sim_tearing_with_te: frames sent but not shown whole: $(grep -o '"shown_fps":[0-9.]*' "$t/te.json" | tr '\n' ' ')"
  elif ! cmp -s "$t/gouraud.raw" "$t/te/frame-10.raw"; then
    echo "FAIL rp2040sim_tearing_with_te: frame 10 (cube-gouraud's frame 0) differs from the host's"
  else
    echo "PASS rp2040sim_tearing_with_te ($(grep -o '"fps":[0-9.]*' "$t/te.json" | sed 's/.*://' | tr '\n' ' ')fps)"
  fi
else
  echo "FAIL rp2040sim_tearing_with_te: $(tail -n 1 "$t/te.err")"
fi

if timeout 300 node $sim --image "$b/firmware/pico/cgfs-cube-te.elf" --frames 3 --uart >/dev/null 2>"$t/none.err" &&
   [ "$(grep -c '^warning panel TE line did not rise' "$t/none.err")" -eq 1 ]; then
  echo "PASS rp2040sim_tearing_te_not_wired"
else
  echo "FAIL rp2040sim_tearing_te_not_wired: $(grep -m1 'warning\|rp2040sim:' "$t/none.err")"
fi
