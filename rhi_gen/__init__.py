"""rhi-gen: generate ros2_control hardware interfaces from a URDF and a vendor YAML."""

__version__ = "0.1.0"
