#!/usr/bin/env python3
"""Writes the small broken inputs of the corpus (tests/data/broken/*/) and
cases.txt. Large inputs (megabytes) are made by the test itself in a
temporary folder ({tmp}). Run from anywhere: python3 make_corpus.py"""
import pathlib
import struct
import zlib

HERE = pathlib.Path(__file__).resolve().parent
CASES = []  # (id, argv, exit, expected substrings)


def write(rel, text, binary=False):
    p = HERE / rel
    p.parent.mkdir(parents=True, exist_ok=True)
    if binary:
        p.write_bytes(text)
    else:
        p.write_text(text)
    return "{data}/" + rel


def case(cid, argv, exit_code, *expect):
    # Every case must fail; the exact status is not part of the contract
    # (usage errors are 2 in some programs, 1 in others).
    del exit_code
    CASES.append((cid, argv, "!0", list(expect)))


ODO = ('<component name="odometry" period="0.1" v="0.1" w="0.1">\n'
       '      <provides data="pose" as="odometric_pose" type="types.pose"/>\n'
       '    </component>')


def config(name, agent_body, head="", root="team", agent_attrs='id="a1" kind="robot"'):
    return write(f"config/{name}.xml",
                 f'{head}<{root}>\n  <agent {agent_attrs}>\n    {agent_body}\n  </agent>\n</{root}>\n')


# --- Configurations: sancta check FILE ---------------------------------------------
laughs = "".join(f' <!ENTITY {chr(98 + i)} "' + f"&{chr(97 + i)};" * 16 + '">\n' for i in range(7))
f = write("config/billion-laughs.xml",
          '<?xml version="1.0"?>\n<!DOCTYPE team [\n <!ENTITY a "' + "a" * 60 + '">\n'
          + laughs + ']>\n<team>\n  <agent id="a1" kind="robot">\n'
          '    <component name="odometry" period="0.1" v="&h;"/>\n  </agent>\n</team>\n')
case("config-billion-laughs", f"sancta check {f}", 1, "billion-laughs.xml:2:", "DOCTYPE")
f = write("config/external-entity.xml",
          '<?xml version="1.0"?>\n<!DOCTYPE team [ <!ENTITY x SYSTEM "file:///etc/passwd"> ]>\n'
          '<team><agent id="a1" kind="robot"><component name="odometry" v="&x;"/></agent></team>\n')
case("config-external-entity", f"sancta check {f}", 1, "external-entity.xml:2:", "DOCTYPE")
f = write("config/doctype-only.xml", '<!DOCTYPE team>\n<team><agent id="a1"/></team>\n')
case("config-doctype", f"sancta check {f}", 1, "doctype-only.xml:1:", "DOCTYPE")
f = config("period-zero", ODO.replace('period="0.1"', 'period="0"'))
case("config-period-zero", f"sancta check {f}", 1, "period-zero.xml:3:", "period")
f = config("period-1ns", ODO.replace('period="0.1"', 'period="1e-9"'))
case("config-period-1ns", f"sancta check {f}", 1, "period-1ns.xml:3:", "0.001")
f = config("period-negative", ODO.replace('period="0.1"', 'period="-1"'))
case("config-period-negative", f"sancta check {f}", 1, "period-negative.xml:3:", "period")
f = config("period-huge", ODO.replace('period="0.1"', 'period="1e300"'))
case("config-period-huge", f"sancta check {f}", 1, "period-huge.xml:3:", "period")
f = config("period-nan", ODO.replace('period="0.1"', 'period="NaN"'))
case("config-period-nan", f"sancta check {f}", 1, "period-nan.xml:3:", "period")
f = config("period-text", ODO.replace('period="0.1"', 'period="fast"'))
case("config-period-text", f"sancta check {f}", 1, "period-text.xml:3:", "fast")
f = config("timeout-huge", ODO + '\n    <component name="watchdog" timeout="1e20">\n'
           '      <requires data="watched" as="odometric_pose"/>\n    </component>')
case("config-timeout-huge", f"sancta check {f}", 1, "timeout-huge.xml:6:", "timeout")
f = write("config/nul-in-id.xml", b'<team>\n  <agent id="a\x001" kind="robot">\n'
          b'    <component name="odometry" period="0.1"/>\n  </agent>\n</team>\n', binary=True)
case("config-nul-in-id", f"sancta check {f}", 1, "nul-in-id.xml:")
f = write("config/ctrl-in-id.xml", '<team>\n  <agent id="a&#1;1" kind="robot">\n'
          '    <component name="odometry" period="0.1"/>\n  </agent>\n</team>\n')
