#!/bin/sh
# SPDX-License-Identifier: MIT
# scene_code.sh — the renderer code an RP2040 image of one scene carries:
# the core compiled with the scene's features (its scenec header's
# SCENE_<ID>_FEATURE_<NAME> lines, through tools/scenec/features.sh) and
# format, as mk/firmware.mk compiles an image's core (Cortex-M0+, -O2, the
# span loops in .ram_text), linked with --gc-sections behind every entry
# point of render.h (tools/scenec/code_probe.c), with libgcc's helpers.
# usage: scene_code.sh CACHE_DIR HEADER NUM_FRAC
# Prints "code=BYTES" (.text, .rodata and .ram_text of the link, less the
# probe's own). Objects are kept in CACHE_DIR by the hash of their
# preprocessed source, so that scenes of the same features and format share
# them. Exit status 2 (one line) when the header has no features or a step
# fails.
set -eu
[ $# -eq 3 ] || { echo "usage: scene_code.sh CACHE_DIR HEADER NUM_FRAC" >&2; exit 2; }
cache=$1 header=$2 frac=$3
cc=${ARM_CC:-arm-none-eabi-gcc}
mkdir -p "$cache"
key=$(sed -n 's/^#define SCENE_[A-Za-z0-9_]*_FEATURES \(0x[0-9a-f]*\)u$/\1/p' "$header")
[ -n "$key" ] || { echo "scene_code.sh: $header: no SCENE_<ID>_FEATURES line (scenec of this tree?)" >&2; exit 2; }
feat="$cache/features-$key.h"
tools/scenec/features.sh "$feat" "$header"   # (rewritten only when it changes)
flags="-mcpu=cortex-m0plus -mthumb -O2 -std=c11 -ffunction-sections -fdata-sections -ffreestanding -fno-common
       -DRENDER_HOST_OUTPUTS=0 -DNUM_MODE=1 -DNUM_FRAC=$frac -DRAS_RAM_TEXT -include $feat -I. -Ifirmware/core"
objs=
for src in $(find firmware/core -name '*.c' | sort) tools/scenec/code_probe.c; do
  # shellcheck disable=SC2086
  h=$($cc $flags -E "$src" | cksum | tr ' ' '-')
  o="$cache/$(basename "$src" .c)-$h.o"
  if [ ! -f "$o" ]; then
    # shellcheck disable=SC2086
    $cc $flags -c "$src" -o "$o.tmp" || { echo "scene_code.sh: $src does not compile with $feat" >&2; exit 2; }
    mv "$o.tmp" "$o"
  fi
  objs="$objs $o"
done
elf="$cache/probe-$key-$frac.elf"
# shellcheck disable=SC2086
$cc -mcpu=cortex-m0plus -mthumb --specs=nano.specs -nostartfiles -Wl,-e,main -Wl,--gc-sections \
    -Wl,--no-warn-rwx-segments -o "$elf" $objs -lc -lgcc ||
  { echo "scene_code.sh: the probe does not link" >&2; exit 2; }
main=$(${ARM_NM:-arm-none-eabi-nm} -S "$elf" | awk '$4 == "main" { print $2 }')
${ARM_SIZE:-arm-none-eabi-size} -A "$elf" | awk -v probe="$(printf '%d' "0x${main:-0}")" '
  /^\.text|^\.rodata|^\.ram_text/ { n += $2 }
  END { printf "code=%d\n", n - probe }'
