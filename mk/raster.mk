# SPDX-License-Identifier: MIT
# Rasterizer (firmware/core/raster/): tests and docs in docs/rasterizer.md.
#
# Test programs link the core sources of one numeric mode directly, plus
# the scene parser: they load the book's scene files (tests/support/scene_files.h).
# The cross-mode accuracy test links three per-mode bundles (core + parser
# + a small API), each keeping only its raster_api_<mode> symbol (the
# Makefile's bundle).

RASTER_TEST_SRCS := tools/scene/scene_parse.c tools/scene/scene_depth.c

$(foreach v,$(VARIANTS),$(foreach m,$(NUM_MODES),$(foreach p,test_raster_book test_raster,$(call program,\
    $(BUILD)/$(v)/tests/$(p)_$(m),$(call obj,$(v),$(m),tests/unit/$(p).c $(RASTER_TEST_SRCS)) $(call core_lib,$(v),$(m)),$(v)))))

$(foreach v,$(VARIANTS),$(foreach m,$(NUM_MODES),$(call bundle,$(BUILD)/$(v)/raster_api_$(m).o,\
    $(call obj,$(v),$(m),$(CORE_SRCS) $(RASTER_TEST_SRCS) tests/support/raster_api.c),raster_api_$(m))))
$(foreach v,$(VARIANTS),$(call program,$(BUILD)/$(v)/tests/test_raster_modes,\
    $(call obj,$(v),none,tests/unit/test_raster_modes.c) $(foreach m,$(NUM_MODES),$(BUILD)/$(v)/raster_api_$(m).o),$(v)))

# The fast path's bilinear texels and blend (mipmap.c, raster_span_lib.h) against their formula.
$(call program,$(BUILD)/asan/tests/test_span_bilinear,$(call obj,asan,fixed,tests/unit/test_span_bilinear.c) $(call core_lib,asan,fixed),asan)

RASTER_TESTS := $(BUILD)/asan/tests/test_span_bilinear \
                $(BUILD)/asan/tests/test_raster_book_double:$(BUILD) \
                $(BUILD)/asan/tests/test_raster_fixed $(BUILD)/asan/tests/test_raster_float \
                $(BUILD)/asan/tests/test_raster_double \
                $(BUILD)/host/tests/test_raster_modes
TESTS += $(RASTER_TESTS)
TEST_NEEDS_test_raster_book_double :=   # (its argument is a directory for its files)
TEST_DEPS += $(foreach t,$(RASTER_TESTS),$(firstword $(subst :, ,$(t))))

# The book's scene files through the parser and core_api (three modes).
$(foreach v,$(VARIANTS),$(call program,$(BUILD)/$(v)/tests/test_raster_scenes,\
    $(call obj,$(v),none,tests/unit/test_raster_scenes.c) $(call core_bundles,$(v)),$(v)))
TESTS += $(BUILD)/host/tests/test_raster_scenes
TEST_DEPS += $(BUILD)/host/tests/test_raster_scenes

# `make bench`: raster-11 and raster-13 at 240x240 on the emulated Cortex-M0+
# and M4F, fixed and float, book path and default path, per frame and per
# drawn pixel (tools/bench/bench_raster.c; scenes as C data from scenec).
BENCH_RAS_SCENES := $(BUILD)/scenes/book/raster-11.c $(BUILD)/scenes/book/raster-13.c
BENCH_RAS_SRCS   := tools/bench/bench_raster.c $(BENCH_RAS_SCENES) $(CORE_SRCS)
$(foreach t,$(BENCH_TARGETS),$(foreach m,fixed float,\
  $(call bench_image,raster,$(t),$(m),$(BENCH_RAS_SRCS),-I$(BUILD)/scenes)\
  $(eval BENCH_IMAGES += $(BUILD)/bench/$(t)/$(m)/raster.elf)\
  $(eval $(BUILD)/bench/$(t)/$(m)/raster.objs/tools/bench/bench_raster.o: $(BENCH_RAS_SCENES))))

# Chapter 15 (normal maps, environment maps, shadow maps, shadow volumes)
# through the parser and core_api in three modes, and the demo scenes.
$(foreach v,$(VARIANTS),$(call program,$(BUILD)/$(v)/tests/test_raster_ch15,\
    $(call obj,$(v),none,tests/unit/test_raster_ch15.c) $(call core_bundles,$(v)),$(v)))
TESTS += $(BUILD)/host/tests/test_raster_ch15
TEST_DEPS += $(BUILD)/host/tests/test_raster_ch15

# The benchmark meshes (firmware/scenes/bench/knot-*.obj) are what
# tools/bench/gen_mesh.py makes.
TESTS += tests/system/test_meshes.sh

