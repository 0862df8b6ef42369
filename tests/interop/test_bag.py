"""rclada bag (issue 15): bags written by `rclada bag record` are read by the
foreign MCAP readers (Python `mcap` + `mcap-ros2-support`, which decode from
the schemas in the file, and `rosbags`, which reads the rosbag2 directory and
metadata.yaml); a bag written by `rosbags` (foreign writer) is read by
`rclada bag info` and played by `rclada bag play` to a Python peer; truncated
and corrupted files are refused with the byte offset."""
import math
import subprocess
import time
from dataclasses import dataclass

import pytest
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import int32
from cyclonedds.util import duration

import pubsub_support as ps
from ros_types import (Clock_, Header_, LaserScan_, MapMetaData_, OccupancyGrid_, Point_,
                       Pose_, Quaternion_, String_, Time_, Twist_, Vector3_, dds)

from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from rosbags.rosbag2 import Reader as BagReader, Writer as BagWriter
from rosbags.rosbag2.enums import StoragePlugin
from rosbags.typesys import Stores, get_typestore

TYPESTORE = get_typestore(Stores.ROS2_HUMBLE)


@final
@dataclass
class Unknown_(IdlStruct, typename=dds("not_on_any_path", "Thing")):
    value: int32 = 0


def rclada(*args, timeout=60):
    return subprocess.run([str(ps.BIN / "rclada"), *map(str, args)], capture_output=True,
                          text=True, timeout=timeout)


def scan(i):
    return LaserScan_(header=Header_(stamp=Time_(sec=100 + i, nanosec=i), frame_id="laser"),
                      angle_min=-1.5, angle_max=1.5, angle_increment=0.01, range_min=0.1,
                      range_max=30.0, ranges=[float(i) + k * 0.25 for k in range(360)])


def acknowledged(writers, timeout=10.0):
    """True when the recorder's readers acknowledged every sample of the
    reliable `writers` within `timeout` seconds each (its readers have
    them)."""
    return all(w.wait_for_acks(duration(seconds=timeout)) for w in writers)


@pytest.fixture(scope="module")
def recorded(tmp_path_factory):
    """A bag recorded by `rclada bag record -a` from Python publishers of
    several types, one of them transient-local and published before the
    recorder started, one of a type no interface path defines."""
    out = tmp_path_factory.mktemp("rec") / "bag"
    dp = ps.participant()
    grid = ps.writer(dp, "rt/map", OccupancyGrid_, transient_local=True, depth=1)
    grid.write(OccupancyGrid_(
        header=Header_(frame_id="map"),
        info=MapMetaData_(resolution=0.5, width=4, height=2,
                          origin=Pose_(position=Point_(x=-1.0), orientation=Quaternion_(w=1.0))),
        data=[0, 100, -1, 0, 0, 0, 100, 100]))
    chatter = ps.writer(dp, "rt/chatter", String_)
    scans = ps.writer(dp, "rt/scan", LaserScan_)
    cmd = ps.writer(dp, "rt/robot1/cmd_vel", Twist_, reliable=False)
    unknown = ps.writer(dp, "rt/thing", Unknown_)
    rec = ps.start("rclada", "bag", "record", "-a", "-o", out, "--duration", 6,
                   "--discovery-period", 0.2)
    for w in (grid, chatter, scans, cmd, unknown):
        assert ps.wait_matched(w, 10), "the recorder did not subscribe"
    # The recorder's side of the matches: it made its readers for topics it
    # found through these writers (so it knew them first); its map reader has
    # acknowledged the map, written before it started.
    assert acknowledged([grid]), "the recorder did not acknowledge the transient-local map"
    for i in range(20):
        chatter.write(String_(data=f"hello {i}"))
        scans.write(scan(i))
        cmd.write(Twist_(linear=Vector3_(x=0.1 * i), angular=Vector3_(z=-0.5)))
        unknown.write(Unknown_(value=i))
        time.sleep(0.02)
    assert acknowledged([chatter, scans, unknown]), \
        "the recorder did not acknowledge every message within 10 s (its --duration is 6 s)"
    log = ps.finish(rec, 30)
    assert rec.returncode == 0, log
    return out, log


