"""End-to-end tests of the `rclada` command against running Ada nodes and a
Python cyclonedds peer that follows the ROS 2 conventions (loopback only)."""
import subprocess
import time
from dataclasses import dataclass

from cyclonedds.core import Policy, Qos
from cyclonedds.idl import IdlStruct
from cyclonedds.idl import types
from cyclonedds.idl.annotations import final
from cyclonedds.pub import DataWriter
from cyclonedds.topic import Topic

import pubsub_support as ps
from ros_types import String_
import service_support as ss


@final
@dataclass
class Gid_(IdlStruct, typename="rmw_dds_common::msg::dds_::Gid_"):
    data: types.array[types.uint8, 24]


@final
@dataclass
class NodeEntitiesInfo_(IdlStruct, typename="rmw_dds_common::msg::dds_::NodeEntitiesInfo_"):
    node_namespace: types.bounded_str[256]
    node_name: types.bounded_str[256]
    reader_gid_seq: types.sequence[Gid_]
    writer_gid_seq: types.sequence[Gid_]


@final
@dataclass
class ParticipantEntitiesInfo_(
        IdlStruct, typename="rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_"):
    gid: Gid_
    node_entities_info_seq: types.sequence[NodeEntitiesInfo_]


def rclada(*args, timeout=30):
    exe = ps.BIN / "rclada"
    assert exe.exists(), "bin/rclada not built"
    p = subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True,
                       timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def rclada_until(check, *args, attempts=5):
    """Runs rclada until check(rc, out, err) holds (discovery is eventually
    consistent, and slow on a loaded machine); returns the last result."""
    for _ in range(attempts):
        result = rclada(*args)
        if check(*result):
            return result
        time.sleep(0.5)
    return result


def gid(guid_bytes):
    return Gid_(data=list(guid_bytes) + [0] * 8)


def announce(dp, namespace, name, readers=(), writers=()):
    """Publishes ros_discovery_info for one node of participant dp."""
    qos = Qos(Policy.History.KeepLast(1), Policy.Reliability.Reliable(max_blocking_time=10**9),
              Policy.Durability.TransientLocal,
              Policy.DataRepresentation(use_cdrv0_representation=True))
    wr = DataWriter(dp, Topic(dp, "ros_discovery_info", ParticipantEntitiesInfo_), qos=qos)
    wr.write(ParticipantEntitiesInfo_(
        gid=gid(dp.guid.bytes),
        node_entities_info_seq=[NodeEntitiesInfo_(
            node_namespace=namespace, node_name=name,
            reader_gid_seq=[gid(r.guid.bytes) for r in readers],
            writer_gid_seq=[gid(w.guid.bytes) for w in writers])]))
    return wr


def test_python_endpoints_in_topic_list():
    dp = ps.participant()
    wr = ps.writer(dp, "rt/py_topic", String_)
    rd = ps.reader(dp, "rt/py_sub/inner", String_)
    rc, out, err = rclada_until(lambda rc, out, err: "/py_sub/inner" in out.split(),
                                "topic", "list", "-t")
    assert rc == 0, err
    assert "/py_topic [std_msgs/msg/String]" in out.splitlines(), out
    assert "/py_sub/inner [std_msgs/msg/String]" in out.splitlines(), out
    rc, out, _ = rclada("topic", "list")
    assert "/py_topic" in out.splitlines()
    rc, out, err = rclada("topic", "info", "/py_topic", "-v")
    assert rc == 0, err
    assert "Type: std_msgs/msg/String" in out and "Publisher count: 1" in out, out
    assert "Reliability: RELIABLE" in out and "Subscription count: 0" in out, out
    del wr, rd


def test_peer_leaving_disappears_from_list():
    dp = ps.participant()
    wr = ps.writer(dp, "rt/short_lived", String_)
    rc, out, _ = rclada_until(lambda rc, out, err: "/short_lived" in out.split(),
                              "topic", "list")
    assert "/short_lived" in out.splitlines(), out
    del wr
    dp = None  # noqa: F841  (the participant goes: its endpoints are disposed)
    import gc
    gc.collect()
    rc, out, _ = rclada_until(lambda rc, out, err: "/short_lived" not in out.split(),
                              "topic", "list")
    assert "/short_lived" not in out.splitlines(), out


