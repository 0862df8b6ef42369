#!/usr/bin/env bash
# Recording throughput (issue 15): messages/s and MB/s for 64 B
# (std_msgs/String) and LaserScan (360 ranges, 1504 B) messages, each
# measure against its Python counterpart on the same bytes (ratio = ours /
# Python):
#  * writer: RCL.MCAP.Writers alone (bin/bench_record write) vs the Python
#    `mcap` writer alone (zstd chunks of 768 KiB, as ours), in-process;
#  * end-to-end: one reliable KEEP_ALL Ada publisher (bin/bench_record pub)
#    over loopback DDS to a recorder: ours, RCL.Bags.Recorders (what `rclada
#    bag record` runs, here bin/bench_record record), vs a Python recorder
#    (bench/record_peer.py record: `cyclonedds` reader taking serialized
#    samples, `mcap` writer, zstd). Every message is checked in the bag by the
#    Python mcap reader (lost = sent - recorded); the rate is the messages
#    over the span from the first one's publication to the last one's
#    reception (all clocks are this machine's);
#  * DDS ceiling: the same publisher to a subscriber that writes nothing (ours:
#    bench_record sink, the recorder's subscription path; Python: record_peer.py
#    sink, the Python recorder's reader): how fast the DDS path alone goes;
#  * the receivers' CPU per message (user + system of the whole process while
#    the publisher runs): on a loaded machine the rates follow the load, the
#    CPU a message costs much less;
#  * the recorder's CPU share during the demo (`sancta demo --no-record`
#    beside `rclada bag record -a`): recorder CPU / (demo + recorder CPU).
# Prints a table; CSV in out/bench/record.csv.
#   BENCH_RECORD_COUNT_64 (default 200000), BENCH_RECORD_COUNT_SCAN (50000),
#   BENCH_RECORD_BIN (default bin: where bench_record is, e.g. a release build),
#   BENCH_RECORD_DEMO=0 skips the demo (which uses bin/sancta and bin/rclada)
set -euo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
bin=${BENCH_RECORD_BIN:-bin}
n64=${BENCH_RECORD_COUNT_64:-200000}
nscan=${BENCH_RECORD_COUNT_SCAN:-50000}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
py=.venv/bin/python
csv=out/bench/record.csv
echo "case,measure,messages,bytes,seconds,msgs_per_s,mb_per_s,python_msgs_per_s,ratio,cpu_us_per_msg,python_cpu_us_per_msg,cpu_ratio,lost" > "$csv"
printf "%-6s %-24s %8s %5s %9s %7s %9s %6s %8s %8s %6s %5s\n" case measure messages bytes \
   "msg/s" "MB/s" "py msg/s" ratio "CPU us" "py CPU" "CPU x" lost

row() {  # case measure count bytes seconds python_seconds cpu python_cpu lost [python_count]
   "$py" - "$@" "$csv" <<'PY'
import sys
case, measure, count, size, seconds, pseconds, cpu, pcpu, lost = sys.argv[1:10]
csv = sys.argv[-1]
pcount = int(sys.argv[10]) if len(sys.argv) > 11 else int(count)
count, size, seconds, pseconds = int(count), int(size), float(seconds), float(pseconds)
rate = count / seconds if seconds > 0 else 0.0
prate = pcount / pseconds if pseconds > 0 else 0.0
mb = rate * size / 1e6
ratio = rate / prate if prate > 0 else 0.0
us = 1e6 * float(cpu) / count if count else 0.0
pus = 1e6 * float(pcpu) / pcount if pcount else 0.0
cratio = pus / us if us > 0 else 0.0
print(f"{case:6} {measure:24} {count:8d} {size:5d} {rate:9.0f} {mb:7.1f} {prate:9.0f} {ratio:6.2f} "
      f"{us:8.2f} {pus:8.2f} {cratio:6.2f} {lost:>5}")
open(csv, "a").write(f"{case},{measure},{count},{size},{seconds:.6f},{rate:.1f},{mb:.2f},"
                     f"{prate:.1f},{ratio:.2f},{us:.3f},{pus:.3f},{cratio:.2f},{lost}\n")
PY
}

span() {  # "count,first_ns,last_ns" -> seconds
   "$py" -c "import sys; c, f, l = map(int, sys.argv[1].split(',')); print(max(1e-9, (l - f) / 1e9))" "$1"
}

cpu_ticks() {  # pid -> user + system CPU clock ticks so far
   awk '{print $14 + $15}' "/proc/$1/stat"
}

