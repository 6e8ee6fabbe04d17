"""Linear and angular impulse and momentum over an interval in which the forces are constant.

m v_G1 + Σ F Δt = m v_G2 and H_P1 + Σ M_P Δt = H_P2 are the Newton–Euler equations of the
scene multiplied by Δt, with a_G Δt = v_G2 − v_G1 and α Δt = ω₂ − ω₁: each unknown
reaction R stands for its average over the interval (its impulse is R Δt). That holds
when the forces and moment arms stay the same through the interval, so the scene is
checked for it first: no springs or links, pins only at mass centres, rolling or
translating bodies on their flat supports, and forces at G or on translating bodies.
A direction (or point) with no external impulse is named: momentum is conserved there.

>>> import sympy
>>> from dynsolve.model.scene import Scene, Body, Load, Travel
>>> m, P, t = sympy.symbols("m P t", positive=True)
>>> box = Body("box", m, sympy.Integer(0), (0, 0), (0, 0), "particle", (), {}, True, "", 0, 0)
>>> push = Load("force", "P", "box", (0, 0), "G", (1, 0))
>>> scene = Scene({"box": box}, {}, (), (), (push,), None, {},
...               travels={"box": Travel("box", "for", duration=t)})
>>> f = impulse_formulation(scene, {"P": P})
>>> sympy.solve([e.residual for e in f.equations], list(f.unknowns))
{v_2x: P*t/m, v_2y: 0}
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from dataclasses import replace as replaced

import sympy

from dynsolve.model.scene import Body, Scene, Vec
from dynsolve.numbers import real_value, tidy
from dynsolve.principles.newton_euler import Formulation, formulate, touches_at_rim
from dynsolve.results import Check
from dynsolve.system import Equation
from dynsolve.units import Dim, with_unit

ZERO: Vec = (sympy.Integer(0), sympy.Integer(0))


def constant_forces(scene: Scene) -> str:
    """Why the forces might change during the interval ("" when they stay constant).

    >>> import sympy
    >>> from dynsolve.model.scene import Scene, Body, Support
    >>> rod = Body("rod", 1, 1, (1, 0), (0, 0), "rod", (2,), {}, False, "", 0, 0)
    >>> pin = Support("pin", "O", "rod", (0, 0), (0, 1))
    >>> constant_forces(Scene({"rod": rod}, {}, (pin,), (), (), (0, -1), {}))
    "the weight's moment about O changes as rod turns"
    """
    if scene.springs:
        return "a spring's force changes as the scene moves"
    if scene.links:
        return "a link's direction changes as the scene moves"
    for support in scene.supports:
        body = scene.bodies[support.body]
        if support.kind == "pin" and tidy(
            (body.G[0] - support.point[0]) ** 2 + (body.G[1] - support.point[1]) ** 2
        ):
            return f"the weight's moment about {support.name} changes as {body.name} turns"
        rim = touches_at_rim(body, support)  # a round body's contact stays below G
        if (
            support.kind == "contact"
            and not body.particle
            and body.name not in scene.motions
            and not rim
        ):
            return f"the contact point {support.name} moves on {body.name} as it turns"
    for load in scene.loads:
        body = scene.bodies.get(load.body)
        moving_arm = load.kind == "force" and load.point_name != "G"
        if body is not None and moving_arm and scene.motions.get(load.body) != "translation":
            turning = any(
                s.body == load.body and s.kind in ("pin", "rolls") for s in scene.supports
            )
            if turning:
                return f"the moment arm of {load.name} changes as {body.name} turns"
    return ""


def impulse_formulation(
    scene: Scene, symbols: Mapping[str, sympy.Expr], slipping: Mapping[str, int] | None = None
) -> Formulation:
    """The impulse–momentum equations over the scene's ``travel … for Δt`` interval.
    ``slipping`` gives the sense of the kinetic friction at contacts that slide through it
    (±1 along the tangent); the body's velocity at the end is in ``after``."""
    why = constant_forces(scene)
    if why:
        raise ValueError(
            f"impulse and momentum over an interval needs constant forces, but {why}; "
            "use work and energy between positions instead"
        )
    (travel,) = scene.travels.values()
    dt = travel.duration
    assert dt is not None
    slipping = dict(slipping or {})
    rolls = None
    if travel.until == "rolls":
        from dynsolve.principles.until import friction_sense, sliding_contact

        if travel.body not in scene.omegas:  # sliding without spin, not rolling at v_G
            scene = replaced(scene, omegas={**scene.omegas, travel.body: sympy.Integer(0)})

        rolls = sliding_contact(scene, travel)
        if rolls.name not in slipping:
            slipping[rolls.name] = friction_sense(scene, travel, rolls)
    motion = formulate(scene, symbols, slipping, inclines=False)  # a_G in x–y symbols
    replace: dict[sympy.Symbol, sympy.Expr] = {}
    unknowns: dict[sympy.Symbol, Dim] = {
        s: d for s, d in motion.unknowns.items() if not _is_acceleration(s, motion)
    }
    kept = _zero_accelerations(motion)  # a contact kept: that velocity component stays
    replace.update({symbol: sympy.Integer(0) for symbol in kept})
    speeds: dict[str, sympy.Expr] = {}
    spins: dict[str, sympy.Expr] = {}
    several = len(scene.bodies) > 1
    ends: dict[str, tuple[Vec, sympy.Expr]] = {}
    moved: dict[str, Vec] = {}
    works: dict[str, sympy.Expr] = {}  # each force's work over the interval (a second method)
    T_1, T_2 = sympy.Integer(0), sympy.Integer(0)
    for name, kin in motion.kinematics.items():
        v1 = scene.velocities.get(name, ZERO)
        tag = f"_{name}" if several else ""
        end: list[sympy.Expr] = []
        for i, axis in enumerate("xy"):
            symbol = kin.a_G[i]
            if (
                isinstance(symbol, sympy.Symbol)
                and symbol in motion.unknowns
                and symbol not in kept
            ):
                v2 = (
                    sympy.Integer(0) if travel.stops else sympy.Symbol(f"v_2{axis}{tag}", real=True)
                )
                replace[symbol] = (v2 - v1[i]) / dt
                if not travel.stops:
                    unknowns[v2] = Dim(1, 0, -1)
                end.append(v2)
            else:
                end.append(None)  # type: ignore[arg-type]
        alpha = kin.alpha
        if isinstance(alpha, sympy.Symbol) and alpha in motion.unknowns:
            w2 = sympy.Integer(0) if travel.stops else sympy.Symbol(f"omega_2{tag}", real=True)
            replace[alpha] = (w2 - kin.omega) / dt
            if not travel.stops:
                unknowns[w2] = Dim(0, 0, -1)
        spin = tidy(kin.omega + (alpha * dt).xreplace(replace))
        v_G = tuple(tidy(v1[i] + (kin.a_G[i] * dt).xreplace(replace)) for i in range(2))
        speeds[name] = tidy(sympy.sqrt(v_G[0] ** 2 + v_G[1] ** 2))
        spins[name] = spin
        ends[name] = (v_G[0], v_G[1]), spin
        # constant accelerations: Δr_G = (v_G1 + v_G2) Δt / 2
        moved[name] = (tidy((v1[0] + v_G[0]) * dt / 2), tidy((v1[1] + v_G[1]) * dt / 2))
        body = scene.bodies[name]
        on_body = _works(motion, body, (v1, kin.omega), ((v_G[0], v_G[1]), spin), dt, replace)
        for force, work in on_body.items():  # a cord's pull on two bodies: the net work
            works[force] = tidy(works.get(force, 0) + work)
        T_1 += body.mass * (v1[0] ** 2 + v1[1] ** 2) / 2 + body.I_G * kin.omega**2 / 2
        T_2 += body.mass * (v_G[0] ** 2 + v_G[1] ** 2) / 2 + body.I_G * spin**2 / 2
    equations = tuple(
        Equation(
            tidy((e.lhs * dt).xreplace(replace)),
            tidy((e.rhs * dt).xreplace(replace)),
            e.label,
            e.line,
            _note(e, dt),
        )
        for e in motion.equations
        if e not in kept.values()
    )
    notes = [
        (
            "impulse and momentum",
            f"the forces stay constant for Δt = {sympy.sstr(dt)}: each reaction below is "
            "its average over the interval, its impulse that times Δt",
        )
    ]
    if kept:
        notes.append(
            (
                "contact kept",
                "; ".join(
                    f"{e.note}, so (v_G)_{_axis(symbol, motion)} is the same at both ends"
                    for symbol, e in kept.items()
                ),
            )
        )
    events: tuple[tuple[str, sympy.Expr, str], ...] = ()
    if rolls is not None:
        from dynsolve.principles.until import contact_slip

        body = scene.bodies[travel.body]
        v_G2, w2 = ends[travel.body]
        slip = contact_slip(body, rolls, v_G2, w2)
        r = tuple(sympy.sstr(tidy(rolls.point[i] - body.G[i])) for i in range(2))
        number = len(equations) + 1
        rule = Equation(
            slip,
            sympy.Integer(0),
            f"eq. {number}",
            number,
            f"it rolls at the end: the contact point {rolls.name} stops slipping, "
            f"(v_G2 + ω₂ k × r_{rolls.name}/G)·t = 0 with r_{rolls.name}/G = ({r[0]}, {r[1]})",
        )
        equations = (*equations, rule)
        notes.append(
            (
                f"slides until it rolls at {rolls.name}",
                f"kinetic friction F = μk N opposes the slip of {rolls.name} at the start "
                f"for the whole interval (the slip falls linearly to zero at Δt = "
                f"{sympy.sstr(dt)}); afterwards {travel.body} rolls",
            )
        )
        events = (
            (
                f"slides until it rolls at {rolls.name}",
                dt,
                f"the slip of {rolls.name} reaches zero after Δt = {{value:.4g}} s",
            ),
        )
    slips = {}  # each contact sliding at the start (or stated to): its slip at both ends
    for support in scene.supports:
        declared = support.friction_sense is not None and slipping.get(support.name) != 0
        sliding = support.name in motion.sliding or declared
        if sliding and support.body in ends and rolls is None:
            body, ((v_x, v_y), spin) = scene.bodies[support.body], ends[support.body]
            r = (support.point[0] - body.G[0], support.point[1] - body.G[1])
            v_P2 = (v_x - spin * r[1], v_y + spin * r[0])  # v_G2 + ω₂ k × r_P/G
            end_slip = tidy(v_P2[0] * support.tangent[0] + v_P2[1] * support.tangent[1])
            v_1, w_1 = scene.velocities.get(support.body, ZERO), motion.kinematics[body.name].omega
            v_P1 = (v_1[0] - w_1 * r[1], v_1[1] + w_1 * r[0])  # 0 from rest
            start = tidy(v_P1[0] * support.tangent[0] + v_P1[1] * support.tangent[1])
            slips[support.name] = (start, end_slip)
    return Formulation(
        equations=equations,
        unknowns=unknowns,
        forces=motion.forces,
        couples=motion.couples,
        kinematics={},
        moment_points=motion.moment_points,
        reactions=motion.reactions,
        speeds=speeds,
        spins=spins,
        notes=tuple(notes),
        displacements=moved,
        events=events,
        after={name: v_G for name, (v_G, _) in ends.items()},
        interval_energy=(tidy(T_1), works, tidy(T_2)),
        sliding=motion.sliding,  # contacts slipping at the start: kinetic friction, said so
        interval_slips=slips,
    )


