# SPDX-License-Identifier: MIT
# host_sim: the host simulator (see docs/host_sim.md).
#
# Built in two variants: $(BUILD)/host_sim (optimised, what `make` and
# `make run` use) and $(BUILD)/asan/host_sim (ASan+UBSan, what the tests run).
# Its own sources are mode-independent ("none"); the renderer comes in as
# the three core bundles of mk/core.mk, and fixed point once per NUM_FRAC
# 12 … 20 (core_frac_bundles): --numeric fixed renders at the format the
# scene's ranges call for (tools/scene/scene_format.c).

HOST_SIM_SRCS := host_sim/main.c host_sim/imgio.c host_sim/panel_out.c host_sim/compare.c tools/common/file_id.c
# --min-psnr, --target and the scene's quality block: methods chosen for an
# accuracy target (tools/quality, its cost model tools/quality/cost_model.def)
HOST_SIM_SRCS += host_sim/quality_opts.c tools/quality/quality.c
# the frame-rate overlay's font (--fps-overlay), shared with the firmware
HOST_SIM_SRCS += firmware/app/font5x7.c
# --pattern check: the bring-up pattern of the cgfs-check images
HOST_SIM_SRCS += firmware/app/check_pattern.c
# --window: SDL2 (the Makefile's WITH_SDL2); without it the option says so, exit 2
HOST_SIM_SRCS += host_sim/window.c
$(foreach v,$(VARIANTS),$(call obj,$(v),none,host_sim/window.c)): EXTRA_CFLAGS += $(SDL2_FLAGS)
$(foreach v,$(VARIANTS),$(call obj,$(v),none,host_sim/window.c)): $(CONFIG_STAMP)

# libpng: PNG_CFLAGS and PNG_LIBS are the Makefile's.
$(foreach v,$(VARIANTS),$(call obj,$(v),none,host_sim/imgio.c)): EXTRA_CFLAGS += $(PNG_CFLAGS)
# libpng is a distribution package: install it first if it is missing.
$(foreach v,$(VARIANTS),$(call obj,$(v),none,host_sim/imgio.c)): | deps

# Every link of host_sim's objects: --wrap=fopen, host_sim keeps every file
# the scene parser reads, so that no output is written onto one of them.
HOST_SIM_LDFLAGS := -Wl,--wrap=fopen

HOST_SIM_BIN_host := $(BUILD)/host_sim
HOST_SIM_BIN_asan := $(BUILD)/asan/host_sim

define HOST_SIM_LINK
$(HOST_SIM_BIN_$(1)): $(call obj,$(1),none,$(HOST_SIM_SRCS)) $(call core_bundles,$(1)) $(call core_frac_bundles,$(1)) \
                      $(call hal_objs,$(1))
	@mkdir -p $$(@D)
	$(Q)$$(CC) $(LDFLAGS_$(1)) $(HOST_SIM_LDFLAGS) -o $$@ $$^ $$(PNG_LIBS) $$(HAL_LDLIBS) $$(SDL2_LIBS) -lm
endef
$(foreach v,$(VARIANTS),$(eval $(call HOST_SIM_LINK,$(v))))

