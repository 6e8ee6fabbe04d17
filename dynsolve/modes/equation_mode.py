"""Turn an equation-mode spec into a checked :class:`Problem`: symbols, exact givens, dimensions.

>>> from dynsolve.spec.parser import parse_spec
>>> problem = build_problem(parse_spec('''
... given:
...   m = 2 kg
... equations:
...   W = m*g
... find: W
... ''', "w.dyn"))
>>> [t.name for t in problem.targets], problem.targets[0].unit
(['W'], 'N')
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import sympy

from dynsolve.dimensions import DimensionReport, EquationCheck, check_dimensions
from dynsolve.errors import DimensionError, DynsolveError, Position, SpecError, with_others
from dynsolve.expressions import relation, to_sympy
from dynsolve.format import pretty_unit
from dynsolve.model.inertia import Term
from dynsolve.quantities import resolve_dimension, resolve_quantity, resolve_unit
from dynsolve.results import EquationRow, Step
from dynsolve.spec.ast import EquationStmt, FindItem, Given, Spec
from dynsolve.spec.parser import iter_names
from dynsolve.spec.printing import statement_latex, statement_text
from dynsolve.suspicious import likely_typos
from dynsolve.system import Constraint, Equation, EquationSystem
from dynsolve.units import GRAVITY, Dim, natural_unit
from dynsolve.usage import unused_note


@dataclass(frozen=True)
class GivenInfo:
    """A given resolved: its symbol, exact value in base units (None if symbolic), dimension."""

    name: str
    symbol: sympy.Symbol
    value: sympy.Expr | None
    dim: Dim
    given: Given | None  # None for the default g and for derived quantities
    note: str = ""  # for a derived quantity (r_G, I_O): what it is
    formula: sympy.Expr | None = None  # for a derived quantity: in terms of the givens
    shown: bool = False  # a modelling step the textbook prints (I_G = m k_G²) though no
    # equation names it (the equations use its formula)


@dataclass(frozen=True)
class Target:
    """A name in ``find`` with its display unit, and how its value is read.

    ``kind`` is "signed" in equation mode (the value as solved, sign and all). Scene
    mode reports magnitudes with a direction: "rotation" (ccw positive: cw/ccw),
    "along" (signed along ``axis``: a direction word), "vector" (``vector``'s
    magnitude and direction) or "magnitude" (a positive scalar). ``expr`` is the
    value in terms of the unknowns and givens; ``trial`` reads it from the first
    trial of a failed assumption.
    """

    name: str
    symbol: sympy.Symbol
    dim: Dim
    unit: str  # pint-parsable; "" for a pure number
    requested: bool
    is_given: bool
    kind: str = "signed"
    expr: sympy.Expr | None = None
    axis: tuple[sympy.Expr, sympy.Expr] | None = None
    vector: tuple[sympy.Expr, sympy.Expr] | None = None
    trial: bool = False
    parts: tuple[Term, ...] = ()  # a composite's I about a point, one line per part
    # quantities its derivation states first, (name, value, dimension): κ_max before a_max
    before: tuple[tuple[str, sympy.Expr, Dim], ...] = ()
    note: str = ""  # what the quantity is, where its name alone does not say (F_avg)


@dataclass(frozen=True)
class Problem:
    """A spec ready to solve: the equation system plus what is needed to report it."""

    spec: Spec
    givens: tuple[GivenInfo, ...]
    system: EquationSystem
    dims: DimensionReport
    targets: tuple[Target, ...]
    symbols: Mapping[str, sympy.Symbol]
    rows: tuple[EquationRow, ...] = ()  # each equation as written, with its unit check
    steps: tuple[Step, ...] = ()  # derivation steps known before solving (none here)
    notes: tuple[tuple[str, str], ...] = ()  # (name, detail) shown with the checks
    mode: str = "equations"


def build_problem(spec: Spec) -> Problem:
    """Resolve givens, infer and check dimensions, and build the sympy equation system."""
    file = spec.file
    if not spec.finds:
        raise SpecError(
            "nothing to find", Position(file, 1, 1), hint="add a 'find:' line, e.g. 'find: alpha'"
        )
    equations = [s for s in spec.equations if s.relation == "="]
    if not equations:
        raise SpecError(
            "no equations to solve",
            Position(file, 1, 1),
            hint="add an 'equations:' section with one equation per indented line",
        )
    givens = givens_of(spec)
    given_names = {g.name for g in givens}
    unknown_names = _unknown_names(spec.equations, given_names)
    _check_finds(spec, unknown_names, given_names)
    requested = _requested_dimensions(spec)
    known_dims = {g.name: g.dim for g in givens} | {"pi": Dim()}
    try:
        report = check_dimensions(
            spec.equations, known_dims, file, spec.system, requested,
            wanted=tuple(asked_name(f) for f in spec.finds),
        )  # fmt: skip
    except DynsolveError as error:  # a misspelt name is a new unknown of unknown dimension
        typos = likely_typos(spec)
        if typos:
            error.hint = "; ".join([*typos, error.hint] if error.hint else typos)
        raise
    symbols: dict[str, sympy.Symbol] = {g.name: g.symbol for g in givens}
    symbols.update({n: sympy.Symbol(n, real=True) for n in unknown_names})
    targets = tuple(_target(f, report, symbols, given_names, spec) for f in spec.finds)
    system = EquationSystem(
        equations=tuple(_equation(s, symbols) for s in equations),
        unknowns=tuple(symbols[n] for n in unknown_names),
        knowns={g.symbol: g.value for g in givens if g.value is not None},
        constraints=tuple(
            _constraint(s, symbols, file) for s in spec.equations if s.relation != "="
        ),
        wanted=(),
    )
    rows = tuple(_row(check, spec) for check in report.checks)
    read = {sym.name for e in system.equations for sym in e.residual.free_symbols}
    read |= {sym.name for c in system.constraints for sym in c.relation.free_symbols}
    read |= {f.name for f in spec.finds}
    notes = unused_note(givens, read)
    return Problem(spec, tuple(givens), system, report, targets, symbols, rows, notes=notes)


def _constraint(
    statement: EquationStmt, symbols: Mapping[str, sympy.Symbol], file: str
) -> Constraint:
    """A constraint line as a sympy relational; a side that is not real is a positioned error.

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("equations:\\n  a <= sqrt(asin(2))\\n  a = 1\\nfind: a", "c.dyn")
    >>> try:
    ...     _constraint(spec.equations[0], {"a": sympy.Symbol("a")}, "c.dyn")
    ... except SpecError as error:
    ...     print(error.position.line, error.message)
    2 this constraint compares a value that is not a real number
    """
    lhs, rhs = to_sympy(statement.lhs, symbols), to_sympy(statement.rhs, symbols)
    try:
        built = relation(statement.relation, lhs, rhs)
    except TypeError:  # sympy refuses to order a side it knows is not real
        raise SpecError(
            "this constraint compares a value that is not a real number",
            Position(file, statement.line, statement.column),
            hint="check square roots of negative numbers and asin/acos outside [-1, 1]",
        ) from None
    return Constraint(built, _plain(statement), statement.line)


def _row(check: EquationCheck, spec: Spec) -> EquationRow:
    """An equation as written, with the dimension both its sides share."""
    statement = check.statement
    unit = natural_unit(check.dim, spec.system) or "1"
    return EquationRow(
        line=statement.line,
        text=statement_text(statement),
        latex=statement_latex(statement),
        note=statement.note,
        dimension=f"{check.dim.name} [{pretty_unit(unit)}]",
        dimension_ok=check.ok,
        constraint=statement.relation != "=",
    )


def _requested_dimensions(spec: Spec) -> dict[str, Dim]:
    """Dimensions the user stated for unknowns: units in find, else in the answer key."""
    requested = {
        a.name: resolve_unit(a.quantity.unit, spec.file).dim
        for a in spec.answers
        if a.quantity is not None and a.quantity.unit is not None
    }
    requested.update(
        {asked_name(f): resolve_unit(f.unit, spec.file).dim for f in spec.finds if f.unit}
    )
    return requested


def asked_name(item: FindItem) -> str:
    """The equations' name a find item asks for: ``g_p`` for ``find: g = g_p``.

    >>> from dynsolve.spec.ast import QuantityRef
    >>> asked_name(FindItem("g", None, 1, 7, QuantityRef("g_p", (), 1, 11)))
    'g_p'
    >>> asked_name(FindItem("a", None, 1, 7))
    'a'
    """
    return item.ref.function if item.ref is not None else item.name


def _plain(statement: EquationStmt) -> str:
    return f"{statement.lhs} {statement.relation} {statement.rhs}"


def givens_of(spec: Spec) -> list[GivenInfo]:
    """Every given resolved (and g, with its default value unless the spec gives it)."""
    out: list[GivenInfo] = []
    errors: list[DynsolveError] = []
    for given in spec.givens:
        symbol = sympy.Symbol(given.name, positive=True)
        if given.quantity is not None:
            try:
                value, dim = resolve_quantity(given.quantity, spec.system, spec.file)
            except DynsolveError as error:  # every bad unit of the givens at once
                errors.append(error)
                continue
            if value.is_zero or value.is_negative:  # magnitudes may be zero or signed
                symbol = sympy.Symbol(given.name, real=True)
            out.append(GivenInfo(given.name, symbol, value, dim, given))
        else:
            assert given.dimension is not None
            try:
                dim = resolve_dimension(given.dimension, spec.file)
            except DynsolveError as error:
                errors.append(error)
                continue
            out.append(GivenInfo(given.name, symbol, None, dim, given))
    if errors:
        raise with_others(errors)
    for info in out:
        if info.name == "g" and info.dim != Dim(1, 0, -2):
            assert info.given is not None
            raise DimensionError(
                f"g is the gravitational acceleration, but it is given as {info.dim.name}",
                Position(spec.file, info.given.line, info.given.column),
                hint="give it a unit, e.g. 'g = 9.81 m/s^2' or 'g = 32.2 ft/s^2'",
            )
    if not any(g.name == "g" for g in out):
        value = sympy.Rational(GRAVITY[spec.system][0])
        out.append(GivenInfo("g", sympy.Symbol("g", positive=True), value, Dim(1, 0, -2), None))
    return out


def _unknown_names(statements: tuple[EquationStmt, ...], given: set[str]) -> list[str]:
    seen: dict[str, None] = {}
    for statement in statements:
        for side in (statement.lhs, statement.rhs):
            for name in iter_names(side):
                if name.text not in given and name.text != "pi":
                    seen.setdefault(name.text, None)
    return list(seen)


def _check_finds(spec: Spec, unknowns: list[str], given: set[str]) -> None:
    seen: set[str] = set()
    for item in spec.finds:
        where = Position(spec.file, item.line, item.column)
        if item.name in seen:
            raise SpecError(f"'{item.name}' is listed twice in find", where, "remove one")
        seen.add(item.name)
        if item.ref is not None:
            _check_alias(spec, item, unknowns)
            where = Position(spec.file, item.ref.line, item.ref.column)
        name = asked_name(item)
        if name not in unknowns and name not in given:
            close = difflib.get_close_matches(name, unknowns + sorted(given), n=1)
            hint = f"did you mean '{close[0]}'?" if close else "use a name from the equations"
            raise SpecError(f"'{name}' in find appears in no equation", where, hint)
    check_answers_in_find(spec)


def check_find_names(spec: Spec) -> None:
    """Refuse, in a scene or a motion, a find ``NAME = quantity`` whose NAME is a given
    (or g, pi): the answer would wear the given's name, and read as its value.

    >>> from dynsolve.spec.parser import parse_spec
    >>> text = "given:\\n  b = 5 m/s^2\\nkinematics:\\n  a = -b\\nfind: b = x(2)"
    >>> check_find_names(parse_spec(text, "k.dyn"))
    Traceback (most recent call last):
    dynsolve.errors.SpecError: k.dyn:5:7: 'b' in find would name x(2), but b is a given \
