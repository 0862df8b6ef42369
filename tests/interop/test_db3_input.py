"""rclada bag info / play on rosbag2's sqlite3 storage (Humble's default:
bag_0.db3 and metadata.yaml). Bags written by the `rosbags` package
(schema version 4, metadata versions 8 and 9) and by hand in the older
layouts (schema 3 as Humble writes, schema 1 without offered_qos_profiles)
are listed as rosbags reads them and played to a Python peer byte for byte;
a split bag plays its files in order; malformed databases are refused with
the file and the table, column or row, and the user's file is never
written. Every participant on loopback."""
import hashlib
import re
import shutil
import sqlite3
import subprocess
import time

import pytest
import yaml
from cyclonedds._clayer import ddspy_take
from cyclonedds.core import InstanceState, SampleState, ViewState

import pubsub_support as ps
import rosbag2_db3  # scripts/rosbag2_db3.py (conftest puts scripts/ on the path)
from ros_types import LaserScan_, String_

from rosbags.rosbag2 import Reader as BagReader, Writer as BagWriter
from rosbags.rosbag2.enums import StoragePlugin
from rosbags.typesys import Stores, get_typestore

TYPESTORE = get_typestore(Stores.ROS2_HUMBLE)
STRING = TYPESTORE.types["std_msgs/msg/String"]
SCAN = TYPESTORE.types["sensor_msgs/msg/LaserScan"]
START = 1_700_000_000_000_000_000


def rclada(*args, timeout=60):
    return subprocess.run([str(ps.BIN / "rclada"), *map(str, args)], capture_output=True,
                          text=True, timeout=timeout)


def play(path, *extra):
    return rclada("bag", "play", path, "--delay", "0", "-r", "1000", *extra)


def text(i):
    return TYPESTORE.serialize_cdr(STRING(data=f"db3 {i}"), STRING.__msgtype__)


def scan(i):
    import numpy as np
    h = TYPESTORE.types["std_msgs/msg/Header"]
    t = TYPESTORE.types["builtin_interfaces/msg/Time"]
    msg = SCAN(header=h(stamp=t(sec=i, nanosec=7), frame_id="laser"), angle_min=0.0,
               angle_max=1.0, angle_increment=0.1, time_increment=0.0, scan_time=0.0,
               range_min=0.0, range_max=9.0, ranges=np.array([i, i + 0.5], dtype=np.float32),
               intensities=np.array([], dtype=np.float32))
    return TYPESTORE.serialize_cdr(msg, SCAN.__msgtype__)


def write_bag(out, version=8, strings=10, offset=0):
    """A rosbags sqlite3 bag: `strings` std_msgs/String on /db3_chatter and a
    LaserScan on /db3_scan every other one, 50 ms apart (the scans 1 ns
    after), from START + offset."""
    with BagWriter(out, version=version, storage_plugin=StoragePlugin.SQLITE3) as w:
        c1 = w.add_connection("/db3_chatter", STRING.__msgtype__, typestore=TYPESTORE)
        c2 = w.add_connection("/db3_scan", SCAN.__msgtype__, typestore=TYPESTORE)
        for i in range(strings):
            stamp = START + offset + i * 50_000_000
            w.write(c1, stamp, text(i))
            if i % 2 == 0:
                w.write(c2, stamp + 1, scan(i))
    return out


def rosbags_view(path):
    """What rosbags reads from the messages: {topic: (type, count)}, total,
    first and last time."""
    topics, stamps = {}, []
    with BagReader(path) as r:
        for conn, stamp, _ in r.messages():
            kind, count = topics.get(conn.topic, (conn.msgtype, 0))
            topics[conn.topic] = (kind, count + 1)
            stamps.append(stamp)
        assert r.message_count == len(stamps)
        assert r.duration - 1 == max(stamps) - min(stamps)
    return topics, len(stamps), min(stamps), max(stamps)


def info_view(out):
    topics = {m.group(1): (m.group(2), int(m.group(3))) for m in re.finditer(
        r"Topic: (\S+)\s*\| Type: (\S+)\s*\| Count: (\d+) \| Serialization Format: cdr", out)}
    total = int(re.search(r"Messages:\s+(\d+)", out).group(1))
    duration = re.search(r"Duration:\s+(\d+)\.(\d{9})s", out)
    start = re.search(r"Start:.*\((\d+)\.(\d{9})\)", out)
    return (topics, total, int(duration.group(1)) * 10**9 + int(duration.group(2)),
            int(start.group(1)) * 10**9 + int(start.group(2)))


def digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.mark.parametrize("version", [8, 9])
def test_info_equals_rosbags_reading(tmp_path, version):
    # Was: 'db.db3: byte 0: not an MCAP file but a SQLite 3 database'.
    bag = write_bag(tmp_path / "bag", version=version)
    topics, total, first, last = rosbags_view(bag)
    for path in (bag, bag / "bag.db3"):
        r = rclada("bag", "info", path)
        assert r.returncode == 0, r.stderr
        assert "Storage id:        sqlite3" in r.stdout, r.stdout
        assert info_view(r.stdout) == (topics, total, last - first, first), r.stdout
    assert topics == {"/db3_chatter": ("std_msgs/msg/String", 10),
                      "/db3_scan": ("sensor_msgs/msg/LaserScan", 5)}


