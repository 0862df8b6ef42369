"""Loaded by pytest before the test modules: keeps every DDS participant of
the run on loopback and on a domain id no other run on this machine holds.

scripts/env.sh does the same for the test command; this file covers running
`pytest tests/interop/test_x.py` by hand. The domain is reserved by an flock
on $TMPDIR/rclada-domain-locks/<id>.lock held by this process until it exits
(the same locks env.sh and the AUnit driver take).
"""
import fcntl
import os
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
_held_lock = None


def _reserve_domain():
    """Return a free domain id in 1..200 and keep its lock for the run."""
    global _held_lock
    folder = Path(tempfile.gettempdir()) / "rclada-domain-locks"
    try:
        folder.mkdir(exist_ok=True)
        os.chmod(folder, 0o1777)
    except OSError:
        pass
    start = os.getpid() % 200
    for step in range(200):
        domain = (start + step) % 200 + 1
        try:
            lock = open(folder / f"{domain}.lock", "a")
        except OSError:
            continue
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            lock.close()
            continue
        _held_lock = lock
        return domain
    return start + 1


os.environ.setdefault(
    "CYCLONEDDS_URI", "file://" + str(REPO / "share" / "cyclonedds-localhost.xml"))
os.environ.setdefault("ROS_LOCALHOST_ONLY", "1")
if not os.environ.get("ROS_DOMAIN_ID"):
    os.environ["ROS_DOMAIN_ID"] = str(_reserve_domain())
