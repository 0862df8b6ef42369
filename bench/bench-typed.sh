#!/usr/bin/env bash
# CDR encode/decode per message, generated (typed) codec vs dynamic codec vs
# C (Cyclone's serializer on idlc-generated types) vs Python cyclonedds, on
# sensor_msgs/LaserScan (720 ranges), nav_msgs/Odometry and
# nav_msgs/OccupancyGrid (1000 x 1000), all in the same run. Ada: bin/
# bench_typed_cdr (release mode, "make bench"); C: bench/typed_cdr_c.c built
# here with idlc; Python: bench/cdr_peer.py (LaserScan and OccupancyGrid
# only; it makes a new buffer / message per call). Prints ns per message and
# the ratios to C; writes out/bench/typed.csv.
#   BENCH_TYPED_SECONDS  time budget of each measurement (default 1)
set -euo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
seconds=${BENCH_TYPED_SECONDS:-1}
build=obj/bench-typed-c
mkdir -p "$build"
[ -x bin/bench_typed_cdr ] || { echo "bench-typed: bin/bench_typed_cdr missing (make bench builds it)"; exit 1; }
bin/bench_typed_cdr "$seconds" out/bench/typed-ada.csv >/dev/null
# The C side runs Cyclone's exported serializer (dds_stream_write/_read and
# dds_stream_normalize_data on the idlc descriptor's ops: what its default
# serdata calls per sample; see bench/typed_cdr_c.c). If it does not build
# (no idlc, another Cyclone), the C columns are empty (nan).
if idlc -o "$build" bench/typed_cdr.idl \
   && gcc -O2 -Wall -I"$build" bench/typed_cdr_c.c "$build/typed_cdr.c" -lddsc \
          -o "$build/typed_cdr_c" 2>"$build/gcc.log"; then
   "$build/typed_cdr_c" "$seconds" > out/bench/typed-c.csv
else
   echo "bench-typed: C side not built ($(tail -1 "$build/gcc.log")); C columns empty"
   : > out/bench/typed-c.csv
fi
py_csv=out/bench/typed-python.csv
if [ -x .venv/bin/python ]; then
   .venv/bin/python bench/cdr_peer.py "$seconds" "$py_csv" >/dev/null 2>&1 || : > "$py_csv"
else
   : > "$py_csv"
fi
python3 - out/bench/typed-ada.csv out/bench/typed-c.csv "$py_csv" out/bench/typed.csv <<'PY'
import csv, sys
ns = {}
for path in sys.argv[1:3]:
    for r in csv.reader(open(path)):
        ns[(r[0], r[1], r[2])] = (int(r[3]), float(r[5]))
for r in csv.reader(open(sys.argv[3])):
    if len(r) >= 7 and r[2] == "python":   # msgs/s -> ns
        ns[(r[0], r[1], "python")] = (int(r[3]), 1e9 / float(r[6]))
out = open(sys.argv[4], "w")
out.write("case,op,bytes,typed_ns,dynamic_ns,c_ns,python_ns,typed_over_c,dynamic_over_c\n")
print(f"{'case':26} {'op':6} {'bytes':>8} {'typed ns':>10} {'dynamic ns':>11} {'C ns':>10} "
      f"{'Python ns':>11} {'typed/C':>8} {'dyn/C':>7}")
cases = sorted({(k[0], k[1]) for k in ns}, key=lambda k: (k[0], k[1] != "encode"))
for case, op in cases:
    if (case, op, "typed") not in ns:
        continue
    size, t = ns[(case, op, "typed")]
    d = ns[(case, op, "dynamic")][1]
    c = ns.get((case, op, "c"), (0, float("nan")))[1]
    p = ns.get((case, op, "python"), (0, float("nan")))[1]
    print(f"{case:26} {op:6} {size:8d} {t:10.0f} {d:11.0f} {c:10.0f} {p:11.0f} {t / c:8.2f} {d / c:7.2f}"
          f"   typed/dynamic {t / d:.2f}")
    out.write(f"{case},{op},{size},{t:.0f},{d:.0f},{c:.0f},{p:.0f},{t / c:.3f},{d / c:.3f}\n")
PY
echo "bench-typed: CSV in out/bench/typed.csv"