def take_raw(rd):
    """The serialized samples (encapsulation header included) available now."""
    mask = SampleState.Any | ViewState.Any | InstanceState.Any
    return [bytes(data) for data, info in ddspy_take(rd._ref, mask, 100) if info.valid_data]


def take_raw_until(rd, count, timeout):
    got, deadline = [], time.monotonic() + timeout
    while len(got) < count and time.monotonic() < deadline:
        got.extend(take_raw(rd))
        time.sleep(0.02)
    return got


def on_the_wire(data):
    """The bytes a DDS reader gets for `data` published: RTPS ends a serialized
    payload at a multiple of 4 bytes, Cyclone DDS pads with zeros."""
    return bytes(data) + b"\0" * (-len(data) % 4)


def recorded_data(path):
    """{topic: [data on the wire...]} in the order rosbags reads them."""
    result = {}
    with BagReader(path) as r:
        for conn, _, data in r.messages():
            result.setdefault(conn.topic, []).append(on_the_wire(data))
    return result


def play_to_peer(bag, expected, *extra):
    """`rclada bag play BAG --delay 1.0 EXTRA...` of a bag as write_bag's (10
    strings, 5 scans) to a Python peer, which must get `expected` (as
    recorded_data gives it) byte for byte; the seconds play took."""
    dp = ps.participant()
    strings = ps.reader(dp, "rt/db3_chatter", String_, depth=100)
    scans = ps.reader(dp, "rt/db3_scan", LaserScan_, depth=100)
    began = time.monotonic()
    p = ps.start("rclada", "bag", "play", bag, "--delay", "1.0", *extra)
    got = take_raw_until(strings, 10, timeout=20)
    got_scans = take_raw_until(scans, 5, timeout=5)
    out = ps.finish(p, 30)
    assert p.returncode == 0, out
    assert "Played 15 messages" in out, out
    assert got == expected["/db3_chatter"], (got[:2], expected["/db3_chatter"][:2])
    assert got_scans == expected["/db3_scan"]
    return time.monotonic() - began


def test_play_to_python_peer_byte_for_byte(tmp_path):
    bag = write_bag(tmp_path / "bag", version=9)
    before = digest(bag / "bag.db3")
    seconds = play_to_peer(bag, recorded_data(bag))
    assert seconds >= 1.0 + 0.45, "played faster than recorded"
    assert digest(bag / "bag.db3") == before, "the bag was written"


def test_split_bag_plays_its_files_in_order(tmp_path):
    # Two files listed in metadata.yaml: the second's messages are earlier,
    # yet played after the first's, as rosbag2 reads split files in order.
    one = write_bag(tmp_path / "one", strings=3, offset=10**9)
    two = write_bag(tmp_path / "two", strings=2)
    bag = tmp_path / "split"
    bag.mkdir()
    shutil.copy(one / "one.db3", bag / "split_0.db3")
    shutil.copy(two / "two.db3", bag / "split_1.db3")
    meta = yaml.safe_load((one / "metadata.yaml").read_text())
    meta["rosbag2_bagfile_information"]["relative_file_paths"] = ["split_0.db3", "split_1.db3"]
    (bag / "metadata.yaml").write_text(yaml.safe_dump(meta))
    r = rclada("bag", "info", bag)
    assert r.returncode == 0, r.stderr
    topics, total, duration, start = info_view(r.stdout)
    assert topics == {"/db3_chatter": ("std_msgs/msg/String", 5),
                      "/db3_scan": ("sensor_msgs/msg/LaserScan", 3)}, r.stdout
    assert (total, start, duration) == (8, START, 10**9 + 100_000_001), r.stdout
    assert "split_0.db3" in r.stdout and "split_1.db3" in r.stdout
    dp = ps.participant()
    strings = ps.reader(dp, "rt/db3_chatter", String_, depth=100)
    p = ps.start("rclada", "bag", "play", bag, "--delay", "1.0", "-r", "10")
    got = take_raw_until(strings, 5, timeout=20)
    out = ps.finish(p, 30)
    assert p.returncode == 0, out
    assert got == [on_the_wire(text(i)) for i in (0, 1, 2, 0, 1)], out


def humble_bag(path, schema_version=3):
    """A .db3 file as Humble's rosbag2 writes it (schema version 3: tables
    schema, metadata, topics with offered_qos_profiles, messages), or the
    older layouts (2: no schema table; 1: no offered_qos_profiles either)."""
    latched = ("- history: 3\n  depth: 0\n  reliability: 1\n  durability: 1\n"
               "  deadline:\n    sec: 2147483647\n    nsec: 4294967295\n")
    return rosbag2_db3.write(
        path, schema_version,
        [(1, "/humble_chatter", "std_msgs/msg/String", latched),
         (2, "/humble_scan", "sensor_msgs/msg/LaserScan", latched)],
        [(1 + i % 2, START + i * 1000, text(i) if i % 2 == 0 else scan(i)) for i in range(6)])


