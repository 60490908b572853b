#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs the distribution packages a make target needs (Debian, Ubuntu,
# Raspberry Pi OS). As root or with passwordless sudo it installs what is
# missing; otherwise it prints the one command to run and fails.
#   tools/deps.sh run|test|firmware|examples|charts|flash|bench
set -eu

group=${1:-run}
run_pkgs="libpng-dev pkg-config"
firmware_pkgs="gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi"
flash_pkgs="libusb-1.0-0-dev libgpiod-dev pkg-config"
charts_pkgs="python3 python3-matplotlib"
bench_pkgs="$firmware_pkgs qemu-system-arm valgrind nodejs"
# make examples: the Cortex-M0+ build, and qemu for the work probe (scenec)
examples_pkgs="$firmware_pkgs qemu-system-arm"
# libFuzzer's runtime is only recommended by clang, and installs skip recommends.
# python3-pip: pip downloads the gpiod source distribution (libgpiod 2, mk/pi.mk).
# libsdl2-dev: host_sim --window; xvfb, xauth, x11-apps (xwd): its test on a virtual display.
# clang-format: tools/format_check.sh, the C style of the files in tools/clang-format.files.
test_pkgs="$run_pkgs $firmware_pkgs $flash_pkgs $bench_pkgs clang libclang-rt-dev python3 python3-pip \
  libsdl2-dev xvfb xauth x11-apps clang-format"

case "$group" in
  run) want=$run_pkgs ;;
  firmware) want=$firmware_pkgs ;;
  examples) want=$examples_pkgs ;;
  flash) want=$flash_pkgs ;;
  charts) want=$charts_pkgs ;;
  bench) want=$bench_pkgs ;;
  test) want=$test_pkgs ;;
  *) echo "deps.sh: unknown group '$group' (run|test|firmware|examples|charts|flash|bench)" >&2; exit 2 ;;
esac

if ! command -v dpkg-query >/dev/null 2>&1; then
  # Not a Debian system: trust the user to have installed the packages.
  exit 0
fi

missing=""
for p in $want; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed"; then
    case " $missing " in *" $p "*) ;; *) missing="$missing $p" ;; esac
  fi
done
# npm comes with nodejs on some distributions (NodeSource) and as its own
# package on others (Debian); ask for it only when the command is missing.
case " $want " in *" nodejs "*)
  command -v npm >/dev/null 2>&1 || missing="$missing npm" ;;
esac
[ -z "$missing" ] && exit 0

if [ "$(id -u)" = 0 ]; then
  sudo=""
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  sudo="sudo"
else
  echo "missing packages:$missing; run: sudo apt-get install -y$missing" >&2
  exit 1
fi

echo "installing:$missing"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q >/dev/null
# shellcheck disable=SC2086
$sudo apt-get install -y -q --no-install-recommends $missing >/dev/null
