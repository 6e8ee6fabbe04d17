"""Turn a kinematics spec into a problem: the given motion, integrated.

A section naming plane components (``y``, ``v_x``, ``a_y``, ``r``, ``theta`` …) is plane
motion, built by :mod:`dynsolve.modes.plane_kinematics`. Otherwise it gives one relation of
rectilinear motion, ``a = …`` in t, v or x, or ``x = …`` /
``v = …`` in t; the initial conditions are the givens ``t_0``, ``x_0``, ``v_0`` (zero
when absent, except ``v_0``, which a(t), a(v) and a(x) need). ``find`` names relations
such as ``v(t)``, ``x(v)``, ``t(x)``, or their values at a given: ``v(t_1)``.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   c = 2 m/s^3
...   v_0 = 1 m/s
...   t_1 = 3 s
... kinematics:
...   a = c*t
... find: v_1 = v(t_1)
... ''', "k.dyn")
>>> problem = build_kinematics_problem(spec)
>>> problem.targets[0].expr
c*t_1**2/2 + v_0
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

import sympy

from dynsolve.dimensions import DimensionReport, check_dimensions
from dynsolve.errors import Position, SpecError
from dynsolve.expressions import to_sympy
from dynsolve.format import latex_unit, pretty_unit
from dynsolve.modes.equation_mode import GivenInfo, Target, check_answers_in_find, givens_of
from dynsolve.modes.oneline_events import EVENTS, QUANTITIES, find_event
from dynsolve.names import latex_name, pretty
from dynsolve.numbers import real_value
from dynsolve.principles.rectilinear import (
    KINDS,
    Motion,
    MotionBlowsUp,
    T,
    V,
    X,
    integrate_motion,
)
from dynsolve.quantities import resolve_unit
from dynsolve.results import EquationRow, Formula, Step
from dynsolve.sections import combine_sections
from dynsolve.shown import formula_latex, formula_text
from dynsolve.spec.ast import EquationStmt, FindItem, Spec
from dynsolve.spec.parser import iter_names
from dynsolve.system import EquationSystem
from dynsolve.units import Dim, System, natural_unit

VARIABLES: dict[str, tuple[sympy.Symbol, Dim]] = {
    "t": (T, Dim.of("time")),
    "x": (X, Dim.of("length")),
    "v": (V, Dim.of("velocity")),
}
ACCELERATION = Dim.of("acceleration")


@dataclass(frozen=True)
class KinematicsProblem:
    """The integrated motion, shaped like the other problems for the shared pipeline."""

    spec: Spec
    givens: tuple[GivenInfo, ...]
    system: EquationSystem
    dims: DimensionReport
    targets: tuple[Target, ...]
    symbols: Mapping[str, sympy.Symbol]
    rows: tuple[EquationRow, ...]
    steps: tuple[Step, ...]
    motion: Motion
    notes: tuple[tuple[str, str], ...] = ()
    mode: str = "kinematics"


def build_kinematics_problem(spec: Spec, numbers_first: bool = False) -> KinematicsProblem:
    """Check the given relation's units, integrate it, and resolve the find list
    (plane motion, with two relations, is handed to :mod:`dynsolve.modes.plane_kinematics`).

    ``numbers_first`` (numeric mode): the givens' values are put into the relation and the
    initial conditions once its units are checked, so the motion is integrated, inverted
    and searched for events with numbers (the steps show v(t) = 3*t^2 - 12*t + 9 rather
    than v(t) = c_1 - 2*c_2*t + 3*c_3*t^2); givens without a value stay letters.

    >>> from dynsolve.spec.parser import parse_spec
    >>> text = "given:\\n  c = 2 m/s\\nkinematics:\\n  x = c*t\\n  y = c*t\\nfind: v_t = v(t)"
    >>> build_kinematics_problem(parse_spec(text, "k.dyn")).targets[0].expr
    sqrt(2)*c
    """
    from dynsolve.modes.plane_kinematics import build_plane_problem, is_plane

    if is_plane(spec):
        if spec.defines or spec.equations:
            line = (*spec.equations, *spec.defines)[0]
            section = "equations:" if spec.equations else "define:"
            raise SpecError(
                f"the {section} section cannot be combined with plane kinematics yet",
                Position(spec.file, line.line, line.column),
                hint="find each quantity of the motion; derived quantities are for one-line "
                "motion and scenes",
            )
        return build_plane_problem(spec, numbers_first)
    file = spec.file
    if len(spec.kinematics) != 1:
        left = {str(st.lhs) for st in spec.kinematics}
        raise SpecError(
            "kinematics takes exactly one relation",
            Position(file, spec.kinematics[1].line if spec.kinematics[1:] else 1, 1),
            hint="dynsolve names the position x and y: write 'x = …' and 'y = …' for plane motion"
            if left & {"s", "s_x", "s_y"}
            else "give one of a = f(t), a = f(v), a = f(x), x = f(t) or v = f(t)",
        )
    spec = combine_sections(spec)
    check_answers_in_find(spec, (d.lhs.text for d in spec.defines))  # type: ignore[union-attr]
    givens = givens_of(spec)
    check_motion_names(givens, ("t", "x", "v", "a"), file)
    symbols: dict[str, sympy.Symbol] = {g.name: g.symbol for g in givens}
    statement = spec.kinematics[0]
    mass = _mass_times_a(statement, symbols)
    kind = _kind(statement, set(symbols), file, newton=mass is not None)
    known_dims = {g.name: g.dim for g in givens} | {n: d for n, (_, d) in VARIABLES.items()}
    known_dims |= {"a": ACCELERATION}
    report = check_dimensions((statement,), known_dims | {"pi": Dim()}, file, spec.system)
    values = {g.symbol: g.value for g in givens if g.value is not None}
    initial = {n: symbols.get(f"{n}_0", sympy.Integer(0)) for n in ("t", "x", "v")}
    if kind.startswith("a(") and "v_0" not in symbols:
        raise SpecError(
            "the initial velocity v_0 is not given",
            Position(file, statement.line, statement.column),
            hint="add 'v_0 = … m/s' under given:",
        )
    variables = {n: s for n, (s, _) in VARIABLES.items()}
    rhs = to_sympy(statement.rhs, {**symbols, **variables}, values)
    if mass is not None:  # F = m a with a force law: a = F/m
        rhs = rhs / mass
    invert = _inverts(spec, givens, kind)
    quick = numbers_first  # numeric mode: relations inverted by peeling where that finds one branch
    if kind in ("a(v)", "a(x)") and invert:
        # an a(v) or a(x) law inverted with the numbers in can cost sympy seconds at
        # extreme scales (exp(c*log(n)) = n**c expanded with c ~ 1e6; the roots of
        # v_0**2 - k*x**2 with v_0 = 6e-9); with letters its formulas do not change
        numbers_first = False
    if numbers_first:
        rhs = rhs.xreplace(values)
        initial = {n: sympy.Integer(0) + e.xreplace(values) for n, e in initial.items()}
    motion = integrate_motion(
        rhs, kind, initial["t"], initial["x"], initial["v"], invert, quick=quick, values=values
    )
    if kind in ("x(t)", "v(t)"):  # the start is the law's own
        initial |= {n: _tidy(motion.formulas[f"{n}(t)"].subs(T, initial["t"])) for n in "xv"}
    all_symbols = {**symbols, **{n: s for n, (s, _) in VARIABLES.items()}}
    given_dims = {g.name: g.dim for g in givens}
    numeric: list[Step] = []
    context = _Context(
        motion, all_symbols, given_dims, spec, values, initial, numeric, {}, numbers_first
    )
    defined_names = {line.lhs.text for line in spec.defines}  # type: ignore[union-attr]
    for item in spec.finds:
        if item.name in defined_names and item.ref is None:
            continue  # a define listed in find: resolved below
        if item.name in context.earlier:
            raise SpecError(
                f"'{item.name}' is listed twice in find",
                Position(file, item.line, item.column),
                hint="remove one",
            )
        target = context.target(item)
        _check_real(item, target, values, file)
        _check_after_start(item, target, initial["t"], values, file)
        _check_no_blow_up(item, motion, context.lookup(), initial["t"], values, file)
        context.earlier[item.name] = target
    targets = _with_defines(spec, context)
    notes = _check_usage(spec, givens, symbols, kind)
    dims = DimensionReport({**known_dims, **{t.name: t.dim for t in targets}}, (), frozenset())
    row = relation_row(statement, report.checks[0].dim, spec)
    steps = _steps(motion, values, all_symbols, numbers_first)
    steps += tuple(replace(step, index=len(steps) + i) for i, step in enumerate(numeric, 1))
    system = EquationSystem(equations=(), unknowns=(), knowns=values)
    return KinematicsProblem(
        spec, tuple(givens), system, dims, targets, all_symbols, (row,), steps, motion, notes
    )


def _inverts(spec: Spec, givens: Sequence[GivenInfo], kind: str) -> bool:
    """Whether the law's relations are inverted for the finds (sympy may spend seconds
    trying, and failing, on 12 t − 40π sin πt). Not when nothing asked needs it:

    - an acceleration law whose finds are all x or v at given times, every given with a
      value: numbers, which integrating the motion numerically gives directly;
    - a law in t (x(t), v(t), a(t)) whose finds are events or values at times: they read
      the laws in t (a relation in x or v, ``t(v_1)``, ``x(v)``, or a define needs t(v)).

    Laws in x or v are otherwise inverted: their laws in t come from the inversion.
    """
    if spec.defines:
        return True
    given_times = {g.name for g in givens if g.dim == _DIMS["t"]}

    def at_a_time(item: FindItem, quantities: tuple[str, ...], times: set[str]) -> bool:
        ref = item.ref
        return (
            ref is not None
            and ref.function in quantities
            and len(ref.args) == 1
            and ref.args[0] in times
        )

    numbers = all(g.value is not None for g in givens)
    at_given_times = all(at_a_time(item, ("x", "v"), given_times) for item in spec.finds)
    if kind.startswith("a(") and numbers and at_given_times:
        return False
    if kind in ("x(t)", "v(t)", "a(t)"):
        times = given_times | {"t", "t_0"}
        times |= {f.name for f in spec.finds if f.ref is not None and f.ref.function == "t_at"}
        return not all(
            (item.ref is not None and item.ref.function in EVENTS)
            or at_a_time(item, ("x", "v", "a"), times)
            for item in spec.finds
        )
    return True


def _tidy(expr: sympy.Expr) -> sympy.Expr:
    from dynsolve.numbers import tidy

    return tidy(expr)


@dataclass
class _Context:
    """What resolving a find needs: the motion, the givens, the start and earlier finds."""

    motion: Motion
    symbols: Mapping[str, sympy.Symbol]
    given_dims: Mapping[str, Dim]
    spec: Spec
    values: Mapping[sympy.Symbol, sympy.Expr]
    initial: Mapping[str, sympy.Expr]
    numeric: list[Step]
    earlier: dict[str, Target]
    numbers_first: bool = False  # numeric mode: a formula that is a number is not shown

    def lookup(self) -> dict[str, sympy.Expr]:
        """Every name a find may be evaluated at: givens, t_0/x_0/v_0 and earlier finds."""
        found: dict[str, sympy.Expr] = {f"{n}_0": e for n, e in self.initial.items()}
        found |= dict(self.symbols)
        found |= {n: t.expr for n, t in self.earlier.items() if t.expr is not None}
        return found

    def dims(self) -> dict[str, Dim]:
        found = {f"{n}_0": _DIMS[n] for n in self.initial}
        return found | dict(self.given_dims) | {n: t.dim for n, t in self.earlier.items()}

    def target(self, item: FindItem) -> Target:
        if item.ref is not None and item.ref.function in EVENTS:
            return _event_target(item, self)
        return _target(
            item,
            self.motion,
            self.lookup(),
            self.dims(),
            self.spec,
            (self.values, self.initial, self.numeric),
        )


def _with_defines(spec: Spec, context: _Context) -> tuple[Target, ...]:
    """The finds' targets with the define lines' derived quantities (a define listed in
    find takes its place there; the others follow), resolved by :mod:`dynsolve.derived`."""
    from dynsolve.derived import define_targets
    from dynsolve.spec.ast import QuantityRef

    found = tuple(context.earlier.values())
    if not spec.defines:
        return found

    def resolve(function: str, args: tuple[str, ...], where: Position) -> Target:
        ref = QuantityRef(function, args, where.line, where.column)
        name = f"{function}({', '.join(args)})"
        return context.target(FindItem(name, None, where.line, where.column, ref))

    lookup = context.lookup()
    names = (*context.given_dims, "t_0", "x_0", "v_0")
    defined = {
        t.name: replace(t, unit=natural_unit(t.dim, spec.system))
        for t in define_targets(spec, found, {n: lookup[n] for n in names}, context.dims(), resolve)
    }
    for target in found:
        if target.name in defined:
            raise SpecError(
                f"'{target.name}' is both a find and a defined quantity",
                Position(spec.file, 1, 1),
                hint="choose another name for the derived quantity",
            )
    ordered: list[Target] = []
    for item in spec.finds:
        if item.name in defined and item.ref is None:
            target = defined.pop(item.name)
            if item.unit is not None:
                _check_unit(item, target.dim, spec)
                target = replace(target, unit=item.unit.text, requested=True)
            ordered.append(target)
        else:
            ordered.append(context.earlier[item.name])
    return (*ordered, *defined.values())


def _check_unit(item: FindItem, dim: Dim, spec: Spec) -> None:
    if item.unit is not None and resolve_unit(item.unit, spec.file).dim != dim:
        raise SpecError(
            f"{item.name} is {dim.name}, not in {item.unit.text}",
            Position(spec.file, item.line, item.column),
            hint=f"use a unit of {dim.name}",
        )


def _check_usage(
    spec: Spec, givens: list[GivenInfo], symbols: Mapping[str, object], kind: str
) -> tuple[tuple[str, str], ...]:
    """A given never read by the relation, the finds or the define lines is named in a
    note (with a did-you-mean); one whose name is a near miss of an initial condition
    taken as 0 (``x0`` for ``x_0``) is an error. x(t) and v(t) laws carry their own
    start: a given x_0 (and v_0) is not read by them."""
    from dynsolve.usage import check_near_misses, unused_note

    statement = spec.kinematics[0]
    used = {n.text for side in (statement.lhs, statement.rhs) for n in iter_names(side)}
    used |= {arg for item in spec.finds if item.ref is not None for arg in item.ref.args}
    for line in spec.defines:
        used |= {n.text for n in iter_names(line.rhs)} | _call_args(line.rhs)
    read = {"a(t)": "txv", "a(v)": "txv", "a(x)": "txv", "x(t)": "t", "v(t)": "tx"}[kind]
    starts = {f"{n}_0" for n in read}
    defaulted = [n for n in sorted(starts) if n not in symbols]
    check_near_misses(givens, used | starts, defaulted, spec.file)
    return unused_note(givens, used | starts, starts)


START = {"x": "x_0", "v": "v_0", "y": "y_0", "v_x": "v_x0", "v_y": "v_y0"}
MOTION_WORDS = {
    "t": "the time the motion is a function of",
    "x": "the position x(t)",
    "y": "the position y(t)",
    "r": "the radial coordinate r(t)",
}


def check_motion_names(givens: Sequence[GivenInfo], reserved: Sequence[str], file: str) -> None:
    """Refuse a given named as one of the motion's own variables (``t``, ``x``, ``v``,
    ``a``, …): the motion would read the variable and ignore the given. A SpecError at
    the given, naming the collision and the fix (another name, and the quantity at it).

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  t = 2 s\\nkinematics:\\n  x = 3*t\\nfind: X = x(t)", "k.dyn")
    >>> try:
    ...     check_motion_names(givens_of(spec), ("t", "x", "v", "a"), "k.dyn")
    ... except SpecError as error:
    ...     print(error.position.line, error.message)
    2 a given cannot be named t: in kinematics t is the time the motion is a function of
    """
    for info in givens:
        if info.name not in reserved or info.given is None:
            continue
        name = info.name
        what = MOTION_WORDS.get(name, f"the motion's {name}(t)")
        if name == "t":
            fix = "name it t_1 (t_1 = …) and ask for x(t_1), v(t_1) …"
        else:
            fix = f"give it another name, e.g. {name}_1"
            fix += f" (its value at the start is {START[name]})" if name in START else ""
        raise SpecError(
            f"a given cannot be named {name}: in kinematics {name} is {what}",
            Position(file, info.given.line, info.given.column),
            hint=fix,
        )


def _call_args(expr: object) -> set[str]:
    """The names passed to quantity calls in a define line (``x(t_2)`` reads t_2)."""
    from dynsolve.spec.ast import Binary, Call, Name, Unary

    found: set[str] = set()
    stack = [expr]
    while stack:
        node = stack.pop()
        if isinstance(node, Call):
            found |= {a.text for a in node.args if isinstance(a, Name)}
            stack.extend(node.args)
        elif isinstance(node, Unary):
            stack.append(node.operand)
        elif isinstance(node, Binary):
            stack.extend((node.left, node.right))
    return found


def _mass_times_a(
    statement: EquationStmt, symbols: Mapping[str, sympy.Symbol]
) -> sympy.Expr | None:
    """m when the relation is Newton's law ``m*a = F(t, x or v)``; None for ``a = …``.

    >>> from dynsolve.spec.parser import parse_spec
    >>> text = "given:\\n  m = 2 kg\\n  c = 1 kg/s\\nkinematics:\\n  m*a = -c*v"
    >>> spec = parse_spec(text, "k.dyn")
    >>> _mass_times_a(spec.kinematics[0], {"m": sympy.Symbol("m"), "c": sympy.Symbol("c")})
    m
    """
    names = {n.text for n in iter_names(statement.lhs)}
    if "a" not in names or str(statement.lhs) == "a" or names - {"a"} - set(symbols):
        return None
    A = sympy.Symbol("a")
    mass = sympy.simplify(to_sympy(statement.lhs, {**symbols, "a": A}) / A)
    return None if mass.has(A) or mass == 0 else mass


def _kind(statement: EquationStmt, given: set[str], file: str, newton: bool = False) -> str:
    left = "a" if newton else statement.lhs
    names = {n.text for n in iter_names(statement.rhs)} - given - {"pi"}
    variables = names & set(VARIABLES)
    unknown = names - set(VARIABLES)
    where = Position(file, statement.line, statement.column)
    if unknown:
        first = sorted(unknown)[0]
        raise SpecError(
            f"'{first}' is neither a given nor t, x or v",
            where,
            hint=POSITION_HINT if first == "s" else "declare it under given:",
        )
    if len(variables) > 1:
        raise SpecError(
            f"the relation mixes {' and '.join(sorted(variables))}",
            where,
            hint="rectilinear motion takes a(t), a(v), a(x), x(t) or v(t)",
        )
    variable = next(iter(variables), "t")
    kind = f"{left}({variable})" if str(left) in ("a", "x", "v") else ""
    if kind not in KINDS:
        raise SpecError(
            f"'{left} = …' in {variable} is not a kinematic relation dynsolve integrates",
            where,
            hint=POSITION_HINT
            if str(left) == "s"
            else "give one of a = f(t), a = f(v), a = f(x), x = f(t) or v = f(t)",
        )
    return kind


# the position, written s in many textbooks
POSITION_HINT = "dynsolve names the position x: write 'x = …' (x_0, x(t), t_at(x, …))"
_DIMS = {"t": Dim.of("time"), "x": Dim.of("length"), "v": Dim.of("velocity"), "a": ACCELERATION}


def _target(
    item: FindItem,
    motion: Motion,
    symbols: Mapping[str, sympy.Expr],
    given_dims: Mapping[str, Dim],
    spec: Spec,
    numbers: tuple[Mapping[sympy.Symbol, sympy.Expr], Mapping[str, sympy.Expr], list[Step]]
    | None = None,
) -> Target:
    where = Position(spec.file, item.line, item.column)
    ref = item.ref
    if ref is None or len(ref.args) != 1 or ref.function not in _DIMS:
        raise SpecError(
            f"'{item.name}' is not a kinematic relation",
            where,
            hint="name one such as 'v_t = v(t)', 'x_v = x(v)' or 'v_1 = v(t_1)'",
        )
    argument = ref.args[0]
    variable = argument if argument in VARIABLES else _variable_of(argument, given_dims, where)
    name = f"{ref.function}({variable})"
    if name not in motion.formulas and ref.function == "t" and variable == "v":
        hint = f"the time at which v = {argument} is t_at(v, {argument})"
        raise SpecError(f"t(v) could not be found from {motion.given}", where, hint=hint)
    numeric = None
    if numbers is not None and argument not in VARIABLES:
        if variable == "t":  # at a time past an a(v) motion's stop: the stop's values
            numeric = _after_a_stop(ref.function, symbols[argument], motion, numbers)
        if numeric is None and name not in motion.formulas:
            try:
                numeric = _numerically(
                    ref.function, variable, symbols[argument], motion, numbers, spec.system
                )
            except MotionBlowsUp as blow_up:
                end = real_value(symbols[argument], numbers[0])
                raise SpecError(
                    f"{ref.function}(t) is not finite at t = {blow_up.time:.6g} s, before "
                    f"{argument} = {end:.6g} s: the motion blows up there (found by "
                    "integrating it)",
                    where,
                    hint="ask for a time before it, or check the law's sign and the initial "
                    "conditions",
                ) from None
    if numeric is not None:
        motion = replace(motion, formulas={**motion.formulas, name: numeric})
        argument = variable  # already evaluated at the given
    if name not in motion.formulas:
        found = ", ".join(motion.formulas)
        raise SpecError(
            f"{name} could not be found from {motion.given}", where, hint=f"found: {found}"
        )
    expr = motion.formulas[name]
    if argument not in VARIABLES:
        expr = expr.subs(VARIABLES[variable][0], symbols[argument])
    dim = _DIMS[ref.function]
    unit = item.unit.text if item.unit is not None else natural_unit(dim, spec.system)
    if item.unit is not None and resolve_unit(item.unit, spec.file).dim != dim:
        raise SpecError(
            f"{item.name} is {dim.name}, not in {item.unit.text}",
            where,
            hint=f"use a unit of {dim.name}",
        )
    return Target(
        item.name, sympy.Symbol(item.name), dim, unit, item.unit is not None, False, "signed", expr
    )


_EVENT_DIMS = {"t_at": "t", "x_at": "x", "distance": "x"}


def _event_target(item: FindItem, context: _Context) -> Target:
    """A find of an event of the motion (``t_at``, ``x_at``, ``max``, ``min``,
    ``distance``): its arguments resolved, the event found, and its step recorded."""
    from dynsolve.numbers import real_value

    assert item.ref is not None
    ref, spec = item.ref, context.spec
    where = Position(spec.file, ref.line, ref.column)
    args, function = ref.args, ref.function
    counts = {"t_at": (2, 3), "x_at": (2, 3), "max": (1, 2), "min": (1, 2), "distance": (1, 2)}
    usage = {
        "t_at": "t_s = t_at(v, 0), or t_at(x, x_1, 2) for the second time",
        "x_at": "x_s = x_at(v, 0), the position where v = 0",
        "max": "x_max = max(x), or max(x, t_2) over t₀ … t₂",
        "min": "v_min = min(v), or min(v, t_2) over t₀ … t₂",
        "distance": "s = distance(t_2) from t₀, or distance(t_1, t_2)",
    }[function]
    low, high = counts[function]
    if not low <= len(args) <= high:
        raise SpecError(f"{function} takes {low} or {high} arguments", where, hint=usage)
    resolved: list[object] = []
    if function == "distance":
        resolved = [_event_value(a, "t", context, where) for a in args]
    else:
        quantity = args[0]
        if quantity not in QUANTITIES:
            raise SpecError(
                f"'{quantity}' is not a quantity of one-line motion",
                where,
                hint="one of x, v, a (plane motion, with two relations, has y, v_x, …)",
            )
        resolved.append(quantity)
        if function in ("t_at", "x_at"):
            resolved.append(_event_value(args[1], quantity, context, where))
            if len(args) == 3:
                if not args[2].isdigit() or int(args[2]) < 1:
                    raise SpecError(
                        f"the root's number '{args[2]}' is not 1, 2, 3, …", where, hint=usage
                    )
                resolved.append(int(args[2]))
        elif len(args) == 2:
            resolved.append(_event_value(args[1], "t", context, where))
    t0, x0 = context.initial["t"], context.initial["x"]
    try:
        event = find_event(function, resolved, context.motion, t0, context.values, x0)
    except ValueError as error:
        raise SpecError(str(error), where, hint=usage) from None
    dim = _DIMS[_EVENT_DIMS.get(function, args[0])]
    _check_unit(item, dim, spec)
    unit = item.unit.text if item.unit is not None else natural_unit(dim, spec.system)

    def shown(expr: sympy.Expr, of: Dim = dim) -> str:
        """A value in the system's base units (those of the motion's numbers), with its unit."""
        number = real_value(expr, context.values)
        if number is None:
            return formula_text(expr)
        return f"{number:.6g} {pretty_unit(natural_unit(of, spec.system))}".rstrip()

    time = _DIMS["t"]
    discarded = tuple(f"t = {shown(t, time)}: {why}" for t, why in event.discarded)
    results = ()
    if event.time is not None and function not in ("t_at",):
        results += (Formula("t", formula_text(event.time), formula_latex(event.time),
                            shown(event.time, time), shown(event.time, time)),)  # fmt: skip
    text = formula_text(event.expr)
    latex = formula_latex(event.expr)
    if (context.numbers_first or event.expr.is_Float) and not event.expr.free_symbols:
        text = latex = ""  # the number itself: "t_a = 1", not "t_a = 1 = 1"
    results += (Formula(item.name, text, latex, shown(event.expr), shown(event.expr)),)
    method = "root choice" if function in ("t_at", "x_at") else "extreme"
    if function == "distance":
        method = "integration"
    rule = f"{item.name} = {function}({', '.join(args)}): {event.rule}"
    context.numeric.append(Step(0, (), (item.name,), method, results, discarded, rule))
    return Target(
        item.name,
        sympy.Symbol(item.name),
        dim,
        unit,
        item.unit is not None,
        False,
        "signed",
        event.expr,
    )


def _event_value(name: str, quantity: str, context: _Context, where: Position) -> sympy.Expr:
    """An event's value or time: 0, a given, t_0/x_0/v_0 or an earlier find, of the
    dimension of ``quantity``."""
    dim = _DIMS[quantity]
    if name[:1].isdigit() or name.startswith("."):
        if sympy.Rational(name) != 0:
            raise SpecError(
                f"the number {name} has no unit",
                where,
                hint="give the value as a given with its unit (0 may be written as is)",
            )
        return sympy.Integer(0)
    lookup, dims = context.lookup(), context.dims()
    if name not in lookup or name in VARIABLES:
        later = any(f.name == name for f in context.spec.finds)
        close = difflib.get_close_matches(name, [n for n in dims], n=1)
        hint = (
            f"list '{name}' before the find that uses it"
            if later
            else f"did you mean '{close[0]}'?"
            if close
            else "declare it under given:"
        )
        raise SpecError(f"'{name}' is neither a given nor an earlier find", where, hint=hint)
    if dims[name] != dim:
        raise SpecError(
            f"'{name}' is {dims[name].name}, but {quantity} is {dim.name}",
            where,
            hint=f"give a value of {dim.name}",
        )
    return lookup[name]


def _check_real(
    item: FindItem, target: Target, values: Mapping[sympy.Symbol, sympy.Expr], file: str
) -> None:
    """Fail loudly when a value found is not real: v(x₁) or t(x₁) past the turning point,
    where v² < 0 — the motion never gets there on this branch.

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("kinematics:\\n  x = 2*t\\nfind: v_1 = v(x_1)", "k.dyn")
    >>> target = Target("v_1", sympy.Symbol("v_1"), _DIMS["v"], "m/s", False, False, "signed",
    ...                 sympy.sqrt(-15))
    >>> _check_real(spec.finds[0], target, {}, "k.dyn")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    dynsolve.errors.SpecError: k.dyn:3:7: v_1 is not real ...
    """
    from dynsolve.numbers import real_value

    if target.expr is None:
        return
    value = target.expr.xreplace(dict(values))
    if value.has(sympy.zoo, sympy.oo, -sympy.oo, sympy.nan):
        return  # infinite: the blow-up and root checks speak to it
    if value.free_symbols or real_value(value) is not None:
        return
    raise SpecError(
        f"{target.name} is not real ({sympy.sstr(sympy.N(value, 4))}): the motion never "
        "reaches that value on this branch (past a turning point v² < 0)",
        Position(file, item.line, item.column),
        hint="check the value against the turning point: x_at(v, 0)",
    )


def _check_after_start(
    item: FindItem,
    target: Target,
    t_0: sympy.Expr,
    values: Mapping[sympy.Symbol, sympy.Expr],
    file: str,
) -> None:
    """Fail loudly when a time found (``t(x_1)``, ``t(v_1)``) comes before the start t₀:
    the motion never reaches that value after t₀ on the branch the relation follows.

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("kinematics:\\n  x = 2*t\\nfind: t_1 = t(x)", "k.dyn")
    >>> target = Target("t_1", sympy.Symbol("t_1"), _DIMS["t"], "s", False, False, "signed",
    ...                 sympy.Integer(-1))
    >>> _check_after_start(spec.finds[0], target, sympy.Integer(0), {}, "k.dyn")
    ... # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    dynsolve.errors.SpecError: k.dyn:3:7: t_1 = -1 s comes before the start t_0 = 0 s ...
    """
    from dynsolve.numbers import real_value

    if item.ref is None or item.ref.function != "t":
        return
    found, start = real_value(target.expr, values), real_value(t_0, values)
    if found is None or start is None or found >= start - 1e-12 * max(1.0, abs(start)):
        return
    raise SpecError(
        f"{target.name} = {found:.6g} s comes before the start t_0 = {start:.6g} s",
        Position(file, item.line, item.column),
        hint="the motion does not reach that value after t_0 on this branch: check the "
        "value's sign and the sense of v_0",
    )


def _check_no_blow_up(
    item: FindItem,
    motion: Motion,
    symbols: Mapping[str, sympy.Expr],
    t_0: sympy.Expr,
    values: Mapping[sympy.Symbol, sympy.Expr],
    file: str,
) -> None:
    """Fail loudly when x(t) or v(t) is not continuous from t₀ to a given time t₁: the motion
    blows up (or leaves its law's domain) before t₁, so a value "at t₁" would be the other
    branch of the formula, not this motion's.

    a = v² from v₀ = 1 m/s gives v = 1/(1 − t), infinite at t = 1 s; v(2 s) = −1 m/s is not
    a speed this particle ever has:

    >>> from dynsolve.spec.parser import parse_spec
    >>> from dynsolve.principles.rectilinear import integrate_motion
    >>> spec = parse_spec("kinematics:\\n  x = 2*t\\nfind: v_1 = v(t_1)", "k.dyn")
    >>> zero, one, t_1 = sympy.Integer(0), sympy.Integer(1), sympy.Symbol("t_1")
    >>> motion = integrate_motion(V**2, "a(v)", zero, zero, one)
    >>> try:
    ...     _check_no_blow_up(spec.finds[0], motion, {"t_1": t_1}, zero, {t_1: 2 * one}, "k.dyn")
    ... except SpecError as error:
    ...     print(error.message.split(":")[0])
    v(t) is not finite at t = 1 s, before t_1 = 2 s
    """
    from sympy.calculus.util import continuous_domain

    from dynsolve.numbers import real_value
    from dynsolve.solver.blocks import BudgetExceeded, time_budget

    ref = item.ref
    if ref is None or ref.function not in ("x", "v") or len(ref.args) != 1:
        return
    law = motion.formulas.get(f"{ref.function}(t)")
    at = symbols.get(ref.args[0])
    if law is None or at is None:
        return
    start, end = real_value(t_0, values), real_value(at, values)
    if (
        start is None
        or end is None
        or end <= start
        or law.xreplace(dict(values)).free_symbols - {T}
    ):
        return
    law = law.xreplace(dict(values))
    interval = sympy.Interval(sympy.nsimplify(start), sympy.nsimplify(end))
    try:
        with time_budget(2.0):
            domain = continuous_domain(law, T, interval)
    except (BudgetExceeded, NotImplementedError, ValueError, TypeError):
        return  # undecided: the substitution and root checks still apply
    if domain == interval:
        return
    gap = sympy.Complement(interval, domain)
    first = float(gap.inf) if gap.inf.is_finite else end
    raise SpecError(
        f"{ref.function}(t) is not finite at t = {first:.6g} s, before {ref.args[0]} = "
        f"{end:.6g} s: the motion blows up (or leaves its law's domain) there",
        Position(file, item.line, item.column),
        hint="ask for a time before it, or check the law's sign and the initial conditions",
    )


def _after_a_stop(
    function: str,
    at: sympy.Expr,
    motion: Motion,
    numbers: tuple[Mapping[sympy.Symbol, sympy.Expr], Mapping[str, sympy.Expr], list[Step]],
) -> sympy.Expr | None:
    """x or v at a time past the stop of an a(v) motion, or None when it has not stopped.

    Under an a(v) law v changes monotonically until it reaches a v_s where a(v_s) = 0; when
    t(v_s) is finite (a = −k√v from v₀ = 9 m/s stops at t = 2 s) the particle stays at v_s,
    x(t) = x(v_s) + v_s (t − t_s). The inverted v(t) = (3 − 1.5 t)² gives 2.25 m/s at 3 s,
    a speed of no motion, and a numerical integration steps into √(v < 0); the step says
    which stop was taken.

    >>> from dynsolve.principles.rectilinear import integrate_motion
    >>> k, v_0, t_3 = sympy.symbols("k v_0 t_3", positive=True)
    >>> zero = sympy.Integer(0)
    >>> motion = integrate_motion(-k * sympy.sqrt(V), "a(v)", zero, zero, v_0)
    >>> values = {k: sympy.Integer(3), v_0: sympy.Integer(9), t_3: sympy.Integer(3)}
    >>> numbers = (values, {"t": zero, "x": zero, "v": v_0}, [])
    >>> _after_a_stop("v", t_3, motion, numbers), _after_a_stop("x", t_3, motion, numbers)
    (0, 2*v_0**(3/2)/(3*k))
    """
    values, initial, steps = numbers
    formulas = motion.formulas
    if motion.given != "a(v)" or function not in ("x", "v") or "t(v)" not in formulas:
        return None
    a = formulas["a(v)"].xreplace(dict(values))
    t_law = formulas["t(v)"].xreplace(dict(values))
    t_q, t_0 = real_value(at, values), real_value(initial["t"], values)
    v_0 = real_value(initial["v"], values)
    if None in (t_q, t_0, v_0) or t_q <= t_0 or (a.free_symbols | t_law.free_symbols) - {V}:
        return None
    a_0 = real_value(a.subs(V, v_0))
    if not a_0 or t_law.has(sympy.Integral):
        return None  # at rest (or a rate sympy did not integrate): no stop to place
    try:
        roots = sympy.solve(a, V)
    except NotImplementedError:
        return None
    stops = []
    for v_s in roots:
        ahead = real_value(v_s)
        t_s = real_value(t_law.subs(V, v_s)) if ahead is not None else None
        reached = ahead is not None and (ahead - v_0) * a_0 > 0  # the way v changes
        if reached and t_s is not None and math.isfinite(t_s) and t_0 < t_s <= t_q:
            stops.append((t_s, v_s))
    if not stops:
        return None
    t_s, v_s = min(stops, key=lambda stop: stop[0])
    if function == "x" and "x(v)" not in formulas:
        return None
    value = (
        v_s
        if function == "v"
        else formulas["x(v)"].subs(V, v_s) + v_s * (at - formulas["t(v)"].subs(V, v_s))
    )
    value = sympy.Integer(0) + value
    how = (
        f"v reaches {v_s} at t = {t_s:.6g} s, where a = 0: the particle stays at that speed, "
        f"so {function}({at}) is the stop's (v(t) holds only until then)"
    )
    number = real_value(value, values)
    shown = f"{number:.6g}" if number is not None else formula_text(value)
    result = Formula(f"{function}({at})", formula_text(value), formula_latex(value), shown, shown)
    steps.append(Step(0, (), (f"{function}({at})",), "stop", (result,), (), how))
    return value


def _numerically(
    function: str,
    variable: str,
    at: sympy.Expr,
    motion: Motion,
    numbers: tuple[Mapping[sympy.Symbol, sympy.Expr], Mapping[str, sympy.Expr], list[Step]],
    system: System,
) -> sympy.Expr | None:
    """x or v at a given time by integrating the motion numerically, when sympy could not
    invert the relation that would give it as a formula; the step is recorded, its value
    with its unit in ``system`` (m/s, ft/s): a number, so no formula is shown."""
    from dynsolve.numbers import real_value
    from dynsolve.principles.rectilinear import integrate_numerically

    values, initial, steps = numbers
    if variable != "t" or function not in ("x", "v") or not motion.given.startswith("a("):
        return None
    a = motion.formulas[motion.given].xreplace(dict(values))
    start = [real_value(initial[n], values) for n in ("t", "x", "v")]
    t_1 = real_value(at, values)
    if None in start or t_1 is None or a.free_symbols - {T, X, V}:
        return None
    t_0, x_0, v_0 = start
    x, v = integrate_numerically(a, motion.given, t_0, x_0, v_0, t_1)  # type: ignore[arg-type]
    value = sympy.Float(x if function == "x" else v, 15)
    why = (
        f"sympy could not invert the relation into {function}(t)"
        if motion.inverted
        else "only values at given times are asked, so no relation is inverted into a formula"
    )
    how = (
        f"{function}({at}) by integrating x' = v, v' = {motion.given} numerically from t₀ "
        f"(mpmath ODE solver): {why}"
    )
    unit = natural_unit(_DIMS[function], system)
    shown = f"{float(value):.6g}"
    result = Formula(
        f"{function}({at})", "", "", f"{shown} {pretty_unit(unit)}", f"{shown}\\,{latex_unit(unit)}"
    )
    steps.append(Step(0, (), (f"{function}({at})",), "numeric", (result,), (), how))
    return value


def _variable_of(given: str, given_dims: Mapping[str, Dim], where: Position) -> str:
    """Which of t, x, v a given stands for (by its dimension): ``v(t_1)`` evaluates at t_1."""
    dim_of_given = given_dims.get(given)
    if dim_of_given is None:
        raise SpecError(
            f"'{given}' is neither t, x, v nor a given",
            where,
            hint="evaluate at a given or an earlier find, e.g. v(t_1) with t_1 = 2 s",
        )
    for name, (_, dim) in VARIABLES.items():
        if dim == dim_of_given:
            return name
    raise SpecError(
        f"'{given}' is {dim_of_given.name}: not a time, position or speed",
        where,
        hint="evaluate at a time, a position or a speed",
    )


def relation_row(statement: EquationStmt, dim: Dim, spec: Spec, note: str = "") -> EquationRow:
    """A kinematic relation as an equation row: as written, with its checked dimension
    (``note``, when given, stands for a missing trailing comment).

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  k = 2 1/s\\nkinematics:\\n  a = -k*v  # drag", "k.dyn")
    >>> row = relation_row(spec.kinematics[0], ACCELERATION, spec)
    >>> row.text, row.dimension, row.note
    ('a = -k*v', 'acceleration [m/s²]', 'drag')
    """
    from dynsolve.format import pretty_unit
    from dynsolve.spec.printing import statement_latex, statement_text

    unit = natural_unit(dim, spec.system) or "1"
    return EquationRow(
        statement.line,
        statement_text(statement),
        statement_latex(statement),
        statement.note or note,
        f"{dim.name} [{pretty_unit(unit)}]",
        True,
        False,
    )


def _steps(
    motion: Motion,
    values: Mapping[sympy.Symbol, sympy.Expr],
    symbols: Mapping[str, sympy.Symbol],
    numbers_first: bool = False,
) -> tuple[Step, ...]:
    pretty_names = {s: sympy.Symbol(pretty(n)) for n, s in symbols.items()}
    latex_names = {s: latex_name(n) for n, s in symbols.items()}
    steps = []
    for index, (name, how) in enumerate(motion.steps, start=1):
        formula = motion.formulas[name]
        text = formula_text(formula, pretty_names)
        latex = formula_latex(formula, latex_names)
        with_numbers = formula.xreplace(dict(values))
        if numbers_first and with_numbers == formula:  # the numbers are in already
            result = Formula(name, "", "", text, latex)
        else:
            rounded = sympy.N(with_numbers, 4)
            shown = formula_text(rounded)
            result = Formula(name, text, latex, shown, formula_latex(rounded))
        steps.append(
            Step(index, (), (name,), "integration" if "∫" in how else "algebra", (result,), (), how)
        )
    return tuple(steps)
