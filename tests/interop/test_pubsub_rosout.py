"""The slides' listener (bin/listener) receives std_msgs/String from a Python
peer, logs it, and the log record is published on /rosout
(rcl_interfaces/msg/Log, reliable, transient local) where the Python peer
reads it; Ctrl-C (SIGINT) then stops the listener cleanly."""
import signal
import time
from dataclasses import dataclass, field

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import uint8, uint32

import pubsub_support as ps
from ros_types import String_, Time_


@final
@dataclass
class Log_(IdlStruct, typename="rcl_interfaces::msg::dds_::Log_"):
    stamp: Time_ = field(default_factory=Time_)
    level: uint8 = 0
    name: str = ""
    msg: str = ""
    file: str = ""
    function: str = ""
    line: uint32 = 0


def test_listener_logs_to_rosout_and_stops_on_sigint():
    dp = ps.participant()
    wr = ps.writer(dp, "rt/chatter", String_)
    rosout = ps.reader(dp, "rt/rosout", Log_, depth=1000, transient_local=True)
    listener = ps.start("listener")
    assert ps.wait_matched(wr), "listener not discovered"
    logs = []
    deadline = time.monotonic() + 15
    while time.monotonic() < deadline and not any("rosout test" in l.msg for l in logs):
        wr.write(String_(data="rosout test"))
        time.sleep(0.2)
        logs.extend(ps.take(rosout))
    start = time.time()
    listener.send_signal(signal.SIGINT)
    out = ps.finish(listener, timeout=10)
    assert listener.returncode == 0, f"listener exit {listener.returncode}:\n{out}"
    mine = [l for l in logs if l.msg == "Got chatter: 'rosout test'"]
    assert mine, f"no record on /rosout; got {logs}; listener said:\n{out}"
    record = mine[0]
    assert record.name == "listener"
    assert record.level == 20  # INFO
    assert abs(record.stamp.sec - start) < 60
    assert "[INFO] [" in out and "[listener]: Got chatter: 'rosout test'" in out


def test_talker_to_python_and_sigterm():
    """The slides' talker publishes "Hello World: N" (1 Hz) that a Python
    subscriber decodes; SIGTERM stops it cleanly (exit 0)."""
    dp = ps.participant()
    rd = ps.reader(dp, "rt/chatter", String_)
    talker = ps.start("talker")
    got = ps.take_until(rd, 2, timeout=15)
    talker.send_signal(signal.SIGTERM)
    out = ps.finish(talker, timeout=10)
    assert talker.returncode == 0, f"talker exit {talker.returncode}:\n{out}"
    texts = [s.data for s in got]
    assert len(texts) >= 2, f"nothing from the talker:\n{out}"
    numbers = [int(t[len("Hello World: "):]) for t in texts]
    assert all(t.startswith("Hello World: ") for t in texts)
    assert numbers == list(range(numbers[0], numbers[0] + len(numbers)))
