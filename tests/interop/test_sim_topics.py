"""sancta-sim against a Python cyclonedds peer (loopback, the run's domain):
its topics carry the ROS 2 type names and values a ROS 2 node expects, a
Twist on cmd_vel moves the robot (seen in ground truth and odometry), and
the /sancta_sim/control service kills, revives and adds robots."""
import math
import time

import pubsub_support as ps
import ros_types as rt
import sim_support as ss


def start_sim(*args):
    return ps.start("sancta-sim", "arena", "--rate", "4x", "--duration", "400", *args)


def stop(sim):
    sim.terminate()  # SIGTERM: a clean stop
    out = ps.finish(sim)
    assert sim.returncode == 0, f"sancta-sim exit {sim.returncode}:\n{out}"
    assert "stopped at" in out, out
    return out


def test_topics_have_ros2_types_and_cmd_vel_moves_the_robot():
    dp = ps.participant()
    odom = ps.reader(dp, "rt/robot1/odom", rt.Odometry_)
    scan = ps.reader(dp, "rt/robot1/scan", rt.LaserScan_, reliable=False, depth=5)
    truth = ps.reader(dp, "rt/robot1/ground_truth", rt.PoseStamped_)
    gps = ps.reader(dp, "rt/robot1/gps", rt.PoseWithCovarianceStamped_)
    clock = ps.reader(dp, "rt/clock", rt.Clock_, reliable=False, depth=1)
    cmd = ps.writer(dp, "rt/robot1/cmd_vel", rt.Twist_)
    sim = start_sim("--robot", "robot1 5 5 0 gps=on gps_std=0.1")
    try:
        for entity in (odom, scan, truth, gps, clock, cmd):
            assert ps.wait_matched(entity, timeout=15), f"{entity} not matched"
        s = ss.latest(scan)
        assert s is not None, "no scan"
        assert len(s.ranges) == 360
        assert s.header.frame_id == "robot1/laser"  # base_link -> laser on /tf_static
        assert abs(s.angle_increment - 2 * math.pi / 360) < 1e-4
        # The robot at (5, 5) facing +x in a 20 m box (walls 0.2 m thick):
        # straight ahead the wall at x = 19.9 is beyond the 8 m range, behind
        # it (angle pi) the wall at x = 0.1 is 4.9 m away.
        behind = min(range(360), key=lambda i: abs(s.angle_min + i * s.angle_increment - math.pi))
        assert abs(s.ranges[behind] - 4.9) < 0.1, s.ranges[behind]
        o = ss.latest(odom)
        assert o is not None and o.header.frame_id == "robot1/odom"
        assert o.child_frame_id == "robot1/base_link"
        assert abs(o.pose.pose.position.x) < 1e-6 and abs(o.pose.pose.position.y) < 1e-6
        g = ss.latest(gps)
        assert g is not None and abs(g.pose.pose.position.x - 5) < 1.0
        assert abs(g.pose.covariance[0] - 0.01) < 1e-9
        c = ss.latest(clock)
        assert c is not None and c.clock.sec + c.clock.nanosec * 1e-9 > 0
        t0 = ss.latest(truth)
        assert t0 is not None and t0.header.frame_id == "map"
        assert abs(t0.pose.position.x - 5) < 1e-6 and abs(t0.pose.position.y - 5) < 1e-6
        # Drive forward at 0.5 m/s for about 2 simulated seconds.
        deadline = time.monotonic() + 10
        moved = None
        while time.monotonic() < deadline:
            cmd.write(rt.Twist_(linear=rt.Vector3_(0.5, 0, 0)))
            time.sleep(0.05)
            t = ss.latest(truth, timeout=1)
            if t is not None and t.pose.position.x > 6.0:
                moved = t
                break
        assert moved is not None, "the robot did not move forward on cmd_vel"
        assert abs(moved.pose.position.y - 5) < 0.05
        cmd.write(rt.Twist_())
        time.sleep(0.5)
        o = ss.latest(odom)
        assert o.pose.pose.position.x > 0.9, o.pose.pose.position
        assert stamp_order_ok(odom)
    finally:
        out = stop(sim)
    assert "added robot1" in out


def stamp_order_ok(odom):
    got = ps.take_until(odom, 5, timeout=5)
    stamps = [ss.stamp_of(m.header) for m in got]
    return len(stamps) >= 2 and all(a < b for a, b in zip(stamps, stamps[1:]))


