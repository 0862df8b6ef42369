"""Storage pools (RCL.Allocators): examples/src/allocators_demo.adb gives its
node a GNAT.Debug_Pools pool and receives laser scans of 100, 720, 2000 and
720 ranges; what decoding them allocated must have come from that pool (the
pool prints its totals, as RCLAda's rclada_test_allocators)."""
import re

import pubsub_support as ps


def test_node_pool_receives_the_decoding_allocations():
    proc = ps.start("allocators_demo")
    out = ps.finish(proc, timeout=30)
    assert proc.returncode == 0, out
    assert "received 4 scans" in out, out
    total = int(re.search(r"Total allocated bytes :\s*(\d+)", out).group(1))
    freed = int(re.search(r"Total logically deallocated bytes :\s*(\d+)", out).group(1))
    high = int(re.search(r"High Water Mark:\s*(\d+)", out).group(1))
    # The kept scan grows to 100, 720 then 2000 float32 ranges (4 bytes
    # each, plus a small header per block), freeing the smaller blocks.
    assert total >= 4 * (100 + 720 + 2000), out
    assert freed >= 4 * (100 + 720), out
    assert high >= 4 * 2000, out
