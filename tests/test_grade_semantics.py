"""Grading semantics at their edges: sig figs, decimals, tolerances with units, directions,
wrong-dimension units, bad cells, the grading: section.

Keys are hand values: Hibbeler 12e Example 17.11 (drum and block), a = 4.5168 m/s^2 down
(a = alpha r, alpha = m_b g r/(I_O + m_b r^2) = 78.48/6.95 = 11.292 rad/s^2 cw),
T = I_O alpha / r = 3.75(11.292)/0.4 = 105.86 N.
"""

from __future__ import annotations

import pytest

from dynsolve.errors import DynsolveError
from dynsolve.grade.cells import CellError, read_cell, significant_figures
from dynsolve.grade.semantics import Key, Rule, judge, rules_for
from dynsolve.spec.parser import parse_spec
from dynsolve.units import Dim

A = Key("a", -4.5168, Dim.of("acceleration"), "m/s^2")  # down: negative
T = Key("T", 105.86, Dim.of("force"), "N")
ALPHA = Key("alpha", -11.292, Dim(0, 0, -2), "rad/s^2")  # cw: negative


@pytest.mark.parametrize(
    ("cell", "verdict"),
    [
        ("4.52 m/s^2", "correct"),  # 3 figures, within 0.51 of the 3rd figure (0.0051)
        ("4.517 m/s^2", "correct"),  # more figures than asked is fine
        ("4.5 m/s^2", "sigfig"),  # right to 2 figures, but 3 are asked
        ("4.50 m/s^2", "wrong"),  # 3 figures, |4.50 - 4.5168| = 0.017 > 0.0051
        ("4.53 m/s^2", "wrong"),  # 0.0132 > 0.0051
    ],
)
def test_sigfig_three(cell: str, verdict: str) -> None:
    key = Key("a", 4.5168, Dim.of("acceleration"), "m/s^2")
    assert judge(cell, key, Rule(sigfig=3)).verdict == verdict


def test_sigfig_edge_is_half_a_unit_of_the_last_figure() -> None:
    # key 4.5168, 3 figures: the last figure is 0.01; allowance 0.51 x 0.01 = 0.0051
    key = Key("a", 4.5168, Dim.of("acceleration"), "m/s^2")
    assert judge("4.5118 m/s^2", key, Rule(sigfig=3)).verdict == "correct"  # 0.0050
    assert judge("4.5116 m/s^2", key, Rule(sigfig=3)).verdict == "wrong"  # 0.0052


def test_significant_figures_as_written() -> None:
    assert significant_figures("0.00450") == 3  # leading zeros never count
    assert significant_figures("4.5e2") == 2
    assert significant_figures("106") == 3
    assert significant_figures("100") == 3  # trailing zeros of a whole number count


def test_decdig_in_the_unit_written() -> None:
    key = Key("T", 105.86, Dim.of("force"), "N")
    assert judge("105.86 N", key, Rule(decdig=2)).verdict == "correct"
    assert judge("105.9 N", key, Rule(decdig=2)).verdict == "sigfig"  # 1 decimal of 2
    assert judge("105.80 N", key, Rule(decdig=2)).verdict == "wrong"  # 0.06 > 0.0051


def test_any_unit_of_the_right_dimension() -> None:
    # 105.86 N / 4.44822 N/lb = 23.798 lb (lb is pound-force)
    assert judge("23.8 lb", T, Rule()).verdict == "correct"
    assert judge("0.106 kN", T, Rule()).verdict == "correct"
    # 4.5168 m/s^2 / 0.3048 = 14.819 ft/s^2
    assert judge("14.8 ft/s^2 down", A, Rule()).verdict == "correct"


def test_wrong_dimension_is_its_own_verdict() -> None:
    result = judge("4.52 m down", A, Rule())
    assert result.verdict == "dimension"
    assert "length" in result.detail and "acceleration" in result.detail
    assert judge("23.8 lbm", T, Rule()).verdict == "dimension"  # lbm is a mass