case("config-ctrl-char-in-id", f"sancta check {f}", 1, "ctrl-in-id.xml:2:")
f = config("space-in-id", ODO, agent_attrs='id="a 1" kind="robot"')
case("config-space-in-id", f"sancta check {f}", 1, "space-in-id.xml:2:", "id")
f = config("slash-in-id", ODO, agent_attrs='id="../a1" kind="robot"')
case("config-slash-in-id", f"sancta check {f}", 1, "slash-in-id.xml:2:", "id")
f = config("long-id", ODO, agent_attrs='id="' + "a" * 300 + '" kind="robot"')
case("config-long-id", f"sancta check {f}", 1, "long-id.xml:2:", "id")
f = config("empty-id", ODO, agent_attrs='id="" kind="robot"')
case("config-empty-id", f"sancta check {f}", 1, "empty-id.xml:2:")
f = config("bad-kind", ODO, agent_attrs='id="a1" kind="toaster"')
case("config-bad-kind", f"sancta check {f}", 1, "bad-kind.xml:2:", "toaster")
f = write("config/copy-loop.xml", """<team>
  <agent id="a1" kind="robot">
    <component name="copy">
      <requires data="input" as="x"/>
      <provides data="output" as="y"/>
    </component>
    <component name="copy">
      <requires data="input" as="y"/>
      <provides data="output" as="x"/>
    </component>
  </agent>
</team>
""")
case("config-copy-loop", f"sancta check {f}", 1, "copy-loop.xml:", "loop")
f = write("config/copy-self.xml", """<team>
  <agent id="a1" kind="robot">
    <component name="copy">
      <requires data="input" as="x"/>
      <provides data="output" as="x"/>
    </component>
  </agent>
</team>
""")
case("config-copy-self", f"sancta check {f}", 1, "copy-self.xml:")
f = write("config/merge-loop.xml", """<team>
  <agent id="a1" kind="robot">
    <component name="value" type="types.real" value="1">
      <provides data="output" as="a"/>
    </component>
    <component name="merge">
      <requires data="a" as="a"/>
      <requires data="b" as="c"/>
      <provides data="output" as="b"/>
    </component>
    <component name="copy">
      <requires data="input" as="b"/>
      <provides data="output" as="c"/>
    </component>
  </agent>
</team>
""")
case("config-merge-loop", f"sancta check {f}", 1, "merge-loop.xml:", "loop")
f = write("config/unclosed.xml", "<team>\n  <agent id=\"a1\">\n")
case("config-unclosed", f"sancta check {f}", 1, "unclosed.xml:3:", "malformed XML")
f = write("config/empty.xml", "")
case("config-empty-file", f"sancta check {f}", 1, "empty.xml:1:")
f = write("config/binary.xml", bytes(range(256)) * 4, binary=True)
case("config-binary", f"sancta check {f}", 1, "binary.xml:1:")
f = write("config/bad-utf8.xml", b'<team>\n  <agent id="\xff\xfe" kind="robot"/>\n</team>\n', binary=True)
case("config-bad-utf8", f"sancta check {f}", 1, "bad-utf8.xml:2:")
f = write("config/two-roots.xml", "<team/>\n<team/>\n")
case("config-two-roots", f"sancta check {f}", 1, "two-roots.xml:2:")
f = write("config/dup-attr.xml", '<team>\n  <agent id="a1" id="a2"/>\n</team>\n')
case("config-duplicate-attribute", f"sancta check {f}", 1, "dup-attr.xml:2:")
f = write("config/unknown-entity.xml", '<team>\n  <agent id="&nope;"/>\n</team>\n')
case("config-unknown-entity", f"sancta check {f}", 1, "unknown-entity.xml:2:")
f = write("config/pi.xml", '<?xml-stylesheet href="x"?>\n<team>\n  <agent id="a1"><component name="nope"/></agent>\n</team>\n')
case("config-unknown-component-after-pi", f"sancta check {f}", 1, "pi.xml:3:", "nope")
f = write("config/constant-loop.xml", '<team>\n  <constant name="$a" value="$b"/>\n'
          '  <constant name="$b" value="$a"/>\n  <agent id="a1" kind="robot">\n'
          '    <component name="odometry" period="$a"/>\n  </agent>\n</team>\n')
case("config-constant-loop", f"sancta check {f}", 1, "constant-loop.xml:")
f = write("config/constant-explosion.xml", '<team>\n  <constant name="$a" value="xxxxxxxxxxxxxxxx"/>\n'
          + "".join(f'  <constant name="${chr(98 + i)}" value="' + f"${chr(97 + i)}" * 16 + '"/>\n'
                    for i in range(7))
          + '  <agent id="a1" kind="robot">\n    <component name="odometry" v="$h"/>\n  </agent>\n</team>\n')
case("config-constant-explosion", f"sancta check {f}", 1, "constant-explosion.xml:")
f = write("config/constant-no-name.xml", '<team>\n  <constant value="1"/>\n  <agent id="a1"/>\n</team>\n')
case("config-constant-no-name", f"sancta check {f}", 1, "constant-no-name.xml:2:")
f = write("config/constant-bad-name.xml", '<team>\n  <constant name="a b" value="1"/>\n  <agent id="a1"/>\n</team>\n')
case("config-constant-bad-name", f"sancta check {f}", 1, "constant-bad-name.xml:2:")
f = write("config/include-self.xml", '<team>\n  <include file="include-self.xml"/>\n  <agent id="a1"/>\n</team>\n')
case("config-include-self", f"sancta check {f}", 1, "include-self.xml:2:")
f = write("config/include-dir.xml", '<team>\n  <include file="."/>\n  <agent id="a1"/>\n</team>\n')
case("config-include-directory", f"sancta check {f}", 1, "include-dir.xml:2:")
f = write("config/include-devzero.xml", '<team>\n  <include file="/dev/zero"/>\n  <agent id="a1"/>\n</team>\n')
case("config-include-dev-zero", f"sancta check {f}", 1, "include-devzero.xml:2:")
f = write("config/include-nofile.xml", '<team>\n  <include/>\n  <agent id="a1"/>\n</team>\n')
case("config-include-no-file", f"sancta check {f}", 1, "include-nofile.xml:2:")
f = write("config/use-missing.xml", '<team>\n  <agent id="a1">\n    <use group="ghost"/>\n  </agent>\n</team>\n')
case("config-use-unknown-group", f"sancta check {f}", 1, "use-missing.xml:3:", "ghost")
f = write("config/group-self.xml", '<team>\n  <group name="g">\n    <use group="g"/>\n  </group>\n'
          '  <agent id="a1">\n    <use group="g"/>\n  </agent>\n</team>\n')
case("config-group-uses-itself", f"sancta check {f}", 1, "group-self.xml:")
f = config("order-huge", ODO.replace('period="0.1"', 'order="99999999999999999999"'))
case("config-order-huge", f"sancta check {f}", 1, "order-huge.xml:3:", "order")
f = config("enabled-maybe", ODO.replace('period="0.1"', 'enabled="maybe"'))
case("config-enabled-maybe", f"sancta check {f}", 1, "enabled-maybe.xml:3:", "maybe")
f = config("speed-inf", ODO.replace('v="0.1"', 'v="Inf"'))
case("config-real-inf", f"sancta check {f}", 1, "speed-inf.xml:3:", "Inf")
f = config("speed-huge", ODO.replace('v="0.1"', 'v="1e400"'))
case("config-real-overflow", f"sancta check {f}", 1, "speed-huge.xml:3:", "1e400")
f = config("unknown-option", ODO.replace('v="0.1"', 'velocity="0.1"'))
case("config-unknown-option", f"sancta check {f}", 1, "unknown-option.xml:3:", "velocity")
f = config("logger-missing-folder", ODO + '\n    <component name="logger" file="/dev/null/x/log.csv" period="0.1">\n'
           '      <requires data="pose" as="odometric_pose"/>\n    </component>')
