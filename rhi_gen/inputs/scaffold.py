"""`rhi-gen new`: write a vendor YAML whose joint map is suggested from the URDF.

The YAML text is built here (with comments a reviewer can read), then parsed back through the
normal validator, so `new` can never write a YAML that `generate` would reject.
"""
from __future__ import annotations

import os
import re
from collections.abc import Mapping, Sequence
from pathlib import Path

from .. import transports
from ..errors import ConfigError, UrdfError
from ..model import MAX_MOTORS, UrdfJoint, UrdfRobot
from ..model.naming import joint_name_problem
from ..model.urdf import safe_position
from ..transports import HandSuggestion, KnownRobot
from ..typed_yaml.yaml_source import yaml_string
from .urdf_transmissions import describe

MAX_LISTED = 12  # <transmission>s the YAML's comment lists before "and N more"


def _limits_comment(joint: UrdfJoint) -> str:
    lim = joint.limits
    parts = [joint.type]
    if lim is not None and lim.lower is not None and lim.upper is not None and joint.type != "continuous":
        parts.append(f"[{lim.lower:g}, {lim.upper:g}]")
    return " ".join(parts)


def suggest_yaml(*, vendor: str, robot: str, urdf: UrdfRobot, urdf_relative: str,
                 transport: str | None = None, xacro_args: Mapping[str, str] | None = None,
                 package_paths: Mapping[str, str] | None = None, class_prefix: str | None = None,
                 urdf_comment: Sequence[str] = (), transport_options: Mapping[str, str] | None = None) -> str:
    """The text of a new vendor YAML for ``urdf``; ``urdf_comment``: comment lines above ``urdf:``;
    ``transport_options``: ``--transport-option KEY=VALUE`` pairs, written over the suggested options."""
    known = transports.known_robot(vendor, robot)
    chosen = transports.for_vendor(vendor) if transport is None else transports.get(transport, key="--transport")
    if known is not None and known.transport != chosen.name:
        known = None  # the vendor order belongs to the vendor's own transport
    given = dict(transport_options or {})
    for key in given:
        if key not in chosen.option_keys:
            raise ConfigError(f"{chosen.name} has no option {key!r}", key="--transport-option",
                              fix=f"use one of {', '.join(chosen.option_keys)}")
    actuated = list(urdf.actuated_joints)
    if not actuated:
        raise ConfigError("has no actuated joints (revolute, continuous or prismatic without <mimic>)",
                          file=urdf.source, fix="give the robot's full description")
    # Checked here, against the URDF, because the YAML does not exist yet: an error must name the
    # file and line the user can fix, not a line of a YAML that was never written.
    for joint in actuated:
        if (problem := joint_name_problem(joint.name)):
            raise UrdfError(problem, file=urdf.source, line=joint.line,
                            fix="rename the joint in the URDF (letters, digits and _ . / - : + [ ] ( ) # @)")
    if len(actuated) > MAX_MOTORS:
        raise ConfigError(f"has {len(actuated)} actuated joints; rhi-gen drives at most {MAX_MOTORS} motors "
                          "per robot", file=urdf.source,
                          fix="split the robot into several descriptions, or make the joints that no motor "
                              "drives fixed")
    by_name = {j.name: j for j in actuated}
    hands = chosen.detect_hands(known, [j.name for j in actuated])
    in_hands = {name for name, _ in hands.slots}
    slots = transports.suggest_slots([j.name for j in actuated if j.name not in in_hands], known)
    slots += list(hands.slots)  # on the hands' own slots, after the body's
    order = [name for name, _ in slots]
    motor_count = max(slot for _, slot in slots) + 1
    slots_count, holder = chosen.slots_for(known, given)
    if slots_count is not None and hands.slots:
        slots_count = max(slots_count, motor_count)
    if slots_count is not None and motor_count > slots_count:
        raise ConfigError(f"has {motor_count} actuated joints but {holder} has {slots_count} "
                          "motor slots", file=urdf.source,
                          fix=f"use --transport {transports.DEFAULT}, or map a subset and list the rest under "
                              "unmapped_joints")
    chosen.check_new(vendor, robot, known, given)

    lines = [
        f"# Vendor YAML for {vendor}/{robot}, written by `rhi-gen new`.",
        "# Edit freely, then run `rhi-gen generate`; docs/vendor-yaml.md has the full YAML reference.",
    ]
    if known is not None:
        lines.append(f"# joint_map follows the vendor's motor order: {known.note}.")
    else:
        lines.append("# joint_map follows the URDF order: check it against your SDK's motor indices.")
    lines += [
        f"vendor: {vendor}",
        f"robot: {robot}",
        *urdf_comment,
        f"urdf: {yaml_string(urdf_relative)}",
        f"transport: {chosen.name}",
        f"motor_count: {motor_count}",
        f"float_type: {chosen.default_float_type}",
    ]
    lines += chosen.suggest_hands(known, hands)
    lines += chosen.suggest_authority(known)
    if class_prefix is not None:
        lines.append(f"class_prefix: {class_prefix}")
    if xacro_args:
        lines.append("xacro_args:")
        lines += [f"  {yaml_string(k)}: {yaml_string(v)}" for k, v in xacro_args.items()]
    if package_paths:
        lines.append("package_paths:")
        lines += [f"  {yaml_string(k)}: {yaml_string(v)}" for k, v in package_paths.items()]
    lines += [
        "imu:",
        "  enabled: true",
        "parameters:",
        "  network_interface: lo",
        "  enable_monitor: true",
        "  command_writer_period_us: 2000",
        "  command_writer_mode: timer",
        "  state_decimation: 1",
        "  state_timeout_ms: 100",
        "  fault_timeout_ms: 1000",
        "  first_state_timeout_ms: 10000",
        "  diagnostics_period_ms: 1000",
        "  motor_temperature_warn_c: 70",
        "  motor_temperature_error_c: 85",
    ]
    lines += ["transport_options:", *_with_given(chosen.suggest_options(order, known, given), given)]
    group_of = chosen.joint_labels(order, known)
    lines.append("joint_map:")
    for index, (name, slot) in enumerate(slots):
        label = f"{group_of[index]}, " if group_of else ""
        lines.append(f"  {yaml_string(name)}: {slot}  # {label}{_limits_comment(by_name[name])}")
    lines.append("unmapped_joints: []")
    lines += _transmission_lines(urdf)
    if chosen.carries_gains:
        lines += _default_gains_lines(vendor, robot, known, order, hands)
    lines += ["# Where the joints start in the description (mock hardware starts there; the launch file's",
              "# joint states show it until the robot reports). Suggested: zero, clamped into the URDF limits.",
              "initial_positions:"]
    lines += [f"  {yaml_string(name)}: {_yaml_float(safe_position(by_name[name].type, by_name[name].limits))}"
              for name in order]
    return "\n".join(lines) + "\n"


