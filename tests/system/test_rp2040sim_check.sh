#!/bin/sh
# SPDX-License-Identifier: MIT
# The bring-up images (cgfs-check*, firmware/app/check_main.c) in the
# emulator: each boots, prints its settings line on the UART (the panel, its
# size and rotation, offsets, colour order, inversion, the SPI clock and
# clk_sys), and the glass the emulated module shows after the first pattern
# equals, pixel for pixel, host_sim --pattern check on the same module with
# the clocks the line gave (--board-clocks): the same pattern module, the
# same driver, the same settings on the glass. ~6 s an image (the pattern
# is sent again after FW_CHECK_PERIOD_MS, 2 s emulated, which ends the
# emulator's frame).
# usage: test_rp2040sim_check.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
sim=tools/rp2040sim/rp2040sim.js
# Hz from a MHz figure of the line (62.5 -> 62500000)
hz() { awk -v m="$1" 'BEGIN { printf "%d", m * 1000000 + 0.5 }'; }
for c in cgfs-check:st7789_240x240:240x240 cgfs-check-ili9341:ili9341_320x240:320x240 \
         cgfs-check-st7735:st7735_128x160:128x160 cgfs-check-ssd1351:ssd1351_128x128:128x128 \
         cgfs-check-gc9a01:gc9a01_240x240:240x240 cgfs-check-ili9488:ili9488_320x480:320x480; do
  img=${c%%:*} rest=${c#*:}
  mod=${rest%%:*} size=${rest#*:}
  name=rp2040sim_${img}_equals_host_sim
  if ! timeout 300 node $sim --image "$b/firmware/pico/$img.elf" --panel "$mod" --frames 1 --uart \
       --out-raw "$t/fw.raw" >/dev/null 2>"$t/err"; then
    echo "FAIL $name: $(tail -n 1 "$t/err")"; continue
  fi
  line=$(grep -a -m 1 '^check panel=' "$t/err" | tr -d '\r')
  want="check panel=$mod size=$size rotation=0 "
  case "$line" in
    "$want"*) ;;
    *) echo "FAIL $name: the UART line is '$line', not '$want...'"; continue ;;
  esac
  spi=$(echo "$line" | sed -n 's/.* spi_mhz=\([0-9.]*\) .*/\1/p')
  sys=$(echo "$line" | sed -n 's/.* clk_sys_mhz=\([0-9.]*\)$/\1/p')
  if [ -z "$spi" ] || [ -z "$sys" ]; then
    echo "FAIL $name: no clocks in '$line'"; continue
  fi
  if ! "$b/host_sim" --pattern check --panel "$mod" --board-clocks "$(hz "$spi"),$(hz "$sys")" \
       --out-raw "$t/hs.raw" 2>"$t/herr"; then
    echo "FAIL $name: host_sim: $(tail -n 1 "$t/herr")"
  elif cmp -s "$t/hs.raw" "$t/fw.raw"; then
    echo "PASS $name ($line)"
  else
    echo "FAIL $name: $(cmp "$t/hs.raw" "$t/fw.raw" 2>&1 | head -n 1)"
  fi
done
