#!/usr/bin/env bash
# The team mission with every robot a SANCTA agent of one configuration
# file (share/config/sim-team.xml) driving a robot of sancta-sim over ROS 2
# topics, one process per agent. When a quarter of the tasks are done, the
# process of robot r2 is killed (its host dies; sancta-sim stops the robot
# when its commands stop); the survivors re-plan and finish. Logs under
# out/demo-sim/. Options: METHOD (annealer|auctions), RATE (default 2),
# SIM_TIME (1|0).
set -uo pipefail
source "$(dirname "$0")/env.sh"
cd "$repo_root"
method="${METHOD:-annealer}"
rate="${RATE:-2}"
# SIM_TIME=1 (default): the agents run on the simulated time of /clock
# (sancta run --sim-time); SIM_TIME=0: on the wall clock.
sim_time=$([ "${SIM_TIME:-1}" = 1 ] && echo --sim-time)
out=out/demo-sim
mkdir -p "$out"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done; wait 2>/dev/null; }
trap cleanup EXIT

./bin/sancta-sim office --robot "r1 2.5 10 0" --robot "r2 6 10 0" --robot "r3 9.5 10 0" \
   --robot "r4 13 10 0" --rate "$rate" --cmd-timeout 0.5 --quiet > "$out/sim.log" 2>&1 &
pids+=($!)
for r in r1 r2 r3 r4; do
   ./bin/sancta run share/config/sim-team.xml --agent "$r" --set "method=$method" $sim_time \
      > "$out/$r.log" 2>&1 &
   pids+=($!)
   [ "$r" = r2 ] && r2_pid=$!
done
./bin/sancta run share/config/sim-team.xml --agent operator $sim_time > "$out/operator.log" 2>&1 &
op_pid=$!
pids+=($op_pid)
echo "demo-sim: sancta-sim (office, 4 robots, ${rate}x) + 5 agents of share/config/sim-team.xml"
killed=no
for _ in $(seq 1 1200); do
   sleep 0.5
   last=$(grep -o 'progress [0-9]*/[0-9]*[^"]*' "$out/operator.log" | tail -1)
   [ -n "$last" ] && [ "$last" != "${shown:-}" ] && { echo "demo-sim: $last"; shown=$last; }
   done_n=$(echo "$last" | sed -n 's/progress \([0-9]*\)\/.*/\1/p')
   if [ "$killed" = no ] && [ "${done_n:-0}" -ge 6 ]; then
      kill -9 "$r2_pid"; killed=yes
      echo "demo-sim: robot r2's agent killed (its host is gone)"
   fi
   kill -0 "$op_pid" 2>/dev/null || break
done
wait "$op_pid"
status=$?
grep -q "every task of the mission is done" "$out/operator.log" && echo "demo-sim: all done" \
   || { echo "demo-sim: mission NOT finished (see $out/)"; status=1; }
exit $status
