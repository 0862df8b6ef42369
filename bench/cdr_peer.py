"""Python cyclonedds side of bench/bench-cdr.sh: serialize / deserialize the
same LaserScan (720 ranges) and OccupancyGrid (1000 x 1000) as
bench/src/bench_cdr.adb, printing the same CSV lines.

usage: cdr_peer.py [SECONDS] [CSV-FILE]
"""
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "interop"))
from ros_types import Header_, LaserScan_, MapMetaData_, OccupancyGrid_, Time_  # noqa: E402


def laser_scan():
    return LaserScan_(
        header=Header_(stamp=Time_(sec=1_700_000_000), frame_id="base_scan"),
        angle_min=-3.14159, angle_max=3.14159, angle_increment=2.0 * 3.14159 / 720.0,
        range_max=30.0, ranges=[0.5 + (i % 97) * 0.25 for i in range(1, 721)])


def occupancy_grid():
    return OccupancyGrid_(
        header=Header_(frame_id="map"),
        info=MapMetaData_(resolution=0.05, width=1000, height=1000),
        data=[(i % 3) * 50 - 1 for i in range(1, 1_000_001)])


def measure(name, msg, budget, out):
    data = msg.serialize()
    size = (len(data) + 3) // 4 * 4  # the Ada encoding counts the final padding
    for op, fn in (("encode", msg.serialize), ("decode", lambda: type(msg).deserialize(data))):
        count = 0
        start = time.perf_counter()
        while True:
            fn()
            count += 1
            elapsed = time.perf_counter() - start
            if elapsed >= budget and count >= 3:
                break
        rate = count / elapsed
        line = f"{name},{op},python,{size},{count},{elapsed:.6f},{rate},{rate * size / 1e6}"
        print(line)
        out.append(line)


def main():
    budget = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
    lines = []
    measure("laser_scan_720", laser_scan(), budget, lines)
    measure("occupancy_grid_1000x1000", occupancy_grid(), budget, lines)
    if len(sys.argv) > 2:
        with open(sys.argv[2], "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
