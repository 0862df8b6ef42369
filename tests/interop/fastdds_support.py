"""The Fast DDS peer of the interoperability suites: tests/fastdds/fastdds_peer
(a Fast DDS 2.9 participant behaving on the wire as an rmw_fastrtps_cpp node),
built on first use by `make -C tests/fastdds` (Debian libfastrtps-dev, g++)
and kept on loopback by share/fastdds-localhost.xml.

    peer = Peer("--node", "talker", "--pub", "/chatter", STRING, payload_file)
    peer.wait_for(lambda line: line == "ready")
    ...
    peer.stop()
"""
import os
import queue
import subprocess
import threading
import time

import pubsub_support as ps

PEER_DIR = ps.REPO / "tests" / "fastdds"
PEER = ps.REPO / "obj" / "fastdds" / "fastdds_peer"
PROFILE = ps.REPO / "share" / "fastdds-localhost.xml"

_built = False


def build():
    """Builds the peer (a no-op when up to date); fails the test if it cannot."""
    global _built
    if not _built:
        result = subprocess.run(["make", "-s", "-C", str(PEER_DIR)], capture_output=True,
                                text=True, timeout=300)
        assert result.returncode == 0, "building the Fast DDS peer failed:\n" + result.stderr
        _built = True
    return PEER


def env():
    return dict(os.environ, FASTRTPS_DEFAULT_PROFILES_FILE=str(PROFILE))


def fnv1a64(data):
    h = 0xcbf29ce484222325
    for b in data:
        h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h


class Peer:
    """A running fastdds_peer; its stdout lines are collected by a thread."""

    def __init__(self, *args):
        self.proc = subprocess.Popen([str(build()), *map(str, args)], env=env(),
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                     text=True)
        self.lines = []
        self._ended = False
        self._queue = queue.Queue()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        for line in self.proc.stdout:
            self._queue.put(line.rstrip("\n"))
        self._queue.put(None)

    def _drain(self, timeout):
        """Collects the next line; False once the peer's output ended."""
        try:
            line = self._queue.get(timeout=timeout) if timeout > 0 else self._queue.get_nowait()
        except queue.Empty:
            return True
        if line is None:
            self._ended = True
            return False
        self.lines.append(line)
        return True

    def wait_for(self, predicate, timeout=15.0):
        """The first line (seen before or arriving within timeout) for which
        predicate holds; None when none came."""
        for line in self.lines:
            if predicate(line):
                return line
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            seen = len(self.lines)
            if not self._drain(min(0.2, max(0.0, deadline - time.monotonic()))):
                break
            for line in self.lines[seen:]:
                if predicate(line):
                    return line
        return None

    def samples(self, topic):
        """(length, fnv1a64, payload bytes or None) of each sample received on topic."""
        result = []
        for line in self.lines:
            parts = line.split(" ")
            if parts[0] == "sample" and parts[1] == topic:
                payload = bytes.fromhex(parts[4]) if len(parts) > 4 else None
                result.append((int(parts[2]), int(parts[3], 16), payload))
        return result

    def stop(self, timeout=10.0):
        if self.proc.poll() is None:
            self.proc.terminate()
        try:
            self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self._reader.join(timeout=2)
        while not self._queue.empty() and self._drain(0):
            pass
        return self.proc.stderr.read()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()
