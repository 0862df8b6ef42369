"""A Python cyclonedds peer speaking the ROS 2 action protocol as rclpy does
on the wire, for example_interfaces/action/Fibonacci: the send_goal,
cancel_goal and get_result services (rmw_cyclonedds conventions, see
service_support) and the feedback and status topics, with goal UUIDs.
Used against the Ada action server and client both ways."""
import os
import time
from dataclasses import dataclass, field

import pubsub_support as ps
from service_support import ServingThread, new_id, service_qos
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import array, int8, int32, int64, sequence, uint8, uint32, uint64
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

FIB = [0, 1, 1, 2, 3, 5, 8, 13, 21, 34, 55, 89, 144, 233, 377, 610, 987]
# The Fibonacci action's sequence: a goal of order N ends with FIB[:N + 1].

STATUS = {0: "UNKNOWN", 1: "ACCEPTED", 2: "EXECUTING", 3: "CANCELING", 4: "SUCCEEDED",
          5: "CANCELED", 6: "ABORTED"}


@final
@dataclass
class UUID(IdlStruct, typename="unique_identifier_msgs::msg::dds_::UUID_"):
    uuid: array[uint8, 16]


@final
@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32 = 0
    nanosec: uint32 = 0


@final
@dataclass
class GoalInfo(IdlStruct, typename="action_msgs::msg::dds_::GoalInfo_"):
    goal_id: UUID
    stamp: Time


@final
@dataclass
class GoalStatus(IdlStruct, typename="action_msgs::msg::dds_::GoalStatus_"):
    goal_info: GoalInfo
    status: int8


@final
@dataclass
class GoalStatusArray(IdlStruct, typename="action_msgs::msg::dds_::GoalStatusArray_"):
    status_list: sequence[GoalStatus]


@final
@dataclass
class SendGoalRequest(IdlStruct,
                      typename="example_interfaces::action::dds_::Fibonacci_SendGoal_Request_"):
    guid: uint64
    seq: int64
    goal_id: UUID
    order: int32  # the Fibonacci_Goal, inline (one field)


@final
@dataclass
class SendGoalResponse(IdlStruct,
                       typename="example_interfaces::action::dds_::Fibonacci_SendGoal_Response_"):
    guid: uint64
    seq: int64
    accepted: bool
    stamp: Time


@final
@dataclass
class GetResultRequest(IdlStruct,
                       typename="example_interfaces::action::dds_::Fibonacci_GetResult_Request_"):
    guid: uint64
    seq: int64
    goal_id: UUID


@final
@dataclass
class GetResultResponse(IdlStruct,
                        typename="example_interfaces::action::dds_::Fibonacci_GetResult_Response_"):
    guid: uint64
    seq: int64
    status: int8
    sequence: sequence[int32]  # the Fibonacci_Result, inline


@final
@dataclass
class CancelRequest(IdlStruct, typename="action_msgs::srv::dds_::CancelGoal_Request_"):
    guid: uint64
    seq: int64
    goal_info: GoalInfo


@final
@dataclass
class CancelResponse(IdlStruct, typename="action_msgs::srv::dds_::CancelGoal_Response_"):
    guid: uint64
    seq: int64
    return_code: int8
    goals_canceling: sequence[GoalInfo]


@final
@dataclass
class FeedbackMessage(IdlStruct,
                      typename="example_interfaces::action::dds_::Fibonacci_FeedbackMessage_"):
    goal_id: UUID
    sequence: sequence[int32]  # the Fibonacci_Feedback, inline


def uuid_hex(u):
    return bytes(u.uuid).hex()


def status_qos():
    return ps.ros_qos(depth=1, transient_local=True)


class _Endpoints:
    def __init__(self, dp, name, kind):
        self.id = new_id()
        qos = service_qos(f"{kind}={self.id};")
        self.pairs = {}
        for srv, req, resp in (("send_goal", SendGoalRequest, SendGoalResponse),
                               ("cancel_goal", CancelRequest, CancelResponse),
                               ("get_result", GetResultRequest, GetResultResponse)):
            rq = Topic(dp, f"rq{name}/_action/{srv}Request", req)
            rr = Topic(dp, f"rr{name}/_action/{srv}Reply", resp)
            if kind == "clientid":
                self.pairs[srv] = (DataWriter(dp, rq, qos=qos), DataReader(dp, rr, qos=qos))
            else:
                self.pairs[srv] = (DataReader(dp, rq, qos=qos), DataWriter(dp, rr, qos=qos))


