#!/bin/sh
# SPDX-License-Identifier: MIT
# The RP2040 images' SRAM placement (RP2040_RAM_TEXT=1) is the profile's:
#   - firmware/board/rp2040/ram_text/on/ram_text_hot.ld is what
#     tools/rp2040_ram_text.py writes from profile.tsv beside it (after a
#     change of the core: make ram-text-profile);
#   - in each image of the `on` placement, the core's sections the profile
#     finds hot lie in SRAM and its others in flash (the linker map).
# usage: test_ram_text.sh BUILD_DIR
set -u
b=${1:-build}
d=firmware/board/rp2040/ram_text/on
python3 tools/rp2040_ram_text.py ld $d/profile.tsv --check $d/ram_text_hot.ld
python3 tools/rp2040_ram_text.py check-map $d/profile.tsv \
  "$b/firmware/pico/cgfs-ili9341.map" "$b/firmware/pico/cgfs-book.map" \
  "$b/firmware/pico/cgfs-cube.map" "$b/firmware/pico/cgfs-rt.map"
