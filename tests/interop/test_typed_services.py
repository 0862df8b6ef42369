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
                self.accept(r, now)
        due = [r for t, r in self.waiting if t <= now]
        self.waiting = [(t, r) for t, r in self.waiting if t > now]
        for r in due:
            self.writer.write(ss.AddTwoInts_Response_(guid=r.guid, seq=r.seq, sum=r.a + r.b))
            self.answered += 1

    def accept(self, r, now):
        """Request `r`, taken at `now`: answered `delay` later."""
        self.waiting.append((now + self.delay, r))


@final
@dataclass
class ShortReply(IdlStruct, typename="example_interfaces::srv::dds_::AddTwoInts_Response_"):
    """An AddTwoInts reply without its `sum`: malformed."""
    guid: uint64
    seq: int64


class MalformedFirstServer(LateServer):
    """A LateServer that answers each request at once with a malformed
    reply (same guid and sequence, no sum: from a participant of its own,
    one topic with two Python types), and with the true one `delay` later."""

    def __init__(self, dp, name, delay=0.3):
        super().__init__(dp, name, delay)
        self.bad_dp = DomainParticipant(ps.domain_id())
        self.bad = DataWriter(self.bad_dp, Topic(self.bad_dp, f"rr{name}Reply", ShortReply),
                              qos=ss.service_qos(f"serviceid={ss.new_id()};"))
        self.malformed = 0

    def accept(self, r, now):
        # Every request taken gets its malformed reply: one reader take only
        # (a second take in the base class lost the malformed reply of a
        # request that came between the two; CI saw 5 of 6).
        if self.malformed == 0:
            assert ps.wait_matched(self.bad), "the client's reply reader was not seen"
        self.bad.write(ShortReply(guid=r.guid, seq=r.seq))
        self.malformed += 1
        super().accept(r, now)


def check_async_client(srv):
    """Runs tests/src/tools/async_client.adb against `srv` (on /typed_async)
    and checks what it printed; returns its output."""
    ada, out = ss.run_client_against(srv.serve_some, "async_client", "typed_async")
    assert ada.returncode == 0, out
    assert "Returned before the responses: TRUE" in out, out
    for label in ("Async answer:", "Dynamic async answer:"):
        answers = sorted(int(line.split(":")[1]) for line in out.splitlines()
                         if line.startswith(label))
        assert answers == [-2, 42], label + "\n" + out
    assert "Sync answer: 7" in out, out
    assert "Self call refused: TRUE" in out, out
    assert "got no response in time" in out, out
    assert "Unanswered call forgotten: TRUE, its callback ran 0 time(s)" in out, out
    assert "dropped: the client is finalized" in out, out
    # typed: 2 asynchronous, 1 synchronous, 1 asynchronous whose callback
    # calls (refused: no request); dynamic: 2 asynchronous
    assert srv.answered == 6, out
    return out


def test_async_calls():
    """Call_Async of the typed and of the dynamic client (one machinery,
    RCL.Pending_Calls.Asynchronous): returns before the (late) responses,
    each callback gets its own sum, a synchronous call of the same client
    still works, a synchronous call from a callback of its own client is
    refused (ROS_Exception, not a wait for itself), an asynchronous call
    nobody answers is forgotten after its timeout with a warning and without
    running its callback, and a client finalized with a call pending drops
    it at once (with a warning)."""
    check_async_client(LateServer(ps.participant(), "/typed_async"))


def test_async_calls_skip_malformed_replies():
    """Each call is first answered with a malformed reply (its own guid and
    sequence, the sum missing): both clients log and skip it, the call stays
    pending, and its callback runs once, with the true reply."""
    srv = MalformedFirstServer(ps.participant(), "/typed_async")
    out = check_async_client(srv)
    assert srv.malformed == 6, out
    # The typed codec's message names the field after a dot, the dynamic
    # one's after a colon. Typed: each of the 4 calls read its own (2
    # asynchronous, 1 synchronous, 1 asynchronous whose callback calls);
    # dynamic: its 2 own, and it logs those of the typed client it sees too.
    typed = out.count("malformed reply dropped: example_interfaces/srv/AddTwoInts_Response.sum:")
    dynamic = out.count("malformed reply dropped: example_interfaces/srv/AddTwoInts_Response: sum:")
    assert typed == 4 and dynamic >= 2, out