# `make bench`: the benchmark scenes of firmware/scenes/bench/ (the
# small3dlib cube workload: textured, Gouraud, flat; an empty frame; the
# trefoil-knot meshes of 4,096 and 16,384 triangles), each image built at the
# scene's own number format (tools/scenec's NUM_FRAC) for the emulated
# Cortex-M0+ and M4F, fixed and float; rows per frame, per drawn pixel, per
# triangle (the meshes) and for render_init (tools/bench/bench_scene.c).
BENCH_SCENE_NAMES := $(patsubst firmware/scenes/bench/%.scene,%,$(sort $(wildcard firmware/scenes/bench/*.scene)))
bench_scene_frac = $(shell sed -n 's/^scenec-summary .* num_frac=\([0-9]*\) .*/\1/p' $(BUILD)/scenes/bench/$(1).log 2>/dev/null)
define BENCH_SCENE_IMAGE
$$(call bench_image,scene-$(1),$(2),$(3),tools/bench/bench_scene.c $(BUILD)/scenes/bench/$(1).c $(CORE_SRCS),\
  -I$(BUILD)/scenes -DBENCH_SCENE_H='"bench/$(1).h"' -DBENCH_SCENE=scene_bench_$(subst -,_,$(1)) \
  -DBENCH_WHAT='"scene:bench/$(1)"' $$$$(if $$$$(filter fixed,$(3)),-DNUM_FRAC=$$$$(call bench_scene_frac,$(1))))
BENCH_IMAGES += $(BUILD)/bench/$(2)/$(3)/scene-$(1).elf
# every object waits for the scene's C file: its log gives the NUM_FRAC
$(patsubst %.c,$(BUILD)/bench/$(2)/$(3)/scene-$(1).objs/%.o,tools/bench/bench_scene.c $(BENCH_RUNTIME) $(CORE_SRCS)): \
  $(BUILD)/scenes/bench/$(1).c
endef
$(foreach n,$(BENCH_SCENE_NAMES),$(foreach t,$(BENCH_TARGETS),$(foreach m,fixed float,\
  $(eval $(call BENCH_SCENE_IMAGE,$(n),$(t),$(m))))))

# The same images measuring the scene as written only (no method variants):
# $(BUILD)/bench/TARGET/MODE/scene-NAME-default.elf, not part of `make bench`;
# quick to run with tools/bench/run.py and to profile. `make profile-mesh`:
# instructions per function of bench/knot-4k-flat and knot-4k-gouraud (M0+,
# fixed, its 10 frames measured twice) from a qemu block trace (tools/bench/profile.py).
define BENCH_SCENE_DEFAULT_IMAGE
$$(call bench_image,scene-$(1)-default,$(2),$(3),tools/bench/bench_scene.c $(BUILD)/scenes/bench/$(1).c $(CORE_SRCS),\
  -I$(BUILD)/scenes -DBENCH_SCENE_H='"bench/$(1).h"' -DBENCH_SCENE=scene_bench_$(subst -,_,$(1)) -DBENCH_DEFAULT_ONLY \
  -DBENCH_WHAT='"scene:bench/$(1)"' $$$$(if $$$$(filter fixed,$(3)),-DNUM_FRAC=$$$$(call bench_scene_frac,$(1))))
$(patsubst %.c,$(BUILD)/bench/$(2)/$(3)/scene-$(1)-default.objs/%.o,tools/bench/bench_scene.c $(BENCH_RUNTIME) $(CORE_SRCS)): \
  $(BUILD)/scenes/bench/$(1).c
endef
$(foreach n,$(BENCH_SCENE_NAMES),$(foreach t,$(BENCH_TARGETS),$(foreach m,fixed float,\
  $(eval $(call BENCH_SCENE_DEFAULT_IMAGE,$(n),$(t),$(m))))))
.PHONY: profile-mesh
profile-mesh: $(foreach n,knot-4k-flat knot-4k-gouraud,$(BUILD)/bench/m0plus-qemu/fixed/scene-$(n)-default.elf)
	$(Q)for f in $^; do echo "$$f"; $(PYTHON) tools/bench/profile.py --top 30 $$f || exit 1; done

# The hand-written ARMv6-M projection of a run of points (ras_div_subs) on
# the emulated Cortex-M0+ against one ras_div_sub per point, at NUM_FRAC 16
# and 20 (its two forms of the rounding half); it also prints both forms'
# instructions per point.
RAS_V6M_SRCS := tests/unit/test_raster_v6m.c firmware/core/raster/raster_num.c $(CORE_NUM_SRCS)
$(call bench_image,test_raster_v6m_q16,m0plus-qemu,fixed,$(RAS_V6M_SRCS),-Itests/support -DNUM_FRAC=16)
$(call bench_image,test_raster_v6m_q20,m0plus-qemu,fixed,$(RAS_V6M_SRCS),-Itests/support -DNUM_FRAC=20)
RAS_V6M_IMAGES := $(BUILD)/bench/m0plus-qemu/fixed/test_raster_v6m_q16.elf $(BUILD)/bench/m0plus-qemu/fixed/test_raster_v6m_q20.elf
TEST_DEPS += $(RAS_V6M_IMAGES)
TESTS     += tools/bench/run.py:--smoke:$(subst $(eval) ,:,$(RAS_V6M_IMAGES))