case("config-logger-folder-cannot-exist", f"sancta run {f} --all --for 2", 1,
     "logger-missing-folder.xml:6:", "/dev/null")
f = config("logger-dev-full", ODO + '\n    <component name="logger" file="/" period="0.1">\n'
           '      <requires data="pose" as="odometric_pose"/>\n    </component>')
case("config-logger-file-is-folder", f"sancta run {f} --all --for 2", 1,
     "logger-dev-full.xml:6:", "folder")
f = config("logger-empty-file", ODO + '\n    <component name="logger" file="" period="0.1">\n'
           '      <requires data="pose" as="odometric_pose"/>\n    </component>')
case("config-logger-empty-file", f"sancta check {f}", 1, "logger-empty-file.xml:6:", "file")
f = config("logger-bad-format", ODO + '\n    <component name="logger" file="out/x.csv" format="xml">\n'
           '      <requires data="pose" as="odometric_pose"/>\n    </component>')
case("config-logger-bad-format", f"sancta check {f}", 1, "logger-bad-format.xml:6:", "xml")
f = config("no-kind", ODO, agent_attrs='id="a1"')
case("config-run-unknown-agent", f"sancta run {f} --agent zz --for 1", 2, "zz")
f = config("value-bad-pose", '<component name="value" type="types.pose" value="1 2">\n'
           '      <provides data="output" as="p"/>\n    </component>')
case("config-value-bad-pose", f"sancta check {f}", 1, "value-bad-pose.xml:3:", "x y yaw")
f = config("value-nan-pose", '<component name="value" type="types.pose" value="NaN 1 2">\n'
           '      <provides data="output" as="p"/>\n    </component>')
case("config-value-nan-pose", f"sancta check {f}", 1, "value-nan-pose.xml:3:")
f = config("ros2-bad-depth", '<component name="ros2_subscriber" topic="/x" msg_type="std_msgs/msg/String" depth="-5">\n'
           '      <provides data="message" as="m" type="ros2:std_msgs/msg/String"/>\n    </component>')
case("config-ros2-negative-depth", f"sancta check {f}", 1, "ros2-bad-depth.xml:3:", "depth")
f = config("ros2-huge-depth", '<component name="ros2_subscriber" topic="/x" msg_type="std_msgs/msg/String" depth="99999999999">\n'
           '      <provides data="message" as="m" type="ros2:std_msgs/msg/String"/>\n    </component>')
case("config-ros2-huge-depth", f"sancta check {f}", 1, "ros2-huge-depth.xml:3:", "depth")
POSE = '<component name="value" type="types.pose" value="2 10 0">\n      <provides data="output" as="pose"/>\n    </component>\n    '
f = config("team-member-bad-lease", POSE + '<component name="team_member" lease="0">\n'
           '      <requires data="pose" as="pose" type="types.pose"/>\n    </component>')
case("config-team-member-lease-zero", f"sancta check {f}", 1, "team-member-bad-lease.xml:6:", "lease")
f = config("team-operator-missing-mission", '<component name="team_operator" mission="/nonexistent/m.xml"/>',
           agent_attrs='id="operator" kind="operator"')
case("config-operator-missing-mission", f"sancta check {f}", 1, "/nonexistent/m.xml")
f = config("team-member-missing-world", POSE + '<component name="team_member" world="/nonexistent/w.yaml" costs="grid">\n'
           '      <requires data="pose" as="pose" type="types.pose"/>\n    </component>')
case("config-member-missing-world", f"sancta check {f}", 1, "/nonexistent/w.yaml")
for name in ["bad-choice", "bad-deep-nesting", "bad-duplicate-agent", "bad-empty", "bad-enabled",
             "bad-include-cycle", "bad-include-missing", "bad-malformed", "bad-missing-option",
             "bad-no-agent", "bad-unknown-component", "bad-unknown-constant", "bad-unknown-type",
             "bad-value-parse"]:
    case(f"config-{name}", f"sancta check {{repo}}/tests/data/config/{name}.xml", 1,
         f"{name}.xml:")
case("config-huge-attribute", "sancta check {tmp}/huge-attribute.xml", 1, "huge-attribute.xml:")
case("config-huge-file", "sancta check {tmp}/huge-file.xml", 1, "huge-file.xml:")
case("config-many-agents", "sancta check {tmp}/many-agents.xml", 1, "many-agents.xml:")

# --- Missions: sancta plan FILE.xml, sancta team FILE --check ----------------------------
WORLD = "../../../../share/worlds/office.yaml"  # from tests/data/broken/mission/


def mission(name, body, attrs='scale="100"'):
    return write(f"mission/{name}.xml", f'<?xml version="1.0"?>\n<mission {attrs}>\n{body}</mission>\n')


