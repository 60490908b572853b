#!/bin/sh
# SPDX-License-Identifier: MIT
# Mistakes that point at their fix: a misspelt option of host_sim or scenec
# or a misspelt scene key names the nearest valid one; a UTF-8 byte order
# mark opens a scene file; a missing image file names the path looked at;
# the no-lights warning names a key that exists; scenec --help; a model
# whose every triangle faces away is said, not drawn in silence.
#   tests/system/test_hints.sh HOST_SIM SCENEC
set -u
hs=${1:?usage: test_hints.sh HOST_SIM SCENEC}
sc=${2:?usage: test_hints.sh HOST_SIM SCENEC}
hs=$(cd "$(dirname "$hs")" && pwd)/$(basename "$hs")   # the test changes directory
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }

# expect NAME STATUS PATTERN PROGRAM ARGS...: exit status STATUS and one line
# on stderr, matching the fixed string PATTERN.
expect() {
  name=$1 want=$2 pat=$3
  shift 3
  "$@" >"$tmp/o" 2>"$tmp/e"
  rc=$?
  lines=$(wc -l <"$tmp/e" | tr -d ' ')
  if [ "$rc" -ne "$want" ]; then fail "$name" "exit $rc, want $want: $(head -c 300 "$tmp/e")"
  elif [ "$lines" -ne 1 ]; then fail "$name" "$lines lines on stderr: $(head -c 300 "$tmp/e")"
  elif ! grep -qF -- "$pat" "$tmp/e"; then fail "$name" "no '$pat' in: $(cat "$tmp/e")"
  else pass "$name"; fi
}

sphere='sphere { center = (0, 0, 3) radius = 1 color = (255, 0, 0) }'
light='light { type = ambient intensity = 1 }'
printf '%s\n%s\n' "$sphere" "$light" >"$tmp/ok.scene"

# ---- options: the nearest name ---------------------------------------------
expect host_sim_option_typo 2 "unknown option '--sceen' (did you mean '--scene'?" "$hs" --sceen "$tmp/ok.scene"
expect host_sim_option_typo_eq 2 "did you mean '--numeric'?" "$hs" --scene "$tmp/ok.scene" --numerc=fixed
expect host_sim_option_far 2 "unknown option '--frobnicate' (try --help)" "$hs" --scene "$tmp/ok.scene" --frobnicate
expect scenec_option_typo 2 "unknown option '--sizes' (did you mean '--size'?" "$sc" --sizes 240x240 -o "$tmp/x.c" "$tmp/ok.scene"
expect scenec_option_far 2 "unknown option '--frobnicate' (try --help)" "$sc" --frobnicate -o "$tmp/x.c" "$tmp/ok.scene"
expect scenec_missing_argument 2 "option --size needs an argument" "$sc" -o "$tmp/x.c" "$tmp/ok.scene" --size
expect scenec_bad_size 2 "bad size '10x0'" "$sc" --size 10x0 -o "$tmp/x.c" "$tmp/ok.scene"
expect scenec_bad_fracs 2 "bad --fracs '20,,12'" "$sc" --fracs 20,,12 -o "$tmp/x.c" "$tmp/ok.scene"
# ---- each bad value with its own reason, exit 2 ------------------------------
expect host_sim_size_zero 2 "bad size '0x0': width: 0 is less than 1" "$hs" --scene "$tmp/ok.scene" --size 0x0
expect host_sim_size_large 2 "bad size '99999x99999': width: larger than 8192" "$hs" --scene "$tmp/ok.scene" --size 99999x99999
expect host_sim_size_junk 2 "bad size '10x10junk': height: 'junk' after the number" "$hs" --scene "$tmp/ok.scene" --size 10x10junk
expect host_sim_size_no_x 2 "bad size '10X10': no 'x' between width and height" "$hs" --scene "$tmp/ok.scene" --size 10X10
expect host_sim_strip_junk 2 "bad strip height '16abc': 'abc' after the number" "$hs" --scene "$tmp/ok.scene" --strip-rows 16abc
expect scenec_size_zero 2 "bad size '0x0': width: 0 is less than 1" "$sc" --size 0x0 -o "$tmp/x.c" "$tmp/ok.scene"
expect scenec_size_large 2 "bad size '99999x99999': width: larger than 4096" "$sc" --size 99999x99999 -o "$tmp/x.c" "$tmp/ok.scene"
expect scenec_size_junk 2 "bad size '10x10junk': height: 'junk' after the number" "$sc" --size 10x10junk -o "$tmp/x.c" "$tmp/ok.scene"
expect scenec_strip_junk 2 "bad strip height '16abc': 'abc' after the number" "$sc" --strip-rows 16abc -o "$tmp/x.c" "$tmp/ok.scene"
expect scenec_fracs_range 2 "bad --fracs '21': item 1: larger than 20" "$sc" --fracs 21 -o "$tmp/x.c" "$tmp/ok.scene"
expect scenec_scene_directory 2 "cannot open file: is a directory" "$sc" -o "$tmp/x.c" "$tmp"
expect scenec_no_output 2 "-o OUT.c is required" "$sc" "$tmp/ok.scene"
expect scenec_no_scene 2 "a scene file is required" "$sc" -o "$tmp/x.c"

