"""Parameters of an Ada node (examples/parameters_demo) through the ROS 2
parameter services and /parameter_events, from a Python cyclonedds peer that
speaks rmw_cyclonedds's service conventions, and through `rclada param`."""
import subprocess
import time
from dataclasses import dataclass, field

from cyclonedds.idl import IdlStruct
from cyclonedds.idl import types
from cyclonedds.idl.annotations import final
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

import pubsub_support as ps
from ros_types import Time_
import service_support as ss


@final
@dataclass
class ParameterValue_(IdlStruct, typename="rcl_interfaces::msg::dds_::ParameterValue_"):
    type: types.uint8 = 0
    bool_value: bool = False
    integer_value: types.int64 = 0
    double_value: types.float64 = 0.0
    string_value: str = ""
    byte_array_value: types.sequence[types.uint8] = field(default_factory=list)
    bool_array_value: types.sequence[bool] = field(default_factory=list)
    integer_array_value: types.sequence[types.int64] = field(default_factory=list)
    double_array_value: types.sequence[types.float64] = field(default_factory=list)
    string_array_value: types.sequence[str] = field(default_factory=list)


@final
@dataclass
class Parameter_(IdlStruct, typename="rcl_interfaces::msg::dds_::Parameter_"):
    name: str
    value: ParameterValue_


@final
@dataclass
class SetParametersResult_(IdlStruct, typename="rcl_interfaces::msg::dds_::SetParametersResult_"):
    successful: bool
    reason: str


@final
@dataclass
class SetParameters_Request_(IdlStruct,
                             typename="rcl_interfaces::srv::dds_::SetParameters_Request_"):
    guid: types.uint64
    seq: types.int64
    parameters: types.sequence[Parameter_]


@final
@dataclass
class SetParameters_Response_(IdlStruct,
                              typename="rcl_interfaces::srv::dds_::SetParameters_Response_"):
    guid: types.uint64
    seq: types.int64
    results: types.sequence[SetParametersResult_]


@final
@dataclass
class GetParameters_Request_(IdlStruct,
                             typename="rcl_interfaces::srv::dds_::GetParameters_Request_"):
    guid: types.uint64
    seq: types.int64
    names: types.sequence[str]


@final
@dataclass
class GetParameters_Response_(IdlStruct,
                              typename="rcl_interfaces::srv::dds_::GetParameters_Response_"):
    guid: types.uint64
    seq: types.int64
    values: types.sequence[ParameterValue_]


@final
@dataclass
class ParameterEvent_(IdlStruct, typename="rcl_interfaces::msg::dds_::ParameterEvent_"):
    stamp: Time_
    node: str
    new_parameters: types.sequence[Parameter_]
    changed_parameters: types.sequence[Parameter_]
    deleted_parameters: types.sequence[Parameter_]


class PyClient:
    """A client of one parameter service of /parameters_demo."""

    def __init__(self, dp, service, req_t, rep_t):
        ident = ss.new_id()
        qos = ss.service_qos(f"clientid={ident};")
        name = f"/parameters_demo/{service}"
        self.writer = DataWriter(dp, Topic(dp, f"rq{name}Request", req_t), qos=qos)
        self.reader = DataReader(dp, Topic(dp, f"rr{name}Reply", rep_t), qos=qos)
        self.rep_t = rep_t
        self.guid = 0xABCDEF
        self.seq = 0

    def call(self, timeout=5.0, **fields):
        assert ps.wait_matched(self.writer) and ps.wait_matched(self.reader)
        time.sleep(0.2)
        self.seq += 1
        self.writer.write(self.writer_type(guid=self.guid, seq=self.seq, **fields))
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            for r in self.reader.take(N=8):
                if isinstance(r, self.rep_t) and r.guid == self.guid and r.seq == self.seq:
                    return r
            time.sleep(0.005)
        return None


def start_demo(*args):
    return ps.start("parameters_demo", *args)


def test_set_and_get_through_services():
    ada = start_demo()
    try:
        dp = ps.participant()
        events = DataReader(dp, Topic(dp, "rt/parameter_events", ParameterEvent_),
                            qos=ps.ros_qos(depth=1000))
        setter = PyClient(dp, "set_parameters", SetParameters_Request_, SetParameters_Response_)
        setter.writer_type = SetParameters_Request_
        getter = PyClient(dp, "get_parameters", GetParameters_Request_, GetParameters_Response_)
        getter.writer_type = GetParameters_Request_
        rep = setter.call(parameters=[
            Parameter_("rate", ParameterValue_(type=2, integer_value=42)),
            Parameter_("rate", ParameterValue_(type=2, integer_value=1000)),
            Parameter_("name", ParameterValue_(type=2, integer_value=1)),
            Parameter_("frozen", ParameterValue_(type=1, bool_value=False)),
            Parameter_("nope", ParameterValue_(type=2, integer_value=1))])
        assert rep is not None, "no reply to set_parameters"
        ok = [r.successful for r in rep.results]
        assert ok == [True, False, False, False, False], rep.results
        assert "1 .. 100" in rep.results[1].reason
        assert "is string, not integer" in rep.results[2].reason
        assert "read-only" in rep.results[3].reason
        assert "not declared" in rep.results[4].reason
        rep = getter.call(names=["rate", "name", "gain", "ids", "nope"])
        assert rep is not None, "no reply to get_parameters"
        v = rep.values
        assert (v[0].type, v[0].integer_value) == (2, 42)
        assert (v[1].type, v[1].string_value) == (4, "demo")
        assert (v[2].type, v[2].double_value) == (3, 1.5)
        assert (v[3].type, list(v[3].integer_array_value)) == (7, [1, 2, 3])
        assert v[4].type == 0
        got = ps.take_until(events, 1, timeout=5)
        changed = [(p.name, p.value.integer_value) for e in got if e.node == "/parameters_demo"
                   for p in e.changed_parameters]
        assert ("rate", 42) in changed, got
    finally:
        out = ss.stop(ada)
    assert "parameter rate = 42" in out, out  # the node itself sees the new value


