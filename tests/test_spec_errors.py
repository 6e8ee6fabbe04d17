"""Malformed specs: every error is a DynsolveError with the exact file, line, column and a hint.

Each case is a small spec written to a file and run through the whole pipeline
(``solve_file``), so errors found after parsing (unknown units, dimension conflicts,
find names, answer keys) are covered as well as syntax errors.

Columns are 1-based and counted in characters. Where a case's spec has a comment line
``#     ^`` straight after the offending line, the caret sits in the expected column
(``#`` is column 1); ``test_caret_comments_agree_with_expected_columns`` checks that
every caret agrees with the number written in the table.
"""

from __future__ import annotations

import re
import string
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dynsolve.errors import DimensionError, DynsolveError, SpecError, UnitError
from dynsolve.pipeline import solve_file
from dynsolve.spec.parser import parse_spec


def spec(*lines: str) -> str:
    """Spec text from its lines (so each line is one aligned literal in the table)."""
    return "\n".join(lines) + "\n"


@dataclass(frozen=True)
class Case:
    id: str
    text: str | bytes
    error: type[DynsolveError]
    line: int
    column: int
    message: tuple[str, ...] = ()  # substrings of error.message
    hint: str = ""  # substring of error.hint
    fixed: str = ""  # regression: the bug this case once exposed


# A tiny well-formed tail: W = m g, find W (used to reach post-parse checks).
TAIL = ("equations:", "  W = m*g", "find: W")
LONG_LINE = "  y = x" + " " * 1000 + "+ x"  # 1010 characters; the limit is 1000

