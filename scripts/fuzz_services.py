"""The `services` reader of scripts/fuzz_inputs.py: bytes from the network
on services. A Python Cyclone DDS peer on loopback writes mutated requests
and replies (raw serialized data, rmw_cyclonedds's conventions: topics
rq/<service>Request and rr/<service>Reply, the 16-byte request header
guid/sequence after the encapsulation header) at the product's servers and
clients:

  servers  examples' server (dynamic, RCL.Services) and typed_server
           (RCL.Services.Typed), AddTwoInts; parameters_demo's parameter
           services (dynamic servers of rcl_interfaces: strings, nested
           sequences); the send_goal / get_result / cancel_goal services of
           fibonacci_server (RCL.Actions) and typed_fibonacci
           (RCL.Actions.Typed)
  clients  examples' client (RCL.Clients) and typed_client
           (RCL.Services.Typed), AddTwoInts; `rclada param get` (RCL.Clients,
           GetParameters replies)

The reference is the dynamic decoder (`cdr_tool reencode`) on the same body.
A server must log every refused request ("malformed request dropped" with
the type and the byte offset, counted from the start of the sample: the
reference's offset + 16) and answer every accepted one, and answer a valid
probe after each batch (it keeps serving). A client must print the answer of
the first reply of its call that decodes (AddTwoInts: that reply's sum, not
another), log the malformed replies to its call that came before it, and
never log a reply addressed to another client. A crash, a hang, an exception
trace, an unlocated refusal, a lost or an extra log line is a finding.

Limits of the peer: Cyclone DDS sends a sample with the sender's byte order
in its encapsulation identifier and builds no valid packet around some
identifiers, and the Python peer writes no sample under 5 bytes; so
big-endian payloads, identifiers FF FF / 01 FF and samples under 8 bytes
are not sent (the cdr and typed readers cover them offline).

    fuzz_services.py TARGET HEX...   replays requests at one server target"""
import os
import re
import select
import signal
import struct
import subprocess
import time
from dataclasses import dataclass

import fuzz_inputs as fi

SERVERS = [
    # (name, argv, service name, service type)
    ("server", ["server", "fuzz_sum"], "/fuzz_sum",
     "example_interfaces::srv::dds_::AddTwoInts"),
    ("typed_server", ["typed_server", "fuzz_sum"], "/fuzz_sum",
     "example_interfaces::srv::dds_::AddTwoInts"),
    ("param_server/set", ["parameters_demo"], "/parameters_demo/set_parameters",
     "rcl_interfaces::srv::dds_::SetParameters"),
    ("param_server/get", ["parameters_demo"], "/parameters_demo/get_parameters",
     "rcl_interfaces::srv::dds_::GetParameters"),
    ("param_server/describe", ["parameters_demo"], "/parameters_demo/describe_parameters",
     "rcl_interfaces::srv::dds_::DescribeParameters"),
    ("action_server/send_goal", ["fibonacci_server", "fuzz_fib", "0.01"],
     "/fuzz_fib/_action/send_goal", "example_interfaces::action::dds_::Fibonacci_SendGoal"),
    ("action_server/get_result", ["fibonacci_server", "fuzz_fib", "0.01"],
     "/fuzz_fib/_action/get_result", "example_interfaces::action::dds_::Fibonacci_GetResult"),
    ("action_server/cancel", ["fibonacci_server", "fuzz_fib", "0.01"],
     "/fuzz_fib/_action/cancel_goal", "action_msgs::srv::dds_::CancelGoal"),
    ("typed_action_server/send_goal", ["typed_fibonacci", "server", "fuzz_fib", "0.01"],
     "/fuzz_fib/_action/send_goal", "example_interfaces::action::dds_::Fibonacci_SendGoal"),
    ("typed_action_server/cancel", ["typed_fibonacci", "server", "fuzz_fib", "0.01"],
     "/fuzz_fib/_action/cancel_goal", "action_msgs::srv::dds_::CancelGoal"),
]

CLIENTS = [
    ("client", ["client", "20", "22", "10", "fuzz_sum"], "/fuzz_sum",
     "example_interfaces::srv::dds_::AddTwoInts"),
    ("typed_client", ["typed_client", "20", "22", "10", "fuzz_sum"], "/fuzz_sum",
     "example_interfaces::srv::dds_::AddTwoInts"),
    ("param_client/get", ["rclada", "param", "get", "/fuzz_peer", "rate", "--timeout", "10"],
     "/fuzz_peer/get_parameters", "rcl_interfaces::srv::dds_::GetParameters"),
]

BATCH = 5
# Mutated requests written before each probe (the readers keep 10 samples).

