"""rclada bag info / play on bags that rosbag2 compresses with zstd
(`ros2 bag record --compression-mode file|message --compression-format
zstd`), for both storages: compression_mode file (each storage file
compressed whole: bag_0.db3.zstd, bag_0.mcap.zstd) and compression_mode
message (each message's data one zstd frame). Bags written by the `rosbags`
package (and by the zstd command line) list and play as the same bag
uncompressed does, byte for byte to a Python peer; the temporary
decompressed file is gone afterwards; corrupt or truncated frames, another
compression format, and metadata that says compressed when the data is not
are refused naming the file and byte (or row). Every participant on
loopback."""
import random
import re
import shutil
import sqlite3
import string
import subprocess
import time

import pytest
import yaml

import pubsub_support as ps
from ros_types import String_
from test_db3_input import (START, STRING, TYPESTORE, digest, on_the_wire, play, play_to_peer,
                            rclada, recorded_data, scan, text)

from rosbags.rosbag2 import Writer as BagWriter
from rosbags.rosbag2.enums import CompressionFormat, CompressionMode, StoragePlugin
from rosbags.typesys import Stores, get_typestore  # noqa: F401 (the typestore's module)

ZSTD_MAGIC = b"\x28\xb5\x2f\xfd"
SCAN = TYPESTORE.types["sensor_msgs/msg/LaserScan"]
STORAGES = {"sqlite3": StoragePlugin.SQLITE3, "mcap": StoragePlugin.MCAP}
MODES = {"file": CompressionMode.FILE, "message": CompressionMode.MESSAGE}


def write(out, storage, mode=None, strings=10):
    """The test bag of test_db3_input (10 strings on /db3_chatter, 5 scans on
    /db3_scan), with rosbags' compression `mode` (None: uncompressed)."""
    w = BagWriter(out, version=8, storage_plugin=STORAGES[storage])
    if mode:
        w.set_compression(MODES[mode], CompressionFormat.ZSTD)
    with w:
        c1 = w.add_connection("/db3_chatter", STRING.__msgtype__, typestore=TYPESTORE)
        c2 = w.add_connection("/db3_scan", SCAN.__msgtype__, typestore=TYPESTORE)
        for i in range(strings):
            stamp = START + i * 50_000_000
            w.write(c1, stamp, text(i))
            if i % 2 == 0:
                w.write(c2, stamp + 1, scan(i))
    return out


def listed(bag):
    return [bag / name for name in yaml.safe_load((bag / "metadata.yaml").read_text())[
        "rosbag2_bagfile_information"]["relative_file_paths"]]


def comparable(info):
    """`bag info` less what compression changes: files, size, compression."""
    return [line for line in info.splitlines()
            if not line.startswith(("Files:", "Bag size:", "Compression:"))]


def compression_line(info):
    return re.search(r"^Compression: +(.*)$", info, re.M).group(1)


def metadata_set(bag, **fields):
    meta = yaml.safe_load((bag / "metadata.yaml").read_text())
    meta["rosbag2_bagfile_information"].update(fields)
    (bag / "metadata.yaml").write_text(yaml.safe_dump(meta))


@pytest.fixture
def tmpdir_env(tmp_path, monkeypatch):
    """TMPDIR of the rclada runs: empty afterwards (the decompressed file is
    deleted)."""
    folder = tmp_path / "tmpdir"
    folder.mkdir()
    monkeypatch.setenv("TMPDIR", str(folder))
    yield folder
    assert list(folder.iterdir()) == [], "temporary files left behind"


