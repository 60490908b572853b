# SPDX-License-Identifier: MIT
# Top-level build. GNU make; out-of-tree objects in $(BUILD); header
# dependencies from -MMD; safe under make -j.
#
# Each area of the project adds its programs, tests and targets in a fragment
# under mk/ (mk/<area>.mk); this file holds only what they share.

BUILD   ?= build
OUT     ?= out
CC      ?= cc
# make's built-in CC is "cc"; keep it unless the user overrides it.
PYTHON  ?= python3

# Quiet by default; V=1 shows the commands.
ifeq ($(V),1)
Q :=
else
Q := @
endif

WARN      := -Wall -Wextra -Werror -pedantic
CSTD      := -std=c11 -D_POSIX_C_SOURCE=200809L
# No FMA contraction: the double build is the reference and must be exact.
HOST_OPT  := -O2 -g -ffp-contract=off
ASAN_OPT  := -O1 -g -ffp-contract=off -fno-omit-frame-pointer \
             -fsanitize=address,undefined -fno-sanitize-recover=all
INCLUDES  := -I. -Ifirmware/core -Ihal -Itools/scene -Itools/core_api

# Optional libraries, each found with pkg-config unless given on the command
# line (make WITH_SDL2=0 ...); `make test` installs both first
# (tools/deps.sh test):
#   WITH_SDL2   host_sim --window, a live window of the glass
#   WITH_GPIOD  the Raspberry Pi's GPIO lines (libgpiod 1.x or 2.x): the
#               hal/linux backend's D/C, RESET and backlight (host_sim
#               --backend linux) and the flasher's --gpio-reset
# Without one, those options say so in one line and exit 2; everything else
# builds. The sources that use one are compiled with its *_FLAGS (-DWITH_SDL2,
# -DWITH_GPIOD) and linked with its *_LIBS.
pkg_found = $(shell pkg-config --exists $(1) 2>/dev/null && echo 1 || echo 0)
ifndef WITH_SDL2
WITH_SDL2 := $(call pkg_found,sdl2)
endif
ifndef WITH_GPIOD
WITH_GPIOD := $(call pkg_found,libgpiod)
endif
ifeq ($(WITH_SDL2),1)
SDL2_FLAGS  := -DWITH_SDL2 $(patsubst -I%,-isystem %,$(shell pkg-config --cflags sdl2))
SDL2_LIBS   := $(shell pkg-config --libs sdl2)
endif
# libgpiod's API (1.x or 2.x) by the version pkg-config reports
ifeq ($(WITH_GPIOD),1)
GPIOD_FLAGS := -DWITH_GPIOD -DGPIOD_API_MAJOR=$(shell pkg-config --modversion libgpiod | cut -d. -f1) \
               $(shell pkg-config --cflags libgpiod)
GPIOD_LIBS  := $(shell pkg-config --libs libgpiod)
endif
# The configuration built, rewritten only when it changes: the objects that
# depend on it have CONFIG_STAMP as a prerequisite, so they follow a change
# (the library installed later, WITH_SDL2=0 on the command line).
CONFIG_STAMP := $(BUILD)/config
$(shell mkdir -p $(BUILD) && { echo '$(SDL2_FLAGS) $(GPIOD_FLAGS)' | cmp -s - $(CONFIG_STAMP) || \
          echo '$(SDL2_FLAGS) $(GPIOD_FLAGS)' >$(CONFIG_STAMP); })

# Numeric modes of the renderer core: the value of NUM_MODE for each.
NUM_MODES        := fixed float double
NUM_MODE_fixed   := 1
NUM_MODE_float   := 2
NUM_MODE_double  := 3

# Build variants of host code: "host" (optimised) and "asan" (ASan+UBSan).
VARIANTS     := host asan
VFLAGS_host  := $(HOST_OPT)
VFLAGS_asan  := $(ASAN_OPT)
LDFLAGS_host :=
LDFLAGS_asan := -fsanitize=address,undefined

# Object of SRC for VARIANT and MODE ("none" for mode-independent code):
#   $(BUILD)/<variant>/<mode>/<src>.o
obj = $(patsubst %.c,$(BUILD)/$(1)/$(2)/%.o,$(3))

# Compile modes and their flags: "none", the three numeric modes, and the
# modes mk fragments add (COMPILE_MODES += fixed13, MODE_FLAGS_fixed13 := ...);
# every variant compiles every mode by the one rule below.
COMPILE_MODES   := none $(NUM_MODES)
MODE_FLAGS_none :=
$(foreach m,$(NUM_MODES),$(eval MODE_FLAGS_$(m) := -DNUM_MODE=$(NUM_MODE_$(m))))
define COMPILE_RULES
$(BUILD)/$(1)/$(2)/%.o: %.c
	@mkdir -p $$(@D)
	$(Q)$$(CC) $(CSTD) $(WARN) $(VFLAGS_$(1)) $(MODE_FLAGS_$(2)) $(INCLUDES) $$(EXTRA_CFLAGS) -MMD -MP -c $$< -o $$@