REQUEST_REFUSAL = re.compile(r"malformed request dropped: (.*)|"
                             r"dropped a malformed sample on \S+: (.*)")
REPLY_REFUSAL = re.compile(r"malformed reply dropped: (.*)")
OFFSET = re.compile(r"at byte offset (\d+)")
TYPE_NAMED = re.compile(r"\w+/(srv|msg|action)/\w+")


def dds():
    """The Cyclone DDS Python modules (imported on first use: the other
    readers do not need them)."""
    from cyclonedds import core, domain, pub, sub, topic
    from cyclonedds._clayer import ddspy_take, ddspy_write
    from cyclonedds.idl import IdlStruct
    from cyclonedds.idl.annotations import final
    from cyclonedds.idl.types import uint8
    return dict(core=core, domain=domain, pub=pub, sub=sub, topic=topic, take=ddspy_take,
                write=ddspy_write, IdlStruct=IdlStruct, final=final, uint8=uint8)


def raw_type(d, dds_name):
    """A Python topic type named dds_name (its layout is never used: samples
    are written and taken as bytes)."""
    @d["final"]
    @dataclass
    class Raw(d["IdlStruct"], typename=dds_name):
        unused: d["uint8"]
    return Raw


class Peer:
    """One end of a service: `side` "client" writes requests and reads
    replies, "server" the reverse."""

    def __init__(self, d, dp, service, srv_type, side):
        self.d = d
        ident = os.urandom(16)
        text = f"{ident[0]:2x}" + "".join(f".{b:x}" for b in ident[1:])
        user = f"{'clientid' if side == 'client' else 'serviceid'}={text};"
        qos = d["core"].Qos(d["core"].Policy.History.KeepLast(10),
                            d["core"].Policy.Reliability.Reliable(max_blocking_time=10**9),
                            d["core"].Policy.Durability.Volatile,
                            d["core"].Policy.DataRepresentation(use_cdrv0_representation=True),
                            d["core"].Policy.Userdata(data=user.encode()))
        rq = d["topic"].Topic(dp, f"rq{service}Request", raw_type(d, srv_type + "_Request_"))
        rr = d["topic"].Topic(dp, f"rr{service}Reply", raw_type(d, srv_type + "_Response_"))
        if side == "client":
            self.writer = d["pub"].DataWriter(dp, rq, qos=qos)
            self.reader = d["sub"].DataReader(dp, rr, qos=qos)
        else:
            self.reader = d["sub"].DataReader(dp, rq, qos=qos)
            self.writer = d["pub"].DataWriter(dp, rr, qos=qos)

    def matched(self, timeout):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if (self.writer.get_publication_matched_status().current_count > 0
                    and self.reader.get_subscription_matched_status().current_count > 0):
                return True
            time.sleep(0.05)
        return False

    def write(self, data):
        if self.d["write"](self.writer._ref, data) < 0:
            raise RuntimeError("raw write failed")

    def take(self):
        """The samples there are, as bytes (invalid samples left out)."""
        c = self.d["core"]
        got = self.d["take"](self.reader._ref,
                             c.SampleState.Any | c.ViewState.Any | c.InstanceState.Any, 64)
        return [data for data, info in got if info.valid_data] if not isinstance(got, int) else []


def header_of(data):
    """(guid, sequence) of a request/reply, or None when cut short or its
    encapsulation is not XCDR1."""
    if len(data) < 20 or data[0] != 0 or data[1] > 1:
        return None
    order = "<" if data[1] == 1 else ">"
    return struct.unpack(order + "Qq", data[4:20])


def with_header(payload, guid, seq):
    """payload (encapsulation + body, little-endian) with a request header."""
    return payload[:4] + struct.pack("<Qq", guid, seq) + payload[4:]


def padded(data):
    """data zero-padded to a multiple of 4 bytes, at least 8 (the Python
    peer cannot write a sample of under 5 bytes)."""
    data = data + b"\0" * (-len(data) % 4)
    return data + b"\0" * max(0, 8 - len(data))


def mutate(rng, payload, guid, seq):
    """A mutated request/reply: the body (after the header) mutated as the
    cdr reader does, one case in six the header region too (cut, flipped)."""
    body, how = fi.mutate_cdr(rng, payload, fi.TYPED_MUTATORS)
    if len(body) >= 2:
        # Cyclone DDS sends the sample with the sender's byte order in the
        # encapsulation identifier (its low bit set here) and builds no
        # valid packet around some others (FF FF, 01 FF): the receiver's bytes
        # are these (big-endian and the rest are covered offline by the cdr
        # and typed readers).
        body = bytes([min(body[0], 1), body[1] | 1 if body[1] < 16 else 1]) + body[2:]
    data = with_header(body, guid, seq)
    if rng.random() < 1 / 6:
        if rng.random() < 0.5:
            cut = rng.randrange(0, 20)
            data, how = data[:cut], how + f"; cut at {cut} (in the header)"
        else:
            i = rng.randrange(4, 20)
            data = data[:i] + bytes([data[i] ^ (1 << rng.randrange(8))]) + data[i + 1:]
            how += f"; header byte {i} flipped"
    return padded(data), how


