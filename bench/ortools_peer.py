#!/usr/bin/env python3
"""OR-tools routing peer for the allocation benchmark (model of
/work/shared/docs/benchmarks.md): depot = node 1, m vehicles on closed tours,
arc cost = distance; MinMax adds a distance dimension with
SetGlobalSpanCostCoefficient(100); a count dimension makes every vehicle
visit at least one city; first solution PATH_CHEAPEST_ARC, metaheuristic
GUIDED_LOCAL_SEARCH; wall-clock limit. Prints one JSON object (with
"time_used": wall seconds of the solve, "cpu_s": its CPU seconds).

With --clock cpu the budget is CPU time instead (for figures on a busy
machine): OR-tools' own limit is wall-clock only, so its wall limit becomes
--wall-cap x the budget and a callback at every solution found (GLS finds one
every few milliseconds) cancels the search once the process's CPU time since
the solve started (time.process_time; routing is single-threaded) reaches the
budget; the overshoot is the time to the next solution (measured ~0.1 s).

usage: ortools_peer.py FILE --robots M --objective minsum|minmax --time S [--real SCALE]
       [--first STRATEGY] [--clock wall|cpu] [--wall-cap F]
"""
import argparse
import json
import math
import sys
import time

from ortools.constraint_solver import pywrapcp, routing_enums_pb2


def read_tsplib(path, scale=0.0):
    """Distance matrix of a TSPLIB file (EUC_2D nint / real x scale, ATT,
    CEIL_2D, EXPLICIT FULL_MATRIX and triangular formats)."""
    with open(path) as f:
        text = f.read().split("\n")
    header, i, dim, wtype, wfmt = {}, 0, 0, "", "FULL_MATRIX"
    coords, weights = {}, []
    while i < len(text):
        line = text[i].strip()
        i += 1
        if not line:
            continue
        key = line.split(":")[0].strip().upper()
        val = line.split(":", 1)[1].strip() if ":" in line else ""
        if key == "DIMENSION":
            dim = int(val)
        elif key == "EDGE_WEIGHT_TYPE":
            wtype = val.upper()
        elif key == "EDGE_WEIGHT_FORMAT":
            wfmt = val.upper()
        elif key == "NODE_COORD_SECTION":
            for _ in range(dim):
                parts = text[i].split()
                i += 1
                coords[int(parts[0])] = (float(parts[1]), float(parts[2]))
        elif key == "EDGE_WEIGHT_SECTION":
            while len(weights) < _count(wfmt, dim):
                weights += [int(x) for x in text[i].split()]
                i += 1
        elif key == "EOF":
            break
        header[key] = val
    d = [[0] * dim for _ in range(dim)]
    if wtype == "EXPLICIT":
        it = iter(weights)
        for a in range(dim):
            for b in _row(wfmt, a, dim):
                w = next(it)
                if a != b:
                    d[a][b] = w
                    if wfmt != "FULL_MATRIX":
                        d[b][a] = w
    else:
        for a in range(dim):
            for b in range(dim):
                if a == b:
                    continue
                (xa, ya), (xb, yb) = coords[a + 1], coords[b + 1]
                r = math.hypot(xa - xb, ya - yb)
                if wtype == "ATT":
                    r = math.sqrt(((xa - xb) ** 2 + (ya - yb) ** 2) / 10.0)
                    t = int(r + 0.5)
                    d[a][b] = t + 1 if t < r else t
                elif wtype == "CEIL_2D":
                    d[a][b] = math.ceil(r)
                elif scale > 0:
                    d[a][b] = int(math.floor(r * scale + 0.5))
                else:
                    d[a][b] = int(math.floor(r + 0.5))
    return d


