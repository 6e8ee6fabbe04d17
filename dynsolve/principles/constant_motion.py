"""Scenes whose accelerations stay constant between two states, and the cords they keep taut.

Drums pinned at their centres, wheels rolling on flat ground and blocks that translate on
straight surfaces, joined by cords that keep their direction and pulled by constant loads,
have the same geometry of forces at every position: the accelerations that Newton–Euler
gives at state 1 hold all the way, so v₂² = v₁² + 2 a s (ω₂² = ω₁² + 2 α Δθ) is a second
method for the work–energy answer, and each cord's tension at state 1 is its tension
throughout (its "taut between the states" is then checked, not assumed).

>>> import sympy
>>> from dynsolve.model.scene import Body, Cord, Scene, Support, Travel
>>> drum = Body("drum", 60, sympy.Rational(15, 4), (0, 0), (0, 0), "", (), {}, False, "", 0, 0)
>>> block = Body("block", 20, 0, (0.4, -0.8), (0.4, -0.8), "particle", (), {}, True, "", 0, 0)
>>> pin = Support("pin", "O", "drum", (0, 0), (0, 1))
>>> cord = Cord("T", "drum", (0.4, 0), (0, -1), "block", (0.4, -0.8))
>>> down = Travel("block", "by", distance=2, direction=(0, -1))
>>> scene = Scene({"drum": drum, "block": block}, {}, (pin,), (cord,), (), (0, -1), {},
...               travels={"block": down})
>>> motion = state_one(scene, {"g": 9.81}, {})
>>> round(motion.rate(scene), 6)  # m_b g h = ½ (m_b + I_O/r²) v²
4.250569
>>> round(motion.tensions["T"], 2)
105.86
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy

from dynsolve.model.scene import Scene
from dynsolve.model.states import Placement, cord_ends, is_wound, placements_of
from dynsolve.numbers import real_value, tidy
from dynsolve.units import with_unit

HOW = (
    "ΣF = m a_G, ΣM = I α at state 1: every acceleration is constant (constant loads, "
    "cords that keep their direction, drums turning about G), from rest v₂² = 2 a s "
    "(ω₂² = 2 α Δθ)"
)


def unsteady(scene: Scene) -> str | None:
    """Why the accelerations of ``scene`` may change between the states (None: they do not).

    A turning body keeps the geometry of its forces only when each acts at G, through a
    pin at G, at a flat rolling contact, or along a cord wound on it; springs, links and
    impacts change with the position.
    """
    if scene.springs or scene.links or scene.pivots:
        return "springs, links or impacts change the forces along the way"
    for name, body in scene.bodies.items():
        if body.particle or scene.motions.get(name) == "translation":
            continue
        supports = [s for s in scene.supports if s.body == name]
        if any(s.kind == "base" for s in supports):
            continue
        for support in supports:
            at_G = support.kind == "pin" and _same(support.point, body.G)
            if not (at_G or support.kind == "rolls"):
                return f"{name} turns about {support.name}, away from its G"
        for load in scene.loads:
            if load.body == name and load.kind == "force" and not _same(load.point, body.G):
                return f"{load.name} acts on the turning {name} away from its G"
        for cord in scene.cords:
            for end, P, d in cord_ends(cord):
                if end == name and not is_wound(scene, name, P, d):
                    return f"the cord {cord.name} is tied to a point of the turning {name}"
    return None


def _same(a: tuple[sympy.Expr, sympy.Expr], b: tuple[sympy.Expr, sympy.Expr]) -> bool:
    return tidy(a[0] - b[0]) == 0 and tidy(a[1] - b[1]) == 0


@dataclass(frozen=True)
class StateOne:
    """The accelerations and cord tensions that Newton–Euler gives at state 1 (numbers)."""

    a_G: Mapping[str, tuple[float, float]]
    alpha: Mapping[str, float]
    tensions: Mapping[str, float]
    steady: str | None  # why they may change along the way (None: constant)
    placements: Mapping[str, Placement] = field(default_factory=dict)  # of state 2

    def rate(self, scene: Scene) -> float | None:
        """The rate of travel in state 2 from rest, by v² = 2 a s along a straight travel
        (ω² = 2 α Δθ for a turn); None if the motion is not constant or runs the other way.
        """
        if self.steady is not None or scene.velocities or scene.omegas:
            return None
        (travel,) = scene.travels.values()
        placement = self.placements[travel.body]
        if travel.kind == "turns":
            step = real_value(placement.turn, scene.values)
            rate = self.alpha.get(travel.body)
        else:
            shift = [real_value(c, scene.values) for c in placement.shift]
            if None in shift:
                return None
            sx, sy = shift  # type: ignore[misc]
            step = (sx**2 + sy**2) ** 0.5
            a = self.a_G.get(travel.body)
            rate = None if a is None or step == 0 else (a[0] * sx + a[1] * sy) / step
        if step is None or rate is None:
            return None
        squared = 2 * rate * step
        return squared**0.5 if squared >= 0 else None


def state_two(scene: Scene) -> Mapping[str, Placement] | None:
    """Each body's placement in state 2 (None if state 2 is not found)."""
    try:
        placements, _ = placements_of(scene)
    except ValueError:
        return None
    return placements


