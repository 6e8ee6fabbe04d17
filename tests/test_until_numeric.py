"""A particle leaving its circle (:mod:`dynsolve.principles.until`): numeric mode writes
the rise of G by rotating r₁ instead of through atan2; both forms are the rise by hand."""

from __future__ import annotations

import math

import pytest
import sympy

from dynsolve.numbers import light_tidying
from dynsolve.principles.until import _rise


@pytest.mark.parametrize("numeric", [False, True])
def test_rise_of_a_block_leaving_a_cylinder(numeric: bool) -> None:
    """A block on a cylinder of R = 1.5 m released 20° from the top, leaving it after a
    further 31.21044° (cw): it rises R (cos(20° + 31.21044°) − cos 20°) = −0.4698463 m
    (by hand, the problem cylinder_block_released_off_top)."""
    R, phi, theta = sympy.symbols("R phi_0 theta", positive=True)
    r1 = (R * sympy.sin(phi), R * sympy.cos(phi))
    if numeric:
        with light_tidying():
            rise = _rise((0, 1), r1, R, -theta)
        assert not rise.has(sympy.atan2)
    else:
        rise = _rise((0, 1), r1, R, -theta)
    values = {R: sympy.Rational(3, 2), phi: sympy.pi / 9, theta: sympy.rad(31.21044)}
    expected = 1.5 * (math.cos(math.radians(20 + 31.21044)) - math.cos(math.radians(20)))
    assert float(rise.xreplace(values)) == pytest.approx(expected, rel=1e-13)
    assert expected == pytest.approx(-0.4698463, rel=1e-6)
