"""Every root of a small polynomial block with number coefficients, by elimination.

Numeric mode's path for a block of polynomial equations in a few unknowns (the energy
equation and a rolling constraint, a steady precession's two moment equations): exact
algebra brings it down to one polynomial in one unknown, whose roots mpmath finds in
floating point; the unknowns eliminated are then computed from them.

* an unknown that enters an equation linearly with a number for its coefficient is
  solved for and substituted into the others (exact: no root is lost or added);
* an equation with rational coefficients that factors (``t (N − 98.1) = 0``) splits
  the block into one block per factor, whose roots together are the block's;
* one equation in one unknown left: its square-free part (rational coefficients: a
  repeated root once, as sympy's solve lists it), then its roots by ``mpmath.polyroots``
  (:func:`~dynsolve.solver.blocks._univariate_roots`, with guard digits; a repeated root
  left, with other coefficients, is refused).

Every root is found, complex ones too (the root choice says why it discards them), as
sympy's algebraic solve would find them. None when the block is not of this kind (an
unknown in a denominator, nothing to eliminate, a repeated root, a dependent equation):
sympy's solve decides then.

>>> x, y = sympy.symbols("x y")
>>> roots = every_root([x - 2 * y, x**2 + y**2 - 5], (x, y))
>>> sorted((float(r[x].real), float(r[y].real)) for r in roots)
[(-2.0, -1.0), (2.0, 1.0)]
"""

from __future__ import annotations

from collections.abc import Sequence

import mpmath
import sympy

from dynsolve.solver.blocks import GUARD_DIGITS, _univariate_roots, numeric_digits
from dynsolve.solver.evaluate import NotQuick, mp_value

__all__ = ["EQUATION_DEGREE", "FINAL_DEGREE", "every_root", "exact_numbers"]

EQUATION_DEGREE = 4  # each equation's total degree at most this
FINAL_DEGREE = 16  # the one polynomial left at most this degree
Root = dict[sympy.Symbol, mpmath.mpc | mpmath.mpf]


def every_root(
    residuals: Sequence[sympy.Expr], unknowns: Sequence[sympy.Symbol]
) -> list[Root] | None:
    """Every root of ``residuals = 0`` (numbers only besides ``unknowns``), each a map of
    the unknowns to mpmath numbers at the working digits plus :data:`GUARD_DIGITS`; None
    when the block is not a polynomial one this elimination solves (see the module).

    >>> t, N = sympy.symbols("t N")
    >>> roots = every_root([t * (N - 5), N * t / 5 - 3], (N, t))
    >>> [(float(r[N].real), float(r[t].real)) for r in roots]
    [(5.0, 3.0)]
    """
    equations = []
    for residual in residuals:
        numerator = sympy.Integer(0) + residual
        if _divides(numerator, unknowns):
            numerator, denominator = sympy.fraction(sympy.together(numerator))
            if set(unknowns) & denominator.free_symbols:
                return None
        polynomial = exact_numbers(sympy.expand(numerator))
        if not polynomial.is_polynomial(*unknowns):
            return None
        if polynomial.free_symbols - set(unknowns):
            return None
        if sympy.Poly(polynomial, *unknowns).total_degree() > EQUATION_DEGREE:
            return None
        equations.append(polynomial)
    with mpmath.workdps(numeric_digits() + GUARD_DIGITS):
        try:
            roots = _solve(equations, list(unknowns))
        except (NotQuick, ArithmeticError, ValueError, TypeError, sympy.PolynomialError):
            return None
    return _distinct(roots) if roots else None


def _divides(expr: sympy.Expr, unknowns: Sequence[sympy.Symbol]) -> bool:
    """Whether an unknown is in a power with a negative exponent (a denominator)."""
    return any(
        p.exp.is_negative and not p.base.free_symbols.isdisjoint(unknowns)
        for p in expr.atoms(sympy.Pow)
    )


