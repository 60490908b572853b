# SPDX-License-Identifier: MIT
# `make examples`: the renderer and the HAL in a program of your own
# (firmware/examples/, docs/embedding.md), one source built twice:
#   $(BUILD)/examples/host/panel_demo        this host (ASan+UBSan)
#   $(BUILD)/examples/m0plus/panel_demo.elf  Cortex-M0+ (arm-none-eabi-gcc), on qemu's
#                                            mps2-an385 board with tools/bench's start-up
# Each build has its own scenes from tools/scenec (the host's work sizes; the
# Cortex-M0+'s, measured by the work probe) and compiles everything at the
# coarsest number format among them (scene_frac_rule). tests/system/test_examples.sh
# runs both and checks their output.

EX         := $(BUILD)/examples
EX_SCENES  := book/raytracer-02 book/raster-11
EX_STRIP   := 16
EX_TARGETS := host m0plus
EX_SRCS    := firmware/examples/panel_demo.c firmware/examples/trace_hal.c $(HAL_SRCS) $(CORE_SRCS)
# the scene's C identifier and file name: raytracer_02, raster_11
ex_id       = $(subst -,_,$(notdir $(1)))
ex_scene_c  = $(foreach n,$(EX_SCENES),$(EX)/$(1)/scenes/$(call ex_id,$(n)).c)
ex_flags    = -DNUM_MODE=1 -include $(EX)/$(1)/scenes/num_frac.h -Ifirmware/core -Ihal -Ifirmware/examples \
              -I$(EX)/$(1)/scenes
ex_objs     = $(patsubst %.c,$(EX)/$(1)/obj/%.o,$(EX_SRCS) $(call ex_scene_c,$(1)) $(2))

$(foreach t,$(EX_TARGETS),$(foreach n,$(EX_SCENES),\
    $(call scenec_rule,$(EX)/$(t)/scenes/$(call ex_id,$(n)).c,$(n),240x240,$(EX_STRIP),$(call ex_id,$(n)),$(if $(filter m0plus,$(t)),1,0))))
$(foreach t,$(EX_TARGETS),$(call scene_frac_rule,$(EX)/$(t)/scenes/num_frac.h,$(patsubst %.c,%.h,$(call ex_scene_c,$(t)))))

# the host: sanitizers on, as every host test
$(EX)/host/obj/%.o: %.c $(EX)/host/scenes/num_frac.h
	@mkdir -p $(@D)
	$(Q)$(CC) $(CSTD) $(WARN) $(ASAN_OPT) $(call ex_flags,host) -MMD -MP -c $< -o $@
$(EX)/host/panel_demo: $(call ex_objs,host)
	$(Q)$(CC) $(LDFLAGS_asan) -o $@ $^ -lm

# the Cortex-M0+: stdout by semihosting (newlib's rdimon), main called by
# firmware/examples/qemu_m0plus.c
EX_M0_CC := $(BENCH_CC) $(BENCH_CPU_m0plus-qemu)
$(EX)/m0plus/obj/firmware/examples/panel_demo.o: EX_MAIN := -Dmain=panel_demo_main
$(EX)/m0plus/obj/%.o: %.c $(EX)/m0plus/scenes/num_frac.h
	@mkdir -p $(@D)
	$(Q)$(EX_M0_CC) -std=c11 -O2 $(WARN) -ffunction-sections -fdata-sections $(call ex_flags,m0plus) $(EX_MAIN) \
		-Itools/bench -MMD -MP -c $< -o $@
$(EX)/m0plus/panel_demo.elf: $(call ex_objs,m0plus,firmware/examples/qemu_m0plus.c tools/bench/startup.c) $(BENCH_LD)
	$(Q)$(EX_M0_CC) -nostartfiles -T $(BENCH_LD) --specs=nano.specs --specs=rdimon.specs -Wl,--gc-sections \
		-o $@ $(filter %.o,$^) -lm

# every object waits for the scenes' headers (panel_demo.c includes them)
$(foreach t,$(EX_TARGETS),$(eval $(call ex_objs,$(t)): $(patsubst %.c,%.h,$(call ex_scene_c,$(t)))))

EX_BINS := $(EX)/host/panel_demo $(EX)/m0plus/panel_demo.elf
.PHONY: examples
examples:
	$(Q)tools/deps.sh examples
	$(Q)$(MAKE) --no-print-directory $(EX_BINS)

TEST_NEEDS_test_examples := $(EX_BINS) $(BUILD)/asan/tests/test_panel_vectors $(BUILD)/host_sim
TEST_DEPS += $(TEST_NEEDS_test_examples)
TESTS     += tests/system/test_examples.sh:$(BUILD)
