"""The simulation cross-check: each travel of a solved scene integrated in time and compared.

A travel (work and energy, or a stage of a chain) moves a particle along a straight line
or a one-degree-of-freedom body or linkage. Its equation of motion
(:mod:`dynsolve.simulate.equations`) is integrated with tight tolerances from the start
state of the travel until its end is reached, or until it stops (q' = 0) for a travel that
``stops``. The speed of each G and each ω at the end are compared with the principle's
answer (relative difference ≤ :data:`AGREEMENT`). For a travel that stops, the check is on
energy: the kinetic energy left at the end, or the work still needed to get there from
where the simulation stops, over the largest kinetic energy on the way (where the end is
an equilibrium a stop distance is ill-conditioned, but this is not). A travel that
cannot be simulated says why.

>>> import sympy
>>> from dynsolve.model.scene import Body, Scene, Travel
>>> m, g, h = sympy.symbols("m g h", positive=True)
>>> ball = Body("ball", m, 0, (0, h), (0, h), "particle", (), {}, True, "", 0, 0)
>>> fall = Travel("ball", "by", distance=h, direction=(0, -1))
>>> scene = Scene({"ball": ball}, {}, (), (), (), (0, -1), {}, travels={"ball": fall})
>>> values = {m: 1, g: sympy.Float(9.81), h: 2}
>>> leg = Leg("fall", scene, fall, {"ball": sympy.sqrt(2 * g * h)}, {"ball": 0})
>>> check = simulate_leg(leg, {"g": g}, values, "SI")
>>> check.passed, check.name
(True, 'simulation: fall')
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping
from dataclasses import replace

import numpy as np
import sympy
from scipy.integrate import IntegrationWarning, quad

from dynsolve.model.scene import Scene, Travel
from dynsolve.model.states import particle_shift, placements_of
from dynsolve.numbers import real_value
from dynsolve.results import Check
from dynsolve.simulate.equations import (
    NotSimulable,
    OneDof,
    Q,
    mechanism,
    numeric_scene,
    straight_line,
)
from dynsolve.simulate.integrator import TIGHT_ATOL, TIGHT_RTOL, Event, Run, integrate
from dynsolve.simulate.legs import Leg

AGREEMENT = 1e-6  # relative
METHOD = "DOP853"
HORIZON = 200.0  # the run gives up after this many times the travel's time scale
STEPS_PER_TRAVEL = 50  # at least this many steps over the travel's time scale
LENGTH_UNITS = {"SI": "m", "FPS": "ft"}


def simulate_leg(
    leg: Leg,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str = "SI",
) -> Check:
    """Integrate one travel and compare its end with the principle's answer."""
    name = f"simulation: {leg.label}" if leg.label else "simulation"
    try:
        motion, q_end = travel_motion(leg.scene, leg.travel, symbols, values)
        qd0 = start_rate(motion, leg.scene, values)
        run = _run(motion, q_end, qd0)
    except NotSimulable as exc:
        return Check.not_run(name, f"not simulated: {exc}")
    except (ArithmeticError, ValueError, TypeError) as exc:  # a singular or complex motion
        return Check.not_run(name, f"not simulated: the integration failed ({exc})")
    length = LENGTH_UNITS.get(system, "m")
    unit = length if motion.unit == "m" else motion.unit
    how = (
        f"M(q) q'' + ½ M'(q) q'² = Q(q, q') in q = {motion.coordinate} [{unit}], "
        f"solve_ivp {run.method} (rtol {run.rtol:.0e}, atol {TIGHT_ATOL:.0e} of each "
        "state's scale); "
    )
    try:
        if leg.travel.stops:
            passed, detail = _stops(motion, run, q_end, unit)
        else:
            passed, detail = _reaches(motion, run, q_end, leg, values, length)
    except NotSimulable as exc:
        return Check.not_run(name, f"not simulated: {exc}")
    return Check(name, bool(passed), how + detail)


