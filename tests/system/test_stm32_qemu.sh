#!/bin/sh
# SPDX-License-Identifier: MIT
# The STM32F411 image on qemu's netduinoplus2 (an STM32F405: the same flash,
# SRAM and USART1 addresses). qemu's clock controller never reports the PLL
# locked, so the board's clock wait must time out and the board run on:
#   - cgfs.elf: "error clock: PLL lock timed out: HSI at 16 MHz", then the
#     boot line at cpu_hz=16000000 and the first frame's fps line;
#   - cgfs-fault-test.elf (faults right after board_init): a line
#     "fault ipsr=3 pc=0x... lr=0x...", then a system reset (AIRCR
#     SYSRESETREQ): the clock line again, and the fault again.
# usage: test_stm32_qemu.sh BUILD_DIR
set -u
b=${1:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
d=$b/firmware/stm32f411
# IMAGE OUT SECONDS PATTERN COUNT: UART output of the image until COUNT
# lines match PATTERN (grep), at most SECONDS
run() {
  : >"$2"
  qemu-system-arm -M netduinoplus2 -kernel "$1" -nographic -monitor none \
    -serial "file:$2" >/dev/null 2>&1 </dev/null &
  q=$!
  i=0
  while [ $i -lt $(($3 * 4)) ] && [ "$(grep -c "$4" "$2")" -lt "$5" ]; do sleep 0.25; i=$((i + 1)); done
  kill $q 2>/dev/null
  wait $q 2>/dev/null
}
run "$d/cgfs.elf" "$t/boot.txt" 60 '^fps scene=book/raytracer-02 frame=0 ' 1
if ! sed -n 1p "$t/boot.txt" | grep -q '^error clock: PLL lock timed out: HSI at 16 MHz'; then
  echo "FAIL stm32_qemu_clock_timeout_line: first line: $(sed -n 1p "$t/boot.txt")"
else
  echo "PASS stm32_qemu_clock_timeout_line"
fi
if grep -q '^boot board=stm32f411 cores=1 cpu_hz=16000000 ' "$t/boot.txt" &&
   grep -q '^fps scene=book/raytracer-02 frame=0 ' "$t/boot.txt"; then
  echo "PASS stm32_qemu_runs_on_hsi"
else
  echo "FAIL stm32_qemu_runs_on_hsi: $(head -n 3 "$t/boot.txt" | tr '\r\n' '  ')"
fi
# (grep sees the file's lines: wait for the second fault's)
run "$d/cgfs-fault-test.elf" "$t/fault.txt" 30 '^fault ' 3
n=$(grep -c '^fault ipsr=3 pc=0x[0-9a-f]\{8\} lr=0x[0-9a-f]\{8\}' "$t/fault.txt")
if [ "$n" -ge 2 ] && sed -n 3p "$t/fault.txt" | grep -q '^error clock:'; then
  echo "PASS stm32_qemu_fault_line_then_reset ($n resets)"
else
  echo "FAIL stm32_qemu_fault_line_then_reset: $n fault lines: $(head -n 4 "$t/fault.txt" | tr '\r\n' '  ')"
fi