R = '  <robot id="r1" x="1" y="1"/>\n'
f = mission("inf-coordinate", R + '  <task id="t1" x="Inf" y="2"/>\n')
case("mission-inf-coordinate", f"sancta plan {f} --time 1", 1, "inf-coordinate.xml:4:", "x")
f = mission("nan-coordinate", R + '  <task id="t1" x="1" y="NaN"/>\n')
case("mission-nan-coordinate", f"sancta plan {f} --time 1", 1, "nan-coordinate.xml:4:", "y")
f = mission("huge-coordinate", R + '  <task id="t1" x="1e300" y="2"/>\n')
case("mission-huge-coordinate", f"sancta plan {f} --time 1", 1, "huge-coordinate.xml:4:", "x")
f = mission("huge-robot", '  <robot id="r1" x="-1e200" y="1"/>\n  <task id="t1" x="1" y="2"/>\n')
case("mission-huge-robot-coordinate", f"sancta plan {f} --time 1", 1, "huge-robot.xml:3:")
f = mission("overflow-coordinate", R + '  <task id="t1" x="1e999" y="2"/>\n')
case("mission-overflow-coordinate", f"sancta plan {f} --time 1", 1, "overflow-coordinate.xml:4:")
f = mission("bad-scale", R + '  <task id="t1" x="1" y="2"/>\n', attrs='scale="0"')
case("mission-scale-zero", f"sancta plan {f} --time 1", 1, "bad-scale.xml:2:", "scale")
f = mission("huge-scale", R + '  <task id="t1" x="1" y="2"/>\n', attrs='scale="1e300"')
case("mission-scale-huge", f"sancta plan {f} --time 1", 1, "huge-scale.xml:2:", "scale")
f = mission("no-robot", '  <task id="t1" x="1" y="2"/>\n')
case("mission-no-robot", f"sancta plan {f} --time 1", 1, "no-robot.xml:")
f = mission("no-task", R)
case("mission-no-task", f"sancta plan {f} --time 1", 1, "no-task.xml:")
f = mission("dup-task", R + '  <task id="t1" x="1" y="2"/>\n  <task id="t1" x="3" y="2"/>\n')
case("mission-duplicate-task", f"sancta plan {f} --time 1", 1, "dup-task.xml:5:", "t1")
f = mission("dup-robot", R + R + '  <task id="t1" x="1" y="2"/>\n')
case("mission-duplicate-robot", f"sancta plan {f} --time 1", 1, "dup-robot.xml:4:", "r1")
f = mission("unknown-robot", R + '  <task id="t1" x="1" y="2" robots="zz"/>\n')
case("mission-task-unknown-robot", f"sancta plan {f} --time 1", 1, "unknown-robot.xml:4:", "zz")
f = mission("done-unknown", R + '  <task id="t1" x="1" y="2"/>\n  <done robot="r1" tasks="t9"/>\n')
case("mission-done-unknown-task", f"sancta plan {f} --time 1", 1, "done-unknown.xml:5:", "t9")
f = mission("or-empty", R + '  <or id="o1"/>\n')
case("mission-or-empty", f"sancta plan {f} --time 1", 1, "or-empty.xml:4:", "o1")
f = mission("bad-cost", '  <robot id="r1" x="1" y="1" cost="-2"/>\n  <task id="t1" x="1" y="2"/>\n')
case("mission-negative-cost", f"sancta plan {f} --time 1", 1, "bad-cost.xml:3:", "cost")
f = mission("nul-task-id", R + '  <task id="t&#0;1" x="1" y="2"/>\n')
case("mission-nul-entity", f"sancta plan {f} --time 1", 1, "nul-task-id.xml:4:")
f = mission("unknown-element", R + '  <tsk id="t1" x="1" y="2"/>\n')
case("mission-unknown-element", f"sancta plan {f} --time 1", 1, "unknown-element.xml:4:", "tsk")
f = mission("missing-x", R + '  <task id="t1" y="2"/>\n')
case("mission-missing-x", f"sancta plan {f} --time 1", 1, "missing-x.xml:4:", "x")
f = write("mission/laughs.xml", '<?xml version="1.0"?>\n<!DOCTYPE mission [\n <!ENTITY a "' + "a" * 60
          + '">\n' + laughs + ']>\n<mission>\n  <robot id="r1" x="1" y="1"/>\n  <task id="&h;" x="1" y="2"/>\n</mission>\n')
case("mission-billion-laughs", f"sancta plan {f} --time 1", 1, "laughs.xml:2:", "DOCTYPE")
case("mission-too-many-tasks", "sancta plan {tmp}/many-tasks.xml --time 2", 1,
     "many-tasks.xml", "tasks")
f = write("mission/team-missing-world.xml", '<?xml version="1.0"?>\n<mission name="m" world="/nonexistent/world.yaml">\n'
          '  <robot id="r1" x="2" y="2"/> <robot id="r2" x="6" y="10"/>\n  <goto id="t1" x="3" y="3"/>\n</mission>\n')
case("team-missing-world", f"sancta team {f} --check", 1, "/nonexistent/world.yaml", "cannot be opened")
f = write("mission/team-outside.xml", f'<?xml version="1.0"?>\n<mission name="m" world="{WORLD}">\n'
          '  <robot id="r1" x="2.5" y="10"/> <robot id="r2" x="6" y="10"/>\n  <goto id="t1" x="500" y="3"/>\n</mission>\n')
case("team-task-outside-world", f"sancta team {f} --check", 1, "team-outside.xml: task t1", "not reachable")
f = write("mission/team-robot-outside.xml", f'<?xml version="1.0"?>\n<mission name="m" world="{WORLD}">\n'
          '  <robot id="r1" x="-50" y="10"/> <robot id="r2" x="6" y="10"/>\n  <goto id="t1" x="3" y="5"/>\n</mission>\n')
case("team-robot-outside-world", f"sancta team {f} --check", 1, "team-robot-outside.xml: robot r1", "outside the world")
f = write("mission/team-inf.xml", f'<?xml version="1.0"?>\n<mission name="m" world="{WORLD}">\n'
          '  <robot id="r1" x="2.5" y="10"/> <robot id="r2" x="6" y="10"/>\n  <goto id="t1" x="-Inf" y="3"/>\n</mission>\n')
case("team-inf-coordinate", f"sancta team {f} --check", 1, "team-inf.xml:4:")
f = write("mission/team-explore-inf.xml", f'<?xml version="1.0"?>\n<mission name="m" world="{WORLD}">\n'
          '  <robot id="r1" x="2.5" y="10"/> <robot id="r2" x="6" y="10"/>\n  <explore id="e1" x1="1" y1="10" x2="1e308" y2="10"/>\n</mission>\n')
case("team-explore-huge", f"sancta team {f} --check", 1, "team-explore-inf.xml:4:")
f = write("mission/team-choose-empty.xml", f'<?xml version="1.0"?>\n<mission name="m" world="{WORLD}">\n'
          '  <robot id="r1" x="2.5" y="10"/> <robot id="r2" x="6" y="10"/>\n  <choose id="c1"/>\n</mission>\n')
case("team-choose-empty", f"sancta team {f} --check", 1, "team-choose-empty.xml:4:", "<choose> needs at least one <at>")
f = write("mission/team-bad-id.xml", f'<?xml version="1.0"?>\n<mission name="m" world="{WORLD}">\n'
          '  <robot id="r 1" x="2.5" y="10"/> <robot id="r2" x="6" y="10"/>\n  <goto id="t1" x="3" y="5"/>\n</mission>\n')
case("team-bad-robot-id", f"sancta team {f} --check", 1, "team-bad-id.xml:3:")
f = write("mission/team-dup.xml", f'<?xml version="1.0"?>\n<mission name="m" world="{WORLD}">\n'
          '  <robot id="r1" x="2.5" y="10"/> <robot id="r2" x="6" y="10"/>\n  <goto id="t1" x="3" y="5"/>\n  <goto id="t1" x="4" y="5"/>\n</mission>\n')
