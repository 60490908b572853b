#!/bin/sh
# SPDX-License-Identifier: MIT
# host_sim --backend linux, its real byte stream and line changes checked by
# the strict emulated panel: tests/support/shim_linux_panel.c is preloaded in place
# of spidev and libgpiod, once with the distribution's libgpiod (1.x API,
# BUILD/host_sim) and once with libgpiod 2 (BUILD/gpiod2/host_sim, mk/pi.mk).
# The glass behind the Linux backend must equal the sim backend's, with the
# Raspberry Pi options (pins, SPI mode and clock, device, rotation) reaching
# the devices; and their errors are one line with exit status 2.
#   tests/system/test_linux_backend.sh BUILD
set -u
build=${1:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scene=firmware/scenes/book/raster-11.scene
case $build in /*) shimdir=$build/shim ;; *) shimdir=$(pwd)/$build/shim ;; esac

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }

# run_linux API MODULE ROT PINS -- host_sim options: the Linux backend with
# the shim; glass in $tmp/lx.raw, the shim's line in $tmp/lx.log.
run_linux() {
  api=$1 module=$2 rot=$3 pins=$4
  shift 5
  hs=$build/host_sim
  [ "$api" = v2 ] && hs=$build/gpiod2/host_sim
  rm -f "$tmp/lx.raw" "$tmp/lx.log"
  CGFS_SHIM_SPIDEV=${SPIDEV:-/dev/spidev0.0} CGFS_SHIM_MODULE=$module CGFS_SHIM_ROT=$rot \
  CGFS_SHIM_PINS=$pins CGFS_SHIM_GLASS=$tmp/lx.raw CGFS_SHIM_LOG=$tmp/lx.log \
  LD_PRELOAD=$shimdir/$api/shim_linux_panel.so \
    "$hs" --scene $scene --backend linux "$@" >"$tmp/out" 2>"$tmp/err"
}

for api in v1 v2; do
  [ -x "$build/shim/$api/shim_linux_panel.so" ] || [ -f "$build/shim/$api/shim_linux_panel.so" ] || {
    fail "linux_backend_$api" "no $build/shim/$api/shim_linux_panel.so"; continue; }

  # ST7789 240x240, the defaults: mode 3, the ST7789VW's 62.5 MHz, DC 25, RESET 27, BL 18
  "$build/host_sim" --scene $scene --out-raw "$tmp/sim.raw" 2>/dev/null
  run_linux $api st7789_240x240 0 25,27,18 --
  rc=$?
  if [ $rc -eq 0 ] && cmp -s "$tmp/sim.raw" "$tmp/lx.raw" && grep -q 'violation none' "$tmp/lx.log"; then
    pass "linux_backend_${api}_st7789_glass_equals_sim"
  else
    fail "linux_backend_${api}_st7789_glass_equals_sim" "rc $rc, $(cat "$tmp/err" "$tmp/lx.log" 2>/dev/null | head -n 2)"
  fi
  if grep -q '^mode 3 bits 8 hz 62500000 ' "$tmp/lx.log" 2>/dev/null; then
    pass "linux_backend_${api}_st7789_defaults_mode3_rated_62_5mhz"
  else
    fail "linux_backend_${api}_st7789_defaults_mode3_rated_62_5mhz" "$(cat "$tmp/lx.log" 2>/dev/null)"
  fi

  # ILI9341 320x240 upside down, every Pi option given
  "$build/host_sim" --scene $scene --panel ili9341 --rotation 2 --out-raw "$tmp/sim2.raw" 2>/dev/null
  SPIDEV=/dev/spidev1.0 run_linux $api ili9341_320x240 2 24,23,12 -- --panel ili9341 --rotation 2 \
    --spi-dev /dev/spidev1.0 --spi-hz 16000000 --spi-mode 0 --gpio-chip gpiochip0 --dc 24 --rst 23 --bl 12
  rc=$?
  if [ $rc -eq 0 ] && cmp -s "$tmp/sim2.raw" "$tmp/lx.raw" && grep -q '^mode 0 bits 8 hz 16000000 .*violation none' "$tmp/lx.log"; then
    pass "linux_backend_${api}_ili9341_pi_options_glass_equals_sim"
  else
    fail "linux_backend_${api}_ili9341_pi_options_glass_equals_sim" "rc $rc, $(cat "$tmp/err" "$tmp/lx.log" 2>/dev/null | head -n 2)"
  fi

  # DC on the wrong line: the controller sees every byte as data
  run_linux $api st7789_240x240 0 25,27,18 -- --dc 5
  if grep -q 'violation none' "$tmp/lx.log" 2>/dev/null && cmp -s "$tmp/sim.raw" "$tmp/lx.raw"; then
    fail "linux_backend_${api}_wrong_dc_pin_is_seen" "the glass is right with DC on line 5"
  else
    pass "linux_backend_${api}_wrong_dc_pin_is_seen"
  fi

  run_linux $api st7789_240x240 0 25,27,18 -- --gpio-chip gpiochip7
  rc=$?
  if [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q 'cannot open GPIO chip gpiochip7' "$tmp/err"; then
    pass "linux_backend_${api}_missing_gpiochip_exit2_one_line"
  else
    fail "linux_backend_${api}_missing_gpiochip_exit2_one_line" "rc $rc: $(cat "$tmp/err")"
  fi

  run_linux $api st7789_240x240 0 25,27,18 -- --bl 40
  rc=$?
  if [ $rc -eq 2 ] && grep -q 'cannot drive BL line 40 on gpiochip0' "$tmp/err"; then
    pass "linux_backend_${api}_line_out_of_range_exit2"
  else
    fail "linux_backend_${api}_line_out_of_range_exit2" "rc $rc: $(cat "$tmp/err")"
  fi
done

# The SPI mode and clock by default are the module's (hal/panel.h, spi_mode
# and spi_max_hz, its controller's rated write clock), whatever its name:
# every ST7789 module in mode 3, the ILI9341 in mode 0; the other
# controllers (the SSD1351: not DCS; the ILI9488: three bytes a pixel) in
# mode 0, their streams through the Linux backend as strict as host_sim's.
for m in st7789_240x320:3:15151515 ili9341_240x320:0:10000000 ili9341_320x240:0:10000000 \
         st7735_128x160:0:15151515 ssd1351_128x128:0:20000000 gc9a01_240x240:0:50000000 \
         ili9488_320x480:0:20000000; do
  module=${m%%:*} rest=${m#*:}
  want=${rest%:*} hz=${rest#*:}
  size=${module#*_} ctl=${module%%_*}
  run_linux v1 "$module" 0 25,27,18 -- --panel "$ctl" --size "$size"
  rc=$?
  if [ $rc -eq 0 ] && grep -q "^mode $want bits 8 hz $hz .*violation none" "$tmp/lx.log" 2>/dev/null; then
    pass "linux_backend_default_spi_mode_clock_${module}_${want}_$hz"
  else
    fail "linux_backend_default_spi_mode_clock_${module}_${want}_$hz" "rc $rc, $(cat "$tmp/err" "$tmp/lx.log" 2>/dev/null | head -n 2)"
  fi
done

hs=$build/host_sim
"$hs" --scene $scene --backend linux --spi-dev "$tmp/none/spidev9.9" >/dev/null 2>"$tmp/err"
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q "cannot open $tmp/none/spidev9.9" "$tmp/err"; then
  pass linux_backend_missing_spidev_exit2_one_line
else
  fail linux_backend_missing_spidev_exit2_one_line "rc $rc: $(cat "$tmp/err")"
fi
bad=""
for args in "--spi-mode 4" "--spi-hz 0" "--dc none" "--rst x" "--rotation 5" "--spi-dev /dev/spidev0.0"; do
  # shellcheck disable=SC2086
  "$hs" --scene $scene $args >/dev/null 2>"$tmp/err"
  rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] || bad="$bad [$args: rc $rc]"
done
"$hs" --scene $scene --panel ili9341 --size 320x240 --rotation 1 >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && grep -q 'odd turns need a square size' "$tmp/err" || bad="$bad [ili9341 320x240 rotation 1]"
if [ -z "$bad" ]; then pass linux_backend_bad_pi_options_exit2; else fail linux_backend_bad_pi_options_exit2 "$bad"; fi

help=$("$hs" --help)
missing=""
for o in --spi-dev --spi-hz --spi-mode --gpio-chip --dc --rst --bl --rotation --panel; do
  printf '%s\n' "$help" | grep -q -- "$o" || missing="$missing $o"
done
if [ -z "$missing" ]; then pass host_sim_help_lists_pi_options; else fail host_sim_help_lists_pi_options "missing$missing"; fi
