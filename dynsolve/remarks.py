"""One-line remarks on the answers: a mass that cancels, and a limit case that tells.

The textbook remarks when a mass drops out ("the speed does not depend on the bob's
mass"). An answer's formula is followed back through the solve's blocks (and the derived
quantities such as I_G = m k_G²) to the givens; a mass that the equations use but the
formula does not contain has cancelled. Only formulas the solve derived symbolically are
read: a block solved in floating point has lost its letters, and a letter missing there
says nothing.

>>> m, g, h, v = sympy.symbols("m g h v", positive=True)
>>> cancelled_masses({"v_2": v}, {v: sympy.sqrt(2 * g * h)}, {m: "m"}, {g, h})
(Remark(answers=('v_2',), masses=('m',)),)
>>> cancelled_masses({"N": v}, {v: m * g}, {m: "m"}, {g, h})
()

The textbook also remarks a limit case where it frees the answer from the other givens
("started from rest, the block leaves the dome at cos θ = 2/3, whatever its radius"): a
start speed set to 0 (from rest) or a friction coefficient set to 0 (smooth) in the
answer's formula, remarked only when the limit no longer depends on some other given.

>>> v_1, R = sympy.symbols("v_1 R", positive=True)
>>> theta = sympy.acos(sympy.Rational(2, 3) + v_1**2 / (3 * g * R))
>>> [(c.given, c.case, c.limit, c.whatever) for c in limit_cases(
...     {"theta": theta}, {}, {v_1: ("v_1", "from rest"), R: ("R", ""), g: ("g", "")})]
[('v_1', 'from rest', acos(2/3), ('R', 'g'))]
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import sympy

from dynsolve.results import Remark

LARGEST = 4000  # operations: a formula larger than this is not followed back


def cancelled_masses(
    answers: Mapping[str, sympy.Expr],
    formulas: Mapping[sympy.Symbol, sympy.Expr],
    masses: Mapping[sympy.Symbol, str],
    givens: set[sympy.Symbol],
    unknowns: frozenset[sympy.Symbol] = frozenset(),
) -> tuple[Remark, ...]:
    """For each answer (a name and its expression in the unknowns), the masses it does
    not depend on once ``formulas`` (each unknown, or derived quantity, in the givens and
    earlier unknowns) are put in. ``masses`` are the mass givens the equations use (their
    symbols and names), ``givens`` the other givens; an answer left with no given at all
    (a number), or still holding an ``unknowns`` symbol (one solved in floats, without a
    formula), gets no remark."""
    cancelled: dict[tuple[str, ...], list[str]] = {}  # the masses gone: the answers
    for name, expr in answers.items():
        found = _in_givens(sympy.Integer(0) + expr, formulas)
        if found is None:
            continue
        letters = found.free_symbols
        if letters & unknowns or not letters & (givens | set(masses)):
            continue
        gone = tuple(label for symbol, label in masses.items() if symbol not in letters)
        if gone:
            cancelled.setdefault(gone, []).append(name)
    remarks = [Remark(tuple(names), gone) for gone, names in cancelled.items()]
    return tuple(remarks)


def _in_givens(expr: sympy.Expr, formulas: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr | None:
    """``expr`` with every unknown replaced by its formula until only givens are left, or
    None when it grows too large or does not settle."""
    for _ in range(len(formulas) + 2):
        if sympy.count_ops(expr) > LARGEST:
            return None
        new = expr.xreplace(formulas)
        if new == expr:
            return expr
        expr = new
    return None


@dataclass(frozen=True)
class LimitCase:
    """An answer's formula with one given set to 0, and the givens it then does not need."""

    answer: str
    given: str
    case: str  # "from rest", "smooth"
    limit: sympy.Expr  # the answer's formula in the limit, in the givens' symbols
    whatever: tuple[str, ...]  # the givens the limit no longer depends on


def limit_cases(
    answers: Mapping[str, sympy.Expr],
    formulas: Mapping[sympy.Symbol, sympy.Expr],
    givens: Mapping[sympy.Symbol, tuple[str, str]],
) -> tuple[LimitCase, ...]:
    """For each answer (a name and its expression in the unknowns) and each given with a
    limit case (``givens``: symbol → (name, case), case "" for none), the answer's formula
    with that given at 0, where it is finite and depends on fewer of the other givens."""
    cases = []
    for name, expr in answers.items():
        found = _in_givens(sympy.Integer(0) + expr, formulas)
        if found is None or not found.free_symbols or found.free_symbols - set(givens):
            continue  # no formula in the givens (solved in floats) or one still unknown
        for symbol, (given, case) in givens.items():
            if not case or symbol not in found.free_symbols:
                continue
            limit = _at_zero(found, symbol)
            if limit is None:
                continue
            gone = found.free_symbols - {symbol} - limit.free_symbols
            if gone:
                whatever = tuple(sorted(givens[s][0] for s in gone))
                cases.append(LimitCase(name, given, case, limit, whatever))
    return tuple(cases)


def _at_zero(formula: sympy.Expr, symbol: sympy.Symbol) -> sympy.Expr | None:
    """``formula`` with ``symbol`` = 0, tidied; None where it is not a finite real."""
    from dynsolve.numbers import tidy

    limit = formula.xreplace({symbol: sympy.Integer(0)})
    if limit.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo, sympy.I):
        return None
    limit = tidy(limit)
    if limit.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo, sympy.I) or limit.is_zero:
        return None
    return limit