def test_node_list_and_info_from_discovery_info():
    dp = ps.participant()
    wr = ps.writer(dp, "rt/py_node_out", String_)
    rd = ps.reader(dp, "rt/py_node_in", String_)
    ann = announce(dp, "/py", "py_node", readers=[rd], writers=[wr])
    rc, out, err = rclada_until(lambda rc, out, err: "/py/py_node" in out.split(),
                                "node", "list")
    assert rc == 0, err
    assert "/py/py_node" in out.splitlines(), out
    rc, out, err = rclada("node", "info", "/py/py_node")
    assert rc == 0, err
    lines = out.splitlines()
    assert lines[0] == "/py/py_node"
    assert "    /py_node_out: std_msgs/msg/String" in lines[lines.index("  Publishers:"):], out
    assert "    /py_node_in: std_msgs/msg/String" in \
        lines[lines.index("  Subscribers:"):lines.index("  Publishers:")], out
    rc, out, err = rclada("node", "info", "/nobody")
    assert rc == 1 and "Unable to find node '/nobody'" in err
    del ann


def test_service_list_and_call():
    ada = ps.start("server")
    try:
        rc, out, err = rclada_until(lambda rc, out, err: "/add_two_ints_server" in out.split(),
                                    "node", "list")
        assert rc == 0 and "/add_two_ints_server" in out.splitlines(), (out, err)
        rc, out, err = rclada("node", "info", "/add_two_ints_server")
        assert rc == 0, err
        lines = out.splitlines()
        assert "    /add_two_ints: example_interfaces/srv/AddTwoInts" in \
            lines[lines.index("  Service Servers:"):lines.index("  Service Clients:")], out
        rc, out, err = rclada_until(lambda rc, out, err: "/add_two_ints" in out.split(),
                                    "service", "list", "-t")
        assert rc == 0, err
        assert "/add_two_ints [example_interfaces/srv/AddTwoInts]" in out.splitlines(), out
        rc, out, err = rclada("service", "call", "/add_two_ints",
                              "example_interfaces/srv/AddTwoInts", "{a: 5, b: 37}")
        assert rc == 0, err
        assert "response:\nsum: 42" in out, out
        rc, out, err = rclada("service", "call", "/add_two_ints",
                              "example_interfaces/srv/AddTwoInts", "{a: 5, c: 1}")
        assert rc == 1 and "has no field 'c'" in err and "<argument>:1:8:" in err, err
    finally:
        ss.stop(ada)


def test_service_call_missing_times_out():
    start = time.monotonic()
    rc, out, err = rclada("service", "call", "/absent", "example_interfaces/srv/AddTwoInts",
                          "{}", "--timeout", "1")
    assert rc == 1 and "not available" in err, err
    assert time.monotonic() - start < 10


def test_topic_echo():
    ada = ps.start("raw_chatter", "pub", 200)
    try:
        rc, out, err = rclada("topic", "echo", "/chatter", "std_msgs/msg/String",
                              "--count", 2, timeout=30)
    finally:
        ss.stop(ada)
    assert rc == 0, err
    blocks = [b for b in out.split("---\n") if b.strip()]
    assert len(blocks) == 2, out
    assert all(b.startswith("data: 'Hello World: ") for b in blocks), out


def test_topic_echo_type_from_graph():
    ada = ps.start("raw_chatter", "pub", 200)
    try:
        rc, out, err = rclada("topic", "echo", "/chatter", "--once", timeout=30)
    finally:
        ss.stop(ada)
    assert rc == 0, err
    assert out.startswith("data: 'Hello World: ") and out.endswith("---\n"), out


def test_topic_echo_once_prints_one_of_a_burst():
    """--once (and --count N) print exactly N messages also when more arrive
    in the same take as the last one (seen once in CI under load: two)."""
    import threading
    dp = ps.participant()
    wr = ps.writer(dp, "rt/burst", String_, reliable=True, depth=100)
    stop = threading.Event()

    def flood():
        i = 0
        while not stop.is_set():
            wr.write(String_(data="m%d" % i))
            i += 1
            if i % 50 == 0:
                time.sleep(0.001)

    feeder = threading.Thread(target=flood, daemon=True)
    feeder.start()
    try:
        for limit in ("--once", "--count 3", "--once"):
            rc, out, err = rclada("topic", "echo", "/burst", "std_msgs/msg/String",
                                  *limit.split(), timeout=30)
            assert rc == 0, err
            blocks = [b for b in out.split("---\n") if b.strip()]
            assert len(blocks) == (3 if "count" in limit else 1), (limit, out)
    finally:
        stop.set()
        feeder.join(5)


