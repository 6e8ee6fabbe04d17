"""The second method of a particle's speed, F = m a integrated along its straight path
(:func:`dynsolve.principles.force_path.speed_by_integration`), with the numbers put in
and integrated in floats; expected speeds by hand (work and energy)."""

from __future__ import annotations

import math

import pytest
import sympy

from dynsolve.model.scene import Body, Load, Scene, Spring, Support, Travel
from dynsolve.principles.force_path import speed_by_integration

g = sympy.Symbol("g", positive=True)
G_VALUE = {g: sympy.Rational(981, 100)}


def _particle(mass: object, at: tuple[object, object]) -> Body:
    return Body("b", mass, 0, at, at, "particle", (), {}, True, "", 0, 0)


def test_bungee_cord_slack_then_stretched() -> None:
    """70 kg falling 20 m on a cord (k = 800 N/m, L₀ = 15 m) tied where it starts:
    v² = 2 g h − (k/m)(h − L₀)² = 392.4 − 285.714… (Hibbeler 14.2 style), v = 10.32888 m/s.
    The cord pulls only past 15 m: the integral is split where it goes taut."""
    k, L0, h, m = sympy.symbols("k L_0 h m", positive=True)
    cord = Spring("S", "b", (0, 0), "", (0, 0), k, L0, tension_only=True)
    fall = Travel("b", "by", distance=h, direction=(0, -1))
    scene = Scene({"b": _particle(m, (0, 0))}, {}, (), (), (), (0, -1), {}, springs=(cord,),
                  travels={"b": fall})  # fmt: skip
    values = {**G_VALUE, **{s: sympy.Integer(v) for s, v in ((k, 800), (L0, 15), (h, 20), (m, 70))}}
    expected = math.sqrt(2 * 9.81 * 20 - 800 / 70 * 25)
    found = speed_by_integration(scene, "b", {"g": g, "k": k}, values)
    assert found == pytest.approx(expected, rel=1e-12)


def test_pushed_up_a_rough_incline_by_a_spring_it_leaves() -> None:
    """2 kg against a spring (k = 800 N/m) compressed 0.2 m, on a 30° incline with
    μk = 0.2, run 0.5 m up: ½ m v² = ½ k δ² − m g s sin 30° − μk m g cos 30° s
    = 16 − 4.905 − 1.699 = 9.39590 J, v = 3.065266 m/s (by hand)."""
    c, s_ = sympy.sqrt(3) / 2, sympy.Rational(1, 2)
    start = (sympy.Rational(3, 10) * c, sympy.Rational(3, 10) * s_)
    spring = Spring("S", "b", start, "", (0, 0), 800, sympy.Rational(1, 2), compression_only=True)
    contact = Support("contact", "C", "b", start, (-s_, c), mu_k=sympy.Rational(1, 5))
    up = Travel("b", "by", distance=sympy.Rational(1, 2), direction=(c, s_))
    scene = Scene({"b": _particle(2, start)}, {}, (contact,), (), (), (0, -1), {},
                  springs=(spring,), travels={"b": up})  # fmt: skip
    work = 16 - 2 * 9.81 * 0.5 * 0.5 - 0.2 * 2 * 9.81 * math.sqrt(3) / 2 * 0.5
    found = speed_by_integration(scene, "b", {"g": g}, G_VALUE)
    assert found == pytest.approx(math.sqrt(work), rel=1e-12)


def test_unknown_load_or_symbolic_value_gives_no_second_method() -> None:
    """A load whose size is not a known quantity, or a letter left without a value: None."""
    P = sympy.Symbol("P", positive=True)
    push = Load("force", "P", "b", (0, 0), "G", (1, 0))
    slide = Travel("b", "by", distance=2, direction=(1, 0))
    scene = Scene({"b": _particle(3, (0, 0))}, {}, (), (), (push,), None, {},
                  travels={"b": slide})  # fmt: skip
    assert speed_by_integration(scene, "b", {}, {}) is None
    assert speed_by_integration(scene, "b", {"P": P}, {}) is None
    found = speed_by_integration(scene, "b", {"P": P}, {P: sympy.Integer(12)})  # v² = 2Ps/m = 16
    assert found == pytest.approx(4.0, rel=1e-13)
