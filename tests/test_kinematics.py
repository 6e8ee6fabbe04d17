"""Rectilinear particle kinematics (seed notes 001, §1.4): a(t), a(v), a(x), x(t)."""

import math
from pathlib import Path

import pytest
import sympy

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file
from dynsolve.principles.rectilinear import T, V, X, integrate_motion

k, v0, c, w, x0, A = sympy.symbols("k v_0 c omega x_0 A", positive=True)
ZERO = sympy.Integer(0)


def same(a: sympy.Expr, b: sympy.Expr) -> bool:
    return sympy.simplify(a - b) == 0


def test_a_of_t():
    # a = c t: v = v_0 + c t^2/2, x = v_0 t + c t^3/6 (integrating twice from rest at 0)
    motion = integrate_motion(c * T, "a(t)", ZERO, ZERO, v0)
    assert same(motion.formulas["v(t)"], v0 + c * T**2 / 2)
    assert same(motion.formulas["x(t)"], v0 * T + c * T**3 / 6)


def test_a_of_v():
    # a = -k v^2: t(v) = (1/v - 1/v_0)/k, v(t) = v_0/(1 + k v_0 t), x(v) = ln(v_0/v)/k
    motion = integrate_motion(-k * V**2, "a(v)", ZERO, ZERO, v0)
    assert same(motion.formulas["t(v)"], (1 / V - 1 / v0) / k)
    assert same(motion.formulas["v(t)"], v0 / (1 + k * v0 * T))
    assert same(sympy.expand_log(motion.formulas["x(v)"] - sympy.log(v0 / V) / k, force=True), 0)
    assert same(motion.formulas["v(x)"], v0 * sympy.exp(-k * X))


def test_a_of_x_from_rest():
    # a = -omega^2 x released from x_0: v^2 = omega^2 (x_0^2 - x^2), moving toward -x,
    # x(t) = x_0 cos(omega t)
    motion = integrate_motion(-(w**2) * X, "a(x)", ZERO, x0, ZERO)
    assert same(motion.formulas["v(x)"], -w * sympy.sqrt(x0**2 - X**2))
    assert same(motion.formulas["x(t)"], x0 * sympy.cos(w * T))


def test_x_of_t():
    motion = integrate_motion(A * sympy.sin(w * T), "x(t)", ZERO, ZERO, ZERO)
    assert same(motion.formulas["v(t)"], A * w * sympy.cos(w * T))
    assert same(motion.formulas["a(t)"], -A * w**2 * sympy.sin(w * T))


SPEC = """\
given:
  a_c = 2 m/s^2
  v_0 = 3 m/s
  t_1 = 4 s
kinematics:
  {relation}
find: {find}
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "k.dyn"
    path.write_text(text)
    return path


def test_constant_acceleration_through_the_cli_pipeline(tmp_path):
    # v(t_1) = 3 + 2(4) = 11 m/s; x(t_1) = 3(4) + 2(16)/2 = 28 m
    text = SPEC.format(relation="a = a_c", find="v_1 = v(t_1), x_1 = x(t_1) [ft]")
    solution = solve_file(write(tmp_path, text))
    got = {a.name: a for a in solution.answers}
    assert got["v_1"].value == pytest.approx(11.0) and got["v_1"].unit == "m/s"
    assert got["x_1"].value == pytest.approx(28 / 0.3048)
    assert solution.mode == "kinematics" and solution.passed


def test_the_bundled_drag_problem_passes():
    path = Path(__file__).resolve().parent.parent / "problems" / "kinematics" / "drag_a_of_v.dyn"
    solution = solve_file(path)
    assert solution.passed, [c.detail for c in solution.checks if c.failed]
    v_1 = next(a for a in solution.answers if a.name == "v_1")
    assert v_1.value == pytest.approx(20 / 21, rel=1e-12)


@pytest.mark.parametrize(
    ("relation", "find", "message"),
    [
        ("a = a_c*t*v/v_0", "v_t = v(t)", "mixes t and v"),
        ("a = q*t", "v_t = v(t)", "'q' is neither a given"),
        ("b = a_c", "v_t = v(t)", "not a kinematic relation"),
        ("a = a_c", "v_t", "not a kinematic relation"),
        ("a = a_c", "v_1 = v(a_c)", "not a time, position or speed"),
    ],
)
def test_bad_kinematics_get_clear_errors(tmp_path, relation, find, message):
    with pytest.raises(SpecError) as caught:
        solve_file(write(tmp_path, SPEC.format(relation=relation, find=find)))
    assert message in caught.value.message
    assert caught.value.position is not None and caught.value.hint


def test_an_acceleration_law_needs_an_initial_velocity(tmp_path):
    text = "kinematics:\n  a = -k*v\ngiven:\n  k = 2 1/s\nfind: v_t = v(t)\n"
    with pytest.raises(SpecError) as caught:
        solve_file(write(tmp_path, text))
    assert "v_0" in caught.value.message


def test_same_answer_whatever_unit_the_time_is_given_in(tmp_path):
    # v(t_1) for a = a_c with t_1 = 4 s or 4000 ms or 1/15 min
    for t_1 in ("4 s", "4000 ms", "0.0666666666666667 min"):
        text = SPEC.replace("t_1 = 4 s", f"t_1 = {t_1}").format(
            relation="a = a_c", find="v_1 = v(t_1)"
        )
        value = solve_file(write(tmp_path, text)).answers[0].value
        assert math.isclose(value, 11.0, rel_tol=1e-9)


DRAG_FALL = Path(__file__).resolve().parent.parent / "problems" / "kinematics" / "drag_fall.dyn"


def test_newtons_law_with_a_drag_law_is_integrated():
    # m dv/dt = m g − c v² from rest: v = v_T tanh(k t), x = (m/c) ln cosh(k t) with
    # v_T = sqrt(m g/c), k = sqrt(g c/m) (separation of variables, by hand)
    solution = solve_file(DRAG_FALL)
    v_1, x_1 = solution.answers
    v_T, k = math.sqrt(2 * 9.81 / 0.02), math.sqrt(9.81 * 0.02 / 2)
    assert v_1.value == pytest.approx(v_T * math.tanh(k * 3), rel=1e-9)
    assert x_1.value == pytest.approx(2 / 0.02 * math.log(math.cosh(k * 3)), rel=1e-9)
    # regression: inverting t(v) used to run for minutes; now it gives up and integrates
    assert any(step.method == "numeric" for step in solution.steps)


def test_linear_drag_as_f_equals_ma_gives_the_exponential(tmp_path):
    # m dv/dt = −c v, v(0) = v_0: v = v_0 e^(−c t/m) = 10 e^(−0.5) = 6.0653 m/s at t = 1 s
    path = tmp_path / "drag.dyn"
    path.write_text(
        "given:\n  m = 2 kg\n  c = 1 kg/s\n  v_0 = 10 m/s\n  t_1 = 1 s\n"
        "kinematics:\n  m*a = -c*v\nfind: v_1 = v(t_1)\n"
    )
    (v_1,) = solve_file(path).answers
    assert v_1.value == pytest.approx(10 * math.exp(-0.5), rel=1e-12)


@pytest.mark.parametrize("quick", [False, True])
def test_t_of_v_from_rest_takes_the_branch_after_the_start(quick):
    # a = c t from rest at t = 0: v = c t²/2, so t(v) = +√(2 v/c) for t ≥ 0 and
    # x(v) = c t³/6 = (2 v/c)^(3/2) c/6 (by hand). Both ±√ pass (t, v) = (0, 0); the
    # derivation showed sympy's first, −√(2 v/c), and x(v) < 0 (regression).
    motion = integrate_motion(c * T, "a(t)", ZERO, ZERO, ZERO, quick=quick)
    assert same(motion.formulas["t(v)"], sympy.sqrt(2 * V / c))
    assert same(motion.formulas["x(v)"], c * (2 * V / c) ** sympy.Rational(3, 2) / 6)


def test_t_of_v_from_rest_in_a_spec_in_both_modes():
    # a = 2 m/s³ · t from rest: v = 9 m/s at t = 3 s, x(t = 3 s) = 9 m (by hand)
    spec = (
        "given:\n  c = 2 m/s^3\n  v_0 = 0 m/s\n  x_0 = 0 m\n  v_9 = 9 m/s\n"
        "kinematics:\n  a = c*t\nfind: t_v = t_at(v, v_9), t_w = t(v_9), x_w = x(v_9)\n"
    )  # t(v) and x(v) are derived when a find asks for them
    from dynsolve.pipeline import solve_text
    from dynsolve.system import SolveOptions

    for mode in ("exact", "numeric"):
        solution = solve_text(spec, "rest.dyn", SolveOptions(mode=mode))
        shown = {r.name: r for s in solution.steps for r in s.results}
        assert not shown["t(v)"].formula.startswith("-"), shown["t(v)"].formula
        assert not shown["x(v)"].value.startswith("-"), shown["x(v)"].value
        assert solution.answers[0].value == pytest.approx(3.0, rel=1e-12)
