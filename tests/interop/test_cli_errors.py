"""Bad input to the user-facing programs (rclada, sancta check/run, sancta-render,
cdr_tool, the examples): each gets a non-zero exit status and a clear one-line
message naming what and where, never a GNAT traceback ("raised ..."), never a hang.
Participants that some of these programs create stay on loopback (CYCLONEDDS_URI)."""
import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
BIN = REPO / "bin"
TEAM = str(REPO / "share" / "config" / "team.xml")
ARENA = str(REPO / "share" / "worlds" / "arena.yaml")
TIMEOUT = 10.0


def env():
    e = dict(os.environ)
    e["CYCLONEDDS_URI"] = "file://" + str(REPO / "share" / "cyclonedds-localhost.xml")
    e["ROS_LOCALHOST_ONLY"] = "1"
    e.setdefault("ROS_DOMAIN_ID", str(os.getpid() % 200 + 1))
    return e


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("bad")
    (d / "adir").mkdir()
    (d / "deep.xml").write_text("<a>" * 100000 + "</a>" * 100000)
    (d / "trunc.xml").write_text("<config>\n")
    (d / "garbage.bin").write_bytes(b"\x00\xff\xfe garbage\x01")
    (d / "deep.yaml").write_text("x: " + "[" * 5000 + "]" * 5000 + "\n")
    (d / "res0.yaml").write_text("image: arena.pgm\nresolution: 0\norigin: [0, 0, 0]\n")
    # Larger than the 8 MiB stack: must be read on the heap.
    (d / "big.yaml").write_text("x: " + "a" * (9 * 1024 * 1024) + "\n")
    # Many keys then a duplicate: found without a quadratic search (was minutes).
    keys = ["    p%d: %d" % (i, i) for i in range(200000)]
    (d / "many.yaml").write_text("\n".join(["/**:", "  ros__parameters:"] + keys
                                            + ["    p7: 1"]) + "\n")
    return d


