"""Tests for solving one block, choosing its root, the time budget and residuals."""

from __future__ import annotations

import math
import signal

import mpmath
import pytest
import sympy
from sympy import Rational

from dynsolve.solver.blocks import (
    BudgetExceeded,
    Candidate,
    _equilibrated,
    solve_block,
    solve_linear_in_floats,
    time_budget,
)
from dynsolve.solver.residuals import equation_residual
from dynsolve.solver.roots import AMBIGUOUS, choose_root, enters_only_squared, truth
from dynsolve.system import Constraint, Equation, SolveOptions

x, y, v = sympy.symbols("x y v")
g, h, m = sympy.symbols("g h m", positive=True)


# --- linear blocks -------------------------------------------------------------------


def test_linear_block_gives_exact_rationals_and_symbolic_formulas():
    # m*a = m*g - T and T = k*a with m = 2, g = 981/100, k = 3:
    # a = m*g/(m + k) = (981/50)/5 = 981/250, T = 3a = 2943/250.
    a, T, k = sympy.symbols("a T k")
    solution = solve_block(
        [m * a - (m * g - T), T - k * a], [a, T], {m: 2, g: Rational(981, 100), k: 3}
    )
    (candidate,) = solution.candidates
    assert solution.method == "linear"
    assert candidate.values == {a: Rational(981, 250), T: Rational(2943, 250)}
    assert sympy.simplify(candidate.formulas[a] - g * m / (k + m)) == 0


@pytest.mark.parametrize(
    ("coefficient", "rhs", "by_hand"),
    [
        # N - m g - m a = 0 for N: N = a m + g m (a block of one contact's normal force)
        (1, g * m + m * h, g * m + h * m),
        # 2 x = m (g + h)**2 / 3: x = m (g² + 2 g h + h²)/6, distributed as monomials
        (2, m * (g + h) ** 2 / 3, g**2 * m / 6 + g * h * m / 3 + h**2 * m / 6),
        # -3/7 x = 0: x = 0
        (Rational(-3, 7), 0, 0),
    ],
)
def test_a_block_of_one_unknown_is_the_fields_reduced_form(coefficient, rhs, by_hand):
    # a number times x = a polynomial: solved without building the polynomial field, the
    # formula must be the very expression (not only an equal one) the field's RREF gives
    from sympy.polys.matrices import DomainMatrix

    from dynsolve.solver.blocks import linear_solution

    matrix, column = sympy.Matrix([[coefficient]]), sympy.Matrix([rhs])
    (found,) = linear_solution(matrix, column, (x,))
    reduced, _ = DomainMatrix.from_Matrix(matrix.row_join(column)).to_field().rref()
    by_field = reduced.to_Matrix()[0, 1]
    assert sympy.srepr(found) == sympy.srepr(by_field)
    assert sympy.expand(found - by_hand) == 0


def test_numeric_mode_linear_block_gives_floats():
    solution = solve_block([3 * x - 1], [x], {}, SolveOptions(mode="numeric"))
    value = solution.candidates[0].values[x]
    assert isinstance(value, sympy.Float)
    assert float(value) == pytest.approx(1 / 3)


def test_singular_linear_block_leaves_its_unknowns_free():
    # x + y = 1 and 2x + 2y = 2 are the same equation twice.
    solution = solve_block([x + y - 1, 2 * x + 2 * y - 2], [x, y], {})
    assert set(solution.free) == {x, y}
    assert solution.missing_equations == 1
    assert not solution.inconsistent


def test_contradictory_linear_block_is_inconsistent():
    solution = solve_block([x + y - 1, 2 * x + 2 * y - 3], [x, y], {})
    assert solution.inconsistent
    assert solution.candidates == ()


def test_linear_block_singular_only_for_the_given_numbers_is_detected():
    # Generically k*x = 1 gives x = 1/k, which is undefined for k = 0.
    k = sympy.Symbol("k")
    solution = solve_block([k * x - 1], [x], {k: 0})
    assert solution.inconsistent


# --- nonlinear blocks ----------------------------------------------------------------


