#!/bin/sh
# SPDX-License-Identifier: MIT
# The two-core images run on both emulated cores (tools/rp2040sim/dualcore.js):
# core 1 is started through the boot ROM's launch handshake, renders the odd
# strips and hands them to core 0 over the SIO FIFOs; every first frame the
# emulated ST7789 shows must equal the host's render bit for bit, also with
# core 1 slowed down and sped up (--core1-speed), which changes how the two
# cores and the strip credits interleave but must not change a pixel.
#   cgfs.elf (built-in pattern, SPI-bound): core 1 at 1, 0.05, 0.3, 3, 20 times
#     core 0's speed, against fw_host_ref
#   cgfs-book.elf (raytracer-02): core 1 at 1 and 0.3, against host_sim
# usage: test_rp2040sim_dual.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
sim=tools/rp2040sim/rp2040sim.js
"$b/fw_host_ref" 0 240 240 8 "$t/pattern.raw" || { echo "FAIL rp2040sim_dual_pattern: fw_host_ref failed"; exit 1; }
frac=$(sed -n 's/^#define NUM_FRAC \([0-9][0-9]*\)$/\1/p' "$b/firmware/scenes/fw_book_num_frac.h" 2>/dev/null)
[ -n "$frac" ] || frac=16
"$b/host_sim" --scene firmware/scenes/book/raytracer-02.scene --size 240x240 --numeric fixed --num-frac "$frac" \
  --out-raw "$t/rt02.raw" >/dev/null 2>"$t/herr" || { echo "FAIL rp2040sim_dual_book: host_sim: $(tail -n 1 "$t/herr")"; exit 1; }

# the two book runs in the background (about 30 s each), the patterns meanwhile
for sp in 1 0.3; do
  timeout 600 node $sim --image "$b/firmware/pico/cgfs-book.elf" --frames 1 --core1-speed "$sp" \
    --json --out-raw "$t/book-$sp.raw" >"$t/book-$sp.json" 2>"$t/book-$sp.err" &
done
for sp in 1 0.05 0.3 3 20; do
  name=rp2040sim_dual_pattern_equals_host_core1_speed_$sp
  if ! timeout 120 node $sim --image "$b/firmware/pico/cgfs.elf" --frames 1 --core1-speed "$sp" \
       --json --out-raw "$t/p.raw" >"$t/p.json" 2>"$t/p.err"; then
    echo "FAIL $name: $(tail -n 1 "$t/p.err")"
  elif ! grep -q '"cores":2' "$t/p.json"; then
    echo "FAIL $name: not a two-core run: $(cat "$t/p.json")"
  elif cmp -s "$t/pattern.raw" "$t/p.raw"; then
    echo "PASS $name"
  else
    echo "FAIL $name: $(cmp "$t/pattern.raw" "$t/p.raw" 2>&1 | head -n 1)"
  fi
done
wait
for sp in 1 0.3; do
  name=rp2040sim_dual_raytracer_02_equals_host_sim_core1_speed_$sp
  if [ ! -s "$t/book-$sp.json" ]; then
    echo "FAIL $name: $(tail -n 1 "$t/book-$sp.err")"
  elif ! grep -q '"cores":2.*"what"\|"what".*"cores":2' "$t/book-$sp.json"; then
    echo "FAIL $name: not a two-core run: $(cat "$t/book-$sp.json")"
  elif cmp -s "$t/rt02.raw" "$t/book-$sp.raw"; then
    echo "PASS $name"
  else
    echo "FAIL $name: $(cmp "$t/rt02.raw" "$t/book-$sp.raw" 2>&1 | head -n 1)"
  fi
done
# a slower core 1 costs core 0 time waiting for its strips: the frame time
# must grow with it (the emulated cores really run side by side)
c1=$(sed -n 's/.*"cycles":\([0-9]*\).*/\1/p' "$t/book-1.json")
c03=$(sed -n 's/.*"cycles":\([0-9]*\).*/\1/p' "$t/book-0.3.json")
if [ -n "$c1" ] && [ -n "$c03" ] && [ "$c03" -gt $((c1 / 2 * 3)) ]; then
  echo "PASS rp2040sim_dual_slow_core1_slows_the_frame ($c1 -> $c03 cycles)"
else
  echo "FAIL rp2040sim_dual_slow_core1_slows_the_frame: ${c1:-?} -> ${c03:-?} cycles"
fi
# each core's deepest stack in the raytracer-02 frame (rp2040sim's
# stack_bytes): both measured, and within the 8 KB stacks (core 0's SCRATCH
# banks, core 1's core1_stack) with 1 KB to spare for what the frame does
# not exercise (an exception stacked at the deepest point, the fault report)
st=$(sed -n 's/.*"stack_bytes":\[\([0-9]*\),\([0-9]*\)\].*/\1 \2/p' "$t/book-1.json")
set -- $st
if [ $# -eq 2 ] && [ "$1" -gt 0 ] && [ "$2" -gt 0 ] && [ "$1" -le 7168 ] && [ "$2" -le 7168 ]; then
  echo "PASS rp2040sim_dual_stacks_fit ($1 and $2 bytes of 8192)"
else
  echo "FAIL rp2040sim_dual_stacks_fit: stack_bytes '${st:-?}' (each in 1..7168)"
fi
