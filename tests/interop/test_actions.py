"""Actions on the ROS 2 wire, both ways: the Ada action server
(examples/fibonacci_server, RCL.Actions.Servers) against a Python peer
implementing rclpy's action client protocol, and the Ada action client
(rclada action send_goal, RCL.Actions.Clients) against a Python peer
implementing rclpy's action server protocol; the rclada action verbs."""
import os
import subprocess
import time

import pytest
from cyclonedds.qos import Policy
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

import pubsub_support as ps
from action_support import (FIB, STATUS, UUID, ActionClient, ActionServer, GoalStatusArray,
                            ScriptedStatusServer, check_cancel, check_goal_result,
                            services_only, status_qos, uuid_hex)


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


def status_profile(qos):
    """(history, reliability kind, durability) of a matched endpoint's QoS."""
    reliable = isinstance(qos[Policy.Reliability], Policy.Reliability.Reliable)
    return qos[Policy.History], "Reliable" if reliable else "BestEffort", qos[Policy.Durability]


RCL_ACTION_STATUS = (Policy.History.KeepLast(1), "Reliable", Policy.Durability.TransientLocal)
# rcl_action_qos_profile_status_default


def test_server_status_topic(client):
    """The Ada server's status topic: each goal goes ACCEPTED or EXECUTING,
    then SUCCEEDED (never back); the writer has rcl_action's status QoS,
    and a reader joining late gets the last array (transient local)."""
    hex_id, _ = check_goal_result(client, 4)
    seen = [dict(s).get(hex_id) for s in client.statuses if hex_id in dict(s)]
    assert seen and seen[-1] == 4 and seen[0] in (1, 2), seen
    assert seen == sorted(seen) and set(seen) <= {1, 2, 4}, seen
    dp = ps.participant()
    late = DataReader(dp, Topic(dp, "rt/fibonacci/_action/status", GoalStatusArray),
                      qos=status_qos())
    assert ps.wait_matched(late, 10), "the Ada server's status writer is not matched"
    writers = [late.get_matched_publication_data(h).qos for h in late.get_matched_publications()]
    assert [status_profile(q) for q in writers] == [RCL_ACTION_STATUS], writers
    arrays = ps.take_until(late, 1, timeout=10)
    assert arrays, "a late status reader got no status array (not transient local?)"
    last = {uuid_hex(g.goal_info.goal_id): g.status for g in arrays[-1].status_list}
    assert last.get(hex_id) == 4, last


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
    # The status topic ends the goal CANCELED (the last array stays until read),
    # never going back (executing, canceling, canceled).
    hex_id, deadline = uuid_hex(gid), time.monotonic() + 10
    while 5 not in [dict(s).get(hex_id) for s in client.statuses] and time.monotonic() < deadline:
        client.poll()
        time.sleep(0.02)
    seen = [dict(s)[hex_id] for s in client.statuses if hex_id in dict(s)]
    assert seen and seen[-1] == 5 and seen == sorted(seen) and set(seen) <= {1, 2, 3, 5}, seen


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
    server = ActionServer(dp, "/fib_py", step=0.03, await_reader=2.0)
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


def test_ada_client_waits_for_feedback_and_status_publishers():
    """A peer offering only the three services of an action is no action
    server (rcl_action_server_is_available): rclada action send_goal
    --feedback waits for the status and feedback publishers too, then times
    out saying what is missing, sending no goal. Before, the services alone
    let it send the goal, and feedback published before its feedback reader
    matched was lost (0 'Feedback:' lines in a fresh-clone CI run)."""
    dp = ps.participant()
    half = services_only(dp, "/fib_half")
    started = time.monotonic()
    r = rclada("action", "send_goal", "/fib_half", "example_interfaces/action/Fibonacci",
               "{order: 2}", "--feedback", "--timeout", "1.5")
    took = time.monotonic() - started
    assert r.returncode == 1, r.stdout + r.stderr
    assert "action /fib_half: no server available after" in r.stderr, r.stderr
    assert "(missing: status publisher, feedback publisher)" in r.stderr, r.stderr
    assert "Sending goal:" not in r.stdout, r.stdout
    assert not half.pairs["send_goal"][0].take(N=4), "a goal was sent"
    assert took < 10, took


