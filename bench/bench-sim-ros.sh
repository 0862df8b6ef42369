#!/usr/bin/env bash
# sancta-sim on ROS 2: real-time factor of the whole program (stepping,
# message building, CDR, DDS writes of odom 20 Hz, scan 10 Hz with 360
# beams, ground truth 10 Hz, /clock every step) for 1, 10, 50 and 100 robots
# in the arena, as fast as possible, on one core, nobody subscribed
# (loopback, this run's domain). Release build first. SIM_ROS_SECONDS
# (simulated seconds per run, default 30) shortens it.
# Writes out/bench/sim-ros.csv.
set -euo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
rm -f bin/sancta-sim  # may be a debug build from build_all.gpr: relink in release
gprbuild -P programs/programs.gpr -XBUILD_MODE=release -p -j2 -q sancta_sim.adb 2>&1 \
   | grep -v "no sources of language" || true
seconds=${SIM_ROS_SECONDS:-30}
csv=out/bench/sim-ros.csv
echo "robots,sim_seconds,wall_seconds,real_time_factor" > "$csv"
printf '%-8s %-12s %-12s %-10s\n' robots "sim s" "wall s" "RTF"
for n in 1 10 50 100; do
   list=$(mktemp)
   for ((i = 0; i < n; i++)); do
      # A 10 x 10 grid of starts 1.8 m apart, facing alternate ways.
      echo "r$i $((2 + (i % 10) * 18 / 10)).$(((i % 10) * 18 % 10)) $((2 + (i / 10) * 18 / 10)).$(((i / 10) * 18 % 10)) $((i % 2 * 3))" >> "$list"
   done
   out=$(taskset -c 0 ./bin/sancta-sim arena --robots "$list" --as-fast-as-possible \
         --duration "$seconds" --quiet | tail -1)
   rm -f "$list"
   wall=$(echo "$out" | sed -n 's/.* after \([0-9.]*\) s of wall time.*/\1/p')
   rtf=$(echo "$out" | sed -n 's/.*real-time factor \([0-9.]*\)).*/\1/p')
   printf '%-8s %-12s %-12s %-10s\n' "$n" "$seconds" "$wall" "$rtf"
   echo "$n,$seconds,$wall,$rtf" >> "$csv"
done
echo "written: $csv"
