"""The simulation's float functions are written without sympy's printers
(:mod:`dynsolve.simulate.compiled`), and a spring's length is a root sympy leaves as
written (:func:`dynsolve.simulate.equations.root`); the numbers are hand-derived."""

from __future__ import annotations

import math

import pytest
import sympy

from dynsolve.simulate.compiled import _Writer, float_function, float_scalar
from dynsolve.simulate.equations import Q, root

q, v = sympy.symbols("q v")


def test_spring_force_of_a_compression_spring() -> None:
    """k = 400 N/m, L₀ = 0.3 m, the ball at 0.2 + q above the base: at q = 0.05 the
    spring is 0.25 m long, compressed 0.05 m, and pushes up k·0.05 = 20 N; past
    q = 0.1 it has left the ball (0 N), and at the base itself (length 0) its branch
    is not evaluated at all."""
    length = root((q + sympy.Rational(1, 5)) ** 2)
    push = sympy.Piecewise((-400 * (length - sympy.Rational(3, 10)), length < 0.3), (0, True))
    (force,) = float_function([q], [push])(0.05)
    assert force == pytest.approx(20.0, rel=1e-14)
    assert float_function([q], [push])(0.15) == (0.0,)
    pull = sympy.Piecewise((400 / length, length > 0), (0, True))
    assert float_function([q], [pull])(-0.2) == (0.0,)  # 1/0 never evaluated


def test_pendulum_terms_and_shared_nodes() -> None:
    """A bob of 2 kg on a 1.2 m cord, q its angle from the bottom: T = ½ m L² q'² and
    V = m g L (1 − cos q); at q = 60° V = 2 × 9.81 × 1.2 × 0.5 = 11.772 J. sin q and
    cos q are each computed once."""
    L, m, g = sympy.Rational(6, 5), 2, sympy.Rational(981, 100)
    x, y = L * sympy.sin(q), -L * sympy.cos(q)
    M = m * (sympy.diff(x, q) ** 2 + sympy.diff(y, q) ** 2)
    V = m * g * (y + L)
    T_and_V = float_function([q, v], [M * v**2 / 2, V])
    kinetic, potential = T_and_V(math.pi / 3, 2.0)
    assert kinetic == pytest.approx(0.5 * 2 * 1.44 * 4.0, rel=1e-14)
    assert potential == pytest.approx(11.772, rel=1e-14)
    source = _Writer([q, v], [M, V, sympy.diff(V, q)]).source()
    assert source.count("math.sin(a0)") == 1 and source.count("math.cos(a0)") == 1


def test_scalar_and_a_node_left_to_lambdify() -> None:
    """float_scalar returns the number itself; a node the writer has no code for
    (Heaviside) is left to sympy's lambdify, with the same numbers."""
    assert float_scalar([q], sympy.sqrt(q) * 3)(16.0) == 12.0
    step = float_scalar([q], sympy.Heaviside(q - 1) * q)
    assert (step(2.0), step(0.5)) == (2.0, 0.0)


def test_root_is_smooth_and_evaluates_numbers() -> None:
    """d√(u²)/dq = u u'/√(u²): for u = 3q − 1 at q = 1, 3·2/2 = 3; √9 = 3 at once."""
    length = root((3 * Q - 1) ** 2)
    slope = sympy.diff(length, Q)
    assert float(slope.subs(Q, 1)) == pytest.approx(3.0, rel=1e-15)
    assert root(sympy.Integer(9)) == 3
    assert float_scalar([Q], slope)(1.0) == pytest.approx(3.0, rel=1e-15)


def test_placements_parametrized_by_the_travel_solved_one_unknown_at_a_time() -> None:
    """A bob on a 1.2 m link from O, released 60° from the vertical and turned q by its
    link: G = O + 1.2 (sin(60° − q), −cos(60° − q)), so it moves by
    (1.2 sin(60° − q) − 1.2 sin 60°, −1.2 cos(60° − q) + 1.2 cos 60°) (by hand); each
    position equation holds one unknown once the link's turn is q."""
    from dynsolve.model.scene import Body, Link, Scene, Travel
    from dynsolve.model.states import placements_of

    s3 = sympy.sqrt(3)
    G = (sympy.Rational(3, 5) * s3, -sympy.Rational(3, 5))
    bob = Body("bob", 2, 0, G, G, "particle", (), {}, True, "", 0, 0)
    cord = Link("cord", "bob", G, "", (0, 0))
    turn = Travel("cord", "turns", angle=-Q)
    scene = Scene({"bob": bob}, {}, (), (), (), (0, -1), {}, links=(cord,), travels={"cord": turn})
    placements, turns = placements_of(scene, simplify=False)
    shift = placements["bob"].shift
    for q_value in (0.0, 0.4, 1.1):
        x = 1.2 * math.sin(math.pi / 3 - q_value) - 1.2 * math.sin(math.pi / 3)
        y = -1.2 * math.cos(math.pi / 3 - q_value) + 1.2 * math.cos(math.pi / 3)
        assert float(shift[0].subs(Q, q_value)) == pytest.approx(x, abs=1e-14)
        assert float(shift[1].subs(Q, q_value)) == pytest.approx(y, abs=1e-14)
    assert turns["cord"] == -Q


def test_straight_line_force_of_a_compression_spring() -> None:
    """A 0.2 kg ball on a spring (k = 400 N/m, L₀ = 0.3 m) compressed 0.1 m, shot up:
    q'' = (k δ − m g)/m = (40 − 1.962)/0.2 = 190.19 m/s² at the start, −g = −9.81 once it
    has left the spring (q > 0.1), by hand; Q_c is the applied force along the line."""
    from dynsolve.model.scene import Body, Scene, Spring
    from dynsolve.simulate.equations import straight_line

    G = (0, sympy.Rational(1, 5))
    ball = Body("ball", sympy.Rational(1, 5), 0, G, G, "particle", (), {}, True, "", 0, 0)
    spring = Spring("S", "ball", G, "", (0, 0), 400, sympy.Rational(3, 10), compression_only=True)
    scene = Scene({"ball": ball}, {}, (), (), (), (0, -1), {}, springs=(spring,))
    g = sympy.Symbol("g", positive=True)
    motion = straight_line(scene, "ball", (0, 1), {"g": g}, {g: sympy.Rational(981, 100)})
    assert motion.acceleration(0.0, 0.0) == pytest.approx(190.19, rel=1e-13)
    assert motion.acceleration(0.15, 1.0) == pytest.approx(-9.81, rel=1e-13)
    assert motion.energy(0.0, 0.0) == pytest.approx(0.5 * 400 * 0.1**2, rel=1e-13)
