"""Python cyclonedds peer of bench/bench-services.sh (rmw_cyclonedds service
conventions, see tests/interop/service_support.py):
   bench_services_peer.py server
   bench_services_peer.py client CALLS THREADS
The client prints "calls=N tasks=T errors=E seconds=S rate=R"."""
import sys
import threading
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "interop"))
import pubsub_support as ps  # noqa: E402
import service_support as ss  # noqa: E402


def server():
    dp = ps.participant()
    srv = ss.Server(dp, "/bench_add")
    while True:
        srv.serve_some()
        time.sleep(0.0001)


def client(calls, threads):
    dp = ps.participant()
    # Every client's reader sees every reply of the topic: a deep history
    # keeps a slow thread's own replies from being pushed out by the others'.
    clients = [ss.Client(dp, "/bench_add", depth=1000) for _ in range(threads)]
    for c in clients:
        c.guid += id(c)
        assert c.wait_for_service(), "no server"
    # This peer's server answers at once (it does not wait for the reply
    # reader as rmw_cyclonedds does): give discovery time to finish.
    time.sleep(1.5)
    errors = [0]
    per = calls // threads

    def work(c, k):
        for i in range(per):
            r = c.call(k * 1000000 + i, 1, timeout=10)
            if r is None or r.sum != k * 1000000 + i + 1:
                errors[0] += 1

    start = time.monotonic()
    ts = [threading.Thread(target=work, args=(c, k)) for k, c in enumerate(clients)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    secs = time.monotonic() - start
    done = per * threads
    print(f"calls={done} tasks={threads} errors={errors[0]} seconds={secs:.3f} "
          f"rate={int(done / secs)}")


if __name__ == "__main__":
    if sys.argv[1] == "server":
        server()
    else:
        client(int(sys.argv[2]), int(sys.argv[3]))
