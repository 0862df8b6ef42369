"""A Python cyclonedds peer following rmw_cyclonedds's service conventions
(request topic rq/<name>Request, reply topic rr/<name>Reply, the 16-byte
request header guid/seq before the body, endpoint USER_DATA clientid= /
serviceid=). Shared by the service interop tests and bench/bench-services."""
import os
import time
from dataclasses import dataclass

import pubsub_support as ps  # noqa: F401  (sets the loopback environment)
from cyclonedds.core import Policy, Qos
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import int64, uint64
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic


@final
@dataclass
class AddTwoInts_Request_(IdlStruct, typename="example_interfaces::srv::dds_::AddTwoInts_Request_"):
    guid: uint64
    seq: int64
    a: int64
    b: int64


@final
@dataclass
class AddTwoInts_Response_(IdlStruct,
                           typename="example_interfaces::srv::dds_::AddTwoInts_Response_"):
    guid: uint64
    seq: int64
    sum: int64


_counter = [0]


def new_id():
    """A 16-byte id printed as rmw_cyclonedds does (hex, '.' separators)."""
    _counter[0] += 1
    raw = os.urandom(12) + _counter[0].to_bytes(4, "big")
    return f"{raw[0]:2x}" + "".join(f".{b:x}" for b in raw[1:])


def service_qos(user_data, depth=10):
    return Qos(Policy.History.KeepLast(depth),
               Policy.Reliability.Reliable(max_blocking_time=10**9),
               Policy.Durability.Volatile,
               Policy.DataRepresentation(use_cdrv0_representation=True),
               Policy.Userdata(data=user_data.encode()))


class Client:
    """A client of AddTwoInts `name` ("/add_two_ints")."""

    def __init__(self, dp, name="/add_two_ints", with_id=True, depth=10):
        self.id = new_id()
        qos = service_qos(f"clientid={self.id};" if with_id else "", depth)
        self.writer = DataWriter(dp, Topic(dp, f"rq{name}Request", AddTwoInts_Request_), qos=qos)
        self.reader = DataReader(dp, Topic(dp, f"rr{name}Reply", AddTwoInts_Response_), qos=qos)
        self.guid = 0x1234_5678_9ABC_DEF0 ^ int.from_bytes(os.urandom(4), "little")
        self.seq = 0

    def wait_for_service(self, timeout=10.0):
        return ps.wait_matched(self.writer, timeout) and ps.wait_matched(self.reader, timeout)

    def call(self, a, b, timeout=5.0):
        self.seq += 1
        seq = self.seq
        self.writer.write(AddTwoInts_Request_(guid=self.guid, seq=seq, a=a, b=b))
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            for r in self.reader.take(N=16):
                if isinstance(r, AddTwoInts_Response_) and r.guid == self.guid and r.seq == seq:
                    return r
            time.sleep(0.0005)
        return None


class Server:
    """An AddTwoInts server; call serve_some() to answer what arrived."""

    def __init__(self, dp, name="/add_two_ints"):
        self.id = new_id()
        qos = service_qos(f"serviceid={self.id};")
        self.reader = DataReader(dp, Topic(dp, f"rq{name}Request", AddTwoInts_Request_), qos=qos)
        self.writer = DataWriter(dp, Topic(dp, f"rr{name}Reply", AddTwoInts_Response_), qos=qos)
        self.answered = 0

    def serve_some(self):
        for r in self.reader.take(N=64):
            if not isinstance(r, AddTwoInts_Request_):
                continue  # InvalidSample: a client went away
            self.writer.write(AddTwoInts_Response_(guid=r.guid, seq=r.seq, sum=r.a + r.b))
            self.answered += 1


def stop(proc, grace=3.0):
    """Ends a long-running Ada program (SIGTERM, then SIGKILL after `grace`
    seconds) and returns its output."""
    import subprocess
    proc.terminate()
    try:
        out, _ = proc.communicate(timeout=grace)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, _ = proc.communicate()
    return out
