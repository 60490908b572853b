# SPDX-License-Identifier: MIT
# Numeric layer (firmware/core/num*): accuracy tests, report, soft-float check.
#
# test_num is built per numeric mode, and for fixed point also with
# NUM_FRAC = 12 and 20 (modes "fixed12", "fixed20"; fixed12 also forces the
# portable integer kernels that ARMv6-M uses, so they are tested on the host).
#   make num-report     prints the markdown accuracy table of docs/numerics.md

NUM_SRCS       := $(CORE_NUM_SRCS)
NUM_TEST_MODES := fixed fixed12 fixed20 float double
COMPILE_MODES       += fixed12 fixed20 fixed16p
MODE_FLAGS_fixed12  := -DNUM_MODE=1 -DNUM_FRAC=12 -DNUM_PORTABLE_INT
MODE_FLAGS_fixed20  := -DNUM_MODE=1 -DNUM_FRAC=20
# fixed16p: the firmware default format with the portable ARMv6-M kernels.
MODE_FLAGS_fixed16p := -DNUM_MODE=1 -DNUM_FRAC=16 -DNUM_PORTABLE_INT


$(foreach v,$(VARIANTS),$(foreach m,$(NUM_TEST_MODES),\
    $(call program,$(BUILD)/$(v)/tests/test_num_$(m),$(call obj,$(v),$(m),tests/unit/test_num.c $(NUM_SRCS)),$(v))))

TEST_DEPS += $(foreach m,$(NUM_TEST_MODES),$(BUILD)/asan/tests/test_num_$(m))
TESTS     += $(foreach m,$(NUM_TEST_MODES),$(BUILD)/asan/tests/test_num_$(m))

# The square-root kernels against slow references, bit for bit (fixed point;
# fixed12 runs the portable ARMv6-M integer paths).
NUM_KERNEL_MODES := fixed fixed12 fixed20
$(foreach v,$(VARIANTS),$(foreach m,$(NUM_KERNEL_MODES),\
    $(call program,$(BUILD)/$(v)/tests/test_num_kernels_$(m),$(call obj,$(v),$(m),tests/unit/test_num_kernels.c $(NUM_SRCS)),$(v))))
TEST_DEPS += $(foreach m,$(NUM_KERNEL_MODES),$(BUILD)/asan/tests/test_num_kernels_$(m))
TESTS     += $(foreach m,$(NUM_KERNEL_MODES),$(BUILD)/asan/tests/test_num_kernels_$(m))

# Division kernels and dot products against slow references, bit for bit
# (fixed12, fixed16p: the ARMv6-M reciprocal digits and 16x16 products;
# fixed, fixed20: the 32-bit hardware-divide digits, as on ARMv7-M).
NUM_DIV_MODES := $(NUM_KERNEL_MODES) fixed16p
$(foreach v,$(VARIANTS),$(foreach m,$(NUM_DIV_MODES),\
    $(call program,$(BUILD)/$(v)/tests/test_num_div_$(m),$(call obj,$(v),$(m),tests/unit/test_num_div.c $(NUM_SRCS) firmware/core/raster/raster_num.c),$(v))))
TEST_DEPS += $(foreach m,$(NUM_DIV_MODES),$(BUILD)/asan/tests/test_num_div_$(m))
TESTS     += $(foreach m,$(NUM_DIV_MODES),$(BUILD)/asan/tests/test_num_div_$(m))

.PHONY: num-report
num-report: $(foreach m,$(NUM_TEST_MODES),$(BUILD)/host/tests/test_num_$(m))
	@echo "| mode | operation | domain | samples | max err | mean err | bound |"
	@echo "|---|---|---|---|---|---|---|"
	$(Q)for m in $(NUM_TEST_MODES); do $(BUILD)/host/tests/test_num_$$m --report || exit 1; done

# Soft-float check of the cross-compiled fixed-point core (all firmware/core/*.c).
TESTS += tests/system/test_softfloat.sh:$(BUILD)
TEST_NEEDS_test_softfloat :=   # (it compiles the core itself, under its argument)

# The ARMv6-M kernels (Thumb-1 assembly, clz table) on the emulated
# Cortex-M0+ against the compiler's 64-bit arithmetic, at NUM_FRAC 16 (the
# num_mul_round kernel of its own) and 20; they also print each kernel's
# instructions per call.
$(call bench_image,test_num_v6m_q16,m0plus-qemu,fixed,tests/unit/test_num_v6m.c $(CORE_NUM_SRCS),-Itests/support -DNUM_FRAC=16)
$(call bench_image,test_num_v6m_q20,m0plus-qemu,fixed,tests/unit/test_num_v6m.c $(CORE_NUM_SRCS),-Itests/support -DNUM_FRAC=20)
NUM_V6M_IMAGES := $(BUILD)/bench/m0plus-qemu/fixed/test_num_v6m_q16.elf $(BUILD)/bench/m0plus-qemu/fixed/test_num_v6m_q20.elf
TEST_DEPS += $(NUM_V6M_IMAGES)
TESTS     += tools/bench/run.py:--smoke:$(subst $(eval) ,:,$(NUM_V6M_IMAGES))
