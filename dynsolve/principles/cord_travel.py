"""Cord tensions along a travel whose accelerations change: Newton–Euler at sampled states.

Where springs or links change the forces between the states, a cord's
tension at state 1 says nothing about the rest of the way. Each sampled state is the
travel cut short at a fraction λ of its length: its placements (:func:`placements_of`)
move every body, point and spring end there; its rate of travel comes from T1 + ΣU = T2
over the shortened travel; Newton–Euler at that instant, with those velocities, gives the
cords' tensions. Where one falls below zero the cord goes slack, found by bisection. The
givens' values are put in first (as floats), so no sample needs symbolic tidying.

>>> from dynsolve.model.scene import Body, Cord, Scene, Spring, Support, Travel
>>> drum = Body("drum", 10, 0.4, (0, 0), (0, 0), "", (), {}, False, "", 0, 0)
>>> block = Body("block", 5, 0, (0.2, -0.6), (0.2, -0.6), "particle", (), {}, True, "", 0, 0)
>>> pin = Support("pin", "O", "drum", (0, 0), (0, 1))
>>> cord = Cord("T", "drum", (0.2, 0), (0, -1), "block", (0.2, -0.6))
>>> spring = Spring("S", "block", (0.2, -0.6), "", (0.2, -1.1), 500, 0.5)
>>> scene = Scene({"drum": drum, "block": block}, {}, (pin,), (cord,), (), (0, -1), {},
...               springs=(spring,),
...               travels={"block": Travel("block", "by", distance=0.15, direction=(0, -1))})
>>> along = tensions_along(scene, {"g": 9.81}, {}, {})
>>> round(along[-1][1]["T"], 2)  # state 2: T = (I/r²) a = 10 (5 g − 500·0.15)/15
-17.3
>>> round(slack_at(scene, {"g": 9.81}, {}, {}, "T", along), 4)  # m g/k = 0.0981 of 0.15
0.654
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

import sympy

from dynsolve.model.scene import Scene, Travel, Vec
from dynsolve.model.states import Placement, cord_ends, is_wound, placements_of, point_after
from dynsolve.numbers import real_value

SAMPLES = 8  # states sampled along the travel (besides state 1)
BISECTIONS = 20


def shortened(travel: Travel, fraction: float) -> Travel | None:
    """``travel`` cut short at ``fraction`` of its length (None: a travel not by a
    distance or an angle, which is not sampled)."""
    if travel.kind == "by" and travel.distance is not None:
        return replace(travel, distance=travel.distance * fraction, stops=False)
    if travel.kind == "turns" and travel.angle is not None:
        return replace(travel, angle=travel.angle * fraction, stops=False)
    return None


def _moved_scene(
    scene: Scene,
    placements: Mapping[str, Placement],
    v_G: Mapping[str, Vec],
    omega: Mapping[str, float],
) -> Scene:
    """``scene`` at its placements, moving with ``v_G`` and ``omega``: every body, its
    points and the ends of supports, cords, springs and loads carried there."""

    def at(name: str, P: Vec) -> Vec:
        return point_after(scene.bodies[name], placements[name], P) if name else P

    def by_G(name: str, P: Vec) -> Vec:
        shift = placements[name].shift
        return (P[0] + shift[0], P[1] + shift[1])

    bodies = {
        n: replace(
            b,
            G=at(n, b.G),
            origin=at(n, b.origin),
            points={k: at(n, P) for k, P in b.points.items()},
        )
        for n, b in scene.bodies.items()
    }
    links = tuple(
        replace(ln, point=at(ln.body, ln.point), other_point=at(ln.other, ln.other_point))
        for ln in scene.links
    )
    supports = tuple(
        s
        if s.kind == "pin"
        else replace(s, point=(by_G if s.kind != "contact" else at)(s.body, s.point))
        for s in scene.supports
    )
    cords = []
    for cord in scene.cords:
        ends = [by_G(n, P) if is_wound(scene, n, P, d) else at(n, P) for n, P, d in cord_ends(cord)]
        other = ends[1] if len(ends) > 1 else cord.other_point
        cords.append(replace(cord, point=ends[0], other_point=other))
    springs = tuple(
        replace(s, point=at(s.body, s.point), other_point=at(s.other, s.other_point))
        for s in scene.springs
    )
    loads = tuple(replace(ld, point=at(ld.body, ld.point)) for ld in scene.loads)
    return replace(
        scene,
        bodies=bodies,
        supports=supports,
        cords=tuple(cords),
        springs=springs,
        links=links,
        loads=loads,
        velocities=dict(v_G),
        omegas=dict(omega),
    )


def tensions_at(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    slipping: Mapping[str, int],
    fraction: float,
) -> dict[str, float] | None:
    """Each cord's tension at ``fraction`` of the travel (None where it cannot be found:
    the scene stops before it, or the instant has no unique solution)."""
    from dynsolve.principles.newton_euler import formulate
    from dynsolve.principles.work_energy import energy_equations
    from dynsolve.simulate.equations import numeric_scene

    (travel,) = scene.travels.values()
    part = shortened(travel, fraction)
    if part is None or scene.pivots or scene.impacts or scene.movers:
        return None
    if scene.velocities or scene.omegas:  # T1 ≠ 0: not written for the shortened travels
        return None
    values = {**scene.values, **values}
    numbers = {k: sympy.N(v) for k, v in values.items()}  # floats: no symbolic tidying
    partial = numeric_scene(replace(scene, travels={travel.body: part}), numbers)
    try:
        placements, _ = placements_of(partial)
        (energy,) = energy_equations(partial, symbols, values)
    except (ValueError, ArithmeticError):
        return None
    if energy.rate is None:
        return None
    values = {k: v for k, v in values.items() if k != energy.rate}  # the answer at state 2
    residual = energy.equation.residual.xreplace(values)
    c = real_value(residual.xreplace({energy.rate: 0}), values)
    a = real_value(residual.xreplace({energy.rate: 1}), values)
    if c is None or a is None or a == c or -c / (a - c) < 0:
        return None
    q = (-c / (a - c)) ** 0.5
    at_q = {energy.rate: sympy.Float(q)}
    v_G = {n: (v[0].xreplace(at_q), v[1].xreplace(at_q)) for n, v in energy.velocities.items()}
    spins = {n: w.xreplace(at_q) for n, w in energy.spins.items() if n in scene.bodies}
    moved = _moved_scene(partial, placements, v_G, spins)
    try:
        formulation = formulate(moved, symbols, slipping, inclines=False)
    except (ValueError, ArithmeticError):
        return None
    residuals = [sympy.N((e.lhs - e.rhs).xreplace(dict(values))) for e in formulation.equations]
    found = sympy.linsolve(residuals, list(formulation.unknowns))
    if len(found) != 1:
        return None
    solved = dict(zip(formulation.unknowns, next(iter(found)), strict=True))
    tensions = {}
    for cord in scene.cords:
        T = real_value(
            (sympy.Integer(0) + formulation.reactions[cord.name][0]).xreplace(solved), values
        )
        if T is not None:
            tensions[cord.name] = T
    return tensions


def tensions_along(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    slipping: Mapping[str, int],
) -> list[tuple[float, dict[str, float]]]:
    """``(λ, tensions)`` at λ = 1/SAMPLES … 1 of the travel, where they can be found."""
    found = []
    for k in range(1, SAMPLES + 1):
        tensions = tensions_at(scene, symbols, values, slipping, k / SAMPLES)
        if tensions is not None:
            found.append((k / SAMPLES, tensions))
    return found


def slack_at(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    slipping: Mapping[str, int],
    name: str,
    along: list[tuple[float, dict[str, float]]],
) -> float | None:
    """The fraction of the travel where the cord ``name`` first goes slack (its tension
    through zero), bisected between the samples of ``along`` (state 1 taut)."""
    low = 0.0
    for fraction, tensions in along:
        if tensions.get(name, 0.0) < 0:
            high = fraction
            break
        low = fraction
    else:
        return None
    for _ in range(BISECTIONS):
        middle = (low + high) / 2
        T = (tensions_at(scene, symbols, values, slipping, middle) or {}).get(name)
        if T is None:
            return None
        low, high = (middle, high) if T >= 0 else (low, middle)
    return (low + high) / 2
