# Scene files: the parser's tests (per numeric mode), its fuzz target, and
# the scene compiler (tools/scenec).

SCENE_PARSER_SRCS := tools/scene/scene_parse.c firmware/core/num.c firmware/core/vec.c

# test_scene_<mode>: the parser built alone in each numeric mode.
define SCENE_TEST
$(BUILD)/$(1)/test_scene_$(2): $(call obj,$(1),$(2),tests/test_scene.c $(SCENE_PARSER_SRCS))
	@mkdir -p $$(@D)
	$(Q)$$(CC) $(LDFLAGS_$(1)) -o $$@ $$^ -lm
endef
$(foreach m,$(NUM_MODES),$(eval $(call SCENE_TEST,asan,$(m))))
$(BUILD)/asan/%/tests/test_scene.o: EXTRA_CFLAGS += -Itests

SCENE_TESTS := $(foreach m,$(NUM_MODES),$(BUILD)/asan/test_scene_$(m))
TEST_DEPS += $(SCENE_TESTS)
TESTS += $(SCENE_TESTS)

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
	tests/test_scene_fuzz.sh $(FUZZ_SCENE) $(FUZZ_SECONDS)

TEST_DEPS += $(FUZZ_SCENE)
TESTS += tests/test_scene_fuzz.sh:$(FUZZ_SCENE):$(FUZZ_SECONDS)

# ---- scenec: scene file -> C source for the firmware -----------------------
# Built in the double mode (the parser's exact doubles are emitted as NUM_C
# literals) and linked with the fixed-point core bundle for render_work_size.
SCENEC := $(BUILD)/scenec
$(SCENEC): $(call obj,host,double,tools/scenec/scenec.c $(SCENE_PARSER_SRCS)) $(BUILD)/host/core_fixed.o
	@mkdir -p $(@D)
	$(Q)$(CC) -o $@ $^ -lm
$(BUILD)/host/double/tools/scenec/scenec.o: EXTRA_CFLAGS += -Ihost_sim
PROGRAMS += $(SCENEC)

# Every scene compiled for the default panel (ST7789 240x240, 16-row strips).
SCENE_SIZE  ?= 240x240
SCENE_STRIP ?= 16
SCENE_FILES := $(sort $(shell find firmware/scenes -name '*.scene' 2>/dev/null))
SCENE_CSRCS := $(patsubst firmware/scenes/%.scene,$(BUILD)/scenes/%.c,$(SCENE_FILES))
$(BUILD)/scenes/%.c: firmware/scenes/%.scene $(SCENEC)
	@mkdir -p $(@D)
	$(Q)$(SCENEC) --size $(SCENE_SIZE) --strip-rows $(SCENE_STRIP) -o $@ $< > $(@:.c=.log) || { cat $(@:.c=.log); exit 2; }
.PHONY: scenes scenes-report
scenes: $(SCENE_CSRCS)
# RAM and flash per compiled scene, as the ARM compiler lays them out.
scenes-report: $(SCENE_CSRCS)
	$(Q)tests/test_scenec.sh $(SCENEC) $(BUILD) --report

TEST_DEPS += $(SCENEC)
TESTS += tests/test_scenec.sh:$(SCENEC):$(BUILD)
