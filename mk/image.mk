# SPDX-License-Identifier: MIT
# `make image`: a board image of your own scene files, wherever they are.
#
#   make image SCENES="path/a.scene path/b.scene" NAME=mine [PANEL=ili9341] [FRAMES=N]
#
# builds build/firmware/pico/NAME.{elf,bin,uf2,map}: the two-core RP2040
# image (as cgfs-book and cgfs-cube, mk/firmware.mk) that shows the scenes in
# turn, each for its own frames (its `frames` key; FRAMES=N: N frames each),
# in a loop. PANEL: a panel of hal/panels.def, or a controller for its first
# one (default st7789: st7789_240x240; ili9341: ili9341_320x240); the scenes
# are compiled for that panel's size. Paths are relative to this directory
# or absolute.
#
# Everything generated lies under $(BUILD): the scene set in
# $(BUILD)/firmware/image/NAME/ and the objects in
# $(BUILD)/firmware/pico/obj-NAME/. The steps:
#   1. each scene by tools/scenec, its work memory measured on the target
#      (tools/scenec/target_work.sh): <id>.{c,h,log}, and <id>.d, the files
#      the scene made scenec read (textures, models), so that a change to any
#      of them compiles the scene again;
#   2. num_frac.h (the coarsest format among the scenes, as the scene sets'
#      fw_<set>_num_frac.h), fw_features.h (the renderer features the scenes
#      need, tools/scenec/features.sh: the rest of the core is left out) and
#      the table fw_scenes.c (firmware/app/scene_table.sh);
#   3. the check, before the scenes are compiled for the board and before the
#      image is linked: budget.elf is the image with the built-in
#      placeholder table instead of the scenes (the same objects otherwise),
#      and firmware/app/image_fits.sh takes the work memory the image has
#      (core 0's context and core 1's sibling of it) from it and the linker
#      script, and refuses, one line per scene, a scene whose work (its
#      scenec-summary line) does not fit;
#   4. the image itself.
# A wrong NAME, no SCENES, a scene file that is not there, a scene scenec
# refuses or one that does not fit: one line "image NAME: ..." and a non-zero
# exit, and no NAME.{elf,bin,uf2,map} is left (an older one is removed).

.PHONY: image
ifneq ($(filter image,$(MAKECMDGOALS)),)

# the characters left when those of the list $(2) are removed from $(1)
img_rest   = $(if $(2),$(call img_rest,$(subst $(firstword $(2)),,$(1)),$(wordlist 2,$(words $(2)),$(2))),$(1))
IMG_DIGITS := 0 1 2 3 4 5 6 7 8 9
IMG_ALNUM  := a b c d e f g h i j k l m n o p q r s t u v w x y z A B C D E F G H I J K L M N O P Q R S T U V W X Y Z \
              $(IMG_DIGITS)
