"""CDR byte-exactness of the Ada codec against an independent encoder.

The Python ``cyclonedds`` package serializes the same IDL types (declared
here with the ROS 2 DDS type names, final extensibility) as XCDR1; its bytes
must equal the Ada encoder's (which adds the final padding to 4 that
``serialize()`` omits), in both byte orders, and each side must decode the
other's bytes. The Ada side is driven through ``bin/cdr_tool`` whose samples
(tests/src/rosidl/rosidl-cdr_samples.adb) hold the same values as SAMPLES.
"""
import os
import subprocess
from dataclasses import dataclass

import pytest
from cyclonedds.idl import IdlStruct, make_idl_struct
from cyclonedds.idl._support import Endianness
from cyclonedds.idl.annotations import final
import cyclonedds.idl.types as t

from ros_types import (Float32MultiArray_, Float64MultiArray_, Header_, LaserScan_,
                       MapMetaData_, MultiArrayDimension_, MultiArrayLayout_,
                       OccupancyGrid_, Odometry_, Point_, Pose_, PoseWithCovariance_,
                       Quaternion_, String_, Time_, Twist_, TwistWithCovariance_, Vector3_,
                       dds)

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = os.path.join(ROOT, "bin", "cdr_tool")


@final
@dataclass
class AddTwoIntsRequestWithHeader(
        IdlStruct, typename=dds("example_interfaces", "AddTwoInts_Request", "srv")):
    # The 16-byte request header (guid, sequence) rmw_cyclonedds puts
    # before the body, declared as members so that the layout matches.
    guid: t.uint64 = 0
    seq: t.int64 = 0
    a: t.int64 = 0
    b: t.int64 = 0


@final
@dataclass
class Everything(IdlStruct, typename=dds("cdr_test_msgs", "Everything")):
    b: bool = False
    by: t.byte = 0
    c: t.char = "\0"
    f32: t.float32 = 0.0
    f64: t.float64 = 0.0
    i8: t.int8 = 0
    u8: t.uint8 = 0
    i16: t.int16 = 0
    u16: t.uint16 = 0
    i32: t.int32 = 0
    u32: t.uint32 = 0
    i64: t.int64 = 0
    u64: t.uint64 = 0
    s: str = ""
    bs: t.bounded_str[10] = ""


@final
@dataclass
class Arrays(IdlStruct, typename=dds("cdr_test_msgs", "Arrays")):
    fixed_i32: t.array[t.int32, 3]
    fixed_f64: t.array[t.float64, 2]
    fixed_strings: t.array[str, 2]
    bounded_u8: t.sequence[t.uint8, 5]
    bounded_f32: t.sequence[t.float32, 3]
    bounded_strings: t.sequence[t.bounded_str[8], 2]
    seq_i16: t.sequence[t.int16]
    points: t.array[Point_, 2]
    bounded_points: t.sequence[Point_, 3]
    flags: t.sequence[bool]
    tail: t.uint8


@final
@dataclass
class Texts(IdlStruct, typename=dds("cdr_test_msgs", "Texts")):
    texts: t.sequence[str]


# Strings YAML must quote or escape (the same list as the Ada sample "texts").
TEXTS = ["", "true", "123", "1.5", "-x", "a: b", "#c", " lead", "trail ", "it's",
         "caf\u00e9", "null", "~", "yes", "y", "0x1F", "tab\there", 'quote"d', "[x]",
         "{y}", "@at", "`b", "%p", "!bang", "&amp", "*star", "|pipe", ">gt", "?q",
         ",comma", "a #b", "a#b", "x:", "1e5", ".5", "+1", "Yes", "NO", "tRue",
         "2023-01-01", "2023-1-1 10:00:00", "0o17", "1_000", ":colon", "-", "- x", "=",
         "<<", "1:30", "1.0e+5", "1.0e5", "---", "--- x", "...", "back\\slash",
         "bell\x07", "del\x7f", ".nan", "-.inf", ".", "0b101", "0777", "09", "plain text"]


def header(sec, nanosec, frame):
    return Header_(stamp=Time_(sec=sec, nanosec=nanosec), frame_id=frame)


