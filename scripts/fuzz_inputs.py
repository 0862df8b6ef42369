#!/usr/bin/env python3
"""Mutation fuzzer for the product's input readers (developers' guide: bad
input gets a clear error with its location, never a crash, a hang or a
silent wrong answer; malformed wire data never over-reads).

Each reader takes valid seed inputs (bundled configurations, missions,
TSPLIB files, worlds, PGM and PNG map images (every PNG colour type, bit
depth, row filter and DEFLATE block kind), SROS2 policies (`rclada security
create_permission`), interface definitions, parameter files, MCAP bags made
with the `mcap` package, rosbag2 sqlite3 bags (.db3, mutated also through
SQL: tables, columns, rows and values of other kinds), both compressed
with zstd as rosbag2 does (whole files: their frames mutated, or their
content then compressed again; each message: a frame cut or flipped),
CDR payloads from
`cdr_tool random`, --ros-args lists), mutates them
(byte flips, truncations, deletions, insertions of huge numbers / control
characters / deep nesting / long lines, duplicated and swapped lines, wrong
values in length fields) and runs the product's own command on every copy.

A case is flagged when the program
  - ends by a signal,
  - prints an Ada exception name, "raised", "Call stack", "internal error"
    (or, for CDR, an exception other than Decode_Error),
  - runs past the time limit,
  - refuses the input without naming where (file:line[:column] or byte N),
  - exits 0 on a mutation that must be refused (XML cut before its root's
    end tag, an MCAP file cut before its end magic, a PNG map image the PNG
    specification forbids: png_problem, an independent reading).

    nice -n 19 .venv/bin/python scripts/fuzz_inputs.py --seed 1 --cases 2000 \
        [--readers config,tsp,...] [--keep out/fuzz]

Readers that do more than read a file: `typed` (the generated codecs,
compared with the dynamic decoder on the same mutated payloads), `args`
(parameters_demo's --ros-args / --params-file; DDS on loopback: source
scripts/env.sh first), `message` (YAML messages given to `rclada topic
pub`), `run` and `demo` (sancta run / sancta demo on mutated
configurations; processes left behind are findings), `services` (mutated
requests and replies written by a Cyclone DDS peer at the product's service
servers and clients, scripts/fuzz_services.py; DDS on loopback), `actions`
(the same peer playing an action server: mutated goal, result and cancel
responses, feedback and status messages at the action clients).

Flagged inputs are kept in --keep (one folder per finding, with the command
line and the output); the summary table goes to standard output. The run is
deterministic for a seed (same mutations, same order)."""
import argparse
import os
import pathlib
import random
import re
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time
import zlib

import domain_lock  # scripts/domain_lock.py, beside this file
import rosbag2_db3  # scripts/rosbag2_db3.py

REPO = pathlib.Path(__file__).resolve().parents[1]
BIN = pathlib.Path(os.environ.get("SANCTA_FUZZ_BIN", REPO / "bin"))
SHARE = REPO / "share"

TRACE = re.compile(r"raised |Call stack|internal error|CONSTRAINT_ERROR|STORAGE_ERROR|"
                   r"PROGRAM_ERROR|TASKING_ERROR|ASSERT_FAILURE|ADA\.[A-Z_.]+|GNAT\.[A-Z_.]+|"
                   r"Traceback|INTERNAL ")

HUGE_NUMBERS = [b"99999999999999999999999999", b"1e400", b"-1e400", b"nan", b"-nan", b"inf",
                b"-inf", b"4294967296", b"-2147483649", b"9223372036854775808",
                b"18446744073709551616", b"-0", b"0", b"-1", b"0x7fffffff", b"1e-400",
                b"123456789012345678901234567890.5", b"2147483647", b"1_000", b"+5", b".5",
                b"5.", b"1e", b"--1"]
TOKENS = [b"\x00", b"\xff", b"\xc3", b"\xe2\x82", b"\r", b"\t", b"\n", b"<", b">", b"&", b"&#0;",
          b"&#x110000;", b"&amp;", b"&lt", b"\"", b"'", b"]]>", b"<!--", b"-->", b"<?", b"?>",
          b"<![CDATA[", b"%", b"{", b"}", b"[", b"]", b":", b"- ", b"#", b"*", b"&a", b"!!str ",
          b"|", b">-", b"---", b"...", b"\\", b"=", b"<=", b"[]", b"[-1]", b"[0]", b"/", b"~",
          b"\xef\xbb\xbf", b"string<=", b"[<=", b"::", b"ros__parameters", b"\x7f", b"\x1b"]
INTERESTING_32 = [0, 1, 2, 3, 4, 7, 8, 0x7F, 0x80, 0xFF, 0x100, 0xFFFF, 0x10000, 0x7FFFFFFF,
                  0x80000000, 0xFFFFFFFE, 0xFFFFFFFF]
INTERESTING_64 = INTERESTING_32 + [0x100000000, 0x7FFFFFFFFFFFFFFF, 0x8000000000000000,
                                   0xFFFFFFFFFFFFFFFF]


# ---------------------------------------------------------------- mutators

def _lines(data):
    return data.split(b"\n")


def m_flip(rng, data, kind):
    if not data:
        return data, "flip (empty)"
    d = bytearray(data)
    for _ in range(rng.choice([1, 1, 2, 4, 8])):
        i = rng.randrange(len(d))
        d[i] = rng.randrange(256) if rng.random() < 0.5 else d[i] ^ (1 << rng.randrange(8))
    return bytes(d), "byte flips"


def m_truncate(rng, data, kind):
    n = rng.randrange(len(data) + 1) if data else 0
    return data[:n], f"truncated at {n}"


def m_delete(rng, data, kind):
    if not data:
        return data, "delete (empty)"
    i = rng.randrange(len(data))
    n = rng.choice([1, 2, 4, 8, 16, 64, 256])
    return data[:i] + data[i + n:], f"deleted {n} at {i}"


def m_insert_token(rng, data, kind):
    i = rng.randrange(len(data) + 1)
    t = rng.choice(TOKENS)
    return data[:i] + t + data[i:], f"inserted {t!r} at {i}"


def m_number(rng, data, kind):
    spans = [m.span() for m in re.finditer(rb"-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?", data)]
    huge = rng.choice(HUGE_NUMBERS)
    if not spans:
        i = rng.randrange(len(data) + 1)
        return data[:i] + huge + data[i:], f"inserted number {huge!r} at {i}"
    a, b = rng.choice(spans)
    return data[:a] + huge + data[b:], f"number at {a} -> {huge!r}"


def m_long_line(rng, data, kind):
    i = rng.randrange(len(data) + 1)
    n = rng.choice([300, 5000, 70000, 1 << 20])
    filler = rng.choice([b"A", b"9", b" ", b"x_"]) * n
    return data[:i] + filler + data[i:], f"inserted {n} x {filler[:2]!r} at {i}"


NESTING = {"xml": [b"<a>"], "yaml": [b"[", b"{a: ", b"- "], "msg": [b"a/"], "tsp": [b"("],
           "binary": [b"\x00"]}


def m_nesting(rng, data, kind):
    i = rng.randrange(len(data) + 1)
    unit = rng.choice(NESTING.get(kind, [b"["]))
    n = rng.choice([100, 1000, 100000])
    return data[:i] + unit * n + data[i:], f"nesting {unit!r} x {n} at {i}"


def m_duplicate_lines(rng, data, kind):
    ls = _lines(data)
    a = rng.randrange(len(ls))
    b = min(len(ls), a + rng.choice([1, 2, 5, 20]))
    times = rng.choice([1, 2, 50])
    return b"\n".join(ls[:b] + ls[a:b] * times + ls[b:]), f"lines {a}..{b} repeated {times}"


def m_swap_lines(rng, data, kind):
    ls = _lines(data)
    if len(ls) < 2:
        return data, "swap (one line)"
    a, b = rng.randrange(len(ls)), rng.randrange(len(ls))
    ls[a], ls[b] = ls[b], ls[a]
    return b"\n".join(ls), f"lines {a} and {b} swapped"


def m_drop_line(rng, data, kind):
    ls = _lines(data)
    a = rng.randrange(len(ls))
    return b"\n".join(ls[:a] + ls[a + 1:]), f"line {a} dropped"


def m_word(rng, data, kind):
    """An integer of 4 or 8 bytes written at an offset (length fields)."""
    if len(data) < 8:
        return m_flip(rng, data, kind)
    size = rng.choice([4, 8])
    i = rng.randrange(len(data) - size + 1)
    if rng.random() < 0.7:
        i -= i % 4
    v = rng.choice(INTERESTING_64 if size == 8 else INTERESTING_32 + [len(data), len(data) - i])
    v &= (1 << (8 * size)) - 1
    return data[:i] + v.to_bytes(size, "little") + data[i + size:], f"u{size * 8} {v:#x} at {i}"


TEXT_MUTATORS = [m_flip, m_truncate, m_delete, m_insert_token, m_number, m_number, m_number,
                 m_long_line, m_nesting, m_duplicate_lines, m_swap_lines, m_drop_line]
BINARY_MUTATORS = [m_flip, m_flip, m_truncate, m_delete, m_insert_token, m_word, m_word, m_word]


def mcap_records(data):
    """(offset, opcode, length) of the top-level MCAP records."""
    out = []
    i = 8
    while i + 9 <= len(data):
        op = data[i]
        n = int.from_bytes(data[i + 1:i + 9], "little")
        out.append((i, op, n))
        if n > len(data):
            break
        i += 9 + n
    return out


def m_mcap_length(rng, data, kind):
    """A wrong record length, or a wrong length inside a record's content."""
    recs = mcap_records(data)
    if not recs:
        return m_word(rng, data, kind)
    off, op, n = rng.choice(recs)
    if rng.random() < 0.5:
        v = rng.choice([0, 1, n - 1, n + 1, n * 2, len(data), 0x7FFFFFFFFFFFFFFF,
                        0xFFFFFFFFFFFFFFFF, 1 << 40]) & 0xFFFFFFFFFFFFFFFF
        return (data[:off + 1] + v.to_bytes(8, "little") + data[off + 9:],
                f"record op {op:#x} at {off}: length {n} -> {v:#x}")
    # a field of the content: every 4-byte position of the first 64 bytes
    start = off + 9
    if n < 4:
        return m_word(rng, data, kind)
    j = start + rng.randrange(min(n, 64) - 3)
    v = rng.choice(INTERESTING_32 + [n, n - (j - start)]) & 0xFFFFFFFF
    return (data[:j] + v.to_bytes(4, "little") + data[j + 4:],
            f"record op {op:#x} at {off}: u32 {v:#x} at {j}")


