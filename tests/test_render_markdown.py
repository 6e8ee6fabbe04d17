"""The Markdown renderer: escaping (unit and property-based), sections, tables and math."""

from __future__ import annotations

import itertools
import re
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st
from specs import DRUM as SHARED_DRUM

from dynsolve.pipeline import solve_file
from dynsolve.render.markdown import escape_markdown, render_markdown
from dynsolve.results import (
    AnswerRow,
    Check,
    EquationRow,
    Formula,
    GivenRow,
    KeyComparison,
    Solution,
    Step,
)

# the drum with Markdown-special characters in a note
DRUM = SHARED_DRUM.replace("(drum), CCW positive", "(drum) | 100% *of* the torque")

ROOTS = """\
problem: Positive root of a quadratic
given:
  k = 2 1/s^2   # stiffness per inertia
  c = 3 1/s     # damping per inertia
equations:
  w^2 - c*w - k = 0   # characteristic equation
  w >= 0              # ω ≥ 0: the positive root
find: w
"""

MARKDOWN_SPECIAL = set("\\`*_[]<>|$~#&")
NASTY = "Σ | \\ * _ ` [x](y) <b> $5$ ~ # & ² ≤ — ✓\n\n- item\r\n1. one"


def unescaped(out: str) -> set[str]:
    """Markdown punctuation in ``out`` that no backslash escapes."""
    found, chars = set(), iter(out)
    for char in chars:
        if char == "\\":
            next(chars, None)
        elif char in MARKDOWN_SPECIAL:
            found.add(char)
    return found


def cells(row: str) -> int:
    """How many cells a GFM table row has: a pipe right after a backslash is escaped."""
    return len(re.findall(r"(?<!\\)\|", row)) - 1


def solve_spec(tmp_path: Path, text: str) -> Solution:
    path = tmp_path / "spec.dyn"
    path.write_text(text, encoding="utf-8")
    return solve_file(path)


def nasty_solution(text: str) -> Solution:
    """A hand-built solution with ``text`` in every plain-text field and pipes in its math."""
    return Solution(
        file="x.dyn", title=text, source=text, system=text, mode="equations",
        givens=(GivenRow("m", text, text, text, False, "m", "\\left|m\\right|"),
                GivenRow("L", text, text, text, True, "L", "\\text{symbolic}")),
        equations=(EquationRow(3, text, "a = \\|b\\|", text, text, True, False),
                   EquationRow(4, text, "a \\ge 0", text, text, False, True)),
        steps=(Step(1, (3,), ("a",), text, (Formula("a", text, "\\|b\\|", text, "1"),),
                    (text,), text),),
        answers=(AnswerRow("a", 1.0, "m", "1.00 m", "1", "1.00\\,\\mathrm{m}", ""),
                 AnswerRow("b", None, "m", "not determined", "", "", "")),
        checks=(Check(text, True, text), Check(text, False, text)),
        key=(KeyComparison("a", text, text, True, text),),
        status=text, messages=(text,),
    )  # fmt: skip


# ---- escaping


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("m_d", r"m\_d"),
        ("a | b", r"a \| b"),
        ("*x* `y` [z]", r"\*x\* \`y\` \[z\]"),
        ("<b> & $5 ~ #1", r"\<b\> \& \$5 \~ \#1"),
        ("back\\slash", r"back\\slash"),
        ("- item", r"\- item"),
        ("+ item", r"\+ item"),
        ("1. one", r"1\. one"),
        ("-0.562 rad/s", "-0.562 rad/s"),
        ("0.15", "0.15"),
        ("a\n\nb\r\nc", "a b c"),
        ("ΣF ≤ μN ✓", "ΣF ≤ μN ✓"),
        ("", ""),
    ],
)
def test_escape_markdown(text: str, expected: str) -> None:
    assert escape_markdown(text) == expected


@given(st.text())
def test_escape_markdown_is_one_safe_line(text: str) -> None:
    out = escape_markdown(text)
    assert "\n" not in out and "\r" not in out
    assert unescaped(out) == set()
    assert not re.match(r"[-+] |\d+[.)]( |$)", out)


@given(st.text())
def test_tables_keep_their_columns(text: str) -> None:
    document = render_markdown(nasty_solution(text))
    lines = document.splitlines()
    separators = [
        i for i, line in enumerate(lines) if re.fullmatch(r"\| [-:]+( \| [-:]+)* \|", line)
    ]
    assert len(separators) == 4  # given, equations, answers, checks
    for index in separators:
        header = cells(lines[index - 1])
        rows = list(itertools.takewhile(lambda r: r.startswith("|"), lines[index + 1 :]))
        assert all(cells(row) == header for row in rows), (header, rows)


# ---- documents


def test_sections_and_content(tmp_path: Path) -> None:
    solution = solve_spec(tmp_path, DRUM)
    document = render_markdown(solution)
    lines = document.splitlines()
    assert lines[0] == "# Drum and hanging block"
    assert "*Hibbeler 12e Example 17.11*" in lines
    for heading in ("Given", "Equations", "Solution", "Answers", "Checks"):
        assert f"## {heading}" in lines
    for answer in solution.answers:
        assert f"${answer.latex}$" in document
        assert answer.shown.split()[0] in document


def test_tables_and_math(tmp_path: Path) -> None:
    document = render_markdown(solve_spec(tmp_path, DRUM))
    assert "| $m_{d}$ | $60\\,\\mathrm{kg}$ | 60" in document
    assert "| 12 | $I_{O} = m_{d} k_{O}^{2}$ | radius of gyration: I\\_O = m k\\_O² |" in document
    assert "ΣM\\_O = I\\_O α (drum) \\| 100% \\*of\\* the torque" in document
    assert "| moment of inertia, kg·m² ✓ |" in document
    assert "**Step 2.** Equations (lines 13–15) give $T$, $\\alpha$ and $a$ (linear):" in document
    # formula, then the givens put in (I_O = 3.75 kg·m², g = 9.81, m_b = 20 kg, r = 0.4 m), then T
    assert (
        "$$T = \\frac{I_{O} g m_{b}}{I_{O} + m_{b} r^{2}} = "
        "\\frac{3.75 \\cdot 9.81 \\cdot 20}{3.75 + 20 \\cdot 0.4^{2}} = 106\\,\\mathrm{N}$$"
    ) in document
    assert "| $\\alpha$ | $11.3\\,\\mathrm{rad/s^{2}}$ | 11.3 rad/s² ± 0.5% | ✓ |" in document
    assert "All 6 checks passed." in document
    assert document.endswith("|\n")


def test_discarded_roots(tmp_path: Path) -> None:
    document = render_markdown(solve_spec(tmp_path, ROOTS))
    assert "Discarded roots:\n\n- w = -0.562 rad/s: violates w \\>= 0 (line 7)" in document


def test_failures_and_missing_answers() -> None:
    document = render_markdown(nasty_solution("plain"))
    assert "**1 of 2 checks failed.**" in document
    assert "| ✗ | plain | plain |" in document
    assert "| $b$ | *not determined* |" in document
    assert "**dimensions differ**: plain ✗" in document
    assert "constraint: plain" in document
    assert "$\\left\\|m\\right\\|$" in document  # pipes in table math are escaped


def test_nasty_text_stays_in_its_place() -> None:
    document = render_markdown(nasty_solution(NASTY))
    assert document.startswith(f"# {escape_markdown(NASTY)}\n")
    assert "\n- item" not in document