CASES: list[Case] = [
    # ---- sections -------------------------------------------------------------------
    Case(
        "unknown-section",
        spec(
            "given:",
            "  m = 2 kg",
            "solution:",
            "  W = 19.6 N",
        ),
        SpecError, 3, 1,
        ("expected a section header", "'solution'"),
        "sections are problem, source, units, given, scene, kinematics, equations, find, "
        "define, answers",
    ),
    Case(
        "misspelt-section-equation",
        spec(
            "equation:",
            "  W = m*g",
        ),
        SpecError, 1, 1, ("'equation'",), "did you mean 'equations:'?",
    ),
    Case(
        "misspelt-section-givens",
        spec(
            "givens:",
            "  m = 2 kg",
        ),
        SpecError, 1, 1, ("'givens'",), "did you mean 'given:'?",
    ),
    Case(
        "duplicate-section",
        spec(
            "given:",
            "  m = 2 kg",
            "given:",
            "  k = 3 m",
        ),
        SpecError, 3, 1, ("section 'given' appears twice", "first on line 1"), "merge",
    ),
    Case(
        "indented-line-before-any-section",
        spec(
            "  m = 2 kg",
            "# ^",
            "given:",
        ),
        SpecError, 1, 3, ("indented line outside a section",), "start a section first",
    ),
    Case(
        "entries-on-given-header",
        spec(
            "given: m = 2 kg",
            "#      ^",
        ),
        SpecError, 1, 8,
        ("'given:' takes its entries on the following, indented lines",),
        "move 'm = 2 kg' to the next line",
    ),
    Case(
        "entries-on-equations-header",
        spec(
            "equations: W = m*g",
            "#          ^",
        ),
        SpecError, 1, 12, ("'equations:' takes its entries",), "move 'W = m*g'",
    ),
    Case(
        "missing-colon-after-section",
        spec(
            "given",
            "  m = 2 kg",
        ),
        SpecError, 1, 1, ("found 'given'",), "write 'given:' with a colon",
    ),
    Case(
        "missing-colon-after-inline-find",
        spec(
            "find W",
        ),
        SpecError, 1, 1, ("found 'find'",), "did you mean 'find:'?",
    ),
    Case(
        "unit-system-imperial",
        spec(
            "units: imperial",
            "#      ^",
        ),
        SpecError, 1, 8, ("unknown unit system 'imperial'",), "write 'units: FPS'",
    ),
    Case(
        "unit-system-unknown",
        spec(
            "units: cgs",
            "#      ^",
        ),
        SpecError, 1, 8, ("unknown unit system 'cgs'",), "'SI' or 'FPS'",
    ),
    # ---- givens and unit syntax -------------------------------------------------------
    Case(
        "given-without-value",
        spec(
            "given:",
            "  m =",
            "#    ^",
        ),
        SpecError, 2, 6, ("a given ends too early", "a number"), "'name = value unit'",
    ),
    Case(
        "given-name-only",
        spec(
            "given:",
            "  m",
            "#  ^",
        ),
        SpecError, 2, 4, ("a given ends too early", "'='"), "'name = value unit'",
    ),
    Case(
        "given-missing-equals",
        spec(
            "given:",
            "  m 2 kg",
            "#   ^",
        ),
        SpecError, 2, 5, ("unexpected '2' in a given",), "'name = value unit'",
    ),
    Case(
        "unit-trailing-slash",
        spec(
            "given:",
            "  m = 2 kg/",
            "#          ^",
        ),
        SpecError, 2, 12, ("a given ends too early",), "",
    ),
    Case(
        "unit-dangling-power",
        spec(
            "given:",
            "  a = 2 m/s^",
            "#           ^",
        ),
        SpecError, 2, 13, ("a given ends too early", "a number"), "",
    ),
    Case(
        "unit-double-slash",
        spec(
            "given:",
            "  v = 3 m//s",
            "#         ^",
        ),
        SpecError, 2, 11, ("unexpected '/' in a given",), "",
    ),
    Case(
        "given-name-starts-with-digit",
        spec(
            "given:",
            "  2m = 3 kg",
            "# ^",
        ),
        SpecError, 2, 3, ("unexpected '2' in a given", "a name"), "names start with a letter",
    ),
    Case(
        "unknown-unit-kgs",
        spec(
            "given:",
            "  m = 2 kgs",
            "#       ^",
            *TAIL,
        ),
        UnitError, 2, 9, ("unknown unit 'kgs'",), "did you mean 'kg'?",
    ),
    Case(
        "unknown-unit-in-find",
        spec(
            "given:",
            "  m = 2 kg",
            "equations:",
            "  W = m*g",
            "find: W [Nn]",
            "#        ^",
        ),
        UnitError, 5, 10, ("unknown unit 'Nn'",), "did you mean 'N'?",
    ),
    Case(
        "dimension-name-force-as-unit",
        spec(
            "given:",
            "  F = 2 force",
            "#       ^",
            "equations:",
            "  a = F/m",
            "find: a",
        ),
        UnitError, 2, 9, ("'force' is a dimension, not a unit",),
        "'name: force' for a symbolic given",
    ),
    Case(
        "dimension-name-mass-as-unit",
        spec(
            "given:",
            "  m = 2 mass",
            "#       ^",
            *TAIL,
        ),
        # regression: pint parsed 'mass' as m-as (milliarcsecond), so '2 mass' was
        # accepted silently as a tiny angle and W = m*g came out in m/s²
        UnitError, 2, 9, ("'mass' is a dimension, not a unit",), "write a unit such as 'kg'",
    ),
    Case(
        "unknown-dimension-of-symbolic-given",
        spec(
            "given:",
            "  m: massive",
            "#    ^",
            *TAIL,
        ),
        UnitError, 2, 6, ("unknown dimension or unit 'massive'",), "use a dimension",
    ),
    Case(
        "unit-outside-mechanics",
        spec(
            "given:",
            "  t = 30 degC",
            "#        ^",
            "equations:",
            "  y = t",
            "find: y",
        ),
        UnitError, 2, 10, ("outside mechanics",), "mechanical units",
    ),
    Case(
        "number-inside-unit",
        spec(
            "given:",
            "  L = 5 m*2",
            "#         ^",
        ),
        SpecError, 2, 11, ("a number '2' inside a unit",), "only '1' may appear in a unit",
    ),
    Case(
        "unit-exponent-too-large",
        spec(
            "given:",
            "  a = 2 m^13",
            "#         ^",
        ),
        SpecError, 2, 11, ("unit exponent 13 is out of range",), "",
    ),
    # ---- expression syntax ------------------------------------------------------------
    Case(
        "implicit-multiplication-of-names",
        spec(
            "equations:",
            "  T r = I_O*alpha",
            "#   ^",
        ),
        SpecError, 2, 5, ("unexpected 'r' in an equation",), "write an operator before 'r'",
    ),
    Case(
        "implicit-multiplication-number-name",
        spec(
            "equations:",
            "  F = 2m*a",
            "#      ^",
        ),
        SpecError, 2, 8, ("unexpected 'm' in an equation",), "write an operator before 'm'",
    ),
    Case(
        "unclosed-parenthesis",
        spec(
            "equations:",
            "  F = (m*a",
            "#         ^",
        ),
        SpecError, 2, 11, ("an equation ends too early", "')'"), "",
    ),
    Case(
        "extra-closing-parenthesis",
        spec(
            "equations:",
            "  F = m*a)",
            "#        ^",
        ),
        SpecError, 2, 10, ("unexpected ')' in an equation",), "",
    ),
    Case(
        "unknown-function-sinh",
        spec(
            "equations:",
            "  y = sinh(x)",
            "#     ^",
        ),
        SpecError, 2, 7, ("unknown function 'sinh'",), "did you mean 'sin'?",
    ),
    Case(
        "atan2-with-one-argument",
        spec(
            "equations:",
            "  t = atan2(y)",
            "#     ^",
        ),
        SpecError, 2, 7, ("atan2 takes 2 argument(s), got 1",), "atan2 takes (y, x)",
    ),
    Case(
        "sqrt-with-two-arguments",
        spec(
            "equations:",
            "  y = sqrt(x, 2)",
            "#     ^",
        ),
        SpecError, 2, 7, ("sqrt takes 1 argument(s), got 2",), "",
    ),
    Case(
        "function-name-used-as-variable",
        spec(
            "equations:",
            "  F = sin*m",
            "#     ^",
        ),
        SpecError, 2, 7, ("'sin' is a function and needs an argument",), "write sin(x)",
    ),
    Case(
        "reserved-given-pi",
        spec(
            "given:",
            "  pi = 3.14",
            "# ^",
        ),
        SpecError, 2, 3, ("'pi' is reserved",), "choose another name",
    ),
    Case(
        "reserved-given-sin",
        spec(
            "given:",
            "  sin = 2",
            "# ^",
        ),
        SpecError, 2, 3, ("'sin' is reserved",), "choose another name",
    ),
    Case(
        "duplicate-given",
        spec(
            "given:",
            "  m = 2 kg",
            "  m = 3 kg",
            "# ^",
        ),
        SpecError, 3, 3, ("'m' is given twice", "first on line 2"), "remove one",
    ),
    # ---- numeric and size limits ------------------------------------------------------
    Case(
        "literal-exponent-out-of-range",
        spec(
            "given:",
            "  m = 1e500 kg",
            "#     ^",
        ),
        SpecError, 2, 7, ("exponent 500 is out of range", "100"), "",
    ),
    Case(
        "negative-literal-exponent-in-equation",
        spec(
            "equations:",
            "  W = m*g*1e-500",
            "#         ^",
        ),
        SpecError, 2, 11, ("exponent -500 is out of range",), "",
    ),
    Case(
        "power-exponent-too-large",
        spec(
            "equations:",
            "  y = x^1000",
            "#      ^",
        ),
        SpecError, 2, 8, ("exponent 1000 is too large", "64"), "",
    ),
    Case(
        "too-many-digits",
        spec(
            "given:",
            "  m = " + "1" * 41 + " kg",
            "#     ^",
        ),
        SpecError, 2, 7, ("more than 40 digits",), "round it",
    ),
    Case(
        # "  y = " is 6 characters, so the 41st "(" is in column 6 + 41 = 47.
        "parentheses-nested-41-deep",
        spec(
            "equations:",
            "  y = " + "(" * 41 + "x" + ")" * 41,
        ),
        SpecError, 2, 47, ("parentheses nested more than 40 levels",), "split",
    ),
    Case(
        # 41 nested unary minus signs: the 41st operator (column 6 + 41 = 47) is the
        # first one beyond the 40 levels the language allows, as for parentheses above.
        "expression-nested-41-operators-deep",
        spec(
            "equations:",
            "  y = " + "-" * 41 + "x",
        ),
        SpecError, 2, 47, ("nested more than 40 levels",), "split",
        fixed="the depth check counts the equation line and the leaf name as levels: "
        "39 nested operators are already rejected, and the column is one operator early (46)",
    ),
    Case(
        "line-longer-than-1000-characters",
        spec("equations:", LONG_LINE),
        SpecError, 2, 1001, ("1010 characters", "limit is 1000"), "break",
    ),
    Case(
        "control-character-bel",
        spec(
            "equations:",
            "  y = x\x07 + 1",
            "#      ^",
        ),
        SpecError, 2, 8, ("control character U+0007",), "remove it",
    ),
    Case(
        "control-character-form-feed",
        spec(
            "given:",
            "  m = 2\x0ckg",
            "#      ^",
        ),
        SpecError, 2, 8, ("control character U+000C",), "remove it",
        fixed="str.splitlines() treats form feed (and \\v, \\x1c-\\x1e, \\x85, \\u2028) as a line "
        "break, so the character is never reported; instead 'expected a section header, "
        "found 'kg'' is reported on a line 3 that no editor shows",
    ),
    Case(
        "line-numbers-after-a-form-feed-in-a-comment",
        spec(
            "given:",
            "  m = 2 kg   # drum mass\x0c",
            "  x = 3 kgs",
            "#       ^",
            *TAIL,
        ),
        UnitError, 3, 9, ("unknown unit 'kgs'",), "did you mean 'kg'?",
        fixed="str.splitlines() splits at the form feed in the comment, so every later "
        "line number is one too large (reported on line 4)",
    ),
    Case(
        "too-many-statements",
        "given:\n" + "".join(f"  x{i} = 1\n" for i in range(1001)),
        SpecError, 1002, 3, ("more than 1000 statements",), "",
    ),
    Case(
        "too-many-lines",
        "\n" * 5001,
        SpecError, 5001, 1, ("more than 5000 lines",), "",
        fixed="the 5000-line limit is reported at 1:1, not at line 5001 where it is exceeded "
        "(docs: 'every limit reports the line and column where it was exceeded')",
    ),
    Case(
        "file-over-256-KiB",
        b"# " + b"x" * (256 * 1024) + b"\n",
        SpecError, 1, 1, ("262144 bytes",), "split",
    ),
    Case(
        "non-utf8-byte",
        b"given:\n  m = 2 k\xe9g\n",  # the byte \xe9 is the 10th character of line 2
        SpecError, 2, 10, ("not valid UTF-8",), "save it as UTF-8",
    ),
    Case(
        # "  m = 2 kg  # " is 14 characters, "α" is the 15th, " " the 16th, \xff the 17th
        # (the 18th byte: α is two bytes in UTF-8).
        "non-utf8-byte-after-a-multibyte-character",
        b"given:\n  m = 2 kg  # \xce\xb1 \xff\n",
        SpecError, 2, 17, ("not valid UTF-8",), "save it as UTF-8",
        fixed="the column of an undecodable byte counts bytes, not characters "
        "(reported as 18 after a two-byte 'α'), unlike every other column",
    ),
    # ---- find and answers -------------------------------------------------------------
    Case(
        "find-name-in-no-equation",
        spec(
            "equations:",
            "  T*r = I*alpha",
            "find: alpah",
            "#     ^",
        ),
        SpecError, 3, 7, ("'alpah' in find appears in no equation",), "did you mean 'alpha'?",
    ),
    Case(
        "find-listed-twice",
        spec(
            "given:",
            "  m = 2 kg",
            "equations:",
            "  W = m*g",
            "find: W, W",
            "#        ^",
        ),
        SpecError, 5, 10, ("'W' is listed twice in find",), "remove one",
    ),
    Case(
        "answer-not-in-find",
        spec(
            "equations:",
            "  T*r = I*alpha",
            "find: alpha",
            "answers:",
            "  alpah = 11.3 rad/s^2",
            "# ^",
        ),
        SpecError, 5, 3, ("answer 'alpah' is not in find",), "did you mean 'alpha'?",
    ),
    Case(
        "answer-with-sign-and-direction",
        spec(
            "given:",
            "  m = 2 kg",
            *TAIL,
            "answers:",
            "  W = -5 N cw",
            "#     ^",
        ),
        SpecError, 7, 7, ("magnitude with a direction, or a signed value, not both",), "cw",
    ),
    Case(
        "tolerance-with-wrong-unit",
        spec(
            "given:",
            "  m = 2 kg",
            *TAIL,
            "answers:",
            "  W = 19.6 N +- 1 m",
            "#                 ^",
        ),
        SpecError, 7, 19, ("tolerance unit m is length", "force"), "the answer's unit",
    ),
    Case(
        "answer-formula-uses-a-non-given",
        spec(
            "given:",
            "  m = 2 kg",
            *TAIL,
            "answers:",
            "  W = m*q",
            "#       ^",
        ),
        SpecError, 7, 9, ("uses 'q'",), "in terms of the givens",
    ),
    Case(
        # T = m g is a force; asking for it in m/s² is the mistake, on the find line.
        "find-unit-of-wrong-dimension",
        spec(
            "given:",
            "  m = 2 kg",
            "equations:",
            "  T = m*g",
            "find: T [m/s^2]",
            "#        ^",
        ),
        DimensionError, 5, 10, ("force",), "'N'",
        fixed="the find unit seeds T's dimension before inference, so the correct equation "
        "'T = m*g' (line 4) is blamed ('left side is an acceleration') instead of the find unit",
    ),
    # ---- dimensions -------------------------------------------------------------------
    Case(
        "dimension-conflict-between-sides",
        spec(
            "given:",
            "  m = 2 kg",
            "  a = 3 m/s^2",
            "  v = 4 m/s",
            "equations:",
            "  F = m*a",
            "  F = m*v",
            "# ^",
            "find: F",
        ),
        DimensionError, 7, 3, ("force", "momentum"), "a missing time derivative?",
    ),
    Case(
        "dimension-conflict-between-terms",
        spec(
            "given:",
            "  m = 2 kg",
            "  a = 3 m/s^2",
            "equations:",
            "  F = m*a + m",
            "#           ^",
            "find: F",
        ),
        DimensionError, 5, 13, ("cannot be added", "force", "mass"), "",
    ),
    Case(
        "sin-of-a-length",
        spec(
            "given:",
            "  L = 2 m",
            "equations:",
            "  y = sin(L)",
            "#         ^",
            "find: y",
        ),
        DimensionError, 4, 11, ("argument of sin", "length"), "",
    ),
    Case(
        "symbolic-power-of-a-dimensional-base",
        spec(
            "given:",
            "  m = 2 kg",
            "equations:",
            "  W = m*g^n",
            "#       ^",
            "find: W",
        ),
        DimensionError, 4, 9, ("base of a symbolic power", "acceleration"), "",
    ),
    Case(
        "undeterminable-dimensions",
        spec(
            "equations:",
            "  x*y = 2",
            "# ^",
            "find: x",
        ),
        DimensionError, 2, 3, ("cannot infer the dimension of x",), "find",
    ),
    # ---- missing sections -------------------------------------------------------------
    Case(
        "no-equations-section",
        spec(
            "given:",
            "  m = 2 kg",
            "find: m",
        ),
        SpecError, 1, 1, ("no equations to solve",), "add an 'equations:' section",
    ),
    Case(
        "no-find",
        spec(
            "given:",
            "  m = 2 kg",
            "equations:",
            "  W = m*g",
        ),
        SpecError, 1, 1, ("nothing to find",), "add a 'find:' line",
    ),
]  # fmt: skip


