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
echo "case,measure,messages,bytes,seconds,msgs_per_s,mb_per_s,python_msgs_per_s,ratio,lost" > "$csv"
printf "%-6s %-24s %9s %6s %11s %9s %11s %7s %5s\n" case measure messages bytes "msg/s" "MB/s" "py msg/s" ratio lost

row() {  # case measure count bytes seconds python_seconds lost [python_count]
   "$py" - "$@" "$csv" <<'PY'
import sys
case, measure, count, size, seconds, pseconds, lost = sys.argv[1:8]
csv = sys.argv[-1]
pcount = int(sys.argv[8]) if len(sys.argv) > 9 else int(count)
count, size, seconds, pseconds = int(count), int(size), float(seconds), float(pseconds)
rate = count / seconds if seconds > 0 else 0.0
prate = pcount / pseconds if pseconds > 0 else 0.0
mb = rate * size / 1e6
ratio = rate / prate if prate > 0 else 0.0
print(f"{case:6} {measure:24} {count:9d} {size:6d} {rate:11.0f} {mb:9.1f} {prate:11.0f} {ratio:7.2f} {lost:>5}")
open(csv, "a").write(f"{case},{measure},{count},{size},{seconds:.6f},{rate:.1f},{mb:.2f},"
                     f"{prate:.1f},{ratio:.2f},{lost}\n")
PY
}

span() {  # "count,first_ns,last_ns" -> seconds
   "$py" -c "import sys; c, f, l = map(int, sys.argv[1].split(',')); print(max(1e-9, (l - f) / 1e9))" "$1"
}

# Runs RECEIVER (a command line, in the background) against the publisher;
# the receiver's stdout in $tmp/out.
against_publisher() {  # case count topic receiver...
   local case=$1 count=$2 topic=$3; shift 3
   "$@" > "$tmp/out" 2> "$tmp/err" &
   local receiver=$!
   "$bin/bench_record" pub "$case" "$count" "$topic"
   kill -TERM "$receiver"; wait "$receiver" || true
}

n=0
for case in 64 scan; do
   count=$n64; [ "$case" = scan ] && count=$nscan
   "$bin/bench_record" payload "$case" "$tmp/payload.bin"
   size=$(stat -c %s "$tmp/payload.bin")
   IFS=, read -r pc _ ps < <("$py" bench/record_peer.py write "$tmp/payload.bin" "$count")
   IFS=, read -r _ ac _ as < <("$bin/bench_record" write "$case" "$count")
   row "$case" "writer alone" "$count" "$size" "$as" "$ps" 0
   # Each run on its own topic: no late sample of a run reaches the next.
   n=$((n + 1)); topic=/bench_record_${case}_$n
   against_publisher "$case" "$count" "$topic" \
      "$py" bench/record_peer.py record "$case" "$topic" "$tmp/py_bag_$case"
   py_rec=$("$py" bench/record_peer.py check "$tmp/py_bag_$case")
   n=$((n + 1)); topic=/bench_record_${case}_$n
   against_publisher "$case" "$count" "$topic" \
      "$bin/bench_record" record "$case" "$topic" "$tmp/bag_$case" 120
   rec=$("$py" bench/record_peer.py check "$tmp/bag_$case")
   row "$case" "end-to-end recorder" "${rec%%,*}" "$size" "$(span "$rec")" "$(span "$py_rec")" \
      "$((count - ${rec%%,*}))/$((count - ${py_rec%%,*}))" "${py_rec%%,*}"
   n=$((n + 1)); topic=/bench_record_${case}_$n
   against_publisher "$case" "$count" "$topic" "$py" bench/record_peer.py sink "$case" "$topic"
   py_sink=$(tail -1 "$tmp/out")
   n=$((n + 1)); topic=/bench_record_${case}_$n
   against_publisher "$case" "$count" "$topic" "$bin/bench_record" sink "$case" "$topic" 120
   sink=$(tail -1 "$tmp/out")
   row "$case" "DDS ceiling (no writing)" "${sink%%,*}" "$size" "$(span "$sink")" \
      "$(span "$py_sink")" "$((count - ${sink%%,*}))/$((count - ${py_sink%%,*}))" "${py_sink%%,*}"
done
echo "(lost: ours/Python; end-to-end and ceiling rates: messages received over the span from the"
echo " first one's publication to the last one's reception; writer: over the time to write the file)"

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
