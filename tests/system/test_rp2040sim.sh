#!/bin/sh
# SPDX-License-Identifier: MIT
# The single-core firmware image runs in the rp2040js emulator: the first
# frame the emulated ST7789 shows equals the host's render of the same scene
# table bit for bit, and the run reports cycles per frame.
# usage: test_rp2040sim.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
elf=$b/firmware/pico/cgfs-1core.elf
if ! timeout 300 node tools/rp2040sim/rp2040sim.js --image "$elf" --frames 1 --out-raw "$t/pico.raw" \
     --json >"$t/json" 2>"$t/err"; then
  echo "FAIL rp2040sim_runs_firmware: $(tail -n 1 "$t/err")"
  exit 1
fi
echo "PASS rp2040sim_runs_firmware"
if grep -q '"cycles":[1-9]' "$t/json"; then
  echo "PASS rp2040sim_reports_cycles_per_frame"
else
  echo "FAIL rp2040sim_reports_cycles_per_frame: $(cat "$t/json")"
fi
"$b/fw_host_ref" 0 240 240 8 "$t/host.raw" || { echo "FAIL rp2040sim_frame_equals_host: fw_host_ref failed"; exit 1; }
if cmp -s "$t/host.raw" "$t/pico.raw"; then
  echo "PASS rp2040sim_frame_equals_host_bit_for_bit"
else
  echo "FAIL rp2040sim_frame_equals_host_bit_for_bit: $(cmp "$t/host.raw" "$t/pico.raw" | head -n 1)"
fi
# A frame is rejected by the panel when the firmware breaks the protocol: the
# emulator exits 3 with one line (checked with a truncated image: no panel
# traffic at all gives exit 1, not a hang).
head -c 4096 "$b/firmware/pico/cgfs-1core.bin" >"$t/short.bin"
timeout 60 node tools/rp2040sim/rp2040sim.js --image "$t/short.bin" --max-cycles 2000000 >/dev/null 2>"$t/err2"
rc=$?
if [ "$rc" -eq 1 ] && [ "$(wc -l <"$t/err2")" -eq 1 ]; then
  echo "PASS rp2040sim_broken_image_fails_in_bounded_time"
else
  echo "FAIL rp2040sim_broken_image_fails_in_bounded_time: exit $rc: $(cat "$t/err2")"
fi
# Any emulator warning ends the run with exit 1 and says what it was: an image
# whose reset code reads an address nothing answers (0x30000000), behind the
# project's boot2.
python3 -c "
import struct, sys
img = bytearray(open(sys.argv[2], 'rb').read()[:0x100]) + struct.pack('<II', 0x20042000, 0x10000109)
img += struct.pack('<HHHH', 0x4801, 0x6801, 0xe7fe, 0) + struct.pack('<I', 0x30000000)
open(sys.argv[1], 'wb').write(img)" "$t/stray.bin" "$b/firmware/pico/cgfs-1core.bin"
timeout 60 node tools/rp2040sim/rp2040sim.js --image "$t/stray.bin" --max-cycles 2000000 >/dev/null 2>"$t/err3"
rc=$?
if [ "$rc" -eq 1 ] && grep -q "emulator warning: .*30000000" "$t/err3"; then
  echo "PASS rp2040sim_emulator_warning_fails_the_run"
else
  echo "FAIL rp2040sim_emulator_warning_fails_the_run: exit $rc: $(cat "$t/err3")"
fi
# The boot ROM starts only an image whose boot2 carries the right CRC32: one
# byte of boot2 changed and the run is refused with one line, exit 1.
python3 -c "
import sys
img = bytearray(open(sys.argv[1], 'rb').read())
img[8] ^= 0x40
open(sys.argv[2], 'wb').write(img)" "$b/firmware/pico/cgfs-1core.bin" "$t/badcrc.bin"
timeout 60 node tools/rp2040sim/rp2040sim.js --image "$t/badcrc.bin" --max-cycles 2000000 >/dev/null 2>"$t/err4"
rc=$?
if [ "$rc" -eq 1 ] && [ "$(wc -l <"$t/err4")" -eq 1 ] && grep -q "boot2 CRC32" "$t/err4"; then
  echo "PASS rp2040sim_boot2_crc_checked"
else
  echo "FAIL rp2040sim_boot2_crc_checked: exit $rc: $(cat "$t/err4")"
fi
# The XIP cache is charged: a frame reports its misses and what they cost,
# at the line-fill cost of the read mode the image's boot2 sets up (quad EBh
# at clk_sys/2: 60 cycles; serial 03h at clk_sys/4: 388). (The placeholder's
# frame may miss no line: its per-frame code runs from SRAM, ram_text_hot.ld.)
case $(cat "$b/firmware/pico/boot2.choice" 2>/dev/null) in
  generic_03h) fill=388 ;;
  *) fill=60 ;;
esac
if python3 -c "
import json, sys
d = json.loads(open(sys.argv[1]).readline())
sys.exit(not (d['xip_fill_cycles'] == int(sys.argv[2]) and d['xip_misses'] >= 0 and
              d['xip_stall_cycles'] == d['xip_misses'] * d['xip_fill_cycles']))" "$t/json" "$fill"; then
  echo "PASS rp2040sim_reports_xip_misses"
else
  echo "FAIL rp2040sim_reports_xip_misses: $(cat "$t/json")"
fi
# A fault is reported, not a silent lock-up: an NMI raised in the middle of
# the first frame reaches the firmware's default handler, which prints the
# exception number and the stacked PC on the UART; the run ends with it.
timeout 120 node tools/rp2040sim/rp2040sim.js --image "$elf" --frames 1 --inject-nmi 30000000 >/dev/null 2>"$t/err5"
rc=$?
if [ "$rc" -eq 1 ] && grep -q "fault core=0 ipsr=2 pc=0x[0-9a-f]\{8\} lr=0x[0-9a-f]\{8\} xpsr=0x[0-9a-f]\{8\}" "$t/err5"; then
  echo "PASS rp2040sim_fault_reported_on_uart"
else
  echo "FAIL rp2040sim_fault_reported_on_uart: exit $rc: $(cat "$t/err5")"
fi
