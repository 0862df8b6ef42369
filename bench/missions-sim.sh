#!/usr/bin/env bash
# Team missions in the simulator at scale (issue 19; run by bench-missions.sh): 4 / 10 / 20 robots with
# 24 / 100 / 200 tasks (office-team.xml, campus-100.xml, campus-200.xml), each
# run by `sancta team` (simulator in-process, every robot a team agent with
# its own DDS node) at 25x with one robot killed at a quarter of the tasks
# and another cut off from the team for CUT seconds (wall, default 2) at half
# of them: makespan (simulated), re-planning time after the loss (wall,
# lease 0.5 s included), tasks done twice, and the time from the heal until
# every replica holds the newest entry (as of the heal) of every key (wall).
# Then, when run as root, the partition test across network namespaces
# (tests/netns/team-netns.sh: one robot's link down 10 s; identical replicas
# = convergence). Uses the binaries in bin/ as built (release with `make
# bench`), or SANCTA=path/to/sancta. SIZES="4:24 10:100" limits the sizes;
# LIMIT=S is each run's wall-clock limit (default 600). Writes
# out/bench/missions-sim.csv.
set -uo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
csv=out/bench/missions-sim.csv
echo "robots,tasks,mission,wall_s,all_done,makespan_s,replanned,replan_wall_s,duplicates,converged,converge_wall_s,converge_keys" > "$csv"
printf "%-7s %-6s %-18s %8s %9s %11s %15s %4s %16s\n" robots tasks mission "wall s" "all done" \
   "makespan s" "re-plan wall s" dup "converge s/keys"
for size in ${SIZES:-4:24 10:100 20:200}; do
   robots=${size%%:*}; tasks=${size##*:}
   case "$size" in
      4:24) mission=share/missions/office-team.xml ;;
      *) mission=share/missions/campus-$tasks.xml
         [ -f "$mission" ] || python3 share/missions/make_campus.py "$robots" "$tasks" > "$mission" ;;
   esac
   out=out/bench/missions-sim-$robots
   rm -rf "$out"
   start=$(date +%s.%N)
   timeout -s KILL "${LIMIT:-600}" "${SANCTA:-./bin/sancta}" team "$mission" --rate 25 --quiet \
      --cut-for "${CUT:-2}" --out "$out" > "$out.log" 2>&1
   wall=$(echo "$(date +%s.%N) - $start" | bc)
   if [ -f "$out/summary.json" ]; then
      row=$(python3 -c "
import json; d = json.load(open('$out/summary.json'))
print(d['all_done'], d['makespan_s'], d['replanned'], round(d['replan_wall_s'], 2), d['duplicates'],
      d['converged'], round(d['converge_wall_s'], 2), d['converge_keys'])")
   else
      row="False - - - - False - -"
   fi
   read -r done makespan replanned replan dup conv conv_s keys <<< "$row"
   [ "$conv" = True ] && converge="$conv_s/$keys" || converge="no"
   printf "%-7s %-6s %-18s %8.1f %9s %11s %15s %4s %16s\n" "$robots" "$tasks" \
      "$(basename "$mission")" "$wall" "$done" "$makespan" "$replan" "$dup" "$converge"
   echo "$robots,$tasks,$(basename "$mission"),$wall,$done,$makespan,$replanned,$replan,$dup,$conv,$conv_s,$keys" >> "$csv"
done
if [ "$(id -u)" -eq 0 ] && [ -z "${NO_NETNS:-}" ]; then
   echo "partition of 10 s and heal (3 robots, 24 tasks; tests/netns/team-netns.sh):"
   RUNS=${NETNS_RUNS:-3} bash tests/netns/team-netns.sh | grep -E "^ok: (tasks done twice|run)|^replicas|PASS|FAIL"
fi
