# SPDX-License-Identifier: MIT
# Raspberry Pi: the Linux HAL backend and the flasher's GPIO reset against
# both libgpiod APIs, and the backend's byte stream through the emulated panel.
#
# The distribution's libgpiod (pkg-config; 1.6 on Debian 12) builds `make`'s
# programs (mk/hal.mk, mk/flasher.mk: GPIOD_API_MAJOR from its version).
# libgpiod 2 comes from the gpiod package of PyPI, whose source distribution
# bundles libgpiod's C sources (include/gpiod.h, lib/*.c): fetched with pip,
# checked against its SHA-256, built into $(BUILD)/gpiod2 as libgpiod.so with
# a libgpiod.pc, and the same sources compiled against it by what that .pc
# reports:
#   $(BUILD)/gpiod2/test_gpio_reset  tests/unit/test_gpio_reset.c, 2.x API (ASan+UBSan)
#   $(BUILD)/gpiod2/test_hal_linux   tests/unit/test_hal_linux.c, 2.x API (ASan+UBSan)
#   $(BUILD)/gpiod2/host_sim         host_sim with hal/linux in the 2.x API
# tests/system/test_linux_backend.sh runs host_sim --backend linux (either API) with
# tests/support/shim_linux_panel.c preloaded: spidev and the GPIO lines go into the
# strict emulated controller, whose glass must equal the sim backend's.

GPIOD2_SDIST   := gpiod-2.5.0.tar.gz
GPIOD2_SHA256  := 53ae5a1f14d6388c155b591ca0fc0cfa73b44d4f6d8d117e8a9e68f5902d187a
GPIOD2_DIR     := $(BUILD)/gpiod2
GPIOD2_SRC     := $(GPIOD2_DIR)/src
GPIOD2_LIB     := $(GPIOD2_DIR)/lib/libgpiod.so
GPIOD2_PC_DIR  := $(GPIOD2_DIR)/lib/pkgconfig
# flags of a libgpiod .pc directory: $(call gpiod_pc,DIR,--cflags|--libs|--modversion)
gpiod_pc = $$(PKG_CONFIG_PATH=$(1) pkg-config $(2) libgpiod)
gpiod_major = $$(PKG_CONFIG_PATH=$(1) pkg-config --modversion libgpiod | cut -d. -f1)

$(GPIOD2_DIR)/$(GPIOD2_SDIST):
	@mkdir -p $(@D)/dl
	$(Q)$(PYTHON) -m pip download -q --no-binary :all: --no-deps gpiod==2.5.0 -d $(@D)/dl >$(@D)/dl/pip.log 2>&1 || \
		{ cat $(@D)/dl/pip.log >&2; echo "gpiod2: pip download of gpiod==2.5.0 failed" >&2; exit 1; }
	$(Q)echo "$(GPIOD2_SHA256)  $(@D)/dl/$(GPIOD2_SDIST)" | sha256sum -c --quiet - || \
		{ echo "gpiod2: $(GPIOD2_SDIST): SHA-256 differs" >&2; exit 1; }
	$(Q)mv $(@D)/dl/$(GPIOD2_SDIST) $@

$(GPIOD2_SRC)/.unpacked: $(GPIOD2_DIR)/$(GPIOD2_SDIST)
	$(Q)rm -rf $(GPIOD2_SRC) && mkdir -p $(GPIOD2_SRC)
	$(Q)tar -xzf $< -C $(GPIOD2_SRC) --strip-components=1
	$(Q)test -f $(GPIOD2_SRC)/include/gpiod.h && test -f $(GPIOD2_SRC)/libgpiod-version.txt
	$(Q)touch $@

