# SPDX-License-Identifier: MIT
# `make bench` on the emulated MCUs (qemu-system-arm, see docs/numerics.md).
#
# Images run on two emulated boards:
#   m0plus-qemu  mps2-an385, code built -mcpu=cortex-m0plus -mthumb (ARMv6-M)
#   m4f-qemu     mps2-an386, -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16
# with -icount shift=0,align=off: the figures are instruction counts, not cycles.
#
# Building an image of your own (e.g. a whole frame of a scene):
#   $(call bench_image,NAME,TARGET,MODE,SOURCES[,CFLAGS])
#   BENCH_IMAGES += $(BUILD)/bench/TARGET/MODE/NAME.elf
# SOURCES are C files (the renderer core, a main); one of them defines
# int bench_main(void) and reports with bench_report() from tools/bench/bench.h,
# e.g. bench_report("scene:book/raytracer-05", NUM_NAME, "strip16", instr * 1000, "frame"),
# a scene row followed by bench_frame_line() (the frame's checksum and what was
# rendered: tools/bench/accuracy.py measures the row's accuracy on that frame).
# The start-up code, semihosting and linker script are added here. `make bench`
# runs every image of BENCH_IMAGES and rewrites its lines of
# $(BUILD)/bench/results.jsonl (other lines are kept).

BENCH_CC       := arm-none-eabi-gcc
BENCH_TARGETS  := m0plus-qemu m4f-qemu
BENCH_CPU_m0plus-qemu := -mcpu=cortex-m0plus -mthumb
BENCH_CPU_m4f-qemu    := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
BENCH_RUNTIME  := tools/bench/startup.c
BENCH_LD       := tools/bench/mps2.ld
BENCH_CFLAGS   := -std=c11 -O2 -g -Wall -Wextra -Werror -ffunction-sections -fdata-sections \
                  -ffp-contract=off $(INCLUDES) -Itools/bench
BENCH_LDFLAGS  := -nostartfiles -T $(BENCH_LD) --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections
BENCH_IMAGES   :=

# 1 name, 2 target, 3 mode, 4 sources, 5 extra flags
define BENCH_IMAGE
$(BUILD)/bench/$(2)/$(3)/$(1).elf: $(patsubst %.c,$(BUILD)/bench/$(2)/$(3)/$(1).objs/%.o,$(4) $(BENCH_RUNTIME)) $(BENCH_LD)
	$(Q)$(BENCH_CC) $(BENCH_CPU_$(2)) $(BENCH_LDFLAGS) -o $$@ $$(filter %.o,$$^) -lm -lc -lgcc
$(BUILD)/bench/$(2)/$(3)/$(1).objs/%.o: %.c
	@mkdir -p $$(@D)
	$(Q)$(BENCH_CC) $(BENCH_CPU_$(2)) $(BENCH_CFLAGS) -DNUM_MODE=$(NUM_MODE_$(3)) $(5) -MMD -MP -c $$< -o $$@
endef
bench_image = $(eval $(call BENCH_IMAGE,$(1),$(2),$(3),$(4),$(5)))

# Microbenchmarks of the numeric layer: every target x numeric mode.
BENCH_NUM_SRCS := tools/bench/bench_num.c $(CORE_NUM_SRCS)
$(foreach t,$(BENCH_TARGETS),$(foreach m,$(NUM_MODES),\
  $(call bench_image,num,$(t),$(m),$(BENCH_NUM_SRCS))\
  $(eval BENCH_IMAGES += $(BUILD)/bench/$(t)/$(m)/num.elf)))

# Boot smoke test (part of `make test`): one short image per target.
$(foreach t,$(BENCH_TARGETS),$(call bench_image,smoke,$(t),fixed,$(BENCH_NUM_SRCS),-DBENCH_SMOKE))
BENCH_SMOKE_IMAGES := $(foreach t,$(BENCH_TARGETS),$(BUILD)/bench/$(t)/fixed/smoke.elf)
TEST_DEPS += $(BENCH_SMOKE_IMAGES)
TESTS     += tools/bench/run.py:--smoke:$(subst $(eval) ,:,$(BENCH_SMOKE_IMAGES))

# Every scene row's accuracy is that of its own image (tools/bench/accuracy.py
# checks host_sim's frame against the image's frame_checksum): the rules on
# rows the test makes, and three images through run.py and accuracy.py (the
# book scenes' default paths and trilinear variant, a scene of 10 frames, and
# the bilinear cube, whose board loop is ARMv6-M assembly on the M0+: its
# frame must be the host's C loop's).
BENCH_ACC_IMAGES := $(BUILD)/bench/m0plus-qemu/fixed/raster.elf $(BUILD)/bench/m0plus-qemu/fixed/scene-cube-flat.elf \
                    $(BUILD)/bench/m0plus-qemu/fixed/scene-cube-bilinear-default.elf
TESTS     += tests/system/test_bench_accuracy.py:$(BUILD)/host_sim \
             tests/system/test_bench_accuracy.py:$(BUILD)/host_sim:$(subst $(eval) ,:,$(BENCH_ACC_IMAGES))
TEST_DEPS += $(BUILD)/host_sim $(BENCH_ACC_IMAGES)

# tools/bench/profile.py's self and inclusive figures and calls on a made-up
# block trace (calls, a tail call, recursion, exceptions, a long jump).
TESTS     += tests/system/test_profile.py

# The measured tables of README.md and docs/*.md come from results.jsonl
# (tools/bench/doc_tables.py: each between comments naming its generator).
# `make bench` ends by listing the tables its figures made stale;
# `make bench-tables` rewrites them.
TESTS     += tests/system/test_doc_tables.py
.PHONY: bench-tables bench-tables-check
bench-tables:
	$(Q)$(PYTHON) tools/bench/doc_tables.py $(BUILD)/bench/results.jsonl
bench-tables-check: bench-accuracy
	$(Q)$(PYTHON) tools/bench/doc_tables.py --check $(BUILD)/bench/results.jsonl || \
		echo "make bench-tables rewrites the stale tables above"

.PHONY: bench bench-qemu
bench: bench-qemu bench-tables-check
# (the recipe expands BENCH_IMAGES after every mk/*.mk has added to it)
bench-qemu:
	$(Q)tools/deps.sh bench || true
	$(Q)$(MAKE) --no-print-directory $(BENCH_IMAGES)
	$(Q)$(PYTHON) tools/bench/run.py --out $(BUILD)/bench/results.jsonl $(BENCH_IMAGES)