def _count(fmt, n):
    return {"FULL_MATRIX": n * n, "UPPER_ROW": n * (n - 1) // 2, "LOWER_ROW": n * (n - 1) // 2,
            "UPPER_DIAG_ROW": n * (n + 1) // 2, "LOWER_DIAG_ROW": n * (n + 1) // 2}[fmt]


def _row(fmt, a, n):
    return {"FULL_MATRIX": range(n), "UPPER_ROW": range(a + 1, n), "LOWER_ROW": range(a),
            "UPPER_DIAG_ROW": range(a, n), "LOWER_DIAG_ROW": range(a + 1)}[fmt]


def solve(d, m, objective, seconds, first="PATH_CHEAPEST_ARC", clock="wall", wall_cap=20.0):
    n = len(d)
    manager = pywrapcp.RoutingIndexManager(n, m, 0)
    routing = pywrapcp.RoutingModel(manager)

    def dist(i, j):
        return d[manager.IndexToNode(i)][manager.IndexToNode(j)]

    transit = routing.RegisterTransitCallback(dist)
    routing.SetArcCostEvaluatorOfAllVehicles(transit)
    if objective == "minmax" and m > 1:
        routing.AddDimension(transit, 0, sum(max(r) for r in d) + 1, True, "Distance")
        routing.GetDimensionOrDie("Distance").SetGlobalSpanCostCoefficient(100)
    if m > 1:
        routing.AddConstantDimension(1, n + 1, True, "Count")
        count = routing.GetDimensionOrDie("Count")
        for v in range(m):
            count.CumulVar(routing.End(v)).SetMin(2)
    params = pywrapcp.DefaultRoutingSearchParameters()
    if first != "SWEEP":
        params.first_solution_strategy = getattr(routing_enums_pb2.FirstSolutionStrategy,
                                                 first)
    params.local_search_metaheuristic = (
        routing_enums_pb2.LocalSearchMetaheuristic.GUIDED_LOCAL_SEARCH)
    wall_limit = seconds * (wall_cap if clock == "cpu" else 1.0)
    params.time_limit.FromMilliseconds(int(wall_limit * 1000))
    start, cpu_start = time.time(), time.process_time()
    if clock == "cpu":
        def cpu_limit():
            if time.process_time() - cpu_start >= seconds:
                routing.CancelSearch()
        routing.AddAtSolutionCallback(cpu_limit)
    if first == "SWEEP":
        # Start from m consecutive chunks of the cities (in node order): used
        # when the protocol's PATH_CHEAPEST_ARC cannot build a first solution
        # satisfying the count constraint (m >= 8 here).
        params.first_solution_strategy = (
            routing_enums_pb2.FirstSolutionStrategy.PATH_CHEAPEST_ARC)
        routing.CloseModelWithParameters(params)
        cities = list(range(1, n))
        k = len(cities)
        routes = [cities[v * k // m:(v + 1) * k // m] for v in range(m)]
        init = routing.ReadAssignmentFromRoutes(routes, True)
        sol = routing.SolveFromAssignmentWithParameters(init, params) if init else None
    else:
        sol = routing.SolveWithParameters(params)
    used = time.time() - start
    cpu = time.process_time() - cpu_start
    if sol is None:
        return {"status": "no solution", "time_used": used, "cpu_s": cpu}
    tours, costs = [], []
    for v in range(m):
        i, tour, c = routing.Start(v), [], 0
        while not routing.IsEnd(i):
            tour.append(manager.IndexToNode(i) + 1)
            j = sol.Value(routing.NextVar(i))
            c += dist(i, j)
            i = j
        tour.append(1)
        tours.append(tour)
        costs.append(c)
    return {"status": "ok", "makespan": max(costs), "total": sum(costs), "costs": costs,
            "tours": tours, "time_used": used, "cpu_s": cpu}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("file")
    ap.add_argument("--robots", type=int, default=1)
    ap.add_argument("--objective", default="minsum", choices=["minsum", "minmax"])
    ap.add_argument("--time", type=float, default=10.0)
    ap.add_argument("--real", type=float, default=0.0)
    ap.add_argument("--first", default="PATH_CHEAPEST_ARC",
                    help="first solution strategy (the protocol's is PATH_CHEAPEST_ARC); "
                         "SWEEP = start from m chunks of the cities in node order")
    ap.add_argument("--clock", default="wall", choices=["wall", "cpu"],
                    help="what --time counts (cpu: see the module comment)")
    ap.add_argument("--wall-cap", type=float, default=20.0,
                    help="--clock cpu: the wall-clock limit as a multiple of --time")
    a = ap.parse_args()
    d = read_tsplib(a.file, a.real)
    r = solve(d, a.robots, a.objective, a.time, a.first, a.clock, a.wall_cap)
    r["clock"] = a.clock
    r["first_solution"] = a.first
    r["objective"] = r.get("makespan" if a.objective == "minmax" else "total")
    json.dump(r, sys.stdout)
    print()


if __name__ == "__main__":
    main()
