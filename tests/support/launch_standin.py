"""A small, faithful stand-in of the ROS 2 ``launch`` / ``launch_ros`` Python API the generated launch files use,
and a tiny launch service that runs a launch file with it and reports what it would start.

No registry ships ``launch`` or ``launch_ros`` (the PyPI package called ``launch`` is unrelated), so the
generated ``launch/*.launch.py`` are loaded with these classes instead. Only what the generated files use
exists here; each class keeps the real constructor's signature (positional and keyword-only parameters,
names, defaults), so a call the real API rejects is rejected here too, and performs its substitutions as
the real one does. Written from, and checked against (the signatures are the same on both branches):

- github.com/ros2/launch, branches ``humble`` and ``rolling``:
  ``launch/launch/launch_description.py`` (LaunchDescription(initial_entities=None, *, deprecated_reason=None)),
  ``launch/launch/actions/declare_launch_argument.py`` (DeclareLaunchArgument(name, *, default_value=None,
  description=None, choices=None, **kwargs); executing it without a value and without a default raises),
  ``launch/launch/actions/opaque_function.py`` (OpaqueFunction(*, function, args=None, kwargs=None)),
  ``launch/launch/actions/set_environment_variable.py`` (SetEnvironmentVariable(name, value, **kwargs): the
  variable is set in the launch context's environment, which every process started after it inherits),
  ``launch/launch/actions/include_launch_description.py`` (IncludeLaunchDescription(launch_description_source,
  *, launch_arguments=None): the arguments become launch configurations; a declared argument without default
  that is not given is an error), ``launch/launch/launch_description_sources/python_launch_description_source.py``
  (PythonLaunchDescriptionSource(launch_file_path)),
  ``launch/launch/substitutions/launch_configuration.py`` (LaunchConfiguration(variable_name, *, default=None)),
  ``launch/launch/substitutions/command.py`` (Command(command, *, on_stderr='fail'): the performed text is split
  with shlex and run, stdout is the value, output on stderr fails the substitution),
  ``launch/launch/substitutions/path_join_substitution.py`` (PathJoinSubstitution(substitutions): os.path.join).
- github.com/ros2/launch_ros, branches ``humble`` and ``rolling``:
  ``launch_ros/launch_ros/actions/node.py`` (Node(*, executable, package=None, name=None, namespace=None,
  exec_name=None, parameters=None, remappings=None, ros_arguments=None, arguments=None, **kwargs)),
  ``launch_ros/launch_ros/parameter_descriptions.py`` (ParameterValue(value, *, value_type=None)),
  ``launch_ros/launch_ros/substitutions/find_package.py`` (FindPackageShare(package)).
"""
from __future__ import annotations

import importlib.util
import os
import shlex
import subprocess
import sys
import types
from collections.abc import Callable, Iterable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any


class SubstitutionFailure(RuntimeError):
    """launch.substitutions.substitution_failure.SubstitutionFailure."""


class LaunchContext:
    """The parts of launch.LaunchContext the substitutions read: the launch configurations, and (test only)
    where FindPackageShare finds each package's share folder."""

    def __init__(self, shares: Mapping[str, Path]) -> None:
        self.launch_configurations: dict[str, str] = {}
        self.shares = dict(shares)

    def perform_substitution(self, substitution: Substitution) -> str:
        return substitution.perform(self)


class Substitution:
    def perform(self, context: LaunchContext) -> str:
        raise NotImplementedError


class TextSubstitution(Substitution):
    def __init__(self, *, text: str) -> None:
        self.text = text

    def perform(self, context: LaunchContext) -> str:
        return self.text


def normalize(value: Any) -> list[Substitution]:
    """launch.utilities.normalize_to_list_of_substitutions: a str, a Substitution or an iterable of them."""
    if isinstance(value, str):
        return [TextSubstitution(text=value)]
    if isinstance(value, Substitution):
        return [value]
    out: list[Substitution] = []
    for item in value:
        if not isinstance(item, (str, Substitution)):
            raise TypeError(f"a substitution must be str or Substitution, got {type(item).__name__}")
        out += normalize(item)
    return out


def perform(context: LaunchContext, value: Any) -> str:
    """launch.utilities.perform_substitutions on a normalized value."""
    return "".join(s.perform(context) for s in normalize(value))


class LaunchConfiguration(Substitution):
    def __init__(self, variable_name: Any, *, default: Any = None) -> None:
        self.variable_name = normalize(variable_name)
        self.default = default

    def perform(self, context: LaunchContext) -> str:
        name = perform(context, self.variable_name)
        if name in context.launch_configurations:
            return context.launch_configurations[name]
        if self.default is None:
            raise SubstitutionFailure(f"launch configuration '{name}' does not exist")
        return perform(context, self.default)


