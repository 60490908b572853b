#!/bin/sh
# SPDX-License-Identifier: MIT
# host_sim live: --loop (bounded by --loop-frames, ended by SIGINT/SIGTERM
# with exit 0), the dirty-rectangle flush against the full one (same glass,
# fewer SPI bytes), per-frame --out patterns, --fps-overlay and the progress
# line on a terminal's stderr.
#   tests/system/test_live.sh HOST_SIM
set -u
hs=${1:-build/host_sim}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
anim=firmware/scenes/demo/spinning-crate.scene
still=firmware/scenes/book/raster-11.scene

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }

# bounded loop: one line per frame, the animation's frame count, exit 0
"$hs" --scene $anim --loop --loop-frames 4 --out "$tmp/dirty.png" --out-raw "$tmp/dirty.raw" >"$tmp/dirty.txt" 2>"$tmp/err"
rc=$?
n=$(grep -c '^frame [0-9]* ([0-9]*/72): host [0-9.]* fps, [0-9.]* ms, [0-9]* SPI bytes, [0-9]* rects$' "$tmp/dirty.txt")
if [ $rc -eq 0 ] && [ "$n" -eq 4 ] && [ ! -s "$tmp/err" ]; then pass live_loop_frames_bounded_one_line_each
else fail live_loop_frames_bounded_one_line_each "rc $rc, $n lines: $(head -n 2 "$tmp/dirty.txt" "$tmp/err")"; fi

# dirty against full: the same glass after every frame, fewer bytes per frame after the first
"$hs" --scene $anim --loop --loop-frames 4 --flush full --out-raw "$tmp/full.raw" >"$tmp/full.txt" 2>&1
bytes() { sed -n "s/^frame $2 .* \([0-9]*\) SPI bytes.*/\1/p" "$1"; }
fb=$(bytes "$tmp/full.txt" 3) db=$(bytes "$tmp/dirty.txt" 3)
if cmp -s "$tmp/full.raw" "$tmp/dirty.raw" && [ -n "$fb" ] && [ -n "$db" ] && [ "$db" -lt $((fb / 2)) ]; then
  pass live_dirty_flush_same_glass_fewer_spi_bytes
else
  fail live_dirty_flush_same_glass_fewer_spi_bytes "full $fb dirty $db bytes; $(cmp "$tmp/full.raw" "$tmp/dirty.raw" 2>&1)"
fi
for f in 1 2 5; do
  "$hs" --scene $anim --frames $f --flush dirty --out-raw "$tmp/d$f.raw" 2>/dev/null
  "$hs" --scene $anim --frames $f --out-raw "$tmp/f$f.raw" 2>/dev/null
  cmp -s "$tmp/d$f.raw" "$tmp/f$f.raw" || { fail live_dirty_flush_frames_$f "glass differs"; continue; }
  pass live_dirty_flush_frames_$f
done
"$hs" --scene $still --loop --loop-frames 3 --panel ili9341 >"$tmp/still.txt" 2>&1
if [ "$(bytes "$tmp/still.txt" 2)" = 0 ]; then pass live_still_scene_sends_nothing_after_first
else fail live_still_scene_sends_nothing_after_first "$(cat "$tmp/still.txt")"; fi

# signals end an endless loop after the frame: exit 0, the last frame written
for sig in INT TERM; do
  rm -f "$tmp/sig.png"
  : >"$tmp/sig.txt"   # exists before the wait below reads it (the shell may open it late)
  "$hs" --scene $anim --loop --out "$tmp/sig.png" >>"$tmp/sig.txt" 2>&1 &
  pid=$!
  i=0
  # up to 60 s for three frames (a loaded machine starts the ASan build slowly;
  # a signal before the handler is installed would kill it)
  while [ "$(grep -c '^frame' "$tmp/sig.txt")" -lt 3 ] && [ $i -lt 1200 ]; do sleep 0.05; i=$((i + 1)); done
  kill -$sig $pid
  wait $pid
  rc=$?
  if [ $rc -eq 0 ] && [ -s "$tmp/sig.png" ] && tail -n 1 "$tmp/sig.txt" | grep -q '^frame'; then
    pass live_loop_sig${sig}_exit0
  else
    fail live_loop_sig${sig}_exit0 "rc $rc, $(tail -n 1 "$tmp/sig.txt")"
  fi
