# SPDX-License-Identifier: MIT
# The repository's own checks, and the targets that build and run a part of
# the tests: `make check T=NAME`, `make test-host`, `make list-tests`.

# The include graph follows the layers (the table is in the script).
TESTS     += tests/system/test_includes.py

# Every source file carries its licence (SPDX-License-Identifier: MIT).
TESTS     += tests/system/test_spdx.py

# The C files of tools/clang-format.files are as clang-format writes them
# with .clang-format (clang-format from tools/deps.sh test).
TESTS     += tools/format_check.sh

# `make test` decides which tests run after installing the packages
# (a library installed by that run counts in the same run).
TESTS     += tests/system/test_make_deps.sh

# A test's name: the base name of its program (the script run by node, the
# last image given to tools/bench/run.py), without its extension.
test_words = $(subst :, ,$(1))
test_prog  = $(if $(filter node,$(firstword $(call test_words,$(1)))),$(word 2,$(call test_words,$(1))),$(if \
             $(filter %/run.py,$(firstword $(call test_words,$(1)))),$(lastword $(call test_words,$(1))),$(firstword \
             $(call test_words,$(1)))))
test_name  = $(basename $(notdir $(call test_prog,$(1))))
# What a test needs built: the files under $(BUILD) its command names, and
# TEST_NEEDS_<name> (set beside the test in its mk fragment). A test handed
# the whole build directory without a TEST_NEEDS_<name> gets all of TEST_DEPS.
test_needs = $(filter $(BUILD)/%,$(call test_words,$(1))) $(if $(filter undefined,$(origin \
             TEST_NEEDS_$(call test_name,$(1)))),$(if $(filter $(BUILD),$(call test_words,$(1))),$(TEST_DEPS)),$(TEST_NEEDS_$(call \
             test_name,$(1))))
test_jobs  = $(if $(filter -j%,$(MAKEFLAGS)),,-j$(TEST_JOBS))

# The tests that need a cross toolchain, qemu or node (the board images, the
# emulated Cortex-M0+/M4F, rp2040js); test-host runs all the others.
TESTS_TARGET_ONLY := node:% tools/bench/run.py:% tests/system/test_rp2040sim% tests/system/test_scenec.sh:% \
                     tests/system/test_softfloat.sh:% tests/system/test_examples.sh:% tests/system/test_stability.py:% \
                     tests/system/test_obj_mcu.sh:% tests/system/test_stm32_qemu.sh:% \
                     tests/system/test_fw_docs.sh:% tests/system/test_bench_accuracy.py:%.elf
TESTS_HOST = $(filter-out $(TESTS_TARGET_ONLY),$(TESTS))

CHECK_SEL = $(foreach t,$(TESTS),$(if $(findstring $(T),$(call test_name,$(t))),$(t)))

.PHONY: check test-host list-tests
check:
	@if [ -z "$(T)" ]; then echo "make check: T=NAME selects the tests whose name contains NAME (make list-tests)" >&2; exit 2; fi
	@if [ -z "$(strip $(CHECK_SEL))" ]; then echo "make check: no test's name contains '$(T)' (make list-tests)" >&2; exit 2; fi
	$(Q)$(MAKE) --no-print-directory $(test_jobs) $(sort $(foreach t,$(CHECK_SEL),$(call test_needs,$(t)))) nothing-else
	$(Q)TEST_JOBS=$(TEST_JOBS) tests/support/run.sh $(CHECK_SEL)

# (like `make test`: the list of tests is read after the install)
test-host: deps-test
	$(Q)$(MAKE) --no-print-directory test-host-after-deps
.PHONY: test-host-after-deps
test-host-after-deps:
	$(Q)$(MAKE) --no-print-directory $(test_jobs) $(sort $(foreach t,$(TESTS_HOST),$(call test_needs,$(t)))) nothing-else
	$(Q)TEST_JOBS=$(TEST_JOBS) $(TEST_RUN) $(TESTS_HOST)

list-tests:
	@$(foreach t,$(TESTS),printf '%-32s %s\n' '$(call test_name,$(t))' '$(t)';)

# (a target for the sub-make when a selection needs nothing built)
.PHONY: nothing-else
nothing-else:
	@:
