"""Regression tests for crashes found by fuzzing (bench/fuzz.py, tests/test_fuzz.py)."""

from __future__ import annotations

import math

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app

SCENE = """\
problem: a direction vector naming an unknown
given:
  m = 2 kg
  r = 0.1 m
  g = 9.81 m/s^2
scene:
  body B: mass m, disk r, at (0, 0)
  point A: (0, -r)
  {line}
  gravity
find: F
"""


@pytest.mark.parametrize(
    ("line", "column"),
    [
        ("force F on B at A: (1, tan_beta)", 26),
        ("contact B at A: normal (1, -tan_beta), mu_k 0.2", 31),
    ],
)
def test_unknown_name_in_a_direction_vector_is_a_clean_error(tmp_path, line, column):
    # Columns counted by hand: two spaces of indent, then 23 (force) or 28 (contact) characters
    # before the name. Fuzz seed 1, input 2535: 'normal (x, -tan_beVta)' raised KeyError
    # from to_sympy.
    spec = tmp_path / "dir.dyn"
    spec.write_text(SCENE.format(line=line), encoding="utf-8")
    result = CliRunner().invoke(app, ["solve", str(spec)])
    assert result.exit_code == 2, result.output
    assert f"dir.dyn:9:{column}: 'tan_beta' in the scene is not a given" in result.output


DRAG = """\
problem: drag a = -k v^2 with an answer that find does not list
given:
  k = 0.5 1/m
  v_0 = 20 m/s
kinematics:
  a = -k*v^2
find: v_x = v(x)
answers:
  v_t = v_0/(1 + k*v_0*t)
"""


def test_kinematics_answer_not_in_find_is_a_clean_error(tmp_path):
    # Fuzz seed 1, input 26290 (a mutation of problems/kinematics/drag_a_of_v.dyn renamed a
    # find item): KeyError 'v_t' in the answer-key comparison. Equation mode already refused it.
    spec = tmp_path / "drag.dyn"
    spec.write_text(DRAG, encoding="utf-8")
    result = CliRunner().invoke(app, ["solve", str(spec)])
    assert result.exit_code == 2, result.output
    assert "drag.dyn:9:3: answer 'v_t' is not in find (hint: did you mean 'v_x'?)" in result.output


def test_a_constraint_with_a_side_that_is_not_real_is_a_clean_error(tmp_path):
    # Fuzz seed 2, input 37548: asin(1e15) is not real, and sympy's `<=` raised TypeError
    # ("Invalid comparison of non-real ...") with a traceback.
    spec = tmp_path / "c.dyn"
    spec.write_text(
        "equations:\n  a <= sqrt(asin(-1e-9+sqrt(1e30)))\n  a = 1\nfind: a\n", encoding="utf-8"
    )
    result = CliRunner().invoke(app, ["solve", str(spec)])
    assert result.exit_code == 2, result.output
    assert "c.dyn:2:3: this constraint compares a value that is not a real number" in (
        result.output
    )


@pytest.mark.parametrize(
    ("equation", "name", "expected"),
    [
        # 1e-9^1e-30 = exp(1e-30 * ln 1e-9) = 1 - 2.1e-29; sin(0.5) = 0.4794255386 (tables)
        ("theta = 1e-9^1e-30 + sin(.5)", "theta", 1.4794255386),
        # 0.5^1e-9/1e30 is about 1e-30, atan2(1e-30, 0.5) = 2e-30 rad, cos of it = 1
        ("t = cos(atan2(0.5^1e-9/1e30*1, .5))", "t", 1.0),
        # --3 = 3, 1e3^1e-30 = 1 (to 1e-29), exp(log(-9.81)) = -9.81: 3 - 1 - 9.81 = -7.81
        ("x = --3+-1e3^1e-30+exp(log(-9.81))", "x", -7.81),
    ],
)
@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_tiny_exponents_solve_fast(equation, name, expected, mode):
    # Open fuzz hangs: a Float^Float power such as 1e-9^1e-30 became a 10^30-th root of a
    # rational, and sympy's linsolve worked on it until the whole run's time budget (30 s).
    import time

    from dynsolve.pipeline import solve_text
    from dynsolve.system import SolveOptions

    started = time.process_time()
    solution = solve_text(
        f"equations:\n  {equation}\nfind: {name}\n", options=SolveOptions(mode=mode)
    )
    assert time.process_time() - started < 5.0
    (row,) = solution.answers
    assert row.value == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_a_huge_power_in_an_exponential_stays_within_memory(mode):
    # Fuzz memory hit: with t = 1e30 deg = 1.745e28 (a number in rad), the root finder tried
    # θ where t^θ is about 1e30 and mpmath built exp(1e30) digit by digit (over 2 GB).
    # By hand: at the root t^θ = 10^(28.24 θ) is about 1e-20, so θ = -0.5 - exp(-1.5)
    # = -0.5 - 0.22313 = -0.72313.
    from dynsolve.pipeline import solve_text
    from dynsolve.system import SolveOptions

    text = "given:\n  t = 1e30 deg\nequations:\n  theta = -.5-exp(t^theta-2+0.5)\nfind: theta\n"
    solution = solve_text(text, options=SolveOptions(mode=mode))
    (row,) = solution.answers
    assert row.value == pytest.approx(-0.5 - math.exp(-1.5), rel=1e-9)


def test_a_division_by_zero_in_an_equation_fails_a_check_instead_of_crashing(tmp_path):
    # fuzz seed 11, input 292: 'a = atan2(-a + 1e30, sin(cos(0.5)))/0' reached the numeric
    # search with sympy's zoo in it, and lambdify could not print zoo for mpmath (KeyError)
    spec = tmp_path / "zoo.dyn"
    spec.write_text(
        "given:\n  b = 1 m\nequations:\n  a = atan2(-a + 1e30*b/b, sin(cos(0.5)))/0\nfind: a\n",
        encoding="utf-8",
    )
    result = CliRunner().invoke(app, ["solve", str(spec)])
    assert result.exit_code == 1, result.output  # a failed check, not a traceback
    assert "division by zero" in result.output