def _transmission_lines(urdf: UrdfRobot) -> list[str]:
    """What the URDF's <transmission>s do, as comments above ``urdf_transmissions: true`` (none: nothing)."""
    if not urdf.transmissions:
        return []
    shown = urdf.transmissions[:MAX_LISTED]
    more = len(urdf.transmissions) - len(shown)
    return [
        f"# The URDF has {len(urdf.transmissions)} <transmission>(s) (docs/transmissions.md). rhi-gen",
        "# applies SimpleTransmission and DifferentialTransmission to mapped joints; a joint under",
        "# transmissions: {joint: {direction, reduction, offset}} or coupled_joints: {group: {joints, matrix}}",
        "# replaces the URDF's; urdf_transmissions: false ignores them all.",
        *(f"#   {''.join(c if c.isprintable() else '?' for c in describe(t))}" for t in shown),
        *([f"#   ... and {more} more (`rhi-gen inspect` lists them all)"] if more else []),
        "urdf_transmissions: true",
    ]


def _yaml_float(value: float) -> str:
    """A float YAML 1.1 reads back as a float: 1e-05 would be a string, 1.0e-05 is not."""
    text = repr(value)
    mantissa, _, exponent = text.partition("e")
    if not exponent:
        return text
    if "." not in mantissa:
        mantissa += ".0"
    return f"{mantissa}e{exponent if exponent[0] in '+-' else '+' + exponent}"


def _with_given(suggested: list[str], given: Mapping[str, str]) -> list[str]:
    """The suggested ``transport_options`` lines with each ``--transport-option`` written over its key."""
    out = [line for line in suggested if line.split(":", 1)[0].strip() not in given]
    return [f"  {key}: {_scalar(value)}  # --transport-option" for key, value in given.items()] + out


def _scalar(value: str) -> str:
    """A command-line value as YAML: a plain number or boolean as typed, anything else quoted."""
    plain = re.fullmatch(r"-?\d+(\.\d+)?|true|false", value)
    return value if plain else yaml_string(value)


def _default_gains_lines(vendor: str, robot: str, known: KnownRobot | None, mapped: Sequence[str],
                         hands: HandSuggestion | None = None) -> list[str]:
    """default_gains: a known robot's (from the vendor's own examples), or a statement that there are none."""
    head = ["# Gains while a controller claims a joint's position or velocity but not its stiffness /",
            "# damping (joint_trajectory_controller, forward_position_controller)."]
    gains = [g for g in known.default_gains if g[0] in mapped] if known is not None else []
    if gains and hands is not None and hands.gains:
        head.append(f"# The hands': {hands.gains_note}.")
        gains += list(hands.gains)
    if known is None or not gains:
        why = known.gains_note if known is not None and known.gains_note else \
            f"rhi-gen knows no gains for {vendor}/{robot}"
        return [*head, f"# None here: {why}.",
                "# A position-only controller leaves the robot limp until you add, per joint,",
                "#   some_joint: {stiffness: 40.0, damping: 1.0}", "default_gains: {}"]
    return [*head, f"# From {known.gains_note}.", "default_gains:",
            *(f"  {yaml_string(n)}: {{stiffness: {kp!r}, damping: {kd!r}}}" for n, kp, kd in gains)]


def relative_urdf_path(urdf: Path, yaml_dir: Path) -> str:
    """How the YAML in ``yaml_dir`` names ``urdf`` (POSIX, relative: the project moves between machines)."""
    return Path(os.path.relpath(urdf.resolve(), yaml_dir.resolve())).as_posix()