# (argv with {d} for the fixture directory, expected exit status or None for
#  "any non-zero", substrings that stderr must contain)
CASES = [
    # sancta check / run: configuration files and options
    (["sancta"], 2, ["usage: sancta"]),
    (["sancta", "check", "{d}/deep.xml"], 1,
     ["{d}/deep.xml:1:", "nested deeper than 100"]),
    (["sancta", "check", "{d}/adir"], 1, ["{d}/adir:1:1: error: cannot read: not a regular file"]),
    (["sancta", "check", "{d}/trunc.xml"], 1, ["{d}/trunc.xml:2:1: error: malformed XML"]),
    (["sancta", "check", "{d}/garbage.bin"], 1, ["{d}/garbage.bin:1:", "malformed XML"]),
    (["sancta", "check", "/nonexistent.xml"], 1, ["/nonexistent.xml:1:1: error: cannot open"]),
    (["sancta", "check", TEAM, "--output", "{d}/garbage.bin"], 1,
     ["--output {d}/garbage.bin: cannot write the wiring picture"]),
    (["sancta", "run", "{d}/deep.xml", "--all"], 1, ["nested deeper than 100"]),
    (["sancta", "run", TEAM, "--all", "--for", "-1"], 2, ["--for expects seconds", "'-1'"]),
    (["sancta", "run", TEAM, "--all", "--for", "1", "--log", "{d}/adir"], 2,
     ["--log: cannot create the file", "{d}/adir"]),
    # rclada: option values, names, YAML messages
    (["rclada", "topic", "pub", "/chatter", "std_msgs/msg/String", "[" * 50000], 1,
     ["<argument>:1:100: collections nested deeper than 100"]),
    (["rclada", "topic", "pub", "/chatter", "std_msgs/msg/String", "", "--once"], 1,
     ["<argument>:1:1: std_msgs/msg/String is a message: expected a mapping of its fields"
      " ({data}), found nothing ('{}' is the default message)"]),
    (["rclada", "topic", "pub", "/chatter", "std_msgs/msg/String", "# x\n", "--once"], 1,
     ["<argument>:", "found nothing"]),
    (["rclada", "topic", "pub", "/chatter", "std_msgs/msg/String", "hello", "--once"], 1,
     ["<argument>:1:1: std_msgs/msg/String is a message: expected a mapping", "found 'hello'"]),
    (["rclada", "service", "call", "/s", "example_interfaces/srv/AddTwoInts", " "], 1,
     ["<argument>:1:", "AddTwoInts_Request is a message", "found nothing"]),
    (["rclada", "action", "send_goal", "/a", "example_interfaces/action/Fibonacci", ""], 1,
     ["<argument>:1:1:", "Fibonacci_Goal is a message", "found nothing"]),
    (["rclada", "topic", "pub", "/chatter", "std_msgs/msg/Int32", "{data: 99999999999}"], 1,
     ["<argument>:1:8:", "out of range for int32"]),
    (["rclada", "topic", "pub", "/chatter", "std_msgs/msg/String", "{data: x}", "--rate", "0"],
     2, ["--rate: 0 is out of range"]),
    (["rclada", "topic", "pub", "/chatter", "std_msgs/msg/String", "{data: x}",
      "--times", "99999999999999999999"], 2, ["--times:", "out of range"]),
    (["rclada", "topic", "echo", "/chatter", "std_msgs/msg/String", "--count", "-1"], 2,
     ["--count: -1 is out of range"]),
    (["rclada", "topic", "hz", "/chatter", "std_msgs/msg/String", "--window", "0"], 2,
     ["--window: 0 is out of range"]),
    (["rclada", "node", "list", "--spin-time", "1e308"], 2, ["--spin-time: '1e308'"]),
    (["rclada", "topic", "echo", "/bad name", "std_msgs/msg/String"], 1,
     ["\"/bad name\"", "invalid character ' ' at position 5"]),
    (["rclada", "param", "get", "/bad name", "p"], 1, ["invalid character ' '"]),
    # sancta-render: worlds and output files
    (["sancta-render", ARENA, "--svg", "/nonexistent/dir/x.svg"], 1,
     ["cannot write", "/nonexistent/dir/x.svg"]),
    (["sancta-render", "{d}/adir", "--svg", "{d}/x.svg"], 1, ["{d}/adir: not a regular file"]),
    (["sancta-render", "{d}/res0.yaml", "--svg", "{d}/x.svg"], 1,
     ["{d}/res0.yaml:2:", "resolution must be positive"]),
    # cdr_tool
    (["cdr_tool", "encode", "nosuch"], 1, ["unknown sample 'nosuch'"]),
    (["cdr_tool", "encode", "string_hi", "xx"], 1, ["usage: cdr_tool"]),
    (["cdr_tool", "decode", "string_hi", "0z"], 1, ["HEX: 'z' is not a hex digit (digit 2)"]),
    (["cdr_tool", "decode", "string_hi", "0"], 1, ["odd number of hex digits: 1"]),
    (["cdr_tool", "random", "abc"], 1, ["SEED 'abc'"]),
    (["cdr_tool", "decode", "string_hi", "00010000ffffffff41"], 2, ["at byte offset 4"]),
    # examples
    (["parameters_demo", "--ros-args", "--params-file", "{d}/adir"], 2,
     ["{d}/adir: not a regular file"]),
    (["parameters_demo", "--ros-args", "--params-file", "{d}/deep.yaml"], 2,
     ["{d}/deep.yaml:1:103: collections nested deeper than 100"]),
    (["parameters_demo", "--ros-args", "--params-file", "{d}/big.yaml"], 2,
     ["{d}/big.yaml:1:1:"]),
    (["parameters_demo", "--ros-args", "--params-file", "{d}/many.yaml"], 2,
     ["{d}/many.yaml:200003:5: duplicate key \"p7\""]),
    (["parameters_demo", "--ros-args", "-p", "rate:=1000"], 2,
     ["the override for '/**' (1000) is rejected: rate must be within 1 .. 100"]),
    (["parameters_demo", "--ros-args", "-p", "rate"], 2, ["argument 3 'rate': expected [node:]name:=value"]),
    (["server", "bad name"], 2, ["bad service name", "position 5"]),
    (["client", "1", "2", "0.5", "bad name"], 2, ["bad service name"]),
    (["client", "1", "2", "-1"], 2, ["usage: client"]),
]


@pytest.mark.parametrize("argv,status,expected", CASES,
                         ids=[" ".join(c[0])[:60] for c in CASES])
def test_bad_input_is_a_clean_error(files, argv, status, expected):
    d = str(files)
    args = [a.replace("{d}", d) for a in argv]
    args[0] = str(BIN / args[0])
    result = subprocess.run(args, capture_output=True, text=True, errors="replace",
                            timeout=TIMEOUT, env=env(), cwd=d)
    err = result.stderr
    if status is None:
        assert result.returncode != 0, err
    else:
        assert result.returncode == status, (result.returncode, err)
    for e in expected:
        assert e.replace("{d}", d) in err, err
    assert "raised " not in err and "raised " not in result.stdout, err
    assert "Traceback" not in err and "internal error" not in err, err
