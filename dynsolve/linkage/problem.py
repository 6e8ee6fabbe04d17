"""Turn a linkage scene into a problem: positions, relative-motion equations and targets.

The joints are placed (:mod:`~dynsolve.linkage.position`); each placed coordinate that
is not a plain number or a given becomes a derived quantity (``x_C``, ``y_C``) shown
with its value, so the equations read as the textbook's ``v_C = v_B + ω_BC × r_C/B``
with ``r_C/B = (x_C − x_B, y_C − y_B)``. Only the levels the find list needs are
written (no acceleration equations for a velocity question). ``find`` takes
``omega(BAR)``, ``alpha(BAR)``, ``v(P)``, ``a(P)`` (a slider's along its guide, signed
with a direction word; any other joint's magnitude with its direction), the components
``v_x(P)``, ``v_y(P)``, ``a_x(P)``, ``a_y(P)``, and ``theta(BAR)`` (the bar's direction
from its first point to its second, from +x, ccw).

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   L = 0.2 m
...   theta = 45 deg
...   v_A = 2 m/s
... scene:
...   point O: (0, 0)
...   bar AB: A to B, length L
...   joint A: (0, L*sin(theta))
...   joint B: (L*cos(theta), 0)
...   slider A: along up, through O
...   slider B: along right, through O
...   velocity A: v_A, down
... find: v_B = v(B), w = omega(AB)
... ''', "blocks.dyn")
>>> problem = build_linkage_problem(spec)
>>> [str(e.lhs - e.rhs) for e in problem.system.equations]
['-omega_AB*y_A + v_B', '-omega_AB*x_B + v_A']
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace

import sympy

from dynsolve.dimensions import DimensionReport
from dynsolve.errors import DimensionError, Position, SpecError
from dynsolve.format import quantity as format_quantity
from dynsolve.linkage.kinetics import FreeBodies, free_bodies, has_kinetics, power_balance
from dynsolve.linkage.model import LENGTH, Linkage, read_linkage
from dynsolve.linkage.position import Placement, place
from dynsolve.linkage.relations import TOGGLE, Level, condition, in_line, relative_motion
from dynsolve.model.scene import Vec
from dynsolve.modes.equation_mode import GivenInfo, Target, check_answers_in_find, givens_of
from dynsolve.modes.scene_mode import _row, _unit, _unused
from dynsolve.quantities import convert
from dynsolve.results import Check, EquationRow, LinkageFigure, Step
from dynsolve.spec.ast import FindItem, Spec
from dynsolve.system import EquationSystem
from dynsolve.units import Dim, natural_unit, with_unit

FUNCTIONS = (
    "force",
    "x_IC",
    "y_IC",
    "omega",
    "alpha",
    "v",
    "a",
    "v_x",
    "v_y",
    "a_x",
    "a_y",
    "theta",
    "v_rel",
    "a_rel",
)
ACCELERATIONS = ("alpha", "a", "a_x", "a_y", "a_rel")


@dataclass(frozen=True)
class LinkageProblem:
    """A linkage ready to solve, shaped as the pipeline expects (``SolvableProblem``)."""

    spec: Spec
    givens: tuple[GivenInfo, ...]
    system: EquationSystem
    dims: DimensionReport
    targets: tuple[Target, ...]
    symbols: Mapping[str, sympy.Symbol]
    rows: tuple[EquationRow, ...]
    linkage: Linkage
    placement: Placement
    steps: tuple[Step, ...] = ()
    notes: tuple[tuple[str, str], ...] = ()
    mode: str = "linkage"
    levels: Mapping[str, Level] = field(default_factory=dict)
    r: Mapping[str, Vec] = field(default_factory=dict)
    free: FreeBodies | None = None
    released: tuple[str, ...] = ()  # bars whose α the loads decide (omega given, no alpha)
    reversed_teeth: frozenset[str] = frozenset()  # tooth forces taken negative (pressure angle)
    translating: tuple[str, ...] = ()  # bars whose IC is at infinity at the instant (method ic)


def build_linkage_problem(
    spec: Spec, reversed_teeth: frozenset[str] = frozenset()
) -> LinkageProblem:
    """Read, place and relate the linkage of ``spec``; resolve its find list.
    ``reversed_teeth``: the tooth forces (``F_A_B``) whose radial push (a pressure angle)
    is written for F < 0, after a first solve found them so (:func:`reversed_teeth`)."""
    where = Position(spec.file, 1, 1)
    if not spec.finds:
        raise SpecError("nothing to find", where, hint="add a 'find:' line")
    if spec.equations or spec.defines:
        line = (spec.equations or spec.defines)[0]
        raise SpecError(
            "equations and define lines cannot be combined with a linkage yet",
            Position(spec.file, line.line, line.column),
            hint="ask for the linkage's own quantities (omega(BC), v(C), …)",
        )
    linkage = read_linkage(spec)
    placement = place(linkage)
    givens = list(givens_of(spec))
    taken = {g.name for g in givens}
    linkage, drives = _named_drives(linkage, taken)
    givens += drives
    taken |= {g.name for g in drives}
    r, derived = _coordinates(linkage, placement, taken, spec)
    givens += derived
    placed = {g.symbol: g.value for g in derived if g.value is not None}
    slots, directions = _slot_directions(linkage, r, taken, placed)
    givens += directions
    asked = {item.ref.function if item.ref else item.name for item in spec.finds}
    translating: tuple[str, ...] = ()
    if linkage.method == "ic":  # velocities by instantaneous centres (Hibbeler 16.6)
        from dynsolve.linkage.centres import by_centres

        placed = {g.symbol: g.value for g in givens if g.value is not None}
        velocity, centres = by_centres(linkage, r, placed)
        named = set().union(*(g.formula.free_symbols for g in centres if g.formula is not None))
        givens = [replace(g, shown=True) if g.symbol in named else g for g in givens]
        givens += centres
        taken |= {g.name for g in centres}
        translating = tuple(g.name.removeprefix("omega_") for g in centres if g.dim != LENGTH)
        levels = {"velocity": velocity}
    else:
        levels = {"velocity": relative_motion(linkage, r, "velocity", slots=slots)}
    kinetics = has_kinetics(linkage)
    released: tuple[str, ...] = ()
    if asked & set(ACCELERATIONS) or kinetics:
        released = _needs_acceleration_drives(linkage, kinetics)
        velocity = levels["velocity"]
        levels["acceleration"] = relative_motion(
            linkage, r, "acceleration", velocity.rotation, slots, velocity.relative,
            len(released),
        )  # fmt: skip
    unknowns: dict[sympy.Symbol, Dim] = {}
    for level in levels.values():
        unknowns |= dict(level.unknowns)
    free = None
    if kinetics:
        g = next(g.symbol for g in givens if g.name == "g")
        motion = (levels["velocity"], levels["acceleration"])
        free = free_bodies(linkage, r, *motion, g, taken, len(released), reversed_teeth)
        unknowns |= dict(free.unknowns)
    clash = sorted({s.name for s in unknowns} & taken)
    if clash:
        raise SpecError(
            f"the given '{clash[0]}' has the name of an unknown of the linkage",
            where,
            hint="rename the given (dynsolve names the unknowns omega_BAR, v_Px, …)",
        )
    knowns = {g.symbol: g.value for g in givens if g.value is not None}
    notes = _placement_notes(linkage, placement, spec)
    notes += _toggle_notes(linkage, levels["velocity"], r, knowns)
    symbols = {g.name: g.symbol for g in givens} | {s.name: s for s in unknowns}
    dims = {g.name: g.dim for g in givens} | {s.name: d for s, d in unknowns.items()}
    for item in spec.finds:
        centre = item.ref and item.ref.function in ("x_IC", "y_IC") and item.ref.args
        if centre and item.ref.args[0] in translating:  # type: ignore[union-attr]
            raise SpecError(
                f"{item.ref.args[0]} translates at the instant: its instantaneous centre is at "
                "infinity",
                Position(spec.file, item.line, item.column),
                hint=f"ask for omega({item.ref.args[0]}) (zero) or the velocity of one of its "
                "points (they are all the same)",
            )
    targets = tuple(
        _target(item, spec, linkage, levels, r, dims, slots, free) for item in spec.finds
    )
    check_answers_in_find(spec)
    wanted: list[sympy.Symbol] = []
    for target in targets:
        for expr in (target.expr, *(target.vector or ())):
            if expr is None:
                continue
            wanted += [
                s
                for s in sorted((sympy.Integer(0) + expr).free_symbols, key=str)
                if s in unknowns and s not in wanted
            ]
    if free is not None:  # the power check needs every velocity
        wanted += [s for s in levels["velocity"].unknowns if s not in wanted]
    equations = tuple(e for level in levels.values() for e in level.equations)
    equations += free.equations if free is not None else ()
    system = EquationSystem(
        equations=equations, unknowns=tuple(unknowns), knowns=knowns, wanted=tuple(wanted)
    )
    symbol_dims = {symbols[n]: d for n, d in dims.items() if n in symbols}
    try:
        rows = tuple(_row(e, symbol_dims, spec) for e in equations)
    except DimensionError as error:
        raise DimensionError(error.message, where, error.hint) from None
    return LinkageProblem(
        spec,
        tuple(givens),
        system,
        DimensionReport(dims, (), frozenset()),
        targets,
        symbols,
        rows,
        linkage,
        placement,
        notes=notes + _unused(spec),
        levels=levels,
        r=r,
        free=free,
        released=released,
        reversed_teeth=reversed_teeth,
        translating=translating,
    )


def _coordinates(
    linkage: Linkage, placement: Placement, taken: set[str], spec: Spec
) -> tuple[dict[str, Vec], list[GivenInfo]]:
    """Each joint's position for the equations: a number or a given as it is, any other
    coordinate as a derived quantity ``x_P``/``y_P`` with its formula and value."""
    r: dict[str, Vec] = {}
    derived: list[GivenInfo] = []
    for point in linkage.joints:
        position = placement.positions[point]
        coordinates = []
        for axis, value in zip("xy", position, strict=True):
            if isinstance(value, sympy.Float) and value.is_zero:  # on a guide through 0
                value = sympy.Integer(0)
            plain = value.is_Number and not isinstance(value, sympy.Float)
            if plain or (value.is_Symbol and value.name in taken):
                coordinates.append(value)
                continue
            name = f"{axis}_{point}"
            if name in taken:
                raise SpecError(
                    f"the given '{name}' has the name of joint {point}'s coordinate",
                    linkage.where(point),
                    hint="rename the given",
                )
            symbol = sympy.Symbol(name, real=True)
            how = placement.how.get(point, "fixed point")
            shown = sympy.Float(value, 6) if isinstance(value, sympy.Float) else value
            derived.append(
                GivenInfo(
                    name,
                    symbol,
                    value.xreplace(dict(linkage.values)) if linkage.values else value,
                    LENGTH,
                    None,
                    f"{axis} of {point} ({how})",
                    shown,
                )
            )
            coordinates.append(symbol)
        r[point] = (coordinates[0], coordinates[1])
    return r, derived


def _slot_directions(
    linkage: Linkage,
    r: Mapping[str, Vec],
    taken: set[str],
    placed: Mapping[sympy.Symbol, sympy.Expr],
) -> tuple[dict[str, Vec], list[GivenInfo]]:
    """The direction of each bar a joint slides along, as (cos θ, sin θ) of the bar's
    angle ``theta_BAR`` (a derived quantity, from its first point to its second)."""
    slots: dict[str, Vec] = {}
    derived: list[GivenInfo] = []
    for slider in linkage.sliders.values():
        if not slider.bar or slider.bar in slots:
            continue
        first, second = linkage.bars[slider.bar].points[:2]
        dx, dy = r[second][0] - r[first][0], r[second][1] - r[first][1]
        angle = sympy.atan2(dy, dx)
        name = f"theta_{slider.bar}"
        if name in taken:
            length = sympy.sqrt(dx**2 + dy**2)
            slots[slider.bar] = (dx / length, dy / length)
            continue
        symbol = sympy.Symbol(name, real=True)
        value = angle.xreplace(dict(placed)).xreplace(dict(linkage.values))
        derived.append(
            GivenInfo(
                name, symbol, value, Dim(), None, f"direction of {slider.bar} (from +x)", angle
            )
        )
        slots[slider.bar] = (sympy.cos(symbol), sympy.sin(symbol))
    return slots, derived


def _named_drives(linkage: Linkage, taken: set[str]) -> tuple[Linkage, list[GivenInfo]]:
    """Each driven bar's ω and α under its own name (``omega_AB = -n``: cw), so the
    equations read as the textbook writes them."""
    named: list[GivenInfo] = []
    drives = []
    for drive in linkage.drives:
        name = f"{drive.kind}_{drive.name}"
        if drive.kind not in ("omega", "alpha") or name in taken or drive.value.is_Symbol:
            drives.append(drive)
            continue
        symbol = sympy.Symbol(name, real=True)
        dim = Dim(0, 0, -1) if drive.kind == "omega" else Dim(0, 0, -2)
        value = drive.value.xreplace(dict(linkage.values)) if linkage.values else drive.value
        what = "ω" if drive.kind == "omega" else "α"
        named.append(
            GivenInfo(
                name,
                symbol,
                value,
                dim,
                None,
                f"{what} of {drive.name} (given; ccw +)",
                drive.value,
            )
        )
        drives.append(replace(drive, value=symbol))
    return replace(linkage, drives=tuple(drives)), named


def _needs_acceleration_drives(linkage: Linkage, kinetics: bool) -> tuple[str, ...]:
    """Accelerations asked: each velocity drive needs its acceleration (α of a driven
    bar, a of a driven joint), stated even when zero; with masses or loads, a bar whose
    ``omega`` is given without its ``alpha`` is *released*: its α is what the loads
    make it (Newton–Euler decides it). The released bars, in order."""
    pairs = {"omega": "alpha", "velocity": "acceleration"}
    released = []
    for drive in linkage.drives:
        if drive.kind in pairs and linkage.drive(pairs[drive.kind], drive.name) is None:
            if kinetics and drive.kind == "omega":
                released.append(drive.name)
                continue
            example = (
                f"'alpha {drive.name}: 0' if its ω is constant"
                if drive.kind == "omega"
                else f"'acceleration {drive.name}: 0, right' if its speed is constant"
            )
            raise SpecError(
                f"accelerations are asked, but the drive of {drive.name} gives only its "
                f"{drive.kind}",
                Position(linkage.file, drive.line, drive.column),
                hint=f"add {example}",
            )
    return tuple(released)


def _placement_notes(
    linkage: Linkage, placement: Placement, spec: Spec
) -> tuple[tuple[str, str], ...]:
    """How the joints were placed, and the assemblies not taken."""
    if not placement.closure:
        return ()
    unit = natural_unit(LENGTH, spec.system)
    found = [p for p, how in placement.how.items() if how == "loop closure"]

    def at(point: str, xy: tuple[float, float]) -> str:
        x, y = (format_quantity(convert(c, unit, spec.system), "") for c in xy)
        return f"{point} = ({x}, {y}) {unit}"

    numbers = {p: tuple(float(c) for c in placement.positions[p]) for p in found}
    detail = (
        f"{', '.join(placement.closure)} solved for {', '.join(found)}: "
        + ", ".join(at(p, numbers[p]) for p in found)  # type: ignore[arg-type]
        + f", {placement.rule}"
    )
    if placement.others:
        detail += "; other assembl" + ("ies" if len(placement.others) > 1 else "y") + ": "
        detail += "; ".join(", ".join(at(p, xy) for p, xy in o.items()) for o in placement.others)
    return (("loop closure", detail),)


def _toggle_notes(
    linkage: Linkage, level: Level, r: Mapping[str, Vec], knowns: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[tuple[str, str], ...]:
    """The velocity equations' condition number; at a toggle position, an error."""
    lengths = []
    for bar in linkage.bars.values():
        for point in bar.points[1:]:
            dx = (r[point][0] - r[bar.points[0]][0]).xreplace(dict(knowns))
            dy = (r[point][1] - r[bar.points[0]][1]).xreplace(dict(knowns))
            try:
                lengths.append(float(sympy.N(sympy.sqrt(dx**2 + dy**2), 15)))
            except TypeError:
                return ()
    number = condition(level, knowns, max(lengths, default=1.0))
    if number is None:
        return ()
    if number > TOGGLE:
        lines = in_line(linkage, r, knowns)
        first = lines[0].split()[0] if lines else next(iter(linkage.bars))
        raise SpecError(
            "the linkage is at a toggle (dead-centre) position"
            + (f": {'; '.join(lines)}" if lines else "")
            + f", so its velocity equations are singular (condition number {number:.3g}) "
            "and the bars' angular velocities are not determined here",
            linkage.where(first),
            hint="a different input angle (even slightly) or a different drive gives an "
            "answer; at the toggle itself the driven bar cannot drive the output",
        )
    detail = f"condition number {number:.3g} of the velocity equations"
    if number > 1e3:
        detail += " (large: near a toggle position, where small errors in the givens grow)"
    return (("conditioning", detail),)


