# SPDX-License-Identifier: MIT
# Scene files: the parser's tests (per numeric mode), its fuzz target, and
# the scene compiler (tools/scenec).

SCENE_PARSER_SRCS := tools/scene/scene_parse.c tools/scene/scene_depth.c $(CORE_NUM_SRCS) firmware/core/mipmap.c

# PNG textures (libpng, WITH_PNG) in every host build of the parser; the
# images that parse scenes on an emulated MCU (the work probe, bench_file)
# build it without, and read binary PPM only.
$(foreach v,$(VARIANTS),$(BUILD)/$(v)/%/tools/scene/scene_parse.o): EXTRA_CFLAGS += -DWITH_PNG $(PNG_CFLAGS)
$(foreach v,$(VARIANTS),$(foreach m,$(COMPILE_MODES),$(call obj,$(v),$(m),tools/scene/scene_parse.c))): | deps

# test_scene_<mode>: the parser built alone in each numeric mode.
$(foreach m,$(NUM_MODES),$(call program,$(BUILD)/asan/tests/test_scene_$(m),\
    $(call obj,asan,$(m),tests/unit/test_scene.c $(SCENE_PARSER_SRCS)),asan))

# test_scene_obj_<mode>: models from OBJ files (tests/data/obj/).
$(foreach m,$(NUM_MODES),$(call program,$(BUILD)/asan/tests/test_scene_obj_$(m),\
    $(call obj,asan,$(m),tests/unit/test_scene_obj.c $(SCENE_PARSER_SRCS)),asan))

SCENE_TESTS := $(foreach m,$(NUM_MODES),$(BUILD)/asan/tests/test_scene_$(m) $(BUILD)/asan/tests/test_scene_obj_$(m))
TEST_DEPS += $(SCENE_TESTS)
TESTS += $(SCENE_TESTS)

# Models from OBJ files end to end: host_sim and scenec on tests/data/obj/,
# and a model of 16384 triangles parsed on the emulated Cortex-M0+ by the
# benchmark image (mk/charts.mk's, fixed point and double).
TEST_DEPS += $(HOST_SIM_BIN_asan) $(SCENEC)
TESTS     += tests/system/test_obj.sh:$(HOST_SIM_BIN_asan):$(SCENEC)
OBJ_MCU_IMAGES := $(foreach m,fixed20 double,$(BUILD)/charts/bench/m0plus-qemu/$(m)/bench_file.elf)
TEST_DEPS += $(OBJ_MCU_IMAGES)
TESTS     += tests/system/test_obj_mcu.sh:$(subst $(eval) ,:,$(OBJ_MCU_IMAGES))

# Fuzz target: libFuzzer (clang), fixed point (the strictest ranges).
FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 20
FUZZ_SCENE   := $(BUILD)/fuzz/fuzz_scene
$(FUZZ_SCENE): tests/fuzz/fuzz_scene.c $(SCENE_PARSER_SRCS) tools/scene/scene_parse.h firmware/core/scene.h firmware/core/num.h
	@mkdir -p $(@D)
	$(Q)$(FUZZ_CC) $(CSTD) $(WARN) -O1 -g -ffp-contract=off -fsanitize=fuzzer,address,undefined \
		-fno-sanitize-recover=all -DNUM_MODE=$(NUM_MODE_fixed) $(INCLUDES) \
		-o $@ tests/fuzz/fuzz_scene.c $(SCENE_PARSER_SRCS) -lm
.PHONY: fuzz-scene
fuzz-scene: $(FUZZ_SCENE)
	tests/system/test_scene_fuzz.sh $(FUZZ_SCENE) $(FUZZ_SECONDS)

TEST_DEPS += $(FUZZ_SCENE)
TESTS += tests/system/test_scene_fuzz.sh:$(FUZZ_SCENE):$(FUZZ_SECONDS)

