"""rclada bag info / play on MCAP files that are valid MCAP but hold what
cannot be played (an invalid topic name, a type that is no ROS type, a
channel without schema, messages shorter than a CDR header), or that leave
out what the format only advises (statistics, channel records repeated in
the summary). Refusals name the file, the byte offset of the record (and in
a chunk, the record's uncompressed offset) and the channel or schema; the
offsets are checked against the file's bytes. Files written with the Python
`mcap` package; every participant on loopback."""
import re
import subprocess
import time

import pytest
from cyclonedds.builtin import BuiltinDataReader, BuiltinTopicDcpsPublication
from cyclonedds.qos import Policy
from mcap.writer import CompressionType, Writer

import pubsub_support as ps

CDR_HI = b"\x00\x01\x00\x00\x03\x00\x00\x00hi\x00"
OP_SCHEMA, OP_CHANNEL, OP_MESSAGE, OP_CHUNK = 0x03, 0x04, 0x05, 0x06


def rclada(*args, timeout=60):
    return subprocess.run([str(ps.BIN / "rclada"), *map(str, args)], capture_output=True,
                          text=True, timeout=timeout)


def play(path, *extra):
    return rclada("bag", "play", path, "--delay", "0", "-r", "1000", *extra)


def write(path, topic="/fine", type_name="std_msgs/msg/String", payload=CDR_HI,
          schema=True, compression=CompressionType.NONE, chunked=True, qos=None, spacing=1,
          **options):
    """A ros2-profile MCAP: channel 1 /chatter (valid), channel 2 `topic`
    of `type_name` (schema 2, or none; offered_qos_profiles qos when given),
    three messages on each, `spacing` ns apart."""
    with open(path, "wb") as f:
        w = Writer(f, compression=compression, use_chunking=chunked, **options)
        w.start(profile="ros2", library="test")
        good = w.register_schema("std_msgs/msg/String", "ros2msg", b"string data\n")
        other = w.register_schema(type_name, "ros2msg", b"string data\n") if schema else 0
        c1 = w.register_channel("/chatter", "cdr", good)
        c2 = w.register_channel(topic, "cdr", other,
                                {} if qos is None else {"offered_qos_profiles": qos})
        for i in range(3):
            t = 1_000_000_000 + i * spacing
            w.add_message(c1, log_time=t, data=CDR_HI, publish_time=0)
            w.add_message(c2, log_time=t, data=payload, publish_time=0)
        w.finish()
    return path


def shortened(text, longest=80, tail=57):
    """`text` as RCL.Names.Shortened (TEXT, 80, 57) quotes a bag file's path:
    its middle replaced by "..." when longer than `longest`."""
    return text if len(text) <= longest else text[:longest - tail - 3] + "..." + text[-tail:]


def offset_of(text, path, what):
    """The byte offset the error gives after `path` (whole, or shortened when
    long: pytest's base directory varies in length): `what` follows it."""
    names = {re.escape(str(path)), re.escape(shortened(str(path)))}
    m = re.search("(?:" + "|".join(names) + r"): byte (\d+):? " + what, text)
    assert m, text
    return int(m.group(1))


def record_content_at(data, offset, opcode, ident):
    """The record whose content starts at offset has this opcode and id."""
    return data[offset - 9] == opcode and int.from_bytes(data[offset:offset + 2], "little") == ident


@pytest.mark.parametrize("compression", [CompressionType.NONE, CompressionType.ZSTD])
@pytest.mark.parametrize("topic,reason", [
    ("/bad topic", "invalid character ' ' at position 5"),
    ("/9lives", "must not start with a digit"),
    ("/a//b", "")])
def test_invalid_topic_name_names_channel_and_byte(tmp_path, compression, topic, reason):
    # Was: 'rclada: topic name "/bad topic": invalid character ...' (no file,
    # no record).
    path = write(tmp_path / "bad.mcap", topic=topic, compression=compression)
    r = play(path)
    assert r.returncode == 1, r.stdout + r.stderr
    offset = offset_of(r.stderr, path, rf"channel 2: topic name \"{re.escape(topic)}\": ")
    assert record_content_at(path.read_bytes(), offset, OP_CHANNEL, 2), r.stderr
    assert reason in r.stderr, r.stderr
    assert "Played" not in r.stdout, r.stdout  # refused before playing anything


@pytest.mark.parametrize("type_name,reason", [
    ("std_msgs/msg/Strin g", "invalid type name 'Strin g'"),
    ("String", "expected package/msg/Type"),
    ("Std_msgs/msg/String", "invalid package name 'Std_msgs'"),
    ("std_msgs/mesg/String", "expected msg, srv or action after the package, found 'mesg'"),
    ("std_msgs/msg/String/x", "expected package/msg/Type")])
