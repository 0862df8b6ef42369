"""Hostile data from the network (issue 19, item 4): a service request or
reply whose rmw header carries sequence -1 (or 2**63 - 1), NaN and infinite
velocities on cmd_vel, NaN poses to the simulator's control service, and
malformed team messages (garbage keys, member names, values, revisions).
Each receiving process must live, answer what is valid, say once (or rate-
limited) what it dropped, print no traceback, and keep no garbage."""
import math
import os
import re
import struct
import subprocess
import sys
import time

import pubsub_support as ps
import ros_types as rt
import service_support as svc
import sim_support as ss
from test_team_security import DbEntry_, Envelope_, Presence_

SANCTA = ps.BIN / "sancta"
WORLD = ps.REPO / "share" / "worlds" / "office.yaml"
NO_CRASH = re.compile(r"internal error|CONSTRAINT_ERROR|STORAGE_ERROR|PROGRAM_ERROR|"
                      r"raised |Call stack|traceback", re.IGNORECASE)


def test_server_answers_a_request_with_sequence_minus_one():
    ada = ps.start("server")
    try:
        dp = ps.participant()
        cl = svc.Client(dp)
        assert cl.wait_for_service(), "the Ada service endpoints were not discovered"
        time.sleep(0.3)
        for seq in (-1, 2**63 - 1, -(2**63)):
            cl.writer.write(svc.AddTwoInts_Request_(guid=cl.guid, seq=seq, a=1, b=2))
            deadline = time.monotonic() + 5
            reply = None
            while reply is None and time.monotonic() < deadline:
                for r in cl.reader.take(N=16):
                    if isinstance(r, svc.AddTwoInts_Response_) and r.seq == seq:
                        reply = r
                time.sleep(0.005)
            assert reply is not None and reply.sum == 3, f"no reply to sequence {seq}"
        r = cl.call(20, 22)  # and the server still answers ordinary calls
        assert r is not None and r.sum == 42
        assert ada.poll() is None, "the server died"
    finally:
        out = svc.stop(ada)
    assert not NO_CRASH.search(out), out


def test_client_ignores_replies_with_hostile_sequences():
    """Every request is answered first with sequence -1, then 2**63 - 1 and
    a foreign guid, then the true reply: the Ada client takes the true one."""
    dp = ps.participant()
    srv = svc.Server(dp)

    def serve_some():
        for r in srv.reader.take(N=64):
            if not isinstance(r, svc.AddTwoInts_Request_):
                continue
            srv.writer.write(svc.AddTwoInts_Response_(guid=r.guid, seq=-1, sum=-1))
            srv.writer.write(svc.AddTwoInts_Response_(guid=r.guid, seq=2**63 - 1, sum=-2))
            srv.writer.write(svc.AddTwoInts_Response_(guid=~r.guid & (2**64 - 1),
                                                      seq=r.seq, sum=-3))
            srv.writer.write(svc.AddTwoInts_Response_(guid=r.guid, seq=r.seq,
                                                      sum=r.a + r.b))

    ada, out = svc.run_client_against(serve_some, "client", 20, 22, 10)
    assert ada.returncode == 0, out
    assert "Got answer: 42" in out, out
    assert not NO_CRASH.search(out), out


def raw_service_peer(dp, service, srv_type, side):
    """A peer writing and taking raw samples (scripts/fuzz_services.py)."""
    sys.path.insert(0, str(ps.REPO / "scripts"))
    import fuzz_services
    return fuzz_services.Peer(fuzz_services.dds(), dp, service, srv_type, side)


def with_header(body, guid, seq):
    """A little-endian body (encapsulation first) with the request header."""
    return body[:4] + struct.pack("<Qq", guid, seq) + body[4:]


SET_RATE_TO_TYPE_13 = bytes.fromhex(
    "00010000010000000500000072617465000d0000000000000000000000000000000000000100000000000000"
    "0000000000000000000000000000000000000000")
# SetParameters request body: parameters [{name: rate, value: {type: 13}}] (no such type).
VALUE_OF_TYPE_13 = bytes.fromhex(
    "00010000010000000d000000000000000000000000000000000000000100000000000000000000000000000000"
    "0000000000000000000000")
# GetParameters response body: values [{type: 13}].