# ---- scenec --help: every option, the defaults, the exit statuses, exit 0 ----
"$sc" --help >"$tmp/help" 2>"$tmp/e"
rc=$?
missing=""
for o in -o --size --strip-rows --fracs --id --allow-wide --target-work --deps --target --ram-budget \
         --flash-budget "default m0plus" --help "default 240x240" \
         "default 16" "exit status"; do
  grep -qF -- "$o" "$tmp/help" || missing="$missing $o"
done
if [ "$rc" -eq 0 ] && [ -z "$missing" ] && [ ! -s "$tmp/e" ]; then pass scenec_help
else fail scenec_help "exit $rc, missing:$missing"; fi
"$sc" -h >"$tmp/help2" 2>&1
cmp -s "$tmp/help" "$tmp/help2" && pass scenec_help_short || fail scenec_help_short "-h differs from --help"
# and every option the help lists is one scenec takes (no "unknown option")
for o in $(grep -o -- '--[a-z-]*' "$tmp/help" | sort -u); do
  "$sc" "$o" >/dev/null 2>"$tmp/e"
  if grep -q "unknown option" "$tmp/e"; then fail "scenec_help_option[$o]" "$(cat "$tmp/e")"; fi
done

# ---- scene keys and values: the nearest name ---------------------------------
printf 'sphere { center = (0, 0, 3) raduis = 1 color = (255, 0, 0) }\n%s\n' "$light" >"$tmp/k.scene"
expect scene_key_typo 2 "unknown key 'raduis' in sphere (did you mean 'radius'?)" "$hs" --scene "$tmp/k.scene" --panel none
printf '%s\n%s\nraytracer { lightning = off }\n' "$sphere" "$light" >"$tmp/k2.scene"
expect scene_option_typo 2 "unknown key 'lightning' in raytracer (did you mean 'lighting'?)" "$hs" --scene "$tmp/k2.scene"
printf '%s\nlights { type = ambient intensity = 1 }\n' "$sphere" >"$tmp/k3.scene"
expect scene_top_key_typo 2 "unknown key 'lights' (did you mean 'light'?)" "$hs" --scene "$tmp/k3.scene"
printf '%s\n%s\nrenderer = raytrace\n' "$sphere" "$light" >"$tmp/k4.scene"
expect scene_value_typo 2 "unknown value 'raytrace' (did you mean 'raytracer'?" "$hs" --scene "$tmp/k4.scene"
printf '%s\n%s\nwobble = 1\n' "$sphere" "$light" >"$tmp/k5.scene"
expect scene_key_far 2 "unknown key 'wobble'" "$hs" --scene "$tmp/k5.scene"
if grep -q "did you mean" "$tmp/e"; then fail scene_key_far_no_guess "$(cat "$tmp/e")"; else pass scene_key_far_no_guess; fi
expect scenec_scene_key_typo 2 "(did you mean 'radius'?)" "$sc" -o "$tmp/x.c" "$tmp/k.scene"

