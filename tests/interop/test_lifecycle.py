"""Lifecycle (managed) nodes on the ROS 2 wire, both ways: the Ada managed
node (examples/lifecycle_talker, RCL.Lifecycle) driven by a Python peer
implementing the lifecycle_msgs protocol (services, transition events,
lifecycle publisher silent unless active); the rclada lifecycle verbs
against it and against a Python managed node."""
import subprocess
import time

import pytest

import pubsub_support as ps
from lifecycle_support import LifecycleClient, LifecycleServer
from ros_types import String_


def rclada(*args, timeout=30):
    return subprocess.run([str(ps.BIN / "rclada"), *args], capture_output=True, text=True,
                          timeout=timeout)


@pytest.fixture(scope="module")
def talker():
    proc = subprocess.Popen([str(ps.BIN / "lifecycle_talker")], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    dp = ps.participant()
    client = LifecycleClient(dp, "/lc_talker")
    chatter = ps.reader(dp, "rt/lifecycle_chatter", String_)
    assert client.wait(), "the managed node's services are not matched"
    yield client, chatter
    proc.terminate()
    try:
        proc.communicate(timeout=5)
    except subprocess.TimeoutExpired:
        proc.kill()


def received(chatter, seconds):
    time.sleep(seconds)
    return [s.data for s in chatter.take(N=100) if isinstance(s, String_)]


def test_state_machine_and_events(talker):
    client, chatter = talker
    assert client.state() == ("unconfigured", 1)
    assert client.transitions() == [("configure", 1, "unconfigured", "configuring"),
                                    ("shutdown", 5, "unconfigured", "shuttingdown")]
    assert not client.change(3), "activate is not allowed when unconfigured"
    assert client.change(1)
    assert client.state() == ("inactive", 2)
    got, deadline = [], time.monotonic() + 10
    while len(got) < 2 and time.monotonic() < deadline:  # the two events of configure
        got += client.take_events()
        time.sleep(0.02)
    assert got == [(1, "configure", "unconfigured", "configuring"),
                   (10, "transition_success", "configuring", "inactive")], got
    assert received(chatter, 0.6) == [], "an inactive lifecycle publisher published"
    assert client.change(label="activate")
    assert client.state() == ("active", 3)
    msgs = received(chatter, 1.0)
    assert len(msgs) >= 2 and all(m.startswith("Lifecycle HelloWorld #") for m in msgs), msgs
    assert client.change(4)
    received(chatter, 0.3)
    assert received(chatter, 0.6) == [], "publishing went on after deactivate"
    assert client.change(2) and client.state() == ("unconfigured", 1)


def test_rclada_lifecycle_verbs(talker):
    assert "/lc_talker" in rclada("lifecycle", "nodes").stdout.splitlines()
    assert rclada("lifecycle", "get", "/lc_talker").stdout.strip() == "unconfigured [1]"
    listing = rclada("lifecycle", "list", "/lc_talker").stdout
    assert listing == ("- configure [1]\n\tStart: unconfigured\n\tGoal: configuring\n"
                       "- shutdown [5]\n\tStart: unconfigured\n\tGoal: shuttingdown\n"), listing
    r = rclada("lifecycle", "set", "/lc_talker", "configure")
    assert r.returncode == 0 and r.stdout.strip() == "Transitioning successful", r.stderr
    assert rclada("lifecycle", "get", "/lc_talker").stdout.strip() == "inactive [2]"
    bad = rclada("lifecycle", "set", "/lc_talker", "deactivate")
    assert bad.returncode == 1 and "Unknown transition requested" in bad.stderr
    assert "- activate [3]" in bad.stderr
    assert rclada("lifecycle", "set", "/lc_talker", "cleanup").returncode == 0


def test_rclada_against_python_managed_node():
    dp = ps.participant()
    server = LifecycleServer(dp, "/py_managed")
    try:
        assert rclada("lifecycle", "get", "/py_managed").stdout.strip() == "unconfigured [1]"
        r = rclada("lifecycle", "set", "/py_managed", "configure")
        assert r.stdout.strip() == "Transitioning successful", r.stderr
        assert server.state == "inactive"
        assert rclada("lifecycle", "set", "/py_managed", "activate").returncode == 0
        assert rclada("lifecycle", "get", "/py_managed").stdout.strip() == "active [3]"
    finally:
        server.stop()


def test_sancta_agent_as_managed_node():
    """`sancta run --managed`: the agent is /sancta_Ari, unconfigured until a
    lifecycle client configures it; its components run only while active,
    are created anew after a deactivate, and shutdown ends the program."""
    proc = subprocess.Popen([str(ps.BIN / "sancta"), "run",
                             str(ps.REPO / "share" / "config" / "team.xml"),
                             "--agent", "Ari", "--managed", "--for", "60"],
                            cwd=ps.REPO, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    try:
        node = "/sancta_Ari"
        deadline = time.monotonic() + 20
        while node not in rclada("lifecycle", "nodes").stdout.splitlines():
            assert time.monotonic() < deadline, "the agent's managed node never appeared"
            time.sleep(0.5)
        assert rclada("lifecycle", "get", node).stdout.strip() == "unconfigured [1]"
        bad = rclada("lifecycle", "set", node, "activate")
        assert bad.returncode != 0, "activate from unconfigured was accepted"
        for transition, state in (("configure", "inactive [2]"), ("activate", "active [3]"),
                                  ("deactivate", "inactive [2]"), ("activate", "active [3]"),
                                  ("deactivate", "inactive [2]"),
                                  ("cleanup", "unconfigured [1]")):
            r = rclada("lifecycle", "set", node, transition)
            assert r.returncode == 0 and "Transitioning successful" in r.stdout, (transition, r)
            assert rclada("lifecycle", "get", node).stdout.strip() == state, transition
        assert rclada("lifecycle", "set", node, "shutdown").returncode == 0
        out = ps.finish(proc, timeout=20)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 0, out
    assert "stopping: every agent finalized" in out, out
    assert out.count("agent Ari started with 4 component(s)") == 2, out
    assert out.count("agent Ari stopped") == 2, out
    assert out.index("configured: components created") < out.index("agent Ari started"), out
