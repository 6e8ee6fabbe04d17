"""Residuals: how well each equation holds once every answer is substituted back.

For an equation ``lhs = rhs`` with the knowns and the solved values substituted,
both sides are evaluated to 30 digits and

* ``absolute = |lhs - rhs|``;
* ``relative = absolute / scale`` with ``scale = max(|lhs|, |rhs|, |largest term|)``,
  where the terms are the top-level summands of either side. The term size keeps an
  equation written as ``T - m*g = 0`` from reading as 100 % off when a numeric root
  leaves ``1e-15`` on a side that is zero; each side's :func:`term_size` (sums taken
  as sums of magnitudes, also inside products) counts as a term too. When the scale is
  0 (both sides exactly zero) the relative residual is 0; no absolute floor, so a
  problem scaled by 10^k is judged the same way.

When free symbols remain (a symbolic problem) the equation is *spot-checked*: the
free symbols get fixed pseudo-random positive values (seeded, so reports are
reproducible), the residual is computed there and ``evaluated`` is False. No
``simplify`` is run: it is slow and can be inconclusive, while a spot check of an
identity gives a relative residual of about ``1e-29``.

An equation holding an unknown that was not solved gets ``nan`` and ``evaluated=False``.

>>> import sympy
>>> from dynsolve.system import Equation
>>> T, m, g = sympy.symbols("T m g")
>>> r = equation_residual(0, Equation(T, m * g, "ΣF"), {T: 20, m: 2, g: 10})
>>> r.absolute, r.relative, r.evaluated
(0.0, 0.0, True)
"""

from __future__ import annotations

import math
import random
from collections.abc import Collection, Mapping, Sequence

import mpmath
import sympy
from sympy.core.cache import cacheit

from dynsolve.numbers import MAX_DIGITS
from dynsolve.solver.blocks import as_expr, substitute
from dynsolve.solver.evaluate import NotQuick, mp_size, mp_value
from dynsolve.solver.outcome import Residual
from dynsolve.system import Equation

DIGITS = 30
SATISFIED = 1e-9  # relative residual up to which an equation counts as holding
SPOT_CHECK_SEED = 20240611
EVALF_MAXN = 100  # sympy's own default


def equation_residual(
    index: int,
    equation: Equation,
    substitution: Mapping[sympy.Symbol, sympy.Expr],
    unsolved: Collection[sympy.Symbol] = (),
    quick: bool = False,
) -> Residual:
    """Substitute ``substitution`` into ``equation`` and measure how far it is from holding.

    ``quick`` (numeric mode): computed by :func:`_quick_residual` where it can be.

    >>> import sympy
    >>> from dynsolve.system import Equation
    >>> x = sympy.Symbol("x")
    >>> equation_residual(3, Equation(x**2, 2, "line 3"), {x: sympy.Rational(7, 5)}).relative
    0.02
    """
    if not equation.residual.free_symbols.isdisjoint(unsolved):
        return Residual(index, math.nan, math.nan, evaluated=False)
    if quick:
        found = _quick_residual(index, equation, substitution)
        if found is not None:
            return found
    sides = [substitute(equation.lhs, substitution), substitute(equation.rhs, substitution)]
    terms = [
        substitute(t, substitution)
        for side in (equation.lhs, equation.rhs)
        for t in sympy.Add.make_args(as_expr(side))
    ]
    letters = set().union(*(e.free_symbols for e in sides + terms))
    spot: dict[sympy.Symbol, sympy.Expr] = {}
    if letters:
        spot = spot_values(letters)
        sides = [side.xreplace(spot) for side in sides]
        terms = [term.xreplace(spot) for term in terms]
    present = as_expr(equation.lhs).free_symbols | as_expr(equation.rhs).free_symbols
    values = {k: as_expr(substitution[k]) for k in present if k in substitution} | spot
    inner = [term_size(as_expr(side), values) for side in (equation.lhs, equation.rhs)]
    absolute, relative = _measure(sides, terms + [sympy.Float(x) for x in inner])
    return Residual(index, absolute, relative, evaluated=not letters)


QUICK_DIGITS = DIGITS + 10  # the working precision of a quick residual


def _quick_residual(
    index: int, equation: Equation, substitution: Mapping[sympy.Symbol, sympy.Expr]
) -> Residual | None:
    """:func:`equation_residual` in mpmath at :data:`QUICK_DIGITS` digits, node by node
    (:mod:`dynsolve.solver.evaluate`), instead of sympy's ``evalf`` of the substituted
    sides: the same sides, terms and term sizes, the same spot values for the letters
    left, at a tenth of the cost. Its error is below 1e-38 of the equation's scale (a
    fixed precision cannot lose more next to the size of the terms the residual is
    judged on), so a residual of an answer in 15 digits reads the same and every
    verdict at :data:`SATISFIED` is the same. None (use ``evalf``) when a node is not
    known to it, a value is not finite or a division by 0 occurs.

    >>> x, y = sympy.symbols("x y")
    >>> r = _quick_residual(0, Equation(x + y, 3, "a"), {x: sympy.Float(1), y: 2})
    >>> r.absolute, r.relative, r.evaluated
    (0.0, 0.0, True)
    """
    lhs, rhs = as_expr(equation.lhs), as_expr(equation.rhs)
    present = lhs.free_symbols | rhs.free_symbols
    values = {k: as_expr(substitution[k]) for k in present if k in substitution}
    letters = (present - set(values)).union(*(v.free_symbols for v in values.values()))
    if letters:  # the letters left once substituted (some may cancel), as evalf's path sees
        forms = [substitute(t, substitution) for side in (lhs, rhs) for t in (side, *_terms(side))]
        letters = set().union(*(f.free_symbols for f in forms))
    spot = spot_values(letters) if letters else {}
    try:
        with mpmath.workdps(QUICK_DIGITS):
            at_letters = {k: mpmath.mpf(v._mpf_) for k, v in spot.items()}
            point = dict(at_letters)
            shared: dict[sympy.Basic, object] = {}
            for symbol, value in values.items():
                point[symbol] = mp_value(value, at_letters, shared)
            seen: dict[sympy.Basic, object] = {}
            sides = [mp_value(side, point, seen) for side in (lhs, rhs)]
            terms = [mp_value(t, point, seen) for side in (lhs, rhs) for t in _terms(side)]
            sizes = [mp_size(side, point, seen) for side in (lhs, rhs)]
            magnitudes = [abs(v) for v in (*sides, *terms, *sizes)]
            if not all(mpmath.isfinite(m) for m in magnitudes):
                return None
            absolute = abs(sides[0] - sides[1])
            scale = max(magnitudes)
            relative = absolute / scale if scale > 0 else mpmath.mpf(0)
    except (NotQuick, ArithmeticError, ValueError, TypeError):
        return None
    return Residual(index, float(absolute), float(relative), evaluated=not letters)


