# SPDX-License-Identifier: MIT
# HAL: DCS layer, panel drivers, emulated panel + sim backend, Linux backend.
#
# For programs that link the HAL (host_sim, tests):
#   $(call hal_objs,<variant>)  all HAL objects of a variant (mode "none")
#   $(HAL_LDLIBS)               libraries they need (libgpiod with WITH_GPIOD=1)

# (HAL_SRCS, the DCS layer and the panel drivers: the Makefile)
HAL_SIM_SRCS   := hal/sim/emu_panel.c hal/sim/hal_sim.c
HAL_LINUX_SRCS := hal/linux/hal_linux.c

# libgpiod: the Makefile's WITH_GPIOD, GPIOD_FLAGS, GPIOD_LIBS.
HAL_LDLIBS := $(GPIOD_LIBS)
$(BUILD)/%/none/hal/linux/hal_linux.o $(BUILD)/%/none/tests/unit/test_hal_linux.o: EXTRA_CFLAGS += $(GPIOD_FLAGS)
$(foreach v,$(VARIANTS),$(call obj,$(v),none,hal/linux/hal_linux.c tests/unit/test_hal_linux.c)): $(CONFIG_STAMP)

hal_objs = $(call obj,$(1),none,$(HAL_SRCS) $(HAL_SIM_SRCS) $(HAL_LINUX_SRCS))

# Tests (ASan+UBSan build).
HAL_TEST_NAMES := test_dcs test_panel test_emu_panel test_panel_vectors test_hal_linux
HAL_TEST_BINS  := $(addprefix $(BUILD)/asan/tests/,$(HAL_TEST_NAMES))

$(BUILD)/asan/tests/%: $(BUILD)/asan/none/tests/unit/%.o $(call hal_objs,asan)
	@mkdir -p $(@D)
	$(Q)$(CC) $(LDFLAGS_asan) -o $@ $^ $(HAL_LDLIBS)

TEST_DEPS += $(HAL_TEST_BINS)
TESTS += $(BUILD)/asan/tests/test_dcs $(BUILD)/asan/tests/test_panel \
         $(BUILD)/asan/tests/test_emu_panel \
         $(BUILD)/asan/tests/test_panel_vectors:tests/vectors/panel \
         $(BUILD)/asan/tests/test_hal_linux
.PRECIOUS: $(BUILD)/asan/none/tests/unit/%.o
