"""Formulas as the reader sees them: the one guard that keeps sympy's internals out of text.

sympy's integrator and solver leave bookkeeping in their results that no textbook prints:
``polar_lift`` and ``exp_polar`` (branches of the complex plane), ``Abs`` of a number, an
imaginary constant from a logarithm of a negative number in the formula of a real time,
an unevaluated ``Integral`` or ``Piecewise``, and Python's ``**``. Every formula shown
(terminal, Markdown, LaTeX, JSON) passes :func:`presentable` first: bookkeeping with a
tidy equivalent is replaced by it (``polar_lift(x)`` → x, ``exp_polar`` → exp, |−44.58| →
44.58, the real part of a real quantity's logarithms), and a form with none is refused
(None): the caller then shows the numbers and says so (:data:`NOT_SHOWN`).

>>> x, v = sympy.symbols("x v")
>>> formula_text(sympy.polar_lift(x) ** 2 + sympy.Abs(sympy.Float(-44.58)))
'x^2 + 44.58'
>>> formula_text(sympy.Integral(sympy.Piecewise((x, x > 0), (0, True)), x))
'(no tidy formula: numbers only)'
>>> formula_text(-sympy.log(v - 3) + sympy.log(v + 3) + 5 * sympy.I)
'-log(abs(v - 3)) + log(abs(v + 3))'
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy
from sympy.printing.str import StrPrinter

NOT_SHOWN = "(no tidy formula: numbers only)"
NOT_SHOWN_LATEX = "\\text{(no tidy formula: numbers only)}"

# what a tidy form has no use for, and what stands in for it
_BOOKKEEPING = {
    sympy.polar_lift: lambda x: x,
    sympy.exp_polar: sympy.exp,
    sympy.principal_branch: lambda x, period: x,
    sympy.unpolarify: lambda x, *_: x,
}
# what has no tidy equivalent: the formula is not shown
_UNSHOWABLE = (
    sympy.Integral,
    sympy.Piecewise,
    sympy.Derivative,
    sympy.Subs,
    sympy.RootSum,
    sympy.CRootOf,
    sympy.Sum,
    sympy.Product,
    sympy.Limit,
    sympy.Order,
    sympy.hyper,
    sympy.meijerg,
    sympy.periodic_argument,
    sympy.arg,
    sympy.re,
    sympy.im,
)
_NOT_FINITE = (sympy.nan, sympy.zoo, sympy.oo, -sympy.oo)


def presentable(expr: sympy.Expr, real: bool = True) -> sympy.Expr | None:
    """``expr`` fit to be shown: sympy's bookkeeping replaced by its tidy equivalent, or
    None where there is none. ``real``: the quantity is real (every quantity dynsolve
    shows), so an imaginary constant beside logarithms is the branch of a logarithm of a
    negative number, and the real part is the formula: log|u| for log u.

    >>> t, v = sympy.symbols("t v")
    >>> presentable(sympy.exp_polar(-t)), presentable(sympy.Abs(sympy.Integer(-3)) * t)
    (exp(-t), 3*t)
    >>> presentable(sympy.sqrt(v - 4) * sympy.I) is None
    True
    """
    expr = sympy.Integer(0) + expr
    for function, stand_in in _BOOKKEEPING.items():
        if expr.has(function):
            expr = expr.replace(function, stand_in)
    if any(a.args[0].is_number for a in expr.atoms(sympy.Abs)):  # |−44.58| = 44.58
        expr = expr.replace(
            lambda e: isinstance(e, sympy.Abs) and e.args[0].is_number,
            lambda e: sympy.Abs(e.args[0]),
        )
    if expr.has(*_UNSHOWABLE) or expr.has(*_NOT_FINITE):
        return None
    if real and expr.has(sympy.I):
        expr = _real_part(expr)
    return expr


def _real_part(expr: sympy.Expr) -> sympy.Expr | None:
    """A real quantity's formula freed of the imaginary constants its logarithms of
    negative numbers left (log(−c) = log c + iπ): those terms dropped and each log u
    written log|u|; None where an imaginary unit sits anywhere else. A constant inside a
    product, c (log d + iπ), is reached by distributing the products.

    >>> v = sympy.Symbol("v")
    >>> _real_part(2 * (sympy.log(3) + sympy.I * sympy.pi) - 2 * sympy.log(v - 3))
    -2*log(Abs(v - 3)) + 2*log(3)
    """
    if not expr.has(sympy.log):
        return None
    for form in (expr, sympy.expand_mul(expr)):
        terms = sympy.Add.make_args(form)
        kept = [
            term
            for term in terms
            if not (term.is_number and sympy.re(term).is_zero and term.has(sympy.I))
        ]
        if len(kept) == len(terms):
            continue
        real = sympy.Add(*kept).replace(
            sympy.log, lambda u: sympy.log(u) if u.is_positive else sympy.log(sympy.Abs(u))
        )
        if not real.has(sympy.I):
            return real
    return None


class _TextPrinter(StrPrinter):
    """sympy's text printer with |x| written as the spec language writes it, abs(x)."""

    def _print_Abs(self, expr: sympy.Abs) -> str:
        return f"abs({self._print(expr.args[0])})"


def formula_text(expr: sympy.Expr, names: Mapping[sympy.Symbol, sympy.Symbol] | None = None) -> str:
    """``expr`` as text (``^`` for powers, ``abs``), with ``names`` put in for its symbols
    (Greek letters), or :data:`NOT_SHOWN` where it has no tidy form."""
    tidy = presentable(expr)
    if tidy is None:
        return NOT_SHOWN
    if names:
        tidy = tidy.xreplace(dict(names))
    return _TextPrinter().doprint(tidy).replace("**", "^")


def formula_latex(
    expr: sympy.Expr, names: Mapping[sympy.Symbol, str] | None = None, **settings: object
) -> str:
    """``expr`` as LaTeX (``names``: each symbol's LaTeX), or :data:`NOT_SHOWN_LATEX`
    where it has no tidy form; ``settings`` go to ``sympy.latex``."""
    tidy = presentable(expr)
    if tidy is None:
        return NOT_SHOWN_LATEX
    if names:
        settings["symbol_names"] = dict(names)
    return sympy.latex(tidy, **settings)
