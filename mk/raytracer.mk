# SPDX-License-Identifier: MIT
# Ray tracer (part I of the book): its tests and measurements.
# See docs/raytracer.md. The renderer itself is part of CORE_SRCS (mk/core.mk).

# The tests load the repository's scene files through the parser
# (tests/support/scene_files.h); the reference digests are tests/data/book_digests.txt.

# test_raytracer_<mode>: one program per numeric mode (the core's symbols
# clash between modes), in both variants.
$(foreach v,$(VARIANTS),$(foreach m,$(NUM_MODES),$(call program,$(BUILD)/$(v)/tests/test_raytracer_$(m),\
    $(call obj,$(v),$(m),tests/unit/test_raytracer.c $(SCENE_SRCS)) $(call core_lib,$(v),$(m)),$(v))))

RT_TEST_BINS := $(foreach m,$(NUM_MODES),$(BUILD)/asan/tests/test_raytracer_$(m)) $(BUILD)/host/tests/test_raytracer_double
TEST_DEPS += $(RT_TEST_BINS)
# Unit and feature tests under ASan+UBSan in every mode; the 600x600 book
# digests in the optimised double build (12 full renders).
TESTS += $(BUILD)/asan/tests/test_raytracer_fixed:quick $(BUILD)/asan/tests/test_raytracer_float:quick \
         $(BUILD)/asan/tests/test_raytracer_double:quick $(BUILD)/host/tests/test_raytracer_double

.PHONY: test-raytracer
test-raytracer: $(RT_TEST_BINS) $(BUILD)/host/tests/test_raytracer_accuracy
	$(Q)tests/support/run.sh $(filter %raytracer_fixed:quick %raytracer_float:quick %raytracer_double:quick \
	    %test_raytracer_double %test_raytracer_accuracy,$(TESTS))

# Accuracy test: fixed and float against double in one program. Each mode's
# core + scene parser become one object exporting only rtacc_<mode>.
# Fixed point also at NUM_FRAC 17, the format of raytracer-01 ... 04.
RTACC_MODES := $(NUM_MODES) fixed17
$(foreach v,$(VARIANTS),$(foreach m,$(RTACC_MODES),$(eval \
    $(call obj,$(v),$(m),tests/support/rt_acc_api.c): EXTRA_CFLAGS += -DRTACC_NAME=rtacc_$(m))))
$(foreach v,$(VARIANTS),$(foreach m,$(RTACC_MODES),$(call bundle,$(BUILD)/$(v)/rtacc_$(m).o,\
    $(call obj,$(v),$(m),tests/support/rt_acc_api.c $(CORE_SRCS) $(SCENE_SRCS)),rtacc_$(m))))
$(foreach v,$(VARIANTS),$(call program,$(BUILD)/$(v)/tests/test_raytracer_accuracy,\
    $(call obj,$(v),none,tests/unit/test_raytracer_accuracy.c) $(foreach m,$(RTACC_MODES),$(BUILD)/$(v)/rtacc_$(m).o),$(v)))
TEST_DEPS += $(BUILD)/host/tests/test_raytracer_accuracy
# The big comparison runs optimised (30 renders, 15 of them 600x600).
TESTS += $(BUILD)/host/tests/test_raytracer_accuracy
# The real-time option's accuracy and ray counts (docs/raytracer.md).
TESTS += tests/system/test_rt_realtime.sh:$(BUILD)/host_sim

# `make bench`: raytracer-05 at 240x240 on the emulated Cortex-M0+ and M4F,
# fixed and float, plus each chapter-5 option (tools/bench/bench_raytracer.c;
# scenes as C data from scenec).
BENCH_RT_SCENES := $(BUILD)/scenes/book/raytracer-05.c $(BUILD)/scenes/book/raytracer-02.c \
                   $(BUILD)/scenes/bench/grid64.c
BENCH_RT_SRCS := tools/bench/bench_raytracer.c $(BENCH_RT_SCENES) $(CORE_SRCS)
# bench_rt_image(NAME,TARGET,MODE,FLAGS)
define BENCH_RT_IMAGE
$$(call bench_image,$(1),$(2),$(3),$(BENCH_RT_SRCS),-I$(BUILD)/scenes $(4))
$(BUILD)/bench/$(2)/$(3)/$(1).objs/tools/bench/bench_raytracer.o: $(BENCH_RT_SCENES)
endef
bench_rt_image = $(eval $(call BENCH_RT_IMAGE,$(1),$(2),$(3),$(4)))
$(foreach t,$(BENCH_TARGETS),$(foreach m,fixed float,\
  $(call bench_rt_image,raytracer,$(t),$(m))\
  $(eval BENCH_IMAGES += $(BUILD)/bench/$(t)/$(m)/raytracer.elf)))

# `make profile-raytracer`: instructions per function of raytracer-05
# (fixed, M0+, 60x60, one frame) from a qemu block trace (tools/bench/profile.py);
# `make profile-raytracer-adaptive`: the same at 120x120 with adaptive_subsample = 4;
# `make profile-raytracer-02`: raytracer-02 at 120x120.
$(call bench_rt_image,raytracer-prof,m0plus-qemu,fixed,-DBENCH_RT_QUICK -DBENCH_RT_SIZE=60)
$(call bench_rt_image,raytracer-prof-adaptive,m0plus-qemu,fixed,-DBENCH_RT_QUICK -DBENCH_RT_SIZE=120 -DBENCH_RT_ADAPT=4)
$(call bench_rt_image,raytracer-prof-02,m0plus-qemu,fixed,-DBENCH_RT_QUICK -DBENCH_RT_SIZE=120 -DBENCH_RT_PROFILE_02)
.PHONY: profile-raytracer profile-raytracer-adaptive profile-raytracer-02
profile-raytracer: $(BUILD)/bench/m0plus-qemu/fixed/raytracer-prof.elf
	$(Q)$(PYTHON) tools/bench/profile.py --top 30 $<
profile-raytracer-adaptive: $(BUILD)/bench/m0plus-qemu/fixed/raytracer-prof-adaptive.elf
	$(Q)$(PYTHON) tools/bench/profile.py --top 30 $<
profile-raytracer-02: $(BUILD)/bench/m0plus-qemu/fixed/raytracer-prof-02.elf
	$(Q)$(PYTHON) tools/bench/profile.py --top 30 $<

# The hand-written ARMv6-M part of a primary ray's lean sphere test
# (rt_prim_disc_v6m, firmware/core/rt/rt_prim_v6m.h) on the emulated
# Cortex-M0+ against its C (rt_prim_disc_c), at NUM_FRAC 16 and 20; it also
# prints both forms' instructions per call.
RT_V6M_SRCS := tests/unit/test_rt_v6m.c $(CORE_NUM_SRCS)
$(call bench_image,test_rt_v6m_q16,m0plus-qemu,fixed,$(RT_V6M_SRCS),-Itests/support -DNUM_FRAC=16)
$(call bench_image,test_rt_v6m_q20,m0plus-qemu,fixed,$(RT_V6M_SRCS),-Itests/support -DNUM_FRAC=20)
RT_V6M_IMAGES := $(BUILD)/bench/m0plus-qemu/fixed/test_rt_v6m_q16.elf $(BUILD)/bench/m0plus-qemu/fixed/test_rt_v6m_q20.elf
TEST_DEPS += $(RT_V6M_IMAGES)
TESTS     += tools/bench/run.py:--smoke:$(subst $(eval) ,:,$(RT_V6M_IMAGES))