class ActionClient:
    """rclpy's ActionClient protocol for Fibonacci action `name`."""

    def __init__(self, dp, name="/fibonacci"):
        self.ep = _Endpoints(dp, name, "clientid")
        self.feedback = ps.reader(dp, f"rt{name}/_action/feedback", FeedbackMessage)
        self.status = DataReader(dp, Topic(dp, f"rt{name}/_action/status", GoalStatusArray),
                                 qos=status_qos())
        self.guid = int.from_bytes(os.urandom(8), "little")
        self.seq = 0
        self.feedbacks = {}  # goal id hex -> list of sequences
        self.statuses = []   # every GoalStatusArray seen: [(id hex, status)]

    def wait_for_server(self, timeout=10.0):
        """The three services and, as rcl_action_server_is_available, the
        feedback and status readers matched (else the first feedback of a
        goal sent at once may be published before they match, and lost).
        One deadline for all."""
        deadline = time.monotonic() + timeout
        return all(ps.wait_matched(e, max(0.01, deadline - time.monotonic()))
                   for e in [x for pair in self.ep.pairs.values() for x in pair]
                   + [self.feedback, self.status])

    def _call(self, srv, make, timeout=10.0):
        w, r = self.ep.pairs[srv]
        self.seq += 1
        seq = self.seq
        w.write(make(self.guid, seq))
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            self.poll()
            for x in r.take(N=16):
                if hasattr(x, "guid") and x.guid == self.guid and x.seq == seq:
                    return x
            time.sleep(0.002)
        return None

    def poll(self):
        for f in self.feedback.take(N=64):
            if isinstance(f, FeedbackMessage):
                self.feedbacks.setdefault(uuid_hex(f.goal_id), []).append(list(f.sequence))
        for s in self.status.take(N=16):
            if isinstance(s, GoalStatusArray):
                self.statuses.append([(uuid_hex(g.goal_info.goal_id), g.status)
                                      for g in s.status_list])

    def send_goal(self, order):
        gid = UUID(uuid=list(os.urandom(16)))
        resp = self._call("send_goal", lambda g, s: SendGoalRequest(
            guid=g, seq=s, goal_id=gid, order=order))
        assert resp is not None, "no send_goal response"
        return uuid_hex(gid), gid, resp

    def get_result(self, gid, timeout=20.0):
        return self._call("get_result",
                          lambda g, s: GetResultRequest(guid=g, seq=s, goal_id=gid), timeout)

    def cancel(self, gid=None, stamp=Time()):
        gid = gid or UUID(uuid=[0] * 16)
        return self._call("cancel_goal", lambda g, s: CancelRequest(
            guid=g, seq=s, goal_info=GoalInfo(goal_id=gid, stamp=stamp)))


def services_only(dp, name):
    """The three services of Fibonacci action `name` as a server offers
    them (request readers, reply writers), answering nothing, with no
    feedback nor status publisher: no action server for
    rcl_action_server_is_available. Returns the endpoints (.pairs[srv] is
    (request reader, reply writer))."""
    return _Endpoints(dp, name, "serviceid")


@dataclass
class _Goal:
    gid: UUID
    order: int
    stamp: Time
    status: int = 2
    seq: list = field(default_factory=lambda: [0, 1])
    waiting: list = field(default_factory=list)
    since: float = field(default_factory=time.monotonic)  # acceptance


