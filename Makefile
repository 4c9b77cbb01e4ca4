# Thin wrapper: the real build is CMake (see CMakePresets.json).
BUILD ?= build
JOBS ?= $(shell nproc)
SPT := $(BUILD)/cli/spt
# Unity builds (each target's sources compiled a batch at a time) take about two thirds of the
# time from a clean tree, which is every CI run; UNITY=OFF builds file by file.
UNITY ?= ON

.PHONY: all deps configure build demo test bench figures resources clean fuzz sanitize core-only deb deb-check

all: build

deps:
	@bash tools/install-deps.sh debian-packages.txt

configure: deps
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=$(UNITY) > /dev/null

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
FUZZ_TARGETS ?= spt_loader pose_file mesh_prepare query scene animated_import
fuzz: deps
	@CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPT_FUZZ=ON \
	  -DSPT_BUILD_BENCH=OFF -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all" > /dev/null
	@cmake --build $(FUZZ_BUILD) --target fuzzers -j $(JOBS)
	@bash tools/run-fuzzers.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# The whole suite built with AddressSanitizer and UndefinedBehaviorSanitizer in its own
# directory; any report fails the test (docs/testing.md). Leaks kept by Debian's GL, LLVM, X and
# font libraries are suppressed (tools/lsan-suppressions.txt). The Qt suites and the EGL backend's
# tests run without leak checking: Mesa's driver, loaded by them, unloads LLVM before the report,
# so its leaks cannot be told apart from ours; so do the Python module's, whose interpreter leaves
# its own objects allocated at exit (tests/python/CMakeLists.txt preloads the runtimes).
SANITIZE_BUILD ?= build-sanitize
SANITIZE_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
# -O1, not Release's -O3: GCC takes about twice as long to compile -O3 with the sanitizers.
SANITIZE_OPT ?= -O1
SANITIZE_TARGETS ?= all
SANITIZE_SKIP ?= _NOT_BUILT|^Install\.
SANITIZE_ONLY ?= .
# ctest labels to run (each GoogleTest binary's tests carry its name; the corpus replays `fuzz`).
SANITIZE_LABELS ?=
SANITIZE_NO_LEAKS := ^(editor|viewer|python)\.|egl
# intercept_tls_get_addr=0: GCC 12's runtime takes a dynamic TLS block (one of a library loaded
# with dlopen, such as Mesa's) that happens to start 16 bytes past a page boundary for one with a
# pre-2.25 glibc header, reads a range from the two words before it, and LeakSanitizer's tracer
# then dies at exit ("Tracer caught signal 11"), now and then, wherever the allocator put the
# block (google/sanitizers#1322). Without the interceptor dynamic TLS is not scanned for pointers;
# only Debian's GL libraries keep any there, and their allocations are suppressed anyway.
SANITIZE_ASAN := abort_on_error=1:intercept_tls_get_addr=0
SANITIZE_ENV := UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions=$(CURDIR)/tools/lsan-suppressions.txt:print_suppressions=0
sanitize: deps
	@cmake -S . -B $(SANITIZE_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=$(UNITY) -DSPT_BUILD_BENCH=OFF \
	  -DCMAKE_CXX_FLAGS="$(SANITIZE_FLAGS)" -DCMAKE_CXX_FLAGS_RELEASE="$(SANITIZE_OPT) -DNDEBUG" > /dev/null
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target $(SANITIZE_TARGETS)
	@cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=1:$(SANITIZE_ASAN) $(SANITIZE_ENV) \
	  ctest --output-on-failure -j $(JOBS) -R '$(SANITIZE_ONLY)' $(if $(SANITIZE_LABELS),-L '$(SANITIZE_LABELS)') \
	  -E '$(SANITIZE_SKIP)|$(SANITIZE_NO_LEAKS)'
	@if [ '$(SANITIZE_ONLY)' = '.' ] && [ -z '$(SANITIZE_LABELS)' ]; then cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=0:$(SANITIZE_ASAN) \
	  $(SANITIZE_ENV) ctest --output-on-failure -j $(JOBS) -R '$(SANITIZE_NO_LEAKS)' -E '$(SANITIZE_SKIP)'; fi

# The library and the commands that need no drawing, configured as a server without Qt or OpenGL
# would be (docs/library.md); ctest adds a check that nothing built links either.
CORE_BUILD ?= build-core
core-only: deps
	@cmake -S . -B $(CORE_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=$(UNITY) \
	  -DSPT_BUILD_EDITOR=OFF -DSPT_BUILD_RENDER=OFF -DSPT_BUILD_BENCH=OFF -DCMAKE_DISABLE_FIND_PACKAGE_Qt6=ON > /dev/null
	@cmake --build $(CORE_BUILD) -j $(JOBS)
	@cd $(CORE_BUILD) && ctest --output-on-failure -j $(JOBS)

# spt_VERSION_amd64.deb in $(BUILD) (docs/library.md); deb-check installs it with apt-get, runs it,
# builds examples/ against it and removes it again (CI runs it).
deb: build
	@cd $(BUILD) && cpack -G DEB
deb-check: build
	@bash tools/check-deb.sh $(BUILD)

bench: build
	@cmake --build $(BUILD) --target bench

# Every figure of docs/benchmarks.md, measured again into bench-out/ (a few minutes; a quiet machine).
figures: build
	@bash tools/bench-all.sh $(BUILD) bench-out

clean:
	rm -rf $(BUILD)
