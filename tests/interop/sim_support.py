"""Shared helpers of the simulator suites: the control service types of
sancta-sim (sancta_msgs/srv/SimControl, request/reply header inline) and a
small client. The ROS 2 message types it speaks are in ros_types."""
import itertools
import math
import time
from dataclasses import dataclass

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import float64, int64, uint64

import pubsub_support as ps
from ros_types import dds


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
