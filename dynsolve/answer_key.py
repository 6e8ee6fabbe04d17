"""Compare computed answers with a spec's answer key: unit-aware, with tolerances and directions.

Values are compared in the problem's base units; a direction word gives the expected
value its sign under the textbook convention (ccw, up, right positive). A formula key
is compared for equivalence: exactly when sympy can decide, else numerically at
random positive values of the free symbols.
"""

from __future__ import annotations

import cmath
import random
from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction

import sympy

from dynsolve.dimensions import check_dimensions
from dynsolve.errors import Position, SpecError
from dynsolve.expressions import to_sympy
from dynsolve.format import quantity as format_quantity
from dynsolve.magnitude import OutOfRange, bound, value_bound
from dynsolve.numbers import real_value, tidy
from dynsolve.quantities import convert, resolve_quantity, resolve_unit
from dynsolve.spec.ast import Answer, EquationStmt, Name, Spec
from dynsolve.spec.parser import iter_names
from dynsolve.units import Dim, System

DEFAULT_RELATIVE = Fraction(1, 200)  # 0.5 %: three significant figures
ZERO_ABSOLUTE = Fraction(1, 10**9)  # for an expected zero, in the answer's unit
SENSE_PAIRS = (("ccw", "cw"), ("up", "down"), ("right", "left"))  # positive, negative
NEGATIVE = tuple(negative for _, negative in SENSE_PAIRS)
EQUIVALENCE_POINTS = 4
EQUIVALENCE_RTOL = 1e-9  # two formulas agree at a point within this relative difference
EQUIVALENCE_SIMPLIFY_OPS = 80  # larger differences are not given to sympy.simplify


def sense_word(key_word: str, value: float) -> str:
    """The word a signed value reads with, in the pair of a key's word ("" for 0, or for a
    word of no pair): an answer keyed ``2251 N down`` reads ``down`` at −2251.

    >>> sense_word("down", -2251.0), sense_word("down", 3.0), sense_word("cw", 0.0)
    ('down', 'up', '')
    """
    pair = next((p for p in SENSE_PAIRS if key_word in p), None)
    if pair is None or value == 0:
        return ""
    return pair[0] if value > 0 else pair[1]


@dataclass(frozen=True)
class Verdict:
    """The comparison of one key entry: pass or fail and a sentence saying why."""

    passed: bool
    expected: str
    detail: str


def compare(
    answer: Answer,
    computed: sympy.Expr | None,
    dim: Dim,
    unit: str,
    spec: Spec,
    symbols: Mapping[str, sympy.Symbol],
    knowns: Mapping[sympy.Symbol, sympy.Expr],
    known_dims: Mapping[str, Dim],
    confirm: bool = True,
) -> Verdict:
    """Judge ``computed`` (in base units; None when not determined) against ``answer``.

    ``knowns`` holds the givens' values and the solved unknowns; ``known_dims`` the
    dimension of every name a formula key may use (givens and solved unknowns).
    ``confirm=False`` (numeric mode) judges formula keys by the numeric comparison at
    random points alone, without the symbolic confirmation.
    """
    if answer.formula is not None:
        return _compare_formula(answer, computed, dim, spec, symbols, knowns, known_dims, confirm)
    expected, shown, mismatch = _expected(answer, dim, spec)
    if mismatch is not None:
        return mismatch
    if answer.direction:
        if answer.quantity.value < 0:
            raise SpecError(
                "give a magnitude with a direction, or a signed value, not both",
                Position(spec.file, answer.quantity.line, answer.quantity.column),
                hint=f"write {answer.quantity.text.lstrip('-')} … {answer.direction}",
            )
        if answer.direction in NEGATIVE:
            expected = -expected
    if computed is None:
        return Verdict(False, shown, "not determined by the equations")
    value = real_value(computed.subs(knowns))
    if value is None:
        return Verdict(False, shown, f"the answer is a formula: {computed}")
    target = float(expected)
    tolerance = _tolerance(answer, target, dim, spec.system, spec.file)
    error = abs(value - target)
    got = format_quantity(convert(value, unit, spec.system), unit, 4)
    if answer.direction and value != 0:  # as the key reads: a magnitude and its word
        word = sense_word(answer.direction, value)
        got = f"{format_quantity(convert(abs(value), unit, spec.system), unit, 4)} {word}"
    if error <= tolerance:
        return Verdict(True, shown, f"got {got}{_relative(error, target)}")
    hint = ""
    if abs(value + target) <= tolerance:
        hint = "; the sign is opposite: check the sign convention (ccw, up, right positive)"
    return Verdict(False, shown, f"got {got}{_relative(error, target)}{hint}")


