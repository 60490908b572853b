#!/bin/sh
# SPDX-License-Identifier: MIT
# docs/firmware.md says what the build does:
#   - its memory figures (the RP2040 images' table, the SRAM the two-core
#     cube image leaves, the STM32F411 sizes) are the images':
#     tools/fw_sizes.py BUILD_DIR --check docs/firmware.md, one case a figure
#     (after a change: tools/fw_sizes.py BUILD_DIR --write docs/firmware.md);
#   - every `make flash` it shows without FLASH_IMAGE= names the image
#     mk/flasher.mk's FLASH_IMAGE writes.
# usage: test_fw_docs.sh BUILD_DIR
set -u
b=${1:-build}
python3 tools/fw_sizes.py "$b" --check docs/firmware.md
img=$(sed -n 's|^FLASH_IMAGE ?= $(FW_OUT)/pico/\([A-Za-z0-9_.-]*\.uf2\)$|\1|p' mk/flasher.mk)
if [ -z "$img" ]; then
  echo "FAIL fw_docs_make_flash_image: no FLASH_IMAGE ?= \$(FW_OUT)/pico/*.uf2 in mk/flasher.mk"
  exit 0
fi
# the lines that show `make flash` and name a .uf2 without choosing one
bad=$(grep -n 'make flash' docs/firmware.md README.md | grep -v 'FLASH_IMAGE=' | grep '\.uf2' | grep -v '\*\.uf2' | grep -v "$img")
if [ -z "$bad" ] && grep -q "make flash\` writes \`$img\`" docs/firmware.md; then
  echo "PASS fw_docs_make_flash_image ($img)"
else
  echo "FAIL fw_docs_make_flash_image: mk/flasher.mk writes $img; ${bad:-docs/firmware.md does not say so}"
fi
