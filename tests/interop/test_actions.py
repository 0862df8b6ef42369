"""Actions on the ROS 2 wire, both ways: the Ada action server
(examples/fibonacci_server, RCL.Actions.Servers) against a Python peer
implementing rclpy's action client protocol, and the Ada action client
(rclada action send_goal, RCL.Actions.Clients) against a Python peer
implementing rclpy's action server protocol; the rclada action verbs."""
import subprocess

import pytest

import pubsub_support as ps
from action_support import (FIB, STATUS, ActionClient, ActionServer, check_cancel,
                            check_goal_result)


def rclada(*args, timeout=30):
    return subprocess.run([str(ps.BIN / "rclada"), *args], capture_output=True, text=True,
                          timeout=timeout)


@pytest.fixture(scope="module")
def ada_server():
    proc = subprocess.Popen([str(ps.BIN / "fibonacci_server"), "fibonacci", "0.05"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    yield proc
    proc.terminate()
    try:
        proc.communicate(timeout=5)
    except subprocess.TimeoutExpired:
        proc.kill()


@pytest.fixture(scope="module")
def client(ada_server):
    dp = ps.participant()
    c = ActionClient(dp, "/fibonacci")
    assert c.wait_for_server(15), "the Ada action server's services are not matched"
    return c


def test_goal_feedback_result(client):
    hex_id, feedback = check_goal_result(client, 6)
    assert len(feedback) >= 3 and feedback[-1] == FIB[:7], feedback
    assert any((hex_id, 4) in s for s in client.statuses), client.statuses[-3:]


def test_several_goals_at_once(client):
    goals = [client.send_goal(n) for n in (9, 4, 7)]
    assert all(resp.accepted for _, _, resp in goals)
    for (hex_id, gid, _), n in zip(goals, (9, 4, 7)):
        res = client.get_result(gid)
        assert res is not None and res.status == 4 and list(res.sequence) == FIB[:n + 1]
    client.poll()
    both = [s for s in client.statuses if sum(1 for _, st in s if st == 2) >= 2]
    assert both, "the status topic never showed two goals executing at once"


def test_rejected_goal(client):
    _, gid, resp = client.send_goal(-1)
    assert not resp.accepted
    res = client.get_result(gid)
    assert res is not None and STATUS[res.status] == "UNKNOWN"


def test_cancel(client):
    gid = check_cancel(client, after=0.4)
    again = client.cancel(gid)
    assert again.return_code == 3  # ERROR_GOAL_TERMINATED
    unknown = client.cancel(type(gid)(uuid=[7] * 16))
    assert unknown.return_code == 2  # ERROR_UNKNOWN_GOAL_ID


def test_action_cli_graph(client):
    out = rclada("action", "list", "-t").stdout
    assert "/fibonacci [example_interfaces/action/Fibonacci]" in out.splitlines(), out
    info = rclada("action", "info", "/fibonacci").stdout
    assert "Action: /fibonacci" in info and "Action servers: 1" in info, info
    assert "    /fibonacci_server" in info.splitlines(), info
    assert rclada("action", "type", "/fibonacci").stdout.strip() == \
        "example_interfaces/action/Fibonacci"
    bad = rclada("action", "info", "/nothing_here")
    assert bad.returncode == 1 and "not found" in bad.stderr


def test_ada_client_against_python_server():
    dp = ps.participant()
    server = ActionServer(dp, "/fib_py", step=0.03)
    try:
        r = rclada("action", "send_goal", "/fib_py", "example_interfaces/action/Fibonacci",
                   "{order: 5}", "--feedback")
        assert r.returncode == 0, r.stderr
        lines = r.stdout.splitlines()
        assert "Waiting for an action server to become available..." in lines
        assert any(l.startswith("Goal accepted with ID: ") and len(l.split()[-1]) == 32
                   for l in lines), r.stdout
        assert lines.count("Feedback:") >= 2, r.stdout
        result = lines[lines.index("Result:") + 1:]
        assert result[:7] == ["    sequence:"] + [f"    - {n}" for n in FIB[:6]], r.stdout
        assert lines[-1] == "Goal finished with status: SUCCEEDED", r.stdout
        rejected = rclada("action", "send_goal", "/fib_py", "example_interfaces/action/Fibonacci",
                          "{order: -3}")
        assert rejected.returncode == 0 and "Goal was rejected." in rejected.stdout
    finally:
        server.stop()
