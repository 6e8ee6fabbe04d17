"""sympy's internals never reach the reader (issue 25 item 14): polar_lift, exp_polar, Abs of
a number, an imaginary unit in a real time's formula, Integral(Piecewise(…)), hyper, **.
The guard (dynsolve.shown) first, then specs that make sympy produce each, in every format.
"""

import json
import re
from pathlib import Path

import pytest
import sympy
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.render.json import render_json
from dynsolve.render.latex import render_latex
from dynsolve.render.markdown import render_markdown
from dynsolve.shown import NOT_SHOWN, formula_latex, formula_text, presentable
from dynsolve.system import SolveOptions

PROBLEMS = Path(__file__).parent.parent / "problems"
x, t, v = sympy.symbols("x t v")
# what no formula shown may hold (Abs( of anything: the text writes abs(x))
FORBIDDEN = re.compile(r"polar_lift|exp_polar|Integral|Piecewise|hyper\(|Abs\(|\*\*|\bI\b")


# ---- the guard


def test_bookkeeping_is_replaced_by_its_tidy_equivalent():
    assert presentable(sympy.polar_lift(x) * t) == x * t
    assert presentable(sympy.exp_polar(-t)) == sympy.exp(-t)
    assert presentable(x * sympy.exp_polar(2 * sympy.I * sympy.pi)) == x  # e^{2πi} = 1
    assert formula_text(sympy.Abs(sympy.Float(-44.58), evaluate=False) + x) == "x + 44.58"


def test_a_form_without_a_tidy_equivalent_is_refused():
    integral = sympy.Integral(sympy.Piecewise((x, x > 0), (0, True)), (x, 0, t))
    assert presentable(integral) is None
    assert formula_text(integral) == NOT_SHOWN
    assert "no tidy formula" in formula_latex(integral)
    assert presentable(sympy.hyper((1, 2), (3,), x)) is None


def test_a_real_logarithms_imaginary_branch_is_dropped_and_any_other_imaginary_refused():
    # log(−c) = log c + iπ: a real time t(v) = log(v + 3) − log(v − 3) + iπ for v < 3 is
    # log|v + 3| − log|v − 3|
    real = presentable(sympy.log(v + 3) - sympy.log(v - 3) + sympy.I * sympy.pi)
    assert real == sympy.log(sympy.Abs(v + 3)) - sympy.log(sympy.Abs(v - 3))
    assert presentable(sympy.I * sympy.sqrt(v - 4)) is None  # no branch of a logarithm
    assert presentable((1 + sympy.sqrt(3) * sympy.I) * v) is None


def test_text_writes_powers_with_a_caret_and_abs_as_the_spec_language_does():
    assert formula_text(2 * v ** sympy.Rational(3, 2) * sympy.Abs(x)) == "2*v^(3/2)*abs(x)"
    assert formula_text(x**2, {x: sympy.Symbol("θ")}) == "θ^2"
    assert formula_latex(x**2, {x: "\\theta"}) == "\\theta^{2}"


# ---- specs that make sympy produce them


def _formulas(solution) -> list[str]:
    """Every formula text shown in the steps (formula, substituted, value, discarded)."""
    shown = []
    for step in solution.steps:
        shown += list(step.discarded)
        for row in step.results:
            shown += [row.formula, row.substituted, row.value, row.formula_latex]
    return shown


def test_a_drag_laws_time_shows_no_imaginary_unit_in_any_format():
    # drag_fall: m a = m g − c v², v_0 = 0: t(v) = √m/(2√(c g)) ln((c_v + v)/(c_v − v)), with
    # c_v = √(m g/c) = 3√109 = 31.32 m/s and √m/(2√(c g)) = √2/(2·√0.02·√9.81) = 1.596 s;
    # sympy writes it −1.596 log(v − c_v) + 1.596 log(v + c_v) + 5.015 i (1.596 π i)
    solution = solve_file(PROBLEMS / "kinematics" / "drag_fall.dyn")
    t_of_v = next(r for s in solution.steps for r in s.results if r.name == "t(v)")
    assert t_of_v.value == "-1.596*log(abs(v - 3*sqrt(109))) + 1.596*log(abs(v + 3*sqrt(109)))"
    path = str(PROBLEMS / "kinematics" / "drag_fall.dyn")
    terminal = CliRunner().invoke(app, ["solve", path], env={"COLUMNS": "200"}).output
    for text in (terminal, render_markdown(solution), render_latex(solution)):
        assert "5.015*I" not in text and "5.015 i" not in text
    steps = json.loads(render_json(solution))["steps"]
    assert not [r for s in steps for r in s["results"] if FORBIDDEN.search(r["value"])]


