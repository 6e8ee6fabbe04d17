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

from dynsolve.model.scene import Impact, Link, Pivot, Scene, Support, Travel, Vec
from dynsolve.model.stages import Slide, Stage, StageRecord, State, stages_of
from dynsolve.numbers import real_value, tidy
from dynsolve.principles.newton_euler import Formulation, bare_formulation, cross, dot
from dynsolve.results import Assumption
from dynsolve.system import Equation
from dynsolve.units import Dim

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


def chain_formulation(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    given_values: Mapping[sympy.Symbol, sympy.Expr],
    senses: Mapping[str, int] | None = None,
) -> Formulation:
    """The equations of every stage of ``scene``, each starting where the last one ended.
    A load whose size is not given is an unknown of the travels that it works in (the
    average resistance that stops a pile). ``senses`` holds the friction senses that an
    earlier solve found for contacts sliding through an interval (``"C@3"``: at C in
    stage 3), where the first guess was contradicted."""
    loads = {
        load.name: sympy.Symbol(load.name, positive=True)
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
    for stage in stages_of(scene.events):
        step = chain.stage(stage)
        first = len(equations)
        for equation in step.equations:
            number = len(equations) + 1
            note = f"{stage.title}: {equation.note}"
            equations.append(Equation(equation.lhs, equation.rhs, f"eq. {number}", number, note))
        unknowns.update(step.unknowns)
        chain.advance(step)
        chain.presolve(step)
        states.append(State(stage.number + 1, dict(chain.velocities), dict(chain.omegas)))
        records.append(replace(step.record, equations=tuple(range(first, len(equations)))))
        second += step.second
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
            r.stage.event.body: states[r.stage.number].omegas[r.stage.event.body]
            for r in records
            if isinstance(r.stage.event, Pivot)
        },
        speeds=_after_travels(
            records, states, lambda s, n: tidy(sympy.sqrt(dot(*[s.velocities[n]] * 2)))
        ),
        spins=_after_travels(records, states, lambda s, n: s.omegas[n]),
        notes=tuple(notes),
        second=tuple(second),
        states=tuple(states),
        stages=tuple(records),
        displacements=dict(chain.displacements),
    )


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
        if isinstance(record.stage.event, Impact):
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
        self.symbols, self.values, self.senses = symbols, values, senses
        self.known: dict[sympy.Symbol, sympy.Expr] = dict(values)  # givens, then each stage's
        self.reaction_names: set[str] = set()  # average reactions named by earlier intervals
        self.velocities = {name: scene.velocities.get(name, ZERO) for name in scene.bodies}
        self.omegas = {n: sympy.Integer(0) + scene.omegas.get(n, 0) for n in scene.bodies}
        self.unfollowed: set[str] = set()  # bodies whose geometry is no longer followed
        self.together: dict[str, frozenset[str]] = {n: frozenset((n,)) for n in scene.bodies}
        self.joined_notes: list[tuple[int, str]] = []
        self.places: dict[str, Vec] = {}  # G of a particle on a link, after a travel
        self.displacements: dict[str, Vec] = {}  # Δr_G over each body's last interval

    def stage(self, stage: Stage) -> _Step:
        event = stage.event
        if isinstance(event, Impact):
            return self.impact(stage, event)
        if event.body in self.unfollowed:
            raise StageError(
                stage,
                f"{stage.title}: where {event.body} is after an earlier stage is not followed "
                "(only a particle's position is); describe this part as a scene of its own",
            )
        if isinstance(event, Pivot) and event.normal is not None:
            raise StageError(
                stage,
                f"{stage.title}: a rebound off a point (e > 0) cannot be chained with other "
                "stages yet; describe it as a scene of its own",
            )
        if isinstance(event, Pivot):
            return self.pivot(stage, event)
        if event.kind == "until":
            raise StageError(
                stage,
                f"{stage.title}: 'until {event.until}' cannot be chained with other stages "
                "yet; describe it as a scene of its own",
            )
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
        equations = [e.residual.xreplace(self.known) for e in step.equations]
        if any(e.free_symbols - set(step.unknowns) for e in equations):
            return  # it depends on a later stage (an unknown extent) or on loads
        try:
            roots = sympy.solve(equations, list(step.unknowns), dict=True)
        except (NotImplementedError, ValueError):  # pragma: no cover - sympy's own limits
            return
        if len(roots) == 1 and set(roots[0]) == set(step.unknowns):
            self.known.update({s: tidy(v) for s, v in roots[0].items()})

    def interval(self, stage: Stage, travel: Travel) -> _Step:
        """Impulse and momentum over an interval of constant forces (``for Δt``, with
        ``stops`` or ``until rolls``), from the motion the last stage left. A rough contact
        slides through it: its kinetic friction opposes the slip at the start, whose sign
        is known from the stages before (or guessed, then checked and re-solved)."""
        from dynsolve.principles.impulse_momentum import impulse_formulation
        from dynsolve.principles.until import contact_slip

        scene, body = self.scene, travel.body
        riders = self.together[body] - {body}
        part = {body} | riders
        for name in scene.bodies:
            v, w = self.velocities[name], self.omegas[name]
            if name not in part and not _still(
                tuple(c.xreplace(self.known) for c in v),  # type: ignore[arg-type]
                (sympy.Integer(0) + w).xreplace(self.known),
            ):
                raise StageError(
                    stage,
                    f"{stage.title}: {name} is still moving (as the stages before leave it) "
                    "but takes no part in the interval; an interval in a chain follows one "
                    "body while the others are at rest",
                )
        joined = _joined(scene, body) - part
        if joined:
            raise StageError(
                stage,
                f"{stage.title}: {body} is joined to {', '.join(sorted(joined))}; an interval "
                "in a chain follows one body (and what a plastic impact stuck to it)",
            )
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
            body = bodies[name]
            bodies[name] = replace(
                body,
                G=_plus(body.G, shift),
                origin=_plus(body.origin, shift),
                points={n: _plus(p, shift) for n, p in body.points.items()},
            )
        supports = tuple(
            replace(s, point=_plus(s.point, shift)) if s.body in part else s for s in scene.supports
        )
        return replace(scene, bodies=bodies, supports=supports)

    def impact(self, stage: Stage, impact: Impact) -> _Step:
        from dynsolve.principles.impact import impact_equations, velocity_after

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

    def travel(self, stage: Stage, travel: Travel) -> _Step:
        """Work and energy for the bodies the travel moves: those joined to its body, or
        moving with it since a plastic impact."""
        from dynsolve.principles.work_energy import energy_equations

        scene, body = self.scene, travel.body
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
        lone = (len(part) - len(riders)) == 1 and scene.bodies[body].particle and not links
        if riders and not lone:
            raise StageError(
                stage,
                f"{stage.title}: {body} carries {', '.join(sorted(riders))} since a plastic "
                "impact; a travel of particles moving together is supported on its own only",
            )
        start_along = None
        if lone and travel.kind in ("to", "by"):
            start_along = _check_straight(stage, travel, scene, self.velocities[body])
        sub = self.moving_part(part, riders, body, links)
        (energy,) = energy_equations(
            replace(sub, travels={body: travel}), self.symbols, self.values
        )
        names: dict[sympy.Symbol, sympy.Symbol] = {}
        if energy.rate is not None:
            prefix = "omega" if energy.rate.name.startswith("omega") else "v"
            names[energy.rate] = _renamed(energy.rate, prefix, stage.number + 1, body)
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
            second = ((names[energy.rate], *energy.second),)
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
            body = scene.bodies[travel.body]
            if body.particle and travel.kind in ("to", "by"):  # where a bob has swung to
                shift = particle_shift(scene, travel)
                assert shift is not None
                self.places[travel.body] = _plus(body.G, shift)
            return scene
        shift = particle_shift(scene, travel)
        assert shift is not None
        bodies = dict(scene.bodies)
        for name in part:
            body = bodies[name]
            bodies[name] = replace(
                body,
                G=_plus(body.G, shift),
                origin=_plus(body.origin, shift),
                points={n: _plus(p, shift) for n, p in body.points.items()},
            )
        return replace(scene, bodies=bodies)


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


