"""Root selection: keep the one physically meaningful root of a block and say why others went.

Filters, in order, each recording a :class:`DiscardedRoot` with its reason:

1. values undefined for the given numbers (a formula divided by zero);
2. roots that are not real (``"not real"``);
3. roots against the sign declared on the unknown's symbol (``positive=True``) or
   breaking a declared constraint (``"violates omega >= 0 (line 12)"``);
4. roots that fail a surplus (over-determined) equation, when another root passes it;
5. the physical-sense rule: an unknown entering the block only through even powers
   (``±x`` both satisfy) keeps its non-negative root;
6. if several roots still remain, the first is kept (preferring all unknowns
   non-negative) and the unknowns are reported ambiguous.

Sign and realness questions about symbolic values (free given symbols, created
``positive=True``) are put to sympy's assumptions; when they are undecidable the
root is kept, never discarded.

>>> import sympy
>>> from dynsolve.solver.blocks import Candidate
>>> v = sympy.Symbol("v")
>>> choice = choose_root([Candidate({v: -3}), Candidate({v: 3})], [v], [v**2 - 9], {})
>>> dict(choice.values), [d.reason for d in choice.discarded]
({v: 3}, ['v enters only squared; its magnitude is taken positive'])
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import mpmath
import sympy
from sympy.logic.boolalg import Boolean, BooleanAtom

from dynsolve.numbers import MAX_DIGITS, real_value
from dynsolve.solver.blocks import (
    FORMULA_MAX_OPS,
    NUMERIC_DIGITS,
    Candidate,
    as_expr,
    is_finite,
    numeric_digits,
)
from dynsolve.solver.evaluate import NotQuick, mp_value
from dynsolve.solver.outcome import DiscardedRoot
from dynsolve.solver.residuals import equation_residual, is_satisfied
from dynsolve.system import Constraint, Equation

AMBIGUOUS = "ambiguous: declare a constraint to choose"
SAMPLE_POINTS = 12
SAMPLES_NEEDED = 3
SAMPLE_SEED = 1729
_IMAGINARY_TOLERANCE = 1e-12
ROUNDING = 1e-12  # relative gap of floating point sides of <=, >=, == taken as equality


@dataclass(frozen=True)
class RootChoice:
    """The root kept for a block (empty when none survives) and the roots discarded."""

    values: Mapping[sympy.Symbol, sympy.Expr]
    formulas: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    discarded: tuple[DiscardedRoot, ...] = ()
    ambiguous: tuple[sympy.Symbol, ...] = ()


_Filter = Callable[[Candidate], str]  # "" keeps the candidate, else the reason to discard


def choose_root(
    candidates: Sequence[Candidate],
    unknowns: Sequence[sympy.Symbol],
    residuals: Sequence[sympy.Expr],
    given: Mapping[sympy.Symbol, sympy.Expr],
    constraints: Sequence[Constraint] = (),
    checks: Sequence[tuple[int, Equation]] = (),
) -> RootChoice:
    """Pick the root of a block; ``constraints`` and ``checks`` must only involve solved names.

    ``residuals`` are the block's equations (``lhs - rhs``) for the even-power rule;
    ``checks`` are surplus equations, with their indices, that also judge the roots.

    >>> import sympy
    >>> from dynsolve.solver.blocks import Candidate
    >>> from dynsolve.system import Constraint
    >>> w = sympy.Symbol("omega")
    >>> positive = Constraint(w >= 0, "omega >= 0", 12)
    >>> choice = choose_root([Candidate({w: -2}), Candidate({w: 2})], [w], [w**3 - 4 * w],
    ...                      {}, [positive])
    >>> dict(choice.values), choice.discarded[0].reason
    ({omega: 2}, 'violates omega >= 0 (line 12)')
    """
    discarded: list[DiscardedRoot] = []
    remaining = _distinct([_realised(c) for c in candidates])
    for keep in (_defined, _real, _as_declared, _within(constraints, given)):
        remaining = _apply(keep, remaining, discarded)
    remaining = _apply_if_any_passes(_satisfying(checks, given), remaining, discarded)
    for unknown in unknowns:  # a preference: a single root has no rival to lose to
        if len(remaining) > 1 and enters_only_squared(residuals, unknown):
            remaining = _apply_if_any_passes(_non_negative(unknown), remaining, discarded)
    if not remaining:
        return RootChoice({}, {}, tuple(discarded))
    if len(remaining) > 1:  # (the sign of a lone root's formulas is not asked: sampling costs)
        remaining.sort(key=lambda c: not all(_is_non_negative(v) for v in c.values.values()))
    kept, others = remaining[0], remaining[1:]
    discarded.extend(DiscardedRoot(c.values, AMBIGUOUS) for c in others)
    ambiguous = tuple(u for u in unknowns if any(c.values[u] != kept.values[u] for c in others))
    return RootChoice(_tidy(kept.values), kept.formulas, tuple(discarded), ambiguous)


def _apply(
    keep: _Filter, candidates: list[Candidate], discarded: list[DiscardedRoot]
) -> list[Candidate]:
    """Keep the candidates ``keep`` has no objection to; record the others."""
    kept = []
    for candidate in candidates:
        reason = keep(candidate)
        if reason:
            discarded.append(DiscardedRoot(candidate.values, reason))
        else:
            kept.append(candidate)
    return kept


def _apply_if_any_passes(
    keep: _Filter, candidates: list[Candidate], discarded: list[DiscardedRoot]
) -> list[Candidate]:
    """Like :func:`_apply`, but only when at least one candidate passes (a preference)."""
    if not any(not keep(c) for c in candidates):
        return candidates
    return _apply(keep, candidates, discarded)


def _distinct(candidates: list[Candidate]) -> list[Candidate]:
    """Drop candidates whose values repeat an earlier candidate's."""
    seen: list[Mapping[sympy.Symbol, sympy.Expr]] = []
    result = []
    for candidate in candidates:
        if dict(candidate.values) not in seen:
            seen.append(dict(candidate.values))
            result.append(candidate)
    return result


