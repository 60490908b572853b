#!/bin/sh
# SPDX-License-Identifier: MIT
# The fixed-point build of the renderer core links no floating-point code.
#
# Cross-compiles every C file of firmware/core (and its folders) for the Cortex-M0+ (ARMv6-M, no FPU)
# with NUM_MODE=1 and inspects the undefined symbols of each object: any
# soft-float routine (__aeabi_f*, __aeabi_d*, conversions to float/double,
# libgcc's *sf*/*df* helpers) or libm function fails the test. The numeric
# layer's own objects (firmware/core/num/) must also avoid the software divide routines (the M0+
# has no divide instruction). Then the float build for the Cortex-M4F (single-
# precision FPU) is checked for double-precision code (see below).
# Usage: test_softfloat.sh BUILD_DIR
set -u
build=${1:-build}/m0plus-softfloat-check
cc=arm-none-eabi-gcc
nm=arm-none-eabi-nm
if ! command -v $cc >/dev/null 2>&1; then
  echo "FAIL core_fixed_no_softfloat: $cc not found (make deps-firmware)"
  exit 1
fi
mkdir -p "$build"
flags="-std=c11 -O2 -mcpu=cortex-m0plus -mthumb -ffunction-sections -DNUM_MODE=1 -I. -Ifirmware/core -Ihal -Itools/scene"
softfloat='^(__aeabi_[fd].*|__aeabi_[a-z0-9]*2[fd]|__(add|sub|mul|div|neg|cmp|eq|ne|lt|le|gt|ge|unord)[sd]f[23]|__(fix|fixuns|float|floatun|extend|trunc)[a-z]*[sd]f[a-z0-9]*)$'
libm='^(sqrt|sqrtf|pow|powf|sin|sinf|cos|cosf|tan|tanf|atan|atanf|atan2|atan2f|exp|expf|log|logf|floor|floorf|ceil|ceilf|fabs|fabsf|fmod|fmodf|ldexp|ldexpf|rint|rintf|lrint|round|roundf|trunc|truncf|hypot|hypotf)$'
divide='^__aeabi_(u?idiv|u?idivmod|u?ldivmod)$'
bad=0; nobj=0; errs=""
for src in $(find firmware/core -name '*.c' | sort); do
  obj="$build/$(echo "${src#firmware/core/}" | tr / _ | sed 's/\.c$//').o"
  if ! $cc $flags -c "$src" -o "$obj" 2>"$obj.err"; then
    echo "FAIL core_fixed_cross_compiles: $src does not build for cortex-m0plus:"
    head -n 5 "$obj.err"
    bad=1
    continue
  fi
  nobj=$((nobj + 1))
  syms=$($nm -u "$obj" | awk '{print $NF}')
  found=$(printf '%s\n' "$syms" | grep -E "$softfloat|$libm" | tr '\n' ' ')
  if [ -n "$found" ]; then errs="$errs $src: $found;"; fi
  case $src in
    firmware/core/num/*)
      d=$(printf '%s\n' "$syms" | grep -E "$divide" | tr '\n' ' ')
      if [ -n "$d" ]; then echo "FAIL num_no_software_divide: $src references $d"; bad=1; fi ;;
  esac
done
if [ -n "$errs" ]; then
  echo "FAIL core_fixed_no_softfloat: soft-float/libm symbols referenced:$errs"
  bad=1
else
  echo "PASS core_fixed_no_softfloat ($nobj objects)"
fi
[ $bad -eq 0 ] && echo "PASS num_no_software_divide"

# The float build of the core on a single-precision FPU (Cortex-M4F) runs no
# double-precision code: a double constant, a promotion or a double libm call
# would become __aeabi_d*/__aeabi_f2d/... library calls. Each offender is
# named as file:function:symbol (from the relocations of the function's own
# section, -ffunction-sections). num_float_m4f_no_double covers the numeric
# layer (firmware/core/num/); core_float_m4f_no_double every C file of the core.
m4f="$build/../m4f-float-double-check"
mkdir -p "$m4f"
ffl="-std=c11 -O2 -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -ffunction-sections -DNUM_MODE=2 -I. -Ifirmware/core -Ihal -Itools/scene"
dbl='^(__aeabi_d[a-z0-9]*|__aeabi_[a-z0-9]+2d|__(add|sub|mul|div|neg|cmp|eq|ne|lt|le|gt|ge|unord)df[23]|__(fix|fixuns)df[a-z0-9]*|__float(un)?[a-z]*df|__extendsfdf2|__truncdfsf2|sqrt|pow|sin|cos|tan|atan|atan2|exp|log|floor|ceil|fabs|fmod|ldexp|rint|lrint|round|trunc|hypot)$'
own=""; other=""; nf=0
for src in $(find firmware/core -name '*.c' | sort); do
  obj="$m4f/$(echo "${src#firmware/core/}" | tr / _ | sed 's/\.c$//').o"
  if ! $cc $ffl -c "$src" -o "$obj" 2>"$obj.err"; then
    echo "FAIL core_float_m4f_cross_compiles: $src does not build for cortex-m4 (float):"
    head -n 5 "$obj.err"
    bad=1
    continue
  fi
  nf=$((nf + 1))
  # "RELOCATION RECORDS FOR [.text.fn]:" then "offset type symbol" lines
  hits=$(arm-none-eabi-objdump -r "$obj" | awk -v f="$src" -v re="$dbl" '
    /^RELOCATION RECORDS FOR/ { sec = $4; gsub(/[\[\]:]/, "", sec); sub(/^\.text\./, "", sec); next }
    NF >= 3 && $3 ~ re { print f ":" sec ":" $3 }' | sort -u | tr '\n' ' ')
  case $src in
    firmware/core/num/*) own="$own$hits" ;;
    *) other="$other$hits" ;;
  esac
done
if [ -n "$own" ]; then
  echo "FAIL num_float_m4f_no_double: double-precision code in the numeric layer: $own"
  bad=1
else
  echo "PASS num_float_m4f_no_double"
fi
if [ -n "$other$own" ]; then
  echo "FAIL core_float_m4f_no_double: double-precision routines (file:function:symbol): $other$own"
  bad=1
else
  echo "PASS core_float_m4f_no_double ($nf objects)"
fi
exit $bad