def test_symbolic_block_returns_every_root_with_formulas():
    # v**2 = 2*g*h with g = 10, h = 5: v = ±10, formula ±sqrt(2 g h).
    solution = solve_block([v**2 - 2 * g * h], [v], {g: 10, h: 5})
    assert solution.method == "symbolic"
    assert sorted(c.values[v] for c in solution.candidates) == [-10, 10]
    assert {c.formulas[v] for c in solution.candidates} == {
        sympy.sqrt(2 * g * h),
        -sympy.sqrt(2 * g * h),
    }


def test_transcendental_block_falls_back_to_numeric():
    # x = cos(x) has no closed form; its one real root is the Dottie number 0.7390851332.
    solution = solve_block([x - sympy.cos(x)], [x], {})
    assert solution.method == "numeric"
    assert "solved numerically" in solution.note
    (candidate,) = solution.candidates
    assert float(candidate.values[x]) == pytest.approx(0.7390851332151607, rel=1e-12)


def test_tiny_time_budget_forces_numeric_with_a_note():
    # x**5 + x = 3 is solvable by sympy (CRootOf) but not within a microsecond.
    # f(1) = -1 < 0 < f(1.2) = 0.689, and f is increasing: one real root near 1.133.
    solution = solve_block([x**5 + x - 3], [x], {}, SolveOptions(time_budget=1e-6))
    assert solution.method == "numeric"
    assert "budget" in solution.note
    (candidate,) = solution.candidates
    assert 1.0 < float(candidate.values[x]) < 1.2
    assert float(candidate.values[x] ** 5 + candidate.values[x]) == pytest.approx(3)


def test_numeric_mode_finds_roots_of_a_coupled_block():
    # x**2 + y**2 = 25, x*y = 12 has the real roots (3, 4), (4, 3) and their negatives.
    solution = solve_block([x**2 + y**2 - 25, x * y - 12], [x, y], {}, SolveOptions(mode="numeric"))
    roots = {
        (round(float(c.values[x]), 9), round(float(c.values[y]), 9)) for c in solution.candidates
    }
    # a small polynomial block: solved algebraically, every root in floats (issue 14)
    assert roots == {(3, 4), (4, 3), (-3, -4), (-4, -3)}
    assert solution.exhaustive and solution.method == "numeric"


def test_numeric_mode_searches_a_transcendental_coupled_block():
    # x = cos(y), y = x: the root x = y = 0.739085… (the Dottie number) by a numeric search,
    # which cannot promise it found every root
    solution = solve_block([x - sympy.cos(y), y - x], [x, y], {}, SolveOptions(mode="numeric"))
    (candidate,) = solution.candidates
    assert float(candidate.values[x]) == pytest.approx(0.7390851332, rel=1e-9)
    assert not solution.exhaustive


def test_numeric_mode_with_free_symbols_stays_symbolic():
    solution = solve_block([v**2 - 2 * g * h], [v], {}, SolveOptions(mode="numeric"))
    assert solution.method == "symbolic"
    assert len(solution.candidates) == 2


# --- time budget ---------------------------------------------------------------------


def test_time_budget_restores_the_previous_handler_and_timer():
    def previous(signum: int, frame: object) -> None:
        raise AssertionError("the outer timer must not fire during the test")

    old = signal.signal(signal.SIGPROF, previous)
    signal.setitimer(signal.ITIMER_PROF, 100.0)
    try:
        with time_budget(1.0):
            pass
        assert signal.getsignal(signal.SIGPROF) is previous
        remaining, _ = signal.getitimer(signal.ITIMER_PROF)
        assert 90.0 < remaining <= 100.1  # the CPU clocks tick in steps of about 10 ms
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, old)


def test_the_block_budget_counts_cpu_time_not_waiting():
    # regression (numeric helper): under load a wall-clock budget ran out before a brief
    # symbolic solve finished, and the root search returned another period's root
    # (θ = −2016.9 for −0.69): the path depended on the machine's load. Sleeping costs no
    # CPU, so it does not spend the budget.
    import time

    with time_budget(0.2):
        time.sleep(0.5)


# --- root choice ---------------------------------------------------------------------


def candidates(*values: object, unknown: sympy.Symbol = v) -> list[Candidate]:
    return [Candidate({unknown: sympy.sympify(value)}) for value in values]