@pytest.mark.parametrize("storage", STORAGES)
@pytest.mark.parametrize("mode", MODES)
def test_info_and_play_as_the_uncompressed_bag(tmp_path, tmpdir_env, storage, mode):
    plain = write(tmp_path / "plain", storage)
    packed = write(tmp_path / "packed", storage, mode)
    (path,) = listed(packed)
    head = path.read_bytes()[:4]
    if mode == "file":
        assert path.name.endswith(f".{'db3' if storage == 'sqlite3' else 'mcap'}.zstd")
        assert head == ZSTD_MAGIC
    else:
        assert head != ZSTD_MAGIC
    before = digest(path)
    r0, r1 = rclada("bag", "info", plain), rclada("bag", "info", packed)
    assert r0.returncode == 0 and r1.returncode == 0, r1.stderr
    assert comparable(r1.stdout) == comparable(r0.stdout), (r0.stdout, r1.stdout)
    assert compression_line(r1.stdout).startswith(f"zstd ({mode})"), r1.stdout
    assert path.name in r1.stdout
    # The same bag's messages, as rosbags reads the uncompressed one.
    play_to_peer(packed, recorded_data(plain), "-r", "5")
    assert digest(path) == before, "the bag was written"


def test_message_mode_data_is_compressed(tmp_path):
    # The test above would pass on raw data too: rosbags did compress each
    # message, and one frame decompresses to the CDR.
    import zstandard
    bag = write(tmp_path / "m", "sqlite3", "message")
    (path,) = listed(bag)
    with sqlite3.connect(path) as db:
        rows = [bytes(d) for (d,) in db.execute("SELECT data FROM messages ORDER BY id")]
    assert all(d.startswith(ZSTD_MAGIC) for d in rows)
    assert zstandard.ZstdDecompressor().decompress(rows[0]) == text(0)


def test_zstd_command_line_files_and_a_single_file(tmp_path, tmpdir_env):
    # The zstd tool's frames (content size, checksum), two frames one after
    # the other, and a .mcap.zstd given alone (no metadata.yaml).
    for storage, ext in (("sqlite3", "db3"), ("mcap", "mcap")):
        plain = write(tmp_path / f"plain_{ext}", storage)
        (path,) = listed(plain)
        reference = comparable(rclada("bag", "info", plain).stdout)
        bag = tmp_path / f"cli_{ext}"
        bag.mkdir()
        packed = bag / f"cli_{ext}_0.{ext}.zstd"
        subprocess.run(["zstd", "-q", "-19", str(path), "-o", str(packed)], check=True)
        r = rclada("bag", "info", bag)  # no metadata.yaml: the directory's files
        assert r.returncode == 0, r.stderr
        assert comparable(r.stdout) == reference
        half = len(path.read_bytes()) // 2
        (tmp_path / "a").write_bytes(path.read_bytes()[:half])
        (tmp_path / "b").write_bytes(path.read_bytes()[half:])
        two = tmp_path / f"two.{ext}.zstd"
        with open(two, "wb") as f:
            for part in ("a", "b"):
                f.write(subprocess.run(["zstd", "-q", "-c", str(tmp_path / part)], check=True,
                                       capture_output=True).stdout)
        r = rclada("bag", "info", two)
        assert r.returncode == 0, r.stderr
        assert comparable(r.stdout) == reference
        r = play(two)
        assert r.returncode == 0 and "Played 15 messages" in r.stdout, r.stdout + r.stderr


