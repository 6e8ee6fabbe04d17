"""Build sympy objects from spec AST nodes: the only place spec text becomes sympy.

Each node is mapped by hand to a sympy constructor from a fixed table; nothing is
evaluated, sympified or parsed from a string.

>>> import sympy
>>> from dynsolve.spec.parser import parse_spec
>>> eq = parse_spec("equations:\\n  y = sqrt(x^2 + 1)*pi", "e.dyn").equations[0]
>>> x, y = sympy.symbols("x y")
>>> to_sympy(eq.rhs, {"x": x, "y": y})
pi*sqrt(x**2 + 1)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

import sympy

from dynsolve.magnitude import Bound, OutOfRange, check_operation, value_bound
from dynsolve.spec.ast import Binary, Call, Expr, Name, Num, Unary

_FUNCTIONS: dict[str, Callable[..., sympy.Expr]] = {
    "sin": sympy.sin,
    "cos": sympy.cos,
    "tan": sympy.tan,
    "asin": sympy.asin,
    "acos": sympy.acos,
    "atan": sympy.atan,
    "atan2": sympy.atan2,
    "sqrt": sympy.sqrt,
    "exp": sympy.exp,
    "log": sympy.log,
    "abs": sympy.Abs,
}

_RELATIONS: dict[str, Callable[[sympy.Expr, sympy.Expr], sympy.Basic]] = {
    ">=": sympy.Ge,
    "<=": sympy.Le,
    ">": sympy.Gt,
    "<": sympy.Lt,
}


MAX_ROOT_INDEX = 1000  # a power whose exponent's denominator is larger is taken in floating point


def to_sympy(
    expr: Expr,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr] | None = None,
) -> sympy.Expr:
    """The sympy expression of ``expr``; ``symbols`` maps every name but ``pi``.

    Each power, product, sum and exponential is bounded before it is built
    (:mod:`dynsolve.magnitude`), with the symbols in ``values`` bounded by the
    values that will be put in later; the error names the operation's line and column.

    >>> from dynsolve.spec.parser import parse_spec
    >>> tower = parse_spec("equations:\\n  y = 2*10^10^10", "t.dyn").equations[0].rhs
    >>> try:
    ...     to_sympy(tower, {})
    ... except OutOfRange as error:
    ...     print(error.line, error.column, error.message)
    2 9 a value of about 1.0e10000000000 is out of range (limit 1e±300)
    """
    try:
        known = {k: value_bound(v) for k, v in (values or {}).items()}
        return _build(expr, symbols, known)
    except OutOfRange as error:
        raise error.at(expr.line, expr.column) from None


def _build(
    expr: Expr, symbols: Mapping[str, sympy.Expr], known: Mapping[sympy.Symbol, Bound]
) -> sympy.Expr:
    if isinstance(expr, Num):
        return sympy.Rational(expr.value.numerator, expr.value.denominator)
    if isinstance(expr, Name):
        return sympy.pi if expr.text == "pi" else symbols[expr.text]
    if isinstance(expr, Unary):
        return -_build(expr.operand, symbols, known)
    if isinstance(expr, Call):
        args = [_build(a, symbols, known) for a in expr.args]
        _checked(expr.function, args, known, expr)
        return _FUNCTIONS[expr.function](*args)
    if isinstance(expr, Binary) and expr.op in "+-":
        return _sum(expr, symbols, known)
    left, right = _build(expr.left, symbols, known), _build(expr.right, symbols, known)
    _checked(expr.op, [left, right], known, expr)
    if expr.op == "*":
        return left * right
    if expr.op == "/":
        return left / right
    if isinstance(right, sympy.Rational) and right.q > MAX_ROOT_INDEX:
        # 1e-9^1e-30 is a 10^30-th root: no readable exact form, and sympy's rational
        # arithmetic on it ran until the time budget; a 30-digit exponent is exact enough
        right = sympy.Float(right, 30)
    return left**right


def _sum(
    expr: Binary, symbols: Mapping[str, sympy.Expr], known: Mapping[sympy.Symbol, Bound]
) -> sympy.Expr:
    """A chain ``a + b - c + …`` built as one sum: the parser nests it to the left, and
    adding term by term re-sorts (and re-bounds) the growing sum each time, n² for n terms."""
    terms: list[sympy.Expr] = []
    node: Expr = expr
    while isinstance(node, Binary) and node.op in "+-":
        right = _build(node.right, symbols, known)
        terms.append(right if node.op == "+" else -right)
        node = node.left
    terms.append(_build(node, symbols, known))
    terms.reverse()
    _checked("+", terms, known, expr)
    return sympy.Add(*terms)


def _checked(
    function: str, args: list[sympy.Expr], known: Mapping[sympy.Symbol, Bound], expr: Expr
) -> None:
    try:
        check_operation(function, args, known)
    except OutOfRange as error:
        raise error.at(expr.line, expr.column) from None


def relation(op: str, lhs: sympy.Expr, rhs: sympy.Expr) -> sympy.Basic:
    """A sympy relational for a constraint operator (``>=``, ``<=``, ``>``, ``<``).

    >>> relation(">=", sympy.Symbol("w"), sympy.Integer(0))
    w >= 0
    """
    return _RELATIONS[op](lhs, rhs)