class PathJoinSubstitution(Substitution):
    def __init__(self, substitutions: Iterable[Any]) -> None:
        self.substitutions = [normalize(s) for s in substitutions]

    def perform(self, context: LaunchContext) -> str:
        return os.path.join(*(perform(context, s) for s in self.substitutions))


class Command(Substitution):
    def __init__(self, command: Any, *, on_stderr: Any = "fail") -> None:
        self.command = normalize(command)
        self.on_stderr = normalize(on_stderr)

    def perform(self, context: LaunchContext) -> str:
        text = perform(context, self.command)
        # The executables of this Python environment (the real xacro) come first, as a sourced ROS would.
        env = {**os.environ, "PATH": os.path.dirname(sys.executable) + os.pathsep + os.environ.get("PATH", "")}
        result = subprocess.run(shlex.split(text), capture_output=True, text=True, env=env)
        if result.returncode != 0:
            raise SubstitutionFailure(f"executed command failed. Command: {text}\nStderr: {result.stderr}")
        if result.stderr and perform(context, self.on_stderr) == "fail":
            raise SubstitutionFailure(f"executed command showed stderr output. Command: {text}\n{result.stderr}")
        return result.stdout


class FindPackageShare(Substitution):
    def __init__(self, package: Any) -> None:
        self.package = normalize(package)

    def perform(self, context: LaunchContext) -> str:
        name = perform(context, self.package)
        if name not in context.shares:
            raise SubstitutionFailure(f"package '{name}' not found")
        return str(context.shares[name])


class ParameterValue:
    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value = value
        self.value_type = value_type


class Action:
    def __init__(self, **kwargs: Any) -> None:
        unknown = set(kwargs) - {"condition"}
        if unknown:
            raise TypeError(f"unexpected keyword arguments {sorted(unknown)}")


