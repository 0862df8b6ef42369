"""A DDS domain id of this process's own: the flock scheme scripts/env.sh,
tests/interop/conftest.py, scripts/fuzz_inputs.py and the AUnit driver
share, so that parallel runs on one machine never see each other's traffic.

Example:
    import domain_lock
    os.environ["ROS_DOMAIN_ID"] = str(domain_lock.reserve())
"""
import fcntl
import os
import tempfile
from pathlib import Path

_held = None  # (domain, open lock file or None), kept until the process exits


def reserve():
    """A domain id in 1..200 no other run on this machine holds: an flock on
    $TMPDIR/rclada-domain-locks/<id>.lock kept until this process exits.
    Reserved once per process; the pid's own choice if no lock can be taken
    (no flock, read-only temporary folder, 200 runs at once)."""
    global _held
    if _held is not None:
        return _held[0]
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
        _held = (domain, lock)
        return domain
    _held = (start + 1, None)
    return start + 1
