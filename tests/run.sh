#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs every test command given as an argument and totals the results.
#
# A test command prints one line per case: "PASS <name>", "FAIL <name>: <why>"
# or "SKIP <name>: <why>" (a case that could not run here; shown, and counted). A command that exits non-zero without printing a
# FAIL line (a crash, a sanitizer report, a missing program) counts as one
# failed case named after the command. Output of failing commands is shown;
# the last line is "N passed, N failed".
set -u
passed=0
failed=0
skipped=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for t in "$@"; do
  # A test command may carry arguments, written as prog:arg1:arg2.
  cmd=$(printf '%s' "$t" | tr ':' ' ')
  # shellcheck disable=SC2086
  $cmd >"$log" 2>&1
  rc=$?
  p=$(grep -c '^PASS ' "$log")
  f=$(grep -c '^FAIL ' "$log")
  k=$(grep -c '^SKIP ' "$log")
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
