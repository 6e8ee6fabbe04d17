"""The simulation check of an until event on a circle: a particle on its cord or circular
surface, integrated in its angle until the cord's tension or the surface's push is zero.

The principle (work and energy with ΣF_n = m v²/R, :mod:`dynsolve.principles.until`)
finds the angle turned and the speed there in closed form; here R φ'' = g·t̂ is
integrated from the start state with scipy's ``solve_ivp`` (DOP853, tight tolerances)
and stopped where side·(R φ'² + g·ê) falls through zero (ê outward, t̂ along the motion),
the same event found independently. Agreement is relative (:data:`AGREEMENT`).

>>> import sympy
>>> from dynsolve.model.scene import Body, Link, Scene, Travel
>>> bob = Body("bob", 2, 0, (0, -1), (0, -1), "particle", (), {}, True, "", 0, 0)
>>> cord = Link("cord", "bob", (0, -1), "", (0, 0))
>>> slack = Travel("bob", "until", until="slack", until_name="cord")
>>> scene = Scene({"bob": bob}, {}, (), (), (), (0, -1), {}, links=(cord,),
...               velocities={"bob": (6, 0)}, travels={"bob": slack})
>>> g = sympy.Symbol("g")
>>> # hand: cos θ = (2gL − v²)/(3gL) = (19.62 − 36)/29.43 → θ = 123.82°, v = 2.3367 m/s
>>> run = circle_event(scene, slack, {"g": g}, {g: sympy.Float(9.81)})
>>> round(math.degrees(run[0]), 2), round(run[1], 4)
(123.82, 2.3367)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

import sympy

from dynsolve.model.scene import Scene, Travel
from dynsolve.numbers import real_value
from dynsolve.results import Check
from dynsolve.units import with_unit

AGREEMENT = 1e-6  # relative
RTOL, ATOL = 1e-12, 1e-14
TURNS = 20  # the run gives up after this many turns without the event


class NotOnCircle(ValueError):
    """The scene has no numbers for the circle's geometry or the start."""


def circle_event(
    scene: Scene,
    travel: Travel,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> tuple[float, float, str]:
    """(angle turned to the event [rad], speed there, "" or why the run ended early)."""
    from scipy.integrate import solve_ivp

    from dynsolve.principles.until import _circle

    circle = _circle(scene, travel)
    body = scene.bodies[travel.body]
    number = _numbers(values)
    C = (number(circle.centre[0]), number(circle.centre[1]))
    R = number(circle.radius)
    G = (number(body.G[0]), number(body.G[1]))
    v = tuple(number(c) for c in scene.velocities.get(travel.body, (0, 0)))
    g = number(symbols["g"])
    assert scene.gravity is not None
    down = (number(scene.gravity[0]), number(scene.gravity[1]))
    phi_0 = math.atan2(G[1] - C[1], G[0] - C[0])
    w_0 = ((G[0] - C[0]) * v[1] - (G[1] - C[1]) * v[0]) / R**2  # ccw rate
    if w_0 == 0:  # from rest: it starts the way its weight pulls it along the circle
        pull = -down[0] * math.sin(phi_0) + down[1] * math.cos(phi_0)
        sense = 1.0 if pull > 0 else -1.0
    else:
        sense = 1.0 if w_0 > 0 else -1.0

    def rhs(_t: float, y: list[float]) -> list[float]:
        phi = y[0]
        return [y[1], g * (-down[0] * math.sin(phi) + down[1] * math.cos(phi)) / R]

    def force(_t: float, y: list[float]) -> float:
        phi, w = y
        return circle.side * (R * w * w + g * (down[0] * math.cos(phi) + down[1] * math.sin(phi)))

    def turned_back(_t: float, y: list[float]) -> float:
        return y[1] * sense

    force.terminal, force.direction = True, -1  # type: ignore[attr-defined]
    turned_back.terminal, turned_back.direction = True, -1  # type: ignore[attr-defined]
    horizon = TURNS * 2 * math.pi * math.sqrt(R / g) * 10
    run = solve_ivp(
        rhs, (0.0, horizon), [phi_0, w_0], method="DOP853", rtol=RTOL, atol=ATOL,
        events=(force, turned_back),
    )  # fmt: skip
    if len(run.t_events[0]):
        phi, w = run.y_events[0][0]
        return float(abs(phi - phi_0)), float(abs(R * w)), ""
    if len(run.t_events[1]):
        phi = run.y_events[1][0][0]
        return float(abs(phi - phi_0)), 0.0, "it stops and swings back first"
    return math.nan, math.nan, "the force never falls to zero: it goes round"


def circle_check(
    name: str,
    scene: Scene,
    travel: Travel,
    answers: tuple[sympy.Expr, sympy.Expr],
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> Check:
    """The until event integrated and compared with the principle's (angle, speed), the
    speeds with their unit in ``system``."""
    try:
        angle, speed, why = circle_event(scene, travel, symbols, values)
        theta, v = (_numbers(values)(a) for a in answers)
    except (NotOnCircle, ValueError, ArithmeticError) as exc:
        return Check.not_run(name, f"not simulated: {exc}")
    how = "R φ'' = g·t̂ in φ, solve_ivp DOP853 (rtol 1e-12) to the event side·(R φ'² + g·ê) = 0; "
    if why:
        return Check(name, False, how + f"{why}, where the principle finds the event")
    gap = max(abs(angle - theta) / max(abs(theta), 1e-300), abs(speed - v) / max(abs(v), 1e-300))
    detail = (
        f"the event at {math.degrees(angle):.7g}° turned, speed "
        f"{with_unit(speed, 'velocity', system, '.7g')} (principle: {math.degrees(theta):.7g}°, "
        f"{with_unit(v, 'velocity', system, '.7g')}; relative {gap:.1e})"
    )
    return Check(name, gap <= AGREEMENT, how + detail)


def _numbers(values: Mapping[sympy.Symbol, sympy.Expr]) -> Callable[[object], float]:
    """A reader of an expression's value as a float, or NotOnCircle."""

    def number(expr: object) -> float:
        found = real_value(sympy.Integer(0) + expr, values)  # type: ignore[operator]
        if found is None:
            raise NotOnCircle("the circle or the start has no numbers")
        return float(found)

    return number
