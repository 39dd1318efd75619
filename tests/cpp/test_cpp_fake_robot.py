"""The generated fake robot executables (<robot>_fake_robot: src/fake_robot_main.cpp + the robot's
src/<vendor>/<robot>_fake_robot.cpp) build with g++ -Werror against each distro's stand-ins, and, run as a
user runs them, refuse to start where ROS 2 discovery reaches other hosts, say how to fix it in one line,
answer --help, refuse bad arguments, and keep running where discovery stays on this host.

What the fake robot does with the driver (motor maps agree, a trajectory is followed, injected faults get
the driver's documented reaction, the loop allocates nothing) is the driver harness's fake_robot section
(tests/cpp/harness/fake_robot_checks.inc, run by test_cpp_drivers.py in every cell).
"""
from __future__ import annotations

import os
import subprocess

import pytest

from rhi_gen.render.fake_robot_views import has_fake_robot
from tests.support import vendor_msgs
from tests.support.cpp_build import DISTROS, FLAVOURS, fake_robot_source, package_digest, project_robot_labels

DISTROS_BUILT = ("humble", "rolling")
CLEAN_ENV = {k: v for k, v in os.environ.items()
             if k not in ("ROS_AUTOMATIC_DISCOVERY_RANGE", "ROS_LOCALHOST_ONLY", "ROS_STATIC_PEERS")}


def fake_robot_labels(reference) -> list[str]:
    return [b.label for b in reference.builds if has_fake_robot(b.model)]


def build_executable(builder, rb, distro: str):
    m = rb.model
    pkg = rb.package_dir
    includes = [pkg / "include", *DISTROS[distro].include_dirs]
    objects = [builder.compile(source, FLAVOURS["plain"], includes, digest_parts=[package_digest(pkg)],
                               name=f"fakeexe_{source.stem}_{m.vendor}_{m.robot}_{distro}", distro=distro,
                               transport=m.transport)
               for source in (pkg / "src" / "fake_robot_main.cpp", fake_robot_source(pkg, m.vendor, m.robot))
               if source is not None]
    for o in objects:
        assert o.ok, f"{o.path.name}: {' '.join(o.command)}\n{o.stderr[-6000:]}"
    link = builder.link(objects, FLAVOURS["plain"], f"fakeexe_{m.vendor}_{m.robot}_{distro}")
    assert link.ok, link.stderr[-4000:]
    return link.path


def run(binary, *args: str, env: dict[str, str] | None = None, timeout: float = 60) -> subprocess.CompletedProcess:
    return subprocess.run([str(binary), *args], capture_output=True, text=True, timeout=timeout,
                          env={**CLEAN_ENV, **(env or {})})


def test_robots_with_a_fake_robot(reference):
    """Every robot whose transport has a fake robot side gets its executable (the PM01 among them)."""
    labels = fake_robot_labels(reference)
    assert "engineai/pm01" in labels
    for b in reference.builds:
        assert (fake_robot_source(b.package_dir, b.model.vendor, b.model.robot) is not None) == has_fake_robot(b.model)
    assert set(labels) <= set(project_robot_labels())


@pytest.mark.parametrize("distro", DISTROS_BUILT)
def test_fake_robot_executable_guards_the_network(reference, cpp_builder, distro):
    labels = fake_robot_labels(reference)
    for label in labels:
        rb = reference.build(label)
        reason = vendor_msgs.skip_reason(rb.model.transport)
        if reason:
            continue  # its messages cannot be generated here (no ../shared): the harness section says so too
        binary = build_executable(cpp_builder, rb, distro)
        name = f"{rb.model.robot}_fake_robot"

        helped = run(binary, "--help")
        assert helped.returncode == 0 and "--allow-network" in helped.stdout and f"/{name}/fault" in helped.stdout

        refused = run(binary)
        assert refused.returncode == 2, refused
        lines = refused.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"{name}: refusing to start: "), refused.stderr
        assert "ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST" in lines[0] and "--allow-network" in lines[0]
        assert "use_fake_robot:=true" in lines[0]
        subnet = run(binary, env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET", "ROS_LOCALHOST_ONLY": "1"})
        assert subnet.returncode == 2 and "ROS_AUTOMATIC_DISCOVERY_RANGE is SUBNET" in subnet.stderr
        peers = run(binary, env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST", "ROS_STATIC_PEERS": "10.0.0.7"})
        assert peers.returncode == 2 and "ROS_STATIC_PEERS" in peers.stderr

        bad_rate = run(binary, "--rate", "0", env={"ROS_LOCALHOST_ONLY": "1"})
        assert bad_rate.returncode == 2 and "--rate 0: expected a rate in Hz" in bad_rate.stderr
        unknown = run(binary, "--fast", env={"ROS_LOCALHOST_ONLY": "1"})
        assert unknown.returncode == 2 and "unknown argument '--fast'" in unknown.stderr

        # Discovery on this host (or --allow-network): it starts and spins until stopped.
        for env, args in (({"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}, ()), ({"ROS_LOCALHOST_ONLY": "1"}, ()),
                          ({}, ("--allow-network",)), ({"ROS_LOCALHOST_ONLY": "1"}, ("--ros-args", "-p", "x:=1"))):
            with pytest.raises(subprocess.TimeoutExpired):
                run(binary, *args, env=env, timeout=1.5)
