#!/bin/sh
# SPDX-License-Identifier: MIT
# Input and output faults of host_sim and scenec: a FIFO or /dev/stdin as the
# scene is read once; an output that is the scene file, or two outputs on
# one path, are refused; a FIFO or character device as an output is written
# in place (it stays what it was); a write that hits `ulimit -f` fails on one
# line and leaves no temporary file, and removes the outputs that run wrote
# before it; scenec's two files are complete or absent; scenes that are
# valid but almost certainly wrong are warned about, exit 0.
# usage: test_io_faults.sh HOST_SIM SCENEC
set -u
hs=$1
sc=$2
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
S=firmware/scenes/book/raytracer-02.scene
ok() { echo "PASS $1"; }
no() { echo "FAIL $1: $2"; }

"$hs" --scene "$S" --size 48x48 --panel none --out-raw "$t/ref.raw" 2>/dev/null || no io_reference "host_sim failed"
mkfifo "$t/scene.fifo"
cat "$S" >"$t/scene.fifo" &
if timeout 30 "$hs" --scene "$t/scene.fifo" --size 48x48 --panel none --compare double --out-raw "$t/fifo.raw" \
   >/dev/null 2>"$t/err" && cmp -s "$t/ref.raw" "$t/fifo.raw"; then ok io_scene_from_fifo_read_once
else no io_scene_from_fifo_read_once "exit $?: $(cat "$t/err")"; fi
if timeout 30 "$hs" --scene /dev/stdin --size 48x48 --panel none --out-raw "$t/stdin.raw" <"$S" >/dev/null 2>"$t/err" &&
   cmp -s "$t/ref.raw" "$t/stdin.raw"; then ok io_scene_from_stdin
else no io_scene_from_stdin "$(cat "$t/err")"; fi
cat "$S" >"$t/scene.fifo" &
if timeout 30 "$sc" --size 48x48 -o "$t/fifo.c" "$t/scene.fifo" >/dev/null 2>"$t/err" && [ -s "$t/fifo.c" ] &&
   [ -s "$t/fifo.h" ]; then ok io_scenec_scene_from_fifo
else no io_scenec_scene_from_fifo "$(cat "$t/err")"; fi

cp "$S" "$t/x.scene"
"$hs" --scene "$t/x.scene" --size 48x48 --panel none --out-raw "$t/x.scene" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 2 ] && grep -q "is the scene file" "$t/err" && cmp -s "$S" "$t/x.scene"; then ok io_output_equal_to_scene_refused
else no io_output_equal_to_scene_refused "exit $rc: $(cat "$t/err")"; fi
"$hs" --scene "$S" --size 48x48 --panel none --out "$t/a.ppm" --out-rgb888 "$t/a.ppm" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 2 ] && grep -q "given as two outputs" "$t/err" && [ ! -e "$t/a.ppm" ]; then ok io_two_outputs_one_path_refused
else no io_two_outputs_one_path_refused "exit $rc: $(cat "$t/err")"; fi

if "$hs" --scene "$S" --size 48x48 --panel none --out-raw /dev/null >/dev/null 2>"$t/err" && [ -c /dev/null ]; then
  ok io_output_char_device_in_place
else no io_output_char_device_in_place "$(cat "$t/err")"; fi
mkfifo "$t/out.fifo"
cat "$t/out.fifo" >"$t/fromfifo.raw" &
reader=$!
if timeout 30 "$hs" --scene "$S" --size 48x48 --panel none --out-raw "$t/out.fifo" >/dev/null 2>"$t/err" &&
   wait $reader && [ -p "$t/out.fifo" ] && cmp -s "$t/ref.raw" "$t/fromfifo.raw"; then ok io_output_fifo_in_place
else no io_output_fifo_in_place "$(cat "$t/err")"; fi

# ulimit -f 60 (30 KB): the 240x240 PNG fits, the raw frame (115 KB) does not
mkdir "$t/lim"
(ulimit -f 60; exec "$hs" --scene "$S" --out "$t/lim/a.png" --out-raw "$t/lim/a.raw") >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && [ "$(wc -l <"$t/err")" -eq 1 ] && grep -q "a.raw: write failed: File too large" "$t/err" &&
   [ -z "$(ls -A "$t/lim")" ]; then ok io_file_size_limit_leaves_nothing
else no io_file_size_limit_leaves_nothing "exit $rc: $(cat "$t/err"); left: $(ls -A "$t/lim")"; fi
mkdir "$t/lim2"
(ulimit -f 2; exec "$sc" --size 240x240 -o "$t/lim2/r.c" firmware/scenes/book/raster-11.scene) >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && [ -z "$(ls -A "$t/lim2")" ]; then ok io_scenec_outputs_complete_or_absent
else no io_scenec_outputs_complete_or_absent "exit $rc: $(cat "$t/err"); left: $(ls -A "$t/lim2")"; fi
# a signal in the middle of a write removes the temporary file (host_sim
# sends itself SIGTERM after the first row of --out-raw, test option); the
# run ends by the signal, and nothing of it is left
mkdir "$t/sig"
"$hs" --scene "$S" --size 48x48 --panel none --out-raw "$t/sig/a.raw" --inject-fault signal-in-write >/dev/null 2>&1
rc=$?
if [ $rc -eq 143 ] && [ -z "$(ls -A "$t/sig")" ]; then ok io_signal_in_write_leaves_nothing
else no io_signal_in_write_leaves_nothing "exit $rc, left: $(ls -A "$t/sig")"; fi

printf 'renderer = raytracer\ncanvas { width = 16 height = 16 }\nviewport { width = 1 height = 1 d = 1 }\nsphere { center = (0, 0, 3) radius = 1 color = (255, 0, 0) }\n' >"$t/nolight.scene"
"$hs" --scene "$t/nolight.scene" --panel none --out "$t/n.png" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "warning: .*no lights" "$t/err" && [ -s "$t/n.png" ]; then ok io_warns_scene_without_lights
else no io_warns_scene_without_lights "exit $rc: $(cat "$t/err")"; fi
"$hs" --scene "$S" --size 16x16 --panel none >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "warning: no output given" "$t/err"; then ok io_warns_no_output
else no io_warns_no_output "exit $rc: $(cat "$t/err")"; fi
"$hs" --scene "$S" --size 16x16 --panel none --out "$t/q.png" >/dev/null 2>"$t/err"
if [ ! -s "$t/err" ]; then ok io_no_warning_for_a_book_scene
else no io_no_warning_for_a_book_scene "$(cat "$t/err")"; fi
