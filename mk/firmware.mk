# SPDX-License-Identifier: MIT
# Board images: `make firmware` cross-builds the RP2040 (Pico + ST7789) and
# STM32F411 images. The fragments read right after this one build on them
# (the Makefile's FW_FRAGMENTS): mk/flasher.mk (the host flasher, `make
# flash`), mk/rp2040sim.mk (the images on the rp2040js emulator: tests) and
# mk/bench-rp2040.mk (`make bench-rp2040`).
#
#   build/firmware/pico/cgfs.{elf,bin,uf2,map}         two cores (the board)
#   build/firmware/pico/cgfs-1core.{elf,bin,uf2,map}   RP2040_SINGLE_CORE=1 (rp2040js)
#   build/firmware/pico/cgfs-{book,cube}{,-1core}.*    scenes compiled by tools/scenec
#   build/firmware/pico/cgfs-cube-{ili9341,st7735,ssd1351,gc9a01,ili9488}{,-1core}.*
#                                                      the cube scenes on the other modules
#                                                      (320x240, 128x160, 128x128, 240x240
#                                                      round, 320x480)
#   build/firmware/pico/cgfs-check{,-ili9341,-st7735,-ssd1351,-gc9a01,-ili9488}.*
#                                                      the bring-up pattern on each module
#   build/firmware/stm32f411/cgfs{,-fixed}.{elf,bin,map}  Cortex-M4F, see below
#
# Build options (make VAR=value): FW_PINS (extra -D pin options, e.g.
# "-DRP2040_PIN_DC=8"), FW_CLK_MHZ (clk_sys in MHz, 125..300, default 133;
# above 133 the core voltage is raised and the flash divider kept within the
# flash's rating: firmware/board/rp2040/board.h; RP2040_SYS_MHZ is its older
# name), FW_SPI_HZ (a ceiling for the SPI clock in place of the panel's rated
# clock: a clock the module was tested at, e.g. 62500000; default none),
# RP2040_RAM_TEXT (1, the
# default: the renderer core's hot functions and tables, the ones the
# images' profiles on the emulator show a frame reading once a pixel, span,
# triangle or vertex (firmware/board/rp2040/ram_text/on/ram_text_hot.ld,
# `make ram-text-profile`, mk/rp2040sim.mk), are copied to SRAM and run from
# there instead of through the 16 KB XIP cache, the rest of the core from
# flash (an image of a scene set carries only what its scenes need, below);
# raster: only the
# rasterizer's default path and the numeric layer, about 64 KB, which leaves
# a mesh room for its work memory; 0: everything from flash), FW_SCENE_SRCS
# (the scene table; default the built-in placeholder), FW_EXTRA (more -D flags).

ARM_CC      ?= arm-none-eabi-gcc
ARM_OBJCOPY ?= arm-none-eabi-objcopy
ARM_SIZE    ?= arm-none-eabi-size
FW_OUT      := $(BUILD)/firmware
RP2040_SYS_MHZ ?= 133
FW_CLK_MHZ ?= $(RP2040_SYS_MHZ)
FW_SPI_HZ ?=
ifneq ($(shell [ '$(FW_CLK_MHZ)' -ge 125 ] 2>/dev/null && [ '$(FW_CLK_MHZ)' -le 300 ] && echo ok),ok)
$(error FW_CLK_MHZ=$(FW_CLK_MHZ): a whole number of MHz, 125..300)
endif
ifneq ($(FW_SPI_HZ),)
ifneq ($(shell echo '$(FW_SPI_HZ)' | grep -Ex '[1-9][0-9]*'),$(FW_SPI_HZ))
$(error FW_SPI_HZ=$(FW_SPI_HZ): a clock in Hz, e.g. 62500000)
endif
endif
RP2040_RAM_TEXT ?= 1
RP2040_BOOT2 ?= w25q16jv
ifeq ($(wildcard firmware/board/rp2040/boot2_$(RP2040_BOOT2).S),)
$(error RP2040_BOOT2=$(RP2040_BOOT2): no firmware/board/rp2040/boot2_$(RP2040_BOOT2).S (w25q16jv or generic_03h))
endif
# boot2's flash divider (its FLASH_DIV) and the flash's rated clock in its
# read mode (W25Q16JV: 133 MHz for EBh, 50 MHz for 03h), for the board's
# divider at FW_CLK_MHZ (firmware/board/rp2040/board.h)
RP2040_BOOT2_FLASH := $(if $(filter generic_03h,$(RP2040_BOOT2)),-DRP2040_BOOT2_DIV=4 -DRP2040_FLASH_MAX_MHZ=50,\
                      -DRP2040_BOOT2_DIV=2 -DRP2040_FLASH_MAX_MHZ=133)
FW_PINS     ?=
FW_EXTRA    ?=
FW_SCENE_SRCS ?= firmware/app/scenes_builtin.c

FW_APP_SRCS  := firmware/app/main.c firmware/app/font5x7.c
FW_HAL_SRCS  := $(HAL_SRCS)
FW_CORE_SRCS := $(CORE_SRCS)
FW_COMMON    := $(FW_APP_SRCS) $(FW_HAL_SRCS) $(FW_CORE_SRCS)
FW_INC       := -I. -Ifirmware/core -Ifirmware/app -Ihal -I$(FW_OUT)/scenes