def test_constraint_discards_the_violating_root_with_its_line():
    constraint = Constraint(v >= 0, "v >= 0", 12)
    choice = choose_root(candidates(-3, 3), [v], [v**2 - 9], {}, [constraint])
    assert choice.values == {v: 3}
    assert [d.reason for d in choice.discarded] == ["violates v >= 0 (line 12)"]


def test_even_power_rule_keeps_the_positive_magnitude():
    choice = choose_root(candidates(-3, 3), [v], [v**2 - 9], {})
    assert choice.values == {v: 3}
    assert choice.discarded[0].reason == "v enters only squared; its magnitude is taken positive"
    assert choice.ambiguous == ()


def test_several_valid_roots_are_ambiguous():
    # x**2 - 3x + 2 = (x - 1)(x - 2): both roots positive, x enters linearly too.
    choice = choose_root(candidates(1, 2, unknown=x), [x], [x**2 - 3 * x + 2], {})
    assert choice.values == {x: 1}
    assert choice.ambiguous == (x,)
    assert [d.reason for d in choice.discarded] == [AMBIGUOUS]


def test_complex_roots_are_discarded_as_not_real():
    choice = choose_root(
        candidates(2 * sympy.I, -2 * sympy.I, 2, unknown=x), [x], [x**3 - 2 * x**2 + 4 * x - 8], {}
    )
    assert choice.values == {x: 2}
    assert [d.reason for d in choice.discarded] == ["not real", "not real"]


def test_no_root_survives():
    choice = choose_root(
        candidates(-1, unknown=x), [x], [x + 1], {}, [Constraint(x > 0, "x > 0", 3)]
    )
    assert choice.values == {}


def test_undecidable_symbolic_constraint_keeps_the_root():
    # sqrt(g) - h may have either sign for positive g, h: sympy cannot decide x > 0.
    value = sympy.sqrt(g) - h
    choice = choose_root(
        candidates(value, unknown=x), [x], [x - value], {}, [Constraint(x > 0, "x > 0", 3)]
    )
    assert choice.values == {x: value}


def test_symbolic_negative_root_is_discarded_by_assumptions():
    root = sympy.sqrt(2 * g * h)
    constraint = Constraint(v >= 0, "v >= 0", 2)
    choice = choose_root(candidates(-root, root), [v], [v**2 - 2 * g * h], {}, [constraint])
    assert choice.values == {v: root}


def test_enters_only_squared_sees_through_even_powers_only():
    assert enters_only_squared([m * v**2 / 2 - m * g * h, v**4 - 1], v)
    assert not enters_only_squared([v**2 + v], v)
    assert not enters_only_squared([sympy.sqrt(v) - 1], v)


def test_truth_compares_numbers_numerically():
    th = sympy.Symbol("theta")
    assert truth(th < sympy.pi / 2, {th: sympy.acos(Rational(1, 7))}) is True
    assert truth(th < sympy.pi / 2, {th: 2}) is False


# --- residuals -----------------------------------------------------------------------


def test_relative_residual_is_judged_against_the_terms():
    # T - m*g = 0 with T a float root: one side is exactly 0, the other ~1e-15;
    # the relative residual compares that with the 19.62 N terms, not with 0.
    T = sympy.Symbol("T")
    root = sympy.Float(19.62, 15) + sympy.Float(1e-14, 15)
    residual = equation_residual(
        0, Equation(T - m * g, 0, "ΣF"), {T: root, m: 2, g: Rational(981, 100)}
    )
    assert residual.evaluated
    assert residual.relative < 1e-12


def test_residual_of_a_wrong_answer():
    # 2x = 3 with x = 1: |2 - 3| = 1, scale max(2, 3) = 3.
    residual = equation_residual(0, Equation(2 * x, 3, "a"), {x: 1})
    assert residual.absolute == pytest.approx(1)
    assert residual.relative == pytest.approx(1 / 3)


def test_residual_with_unsolved_unknown_is_not_evaluated():
    residual = equation_residual(0, Equation(x + y, 3, "a"), {x: 1}, unsolved={y})
    assert not residual.evaluated
    assert math.isnan(residual.absolute)


def test_symbolic_residual_is_spot_checked():
    residual = equation_residual(
        0, Equation(m * v**2 / 2, m * g * h, "E"), {v: sympy.sqrt(2 * g * h)}
    )
    assert not residual.evaluated
    assert residual.relative < 1e-20


