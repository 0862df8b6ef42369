"""A short, deterministic run of scripts/fuzz_inputs.py (fixed seed, a dozen
mutated inputs per reader, no DDS): every reader refuses its mutated inputs
with a located error or accepts them, and nothing crashes, hangs or prints
an exception; the typed reader also compares the generated codecs with the
dynamic decoder on the same payloads. The long runs and their findings:
/work/notes/fuzz-s8.md."""
import os
import pathlib
import signal
import subprocess
import sys
import time

REPO = pathlib.Path(__file__).resolve().parents[2]
READERS = ("config,mission,team,tsp,world,walls,trajectories,pgm,png,definition,params,policy,"
           "mcap,mcap-recover,db3,zstd-file,zstd-message,cdr,typed")


def test_fuzz_smoke():
    p = subprocess.run([sys.executable, str(REPO / "scripts" / "fuzz_inputs.py"), "--seed", "19",
                        "--cases", "12", "--readers", READERS],
                       capture_output=True, text=True, timeout=240)
    assert p.returncode == 0, p.stdout + p.stderr[-3000:]
    # Every reader ran its cases.
    rows = [line.split() for line in p.stdout.splitlines()[1:]]
    assert sorted(r[0] for r in rows) == sorted(READERS.split(",")), p.stdout
    assert all(int(r[1]) == 12 for r in rows), p.stdout


def test_fuzz_smoke_command_lines():
    """The args reader (DDS on loopback: each case starts parameters_demo):
    mutated --ros-args lists and --params-file files are refused naming the
    argument or file:line, or the node starts; nothing hangs. The message
    reader: mutated YAML messages given to `rclada topic pub` are refused at
    <argument>:line:column or published."""
    p = subprocess.run([sys.executable, str(REPO / "scripts" / "fuzz_inputs.py"), "--seed", "19",
                        "--cases", "8", "--readers", "args,message"],
                       capture_output=True, text=True, timeout=240)
    assert p.returncode == 0, p.stdout + p.stderr[-3000:]
    rows = sorted(line.split()[:2] for line in p.stdout.splitlines()[1:])
    assert rows == [["args", "8"], ["message", "8"]], p.stdout


def test_fuzz_smoke_services():
    """The services reader (DDS on loopback): mutated requests at the
    examples' servers and parameters_demo's parameter services, mutated
    replies at the clients: refusals logged with type and byte offset,
    accepted requests answered, every client takes its true answer."""
    p = subprocess.run([sys.executable, str(REPO / "scripts" / "fuzz_inputs.py"), "--seed", "19",
                        "--cases", "10", "--readers", "services"],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout + p.stderr[-3000:]
    row = p.stdout.splitlines()[1].split()
    assert row[0] == "services" and int(row[1]) >= 50, p.stdout


def test_fuzz_smoke_actions():
    """The actions reader (DDS on loopback): a raw action server answers
    the action clients (rclada action send_goal, typed_fibonacci client,
    with cancel) with mutated replies, feedback and status messages: each
    client reports what it drops, with type and byte offset, and takes the
    first answer that decodes."""
    p = subprocess.run([sys.executable, str(REPO / "scripts" / "fuzz_inputs.py"), "--seed", "19",
                        "--cases", "8", "--readers", "actions"],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout + p.stderr[-3000:]
    row = p.stdout.splitlines()[1].split()
    assert row[0] == "actions" and int(row[1]) == 6, p.stdout


def node_parameter(args, name):
    """The value parameters_demo logs for parameter `name` when started with
    args (it logs every parameter once it is ready, then is stopped)."""
    e = dict(os.environ)
    e["CYCLONEDDS_URI"] = "file://" + str(REPO / "share" / "cyclonedds-localhost.xml")
    e["ROS_LOCALHOST_ONLY"] = "1"
    e.setdefault("ROS_DOMAIN_ID", str(os.getpid() % 200 + 21))
    p = subprocess.Popen([str(REPO / "bin" / "parameters_demo")] + args, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, env=e, start_new_session=True)
    seen = []
    try:
        began = time.monotonic()
        for line in p.stdout:
            seen.append(line)
            if f"parameter {name} = " in line:
                return line.split(" = ", 1)[1].strip()
            if time.monotonic() - began > 15:
                break
    finally:
        os.killpg(p.pid, signal.SIGKILL)
        p.wait()
    raise AssertionError("no value logged:\n" + "".join(seen[-20:]))


def test_node_specific_parameter_override():
    """rcl's "-p node:name:=value" applies to that node only (the args
    reader's finding: the whole "node:name" was taken as a parameter name,
    so the override never applied)."""
    assert node_parameter(["--ros-args", "-p", "parameters_demo:rate:=20"], "rate") == "20"
    assert node_parameter(["--ros-args", "-p", "other_node:rate:=30"], "rate") == "10"
    assert node_parameter(["--ros-args", "-r", "__node:=renamed", "-p", "parameters_demo:rate:=40",
                           "-p", "renamed:gain:=2.5"], "gain") == "2.5"


def test_params_file_node_name_wildcards(tmp_path):
    """A parameter file's node names may use rcl's wildcards ("/**" for any
    namespace, "*" for any one name): such overrides never applied (only
    "/**" alone, a full name or a base name matched), silently."""
    def rate_with(node_names):
        f = tmp_path / "p.yaml"
        f.write_text(f"{node_names}:\n  ros__parameters:\n    rate: 42\n")
        return node_parameter(["--ros-args", "--params-file", str(f)], "rate")

    for pattern in ("/**/parameters_demo", "/*", "/**/*"):
        assert rate_with(pattern) == "42", pattern
    for pattern in ("/other/*", "/**/other", "/ns/parameters_demo"):
        assert rate_with(pattern) == "10", pattern
    (tmp_path / "p.yaml").write_text("/robots/r1/*:\n  ros__parameters:\n    rate: 43\n")
    assert node_parameter(["--ros-args", "-r", "__ns:=/robots/r1", "--params-file",
                           str(tmp_path / "p.yaml")], "rate") == "43"


def test_node_names_without_slash_are_absolute(tmp_path):
    """As in rclcpp/rclpy, a node name without a leading '/' (in a parameter
    file or in '-p node:name:=value') is made absolute: 'parameters_demo' is
    '/parameters_demo', not a node of that name in another namespace (it
    matched any namespace; ROS 2 behaves so: ros2/rcl issue 1306)."""
    f = tmp_path / "p.yaml"
    f.write_text("parameters_demo:\n  ros__parameters:\n    rate: 42\n")
    in_root = ["--ros-args", "--params-file", str(f)]
    in_ns = ["--ros-args", "-r", "__ns:=/robots", "--params-file", str(f)]
    assert node_parameter(in_root, "rate") == "42"
    assert node_parameter(in_ns, "rate") == "10"
    assert node_parameter(["--ros-args", "-r", "__ns:=/robots", "-p",
                           "parameters_demo:rate:=20"], "rate") == "10"