def travel_motion(
    scene: Scene,
    travel: Travel,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    simplify: bool = False,
) -> tuple[OneDof, float]:
    """The travel's equation of motion, q measured from its start toward its end, and q
    at the end (> 0); ``simplify`` for a long run (see :func:`~.equations.mechanism`)."""
    scene = numeric_scene(replace(scene, travels={travel.body: travel}), values)
    travel = scene.travels[travel.body]
    lone = all(b.particle for b in scene.bodies.values()) and not scene.links and not scene.cords
    if lone:
        if travel.kind not in ("to", "by"):
            raise NotSimulable(f"{travel.body} is a particle: it travels to or by, not turns")
        shift = particle_shift(scene, travel)
        assert shift is not None
        sx, sy = _value(shift[0], values), _value(shift[1], values)
        size = math.hypot(sx, sy)
        if size == 0:
            raise NotSimulable("the travel has no length")
        unit = (sympy.Float(sx / size, 17), sympy.Float(sy / size, 17))
        return straight_line(scene, travel.body, unit, symbols, values), size
    if travel.kind == "turns":
        assert travel.angle is not None
        angle = _value(travel.angle, values)
        sense = 1 if angle >= 0 else -1
        param = Travel(travel.body, "turns", angle=sense * Q)
        what = f"turn of {travel.body}" + (" (cw)" if sense < 0 else "")
        return mechanism(scene, param, symbols, values, what, "rad", simplify), abs(angle)
    if travel.kind == "by":
        assert travel.distance is not None and travel.direction is not None
        distance = _value(travel.distance, values)
        sense = 1 if distance >= 0 else -1
        param = Travel(travel.body, "by", distance=sense * Q, direction=travel.direction)
        what = f"distance of G of {travel.body} along its travel"
        return mechanism(scene, param, symbols, values, what, "m", simplify), abs(distance)
    if travel.kind == "to":
        return _to_motion(scene, travel, symbols, values, simplify)
    raise NotSimulable(f"a travel '{travel.kind}' is not simulated")  # see legs.SIMULATED_KINDS


def _to_motion(
    scene: Scene,
    travel: Travel,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    simplify: bool = False,
) -> tuple[OneDof, float]:
    """A rigid body or linkage travelling to a position: q is the turn of the body or link
    that turns most on the way."""
    try:
        placed = replace(scene, travels={travel.body: travel})
        placements, link_turns = placements_of(placed, simplify=False)
    except ValueError as exc:
        raise NotSimulable(str(exc)) from None
    turns = {n: _value(p.turn, values) for n, p in placements.items()}
    turns |= {n: _value(t, values) for n, t in link_turns.items()}
    name, turn = max(turns.items(), key=lambda item: abs(item[1]))
    if abs(turn) < 1e-12:
        raise NotSimulable("nothing turns on the way: give the travel 'by' a distance")
    sense = 1 if turn > 0 else -1
    param = Travel(name, "turns", angle=sense * Q)
    what = f"turn of {name}" + (" (cw)" if sense < 0 else "")
    return mechanism(scene, param, symbols, values, what, "rad", simplify), abs(turn)


def _value(expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]) -> float:
    number = real_value(expr, values)
    if number is None:
        names = ", ".join(sorted(str(s) for s in (sympy.Integer(0) + expr).free_symbols))
        raise NotSimulable(f"symbolic givens ({names}) have no values")
    return number


def start_rate(motion: OneDof, scene: Scene, values: Mapping[sympy.Symbol, sympy.Expr]) -> float:
    """q' at the start, from the scene's ``velocity`` (v_G·r_G'/|r_G'|²) or ``omega``
    (ω/θ') line; 0 from rest."""
    places = motion.places(0.0)
    for name, v in scene.velocities.items():
        if name in places:
            dx, dy = places[name][3], places[name][4]
            if dx * dx + dy * dy > 0:
                vx, vy = _value(v[0], values), _value(v[1], values)
                return (vx * dx + vy * dy) / (dx * dx + dy * dy)
    for name, w in scene.omegas.items():
        if name in places and places[name][5] != 0:
            return _value(w, values) / places[name][5]
    return 0.0


