"""Turn a scene-mode spec into a problem: model, Newton–Euler equations, targets, assumptions.

The result has the same shape as an equation-mode :class:`~dynsolve.modes.equation_mode.Problem`
(givens, equation system, targets, dimensions), plus the scene's free-body diagrams
and the assumptions to check once it is solved.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace

import sympy
from sympy.core.cache import cacheit

from dynsolve.dimensions import DimensionReport, sympy_dimension
from dynsolve.errors import DimensionError, Position, SpecError
from dynsolve.format import quantity as format_quantity
from dynsolve.model.inertia import composite, parallel_axis
from dynsolve.model.scene import Body, Load, Path, Scene, Support, Vec, build_scene
from dynsolve.modes.equation_mode import GivenInfo, Target, check_answers_in_find, givens_of
from dynsolve.momentum_finds import MOMENTUM_FUNCTIONS, momentum_dimension, momentum_quantity
from dynsolve.names import latex_name, pretty
from dynsolve.numbers import light_tidying, real_value, tidy
from dynsolve.principles.newton_euler import Formulation, dot, formulate
from dynsolve.principles.vibration import (
    VIBRATION_FINDS,
    scene_vibration_checks,
    vibration_notes,
    vibration_target,
)
from dynsolve.quantities import resolve_unit
from dynsolve.results import Assumption, Check, EquationRow, ForceRow, FreeBody, Step
from dynsolve.shown import formula_text
from dynsolve.spec.ast import FindItem, Spec
from dynsolve.system import EquationSystem
from dynsolve.units import Dim, InSystem, System, natural_unit, with_unit

IMPENDING = 1e-9  # |F| within this fraction of μs N counts as impending slip, not slip


@dataclass(frozen=True)
class SceneProblem:
    """A scene ready to solve, with what is needed to report and re-check it."""

    spec: Spec
    givens: tuple[GivenInfo, ...]
    system: EquationSystem
    dims: DimensionReport
    targets: tuple[Target, ...]
    symbols: Mapping[str, sympy.Symbol]
    scene: Scene
    formulation: Formulation
    rows: tuple[EquationRow, ...]
    slipping: Mapping[str, int] = field(default_factory=dict)
    steps: tuple[Step, ...] = ()
    mode: str = "scene"
    notes: tuple[tuple[str, str], ...] = ()  # (name, derivation) shown with the checks
    released: Mapping[str, str] = field(default_factory=dict)  # slack cords, lost contacts
    released_elements: Mapping[str, object] = field(default_factory=dict)  # their models


def build_scene_problem(
    spec: Spec,
    slipping: Mapping[str, int] | None = None,
    released: Mapping[str, str] | None = None,
) -> SceneProblem:
    """Model the scene, write its equations and resolve the find list. ``released`` maps
    cords found slack and contacts found lost in an earlier trial to what they were
    ("cord", "contact"): they are left out (their force is zero)."""
    from dynsolve.sections import combine_sections

    spec = combine_sections(spec)
    if not spec.finds:
        raise SpecError("nothing to find", Position(spec.file, 1, 1), hint="add a 'find:' line")
    givens = givens_of(spec)
    symbols: dict[str, sympy.Symbol] = {g.name: g.symbol for g in givens}
    given_dims = {g.name: g.dim for g in givens}
    state_unknowns = _state_unknowns(spec, symbols)
    symbols.update({s.name: s for s in state_unknowns})
    scene = build_scene(
        spec,
        symbols,
        given_dims | {s.name: d for s, d in state_unknowns.items()},
        {g.symbol: g.value for g in givens if g.value is not None},
    )
    given_values = {g.symbol: g.value for g in givens if g.value is not None}
    scene = _cord_states(scene, slipping or {})
    scene = _load_senses(scene, slipping or {})
    removed: dict[str, object] = {}
    if released:
        removed = {c.name: c for c in scene.cords if c.name in released}
        removed |= {s.name: s for s in scene.supports if s.name in released}
        scene = replace(
            scene,
            cords=tuple(c for c in scene.cords if c.name not in released),
            supports=tuple(s for s in scene.supports if s.name not in released),
        )
    rigid = any(not b.particle for b in scene.bodies.values()) or bool(scene.links)
    staged = _staged(scene, spec)
    try:
        if staged:
            from dynsolve.principles.stage_chain import chain_formulation

            instants = _instants_asked(spec, scene)
            if _single_travel(scene, rigid):  # state 1's reactions come with it
                instants -= {1}
            formulation = chain_formulation(scene, symbols, given_values, slipping, instants)
            if _single_travel(scene, rigid):  # the state-1 reactions are asked too
                formulation = _with_instant(formulation, formulate(scene, symbols, slipping))
        elif scene.impacts:
            from dynsolve.principles.impact import impact_formulation

            formulation = impact_formulation(scene)
        elif scene.pivots:
            from dynsolve.principles.impact import pivot_formulation

            formulation = pivot_formulation(scene, given_values)
        elif any(t.kind == "until" for t in scene.travels.values()):
            from dynsolve.principles.until import until_formulation

            formulation = until_formulation(scene, symbols)
        elif any(t.kind == "for" for t in scene.travels.values()):
            from dynsolve.principles.impulse_momentum import impulse_formulation

            formulation = impulse_formulation(scene, symbols, slipping)
        elif (scene.travels and rigid) or (
            scene.movers and not set(scene.movers) & set(scene.bodies)
        ):
            formulation = _states_only(scene)
        else:
            formulation = formulate(scene, symbols, slipping)
        if (
            scene.travels
            and not staged
            and not any(t.kind in ("for", "until") for t in scene.travels.values())
        ):
            formulation = _with_energy(formulation, scene, symbols, given_values)
    except ValueError as exc:  # a stage's error names its line; else the travel's, if any
        line, column = getattr(exc, "line", 0), getattr(exc, "column", 0)
        if not line:
            travel = next(iter(scene.travels.values()), None)
            line, column = (travel.line, travel.column) if travel else (spec.scene[0].line, 1)
        where = Position(spec.file, line or 1, column or 1)
        raise SpecError(str(exc), where, hint="check the scene") from None
    if state_unknowns:
        formulation = replace(formulation, unknowns={**formulation.unknowns, **state_unknowns})
    symbols.update({s.name: s for s in formulation.unknowns})
    symbols.update({s.name: s for s in formulation.derived})
    dims = given_dims | {s.name: d for s, d in formulation.unknowns.items()}
    dims |= {s.name: d for s, (_, d, _) in formulation.derived.items()}
    givens = givens + _inertia_rows(scene, formulation, symbols, given_values)
    resolved: dict[sympy.Symbol, sympy.Expr] = {}  # one may be written with earlier ones
    for s, (value, _dim, _meaning) in formulation.derived.items():
        resolved[s] = value.xreplace(resolved)
    givens = givens + [
        GivenInfo(
            s.name,
            s,
            resolved[s].xreplace(given_values) if given_values else resolved[s],
            dim,
            None,
            meaning,
            value,
        )
        for s, (value, dim, meaning) in formulation.derived.items()
    ]
    if released:  # a slack cord's tension, a lost contact's forces: zero
        zero = sympy.Integer(0)
        reactions = dict(formulation.reactions)
        for name, kind in released.items():
            names = [name] if kind == "cord" else [f"N_{name}", f"F_{name}", f"x_{name}"]
            reactions.update({n: (zero, (zero, zero)) for n in names})
        formulation = replace(formulation, reactions=reactions)
    targets = _targets(spec, scene, formulation, symbols, dims, givens)
    check_answers_in_find(spec, (d.lhs.text for d in spec.defines))  # type: ignore[union-attr]
    wanted = _wanted(targets, formulation)
    # every assumption is checked, whatever the find list asks, also when the answers
    # follow from the givens alone (a crate's speed, "unchanged" only if it does not slip)
    wanted += tuple(s for s in _checked(scene, formulation) if s not in wanted)
    knowns = {g.symbol: g.value for g in givens if g.value is not None}
    equations = formulation.equations if wanted else ()  # nothing asked needs an equation
    system = EquationSystem(
        equations=equations,
        unknowns=tuple(formulation.unknowns) if wanted else (),
        knowns=knowns,
        constraints=formulation.constraints if wanted else (),
        wanted=wanted,
    )
    symbol_dims = {symbols[n]: d for n, d in dims.items() if n in symbols}
    rows = tuple(_row(e, symbol_dims, spec) for e in equations)
    report = DimensionReport(dims, (), frozenset())
    notes = formulation.notes + tuple(
        _inertia_note(t, item, scene)
        for t, item in zip(targets[: len(spec.finds)], spec.finds, strict=True)
        if item.ref is not None and item.ref.function == "I"
    )
    notes += _unused(spec)
    notes += vibration_notes(spec, scene, symbols)
    notes += tuple(
        _path_note(scene, name, _path_extremes(scene, name, Position(spec.file, 1, 1)))
        for name in scene.movers
        if name not in scene.bodies  # a body on a path has its speed at the instant only
    )
    return SceneProblem(
        spec,
        tuple(givens),
        system,
        report,
        targets,
        symbols,
        scene,
        formulation,
        rows,
        dict(slipping or {}),
        notes=notes,
        released=dict(released or {}),
        released_elements=removed,
    )


def _single_travel(scene: Scene, rigid: bool) -> bool:
    """A lone particle's single travel (to or by), whose scene as described is also an
    instant: its Newton–Euler equations give the reactions at state 1."""
    from dynsolve.model.scene import Travel

    events = scene.events
    return (
        len(events) == 1
        and isinstance(events[0], Travel)
        and events[0].kind in ("to", "by")
        and not rigid
        and not scene.movers
    )


def _with_instant(chain: Formulation, instant: Formulation) -> Formulation:
    """The Newton–Euler equations of state 1, then the stage's equations (renumbered)."""
    from dynsolve.system import Equation

    n = len(instant.equations)
    shifted = tuple(
        Equation(e.lhs, e.rhs, f"eq. {n + k}", n + k, e.note)
        for k, e in enumerate(chain.equations, start=1)
    )
    stages = tuple(replace(r, equations=tuple(i + n for i in r.equations)) for r in chain.stages)
    return replace(
        chain,
        equations=instant.equations + shifted,
        unknowns={**instant.unknowns, **chain.unknowns},
        forces=instant.forces,
        couples=instant.couples,
        kinematics=instant.kinematics,
        moment_points=instant.moment_points,
        reactions={**chain.reactions, **instant.reactions},
        events=chain.events + instant.events,
        kinetic=instant.kinetic,
        derived={**instant.derived, **chain.derived},
        stages=stages,
        axes=instant.axes,
        inclines=instant.inclines,
    )


def _unused(spec: Spec) -> tuple[tuple[str, str], ...]:
    """A note naming each given the scene never reads (with a did-you-mean)."""
    from dynsolve.usage import scene_reads, unused_note

    return unused_note(givens_of(spec), scene_reads(spec))


def _staged(scene: Scene, spec: Spec) -> bool:
    """Whether the scene is followed through stages: several travel or impact lines, an
    impact with the ground, or a find that needs the states (T, work, …)."""
    from dynsolve.derived import called_functions
    from dynsolve.model.momentum_events import Clutch, Reshape
    from dynsolve.model.scene import GROUND, Impact
    from dynsolve.stage_finds import STAGE_FUNCTIONS

    events = scene.events
    if len(events) == 1 and getattr(events[0], "kind", "") == "for":
        return False
    ground = any(i.other == GROUND and GROUND not in scene.bodies for i in scene.impacts)
    asked = {item.ref.function for item in spec.finds if item.ref is not None}
    asked |= called_functions(spec)
    at_state = any(i.ref and i.ref.function == "speed" and len(i.ref.args) == 2 for i in spec.finds)
    at_state |= any(  # H(B, P, k), p(B, k): a momentum at a numbered state
        i.ref
        and i.ref.function in MOMENTUM_FUNCTIONS
        and len(i.ref.args) > 1
        and str(i.ref.args[-1]).isdigit()
        for i in spec.finds
    )
    stage_functions = {*STAGE_FUNCTIONS, "V", *AVERAGE_FORCES}
    impacts = any(isinstance(e, Impact | Clutch | Reshape) for e in events)  # checked too
    return (
        len(events) > 1
        or ground
        or impacts
        or bool(events and (asked & stage_functions or at_state or _instants_asked(spec, scene)))
    )