# ---- a UTF-8 byte order mark before the scene ------------------------------
printf '\357\273\277%s\n%s\n' "$sphere" "$light" >"$tmp/bom.scene"
"$hs" --scene "$tmp/bom.scene" --panel none --size 16x16 --out "$tmp/bom.png" 2>"$tmp/e"
rc=$?
"$hs" --scene "$tmp/ok.scene" --panel none --size 16x16 --out "$tmp/nobom.png" 2>/dev/null
if [ "$rc" -eq 0 ] && [ ! -s "$tmp/e" ] && cmp -s "$tmp/bom.png" "$tmp/nobom.png"; then pass scene_bom_accepted
else fail scene_bom_accepted "exit $rc: $(cat "$tmp/e")"; fi
# positions after it are counted as without it
printf '\357\273\277sphere { center = (0, 0, 3) raduis = 1 color = (255, 0, 0) }\n' >"$tmp/bom2.scene"
expect scene_bom_columns 2 "bom2.scene:1:29: error: unknown key 'raduis'" "$hs" --scene "$tmp/bom2.scene"
# a BOM anywhere else is still a stray byte
printf '%s\n\357\273\277%s\n' "$sphere" "$light" >"$tmp/bom3.scene"
expect scene_bom_inside 2 "unexpected byte 0xef" "$hs" --scene "$tmp/bom3.scene"

# ---- a missing image file: the path looked at ------------------------------
mkdir -p "$tmp/sub"
cat >"$tmp/sub/tex.scene" <<'S'
texture { name = t file = "crate.png" }
model { name = q vertices { (0, 0, 0) (1, 0, 0) (0, 1, 0) } color = (255, 0, 0)
        triangles { (0, 1, 2, uv = ((0, 0), (1, 0), (0, 1))) } }
instance { model = q texture = t transform { translation = (0, 0, 3) } }
S
expect missing_texture_path 2 "cannot open image file '$tmp/sub/crate.png': No such file or directory" \
  "$hs" --scene "$tmp/sub/tex.scene"
( cd "$tmp/sub" && "$hs" --scene tex.scene ) >/dev/null 2>"$tmp/e"
real=$(cd "$tmp/sub" && pwd -P)
if grep -qF "'$real/crate.png'" "$tmp/e" || grep -qF "'$tmp/sub/crate.png'" "$tmp/e"; then pass missing_texture_path_absolute
else fail missing_texture_path_absolute "$(cat "$tmp/e")"; fi
sed 's/texture { name = t file = "crate.png" }//; s/ texture = t//; s/q vertices/q file = "gone.obj" fit = 1 } #/; s/^        triangles.*//' \
  "$tmp/sub/tex.scene" >"$tmp/sub/obj.scene"
expect missing_model_path 2 "cannot open model file '$tmp/sub/gone.obj'" "$hs" --scene "$tmp/sub/obj.scene"

# ---- no lights: the warning names a key that exists ------------------------
printf '%s\n' "$sphere" >"$tmp/dark.scene"
"$hs" --scene "$tmp/dark.scene" --panel none --size 8x8 --out "$tmp/d.png" 2>"$tmp/e"
key=$(sed -n 's/.*or \(raytracer { [a-z_]* = [a-z]* }\).*/\1/p' "$tmp/e")
printf '%s\n%s\n' "$sphere" "$key" >"$tmp/dark2.scene"
if [ -n "$key" ] && "$hs" --scene "$tmp/dark2.scene" --panel none --size 8x8 --out "$tmp/d2.png" 2>"$tmp/e2" &&
   [ ! -s "$tmp/e2" ]; then pass no_lights_names_real_key
else fail no_lights_names_real_key "warning '$(cat "$tmp/e")', its advice: $(cat "$tmp/e2")"; fi

# ---- culling: a model wound the other way is said, and not counted as drawn -
cat >"$tmp/ccw.scene" <<'S'
model { name = quad color = (255, 0, 0)
        vertices { (-1, -1, 0) (1, -1, 0) (1, 1, 0) (-1, 1, 0) }
        triangles { (0, 1, 2) (0, 2, 3) } }
