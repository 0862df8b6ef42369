"""Typed actions (RCL.Actions.Typed over the generated
example_interfaces/action/Fibonacci records), both ways, on the rclpy action
protocol: the typed Ada server (examples/typed_fibonacci server) against a
Python peer implementing rclpy's action client, and the typed Ada client
(typed_fibonacci client) against a Python peer implementing rclpy's action
server."""
import re
import subprocess

import pytest

import pubsub_support as ps
from action_support import (FIB, STATUS, ActionClient, ActionServer, check_cancel,
                            check_goal_result)


@pytest.fixture(scope="module")
def client():
    proc = subprocess.Popen([str(ps.BIN / "typed_fibonacci"), "server", "typed_fib", "0.05"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        dp = ps.participant()
        c = ActionClient(dp, "/typed_fib")
        assert c.wait_for_server(15), "the typed Ada action server's services are not matched"
        yield c
    finally:
        proc.terminate()
        try:
            proc.communicate(timeout=5)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()


def test_typed_server_goal_feedback_result(client):
    _, feedback = check_goal_result(client, 7)
    # One number more per step: [0, 1, 1], [0, 1, 1, 2], ... up to the result.
    assert feedback and feedback[0] == FIB[:3] and feedback[-1] == FIB[:8], feedback


def test_typed_server_two_goals_and_rejection(client):
    goals = [client.send_goal(n) for n in (5, 9)]
    assert all(resp.accepted for _, _, resp in goals)
    for (_, gid, _), n in zip(goals, (5, 9)):
        res = client.get_result(gid)
        assert res is not None and STATUS[res.status] == "SUCCEEDED"
        assert list(res.sequence) == FIB[:n + 1]
    _, gid, resp = client.send_goal(-4)
    assert not resp.accepted


def test_typed_server_cancel(client):
    check_cancel(client, after=0.3)


def test_typed_client_against_python_server():
    dp = ps.participant()
    server = ActionServer(dp, "/typed_fib_py", step=0.03, await_reader=2.0)
    try:
        ok = subprocess.run([str(ps.BIN / "typed_fibonacci"), "client", "6", "typed_fib_py", "20"],
                            capture_output=True, text=True, timeout=60)
        out = ok.stdout + ok.stderr
        assert ok.returncode == 0, out
        assert "result (SUCCEEDED): [ 0, 1, 1, 2, 3, 5, 8 ]" in out, out
        assert out.count("feedback of ") >= 2, out
        # The status topic (On_Status) gives the client's own goal. Its QoS is
        # rcl_action's keep last 1: a client busy with feedback may see only a
        # later array (CI at load ~8: SUCCEEDED only, no EXECUTING), never a
        # status its goal did not reach, nor one after SUCCEEDED.
        own = re.search(r"goal ([0-9a-f]{32}) accepted", out).group(1)
        seen = re.findall(rf"status of {own}: (\w+)", out)
        assert seen, out
        assert set(seen) <= {"ACCEPTED", "EXECUTING", "SUCCEEDED"}, out
        assert "SUCCEEDED" not in seen[:-1], out
        rejected = subprocess.run([str(ps.BIN / "typed_fibonacci"), "client", "-2", "typed_fib_py",
                                   "20"], capture_output=True, text=True, timeout=60)
        assert rejected.returncode == 1
        assert "rejected" in rejected.stdout + rejected.stderr
    finally:
        server.stop()
