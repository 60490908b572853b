#!/bin/sh
# SPDX-License-Identifier: MIT
# The renderer's work memory for a scene on the target: runs the work probe
# image (tools/scenec/work_probe.c) on the emulated Cortex-M0+ and prints
# render_work_size() and render_sibling_work_size() (a second core's
# context) as the 32-bit firmware computes them, and the sizes of the types
# of a compiled scene's const data there (tools/scenec/scene_layout.h).
#   tools/scenec/target_work.sh PROBE.elf SCENE W H STRIP_ROWS
# Exit 0 with "WORK:SIBLING:LAYOUT" (two byte counts and the sizes, scenec's
# --target-work) on stdout; 2 with a one-line error on stderr.
# SCENE must not contain spaces or commas (qemu's argument syntax).
# TARGET_WORK_TIMEOUT: seconds the probe may run (default 300; a mesh of
# thousands of triangles is parsed in the emulator, slowly on a loaded machine).
set -u
[ $# -eq 5 ] || { echo "usage: target_work.sh PROBE.elf SCENE W H STRIP_ROWS" >&2; exit 2; }
case "$2" in *[\ ,]*) echo "target_work.sh: $2: no spaces or commas in scene paths" >&2; exit 2 ;; esac
command -v qemu-system-arm >/dev/null 2>&1 || { echo "target_work.sh: qemu-system-arm not found (tools/deps.sh bench)" >&2; exit 2; }
limit=${TARGET_WORK_TIMEOUT:-300}
case "$limit" in ''|*[!0-9]*) echo "target_work.sh: TARGET_WORK_TIMEOUT=$limit: not a number of seconds" >&2; exit 2 ;; esac
out=$(timeout "$limit" qemu-system-arm -M mps2-an385 -nographic -monitor none -serial null \
  -semihosting-config "enable=on,target=native,arg=probe,arg=$2,arg=$3,arg=$4,arg=$5" -kernel "$1" 2>&1)
rc=$?
if [ "$rc" -eq 124 ]; then
  echo "target_work.sh: $2: the probe ran longer than ${limit} s (TARGET_WORK_TIMEOUT)" >&2
  exit 2
fi
n=$(printf '%s\n' "$out" | sed -n 's/^WORK \([0-9][0-9]*\)$/\1/p')
m=$(printf '%s\n' "$out" | sed -n 's/^SIBLING \([0-9][0-9]*\)$/\1/p')
l=$(printf '%s\n' "$out" | sed -n 's/^LAYOUT \([a-z0-9=,]*\)$/\1/p')
if [ -z "$n" ] || [ -z "$m" ] || [ -z "$l" ]; then
  echo "target_work.sh: $2: $(printf '%s' "$out" | head -n 2 | tr '\n' ' ')" >&2
  exit 2
fi
echo "$n:$m:$l"
