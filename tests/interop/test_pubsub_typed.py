"""Typed interoperability: Ada nodes (bin/pubsub_peer, RCL with ROSIDL.Dynamic
and ROSIDL.CDR) and a Python cyclonedds peer following the ROS 2 conventions
exchange std_msgs/String, geometry_msgs/Twist (best effort),
sensor_msgs/LaserScan (sequences) and nav_msgs/Odometry (nested messages,
fixed arrays); the values are equal on both sides. Python -> Ada is checked
through the Ada peer's echo: it decodes, re-encodes and republishes."""
import time

import pytest

import pubsub_support as ps
from ros_types import (Header_, LaserScan_, MapMetaData_, OccupancyGrid_, Odometry_,
                       Point_, Pose_, PoseWithCovariance_, Quaternion_, String_, Time_,
                       Twist_, TwistWithCovariance_, Vector3_)

HEADER = Header_(stamp=Time_(sec=1_700_000_123, nanosec=456_789), frame_id="base_laser")


def ada_values(name, n):
    """What bin/pubsub_peer publishes as its n-th message."""
    if name == "String":
        return String_(data=f"Hello World: {n}")
    if name == "Twist":
        return Twist_(linear=Vector3_(0.5, -1.25, 0.0), angular=Vector3_(0.0, 0.0, 0.75 * n))
    if name == "LaserScan":
        return LaserScan_(header=HEADER, angle_min=-1.5, angle_max=1.5, angle_increment=0.25,
                          time_increment=float32_of(0.001), scan_time=float32_of(0.1),
                          range_min=0.125, range_max=30.0,
                          ranges=[i * 0.5 for i in range(1, 14)],
                          intensities=[100.0, 200.0, 300.0])
    if name == "Odometry":
        return Odometry_(
            header=HEADER, child_frame_id="base_link",
            pose=PoseWithCovariance_(Pose_(Point_(1.0, 2.0, 3.0), Quaternion_(0, 0, 0, 1.0)),
                                     [i / 4.0 for i in range(1, 37)]),
            twist=TwistWithCovariance_(Twist_(Vector3_(0.25, 0, 0), Vector3_(0, 0, -0.5)),
                                       [0.01 if i % 7 == 1 else 0.0 for i in range(1, 37)]))
    raise ValueError(name)


def float32_of(x):
    import struct
    return struct.unpack("<f", struct.pack("<f", x))[0]


def python_values(name, n):
    """What the Python peer sends (other values than Ada's)."""
    if name == "String":
        return String_(data=f"from python {n}: \u00e9t\u00e9")
    if name == "Twist":
        return Twist_(linear=Vector3_(n, 2.5, -3.0), angular=Vector3_(0.1, 0.2, 0.3))
    if name == "LaserScan":
        return LaserScan_(header=Header_(Time_(n, 7), "scanner"), angle_min=-0.5,
                          angle_max=0.5, angle_increment=0.125, time_increment=0.0,
                          scan_time=0.25, range_min=0.0, range_max=10.0,
                          ranges=[float(i) for i in range(n + 5)], intensities=[])
    if name == "Odometry":
        return Odometry_(
            header=Header_(Time_(n, 99), "odom"), child_frame_id="robot",
            pose=PoseWithCovariance_(Pose_(Point_(-1.0, n, 0.5), Quaternion_(0, 0, 0.6, 0.8)),
                                     [float(-i) for i in range(36)]),
            twist=TwistWithCovariance_(Twist_(Vector3_(1, 0, 0), Vector3_(0, 0, 2)),
                                       [0.5] * 36))
    raise ValueError(name)


TYPES = {
    "String": ("std_msgs", String_, False),
    "Twist": ("geometry_msgs", Twist_, True),  # best effort, as cmd_vel often is
    "LaserScan": ("sensor_msgs", LaserScan_, False),
    "Odometry": ("nav_msgs", Odometry_, False),
}


@pytest.mark.parametrize("name", list(TYPES))
def test_ada_to_python(name):
    pkg, cls, best = TYPES[name]
    topic = f"/interop/{name.lower()}_a2p"
    dp = ps.participant()
    rd = ps.reader(dp, "rt" + topic, cls, reliable=not best)
    ada = ps.start("pubsub_peer", "pub", pkg, name, topic, 40,
                   *(["best_effort"] if best else []))
    got = ps.take_until(rd, 3, timeout=15)
    out = ps.finish(ada)
    assert len(got) >= 3, f"nothing from Ada; Ada said:\n{out}"
    for sample in got:
        if name in ("String", "Twist"):
            # The n-th message carries n: find it from the sample itself.
            n = (int(sample.data.split(":")[1]) if name == "String"
                 else round(sample.angular.z / 0.75))
        else:
            n = 1
        assert sample == ada_values(name, n), (sample, ada_values(name, n))


