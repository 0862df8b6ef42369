#!/usr/bin/env bash
# Simulator benchmark (see bench/src/bench_sim.adb): real-time factor for
# 1, 10, 50 and 100 robots (360-beam lasers at 10 Hz, odometry at 20 Hz,
# one core), then scan-matching time per scan and error. Builds the bench
# in release mode first. Optional: SIM_BENCH_SCALE=0.2 for a quick look.
# Writes out/bench/sim.csv and out/bench/sim-icp.csv.
set -euo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
rm -f bin/bench_sim  # may be a debug build from build_all.gpr: relink
gprbuild -P bench/bench.gpr -XBUILD_MODE=release -p -j2 -q 2>&1 | grep -v "no sources of language" || true
taskset -c 0 ./bin/bench_sim share/worlds/office.yaml "${SIM_BENCH_SCALE:-1.0}"