def _param(case: Case) -> object:
    marks: list = []
    return pytest.param(case, id=case.id, marks=marks)


def _write(directory: Path, case: Case) -> Path:
    path = directory / f"{case.id}.dyn"
    if isinstance(case.text, bytes):
        path.write_bytes(case.text)
    else:
        path.write_text(case.text, encoding="utf-8", newline="")
    return path


def test_table_is_large_and_ids_are_unique():
    assert len(CASES) >= 35
    assert len({c.id for c in CASES}) == len(CASES)


def test_caret_comments_agree_with_expected_columns():
    """A ``#   ^`` line right after the offending line marks the expected column."""
    checked = 0
    for case in CASES:
        if not isinstance(case.text, str):
            continue
        lines = case.text.split("\n")
        if case.line < len(lines) and re.fullmatch(r"#\s*\^", lines[case.line]):
            assert lines[case.line].index("^") + 1 == case.column, case.id
            checked += 1
    assert checked >= 40


@pytest.mark.parametrize("case", [_param(c) for c in CASES])
def test_malformed_spec_reports_position_message_and_hint(case: Case, tmp_path: Path):
    path = _write(tmp_path, case)
    with pytest.raises(DynsolveError) as info:
        solve_file(path)
    error = info.value
    assert isinstance(error, case.error), f"{type(error).__name__}: {error}"
    assert error.position is not None, str(error)
    assert error.position.file == str(path)
    assert (error.position.line, error.position.column) == (case.line, case.column), str(error)
    for part in case.message:
        assert part in error.message, str(error)
    assert case.hint in error.hint, str(error)
    # The rendered form is what the CLI prints.
    assert str(error).startswith(f"{path}:{case.line}:{case.column}: {error.message}")


