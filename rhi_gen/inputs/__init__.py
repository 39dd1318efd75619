"""Inputs: read the robot description (URDF / xacro) and the vendor YAML strictly, errors at file:line.

urdf_loader.py + xacro_expand.py give a ``UrdfRobot`` (each delegating to the urdf_*.py and
xacro_*.py modules); vendor_config.py (reading through typed_yaml/) gives a ``VendorConfig`` (each
transport validates its own options, see transports/). scaffold.py writes a new vendor YAML
(`rhi-gen new`), inspect_report.py describes a URDF (`rhi-gen inspect`).
"""
