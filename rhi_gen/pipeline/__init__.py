"""The pipeline: strings the stages together for the CLI (inputs -> model -> render -> write).

load.py (every robot's inputs -> RobotModel), generate.py (render and plan against the disk, for
generate / check / diff), new_robot.py (`rhi-gen new`). Nothing here writes: the CLI applies a plan
with write/transaction.apply.
"""
