"""Literal filters: what Python prints must mean exactly the same text to g++, lxml and YAML."""
from __future__ import annotations

import random
import subprocess

import yaml
from hypothesis import given, settings
from hypothesis import strategies as st
from lxml import etree

from rhi_gen.render.literals import cpp_double, cpp_string, header_guard, xml_escape
from rhi_gen.typed_yaml.yaml_source import yaml_string
from tests.support.cpp_build import require_compiler

HOSTILE = ['plain', 'quote"inside', "back\\slash", "new\nline", "tab\tcr\r", "trigraph??=", "é中文",
           "\x01ctrl", "end\\", '"', "*/ /* //", "\\x41", "?" * 5, "", "a\u2028b"]


def test_cpp_string_compiles_to_the_same_bytes(tmp_path):
    rng = random.Random(1234)
    samples = list(HOSTILE)
    alphabet = ['"', "\\", "\n", "?", "a", "7", "é", "\x00", "\x7f", "中", "x", "0", "'"]
    for _ in range(200):
        samples.append("".join(rng.choice(alphabet) for _ in range(rng.randint(0, 12))))
    body = ",\n".join(f"  std::string({cpp_string(s)}, {len(s.encode())})" for s in samples)
    src = tmp_path / "lit.cpp"
    src.write_text("#include <cstdio>\n#include <string>\n#include <vector>\n"
                   f"int main() {{\n  std::vector<std::string> v = {{\n{body}\n}};\n"
                   "  for (const auto& s : v) { for (unsigned char c : s) std::printf(\"%02x\", c); "
                   "std::printf(\"\\n\"); }\n}\n", encoding="utf-8")
    exe = tmp_path / "lit"
    subprocess.run([require_compiler(), "-std=c++17", "-Wall", "-Wextra", "-Werror", "-o", str(exe), str(src)],
                   check=True, capture_output=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout.splitlines()
    assert out == [s.encode("utf-8").hex() for s in samples]


@given(st.text())
def test_cpp_string_is_ascii_and_single_line(text):
    lit = cpp_string(text)
    assert lit.isascii() and "\n" not in lit and lit.startswith('"') and lit.endswith('"')


@settings(max_examples=200)
@given(st.text(alphabet=st.characters(exclude_categories=["Cs"], exclude_characters="\x00")))
def test_yaml_string_round_trips(text):
    assert yaml.safe_load(f"key: {yaml_string(text)}")["key"] == text


@settings(max_examples=200)
@given(st.text(alphabet=st.characters(min_codepoint=0x20, exclude_categories=["Cs"],
                                      exclude_characters="\ufffe\uffff")))
def test_xml_escape_round_trips_in_attributes(text):
    root = etree.fromstring(f'<a n="{xml_escape(text)}">{xml_escape(text)}</a>'.encode())
    assert root.get("n") == text and (root.text or "") == text


def test_cpp_double_round_trips():
    for value in (0.0, -0.0, 1.5, 1e-300, 2.8798, -3.14159265358979, 1e22, 123456789.0):
        text = cpp_double(value)
        assert float(text) == value
    assert cpp_double(float("inf")) == "std::numeric_limits<double>::infinity()"
    assert cpp_double(3) == "3.0"


def test_header_guard():
    assert header_guard("robot_hardware_interface/unitree/g1.hpp") == "ROBOT_HARDWARE_INTERFACE__UNITREE__G1_HPP_"
