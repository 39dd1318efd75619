"""robots/package.yaml: the generated package's owner (copyright, license, maintainer).

Optional: without it the package keeps neutral defaults (model.config.PackageInfo). Read with the
same YAML rules and one-line errors as a vendor YAML.
"""
from __future__ import annotations

import re
from pathlib import Path

from ..model import PackageInfo
from ..typed_yaml.validator import Validator
from ..typed_yaml.yaml_source import parse_yaml_text, read_text

FILE_NAME = "package.yaml"
KEYS = ("copyright", "license", "maintainer", "maintainer_email")
# SPDX license expressions: identifiers joined by AND / OR / WITH, optional parentheses.
LICENSE_RE = re.compile(r"^[A-Za-z0-9.+\-() ]{1,100}$")
EMAIL_RE = re.compile(r"^[^@\s<>\"]+@[^@\s<>\"]+$")
# One line of printable text: it becomes a comment line in every generated file.
TEXT_RE = re.compile(r"^[^\x00-\x1f\x7f]{1,80}$")


def load_package_info(robots_dir: Path, shown: str) -> PackageInfo:
    """robots/package.yaml when it exists, the defaults otherwise; ``shown`` names it in errors."""
    path = robots_dir / FILE_NAME
    if not path.exists():
        return PackageInfo()
    data, lines = parse_yaml_text(read_text(path, shown), shown)
    v = Validator(shown, lines)
    m = v.mapping(data, "", KEYS)
    default = PackageInfo()
    return PackageInfo(
        copyright=v.optional(m, "", "copyright",
                             lambda x, q: v.string(x, q, TEXT_RE, "copyright holder (one line, at most 80 "
                                                   "characters, e.g. \"2026 Acme Robotics GmbH\")"),
                             default.copyright).strip(),
        license=v.optional(m, "", "license",
                           lambda x, q: v.string(x, q, LICENSE_RE, "SPDX license identifier (e.g. Apache-2.0)"),
                           default.license).strip(),
        maintainer_name=v.optional(m, "", "maintainer",
                                   lambda x, q: v.string(x, q, TEXT_RE, "maintainer name"),
                                   default.maintainer_name).strip(),
        maintainer_email=v.optional(m, "", "maintainer_email",
                                    lambda x, q: v.string(x, q, EMAIL_RE, "e-mail address"),
                                    default.maintainer_email),
        source=shown,
    )
