"""What a transport is: the interface every folder in transports/ implements.

A transport is how a generated driver talks to its robot (a vendor SDK over DDS, or ROS 2 topics).
Everything rhi-gen knows about one transport lives in its own folder, whose ``__init__.py`` exports it: the YAML
options it accepts (its ``TransportOptions`` subclass, with validation and defaults), its default
float type, the packages its driver needs (``Dependency``: how CMakeLists.txt and package.xml
declare each, render/views.py), the files it adds to the package once, the ``transport_options``
lines `rhi-gen new` writes, and the vendor robots whose real SDK motor order is known. Its C++ logic
lives next to it in ``transports/<name>/<name>.hpp`` (a plain header, copied once into every package
that uses it) and its per-robot glue (the options a robot's source passes to it) in the template
``transports/<name>/glue.j2``, found by name.
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, ClassVar

from ..model import TransportOptions
from ..typed_yaml.validator import Validator

# Packages every driver needs, whatever its transport.
COMMON_DEPENDENCIES = ("hardware_interface", "pluginlib", "rclcpp", "rclcpp_lifecycle")
# Message packages every driver needs (linked through ${<pkg>_TARGETS}): /diagnostics.
COMMON_MESSAGE_DEPENDENCIES = ("diagnostic_msgs",)

# Motor health a state message may carry, per joint, in the order the description lists them (the C++
# names in cpp/common/driver_health.hpp): winding temperature [deg C], supply voltage [V], the motor's
# error code (a vendor bit field, 0 = no error).
MOTOR_HEALTH_INTERFACES = ("temperature", "voltage", "error_code")

# Where a dependency comes from decides how package.xml and CMakeLists.txt declare it.
ROSDISTRO = "rosdistro"          # a released ROS package: <depend>, rosdep key, ament variables
VENDOR_SOURCE = "vendor_source"  # a ROS package built from the vendor's sources: no rosdep key
PLAIN_CMAKE = "plain_cmake"      # a plain CMake package: no package.xml, no rosdep key; linked by target


@dataclass(frozen=True)
class Dependency:
    """A package a transport's driver needs: CMakeLists.txt and package.xml declare it from this alone
    (render/views.py), and only in a package where a robot uses the transport."""
    name: str
    source: str  # ROSDISTRO | VENDOR_SOURCE | PLAIN_CMAKE
    # PLAIN_CMAKE only (a ROS package is found by find_package(name) and linked by ${name_TARGETS}):
    cmake_find: str = ""    # the CMakeLists.txt lines that find it and set cmake_target
    cmake_target: str = ""  # the CMake variable holding its imported target ("" = not found)
    package_xml_note: tuple[str, ...] = ()  # package.xml's comment in its place: why it is not declared


@dataclass(frozen=True)
class KnownRobot:
    """A vendor robot whose SDK motor order rhi-gen knows (`rhi-gen new` and `inspect` suggest it)."""
    vendor: str
    robot: str
    transport: str
    joint_order: tuple[str, ...]                       # SDK motor index order ("" for a slot no joint drives)
    note: str                                          # where the order comes from, for the YAML comment
    groups: tuple[tuple[str, tuple[str, ...]], ...] = ()  # per joint group, for grouped transports
    aliases: tuple[str, ...] = ()                      # other robot names it goes by ("go2_w" for "go2w")
    family: str = ""                                   # unitree_dds: "hg" | "go" message family
    motor_modes: tuple[int, ...] = ()                  # unitree go: MotorCmd_.mode per slot
    # joint -> (stiffness, damping) for a controller that claims only position / velocity
    default_gains: tuple[tuple[str, float, float], ...] = ()
    gains_note: str = ""                               # where the gains come from, or why there are none

    def named(self, robot: str) -> bool:
        return robot == self.robot or robot in self.aliases


def suggest_order(actuated: Sequence[str], known: KnownRobot | None) -> list[str]:
    """Actuated joints in SDK order: the known robot's order where names match, the rest in URDF order."""
    if known is None or not known.joint_order:
        return list(actuated)
    first = [n for n in known.joint_order if n and n in actuated]
    return first + [n for n in actuated if n not in first]


@dataclass(frozen=True)
class HandSuggestion:
    """The hands `rhi-gen new` finds in a URDF: the YAML's ``hands`` value, the hand joints' slots and gains."""
    hands: str = "none"
    slots: tuple[tuple[str, int], ...] = ()
    gains: tuple[tuple[str, float, float], ...] = ()  # (joint, stiffness, damping), the vendor's own
    gains_note: str = ""  # where those gains come from


