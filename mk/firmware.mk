# Board images: `make firmware` cross-builds the RP2040 (Pico + ST7789) and
# STM32F411 images; `make flash` writes the Pico image over USB.
#
#   build/firmware/pico/cgfs.{elf,bin,uf2,map}         two cores (the board)
#   build/firmware/pico/cgfs-1core.{elf,bin,uf2,map}   RP2040_SINGLE_CORE=1 (rp2040js)
#
# Build options (make VAR=value): FW_PINS (extra -D pin options, e.g.
# "-DRP2040_PIN_DC=8"), RP2040_SYS_MHZ (125 or 133), FW_SCENE_SRCS (the
# scene table; default the built-in placeholder), FW_EXTRA (more -D flags).

ARM_CC      ?= arm-none-eabi-gcc
ARM_OBJCOPY ?= arm-none-eabi-objcopy
ARM_SIZE    ?= arm-none-eabi-size
FW_OUT      := $(BUILD)/firmware
RP2040_SYS_MHZ ?= 133
FW_PINS     ?=
FW_EXTRA    ?=
FW_SCENE_SRCS ?= firmware/app/scenes_builtin.c

FW_APP_SRCS  := firmware/app/main.c firmware/app/font5x7.c
FW_HAL_SRCS  := hal/dcs.c $(sort $(wildcard hal/panel*.c))
FW_CORE_SRCS := $(sort $(wildcard firmware/core/*.c))
FW_COMMON    := $(FW_APP_SRCS) $(FW_HAL_SRCS) $(FW_CORE_SRCS) $(FW_SCENE_SRCS)
FW_INC       := -I. -Ifirmware/core -Ifirmware/app -Ihal

# ---- RP2040 ------------------------------------------------------------------
RP_DIR   := firmware/board/rp2040
RP_SRCS  := $(RP_DIR)/crt0.c $(RP_DIR)/board.c $(RP_DIR)/fw_board_rp2040.c hal/rp2040/hal_rp2040.c \
            $(FW_COMMON)
RP_ASM   := $(RP_DIR)/hwdiv.S
RP_CFLAGS := -mcpu=cortex-m0plus -mthumb -O2 -g -std=c11 $(WARN) -ffunction-sections -fdata-sections \
             -ffreestanding -fno-common -DNUM_MODE=1 -DRP2040_SYS_MHZ=$(RP2040_SYS_MHZ) \
             $(FW_INC) -I$(RP_DIR) -Ihal/rp2040 $(FW_PINS) $(FW_EXTRA)
RP_LDFLAGS := -mcpu=cortex-m0plus -mthumb --specs=nano.specs -nostartfiles -T $(RP_DIR)/rp2040.ld \
              -Wl,--gc-sections -Wl,--no-warn-rwx-segments

# boot2: assembled, linked at its SRAM address, CRC appended, re-emitted as .S
$(FW_OUT)/pico/boot2.elf: $(RP_DIR)/boot2.S $(RP_DIR)/boot2.ld
	@mkdir -p $(@D)
	$(Q)$(ARM_CC) -mcpu=cortex-m0plus -mthumb -nostdlib -T $(RP_DIR)/boot2.ld $< -o $@
$(FW_OUT)/pico/boot2.bin: $(FW_OUT)/pico/boot2.elf
	$(Q)$(ARM_OBJCOPY) -O binary $< $@
$(FW_OUT)/pico/boot2_crc.S: $(FW_OUT)/pico/boot2.bin tools/uf2/boot2crc.py
	$(Q)$(PYTHON) tools/uf2/boot2crc.py $< $@

# $(1) = image name, $(2) = extra flags
define RP_IMAGE
$(FW_OUT)/pico/obj-$(1)/%.o: %.c
	@mkdir -p $$(@D)
	$$(Q)$$(ARM_CC) $$(RP_CFLAGS) $(2) -MMD -MP -c $$< -o $$@
$(FW_OUT)/pico/obj-$(1)/%.o: %.S
	@mkdir -p $$(@D)
	$$(Q)$$(ARM_CC) -mcpu=cortex-m0plus -mthumb -c $$< -o $$@
$(FW_OUT)/pico/obj-$(1)/boot2_crc.o: $(FW_OUT)/pico/boot2_crc.S
	@mkdir -p $$(@D)
	$$(Q)$$(ARM_CC) -mcpu=cortex-m0plus -mthumb -c $$< -o $$@
$(FW_OUT)/pico/$(1).elf: $(patsubst %.c,$(FW_OUT)/pico/obj-$(1)/%.o,$(RP_SRCS)) \
                         $(patsubst %.S,$(FW_OUT)/pico/obj-$(1)/%.o,$(RP_ASM)) \
                         $(FW_OUT)/pico/obj-$(1)/boot2_crc.o $(RP_DIR)/rp2040.ld
	$$(Q)$$(ARM_CC) $$(RP_LDFLAGS) -Wl,-Map=$(FW_OUT)/pico/$(1).map \
		$$(filter %.o,$$^) -lc -lgcc -o $$@
$(FW_OUT)/pico/$(1).bin: $(FW_OUT)/pico/$(1).elf
	$$(Q)$$(ARM_OBJCOPY) -O binary $$< $$@
$(FW_OUT)/pico/$(1).uf2: $(FW_OUT)/pico/$(1).bin tools/uf2/uf2conv.py
	$$(Q)$$(PYTHON) tools/uf2/uf2conv.py $$< $$@ --base 0x10000000 --family 0xE48BFF56
endef
$(eval $(call RP_IMAGE,cgfs,))
$(eval $(call RP_IMAGE,cgfs-1core,-DRP2040_SINGLE_CORE=1))

FW_RP_IMAGES := $(FW_OUT)/pico/cgfs.uf2 $(FW_OUT)/pico/cgfs-1core.uf2

.PHONY: firmware-pico
firmware-pico: deps-firmware
	$(Q)$(MAKE) --no-print-directory $(FW_RP_IMAGES)

firmware: firmware-pico
	$(Q)$(ARM_SIZE) $(FW_RP_IMAGES:.uf2=.elf) $(FW_EXTRA_ELFS)