def test_clients_leave_malformed_replies_to_other_clients_alone():
    """Every client of a service reads every reply on its topic: a malformed
    reply addressed to another client (the header's guid) is dropped
    undecoded, unreported; one addressed to this client is reported with the
    type and byte offset; the true reply is then taken (dynamic and typed
    clients)."""
    dp = ps.participant()
    srv = raw_service_peer(dp, "/add_two_ints", "example_interfaces::srv::dds_::AddTwoInts",
                           "server")

    def serve_some():
        for r in srv.take():
            guid, seq, a, b = struct.unpack("<4xQqqq", r[:36])
            for to in (guid ^ 1, guid):  # another client's, then this one's
                srv.write(struct.pack("<BBxxQqI", 0, 1, to, seq, 42))  # the sum cut to 4 bytes
            srv.write(struct.pack("<BBxxQqq", 0, 1, guid, seq, a + b))

    for program in ("client", "typed_client"):
        ada, out = svc.run_client_against(serve_some, program, 20, 22, 10)
        assert ada.returncode == 0 and "Got answer: 42" in out, out
        dropped = [line for line in out.splitlines() if "malformed reply dropped" in line]
        assert len(dropped) == 1, out
        assert ("example_interfaces/srv/AddTwoInts_Response" in dropped[0]
                and "at byte offset 20" in dropped[0]), out
        assert not NO_CRASH.search(out), out


def test_parameter_server_answers_a_value_of_unknown_type():
    """SetParameters naming a ParameterValue type that does not exist (13):
    answered, refused with the reason (it was left unanswered: the
    exception ended the request)."""
    ada = ps.start("parameters_demo")
    try:
        dp = ps.participant()
        peer = raw_service_peer(dp, "/parameters_demo/set_parameters",
                                "rcl_interfaces::srv::dds_::SetParameters", "client")
        assert peer.matched(15), "the parameter service was not discovered"
        time.sleep(0.3)
        peer.write(with_header(SET_RATE_TO_TYPE_13, 77, 1))
        deadline, reply = time.monotonic() + 10, None
        while reply is None and time.monotonic() < deadline:
            reply = next((r for r in peer.take() if r[4:20] == struct.pack("<Qq", 77, 1)), None)
            time.sleep(0.01)
        assert reply is not None, "no answer"
        # results [{successful: false, reason: "parameter 'rate': unknown ..."}]
        assert reply[24] == 0 and b"parameter 'rate': unknown parameter type 13" in reply, reply
        assert ada.poll() is None, "the node died"
    finally:
        out = svc.stop(ada)
    assert not NO_CRASH.search(out), out


def test_param_get_says_the_node_answered_an_unknown_type():
    """`rclada param get` answered a ParameterValue of type 13: a clear
    error saying so, not 'internal error'."""
    dp = ps.participant()
    peer = raw_service_peer(dp, "/fuzz_peer/get_parameters",
                            "rcl_interfaces::srv::dds_::GetParameters", "server")
    ada = ps.start("rclada", "param", "get", "/fuzz_peer", "rate", "--timeout", "10")
    deadline = time.monotonic() + 20
    while ada.poll() is None and time.monotonic() < deadline:
        for request in peer.take():
            if len(request) >= 20:
                peer.write(VALUE_OF_TYPE_13[:4] + request[4:20] + VALUE_OF_TYPE_13[4:])
        time.sleep(0.01)
    out = ps.finish(ada)
    assert ada.returncode == 1, out
    assert "the node answered a value rclada cannot read: unknown parameter type 13" in out, out
    assert not NO_CRASH.search(out), out


def action_peer(dp, action):
    """The server side of an example_interfaces/Fibonacci action, raw
    (scripts/fuzz_services.py)."""
    sys.path.insert(0, str(ps.REPO / "scripts"))
    import fuzz_services
    return fuzz_services.ActionPeer(fuzz_services.dds(), dp, action)


LE = b"\x00\x01\x00\x00"


