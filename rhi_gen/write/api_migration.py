"""Carry user code across a rename of the C++ API it calls.

rhi-gen renamed the methods of the shared driver headers from lowerCamel to ROS 2's snake_case
(``receiveState`` -> ``receive_state``). User regions are copied byte for byte, so code written
against the old names would stop compiling after a regeneration. Before the bodies are carried
over, every old name of the API a region can reach (the custom transport, SystemDriver,
DriverCore, ImuData, the monitor helpers) is rewritten to its new name, and each rewrite is
reported so the user sees it in `rhi-gen generate` / `diff`. Names generic enough to be the user's
own or an SDK's (``getData``, ``setData``) are not touched; docs/migration.md says so.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from .regions import parse_regions

# Old -> new, only for names a user region can reach. Order does not matter: no name is a prefix
# match of another under \b...\b.
RENAMED_API: dict[str, str] = {
    # CustomTransport (transport_* regions)
    "receiveState": "receive_state", "receiveImu": "receive_imu", "networkInterface": "network_interface",
    # SystemDriver and DriverCore (driver regions, SystemDriver hooks)
    "getJointIndex": "get_joint_index", "setLogger": "set_logger", "throttleClock": "throttle_clock",
    "hasImu": "has_imu", "mappedSlots": "mapped_slots", "slotJointNames": "slot_joint_names",
    "modeOf": "mode_of", "slotOf": "slot_of", "imuData": "imu_data",
    "resetForActivation": "reset_for_activation", "startStateFrame": "start_state_frame",
    "stateFrame": "state_frame", "publishState": "publish_state", "rejectState": "reject_state",
    "markStateFresh": "mark_state_fresh", "firstStateReceived": "first_state_received",
    "imuFrame": "imu_frame", "publishImu": "publish_imu", "rejectImu": "reject_imu",
    "checkStateLatency": "check_state_latency", "checkWriterJitter": "check_writer_jitter",
    "nextCommand": "next_command", "checkWriterLatency": "check_writer_latency",
    "prepareClaims": "prepare_claims", "commitClaims": "commit_claims",
    "jointsWithoutDefaultStiffness": "joints_without_default_stiffness", "readState": "read_state",
    "writeCommand": "write_command", "checkReadLatency": "check_read_latency",
    "checkWriteLatency": "check_write_latency",
    # ImuData members and the monitor helpers
    "ori_": "orientation", "angularVel_": "angular_velocity", "linearAcc_": "linear_acceleration",
    "allFinite": "all_finite", "steadyNowNs": "steady_now_ns", "steadyNowUs": "steady_now_us",
    "elapsedUs": "elapsed_us",
}
_OLD_NAME = re.compile(r"\b(" + "|".join(sorted(RENAMED_API, key=len, reverse=True)) + r")\b")
_CPP_SUFFIXES = (".cpp", ".hpp")


@dataclass(frozen=True)
class ApiRename:
    """One old name rewritten in one user region, for the command's report."""
    path: str      # as shown to the user (generated/...)
    region: str
    line: int      # line of the old file where the name stood
    old: str
    new: str

    def note(self) -> str:
        return (f"{self.path}:{self.line}: user region {self.region!r}: {self.old} -> {self.new} "
                "(the shared C++ API now uses ROS 2 snake_case)")


def migrate_region_bodies(text: str, path: str) -> tuple[str, list[ApiRename]]:
    """``text`` with the old API names in its user-region bodies renamed, and what was renamed.

    Only C++ files; text outside regions is never touched (that is the template's). ``text`` must
    parse (the caller reports broken markers).
    """
    if not path.endswith(_CPP_SUFFIXES):
        return text, []
    renames: list[ApiRename] = []
    out: list[str] = []
    pos = 0
    for region in parse_regions(text, path):
        body = region.body(text)
        for match in _OLD_NAME.finditer(body):
            line = region.begin_line + 1 + body.count("\n", 0, match.start())
            old = match.group(1)
            renames.append(ApiRename(path, region.name, line, old, RENAMED_API[old]))
        out.append(text[pos:region.body_start])
        out.append(_OLD_NAME.sub(lambda m: RENAMED_API[m.group(1)], body))
        pos = region.body_end
    out.append(text[pos:])
    return "".join(out), renames