def test_numeric_mode_with_free_symbols_notes_why_it_stayed_symbolic():
    solution = solve_block([v**2 - 2 * g * h], [v], {}, SolveOptions(mode="numeric"))
    assert solution.note == "numeric mode needs values for g, h; solved symbolically"


@pytest.mark.parametrize("name", ["bob_cord_slack", "dome_contact_lost"])
def test_numeric_mode_starts_angles_near_one_radian_at_any_scale(name):
    # regression (bench/accuracy.py, 2026-11-24): with lengths ×1e9 every unknown started at
    # the data's scale, so the angle where the cord goes slack was found 1e12 rad away and
    # rejected: no valid root. Scaled answers must still match the key (angles unchanged).
    from pathlib import Path

    from dynsolve.pipeline import solve_spec
    from dynsolve.scaling import scale_spec
    from dynsolve.spec.parser import parse_file

    path = Path(__file__).resolve().parent.parent / "problems" / "scenes" / f"{name}.dyn"
    solution = solve_spec(scale_spec(parse_file(path), 9), SolveOptions(mode="numeric"))
    theta = next(a for a in solution.answers if a.name == "theta")
    unscaled = next(a for a in solve_spec(parse_file(path)).answers if a.name == "theta")
    assert theta.value == pytest.approx(unscaled.value, rel=1e-12)


def test_numeric_mode_polishes_a_tiny_root_beside_a_large_one() -> None:
    # regression: x² + x = c² with c = 1e-50: polyroots' error is absolute, so the root
    # c² = 1e-100 (to first order; hand: x = (−1 + √(1 + 4c²))/2 = c² − c⁴ + …) came out
    # as about 1e-36 or 0; a Newton step on the polynomial makes it relative
    from dynsolve.solver.blocks import _univariate_roots

    x = sympy.Symbol("x")
    roots = sorted(_univariate_roots(x**2 + x - sympy.Rational(1, 10**100), x), key=abs)
    assert float(roots[0]) == pytest.approx(1e-100, rel=1e-12)


def test_float_linear_solve_undoes_a_change_of_units() -> None:
    """The acceleration block of ``linkages/double_pendulum_swinging`` with masses and
    lengths scaled by 1e9 (entries from 1 to 4e25): scaling rows and columns by their
    largest entries leaves it 1e17-conditioned, so numeric mode solved it exactly (5x its
    time at k = 0); sweeps by geometric means bring it to k = 0's condition. The floats
    must agree with the exact rational solution (sympy's LU, another method) to 1e-14."""
    e = sympy.Integer(10)
    big = -sympy.Rational(125, 3) * e**24
    rows = [
        [0, 0, 1, 0, 0, 0, 0, 0],
        [-5 * e**8, 0, 0, 1, 0, 0, 0, 0],
        [0, 0, 0, 0, 1, 0, 1, 0],
        [-5 * e**17, 0, 0, 0, 0, 1, 0, 1],
        [big, 0, 0, 0, 0, -25 * e**7, 0, 25 * e**7],
        [0, -5 * e**17, -2 * e**9, 0, 0, 0, -1, 0],
        [0, 0, 0, -2 * e**9, 0, 0, 0, -1],
        [0, big, 0, 0, 0, 0, 25 * e**7, 0],
    ]
    matrix = sympy.Matrix(rows)
    rhs = sympy.Matrix([-8 * e**9, 0, -8 * e**18, 1962 * e**16, 0, 0, 1962 * e**16, 0])
    unknowns = sympy.symbols("alpha_OA alpha_AB a_Ax a_Ay O_x O_y A_x A_y")
    with mpmath.workdps(35):
        A = [[mpmath.mpf(int(v.p)) / int(v.q) for v in map(sympy.Rational, r)] for r in rows]
        once = mpmath.matrix(_equilibrated(A, [mpmath.mpf(1)] * 8, [1] * 8, False)[0])
        assert mpmath.mnorm(once, 1) * mpmath.mnorm(mpmath.inverse(once), 1) > 1e15
    found = solve_linear_in_floats(matrix, rhs, unknowns)
    assert found is not None
    exact = matrix.LUsolve(rhs)
    for unknown, value in zip(unknowns, exact, strict=True):
        assert float(found.candidates[0].values[unknown]) == pytest.approx(float(value), rel=1e-14)