def sliding(
    scene: Scene,
    values: Mapping[sympy.Symbol, sympy.Expr],
    placements: Mapping[str, Placement] | None,
) -> dict[str, int] | None:
    """The contacts whose point slides between the states to ``placements`` (state 2),
    each with the sense (±1 along its tangent) of the kinetic friction against the slide;
    None if state 2 is not found."""
    from dynsolve.principles.newton_euler import dot

    if placements is None:
        return None
    slipping = {}
    for support in scene.supports:
        if support.smooth or support.kind not in ("contact", "base"):
            continue
        slide = real_value(dot(placements[support.body].shift, support.tangent), values)
        if slide:  # friction opposes the slide
            slipping[support.name] = -1 if slide > 0 else 1
    return slipping


def state_one(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    placements: Mapping[str, Placement] | None = None,
) -> StateOne | None:
    """Newton–Euler at state 1, solved with numbers; a contact that slides between the
    states to ``placements`` (state 2, found here if not given; its point moving along
    the surface) has kinetic friction against the motion. The equations are written with
    the givens' values put in (nothing of them is shown). None where the instant has no
    unique solution.
    """
    from dynsolve.principles.newton_euler import VelocityConflict, formulate
    from dynsolve.simulate.equations import numeric_scene

    values = {**scene.values, **values}
    placements = state_two(scene) if placements is None else placements
    slipping = sliding(scene, values, placements)
    if slipping is None or placements is None:
        return None
    numbers = {name: (sympy.Integer(0) + v).xreplace(values) for name, v in symbols.items()}
    try:
        formulation = formulate(numeric_scene(scene, values), numbers, slipping, inclines=False)
    except VelocityConflict:
        raise  # the givens contradict the scene: an error, not an instant to skip
    except ValueError:  # the instant cannot be written (a cord across the motion …)
        return None
    residuals = [sympy.N((e.lhs - e.rhs).xreplace(dict(values))) for e in formulation.equations]
    unknowns = list(formulation.unknowns)
    found = sympy.linsolve(residuals, unknowns)
    if len(found) != 1:
        return None
    (solution,) = tuple(found)
    if any(v.free_symbols for v in solution):
        return None
    solved = dict(zip(unknowns, solution, strict=True))

    def number(expr: sympy.Expr) -> float | None:
        return real_value((sympy.Integer(0) + expr).xreplace(solved), values)

    a_G, alpha = {}, {}
    for name, kinematics in formulation.kinematics.items():
        ax, ay = (number(c) for c in kinematics.a_G)
        if ax is not None and ay is not None:
            a_G[name] = (ax, ay)
        turning = number(kinematics.alpha)
        if turning is not None:
            alpha[name] = turning
    tensions = {}
    for cord in scene.cords:
        tension = number(formulation.reactions[cord.name][0])
        if tension is not None:
            tensions[cord.name] = tension
    return StateOne(a_G, alpha, tensions, unsteady(scene), placements)