def compare_magnitude(
    answer: Answer, magnitude: float | None, direction: str, dim: Dim, unit: str, spec: Spec
) -> Verdict:
    """Judge a scene answer: its magnitude (base units) and, when the key gives one, its
    direction word (cw/ccw, up/down/left/right)."""
    expected, shown, mismatch = _expected(answer, dim, spec)
    if mismatch is not None:
        return mismatch
    if magnitude is None:
        return Verdict(False, shown, "not determined by the scene")
    target = abs(float(expected))
    tolerance = _tolerance(answer, target, dim, spec.system, spec.file)
    error = abs(magnitude - target)
    got = format_quantity(convert(magnitude, unit, spec.system), unit, 4)
    detail = f"got {got} {direction}".rstrip() + _relative(error, target)
    if error > tolerance:
        return Verdict(False, shown, detail)
    if answer.direction and target > tolerance and answer.direction != direction:
        return Verdict(
            False, shown, f"{detail}; direction {direction or 'none'}, not {answer.direction}"
        )
    return Verdict(True, shown, detail)


def _expected(answer: Answer, dim: Dim, spec: Spec) -> tuple[sympy.Expr, str, Verdict | None]:
    """The key's value in base units, its text, and a failed verdict if its unit is wrong."""
    assert answer.quantity is not None
    expected, expected_dim = resolve_quantity(answer.quantity, spec.system, spec.file)
    shown = _expected_text(answer)
    if expected_dim != dim:
        detail = f"unit mismatch: the key gives {expected_dim.name}, the answer is {dim.name}"
        return expected, shown, Verdict(False, shown, detail)
    return expected, shown, None


def _expected_text(answer: Answer) -> str:
    assert answer.quantity is not None
    unit = answer.quantity.unit.text if answer.quantity.unit else ""
    parts = [answer.quantity.text, unit]
    if answer.tolerance:
        parts.append(
            answer.tolerance.text + (answer.tolerance.unit.text if answer.tolerance.unit else "")
        )
    if answer.direction:
        parts.append(answer.direction)
    return " ".join(p for p in parts if p)


def _relative(error: float, target: float) -> str:
    if target == 0:
        return ""
    return f" (off by {100 * error / abs(target):.3g} %)"


def _tolerance(answer: Answer, target: float, dim: Dim, system: System, file: str) -> float:
    tolerance = answer.tolerance
    assert answer.quantity is not None
    if tolerance is None:
        if target != 0:
            return float(DEFAULT_RELATIVE) * abs(target)
        tolerance_value, tolerance_unit = ZERO_ABSOLUTE, answer.quantity.unit
    elif tolerance.kind == "rel":
        return float(tolerance.value) * abs(target)
    else:
        tolerance_value = tolerance.value
        tolerance_unit = tolerance.unit or answer.quantity.unit
    if tolerance_unit is None:
        return float(tolerance_value)
    tolerance_dim = resolve_unit(tolerance_unit, file).dim
    if tolerance_dim != dim:
        raise SpecError(
            f"tolerance unit {tolerance_unit.text} is {tolerance_dim.name}, "
            f"the answer is {dim.name}",
            Position(file, tolerance_unit.line, tolerance_unit.column),
            hint="give the tolerance in the answer's unit, or as a percentage",
        )
    value, _ = resolve_quantity(_as_quantity(tolerance_value, tolerance_unit, answer), system, file)
    return float(value)


def _as_quantity(value: Fraction, unit: object, answer: Answer) -> object:
    from dynsolve.spec.ast import Quantity

    assert answer.quantity is not None
    return Quantity(value, str(value), unit, answer.line, answer.column)  # type: ignore[arg-type]


