#!/bin/sh
# SPDX-License-Identifier: MIT
# Resets while the board runs (tools/rp2040sim):
#   --reset-core0-at-frame N: core 0 alone is reset once N frames are on the
#     glass (a debug probe's reset, SYSRESETREQ) and boots again, core 1 and
#     the peripherals going on as on the chip;
#   --watchdog-reset-at-frame N: both cores (a watchdog reset that selects
#     them, as the boot ROM's reboot after flashing does).
# The firmware must bring core 1 back through the PSM, launch it again and go
# on showing frames: the UART shows a second boot line, core 1 was reset (by
# the firmware at each start, and by the watchdog), and the first frame after
# the reset (frame 0 again) equals the host's render bit for bit:
#   cgfs.elf (built-in pattern, two cores) against fw_host_ref
#   cgfs-cube.elf (the cube scenes, two cores, vertices and triangles shared)
#     against host_sim's frame 0 of bench/cube-textured, both resets
# And a core 1 that never answers the launch handshake (--core1-absent): the
# launch gives up and says so on the UART (rp2040sim ends on the error line).
# And a glitch on the wire (--corrupt-at-frame): the repair strips mend it.
# usage: test_rp2040sim_reset.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
sim=tools/rp2040sim/rp2040sim.js
"$b/fw_host_ref" 0 240 240 8 "$t/pattern.raw" || { echo "FAIL rp2040sim_reset_pattern: fw_host_ref failed"; exit 1; }
frac=$(sed -n 's/^#define NUM_FRAC \([0-9][0-9]*\)$/\1/p' "$b/firmware/scenes/fw_cube_num_frac.h" 2>/dev/null)
[ -n "$frac" ] || { echo "FAIL rp2040sim_reset_cube: no NUM_FRAC in fw_cube_num_frac.h"; exit 1; }
"$b/host_sim" --scene firmware/scenes/bench/cube-textured.scene --size 240x240 --numeric fixed --num-frac "$frac" \
  --out-raw "$t/cube.raw" >/dev/null 2>"$t/herr" || { echo "FAIL rp2040sim_reset_cube: host_sim: $(tail -n 1 "$t/herr")"; exit 1; }

# IMAGE NAME REF AT [KIND]: reset core 0 (KIND watchdog: both cores, a
# watchdog reset) after AT frames; frame AT (the first after the reset) must
# be frame 0 of the first scene and equal REF
check() {
  kind=${5:-core0}
  name=rp2040sim_reset_${kind}_$2
  # core 1 is reset by the firmware at each start, and by a watchdog reset
  c1=2
  [ "$kind" = watchdog ] && c1=3
  if ! timeout 300 node $sim --image "$b/firmware/pico/$1.elf" --frames $(($4 + 2)) \
       $([ "$kind" = watchdog ] && echo --watchdog-reset-at-frame || echo --reset-core0-at-frame) "$4" \
       --uart --json --out-dir "$t/$2" >"$t/$2.json" 2>"$t/$2.err"; then
    echo "FAIL $name: $(tail -n 1 "$t/$2.err")"
    return
  fi
  boots=$(grep -c '^boot board=rp2040 cores=2' "$t/$2.err")
  if [ "$boots" -ne 2 ]; then
    echo "FAIL $name: $boots boot lines, not 2"
  elif ! tail -n 1 "$t/$2.err" | grep -q "core 0 reset 1 time(s), core 1 $c1\$"; then
    echo "FAIL $name: $(tail -n 1 "$t/$2.err")"
  elif ! sed -n "$(($4 + 1))p" "$t/$2.json" | grep -q '"frame":0,'; then
    echo "FAIL $name: frame $4 is not a frame 0: $(sed -n "$(($4 + 1))p" "$t/$2.json")"
  elif cmp -s "$3" "$t/$2/frame-$4.raw"; then
    echo "PASS $name"
  else
    echo "FAIL $name: $(cmp "$3" "$t/$2/frame-$4.raw" 2>&1 | head -n 1)"
  fi
}
check cgfs pattern "$t/pattern.raw" 2
check cgfs-cube cube_textured "$t/cube.raw" 3
check cgfs-cube cube_textured "$t/cube.raw" 2 watchdog
name=rp2040sim_core1_launch_timeout_error_line
if timeout 120 node $sim --image "$b/firmware/pico/cgfs.elf" --core1-absent --frames 1 >/dev/null 2>"$t/absent.err"; then
  echo "FAIL $name: the run succeeded"
elif tail -n 1 "$t/absent.err" | grep -q '^rp2040sim: error core 1 did not answer the launch sequence: one core$'; then
  echo "PASS $name"
else
  echo "FAIL $name: $(tail -n 1 "$t/absent.err")"
fi

# A glitch on the wire (--corrupt-at-frame 2: one pixel in every 16 rows of
# the panel's memory flipped, in column 0, which the cube scenes leave
# background): the changed-columns flush alone never sends those columns
# again; one strip a frame sent whole mends them. Frame 30, cube-textured's
# frame 0 again, must equal the host's render.
if ! timeout 300 node $sim --image "$b/firmware/pico/cgfs-cube.elf" --frames 31 --corrupt-at-frame 2 \
     --json --out-dir "$t/glitch" >"$t/glitch.json" 2>"$t/glitch.err"; then
  echo "FAIL rp2040sim_repair_after_glitch: $(tail -n 1 "$t/glitch.err")"
elif ! sed -n 31p "$t/glitch.json" | grep -q '"what":"scene:bench/cube-textured".*"frame":0,'; then
  echo "FAIL rp2040sim_repair_after_glitch: frame 30 is not cube-textured's frame 0: $(sed -n 31p "$t/glitch.json" | head -c 200)"
elif cmp -s "$t/cube.raw" "$t/glitch/frame-30.raw"; then
  echo "PASS rp2040sim_repair_after_glitch"
else
  echo "FAIL rp2040sim_repair_after_glitch: $(cmp "$t/cube.raw" "$t/glitch/frame-30.raw" 2>&1 | head -n 1)"
fi
