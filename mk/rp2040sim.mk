# SPDX-License-Identifier: MIT
# The board images on the rp2040js emulator (tools/rp2040sim): its npm
# packages, the host reference of the firmware's scene table, and the tests
# that run the images of mk/firmware.mk (read before this file: its
# variables are used here).

RP2040SIM_DEPS := tools/rp2040sim/node_modules/.package-lock.json
$(RP2040SIM_DEPS): tools/rp2040sim/package.json tools/rp2040sim/package-lock.json
	$(Q)cd tools/rp2040sim && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error >/dev/null
	@touch $@

# The host reference of the firmware's scene table (fixed point, as on the MCU).
FW_HOST_REF := $(BUILD)/fw_host_ref
$(BUILD)/host/fixed/firmware/app/%.o: EXTRA_CFLAGS += -Ifirmware/app
$(BUILD)/host/none/tests/support/fw_host_ref.o: EXTRA_CFLAGS += -Ifirmware/app
$(FW_HOST_REF): $(call obj,host,none,tests/support/fw_host_ref.c) $(call obj,host,fixed,$(FW_SCENE_SRCS)) \
                $(BUILD)/host/core_fixed.o
	$(Q)$(CC) $^ $(PNG_LIBS) -lm -o $@

TEST_DEPS += $(RP2040SIM_DEPS) $(FW_HOST_REF) $(FW_OUT)/pico/cgfs-1core.elf $(FW_OUT)/pico/cgfs-1core.bin
TESTS     += tests/system/test_rp2040sim.sh:$(BUILD)
TEST_DEPS += $(FW_OUT)/pico/cgfs-ili9341.elf $(FW_OUT)/pico/cgfs-rot2.elf $(FW_OUT)/pico/cgfs-book-gc9a01.elf \
             $(FW_OUT)/pico/cgfs-book-ssd1351.elf $(FW_OUT)/pico/cgfs-book-ili9488.elf
TESTS     += tests/system/test_rp2040sim_panels.sh:$(BUILD)
TEST_DEPS += $(FW_OUT)/pico/cgfs-book-1core.elf $(FW_OUT)/pico/cgfs-cube-1core.elf $(BUILD)/host_sim
TESTS     += tests/system/test_rp2040sim_book.sh:$(BUILD) tests/system/test_rp2040sim_cube.sh:$(BUILD):$(FW_CUBE_FRAMES)
TEST_DEPS += $(FW_OUT)/pico/cgfs-cube-ili9341-1core.elf
TESTS     += tests/system/test_rp2040sim_cube.sh:$(BUILD):$(FW_CUBE_FRAMES):cgfs-cube-ili9341-1core:ili9341_320x240:320x240
# and on the ST7735S 1.8" module, 128x160
TEST_DEPS += $(FW_OUT)/pico/cgfs-cube-st7735-1core.elf
TESTS     += tests/system/test_rp2040sim_cube.sh:$(BUILD):$(FW_CUBE_FRAMES):cgfs-cube-st7735-1core:st7735_128x160:128x160
# and on the SSD1351 OLED module, 128x128 (not DCS)
TEST_DEPS += $(FW_OUT)/pico/cgfs-cube-ssd1351-1core.elf
TESTS     += tests/system/test_rp2040sim_cube.sh:$(BUILD):$(FW_CUBE_FRAMES):cgfs-cube-ssd1351-1core:ssd1351_128x128:128x128
# and on the GC9A01 round module, 240x240 (the glass: the circle)
TEST_DEPS += $(FW_OUT)/pico/cgfs-cube-gc9a01-1core.elf
TESTS     += tests/system/test_rp2040sim_cube.sh:$(BUILD):$(FW_CUBE_FRAMES):cgfs-cube-gc9a01-1core:gc9a01_240x240:240x240
# and on the ILI9488 module, 320x480 (18-bit pixels on the bus)
TEST_DEPS += $(FW_OUT)/pico/cgfs-cube-ili9488-1core.elf
TESTS     += tests/system/test_rp2040sim_cube.sh:$(BUILD):$(FW_CUBE_FRAMES):cgfs-cube-ili9488-1core:ili9488_320x480:320x480
# the two-core images on both emulated cores (tools/rp2040sim/dualcore.js)
TEST_DEPS += $(FW_OUT)/pico/cgfs.elf $(FW_OUT)/pico/cgfs-book.elf
TESTS     += tests/system/test_rp2040sim_dual.sh:$(BUILD)
# a reset of core 0 alone while core 1 renders (rp2040sim --reset-core0-at-frame)
TEST_DEPS += $(FW_OUT)/pico/cgfs-cube.elf
TESTS     += tests/system/test_rp2040sim_reset.sh:$(BUILD)
# tearing: the panel's scan modelled, the TE line wired or not (cgfs-cube-te)
TEST_DEPS += $(FW_OUT)/pico/cgfs-cube-te.elf
TESTS     += tests/system/test_rp2040sim_tearing.sh:$(BUILD)
# the bring-up images (cgfs-check*): the UART's settings line, and the glass
# equal to host_sim --pattern check on each module
TEST_DEPS += $(foreach i,$(FW_CHECK_IMAGES),$(FW_OUT)/pico/$(i).elf) $(BUILD)/host_sim
TESTS     += tests/system/test_rp2040sim_check.sh:$(BUILD)
# (make check: each of these tests builds what all of them need)
RP2040SIM_TEST_NEEDS := $(filter $(RP2040SIM_DEPS) $(FW_HOST_REF) $(FW_OUT)/% $(BUILD)/host_sim,$(TEST_DEPS))
$(foreach t,test_rp2040sim test_rp2040sim_panels test_rp2040sim_book test_rp2040sim_cube test_rp2040sim_dual test_rp2040sim_reset test_rp2040sim_tearing test_rp2040sim_check,    $(eval TEST_NEEDS_$(t) := $(RP2040SIM_TEST_NEEDS)))
TESTS     += node:tools/rp2040sim/test_models.js
# The JavaScript panel (emu_panel.js) replays the vectors the C emulator
# replays (test_panel_vectors), so the two decoders cannot drift apart.
TESTS     += node:tools/rp2040sim/replay_vectors.js:tests/vectors/panel