PANEL  ?= st7789
FRAMES ?= 0
IMG_LPAREN := (
IMG_PANELS := $(shell sed -n 's/^PANEL$(IMG_LPAREN)\([A-Za-z0-9_]*\),.*/\1/p' hal/panels.def)
IMG_CONTROLLERS := $(sort $(foreach p,$(IMG_PANELS),$(firstword $(subst _, ,$(p)))))
IMG_PANEL  := $(if $(filter $(PANEL),$(IMG_PANELS)),$(PANEL),$(firstword $(filter $(PANEL)_%,$(IMG_PANELS))))

ifneq ($(words $(NAME)),1)
$(error image: NAME=name is needed: the image's name, of letters, digits, '-' and '_')
endif
ifneq ($(call img_rest,$(NAME),$(IMG_ALNUM) - _),)
$(error image $(NAME): NAME may have only letters, digits, '-' and '_')
endif
ifneq ($(filter cgfs cgfs-% boot2,$(NAME)),)
$(error image $(NAME): the name of an image of mk/firmware.mk; choose another NAME)
endif
ifeq ($(strip $(SCENES)),)
$(error image $(NAME): SCENES="a.scene b.scene" is needed: the scene files to show)
endif
IMG_BADPATH := $(firstword $(foreach f,$(SCENES),$(if $(call img_rest,$(f),$(IMG_ALNUM) . _ - / +),$(f))))
ifneq ($(IMG_BADPATH),)
$(error image $(NAME): $(IMG_BADPATH): a scene path may have only letters, digits and . _ - / +)
endif
IMG_MISSING := $(firstword $(foreach f,$(SCENES),$(if $(shell [ -f '$(f)' ] && [ -r '$(f)' ] && echo y),,$(f))))
ifneq ($(IMG_MISSING),)
$(error image $(NAME): $(IMG_MISSING): no such scene file)
endif
ifeq ($(IMG_PANEL),)
$(error image $(NAME): PANEL=$(PANEL): not a panel of hal/panels.def ($(IMG_PANELS), or a controller: $(IMG_CONTROLLERS)))
endif
ifneq ($(words $(FRAMES))$(call img_rest,$(FRAMES),$(IMG_DIGITS)),1)
$(error image $(NAME): FRAMES=$(FRAMES): a number of frames per scene, or 0 for each scene's own)
endif
ifneq ($(shell [ '$(FRAMES)' -le 65535 ] && echo y),y)
$(error image $(NAME): FRAMES=$(FRAMES): at most 65535)
endif
# the cross compiler and qemu (the work probe), installed or asked for
IMG_DEPS_ERR := $(shell tools/deps.sh examples 3>&2 2>&1 1>&3)
ifneq ($(.SHELLSTATUS),0)
$(error image $(NAME): $(IMG_DEPS_ERR))
endif

IMG        := $(FW_OUT)/image/$(NAME)
IMG_OBJ    := $(FW_OUT)/pico/obj-$(NAME)
IMG_OUTS   := $(foreach e,elf bin uf2 map,$(FW_OUT)/pico/$(NAME).$(e))
IMG_SIZE   := $(lastword $(subst _, ,$(IMG_PANEL)))
IMG_FILES  := $(abspath $(SCENES))
IMG_IDX    := $(shell seq 1 $(words $(IMG_FILES)))
# scene i: its name on the UART (the file's name without .scene) and its
# C identifier (s<i>_<name>)
img_file   = $(word $(1),$(IMG_FILES))
img_label  = $(patsubst %.scene,%,$(notdir $(call img_file,$(1))))
img_id     = s$(1)_$(subst .,_,$(subst -,_,$(subst +,_,$(call img_label,$(1)))))
IMG_C      := $(foreach i,$(IMG_IDX),$(IMG)/$(call img_id,$(i)).c)
IMG_FLAGS  := -DFW_PANEL=panel_$(IMG_PANEL) -DFW_WIDTH=$(firstword $(subst x, ,$(IMG_SIZE))) \
              -DFW_HEIGHT=$(lastword $(subst x, ,$(IMG_SIZE))) -DFW_FRAMES_PER_SCENE=$(FRAMES)

# What the scenes are compiled for, the file of each identifier (<id>.src)
# and the list of the table: each rewritten only when it changes, so that the
# scenes and the table follow.
img_keep = { echo '$(2)' | cmp -s - $(1) || echo '$(2)' >$(1); }
IMG_ARGS := $(IMG_SIZE) $(FW_STRIP_ROWS)
IMG_LIST := $(foreach i,$(IMG_IDX),$(call img_label,$(i))=$(call img_id,$(i)))
$(shell mkdir -p $(IMG) && $(call img_keep,$(IMG)/scenec.args,$(IMG_ARGS)) && \
        $(call img_keep,$(IMG)/scenes.list,$(IMG_LIST)) $(foreach i,$(IMG_IDX),&& $(call img_keep,$(IMG)/$(call img_id,$(i)).src,$(call img_file,$(i)))))

# 1. a scene: $(1) the file, $(2) its identifier
define IMG_SCENE
$(IMG)/$(2).c $(IMG)/$(2).h $(IMG)/$(2).log &: $(1) $(IMG)/$(2).src $(IMG)/scenec.args $(SCENEC) $(SCENE_PROBE) \
                                               firmware/app/image_scene.sh
	$(Q)firmware/app/image_scene.sh $(NAME) $(SCENEC) $(SCENE_PROBE) $(1) $(IMG_SIZE) $(FW_STRIP_ROWS) $(2) \
		$(IMG)/$(2).c || { rm -f $(IMG_OUTS); exit 2; }
endef
$(foreach i,$(IMG_IDX),$(eval $(call IMG_SCENE,$(call img_file,$(i)),$(call img_id,$(i)))))

# 2. the format (num_frac.h, rewritten only when it changes: the objects are
# compiled again only then) and the table
$(IMG)/num_frac.h: $(IMG_C:.c=.h)
	$(Q)f=$$(sed -n 's/^#define SCENE_[A-Za-z0-9_]*_NUM_FRAC *\([0-9][0-9]*\)$$/\1/p' $^ | sort -n | head -n 1); \
	[ -n "$$f" ] || { echo "image $(NAME): no SCENE_<ID>_NUM_FRAC in $^" >&2; exit 2; }; \
	printf '/* num_frac.h: generated by mk/image.mk, the coarsest format among the scenes of image %s */\n' \
		"$(NAME)" >$@.tmp; \
	printf '#ifndef NUM_FRAC\n#define NUM_FRAC %s\n#endif\n' "$$f" >>$@.tmp; \
	if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@; fi
$(IMG)/fw_scenes.c: $(IMG_C:.c=.h) firmware/app/scene_table.sh $(IMG)/scenes.list
	$(Q)firmware/app/scene_table.sh $@ $(foreach i,$(IMG_IDX),$(call img_label,$(i))=$(IMG)/$(call img_id,$(i)).h)

FW_IMG_SRCS       := $(IMG_C) $(IMG)/fw_scenes.c
FW_IMG_FRAC_H     := $(IMG)/num_frac.h
FW_IMG_FRAC_FLAGS := -include $(FW_IMG_FRAC_H)
FW_IMG_FEAT_H     := $(IMG)/fw_features.h
FW_IMG_FEAT_FLAGS := -include $(FW_IMG_FEAT_H)
$(FW_IMG_FEAT_H): $(IMG_C:.c=.h) tools/scenec/features.sh
	$(Q)tools/scenec/features.sh $@ $(IMG_C:.c=.h) || { rm -f $(IMG_OUTS); exit 2; }
$(call fw_scene_image,$(NAME),IMG,$(IMG_FLAGS))

# 3. the check: the image with the placeholder table (firmware/app/scenes_builtin.c)
ARM_NM ?= arm-none-eabi-nm
IMG_BUDGET_OBJS := $(patsubst %.c,$(IMG_OBJ)/%.o,$(RP_SRCS) firmware/app/scenes_builtin.c) \
                   $(patsubst %.S,$(IMG_OBJ)/%.o,$(RP_ASM)) $(IMG_OBJ)/boot2_crc.o
$(IMG_OBJ)/firmware/app/scenes_builtin.o: $(FW_IMG_FRAC_H) $(FW_IMG_FEAT_H)
$(IMG)/budget.elf: $(IMG_BUDGET_OBJS) $(RP_DIR)/rp2040.ld \
                   $(wildcard $(RP_DIR)/ram_text/$(RP_RAM_TEXT_DIR)/*.ld)
	$(Q)$(ARM_CC) $(RP_LDFLAGS) $(filter %.o,$^) -lc -lgcc -o $@
$(IMG)/fits: $(IMG)/budget.elf $(IMG_C:.c=.log) firmware/app/image_fits.sh
	$(Q)rm -f $@
	$(Q)ARM_NM=$(ARM_NM) firmware/app/image_fits.sh $(NAME) 2 $(RP_DIR)/rp2040.ld $< \
		$(foreach i,$(IMG_IDX),$(notdir $(call img_file,$(i)))=$(IMG)/$(call img_id,$(i)).log) >$@.tmp || \
		{ rm -f $@.tmp $(IMG_OUTS); exit 2; }
	$(Q)mv $@.tmp $@
# the scenes are compiled for the board, and the image linked, only once they fit
$(patsubst %.c,$(IMG_OBJ)/%.o,$(FW_IMG_SRCS)): | $(IMG)/fits
$(FW_OUT)/pico/$(NAME).elf: $(IMG)/fits

# 4. the image
image: $(FW_OUT)/pico/$(NAME).uf2 $(FW_OUT)/pico/$(NAME).elf
	$(Q)cat $(IMG)/fits
	@echo "image $(NAME): $(FW_OUT)/pico/$(NAME).uf2 (and .elf): $(words $(IMG_FILES)) scene(s), $(IMG_PANEL)," \
	      "NUM_FRAC $$(sed -n 's/^#define NUM_FRAC //p' $(FW_IMG_FRAC_H)), two cores"

endif

# tests/system/test_image.sh runs `make image` itself, on scenes in a
# temporary directory, and the image in rp2040js.
TEST_NEEDS_test_image := $(SCENEC) $(SCENE_PROBE) $(FW_OUT)/pico/boot2_crc.S $(BUILD)/host_sim $(RP2040SIM_DEPS)
TEST_DEPS += $(TEST_NEEDS_test_image)
TESTS     += tests/system/test_image.sh:$(BUILD)
TESTS_TARGET_ONLY += tests/system/test_image.sh:%
