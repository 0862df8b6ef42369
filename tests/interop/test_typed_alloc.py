"""Allocation-free steady state of the typed message path: bin/typed_alloc_check
publishes generated messages and takes them back (decode + callback) on one
node, counting the Ada heap allocations of the program's own code
(__gnat_malloc wrapped at link time; the program first checks that the
counter sees an allocation; calls inside the shared GNAT run time, such as
Unbounded_String's, are not seen). After
warm-up a bounded type (geometry_msgs/Twist) must allocate nothing; the
unbounded LaserScan with unchanged sizes is reported too. Then typed service
calls (example_interfaces/srv/AddTwoInts, bounded): client in the checked task,
typed server on the same node spun by another task; neither the calling task
nor the process may allocate."""
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
    service = re.search(r"^example_interfaces/srv/AddTwoInts \(bounded\): called (\d+), wrong sums (\d+),"
                        r" .*calling task: (\d+) .*serving one included: (\d+)\)", out, re.M)
    assert service, out
    assert service.group(1) == "1500" and service.group(2) == "0", out
    assert service.group(3) == "0" and service.group(4) == "0", out
