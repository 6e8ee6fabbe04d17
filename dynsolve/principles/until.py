"""The end of an interval fixed by an event: a round body slides until it rolls.

``travel B: for t_1, until rolls`` describes a body whose contact point slips at state 1
(a bowling ball thrown with backspin, a disk set down spinning): kinetic friction
μk N opposes the slip, the forces stay constant, and the interval ends when the contact
point comes to rest, v_G + ω × r_P/G = 0 along the surface. That condition fixes the
unknown time t_1; the friction's sense is that of the slip at state 1, which holds
through the interval exactly when t_1 > 0 (the slip velocity changes linearly in time).

>>> import sympy
>>> from dynsolve.model.scene import Body, Support, WORDS
>>> m, r = sympy.symbols("m r", positive=True)
>>> disk = Body("disk", m, m * r**2 / 2, (0, r), (0, r), "disk", (r,), {}, False, "", 0, 0)
>>> C = Support("contact", "C", "disk", (0, 0), WORDS["up"], mu_k=sympy.Rational(1, 5))
>>> contact_slip(disk, C, (5, 0), 10)   # v_P = v_G + ω r = 5 + 10 r, along +x
10*r + 5
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import sympy

from dynsolve.model.scene import Body, Scene, Support, Travel, Vec
from dynsolve.names import pretty
from dynsolve.numbers import real_value, tidy, tidying_lightly
from dynsolve.principles.newton_euler import Formulation, cross, dot
from dynsolve.simulate.compiled import float_scalar
from dynsolve.system import Constraint, Equation
from dynsolve.units import Dim


def contact_slip(body: Body, support: Support, v_G: Vec, omega: sympy.Expr) -> sympy.Expr:
    """The velocity of the body's point at the contact along the contact's tangent."""
    r = (support.point[0] - body.G[0], support.point[1] - body.G[1])
    v_P = (v_G[0] - omega * r[1], v_G[1] + omega * r[0])
    return tidy(dot(v_P, support.tangent))


def sliding_contact(scene: Scene, travel: Travel) -> Support:
    """The one rough contact of the travelling body that slides until it rolls."""
    rough = [
        s for s in scene.supports if s.body == travel.body and s.kind == "contact" and not s.smooth
    ]
    if len(rough) != 1 or rough[0].mu_k is None:
        raise UntilError(
            travel,
            f"'until rolls' needs {travel.body} on one rough contact with mu_k "
            f"(found {len(rough)} rough contacts)",
        )
    return rough[0]


def friction_sense(scene: Scene, travel: Travel, support: Support) -> int:
    """±1 along the tangent: kinetic friction opposes the slip of the contact point at
    state 1 (or the stated ``slides`` when the slip's sign depends on symbolic givens)."""
    body = scene.bodies[travel.body]
    zero = sympy.Integer(0)
    v_G = scene.velocities.get(travel.body, (zero, zero))
    slip = contact_slip(body, support, v_G, scene.omegas.get(travel.body, zero))
    value = real_value(slip, scene.values)
    if value is None:
        if support.friction_sense is not None:
            return support.friction_sense
        raise UntilError(
            travel,
            f"the sense of the slip at {support.name} depends on symbolic givens; state it "
            f"on the contact ('slides right')",
        )
    if value == 0:
        raise UntilError(
            travel,
            f"{travel.body} already rolls at state 1 (its contact point {support.name} does not "
            "slip): there is no slide to end",
        )
    return -1 if value > 0 else 1


class UntilError(ValueError):
    """An until event that cannot be followed, with the line of its travel."""

    def __init__(self, travel: Travel, message: str) -> None:
        super().__init__(message)
        self.line, self.column = travel.line, travel.column


# ---- a particle on a circle until its cord goes slack or it leaves the surface
@dataclass(frozen=True)
class Circle:
    """The circle a particle moves on: centre O, radius R, and the side of its support
    (``side`` +1: the cord or surface pulls/pushes toward O, −1: the surface pushes away)."""

    centre: Vec
    radius: sympy.Expr
    side: int
    what: str  # "the cord L", "the surface dome"
    force: str  # the name of the tension or normal force that falls to zero


@dataclass(frozen=True)
class CircleUntil:
    """A particle on a circle until its support lets go: the two equations, the unknown
    speed and turned angle at the event, and what follows from them."""

    equations: tuple[Equation, Equation]  # work and energy; ΣF_n = m v²/R with the force 0
    speed: sympy.Symbol
    theta: sympy.Symbol
    height: sympy.Expr  # how far G rises (up positive) until the event
    velocity: Vec  # v_G at the event
    condition: Constraint  # θ's root branch: the first zero of the force after the start
    events: tuple[tuple[str, sympy.Expr, str], ...]  # the support holds at the start
    note: tuple[str, str]


def until_formulation(scene: Scene, symbols: Mapping[str, sympy.Expr]) -> Formulation:
    """Work–energy and ΣF_n = m v²/R for a particle on a circle until the tension of its
    cord, or the push of its surface, falls to zero: the angle turned and the speed there.

    The turned angle θ is an unknown with the root branch stated: the first zero of the
    force after the start, in the sense of motion (a constraint on θ keeps that root).
    """
    (travel,) = scene.travels.values()
    found = circle_until(scene, symbols, travel)
    from dynsolve.principles.newton_euler import bare_formulation

    name = travel.body
    return bare_formulation(
        scene.bodies,
        equations=found.equations,
        unknowns={found.speed: Dim(1, 0, -1), found.theta: Dim()},  # this order solves fastest
        speeds={name: found.speed},
        turns={name: found.theta},
        heights={name: found.height},
        constraints=(found.condition,),
        events=found.events,
        notes=(found.note,),
    )


def circle_until(
    scene: Scene, symbols: Mapping[str, sympy.Expr], travel: Travel, state: int = 2
) -> CircleUntil:
    """The equations of ``travel`` (``until CORD slack`` or ``until contact lost``) of a
    particle on a circle, from its velocity in ``scene`` (numbers for the root's branch
    from ``scene.values``); the unknowns are named for the end ``state``."""
    name = travel.body
    body = scene.bodies[name]
    if not body.particle:
        raise UntilError(travel, f"'until {travel.until}' is for a particle: {name} is a body")
    if scene.gravity is None:
        raise UntilError(travel, f"'until {travel.until}' needs gravity: add 'gravity'")
    if any(load.body == name for load in scene.loads) or scene.springs:
        raise UntilError(
            travel,
            f"'until {travel.until}' follows a particle under its weight and its support only",
        )
    circle = _circle(scene, travel)
    values = scene.values
    g = symbols["g"]
    p1, C0, R = body.G, circle.centre, circle.radius  # C0: the circle's centre
    zero = sympy.Integer(0)
    v1 = scene.velocities.get(name, (zero, zero))
    r1 = (tidy(p1[0] - C0[0]), tidy(p1[1] - C0[1]))
    radial_speed = real_value(dot(v1, r1), values) or 0.0
    size = real_value(R * sympy.sqrt(dot(v1, v1)), values) or 0.0
    if abs(radial_speed) > 1e-9 * size:
        raise UntilError(
            travel,
            f"{name}'s velocity at state {state - 1} is not along its circle (it must be tangent)",
        )
    gravity = (g * scene.gravity[0], g * scene.gravity[1])
    spin = real_value(cross(r1, v1), values)
    if spin is None:
        raise UntilError(travel, f"'until {travel.until}' needs numbers for the givens")
    if spin == 0:
        spin = real_value(cross(r1, gravity), values) or 0.0
    if spin == 0:
        raise UntilError(
            travel, f"{name} is at rest where its weight has no part along its circle: it stays"
        )
    s = 1 if spin > 0 else -1  # ccw +1
    theta = sympy.Symbol(f"theta_{state}_{name}", positive=True)
    speed = sympy.Symbol(f"v_{state}_{name}", positive=True)
    phi = sympy.atan2(r1[1], r1[0]) + s * theta
    e = (sympy.cos(phi), sympy.sin(phi))
    p2 = (C0[0] + R * e[0], C0[1] + R * e[1])
    m = body.mass
    work = tidy(m * dot(gravity, (p2[0] - p1[0], p2[1] - p1[1])))
    T1 = tidy(m * dot(v1, v1) / 2)
    energy = Equation(
        tidy(T1 + work),
        m * speed**2 / 2,
        "eq. 1",
        1,
        f"T{state - 1} + ΣU({state - 1}→{state}) = T{state} ({name}: ½ m v₁² + W·Δr = ½ m v₂²; "
        f"{circle.force} does no "
        "work, being normal to the path)",
    )
    inward = (-e[0], -e[1])
    radial = Equation(
        tidy(m * dot(gravity, inward)),
        m * speed**2 / R,
        "eq. 2",
        2,
        f"ΣF_n = m v²/R toward {_point_text(C0)} at state {state} with {circle.force} = 0 "
        f"({circle.what} {'goes slack' if travel.until == 'slack' else 'is left'})",
    )
    first, bound = _first_zero(circle, m, g, gravity, v1, r1, s, values, travel)
    condition = Constraint(
        sympy.Le(theta, bound),
        f"{pretty(theta.name)} <= {bound:.6g} (the first zero of {circle.force} after the start)",
        travel.line,
    )
    start_force = tidy(circle.side * (m * dot(v1, v1) / R - m * dot(gravity, _unit(r1, -1))))
    what = "taut" if travel.until == "slack" else "in contact"
    events = (
        (
            f"{circle.what} {what} at the start",
            start_force,
            f"{circle.force} = {{value:.4g force}} > 0 at the start",
        ),
    )
    note = (
        f"until {circle.what} {'goes slack' if travel.until == 'slack' else 'is left'}",
        f"{name} moves {'ccw' if s > 0 else 'cw'} round {_point_text(C0)} (radius "
        f"{sympy.sstr(R)}); the first zero of {circle.force} after the start is at θ = "
        f"{math.degrees(first):.4g}°, before which the speed stays above zero; beyond it "
        f"{name} is a projectile",
    )
    return CircleUntil(
        (energy, radial),
        speed,
        theta,
        _rise(_unit(scene.gravity, -1), r1, R, s * theta),
        (-s * speed * e[1], s * speed * e[0]),  # along the circle, in the sense of motion
        condition,
        events,
        note,
    )


def _rise(up: Vec, r1: Vec, R: sympy.Expr, turn: sympy.Expr) -> sympy.Expr:
    """How far G rises (along ``up``) once it has turned by ``turn`` (ccw) from
    r₁ = G₁ − O on the circle of radius R = |r₁|: up·(R e − r₁), e the unit vector to G.
    Exact mode writes e = (cos φ, sin φ) with φ = atan2(r₁) + turn, as its equations do,
    and tidies it into the textbook's cos(φ₀ + θ); numeric mode, which shows h tidied
    only, rotates r₁ instead (no atan2): its tidying takes a third of the time.

    >>> R, a, t = sympy.symbols("R a t", positive=True)
    >>> r1 = (R * sympy.sin(a), R * sympy.cos(a))
    >>> from dynsolve.numbers import light_tidying
    >>> with light_tidying():
    ...     _rise((0, 1), r1, R, t)
    R*sin(a)*sin(t) + R*cos(a)*cos(t) - R*cos(a)
    """
    if tidying_lightly():
        c, s = sympy.cos(turn), sympy.sin(turn)
        e = ((r1[0] * c - r1[1] * s) / R, (r1[1] * c + r1[0] * s) / R)
    else:
        phi = sympy.atan2(r1[1], r1[0]) + turn
        e = (sympy.cos(phi), sympy.sin(phi))
    return tidy(dot(up, (R * e[0] - r1[0], R * e[1] - r1[1])))


def _unit(r: Vec, sign: int) -> Vec:
    size = sympy.sqrt(r[0] ** 2 + r[1] ** 2)
    return (sign * r[0] / size, sign * r[1] / size)


def _point_text(p: Vec) -> str:
    return f"({sympy.sstr(p[0])}, {sympy.sstr(p[1])})"


def _circle(scene: Scene, travel: Travel) -> Circle:
    """The cord (a link to a fixed point) or the circular path the particle moves on."""
    body = scene.bodies[travel.body]
    if travel.until == "slack":
        link = next((k for k in scene.links if k.name == travel.until_name), None)
        if link is None or link.body != travel.body or link.other:
            raise UntilError(
                travel,
                f"'until {travel.until_name} slack' needs a link {travel.until_name} from "
                f"{travel.body} to a fixed point ('link {travel.until_name}: {travel.body} at G "
                "to O')",
            )
        C0 = link.other_point
        R = tidy(sympy.sqrt((body.G[0] - C0[0]) ** 2 + (body.G[1] - C0[1]) ** 2))
        return Circle(C0, R, 1, link.name, f"the tension in {link.name}")
    missed: list[str] = []  # circles G is not on, with how far off
    for path in scene.paths.values():
        circle = _circle_of(path.curve, path.x, path.y)
        if circle is None:
            continue
        C0, R = circle
        on = tidy((body.G[0] - C0[0]) ** 2 + (body.G[1] - C0[1]) ** 2 - R**2)
        if on != 0:
            distance = real_value(
                sympy.sqrt((body.G[0] - C0[0]) ** 2 + (body.G[1] - C0[1]) ** 2), scene.values
            )
            radius = real_value(R, scene.values)
            if distance is not None and radius is not None:
                missed.append(
                    f"{path.name} (G is {distance:.7g} from its centre, R = {radius:.7g})"
                )
            continue
        r1 = (body.G[0] - C0[0], body.G[1] - C0[1])
        assert scene.gravity is not None
        pressed = real_value(dot(scene.gravity, r1), scene.values)
        if not pressed:
            raise UntilError(
                travel,
                f"which side of {path.name} {travel.body} is on is not known where its weight "
                "is along the surface: start it above or below the centre",
            )
        side = 1 if pressed > 0 else -1  # weight away from O: on the inside of a loop
        return Circle(C0, R, side, f"the surface {path.name}", f"N_{path.name}")
    off = (
        f"; off the circle: {'; '.join(missed)}: place G on it with a formula, e.g. "
        "'at (R*sin(phi_0), R*cos(phi_0))'"
        if missed
        else ""
    )
    raise UntilError(
        travel,
        f"'until contact lost' needs a circular path through {travel.body}'s G "
        f"(e.g. 'path dome: x^2 + y^2 = R^2'){off}",
    )


def _circle_of(
    curve: sympy.Expr, x: sympy.Symbol, y: sympy.Symbol
) -> tuple[Vec, sympy.Expr] | None:
    """(centre, radius) when ``curve`` = 0 is a circle, else None.

    >>> x, y = sympy.symbols("x y")
    >>> _circle_of(x**2 + (y - 1)**2 - 4, x, y)
    ((0, 1), 2)
    """
    try:
        poly = sympy.Poly(sympy.expand(curve), x, y)
    except sympy.PolynomialError:
        return None
    if poly.total_degree() != 2:
        return None
    a, b, c = poly.coeff_monomial(x**2), poly.coeff_monomial(y**2), poly.coeff_monomial(x * y)
    if tidy(a - b) != 0 or c != 0 or a == 0:
        return None
    D, E, F = poly.coeff_monomial(x), poly.coeff_monomial(y), poly.coeff_monomial(1)
    centre = (tidy(-D / (2 * a)), tidy(-E / (2 * a)))
    radius = tidy(sympy.sqrt(centre[0] ** 2 + centre[1] ** 2 - F / a))
    return centre, radius


def _first_zero(
    circle: Circle,
    m: sympy.Expr,
    g: sympy.Expr,
    gravity: Vec,
    v1: Vec,
    r1: Vec,
    s: int,
    values: Mapping[sympy.Symbol, sympy.Expr],
    travel: Travel,
) -> tuple[float, float]:
    """The first turned angle (rad) where the support force falls to zero, and a bound
    between it and the next zero (the root the constraint keeps). Refused when the speed
    falls to zero first (it swings back) or the force never vanishes."""
    theta = sympy.Symbol("theta")
    phi1 = sympy.atan2(r1[1], r1[0])
    e = (sympy.cos(phi1 + s * theta), sympy.sin(phi1 + s * theta))
    R = circle.radius
    p_rel = (R * e[0] - r1[0], R * e[1] - r1[1])
    v2 = dot(v1, v1) + 2 * dot(gravity, p_rel)  # v² along the circle
    force = circle.side * (v2 / R + dot(gravity, e))  # per unit mass, positive while held
    f_v2 = float_scalar([theta], v2.xreplace(values))
    f_force = float_scalar([theta], force.xreplace(values))
    try:
        if f_force(0.0) <= 0:
            raise UntilError(
                travel,
                f"{circle.force} is not positive at the start: {circle.what} does not hold "
                f"{travel.body} at the start",
            )
        steps = 4000
        previous = 0.0
        for k in range(1, steps + 1):
            angle = 2 * math.pi * k / steps
            if f_v2(angle) <= 0:
                stop = _bisect(f_v2, previous, angle)  # where v² = 0, to the last digit
                raise UntilError(
                    travel,
                    f"{travel.body} stops at θ = {math.degrees(stop):.5g}° (its speed falls to "
                    f"zero) before {circle.force} does: it swings back, and {circle.what} "
                    f"never {'goes slack' if travel.until == 'slack' else 'is left'}",
                )
            if f_force(angle) <= 0:
                root = _bisect(f_force, previous, angle)
                later = next(
                    (
                        2 * math.pi * j / steps
                        for j in range(k + 1, 2 * steps)
                        if f_force(2 * math.pi * j / steps) > 0
                    ),
                    None,
                )
                bound = (root + later) / 2 if later is not None else root + math.pi / 2
                return root, bound
            previous = angle
    except (TypeError, ValueError, ZeroDivisionError) as exc:
        if isinstance(exc, UntilError):
            raise
        raise UntilError(
            travel, f"'until {travel.until}' needs numbers for the givens ({exc})"
        ) from None
    raise UntilError(
        travel,
        f"{circle.force} stays above zero all the way round: {travel.body} loops and "
        f"{circle.what} never {'goes slack' if travel.until == 'slack' else 'is left'}",
    )


def _bisect(f: Callable[[float], float], low: float, high: float) -> float:
    """The root of ``f`` in [low, high] where f(low) > 0 ≥ f(high), by bisection.

    >>> round(_bisect(lambda x: 2 - x * x, 0.0, 2.0), 12)
    1.414213562373
    """
    for _ in range(200):
        middle = (low + high) / 2
        if middle in (low, high):
            break
        if f(middle) > 0:
            low = middle
        else:
            high = middle
    return (low + high) / 2
