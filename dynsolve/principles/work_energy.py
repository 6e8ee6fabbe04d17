"""Work and energy between two states of a scene: T1 + ΣU(1→2) = T2.

State 1 is the scene as described (velocities from ``velocity``/``omega`` lines, else
rest); state 2 is where its ``travel`` line puts it. A lone particle's state 2 is its
own position; a rigid body or a linkage is placed by :mod:`dynsolve.model.states`,
which also gives every velocity in state 2 as a multiple of one rate of travel.
T = Σ ½ m v_G² + ½ I_G ω². The work of weights (W·Δr_G), springs (−½k(s₂² − s₁²), both
stretches from the geometry), couples (M Δθ), constant forces (F·Δr of their point)
and kinetic friction while sliding (−μk N s) is summed; the forces that do no work
are named with the reason.

>>> import sympy
>>> from dynsolve.model.scene import Scene, Body, Travel
>>> m, g, h = sympy.symbols("m g h", positive=True)
>>> ball = Body("ball", m, sympy.Integer(0), (0, h), (0, h), "particle", (), {}, True, "", 0, 0)
>>> scene = Scene({"ball": ball}, {}, (), (), (), (0, -1), {},
...               travels={"ball": Travel("ball", "to", position=(0, 0))})
>>> (energy,) = energy_equations(scene, {"g": g})
>>> sympy.solve(energy.equation.residual, energy.rate)
[-sqrt(2)*sqrt(g)*sqrt(h), sqrt(2)*sqrt(g)*sqrt(h)]
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy

from dynsolve.model.scene import Cord, CordState, Scene, Spring, Support, Travel, Vec
from dynsolve.model.states import (
    Placement,
    Rates,
    cord_ends,
    held_only_by_cords,
    particle_shift,
    point_after,
    state_change,
    wound_after,
)
from dynsolve.numbers import abs_resolved, real_value, tidy
from dynsolve.principles.newton_euler import dot
from dynsolve.system import Equation

ZERO: Vec = (sympy.Integer(0), sympy.Integer(0))
FORCE_PATH = "F = m a along the path, m v dv = F_t ds integrated numerically"
CONSTANT_ALPHA = (
    "ΣF = m a_G, ΣM = I α at state 1: α is constant (constant loads, flat support), "
    "ω₂² = ω₁² + 2 α Δθ"
)
STILL = Placement(ZERO, sympy.Integer(0), sympy.Integer(1), sympy.Integer(0))


@dataclass(frozen=True)
class Energy:
    """One work–energy equation and what it tells about state 2."""

    equation: Equation
    rate: sympy.Symbol | None  # the unknown rate of travel in state 2 (None: at rest)
    speeds: Mapping[str, sympy.Expr]  # |v_G| in state 2, per body
    spins: Mapping[str, sympy.Expr]  # ω in state 2 (ccw positive), per body or link
    relations: tuple[str, ...]  # kinematics between the states
    idle: tuple[str, ...]  # the forces that do no work, each with its reason
    # the rate by a second method: (value, how, what the rate measures)
    second: tuple[float, str, str] | None = None
    velocities: Mapping[str, Vec] = field(default_factory=dict)  # v_G in state 2, per body
    works: Mapping[str, sympy.Expr] = field(default_factory=dict)  # U(1→2) per force's name
    # the equation's terms as the textbook lists them: ("T1", T1), each ("U_… = …", U), ("T2", T2)
    terms: tuple[tuple[str, sympy.Expr], ...] = ()
    cords: tuple[CordState, ...] = ()  # elastic cords whose state at state 2 was assumed


def _side_kept(expr: sympy.Expr, known: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """A spring's length |E − P₂| at the end of a travel of unknown extent, written with
    the sign its end had at the start (the unknowns at 0: not moved yet): a spring's end
    does not pass through its anchor, so the root beyond it (the block through the wall)
    is not a root of the equation at all.

    >>> d = sympy.Symbol("d", nonnegative=True)
    >>> _side_kept(sympy.Abs(sympy.Rational(3, 5) - d), {})
    3/5 - d
    """
    at_start = {s: sympy.Integer(0) for s in expr.free_symbols if s not in known}
    return abs_resolved(expr, {**at_start, **known})


def _length(a: Vec, b: Vec) -> sympy.Expr:
    d = (a[0] - b[0], a[1] - b[1])
    return tidy(sympy.sqrt(dot(d, d)))


def _cross(a: Vec, b: Vec) -> sympy.Expr:
    return a[0] * b[1] - a[1] * b[0]


def _norm(v: Vec) -> sympy.Expr:
    return sympy.sqrt(dot(v, v))


def _is_zero(
    expr: sympy.Expr,
    values: Mapping[sympy.Symbol, sympy.Expr],
    scale: sympy.Expr = sympy.S.One,
    *scales: sympy.Expr,
) -> bool:
    """Whether ``expr`` is zero, numerically within 1e-12 of ``scale`` (its size if not
    zero; the largest of ``scale`` and ``scales``, each a number at the values).

    The tolerance is relative, so a problem scaled by 10^k decides the same way:

    >>> from sympy import Float
    >>> _is_zero(Float("1e-14"), {}, Float("1e-8") ** 2), _is_zero(Float("1e-30"), {}, 1)
    (False, True)
    >>> _is_zero(Float("1e-14"), {}, Float("1e-8"), 1)
    True
    """
    if tidy(expr) == 0:
        return True
    number = real_value(expr, values)
    sizes = [real_value(s, values) for s in (scale, *scales)]
    if number is None or None in sizes:
        return False
    return abs(number) <= 1e-12 * max(abs(s) for s in sizes)  # type: ignore[arg-type]


class _Work:
    """Sums the work done between the states, and names what does none."""

    def __init__(
        self,
        scene: Scene,
        placements: Mapping[str, Placement],
        link_turns: Mapping[str, sympy.Expr],
        symbols: Mapping[str, sympy.Expr],
        values: Mapping[sympy.Symbol, sympy.Expr],
    ):
        self.scene, self.placements, self.link_turns = scene, placements, link_turns
        self.symbols, self.values = symbols, values
        self.terms: list[sympy.Expr] = []
        self.notes: list[str] = []
        self.idle: list[str] = []
        self.named: dict[str, sympy.Expr] = {}  # each force's work, by its name
        self.cords: list[CordState] = []  # elastic cords assumed taut (or slack) at the end

    def by_name(self, name: str, term: sympy.Expr, note: str) -> None:
        """Add the work ``term`` of the force called ``name`` (0 when it does none)."""
        self.named[name] = self.named.get(name, sympy.Integer(0)) + tidy(term)
        self.add(term, note)

    def moved(self, body: str, P: Vec) -> Vec:
        placement = self.placements.get(body)
        if placement is None:
            return P
        return point_after(self.scene.bodies[body], placement, P)

    def add(self, term: sympy.Expr, note: str) -> None:
        self.terms.append(tidy(term))
        self.notes.append(note)

    def weights(self) -> None:
        if self.scene.gravity is None:
            return
        for name, placement in self.placements.items():
            mass = self.scene.bodies[name].mass
            if mass == 0:
                continue
            work = mass * self.symbols["g"] * dot(self.scene.gravity, placement.shift)
            size = mass * self.symbols["g"] * _norm(self.scene.gravity) * _norm(placement.shift)
            if _is_zero(work, self.values, size):
                self.named[f"W_{name}"] = sympy.Integer(0)
                self.idle.append(f"W_{name} (G moves across the weight)")
            else:
                self.by_name(f"W_{name}", work, f"U_W = W·Δr_G ({name})")

    def springs(self) -> None:
        for spring in self.scene.springs:
            if spring.body not in self.placements and spring.other not in self.placements:
                continue
            if spring.wound:
                body = self.scene.bodies[spring.body]
                start = wound_after(body, self.placements[spring.body], spring.point)
                shift = (start[0] - spring.point[0], start[1] - spring.point[1])
                line = (
                    spring.other_point[0] - spring.point[0],
                    spring.other_point[1] - spring.point[1],
                )
                cross = shift[0] * line[1] - shift[1] * line[0]
                if not _is_zero(cross, self.values, _norm(shift) * _norm(line)):
                    raise ValueError(
                        f"the wound spring {spring.name} must pull along the motion of its "
                        "cord's end (keep it tangent to the rim, along its travel)"
                    )
                how = "its cord unwinds from the rim"
            else:
                start = self.moved(spring.body, spring.point)
                how = "from the positions of its ends"
            end = self.moved(spring.other, spring.other_point) if spring.other else None
            end = end or spring.other_point
            known = {**self.scene.values, **self.values}  # |E − P| as E − P where its sign shows
            s1 = abs_resolved(_length(spring.point, spring.other_point) - spring.unstretched, known)
            s2 = _side_kept(_length(start, end) - spring.unstretched, known)
            if spring.one_way:  # an elastic cord stores energy only while stretched, a
                # push-only spring only while compressed
                values = {**self.scene.values, **self.values}
                try:
                    spring.stretch(s2, values)
                except ValueError:  # not known before solving: assumed (acting), then checked
                    state = CordState(
                        spring.name, tidy(s2), bool(spring.taut), line=spring.line,
                        sign=spring.one_way,
                    )  # fmt: skip
                    self.cords.append(state)
                s1 = spring.stretch(s1, values)
                s2 = spring.stretch(s2, values, end=True)
            self.by_name(
                spring.name,
                -spring.k * (s2**2 - s1**2) / 2,
                f"U_{spring.name} = −½k(s₂² − s₁²), s₁ = {sympy.sstr(tidy(s1))}, "
                f"s₂ = {sympy.sstr(tidy(s2))} ({how})",
            )

    def loads(self) -> None:
        for load in self.scene.loads:
            if load.kind == "couple":
                turn = self.link_turns.get(load.body)
                if turn is None:
                    turn = self.placements.get(load.body, STILL).turn
                work = self.magnitude(load.name) * load.sense * turn
                self.by_name(load.name, work, f"U_{load.name} = M Δθ")
                continue
            if load.body not in self.placements:
                continue
            shift = self.moved(load.body, load.point)
            shift = (shift[0] - load.point[0], shift[1] - load.point[1])
            work = self.magnitude(load.name) * dot(load.direction, shift)
            size = self.magnitude(load.name) * _norm(load.direction) * _norm(shift)
            if _is_zero(work, self.values, size):
                self.named[load.name] = sympy.Integer(0)
                self.idle.append(f"{load.name} (its point moves across it)")
            else:
                self.by_name(load.name, work, f"U_{load.name} = F·Δr (constant force)")

    def magnitude(self, name: str) -> sympy.Expr:
        if name not in self.symbols:
            raise ValueError(f"the work of the unknown load {name} is not known; give its size")
        return self.symbols[name]

    def supports(self) -> None:
        for support in self.scene.supports:
            if support.body not in self.placements:
                continue
            if support.kind == "pin":
                self.idle.append(f"{support.name} (the pin does not move)")
            elif support.kind == "rolls":
                self.idle.append(
                    f"N_{support.name}, F_{support.name} (rolling without slipping: the "
                    "contact point has no velocity)"
                )
            else:
                self.contact(support)

    def contact(self, support: Support) -> None:
        placement = self.placements[support.body]
        P2 = self.moved(support.body, support.point)
        step = (P2[0] - support.point[0], P2[1] - support.point[1])
        if not _is_zero(
            dot(step, support.normal), self.values, _norm(step) * _norm(support.normal)
        ):
            error = ValueError(
                f"{support.body} would leave its contact {support.name} on the way to state 2 "
                "(a travel must run along the surface: check the travel's direction and the "
                "contact's normal)"
            )
            error.line, error.column = support.line, support.column  # type: ignore[attr-defined]
            raise error
        path = _length(P2, support.point)
        if support.smooth or _is_zero(path, self.values, _norm(P2), _norm(support.point)):
            self.idle.append(f"N_{support.name} (normal to the motion)")
            return
        if support.mu_k is None:
            raise ValueError(
                f"{support.body} slides at {support.name} between the states: give mu_k there"
            )
        if not _is_zero(placement.turn, self.values) or support.two_sided:
            raise ValueError(
                f"friction work at {support.name} needs a body translating on a one-sided "
                "surface (the normal force is taken from ΣF_n = 0)"
            )
        v_1 = real_value(dot(self.scene.velocities.get(support.body, ZERO), step), self.values)
        if v_1 is not None and v_1 < 0:
            raise ValueError(
                f"{support.body} moves away from state 2 at state 1, so the friction at "
                f"{support.name} would change sense on the way (U_F = −μk N s assumes one "
                "sense): split the travel where it turns back"
            )
        N = self.normal_force(support, step)
        self.by_name(
            f"F_{support.name}",
            -support.mu_k * N * path,
            f"U_F = −μk N s at {support.name}, N = {sympy.sstr(N)} from ΣF_n = 0 "
            "(constant along the straight path)",
        )

    def normal_force(self, support: Support, step: Vec) -> sympy.Expr:
        """N from ΣF_n = 0 for a body translating along a straight surface by ``step``; a
        spring to a fixed point on the line of the motion pushes or pulls along the surface
        only, so it leaves N alone (a block launched by a spring on a rough floor)."""
        body = self.scene.bodies[support.body]
        n = support.normal
        others = [s for s in self.scene.supports if s.body == body.name and s is not support]
        pulls = [
            s
            for s in self.scene.springs
            if body.name in (s.body, s.other) and not self._along_the_motion(s, step)
        ]
        pulls += [  # a cord pulling across the surface changes N as much as a spring
            c
            for c in self.scene.cords
            if body.name in (c.body, c.other)
            and not _is_zero(dot(c.direction, n), self.values, _norm(c.direction))
        ]
        if others or pulls or any(link.body == body.name for link in self.scene.links):
            what = others[0].name if others else pulls[0].name if pulls else "a link"
            error = ValueError(
                f"friction work at {support.name}: the normal force would change along the "
                f"path ({what} acts on {body.name} across the surface), so U_F = −μk N s "
                "does not hold"
            )
            error.line, error.column = support.line, support.column  # type: ignore[attr-defined]
            raise error
        total = sympy.Integer(0)
        if self.scene.gravity is not None:
            total += body.mass * self.symbols["g"] * dot(self.scene.gravity, n)
        for load in self.scene.loads:
            if load.body == body.name and load.kind == "force":
                total += self.magnitude(load.name) * dot(load.direction, n)
        N = tidy(-total)
        number = real_value(N, self.values)
        if number is not None and number < 0:
            raise ValueError(f"{body.name} would leave the surface at {support.name} (N < 0)")
        return N

    def _along_the_motion(self, spring: Spring, step: Vec) -> bool:
        """Whether ``spring`` runs from a fixed point along the line its end moves on (its
        force then has no part across the surface, at every point of the travel)."""
        if spring.other or spring.wound:
            return False
        start = spring.point
        reach = spring.other_point[0] - start[0], spring.other_point[1] - start[1]
        scale = _norm(reach) * _norm(step)
        return _is_zero(reach[0] * step[1] - reach[1] * step[0], self.values, scale)

    def along_the_cord(self, name: str, cord: Cord, d: Vec) -> None:
        """A body that only cords hold stays on the cord's line only if nothing pushes it
        across: its weight, loads, springs and velocity at state 1 lie along the cord (else
        it swings, and the cord's direction changes)."""
        body = self.scene.bodies[name]
        across = sympy.Integer(0)
        if self.scene.gravity is not None:
            across += body.mass * self.symbols["g"] * _cross(self.scene.gravity, d)
        for load in self.scene.loads:
            if load.body == name and load.kind == "force":
                across += self.magnitude(load.name) * _cross(load.direction, d)
        drift = _cross(self.scene.velocities.get(name, ZERO), d)
        for spring in self.scene.springs:  # a spring pulls along its line, which must be d's
            if name in (spring.body, spring.other):
                line = (
                    spring.other_point[0] - spring.point[0],
                    spring.other_point[1] - spring.point[1],
                )
                if not _is_zero(_norm(line), self.values):
                    drift += _cross(line, d) / _norm(line)
        if _is_zero(across, self.values) and _is_zero(drift, self.values):
            return
        error = ValueError(
            f"{name} hangs on the cord {cord.name} alone, but its weight, a load, a spring "
            "or its velocity acts across the cord: it would swing, and the cord's direction "
            "change between the states (hold it on the cord's line with a support, or "
            "write the cord as a link)"
        )
        error.line, error.column = cord.line, cord.column  # type: ignore[attr-defined]
        raise error

    def links(self) -> None:
        if self.scene.links:
            names = ", ".join(link.name for link in self.scene.links)
            self.idle.append(f"the forces in {names} (pin-jointed: no net work on the system)")

    def tensions(self) -> None:
        for cord in self.scene.cords:
            for name, _, d in cord_ends(cord):
                if held_only_by_cords(self.scene, name):
                    self.along_the_cord(name, cord, d)
            self.idle.append(
                f"{cord.name} (inextensible and taut: its pulls on the two ends do equal and "
                "opposite work)"
                if cord.other
                else f"{cord.name} (inextensible and taut, to a fixed point: its end does not "
                "move along it)"
            )


def _work(
    scene: Scene,
    placements: Mapping[str, Placement],
    link_turns: Mapping[str, sympy.Expr],
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> _Work:
    work = _Work(scene, placements, link_turns, symbols, values)
    work.weights()
    work.springs()
    work.loads()
    work.supports()
    work.links()
    work.tensions()
    return work


def _kinetic(scene: Scene, v_G: Mapping[str, Vec], omega: Mapping[str, sympy.Expr]) -> sympy.Expr:
    """T = Σ ½ m v_G² + ½ I_G ω²."""
    terms = []
    for name, body in scene.bodies.items():
        v = v_G.get(name, ZERO)
        terms += [
            tidy(body.mass * dot(v, v) / 2, light=False),
            tidy(body.I_G * omega.get(name, 0) ** 2 / 2, light=False),
        ]
    return sympy.Add(*terms)


def _equation(T1: sympy.Expr, work: _Work, T2: sympy.Expr) -> Equation:
    note = "T1 + ΣU(1→2) = T2"
    if work.notes:
        note += " (" + "; ".join(work.notes) + ")"
    if work.idle:
        note += "; no work: " + ", ".join(work.idle)
    return Equation(sympy.Add(T1, *work.terms), T2, "energy", 0, note)


def _terms(T1: sympy.Expr, work: _Work, T2: sympy.Expr) -> tuple[tuple[str, sympy.Expr], ...]:
    """T1, each work term with the note that names it, and T2: the equation term by term."""
    return (("T1", tidy(T1)), *zip(work.notes, work.terms, strict=True), ("T2", tidy(T2)))


def energy_equations(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    given_values: Mapping[sympy.Symbol, sympy.Expr] | None = None,
) -> tuple[Energy, ...]:
    """T1 + ΣU = T2 for the scene's travel: one per travelling particle, or one for a
    rigid body or linkage moving as a whole."""
    values = dict(given_values or {})
    if all(b.particle for b in scene.bodies.values()) and not scene.links and not scene.cords:
        return tuple(_particle(scene, t, symbols, values) for t in scene.travels.values())
    return (_mechanism(scene, symbols, values),)


def _particle(
    scene: Scene,
    travel: Travel,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> Energy:
    name = travel.body
    if travel.kind == "turns":
        raise ValueError(f"{name} is a particle: it has no angle to turn through")
    shift = particle_shift(scene, travel)
    assert shift is not None
    work = _work(
        scene, {name: Placement(shift, STILL.turn, STILL.cos, STILL.sin)}, {}, symbols, values
    )
    mass = scene.bodies[name].mass
    v1 = scene.velocities.get(name, ZERO)
    rate = None if travel.stops else sympy.Symbol(f"v_2_{name}", real=True)
    T2 = mass * rate**2 / 2 if rate is not None else sympy.Integer(0)
    equation = _equation(mass * dot(v1, v1) / 2, work, T2)
    speed = rate if rate is not None else sympy.Integer(0)
    second = None
    if rate is not None:
        from dynsolve.principles.force_path import speed_by_integration

        found = speed_by_integration(scene, name, symbols, values)
        if found is not None:
            second = (found, FORCE_PATH, f"speed of {name}")
    length = _length(shift, ZERO)  # straight along the travel: its velocity's direction
    velocity = (tidy(speed * shift[0] / length), tidy(speed * shift[1] / length))
    return Energy(
        equation,
        rate,
        {name: speed},
        {},
        (),
        tuple(work.idle),
        second,
        {name: velocity},
        work.named,
        _terms(mass * dot(v1, v1) / 2, work, T2),
        tuple(work.cords),
    )


def _mechanism(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> Energy:
    change = state_change(scene, values)
    work = _work(scene, change.placements, change.link_turns, symbols, values)
    (travel,) = scene.travels.values()
    rates = change.rates
    T1 = _initial_energy(scene, change.initial)
    rate = None
    if not travel.stops:
        prefix = "omega_2" if travel.kind == "turns" else "v_2"
        rate = sympy.Symbol(f"{prefix}_{travel.body}", real=True)
    q = rate if rate is not None else sympy.Integer(0)
    v_G = {n: (v[0] * q, v[1] * q) for n, v in rates.v_G.items()}
    spins = {n: tidy(w * q) for n, w in {**rates.omega, **rates.link_omega}.items()}
    T2 = _kinetic(scene, v_G, spins)
    speeds = {
        n: tidy(sympy.sqrt(v[0] ** 2 + v[1] ** 2), light=False) * q for n, v in rates.v_G.items()
    }
    relations = (*change.relations, f"velocities in state 2 in terms of the {change.rate_name}")
    equation = _equation(T1, work, T2)
    second = None
    if rate is not None and not scene.velocities:
        from dynsolve.principles.force_path import omega_by_constant_alpha

        body = travel.body
        omega = (
            omega_by_constant_alpha(scene, body, change.placements[body].turn, symbols, values)
            if body in scene.bodies
            else None
        )
        ratio = real_value(rates.omega.get(body, 0), values)
        if omega is not None and ratio:  # the rate of travel per unit |ω|
            second = (omega / abs(ratio), CONSTANT_ALPHA, change.rate_name)
        elif scene.cords:  # blocks and drums on cords: constant accelerations
            from dynsolve.principles.constant_motion import HOW, state_one

            motion = state_one(scene, symbols, values, change.placements)
            found = None if motion is None else motion.rate(scene)
            if found is not None:
                second = (found, HOW, change.rate_name)
    return Energy(
        equation,
        rate,
        speeds,
        spins,
        relations,
        tuple(work.idle),
        second,
        {n: (tidy(v[0]), tidy(v[1])) for n, v in v_G.items()},
        work.named,
        _terms(T1, work, T2),
        tuple(work.cords),
    )


def _initial_energy(scene: Scene, rates: Rates) -> sympy.Expr:
    """T1 from a given velocity or angular velocity in state 1 (0 from rest); ``rates``
    are the state-1 velocities per unit rate."""
    if not scene.velocities and not scene.omegas:
        return sympy.Integer(0)
    if scene.omegas:
        name, omega = next(iter(scene.omegas.items()))
        q = omega / rates.omega[name]
    else:
        name, v = next(iter(scene.velocities.items()))
        unit = rates.v_G[name]
        q = dot(v, unit) / dot(unit, unit)
    v_G = {n: (v[0] * q, v[1] * q) for n, v in rates.v_G.items()}
    return _kinetic(scene, v_G, {n: w * q for n, w in rates.omega.items()})
