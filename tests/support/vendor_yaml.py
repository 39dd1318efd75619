"""Vendor YAML texts the input tests start from."""
from __future__ import annotations

# A three-joint arm on generic_topics; the next line written after it is line 10.
ARM_YAML = """\
vendor: acme
robot: arm
urdf: arm.urdf
transport: generic_topics
motor_count: 3
joint_map:
  j1: 0
  j2: 1
  j3: 2
"""
