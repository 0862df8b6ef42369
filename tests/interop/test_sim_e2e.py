"""End to end: sancta-sim (office world, 4x clock) and `sancta run
share/config/sim-robot.xml`: the agent drives robot1 through its three
goals (a corridor, an office behind a door, back along the corridor)
without collision, reports progress and status, publishes its map, and
takes a new task list at run time. Bounded by timeouts that fail with
both programs' output."""
import time

import pubsub_support as ps
import ros_types as rt
import sim_support as ss

CONFIG = ps.REPO / "share" / "config" / "sim-robot.xml"
LAST_GOAL = (16.0, 10.0)


def wait_status(rd, text, timeout):
    deadline = time.monotonic() + timeout
    seen = []
    while time.monotonic() < deadline:
        seen.extend(s.data for s in ps.take(rd))
        if text in seen:
            return seen
        time.sleep(0.05)
    raise TimeoutError(f"status {text!r} not seen within {timeout} s; seen {seen}")


def test_agent_drives_simulated_robot_through_its_goals():
    dp = ps.participant()
    status = ps.reader(dp, "rt/robot1/sancta/status", rt.String_, depth=100)
    progress = ps.reader(dp, "rt/robot1/sancta/progress", rt.Float64_, depth=100)
    truth = ps.reader(dp, "rt/robot1/ground_truth", rt.PoseStamped_)
    events = ps.reader(dp, "rt/sancta_sim/events", rt.String_, depth=100)
    grid = ps.reader(dp, "rt/robot1/map", rt.OccupancyGrid_, depth=2)
    tasks = ps.writer(dp, "rt/robot1/sancta/tasks", rt.String_)
    sim = ps.start("sancta-sim", "office", "--robot", "robot1 2 10 0", "--rate", "4x",
                   "--duration", "1000", "--seed", "7")
    agent = ps.start("sancta", "run", CONFIG, "--agent", "Ari", "--for", "120")
    sim_out = agent_out = ""
    try:
        try:
            seen = wait_status(status, "done 3 / 3", timeout=90)
            assert ps.wait_matched(tasks, 10)
            tasks.write(rt.String_(data="14.0,10.0"))
            seen += wait_status(status, "done 1 / 1", timeout=40)
        except TimeoutError as e:
            raise AssertionError(str(e)) from None
        final = ss.latest(truth)
        maps = ps.take(grid) or ps.take_until(grid, 1, timeout=10)
        values = [p.data for p in ps.take(progress)]
        collisions = [e.data for e in ps.take(events) if e.data.startswith("collision")]
    finally:
        agent.terminate()
        agent_out = ps.finish(agent)
        sim.terminate()
        sim_out = ps.finish(sim)
    context = f"\nagent said:\n{agent_out}\nsimulator said:\n{sim_out}"
    # The first status may go out before the status publisher has started
    # (start order): the agent's log has every goal.
    goals = [s for s in seen if s.startswith("goal")]
    assert goals[-3:] == ["goal 2 / 3 (7.0,4.0)", "goal 3 / 3 (16.0,10.0)",
                          "goal 1 / 1 (14.0,10.0)"], f"{seen}{context}"
    logged = [agent_out.find(f"goal {g}") for g in
              ("1 / 3 (8.0,10.0)", "2 / 3 (7.0,4.0)", "3 / 3 (16.0,10.0)")]
    assert -1 not in logged and logged == sorted(logged), context
    assert final is not None, context
    # After the new task list, the robot stands at (14, 10).
    assert abs(final.pose.position.x - 14.0) < 0.35 and abs(final.pose.position.y - 10.0) < 0.35, \
        f"final pose {final.pose.position}{context}"
    assert not collisions, f"{collisions}{context}"
    assert "collision" not in sim_out, context
    assert values and values[-1] == 1.0, f"progress {values}{context}"
    assert maps, f"no map{context}"
    m = maps[-1]
    assert (m.info.width, m.info.height) == (300, 200) and abs(m.info.resolution - 0.1) < 1e-6
    known = sum(1 for v in m.data if v >= 0)
    occupied = sum(1 for v in m.data if v > 50)
    assert known > 2000 and occupied > 100, (known, occupied)
    # The corridor the robot drove along is free on the map (row y = 10).
    row = int(10.0 / 0.1)
    corridor = [m.data[row * 300 + i] for i in range(30, 150)]
    assert sum(1 for v in corridor if 0 <= v < 50) > 100, corridor
    assert "all 3 goals done" in agent_out, context


TEAM = ps.REPO / "share" / "config" / "sim-corridor.xml"


def test_two_agents_swap_ends_of_the_corridor_without_collision():
    dp = ps.participant()
    status = {n: ps.reader(dp, f"rt/{n}/sancta/status", rt.String_, depth=100)
              for n in ("Ari", "Ben")}
    truth = {n: ps.reader(dp, f"rt/{n}/ground_truth", rt.PoseStamped_) for n in ("Ari", "Ben")}
    events = ps.reader(dp, "rt/sancta_sim/events", rt.String_, depth=100)
    sim = ps.start("sancta-sim", "office", "--robot", "Ari 2 10 0",
                   "--robot", "Ben 18 10 3.14159265", "--rate", "4x", "--duration", "1000")
    agents = ps.start("sancta", "run", TEAM, "--all", "--for", "120")
    sim_out = agents_out = ""
    try:
        try:
            for name in ("Ari", "Ben"):
                wait_status(status[name], "done 2 / 2", timeout=90)
        except TimeoutError as e:
            raise AssertionError(str(e)) from None
        final = {n: ss.latest(truth[n]) for n in ("Ari", "Ben")}
        texts = [e.data for e in ps.take(events)]
    finally:
        agents.terminate()
        agents_out = ps.finish(agents)
        sim.terminate()
        sim_out = ps.finish(sim)
    context = f"\nagents said:\n{agents_out}\nsimulator said:\n{sim_out}"
    assert not [t for t in texts if t.startswith("collision")], f"{texts}{context}"
    assert "collision" not in sim_out, context
    for name, home in (("Ari", (2.0, 10.0)), ("Ben", (18.0, 10.0))):
        p = final[name].pose.position
        assert abs(p.x - home[0]) < 0.35 and abs(p.y - home[1]) < 0.35, f"{name} at {p}{context}"
    # Both went to the far end first (they met on the way).
    for name, far in (("Ari", "18.0,10.0"), ("Ben", "2.0,10.0")):
        assert f"[{name}/executor#8] goal 2 / 2" in agents_out, context
        assert agents_out.find(f"[{name}/executor#8] goal 1 / 2 ({far})") >= 0, context