def _works(
    motion: Formulation,
    body: Body,
    start: tuple[Vec, sympy.Expr],
    end: tuple[Vec, sympy.Expr],
    dt: sympy.Expr,
    replace: Mapping[sympy.Symbol, sympy.Expr],
) -> dict[str, sympy.Expr]:
    """The work of each force and couple on ``body`` over the interval.

    The forces are constant and each acts at a point fixed relative to G (G itself, a
    point of a translating body, or a round body's contact below G), whose velocity
    v_P = v_G + ω k × r_P/G changes linearly in time: U = F·(v_P1 + v_P2) Δt/2, and a
    couple's U = M (ω₁ + ω₂) Δt/2. Not used to solve: T₁ + ΣU = T₂ is checked with them.
    """
    (v1, w1), (v2, w2) = start, end
    works = {}
    for force in motion.forces.get(body.name, ()):
        r = (force.point[0] - body.G[0], force.point[1] - body.G[1])
        v_P1 = (v1[0] - w1 * r[1], v1[1] + w1 * r[0])
        v_P2 = (v2[0] - w2 * r[1], v2[1] + w2 * r[0])
        F = tuple((sympy.Integer(0) + c).xreplace(replace) for c in force.vector)
        power = F[0] * (v_P1[0] + v_P2[0]) + F[1] * (v_P1[1] + v_P2[1])
        works[force.name] = tidy(power * dt / 2)
    for couple in motion.couples.get(body.name, ()):
        works[couple.name] = tidy((sympy.Integer(0) + couple.moment) * (w1 + w2) * dt / 2)
    return works


