#!/usr/bin/env bash
# Benchmark of the component runtime:
#  * lateness of a 100 Hz periodic component run by the SANCTA scheduler task
#    (median, p99, max), measured in the same run as cyclictest (rt-tests)
#    at the same 10 ms interval, the limit the machine allows;
#  * local database puts/s with 0, 1 and 10 listeners.
# Both sides run with the default (non real-time) scheduling policy, like
# a user's "sancta run". BENCH_SECONDS (default 10) sets the duration.
# Writes out/bench/runtime.csv and out/bench/runtime.json.
set -uo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
seconds=${BENCH_SECONDS:-10}
bench=bin/bench_runtime
if [ ! -x "$bench" ]; then
   echo "bench-runtime: $bench is missing: build first (make bench)" >&2
   exit 1
fi

cyc_out=out/bench/cyclictest.txt
have_cyclictest=0
if command -v cyclictest >/dev/null 2>&1; then
   have_cyclictest=1
   # One thread, 10 ms interval (100 Hz), histogram in microseconds.
   cyclictest -q -t1 -i10000 -D"${seconds}" -h20000 >"$cyc_out" 2>&1 &
   cyc_pid=$!
else
   echo "bench-runtime: cyclictest not found (scripts/install-deps.sh --bench installs rt-tests)"
fi

"$bench" --seconds "$seconds" --csv out/bench/runtime-sancta.csv >out/bench/runtime-sancta.txt
status=$?
[ "$have_cyclictest" = 1 ] && wait "$cyc_pid"
if [ $status -ne 0 ]; then
   cat out/bench/runtime-sancta.txt
   echo "bench-runtime: bench_runtime failed ($status)" >&2
   exit 1
fi

value() { awk -F, -v m="$1" '$1 == m { print $2 }' out/bench/runtime-sancta.csv; }

cyc_median=""; cyc_p99=""; cyc_max=""
if [ "$have_cyclictest" = 1 ]; then
   # Histogram lines "LATENCY_US COUNT"; median and p99 from the cumulative
   # counts; max from the summary (covers histogram overflows too).
   read -r cyc_median cyc_p99 < <(awk '
      /^[0-9]+ [0-9]+$/ { lat[n] = $1 + 0; cnt[n] = $2 + 0; total += $2; n++ }
      END {
         if (total == 0) { print "nan nan"; exit }
         acc = 0; med = ""; p99 = ""
         for (i = 0; i < n; i++) {
            acc += cnt[i]
            if (med == "" && acc >= total * 0.5) med = lat[i]
            if (p99 == "" && acc >= total * 0.99) p99 = lat[i]
         }
         print med, p99
      }' "$cyc_out")
   cyc_max=$(sed -n 's/^# Max Latencies: *0*\([0-9]\+\).*/\1/p' "$cyc_out" | head -1)
   [ -z "$cyc_max" ] && cyc_max=0
fi

printf '\n== runtime benchmark (%s s, 100 Hz)\n' "$seconds"
printf '%-34s %12s %12s %12s\n' "periodic lateness (us)" median p99 max
printf '%-34s %12s %12s %12s\n' "sancta scheduler task" \
   "$(value sancta_lateness_median_us)" "$(value sancta_lateness_p99_us)" \
   "$(value sancta_lateness_max_us)"
if [ "$have_cyclictest" = 1 ]; then
   printf '%-34s %12s %12s %12s\n' "cyclictest (same run)" "$cyc_median" "$cyc_p99" "$cyc_max"
fi
printf '%-34s %12s\n' "database puts/s" ""
for l in 0 1 10; do
   printf '%-34s %12s\n' "  $l listener(s)" "$(value db_puts_per_s_${l}_listeners)"
done

{
   echo "metric,value"
   tail -n +2 out/bench/runtime-sancta.csv
   if [ "$have_cyclictest" = 1 ]; then
      echo "cyclictest_latency_median_us,$cyc_median"
      echo "cyclictest_latency_p99_us,$cyc_p99"
      echo "cyclictest_latency_max_us,$cyc_max"
   fi
} >out/bench/runtime.csv
awk -F, 'NR > 1 { printf "%s  \"%s\": %s", (n++ ? ",\n" : "{\n"), $1, $2 } END { print "\n}" }' \
   out/bench/runtime.csv >out/bench/runtime.json
echo "wrote out/bench/runtime.csv and out/bench/runtime.json"