# ---- scenec: scene file -> C source for the firmware -----------------------
# Built in the double mode (the parser's exact doubles are emitted as NUM_C
# literals) and linked with the NUM_FRAC 12 core bundle for render_work_size
# (its fallback when the target's is not given). fopen is wrapped: scenec
# --deps names every file the scene made it read (tools/scenec/scenec.c).
# With an accuracy target (--min-psnr, the scene's quality block) it renders
# the candidate methods on this host (tools/quality): every core bundle.
# Its flash figure counts the types of the const data at the target's sizes
# (--target-work's, the work probe's) or else at this host's fixed-point
# build's (tools/scenec/scene_layout.c, compiled in fixed point here).
$(SCENEC): $(call obj,host,double,tools/scenec/scenec.c tools/common/file_id.c tools/scene/scene_format.c $(SCENE_PARSER_SRCS)) \
           $(call obj,host,fixed,tools/scenec/scene_layout.c) \
           $(call obj,host,none,tools/quality/quality.c) $(call core_bundles,host) \
           $(call core_frac_bundles,host)
	@mkdir -p $(@D)
	$(Q)$(CC) -Wl,--wrap=fopen -o $@ $^ $(PNG_LIBS) -lm
PROGRAMS += $(SCENEC)

# Every scene compiled for the default panel (ST7789 240x240, 16-row strips).
SCENE_SIZE  ?= 240x240
SCENE_STRIP ?= 16
SCENE_FILES := $(sort $(shell find firmware/scenes -name '*.scene' 2>/dev/null))
SCENE_CSRCS := $(patsubst firmware/scenes/%.scene,$(BUILD)/scenes/%.c,$(SCENE_FILES))
# The work size is the target's (SCENE_TARGET_WORK=0: this host's upper bound).
SCENE_TARGET_WORK ?= 1
$(foreach f,$(SCENE_FILES),$(call scenec_rule,$(patsubst firmware/scenes/%.scene,$(BUILD)/scenes/%.c,$(f)),\
    $(patsubst firmware/scenes/%.scene,%,$(f)),$(SCENE_SIZE),$(SCENE_STRIP),,$(SCENE_TARGET_WORK)))

# The work probe: core + parser for the Cortex-M0+ at NUM_FRAC 12, run in
# qemu-system-arm by tools/scenec/target_work.sh (file I/O by semihosting).
SCENE_PROBE_SRCS := tools/scenec/work_probe.c tools/scenec/scene_layout.c tools/bench/startup.c $(CORE_SRCS) $(SCENE_SRCS)
SCENE_PROBE_OBJS := $(patsubst %.c,$(BUILD)/scenes/probe-obj/%.o,$(SCENE_PROBE_SRCS))
$(BUILD)/scenes/probe-obj/%.o: %.c
	@mkdir -p $(@D)
	$(Q)arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -std=c11 -Os $(WARN) -ffunction-sections -fdata-sections \
		-DNUM_MODE=1 -DNUM_FRAC=12 $(INCLUDES) -Itools/bench -MMD -MP -c $< -o $@
$(SCENE_PROBE): $(SCENE_PROBE_OBJS) tools/bench/mps2.ld
	$(Q)arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -nostartfiles -T tools/bench/mps2.ld --specs=nano.specs \
		--specs=rdimon.specs -Wl,--gc-sections -o $@ $(SCENE_PROBE_OBJS) -lm
-include $(SCENE_PROBE_OBJS:.o=.d)
.PHONY: scenes scenes-report
scenes: $(SCENE_CSRCS)
# RAM and flash per compiled scene, as the ARM compiler lays them out, and
# the renderer code an image of it alone carries with its features
# (tools/scenec/scene_code.sh; its objects kept in $(BUILD)/scenes/code).
scenes-report: $(SCENE_CSRCS) $(SCENE_PROBE)
	$(Q)tests/system/test_scenec.sh $(SCENEC) $(BUILD) --report

# A core without some renderer features refuses the scenes that need them
# (firmware/core/scene_features.def; the test compiles its own core).
TESTS += tests/system/test_features.sh

