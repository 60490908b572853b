# Renderer core + scene parser, bundled once per numeric mode.
#
# CORE_SRCS run on the microcontroller; SCENE_SRCS are the host-side parser.
# Each (variant, mode) gets one relocatable object, $(BUILD)/<variant>/core_<mode>.o,
# in which every global symbol but core_api_<mode> is made local, so the
# three modes link into one program without clashes.

CORE_SRCS  := $(sort $(wildcard firmware/core/*.c))
SCENE_SRCS := $(sort $(wildcard tools/scene/*.c))
CORE_GLUE  := host_sim/core_api.c

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
core_bundles = $(foreach m,$(NUM_MODES),$(BUILD)/$(1)/core_$(m).o) $(call obj,$(1),none,host_sim/core_select.c)