# ---------------------------------------------------------------- readers

class Reader:
    """name: how a case is made and run. argv holds {input} (the mutated
    file) and {dir} (the case's folder); `where` is the pattern an error must
    contain; `unlocated_ok` matches outputs that concern no place in the
    file (the input was read)."""

    def __init__(self, name, seeds, argv, kind, where, mutators, timeout=10.0,
                 unlocated_ok=None, prepare=None, name_of=None, must_refuse=None,
                 session=False, outlasts=None):
        self.name, self.seeds, self.argv, self.kind = name, seeds, argv, kind
        # outlasts(data): the input takes longer than the time limit to
        # process as it should (a bag whose recorded timing spans hours); the
        # program must then stop on SIGINT at the limit (else a hang).
        self.outlasts = outlasts
        self.where, self.mutators, self.timeout = where, mutators, timeout
        self.unlocated_ok = unlocated_ok
        self.prepare = prepare or (lambda seed, folder: None)
        self.name_of = name_of or (lambda seed: "input" + seed.suffix)
        self.must_refuse = must_refuse or (lambda seed_data, data, how: False)
        self.session = session
        # session: the program starts others (sancta demo): run in the
        # repository, each case in a session whose leftovers are a finding.


def located_in(file_name):
    return re.compile(re.escape(file_name) + r"(:\d+)+")


def xml_must_refuse(seed, data, how):
    # Cut before the root's end tag: not well-formed.
    if not how.startswith("truncated"):
        return False
    end = seed.rstrip().rsplit(b"</", 1)
    return len(end) == 2 and b"</" + end[1] not in data


def mcap_play_outlasts(data, rate=1000.0, limit=20.0):
    """bag play keeps the recorded timing: the messages' log times, read by
    the Python mcap reader, span more than the time limit at play's rate
    (less a margin for starting). False when that reader refuses the file."""
    import io
    from mcap.reader import make_reader
    try:
        times = [m.log_time for _, _, m in make_reader(io.BytesIO(data)).iter_messages()]
    except Exception:
        return False
    return len(times) > 1 and (max(times) - min(times)) / 1e9 / rate > limit - 5.0


def mcap_must_refuse(seed, data, how):
    return how.startswith("truncated") and not data.endswith(b"\x89MCAP0\r\n")


def make_mcap_seeds(folder):
    """Five rosbag2-profile MCAP files written by the `mcap` package:
    uncompressed chunks with and without CRCs, lz4 and zstd chunks, no
    chunks."""
    from mcap.writer import Writer, CompressionType
    seeds = []
    schema_text = b"string data\n"
    scan_text = (b"std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\n"
                 b"float32 angle_increment\nfloat32 time_increment\nfloat32 scan_time\n"
                 b"float32 range_min\nfloat32 range_max\nfloat32[] ranges\n"
                 b"float32[] intensities\n"
                 b"================================================================================\n"
                 b"MSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id\n"
                 b"================================================================================\n"
                 b"MSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n")
    # Without CRCs (as the format allows: 0 = not computed), a flipped byte
    # reaches the record readers instead of the CRC check.
    for label, comp, chunked, crcs in (("plain", CompressionType.NONE, True, True),
                                       ("nocrc", CompressionType.NONE, True, False),
                                       ("lz4", CompressionType.LZ4, True, False),
                                       ("zstd", CompressionType.ZSTD, True, False),
                                       ("flat", CompressionType.NONE, False, False)):
        path = folder / f"seed-{label}.mcap"
        with open(path, "wb") as f:
            w = Writer(f, compression=comp, use_chunking=chunked, chunk_size=300,
                       use_summary_offsets=chunked, enable_crcs=crcs)
            w.start(profile="ros2", library="fuzz")
            s1 = w.register_schema("std_msgs/msg/String", "ros2msg", schema_text)
            s2 = w.register_schema("sensor_msgs/msg/LaserScan", "ros2msg", scan_text)
            # QoS as rosbag2 writes it: Humble's numbers, Jazzy's names.
            c1 = w.register_channel("/chatter", "cdr", s1, {"offered_qos_profiles": (
                "- history: 1\n  depth: 10\n  reliability: 1\n  durability: 1\n"
                if label in ("plain", "lz4") else "")})
            c2 = w.register_channel("/scan", "cdr", s2, {} if label == "flat" else {
                "offered_qos_profiles": "- history: keep_last\n  depth: 5\n"
                "  reliability: best_effort\n  durability: volatile\n"})
            for i in range(6):
                text = f"hello {i}".encode()
                payload = (b"\x00\x01\x00\x00" + (len(text) + 1).to_bytes(4, "little")
                           + text + b"\x00")
                w.add_message(c1, log_time=1_000_000_000 + i * 10_000_000, data=payload,
                              publish_time=1_000_000_000 + i * 10_000_000, sequence=i)
                scan = (b"\x00\x01\x00\x00" + i.to_bytes(4, "little") + b"\x00" * 4
                        + (2).to_bytes(4, "little") + b"l\x00\x00\x00" + b"\x00" * 28
                        + (2).to_bytes(4, "little") + b"\x00\x00\x80\x3f" * 2
                        + (0).to_bytes(4, "little"))
                w.add_message(c2, log_time=1_000_000_000 + i * 10_000_000 + 1, data=scan,
                              publish_time=1_000_000_000 + i * 10_000_000 + 1, sequence=i)
            w.finish()
        seeds.append(path)
    return seeds


DB3_VALUES = ["NULL", "0", "-1", "1", "2", "9", "1.5", "'text'", "''", "x''", "x'00'",
              "x'000100'", "x'0001000002000000410000'", "'/chatter'", "'/bad topic'",
              "'std_msgs/msg/Int32'", "'no/type'", "'json'", "'- [1, 2'",
              "'- history: 1\n  depth: ten\n'", "9223372036854775807",
              "-9223372036854775808", "4611686018427387904", "1e300"]
DB3_STATEMENTS = [
    "DROP TABLE {table}", "DELETE FROM {table}", "DELETE FROM {table} WHERE rowid = {row}",
    "UPDATE {table} SET {column} = {value} WHERE rowid = {row}",
    "UPDATE {table} SET {column} = {value}",
    "INSERT INTO {table} SELECT * FROM {table} WHERE rowid = {row}",
    "ALTER TABLE {table} DROP COLUMN {column}",
    "ALTER TABLE {table} RENAME COLUMN {column} TO renamed"]
DB3_COLUMNS = {"topics": ["id", "name", "type", "serialization_format", "offered_qos_profiles"],
               "messages": ["id", "topic_id", "timestamp", "data"]}


def with_database(data, change):
    """change(connection) applied to the database `data`; its bytes after
    (None when sqlite refuses the database or the change)."""
    import sqlite3
    with tempfile.TemporaryDirectory(prefix="fuzz-db3-") as tmp:
        path = pathlib.Path(tmp) / "x.db3"
        path.write_bytes(data)
        try:
            db = sqlite3.connect(path)
            try:
                result = change(db)
                db.commit()
            finally:
                db.close()
        except (sqlite3.Error, ValueError, OverflowError):
            # ValueError: Python's own reading (a text not in UTF-8).
            return None, None
        return path.read_bytes(), result


def m_db3_sql(rng, data, kind):
    """A rosbag2 table changed through SQL: a table or column gone, rows
    deleted or duplicated, a value of another kind or out of range (topic
    ids naming no topic, empty data, texts for numbers...)."""
    table = rng.choice(["topics", "messages"])
    statement = rng.choice(DB3_STATEMENTS).format(
        table=table, column=rng.choice(DB3_COLUMNS[table]), value=rng.choice(DB3_VALUES),
        row=rng.randrange(1, 14))
    changed, _ = with_database(data, lambda db: db.execute(statement))
    if changed is None:
        return m_word(rng, data, kind)
    return changed, f"sql: {statement}"


def db3_play_outlasts(data, rate=1000.0, limit=20.0):
    """As mcap_play_outlasts, the timestamps read by Python's sqlite3."""
    _, span = with_database(data, lambda db: db.execute(
        "SELECT max(timestamp) - min(timestamp) FROM messages").fetchone()[0])
    return isinstance(span, int) and span / 1e9 / rate > limit - 5.0


def make_db3_seeds(folder):
    """rosbag2 sqlite3 files in the layouts of schema version 4 (topics with
    type_description_hash, as rosbags writes them; no message_definitions,
    which is not read), 3 (Humble) and 1 (no QoS column): 6 strings on
    /chatter, 6 scans on /scan (the MCAP seeds' payloads)."""
    seeds = []
    for label, schema, qos in (("schema4", 4, True), ("humble", 3, True), ("old", 1, False)):
        path = folder / f"seed-{label}.db3"
        path.unlink(missing_ok=True)
        qos_text = ("- history: 1\n  depth: 10\n  reliability: 1\n  durability: 1\n"
                    if label == "humble" else "- history: keep_last\n  depth: 5\n"
                    "  reliability: best_effort\n  durability: volatile\n")
        messages = []
        for i in range(6):
            text = f"hello {i}".encode()
            payload = (b"\x00\x01\x00\x00" + (len(text) + 1).to_bytes(4, "little") + text
                       + b"\x00")
            scan = (b"\x00\x01\x00\x00" + i.to_bytes(4, "little") + b"\x00" * 4
                    + (2).to_bytes(4, "little") + b"l\x00\x00\x00" + b"\x00" * 28
                    + (2).to_bytes(4, "little") + b"\x00\x00\x80\x3f" * 2
                    + (0).to_bytes(4, "little"))
            stamp = 1_000_000_000 + i * 10_000_000
            messages += [(1, stamp, payload), (2, stamp + 1, scan)]
        rosbag2_db3.write(path, schema,
                          [(1, "/chatter", "std_msgs/msg/String", qos_text),
                           (2, "/scan", "sensor_msgs/msg/LaserScan", qos_text)],
                          messages, vacuum=True)
        seeds.append(path)
    return seeds


def zstd_frame(data, checksum):
    import zstandard
    return zstandard.ZstdCompressor(level=3, write_checksum=checksum).compress(data)


