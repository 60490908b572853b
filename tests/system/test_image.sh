#!/bin/sh
# SPDX-License-Identifier: MIT
# make image (mk/image.mk): a two-core board image of scene files that lie
# outside the repository, in a temporary directory:
#   flat.scene   firmware/scenes/bench/cube-flat.scene, copied
#   tex.scene    bench/cube-textured with its texture read from tiles.ppm,
#                a file next to it
#   - the image is built (NAME.elf, NAME.uf2), its generated files under
#     BUILD only, and the work memory the check gave it is what the linked
#     image has;
#   - it runs on both emulated cores (rp2040js): each scene's 10 frames, then
#     the first scene again; frame 0 of each equals
#     host_sim --numeric fixed --num-frac F (F: the image's num_frac.h) bit
#     for bit, and frame 9 below the fps overlay;
#   - a new tiles.ppm compiles tex.scene again (not flat.scene), and the
#     image shows the new texture;
#   - refused, one line "image NAME: ..." and no image left: a scene scenec
#     refuses, a scene over the RP2040's flash (a 1024x1024 texture: 3 MB), a
#     missing scene file, a bad NAME, no SCENES, an unknown PANEL,
#     and a scene whose work memory does not fit (three spheres of 64 divisions),
#     with the bytes it needs and the bytes the image has, before the scene
#     is compiled for the board and the image linked.
#   - the image carries only the renderer features its scenes need
#     (fw_features.h: the cubes need neither the ray tracer nor chapter 15),
#     and a scene's C does not compile into an image without its features;
#   - a mesh (the 4,096-triangle knot of firmware/scenes/bench/, its OBJ
#     next to it): built with the core its features need in SRAM (the
#     default RP2040_RAM_TEXT), core 1 a sibling of core 0's context; its
#     frame 0 on both emulated cores equals host_sim's; the flash scenec
#     counted for the scene (its scenec-summary flash=, at the target's
#     sizes) is what the linked image's map places in flash from the
#     scene's object, within 1 %.
# ~60 s (two cores). usage: test_image.sh BUILD_DIR
set -u
b=${1:-build}
name=test-image
t=$(mktemp -d)
img=$b/firmware/pico/$name
set_dir=$b/firmware/image/$name
cleanup() { rm -rf "$t" "$set_dir" "$b/firmware/pico/obj-$name" "$img".elf "$img".bin "$img".uf2 "$img".map; }
trap cleanup EXIT
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }
# make as a user runs it (the MAKEFLAGS of an outer make dropped)
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory -j2 BUILD="$b" image NAME="$name" "$@"; }

mkdir -p "$t/my" "$t/big"
cp firmware/scenes/bench/cube-flat.scene "$t/my/flat.scene"
sed 's/^texture {.*}$/texture { name = tiles file = "tiles.ppm" filter = nearest }/' \
  firmware/scenes/bench/cube-textured.scene >"$t/my/tex.scene"