# ---- scenes compiled by tools/scenec -------------------------------------------
# Scene sets: a list of scenes linked into an image. Each scene is compiled
# for the firmware's render size and strip height with the work size measured
# on the target (the emulated Cortex-M0+ work probe of mk/scene.mk,
# tools/scenec/target_work.sh) and checked against the RP2040's budget
# (scenec --target rp2040); each set has its table and its format. Every
# image that links a set builds its core at the coarsest format among its
# scenes: fw_<set>_num_frac.h (-include'd; the Makefile's scene_frac_rule).
#   book  FW_BOOK_SCENES: the "book" images (raytracer-02 and raster-11)
#   cube  FW_CUBE_SCENES: small3dlib's cube workload (firmware/scenes/bench)
#   rt    FW_RT_SCENES: the ray tracer's benchmark (raytracer-05, exact and with
#         its real-time option)
# Each image of a set is compiled with the renderer features its scenes
# need and no others (fw_<set>_features.h, tools/scenec/features.sh, from
# the scenes' headers: firmware/core/scene_features.def), so that the code no
# scene of the set reaches is left out of flash and SRAM.
# $(call fw_scene_set,SET,set) with FW_<SET>_SCENES set defines FW_<SET>_SRCS
# (the scenes' sources and their table fw_scenes_<set>.c), FW_<SET>_FRAC_H
# and FW_<SET>_FRAC_FLAGS (the -include of it and of FW_<SET>_FEAT_H, the
# features).
FW_BOOK_SCENES ?= book/raytracer-02 book/raster-11
FW_CUBE_SCENES ?= bench/cube-textured bench/cube-gouraud bench/cube-flat
FW_RT_SCENES   ?= book/raytracer-05 bench/raytracer-05-adaptive
FW_MESH_SCENES ?= bench/knot-4k-gouraud bench/knot-4k-flat bench/knot-4k-textured
FW_STRIP_ROWS  ?= 8
# Where the rasterizer's fast path finds its texels (scenec --fast-textures):
# ram (render_init makes them in work memory) or flash (scenec writes them
# as const data). A change takes effect on scenes compiled after it (remove
# $(FW_OUT)/scenes/ to compile them again).
FW_FAST_TEXTURES ?= ram
# Where fast Phong's specular tables are (scenec --spec-tables): flash
# (scenec writes them as const data, the default) or ram (render_init makes
# them in work memory); the same rule for a change.
FW_SPEC_TABLES ?= flash
$(FW_OUT)/scenes/%.c $(FW_OUT)/scenes/%.h: SCENEC_FLAGS = --fast-textures $(FW_FAST_TEXTURES) --spec-tables $(FW_SPEC_TABLES)
fw_scene_id     = $(subst -,_,$(subst /,_,$(1)))
fw_scene_h      = $(foreach n,$(1),$(FW_OUT)/scenes/$(call fw_scene_id,$(n))$(2).h)
# once per scene of all the sets (book/raytracer-02 -> book_raytracer_02.c)
$(foreach n,$(sort $(FW_BOOK_SCENES) $(FW_CUBE_SCENES) $(FW_RT_SCENES) $(FW_MESH_SCENES)),\
    $(call scenec_rule,$(FW_OUT)/scenes/$(call fw_scene_id,$(n)).c,$(n),240x240,$(FW_STRIP_ROWS),$(call fw_scene_id,$(n)),1,rp2040))
# The cube scenes again at 320x240, for the ILI9341 module in landscape
# (files and identifiers <id>_320).
$(foreach n,$(FW_CUBE_SCENES),\
    $(call scenec_rule,$(FW_OUT)/scenes/$(call fw_scene_id,$(n))_320.c,$(n),320x240,$(FW_STRIP_ROWS),$(call fw_scene_id,$(n))_320,1,rp2040))
FW_CUBE320_SCENES := $(FW_CUBE_SCENES)
# And at 128x160, for the ST7735S 1.8" module (files and identifiers <id>_128).
$(foreach n,$(FW_CUBE_SCENES),\
    $(call scenec_rule,$(FW_OUT)/scenes/$(call fw_scene_id,$(n))_128.c,$(n),128x160,$(FW_STRIP_ROWS),$(call fw_scene_id,$(n))_128,1,rp2040))
FW_CUBE128_SCENES := $(FW_CUBE_SCENES)
# And at 128x128, for the SSD1351 OLED module (files and identifiers <id>_128sq).
$(foreach n,$(FW_CUBE_SCENES),\
    $(call scenec_rule,$(FW_OUT)/scenes/$(call fw_scene_id,$(n))_128sq.c,$(n),128x128,$(FW_STRIP_ROWS),$(call fw_scene_id,$(n))_128sq,1))
FW_CUBE128SQ_SCENES := $(FW_CUBE_SCENES)
# And at 320x480, for the ILI9488 module (files and identifiers <id>_480).
$(foreach n,$(FW_CUBE_SCENES),\
    $(call scenec_rule,$(FW_OUT)/scenes/$(call fw_scene_id,$(n))_480.c,$(n),320x480,$(FW_STRIP_ROWS),$(call fw_scene_id,$(n))_480,1))