def test_no_malformed_spec_raises_anything_but_a_dynsolve_error(tmp_path: Path):
    """Bad input never escapes as another exception type (no traceback for the user)."""
    escaped = []
    for case in CASES:
        path = _write(tmp_path, case)
        try:
            solve_file(path)
        except DynsolveError:
            pass
        except Exception as exc:  # the thing this test is about
            escaped.append(f"{case.id}: {type(exc).__name__}: {exc}")
    assert escaped == []


def test_expression_depth_limit_rejects_very_deep_nesting_on_its_line():
    """Whatever the exact count, a 60-deep expression is rejected at a column inside it."""
    line = "  y = " + "-" * 60 + "x"
    with pytest.raises(SpecError) as info:
        parse_spec(spec("equations:", line), "deep.dyn")
    error = info.value
    assert "nested more than 40 levels" in error.message
    assert error.position is not None and error.position.line == 2
    assert 7 <= error.position.column <= len(line)


# regression (fixed): the documented limit is 40 levels, but 39 nested operators are rejected (the
# equation line and the leaf count as levels)
def test_expression_forty_operators_deep_is_within_the_limit():
    parse_spec(spec("equations:", "  y = " + "-" * 40 + "x"), "deep.dyn")


def test_parentheses_forty_deep_are_within_the_limit():
    parse_spec(spec("equations:", "  y = " + "(" * 40 + "x" + ")" * 40), "deep.dyn")