SAMPLES = {
    "string_hi": String_(data="hi"),
    "header": header(1_700_000_000, 123_456_789, "base_link"),
    "laser_scan": LaserScan_(
        header=header(10, 500, "laser"), angle_min=-1.5, angle_max=1.5,
        angle_increment=0.25, time_increment=0.001, scan_time=0.1,
        range_min=0.1, range_max=30.0,
        ranges=[i * 0.5 for i in range(1, 14)],
        intensities=[100.0 + i for i in range(1, 14)]),
    "odometry": Odometry_(
        header=header(5, 6, "odom"), child_frame_id="base_link",
        pose=PoseWithCovariance_(
            pose=Pose_(position=Point_(x=1.0, y=2.0, z=3.0),
                      orientation=Quaternion_(x=0.0, y=0.0, z=0.5, w=0.75)),
            covariance=[i * 0.125 for i in range(36)]),
        twist=TwistWithCovariance_(
            twist=Twist_(linear=Vector3_(x=0.5), angular=Vector3_(z=0.25)),
            covariance=[-float(i) for i in range(36)])),
    "occupancy_grid": OccupancyGrid_(
        header=header(1, 2, "map"),
        info=MapMetaData_(
            map_load_time=Time_(sec=3, nanosec=4), resolution=0.05, width=4, height=3,
            origin=Pose_(position=Point_(x=-1.0, y=-2.0, z=0.0),
                        orientation=Quaternion_(w=1.0))),
        data=[(i % 3) * 50 - 1 for i in range(1, 13)]),
    "add_two_ints_request": AddTwoIntsRequestWithHeader(
        guid=0x0102030405060708, seq=42, a=2, b=3),
    "everything": Everything(
        b=True, by=0xAB, c="Z", f32=-2.5, f64=3.125, i8=-8, u8=200, i16=-16000,
        u16=65000, i32=-2_000_000_000, u32=4_000_000_000,
        i64=-9_000_000_000_000_000_000, u64=18_000_000_000_000_000_000,
        s="every", bs="bounded"),
    "arrays": Arrays(
        fixed_i32=[-1, 0, 1], fixed_f64=[0.5, -0.25], fixed_strings=["a", "bcd"],
        bounded_u8=[1, 2, 3], bounded_f32=[1.5], bounded_strings=["x", "yz"],
        seq_i16=[7, -7, 300, -300, 0],
        points=[Point_(x=1.0, y=2.0, z=3.0), Point_(x=-1.0, y=-2.0, z=-3.0)],
        bounded_points=[Point_(x=0.5, y=0.25, z=0.125)],
        flags=[True, False, True], tail=255),
    "texts": Texts(texts=TEXTS),
    "doubles": Float64MultiArray_(
        layout=MultiArrayLayout_(dim=[MultiArrayDimension_(label="x", size=9, stride=9)]),
        data=[0.1, 1e-5, 1e22, 1e16, 123456.789, -2.5, 0.0, -0.0, 1.7976931348623157e308]),
    "floats": Float32MultiArray_(
        data=[0.1, 1e-5, 3e38, 16777216.0, -1.401298464324817e-45, 0.05, 3.4028234663852886e38]),
}


def tool(*args, check=True):
    result = subprocess.run([TOOL, *args], capture_output=True, text=True, timeout=60)
    if check:
        assert result.returncode == 0, result.stderr
    return result


def ada_bytes(name, big=False):
    return bytes.fromhex(tool("encode", name, *(["be"] if big else [])).stdout.strip())


def test_ada_tool_lists_every_python_sample():
    names = tool("list").stdout.split()
    assert set(SAMPLES) <= set(names)


def test_string_hi_vector():
    assert ada_bytes("string_hi").hex() == "000100000300000068690000"


@pytest.mark.parametrize("big", [False, True], ids=["le", "be"])
@pytest.mark.parametrize("name", list(SAMPLES))
def test_ada_encoding_equals_cyclonedds(name, big):
    py = SAMPLES[name].serialize(endianness=Endianness.Big if big else Endianness.Little)
    ada = ada_bytes(name, big)
    assert ada[:len(py)].hex() == py.hex()
    assert len(ada) == (len(py) + 3) // 4 * 4
    assert ada[len(py):] == bytes(len(ada) - len(py))


@pytest.mark.parametrize("big", [False, True], ids=["le", "be"])
@pytest.mark.parametrize("name", list(SAMPLES))
def test_ada_decodes_cyclonedds_bytes(name, big):
    py = SAMPLES[name].serialize(endianness=Endianness.Big if big else Endianness.Little)
    decoded = tool("decode", name, py.hex()).stdout
    expected = tool("image", name).stdout
    if name == "add_two_ints_request":
        first, decoded = decoded.split("\n", 1)
        assert first == "# guid 72623859790382856 seq 42"
    assert decoded == expected


@pytest.mark.parametrize("big", [False, True], ids=["le", "be"])
@pytest.mark.parametrize("name", list(SAMPLES))
def test_cyclonedds_decodes_ada_bytes(name, big):
    cls = type(SAMPLES[name])
    ada = ada_bytes(name, big)
    assert cls.deserialize(ada).serialize() == SAMPLES[name].serialize()


def echo_dict(value):
    """The ordered dictionary ros2 topic echo dumps (rosidl_runtime_py's
    message_to_ordereddict) for a decoded cyclonedds object."""
    if hasattr(value, "__dataclass_fields__"):
        return {name: echo_dict(getattr(value, name)) for name in value.__dataclass_fields__}
    if isinstance(value, (list, tuple)):
        return [echo_dict(v) for v in value]
    return value


