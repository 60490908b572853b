#!/bin/sh
# SPDX-License-Identifier: MIT
# host_sim renders every scene of firmware/scenes on every panel of
# hal/panels.def at the panel's own size, through its driver and emulated
# controller, and the glass shows what the plain memory framebuffer
# (--panel none) holds at that size, pixel for pixel; on a round glass
# (GC9A01) inside the circle, black outside it. A scene that does not fit
# a size (host_sim refuses it: work memory, cost) must be refused alike on
# the panel. One case per panel.
# usage: test_host_sim_panels.sh HOST_SIM
set -u
hs=${1:-build/host_sim}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
scenes=$(find firmware/scenes -name '*.scene' | sort)
[ -n "$scenes" ] || { echo "FAIL host_sim_panels: no scenes"; exit 1; }
for p in $(sed -n 's/^PANEL(\([a-z0-9_]*\),.*/\1/p' hal/panels.def); do
  size=${p##*_}
  round=0
  case $p in gc9a01_*) round=1 ;; esac
  bad="" n=0 refused=0
  for s in $scenes; do
    "$hs" --scene "$s" --panel none --size "$size" --out-raw "$t/none.raw" >/dev/null 2>"$t/e1"; r1=$?
    "$hs" --scene "$s" --panel "$p" --out-raw "$t/p.raw" >/dev/null 2>"$t/e2"; r2=$?
    if [ "$r1" -ne 0 ] || [ "$r2" -ne 0 ]; then
      if [ "$r1" -eq "$r2" ] && [ "$r1" -eq 2 ]; then refused=$((refused + 1)); continue; fi
      bad="$bad [$s: exit $r1 / $r2: $(head -c 160 "$t/e2")]"
      continue
    fi
    if ! python3 - "$t/none.raw" "$t/p.raw" "$size" "$round" <<'PY'
import sys
a = open(sys.argv[1], 'rb').read(); g = open(sys.argv[2], 'rb').read()
w, h = map(int, sys.argv[3].split('x')); rnd = sys.argv[4] == '1'
if len(a) != 2 * w * h or len(g) != len(a): sys.exit(1)
if not rnd: sys.exit(0 if a == g else 1)
for y in range(h):
    dy = 2 * y + 1 - h
    for x in range(w):
        dx = 2 * x + 1 - w
        i = 2 * (y * w + x)
        want = a[i:i + 2] if dx * dx + dy * dy <= w * w else b'\0\0'
        if g[i:i + 2] != want: sys.exit(1)
PY
    then
      bad="$bad [$s: the glass differs]"
    fi
    n=$((n + 1))
  done
  if [ -z "$bad" ] && [ "$n" -gt 0 ]; then
    echo "PASS host_sim_panel_${p}_every_scene ($n scenes, $refused refused at $size)"
  else
    echo "FAIL host_sim_panel_${p}_every_scene: $n rendered,$bad"
  fi
done
