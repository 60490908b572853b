#!/bin/sh
# SPDX-License-Identifier: MIT
# image_scene.sh — one scene of `make image` (mk/image.mk): its work memory
# measured on the target (tools/scenec/target_work.sh), then the scene
# compiled by tools/scenec into OUT.c and OUT.h, with OUT.log (scenec's
# report, ending in its scenec-summary line) and OUT.d (the files the scene
# made scenec read, as a make rule).
#   firmware/app/image_scene.sh IMAGE SCENEC PROBE SCENE WxH STRIP_ROWS ID OUT.c
# Exit 0; or 2 with one line "image IMAGE: MESSAGE" on stderr, for a scene
# scenec refuses in scenec's words (FILE:LINE:COLUMN: error: ...), else the
# work probe's. OUT.c and OUT.h are replaced only when scenec succeeds.
set -u
[ $# -eq 8 ] || { echo "usage: image_scene.sh IMAGE SCENEC PROBE SCENE WxH STRIP_ROWS ID OUT.c" >&2; exit 2; }
image=$1 scenec=$2 probe=$3 scene=$4 size=$5 strip=$6 id=$7 out=$8
base=${out%.c}
# the RP2040's flash budget (scenec --target rp2040's: 2 MB less 256 KB for
# the firmware); the work memory is image_fits.sh's to check, against what
# the linked image leaves
budget="--flash-budget 1792K"
fail() {
  echo "image $image: ${1:-$2}" >&2
  rm -f "$base.err" "$base.log.tmp" "$base.check.c" "$base.check.h"
  exit 2
}
# a scene with an accuracy target (a quality block): its work memory is that
# of the methods scenec chooses, measured on the scene text with them written
# (scenec --chosen-scene). A scene that reads files next to it cannot be
# measured there: scenec then reserves this host's size, which the image's
# check refuses (image_fits.sh wants the target's).
choice=""
if grep -q '^[[:space:]]*quality[[:space:]]*[{=]' "$scene" 2>/dev/null &&
   "$scenec" --size "$size" --strip-rows "$strip" --id "$id" $budget --chosen-scene "$base.chosen.scene" \
     -o "$base.check.c" "$scene" >/dev/null 2>&1 &&
   tw=$(tools/scenec/target_work.sh "$probe" "$base.chosen.scene" "${size%x*}" "${size#*x}" "$strip" 2>/dev/null); then
  choice=--work-of-choice
  rm -f "$base.check.c" "$base.check.h"
elif ! tw=$(tools/scenec/target_work.sh "$probe" "$scene" "${size%x*}" "${size#*x}" "$strip" 2>"$base.err"); then
  probe_err=$(head -n 1 "$base.err")
  if "$scenec" --size "$size" --strip-rows "$strip" --id "$id" $budget -o "$base.check.c" "$scene" \
     >/dev/null 2>"$base.err"; then
    fail "$probe_err" "the work probe failed on $scene"
  fi
  fail "$(head -n 1 "$base.err")" "scenec refused $scene"
fi
"$scenec" --size "$size" --strip-rows "$strip" --id "$id" --target-work "$tw" $choice $budget --deps "$base.d" -o "$out" \
  "$scene" >"$base.log.tmp" 2>"$base.err" || fail "$(head -n 1 "$base.err")" "scenec refused $scene"
mv "$base.log.tmp" "$base.log"
rm -f "$base.err"
