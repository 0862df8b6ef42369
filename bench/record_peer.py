"""The Python reference of bench/bench-record.sh: the `mcap` package's writer
(zstd chunks of 768 KiB, as RCL.MCAP.Writers) writing COUNT copies of the
same CDR payload, and a reader of a recorded bag.
    record_peer.py write PAYLOAD COUNT      -> "count,bytes,seconds"
    record_peer.py check BAG                -> "count,first_ns,last_ns"
"""
import sys
import time
from pathlib import Path


def write(payload, count):
    from mcap.writer import CompressionType, Writer
    data = Path(payload).read_bytes()
    out = Path("/tmp/bench_record_python.mcap")
    start = time.perf_counter()
    with open(out, "wb") as f:
        w = Writer(f, chunk_size=768 * 1024, compression=CompressionType.ZSTD)
        w.start(profile="ros2", library="python-mcap")
        schema = w.register_schema(name="bench/msg/Payload", encoding="ros2msg", data=b"")
        channel = w.register_channel(topic="/bench", message_encoding="cdr", schema_id=schema,
                                     metadata={"offered_qos_profiles": ""})
        stamp = 1_700_000_000_000_000_000
        for i in range(count):
            stamp += 1000
            w.add_message(channel_id=channel, log_time=stamp, data=data, publish_time=stamp,
                          sequence=i)
        w.finish()
    seconds = time.perf_counter() - start
    out.unlink()
    print(f"{count},{len(data)},{seconds:.6f}")


def check(bag):
    from mcap.reader import make_reader
    count, first, last = 0, None, None
    for path in sorted(Path(bag).glob("*.mcap")):
        with open(path, "rb") as f:
            for _, channel, message in make_reader(f, validate_crcs=True).iter_messages():
                if channel.topic.startswith("/bench_record"):
                    count += 1
                    first = message.log_time if first is None else min(first, message.log_time)
                    last = message.log_time if last is None else max(last, message.log_time)
    print(f"{count},{first or 0},{last or 0}")


if __name__ == "__main__":
    if sys.argv[1] == "write":
        write(sys.argv[2], int(sys.argv[3]))
    else:
        check(sys.argv[2])
