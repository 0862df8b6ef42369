# Build, run, test and benchmark SANCTA for ROS 2.
#   make run    build everything and run the main job on its embedded default
#   make view   the same, watched live in a window (sancta-view)
#   make test   build everything and run every test suite
#   make bench  build in release mode and run the benchmarks
# Every target installs what it lacks first (Debian packages, Python venv).

BUILD_MODE ?= debug
GPRBUILD    = gprbuild -P build_all.gpr -p -j0 -XBUILD_MODE=$(BUILD_MODE)

.PHONY: all deps bench-deps build run view test bench clean

all: build

deps:
	@scripts/install-deps.sh

bench-deps:
	@scripts/install-deps.sh --bench

# Debug and release share bin/: executables of the other mode are removed
# first so that a mode switch always relinks (gprbuild would keep them).
build: deps
	@if [ -f bin/.build-mode ] && [ "$$(cat bin/.build-mode)" != "$(BUILD_MODE)" ]; then \
	   find bin -maxdepth 1 -type f -delete; fi
	@$(GPRBUILD)
	@echo "$(BUILD_MODE)" > bin/.build-mode

run: build
	@scripts/demo.sh

# The demo with its live view (sancta-view) in a window; without a display
# the demo runs as for "run".
view: build
	@scripts/demo.sh --view

test: build
	@scripts/run-tests.sh

bench: bench-deps
	@$(MAKE) --no-print-directory build BUILD_MODE=release
	@bench/run-all.sh

clean:
	@gprclean -P build_all.gpr -q -r 2>/dev/null || true
	@rm -rf obj lib bin
