"""End-to-end tests of solve_system: whole problems, statuses, root choice and pruning."""

from __future__ import annotations

import pytest
import sympy
from sympy import Rational

from dynsolve.solver import solve_system
from dynsolve.system import Constraint, Equation, EquationSystem, SolveOptions

x, y, z, v = sympy.symbols("x y z v")


def equations(*pairs: tuple[object, object]) -> tuple[Equation, ...]:
    return tuple(
        Equation(sympy.sympify(lhs), sympy.sympify(rhs), f"line {i + 1}", line=i + 1)
        for i, (lhs, rhs) in enumerate(pairs)
    )


# --- the drum: Hibbeler, Engineering Mechanics: Dynamics, Example 17.11 --------------
# A 60 kg drum (radius of gyration 0.25 m) is turned by a 20 kg block hanging from a
# cord wound at r = 0.4 m. By hand:
#   I_O = 60 * 0.25**2 = 3.75 kg m²
#   ΣM_O:  0.4 T = 3.75 α        -> T = 9.375 α
#   ΣF_y:  20 * 9.81 - T = 20 a  -> 196.2 - 9.375 α = 20 * 0.4 α = 8 α
#   α = 196.2 / 17.375 = 7848/695 = 11.29 rad/s²,  T = 9.375 α = 14715/139 = 105.9 N,
#   a = 0.4 α = 15696/3475 = 4.52 m/s²  (the book: α = 11.3 rad/s², T = 106 N).

T, alpha, a, I_O = sympy.symbols("T alpha a I_O")
DRUM = EquationSystem(
    equations=equations(
        (I_O, 60 * Rational(1, 4) ** 2),
        (T * Rational(4, 10), I_O * alpha),
        (20 * Rational(981, 100) - T, 20 * a),
        (a, Rational(4, 10) * alpha),
    ),
    unknowns=(I_O, T, alpha, a),
)


def test_drum_is_solved_exactly_in_two_blocks():
    outcome = solve_system(DRUM)
    assert outcome.status == "solved"
    assert outcome.values == {
        I_O: Rational(15, 4),
        alpha: Rational(7848, 695),
        T: Rational(14715, 139),
        a: Rational(15696, 3475),
    }
    assert float(outcome.values[alpha]) == pytest.approx(11.29, abs=5e-3)
    assert float(outcome.values[T]) == pytest.approx(105.9, abs=5e-2)
    assert float(outcome.values[a]) == pytest.approx(4.52, abs=5e-3)
    assert [b.equations for b in outcome.blocks] == [(0,), (1, 2, 3)]
    assert {b.method for b in outcome.blocks} == {"linear"}
    assert outcome.max_residual == 0.0
    assert all(r.evaluated for r in outcome.residuals)


def test_drum_formulas_keep_earlier_unknowns_as_symbols():
    # From the hand solution with I_O kept: T = 0.4*196.2*I_O/(0.16*20 + I_O) ... i.e.
    # T = 981 I_O / (5 I_O + 16).
    formulas = solve_system(DRUM).blocks[1].formulas
    assert sympy.simplify(formulas[T] - 981 * I_O / (5 * I_O + 16)) == 0


def test_drum_formulas_with_letters_read_like_the_textbook():
    # With m_b, g, r as givens: T r = I_O α, m_b g - T = m_b a, a = r α gives
    # α = m_b g r / (I_O + m_b r²) and T = I_O α / r = m_b g I_O / (I_O + m_b r²).
    m_b, g, r = sympy.symbols("m_b g r", positive=True)
    system = EquationSystem(
        equations((T * r, I_O * alpha), (m_b * g - T, m_b * a), (a, r * alpha)),
        unknowns=(T, alpha, a),
        knowns={m_b: 20, g: Rational(981, 100), r: Rational(2, 5), I_O: Rational(15, 4)},
    )
    outcome = solve_system(system)
    assert sympy.simplify(outcome.blocks[0].formulas[T] - m_b * g * I_O / (I_O + m_b * r**2)) == 0
    assert outcome.values[T] == Rational(14715, 139)


# --- structure-level verdicts --------------------------------------------------------


def test_triangular_system_is_solved_in_dependency_order():
    # z = x + y, x = 2, y = 3x  ->  x = 2, y = 6, z = 8.
    outcome = solve_system(EquationSystem(equations((z, x + y), (x, 2), (y, 3 * x)), (x, y, z)))
    assert [b.unknowns for b in outcome.blocks] == [(x,), (y,), (z,)]
    assert outcome.values == {x: 2, y: 6, z: 8}


