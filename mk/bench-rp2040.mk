# SPDX-License-Identifier: MIT
# `make bench-rp2040` (part of `make bench`): the emulated Pico's frame time
# per scene, of the single-core images ("cores":1, variant single-core) and
# of the two-core ones ("cores":2, variant two-core, both emulated cores),
# cycles at 133 MHz including SPI time, appended to results.jsonl: the
# placeholder, frame 0 of each book scene, for each cube scene the mean of
# its FW_CUBE_FRAMES frames (rp2040sim --average: "frames", "cycles_min",
# "cycles_max"; frame 0 is drawn without the fps overlay, the others with it,
# as on the board), and the ray tracer's benchmark scenes with the
# progressive preview's first_image_us; the cube scenes again on the ILI9341
# in landscape ("width":320). Read after mk/firmware.mk and mk/rp2040sim.mk,
# whose images and RP2040SIM_DEPS it runs.

RP2040SIM_BENCH_FRAMES ?= 1
RP2040SIM_TMP := $(BUILD)/bench/rp2040sim.jsonl.tmp
.PHONY: bench-rp2040
RP2040SIM_BENCH_IMAGES := cgfs-1core cgfs cgfs-book-1core cgfs-book-bench \
                          cgfs-cube-1core cgfs-cube cgfs-rt-1core cgfs-rt \
                          cgfs-cube-ili9341-1core cgfs-cube-ili9341
bench-rp2040: $(RP2040SIM_DEPS) $(foreach i,$(RP2040SIM_BENCH_IMAGES),$(FW_OUT)/pico/$(i).elf)
	@mkdir -p $(BUILD)/bench
	@# this step's lines are rewritten, the other steps' kept
	$(Q)grep -v '"target": *"rp2040-sim"' $(BUILD)/bench/results.jsonl >$(BUILD)/bench/results.jsonl.tmp 2>/dev/null; \
		mv $(BUILD)/bench/results.jsonl.tmp $(BUILD)/bench/results.jsonl
	$(Q)for i in cgfs-1core:single-core cgfs:two-core; do \
		node tools/rp2040sim/rp2040sim.js --image $(FW_OUT)/pico/$${i%%:*}.elf --variant $${i#*:} \
			--frames $(RP2040SIM_BENCH_FRAMES) --json >>$(BUILD)/bench/results.jsonl || exit 1; done
	$(Q)for i in cgfs-book-1core:single-core cgfs-book-bench:two-core; do \
		node tools/rp2040sim/rp2040sim.js --image $(FW_OUT)/pico/$${i%%:*}.elf --variant $${i#*:} \
			--frames $(words $(FW_BOOK_SCENES)) --json >$(RP2040SIM_TMP) || exit 1; \
		cat $(RP2040SIM_TMP) && cat $(RP2040SIM_TMP) >>$(BUILD)/bench/results.jsonl; done
	$(Q)for i in cgfs-cube-1core:single-core cgfs-cube:two-core; do \
		node tools/rp2040sim/rp2040sim.js --image $(FW_OUT)/pico/$${i%%:*}.elf --variant $${i#*:} \
			--frames $$(($(words $(FW_CUBE_SCENES)) * $(FW_CUBE_FRAMES))) --json --average >$(RP2040SIM_TMP) || exit 1; \
		cat $(RP2040SIM_TMP) && cat $(RP2040SIM_TMP) >>$(BUILD)/bench/results.jsonl; done
	$(Q)for i in cgfs-cube-ili9341-1core:single-core cgfs-cube-ili9341:two-core; do \
		node tools/rp2040sim/rp2040sim.js --image $(FW_OUT)/pico/$${i%%:*}.elf --variant $${i#*:} \
			--panel ili9341_320x240 --frames $$(($(words $(FW_CUBE_SCENES)) * $(FW_CUBE_FRAMES))) --json --average \
			>$(RP2040SIM_TMP) || exit 1; \
		cat $(RP2040SIM_TMP) && cat $(RP2040SIM_TMP) >>$(BUILD)/bench/results.jsonl; done
	$(Q)for i in cgfs-rt-1core:single-core cgfs-rt:two-core; do \
		node tools/rp2040sim/rp2040sim.js --image $(FW_OUT)/pico/$${i%%:*}.elf --variant $${i#*:} \
			--frames $(words $(FW_RT_SCENES)) --json >$(RP2040SIM_TMP) || exit 1; \
		cat $(RP2040SIM_TMP) && cat $(RP2040SIM_TMP) >>$(BUILD)/bench/results.jsonl; done
	$(Q)rm -f $(RP2040SIM_TMP)
bench: bench-rp2040
