# Thin wrapper: the real build is CMake (see CMakePresets.json).
BUILD ?= build
JOBS ?= $(shell nproc)
SPT := $(BUILD)/cli/spt

.PHONY: all deps configure build demo test bench resources clean

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

bench: build
	@cmake --build $(BUILD) --target bench

clean:
	rm -rf $(BUILD)
