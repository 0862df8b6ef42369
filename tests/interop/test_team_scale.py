"""Scale (issue 19, item 3): twenty robots on the campus world, in one
process (`sancta team`: the simulator in-process, each robot a team agent
with its own DDS node), at 25x simulated time. Every task must be done
exactly once (--check) and every robot appear in the summary."""
import re
import subprocess
import sys

import pubsub_support as ps

MAKE = ps.REPO / "share" / "missions" / "make_campus.py"
WORLD = ps.REPO / "share" / "worlds" / "campus.yaml"


def test_twenty_robots_finish_a_campus_mission(tmp_path):
    text = subprocess.run([sys.executable, str(MAKE), "20", "30"], capture_output=True,
                          text=True, check=True).stdout
    mission = tmp_path / "campus-20.xml"
    mission.write_text(text.replace('world="../worlds/campus.yaml"', f'world="{WORLD}"'))
    p = subprocess.run([str(ps.BIN / "sancta"), "team", str(mission), "--rate", "25",
                        "--no-kill", "--check", "--quiet", "--out", str(tmp_path / "out")],
                       capture_output=True, text=True, timeout=240)
    out = p.stdout + p.stderr
    assert p.returncode == 0, out[-3000:]
    assert "check: passed (every task done exactly once)" in out, out[-3000:]
    rows = re.findall(r"^r([0-9]+) +([0-9]+) +[0-9.]+$", p.stdout, re.MULTILINE)
    assert sorted(int(r) for r, _ in rows) == list(range(1, 21)), p.stdout
    assert sum(int(t) for _, t in rows) == 30, p.stdout