class ActionServer(ServingThread):
    """rclpy's ActionServer protocol for Fibonacci `name`: accepts orders >= 0,
    one number per `step` seconds (feedback), accepts every cancel request.
    With `result_timeout` (s), forgets goals that long after they ended (as
    rcl_action; by default it keeps them all). With `await_reader` (s), a
    goal publishes its first feedback only once the feedback writer has
    matched a reader, waiting that long at most: the writer is volatile, so
    a client whose feedback reader this server discovers after the goal
    (a lost discovery packet, repaired only later) would lose it; the
    same as rmw_cyclonedds waits for a service client's reply reader.
    Runs in a thread of its own until stop()."""

    def __init__(self, dp, name="/fibonacci", step=0.05, result_timeout=None, await_reader=0.0):
        self.ep = _Endpoints(dp, name, "serviceid")
        self.fb = ps.writer(dp, f"rt{name}/_action/feedback", FeedbackMessage)
        self.st = DataWriter(dp, Topic(dp, f"rt{name}/_action/status", GoalStatusArray),
                             qos=status_qos())
        self.step = step
        self.result_timeout = result_timeout
        self.await_reader = await_reader
        self.ended = {}  # goal id hex -> time.monotonic() of its end
        self.goals = {}
        self.canceled = []
        self._start_serving()

    def _publish_status(self):
        if self.result_timeout is not None:
            now = time.monotonic()
            for k in [k for k, t in self.ended.items() if now - t > self.result_timeout]:
                del self.goals[k], self.ended[k]
        self.st.write(GoalStatusArray(status_list=[
            GoalStatus(goal_info=GoalInfo(goal_id=g.gid, stamp=g.stamp), status=g.status)
            for g in self.goals.values()]))

    def _result(self, g, guid, seq):
        return GetResultResponse(guid=guid, seq=seq, status=g.status,
                                 sequence=g.seq[:g.order + 1])

    def _run(self):
        next_step = time.monotonic()
        while not self._stop:
            sg_r, sg_w = self.ep.pairs["send_goal"]
            for r in sg_r.take(N=16):
                if not isinstance(r, SendGoalRequest):
                    continue
                ok = r.order >= 0
                now = time.time()
                stamp = Time(sec=int(now), nanosec=int((now % 1) * 1e9))
                if ok:
                    self.goals[uuid_hex(r.goal_id)] = _Goal(r.goal_id, r.order, stamp)
                sg_w.write(SendGoalResponse(guid=r.guid, seq=r.seq, accepted=ok, stamp=stamp))
                if ok:
                    self._publish_status()
            c_r, c_w = self.ep.pairs["cancel_goal"]
            for r in c_r.take(N=16):
                if not isinstance(r, CancelRequest):
                    continue
                want = uuid_hex(r.goal_info.goal_id)
                hit = [g for k, g in self.goals.items()
                       if g.status in (1, 2) and (want == "0" * 32 or k == want)]
                for g in hit:
                    g.status = 3
                    self.canceled.append(uuid_hex(g.gid))
                code = 0 if hit else (2 if want not in self.goals else 3)
                c_w.write(CancelResponse(guid=r.guid, seq=r.seq, return_code=code,
                                         goals_canceling=[GoalInfo(goal_id=g.gid, stamp=g.stamp)
                                                          for g in hit]))
                if hit:
                    self._publish_status()
            gr_r, gr_w = self.ep.pairs["get_result"]
            for r in gr_r.take(N=16):
                if not isinstance(r, GetResultRequest):
                    continue
                g = self.goals.get(uuid_hex(r.goal_id))
                if g is None:
                    gr_w.write(GetResultResponse(guid=r.guid, seq=r.seq, status=0, sequence=[]))
                elif g.status >= 4:
                    gr_w.write(self._result(g, r.guid, r.seq))
                else:
                    g.waiting.append((r.guid, r.seq))
            if time.monotonic() >= next_step:
                next_step += self.step
                for g in list(self.goals.values()):
                    if g.status == 3:
                        g.status = 5
                    elif g.status == 2 and len(g.seq) < g.order + 1:
                        if (len(g.seq) == 2 and time.monotonic() < g.since + self.await_reader
                                and self.fb.get_publication_matched_status().current_count == 0):
                            continue
                        g.seq.append(g.seq[-1] + g.seq[-2])
                        self.fb.write(FeedbackMessage(goal_id=g.gid, sequence=list(g.seq)))
                        continue
                    elif g.status == 2:
                        g.status = 4
                    else:
                        continue
                    if g.status >= 4:
                        self.ended[uuid_hex(g.gid)] = time.monotonic()
                    self._publish_status()
                    for guid, seq in g.waiting:
                        gr_w.write(self._result(g, guid, seq))
                    g.waiting.clear()
            time.sleep(0.002)


