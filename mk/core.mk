# SPDX-License-Identifier: MIT
# Renderer core + scene parser, bundled once per numeric mode.
#
# CORE_SRCS (the Makefile's) run on the microcontroller; SCENE_SRCS are the host-side parser.
# Each (variant, mode) gets one relocatable object, $(BUILD)/<variant>/core_<mode>.o,
# in which every global symbol but core_api_<mode> is made local (the
# Makefile's bundle), so the three modes link into one program without clashes.

SCENE_SRCS := $(sort $(wildcard tools/scene/*.c))
CORE_GLUE  := tools/core_api/core_api.c

# Debug/test counting of saturations in host builds.
$(BUILD)/host/%.o $(BUILD)/asan/%.o: EXTRA_CFLAGS += -DNUM_COUNT_SAT

$(foreach v,$(VARIANTS),$(foreach m,$(NUM_MODES),$(call bundle,$(BUILD)/$(v)/core_$(m).o,\
    $(call obj,$(v),$(m),$(CORE_SRCS) $(SCENE_SRCS) $(CORE_GLUE)),core_api_$(m))))

# All three modes of a variant, as objects to link.
core_bundles = $(foreach m,$(NUM_MODES),$(BUILD)/$(1)/core_$(m).o) $(call obj,$(1),none,tools/core_api/core_select.c)

# ---- fixed point at every NUM_FRAC the scene analysis may choose ------------
# (tools/scene/scene_format.c: scenec for the firmware, host_sim --numeric
# fixed.) The core + parser bundled once per format, each exporting
# core_api_fixed<F> (core_api_fixed is NUM_FRAC 16; modes fixed12 and
# fixed20 are mk/num.mk's, fixed13 … fixed19 these).
CORE_FRACS      := 12 13 14 15 16 17 18 19 20
CORE_FRAC_MODES := $(foreach f,$(filter-out 16,$(CORE_FRACS)),fixed$(f))
CORE_FRAC_OWN   := $(filter-out fixed12 fixed20,$(CORE_FRAC_MODES))
COMPILE_MODES   += $(CORE_FRAC_OWN)
$(foreach m,$(CORE_FRAC_OWN),$(eval MODE_FLAGS_$(m) := -DNUM_MODE=1 -DNUM_FRAC=$(m:fixed%=%)))
$(foreach v,$(VARIANTS),$(foreach m,$(CORE_FRAC_MODES),$(call bundle,$(BUILD)/$(v)/core_$(m).o,\
    $(call obj,$(v),$(m),$(CORE_SRCS) $(SCENE_SRCS) $(CORE_GLUE)),core_api_$(m),core_api_fixed)))

# Every format's bundle of a variant and the selector core_api_fixed_frac().
core_frac_bundles = $(foreach m,$(CORE_FRAC_MODES),$(BUILD)/$(1)/core_$(m).o) \
                    $(call obj,$(1),none,tools/core_api/core_fracs.c)

# render.h's contract, the same for both renderers (coverage mask and count,
# NULL stats, strip heights, bad arguments), in every numeric mode.
$(foreach m,$(NUM_MODES),$(call program,$(BUILD)/asan/tests/test_render_contract_$(m),\
    $(call obj,asan,$(m),tests/unit/test_render_contract.c $(SCENE_SRCS)) $(call core_lib,asan,$(m)),asan))
TEST_DEPS += $(foreach m,$(NUM_MODES),$(BUILD)/asan/tests/test_render_contract_$(m))
TESTS     += $(foreach m,$(NUM_MODES),$(BUILD)/asan/tests/test_render_contract_$(m))

# Every external symbol of the core carries its layer's prefix (nm of the
# objects of each numeric mode).
TEST_NEEDS_test_symbols := $(foreach m,$(NUM_MODES),$(call obj,host,$(m),$(CORE_SRCS)))
TEST_DEPS += $(TEST_NEEDS_test_symbols)
TESTS     += tests/system/test_symbols.py:$(BUILD)
