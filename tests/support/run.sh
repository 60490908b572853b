#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs every test command given as an argument and totals the results.
#
# A test command prints one line per case: "PASS <name>", "FAIL <name>: <why>"
# or "SKIP <name>: <why>" (a case that could not run here; shown, and counted).
# A command that exits non-zero without printing a FAIL line (a crash, a
# sanitizer report, a missing program) counts as one failed case named after
# the command. Output of failing commands is shown; the last line is
# "N passed, N failed".
#
# Commands run TEST_JOBS at a time (default: the number of processors); each
# writes its own log, and the results are reported in the order given, so the
# report reads the same at any TEST_JOBS. Every test keeps its files in its
# own temporary directory, which is what makes running them side by side safe.
set -u
jobs=${TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
case $jobs in ''|*[!0-9]*|0) echo "run.sh: TEST_JOBS must be a positive integer, not '$jobs'" >&2; exit 2 ;; esac
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
i=0
for t in "$@"; do
  i=$((i + 1))
  printf '%s %s\n' "$i" "$t"
done >"$dir/list"
# A test command may carry arguments, written as prog:arg1:arg2.
# shellcheck disable=SC2016
xargs -P "$jobs" -L 1 sh -c 'cmd=$(printf "%s" "$2" | tr ":" " "); $cmd >"$0/$1.log" 2>&1; echo $? >"$0/$1.rc"' "$dir" <"$dir/list"
passed=0
failed=0
skipped=0
i=0
for t in "$@"; do
  i=$((i + 1))
  log=$dir/$i.log
  rc=$(cat "$dir/$i.rc" 2>/dev/null || echo 127)
  p=$(grep -c '^PASS ' "$log" 2>/dev/null)
  f=$(grep -c '^FAIL ' "$log" 2>/dev/null)
  k=$(grep -c '^SKIP ' "$log" 2>/dev/null)
  p=${p:-0} f=${f:-0} k=${k:-0}
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
    f=1
    echo "FAIL $t: exit status $rc"
  fi
  if [ "$f" -ne 0 ]; then
    echo "--- $t"
    grep -v '^PASS ' "$log" | tail -n 40
  else
    echo "ok   $t ($p)"
  fi
  [ "$k" -ne 0 ] && grep '^SKIP ' "$log"
  passed=$((passed + p))
  failed=$((failed + f))
  skipped=$((skipped + k))
done
if [ "$skipped" -ne 0 ]; then
  echo "$passed passed, $failed failed, $skipped skipped"
else
  echo "$passed passed, $failed failed"
fi
[ "$failed" -eq 0 ]