def test_topic_pub():
    dp = ps.participant()
    rd = ps.reader(dp, "rt/pub_test", String_)
    rc, out, err = rclada("topic", "pub", "/pub_test", "std_msgs/msg/String",
                          "{data: 'hi there'}", "--times", 3, "--rate", 20)
    assert rc == 0, err
    assert "publishing #3: " in out, out
    got = ps.take_until(rd, 3, timeout=5)
    assert [s.data for s in got] == ["hi there"] * 3
    # No message: the default one ('{}'), for a bounded number only; an
    # empty message argument is refused (ros2: not a dictionary).
    rc, out, err = rclada("topic", "pub", "/pub_test", "std_msgs/msg/String", "--once")
    assert rc == 0 and "publishing #1: std_msgs/msg/String(data: '')" in out, (out, err)
    rc, _, err = rclada("topic", "pub", "/pub_test", "std_msgs/msg/String")
    assert rc == 2 and "no YAML message" in err, err
    rc, _, err = rclada("topic", "pub", "/pub_test", "std_msgs/msg/String", "", "--once")
    assert rc == 1 and "<argument>:1:1:" in err and "found nothing" in err, err


def test_topic_hz():
    ada = ps.start("raw_chatter", "pub", 200)
    try:
        rc, out, err = rclada("topic", "hz", "/chatter", "std_msgs/msg/String",
                              "--count", 2, timeout=30)
    finally:
        ss.stop(ada)
    assert rc == 0, err
    rates = [float(l.split(":")[1]) for l in out.splitlines() if l.startswith("average rate:")]
    assert rates, out
    assert 2.0 < rates[-1] < 50.0, out  # raw_chatter publishes at 10 Hz


def test_interface_commands():
    rc, out, _ = rclada("interface", "show", "example_interfaces/srv/AddTwoInts")
    assert rc == 0 and out == "int64 a\nint64 b\n---\nint64 sum\n", out
    rc, out, _ = rclada("interface", "list", "-s")
    assert "    example_interfaces/srv/AddTwoInts" in out.splitlines(), out
    rc, out, _ = rclada("interface", "package", "std_msgs")
    assert "std_msgs/msg/String" in out.splitlines(), out
    rc, _, err = rclada("interface", "show", "std_msgs/msg/Strng")
    assert rc == 1 and "did you mean: std_msgs/msg/String" in err, err


def test_errors_and_help():
    rc, out, _ = rclada("--help")
    assert rc == 0 and "topic" in out
    for verb in ("node", "topic", "service", "param", "interface"):
        rc, out, _ = rclada(verb, "--help")
        assert rc == 0 and out.startswith("usage: rclada " + verb), (verb, out)
    rc, _, err = rclada("topic", "frobnicate")
    assert rc == 2 and "unknown topic sub-command 'frobnicate'" in err
    rc, _, err = rclada("topic", "list", "--bogus")
    assert rc == 2 and "unknown option --bogus" in err
    rc, _, err = rclada("topic", "pub", "/x", "std_msgs/msg/String", "{data: [1}", "--once")
    assert rc == 1 and "<argument>:1:10" in err, err
    rc, _, err = rclada("topic", "pub", "/x", "std_msgs/msg/Nope", "{}", "--once")
    assert rc == 1 and "unknown message type" in err, err
    # Invalid names are rejected at once (echo and hz used to wait forever).
    for verb in ("echo", "hz", "info"):
        rc, _, err = rclada("topic", verb, "bad name!", timeout=10)
        assert rc == 1 and "invalid name 'bad name!'" in err, (verb, err)
    rc, _, err = rclada("service", "call", "/a//b", "example_interfaces/srv/AddTwoInts",
                        "{a: 1, b: 2}", timeout=10)
    assert rc == 1 and "invalid name '/a//b'" in err, err