def _run(motion: OneDof, q_end: float, qd0: float) -> Run:
    a0 = abs(motion.acceleration(0.0, qd0))
    speed = max(abs(qd0), math.sqrt(a0 * q_end))
    if speed == 0:
        raise NotSimulable("the scene is at rest in equilibrium at the start: it does not move")
    end = Event("end of the travel", lambda q, qd: q - q_end, 1)
    stop = Event("at rest", lambda q, qd: qd, -1)
    # absolute tolerances in the travel's own scales (q, q', and the work of friction), so
    # the check is the same for a problem in metres and one scaled by 1e-9
    energy = max(abs(motion.kinetic(0.0, speed)), abs(motion.energy(0.0, qd0)), 1e-300)
    atol = TIGHT_ATOL * np.array([abs(q_end), speed, energy])
    if motion.frictionless:
        atol = atol[:2]
    # steps of at most 1/50 of the travel's time scale: one long step over a smooth flight
    # can pass a top and the fall back onto a spring, and its events with it
    return integrate(
        motion, 0.0, qd0, HORIZON * q_end / speed, [end, stop], METHOD, TIGHT_RTOL, atol,
        max_step=q_end / speed / STEPS_PER_TRAVEL,
    )  # fmt: skip


def _reaches(
    motion: OneDof,
    run: Run,
    q_end: float,
    leg: Leg,
    values: Mapping[sympy.Symbol, sympy.Expr],
    length: str,
) -> tuple[bool, str]:
    t, q, qd = float(run.t[-1]), float(run.q[-1]), float(run.qd[-1])
    if run.stopped_by != "end of the travel":
        where = "comes to rest" if run.stopped_by else "has not got there"
        return False, (
            f"it {where} at q = {q:.7g} after t = {t:.4g} s, before the end of the travel "
            f"(q = {q_end:.7g}); the principle says it gets there"
        )
    parts: list[str] = []
    worst = 0.0
    for name, (vx, vy, omega) in motion.velocities(q, qd).items():
        expected = real_value(leg.speeds.get(name, 0), values)
        if expected is not None and name in leg.speeds:
            found = math.hypot(vx, vy)
            worst = max(worst, _gap(found, expected))
            parts.append(f"|v_G({name})| = {found:.7g} {length}/s (principle {expected:.7g})")
        turning = abs(motion.places(q)[name][5]) > 1e-12
        spin = real_value(leg.spins.get(name, 0), values)
        if turning and spin is not None and name in leg.spins:
            worst = max(worst, _gap(omega, spin))
            parts.append(f"ω({name}) = {omega:.7g} rad/s (principle {spin:.7g})")
    if not parts:
        raise NotSimulable("the principle's end state has no values to compare")
    passed = worst <= AGREEMENT
    return passed, (
        f"at the end (t = {t:.4g} s) " + ", ".join(parts) + f"; largest relative difference "
        f"{worst:.1e} {'≤' if passed else '>'} {AGREEMENT:.0e}; energy drift {run.drift:.1e}"
    )


def _gap(found: float, expected: float) -> float:
    size = max(abs(found), abs(expected))
    return 0.0 if size == 0 else abs(found - expected) / size


def _stops(motion: OneDof, run: Run, q_end: float, unit: str) -> tuple[bool, str]:
    """Whether the run stops where the principle's end is (``unit``: q's, as shown)."""
    T1 = max(motion.kinetic(a, b) for a, b in zip(run.q, run.qd, strict=True))
    t, q, qd = float(run.t[-1]), float(run.q[-1]), float(run.qd[-1])
    if T1 <= 0:
        return False, "it does not move"
    if run.stopped_by == "end of the travel":
        left = motion.kinetic(q, qd) / T1
        passed = left <= AGREEMENT
        return passed, (
            f"it reaches the end (q = {q_end:.7g} {unit}) at t = {t:.4g} s with T/T_max = "
            f"{left:.1e} {'≤' if passed else '>'} {AGREEMENT:.0e} (the principle: at rest there)"
        )
    if run.stopped_by != "at rest":
        return False, f"it neither stops nor reaches the end by t = {t:.4g} s"
    with warnings.catch_warnings():  # a kink at the stop (a spring's end): judged by value
        warnings.simplefilter("ignore", IntegrationWarning)
        needed, _ = quad(lambda s: motion.generalized_force(s, 1.0), q, q_end, epsabs=0, limit=200)
    short = abs(needed) / T1
    passed = short <= AGREEMENT
    return passed, (
        f"it comes to rest at q = {q:.7g} {unit} (t = {t:.4g} s; principle: q = {q_end:.7g} "
        f"{unit}, "
        f"relative {abs(q - q_end) / q_end:.1e}); the work between the two, over the largest T "
        f"on the way, is {short:.1e} {'≤' if passed else '>'} {AGREEMENT:.0e}"
    )
