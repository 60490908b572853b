# SPDX-License-Identifier: MIT
# The flasher (host), which writes a Pico image over USB, its tests, and
# `make flash` (an image of mk/firmware.mk, read before this file).
#
# build/flasher links the real libusb transport; tests drive the same sequence
# through a fake transport (tests/unit/test_flasher.c).
USB_CFLAGS := $(shell pkg-config --cflags libusb-1.0 2>/dev/null)
USB_LIBS   := $(shell pkg-config --libs libusb-1.0 2>/dev/null || echo -lusb-1.0)
FLASHER_CORE := tools/flasher/picoboot.c tools/flasher/image.c
FLASHER_SRCS := $(FLASHER_CORE) tools/flasher/usb_libusb.c tools/flasher/gpio_reset.c tools/flasher/main.c
FLASHER_BIN  := $(BUILD)/flasher
# --gpio-reset (Raspberry Pi host) with libgpiod (the Makefile's WITH_GPIOD);
# without it the option says so and exits 2.
$(BUILD)/host/none/tools/flasher/%.o $(BUILD)/asan/none/tools/flasher/%.o: EXTRA_CFLAGS += -Itools/flasher $(USB_CFLAGS)
$(BUILD)/host/none/tools/flasher/gpio_reset.o $(BUILD)/asan/none/tools/flasher/gpio_reset.o: EXTRA_CFLAGS += $(GPIOD_FLAGS)
$(BUILD)/host/none/tools/flasher/gpio_reset.o $(BUILD)/asan/none/tools/flasher/gpio_reset.o: $(CONFIG_STAMP)
$(BUILD)/asan/none/tests/unit/test_flasher.o: EXTRA_CFLAGS += -Itools/flasher -Itests/support

$(FLASHER_BIN): $(call obj,host,none,$(FLASHER_SRCS))
	$(Q)$(CC) $(LDFLAGS_host) $^ $(USB_LIBS) $(GPIOD_LIBS) -o $@
$(BUILD)/asan/tests/test_flasher: $(call obj,asan,none,$(FLASHER_CORE) tests/unit/test_flasher.c)
	@mkdir -p $(@D)
	$(Q)$(CC) $(LDFLAGS_asan) $^ -o $@

# The libusb transport against a fake libusb (tests/support/fake_libusb.c
# defines the libusb functions; needs only the header).
$(BUILD)/asan/none/tests/unit/test_usb_libusb.o $(BUILD)/asan/none/tests/support/fake_libusb.o: EXTRA_CFLAGS += -Itools/flasher -Itests/support $(USB_CFLAGS)
$(BUILD)/asan/tests/test_usb_libusb: $(call obj,asan,none,tools/flasher/picoboot.c tools/flasher/usb_libusb.c tests/support/fake_libusb.c tests/unit/test_usb_libusb.c)
	@mkdir -p $(@D)
	$(Q)$(CC) $(LDFLAGS_asan) $^ -o $@

PROGRAMS  += $(FLASHER_BIN)
TEST_DEPS += $(FLASHER_BIN) $(BUILD)/asan/tests/test_flasher $(BUILD)/asan/tests/test_usb_libusb
TESTS     += $(BUILD)/asan/tests/test_flasher $(BUILD)/asan/tests/test_usb_libusb tests/system/test_flasher_noboard.sh:$(BUILD)
TEST_NEEDS_test_flasher_noboard := $(FLASHER_BIN)

# The GPIO reset sequence against a fake libgpiod (tests/support/fake_gpiod.c defines
# the gpiod functions; needs only the header). The 2.x API: mk/pi.mk.
ifeq ($(WITH_GPIOD),1)
$(BUILD)/asan/none/tests/unit/test_gpio_reset.o $(BUILD)/asan/none/tests/support/fake_gpiod.o: EXTRA_CFLAGS += -Itools/flasher -Itests/support $(GPIOD_FLAGS)
$(BUILD)/asan/tests/test_gpio_reset: $(call obj,asan,none,tools/flasher/gpio_reset.c tests/support/fake_gpiod.c tests/unit/test_gpio_reset.c)
	@mkdir -p $(@D)
	$(Q)$(CC) $(LDFLAGS_asan) $^ -o $@
TEST_DEPS += $(BUILD)/asan/tests/test_gpio_reset
TESTS     += $(BUILD)/asan/tests/test_gpio_reset
endif

# `make flash`: the two-core book image (raytracer-02 and raster-11, three
# frames each, in a loop) through the flasher; FLASH_IMAGE to override (for
# example build/firmware/pico/cgfs-cube.uf2, the real-time cube scenes).
FLASH_IMAGE ?= $(FW_OUT)/pico/cgfs-book.uf2
flash: $(FLASHER_BIN)
	$(Q)tools/deps.sh flash
	$(Q)$(MAKE) --no-print-directory $(FLASH_IMAGE)
	$(Q)$(FLASHER_BIN) $(FLASH_IMAGE)