def cut_and_flipped(tmp_path, storage):
    """A file-mode bag, and copies truncated to half and with a byte of the
    frame's middle flipped."""
    bag = write(tmp_path / f"f_{storage}", storage, "file")
    (path,) = listed(bag)
    data = path.read_bytes()
    cut = tmp_path / f"cut_{storage}"
    shutil.copytree(bag, cut)
    (cut / path.name).write_bytes(data[:len(data) // 2])
    return bag, path, cut, len(data) // 2


@pytest.mark.parametrize("storage", STORAGES)
def test_truncated_file_is_refused_with_its_byte(tmp_path, tmpdir_env, storage):
    bag, path, cut, size = cut_and_flipped(tmp_path, storage)
    for r in (rclada("bag", "info", cut), play(cut)):
        assert r.returncode == 1, r.stdout
        assert f"{path.name}: byte {size}: truncated zstd frame (from byte 0)" in r.stderr, \
            r.stderr


def test_corrupt_frame_is_refused_with_its_byte(tmp_path, tmpdir_env):
    # A frame the zstd tool wrote with its checksum: any flipped byte of the
    # compressed blocks is caught (libzstd's message, where it stopped).
    plain = write(tmp_path / "p", "sqlite3")
    (path,) = listed(plain)
    bag = tmp_path / "corrupt"
    bag.mkdir()
    packed = bag / "corrupt_0.db3.zstd"
    subprocess.run(["zstd", "-q", "--check", str(path), "-o", str(packed)], check=True)
    data = bytearray(packed.read_bytes())
    data[len(data) // 2] ^= 0xFF
    packed.write_bytes(bytes(data))
    for r in (rclada("bag", "info", bag), play(bag)):
        assert r.returncode == 1, r.stdout
        m = re.search(re.escape(packed.name) + r": byte (\d+): zstd: \w", r.stderr)
        assert m, r.stderr
        # Where libzstd stopped: from the flipped byte to the checksum at
        # the end, to the KiB (the slice it was given).
        assert len(data) // 2 - 1024 < int(m.group(1)) < len(data), r.stderr


def test_empty_frame_and_plain_text_inside(tmp_path, tmpdir_env):
    empty, text_file = tmp_path / "empty.mcap.zstd", tmp_path / "notes.db3.zstd"
    for path, content in ((empty, b""), (text_file, b"not a bag\n" * 100)):
        path.write_bytes(subprocess.run(["zstd", "-q", "-c"], input=content, check=True,
                                        capture_output=True).stdout)
    r = rclada("bag", "info", empty)
    assert r.returncode == 1 and "empty.mcap.zstd: decompresses to 0 bytes: no MCAP or SQLite" \
        " file inside" in r.stderr, r.stderr
    r = rclada("bag", "info", text_file)
    assert r.returncode == 1 and "notes.db3.zstd (decompressed): byte 0: not an MCAP file" \
        in r.stderr, r.stderr


@pytest.mark.parametrize("storage", STORAGES)
def test_metadata_says_file_but_the_file_is_plain(tmp_path, storage):
    bag = write(tmp_path / "b", storage)
    metadata_set(bag, compression_mode="FILE", compression_format="zstd")
    (path,) = listed(bag)
    for r in (rclada("bag", "info", bag), play(bag)):
        assert r.returncode == 1, r.stdout
        assert (f"{path.name}: byte 0: no zstd frame (expected 28 B5 2F FD), but metadata.yaml says"
                " compression_mode file") in r.stderr, r.stderr


def test_metadata_says_message_but_the_data_is_plain(tmp_path):
    db = write(tmp_path / "db", "sqlite3")
    metadata_set(db, compression_mode="MESSAGE", compression_format="zstd")
    (path,) = listed(db)
    for r in (rclada("bag", "info", db), play(db)):
        assert r.returncode == 1, r.stdout
        assert (f"{path.name}: messages row 1: data is no zstd frame, but metadata.yaml says"
                " compression_mode message") in r.stderr, r.stderr
    mc = write(tmp_path / "mc", "mcap")
    metadata_set(mc, compression_mode="message", compression_format="zstd")
    (path,) = listed(mc)
    r = play(mc)  # info reads no message data
    assert r.returncode == 1, r.stdout
    assert re.search(re.escape(path.name) + r": byte \d+: the chunk's uncompressed byte \d+: data"
                     r" is no zstd frame, but metadata.yaml says compression_mode message",
                     r.stderr), r.stderr


def test_corrupt_message_frame_is_refused_with_its_row(tmp_path):
    bag = write(tmp_path / "m", "sqlite3", "message")
    (path,) = listed(bag)
    with sqlite3.connect(path) as db:
        (data,) = db.execute("SELECT data FROM messages WHERE id = 3").fetchone()
        db.execute("UPDATE messages SET data = ? WHERE id = 3", (bytes(data)[:-3],))
    r = play(bag)
    assert r.returncode == 1, r.stdout
    assert (f"{path.name}: messages row 3: data: byte {len(data) - 3}: truncated zstd frame"
            " (from byte 0)") in r.stderr, r.stderr


@pytest.mark.parametrize("fields, error", [
    ({"compression_format": "lz4"}, "compression_format 'lz4' (compression_mode file): only"
     " zstd is read"),
    ({"compression_mode": "chunk"}, "compression_mode 'chunk': expected file, message or none"),
])
def test_metadata_compression_it_cannot_read(tmp_path, fields, error):
    bag = write(tmp_path / "b", "sqlite3", "file")
    metadata_set(bag, **fields)
    for r in (rclada("bag", "info", bag), play(bag)):
        assert r.returncode == 1, r.stdout
        assert re.search(r"metadata\.yaml:\d+:\d+: "
                         + re.escape(error), r.stderr), r.stderr


@pytest.mark.parametrize("mode", MODES)
def test_record_compressed_read_by_rosbags_and_mcap(tmp_path, mode):
    # rclada bag record --compression-mode file|message --compression-format
    # zstd, split in files of 20 kB: rosbags reads it (decompressing as
    # rosbag2 does), the mcap package reads each decompressed file / frame.
    import zstandard
    from cyclonedds.util import duration
    from mcap.reader import make_reader
    from rosbags.rosbag2 import Reader as BagReader
    out = tmp_path / "rec"
    dp = ps.participant()
    chatter = ps.writer(dp, "rt/zstd_chatter", String_)
    rec = ps.start("rclada", "bag", "record", "/zstd_chatter", "-o", out, "-b", "20000",
                   "--duration", 4, "--discovery-period", 0.2, "--compression-mode", mode,
                   "--compression-format", "zstd")
    assert ps.wait_matched(chatter, 10), "the recorder did not subscribe"
    # Letters at random: compressed, 80 of them still fill 2 files or more.
    rng = random.Random(5)
    sent = [f"zstd {i} " + "".join(rng.choice(string.ascii_letters)
                                   for _ in range(i * 53 % 1200)) for i in range(80)]
    for s in sent:
        chatter.write(String_(data=s))
        time.sleep(0.01)
    assert chatter.wait_for_acks(duration(seconds=10)), "not acknowledged"
    log = ps.finish(rec, 30)
    assert rec.returncode == 0, log
    meta = yaml.safe_load((out / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    assert (meta["compression_mode"], meta["compression_format"]) == (mode.upper(), "zstd")
    files = listed(out)
    assert len(files) >= 2, files
    assert all(f.name.endswith(".mcap.zstd") == (mode == "file") for f in files), files
    assert sorted(out.iterdir()) == sorted(files + [out / "metadata.yaml"])
    with BagReader(out) as bag:
        got = [TYPESTORE.deserialize_cdr(raw, c.msgtype).data for c, _, raw in bag.messages()]
    assert got == sent, log
    via_mcap = []
    for f in files:
        data = f.read_bytes()
        if mode == "file":
            data = zstandard.ZstdDecompressor().decompressobj().decompress(data)
        import io
        for _, _, m in make_reader(io.BytesIO(data)).iter_messages():
            raw = m.data
            if mode == "message":
                assert raw.startswith(ZSTD_MAGIC)
                raw = zstandard.ZstdDecompressor().decompress(raw)
            via_mcap.append(TYPESTORE.deserialize_cdr(raw, "std_msgs/msg/String").data)
    assert via_mcap == sent
    r = rclada("bag", "info", out)
    assert r.returncode == 0 and f"zstd ({mode})" in r.stdout and "Count: 80" in r.stdout, \
        r.stdout + r.stderr


def test_record_compression_command_line(tmp_path):
    r = rclada("bag", "record", "-a", "-o", tmp_path / "a", "--compression-mode", "chunk")
    assert r.returncode == 2 and "--compression-mode: 'chunk': expected file, message or" \
        in r.stderr, r.stderr
    r = rclada("bag", "record", "-a", "-o", tmp_path / "b", "--compression-mode", "file",
               "--compression-format", "lz4")
    assert r.returncode == 2 and "--compression-format: 'lz4': only zstd" in r.stderr, r.stderr
