"""Typed services and clients (RCL.Services.Typed, generated
example_interfaces/srv/AddTwoInts records): the examples `typed_server` and
`typed_client` against a Python cyclonedds peer following rmw_cyclonedds's
conventions, and against the dynamic `server` and `client`. The typed path
encodes and decodes with the generated codecs straight in the DDS samples (no
dynamic message)."""
import time
from dataclasses import dataclass

from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import int64, uint64
from cyclonedds.pub import DataWriter
from cyclonedds.topic import Topic

import pubsub_support as ps
import service_support as ss


def test_python_client_calls_typed_ada_service():
    ss.check_python_client_against("typed_server")


def test_typed_ada_client_calls_python_service():
    srv = ss.Server(ps.participant())
    ada, out = ss.run_client_against(srv.serve_some, "typed_client", 20, 22, 10)
    assert ada.returncode == 0, out
    assert "Got answer: 42" in out, out
    assert srv.answered == 1


def test_typed_client_calls_dynamic_server():
    server = ps.start("server", "typed_to_dynamic")
    try:
        ada = ps.start("typed_client", -5, 12, 10, "typed_to_dynamic")
        out = ps.finish(ada)
    finally:
        ss.stop(server)
    assert ada.returncode == 0, out
    assert "Got answer: 7" in out, out


def test_dynamic_client_calls_typed_server():
    server = ps.start("typed_server", "dynamic_to_typed")
    try:
        ada = ps.start("client", 40, -2, 10, "dynamic_to_typed")
        out = ps.finish(ada)
    finally:
        served = ss.stop(server)
    assert ada.returncode == 0, out
    assert "38" in out, out
    assert "Incoming request a: 40 b:-2" in served, served


@final
@dataclass
class ShortRequest(IdlStruct, typename="example_interfaces::srv::dds_::AddTwoInts_Request_"):
    """An AddTwoInts request cut after `a` (its `b` missing)."""
    guid: uint64
    seq: int64
    a: int64


def test_typed_server_drops_malformed_request_and_goes_on():
    ada = ps.start("typed_server", "malformed_typed")
    try:
        # The truncated request from a participant of its own (one topic,
        # two Python types).
        bad_dp = DomainParticipant(ps.domain_id())
        bad = DataWriter(bad_dp, Topic(bad_dp, "rq/malformed_typedRequest", ShortRequest),
                         qos=ss.service_qos(f"clientid={ss.new_id()};"))
        assert ps.wait_matched(bad), "the typed Ada service was not discovered"
        bad.write(ShortRequest(guid=7, seq=1, a=5))
        dp = ps.participant()
        cl = ss.Client(dp, "/malformed_typed")
        assert cl.wait_for_service()
        time.sleep(0.3)
        r = cl.call(20, 22)
        assert r is not None and r.sum == 42, "the typed server stopped answering"
    finally:
        out = ss.stop(ada)
    assert "malformed" in out and "AddTwoInts_Request" in out, out
    assert "offset" in out, out


class LateServer(ss.Server):
    """An AddTwoInts server answering each request `delay` seconds after it
    came (so a client that waited for the response is seen)."""

    def __init__(self, dp, name, delay=0.3):
        super().__init__(dp, name)
        self.delay = delay
        self.waiting = []

    def serve_some(self):
        now = time.monotonic()
        for r in self.reader.take(N=64):
            if isinstance(r, ss.AddTwoInts_Request_):
                self.waiting.append((now + self.delay, r))
        due = [r for t, r in self.waiting if t <= now]
        self.waiting = [(t, r) for t, r in self.waiting if t > now]
        for r in due:
            self.writer.write(ss.AddTwoInts_Response_(guid=r.guid, seq=r.seq, sum=r.a + r.b))
            self.answered += 1


def test_typed_async_calls():
    """RCL.Services.Typed.Call_Async (tests/src/tools/typed_async_client.adb):
    returns before the (late) responses, each callback gets its own sum, a
    synchronous call of the same client still works, and an asynchronous
    call nobody answers is forgotten after its timeout with a warning and
    without running its callback."""
    srv = LateServer(ps.participant(), "/typed_async")
    ada, out = ss.run_client_against(srv.serve_some, "typed_async_client", "typed_async")
    assert ada.returncode == 0, out
    assert "Returned before the responses: TRUE" in out, out
    answers = sorted(int(line.split(":")[1]) for line in out.splitlines()
                     if line.startswith("Async answer:"))
    assert answers == [-2, 42], out
    assert "Sync answer: 7" in out, out
    assert "got no response in time" in out, out
    assert "Unanswered call forgotten: TRUE, its callback ran 0 time(s)" in out, out
    assert srv.answered == 3
