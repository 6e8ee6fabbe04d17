"""A stage chain's presolve in numeric mode (:func:`_polynomial_roots`): linear stages by
linsolve, a polynomial in one unknown by its roots, each root kept as sympy's solve keeps
it; the numbers by hand."""

from __future__ import annotations

import pytest
import sympy

from dynsolve.principles.stage_chain import _polynomial_roots


def test_fall_and_plastic_impact() -> None:
    """A ram (800 kg) falls 1.5 m: 400 v² = 800·9.81·1.5 = 11772 J, v = ±5.424942 m/s
    (its speed is the positive root); a 50 g bullet at 250 m/s embeds in a 2 kg bob:
    0.05·250 = 2.05 v, v = 6.097561 m/s (Hibbeler 15.4 style, plastic impact)."""
    v = sympy.Symbol("v_2_ram", real=True)
    roots = _polynomial_roots([11772 - 400 * v**2], [v])
    assert sorted(float(r[v]) for r in roots) == pytest.approx([-5.424942, 5.424942], rel=1e-6)
    a, b = sympy.symbols("vn_2_bob vn_2_bullet", real=True)
    equations = [-2 * a - b / 20 + sympy.Rational(25, 2), -a + b]
    (root,) = _polynomial_roots(equations, [b, a])
    assert root == {a: sympy.Rational(250, 41), b: sympy.Rational(250, 41)}
    assert float(root[a]) == pytest.approx(6.097561, rel=1e-7)


def test_roots_as_sympys_solve_keeps_them() -> None:
    """A positive time keeps its positive root only; no real root, none; a system that
    is not polynomial (a cosine of the unknown) is left to sympy's solve (None)."""
    t = sympy.Symbol("t", positive=True)
    assert _polynomial_roots([t**2 - 4], [t]) == [{t: 2}]
    x = sympy.Symbol("x", real=True)
    assert _polynomial_roots([x**2 + 1], [x]) == []
    assert _polynomial_roots([sympy.cos(x) - sympy.Rational(1, 2)], [x]) is None
    for equations, unknowns in (([t**2 - 4], [t]), ([x**2 + 1], [x])):
        assert _polynomial_roots(equations, unknowns) == sympy.solve(equations, unknowns, dict=True)
