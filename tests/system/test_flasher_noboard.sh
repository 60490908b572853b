#!/bin/sh
# SPDX-License-Identifier: MIT
# With no board in BOOTSEL mode attached, the real flasher says so on one
# line and exits 2. Usage: test_flasher_noboard.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
python3 tools/uf2/uf2conv.py /dev/stdin "$t/x.uf2" <<EOF2
0123456789
EOF2
"$b/flasher" "$t/x.uf2" >"$t/out" 2>&1
rc=$?
if [ "$rc" -eq 2 ] && grep -q "no RP2040 in BOOTSEL mode\|wrong device\|permission denied" "$t/out" &&
   [ "$(wc -l <"$t/out")" -eq 1 ]; then
  echo "PASS flasher_without_board_exits_2"
else
  echo "FAIL flasher_without_board_exits_2: exit $rc, output: $(cat "$t/out")"
fi
"$b/flasher" "$t/missing.uf2" >"$t/out" 2>&1
rc=$?
if [ "$rc" -eq 2 ] && grep -q "missing.uf2: cannot open: No such file or directory" "$t/out"; then
  echo "PASS flasher_missing_file_exits_2"
else
  echo "FAIL flasher_missing_file_exits_2: exit $rc"
fi
# --gpio-reset without the gpiochip (or without libgpiod): one line, exit 2,
# before any USB access.
"$b/flasher" --gpio-reset --gpio-chip /dev/cgfs-no-such-gpiochip "$t/x.uf2" >"$t/out" 2>&1
rc=$?
if [ "$rc" -eq 2 ] && [ "$(wc -l <"$t/out")" -eq 1 ] &&
   grep -q "^flasher: gpio: \(cannot open /dev/cgfs-no-such-gpiochip\|built without libgpiod\)" "$t/out"; then
  echo "PASS flasher_gpio_reset_without_gpiochip_exits_2"
else
  echo "FAIL flasher_gpio_reset_without_gpiochip_exits_2: exit $rc, output: $(cat "$t/out")"
fi
"$b/flasher" --gpio-reset --bootsel-pin 99999 "$t/x.uf2" >"$t/out" 2>&1
rc=$?
if [ "$rc" -eq 2 ] && grep -q "bootsel-pin needs a line number" "$t/out"; then
  echo "PASS flasher_gpio_bad_pin_exits_2"
else
  echo "FAIL flasher_gpio_bad_pin_exits_2: exit $rc, output: $(cat "$t/out")"
fi
# The image is judged by its content and checked whole before the board is
# looked for: UF2 bytes in a .bin or a .UF2 file are a UF2 (and get as far as
# the missing board); bad images are refused on one line, exit 2.
cp "$t/x.uf2" "$t/x.bin"
cp "$t/x.uf2" "$t/X.UF2"
for f in x.bin X.UF2; do
  "$b/flasher" "$t/$f" >"$t/out" 2>&1
  rc=$?
  if [ "$rc" -eq 2 ] && grep -q "no RP2040 in BOOTSEL mode\|wrong device\|permission denied" "$t/out" &&
     [ "$(wc -l <"$t/out")" -eq 1 ]; then
    echo "PASS flasher_uf2_by_content_$f"
  else
    echo "FAIL flasher_uf2_by_content_$f: exit $rc, output: $(cat "$t/out")"
  fi
done
python3 - "$t" <<'EOF2'
import struct, sys
d = sys.argv[1]
def block(addr, no, total):
    return (struct.pack('<8I', 0x0A324655, 0x9E5D5157, 0x2000, addr, 256, no, total, 0xE48BFF56)
            + bytes(476) + struct.pack('<I', 0x0AB16F30))