def test_metadata_and_rosbags_decode(recorded):
    out, log = recorded
    assert (out / "metadata.yaml").exists()
    with BagReader(out) as bag:
        topics = {c.topic: c for c in bag.connections}
        for t in ("/chatter", "/scan", "/robot1/cmd_vel", "/map", "/thing"):
            assert t in topics, (t, list(topics), log)
        assert topics["/scan"].msgtype == "sensor_msgs/msg/LaserScan"
        assert topics["/chatter"].msgcount == 20 and topics["/scan"].msgcount == 20, log
        assert topics["/map"].msgcount == 1, "the transient-local map was not recorded"
        qos = topics["/robot1/cmd_vel"].ext.offered_qos_profiles
        assert qos and qos[0].reliability.name.lower().startswith("best"), qos
        got = {"/chatter": [], "/scan": [], "/robot1/cmd_vel": [], "/map": []}
        for conn, stamp, raw in bag.messages():
            if conn.topic in got:
                got[conn.topic].append(TYPESTORE.deserialize_cdr(raw, conn.msgtype))
    assert [m.data for m in got["/chatter"]] == [f"hello {i}" for i in range(20)]
    assert [round(m.linear.x, 6) for m in got["/robot1/cmd_vel"]] == \
        [round(0.1 * i, 6) for i in range(20)]
    s = got["/scan"][7]
    assert s.header.stamp.sec == 107 and s.header.frame_id == "laser"
    assert len(s.ranges) == 360 and math.isclose(s.ranges[4], 7.0 + 4 * 0.25)
    m = got["/map"][0]
    assert m.info.width == 4 and list(m.data) == [0, 100, -1, 0, 0, 0, 100, 100]


def test_mcap_readers_decode_from_schemas(recorded):
    out, _ = recorded
    files = sorted(out.glob("*.mcap"))
    assert files
    counts = {}
    with open(files[0], "rb") as f:
        reader = make_reader(f, validate_crcs=True, decoder_factories=[DecoderFactory()])
        summary = reader.get_summary()
        assert reader.get_header().profile == "ros2"
        assert summary.chunk_indexes, "no chunk index: readers cannot seek"
        schemas = {s.name: s for s in summary.schemas.values()}
        assert schemas["sensor_msgs/msg/LaserScan"].encoding == "ros2msg"
        text = schemas["sensor_msgs/msg/LaserScan"].data.decode()
        assert "\n" + "=" * 80 + "\nMSG: std_msgs/msg/Header\n" in text, text
        assert "MSG: builtin_interfaces/msg/Time" in text, text
        for ch in summary.channels.values():
            assert ch.message_encoding == "cdr"
            assert "offered_qos_profiles" in ch.metadata
        for schema, channel, message, ros in reader.iter_decoded_messages(
                topics=["/chatter", "/scan", "/robot1/cmd_vel", "/map"]):
            counts[channel.topic] = counts.get(channel.topic, 0) + 1
            if channel.topic == "/scan" and ros.header.stamp.sec == 103:
                assert ros.ranges[0] == 3.0 and len(ros.ranges) == 360
            if channel.topic == "/robot1/cmd_vel":
                assert ros.angular.z == -0.5
            if channel.topic == "/map":
                assert ros.info.resolution == 0.5 and ros.info.origin.position.x == -1.0
            assert message.log_time > 1.6e18
    assert counts == {"/chatter": 20, "/scan": 20, "/robot1/cmd_vel": 20, "/map": 1}, counts


def test_info_lists_topics(recorded):
    out, _ = recorded
    r = rclada("bag", "info", out)
    assert r.returncode == 0, r.stderr
    assert "Storage id:        mcap" in r.stdout
    line = [l for l in r.stdout.splitlines() if "Topic: /scan " in l]
    assert line and "sensor_msgs/msg/LaserScan" in line[0] and "Count: 20 " in line[0], r.stdout
    thing = [l for l in r.stdout.splitlines() if "Topic: /thing " in l]
    assert thing and "not_on_any_path/msg/Thing" in thing[0] and "Count: 20 " in thing[0]


