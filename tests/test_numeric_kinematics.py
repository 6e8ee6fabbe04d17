"""Numeric mode's kinematics: plane motion built with the numbers put in, relations
inverted by peeling their operations, one numeric integration per time asked for.
Expected values from the hand derivations cited in each test."""

from __future__ import annotations

import math

import mpmath
import pytest
import sympy

from dynsolve.pipeline import solve_text
from dynsolve.principles.rectilinear import T, V, X, _inverse, integrate_motion, peeled_roots
from dynsolve.results import AnswerRow, Solution
from dynsolve.system import SolveOptions

NUMERIC = SolveOptions(mode="numeric")
k, v_0, c = sympy.symbols("k v_0 c", positive=True)
ZERO = sympy.Integer(0)

PROJECTILE = """\
problem: Projectile on level ground
given:
  v_0 = 20 m/s
  theta_0 = 30 deg
kinematics:
  v_x0 = v_0*cos(theta_0)
  v_y0 = v_0*sin(theta_0)
  a_x = 0
  a_y = -g
find: y_t = y(t), t_f = t_at(y, y_0), R = x(t_f), h = max(y), v_f = v(t_f)
"""


def _answers(text: str, mode: str) -> tuple[dict[str, AnswerRow], Solution]:
    """The answers by name, and the solution."""
    solution = solve_text(text, "p.dyn", SolveOptions(mode=mode))
    return {row.name: row for row in solution.answers}, solution


def test_projectile_numbers_first_gives_the_hand_values() -> None:
    # Hibbeler 12.6: v_y0 = 10 m/s, t_f = 2 v_y0/g, R = v_0² sin 60°/g, h = v_y0²/(2g), and
    # on level ground the landing speed is the launch speed (g = 9.81 m/s², the default)
    g = 9.81
    rows, solution = _answers(PROJECTILE, "numeric")
    assert rows["t_f"].value == pytest.approx(20 / g, rel=1e-12)
    assert rows["R"].value == pytest.approx(400 * math.sin(math.radians(60)) / g, rel=1e-12)
    assert rows["h"].value == pytest.approx(100 / (2 * g), rel=1e-12)
    assert rows["v_f"].value == pytest.approx(20, rel=1e-12)
    # the notes read the letters: a projectile, and the default g used by the answers
    names = {check.name for check in solution.checks}
    assert {"projectile", "standard gravity"} <= names


def test_projectile_numeric_keeps_exact_modes_checks() -> None:
    exact = solve_text(PROJECTILE, "p.dyn", SolveOptions(mode="exact"))
    numeric = solve_text(PROJECTILE, "p.dyn", NUMERIC)
    assert [(c.name, c.status) for c in exact.checks] == [
        (c.name, c.status) for c in numeric.checks
    ]


def test_plane_component_motion_gives_components_in_t_only() -> None:
    # a_y = -g along one axis of plane motion: v, x and a in t, no t(v) (never read)
    motion = integrate_motion(-c + 0 * T, "a(t)", ZERO, ZERO, v_0, in_time_only=True)
    assert set(motion.formulas) == {"a(t)", "v(t)", "x(t)"}


def test_peeled_inverse_of_quadratic_drag() -> None:
    # a = -k v²: t = (1/v - 1/v_0)/k, so v(t) = v_0/(1 + k v_0 t) (seed 001, §1.4.2)
    roots = peeled_roots((1 / V - 1 / v_0) / k, V, T)
    assert roots is not None and len(roots) == 1
    assert sympy.simplify(roots[0] - v_0 / (1 + k * v_0 * T)) == 0


def test_peeled_inverse_of_a_linear_spring() -> None:
    # a = -k x from x = 0 with v_0: t = asin(√k x/v_0)/√k, so x(t) = v_0 sin(√k t)/√k
    relation = sympy.asin(sympy.sqrt(k) * X / v_0) / sympy.sqrt(k)
    found = _inverse(relation, X, T, ZERO, ZERO, quick=True)
    assert sympy.simplify(found - v_0 * sympy.sin(sympy.sqrt(k) * T) / sympy.sqrt(k)) == 0


def test_peeling_leaves_two_branches_through_the_start_to_sympy() -> None:
    # v = v_0 + c t²/2 from rest in t: t = ±√(2 (v − v_0)/c) both pass (t, v) = (0, v_0);
    # which one exact mode takes is sympy's solve's choice, so numeric mode asks it too
    relation = v_0 + c * T**2 / 2
    assert _inverse(relation, T, V, v_0, ZERO, quick=True) == _inverse(relation, T, V, v_0, ZERO)


def test_peeling_gives_up_on_a_repeated_variable() -> None:
    assert peeled_roots(V**2 + V, V, T) is None
    assert peeled_roots(V**3, V, T) is None  # no listed inverse: sympy's solve decides


DRAG = """\
problem: A ball falling with quadratic drag
given:
  m = 2 kg
  c = 0.02 kg/m
  g = 9.81 m/s^2
  v_0 = 0 m/s
  t_1 = 3 s
kinematics:
  m*a = m*g - c*v^2
find: v_1 = v(t_1), x_1 = x(t_1)
"""


def test_one_integration_gives_x_and_v_at_a_time(monkeypatch: pytest.MonkeyPatch) -> None:
    # v(t) = v_T tanh(k t), x(t) = (m/c) ln cosh(k t), v_T = √(m g/c), k = √(g c/m):
    # v(3 s) = 23.022 m/s, x(3 s) = 38.859 m (drag_fall.dyn's hand derivation)
    calls = []
    original = mpmath.odefun

    def counted(*args: object, **kwargs: object) -> object:
        calls.append(args)
        return original(*args, **kwargs)

    monkeypatch.setattr(mpmath, "odefun", counted)
    sympy.core.cache.clear_cache()
    rows, _ = _answers(DRAG, "numeric")
    v_t, rate = math.sqrt(2 * 9.81 / 0.02), math.sqrt(9.81 * 0.02 / 2)
    assert rows["v_1"].value == pytest.approx(v_t * math.tanh(rate * 3), rel=1e-9)
    assert rows["x_1"].value == pytest.approx(100 * math.log(math.cosh(rate * 3)), rel=1e-9)
    assert len(calls) == 1