def test_a_root_search_keeps_angles_in_one_turn():
    # regression (numeric helper): with the symbolic attempt skipped (as when its budget ran
    # out), the bar-on-shaft block returned θ = −2016.9 rad, a root many turns away. By
    # hand: sin θ (L Ω² cos θ/3 − g/2) = 0 → θ = 0 or cos θ = 3g/(2 L Ω²), each once in (−π, π]
    theta = sympy.Symbol("theta_s", real=True)
    L, W, g, m = sympy.symbols("L Omega g m", positive=True)
    residual = (
        L**2 * W**2 * m * sympy.sin(theta) * sympy.cos(theta) / 3 - L * g * m * sympy.sin(theta) / 2
    )
    given = {L: sympy.Rational(6, 5), W: 4, g: sympy.Rational(981, 100), m: 3}
    found = solve_block([residual], [theta], given, SolveOptions(mode="numeric", time_budget=0))
    values = sorted(float(c.values[theta]) for c in found.candidates)
    assert all(-math.pi - 1e-12 < v <= math.pi for v in values)
    assert len(values) == 4  # 0, π (the bar up) and ±acos(3g/(2LΩ²)), once each
    steady = math.acos(3 * 9.81 / (2 * 1.2 * 16))
    for expected in (-steady, steady):
        assert any(v == pytest.approx(expected, rel=1e-12) for v in values)


def test_an_angle_inside_one_cosine_is_solved_through_the_cosine():
    # regression (scale helper): a particle leaving a cylinder from 20° off its top waited
    # out the 5 s symbolic budget on cos(θ + φ0), twice, then searched numerically (5.2 s).
    # By hand (energy and N = 0): v² = 2 g R (cos φ0 − cos(θ+φ0)) and v² = g R cos(θ+φ0), so
    # cos(θ + φ0) = (2/3) cos φ0 and θ = acos(2 cos φ0 / 3) − φ0 (or −acos(…) − φ0)
    v = sympy.Symbol("v", positive=True)
    t = sympy.Symbol("theta", real=True)
    R, gg, p = sympy.symbols("R g phi_0", positive=True)
    residuals = [
        R * gg * (sympy.cos(p) - sympy.cos(t + p)) - v**2 / 2,
        gg * sympy.cos(t + p) - v**2 / R,
    ]
    given = {R: sympy.Rational(3, 2), gg: sympy.Rational(981, 100), p: sympy.pi / 9}
    solution = solve_block(residuals, [v, t], given, SolveOptions(time_budget=5.0))
    assert solution.method == "symbolic"
    angles = sorted(float(c.values[t]) for c in solution.candidates)
    phi = math.pi / 9
    expected = sorted(
        (math.acos(2 * math.cos(phi) / 3) - phi, -math.acos(2 * math.cos(phi) / 3) - phi)
    )
    assert angles == pytest.approx(expected, rel=1e-12)
    formulas = {sympy.sstr(c.formulas[t]) for c in solution.candidates if t in c.formulas}
    assert "-phi_0 + acos(2*cos(phi_0)/3)" in formulas


def test_a_swallowed_budget_expiry_is_raised_again():
    # a library that catches everything once must not let the work run on past the budget
    swallowed = []
    with pytest.raises(BudgetExceeded), time_budget(0.2):
        try:
            while True:
                sum(range(1000))
        except BaseException:
            swallowed.append(True)
        while True:
            sum(range(1000))
    assert swallowed == [True]


def test_a_polynomial_search_that_does_not_converge_goes_to_sympy(monkeypatch) -> None:
    """mpmath.polyroots raising NoConvergence gives None (sympy then solves the block);
    the handler named mpmath.NoConvergence, which mpmath 1.3 does not have, so the
    failure became an AttributeError (regression)."""
    import mpmath

    from dynsolve.solver.blocks import _univariate_roots

    def no_convergence(*args: object, **kwargs: object) -> None:
        raise mpmath.mp.NoConvergence("Didn't converge in maxsteps=100 steps.")

    monkeypatch.setattr(mpmath, "polyroots", no_convergence)
    w = sympy.Symbol("w")
    assert _univariate_roots(2 * w**2 - 8, w) is None
