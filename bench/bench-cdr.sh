#!/usr/bin/env bash
# CDR codec throughput: the Ada encoder/decoder (bin/bench_cdr, built in
# release mode by "make bench") against the Python cyclonedds serializer on
# the same messages: sensor_msgs/LaserScan with 720 ranges and
# nav_msgs/OccupancyGrid of 1000 x 1000 cells. Encode = a new buffer per
# message, decode = a new message per buffer. Prints a table with the
# Ada/Python ratio and writes out/bench/cdr.csv.
#   BENCH_CDR_SECONDS  time budget of each measurement (default 2)
set -euo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
seconds=${BENCH_CDR_SECONDS:-2}
[ -x bin/bench_cdr ] || { echo "bench-cdr: bin/bench_cdr missing (make bench builds it)"; exit 1; }
[ -x .venv/bin/python ] || { echo "bench-cdr: .venv missing (scripts/install-deps.sh --bench)"; exit 1; }
bin/bench_cdr "$seconds" out/bench/cdr-ada.csv >/dev/null
.venv/bin/python bench/cdr_peer.py "$seconds" out/bench/cdr-python.csv >/dev/null
.venv/bin/python - out/bench/cdr-ada.csv out/bench/cdr-python.csv out/bench/cdr.csv <<'PY'
import csv, sys
def load(path):
    rows = {}
    for r in csv.reader(open(path)):
        rows[(r[0], r[1])] = r
    return rows
ada, py = load(sys.argv[1]), load(sys.argv[2])
out = open(sys.argv[3], "w")
out.write("case,op,bytes,ada_msgs_per_s,ada_mb_per_s,python_msgs_per_s,python_mb_per_s,ratio\n")
print(f"{'case':26} {'op':6} {'bytes':>8} {'Ada msg/s':>11} {'Ada MB/s':>9} "
      f"{'Py msg/s':>10} {'Py MB/s':>8} {'Ada/Py':>8}")
for key in ada:
    a, p = ada[key], py[key]
    if a[3] != p[3]:
        sys.exit(f"bench-cdr: {key} encoded sizes differ: Ada {a[3]}, Python {p[3]}")
    ar, am, pr, pm = float(a[6]), float(a[7]), float(p[6]), float(p[7])
    ratio = ar / pr
    print(f"{key[0]:26} {key[1]:6} {int(a[3]):8d} {ar:11.0f} {am:9.1f} {pr:10.1f} {pm:8.1f} {ratio:8.1f}")
    out.write(f"{key[0]},{key[1]},{a[3]},{ar:.1f},{am:.2f},{pr:.2f},{pm:.3f},{ratio:.2f}\n")
PY
echo "bench-cdr: CSV in out/bench/cdr.csv"
