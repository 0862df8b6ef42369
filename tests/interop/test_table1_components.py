"""The paper's Table 1 as XML components (issue 19, item 2): network,
global_database, annealer and bidder wired in a configuration and run by
`sancta run --all` (every agent in one process, each with its own DDS node).
The robots "teleport": a merge feeds team_member's goal back as its pose, so
a task is done as soon as it is assigned and the tests take seconds."""
import os
import re
import subprocess

import pubsub_support as ps

SANCTA = ps.BIN / "sancta"


def run(tmp_path, config_text, seconds, *extra):
    cfg = tmp_path / "config.xml"
    cfg.write_text(config_text)
    check = subprocess.run([str(SANCTA), "check", str(cfg), "--output", str(tmp_path)],
                           capture_output=True, text=True, timeout=60, cwd=tmp_path)
    assert check.returncode == 0, check.stdout + check.stderr
    p = subprocess.run([str(SANCTA), "run", str(cfg), "--all", "--for", str(seconds), *extra],
                       capture_output=True, text=True, timeout=seconds + 60, cwd=tmp_path)
    return p.returncode, p.stdout + p.stderr


def agent(name, body, kind="robot"):
    return f'  <agent id="{name}" kind="{kind}">\n{body}  </agent>\n'


def test_network_component_hears_the_other_members(tmp_path):
    team = f"net{os.getpid()}"
    body = (f'    <component name="network" team="{team}" lease="0.5">\n'
            '      <provides data="members" as="members"/>\n    </component>\n'
            '    <component name="logger" file="{d}/$id-members.csv">\n'
            '      <requires data="members" as="members"/>\n    </component>\n')
    text = "<t>\n" + "".join(agent(a, body.replace("{d}", str(tmp_path))) for a in ("a1", "a2")) \
        + "</t>\n"
    code, out = run(tmp_path, text, 4)
    assert code == 0, out
    for a in ("a1", "a2"):
        log = (tmp_path / f"{a}-members.csv").read_text()
        assert re.search(r"a1,a2", log), log  # each hears both (itself included)


def test_global_database_component_replicates_puts(tmp_path):
    team = f"db{os.getpid()}"
    body = (f'    <component name="network" team="{team}" lease="0.5"/>\n'
            '    <component name="global_database">\n'
            '      <requires data="put" as="entry"/>\n'
            '      <provides data="size" as="size"/>\n    </component>\n'
            '    <component name="value" type="types.string" value="key/$id=from $id">\n'
            '      <provides data="output" as="entry"/>\n    </component>\n'
            '    <component name="logger" file="{d}/$id-size.csv">\n'
            '      <requires data="size" as="size"/>\n    </component>\n')
    text = "<t>\n" + "".join(agent(a, body.replace("{d}", str(tmp_path)))
                             for a in ("a1", "a2", "a3")) + "</t>\n"
    code, out = run(tmp_path, text, 4)
    assert code == 0, out
    for a in ("a1", "a2", "a3"):
        sizes = [int(line.split(",")[-1]) for line in
                 (tmp_path / f"{a}-size.csv").read_text().splitlines()[1:]]
        assert sizes and sizes[-1] == 3, (a, sizes)  # every agent's key on every replica


MISSION = """<?xml version="1.0"?>
<mission name="table1">
  <goto id="t1" x="1" y="1"/> <goto id="t2" x="4" y="1"/> <goto id="t3" x="4" y="4"/>
  <goto id="t4" x="1" y="4"/> <goto id="t5" x="2.5" y="6"/>
</mission>
"""


def team_config(tmp_path, allocator):
    (tmp_path / "mission.xml").write_text(MISSION)
    team = f"{allocator}{os.getpid()}"
    robot = (f'    <component name="network" team="{team}" lease="0.5"/>\n'
             '    <component name="global_database"/>\n'
             f'    <component name="{allocator}"/>\n'
             '    <component name="value" type="types.pose" value="$x 0 0">\n'
             '      <provides data="output" as="start"/>\n    </component>\n'
             '    <component name="merge">\n'
             '      <requires data="a" as="start"/>\n      <requires data="b" as="goal"/>\n'
             '      <provides data="output" as="pose"/>\n    </component>\n'
             '    <component name="team_member" tolerance="0.1">\n'
             '      <requires data="pose" as="pose"/>\n'
             '      <provides data="goal" as="goal"/>\n    </component>\n')
    operator = (f'    <component name="network" team="{team}" lease="0.5"/>\n'
                '    <component name="global_database"/>\n'
                f'    <component name="team_operator" mission="{tmp_path}/mission.xml"/>\n')
    return ("<t>\n"
            + "".join(agent(r, robot.replace("$x", x)) for r, x in (("r1", "0"), ("r2", "5")))
            + agent("operator", operator, kind="operator") + "</t>\n")


def test_annealer_component_allocates_the_mission(tmp_path):
    code, out = run(tmp_path, team_config(tmp_path, "annealer"), 60)
    assert code == 0, out
    assert "every task of the mission is done" in out, out
    assert re.search(r"annealed round [0-9]+", out), out
    assert "auctions of round" not in out, out
    assert len(set(re.findall(r"did (t[0-9])", out))) == 5, out


def test_bidder_component_allocates_the_mission(tmp_path):
    code, out = run(tmp_path, team_config(tmp_path, "bidder"), 60)
    assert code == 0, out
    assert "every task of the mission is done" in out, out
    assert re.search(r"auctions of round [0-9]+ done", out), out
    assert "annealed round" not in out, out
    assert len(set(re.findall(r"did (t[0-9])", out))) == 5, out