def reference(cases):
    """The dynamic decoder's verdict on each (type, data) (with header):
    None when it decodes, else (error text, byte offset counted in data)."""
    lines, answers = [], [None] * len(cases)
    for k, (name, data) in enumerate(cases):
        if len(data) < 4 or data[0] != 0 or data[1] > 1:
            answers[k] = ("encapsulation", 0)
        elif len(data) < 20:
            answers[k] = ("request header cut short", 4 if len(data) < 12 else 12)
        else:
            lines.append((k, f"{name} {(data[:4] + data[20:]).hex()}\n"))
    if lines:
        rc, text, hung, _ = fi.run([str(fi.BIN / "cdr_tool"), "reencode"], 120,
                                   stdin="".join(t for _, t in lines).encode())
        outs = text.splitlines()
        if rc != 0 or hung or len(outs) != len(lines):
            raise RuntimeError(f"cdr_tool reencode failed: {text[-500:]}")
        for (k, _), out in zip(lines, outs):
            if " ERROR " in out:
                m = OFFSET.search(out)
                answers[k] = (out.split(" ERROR ", 1)[1], int(m.group(1)) + 16 if m else None)
            else:
                answers[k] = None
    return answers


def decoded_body(name, data):
    """The little-endian re-encoding of data's body (the reference's)."""
    rc, text, _, _ = fi.run([str(fi.BIN / "cdr_tool"), "reencode"], 20,
                            stdin=f"{name} {(data[:4] + data[20:]).hex()}\n".encode())
    return bytes.fromhex(text.split()[1])


class Output:
    """A process's output, read as it comes."""

    def __init__(self, argv):
        self.p = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  stdin=subprocess.DEVNULL, env=fi.env(),
                                  start_new_session=True)
        self.text = ""

    def read(self, wait=0.0):
        deadline = time.monotonic() + wait
        while True:
            r, _, _ = select.select([self.p.stdout], [], [],
                                    max(0.0, deadline - time.monotonic()))
            if not r:
                return self.text
            chunk = os.read(self.p.stdout.fileno(), 65536)
            if not chunk:
                return self.text
            self.text += chunk.decode("utf-8", "replace")

    def stop(self):
        if self.p.poll() is None:
            try:
                os.killpg(self.p.pid, signal.SIGINT)
                self.p.wait(3)
            except subprocess.TimeoutExpired:
                os.killpg(self.p.pid, signal.SIGKILL)
                self.p.wait()
            except ProcessLookupError:
                pass
        self.read(0.2)
        return self.text


def trace_line(text):
    """The first output line with an exception trace, or None. The examples'
    refusal of an AddTwoInts whose sum overflows int64 (their callback raises
    Constraint_Error saying so, the executor logs it and answers nothing) is
    not one."""
    for line in text.splitlines():
        if fi.TRACE.search(line) and "overflows int64" not in line:
            return line
    return None


def refusals(pattern, text):
    return [m.group(1) or (m.group(2) if m.lastindex and m.lastindex > 1 else "")
            for m in pattern.finditer(text)]


def located(line):
    """A refusal names the type and the byte offset."""
    return bool(TYPE_NAMED.search(line) and OFFSET.search(line))


