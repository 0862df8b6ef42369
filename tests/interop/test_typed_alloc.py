"""Allocation-free steady state of the typed message path: bin/typed_alloc_check
publishes generated messages and takes them back (decode + callback) on one
node, counting the Ada heap allocations of the program's own code
(__gnat_malloc wrapped at link time; the program first checks that the
counter sees an allocation; calls inside the shared GNAT run time, such as
Unbounded_String's, are not seen). After
warm-up a bounded type (geometry_msgs/Twist) must allocate nothing; the
unbounded LaserScan with unchanged sizes is reported too."""
import re

import pubsub_support as ps


def test_typed_steady_state_allocates_nothing():
    proc = ps.start("typed_alloc_check", 1500)
    out = ps.finish(proc, timeout=60)
    assert proc.returncode == 0, out
    counts = dict(re.findall(r"^(\S+)(?: \(bounded\))?: .*task: (\d+)", out, re.M))
    assert counts.get("geometry_msgs/msg/Twist") == "0", out
    # LaserScan keeps its sequences and strings: no allocation once warm.
    assert counts.get("sensor_msgs/msg/LaserScan") == "0", out