def test_overrides_from_command_line_and_file(tmp_path):
    f = tmp_path / "params.yaml"
    f.write_text("parameters_demo:\n  ros__parameters:\n    name: from_file\n"
                 "/**:\n  ros__parameters:\n    gain: 3   # an integer for a double\n")
    ada = start_demo("--ros-args", "-p", "rate:=20", "--params-file", str(f))
    try:
        time.sleep(0.5)
    finally:
        out = ss.stop(ada)
    assert "parameter rate = 20" in out, out
    assert "parameter name = from_file" in out, out
    assert "parameter gain = 3.0" in out, out


def test_bad_parameter_file_names_the_place(tmp_path):
    f = tmp_path / "bad.yaml"
    f.write_text("parameters_demo:\n  ros__parameters:\n    rate: [1, 'x']\n")
    ada = start_demo("--ros-args", "--params-file", str(f))
    out = ps.finish(ada)
    assert f"{f}:3:15: a parameter array holds values of one type" in out, out


def test_wrong_override_type_is_reported():
    ada = start_demo("--ros-args", "-p", "rate:=fast")
    out = ps.finish(ada)
    assert "parameter 'rate' of /parameters_demo is integer" in out, out


def rclada(*args):
    p = subprocess.run([str(ps.BIN / "rclada"), *map(str, args)], capture_output=True,
                       text=True, timeout=30)
    return p.returncode, p.stdout, p.stderr


def test_rclada_param_commands():
    ada = start_demo()
    try:
        rc, out, err = rclada("param", "list", "/parameters_demo")
        assert rc == 0, err
        assert out.split() == ["frozen", "gain", "ids", "name", "rate", "use_sim_time"], out
        rc, out, err = rclada("param", "get", "/parameters_demo", "use_sim_time")
        assert out == "Boolean value is: False\n", out
        rc, out, err = rclada("param", "get", "/parameters_demo", "gain")
        assert (rc, out) == (0, "Double value is: 1.5\n"), err
        rc, out, err = rclada("param", "set", "/parameters_demo", "rate", "77")
        assert (rc, out) == (0, "Set parameter successful\n"), err
        rc, out, err = rclada("param", "get", "/parameters_demo", "rate")
        assert out == "Integer value is: 77\n", out
        rc, out, err = rclada("param", "set", "/parameters_demo", "rate", "0")
        assert rc == 1 and "rate must be within 1 .. 100" in err, err
        rc, out, err = rclada("param", "set", "/parameters_demo", "ids", "[4, 5]")
        assert rc == 0, err
        rc, out, err = rclada("param", "get", "/parameters_demo", "ids")
        assert out == "Integer values are: [4, 5]\n", out
        rc, out, err = rclada("param", "describe", "/parameters_demo", "rate")
        assert "Type: integer" in out and "publish rate (Hz)" in out, out
        rc, out, err = rclada("param", "get", "/nobody", "x", "--timeout", "1")
        assert rc == 1 and "Node not found: /nobody" in err, err
    finally:
        ss.stop(ada)


def test_rclada_param_dump_round_trip(tmp_path):
    """param dump writes a ROS 2 parameter file that --params-file reads
    back to the same values."""
    ada = start_demo()
    try:
        assert rclada("param", "set", "/parameters_demo", "name", "it's 'quoted'")[0] == 0
        assert rclada("param", "set", "/parameters_demo", "gain", "0.1")[0] == 0
        rc, dumped, err = rclada("param", "dump", "/parameters_demo")
        assert rc == 0, err
    finally:
        ss.stop(ada)
    assert dumped.startswith("/parameters_demo:\n  ros__parameters:\n"), dumped
    assert "    name: 'it''s ''quoted'''\n" in dumped, dumped
    assert "    ids: [1, 2, 3]\n" in dumped and "    gain: 0.1\n" in dumped, dumped
    f = tmp_path / "dump.yaml"
    # Overrides apply at declaration, to read-only parameters too (as in ROS 2).
    f.write_text(dumped)
    ada = start_demo("--ros-args", "--params-file", str(f))
    try:
        rc, again, err = rclada("param", "dump", "/parameters_demo")
    finally:
        ss.stop(ada)
    assert rc == 0, err
    assert again == dumped