def _defined(candidate: Candidate) -> str:
    return "" if all(is_finite(v) for v in candidate.values.values()) else "undefined here"


def _real(candidate: Candidate) -> str:
    values = candidate.values.values()
    return "not real" if any(_may_be_unreal(v) and is_real(v) is False for v in values) else ""


_REAL_FUNCTIONS = (sympy.sin, sympy.cos, sympy.exp)


def _may_be_unreal(value: sympy.Expr) -> bool:
    """False when ``value`` is built from real letters and real numbers by sums, products,
    whole powers, sines, cosines and exponentials: then it is real wherever it is
    defined, and sympy's ``is_real`` cannot be False for it (a value undefined at the
    givens is the filter before's), so the query is spared. True otherwise.

    >>> a, b = sympy.symbols("a b", positive=True)
    >>> _may_be_unreal(a * b / (a - b) + sympy.cos(a) ** 2), _may_be_unreal(sympy.sqrt(a - b))
    (False, True)
    """
    stack = [value]
    while stack:
        node = stack.pop()
        if node.is_Symbol:
            if not node.is_real:
                return True
        elif node.is_Add or node.is_Mul or isinstance(node, _REAL_FUNCTIONS):
            stack.extend(node.args)
        elif node.is_Pow:
            if not node.exp.is_Integer:
                return True
            stack.append(node.base)
        elif not (node.is_Rational or node.is_Float or node in (sympy.pi, sympy.E)):
            return True
    return False


def _as_declared(candidate: Candidate) -> str:
    """Respect a sign declared on the unknown's symbol itself (``positive=True``)."""
    for unknown, value in candidate.values.items():
        if unknown.is_positive and (_is_negative(value) or value.is_zero):
            return f"{unknown} is declared positive"
        if unknown.is_nonnegative and _is_negative(value):
            return f"{unknown} is declared non-negative"
    return ""