# find functions that take a state number (or a body) and are not a reaction at a state
_NOT_REACTIONS = frozenset(
    {"T", "V", "work", "energy_lost", "impulse", "F_avg", "F_net_avg", "power", "speed", "omega2"}
    | {"v_after", "omega_after", "distance", "angle", "height", "m", "I", "alpha", "omega"}
    | {"a_G", "a", "trial", "steepest", "tips", "slips", "slack", "lifts", "H", "p"}
    | {"omega_n", "f_n", "period", "for_period"}
)


def _instants_asked(spec: Spec, scene: Scene) -> frozenset[int]:
    """The states whose reactions a find asks for: ``cord(2)``, ``N_C(3)`` (a name that
    is not a find function, with a state number)."""
    return frozenset(
        int(item.ref.args[0])
        for item in spec.finds
        if item.ref is not None
        and item.ref.function not in _NOT_REACTIONS
        and item.ref.function not in scene.bodies
        and item.ref.function not in {s.name for s in scene.springs}
        and len(item.ref.args) == 1
        and item.ref.args[0].isdigit()
        and scene.events
    )


def _targets(
    spec: Spec,
    scene: Scene,
    formulation: Formulation,
    symbols: Mapping[str, sympy.Symbol],
    dims: Mapping[str, Dim],
    givens: list[GivenInfo],
) -> tuple[Target, ...]:
    """The find list's targets, with the ``define:`` lines' derived quantities (a define
    listed in find takes its place and unit there; the others follow)."""
    from dynsolve.derived import define_targets

    names = {line.lhs.text for line in spec.defines}  # type: ignore[union-attr]
    found = tuple(
        _target(item, spec, scene, formulation, symbols, dims)
        for item in spec.finds
        if item.name not in names or item.ref is not None
    )
    if not spec.defines:
        return found
    for item in spec.finds:  # a defined name must not hide a quantity of the scene
        if item.name in names and item.ref is None:
            try:
                _target(item, spec, scene, formulation, symbols, dims)
            except SpecError:
                continue
            line = next(d for d in spec.defines if d.lhs.text == item.name)  # type: ignore[union-attr]
            raise SpecError(
                f"'{item.name}' is already a quantity of the scene: its definition on line "
                f"{line.line} would replace it",
                Position(spec.file, line.line, line.column),
                hint="choose another name for the derived quantity; an equation to solve "
                "for a scene quantity cannot be combined with the scene: section",
            )

    def resolve(function: str, args: tuple[str, ...], where: Position) -> Target:
        item = FindItem(f"{function}({', '.join(args)})", None, where.line, where.column)
        return _quantity(function, args, item, scene, formulation, symbols, dims, where)

    defined = {
        t.name: t
        for t in define_targets(
            spec,
            found,
            {g.name: g.symbol for g in givens},
            {g.name: g.dim for g in givens},
            resolve,
        )
    }
    ordered: list[Target] = []
    for item in spec.finds:
        if item.name in defined and item.ref is None:
            where = Position(spec.file, item.line, item.column)
            unit, _ = _unit(item, defined[item.name].dim, spec, where)
            if item.unit is None:  # a derived energy is shown in J, not N·m
                unit = natural_unit(defined[item.name].dim, spec.system, "E")
            requested = item.unit is not None
            ordered.append(replace(defined.pop(item.name), unit=unit, requested=requested))
        else:
            ordered.append(next(t for t in found if t.name == item.name))
    for target in defined.values():
        ordered.append(replace(target, unit=natural_unit(target.dim, spec.system, "E")))
    return tuple(ordered)


INERTIA = Dim(2, 1, 0)


def _inertia_rows(
    scene: Scene,
    formulation: Formulation,
    symbols: dict[str, sympy.Symbol],
    given_values: Mapping[sympy.Symbol, sympy.Expr],
) -> list[GivenInfo]:
    """Each turning body's I_G from its table formula or radius of gyration, listed with the
    givens as the textbook computes it first (I_G = m k_G² = 8(0.35)² = 0.980 kg·m²), even
    where the equations carry the formula itself: a body that only translates, a particle,
    a composite (its I_O row shows the sum) and an I_G given by name have no row."""
    turning = [
        body
        for body in scene.bodies.values()
        if not body.particle
        and body.shape != "composite"
        and not (sympy.Integer(0) + body.I_G).is_Symbol
        and not _is_zero_expr(body.I_G)
        and getattr(formulation.kinematics.get(body.name), "motion", "") != "translation"
    ]
    rows = []
    for body in turning:
        name = "I_G" if len(turning) == 1 else f"I_G_{body.name}"
        if name in symbols:
            continue
        symbol = sympy.Symbol(name, positive=True)
        value = body.I_G.xreplace(given_values) if given_values else body.I_G
        note = f"I about G of {body.name}: {body.inertia_note or 'given'}"
        rows.append(GivenInfo(name, symbol, value, INERTIA, None, note, body.I_G, shown=True))
    for pivot in scene.pivots:  # a body struck at a point turns about it: I_P = I_G + m d²
        body = scene.bodies[pivot.body]
        name = f"I_{pivot.name}" if len(scene.pivots) == 1 else f"I_{pivot.name}_{body.name}"
        d2 = tidy(
            (body.G[0] - pivot.point[0]) ** 2 + (body.G[1] - pivot.point[1]) ** 2, light=False
        )
        if body.particle or name in symbols or _is_zero_expr(d2):
            continue
        formula = tidy(body.I_G + body.mass * d2, light=False)
        value = formula.xreplace(given_values) if given_values else formula
        note = (
            f"I about {pivot.name} of {body.name}: I_G + m d² (parallel-axis theorem), "
            f"d² = {sympy.sstr(d2).replace('**', '^')}"
        )
        symbol = sympy.Symbol(name, positive=True)
        rows.append(GivenInfo(name, symbol, value, INERTIA, None, note, formula, shown=True))
    return rows


def _is_zero_expr(expr: sympy.Expr) -> bool:
    """True for an expression that is exactly zero (a particle's I_G)."""
    return bool((sympy.Integer(0) + expr).is_zero)


def _inertia_note(target: Target, item: FindItem, scene: Scene) -> tuple[str, str]:
    """How an asked-for inertia was found: the body's own I_G, then the parallel axis."""
    assert item.ref is not None
    body = scene.bodies[item.ref.args[0]]
    lines = [body.inertia_note or "I_G given"]
    if len(item.ref.args) > 1:
        lines.append(f"parallel-axis theorem: I_{item.ref.args[1]} = I_G + m d²")
    return (f"inertia {item.name} of {body.name}", "; ".join(lines))


_STATE_DIMS = {"velocity": Dim(1, 0, -1), "omega": Dim(0, 0, -1), "travel": Dim(0, 0, 1)}


def _state_unknowns(spec: Spec, symbols: Mapping[str, sympy.Symbol]) -> dict[sympy.Symbol, Dim]:
    """The speeds of ``velocity``/``omega`` lines that are asked for, not given: a name in
    find written there becomes an unknown magnitude (the 'minimum speed' of a problem)."""
    from dynsolve.spec.ast import Name

    asked = {item.name for item in spec.finds if item.ref is None}
    found: dict[sympy.Symbol, Dim] = {}
    stops = {n.text for n in _stopping_distances(spec)}
    for stmt in spec.scene:
        value = stmt.value
        dim = _STATE_DIMS.get(stmt.kind)
        if stmt.kind == "travel" and stmt.word != "for":  # a distance (by), not an angle
            dim = Dim.of("length") if stmt.word == "" and stmt.direction is not None else None
        if (
            dim is not None
            and isinstance(value, Name)
            and value.text not in symbols
            and (value.text in asked or value.text in stops)
        ):
            extent = stmt.kind == "travel" and stmt.word == ""  # a distance may be 0
            if extent and value.text in stops and _from_rest(spec, stmt.body):
                extent = False  # from rest until it stops: d = 0 (not moving) is no answer
            sign = {"nonnegative": True} if extent else {"positive": True}
            if any(p.key == "until" for p in stmt.props):
                sign = {"real": True}  # its sign is checked: the event comes after the start
            found[sympy.Symbol(value.text, **sign)] = dim
    return found


def _from_rest(spec: Spec, body: str) -> bool:
    """Whether ``body`` starts at rest in a single stage: no velocity or ω given to it and
    no impact before its travel."""
    scene = spec.scene or ()
    moving = any(s.kind in ("velocity", "omega") and s.body == body for s in scene)
    return not moving and not any(s.kind in ("impact", "pivot", "clutch", "change") for s in scene)


def _stopping_distances(spec: Spec) -> list[object]:
    """The names of distances in ``travel B: by NAME, DIR, stops`` lines: how far it
    goes until it stops is an unknown that the stop fixes (a rebound height)."""
    from dynsolve.spec.ast import Name

    return [
        stmt.value
        for stmt in spec.scene
        if stmt.kind == "travel"
        and isinstance(stmt.value, Name)
        and (
            (
                stmt.word == ""
                and stmt.direction is not None
                and any(p.key == "stops" for p in stmt.props)
            )
            or (stmt.word == "for" and any(p.key == "until" for p in stmt.props))
        )
    ]


def _states_only(scene: Scene) -> Formulation:
    """An empty formulation for a rigid body or linkage between states: its answers come
    from work and energy alone, not from the equations of motion at state 1."""
    from dynsolve.principles.newton_euler import bare_formulation

    return bare_formulation(scene.bodies)


def _cord_states(scene: Scene, slipping: Mapping[str, int]) -> Scene:
    """Each elastic cord assumed taut at the end of a travel whose extent is unknown, or
    slack where a solve found it so (``slipping["taut:S"]`` = −1)."""
    springs = tuple(
        replace(s, taut=slipping.get(f"taut:{s.name}", 1) > 0) if s.one_way else s
        for s in scene.springs
    )
    return replace(scene, springs=springs)


def _load_senses(scene: Scene, slipping: Mapping[str, int]) -> Scene:
    """Each load of unknown size in its stated sense, or reversed where a solve found it
    acting the other way (``slipping["sense:NAME"]`` = −1)."""
    loads = []
    for load in scene.loads:
        if slipping.get(f"sense:{load.name}", 1) < 0:
            x, y = load.direction
            load = replace(load, direction=(-x, -y), sense=-load.sense)
        loads.append(load)
    return replace(scene, loads=tuple(loads))


def _with_energy(
    formulation: Formulation,
    scene: Scene,
    symbols: Mapping[str, sympy.Symbol],
    given_values: Mapping[sympy.Symbol, sympy.Expr],
) -> Formulation:
    """Add T1 + ΣU = T2 for the scene's travel (one per travelling particle)."""
    from dynsolve.principles.work_energy import energy_equations
    from dynsolve.system import Equation

    equations = list(formulation.equations)
    unknowns = dict(formulation.unknowns)
    speeds, spins = dict(formulation.speeds), dict(formulation.spins)
    notes = list(formulation.notes)
    second = list(formulation.second)
    terms = list(formulation.energy_terms)
    cords = list(formulation.cords)
    for energy in energy_equations(_after_pivot(scene, formulation), symbols, given_values):
        terms += energy.terms
        cords += energy.cords
        number = len(equations) + 1
        equation = energy.equation
        equations.append(
            Equation(equation.lhs, equation.rhs, f"eq. {number}", number, equation.note)
        )
        if energy.rate is not None:
            rotation = energy.rate.name.startswith("omega")
            unknowns[energy.rate] = Dim(0, 0, -1) if rotation else Dim(1, 0, -1)
        speeds.update(energy.speeds)
        spins.update(energy.spins)
        if energy.relations:
            notes.append(("kinematics between the states", "; ".join(energy.relations)))
        if energy.rate is not None and energy.second is not None:
            second.append((energy.rate, *energy.second))
    return replace(
        formulation,
        equations=tuple(equations),
        unknowns=unknowns,
        speeds=speeds,
        spins=spins,
        notes=tuple(notes),
        second=tuple(second),
        energy_terms=tuple(terms),
        cords=tuple(cords),
        constraints=formulation.constraints + tuple(c.branch() for c in cords),
    )


SECOND_METHOD_AGREEMENT = 1e-6  # relative