@pytest.fixture(scope="module")
def foreign_bag(tmp_path_factory):
    """A rosbag2 MCAP bag written by rosbags: 10 strings and 5 scans, 50 ms apart."""
    out = tmp_path_factory.mktemp("foreign") / "bag"
    String = TYPESTORE.types["std_msgs/msg/String"]
    Scan = TYPESTORE.types["sensor_msgs/msg/LaserScan"]
    Header = TYPESTORE.types["std_msgs/msg/Header"]
    Time = TYPESTORE.types["builtin_interfaces/msg/Time"]
    import numpy as np
    start = 1_700_000_000_000_000_000
    with BagWriter(out, version=8, storage_plugin=StoragePlugin.MCAP) as w:
        c1 = w.add_connection("/foreign_chatter", String.__msgtype__, typestore=TYPESTORE)
        c2 = w.add_connection("/foreign_scan", Scan.__msgtype__, typestore=TYPESTORE)
        for i in range(10):
            w.write(c1, start + i * 50_000_000,
                    TYPESTORE.serialize_cdr(String(data=f"foreign {i}"), String.__msgtype__))
            if i % 2 == 0:
                msg = Scan(header=Header(stamp=Time(sec=i, nanosec=0), frame_id="l"),
                           angle_min=0.0, angle_max=1.0, angle_increment=0.1,
                           time_increment=0.0, scan_time=0.0, range_min=0.0, range_max=9.0,
                           ranges=np.array([i, i + 1], dtype=np.float32),
                           intensities=np.array([], dtype=np.float32))
                w.write(c2, start + i * 50_000_000 + 1,
                        TYPESTORE.serialize_cdr(msg, Scan.__msgtype__))
    return out


def test_info_reads_foreign_bag(foreign_bag):
    r = rclada("bag", "info", foreign_bag)
    assert r.returncode == 0, r.stderr
    assert "Messages:          15" in r.stdout, r.stdout
    assert "Topic: /foreign_chatter" in r.stdout and "Count: 10 " in r.stdout, r.stdout


def test_play_foreign_bag_to_python_peer(foreign_bag):
    dp = ps.participant()
    strings = ps.reader(dp, "rt/foreign_chatter", String_)
    scans = ps.reader(dp, "rt/foreign_scan", LaserScan_)
    clock = ps.reader(dp, "rt/clock", Clock_, reliable=False, depth=100)
    began = time.monotonic()
    play = ps.start("rclada", "bag", "play", foreign_bag, "--clock", "20", "--delay", "1.0")
    got = ps.take_until(strings, 10, timeout=20)
    got_scans = ps.take_until(scans, 5, timeout=5)
    ticks = ps.take(clock)
    out = ps.finish(play, 30)
    elapsed = time.monotonic() - began
    assert play.returncode == 0, out
    assert [m.data for m in got] == [f"foreign {i}" for i in range(10)], out
    assert [list(m.ranges) for m in got_scans] == [[i, i + 1] for i in range(0, 10, 2)]
    assert elapsed >= 1.0 + 0.45, "played faster than recorded"
    assert ticks, "no /clock with --clock"
    assert all(1_700_000_000 <= t.clock.sec <= 1_700_000_001 for t in ticks), ticks[:3]


