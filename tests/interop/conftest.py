"""Loaded by pytest before the test modules: keeps every DDS participant of
the run on loopback and on a domain id no other run on this machine holds.

scripts/env.sh does the same for the test command; this file covers running
`pytest tests/interop/test_x.py` by hand. The domain is reserved by an flock
on $TMPDIR/rclada-domain-locks/<id>.lock held by this process until it exits
(the same locks env.sh and the AUnit driver take).
"""
import os
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "scripts"))
import domain_lock  # noqa: E402  (scripts/domain_lock.py)

os.environ.setdefault(
    "CYCLONEDDS_URI", "file://" + str(REPO / "share" / "cyclonedds-localhost.xml"))
os.environ.setdefault("ROS_LOCALHOST_ONLY", "1")
if not os.environ.get("ROS_DOMAIN_ID"):
    os.environ["ROS_DOMAIN_ID"] = str(domain_lock.reserve())