def test_underdetermined_names_free_unknowns_and_solves_the_rest():
    # x = 1 is determined; y + z = x leaves one equation for two unknowns.
    outcome = solve_system(EquationSystem(equations((x, 1), (y + z, x)), (x, y, z)))
    assert outcome.status == "underdetermined"
    assert outcome.undetermined == (y, z)
    assert outcome.missing_equations == 1
    assert outcome.values == {x: 1}


def test_numerically_dependent_equations_are_underdetermined():
    # Structurally square, but 2x + 2y = 2 is twice x + y = 1.
    outcome = solve_system(EquationSystem(equations((x + y, 1), (2 * x + 2 * y, 2)), (x, y)))
    assert outcome.status == "underdetermined"
    assert outcome.undetermined == (x, y)
    assert outcome.missing_equations == 1


def test_overdetermined_consistent_equation_is_redundant():
    # x = 1, 2x = 2 (same information), y = x + 1.
    outcome = solve_system(EquationSystem(equations((x, 1), (2 * x, 2), (y, x + 1)), (x, y)))
    assert outcome.status == "solved"
    assert outcome.redundant == (1,)
    assert outcome.values == {x: 1, y: 2}


def test_overdetermined_inconsistent_equation_is_conflicting():
    # x = 1 but 2x = 3: line 2 contradicts line 1; |2 - 3| / 3 relative residual.
    outcome = solve_system(EquationSystem(equations((x, 1), (2 * x, 3), (y, x + 1)), (x, y)))
    assert outcome.status == "inconsistent"
    assert outcome.conflicting == (1,)
    assert outcome.residuals[1].relative == pytest.approx(1 / 3)


def test_contradictory_square_block_is_inconsistent():
    outcome = solve_system(EquationSystem(equations((x + y, 1), (x + y, 2)), (x, y)))
    assert outcome.status == "inconsistent"
    assert outcome.conflicting == (0, 1)


def test_wanted_prunes_unneeded_equations():
    # Only y is wanted: y = 2x needs x = 1; z = 5 is not needed.
    system = EquationSystem(equations((x, 1), (y, 2 * x), (z, 5)), (x, y, z), wanted=(y,))
    outcome = solve_system(system)
    assert outcome.status == "solved"
    assert outcome.values == {x: 1, y: 2}
    assert outcome.unneeded == (2,)


def test_wanted_ignores_an_unneeded_underdetermined_part():
    system = EquationSystem(equations((x, 1), (y + z, 4)), (x, y, z), wanted=(x,))
    outcome = solve_system(system)
    assert outcome.status == "solved"
    assert outcome.unneeded == (1,)


# --- several roots -------------------------------------------------------------------


def test_constraint_selects_the_root():
    # v² = 9 -> v = ±3; the declared v >= 0 keeps 3.
    system = EquationSystem(
        equations((v**2, 9)), (v,), constraints=(Constraint(v >= 0, "v >= 0", 7),)
    )
    outcome = solve_system(system)
    assert outcome.values == {v: 3}
    assert outcome.blocks[0].discarded[0].reason == "violates v >= 0 (line 7)"


def test_even_power_rule_selects_the_root_without_constraint():
    outcome = solve_system(EquationSystem(equations((v**2, 9)), (v,)))
    assert outcome.status == "solved"
    assert outcome.values == {v: 3}
    assert "enters only squared" in outcome.blocks[0].discarded[0].reason


def test_two_valid_roots_are_reported_ambiguous():
    # x² - 3x + 2 = (x - 1)(x - 2) = 0: x = 1 and x = 2 both pass every check.
    outcome = solve_system(EquationSystem(equations((x**2 - 3 * x + 2, 0)), (x,)))
    assert outcome.status == "solved"
    assert outcome.ambiguous == (x,)
    assert outcome.values == {x: 1}
    assert outcome.blocks[0].discarded[0].values == {x: 2}


def test_complex_roots_are_discarded():
    # x³ = 8 -> x = 2 and the complex pair -1 ± i√3.
    outcome = solve_system(EquationSystem(equations((x**3, 8)), (x,)))
    assert outcome.values == {x: 2}
    assert [d.reason for d in outcome.blocks[0].discarded] == ["not real", "not real"]


def test_no_real_root_gives_no_valid_root():
    # x² = -4 -> x = ±2i only.
    outcome = solve_system(EquationSystem(equations((x**2, -4)), (x,)))
    assert outcome.status == "no_valid_root"
    assert outcome.values == {}


def test_surplus_equation_picks_the_root_it_agrees_with():
    # v² = 9 alone would keep +3 by the even-power rule; v = -3 (surplus) says otherwise.
    outcome = solve_system(EquationSystem(equations((v**2, 9), (v, -3)), (v,)))
    assert outcome.status == "solved"
    assert outcome.values == {v: -3}
    assert outcome.redundant == (1,)


