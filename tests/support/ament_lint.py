"""Run the real ament_cpplint and ament_uncrustify on a package, as `colcon test` runs them.

ament_lint_auto's hooks (ament_cmake_cpplint, ament_cmake_uncrustify) run `ament_cpplint` and
`ament_uncrustify` with no path arguments from the package's source folder: every C/C++ file below
it, ament's default options (cpplint: line length 100 and ament's filters; uncrustify: the ROS 2
style of ament_code_style_0_78.cfg, picked because the binary is uncrustify 0.78.1). Both come from
the Jazzy wheels of the `test` extra; uncrustify from ros-jazzy-uncrustify-vendor, whose environment
hook puts `<prefix>/opt/uncrustify_vendor/bin` on PATH (done here by hand). Debian's uncrustify 0.72
formats differently and is never used.

    .venv/bin/python -m tests.support.ament_lint generated/robot_hardware_interface   # prints findings, exit 1 if any
"""
from __future__ import annotations

import os
import re
import subprocess
import sys
import sysconfig
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from tests.support.ros_msgs import require_dir

# The same checks by hand, from the repository root after `pip install -e '.[test]'`:
COMMAND_LINE = ("(cd generated/robot_hardware_interface && "
                'PATH="$OLDPWD/.venv/bin:$OLDPWD/.venv/opt/uncrustify_vendor/bin:$PATH"; '
                "ament_cpplint; ament_uncrustify)")
# `ament_uncrustify --reformat` (same folder and PATH) rewrites the files in the ROS 2 style.

_CPPLINT_LINE = re.compile(r"^(?P<file>.+?):(?P<line>\d+):\s+(?P<message>.*?)\s+\[(?P<rule>[^\]]+)\] \[\d\]$")
_DIVERGENCE = re.compile(r"^Code style divergence in file '(?P<file>.+)':$")
_HUNK = re.compile(r"^@@ -(?P<line>\d+)(?:,\d+)? \+\d+(?:,\d+)? @@")


@dataclass(frozen=True)
class Finding:
    linter: str     # "cpplint" or "uncrustify"
    file: str       # relative to the package folder, "/"-separated
    line: int       # 1-based; cpplint uses 0 for whole-file findings (e.g. legal/copyright)
    rule: str       # cpplint category, e.g. "whitespace/line_length"; "uncrustify" for a style divergence
    message: str    # cpplint's text; for uncrustify the diff hunk (- original, + ROS 2 style)


@dataclass
class UncrustifyResult:
    findings: list[Finding] = field(default_factory=list)   # one per diff hunk
    diffs: dict[str, str] = field(default_factory=dict)     # file -> ament_uncrustify's unified diff

    def lines_changed(self) -> dict[str, tuple[int, int]]:
        """file -> (lines removed, lines added) by the reformatting."""
        out = {}
        for name, diff in self.diffs.items():
            body = [ln for ln in diff.splitlines() if not ln.startswith(("---", "+++"))]
            out[name] = (sum(ln.startswith("-") for ln in body), sum(ln.startswith("+") for ln in body))
        return out


def linter_env() -> dict[str, str]:
    uncrustify_bin = require_dir("ros-uncrustify-vendor", "opt", "uncrustify_vendor") / "bin"
    scripts = sysconfig.get_path("scripts")
    return {**os.environ, "PATH": os.pathsep.join([scripts, str(uncrustify_bin), os.environ.get("PATH", "")]),
            "LC_ALL": "C", "LANG": "C"}


def _run(tool: str, package_dir: Path) -> subprocess.CompletedProcess:
    script = Path(sysconfig.get_path("scripts")) / tool
    proc = subprocess.run([sys.executable, str(script)], cwd=package_dir, capture_output=True, text=True,
                          env=linter_env(), timeout=600)
    if proc.returncode not in (0, 1) or "No files found" in proc.stderr:
        raise RuntimeError(f"{tool} did not run on {package_dir} (exit {proc.returncode}):\n"
                           f"{proc.stdout[-2000:]}\n{proc.stderr[-4000:]}")
    return proc


def _relative(name: str, package_dir: Path) -> str:
    path = Path(name)
    if path.is_absolute():
        resolved = path.resolve()  # a linked file (tests/cpp/test_cpp_sources.py) is named by its source
        path = resolved.relative_to(package_dir.resolve()) if resolved.is_relative_to(package_dir.resolve()) \
            else resolved
    return path.as_posix().removeprefix("./")


def run_cpplint(package_dir: Path) -> list[Finding]:
    proc = _run("ament_cpplint", package_dir)
    findings = []
    for line in proc.stderr.splitlines():
        m = _CPPLINT_LINE.match(line)
        if m:
            findings.append(Finding("cpplint", _relative(m["file"], package_dir), int(m["line"]), m["rule"],
                                    m["message"]))
    if proc.returncode == 1 and not findings:
        raise RuntimeError(f"ament_cpplint failed but printed no finding I can read:\n{proc.stderr[-4000:]}")
    return findings


def run_uncrustify(package_dir: Path) -> UncrustifyResult:
    proc = _run("ament_uncrustify", package_dir)
    result = UncrustifyResult()
    current: str | None = None
    hunk: list[str] = []
    hunk_line = 0

    def close_hunk():
        if current and hunk:
            result.findings.append(Finding("uncrustify", current, hunk_line, "uncrustify", "\n".join(hunk)))

    for line in proc.stderr.splitlines():
        m = _DIVERGENCE.match(line)
        if m:
            close_hunk()
            current, hunk = _relative(m["file"], package_dir), []
            result.diffs[current] = ""
            continue
        if current is None or not line:
            continue
        if re.match(r"^\d+ files with code style divergence$", line):
            continue
        result.diffs[current] += line + "\n"
        h = _HUNK.match(line)
        if h:
            close_hunk()
            hunk, hunk_line = [], int(h["line"])
        elif line.startswith(("-", "+")) and not line.startswith(("---", "+++")):
            hunk.append(line)
    close_hunk()
    if proc.returncode == 1 and not result.diffs:
        raise RuntimeError(f"ament_uncrustify failed but printed no divergence I can read:\n{proc.stderr[-4000:]}")
    return result


def summary(cpplint: list[Finding], uncrustify: UncrustifyResult) -> str:
    lines = [f"ament_cpplint: {len(cpplint)} findings"]
    lines += [f"  {n:5d} {rule}" for rule, n in Counter(f.rule for f in cpplint).most_common()]
    changed = uncrustify.lines_changed()
    lines.append(f"ament_uncrustify: {len(changed)} files to reformat, {len(uncrustify.findings)} hunks, "
                 f"{sum(r for r, _ in changed.values())} lines removed / {sum(a for _, a in changed.values())} added")
    lines += [f"  {name}: -{r} +{a}" for name, (r, a) in sorted(changed.items())]
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    package_dir = Path(argv[0] if argv else "generated/robot_hardware_interface")
    cpplint, uncrustify = run_cpplint(package_dir), run_uncrustify(package_dir)
    for f in cpplint:
        print(f"{f.file}:{f.line}: [{f.rule}] {f.message}")
    for name, diff in uncrustify.diffs.items():
        print(f"--- uncrustify: {name}\n{diff}")
    print(summary(cpplint, uncrustify))
    return 1 if cpplint or uncrustify.findings else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
