"""tests/support/cpp_mutate.py: the C++ tokenizer, the token matcher and the two mutation kinds (pure Python)."""
from __future__ import annotations

import dataclasses

import pytest

from tests.support.cpp_mutate import (
    MutationError,
    SwapSlots,
    TokenEdit,
    apply_schema,
    code_of,
    disjoint_groups,
    find,
    replace,
    tokenize,
)


def texts(source: str) -> list[str]:
    return [t.text for t in tokenize(source)]


# ------------------------------------------------------------------------------------ tokenizer
def test_punctuators_take_the_longest_match():
    assert texts("a<<=b>>=c<=>d->e::f&&g||h...i->*j++k") == [
        "a", "<<=", "b", ">>=", "c", "<=>", "d", "->", "e", "::", "f", "&&", "g", "||", "h", "...", "i", "->*",
        "j", "++", "k"]
    assert texts("std::vector<std::vector<int>> v;") == [
        "std", "::", "vector", "<", "std", "::", "vector", "<", "int", ">>", "v", ";"]


def test_numbers_keep_their_suffixes_and_separators():
    tokens = tokenize("0x04C11DB7U 1.5e-3f 1'000'000ULL .5 0b1010 3.f 1e+9")
    assert [(t.kind, t.text) for t in tokens] == [
        ("number", "0x04C11DB7U"), ("number", "1.5e-3f"), ("number", "1'000'000ULL"), ("number", ".5"),
        ("number", "0b1010"), ("number", "3.f"), ("number", "1e+9")]
    assert texts("a.b+1-2") == ["a", ".", "b", "+", "1", "-", "2"]


def test_string_and_character_literals_are_one_token():
    source = r'''f("a // not a comment", 'x', '\'', "q\"uote", u8"u", L'w', R"d(raw "x" )" )d", "s"sv);'''
    tokens = tokenize(source)
    assert [t.kind for t in tokens] == [
        "identifier", "punct", "string", "punct", "char", "punct", "char", "punct", "string", "punct", "string",
        "punct", "char", "punct", "string", "punct", "string", "punct", "punct"]
    assert tokens[14].text == 'R"d(raw "x" )" )d"'
    assert tokens[16].text == '"s"sv'


def test_comments_and_whitespace_are_skipped_and_offsets_point_into_the_text():
    source = "int /* one */ a = 1;  // two\n/* multi\nline */ b\\\n;"
    tokens = tokenize(source)
    assert [t.text for t in tokens] == ["int", "a", "=", "1", ";", "b", ";"]
    assert all(source[t.start:t.end] == t.text for t in tokens)
    assert texts("a // continued \\\n still comment\nc") == ["a", "c"]


def test_preprocessor_lines_tokenize():
    assert texts('#include <rclcpp/rclcpp.hpp>\n#define CAT(a, b) a##b\n') == [
        "#", "include", "<", "rclcpp", "/", "rclcpp", ".", "hpp", ">", "#", "define", "CAT", "(", "a", ",", "b",
        ")", "a", "##", "b"]


@pytest.mark.parametrize("source", ['"open', "'x", "/* open", 'R"x(no end'])
def test_unterminated_literals_and_comments_raise(source):
    with pytest.raises(ValueError, match="unterminated"):
        tokenize(source)


def test_the_wildcard_is_a_token_of_patterns_only():
    assert [t.kind for t in tokenize("f($$)", pattern=True)] == ["identifier", "punct", "wildcard", "punct"]
    with pytest.raises(ValueError, match="not C\\+\\+"):
        tokenize("f($$)")


# ------------------------------------------------------------------------------------ matching
GUARD = """\
  const T * next()
  {
    // Layer 1: send nothing before the first valid state.
    if (!first_state_received_.load(std::memory_order_acquire)) {
      return nullptr;
    }
    return buffer_.get_data();
  }
"""
GUARD_PATTERN = "if (!first_state_received_.load(std::memory_order_acquire)) { return nullptr; }"


