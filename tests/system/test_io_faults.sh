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
# a failed run leaves every file of an earlier run as it was: --out and each
# frame of a per-frame pattern (all frames, not only the first three); the
# outputs are renamed into place only when the whole run has succeeded
# (ulimit -f 30, 15 KB: each 100x100 PNG fits, the raw frame, 20 KB, does not)
mkdir "$t/keep"
for f in a.png f000.png f001.png f002.png f003.png f004.png a.raw; do echo old >"$t/keep/$f"; done
(ulimit -f 30; exec "$hs" --scene "$S" --panel none --size 100x100 --out "$t/keep/a.png" --out-raw "$t/keep/a.raw") \
  >/dev/null 2>"$t/err"
rc=$?
(ulimit -f 30; exec "$hs" --scene "$S" --panel none --size 100x100 --frames 5 --out "$t/keep/f%03d.png" \
  --out-raw "$t/keep/a.raw") >/dev/null 2>>"$t/err"
rc2=$?
kept=0
for f in a.png f000.png f001.png f002.png f003.png f004.png a.raw; do [ "$(cat "$t/keep/$f")" = old ] && kept=$((kept + 1)); done
if [ $rc -eq 1 ] && [ $rc2 -eq 1 ] && [ $kept -eq 7 ] && [ "$(ls -A "$t/keep" | wc -l)" -eq 7 ]; then
  ok io_failed_run_keeps_earlier_files
else no io_failed_run_keeps_earlier_files "exit $rc/$rc2, $kept of 7 kept: $(ls -A "$t/keep") $(cat "$t/err")"; fi
# the same file under two names (./a.ppm, a hard link) is one output; a
# file the scene reads (its texture) is not an output
mkdir "$t/same"
"$hs" --scene "$S" --size 16x16 --panel none --out "$t/same/a.ppm" --out-rgb888 "$t/same/./a.ppm" >/dev/null 2>"$t/err"
rc=$?
echo old >"$t/same/b.ppm"
ln "$t/same/b.ppm" "$t/same/c.ppm"
"$hs" --scene "$S" --size 16x16 --panel none --out "$t/same/b.ppm" --out-rgb888 "$t/same/c.ppm" >/dev/null 2>>"$t/err"
rc2=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 2 ] && [ "$(grep -c "given as two outputs" "$t/err")" -eq 2 ] && [ ! -e "$t/same/a.ppm" ] &&
   [ "$(cat "$t/same/b.ppm")" = old ]; then ok io_same_file_two_names_refused
else no io_same_file_two_names_refused "exit $rc/$rc2: $(cat "$t/err")"; fi
mkdir "$t/tex"
printf 'P6\n2 2\n255\n' >"$t/tex/t.ppm"
printf '\377\0\0\0\377\0\0\0\377\377\377\377' >>"$t/tex/t.ppm"
cp "$t/tex/t.ppm" "$t/tex/orig.ppm"
cp firmware/scenes/bench/knot-4k.obj "$t/tex/"
sed 's/^texture .*/texture { name = checker file = "t.ppm" }/' firmware/scenes/bench/knot-4k-textured.scene >"$t/tex/t.scene"
"$hs" --scene "$t/tex/t.scene" --size 16x16 --panel none --out "$t/tex/ok.ppm" >/dev/null 2>"$t/err" || no io_texture_scene "$(cat "$t/err")"
"$hs" --scene "$t/tex/t.scene" --size 16x16 --panel none --out-rgb888 "$t/tex/./t.ppm" >/dev/null 2>"$t/err"
rc=$?
cp "$t/tex/knot-4k.obj" "$t/tex/orig.obj"
"$hs" --scene "$t/tex/t.scene" --size 16x16 --panel none --out-raw "$t/tex/knot-4k.obj" >/dev/null 2>>"$t/err"
rc2=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 2 ] && [ "$(grep -c "is a file the scene reads" "$t/err")" -eq 2 ] &&
   cmp -s "$t/tex/t.ppm" "$t/tex/orig.ppm" && cmp -s "$t/tex/knot-4k.obj" "$t/tex/orig.obj"; then
  ok io_output_onto_texture_refused