def energy_check(
    what: str,
    energy: tuple[sympy.Expr, Mapping[str, sympy.Expr], sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    agreement: float,
    system: str,
    state: int = 1,
    kinetic: Collection[str] = (),
) -> Check | None:
    """T_k + ΣU = T_{k+1} over an interval solved by impulse and momentum (from
    ``state`` k), with the work of each force from the motion found (None where symbols
    remain). Kinetic friction (the forces named in ``kinetic``) opposes the slip of the
    point it acts on, so its work relative to the fixed surface is never positive: where
    it is, the slide assumed is wrong and the check fails, however well the sum agrees.
    Every energy is shown with its unit in ``system`` (J, ft·lb).

    >>> import sympy
    >>> m = sympy.Symbol("m")
    >>> energy_check("stage 2", (m * 8, {"F_C": -m * 8}, 0), {m: 2}, 1e-6, "SI").passed
    True
    >>> energy_check("", (0, {"P": -6, "F_C": 7}, 1), {}, 1e-6, "FPS", kinetic={"F_C"}).passed
    False
    """
    T_1, works, T_2 = energy
    numbers = [real_value(e, values) for e in (T_1, *works.values(), T_2)]
    if any(n is None for n in numbers):
        return None
    t_1, *u, t_2 = numbers

    def energy(value: float) -> str:
        return with_unit(value, "energy", system, ".7g")

    scale = max(abs(n) for n in numbers) or 1.0  # type: ignore[arg-type]
    gap = abs(t_1 + sum(u) - t_2) / scale  # type: ignore[operator]
    terms = ", ".join(
        f"U_{n} = {with_unit(v, 'energy', system, '.6g')}" for n, v in zip(works, u, strict=True)
    )
    pushing = [
        f"U_{n} = {with_unit(v, 'energy', system, '+.4g')}"
        for n, v in zip(works, u, strict=True)
        if n in kinetic and v > 1e-9 * scale  # type: ignore[operator]
    ]
    detail = (
        f"T{state} + ΣU = {energy(t_1)} + ({terms}) = {energy(t_1 + sum(u))}; "
        f"T{state + 1} = {energy(t_2)}; "
        f"relative difference {gap:.1e}"
    )
    if pushing:
        detail = (
            f"kinetic friction does positive work ({', '.join(pushing)}): friction cannot push "
            f"a body along the surface it slides on, so the slide assumed is wrong; {detail}"
        )
    return Check(
        f"second method: work and energy ({what})" if what else "second method: work and energy",
        gap <= agreement and not pushing,
        detail,
    )


def _zero_accelerations(motion: Formulation) -> dict[sympy.Symbol, Equation]:
    """The accelerations that a constraint sets to zero on its own (a contact kept: the
    centre keeps its height), with that equation: over the interval the velocity component
    does not change, so it is no unknown and the equation is not repeated."""
    zero = {}
    for equation in motion.equations:
        residual = tidy(equation.lhs - equation.rhs)
        if len(residual.free_symbols) != 1:
            continue
        (symbol,) = residual.free_symbols
        linear = sympy.Poly(residual, symbol).degree() == 1 and residual.subs(symbol, 0) == 0
        if linear and _is_acceleration(symbol, motion):
            zero[symbol] = equation
    return zero


def _axis(symbol: sympy.Symbol, motion: Formulation) -> str:
    """The axis ("x" or "y") of the acceleration component ``symbol``."""
    return next(
        "xy"[i] for kin in motion.kinematics.values() for i in range(2) if kin.a_G[i] == symbol
    )


def _is_acceleration(symbol: sympy.Symbol, motion: Formulation) -> bool:
    return any(symbol == kin.alpha or symbol in kin.a_G for kin in motion.kinematics.values())


def _note(equation: Equation, dt: sympy.Expr) -> str:
    """The Newton–Euler principle of ``equation`` read over the interval."""
    note = equation.note
    if note.startswith("ΣF"):
        axis = note[3:].split(" ")[0]
        conserved = (
            " (no external impulse along it: momentum conserved)" if equation.lhs == 0 else ""
        )
        return (
            f"linear impulse and momentum along {axis}: m v_G1 + Σ F Δt = m v_G2{conserved}; {note}"
        )
    if note.startswith("ΣM"):
        point = note[3:].split(" ")[0]
        conserved = (
            " (no external angular impulse about it: conserved)" if equation.lhs == 0 else ""
        )
        return f"angular impulse and momentum about {point}: H1 + Σ M Δt = H2{conserved}; {note}"
    return f"{note}, over Δt (velocities)"