open(d + '/dup.uf2', 'wb').write(block(0x10000000, 0, 2) + block(0x10000000, 1, 2))
open(d + '/far.uf2', 'wb').write(block(0x10000000 + 3 * 1024 * 1024, 0, 1))
open(d + '/big.bin', 'wb').write(bytes(2 * 1024 * 1024 + 1))
EOF2
for c in "dup.uf2:given twice" "far.uf2:outside the 2048 KB" "big.bin:more than 2048 KB"; do
  f=${c%%:*}; want=${c#*:}
  "$b/flasher" "$t/$f" >"$t/out" 2>&1
  rc=$?
  if [ "$rc" -eq 2 ] && grep -q "$want" "$t/out" && [ "$(wc -l <"$t/out")" -eq 1 ]; then
    echo "PASS flasher_refuses_$f"
  else
    echo "FAIL flasher_refuses_$f: exit $rc, output: $(cat "$t/out")"
  fi
done
"$b/flasher" --flash-size 4194304 "$t/far.uf2" >"$t/out" 2>&1
if grep -q "no RP2040 in BOOTSEL mode\|wrong device\|permission denied" "$t/out"; then
  echo "PASS flasher_flash_size_option"
else
  echo "FAIL flasher_flash_size_option: $(cat "$t/out")"
fi
# A .uf2 name (any case) promises a UF2: damaged, text or zero bytes are
# refused, never flashed raw. Not regular files and empty files are refused
# before anything is read (a FIFO without a writer would hang a read).
python3 - "$t" <<'EOF2'
import sys
d = sys.argv[1]
u = bytearray(open(d + '/x.uf2', 'rb').read())
u[0] ^= 1
open(d + '/bad.uf2', 'wb').write(u)
open(d + '/text.UF2', 'w').write('not an image\n')
open(d + '/zero.uf2', 'wb').write(bytes(512))
open(d + '/empty.bin', 'wb').close()
EOF2
mkfifo "$t/fifo.uf2"
mkdir "$t/dir.uf2"
for c in "bad.uf2:not a UF2 file: block 0 has bad magic" "text.UF2:not a UF2 file" \
         "zero.uf2:not a UF2 file: block 0 has bad magic" "empty.bin:empty file (0 bytes)" \
         "fifo.uf2:not a regular file (a FIFO)" "dir.uf2:Is a directory"; do
  f=${c%%:*}; want=${c#*:}
  timeout 10 "$b/flasher" "$t/$f" >"$t/out" 2>&1
  rc=$?
  if [ "$rc" -eq 2 ] && grep -q "^flasher: $t/$f: .*$want" "$t/out" && [ "$(wc -l <"$t/out")" -eq 1 ]; then
    echo "PASS flasher_refuses_$f"
  else
    echo "FAIL flasher_refuses_$f: exit $rc, output: $(cat "$t/out")"
  fi
done
# --help: every option with its default and the exit statuses, on stdout,
# exit 0; a usage error stays one line, exit 2.
"$b/flasher" --help >"$t/out" 2>"$t/err"
rc=$?
ok=1
for w in --no-reboot --base --flash-size --bus --address --serial --gpio-reset --gpio-chip --run-pin \
         --bootsel-pin "0x10000000" "2097152" "gpiochip0" "\[23\]" "\[24\]" "Exit status: 0" "2 any error"; do
  grep -q -- "$w" "$t/out" || ok=0
done
if [ "$rc" -eq 0 ] && [ "$ok" -eq 1 ] && [ ! -s "$t/err" ]; then
  echo "PASS flasher_help_lists_options_defaults_exit_codes"
else
  echo "FAIL flasher_help_lists_options_defaults_exit_codes: exit $rc, output: $(cat "$t/out" "$t/err")"
fi
n=0
for args in "--bogus $t/x.uf2" "" "$t/x.uf2 $t/x.bin" "--bus 0 $t/x.uf2" "--address 300 $t/x.uf2" "--serial"; do
  n=$((n + 1))
  # shellcheck disable=SC2086
  "$b/flasher" $args >"$t/out" 2>&1
  rc=$?
  if [ "$rc" -eq 2 ] && [ "$(wc -l <"$t/out")" -eq 1 ] && grep -q "^flasher: " "$t/out"; then
    echo "PASS flasher_usage_error_exits_2_one_line_$n"
  else
    echo "FAIL flasher_usage_error_exits_2_one_line_$n ($args): exit $rc, output: $(cat "$t/out")"
  fi
done
# a choice of device gets as far as the (missing) board
"$b/flasher" --bus 1 --address 2 --serial E66141040396512A "$t/x.uf2" >"$t/out" 2>&1
if [ "$?" -eq 2 ] && grep -q "no RP2040 in BOOTSEL mode\|wrong device\|permission denied" "$t/out"; then
  echo "PASS flasher_device_choice_options"
else
  echo "FAIL flasher_device_choice_options: $(cat "$t/out")"
fi