def test_type_that_is_no_ros_type_names_schema_and_byte(tmp_path, type_name, reason):
    # Was: played on a DDS type made of the text (no reader ever matches).
    path = write(tmp_path / "type.mcap", type_name=type_name)
    r = play(path)
    assert r.returncode == 1, r.stdout + r.stderr
    offset = offset_of(r.stderr, path, "schema 2: topic '/fine': ")
    assert record_content_at(path.read_bytes(), offset, OP_SCHEMA, 2), r.stderr
    assert reason in r.stderr, r.stderr


def test_generated_type_names_are_played(tmp_path):
    path = write(tmp_path / "event.mcap", type_name="example_interfaces/srv/AddTwoInts_Event")
    r = play(path)
    assert r.returncode == 0 and "Played 6 messages" in r.stdout, r.stdout + r.stderr


def test_channel_without_schema_is_refused_with_its_place(tmp_path):
    # Was: its messages were left out silently ("Played 3 messages").
    path = write(tmp_path / "noschema.mcap", schema=False)
    r = play(path)
    assert r.returncode == 1, r.stdout + r.stderr
    offset = offset_of(r.stderr, path, "channel 2: topic '/fine': no message type")
    assert record_content_at(path.read_bytes(), offset, OP_CHANNEL, 2), r.stderr
    # Only the topics played are checked.
    r = play(path, "--topics", "/chatter")
    assert r.returncode == 0 and "Played 3 messages" in r.stdout, r.stdout + r.stderr


@pytest.mark.parametrize("chunked", [True, False])
def test_messages_shorter_than_a_cdr_header_are_reported(tmp_path, chunked):
    # Was: left out silently (rc 0, "Played 3 messages").
    path = write(tmp_path / "short.mcap", payload=b"\x00\x01", chunked=chunked)
    r = play(path)
    assert r.returncode == 1 and "Played 3 messages" in r.stdout, r.stdout + r.stderr
    assert "3 message(s) not played, shorter than a CDR header (4 bytes)" in r.stderr, r.stderr
    data = path.read_bytes()
    if chunked:
        m = re.search(re.escape(str(path)) + r": byte (\d+): the chunk's uncompressed byte (\d+)"
                      r" \(topic /fine\): 2 bytes", r.stderr)
        assert m and data[int(m.group(1))] == OP_CHUNK, r.stderr
    else:
        offset = offset_of(r.stderr, path, r"\(topic /fine\): 2 bytes")
        assert record_content_at(data, offset, OP_MESSAGE, 2), r.stderr


def test_topics_option_naming_no_topic_of_the_bag(tmp_path):
    # Was: nothing played, rc 0.
    path = write(tmp_path / "ok.mcap")
    r = play(path, "--topics", "/chatter", "/chater")
    assert r.returncode == 1 and "--topics: the bag has no topic '/chater'" in r.stderr, r.stderr
    r = play(path, "--topics", "chatter")
    assert r.returncode == 1 and ("--topics: the bag has no topic 'chatter' (its topics are "
                                  "fully qualified: '/chatter')") in r.stderr, r.stderr


@pytest.mark.parametrize("options", [dict(use_statistics=False),
                                     dict(repeat_channels=False, repeat_schemas=False),
                                     dict(repeat_channels=False, repeat_schemas=False,
                                          use_statistics=False)],
                         ids=["no statistics", "channels only in chunks", "neither"])
def test_summary_without_statistics_or_channels(tmp_path, options):
    # MCAP only advises both. Was: "Messages: 0" and no topic (bag info), an
    # internal error (bag play).
    path = write(tmp_path / "lean.mcap", **options)
    r = rclada("bag", "info", path)
    assert r.returncode == 0, r.stderr
    assert "Messages:          6" in r.stdout, r.stdout
    assert re.search(r"Topic: /fine +\| Type: std_msgs/msg/String \| Count: 3 ", r.stdout), r.stdout
    r = play(path)
    assert r.returncode == 0 and "Played 6 messages" in r.stdout, r.stdout + r.stderr


def jazzy_qos(reliability, durability):
    """offered_qos_profiles as rosbag2 writes it from metadata version 9
    (Jazzy): the policies by name."""
    return ("- history: keep_last\n  depth: 1\n  reliability: " + reliability
            + "\n  durability: " + durability + "\n  deadline:\n    sec: 9223372036\n"
            "    nsec: 854775807\n  lifespan:\n    sec: 9223372036\n    nsec: 854775807\n"
            "  liveliness: automatic\n  liveliness_lease_duration:\n    sec: 9223372036\n"
            "    nsec: 854775807\n  avoid_ros_namespace_conventions: false\n")


@pytest.mark.parametrize("reliability,durability,expected", [
    ("best_effort", "volatile", ("BestEffort", Policy.Durability.Volatile)),
    ("reliable", "transient_local", ("Reliable", Policy.Durability.TransientLocal))])
