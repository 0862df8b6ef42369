"""Shared helpers of the simulator suites: the ROS 2 message types sancta-sim
speaks (declared with the ROS 2 DDS type names), its control service types
(sancta_msgs/srv/SimControl, request/reply header inline) and a small client."""
import itertools
import math
import time
from dataclasses import dataclass, field

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import array, float32, float64, int32, int64, sequence, uint32, uint64

import pubsub_support as ps


def dds(pkg, name, kind="msg"):
    return f"{pkg}::{kind}::dds_::{name}_"


@final
@dataclass
class Time_(IdlStruct, typename=dds("builtin_interfaces", "Time")):
    sec: int32 = 0
    nanosec: uint32 = 0


@final
@dataclass
class Clock_(IdlStruct, typename=dds("rosgraph_msgs", "Clock")):
    clock: Time_ = field(default_factory=Time_)


@final
@dataclass
class String_(IdlStruct, typename=dds("std_msgs", "String")):
    data: str = ""


@final
@dataclass
class Header_(IdlStruct, typename=dds("std_msgs", "Header")):
    stamp: Time_ = field(default_factory=Time_)
    frame_id: str = ""


@final
@dataclass
class LaserScan_(IdlStruct, typename=dds("sensor_msgs", "LaserScan")):
    header: Header_ = field(default_factory=Header_)
    angle_min: float32 = 0.0
    angle_max: float32 = 0.0
    angle_increment: float32 = 0.0
    time_increment: float32 = 0.0
    scan_time: float32 = 0.0
    range_min: float32 = 0.0
    range_max: float32 = 0.0
    ranges: sequence[float32] = field(default_factory=list)
    intensities: sequence[float32] = field(default_factory=list)


@final
@dataclass
class Vector3_(IdlStruct, typename=dds("geometry_msgs", "Vector3")):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0


@final
@dataclass
class Twist_(IdlStruct, typename=dds("geometry_msgs", "Twist")):
    linear: Vector3_ = field(default_factory=Vector3_)
    angular: Vector3_ = field(default_factory=Vector3_)


@final
@dataclass
class Point_(IdlStruct, typename=dds("geometry_msgs", "Point")):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0


@final
@dataclass
class Quaternion_(IdlStruct, typename=dds("geometry_msgs", "Quaternion")):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0
    w: float64 = 1.0


@final
@dataclass
class Pose_(IdlStruct, typename=dds("geometry_msgs", "Pose")):
    position: Point_ = field(default_factory=Point_)
    orientation: Quaternion_ = field(default_factory=Quaternion_)


@final
@dataclass
class PoseStamped_(IdlStruct, typename=dds("geometry_msgs", "PoseStamped")):
    header: Header_ = field(default_factory=Header_)
    pose: Pose_ = field(default_factory=Pose_)


@final
@dataclass
class PoseWithCovariance_(IdlStruct, typename=dds("geometry_msgs", "PoseWithCovariance")):
    pose: Pose_ = field(default_factory=Pose_)
    covariance: array[float64, 36] = field(default_factory=lambda: [0.0] * 36)


@final
@dataclass
class PoseWithCovarianceStamped_(
        IdlStruct, typename=dds("geometry_msgs", "PoseWithCovarianceStamped")):
    header: Header_ = field(default_factory=Header_)
    pose: PoseWithCovariance_ = field(default_factory=PoseWithCovariance_)


@final
@dataclass
class TwistWithCovariance_(IdlStruct, typename=dds("geometry_msgs", "TwistWithCovariance")):
    twist: Twist_ = field(default_factory=Twist_)
    covariance: array[float64, 36] = field(default_factory=lambda: [0.0] * 36)


@final
@dataclass
class Odometry_(IdlStruct, typename=dds("nav_msgs", "Odometry")):
    header: Header_ = field(default_factory=Header_)
    child_frame_id: str = ""
    pose: PoseWithCovariance_ = field(default_factory=PoseWithCovariance_)
    twist: TwistWithCovariance_ = field(default_factory=TwistWithCovariance_)


@final
@dataclass
class SimControl_Request_(IdlStruct, typename=dds("sancta_msgs", "SimControl_Request", "srv")):
    guid: uint64 = 0
    seq: int64 = 0
    command: str = ""
    name: str = ""
    x: float64 = 0.0
    y: float64 = 0.0
    yaw: float64 = 0.0


@final
@dataclass
class SimControl_Response_(
        IdlStruct, typename=dds("sancta_msgs", "SimControl_Response", "srv")):
    guid: uint64 = 0
    seq: int64 = 0
    success: bool = False
    message: str = ""


def yaw_of(q):
    return 2.0 * math.atan2(q.z, q.w)


def stamp_of(header):
    return header.stamp.sec + header.stamp.nanosec * 1e-9


class Control:
    """A client of /sancta_sim/control (the request header carried inline)."""

    GUID = 0x5AC7A_0001
    _seq = itertools.count(1)

    def __init__(self, dp):
        self.wr = ps.writer(dp, "rq/sancta_sim/controlRequest", SimControl_Request_)
        self.rd = ps.reader(dp, "rr/sancta_sim/controlReply", SimControl_Response_)

    def wait_available(self, timeout=15.0):
        return ps.wait_matched(self.wr, timeout) and ps.wait_matched(self.rd, timeout)

    def call(self, command, name="", x=0.0, y=0.0, yaw=0.0, timeout=10.0):
        seq = next(self._seq)
        self.wr.write(SimControl_Request_(guid=self.GUID, seq=seq, command=command, name=name,
                                          x=x, y=y, yaw=yaw))
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            for reply in ps.take(self.rd):
                if reply.guid == self.GUID and reply.seq == seq:
                    return reply
            time.sleep(0.02)
        raise AssertionError(f"no reply to {command} {name} within {timeout} s")


def latest(rd, timeout=5.0):
    """The newest sample arriving within timeout (None when none)."""
    got = []
    deadline = time.monotonic() + timeout
    while not got and time.monotonic() < deadline:
        got = ps.take(rd)
        if not got:
            time.sleep(0.02)
    return got[-1] if got else None
