#!/bin/sh
# SPDX-License-Identifier: MIT
# scenec: every scene under firmware/scenes compiles to C; the C compiles for
# the firmware (arm-none-eabi-gcc, Cortex-M0+, fixed point at the NUM_FRAC
# scenec chose); the RAM it reserves (.bss) is the renderer's exact need ON
# THE TARGET (render_work_size run on the emulated Cortex-M0+ by the work
# probe) with no more than 10% slack; nothing lands in .data; the flash
# scenec counts (at the target's sizes, the probe's LAYOUT) is what the
# object's .rodata takes, within 1 % (tools/scenec/scene_layout.h). The compiled
# data equals the parsed scene field by field (host, fixed point, at the
# chosen format), and the renderers at the chosen format stay close to the
# double build (test_scene_fracs). A scene whose numbers cannot fit fails
# with the object and quantity named.
#   tests/system/test_scenec.sh SCENEC BUILD [--report]
# --report (make scenes-report): one line a scene instead, its format, the
# flash of its const data, its work memory (.bss of the compiled scene; the
# target's render_work_size and this host's), the renderer code an image of
# it alone carries (tools/scenec/scene_code.sh: the core with only its
# features) and those features (firmware/core/scene_features.def: the
# renderer, paths and span loops its options choose).
set -u
scenec=$1
build=$2
report=${3:-}
probe=$build/scenes/work_probe.elf
fracs=$build/asan/tests/test_scene_fracs
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc=arm-none-eabi-gcc
command -v $cc >/dev/null 2>&1 || cc=""
[ -n "$report" ] && printf '%-28s %8s %10s %10s %10s %10s %8s %8s  %s\n' scene num_frac flash_B work_B target_B host_B \
  slack code_B features
