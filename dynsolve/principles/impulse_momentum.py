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

from collections.abc import Mapping
from dataclasses import replace as replaced

import sympy

from dynsolve.model.scene import Scene, Vec
from dynsolve.numbers import tidy
from dynsolve.principles.newton_euler import Formulation, formulate, touches_at_rim
from dynsolve.system import Equation
from dynsolve.units import Dim

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


def impulse_formulation(scene: Scene, symbols: Mapping[str, sympy.Expr]) -> Formulation:
    """The impulse–momentum equations over the scene's ``travel … for Δt`` interval."""
    why = constant_forces(scene)
    if why:
        raise ValueError(
            f"impulse and momentum over an interval needs constant forces, but {why}; "
            "use work and energy between positions instead"
        )
    (travel,) = scene.travels.values()
    dt = travel.duration
    assert dt is not None
    slipping: dict[str, int] = {}
    rolls = None
    if travel.until == "rolls":
        from dynsolve.principles.until import friction_sense, sliding_contact

        if travel.body not in scene.omegas:  # sliding without spin, not rolling at v_G
            scene = replaced(scene, omegas={**scene.omegas, travel.body: sympy.Integer(0)})

        rolls = sliding_contact(scene, travel)
        slipping[rolls.name] = friction_sense(scene, travel, rolls)
    motion = formulate(scene, symbols, slipping)
    replace: dict[sympy.Symbol, sympy.Expr] = {}
    unknowns: dict[sympy.Symbol, Dim] = {
        s: d for s, d in motion.unknowns.items() if not _is_acceleration(s, motion)
    }
    speeds: dict[str, sympy.Expr] = {}
    spins: dict[str, sympy.Expr] = {}
    several = len(scene.bodies) > 1
    ends: dict[str, tuple[Vec, sympy.Expr]] = {}
    moved: dict[str, Vec] = {}
    for name, kin in motion.kinematics.items():
        v1 = scene.velocities.get(name, ZERO)
        tag = f"_{name}" if several else ""
        end: list[sympy.Expr] = []
        for i, axis in enumerate("xy"):
            symbol = kin.a_G[i]
            if isinstance(symbol, sympy.Symbol) and symbol in motion.unknowns:
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
    equations = tuple(
        Equation(
            tidy((e.lhs * dt).xreplace(replace)),
            tidy((e.rhs * dt).xreplace(replace)),
            e.label,
            e.line,
            _note(e, dt),
        )
        for e in motion.equations
    )
    notes = [
        (
            "impulse and momentum",
            f"the forces stay constant for Δt = {sympy.sstr(dt)}: each reaction below is "
            "its average over the interval, its impulse that times Δt",
        )
    ]
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
                f"kinetic friction F = μk N opposes the slip of {rolls.name} at state 1 "
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