@pytest.mark.parametrize("schema_version", [3, 2, 1])
def test_older_schema_versions(tmp_path, schema_version):
    path = humble_bag(tmp_path / "humble.db3", schema_version)
    r = rclada("bag", "info", path)
    assert r.returncode == 0, r.stderr
    assert info_view(r.stdout) == ({"/humble_chatter": ("std_msgs/msg/String", 3),
                                    "/humble_scan": ("sensor_msgs/msg/LaserScan", 3)},
                                   6, 5000, START), r.stdout
    r = play(path)
    assert r.returncode == 0, r.stderr
    assert "Played 6 messages" in r.stdout, r.stdout


def broken(tmp_path, *statements):
    path = humble_bag(tmp_path / "bad.db3")
    db = sqlite3.connect(path)
    for s in statements:
        db.execute(s)
    db.commit()
    db.close()
    return path


@pytest.mark.parametrize("statements,error", [
    (["DROP TABLE messages"], "no table 'messages' (a SQLite database, but no rosbag2"),
    (["DROP TABLE topics"], "no table 'topics'"),
    (["ALTER TABLE topics DROP COLUMN serialization_format"],
     "table topics has no column 'serialization_format'"),
    (["UPDATE messages SET topic_id = 9 WHERE id = 5"],
     "messages row 5: topic_id 9 names no topic"),
    (["UPDATE messages SET data = 'text' WHERE id = 2"], "messages row 2: data is text, expected"
     " blob"),
    (["UPDATE messages SET timestamp = 'soon' WHERE id = 3"], "messages row 3: timestamp is text,"
     " expected integer"),
    (["UPDATE messages SET topic_id = 1.5 WHERE id = 4"], "messages row 4: topic_id is real"),
    (["UPDATE messages SET data = x'' WHERE id = 6"], "messages row 6: data is empty (0 bytes"),
    (["UPDATE messages SET timestamp = -1 WHERE id = 1"], "messages row 1: timestamp -1 is"
     " negative"),
    (["UPDATE topics SET name = x'2f41' WHERE id = 2"], "topics row 2: name is blob, expected"
     " text"),
    (["UPDATE topics SET serialization_format = 'json' WHERE id = 1"],
     "topics row 1: topic '/humble_chatter': serialization_format 'json' (only cdr is read)"),
    (["UPDATE topics SET type = 'std_msgs/msg/Int32' WHERE id = 2",
      "UPDATE topics SET name = '/humble_chatter' WHERE id = 2"],
     "topics row 2: topic '/humble_chatter' is 'std_msgs/msg/Int32' here, "
     "'std_msgs/msg/String' in topics row 1")],
    ids=["no messages", "no topics", "no column", "topic_id", "data text", "timestamp text",
         "topic_id real", "empty data", "negative time", "name blob", "json",
         "two types"])
def test_malformed_database_is_refused_with_its_place(tmp_path, statements, error):
    path = broken(tmp_path, *statements)
    before = digest(path)
    for r in (rclada("bag", "info", path), play(path)):
        assert r.returncode == 1, r.stdout + r.stderr
        assert f"rclada: {path}: {error}" in r.stderr, r.stderr
        assert "raised" not in r.stderr and "Traceback" not in r.stderr, r.stderr
    assert digest(path) == before


def test_play_checks_the_topics_it_plays_with_their_row(tmp_path):
    path = broken(tmp_path, "UPDATE topics SET type = 'not a type' WHERE id = 2",
                  "UPDATE topics SET offered_qos_profiles = '- [1, 2' WHERE id = 1")
    r = play(path, "--topics", "/humble_scan")
    assert r.returncode == 1, r.stdout
    assert (f"{path}: topics row 2: topic '/humble_scan': type 'not a type': expected "
            "package/msg/Type") in r.stderr, r.stderr
    r = play(path, "--topics", "/humble_chatter")
    assert r.returncode == 1, r.stdout
    assert f"{path}: topics row 1: offered_qos_profiles: " in r.stderr, r.stderr


def test_truncated_and_corrupt_databases_give_sqlite_messages(tmp_path):
    good = write_bag(tmp_path / "bag", strings=400)
    data = (good / "bag.db3").read_bytes()
    cut = tmp_path / "cut.db3"
    cut.write_bytes(data[:len(data) // 2])
    garbage = tmp_path / "garbage.db3"
    garbage.write_bytes(data[:16] + bytes(range(256)) * 8)
    for path, error in ((cut, "database disk image is malformed"),
                        (garbage, "file is not a database")):
        for r in (rclada("bag", "info", path), play(path)):
            assert r.returncode == 1, r.stdout + r.stderr
            assert f"rclada: {path}: {error}" in r.stderr, r.stderr


def test_directory_without_metadata_reads_its_db3_files(tmp_path):
    bag = write_bag(tmp_path / "bag", strings=4)
    (bag / "metadata.yaml").unlink()
    r = rclada("bag", "info", bag)
    assert r.returncode == 0, r.stderr
    assert info_view(r.stdout)[:2] == ({"/db3_chatter": ("std_msgs/msg/String", 4),
                                        "/db3_scan": ("sensor_msgs/msg/LaserScan", 2)}, 6)