FW_CUBE480_SCENES := $(FW_CUBE_SCENES)
# The book scenes at 128x128 (the SSD1351) and 320x480 (the ILI9488), likewise.
$(foreach n,$(FW_BOOK_SCENES),\
    $(call scenec_rule,$(FW_OUT)/scenes/$(call fw_scene_id,$(n))_128sq.c,$(n),128x128,$(FW_STRIP_ROWS),$(call fw_scene_id,$(n))_128sq,1))
$(foreach n,$(FW_BOOK_SCENES),\
    $(call scenec_rule,$(FW_OUT)/scenes/$(call fw_scene_id,$(n))_480.c,$(n),320x480,$(FW_STRIP_ROWS),$(call fw_scene_id,$(n))_480,1))
FW_BOOK128SQ_SCENES := $(FW_BOOK_SCENES)
FW_BOOK480_SCENES := $(FW_BOOK_SCENES)
# $(1) = SET (variable names), $(2) = set (file names), $(3) = the suffix of
# the scenes' files (none: compiled at 240x240). The list of scenes,
# fw_<set>_scenes.list, is rewritten only when FW_<SET>_SCENES changes, so
# that the table and the format follow the list.
define FW_SCENE_SET
FW_$(1)_LIST   := $(FW_OUT)/scenes/fw_$(2)_scenes.list
FW_$(1)_FRAC_H := $(FW_OUT)/scenes/fw_$(2)_num_frac.h
FW_$(1)_SRCS   := $(foreach n,$(FW_$(1)_SCENES),$(FW_OUT)/scenes/$(call fw_scene_id,$(n))$(3).c) \
                  $(FW_OUT)/scenes/fw_scenes_$(2).c
FW_$(1)_FEAT_H := $(FW_OUT)/scenes/fw_$(2)_features.h
FW_$(1)_FRAC_FLAGS := -include $(FW_OUT)/scenes/fw_$(2)_num_frac.h
FW_$(1)_FEAT_FLAGS := -include $(FW_OUT)/scenes/fw_$(2)_features.h
$(FW_OUT)/scenes/fw_$(2)_features.h: $(call fw_scene_h,$(FW_$(1)_SCENES),$(3)) tools/scenec/features.sh \
                                     $(FW_OUT)/scenes/fw_$(2)_scenes.list
	$(Q)tools/scenec/features.sh $$@ $(call fw_scene_h,$(FW_$(1)_SCENES),$(3))
$$(shell mkdir -p $(FW_OUT)/scenes && { echo '$(FW_$(1)_SCENES)' | cmp -s - $(FW_OUT)/scenes/fw_$(2)_scenes.list || \
          echo '$(FW_$(1)_SCENES)' >$(FW_OUT)/scenes/fw_$(2)_scenes.list; })
$(FW_OUT)/scenes/fw_scenes_$(2).c: $(call fw_scene_h,$(FW_$(1)_SCENES),$(3)) firmware/app/scene_table.sh \
                                   $(FW_OUT)/scenes/fw_$(2)_scenes.list
	$(Q)firmware/app/scene_table.sh $$@ $(foreach n,$(FW_$(1)_SCENES),$(n)=$(call fw_scene_h,$(n),$(3)))
endef
fw_scene_set = $(eval $(call FW_SCENE_SET,$(1),$(2),$(3)))$(call scene_frac_rule,$(FW_$(1)_FRAC_H),$(call \
    fw_scene_h,$(FW_$(1)_SCENES),$(3)),$(FW_$(1)_LIST))
$(call fw_scene_set,BOOK,book)
$(call fw_scene_set,CUBE,cube)
$(call fw_scene_set,RT,rt)
$(call fw_scene_set,MESH,mesh)
$(call fw_scene_set,CUBE320,cube320,_320)
$(call fw_scene_set,CUBE128,cube128,_128)
$(call fw_scene_set,CUBE128SQ,cube128sq,_128sq)
$(call fw_scene_set,CUBE480,cube480,_480)
$(call fw_scene_set,BOOK128SQ,book128sq,_128sq)
$(call fw_scene_set,BOOK480,book480,_480)
# fw_frac_objs(OBJ_DIR,SOURCES): the objects of an image that links a scene
# set; they are compiled after, and again when, the format changes.
fw_frac_objs = $(patsubst %.c,$(1)/%.o,$(2))

# ---- RP2040 ------------------------------------------------------------------
RP_DIR   := firmware/board/rp2040
# RP2040_RAM_TEXT: 1 the whole core in SRAM, raster the rasterizer's default
# path only (firmware/board/rp2040/ram_text/raster: room for a mesh's work
# memory), 0 nothing (code from flash through the XIP cache)
ifeq ($(filter 0 1 raster,$(RP2040_RAM_TEXT)),)
$(error RP2040_RAM_TEXT=$(RP2040_RAM_TEXT): 1, raster or 0)
endif
RP_RAM_TEXT_DIR := $(if $(filter 1,$(RP2040_RAM_TEXT)),on,$(if $(filter raster,$(RP2040_RAM_TEXT)),raster,off))
RP_SRCS  := $(RP_DIR)/crt0.c $(RP_DIR)/board.c $(RP_DIR)/fw_board_rp2040.c hal/rp2040/hal_rp2040.c \
            $(FW_COMMON)
