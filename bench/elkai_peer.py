#!/usr/bin/env python3
"""LKH-3 (through PyPI elkai) as the TSP/ATSP peer of bench/allocation: reads a
TSPLIB instance (EUC_2D, CEIL_2D, ATT, or EXPLICIT FULL_MATRIX), solves it with
elkai and prints JSON {"objective": tour length in TSPLIB distances,
"time_s": wall time of the solve, "cpu_s": CPU time of the solve (this process,
time.process_time: elkai is single-threaded), "n": cities}.

usage: elkai_peer.py FILE [--runs N]
       elkai_peer.py FILE --robots M --objective minmax|minsum [--time-limit S]
                     [--runs N] [--seed K]
Above 1000 cities (EUC_2D) the coordinates are given to elkai instead of a
matrix (memory); the length is always recomputed here with TSPLIB's rounding.

With --robots M > 1: the single-depot mTSP of bench/allocation's mTSP rows
(share/tsplib/reference.csv: depot = node 1, M closed tours from and back to
the depot, every salesman visits at least one city, MinMax = longest tour,
MinSum = total). Solved by the full LKH-3 inside elkai through its low-level
entry _elkai.solve_problem (LKH parameter text, TSPLIB problem text):
TYPE TSP with the instance's own EDGE_WEIGHT_TYPE and coordinates or matrix,
SALESMEN = M, MTSP_OBJECTIVE = MINMAX | MINSUM, DEPOT = 1, MTSP_MIN_SIZE = 1
(LKH-3's default, said explicitly), RUNS = N (default 1), SEED = K, and
SPECIAL (LKH-3's setting for its penalty-based special problems, used by its
own mTSP parameter files: GAIN23 = NO, KICKS = 1, KICK_TYPE = 4, MAX_SWAPS = 0,
MOVE_TYPE = 5 SPECIAL, POPULATION_SIZE = 10; without it LKH-3's MinMax after
10 s was 6-19% above the best-known values, with it 0-0.7%). With
--time-limit S: TIME_LIMIT = TOTAL_TIME_LIMIT = S (LKH-3 counts CPU time: its
GetTime is clock()) and MAX_TRIALS = 1 000 000, so the limit is what stops
it. LKH-3 returns one cycle of n + M - 1 nodes, the nodes above n being
the depot's copies; the routes are the pieces between node 1 and the copies.
Each route is checked here (M routes, each city once, none empty) and the
objective recomputed with TSPLIB's rounding; the JSON adds "makespan",
"total", "costs" and "valid". Without --time-limit LKH-3 stops on its own
(RUNS runs of its default MAX_TRIALS = n trials).
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


def problem_text(path):
    """The instance's TSPLIB text with TYPE : TSP (LKH-3 reads SALESMEN and
    MTSP_OBJECTIVE from the parameters; an ATSP file keeps its matrix)."""
    out = []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if s == "EOF":
                break
            if s.upper().startswith("TYPE") and ":" in s:
                kind = s.split(":", 1)[1].strip().upper()
                out.append("TYPE : " + ("ATSP" if kind == "ATSP" else "TSP"))
            else:
                out.append(line.rstrip("\n"))
    return "\n".join(out) + "\nEOF\n"


def routes_of(cycle, n, m):
    """The M routes (city numbers, 1-based, depot excluded) of LKH-3's mTSP
    cycle: the depot is node 1 and its copies are the nodes n+1 .. n+M-1."""
    k = cycle.index(1)
    cycle = cycle[k:] + cycle[:k]
    routes, cur = [], None
    for v in cycle:
        if v == 1 or v > n:
            if cur is not None:
                routes.append(cur)
            cur = []
        else:
            cur.append(v)
    routes.append(cur)
    return routes


def solve_mtsp(a, n, dist):
    from elkai import _elkai
    params = ["PROBLEM_FILE = :stdin:", "SALESMEN = %d" % a.robots,
              "MTSP_OBJECTIVE = %s" % a.objective.upper(), "DEPOT = 1", "MTSP_MIN_SIZE = 1",
              "RUNS = %d" % a.runs, "SEED = %d" % a.seed, "TRACE_LEVEL = 0", "SPECIAL"]
    if a.time_limit:
        params += ["MAX_TRIALS = 1000000", "TIME_LIMIT = %g" % a.time_limit, "TOTAL_TIME_LIMIT = %g" % a.time_limit]
    text = problem_text(a.file)
    start, cpu_start = time.perf_counter(), time.process_time()
    cycle = _elkai.solve_problem("\n".join(params) + "\n", text)
    elapsed = time.perf_counter() - start
    cpu = time.process_time() - cpu_start
    routes = routes_of(list(cycle), n, a.robots)
    costs = []
    for r in routes:
        p = [1] + r + [1]
        costs.append(sum(dist(p[k] - 1, p[k + 1] - 1) for k in range(len(p) - 1)))
    cities = sorted(v for r in routes for v in r)
    valid = (len(routes) == a.robots and all(routes) and cities == list(range(2, n + 1)))
    total, makespan = sum(costs), max(costs)
    return {"objective": makespan if a.objective == "minmax" else total,
            "makespan": makespan, "total": total, "costs": costs, "valid": valid,
            "time_s": elapsed, "cpu_s": cpu, "n": n, "robots": a.robots,
            "time_limit": a.time_limit, "runs": a.runs, "seed": a.seed}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("file")
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--robots", type=int, default=1)
    ap.add_argument("--objective", default="minsum", choices=["minsum", "minmax"])
    ap.add_argument("--time-limit", type=float, default=0.0,
                    help="mTSP: LKH-3's TIME_LIMIT and TOTAL_TIME_LIMIT (CPU seconds)")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    n, kind, fmt, coords, weights = read(a.file)
    if kind == "EXPLICIT":
        if fmt != "FULL_MATRIX":
            raise SystemExit("elkai_peer: EDGE_WEIGHT_FORMAT %s not supported" % fmt)
        d = [weights[i * n:(i + 1) * n] for i in range(n)]
        dist = lambda i, j: d[i][j]
    else:
        dist = lambda i, j: distance(kind, coords[i], coords[j])
    if a.robots > 1:
        json.dump(solve_mtsp(a, n, dist), sys.stdout)
        print()
        return
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