# tiles.ppm: 16x16 texels, checks of 4 in two colours (one of them the argument)
tiles() {
  python3 - "$t/my/tiles.ppm" "$1" <<'EOF'
import sys
c = bytes(int(v) for v in sys.argv[2].split(','))
px = b''.join(c if (x // 4 + y // 4) % 2 else bytes((20, 40, 200)) for y in range(16) for x in range(16))
open(sys.argv[1], 'wb').write(b'P6\n16 16\n255\n' + px)
EOF
}
tiles 250,200,40

# ---- the image --------------------------------------------------------------
if ! mk SCENES="$t/my/flat.scene $t/my/tex.scene" >"$t/out" 2>&1; then
  fail image_builds "$(tail -n 3 "$t/out")"
  exit 1
fi
if [ -s "$img.elf" ] && [ "$(od -An -tx1 -N4 "$img.uf2" 2>/dev/null | tr -d ' \n')" = 5546320a ]; then
  pass image_builds
else
  fail image_builds "no $img.elf or $img.uf2"
fi
extra=$(find "$t/my" -type f ! -name flat.scene ! -name tex.scene ! -name tiles.ppm)
if [ -z "$extra" ] && [ -s "$set_dir/fw_scenes.c" ] && [ -s "$set_dir/num_frac.h" ]; then
  pass image_generates_under_build_only
else
  fail image_generates_under_build_only "files next to the scenes: '$extra'; $set_dir: $(ls "$set_dir" 2>&1)"
fi
# the check's "N of them for code, data, strips and stacks" is what the image
# has besides its work buffers: __bss_end - RAM origin - sizeof fw_work0 -
# sizeof fw_work1 (core 0's context and core 1's sibling of it)
other=$(sed -n 's/.* bytes of RAM, \([0-9]*\) of them for code.*/\1/p' "$t/out")
syms=$(arm-none-eabi-nm -S "$img.elf")
end=$(printf '%s\n' "$syms" | awk '$NF == "__bss_end" { print $1 }')
w0=$(printf '%s\n' "$syms" | awk '$NF == "fw_work0" && NF == 4 { print $2 }')
w1=$(printf '%s\n' "$syms" | awk '$NF == "fw_work1" && NF == 4 { print $2 }')
if [ -n "$other" ] && [ -n "$end" ] && [ -n "$w0" ] && [ -n "$w1" ] && \
   [ $((0x$end - 0x20000000 - 0x$w0 - 0x$w1)) -eq "$other" ] && [ $((0x$w1)) -lt $((0x$w0)) ]; then
  pass "image_check_budget_equals_the_linked_image (core 0 $((0x$w0)) bytes of work, core 1 $((0x$w1)))"
else
  fail image_check_budget_equals_the_linked_image "check: '$other', image: ${end:-?} - 0x20000000 - ${w0:-?} - ${w1:-?}"
fi

# ---- the features --------------------------------------------------------------
f=$set_dir/fw_features.h
if grep -q '^#define FW_FEATURE_RAYTRACER 0$' "$f" && grep -q '^#define FW_FEATURE_RAS_CH15 0$' "$f" &&
   grep -q '^#define FW_FEATURE_RAS_FAST 1$' "$f" && ! printf '%s\n' "$syms" | grep -q ' rt_render_strip$'; then
  pass image_carries_only_its_features
else
  fail image_carries_only_its_features "$(cat "$f" 2>&1 | tr '\n' ' ')"
fi
# a scene's C against an image's features without one it needs: an #error naming it
if arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -std=c11 -DNUM_MODE=1 -DNUM_FRAC=12 -DFW_FEATURE_RAS_FAST=0 -Ifirmware/core \
     -c "$set_dir/s1_flat.c" -o "$t/s1.o" 2>"$t/ferr"; then
  fail image_scene_refuses_a_core_without_its_features "compiled"
elif grep -q 'needs the renderer feature RAS_FAST' "$t/ferr"; then
  pass image_scene_refuses_a_core_without_its_features
else
  fail image_scene_refuses_a_core_without_its_features "$(head -n 2 "$t/ferr")"
fi

# ---- on the emulated board ----------------------------------------------------
frac=$(sed -n 's/^#define NUM_FRAC \([0-9][0-9]*\)$/\1/p' "$set_dir/num_frac.h")
host() {   # host SCENE FRAMES OUT
  "$b/host_sim" --scene "$t/my/$1.scene" --size 240x240 --numeric fixed --num-frac "$frac" --frames "$2" \
    --out-raw "$3" >/dev/null 2>"$t/herr" || echo "host_sim: $(tail -n 1 "$t/herr")"
}
sim() {    # sim FRAMES DIR
  timeout 300 node tools/rp2040sim/rp2040sim.js --image "$img.elf" --frames "$1" --out-dir "$2" --json \
    >"$2.json" 2>"$t/simerr" || echo "rp2040sim: $(tail -n 1 "$t/simerr")"
}
# frame_is K SCENE FRAME: line K+1 of the JSON is frame FRAME of SCENE, two cores
frame_is() {
  sed -n "$(($1 + 1))p" "$t/pico.json" | grep "\"what\":\"scene:$2\"" | grep '"cores":2' | grep -q "\"frame\":$3,"
}
e=$(sim 21 "$t/pico")$(host flat 1 "$t/flat0.raw")$(host flat 10 "$t/flat9.raw")
e=$e$(host tex 1 "$t/tex0.raw")$(host tex 10 "$t/tex9.raw")
if [ -n "$e" ]; then
  fail image_runs_on_two_cores "$e"
else
  pass image_runs_on_two_cores
  skip=$((3 * 8 * 240 * 2))   # the fps overlay: rows 2-19 of the frames after the first
  for c in "0 flat 0 flat0 0" "9 flat 9 flat9 $skip" "10 tex 0 tex0 0" "19 tex 9 tex9 $skip" "20 flat 0 flat0 0"; do
    set -- $c
    case_name=image_frame_$1_is_$2_frame_$3_as_host_sim
    if ! frame_is "$1" "$2" "$3"; then
      fail "$case_name" "frame $1 is $(sed -n "$(($1 + 1))p" "$t/pico.json" | cut -c 1-120)"
    elif cmp -s -i "$5" "$t/$4.raw" "$t/pico/frame-$1.raw"; then
      pass "$case_name"
    else
      fail "$case_name" "$(cmp -i "$5" "$t/$4.raw" "$t/pico/frame-$1.raw" 2>&1 | head -n 1)"
    fi
  done
fi

# ---- a file the scene reads ---------------------------------------------------
touch "$t/marker"
tiles 40,230,90
if ! mk SCENES="$t/my/flat.scene $t/my/tex.scene" >"$t/out2" 2>&1; then
  fail image_follows_a_texture_file "$(tail -n 3 "$t/out2")"
elif [ -z "$(find "$set_dir/s2_tex.c" -newer "$t/marker")" ] ||
     [ -n "$(find "$set_dir/s1_flat.c" -newer "$t/marker")" ]; then
  fail image_follows_a_texture_file "tex.scene not compiled again, or flat.scene compiled again"
else
  e=$(sim 11 "$t/pico2")$(host tex 1 "$t/tex0b.raw")
  if [ -z "$e" ] && cmp -s "$t/tex0b.raw" "$t/pico2/frame-10.raw" && ! cmp -s "$t/tex0.raw" "$t/tex0b.raw"; then
    pass image_follows_a_texture_file
  else
    fail image_follows_a_texture_file "${e:-the image does not show the new texture}"
  fi
fi

# ---- refused ---------------------------------------------------------------------
# refused CASE PATTERN ARGS...: make fails, its one line "image NAME: ..."
# matches PATTERN, no line of the linker, and no image is left
refused() {
  case_name=$1 pattern=$2
  shift 2
  if env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory -j2 BUILD="$b" image "$@" >"$t/r" 2>&1; then
    fail "$case_name" "make succeeded"
  elif [ "$(grep -c 'image [^ ]*: ' "$t/r")" -ne 1 ] || ! grep 'image [^ ]*: ' "$t/r" | grep -q -- "$pattern"; then
    fail "$case_name" "$(cat "$t/r")"
  elif grep -q 'overflowed\|collect2\|ld returned' "$t/r"; then
    fail "$case_name" "the image was linked: $(cat "$t/r")"
  elif ls "$img".elf "$img".uf2 "$img".bin >/dev/null 2>&1; then
    fail "$case_name" "an image is left: $(ls "$img".*)"
  else
    pass "$case_name"
  fi
}
printf 'name = "x"\nrenderer = rasterizer\nbogus = 1\n' >"$t/my/bad.scene"
refused image_refuses_a_scene_scenec_refuses "^image $name: $t/my/bad.scene:3:1: error: unknown key 'bogus'\$" \
  NAME="$name" SCENES="$t/my/flat.scene $t/my/bad.scene"
{ echo 'texture { name = t generate = checkerboard width = 1024 height = 1024 }'
  echo 'model { name = q vertices { (-1, -1, 0) (1, 1, 0) (1, -1, 0) } triangles { (0, 1, 2, color = (255, 0, 0), uv = ((0, 0), (1, 1), (1, 0))) } }'
  echo 'instance { model = q texture = t transform { translation = (0, 0, 5) } }'; } >"$t/my/huge.scene"
refused image_refuses_a_scene_over_the_flash \
  "^image $name: scenec: $t/my/huge.scene: needs [0-9]* bytes of flash (the scene's const data, 3145728 of them textures), over the flash budget of 1835008 bytes (--flash-budget)\$" \
  NAME="$name" SCENES="$t/my/flat.scene $t/my/huge.scene"
refused image_refuses_a_missing_scene_file "^.*image $name: $t/my/none.scene: no such scene file" \
  NAME="$name" SCENES="$t/my/flat.scene $t/my/none.scene"
refused image_refuses_a_bad_name "NAME may have only letters, digits" NAME="my.image" SCENES="$t/my/flat.scene"
refused image_needs_scenes "SCENES=.* is needed" NAME="$name"
refused image_refuses_an_unknown_panel "PANEL=foo: not a panel" NAME="$name" SCENES="$t/my/flat.scene" PANEL=foo
cat >"$t/big/big.scene" <<'EOF'
name = "big"
renderer = rasterizer
canvas { width = 240 height = 240 }
viewport { width = 1 height = 1 d = 1 }
background = (0, 0, 0)
camera { position = (0, 0, 0) }
rasterizer { shading = gouraud }
light { type = ambient intensity = 0.2 }
light { type = directional intensity = 0.8 direction = (-1, 0, 1) }
model { name = m generate = sphere divs = 64 color = (0, 255, 0) }
instance { model = m transform { translation = (0, 0, 3) } }
instance { model = m transform { translation = (-1, 0, 4) } }
instance { model = m transform { translation = (1, 0, 4) } }
EOF
refused image_refuses_a_scene_that_does_not_fit \
  "^image $name: scene big.scene needs [0-9]* bytes of work on core 0 and [0-9]* on core 1, the RP2040 two-core image has [0-9]*\$" \
  NAME="$name" SCENES="$t/my/flat.scene $t/big/big.scene"
need=$(sed -n 's/.* needs \([0-9]*\) bytes of work on core 0 and \([0-9]*\) on core 1.*has \([0-9]*\)$/\1 \2 \3/p' "$t/r")
set -- $need 0 0 0
if [ $(($1 + $2)) -gt "$3" ] && [ "$3" -gt 0 ] && [ ! -e "$b/firmware/pico/obj-$name/$set_dir/s2_big.o" ]; then
  pass "image_does_not_fit_before_compiling_the_scene_for_the_board (needs $1 + $2, has $3)"
else
  fail image_does_not_fit_before_compiling_the_scene_for_the_board \
    "'$need'; $(ls "$b/firmware/pico/obj-$name/$set_dir" 2>&1)"
fi
# ---- a mesh ---------------------------------------------------------------------
mkdir -p "$t/mesh"
cp firmware/scenes/bench/knot-4k-gouraud.scene firmware/scenes/bench/knot-4k.obj "$t/mesh/"
if ! mk SCENES="$t/mesh/knot-4k-gouraud.scene" >"$t/r" 2>&1; then
  fail image_mesh_builds_with_its_features_in_sram "$(grep "^image" "$t/r" | head -n 1)"
else
  pass "image_mesh_builds_with_its_features_in_sram ($(sed -n 's/.*the RP2040 two-core image has \([0-9]*\).*/\1/p;s/.* \([0-9]*\) bytes of RAM, .*/\1/p' "$t/r" | head -n 1))"
  # the .rodata input sections of the scene's object at flash addresses (XIP, 0x10000000)
  log=$(ls "$set_dir"/s*_knot_4k_gouraud.log 2>/dev/null | head -n 1)
  est=$(sed -n 's/^scenec-summary .* flash=\([0-9]*\) .*/\1/p' "$log" 2>/dev/null)
  linked=$(python3 -c '
import re, sys
obj, n = "/" + sys.argv[2], 0
for m in re.finditer(r"^ (\.\S+)\s+(0x[0-9a-f]+)\s+(0x[0-9a-f]+)\s+(\S+\.o)$", open(sys.argv[1]).read(), re.M):
    sec, addr, size, path = m.groups()
    if sec.startswith(".rodata") and 0x10000000 <= int(addr, 16) < 0x20000000 and path.endswith(obj):
        n += int(size, 16)
print(n)' "$img.map" "$(basename "${log%.log}").o" 2>/dev/null)
  if [ -n "$est" ] && [ "${linked:-0}" -gt 0 ] && [ $((est * 100)) -ge $((linked * 99)) ] &&
     [ $((est * 100)) -le $((linked * 101)) ]; then
    pass "image_scene_flash_as_linked (scenec $est bytes, the image's $linked)"
  else
    fail image_scene_flash_as_linked "scenec '$est' bytes, the image's map '$linked' ($log)"
  fi
  frac=$(sed -n 's/^#define NUM_FRAC \([0-9][0-9]*\)$/\1/p' "$set_dir/num_frac.h")
  e=$(sim 1 "$t/knot")
  "$b/host_sim" --scene "$t/mesh/knot-4k-gouraud.scene" --size 240x240 --numeric fixed --num-frac "$frac" \
    --out-raw "$t/knot0.raw" >/dev/null 2>"$t/herr" || e="$e host_sim: $(tail -n 1 "$t/herr")"
  if [ -z "$e" ] && grep -q '"cores":2' "$t/knot.json" && cmp -s "$t/knot0.raw" "$t/knot/frame-0.raw"; then
    pass "image_mesh_frame_0_as_host_sim ($(sed -n 's/.*"fps":\([0-9.]*\).*/\1/p' "$t/knot.json" | head -n 1) fps)"
  else
    fail image_mesh_frame_0_as_host_sim "${e:-frames differ}"
  fi
fi
exit 0