def fuzz_server(d, dp, target, rng, cases, record):
    """Mutated requests at one server, BATCH at a time, each batch followed
    by a valid probe request that must be answered."""
    name, argv, service, srv_type = target
    req_type = srv_type + "_Request_"
    seeds = [p for t, p in fi.cdr_seeds() if t == req_type]
    ada = Output([str(fi.BIN / argv[0])] + argv[1:])
    peer = Peer(d, dp, service, srv_type, "client")
    try:
        if not peer.matched(15):
            record(name, "no match", "", b"", ada.stop()[-300:])
            return
        time.sleep(0.3)
        guid = int.from_bytes(os.urandom(8), "little")
        seq = 0
        done = 0
        while done < cases:
            batch = []
            for _ in range(min(BATCH, cases - done)):
                seq += 1
                data, how = mutate(rng, seeds[rng.randrange(len(seeds))], guid, seq)
                batch.append((data, how))
            answers = reference([(req_type, data) for data, _ in batch])
            seen_before = ada.read()
            for data, _ in batch:
                peer.write(data)
            seq += 1
            probe = padded(with_header(seeds[0], guid, seq))
            peer.write(probe)
            replies, probe_answered = [], False
            deadline = time.monotonic() + 10
            while not probe_answered and time.monotonic() < deadline:
                for r in peer.take():
                    replies.append(header_of(r))
                    probe_answered |= header_of(r) == (guid, seq)
                time.sleep(0.005)
            new = ada.read(0.3)[len(seen_before):]
            done += len(batch)
            if ada.p.poll() is not None or not probe_answered:
                verdict = ("exit" if ada.p.poll() is not None else "hang")
                for data, how in batch:
                    record(name, verdict, how, data, new[-300:])
                break
            judge_requests(name, req_type, batch, answers, replies,
                           refusals(REQUEST_REFUSAL, new),
                           new, record)
    finally:
        text = ada.stop()
        if trace_line(text):
            record(name, "exception", "whole run", b"", trace_line(text))


def judge_requests(name, req_type, batch, answers, replies, logged, new, record):
    """Each refused request logged (located, at the reference's offset),
    each accepted one answered (AddTwoInts: unless a + b overflows, which
    the examples refuse to answer, saying so)."""
    expected = [a for a in answers if a is not None]
    offsets = sorted(a[1] for a in expected if a[1] is not None)
    got_offsets = sorted(int(OFFSET.search(t).group(1)) for t in logged if OFFSET.search(t))
    for (data, how), a in zip(batch, answers):
        if a is None:
            verdict = None
            if header_of(data) not in replies:
                verdict = "accepted, not answered"
                if "AddTwoInts" in req_type:
                    a_, b_ = struct.unpack("<qq", decoded_body(req_type, data)[4:20])
                    if not -2**63 <= a_ + b_ < 2**63 and "overflows int64" in new:
                        verdict = None
            record(name, verdict, how, data, "decoded")
        else:
            record(name, None, how, data, "ERROR " + a[0])
    batch_data = "\n   ".join(data.hex() for data, _ in batch)
    if trace_line(new):
        record(name, "exception", "batch", b"", trace_line(new) + "\n   " + batch_data)
    if len(logged) != len(expected):
        record(name, "refusals logged %d, expected %d" % (len(logged), len(expected)),
               "batch: " + " | ".join(h for _, h in batch), b"",
               new[-600:] + "\n   " + batch_data)
    elif any(not located(t) for t in logged):
        record(name, "no location", "batch", b"", " | ".join(logged)[:600])
    elif got_offsets != offsets and len(got_offsets) == len(logged):
        record(name, "offsets differ", "batch", b"",
               f"logged {got_offsets}, reference {offsets}: " + " | ".join(logged)[:400]
               + "\n   " + batch_data)


def fuzz_client(d, dp, target, rng, cases, record):
    """One client run per case: each request is answered with 1-4 mutated
    replies (its own header), one to another client, then the true reply."""
    name, argv, service, srv_type = target
    resp_type = srv_type + "_Response_"
    seeds = [p for t, p in fi.cdr_seeds() if t == resp_type]
    if "AddTwoInts" in srv_type:
        true_body = padded(b"\x00\x01\x00\x00" + struct.pack("<q", 42))
    else:
        true_body = seeds[0]
    peer = Peer(d, dp, service, srv_type, "server")
    for n in range(cases):
        ada = Output([str(fi.BIN / argv[0])] + argv[1:])
        sent = []  # (data, how, own call)
        began = time.monotonic()
        try:
            while ada.p.poll() is None and time.monotonic() - began < 20:
                for req in peer.take():
                    h = header_of(req)
                    if h is None:
                        continue
                    guid, seq = h
                    for _ in range(rng.randrange(1, 5)):
                        data, how = mutate(rng, seeds[rng.randrange(len(seeds))], guid, seq)
                        sent.append((data, how, guid))
                        peer.write(data)
                    other, how = mutate(rng, seeds[rng.randrange(len(seeds))], guid ^ 1, seq)
                    sent.append((other, how + "; to another client", guid))
                    peer.write(other)
                    peer.write(padded(with_header(true_body, guid, seq)))
                    sent.append((padded(with_header(true_body, guid, seq)), "true reply", guid))
                ada.read(0.02)
            hung = ada.p.poll() is None
        finally:
            text = ada.stop()
        judge_client(name, resp_type, sent, text, hung, ada.p.returncode, record)