TEST_NEEDS_test_scenec := $(SCENEC) $(SCENE_PROBE) $(BUILD)/asan/tests/test_scene_fracs
TEST_DEPS += $(TEST_NEEDS_test_scenec)
TESTS += tests/system/test_scenec.sh:$(SCENEC):$(BUILD)

# ---- the renderers at every NUM_FRAC scenec may choose ----------------------
# The bundles core_fixed12 … core_fixed20 are mk/core.mk's (CORE_FRAC_MODES).
SCENE_FRACS       := $(CORE_FRACS)
SCENE_FRAC_MODES  := $(CORE_FRAC_MODES)

# test_scene_fracs: every scene at every format against the double core.
$(foreach v,$(VARIANTS),$(call program,$(BUILD)/$(v)/tests/test_scene_fracs,$(call obj,$(v),none,tests/unit/test_scene_fracs.c \
    host_sim/compare.c) $(foreach m,$(SCENE_FRAC_MODES) fixed double,$(BUILD)/$(v)/core_$(m).o),$(v)))
$(foreach v,$(VARIANTS),$(call obj,$(v),none,tests/unit/test_scene_fracs.c)): EXTRA_CFLAGS += -Itests/support -Ihost_sim
.PHONY: scene-fracs-report
scene-fracs-report: $(BUILD)/host/tests/test_scene_fracs
	$(Q)$(BUILD)/host/tests/test_scene_fracs --report $(SCENE_FILES)

# ---- the keys' table (firmware/core/scene_options.def) and the doc ---------
# docs/scene-format.md's option tables are generated from it
# (tools/scene/options_doc.py --write docs/scene-format.md) and checked here.
TESTS += tools/scene/options_doc.py:--check:docs/scene-format.md tools/scene/options_doc.py:--self-test

# Fast Phong's specular tables scenec writes (--spec-tables flash) against
# the core's own (tests/unit/test_spec_tables.c): each scene of
# tests/data/spec/ compiled by scenec (identifier spec_scene), then linked
# with the host core of every format it holds (the ones its tables are
# written for): test_spec_tables_<scene>_<F>.
SPEC_T      := $(BUILD)/tests/spec
spec_mode    = $(if $(filter 16,$(1)),fixed,fixed$(1))
SPEC_FRACS_exponents       := 12 13 14 15 16 17 18 19 20
SPEC_FRACS_exponents-large := 12 13 14 15 16
define SPEC_SCENE_RULE
$(SPEC_T)/$(1)/spec_scene.c $(SPEC_T)/$(1)/spec_scene.h &: tests/data/spec/$(1).scene $(SCENEC)
	@mkdir -p $(SPEC_T)/$(1)
	$(Q)$(SCENEC) --size 64x64 --id spec_scene --spec-tables flash -o $(SPEC_T)/$(1)/spec_scene.c $$< \
		>$(SPEC_T)/$(1)/spec_scene.log || { cat $(SPEC_T)/$(1)/spec_scene.log; exit 2; }
endef
$(foreach n,exponents exponents-large,$(eval $(call SPEC_SCENE_RULE,$(n))))
$(foreach n,exponents exponents-large,$(foreach f,$(SPEC_FRACS_$(n)),$(call program,$(SPEC_T)/test_spec_tables_$(n)_$(f),\
    $(call obj,host,$(call spec_mode,$(f)),tests/unit/test_spec_tables.c $(SPEC_T)/$(n)/spec_scene.c $(CORE_SRCS)),host)\
    $(eval $(call obj,host,$(call spec_mode,$(f)),$(SPEC_T)/$(n)/spec_scene.c): $(SPEC_T)/$(n)/spec_scene.h)\
    $(eval TESTS += $(SPEC_T)/test_spec_tables_$(n)_$(f))\
    $(eval TEST_DEPS += $(SPEC_T)/test_spec_tables_$(n)_$(f))))
