# SPDX-License-Identifier: MIT
# `make bench-rp2040` (part of `make bench`): the emulated Pico's frame time
# per scene, of the single-core images ("cores":1, variant single-core) and
# of the two-core ones ("cores":2, variant two-core, both emulated cores),
# cycles at 133 MHz including SPI time, with the image's num_frac,
# appended to results.jsonl: the
# placeholder, frame 0 of each book scene, for each cube scene the mean of
# its FW_CUBE_FRAMES frames (rp2040sim --average: "frames", "cycles_min",
# "cycles_max"; frame 0 is drawn without the fps overlay, the others with it,
# as on the board), and the ray tracer's benchmark scenes with the
# progressive preview's first_image_us; the cube scenes again on the ILI9341
# in landscape ("width":320), also with SPI0 at 62.5 MHz (variant
# two-core-fastspi, FW_SPI_HZ); the 4,096-triangle meshes on two cores (the
# mean of FW_MESH_FRAMES frames each, RP2040_RAM_TEXT=raster). Read after mk/firmware.mk and mk/rp2040sim.mk,
# whose images and RP2040SIM_DEPS it runs.

RP2040SIM_BENCH_FRAMES ?= 1
RP2040SIM_TMP := $(BUILD)/bench/rp2040sim.jsonl.tmp
# rp2040sim's arguments for the images of each scene set (expanded when the
# recipe runs)
RP2040SIM_ARGS_plain   = --frames $(RP2040SIM_BENCH_FRAMES) --json
RP2040SIM_ARGS_book    = --frames $(words $(FW_BOOK_SCENES)) --json
RP2040SIM_ARGS_cube    = --frames $$(($(words $(FW_CUBE_SCENES)) * $(FW_CUBE_FRAMES))) --json --average
RP2040SIM_ARGS_cube320 = --panel ili9341_320x240 $(RP2040SIM_ARGS_cube)
RP2040SIM_ARGS_cubete  = --te-pin 22 $(RP2040SIM_ARGS_cube)
RP2040SIM_ARGS_rt      = --frames $(words $(FW_RT_SCENES)) --json
RP2040SIM_ARGS_mesh    = --frames $$(($(words $(FW_MESH_SCENES)) * $(FW_MESH_FRAMES))) --json --average
# The runs, IMAGE:VARIANT:SET (SET: RP2040SIM_ARGS_<SET>), in the order of
# their rows in results.jsonl.
RP2040SIM_BENCH_RUNS := cgfs-1core:single-core:plain cgfs:two-core:plain \
                        cgfs-book-1core:single-core:book cgfs-book-bench:two-core:book \
                        cgfs-cube-1core:single-core:cube cgfs-cube:two-core:cube cgfs-cube-te:two-core-te:cubete \
                        cgfs-cube-ili9341-1core:single-core:cube320 cgfs-cube-ili9341:two-core:cube320 \
                        cgfs-cube-ili9341-fastspi:two-core-fastspi:cube320 \
                        cgfs-rt-1core:single-core:rt cgfs-rt:two-core:rt \
                        cgfs-mesh:two-core:mesh
# $(call rp2040sim_field,N,RUN): field N of a run (1 image, 2 variant, 3 set)
rp2040sim_field = $(word $(1),$(subst :, ,$(2)))
RP2040SIM_BENCH_IMAGES := $(foreach r,$(RP2040SIM_BENCH_RUNS),$(call rp2040sim_field,1,$(r)))
# The generated header that states a scene set's format (tools/bench/tag_frac.py
# adds it to the rows, "num_frac", so their accuracy is the image's): "-" for
# the placeholder, which has no scene.
rp2040sim_frac_h = $(if $(filter plain,$(1)),-,$(FW_OUT)/scenes/fw_$(patsubst cubete,cube,$(1))_num_frac.h)
# One recipe line per run: its rows to the terminal and to results.jsonl.
define RP2040SIM_BENCH_RUN
	$(Q)node tools/rp2040sim/rp2040sim.js --image $(FW_OUT)/pico/$(call rp2040sim_field,1,$(1)).elf \
		--variant $(call rp2040sim_field,2,$(1)) $(RP2040SIM_ARGS_$(call rp2040sim_field,3,$(1))) >$(RP2040SIM_TMP) && \
		$(PYTHON) tools/bench/tag_frac.py $(RP2040SIM_TMP) $(call rp2040sim_frac_h,$(call rp2040sim_field,3,$(1))) && \
		cat $(RP2040SIM_TMP) && cat $(RP2040SIM_TMP) >>$(BUILD)/bench/results.jsonl

endef
.PHONY: bench-rp2040
bench-rp2040: $(RP2040SIM_DEPS) $(foreach i,$(RP2040SIM_BENCH_IMAGES),$(FW_OUT)/pico/$(i).elf)
	@mkdir -p $(BUILD)/bench
	@# this step's lines are rewritten, the other steps' kept
	$(Q)grep -v '"target": *"rp2040-sim"' $(BUILD)/bench/results.jsonl >$(BUILD)/bench/results.jsonl.tmp 2>/dev/null; \
		mv $(BUILD)/bench/results.jsonl.tmp $(BUILD)/bench/results.jsonl
	$(foreach r,$(RP2040SIM_BENCH_RUNS),$(call RP2040SIM_BENCH_RUN,$(r)))
	$(Q)rm -f $(RP2040SIM_TMP)
bench: bench-rp2040