instance { model = quad transform { translation = (0, 0, 4) } }
S
sed 's/(0, 1, 2) (0, 2, 3)/(0, 2, 1) (0, 3, 2)/' "$tmp/ccw.scene" >"$tmp/cw.scene"
drawn() { sed -n 's/.*"triangles_drawn":\([0-9]*\).*/\1/p' "$1"; }
for path in default book; do
  extra=""
  [ $path = book ] && extra="rasterizer { book_exact = on }"
  for f in ccw cw; do { cat "$tmp/$f.scene"; echo "$extra"; } >"$tmp/$f-$path.scene"; done
  "$hs" --scene "$tmp/ccw-$path.scene" --stats --out "$tmp/ccw.png" >"$tmp/o" 2>"$tmp/e"
  rc=$?
  if [ $rc -eq 0 ] && [ "$(wc -l <"$tmp/e")" -eq 1 ] && [ "$(drawn "$tmp/o")" = 0 ] &&
     grep -qF "instance 0 (model 'quad'): all 2 of its triangles face away and are culled" "$tmp/e" &&
     grep -qF "rasterizer { cull = off }" "$tmp/e"; then pass "culled_instance_warned[$path]"
  else fail "culled_instance_warned[$path]" "exit $rc, drawn '$(drawn "$tmp/o")': $(cat "$tmp/e")"; fi
  "$hs" --scene "$tmp/cw-$path.scene" --stats --out "$tmp/cw.png" >"$tmp/o" 2>"$tmp/e"
  rc=$?
  if [ $rc -eq 0 ] && [ ! -s "$tmp/e" ] && [ "$(drawn "$tmp/o")" = 2 ]; then pass "front_facing_quad_drawn[$path]"
  else fail "front_facing_quad_drawn[$path]" "exit $rc, drawn '$(drawn "$tmp/o")': $(cat "$tmp/e")"; fi
done
{ cat "$tmp/ccw.scene"; echo "rasterizer { cull = off }"; } >"$tmp/nocull.scene"
"$hs" --scene "$tmp/nocull.scene" --stats --out "$tmp/n.png" >"$tmp/o" 2>"$tmp/e"
if [ $? -eq 0 ] && [ ! -s "$tmp/e" ] && [ "$(drawn "$tmp/o")" = 2 ]; then pass cull_off_no_warning
else fail cull_off_no_warning "drawn '$(drawn "$tmp/o")': $(cat "$tmp/e")"; fi

# ---- standing inside a huge sphere: refused for fixed point and float ------
cat >"$tmp/inside.scene" <<'S'
sphere { center = (0, 0, 0) radius = 40000 color = (0, 0, 255) specular = 10 }
sphere { center = (0, -1, 3) radius = 1 color = (255, 0, 0) specular = 500 }
light { type = ambient intensity = 0.2 }
light { type = point intensity = 0.6 position = (2, 1, 0) }
S
for n in fixed float; do
  expect "inside_huge_sphere_refused[$n]" 2 "the camera stands inside sphere 0 (radius 40000)" \
    "$hs" --scene "$tmp/inside.scene" --numeric $n --size 32x32 --panel none --out "$tmp/i.png"
done
expect inside_huge_sphere_refused_compare_float 2 "inside sphere 0" "$hs" --scene "$tmp/inside.scene" \
  --numeric double --compare float --size 32x32 --panel none --summary
expect inside_huge_sphere_refused_scenec 2 "inside sphere 0" "$sc" -o "$tmp/i.c" "$tmp/inside.scene"
"$hs" --scene "$tmp/inside.scene" --numeric double --size 32x32 --panel none --out "$tmp/i.png" 2>"$tmp/e" &&
  pass inside_huge_sphere_double_renders || fail inside_huge_sphere_double_renders "$(cat "$tmp/e")"
# below the limit it renders, at 20 dB or more in both
sed 's/radius = 40000/radius = 3000/' "$tmp/inside.scene" >"$tmp/inside3k.scene"
for n in fixed float; do
  "$hs" --scene "$tmp/inside3k.scene" --numeric $n --size 96x96 --panel none --compare double --stats >"$tmp/o" 2>"$tmp/e"
  rc=$?
  p=$(sed -n 's/.*"psnr":\([0-9.]*\).*/\1/p' "$tmp/o" | tail -n 1)
  if [ $rc -eq 0 ] && [ -n "$p" ] && awk "BEGIN { exit !($p >= 20) }"; then pass "inside_sphere_3000_renders[$n] ($p dB)"
  else fail "inside_sphere_3000_renders[$n]" "exit $rc, psnr '$p': $(cat "$tmp/e")"; fi
done