def test_text_over_256_kib_is_rejected_by_parse_spec_too():
    with pytest.raises(SpecError) as info:
        parse_spec("# " + "x" * (256 * 1024), "big.dyn")
    assert info.value.position is not None
    assert (info.value.position.line, info.value.position.column) == (1, 1)


# regression (fixed): Fraction(1, 0) in unit_exponent escapes as lark
# VisitError(ZeroDivisionError): a traceback instead of a positioned error
def test_unit_exponent_with_zero_denominator_is_a_spec_error(tmp_path: Path):
    path = tmp_path / "zero.dyn"
    # "  a = 2 m^(1/0)": '(' is column 11, '1' 12, '0' 14.
    path.write_text(spec("given:", "  a = 2 m^(1/0)", *TAIL), encoding="utf-8")
    with pytest.raises(SpecError) as info:
        solve_file(path)
    assert info.value.position is not None
    assert info.value.position.line == 2
    assert info.value.position.column in (11, 12, 14)


@pytest.mark.parametrize(
    "text",
    [
        pytest.param(spec("given:", "  a = 2 m^13"), id="unit-exponent"),
        pytest.param("given:\n" + "".join(f"  x{i} = 1\n" for i in range(1001)), id="statements"),
        pytest.param("\n" * 5001, id="lines"),
    ],
)
# regression (fixed): limit errors without a hint (and the unit exponent message does not name its
# ±12 limit); docs promise a hint on every error
def test_limit_errors_name_the_limit_and_give_a_hint(text: str):
    with pytest.raises(SpecError) as info:
        parse_spec(text, "limit.dyn")
    error = info.value
    assert error.hint
    assert re.search(r"\b(12|1000|5000)\b", error.message + error.hint)