@pytest.mark.parametrize("variant", [
    GUARD,
    # reformatted: Allman braces, other indentation, wrapped call, no spaces
    GUARD.replace("if (!first_state_received_.load(std::memory_order_acquire)) {",
                  "if(!first_state_received_\n        .load( std::memory_order_acquire ))\n{"),
    GUARD.replace("    if (", "\t\t\tif (").replace("      return nullptr;", "return nullptr;"),
    # a single line
    GUARD.replace("{\n      return nullptr;\n    }", "{ return nullptr; }"),
])
def test_formatting_variants_match(variant):
    assert len(find(GUARD_PATTERN, variant)) == 1


@pytest.mark.parametrize("variant", [
    GUARD.replace("// Layer 1: send nothing before the first valid state.\n", ""),
    GUARD.replace("return nullptr;", "return nullptr;  // nothing yet"),
    GUARD.replace("(!first_state_received_", "(/* layer 1 */ !first_state_received_"),
    GUARD.replace("    }\n    return buffer_", "    }  // end of layer 1\n    return buffer_"),
])
def test_comment_only_differences_match(variant):
    assert len(find(GUARD_PATTERN, variant)) == 1


@pytest.mark.parametrize("variant", [
    GUARD.replace("first_state_received_", "first_state_seen_"),          # renamed identifier
    GUARD.replace("memory_order_acquire", "memory_order_relaxed"),       # another argument
    GUARD.replace("(!first", "( ! ! first"),                              # another expression
    GUARD.replace("::memory_order", ":: memory_order").replace("std::", "std."),
])
def test_changed_code_does_not_match(variant):
    assert find(GUARD_PATTERN, variant) == []
    with pytest.raises(MutationError, match=r"pattern not found in include/x\.hpp"):
        replace(variant, GUARD_PATTERN, "", where="include/x.hpp")


def test_tokens_match_whole_tokens_only():
    assert find("kHead0 = 0xFE", "kHead0 = 0xFEU;") == []            # a number with a suffix is another number
    assert find("pos[slot]", "pos_des[slot] + pos [ slot ]") == [(16, 28)]
    assert find('"a b"', 'f("a  b", "a b")') == [(10, 15)]            # inside literals spaces count


def test_counts_are_enforced():
    text = "{8, 2, 1, 0}, {8, 2, 1, 0}, {8, 24, kSlots, 28}"
    assert len(find("{8, 2, 1, 0}", text)) == 2
    with pytest.raises(MutationError, match=r"matched 2 times in unitree_hg\.hpp, expected 1"):
        replace(text, "{8, 2, 1, 0}", "{8, 4, 1, 0}", where="unitree_hg.hpp")
    assert replace(text, "{8,2,1,0}", "{8, 4, 1, 0}", count=2) == text.replace("{8, 2, 1, 0}", "{8, 4, 1, 0}")
    with pytest.raises(MutationError, match="matched 2 times"):
        replace(text, "{8, 2, 1, 0}", "{8, 4, 1, 0}", count=3)


def test_matches_do_not_overlap():
    assert len(find("a a", "a a a a a")) == 2


def test_splicing_keeps_every_other_byte():
    out = replace(GUARD, GUARD_PATTERN, "")
    start = GUARD.index("if (!first")
    end = GUARD.index("}\n    return buffer_") + 1
    assert out == GUARD[:start] + GUARD[end:]
    # a replacement inside a line: the comment after it and the layout around it stay as they were
    source = "  {8, 24, kMotorSlots, 28},   // motor_cmd[i].q .. reserve\n"
    assert replace(source, "{8, 24, kMotorSlots, 28}", "{8, 20, kMotorSlots, 28}") == (
        "  {8, 20, kMotorSlots, 28},   // motor_cmd[i].q .. reserve\n")
    # a match that starts or ends next to a comment does not take the comment
    source = "x = /* a */ f(1) /* b */;"
    assert replace(source, "f(1)", "g(2)") == "x = /* a */ g(2) /* b */;"


