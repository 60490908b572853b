# SPDX-License-Identifier: MIT
# `make charts`: the speed/accuracy lab's Pareto charts, each scene at every
# fixed-point format, and the stability sweeps (tools/charts/charts.py,
# matplotlib from the distribution), into $(OUT)/charts. The lab measures
# its variants on the emulated MCUs itself (tools/charts/lab.py: images
# built below, the firmware's RP2040 images) and caches every run under
# $(BUILD)/charts/cache by the hash of the image, scene text and arguments:
# a second run reuses every result still up to date. CHARTS_JOBS emulator
# runs at a time; CHARTS_ONLY=pareto,formats,stability for a part.
CHARTS_PY   ?= $(if $(wildcard /usr/bin/python3),/usr/bin/python3,$(PYTHON))
CHARTS_JOBS ?= 2
CHARTS_ONLY ?= pareto,formats,stability

charts: $(BUILD)/host_sim
	$(Q)tools/deps.sh charts
	$(Q)tools/deps.sh bench
	$(Q)$(CHARTS_PY) tools/charts/charts.py --host-sim $(BUILD)/host_sim --build $(BUILD) \
		--scenes firmware/scenes --out $(OUT)/charts --jobs $(CHARTS_JOBS) --only $(CHARTS_ONLY) \
		--make "$(MAKE)"

# The sweeps' boundaries, pinned (tests/system/test_stability.py); the span loops'
# range is measured on the emulated M0+ with the lab's images at the formats
# its scenes take (Q11.20 up to 1000 pixels a side, Q12.19 above).
TESTS += tests/system/test_stability.py:$(BUILD)/host_sim:$(BUILD)
TEST_NEEDS_test_stability := $(BUILD)/charts/bench/m0plus-qemu/fixed20/bench_file.elf \
                             $(BUILD)/charts/bench/m0plus-qemu/fixed19/bench_file.elf
TEST_DEPS += $(TEST_NEEDS_test_stability)

# The scene compiler's choices for accuracy targets (tools/quality): its cost
# model against the committed lab rows, each lab scene's choices within 10 %
# of the cheapest candidate meeting the target, the quality block end to end.
TESTS += tests/system/test_quality.py:$(BUILD)/host_sim:$(SCENEC):$(BUILD)/asan/host_sim
TEST_DEPS += $(SCENEC) $(BUILD)/asan/host_sim

# The cost model refitted in one command: the lab's variants the model and
# its checks use, measured on the emulators (cached as make charts' runs are),
# into tests/data/quality/lab.json; the model tools/quality/cost_model.def
# fitted on it; its predictions on the held-out scenes and leave one out
# ($(OUT)/charts/cost-model-validate.csv).
# COST_MODEL_ONLY=SCENE,...: those lab scenes alone measured (in the modes of
# COST_MODEL_NUMERIC=MODE,..., default all; no RP2040 runs), the fixture's
# other rows kept.
COST_MODEL_ONLY    ?=
COST_MODEL_NUMERIC ?=
.PHONY: cost-model
cost-model: $(BUILD)/host_sim
	$(Q)tools/deps.sh bench
	$(Q)$(CHARTS_PY) tools/quality/cost_model.py measure --host-sim $(BUILD)/host_sim --build $(BUILD) \
		--scenes firmware/scenes --jobs $(CHARTS_JOBS) --make "$(MAKE)" --out tests/data/quality/lab.json \
		$(if $(COST_MODEL_ONLY),--only $(COST_MODEL_ONLY) --no-rp2040 $(if $(COST_MODEL_NUMERIC),--numeric $(COST_MODEL_NUMERIC)))
	$(Q)$(CHARTS_PY) tools/quality/cost_model.py model --fixture tests/data/quality/lab.json \
		--write tools/quality/cost_model.def
	$(Q)mkdir -p $(OUT)/charts
	$(Q)$(CHARTS_PY) tools/quality/cost_model.py validate --fixture tests/data/quality/lab.json \
		--csv $(OUT)/charts/cost-model-validate.csv
	$(Q)$(MAKE) --no-print-directory choices-table