def _compare_formula(
    answer: Answer,
    computed: sympy.Expr | None,
    dim: Dim,
    spec: Spec,
    symbols: Mapping[str, sympy.Symbol],
    knowns: Mapping[sympy.Symbol, sympy.Expr],
    known_dims: Mapping[str, Dim],
    confirm: bool = True,
) -> Verdict:
    assert answer.formula is not None
    for name in iter_names(answer.formula):
        if name.text != "pi" and name.text not in known_dims:
            raise SpecError(
                f"the answer formula for {answer.name} uses '{name.text}', which is neither "
                "a given nor a solved unknown",
                Position(spec.file, name.line, name.column),
                hint="write formulas in terms of the givens and the other answers",
            )
    statement = EquationStmt(
        Name(answer.name, answer.line, answer.column), "=", answer.formula, "", "",
        answer.line, answer.column,
    )  # fmt: skip
    check_dimensions((statement,), {**known_dims, answer.name: dim}, spec.file, spec.system)
    # givens with values and solved unknowns are put in; symbolic givens stay symbols
    formula = to_sympy(answer.formula, symbols)
    try:  # bound the formula's numbers before the values are put in
        bound(formula, {k: value_bound(v) for k, v in knowns.items()})
    except OutOfRange as error:
        raise error.at(answer.line, answer.column).located(spec.file) from None
    expected = formula.xreplace(dict(knowns))
    shown = str(answer.formula)
    if computed is None:
        return Verdict(False, shown, "not determined by the equations")
    computed = computed.xreplace(dict(knowns))
    if computed.free_symbols:
        return _equivalent(expected, computed, shown, confirm)
    value = real_value(computed)
    target = real_value(expected.subs(knowns))
    if value is None or target is None:
        return Verdict(False, shown, "the formula cannot be evaluated with the givens")
    passed = abs(value - target) <= float(DEFAULT_RELATIVE) * abs(target) or value == target
    return Verdict(passed, shown, f"formula gives {target:.6g}, computed {value:.6g} (base units)")


def _equivalent(
    expected: sympy.Expr, computed: sympy.Expr, shown: str, confirm: bool = True
) -> Verdict:
    """Two formulas compared numerically first, at random points (relative tolerance
    ``EQUIVALENCE_RTOL``), and only then confirmed symbolically, cheaply (``tidy`` of the
    difference; ``simplify`` for a small difference free of floating-point numbers);
    without ``confirm`` (numeric mode) the numeric comparison is the verdict."""
    difference = expected - computed
    if difference == 0:
        return Verdict(True, shown, "equivalent (exactly)")
    rng = random.Random(20261121)
    # every symbol of either side gets a value, also one that cancels in the difference
    free = sorted(expected.free_symbols | computed.free_symbols, key=lambda s: s.name)
    for _ in range(EQUIVALENCE_POINTS):
        point = {s: sympy.Rational(rng.randint(50, 400), 100) for s in free}
        a, b = _complex_value(expected.xreplace(point)), _complex_value(computed.xreplace(point))
        if a is None:
            return Verdict(False, shown, "the formula has no finite value (a division by zero?)")
        if b is None or abs(a - b) > EQUIVALENCE_RTOL * max(abs(a), abs(b), 1e-300):
            return Verdict(False, shown, f"not equivalent: computed {computed}")
    if confirm and _zero_symbolically(difference):
        return Verdict(True, shown, "equivalent (exactly)")
    return Verdict(
        True,
        shown,
        f"equivalent (numerically: equal within {EQUIVALENCE_RTOL:g} at {EQUIVALENCE_POINTS} "
        "random points)",
    )


def _zero_symbolically(difference: sympy.Expr) -> bool:
    """``difference`` shown to be 0 by cheap tidying, or by ``simplify`` when it is small and
    exact (floats never cancel exactly: there the numeric test is the answer)."""
    if difference.has(sympy.Float):
        return False
    if tidy(difference) == 0:
        return True
    return (
        sympy.count_ops(difference) <= EQUIVALENCE_SIMPLIFY_OPS and sympy.simplify(difference) == 0
    )


def _complex_value(expr: sympy.Expr) -> complex | None:
    """A number's value as a finite complex, or None (infinite, undefined or not a number).

    >>> _complex_value(sympy.sqrt(-4)), _complex_value(sympy.zoo), _complex_value(sympy.Symbol("x"))
    (2j, None, None)
    """
    try:
        value = complex(expr.evalf(20))
    except (TypeError, ValueError, ArithmeticError):
        return None
    return value if cmath.isfinite(value) else None
