# Build, run, test and benchmark SANCTA for ROS 2.
#   make run    build everything and run the main job on its embedded default
#   make view   the same, watched live in a window (sancta-view)
#   make test   build everything and run every test suite
#   make bench  build in release mode and run the benchmarks
# Every target installs what it lacks first (Debian packages, Python venv).

BUILD_MODE ?= debug
GPRBUILD    = gprbuild -P build_all.gpr -p -j0 -XBUILD_MODE=$(BUILD_MODE)

.PHONY: all deps bench-deps generate build run view test bench clean interfaces

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
	@$(MAKE) --no-print-directory generate
	@$(GPRBUILD)
	@echo "$(BUILD_MODE)" > bin/.build-mode

# The generated message types (never committed): bin/rosidl_generate is
# built, then writes ROSIDL.Static.* for the bundled interfaces (library
# ros2/rclada_messages.gpr) and for the test interfaces (tests.gpr);
# unchanged files are left alone, so only what changed recompiles.
generate:
	@gprbuild -P ros2/generator/rosidl_generate.gpr -p -j0 -q -XBUILD_MODE=$(BUILD_MODE)
	@bin/rosidl_generate -o obj/generated/interfaces \
	   --registry ROSIDL.Static.Bundled_Types share/ros2_interfaces
	@bin/rosidl_generate -o obj/generated/tests --registry ROSIDL.Static.Test_Types \
	   tests/interfaces tests/data/user_interfaces

# A user's interface packages (a folder holding <pkg>/msg, <pkg>/srv,
# <pkg>/action) as an Ada library: make interfaces FROM=my_interfaces
# [TO=obj/generated/user] writes the packages and TO/user_interfaces.gpr,
# and builds it; a program then does with "TO/user_interfaces.gpr".
TO ?= obj/generated/user
interfaces: generate
	@test -n "$(FROM)" || { echo "usage: make interfaces FROM=folder [TO=folder]"; exit 2; }
	@bin/rosidl_generate -o $(TO) --project User_Interfaces $(FROM)
	@gprbuild -P $(TO)/user_interfaces.gpr -p -j0 -q -XBUILD_MODE=$(BUILD_MODE)

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
