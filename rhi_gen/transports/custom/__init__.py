"""custom: bring your own SDK. The generator writes everything but the SDK calls.

The robot's source file (src/<vendor>/<robot>.cpp) holds a small transport class whose SDK glue is
user regions: the SDK headers go into the ``includes`` region, SDK objects into
``transport_members``, and the bodies of ``connect()`` (on_activate), ``disconnect()``
(on_deactivate) and ``send(command)`` (the command writer thread, every command_writer_period_us)
into ``transport_connect``, ``transport_disconnect`` and ``transport_send``. State reaches the driver
through ``receive_state(fill)`` / ``receive_imu(fill)``, called from the SDK's callback. Everything else
(threads, safe start, decimation, stale-state hold, limits, monitoring) is the shared core, in
transports/custom/custom.hpp.

As generated, each of the three function regions holds one ``#define RHI_CUSTOM_NOT_FILLED_IN_...``
line: the driver compiles and loads, and refuses to activate with one log line naming the first
region that still holds it. The user deletes the line when filling the region. Regeneration keeps
the regions byte for byte (write/regions.py).
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from ...model import TransportOptions
from ...typed_yaml.validator import Validator
from ..base import KnownRobot, Transport, transport_header

NAME = "custom"
# The function regions of the generated transport class, in the order activation checks them.
FUNCTION_REGIONS = ("transport_connect", "transport_send", "transport_disconnect")
MEMBER_REGION = "transport_members"


def not_filled_macro(region: str) -> str:
    """The macro a region's default body defines; its presence means "not filled in yet"."""
    return f"RHI_CUSTOM_NOT_FILLED_IN_{region.upper()}"


class Custom(Transport):
    name = NAME
    summary = "your own SDK: the generated driver calls the connect/disconnect/send code you write in its user regions"
    option_keys = ()
    default_float_type = "double"
    dependencies = ()  # the SDK is the user's: add it to CMakeLists.txt's user regions
    shared_files = (transport_header("ros_topics", "ros_topics.hpp"), transport_header(NAME, "custom.hpp"))

    def read_options(self, v: Validator, options: dict[str, Any], motor_count: int) -> TransportOptions:
        return TransportOptions(sdk_slots=motor_count)  # no options of its own

    def suggest_options(self, order: Sequence[str], known: KnownRobot | None,
                        given: Mapping[str, str] | None = None) -> list[str]:
        return ["  {}  # custom: no options; the SDK glue is in the user regions of the robot's source file"]


TRANSPORT = Custom()