def run_action_client(argv, action, feedback=lambda goal: [], status=4, cancel_code=0):
    """Runs an action client (argv) against a raw action server: the goal
    is accepted, then the feedback samples feedback(goal id) published; the
    cancel request (if any) answered cancel_code, the result request
    (after 1.5 s: the feedback is printed first) status and [0, 1, 1, 2]."""
    dp = ps.participant()
    peer = action_peer(dp, action)
    ada = ps.start(*argv)
    deadline = time.monotonic() + 30
    while ada.poll() is None and time.monotonic() < deadline:
        for r in peer.send.take():
            peer.send.write(LE + r[4:20] + b"\x01\0\0\0" + struct.pack("<iI", 5, 0))
            assert peer.feedback_matched(5), "the client's feedback reader was not discovered"
            for sample in feedback(r[20:36]):
                peer.publish(peer.feedback, sample)
        for r in peer.cancel.take():
            peer.cancel.write(LE + r[4:20] + struct.pack("<b3xI", cancel_code, 1) + r[20:36]
                              + struct.pack("<iI", 0, 0))
        for r in peer.result.take():
            time.sleep(1.5)
            peer.result.write(LE + r[4:20] + struct.pack("<b3xI4i", status, 4, 0, 1, 1, 2))
        time.sleep(0.01)
    return ada, ps.finish(ada)


ACTION_CLIENTS = [
    ["rclada", "action", "send_goal", "/hostile_fib", "example_interfaces/action/Fibonacci",
     "{order: 3}", "-f", "--timeout", "10"],
    ["typed_fibonacci", "client", "3", "hostile_fib", "10"],
]


def test_action_clients_leave_malformed_feedback_of_other_goals_alone():
    """Every action client reads every feedback message of the action: a
    malformed one about another client's goal (the goal_id, its first
    field) is dropped undecoded, unreported (it was reported by every
    client); one about this client's goal is reported with the type and the
    byte offset; the valid feedback and the result are still taken (dynamic
    and typed clients)."""
    def feedback(goal):
        cut = struct.pack("<I", 1000)  # a sequence of 1000 int32 with no data
        return [LE + bytes(16) + cut, LE + goal + cut, LE + goal + struct.pack("<I3i", 3, 0, 1, 1)]

    for argv in ACTION_CLIENTS:
        ada, out = run_action_client(argv, "/hostile_fib", feedback)
        assert ada.returncode == 0, out
        dropped = [line for line in out.splitlines() if "dropped a malformed sample" in line]
        assert len(dropped) == 1, out
        assert ("example_interfaces/action/Fibonacci_FeedbackMessage" in dropped[0]
                and "at byte offset 20" in dropped[0]), out
        assert out.count("Feedback:" if argv[0] == "rclada" else "feedback of") == 1, out
        assert "SUCCEEDED" in out, out
        assert not NO_CRASH.search(out), out


def test_action_clients_refuse_a_status_that_is_no_goal_status():
    """A get_result answer with status 9 (GoalStatus has 0 .. 6): a clear
    error naming it (it was reported as the goal's status UNKNOWN)."""
    for argv in ACTION_CLIENTS:
        ada, out = run_action_client(argv, "/hostile_fib", status=9)
        assert ada.returncode == 1, out
        assert ("action /hostile_fib: get_result answered status 9, which is no goal status"
                in out), out
        assert "UNKNOWN" not in out and not NO_CRASH.search(out), out


def test_action_client_refuses_a_cancel_code_that_is_no_code():
    """A cancel_goal answer with return code -3 (CancelGoal has 0 .. 3): a
    clear error naming it (it was taken as ERROR_REJECTED)."""
    ada, out = run_action_client(["typed_fibonacci", "client", "3", "hostile_fib", "10",
                                  "cancel"], "/hostile_fib", cancel_code=-3)
    assert ada.returncode == 1, out
    assert ("action /hostile_fib: cancel_goal answered return code -3, which is no cancel code"
            in out), out
    assert "ERROR_REJECTED" not in out and not NO_CRASH.search(out), out


