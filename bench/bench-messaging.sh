#!/usr/bin/env bash
# Messaging benchmark: ping-pong round trip (median, p99) and one-way
# throughput of std_msgs/UInt8MultiArray with 64 B, 4 KiB and 256 KiB of data,
# reliable, loopback only, between two processes of the same implementation:
#   C       bench/messaging_c.c directly on Cyclone DDS, idlc-generated type
#           (the limit; generated here under out/, never committed)
#   Ada     bin/bench_messaging (RCL dynamic API: ROSIDL.Dynamic + ROSIDL.CDR)
#   Ada-typed bin/bench_messaging --typed (generated record and codec,
#           RCL.Nodes.Typed: encoded into / decoded out of the DDS sample)
#   Ada-raw bin/bench_messaging --raw (RCL raw bytes: the transport alone)
#   Python  bench/messaging_py.py (cyclonedds Python package)
# Ping-pong uses the ROS 2 default QoS (reliable, keep last 10); throughput
# keep-all so that no sample is lost. Prints a table and the Ada/C ratios
# (targets: median RTT <= 1.25x C, throughput >= 0.8x C) and writes
# out/bench/messaging.csv and .json.
# Throughput is the best of BENCH_REPEAT runs (default 3) of BENCH_SECONDS
# (default 1) each: the machine is shared, the best run is the least
# disturbed. BENCH_QUICK=1: fewer round trips, one throughput run.
# BENCH_IMPLS="C Ada-typed": only these implementations (default: all).
# Ada-typed's RTT target at 64 B is 1.1x C (issue 12).
set -uo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
out=out/bench
build=$out/messaging_c
mkdir -p "$out" "$build"

quick=${BENCH_QUICK:-0}
seconds=${BENCH_SECONDS:-1}
repeat=${BENCH_REPEAT:-3}
[ "$quick" = 1 ] && repeat=1
sizes=(64 4096 262144)

echo "bench-messaging: building (Ada release mode, C with idlc)"
gprbuild -P bench/bench.gpr -XBUILD_MODE=release -p -j2 -q >"$out/build-ada.log" 2>&1 \
   || { cat "$out/build-ada.log"; exit 1; }
idlc -o "$build" bench/messaging.idl || exit 1
gcc -O2 -Wall -I"$build" bench/messaging_c.c "$build/messaging.c" -lddsc -o "$build/messaging_c" \
   || exit 1
python=.venv/bin/python
[ -x "$python" ] || { echo "bench-messaging: no .venv (scripts/install-deps.sh --bench)"; exit 1; }

run_impl() {  # impl -> command prefix
   case $1 in
      C) echo "$build/messaging_c" ;;
      Ada) echo "bin/bench_messaging" ;;
      Ada-typed) echo "bin/bench_messaging --typed" ;;
      Ada-raw) echo "bin/bench_messaging --raw" ;;
      Python) echo "$python bench/messaging_py.py" ;;
   esac
}

count_for() {  # impl size -> round trips
   local n
   case $2 in 64|4096) n=2000 ;; *) n=300 ;; esac
   [ "$1" = Python ] && n=$((n / 4))
   [ "$quick" = 1 ] && n=$((n / 5))
   echo $n
}

csv=$out/messaging.csv
echo "impl,size,rtt_median_us,rtt_p99_us,msgs_per_s,mb_per_s" > "$csv"

impls=${BENCH_IMPLS:-C Ada Ada-typed Ada-raw Python}
for impl in $impls; do
   cmd=$(run_impl $impl)
   for size in "${sizes[@]}"; do
      # Ping-pong.
      $cmd pong >/dev/null 2>&1 &
      pong=$!
      rtt=$(timeout 120 $cmd ping "$size" "$(count_for $impl "$size")" 2>/dev/null | grep '^rtt_us')
      sleep 0.3
      kill "$pong" 2>/dev/null; wait "$pong" 2>/dev/null
      # Throughput: best of $repeat runs.
      thr=""
      for _ in $(seq "$repeat"); do
         $cmd sub >"$out/sub.txt" 2>/dev/null &
         sub=$!
         sleep 0.5
         timeout 120 $cmd pub "$size" "$seconds" >/dev/null 2>&1
         for _ in $(seq 50); do kill -0 "$sub" 2>/dev/null || break; sleep 0.2; done
         kill "$sub" 2>/dev/null; wait "$sub" 2>/dev/null
         run=$(grep '^throughput' "$out/sub.txt")
         if [ -n "$run" ]; then
            if [ -z "$thr" ] || awk -v a="$run" -v b="$thr" \
                  'BEGIN { split(a, x, " "); split(b, y, " "); exit !(x[2] > y[2]) }'; then
               thr=$run
            fi
         fi
      done
      read -r _ median p99 <<<"${rtt:-rtt_us nan nan}"
      read -r _ msgs mbs <<<"${thr:-throughput nan nan}"
      echo "$impl,$size,$median,$p99,$msgs,$mbs" >> "$csv"
   done
done

"$python" - "$csv" "$out/messaging.json" <<'PY'
import csv, json, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
def f(x):
    try:
        return float(x)
    except ValueError:
        return math.nan
print(f"{'impl':9} {'size':>7} {'RTT med us':>11} {'RTT p99 us':>11} {'msg/s':>10} {'MB/s':>9}")
for r in rows:
    print(f"{r['impl']:9} {r['size']:>7} {f(r['rtt_median_us']):11.1f} {f(r['rtt_p99_us']):11.1f}"
          f" {f(r['msgs_per_s']):10.0f} {f(r['mb_per_s']):9.2f}")
by = {(r['impl'], r['size']): r for r in rows}
ratios = []
print("\nratios vs C (targets: RTT <= 1.25, throughput >= 0.8)")
for impl in ("Ada", "Ada-typed", "Ada-raw", "Python"):
    for size in ("64", "4096", "262144"):
        c, a = by.get(("C", size)), by.get((impl, size))
        if not c or not a:
            continue
        rtt = f(a['rtt_median_us']) / f(c['rtt_median_us'])
        thr = f(a['msgs_per_s']) / f(c['msgs_per_s'])
        rtt_target = 1.1 if impl == "Ada-typed" and size == "64" else 1.25
        ok = "" if impl == "Python" else (
            "  ok" if rtt <= rtt_target and thr >= 0.8 else "  MISSES TARGET")
        print(f"{impl:9} {size:>7}  RTT x{rtt:5.2f}  throughput x{thr:5.2f}{ok}")
        ratios.append({"impl": impl, "size": int(size), "rtt_ratio": rtt, "throughput_ratio": thr})
json.dump({"rows": rows, "ratios_vs_c": ratios}, open(sys.argv[2], "w"), indent=1)
PY