HAND_OPTION_KEYS = ("hand_command_topic", "hand_state_topic")  # transport_options of a transport that drives hands


def check_hand_choice(v: Validator, hands: str, own: str, transport: str, what: str) -> None:
    """A transport drives its own vendor's hand (``own``) or none; its hand topic options only come with it."""
    if hands not in ("none", own):
        raise v.error("hands", f"hands {hands!r} is not {what}'s hand; the {transport} transport drives {what}'s "
                      f"(hands: {own})", fix=f"set hands: {own}, or remove hands")
    given = [k for k in HAND_OPTION_KEYS if f"transport_options.{k}" in v.lines]
    if hands == "none" and given:
        raise v.error(f"transport_options.{given[0]}", f"is a hand option, used only with hands: {own}",
                      fix=f"remove {given[0]}, or set hands: {own}")


def suggest_slots(actuated: Sequence[str], known: KnownRobot | None) -> list[tuple[str, int]]:
    """(joint, SDK slot) of every actuated joint: a known robot's real slots (which may skip slots no
    joint drives), then the remaining joints on the next free slots."""
    slots: list[tuple[str, int]] = []
    if known is not None:
        slots = [(n, i) for i, n in enumerate(known.joint_order) if n and n in actuated]
    taken = {i for _, i in slots}
    named = {n for n, _ in slots}
    free = (i for i in range(len(actuated) + len(taken) + 1) if i not in taken)
    return slots + [(n, next(free)) for n in actuated if n not in named]


