"""Root choice in symbolic problems when sympy's assumptions cannot decide a sign.

Regression: the collar problem (seed we_seed_collar-symbolic) kept both roots
v_0 = ±sqrt(k/W * g)*(sqrt(L^2 + s^2) - L), because sympy cannot tell that
sqrt(L^2 + s^2) - L > 0; the constraint v_0 >= 0 is now decided by sampling
positive values of the givens.
"""

import math

import pytest
import sympy

from dynsolve.solver import solve_system
from dynsolve.solver.roots import sampled, truth
from dynsolve.system import Constraint, Equation, EquationSystem

k, W, g, L, s = sympy.symbols("k W g L s", positive=True)
v = sympy.Symbol("v_0", real=True)


def test_spring_energy_root_is_chosen_by_the_declared_sign():
    # (W/g) v^2 / 2 = k (sqrt(s^2 + L^2) - L)^2 / 2  (seed 001, Sec. 4.4; gravity does no work)
    stretch = sympy.sqrt(s**2 + L**2) - L
    energy = Equation(W / g * v**2 / 2, k * stretch**2 / 2, "line 1", 1)
    system = EquationSystem(
        equations=(energy,), unknowns=(v,), constraints=(Constraint(v >= 0, "v_0 >= 0", 2),)
    )
    outcome = solve_system(system)
    assert outcome.status == "solved"
    expected = sympy.sqrt(k * g / W) * stretch
    value = outcome.values[v]
    point = {k: 5, W: 2, g: sympy.Rational(322, 10), L: 1, s: 2}
    assert abs(float((value - expected).subs(point))) < 1e-12
    assert not outcome.ambiguous


def test_sampling_decides_only_when_every_sample_agrees():
    x = sympy.Symbol("x", real=True)
    assert truth(x >= 0, {x: sympy.sqrt(L**2 + s**2) - L}) is True
    assert truth(x >= 0, {x: L - s}) is None  # sign depends on the givens
    assert sampled(x + L) == []  # x is not a positive given: no sampling


def test_a_lone_equation_is_solved_factor_by_factor() -> None:
    """The bar on a shaft at its steady angle: sin θ (Ω² cos θ − 3g/(2L)) = 0 (seed notes:
    θ_s = acos(3g/(2LΩ²)) besides θ = 0, π), solved with its common factor out, so the
    nonzero root reads as the notes write it (sympy gave 2 atan(…) for the whole)."""
    from dynsolve.solver.blocks import _symbolic_candidates

    theta = sympy.Symbol("theta", real=True)
    g, L, W = sympy.symbols("g L Omega", positive=True)
    residual = W**2 * sympy.sin(theta) * sympy.cos(theta) - 3 * g * sympy.sin(theta) / (2 * L)
    found, _ = _symbolic_candidates([residual], (theta,), 5.0, None)
    roots = [c.values[theta] for c in found.candidates]
    assert sympy.acos(3 * g / (2 * L * W**2)) in roots


def test_an_angle_from_sympy_is_written_in_the_principal_range() -> None:
    """sympy gives cos θ = c as acos(c) and 2π − acos(c); the root choice reads angles in
    (−π, π] (as the root search writes them), so the second is −acos(c): by hand the bar
    on a shaft's steady angles are 0, π and ±acos(3g/(2LΩ²))."""
    from dynsolve.solver.blocks import solve_block
    from dynsolve.system import SolveOptions

    theta = sympy.Symbol("theta_s", real=True)
    L, W, g, m = sympy.symbols("L Omega g m", positive=True)
    residual = (
        L**2 * W**2 * m * sympy.sin(theta) * sympy.cos(theta) / 3 - L * g * m * sympy.sin(theta) / 2
    )
    given = {L: sympy.Rational(6, 5), W: 4, g: sympy.Rational(981, 100), m: 3}
    found = solve_block([residual], [theta], given, SolveOptions(mode="exact"))
    values = sorted(float(c.values[theta]) for c in found.candidates)
    root = math.acos(3 * 9.81 / (2 * 1.2 * 16))
    assert values == pytest.approx([-root, 0.0, root, math.pi], rel=1e-12, abs=1e-300)