# libgpiod's own sources, with its own flags (not the project's warnings).
$(GPIOD2_LIB): $(GPIOD2_SRC)/.unpacked
	@mkdir -p $(@D)/obj $(GPIOD2_PC_DIR)
	$(Q)v=$$(cat $(GPIOD2_SRC)/libgpiod-version.txt); \
	for f in $(GPIOD2_SRC)/lib/*.c; do \
		$(CC) -std=gnu11 -O2 -g -fPIC -D_GNU_SOURCE -DGPIOD_API_VERSION_STR="\"$$v\"" \
			-I$(GPIOD2_SRC)/include -I$(GPIOD2_SRC)/lib -c $$f -o $(@D)/obj/$$(basename $$f .c).o || exit 1; \
	done; \
	$(CC) -shared -o $@ $(@D)/obj/*.o && \
	abs=$$(cd $(GPIOD2_DIR) && pwd); \
	printf 'Name: libgpiod\nDescription: libgpiod %s (gpiod sdist)\nVersion: %s\nCflags: -I%s\nLibs: -L%s -Wl,-rpath,%s -lgpiod\n' \
		"$$v" "$$v" "$$abs/src/include" "$$abs/lib" "$$abs/lib" >$(GPIOD2_PC_DIR)/libgpiod.pc

# Objects built against libgpiod 2: $(GPIOD2_DIR)/obj/<variant>/<src>.o
define GPIOD2_COMPILE
$(GPIOD2_DIR)/obj/$(1)/%.o: %.c $(GPIOD2_LIB)
	@mkdir -p $$(@D)
	$(Q)$$(CC) $(CSTD) $(WARN) $(VFLAGS_$(1)) $(INCLUDES) -Itools/flasher -Itests/support -DWITH_GPIOD \
		-DGPIOD_API_MAJOR=$$(call gpiod_major,$(GPIOD2_PC_DIR)) $$(call gpiod_pc,$(GPIOD2_PC_DIR),--cflags) \
		-MMD -MP -c $$< -o $$@
endef
$(foreach v,$(VARIANTS),$(eval $(call GPIOD2_COMPILE,$(v))))
-include $(wildcard $(GPIOD2_DIR)/obj/*/*/*.d $(GPIOD2_DIR)/obj/*/*/*/*.d)

gpiod2_obj = $(patsubst %.c,$(GPIOD2_DIR)/obj/$(1)/%.o,$(2))

$(GPIOD2_DIR)/tests/test_gpio_reset: $(call gpiod2_obj,asan,tools/flasher/gpio_reset.c tests/support/fake_gpiod.c tests/unit/test_gpio_reset.c)
	@mkdir -p $(@D)
	$(Q)$(CC) $(LDFLAGS_asan) -o $@ $^
$(GPIOD2_DIR)/tests/test_hal_linux: $(call gpiod2_obj,asan,tests/unit/test_hal_linux.c hal/linux/hal_linux.c) \
                              $(call obj,asan,none,$(HAL_SRCS) $(HAL_SIM_SRCS))
	@mkdir -p $(@D)
	$(Q)$(CC) $(LDFLAGS_asan) -o $@ $^ $(call gpiod_pc,$(GPIOD2_PC_DIR),--libs)

# host_sim with the Linux backend on libgpiod 2 (the rest as $(BUILD)/host_sim).
GPIOD2_HOST_SIM := $(GPIOD2_DIR)/host_sim
$(GPIOD2_HOST_SIM): $(call obj,host,none,$(HOST_SIM_SRCS)) $(call core_bundles,host) $(call core_frac_bundles,host) \
                    $(filter-out %/hal_linux.o,$(call hal_objs,host)) $(call gpiod2_obj,host,hal/linux/hal_linux.c)
	$(Q)$(CC) $(LDFLAGS_host) $(HOST_SIM_LDFLAGS) -o $@ $^ $(PNG_LIBS) $(call gpiod_pc,$(GPIOD2_PC_DIR),--libs) $(SDL2_LIBS) -lm

# The LD_PRELOAD shim, once per API: the emulated panel behind spidev and a
# fake libgpiod (position-independent objects of their own).
SHIM_SRCS := tests/support/shim_linux_panel.c tests/support/fake_gpiod.c hal/sim/emu_panel.c
$(BUILD)/shim/v1/%.o: %.c
	@mkdir -p $(@D)
	$(Q)$(CC) $(CSTD) $(WARN) $(HOST_OPT) -fPIC $(INCLUDES) -Itests/support \
		$(GPIOD_FLAGS) -MMD -MP -c $< -o $@
$(BUILD)/shim/v2/%.o: %.c $(GPIOD2_LIB)
	@mkdir -p $(@D)
	$(Q)$(CC) $(CSTD) $(WARN) $(HOST_OPT) -fPIC $(INCLUDES) -Itests/support \
		-DGPIOD_API_MAJOR=$(call gpiod_major,$(GPIOD2_PC_DIR)) $(call gpiod_pc,$(GPIOD2_PC_DIR),--cflags) \
		-MMD -MP -c $< -o $@
-include $(wildcard $(BUILD)/shim/*/*/*.d $(BUILD)/shim/*/*/*/*.d)
$(BUILD)/shim/%/shim_linux_panel.so: $(foreach s,$(SHIM_SRCS),$(BUILD)/shim/%/$(s:.c=.o))
	$(Q)$(CC) -shared -o $@ $^ -ldl

ifeq ($(WITH_GPIOD),1)
GPIOD2_TESTS := $(GPIOD2_DIR)/tests/test_gpio_reset $(GPIOD2_DIR)/tests/test_hal_linux
TEST_NEEDS_test_linux_backend := $(GPIOD2_HOST_SIM) $(BUILD)/host_sim $(BUILD)/shim/v1/shim_linux_panel.so \
             $(BUILD)/shim/v2/shim_linux_panel.so
TEST_DEPS += $(GPIOD2_TESTS) $(TEST_NEEDS_test_linux_backend)
TESTS     += $(GPIOD2_DIR)/tests/test_gpio_reset $(GPIOD2_DIR)/tests/test_hal_linux \
             tests/system/test_linux_backend.sh:$(BUILD)
endif
.PHONY: gpiod2
gpiod2: $(GPIOD2_TESTS) $(GPIOD2_HOST_SIM)