pairs=""
for f in $(find firmware/scenes -name '*.scene' | sort); do
  name=${f#firmware/scenes/}; name=${name%.scene}
  id=$(printf '%s' "$name" | tr -c 'A-Za-z0-9\n' '_')
  out="$work/$id.c"
  # the exact need: render_work_size on the target, measured here (not taken
  # from scenec), with the second core's (render_sibling_work_size) and the
  # target's sizes of the const data's types: WORK:SIBLING:LAYOUT
  if ! tw=$(tools/scenec/target_work.sh "$probe" "$f" 240 240 16 2>"$work/$id.perr"); then
    echo "FAIL scenec_target_work_$id: $(cat "$work/$id.perr")"
    continue
  fi
  target=${tw%%:*} sibling=${tw#*:}; sibling=${sibling%%:*}
  if ! "$scenec" --size 240x240 --strip-rows 16 --target-work "$tw" -o "$out" "$f" >"$work/$id.log" 2>&1; then
    echo "FAIL scenec_$id: $(tail -n 3 "$work/$id.log")"
    continue
  fi
  [ -z "$report" ] && echo "PASS scenec_$id"
  if [ -z "$report" ]; then
    hs=$(sed -n 's/^#define SCENE_[A-Z0-9_]*_SIBLING_WORK_SIZE \([0-9]*\)$/\1/p' "${out%.c}.h")
    if [ "$hs" = "$sibling" ] && [ "$sibling" -le "$target" ]; then
      echo "PASS scenec_sibling_work_$id ($sibling of $target bytes)"
    else
      echo "FAIL scenec_sibling_work_$id: header '$hs', probe $sibling, work $target"
    fi
  fi
  frac=$(sed -n 's/.*num_frac=\([0-9]*\).*/\1/p' "$work/$id.log")
  host=$(sed -n 's/.*host_work=\([0-9]*\).*/\1/p' "$work/$id.log")
  # fast Phong's specular tables in flash (scenec --spec-tables flash, the
  # default): the probe's need less their copies, which this host's core
  # counts as the target's (arrays of uint16_t and uint32_t): its work with
  # them made in work memory (--spec-tables ram) less the work without
  if grep -q '^scenec-summary .*features=[^ ]*RAS_FAST_PHONG' "$work/$id.log"; then
    if "$scenec" --size 240x240 --strip-rows 16 --spec-tables ram -o "$work/${id}_ram.c" "$f" >"$work/${id}_ram.log" 2>&1
    then
      hr=$(sed -n 's/.*host_work=\([0-9]*\).*/\1/p' "$work/${id}_ram.log")
      target=$((target - (hr - host)))
    else
      echo "FAIL scenec_spec_ram_$id: $(tail -n 3 "$work/${id}_ram.log")"
    fi
  fi
  est=$(sed -n 's/^scenec-summary .* flash=\([0-9]*\) .*/\1/p' "$work/$id.log")
  pairs="$pairs $f=$frac"
  echo "$f $id $frac" >>"$work/list"
  if [ -z "$cc" ]; then
    echo "FAIL scenec_firmware_$id: arm-none-eabi-gcc not installed (tools/deps.sh firmware)"
    continue
  fi
  if ! $cc -mcpu=cortex-m0plus -mthumb -Os -std=c11 -Wall -Wextra -Werror -DNUM_MODE=1 -DNUM_FRAC="$frac" \
       -Ifirmware/core -c "$out" -o "$work/$id.o" 2>"$work/$id.err"; then
    echo "FAIL scenec_firmware_$id: $(head -n 3 "$work/$id.err")"
    continue
  fi
  # sizes by section: text+rodata = flash, bss = RAM, data must be empty
  eval "$(arm-none-eabi-size -A "$work/$id.o" | awk '
    /^\.rodata|^\.text/ { fl += $2 } /^\.bss/ { bss += $2 } /^\.data/ { d += $2 }
    END { printf "flash=%d bss=%d data=%d\n", fl, bss, d }')"
  # the exact need is the target's work size (at least 1 byte: an array cannot be empty)
  exact=$target; [ "$exact" -lt 1 ] && exact=1
  slack=$(awk -v b="$bss" -v n="$exact" 'BEGIN { printf "%.1f%%", (b - n) * 100 / n }')
  if [ -n "$report" ]; then
    code=$(tools/scenec/scene_code.sh "$build/scenes/code" "${out%.c}.h" "$frac" 2>&1) || code="?"
    feats=$(sed -n 's/.* features=\([^ ]*\).*/\1/p' "$work/$id.log" | tr 'A-Z' 'a-z')
    printf '%-28s %8s %10s %10s %10s %10s %8s %8s  %s\n' "$name" "$frac" "$flash" "$bss" "$target" "$host" "$slack" \
      "${code#code=}" "$feats"
    continue
  fi
  if [ "$bss" -ge "$exact" ] && [ $((bss * 10)) -le $((exact * 11)) ] && [ "$data" -eq 0 ]; then
    echo "PASS scenec_ram_$id (target need $target B, .bss $bss B, host core $host B, flash $flash B)"
  else
    echo "FAIL scenec_ram_$id: .bss $bss B for a need of $exact B (more than 10% slack), .data $data B"
  fi
  if [ -n "$est" ] && [ $((est * 100)) -ge $((flash * 99)) ] && [ $((est * 100)) -le $((flash * 101)) ]; then
    echo "PASS scenec_flash_$id (scenec $est B, the object's $flash B)"
  else
    echo "FAIL scenec_flash_$id: scenec counts ${est:-no} bytes of flash, the object takes $flash B (more than 1 % apart)"
  fi
done
[ -n "$report" ] && exit 0

# The 7,350-vertex, 14,700-triangle Gouraud knot (tools/bench/gen_mesh.py
# --no-uv 245 30, bench/knot-16k-gouraud's scene otherwise) fits the two-core
# RP2040 image with all code in flash (RP2040_RAM_TEXT=0, 228,896 bytes of
# work: scenec --target rp2040's RAM budget): its work on the target, core 0 +
# core 1, with the 8-row strips `make image` builds, against that budget, and
# its const data at the target's sizes (1,264,636 bytes) against `make
# image`'s flash budget (--flash-budget 1792K). A mesh of 24,500 triangles
# (gen_mesh.py --no-uv 245 50) does not fit that flash: refused with the
# bytes it needs (its work is not measured: the target's sizes are the same
# for every scene).
mkdir "$work/k14"
if ! python3 tools/bench/gen_mesh.py --no-uv 245 30 "$work/k14/knot.obj" >/dev/null 2>"$work/k14/err"; then
  echo "FAIL scenec_rp2040_mesh_14k: gen_mesh.py: $(head -n 1 "$work/k14/err")"
else
  sed 's/"knot-16k.obj"/"knot.obj"/' firmware/scenes/bench/knot-16k-gouraud.scene >"$work/k14/knot.scene"
  if ! tw=$(tools/scenec/target_work.sh "$probe" "$work/k14/knot.scene" 240 240 8 2>"$work/k14/err"); then
    echo "FAIL scenec_rp2040_mesh_14k: $(cat "$work/k14/err")"
  elif "$scenec" --target rp2040 --flash-budget 1792K --size 240x240 --strip-rows 8 --target-work "$tw" \
       -o "$work/k14/knot.c" "$work/k14/knot.scene" >"$work/k14/log" 2>&1; then
    sib=${tw#*:}
    echo "PASS scenec_rp2040_mesh_14k (${tw%%:*} + ${sib%%:*} of 228896 bytes of work, \
$(sed -n 's/^scenec-summary .* flash=\([0-9]*\) .*/\1/p' "$work/k14/log") of 1835008 bytes of flash)"
  else
    echo "FAIL scenec_rp2040_mesh_14k: $(tail -n 2 "$work/k14/log")"
  fi
  if python3 tools/bench/gen_mesh.py --no-uv 245 50 "$work/k14/knot.obj" >/dev/null 2>"$work/k14/err"; then
    "$scenec" --target rp2040 --flash-budget 1792K --size 240x240 --strip-rows 8 --target-work "1:1:${tw##*:}" \
      -o "$work/k14/big.c" "$work/k14/knot.scene" >/dev/null 2>"$work/k14/err"
    rc=$?
    need=$(sed -n 's/.*: needs \([0-9]*\) bytes of flash (the scene.s const data, 0 of them textures), over the flash budget of 1835008 bytes (--flash-budget)$/\1/p' \
      "$work/k14/err")
    # 24,500 triangles of 80 bytes and 12,250 vertices of 12 on the target
    if [ "$rc" -eq 2 ] && [ -n "$need" ] && [ "$need" -gt $((24500 * 80 + 12250 * 12)) ] &&
       [ "$need" -lt $((24500 * 80 + 12250 * 12 + 1024)) ] && [ ! -e "$work/k14/big.c" ]; then
      echo "PASS scenec_rp2040_mesh_24k_over_flash (needs $need bytes)"
    else
      echo "FAIL scenec_rp2040_mesh_24k_over_flash: rc $rc $(head -n 1 "$work/k14/err")"
    fi
  else
    echo "FAIL scenec_rp2040_mesh_24k_over_flash: gen_mesh.py: $(head -n 1 "$work/k14/err")"
  fi
fi

# The compiled data equals the parsed scene field by field: one host program
# per format scenec chose (the generated files #error at a finer one).
hostcc=${CC:-cc}
for frac in $(awk '{ print $3 }' "$work/list" | sort -u); do
  tab="$work/table$frac.c"
  { echo '#include "scene.h"'
    echo 'struct scenec_entry { const char *path, *id; const struct scene *data; };'
    awk -v f="$frac" '$3 == f { print "extern const struct scene scene_" $2 ";" }' "$work/list"
    echo 'const struct scenec_entry scenec_table[] = {'
    awk -v f="$frac" '$3 == f { print "    { \"" $1 "\", \"" $2 "\", &scene_" $2 " }," }' "$work/list"
    echo '    { 0, 0, 0 } };'; } >"$tab"
  srcs=$(awk -v f="$frac" -v d="$work" '$3 == f { print d "/" $2 ".c" }' "$work/list")
  if ! $hostcc -std=c11 -D_POSIX_C_SOURCE=200809L -O1 -g -Wall -Wextra -Werror -fsanitize=address,undefined \
       -DNUM_MODE=1 -DNUM_FRAC="$frac" -I. -Ifirmware/core -Itools/scene -Itests/support -I"$work" \
       -o "$work/fields$frac" tests/unit/scenec_fields.c "$tab" $srcs tools/scene/scene_parse.c tools/scene/scene_depth.c firmware/core/num/*.c \
       firmware/core/mipmap.c -lm 2>"$work/fields$frac.err"; then
    echo "FAIL scenec_fields_frac$frac: $(head -n 3 "$work/fields$frac.err")"
    continue
  fi
  "$work/fields$frac"
done

# The renderers at the format scenec chose, against the double build.
if [ -x "$fracs" ]; then
  "$fracs" $pairs
else
  echo "FAIL scenec_formats_render: $fracs not built"
fi

# Formats that vary with the scene: the book's small raster scenes earn
# Q11.20; a planet-sized ground sphere forces Q18.13 (spheres alone: the
# tight argument of tools/scene/scene_format.c; Q19.12 by the doubled one).
for want in book/raster-06=20 demo/planet-horizon=13 book/raytracer-02=17 book/raytracer-05=16; do
  n=${want%=*} f=${want#*=}
  id=$(printf '%s' "$n" | tr -c 'A-Za-z0-9\n' '_')
  got=$(awk -v p="firmware/scenes/$n.scene" '$1 == p { print $3 }' "$work/list")
  if [ "$got" = "$f" ]; then echo "PASS scenec_format_$id (NUM_FRAC $f)"
  else echo "FAIL scenec_format_$id: NUM_FRAC ${got:-none}, expected $f"; fi
done
# --fracs limits the candidates; a coarser build of the data compiles, a finer one is refused
"$scenec" --fracs 16,12 -o "$work/r6.c" firmware/scenes/book/raster-06.scene >"$work/r6.log" 2>&1
if grep -q "num_frac=16" "$work/r6.log" && [ -n "$cc" ] && \
   $cc -mcpu=cortex-m0plus -mthumb -std=c11 -DNUM_MODE=1 -DNUM_FRAC=12 -Ifirmware/core -c "$work/r6.c" -o "$work/r6.o" 2>/dev/null && \
   ! $cc -mcpu=cortex-m0plus -mthumb -std=c11 -DNUM_MODE=1 -DNUM_FRAC=17 -Ifirmware/core -c "$work/r6.c" -o "$work/r6.o" 2>/dev/null; then
  echo "PASS scenec_format_guard"
else
  echo "FAIL scenec_format_guard: $(tail -n 1 "$work/r6.log")"
fi

# A scene that cannot fit: the book's ground sphere with the book's operation
# order (r^2 and |CO|^2 kept in num) needs more than any format has.
cat >"$work/ground.scene" <<'SCENE'
raytracer { formulation = book }
sphere { center = (0, -1, 3) radius = 1 color = (255, 0, 0) }
sphere { center = (0, -5001, 0) radius = 5000 color = (255, 255, 0) }
SCENE
if "$scenec" --fracs 16,12 -o "$work/ground.c" "$work/ground.scene" >"$work/g.log" 2>"$work/g.err"; then
  echo "FAIL scenec_refuses_overflow: accepted"
elif grep -q "error: sphere 1: .* exceeds the widest number format (|x| < 524288 at NUM_FRAC 12); use a plane, or formulation = robust" "$work/g.err"; then
  echo "PASS scenec_refuses_overflow"
else
  echo "FAIL scenec_refuses_overflow: $(cat "$work/g.err")"
fi
# The same refusal of positions past every format names scenec's option.
printf 'sphere { center = (0, 0, 3000000) radius = 100000 color = (255, 0, 0) }\n' >"$work/far.scene"
if "$scenec" -o "$work/far.c" "$work/far.scene" >"$work/f.log" 2>"$work/f.err"; then
  echo "FAIL scenec_refusal_hint: accepted"
elif grep -q "exceeds the widest number format .*; scale the scene down, or allow 64-bit intermediates for this scene (--allow-wide)$" "$work/f.err" &&
     [ ! -e "$work/far.c" ]; then
  echo "PASS scenec_refusal_hint"
else
  echo "FAIL scenec_refusal_hint: $(cat "$work/f.err")"
fi
# Bad input: the parser's message and exit status 2
printf 'sphere { radius = 1 }\n' >"$work/bad.scene"
"$scenec" -o "$work/bad.c" "$work/bad.scene" >/dev/null 2>"$work/b.err"; rc=$?
if [ "$rc" -eq 2 ] && grep -q "bad.scene:1:1: error: sphere: missing 'center'" "$work/b.err"; then
  echo "PASS scenec_bad_input_exit_2"
else
  echo "FAIL scenec_bad_input_exit_2: rc $rc $(cat "$work/b.err")"
fi
# --fast-textures flash: the fast path's texels as const data (8 KB of RGB565
# for the nearest 64x64 cube, 34,848 bytes of mip_fast_bilinear's words for the
# bilinear one), that much less work memory and more flash (and the scene's
# tex_fast, one pointer a texture); a bad value exit 2
for c in cube-textured:8192 cube-bilinear:34848; do
  n=${c%%:*} b=${c#*:}
  if "$scenec" -o "$work/fr.c" "firmware/scenes/bench/$n.scene" >"$work/fr.log" 2>&1 &&
     "$scenec" --fast-textures flash -o "$work/ff.c" "firmware/scenes/bench/$n.scene" >"$work/ff.log" 2>&1; then
    wr=$(sed -n 's/.* work=\([0-9]*\) .*/\1/p' "$work/fr.log") wf=$(sed -n 's/.* work=\([0-9]*\) .*/\1/p' "$work/ff.log")
    fr=$(sed -n 's/.* flash=\([0-9]*\) .*/\1/p' "$work/fr.log") ff=$(sed -n 's/.* flash=\([0-9]*\) .*/\1/p' "$work/ff.log")
    if [ $((wr - wf)) -eq "$b" ] && [ $((ff - fr)) -ge "$b" ] && [ $((ff - fr)) -le $((b + 8)) ] &&
       grep -q '\.tex_fast = tex_fast' "$work/ff.c" && ! grep -q 'tex_fast' "$work/fr.c"; then
      echo "PASS scenec_fast_textures_$n"
    else
      echo "FAIL scenec_fast_textures_$n: work $wr -> $wf, flash $fr -> $ff (want $b bytes moved)"
    fi
  else
    echo "FAIL scenec_fast_textures_$n: $(tail -n 2 "$work/ff.log")"
  fi
done
# --spec-tables (flash by default): fast Phong's specular tables as const
# data, one set per format the file may be compiled at (12 .. its own), that
# much less work memory (257 uint16_t and 2 uint32_t a table: bench/phong has
# one exponent, demo/spinning-crate two), one set more flash; ram writes none
for c in bench/phong:1:20 demo/spinning-crate:2:19; do
  n=${c%%:*} k=${c#*:}; k=${k%%:*} fr=${c##*:}
  if "$scenec" --spec-tables ram -o "$work/sr.c" "firmware/scenes/$n.scene" >"$work/sr.log" 2>&1 &&
     "$scenec" -o "$work/sf.c" "firmware/scenes/$n.scene" >"$work/sf.log" 2>&1; then
    wr=$(sed -n 's/.* work=\([0-9]*\) .*/\1/p' "$work/sr.log") wf=$(sed -n 's/.* work=\([0-9]*\) .*/\1/p' "$work/sf.log")
    flr=$(sed -n 's/.* flash=\([0-9]*\) .*/\1/p' "$work/sr.log") flf=$(sed -n 's/.* flash=\([0-9]*\) .*/\1/p' "$work/sf.log")
    b=$((k * (257 * 2 + 2 * 4))) sets=$(grep -c '^#\(el\)\{0,1\}if NUM_MODE == NUM_MODE_FIXED && NUM_FRAC == ' "$work/sf.c")
    if [ $((wr - wf)) -ge "$b" ] && [ $((wr - wf)) -le $((b + 8)) ] && [ $((flf - flr)) -eq "$b" ] &&
       [ "$sets" -eq $((fr - 11)) ] && grep -q "^#define SCENE_SPEC_TABLES $k\$" "$work/sf.c" &&
       ! grep -q 'spec_tab' "$work/sr.c"; then
      echo "PASS scenec_spec_tables_$n ($k tables, $sets formats: work $wr -> $wf, flash $flr -> $flf)"
    else
      echo "FAIL scenec_spec_tables_$n: work $wr -> $wf, flash $flr -> $flf, $sets formats (want $b bytes moved, $((fr - 11)) formats)"
    fi
  else
    echo "FAIL scenec_spec_tables_$n: $(tail -n 2 "$work/sf.log")"
  fi
done
"$scenec" --spec-tables rom -o "$work/sx.c" firmware/scenes/bench/phong.scene >/dev/null 2>"$work/sx.err"
rc=$?
if [ "$rc" -eq 2 ] && grep -q "bad --spec-tables 'rom' (ram or flash)" "$work/sx.err"; then
  echo "PASS scenec_spec_tables_bad"
else
  echo "FAIL scenec_spec_tables_bad: rc $rc $(cat "$work/sx.err")"
fi
"$scenec" --fast-textures rom -o "$work/fx.c" firmware/scenes/bench/cube-textured.scene >/dev/null 2>"$work/fx.err"
rc=$?
if [ "$rc" -eq 2 ] && grep -q "bad --fast-textures 'rom' (ram or flash)" "$work/fx.err"; then
  echo "PASS scenec_fast_textures_bad"
else
  echo "FAIL scenec_fast_textures_bad: rc $rc $(cat "$work/fx.err")"
fi
