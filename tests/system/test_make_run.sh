#!/bin/sh
# SPDX-License-Identifier: MIT
# `make run` itself: renders every scene of firmware/scenes/ into a
# temporary OUT directory, one line per scene, each a 240x240 PNG at
# OUT/<scene>.png (subdirectories created); and the scene loop on a scene
# tree with subdirectories.
#   tests/system/test_make_run.sh BUILD
set -u
build=${1:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }

png_size() {
  sig=$(od -An -tx1 -N8 "$1" 2>/dev/null | tr -d ' \n')
  [ "$sig" = 89504e470d0a1a0a ] || { echo bad; return; }
  set -- $(od -An -tu1 -j16 -N8 "$1")
  echo "$(( ($1 << 24) | ($2 << 16) | ($3 << 8) | $4 ))x$(( ($5 << 24) | ($6 << 16) | ($7 << 8) | $8 ))"
}

# check_tree NAME SCENES OUT LOG: one line per scene naming it, a 240x240 PNG for each.
check_tree() {
  name=$1 scenes=$2 out=$3 log=$4
  n=0 bad=""
  for f in $(find "$scenes" -type f -name '*.scene' 2>/dev/null | LC_ALL=C sort); do
    n=$((n + 1))
    s=${f#"$scenes"/}
    s=${s%.scene}
    grep -q "^$s " "$log" || bad="$bad no-line:$s"
    [ "$(png_size "$out/$s.png")" = 240x240 ] || bad="$bad png:$s=$(png_size "$out/$s.png")"
  done
  lines=$(grep -c ' -> ' "$log")
  [ "$lines" -eq "$n" ] || bad="$bad $lines-lines-for-$n-scenes"
  if [ -z "$bad" ]; then pass "$name ($n scenes)"; else fail "$name" "$bad; output: $(head -c 600 "$log")"; fi
}

# The real target, as a user runs it (MAKEFLAGS of an outer make dropped).
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory run BUILD="$build" OUT="$tmp/out" \
  >"$tmp/log" 2>&1
rc=$?
if [ "$rc" -eq 0 ]; then pass make_run_status; else fail make_run_status "exit $rc: $(tail -n 5 "$tmp/log")"; fi
check_tree make_run_outputs firmware/scenes "$tmp/out" "$tmp/log"
grep -q '^make run: rendering every scene of firmware/scenes/' "$tmp/log" && pass make_run_says_rendering ||
  fail make_run_says_rendering "$(head -n 3 "$tmp/log")"

# The first build says what it builds and how far it is: with a build
# directory of nothing (make -n: the commands it would run, without running
# them), the line before the build and one line before each of the renderer
# core's number formats.
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory -n run BUILD="$tmp/fresh" OUT="$tmp/out4" \
  >"$tmp/log4" 2>&1
first=$(grep -c "^make run: building $tmp/fresh/host_sim: the renderer core once per number format (11 of 11" "$tmp/log4")
steps=$(grep -c '^make run:   \[[0-9]*/11\] the renderer core in [a-z0-9]*$' "$tmp/log4")
if [ "$first" -eq 1 ] && [ "$steps" -eq 11 ]; then pass make_run_first_build_progress
else fail make_run_first_build_progress "$first announcement(s), $steps progress lines: $(head -c 400 "$tmp/log4")"; fi

# The loop on a tree with nested directories (small test scenes).
mkdir -p "$tmp/sc/book" "$tmp/sc/extra/deep"
for s in book/one book/two extra/deep/three top; do cp tests/data/spheres.scene "$tmp/sc/$s.scene"; done
tools/run_scenes.sh "$build/host_sim" "$tmp/sc" "$tmp/out2" >"$tmp/log2" 2>&1
rc=$?
[ "$rc" -eq 0 ] && pass run_scenes_nested_status || fail run_scenes_nested_status "exit $rc: $(tail -n 3 "$tmp/log2")"
# Every scene renders, so the loop exits 0 and writes each PNG.
if [ "$rc" -eq 0 ]; then
  check_tree run_scenes_nested "$tmp/sc" "$tmp/out2" "$tmp/log2"
fi
# A failing scene is reported on its own line, the others still render, and
# the loop exits 1 (a stand-in host_sim that fails for one scene).
mkdir -p "$tmp/sc2"
for s in a broken c; do : >"$tmp/sc2/$s.scene"; done
cat >"$tmp/fake_host_sim" <<'SH'
#!/bin/sh
case "$2" in *broken*) echo "host_sim: $2: cannot open scene" >&2; exit 2 ;; esac
echo "fake 240x240"
SH
chmod +x "$tmp/fake_host_sim"
tools/run_scenes.sh "$tmp/fake_host_sim" "$tmp/sc2" "$tmp/out3" >"$tmp/log3" 2>&1
rc=$?
if [ "$rc" -eq 1 ] && grep -q '^broken: FAILED (exit 2): host_sim: ' "$tmp/log3" &&
   [ "$(grep -c ' -> ' "$tmp/log3")" -eq 2 ]; then
  pass run_scenes_failure
else
  fail run_scenes_failure "exit $rc: $(cat "$tmp/log3")"
fi
exit 0
