#!/bin/sh
# SPDX-License-Identifier: MIT
# The ray tracer's real-time option (adaptive subsampling) keeps the accuracy
# and ray counts docs/raytracer.md states: raytracer-05 at 240x240 in fixed
# point against the double exact render. A change that costs accuracy or
# traces more rays than stated fails here.
#   tests/system/test_rt_realtime.sh HOST_SIM
set -u
hs=${1:?usage: test_rt_realtime.sh HOST_SIM}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bad=0

# check NAME BLOCK THRESHOLD MIN_PSNR MAX_RAYS
check() {
  sed "s/adaptive_subsample = [0-9]*/adaptive_subsample = $2 adaptive_threshold = $3/" \
    firmware/scenes/bench/raytracer-05-adaptive.scene >"$tmp/s.scene"
  if ! "$hs" --scene "$tmp/s.scene" --size 240x240 --panel none --stats --compare double >"$tmp/o" 2>"$tmp/e"; then
    echo "FAIL $1: host_sim: $(head -c 300 "$tmp/e")"; bad=1; return
  fi
  if python3 - "$tmp/o" "$4" "$5" <<'PY'
import json, sys
o = json.loads(open(sys.argv[1]).read().splitlines()[-1])
ok = o["psnr"] is not None and o["psnr"] >= float(sys.argv[2]) and o["rays"] <= int(sys.argv[3])
print("# psnr %s dB, rays %d" % (o["psnr"], o["rays"]))
sys.exit(0 if ok else 1)
PY
  then echo "PASS $1"; else echo "FAIL $1: want psnr >= $4 dB, rays <= $5"; bad=1; fi
}

check realtime_b4_t6 4 6 58.5 47100
check realtime_b4_t7 4 7 56.7 42600
check realtime_b8_t6 8 6 58.0 45700
exit $bad
