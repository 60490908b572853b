#!/bin/sh
# SPDX-License-Identifier: MIT
# Renders every scene under SCENES (recursively, *.scene) through host_sim
# on the emulated ST7789 at 240x240 in fixed point, into OUT/<scene>.png,
# and prints one line per scene: name, size, numeric, panel, render time per
# frame, and the accuracy of the fixed-point colours against the double
# build at the same size (PSNR over 8-bit RGB, largest channel error).
#   tools/run_scenes.sh HOST_SIM SCENES OUT
# Exit status 0 if every scene rendered, 1 otherwise (the failing scenes'
# messages are shown).
set -u
host_sim=$1
scenes=${2%/}
out=${3%/}

if [ ! -x "$host_sim" ]; then
  echo "run_scenes.sh: $host_sim is not built" >&2
  exit 1
fi
mkdir -p "$out" || exit 1

list=$(mktemp)
err=$(mktemp)
trap 'rm -f "$list" "$err"' EXIT
if [ -d "$scenes" ]; then
  find "$scenes" -type f -name '*.scene' | LC_ALL=C sort >"$list"
fi
total=$(wc -l <"$list" | tr -d ' ')
if [ "$total" -eq 0 ]; then
  echo "no scenes under $scenes/"
  exit 0
fi

failed=0
while IFS= read -r f; do
  name=${f#"$scenes"/}
  name=${name%.scene}
  case "$name" in */*) mkdir -p "$out/${name%/*}" ;; esac
  if line=$("$host_sim" --scene "$f" --panel st7789 --numeric fixed \
      --out "$out/$name.png" --compare double --summary 2>"$err"); then
    # host_sim names the scene after its path; say it relative to SCENES.
    rest=$(printf '%s\n' "$line" | sed 's/^[^ ]* *//')
    printf '%-28s %s -> %s\n' "$name" "$rest" "$out/$name.png"
  else
    rc=$?
    failed=$((failed + 1))
    echo "$name: FAILED (exit $rc): $(head -n 1 "$err")"
  fi
done <"$list"

echo "$((total - failed)) of $total scenes rendered into $out/"
[ "$failed" -eq 0 ]