@pytest.mark.parametrize(
    "text",
    [
        pytest.param(spec("equations:", "  F = m*a)"), id="extra-parenthesis"),
        pytest.param(
            spec("given:", "  m = 2 kg", *TAIL, "answers:", "  W = 19.6 N cw down"),
            id="two-directions",
        ),
    ],
)
# regression (fixed): lark's end token leaks into the message: 'expected $end, ...' / 'expected
# <end-of-file>' for the end of a line
def test_messages_do_not_leak_parser_token_names(text: str, tmp_path: Path):
    path = tmp_path / "leak.dyn"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(SpecError) as info:
        solve_file(path)
    message = info.value.message
    assert "$end" not in message and "end-of-file" not in message and "$" not in message


# regression (fixed): _describe builds 'must be an pure number' for exponents and symbolic-power
# bases
def test_symbolic_power_message_is_grammatical(tmp_path: Path):
    path = tmp_path / "power.dyn"
    path.write_text(spec("given:", "  m = 2 kg", "equations:", "  W = m*g^n", "find: W"))
    with pytest.raises(DimensionError) as info:
        solve_file(path)
    assert "an pure" not in info.value.message
    assert "a pure number" in info.value.message


# regression (fixed): the '-' of a signed number counts as 'an operator expected', so a missing
# value gets the hint 'write an operator before 'kg''
def test_given_without_number_does_not_suggest_an_operator():
    with pytest.raises(SpecError) as info:
        parse_spec(spec("given:", "  m = kg"), "novalue.dyn")
    error = info.value
    assert error.position is not None
    assert (error.position.line, error.position.column) == (2, 7)
    assert "operator" not in error.hint
    assert "value" in error.hint