(line 2) (hint: name the answer otherwise, e.g. 'b_1 = x(2)')
    """
    givens = {g.name: g.line for g in spec.givens}
    for item in spec.finds:
        ref = item.ref
        if ref is None or (ref.function == item.name and not ref.args):
            continue
        if item.name in givens:
            clash = f"{item.name} is a given (line {givens[item.name]})"
        elif item.name == "g":
            clash = "g is the gravitational acceleration"
        elif item.name == "pi":
            clash = "pi is the constant 3.14159…"
        else:
            continue
        asked = ref.function + (f"({', '.join(ref.args)})" if ref.args else "")
        raise SpecError(
            f"'{item.name}' in find would name {asked}, but {clash}",
            Position(spec.file, item.line, item.column),
            hint=f"name the answer otherwise, e.g. '{item.name}_1 = {asked}'",
        )


def _check_alias(spec: Spec, item: FindItem, unknowns: list[str]) -> None:
    """Refuse ``find: NAME = OTHER`` where NAME already means something else in the spec
    (a given, an unknown, g in the equations, pi), or OTHER is a scene quantity.

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  L = 1 m\\nequations:\\n  L = g*g_p\\nfind: g = g_p", "p.dyn")
    >>> try:
    ...     _check_alias(spec, spec.finds[0], ["g_p"])
    ... except SpecError as error:
    ...     print(error.position.column, error.message.split(", but ")[1])
    7 g is the gravitational acceleration the equations use (9.81 m/s² unless given)
    """
    assert item.ref is not None
    ref, name = item.ref, item.name
    if ref.args:
        raise SpecError(
            f"{ref.function}({', '.join(ref.args)}) is a scene quantity: equation mode has "
            "no scene to read it from",
            Position(spec.file, ref.line, ref.column),
            hint=f"find a name from the equations, e.g. 'find: {name}'",
        )
    if ref.function == name:
        return
    in_equations = {n.text for s in spec.equations for side in (s.lhs, s.rhs)
                    for n in iter_names(side)}  # fmt: skip
    given = next((g for g in spec.givens if g.name == name), None)
    if given is not None:
        clash = f"{name} is a given (line {given.line})"
    elif name == "pi":
        clash = "pi is the constant 3.14159…"
    elif name == "g" and "g" in in_equations:
        clash = (
            "g is the gravitational acceleration the equations use "
            f"({'9.81 m/s²' if spec.system == 'SI' else '32.2 ft/s²'} unless given)"
        )
    elif name in unknowns:
        clash = f"{name} is another unknown of the equations"
    else:
        return
    raise SpecError(
        f"'{name}' in find would name {ref.function}, but {clash}",
        Position(spec.file, item.line, item.column),
        hint=f"name the answer otherwise, e.g. 'find: {name}_local = {ref.function}', "
        f"or ask for {ref.function} itself",
    )


def check_answers_in_find(spec: Spec, also: Iterable[str] = ()) -> None:
    """Refuse an answer whose name is not in ``find`` or ``also`` (nothing to compare it with).

    >>> from dynsolve.spec.parser import parse_spec
    >>> text = "kinematics:\\n  x = 2*t\\nfind: v_t = v(t)\\nanswers:\\n  w = 1"
    >>> check_answers_in_find(parse_spec(text, "k.dyn"))
    Traceback (most recent call last):
    dynsolve.errors.SpecError: k.dyn:5:3: answer 'w' is not in find (hint: add 'w' to find)
    """
    seen = {item.name for item in spec.finds} | set(also)
    for answer in spec.answers:
        if answer.name not in seen:
            close = difflib.get_close_matches(answer.name, sorted(seen), n=1)
            hint = f"did you mean '{close[0]}'?" if close else f"add '{answer.name}' to find"
            raise SpecError(
                f"answer '{answer.name}' is not in find",
                Position(spec.file, answer.line, answer.column),
                hint,
            )


def _target(
    item: FindItem,
    report: DimensionReport,
    symbols: Mapping[str, sympy.Symbol],
    given: set[str],
    spec: Spec,
) -> Target:
    dim = report.dims[asked_name(item)]
    if item.unit is not None:
        unit_dim = resolve_unit(item.unit, spec.file).dim
        if unit_dim != dim:
            raise DimensionError(
                f"find asks for {item.name} in {item.unit.text} ({unit_dim.name}), "
                f"but the equations make it {_article(dim.name)}",
                Position(spec.file, item.unit.line, item.unit.column),
                hint=f"use a unit of {dim.name}, e.g. '{natural_unit(dim, spec.system) or '1'}'",
            )
        unit = item.unit.text
    elif dim.dimensionless and asked_name(item) in report.angles:
        unit = "deg"
    else:
        unit = natural_unit(dim, spec.system, item.name)
    if item.ref is not None and item.ref.function != item.name:  # another name for it
        symbol = symbols[item.ref.function]
        return Target(item.name, symbol, dim, unit, item.unit is not None, False, expr=symbol)
    return Target(
        item.name, symbols[item.name], dim, unit, item.unit is not None, item.name in given
    )


def _article(text: str) -> str:
    return ("an " if text[:1] in "aeiou" else "a ") + text


def _equation(statement: EquationStmt, symbols: Mapping[str, sympy.Symbol]) -> Equation:
    return Equation(
        lhs=to_sympy(statement.lhs, symbols),
        rhs=to_sympy(statement.rhs, symbols),
        label=f"line {statement.line}",
        line=statement.line,
        note=statement.note,
    )