def _plus(a: Vec, b: Vec) -> Vec:
    return (tidy(a[0] + b[0]), tidy(a[1] + b[1]))


def chain_assumptions(
    scene: Scene, formulation: Formulation, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Assumption, ...]:
    """What following the stages assumes, checked against the solution: each travel gets
    to its end (T + ΣU ≥ 0, or = 0 where it stops), and each impact's model is stated."""
    checks: list[Assumption] = []
    for record in formulation.stages:
        event, k = record.stage.event, record.stage.number
        if isinstance(event, Travel) and event.kind == "for":
            checks += _interval_checks(record, values)
            continue
        if isinstance(event, Impact) and record.approach is not None:
            closing = real_value(record.approach, values)
            if closing is not None:
                checks.append(
                    Assumption(
                        f"approach in stage {k}",
                        closing > 0,
                        f"before the impact (v_A − v_B)·n = {closing:.4g}"
                        + (
                            " > 0"
                            if closing > 0
                            else f": {event.body} does not strike {event.other} (the line "
                            f"points from {event.body} toward {event.other})"
                        ),
                    )
                )
        if isinstance(event, Impact):
            checks.append(
                Assumption(
                    f"impact in stage {k}",
                    True,
                    f"stated: smooth contact, restitution e = {sympy.sstr(event.e)} along the line "
                    "of impact; finite forces (weights, supports) give no impulse over it",
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
                detail = f"T{k + 1} = T{k} + ΣU = {0.0 if at_rest else energy:.4g}"
                if not at_rest:
                    detail += ": it still moves there" if energy > 0 else ": it stops before"
                checks.append(Assumption(f"at rest in state {k + 1}", at_rest, detail))
                continue
            reaches = energy >= -tolerance
            checks.append(
                Assumption(
                    f"reaches state {k + 1}",
                    reaches,
                    f"T{k} + ΣU = {max(energy, 0.0) if reaches else energy:.4g} "
                    + ("≥ 0" if reaches else f"< 0: it stops before state {k + 1}"),
                )
            )
    return tuple(checks)


def _interval_checks(
    record: StageRecord, values: Mapping[sympy.Symbol, sympy.Expr]
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
                    f"average {name} = {N:.4g} N" + (" ≥ 0" if N >= 0 else " < 0: it would pull"),
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
                f"the contact point's slip at state {k} is {start:.4g} m/s ({way} the tangent): "
                + ("it does not slide" if start == 0 else "the friction assumed does not oppose it")
            )
            checks.append(Assumption(name, False, detail))
            continue
        scale = max(abs(start), abs(end)) or 1.0
        keeps = end * (1 if start > 0 else -1) >= -1e-9 * scale  # relative: a speed vs speeds
        detail = (
            f"slip {start:.4g} m/s at state {k}, {0.0 if abs(end) <= 1e-9 * scale else end:.4g} "
            f"m/s at state {k + 1}: kinetic friction opposes it throughout"
        )
        if not keeps:
            detail = (
                f"slip {start:.4g} m/s at state {k} but {end:.4g} m/s at state {k + 1}: it stops "
                "sliding before the interval ends (state the end with ', until rolls' or "
                "', stops')"
            )
        checks.append(Assumption(name, keeps, detail))
    for what, value, detail in record.events:
        number = real_value(value, values)
        if number is not None:
            text = detail.format(value=number)
            if number <= 0:
                text += ": it would have to happen before the start, so it never happens"
            checks.append(Assumption(f"{what} in stage {k}", number > 0, text))
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
