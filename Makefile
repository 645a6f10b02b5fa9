# mdr: the two commands of the README are `make demo` and `make test`.
BUILD_DIR := build
PYTHON := /usr/bin/python3
JOBS ?= $(shell nproc)

.PHONY: deps configure build test sanitize demo bench figures compare clean

deps:
	@scripts/install-deps

configure: deps
	@cmake --preset release >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	@ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

# The C++ tests, the command-line suites and the fuzzer again, built with AddressSanitizer and
# UndefinedBehaviorSanitizer (CMakePresets.json: sanitize). CI runs it after `make test`.
sanitize: deps
	@cmake --preset sanitize >/dev/null
	@cmake --build build-sanitize -j $(JOBS)
	@ctest --test-dir build-sanitize --output-on-failure -j $(JOBS)

# The demo builds only what it runs: the command line and the Python module for the figures.
demo: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target mdr _mdr
	@$(BUILD_DIR)/bin/mdr run examples/default.toml --out out/demo
	@PYTHONPATH=$(BUILD_DIR)/python MPLBACKEND=Agg $(PYTHON) -m mdr plot out/demo

figures: build
	@scripts/figures

bench: build
	@$(BUILD_DIR)/bin/mdr_bench --benchmark_counters_tabular=true

# Byte identity of every example and fuzz-corpus output against a binary kept from before a change
# (docs/extending.md): make compare OLD=/tmp/mdr-old
compare:
	@test -n "$(OLD)" || { echo "make compare: give OLD=path/to/the/old/mdr" >&2; exit 2; }
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target mdr
	@$(PYTHON) tests/support/compare_outputs.py $(OLD) $(BUILD_DIR)/bin/mdr

clean:
	@rm -rf $(BUILD_DIR) build-dev build-sanitize out