def make_zstd_file_seeds(folder):
    """rosbag2's compression_mode file: the MCAP seeds (uncompressed and
    zstd chunks) and the db3 seeds (Humble's, schema 4) compressed whole,
    with and without the frame checksum (rosbag2 writes none)."""
    mcaps = {p.stem.split("-")[1]: p for p in make_mcap_seeds(folder)}
    db3s = {p.stem.split("-")[1]: p for p in make_db3_seeds(folder)}
    seeds = []
    for label, source, checksum in (("plain", mcaps["plain"], False),
                                    ("zstd", mcaps["zstd"], True),
                                    ("humble", db3s["humble"], False),
                                    ("schema4", db3s["schema4"], True)):
        path = folder / f"seed-file-{label}{source.suffix}.zstd"
        path.write_bytes(zstd_frame(source.read_bytes(), checksum))
        seeds.append(path)
    return seeds


def m_zstd_inner(rng, data, kind):
    """The compressed file's content mutated (as its storage's reader is
    fuzzed) and compressed again: the defects reach the MCAP / SQLite
    readers through the decompression."""
    import zstandard
    try:
        inner = zstandard.ZstdDecompressor().decompressobj().decompress(data)
    except zstandard.ZstdError:
        return m_flip(rng, data, kind)
    sql = inner.startswith(b"SQLite format 3\0")
    mutator = rng.choice(BINARY_MUTATORS + ([m_db3_sql] * 3 if sql else [m_mcap_length] * 3))
    inner, how = mutator(rng, inner, kind)
    return zstd_frame(inner, rng.random() < 0.5), "inside: " + how


def make_zstd_message_seeds(folder):
    """rosbag2's compression_mode message, one file given alone (no
    metadata.yaml: data that starts a zstd frame is decompressed): the db3
    seeds with every data blob one zstd frame, the uncompressed-chunk MCAP
    seed with every message's data one."""
    import sqlite3
    from mcap.reader import make_reader
    from mcap.writer import Writer, CompressionType
    seeds = []
    for seed in make_db3_seeds(folder)[:2]:
        path = folder / f"seed-message-{seed.stem.split('-')[1]}.db3"
        shutil.copy(seed, path)
        with sqlite3.connect(path) as db:
            db.create_function("frame", 1, lambda d: zstd_frame(bytes(d), False))
            db.execute("UPDATE messages SET data = frame (data)")
        seeds.append(path)
    source = [p for p in make_mcap_seeds(folder) if p.stem == "seed-plain"][0]
    path = folder / "seed-message-plain.mcap"
    with open(source, "rb") as f, open(path, "wb") as out:
        reader = make_reader(f)
        w = Writer(out, compression=CompressionType.NONE, chunk_size=300, enable_crcs=False)
        w.start(profile="ros2", library="fuzz")
        summary = reader.get_summary()
        ids = {}
        for sid, schema in summary.schemas.items():
            ids[sid] = w.register_schema(schema.name, schema.encoding, schema.data)
        chans = {}
        for cid, c in summary.channels.items():
            chans[cid] = w.register_channel(c.topic, c.message_encoding, ids[c.schema_id],
                                            c.metadata)
        for _, channel, m in reader.iter_messages():
            w.add_message(chans[channel.id], log_time=m.log_time, publish_time=m.publish_time,
                          sequence=m.sequence, data=zstd_frame(m.data, m.sequence % 2 == 0))
        w.finish()
    seeds.append(path)
    return seeds


def m_db3_frame(rng, data, kind):
    """One message's zstd frame cut, flipped or replaced by a plain CDR
    message (compression_mode message)."""
    row = rng.randrange(1, 14)

    def change(db):
        found = db.execute("SELECT data FROM messages WHERE rowid = ?", (row,)).fetchone()
        if not found or not isinstance(found[0], bytes) or not found[0]:
            return "no row"
        frame = bytearray(found[0])
        what = rng.choice(["cut", "flip", "plain"])
        if what == "cut":
            frame = frame[:rng.randrange(len(frame))]
        elif what == "flip":
            frame[rng.randrange(len(frame))] ^= 1 << rng.randrange(8)
        else:
            frame = bytearray(b"\x00\x01\x00\x00\x02\x00\x00\x00a\x00")
        db.execute("UPDATE messages SET data = ? WHERE rowid = ?", (bytes(frame), row))
        return f"{what} row {row}"
    changed, how = with_database(data, change)
    if changed is None:
        return m_flip(rng, data, kind)
    return changed, f"frame: {how}"


def zstd_message_play_outlasts(data):
    return (db3_play_outlasts(data) if data.startswith(b"SQLite format 3\0")
            else mcap_play_outlasts(data))


def definition_seeds():
    root = SHARE / "ros2_interfaces"
    picks = ["std_msgs/msg/Header.msg", "sensor_msgs/msg/LaserScan.msg",
             "geometry_msgs/msg/PoseWithCovariance.msg", "example_interfaces/srv/AddTwoInts.srv",
             "example_interfaces/action/Fibonacci.action", "rcl_interfaces/msg/ParameterDescriptor.msg",
             "std_msgs/msg/MultiArrayLayout.msg", "lifecycle_msgs/msg/State.msg",
             "nav_msgs/srv/GetPlan.srv", "action_msgs/msg/GoalStatus.msg"]
    return [root / p for p in picks if (root / p).is_file()]


def params_seeds(folder):
    texts = {
        "plain.yaml": "/**:\n  ros__parameters:\n    speed: 1.5\n    name: \"robot\"\n"
                      "    count: 3\n    enabled: true\n    ratios: [0.5, 1.0, 2.5]\n"
                      "    names: ['a', 'b']\n    flags: [true, false]\n"
                      "    nested:\n      depth: 4\n      label: x\n",
        "node.yaml": "fuzz_nobody:\n  ros__parameters:\n    use_sim_time: false\n"
                     "    qos_overrides:\n      /chatter:\n        publisher:\n"
                     "          depth: 10\n          reliability: reliable\n"
                     "    bytes: [1, 2, 3]\n    text: |\n      two\n      lines\n",
        "flow.yaml": "{/**: {ros__parameters: {a: 1, b: [1, 2], c: {d: 'q', e: -0.5e3}}}}\n",
    }
    out = []
    for name, text in texts.items():
        (folder / name).write_text(text)
        out.append(folder / name)
    return out


MESSAGE_SEEDS = {
    "std_msgs.msg.String": "{data: hello}",
    "geometry_msgs.msg.Twist": "{linear: {x: 1.0, y: -2.5, z: 0}, angular: {z: 0.5}}",
    "sensor_msgs.msg.JointState": "{header: {stamp: {sec: 1, nanosec: 2}, frame_id: base}, "
                                  "name: [a, b], position: [1.0, 2.0], velocity: [], "
                                  "effort: [0.5]}",
    "std_msgs.msg.Float64MultiArray": "{layout: {dim: [{label: x, size: 2, stride: 2}], "
                                      "data_offset: 0}, data: [1.5, 2.5]}",
    "rcl_interfaces.msg.ParameterValue": "{type: 9, integer_value: -5, "
                                         "string_array_value: ['a', \"b c\"]}",
    "sensor_msgs.msg.CompressedImage": "{format: jpeg, data: [1, 2, 255]}",
    "builtin_interfaces.msg.Time": "{sec: -1, nanosec: 999999999}",
}


def message_seeds(folder):
    """YAML messages as `rclada topic pub` takes them (the file's stem is the
    type, dots for slashes): flow ones above, block ones as `cdr_tool image`
    prints them (LaserScan, OccupancyGrid, Odometry)."""
    seeds = []
    for name, text in MESSAGE_SEEDS.items():
        seeds.append(folder / f"{name}.yaml")
        seeds[-1].write_text(text)
    for sample, name in (("laser_scan", "sensor_msgs.msg.LaserScan"),
                         ("occupancy_grid", "nav_msgs.msg.OccupancyGrid"),
                         ("odometry", "nav_msgs.msg.Odometry")):
        image = subprocess.run([str(BIN / "cdr_tool"), "image", sample], capture_output=True,
                               text=True, check=True).stdout
        seeds.append(folder / f"{name}.yaml")
        seeds[-1].write_text(image)
    return seeds


def config_prepare(seed, folder):
    # Includes are relative to the including file.
    shutil.copytree(SHARE / "config" / "parts", folder / "parts")


def world_prepare(seed, folder):
    for f in ("arena.pgm",):
        shutil.copy(SHARE / "worlds" / f, folder / f)


def pgm_prepare(seed, folder):
    (folder / "world.yaml").write_text(
        "image: input.pgm\nresolution: 0.05\norigin: [-0.70, -0.70, 0.0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n")


def small_pgm(folder):
    # A 40 x 30 P5 map (the bundled ones are 180 KB: most flips land in pixels).
    body = bytes((0 if (x in (0, 39) or y in (0, 29)) else 254) for y in range(30) for x in range(40))
    p5 = folder / "small.pgm"
    p5.write_bytes(b"P5\n# fuzz seed\n40 30\n255\n" + body)
    p2 = folder / "small-ascii.pgm"
    p2.write_text("P2\n40 30\n255\n" + "\n".join(" ".join(str(b) for b in body[y * 40:(y + 1) * 40])
                                                  for y in range(30)) + "\n")
    return [p5, p2]


# ------------------------------------------------------------------ PNG maps
# Map images in PNG go through the simulator's own PNG reader and inflater
# (Sancta.Simulation.Raster_Images, .Deflate). The seeds cover every colour
# type and bit depth the reader takes, all five row filters, the three
# DEFLATE block kinds and image data split over several IDAT chunks; most
# mutations keep the chunks' CRCs right so that they reach the inflater and
# the row filters.

def png_chunk(kind, body):
    return (struct.pack(">I", len(body)) + kind + body
            + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))


PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png_chunks(data):
    """[(kind, body)] of a PNG whose chunk lengths are right, else None."""
    if not data.startswith(PNG_SIGNATURE):
        return None
    pos, chunks = 8, []
    while pos + 12 <= len(data):
        n = struct.unpack(">I", data[pos:pos + 4])[0]
        if pos + 12 + n > len(data):
            return None
        chunks.append((data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]))
        pos += 12 + n
    return chunks if pos == len(data) else None


def png_from(chunks):
    return PNG_SIGNATURE + b"".join(png_chunk(k, b) for k, b in chunks)