def _target(
    item: FindItem,
    spec: Spec,
    linkage: Linkage,
    levels: Mapping[str, Level],
    r: Mapping[str, Vec],
    dims: Mapping[str, Dim],
    slots: Mapping[str, Vec],
    free: FreeBodies | None,
) -> Target:
    where = Position(spec.file, item.line, item.column)
    alias = item.ref.function if item.ref is not None and not item.ref.args else item.name
    if item.ref is None or alias != item.name:  # a name, or another name for it (F = F_W)
        forces = {s.name: s for s in free.unknowns} if free is not None else {}
        if alias in forces:
            unit, dim = _unit(item, dims[alias], spec, where)
            symbol = forces[alias]
            requested = item.unit is not None
            if free is not None and alias in free.normals:  # a guide's push, in words
                normal = free.normals[alias]
                return Target(
                    item.name, symbol, dim, unit, requested, False, "along", symbol, axis=normal
                )
            return Target(item.name, symbol, dim, unit, requested, False, "signed", symbol)
        motion = {s.name: s for level in levels.values() for s in level.unknowns}
        if alias in motion:  # an unknown by its own name: omega_BC, v_Cx, …
            unit, dim = _unit(item, dims[alias], spec, where)
            requested = item.unit is not None
            return Target(
                item.name, motion[alias], dim, unit, requested, False, "signed", motion[alias]
            )
        if alias == item.name and item.name in dims:  # a given, asked back
            unit, dim = _unit(item, dims[item.name], spec, where)
            symbol = sympy.Symbol(item.name)
            return Target(item.name, symbol, dim, unit, item.unit is not None, True)
        raise SpecError(
            f"'{item.name}' is not a quantity of the linkage",
            where,
            hint="ask for omega(BAR), alpha(BAR), v(P), a(P), v_x(P), …, theta(BAR), "
            "e.g. 'w_BC = omega(BC)'",
        )
    function, args = item.ref.function, item.ref.args
    if function not in FUNCTIONS or len(args) != 1:
        close = difflib.get_close_matches(function, FUNCTIONS, n=1)
        raise SpecError(
            f"'{function}({', '.join(args)})' is not a linkage quantity",
            where,
            hint=f"did you mean '{close[0]}(…)'?"
            if close
            else "ask for omega(BAR), alpha(BAR), v(P), a(P), v_x(P), v_y(P), a_x(P), "
            "a_y(P) or theta(BAR)",
        )
    name = args[0]
    level = levels["acceleration" if function in ACCELERATIONS else "velocity"]
    symbol = sympy.Symbol(item.name)

    def target(kind: str, dim: Dim, expr: sympy.Expr | None = None, **extra: object) -> Target:
        unit, dim = _unit(item, dim, spec, where)
        if kind == "angle":
            unit = "deg" if item.unit is None else unit
            kind = "signed"
        return Target(
            item.name, symbol, dim, unit, item.unit is not None, False, kind, expr, **extra
        )  # type: ignore[arg-type]

    if function in ("v_rel", "a_rel"):
        slider = linkage.sliders.get(name)
        if slider is None or not slider.bar:
            raise SpecError(
                f"{function}({name}) is the rate of a joint sliding along a bar, and {name} "
                "does not",
                where,
                hint="declare it with 'slider P: along bar BAR'",
            )
        dim = Dim.of("velocity") if function == "v_rel" else Dim.of("acceleration")
        return target("along", dim, level.relative[name], axis=slots[slider.bar])
    if function == "force":
        if free is None or name not in free.at_joint:
            raise SpecError(
                f"force({name}) is the force at a pin of a loaded linkage, and {name} is not one",
                where,
                hint="force(P) needs a pin P joining bars (or a bar to the ground) in a "
                "linkage with masses or loads",
            )
        return target("vector", Dim.of("force"), vector=free.at_joint[name])
    if function in ("x_IC", "y_IC"):
        if name not in linkage.bars:
            close = difflib.get_close_matches(name, sorted(linkage.bars), n=1)
            hint = f"did you mean '{close[0]}'?" if close else "name a bar"
            raise SpecError(f"there is no bar '{name}'", where, hint)
        first = linkage.bars[name].points[0]
        w, v = level.rotation[name], level.rate[first]
        if function == "x_IC":  # r_IC = r_P + (k × v_P)/ω
            return target("signed", LENGTH, r[first][0] - v[1] / w)
        return target("signed", LENGTH, r[first][1] + v[0] / w)
    if function in ("omega", "alpha", "theta"):
        if name not in linkage.bars:
            close = difflib.get_close_matches(name, sorted(linkage.bars), n=1)
            raise SpecError(
                f"there is no bar '{name}'",
                where,
                hint=f"did you mean '{close[0]}'?" if close else "name a bar",
            )
        if function == "theta":
            first, second = linkage.bars[name].points[:2]
            dx, dy = r[second][0] - r[first][0], r[second][1] - r[first][1]
            return target("angle", Dim(), sympy.atan2(dy, dx))
        dim = Dim(0, 0, -1) if function == "omega" else Dim(0, 0, -2)
        return target("rotation", dim, level.rotation[name])
    if name not in level.rate:
        close = difflib.get_close_matches(name, sorted(level.rate), n=1)
        raise SpecError(
            f"there is no joint '{name}'",
            where,
            hint=f"did you mean '{close[0]}'?" if close else "name a point of a bar",
        )
    dim = Dim.of("velocity") if function.startswith("v") else Dim.of("acceleration")
    vector = level.rate[name]
    if function in ("v_x", "a_x", "v_y", "a_y"):
        return target("signed", dim, vector[0 if function.endswith("x") else 1])
    slider = linkage.sliders.get(name)
    if slider is not None and slider.axis is not None:
        return target("along", dim, level.along[name], axis=slider.axis)
    if name in linkage.fixed:
        return target("magnitude", dim, sympy.Integer(0))
    return target("vector", dim, vector=vector)