done

# per-frame output pattern: one file per frame, the last equal to --out of that frame
"$hs" --scene $anim --loop --loop-frames 3 --out "$tmp/frame-%03d.png" >/dev/null 2>"$tmp/err"
rc=$?
"$hs" --scene $anim --frames 3 --out "$tmp/last.png" 2>/dev/null
if [ $rc -eq 0 ] && [ -f "$tmp/frame-000.png" ] && [ -f "$tmp/frame-001.png" ] && cmp -s "$tmp/frame-002.png" "$tmp/last.png" \
   && [ ! -e "$tmp/frame-003.png" ] && ! cmp -s "$tmp/frame-000.png" "$tmp/frame-001.png"; then
  pass live_out_pattern_one_file_per_frame
else
  fail live_out_pattern_one_file_per_frame "rc $rc: $(ls "$tmp") $(cat "$tmp/err")"
fi
"$hs" --scene $anim --frames 2 --out "$tmp/n%d.ppm" 2>/dev/null
if [ -f "$tmp/n0.ppm" ] && [ -f "$tmp/n1.ppm" ]; then pass live_out_pattern_with_frames
else fail live_out_pattern_with_frames "$(ls "$tmp")"; fi
bad=""
for args in "--out $tmp/a%s.png" "--out $tmp/a%d%d.png" "--out $tmp/a%5d.png" "--loop-frames 3" "--loop --frames 2" \
            "--loop --compare double" "--flush some" "--loop --loop-frames 0"; do
  # shellcheck disable=SC2086
  "$hs" --scene $anim $args >/dev/null 2>"$tmp/err"
  rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] || bad="$bad [$args: rc $rc]"
done
if [ -z "$bad" ] && [ ! -e "$tmp/a%s.png" ]; then pass live_bad_options_exit2_one_line; else fail live_bad_options_exit2_one_line "$bad"; fi

# the frame rate on the glass: only the top-left corner differs
"$hs" --scene $still --loop --loop-frames 2 --fps-overlay --out-raw "$tmp/ov.raw" >/dev/null 2>&1
rc=$?
"$hs" --scene $still --out-raw "$tmp/plain.raw" 2>/dev/null
first=$(cmp "$tmp/ov.raw" "$tmp/plain.raw" 2>/dev/null | sed -n 's/.* byte \([0-9]*\),.*/\1/p')
last=$(cmp -l "$tmp/ov.raw" "$tmp/plain.raw" 2>/dev/null | tail -n 1 | awk '{print $1}')
if [ $rc -eq 0 ] && [ -n "$first" ] && [ "$last" -le $((240 * 2 * 24)) ]; then pass live_fps_overlay_top_left
else fail live_fps_overlay_top_left "rc $rc, differs from byte $first to $last"; fi

# progress line: on a terminal's stderr during a long frame, never into a file
long="--scene firmware/scenes/book/raytracer-05.scene --panel none --size 1000x1000"
if command -v script >/dev/null 2>&1; then
  script -qec "$hs $long --out $tmp/long.png" /dev/null >"$tmp/tty.txt" 2>&1
  if tr '\r' '\n' <"$tmp/tty.txt" | grep -q '^host_sim: frame 0: rows [0-9]*/1000 ([0-9]*%), [0-9.]* s'; then
    pass live_progress_line_on_terminal
  else
    fail live_progress_line_on_terminal "$(tr '\r' '\n' <"$tmp/tty.txt" | head -n 3)"
  fi
else
  echo "SKIP live_progress_line_on_terminal: no script(1)"
fi
# shellcheck disable=SC2086
"$hs" $long --out "$tmp/long2.png" 2>"$tmp/err"
if [ ! -s "$tmp/err" ]; then pass live_no_progress_line_into_a_file; else fail live_no_progress_line_into_a_file "$(head -c 200 "$tmp/err")"; fi

if "$hs" --help | grep -q -- '--loop' && "$hs" --help | grep -q -- '--loop-frames'; then pass host_sim_help_lists_loop
else fail host_sim_help_lists_loop "no --loop in --help"; fi