def test_a_replacement_must_be_lexically_cpp_and_errors_name_the_file():
    with pytest.raises(ValueError, match="unterminated"):
        replace(GUARD, GUARD_PATTERN, 'log("open);')
    with pytest.raises(MutationError, match=r"src/x\.cpp does not tokenize: unterminated string literal at line 2"):
        replace('int a;\nf("open);\n', "a", "b", where="src/x.cpp")


def test_the_wildcard_matches_the_shortest_balanced_run():
    source = "if (valid_) {\n  markFresh(now(a[1], {2, 3}));\n}\nif (valid_) { other(); }\n"
    spans = find("if (valid_) { markFresh($$); }", source)
    assert [source[s:e] for s, e in spans] == ["if (valid_) {\n  markFresh(now(a[1], {2, 3}));\n}"]
    # a whole block: the wildcard never crosses the brace that closes the block it started in
    block = "namespace ns\n{\nenum class E { kA, kB };\nstruct S { int f() { return 1; } };\n}  // namespace ns\n"
    (span,) = find("namespace ns { $$ }", block)
    assert block[span[0]:span[1]] == block[:block.index("}  // namespace")] + "}"
    # it takes at least one token and cannot close a bracket opened before it
    assert find("f($$)", "f()") == []
    assert find("g(f($$) x)", "g(f(a) b) x)") == []


def test_a_pattern_needs_code_and_anchors_around_a_wildcard():
    with pytest.raises(ValueError, match="no C\\+\\+ tokens"):
        find("// only a comment", "int a;")
    with pytest.raises(ValueError, match="tokens on both sides"):
        find("$$ ;", "int a;")


def test_code_of_drops_comments_around_the_code():
    assert code_of("// header\n\nnamespace n {\n}  // namespace n\n") == "namespace n {\n}"


# ------------------------------------------------------------------------------------ mutations
def test_token_edit_names_the_generated_file():
    plan = {"include/a.hpp": "int a = 1;\n", "src/b.cpp": "int b = 1;\n"}
    TokenEdit("include/a.hpp", "a = 1", "a = 2").apply_to_plan(plan, "demo")
    assert plan == {"include/a.hpp": "int a = 2;\n", "src/b.cpp": "int b = 1;\n"}
    with pytest.raises(MutationError, match=r"pattern not found in src/b\.cpp \(demo\)"):
        TokenEdit("src/b.cpp", "c = 1", "c = 2").apply_to_plan(plan, "demo")
    with pytest.raises(MutationError,
                       match=r"include/moved\.hpp: the package has no such file; it has include/a\.hpp, src/b\.cpp"):
        TokenEdit("include/moved.hpp", "a", "b").apply_to_plan(plan)


@dataclasses.dataclass(frozen=True)
class _Joint:
    name: str
    index: int


@dataclasses.dataclass(frozen=True)
class _Model:
    vendor: str
    robot: str
    joints: tuple[_Joint, ...]


def test_swap_slots_swaps_two_joints_and_keeps_the_rest():
    model = _Model("acme", "arm", (_Joint("elbow", 1), _Joint("shoulder", 0), _Joint("wrist", 4)))
    swapped = SwapSlots(0, 1).apply_to_model(model)
    assert swapped.joints == (_Joint("elbow", 0), _Joint("shoulder", 1), _Joint("wrist", 4))
    assert model.joints[0].index == 1  # the original model is untouched (frozen dataclasses)
    with pytest.raises(MutationError, match=r"acme/arm: no joint in SDK slot\(s\) \[2\]"):
        SwapSlots(1, 2).apply_to_model(model)


def test_every_generated_cpp_file_tokenizes_with_balanced_brackets(tmp_path):
    """The tokenizer reads every C++ file rhi-gen generates for the project's and the harness's robots
    (a mis-lexed literal or comment would show as unbalanced brackets)."""
    from rhi_gen.render.package import render_package
    from tests.support.cpp_build import load_models, make_test_project

    plan = render_package([r.model for r in load_models(make_test_project(tmp_path))])
    files = [path for path in plan if path.endswith((".hpp", ".cpp"))]
    assert any("common/driver_core.hpp" in path for path in files)
    pairs = {")": "(", "]": "[", "}": "{"}
    for path in files:
        stack: list[str] = []
        for token in tokenize(plan[path]):
            if token.kind == "punct" and token.text in "([{":
                stack.append(token.text)
            elif token.kind == "punct" and token.text in pairs:
                assert stack and stack.pop() == pairs[token.text], f"{path}: unbalanced at offset {token.start}"
        assert not stack, f"{path}: unclosed {stack}"