endef

# libpng through pkg-config (host_sim's PNG output, the scene parser's PNG
# textures); recursive (=) so that it is asked only when a recipe runs, after
# tools/deps.sh may have installed it.
PNG_CFLAGS = $(shell pkg-config --cflags libpng 2>/dev/null)
PNG_LIBS   = $(or $(shell pkg-config --libs libpng 2>/dev/null),-lpng)

# $(call program,OUT,OBJECTS,VARIANT[,LIBS]): links OBJECTS into the host
# program OUT with VARIANT's link flags (and libpng, which the scene parser
# needs wherever it is linked in).
define PROGRAM_RULE
$(1): $(2)
	@mkdir -p $$(@D)
	$(Q)$$(CC) $(LDFLAGS_$(3)) -o $$@ $$^ $(4) $$(PNG_LIBS) -lm
endef
program = $(eval $(call PROGRAM_RULE,$(strip $(1)),$(strip $(2)),$(strip $(3)),$(strip $(4))))

# $(call bundle,OUT.o,OBJECTS,SYMBOL[,FROM]): links OBJECTS (one numeric
# mode of the core and what goes with it) into the relocatable object OUT.o
# whose only global symbol is SYMBOL (FROM renamed to SYMBOL, when given),
# so that several modes of the same sources link into one program.
define BUNDLE_RULE
$(1): $(2)
	@mkdir -p $$(@D)
	$(Q)ld -r -o $$@.tmp $$^
	$(Q)objcopy --keep-global-symbol=$(3) $(if $(4),--redefine-sym $(4)=$(3)) $$@.tmp $$@
	$(Q)rm -f $$@.tmp
endef
bundle = $(eval $(call BUNDLE_RULE,$(strip $(1)),$(strip $(2)),$(strip $(3)),$(strip $(4))))

# The renderer core (firmware/core, docs/extending.md has its map): the
# numeric layer (num/), texture levels (mipmap.c, which scene builders use
# too), the dispatcher, the ray tracer (rt/) and the rasterizer (raster/).
CORE_NUM_SRCS := $(sort $(wildcard firmware/core/num/*.c))
CORE_SRCS     := $(sort $(wildcard firmware/core/*.c firmware/core/*/*.c))
# The core of one host variant and compile mode as a static library, which
# host programs and tests link: $(call core_lib,VARIANT,MODE).
core_lib = $(BUILD)/$(1)/$(2)/libcore.a

# The display layer every program with a panel links: the DCS layer and the
# panel drivers (hal/; backends and the emulated panel: mk/hal.mk).
HAL_SRCS := hal/dcs.c $(sort $(wildcard hal/panel*.c))

# Scenes compiled by tools/scenec (mk/scene.mk builds scenec and the work
# probe). $(call scenec_rule,OUT.c,SCENE,WxH,STRIP_ROWS,ID,TARGET[,BUDGET]) writes
# OUT.c and OUT.h from firmware/scenes/SCENE.scene, with the C identifier ID
# (empty: scenec's default) and the work size of the emulated Cortex-M0+
# (TARGET 1: measured by the work probe) or of this host (TARGET 0: an upper
# bound for the target); BUDGET names the board whose RAM and flash budget
# the scene must fit (scenec --target; empty: scenec's default, m0plus).
# SCENEC_FLAGS: more options (a target-specific variable: mk/firmware.mk's).
SCENEC      := $(BUILD)/scenec
SCENE_PROBE := $(BUILD)/scenes/work_probe.elf
# The .c and the .h are one grouped target (GNU make 4.3): whatever includes
# the header is rebuilt in the same run as the scene is recompiled.
define SCENEC_RULE
$(1) $(patsubst %.c,%.h,$(1)) &: firmware/scenes/$(2).scene $(SCENEC) $(if $(filter 1,$(6)),$(SCENE_PROBE))
	@mkdir -p $(dir $(1))
	$(Q)$(if $(filter 1,$(6)),tw=$$$$(tools/scenec/target_work.sh $(SCENE_PROBE) $$< $(subst x, ,$(3)) $(4)) || exit 2;) \
	$(SCENEC) --size $(3) --strip-rows $(4) $(if $(5),--id $(5)) $(if $(filter 1,$(6)),--target-work $$$$tw) $(if $(7),--target $(7)) $$(SCENEC_FLAGS) \
		-o $(1) $$< >$(patsubst %.c,%.log,$(1)) || { cat $(patsubst %.c,%.log,$(1)); exit 2; }
endef
scenec_rule = $(eval $(call SCENEC_RULE,$(strip $(1)),$(strip $(2)),$(strip $(3)),$(strip $(4)),$(strip $(5)),$(strip $(6)),$(strip $(7))))

