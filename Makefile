# hemiroll: the two commands a new user needs are `make play` and `make test`.
# Each installs what is missing (Debian packages, once), configures, builds
# and runs. Everything builds out of tree in build/ (Release).

BUILD     := build
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
OUT       := out
CMAKE_CFG := cmake --preset release -Wno-dev > /dev/null

.PHONY: play test build bench asan tsan fuzz deps peer-deps configure clean

deps:
	@tools/install-deps.sh

# The peer engines of tools/peers (issue 15): only the benchmark links them.
# A build configured before they were installed is configured again, so
# that peer_bench joins it.
peer-deps:
	@tools/install-deps.sh --peers
	@if [ -f $(BUILD)/build.ninja ] && ! grep -q peer_bench $(BUILD)/build.ninja; then $(CMAKE_CFG); fi

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
test: peer-deps build
	@ctest --test-dir $(BUILD) -j $(JOBS) --output-on-failure -LE heavy

# Ends with issue 32's figures against an earlier commit, both measured in
# this run (tools/bench-against.sh); BENCH_AGAINST=none leaves that out.
BENCH_AGAINST ?= HEAD~1
bench: peer-deps build
	@tools/run-benchmarks.sh $(BUILD)
	@if [ "$(BENCH_AGAINST)" != none ]; then tools/bench-against.sh $(BENCH_AGAINST) $(BUILD); fi

# Debug build with AddressSanitizer and UndefinedBehaviorSanitizer.
asan: deps
	@cmake --preset asan -Wno-dev > /dev/null
	@cmake --build build-asan -j $(JOBS)
	@ctest --test-dir build-asan -j $(JOBS) --output-on-failure -LE heavy

# ThreadSanitizer on the threaded parts: the servo loop and devices (the
# UDP bridge), the recorder's writer threads, the play session and window.
TSAN_TARGETS := haptics_tests haptics_devices_tests record_tests screens_tests screens_window_tests hemiroll hemiroll-haptic-client
tsan: deps
	@cmake --preset tsan -Wno-dev > /dev/null
	@cmake --build build-tsan -j $(JOBS) --target $(TSAN_TARGETS)
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$(CURDIR)/cmake/tsan.supp" ctest --test-dir build-tsan -j $(JOBS) --output-on-failure -LE heavy -L "haptics|record|screens"

# libFuzzer (Debian's clang) with ASan and UBSan on every parser and loader,
# a minute each (tests/fuzz; `make test` runs the same targets a few
# seconds each without libFuzzer).
fuzz: deps
	@tools/install-deps.sh --fuzz
	@cmake --preset fuzz -Wno-dev > /dev/null
	@cmake --build build-fuzz -j $(JOBS) --target fuzz_all
	@ctest --test-dir build-fuzz -j $(JOBS) --output-on-failure -L fuzz

clean:
	@rm -rf $(BUILD) build-asan build-tsan build-debug build-fuzz