case("team-duplicate-task", f"sancta team {f} --check", 1, "team-dup.xml:5:", "t1")
f = write("mission/team-world-garbage.xml", '<?xml version="1.0"?>\n<mission name="m" world="../world/garbage.yaml">\n'
          '  <robot id="r1" x="2" y="2"/> <robot id="r2" x="6" y="10"/>\n  <goto id="t1" x="3" y="3"/>\n</mission>\n')
case("team-world-garbage", f"sancta team {f} --check", 1, "garbage.yaml")
case("team-too-many-tasks", "sancta team {tmp}/team-many-tasks.xml --check", 1,
     "team-many-tasks.xml", "tasks")

# --- Worlds -------------------------------------------------------------------------
g = write("world/garbage.yaml", "image: [unclosed\nresolution: x\n")
case("world-garbage-yaml", f"sancta-render {g} --svg {{tmp}}/w.svg", 1, "garbage.yaml:")
g = write("world/res-nan.yaml", "image: ../../simulation/room.pgm\nresolution: .nan\norigin: [0, 0, 0]\n")
case("world-resolution-nan", f"sancta-render {g} --svg {{tmp}}/w.svg", 1, "res-nan.yaml:2:")
g = write("world/res-neg.yaml", "image: ../../simulation/room.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n")
case("world-resolution-negative", f"sancta-render {g} --svg {{tmp}}/w.svg", 1, "res-neg.yaml:2:")
g = write("world/origin-inf.yaml", "image: ../../simulation/room.pgm\nresolution: 0.05\norigin: [.inf, 0, 0]\n")
case("world-origin-inf", f"sancta-render {g} --svg {{tmp}}/w.svg", 1, "origin-inf.yaml:3:")
g = write("world/no-image.yaml", "image: nothing-here.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n")
case("world-missing-image", f"sancta-render {g} --svg {{tmp}}/w.svg", 1, "nothing-here.pgm")
g = write("world/image-dir.yaml", "image: .\nresolution: 0.05\norigin: [0, 0, 0]\n")
case("world-image-is-folder", f"sancta-render {g} --svg {{tmp}}/w.svg", 1, "not a regular file")
case("sim-missing-world", "sancta-sim /nonexistent/w.yaml --duration 1", 1, "/nonexistent/w.yaml")
case("sim-world-garbage", f"sancta-sim {{data}}/world/garbage.yaml --duration 1", 1, "garbage.yaml:")

# --- TSPLIB: sancta plan FILE.tsp ---------------------------------------------------------


def tsp(name, text):
    return write(f"tsp/{name}", text)


HEAD = "NAME : x\nTYPE : TSP\nDIMENSION : {n}\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n"
f = tsp("dim-zero.tsp", HEAD.format(n=0) + "EOF\n")
case("tsp-dimension-zero", f"sancta plan {f} --time 1", 1, "dim-zero.tsp:3:", "DIMENSION")
f = tsp("dim-negative.tsp", HEAD.format(n=-5) + "EOF\n")
case("tsp-dimension-negative", f"sancta plan {f} --time 1", 1, "dim-negative.tsp:3:", "DIMENSION")
f = tsp("dim-huge.tsp", HEAD.format(n=2000000000) + "1 0 0\n2 1 1\nEOF\n")
case("tsp-dimension-huge", f"sancta plan {f} --time 1", 1, "dim-huge.tsp:3:", "DIMENSION")
f = tsp("dim-text.tsp", HEAD.format(n="many") + "EOF\n")
case("tsp-dimension-text", f"sancta plan {f} --time 1", 1, "dim-text.tsp:3:", "many")
f = tsp("short.tsp", HEAD.format(n=5) + "1 0 0\n2 1 1\nEOF\n")
case("tsp-fewer-nodes", f"sancta plan {f} --time 1", 1, "short.tsp:8:", "EOF")
f = tsp("nan.tsp", HEAD.format(n=3) + "1 0 0\n2 nan 1\n3 2 2\nEOF\n")
case("tsp-nan-coordinate", f"sancta plan {f} --time 1", 1, "nan.tsp:7:")
f = tsp("inf.tsp", HEAD.format(n=3) + "1 0 0\n2 1e999 1\n3 2 2\nEOF\n")
case("tsp-overflow-coordinate", f"sancta plan {f} --time 1", 1, "inf.tsp:7:")
f = tsp("huge.tsp", HEAD.format(n=3) + "1 0 0\n2 1e300 1\n3 2 2\nEOF\n")
case("tsp-huge-coordinate", f"sancta plan {f} --time 1", 1, "huge.tsp:7:")
f = tsp("bad-index.tsp", HEAD.format(n=3) + "1 0 0\n7 1 1\n3 2 2\nEOF\n")
case("tsp-node-index-out-of-range", f"sancta plan {f} --time 1", 1, "bad-index.tsp:7:")
f = tsp("dup-index.tsp", HEAD.format(n=3) + "1 0 0\n1 1 1\n3 2 2\nEOF\n")
case("tsp-duplicate-node", f"sancta plan {f} --time 1", 1, "dup-index.tsp:7:")
f = tsp("garbage-line.tsp", HEAD.format(n=3) + "1 0 0\n2 one two\n3 2 2\nEOF\n")
case("tsp-garbage-line", f"sancta plan {f} --time 1", 1, "garbage-line.tsp:7:")
f = tsp("unknown-type.tsp", "NAME : x\nTYPE : TSP\nDIMENSION : 3\nEDGE_WEIGHT_TYPE : SPHERE_9D\n"
        "NODE_COORD_SECTION\n1 0 0\n2 1 1\n3 2 2\nEOF\n")
case("tsp-unknown-weight-type", f"sancta plan {f} --time 1", 1, "unknown-type.tsp:", "SPHERE_9D")
f = tsp("no-dimension.tsp", "NAME : x\nTYPE : TSP\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n1 0 0\nEOF\n")
case("tsp-no-dimension", f"sancta plan {f} --time 1", 1, "no-dimension.tsp:", "DIMENSION")
f = tsp("matrix-short.atsp", "NAME: x\nTYPE: ATSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EXPLICIT\n"
        "EDGE_WEIGHT_FORMAT: FULL_MATRIX\nEDGE_WEIGHT_SECTION\n0 1 2\n3 0\nEOF\n")