# ------------------------------------------------------------------------------------ mutation schemata
ON = "::rhi_mutant_on"


def schema_of(text: str, *edits: TokenEdit) -> str:
    """``text`` as include/a.hpp with ``edits`` switched in, numbered from 1; the declaration line dropped."""
    plan = {"include/a.hpp": text}
    apply_schema(plan, [(edit, n) for n, edit in enumerate(edits, 1)])
    declaration, rest = plan["include/a.hpp"].split("\n", 1)
    assert declaration.startswith('extern "C" bool rhi_mutant_on(int mutant) noexcept;')
    return rest


def test_statements_are_switched_whole():
    deleted = TokenEdit("include/a.hpp", "if (!ready()) { return nullptr; }", "", switch="statements")
    replaced = TokenEdit("include/a.hpp", "count_.add();", "count_.add(); count_.add();", switch="statements")
    text = "void f() {\n  if (!ready()) { return nullptr; }\n  count_.add();\n}\n"
    assert schema_of(text, deleted, replaced) == (
        "void f() {\n  if (!" + ON + "(1)) { if (!ready()) { return nullptr; } }\n"
        "  if (" + ON + "(2)) { count_.add(); count_.add(); } else { count_.add(); }\n}\n")


def test_an_operand_is_what_the_match_and_replacement_do_not_share():
    def switched(pattern: str, replacement: str, text: str) -> str:
        return schema_of(text, TokenEdit("include/a.hpp", pattern, replacement, switch="operand"))

    # the shared start and end stay; what differs is switched as an expression
    assert switched("if (facts.estop) {", "if (false) {", "if (facts.estop) {}") == \
        f"if (({ON}(1) ? (false) : (facts.estop))) {{}}"
    assert switched("x % d", "x % (d + 1)", "y = x % d;") == f"y = x % ({ON}(1) ? ((d + 1)) : (d));"
    # a shared end that would leave one side empty or unbalanced is not shared
    assert switched("a != g) {", "a != 0 * g) {", "if (a != g) {}") == f"if (a != ({ON}(1) ? (0 * g) : (g))) {{}}"
    assert switched("s(min(1.0, r))", "s(1.0 + r)", "s(min(1.0, r))") == f"s(({ON}(1) ? (1.0 + r) : (min(1.0, r))))"
    assert switched("c ? a : 0.0", "0.0", "v = c ? a : 0.0;") == f"v = ({ON}(1) ? (0.0) : (c ? a : 0.0));"


def test_overlapping_mutants_are_refused_and_grouped_apart():
    text = "void f() { if (valid) { fresh(); } }"
    whole = TokenEdit("include/a.hpp", "if (valid) { fresh(); }", "", switch="statements")
    condition = TokenEdit("include/a.hpp", "if (valid)", "if (true)", switch="operand")
    other = TokenEdit("include/a.hpp", "void f()", "void g()", switch="operand")
    with pytest.raises(MutationError, match="mutants 1 and 2 overlap"):
        schema_of(text, whole, condition)
    groups = disjoint_groups({"include/a.hpp": text}, [(whole, 1), (condition, 2), (other, 3)])
    assert [[n for _, n in group] for group in groups] == [[1, 3], [2]]


def test_an_edit_without_a_switch_is_not_put_in_a_schema():
    with pytest.raises(MutationError, match="not switchable"):
        schema_of("int a = 1;", TokenEdit("include/a.hpp", "a = 1", "a = 2"))
    with pytest.raises(MutationError, match="matched 0 times"):
        schema_of("int a = 1;", TokenEdit("include/a.hpp", "b = 1", "b = 2", switch="operand"))