def _within(constraints: Sequence[Constraint], given: Mapping[sympy.Symbol, sympy.Expr]) -> _Filter:
    def keep(candidate: Candidate) -> str:
        if not constraints:
            return ""  # (no copy of the givens per root: n² over a chain's blocks)
        substitution = {**given, **candidate.values}
        for constraint in constraints:
            if truth(constraint.relation, substitution) is False:
                where = f" (line {constraint.line})" if constraint.line else ""
                return f"violates {constraint.text}{where}"
        return ""

    return keep


def _satisfying(
    checks: Sequence[tuple[int, Equation]], given: Mapping[sympy.Symbol, sympy.Expr]
) -> _Filter:
    def keep(candidate: Candidate) -> str:
        if not checks:
            return ""
        substitution = {**given, **candidate.values}
        for index, equation in checks:
            if is_satisfied(equation_residual(index, equation, substitution)) is False:
                return f"does not satisfy {equation.label}"
        return ""

    return keep


def _non_negative(unknown: sympy.Symbol) -> _Filter:
    reason = f"{unknown} enters only squared; its magnitude is taken positive"

    def keep(candidate: Candidate) -> str:
        return reason if _is_negative(candidate.values[unknown]) else ""

    return keep


def enters_only_squared(residuals: Sequence[sympy.Expr], unknown: sympy.Symbol) -> bool:
    """True when ``unknown`` occurs in the residuals only as even powers (so ``±x`` both fit).

    >>> import sympy
    >>> v, h = sympy.symbols("v h")
    >>> enters_only_squared([v**2 / 2 - 9 * h], v), enters_only_squared([v**2 + v], v)
    (True, False)
    """
    square = sympy.Dummy("square")

    def is_even_power(e: sympy.Basic) -> bool:
        return bool(e.is_Pow and e.base == unknown and e.exp.is_even)

    occurs = False
    for residual in residuals:
        if unknown in residual.free_symbols:
            occurs = True
            replaced = residual.replace(is_even_power, lambda e: square ** (e.exp / 2))
            if unknown in replaced.free_symbols:
                return False
    return occurs


def is_real(value: sympy.Expr) -> bool | None:
    """Whether ``value`` is real: by assumptions for symbolic values, numerically for numbers.

    >>> import sympy
    >>> is_real(sympy.sqrt(2)), is_real(1 + sympy.I), is_real(sympy.Symbol("x"))
    (True, False, None)
    """
    if value.is_Float or value.is_Rational:
        return True  # (a number's real part alone: nothing to evaluate)
    if value.free_symbols:
        return value.is_real
    try:
        number = complex(sympy.N(value, NUMERIC_DIGITS + 5, maxn=MAX_DIGITS))
    except (TypeError, ValueError):
        return value.is_real
    return abs(number.imag) <= _IMAGINARY_TOLERANCE * abs(number.real)  # relative: scale-free


def truth(relation: Boolean, substitution: Mapping[sympy.Symbol, sympy.Expr]) -> bool | None:
    """Evaluate a constraint after substitution: True, False, or None when undecidable.

    >>> import sympy
    >>> th, g = sympy.Symbol("th"), sympy.Symbol("g", positive=True)
    >>> truth(th < sympy.pi / 2, {th: sympy.acos(sympy.Rational(1, 7))})
    True
    >>> truth(th >= 0, {th: -sympy.sqrt(g)}), truth(th > 1, {th: g})
    (False, None)
    """
    try:
        values = {k: as_expr(v) for k, v in substitution.items()}
        if isinstance(relation, sympy.core.relational.Relational):
            # each side on its own: sympy would decide Float <= Float itself, with no
            # allowance for rounding (an impending-slip F = mu_s N failed at some scales)
            lhs, rhs = relation.lhs.xreplace(values), relation.rhs.xreplace(values)
            if lhs.is_number and rhs.is_number:
                return _compare(relation.rel_op, lhs, rhs)
        if isinstance(relation, (sympy.And, sympy.Or, sympy.Not)):
            parts = [truth(arg, substitution) for arg in relation.args]
            return _combine(relation, parts)
        result = relation.xreplace(values)
    except (TypeError, ValueError):
        return None
    return _decide(result)


