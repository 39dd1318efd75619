"""The model: what a robot is, as plain frozen data (no I/O), in three layers.

- ``UrdfRobot``    what the URDF says (model/urdf.py, read by inputs/urdf_loader.py)
- ``VendorConfig`` what the vendor YAML says (model/config.py, read by inputs/vendor_config.py)
- ``RobotModel``   both cross-checked, every C++ name decided (model/robot.py, made by
  assemble/robot_model.py, the stage above the transports);
  the templates read only this.
"""
from .config import (
    AUTHORITIES,
    FLOAT_TYPES,
    HANDS,
    MAX_MOTORS,
    ImuConfig,
    PackageInfo,
    Parameters,
    TransportOptions,
    VendorConfig,
)
from .robot import CoupledGroup, InputProvenance, JointTransmission, MeshCopy, MissingMesh, MotorJoint, RobotModel
from .urdf import (
    ACTUATED_TYPES,
    JointLimits,
    Mimic,
    Ros2ControlBlock,
    Ros2ControlJoint,
    UrdfJoint,
    UrdfRobot,
    UrdfTransmission,
)

__all__ = [
    "ACTUATED_TYPES",
    "AUTHORITIES",
    "FLOAT_TYPES",
    "HANDS",
    "MAX_MOTORS",
    "CoupledGroup",
    "ImuConfig",
    "InputProvenance",
    "JointLimits",
    "JointTransmission",
    "MeshCopy",
    "Mimic",
    "MissingMesh",
    "MotorJoint",
    "PackageInfo",
    "Parameters",
    "RobotModel",
    "Ros2ControlBlock",
    "Ros2ControlJoint",
    "TransportOptions",
    "UrdfJoint",
    "UrdfRobot",
    "UrdfTransmission",
    "VendorConfig",
]
