"""RobotModels for tests: small ones built directly (no URDF, no YAML) for the view-model tests of tests/unit/render/,
and the one a vendor YAML makes (model_of_yaml)."""
from __future__ import annotations

from pathlib import Path

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


def model_of_yaml(path: Path) -> RobotModel:
    """The RobotModel `rhi-gen generate` builds from the vendor YAML at ``path`` (its URDF as the YAML names it)."""
    from rhi_gen.assemble.robot_model import build_model
    from rhi_gen.inputs.urdf_loader import load_urdf
    from rhi_gen.inputs.vendor_config import load_config

    config = load_config(path)
    return build_model(config, load_urdf(config.urdf), project_root=path.parent, yaml_path=path)
