"""Evaluate sympy expressions to real floats, when they hold no free symbols.

>>> import sympy
>>> real_value(sympy.sqrt(2) * sympy.pi), real_value(sympy.Symbol("x")), real_value(sympy.I)
(4.442882938158366, None, None)
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

IMAGINARY_TOLERANCE = 1e-12


def real_value(
    expr: sympy.Expr | int, substitution: Mapping[sympy.Symbol, sympy.Expr] | None = None
) -> float | None:
    """``expr`` (after ``substitution``) as a float; None if symbols remain or it is not real."""
    value = sympy.Integer(0) + expr
    if substitution:
        value = value.xreplace(dict(substitution))
    if value.free_symbols:
        return None
    number = complex(sympy.N(value, 30))
    if abs(number.imag) > IMAGINARY_TOLERANCE * max(1.0, abs(number.real)):
        return None
    return number.real