def taut_details(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> list[tuple[str, bool | None, str]]:
    """``(name, holds, detail)`` for each cord assumed taut between the states (``holds``
    None where it could not be checked: no tension at state 1 to check it with): its tension
    at state 1 from Newton–Euler, which is its tension throughout when the accelerations are
    constant; otherwise also at :data:`~dynsolve.principles.cord_travel.SAMPLES` states
    along the travel up to state 2 (Newton–Euler at each, with its geometry, spring forces
    and velocities), and where it would fall below zero the cord goes slack there: fails."""
    if not scene.cords:
        return []
    placements = state_two(scene)
    motion = state_one(scene, symbols, values, placements)
    along: list[tuple[float, dict[str, float]]] = []
    slipping = sliding(scene, {**scene.values, **values}, placements) or {}
    if motion is not None and motion.steady is not None:
        from dynsolve.principles.cord_travel import tensions_along

        along = tensions_along(scene, symbols, values, slipping)
    found: list[tuple[str, bool | None, str]] = []
    for cord in scene.cords:
        name = f"cord {cord.name} taut between the states"
        T = None if motion is None else motion.tensions.get(cord.name)
        if T is None:
            detail = (
                "assumed (inextensible, its tension doing no net work): Newton–Euler at "
                "state 1 does not give its tension, so it is not checked"
            )
            found.append((name, None, detail))
            continue
        holds = T >= 0
        tension = with_unit(T, "force", system)
        detail = f"{cord.name} = {tension} {'≥' if holds else '<'} 0 at state 1 (Newton–Euler)"
        assert motion is not None
        if not holds:
            detail += ": the cord goes slack, and the scene does not move as one"
        elif motion.steady is None:
            detail += "; the accelerations are constant, so it stays so to state 2"
        else:
            holds, detail = _along(
                scene, symbols, values, cord.name, (along, slipping), detail, motion.steady, system
            )
        found.append((name, holds, detail))
    return found


def _along(
    scene: Scene,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    name: str,
    sampled_along: tuple[list[tuple[float, dict[str, float]]], Mapping[str, int]],
    detail: str,
    steady: str,
    system: str,
) -> tuple[bool, str]:
    """Whether the cord ``name`` stays taut at the sampled states (``sampled_along``: the
    tensions there, and the contacts sliding), and the detail saying where it was checked
    and, if it goes slack, where."""
    from dynsolve.principles.cord_travel import SAMPLES, slack_at

    along, slipping = sampled_along
    sampled = [(f, t[name]) for f, t in along if name in t]
    if not sampled:
        return True, detail + f"; checked there only ({steady})"
    end = next((T for f, T in sampled if f == 1.0), None)
    if end is not None:
        detail += f", {name} = {with_unit(end, 'force', system)} at state 2"
    low = min(T for _, T in sampled)
    if low >= 0:
        return True, detail + (
            f"; ≥ 0 at {len(sampled)} of {SAMPLES} states sampled along the travel ({steady}): "
            "between them it is not checked"
        )
    fraction = slack_at(scene, symbols, values, slipping, name, along)
    where = "between the samples" if fraction is None else _distance(scene, fraction)
    return False, detail + (
        f"; it falls below 0 along the travel ({steady}): the cord goes slack at {where}, "
        "past which the bodies move apart: split the travel there (the work–energy answer "
        "with the cord kept taut is wrong)"
    )


def _distance(scene: Scene, fraction: float) -> str:
    """Where ``fraction`` of the travel is, in words with the number."""
    (travel,) = scene.travels.values()
    total = travel.distance if travel.kind == "by" else travel.angle
    size = real_value(total, scene.values) if total is not None else None
    if size is None:
        return f"{fraction:.4g} of the travel"
    what = "Δθ" if travel.kind == "turns" else "a travel"
    return f"{what} of {abs(size) * fraction:.4g} of the {abs(size):.4g} ({fraction:.4g} of it)"