PROGRAMS  += $(HOST_SIM_BIN_host)
TEST_DEPS += $(HOST_SIM_BIN_asan) $(HOST_SIM_BIN_host)
TESTS     += tests/system/test_host_sim.sh:$(HOST_SIM_BIN_asan)
# every scene on every panel of hal/panels.def, at the panel's size (the
# optimised build: 40 scenes x 9 panels)
TESTS     += tests/system/test_host_sim_panels.sh:$(HOST_SIM_BIN_host)
# --pattern check (the bring-up pattern) on every panel in every rotation, --miswire
TESTS     += tests/system/test_check_pattern.py:$(HOST_SIM_BIN_asan)
# --loop, dirty-rectangle flush, per-frame --out, --fps-overlay, progress line
TESTS     += tests/system/test_live.sh:$(HOST_SIM_BIN_asan)
# --window under Xvfb: a screenshot (xwd) against the PNG
TESTS     += tests/system/test_window.sh:$(HOST_SIM_BIN_asan)
# input/output faults (FIFOs, devices, ulimit -f, signals) of host_sim and scenec
TEST_DEPS += $(BUILD)/scenec
TESTS     += tests/system/test_io_faults.sh:$(HOST_SIM_BIN_asan):$(BUILD)/scenec
# mistakes that point at their fix: nearest names, byte order mark, missing
# files, the no-lights and culling warnings, scenec --help
TESTS     += tests/system/test_hints.sh:$(HOST_SIM_BIN_asan):$(BUILD)/scenec
# the format promise on generated extreme scenes (tools/scene/gen_extreme.py),
# under the sanitizers: a bounded count here, `make extremes` for more
# (family 2, round two: flat views and sizes, the book quadratic, mirrored
# cameras, the camera inside, grazing planes, 3D lines)
EXTREMES_COUNT ?= 300
EXTREMES2_COUNT ?= 200
TESTS     += tests/system/test_scene_extremes.sh:$(HOST_SIM_BIN_asan):1:$(EXTREMES_COUNT)
TESTS     += tests/system/test_scene_extremes.sh:$(HOST_SIM_BIN_asan):9100:$(EXTREMES2_COUNT):2
EXTREMES_SEEDS ?= 2 3 4 5 6 7 8 9 10 11
EXTREMES2_SEEDS ?= 9100 9200 9300
.PHONY: extremes
extremes: $(HOST_SIM_BIN_asan)
	$(Q)tests/support/run.sh $(foreach s,$(EXTREMES_SEEDS),tests/system/test_scene_extremes.sh:$(HOST_SIM_BIN_asan):$(s):1000) \
	  $(foreach s,$(EXTREMES2_SEEDS),tests/system/test_scene_extremes.sh:$(HOST_SIM_BIN_asan):$(s):1000:2)
TESTS     += tests/system/test_make_run.sh:$(BUILD)
TEST_NEEDS_test_make_run := $(BUILD)/host_sim

# `make pictures`: the README's pictures, a few scenes rendered as `make run`
# renders them, into docs/images/ (tools/pictures.sh); the test renders them
# again and compares the pixels with the committed files.
.PHONY: pictures
pictures:
	$(Q)tools/deps.sh run
	$(Q)$(MAKE) --no-print-directory $(HOST_SIM_BIN_host)
	$(Q)tools/pictures.sh $(HOST_SIM_BIN_host) docs/images
TESTS     += tests/system/test_pictures.py:$(HOST_SIM_BIN_host)

# `make run`: every scene in firmware/scenes/ through host_sim (ST7789
# 240x240, fixed point) into $(OUT)/<scene>.png, one line per scene. The
# first build of host_sim takes a minute or more: it says what it builds,
# then builds the renderer core's number formats one at a time (each with
# every core), a line before each.
RUN_BUNDLES := $(foreach m,$(NUM_MODES) $(CORE_FRAC_MODES),$(BUILD)/host/core_$(m).o)
run_jobs     = $(if $(filter -j%,$(MAKEFLAGS)),,-j$(TEST_JOBS))
run:
	$(Q)tools/deps.sh run
	$(Q)missing=""; for b in $(RUN_BUNDLES); do [ -e "$$b" ] || missing="$$missing $$b"; done; \
	n=$$(echo $$missing | wc -w); k=0; \
	if [ $$n -gt 0 ]; then \
		echo "make run: building $(HOST_SIM_BIN_host): the renderer core once per number format ($$n of" \
		     "$(words $(RUN_BUNDLES)): double, float, fixed point at Q11.20 ... Q19.12), then host_sim itself;" \
		     "about a minute on two cores the first time"; \
	elif [ ! -e $(HOST_SIM_BIN_host) ]; then echo "make run: building $(HOST_SIM_BIN_host)"; fi; \
	for b in $$missing; do \
		k=$$((k + 1)); m=$${b##*/core_}; \
		echo "make run:   [$$k/$$n] the renderer core in $${m%.o}"; \
		$(MAKE) --no-print-directory $(run_jobs) $$b || exit 1; \
	done; \
	$(MAKE) --no-print-directory $(run_jobs) $(HOST_SIM_BIN_host) || exit 1; \
	if [ $$n -gt 0 ]; then echo "make run: $(HOST_SIM_BIN_host) built"; fi
	$(Q)echo "make run: rendering every scene of firmware/scenes/ (ST7789 240x240, fixed point, compared with double) into $(OUT)/"
	$(Q)tools/run_scenes.sh $(HOST_SIM_BIN_host) firmware/scenes $(OUT)