class ScriptedStatusServer(ServingThread):
    """An rclpy-protocol Fibonacci server `name` whose status topic plays a
    script: it accepts every goal, then publishes, `gap` seconds apart,
    the status arrays script(own goal UUID) lists (each a list of
    (UUID, status value), other goals and status values that are no
    GoalStatus allowed), answering get_result (SUCCEEDED, `result`) after
    the last. `readers_qos` gets the QoS of the status readers matched at
    acceptance (the client's; waiting 2 s at most for one)."""

    def __init__(self, dp, name, script, result=(0, 1, 1), gap=0.3):
        self.ep = _Endpoints(dp, name, "serviceid")
        self.st = DataWriter(dp, Topic(dp, f"rt{name}/_action/status", GoalStatusArray),
                             qos=status_qos())
        self.script, self.result, self.gap = script, list(result), gap
        self.readers_qos = []
        self._start_serving()

    def _publish(self, entries):
        self.st.write(GoalStatusArray(status_list=[
            GoalStatus(goal_info=GoalInfo(goal_id=g, stamp=Time(sec=1)), status=v)
            for g, v in entries]))

    def _run(self):
        steps, waiting, next_at = [], [], 0.0
        sg_r, sg_w = self.ep.pairs["send_goal"]
        gr_r, gr_w = self.ep.pairs["get_result"]
        while not self._stop:
            for r in sg_r.take(N=16):
                if isinstance(r, SendGoalRequest):
                    sg_w.write(SendGoalResponse(guid=r.guid, seq=r.seq, accepted=True,
                                                stamp=Time(sec=1)))
                    ps.wait_matched(self.st, 2.0)  # see ActionServer's await_reader
                    self.readers_qos = [self.st.get_matched_subscription_data(h).qos
                                        for h in self.st.get_matched_subscriptions()]
                    steps = list(self.script(r.goal_id))
                    next_at = time.monotonic()
            waiting += [r for r in gr_r.take(N=16) if isinstance(r, GetResultRequest)]
            if steps and time.monotonic() >= next_at:
                self._publish(steps.pop(0))
                next_at = time.monotonic() + self.gap
            if not steps and next_at and time.monotonic() >= next_at:
                for r in waiting:
                    gr_w.write(GetResultResponse(guid=r.guid, seq=r.seq, status=4,
                                                 sequence=self.result))
                waiting.clear()
            time.sleep(0.002)


def check_goal_result(client, order):
    """Sends the Fibonacci goal `order` through `client` (an ActionClient),
    checks that it succeeds with FIB[:order + 1], then returns the goal's
    hex id and the feedback received for it."""
    hex_id, gid, resp = client.send_goal(order)
    assert resp.accepted
    res = client.get_result(gid)
    assert res is not None, "no result"
    assert STATUS[res.status] == "SUCCEEDED"
    assert list(res.sequence) == FIB[:order + 1]
    time.sleep(0.3)
    client.poll()
    return hex_id, client.feedbacks.get(hex_id, [])


def check_cancel(client, after):
    """Sends a long goal (order 60), cancels it `after` seconds later and
    checks the cancel response and the canceled result (a prefix of the
    sequence); returns the goal's id."""
    hex_id, gid, resp = client.send_goal(60)
    assert resp.accepted
    time.sleep(after)
    c = client.cancel(gid)
    assert c is not None and c.return_code == 0
    assert [bytes(g.goal_id.uuid).hex() for g in c.goals_canceling] == [hex_id]
    res = client.get_result(gid)
    assert res is not None and STATUS[res.status] == "CANCELED"
    assert 2 <= len(res.sequence) < 61 and list(res.sequence) == FIB[:len(res.sequence)]
    return gid
