"""The rclada verbs added with issue 13, against running nodes, with the ros2
command's output: topic type/find/bw/delay, service type/find, param
load/delete."""
import subprocess
import threading
import time

import pytest

import pubsub_support as ps
from ros_types import Header_, PoseStamped_, String_, Time_


def rclada(*args, timeout=30):
    return subprocess.run([str(ps.BIN / "rclada"), *args], capture_output=True, text=True,
                          timeout=timeout)


@pytest.fixture(scope="module")
def demo():
    proc = subprocess.Popen([str(ps.BIN / "parameters_demo")], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    dp = ps.participant()
    chatter = ps.writer(dp, "rt/verbs_chatter", String_)
    poses = ps.writer(dp, "rt/verbs_pose", PoseStamped_)
    stopping = []

    def feed():
        while not stopping:
            chatter.write(String_(data="hello"))
            now = time.time()
            poses.write(PoseStamped_(header=Header_(stamp=Time_(
                sec=int(now), nanosec=int((now % 1) * 1e9)), frame_id="map")))
            time.sleep(0.05)
    t = threading.Thread(target=feed, daemon=True)
    t.start()
    time.sleep(1.0)
    yield
    stopping.append(1)
    t.join()
    proc.terminate()
    proc.wait(5)


def test_types_and_finds(demo):
    assert rclada("topic", "type", "/verbs_chatter").stdout == "std_msgs/msg/String\n"
    assert "/verbs_chatter" in rclada("topic", "find", "std_msgs/msg/String").stdout.splitlines()
    assert rclada("service", "type", "/parameters_demo/get_parameters").stdout == \
        "rcl_interfaces/srv/GetParameters\n"
    assert "/parameters_demo/get_parameters" in \
        rclada("service", "find", "rcl_interfaces/srv/GetParameters").stdout.splitlines()
    bad = rclada("topic", "type", "/no_such_topic")
    assert bad.returncode == 1 and "Unknown topic '/no_such_topic'" in bad.stderr


def test_bw_and_delay(demo):
    r = subprocess.run(f"'{ps.BIN / 'rclada'}' topic bw /verbs_chatter | head -3", shell=True,
                       capture_output=True, text=True, timeout=30, executable="/bin/bash")
    lines = r.stdout.splitlines()
    assert lines[0] == "Subscribed to [/verbs_chatter]", r.stdout
    # std_msgs/String "hello": 4 + 4 + 6 bytes, padded to 16; about 20 messages/s.
    assert lines[1].endswith("messages") and " B/s from " in lines[1], r.stdout
    rate = int(lines[1].split()[0])
    assert 150 <= rate <= 500, r.stdout
    assert lines[2] == "\tMessage size mean: 16 B min: 16 B max: 16 B", r.stdout
    d = subprocess.run(f"'{ps.BIN / 'rclada'}' topic delay /verbs_pose | head -2", shell=True,
                       capture_output=True, text=True, timeout=30, executable="/bin/bash")
    lines = d.stdout.splitlines()
    assert lines[0].startswith("average delay: "), d.stdout
    assert 0.0 <= float(lines[0].split()[-1]) < 0.5, d.stdout
    assert lines[1].startswith("\tmin: ") and "window:" in lines[1], d.stdout


def test_param_load_and_delete(demo, tmp_path):
    f = tmp_path / "p.yaml"
    f.write_text("parameters_demo:\n  ros__parameters:\n    rate: 20\n    gain: 2.5\n"
                 "other_node:\n  ros__parameters:\n    rate: 99\n")
    r = rclada("param", "load", "/parameters_demo", str(f))
    assert r.stdout.splitlines() == ["Set parameter rate successful",
                                     "Set parameter gain successful"], r.stdout + r.stderr
    assert rclada("param", "get", "/parameters_demo", "rate").stdout.strip() == \
        "Integer value is: 20"
    d = rclada("param", "delete", "/parameters_demo", "rate")
    assert d.returncode == 1
    assert "Deleting parameter failed: cannot undeclare a statically typed parameter" in d.stderr