def test_directions_and_signs() -> None:
    assert judge("4.52 m/s^2 down", A, Rule()).verdict == "correct"
    assert judge("-4.52 m/s^2", A, Rule()).verdict == "correct"
    assert judge("11.3 rad/s^2 CW", ALPHA, Rule()).verdict == "correct"
    reversed_ = judge("4.52 m/s^2 up", A, Rule(partial=0.5))
    assert (reversed_.verdict, reversed_.credit) == ("sign", 0.5)
    assert judge("11.3 rad/s^2", ALPHA, Rule()).verdict == "correct"  # a bare magnitude
    assert judge("11.3 rad/s^2", ALPHA, Rule(signed=True)).verdict == "sign"  # ccw positive
    assert judge("-4.52 m/s^2 down", A, Rule()).verdict == "unreadable"  # sign and word


def test_tolerances_with_units() -> None:
    # rtol 1 %: 105.86 +- 1.0586 N
    assert judge("106.9 N", T, Rule(rtol=0.01)).verdict == "correct"
    assert judge("107.0 N", T, Rule(rtol=0.01)).verdict == "wrong"
    # atol 2 N (SI base) wins over rtol 1 % where larger
    assert judge("107.5 N", T, Rule(rtol=0.01, atol=2.0)).verdict == "correct"


def test_bare_numbers_take_the_header_unit_or_fail() -> None:
    assert judge("106", T, Rule(), header_unit="N").verdict == "correct"
    assert judge("23.8", T, Rule(), header_unit="lb").verdict == "correct"
    result = judge("106", T, Rule())
    assert result.verdict == "unreadable" and "no unit" in result.detail


@pytest.mark.parametrize(
    "cell",
    ["abc", "1e999 N", "__import__('os') N", "4.5 +- 1% N", "4.5 blargs", "x" * 200, "1 N 2"],
)
def test_bad_cells_are_wrong_with_a_reason(cell: str) -> None:
    result = judge(cell, T, Rule())
    assert result.verdict == "unreadable"
    assert result.credit == 0 and result.detail


def test_missing_cell() -> None:
    assert judge("  ", T, Rule()).verdict == "missing"


def test_read_cell_never_evaluates() -> None:
    with pytest.raises(CellError):
        read_cell("2**1000 N")


SPEC = """given:
  m = 2 kg
equations:
  W = m*g
  F = W
find: W, F
grading:
  sigfig 3
  atol 0.5 N
  partial 50%
  F weight 2
  F rtol 2%
"""


def test_grading_section_and_overrides() -> None:
    spec = parse_spec(SPEC, "g.dyn")
    rules = rules_for(["W", "F"], spec.grading)
    assert rules["W"] == Rule(rtol=0.01, atol=0.5, sigfig=3, partial=0.5)
    assert rules["F"].weight == 2 and rules["F"].rtol == 0.02 and rules["F"].sigfig == 0
    overridden = rules_for(["W"], spec.grading, Rule(decdig=2))
    assert overridden["W"].decdig == 2 and overridden["W"].sigfig == 0


@pytest.mark.parametrize(
    ("line", "message"),
    [
        ("rtol 1", "percentage"),
        ("sigfig 2.5", "whole number"),
        ("tolerance 3", "unknown grading rule"),
        ("atol 1 blarg", "unknown unit"),
        ("partial 150%", "more than full credit"),
    ],
)
def test_grading_errors_point_at_the_line(line: str, message: str) -> None:
    with pytest.raises(DynsolveError) as caught:
        parse_spec(
            f"given:\n  m = 2 kg\nequations:\n  W = m*g\nfind: W\ngrading:\n  {line}\n", "g.dyn"
        )
    assert message in str(caught.value)
    assert caught.value.position is not None and caught.value.position.line == 7


def test_solve_and_check_ignore_the_grading_section() -> None:
    from dynsolve.pipeline import solve_spec

    # W = m g = 2(9.81) = 19.62 N
    solution = solve_spec(parse_spec(SPEC + "answers:\n  W = 19.62 N\n", "g.dyn"))
    assert solution.passed and solution.answers[0].value == pytest.approx(19.62)