def cross_checks(
    problem: LinkageProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """Checks of a solved linkage by a second method: each asked instantaneous centre
    (every point's speed is ω times its distance from it), and for a loaded linkage the
    power equation (the loads' power equals the rate of change of the kinetic energy),
    in which no pin or guide force appears; where every bar's α is left to the loads
    (a chain released), each α against Lagrange's equations of the open chain."""
    return (
        _centre_checks(problem, values)
        + _relative_velocity_check(problem, values)
        + _power_check(problem, values)
        + _lagrange_check(problem, values)
        + _pressure_checks(problem, values)
        + _load_senses(problem, values)
    )


def _load_senses(
    problem: LinkageProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """Each couple or force of unknown size acts in the sense the scene states: a size
    that comes out negative is the load acting the other way, a failed check that says
    which way (never an answer with its sign silently against its words)."""
    known = {**problem.system.knowns, **values}
    unknowns = {s.name: s for s in problem.system.unknowns}
    checks = []
    for load in problem.linkage.loads:
        symbol = unknowns.get(load.name)
        size = known.get(symbol) if symbol is not None else None
        if size is None or not getattr(size, "is_number", False):
            continue
        number = float(size)
        if load.kind == "couple":
            stated, other = ("ccw", "cw") if load.sense > 0 else ("cw", "ccw")
        else:
            stated, other = "as stated", "the other way"
        holds = number >= -1e-9 * max(1.0, abs(number))
        size = with_unit(
            number, "moment" if load.kind == "couple" else "force", problem.spec.system
        )
        detail = f"{load.name} = {size} ≥ 0: {stated}, as stated"
        if not holds:
            detail = (
                f"{load.name} = {size} against its stated sense ({stated}): it acts "
                f"{other}; state it so in the scene ('{load.kind} {load.name} on {load.bar}: "
                f"{other}')"
                if load.kind == "couple"
                else f"{load.name} = {size} against its stated direction: it acts the "
                "other way; state its direction reversed in the scene"
            )
        checks.append(Check(f"sense of {load.kind} {load.name}", holds, detail))
    return tuple(checks)


def _tooth_values(
    problem: LinkageProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> dict[str, float | None]:
    """Each tooth force with a pressure angle, as solved (None where not a number)."""
    known = {**problem.system.knowns, **values}
    found: dict[str, float | None] = {}
    for mesh in problem.linkage.meshes:
        if mesh.pressure is None:
            continue
        value = _full(sympy.Symbol(mesh.tooth, real=True), known)
        found[mesh.tooth] = None if value.free_symbols else float(sympy.N(value, 20))
    return found


def reversed_teeth(
    problem: LinkageProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> frozenset[str]:
    """The tooth forces whose solved sign contradicts the sense their radial push
    |F| tan φ was written with: the linkage is to be rebuilt with them reversed.

    The radial push always parts the gears, so it is |F| tan φ, written as ±F tan φ with
    a sense assumed (F ≥ 0 first); a solve that gives the other sign is redone."""
    flipped = set(problem.reversed_teeth)
    for name, value in _tooth_values(problem, values).items():
        sense = -1 if name in problem.reversed_teeth else 1
        if value is not None and sense * value < 0:
            flipped ^= {name}
    return frozenset(flipped)


def _force(problem: LinkageProblem, value: float) -> str:
    """A force in base units, shown in the problem's unit system."""
    unit = natural_unit(Dim.of("force"), problem.spec.system)
    return format_quantity(convert(value, unit, problem.spec.system), unit)


def _pressure_checks(
    problem: LinkageProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """The sense each tooth force's radial push was written with, against its answer."""
    checks = []
    for name, value in _tooth_values(problem, values).items():
        sense = -1 if name in problem.reversed_teeth else 1
        mesh = next(m for m in problem.linkage.meshes if m.tooth == name)
        assert mesh.pressure is not None
        taken = "F < 0" if sense < 0 else "F ≥ 0"
        if value is None:
            detail = (
                f"the radial push |F| tan φ parting the gears is written for {taken} "
                "(assumed: F has no value to check it with)"
            )
            checks.append(Check.not_run(f"pressure angle ({name})", detail))
            continue
        phi = float(sympy.N(_full(mesh.pressure, dict(problem.system.knowns)), 20))
        again = " (re-solved: the first solve found F the other way)" if sense < 0 else ""
        detail = (
            f"the teeth push along the line of action at φ = {math.degrees(phi):.4g}°: "
            f"{name} = {_force(problem, value)} along the common tangent, radial push "
            f"|F| tan φ = {_force(problem, abs(value) * math.tan(phi))} parting the gears, "
            f"written for {taken}{again}"
        )
        checks.append(Check(f"pressure angle ({name})", sense * value >= 0, detail))
    return tuple(checks)


def _relative_velocity_check(
    problem: LinkageProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """Velocities found by instantaneous centres, put into the relative-velocity equations
    v_B = v_A + ω × r_B/A of every bar (the default method): each must hold."""
    if problem.linkage.method != "ic":
        return ()
    level = problem.levels["velocity"]
    relative = relative_motion(problem.linkage, problem.r, "velocity")
    rates = {}
    for point, (x, y) in relative.rate.items():
        for symbol, expr in zip((x, y), level.rate[point], strict=True):
            if isinstance(symbol, sympy.Symbol) and symbol in relative.unknowns:
                rates[symbol] = expr
    known = {**problem.system.knowns, **values}
    worst, scale = 0.0, 0.0
    for equation in relative.equations:
        sides = [_full(side.xreplace(rates), known) for side in (equation.lhs, equation.rhs)]
        try:
            lhs, rhs = (float(sympy.N(side, 20)) for side in sides)
        except TypeError:
            return ()
        worst, scale = max(worst, abs(lhs - rhs)), max(scale, abs(lhs), abs(rhs))
    relative_error = worst / scale if scale else worst
    detail = (
        f"the velocities by instantaneous centres put into v_B = v_A + ω × r_B/A of every bar "
        f"({len(relative.equations)} equations): largest relative difference {relative_error:.1e}"
    )
    return (Check("relative velocity", relative_error < 1e-9, detail),)


def _centre_checks(
    problem: LinkageProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """The instantaneous centre of each bar asked for (x_IC, y_IC): where it is, and each
    of the bar's points moving at |ω| times its distance from it, perpendicular to it."""
    known = {**problem.system.knowns, **values}
    asked = {
        item.ref.args[0]
        for item in problem.spec.finds
        if item.ref and item.ref.function in ("x_IC", "y_IC")
    }
    level = problem.levels["velocity"]
    unit = natural_unit(LENGTH, problem.spec.system)
    checks = []
    for name in sorted(asked):
        bar = problem.linkage.bars[name]
        numbers = {}
        for point in bar.points:
            exprs = (*problem.r[point], *level.rate[point])
            try:
                numbers[point] = [float(sympy.N(_full(e, known), 20)) for e in exprs]
            except TypeError:
                return ()
        try:
            w = float(sympy.N(_full(level.rotation[name], known), 20))
        except TypeError:
            return ()
        if w == 0:
            checks.append(
                Check(
                    f"instantaneous centre of {name}", True, f"{name} translates (ω = 0): no centre"
                )
            )
            continue
        x, y, vx, vy = numbers[bar.points[0]]
        centre = (x - vy / w, y + vx / w)
        parts, worst = [], 0.0
        for point, (px, py, ux, uy) in numbers.items():
            dx, dy = px - centre[0], py - centre[1]
            predicted = (-w * dy, w * dx)
            speed = math.hypot(ux, uy)
            worst = max(
                worst,
                math.hypot(predicted[0] - ux, predicted[1] - uy)
                / max(speed, abs(w) * math.hypot(dx, dy), 1e-300),
            )
            distance = format_quantity(convert(math.hypot(dx, dy), unit, problem.spec.system), unit)
            parts.append(f"r_{point}/IC = {distance}")
        at = ", ".join(format_quantity(convert(c, unit, problem.spec.system), "") for c in centre)
        detail = (
            f"IC at ({at}) {unit}; "
            + ", ".join(parts)
            + f"; each v = ω × r/IC (largest relative difference {worst:.1e})"
        )
        checks.append(Check(f"instantaneous centre of {name}", worst < 1e-9, detail))
    return tuple(checks)


def _full(expr: sympy.Expr, known: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``expr`` with the known values put in, twice (derived quantities hold givens)."""
    return (sympy.Integer(0) + expr).xreplace(dict(known)).xreplace(dict(known))


def _power_check(
    problem: LinkageProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """The power equation of a loaded linkage (see :func:`cross_checks`)."""
    if problem.free is None:
        return ()
    g = problem.symbols["g"]
    balance = power_balance(
        problem.linkage,
        problem.r,
        problem.levels["velocity"],
        problem.levels["acceleration"],
        g,
        {**problem.system.knowns, **values},
    )
    if balance is None:
        return ()
    rates = problem.levels["velocity"].rotation.values()
    known = {**problem.system.knowns, **values}
    if all(_full(sympy.Integer(0) + w, known) == 0 for w in rates):
        detail = "every bar is at rest: the power equation reads 0 = 0 and checks nothing"
        return (Check.not_run("power equation", detail),)
    supplied, stored = balance
    scale = max(abs(supplied), abs(stored), 1e-300)
    error = abs(supplied - stored) / scale
    unit = natural_unit(Dim(2, 1, -3), problem.spec.system)
    shown = format_quantity(convert(supplied, unit, problem.spec.system), unit)
    heavy = [s.point for s in problem.linkage.sliders.values() if s.mass is not None]
    blocks = f" + m v·a of block{'s' * (len(heavy) > 1)} {', '.join(heavy)}" if heavy else ""
    detail = (
        f"power of the loads {shown} = dT/dt = Σ (m v_G·a_G + I_G ω α){blocks} "
        f"{format_quantity(convert(stored, unit, problem.spec.system), unit)} "
        f"(relative difference {error:.1e})"
    )
    return (Check("power equation", error < 1e-9, detail),)


def _lagrange_check(
    problem: LinkageProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """Each released bar's α against q'' of Lagrange's equations of the open chain
    (:mod:`dynsolve.simulate.chain`), built from the energies alone: no pin force, no
    relative-acceleration equation in common with Newton–Euler."""
    moving = [b for b in problem.linkage.bars if b not in problem.released]
    if not problem.released or any(
        not set(problem.linkage.bars[b].points) <= set(problem.linkage.fixed) for b in moving
    ):
        return ()
    from dynsolve.simulate.chain import chain_of
    from dynsolve.simulate.equations import NotSimulable

    try:
        chain = chain_of(problem.spec)
    except (NotSimulable, SpecError) as exc:
        return (Check.not_run("second method: Lagrange", f"not checked: {exc}"),)
    rates = chain.rates(0.0, [0.0] * chain.size + list(chain.qd0))[chain.size :]
    known = {**problem.system.knowns, **values}
    worst, shown = 0.0, []
    for bar, lagrange in zip(chain.bars, rates, strict=True):
        alpha = (sympy.Integer(0) + problem.levels["acceleration"].rotation[bar]).xreplace(known)
        if alpha.free_symbols:
            return ()
        newton = float(alpha)
        scale = max(abs(newton), abs(lagrange), 1e-300)
        worst = max(worst, abs(newton - lagrange) / scale if scale > 1e-300 else 0.0)
        shown.append(f"α_{bar} {lagrange:.9g}")
    detail = (
        f"M(q) q'' = Q − Σ m J_Gᵀ J_G' q' from T and V of the chain: {', '.join(shown)} "
        f"rad/s² (largest relative difference {worst:.1e})"
    )
    return (Check("second method: Lagrange", worst < 1e-9, detail),)


def figure(problem: LinkageProblem) -> LinkageFigure | None:
    """The linkage at the instant for a drawing, in metres; None when a position is
    symbolic."""
    linkage = problem.linkage
    known = dict(problem.system.knowns)
    joints = []
    for point in linkage.joints:
        try:
            x, y = (float(sympy.N(_full(c, known), 15)) for c in problem.placement.positions[point])
        except TypeError:
            return None
        joints.append((point, x, y, point in linkage.fixed))
    guides = []
    for slider in linkage.sliders.values():
        if slider.axis is None:
            continue
        try:
            dx, dy = (float(sympy.N(_full(c, known), 15)) for c in slider.axis)
        except TypeError:
            return None
        guides.append((slider.point, dx, dy))
    wheels = []
    radii = {w.bar: w.radius for w in linkage.wheels.values()}
    for mesh in linkage.meshes:
        radii.setdefault(mesh.first, mesh.radii[0])
        radii.setdefault(mesh.second, mesh.radii[1])
    for bar, radius in radii.items():
        try:
            wheels.append(
                (bar, linkage.bars[bar].points[0], float(sympy.N(_full(radius, known), 15)))
            )
        except TypeError:
            return None
    grounds = []
    where = {name: (x, y) for name, x, y, _ in joints}
    for wheel in linkage.wheels.values():
        centre = where[linkage.bars[wheel.bar].points[0]]
        try:
            n = [float(sympy.N(_full(c, known), 15)) for c in wheel.normal]
            radius = float(sympy.N(_full(wheel.radius, known), 15))
        except TypeError:
            return None
        grounds.append((centre[0] - radius * n[0], centre[1] - radius * n[1], n[0], n[1]))
    bars = tuple((b.name, b.points) for b in linkage.bars.values())
    return LinkageFigure(tuple(joints), bars, tuple(guides), tuple(wheels), tuple(grounds))