# a newcomer writes a textbook's omega = pi/2 rad/s as a given: the hint says how to write it
def test_pi_in_a_given_is_told_how_to_write_it():
    with pytest.raises(SpecError) as info:
        parse_spec(spec("given:", "  w = pi/2 rad/s"), "pi.dyn")
    error = info.value
    assert error.position is not None
    assert (error.position.line, error.position.column) == (2, 7)
    assert "1.570796 rad/s" in error.hint and "pi in the equations" in error.hint


# ---- random text never escapes as another exception ------------------------------------

SPEC_TOKENS = [
    "given:", "equations:", "find:", "answers:", "units:", "problem:", "SI", "FPS", "US",
    "  ", "\t", "#", "m", "x", "T", "alpha", "g", "pi", "sin", "atan2", "sqrt", "kg",
    "m/s^2", "N", "lb", "rad", "rev", "deg", "mass", "cw", "down", "=", ">=", "<", ":", ",",
    "(", ")", "[", "]", "^", "**", "*", "/", "+", "-", "+-", "±", "%", "·", "0", "1", "2.5",
    ".5", "1e5", "1e500", "9" * 45, "\x07", "é",
]  # fmt: skip
_spec_line = st.lists(st.sampled_from(SPEC_TOKENS), max_size=10).map(" ".join)
_indented_line = st.tuples(st.sampled_from(["", "  ", "\t"]), _spec_line).map("".join)
_spec_like = st.lists(_indented_line, max_size=8).map("\n".join)

_FUZZ = settings(
    max_examples=250,
    deadline=2000,  # ms per example: a hang or blow-up fails the test
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.too_slow],
)


def _parse_or_spec_error(text: str) -> None:
    try:
        parse_spec(text, "fuzz.dyn")
    except DynsolveError as error:
        assert error.position is None or error.position.line >= 1


@_FUZZ
@given(st.text(max_size=120))
def test_random_text_only_raises_dynsolve_errors(text: str):
    _parse_or_spec_error(text)