else no io_output_onto_texture_refused "exit $rc/$rc2: $(cat "$t/err")"; fi

# scenec: no output onto the scene (-o same.c same.c; -o x.c with the scene
# named x.h), nor two outputs on one file; an output directory that does not
# exist is an input error (exit 2)
mkdir "$t/sc"
cp "$S" "$t/sc/same.c"
cp "$S" "$t/sc/x.h"
"$sc" -o "$t/sc/same.c" "$t/sc/same.c" >/dev/null 2>"$t/err"
rc=$?
"$sc" -o "$t/sc/x.c" "$t/sc/x.h" >/dev/null 2>>"$t/err"
rc2=$?
"$sc" -o "$t/sc/z.c" --deps "$t/sc/./z.c" "$S" >/dev/null 2>>"$t/err"
rc3=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 2 ] && [ $rc3 -eq 2 ] && [ "$(grep -c "is the scene file; refusing" "$t/err")" -eq 2 ] &&
   grep -q "given as two outputs" "$t/err" && cmp -s "$S" "$t/sc/same.c" && cmp -s "$S" "$t/sc/x.h" &&
   [ ! -e "$t/sc/x.c" ] && [ ! -e "$t/sc/z.c" ]; then ok io_scenec_output_onto_scene_refused
else no io_scenec_output_onto_scene_refused "exit $rc/$rc2/$rc3: $(cat "$t/err")"; fi
"$sc" -o /nonexistent/x.c "$S" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$t/err")" -eq 1 ] && grep -q "does not exist" "$t/err"; then ok io_scenec_missing_output_dir_exit_2
else no io_scenec_missing_output_dir_exit_2 "exit $rc: $(cat "$t/err")"; fi

# FIFOs and devices: a scene FIFO no program writes to, an output FIFO no
# program reads, are refused after 10 s (exit 2, one line) instead of
# hanging; a texture that is a FIFO, and a device as the scene, at once; a
# directory as the scene is said to be one (the three slow cases side by side)
mkdir "$t/ff"
mkfifo "$t/ff/scene.fifo" "$t/ff/out.fifo"
timeout 60 "$hs" --scene "$t/ff/scene.fifo" --size 16x16 --panel none --out-raw "$t/ff/a.raw" >/dev/null 2>"$t/ff/e1" &
p1=$!
timeout 60 "$sc" -o "$t/ff/s.c" "$t/ff/scene.fifo" >/dev/null 2>"$t/ff/e2" &
p2=$!
timeout 60 "$hs" --scene "$S" --size 16x16 --panel none --out-raw "$t/ff/out.fifo" >/dev/null 2>"$t/ff/e3" &
p3=$!
mkdir "$t/ff/tex"
cp firmware/scenes/bench/knot-4k.obj "$t/ff/tex/"
mkfifo "$t/ff/tex/t.ppm"
cp "$t/tex/t.scene" "$t/ff/tex/t.scene"
timeout 30 "$hs" --scene "$t/ff/tex/t.scene" --size 16x16 --panel none --out "$t/ff/t.ppm" >/dev/null 2>"$t/err"
rc=$?
timeout 30 "$sc" -o "$t/ff/t.c" "$t/ff/tex/t.scene" >/dev/null 2>>"$t/err"
rc2=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 2 ] && [ "$(grep -c "is not a regular file" "$t/err")" -eq 2 ]; then ok io_texture_fifo_refused
else no io_texture_fifo_refused "exit $rc/$rc2: $(cat "$t/err")"; fi
timeout 30 "$hs" --scene /dev/zero --size 16x16 --panel none >/dev/null 2>"$t/err"
rc=$?
timeout 30 "$sc" -o "$t/ff/z.c" /dev/zero >/dev/null 2>>"$t/err"
rc2=$?
timeout 30 "$sc" -o "$t/ff/d.c" "$t/ff" >/dev/null 2>>"$t/err"
rc3=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 2 ] && [ $rc3 -eq 2 ] && [ "$(grep -c "not a regular file or a FIFO" "$t/err")" -eq 2 ] &&
   grep -q "is a directory" "$t/err" && [ "$(wc -l <"$t/err")" -eq 3 ]; then ok io_device_or_directory_scene_refused