# Runs RECEIVER (a command line, in the background, printing "ready" once
# it has started) against the publisher; its stdout in $tmp/out, the CPU
# it used from "ready" until the publisher has finished in $cpu (seconds).
against_publisher() {  # case count topic receiver...
   local case=$1 count=$2 topic=$3; shift 3
   "$@" > "$tmp/out" 2> "$tmp/err" &
   local receiver=$! i before after
   for i in $(seq 600); do
      grep -q '^ready' "$tmp/out" 2>/dev/null && break
      sleep 0.1
   done
   before=$(cpu_ticks "$receiver")
   "$bin/bench_record" pub "$case" "$count" "$topic"
   after=$(cpu_ticks "$receiver")
   kill -TERM "$receiver"; wait "$receiver" || true
   cpu=$("$py" -c "print(($after - $before) / $(getconf CLK_TCK))")
}

n=0
for case in 64 scan; do
   count=$n64; [ "$case" = scan ] && count=$nscan
   "$bin/bench_record" payload "$case" "$tmp/payload.bin"
   size=$(stat -c %s "$tmp/payload.bin")
   IFS=, read -r pc _ ps < <("$py" bench/record_peer.py write "$tmp/payload.bin" "$count")
   IFS=, read -r _ ac _ as < <("$bin/bench_record" write "$case" "$count")
   row "$case" "writer alone" "$count" "$size" "$as" "$ps" "$as" "$ps" 0
   # Each run on its own topic: no late sample of a run reaches the next.
   n=$((n + 1)); topic=/bench_record_${case}_$n
   against_publisher "$case" "$count" "$topic" \
      "$py" bench/record_peer.py record "$case" "$topic" "$tmp/py_bag_$case"
   py_rec=$("$py" bench/record_peer.py check "$tmp/py_bag_$case"); py_cpu=$cpu
   n=$((n + 1)); topic=/bench_record_${case}_$n
   against_publisher "$case" "$count" "$topic" \
      "$bin/bench_record" record "$case" "$topic" "$tmp/bag_$case" 120
   rec=$("$py" bench/record_peer.py check "$tmp/bag_$case")
   row "$case" "end-to-end recorder" "${rec%%,*}" "$size" "$(span "$rec")" "$(span "$py_rec")" \
      "$cpu" "$py_cpu" \
      "$((count - ${rec%%,*}))/$((count - ${py_rec%%,*}))" "${py_rec%%,*}"
   n=$((n + 1)); topic=/bench_record_${case}_$n
   against_publisher "$case" "$count" "$topic" "$py" bench/record_peer.py sink "$case" "$topic"
   py_sink=$(tail -1 "$tmp/out"); py_cpu=$cpu
   n=$((n + 1)); topic=/bench_record_${case}_$n
   against_publisher "$case" "$count" "$topic" "$bin/bench_record" sink "$case" "$topic" 120
   sink=$(tail -1 "$tmp/out")
   row "$case" "DDS ceiling (no writing)" "${sink%%,*}" "$size" "$(span "$sink")" \
      "$(span "$py_sink")" "$cpu" "$py_cpu" "$((count - ${sink%%,*}))/$((count - ${py_sink%%,*}))" "${py_sink%%,*}"
done
echo "(ratio: our rate / Python's; lost: ours/Python; end-to-end and ceiling rates: messages"
echo " received over the span from the first one's publication to the last one's reception; writer:"
echo " over the time to write the file. CPU us: the receiver process's CPU per message (user +"
echo " system, every thread) while the publisher ran; CPU x: Python's / ours)"

if [ "${BENCH_RECORD_DEMO:-1}" != 0 ]; then
   bin/rclada bag record -a -o "$tmp/demo_bag" --discovery-period 0.3 > "$tmp/demo_rec.log" 2>&1 &
   rec=$!
   /usr/bin/time -f "%U %S" -o "$tmp/demo.time" bin/sancta demo share/config/sim-team.xml \
      --out "$tmp/demo" --no-record --quiet > "$tmp/demo.log" 2>&1 || true
   read -r rec_user rec_sys < <(awk '{print $14, $15}' /proc/$rec/stat)
   kill -TERM "$rec"; wait "$rec" || true
   read -r demo_user demo_sys < "$tmp/demo.time"
   tick=$(getconf CLK_TCK)
   "$py" - "$rec_user" "$rec_sys" "$tick" "$demo_user" "$demo_sys" "$tmp/demo_rec.log" "$csv" <<'PY'
import sys
ru, rs, tick, du, ds, log, csv = sys.argv[1:8]
rec = (int(ru) + int(rs)) / int(tick)
demo = float(du) + float(ds)
share = 100.0 * rec / (rec + demo)
msgs = [l for l in open(log) if l.startswith("Recorded")]
print(f"demo   recorder CPU share: {share:.1f} % ({rec:.2f} s of {rec + demo:.2f} s CPU); "
      f"{msgs[-1].strip() if msgs else ''}")
open(csv, "a").write(f"demo,recorder_cpu_share_percent,,,{rec:.3f},,,,{share:.2f},\n")
PY
fi
echo "bench-record: CSV in $csv"
