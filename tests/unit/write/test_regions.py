"""User regions: parsing (with file:line errors), splicing by name, orphans, stripping for hashes."""
from __future__ import annotations

import pytest

from rhi_gen.errors import RegionError, RhiGenError
from rhi_gen.render.markers import REGION_BEGIN, REGION_END, user_region
from rhi_gen.write.regions import parse_regions, region_bodies, splice, strip_bodies, user_code_regions


def _region(name: str, body: str = "", style: str = "//", indent: str = "") -> str:
    return f"{indent}{style} {REGION_BEGIN} {name}\n{body}{indent}{style} {REGION_END} {name}\n"


TEMPLATE_V1 = ("// banner\nint a = 1;\n" + _region("includes") + "void f() {\n" + _region("body", indent="  ")
               + "}\n" + _region("callbacks"))
TEMPLATE_V2 = ("// banner v2\nint a = 2;\nint b = 3;\n" + _region("includes") + "void f() {\n  g();\n"
               + _region("body", indent="    ") + "}\n" + _region("callbacks") + "// tail\n")


def test_render_helper_and_parser_agree():
    text = user_region("sdk_init", indent="    ") + "\n" + user_region("deps", "#") + "\n"
    regions = parse_regions(text, "x.cpp")
    assert [(r.name, r.begin_line, r.end_line) for r in regions] == [("sdk_init", 1, 2), ("deps", 3, 4)]
    assert all(r.body(text) == "" for r in regions)


def test_styles_hash_and_xml_comments():
    xml_region = "<!-- rhi-gen:begin-user-region b -->\n<tag/>\n<!-- rhi-gen:end-user-region b -->\n"
    text = _region("a", "x\n", "#") + xml_region
    assert region_bodies(text, "f") == {"a": "x\n", "b": "<tag/>\n"}


@pytest.mark.parametrize("text, line, words", [
    (f"x\n// {REGION_END} a\n", 2, "without a begin"),
    (f"// {REGION_BEGIN} a\nx\n", 1, "never closed"),
    (f"// {REGION_BEGIN} a\n// {REGION_END} a\n// {REGION_BEGIN} a\n// {REGION_END} a\n", 3, "appears twice"),
    (f"// {REGION_BEGIN} a\n// {REGION_BEGIN} b\n// {REGION_END} b\n// {REGION_END} a\n", 2, "cannot nest"),
    (f"// {REGION_BEGIN} a\n// {REGION_END} b\n", 2, "while region 'a'"),
    (f"int x; // {REGION_BEGIN} a\n// {REGION_END} a\n", 1, "stand alone"),
    (f"// {REGION_BEGIN}\n", 1, "no region name"),
    (f"// {REGION_BEGIN} a;b\n", 1, "invalid region name"),
])
def test_broken_markers_name_file_and_line(text, line, words):
    with pytest.raises(RegionError) as info:
        parse_regions(text, "generated/src/a.cpp")
    err = info.value
    assert isinstance(err, RhiGenError) and err.exit_code == 2
    assert str(err).startswith(f"generated/src/a.cpp:{line}: ")
    assert words in str(err)
    assert "\n" not in str(err)


def test_splice_keeps_bodies_byte_for_byte_while_surroundings_change():
    body_a = "#include <vendor/sdk.h>  \t// trailing spaces kept\n"
    body_b = "\tstrange_indent();\r\n    // unicode: µs ✓\n\n"
    old = TEMPLATE_V1.replace(_region("includes"), _region("includes", body_a)).replace(
        _region("body", indent="  "), _region("body", body_b, indent="  "))
    merged, orphans = splice(TEMPLATE_V2, old, "f.cpp")
    assert orphans == []
    assert region_bodies(merged, "f.cpp") == {"includes": body_a, "body": body_b, "callbacks": ""}
    # Everything outside the regions is the new template, markers included (re-indented as the template says).
    assert strip_bodies(merged) == strip_bodies(TEMPLATE_V2)
    assert "    // rhi-gen:begin-user-region body\n" in merged and "int b = 3;" in merged
    # Splicing again is a fixed point.
    assert splice(TEMPLATE_V2, merged, "f.cpp") == (merged, [])


def test_region_new_in_template_starts_empty_and_old_empty_region_may_vanish():
    old = "x\n" + _region("gone") + _region("kept", "k\n")
    new = "y\n" + _region("kept") + _region("fresh")
    merged, orphans = splice(new, old, "f")
    assert orphans == []
    assert region_bodies(merged) == {"kept": "k\n", "fresh": ""}


def test_region_dropped_by_the_template_with_code_is_reported_not_dropped():
    old = "x\n" + _region("sdk_init", "init_sdk();\n") + _region("blank", "  \n\n")
    merged, orphans = splice("y\n", old, "g.cpp")
    assert [(o.path, o.name, o.line) for o in orphans] == [("g.cpp", "sdk_init", 2)]
    assert merged == "y\n"  # the caller refuses to write this (see test_regenerate)


def test_user_code_regions_of_a_file_to_remove():
    text = _region("a") + _region("b", "code();\n")
    assert [o.name for o in user_code_regions(text, "f")] == ["b"]


def test_strip_bodies_is_what_a_hand_edit_check_compares():
    clean = TEMPLATE_V1
    inside = clean.replace(_region("callbacks"), _region("callbacks", "void cb() {}\n"))
    outside = clean.replace("int a = 1;", "int a = 42;")
    assert strip_bodies(inside) == strip_bodies(clean)
    assert strip_bodies(outside) != strip_bodies(clean)


def test_broken_old_file_is_an_error_for_splice():
    with pytest.raises(RegionError, match=r"^old\.cpp:1: "):
        splice(TEMPLATE_V2, f"// {REGION_BEGIN} includes\n", "old.cpp")
