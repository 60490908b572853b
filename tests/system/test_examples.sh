#!/bin/sh
# SPDX-License-Identifier: MIT
# make examples: firmware/examples/panel_demo on the host and on the emulated
# Cortex-M0+. The host's trace (its HAL's bus, in the notation of the panel
# test vectors) is replayed through the strict emulated ST7789: no protocol
# violation, and after each scene the glass is host_sim's render of that
# scene at the example's number format. The Cortex-M0+ build, run in
# qemu-system-arm (mps2-an385), writes the same trace byte for byte.
#   tests/system/test_examples.sh BUILD
set -u
b=${1:?usage: test_examples.sh BUILD}
ex=$b/examples
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }

"$ex/host/panel_demo" >"$tmp/host.txt" 2>"$tmp/host.err"
rc=$?
shown=$(sed -n 's/^# shown //p' "$tmp/host.txt")
if [ $rc -eq 0 ] && [ ! -s "$tmp/host.err" ] && [ "$(echo $shown)" = "book/raytracer-02 book/raster-11" ]; then
  pass example_host_runs
else
  fail example_host_runs "exit $rc, scenes shown '$(echo $shown)': $(head -c 300 "$tmp/host.err")"
fi

# The expected glass after each scene: host_sim's render through its own
# emulated panel at the format the example is compiled at.
frac=$(sed -n 's/^#define NUM_FRAC \([0-9][0-9]*\)$/\1/p' "$ex/host/scenes/num_frac.h")
: >"$tmp/expect.sed"
for n in $shown; do
  id=$(echo "$n" | tr '/' '_')
  if ! "$b/host_sim" --scene "firmware/scenes/$n.scene" --panel st7789 --size 240x240 --numeric fixed \
       --num-frac "$frac" --out-raw "$tmp/$id.raw" 2>"$tmp/hs.err"; then
    fail "example_reference_$id" "host_sim: $(head -n 1 "$tmp/hs.err")"
    continue
  fi
  crc=$(python3 -c 'import sys, zlib; print("%08X" % zlib.crc32(open(sys.argv[1], "rb").read()))' "$tmp/$id.raw")
  printf 's|^# shown %s$|&\\nexpect_glass_crc32 %s|\n' "$n" "$crc" >>"$tmp/expect.sed"
done
{ sed -f "$tmp/expect.sed" "$tmp/host.txt"; echo finish; echo expect_ok; } >"$tmp/replay.txt"
if [ "$(grep -c '^expect_glass_crc32' "$tmp/replay.txt")" -eq 2 ] &&
   out=$("$b/asan/tests/test_panel_vectors" "$tmp/replay.txt" 2>&1) && ! echo "$out" | grep -q '^FAIL' &&
   echo "$out" | grep -q "^PASS $tmp/replay.txt"; then
  pass example_host_trace_replays_to_host_sim_glass
else
  fail example_host_trace_replays_to_host_sim_glass "$(echo "${out:-no expectations}" | grep -v '^PASS' | head -n 3)"
fi

# The Cortex-M0+ build in qemu: the same trace.
timeout 300 qemu-system-arm -M mps2-an385 -nographic -monitor none -serial null \
  -semihosting-config enable=on,target=native -kernel "$ex/m0plus/panel_demo.elf" >"$tmp/m0.txt" 2>"$tmp/m0.err"
rc=$?
if [ $rc -eq 0 ] && cmp -s "$tmp/host.txt" "$tmp/m0.txt"; then
  pass example_m0plus_same_trace
else
  fail example_m0plus_same_trace "exit $rc, $(cmp "$tmp/host.txt" "$tmp/m0.txt" 2>&1 | head -n 1) $(head -c 200 "$tmp/m0.err")"
fi