def _combine(result: sympy.Basic, parts: list[bool | None]) -> bool | None:
    """The truth of And/Or/Not from the truths of its parts."""
    if isinstance(result, sympy.And):
        return False if False in parts else (None if None in parts else True)
    if isinstance(result, sympy.Or):
        return True if True in parts else (None if None in parts else False)
    if isinstance(result, sympy.Not) and parts[0] is not None:
        return not parts[0]
    return None


def _decide(result: sympy.Basic) -> bool | None:
    """Three-valued truth of a substituted relation or combination of relations."""
    if isinstance(result, BooleanAtom):
        return bool(result)
    if isinstance(result, sympy.core.relational.Relational):
        return _decide_numerically(result)
    return _combine(result, [_decide(arg) for arg in result.args])


def _decide_numerically(relation: sympy.core.relational.Relational) -> bool | None:
    """Compare the two sides of a relation numerically.

    Between numbers the comparison is direct. With free (positive, given) symbols
    left, sympy's assumptions come first; when they cannot decide, the difference is
    sampled at seeded random positive values, and the relation is decided only when
    every real sample agrees.
    """
    return _compare(relation.rel_op, relation.lhs, relation.rhs)


def _compare(op: str, lhs: sympy.Expr, rhs: sympy.Expr) -> bool | None:
    """``lhs op rhs`` decided numerically (see :func:`_decide_numerically`)."""
    compare = {
        ">": lambda d: d > 0, ">=": lambda d: d >= 0, "<": lambda d: d < 0,
        "<=": lambda d: d <= 0, "==": lambda d: d == 0, "!=": lambda d: d != 0,
    }  # fmt: skip
    test = compare.get(op)
    if test is None:
        return None
    difference = lhs - rhs
    if not difference.is_number:
        verdicts = {test(d) for d in sampled(difference)}
        return verdicts.pop() if len(verdicts) == 1 else None
    try:
        number = complex(sympy.N(difference, NUMERIC_DIGITS + 5, maxn=MAX_DIGITS))
        scale = max(abs(complex(sympy.N(side, 17))) for side in (lhs, rhs))
    except (TypeError, ValueError):
        return None
    if abs(number.imag) > _IMAGINARY_TOLERANCE * max(scale, abs(number.real)):
        return None
    rounded = op in ("<=", ">=", "==") and difference.has(sympy.Float)
    if rounded and abs(number.real) <= ROUNDING * scale:
        return True  # floating point sides that agree to 12 digits are equal, at any scale
    return bool(test(number.real))


def sampled(expr: sympy.Expr) -> list[float]:
    """``expr`` at seeded random positive values of its free symbols: the real results.

    Only symbols declared positive (given magnitudes) are sampled; fewer than
    :data:`SAMPLES_NEEDED` real values means no verdict (an empty list). Each value is
    read for its sign only; it is :func:`_sample`'s (sympy's 20-digit ``evalf`` where a
    quick evaluation cannot vouch for its sign).

    >>> import sympy
    >>> L, s = sympy.symbols("L s", positive=True)
    >>> all(v > 0 for v in sampled(sympy.sqrt(L**2 + s**2) - L))
    True
    """
    free = sorted(expr.free_symbols, key=lambda symbol: symbol.name)
    if not all(symbol.is_positive for symbol in free):
        return []
    rng = random.Random(SAMPLE_SEED)
    values = []
    for _ in range(SAMPLE_POINTS):
        point = {symbol: sympy.Rational(rng.randint(10, 1000), 100) for symbol in free}
        number = _sample(expr, point)
        if number is None:
            continue
        if math.isfinite(number.real) and abs(number.imag) <= _IMAGINARY_TOLERANCE * max(
            1.0, abs(number.real)
        ):
            values.append(number.real)
    return values if len(values) >= SAMPLES_NEEDED else []


QUICK_DIGITS = (25, 45)  # the two precisions a quick sample is computed at
QUICK_AGREEMENT = 1e-18  # relative gap within which the two vouch for the value's digits