def cross_checks(
    problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """Each answer found a second way, compared with the one solved for."""
    checks = []
    substitution = {**problem.system.knowns, **values}
    for unknown, other, how, what in problem.formulation.second:
        found = real_value(unknown, substitution)
        if found is None:
            continue
        gap = abs(found - other) / max(abs(found), 1e-300)
        dim = problem.formulation.unknowns.get(unknown, Dim())  # a speed or a rate of turn
        checks.append(
            Check(
                f"second method: {what}",
                gap <= SECOND_METHOD_AGREEMENT,
                f"{how}: {with_unit(other, dim, problem.spec.system, '.7g')} (work–energy: "
                f"{with_unit(found, dim, problem.spec.system, '.7g')}; relative difference "
                f"{gap:.1e})",
            )
        )
    return (
        tuple(checks)
        + _interval_checks(problem, substitution)
        + _moment_checks(problem, substitution)
        + scene_vibration_checks(problem, substitution)
    )


def _interval_checks(
    problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """Work and energy over each interval that impulse and momentum solved."""
    from dynsolve.principles.impulse_momentum import energy_check

    formulation, system = problem.formulation, problem.spec.system
    kinetic = {  # kinetic friction (a known μk N) on the instant's free bodies
        f.name
        for forces in formulation.forces.values()
        for f in forces
        if f.kind == "friction" and f.known
    }
    intervals = [("", formulation.interval_energy, 1, kinetic)] + [
        (f"stage {r.stage.number}", r.energy, r.stage.number, {f"F_{s.support}" for s in r.slides})
        for r in formulation.stages
    ]
    checks = (
        energy_check(what, energy, values, SECOND_METHOD_AGREEMENT, system, state, kinetic)
        for what, energy, state, kinetic in intervals
        if energy is not None
    )
    return tuple(c for c in checks if c is not None)


def _moment_checks(
    problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Check, ...]:
    """Method II for each rigid body with equations of motion at the instant: its moments
    balanced about other points (:mod:`dynsolve.principles.moment_check`)."""
    from dynsolve.principles.moment_check import balance

    formulation, checks = problem.formulation, []
    for name, kinematics in formulation.kinematics.items():
        body = problem.scene.bodies.get(name)
        if body is None or kinematics.motion == "particle":  # a translating "particle" counts
            continue
        check = balance(
            name,
            body,
            formulation.forces.get(name, ()),
            formulation.couples.get(name, ()),
            kinematics,
            values,
        )
        if check is not None:
            checks.append(check)
    return tuple(checks)


def second_moment_rows(problem: SceneProblem) -> tuple[EquationRow, ...]:
    """The textbook's other moment equation of each rigid body, printed in the unknowns as
    a check: about G where the equations took moments about a pin or a contact (the
    spool's Method I, the car's Section I, the flywheel's ΣM_G = I_G α). Not part of the
    solved system; the 'second moment point' check verifies it with the solved values."""
    with light_tidying(False):  # shown as exact mode shows it, in every mode
        return _second_moment_rows(problem)


def _second_moment_rows(problem: SceneProblem) -> tuple[EquationRow, ...]:
    from dynsolve.principles.moment_check import moment_equation
    from dynsolve.system import Equation

    formulation = problem.formulation
    dims = {problem.symbols[n]: d for n, d in problem.dims.dims.items() if n in problem.symbols}
    line = max((row.line for row in problem.rows), default=0)
    rows = []
    for name, kinematics in formulation.kinematics.items():
        body = problem.scene.bodies.get(name)
        used = formulation.moment_points.get(name, "")
        if body is None or kinematics.motion == "particle" or not used:
            continue
        point, label = body.G, "G"
        if used.startswith("G"):  # on incline axes about G: the contact is Method II
            contact = next((s for s in problem.scene.supports if s.body == name), None)
            if name not in formulation.axes or contact is None:
                continue
            point, label = contact.point, contact.point_name
        pin = kinematics.pin
        if pin is not None and all(
            tidy(a - b) == 0 for a, b in zip(pin.point, body.G, strict=True)
        ):
            continue  # a pin at G: the equations already took moments about G
        applied, kinetic = moment_equation(
            body,
            formulation.forces.get(name, ()),
            formulation.couples.get(name, ()),
            kinematics,
            point,
            formulation.inclines.get(name),
        )
        principle = (
            "ΣM_G = 0 (translation)" if kinematics.motion == "translation" else ("ΣM_G = I_G α")
        )
        if label != "G":
            principle = f"ΣM_{label} = I_G α + (r_G/{label} × m a_G)"
        line += 1
        note = f"{principle} ({name}): a second moment point, a check, not used in the solve"
        equation = Equation(tidy(applied), tidy(kinetic), f"ΣM_{label} ({name})", line, note)
        rows.append(_row(equation, dims, problem.spec))
    return tuple(rows)


def _after_pivot(scene: Scene, formulation: Formulation) -> Scene:
    """The scene just after an eccentric impact: pinned at the struck point, turning at ω₁."""
    if not scene.pivots:
        return scene
    from dynsolve.model.scene import WORDS, Support

    pins = tuple(
        Support("pin", p.name, p.body, p.point, WORDS["up"], line=p.line, column=p.column)
        for p in scene.pivots
    )
    return replace(
        scene, supports=pins, omegas=dict(formulation.after_omega), velocities={}, pivots=()
    )


def _wanted(targets: tuple[Target, ...], formulation: Formulation) -> tuple[sympy.Symbol, ...]:
    unknowns = set(formulation.unknowns)
    wanted: list[sympy.Symbol] = []
    for target in targets:
        exprs = [target.expr] if target.expr is not None else []
        if target.kind == "steepest":  # needs the friction's sense in the solved scene
            exprs = [formulation.reactions[f"F_{target.expr}"][0]]
        if target.kind == "threshold":  # solved apart, with its load as a letter
            exprs = []
        if target.vector is not None:
            exprs += list(target.vector)
        for expr in exprs:
            wanted += [s for s in expr.free_symbols if s in unknowns and s not in wanted]
    return tuple(wanted)


def _checked(scene: Scene, formulation: Formulation) -> tuple[sympy.Symbol, ...]:
    """The unknowns that checking the assumptions needs: each contact's N and F (contact
    kept, no slip), a base's x (no tipping), each cord's tension (taut), and the motion of
    the bodies whose friction is kinetic (the sense of their slide)."""
    exprs: list[sympy.Expr] = []
    for support in scene.supports:
        if support.kind == "pin":
            continue
        exprs += [
            formulation.reactions[f"{prefix}{support.name}"][0]
            for prefix in ("N_", "F_")
            if f"{prefix}{support.name}" in formulation.reactions
        ]
        if support.kind == "base":
            exprs.append(sympy.Symbol(f"x_{support.name}", real=True))
        kin = formulation.kinematics.get(support.body)
        if kin is not None and not support.smooth:
            exprs += [kin.alpha, *kin.a_G]
    exprs += [
        formulation.reactions[c.name][0] for c in scene.cords if c.name in formulation.reactions
    ]
    found: dict[sympy.Symbol, None] = {}  # in order, each once (a list's 'in' is n²)
    for expr in exprs:
        for s in sorted((sympy.Integer(0) + expr).free_symbols, key=str):
            if s in formulation.unknowns:
                found.setdefault(s)
    return tuple(found)


def _row(equation: object, dims: Mapping[sympy.Symbol, Dim], spec: Spec) -> EquationRow:
    from dynsolve.system import Equation

    assert isinstance(equation, Equation)
    used = equation.residual.free_symbols  # not every symbol: n² for n bodies
    pretty_names = {s: sympy.Symbol(pretty(s.name)) for s in used if pretty(s.name) != s.name}
    latex_names = {s: latex_name(s.name) for s in used}
    try:
        dim = sympy_dimension(equation.residual, dims)
        ok = True
    except DimensionError as exc:  # a scene whose givens have the wrong units
        raise DimensionError(
            f"{equation.note}: {exc.message}", Position(spec.file, 1, 1), exc.hint
        ) from None
    lhs, rhs = equation.lhs, equation.rhs
    if pretty_names:  # Greek letters: the terms reorder as the new names sort
        lhs, rhs = lhs.xreplace(pretty_names), rhs.xreplace(pretty_names)
    text = f"{sympy.sstr(lhs)} = {sympy.sstr(rhs)}"
    latex = sympy.latex(
        sympy.Eq(equation.lhs, equation.rhs, evaluate=False), symbol_names=latex_names
    )
    unit = natural_unit(dim, spec.system) or "1"
    return EquationRow(
        equation.line,
        text.replace("**", "^"),
        latex,
        equation.note,
        f"{dim.name} [{unit}]",
        ok,
        False,
    )


# ---- targets
_ROTATION = ("alpha", "omega")


def _target(
    item: FindItem,
    spec: Spec,
    scene: Scene,
    formulation: Formulation,
    symbols: Mapping[str, sympy.Symbol],
    dims: Mapping[str, Dim],
) -> Target:
    ref = item.ref
    where = Position(spec.file, item.line, item.column)
    function = ref.function if ref else item.name
    args = ref.args if ref else ()
    trial = False
    if function == "trial":
        if len(args) != 1:
            raise SpecError("trial takes one name: trial(F_A)", where, "write trial(NAME)")
        function, args, trial = args[0], (), True
    if function in AVERAGE_FORCES and len(args) > 1:
        _contact_time_positive(spec, args[1], item)
    target = _quantity(function, args, item, scene, formulation, symbols, dims, where)
    unit, dim = _unit(item, target.dim, spec, where)
    if item.unit is None and function in ("T", "work", "energy_lost", "V"):
        unit = natural_unit(dim, spec.system, "E")  # an energy, not a moment
    if (target.kind == "steepest" or function == "angle") and item.unit is None:
        unit = "deg"
    if function == "f_n" and item.unit is None:
        unit = "Hz"
    return replace(target, unit=unit, dim=dim, trial=trial, requested=item.unit is not None)


def _contact_time_positive(spec: Spec, name: str, item: FindItem) -> None:
    """An average force's contact time t_c is a given and positive (an error at it)."""
    from dynsolve.model.physical import POSITIVE, check_sign
    from dynsolve.spec.ast import Name

    givens = {g.name: g for g in spec.givens}
    given = givens.get(name)
    if given is None or given.quantity is None:
        return
    value = sympy.Rational(given.quantity.value.numerator, given.quantity.value.denominator)
    used = Name(name, item.line, item.column)
    check_sign(value, used, "a contact time", POSITIVE, {}, spec.file, givens)


def _unit(item: FindItem, dim: Dim, spec: Spec, where: Position) -> tuple[str, Dim]:
    if item.unit is None:
        return natural_unit(dim, spec.system, item.name), dim
    unit_dim = resolve_unit(item.unit, spec.file).dim
    if unit_dim != dim:
        raise DimensionError(
            f"find asks for {item.name} in {item.unit.text} ({unit_dim.name}), "
            f"but it is {dim.name}",
            where,
            hint=f"use a unit of {dim.name}",
        )
    return item.unit.text, dim


def _quantity(
    function: str,
    args: tuple[str, ...],
    item: FindItem,
    scene: Scene,
    formulation: Formulation,
    symbols: Mapping[str, sympy.Symbol],
    dims: Mapping[str, Dim],
    where: Position,
) -> Target:
    name = item.name
    symbol = sympy.Symbol(name)

    def target(kind: str, dim: Dim, expr: sympy.Expr | None = None, **extra: object) -> Target:
        return Target(name, symbol, dim, "", False, False, kind, expr, **extra)  # type: ignore[arg-type]

    from dynsolve.stage_finds import STAGE_FUNCTIONS, potential_energy, stage_quantity

    if function == "V" and not formulation.states:  # the scene as described
        bodies = (_body(args[0], scene, where),) if args else tuple(scene.bodies)
        g = symbols.get("g", sympy.Symbol("g", positive=True))
        return target("signed", Dim(2, 1, -2), potential_energy(scene, bodies, g))
    if function == "V" and len(args) <= 2 and args:
        return target(
            "signed", Dim(2, 1, -2), stage_quantity("V", args, scene, formulation, where)[2]
        )
    if function == "power":
        return target("signed", Dim(2, 1, -3), _power(args, scene, formulation, where))
    if function in VIBRATION_FINDS:
        return _vibration_target(function, args, scene, symbols, dims, target, where)
    if function in AVERAGE_FORCES:
        kind, dim, vector, note = _average_force(
            function, args, scene, formulation, symbols, dims, where
        )
        return target(kind, dim, vector=vector, note=note)

    if function in MOMENTUM_FUNCTIONS and args:
        kind, dim, expr, vector, note = _momentum(function, args, scene, formulation, where)
        return target(kind, dim, expr, vector=vector, note=note)
    staged = function in STAGE_FUNCTIONS and (args or function == "energy_lost")
    if staged or (function == "speed" and len(args) == 2):  # T alone may be a tension
        kind, dim, expr, vector = stage_quantity(function, args, scene, formulation, where)
        return target(kind, dim, expr, vector=vector)
    from dynsolve.thresholds import THRESHOLDS, threshold_target

    if function in THRESHOLDS:
        expr = threshold_target(function, args, scene, formulation, symbols, where)
        load = expr.args[1]
        return target("threshold", dims.get(load.name, Dim.of("force")), expr)
    if function == "steepest":
        support = _support_named((args or ("",))[0], scene, where, rough=True)
        if support is None or support.mu_s is None or scene.gravity is None:
            raise SpecError(
                "steepest(C) needs a contact C with mu_s, and gravity",
                where,
                hint="name a rough contact, e.g. steepest(C) for 'rolls disk at C: …, mu_s mu_s'",
            )
        return target("steepest", Dim(), sympy.Symbol(support.name))
    if function == "speed" and len(args) == 1:
        body = _body(args[0], scene, where)
        if body not in formulation.speeds:
            raise SpecError(
                f"{body} does not travel to a second state",
                where,
                hint=f"add 'travel {body}: to (x, y)'",
            )
        return target("magnitude", Dim(1, 0, -1), formulation.speeds[body])
    if function == "angle" and len(args) == 1:
        body = _body(args[0], scene, where)
        if body not in formulation.turns:
            raise SpecError(
                f"{body} does not go round a centre until an event",
                where,
                hint=f"angle(B) is the angle turned by 'travel {body}: until CORD slack' "
                "or 'until contact lost'",
            )
        return target("magnitude", Dim(), formulation.turns[body])
    if function == "height" and len(args) == 1:
        body = _body(args[0], scene, where)
        if body not in formulation.turns:
            raise SpecError(
                f"{body} does not go round a centre until an event",
                where,
                hint="height(B) is how far G rises (up positive) until the event",
            )
        assert scene.gravity is not None  # an until event needs gravity
        up = (-scene.gravity[0], -scene.gravity[1])
        return target("along", Dim.of("length"), formulation.heights[body], axis=up)
    if function == "distance" and len(args) == 1:
        body = _body(args[0], scene, where)
        if body not in formulation.displacements:
            raise SpecError(
                f"{body} does not move over an interval",
                where,
                hint=f"distance(B) is how far G moves over 'travel {body}: for t, …'",
            )
        return target("vector", Dim.of("length"), vector=formulation.displacements[body])
    if function in ("a_max", "a_min") and len(args) == 1:
        if args[0] not in scene.movers or args[0] in scene.bodies:
            raise SpecError(
                f"{args[0]} is not a point moving along a path at constant speed",
                where,
                hint=f"add 'moves {args[0]}: along PATH, speed v' for a point that is not a body",
            )
        extreme = _path_extremes(scene, args[0], where)
        chosen = extreme.maximum if function == "a_max" else extreme.minimum
        kappa = (f"kappa_{function[2:]}", chosen.kappa, Dim(-1, 0, 0))  # a = v² κ
        return target("magnitude", Dim(1, 0, -2), chosen.a, before=(kappa,))
    if function == "omega_after" and len(args) == 1:
        if args[0] not in formulation.after_omega:
            raise SpecError(
                f"{args[0]} strikes no fixed point", where, hint="add 'impact B at P: e 0'"
            )
        return target("rotation", Dim(0, 0, -1), formulation.after_omega[args[0]])
    if function == "omega2" and len(args) == 1:
        if args[0] not in formulation.spins:
            raise SpecError(
                f"{args[0]} does not turn between two states",
                where,
                hint="describe state 2 with a 'travel' line of a rigid body or link",
            )
        return target("rotation", Dim(0, 0, -1), formulation.spins[args[0]])
    if function == "v_after" and len(args) == 1:
        body = _body(args[0], scene, where)
        if body not in formulation.after:
            raise SpecError(
                f"{body} takes part in no impact", where, hint="add 'impact A with B: …'"
            )
        return target("vector", Dim(1, 0, -1), vector=formulation.after[body])
    if args and function in ("m", "I"):
        body = _body(args[0], scene, where)
        model = scene.bodies[body]
        if function == "m":
            return target("magnitude", Dim(0, 1), model.mass)
        if len(args) == 1:
            return target("magnitude", Dim(2, 1), model.I_G)
        point = _point(args[1], scene, body, where)
        d2 = (model.G[0] - point[0]) ** 2 + (model.G[1] - point[1]) ** 2
        found = target("magnitude", Dim(2, 1), parallel_axis(model.I_G, model.mass, sympy.sqrt(d2)))
        if model.parts:  # the textbook's sum: each part's I_G + m d² about the point
            relative = (point[0] - model.origin[0], point[1] - model.origin[1])
            found = replace(found, parts=composite(model.parts).terms(relative))
        return found
    at_state = f"{function}({args[0]})" if len(args) == 1 and args[0].isdigit() else ""
    if at_state == f"{function}(1)" and function in formulation.reactions:
        at_state = function  # a single travel's state 1 is the scene's instant
    if at_state in formulation.reactions:
        reaction, axis = formulation.reactions[at_state]
        if any(c.name == function for c in scene.cords) or any(
            link.name == function for link in scene.links
        ):
            return target("signed", Dim(1, 1, -2), reaction)  # a tension (+) or a push (−)
        return target("along", Dim(1, 1, -2), reaction, axis=axis)
    if any(s.name == function for s in scene.springs):
        raise SpecError(
            f"the force of the spring {function} is not a find",
            where,
            hint="define it from its stretch, e.g. 'define: F_S = k*x' with x the stretch "
            "at that state (or ask work(S, k) for its work over a stage)",
        )
    if args and not formulation.kinematics:
        raise SpecError(
            f"'{function}' is not a quantity of a scene between states or impacts",
            where,
            hint="such a scene answers speed(B[, k]), omega2(B), v_after(B), omega_after(B), "
            "T(B, k), V(B, k), work(F, k), energy_lost(k), impulse(B, k), distance(B), "
            "angle(B), height(B), a reaction at a state (cord(2)), m(B), I(B) and I(B, P)",
        )
    if args:
        body = _body(args[0], scene, where)
        kin = formulation.kinematics[body]
        if function == "alpha":
            return target("rotation", Dim(0, 0, -2), kin.alpha)
        if function == "omega":
            return target("rotation", Dim(0, 0, -1), kin.omega)
        if function in ("a_G", "a"):
            if kin.tangent is not None and kin.along is not None:  # along the incline
                return target("along", Dim(1, 0, -2), kin.along, axis=kin.tangent)
            return target("vector", Dim(1, 0, -2), vector=kin.a_G)
        raise SpecError(
            f"unknown scene quantity '{function}'",
            where,
            hint="use alpha(B), omega(B), a_G(B), m(B), I(B), I(B, P) or trial(X)",
        )
    if function in formulation.reactions:
        reaction, axis = formulation.reactions[function]
        if any(c.name == function for c in scene.cords):
            return target("magnitude", Dim(1, 1, -2), reaction)  # a tension has no sense to state
        return target("along", Dim(1, 1, -2), reaction, axis=axis)
    pins = [s for s in scene.supports if s.kind == "pin" and s.name == function]
    if pins:
        parts = [v for k, v in formulation.reactions.items() if k.startswith(f"{function}_")]
        vector = (
            sympy.Add(*(s * a[0] for s, a in parts)),
            sympy.Add(*(s * a[1] for s, a in parts)),
        )
        return target("vector", Dim(1, 1, -2), vector=vector)
    pin, _, axis_name = function.rpartition("_")
    if axis_name in ("x", "y") and any(s.kind == "pin" and s.name == pin for s in scene.supports):
        # O_x, O_y of a pin whose reactions are written along n and t (G off the pin):
        # the components the textbook also asks for, projected from O_n and O_t
        parts = [v for k, v in formulation.reactions.items() if k.startswith(f"{pin}_")]
        index = 0 if axis_name == "x" else 1
        component = sympy.Add(*(s * a[index] for s, a in parts))
        axis = (sympy.Integer(1), sympy.Integer(0)) if index == 0 else (0, 1)
        return target("along", Dim(1, 1, -2), tidy(component), axis=axis)
    if function in symbols and function in dims:
        kind = "rotation" if function.startswith(_ROTATION) else "signed"
        return target(kind, dims[function], symbols[function])
    known = sorted({*formulation.reactions, *(s.name for s in formulation.unknowns)})
    close = difflib.get_close_matches(function, known, n=1)
    hint = (
        f"did you mean '{close[0]}'?" if close else f"the scene's unknowns are {', '.join(known)}"
    )
    raise SpecError(f"'{function}' is not a quantity of this scene", where, hint)


def _vibration_target(
    function: str,
    args: tuple[str, ...],
    scene: Scene,
    symbols: Mapping[str, sympy.Symbol],
    dims: Mapping[str, Dim],
    target: object,
    where: Position,
) -> Target:
    """``period(B)``, ``omega_n(B)``, ``f_n(B)``: the small free vibration of the scene;
    ``for_period(B, X, T)``: the given X at which the period is the given T."""
    body = _body((args or ("",))[0], scene, where)
    if function == "for_period" and len(args) == 3 and dims.get(args[2]) != Dim(0, 0, 1):
        raise SpecError(
            f"for_period({', '.join(args)}): {args[2]} is not a time",
            where,
            hint="the third argument is the period wanted, a given in s",
        )
    try:
        expr, before = vibration_target(function, body, scene, symbols, args[1:])
    except ValueError as exc:
        raise SpecError(
            f"{function}({', '.join(args)}): {exc}",
            where,
            hint="see 'Vibrations' in docs/scene-mode.md",
        ) from None
    if function == "for_period":
        return target("magnitude", dims[args[1]], expr, before=before)  # type: ignore[operator]
    dim = Dim(0, 0, 1 if function == "period" else -1)
    return target("magnitude", dim, expr, before=before)  # type: ignore[operator]


def _momentum(
    function: str, args: tuple[str, ...], scene: Scene, formulation: Formulation, where: Position
) -> tuple[str, Dim, sympy.Expr | None, Vec | None, str]:
    """H(B[, P][, k]) or p(B[, k]): kind, dimension, expression, vector and what it is."""
    body = _body(args[0], scene, where)
    rest = list(args[1:])
    state = rest.pop() if rest and rest[-1].isdigit() else None
    if len(rest) > (1 if function == "H" else 0):
        raise SpecError(
            f"{function} takes the body, "
            + ("a point and " if function == "H" else "")
            + "a state number at most",
            where,
            hint="H(B) about G, H(B, O) about O, H(B, O, 2) at state 2; p(B), p(B, 2)",
        )
    point = (rest[0], _point(rest[0], scene, body, where)) if rest else None
    kind, expr, vector, note = momentum_quantity(
        function, body, point, state, scene, formulation, where
    )
    return kind, momentum_dimension(function), expr, vector, note


def _power(
    args: tuple[str, ...], scene: Scene, formulation: Formulation, where: Position
) -> sympy.Expr:
    """P = F·v_P of a force (or M ω of a couple) at the instant."""
    if len(args) != 1 or not formulation.kinematics:
        raise SpecError(
            "power(F) is the power of one force or couple at the instant",
            where,
            hint="write power(P) in a scene without travels or impacts",
        )
    name = args[0]
    for body, forces in formulation.forces.items():
        kin = formulation.kinematics.get(body)
        if kin is None:
            continue
        G = scene.bodies[body].G
        v_G = scene.velocities.get(body, (sympy.Integer(0), sympy.Integer(0)))
        for force in forces:
            if force.name == name:
                r = (force.point[0] - G[0], force.point[1] - G[1])
                v_P = (v_G[0] - kin.omega * r[1], v_G[1] + kin.omega * r[0])
                return tidy(force.magnitude * dot(force.direction, v_P))
        for couple in formulation.couples.get(body, ()):
            if couple.name == name:
                return tidy(couple.moment * kin.omega)
    names = sorted(
        {f.name for fs in formulation.forces.values() for f in fs}
        | {c.name for cs in formulation.couples.values() for c in cs}
    )
    close = difflib.get_close_matches(name, names, n=1)
    hint = f"did you mean '{close[0]}'?" if close else "forces: " + ", ".join(names)
    raise SpecError(f"'{name}' is not a force or couple of the scene", where, hint)


AVERAGE_FORCES = ("F_avg", "F_net_avg")  # the contact force, the net force over t_c


def _average_force(
    function: str,
    args: tuple[str, ...],
    scene: Scene,
    formulation: Formulation,
    symbols: Mapping[str, sympy.Symbol],
    dims: Mapping[str, Dim],
    where: Position,
) -> tuple[str, Dim, tuple[sympy.Expr, sympy.Expr], str]:
    """An average force on B over a given contact time t_c of its impact (stage k): the net
    force ``F_net_avg(B, t_c [, k])`` = impulse(B [, k])/t_c = m Δv/t_c, every force on B
    included; the contact (impact) force ``F_avg(B, t_c [, k])`` = m Δv/t_c − W, the weight's
    impulse W t_c over the contact taken out (the impact keeps the velocity across its
    line, so the contact also held the weight). Returns kind, dimension, vector and what
    it is, in words."""
    from dynsolve.stage_finds import stage_quantity

    if len(args) not in (2, 3) or args[1] not in symbols:
        raise SpecError(
            f"{function} takes the body and the contact time: {function}(B, t_c) or "
            f"{function}(B, t_c, k)",
            where,
            hint="t_c is a given time, e.g. t_c = 0.002 s",
        )
    if dims.get(args[1]) != Dim(0, 0, 1):
        raise SpecError(f"'{args[1]}' is not a time", where, hint="give the contact time in s")
    impulse_args = (args[0], *args[2:])
    _, _, _, vector = stage_quantity("impulse", impulse_args, scene, formulation, where)
    assert vector is not None
    t_c = symbols[args[1]]
    net = (tidy(vector[0] / t_c), tidy(vector[1] / t_c))
    body = scene.bodies[args[0]]
    if function == "F_net_avg":
        note = (
            f"the average net force on {body.name} over t_c, m Δv/t_c: every force on it "
            f"included (its weight too); F_avg({body.name}, {args[1]}) is the contact force"
        )
        return "vector", Dim.of("force"), net, note
    if scene.gravity is None:
        note = (
            f"the average contact force on {body.name} over t_c, m Δv/t_c (no gravity: "
            "the net force)"
        )
        return "vector", Dim.of("force"), net, note
    W = body.mass * symbols.get("g", sympy.Symbol("g", positive=True))
    contact = tuple(tidy(net[i] - W * scene.gravity[i]) for i in range(2))
    note = (
        f"the average contact (impact) force on {body.name} over t_c: m Δv/t_c − W, its "
        f"weight's impulse over the contact taken out; F_net_avg({body.name}, {args[1]}) "
        "is the net force m Δv/t_c"
    )
    return "vector", Dim.of("force"), (contact[0], contact[1]), note


@dataclass(frozen=True)
class SteepestLimit:
    """steepest(C)'s scene with gravity tilted by φ, solved in the givens' symbols: the
    friction F(φ) and normal force N(φ) at the contact, friction's sense and μs, and on
    a base the resultant normal force's place x(φ) and the base's edges from G's line."""

    F: sympy.Expr
    N: sympy.Expr
    sense: int
    mu_s: sympy.Expr
    phi: sympy.Symbol
    x: sympy.Expr | None = None
    edges: tuple[sympy.Expr, sympy.Expr] | None = None


@dataclass(frozen=True)
class Steepest:
    """The steepest slope at a contact and what happens just beyond it: 'slips' (|F|
    reaches μs N first) or 'tips' (N reaches an edge of the base first)."""

    angle: sympy.Expr | None
    happens: str = "slips"


def steepest_limit(
    problem: SceneProblem, contact: str, values: Mapping[sympy.Symbol, sympy.Expr], options: object
) -> SteepestLimit | None:
    """F(φ), N(φ) (and x(φ) on a base) at ``contact`` in the givens' symbols with gravity
    tilted by φ (:func:`steepest` and :func:`steepest_lines` share it: the slope's value is
    its numbers put in, its derivation its letters)."""
    return _steepest_limit(problem, contact, values, options, {})


def steepest(
    problem: SceneProblem,
    contact: str,
    values: Mapping[sympy.Symbol, sympy.Expr],
    options: object,
    found: SteepestLimit | None = None,
) -> Steepest:
    """The steepest slope at ``contact`` (angle of its surface to the horizontal) on which
    the body stays: the scene re-solved with gravity tilted by an unknown angle φ, and the
    smaller of the angle where |F| = μs N (friction in the sense it has in ``values``) and,
    on a base, the angle where N reaches an edge of the base (it tips first)."""
    knowns = problem.system.knowns
    found = found or _steepest_limit(problem, contact, values, options, knowns)
    if found is None:
        return Steepest(None)
    condition = tidy((found.F - found.sense * found.mu_s * found.N).xreplace(knowns))
    best = Steepest(_angle_root(condition, found.phi), "slips")
    for edge in _tip_conditions(found):
        root = _angle_root(tidy(edge.xreplace(knowns)), found.phi)
        value = real_value(root, {}) if root is not None else None
        least = real_value(best.angle, {}) if best.angle is not None else None
        if value is not None and (least is None or value < least - 1e-12):
            best = Steepest(root, "tips")
    return best


def _tip_conditions(found: SteepestLimit) -> tuple[sympy.Expr, ...]:
    """x(φ) at either edge of the base, each written as a balance free of fractions."""
    if found.x is None or found.edges is None:
        return ()
    return tuple(sympy.numer(sympy.together(sympy.expand(found.x - edge))) for edge in found.edges)


def steepest_checks(
    name: str,
    contact: str,
    found: SteepestLimit,
    at: Steepest,
    knowns: Mapping,
    system: System,
) -> tuple[Check, ...]:
    """The friction and (on a base) the tipping condition evaluated AT the steepest slope
    found, not on the scene as written: |F| ≤ μs N and N within the base, in ``system``'s
    units."""
    if at.angle is None:
        return ()
    values = {**knowns, found.phi: at.angle}
    F, N = real_value(found.F, values), real_value(found.N, values)
    mu = real_value(found.mu_s, values)
    degrees = real_value(at.angle * 180 / sympy.pi, {})
    where = f"at {name} = {degrees:.4g}°" if degrees is not None else f"at {name}"
    checks = []
    if F is not None and N is not None and mu is not None:
        holds = abs(F) <= mu * N * (1 + IMPENDING)
        limit = at.happens == "slips"
        checks.append(
            Check(
                f"no slip at {contact} {where}",
                holds,
                f"|F| = {with_unit(abs(F), 'force', system)} {'≤' if holds else '>'} "
                f"μs N = {with_unit(mu * N, 'force', system)}"
                + (": the limit, it is about to slip" if limit else ""),
            )
        )
    if found.x is not None and found.edges is not None:
        x = real_value(found.x, values)
        ends = [real_value(e, values) for e in found.edges]
        if x is not None and None not in ends:
            lo, hi = min(ends), max(ends)  # type: ignore[type-var]
            tol = 1e-9 * max(abs(lo), abs(hi), 1e-300)
            holds = lo - tol <= x <= hi + tol
            checks.append(
                Check(
                    f"no tipping on base {contact} {where}",
                    holds,
                    f"N_{contact} acts at x = {with_unit(x, 'length', system)} from G's line, "
                    + ("within" if holds else "outside")
                    + f" [{lo:.4g}, {with_unit(hi, 'length', system)}]"
                    + (": at the edge, it is about to tip" if at.happens == "tips" else ""),
                )
            )
    return tuple(checks)


def steepest_lines(
    problem: SceneProblem,
    contact: str,
    values: Mapping[sympy.Symbol, sympy.Expr],
    options: object,
    found: SteepestLimit | None = None,
    happens: str = "slips",
) -> tuple[sympy.Expr, sympy.Expr, sympy.Expr, sympy.Symbol] | None:
    """The steepest slope's derivation in the givens' symbols: the friction F(φ) and the
    normal force N(φ) the body needs on a slope φ (where it slips first), or N's place
    x(φ) and N(φ) (where it tips first), and tan φ where |F| = μs N (the seed's
    tan β = μs(1 + m R²/I)) or x(φ) reaches the edge (tan β = b/h); None where the
    condition is not a sin/cos balance."""
    found = found or steepest_limit(problem, contact, values, options)
    if found is None:
        return None
    phi = found.phi
    if happens == "tips":
        if found.x is None:
            return None
        for condition in _tip_conditions(found):
            tangent = _tangent(sympy.expand(condition), phi)
            value = real_value(tangent, problem.system.knowns) if tangent is not None else None
            if tangent is not None and value is not None and value > 0:
                return tidy(found.x), tidy(found.N), tangent, phi
        return None
    tangent = _tangent(sympy.expand(found.F - found.sense * found.mu_s * found.N), phi)
    if tangent is None:
        return None
    return tidy(found.F), tidy(found.N), tangent, phi


def _tangent(condition: sympy.Expr, phi: sympy.Symbol) -> sympy.Expr | None:
    """tan φ from a sin φ + b cos φ = 0, or None where ``condition`` is not of that form."""
    a, b = condition.coeff(sympy.sin(phi)), condition.coeff(sympy.cos(phi))
    if sympy.expand(condition - a * sympy.sin(phi) - b * sympy.cos(phi)) != 0 or a == 0:
        return None
    return tidy(sympy.factor(-b / a))


def _steepest_limit(
    problem: SceneProblem,
    contact: str,
    values: Mapping[sympy.Symbol, sympy.Expr],
    options: object,
    knowns: Mapping[sympy.Symbol, sympy.Expr],
) -> SteepestLimit | None:
    """F and N (and x on a base) at ``contact`` with gravity tilted by φ, solved with
    ``knowns`` put in; friction's sense and μs: |F| = μs N at the steepest slope."""
    from dynsolve.solver import solve_system

    scene, formulation = problem.scene, problem.formulation
    support = next(s for s in scene.supports if s.name == contact)
    assert scene.gravity is not None and support.mu_s is not None
    all_knowns = problem.system.knowns
    up = (-scene.gravity[0], -scene.gravity[1])
    side = real_value(dot(up, support.tangent), all_knowns) or 0.0
    friction = real_value(formulation.reactions[f"F_{contact}"][0], {**all_knowns, **values})
    if friction is None:
        return None
    phi = sympy.Symbol("phi_steepest", positive=True)
    s = 1 if side >= 0 else -1
    n, t = support.normal, support.tangent
    tilted = (
        -(sympy.cos(phi) * n[0] + s * sympy.sin(phi) * t[0]),
        -(sympy.cos(phi) * n[1] + s * sympy.sin(phi) * t[1]),
    )
    symbols = {g.name: g.symbol for g in problem.givens}
    limit = formulate(replace(scene, gravity=tilted), symbols, problem.slipping)
    # friction keeps its sense; on level ground it opposes the slide the tilt starts
    sense = (1 if friction > 0 else -1) if friction != 0 else s
    F, N = limit.reactions[f"F_{contact}"][0], limit.reactions[f"N_{contact}"][0]
    x_symbol = sympy.Symbol(f"x_{contact}", real=True)
    on_base = support.kind == "base" and support.end is not None
    x = limit.reactions.get(f"x_{contact}", (x_symbol,))[0] if on_base else None
    wanted = (F, N) if x is None else (F, N, x)
    wanted = tuple(w for w in wanted if w in limit.unknowns) or (F, N)
    # solve the (linear) scene with φ as a parameter, then |F| = μs N for φ alone
    system = EquationSystem(limit.equations, tuple(limit.unknowns), knowns, wanted=wanted)
    quiet = replace(options, show_formulas=False)  # type: ignore[type-var]
    solved = solve_system(system, quiet).values
    if F not in solved or N not in solved:
        return None
    edges = None
    if x is not None and x in solved:
        body = scene.bodies[support.body]
        foot = dot((body.G[0] - support.point[0], body.G[1] - support.point[1]), t)
        assert support.end is not None
        length = dot((support.end[0] - support.point[0], support.end[1] - support.point[1]), t)
        edges = (-foot, length - foot)
    return SteepestLimit(
        solved[F], solved[N], sense, support.mu_s, phi,
        solved.get(x) if x is not None else None, edges,
    )  # fmt: skip


def _angle_root(condition: sympy.Expr, phi: sympy.Symbol) -> sympy.Expr | None:
    """The root of ``condition`` = 0 in (0, π/2]: exactly when sympy can, else numerically."""
    try:
        roots = sympy.solve(condition, phi)
    except (NotImplementedError, ValueError):
        roots = []
    for root in roots:
        value = real_value(root, {})
        if value is not None and 0 < value <= float(sympy.pi / 2) + 1e-12:
            return root
    for start in (0.1, 0.5, 1.0, 1.4):
        try:
            root = sympy.nsolve(condition, phi, start)
        except (ValueError, ZeroDivisionError, TypeError):
            continue
        if 0 < float(root) <= float(sympy.pi / 2) + 1e-12:
            return root
    return None


SAMPLES = (1.0, 2.0, 3.0, 5.0, 7.0, 0.5, 1.5, 4.0, 11.0)


def _path_extremes(scene: Scene, name: str, where: Position) -> object:
    """The largest and smallest acceleration of a point moving along a path at constant
    speed; symbolic givens are ordered with sample values that meet the scene's
    ``assume`` lines, and the order must be the same for every such sample."""
    mover = scene.movers[name]
    values = tuple(sorted(scene.values.items(), key=lambda item: str(item[0])))
    found = _extremes(mover.path, mover.speed, values, scene.assumptions)
    if found is None:
        raise SpecError(
            f"which point of the path {mover.path.name} has the largest acceleration depends "
            "on the givens",
            where,
            hint="say which region you mean, e.g. 'assume a > b' in the scene",
        )
    return found


@cacheit  # once per path and solve (cleared with sympy's cache, as every form's tidying)
def _extremes(
    path: Path,
    speed: sympy.Expr,
    values: tuple[tuple[sympy.Symbol, sympy.Expr], ...],
    assumptions: tuple[sympy.core.relational.Relational, ...],
) -> object | None:
    """The curvature extremes of ``path`` (once per path: the notes and every find that
    asks share them); None when their order differs between the samples."""
    from dynsolve.principles.curvilinear import (
        ExplicitPath,
        ImplicitPath,
        acceleration_extremes,
    )

    shape = (
        ExplicitPath(path.explicit, path.x)
        if path.explicit is not None
        else ImplicitPath(path.curve, path.x, path.y)
    )
    given = dict(values)
    symbols = sorted(path.curve.free_symbols - {path.x, path.y}, key=str)
    if all(s in given for s in symbols):
        return acceleration_extremes(shape, speed, order_by=given)
    found = []
    for shift in range(len(SAMPLES)):
        sample = {s: SAMPLES[(i + shift) % len(SAMPLES)] for i, s in enumerate(symbols)}
        if all(bool(a.xreplace(sample)) for a in assumptions):
            found.append(acceleration_extremes(shape, speed, order_by=sample))
    orders = {(sympy.srepr(f.maximum.a), sympy.srepr(f.minimum.a)) for f in found}
    return found[0] if len(orders) == 1 else None


def _path_note(scene: Scene, name: str, extremes: object) -> tuple[str, str]:
    """How the extremes along a path were found, and where they are."""
    from dynsolve.principles.curvilinear import AccelerationExtremes

    assert isinstance(extremes, AccelerationExtremes)
    mover = scene.movers[name]

    def points(extreme: object) -> str:
        shown = [f"({formula_text(x)}, {formula_text(y)})" for x, y in extreme.points]  # type: ignore[attr-defined]
        return ", ".join(shown) or "everywhere"

    return (
        f"{name} along {mover.path.name}",
        "constant speed: a_t = 0, so |a| = a_n = v²κ; the extremes of the curvature κ "
        f"along the path: largest a = {formula_text(extremes.maximum.a)} at "
        f"{points(extremes.maximum)}, smallest a = {formula_text(extremes.minimum.a)} at "
        f"{points(extremes.minimum)}",
    )


def _support_named(name: str, scene: Scene, where: Position, rough: bool = False) -> object:
    """The support named ``name``; a point name shared by several bodies' supports
    (``contact A at G`` and ``contact B at G`` are ``G_A`` and ``G_B``) finds the one of
    them that fits (rough, when ``rough``), else says which names to use."""
    exact = next((s for s in scene.supports if s.name == name), None)
    if exact is not None:
        return exact
    shared = [s for s in scene.supports if s.at == name]
    fitting = [s for s in shared if not rough or s.mu_s is not None]
    if len(fitting) == 1:
        return fitting[0]
    if len(fitting) > 1:
        raise SpecError(
            f"several supports are at {name}",
            where,
            hint="name one: " + ", ".join(s.name for s in fitting),
        )
    return None


def _body(name: str, scene: Scene, where: Position) -> str:
    if name not in scene.bodies:
        close = difflib.get_close_matches(name, list(scene.bodies), n=1)
        hint = f"did you mean '{close[0]}'?" if close else "name a body of the scene"
        raise SpecError(f"there is no body '{name}'", where, hint)
    return name


def _point(name: str, scene: Scene, body: str, where: Position) -> Vec:
    if name in scene.fixed_points:
        return scene.fixed_points[name]
    if name in scene.bodies[body].points:
        return scene.bodies[body].points[name]
    raise SpecError(
        f"there is no point '{name}'", where, hint="declare it with 'point NAME: (x, y)'"
    )


# ---- after solving: assumptions and diagrams
def assess(
    problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[tuple[Assumption, ...], dict[str, int]]:
    """Check every assumption against a solution; return them and any contacts that slip.

    A no-slip contact whose friction exceeds μs N, and that has a μk, is returned in
    the second item with the sense of its (kinetic) friction along the tangent; a load of
    unknown size that came out against its stated sense, as ``"sense:NAME"``: −1.
    """
    checks, slips = _assess(problem, values)
    senses, flipped = _load_senses_kept(problem, {**problem.system.knowns, **values})
    return checks + senses, slips | flipped


def _load_senses_kept(
    problem: SceneProblem, substitution: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[tuple[Assumption, ...], dict[str, int]]:
    """Each force or couple whose size is an unknown acts in the sense the scene states
    (``couple M on B: ccw``, ``force R on B at G: up``): a size that comes out negative
    is that load acting the other way, a failed assumption re-solved with the sense
    reversed (``"sense:NAME"``), and said so, as a friction's sense is."""
    checks, flipped = [], {}
    unknowns = {s.name: s for s in problem.formulation.unknowns}
    for load in problem.scene.loads:
        symbol = unknowns.get(load.name)
        size = real_value(symbol, substitution) if symbol is not None else None
        if size is None:
            continue
        word = _sense_word(load)
        reversed_ = problem.slipping.get(f"sense:{load.name}", 1) < 0
        name = f"sense of {load.kind} {load.name}"
        stated = f" (stated the other way: re-solved {word})" if reversed_ else ""
        if size >= -SENSE_TOLERANCE * max(1.0, abs(size)):
            checks.append(Assumption(name, True, f"{load.name} = {size:.4g} ≥ 0 {word}{stated}"))
            continue
        other = _sense_word(load, -1)
        checks.append(
            Assumption(
                name,
                False,
                f"{load.name} = {size:.4g} against its stated sense ({word}): it acts {other}; "
                f"re-solved with {load.name} {other}",
            )
        )
        flipped[f"sense:{load.name}"] = -1 if not reversed_ else 1
    return tuple(checks), flipped


def _sense_word(load: Load, flip: int = 1) -> str:
    """A load's sense in words: cw/ccw for a couple, its direction for a force."""
    if load.kind == "couple":
        return "ccw" if load.sense * flip > 0 else "cw"
    x, y = (real_value(flip * c, {}) for c in load.direction)
    if x is None or y is None:
        return "the other way" if flip < 0 else "as stated"
    return direction_word(x, y)


def _assess(
    problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[tuple[Assumption, ...], dict[str, int]]:
    """The assumptions of the scene's friction, cords, contacts and events (:func:`assess`)."""
    knowns = problem.system.knowns
    substitution = {**knowns, **values}
    checks: list[Assumption] = []
    slips: dict[str, int] = {}
    scene, formulation = problem.scene, problem.formulation
    system = problem.spec.system
    cords, switched = _cord_checks(formulation, substitution, system)
    slips |= switched
    if formulation.stages:
        from dynsolve.principles.stage_chain import chain_assumptions, chain_slips

        chained = chain_assumptions(scene, formulation, substitution, system) + cords
        slips |= chain_slips(formulation, substitution)
        if not formulation.kinematics:
            return chained, slips
        checks += chained  # a single travel: its state 1 is checked as an instant too
        cords = ()
    if scene.travels and not formulation.reactions:
        events = tuple(_event_checks(formulation, substitution, system))
        return _between_states(problem, substitution) + events + cords, slips
    checks += _event_checks(formulation, substitution, system)
    checks += _slides_kept(formulation, substitution, system)
    sliding_until = {
        s.name
        for s in scene.supports
        for t in scene.travels.values()
        if t.until == "rolls" and s.body == t.body and s.kind == "contact" and not s.smooth
    }
    for support in scene.supports:
        if support.kind == "pin":
            continue
        N = real_value(formulation.reactions[f"N_{support.name}"][0], substitution)
        if N is not None and support.two_sided and not _is_zero_expr(support.normal_acceleration):
            checks += _path_side(scene, support, N, substitution, system)
        if N is None and not support.two_sided:
            checks.append(Assumption.undecided(f"contact at {support.name} kept", UNDECIDED))
        if N is not None and not support.two_sided:
            checks.append(
                Assumption(
                    f"contact at {support.name} kept",
                    N >= 0,
                    f"N_{support.name} = {with_unit(N, 'force', system)} {'≥' if N >= 0 else '<'} 0"
                    + ("" if N >= 0 else f": the body leaves the surface; {RELEASED}"),
                )
            )
        friction_name = f"F_{support.name}"
        state = problem.slipping.get(support.name)
        if state:
            checks.append(_slip_sense(problem, support, state, substitution))
        elif state is None and support.friction_sense is not None:
            slide = _declared_slide(problem, support, substitution)
            if slide is not None:
                checks.append(slide)
                if not slide.holds and "re-solved" in slide.detail:
                    slips[support.name] = 0
        elif support.name in sliding_until:
            pass  # kinetic friction until it rolls: checked by the event's time
        elif support.name in formulation.sliding:
            slip = real_value(formulation.sliding[support.name], substitution)
            known = slip is not None and math.isfinite(slip)
            checks.append(
                Assumption(
                    f"sliding at {support.name}",
                    known,
                    f"its contact point moves at {with_unit(slip, 'velocity', system)} along "
                    "the surface at the "
                    "instant (the velocities given): kinetic friction μk N opposes it"
                    if known
                    else "the speed of its contact point along the surface is undefined",
                )
            )
        elif friction_name in formulation.reactions and N is not None:
            friction = formulation.reactions[friction_name][0]
            check = _no_slip(support, friction, N, substitution, system)
            if check is not None:
                assumption, sense = check
                checks.append(assumption)
                if sense:
                    slips[support.name] = sense
            elif support.mu_s is not None or support.mu_k is not None:
                checks.append(Assumption.undecided(f"no slip at {support.name}", UNDECIDED))
        elif friction_name in formulation.reactions and (
            support.mu_s is not None or support.mu_k is not None
        ):  # a rough contact without a coefficient holds whatever it must: nothing to check
            checks.append(Assumption.undecided(f"no slip at {support.name}", UNDECIDED))
        if support.kind == "base":
            x = real_value(
                formulation.reactions.get(
                    f"x_{support.name}", (sympy.Symbol(f"x_{support.name}", real=True),)
                )[0],
                substitution,
            )
            checks.append(_tipping(support, problem, x, substitution))
    checks += _held_at_rest(scene, checks)
    for cord in scene.cords:
        T = real_value(formulation.reactions[cord.name][0], substitution)
        if T is None:
            checks.append(Assumption.undecided(f"cord {cord.name} taut", UNDECIDED))
        if T is not None:
            checks.append(
                Assumption(
                    f"cord {cord.name} taut",
                    T >= 0,
                    f"{cord.name} = {with_unit(T, 'force', system)} {'≥' if T >= 0 else '<'} 0"
                    + ("" if T >= 0 else f": the cord goes slack; {RELEASED}"),
                )
            )
    checks += _released_checks(problem, substitution)
    return tuple(checks), slips


RELEASED = "re-solved without it (its force zero)"
UNDECIDED = "cannot be decided: the force has no numeric value (symbolic givens)"


def _released_checks(
    problem: SceneProblem, substitution: Mapping[sympy.Symbol, sympy.Expr]
) -> list[Assumption]:
    """A cord re-solved slack must not be stretched by the motion found without it (its
    end moves toward its anchor or the other end), and a contact re-solved lost must see
    its point leave the surface (a_P·n ≥ 0, from rest at the instant)."""
    from dynsolve.model.scene import Cord, Support

    system = problem.spec.system
    checks = []
    for name, element in problem.released_elements.items():
        if isinstance(element, Cord):
            cord = element
            a_1 = _accel(problem, cord.body, cord.point)
            a_2: Vec = (sympy.Integer(0), sympy.Integer(0))
            if cord.other and cord.other_point is not None:
                a_2 = _accel(problem, cord.other, cord.other_point)
            closing = real_value(
                dot((a_1[0] - a_2[0], a_1[1] - a_2[1]), cord.direction), substitution
            )
            holds = closing is None or closing >= -SENSE_TOLERANCE * max(1.0, abs(closing))
            detail = (
                f"{name} = 0; without it, its ends do not draw apart (relative "
                "acceleration along it "
                f"{with_unit(0.0 if closing is None else closing, 'acceleration', system)} "
                "toward the anchor)"
            )
            if not holds:
                detail = f"{name} = 0, but without it the motion would stretch it: neither holds"
            checks.append(Assumption(f"cord {name} slack", holds, detail))
        else:
            assert isinstance(element, Support)
            support = element
            a_P = _accel(problem, support.body, support.point)
            away = real_value(dot(a_P, support.normal), substitution)
            holds = away is None or away >= -SENSE_TOLERANCE * max(1.0, abs(away))
            detail = (
                f"N_{name} = 0; without the contact its point accelerates away from the "
                f"surface at {with_unit(0.0 if away is None else away, 'acceleration', system)}"
            )
            if not holds:
                detail = f"N_{name} = 0, but without it the body would move into the surface"
            checks.append(Assumption(f"contact at {name} lost", holds, detail))
    return checks


def _accel(problem: SceneProblem, body: str, point: Vec) -> Vec:
    """The acceleration of a body's point at the instant (zero for no equations of motion)."""
    from dynsolve.principles.newton_euler import point_acceleration

    kin = problem.formulation.kinematics.get(body)
    if kin is None:
        return (sympy.Integer(0), sympy.Integer(0))
    return point_acceleration(kin, problem.scene.bodies[body].G, point)


def _cord_checks(
    formulation: Formulation, substitution: Mapping[sympy.Symbol, sympy.Expr], system: str
) -> tuple[tuple[Assumption, ...], dict[str, int]]:
    """Each elastic cord's state assumed at the end of a travel, against the answer: a cord
    assumed taut must be stretched there (s₂ > 0), one assumed slack must not be. Returns
    the checks and the states to re-solve with (``"taut:S"``: +1 taut, −1 slack)."""
    checks, switched = [], {}
    for cord in formulation.cords:
        name, taut, k = cord.name, cord.taut, cord.state
        s = real_value(cord.stretch, substitution)
        if s is None and taut and not cord.stretch.free_symbols <= set(substitution):
            on, off = cord.words
            what = "elastic cord" if cord.sign > 0 else "spring"
            relation = "s > 0" if cord.sign > 0 else "s < 0"
            detail = (
                f"no root keeps it {on} ({relation} at state {k}): it is {off} there; re-solved so"
            )
            checks.append(Assumption(f"{what} {name} {on} at state {k}", False, detail))
            switched[f"taut:{name}"] = -1
            continue
        if s is None:
            continue
        acting = cord.sign * s > 0
        holds = acting if taut else not acting
        what = "elastic cord" if cord.sign > 0 else "spring"
        on, off = cord.words
        detail = f"stretch at state {k} s = {with_unit(s, 'length', system)}" + (
            " > 0" if s > 0 else " ≤ 0"
        )
        if not holds:
            detail += f": it is {off if taut else on} there; re-solved so"
            switched[f"taut:{name}"] = -1 if taut else 1
        state = on if taut else off
        checks.append(Assumption(f"{what} {name} {state} at state {k}", holds, detail))
    return tuple(checks), switched


def _slides_kept(
    formulation: Formulation, substitution: Mapping[sympy.Symbol, sympy.Expr], system: System
) -> list[Assumption]:
    """Each contact sliding at the start of an interval (impulse and momentum) slides to
    its end: a block that stops before it (friction alone would bring it back) fails. A
    slide stated from rest is judged by ``_declared_slide``."""
    from dynsolve.principles.stage_chain import slide_kept

    checks = []
    for name, (start, end) in formulation.interval_slips.items():
        first, last = real_value(start, substitution), real_value(end, substitution)
        if first is not None and last is not None and abs(first) > SENSE_TOLERANCE * abs(last):
            checks.append(
                slide_kept(f"sliding at {name} through the interval", first, last, 1, system)
            )
    return checks


def _event_checks(
    formulation: Formulation, substitution: Mapping[sympy.Symbol, sympy.Expr], system: System
) -> list[Assumption]:
    """Each until event holds: it comes after the start (its time or turn is positive), a
    cord is taut or a contact pushes where it starts; values in ``system``'s units."""
    checks = []
    for name, value, detail in formulation.events:
        number = real_value(value, substitution)
        if number is None:
            continue
        holds = number > 0
        text = detail.format(value=InSystem(number, system))
        if not holds:
            text += ": it would have to happen before the start, so it never happens"
        checks.append(Assumption(name, holds, text))
    return checks


def _held_at_rest(scene: Scene, checks: list[Assumption]) -> tuple[Assumption, ...]:
    """A body that travels to state 2 from rest must start to move: one whose contact holds
    it by static friction at state 1 (no slip holds) never gets there."""
    held = []
    for support in scene.supports:
        travel = scene.travels.get(support.body)
        if travel is None or travel.kind == "for" or support.body in scene.velocities:
            continue
        stuck = any(c.name == f"no slip at {support.name}" and c.holds for c in checks)
        if stuck and support.kind in ("contact", "base"):
            held.append(
                Assumption(
                    f"{support.body} starts toward state 2",
                    False,
                    f"at rest in state 1, static friction at {support.name} holds it (no slip "
                    "holds): it does not start to move, so it never reaches state 2",
                )
            )
    return tuple(held)


def _no_slip(
    support: object,
    friction: sympy.Expr,
    N: float,
    substitution: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> tuple[Assumption, int] | None:
    """|F| ≤ μs N at a contact assumed not to slip, and the sense (±1 along the tangent)
    of kinetic friction to re-solve with when it fails (0: no re-solve). Without μs, μk N
    is a lower bound of μs N: below it the contact surely holds; above it μs is taken
    equal to μk, the only coefficient given."""
    from dynsolve.model.scene import Support

    assert isinstance(support, Support)
    F = real_value(friction, substitution)
    mu = support.mu_s if support.mu_s is not None else support.mu_k
    mu_value = real_value(mu, substitution) if mu is not None else None
    if F is None or mu_value is None:
        return None
    limit = mu_value * N
    holds = abs(F) <= limit * (1 + IMPENDING)

    def force(value: float) -> str:
        return with_unit(value, "force", system)

    name = f"no slip at {support.name}"
    if support.mu_s is None:
        detail = f"|F| = {force(abs(F))} {'≤' if holds else '>'} μk N = {force(limit)}"
        if holds:
            return Assumption(name, True, detail + " ≤ μs N (μs ≥ μk)"), 0
        detail += " (no mu_s given: taken equal to μk); re-solved with F = μk N opposing the slip"
        return Assumption(name, False, detail), 1 if F > 0 else -1
    impending = holds and abs(abs(F) - limit) <= IMPENDING * max(limit, 1e-300)
    detail = f"|F| = {force(abs(F))} {'≤' if holds else '>'} μs N = {force(limit)}"
    if impending:
        detail += " (impending slip: still no slip)"
    sense = 0
    if not holds and support.mu_k is not None:
        detail += "; re-solved with F = μk N opposing the slip"
        sense = 1 if F > 0 else -1
    return Assumption(name, holds, detail), sense


def _contact_motion(
    problem: SceneProblem, support: object, substitution: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[float | None, float | None]:
    """The velocity and acceleration of a body's contact point along the contact tangent."""
    from dynsolve.model.scene import ZERO, Support
    from dynsolve.principles.newton_euler import point_acceleration

    assert isinstance(support, Support)
    kin = problem.formulation.kinematics.get(support.body)  # none over an interval
    G = problem.scene.bodies[support.body].G
    omega = kin.omega if kin else problem.scene.omegas.get(support.body, sympy.Integer(0))
    v_G = problem.scene.velocities.get(support.body, ZERO)
    r = (support.point[0] - G[0], support.point[1] - G[1])
    v_P = (v_G[0] - omega * r[1], v_G[1] + omega * r[0])
    a_P = point_acceleration(kin, G, support.point) if kin else None
    return (
        real_value(dot(v_P, support.tangent), substitution),
        real_value(dot(a_P, support.tangent), substitution) if a_P else None,
    )


SENSE_TOLERANCE = 1e-9  # a relative speed or acceleration this small counts as zero


def _declared_slide(
    problem: SceneProblem, support: object, substitution: Mapping[sympy.Symbol, sympy.Expr]
) -> Assumption | None:
    """A stated ``slides DIR``: the contact point must move that way, or (at rest at the
    instant) start to; a slide the answer contradicts is re-solved without slip."""
    from dynsolve.model.scene import Support

    assert isinstance(support, Support) and support.friction_sense is not None
    name = f"sliding at {support.name}"
    if support.kind == "contact" and problem.scene.motions.get(support.body) == "translation":
        return Assumption(
            name,
            True,
            f"stated: {support.body} is stated to translate, so the slide at {support.name} is "
            "of a wheel spinning there (a driven wheel), not of the body's own point",
        )
    v, a = _contact_motion(problem, support, substitution)
    if v is None:
        return None
    system = problem.spec.system
    along = -support.friction_sense  # the slide's sense along the tangent
    over = problem.formulation.interval_slips.get(support.name)
    if a is None and over is not None and abs(v) <= SENSE_TOLERANCE:
        return _slide_from_rest(support, along, real_value(over[1], substitution), system)
    v_P = with_unit(abs(v), "velocity", system)
    if along * v > SENSE_TOLERANCE:
        return Assumption(name, True, f"its contact point slides that way (v_P = {v_P})")
    if along * v < -SENSE_TOLERANCE:
        return Assumption(
            name, False, f"its contact point moves against the stated slide (v_P = {v_P})"
        )
    if a is None:
        return None
    if along * a >= -SENSE_TOLERANCE and support.mu_s is not None:
        return Assumption(
            name,
            False,
            "from rest, a slide starts only if static friction cannot hold the contact: "
            "re-solved with no slip to check |F| ≤ μs N",
        )
    if along * a >= -SENSE_TOLERANCE:
        return Assumption(
            name,
            True,
            f"from rest, the contact point accelerates that way at "
            f"{with_unit(abs(a), 'acceleration', system)} (no mu_s: "
            "static friction is not checked)",
        )
    return Assumption(
        name,
        False,
        f"from rest, F = μk N opposing the slide would accelerate the contact point the other "
        f"way ({with_unit(abs(a), 'acceleration', system)}): it cannot start to slide; "
        "re-solved with no slip",
    )


def _slide_from_rest(
    support: object, along: int, end: float | None, system: System
) -> Assumption | None:
    """A slide stated from rest over an interval of constant forces (impulse and momentum):
    the contact point's slip at the end, ``end``, must be along the stated sense ``along``;
    kinetic friction that would drive it the other way is friction pushing, so the scene is
    re-solved with no slip (and, with μs given, a slide from rest starts only if static
    friction cannot hold it)."""
    from dynsolve.model.scene import Support

    assert isinstance(support, Support)
    if end is None:
        return None
    name = f"sliding at {support.name}"
    if along * end > SENSE_TOLERANCE and support.mu_s is not None:
        return Assumption(
            name,
            False,
            "from rest, a slide starts only if static friction cannot hold the contact: "
            "re-solved with no slip to check |F| ≤ μs N",
        )
    if along * end > SENSE_TOLERANCE:
        return Assumption(
            name,
            True,
            f"from rest, its contact point slides that way, at "
            f"{with_unit(abs(end), 'velocity', system)} at the end "
            "of the interval (no mu_s: static friction is not checked)",
        )
    return Assumption(
        name,
        False,
        f"from rest, F = μk N opposing the slide would drive the contact point the other way "
        f"({with_unit(abs(end), 'velocity', system)} at the end of the interval): kinetic "
        "friction cannot push, so "
        "it cannot start to slide; re-solved with no slip",
    )


def _slip_sense(
    problem: SceneProblem,
    support: object,
    sense: int,
    substitution: Mapping[sympy.Symbol, sympy.Expr],
) -> Assumption:
    """After a failed no-slip trial: the contact point must slip against the friction."""
    from dynsolve.model.scene import Support

    assert isinstance(support, Support)
    name = f"slip at {support.name}"
    if support.friction_sense is not None and sense != support.friction_sense:
        return Assumption(
            name,
            False,
            "static friction cannot hold the contact, but it slips the other way than the "
            "stated 'slides'",
        )
    v, a = _contact_motion(problem, support, substitution)
    slip = v if v is not None and abs(v) > SENSE_TOLERANCE else a
    if slip is None:
        return Assumption(name, True, "no-slip failed; F = μk N opposing the slip")
    holds = -sense * slip >= -SENSE_TOLERANCE
    kind = "velocity" if slip is v else "acceleration"
    detail = (
        f"no-slip failed; F = μk N opposing the slip, and the contact point slips against it "
        f"(relative {kind} {with_unit(abs(slip), kind, problem.spec.system)})"
    )
    if not holds:
        detail = (
            "no-slip failed, but with F = μk N the contact point would slip along the "
            "friction, not against it: neither assumption holds"
        )
    return Assumption(name, holds, detail)


def _between_states(
    problem: SceneProblem, substitution: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Assumption, ...]:
    """What work–energy between two states assumes: the scene gets there, moving toward it,
    and its rolling contacts do not slip on the way."""
    checks: list[Assumption] = []

    def energy_text(value: float) -> str:
        return with_unit(value, "energy", problem.spec.system)

    for pivot in problem.scene.pivots:
        checks.append(
            Assumption(
                f"plastic impact at {pivot.name}",
                True,
                f"stated (e 0): {pivot.name} neither rebounds nor slides, so {pivot.body} "
                f"turns about {pivot.name} after the impact",
            )
        )
    for equation in problem.formulation.equations:
        if not equation.note.startswith("T1 + ΣU"):
            continue
        energy = real_value(equation.lhs, substitution)
        scale = sum(
            abs(real_value(t, substitution) or 0) for t in sympy.Add.make_args(equation.lhs)
        )
        if energy is None:
            continue
        tolerance = 1e-9 * max(scale, 1e-300)
        if any(t.stops for t in problem.scene.travels.values()):
            at_rest = abs(energy) <= tolerance
            detail = f"T2 = T1 + ΣU = {energy_text(0.0 if at_rest else energy)}"
            if not at_rest:
                detail += (
                    ": it still moves at state 2" if energy > 0 else ": it stops before state 2"
                )
            checks.append(Assumption("at rest in state 2", at_rest, detail))
            continue
        reaches = energy >= -tolerance
        checks.append(
            Assumption(
                "reaches state 2",
                reaches,
                f"T1 + ΣU = {energy_text(abs(energy) if reaches and energy <= 0 else energy)} "
                + ("≥ 0" if reaches else "< 0: it stops before state 2"),
            )
        )
    for support in problem.scene.supports:
        if support.kind == "rolls":
            checks.append(
                Assumption.undecided(
                    f"no slip at {support.name}",
                    "stated by 'rolls' for the whole travel; the friction it needs between "
                    "the states is not computed",
                )
            )
    if problem.scene.cords and len(problem.scene.travels) == 1:
        from dynsolve.principles.constant_motion import taut_details

        found = taut_details(problem.scene, problem.symbols, substitution, problem.spec.system)
        checks += [
            Assumption(name, holds, detail)
            if holds is not None
            else Assumption.undecided(name, detail)
            for name, holds, detail in found
        ]
    if any(t.stops for t in problem.scene.travels.values()):
        return tuple(checks)
    checks.append(
        Assumption(
            "sense of motion",
            True,
            "in state 2 the scene still moves toward it (speeds taken in the travel's sense)",
        )
    )
    return tuple(checks)


def _tipping(
    support: object,
    problem: SceneProblem,
    x: float | None,
    substitution: Mapping[sympy.Symbol, sympy.Expr],
) -> Assumption:
    from dynsolve.model.scene import Support

    assert isinstance(support, Support) and support.end is not None
    body = problem.scene.bodies[support.body]
    along = support.tangent
    foot = dot((body.G[0] - support.point[0], body.G[1] - support.point[1]), along)
    length = dot((support.end[0] - support.point[0], support.end[1] - support.point[1]), along)
    low, high = real_value(-foot, substitution), real_value(length - foot, substitution)
    if x is None or low is None or high is None:
        return Assumption.undecided(
            f"no tipping on base {support.name}",
            "cannot be decided: where N acts, or the base's ends, have no numeric value",
        )
    lo, hi = min(low, high), max(low, high)
    holds = lo <= x <= hi

    metres = with_unit(1.0, "length", problem.spec.system).split(" ", 1)[1]  # m, or ft
    detail = (
        f"N_{support.name} acts at x = {x:.4g} {metres} from G's line, within "
        f"[{lo:.4g}, {hi:.4g}] {metres}"
    )
    if not holds:
        detail = (
            f"N_{support.name} would act at x = {x:.4g} {metres}, outside the base "
            f"[{lo:.4g}, {hi:.4g}] {metres}: the body tips"
        )
    return Assumption(f"no tipping on base {support.name}", holds, detail)


def free_bodies(
    problem: SceneProblem, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[FreeBody, ...]:
    """Each body's free-body diagram as data, with solved magnitudes where known."""
    knowns = problem.system.knowns
    substitution = {**knowns, **values}
    system = problem.spec.system
    out: list[FreeBody] = []
    formulation = problem.formulation
    at_start = None if formulation.kinematics else _drawn_at_start(problem)
    if at_start is not None:  # work and energy of a rigid body: its forces in state 1
        formulation = at_start
    if not formulation.kinematics:  # an impact: no free-body diagrams to draw
        return ()
    for name, body in problem.scene.bodies.items():
        rows = []
        G = body.G
        for force in formulation.forces[name]:
            x = real_value(force.point[0] - G[0], substitution) or 0.0
            y = real_value(force.point[1] - G[1], substitution) or 0.0
            dx = real_value(force.direction[0], knowns) or 0.0
            dy = real_value(force.direction[1], knowns) or 0.0
            magnitude = real_value(force.magnitude, substitution)
            value = (
                format_quantity(abs(magnitude), natural_unit(Dim.of("force"), system))
                if magnitude is not None
                else ""
            )
            if magnitude is not None and magnitude < 0:
                dx, dy = -dx, -dy
            kind = force.kind
            if force.kind == "friction" and force.known:  # as the equations write it
                kind = f"friction = μk N_{force.name[2:]}"
            rows.append(
                ForceRow(
                    force.name,
                    kind,
                    force.point_name or "P",
                    x,
                    y,
                    direction_word(dx, dy),
                    dx,
                    dy,
                    force.known,
                    value,
                )
            )
        for couple in formulation.couples[name]:
            moment = real_value(couple.moment, substitution)
            sense = "ccw" if (moment or 0) >= 0 else "cw"
            value = (
                format_quantity(abs(moment), natural_unit(Dim.of("moment"), system))
                if moment is not None
                else ""
            )
            rows.append(
                ForceRow(couple.name, "couple", "G", 0.0, 0.0, sense, 0.0, 0.0, couple.known, value)
            )
        sizes = tuple(real_value(s, knowns) or 0.0 for s in body.sizes)
        kin = formulation.kinematics[name]
        motion = {
            "rotation": f"fixed-axis rotation about {kin.pin.name if kin.pin else 'O'}",
            "translation": "translation",
            "general": "general plane motion",
            "particle": "particle",
        }[kin.motion]
        if at_start is not None:
            motion += " (drawn in state 1: the forces whose work enters T1 + ΣU = T2)"
        elif name in formulation.axes:
            motion += f"; {formulation.axes[name]}"
        axes = None
        incline = formulation.inclines.get(name) if at_start is None else None
        if incline is not None:  # drawn where the slope has numbers
            found = [real_value(c, knowns) for c in (*incline.t, *incline.n)]
            floats = [v for v in found if v is not None]
            if len(floats) == 4:
                axes = ((floats[0], floats[1]), (floats[2], floats[3]))
        omega = real_value(kin.omega, knowns) if at_start is None else None
        out.append(
            FreeBody(
                name,
                body.shape,
                sizes,
                motion,
                tuple(rows),
                () if at_start is not None else formulation.kinetic.get(name, ()),
                "" if at_start is not None else formulation.moment_points.get(name, ""),
                axes,
                "" if not omega else ("ccw" if omega > 0 else "cw"),
                _parts_from_G(body, problem.scene, knowns),
            )
        )
    return tuple(out)


def _parts_from_G(body: Body, scene: Scene, knowns: Mapping) -> tuple[tuple, ...]:
    """A composite's parts for its free-body diagram, placed from G (metres); () where a
    size or place has no number."""
    from dynsolve.modes.scene_sketch import NoNumber, part_outlines

    if not body.parts:
        return ()
    try:
        parts = part_outlines(body, scene, knowns)
        gx, gy = (real_value(c, knowns) for c in body.G)
    except NoNumber:
        return ()
    if gx is None or gy is None:
        return ()
    return tuple((p[0], p[1] - gx, p[2] - gy, *p[3:]) for p in parts)


def _drawn_at_start(problem: SceneProblem) -> Formulation | None:
    """The forces of a rigid body's work-and-energy scene in state 1, for its free-body
    diagram only (nothing of it is solved); None for anything else or a scene that has no
    instant formulation."""
    from dynsolve.principles.newton_euler import formulate

    scene = problem.scene
    if not scene.travels or scene.impacts or scene.pivots or len(scene.events) > 1:
        return None
    try:
        return formulate(replace(scene, travels={}, events=()), problem.symbols)
    except (ValueError, SpecError, KeyError):  # a mechanism formulate does not take
        return None


def direction_word(dx: float, dy: float) -> str:
    """The direction of a vector in words: up, down, left, right, or its angle above or below
    the horizontal and its side, as a textbook states it.

    >>> direction_word(0.0, -1.0), direction_word(0.6, 0.8), direction_word(1e-36, 1e-20)
    ('down', '53.1° above the horizontal, to the right', 'up')
    >>> direction_word(-0.857, -0.515)
    '31.0° below the horizontal, to the left'
    """
    import math

    size = math.hypot(dx, dy)  # any length: the test is relative to it
    if size == 0:
        return ""
    if abs(dx) < 1e-12 * size:
        return "up" if dy > 0 else "down"
    if abs(dy) < 1e-12 * size:
        return "right" if dx > 0 else "left"
    elevation = math.degrees(math.atan2(abs(dy), abs(dx)))
    above = "above" if dy > 0 else "below"
    side = "right" if dx > 0 else "left"
    return f"{elevation:.1f}° {above} the horizontal, to the {side}"


def direction_of(kind: str, value: float, axis: tuple[float, float] | None = None) -> str:
    """The word for a signed value: cw/ccw for a rotation, up/down/… along an axis.

    >>> direction_of("rotation", -2.0), direction_of("along", -1.0, (0.0, 1.0))
    ('cw', 'down')
    """
    if kind == "rotation":
        return "" if value == 0 else ("ccw" if value > 0 else "cw")
    if kind == "along" and axis is not None:
        if value == 0:
            return ""
        sign = 1 if value > 0 else -1
        return direction_word(sign * axis[0], sign * axis[1])
    return ""


def _path_side(
    scene: Scene,
    support: Support,
    N: float,
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> tuple[Assumption, ...]:
    """Which way a curved path pushes its particle: a path takes either sign (a bead on a
    wire, a car in a track), but a road under the particle only pushes it up. Said in words
    whenever the path holds the particle down, so that a car too fast over a hump is not
    answered as if the road could pull it without a word."""
    if scene.gravity is None:
        return ()
    up = real_value(
        -(support.normal[0] * scene.gravity[0] + support.normal[1] * scene.gravity[1]), values
    )
    if up is None or N * up >= 0:
        return ()
    return (
        Assumption(
            f"path {support.name} holds {support.body} down",
            True,
            f"N_{support.name} = {with_unit(N, 'force', system)} pulls {support.body} down "
            "toward the path: a wire, a "
            "track, a tube or the inside of a loop can; a road or surface under it cannot — on "
            "one, it leaves the path (too fast for the curvature) and these answers do not hold",
        ),
    )
