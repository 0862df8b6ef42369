#!/usr/bin/env bash
# Team missions benchmark (see bench/src/bench_missions.adb): makespan and
# total distance of the annealer, auctions and greedy on the same random
# missions (10, 50, 200 tasks; 4 and 10 robots); time to re-plan after a
# robot loss over DDS (loopback); team database convergence time with 2, 5
# and 10 nodes; then bench/missions-sim.sh (4 / 10 / 20 robots with 24 / 100 /
# 200 tasks in the simulator, partition and heal). Builds the bench in release mode first. "--quick" for a
# short look. Writes out/bench/missions.csv and out/bench/missions.json.
set -euo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
rm -f bin/bench_missions  # may be a debug build from build_all.gpr: relink
gprbuild -P bench/bench.gpr -XBUILD_MODE=release -p -j2 -q 2>&1 | grep -v "no sources of language" || true
./bin/bench_missions "$@"
# In the simulator at scale: 4 / 10 / 20 robots with 24 / 100 / 200 tasks,
# re-planning after a loss, convergence after a partition heals.
if [ "${1:-}" != "--quick" ]; then
   bench/missions-sim.sh
fi