case("tsp-matrix-short", f"sancta plan {f} --time 1", 1, "matrix-short.atsp:")
f = tsp("matrix-negative.atsp", "NAME: x\nTYPE: ATSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EXPLICIT\n"
        "EDGE_WEIGHT_FORMAT: FULL_MATRIX\nEDGE_WEIGHT_SECTION\n0 1 2\n3 0 -4\n5 6 0\nEOF\n")
case("tsp-matrix-negative", f"sancta plan {f} --time 1", 1, "matrix-negative.atsp:8:")
f = tsp("matrix-huge.atsp", "NAME: x\nTYPE: ATSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EXPLICIT\n"
        "EDGE_WEIGHT_FORMAT: FULL_MATRIX\nEDGE_WEIGHT_SECTION\n0 1 2\n3 0 99999999999999999999999\n5 6 0\nEOF\n")
case("tsp-matrix-huge-weight", f"sancta plan {f} --time 1", 1, "matrix-huge.atsp:8:")
f = tsp("unknown-format.atsp", "NAME: x\nTYPE: ATSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EXPLICIT\n"
        "EDGE_WEIGHT_FORMAT: SPIRAL\nEDGE_WEIGHT_SECTION\n0 1 2\nEOF\n")
case("tsp-unknown-matrix-format", f"sancta plan {f} --time 1", 1, "unknown-format.atsp:", "SPIRAL")
f = tsp("empty.tsp", "")
case("tsp-empty", f"sancta plan {f} --time 1", 1, "empty.tsp:")
f = tsp("binary.tsp", "NAME : \x01\x02\x03\nTYPE : TSP\nDIMENSION : 3\x00\n")
case("tsp-binary", f"sancta plan {f} --time 1", 1, "binary.tsp:")
case("tsp-too-many-cities", "sancta plan {tmp}/many.tsp --time 2", 1, "many.tsp:3:", "DIMENSION")
f = tsp("robots-more.tsp", HEAD.format(n=3) + "1 0 0\n2 1 1\n3 2 2\nEOF\n")
case("tsp-more-robots-than-cities", f"sancta plan {f} --robots 10 --time 1", 2, "too few tasks")

# --- Command lines -----------------------------------------------------------------------
EX = "{repo}/share/missions/example.xml"
TEAMX = "{repo}/share/config/team.xml"
case("cli-unknown-command", "sancta frobnicate", 2, "frobnicate")
case("cli-check-no-file", "sancta check", 2, "usage")
case("cli-run-set-unknown", f"sancta run {TEAMX} --all --for 1 --set nosuch=3", 2, "nosuch")
case("cli-run-set-no-equals", f"sancta run {TEAMX} --all --for 1 --set speed", 2, "--set")
case("cli-run-for-nan", f"sancta run {TEAMX} --all --for nan", 2, "--for")
case("cli-run-for-huge", f"sancta run {TEAMX} --all --for 1e300", 2, "--for")
case("cli-run-no-agent", f"sancta run {TEAMX}", 2, "--agent")
case("cli-run-unknown-option", f"sancta run {TEAMX} --all --bogus", 2, "--bogus")
case("cli-plan-robots-zero", f"sancta plan {EX} --robots 0", 2, "--robots")
case("cli-plan-robots-huge", "sancta plan {repo}/share/tsplib/eil76.tsp --robots 99999999999", 2, "--robots")
case("cli-plan-time-negative", f"sancta plan {EX} --time -3", 2, "--time")
case("cli-plan-time-nan", f"sancta plan {EX} --time nan", 2, "--time")
case("cli-plan-time-huge", f"sancta plan {EX} --time 1e300", 2, "--time")
case("cli-plan-unknown-objective", f"sancta plan {EX} --objective fastest", 2, "fastest")
case("cli-plan-bad-weights", f"sancta plan {EX} --objective 1,nan,2", 2, "--objective")
case("cli-plan-unknown-solver", f"sancta plan {EX} --solver magic", 2, "magic")
case("cli-plan-seed-text", f"sancta plan {EX} --seed x", 2, "--seed")
case("cli-plan-iterations-negative", f"sancta plan {EX} --iterations -1", 2, "--iterations")
case("cli-plan-restarts-huge", f"sancta plan {EX} --restarts 100000", 2, "--restarts")
case("cli-plan-ruin-2", f"sancta plan {EX} --ruin 2", 2, "--ruin")
case("cli-plan-missing-value", f"sancta plan {EX} --time", 2, "--time")
case("cli-plan-json-unwritable", f"sancta plan {EX} --time 0.2 --json /nonexistent/x.json", 1, "/nonexistent/x.json")
case("cli-plan-missing-file", "sancta plan /nonexistent/m.xml", 1, "/nonexistent/m.xml")
case("cli-plan-unknown-extension", "sancta plan {repo}/README.md", 1, "README.md")
case("cli-team-rate-zero", "sancta team --rate 0 --check", 2, "--rate")
case("cli-team-lease-negative", "sancta team --lease -1 --check", 2, "--lease")
case("cli-team-unknown-method", "sancta team --method telepathy --check", 2, "telepathy")
case("cli-team-kill-at-2", "sancta team --kill-at 2 --check", 2, "--kill-at")
case("cli-demo-set-unknown", "sancta demo {repo}/share/config/sim-team.xml --set "
     "mission={repo}/share/missions/office-team.xml --set nosuch=1 --check", 2, "nosuch")
case("cli-demo-rate-nan", "sancta demo --rate nan --check", 2, "--rate")
case("cli-demo-missing-config", "sancta demo /nonexistent/c.xml --check", 1, "/nonexistent/c.xml")
case("cli-team-agent-no-id", "sancta team-agent --for 1", 2, "--id")
case("cli-team-agent-bad-id", "sancta team-agent --id 'r 1' --for 1", 2, "r 1")
case("cli-team-agent-speed-inf", "sancta team-agent --id r1 --speed inf --for 1", 2, "--speed")
case("cli-rclada-pub-times-negative",
     "rclada topic pub /chatter std_msgs/msg/String '{data: x}' --times -1", 2, "--times")
