#!/bin/sh
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
if [ "$rc" -eq 2 ] && grep -q "cannot open" "$t/out"; then
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
