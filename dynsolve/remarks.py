"""One-line remarks on the answers: a mass that cancels, and a limit case that tells.

The textbook remarks when a mass drops out ("the speed does not depend on the bob's
mass"). An answer's formula is followed back through the solve's blocks (and the derived
quantities such as I_G = m k_G²) to the givens; a mass that the equations of its
derivation use but the formula does not contain has cancelled. A mass no equation of the
answer's derivation holds (another body's, one of a later stage) never entered it: it did
not cancel, and is not remarked. Only formulas the solve derived symbolically are read: a
block solved in floating point has lost its letters, and a letter missing there says
nothing. (The caller confirms each remark by solving again with the mass changed: a
formula read under an assumption, no slip, holds only while the assumption does.)

>>> m, g, h, v = sympy.symbols("m g h v", positive=True)
>>> uses = {v: frozenset({m, g, h})}  # v's equation: m g h = m v²/2
>>> cancelled_masses({"v_2": v}, {v: sympy.sqrt(2 * g * h)}, {m: "m"}, {g, h}, uses=uses)
(Remark(answers=('v_2',), masses=('m',)),)
>>> cancelled_masses({"N": v}, {v: m * g}, {m: "m"}, {g, h}, uses=uses)
()
>>> cancelled_masses({"v_2": v}, {v: sympy.sqrt(2 * g * h)}, {m: "m"}, {g, h},
...                  uses={v: frozenset({g, h})})  # m never entered v's equations
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
from dynsolve.spec.ast import Name, Num, Spec
from dynsolve.spec.parser import iter_names

LARGEST = 4000  # operations: a formula larger than this is not followed back


def cancelled_masses(
    answers: Mapping[str, sympy.Expr],
    formulas: Mapping[sympy.Symbol, sympy.Expr],
    masses: Mapping[sympy.Symbol, str],
    givens: set[sympy.Symbol],
    unknowns: frozenset[sympy.Symbol] = frozenset(),
    uses: Mapping[sympy.Symbol, frozenset[sympy.Symbol]] | None = None,
) -> tuple[Remark, ...]:
    """For each answer (a name and its expression in the unknowns), the masses it does
    not depend on once ``formulas`` (each unknown, or derived quantity, in the givens and
    earlier unknowns) are put in, among those its derivation used. ``masses`` are the mass
    givens the equations use (their symbols and names), ``givens`` the other givens;
    ``uses`` maps each unknown (or derived quantity) to the symbols the equations (or the
    formula) it comes from hold (None: every mass counts as used). An answer left with no
    given at all (a number), or still holding an ``unknowns`` symbol (one solved in
    floats, without a formula), gets no remark."""
    cancelled: dict[tuple[str, ...], list[str]] = {}  # the masses gone: the answers
    for name, expr in answers.items():
        expr = sympy.Integer(0) + expr
        found = _in_givens(expr, formulas)
        if found is None:
            continue
        letters = found.free_symbols
        if letters & unknowns or not letters & (givens | set(masses)):
            continue
        entered = derivation_symbols(expr, uses) if uses is not None else set(masses)
        gone = tuple(
            label for symbol, label in masses.items() if symbol not in letters and symbol in entered
        )
        if gone:
            cancelled.setdefault(gone, []).append(name)
    remarks = [Remark(tuple(names), gone) for gone, names in cancelled.items()]
    return tuple(remarks)


def derivation_symbols(
    expr: sympy.Expr, uses: Mapping[sympy.Symbol, frozenset[sympy.Symbol]]
) -> set[sympy.Symbol]:
    """Every symbol ``expr``'s derivation holds: its own, and, for each unknown (or derived
    quantity) among them, those of the equations it was solved from (``uses``), and so on.

    >>> a, b, m, F = sympy.symbols("a b m F")
    >>> sorted(derivation_symbols(2 * a, {a: frozenset({F, m, a}), m: frozenset()}), key=str)
    [F, a, m]
    """
    seen: set[sympy.Symbol] = set()
    todo = list(expr.free_symbols)
    while todo:
        symbol = todo.pop()
        if symbol in seen:
            continue
        seen.add(symbol)
        todo.extend(uses.get(symbol, ()))
    return seen


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


START_SPEEDS = ("v_0", "v_x0", "v_y0")  # the start of a kinematics motion


def starting_speeds(spec: Spec) -> frozenset[str]:
    """The givens that are a starting speed, which at 0 means "from rest": a scene's body
    given a ``velocity`` and no spin (a disk given v_1 and ω_1 is not at rest when v_1 is
    0), or a kinematics motion's ``v_0`` (``v_x0``, ``v_y0``, and the givens they are
    written with). Equations give no such meaning: a speed there (a rebound's, a final
    one) is no start, and gets no "from rest" remark.

    >>> from dynsolve.spec.parser import parse_spec
    >>> sorted(starting_speeds(parse_spec(
    ...     "given:\\n  v_1 = 2 m/s\\n  w = 3 rad/s\\n  v_r = 1 m/s\\n  m = 1 kg\\n"
    ...     "scene:\\n  body a: particle, mass m\\n  velocity a: v_1, right\\n"
    ...     "  body b: particle, mass m\\n  velocity b: v_r, right\\n  omega b: w ccw\\n"
    ...     "find: x = speed(a)\\n", "s.dyn")))
    ['v_1']
    """
    spinning = {
        s.body
        for s in spec.scene
        if s.kind == "omega" and not (isinstance(s.value, Num) and s.value.value == 0)
    }
    starts = {
        name.text
        for s in spec.scene
        if s.kind == "velocity" and s.value is not None and s.body not in spinning
        for name in iter_names(s.value)
    }
    if spec.kinematics:
        starts.update(START_SPEEDS)
        for statement in spec.kinematics:
            if isinstance(statement.lhs, Name) and statement.lhs.text in START_SPEEDS:
                starts.update(n.text for n in iter_names(statement.rhs))
    return frozenset(starts)


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