# --- a trig block: the conical pendulum / spinning rod -------------------------------
# Ω² sin θ cos θ = (3g / 2L) sin θ  ->  sin θ = 0 or cos θ = 3g / (2 L Ω²).
# With 0 < θ < π/2 only θ = acos(3g / (2 L Ω²)) remains. With Ω = 10 rad/s, L = 1 m,
# g = 9.81 m/s²: cos θ = 29.43 / 200 = 0.14715, θ = 1.42311 rad.


def spinning_rod(options: SolveOptions | None = None) -> tuple[sympy.Expr, object]:
    th, omega, length, g = sympy.symbols("theta Omega L g")
    system = EquationSystem(
        equations((omega**2 * sympy.sin(th) * sympy.cos(th), 3 * g / (2 * length) * sympy.sin(th))),
        unknowns=(th,),
        knowns={omega: 10, length: 1, g: Rational(981, 100)},
        constraints=(
            Constraint(th > 0, "theta > 0", 4),
            Constraint(th < sympy.pi / 2, "theta < pi/2", 5),
        ),
    )
    return th, solve_system(system, options or SolveOptions())


def test_trig_block_keeps_the_root_inside_the_constraints():
    th, outcome = spinning_rod()
    assert outcome.status == "solved"
    assert outcome.blocks[0].method == "symbolic"
    expected = sympy.acos(Rational(2943, 20000))
    assert sympy.N(outcome.values[th] - expected, 30) == pytest.approx(0, abs=1e-25)
    assert float(outcome.values[th]) == pytest.approx(1.42311, abs=1e-5)
    assert all("violates" in d.reason for d in outcome.blocks[0].discarded)


def test_trig_block_in_numeric_mode():
    th, outcome = spinning_rod(SolveOptions(mode="numeric"))
    assert outcome.status == "solved"
    assert outcome.blocks[0].method == "numeric"
    assert float(outcome.values[th]) == pytest.approx(1.4231100418439, rel=1e-12)


# --- numeric fallback ----------------------------------------------------------------


def test_transcendental_equation_in_numeric_mode():
    # x = cos x: the Dottie number 0.7390851332151607.
    outcome = solve_system(
        EquationSystem(equations((x, sympy.cos(x))), (x,)), SolveOptions(mode="numeric")
    )
    assert outcome.blocks[0].method == "numeric"
    assert float(outcome.values[x]) == pytest.approx(0.7390851332151607, rel=1e-12)
    assert outcome.max_residual < 1e-12


def test_tiny_time_budget_falls_back_to_numeric_with_a_note():
    outcome = solve_system(
        EquationSystem(equations((x, sympy.cos(x))), (x,)), SolveOptions(time_budget=1e-6)
    )
    block = outcome.blocks[0]
    assert block.method == "numeric"
    assert "budget" in block.note and "numerically" in block.note
    assert block.formulas == {}
    assert float(outcome.values[x]) == pytest.approx(0.7390851332151607, rel=1e-12)


# --- a symbolic problem --------------------------------------------------------------


def test_symbolic_problem_gives_a_formula():
    # m v²/2 = m g h with v >= 0  ->  v = sqrt(2 g h).
    m, g, h = sympy.symbols("m g h", positive=True)
    system = EquationSystem(
        equations((m * v**2 / 2, m * g * h)), (v,), constraints=(Constraint(v >= 0, "v >= 0", 3),)
    )
    outcome = solve_system(system)
    assert outcome.status == "solved"
    assert sympy.simplify(outcome.values[v] - sympy.sqrt(2 * g * h)) == 0
    residual = outcome.residuals[0]
    assert not residual.evaluated and residual.relative < 1e-20


def test_symbolic_linear_problem_keeps_letters():
    # F = m a with F, m given as letters: a = F/m.
    F, m = sympy.symbols("F m", positive=True)
    outcome = solve_system(EquationSystem(equations((F, m * a)), (a,)))
    assert outcome.values == {a: F / m}


def test_sign_declared_on_the_unknown_discards_a_negative_root():
    # t + 1 = 0 gives t = -1, but t was created positive (a duration, say).
    t = sympy.Symbol("t", positive=True)
    outcome = solve_system(EquationSystem(equations((t + 1, 0)), (t,)))
    assert outcome.status == "no_valid_root"
    assert outcome.blocks[0].discarded[0].reason == "t is declared positive"


def test_no_root_found_numerically_is_failed():
    # exp(x) = 0 has no root at all; the numeric search must give up, not invent one.
    outcome = solve_system(
        EquationSystem(equations((sympy.exp(x), 0)), (x,)), SolveOptions(mode="numeric")
    )
    assert outcome.status == "failed"
    assert "found no root" in outcome.blocks[0].note
