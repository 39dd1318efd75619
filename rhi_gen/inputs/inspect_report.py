"""`rhi-gen inspect`: what rhi-gen sees in a URDF, as text a person reads before writing a YAML."""
from __future__ import annotations

from .. import transports
from ..model import UrdfRobot
from .urdf_transmissions import describe


def _fmt(value: float | None) -> str:
    return "-" if value is None else f"{value:g}"


def inspect_text(urdf: UrdfRobot, *, vendor: str | None = None, robot: str | None = None) -> str:
    """The report: every joint with type, limits and mimic, existing <ros2_control> tags, the
    <transmission>s, then the suggested joint_map."""
    actuated = urdf.actuated_joints
    out = [(f"robot {urdf.name!r} from {urdf.source}: {len(urdf.joints)} joints, {len(urdf.links)} links, "
            f"{len(actuated)} actuated, {len(urdf.mimic_joints)} mimic")]
    width = max([len(j.name) for j in urdf.joints] + [5])
    out.append(f"  {'#':>3}  {'joint':<{width}}  {'type':<10}  {'lower':>9} {'upper':>9} {'effort':>8} "
               f"{'velocity':>8}  note")
    for i, j in enumerate(urdf.joints):
        lim = j.limits
        note = []
        if j.mimic is not None:
            note.append(f"mimics {j.mimic.joint} (x{j.mimic.multiplier:g} {j.mimic.offset:+g})")
        if not j.actuated and j.mimic is None:
            note.append("not actuated")
        out.append(f"  {i:>3}  {j.name:<{width}}  {j.type:<10}  {_fmt(lim.lower if lim else None):>9} "
                   f"{_fmt(lim.upper if lim else None):>9} {_fmt(lim.effort if lim else None):>8} "
                   f"{_fmt(lim.velocity if lim else None):>8}  {'; '.join(note)}".rstrip())
    for block in urdf.ros2_control:
        names = [j.name for j in block.joints]
        listed = f" ({', '.join(names[:3])}{f' and {len(names) - 3} more' if len(names) > 3 else ''})" if names else ""
        out.append(f"existing <ros2_control name={block.name!r}> plugin {block.plugin or '-'}: "
                   f"{len(block.joints)} joints{listed}")
    if urdf.ros2_control:
        out.append("note: `rhi-gen new` writes its own ros2_control macro for the mapped joints: replace the "
                   "existing tag with it, or keep the tag and do not include the macro (docs/adding-a-robot.md: "
                   "\"A description that already has <ros2_control>\")")
    if urdf.transmissions:
        applicable = sum(1 for t in urdf.transmissions if not t.problem)
        out.append(f"transmissions: {len(urdf.transmissions)} <transmission> (joint = direction * motor / reduction "
                   f"+ offset; {applicable} applicable to mapped joints, docs/transmissions.md)")
        out += [f"  {describe(t)}" + (f" (line {t.line})" if t.line else "") for t in urdf.transmissions]
    known = transports.known_robot(vendor, robot) if vendor and robot else None
    order = transports.suggest_order([j.name for j in actuated], known)
    source = f"the {known.vendor} profile ({known.note})" if known else "URDF order"
    out.append(f"suggested joint_map ({source}):")
    out += [f"  {name}: {index}" for index, name in enumerate(order)]
    return "\n".join(out) + "\n"
