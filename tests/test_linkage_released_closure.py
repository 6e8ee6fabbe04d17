"""A loaded four-bar placed by loop closure, released under a couple (regression: exact mode
ran 20 s and then refused "a value of about 10^inf is out of range": eliminating its 15
acceleration equations exactly, with the closure's decimals in them, grew numbers to
10^36683). A block that large whose entries hold decimals is solved in floats with guard
digits, as numeric mode does.

Expected α_AB by Lagrange's equation, computed here independently of dynsolve: the crank
angle θ is the coordinate, C from the two circles |C − B| = L_BC, |C − D| = L_CD (the open
assembly, C above AD), T = ½ M(θ) θ'² with M = Σ m |dr_G/dθ|² + (m L²/12)(dφ/dθ)², V = Σ m g
y_G, and M θ'' + ½ M' θ'² = M_0 − V' (derivatives by central differences).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from dynsolve.pipeline import solve_text
from dynsolve.system import SolveOptions

SPEC = """\
given:
  d = 250 mm
  L_AB = 100 mm
  L_BC = 250 mm
  L_CD = 150 mm
  theta = 60 deg
  omega_0 = 6 rad/s
  m = 2 kg
  M_0 = 3 N*m
scene:
  point A: (0, 0)
  point D: (d, 0)
  bar AB: A to B, length L_AB, angle theta, mass m
  bar BC: B to C, length L_BC, mass m
  bar CD: C to D, length L_CD, mass m
  branch open
  omega AB: omega_0 ccw
  couple M_0 on AB: ccw
  gravity
find: al = alpha(AB)
"""
d, a, b, c, m, g = 0.25, 0.1, 0.25, 0.15, 2.0, 9.81


def _joints(theta: float) -> tuple[np.ndarray, np.ndarray]:
    B = a * np.array([math.cos(theta), math.sin(theta)])
    D = np.array([d, 0.0])
    e = D - B
    r = float(np.linalg.norm(e))
    along = (b * b - c * c + r * r) / (2 * r)
    up = math.sqrt(b * b - along * along)
    n = np.array([-e[1], e[0]]) / r
    return B, B + along * e / r + up * n  # the open assembly: C above AD


def _energy_terms(theta: float) -> tuple[list[np.ndarray], list[float]]:
    B, C = _joints(theta)
    A, D = np.zeros(2), np.array([d, 0.0])
    G = [(A + B) / 2, (B + C) / 2, (C + D) / 2]
    phi = [math.atan2(*(B - A)[::-1]), math.atan2(*(C - B)[::-1]), math.atan2(*(D - C)[::-1])]
    return G, phi


def _alpha_by_lagrange(theta: float, omega: float, M_0: float) -> float:
    h = 1e-5

    def mass(t: float) -> float:
        G1, p1 = _energy_terms(t + h)
        G0, p0 = _energy_terms(t - h)
        total = 0.0
        for L, g1, g0, q1, q0 in zip((a, b, c), G1, G0, p1, p0, strict=True):
            dG = (g1 - g0) / (2 * h)
            dphi = (q1 - q0) / (2 * h)
            total += m * float(dG @ dG) + m * L * L / 12 * dphi * dphi
        return total

    def potential(t: float) -> float:
        return sum(m * g * G[1] for G in _energy_terms(t)[0])

    M = mass(theta)
    dM = (mass(theta + h) - mass(theta - h)) / (2 * h)
    dV = (potential(theta + h) - potential(theta - h)) / (2 * h)
    return (M_0 - dV - 0.5 * dM * omega * omega) / M


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_a_loaded_four_bar_released_under_a_couple(mode):
    solution = solve_text(SPEC, "four_bar.dyn", SolveOptions(mode=mode))
    assert not any(check.failed for check in solution.checks)
    (al,) = solution.answers
    expected = _alpha_by_lagrange(math.radians(60), 6.0, 3.0)
    assert al.value == pytest.approx(abs(expected), rel=1e-6)
    assert al.direction == ("ccw" if expected > 0 else "cw")
