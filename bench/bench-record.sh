#!/usr/bin/env bash
# Recording throughput (issue 15): messages/s and MB/s for 64 B
# (std_msgs/String) and LaserScan (360 ranges, 1504 B) messages, against the
# Python `mcap` writer (zstd chunks of 768 KiB, as ours) on the same bytes:
#  * writer: RCL.MCAP.Writers alone (bin/bench_record write) vs mcap.Writer;
#  * end-to-end: RCL.Bags.Recorders (what `rclada bag record` runs, here in
#    bin/bench_record record) recording a reliable KEEP_ALL Ada publisher
#    (bin/bench_record pub) over loopback DDS, every message checked in the
#    bag by the Python mcap reader (loss = sent - recorded); its rate is the
#    span of the recorded log times;
#  * the recorder's CPU share during the demo (`sancta demo --no-record`
#    beside `rclada bag record -a`): recorder CPU / (demo + recorder CPU).
# Prints a table; CSV in out/bench/record.csv. Ratios are ours / Python writer.
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
printf "%-6s %-22s %9s %6s %11s %9s %11s %7s %5s\n" case measure messages bytes "msg/s" "MB/s" "py msg/s" ratio lost

row() {  # case measure count bytes seconds python_rate lost
   "$py" - "$@" "$csv" <<'PY'
import sys
case, measure, count, size, seconds, prate, lost, csv = sys.argv[1:9]
count, size, seconds, prate = int(count), int(size), float(seconds), float(prate)
rate = count / seconds if seconds > 0 else 0.0
mb = rate * size / 1e6
ratio = rate / prate if prate > 0 else 0.0
print(f"{case:6} {measure:22} {count:9d} {size:6d} {rate:11.0f} {mb:9.1f} {prate:11.0f} {ratio:7.2f} {lost:>5}")
open(csv, "a").write(f"{case},{measure},{count},{size},{seconds:.6f},{rate:.1f},{mb:.2f},"
                     f"{prate:.1f},{ratio:.2f},{lost}\n")
PY
}

for case in 64 scan; do
   count=$n64; [ "$case" = scan ] && count=$nscan
   "$bin/bench_record" payload "$case" "$tmp/payload.bin"
   size=$(stat -c %s "$tmp/payload.bin")
   IFS=, read -r pc _ ps < <("$py" bench/record_peer.py write "$tmp/payload.bin" "$count")
   prate=$("$py" -c "print($pc / $ps)")
   IFS=, read -r _ ac _ as < <("$bin/bench_record" write "$case" "$count")
   row "$case" "writer" "$count" "$size" "$as" "$prate" 0
   topic=/bench_record_$case
   "$bin/bench_record" record "$case" "$topic" "$tmp/bag_$case" 60 > "$tmp/rec_$case.log" 2>&1 &
   rec=$!
   "$bin/bench_record" pub "$case" "$count" "$topic"
   kill -TERM "$rec"; wait "$rec" || true
   IFS=, read -r got first last < <("$py" bench/record_peer.py check "$tmp/bag_$case")
   seconds=$("$py" -c "print(max(1e-9, ($last - $first) / 1e9))")
   row "$case" "end-to-end (DDS)" "$got" "$size" "$seconds" "$prate" $((count - got))
done

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
