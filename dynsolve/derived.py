"""Derived finds: ``define:`` lines, expressions of givens, finds and scene quantities.

``dE = T(ram, 2) - T(ram, 3)`` is parsed by the spec parser (never evaluated): each call
of a scene quantity is resolved by the scene like a find, every other name must be a
given, a find or an earlier define, and the expression is dimension-checked like any
equation before it becomes sympy. A rotation or a component enters with its sign (ccw,
along its axis), a vector by its magnitude.

>>> import sympy
>>> from dynsolve.modes.equation_mode import Target
>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec("scene:\\n  gravity\\ndefine:\\n  twice = 2*v", "d.dyn")
>>> v = Target("v", sympy.Symbol("v"), Dim(1, 0, -1), "m/s", False, False, "magnitude",
...            sympy.Symbol("v_2"))
>>> (twice,) = define_targets(spec, (v,), {}, {}, resolve=None)
>>> twice.expr, twice.dim == v.dim
(2*v_2, True)
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Mapping
from dataclasses import replace

import sympy

from dynsolve.dimensions import check_dimensions
from dynsolve.errors import Position, SpecError
from dynsolve.expressions import to_sympy
from dynsolve.modes.equation_mode import Target
from dynsolve.spec.ast import Binary, Call, EquationStmt, Expr, Name, Num, Spec, Unary
from dynsolve.spec.parser import FUNCTIONS
from dynsolve.units import Dim

# resolves a scene quantity called in a define line: (function, args, where) → its target
Resolver = Callable[[str, tuple[str, ...], Position], Target]


def define_targets(
    spec: Spec,
    targets: tuple[Target, ...],
    symbols: Mapping[str, sympy.Expr],
    dims: Mapping[str, Dim],
    resolve: Resolver | None,
) -> tuple[Target, ...]:
    """One target per define line, in order; ``targets`` are the finds they may use,
    ``symbols`` and ``dims`` the givens (and ``g``)."""
    values: dict[str, sympy.Expr] = {n: s for n, s in symbols.items()}
    known: dict[str, Dim] = {**dims, "pi": Dim()}
    for target in targets:
        values[target.name], known[target.name] = _signed(target), target.dim
    defined: list[Target] = []
    for line in spec.defines:
        name = line.lhs.text  # type: ignore[union-attr]
        if name in known:
            what = "find" if name in {t.name for t in (*targets, *defined)} else "given"
            raise SpecError(
                f"'{name}' is already a {what}",
                Position(spec.file, line.line, line.column),
                hint="choose another name for the derived quantity",
            )
        calls: dict[str, tuple[sympy.Expr, Dim]] = {}
        rhs = _calls_named(line.rhs, calls, spec.file, resolve)
        for called, (value, dim) in calls.items():
            values[called], known[called] = value, dim
        _check_names(rhs, known, spec.file)
        probe = EquationStmt(Name("__define__", line.line, line.column), "=", rhs, "", "",
                             line.line, line.column)  # fmt: skip
        dim = check_dimensions((probe,), known, spec.file, spec.system).dims["__define__"]
        expr = to_sympy(rhs, values)
        target = Target(name, sympy.Symbol(name), dim, "", False, False, "signed", expr)
        defined.append(target)
        values[name], known[name] = expr, dim
    return tuple(defined)


def called_functions(spec: Spec) -> set[str]:
    """The scene quantities the define lines call (``T``, ``work``, …).

    >>> from dynsolve.spec.parser import parse_spec
    >>> text = "scene:\\n  gravity\\ndefine:\\n  d = T(1) - sqrt(T(2))"
    >>> called_functions(parse_spec(text, "d.dyn"))
    {'T'}
    """
    found: set[str] = set()
    stack: list[Expr] = [line.rhs for line in spec.defines]
    while stack:
        node = stack.pop()
        if isinstance(node, Call):
            if node.function not in FUNCTIONS:
                found.add(node.function)
            stack.extend(node.args)
        elif isinstance(node, Unary):
            stack.append(node.operand)
        elif isinstance(node, Binary):
            stack.extend((node.left, node.right))
    return found


def _signed(target: Target) -> sympy.Expr:
    """The target's value in a define line: steepest(C) kept as a call, put in once solved."""
    if target.kind == "steepest":
        assert isinstance(target.expr, sympy.Symbol)
        return sympy.Function("steepest")(target.expr)
    if target.vector is not None:
        x, y = target.vector
        return sympy.sqrt(x**2 + y**2)
    assert target.expr is not None
    return target.expr


def _calls_named(
    expr: Expr, calls: dict[str, tuple[sympy.Expr, Dim]], file: str, resolve: Resolver | None
) -> Expr:
    """``expr`` with each scene-quantity call replaced by a name bound in ``calls``."""
    if isinstance(expr, Call) and expr.function not in FUNCTIONS:
        where = Position(file, expr.line, expr.column)
        args = tuple(_argument(a, file) for a in expr.args)
        if resolve is None:
            raise SpecError(f"'{expr.function}' is not a function", where, "use a scene quantity")
        target = resolve(expr.function, args, where)
        name = f"__{len(calls)}__"
        calls[name] = (_signed(target), target.dim)
        return Name(name, expr.line, expr.column)
    if isinstance(expr, Call):
        args = tuple(_calls_named(a, calls, file, resolve) for a in expr.args)
        return replace(expr, args=args)
    if isinstance(expr, Unary):
        return replace(expr, operand=_calls_named(expr.operand, calls, file, resolve))
    if isinstance(expr, Binary):
        left = _calls_named(expr.left, calls, file, resolve)
        return replace(expr, left=left, right=_calls_named(expr.right, calls, file, resolve))
    return expr


def _argument(arg: Expr, file: str) -> str:
    """A scene quantity's argument: a name (a body, a force) or a state's number."""
    if isinstance(arg, Name):
        return arg.text
    if isinstance(arg, Num) and arg.value.denominator == 1 and arg.value >= 0:
        return str(arg.value.numerator)
    raise SpecError(
        "a scene quantity takes names and state numbers",
        Position(file, arg.line, arg.column),  # type: ignore[union-attr]
        hint="e.g. T(ram, 2) or work(P, 1)",
    )


def _check_names(expr: Expr, known: Mapping[str, Dim], file: str) -> None:
    from dynsolve.spec.parser import iter_names

    for name in iter_names(expr):
        if name.text not in known:
            choices = [n for n in known if not n.startswith("__")]
            close = difflib.get_close_matches(name.text, choices, n=1)
            hint = (
                f"did you mean '{close[0]}'?"
                if close
                else "use givens, finds, earlier define lines or scene quantities such as T(B, 2)"
            )
            raise SpecError(
                f"'{name.text}' is not a given, a find or a defined quantity",
                Position(file, name.line, name.column),
                hint,
            )
