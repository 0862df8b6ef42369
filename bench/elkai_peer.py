#!/usr/bin/env python3
"""LKH-3 (through PyPI elkai) as the TSP/ATSP peer of bench/allocation: reads a
TSPLIB instance (EUC_2D, CEIL_2D, ATT, or EXPLICIT FULL_MATRIX), solves it with
elkai and prints JSON {"objective": tour length in TSPLIB distances,
"time_s": wall time of the solve, "cpu_s": CPU time of the solve (this process,
time.process_time: elkai is single-threaded), "n": cities}.

usage: elkai_peer.py FILE [--runs N]
Above 1000 cities (EUC_2D) the coordinates are given to elkai instead of a
matrix (memory); the length is always recomputed here with TSPLIB's rounding.
"""
import argparse
import json
import math
import sys
import time

import elkai


def read(path):
    head, coords, weights, section = {}, [], [], None
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s or s == "EOF":
                continue
            if section is None and ":" in s:
                k, v = s.split(":", 1)
                head[k.strip().upper()] = v.strip()
                continue
            if s.upper().startswith("NODE_COORD_SECTION"):
                section = "coords"
                continue
            if s.upper().startswith("EDGE_WEIGHT_SECTION"):
                section = "weights"
                continue
            if s.upper().startswith("DISPLAY_DATA_SECTION"):
                section = "skip"
                continue
            if section == "coords":
                p = s.split()
                coords.append((float(p[1]), float(p[2])))
            elif section == "weights":
                weights.extend(int(float(x)) for x in s.split())
    n = int(head["DIMENSION"])
    kind = head.get("EDGE_WEIGHT_TYPE", "")
    return n, kind, head.get("EDGE_WEIGHT_FORMAT", ""), coords, weights


def distance(kind, a, b):
    dx, dy = a[0] - b[0], a[1] - b[1]
    if kind == "EUC_2D":
        return int(math.sqrt(dx * dx + dy * dy) + 0.5)
    if kind == "CEIL_2D":
        return int(math.ceil(math.sqrt(dx * dx + dy * dy)))
    if kind == "ATT":
        r = math.sqrt((dx * dx + dy * dy) / 10.0)
        t = int(r + 0.5)
        return t + 1 if t < r else t
    raise SystemExit("elkai_peer: EDGE_WEIGHT_TYPE %s not supported" % kind)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("file")
    ap.add_argument("--runs", type=int, default=1)
    a = ap.parse_args()
    n, kind, fmt, coords, weights = read(a.file)
    if kind == "EXPLICIT":
        if fmt != "FULL_MATRIX":
            raise SystemExit("elkai_peer: EDGE_WEIGHT_FORMAT %s not supported" % fmt)
        d = [weights[i * n:(i + 1) * n] for i in range(n)]
        dist = lambda i, j: d[i][j]
    else:
        dist = lambda i, j: distance(kind, coords[i], coords[j])
    start = time.perf_counter()
    if kind == "EXPLICIT" or n <= 1000:
        m = [[0 if i == j else dist(i, j) for j in range(n)] for i in range(n)]
        start, cpu_start = time.perf_counter(), time.process_time()
        tour = elkai.DistanceMatrix(m).solve_tsp(runs=a.runs)
    else:
        start, cpu_start = time.perf_counter(), time.process_time()
        tour = elkai.Coordinates2D({i: coords[i] for i in range(n)}).solve_tsp(runs=a.runs)
    elapsed = time.perf_counter() - start
    cpu = time.process_time() - cpu_start
    if tour[0] != tour[-1]:
        tour = tour + [tour[0]]
    length = sum(dist(tour[k], tour[k + 1]) for k in range(len(tour) - 1))
    json.dump({"objective": length, "time_s": elapsed, "cpu_s": cpu, "n": n}, sys.stdout)
    print()


if __name__ == "__main__":
    main()
