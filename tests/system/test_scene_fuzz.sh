#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs the scene parser's fuzz target for a bounded time over its corpus
# (tests/fuzz/corpus/scene, plus every scene under firmware/scenes, read
# only). New inputs go to a temporary directory, not into the tree.
#   tests/system/test_scene_fuzz.sh FUZZER SECONDS
set -u
fuzzer=$1
secs=${2:-20}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/new" "$work/scenes"
find firmware/scenes -name '*.scene' | while read -r f; do
  cp "$f" "$work/scenes/$(echo "$f" | tr '/' '_')"
done
if "$fuzzer" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
     -print_final_stats=1 -artifact_prefix="$work/" \
     "$work/new" tests/fuzz/corpus/scene "$work/scenes" >"$work/log" 2>&1; then
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/log" | grep -o '[0-9]*$')
  echo "PASS fuzz_scene_${secs}s (${runs:-?} inputs)"
else
  echo "FAIL fuzz_scene: the fuzzer found a failing input"
  grep -E 'ERROR|SUMMARY|Test unit written|^#' "$work/log" | tail -n 20
  for a in "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-*; do
    [ -f "$a" ] && { echo "input:"; od -c "$a" | head -n 10; }
  done
  exit 1
fi