def test_jazzy_qos_names_are_understood(tmp_path, reliability, durability, expected):
    # Was: only Humble's numbers were read, a latched topic of a Jazzy bag
    # was played volatile (late subscribers missed it), best effort reliable.
    topic = f"/jazzy_{reliability}"
    path = write(tmp_path / "jazzy.mcap", topic=topic, qos=jazzy_qos(reliability, durability),
                 spacing=1_000_000_000)
    dp = ps.participant()
    pubs = BuiltinDataReader(dp, BuiltinTopicDcpsPublication)
    p = ps.start("rclada", "bag", "play", path, "--delay", "0.5")
    seen = None
    deadline = time.monotonic() + 15
    while seen is None and time.monotonic() < deadline:
        seen = next((w for w in pubs.take(N=100) if w.topic_name == "rt" + topic), None)
        time.sleep(0.1)
    out = ps.finish(p, 30)
    assert seen is not None, out
    reliable = isinstance(seen.qos[Policy.Reliability], Policy.Reliability.Reliable)
    assert ("Reliable" if reliable else "BestEffort", seen.qos[Policy.Durability]) == expected
    assert "Played 6 messages" in out, out


@pytest.mark.parametrize("qos,reason", [
    (jazzy_qos("reliable", "latched"), "profile 1: durability 'latched' is no durability"),
    (jazzy_qos("sometimes", "volatile"), "profile 1: reliability 'sometimes' is no reliability"),
    ("history: 1\ndepth: 10\n", "expected a sequence of QoS profiles"),
    ("- history: 1\n  depth: ten\n", "profile 1: depth 'ten' is no number of messages"),
    ("- [1, 2\n", "offered_qos_profiles")],
    ids=["durability", "reliability", "no sequence", "depth", "yaml"])
def test_offered_qos_not_understood_is_refused_with_its_place(tmp_path, qos, reason):
    # Was: played with the default QoS, silently.
    path = write(tmp_path / "qos.mcap", qos=qos)
    r = play(path)
    assert r.returncode == 1, r.stdout + r.stderr
    offset = offset_of(r.stderr, path, "channel 2: offered_qos_profiles: ")
    assert record_content_at(path.read_bytes(), offset, OP_CHANNEL, 2), r.stderr
    assert reason in r.stderr, r.stderr


def test_metadata_yaml_not_understood_is_said(tmp_path):
    # Was: the directory's files were read instead, silently.
    bag = tmp_path / "bag"
    bag.mkdir()
    write(bag / "bag_0.mcap")
    (bag / "metadata.yaml").write_text("rosbag2_bagfile_information:\n"
                                       "  relative_file_paths: [bag_0.mcap\n")
    for r in (rclada("bag", "info", bag), play(bag)):
        assert r.returncode == 0, r.stderr
        assert f"rclada: warning: {bag}/metadata.yaml:2:" in r.stderr, r.stderr
        assert "the directory's .mcap or .db3 files are read" in r.stderr, r.stderr
    assert "Messages:          6" in rclada("bag", "info", bag).stdout


def test_one_topic_with_two_types_is_refused(tmp_path):
    # Was: every message played with the first type seen, silently.
    path = write(tmp_path / "two.mcap", topic="/chatter", type_name="std_msgs/msg/Int32")
    for r in (rclada("bag", "info", path), play(path)):
        assert r.returncode == 1, r.stdout
        offset = offset_of(r.stderr, path, "channel 2: topic '/chatter' is "
                           r"'std_msgs/msg/Int32' here, 'std_msgs/msg/String' on channel 1")
        assert record_content_at(path.read_bytes(), offset, OP_CHANNEL, 2), r.stderr
    bag = tmp_path / "split"
    bag.mkdir()
    write(bag / "split_0.mcap")
    write(bag / "split_1.mcap", type_name="std_msgs/msg/Int32")
    r = rclada("bag", "info", bag)
    assert r.returncode == 1, r.stdout
    offset = offset_of(r.stderr, bag / "split_1.mcap", "channel 2: topic '/fine' is "
                       r"'std_msgs/msg/Int32' here, 'std_msgs/msg/String' in split_0\.mcap on "
                       r"channel 2")
    assert record_content_at((bag / "split_1.mcap").read_bytes(), offset, OP_CHANNEL, 2)


def test_bag_command_lines(tmp_path):
    # A topic name no topic can have was a wish recorded silently (rc 0,
    # "Recorded 0 messages"); an argument past the bag was not named.
    out = tmp_path / "rec"
    r = rclada("bag", "record", "/bad topic", "-o", out, "--duration", "0.2")
    assert r.returncode == 2, r.stdout + r.stderr
    assert ("bag record: topic name \"/bad topic\": invalid character ' ' at position 5"
            in r.stderr), r.stderr
    assert not out.exists()
    path = write(tmp_path / "ok.mcap")
    r = rclada("bag", "play", path, "--clock", "x")
    assert r.returncode == 2 and ("bag play takes one bag (directory, .mcap or .db3 file), "
                                  "not also 'x'") in r.stderr, r.stderr
