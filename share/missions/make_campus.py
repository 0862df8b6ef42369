#!/usr/bin/env python3
"""Writes the campus missions (share/worlds/campus.walls): ROBOTS robots on
the central street and TASKS visits on a grid of the open ground, at least
1 m from every wall. python3 make_campus.py ROBOTS TASKS > campus-T.xml"""
import sys

BUILDINGS = [(8, 5, 18, 14), (26, 5, 36, 14), (44, 5, 54, 14),
             (8, 26, 18, 35), (26, 26, 36, 35), (44, 26, 54, 35),
             (19.5, 15.5, 24.5, 16.5), (37.5, 23.5, 42.5, 24.5)]


def free(x, y, margin=1.0):
    if not (margin <= x <= 60 - margin and margin <= y <= 40 - margin):
        return False
    return all(not (x0 - margin <= x <= x1 + margin and y0 - margin <= y <= y1 + margin)
               for x0, y0, x1, y1 in BUILDINGS)


def main():
    robots, tasks = int(sys.argv[1]), int(sys.argv[2])
    points = [(x / 2, y / 2) for y in range(3, 78, 5) for x in range(3, 118, 5)
              if free(x / 2, y / 2)]
    step = len(points) / tasks
    chosen = [points[int(k * step)] for k in range(tasks)]
    assert len(chosen) == tasks and len(set(chosen)) == tasks, (len(points), tasks)
    print('<?xml version="1.0"?>')
    print(f"<!-- {robots} robots, {tasks} visits on the campus (60 m x 40 m); written by"
          f" make_campus.py {robots} {tasks}. -->")
    print(f'<mission name="campus-{tasks}" world="../worlds/campus.yaml">')
    for r in range(robots):
        print(f'  <robot id="r{r + 1}" x="{3 + r * 54 / max(1, robots - 1):.1f}" y="20" yaw="0"/>')
    for k, (x, y) in enumerate(chosen):
        print(f'  <goto id="v{k + 1}" x="{x}" y="{y}"/>')
    print("</mission>")


main()