# The same from the fixture's stored rows, without an emulator run: the work
# of each lab scene and ray-traced row recomputed by host renders (after a
# change to what a unit of work counts), the model fitted, its predictions.
# Both end with make choices-table in a new make, which first links host_sim
# again with the model just written (quality.c includes cost_model.def).
.PHONY: cost-model-refit
cost-model-refit: $(BUILD)/host_sim
	$(Q)$(CHARTS_PY) tools/quality/cost_model.py work --fixture tests/data/quality/lab.json \
		--host-sim $(BUILD)/host_sim
	$(Q)$(CHARTS_PY) tools/quality/cost_model.py model --fixture tests/data/quality/lab.json \
		--write tools/quality/cost_model.def
	$(Q)mkdir -p $(OUT)/charts
	$(Q)$(CHARTS_PY) tools/quality/cost_model.py validate --fixture tests/data/quality/lab.json \
		--csv $(OUT)/charts/cost-model-validate.csv
	$(Q)$(MAKE) --no-print-directory choices-table

# docs/charts.md's table of choices, made of the fixture's rows (the
# compiler's choices as tests/system/test_quality.py checks them).
.PHONY: choices-table
choices-table: $(BUILD)/host_sim
	$(Q)$(CHARTS_PY) tools/quality/cost_model.py choices --fixture tests/data/quality/lab.json \
		--host-sim $(BUILD)/host_sim --write docs/charts.md

# Accuracy fields of the scene measurements (contract: psnr, ssim, max_err,
# pct_diff against the double build), added once every bench step has run.
.PHONY: bench-accuracy
bench-accuracy: bench-qemu bench-rp2040 $(BUILD)/host_sim
	$(Q)$(PYTHON) tools/bench/accuracy.py $(BUILD)/bench/results.jsonl $(BUILD)/host_sim
bench: bench-accuracy

# ---- the speed/accuracy lab's benchmark images -----------------------------
# tools/bench/bench_file.c parses a scene file on the target (semihosting,
# newlib's rdimon) and measures init and every frame: one image per target
# and numeric mode serves every scene and method choice. Modes: fixed12 …
# fixed20 (NUM_FRAC), float, double. tools/charts/lab.py builds the ones it
# needs (make $(BUILD)/charts/bench/TARGET/MODE/bench_file.elf) and caches
# each run by the hash of the image, the scene text and the arguments.
# (mk/core.mk's lists are read after this file: spelled out here)
LAB_MODES := $(foreach f,12 13 14 15 16 17 18 19 20,fixed$(f)) float double
LAB_SRCS  := tools/bench/bench_file.c $(BENCH_RUNTIME) $(CORE_SRCS) \
             $(sort $(wildcard tools/scene/*.c))
lab_mode_flags = $(if $(filter fixed%,$(1)),-DNUM_MODE=1 -DNUM_FRAC=$(1:fixed%=%),-DNUM_MODE=$(NUM_MODE_$(1)))
define LAB_IMAGE
$(BUILD)/charts/bench/$(1)/$(2)/bench_file.elf: $(patsubst %.c,$(BUILD)/charts/bench/$(1)/$(2)/objs/%.o,$(LAB_SRCS)) $(BENCH_LD)
	$(Q)$(BENCH_CC) $(BENCH_CPU_$(1)) -nostartfiles -T $(BENCH_LD) --specs=nano.specs --specs=rdimon.specs \
		-Wl,--gc-sections -o $$@ $$(filter %.o,$$^) -lm
$(BUILD)/charts/bench/$(1)/$(2)/objs/%.o: %.c
	@mkdir -p $$(@D)
	$(Q)$(BENCH_CC) $(BENCH_CPU_$(1)) $(BENCH_CFLAGS) $(call lab_mode_flags,$(2)) -MMD -MP -c $$< -o $$@
-include $(patsubst %.c,$(BUILD)/charts/bench/$(1)/$(2)/objs/%.d,$(LAB_SRCS))
endef
$(foreach t,$(BENCH_TARGETS),$(foreach m,$(LAB_MODES),$(eval $(call LAB_IMAGE,$(t),$(m)))))