@pytest.mark.parametrize("late", [2**63 - 1, 2**64 - 1])
def test_play_stops_on_sigterm_during_a_far_time_jump(tmp_path, late):
    """A bag whose log times jump centuries ahead (found by scripts/fuzz_inputs.py:
    a mutated log time) must not make play deaf to signals while it waits, nor
    overflow its wait (2**64 - 1 ns is beyond Ada's Duration)."""
    out = tmp_path / "jump"
    String = TYPESTORE.types["std_msgs/msg/String"]
    start = 1_700_000_000_000_000_000
    with BagWriter(out, version=8, storage_plugin=StoragePlugin.MCAP) as w:
        c = w.add_connection("/jump_chatter", String.__msgtype__, typestore=TYPESTORE)
        w.write(c, start, TYPESTORE.serialize_cdr(String(data="first"), String.__msgtype__))
        w.write(c, late, TYPESTORE.serialize_cdr(String(data="late"), String.__msgtype__))
    dp = ps.participant()
    strings = ps.reader(dp, "rt/jump_chatter", String_)
    play = ps.start("rclada", "bag", "play", out, "--delay", "1.0")
    got = ps.take_until(strings, 1, timeout=20)
    assert [m.data for m in got] == ["first"], got
    time.sleep(0.5)
    play.terminate()
    began = time.monotonic()
    text = ps.finish(play, 5)
    assert time.monotonic() - began < 3.0, text
    assert "Played 1 messages" in text, text


def test_truncated_and_corrupt_files(recorded, tmp_path):
    out, _ = recorded
    whole = sorted(out.glob("*.mcap"))[0].read_bytes()
    cut = tmp_path / "cut.mcap"
    cut.write_bytes(whole[: len(whole) * 2 // 3])
    r = rclada("bag", "info", cut)
    assert r.returncode == 1 and "truncated" in r.stderr and ": byte " in r.stderr, r.stderr
    r = rclada("bag", "info", cut, "--recover")
    assert r.returncode == 0 and "Messages:" in r.stdout, r.stderr
    bad = tmp_path / "bad.mcap"
    with open(sorted(out.glob("*.mcap"))[0], "rb") as f:
        chunk = make_reader(f).get_summary().chunk_indexes[0]
    data = bytearray(whole)
    middle = chunk.chunk_start_offset + chunk.chunk_length // 2
    data[middle] ^= 0xFF
    bad.write_bytes(bytes(data))
    r = rclada("bag", "play", bad, "--delay", "0", "-r", "1000")
    assert r.returncode == 1 and "corrupt" in r.stderr and ": byte " in r.stderr, r.stderr
    text = tmp_path / "text.mcap"
    text.write_text("hello, not a bag\n")
    r = rclada("bag", "info", text)
    assert r.returncode == 1 and "byte 0: not an MCAP file" in r.stderr, r.stderr


def test_split_by_size(tmp_path):
    out = tmp_path / "split"
    dp = ps.participant()
    scans = ps.writer(dp, "rt/split_scan", LaserScan_)
    rec = ps.start("rclada", "bag", "record", "/split_scan", "-o", out, "-b", "20000",
                   "--duration", 4, "--discovery-period", 0.2, "--compression", "lz4")
    assert ps.wait_matched(scans, 10), "the recorder did not subscribe"
    # The recorder's side of the match: it made its reader for a topic it
    # found through this writer (it knew the writer first).
    for i in range(40):
        scans.write(scan(i))
        time.sleep(0.01)
    assert acknowledged([scans]), \
        "the recorder did not acknowledge every scan within 10 s (its --duration is 4 s)"
    log = ps.finish(rec, 30)
    files = sorted(out.glob("*.mcap"))
    assert len(files) >= 3, (files, log)
    with BagReader(out) as bag:
        stamps = [TYPESTORE.deserialize_cdr(raw, c.msgtype).header.stamp.sec
                  for c, _, raw in bag.messages()]
    assert stamps == [100 + i for i in range(40)], stamps


def test_bad_command_lines(tmp_path):
    r = rclada("bag", "record", "-o", tmp_path / "x")
    assert r.returncode == 2 and "needs topics, or -a" in r.stderr
    r = rclada("bag", "record", "-a", "-o", tmp_path, "--duration", "0.1")
    assert r.returncode == 1 and "exists already" in r.stderr, r.stderr
    r = rclada("bag", "play", tmp_path / "missing")
    assert r.returncode == 1 and "no such bag" in r.stderr, r.stderr
    r = rclada("bag", "record", "-a", "--compression", "rar")
    assert r.returncode == 2 and "unknown compression" in r.stderr, r.stderr
