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

The `actions` reader: the peer plays the server of a Fibonacci action
(its three services, its feedback and status topics) for one client run
per case: `rclada action send_goal -f` (RCL.Actions.Clients) and
`typed_fibonacci client` (RCL.Actions.Typed), also with `cancel`. Each call
is answered with 1-4 mutated replies, one to another client, then the true
one; once the goal is accepted, 0-4 mutated feedback messages (two in three
about the client's goal), a valid one and 0-2 mutated status arrays are
published (their first goal the client's two times in three, its status
any int8 one time in three). A client must log every refused reply of its
call before the first that decodes, and every refused feedback about its
goal (or whose goal cannot be read) at the reference's offset, none about
another goal; print every feedback about its goal that decodes, and act on
the first reply that decodes: rejected, the cancel code, the status and the
result, or a clear error naming a status or cancel code that is no such
value. The status topic keeps one array (rcl_action's QoS), so an array may
be replaced unread: a client may log only the refusals of arrays sent (at
their reference offset) and only an entry of its own goal whose status is
no GoalStatus value (naming the value and the goal), nothing else about
the status topic.

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
    problem, detail, first = reply_verdict(resp_type, sent, refusals(REPLY_REFUSAL, text))
    if problem:
        return record(name, problem, how, b"",
                      f"{detail}: {text[-400:]}" if problem == "refusal not logged" else detail)
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


def recorder(counts, findings, keep, log, reader):
    """record(target, verdict, how, data, text): counts a case, logs and
    keeps a finding (verdict not None)."""
    def record(target, verdict, how, data, text):
        ok = ("refused" if text.startswith("ERROR")
              else "rejected" if text == "rejected" else "ok")
        key = verdict or ok
        counts[key] = counts.get(key, 0) + 1
        if verdict:
            findings.append((verdict, target, how, [text.strip()[:300]]))
            log.write(f"{reader} {target} {verdict}: {how[:600]}\n   {data.hex()[:200]}\n"
                      f"   {text.strip()[:1500]}\n")
            log.flush()
            if keep:
                folder = keep / reader
                folder.mkdir(parents=True, exist_ok=True)
                with open(folder / "findings.txt", "a") as f:
                    f.write(f"{target} {verdict}: {how}\n{data.hex()}\n# {text.strip()[:600]}\n")
    return record


def fuzz_services(rng, cases, keep, log):
    """Entry point for fuzz_inputs.py: `cases` requests per server target
    and `cases // 8` client runs per client target (a run takes a second)."""
    os.environ["CYCLONEDDS_URI"] = fi.env()["CYCLONEDDS_URI"]  # loopback only
    d = dds()
    dp = d["domain"].DomainParticipant(int(fi.env()["ROS_DOMAIN_ID"]))
    counts, findings = {}, []
    record = recorder(counts, findings, keep, log, "services")
    for target in SERVERS:
        fuzz_server(d, dp, target, rng, cases, record)
    for target in CLIENTS:
        fuzz_client(d, dp, target, rng, max(1, cases // 8), record)
    return counts, findings


# ---------------------------------------------------------------- actions
# The peer plays an action server (its three services and two topics) for
# one action client run per case.

ACTION = "/fuzz_act"
FIB = "example_interfaces::action::dds_::Fibonacci"
CANCEL = "action_msgs::srv::dds_::CancelGoal"
STATUS = "action_msgs::msg::dds_::GoalStatusArray_"
FEEDBACK = FIB + "_FeedbackMessage_"
ACTION_CLIENTS = [
    # (name, argv, how it prints feedback)
    ("action_client", ["rclada", "action", "send_goal", ACTION,
                       "example_interfaces/action/Fibonacci", "{order: 5}", "-f",
                       "--timeout", "10"], "Feedback:"),
    ("typed_action_client", ["typed_fibonacci", "client", "5", ACTION[1:], "10"],
     "feedback of "),
    ("typed_action_client/cancel", ["typed_fibonacci", "client", "5", ACTION[1:], "10",
                                    "cancel"], "feedback of "),
]
STATUS_NAMES = ["UNKNOWN", "ACCEPTED", "EXECUTING", "CANCELING", "SUCCEEDED", "CANCELED",
                "ABORTED"]
CANCEL_NAMES = ["ERROR_NONE", "ERROR_REJECTED", "ERROR_UNKNOWN_GOAL_ID",
                "ERROR_GOAL_TERMINATED"]
LE = b"\x00\x01\x00\x00"
FEEDBACK_REFUSAL = re.compile(r"dropped a malformed sample on (\S+/_action/feedback): (.*)")
STATUS_REFUSAL = re.compile(r"dropped a malformed sample on (\S+/_action/status): (.*)")
BAD_STATUS = re.compile(r"the status topic gives goal ([0-9a-f]{32}) status (-?\d+), which is "
                        r"no goal status")


def mutate_sample(rng, payload):
    """A mutated topic sample (no request header), as mutate() does the
    body of a reply."""
    body, how = fi.mutate_cdr(rng, payload, fi.TYPED_MUTATORS)
    if len(body) >= 2:
        body = bytes([min(body[0], 1), body[1] | 1 if body[1] < 16 else 1]) + body[2:]
    return padded(body), how


def sample_reference(cases):
    """The dynamic decoder's verdict on each (type, sample): None when it
    decodes, else (error text, byte offset)."""
    if not cases:
        return []
    rc, text, hung, _ = fi.run([str(fi.BIN / "cdr_tool"), "reencode"], 120,
                               stdin="".join(f"{n} {data.hex()}\n" for n, data in cases).encode())
    outs = text.splitlines()
    if rc != 0 or hung or len(outs) != len(cases):
        raise RuntimeError(f"cdr_tool reencode failed: {text[-500:]}")
    answers = []
    for out in outs:
        m = OFFSET.search(out)
        answers.append((out.split(" ERROR ", 1)[1], int(m.group(1)) if m else None)
                       if " ERROR " in out else None)
    return answers


class ActionPeer:
    """The server side of action ACTION: three services, the feedback and
    status topics."""

    def __init__(self, d, dp, action=ACTION):
        self.d = d
        self.send = Peer(d, dp, action + "/_action/send_goal", FIB + "_SendGoal", "server")
        self.result = Peer(d, dp, action + "/_action/get_result", FIB + "_GetResult", "server")
        self.cancel = Peer(d, dp, action + "/_action/cancel_goal", CANCEL, "server")
        qos = d["core"].Qos(d["core"].Policy.History.KeepLast(10),
                            d["core"].Policy.Reliability.Reliable(max_blocking_time=10**9),
                            d["core"].Policy.Durability.Volatile,
                            d["core"].Policy.DataRepresentation(use_cdrv0_representation=True))
        self.feedback = d["pub"].DataWriter(
            dp, d["topic"].Topic(dp, f"rt{action}/_action/feedback", raw_type(d, FEEDBACK)),
            qos=qos)
        status_qos = d["core"].Qos(  # rcl_action's: the client's reader asks for it
            d["core"].Policy.History.KeepLast(1),
            d["core"].Policy.Reliability.Reliable(max_blocking_time=10**9),
            d["core"].Policy.Durability.TransientLocal,
            d["core"].Policy.DataRepresentation(use_cdrv0_representation=True))
        self.status = d["pub"].DataWriter(
            dp, d["topic"].Topic(dp, f"rt{action}/_action/status", raw_type(d, STATUS)),
            qos=status_qos)
        self.last_status = None

    def publish(self, writer, data):
        if self.d["write"](writer._ref, data) < 0:
            raise RuntimeError("raw write failed")
        if writer is self.status:
            self.last_status = data

    def feedback_matched(self, timeout):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.feedback.get_publication_matched_status().current_count > 0:
                return True
            time.sleep(0.05)
        return False


class ActionRun:
    """What the peer sent in one client run, for the verdict."""

    def __init__(self):
        self.replies = {"send_goal": [], "get_result": [], "cancel_goal": []}
        self.feedback = []   # (data, how, own goal id)
        self.status = []
        self.goal = None


def answer_call(rng, peer, run, service, req, seeds, true_body):
    """1-4 mutated replies to the call, one to another client, the true one."""
    h = header_of(req)
    if h is None:
        return None
    guid, seq = h
    sent = run.replies[service]
    for _ in range(rng.randrange(1, 5)):
        data, how = mutate(rng, seeds[rng.randrange(len(seeds))], guid, seq)
        sent.append((data, how, guid))
        peer.write(data)
    other, how = mutate(rng, seeds[rng.randrange(len(seeds))], guid ^ 1, seq)
    sent.append((other, how + "; to another client", guid))
    peer.write(other)
    true = padded(with_header(true_body, guid, seq))
    sent.append((true, "true reply", guid))
    peer.write(true)
    return h


def fuzz_action_client(d, dp, target, rng, cases, record):
    """One client run per case: each call answered as fuzz_client does;
    after the goal is accepted, 0-4 mutated feedback messages (two in three
    about the client's goal), a valid one, 0-2 mutated status arrays; the
    result is answered once the client has printed the feedback it must."""
    name, argv, feedback_mark = target
    seeds = {t: [p for tt, p in fi.cdr_seeds() if tt == t]
             for t in (FIB + "_SendGoal_Response_", FIB + "_GetResult_Response_",
                       CANCEL + "_Response_", FEEDBACK, STATUS)}
    peer = ActionPeer(d, dp)
    for n in range(cases):
        ada = Output([str(fi.BIN / argv[0])] + argv[1:])
        run = ActionRun()
        if peer.last_status is not None:  # transient local: the new client gets it
            run.status.append((peer.last_status, "the last run's last status array"))
        for ends in (peer.send, peer.result, peer.cancel):
            ends.take()  # a former client's late calls
        began = time.monotonic()
        feedback_due = 0
        try:
            while ada.p.poll() is None and time.monotonic() - began < 25:
                for req in peer.send.take():
                    if len(req) >= 36 and run.goal is None:
                        run.goal = req[20:36]
                    if answer_call(rng, peer.send, run, "send_goal", req,
                                   seeds[FIB + "_SendGoal_Response_"],
                                   LE + b"\x01\0\0\0" + struct.pack("<iI", 5, 0)) is None:
                        continue
                    feedback_due = send_feedback(rng, peer, run, seeds)
                for req in peer.cancel.take():
                    answer_call(rng, peer.cancel, run, "cancel_goal", req,
                                seeds[CANCEL + "_Response_"],
                                LE + b"\0\0\0\0" + struct.pack("<I", 1)
                                + (run.goal or bytes(16)) + struct.pack("<iI", 0, 0))
                for req in peer.result.take():
                    # The feedback first (the client prints it as it comes).
                    wait = time.monotonic() + 5
                    while (ada.read(0.05).count(feedback_mark) < feedback_due
                           and time.monotonic() < wait and ada.p.poll() is None):
                        pass
                    answer_call(rng, peer.result, run, "get_result", req,
                                seeds[FIB + "_GetResult_Response_"],
                                LE + b"\x04\0\0\0" + struct.pack("<I6i", 6, 0, 1, 1, 2, 3, 5))
                ada.read(0.02)
            hung = ada.p.poll() is None
        finally:
            text = ada.stop()
        judge_action_client(name, feedback_mark, run, text, hung, ada.p.returncode, record)


def send_feedback(rng, peer, run, seeds):
    """Publishes the mutated and valid feedback and the mutated status
    arrays; returns how many feedback messages the client must print."""
    if not peer.feedback_matched(5):
        return 0
    goal = run.goal or bytes(16)
    for _ in range(rng.randrange(0, 5)):
        seed = seeds[FEEDBACK][rng.randrange(len(seeds[FEEDBACK]))]
        own = rng.random() < 2 / 3
        seed = seed[:4] + (goal if own else os.urandom(16)) + seed[20:]
        data, how = mutate_sample(rng, seed)
        run.feedback.append((data, how + ("" if own else "; another goal"), goal))
        peer.publish(peer.feedback, data)
    valid = LE + goal + struct.pack("<I4i", 4, 0, 1, 1, 2)
    run.feedback.append((valid, "valid feedback", goal))
    peer.publish(peer.feedback, valid)
    for _ in range(rng.randrange(0, 3)):
        seed = seeds[STATUS][rng.randrange(len(seeds[STATUS]))]
        own = len(seed) >= 33 and rng.random() < 2 / 3
        if own:
            seed = seed[:8] + goal + seed[24:]
        if len(seed) >= 33 and rng.random() < 1 / 3:
            seed = seed[:32] + struct.pack("<b", rng.randrange(-128, 128)) + seed[33:]
        data, how = (mutate_sample(rng, seed) if rng.random() < 2 / 3
                     else (padded(seed), "unmutated"))
        run.status.append((data, how + ("; own goal" if own else "")))
        peer.publish(peer.status, data)
    answers = sample_reference([(FEEDBACK, data) for data, _, _ in run.feedback])
    return sum(1 for (data, _, g), a in zip(run.feedback, answers)
               if a is None and data[4:20] == g)


def reply_verdict(resp_type, sent, logged):
    """(problem, detail, first reply of the call that decodes) for the
    replies sent to one client call and the refusals the client logged.
    The replies of the call (its guid and sequence) up to the first that
    decodes: each refused one must be logged. At most: every refused reply
    with the client's guid (any sequence: a late reply is decoded, then
    dropped) and those whose header cannot be read; never one with another
    client's guid. problem is None when the log is right."""
    answers = reference([(resp_type, data) for data, _, _ in sent])
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
        return "no location", " | ".join(logged)[:600], None
    if len(logged) < must:
        return "refusal not logged", f"logged {len(logged)}, expected {must}", None
    if len(logged) > may:
        return ("another client's reply logged",
                f"logged {len(logged)}, at most {may}: " + " | ".join(logged)[:600], None)
    return None, "", first


def first_answer(service, resp_type, sent, lines):
    """(verdict, body of the first reply of the call that decodes) for one
    service's replies and the client's log lines about that service."""
    if not sent:
        return None, None
    logged = [t for t in lines if f"{service}: malformed reply dropped" in t]
    problem, detail, first = reply_verdict(resp_type, sent, logged)
    if problem:
        return f"{service}: {problem} ({detail})", None
    return None, decoded_body(resp_type, first) if first is not None else None


def bad_statuses(data):
    """{(goal id hex, status value)} of the entries of a status array (one
    the reference decodes, little-endian) whose status is no GoalStatus."""
    count = struct.unpack("<I", data[4:8])[0]
    found = set()
    for i in range(min(count, max(0, len(data) - 8) // 28 + 1)):
        at = 8 + 28 * i  # an entry: UUID, Time (8 bytes), int8 status, padding
        if len(data) >= at + 25:
            value = struct.unpack("<b", data[at + 24:at + 25])[0]
            if not 0 <= value < len(STATUS_NAMES):
                found.add((data[at:at + 16].hex(), value))
    return found


def status_verdict(run, lines):
    """None when what the client logged about the status topic is right: a
    refusal of an array sent (at its reference offset) or an entry of its
    own goal with a status that is no GoalStatus value, sent (value and goal
    named); nothing else names the status topic."""
    answers = sample_reference([(STATUS, data) for data, _ in run.status])
    refused = {a[1] for a in answers if a is not None}
    bad = set().union(*[bad_statuses(data) for (data, _), a in zip(run.status, answers)
                        if a is None and data[1] & 1] or [set()])
    own = run.goal.hex() if run.goal else None
    for t in lines:
        refusal, entry = STATUS_REFUSAL.search(t), BAD_STATUS.search(t)
        if refusal:
            if not located(t):
                return "status refusal without location"
            if int(OFFSET.search(t).group(1)) not in refused:
                return f"status refusal at an offset no array sent was refused at ({refused})"
        elif entry:
            if entry.group(1) != own:
                return "the status of another goal reported"
            if (own, int(entry.group(2))) not in bad:
                return f"status {entry.group(2)} reported, not sent"
        elif "/_action/status" in t or "status topic" in t:
            return "status topic message unexplained"
    return None


def judge_action_client(name, feedback_mark, run, text, hung, rc, record):
    sent_all = [x for v in run.replies.values() for x in v]
    how = " | ".join(h for _, h, _ in sent_all + run.feedback)[:600]
    how += "".join(f" | status {h}" for _, h in run.status)[:200]
    if not run.replies["send_goal"]:
        return record(name, "no goal sent", how, b"", text[-300:])
    if hung:
        return record(name, "hang", how, b"", text[-300:])
    if rc is not None and rc < 0:
        return record(name, f"signal {-rc}", how, b"", text[-300:])
    if trace_line(text):
        return record(name, "exception", how, b"", trace_line(text))
    lines = text.splitlines()
    problem = status_verdict(run, lines)
    if problem:
        return record(name, problem, how, b"", text[-400:])
    # Feedback: every refused one about the client's goal (or whose goal
    # cannot be read) logged at the reference's offset, none about another
    # goal; every one about its goal that decodes printed.
    answers = sample_reference([(FEEDBACK, data) for data, _, _ in run.feedback])
    logged = [m.group(2) for m in map(FEEDBACK_REFUSAL.search, lines) if m]
    want = sorted(a[1] for (data, _, g), a in zip(run.feedback, answers)
                  if a is not None and (len(data) < 20 or data[4:20] == g
                                        or data[:2] not in (b"\0\0", b"\0\1")))
    shown = sum(1 for (data, _, g), a in zip(run.feedback, answers)
                if a is None and data[4:20] == g)
    got = sorted(int(OFFSET.search(t).group(1)) for t in logged if OFFSET.search(t))
    # The calls: the first reply of each that decodes decides.
    verdict, send_body = first_answer("send_goal", FIB + "_SendGoal_Response_",
                                      run.replies["send_goal"], lines)
    if verdict:
        return record(name, verdict, how, b"", text[-400:])
    if send_body is None:
        return record(name, "no answer to send_goal", how, b"", text[-300:])
    # A rejected goal's client may stop before the feedback comes: then
    # what it read must be a part of what it would have read.
    accepted = send_body[4] != 0
    if any(not located(t) for t in logged):
        return record(name, "feedback refusal without location", how, b"", " | ".join(logged))
    if got != want and (accepted or any(got.count(o) > want.count(o) for o in got)):
        return record(name, "feedback refusals logged %s, expected %s" % (got, want), how, b"",
                      " | ".join(logged)[:600])
    printed = text.count(feedback_mark)
    if printed != shown and (accepted or printed > shown):
        return record(name, "feedback printed %d times, expected %d" % (printed, shown),
                      how, b"", text[-600:])
    if not accepted:
        ok = "rejected" in text and not run.replies["get_result"]
        return record(name, None if ok else "rejection not reported", how, b"",
                      "rejected" if ok else text[-300:])
    if "cancel" in name:
        verdict, body = first_answer("cancel_goal", CANCEL + "_Response_",
                                     run.replies["cancel_goal"], lines)
        if verdict or body is None:
            return record(name, verdict or "no answer to cancel_goal", how, b"", text[-400:])
        code = struct.unpack("<b", body[4:5])[0]
        if 0 <= code < len(CANCEL_NAMES):
            if f"cancel: {CANCEL_NAMES[code]}" not in text:
                return record(name, f"cancel code {code} not reported", how, b"", text[-300:])
        elif not re.search(rf"cancel_goal.*(?<![\d-]){code}\b", text) or rc == 0:
            return record(name, f"cancel code {code} (not a code) not refused clearly", how, b"",
                          text[-300:])
        else:
            return record(name, None, how, b"", "ERROR cancel code")
    verdict, body = first_answer("get_result", FIB + "_GetResult_Response_",
                                 run.replies["get_result"], lines)
    if verdict or body is None:
        return record(name, verdict or "no answer to get_result", how, b"", text[-400:])
    status = struct.unpack("<b", body[4:5])[0]
    count = struct.unpack("<I", body[8:12])[0]
    sequence = list(struct.unpack(f"<{count}i", body[12:12 + 4 * count]))
    if not 0 <= status < len(STATUS_NAMES):
        if not re.search(rf"get_result.*(?<![\d-]){status}\b", text) or rc == 0:
            return record(name, f"status {status} (not a status) not refused clearly", how, b"",
                          text[-300:])
        return record(name, None, how, b"", "ERROR status")
    if feedback_mark == "Feedback:":
        m = re.search(r"Result:\n(.*?)Goal finished with status: (\w+)", text, re.S)
        printed = [int(x) for x in re.findall(r"-?\d+", m.group(1))] if m else None
        if not m or m.group(2) != STATUS_NAMES[status] or printed != sequence:
            return record(name, "wrong result", how, b"",
                          f"expected {STATUS_NAMES[status]} {sequence}: {text[-300:]}")
    else:
        if status == 0:
            sequence = []  # the typed client's default result for an unknown goal
        want = "[" + ",".join(f" {v}" if v >= 0 else str(v) for v in sequence) + " ]"
        if f"result ({STATUS_NAMES[status]}): {want}" not in text:
            return record(name, "wrong result", how, b"",
                          f"expected result ({STATUS_NAMES[status]}): {want}: {text[-300:]}")
    record(name, None, how, b"", "answered")


def fuzz_actions(rng, cases, keep, log):
    """Entry point for fuzz_inputs.py (reader `actions`): `cases // 4`
    client runs per action client target."""
    os.environ["CYCLONEDDS_URI"] = fi.env()["CYCLONEDDS_URI"]  # loopback only
    d = dds()
    dp = d["domain"].DomainParticipant(int(fi.env()["ROS_DOMAIN_ID"]))
    counts, findings = {}, []
    record = recorder(counts, findings, keep, log, "actions")
    for target in ACTION_CLIENTS:
        fuzz_action_client(d, dp, target, rng, max(1, cases // 4), record)
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
