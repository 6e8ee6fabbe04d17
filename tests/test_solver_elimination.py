"""Numeric mode's polynomial blocks by elimination (dynsolve.solver.elimination): every
root, from exact elimination down to one polynomial. Expected roots by hand."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import sympy

from dynsolve.solver.blocks import _eliminated_roots, solve_block
from dynsolve.solver.elimination import every_root
from dynsolve.system import SolveOptions

NUMERIC = SolveOptions(mode="numeric")


def _pairs(roots: list[dict], first: sympy.Symbol, second: sympy.Symbol) -> list[tuple]:
    return sorted((float(r[first].real), float(r[second].real)) for r in roots)


def test_rolling_disk_energy_block() -> None:
    # v = r ω (r = 0.5 m) and T = ½ m v² + ½ I ω² = 8 J (m = 2 kg, I = 0.5 kg m²):
    # ½·2·(0.5 ω)² + ½·0.5·ω² = 0.5 ω² = 8, so ω = ±4 rad/s, v = ±2 m/s
    v, w = sympy.symbols("v omega")
    residuals = [v - sympy.Rational(1, 2) * w, v**2 + sympy.Rational(1, 4) * w**2 - 8]
    assert _pairs(every_root(residuals, (v, w)), v, w) == [(-2.0, -4.0), (2.0, 4.0)]


def test_a_factor_splits_the_block() -> None:
    # a slide that stops: t (N − 98.1) = 0 and N t/5 = 3. t = 0 gives 0 = 3 (no root);
    # N = 98.1 gives t = 15/98.1 = 0.152905... s
    N, t = sympy.symbols("N t")
    residuals = [t * (N - sympy.Rational(981, 10)), N * t / 5 - 3]
    assert _pairs(every_root(residuals, (N, t)), N, t) == [(98.1, pytest.approx(15 / 98.1))]


def test_a_repeated_root_is_found_once() -> None:
    # x = y, (y − 1)² = 0: the one root (1, 1), as sympy's solve lists it
    x, y = sympy.symbols("x y")
    assert _pairs(every_root([x - y, (y - 1) ** 2], (x, y)), x, y) == [(1.0, 1.0)]


def test_floats_are_taken_as_the_decimals_they_print() -> None:
    # 0.25 v² = 4.375 − 0.5 w², v = w: 0.75 v² = 4.375, v = ±sqrt(35/6)
    v, w = sympy.symbols("v w")
    residuals = [sympy.Float("0.25") * v**2 + sympy.Float("0.5") * w**2 - 4.375, v - w]
    root = math.sqrt(35 / 6)
    found = _pairs(every_root(residuals, (v, w)), v, w)
    assert found == [(pytest.approx(-root), pytest.approx(-root)), (pytest.approx(root),) * 2]


def test_what_elimination_leaves_to_sympy() -> None:
    x, y = sympy.symbols("x y")
    assert every_root([x - y, 1 / x - 2], (x, y)) is None  # an unknown in a denominator
    assert every_root([x - y, (y - 1) ** 2 * sympy.sqrt(2)], (x, y)) is None  # repeated root
    assert every_root([x * y - 1, x**2 + y**2 - 4], (x, y)) is None  # nothing to eliminate
    assert every_root([x - y, 2 * x - 2 * y], (x, y)) is None  # dependent equations


def test_block_through_one_cosine() -> None:
    # a block leaving a dome (R = 1 m): v²/4 = (g/2) cos θ from the normal force, and
    # energy v²/4 = 10.06 − g cos θ (g = 9.81): (g/2 + g) cos θ = 10.06,
    # cos θ = 10.06/14.715; v = sqrt(2 g cos θ); θ = ±acos(cos θ), v > 0 declared
    v = sympy.Symbol("v", positive=True)
    theta = sympy.Symbol("theta", real=True)
    g = sympy.Rational(981, 100)
    residuals = [
        -(v**2) / 4 - g * sympy.cos(theta) + sympy.Rational(503, 50),
        -(v**2) / 4 + g * sympy.cos(theta) / 2,
    ]
    found = _eliminated_roots(residuals, (v, theta))
    cosine = 10.06 / 14.715
    expected = [(math.sqrt(2 * 9.81 * cosine), s * math.acos(cosine)) for s in (-1, 1)]
    got = sorted((float(c.values[v]), float(c.values[theta])) for c in found.candidates)
    assert got == [pytest.approx(e, rel=1e-13) for e in expected]
    assert "elimination" in found.note


def test_an_angle_at_its_branch_point_is_left_to_sympy() -> None:
    # cos θ = 1 (θ = 0, a double root of θ): ±acos would split it in two
    theta, v = sympy.symbols("theta v", real=True)
    assert _eliminated_roots([sympy.cos(theta) - 1, v - 2], (theta, v)) is None


def test_numeric_solve_block_takes_the_elimination() -> None:
    # the gear rolling on a fixed gear: ω_spin = 3 ω_CD and 0.185 ω_CD² + 0.01 ω_spin² = 62.83
    # (the energy): 0.275 ω_CD² = 62.8318530717959, ω_CD = ±15.1156...
    w_cd, w_spin = sympy.symbols("omega_CD omega_spin")
    residuals = [
        w_spin / 10 - 3 * w_cd / 10,
        -sympy.Float("0.185") * w_cd**2 - sympy.Float("0.01") * w_spin**2 + 20 * sympy.pi,
    ]
    solution = solve_block(residuals, [w_cd, w_spin], {}, NUMERIC)
    speeds = sorted(float(c.values[w_cd]) for c in solution.candidates)
    root = math.sqrt(20 * math.pi / 0.275)
    assert speeds == [pytest.approx(-root, rel=1e-14), pytest.approx(root, rel=1e-14)]
    assert solution.exhaustive and "elimination" in solution.note


def test_symbolic_roots_checked_at_samples_match_sympys_check() -> None:
    # energy of a fall: m v²/2 = m g h with v > 0 declared, letters positive: v = √(2 g h)
    # only (sympy's check drops −√(2 g h), which contradicts v > 0); h = v²/(2 g) then.
    m, g, h = sympy.symbols("m g h", positive=True)
    v = sympy.Symbol("v", positive=True)
    residuals = [m * v**2 / 2 - m * g * h]
    numeric = solve_block(residuals, [v], {}, NUMERIC)
    exact = solve_block(residuals, [v], {}, SolveOptions(mode="exact"))
    assert [c.values[v] for c in numeric.candidates] == [c.values[v] for c in exact.candidates]
    assert sympy.simplify(numeric.candidates[0].values[v] - sympy.sqrt(2 * g * h)) == 0


def test_a_spurious_symbolic_root_is_dropped() -> None:
    # sqrt(x) = a - x with a > 0: squaring gives x² − (2a + 1) x + a² = 0, whose larger root
    # (2a + 1 + √(4a + 1))/2 makes a − x < 0: not a root of the equation, as sympy finds
    a = sympy.Symbol("a", positive=True)
    x = sympy.Symbol("x", real=True)
    residuals = [sympy.sqrt(x) - a + x]
    numeric = solve_block(residuals, [x], {}, NUMERIC)
    exact = solve_block(residuals, [x], {}, SolveOptions(mode="exact"))
    assert len(numeric.candidates) == len(exact.candidates) == 1
    root = numeric.candidates[0].values[x]
    expected = (2 * a + 1 - sympy.sqrt(4 * a + 1)) / 2
    assert abs(float((root - expected).subs(a, 3))) < 1e-12


def test_a_pivot_with_an_irrational_sum_for_coefficient() -> None:
    # (1 + √2) x = y, y² = 2: y = ±√2, x = y/(1 + √2) = ±√2 (√2 − 1) = ±(2 − √2)
    x, y = sympy.symbols("x y")
    residuals = [(1 + sympy.sqrt(2)) * x - y, y**2 - 2]
    found = _pairs(every_root(residuals, (x, y)), x, y)
    expected = [(-(2 - math.sqrt(2)), -math.sqrt(2)), (2 - math.sqrt(2), math.sqrt(2))]
    assert found == [tuple(pytest.approx(v, rel=1e-14) for v in pair) for pair in expected]


def test_auto_mode_keeps_an_eliminated_block_in_floats() -> None:
    # a 40-lb disk rolled by a 15 ft·lb couple against a spring (rwe_seed_disk40lb): with
    # m = 40/32.2 = 200/161 slug, I_G = m (0.6 ft)², v_G = 0.8 ω: T = ½ m (0.64 + 0.36) ω²
    # = (100/161) ω² = U = 15 (0.625) − 10 (1²)/2 = 4.375 ft·lb, so ω = √(4.375·161/100)
    from dynsolve.pipeline import solve_file

    path = (
        Path(__file__).resolve().parent.parent / "problems" / "equations" / "rwe_seed_disk40lb.dyn"
    )
    for mode in ("numeric", "auto"):
        solution = solve_file(path, SolveOptions(mode=mode))
        omega = {row.name: row.value for row in solution.answers}["omega"]
        assert omega == pytest.approx(math.sqrt(4.375 * 161 / 100), rel=1e-13)
        assert any("elimination" in step.note for step in solution.steps)
    (precision,) = [c for c in solution.checks if c.name == "precision"]
    assert precision.detail.startswith("auto mode: numeric (float64) kept")
