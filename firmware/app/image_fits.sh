#!/bin/sh
# SPDX-License-Identifier: MIT
# image_fits.sh — whether the scenes of `make image` (mk/image.mk) fit the
# RP2040 image, checked before the scenes are compiled for it and before it
# is linked.
#   firmware/app/image_fits.sh IMAGE CORES LINKER_SCRIPT BUDGET.elf NAME=LOG...
# BUDGET.elf is the image linked with the placeholder scene table
# (firmware/app/scenes_builtin.c, whose work buffers are work0 and work1)
# instead of the scenes: the same code in SRAM, data, strips and stacks. The
# scene table of the image (firmware/app/scene_table.sh) has instead a
# buffer for core 0 of the largest scene's work size and, with two cores
# (CORES), one for core 1 of the largest sibling size (core 1's context
# shares core 0's frame: render_init_sibling); the scenes are const data, in
# flash. So the work buffers have
#   LENGTH(RAM) - (__bss_end - ORIGIN(RAM) - work0 - work1)
# bytes together, with RAM the region of LINKER_SCRIPT. A scene needs the
# work and sibling sizes of the scenec-summary line of its LOG (scenec's
# report; the sizes measured on the target). NAME=LOG words have no spaces
# (mk/image.mk allows none in paths).
# Exit 0 with one line on stdout; or 2 with one line on stderr for each scene
# that does not fit:
#   image IMAGE: scene NAME needs W bytes of work on core 0 and S on core 1, the RP2040 two-core image has M
# (one core: "needs W bytes of work, the RP2040 one-core image has M"), or
# one line for two scenes that fit apart but not together (the buffers are
# sized by the largest of each):
#   image IMAGE: scenes A and B need W bytes of work on core 0 and S on core 1, the RP2040 two-core image has M
set -u
[ $# -ge 5 ] || { echo "usage: image_fits.sh IMAGE CORES LINKER_SCRIPT BUDGET.elf NAME=LOG..." >&2; exit 2; }
image=$1 cores=$2 ld=$3 elf=$4
shift 4
nm=${ARM_NM:-arm-none-eabi-nm}
die() { echo "image $image: $1" >&2; exit 2; }

# "RAM (rwx) : ORIGIN = 0x20000000, LENGTH = 256K"
s='[[:space:]]*'
origin_re="ORIGIN$s=$s\\(0x[0-9A-Fa-f]*\\)" length_re="LENGTH$s=$s\\([0-9]*\\)\\([KM]\\{0,1\\}\\)"
ram=$(sed -n "s/^${s}RAM$s([a-z]*)$s:$s$origin_re$s,$s$length_re.*/\\1 \\2 \\3/p" "$ld")
set -- "$@" -- $ram
pairs=
while [ "$1" != -- ]; do pairs="$pairs $1"; shift; done
shift
[ $# -ge 2 ] || die "$ld: no line 'RAM (...) : ORIGIN = ..., LENGTH = ...'"
origin=$(($1)) length=$2
case ${3:-} in K) length=$((length * 1024)) ;; M) length=$((length * 1048576)) ;; esac

syms=$("$nm" -S "$elf") || die "$nm -S $elf failed"
bss_end=$(printf '%s\n' "$syms" | awk '$NF == "__bss_end" { print $1 }')
placeholder=0 n=0
for sz in $(printf '%s\n' "$syms" | awk '($NF == "work0" || $NF == "work1") && NF == 4 { print $2 }'); do
  placeholder=$((placeholder + 0x$sz)) n=$((n + 1))
done
[ "$n" -eq 2 ] || placeholder=
[ -n "$bss_end" ] && [ -n "$placeholder" ] || die "$elf: no __bss_end, or not the placeholder's work0 and work1"
other=$((0x$bss_end - origin - placeholder))
has=$(((length - other) / 8 * 8))
case $cores in 1) kind=one-core ;; 2) kind=two-core ;; *) kind=$cores-core ;; esac

bad=0 most=0 most_name= most_s=0 most_s_name=
for p in $pairs; do
  name=${p%%=*} log=${p#*=}
  line=$(grep '^scenec-summary .*target=1 ' "$log" 2>/dev/null | tail -n 1)
  work=$(printf '%s\n' "$line" | sed -n 's/.* work=\([0-9][0-9]*\) .*/\1/p')
  sib=$(printf '%s\n' "$line" | sed -n 's/.* sibling=\([0-9][0-9]*\).*/\1/p')
  [ -n "$work" ] && [ -n "$sib" ] || die "$log: no scenec-summary line with the target's work and sibling sizes (target=1)"
  [ "$cores" -gt 1 ] || sib=0
  if [ $((work + sib)) -gt "$has" ]; then
    if [ "$cores" -gt 1 ]; then
      echo "image $image: scene $name needs $work bytes of work on core 0 and $sib on core 1, the RP2040 $kind image has $has" >&2
    else
      echo "image $image: scene $name needs $work bytes of work, the RP2040 $kind image has $has" >&2
    fi
    bad=1
  fi
  if [ "$work" -gt "$most" ]; then most=$work most_name=$name; fi
  if [ "$sib" -gt "$most_s" ]; then most_s=$sib most_s_name=$name; fi
done
[ "$bad" -eq 0 ] || exit 2
if [ $((most + most_s)) -gt "$has" ]; then
  echo "image $image: scenes $most_name and $most_s_name need $most bytes of work on core 0 and $most_s on core 1," \
       "the RP2040 $kind image has $has" >&2
  exit 2
fi
if [ "$cores" -gt 1 ]; then
  echo "image $image: at most $most bytes of work on core 0 ($most_name) and $most_s on core 1 ($most_s_name)," \
       "the RP2040 $kind image has $has ($length bytes of RAM, $other of them for code, data, strips and stacks)"
else
  echo "image $image: at most $most bytes of work ($most_name), the RP2040 $kind image has $has" \
       "($length bytes of RAM, $other of them for code, data, strips and stacks)"
fi
