#!/bin/sh
# SPDX-License-Identifier: MIT
# Models read from Wavefront OBJ files, end to end (tests/data/obj/): the
# imported mesh renders the same pixels as the same mesh typed out inline
# (a cube of quads with normals, uv and a PNG texture; a file of four
# materials whose three parts are an untextured one, a PNG and a PPM), in
# every numeric mode; the parts' colours and textures show, the right way
# up; `fit` scales a mesh in millimetres back to the cube (>= 50 dB); a bad
# file stops host_sim and scenec with exit status 2, one FILE:LINE:COLUMN
# line and no output; a torus of 8192 vertices and 16384 triangles renders.
#   tests/system/test_obj.sh HOST_SIM SCENEC
set -u
hs=${1:?usage: test_obj.sh HOST_SIM SCENEC}
scenec=${2:?usage: test_obj.sh HOST_SIM SCENEC}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
d=tests/data/obj

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }

# render SCENE OUT.raw [ARGS...]: host_sim's RGB565 frame of SCENE (exit status in $rc).
render() {
  scene=$1 out=$2
  shift 2
  "$hs" --scene "$scene" --panel none --out-raw "$out" "$@" >/dev/null 2>"$tmp/e"
  rc=$?
}

# ---- the imported mesh against the mesh typed out: the same pixels ----------
for pair in cube:240x240 two:120x120; do
  s=${pair%%:*} size=${pair#*:}
  for m in fixed float double; do
    render "$d/obj-$s.scene" "$tmp/a.raw" --size "$size" --numeric "$m"
    ra=$rc
    render "$d/obj-$s-inline.scene" "$tmp/b.raw" --size "$size" --numeric "$m"
    if [ "$ra" -ne 0 ] || [ "$rc" -ne 0 ]; then
      fail "obj_${s}_same_as_inline_$m" "exit $ra / $rc: $(cat "$tmp/e")"
    elif cmp -s "$tmp/a.raw" "$tmp/b.raw"; then
      pass "obj_${s}_same_as_inline_$m"
    else
      fail "obj_${s}_same_as_inline_$m" "the frames differ"
    fi
  done
done

# ---- every part shows: red, blue, tiles.png (its yellow row on top), stripes.ppm
"$hs" --scene "$d/obj-two.scene" --panel none --size 120x120 --out-rgb888 "$tmp/two.ppm" >/dev/null 2>"$tmp/e"
if msg=$(python3 - "$tmp/two.ppm" <<'PY' 2>&1
import sys
data = open(sys.argv[1], "rb").read()
head = data.split(b"\n", 3)
w, h = (int(x) for x in head[1].split())
px = head[3]
want = {"red": (255, 0, 0), "blue": (0, 0, 255), "yellow": (250, 220, 0), "cyan": (0, 200, 220),
        "magenta": (200, 0, 180), "orange": (240, 130, 0), "purple": (90, 40, 160)}
rows = {k: [] for k in want}
for y in range(h):
    for x in range(w):
        c = px[3 * (y * w + x):3 * (y * w + x) + 3]
        for k, v in want.items():
            if all(abs(c[i] - v[i]) <= 8 for i in range(3)):
                rows[k].append(y)
few = [k for k in want if len(rows[k]) < 50]
assert not few, "colours missing: %s" % few
# OBJ's v = 1 at the top of the image: the yellow row above the cyan and magenta ones
assert max(rows["yellow"]) < min(rows["cyan"]), "tiles.png upside down"
PY
); then pass obj_parts_show; else fail obj_parts_show "$msg"; fi

# ---- fit: cube-mm.obj (millimetres, centred at x = 40000) scaled to cube.obj ----
for m in fixed double; do
  "$hs" --scene "$d/obj-cube-fit.scene" --panel none --size 240x240 --numeric "$m" --out-rgb888 "$tmp/f.ppm" \
    >/dev/null 2>"$tmp/e"
  ra=$?
  "$hs" --scene "$d/obj-cube.scene" --panel none --size 240x240 --numeric "$m" --out-rgb888 "$tmp/c.ppm" \
    >/dev/null 2>>"$tmp/e"
  rb=$?
  if [ "$ra" -ne 0 ] || [ "$rb" -ne 0 ]; then
    fail "obj_fit_$m" "$(cat "$tmp/e")"
  elif msg=$(python3 - "$tmp/f.ppm" "$tmp/c.ppm" <<'PY' 2>&1
import math, sys
a, b = (open(p, "rb").read().split(b"\n", 3)[3] for p in sys.argv[1:3])
assert len(a) == len(b)
mse = sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)
psnr = math.inf if mse == 0 else 10 * math.log10(255 ** 2 / mse)
assert psnr >= 50, "PSNR %.2f dB" % psnr
PY
  ); then pass "obj_fit_$m"; else fail "obj_fit_$m" "$msg"; fi