RP_ASM   := $(RP_DIR)/hwdiv.S
RP_CFLAGS := -mcpu=cortex-m0plus -mthumb -O2 -g -std=c11 $(WARN) -ffunction-sections -fdata-sections \
             -ffreestanding -fno-common -DRENDER_HOST_OUTPUTS=0 -DNUM_MODE=1 -DRP2040_SYS_MHZ=$(FW_CLK_MHZ) -DFW_STRIP_ROWS=$(FW_STRIP_ROWS) \
             $(RP2040_BOOT2_FLASH) $(if $(FW_SPI_HZ),-DRP2040_SPI_HZ=$(FW_SPI_HZ)) \
             $(if $(filter 1 raster,$(RP2040_RAM_TEXT)),-DRAS_RAM_TEXT) \
             $(if $(filter raster,$(RP2040_RAM_TEXT)),-DRP2040_RAM_TEXT_RASTER) \
             $(FW_INC) -I$(RP_DIR) -Ihal/rp2040 $(FW_PINS) $(FW_EXTRA)
RP_LDFLAGS_BASE := -mcpu=cortex-m0plus -mthumb --specs=nano.specs -nostartfiles -T $(RP_DIR)/rp2040.ld \
                   -Wl,--gc-sections -Wl,--no-warn-rwx-segments
RP_LDFLAGS := $(RP_LDFLAGS_BASE) -L$(RP_DIR)/ram_text/$(RP_RAM_TEXT_DIR)

# boot2: assembled, linked at its SRAM address, CRC appended, re-emitted as .S.
# RP2040_BOOT2: w25q16jv (the Pico's flash, quad EBh continuous read at
# clk_sys/2) or generic_03h (any flash, serial 03h at clk_sys/4); the choice
# is recorded so that changing it rebuilds boot2.
$(shell mkdir -p $(FW_OUT)/pico && { echo '$(RP2040_BOOT2)' | cmp -s - $(FW_OUT)/pico/boot2.choice || \
          echo '$(RP2040_BOOT2)' >$(FW_OUT)/pico/boot2.choice; })
$(FW_OUT)/pico/boot2.elf: $(RP_DIR)/boot2_$(RP2040_BOOT2).S $(RP_DIR)/boot2_common.inc $(RP_DIR)/boot2.ld \
                         $(FW_OUT)/pico/boot2.choice
	@mkdir -p $(@D)
	$(Q)$(ARM_CC) -mcpu=cortex-m0plus -mthumb -nostdlib -Wa,-I$(RP_DIR) -T $(RP_DIR)/boot2.ld $< -o $@
$(FW_OUT)/pico/boot2.bin: $(FW_OUT)/pico/boot2.elf
	$(Q)$(ARM_OBJCOPY) -O binary $< $@
$(FW_OUT)/pico/boot2_crc.S: $(FW_OUT)/pico/boot2.bin tools/uf2/boot2crc.py
	$(Q)$(PYTHON) tools/uf2/boot2crc.py $< $@

# $(1) = image name, $(2) = extra flags, $(3) = scene table sources, $(4) =
# the image's ram_text directory (on, raster, off; default RP2040_RAM_TEXT's),
# $(5) = the image's other sources (default RP_SRCS: the scene application).
# obj-<image>/cflags holds the image's compile flags, rewritten only when they
# change (RP2040_RAM_TEXT=0, FW_CLK_MHZ=200, ...), so that its objects follow.
define RP_IMAGE
$$(shell mkdir -p $(FW_OUT)/pico/obj-$(1) && { printf '%s\n' '$(strip $(RP_CFLAGS) $(2))' | \
          cmp -s - $(FW_OUT)/pico/obj-$(1)/cflags || printf '%s\n' '$(strip $(RP_CFLAGS) $(2))' >$(FW_OUT)/pico/obj-$(1)/cflags; })
$(FW_OUT)/pico/obj-$(1)/%.o: %.c $(FW_OUT)/pico/obj-$(1)/cflags
	@mkdir -p $$(@D)
	$$(Q)$$(ARM_CC) $$(RP_CFLAGS) $(2) -MMD -MP -c $$< -o $$@
$(FW_OUT)/pico/obj-$(1)/%.o: %.S
	@mkdir -p $$(@D)
	$$(Q)$$(ARM_CC) -mcpu=cortex-m0plus -mthumb -c $$< -o $$@
$(FW_OUT)/pico/obj-$(1)/boot2_crc.o: $(FW_OUT)/pico/boot2_crc.S
	@mkdir -p $$(@D)
	$$(Q)$$(ARM_CC) -mcpu=cortex-m0plus -mthumb -c $$< -o $$@
