# Renderer core + scene parser, bundled once per numeric mode.
#
# CORE_SRCS run on the microcontroller; SCENE_SRCS are the host-side parser.
# Each (variant, mode) gets one relocatable object, $(BUILD)/<variant>/core_<mode>.o,
# in which every global symbol but core_api_<mode> is made local, so the
# three modes link into one program without clashes.

CORE_SRCS  := $(sort $(wildcard firmware/core/*.c))
SCENE_SRCS := $(sort $(wildcard tools/scene/*.c))
CORE_GLUE  := tools/core_api/core_api.c

# Debug/test counting of saturations in host builds.
$(BUILD)/host/%.o $(BUILD)/asan/%.o: EXTRA_CFLAGS += -DNUM_COUNT_SAT

define CORE_BUNDLE
$(BUILD)/$(1)/core_$(2).o: $(call obj,$(1),$(2),$(CORE_SRCS) $(SCENE_SRCS) $(CORE_GLUE))
	@mkdir -p $$(@D)
	$(Q)ld -r -o $$@.tmp $$^
	$(Q)objcopy --keep-global-symbol=core_api_$(2) $$@.tmp $$@
	$(Q)rm -f $$@.tmp
endef
$(foreach v,$(VARIANTS),$(foreach m,$(NUM_MODES),$(eval $(call CORE_BUNDLE,$(v),$(m)))))

# All three modes of a variant, as objects to link.
core_bundles = $(foreach m,$(NUM_MODES),$(BUILD)/$(1)/core_$(m).o) $(call obj,$(1),none,tools/core_api/core_select.c)

# ---- fixed point at every NUM_FRAC the scene analysis may choose ------------
# (tools/scene/scene_format.c: scenec for the firmware, host_sim --numeric
# fixed.) The core + parser bundled once per format, each exporting
# core_api_fixed<F> (core_api_fixed is NUM_FRAC 16; fixed12 and fixed20
# compile by mk/num.mk's rules, fixed13 … fixed19 by the rule below).
CORE_FRACS      := 12 13 14 15 16 17 18 19 20
CORE_FRAC_MODES := $(foreach f,$(filter-out 16,$(CORE_FRACS)),fixed$(f))
CORE_FRAC_OWN   := $(filter-out fixed12 fixed20,$(CORE_FRAC_MODES))
define CORE_FRAC_RULE
$(BUILD)/$(1)/$(2)/%.o: %.c
	@mkdir -p $$(@D)
	$(Q)$$(CC) $(CSTD) $(WARN) $(VFLAGS_$(1)) -DNUM_MODE=1 -DNUM_FRAC=$(2:fixed%=%) $(INCLUDES) $$(EXTRA_CFLAGS) -MMD -MP -c $$< -o $$@
endef
define CORE_FRAC_BUNDLE
$(BUILD)/$(1)/core_$(2).o: $(call obj,$(1),$(2),$(CORE_SRCS) $(SCENE_SRCS) $(CORE_GLUE))
	@mkdir -p $$(@D)
	$(Q)ld -r -o $$@.tmp $$^
	$(Q)objcopy --keep-global-symbol=core_api_fixed $$@.tmp $$@.tmp2
	$(Q)objcopy --redefine-sym core_api_fixed=core_api_$(2) $$@.tmp2 $$@
	$(Q)rm -f $$@.tmp $$@.tmp2
endef
$(foreach v,$(VARIANTS),$(foreach m,$(CORE_FRAC_OWN),$(eval $(call CORE_FRAC_RULE,$(v),$(m)))))
$(foreach v,$(VARIANTS),$(foreach m,$(CORE_FRAC_MODES),$(eval $(call CORE_FRAC_BUNDLE,$(v),$(m)))))

# Every format's bundle of a variant and the selector core_api_fixed_frac().
core_frac_bundles = $(foreach m,$(CORE_FRAC_MODES),$(BUILD)/$(1)/core_$(m).o) \
                    $(call obj,$(1),none,tools/core_api/core_fracs.c)
