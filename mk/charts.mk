# `make charts`: speed-vs-accuracy and stability charts (tools/charts/charts.py,
# matplotlib from the distribution). Uses build/bench/results.jsonl from
# `make bench`, running it first when it is missing.
CHARTS_PY ?= $(if $(wildcard /usr/bin/python3),/usr/bin/python3,$(PYTHON))

charts: $(BUILD)/host_sim
	$(Q)tools/deps.sh charts
	$(Q)[ -f $(BUILD)/bench/results.jsonl ] || $(MAKE) --no-print-directory bench
	$(Q)$(CHARTS_PY) tools/charts/charts.py --results $(BUILD)/bench/results.jsonl \
		--host-sim $(BUILD)/host_sim --out $(OUT)/charts

TESTS += tests/test_stability.py:$(BUILD)/host_sim

# Accuracy fields of the scene measurements (contract: psnr, ssim, max_err,
# pct_diff against the double build), added once every bench step has run.
.PHONY: bench-accuracy
bench-accuracy: bench-qemu bench-rp2040 $(BUILD)/host_sim
	$(Q)$(PYTHON) tools/bench/accuracy.py $(BUILD)/bench/results.jsonl $(BUILD)/host_sim
bench: bench-accuracy