case("cli-rclada-pub-no-yaml", "rclada topic pub /chatter std_msgs/msg/String", 2, "YAML")
case("cli-rclada-pub-rate-nan",
     "rclada topic pub /chatter std_msgs/msg/String '{data: x}' --rate nan", 2, "--rate")
case("cli-rclada-unknown-verb", "rclada topic frob", 2, "frob")
case("cli-rclada-echo-no-type-timeout", "rclada topic echo /chatter std_msgs/msg/String --count 0", 2, "--count")
case("cli-rclada-call-bad-yaml", "rclada service call /x example_interfaces/srv/AddTwoInts '{a: [}'", 1, "<argument>:1:")
case("cli-sim-rate-zero", "sancta-sim arena --rate 0x --duration 1", 2, "--rate")
case("cli-sim-duration-negative", "sancta-sim arena --duration -5", 2, "--duration")
case("cli-sim-bad-robot", "sancta-sim arena --robot 'r1 nan 5 0' --duration 1", 2, "--robot")
case("cli-sim-robot-outside", "sancta-sim arena --robot 'r1 500 5 0' --duration 1", 2, "outside")
case("cli-sim-unknown-option", "sancta-sim arena --frob", 2, "--frob")
case("cli-render-no-args", "sancta-render", 2, "usage")

# Found by scripts/fuzz_inputs.py (session 8); each failed on the code before its fix.
# A mission that is not well-formed XML: the file named once, then line:column
# (was "m.xml:m.xml:4:5: ...").
f = mission("unclosed-attribute", R + '  <task id="t1" x="1 y="2"/>\n')
case("fuzz-mission-malformed-xml-located-once", f"sancta plan {f} --time 1", 1,
     f"sancta plan: {f}:4:")
# A map of a few cells with a huge resolution: its picture measures more
# pixels than an integer holds (was "sancta-simulation-rendering.adb:400
# range check failed").
g = write("world/res-huge.yaml", "image: ../../simulation/room.pgm\nresolution: 2147483647\n"
          "origin: [0, 0, 0]\n")
case("fuzz-world-picture-too-large", f"sancta-render {g} --svg {{tmp}}/w.svg", 1,
     "res-huge.yaml: the world is", "--scale")
# A 2 MB line in a wall world, a map YAML and a trajectories CSV (made in
# {tmp}): "FILE:1: line longer than 65536 characters" (was STORAGE_ERROR).
case("fuzz-walls-long-line", "sancta-render {tmp}/long-line.walls --svg {tmp}/w.svg", 1,
     "long-line.walls:2: line longer than")
case("fuzz-map-yaml-long-line", "sancta-render {tmp}/long-line.yaml --svg {tmp}/w.svg", 1,
     "long-line.yaml:2: line longer than")
case("fuzz-trajectories-long-line", "sancta-render {repo}/share/worlds/arena.walls "
     "--trajectories {tmp}/long-line.csv --svg {tmp}/w.svg", 1, "long-line.csv:3: line longer than")
# 2 MB lines in XML read by the configuration loader (sancta check, sancta
# team): the whole file is read (was "FILE:1:1: cannot read: STORAGE_ERROR").
case("fuzz-config-long-line", "sancta check {tmp}/long-line-config.xml", 1,
     "long-line-config.xml:2:", "nosuch")
case("fuzz-team-mission-long-line", "sancta team {tmp}/long-line-mission.xml --check", 1,
     "long-line-mission.xml:5:", "t1")
# A trajectory sample of 1e400 (an infinity): its line (was
# "sancta-simulation-rendering.adb:465 invalid data").
g = write("world/trajectory-inf.csv", "robot,x,y\n1,1,1\n1,1e400,2\n")
case("fuzz-trajectory-infinite", f"sancta-render {{repo}}/share/worlds/arena.walls --trajectories {g}"
     " --svg {tmp}/w.svg", 1, "trajectory-inf.csv:3:")
case("fuzz-config-long-unknown-option", "sancta check {tmp}/long-option.xml", 1,
     "long-option.xml:3:", "unknown option")
# A missing image with a 300-character name: the YAML line first (the
# message used to start with the path and lose its reason past 200 characters).
g = write("world/long-image-name.yaml", "resolution: 0.05\nimage: " + "x" * 300
          + ".pgm\norigin: [0, 0, 0]\n")
case("fuzz-world-long-image-name", f"sancta-render {g} --svg {{tmp}}/w.svg", 1,
     "long-image-name.yaml:2: image: no such file")

# Found by the fuzzer's args reader (session 9): --ros-args and --params-file
# through a node program's argument parser. Each failed on the code before its fix.
# A long argument: its reason kept (GNAT cuts exception messages at 200
# characters; the argument was quoted whole before the reason).
A300 = "a" * 300
case("fuzz-ros-args-long-remap", f"parameters_demo --ros-args -r {A300}", 2,
     "argument 3", "expected from:=to")
case("fuzz-ros-args-long-param", f"parameters_demo --ros-args -p {A300}", 2,
     "argument 3", "expected [node:]name:=value")
case("fuzz-ros-args-long-log-level", f"parameters_demo --ros-args --log-level {A300}", 2,
     "argument 3", "unknown log level", "(debug, info, warn, error, fatal)")
# A parameter name or node prefix rcl refuses (was accepted: an override
# that never applies).
case("fuzz-ros-args-parameter-name", "parameters_demo --ros-args -p 'a b:=1'", 2,
     "argument 3", "parameter name \"a b\": invalid character ' ' at position 2")
case("fuzz-ros-args-parameter-node", "parameters_demo --ros-args -p 9node:rate:=1", 2,
     "argument 3", "node name \"9node\": must not start with a digit")
# Names longer than rmw's limits (a 300-character node name ran, and its
# discovery announcement failed at every publication).
case("fuzz-ros-args-long-node-name", f"parameters_demo --ros-args -r __node:={A300}", 2,
     "argument 3", "node name", "300 characters, longer than 255")
case("fuzz-ros-args-long-namespace", f"parameters_demo --ros-args -r __ns:=/{A300}", 2,
     "argument 3", "namespace", "301 characters, longer than 245")
