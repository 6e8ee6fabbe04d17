"""Closed sympy forms as mpmath numbers at the working precision, node by node.

sympy's ``evalf`` finds the precision that gives every digit asked for, at a cost of a
millisecond or more per form; a walk over the form's nodes in mpmath at a fixed
precision costs a tenth of that, and is right to that precision wherever nothing
cancels (callers that read a sign check it with a second precision). A repeated
subexpression is computed once. A node the walk does not know (a Piecewise, a special
function) raises :class:`NotQuick`, so the caller can fall back to ``evalf``.

>>> x = sympy.Symbol("x")
>>> with mpmath.workdps(20):
...     print(mp_value(sympy.sqrt(x) + sympy.pi, {x: mpmath.mpf(4)}))
5.1415926535897932385
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

import mpmath
import sympy

__all__ = ["NotQuick", "mp_size", "mp_value"]

Number = mpmath.mpf | mpmath.mpc

FUNCTIONS: dict[type, Callable[..., Number]] = {
    sympy.sin: mpmath.sin, sympy.cos: mpmath.cos, sympy.tan: mpmath.tan,
    sympy.asin: mpmath.asin, sympy.acos: mpmath.acos, sympy.atan: mpmath.atan,
    sympy.sinh: mpmath.sinh, sympy.cosh: mpmath.cosh, sympy.tanh: mpmath.tanh,
    sympy.exp: mpmath.exp, sympy.log: mpmath.log, sympy.Abs: abs, sympy.atan2: mpmath.atan2,
}  # fmt: skip


class NotQuick(Exception):
    """A node :func:`mp_value` does not know (the caller falls back to ``evalf``)."""


def mp_value(
    expr: sympy.Expr,
    point: Mapping[sympy.Basic, Number],
    seen: dict[sympy.Basic, Number] | None = None,
) -> Number:
    """``expr`` at ``point`` (its symbols' mpmath values) at the working precision.

    ``seen`` holds the nodes already computed (pass one dict for several forms at the
    same point). A symbol missing from ``point`` or an unknown node raises NotQuick; a
    division by zero, ZeroDivisionError.

    >>> a = sympy.Symbol("a")
    >>> mp_value(a**2 / 4 - sympy.cos(a), {a: mpmath.mpf(0)})
    mpf('-1.0')
    """
    seen = {} if seen is None else seen
    if expr in seen:
        return seen[expr]
    if expr.is_Symbol:
        if expr not in point:
            raise NotQuick(expr)
        value = point[expr]
    elif expr.is_Rational:
        value = mpmath.mpf(int(expr.p)) / int(expr.q)
    elif expr.is_Float:
        value = mpmath.mpf(expr._mpf_)
    elif expr is sympy.pi:
        value = +mpmath.pi
    elif expr is sympy.E:
        value = mpmath.e()
    elif expr is sympy.I:
        value = mpmath.mpc(0, 1)
    elif expr.is_Add:
        value = mpmath.fsum(mp_value(a, point, seen) for a in expr.args)
    elif expr.is_Mul:
        value = mpmath.fprod(mp_value(a, point, seen) for a in expr.args)
    elif expr.is_Pow:
        value = _power(expr, point, seen)
    elif type(expr) in FUNCTIONS:
        arguments = [mp_value(a, point, seen) for a in expr.args]
        value = FUNCTIONS[type(expr)](*arguments)
    else:
        raise NotQuick(expr)
    seen[expr] = value
    return value


def _power(
    expr: sympy.Pow, point: Mapping[sympy.Basic, Number], seen: dict[sympy.Basic, Number]
) -> Number:
    """A power: whole exponents exactly, ½ as a square root, others as mpmath's principal
    branch (sympy's too)."""
    base = mp_value(expr.base, point, seen)
    exponent = expr.exp
    if exponent.is_Integer:
        if exponent < 0 and base == 0:
            raise ZeroDivisionError("0 to a negative power")
        return base ** int(exponent)
    if exponent == sympy.S.Half:
        return mpmath.sqrt(base)
    return mpmath.power(base, mp_value(exponent, point, seen))


def mp_size(
    expr: sympy.Expr,
    point: Mapping[sympy.Basic, Number],
    seen: dict[sympy.Basic, Number] | None = None,
) -> mpmath.mpf:
    """The size of ``expr`` with every sum taken as a sum of magnitudes (products of sizes,
    powers with a positive exponent of the base's size), at ``point``: the scale a rounded
    zero is judged on, as :func:`dynsolve.solver.residuals.term_size` measures it.

    >>> a, b = sympy.symbols("a b")
    >>> mp_size(3 * (a - b), {a: mpmath.mpf(2), b: mpmath.mpf(2)})
    mpf('12.0')
    """
    seen = {} if seen is None else seen
    if expr.is_Add:
        return mpmath.fsum(mp_size(a, point, seen) for a in expr.args)
    if expr.is_Mul:
        return mpmath.fprod(mp_size(a, point, seen) for a in expr.args)
    if expr.is_Pow and expr.exp.is_number and expr.exp.is_positive:
        return mpmath.power(mp_size(expr.base, point, seen), mp_value(expr.exp, {}, seen))
    return abs(mp_value(expr, point, seen))