else no io_device_or_directory_scene_refused "exit $rc/$rc2/$rc3: $(cat "$t/err")"; fi
wait $p1; r1=$?
wait $p2; r2=$?
wait $p3; r3=$?
if [ $r1 -eq 2 ] && [ $r2 -eq 2 ] && grep -q "nothing written to it" "$t/ff/e1" && grep -q "nothing written to it" "$t/ff/e2"
then ok io_scene_fifo_without_writer_refused
else no io_scene_fifo_without_writer_refused "exit $r1/$r2: $(cat "$t/ff/e1" "$t/ff/e2")"; fi
if [ $r3 -eq 2 ] && [ "$(wc -l <"$t/ff/e3")" -eq 1 ] && grep -q "no program read" "$t/ff/e3" && [ -p "$t/ff/out.fifo" ]
then ok io_output_fifo_without_reader_refused
else no io_output_fifo_without_reader_refused "exit $r3: $(cat "$t/ff/e3")"; fi

# a texture (or model file) through a symbolic link that leads outside the
# scene's directory is refused, by host_sim and scenec alike
mkdir "$t/ln" "$t/ln/in"
cp firmware/scenes/bench/knot-4k.obj "$t/tex/t.scene" "$t/ln/in/"
cp "$t/tex/t.ppm" "$t/ln/secret.ppm"
ln -s ../secret.ppm "$t/ln/in/t.ppm"
"$hs" --scene "$t/ln/in/t.scene" --size 16x16 --panel none --out "$t/ln/o.ppm" >/dev/null 2>"$t/err"
rc=$?
"$sc" -o "$t/ln/o.c" "$t/ln/in/t.scene" >/dev/null 2>>"$t/err"
rc2=$?
rm "$t/ln/in/t.ppm"
cp "$t/tex/t.ppm" "$t/ln/in/real.ppm"
ln -s real.ppm "$t/ln/in/t.ppm"
"$hs" --scene "$t/ln/in/t.scene" --size 16x16 --panel none --out "$t/ln/o2.ppm" >/dev/null 2>>"$t/err"
rc3=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 2 ] && [ $rc3 -eq 0 ] && [ "$(grep -c "leads outside the scene's directory" "$t/err")" -eq 2 ] &&
   [ ! -e "$t/ln/o.ppm" ] && [ ! -e "$t/ln/o.c" ]; then ok io_symlink_outside_scene_dir_refused
else no io_symlink_outside_scene_dir_refused "exit $rc/$rc2/$rc3: $(cat "$t/err")"; fi

# bounded work: the renderer's work memory over --max-memory (default 1 GiB)
# is refused before it is allocated, a ray-traced frame whose estimated
# ray-object tests exceed --max-cost before rendering (4,096 reflective
# spheres, 64 lights), a recursion_depth past what the ray tracer follows is
# an error, not a silent clamp; all exit 2 on one line
"$hs" --scene "$S" --size 64x64 --panel none --max-memory 1000 >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$t/err")" -eq 1 ] && grep -q "bytes of renderer work memory, over the limit of 1000" "$t/err"
then ok io_work_memory_limit
else no io_work_memory_limit "exit $rc: $(cat "$t/err")"; fi
awk 'BEGIN { print "renderer = raytracer"; print "canvas { width = 240 height = 240 }";
             print "viewport { width = 1 height = 1 d = 1 }";
             for (i = 0; i < 4096; i++)
               printf "sphere { center = (%d, %d, %d) radius = 0.4 color = (200, 100, 50) reflective = 0.5 }\n",
                      i % 16 - 8, int(i / 16) % 16 - 8, int(i / 256) + 5;
             for (i = 0; i < 64; i++) printf "light { type = point intensity = 0.01 position = (%d, 5, 0) }\n", i - 32 }' \
  >"$t/heavy.scene"
timeout 60 "$hs" --scene "$t/heavy.scene" --panel none --out "$t/heavy.png" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$t/err")" -eq 1 ] && grep -q "ray-object tests a frame.*over the limit" "$t/err" &&
   [ ! -e "$t/heavy.png" ]; then ok io_ray_tracer_cost_limit
