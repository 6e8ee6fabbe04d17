"""A scene followed through its stages: each stage's principle, from the state the last one left.

Stage k runs from state k to state k + 1 (:mod:`dynsolve.model.stages`). A travel applies
work and energy (:mod:`dynsolve.principles.work_energy`) to the bodies it moves, starting
from their velocities at state k; an impact applies momentum and restitution
(:mod:`dynsolve.principles.impact`) to the velocities just before it; an eccentric impact
conserves angular momentum about the struck point, after which the body turns about it.
The unknowns of one stage (the speed at the end of a fall) enter the equations of the next
(the momentum before the impact), so the whole chain is one system, solved in order.

>>> import sympy
>>> from dynsolve.model.scene import Body, Impact, Scene, Travel
>>> m, g, h = sympy.symbols("m g h", positive=True)
>>> ball = Body("ball", m, sympy.Integer(0), (0, h), (0, h), "particle", (), {}, True, "", 0, 0)
>>> fall = Travel("ball", "by", distance=h, direction=(0, -1))
>>> bounce = Impact("ball", "ground", sympy.Rational(1, 2), (0, -1))
>>> scene = Scene({"ball": ball}, {}, (), (), (), (0, -1), {}, events=(fall, bounce))
>>> f = chain_formulation(scene, {"g": g}, {})
>>> solved = sympy.solve([e.residual for e in f.equations], list(f.unknowns), dict=True)
>>> sorted((s.name, v) for s, v in solved[-1].items())  # v₃ = e √(2 g h), up
[('v_2_ball', sqrt(2)*sqrt(g)*sqrt(h)), ('vn_3_ball', -sqrt(2)*sqrt(g)*sqrt(h)/2)]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace

import sympy
from sympy.core.assumptions import check_assumptions

from dynsolve.model.momentum_events import Clutch, Reshape
from dynsolve.model.scene import (
    Body,
    CordState,
    Impact,
    Link,
    Pivot,
    Scene,
    Support,
    Travel,
    Vec,
)
from dynsolve.model.stages import Slide, Stage, StageRecord, State, stages_of
from dynsolve.numbers import float_functions, real_value, tidy, tidying_lightly
from dynsolve.principles.newton_euler import (
    Formulation,
    bare_formulation,
    cross,
    dot,
    formulate,
)
from dynsolve.results import Assumption
from dynsolve.system import Constraint, Equation
from dynsolve.units import Dim, InSystem, with_unit

ZERO: Vec = (sympy.Integer(0), sympy.Integer(0))


class StageError(ValueError):
    """A stage that cannot be followed, with the line of its travel or impact."""

    def __init__(self, stage: Stage, message: str) -> None:
        super().__init__(message)
        event = stage.event
        self.line = event.stmt_line if isinstance(event, Impact) else event.line
        self.column = event.column


@dataclass(frozen=True)
class _Step:
    """What one stage adds: equations, unknowns, and the motion at its end."""

    equations: tuple[Equation, ...]
    unknowns: Mapping[sympy.Symbol, Dim]
    velocities: Mapping[str, Vec]  # v_G at the end, for the bodies the stage changed
    omegas: Mapping[str, sympy.Expr]
    record: StageRecord
    scene: Scene  # the scene's geometry and supports at the end of the stage
    second: tuple[tuple[sympy.Symbol, float, str, str], ...] = ()
    relations: tuple[str, ...] = ()
    relations_are: str = "kinematics"  # what the relations are, for their note's name
    constraints: tuple[Constraint, ...] = ()  # root branches (an until event's first zero)
    turn: tuple[str, sympy.Expr, sympy.Expr] | None = None  # (body, angle turned, rise of G)
    cords: tuple[CordState, ...] = ()  # elastic cords assumed taut (or slack) at its end
    speed: sympy.Expr | None = None  # |v_G| at its end where it is an unknown itself (until)


def chain_formulation(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    given_values: Mapping[sympy.Symbol, sympy.Expr],
    senses: Mapping[str, int] | None = None,
    instants: frozenset[int] = frozenset(),
) -> Formulation:
    """The equations of every stage of ``scene``, each starting where the last one ended.
    A load whose size is not given is an unknown of the travels that it works in (the
    average resistance that stops a pile). ``senses`` holds the friction senses that an
    earlier solve found for contacts sliding through an interval (``"C@3"``: at C in
    stage 3), where the first guess was contradicted. ``instants`` are the states whose
    reactions are asked (``cord(2)``): Newton–Euler at that instant, from the motion there."""
    loads = {
        load.name: sympy.Symbol(load.name, real=True)  # its sense: checked
        for load in scene.loads
        if load.name not in symbols
    }
    chain = _Chain(scene, {**symbols, **loads}, given_values, senses or {})
    states = [State(1, dict(chain.velocities), dict(chain.omegas))]
    equations: list[Equation] = []
    unknowns: dict[sympy.Symbol, Dim] = {}
    records: list[StageRecord] = []
    notes: list[tuple[str, str]] = []
    second: list[tuple[sympy.Symbol, float, str, str]] = []
    constraints: list[Constraint] = []
    cords: list[CordState] = []
    turns: dict[str, sympy.Expr] = {}
    heights: dict[str, sympy.Expr] = {}
    reactions: dict[str, tuple[sympy.Symbol, Vec]] = {}
    events: list[tuple[str, sympy.Expr, str]] = []
    named: dict[tuple[int, str], sympy.Expr] = {}  # (state, body): its speed, an unknown

    def instant(k: int) -> None:
        """Newton–Euler at state k, its unknowns named for the state (cord_2)."""
        found = chain.instant(k, first_stage)
        names = {s: chain.state_symbol(s, k) for s in found.unknowns}
        for equation in found.equations:
            number = len(equations) + 1
            lhs, rhs = equation.lhs.xreplace(names), equation.rhs.xreplace(names)
            note = f"state {k} (the instant): {equation.note}"
            equations.append(Equation(lhs, rhs, f"eq. {number}", number, note))
        unknowns.update({names[s]: d for s, d in found.unknowns.items()})
        for name, (symbol, axis) in found.reactions.items():
            reactions[f"{name}({k})"] = (names.get(symbol, symbol), axis)
        for what, force in chain.one_sided(found, k):
            events.append((what, force.xreplace(names), f"{{value:.4g force}} > 0 at state {k}"))

    stages = stages_of(scene.events)
    first_stage = stages[0] if stages else None
    if 1 in instants:
        instant(1)
    for stage in stages:
        step = chain.stage(stage)
        first = len(equations)
        for equation in step.equations:
            number = len(equations) + 1
            note = f"{stage.title}: {equation.note}"
            equations.append(Equation(equation.lhs, equation.rhs, f"eq. {number}", number, note))
        unknowns.update(step.unknowns)
        chain.advance(step)
        if stage is not stages[-1]:  # what it finds is read by the stages after it only
            chain.presolve(step)
        inertias = {n: b.I_G for n, b in chain.scene.bodies.items()}
        states.append(State(stage.number + 1, dict(chain.velocities), dict(chain.omegas), inertias))
        records.append(replace(step.record, equations=tuple(range(first, len(equations)))))
        if stage.number + 1 in instants:
            first_stage = stage
            instant(stage.number + 1)
        second += step.second
        constraints += step.constraints
        cords += step.cords
        if step.turn is not None:
            body, turns[body], heights[body] = step.turn
        if step.speed is not None:
            named.update({(stage.number + 1, n): step.speed for n in step.record.bodies})
        if step.relations:
            notes.append(
                (f"{step.relations_are} in stage {stage.number}", "; ".join(step.relations))
            )
    used = set().union(*(e.lhs.free_symbols | e.rhs.free_symbols for e in equations))
    for load in scene.loads:
        if loads.get(load.name) in used:
            unknowns[loads[load.name]] = Dim.of("force" if load.kind == "force" else "moment")
    notes.insert(0, ("stages", "; ".join(r.stage.title for r in records)))
    notes += [(f"together after stage {k}", text) for k, text in chain.joined_notes]
    return bare_formulation(
        scene.bodies,
        equations=tuple(equations),
        unknowns=unknowns,
        after=_after(records, states),
        after_omega={
            r.bodies[-1]: states[r.stage.number].omegas[r.bodies[-1]]
            for r in records
            if isinstance(r.stage.event, Pivot) or r.pin
        }
        | {
            name: states[r.stage.number].omegas[name]
            for r in records
            if isinstance(r.stage.event, Clutch | Reshape)
            for name in r.bodies
        },
        speeds=_after_travels(
            records, states, lambda s, n: named.get((s.number, n)) or _speed(s, n)
        ),
        turns=turns,
        heights=heights,
        constraints=tuple(constraints),
        cords=tuple(cords),
        reactions=reactions,
        events=tuple(events),
        spins=_after_travels(records, states, lambda s, n: s.omegas[n]),
        notes=tuple(notes),
        second=tuple(second),
        states=tuple(states),
        stages=tuple(records),
        displacements=dict(chain.displacements),
    )


def _speed(state: State, body: str) -> sympy.Expr:
    """|v_G| of ``body`` at ``state``, tidied (an answer's formula)."""
    return tidy(sympy.sqrt(dot(*[state.velocities[body]] * 2)), light=False)


def _after_travels(
    records: list[StageRecord], states: list[State], read: Callable[[State, str], sympy.Expr]
) -> dict[str, sympy.Expr]:
    """A quantity of each body at the end of the last travel that moves it (speed(B))."""
    found: dict[str, sympy.Expr] = {}
    for record in records:
        if isinstance(record.stage.event, Travel):
            for body in record.bodies:
                found[body] = read(states[record.stage.number], body)
    return found


def _after(records: list[StageRecord], states: list[State]) -> dict[str, Vec]:
    """Each body's velocity just after the last impact it takes part in."""
    after: dict[str, Vec] = {}
    for record in records:
        event = record.stage.event
        if isinstance(event, Impact) or (isinstance(event, Pivot) and event.normal is not None):
            for body in record.bodies:
                after[body] = states[record.stage.number].velocities[body]
    return after


class _Chain:
    """The scene as the stages leave it: geometry, velocities, and what moves together."""

    def __init__(
        self,
        scene: Scene,
        symbols: Mapping[str, sympy.Expr],
        values: Mapping[sympy.Symbol, sympy.Expr],
        senses: Mapping[str, int],
    ) -> None:
        self.scene = replace(scene, travels={}, impacts=(), pivots=(), events=())
        self.start = self.scene  # the scene as written (links and springs stay drawn there)
        self.symbols, self.values, self.senses = symbols, values, senses
        self.known: dict[sympy.Symbol, sympy.Expr] = dict(values)  # givens, then each stage's
        self.reaction_names: set[str] = set()  # average reactions named by earlier intervals
        self.velocities = {name: scene.velocities.get(name, ZERO) for name in scene.bodies}
        self.omegas = {n: sympy.Integer(0) + scene.omegas.get(n, 0) for n in scene.bodies}
        for pin in scene.supports:  # a pinned body given its spin: G turns about the pin
            if pin.kind == "pin" and pin.body not in scene.velocities:
                G, w = scene.bodies[pin.body].G, self.omegas[pin.body]
                r = (G[0] - pin.point[0], G[1] - pin.point[1])
                self.velocities[pin.body] = (tidy(-w * r[1]), tidy(w * r[0]))
        self.unfollowed: set[str] = set()  # bodies whose geometry is no longer followed
        self.together: dict[str, frozenset[str]] = {n: frozenset((n,)) for n in scene.bodies}
        self.joined_notes: list[tuple[int, str]] = []
        self.places: dict[str, Vec] = {}  # G of a particle on a link, after a travel
        self.displacements: dict[str, Vec] = {}  # Δr_G over each body's last interval

    def stage(self, stage: Stage) -> _Step:
        event = stage.event
        if isinstance(event, Impact):
            return self.impact(stage, event)
        if isinstance(event, Clutch | Reshape):
            return self.spin(stage, event)
        followed = event.body in self.places and getattr(event, "kind", "") == "until"
        if event.body in self.unfollowed and not followed:  # a bob's place is followed
            raise StageError(
                stage,
                f"{stage.title}: where {event.body} is after an earlier stage is not followed "
                "(only a particle's position is); describe this part as a scene of its own",
            )
        if isinstance(event, Pivot) and event.normal is not None:
            return self.rebound(stage, event)
        if isinstance(event, Pivot):
            return self.pivot(stage, event)
        if event.kind == "until":
            return self.until(stage, event)
        if event.kind == "for":
            return self.interval(stage, event)
        return self.travel(stage, event)

    def advance(self, step: _Step) -> None:
        """Move on to the state at the end of ``step``."""
        self.velocities.update(step.velocities)
        self.omegas.update(step.omegas)
        self.scene = step.scene

    def presolve(self, step: _Step) -> None:
        """Solve one stage's equations for its own unknowns, from what the stages before
        found: the motion at the start of the next stage, for the sense of a slide (a
        guess when the stage has several roots or none; the full solve decides)."""
        if not step.unknowns:
            return
        equations = [float_functions(e.residual.xreplace(self.known)) for e in step.equations]
        if any(e.free_symbols - set(step.unknowns) for e in equations):
            return  # it depends on a later stage (an unknown extent) or on loads
        # numeric mode: without sympy's simplify of every root (half the time here): the
        # same roots, tidied below; they are numbers, read only for the senses and signs
        simplify = not tidying_lightly()
        roots = _polynomial_roots(equations, list(step.unknowns)) if not simplify else None
        try:
            if roots is None:
                roots = sympy.solve(equations, list(step.unknowns), dict=True, simplify=simplify)
        except (NotImplementedError, ValueError):  # pragma: no cover - sympy's own limits
            return
        if len(roots) > 1:  # as the solve does: a rate entering only squared is taken ≥ 0
            roots = [r for r in roots if all((0 + v).is_nonnegative for v in r.values())]
        if len(roots) == 1 and set(roots[0]) == set(step.unknowns):
            self.known.update({s: tidy(v, light=False) for s, v in roots[0].items()})

    def interval(self, stage: Stage, travel: Travel) -> _Step:
        """Impulse and momentum over an interval of constant forces (``for Δt``, with
        ``stops`` or ``until rolls``), from the motion the last stage left. A rough contact
        slides through it: its kinetic friction opposes the slip at the start, whose sign
        is known from the stages before (or guessed, then checked and re-solved)."""
        from dynsolve.principles.impulse_momentum import impulse_formulation
        from dynsolve.principles.until import contact_slip

        scene, body = self.scene, travel.body
        part = self.lone_part(stage, travel, "an interval")
        riders = part - {body}
        model = scene.bodies[body]
        if riders:
            mass = model.mass + sum(scene.bodies[n].mass for n in riders)
            model = replace(model, mass=tidy(mass))
        v_1, omega_1 = self.velocities[body], self.omegas[body]
        supports = tuple(s for s in scene.supports if s.body == body)
        slides, senses = [], {}
        for support in supports:
            if support.kind not in ("contact", "base") or support.smooth:
                continue
            slip = contact_slip(model, support, v_1, omega_1)
            sense, guessed = self.friction_sense(stage, support, slip)
            senses[support.name] = sense
            slides.append((support, sense, slip, guessed))
        sub = replace(
            scene,
            bodies={body: model},
            supports=supports,
            loads=tuple(load for load in scene.loads if load.body in part),
            links=(),
            springs=(),
            cords=(),
            velocities={body: v_1},
            omegas={body: omega_1},
            travels={body: travel},
        )
        try:
            found = impulse_formulation(sub, self.symbols, senses)
        except ValueError as exc:
            raise StageError(stage, f"{stage.title}: {exc}") from None
        k = stage.number
        names: dict[sympy.Symbol, sympy.Symbol] = {}
        for symbol in found.unknowns:
            if symbol.name.startswith(("v_2", "omega_2")):
                prefix, _, axis = symbol.name.partition("_2")
                names[symbol] = sympy.Symbol(
                    f"{prefix}_{k + 1}{axis}_{body}", **symbol.assumptions0
                )
        for reaction, (symbol, _) in found.reactions.items():
            if reaction in self.reaction_names:  # a second interval on the same contact
                names[symbol] = sympy.Symbol(f"{symbol.name}_{k}", **symbol.assumptions0)
            self.reaction_names.add(reaction)
        equations = tuple(
            replace(e, lhs=e.lhs.xreplace(names), rhs=e.rhs.xreplace(names))
            for e in found.equations
        )
        v_2 = tuple(tidy(c.xreplace(names)) for c in found.after[body])
        omega_2 = tidy(found.spins[body].xreplace(names))
        shift = tuple(tidy(c.xreplace(names)) for c in found.displacements[body])
        self.displacements[body] = shift  # type: ignore[assignment]
        assert found.interval_energy is not None
        T_k, works, T_next = found.interval_energy
        works = {n: tidy(u.xreplace(names)) for n, u in works.items()}
        record = StageRecord(
            stage,
            tuple(sorted(part)),
            works,
            stops=travel.stops,
            energy=(tidy(T_k.xreplace(names)), works, tidy(T_next.xreplace(names))),
            slides=tuple(
                Slide(s.name, sense, slip, contact_slip(model, s, v_2, omega_2), guessed)
                for s, sense, slip, guessed in slides
            ),
            normals=tuple(
                (f"N_{s.name}", found.reactions[f"N_{s.name}"][0].xreplace(names))
                for s in supports
                if f"N_{s.name}" in found.reactions and not s.two_sided
            ),
            events=found.events,
        )
        relations = tuple(text for _, text in found.notes[1:])
        return _Step(
            equations,
            {names.get(s, s): d for s, d in found.unknowns.items()},
            {n: v_2 for n in part},  # type: ignore[misc]
            {body: omega_2, **{n: sympy.Integer(0) for n in riders}},
            record,
            self.shifted(part, shift),  # type: ignore[arg-type]
            relations=relations,
            relations_are="over the interval",
        )

    def instant(self, k: int, stage: Stage | None) -> Formulation:
        """Newton–Euler for the scene at state k: each body where the stages leave it,
        moving as they leave it (a plastic impact's bodies as one)."""
        from dynsolve.principles.newton_euler import formulate

        scene = self.scene
        bodies, loads = dict(scene.bodies), list(scene.loads)
        for name in self.unfollowed:
            body = bodies[name]
            if name not in self.places or not body.particle:
                raise StageError(
                    stage,  # type: ignore[arg-type]
                    f"the reactions at state {k} need where {name} is there, which is not "
                    "followed after a travel (only a particle's place is)",
                )
            shift = (self.places[name][0] - body.G[0], self.places[name][1] - body.G[1])
            bodies[name] = _carried(body, shift)
        for name, group in self.together.items():
            riders = sorted(group - {name})
            if len(group) > 1 and name == min(group):  # the group moves as its first body
                mass = bodies[name].mass + sum(scene.bodies[n].mass for n in riders)
                bodies[name] = replace(bodies[name], mass=tidy(mass))
                for rider in riders:
                    del bodies[rider]
                loads = [replace(ld, body=name) if ld.body in riders else ld for ld in loads]

        # links and springs are drawn in the scene as written: carry their ends with G
        start = self.start.bodies
        shifts = {n: (b.G[0] - start[n].G[0], b.G[1] - start[n].G[1]) for n, b in bodies.items()}

        def carried(body: str, point: Vec | None) -> Vec | None:
            return point if point is None or body not in shifts else _plus(point, shifts[body])

        sub = replace(
            scene,
            bodies=bodies,
            loads=tuple(loads),
            links=tuple(
                replace(
                    link,
                    point=carried(link.body, link.point),
                    other_point=carried(link.other, link.other_point),
                )
                for link in self.start.links
            ),
            springs=tuple(
                replace(
                    s, point=carried(s.body, s.point), other_point=carried(s.other, s.other_point)
                )
                for s in self.start.springs
            ),
            velocities={
                n: tuple(sympy.Integer(0) + c for c in v)
                for n, v in self.velocities.items()
                if n in bodies and not _still(v, 0)
            },
            omegas={n: w for n, w in self.omegas.items() if n in bodies and not _still(ZERO, w)},
        )
        try:
            return formulate(sub, self.symbols)  # type: ignore[arg-type]
        except ValueError as exc:
            raise StageError(stage, f"at state {k}: {exc}") from None  # type: ignore[arg-type]

    def state_symbol(self, symbol: sympy.Symbol, k: int) -> sympy.Symbol:
        """An unknown of the instant at state k, named for it (cord → cord_2)."""
        name = f"{symbol.name}_{k}"
        while name in self.symbols:
            name += "_"
        return sympy.Symbol(name, **symbol.assumptions0)

    def one_sided(self, found: Formulation, k: int) -> list[tuple[str, sympy.Expr]]:
        """The forces of the instant at state k that can only pull or push (cords and
        tension-only links are taut, contacts press): checked positive."""
        checks = [
            (f"cord {c.name} taut at state {k}", found.reactions[c.name][0])
            for c in self.scene.cords
            if c.name in found.reactions
        ]
        for support in self.scene.supports:
            normal = found.reactions.get(f"N_{support.name}")
            if normal is not None and not support.two_sided:
                checks.append((f"contact at {support.name} kept at state {k}", normal[0]))
        return checks

    def lone_part(self, stage: Stage, travel: Travel, what: str) -> set[str]:
        """The body a stage follows alone, with what a plastic impact stuck to it; refused
        when another body still moves (as the stages before leave it) or is joined to it."""
        body = travel.body
        part = {body} | self.together[body]
        for name in self.scene.bodies:
            v, w = self.velocities[name], self.omegas[name]
            if name not in part and not _still(
                tuple(c.xreplace(self.known) for c in v),  # type: ignore[arg-type]
                (sympy.Integer(0) + w).xreplace(self.known),
            ):
                raise StageError(
                    stage,
                    f"{stage.title}: {name} is still moving (as the stages before leave it) "
                    f"but takes no part in the stage; {what} in a chain follows one body while "
                    "the others are at rest",
                )
        joined = _joined(self.scene, body) - part
        if travel.kind == "until":  # the cord that goes slack is the particle's own
            joined -= {link.other for link in self.scene.links if link.body == body}
        if joined:
            raise StageError(
                stage,
                f"{stage.title}: {body} is joined to {', '.join(sorted(joined))}; {what} "
                "in a chain follows one body (and what a plastic impact stuck to it)",
            )
        return part

    def until(self, stage: Stage, travel: Travel) -> _Step:
        """A particle on a circle until its cord goes slack or it leaves its surface, from
        the motion the stage before left: work and energy with ΣF_n = m v²/R where the
        force is zero. The root's branch (the first zero after the start) is found from
        the numbers the stages before give."""
        from dynsolve.principles.until import UntilError, circle_until

        scene, body = self.scene, travel.body
        part = self.lone_part(stage, travel, f"'until {travel.until}'")
        riders = part - {body}
        model = scene.bodies[body]
        if not model.particle:
            raise StageError(stage, f"{stage.title}: 'until {travel.until}' is for a particle")
        shift = (sympy.Integer(0),) * 2
        if body in self.places:  # a bob that swung: its place, not its drawing
            shift = (self.places[body][0] - model.G[0], self.places[body][1] - model.G[1])
        mass = tidy(model.mass + sum(scene.bodies[n].mass for n in riders))
        model = replace(_carried(model, shift), mass=mass)
        held = [s.name for s in scene.supports if s.body in part]
        if held:
            raise StageError(
                stage,
                f"{stage.title}: {body} moves on its cord or path only until the event; its "
                f"support {', '.join(held)} would act too (leave it out of the scene)",
            )
        sub = replace(
            scene,
            bodies={body: model},
            supports=(),
            loads=tuple(replace(load, body=body) for load in scene.loads if load.body in part),
            links=tuple(
                replace(link, point=_plus(link.point, shift))
                for link in scene.links
                if link.body == body and not link.other
            ),
            springs=tuple(s for s in scene.springs if {s.body, s.other} & part),
            cords=(),
            velocities={body: self.velocities[body]},
            omegas={},
            travels={body: travel},
            values=self.known,
        )
        try:
            found = circle_until(sub, self.symbols, travel, stage.number + 1)
        except UntilError as exc:
            raise StageError(stage, f"{stage.title}: {exc}") from None
        record = StageRecord(stage, tuple(sorted(part)), {}, events=found.events, scene=sub)
        return _Step(
            found.equations,
            {found.speed: Dim(1, 0, -1), found.theta: Dim()},
            {n: found.velocity for n in part},
            {n: sympy.Integer(0) for n in part},
            record,
            scene,
            relations=(found.note[1],),
            relations_are=found.note[0],
            constraints=(found.condition,),
            turn=(body, found.theta, found.height),
            speed=found.speed,
        )

    def friction_sense(self, stage: Stage, support: Support, slip: sympy.Expr) -> tuple[int, bool]:
        """The sense of kinetic friction at a contact sliding through an interval, against
        the slip at its start; whether it was guessed (the start not known before solving)."""
        key = f"{support.name}@{stage.number}"
        if key in self.senses:
            return self.senses[key], False
        value = real_value(slip, self.known)
        start = tidy(slip.xreplace(self.known))
        if value is None and start.is_positive is not None:
            value = 1.0 if start.is_positive else (-1.0 if start.is_negative else None)
        if value == 0:
            raise StageError(
                stage,
                f"{stage.title}: {support.body} does not slide at {support.name} at the start "
                "of the interval; static friction over an interval in a chain is not followed",
            )
        if value is not None:
            return (-1 if value > 0 else 1), False
        if stage.number == 1 and support.friction_sense is not None:
            return support.friction_sense, False
        return -1, True  # assumed sliding along the tangent; checked once solved

    def shifted(self, part: set[str], shift: Vec) -> Scene:
        """The scene after an interval: the bodies that moved, and their contacts, carried
        by Δr_G (the contacts stay where they were on each body: the forces are constant)."""
        scene = self.scene
        bodies = dict(scene.bodies)
        for name in part:
            bodies[name] = _carried(bodies[name], shift)
        supports = tuple(
            replace(s, point=_plus(s.point, shift)) if s.body in part else s for s in scene.supports
        )
        springs = _springs_carried(scene, part, shift)
        return replace(scene, bodies=bodies, supports=supports, springs=springs)

    def impact(self, stage: Stage, impact: Impact) -> _Step:
        from dynsolve.principles.impact import impact_equations, velocity_after

        if self.pin_of(impact.other) is not None or self.pin_of(impact.body) is not None:
            return self.pinned(stage, impact)
        self.check_impulses(stage, impact)
        masses = {name: body.mass for name, body in self.scene.bodies.items()}
        equations, along = impact_equations(impact, masses, self.velocities)
        names = {s: _renamed(s, "vn", stage.number + 1, body) for body, s in along.items()}
        equations = tuple(
            replace(e, lhs=e.lhs.xreplace(names), rhs=e.rhs.xreplace(names)) for e in equations
        )
        after = {
            body: velocity_after(impact, body, names[symbol], self.velocities)
            for body, symbol in along.items()
        }
        if len(after) == 2 and tidy(impact.e) == 0:
            self.stick(stage, impact)
        return _Step(
            equations,
            {names[s]: Dim.of("velocity") for s in along.values()},
            after,
            {},
            StageRecord(stage, tuple(along), approach=self.approach(impact)),
            self.scene,
        )

    def pin_of(self, name: str) -> Support | None:
        """The pin a rigid body turns about, if it is pinned."""
        body = self.scene.bodies.get(name)
        if body is None or body.particle:
            return None
        return next((s for s in self.scene.supports if s.body == name and s.kind == "pin"), None)

    def pinned(self, stage: Stage, impact: Impact) -> _Step:
        """A particle striking a body that turns about a pin: angular momentum of the two
        about the pin conserved, with restitution along the line (embedded when e = 0)."""
        from dynsolve.principles.angular_momentum import pinned_impact

        scene = self.scene
        if self.pin_of(impact.body) is not None:  # the pinned body strikes the particle
            impact = replace(
                impact,
                body=impact.other,
                other=impact.body,
                line=(-impact.line[0], -impact.line[1]),
            )
        A, B = impact.body, impact.other
        pin = self.pin_of(B)
        if pin is None or A not in scene.bodies or not scene.bodies[A].particle:
            raise StageError(
                stage,
                f"{stage.title}: an impact on a pinned body is supported with a particle "
                "(placed where it strikes) on the other side",
            )
        moved = sorted({A, B} & self.unfollowed)
        if moved:
            raise StageError(
                stage,
                f"{stage.title}: where {' and '.join(moved)} is after an earlier stage is not "
                "followed (only a particle's position is); describe the impact as a scene of "
                "its own, from the motion just before it",
            )
        riders = sorted(self.together[A] - {A})
        if riders:
            raise StageError(
                stage,
                f"{stage.title}: {A} moves with {', '.join(riders)} since a plastic impact; "
                "describe the particle that strikes as one body",
            )
        held = [s.name for s in scene.supports if s.body == A]
        held += [k.name for k in scene.links if A in (k.body, k.other)]
        held += [s.name for s in scene.supports if s.body == B and s is not pin]
        held += [k.name for k in scene.links if B in (k.body, k.other)]
        if held:
            raise StageError(
                stage,
                f"{stage.title}: {', '.join(held)} would take part in the impulse; a particle "
                "striking a pinned body is supported with the pin the only support",
            )
        r_G = (scene.bodies[B].G[0] - pin.point[0], scene.bodies[B].G[1] - pin.point[1])
        w_1 = self.omegas[B]
        v_B = self.velocities[B]
        spun = (-w_1 * r_G[1], w_1 * r_G[0])
        if tidy(v_B[0] - spun[0]) != 0 or tidy(v_B[1] - spun[1]) != 0:
            raise StageError(
                stage,
                f"{stage.title}: {B} turns about the pin {pin.name}; give its motion before "
                f"the impact as 'omega {B}: …' (its G then moves with ω k × r_G/{pin.name})",
            )
        found = pinned_impact(
            impact, scene.bodies[A], scene.bodies[B], (pin.name, pin.point), self.velocities,
            w_1, stage.number + 1, real_value(impact.e, self.values) == 0,
        )  # fmt: skip
        self.unfollowed |= {A, B}  # where they are afterwards is not followed
        checks = (
            ("approach", found.approach),
            ("separation", found.separation),
            ("lost", found.lost),
            ("energy", found.energy),
        ) + ((("reach", found.reach),) if found.reach is not None else ())
        return _Step(
            found.equations,
            found.unknowns,
            found.velocities,
            {B: found.omega},
            StageRecord(stage, (A, B), pin=pin.name, pinned=checks),
            scene,
        )

    def spin(self, stage: Stage, event: Clutch | Reshape) -> _Step:
        """A clutch locking two rotors on one axis, or a body changing its inertia: angular
        momentum about the axis (the pin, or G of a free body) kept."""
        from dynsolve.principles.angular_momentum import clutch, reshape

        scene = self.scene
        names = (event.body, event.other) if isinstance(event, Clutch) else (event.body,)
        moved = sorted(set(names) & self.unfollowed)
        if moved:
            raise StageError(
                stage,
                f"{stage.title}: where {' and '.join(moved)} is after an earlier stage is not "
                "followed; describe this part as a scene of its own",
            )
        for name in names:
            held = [s.name for s in scene.supports if s.body == name and s.kind != "pin"]
            held += [k.name for k in scene.links if name in (k.body, k.other)]
            held += [c.name for c in scene.cords if name in (c.body, c.other)]
            held += [s.name for s in scene.springs if name in (s.body, s.other)]
            held += [load.name for load in scene.loads if load.body == name]
            if held:
                raise StageError(
                    stage,
                    f"{stage.title}: {', '.join(held)} on {name} would change its angular "
                    "momentum; this stage is supported with a pin the only support and no load",
                )
        pins = [self.pin_of(name) for name in names]
        if isinstance(event, Clutch):
            A, B = pins
            if (
                A is None
                or B is None
                or tidy(A.point[0] - B.point[0]) != 0
                or (tidy(A.point[1] - B.point[1]) != 0)
            ):
                raise StageError(
                    stage,
                    f"{stage.title}: a clutch locks two rotors on one axis: pin both at the "
                    "same point ('pin A at O', 'pin B at O')",
                )
            bodies = (scene.bodies[event.body], scene.bodies[event.other])
            w = (self.omegas[event.body], self.omegas[event.other])
            axis = scene.point_names.get(A.point, A.name)  # O, not the pins' O_A and O_B
            found = clutch(bodies, (axis, A.point), w, stage.number + 1)
            omegas = dict.fromkeys(names, found.omega)
        else:
            (pin,) = pins
            if pin is not None and scene.gravity is not None:
                G = scene.bodies[event.body].G
                if tidy(G[0] - pin.point[0]) != 0 or tidy(G[1] - pin.point[1]) != 0:
                    raise StageError(
                        stage,
                        f"{stage.title}: the weight of {event.body} has a moment about the pin "
                        f"{pin.name} while it changes its inertia",
                    )
            body = scene.bodies[event.body]
            place = (pin.name, pin.point) if pin is not None else None
            found = reshape(
                body, event.I_G, place, self.velocities[event.body], self.omegas[event.body],
                stage.number + 1,
            )  # fmt: skip
            omegas = {event.body: found.omega}
            scene = replace(
                scene, bodies={**scene.bodies, event.body: replace(body, I_G=event.I_G)}
            )
        checks = (("lost", found.lost), ("energy", found.energy))
        return _Step(
            (found.equation,),
            {found.omega: Dim(0, 0, -1)},
            found.velocities,
            omegas,
            StageRecord(stage, names, pinned=checks),
            scene,
        )

    def approach(self, impact: Impact) -> sympy.Expr:
        """(v_A − v_B)·n just before the impact: positive when A closes on B along the line
        (for the ground, either sense of the line is allowed: only its size counts)."""
        v_A = self.velocities[impact.body]
        v_B = self.velocities.get(impact.other, ZERO)
        closing = tidy(dot((v_A[0] - v_B[0], v_A[1] - v_B[1]), impact.line))
        return closing if impact.other in self.scene.bodies else sympy.Abs(closing)

    def check_impulses(self, stage: Stage, impact: Impact) -> None:
        """An impact along a line is that of particles (or translating bodies) whose supports
        and links give no impulse along it: refuse a body turning about a pin, a support
        whose normal has a part along the line, or a link along it."""
        scene, n = self.scene, impact.line
        for name in (impact.body, impact.other):
            if name not in scene.bodies:
                continue  # the ground
            body = scene.bodies[name]
            pinned = any(s.body == name and s.kind == "pin" for s in scene.supports)
            if not body.particle and (pinned or tidy(self.omegas[name]) != 0):
                raise StageError(
                    stage,
                    f"{stage.title}: {name} turns at the impact; an impact along a line is "
                    "supported for particles and translating bodies",
                )
            for support in scene.supports:
                if support.body == name and tidy(dot(support.normal, n)) != 0:
                    raise StageError(
                        stage,
                        f"{stage.title}: the support {support.name} of {name} pushes along the "
                        "line of impact, so it would take part in the impulse",
                    )
            for link in scene.links:
                if name not in (link.body, link.other):
                    continue
                place = self.places.get(name, body.G)
                P = _plus(place, (link.point[0] - body.G[0], link.point[1] - body.G[1]))
                along = (P[0] - link.other_point[0], P[1] - link.other_point[1])
                if link.other or tidy(dot(along, n)) != 0:
                    raise StageError(
                        stage,
                        f"{stage.title}: the link {link.name} on {name} is not across the line "
                        "of impact, so it would take part in the impulse",
                    )

    def stick(self, stage: Stage, impact: Impact) -> None:
        """After a plastic impact (equal components along the line) with equal components
        across it too, two particles move on as one (a ram and the pile it drives): later
        travels carry both."""
        A, B = impact.body, impact.other
        across = (-impact.line[1], impact.line[0])
        v_A, v_B = self.velocities[A], self.velocities[B]
        same = tidy(dot(v_A, across) - dot(v_B, across)) == 0
        if not same or not all(self.scene.bodies[n].particle for n in (A, B)):
            return
        group = self.together[A] | self.together[B]
        for name in group:
            self.together[name] = group
        self.joined_notes.append(
            (stage.number, f"the plastic impact leaves {' and '.join(sorted(group))} with one "
             "velocity: they move on together (their masses add in later travels)")
        )  # fmt: skip

    def pivot(self, stage: Stage, pivot: Pivot) -> _Step:
        """An eccentric plastic impact; afterwards the body is pinned at the struck point."""
        from dynsolve.model.scene import WORDS
        from dynsolve.principles.impact import pivot_formulation

        body, scene = pivot.body, self.scene
        struck = replace(
            scene,
            velocities={body: self.velocities[body]},
            omegas={body: self.omegas[body]},
            pivots=(pivot,),
        )
        found = pivot_formulation(struck, self.values)
        (old,) = found.unknowns
        omega = _renamed(old, "omega", stage.number + 1, body)
        (equation,) = found.equations
        equation = replace(equation, rhs=equation.rhs.xreplace({old: omega}))
        spin = found.after_omega[body].xreplace({old: omega})
        G = scene.bodies[body].G
        r = (G[0] - pivot.point[0], G[1] - pivot.point[1])
        pin = Support("pin", pivot.name, body, pivot.point, WORDS["up"], line=pivot.line)
        supports = (*(s for s in scene.supports if s.body != body), pin)
        return _Step(
            (equation,),
            {omega: Dim(0, 0, -1)},
            {body: (tidy(-spin * r[1]), tidy(spin * r[0]))},  # v_G = ω k × r_G/P
            {body: spin},
            StageRecord(stage, (body,)),
            replace(scene, supports=supports),
        )

    def rebound(self, stage: Stage, pivot: Pivot) -> _Step:
        """A body striking a fixed point with restitution e, from the motion the stage
        before left: linear and angular impulse and momentum with the impulse J at the
        point, and e along the line; afterwards the body is free (not pinned)."""
        from dynsolve.principles.impact import rebound_formulation

        body, scene = pivot.body, self.scene
        self.lone_part(stage, Travel(body, "rebound"), "a rebound off a point")
        held = [s.name for s in scene.supports if s.body == body]
        if held or any(body in (link.body, link.other) for link in scene.links):
            raise StageError(
                stage,
                f"{stage.title}: {body} is held ({', '.join(held) or 'a link'}) and would take "
                "part in the impulse; a rebound off a point is of a body in free flight",
            )
        struck = replace(
            scene,
            velocities={body: self.velocities[body]},
            omegas={body: self.omegas[body]},
            pivots=(pivot,),
        )
        found = rebound_formulation(struck)
        k = stage.number
        names = {}
        for symbol in found.unknowns:
            prefix, _, rest = symbol.name.partition("_2")
            if symbol.name.startswith(("v_2", "omega_2")):
                names[symbol] = sympy.Symbol(f"{prefix}_{k + 1}{rest}", **symbol.assumptions0)
            elif symbol.name in self.reaction_names:  # the same point struck again
                names[symbol] = sympy.Symbol(f"{symbol.name}_{k}", **symbol.assumptions0)
            self.reaction_names.add(names.get(symbol, symbol).name)
        equations = tuple(
            replace(e, lhs=e.lhs.xreplace(names), rhs=e.rhs.xreplace(names))
            for e in found.equations
        )
        v_2 = tuple(c.xreplace(names) for c in found.after[body])
        return _Step(
            equations,
            {names.get(s, s): d for s, d in found.unknowns.items()},
            {body: v_2},  # type: ignore[dict-item]
            {body: found.after_omega[body].xreplace(names)},
            StageRecord(stage, (body,), events=found.events),
            scene,
        )

    def travel(self, stage: Stage, travel: Travel) -> _Step:
        """Work and energy for the bodies the travel moves: those joined to its body, or
        moving with it since a plastic impact."""
        from dynsolve.principles.work_energy import energy_equations

        scene, body = self.scene, travel.body
        link = next((k for k in scene.links if k.name == body), None)
        if body not in scene.bodies and link is not None:  # 'travel cord: turns …': its body
            body = link.body
        riders = self.together[body] - {body}  # carried along since a plastic impact
        part = _joined(scene, body) | riders
        for name in scene.bodies:
            if name not in part and not _still(self.velocities[name], self.omegas[name]):
                raise StageError(
                    stage,
                    f"{stage.title}: {name} is moving but takes no part in the travel; "
                    "give it its own stage or join it to the travelling body",
                )
        links = tuple(link for link in scene.links if {link.body, link.other} & part)
        translates = (
            scene.motions.get(body) == "translation"
            and not any(s.body == body for s in scene.supports)
            and _still(ZERO, self.omegas[body])
        )  # a body in free flight that does not turn: it moves as its G does
        lone = (
            (len(part) - len(riders)) == 1
            and (scene.bodies[body].particle or translates)
            and not links
        )
        if riders and not scene.bodies[body].particle:  # a plastic impact sticks particles
            raise StageError(
                stage,
                f"{stage.title}: {body} carries {', '.join(sorted(riders))} since a plastic "
                "impact; bodies moving together are followed as one particle only",
            )
        start_along = None
        if lone and travel.kind in ("to", "by"):
            start_along = _check_straight(stage, travel, scene, self.velocities[body])
        sub = self.moving_part(part, riders, body, links)
        if translates:  # its energy is that of its mass at G: ½ m v_G², W·Δr_G
            sub = replace(sub, bodies={body: replace(sub.bodies[body], particle=True)})
        # the start's unknowns (v_2_B from a travel before) hidden from the new stage's
        # own rate, which work and energy names v_2_B too, until it is renamed v_{k+1}_B
        starts = {s for v in sub.velocities.values() for c in v for s in (0 + c).free_symbols}
        starts |= {s for w in sub.omegas.values() for s in (0 + w).free_symbols}
        hidden = {s: sympy.Dummy(s.name, **s.assumptions0) for s in starts}
        unseen = replace(
            sub,
            velocities={
                n: tuple((0 + c).xreplace(hidden) for c in v) for n, v in sub.velocities.items()
            },
            omegas={n: (0 + w).xreplace(hidden) for n, w in sub.omegas.items()},
            travels={body: travel},
        )
        (energy,) = energy_equations(unseen, self.symbols, self.values)
        names: dict[sympy.Symbol, sympy.Symbol] = {d: s for s, d in hidden.items()}
        if energy.rate is not None:
            prefix = "omega" if energy.rate.name.startswith("omega") else "v"
            names[energy.rate] = _renamed(energy.rate, prefix, stage.number + 1, body)
        cords = tuple(  # assumed taut (or slack) at the stage's end: checked, switched
            replace(c, stretch=c.stretch.xreplace(names), state=stage.number + 1)
            for c in energy.cords
        )
        k = stage.number
        note = energy.equation.note.replace(
            "T1 + ΣU(1→2) = T2", f"T{k} + ΣU({k}→{k + 1}) = T{k + 1}"
        )
        if riders:
            note += f"; {', '.join(sorted(riders))} moving with {body}: their masses added"
        lhs, rhs = energy.equation.lhs, energy.equation.rhs
        equation = Equation(lhs.xreplace(names), rhs.xreplace(names), "energy", 0, note)
        unknowns = {}
        if energy.rate is not None:
            rotation = energy.rate.name.startswith("omega")
            unknowns[names[energy.rate]] = Dim(0, 0, -1) if rotation else Dim(1, 0, -1)
        after_v = {
            n: tuple((sympy.Integer(0) + c).xreplace(names) for c in v)
            for n, v in energy.velocities.items()
        }
        after_v |= {rider: after_v[body] for rider in riders}
        after_w = {n: (sympy.Integer(0) + w).xreplace(names) for n, w in energy.spins.items()}
        if lone:
            after_w = {n: sympy.Integer(0) for n in (body, *riders)}
        second = ()
        if energy.rate is not None and energy.second is not None:
            value, how, what = energy.second
            if isinstance(value, sympy.Basic):  # from the start's unknowns: shown again
                value = value.xreplace(names)
            second = ((names[energy.rate], value, how, what),)
        record = StageRecord(
            stage, tuple(sorted(part)), dict(energy.works), stops=travel.stops,
            start_along=start_along, scene=replace(sub, travels={body: travel}),
        )  # fmt: skip
        return _Step(
            (equation,),
            unknowns,
            after_v,  # type: ignore[arg-type]
            {n: w for n, w in after_w.items() if n in scene.bodies},
            record,
            self.moved(travel, part, lone),
            second,
            energy.relations,
            constraints=tuple(c.branch() for c in cords),
            cords=cords,
        )

    def moving_part(
        self, part: set[str], riders: frozenset[str], body: str, links: tuple[Link, ...]
    ) -> Scene:
        """The scene of the bodies a travel moves, starting from their current motion; a
        body's riders are merged into it (one particle, the masses added)."""
        scene = self.scene
        bodies = {n: b for n, b in scene.bodies.items() if n in part and n not in riders}
        if riders:
            mass = scene.bodies[body].mass + sum(scene.bodies[n].mass for n in riders)
            bodies[body] = replace(bodies[body], mass=tidy(mass))
        aboard = {n: body for n in riders}
        moving = {n: v for n in bodies if not _still(v := self.velocities[n], 0)}
        spinning = {n: w for n in bodies if not _still(ZERO, w := self.omegas[n])}
        return replace(
            scene,
            bodies=bodies,
            supports=tuple(
                replace(s, body=aboard.get(s.body, s.body))
                for s in scene.supports
                if s.body in part
            ),
            loads=tuple(
                replace(load, body=aboard.get(load.body, load.body))
                for load in scene.loads
                if load.body in part or load.body not in scene.bodies
            ),
            links=links,
            springs=tuple(s for s in scene.springs if {s.body, s.other} & part),
            cords=tuple(c for c in scene.cords if {c.body, c.other} & part),
            velocities=moving if not spinning else {},
            omegas=spinning,
        )

    def moved(self, travel: Travel, part: set[str], lone: bool) -> Scene:
        """The geometry after a travel: a lone particle (and its riders) moved to the new
        place; the bodies of a mechanism are marked as no longer followed."""
        from dynsolve.model.states import particle_shift

        scene = self.scene
        if not lone:
            self.unfollowed |= part
            place = _bob_place(scene, travel)
            if place is not None:  # a particle on a link: where it swung to
                name, G = place
                for rider in self.together[name]:
                    self.places[rider] = G
            return scene
        shift = particle_shift(scene, travel)
        assert shift is not None
        bodies = dict(scene.bodies)
        for name in part:
            bodies[name] = _carried(bodies[name], shift)
        return replace(scene, bodies=bodies, springs=_springs_carried(scene, part, shift))


def _polynomial_roots(
    equations: list[sympy.Expr], unknowns: list[sympy.Symbol]
) -> list[dict[sympy.Symbol, sympy.Expr]] | None:
    """The roots sympy's solve gives a stage's equations (numbers and its unknowns only)
    where they are linear (linsolve) or one polynomial in one unknown (its roots), each
    kept unless it contradicts its unknown's assumptions (a real speed, a positive time),
    as solve keeps it; a third of solve's time. None for any other system.

    >>> v = sympy.Symbol("v", real=True)
    >>> _polynomial_roots([sympy.Integer(9) - v**2], [v])
    [{v: -3}, {v: 3}]
    >>> _polynomial_roots([v**2 + 4], [v])  # no real root
    []
    """
    try:
        polynomials = [sympy.Poly(e, *unknowns) for e in equations]
    except sympy.PolynomialError:
        return None
    if all(p.total_degree() <= 1 for p in polynomials):
        solutions = [
            dict(zip(unknowns, values, strict=True))
            for values in sympy.linsolve(equations, unknowns)
        ]
    elif len(unknowns) == 1 and len(polynomials) == 1:
        found = sympy.roots(polynomials[0], unknowns[0])
        if sum(found.values()) != polynomials[0].degree():  # not all of them in radicals
            return None
        solutions = [{unknowns[0]: root} for root in found]
    else:
        return None
    free = set(unknowns)
    return [
        root
        for root in solutions
        if not any(v.free_symbols & free for v in root.values())
        and all(check_assumptions(v, **s.assumptions0) is not False for s, v in root.items())
    ]


def _renamed(symbol: sympy.Symbol, prefix: str, state: int, body: str) -> sympy.Symbol:
    """The unknown of a stage named for the state it belongs to (v_3_ball)."""
    return sympy.Symbol(f"{prefix}_{state}_{body}", **symbol.assumptions0)


def _still(v: Vec, w: sympy.Expr) -> bool:
    return (
        tidy(sympy.Integer(0) + v[0]) == 0
        and tidy(sympy.Integer(0) + v[1]) == 0
        and tidy(sympy.Integer(0) + w) == 0
    )


def _check_straight(stage: Stage, travel: Travel, scene: Scene, v: Vec) -> sympy.Expr:
    """A lone particle's velocity at the end of a travel is taken along the travel: it must
    start at rest or moving along that line (work and energy gives only its speed).
    Returns v·Δr, whose sign (checked once solved) says it starts toward the end."""
    from dynsolve.model.states import particle_shift

    shift = particle_shift(scene, travel)
    assert shift is not None
    if tidy(cross(shift, v)) != 0:
        raise StageError(
            stage,
            f"{stage.title}: {travel.body} starts moving across the line of its travel, so "
            "the direction of its velocity at the end is not known from work and energy "
            "(only its speed); its path must be straight along the travel",
        )
    return tidy(dot(v, shift))


def _bob_place(scene: Scene, travel: Travel) -> tuple[str, Vec] | None:
    """Where a particle swinging on a link ends a travel (``to``/``by`` it, or a turn of
    its link to a fixed point), as (particle, G); None for a rigid body or a linkage."""
    from dynsolve.model.states import particle_shift

    body = scene.bodies.get(travel.body)
    if body is not None:
        if body.particle and travel.kind in ("to", "by"):
            shift = particle_shift(scene, travel)
            assert shift is not None
            return travel.body, _plus(body.G, shift)
        return None
    link = next((k for k in scene.links if k.name == travel.body), None)
    if link is None or link.other or travel.kind != "turns" or travel.angle is None:
        return None
    if not scene.bodies[link.body].particle:
        return None
    centre, G = link.other_point, scene.bodies[link.body].G
    c, s = sympy.cos(travel.angle), sympy.sin(travel.angle)
    r = (G[0] - centre[0], G[1] - centre[1])
    x, y = centre[0] + c * r[0] - s * r[1], centre[1] + s * r[0] + c * r[1]
    return link.body, (tidy(x), tidy(y))


def _joined(scene: Scene, body: str) -> set[str]:
    """``body`` and every body joined to it by links, springs or cords."""
    pairs = [(c.body, c.other) for c in (*scene.links, *scene.springs, *scene.cords)]
    part = {body}
    grown = True
    while grown:
        grown = False
        for a, b in pairs:
            if b and (a in part) != (b in part):
                part |= {a, b}
                grown = True
    return {name for name in part if name in scene.bodies}


def _springs_carried(scene: Scene, part: set[str], shift: Vec) -> tuple:
    """The scene's springs with the ends on the bodies of ``part`` moved by ``shift``."""
    return tuple(
        replace(
            s,
            point=_plus(s.point, shift) if s.body in part else s.point,
            other_point=_plus(s.other_point, shift) if s.other in part else s.other_point,
        )
        for s in scene.springs
    )


def _carried(body: Body, shift: Vec) -> Body:
    """``body`` moved by ``shift`` without turning: its G, origin and named points."""
    return replace(
        body,
        G=_plus(body.G, shift),
        origin=_plus(body.origin, shift),
        points={n: _plus(p, shift) for n, p in body.points.items()},
    )


def _plus(a: Vec, b: Vec) -> Vec:
    return (tidy(a[0] + b[0]), tidy(a[1] + b[1]))


def chain_assumptions(
    scene: Scene,
    formulation: Formulation,
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> tuple[Assumption, ...]:
    """What following the stages assumes, checked against the solution: each travel gets
    to its end (T + ΣU ≥ 0, or = 0 where it stops), and each impact's model is stated;
    every value with its unit in ``system``."""
    checks: list[Assumption] = []

    def speed(value: float) -> str:
        return with_unit(value, "velocity", system)

    for what, force, detail in formulation.events:  # one-sided forces at asked instants
        value = real_value(force, values)
        if value is not None:
            text = detail.format(value=InSystem(value, system))
            if value <= 0:
                text = text.replace(" > 0", " ≤ 0") + ": the assumption fails there"
            checks.append(Assumption(what, value > 0, text))
    for record in formulation.stages:
        event, k = record.stage.event, record.stage.number
        if isinstance(event, Travel) and event.kind == "for":
            checks += _interval_checks(record, values, system)
            continue
        if isinstance(event, Travel) and event.kind == "until":
            checks += _event_checks(record, values, system, "")
            continue
        if isinstance(event, Clutch | Reshape):
            from dynsolve.principles.angular_momentum import spin_checks

            checks += spin_checks(k, event, record.pinned, values, system)
            continue
        if isinstance(event, Impact) and record.pin:
            from dynsolve.principles.angular_momentum import pinned_impact_checks

            struck = (record.bodies[0], record.bodies[1])
            embeds = real_value(event.e, values) == 0
            checks += pinned_impact_checks(
                k, struck, embeds, record.pin, record.pinned, values, system
            )
            continue
        if isinstance(event, Impact) and record.approach is not None:
            closing = real_value(record.approach, values)
            if closing is not None:
                ground = event.other not in scene.bodies  # either sense of the line
                checks.append(
                    Assumption(
                        f"approach in stage {k}",
                        closing > 0,
                        (
                            f"before the impact |v·n| = {speed(closing)} (the ground)"
                            if ground
                            else f"before the impact (v_A − v_B)·n = {speed(closing)}"
                        )
                        + (
                            " > 0"
                            if closing > 0
                            else _no_approach(scene, event, values, first=k == 1)
                        ),
                    )
                )
        if isinstance(event, Impact):
            checks.append(
                Assumption(
                    f"impact in stage {k}",
                    True,
                    f"stated: smooth contact, restitution {_restitution(event.e, values)} along "
                    "the line of impact; finite forces (weights, supports) give no impulse over it",
                )
            )
            continue
        if isinstance(event, Pivot) and event.normal is not None:
            checks += _event_checks(record, values, system, ": it does not strike the point")
            checks.append(
                Assumption(
                    f"impact at {event.name} in stage {k}",
                    True,
                    f"stated: smooth contact, restitution {_restitution(event.e, values)} along "
                    "the line; finite forces (the weight) give no impulse over it",
                )
            )
            continue
        if isinstance(event, Pivot):
            checks.append(
                Assumption(
                    f"plastic impact at {event.name}",
                    True,
                    f"stated (e 0): {event.name} neither rebounds nor slides, so {event.body} "
                    f"turns about {event.name} after the impact",
                )
            )
            continue
        for support in scene.supports:
            if support.kind == "rolls" and support.body in record.bodies:
                checks.append(
                    Assumption(
                        f"no slip at {support.name} in stage {k}",
                        True,
                        "stated by 'rolls' for the whole travel; the friction it needs "
                        "between the states is not computed",
                    )
                )
        checks += from_rest(record, values, system)[0]
        along = real_value(record.start_along, values) if record.start_along is not None else None
        if along is not None and along != 0:
            checks.append(
                Assumption(
                    f"sense of motion in stage {k}",
                    along > 0,
                    f"at state {k} {event.body} moves "
                    + ("toward" if along > 0 else "away from")
                    + " the end of its travel (the sign of v·Δr)"
                    + ("" if along > 0 else ": it does not travel that way"),
                )
            )
        for index in record.equations:
            equation = formulation.equations[index]
            energy = real_value(equation.lhs, values)
            if energy is None:
                continue
            scale = sum(abs(real_value(t, values) or 0) for t in sympy.Add.make_args(equation.lhs))
            tolerance = 1e-9 * max(scale, 1e-300)
            if record.stops:
                at_rest = abs(energy) <= tolerance
                shown = with_unit(0.0 if at_rest else energy, "energy", system)
                detail = f"T{k + 1} = T{k} + ΣU = {shown}"
                if not at_rest:
                    detail += ": it still moves there" if energy > 0 else ": it stops before"
                checks.append(Assumption(f"at rest in state {k + 1}", at_rest, detail))
                continue
            reaches = energy >= -tolerance
            shown = with_unit(max(energy, 0.0) if reaches else energy, "energy", system)
            checks.append(
                Assumption(
                    f"reaches state {k + 1}",
                    reaches,
                    f"T{k} + ΣU = {shown} "
                    + ("≥ 0" if reaches else f"< 0: it stops before state {k + 1}"),
                )
            )
    return tuple(checks)


def from_rest(
    record: StageRecord, values: Mapping[sympy.Symbol, sympy.Expr], system: str
) -> tuple[tuple[Assumption, ...], tuple[str, ...]]:
    """A travel that starts from rest on a rough contact: static friction must not be able
    to hold the body there (|F needed| ≤ μs N: it stays, the travel fails). Without μs,
    μk N ≤ μs N still decides where it holds the body; elsewhere that it slides is an
    assumption NOT checked, returned as a warning (second item), never a pass; forces in
    ``system``'s units."""
    event, k = record.stage.event, record.stage.number
    scene = record.scene
    if not isinstance(event, Travel) or event.kind in ("for", "until") or scene is None:
        return (), ()
    if not all(real_value(c, values) == 0 for v in scene.velocities.values() for c in v):
        return (), ()
    if not all(real_value(w, values) in (0, None) for w in scene.omegas.values()):
        return (), ()
    rough = [
        s
        for s in scene.supports
        if s.kind in ("contact", "base") and not s.smooth and s.body in record.bodies
    ]
    rough = [s for s in rough if s.mu_s is not None or s.mu_k is not None]
    if not rough:
        return (), ()
    symbols = {s.name: s for s in values if isinstance(s, sympy.Symbol)}
    still = formulate(replace(scene, travels={}, velocities={}, omegas={}), symbols)
    residuals = [(e.lhs - e.rhs).xreplace(values) for e in still.equations]
    try:
        solved = sympy.solve(residuals, list(still.unknowns), dict=True)
    except (NotImplementedError, ValueError):
        solved = []
    if len(solved) != 1:
        return (), ()
    checks: list[Assumption] = []
    warnings: list[str] = []
    name = f"slides from rest in stage {k}"
    for support in rough:
        C = support.name
        if f"F_{C}" not in still.reactions or f"N_{C}" not in still.reactions:
            continue
        F = real_value(still.reactions[f"F_{C}"][0].xreplace(solved[0]), values)
        N = real_value(still.reactions[f"N_{C}"][0].xreplace(solved[0]), values)
        mu = support.mu_s if support.mu_s is not None else support.mu_k
        mu_value = real_value(mu, values) if mu is not None else None
        if F is None or N is None or mu_value is None or N <= 0:
            continue
        limit = mu_value * N
        held = abs(F) <= limit * (1 + 1e-9)
        needed, most = with_unit(abs(F), "force", system), with_unit(limit, "force", system)
        start = f"at state {k} {event.body} is at rest on {C}: to hold it there static friction "
        if held:
            bound = "μs N" if support.mu_s is not None else "μk N ≤ μs N"
            checks.append(
                Assumption(
                    name,
                    False,
                    start + f"needs |F| = {needed} ≤ {bound} = {most}: static friction "
                    f"holds it, it stays at state {k} and does not travel",
                )
            )
        elif support.mu_s is not None:
            checks.append(
                Assumption(
                    name,
                    True,
                    start + f"would need |F| = {needed} > μs N = {most}: it cannot, "
                    "the body slides",
                )
            )
        else:
            warnings.append(
                f"stage {k}: {start}would need |F| = {needed} > μk N = {most}; with no "
                f"mu_s given, that static friction cannot hold it (that it slides) is NOT checked"
            )
    return tuple(checks), tuple(warnings)


def _interval_checks(
    record: StageRecord, values: Mapping[sympy.Symbol, sympy.Expr], system: str
) -> list[Assumption]:
    """What an interval in a chain assumed: each contact pushes (average N ≥ 0), each
    sliding contact slides through the whole interval in the sense its friction opposes,
    and its end event comes after its start."""
    k = record.stage.number
    checks = []
    for name, normal in record.normals:
        N = real_value(normal, values)
        if N is not None:
            checks.append(
                Assumption(
                    f"contact in stage {k}",
                    N >= 0,
                    f"average {name} = {with_unit(N, 'force', system)}"
                    + (" ≥ 0" if N >= 0 else " < 0: it would pull"),
                )
            )
    for slide in record.slides:
        start, end = real_value(slide.start, values), real_value(slide.end, values)
        if start is None or end is None:
            continue
        name = f"sliding at {slide.support} in stage {k}"
        opposes = start * slide.sense < 0
        if not opposes:
            way = "along" if start > 0 else "against"
            detail = (
                f"the contact point's slip at state {k} is "
                f"{with_unit(start, 'velocity', system)} ({way} the tangent): "
                + ("it does not slide" if start == 0 else "the friction assumed does not oppose it")
            )
            checks.append(Assumption(name, False, detail))
            continue
        checks.append(slide_kept(name, start, end, k, system))
    return checks + _event_checks(
        record, values, system, ": it would have to happen before the start, so it never happens"
    )


def _no_approach(
    scene: Scene, event: Impact, values: Mapping[sympy.Symbol, sympy.Expr], first: bool
) -> str:
    """Why two bodies do not close along the line of impact: the line written from B toward
    A (where the scene's positions tell, at the first stage), or their motions."""
    if first and event.other in scene.bodies:
        G_A, G_B = scene.bodies[event.body].G, scene.bodies[event.other].G
        toward = real_value(
            (G_B[0] - G_A[0]) * event.line[0] + (G_B[1] - G_A[1]) * event.line[1], values
        )
        if toward is not None and toward < 0:
            return (
                f": the line of impact is written from {event.other} toward {event.body}; "
                f"it must point from {event.body} toward {event.other} (reverse its direction)"
            )
    return (
        f": {event.body} does not strike {event.other} (the line points from {event.body} "
        f"toward {event.other})"
    )


def slide_kept(name: str, start: float, end: float, k: int, system: str) -> Assumption:
    """A contact's slip keeps its sign from state k to k + 1 (0 at the end allowed): kinetic
    friction opposes it throughout an interval of constant forces, else the body stopped
    sliding inside it and the interval's equation no longer holds.

    >>> slide_kept("sliding at C", -3.0, 0.92, 1, "SI").holds  # a block stopped and came back
    False
    >>> kept = slide_kept("sliding at C", 3.0, 0.0, 1, "FPS")  # it stops just at the end
    >>> kept.holds, kept.detail[:41]
    (True, 'slip 3 ft/s at state 1, 0 ft/s at state 2')
    """
    scale = max(abs(start), abs(end)) or 1.0
    keeps = end * (1 if start > 0 else -1) >= -1e-9 * scale  # relative: a speed vs speeds
    first = with_unit(start, "velocity", system)
    detail = (
        f"slip {first} at state {k}, "
        f"{with_unit(0.0 if abs(end) <= 1e-9 * scale else end, 'velocity', system)} "
        f"at state {k + 1}: kinetic friction opposes it throughout"
    )
    if not keeps:
        detail = (
            f"slip {first} at state {k} but {with_unit(end, 'velocity', system)} at state "
            f"{k + 1}: it stops "
            "sliding before the interval ends, and friction does not push it back (state the "
            "end with ', until rolls' or ', stops')"
        )
    return Assumption(name, keeps, detail)


def _event_checks(
    record: StageRecord, values: Mapping[sympy.Symbol, sympy.Expr], system: str, failed: str
) -> list[Assumption]:
    """Each of a stage's events holds (a positive value): an end event after the start,
    a cord taut or a contact pushing where an until stage starts."""
    checks = []
    for what, value, detail in record.events:
        number = real_value(value, values)
        if number is not None:
            text = detail.format(value=InSystem(number, system)) + (failed if number <= 0 else "")
            checks.append(Assumption(f"{what} in stage {record.stage.number}", number > 0, text))
    return checks


def chain_slips(
    formulation: Formulation, values: Mapping[sympy.Symbol, sympy.Expr]
) -> dict[str, int]:
    """The friction senses to re-solve with (``"C@3"``: at C in stage 3) where a slide's
    sense was guessed and the solution slips the other way."""
    slips = {}
    for record in formulation.stages:
        for slide in record.slides:
            start = real_value(slide.start, values)
            if slide.guessed and start is not None and start * slide.sense > 0:
                slips[f"{slide.support}@{record.stage.number}"] = -slide.sense
    return slips


def _restitution(e: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]) -> str:
    """``e = 0.6`` (a given e with its value, not "e = e").

    >>> e = sympy.Symbol("e", positive=True)
    >>> _restitution(e, {e: sympy.Rational(3, 5)}), _restitution(sympy.Rational(1, 2), {})
    ('e = 0.6', 'e = 1/2')
    """
    value = real_value(e, values)
    if isinstance(e, sympy.Symbol) and value is not None:
        return f"e = {value:.4g}"
    return f"e = {sympy.sstr(e)}"
