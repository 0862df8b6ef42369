"""The ROS 2 message types the Python interop and benchmark peers share,
declared once as cyclonedds ``IdlStruct`` classes with the ROS 2 DDS type
names (``<pkg>::msg::dds_::<Name>_``) and final extensibility, the way
rmw_cyclonedds_cpp declares them. Field lists follow the ROS 2 .msg files.

Types used by only one suite (rcl_interfaces, rmw_dds_common, the
simulator's control service, CDR test types) stay in that suite."""
from dataclasses import dataclass, field

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import array, float32, float64, int8, int32, sequence, uint8, uint32


def dds(pkg, name, kind="msg"):
    """The DDS type name of ROS 2 type pkg/kind/name."""
    return f"{pkg}::{kind}::dds_::{name}_"


# --- builtin_interfaces, rosgraph_msgs, std_msgs ------------------------------

@final
@dataclass
class Time_(IdlStruct, typename=dds("builtin_interfaces", "Time")):
    sec: int32 = 0
    nanosec: uint32 = 0


@final
@dataclass
class Clock_(IdlStruct, typename=dds("rosgraph_msgs", "Clock")):
    clock: Time_ = field(default_factory=Time_)


@final
@dataclass
class String_(IdlStruct, typename=dds("std_msgs", "String")):
    data: str = ""


@final
@dataclass
class Float64_(IdlStruct, typename=dds("std_msgs", "Float64")):
    data: float64 = 0.0


@final
@dataclass
class Header_(IdlStruct, typename=dds("std_msgs", "Header")):
    stamp: Time_ = field(default_factory=Time_)
    frame_id: str = ""


@final
@dataclass
class MultiArrayDimension_(IdlStruct, typename=dds("std_msgs", "MultiArrayDimension")):
    label: str = ""
    size: uint32 = 0
    stride: uint32 = 0


@final
@dataclass
class MultiArrayLayout_(IdlStruct, typename=dds("std_msgs", "MultiArrayLayout")):
    dim: sequence[MultiArrayDimension_] = field(default_factory=list)
    data_offset: uint32 = 0


@final
@dataclass
class Float64MultiArray_(IdlStruct, typename=dds("std_msgs", "Float64MultiArray")):
    layout: MultiArrayLayout_ = field(default_factory=MultiArrayLayout_)
    data: sequence[float64] = field(default_factory=list)


@final
@dataclass
class Float32MultiArray_(IdlStruct, typename=dds("std_msgs", "Float32MultiArray")):
    layout: MultiArrayLayout_ = field(default_factory=MultiArrayLayout_)
    data: sequence[float32] = field(default_factory=list)


@final
@dataclass
class UInt8MultiArray_(IdlStruct, typename=dds("std_msgs", "UInt8MultiArray")):
    layout: MultiArrayLayout_ = field(default_factory=MultiArrayLayout_)
    data: sequence[uint8] = field(default_factory=list)


# --- sensor_msgs --------------------------------------------------------------

@final
@dataclass
class LaserScan_(IdlStruct, typename=dds("sensor_msgs", "LaserScan")):
    header: Header_ = field(default_factory=Header_)
    angle_min: float32 = 0.0
    angle_max: float32 = 0.0
    angle_increment: float32 = 0.0
    time_increment: float32 = 0.0
    scan_time: float32 = 0.0
    range_min: float32 = 0.0
    range_max: float32 = 0.0
    ranges: sequence[float32] = field(default_factory=list)
    intensities: sequence[float32] = field(default_factory=list)


# --- geometry_msgs ------------------------------------------------------------

@final
@dataclass
class Vector3_(IdlStruct, typename=dds("geometry_msgs", "Vector3")):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0


@final
@dataclass
class Twist_(IdlStruct, typename=dds("geometry_msgs", "Twist")):
    linear: Vector3_ = field(default_factory=Vector3_)
    angular: Vector3_ = field(default_factory=Vector3_)


@final
@dataclass
class Point_(IdlStruct, typename=dds("geometry_msgs", "Point")):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0


@final
@dataclass
class Quaternion_(IdlStruct, typename=dds("geometry_msgs", "Quaternion")):
    x: float64 = 0.0
    y: float64 = 0.0
    z: float64 = 0.0
    w: float64 = 1.0


@final
@dataclass
class Pose_(IdlStruct, typename=dds("geometry_msgs", "Pose")):
    position: Point_ = field(default_factory=Point_)
    orientation: Quaternion_ = field(default_factory=Quaternion_)


@final
@dataclass
class PoseStamped_(IdlStruct, typename=dds("geometry_msgs", "PoseStamped")):
    header: Header_ = field(default_factory=Header_)
    pose: Pose_ = field(default_factory=Pose_)


@final
@dataclass
class PoseWithCovariance_(IdlStruct, typename=dds("geometry_msgs", "PoseWithCovariance")):
    pose: Pose_ = field(default_factory=Pose_)
    covariance: array[float64, 36] = field(default_factory=lambda: [0.0] * 36)


@final
@dataclass
class PoseWithCovarianceStamped_(
        IdlStruct, typename=dds("geometry_msgs", "PoseWithCovarianceStamped")):
    header: Header_ = field(default_factory=Header_)
    pose: PoseWithCovariance_ = field(default_factory=PoseWithCovariance_)


@final
@dataclass
class TwistWithCovariance_(IdlStruct, typename=dds("geometry_msgs", "TwistWithCovariance")):
    twist: Twist_ = field(default_factory=Twist_)
    covariance: array[float64, 36] = field(default_factory=lambda: [0.0] * 36)


# --- nav_msgs -----------------------------------------------------------------

@final
@dataclass
class Odometry_(IdlStruct, typename=dds("nav_msgs", "Odometry")):
    header: Header_ = field(default_factory=Header_)
    child_frame_id: str = ""
    pose: PoseWithCovariance_ = field(default_factory=PoseWithCovariance_)
    twist: TwistWithCovariance_ = field(default_factory=TwistWithCovariance_)


@final
@dataclass
class MapMetaData_(IdlStruct, typename=dds("nav_msgs", "MapMetaData")):
    map_load_time: Time_ = field(default_factory=Time_)
    resolution: float32 = 0.0
    width: uint32 = 0
    height: uint32 = 0
    origin: Pose_ = field(default_factory=Pose_)


@final
@dataclass
class OccupancyGrid_(IdlStruct, typename=dds("nav_msgs", "OccupancyGrid")):
    header: Header_ = field(default_factory=Header_)
    info: MapMetaData_ = field(default_factory=MapMetaData_)
    data: sequence[int8] = field(default_factory=list)


# --- tf2_msgs -------------------------------------------------------------------

@final
@dataclass
class Transform_(IdlStruct, typename=dds("geometry_msgs", "Transform")):
    translation: Vector3_ = field(default_factory=Vector3_)
    rotation: Quaternion_ = field(default_factory=Quaternion_)


@final
@dataclass
class TransformStamped_(IdlStruct, typename=dds("geometry_msgs", "TransformStamped")):
    header: Header_ = field(default_factory=Header_)
    child_frame_id: str = ""
    transform: Transform_ = field(default_factory=Transform_)


@final
@dataclass
class TFMessage_(IdlStruct, typename=dds("tf2_msgs", "TFMessage")):
    transforms: sequence[TransformStamped_] = field(default_factory=list)