def test_simulator_survives_hostile_control_and_cmd_vel():
    dp = ps.participant()
    truth = ps.reader(dp, "rt/robot1/ground_truth", rt.PoseStamped_)
    cmd = ps.writer(dp, "rt/robot1/cmd_vel", rt.Twist_)
    ctl = ss.Control(dp)
    sim = ps.start("sancta-sim", "arena", "--rate", "4x", "--duration", "400",
                   "--robot", "robot1 5 5 0")
    try:
        assert ctl.wait_available() and ps.wait_matched(cmd, 15) and ps.wait_matched(truth, 15)
        # A request whose header sequence is -1: answered, echoed.
        ctl.wr.write(ss.SimControl_Request_(guid=ctl.GUID, seq=-1, command="list"))
        deadline, reply = time.monotonic() + 10, None
        while reply is None and time.monotonic() < deadline:
            reply = next((r for r in ps.take(ctl.rd) if r.seq == -1), None)
            time.sleep(0.02)
        assert reply is not None and reply.success and "robot1" in reply.message
        # Non-finite poses are refused by name.
        for bad in (math.nan, math.inf, -math.inf):
            r = ctl.call("teleport", "robot1", x=bad, y=5.0)
            assert not r.success and "invalid pose" in r.message, r.message
            r = ctl.call("add", "robot9", x=5.0, y=bad)
            assert not r.success, r.message
        # NaN and infinite velocities for 2 s: ignored, the robot stays put.
        t0 = ss.latest(truth)
        deadline = time.monotonic() + 2
        while time.monotonic() < deadline:
            for v in (math.nan, math.inf, -math.inf):
                cmd.write(rt.Twist_(linear=rt.Vector3_(v, 0, 0), angular=rt.Vector3_(0, 0, 0)))
                cmd.write(rt.Twist_(linear=rt.Vector3_(0, 0, 0), angular=rt.Vector3_(0, 0, v)))
            time.sleep(0.02)
        t1 = ss.latest(truth)
        for p in (t1.pose.position.x, t1.pose.position.y, t1.pose.orientation.z):
            assert math.isfinite(p), t1
        assert abs(t1.pose.position.x - t0.pose.position.x) < 0.01, (t0, t1)
        # A finite command still drives it.
        deadline, moved = time.monotonic() + 10, False
        while not moved and time.monotonic() < deadline:
            cmd.write(rt.Twist_(linear=rt.Vector3_(0.5, 0, 0)))
            time.sleep(0.05)
            t = ss.latest(truth, timeout=1)
            moved = t is not None and t.pose.position.x > t0.pose.position.x + 0.3
        assert moved, "the robot no longer obeys finite commands"
        assert ctl.call("list").success
        assert sim.poll() is None, "sancta-sim died"
    finally:
        sim.terminate()
        out = ps.finish(sim)
    assert sim.returncode == 0, out
    assert out.count("non-finite velocity ignored") == 1, out  # said once, not per sample
    assert not NO_CRASH.search(out), out


GOOD_ID = re.compile(r"^[A-Za-z0-9_]{1,64}$")


def hostile_samples(team, n):
    """Malformed team samples: garbage keys, writers, value types, values,
    revisions, member names, leases, senders, channels and payloads."""
    big = 2**63 + 5
    cases = [
        DbEntry_("task/\x01\x02", "types.string", "x", 1, "r1"),
        DbEntry_("k" * 5000, "types.string", "x", 1, "r1"),
        DbEntry_("", "types.string", "x", 1, "r1"),
        DbEntry_(f"junk{n}", "types.string", "x", 1, "r 1\x7f"),
        DbEntry_(f"junk{n}", "types.string", "x", big, "r1"),
        DbEntry_(f"junk{n}", "types.string", "x", 0, "r1"),
        DbEntry_(f"junk{n}", "no such type!", "x", 5, "r1"),
        DbEntry_(f"junk{n}", "types.integer", "12abc", 5, "r1"),
        DbEntry_(f"junk{n}", "types.real", "1e999", 5, "r1"),
        DbEntry_(f"junk{n}", "types.boolean", "maybe", 5, "r1"),
        DbEntry_(f"junk{n}", "types.string", "\x00\xff" * 10, 5, "r1"),
        DbEntry_(f"junk{n}", "types.string", "v" * 70000, 5, "r1"),
    ]
    presences = [Presence_("bad name\x01", "robots", 2.0, n), Presence_("", "robots", 2.0, n),
                 Presence_(f"ghost{n}", "robots", math.nan, n),
                 Presence_(f"ghost{n}", "robots", math.inf, n),
                 Presence_("x" * 300, "robots", 2.0, n)]
    envelopes = [Envelope_("r\x001", "", "auction", n, "bid\n1\n1\nx"),
                 Envelope_("r1", "", "auction", n, "bid\nNaN\n-5\n\x00"),
                 Envelope_("r1", "", "auction", n, "offer\n99999999999999999999\n1\nz\nq"),
                 Envelope_("r1", "@@@", "auction", n, "x"),
                 Envelope_("r1", "", "auc tion", n, "x")]
    return cases, presences, envelopes