def test_ada_client_follows_its_goal_status():
    """rclada action send_goal --status against a server whose status topic
    plays a script: the client prints its own goal's status changes in
    order, ignores other goals (even with statuses that are no GoalStatus),
    reports an entry of its goal with status 9 (value and goal) and keeps
    the entries after it; its status reader has rcl_action's status QoS."""
    other_a, other_b = UUID(uuid=list(os.urandom(16))), UUID(uuid=list(os.urandom(16)))

    def script(own):
        return [[(own, 1), (other_a, 2)],
                [(other_a, 9), (own, 2), (other_b, 6)],
                [(own, 9), (other_a, 5)],
                [(other_b, 3), (own, 2)],
                [(other_a, 1), (own, 4), (other_b, -3)]]

    dp = ps.participant()
    server = ScriptedStatusServer(dp, "/fib_status", script)
    try:
        r = rclada("action", "send_goal", "/fib_status", "example_interfaces/action/Fibonacci",
                   "{order: 2}", "--status")
    finally:
        server.stop()
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    own = next(l.split()[-1] for l in lines if l.startswith("Goal accepted with ID: "))
    statuses = [l for l in lines if l.startswith("Goal status: ")]
    assert statuses == ["Goal status: ACCEPTED", "Goal status: EXECUTING",
                        "Goal status: SUCCEEDED"], r.stdout
    assert lines.index(statuses[-1]) < lines.index("Result:"), r.stdout
    assert lines[-1] == "Goal finished with status: SUCCEEDED", r.stdout
    errors = r.stderr.splitlines()
    assert len(errors) == 1, r.stderr
    assert f"goal {own} status 9," in errors[0] and "no goal status" in errors[0], errors
    assert "stays EXECUTING" in errors[0], errors
    assert uuid_hex(other_a) not in r.stderr + r.stdout, r.stderr
    assert [status_profile(q) for q in server.readers_qos] == [RCL_ACTION_STATUS], \
        server.readers_qos


CHURN = 1000  # goals sent by the goal-lifetime tests


def test_ada_client_goal_set_stays_bounded():
    """tests/src/tools/action_churn: the Ada client sends 1000 goals one
    after the other to an rclpy-protocol server and takes each result; the
    set of goals it follows stays small (it drops a goal once its result
    was taken and the status topic ended it; before, it kept all 1000)
    and is empty at the end."""
    dp = ps.participant()
    server = ActionServer(dp, "/churn_py", step=0.002, result_timeout=3.0)
    try:
        r = subprocess.run([str(ps.BIN / "action_churn"), "client", "/churn_py", str(CHURN)],
                           capture_output=True, text=True, timeout=300)
    finally:
        server.stop()
    assert r.returncode == 0, r.stdout + r.stderr
    rows = [l.split() for l in r.stdout.splitlines() if l.startswith("goals ")]
    assert [int(x[1]) for x in rows] == list(range(100, CHURN + 1, 100)), r.stdout
    followed = [int(x[3]) for x in rows]
    # Before: every goal sent (100, 200, ... 1000). Now at most the goals
    # whose result came within Status_Linger (2 s) but whose terminal status
    # did not come yet: 0 or 1 measured (9 in process, AUnit).
    assert max(followed) < 100, r.stdout
    assert r.stdout.splitlines()[-1].startswith("done followed 0 "), r.stdout
    print(r.stdout)


def test_ada_server_goal_set_stays_bounded():
    """tests/src/tools/action_churn server with a 2 s result timeout: an
    rclpy-protocol client sends 1000 goals and takes each result; every
    status array it gets lists no goal whose result it got more than the
    timeout (plus 2 s of margin) before (the server drops expired goals,
    which it did before only while publishing), the server keeps fewer
    than half of the goals, and once idle drops them all and publishes an
    empty array (a late reader gets it; before, the last array stayed); an
    expired goal's result is UNKNOWN and its cancel ERROR_UNKNOWN_GOAL_ID."""
    timeout = 2.0
    watched = ps.Watched(ps.start("action_churn", "server", "churn_ada", timeout))
    try:
        dp = ps.participant()
        c = ActionClient(dp, "/churn_ada")
        assert c.wait_for_server(15), "the Ada churn server's services are not matched"
        started, first, taken, longest = time.monotonic(), None, {}, 0
        for i in range(CHURN):
            before = time.monotonic()
            hex_id, gid, resp = c.send_goal(i % 5)
            assert resp.accepted
            res = c.get_result(gid)
            assert res is not None and res.status == 4 and list(res.sequence) == [i % 5], res
            taken[hex_id] = time.monotonic()
            first = first or gid
            # The arrays polled during the two calls (after `before`): none may
            # list a goal whose result came more than timeout + 2 s before.
            stale = [g for s in c.statuses for g, _ in s
                     if g in taken and taken[g] < before - timeout - 2.0]
            assert not stale, f"goal {i}: arrays still list goals ended long ago: {stale[:3]}"
            longest = max([longest] + [len(s) for s in c.statuses])
            c.statuses.clear()
        rate = CHURN / (time.monotonic() - started)
        assert watched.wait(lambda out: "\nkept 0 " in out, timeout + 10), watched.text()[-500:]
        rows = [l.split() for l in watched.text().splitlines() if l.startswith("kept ")]
        kept = [int(x[1]) for x in rows]
        assert max(kept) < CHURN // 2, max(kept)
        res = c.get_result(first)
        assert res is not None and STATUS[res.status] == "UNKNOWN"
        assert c.cancel(first).return_code == 2  # ERROR_UNKNOWN_GOAL_ID
        late = DataReader(dp, Topic(dp, "rt/churn_ada/_action/status", GoalStatusArray),
                          qos=status_qos())
        arrays = ps.take_until(late, 1, timeout=10)
        assert arrays and arrays[-1].status_list == [], arrays[-1:]
        print(f"{CHURN} goals at {rate:.0f}/s: kept at most {max(kept)}, longest status array "
              f"{longest}, rss {rows[0][3]} -> {max(int(x[3]) for x in rows)} (max) kB")
    finally:
        watched.stop()
