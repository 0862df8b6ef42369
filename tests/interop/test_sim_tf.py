"""sancta-sim's standard visualization topics (issue 15), checked by a
Python peer as RViz would use them: /tf_static (latched) holds base_link ->
laser for every robot, /tf carries map -> <robot>/odom -> <robot>/base_link,
and the chain map -> base_link equals the ground truth; /map is the world's
occupancy grid, latched, so a late subscriber gets it."""
import math
import time

import pubsub_support as ps
import ros_types as rt
import sim_support as ss


def compose(a, b):
    """2D poses (x, y, yaw): a (+) b."""
    x, y, t = a
    return (x + math.cos(t) * b[0] - math.sin(t) * b[1],
            y + math.sin(t) * b[0] + math.cos(t) * b[1], t + b[2])


def pose2d(tr):
    return (tr.translation.x, tr.translation.y, ss.yaw_of(tr.rotation))


def test_tf_chains_and_map():
    dp = ps.participant()
    tf = ps.reader(dp, "rt/tf", rt.TFMessage_, depth=100)
    truth = {r: ps.reader(dp, f"rt/{r}/ground_truth", rt.PoseStamped_) for r in ("r1", "r2")}
    cmd = ps.writer(dp, "rt/r1/cmd_vel", rt.Twist_)
    sim = ps.start("sancta-sim", "arena", "--rate", "4x", "--duration", "400",
                   "--robot", "r1 5 5 0", "--robot", "r2 10 8 1.57")
    try:
        assert ps.wait_matched(tf, 15) and ps.wait_matched(cmd, 15)
        for _ in range(20):
            cmd.write(rt.Twist_(linear=rt.Vector3_(x=0.5), angular=rt.Vector3_(z=0.3)))
            time.sleep(0.05)
        # Late subscribers: the latched topics still arrive.
        static = ps.reader(dp, "rt/tf_static", rt.TFMessage_, depth=1, transient_local=True)
        grid = ps.reader(dp, "rt/map", rt.OccupancyGrid_, depth=1, transient_local=True)
        statics = ps.take_until(static, 1, timeout=10)
        maps = ps.take_until(grid, 1, timeout=10)
        latest = {}
        deadline = time.monotonic() + 5
        while time.monotonic() < deadline and len(latest) < 4:
            for msg in ps.take(tf):
                for t in msg.transforms:
                    latest[(t.header.frame_id, t.child_frame_id)] = t
            time.sleep(0.05)
        # Compare with the ground truth published right after.
        cmd.write(rt.Twist_())
        time.sleep(0.5)
        for msg in ps.take(tf):
            for t in msg.transforms:
                latest[(t.header.frame_id, t.child_frame_id)] = t
        truths = {r: ss.latest(rd) for r, rd in truth.items()}
    finally:
        sim.terminate()
        out = ps.finish(sim)
    assert statics, "no /tf_static for a late subscriber"
    links = {(t.header.frame_id, t.child_frame_id) for t in statics[-1].transforms}
    assert links == {("r1/base_link", "r1/laser"), ("r2/base_link", "r2/laser")}, links
    for r in ("r1", "r2"):
        assert ("map", f"{r}/odom") in latest, (sorted(latest), out)
        assert (f"{r}/odom", f"{r}/base_link") in latest, sorted(latest)
        chain = compose(pose2d(latest[("map", f"{r}/odom")].transform),
                        pose2d(latest[(f"{r}/odom", f"{r}/base_link")].transform))
        t = truths[r]
        assert t is not None
        assert abs(chain[0] - t.pose.position.x) < 0.05, (r, chain, t.pose.position)
        assert abs(chain[1] - t.pose.position.y) < 0.05, (r, chain, t.pose.position)
        dyaw = (chain[2] - ss.yaw_of(t.pose.orientation) + math.pi) % (2 * math.pi) - math.pi
        assert abs(dyaw) < 0.05, (r, chain)
    # r1 moved: its odom -> base_link is not the identity.
    moved = pose2d(latest[("r1/odom", "r1/base_link")].transform)
    assert math.hypot(moved[0], moved[1]) > 0.1, moved
    assert maps, "no /map for a late subscriber"
    m = maps[-1]
    assert m.header.frame_id == "map" and m.info.resolution > 0
    assert len(m.data) == m.info.width * m.info.height
    assert 100 in m.data and 0 in m.data

    def cell(x, y):
        i = int((x - m.info.origin.position.x) / m.info.resolution)
        j = int((y - m.info.origin.position.y) / m.info.resolution)
        return m.data[j * m.info.width + i]
    # The arena: 20 m box, walls 0.2 m thick; r1 starts in free space.
    assert cell(5.0, 5.0) == 0 and cell(0.1, 5.0) == 100 and cell(5.0, 0.1) == 100