# $(call scene_frac_rule,OUT.h,HEADERS[,MORE]): OUT.h defines NUM_FRAC as the
# smallest SCENE_<ID>_NUM_FRAC of the scenec headers HEADERS (MORE: other
# prerequisites). That is the coarsest format among those scenes, the one a
# program linking them all is compiled at: a finer one would trip a scene's
# #error, and a coarser one holds every range a finer one does.
define SCENE_FRAC_RULE
$(1): $(2) $(3)
	@mkdir -p $$(@D)
	$(Q)f=$$$$(sed -n 's/^#define SCENE_[A-Za-z0-9_]*_NUM_FRAC *\([0-9][0-9]*\)$$$$/\1/p' $(2) | sort -n | head -n 1); \
	[ -n "$$$$f" ] || { echo "$$@: no SCENE_<ID>_NUM_FRAC in $(2)" >&2; exit 2; }; \
	printf '/* %s: generated by the Makefile, the coarsest format among %s */\n#ifndef NUM_FRAC\n#define NUM_FRAC %s\n#endif\n' \
		"$$(@F)" "$(notdir $(2))" "$$$$f" >$$@
endef
scene_frac_rule = $(eval $(call SCENE_FRAC_RULE,$(strip $(1)),$(strip $(2)),$(strip $(3))))

# Programs built by `make`, tests run by `make test` (commands, one per
# word; each prints PASS/FAIL lines, see tests/support/run.sh), and bench steps.
PROGRAMS :=
TESTS    :=
TEST_DEPS :=
BENCH_DEPS :=

.PHONY: all run test firmware bench charts flash clean deps deps-test deps-firmware
# Keep intermediate objects (test objects built through pattern rules).
.SECONDARY:
all: programs

# The fragments in the order of their names, but for the firmware's: the
# board images (mk/firmware.mk) and the fragments that use their variables
# when they are read, in this order, where mk/firmware.mk's name puts it.
FW_FRAGMENTS := mk/firmware.mk mk/flasher.mk mk/rp2040sim.mk mk/bench-rp2040.mk
MK_FRAGMENTS := $(patsubst mk/firmware.mk,$(FW_FRAGMENTS),$(filter-out $(filter-out mk/firmware.mk,$(FW_FRAGMENTS)),\
                  $(sort $(wildcard mk/*.mk))))
include $(MK_FRAGMENTS)

$(foreach v,$(VARIANTS),$(foreach m,$(COMPILE_MODES),$(eval $(call COMPILE_RULES,$(v),$(m)))))
# (the rule of $(call core_lib,VARIANT,MODE), for every compile mode)
define CORE_LIB_RULE
$(call core_lib,$(1),$(2)): $(call obj,$(1),$(2),$(CORE_SRCS))
	@mkdir -p $$(@D)
	$(Q)rm -f $$@ && ar rcs $$@ $$^
endef
$(foreach v,$(VARIANTS),$(foreach m,$(filter-out none,$(COMPILE_MODES)),$(eval $(call CORE_LIB_RULE,$(v),$(m)))))

# The tests' C files find their shared headers (tests/support/) by name.
$(foreach v,$(VARIANTS),$(foreach m,$(COMPILE_MODES),$(eval $(BUILD)/$(v)/$(m)/tests/%.o: EXTRA_CFLAGS += -Itests/support)))

.PHONY: programs
programs: $(PROGRAMS)

# Distribution packages: installed when root or passwordless sudo, otherwise
# one line with the exact command to run. See tools/deps.sh.
# DEPS_SH: the installer (tests replace it).
DEPS_SH ?= tools/deps.sh
deps:
	$(Q)$(DEPS_SH) run
deps-test:
	$(Q)$(DEPS_SH) test
deps-firmware:
	$(Q)$(DEPS_SH) firmware

# What the tests need is built with one job per processor unless make was
# given -j; the tests then run TEST_JOBS at a time (tests/support/run.sh).
# The packages are installed first, then a second make reads the Makefile
# again: which libraries are found (WITH_GPIOD, WITH_SDL2) and so which tests
# run is decided after the install, the same on a fresh machine as on any
# later run. TEST_RUN: the runner (tests replace it).
TEST_JOBS ?= $(shell nproc 2>/dev/null || echo 1)
TEST_RUN  ?= tests/support/run.sh
test: deps-test
	$(Q)$(MAKE) --no-print-directory test-after-deps
.PHONY: test-after-deps
test-after-deps:
	$(Q)$(MAKE) --no-print-directory $(if $(filter -j%,$(MAKEFLAGS)),,-j$(TEST_JOBS)) $(TEST_DEPS) $(PROGRAMS)
	$(Q)TEST_JOBS=$(TEST_JOBS) $(TEST_RUN) $(TESTS)

clean:
	rm -rf $(BUILD) $(OUT)

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
