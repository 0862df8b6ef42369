"""The ROS 2 command line (--ros-args) as rcl reads it, seen from a peer:
remapped topic and node names, node-specific rules, the enclave in the
participant's USER_DATA, log levels; bad arguments rejected naming them;
parameter services on every node; timers and a Rate on simulated time
counted against the /clock a Python peer publishes; rclada topic hz | head."""
import re
import subprocess
import time

import pytest

import pubsub_support as ps
from cyclonedds.builtin import BuiltinDataReader, BuiltinTopicDcpsParticipant
from cyclonedds.core import Policy
from ros_types import Clock_, String_, Time_


def rclada(*args, timeout=30):
    return subprocess.run([str(ps.BIN / "rclada"), *args], capture_output=True, text=True,
                          timeout=timeout)


def stop(proc):
    return ps.stop(proc, grace=5)


def test_remapping_seen_from_a_peer():
    dp = ps.participant()
    news = ps.reader(dp, "rt/robot1/news", String_)
    parts = BuiltinDataReader(dp, BuiltinTopicDcpsParticipant)
    proc = ps.start("talker", "--ros-args", "-r", "/chatter:=news", "-r", "__ns:=/robot1",
                 "-r", "__node:=speaker", "-e", "/robot1")
    try:
        deadline = time.monotonic() + 10
        got = []
        while time.monotonic() < deadline and not got:
            got = [s.data for s in news.take(N=10) if isinstance(s, String_)]
            time.sleep(0.05)
        assert got and got[0].startswith("Hello World"), "nothing on /robot1/news"
        assert "/robot1/speaker" in rclada("node", "list").stdout.splitlines()
        topics = rclada("topic", "list").stdout.splitlines()
        assert "/robot1/news" in topics and "/chatter" not in topics, topics
        enclaves = {p.qos[Policy.Userdata].data for p in parts.take(N=100)
                    if Policy.Userdata in p.qos}
        assert b"enclave=/robot1;" in enclaves, enclaves
        # Parameter services on every node (talker never asks for them).
        assert "use_sim_time" in rclada("param", "list", "/robot1/speaker").stdout
    finally:
        stop(proc)


def test_node_specific_rules():
    dp = ps.participant()
    mine = ps.reader(dp, "rt/mine", String_)
    other = ps.reader(dp, "rt/not_mine", String_)
    proc = ps.start("talker", "--ros-args", "-r", "someone_else:/chatter:=/not_mine",
                 "-r", "talker:/chatter:=/mine")
    try:
        deadline = time.monotonic() + 10
        got = []
        while time.monotonic() < deadline and not got:
            got = [s for s in mine.take(N=10) if isinstance(s, String_)]
            time.sleep(0.05)
        assert got, "the rule for node 'talker' was not applied"
        assert not [s for s in other.take(N=10) if isinstance(s, String_)]
    finally:
        stop(proc)


@pytest.mark.parametrize("args,named", [
    (["--bogus"], "'--bogus'"),
    (["-r", "nonsense"], "'nonsense': expected from:=to"),
    (["-r", "__ns:=bad//ns"], "'__ns:=bad//ns'"),
    (["-r", "a:=b c"], "'a:=b c'"),
    (["--log-level", "loud"], "unknown log level 'loud'"),
    (["-e"], "-e needs a value"),
])
def test_bad_ros_args_are_rejected(args, named):
    r = subprocess.run([str(ps.BIN / "parameters_demo"), "--ros-args", *args],
                       capture_output=True, text=True, timeout=20)
    assert r.returncode == 2, (r.returncode, r.stdout, r.stderr)
    assert named in r.stdout + r.stderr, r.stdout + r.stderr


def test_log_level():
    proc = ps.start("parameters_demo", "--ros-args", "--log-level", "warn")
    time.sleep(2.0)
    assert "parameters ready" not in stop(proc)
    proc = ps.start("parameters_demo", "--ros-args", "--log-level", "parameters_demo:=error",
                 "--log-level", "info")
    time.sleep(2.0)
    assert "parameters ready" not in stop(proc), "the logger's own level must win"


def tick_times(text, kind="tick"):
    return [float(t) for t in re.findall(rf"^{kind} \d+ at +([0-9.]+)", text, re.M)]


def test_timers_follow_sim_time():
    dp = ps.participant()
    clock = ps.writer(dp, "rt/clock", Clock_, reliable=False, depth=1)

    def at(ns):
        clock.write(Clock_(clock=Time_(sec=ns // 10**9, nanosec=ns % 10**9)))

    demo = ps.Watched(ps.start("timer_demo", "1.0", "--ros-args", "-p", "use_sim_time:=true"))
    try:
        assert ps.wait_matched(clock, 10), "timer_demo did not subscribe to /clock"
        # 100 s until the demo ticks on it (ROS time jumps from 0): its side
        # of the match is made, no later step is lost for want of it.
        assert demo.wait(tick_times, 20, feed=lambda: at(100 * 10**9)), \
            "timer_demo never ticked on /clock at 100 s within 20 s:\n" + demo.text()
        # 12 s of simulated time in about 2.4 s of wall time, 0.1 s steps.
        for k in range(1, 121):
            at(100 * 10**9 + k * 10**8)
            time.sleep(0.02)
        # The last step (112 s, repeated: the clock stays there) until its tick.
        assert demo.wait(lambda text: max(tick_times(text)) >= 112.0, 20,
                         feed=lambda: at(112 * 10**9)), \
            "no tick at 112 s of simulated time within 20 s:\n" + demo.text()
        # The clock stands still: nothing more may tick.
        time.sleep(1.5)
    finally:
        out = demo.stop(grace=5)
    ticks, rates = tick_times(out), tick_times(out, "rate")
    on_grid = [t for t in ticks if 100.5 < t <= 112.05]
    assert len(on_grid) == 12, ticks
    assert all(t >= 100.0 for t in ticks), ticks
    assert 11 <= len([t for t in rates if 100.5 < t <= 112.05]) <= 12, rates


def test_topic_hz_into_head():
    dp = ps.participant()
    w = ps.writer(dp, "rt/hz_head", String_)
    stopping = []

    import threading

    def feed():
        while not stopping:
            w.write(String_(data="x"))
            time.sleep(0.02)
    t = threading.Thread(target=feed, daemon=True)
    t.start()
    try:
        r = subprocess.run(f"'{ps.BIN / 'rclada'}' topic hz /hz_head std_msgs/msg/String | head -1",
                           shell=True, capture_output=True, text=True, timeout=30,
                           executable="/bin/bash")
        assert r.stdout.count("\n") == 1, r.stdout
        assert "exception" not in r.stderr.lower() and "raised" not in r.stderr, r.stderr
    finally:
        stopping.append(1)
        t.join()
