"""Services and clients: the Ada examples `server` and `client` against a
Python cyclonedds peer that follows rmw_cyclonedds's conventions."""
import time

import pubsub_support as ps
import service_support as ss


def test_python_client_calls_ada_service():
    ss.check_python_client_against("server")


def test_ada_client_calls_python_service():
    srv = ss.Server(ps.participant())
    ada, out = ss.run_client_against(srv.serve_some, "client", 20, 22, 10)
    assert ada.returncode == 0, out
    assert "Got answer: 42" in out, out
    assert srv.answered == 1


def test_missing_service_times_out():
    start = time.monotonic()
    ada = ps.start("client", 1, 2, 1.5, "no_such_service")
    out = ps.finish(ada)
    elapsed = time.monotonic() - start
    assert ada.returncode == 1, out
    assert "RCL_Timeout" in out and "/no_such_service" in out, out
    assert elapsed < 6.0, elapsed


def test_server_answers_only_matched_clients():
    """rmw_cyclonedds's rule: the reply waits (up to 100 ms) for a reply
    reader carrying the requester's clientid; without one it is dropped.
    Our request writer says clientid=A while the only reply reader we have
    says clientid=B: no reply may come. A client whose reader has the same
    id is answered."""
    from cyclonedds.pub import DataWriter
    from cyclonedds.sub import DataReader
    from cyclonedds.topic import Topic
    ada = ps.start("server")
    try:
        dp = ps.participant()
        req_t = Topic(dp, "rq/add_two_intsRequest", ss.AddTwoInts_Request_)
        rep_t = Topic(dp, "rr/add_two_intsReply", ss.AddTwoInts_Response_)
        wr = DataWriter(dp, req_t, qos=ss.service_qos("clientid=aa.1;"))
        rd = DataReader(dp, rep_t, qos=ss.service_qos("clientid=bb.2;"))
        assert ps.wait_matched(wr) and ps.wait_matched(rd)
        time.sleep(0.5)
        wr.write(ss.AddTwoInts_Request_(guid=7, seq=1, a=1, b=2))
        time.sleep(1.0)
        assert [r for r in rd.take(N=10) if isinstance(r, ss.AddTwoInts_Response_)] == []
        good = ss.Client(dp)  # same clientid on both endpoints
        assert good.wait_for_service()
        time.sleep(0.5)
        r = good.call(20, 3)
        assert r is not None and r.sum == 23
    finally:
        out = ss.stop(ada)
    assert "reply dropped" in out, out
