"""QoS events (RCL.Events), each provoked by a Python peer and observed on
the Ada side (examples/qos_events_demo): incompatible QoS both ways with
rclcpp's warning naming the policy, requested and offered deadline missed,
liveliness changed (a publisher appearing and going), liveliness lost (a
manual-by-topic publisher that stops asserting), matched, message lost (a
sample stamped earlier than the last one, to a subscription ordered by
source timestamp: the only way Cyclone DDS 0.10 loses a sample it received)."""
import time

import pubsub_support as ps
from cyclonedds.core import Policy, Qos
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from ros_types import String_


def start(*args):
    return ps.start("qos_events_demo", *args)


def stop(proc):
    return ps.stop(proc, grace=5)


def qos(reliable=True, deadline=None, lease=None, by_source=False):
    p = [Policy.History.KeepLast(10),
         Policy.Reliability.Reliable(max_blocking_time=10**9) if reliable
         else Policy.Reliability.BestEffort,
         Policy.Durability.Volatile,
         Policy.DataRepresentation(use_cdrv0_representation=True)]
    if deadline:
        p.append(Policy.Deadline(int(deadline * 1e9)))
    if lease:
        p.append(Policy.Liveliness.ManualByTopic(int(lease * 1e9)))
    if by_source:
        p.append(Policy.DestinationOrder.BySourceTimestamp)
    return Qos(*p)


def events(out, kind):
    return [l for l in out.splitlines() if l.startswith(f"event {kind} ")]


def test_requested_incompatible_qos_and_liveliness():
    proc = start("sub", "qos_a", "reliable")
    dp = ps.participant()
    time.sleep(1.5)
    topic = Topic(dp, "rt/qos_a", String_)
    best_effort = DataWriter(dp, topic, qos=qos(reliable=False))
    time.sleep(1.0)
    reliable = DataWriter(dp, topic, qos=qos())
    time.sleep(1.0)
    del reliable
    import gc
    gc.collect()
    time.sleep(1.0)
    out = stop(proc)
    assert ("New publisher discovered on topic '/qos_a', offering incompatible QoS. "
            "No messages will be received from it. Last incompatible policy: "
            "RELIABILITY_QOS_POLICY") in out, out
    inc = events(out, "INCOMPATIBLE_QOS")
    assert inc and "policy=RELIABILITY_QOS_POLICY" in inc[0], out
    alive = events(out, "LIVELINESS_CHANGED")
    assert any("alive=1" in l for l in alive) and "alive=0" in alive[-1], out
    matched = events(out, "MATCHED")
    assert any("current=1" in l for l in matched) and "current=0" in matched[-1], out
    del best_effort


def test_offered_incompatible_qos():
    proc = start("pub", "qos_b", "best_effort")
    dp = ps.participant()
    time.sleep(1.5)
    reader = DataReader(dp, Topic(dp, "rt/qos_b", String_), qos=qos())
    time.sleep(1.5)
    out = stop(proc)
    assert ("New subscription discovered on topic '/qos_b', requesting incompatible QoS. "
            "No messages will be sent to it. Last incompatible policy: "
            "RELIABILITY_QOS_POLICY") in out, out
    assert events(out, "INCOMPATIBLE_QOS"), out
    del reader


def test_deadlines_missed():
    sub = start("sub", "qos_c", "reliable", "0.2")
    pub = start("pub", "qos_d", "reliable", "0.2", "5.0")
    dp = ps.participant()
    time.sleep(1.0)
    w = DataWriter(dp, Topic(dp, "rt/qos_c", String_), qos=qos(deadline=0.2))
    r = DataReader(dp, Topic(dp, "rt/qos_d", String_), qos=qos(deadline=0.5))
    assert ps.wait_matched(w, 10)
    w.write(String_(data="once"))
    time.sleep(2.0)
    out_sub, out_pub = stop(sub), stop(pub)
    missed = events(out_sub, "DEADLINE_MISSED")
    assert missed and int(missed[-1].split("total=")[1].split()[0]) >= 3, out_sub
    assert events(out_pub, "DEADLINE_MISSED"), out_pub
    del w, r


def test_liveliness_lost():
    pub = start("pub", "qos_e", "reliable", "0", "0.2", "0.5")
    dp = ps.participant()
    r = DataReader(dp, Topic(dp, "rt/qos_e", String_), qos=qos(lease=1.0))
    assert ps.wait_matched(r, 10)
    time.sleep(1.0)
    stop(pub)
    pub = start("pub", "qos_e", "reliable", "0", "60", "0.3")
    time.sleep(2.5)
    out = stop(pub)
    assert events(out, "LIVELINESS_LOST"), out
    del r


def test_message_lost():
    sub = ps.Watched(start("sub", "qos_f", "reliable", "0", "1.0", "0", "by_source"))
    dp = ps.participant()
    w = DataWriter(dp, Topic(dp, "rt/qos_f", String_), qos=qos(by_source=True))
    try:
        assert ps.wait_matched(w, 10)
        # The demo's side of the match too: its MATCHED event.
        assert sub.wait(lambda out: any("current=1" in l for l in events(out, "MATCHED")), 10), \
            "qos_events_demo's subscription did not report the match:\n" + sub.text()
        now = time.time_ns()
        w.write(String_(data="now"), timestamp=now)
        w.write(String_(data="a second ago"), timestamp=now - 10**9)   # lost
        w.write(String_(data="later"), timestamp=now + 10**6)
        w.write(String_(data="two seconds ago"), timestamp=now - 2 * 10**9)   # lost
        assert sub.wait(lambda out: any("total=2" in l for l in events(out, "MESSAGE_LOST")),
                        10), "qos_events_demo did not report 2 lost messages:\n" + sub.text()
        time.sleep(0.5)  # no third loss may follow
    finally:
        out = sub.stop(grace=5)
    lost = events(out, "MESSAGE_LOST")
    assert lost and "total=2" in lost[-1], out
    assert not events(out, "INCOMPATIBLE_QOS"), out
    del w


def test_message_lost_needs_a_publisher_offering_source_order():
    sub = start("sub", "qos_g", "reliable", "0", "1.0", "0", "by_source")
    dp = ps.participant()
    time.sleep(1.5)
    w = DataWriter(dp, Topic(dp, "rt/qos_g", String_), qos=qos())
    time.sleep(1.5)
    out = stop(sub)
    inc = events(out, "INCOMPATIBLE_QOS")
    assert inc and "policy=DESTINATION_ORDER_QOS_POLICY" in inc[0], out
    del w