@_FUZZ
@given(_spec_like)
def test_random_spec_like_lines_only_raise_dynsolve_errors(text: str):
    _parse_or_spec_error(text)


@_FUZZ
@given(
    st.sampled_from(["given:", "equations:", "find:", "answers:"]),
    st.lists(
        st.text(alphabet=string.ascii_letters + string.digits + " =*/^+-()[],.:%#_", max_size=30),
        min_size=1,
        max_size=4,
    ),
)
def test_random_section_bodies_only_raise_dynsolve_errors(header: str, bodies: list[str]):
    _parse_or_spec_error(header + "\n" + "".join(f"  {b}\n" for b in bodies))


def test_a_unit_in_a_scene_line_is_told_to_become_a_given():
    # newcomer report: 'velocity ball: 20 m/s, right' got the hint "write an operator
    # before 'm'", which sends a newcomer the wrong way
    text = spec(
        "given:",
        "  m = 2 kg",
        "scene:",
        "  body ball: particle, mass m, at (0, 0)",
        "  velocity ball: 20 m/s, right",
        "  gravity",
        "find: a = a_G(ball)",
    )
    with pytest.raises(SpecError) as info:
        parse_spec(text, "units.dyn")
    assert (info.value.position.line, info.value.position.column) == (5, 21)
    assert "scene lines take no units" in info.value.hint and "given:" in info.value.hint


def test_degrees_in_a_scene_line_are_told_to_become_radians_or_a_given():
    # newcomer round: 'angle 180 deg + theta' got "for a product write '*' (e.g. '2*deg')",
    # and '180*deg' then failed with "'deg' in the scene is not a given"
    text = spec(
        "given:",
        "  d = 2 m",
        "  theta = 30 deg",
        "scene:",
        "  body block: particle, mass 1, at (0, 0)",
        "  travel block: by d, angle 180 deg + theta",
        "find: v = speed(block)",
    )
    with pytest.raises(SpecError) as info:
        parse_spec(text, "deg.dyn")
    assert "2*deg" not in info.value.hint
    assert "angle pi + theta" in info.value.hint and "given:" in info.value.hint


@pytest.mark.parametrize("kind", ["omega", "alpha"])
def test_a_rotation_without_its_sense_is_refused(kind):
    # newcomer report: 'omega AB: 3' was taken ccw without a word, so a cw drive came out
    # mirrored with every check green; 0 needs no sense
    text = spec(
        "given:",
        "  w = 3 rad/s",
        "scene:",
        "  point O: (0, 0)",
        "  body rod: mass 2, rod 1, at (0.5, 0)",
        "  pin rod at O",
        f"  {kind} rod: w",
        "find: O_n",
    )
    with pytest.raises(SpecError) as info:
        parse_spec(text, "sense.dyn")
    assert f"the sense of {kind} rod is missing" in info.value.message
    assert (info.value.position.line, info.value.position.column) == (7, len(kind) + 4)
    assert "cw" in info.value.hint
    parse_spec(text.replace(f"{kind} rod: w", f"{kind} rod: 0"), "zero.dyn")  # no sense needed


def test_a_bare_number_for_a_position_is_told_to_become_a_given():
    # newcomer round 6: 'joint C: near (3.4, 1.9)' got "check the units of the givens it
    # uses", but it uses no givens
    from dynsolve.pipeline import solve_text

    text = spec(
        "units: FPS",
        "given:",
        "  d = 4 ft",
        "  L_AB = 1 ft",
        "  L_BC = 4 ft",
        "  L_CD = 2 ft",
        "  theta = 120 deg",
        "  w_0 = 5 rad/s",
        "scene:",
        "  point A: (0, 0)",
        "  point D: (d, 0)",
        "  bar AB: A to B, length L_AB, angle theta",
        "  bar BC: B to C, length L_BC",
        "  bar CD: C to D, length L_CD",
        "  joint C: near (3.4, 1.9)",
        "  omega AB: w_0 cw",
        "find: w_BC = omega(BC)",
    )
    with pytest.raises(DynsolveError) as info:
        solve_text(text, "near.dyn")
    assert "givens it uses" not in info.value.hint
    assert "bare number has no unit" in info.value.hint
