#!/bin/sh
# SPDX-License-Identifier: MIT
# host_sim --window on a virtual display (Xvfb): the window, read back with
# xwd, is the glass --out writes, scaled by --window-scale; it is updated
# while --loop runs and ends cleanly on SIGINT; a build or a machine without
# SDL2 or a display gets one line and exit status 2.
#   tests/system/test_window.sh HOST_SIM
set -u
hs=${1:-build/host_sim}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scene=firmware/scenes/book/raster-11.scene
# (SDL and X11 keep allocations until exit: not the program's leaks)
ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0
export ASAN_OPTIONS

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }

env -u DISPLAY "$hs" --scene $scene --window --loop --loop-frames 1 >/dev/null 2>"$tmp/err"
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ]; then pass window_without_display_exit2_one_line
else fail window_without_display_exit2_one_line "rc $rc: $(cat "$tmp/err")"; fi
"$hs" --scene $scene --window-scale 3 >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && pass window_scale_needs_window || fail window_scale_needs_window "$(cat "$tmp/err")"

for t in xvfb-run xwd; do
  command -v $t >/dev/null 2>&1 || { echo "SKIP window_screenshot: no $t (tools/deps.sh test)"; exit 0; }
done
"$hs" --scene $scene --out "$tmp/ref.png" 2>/dev/null

# (the log exists before the loop reads it; --loop-frames bounds a run whose
# SIGINT went astray)
: >"$tmp/log"
cat >"$tmp/run.sh" <<EOS
"$hs" --scene $scene --window --window-scale 2 --loop --loop-frames 600 >"$tmp/log" 2>"$tmp/err" &
pid=\$!
i=0
while [ "\$(grep -c '^frame' "$tmp/log")" -lt 2 ] && [ \$i -lt 1200 ]; do sleep 0.05; i=\$((i + 1)); done
xwd -silent -nobdrs -name "host_sim book/raster-11" -out "$tmp/shot.xwd"
kill -INT \$pid
wait \$pid
echo "rc \$?" >"$tmp/rc"
EOS
xvfb-run -a -s "-screen 0 640x560x24" sh "$tmp/run.sh" >"$tmp/xvfb.log" 2>&1
rc=$(sed -n 's/^rc //p' "$tmp/rc" 2>/dev/null)
if [ "$rc" = 0 ] && grep -q '^frame 1 ' "$tmp/log"; then pass window_loop_sigint_exit0
else fail window_loop_sigint_exit0 "rc ${rc:-none}: $(cat "$tmp/err" "$tmp/xvfb.log" | head -n 3)"; fi
if [ -s "$tmp/shot.xwd" ] && msg=$(python3 tests/support/xwd_compare.py "$tmp/shot.xwd" "$tmp/ref.png" 2 8); then
  pass window_screenshot_equals_png_scaled
else
  fail window_screenshot_equals_png_scaled "${msg:-no screenshot}: $(head -n 3 "$tmp/xvfb.log")"
fi
