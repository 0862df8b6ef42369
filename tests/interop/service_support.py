"""A Python cyclonedds peer following rmw_cyclonedds's service conventions
(request topic rq/<name>Request, reply topic rr/<name>Reply, the 16-byte
request header guid/seq before the body, endpoint USER_DATA clientid= /
serviceid=). Shared by the service interop tests and bench/bench-services."""
import os
import time
from dataclasses import dataclass

import pubsub_support as ps  # (also sets the loopback environment)
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


stop = ps.stop  # SIGTERM, then SIGKILL; returns the output


class ServingThread:
    """A Python peer serving in a daemon thread of its own: a subclass calls
    _start_serving() at the end of __init__; its _run() loops while
    self._stop is false; stop() ends it."""

    def _start_serving(self):
        import threading
        self._stop = False
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def stop(self):
        self._stop = True
        self._thread.join(5)


def check_python_client_against(program):
    """Starts the Ada service `program` (the example_interfaces AddTwoInts
    service "add_two_ints"), calls it from a Python client following
    rmw_cyclonedds's conventions and checks each reply (sum, echoed request
    header) and the server's log line."""
    ada = ps.start(program)
    try:
        dp = ps.participant()
        cl = Client(dp)
        assert cl.wait_for_service(), f"the {program} service endpoints were not discovered"
        time.sleep(0.3)  # let the Ada side match our reply reader
        for a, b in [(2, 3), (-7, 100), (2**40, 2**40)]:
            r = cl.call(a, b)
            assert r is not None, f"no reply from {program}"
            assert r.sum == a + b
            assert r.guid == cl.guid and r.seq == cl.seq  # header echoed
    finally:
        out = stop(ada)
    assert "Incoming request a: 2 b: 3" in out, out


def run_client_against(serve_some, program, *args):
    """Runs the Ada client `program` with `args` while a thread calls
    `serve_some()` (answers whatever requests have come) every millisecond;
    returns the finished process and its output."""
    import threading
    stop_serving = threading.Event()

    def serve():
        while not stop_serving.is_set():
            serve_some()
            time.sleep(0.001)

    t = threading.Thread(target=serve)
    t.start()
    try:
        ada = ps.start(program, *args)
        out = ps.finish(ada)
    finally:
        stop_serving.set()
        t.join()
    return ada, out
