"""Python cyclonedds side of bench/bench-cdr.sh: serialize / deserialize the
same LaserScan (720 ranges) and OccupancyGrid (1000 x 1000) as
bench/src/bench_cdr.adb, printing the same CSV lines.

usage: cdr_peer.py [SECONDS] [CSV-FILE]
"""
import sys
import time
from dataclasses import dataclass, field

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
import cyclonedds.idl.types as t


def ros(pkg, name):
    return f"{pkg}::msg::dds_::{name}_"


@final
@dataclass
class Time(IdlStruct, typename=ros("builtin_interfaces", "Time")):
    sec: t.int32 = 0
    nanosec: t.uint32 = 0


@final
@dataclass
class Header(IdlStruct, typename=ros("std_msgs", "Header")):
    stamp: Time = field(default_factory=Time)
    frame_id: str = ""


@final
@dataclass
class LaserScan(IdlStruct, typename=ros("sensor_msgs", "LaserScan")):
    header: Header = field(default_factory=Header)
    angle_min: t.float32 = 0.0
    angle_max: t.float32 = 0.0
    angle_increment: t.float32 = 0.0
    time_increment: t.float32 = 0.0
    scan_time: t.float32 = 0.0
    range_min: t.float32 = 0.0
    range_max: t.float32 = 0.0
    ranges: t.sequence[t.float32] = field(default_factory=list)
    intensities: t.sequence[t.float32] = field(default_factory=list)


@final
@dataclass
class Point(IdlStruct, typename=ros("geometry_msgs", "Point")):
    x: t.float64 = 0.0
    y: t.float64 = 0.0
    z: t.float64 = 0.0


@final
@dataclass
class Quaternion(IdlStruct, typename=ros("geometry_msgs", "Quaternion")):
    x: t.float64 = 0.0
    y: t.float64 = 0.0
    z: t.float64 = 0.0
    w: t.float64 = 1.0


@final
@dataclass
class Pose(IdlStruct, typename=ros("geometry_msgs", "Pose")):
    position: Point = field(default_factory=Point)
    orientation: Quaternion = field(default_factory=Quaternion)


@final
@dataclass
class MapMetaData(IdlStruct, typename=ros("nav_msgs", "MapMetaData")):
    map_load_time: Time = field(default_factory=Time)
    resolution: t.float32 = 0.0
    width: t.uint32 = 0
    height: t.uint32 = 0
    origin: Pose = field(default_factory=Pose)


@final
@dataclass
class OccupancyGrid(IdlStruct, typename=ros("nav_msgs", "OccupancyGrid")):
    header: Header = field(default_factory=Header)
    info: MapMetaData = field(default_factory=MapMetaData)
    data: t.sequence[t.int8] = field(default_factory=list)


def laser_scan():
    return LaserScan(
        header=Header(stamp=Time(sec=1_700_000_000), frame_id="base_scan"),
        angle_min=-3.14159, angle_max=3.14159, angle_increment=2.0 * 3.14159 / 720.0,
        range_max=30.0, ranges=[0.5 + (i % 97) * 0.25 for i in range(1, 721)])


def occupancy_grid():
    return OccupancyGrid(
        header=Header(frame_id="map"),
        info=MapMetaData(resolution=0.05, width=1000, height=1000),
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
