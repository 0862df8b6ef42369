"""Shared helpers of the publish/subscribe interoperability suites.

The Python `cyclonedds` package plays a foreign node following the ROS 2
conventions (topic "rt/<name>", type "<pkg>::msg::dds_::<Name>_", XCDR1,
final types). Every participant stays on loopback: the test runner sets
CYCLONEDDS_URI (share/cyclonedds-localhost.xml) and a per-run ROS_DOMAIN_ID,
which Python's cyclonedds honours too; they are defaulted here when the suite
is run on its own.
"""
import os
import re
import subprocess
import threading
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
BIN = REPO / "bin"

os.environ.setdefault(
    "CYCLONEDDS_URI", "file://" + str(REPO / "share" / "cyclonedds-localhost.xml"))
os.environ.setdefault("ROS_DOMAIN_ID", str(os.getpid() % 200 + 1))
os.environ.setdefault("ROS_LOCALHOST_ONLY", "1")

from cyclonedds.core import Policy, Qos  # noqa: E402
from cyclonedds.domain import DomainParticipant  # noqa: E402
from cyclonedds.idl import IdlStruct  # noqa: E402
from cyclonedds.pub import DataWriter  # noqa: E402
from cyclonedds.sub import DataReader  # noqa: E402
from cyclonedds.topic import Topic  # noqa: E402


def domain_id():
    return int(os.environ["ROS_DOMAIN_ID"])


def participant():
    return DomainParticipant(domain_id())


def ros_qos(reliable=True, depth=10, transient_local=False):
    """The ROS 2 default profile (or a variant), XCDR1 only."""
    policies = [
        Policy.History.KeepLast(depth),
        Policy.Reliability.Reliable(max_blocking_time=10**9) if reliable
        else Policy.Reliability.BestEffort,
        Policy.Durability.TransientLocal if transient_local else Policy.Durability.Volatile,
        Policy.DataRepresentation(use_cdrv0_representation=True),
    ]
    return Qos(*policies)


def writer(dp, name, type_, **qos):
    return DataWriter(dp, Topic(dp, name, type_), qos=ros_qos(**qos))


def reader(dp, name, type_, **qos):
    return DataReader(dp, Topic(dp, name, type_), qos=ros_qos(**qos))


def wait_matched(entity, timeout=10.0):
    """Waits until a writer / reader has a match; True when it has."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if isinstance(entity, DataWriter):
            count = entity.get_publication_matched_status().current_count
        else:
            count = entity.get_subscription_matched_status().current_count
        if count > 0:
            return True
        time.sleep(0.05)
    return False


def take(rd):
    """The valid samples available now (instance state changes, such as the
    writer leaving, come as InvalidSample and are dropped)."""
    return [s for s in rd.take(N=100) if isinstance(s, IdlStruct)]


def take_until(rd, count, timeout=10.0):
    """Takes valid samples until `count` arrived or time is out."""
    got = []
    deadline = time.monotonic() + timeout
    while len(got) < count and time.monotonic() < deadline:
        got.extend(take(rd))
        time.sleep(0.02)
    return got


ECHO_UNTIL_STOPPED = 0
"""The COUNT of `pubsub_peer echo` and `typed_peer echo` (Echo_Peers.Until_Stopped)
that has the peer echo until it is stopped: a test that needs echoes back feeds
it until they came (those sent before the peer's writer and the test's reader
have matched each other are lost), then stops it."""


def start(program, *args):
    exe = BIN / program
    assert exe.exists(), f"{exe} not built (gprbuild -P build_all.gpr)"
    return subprocess.Popen([str(exe), *map(str, args)], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)


class Watched:
    """The output of a program started by start(), collected line by line
    as it comes (a thread reads it), so that a test waits for what the
    program prints instead of a fixed time. stop() ends the program and
    returns all of its output (use it instead of stop(proc))."""

    def __init__(self, proc):
        self.proc = proc
        self._lines = []
        self._lock = threading.Lock()
        self._thread = threading.Thread(target=self._read, daemon=True)
        self._thread.start()

    def _read(self):
        for line in self.proc.stdout:
            with self._lock:
                self._lines.append(line)

    def text(self):
        with self._lock:
            return "".join(self._lines)

    def count(self, pattern):
        """How many lines match the regular expression so far."""
        return len(re.findall(pattern, self.text(), re.M))

    def wait(self, predicate, timeout, feed=None):
        """Waits until predicate(output so far) is true, calling feed()
        (when given) every 50 ms meanwhile; True when it became true."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if predicate(self.text()):
                return True
            if feed is not None:
                feed()
            time.sleep(0.05)
        return predicate(self.text())

    def stop(self, grace=3.0):
        """SIGTERM, then SIGKILL after `grace` seconds; all the output."""
        self.proc.terminate()
        try:
            self.proc.wait(timeout=grace)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self._thread.join(5)
        return self.text()


def finish(proc, timeout=20.0):
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, _ = proc.communicate()
        raise AssertionError(f"{proc.args} did not finish; output:\n{out}")
    return out


def stop(proc, grace=3.0):
    """Ends a long-running program (SIGTERM, then SIGKILL after `grace`
    seconds) and returns its output."""
    proc.terminate()
    try:
        out, _ = proc.communicate(timeout=grace)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, _ = proc.communicate()
    return out
