"""Numeric mode's shortcuts (issue 14, part 3) keep exact mode's decisions and answers.

* While building in numeric mode (:func:`dynsolve.numbers.light_tidying`), a formula that
  is surely not 0 is left as written, but anything that may be 0 gets the full ``tidy``,
  so a test ``tidy(x) == 0`` answers as in exact mode.
* Where sympy's root check is skipped (numbers only), :func:`_holds` rejects what
  ``checksol`` would: a root off its equation, a value its unknown's assumptions forbid.
* On bundled problems, numeric mode gives exact mode's checks and answers (1e-12).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import sympy

from dynsolve.numbers import light_tidying, surely_nonzero, tidy, tidying_lightly
from dynsolve.pipeline import solve_file
from dynsolve.solver.blocks import _holds, solve_block
from dynsolve.system import SolveOptions

ROOT = Path(__file__).resolve().parent.parent
a, b, u = sympy.symbols("a b u", positive=True)
x = sympy.Symbol("x", real=True)


def test_light_tidying_leaves_a_nonzero_form_as_written() -> None:
    expr = a * b * sympy.sin(u) ** 2 + a * b * sympy.cos(u) ** 2
    assert tidy(expr) == a * b
    with light_tidying():
        assert tidying_lightly()
        assert tidy(expr) == expr
        assert tidy(expr, light=False) == a * b  # a decision read from the form
    assert not tidying_lightly()


@pytest.mark.parametrize(
    "zero",
    [
        sympy.sin(u) ** 2 + sympy.cos(u) ** 2 - 1,
        (a * b - b**2) / (a - b) - b,
        sympy.sqrt(3) * sympy.sqrt(a) - sympy.sqrt(3 * a),
        a * (sympy.sin(x) ** 2 + sympy.cos(x) ** 2) - a,
    ],
)
def test_light_tidying_still_finds_zero(zero: sympy.Expr) -> None:
    assert not surely_nonzero(zero)
    with light_tidying():
        assert tidy(zero) == 0


def testsurely_nonzero_only_with_digits() -> None:
    assert surely_nonzero(a - b + 1 - a + b - 1 + sympy.Rational(1, 10**20))
    assert not surely_nonzero(sympy.Function("f")(a))  # not a number: not known
    assert not surely_nonzero(sympy.Symbol("n", integer=True) - 1)  # no probe for an integer
    w = sympy.Symbol("w", negative=True)
    assert surely_nonzero(sympy.sqrt(-w))  # probed at a negative value: a real root


def test_holds_rejects_what_checksol_rejects() -> None:
    theta = sympy.Symbol("theta", real=True)
    residual = [sympy.sin(theta) * (2 * sympy.cos(theta) - 1)]
    assert _holds(residual, (theta,), {theta: sympy.pi / 3}, {})
    assert not _holds(residual, (theta,), {theta: sympy.oo * sympy.I}, {})
    assert not _holds(residual, (theta,), {theta: sympy.Rational(1, 2)}, {})
    t = sympy.Symbol("t", positive=True)
    squared = [t**2 - 4]
    assert _holds(squared, (t,), {t: sympy.Integer(2)}, {})
    assert not _holds(squared, (t,), {t: sympy.Integer(-2)}, {})  # t is positive
    g = sympy.Symbol("g", positive=True)
    assert _holds([t**2 - g], (t,), {t: sympy.sqrt(g)}, {g: sympy.Integer(9)})
    # a letter left (a symbolic given): judged at sample points of g > 0, as checksol would
    assert _holds([t**2 - g], (t,), {t: sympy.sqrt(g)}, {})  # (√g)² = g for every g
    assert not _holds([t**2 - g], (t,), {t: -sympy.sqrt(g)}, {})  # t is positive
    assert not _holds([t**2 - g], (t,), {t: 2 * sympy.sqrt(g)}, {})  # (2√g)² = 4g ≠ g


def test_brief_symbolic_block_in_numbers() -> None:
    """A transcendental block numeric mode solves with the knowns as letters, without
    sympy's root check: the spurious ±oo*I roots are gone, the real ones kept. By hand,
    sin θ (L Ω² cos θ/3 − g/2) = 0: θ = 0, π and ±acos(3g/(2LΩ²)) in (−π, π] (θ = π, the
    bar straight up, was missed while sympy solved the unfactored form)."""
    theta = sympy.Symbol("theta_s", real=True)
    L, W, g, m = sympy.symbols("L Omega g m", positive=True)
    residual = (
        L**2 * W**2 * m * sympy.sin(theta) * sympy.cos(theta) / 3 - L * g * m * sympy.sin(theta) / 2
    )
    given = {L: sympy.Rational(6, 5), W: 4, g: sympy.Rational(981, 100), m: 3}
    found = solve_block([residual], [theta], given, SolveOptions(mode="numeric"))
    values = sorted(float(c.values[theta]) for c in found.candidates)
    exact = float(sympy.acos(3 * given[g] / (2 * given[L] * given[W] ** 2)))
    assert values == pytest.approx([-exact, 0.0, exact, math.pi], rel=1e-13, abs=1e-300)


@pytest.mark.parametrize(
    "name",
    [
        "seed/fa_seed_pendulum",
        "scenes/path_dome_nt",
        "stages/bob_horizontal_then_slack",
        "rigid3d/bar_on_shaft_steady",
        "seed/gpm_seed_incline_threshold",
    ],
)
def test_numeric_mode_agrees_with_exact(name: str) -> None:
    path = ROOT / "problems" / f"{name}.dyn"
    exact = solve_file(path, SolveOptions(mode="exact"))
    numeric = solve_file(path, SolveOptions(mode="numeric"))
    assert [(c.name, c.status) for c in numeric.checks] == [
        (c.name, c.status) for c in exact.checks
    ]
    got = {row.name: row.value for row in numeric.answers}
    for row in exact.answers:
        assert row.value is not None
        assert got[row.name] == pytest.approx(row.value, rel=1e-12)
    assert len(numeric.equations) == len(exact.equations)


@pytest.mark.parametrize(
    "name",
    [
        "seed/fa_seed_pendulum",
        "scenes/path_hump_nt",
        "seed/gpm_seed_incline_threshold",
        "seed/rwe_seed_platform",
        "stages/pendulum_tension_bottom",
    ],
)
def test_numeric_mode_equations_read_as_exact_modes(name: str) -> None:
    """The geometry the equations are written with (unit vectors, direction cosines,
    moment arms, kinetic energies) and what is only shown (derived givens, the second
    moment point, an answer's own formula) are tidied in numeric mode too: no longer than
    exact mode's (they were up to 8× as long with sin² + cos² left in)."""
    path = ROOT / "problems" / f"{name}.dyn"
    exact = solve_file(path, SolveOptions(mode="exact"))
    numeric = solve_file(path, SolveOptions(mode="numeric"))
    shown = sum(len(row.text) for row in numeric.equations)
    assert shown <= 1.1 * sum(len(row.text) for row in exact.equations)
    # the givens' derived rows (I_O = I_G + m r_G²) and the second moment point as well
    assert sum(len(g.written) for g in numeric.givens) <= 1.1 * sum(
        len(g.written) for g in exact.givens
    )
    assert [row.text for row in numeric.second_moments] == [
        row.text for row in exact.second_moments
    ]


def test_numeric_mode_locates_instantaneous_centres_as_exact_mode() -> None:
    """The IC of the connecting rod of ``linkages/ic_slider_crank`` by hand: the normal to
    v_B is the line AB (y = x y_B/x_B), the normal to v_C the vertical x = x_C, so the IC
    is at (x_C, x_C y_B/x_B) and r_C/IC = x_C y_B/x_B. Numeric mode writes these rows as
    exact mode does (it wrote y_B + y_B (x_C − x_B)/x_B and took longer than exact mode)."""
    path = ROOT / "problems" / "linkages" / "ic_slider_crank.dyn"
    exact = {g.name: g.written for g in solve_file(path, SolveOptions(mode="exact")).givens}
    numeric = {g.name: g.written for g in solve_file(path, SolveOptions(mode="numeric")).givens}
    for name in ("y_IC_BC", "r_C_BC"):
        assert numeric[name].startswith("= x_C*y_B/x_B =")
        assert numeric[name] == exact[name]


def test_tidy_once_per_form_and_mode() -> None:
    """``tidy`` remembers a form's tidiest form per solve, apart for numeric mode's light
    tidying (where a form surely not 0 is kept as written)."""
    untidy = a * b * sympy.sin(u) ** 2 + a * b * sympy.cos(u) ** 2 + a
    assert tidy(untidy) == a * (b + 1)  # sin² + cos² = 1, then a taken out
    with light_tidying():
        assert tidy(untidy) == untidy  # not 0 at a point: kept as written
        assert tidy(untidy, light=False) == a * (b + 1)
    assert tidy(untidy) == a * (b + 1)  # exact mode's tidy, not numeric mode's remembered one


def test_light_tidying_finds_zero_by_numbers_without_the_search(monkeypatch) -> None:
    """Numeric mode settles "is this 0?" at three points of the letters' domain, to 30
    digits, instead of searching for the tidiest form (which proves 0 only at its end)."""
    import dynsolve.numbers as numbers

    def no_search(expr: sympy.Expr) -> list[sympy.Expr]:
        raise AssertionError("the search for a tidy form ran")

    monkeypatch.setattr(numbers, "_cheap_forms", no_search)
    zero = a * b * (sympy.sin(u) ** 2 + sympy.cos(u) ** 2) / (a + b) - a * b / (a + b)
    with light_tidying():
        assert tidy(zero) == 0


def test_a_form_zero_at_one_point_only_is_not_zero() -> None:
    """A form that vanishes at the first point (x minus x's own probe value) is not 0."""
    from dynsolve.numbers import _numerically_zero, _probe

    y = sympy.Symbol("y", positive=True)
    at_first_point = y - _probe(y, 0)
    assert at_first_point.xreplace({y: _probe(y, 0)}) == 0
    assert not _numerically_zero(at_first_point)
    with light_tidying():
        assert tidy(at_first_point) != 0


def test_a_part_at_an_angle_has_its_distance_squared_factored() -> None:
    """A rod (G at L/2) and a sphere (at d_s) on one line at angle θ: the composite's G is
    at (m_rod L/2 + m_s d_s)/(m_rod + m_s) along it, so the rod's G is
    m_s |L/2 − d_s|/(m_rod + m_s) from it (by hand): d² = m_s² (L − 2 d_s)²/(4 (m_rod + m_s)²),
    found through sin² θ + cos² θ = 1 without cancelling the trigonometric form."""
    L, m_rod, m_s, d_s, theta = sympy.symbols("L m_rod m_s d_s theta", positive=True)
    s, c = sympy.sin(theta), sympy.cos(theta)
    G = (L * m_rod / 2 + d_s * m_s) / (m_rod + m_s)
    d2 = (L * s / 2 - G * s) ** 2 + (L * c / 2 - G * c) ** 2
    by_hand = m_s**2 * (L - 2 * d_s) ** 2 / (4 * (m_rod + m_s) ** 2)
    tidied = tidy(d2)
    assert sympy.expand(tidied - by_hand) == 0
    assert len(sympy.sstr(tidied)) <= len(sympy.sstr(by_hand))
