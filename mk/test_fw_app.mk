# SPDX-License-Identifier: MIT
# The firmware application on a host board (tests/support/fw_app_host.c): main.c,
# the HAL's DCS layer and panel drivers, hal/sim into the emulated ST7789,
# the core in fixed point; scenes compiled by tools/scenec for this host (its
# own work sizes) at the coarsest format among them, with the renderer
# features they need and no others (as a board image). ASan+UBSan. (This file
# is read after mk/core.mk, hal.mk and scene.mk: it uses their variables.)
FWH         := $(BUILD)/fw_app_host
FWH_SCENES  ?= book/raytracer-02 book/raster-11
FWH_STRIP   := 8
FWH_FLAGS   := -DNUM_MODE=1 -include $(FWH)/scenes/num_frac.h -include $(FWH)/scenes/fw_host_features.h \
               -Ifirmware/app -I$(FWH)/scenes -Itests/support \
               -DFW_STRIP_ROWS=$(FWH_STRIP) -DFW_FRAMES_PER_SCENE=2 -DFW_WORK_CORES=1
FWH_SCENE_C := $(foreach n,$(FWH_SCENES),$(FWH)/scenes/$(call fw_scene_id,$(n)).c)
FWH_SRCS    := firmware/app/main.c firmware/app/font5x7.c $(HAL_SRCS) $(HAL_SIM_SRCS) $(CORE_SRCS) \
               tests/support/fw_app_host.c
FWH_OBJS    := $(patsubst %.c,$(FWH)/obj/%.o,$(FWH_SRCS)) \
               $(patsubst $(FWH)/scenes/%.c,$(FWH)/obj/scenes/%.o,$(FWH_SCENE_C) $(FWH)/scenes/fw_scenes_host.c)

$(foreach n,$(FWH_SCENES),\
    $(call scenec_rule,$(FWH)/scenes/$(call fw_scene_id,$(n)).c,$(n),240x240,$(FWH_STRIP),$(call fw_scene_id,$(n)),0))
$(FWH)/scenes/fw_scenes_host.c: $(FWH_SCENE_C:.c=.h) firmware/app/scene_table.sh
	$(Q)firmware/app/scene_table.sh $@ $(foreach n,$(FWH_SCENES),$(n)=$(FWH)/scenes/$(call fw_scene_id,$(n)).h)
$(call scene_frac_rule,$(FWH)/scenes/num_frac.h,$(FWH_SCENE_C:.c=.h))
$(FWH)/scenes/fw_host_features.h: $(FWH_SCENE_C:.c=.h) tools/scenec/features.sh
	$(Q)tools/scenec/features.sh $@ $(FWH_SCENE_C:.c=.h)

$(FWH)/obj/firmware/app/main.o: FWH_MAIN := -Dmain=fw_app_main
$(FWH)/obj/%.o: %.c $(FWH)/scenes/num_frac.h $(FWH)/scenes/fw_host_features.h $(FWH_SCENE_C:.c=.h)
	@mkdir -p $(@D)
	$(Q)$(CC) $(CSTD) $(WARN) $(ASAN_OPT) $(INCLUDES) $(FWH_FLAGS) $(FWH_MAIN) -MMD -MP -c $< -o $@
$(FWH)/obj/scenes/%.o: $(FWH)/scenes/%.c $(FWH)/scenes/num_frac.h $(FWH)/scenes/fw_host_features.h
	@mkdir -p $(@D)
	$(Q)$(CC) $(CSTD) $(WARN) $(ASAN_OPT) $(INCLUDES) $(FWH_FLAGS) -MMD -MP -c $< -o $@
$(FWH)/tests/fw_app_host: $(FWH_OBJS)
	@mkdir -p $(@D)
	$(Q)$(CC) $(LDFLAGS_asan) -o $@ $^ -lm

TEST_DEPS += $(FWH)/tests/fw_app_host
TESTS     += $(FWH)/tests/fw_app_host