class DeclareLaunchArgument(Action):
    def __init__(self, name: str, *, default_value: Any = None, description: str | None = None,
                 choices: Iterable[str] | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = name
        self.default_value = normalize(default_value) if default_value is not None else None
        self.description = description
        self.choices = list(choices) if choices is not None else None


class OpaqueFunction(Action):
    def __init__(self, *, function: Callable[..., Any], args: Iterable[Any] | None = None,
                 kwargs: dict[str, Any] | None = None, **left_over_kwargs: Any) -> None:
        super().__init__(**left_over_kwargs)
        self.function = function
        self.args = list(args or [])
        self.kwargs = dict(kwargs or {})


class SetEnvironmentVariable(Action):
    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name, self.value = name, value


class PythonLaunchDescriptionSource:
    def __init__(self, launch_file_path: Any) -> None:
        self.launch_file_path = normalize(launch_file_path)


class IncludeLaunchDescription(Action):
    def __init__(self, launch_description_source: Any, *,
                 launch_arguments: Iterable[tuple[Any, Any]] | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        if not isinstance(launch_description_source, PythonLaunchDescriptionSource):
            launch_description_source = PythonLaunchDescriptionSource(launch_description_source)
        self.source = launch_description_source
        self.launch_arguments = list(launch_arguments or [])


class Node(Action):
    def __init__(self, *, executable: Any, package: Any = None, name: Any = None, namespace: Any = None,
                 exec_name: Any = None, parameters: Any = None, remappings: Any = None,
                 ros_arguments: Any = None, arguments: Any = None, **kwargs: Any) -> None:
        output = kwargs.pop("output", None)  # an ExecuteProcess keyword
        super().__init__(**kwargs)
        self.executable, self.package, self.name, self.namespace = executable, package, name, namespace
        self.parameters = list(parameters or [])
        self.remappings = list(remappings or [])
        self.arguments = list(arguments or [])
        self.output = output


class LaunchDescription:
    def __init__(self, initial_entities: Iterable[Any] | None = None, *, deprecated_reason: str | None = None) -> None:
        self.entities = list(initial_entities or [])


MODULES: dict[str, dict[str, object]] = {
    "launch": {"LaunchDescription": LaunchDescription, "LaunchContext": LaunchContext,
               "Substitution": Substitution},
    "launch.actions": {"DeclareLaunchArgument": DeclareLaunchArgument, "OpaqueFunction": OpaqueFunction,
                       "IncludeLaunchDescription": IncludeLaunchDescription,
                       "SetEnvironmentVariable": SetEnvironmentVariable},
    "launch.launch_description_sources": {"PythonLaunchDescriptionSource": PythonLaunchDescriptionSource},
    "launch.substitutions": {"Command": Command, "LaunchConfiguration": LaunchConfiguration,
                             "PathJoinSubstitution": PathJoinSubstitution, "TextSubstitution": TextSubstitution},
    "launch_ros": {},
    "launch_ros.actions": {"Node": Node},
    "launch_ros.parameter_descriptions": {"ParameterValue": ParameterValue},
    "launch_ros.substitutions": {"FindPackageShare": FindPackageShare},
}


@contextmanager
def installed() -> Iterator[None]:
    """The stand-in modules in sys.modules while a launch file is imported (the previous entries put back)."""
    saved = {name: sys.modules.get(name) for name in MODULES}
    for name, members in MODULES.items():
        module = types.ModuleType(name)
        module.__dict__.update(members)
        sys.modules[name] = module
    try:
        yield
    finally:
        for name, previous in saved.items():
            if previous is None:
                sys.modules.pop(name, None)
            else:
                sys.modules[name] = previous


def load_launch_file(path: Path) -> LaunchDescription:
    """Import a launch file with the stand-in API and call its generate_launch_description()."""
    with installed():
        spec = importlib.util.spec_from_file_location(f"rhi_launch_{path.stem.replace('.', '_')}", path)
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        description = module.generate_launch_description()
    assert isinstance(description, LaunchDescription), f"{path}: generate_launch_description() returned {description!r}"
    return description


@dataclass
class StartedNode:
    """A Node as the launch service would start it: every substitution performed."""
    package: str
    executable: str
    arguments: list[str]
    parameters: list[Any]       # a performed dict (ParameterValue -> its value) or a parameter file path
    remappings: list[tuple[str, str]]
    environment: dict[str, str] = field(default_factory=dict)  # what SetEnvironmentVariable set before it


@dataclass
class Launched:
    arguments: dict[str, DeclareLaunchArgument] = field(default_factory=dict)  # the top file's, by name
    configurations: dict[str, str] = field(default_factory=dict)
    nodes: list[StartedNode] = field(default_factory=list)
    environment: dict[str, str] = field(default_factory=dict)  # set by SetEnvironmentVariable, in order


def launch(path: Path, shares: Mapping[str, Path], overrides: Mapping[str, str] | None = None) -> Launched:
    """Run ``path`` as `ros2 launch` would with ``overrides`` (NAME:=VALUE): declare its arguments, include
    what it includes, run its OpaqueFunctions, and perform every Node's substitutions (nothing is started)."""
    context = LaunchContext(shares)
    context.launch_configurations.update(overrides or {})
    out = Launched()
    top = load_launch_file(path)
    out.arguments = {e.name: e for e in top.entities if isinstance(e, DeclareLaunchArgument)}
    _visit(top.entities, context, out)
    out.configurations = dict(context.launch_configurations)
    return out


def _visit(entities: Iterable[Any], context: LaunchContext, out: Launched) -> None:
    for entity in entities:
        if isinstance(entity, DeclareLaunchArgument):
            if entity.name not in context.launch_configurations:
                if entity.default_value is None:
                    raise RuntimeError(f"Required launch argument '{entity.name}' was not provided")
                context.launch_configurations[entity.name] = perform(context, entity.default_value)
            if entity.choices is not None and context.launch_configurations[entity.name] not in entity.choices:
                raise RuntimeError(f"argument '{entity.name}' is not one of {entity.choices}")
        elif isinstance(entity, IncludeLaunchDescription):
            included = load_launch_file(Path(perform(context, entity.source.launch_file_path)))
            given = {perform(context, k): perform(context, v) for k, v in entity.launch_arguments}
            for e in included.entities:
                if isinstance(e, DeclareLaunchArgument) and e.default_value is None and e.name not in given:
                    raise RuntimeError(f"Included launch description missing required argument '{e.name}'")
            context.launch_configurations.update(given)
            _visit(included.entities, context, out)
        elif isinstance(entity, OpaqueFunction):
            _visit(entity.function(context, *entity.args, **entity.kwargs) or [], context, out)
        elif isinstance(entity, Node):
            out.nodes.append(StartedNode(
                package=perform(context, entity.package), executable=perform(context, entity.executable),
                arguments=[perform(context, a) for a in entity.arguments],
                parameters=[_parameters(context, p) for p in entity.parameters],
                remappings=[(perform(context, a), perform(context, b)) for a, b in entity.remappings],
                environment=dict(out.environment)))
        elif isinstance(entity, SetEnvironmentVariable):
            out.environment[perform(context, entity.name)] = perform(context, entity.value)
        else:
            raise TypeError(f"the stand-in does not know {type(entity).__name__}")


def _parameters(context: LaunchContext, item: Any) -> Any:
    if isinstance(item, dict):
        return {perform(context, k): perform(context, v.value) if isinstance(v, ParameterValue) else perform(context, v)
                for k, v in item.items()}
    return perform(context, item)  # a parameter file
