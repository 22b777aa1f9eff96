# hemiroll: the two commands a new user needs are `make play` and `make test`.
# Each installs what is missing (Debian packages, once), configures, builds
# and runs. Everything builds out of tree in build/ (Release).

BUILD     := build
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
OUT       := out
CMAKE_CFG := cmake --preset release -Wno-dev > /dev/null

.PHONY: play test build bench asan deps configure clean

deps:
	@tools/install-deps.sh

$(BUILD)/build.ninja: CMakeLists.txt CMakePresets.json | deps
	@$(CMAKE_CFG)

configure: deps $(BUILD)/build.ninja

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# `make play` opens the game window on the title screen. Without a display
# hemiroll says how to run headless and exits with 2.
play: build
	@$(BUILD)/hemiroll play

# The fast suite; `ctest --test-dir build -L heavy` runs the heavy variants.
test: build
	@ctest --test-dir $(BUILD) -j $(JOBS) --output-on-failure -LE heavy

bench: build
	@tools/run-benchmarks.sh $(BUILD)

# Debug build with AddressSanitizer and UndefinedBehaviorSanitizer.
asan: deps
	@cmake --preset asan -Wno-dev > /dev/null
	@cmake --build build-asan -j $(JOBS)
	@ctest --test-dir build-asan -j $(JOBS) --output-on-failure -LE heavy

clean:
	@rm -rf $(BUILD) build-asan build-debug
