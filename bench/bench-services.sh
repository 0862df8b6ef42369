#!/usr/bin/env bash
# Service round trips per second (example_interfaces/AddTwoInts on loopback):
# sequential calls and 8 concurrent callers, Ada client -> Ada server
# (RCL.Services / RCL.Clients) vs Python client -> Python server (the
# cyclonedds peer following the same conventions). Prints a table and writes
# out/bench/services.csv. CALLS (default 2000) sets the calls per run.
set -uo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
calls=${CALLS:-2000}
csv=out/bench/services.csv
echo "implementation,mode,calls,tasks,errors,seconds,rate" > "$csv"

run() {  # run IMPL SERVER_CMD CLIENT_CMD...
   local impl=$1 server_cmd=$2
   shift 2
   $server_cmd > /dev/null 2>&1 &
   local spid=$!
   sleep 1
   for tasks in 1 8; do
      local line
      line=$("$@" "$calls" "$tasks" 2>&1 | grep '^calls=' | tail -1)
      if [ -z "$line" ]; then
         echo "bench-services: $impl client with $tasks task(s) gave no result" >&2
         continue
      fi
      local n e s r
      n=$(sed -n 's/.*calls= *\([0-9]*\).*/\1/p' <<< "$line")
      e=$(sed -n 's/.*errors= *\([0-9]*\).*/\1/p' <<< "$line")
      s=$(sed -n 's/.*seconds= *\([0-9.]*\).*/\1/p' <<< "$line")
      r=$(sed -n 's/.*rate= *\([0-9]*\).*/\1/p' <<< "$line")
      local mode=sequential
      [ "$tasks" -gt 1 ] && mode="concurrent"
      echo "$impl,$mode,$n,$tasks,$e,$s,$r" >> "$csv"
   done
   kill "$spid" 2>/dev/null
   sleep 0.5
   kill -9 "$spid" 2>/dev/null
   wait "$spid" 2>/dev/null
}

run ada "bin/bench_services server" bin/bench_services client
run python ".venv/bin/python bench/bench_services_peer.py server" \
   .venv/bin/python bench/bench_services_peer.py client

printf "%-8s %-11s %6s %6s %7s %10s\n" impl mode calls tasks errors "calls/s"
tail -n +2 "$csv" | while IFS=, read -r impl mode n t e s r; do
   printf "%-8s %-11s %6s %6s %7s %10s\n" "$impl" "$mode" "$n" "$t" "$e" "$r"
done
ada_seq=$(grep '^ada,sequential' "$csv" | cut -d, -f7)
py_seq=$(grep '^python,sequential' "$csv" | cut -d, -f7)
if [ -n "$ada_seq" ] && [ -n "$py_seq" ] && [ "$py_seq" -gt 0 ]; then
   echo "Ada / Python sequential: $(awk "BEGIN { printf \"%.2f\", $ada_seq / $py_seq }")x"
fi
echo "CSV: $csv"
