"""Small sympy helpers: real values of closed expressions, and cheap simplification.

>>> import sympy
>>> real_value(sympy.sqrt(2) * sympy.pi), real_value(sympy.Symbol("x")), real_value(sympy.I)
(4.442882938158366, None, None)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

import sympy

IMAGINARY_TOLERANCE = 1e-12
MAX_DIGITS = 400  # evalf may work this many digits through cancellation (sympy: 100)


def real_value(
    expr: sympy.Expr | int, substitution: Mapping[sympy.Symbol, sympy.Expr] | None = None
) -> float | None:
    """``expr`` (after ``substitution``) as a float; None if symbols remain or it is not real."""
    value = sympy.Integer(0) + expr
    if substitution:
        value = value.xreplace(dict(substitution))
    if value.free_symbols:
        return None
    number = complex(sympy.N(value, 30, maxn=MAX_DIGITS))
    if abs(number.imag) > IMAGINARY_TOLERANCE * abs(number.real):
        return None
    return number.real


def tidy(expr: sympy.Expr | int) -> sympy.Expr:
    """``expr`` simplified, skipping sympy's (costly) simplify when it is already simple.

    >>> import sympy
    >>> r = sympy.Symbol("r")
    >>> tidy(2 * r), tidy(sympy.sin(r) ** 2 + sympy.cos(r) ** 2)
    (2*r, 1)
    """
    expr = sympy.Integer(0) + expr
    if expr.is_Atom or sympy.count_ops(expr) <= 3:
        return expr
    return sympy.simplify(expr)


def mpmath_function(
    variables: Sequence[sympy.Symbol], expr: sympy.Expr | sympy.Matrix | list[sympy.Expr]
) -> Callable[..., object]:
    """``expr`` as a function of ``variables`` evaluated with mpmath.

    The variables are renamed first: lambdify puts every symbol of a matrix into the
    generated code's namespace under its own name, so an unknown called ``mpf`` would
    replace mpmath's ``mpf`` (and every constant written ``mpf(1)/mpf(2)`` would fail).

    >>> mpf, x = sympy.symbols("mpf x")
    >>> jacobian = mpmath_function([mpf, x], sympy.Matrix([[mpf / 2 + x]]))
    >>> jacobian(3, 1)
    matrix(
    [['2.5']])
    """
    renamed = {v: sympy.Dummy(f"u{i}") for i, v in enumerate(variables)}
    plain = (
        [e.xreplace(renamed) for e in expr] if isinstance(expr, list) else expr.xreplace(renamed)
    )
    return sympy.lambdify(list(renamed.values()), plain, modules="mpmath")