def judge_client(name, resp_type, sent, text, hung, rc, record):
    how = " | ".join(h for _, h, _ in sent)[:600]
    if not sent:
        return record(name, "no request", how, b"", text[-300:])
    if hung:
        return record(name, "hang", how, b"", text[-300:])
    if rc is not None and rc < 0:
        return record(name, f"signal {-rc}", how, b"", text[-300:])
    if trace_line(text):
        return record(name, "exception", how, b"", trace_line(text))
    answers = reference([(resp_type, data) for data, _, _ in sent])
    logged = refusals(REPLY_REFUSAL, text)
    # The replies of the call (its guid and sequence) up to the first that
    # decodes: each refused one must be logged. At most: every refused reply
    # with the client's guid (any sequence: a late reply is decoded, then
    # dropped) and those whose header cannot be read; never one with
    # another client's guid.
    must, first = 0, None
    for (data, h, guid), a in zip(sent, answers):
        own = header_of(data) is not None and header_of(data)[0] == guid
        call = own and header_of(data)[1] == header_of(sent[-1][0])[1]
        if call and a is None:
            first = data
            break
        must += call
    may = sum(1 for (data, h, guid), a in zip(sent, answers)
              if a is not None and (header_of(data) is None or header_of(data)[0] == guid))
    if any(not located(t) for t in logged):
        return record(name, "no location", how, b"", " | ".join(logged)[:600])
    if len(logged) < must:
        return record(name, "refusal not logged", how, b"",
                      f"logged {len(logged)}, expected {must}: {text[-400:]}")
    if len(logged) > may:
        return record(name, "another client's reply logged", how, b"",
                      f"logged {len(logged)}, at most {may}: " + " | ".join(logged)[:600])
    if first is None:
        return record(name, "no answer", how, b"", text[-300:])
    if "AddTwoInts" in resp_type:
        body = decoded_body(resp_type, first)
        want = struct.unpack("<q", body[4:12])[0]
        if not re.search(rf"Got answer: ?{want}\b", text):
            return record(name, "wrong answer", how, b"",
                          f"expected {want} (first reply that decodes): {text[-300:]}")
    elif rc != 0 and "answered" not in text:
        return record(name, f"exit {rc}", how, b"", text[-300:])
    record(name, None, how, b"", "answered")


def fuzz_services(rng, cases, keep, log):
    """Entry point for fuzz_inputs.py: `cases` requests per server target
    and `cases // 8` client runs per client target (a run takes a second)."""
    os.environ["CYCLONEDDS_URI"] = fi.env()["CYCLONEDDS_URI"]  # loopback only
    d = dds()
    dp = d["domain"].DomainParticipant(int(fi.env()["ROS_DOMAIN_ID"]))
    counts, findings = {}, []

    def record(target, verdict, how, data, text):
        ok = "refused" if text.startswith("ERROR") else "ok"
        key = verdict or ok
        counts[key] = counts.get(key, 0) + 1
        if verdict:
            findings.append((verdict, target, how, [text.strip()[:300]]))
            log.write(f"services {target} {verdict}: {how[:600]}\n   {data.hex()[:200]}\n"
                      f"   {text.strip()[:1500]}\n")
            log.flush()
            if keep:
                folder = keep / "services"
                folder.mkdir(parents=True, exist_ok=True)
                with open(folder / "findings.txt", "a") as f:
                    f.write(f"{target} {verdict}: {how}\n{data.hex()}\n# {text.strip()[:600]}\n")

    for target in SERVERS:
        fuzz_server(d, dp, target, rng, cases, record)
    for target in CLIENTS:
        fuzz_client(d, dp, target, rng, max(1, cases // 8), record)
    return counts, findings


def replay(target_name, hexes):
    """Writes the given requests (hex, header included) at one server
    target, then prints its output: `fuzz_services.py TARGET HEX...`."""
    os.environ["CYCLONEDDS_URI"] = fi.env()["CYCLONEDDS_URI"]  # loopback only
    d = dds()
    dp = d["domain"].DomainParticipant(int(fi.env()["ROS_DOMAIN_ID"]))
    name, argv, service, srv_type = next(t for t in SERVERS if t[0] == target_name)
    ada = Output([str(fi.BIN / argv[0])] + argv[1:])
    peer = Peer(d, dp, service, srv_type, "client")
    try:
        if peer.matched(15):
            time.sleep(0.3)
            for h in hexes:
                peer.write(bytes.fromhex(h))
            time.sleep(1.0)
            for r in peer.take():
                print("reply", r.hex())
    finally:
        print(ada.stop())


if __name__ == "__main__":
    import sys
    replay(sys.argv[1], sys.argv[2:])