def _terms(side: sympy.Expr) -> tuple[sympy.Expr, ...]:
    """The top-level summands of one side of an equation."""
    return sympy.Add.make_args(side)


def term_size(expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]) -> float:
    """The size of ``expr`` with every sum taken as a sum of magnitudes, at ``values``.

    The scale a rounded zero is judged on: ``tan_b*(R*alpha*tan_b/c + a_y)`` is one
    top-level term, but it is the difference of two parts of size 2.9 each, and a
    float64 answer leaves 1e-16 of it (a relative residual of 1e-16, not 1.0).

    >>> import sympy
    >>> a, b = sympy.symbols("a b")
    >>> term_size(3 * (a - b), {a: 2, b: 2})
    12.0
    """
    if expr.is_Add:
        return math.fsum(term_size(arg, values) for arg in expr.args)
    if expr.is_Mul:
        return math.prod(term_size(arg, values) for arg in expr.args)
    if expr.is_Pow and expr.exp.is_number and expr.exp.is_positive:
        return term_size(expr.base, values) ** float(expr.exp)
    magnitude = _size(expr.xreplace(values), 17, EVALF_MAXN)
    return 0.0 if math.isnan(magnitude) else magnitude


def spot_values(letters: Collection[sympy.Symbol]) -> dict[sympy.Symbol, sympy.Expr]:
    """Reproducible pseudo-random positive values (0.5 to 2.5) for free symbols, by name.

    >>> import sympy
    >>> a, b = sympy.symbols("a b")
    >>> values = spot_values({b, a})
    >>> values == spot_values([a, b]) and all(0.5 <= v <= 2.5 for v in values.values())
    True
    """
    rng = random.Random(SPOT_CHECK_SEED)
    ordered = sorted(letters, key=lambda s: s.name)
    return {s: sympy.Float(rng.uniform(0.5, 2.5), DIGITS) for s in ordered}


def _measure(sides: Sequence[sympy.Expr], terms: Sequence[sympy.Expr]) -> tuple[float, float]:
    """Absolute and relative residual from the two sides and the additive terms."""
    try:
        lhs, rhs = (sympy.N(side, DIGITS, maxn=MAX_DIGITS) for side in sides)
        absolute = _magnitude(lhs - rhs)
        sizes = [_size(t, DIGITS, MAX_DIGITS) for t in terms]
        scale = max(_magnitude(lhs), _magnitude(rhs), *sizes)
    except (TypeError, ValueError, ArithmeticError):
        return math.nan, math.nan
    if math.isnan(absolute) or math.isnan(scale):
        return math.nan, math.nan
    relative = absolute / scale if scale > 0 else 0.0
    return absolute, relative


@cacheit  # the terms of a long chain's equations repeat: each number evaluated once
def _size(value: sympy.Expr, digits: int, maxn: int) -> float:
    """``|value|`` evaluated to ``digits`` digits (``maxn`` at most through cancellation)."""
    return _magnitude(sympy.N(value, digits, maxn=maxn))


def _magnitude(value: sympy.Expr) -> float:
    """``|value|`` as a float; nan when it is not a finite number."""
    try:
        return abs(complex(value))
    except (TypeError, ValueError, OverflowError):
        return math.nan


def is_satisfied(residual: Residual) -> bool | None:
    """True when the equation holds to ``SATISFIED``, False when not, None when unknown.

    >>> is_satisfied(Residual(0, 1e-20, 1e-18, True)), is_satisfied(Residual(0, 1.0, 0.5, True))
    (True, False)
    """
    if math.isnan(residual.relative):
        return None
    return residual.relative <= SATISFIED


def all_residuals(
    equations: Sequence[Equation],
    substitution: Mapping[sympy.Symbol, sympy.Expr],
    unsolved: Collection[sympy.Symbol] = (),
    quick: bool = False,
) -> tuple[Residual, ...]:
    """The residual of every equation, in equation order.

    >>> import sympy
    >>> from dynsolve.system import Equation
    >>> x = sympy.Symbol("x")
    >>> [r.relative for r in all_residuals([Equation(x, 1, "a"), Equation(2 * x, 3, "b")], {x: 1})]
    [0.0, 0.3333333333333333]
    """
    return tuple(
        equation_residual(i, equation, substitution, unsolved, quick)
        for i, equation in enumerate(equations)
    )