else no io_ray_tracer_cost_limit "exit $rc: $(cat "$t/err")"; fi
# the rasterizer's frame estimated the same way (triangle-strip visits plus
# pixels, --max-cost): 4,096 instances of a 2,000-triangle fan at 4096x4096
# in 1-row strips are refused before any memory is allocated; the
# 16,384-triangle knots pass at the default limit; the scene's textures count
# in --max-memory (16 generated 1024x1024 trilinear textures, 67 MB)
awk 'BEGIN { print "rasterizer { shading = flat }"; print "light { type = ambient intensity = 1 }";
             printf "model { name = fan color = (200, 100, 50) vertices { (0, 0, 0)";
             for (i = 0; i <= 2000; i++) printf " (%.4f, %.4f, 0)", cos(i * 0.00314), sin(i * 0.00314);
             printf " } triangles {"; for (i = 1; i <= 2000; i++) printf " (0, %d, %d)", i + 1, i; print " } }";
             for (i = 0; i < 4096; i++) printf "instance { model = fan transform { translation = (%d, %d, 40) } }\n",
                                               i % 64 - 32, int(i / 64) - 32 }' >"$t/fans.scene"
timeout 120 "$hs" --scene "$t/fans.scene" --panel none --size 4096x4096 --strip-rows 1 --out "$t/fans.png" >/dev/null 2>"$t/err"
rc=$?
timeout 120 "$hs" --scene firmware/scenes/bench/knot-16k-gouraud.scene --panel none --size 240x240 --max-cost 100K \
  >/dev/null 2>>"$t/err"
rc2=$?
timeout 300 "$hs" --scene firmware/scenes/bench/knot-16k-flat.scene --panel none --size 960x960 --strip-rows 1 \
  --summary >/dev/null 2>>"$t/err"
rc3=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 2 ] && [ $rc3 -eq 0 ] && [ "$(wc -l <"$t/err")" -eq 2 ] &&
   grep -q "fans.scene: about 3.36e+10 triangle-strip visits and pixels a frame (8192000 triangles, lines and 2-D primitives x 4096 strips of 1 rows at 4096x4096), over the limit of 2e+10 (--max-cost to raise it)" "$t/err" &&
   grep -q "knot-16k-gouraud.scene: about .* over the limit of 1e+05" "$t/err" && [ ! -e "$t/fans.png" ]
then ok io_rasterizer_cost_limit
else no io_rasterizer_cost_limit "exit $rc/$rc2/$rc3: $(cat "$t/err")"; fi
# and scenec refuses its 402 MB work array under the default budget (m0plus)
"$sc" -o "$t/fans.c" "$t/fans.scene" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$t/err")" -eq 1 ] && [ ! -e "$t/fans.c" ] &&
   grep -q "fans.scene: needs [0-9]* bytes of RAM at 240x240 (renderer work memory [0-9]*), over the m0plus RAM budget of 3670016 bytes (--ram-budget or --target to change it)" "$t/err"
then ok io_scenec_work_array_over_default_budget
else no io_scenec_work_array_over_default_budget "exit $rc: $(cat "$t/err")"; fi
{ i=0; while [ $i -lt 16 ]; do
    echo "texture { name = t$i generate = checkerboard width = 1024 height = 1024 filter = trilinear }"; i=$((i + 1))
  done
  echo 'model { name = q vertices { (-1, -1, 0) (1, 1, 0) (1, -1, 0) } triangles { (0, 1, 2, color = (255, 0, 0), uv = ((0, 0), (1, 1), (1, 0))) } }'
  echo 'instance { model = q texture = t0 transform { translation = (0, 0, 5) } }'; } >"$t/tex16.scene"
timeout 120 "$hs" --scene "$t/tex16.scene" --panel none --size 64x64 --max-memory 64M --out "$t/tex16.png" >/dev/null 2>"$t/err"
rc=$?
timeout 120 "$hs" --scene "$t/tex16.scene" --panel none --size 64x64 --max-memory 65M --out "$t/tex16.png" >/dev/null 2>>"$t/err"
rc2=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 0 ] && [ "$(wc -l <"$t/err")" -eq 1 ] && [ -s "$t/tex16.png" ] &&
   grep -q "needs [0-9]* bytes of renderer work memory and 67108848 bytes of textures ([0-9]* in all), over the limit of 67108864 (--max-memory to raise it)" "$t/err"