class Transport(ABC):
    """One transport. Subclasses set the class attributes and implement the two abstract methods."""

    name: ClassVar[str]                        # the YAML's `transport:` value
    summary: ClassVar[str]                     # one line: what the driver talks to
    option_keys: ClassVar[tuple[str, ...]]     # keys allowed under `transport_options:`
    default_float_type: ClassVar[str]          # MotorCommand<N, T>'s T when the YAML gives none
    dependencies: ClassVar[tuple[Dependency, ...]]  # packages the driver needs besides COMMON_DEPENDENCIES
    shared_files: ClassVar[tuple[tuple[str, str], ...]] = ()  # (source, package path), once per package
    vendors: ClassVar[tuple[str, ...]] = ()    # vendors whose robots `rhi-gen new` gives this transport
    known_robots: ClassVar[tuple[KnownRobot, ...]] = ()
    motor_slots: ClassVar[int | None] = None   # fixed motor slot count of the SDK message, if any
    # Whether the robot receives stiffness and damping: if not, joints export no gain interfaces.
    carries_gains: ClassVar[bool] = True
    slots_holder: ClassVar[str] = ""           # what has those slots, for messages ("a unitree hg LowCmd_")
    # The robot's side of the transport for the generated fake robot (transport/<name>_fake_robot.hpp, one
    # of shared_files; its type is the glue's fake_robot_type macro), "" when there is none yet, and the
    # rate the real robot publishes its state at, which the fake robot's loop keeps.
    fake_robot_header: ClassVar[str] = ""
    fake_state_rate_hz: ClassVar[float] = 500.0

    @abstractmethod
    def read_options(self, v: Validator, options: dict[str, Any], motor_count: int) -> TransportOptions:
        """Validate ``transport_options`` (keys already checked against ``option_keys``), fill defaults."""

    def resolve_options(self, v: Validator, options: TransportOptions, *, vendor: str, robot: str,
                        motor_count: int) -> TransportOptions:
        """Options that depend on which robot this is (a known robot's defaults); unchanged by default."""
        return options

    def resolve_authority(self, v: Validator, authority: str, options: TransportOptions, *, vendor: str,
                          robot: str, mapped_slots: frozenset[int]) -> TransportOptions:
        """Options for the YAML's ``authority``. Only ``full`` by default: sharing the robot with its own
        controller needs the vendor's protocol for it (Unitree's arm SDK is the one rhi-gen speaks)."""
        if authority != "full":
            raise v.error("authority", f"the {self.name} transport commands the whole robot; authority "
                          f"{authority!r} is supported on Unitree hg robots (G1, H1-2) through the arm SDK",
                          fix="remove authority (the default is full)")
        return options

    def resolve_hands(self, v: Validator, hands: str, options: TransportOptions, *, vendor: str,
                      robot: str) -> TransportOptions:
        """Options for the YAML's ``hands`` (before resolve_options). Only ``none`` by default: a hand needs
        its vendor's protocol (the G1's Dex3-1 over unitree_sdk2, the X2's OmniHand over AimDK)."""
        if hands != "none":
            raise v.error("hands", f"the {self.name} transport drives no hands; hands dex3 is the G1's Dex3-1 over "
                          "unitree_sdk2 (transport unitree_dds), omnihand the X2's OmniHand (transport agibot_topics)",
                          fix="remove hands (the default is none), or map the hand joints as body motors")
        return options

    def check_hand_map(self, v: Validator, options: TransportOptions,
                       joint_map: tuple[tuple[str, int], ...]) -> None:
        """Refuse a joint_map that leaves out a hand motor of ``options.hand_slots()`` (none by default)."""
        return None

    def detect_hands(self, known: KnownRobot | None, actuated: Sequence[str]) -> HandSuggestion:
        """The hands of a new robot whose URDF has every joint of hands this transport drives (none by default)."""
        return HandSuggestion()

    def suggest_hands(self, known: KnownRobot | None, hands: HandSuggestion) -> list[str]:
        """The top-level YAML lines `rhi-gen new` writes about ``hands`` (none: the transport drives none)."""
        return []

    def suggest_authority(self, known: KnownRobot | None) -> list[str]:
        """The top-level YAML lines `rhi-gen new` writes about ``authority`` (none: only full exists)."""
        return []

    def motor_health(self, options: TransportOptions) -> tuple[str, ...]:
        """The per-joint health state interfaces the robot's state message carries (after position,
        velocity and effort), in MOTOR_HEALTH_INTERFACES order: none unless the transport says."""
        return ()

    def detected_motor_health(self, options: TransportOptions) -> tuple[str, ...]:
        """Health interfaces only some releases of the vendor's messages carry (MOTOR_HEALTH_INTERFACES
        order): not in the description; the driver finds them in the installed messages when it is compiled
        and then exports them beyond the description (C++ DriverTransport::detected_motor_health())."""
        return ()

    def command_interfaces(self, mode: str) -> tuple[str, ...]:
        """A joint's command interfaces: a position-commanded joint takes the full PD command, a
        velocity-commanded one (a wheel) no position or stiffness; gains only where they travel."""
        if mode == "position_target":
            return ("position",)  # the robot's own controller tracks the target: nothing else travels
        full = ("position", "velocity", "stiffness", "damping", "effort") if mode == "position" \
            else ("velocity", "damping", "effort")
        return tuple(i for i in full if self.carries_gains or i not in ("stiffness", "damping"))

    @abstractmethod
    def suggest_options(self, order: Sequence[str], known: KnownRobot | None,
                        given: Mapping[str, str] | None = None) -> list[str]:
        """The YAML lines under ``transport_options:`` that `rhi-gen new` writes (indented two spaces);
        ``given``: the ``--transport-option`` values (written over these lines by the caller)."""

    def slots_for(self, known: KnownRobot | None, given: Mapping[str, str]) -> tuple[int | None, str]:
        """(motor slots, what has them) for a new robot: ``motor_slots`` unless the options change it."""
        return self.motor_slots, self.slots_holder

    def check_new(self, vendor: str, robot: str, known: KnownRobot | None, given: Mapping[str, str]) -> None:
        """Refuse (ConfigError, in `rhi-gen new`'s words) a new robot this transport cannot guess for."""
        return None  # every transport but unitree_dds can guess: nothing to refuse

    def joint_labels(self, order: Sequence[str], known: KnownRobot | None) -> list[str]:
        """Per motor slot, a label for the joint_map comment `rhi-gen new` writes (none by default)."""
        return []

    @property
    def glue_template(self) -> str:
        """The template a robot's source imports: this transport's options and C++ type."""
        return f"transports/{self.name}/glue.j2"


def transport_header(folder: str, name: str) -> tuple[str, str]:
    """(source, package path) of a C++ header kept in ``transports/<folder>/``, copied once per package
    into include/robot_hardware_interface/transport/ (source paths are relative to the rhi_gen package)."""
    return (f"transports/{folder}/{name}", f"include/robot_hardware_interface/transport/{name}")
