"""Raw-bytes interoperability: Ada (bin/raw_chatter, RCL raw pub/sub) and a
Python cyclonedds peer exchange std_msgs/String on rt/chatter."""
import time
from dataclasses import dataclass

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final

import pubsub_support as ps
from ros_types import String_


def test_ada_publisher_to_python_subscriber():
    dp = ps.participant()
    rd = ps.reader(dp, "rt/chatter", String_)
    ada = ps.start("raw_chatter", "pub", 30)
    got = ps.take_until(rd, 3, timeout=15)
    out = ps.finish(ada)
    texts = [s.data for s in got]
    assert len(texts) >= 3, f"no data from Ada; Ada said:\n{out}"
    numbers = [int(t.split(":")[1]) for t in texts]
    assert all(t.startswith("Hello World: ") for t in texts), texts
    assert numbers == sorted(numbers) and len(set(numbers)) == len(numbers), texts


def test_python_publisher_to_ada_subscriber():
    dp = ps.participant()
    wr = ps.writer(dp, "rt/chatter", String_)
    ada = ps.start("raw_chatter", "sub", 3)
    assert ps.wait_matched(wr), "the Ada reader was not discovered"
    sent = []
    deadline = time.monotonic() + 15
    i = 0
    while ada.poll() is None and time.monotonic() < deadline:
        i += 1
        text = f"from python {i} \u00e9"  # UTF-8 bytes pass through unchanged
        wr.write(String_(data=text))
        sent.append(text)
        time.sleep(0.1)
    out = ps.finish(ada)
    heard = [l[len("heard: "):] for l in out.splitlines() if l.startswith("heard: ")]
    assert len(heard) >= 3, out
    assert all(h in sent for h in heard), (heard, sent)


def test_type_name_must_match():
    """A reader of another type name on the same topic gets nothing (and
    does not match): matching is by type name, as ROS 2 does."""

    @final
    @dataclass
    class Other_(IdlStruct, typename="std_msgs::msg::dds_::Other_"):
        data: str

    dp = ps.participant()
    rd = ps.reader(dp, "rt/chatter", Other_)
    ada = ps.start("raw_chatter", "pub", 10)
    got = ps.take_until(rd, 1, timeout=3)
    ps.finish(ada)
    assert got == []