then ok io_texture_memory_limit
else no io_texture_memory_limit "exit $rc/$rc2: $(cat "$t/err")"; fi
printf 'renderer = raytracer\nraytracer { recursion_depth = 16 }\nsphere { center = (0, 0, 3) radius = 1 color = (255, 0, 0) }\nlight { type = ambient intensity = 1 }\n' >"$t/deep.scene"
"$hs" --scene "$t/deep.scene" --size 16x16 --panel none >/dev/null 2>"$t/err"
rc=$?
"$sc" -o "$t/deep.c" "$t/deep.scene" >/dev/null 2>>"$t/err"
rc2=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 2 ] && [ "$(grep -c "recursion_depth must be in 0 .. 5, found 16" "$t/err")" -eq 2 ]
then ok io_recursion_depth_past_max_refused
else no io_recursion_depth_past_max_refused "exit $rc/$rc2: $(cat "$t/err")"; fi

# values the parser would change silently are errors (docs/scene-format.md,
# "Values changed"): a literal below the smallest normal double (it was read
# as 0, in the scene and in an OBJ file); a value given in the scene whose 0
# means something else that the chosen fixed-point format rounds to 0 (a
# light's intensity of 1e-9 at Q11.20), refused by host_sim's fixed core and
# by scenec alike, while the double core renders it
mkdir -p "$t/val"
printf 'sphere { center = (0, 0, 3) radius = 1e-400 color = (255, 0, 0) }\nlight { type = ambient intensity = 1 }\n' \
  >"$t/val/under.scene"
printf 'v 0 0 0\nv 1 0 1e-400\nv 0 1 0\nf 1 2 3\n' >"$t/val/u.obj"
printf 'model { name = u file = "u.obj" color = (255, 0, 0) }\ninstance { model = u transform { translation = (0, 0, 5) } }\n' \
  >"$t/val/obj.scene"
printf 'sphere { center = (0, 0, 3) radius = 1 color = (255, 0, 0) }\nlight { type = ambient intensity = 1e-9 }\nlight { type = ambient intensity = 1 }\n' \
  >"$t/val/tiny.scene"
: >"$t/err"
for f in under obj tiny; do
  "$hs" --scene "$t/val/$f.scene" --size 16x16 --panel none >/dev/null 2>>"$t/err"; echo "$?" >>"$t/rcs"
  "$sc" -o "$t/val/$f.c" "$t/val/$f.scene" >/dev/null 2>>"$t/err"; echo "$?" >>"$t/rcs"
done
"$hs" --scene "$t/val/tiny.scene" --size 16x16 --panel none --numeric double --summary >/dev/null 2>>"$t/err"
rc=$?
if [ "$(sort -u "$t/rcs")" = 2 ] && [ $rc -eq 0 ] && [ "$(wc -l <"$t/err")" -eq 6 ] &&
   [ "$(grep -c "under.scene:1:38: error: number 1e-400 is too small (under 2.22507e-308, it would be read as 0)" "$t/err")" -eq 2 ] &&
   [ "$(grep -c "u.obj:2:7: error: v: number 1e-400 is too small" "$t/err")" -eq 2 ] &&
   [ "$(grep -c "tiny.scene:1:1: error: light 0 intensity 1e-09 would be 0 in the format Q11.20 the scene needs (step 9.54e-07)" "$t/err")" -eq 2 ] &&
   [ ! -e "$t/val/under.c" ] && [ ! -e "$t/val/obj.c" ] && [ ! -e "$t/val/tiny.c" ]; then ok io_parser_no_silent_zero
else no io_parser_no_silent_zero "exits $(tr '\n' ' ' <"$t/rcs")/$rc: $(cat "$t/err")"; fi

