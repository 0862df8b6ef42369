"""The Python references of bench/bench-record.sh and a reader of what was
recorded:
    record_peer.py write PAYLOAD COUNT      the `mcap` package's writer alone
                                            (zstd chunks of 768 KiB, as
                                            RCL.MCAP.Writers) writing COUNT copies
                                            of the CDR payload: "count,bytes,seconds"
    record_peer.py record CASE TOPIC DIR    a Python recorder of TOPIC until
                                            SIGTERM: a `cyclonedds` reader (reliable,
                                            keep all, as ours) taking serialized
                                            samples 256 at a time, as rosbag2 records
                                            them (no decoding), into DIR/DIR_0.mcap
                                            through `mcap` (ros2 profile, zstd)
    record_peer.py sink CASE TOPIC          the same reader writing nothing (the
                                            Python DDS ceiling) until SIGTERM:
                                            "count,first_ns,last_ns" (as check)
    record_peer.py check BAG                -> "count,first_ns,last_ns": the
                                            first publication time, the last
                                            reception (log) time
CASE: 64 (std_msgs/String) or scan (sensor_msgs/LaserScan).
"""
import os
import signal
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


def _reader(case, topic):
    """A reliable keep-all reader of TOPIC (a ROS name) and its wait set."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "interop"))
    from cyclonedds.core import InstanceState, Policy, Qos, ReadCondition, SampleState
    from cyclonedds.core import ViewState, WaitSet
    from cyclonedds.domain import DomainParticipant
    from cyclonedds.sub import DataReader
    from cyclonedds.topic import Topic
    from ros_types import LaserScan_, String_
    dp = DomainParticipant(int(os.environ.get("ROS_DOMAIN_ID", "0")))
    kind = LaserScan_ if case == "scan" else String_
    qos = Qos(Policy.Reliability.Reliable(max_blocking_time=10**9),
              Policy.History.KeepAll, Policy.Durability.Volatile,
              Policy.DataRepresentation(use_cdrv0_representation=True))
    reader = DataReader(dp, Topic(dp, "rt" + topic, kind), qos=qos)
    mask = SampleState.Any | ViewState.Any | InstanceState.Any
    waitset = WaitSet(dp)
    waitset.attach(ReadCondition(reader, mask))
    return dp, reader, waitset, mask


def _receive(case, topic, store):
    """Calls store(cdr_bytes, source_timestamp) for each sample until SIGTERM."""
    from cyclonedds._clayer import ddspy_take
    from cyclonedds.util import duration
    stop = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    _dp, reader, waitset, mask = _reader(case, topic)
    print("ready", flush=True)
    while not stop:
        waitset.wait(duration(milliseconds=100))
        while True:
            # Serialized samples (encapsulation header included), no decoding.
            batch = ddspy_take(reader._ref, mask, 256)
            if isinstance(batch, int) or not batch:
                break
            for data, info in batch:
                if info.valid_data:
                    store(data, info.source_timestamp)


def record(case, topic, bag):
    from mcap.writer import CompressionType, Writer
    type_name = "sensor_msgs/msg/LaserScan" if case == "scan" else "std_msgs/msg/String"
    directory = Path(bag)
    directory.mkdir(parents=True)
    with open(directory / f"{directory.name}_0.mcap", "wb") as f:
        w = Writer(f, chunk_size=768 * 1024, compression=CompressionType.ZSTD)
        w.start(profile="ros2", library="python-mcap")
        schema = w.register_schema(name=type_name, encoding="ros2msg", data=b"")
        channel = w.register_channel(topic=topic, message_encoding="cdr", schema_id=schema,
                                     metadata={"offered_qos_profiles": ""})
        sequence = [0]

        def store(data, source_time):
            sequence[0] += 1
            w.add_message(channel_id=channel, log_time=time.time_ns(), data=data,
                          publish_time=source_time, sequence=sequence[0])
        _receive(case, topic, store)
        w.finish()


def sink(case, topic):
    got = [0, None, 0]

    def store(_data, source_time):
        got[0] += 1
        got[1] = got[1] or source_time
        got[2] = time.time_ns()
    _receive(case, topic, store)
    print(f"{got[0]},{got[1] or 0},{got[2]}")


def check(bag):
    from mcap.reader import make_reader
    count, first, last = 0, None, None
    for path in sorted(Path(bag).glob("*.mcap")):
        with open(path, "rb") as f:
            for _, channel, message in make_reader(f, validate_crcs=True).iter_messages():
                if channel.topic.startswith("/bench_record"):
                    count += 1
                    first = (message.publish_time if first is None
                             else min(first, message.publish_time))
                    last = message.log_time if last is None else max(last, message.log_time)
    print(f"{count},{first or 0},{last or 0}")


if __name__ == "__main__":
    if sys.argv[1] == "write":
        write(sys.argv[2], int(sys.argv[3]))
    elif sys.argv[1] == "record":
        record(sys.argv[2], sys.argv[3], sys.argv[4])
    elif sys.argv[1] == "sink":
        sink(sys.argv[2], sys.argv[3])
    else:
        check(sys.argv[2])
