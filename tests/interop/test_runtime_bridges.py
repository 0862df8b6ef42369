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


def test_bridges_echo_text_and_correct_poses():
    dp = ps.participant()
    text_wr = ps.writer(dp, "rt/sancta_in", String_)
    text_rd = ps.reader(dp, "rt/sancta_out", String_)
    pose_wr = ps.writer(dp, "rt/sancta_pose_in", Pose2D_)
    pose_rd = ps.reader(dp, "rt/sancta_pose_out", Pose2D_)
    sancta = run_sancta(12)
    try:
        for entity in (text_wr, text_rd, pose_wr, pose_rd):
            assert ps.wait_matched(entity, timeout=10), f"{entity} not matched"
        sent = [f"hello {i}" for i in range(5)]
        for text in sent:
            text_wr.write(String_(data=text))
            time.sleep(0.05)
        poses = [(1.0 * i, 2.0, 0.1 * i) for i in range(5)]
        for x, y, theta in poses:
            pose_wr.write(Pose2D_(x=x, y=y, theta=theta))
            time.sleep(0.05)
        texts = [s.data for s in ps.take_until(text_rd, len(sent), timeout=10)]
        got = ps.take_until(pose_rd, len(poses), timeout=10)
    finally:
        sancta.terminate()  # SIGTERM: not waited for the 12 s
        out = ps.finish(sancta)
    assert texts == sent, f"texts {texts}; sancta said:\n{out}"
    assert len(got) == len(poses), f"poses {got}; sancta said:\n{out}"
    for (x, y, theta), p in zip(poses, got):
        # scan_matching composes (dx=1, dy=0, dyaw=0) with the pose.
        assert math.isclose(p.x, x + 1.0, abs_tol=1e-9), (p, x)
        assert math.isclose(p.y, y, abs_tol=1e-9), (p, y)
        assert math.isclose(p.theta, theta, abs_tol=1e-9), (p, theta)