def check_echoes(ada, wr, rd, message, who, count=3):
    """Writes message(1), message(2), ... on `wr` every 0.1 s, taking what the
    Ada echo peer `ada` (echoing until stopped) sends back on `rd`, until
    `count` echoes came (at most 15 s), then stops it; each echo must be one
    of the messages sent. The first echoes may be lost: the Ada writer can
    match `rd` after the Ada reader matched `wr`."""
    sent = []
    echoed = []
    deadline = time.monotonic() + 15
    n = 0
    while len(echoed) < count and ada.poll() is None and time.monotonic() < deadline:
        n += 1
        msg = message(n)
        wr.write(msg)
        sent.append(msg)
        time.sleep(0.1)
        echoed.extend(ps.take(rd))
    out = ps.stop(ada)
    assert len(echoed) >= count, f"{len(echoed)} echoes of {n} from {who}; it said:\n{out}"
    for e in echoed:
        assert e in sent, (e, sent)


@pytest.mark.parametrize("name", list(TYPES))
def test_python_to_ada_echo(name):
    pkg, cls, best = TYPES[name]
    topic = f"/interop/{name.lower()}_p2a"
    dp = ps.participant()
    wr = ps.writer(dp, "rt" + topic, cls, reliable=not best)
    rd = ps.reader(dp, "rt" + topic + "_echo", cls, reliable=not best)
    ada = ps.start("pubsub_peer", "echo", pkg, name, topic, topic + "_echo",
                   ps.ECHO_UNTIL_STOPPED, *(["best_effort"] if best else []))
    assert ps.wait_matched(wr) and ps.wait_matched(rd), "Ada endpoints not discovered"
    check_echoes(ada, wr, rd, lambda n: python_values(name, n), "Ada")


def test_qos_mismatch_no_delivery():
    """A reliable reader does not match a best-effort writer: nothing is
    delivered (as in DDS), while a best-effort reader on the same topic gets
    the data."""
    dp = ps.participant()
    topic = "rt/interop/qos_mismatch"
    reliable = ps.reader(dp, topic, Twist_, reliable=True)
    control = ps.reader(dp, topic, Twist_, reliable=False)
    ada = ps.start("pubsub_peer", "pub", "geometry_msgs", "Twist", "/interop/qos_mismatch",
                   30, "best_effort")
    got = ps.take_until(control, 3, timeout=15)
    ps.finish(ada)
    assert len(got) >= 3, "control reader received nothing"
    assert ps.take(reliable) == []
    assert reliable.get_subscription_matched_status().total_count == 0


# The generated (static) message path: bin/typed_peer publishes and echoes
# ROSIDL.Static records through RCL.Nodes.Typed.
HEADER_TYPED = Header_(stamp=Time_(sec=1_700_000_123, nanosec=456_789), frame_id="base_laser")


def typed_values(name):
    """What bin/typed_peer publishes."""
    if name in ("LaserScan", "Odometry"):
        return ada_values(name, 1)
    if name == "OccupancyGrid":
        return OccupancyGrid_(
            header=HEADER_TYPED,
            info=MapMetaData_(map_load_time=Time_(3, 4), resolution=float32_of(0.05),
                              width=100, height=50,
                              origin=Pose_(Point_(-25.0, -25.0, 0.0), Quaternion_(0, 0, 0, 1.0))),
            data=[(i % 101) - (1 if i % 3 == 0 else 0) for i in range(100 * 50)])
    raise ValueError(name)


TYPED = {"LaserScan": LaserScan_, "Odometry": Odometry_, "OccupancyGrid": OccupancyGrid_}


@pytest.mark.parametrize("name", list(TYPED))
def test_typed_ada_to_python(name):
    topic = f"/interop/typed_{name.lower()}_a2p"
    dp = ps.participant()
    rd = ps.reader(dp, "rt" + topic, TYPED[name])
    ada = ps.start("typed_peer", "pub", name, topic, 40)
    got = ps.take_until(rd, 3, timeout=15)
    out = ps.finish(ada)
    assert len(got) >= 3, f"nothing from the typed Ada peer; it said:\n{out}"
    for sample in got:
        assert sample == typed_values(name), (sample, typed_values(name))


@pytest.mark.parametrize("name", list(TYPED))
def test_typed_python_to_ada_echo(name):
    topic = f"/interop/typed_{name.lower()}_p2a"
    dp = ps.participant()
    wr = ps.writer(dp, "rt" + topic, TYPED[name])
    rd = ps.reader(dp, "rt" + topic + "_echo", TYPED[name])
    ada = ps.start("typed_peer", "echo", name, topic, topic + "_echo", ps.ECHO_UNTIL_STOPPED)
    assert ps.wait_matched(wr) and ps.wait_matched(rd), "typed Ada endpoints not discovered"

    def message(n):
        return (python_values(name, n) if name != "OccupancyGrid"
                else OccupancyGrid_(header=Header_(Time_(n, 1), "map"),
                                    info=MapMetaData_(width=3, height=2),
                                    data=[n, -n, 0, 127, -128, 5]))

    check_echoes(ada, wr, rd, message, "the typed Ada peer")