def png_filtered(rows, bpp):
    """Rows (bytes) with filter type row % 5 applied (the encoder's side)."""
    out, prior = b"", bytes(len(rows[0]))
    for y, row in enumerate(rows):
        f = y % 5
        line = bytearray()
        for i, x in enumerate(row):
            a = row[i - bpp] if i >= bpp else 0
            b = prior[i]
            c = prior[i - bpp] if i >= bpp else 0
            if f == 0:
                pred = 0
            elif f == 1:
                pred = a
            elif f == 2:
                pred = b
            elif f == 3:
                pred = (a + b) // 2
            else:
                p_ = a + b - c
                pa, pb, pc = abs(p_ - a), abs(p_ - b), abs(p_ - c)
                pred = a if pa <= pb and pa <= pc else b if pb <= pc else c
            line.append((x - pred) % 256)
        out += bytes([f]) + bytes(line)
        prior = row
    return out


def png_seeds(folder):
    w, h = 24, 18
    gray = [[0 if x in (0, w - 1) or y in (0, h - 1) else 205 if 8 <= x < 12 else 254
             for x in range(w)] for y in range(h)]

    def packed(values, depth):
        bits = "".join(format(v, f"0{depth}b") for v in values)
        bits += "0" * (-len(bits) % 8)
        return bytes(int(bits[i:i + 8], 2) for i in range(0, len(bits), 8))

    variants = [  # (name, colour type, depth, rows, bytes per pixel, extra chunks)
        ("gray8", 0, 8, [bytes(r) for r in gray], 1, []),
        ("gray1", 0, 1, [packed([int(v > 128) for v in r], 1) for r in gray], 1, []),
        ("gray4", 0, 4, [packed([v // 17 for v in r], 4) for r in gray], 1, []),
        ("gray16", 0, 16, [b"".join(struct.pack(">H", v * 257) for v in r) for r in gray], 2, []),
        ("graya8", 4, 8, [bytes(x for v in r for x in (v, 255)) for r in gray], 2, []),
        ("rgb8", 2, 8, [bytes(x for v in r for x in (v, v, 255 - v // 2)) for r in gray], 3, []),
        ("rgba16", 6, 16, [b"".join(struct.pack(">4H", v * 257, v * 257, v * 257, 65535)
                                    for v in r) for r in gray], 8, []),
        ("palette2", 3, 2, [packed([{0: 0, 205: 1, 254: 2}[v] for v in r], 2) for r in gray], 1,
         [(b"PLTE", bytes([0, 0, 0, 205, 205, 205, 254, 254, 254]))]),
    ]
    seeds = []
    for n, (name, ctype, depth, rows, bpp, extra) in enumerate(variants):
        raw = png_filtered(rows, bpp)
        level, strategy = [(9, zlib.Z_DEFAULT_STRATEGY), (6, zlib.Z_FIXED), (0, 0)][n % 3]
        c = zlib.compressobj(level, zlib.DEFLATED, 15, 9, strategy)
        stream = c.compress(raw) + c.flush()
        idat = [(b"IDAT", stream)] if n % 2 else [(b"IDAT", stream[i:i + 40])
                                                   for i in range(0, len(stream), 40)]
        ihdr = struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, 0)
        data = png_from([(b"IHDR", ihdr)] + extra + [(b"tEXt", b"Comment\0fuzz seed")] + idat
                        + [(b"IEND", b"")])
        path = folder / f"{name}.png"
        path.write_bytes(data)
        seeds.append(path)
    return seeds


def png_prepare(seed, folder):
    (folder / "world.yaml").write_text(
        "image: input.png\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n")


def png_rebuilt(rng, data, change):
    """data with change(rng, chunks) -> (chunks, how) applied, every CRC
    right; the plain byte mutations when data's chunks cannot be read."""
    chunks = png_chunks(data)
    if not chunks:
        return m_flip(rng, data, "binary")
    chunks, how = change(rng, chunks)
    return png_from(chunks), how


def png_image_data(chunks):
    return b"".join(b for k, b in chunks if k == b"IDAT")


def with_image_data(chunks, stream, split):
    """chunks with their IDAT chunks replaced by stream (in `split`-byte
    chunks) where the first one was."""
    first = next((i for i, (k, _) in enumerate(chunks) if k == b"IDAT"), len(chunks) - 1)
    rest = [c for c in chunks if c[0] != b"IDAT"]
    idat = [(b"IDAT", stream[i:i + split]) for i in range(0, max(1, len(stream)), split)]
    return rest[:first] + idat + rest[first:]


def m_png_pixels(rng, data, kind):
    """The decompressed rows mutated (filter types, bytes, length), then
    compressed again."""
    def change(rng, chunks):
        try:
            raw = zlib.decompress(png_image_data(chunks))
        except zlib.error:
            return chunks, "pixels (image data unreadable)"
        raw = bytearray(raw)
        r = rng.random()
        if r < 0.4 and raw:
            for _ in range(rng.choice([1, 2, 4])):
                raw[rng.randrange(len(raw))] = rng.choice([5, 6, 255, 128, rng.randrange(256)])
            how = "image bytes changed"
        elif r < 0.7:
            cut = rng.randrange(len(raw) + 1)
            raw, how = raw[:cut], f"image data cut at {cut}"
        else:
            more = rng.choice([1, 7, 100, 100000])
            raw, how = raw + bytes(rng.randrange(256) for _ in range(more)), f"{more} bytes more"
        level = rng.choice([0, 1, 9])
        stream = zlib.compress(bytes(raw), level)
        split = rng.choice([8, 64, 1 << 20])
        return with_image_data(chunks, stream, split), how + f", level {level}"
    return png_rebuilt(rng, data, change)


def m_png_stream(rng, data, kind):
    """The compressed image data mutated (DEFLATE and zlib errors)."""
    def change(rng, chunks):
        stream = bytearray(png_image_data(chunks))
        r = rng.random()
        if r < 0.5 and stream:
            for _ in range(rng.choice([1, 1, 2, 3])):
                i = rng.randrange(len(stream))
                stream[i] ^= 1 << rng.randrange(8)
            how = "image stream bits flipped"
        elif r < 0.75:
            cut = rng.randrange(len(stream) + 1)
            stream, how = stream[:cut], f"image stream cut at {cut}"
        else:
            i = rng.randrange(len(stream) + 1)
            junk = bytes(rng.randrange(256) for _ in range(rng.choice([1, 4, 64])))
            stream = stream[:i] + junk + stream[i:]
            how = f"{len(junk)} bytes into the stream at {i}"
        return with_image_data(chunks, bytes(stream), rng.choice([8, 64, 1 << 20])), how
    return png_rebuilt(rng, data, change)


def m_png_header(rng, data, kind):
    """An IHDR field changed."""
    def change(rng, chunks):
        i = next((i for i, (k, _) in enumerate(chunks) if k == b"IHDR"), None)
        if i is None or len(chunks[i][1]) != 13:
            return chunks, "header (no IHDR)"
        body = bytearray(chunks[i][1])
        field = rng.choice(["width", "height", "depth", "colour", "compression", "filter",
                            "interlace"])
        if field in ("width", "height"):
            v = rng.choice([0, 1, 2, 23, 25, 30000, 30001, 65535, 2**31 - 1, 2**31, 2**32 - 1])
            struct.pack_into(">I", body, 0 if field == "width" else 4, v)
        else:
            v = rng.choice([0, 1, 2, 3, 4, 5, 6, 7, 8, 16, 32, 255])
            body[8 + ["depth", "colour", "compression", "filter", "interlace"].index(field)] = v
        chunks = list(chunks)
        chunks[i] = (b"IHDR", bytes(body))
        return chunks, f"IHDR {field} {v}"
    return png_rebuilt(rng, data, change)


def m_png_chunks(rng, data, kind):
    """Chunks dropped, doubled, moved or added (unknown critical and
    ancillary chunks, palettes of odd sizes)."""
    def change(rng, chunks):
        chunks = list(chunks)
        r = rng.random()
        i = rng.randrange(len(chunks))
        if r < 0.2:
            how = f"chunk {chunks[i][0]!r} dropped"
            del chunks[i]
        elif r < 0.35:
            how = f"chunk {chunks[i][0]!r} doubled"
            chunks.insert(i, chunks[i])
        elif r < 0.5:
            j = rng.randrange(len(chunks))
            how = f"chunk {chunks[i][0]!r} moved to {j}"
            chunks.insert(j, chunks.pop(i))
        elif r < 0.7:
            k = rng.choice([b"ABCD", b"abCD", b"IDAT", b"PLTE", b"tRNS", b"\0\1\2\3", b"IEND"])
            body = bytes(rng.randrange(256) for _ in range(rng.choice([0, 3, 9, 768, 771])))
            how = f"chunk {k!r} of {len(body)} bytes added at {i}"
            chunks.insert(i, (k, body))
        else:
            n = rng.choice([0, 1, 2, 255, 256, 257])
            how = f"palette of {n} entries"
            chunks = [c for c in chunks if c[0] != b"PLTE"]
            chunks.insert(1, (b"PLTE", bytes(rng.randrange(256) for _ in range(3 * n))))
        return chunks, how
    return png_rebuilt(rng, data, change)


PNG_MUTATORS = ([m_png_pixels] * 3 + [m_png_stream] * 4 + [m_png_header] * 2 + [m_png_chunks] * 3
                + BINARY_MUTATORS)


def png_problem(data):
    """Why a PNG is not valid by the PNG specification (chunks, CRCs, header,
    image data) or None: an independent reading, used to flag a mutated file
    the simulator accepts."""
    if not data.startswith(PNG_SIGNATURE):
        return "signature"
    pos, chunks = 8, []
    while True:
        if pos + 12 > len(data):
            return "no IEND"
        n = struct.unpack(">I", data[pos:pos + 4])[0]
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        if n > 2**31 - 1 or pos + 12 + n > len(data):
            return "chunk length"
        if zlib.crc32(kind + body) & 0xFFFFFFFF != struct.unpack(">I", data[pos + 8 + n:
                                                                         pos + 12 + n])[0]:
            return "CRC"
        chunks.append((kind, body))
        pos += 12 + n
        if kind == b"IEND":
            break
    kinds = [k for k, _ in chunks]
    if kinds[0] != b"IHDR" or kinds.count(b"IHDR") != 1 or len(chunks[0][1]) != 13:
        return "IHDR"
    for k in kinds:
        if not all(65 <= c <= 90 or 97 <= c <= 122 for c in k):
            return f"chunk type {k!r}"
        if 65 <= k[0] <= 90 and k not in (b"IHDR", b"PLTE", b"IDAT", b"IEND"):
            return f"unknown critical chunk {k!r}"
    w, h, depth, ctype, comp, filt, lace = struct.unpack(">IIBBBBB", chunks[0][1])
    if not (0 < w < 2**31 and 0 < h < 2**31) or comp or filt or lace > 1:
        return "IHDR fields"
    if depth not in {0: (1, 2, 4, 8, 16), 2: (8, 16), 3: (1, 2, 4, 8), 4: (8, 16),
                     6: (8, 16)}.get(ctype, ()):
        return "colour type / depth"
    idat = [i for i, k in enumerate(kinds) if k == b"IDAT"]
    if not idat or idat != list(range(idat[0], idat[-1] + 1)):
        return "IDAT missing or not consecutive"
    plte = [i for i, k in enumerate(kinds) if k == b"PLTE"]
    if len(plte) > 1 or (plte and (ctype in (0, 4) or plte[0] > idat[0])):
        return "PLTE"
    if plte:
        n = len(chunks[plte[0]][1])
        if n == 0 or n % 3 or n > 768:
            return "PLTE length"
    if ctype == 3 and not plte:
        return "no PLTE"
    if lace:
        return None  # valid; the simulator says it does not read interlaced images
    try:
        d = zlib.decompressobj()
        raw = d.decompress(b"".join(chunks[i][1] for i in idat))
        if not d.eof:
            return "image data cut short"
    except zlib.error:
        return "image data"
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]
    stride = (w * channels * depth + 7) // 8
    if len(raw) < h * (stride + 1):
        return "too little image data"
    if any(raw[y * (stride + 1)] > 4 for y in range(h)):
        return "filter type"
    return None


def png_must_refuse(seed, data, how):
    return png_problem(data) is not None


POLICY_KEYSTORE = []  # the keystore the policy reader's cases write into


def policy_seeds(folder):
    """Two SROS2 policies (format 0.2.0) and a keystore with enclave
    /talker, made once (`rclada security create_permission` signs into it)."""
    ks = folder / "keystore"
    for argv in (["create_keystore", str(ks)], ["create_enclave", str(ks), "/talker"]):
        subprocess.run([str(BIN / "rclada"), "security"] + argv, check=True,
                       capture_output=True, env=env())
    POLICY_KEYSTORE.append(str(ks))
    one = folder / "talker.xml"
    one.write_text(
        '<?xml version="1.0" encoding="UTF-8"?>\n<policy version="0.2.0">\n  <enclaves>\n'
        '    <enclave path="/talker">\n      <profiles>\n'
        '        <profile ns="/" node="talker">\n'
        '          <topics publish="ALLOW">\n            <topic>chatter</topic>\n'
        '            <topic>~/status</topic>\n          </topics>\n'
        '          <topics subscribe="DENY">\n            <topic>/secret</topic>\n'
        '          </topics>\n'
        '          <services reply="ALLOW">\n            <service>add_two_ints</service>\n'
        '          </services>\n'
        '          <actions call="ALLOW">\n            <action>fibonacci</action>\n'
        '          </actions>\n        </profile>\n      </profiles>\n    </enclave>\n'
        '  </enclaves>\n</policy>\n')
    two = folder / "robots.xml"
    two.write_text(
        '<policy version="0.2.0">\n<enclaves>\n'
        '<enclave path="/listener"><profiles><profile ns="/" node="listener">'
        '<topics subscribe="ALLOW"><topic>chatter</topic></topics></profile></profiles>'
        '</enclave>\n'
        '<enclave path="/talker"><profiles>\n'
        '<profile ns="/robots/r1" node="talker">\n'
        '<topics publish="ALLOW" subscribe="ALLOW"><topic>odom</topic><topic>/tf</topic>'
        '</topics>\n'
        '<services request="ALLOW"><service>~/get_map</service></services>\n'
        '<actions execute="DENY"><action>navigate</action></actions>\n'
        '</profile>\n<profile ns="/robots/r1/" node="helper">\n'
        '<topics publish="DENY"><topic>cmd_vel</topic></topics>\n</profile>\n'
        '</profiles></enclave>\n</enclaves>\n</policy>\n')
    return [one, two]


def trajectories_seed(folder):
    p = folder / "trajectories.csv"
    p.write_text("robot,x,y\n" + "".join(f"{1 + i % 3},{1 + i * 0.25:.2f},{2 + (i % 7) * 0.5:.2f}\n"
                                          for i in range(30)))
    return p


def definition_prepare(seed, folder):
    kind = seed.parent.name
    d = folder / "defs" / "fuzz_pkg" / kind
    d.mkdir(parents=True)


def build_readers(seed_folder):
    xml_where = None  # filled per case by the input's name
    readers = [
        Reader("config", sorted((SHARE / "config").glob("*.xml"))
               + sorted((SHARE / "config" / "parts").glob("*.xml")),
               ["sancta", "check", "{input}"], "xml", None, TEXT_MUTATORS,
               must_refuse=xml_must_refuse,
               # A configuration naming another file (an include, a mission, a
               # world) may fail on that file: the message names it.
               unlocated_ok=re.compile(r"cannot be opened|no such file|not found|does not exist",
                                       re.I)),
        Reader("mission", [SHARE / "missions" / n for n in ("example.xml", "plans.xml")],
               ["sancta", "plan", "{input}", "--time", "0.05"], "xml", None, TEXT_MUTATORS,
               must_refuse=xml_must_refuse),
        Reader("team", [SHARE / "missions" / "office-team.xml"],
               ["sancta", "team", "{input}", "--check"], "xml", None, TEXT_MUTATORS,
               must_refuse=xml_must_refuse,
               unlocated_ok=re.compile(r"cannot be opened|not reachable|outside the world")),
        Reader("tsp", [SHARE / "tsplib" / n for n in ("berlin52.tsp", "eil51.tsp", "br17.atsp",
                                                        "ftv33.atsp")],
               ["sancta", "plan", "{input}", "--time", "0.05"], "tsp", None, TEXT_MUTATORS,
               unlocated_ok=re.compile(r"too few tasks")),
        Reader("world", [SHARE / "worlds" / "arena.yaml"],
               ["sancta-render", "{input}", "--svg", "{dir}/w.svg"], "yaml", None, TEXT_MUTATORS,
               prepare=world_prepare,
               # A whole-file verdict: the world's extent at the picture's scale.
               unlocated_ok=re.compile(r": the world is \d+ x \d+ cells")),
        Reader("walls", sorted((SHARE / "worlds").glob("*.walls")),
               ["sancta-render", "{input}", "--svg", "{dir}/w.svg"], "tsp", None, TEXT_MUTATORS,
               unlocated_ok=re.compile(r": the world is \d+ x \d+ cells")),
        Reader("trajectories", [trajectories_seed(seed_folder)],
               ["sancta-render", str(SHARE / "worlds" / "arena.walls"), "--trajectories",
                "{input}", "--svg", "{dir}/w.svg"], "tsp", None, TEXT_MUTATORS),
        Reader("pgm", small_pgm(seed_folder),
               ["sancta-render", "{dir}/world.yaml", "--svg", "{dir}/w.svg"], "binary", None,
               BINARY_MUTATORS + [m_number, m_long_line], prepare=pgm_prepare,
               name_of=lambda seed: "input.pgm"),
        Reader("png", png_seeds(seed_folder),
               ["sancta-render", "{dir}/world.yaml", "--svg", "{dir}/w.svg"], "binary", None,
               PNG_MUTATORS, prepare=png_prepare, name_of=lambda seed: "input.png",
               must_refuse=png_must_refuse),
        Reader("policy", policy_seeds(seed_folder),
               ["rclada", "security", "create_permission", "{keystore}", "/talker", "{input}"],
               "xml", None, TEXT_MUTATORS, must_refuse=xml_must_refuse,
               # Verdicts on the whole file: no rules for the enclave, too
               # many, too large a file.
               unlocated_ok=re.compile(r"no <enclave path=|more than \d+ rules|may not exceed")),
        Reader("definition", definition_seeds(),
               ["rosidl_generate", "-o", "{dir}/out", "{dir}/defs"], "msg", None, TEXT_MUTATORS,
               prepare=definition_prepare,
               name_of=lambda seed: f"defs/fuzz_pkg/{seed.parent.name}/{seed.name}",
               unlocated_ok=re.compile(r"unknown (type|package)|cannot find|not found", re.I)),
        Reader("params", params_seeds(seed_folder),
               ["rclada", "param", "load", "/fuzz_nobody", "{input}", "--timeout", "0.01"],
               "yaml", None, TEXT_MUTATORS, timeout=15.0,
               # Read and understood: it then waits for a node that is not there.
               unlocated_ok=re.compile(r"service after|not available|set_parameters|has no parameters for")),
        Reader("message", message_seeds(seed_folder),
               ["rclada", "topic", "pub", "/fuzz_yaml", "{seed_type}", "{text}", "--once"],
               "yaml", None, TEXT_MUTATORS, timeout=15.0, name_of=lambda seed: "<argument>",
               # A mutated argument that starts with '-' is an option.
               unlocated_ok=re.compile(r"^rclada: unknown option -", re.M)),
        Reader("mcap", make_mcap_seeds(seed_folder),
               ["rclada", "bag", "info", "{input}"], "binary", None,
               BINARY_MUTATORS + [m_mcap_length] * 4, must_refuse=mcap_must_refuse),
        Reader("mcap-recover", make_mcap_seeds(seed_folder),
               ["rclada", "bag", "info", "{input}", "--recover"], "binary", None,
               BINARY_MUTATORS + [m_mcap_length] * 4),
        Reader("mcap-play", make_mcap_seeds(seed_folder),
               ["rclada", "bag", "play", "{input}", "--delay", "0", "-r", "1000"], "binary",
               None, BINARY_MUTATORS + [m_mcap_length] * 4, timeout=20.0,
               must_refuse=mcap_must_refuse, outlasts=mcap_play_outlasts),
        Reader("db3", make_db3_seeds(seed_folder),
               ["rclada", "bag", "info", "{input}"], "binary", None,
               BINARY_MUTATORS + [m_db3_sql] * 8),
        Reader("db3-play", make_db3_seeds(seed_folder),
               ["rclada", "bag", "play", "{input}", "--delay", "0", "-r", "1000"], "binary",
               None, BINARY_MUTATORS + [m_db3_sql] * 8, timeout=20.0,
               outlasts=db3_play_outlasts),
        Reader("zstd-file", make_zstd_file_seeds(seed_folder),
               ["rclada", "bag", "info", "{input}"], "binary", None,
               BINARY_MUTATORS + [m_zstd_inner] * 6,
               name_of=lambda seed: "input" + "".join(seed.suffixes[-2:])),
        Reader("zstd-file-play", make_zstd_file_seeds(seed_folder),
               ["rclada", "bag", "play", "{input}", "--delay", "0", "-r", "1000"], "binary",
               None, BINARY_MUTATORS + [m_zstd_inner] * 6, timeout=20.0,
               name_of=lambda seed: "input" + "".join(seed.suffixes[-2:])),
        Reader("zstd-message", make_zstd_message_seeds(seed_folder),
               ["rclada", "bag", "play", "{input}", "--delay", "0", "-r", "1000"], "binary",
               None, BINARY_MUTATORS + [m_db3_frame] * 4 + [m_mcap_length], timeout=20.0,
               outlasts=zstd_message_play_outlasts),
    ]
    # Configurations that run: each agent for a second (sancta run), the team
    # demo with sancta-sim and an agent process per robot (sancta demo).
    run_seeds = [SHARE / "config" / n for n in ("listing-1.1.xml", "robot-ros2.xml", "team.xml",
                                                "sim-robot.xml", "sim-corridor.xml")]
    readers += [
        Reader("run", run_seeds, ["sancta", "run", "{input}", "--all", "--for", "1"], "xml",
               None, TEXT_MUTATORS, timeout=20.0, must_refuse=xml_must_refuse,
               prepare=config_prepare, session=True,
               unlocated_ok=re.compile(r"cannot be opened|no such file|not found|does not exist",
                                       re.I)),
        Reader("demo", [SHARE / "config" / "sim-team.xml"],
               ["sancta", "demo", "{input}", "--max", "3", "--max-wall", "10", "--no-record",
                "--no-kill", "--quiet", "--out", "{dir}/out"], "xml", None, TEXT_MUTATORS,
               timeout=40.0, must_refuse=xml_must_refuse, prepare=config_prepare, session=True,
               # Ran: the summary (exit 1 when tasks are left at --max).
               unlocated_ok=re.compile(r"cannot be opened|no such file|not found|does not exist|"
                                       r"== summary ==", re.I)),
    ]
    del xml_where
    return readers


def env():
    e = dict(os.environ)
    e["CYCLONEDDS_URI"] = "file://" + str(SHARE / "cyclonedds-localhost.xml")
    e["ROS_LOCALHOST_ONLY"] = "1"
    if not e.get("ROS_DOMAIN_ID"):
        # Not pid % 200 + 20 unlocked: that could be the domain of a test
        # run going on (its tests would see the fuzzed programs' traffic).
        e["ROS_DOMAIN_ID"] = str(domain_lock.reserve())
    e["SANCTA_ROOT"] = str(REPO)
    e["RCLADA_ROOT"] = str(REPO)
    return e


def run(argv, timeout, stdin=None, interrupt=False):
    """(exit status, output, hung, seconds). At the time limit the process
    group is killed (hung True); with interrupt, it gets SIGINT first and
    3 s to end (hung "interrupted" when it does)."""
    began = time.monotonic()
    p = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         stdin=subprocess.PIPE if stdin is not None else subprocess.DEVNULL,
                         env=env(), start_new_session=True)
    try:
        out, err = p.communicate(stdin, timeout=timeout)
        hung = False
    except subprocess.TimeoutExpired:
        hung = True
        if interrupt:
            os.killpg(p.pid, signal.SIGINT)
            try:
                out, err = p.communicate(timeout=3.0)
                hung = "interrupted"
            except subprocess.TimeoutExpired:
                pass
        if hung is True:
            os.killpg(p.pid, signal.SIGKILL)
            out, err = p.communicate()
    text = (out + err).decode("utf-8", "replace")
    return p.returncode, text, hung, time.monotonic() - began


def session_members(sid):
    """Processes of session sid still alive (a program started with
    start_new_session=True is its session's leader: its descendants stay in
    the session unless they leave it)."""
    members = []
    for d in pathlib.Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                fields = (d / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[3]) == sid and fields[0] != "Z":
                members.append(int(d.name))
    return members


def run_session(argv, timeout, cwd=None):
    """Runs argv in a session of its own, output to a file (children that
    outlive it cannot hold a pipe open). After it ends or the time limit,
    every process left in the session is killed. (exit status, output, hung,
    how many processes it left behind)."""
    with tempfile.TemporaryFile() as out:
        p = subprocess.Popen(argv, stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                             env=env(), start_new_session=True, cwd=cwd)
        try:
            p.wait(timeout=timeout)
            hung = False
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGINT)
            try:
                p.wait(timeout=3)
            except subprocess.TimeoutExpired:
                pass
            hung = True
        time.sleep(0.2)  # children stopping with their parent
        left = [pid for pid in session_members(p.pid) if pid != p.pid]
        for pid in session_members(p.pid):
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        p.wait()
        out.seek(0)
        text = out.read().decode("utf-8", "replace")
    return p.returncode, text, hung, len(left)


def judge(reader, rc, text, hung, data, seed_data, how, file_name):
    if hung == "interrupted" and reader.outlasts is not None and reader.outlasts(data):
        hung = False  # long as it should be, and stopped when asked: judged as it ended
    if hung:
        return "hang"
    if rc < 0:
        return f"signal {-rc}"
    if TRACE.search(text):
        return "exception"
    if rc == 0:
        if reader.must_refuse(seed_data, data, how):
            return "accepted"
        return None
    base = pathlib.PurePath(file_name).name
    if reader.kind == "binary" and reader.name.startswith("mcap"):
        if re.search(r": byte \d+", text):
            return None
    elif reader.name.startswith("zstd"):
        # The file (its decompressed content), then a byte, table, column or
        # row, or SQLite's own message.
        if re.search(re.escape(base) + r"( \(decompressed\))?: \S", text):
            return None
    elif reader.name.startswith("db3"):
        # The file, then a table, column or row, or SQLite's own message.
        if re.search(re.escape(base) + r": \S", text):
            return None
    elif re.search(re.escape(base) + r":\d+", text):
        return None
    if reader.unlocated_ok is not None and reader.unlocated_ok.search(text):
        return None
    if reader.name == "pgm" and re.search(r"input\.pgm(:\d+|: byte \d+)", text):
        return None
    if reader.name == "png" and re.search(r"input\.png(:\d+|: byte \d+"
                                          r"|: image data: (zlib|deflate): byte \d+)", text):
        return None
    # An error located in a file the input includes (a value from one of the
    # input's constants is reported where it is used).
    if re.search(r"/parts/[\w.-]+\.xml:\d+", text):
        return None
    return "no location"


VERBOSE = False


def fuzz_reader(reader, rng, cases, keep, log):
    counts = {}
    findings = []
    seeds = [(s, s.read_bytes()) for s in reader.seeds]
    for n in range(cases):
        seed, seed_data = seeds[n % len(seeds)]
        data = seed_data
        hows = []
        for _ in range(rng.choice([1, 1, 1, 2, 3])):
            mut = rng.choice(reader.mutators)
            data, how = mut(rng, data, reader.kind)
            hows.append(how)
        how = "; ".join(hows)
        with tempfile.TemporaryDirectory(prefix="fuzz-") as tmp:
            folder = pathlib.Path(tmp)
            reader.prepare(seed, folder)
            file_name = reader.name_of(seed)
            (folder / file_name).parent.mkdir(parents=True, exist_ok=True)
            (folder / file_name).write_bytes(data)
            # {text}: the input as an argument (no NUL, at most 100 KB:
            # execve's limits); {seed_type}: the seed's stem, dots for slashes.
            text_argument = data.replace(b"\x00", b"").decode("utf-8", "replace")[:100000]
            argv = [a.replace("{input}", str(folder / file_name)).replace("{dir}", str(folder))
                    .replace("{seed_type}", seed.stem.replace(".", "/"))
                    .replace("{keystore}", POLICY_KEYSTORE[-1] if POLICY_KEYSTORE else "")
                    .replace("{text}", text_argument)
                    for a in reader.argv]
            argv[0] = str(BIN / argv[0])
            if reader.session:
                rc, text, hung, left = run_session(argv, reader.timeout, cwd=REPO)
            else:
                (rc, text, hung, _), left = run(argv, reader.timeout,
                                                interrupt=reader.outlasts is not None), 0
            verdict = judge(reader, rc, text, hung, data, seed_data if len(hows) == 1 else b"",
                            how, file_name)
            if left and not verdict:
                verdict = "left processes"
            # The processes a demo starts log into its out/ folder.
            logs = "".join(f.read_text(errors="replace") for f in sorted(folder.glob("out/*.log")))
            if not verdict and TRACE.search(logs):
                verdict = "exception in a log"
                text += "\n--- logs\n" + logs
            counts[verdict or "ok"] = counts.get(verdict or "ok", 0) + 1
            if VERBOSE:
                log.write(f"{reader.name} #{n} exit {rc} {verdict or 'ok'}: {how[:100]}\n   "
                          + (text.strip().splitlines() or [""])[-1][:200] + "\n")
            if verdict:
                findings.append((verdict, seed.name, how, text.strip().splitlines()[-3:]))
                log.write(f"{reader.name} #{n} {verdict}: seed {seed.name}; {how}\n"
                          f"   {' | '.join(text.strip().splitlines()[-3:])[:400]}\n")
                log.flush()
                if keep:
                    d = keep / reader.name / f"{n:05d}-{verdict.replace(' ', '_')}"
                    d.mkdir(parents=True, exist_ok=True)
                    shutil.copytree(folder, d, dirs_exist_ok=True)
                    (d / "CASE.txt").write_text(f"seed {seed}\nmutation {how}\nargv {argv}\n"
                                                f"exit {rc} hung {hung}\n--- output\n{text}")
    return counts, findings


RICH_TYPES = re.compile(r"^(cdr_test_msgs|sancta_test_msgs)::|::(LaserScan|PointCloud2?|Image|"
                        r"CompressedImage|JointState|Marker|MarkerArray|InteractiveMarker\w*|"
                        r"OccupancyGrid|Path|GetPlan_\w+|ParameterDescriptor|ParameterValue|"
                        r"SetParameters\w*|DiagnosticArray|MultiArrayLayout|\w+MultiArray|"
                        r"WString|GoalStatusArray|Odometry|PoseArray|PolygonStamped)_$")
# Types with strings, bounded and unbounded sequences, nested arrays and wide
# strings: half of the typed reader's cases mutate one of them.


def m_cdr_shift(rng, data, kind):
    """Four bytes inserted or removed at an aligned offset: every later field
    is read from the wrong place (counts become data and data counts)."""
    i = rng.randrange(len(data) // 4 + 1) * 4
    if rng.random() < 0.5 and len(data) >= i + 4:
        return data[:i] + data[i + 4:], f"4 bytes removed at {i}"
    v = rng.choice(INTERESTING_32)
    return data[:i] + v.to_bytes(4, "little") + data[i:], f"u32 {v:#x} inserted at {i}"


CDR_MUTATORS = [m_flip, m_truncate, m_word, m_word, m_word, m_delete]
TYPED_MUTATORS = CDR_MUTATORS + [m_cdr_shift, m_cdr_shift]


def cdr_seeds(user=False):
    """(dds_name, payload) of every type: random messages of seeds 1 and 2
    (cdr_tool random), little-endian."""
    seeds = []
    for s in (1, 2):
        out = subprocess.run([str(BIN / "cdr_tool"), "random", str(s)] + (["user"] if user else []),
                             capture_output=True, text=True, check=True, env=env()).stdout
        seeds += [(line.split(" ")[0], bytes.fromhex(line.split(" ")[1]))
                  for line in out.splitlines()]
    return seeds


def mutate_in_batches(rng, cases, pick, mutators, batch, flush, size=500):
    """Mutates `cases` payloads, pick(n) giving case n's (type name, seed
    payload), and hands them to flush() `size` at a time (batch is the list
    flush() reads and clears)."""
    for n in range(cases):
        name, seed_data = pick(n)
        data, how = mutate_cdr(rng, seed_data, mutators)
        batch.append((name, data, how))
        if len(batch) == size:
            flush()
    if batch:
        flush()


def mutate_cdr(rng, seed_data, mutators):
    """Mutations of the body (after the 4-byte encapsulation header); one
    case in ten also gets another header."""
    data = seed_data
    hows = []
    for _ in range(rng.choice([1, 1, 2, 3])):
        body, how = rng.choice(mutators)(rng, data[4:], "binary")
        data = data[:4] + body
        hows.append(how)
    if len(data) >= 4 and rng.random() < 0.1:
        # Big-endian (the body is read with the other byte order), other
        # representations (PL_CDR, XCDR2, unknown), options bits.
        header = rng.choice([b"\x00\x00\x00\x00", b"\x00\x00\x00\x00", b"\x00\x01\x00\x03",
                             b"\x00\x02\x00\x00", b"\x00\x03\x00\x00", b"\x00\x06\x00\x00",
                             b"\x00\x07\x00\x00", b"\x00\x0a\x00\x00", b"\x01\x01\x00\x00",
                             b"\xff\xff\xff\xff"])
        data = header + data[4:]
        hows.append(f"header {header.hex()}")
    return data, "; ".join(hows)


def fuzz_cdr(rng, cases, keep, log):
    """CDR payloads of every bundled type (cdr_tool random), mutated and
    decoded by the dynamic decoder in batches (cdr_tool reencode): a line
    must re-encode or say ERROR (Decode_Error) with a byte offset; INTERNAL,
    a crash or a hang is a finding."""
    tool = str(BIN / "cdr_tool")
    seeds = cdr_seeds()
    counts = {}
    findings = []
    batch = []

    def flush():
        lines = "".join(f"{name} {data.hex()}\n" for name, data, _ in batch).encode()
        rc, text, hung, _ = run([tool, "reencode"], 120, stdin=lines)
        outs = text.splitlines()
        if rc != 0 or hung or len(outs) != len(batch):
            # Find the culprit(s) one at a time.
            for name, data, how in batch:
                rc1, t1, h1, _ = run([tool, "reencode"], 10,
                                     stdin=f"{name} {data.hex()}\n".encode())
                v = "hang" if h1 else (f"signal {-rc1}" if rc1 < 0 else
                                       ("exception" if rc1 != 0 or TRACE.search(t1) else None))
                record(v, name, data, how, t1)
        else:
            for (name, data, how), line in zip(batch, outs):
                # A refusal names the field and the byte offset.
                record("exception" if TRACE.search(line) else
                       ("no location" if " ERROR " in line and " byte" not in line else None),
                       name, data, how, line)
        batch.clear()

    def record(v, name, data, how, text):
        record_cdr_case(counts, findings, keep, log, "cdr", v, name, data, how, text)

    mutate_in_batches(rng, cases, lambda n: seeds[rng.randrange(len(seeds))], CDR_MUTATORS,
                      batch, flush)
    return counts, findings


def record_cdr_case(counts, findings, keep, log, reader, v, name, data, how, text):
    # "ok" splits into refused and re-encoded (how much of the decoders the
    # cases reach).
    ok = "refused" if " ERROR " in text else "decoded"
    counts[v or ok] = counts.get(v or ok, 0) + 1
    if v:
        findings.append((v, name, how, [text.strip()[:300]]))
        log.write(f"{reader} {v}: {name} {data.hex()} ({how})\n   {text.strip()[:300]}\n")
        log.flush()
        if keep:
            d = keep / reader
            d.mkdir(parents=True, exist_ok=True)
            with open(d / "findings.txt", "a") as f:
                f.write(f"{name} {data.hex()}\n# {how}: {text.strip()[:300]}\n")


TYPED_REFUSAL = re.compile(r"^\S+ ERROR (\w+/(msg|srv|action)/\w+[.:].* at byte offset \d+"
                           r"|.*encapsulation.* at byte offset 0$)")
# "NAME ERROR pkg/msg/Type.field: problem at byte offset N", or a refused
# encapsulation header (the same words as the dynamic decoder's).


def typed_verdict(typed, dynamic):
    """Compares one payload's lines from `cdr_tool reencode typed` (the
    generated codecs) and `cdr_tool reencode user` (the dynamic codec, the
    reference): the same answer (same re-encoding, or both refuse), and a
    typed refusal names the type, the field and the byte offset."""
    if TRACE.search(typed):
        return "exception"
    if typed.endswith(" NONE"):
        return None
        # No generated codec for this type (e.g. a user interface found on
        # the interface path): nothing to compare.
    t_refused, d_refused = " ERROR " in typed, " ERROR " in dynamic
    if t_refused and not TYPED_REFUSAL.search(typed):
        return "no location"
    if t_refused != d_refused:
        return "typed refused only" if t_refused else "typed accepted only"
    if not t_refused and typed != dynamic:
        return "differ"
    return None


def fuzz_typed(rng, cases, keep, log):
    """The generated (typed) codecs: mutated payloads of every generated
    type, half of them of types with strings, sequences, nested arrays or
    wide strings, decoded through ROSIDL.Static (cdr_tool reencode typed) and
    compared with the dynamic decoder on the same bytes."""
    tool = str(BIN / "cdr_tool")
    seeds = cdr_seeds(user=True)
    rich = [s for s in seeds if RICH_TYPES.search(s[0])]
    counts = {}
    findings = []
    batch = []

    def decode(mode, lines, timeout):
        rc, text, hung, _ = run([tool, "reencode", mode], timeout, stdin=lines)
        return rc, text.splitlines(), hung

    def flush():
        lines = "".join(f"{name} {data.hex()}\n" for name, data, _ in batch).encode()
        rc_t, typed, hung_t = decode("typed", lines, 120)
        rc_d, dynamic, hung_d = decode("user", lines, 120)
        if (rc_t != 0 or hung_t or len(typed) != len(batch)
                or rc_d != 0 or hung_d or len(dynamic) != len(batch)):
            for name, data, how in batch:
                one = f"{name} {data.hex()}\n".encode()
                rc1, t1, h1 = decode("typed", one, 10)
                _, d1, _ = decode("user", one, 10)
                v = ("hang" if h1 else f"signal {-rc1}" if rc1 < 0 else
                     "exception" if rc1 != 0 or len(t1) != 1 else
                     typed_verdict(t1[0], d1[0] if d1 else ""))
                record(v, name, data, how, " / ".join(t1 + d1))
        else:
            for (name, data, how), t, d in zip(batch, typed, dynamic):
                v = typed_verdict(t, d)
                record(v, name, data, how, t if v in (None, "exception", "no location")
                       else f"typed: {t[:150]} / dynamic: {d[:150]}")
        batch.clear()

    def record(v, name, data, how, text):
        record_cdr_case(counts, findings, keep, log, "typed", v, name, data, how, text)

    def pick(n):
        pool = rich if rich and n % 2 == 0 else seeds
        return pool[rng.randrange(len(pool))]

    mutate_in_batches(rng, cases, pick, TYPED_MUTATORS, batch, flush)
    return counts, findings


# ---------------------------------------------------------------- command lines

def cpu_seconds(pid):
    """User + system CPU time of a running process (Linux /proc)."""
    try:
        fields = pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, IndexError, ValueError):
        return 0.0


def run_until_ready(argv, timeout, ready, quiet_after=None):
    """Runs argv until it ends, prints a line matching `ready` (then it is
    stopped with SIGINT, SIGKILL after 3 s: a node that spins) or the time
    limit (a hang). With quiet_after, a program still running and idle
    after that many seconds counts as ready (its log may be off or its
    level above info: nothing to match).
    (exit status, output, hung, was ready)."""
    import select
    p = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         stdin=subprocess.DEVNULL, env=env(), start_new_session=True)
    out = b""
    began = time.monotonic()
    was_ready = ended = False
    while not (was_ready or ended):
        left = began + timeout - time.monotonic()
        if left <= 0:
            break
        r, _, _ = select.select([p.stdout], [], [], min(left, 0.2))
        if r:
            chunk = os.read(p.stdout.fileno(), 65536)
            out += chunk
            ended = not chunk
            if ready.search(out.decode("utf-8", "replace")):
                was_ready = True
                time.sleep(0.1)  # the first lines after "ready"
        if quiet_after is not None and time.monotonic() - began > quiet_after:
            # Still running, silent: ready when idle (a node waiting for
            # work), a hang when busy (over half a CPU since it started).
            was_ready = p.poll() is None and cpu_seconds(p.pid) < 0.5 * quiet_after
            break
    if not ended:
        try:
            os.killpg(p.pid, signal.SIGINT)
        except ProcessLookupError:
            pass
    try:
        rest, _ = p.communicate(timeout=3)
        hung = not (was_ready or ended)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        rest, _ = p.communicate()
        hung = True  # ended its output, or was asked to stop, but did not exit
    out += rest
    return p.returncode, out.decode("utf-8", "replace"), hung, was_ready


ROS_FLAGS = ["--ros-args", "--", "-r", "--remap", "-p", "--param", "--params-file", "-e",
             "--enclave", "--log-level", "--enable-rosout-logs", "--disable-rosout-logs",
             "--enable-stdout-logs", "--disable-stdout-logs", "--log-config-file", "-x",
             "--ros-arg", "-pp", "--remap="]
ROS_VALUES = ["a:=b", "__node:=", "__node:=x", "__ns:=", "__ns:=/a/b", "__name:=n", "__other:=1",
              ":=", "x:=", "rostopic://", "rostopic://a:=b", "rosservice://a:=b", "http://a:=b",
              "n:p:=1", "parameters_demo:rate:=7", "other:rate:=7", "a.b.c:=1", "a..b:=1",
              ".a:=1", "a.:=1", "~/x:=y", "{node}:=z", "{ns}/a:=b", "/a/b:=/c", "1abc:=2",
              "x:=[1,2", "x:={a: 1}", "x:=!!str 1", "x:='", "x:=nan", "x:=-.inf", "x:=0x1F",
              "x:=1_000", "rate:=0", "rate:=101", "rate:=abc", "ids:=[]", "ids:=[1, 'a']",
              "frozen:=false", "gain:=1e400", "debug", "DEBUG", "Fatal", "x:=bogus", "/", "//",
              "", " ", "a b:=1", "n:=", "-p", "--", "parameters_demo:=warn", ":=info"]


def args_seeds():
    """(argument list, parameter file text): {input} is the parameter file."""
    return [
        (["--ros-args", "-p", "rate:=20", "-p", "name:=robot", "-p", "gain:=2.5", "-p",
          "ids:=[4, 5]", "--params-file", "{input}", "--"],
         "parameters_demo:\n  ros__parameters:\n    rate: 15\n    name: \"yaml\"\n"
         "    gain: 0.5\n    ids: [7, 8, 9]\n"),
        (["--ros-args", "-r", "__node:=demo2", "-r", "__ns:=/fuzz", "-r",
          "parameter_events:=events", "--log-level", "warn", "--log-level",
          "fuzz.demo2:=info", "-e", "/enclave", "--params-file", "{input}"],
         "/**:\n  ros__parameters:\n    rate: 12\n    frozen: true\n    nested:\n"
         "      depth: 4\n"),
        (["first", "--ros-args", "-r", "rostopic://chatter:=news", "-r",
          "parameters_demo:rosservice://x:=y", "--disable-rosout-logs", "--enable-stdout-logs",
          "--params-file", "{input}", "-p", "parameters_demo:rate:=30", "--", "last"],
         "{/fuzz/parameters_demo: {ros__parameters: {gain: -0.5e3, name: 'flow', "
         "ids: [1, 2]}}}\n"),
    ]


def m_args(rng, args):
    """One change to an argument list."""
    args = list(args)
    what = rng.randrange(8)
    i = rng.randrange(len(args) + 1)
    if what == 0 and args:
        i = min(i, len(args) - 1)
        del args[i]
        return args, f"argument {i} dropped"
    if what == 1 and args:
        i = min(i, len(args) - 1)
        args.insert(i, args[i])
        return args, f"argument {i} doubled"
    if what == 2 and len(args) > 1:
        a, b = rng.randrange(len(args)), rng.randrange(len(args))
        args[a], args[b] = args[b], args[a]
        return args, f"arguments {a} and {b} swapped"
    if what == 3:
        f = rng.choice(ROS_FLAGS)
        args.insert(i, f)
        return args, f"flag {f!r} inserted at {i}"
    if what == 4:
        v = rng.choice(ROS_VALUES)
        args.insert(i, v)
        return args, f"value {v!r} inserted at {i}"
    if not args:
        return args, "no argument"
    # The text of one argument ({input} is the file: left alone).
    i = min(i, len(args) - 1)
    if args[i] == "{input}":
        return args, "file argument kept"
    data, how = rng.choice([m_flip, m_truncate, m_delete, m_insert_token, m_number,
                            m_number, m_long_line])(rng, args[i].encode(), "args")
    # An argument holds no NUL and at most 128 KB (execve's limit).
    text = data.replace(b"\x00", b"").decode("utf-8", "replace")[:100000]
    args[i] = text
    return args, f"argument {i}: {how}"


ARGS_LOCATED = re.compile(r"--ros-args|input\.yaml:\d+")
# A refusal names the argument ("--ros-args: argument 3 ...", "--ros-args -p
# rate ...") or the parameter file's line ("input.yaml:4:11: ...").
ARGS_UNLOCATED_OK = re.compile(r": no such file|cannot be opened|cannot read")


def fuzz_args(rng, cases, keep, log):
    """--ros-args and --params-file through the argument parser of a node
    program (parameters_demo): mutated argument lists and parameter files.
    A case runs until the node says 'parameters ready' (then it is stopped:
    accepted) or ends; a refusal must name the argument or file:line."""
    seeds = args_seeds()
    ready = re.compile(r"parameters ready")
    counts = {}
    findings = []
    for n in range(cases):
        args, text = seeds[n % len(seeds)]
        hows = []
        for _ in range(rng.choice([1, 1, 2, 3])):
            args, how = m_args(rng, args)
            hows.append(how)
        data = text.encode()
        if rng.random() < 0.3:
            data, how = rng.choice(TEXT_MUTATORS)(rng, data, "yaml")
            hows.append("file: " + how)
        how = "; ".join(hows)
        with tempfile.TemporaryDirectory(prefix="fuzz-") as tmp:
            folder = pathlib.Path(tmp)
            (folder / "input.yaml").write_bytes(data)
            argv = ([str(BIN / "parameters_demo")]
                    + [a.replace("{input}", str(folder / "input.yaml")) for a in args])
            rc, out, hung, was_ready = run_until_ready(argv, 15.0, ready, quiet_after=4.0)
            if hung:
                verdict = "hang"
            elif rc is not None and rc < 0 and not was_ready:
                verdict = f"signal {-rc}"
            elif TRACE.search(out):
                verdict = "exception"
            elif was_ready or rc == 0:
                verdict = None
            elif ARGS_LOCATED.search(out) or ARGS_UNLOCATED_OK.search(out):
                verdict = None
            else:
                verdict = "no location"
            ok = "accepted" if was_ready or rc == 0 else "refused"
            counts[verdict or ok] = counts.get(verdict or ok, 0) + 1
            lines = out.strip().splitlines()
            if VERBOSE:
                log.write(f"args #{n} exit {rc} {verdict or ok}: {how[:120]}\n   "
                          + (lines[-1][:200] if lines else "") + "\n")
            if verdict:
                findings.append((verdict, "args", how, lines[-3:]))
                log.write(f"args #{n} {verdict}: {how}\n   argv {argv[1:]!r}"[:600] + "\n   "
                          + " | ".join(lines[-3:])[:400] + "\n")
                log.flush()
                if keep:
                    d = keep / "args" / f"{n:05d}-{verdict.replace(' ', '_')}"
                    d.mkdir(parents=True, exist_ok=True)
                    shutil.copytree(folder, d, dirs_exist_ok=True)
                    (d / "CASE.txt").write_text(f"mutation {how}\nargv {argv}\nexit {rc}\n"
                                                f"--- output\n{out}")
    return counts, findings


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cases", type=int, default=200, help="cases per reader")
    ap.add_argument("--readers", default="all")
    ap.add_argument("--keep", type=pathlib.Path, default=None)
    ap.add_argument("--log", type=pathlib.Path, default=None)
    ap.add_argument("--verbose", action="store_true", help="log every case")
    args = ap.parse_args()
    global VERBOSE
    VERBOSE = args.verbose
    rng_master = random.Random(args.seed)
    with tempfile.TemporaryDirectory(prefix="fuzz-seeds-") as seeds_tmp:
        readers = build_readers(pathlib.Path(seeds_tmp))
        wanted = None if args.readers == "all" else set(args.readers.split(","))
        log = open(args.log, "a") if args.log else sys.stderr
        table = []
        total_findings = 0
        for reader in readers + ["cdr", "typed", "args", "services", "actions"]:
            name = reader if isinstance(reader, str) else reader.name
            # Each reader its own generator: a reader's cases do not depend on
            # which other readers ran.
            rng = random.Random(f"{args.seed}/{name}")
            if wanted is not None and name not in wanted:
                continue
            began = time.monotonic()
            if reader == "cdr":
                counts, findings = fuzz_cdr(rng, args.cases, args.keep, log)
            elif reader == "typed":
                counts, findings = fuzz_typed(rng, args.cases, args.keep, log)
            elif reader == "args":
                counts, findings = fuzz_args(rng, args.cases, args.keep, log)
            elif reader == "services":
                import fuzz_services
                counts, findings = fuzz_services.fuzz_services(rng, args.cases, args.keep, log)
            elif reader == "actions":
                import fuzz_services
                counts, findings = fuzz_services.fuzz_actions(rng, args.cases, args.keep, log)
            else:
                counts, findings = fuzz_reader(reader, rng, args.cases, args.keep, log)
            total_findings += len(findings)
            table.append((name, sum(counts.values()), counts, time.monotonic() - began))
        del rng_master
        print(f"{'reader':12} {'cases':>6} {'time s':>7}  verdicts")
        for name, n, counts, took in table:
            print(f"{name:12} {n:6d} {took:7.1f}  "
                  + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    return 1 if total_findings else 0


if __name__ == "__main__":
    sys.exit(main())
