#!/usr/bin/env bash
# CDR encode/decode per message, generated (typed) codec vs dynamic codec vs
# C (Cyclone's serializer on idlc-generated types) vs Python cyclonedds, on
# sensor_msgs/LaserScan (720 ranges), nav_msgs/Odometry and
# nav_msgs/OccupancyGrid (1000 x 1000). Ada: bench_typed_cdr, built here in
# release mode from bench/bench_typed.gpr (the ROS 2 library and message
# types only; incremental); C: bench/typed_cdr_c.c built here with idlc;
# Python: bench/cdr_peer.py (LaserScan and OccupancyGrid only; it makes a
# new buffer / message per call). The Ada and C programs run
# BENCH_TYPED_RUNS times each, alternating; the table gives the best run
# (and the spread) of each, the ratios to C, and checks that the typed Ada
# and the C encodings of every case are equal byte for byte (exit 1 if
# not). Writes out/bench/typed.csv. Run it under "nice -n 19" on a shared
# machine.
#   BENCH_TYPED_SECONDS  time budget of each measurement (default 1)
#   BENCH_TYPED_RUNS     runs of each side (default 3)
set -euo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
seconds=${BENCH_TYPED_SECONDS:-1}
runs=${BENCH_TYPED_RUNS:-3}
build=obj/bench-typed-c
dumps=out/bench/typed-encodings
mkdir -p "$build" "$dumps/ada" "$dumps/c"
rm -f out/bench/typed-ada-*.csv out/bench/typed-c-*.csv "$dumps"/ada/* "$dumps"/c/*
make --no-print-directory generate >/dev/null
gprbuild -P bench/bench_typed.gpr -p -j0 -q -XBUILD_MODE=release
ada=obj/release/bench_typed/bench_typed_cdr
# The C side runs Cyclone's exported serializer (dds_stream_write/_read and
# dds_stream_normalize_data on the idlc descriptor's ops: what its default
# serdata calls per sample; see bench/typed_cdr_c.c). If it does not build
# (no idlc, another Cyclone), the C columns are empty (nan).
c_bin=""
if idlc -o "$build" bench/typed_cdr.idl \
   && gcc -O2 -Wall -I"$build" bench/typed_cdr_c.c "$build/typed_cdr.c" -lddsc \
          -o "$build/typed_cdr_c" 2>"$build/gcc.log"; then
   c_bin="$build/typed_cdr_c"
else
   echo "bench-typed: C side not built ($(tail -1 "$build/gcc.log")); C columns empty"
fi
for run in $(seq 1 "$runs"); do
   "$ada" "$seconds" "out/bench/typed-ada-$run.csv" "$dumps/ada" >/dev/null
   if [ -n "$c_bin" ]; then
      "$c_bin" "$seconds" "$dumps/c" > "out/bench/typed-c-$run.csv"
   fi
done
if [ -n "$c_bin" ]; then
   for f in "$dumps"/c/*.cdr; do
      name=$(basename "$f")
      if ! cmp -s "$f" "$dumps/ada/$name"; then
         echo "bench-typed: the typed Ada and the C encodings of ${name%.cdr} differ" \
              "($(cmp "$f" "$dumps/ada/$name" 2>&1 | head -1))"
         exit 1
      fi
   done
   echo "bench-typed: typed Ada and C encodings equal byte for byte:" \
        "$(cd "$dumps/c" && ls -- *.cdr | sed 's/\.cdr$//' | tr '\n' ' ')"
fi
py_csv=out/bench/typed-python.csv
if [ -x .venv/bin/python ]; then
   .venv/bin/python bench/cdr_peer.py "$seconds" "$py_csv" >/dev/null 2>&1 || : > "$py_csv"
else
   : > "$py_csv"
fi
python3 - "$py_csv" out/bench/typed.csv out/bench/typed-ada-*.csv out/bench/typed-c-*.csv <<'PY'
import csv, sys
runs = {}  # (case, op, impl) -> (bytes, [ns of each run])
for path in sys.argv[3:]:
    for r in csv.reader(open(path)):
        runs.setdefault((r[0], r[1], r[2]), (int(r[3]), []))[1].append(float(r[5]))
for r in csv.reader(open(sys.argv[1])):
    if len(r) >= 7 and r[2] == "python":   # msgs/s -> ns
        runs[(r[0], r[1], "python")] = (int(r[3]), [1e9 / float(r[6])])
best = {k: min(v[1]) for k, v in runs.items()}
def spread(k):
    v = runs.get(k, (0, []))[1]
    return f"{min(v):.0f}-{max(v):.0f}" if len(v) > 1 else ""
nan = float("nan")
out = open(sys.argv[2], "w")
out.write("case,op,bytes,typed_ns,dynamic_ns,c_ns,python_ns,typed_over_c,dynamic_over_c,"
          "typed_runs,c_runs\n")
print(f"best of each side's runs (ns per message); spread of the runs in brackets")
print(f"{'case':26} {'op':6} {'bytes':>8} {'typed ns':>18} {'dynamic ns':>11} {'C ns':>18} "
      f"{'Python ns':>11} {'typed/C':>8} {'dyn/C':>7}")
cases = sorted({(k[0], k[1]) for k in runs}, key=lambda k: (k[0], k[1] != "encode"))
for case, op in cases:
    if (case, op, "typed") not in runs:
        continue
    size = runs[(case, op, "typed")][0]
    t = best[(case, op, "typed")]
    d = best.get((case, op, "dynamic"), nan)
    c = best.get((case, op, "c"), nan)
    p = best.get((case, op, "python"), nan)
    ts, cs = spread((case, op, "typed")), spread((case, op, "c"))
    print(f"{case:26} {op:6} {size:8d} {t:6.0f} [{ts:>9}] {d:11.0f} {c:6.0f} [{cs:>9}] "
          f"{p:11.0f} {t / c:8.2f} {d / c:7.2f}   typed/dynamic {t / d:.2f}")
    out.write(f"{case},{op},{size},{t:.0f},{d:.0f},{c:.0f},{p:.0f},{t / c:.3f},{d / c:.3f},"
              f"{' '.join(f'{x:.0f}' for x in runs[(case, op, 'typed')][1])},"
              f"{' '.join(f'{x:.0f}' for x in runs.get((case, op, 'c'), (0, []))[1])}\n")
PY
echo "bench-typed: CSV in out/bench/typed.csv"
