"""SANCTA's ROS 2 bridge components against a Python cyclonedds peer
(loopback): `sancta run tests/data/config/ros2-bridge.xml` subscribes to
/sancta_in (std_msgs/String) and /sancta_pose_in (geometry_msgs/Pose2D),
and publishes what its components write on /sancta_out and /sancta_pose_out
(the text copied, the pose corrected by scan_matching with dx = 1 m)."""
import math
import time
from dataclasses import dataclass

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import float64

import pubsub_support as ps
from ros_types import String_

CONFIG = ps.REPO / "tests" / "data" / "config" / "ros2-bridge.xml"


@final
@dataclass
class Pose2D_(IdlStruct, typename="geometry_msgs::msg::dds_::Pose2D_"):
    x: float64
    y: float64
    theta: float64


def run_sancta(seconds):
    return ps.start("sancta", "run", CONFIG, "--agent", "Ari", "--for", seconds)


def probe_until_echoed(write_probe, rd, is_probe, timeout=30.0):
    """Writes probes (every 100 ms) until the first comes back on rd: each
    direction matched from both sides. Python's side matching first is not
    enough: a volatile writer drops what it writes before it has learned of
    a reader, so the first samples may be lost under load. Returns the
    samples taken meanwhile that are not probes (there must be none)."""
    others = []
    deadline = time.monotonic() + timeout
    index = 0
    while time.monotonic() < deadline:
        write_probe(index)
        index += 1
        time.sleep(0.1)
        got = ps.take(rd)
        others.extend(s for s in got if not is_probe(s))
        if any(is_probe(s) for s in got):
            return True, others
    return False, others


def take_all_but_probes(rd, count, is_probe, timeout=20.0):
    """Takes samples until `count` that are not probes came (late probe
    echoes are dropped) or time is out."""
    got = []
    deadline = time.monotonic() + timeout
    while len(got) < count and time.monotonic() < deadline:
        got.extend(s for s in ps.take(rd) if not is_probe(s))
        time.sleep(0.02)
    return got


# Probes are told apart from the checked samples: texts "probe N", poses at
# y = -1 (the checked ones are at y = 2; scan_matching keeps y).
def text_probe(sample):
    return sample.data.startswith("probe ")


def pose_probe(pose):
    return pose.y == -1.0


def test_bridges_echo_text_and_correct_poses():
    dp = ps.participant()
    text_wr = ps.writer(dp, "rt/sancta_in", String_)
    text_rd = ps.reader(dp, "rt/sancta_out", String_)
    pose_wr = ps.writer(dp, "rt/sancta_pose_in", Pose2D_)
    pose_rd = ps.reader(dp, "rt/sancta_pose_out", Pose2D_)
    sancta = run_sancta(120)
    texts, got, problem = [], [], None
    try:
        for entity in (text_wr, text_rd, pose_wr, pose_rd):
            assert ps.wait_matched(entity, timeout=30), f"{entity} not matched"
        echoed, early = probe_until_echoed(
            lambda i: text_wr.write(String_(data=f"probe {i}")), text_rd, text_probe)
        if not echoed or early:
            problem = (f"text probe came back: {echoed}; {len(early)} texts not sent"
                       f" came back: {early[:5]}")
        else:
            echoed, early = probe_until_echoed(
                lambda i: pose_wr.write(Pose2D_(x=0.0, y=-1.0, theta=0.0)),
                pose_rd, pose_probe)
            if not echoed or early:
                problem = (f"pose probe came back: {echoed}; {len(early)} poses not sent"
                           f" came back: {early[:5]}")
        if problem is None:
            sent = [f"hello {i}" for i in range(5)]
            for text in sent:
                text_wr.write(String_(data=text))
                time.sleep(0.05)
            poses = [(1.0 * i, 2.0, 0.1 * i) for i in range(5)]
            for x, y, theta in poses:
                pose_wr.write(Pose2D_(x=x, y=y, theta=theta))
                time.sleep(0.05)
            texts = [s.data for s in take_all_but_probes(text_rd, len(sent), text_probe)]
            got = take_all_but_probes(pose_rd, len(poses), pose_probe)
    finally:
        sancta.terminate()  # SIGTERM: not waited for the 120 s
        out = ps.finish(sancta)
    assert problem is None, f"{problem} (probes for 30 s); sancta said:\n{out}"
    assert texts == sent, f"texts {texts}; sancta said:\n{out}"
    assert len(got) == len(poses), f"poses {got}; sancta said:\n{out}"
    for (x, y, theta), p in zip(poses, got):
        # scan_matching composes (dx=1, dy=0, dyaw=0) with the pose.
        assert math.isclose(p.x, x + 1.0, abs_tol=1e-9), (p, x)
        assert math.isclose(p.y, y, abs_tol=1e-9), (p, y)
        assert math.isclose(p.theta, theta, abs_tol=1e-9), (p, theta)