def test_team_member_drops_malformed_team_messages(tmp_path):
    team = f"hostile{os.getpid()}"
    mission = tmp_path / "mission.xml"
    mission.write_text(f"""<?xml version="1.0"?>
<mission name="hostile" world="{WORLD}">
  <goto id="t1" x="4" y="10"/> <goto id="t2" x="10" y="10"/> <goto id="t3" x="16" y="10"/>
  <goto id="t4" x="22" y="10"/>
</mission>""")
    logs, procs = {}, {}

    def start(name, *args):
        logs[name] = tmp_path / f"{name}.log"
        procs[name] = subprocess.Popen(
            [str(SANCTA), "team-agent", "--team", team, "--lease", "1.0", "--for", "120", *args],
            stdout=open(logs[name], "w"), stderr=subprocess.STDOUT, cwd=ps.REPO)

    attacker = ps.participant()
    base = f"rt/sancta/{team}"
    state = ps.writer(attacker, f"{base}/state", DbEntry_, transient_local=True, depth=100)
    presence = ps.writer(attacker, f"{base}/presence", Presence_)
    messages = ps.writer(attacker, f"{base}/messages", Envelope_)
    try:
        start("r1", "--id", "r1", "--x", "3", "--y", "10", "--rate", "1", "--speed", "0.5")
        start("r2", "--id", "r2", "--x", "6", "--y", "10", "--rate", "1", "--speed", "0.5")
        start("operator", "--operator", mission)
        # Attack while the mission runs (the robots need about 30 s).
        n = 0
        deadline = time.monotonic() + 6
        while time.monotonic() < deadline:
            n += 1
            entries, presences, envelopes = hostile_samples(team, n)
            for e in entries:
                state.write(e)
            for p in presences:
                presence.write(p)
            for e in envelopes:
                messages.write(e)
            time.sleep(0.1)
        del state, presence, messages, attacker  # its history goes with it
        # A valid newcomer makes every member republish its whole replica.
        probe = ps.participant()
        held = ps.reader(probe, f"{base}/state", DbEntry_, transient_local=True, depth=1000)
        me = ps.writer(probe, f"{base}/presence", Presence_)
        ps.wait_matched(me, 10)
        seen = []
        deadline = time.monotonic() + 5
        while time.monotonic() < deadline:
            me.write(Presence_("probe", "", 1.0, int(time.monotonic())))
            seen += [s for s in ps.take(held) if isinstance(s, DbEntry_)]
            time.sleep(0.25)
        alive = {name: p.poll() is None for name, p in procs.items()}
        procs["operator"].wait(timeout=120)
        op = logs["operator"].read_text()
        assert procs["operator"].returncode == 0, op
        assert "operator: all done" in op, op
    finally:
        for p in procs.values():
            if p.poll() is None:
                p.kill()
            p.wait()
    text = {name: log.read_text() for name, log in logs.items()}
    keys = {s.key for s in seen}
    assert all(alive.values()), alive  # the probe saw a running team
    assert {"pose/r1", "robot/r1", "robot/r2", "round"} <= keys, sorted(keys)  # ("mission" and
    # "task/*" travel on the tasks topic)
    garbage = [s for s in seen if s.key.startswith("junk") or not GOOD_ID.match(s.writer)
               or any(not (" " <= c <= "~") for c in s.key) or "ghost" in s.key]
    assert not garbage, garbage[:5]
    for name in ("r1", "r2", "operator"):
        t = text[name]
        assert "dropped malformed" in t, t[-3000:]
        # Rate-limited: at most one warning per 10 s per process.
        assert t.count("dropped malformed") <= 12, t.count("dropped malformed")
        assert not NO_CRASH.search(t), t[-3000:]
    rounds = re.findall(r"round [0-9]+ robots ([\w,]+) ", text["operator"])
    assert rounds and all(set(r.split(",")) <= {"r1", "r2"} for r in rounds), rounds
