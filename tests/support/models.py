"""Small RobotModels built directly (no URDF, no YAML) for the view-model tests of tests/unit/render/."""
from __future__ import annotations

from rhi_gen import transports
from rhi_gen.model import (
    ImuConfig,
    InputProvenance,
    JointLimits,
    MotorJoint,
    Parameters,
    RobotModel,
    TransportOptions,
)


def robot_model(transport: str, vendor: str = "acme", robot: str = "arm", *, imu: bool = True,
                joints: tuple[MotorJoint, ...] | None = None, period: int = 2000) -> RobotModel:
    t = transports.get(transport)
    if joints is None:
        joints = (
            MotorJoint("shoulder", 0, "revolute", JointLimits(-1.5, 1.5), command_interfaces=t.command_interfaces(
                "position"), default_stiffness=10.0, default_damping=1.0),
            MotorJoint("wheel", 1, "continuous", None, command_mode="velocity",
                       command_interfaces=t.command_interfaces("velocity")),
        )
    return RobotModel(vendor=vendor, robot=robot, robot_pascal="Arm", robot_upper="ARM",
                      class_name="ArmHardwareInterface", plugin_name=f"{vendor}/ArmHardwareInterface",
                      node_name="arm_hardware_interface", transport=transport, motor_count=len(joints),
                      float_type="double", joints=joints, unmapped_joints=(), mimic_joints=(),
                      imu=ImuConfig(enabled=imu), parameters=Parameters(command_writer_period_us=period),
                      transport_options=TransportOptions(sdk_slots=len(joints)),
                      provenance=InputProvenance("robots/a.yaml", "robots/a.urdf", "", ""))