# The SRAM placement of RP2040_RAM_TEXT=1 (firmware/board/rp2040/ram_text/on):
# which functions and tables of the core, the application, the panel drivers
# and the board's code run from SRAM is decided from profiles of the images
# on the emulator (rp2040sim --profile: reads per symbol over a run).
# `make ram-text-profile` builds the profiled images, runs them
# as `make bench-rp2040` does (IMAGE:ARGS, ARGS: mk/bench-rp2040.mk's
# RP2040SIM_ARGS_<ARGS>) and rewrites profile.tsv and ram_text_hot.ld
# (tools/rp2040_ram_text.py); test_ram_text checks that ram_text_hot.ld is
# the one profile.tsv gives and that the images place their code as it says.
RAM_TEXT_DIR := $(RP_DIR)/ram_text/on
RAM_TEXT_PROFILE_RUNS := cgfs-ili9341:plain320 cgfs-book-bench:book cgfs-cube:cube cgfs-rt:rt cgfs-mesh:mesh
RP2040SIM_ARGS_plain320 = --panel ili9341_320x240 $(RP2040SIM_ARGS_plain)
ram_text_field = $(word $(1),$(subst :, ,$(2)))
define RAM_TEXT_PROFILE_RUN
	$(Q)node tools/rp2040sim/rp2040sim.js --image $(FW_OUT)/pico/$(call ram_text_field,1,$(1)).elf --variant two-core \
		$(RP2040SIM_ARGS_$(call ram_text_field,2,$(1))) --profile $(BUILD)/ram_text/$(call ram_text_field,1,$(1)).json >/dev/null

endef
.PHONY: ram-text-profile
ram-text-profile: $(RP2040SIM_DEPS) $(foreach r,$(RAM_TEXT_PROFILE_RUNS),$(FW_OUT)/pico/$(call ram_text_field,1,$(r)).elf)
	@mkdir -p $(BUILD)/ram_text
	$(foreach r,$(RAM_TEXT_PROFILE_RUNS),$(call RAM_TEXT_PROFILE_RUN,$(r)))
	$(Q)$(PYTHON) tools/rp2040_ram_text.py collect --out $(RAM_TEXT_DIR)/profile.tsv \
		$(foreach r,$(RAM_TEXT_PROFILE_RUNS),$(BUILD)/ram_text/$(call ram_text_field,1,$(r)).json:$(FW_OUT)/pico/$(call ram_text_field,1,$(r)).map)
	$(Q)$(PYTHON) tools/rp2040_ram_text.py ld $(RAM_TEXT_DIR)/profile.tsv --out $(RAM_TEXT_DIR)/ram_text_hot.ld
TEST_NEEDS_test_ram_text := $(foreach i,cgfs-ili9341 cgfs-book cgfs-cube cgfs-rt,$(FW_OUT)/pico/$(i).elf)
TEST_DEPS += $(TEST_NEEDS_test_ram_text)
TESTS     += tests/system/test_ram_text.sh:$(BUILD)
