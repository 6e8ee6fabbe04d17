"""One-line remarks on the answers: a mass that cancels, so the answer holds for any mass.

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
"""

from __future__ import annotations

from collections.abc import Mapping

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