def _sample(expr: sympy.Expr, point: Mapping[sympy.Symbol, sympy.Rational]) -> complex | None:
    """``expr`` at ``point`` as a complex number (None when it is not a number).

    Computed quickly in mpmath at two precisions (:data:`QUICK_DIGITS`); when they agree
    to :data:`QUICK_AGREEMENT` the value's sign and its first 18 digits are certain, so it
    is the value sympy's 20-digit ``evalf`` gives to those digits. Otherwise (a value that
    cancels to 0 or nearly, a function the quick evaluation lacks, a division by 0)
    sympy's ``evalf`` gives it, as it did before the quick path existed: every sign read
    from a sample is the same.

    >>> x = sympy.Symbol("x", positive=True)
    >>> _sample(sympy.sqrt(x) - 1, {x: sympy.Rational(9, 4)})
    (0.5+0j)
    >>> _sample(sympy.sqrt(x) ** 2 - x, {x: sympy.Rational(9, 4)})  # 0: evalf's answer
    0j
    """
    try:
        found = []
        for digits in QUICK_DIGITS:
            with mpmath.workdps(digits):
                at = {s: mpmath.mpf(int(v.p)) / int(v.q) for s, v in point.items()}
                found.append(mpmath.mpmathify(mp_value(expr, at)))
        low, high = found
        if mpmath.isfinite(high) and high != 0 and abs(high - low) <= QUICK_AGREEMENT * abs(high):
            return complex(high)
    except (NotQuick, ArithmeticError, ValueError, TypeError):
        pass
    try:
        return complex(sympy.N(expr.xreplace(dict(point)), 20))
    except (TypeError, ValueError):
        return None


def _is_negative(value: sympy.Expr) -> bool:
    """True only when ``value`` is decidably negative (by assumptions, else by sampling)."""
    if value.free_symbols:
        if value.is_negative is not None:
            return bool(value.is_negative)
        samples = sampled(value)
        return bool(samples) and all(v < 0 for v in samples)
    try:
        return complex(sympy.N(value, NUMERIC_DIGITS + 5, maxn=MAX_DIGITS)).real < 0
    except (TypeError, ValueError):
        return bool(value.is_negative)


def _is_non_negative(value: sympy.Expr) -> bool:
    """True only when ``value`` is decidably non-negative (by assumptions, else by sampling)."""
    if value.free_symbols:
        if value.is_nonnegative is not None:
            return bool(value.is_nonnegative)
        samples = sampled(value)
        return bool(samples) and all(v >= 0 for v in samples)
    return not _is_negative(value)


def _realised(candidate: Candidate) -> Candidate:
    """Replace numbers that are real but written with ``I`` (casus irreducibilis) by Floats."""
    values = {u: as_expr(v) for u, v in candidate.values.items()}
    for unknown, value in values.items():
        if is_finite(value) and not value.free_symbols and value.has(sympy.I) and is_real(value):
            values[unknown] = sympy.re(sympy.N(value, numeric_digits(), maxn=MAX_DIGITS))
    return Candidate(values, candidate.formulas)


def _tidy(values: Mapping[sympy.Symbol, sympy.Expr]) -> dict[sympy.Symbol, sympy.Expr]:
    """Numbers too long to read (nested radicals) become Floats; the rest stay exact."""
    return {
        u: sympy.N(v, numeric_digits(), maxn=MAX_DIGITS)
        if not v.free_symbols and sympy.count_ops(v) > FORMULA_MAX_OPS
        else v
        for u, v in values.items()
    }


def sign_of(expr: sympy.Expr, given_values: Mapping[sympy.Symbol, sympy.Expr]) -> int:
    """The sign of ``expr`` with the givens' values, else the same for sampled positive
    values of its symbols; ValueError when it cannot be told.

    >>> import sympy
    >>> a, b = sympy.symbols("a b", positive=True)
    >>> sign_of(-a * b, {}), sign_of(a - b, {a: 1, b: 2})
    (-1, -1)
    """
    number = real_value(expr, given_values)
    if number is None:
        samples = sampled(expr)
        number = samples[0] if samples and all(v * samples[0] > 0 for v in samples) else None
    if number is None or number == 0:
        raise ValueError("cannot tell which way the scene moves toward state 2")
    return 1 if number > 0 else -1
