"""The Python side of bench/bench-messaging.sh: the same runs as
bench/messaging_c.c with the cyclonedds Python package and an IdlStruct
std_msgs/msg/UInt8MultiArray.

    messaging_py.py ping SIZE COUNT | pong | pub SIZE SECONDS | sub
"""
import os
import statistics
import sys
import time
from pathlib import Path

from cyclonedds.core import Policy, Qos, ReadCondition, SampleState, ViewState, InstanceState
from cyclonedds.core import WaitSet
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "interop"))
from ros_types import MultiArrayLayout_, UInt8MultiArray_  # noqa: E402

STOP = 0xFFFFFFFF


def qos(keep_all):
    return Qos(Policy.Reliability.Reliable(max_blocking_time=duration(seconds=10)),
               Policy.History.KeepAll if keep_all else Policy.History.KeepLast(10),
               Policy.Durability.Volatile,
               Policy.DataRepresentation(use_cdrv0_representation=True))


def main():
    dp = DomainParticipant(int(os.environ.get("ROS_DOMAIN_ID", "0")))

    def endpoint(name, writer):
        keep_all = name == "rt/bench_thr"
        t = Topic(dp, name, UInt8MultiArray_)
        return DataWriter(dp, t, qos=qos(keep_all)) if writer else \
            DataReader(dp, t, qos=qos(keep_all))

    def waiter(rd):
        ws = WaitSet(dp)
        ws.attach(ReadCondition(rd, SampleState.Any | ViewState.Any | InstanceState.Any))
        return ws

    def wait_matched(wr):
        for _ in range(2000):
            if wr.get_publication_matched_status().current_count > 0:
                break
            time.sleep(0.005)
        time.sleep(0.3)

    mode = sys.argv[1]
    if mode == "pong":
        rd, wr = endpoint("rt/bench_ping", False), endpoint("rt/bench_pong", True)
        ws = waiter(rd)
        while True:
            samples = [s for s in rd.take(N=16) if isinstance(s, IdlStruct)]
            if not samples:
                ws.wait(duration(seconds=30))
                continue
            stop = False
            for s in samples:
                wr.write(s)
                stop = stop or s.layout.data_offset == STOP
            if stop:
                break
    elif mode == "ping":
        size, count = int(sys.argv[2]), int(sys.argv[3])
        warm = count // 10 + 10
        wr, rd = endpoint("rt/bench_ping", True), endpoint("rt/bench_pong", False)
        ws = waiter(rd)
        wait_matched(wr)
        msg = UInt8MultiArray_(data=bytes(size))
        rtt = []
        for i in range(warm + count):
            t0 = time.perf_counter()
            wr.write(msg)
            while not [s for s in rd.take(N=1) if isinstance(s, IdlStruct)]:
                ws.wait(duration(seconds=10))
            if i >= warm:
                rtt.append(time.perf_counter() - t0)
        rtt.sort()
        print(f"rtt_us {statistics.median(rtt) * 1e6:.2f} {rtt[(count * 99) // 100] * 1e6:.2f}")
        wr.write(UInt8MultiArray_(layout=MultiArrayLayout_(data_offset=STOP)))
        time.sleep(0.2)
    elif mode == "pub":
        size, seconds = int(sys.argv[2]), float(sys.argv[3])
        wr = endpoint("rt/bench_thr", True)
        wait_matched(wr)
        msg = UInt8MultiArray_(data=bytes(size))
        end = time.perf_counter() + seconds
        sent = 0
        while time.perf_counter() < end:
            wr.write(msg)
            sent += 1
        wr.write(UInt8MultiArray_(layout=MultiArrayLayout_(data_offset=STOP)))
        time.sleep(0.5)
        print(f"sent {sent}", file=sys.stderr)
    elif mode == "sub":
        rd = endpoint("rt/bench_thr", False)
        ws = waiter(rd)
        count, nbytes, first, last = 0, 0, 0.0, 0.0
        stop = False
        while not stop:
            samples = [s for s in rd.take(N=64) if isinstance(s, IdlStruct)]
            if not samples:
                ws.wait(duration(seconds=30))
                continue
            for s in samples:
                if s.layout.data_offset == STOP:
                    stop = True
                    continue
                if count == 0:
                    first = time.perf_counter()
                count += 1
                nbytes += len(s.data)
                last = time.perf_counter()
        secs = last - first
        if count > 1 and secs > 0:
            print(f"throughput {(count - 1) / secs:.1f} {nbytes / secs / 1e6:.3f}")
        else:
            print("throughput 0 0")
    else:
        sys.exit("bad mode")


if __name__ == "__main__":
    main()