$(FW_OUT)/pico/$(1).elf: $(patsubst %.c,$(FW_OUT)/pico/obj-$(1)/%.o,$(or $(5),$(RP_SRCS)) $(3)) \
                         $(patsubst %.S,$(FW_OUT)/pico/obj-$(1)/%.o,$(RP_ASM)) \
                         $(FW_OUT)/pico/obj-$(1)/boot2_crc.o $(RP_DIR)/rp2040.ld \
                         $(wildcard $(RP_DIR)/ram_text/$(or $(4),$(RP_RAM_TEXT_DIR))/*.ld)
	$$(Q)$$(ARM_CC) $$(RP_LDFLAGS_BASE) -L$(RP_DIR)/ram_text/$(or $(4),$(RP_RAM_TEXT_DIR)) -Wl,-Map=$(FW_OUT)/pico/$(1).map \
		$$(filter %.o,$$^) -lc -lgcc -o $$@
$(FW_OUT)/pico/$(1).bin: $(FW_OUT)/pico/$(1).elf
	$$(Q)$$(ARM_OBJCOPY) -O binary $$< $$@
$(FW_OUT)/pico/$(1).uf2: $(FW_OUT)/pico/$(1).bin tools/uf2/uf2conv.py
	$$(Q)$$(PYTHON) tools/uf2/uf2conv.py $$< $$@ --base 0x10000000 --family 0xE48BFF56
endef
$(eval $(call RP_IMAGE,cgfs,,$(FW_SCENE_SRCS)))
$(eval $(call RP_IMAGE,cgfs-1core,-DRP2040_SINGLE_CORE=1,$(FW_SCENE_SRCS)))
# The other panel: an ILI9341 module in landscape, 320x240 (two cores).
$(eval $(call RP_IMAGE,cgfs-ili9341,-DFW_PANEL=panel_ili9341_320x240 -DFW_WIDTH=320 -DFW_HEIGHT=240 -DFW_SCAN_HZ=70,$(FW_SCENE_SRCS)))
# The ST7789 upside down (FW_ROTATION=2: the module mounted the other way).
$(eval $(call RP_IMAGE,cgfs-rot2,-DFW_ROTATION=2,$(FW_SCENE_SRCS)))
# fw_scene_image(IMAGE,SET,FLAGS[,RAM_TEXT_DIR]): an image of the scene set
# SET (its table, its format, its features), built with FLAGS.
fw_scene_image = $(eval $(call RP_IMAGE,$(1),$(3) $(FW_$(2)_FRAC_FLAGS) $(FW_$(2)_FEAT_FLAGS),$(FW_$(2)_SRCS),$(4)))\
    $(eval $(call fw_frac_objs,$(FW_OUT)/pico/obj-$(1),$(RP_SRCS) $(FW_$(2)_SRCS)): $(FW_$(2)_FRAC_H) $(FW_$(2)_FEAT_H))
FW_1CORE_FLAGS := -DRP2040_SINGLE_CORE=1 -DFW_WORK_CORES=1
# The book scenes: for the board, and for the emulator (one core, one frame
# per scene so that a run reaches every scene quickly).
$(call fw_scene_image,cgfs-book,BOOK,)
$(call fw_scene_image,cgfs-book-1core,BOOK,$(FW_1CORE_FLAGS) -DFW_FRAMES_PER_SCENE=1)
$(call fw_scene_image,cgfs-book-bench,BOOK,-DFW_FRAMES_PER_SCENE=1)
# The cube scenes: FW_CUBE_FRAMES frames of each (default 10, all of their
# frames: a 90-degree turn, so the board's loop is seamless), for the board
# and for the emulator (`make bench-rp2040` averages them).
FW_CUBE_FRAMES ?= 10
$(call fw_scene_image,cgfs-cube,CUBE,-DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
$(call fw_scene_image,cgfs-cube-1core,CUBE,$(FW_1CORE_FLAGS) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
# The same with the panel's TE output wired to GP22: frames start in the
# panel's vertical blank (no tearing; at most its scan rate).
$(call fw_scene_image,cgfs-cube-te,CUBE,-DRP2040_PIN_TE=22 -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
# The same on the ILI9341 module in landscape, 320x240.
FW_ILI320 := -DFW_PANEL=panel_ili9341_320x240 -DFW_WIDTH=320 -DFW_HEIGHT=240 -DFW_SCAN_HZ=70
$(call fw_scene_image,cgfs-cube-ili9341,CUBE320,$(FW_ILI320) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
$(call fw_scene_image,cgfs-cube-ili9341-1core,CUBE320,$(FW_ILI320) $(FW_1CORE_FLAGS) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
# And with SPI0 at 62.5 MHz, beyond the ILI9341's rated 10 MHz (8.93 MHz on
# the RP2040): the clock the common modules are tested at (FW_SPI_HZ).
$(call fw_scene_image,cgfs-cube-ili9341-fastspi,CUBE320,$(FW_ILI320) $(if $(FW_SPI_HZ),,-DRP2040_SPI_HZ=62500000) \
    -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
# And on the ST7735S 1.8" module, 128x160.
FW_ST7735 := -DFW_PANEL=panel_st7735_128x160 -DFW_WIDTH=128 -DFW_HEIGHT=160
$(call fw_scene_image,cgfs-cube-st7735,CUBE128,$(FW_ST7735) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
$(call fw_scene_image,cgfs-cube-st7735-1core,CUBE128,$(FW_ST7735) $(FW_1CORE_FLAGS) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
# And on the SSD1351 OLED module, 128x128 (the first controller that is not DCS).
FW_SSD1351 := -DFW_PANEL=panel_ssd1351_128x128 -DFW_WIDTH=128 -DFW_HEIGHT=128
$(call fw_scene_image,cgfs-cube-ssd1351,CUBE128SQ,$(FW_SSD1351) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
$(call fw_scene_image,cgfs-cube-ssd1351-1core,CUBE128SQ,$(FW_SSD1351) $(FW_1CORE_FLAGS) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
$(call fw_scene_image,cgfs-book-ssd1351,BOOK128SQ,$(FW_SSD1351) -DFW_FRAMES_PER_SCENE=1)
# And on the GC9A01 round module, 240x240 (the cube scenes as compiled for the ST7789),
# the ray tracer skipping the pixels outside the glass's circle (FW_GC9A01_ROUND=0: not).
FW_GC9A01_ROUND ?= 1
FW_GC9A01 := -DFW_PANEL=panel_gc9a01_240x240 -DFW_WIDTH=240 -DFW_HEIGHT=240 -DFW_ROUND_GLASS=$(FW_GC9A01_ROUND)
$(call fw_scene_image,cgfs-cube-gc9a01,CUBE,$(FW_GC9A01) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
$(call fw_scene_image,cgfs-cube-gc9a01-1core,CUBE,$(FW_GC9A01) $(FW_1CORE_FLAGS) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
# The book scenes on it, one frame each (the ray-traced one is where the circle saves).
$(call fw_scene_image,cgfs-book-gc9a01,BOOK,$(FW_GC9A01) -DFW_FRAMES_PER_SCENE=1)
# And on the ILI9488 module, 320x480, 18-bit pixels (three bytes each on the bus).
FW_ILI9488 := -DFW_PANEL=panel_ili9488_320x480 -DFW_WIDTH=320 -DFW_HEIGHT=480
$(call fw_scene_image,cgfs-cube-ili9488,CUBE480,$(FW_ILI9488) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
$(call fw_scene_image,cgfs-cube-ili9488-1core,CUBE480,$(FW_ILI9488) $(FW_1CORE_FLAGS) -DFW_FRAMES_PER_SCENE=$(FW_CUBE_FRAMES))
$(call fw_scene_image,cgfs-book-ili9488,BOOK480,$(FW_ILI9488) -DFW_FRAMES_PER_SCENE=1)
# The ray tracer's benchmark: one frame of each, progressive (the preview's
# time is rp2040sim's first_image_us).
$(call fw_scene_image,cgfs-rt,RT,-DFW_FRAMES_PER_SCENE=1)
$(call fw_scene_image,cgfs-rt-1core,RT,$(FW_1CORE_FLAGS) -DFW_FRAMES_PER_SCENE=1)
# The 4,096-triangle meshes (Gouraud, flat), FW_MESH_FRAMES frames of each,
# two cores, with only the rasterizer's default path in SRAM (the whole core
# there leaves too little work memory for a mesh: RP2040_RAM_TEXT=raster).
# Its strips go through a ring of 8 buffers (FW_RING, firmware/app/main.c;
# 4 elsewhere): with 4, core 1 often waited for a buffer while core 0, which
# sends the strips, rendered one of the knot's long strips.
# Its UART log ring is the default 512 characters (RP2040_LOG_RING,
# firmware/board/rp2040/board.c): with 64, a frame's two lines (about 113
# characters) waited for the last ~17 to enter the FIFO (uart_stall_cycles).
FW_MESH_FRAMES ?= 10
$(call fw_scene_image,cgfs-mesh,MESH,-DFW_FRAMES_PER_SCENE=$(FW_MESH_FRAMES) -DFW_RING=8 -DRAS_RAM_TEXT -DRP2040_RAM_TEXT_RASTER,raster)

# The bring-up pattern (firmware/app/check_main.c, check_pattern.h): no
# scenes, no renderer core, one core; the pattern sent again every
# FW_CHECK_PERIOD_MS with the settings on the UART. cgfs-check on the ST7789
# 240x240, and one image per other module the cube images are built for.
FW_CHECK_PERIOD_MS ?= 2000
RP_CHECK_SRCS := $(RP_DIR)/crt0.c $(RP_DIR)/board.c $(RP_DIR)/fw_board_rp2040.c hal/rp2040/hal_rp2040.c \
                 firmware/app/check_main.c firmware/app/check_pattern.c firmware/app/font5x7.c $(FW_HAL_SRCS)
FW_CHECK := -DRP2040_SINGLE_CORE=1 -DFW_CHECK_PERIOD_MS=$(FW_CHECK_PERIOD_MS)u
FW_CHECK_IMAGES := cgfs-check cgfs-check-ili9341 cgfs-check-st7735 cgfs-check-ssd1351 cgfs-check-gc9a01 \
                   cgfs-check-ili9488
$(eval $(call RP_IMAGE,cgfs-check,$(FW_CHECK),,,$(RP_CHECK_SRCS)))
$(eval $(call RP_IMAGE,cgfs-check-ili9341,$(FW_CHECK) $(FW_ILI320),,,$(RP_CHECK_SRCS)))
$(eval $(call RP_IMAGE,cgfs-check-st7735,$(FW_CHECK) $(FW_ST7735),,,$(RP_CHECK_SRCS)))
$(eval $(call RP_IMAGE,cgfs-check-ssd1351,$(FW_CHECK) $(FW_SSD1351),,,$(RP_CHECK_SRCS)))
$(eval $(call RP_IMAGE,cgfs-check-gc9a01,$(FW_CHECK) $(FW_GC9A01),,,$(RP_CHECK_SRCS)))
$(eval $(call RP_IMAGE,cgfs-check-ili9488,$(FW_CHECK) $(FW_ILI9488),,,$(RP_CHECK_SRCS)))

FW_RP_IMAGES := $(FW_OUT)/pico/cgfs.uf2 $(FW_OUT)/pico/cgfs-1core.uf2 $(FW_OUT)/pico/cgfs-ili9341.uf2 \
                $(FW_OUT)/pico/cgfs-rot2.uf2 \
                $(foreach i,cgfs-book cgfs-book-1core cgfs-book-bench cgfs-cube cgfs-cube-1core cgfs-cube-te cgfs-cube-ili9341 \
                  cgfs-cube-ili9341-1core cgfs-cube-ili9341-fastspi cgfs-cube-st7735 \
                  cgfs-cube-st7735-1core cgfs-cube-ssd1351 cgfs-cube-ssd1351-1core \
                  cgfs-cube-gc9a01 cgfs-cube-gc9a01-1core cgfs-book-gc9a01 cgfs-cube-ili9488 \
                  cgfs-cube-ili9488-1core cgfs-book-ssd1351 cgfs-book-ili9488 cgfs-rt cgfs-rt-1core cgfs-mesh \
                  $(FW_CHECK_IMAGES),$(FW_OUT)/pico/$(i).uf2)

.PHONY: firmware-pico
firmware-pico: deps-firmware
	$(Q)$(MAKE) --no-print-directory $(FW_RP_IMAGES)

# ---- STM32F411 (Cortex-M4F, one core) -------------------------------------------
#   build/firmware/stm32f411/cgfs.{elf,bin,map}        float numbers (FPU), default
#   build/firmware/stm32f411/cgfs-fixed.{elf,bin,map}  fixed point, for comparison
# Options: STM32_NUM_MODE (float|fixed|double: the mode of cgfs.elf),
# STM32_PINS (e.g. "-DSTM32_PIN_DC=16"), STM32_HSE_MHZ (crystal, default 25).
ST_DIR   := firmware/board/stm32f411
STM32_NUM_MODE ?= float
STM32_PINS ?=
STM32_HSE_MHZ ?= 25
ST_SRCS  := $(ST_DIR)/crt0.c $(ST_DIR)/board.c $(ST_DIR)/fw_board_stm32f411.c hal/stm32f4/hal_stm32f4.c \
            $(FW_COMMON) $(FW_BOOK_SRCS)
ST_CPU   := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
ST_CFLAGS := $(ST_CPU) -O2 -g -std=c11 $(WARN) -ffunction-sections -fdata-sections -ffreestanding \
             -fno-common -DRENDER_HOST_OUTPUTS=0 -fno-math-errno -ffp-contract=off -DSTM32_HSE_MHZ=$(STM32_HSE_MHZ) \
             -DFW_STRIP_ROWS=$(FW_STRIP_ROWS) -DFW_WORK_CORES=1 \
             $(FW_INC) -I$(ST_DIR) -Ihal/stm32f4 $(STM32_PINS) $(FW_EXTRA)
ST_LDFLAGS := $(ST_CPU) --specs=nano.specs -nostartfiles -T $(ST_DIR)/stm32f411.ld \
              -Wl,--gc-sections -Wl,--no-warn-rwx-segments

# $(1) = image name, $(2) = numeric mode (fixed point at the book scenes' format),
# $(3) = extra flags
define ST_IMAGE
$(FW_OUT)/stm32f411/obj-$(1)/%.o: %.c
	@mkdir -p $$(@D)
	$$(Q)$$(ARM_CC) $$(ST_CFLAGS) -DNUM_MODE=$$(NUM_MODE_$(2)) $(if $(filter fixed,$(2)),$(FW_BOOK_FRAC_FLAGS)) \
		$(FW_BOOK_FEAT_FLAGS) $(3) -MMD -MP -c $$< -o $$@
$(FW_OUT)/stm32f411/$(1).elf: $(patsubst %.c,$(FW_OUT)/stm32f411/obj-$(1)/%.o,$(ST_SRCS)) $(ST_DIR)/stm32f411.ld
	$$(Q)$$(ARM_CC) $$(ST_LDFLAGS) -Wl,-Map=$(FW_OUT)/stm32f411/$(1).map \
		$$(filter %.o,$$^) -lm -lc -lgcc -o $$@
$(FW_OUT)/stm32f411/$(1).bin: $(FW_OUT)/stm32f411/$(1).elf
	$$(Q)$$(ARM_OBJCOPY) -O binary $$< $$@
endef
$(eval $(call ST_IMAGE,cgfs,$(STM32_NUM_MODE)))
$(eval $(call ST_IMAGE,cgfs-fixed,fixed))
# tests only (tests/system/test_stm32_qemu.sh): faults right after board_init
$(eval $(call ST_IMAGE,cgfs-fault-test,$(STM32_NUM_MODE),-DSTM32_TEST_FAULT=1))
$(call fw_frac_objs,$(FW_OUT)/stm32f411/obj-cgfs-fixed,$(ST_SRCS)): $(FW_BOOK_FRAC_H) $(FW_BOOK_FEAT_H)
$(foreach i,cgfs cgfs-fault-test,$(call fw_frac_objs,$(FW_OUT)/stm32f411/obj-$(i),$(ST_SRCS))): $(FW_BOOK_FEAT_H)
ifeq ($(STM32_NUM_MODE),fixed)
$(call fw_frac_objs,$(FW_OUT)/stm32f411/obj-cgfs,$(ST_SRCS)): $(FW_BOOK_FRAC_H)
endif

FW_ST_IMAGES := $(FW_OUT)/stm32f411/cgfs.bin $(FW_OUT)/stm32f411/cgfs-fixed.bin

.PHONY: firmware-stm32f411
firmware-stm32f411: deps-firmware
	$(Q)$(MAKE) --no-print-directory $(FW_ST_IMAGES)

# One make builds both boards' images: two recursive makes side by side would
# each build the host tools the images need (scenec, the core bundles) and
# race on the same files.
firmware: deps-firmware
	$(Q)$(MAKE) --no-print-directory $(FW_RP_IMAGES) $(FW_ST_IMAGES)
	$(Q)$(ARM_SIZE) $(FW_RP_IMAGES:.uf2=.elf) $(FW_ST_IMAGES:.bin=.elf) $(FW_EXTRA_ELFS)
	@echo "RAM, flash and renderer code each compiled scene needs (240x240, 16-row strips; tools/scenec):"
	$(Q)$(MAKE) --no-print-directory scenes-report

# ---- the renderer core alone on the qemu benchmark boards (mk/bench.mk) ----------
# Instructions per frame of the book scenes: Cortex-M4F (mps2-an386) fixed vs
# float, and Cortex-M0+ code (mps2-an385) in fixed point.
FW_BENCH_SRCS := tools/bench/bench_frame.c $(FW_CORE_SRCS) $(FW_BOOK_SRCS)
FW_BENCH_FLAGS := -Ifirmware/app -I$(FW_OUT)/scenes -DFW_STRIP_ROWS=$(FW_STRIP_ROWS) -DFW_WORK_CORES=1
$(call bench_image,frame,m4f-qemu,fixed,$(FW_BENCH_SRCS),$(FW_BENCH_FLAGS) $(FW_BOOK_FRAC_FLAGS))
$(call bench_image,frame,m4f-qemu,float,$(FW_BENCH_SRCS),$(FW_BENCH_FLAGS))
$(call bench_image,frame,m0plus-qemu,fixed,$(FW_BENCH_SRCS),$(FW_BENCH_FLAGS) $(FW_BOOK_FRAC_FLAGS))
$(foreach t,m4f-qemu m0plus-qemu,$(call fw_frac_objs,$(BUILD)/bench/$(t)/fixed/frame.objs,$(FW_BENCH_SRCS) $(BENCH_RUNTIME))): \
    $(FW_BOOK_FRAC_H)
BENCH_IMAGES += $(BUILD)/bench/m4f-qemu/fixed/frame.elf $(BUILD)/bench/m4f-qemu/float/frame.elf \
                $(BUILD)/bench/m0plus-qemu/fixed/frame.elf

# The STM32F411 image on qemu (netduinoplus2): the clock waits' timeouts, the
# fault line and the reset (tests/system/test_stm32_qemu.sh).
TESTS += tests/system/test_stm32_qemu.sh:$(BUILD)
TEST_NEEDS_test_stm32_qemu := $(FW_OUT)/stm32f411/cgfs.elf $(FW_OUT)/stm32f411/cgfs-fault-test.elf
TEST_DEPS += $(TEST_NEEDS_test_stm32_qemu)

# docs/firmware.md against the build: its memory figures (tools/fw_sizes.py),
# the image `make flash` writes.
TEST_NEEDS_test_fw_docs := $(foreach i,cgfs-book cgfs-book-1core cgfs-cube cgfs-cube-1core cgfs-cube-ili9341 cgfs-rt \
                              cgfs-mesh cgfs cgfs-check,$(FW_OUT)/pico/$(i).elf) $(FW_OUT)/stm32f411/cgfs.elf $(FW_OUT)/stm32f411/cgfs-fixed.elf
TEST_DEPS += $(TEST_NEEDS_test_fw_docs)
TESTS     += tests/system/test_fw_docs.sh:$(BUILD)
