"""Dimension inference and homogeneity checks over spec expressions, before any solving.

Every sum, every equation's two sides, every function argument and exponent gives a
constraint between dimensions. Unknowns' dimensions are inferred from those
constraints; then every constraint is checked and each failure is reported with its
line, the two sides or terms, their dimensions and a likely cause.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec("equations:\\n  F = m*a", "f.dyn")
>>> known = {"m": Dim.of("mass"), "a": Dim.of("acceleration")}
>>> report = check_dimensions(spec.equations, known, "f.dyn")
>>> report.dims["F"].name
'force'
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction

import sympy

from dynsolve.errors import DimensionError, Position
from dynsolve.spec.ast import Binary, Call, EquationStmt, Expr, Name, Num, Unary
from dynsolve.units import Dim, System, natural_unit

_DIMENSIONLESS_ARGUMENT = ("sin", "cos", "tan", "exp", "log", "asin", "acos", "atan")


@dataclass(frozen=True)
class _Mono:
    """A dimension known up to unknowns: ``known · Π D(u)^e``."""

    known: Dim
    powers: tuple[tuple[str, Fraction], ...] = ()

    def times(self, other: _Mono, sign: int = 1) -> _Mono:
        powers = dict(self.powers)
        for name, exp in other.powers:
            powers[name] = powers.get(name, Fraction(0)) + sign * exp
        known = self.known * other.known if sign > 0 else self.known / other.known
        return _Mono(known, tuple((n, e) for n, e in powers.items() if e != 0))

    def power(self, exponent: Fraction) -> _Mono:
        return _Mono(self.known**exponent, tuple((n, e * exponent) for n, e in self.powers))


@dataclass(frozen=True)
class _Constraint:
    """Two expressions that must share a dimension, and how to describe a failure."""

    kind: str  # "sides", "terms", "argument", "exponent"
    left: Expr
    right: Expr | None  # None: must be dimensionless
    left_mono: _Mono
    right_mono: _Mono
    statement: EquationStmt
    context: str = ""  # e.g. the function name for "argument"


@dataclass(frozen=True)
class EquationCheck:
    """The dimension check of one equation line."""

    statement: EquationStmt
    dim: Dim  # the dimension of both sides
    ok: bool


@dataclass(frozen=True)
class DimensionReport:
    """Every name's dimension and every equation's check."""

    dims: Mapping[str, Dim]
    checks: tuple[EquationCheck, ...]
    angles: frozenset[str] = field(default_factory=frozenset)  # names used as angles
    free: tuple[str, ...] = ()  # unknowns whose dimension the equations leave open


def check_dimensions(
    statements: Sequence[EquationStmt],
    known: Mapping[str, Dim],
    file: str,
    system: System = "SI",
    requested: Mapping[str, Dim] | None = None,
    wanted: tuple[str, ...] = (),
) -> DimensionReport:
    """Infer unknown dimensions and check every statement; raise on any conflict.

    ``known`` maps given names (and ``g``, ``pi``) to dimensions; ``requested`` maps
    unknowns to the dimension of the unit asked for in ``find``. An unknown whose
    dimension the equations leave open is an error when it is ``wanted``; otherwise
    it is taken as dimensionless (the equations hold for any choice) and listed in
    the report's ``free``.
    """
    dims: dict[str, Dim] = dict(known)
    collector = _Collector(dims)
    constraints: list[_Constraint] = []
    for statement in statements:
        constraints.extend(collector.equation(statement))
    _infer(constraints, dims)
    # requested units fill in only what the equations leave open; a requested unit
    # that contradicts the equations is reported at the find line by the caller
    for name, dim in (requested or {}).items():
        if name not in dims:
            dims[name] = dim
            _infer(constraints, dims)
    names = {n for s in statements for n in _names(s)}
    free = _fix_free_dimensions(constraints, dims, names, set(requested or ()) | set(wanted))
    if free.asked:
        first = next(s for s in statements if any(n in free.asked for n in _names(s)))
        shown = ", ".join(free.asked)
        raise DimensionError(
            f"cannot infer the dimension of {shown} from the equations",
            Position(file, first.line, first.column),
            hint=f"give it an output unit in find: '{free.asked[0]} [unit]'",
        )
    errors = [_describe(c, dims, file, system) for c in constraints if not _holds(c, dims)]
    if errors:
        first, *others = errors
        first.others = others  # type: ignore[attr-defined]
        raise first
    checks = tuple(
        EquationCheck(s, _resolve(collector.side_mono[id(s)], dims), True) for s in statements
    )
    return DimensionReport(dims, checks, frozenset(collector.angles), tuple(free.unasked))


class _Collector:
    """Walks expressions, building monomials and constraints."""

    def __init__(self, dims: Mapping[str, Dim]) -> None:
        self.dims = dims
        self.constraints: list[_Constraint] = []
        self.statement: EquationStmt | None = None
        self.side_mono: dict[int, _Mono] = {}
        self.angles: set[str] = set()

    def equation(self, statement: EquationStmt) -> list[_Constraint]:
        self.constraints = []
        self.statement = statement
        left = self.mono(statement.lhs)
        right = self.mono(statement.rhs)
        self.side_mono[id(statement)] = right if _is_zero(statement.lhs) else left
        if not (_is_zero(statement.lhs) or _is_zero(statement.rhs)):
            self.constraints.insert(
                0, _Constraint("sides", statement.lhs, statement.rhs, left, right, statement)
            )
        return self.constraints

    def mono(self, expr: Expr) -> _Mono:
        if isinstance(expr, Num):
            return _Mono(Dim())
        if isinstance(expr, Name):
            if expr.text in self.dims:
                return _Mono(self.dims[expr.text])
            return _Mono(Dim(), ((expr.text, Fraction(1)),))
        if isinstance(expr, Unary):
            return self.mono(expr.operand)
        if isinstance(expr, Call):
            return self.call(expr)
        return self.binary(expr)

    def binary(self, expr: Binary) -> _Mono:
        assert self.statement is not None
        if expr.op in "+-":
            terms = [t for t in _terms(expr) if not _is_zero(t)] or [expr.left]
            monos = [self.mono(t) for t in terms]
            for term, mono in zip(terms[1:], monos[1:], strict=True):
                self.constraints.append(
                    _Constraint("terms", terms[0], term, monos[0], mono, self.statement)
                )
            return monos[0]
        left = self.mono(expr.left)
        if expr.op == "^":
            exponent = constant_value(expr.right)
            if exponent is None:
                self.dimensionless(expr.right, "exponent")
                self.dimensionless(expr.left, "base of a symbolic power")
                return _Mono(Dim())
            return left.power(exponent)
        right = self.mono(expr.right)
        return left.times(right, 1 if expr.op == "*" else -1)

    def call(self, expr: Call) -> _Mono:
        name = expr.function
        if name in _DIMENSIONLESS_ARGUMENT:
            (arg,) = expr.args
            self.dimensionless(arg, name)
            if name in ("sin", "cos", "tan") and isinstance(arg, Name):
                self.angles.add(arg.text)
            return _Mono(Dim())
        if name == "atan2":
            y, x = expr.args
            assert self.statement is not None
            self.constraints.append(
                _Constraint("argument", y, x, self.mono(y), self.mono(x), self.statement, name)
            )
            return _Mono(Dim())
        inner = self.mono(expr.args[0])
        return inner.power(Fraction(1, 2)) if name == "sqrt" else inner

    def dimensionless(self, expr: Expr, context: str) -> None:
        assert self.statement is not None
        self.constraints.append(
            _Constraint(
                "argument", expr, None, self.mono(expr), _Mono(Dim()), self.statement, context
            )
        )


def _terms(expr: Expr) -> list[Expr]:
    """The terms of a sum, left to right (signs dropped: they do not change dimensions)."""
    out: list[Expr] = []
    stack = [expr]
    while stack:
        node = stack.pop()
        if isinstance(node, Binary) and node.op in "+-":
            stack.extend((node.right, node.left))
        else:
            out.append(node)
    return out


def _is_zero(expr: Expr) -> bool:
    """A literal zero fits any dimension (``F - m*a = 0``)."""
    return constant_value(expr) == 0


def constant_value(expr: Expr) -> Fraction | None:
    """The value of an expression made only of numbers, else ``None``.

    >>> from dynsolve.spec.ast import Num
    >>> constant_value(Binary("/", Num(Fraction(1), "1", 1, 1), Num(Fraction(2), "2", 1, 3), 1, 1))
    Fraction(1, 2)
    """
    if isinstance(expr, Num):
        return expr.value
    if isinstance(expr, Unary):
        inner = constant_value(expr.operand)
        return None if inner is None else -inner
    if isinstance(expr, Binary) and expr.op != "^":
        left, right = constant_value(expr.left), constant_value(expr.right)
        if left is None or right is None:
            return None
        if expr.op == "/":
            return None if right == 0 else left / right
        return {"+": left + right, "-": left - right, "*": left * right}[expr.op]
    return None


def _infer(constraints: list[_Constraint], dims: dict[str, Dim]) -> None:
    """Fill ``dims`` from constraints that leave exactly one unknown, until nothing changes."""
    progress = True
    while progress:
        progress = False
        for c in constraints:
            net = c.left_mono.times(c.right_mono, -1)
            pending = [(n, e) for n, e in net.powers if n not in dims]
            if len(pending) != 1:
                continue
            name, exponent = pending[0]
            rest = net.known
            for other, e in net.powers:
                if other != name:
                    rest = rest * dims[other] ** e
            # rest · D(name)^exponent = 1
            dims[name] = (Dim() / rest) ** (1 / exponent)
            progress = True


@dataclass(frozen=True)
class _Free:
    asked: list[str]
    unasked: list[str]


def _fix_free_dimensions(
    constraints: list[_Constraint], dims: dict[str, Dim], names: set[str], wanted: set[str]
) -> _Free:
    """Pin unknowns the constraints leave open: one at a time, to dimensionless."""
    free: list[str] = []
    while True:
        open_names = sorted(names - set(dims))
        if not open_names:
            break
        asked = [n for n in open_names if n in wanted]
        if asked:
            return _Free(asked, free)
        dims[open_names[0]] = Dim()
        free.append(open_names[0])
        _infer(constraints, dims)
    return _Free([], free)


def _resolve(mono: _Mono, dims: Mapping[str, Dim]) -> Dim:
    result = mono.known
    for name, exp in mono.powers:
        result = result * dims[name] ** exp
    return result


def _holds(c: _Constraint, dims: Mapping[str, Dim]) -> bool:
    return _resolve(c.left_mono, dims) == _resolve(c.right_mono, dims)


def _names(statement: EquationStmt) -> set[str]:
    from dynsolve.spec.parser import iter_names

    return {n.text for side in (statement.lhs, statement.rhs) for n in iter_names(side)}


def _shown(dim: Dim, system: System) -> str:
    unit = natural_unit(dim, system) or "1"
    return f"{dim.name} [{unit.replace('*', '·')}]"


def _describe(c: _Constraint, dims: Mapping[str, Dim], file: str, system: System) -> DimensionError:
    left, right = _resolve(c.left_mono, dims), _resolve(c.right_mono, dims)
    statement = c.statement
    where = Position(file, statement.line, statement.column)
    hint = likely_cause(left, right)
    if c.kind == "sides":
        message = (
            f"line {statement.line}: left side is {_article(_shown(left, system))}, "
            f"right side is {_article(_shown(right, system))}"
        )
    elif c.kind == "terms":
        message = (
            f"line {statement.line}: terms '{c.left}' and '{c.right}' cannot be added: "
            f"{_shown(left, system)} vs {_shown(right, system)}"
        )
        where = Position(file, c.right.line, c.right.column) if c.right else where
    else:
        what = (
            "an angle or a pure number" if c.context in _DIMENSIONLESS_ARGUMENT else "a pure number"
        )
        if c.context == "atan2":
            message = (
                f"line {statement.line}: atan2 needs both arguments of one dimension, "
                f"got {_shown(left, system)} and {_shown(right, system)}"
            )
        else:
            message = (
                f"line {statement.line}: the {_context(c.context)} must be {what}, "
                f"but '{c.left}' is {_article(_shown(left, system))}"
            )
            hint = "divide by a reference quantity, or check the units of the givens"
        where = Position(file, c.left.line, c.left.column)
    return DimensionError(message, where, hint)


def _context(context: str) -> str:
    if context in ("exponent", "base of a symbolic power"):
        return context
    return f"argument of {context}"


def _article(text: str) -> str:
    return ("an " if text[:1] in "aeiou" else "a ") + text


_CAUSES: dict[Dim, str] = {
    Dim(0, 0, -1): "a missing time derivative?",
    Dim(0, 0, 1): "an extra time derivative, or a missing factor of time (impulse F·Δt)?",
    Dim(1): "an extra length: a moment arm where none belongs?",
    Dim(-1): "a missing moment arm (length)?",
    Dim(0, 1): "an extra mass?",
    Dim(0, -1): "a missing mass?",
    Dim(1, 0, -2): "weight vs mass: W = m g?",
    Dim(-1, 0, 2): "weight vs mass: m = W/g?",
    Dim(2): "a moment of inertia vs a mass: I = m k²?",
    Dim(-2): "a mass vs a moment of inertia: I = m k²?",
    Dim(0, 0, -2): "ω vs α, or a missing second time derivative?",
    Dim(0, 0, 2): "α vs ω, or an extra second time derivative?",
    Dim(1, 0, -1): "a missing velocity factor (v or ω r)?",
    Dim(-1, 0, 1): "an extra velocity factor?",
}


def sympy_dimension(expr: sympy.Expr, dims: Mapping[sympy.Symbol, Dim]) -> Dim:
    """The dimension of a generated sympy expression; raises if a sum mixes dimensions.

    Used to check the equations scene mode writes (its symbols all have known dimensions).

    >>> import sympy
    >>> m, a = sympy.symbols("m a")
    >>> sympy_dimension(m * a, {m: Dim.of("mass"), a: Dim.of("acceleration")}).name
    'force'
    >>> R, x = sympy.symbols("R x")  # an angle from two lengths (numeric mode's untidied form)
    >>> angle = sympy.atan2(R * sympy.cos(x), R)
    >>> sympy_dimension(angle, {R: Dim.of("length"), x: Dim()}).dimensionless
    True
    """
    if expr.is_Number or expr.is_NumberSymbol or expr == 0:
        return Dim()
    if expr.is_Symbol:
        return dims[expr]
    if expr.is_Add:
        terms = [t for t in expr.args if t != 0]
        found = [sympy_dimension(t, dims) for t in terms]
        for term, dim in zip(terms[1:], found[1:], strict=True):
            if dim != found[0]:
                raise DimensionError(
                    f"terms '{terms[0]}' and '{term}' cannot be added: "
                    f"{found[0].name} vs {dim.name}",
                    hint=likely_cause(found[0], dim),
                )
        return found[0] if found else Dim()
    if expr.is_Mul:
        result = Dim()
        for factor in expr.args:
            result = result * sympy_dimension(factor, dims)
        return result
    if expr.is_Pow:
        base = sympy_dimension(expr.base, dims)
        if base.dimensionless:
            return Dim()
        exponent = expr.exp
        if not exponent.is_Rational:
            raise DimensionError(f"'{expr}' raises a dimensional quantity to a symbolic power")
        return base ** Fraction(int(exponent.p), int(exponent.q))
    if isinstance(expr, sympy.atan2):  # atan2(y, x): any dimension, the same for both
        y_dim, x_dim = (sympy_dimension(a, dims) for a in expr.args)
        if y_dim != x_dim and not (expr.args[0] == 0 or expr.args[1] == 0):
            raise DimensionError(
                f"the arguments of atan2 in '{expr}' differ: {y_dim.name} vs {x_dim.name}"
            )
        return Dim()
    if isinstance(expr, sympy.sign):
        sympy_dimension(expr.args[0], dims)
        return Dim()
    if isinstance(expr, sympy.Function):
        for arg in expr.args:
            if expr.func is not sympy.Abs and not sympy_dimension(arg, dims).dimensionless:
                raise DimensionError(f"the argument of {expr.func} in '{expr}' has a dimension")
        return sympy_dimension(expr.args[0], dims) if expr.func is sympy.Abs else Dim()
    return Dim()


def likely_cause(left: Dim, right: Dim) -> str:
    """A guess at why two dimensions differ, from their ratio.

    >>> likely_cause(Dim.of("force"), Dim.of("momentum"))
    'a missing time derivative?'
    """
    return _CAUSES.get(left / right, "check the units of the givens and each term")