# An override the node refuses: where it was given (a file's line and column,
# or the argument) leads the message (was named by neither).
g = write("args/wrong-type.yaml", "parameters_demo:\n  ros__parameters:\n    rate: fast\n")
case("fuzz-params-file-override-type", f"parameters_demo --ros-args --params-file {g}", 2,
     "wrong-type.yaml:3:11: parameter 'rate' of /parameters_demo is integer")
g = write("args/rejected.yaml", "/**:\n  ros__parameters:\n    name: x\n    rate: 500\n")
case("fuzz-params-file-override-rejected", f"parameters_demo --ros-args --params-file {g}", 2,
     "rejected.yaml:4:11: parameter 'rate'", "rate must be within 1 .. 100")
case("fuzz-ros-args-override-rejected", "parameters_demo --ros-args -p rate:=0", 2,
     "--ros-args -p rate: parameter 'rate'", "rate must be within 1 .. 100")

# Found by the fuzzer's run reader (session 9): a group used twice by one
# agent is refused at the second <use> (its components' keys were reported
# as provided twice at the group's lines, possibly in an included file).
g = write("config/group-used-twice.xml",
          '<team>\n  <group name="base">\n    ' + ODO + '\n  </group>\n'
          '  <agent id="a1" kind="robot">\n    <use group="base"/>\n    <use group="base"/>\n'
          '  </agent>\n</team>\n')
case("fuzz-config-group-used-twice", f"sancta check {g}", 1,
     "group-used-twice.xml:9:", "group 'base' is used twice in agent 'a1'",
     "(first at ", "group-used-twice.xml:8:")

# A logger file whose name has a part longer than 255 characters: refused
# by the check (sancta run started it and the logger failed in Start with
# ADA.IO_EXCEPTIONS.USE_ERROR, retried forever).
g = config("logger-long-name", '<component name="logger" file="out/' + "x_" * 150
           + '.csv">\n      <requires data="a" as="a"/>\n    </component>\n    '
           + ODO.replace('as="odometric_pose"', 'as="a"'))
case("fuzz-config-logger-long-file-name", f"sancta check {g}", 1,
     "logger-long-name.xml:3:", "a part of the file name has 304 characters, more than 255")

# Session 10: --params-file keys checked as rcl does (node names by the rmw
# rules, no empty parameter name: they silently matched nothing); a long path
# keeps the reason of its error (GNAT cuts exception messages at 200).
g = write("args/empty-name.yaml", 'parameters_demo:\n  ros__parameters:\n    "": 1\n    rate: 15\n')
case("fuzz-params-file-empty-name", f"parameters_demo --ros-args --params-file {g}", 2,
     "empty-name.yaml:3:5: empty parameter name")
g = write("args/bad-node-name.yaml", 'parameters_demo:\n  ros__parameters:\n    rate: 15\n'
          '"robot 1":\n  ros__parameters:\n    rate: 16\n')
case("fuzz-params-file-bad-node-name", f"parameters_demo --ros-args --params-file {g}", 2,
     "bad-node-name.yaml:4:1: node name \"robot 1\": invalid character ' '")
case("fuzz-params-file-long-path",
     f"parameters_demo --ros-args --params-file {{tmp}}/{'d' * 190}/params.yaml", 2,
     "params.yaml: no such file")

# Found by the fuzzer's png reader (session 11): PNG map images whose chunks
# the PNG specification forbids were read as if the chunk were not there
# (libpng refuses all but a palette in a grey image, which it ignores with a
# warning). Each is refused at the chunk's byte offset.
def png(name, chunks):
    """A 2 x 2 grey PNG map (the given chunks between IHDR and IEND, "IDAT"
    for the image data) and a world YAML naming it."""
    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))
    body = b"".join(chunk(b"IDAT", PIXELS) if k == b"IDAT" else chunk(k, b) for k, b in chunks)
    header = chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 0, 0, 0, 0))
    write(f"world/{name}.png", b"\x89PNG\r\n\x1a\n" + header + body + chunk(b"IEND", b""),
          binary=True)
    return write(f"world/{name}.yaml", f"image: {name}.png\nresolution: 0.5\norigin: [0, 0, 0]\n")


PIXELS = zlib.compress(b"\0\0\xfe\0\xfe\0")  # two rows, filter 0

IDAT = (b"IDAT", b"")
g = png("png-critical-chunk", [(b"ABCD", b"xyz"), IDAT])
case("fuzz-png-unknown-critical-chunk", f"sancta-render {g} --svg {{tmp}}/w.svg", 1,
     "png-critical-chunk.png: byte 33: unknown critical chunk ABCD")
g = png("png-chunk-type", [(b"\0\1AB", b""), IDAT])
case("fuzz-png-chunk-type-not-letters", f"sancta-render {g} --svg {{tmp}}/w.svg", 1,
     "png-chunk-type.png: byte 33: chunk type 00 01 41 42 is not four ASCII letters")
g = png("png-second-header", [(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 0, 0, 0, 0)), IDAT])
case("fuzz-png-second-header", f"sancta-render {g} --svg {{tmp}}/w.svg", 1,
     "png-second-header.png: byte 33: second IHDR chunk")
g = png("png-grey-palette", [(b"PLTE", bytes(6)), IDAT])
case("fuzz-png-palette-in-grey-image", f"sancta-render {g} --svg {{tmp}}/w.svg", 1,
     "png-grey-palette.png: byte 33: PLTE chunk in a grey image (colour type 0)")
g = png("png-split-data", [IDAT, (b"tEXt", b"a\0b"), IDAT])
case("fuzz-png-image-data-not-consecutive", f"sancta-render {g} --svg {{tmp}}/w.svg", 1,
     f"png-split-data.png: byte {33 + 12 + len(PIXELS) + 15}: IDAT chunks are not consecutive")

with open(HERE / "cases.txt", "w") as out:
    out.write("# The broken-input corpus (issue 19): one case a line,\n"
              "#   id | command line | expected exit (a number, or !0) | substrings ;; ...\n"
              "# {data} = tests/data/broken, {repo} = the repository, {tmp} = the test's\n"
              "# folder (large inputs made by test_broken_inputs.py). Every case must end\n"
              "# within its time limit, non-zero, with every substring in its output and\n"
              "# no traceback. Regenerate with make_corpus.py.\n")
    for cid, argv, code, expect in CASES:
        out.write(f"{cid} | {argv} | {code} | {' ;; '.join(expect)}\n")
print(len(CASES), "cases")
