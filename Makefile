# Thin wrapper: the real build is CMake (see CMakePresets.json).
BUILD ?= build
JOBS ?= $(shell nproc)
SPT := $(BUILD)/cli/spt

.PHONY: all deps configure build demo test bench resources clean fuzz sanitize

all: build

deps:
	@bash tools/install-deps.sh debian-packages.txt

configure: deps
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@bash tools/demo.sh $(BUILD)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Opt-in: each libFuzzer target for FUZZ_SECONDS, built with clang and ASan/UBSan in its own
# directory (docs/fuzzing.md).
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= spt_loader pose_file mesh_prepare query scene
fuzz: deps
	@CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPT_FUZZ=ON \
	  -DSPT_BUILD_BENCH=OFF -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all" > /dev/null
	@cmake --build $(FUZZ_BUILD) --target fuzzers -j $(JOBS)
	@bash tools/run-fuzzers.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# The core and command-line suites built with AddressSanitizer and UndefinedBehaviorSanitizer
# in their own directory; any report fails the test. Render, plot and editor tests (Mesa, Qt)
# are left out: docs/testing.md says why.
SANITIZE_BUILD ?= build-sanitize
SANITIZE_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
SANITIZE_TARGETS := spt mesh_tests sampling_tests tree_tests geometry_tests query_tests query_alloc_tests io_tests \
  convert_tests hard_tests hard_extreme_tests cli_tests scene_tests selection_tests fuzzers spt-make-resources spt-make-scenes
SANITIZE_SKIP := _NOT_BUILT|^Install\.|^editor\.|^render\.
SANITIZE_ONLY := .
sanitize: deps
	@cmake -S . -B $(SANITIZE_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DSPT_BUILD_BENCH=OFF \
	  -DCMAKE_CXX_FLAGS="$(SANITIZE_FLAGS)" > /dev/null
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target $(SANITIZE_TARGETS)
	@cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --output-on-failure -j $(JOBS) -R '$(SANITIZE_ONLY)' -E '$(SANITIZE_SKIP)'

bench: build
	@cmake --build $(BUILD) --target bench

clean:
	rm -rf $(BUILD)
