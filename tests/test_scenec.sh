#!/bin/sh
# scenec: every scene under firmware/scenes compiles to C; the C compiles for
# the firmware (arm-none-eabi-gcc, Cortex-M0+, fixed point at the NUM_FRAC
# scenec chose); the RAM it reserves (.bss) is the renderer's exact need
# (render_work_size) with no more than 10% slack; nothing lands in .data.
# A scene whose numbers cannot fit fails with the object and quantity named.
#   tests/test_scenec.sh SCENEC BUILD [--report]
set -u
scenec=$1
build=$2
report=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc=arm-none-eabi-gcc
command -v $cc >/dev/null 2>&1 || cc=""
[ -n "$report" ] && printf '%-28s %8s %10s %10s %8s\n' scene num_frac flash_B ram_B slack
for f in $(find firmware/scenes -name '*.scene' | sort); do
  name=${f#firmware/scenes/}; name=${name%.scene}
  id=$(printf '%s' "$name" | tr -c 'A-Za-z0-9\n' '_')
  out="$work/$id.c"
  if ! "$scenec" --size 240x240 --strip-rows 16 -o "$out" "$f" >"$work/$id.log" 2>&1; then
    echo "FAIL scenec_$id: $(tail -n 3 "$work/$id.log")"
    continue
  fi
  [ -z "$report" ] && echo "PASS scenec_$id"
  frac=$(sed -n 's/.*num_frac=\([0-9]*\).*/\1/p' "$work/$id.log")
  need=$(sed -n 's/.*work=\([0-9]*\).*/\1/p' "$work/$id.log")
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
  # the exact need is the work size (at least 1 byte: an array cannot be empty)
  exact=$need; [ "$exact" -lt 1 ] && exact=1
  slack=$(awk -v b="$bss" -v n="$exact" 'BEGIN { printf "%.1f%%", (b - n) * 100 / n }')
  if [ -n "$report" ]; then
    printf '%-28s %8s %10s %10s %8s\n' "$name" "$frac" "$flash" "$bss" "$slack"
    continue
  fi
  if [ "$bss" -ge "$exact" ] && [ $((bss * 10)) -le $((exact * 11)) ] && [ "$data" -eq 0 ]; then
    echo "PASS scenec_ram_$id (work $need B, .bss $bss B, flash $flash B)"
  else
    echo "FAIL scenec_ram_$id: .bss $bss B for a need of $exact B (more than 10% slack), .data $data B"
  fi
done
[ -n "$report" ] && exit 0

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
# Bad input: the parser's message and exit status 2
printf 'sphere { radius = 1 }\n' >"$work/bad.scene"
"$scenec" -o "$work/bad.c" "$work/bad.scene" >/dev/null 2>"$work/b.err"; rc=$?
if [ "$rc" -eq 2 ] && grep -q "bad.scene:1:1: error: sphere: missing 'center'" "$work/b.err"; then
  echo "PASS scenec_bad_input_exit_2"
else
  echo "FAIL scenec_bad_input_exit_2: rc $rc $(cat "$work/b.err")"
fi