@pytest.mark.parametrize("mode", ["exact", "numeric", "auto"])
def test_a_time_whose_formula_holds_an_imaginary_unit_is_shown_in_numbers(mode):
    # a = −k v^(1/3): v^(2/3) = v_0^(2/3) − (2k/3) t, so v reaches v_1 at
    # t = 3 (v_0^(2/3) − v_1^(2/3))/(2k) = 3 (4.64159 − 2.92402)/1 = 5.1527 s; sympy's root
    # of the cubic holds (1 + √3 i): the formula is not shown, its number is
    spec = "given:\n  k = 0.5 m^(2/3)*s^(-5/3)\n  v_0 = 10 m/s\n  v_1 = 5 m/s\n"
    spec += "kinematics:\n  a = -k*v^(1/3)\nfind: t_2 = t_at(v, v_1)\n"
    solution = solve_text(spec, "cube.dyn", SolveOptions(mode=mode))
    assert solution.answers[0].value == pytest.approx(5.1527, rel=1e-4)
    assert not [f for f in _formulas(solution) if FORBIDDEN.search(f)]
    assert any(NOT_SHOWN in f for f in _formulas(solution))


def test_a_hypergeometric_time_with_exp_polar_is_shown_in_numbers():
    # a = −k x^(3/2): v² = v_0² − (4k/5) x^(5/2); t(x) = ∫ dx/v, for x = 2 m with v_0 = 10,
    # k = 0.5: t = ∫₀² (1/10)(1 + 0.002 x^2.5 + …) dx = 0.2 + 0.0002·2^3.5/3.5 + … = 0.20065 s;
    # sympy's t(x) is a hyper(…, x^(5/2) exp_polar(2πi)/…)
    spec = "given:\n  k = 0.5 m^(-1/2)/s^2\n  v_0 = 10 m/s\n  x_1 = 2 m\n"
    spec += "kinematics:\n  a = -k*x^(3/2)\nfind: t_3 = t_at(x, x_1)\n"
    solution = solve_text(spec, "hyper.dyn")
    assert solution.answers[0].value == pytest.approx(0.20065, rel=1e-4)
    assert not [f for f in _formulas(solution) if FORBIDDEN.search(f)]
    assert "exp_polar" not in render_latex(solution) + render_markdown(solution)


def test_abs_of_a_known_sign_is_resolved_in_formula_and_numbers():
    # projectile_cliff: at the top ρ = v_x²/g = (15 cos 40°)²/9.81 = 13.459 m; sympy's
    # (v_0² − v_0² sin²θ_0)^(3/2)/(g v_0 |cos θ_0|) has cos 40° > 0: no Abs((…)) shown
    solution = solve_file(PROBLEMS / "kinematics" / "projectile_cliff.dyn")
    rho = next(r for s in solution.steps for r in s.results if r.name == "rho_top")
    assert rho.formula == "v_0^2*cos(θ_0)^2/g"
    assert rho.substituted == "15^2*cos(40°)^2/9.81"
    assert rho.value == "13.5 m"


def test_no_python_power_reaches_a_kinematics_formula():
    # sqrt_drag_past_stop: a = −k √v stops at x_s = 2 v_0^(3/2)/(3k) = 2·27/9 = 6 m
    solution = solve_file(PROBLEMS / "kinematics" / "sqrt_drag_past_stop.dyn")
    assert not [f for f in _formulas(solution) if "**" in f]
    x_s = next(r for s in solution.steps for r in s.results if r.name == "x_s")
    assert x_s.formula == "2*v_0^(3/2)/(3*k)"


@pytest.mark.parametrize("mode", ["numeric", "auto"])
def test_a_drag_laws_time_is_real_in_every_mode(mode):
    # drag_fall in numeric mode: sympy writes t(v) with c (log(3√109) + iπ): distributed,
    # the iπ term dropped, t(v) = (50√109/327)(ln|v + c_v| − ln|v − c_v|), 50√109/327 = 1.596
    solution = solve_file(PROBLEMS / "kinematics" / "drag_fall.dyn", SolveOptions(mode=mode))
    t_of_v = next(r for s in solution.steps for r in s.results if r.name == "t(v)")
    assert not FORBIDDEN.search(t_of_v.value) and "log(abs(v - 3*sqrt(109)))" in t_of_v.value
    assert solution.answers[0].value == pytest.approx(23.022, rel=1e-4)  # the key's v_1