def exact_numbers(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` with each float as the rational it prints as (exact elimination; what
    ``nsimplify(expr, rational=True)`` gives, at a hundredth of its cost).

    >>> x = sympy.Symbol("x")
    >>> exact_numbers(sympy.Float("0.125") * x + sympy.Float("4.375"))
    x/8 + 35/8
    """
    floats = expr.atoms(sympy.Float)
    if not floats:
        return expr
    return sympy.expand(expr.xreplace({f: sympy.Rational(str(f)) for f in floats}))


def _solve(equations: list[sympy.Expr], unknowns: list[sympy.Symbol]) -> list[Root] | None:
    """The roots of a square polynomial block (see :func:`every_root`); [] when there are
    none, None when this elimination cannot tell."""
    for equation in equations:
        if not equation.free_symbols & set(unknowns):
            return None if equation == 0 else []  # dependent; or 0 = c: no root
    if len(unknowns) == 1:
        polynomial = sympy.Poly(equations[0], unknowns[0])
        if polynomial.degree() > FINAL_DEGREE:
            return None
        if polynomial.domain.is_QQ or polynomial.domain.is_ZZ:  # a repeated root once
            polynomial = polynomial.sqf_part()
        found = _univariate_roots(polynomial.as_expr(), unknowns[0])
        return None if found is None else [{unknowns[0]: r} for r in found]
    pivot = _linear_pivot(equations, unknowns)
    if pivot is not None:
        return _eliminated(equations, unknowns, *pivot)
    return _split(equations, unknowns)


def _linear_pivot(
    equations: list[sympy.Expr], unknowns: list[sympy.Symbol]
) -> tuple[int, sympy.Symbol, sympy.Expr] | None:
    """An equation, an unknown it holds linearly with a nonzero number for coefficient,
    and that unknown's value from it (in the other unknowns); None when there is none."""
    for i, equation in enumerate(equations):
        terms = sympy.Poly(equation, *unknowns).terms()
        for k, unknown in enumerate(unknowns):
            holding = [(m, c) for m, c in terms if m[k]]
            if len(holding) != 1 or sum(holding[0][0]) != 1:
                continue  # a power, or a product with another unknown
            coefficient = holding[0][1]
            if coefficient.is_zero is not False:
                continue
            value = sympy.expand(-sympy.expand(equation - coefficient * unknown) / coefficient)
            if unknown not in value.free_symbols:
                return i, unknown, value
    return None


def _eliminated(
    equations: list[sympy.Expr],
    unknowns: list[sympy.Symbol],
    index: int,
    unknown: sympy.Symbol,
    value: sympy.Expr,
) -> list[Root] | None:
    """The roots with ``unknown`` = ``value`` (from equation ``index``) substituted into the
    other equations; ``unknown`` computed from each root of the rest."""
    rest = [
        sympy.expand(e.xreplace({unknown: value})) for i, e in enumerate(equations) if i != index
    ]
    others = [u for u in unknowns if u != unknown]
    if any(sympy.Poly(e, *others).total_degree() > FINAL_DEGREE for e in rest if e.free_symbols):
        return None
    found = _solve(rest, others)
    if found is None:
        return None
    return [{**root, unknown: mp_value(value, root)} for root in found]


def _split(equations: list[sympy.Expr], unknowns: list[sympy.Symbol]) -> list[Root] | None:
    """The roots of a block one of whose equations (rational coefficients) factors: the
    union of the roots of the blocks with each factor in its place; None when none
    factors."""
    for i, equation in enumerate(equations):
        polynomial = sympy.Poly(equation, *unknowns)
        if not polynomial.domain.is_QQ and not polynomial.domain.is_ZZ:
            continue
        factors = [f for f, _ in sympy.factor_list(equation, *unknowns)[1]]
        if len(factors) < 2:
            continue
        found: list[Root] = []
        for factor in factors:
            branch = _solve([*equations[:i], sympy.expand(factor), *equations[i + 1 :]], unknowns)
            if branch is None:
                return None
            found += branch
        return found
    return None


def _distinct(roots: list[Root]) -> list[Root]:
    """Each root once: two roots of different factors that agree to about 25 digits
    (relative; exactly the same point found twice) are one."""
    tolerance = mpmath.mpf(10) ** -(numeric_digits() + 10)
    kept: list[Root] = []
    for root in roots:
        if not any(
            all(abs(root[u] - old[u]) <= tolerance * max(abs(root[u]), abs(old[u])) for u in root)
            for old in kept
        ):
            kept.append(root)
    return kept