# scenec: a scene over the target's budget is refused before anything is
# written (exit 2, one line naming the need, the budget and the option): 16
# generated 1024x1024 trilinear textures (67 MB of texels, 214 MB of C) over
# the default target's flash (m0plus), the 16,384-triangle knot's work memory
# over the RP2040's RAM, any scene over --ram-budget / --flash-budget; the
# same scene within a budget compiles
mkdir -p "$t/bud"
{ i=0; while [ $i -lt 16 ]; do
    echo "texture { name = t$i generate = checkerboard width = 1024 height = 1024 filter = trilinear }"; i=$((i + 1))
  done
  echo 'model { name = q vertices { (-1, -1, 0) (1, -1, 0) (1, 1, 0) } triangles { (0, 1, 2, color = (255, 0, 0), uv = ((0, 0), (1, 0), (1, 1))) } }'
  echo 'instance { model = q texture = t0 transform { translation = (0, 0, 5) } }'; } >"$t/bud/tex16.scene"
timeout 60 "$sc" -o "$t/bud/tex16.c" "$t/bud/tex16.scene" >/dev/null 2>"$t/err"
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$t/err")" -eq 1 ] &&
   grep -q "needs [0-9]* bytes of flash (the scene's const data, 67108848 of them textures), over the m0plus flash budget of 3670016 bytes (--flash-budget or --target to change it)" "$t/err" &&
   [ -z "$(ls -A "$t/bud" | grep -v tex16.scene)" ]; then ok io_scenec_flash_budget_textures
else no io_scenec_flash_budget_textures "exit $rc: $(cat "$t/err"); left: $(ls -A "$t/bud")"; fi
# (the 16,384-triangle Gouraud knot fits the RP2040 in 8- or 16-row strips, not
# with a whole frame's depth strip)
"$sc" --target rp2040 --strip-rows 240 -o "$t/bud/k.c" firmware/scenes/bench/knot-16k-gouraud.scene >/dev/null 2>"$t/err"
rc=$?
"$sc" --ram-budget 4K -o "$t/bud/r.c" "$S" >/dev/null 2>>"$t/err"
rc2=$?
"$sc" --flash-budget 1K -o "$t/bud/f.c" firmware/scenes/book/raster-11.scene >/dev/null 2>>"$t/err"
rc3=$?
"$sc" --target m4f --ram-budget 64K --flash-budget 1M -o "$t/bud/ok.c" firmware/scenes/book/raster-11.scene >"$t/out" 2>>"$t/err"
rc4=$?
"$sc" --target rp2050 -o "$t/bud/x.c" "$S" >/dev/null 2>>"$t/err"
rc5=$?
if [ $rc -eq 2 ] && [ $rc2 -eq 2 ] && [ $rc3 -eq 2 ] && [ $rc4 -eq 0 ] && [ $rc5 -eq 2 ] && [ "$(wc -l <"$t/err")" -eq 4 ] &&
   grep -q "knot-16k-gouraud.scene: needs [0-9]* bytes of RAM at 240x240 (renderer work memory [0-9]* + [0-9]* of a second core's context), over the rp2040 RAM budget of 228896 bytes (--ram-budget or --target to change it)" "$t/err" &&
   grep -q "raytracer-02.scene: needs [0-9]* bytes of RAM .*, over the RAM budget of 4096 bytes (--ram-budget)" "$t/err" &&
   grep -q "raster-11.scene: needs [0-9]* bytes of flash (the scene's const data, 0 of them textures), over the flash budget of 1024 bytes (--flash-budget)" "$t/err" &&
   grep -q "unknown --target 'rp2050' (did you mean 'rp2040'?)" "$t/err" &&
   grep -q "the budget (m4f, emulated Cortex-M4F, mps2-an386): RAM 65536, flash 1048576 bytes" "$t/out" && [ -s "$t/bud/ok.c" ] &&
   [ ! -e "$t/bud/k.c" ] && [ ! -e "$t/bud/r.c" ] && [ ! -e "$t/bud/f.c" ]; then ok io_scenec_ram_and_flash_budget
else no io_scenec_ram_and_flash_budget "exit $rc/$rc2/$rc3/$rc4/$rc5: $(cat "$t/err")"; fi

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
