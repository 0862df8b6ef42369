"""Typed services and clients (RCL.Services.Typed, generated
example_interfaces/srv/AddTwoInts records): the examples `typed_server` and
`typed_client` against a Python cyclonedds peer following rmw_cyclonedds's
conventions, and against the dynamic `server`."""
import threading
import time

import pubsub_support as ps
import service_support as ss


def test_python_client_calls_typed_ada_service():
    ada = ps.start("typed_server")
    try:
        dp = ps.participant()
        cl = ss.Client(dp)
        assert cl.wait_for_service(), "the typed Ada service endpoints were not discovered"
        time.sleep(0.3)
        for a, b in [(2, 3), (-7, 100), (2**40, 2**40)]:
            r = cl.call(a, b)
            assert r is not None, "no reply from the typed Ada server"
            assert r.sum == a + b
            assert r.guid == cl.guid and r.seq == cl.seq
    finally:
        out = ss.stop(ada)
    assert "Incoming request a: 2 b: 3" in out, out


def test_typed_ada_client_calls_python_service():
    dp = ps.participant()
    srv = ss.Server(dp)
    stop = threading.Event()

    def serve():
        while not stop.is_set():
            srv.serve_some()
            time.sleep(0.001)

    t = threading.Thread(target=serve)
    t.start()
    try:
        ada = ps.start("typed_client", 20, 22, 10)
        out = ps.finish(ada)
    finally:
        stop.set()
        t.join()
    assert ada.returncode == 0, out
    assert "Got answer: 42" in out, out
    assert srv.answered == 1


def test_typed_client_calls_dynamic_server():
    server = ps.start("server", "typed_to_dynamic")
    try:
        ada = ps.start("typed_client", -5, 12, 10, "typed_to_dynamic")
        out = ps.finish(ada)
    finally:
        ss.stop(server)
    assert ada.returncode == 0, out
    assert "Got answer: 7" in out, out