@pytest.mark.parametrize(
    "name", ["string_hi", "header", "laser_scan", "odometry", "occupancy_grid", "arrays",
             "texts", "doubles", "floats", "everything"])
def test_image_is_what_ros2_topic_echo_prints(name):
    # Independent rendering: PyYAML with the options ros2 topic echo uses,
    # on the values Python decodes from the Ada bytes (float32 widened).
    import yaml
    obj = type(SAMPLES[name]).deserialize(ada_bytes(name))
    fields = echo_dict(obj)
    if name == "everything":
        # rclpy holds a byte as bytes, which echo turns into its character
        # (cyclonedds gives an int); a char is a 1-character str in both.
        fields["by"] = chr(fields["by"])
    expected = yaml.dump(fields, allow_unicode=True, width=2**31 - 1, sort_keys=False)
    assert tool("image", name).stdout == expected


@pytest.mark.parametrize("name,fmt", [("doubles", "<d"), ("floats", "<f")])
def test_float_images_match_python_repr(name, fmt):
    # Random bit patterns (fixed seed), NaN and infinities included: the Ada
    # image of each value must be PyYAML's (Python's repr, as ros2 topic echo).
    import random
    import struct
    import yaml
    rng = random.Random(20261121)
    size = struct.calcsize(fmt)
    values = [struct.unpack(fmt, rng.getrandbits(8 * size).to_bytes(size, "little"))[0]
              for _ in range(2000)]
    values += [struct.unpack(fmt, struct.pack(fmt, v))[0]
               for v in (float("nan"), float("inf"), -float("inf"), 5e-324, 1e-310, 0.5)]
    msg = type(SAMPLES[name])(data=values)
    decoded = tool("decode", name, msg.serialize().hex()).stdout
    expected = yaml.dump(echo_dict(msg), allow_unicode=True, width=2**31 - 1,
                         sort_keys=False)
    assert decoded == expected


# --- every bundled type -----------------------------------------------------

PRIMITIVES = {
    "bool": bool, "byte": t.uint8, "char": t.uint8, "uint8": t.uint8, "int8": t.int8,
    "int16": t.int16, "uint16": t.uint16, "int32": t.int32, "uint32": t.uint32,
    "int64": t.int64, "uint64": t.uint64, "float32": t.float32, "float64": t.float64,
}


def python_types():
    """cyclonedds classes for every message type the Ada side knows
    (``cdr_tool types``), declared from its field list; None for a type
    holding a wstring (the Python package has none)."""
    fields = {}
    order = []
    for line in tool("types").stdout.splitlines():
        kind, *rest = line.split(" ")
        if kind == "T":
            current = rest[0]
            fields[current] = []
            order.append(current)
        else:
            fields[current].append(rest)
    classes = {}

    def build(name):
        if name in classes:
            return classes[name]
        members = {}
        for fname, kind, collection, size, bound, nested in fields[name]:
            if kind == "wstring":
                classes[name] = None
                return None
            if kind == "message":
                element = build(nested)
                if element is None:
                    classes[name] = None
                    return None
            elif kind == "string":
                element = t.bounded_str[int(bound)] if int(bound) > 0 else str
            else:
                element = PRIMITIVES[kind]
            if collection == "FIXED_ARRAY":
                element = t.array[element, int(size)]
            elif collection == "BOUNDED_SEQUENCE":
                element = t.sequence[element, int(size)]
            elif collection == "UNBOUNDED_SEQUENCE":
                element = t.sequence[element]
            members[fname] = element
        cls = make_idl_struct("T" + str(len(classes)), name, members)
        classes[name] = final(cls)
        return classes[name]

    for name in order:
        build(name)
    return order, classes


def test_every_bundled_type_matches_cyclonedds():
    # Random messages of every type (fixed seeds): Python decodes Ada's bytes
    # and re-encodes them identically (LE and BE), and Ada decodes Python's
    # big-endian bytes and re-encodes them as its own little-endian bytes.
    order, classes = python_types()
    checked = [n for n in order if classes[n] is not None]
    assert len(checked) > 150
    back_lines = []
    expected = {}
    for seed in (1, 2, 3):
        for line in tool("random", str(seed)).stdout.splitlines():
            name, hexs = line.split(" ")
            cls = classes[name]
            if cls is None:
                continue
            ada = bytes.fromhex(hexs)
            value = cls.deserialize(ada)
            py = value.serialize(endianness=Endianness.Little)
            assert ada[:len(py)] == py and len(ada) == (len(py) + 3) // 4 * 4, name
            big = value.serialize(endianness=Endianness.Big)
            back_lines.append(f"{name} {big.hex()}")
            expected[len(back_lines)] = (name, hexs)
    result = subprocess.run([TOOL, "reencode"], input="\n".join(back_lines) + "\n",
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert len(lines) == len(back_lines)
    for i, line in enumerate(lines, start=1):
        assert line == "{} {}".format(*expected[i]), line