def test_control_service_kills_revives_and_adds_robots():
    dp = ps.participant()
    control = ss.Control(dp)
    truth1 = ps.reader(dp, "rt/robot1/ground_truth", rt.PoseStamped_)
    odom2 = ps.reader(dp, "rt/robot2/odom", rt.Odometry_)
    events = ps.reader(dp, "rt/sancta_sim/events", rt.String_, depth=100)
    sim = start_sim("--robot", "robot1 3 3 0")
    try:
        assert control.wait_available(), "service not available"
        assert ps.wait_matched(truth1, 15) and ps.wait_matched(events, 15)
        assert ss.latest(truth1) is not None
        reply = control.call("kill", "robot1")
        assert reply.success, reply.message
        time.sleep(0.3)
        ps.take(truth1)  # what was under way
        time.sleep(1.0)
        assert ps.take(truth1) == [], "a killed robot still publishes"
        reply = control.call("revive", "robot1")
        assert reply.success, reply.message
        assert ss.latest(truth1) is not None, "a revived robot does not publish"
        reply = control.call("kill", "nobody")
        assert not reply.success and "nobody" in reply.message
        reply = control.call("add", "robot2", x=10.0, y=10.0, yaw=1.0)
        assert reply.success, reply.message
        assert ps.wait_matched(odom2, 15), "robot2's odom never appeared"
        assert ss.latest(odom2) is not None
        reply = control.call("add", "robot2", x=12.0, y=10.0)
        assert not reply.success and "exists" in reply.message
        reply = control.call("list")
        assert reply.success and "robot1" in reply.message and "robot2" in reply.message
        reply = control.call("fly", "robot1")
        assert not reply.success and "unknown command" in reply.message
        texts = [e.data for e in ps.take_until(events, 4, timeout=5)]
    finally:
        stop(sim)
    assert any(t.startswith("killed robot1") for t in texts), texts
    assert any(t.startswith("revived robot1") for t in texts), texts


def test_collision_is_reported():
    dp = ps.participant()
    events = ps.reader(dp, "rt/sancta_sim/events", rt.String_, depth=100)
    cmd = ps.writer(dp, "rt/robot1/cmd_vel", rt.Twist_)
    sim = start_sim("--robot", "robot1 1 10 3.14159")
    try:
        assert ps.wait_matched(cmd, 15) and ps.wait_matched(events, 15)
        found = []
        deadline = time.monotonic() + 15
        while not found and time.monotonic() < deadline:
            cmd.write(rt.Twist_(linear=rt.Vector3_(0.8, 0, 0)))
            found = [e.data for e in ps.take(events) if e.data.startswith("collision robot1 wall")]
            time.sleep(0.05)
    finally:
        out = stop(sim)
    assert found, f"no collision event; sancta-sim said:\n{out}"
    assert "collision robot1 wall" in out


def test_bad_command_lines_fail_with_positions():
    for args, expected in [
        (["arena", "--robot", "robot1 1 x 0"], "--robot:1:10: expected the start Y"),
        (["arena", "--robot", "9robot 1 1 0"], "--robot:1:1: expected a robot name"),
        (["nowhere_world"], "nowhere_world: no such file"),
        (["arena", "--rate", "fast"], "--rate: expected a number"),
    ]:
        proc = ps.start("sancta-sim", *args)
        out = ps.finish(proc, timeout=10)
        assert proc.returncode == 1, (args, out)
        assert expected in out, (args, out)


def test_robot_list_file_errors_name_file_line_column(tmp_path):
    robots = tmp_path / "robots.txt"
    robots.write_text("# two robots\nr1 1 1 0 beams=90\nr2 2 2 0 odom_bias=fast\n")
    proc = ps.start("sancta-sim", "arena", "--robots", robots)
    out = ps.finish(proc, timeout=10)
    assert proc.returncode == 1, out
    assert f"{robots}:3:20: expected a value of odom_bias (a number), found \"fast\"" in out, out


def test_sigint_stops_cleanly():
    import signal
    dp = ps.participant()
    clock = ps.reader(dp, "rt/clock", rt.Clock_, reliable=False, depth=1)
    sim = ps.start("sancta-sim", "arena", "--robot", "r1 5 5 0", "--rate", "10x")
    try:
        assert ps.wait_matched(clock, 15)
        first = ss.latest(clock)
        time.sleep(0.5)
        last = ss.latest(clock)
    finally:
        sim.send_signal(signal.SIGINT)
        out = ps.finish(sim)
    assert sim.returncode == 0 and "stopped at" in out, out
    assert first is not None and last is not None, out
    assert (last.clock.sec, last.clock.nanosec) > (first.clock.sec, first.clock.nanosec)


def test_cmd_timeout_stops_a_robot_left_without_commands():
    dp = ps.participant()
    truth = ps.reader(dp, "rt/r1/ground_truth", rt.PoseStamped_)
    cmd = ps.writer(dp, "rt/r1/cmd_vel", rt.Twist_)
    sim = ps.start("sancta-sim", "arena", "--robot", "r1 5 5 0", "--rate", "4x",
                   "--cmd-timeout", "0.5")
    try:
        assert ps.wait_matched(cmd, 15) and ps.wait_matched(truth, 15)
        start = ss.latest(truth)
        cmd.write(rt.Twist_(linear=rt.Vector3_(0.5, 0, 0)))  # once, then silence
        time.sleep(2.0)  # 8 simulated seconds
        a = ss.latest(truth)
        time.sleep(0.5)
        b = ss.latest(truth)
    finally:
        stop(sim)
    moved = a.pose.position.x - start.pose.position.x
    # It moved (at most 0.5 s at 0.5 m/s, with acceleration), then stopped.
    assert 0.02 < moved < 0.3, moved
    assert b.pose.position.x == a.pose.position.x and ss.stamp_of(b.header) > ss.stamp_of(a.header)