done

# ---- a bad file: exit 2, one line naming the file, line and column, no output ----
cp "$d/cube.mtl" "$tmp/"
printf 'mtllib cube.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl violet\nf 1 2 3\nf 1 3 4\n' >"$tmp/bad.obj"
printf 'model { name = m file = "bad.obj" }\ninstance { model = m transform { translation = (0, 0, 5) } }\n' \
  >"$tmp/bad.scene"
"$hs" --scene "$tmp/bad.scene" --panel none --size 32x32 --out "$tmp/bad.png" >/dev/null 2>"$tmp/e"
rc=$?
if [ "$rc" -eq 2 ] && [ "$(wc -l <"$tmp/e")" -eq 1 ] && [ ! -e "$tmp/bad.png" ] &&
     grep -q "^$tmp/bad.obj:7:7: error: vertex index 4 is out of range (the file has 3)\$" "$tmp/e"; then
  pass obj_error_host_sim
else
  fail obj_error_host_sim "exit $rc: $(cat "$tmp/e")"
fi
"$scenec" -o "$tmp/bad.c" "$tmp/bad.scene" >/dev/null 2>"$tmp/e"
rc=$?
if [ "$rc" -eq 2 ] && [ ! -e "$tmp/bad.c" ] && [ ! -e "$tmp/bad.h" ] && grep -q "^$tmp/bad.obj:7:7: error: " "$tmp/e"; then
  pass obj_error_scenec
else
  fail obj_error_scenec "exit $rc: $(cat "$tmp/e")"
fi
rm "$tmp/cube.mtl"
"$hs" --scene "$tmp/bad.scene" --panel none --size 32x32 --out "$tmp/bad.png" >/dev/null 2>"$tmp/e"
rc=$?
if [ "$rc" -eq 2 ] && grep -q "^$tmp/bad.obj:1:8: error: cannot open material file '$tmp/cube.mtl': No such file or directory (its path is relative to the model file's directory)\$" "$tmp/e"; then
  pass obj_missing_material_file
else
  fail obj_missing_material_file "exit $rc: $(cat "$tmp/e")"
fi

# ---- scenec: the parts are models of the compiled scene ----------------------
if "$scenec" --size 120x120 -o "$tmp/two.c" "$d/obj-two.scene" >"$tmp/o" 2>"$tmp/e" &&
     grep -q '\.nmodels = 3, \.ninstances = 3, \.ntextures = 2' "$tmp/two.c" && grep -q '"two:2"' "$tmp/two.c"; then
  pass obj_scenec
else
  fail obj_scenec "$(cat "$tmp/e")"
fi

# ---- a large model: 8192 vertices, 16384 triangles ----------------------------
python3 tests/support/obj_torus.py 128 64 "$tmp/torus.obj"
cp tests/data/obj/torus.scene "$tmp/"
"$hs" --scene "$tmp/torus.scene" --panel none --size 240x240 --stats >"$tmp/o" 2>"$tmp/e"
rc=$?
if [ "$rc" -eq 0 ] && grep -q '"triangles_in":16384' "$tmp/o"; then
  pass obj_large_model
else
  fail obj_large_model "exit $rc: $(cat "$tmp/e") $(cat "$tmp/o")"
fi
