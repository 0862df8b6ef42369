"""A Python cyclonedds peer speaking the ROS 2 lifecycle protocol
(lifecycle_msgs services ~/get_state, ~/change_state,
~/get_available_transitions and the ~/transition_event topic) as
rclpy/rclcpp do on the wire: a client of a managed node, and a minimal
managed node (server) for the rclada lifecycle verbs."""
import os
import time
from dataclasses import dataclass

import pubsub_support as ps
from service_support import ServingThread, new_id, service_qos
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import int64, sequence, uint8, uint64
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic


@final
@dataclass
class State(IdlStruct, typename="lifecycle_msgs::msg::dds_::State_"):
    id: uint8
    label: str


@final
@dataclass
class Transition(IdlStruct, typename="lifecycle_msgs::msg::dds_::Transition_"):
    id: uint8
    label: str


@final
@dataclass
class TransitionDescription(IdlStruct,
                            typename="lifecycle_msgs::msg::dds_::TransitionDescription_"):
    transition: Transition
    start_state: State
    goal_state: State


@final
@dataclass
class TransitionEvent(IdlStruct, typename="lifecycle_msgs::msg::dds_::TransitionEvent_"):
    timestamp: uint64
    transition: Transition
    start_state: State
    goal_state: State


@final
@dataclass
class GetStateRequest(IdlStruct, typename="lifecycle_msgs::srv::dds_::GetState_Request_"):
    guid: uint64
    seq: int64
    structure_needs_at_least_one_member: uint8 = 0


@final
@dataclass
class GetStateResponse(IdlStruct, typename="lifecycle_msgs::srv::dds_::GetState_Response_"):
    guid: uint64
    seq: int64
    current_state: State


@final
@dataclass
class ChangeStateRequest(IdlStruct, typename="lifecycle_msgs::srv::dds_::ChangeState_Request_"):
    guid: uint64
    seq: int64
    transition: Transition


@final
@dataclass
class ChangeStateResponse(IdlStruct,
                          typename="lifecycle_msgs::srv::dds_::ChangeState_Response_"):
    guid: uint64
    seq: int64
    success: bool


@final
@dataclass
class GetTransitionsRequest(IdlStruct,
                            typename="lifecycle_msgs::srv::dds_::GetAvailableTransitions_Request_"):
    guid: uint64
    seq: int64
    structure_needs_at_least_one_member: uint8 = 0


@final
@dataclass
class GetTransitionsResponse(
        IdlStruct, typename="lifecycle_msgs::srv::dds_::GetAvailableTransitions_Response_"):
    guid: uint64
    seq: int64
    available_transitions: sequence[TransitionDescription]


SERVICES = {"get_state": (GetStateRequest, GetStateResponse),
            "change_state": (ChangeStateRequest, ChangeStateResponse),
            "get_available_transitions": (GetTransitionsRequest, GetTransitionsResponse)}


class LifecycleClient:
    """Drives managed node `node` ("/lc_talker") as ros2 lifecycle does."""

    def __init__(self, dp, node):
        self.id = new_id()
        qos = service_qos(f"clientid={self.id};")
        self.pairs = {}
        for srv, (req, resp) in SERVICES.items():
            self.pairs[srv] = (
                DataWriter(dp, Topic(dp, f"rq{node}/{srv}Request", req), qos=qos),
                DataReader(dp, Topic(dp, f"rr{node}/{srv}Reply", resp), qos=qos))
        self.events = ps.reader(dp, f"rt{node}/transition_event", TransitionEvent)
        self.guid = int.from_bytes(os.urandom(8), "little")
        self.seq = 0

    def wait(self, timeout=15.0):
        return all(ps.wait_matched(w, timeout) and ps.wait_matched(r, timeout)
                   for w, r in self.pairs.values()) and ps.wait_matched(self.events, timeout)

    def _call(self, srv, **fields):
        w, r = self.pairs[srv]
        self.seq += 1
        w.write(SERVICES[srv][0](guid=self.guid, seq=self.seq, **fields))
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            for x in r.take(N=8):
                if hasattr(x, "guid") and x.guid == self.guid and x.seq == self.seq:
                    return x
            time.sleep(0.002)
        raise AssertionError(f"no answer from {srv}")

    def state(self):
        s = self._call("get_state").current_state
        return s.label, s.id

    def change(self, tid=0, label=""):
        return self._call("change_state", transition=Transition(id=tid, label=label)).success

    def transitions(self):
        return [(d.transition.label, d.transition.id, d.start_state.label, d.goal_state.label)
                for d in self._call("get_available_transitions").available_transitions]

    def take_events(self):
        return [(e.transition.id, e.transition.label, e.start_state.label, e.goal_state.label)
                for e in self.events.take(N=64) if isinstance(e, TransitionEvent)]


class LifecycleServer(ServingThread):
    """A minimal managed node `node` (no callbacks: every transition succeeds),
    serving in a thread of its own until stop()."""

    STEPS = {("unconfigured", 1): ("configure", "inactive"),
             ("inactive", 2): ("cleanup", "unconfigured"),
             ("inactive", 3): ("activate", "active"),
             ("active", 4): ("deactivate", "inactive"),
             ("unconfigured", 5): ("shutdown", "finalized"),
             ("inactive", 6): ("shutdown", "finalized"),
             ("active", 7): ("shutdown", "finalized")}
    IDS = {"unconfigured": 1, "inactive": 2, "active": 3, "finalized": 4}
    VIA = {"configure": "configuring", "cleanup": "cleaningup", "activate": "activating",
           "deactivate": "deactivating", "shutdown": "shuttingdown"}

    def __init__(self, dp, node):
        self.id = new_id()
        qos = service_qos(f"serviceid={self.id};")
        self.pairs = {}
        for srv, (req, resp) in SERVICES.items():
            self.pairs[srv] = (
                DataReader(dp, Topic(dp, f"rq{node}/{srv}Request", req), qos=qos),
                DataWriter(dp, Topic(dp, f"rr{node}/{srv}Reply", resp), qos=qos))
        self.state = "unconfigured"
        self._start_serving()

    def _available(self):
        return [TransitionDescription(
                    transition=Transition(id=tid, label=label),
                    start_state=State(id=self.IDS[start], label=start),
                    goal_state=State(id=10, label=self.VIA[label]))
                for (start, tid), (label, _) in self.STEPS.items() if start == self.state]

    def _run(self):
        while not self._stop:
            for srv, (rd, wr) in self.pairs.items():
                for r in rd.take(N=8):
                    if not hasattr(r, "guid"):
                        continue
                    if srv == "get_state":
                        wr.write(GetStateResponse(guid=r.guid, seq=r.seq, current_state=State(
                            id=self.IDS[self.state], label=self.state)))
                    elif srv == "get_available_transitions":
                        wr.write(GetTransitionsResponse(guid=r.guid, seq=r.seq,
                                                        available_transitions=self._available()))
                    else:
                        step = self.STEPS.get((self.state, r.transition.id))
                        if step:
                            self.state = step[1]
                        wr.write(ChangeStateResponse(guid=r.guid, seq=r.seq,
                                                     success=step is not None))
            time.sleep(0.002)
