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
