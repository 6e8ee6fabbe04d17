"""The solver's numbers computed node by node in mpmath (dynsolve.solver.evaluate): the
samples a sign is read from, and numeric mode's residuals, give the verdicts sympy's
evalf gave."""

from __future__ import annotations

import math

import mpmath
import pytest
import sympy

from dynsolve.solver.evaluate import NotQuick, mp_size, mp_value
from dynsolve.solver.residuals import equation_residual
from dynsolve.solver.roots import _sample, sampled
from dynsolve.system import Equation

L, s, a, b = sympy.symbols("L s a b", positive=True)


def test_mp_value_of_a_textbook_form() -> None:
    # the stretch of a spring from a rod: sqrt(s^2 + L^2) - L; s = 4, L = 3 gives 5 - 3 = 2
    with mpmath.workdps(30):
        value = mp_value(sympy.sqrt(s**2 + L**2) - L, {s: mpmath.mpf(4), L: mpmath.mpf(3)})
    assert value == 2


def test_mp_value_refuses_what_it_does_not_know() -> None:
    with pytest.raises(NotQuick):
        mp_value(sympy.gamma(a), {a: mpmath.mpf(2)})
    with pytest.raises(NotQuick):
        mp_value(a + b, {a: mpmath.mpf(2)})  # b has no value


def test_mp_size_sums_magnitudes() -> None:
    # 3*(a - b) at a = b = 2: the terms are 3*2 and 3*2, size 3*(2 + 2) = 12
    assert mp_size(3 * (a - b), {a: mpmath.mpf(2), b: mpmath.mpf(2)}) == 12


def test_samples_of_a_positive_stretch_are_positive() -> None:
    # sqrt(L^2 + s^2) > L for every positive L, s (the hypotenuse is longer than a leg)
    values = sampled(sympy.sqrt(L**2 + s**2) - L)
    assert len(values) == 12 and all(v > 0 for v in values)


def test_a_sample_that_cancels_is_evalfs() -> None:
    # (sqrt(a) + 1)^2 - a - 1 - 2 sqrt(a) is 0 for every a: no quick value vouches for a sign,
    # so the sample is sympy's 20-digit evalf, as before the quick path
    zero = (sympy.sqrt(a) + 1) ** 2 - a - 1 - 2 * sympy.sqrt(a)
    point = {a: sympy.Rational(37, 10)}
    assert _sample(zero, point) == complex(sympy.N(zero.xreplace(point), 20))


def test_a_sample_agrees_with_the_hand_value() -> None:
    # atan(a - b) at a = 2, b = 1: atan(1) = pi/4
    found = _sample(sympy.atan(a - b), {a: sympy.Integer(2), b: sympy.Integer(1)})
    assert found == pytest.approx(math.pi / 4, rel=1e-15)


def test_quick_residual_reads_as_the_hand_residual() -> None:
    # x^2 = 2 at x = 7/5: |1.96 - 2| / max(1.96, 2) = 0.02
    x = sympy.Symbol("x")
    equation = Equation(x**2, 2, "line 3")
    for quick in (False, True):
        found = equation_residual(3, equation, {x: sympy.Rational(7, 5)}, quick=quick)
        assert found.relative == pytest.approx(0.02, rel=1e-12)
        assert found.evaluated


def test_quick_residual_of_a_symbolic_answer_is_a_spot_check() -> None:
    # v = sqrt(2 g h) put into v^2 = 2 g h holds at every point: not evaluated, ~0
    v, g, h = sympy.symbols("v g h", positive=True)
    equation = Equation(v**2, 2 * g * h, "energy")
    found = equation_residual(0, equation, {v: sympy.sqrt(2 * g * h)}, quick=True)
    assert not found.evaluated and found.relative < 1e-35


def test_quick_residual_falls_back_on_a_division_by_zero() -> None:
    x = sympy.Symbol("x")
    equation = Equation(1 / x, 1, "reciprocal")
    slow = equation_residual(0, equation, {x: sympy.Integer(0)})
    quick = equation_residual(0, equation, {x: sympy.Integer(0)}, quick=True)
    assert math.isnan(slow.relative) == math.isnan(quick.relative)
    assert slow.evaluated == quick.evaluated
